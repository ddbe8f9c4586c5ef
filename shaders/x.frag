// x.frag: a dark X on every atom (fragment stage, with x.vert).
//
// What it does: sphere.frag's ray-cast, depth and lighting, except that on
// the two diagonals of the atom's quad (where |u1| = |r1|, u1 and r1 the
// pixel's coordinates on the quad, corners at +-1) the surface normal is
// inverted, so the lights face its back and only ambient light remains:
// a dark, unlit X across each sphere (the seed talk's "Example 02: X").
//
// State it reads: as sphere.frag (perspective, viewport, fogging[4],
// light_enabled[8], the lights, front material, fog, projection matrix,
// depth range, gl_FragCoord) plus the varying half_size from x.vert.
//
// Fixes of the seed talk's text ("GLSL v1.20", Example 02, X fragment
// shader; it compiles as given, its indentation lost at a page break):
// - Same fixes as sphere.frag: the exp2 fog term, the eye ray from
//   gl_FragCoord, the well-conditioned ray-sphere test,
//   gl_DepthRange-aware depth, light_enabled[8]
//   instead of the hard-wired lights 0 and 1, alpha from the atom colour.

uniform float fogging[4];
uniform float perspective;
uniform vec4 viewport;
uniform float light_enabled[8];

varying vec4 color;
varying vec3 view_direction;
varying vec3 sphere_center;
varying float radius2;
varying vec3 point;

varying float half_size;

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

    // The pixel's coordinates on the atom's square, corners at +-1 (the
    // seed's interpolated u1, r1): where the ray crosses the square's
    // plane z = c.z, less the centre, is (-across.y, across.x) in both
    // projections.
    float r1 = -across.y / half_size;
    float u1 = across.x / half_size;

    // Nearest intersection (towards the viewer).
    float root = sqrt(position * vv);
    vec3 ipoint = o + ((dot(w, v) - root) / vv) * v;
    // ipoint - c = -(v x across + root v) / |v|^2, without the
    // cancellation of two points far from the eye.
    vec3 N = normalize(cross(across, v) - root * v);

    // The X: on the quad's diagonals (|u1| = |r1|, 0.1 wide in corner
    // units) the normal is turned round, which leaves the surface unlit
    // (ambient only): a cheap dark X.
    if (abs(abs(u1) - abs(r1)) < 0.1)
        N = -N;

    // Window depth of the surface point.
    vec2 clipZW = ipoint.z * gl_ProjectionMatrix[2].zw + gl_ProjectionMatrix[3].zw;
    float ndc_z = clipZW.x / clipZW.y;
    gl_FragDepth = gl_DepthRange.near + gl_DepthRange.diff * (0.5 + 0.5 * ndc_z);

    // Lighting.
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

    // Fog factor (1: no fog, 0: all fog colour), fixed-function formulas.
    float c = gl_FogFragCoord;
    float fog = fogging[0];
    fog += mix(0.0, clamp((gl_Fog.end - c) * gl_Fog.scale, 0.0, 1.0), fogging[1]);
    fog += mix(0.0, clamp(exp(-gl_Fog.density * c), 0.0, 1.0), fogging[2]);
    fog += mix(0.0, clamp(exp2(-gl_Fog.density * gl_Fog.density * c * c * INV_LOG2),
                          0.0, 1.0), fogging[3]);

    vec4 lit = color * (diffuse + ambient + gl_FrontMaterial.emission) + specular;
    gl_FragColor = vec4(mix(gl_Fog.color.rgb, lit.rgb, fog), color.a);
}
