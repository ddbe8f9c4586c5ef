void main()
{
    gl_FrontColor = gl_Color;
}
