void main()
{
    float x = 1.0;
    if (x) gl_FragColor = vec4(1.0);
}
