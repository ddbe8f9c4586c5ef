void main()
{
    uniform float u;
    gl_FragColor = vec4(u);
}
