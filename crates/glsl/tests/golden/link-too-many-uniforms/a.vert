uniform vec4 weights[4100];
attribute float index;
void main()
{
    gl_Position = weights[int(index)] + ftransform();
}
