// cylinder.vert: cylinder impostor billboard for bonds (vertex stage, for
// cylinder.frag).
//
// What it does: every cylinder (a bond, or half a bond in its atom's
// colour) is one GL_QUADS quad. All four vertices carry the whole
// cylinder: gl_Vertex = start point, gl_MultiTexCoord0 = (end point xyz,
// radius); gl_MultiTexCoord1.xy = (along, side) picks the corner: along 0
// at the start, 1 at the end; side -1 or +1. The shader projects both
// end points to the screen (x/-z in perspective, x in orthographic),
// takes the screen-space square each end's bounding sphere of the
// cylinder radius covers (grown in perspective as sphere.vert grows its
// square), and puts the corner on the hull of the two squares, back in
// the eye-space plane z = that end's z. The quad so covers the whole
// projected cylinder; cylinder.frag ray-casts it and discards the rest.
// It hands on the eye-space cylinder (base, unit axis, length, radius),
// the eye-space point on the quad and the colour.
//
// State it reads: uniform float perspective (1.0 perspective, 0.0
// orthographic); gl_Vertex, gl_MultiTexCoord0, gl_MultiTexCoord1,
// gl_Color, gl_ModelViewMatrix (affine), gl_ProjectionMatrix.
// It writes gl_Position, gl_ClipVertex, gl_FogFragCoord (eye distance
// along z of the cylinder's midpoint: fog per object, as sphere.vert does
// per atom) and the varyings color, point, cylinder_base, cylinder_axis,
// cylinder_length, cylinder_radius.
// Limitation: the whole cylinder must be in front of the eye.
//
// Written by the project (ball-and-stick goes beyond the seeds; the
// interface follows the seed talk's sphere impostors).

uniform float perspective;

varying vec4 color;
varying vec3 point;
varying vec3 cylinder_base;
varying vec3 cylinder_axis;
varying float cylinder_length;
varying float cylinder_radius;

// The quad is drawn 2 % wider than the bond's silhouette: at the exact
// width the silhouette runs along the quad's long edges, and a pixel the
// bond covers there is inside or outside the quad by each implementation's
// own sub-pixel snapping of the corners.
const float COVER_MARGIN = 1.02;

// Grown half-size of the square that covers a sphere of radius r at
// eye-space centre c (see sphere.vert).
float coverRadius(in vec3 c, in float r)
{
    float dist = length(c);
    float cos_theta = clamp(-c.z / max(dist, 1e-6), -1.0, 1.0);
    float sin_theta = sqrt(max(0.0, 1.0 - cos_theta * cos_theta));
    float sin_alpha = clamp(r / max(dist, 1e-6), 0.0, 1.0);
    float cos_alpha = sqrt(max(0.0, 1.0 - sin_alpha * sin_alpha));
    float cos_edge = cos_theta * cos_alpha - sin_theta * sin_alpha;
    return r * mix(1.0, 1.0 / max(cos_edge, 0.05), perspective);
}

void main(void)
{
    vec3 a = (gl_ModelViewMatrix * vec4(gl_Vertex.xyz, 1.0)).xyz;
    vec3 b = (gl_ModelViewMatrix * vec4(gl_MultiTexCoord0.xyz, 1.0)).xyz;
    float r = gl_MultiTexCoord0.w;
    float along = gl_MultiTexCoord1.x;
    float side = gl_MultiTexCoord1.y;

    vec3 d = b - a;
    float len = length(d);
    cylinder_base = a;
    cylinder_axis = len > 0.0 ? d / len : vec3(0.0, 0.0, 1.0);
    cylinder_length = len;
    cylinder_radius = r;

    // Screen positions (x/-z or x) and half-sizes of the ends' squares.
    float sa = mix(1.0, 1.0 / max(-a.z, 1e-6), perspective);
    float sb = mix(1.0, 1.0 / max(-b.z, 1e-6), perspective);
    vec2 pa = a.xy * sa;
    vec2 pb = b.xy * sb;
    float h = max(coverRadius(a, r) * sa, coverRadius(b, r) * sb) * COVER_MARGIN;
    vec2 axis2 = pb - pa;
    float axis2_len = length(axis2);
    vec2 dir = axis2_len > 1e-9 ? axis2 / axis2_len : vec2(1.0, 0.0);
    vec2 perp = vec2(-dir.y, dir.x);

    // The corner, on the hull of the two squares, back in eye space.
    vec3 end = mix(a, b, along);
    vec2 screen = mix(pa, pb, along) + (2.0 * along - 1.0) * h * dir + side * h * perp;
    float back = mix(1.0, max(-end.z, 1e-6), perspective);
    vec4 eye = vec4(screen * back, end.z, 1.0);

    point = eye.xyz;
    color = gl_Color;
    gl_FogFragCoord = abs(0.5 * (a.z + b.z));
    gl_ClipVertex = eye;
    gl_Position = gl_ProjectionMatrix * eye;
}
