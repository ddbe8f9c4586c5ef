// lighting.vert: per-pixel lighting set-up (vertex stage, for
// one-sided-lighting.frag / two-sided-lighting.frag with
// phong-lighting-lib.frag, and for toon.frag).
//
// What it does: hands the fragment stage the eye-space unit normal
// (`normal`) and eye-space position (`vertex`), copies the vertex colour
// to both faces, and transforms the vertex with ftransform.
//
// State it reads: gl_Vertex, gl_Normal, gl_Color, gl_NormalMatrix,
// gl_ModelViewMatrix, gl_ModelViewProjectionMatrix. It writes
// gl_Position, gl_FrontColor, gl_BackColor, `varying vec3 normal, vertex`.
//
// After the seed ("Creating a GLSL Library", Lighting.vert), which has no
// slips; the colour copy is added for toon.frag.

varying vec3 normal;
varying vec3 vertex;

void main(void)
{
    normal = normalize(gl_NormalMatrix * gl_Normal);
    vertex = vec3(gl_ModelViewMatrix * gl_Vertex);
    gl_FrontColor = gl_Color;
    gl_BackColor = gl_Color;
    gl_Position = ftransform();
}
