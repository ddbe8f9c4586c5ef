#version 110
uniform mat4 m;
void main()
{
    gl_Position = transpose(m) * gl_Vertex;
}
