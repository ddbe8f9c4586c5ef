// seed: 001_59bddf836d92c59d.txt lines 147-151
// expect: pass
// version: 110
// stage: fragment
// note: no #version in the document, so this compiles as GLSL 1.10 (the slides mix GLSL 1.30+/3.x syntax with 1.10 built-ins)
// note: the broken line wrap inside vec4(...) is kept; it is harmless
void main(void)
{
    gl_FragColor = vec4(1.0, 0.0,
    0.0, 1.0);
}
