// seed: 000_bda539806ee70a96.txt lines 101-111
// expect: pass
// version: 120
// stage: vertex
// This is a vertex shader using the current material settings
varying vec3 normal;

void main()
{
    normal = normalize(gl_NormalMatrix * gl_Normal);

    gl_Position = ftransform();
    gl_FrontColor = gl_Color;
    gl_BackColor = gl_Color;
}
