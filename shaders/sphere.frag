// sphere.frag: sphere impostor ray-caster (fragment stage).
//
// What it does: for each pixel of the billboard quad written by
// sphere.vert, intersects the eye ray with the atom's sphere; misses are
// discarded, hits get the true depth of the sphere surface in
// gl_FragDepth (so intersecting spheres cut each other correctly), a
// per-pixel lighting of the surface normal with the front material and up
// to eight GL lights, and the fixed-function fog of the chosen mode.
//
// State it reads:
//   uniform float perspective       1.0 perspective, 0.0 orthographic
//   uniform float fogging[4]        one-hot fog mode: [0] none, [1] linear,
//                                   [2] exp, [3] exp2 (exactly one is 1.0)
//   uniform float light_enabled[8]  1.0 for each GL light to use, else 0.0
//                                   (the seed's "variable lights")
//   gl_LightSource[i].position, .halfVector (directional lights, eye space)
//   gl_FrontLightProduct[i].ambient/.diffuse/.specular,
//   gl_FrontMaterial.emission/.shininess
//   gl_Fog.color/.density/.end/.scale, gl_FogFragCoord
//   gl_ProjectionMatrix, gl_DepthRange
//   varyings from sphere.vert: color, sphere_center, radius2, point
//   (view_direction is declared for interface compatibility with the seed)
//
// Fixes of the seed talk's text ("GLSL v1.20", Example 03 and 04):
// - Exp2 fog: the seed computes exp2(-density * c * c * c / ln 2), i.e.
//   density * c^3, a transcription slip; GL_EXP2 fog (GL 2.1 section 3.10)
//   is exp(-(density * c)^2) = exp2(-density^2 * c^2 / ln 2). Fixed here.
// - Perspective ray direction: the seed re-normalises the interpolated
//   view_direction; interpolated unit vectors are not the direction to
//   the pixel, so the ray is now normalize(point), exact for every pixel.
// - Ray-sphere test: the seed's r^2 - d^2 = b^2 + r^2 - |c|^2 subtracts two
//   nearly equal large numbers in perspective (b^2 and |c|^2 are about
//   distance^2, 360,000 at 600 units from the eye, where f32 keeps only
//   steps of 0.03), so the hit test and the surface point came out noisy;
//   d^2 is now |c - b * ray|^2, the squared length of a vector no longer
//   than the radius, accurate to a few ulps. The same value in exact
//   arithmetic.
// - Depth: the seed writes 0.5 + 0.5 * z/w, right only for the default
//   glDepthRange(0, 1); this uses gl_DepthRange.
// - Lights: the seed's two hard-wired getLight(0..1) calls become its own
//   variable-lights scheme (light_enabled[8]), skipping disabled lights.
// - Alpha: the seed's lit alpha saturates to 1; here it is the atom
//   colour's alpha, as its materials shader does.
// The seed's mismatched braces are in its outline/transparent variants,
// not in this pair (fixed in outline.frag and transparent.frag).

uniform float fogging[4];
uniform float perspective;
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
    // Orthographic: rays along +z (towards the viewer) through the quad
    // point. Perspective: rays from the eye through the quad point.
    vec3 ray_origin = mix(point, vec3(0.0), perspective);
    vec3 ray_direction = mix(vec3(0.0, 0.0, 1.0), normalize(point), perspective);
    vec3 sphere_direction = mix(ray_origin - sphere_center, sphere_center,
                                perspective);

    // |origin + t * direction - center|^2 = radius^2
    float b = dot(sphere_direction, ray_direction);
    // r^2 - d^2, d the distance of the centre from the ray, with d^2 taken
    // as |sphere_direction - b * ray_direction|^2 (see the header).
    vec3 perpendicular = sphere_direction - b * ray_direction;
    float position = radius2 - dot(perpendicular, perpendicular);
    if (position < 0.0)
        discard;

    // Nearest intersection (towards the viewer).
    float nearest = mix(sqrt(position) - b, b - sqrt(position), perspective);
    vec3 ipoint = nearest * ray_direction + ray_origin;
    vec3 N = normalize(ipoint - sphere_center);

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
