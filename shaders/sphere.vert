// sphere.vert: sphere impostor billboard (vertex stage).
//
// What it does: every atom is drawn as one GL_QUADS quad whose four
// vertices all sit at the atom centre (gl_Vertex). Each vertex carries its
// corner in gl_MultiTexCoord0 = (right, up, radius), right and up being
// +1 or -1. The shader pushes the vertex out to that corner of a
// screen-aligned square around the centre, so the quad covers the sphere
// on screen, and hands the fragment stage what it needs to ray-cast the
// sphere (sphere.frag): the eye-space centre, squared radius, the
// eye-space point on the quad, the colour.
//
// State it reads:
//   uniform vec3 right_vector, up_vector  object-space directions that the
//                                         model-view maps to eye +x and +y
//                                         (unit length)
//   uniform float perspective             1.0 perspective, 0.0 orthographic
//   gl_Vertex                             atom centre (w = 1)
//   gl_MultiTexCoord0                     (right, up, radius)
//   gl_Color                              atom colour
//   gl_ModelViewMatrix, gl_ModelViewProjectionMatrix
// It writes gl_Position, gl_ClipVertex (eye space, for user clip planes),
// gl_FogFragCoord (eye distance of the atom centre along z) and the
// varyings color, view_direction, sphere_center, radius2, point.
//
// Changes from the seed talk ("GLSL v1.20", Example 03, sphere vertex
// shader), which this follows otherwise:
// - In perspective the seed's square of half-size `radius` in the plane of
//   the centre is too small: the eye sees the sphere's silhouette cone cut
//   that plane in an ellipse reaching up to radius / cos(theta + alpha)
//   from the centre (theta: angle between the view axis and the centre,
//   alpha = asin(radius / distance)), so the seed clips the rims of
//   off-centre or near spheres. The square is grown by that factor here
//   (orthographic: factor 1, as in the seed).
// - The seed's comment about sqrt(2) is kept in spirit: corner_direction
//   has length sqrt(2), so the square's half-size is radius (times the
//   factor above) along right_vector and up_vector.

uniform vec3 right_vector;
uniform vec3 up_vector;
uniform float perspective;

varying vec4 color;
varying vec3 view_direction;
varying vec3 sphere_center;
varying float radius2;
varying vec3 point;

// The square is drawn 2 % larger than the silhouette it must cover: at
// the exact size the silhouette touches the square's edges, and a pixel the
// sphere covers there is inside or outside the square by each
// implementation's own sub-pixel snapping of the corners.
const float COVER_MARGIN = 1.02;

void main(void)
{
    // Billboard attributes.
    float right = gl_MultiTexCoord0.x;
    float up = gl_MultiTexCoord0.y;
    float radius = gl_MultiTexCoord0.z;
    radius2 = radius * radius;

    // Sphere centre in eye space.
    vec4 center4 = gl_ModelViewMatrix * vec4(gl_Vertex.xyz, 1.0);
    sphere_center = center4.xyz / center4.w;

    // Perspective growth of the square (see the header).
    float dist = length(sphere_center);
    float cos_theta = clamp(-sphere_center.z / max(dist, 1e-6), -1.0, 1.0);
    float sin_theta = sqrt(max(0.0, 1.0 - cos_theta * cos_theta));
    float sin_alpha = clamp(radius / max(dist, 1e-6), 0.0, 1.0);
    float cos_alpha = sqrt(max(0.0, 1.0 - sin_alpha * sin_alpha));
    float cos_edge = cos_theta * cos_alpha - sin_theta * sin_alpha;
    float grow = mix(1.0, 1.0 / max(cos_edge, 0.05), perspective);

    // Corner of the screen-aligned square (billboard), object space.
    vec3 corner_direction = up * up_vector + right * right_vector;
    vec4 vertex = vec4(gl_Vertex.xyz + (radius * grow * COVER_MARGIN) * corner_direction,
                       1.0);

    vec4 eye_space_pos = gl_ModelViewMatrix * vertex;

    // Ray origin (orthographic) / direction (perspective) data.
    point = eye_space_pos.xyz / eye_space_pos.w;
    view_direction = normalize(point);

    gl_FogFragCoord = abs(sphere_center.z);
    gl_ClipVertex = eye_space_pos;
    color = gl_Color;
    gl_Position = gl_ModelViewProjectionMatrix * vertex;
}
