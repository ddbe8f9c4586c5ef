// seed: 000_bda539806ee70a96.txt lines 56-66
// expect: pass
// version: 120
// stage: vertex
// This is a pass-through vertex shader
void main()
{
    gl_Position = ftransform();
    gl_FrontColor = gl_Color;
    gl_BackColor = gl_Color;
}
