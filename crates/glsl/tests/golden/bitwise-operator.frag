void main()
{
    int a = 6 & 3;
    gl_FragColor = vec4(float(a));
}
