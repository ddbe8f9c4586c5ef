// seed: 001_59bddf836d92c59d.txt lines 654-660
// expect: pass
// version: 110
// stage: vertex
// note: no #version in the document, so this compiles as GLSL 1.10 (the slides mix GLSL 1.30+/3.x syntax with 1.10 built-ins)
// vertex shader
void main(void)
{
 gl_Position = gl_ModelViewProjectionMatrix*gl_Vertex;
 gl_FrontColor = gl_Color;
 gl_BackColor = vec4(0,0,0,0); // black for backface
}
