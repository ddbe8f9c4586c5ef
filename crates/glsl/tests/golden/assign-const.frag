void main()
{
    const float k = 1.0;
    k = 2.0;
    gl_FragColor = vec4(k);
}
