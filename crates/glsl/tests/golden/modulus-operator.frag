void main()
{
    int a = 7 % 2;
    gl_FragColor = vec4(float(a));
}
