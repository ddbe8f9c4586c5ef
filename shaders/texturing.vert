// texturing.vert: hands texture coordinates sets 0 and 1 to the fragment
// stage (vertex stage, for single-texture.frag / multi-texture.frag with
// texturing-lib.frag).
//
// What it does: copies gl_MultiTexCoord0 and gl_MultiTexCoord1 to
// gl_TexCoord[0] and [1] (no texture matrix, as in the seed), the vertex
// colour to gl_FrontColor, and transforms the vertex with ftransform.
//
// State it reads: gl_Vertex, gl_Color, gl_MultiTexCoord0,
// gl_MultiTexCoord1, gl_ModelViewProjectionMatrix.
//
// Changes from the seed ("Creating a GLSL Library", Texturing.vert):
// - gl_TexCoord is redeclared with size 2 (GLSL 1.10 section 7.6), the
//   same size texturing-lib.frag needs to index it with a variable;
//   set 1 is copied too so multi-texture.frag can use a second set.
// - gl_FrontColor = gl_Color: the seed's fragment mains start from
//   gl_Color, which a vertex shader must write (it is undefined otherwise).

varying vec4 gl_TexCoord[2];

void main(void)
{
    gl_TexCoord[0] = gl_MultiTexCoord0;
    gl_TexCoord[1] = gl_MultiTexCoord1;
    gl_FrontColor = gl_Color;
    gl_Position = ftransform();
}
