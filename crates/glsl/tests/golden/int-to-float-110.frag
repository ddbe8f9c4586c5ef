#version 110
void main()
{
    int i = 2;
    float f;
    f = i;
    gl_FragColor = vec4(f);
}
