void main()
{
    vec2 v = vec2(1.0, 2.0, 3.0);
    gl_FragColor = vec4(v, v);
}
