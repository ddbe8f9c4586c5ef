#version 120
void never_defined();
void main()
{
    gl_FragColor = vec4(1.0);
    if (sqrt(4.0) != 2.0)
        never_defined();
}
