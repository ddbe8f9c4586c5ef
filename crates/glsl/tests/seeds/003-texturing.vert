// seed: 003_227224f6d3ad0fd5.txt lines 36-52
// expect: pass
// version: 110
// stage: vertex
// note: the dump double-spaces every line; the inserted blank lines are removed
/**
 * \file Texturing.vert
 */
void main()
{
    gl_TexCoord[0] = gl_MultiTexCoord0;

    gl_Position = ftransform();
}
