void main()
{
    bool b = true;
    gl_FragColor = b ? vec4(1.0) : vec3(0.0);
}
