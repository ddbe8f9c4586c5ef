// seed: 000_bda539806ee70a96.txt lines 68-72
// expect: pass
// version: 120
// stage: fragment
// This is the pass-through fragment shader
void main()
{
    gl_FragColor = gl_Color;
}
