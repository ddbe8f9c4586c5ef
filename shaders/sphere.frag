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
//   uniform vec4 viewport           the glViewport rectangle (x, y, width,
//                                   height) in pixels: with gl_FragCoord
//                                   and gl_ProjectionMatrix it gives the
//                                   pixel's eye ray
//   uniform float fogging[4]        one-hot fog mode: [0] none, [1] linear,
//                                   [2] exp, [3] exp2 (exactly one is 1.0)
//   uniform float light_enabled[8]  1.0 for each GL light to use, else 0.0
//                                   (the seed's "variable lights")
//   gl_LightSource[i].position, .halfVector (directional lights, eye space)
//   gl_FrontLightProduct[i].ambient/.diffuse/.specular,
//   gl_FrontMaterial.emission/.shininess
//   gl_Fog.color/.density/.end/.scale, gl_FogFragCoord
//   gl_ProjectionMatrix, gl_DepthRange, gl_FragCoord
//   varyings from sphere.vert: color, sphere_center, radius2 (point and
//   view_direction are declared for interface compatibility with the seed)
//
// Fixes of the seed talk's text ("GLSL v1.20", Example 03 and 04):
// - Exp2 fog: the seed computes exp2(-density * c * c * c / ln 2), i.e.
//   density * c^3, a transcription slip; GL_EXP2 fog (GL 2.1 section 3.10)
//   is exp(-(density * c)^2) = exp2(-density^2 * c^2 / ln 2). Fixed here.
// - The eye ray: the seed takes it from the interpolated varying `point`
//   (orthographic: along z through it; perspective: re-normalising the
//   interpolated view_direction, which is not the direction to the
//   pixel). Here it comes from gl_FragCoord, the `viewport` uniform and
//   the projection: the exact ray through the pixel centre, and the same
//   one in every implementation. An interpolated point carries each
//   implementation's own rounding (GL leaves sub-pixel precision to the
//   implementation; the quad's corners are snapped differently), enough to
//   move a ray that grazes the sphere across its silhouette: one
//   implementation then discards the pixel and another draws it (against
//   Mesa, 1-10 such pixels per image, up to 234/255 apart).
// - Ray-sphere test: the seed's r^2 - d^2 = b^2 + r^2 - |c|^2 subtracts two
//   nearly equal large numbers in perspective (b^2 and |c|^2 are about
//   distance^2, 360,000 at 600 units from the eye, where f32 keeps only
//   steps of 0.03), so the hit test and the surface point came out noisy;
//   d^2 is now |(c - o) x v|^2 / |v|^2 (o + t v the ray), a cross product
//   of the centre's offset, accurate to a few ulps of r^2, and the normal
//   is taken from the same cross product instead of subtracting the centre
//   from the hit point. The same values in exact arithmetic.
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
    // normalised, v.z = -1), from gl_FragCoord (the same exact pixel centre
    // in every implementation) and the projection: orthographic rays run
    // along -z from z = 0, perspective ones from the eye. An interpolated
    // eye-space point would carry each implementation's own rounding of the
    // quad's vertices (up to half a sub-pixel), enough to move a grazing
    // ray across the silhouette.
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
