uniform sampler2D tex;
void main()
{
    vec3 a = vec4(1.0);
    float b = undefined_thing;
    gl_FragColor = texture2D(tex, 1.0);
}
