void main()
{
    float a[0];
    gl_FragColor = vec4(1.0);
}
