void main()
{
    const float k;
    gl_FragColor = vec4(k);
}
