// materials.vert: per-pixel lighting with the current material (vertex
// stage, for materials.frag and variable-lights.frag).
//
// What it does: hands the fragment stage the eye-space unit normal (the
// varying `normal`) and the vertex colour for both faces; the position
// goes through ftransform, as fixed function would place it.
//
// State it reads: gl_Vertex, gl_Normal, gl_Color, gl_NormalMatrix,
// gl_ModelViewProjectionMatrix. It writes gl_Position, gl_FrontColor,
// gl_BackColor and `varying vec3 normal`.
//
// After the seed talk ("GLSL v1.20", Example 02, materials vertex
// shader), which has no slips.

varying vec3 normal;

void main(void)
{
    normal = normalize(gl_NormalMatrix * gl_Normal);
    gl_Position = ftransform();
    gl_FrontColor = gl_Color;
    gl_BackColor = gl_Color;
}
