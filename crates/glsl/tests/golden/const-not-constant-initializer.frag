uniform float u;
void main()
{
    const float k = u * 2.0;
    gl_FragColor = vec4(k);
}
