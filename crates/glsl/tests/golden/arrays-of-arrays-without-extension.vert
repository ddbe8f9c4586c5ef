#version 120
uniform float a[2][3];
void main()
{
    float[2] b[3];
    gl_Position = vec4(a[1][2] + b[2][1]);
}
