#version 120
uniform int mode;
void main()
{
    switch (mode) {
    default: gl_FragColor = vec4(1.0);
    }
}
