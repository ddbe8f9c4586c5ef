// wireframe-geom.vert: single-pass wireframe, vertex stage of the
// geometry-shader form (for wireframe.geom and wireframe.frag).
//
// What it does: the ordinary per-vertex part only: clip-space position,
// eye-space normal, colour. Unlike wireframe.vert, a vertex needs no
// copy of its triangle's corners: wireframe.geom sees the whole triangle
// and computes the edge distances itself, so the mesh can share vertices
// (glDrawElements) and carries no extra attributes.
//
// State it reads: gl_Vertex, gl_Normal, gl_Color,
// gl_ModelViewProjectionMatrix, gl_NormalMatrix.
// It writes gl_Position, gl_FrontColor, gl_BackColor and the varying
// vertex_normal (eye space, unit length).

varying vec3 vertex_normal;

void main(void)
{
    vertex_normal = normalize(gl_NormalMatrix * gl_Normal);
    gl_FrontColor = gl_Color;
    gl_BackColor = gl_Color;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
