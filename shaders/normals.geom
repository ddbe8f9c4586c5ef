// normals.geom: normals view, geometry stage (GL_EXT_geometry_shader4;
// vertex: normals.vert; fragment: trivial.frag).
//
// What it does: for each triangle of a mesh, draws each of its three
// vertex normals as a short line: from the vertex to the vertex plus
// normal_length times the unit normal (object space), both ends projected
// by gl_ModelViewProjectionMatrix; the line is root_color at the vertex
// and tip_color at its end. The triangle itself is not drawn: draw the
// mesh with another program first and this over it. A vertex shared by
// several triangles gets its line once per triangle (the same line).
//
// Program parameters (glProgramParameteriEXT before linking):
//   GL_GEOMETRY_INPUT_TYPE_EXT = GL_TRIANGLES,
//   GL_GEOMETRY_OUTPUT_TYPE_EXT = GL_LINE_STRIP,
//   GL_GEOMETRY_VERTICES_OUT_EXT = 6 (three strips of two).
//
// State it reads: uniform float normal_length (object-space units);
// uniform vec4 root_color, tip_color; gl_PositionIn[0..2] (object space),
// vertex_normal[] (normals.vert); gl_ModelViewProjectionMatrix.

#version 120
#extension GL_EXT_geometry_shader4 : enable

uniform float normal_length;
uniform vec4 root_color;
uniform vec4 tip_color;

varying in vec3 vertex_normal[];

void main(void)
{
    for (int i = 0; i < 3; i++) {
        vec4 root = vec4(gl_PositionIn[i].xyz, 1.0);
        vec4 tip = vec4(root.xyz + normal_length * normalize(vertex_normal[i]), 1.0);
        gl_FrontColor = root_color;
        gl_Position = gl_ModelViewProjectionMatrix * root;
        EmitVertex();
        gl_FrontColor = tip_color;
        gl_Position = gl_ModelViewProjectionMatrix * tip;
        EmitVertex();
        EndPrimitive();
    }
}
