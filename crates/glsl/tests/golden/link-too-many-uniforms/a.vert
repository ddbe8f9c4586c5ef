uniform vec4 weights[1100];
attribute float index;
void main()
{
    gl_Position = weights[int(index)] + ftransform();
}
