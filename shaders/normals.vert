// normals.vert: normals view, vertex stage (for normals.geom and
// trivial.frag).
//
// What it does: hands the object-space position and normal on to
// normals.geom, which draws the normal as a line; nothing is projected
// here (the geometry stage projects both ends of each line).
//
// State it reads: gl_Vertex, gl_Normal.
// It writes gl_Position = gl_Vertex (object space, not clip space: only
// normals.geom reads it) and the varying vertex_normal (object space).

varying vec3 vertex_normal;

void main(void)
{
    vertex_normal = gl_Normal;
    gl_Position = gl_Vertex;
}
