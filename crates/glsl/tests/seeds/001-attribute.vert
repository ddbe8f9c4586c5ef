// seed: 001_59bddf836d92c59d.txt lines 260-265
// expect: fail: missing `;` after the declaration `in vec3 in_pos` on line 7 (syntax error at `void` on line 8); besides, `gl_Position = in_pos;` (line 10) assigns a vec3 to the vec4 gl_Position
// version: 140
// stage: vertex
// note: the document's own #version line says 140, hence `version: 140`
#version 140
in vec3 in_pos
void main(void)
{
    gl_Position = in_pos;
}
