void main()
{
    gl_Position = vec4(dFdx(gl_Vertex.x));
}
