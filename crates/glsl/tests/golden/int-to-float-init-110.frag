void main()
{
    float f = 1;
    gl_FragColor = vec4(f);
}
