// sphere-point.vert: sphere impostor, one point per atom (vertex stage,
// for sphere.geom).
//
// What it does: the per-atom half of sphere.vert. Every atom is drawn as
// ONE GL_POINTS vertex at its centre (gl_Vertex) with its radius in
// gl_MultiTexCoord0.x and its colour in gl_Color: a quarter of the
// vertices of sphere.vert's GL_QUADS quad (and 8 floats per atom instead
// of 40). This stage computes what is the same at all four corners: the
// eye-space centre, the squared radius, the perspective growth of the
// square and so its half-size, the fog coordinate, the colour. sphere.geom
// expands the point to the quad. The operations are sphere.vert's, in its
// order, so the corners sphere.geom builds are bit-identical to
// sphere.vert's.
//
// State it reads:
//   uniform float perspective   1.0 perspective, 0.0 orthographic
//   gl_Vertex                   atom centre (w = 1)
//   gl_MultiTexCoord0.x         atom radius
//   gl_Color                    atom colour
//   gl_ModelViewMatrix
// It writes gl_Position = the object-space centre (w = 1; sphere.geom
// projects the corners, not this), gl_FogFragCoord (eye distance of the
// centre along z) and the varyings atom_center (eye space), atom_radius2,
// atom_half_size (radius times the perspective growth: x.frag's
// half_size), atom_extent (the corner offset along right and up: half
// size times the cover margin), atom_color.
//
// Same technique and fixes as sphere.vert (see its header: the growth of
// the square in perspective, the 2 % cover margin).

uniform float perspective;

varying vec3 atom_center;
varying float atom_radius2;
varying float atom_half_size;
varying float atom_extent;
varying vec4 atom_color;

// sphere.vert's margin (see there).
const float COVER_MARGIN = 1.02;

void main(void)
{
    float radius = gl_MultiTexCoord0.x;
    atom_radius2 = radius * radius;

    // Sphere centre in eye space.
    vec4 center4 = gl_ModelViewMatrix * vec4(gl_Vertex.xyz, 1.0);
    atom_center = center4.xyz / center4.w;

    // Perspective growth of the square (sphere.vert's header).
    float dist = length(atom_center);
    float cos_theta = clamp(-atom_center.z / max(dist, 1e-6), -1.0, 1.0);
    float sin_theta = sqrt(max(0.0, 1.0 - cos_theta * cos_theta));
    float sin_alpha = clamp(radius / max(dist, 1e-6), 0.0, 1.0);
    float cos_alpha = sqrt(max(0.0, 1.0 - sin_alpha * sin_alpha));
    float cos_edge = cos_theta * cos_alpha - sin_theta * sin_alpha;
    float grow = mix(1.0, 1.0 / max(cos_edge, 0.05), perspective);

    // sphere.vert's `radius * grow * COVER_MARGIN`, evaluated left to
    // right as there.
    atom_extent = radius * grow * COVER_MARGIN;
    atom_half_size = radius * grow;

    gl_FogFragCoord = abs(atom_center.z);
    atom_color = gl_Color;
    gl_Position = vec4(gl_Vertex.xyz, 1.0);
}
