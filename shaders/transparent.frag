// transparent.frag: screen-door transparency on red atoms (fragment
// stage, with sphere.vert).
//
// What it does: sphere.frag's ray-cast, depth, lighting and fog, except
// that atoms whose colour is mostly red (r > 0.7, g < 0.3, b < 0.3:
// oxygen in the element colours) discard every other pixel in a
// checkerboard, so what lies behind them shows through the holes: a 50%
// transparency without blending or sorting (the seed talk's "Example 04:
// Transparent atoms"). Supersampled renders average the checkerboard into
// a smooth 50% blend.
//
// State it reads: as sphere.frag (perspective, viewport, fogging[4],
// light_enabled[8], the lights, front material, fog, projection matrix,
// depth range) plus gl_FragCoord; per-atom "is red" comes from the atom
// colour (gl_Color through the varying `color`), as in the seed.
//
// Fixes of the seed talk's text ("GLSL v1.20", Example 04):
// - `int(abs(gl_FragCoord.x + gl_FragCoord.y)) % 2`: `%` is reserved in
//   GLSL 1.10/1.20 (a compile error); the same checkerboard is now
//   mod(floor(x) + floor(y), 2.0) on floats.
// - A misplaced brace: main()'s closing `}` stands inside the unfinished
//   final `gl_FragColor = mix(gl_Fog.color, color * (diffuse + ambient +`
//   line (a syntax error, and main never closed); the statement is whole
//   here and main is closed after it.
// - The exp2 fog term: the seed's transparent shader computes
//   density * c^3 (its other shaders density^2 * c^2); GL_EXP2 fog is
//   exp(-(density * c)^2), as here.
// - The unused `varying float depth_level` (written by no vertex shader)
//   is dropped.
// - Same fixes as sphere.frag: the eye ray from gl_FragCoord and the
//   viewport uniform, the well-conditioned ray-sphere test,
//   gl_DepthRange-aware depth, light_enabled[8] instead of the hard-wired
//   lights 0 and 1, alpha from the atom colour.

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

    // 50% "cheesy transparency" on mostly red atoms (oxygen): discard
    // every other pixel in a checkerboard (the seed's
    // int(abs(x + y)) % 2 == 1 at pixel centres x, y = n + 0.5, i.e. the
    // pixels whose integer coordinates have an even sum).
    if (color.r > 0.7 && color.g < 0.3 && color.b < 0.3 &&
        mod(floor(gl_FragCoord.x) + floor(gl_FragCoord.y), 2.0) < 0.5)
        discard;

    // Nearest intersection (towards the viewer).
    float root = sqrt(position * vv);
    vec3 ipoint = o + ((dot(w, v) - root) / vv) * v;
    // ipoint - c = -(v x across + root v) / |v|^2, without the
    // cancellation of two points far from the eye.
    vec3 N = normalize(cross(across, v) - root * v);

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
