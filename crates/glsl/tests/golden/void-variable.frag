void main()
{
    void v;
    gl_FragColor = vec4(1.0);
}
