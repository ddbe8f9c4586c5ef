void main()
{
    double d = 1.0;
    gl_Position = vec4(d);
}
