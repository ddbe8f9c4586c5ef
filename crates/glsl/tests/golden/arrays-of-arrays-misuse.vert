#version 120
#extension GL_ARB_arrays_of_arrays : enable
uniform float a[2][];
void main()
{
    float b[2][3] = float[2][3](float[3](1.0, 2.0, 3.0));
    float c[2][3];
    c[1] = float[2](1.0, 2.0);
    gl_Position = vec4(c[1][3]);
}
