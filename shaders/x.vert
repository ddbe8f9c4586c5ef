// x.vert: sphere impostor billboard that also hands on the quad corner
// (vertex stage, for x.frag and x-red.frag).
//
// What it does: exactly what sphere.vert does (see its header: one
// screen-aligned quad per atom, corners in gl_MultiTexCoord0 =
// (right, up, radius)), and besides hands on the square's half-size in
// eye space (half_size), so the fragment shaders can place the pixel on
// the quad with corners at +-1 (the seed's u1, r1) from the pixel's own
// ray; |u1| = |r1| on the quad's two diagonals, where they draw the X.
//
// State it reads: as sphere.vert (right_vector, up_vector, perspective,
// gl_Vertex, gl_MultiTexCoord0, gl_Color, the model-view and projection
// matrices). It writes sphere.vert's outputs plus half_size.
//
// Changes from the seed talk ("GLSL v1.20", Example 02, X vertex shader):
// the seed's X vertex shader is its sphere vertex shader plus u1/r1, and
// compiles as given; it gets sphere.vert's perspective growth of the
// square (the seed clips the rims of off-centre spheres in perspective),
// and half_size replaces the interpolated u1, r1: an interpolated corner
// coordinate carries each implementation's own rounding of the quad's
// corners, which moved the X's edges by a pixel here and there.

uniform vec3 right_vector;
uniform vec3 up_vector;
uniform float perspective;

varying vec4 color;
varying vec3 view_direction;
varying vec3 sphere_center;
varying float radius2;
varying vec3 point;

varying float half_size;

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
    // The square's half-size in eye space (x.frag, x-red.frag): corners
    // at +-1 in units of it.
    half_size = radius * grow;

    vec4 eye_space_pos = gl_ModelViewMatrix * vertex;

    // Ray origin (orthographic) / direction (perspective) data.
    point = eye_space_pos.xyz / eye_space_pos.w;
    view_direction = normalize(point);

    gl_FogFragCoord = abs(sphere_center.z);
    gl_ClipVertex = eye_space_pos;
    color = gl_Color;
    gl_Position = gl_ModelViewProjectionMatrix * vertex;
}
