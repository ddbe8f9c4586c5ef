void main()
{
    break;
    gl_FragColor = vec4(1.0);
}
