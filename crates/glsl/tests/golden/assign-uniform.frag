uniform vec4 tint;
void main()
{
    tint = vec4(0.0);
    gl_FragColor = tint;
}
