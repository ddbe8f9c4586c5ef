void main()
{
    gl_Position = transform(gl_Vertex);
}
