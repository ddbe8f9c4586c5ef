void main()
{
    gl_FragColour = vec4(1.0);
}
