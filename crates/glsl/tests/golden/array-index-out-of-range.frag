void main()
{
    float a[3];
    a[3] = 1.0;
    gl_FragColor = vec4(a[0]);
}
