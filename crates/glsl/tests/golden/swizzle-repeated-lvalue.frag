void main()
{
    vec4 v = vec4(1.0);
    v.xx = vec2(2.0);
    gl_FragColor = v;
}
