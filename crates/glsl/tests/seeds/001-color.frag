// seed: 001_59bddf836d92c59d.txt lines 664-668
// expect: pass
// version: 110
// stage: fragment
// note: no #version in the document, so this compiles as GLSL 1.10 (the slides mix GLSL 1.30+/3.x syntax with 1.10 built-ins)
// fragment shader
void main(void)
{
 gl_FragColor = gl_Color;
}
