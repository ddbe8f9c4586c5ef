// outline.frag: outlines of the structure (fragment stage, with sphere.vert).
//
// What it does: ray-casts the atom's sphere like sphere.frag, but lights
// only a thin rim at the sphere's silhouette; the rest of the disc is
// black and keeps the depth of the billboard quad (the plane through the
// sphere centre) instead of the surface depth. Neighbouring atoms' black
// interiors therefore erase each other's rims where they overlap, and
// what survives is a lit line around the outside of the structure
// (the seed talk's "Example 01: Outlines").
//
// State it reads:
//   uniform float outline_width     rim width in eye-space units (the
//                                   renderer sets about 1.5 pixels)
//   uniform float perspective       1.0 perspective, 0.0 orthographic
//   uniform float fogging[4]        one-hot fog mode: none, linear, exp, exp2
//   uniform float light_enabled[8]  1.0 for each GL light to use
//   gl_LightSource[i], gl_FrontLightProduct[i], gl_FrontMaterial,
//   gl_Fog, gl_FogFragCoord, gl_ProjectionMatrix, gl_DepthRange,
//   gl_FragCoord
//   uniform vec4 viewport (as sphere.frag: the pixel's eye ray)
//   varyings from sphere.vert: color, sphere_center, radius2
//
// Fixes of the seed talk's text ("GLSL v1.20", Example 01, outline
// fragment shader):
// - Unbalanced braces: in the seed a `}` closes the `if (position < 0.1) {`
//   block and the next `}` closes main() right after the depth is
//   written, so the lighting, fog and `else { black }` code lands at
//   global scope (6 `}` for 4 `{`; no compiler accepts it). Here the rim
//   branch holds the depth, lighting and fog, the else branch the black.
// - Rim test: the seed's `position < 0.1` compares r^2 - d^2 (d: distance
//   of the ray from the centre) with a constant in square scene units, a
//   rim 0.03 A wide on a carbon atom: less than a pixel at usual sizes,
//   and thinner on bigger atoms. The rim is now `outline_width` wide on
//   every atom: d > r - outline_width.
// - Interior depth: the seed leaves gl_FragDepth unwritten on the black
//   path, which GLSL 1.20 section 7.2 makes undefined once a shader
//   assigns gl_FragDepth anywhere; the black path now writes the quad's
//   own depth ("without adjusting the Z value"), taken as the depth of
//   its plane z = c.z rather than the interpolated gl_FragCoord.z (equal
//   in exact arithmetic; interpolation rounds differently in every
//   implementation, which moved where a neighbour's rim survives).
// - Same fixes as sphere.frag: the eye ray from gl_FragCoord, the
//   well-conditioned ray-sphere test, gl_DepthRange-aware depth,
//   light_enabled[8] instead of lights 0 and 1.

uniform float outline_width;
uniform float fogging[4];
uniform float perspective;
uniform vec4 viewport;
uniform float light_enabled[8];

varying vec4 color;
varying vec3 view_direction;
varying vec3 sphere_center;
varying float radius2;
varying vec3 point;

const float INV_LOG2 = 1.442695;

void getLight(in int light, in vec3 N, inout vec4 ambient, inout vec4 diffuse,
              inout vec4 specular)
{
    vec3 L = normalize(gl_LightSource[light].position.xyz);
    vec3 H = normalize(gl_LightSource[light].halfVector.xyz);
    diffuse += max(0.0, dot(N, L)) * gl_FrontLightProduct[light].diffuse;
    specular += pow(max(0.0, dot(N, H)), gl_FrontMaterial.shininess) *
                gl_FrontLightProduct[light].specular;
    ambient += gl_FrontLightProduct[light].ambient;
}

void main(void)
{
    // The eye-space ray through this pixel's centre, o + t * v (v not
    // normalised, v.z = -1), from gl_FragCoord, as in sphere.frag.
    vec2 ndc = (gl_FragCoord.xy - viewport.xy) * 2.0 / viewport.zw - 1.0;
    vec2 scale = vec2(gl_ProjectionMatrix[0][0], gl_ProjectionMatrix[1][1]);
    vec3 o = mix(vec3((ndc - gl_ProjectionMatrix[3].xy) / scale, 0.0), vec3(0.0),
                 perspective);
    vec3 v = mix(vec3(0.0, 0.0, -1.0),
                 vec3((ndc + gl_ProjectionMatrix[2].xy) / scale, -1.0), perspective);

    // |o + t v - c|^2 = r^2. The centre's distance d from the ray is
    // |(c - o) x v| / |v|: a cross product of the centre's offset, no
    // difference of squared distances from the eye (see the header).
    vec3 w = sphere_center - o;
    vec3 across = cross(w, v);
    float vv = dot(v, v);
    float position = radius2 - dot(across, across) / vv;  // r^2 - d^2
    if (position < 0.0)
        discard;

    // Rim: distance d of the ray from the centre beyond r - outline_width,
    // i.e. position = r^2 - d^2 < r^2 - (r - outline_width)^2.
    float inner = max(sqrt(radius2) - outline_width, 0.0);
    if (position < radius2 - inner * inner) {
        float root = sqrt(position * vv);
        vec3 ipoint = o + ((dot(w, v) - root) / vv) * v;
        // ipoint - c = -(v x across + root v) / |v|^2, without the
        // cancellation of two points far from the eye.
        vec3 N = normalize(cross(across, v) - root * v);

        vec2 clipZW = ipoint.z * gl_ProjectionMatrix[2].zw + gl_ProjectionMatrix[3].zw;
        float ndc_z = clipZW.x / clipZW.y;
        gl_FragDepth = gl_DepthRange.near + gl_DepthRange.diff * (0.5 + 0.5 * ndc_z);

        vec4 ambient = vec4(0.0, 0.0, 0.0, 1.0);
        vec4 diffuse = vec4(0.0, 0.0, 0.0, 1.0);
        vec4 specular = vec4(0.0, 0.0, 0.0, 1.0);
        for (int i = 0; i < 8; i++) {
            if (light_enabled[i] > 0.5)
                getLight(i, N, ambient, diffuse, specular);
        }
        ambient.w = 1.0;
        diffuse.w = 1.0;
        specular.w = 1.0;

        float c = gl_FogFragCoord;
        float fog = fogging[0];
        fog += mix(0.0, clamp((gl_Fog.end - c) * gl_Fog.scale, 0.0, 1.0), fogging[1]);
        fog += mix(0.0, clamp(exp(-gl_Fog.density * c), 0.0, 1.0), fogging[2]);
        fog += mix(0.0, clamp(exp2(-gl_Fog.density * gl_Fog.density * c * c * INV_LOG2),
                              0.0, 1.0), fogging[3]);

        vec4 lit = color * (diffuse + ambient + gl_FrontMaterial.emission) + specular;
        gl_FragColor = vec4(mix(gl_Fog.color.rgb, lit.rgb, fog), color.a);
    } else {
        // The quad's own depth: its plane z = c.z, from the centre rather
        // than the interpolated gl_FragCoord.z (the same in exact
        // arithmetic; each implementation rounds the interpolation its own
        // way, which moved where a neighbour's rim shows).
        vec2 centerZW = sphere_center.z * gl_ProjectionMatrix[2].zw + gl_ProjectionMatrix[3].zw;
        gl_FragDepth = gl_DepthRange.near + gl_DepthRange.diff * (0.5 + 0.5 * centerZW.x / centerZW.y);
        gl_FragColor = vec4(0.0, 0.0, 0.0, color.a);
    }
}
