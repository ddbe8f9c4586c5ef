// sphere.geom: sphere impostor quad from one point (geometry stage,
// GL_EXT_geometry_shader4; vertex: sphere-point.vert; fragment:
// sphere.frag or an effect's: outline.frag, x.frag, x-red.frag,
// transparent.frag).
//
// What it does: turns each atom's point into sphere.vert's screen-aligned
// square, a triangle strip of 4 vertices in the order (right, up) =
// (-1,-1), (1,-1), (-1,1), (1,1), and gives every corner the varyings
// sphere.vert gives it: the eye-space corner `point`, `view_direction`,
// and the per-atom sphere_center, radius2, color, half_size (x effects),
// gl_FogFragCoord, gl_ClipVertex. Each corner is computed with exactly
// sphere.vert's operations (corner_direction = up * up_vector + right *
// right_vector, the centre pushed out by atom_extent along it, then the
// model-view and model-view-projection matrices), so the corners are
// bit-identical to sphere.vert's.
//
// Program parameters (glProgramParameteriEXT before linking):
//   GL_GEOMETRY_INPUT_TYPE_EXT = GL_POINTS,
//   GL_GEOMETRY_OUTPUT_TYPE_EXT = GL_TRIANGLE_STRIP,
//   GL_GEOMETRY_VERTICES_OUT_EXT = 4.
//
// State it reads:
//   uniform vec3 right_vector, up_vector  object-space directions that the
//                                         model-view maps to eye +x and +y
//                                         (unit length)
//   gl_PositionIn[0]                      object-space atom centre
//   gl_FogFragCoordIn[0]
//   atom_center[0], atom_radius2[0], atom_half_size[0], atom_extent[0],
//   atom_color[0]                         from sphere-point.vert
//   gl_ModelViewMatrix, gl_ModelViewProjectionMatrix
//
// GLSL 1.20 with the extension, so it links into the renderer's GL 2.1
// context and reads its compatibility state; Mesa never implemented the
// extension form (it has only GLSL 1.50 geometry shaders, in core
// contexts), so only shaderbox runs this program.

#version 120
#extension GL_EXT_geometry_shader4 : enable

uniform vec3 right_vector;
uniform vec3 up_vector;

varying in vec3 atom_center[];
varying in float atom_radius2[];
varying in float atom_half_size[];
varying in float atom_extent[];
varying in vec4 atom_color[];

varying out vec4 color;
varying out vec3 view_direction;
varying out vec3 sphere_center;
varying out float radius2;
varying out vec3 point;
varying out float half_size;

void corner(in float right, in float up)
{
    vec3 corner_direction = up * up_vector + right * right_vector;
    vec4 vertex = vec4(gl_PositionIn[0].xyz + atom_extent[0] * corner_direction, 1.0);
    vec4 eye_space_pos = gl_ModelViewMatrix * vertex;

    point = eye_space_pos.xyz / eye_space_pos.w;
    view_direction = normalize(point);
    sphere_center = atom_center[0];
    radius2 = atom_radius2[0];
    half_size = atom_half_size[0];
    color = atom_color[0];
    gl_FogFragCoord = gl_FogFragCoordIn[0];
    gl_ClipVertex = eye_space_pos;
    gl_Position = gl_ModelViewProjectionMatrix * vertex;
    EmitVertex();
}

void main(void)
{
    corner(-1.0, -1.0);
    corner(1.0, -1.0);
    corner(-1.0, 1.0);
    corner(1.0, 1.0);
    EndPrimitive();
}
