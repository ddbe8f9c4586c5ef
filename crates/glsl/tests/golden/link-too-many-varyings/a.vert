varying vec4 v[20];
void main()
{
    for (int i = 0; i < 20; i++)
        v[i] = gl_Vertex * float(i);
    gl_Position = ftransform();
}
