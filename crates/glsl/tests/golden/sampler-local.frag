uniform sampler2D tex;
void main()
{
    sampler2D t = tex;
    gl_FragColor = texture2D(t, vec2(0.0));
}
