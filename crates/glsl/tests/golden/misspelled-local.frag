void main()
{
    vec4 colour = vec4(1.0);
    gl_FragColor = color;
}
