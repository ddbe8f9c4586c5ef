float f()
{
    return;
}
void main() { gl_FragColor = vec4(f()); }
