// seed: 001_59bddf836d92c59d.txt lines 129-133
// expect: fail: line 6: `in vec4 vPosition;` uses `in` as a global storage qualifier, which GLSL 1.10/1.20 do not have (`in` is only a parameter qualifier before GLSL 1.30; a 1.10 vertex input is declared `attribute vec4 vPosition;`)
// version: 110
// stage: vertex
// note: no #version in the document, so this compiles as GLSL 1.10 (the slides mix GLSL 1.30+/3.x syntax with 1.10 built-ins)
in vec4 vPosition;
void main(void)
{
    gl_Position = vPosition;
}
