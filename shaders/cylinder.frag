// cylinder.frag: cylinder impostor ray-caster for bonds (fragment stage;
// vertex: cylinder.vert).
//
// What it does: intersects the eye ray through the pixel centre (from
// gl_FragCoord, the viewport uniform and the projection, as sphere.frag
// does and for its reason: perspective from the eye, orthographic along
// -z) with the infinite cylinder (cylinder_base, unit cylinder_axis,
// cylinder_radius), keeps the nearest hit, and discards the fragment when
// the ray misses or the hit lies beyond either end (0 to cylinder_length
// along the axis: the cylinder is open, its ends are meant to be inside
// atom spheres or to meet the other half of the bond). A hit gets the
// true depth of the surface point in gl_FragDepth, so bonds and atoms cut
// each other where they meet, and the lighting and fog of sphere.frag:
// lights 0-7 switched by light_enabled[8] (directional, Blinn-Phong with
// the front light products), fixed-function fog chosen by fogging[4].
//
// State it reads: uniform float perspective, vec4 viewport, fogging[4],
// light_enabled[8]; gl_LightSource[i].position/.halfVector,
// gl_FrontLightProduct[i], gl_FrontMaterial.emission/.shininess, gl_Fog,
// gl_FogFragCoord, gl_ProjectionMatrix, gl_DepthRange, gl_FragCoord;
// varyings from cylinder.vert (all but `point`, which the ray replaces).
//
// Written by the project (no seed has cylinders; lighting, fog and depth
// are sphere.frag's, so spheres and cylinders match).
//
// Precision: the quadratic is solved for the ray re-centred at its point
// nearest the cylinder's base, not at the eye: from the eye, the squared
// distances are about distance^2 and the radius^2 term (0.03 for the
// renderer's bonds) drowns in their rounding in f32, which made
// perspective bonds noisy.

uniform float fogging[4];
uniform float perspective;
uniform vec4 viewport;
uniform float light_enabled[8];

varying vec4 color;
varying vec3 cylinder_base;
varying vec3 cylinder_axis;
varying float cylinder_length;
varying float cylinder_radius;

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
    // normalised, v.z = -1), from gl_FragCoord and the projection, as in
    // sphere.frag (see its header).
    vec2 ndc = (gl_FragCoord.xy - viewport.xy) * 2.0 / viewport.zw - 1.0;
    vec2 scale = vec2(gl_ProjectionMatrix[0][0], gl_ProjectionMatrix[1][1]);
    vec3 o = mix(vec3((ndc - gl_ProjectionMatrix[3].xy) / scale, 0.0), vec3(0.0),
                 perspective);
    vec3 v = mix(vec3(0.0, 0.0, -1.0),
                 vec3((ndc + gl_ProjectionMatrix[2].xy) / scale, -1.0), perspective);

    // |w' + s v'|^2 = r^2 with the components across the axis, the ray
    // re-centred at t0, its closest approach to cylinder_base: w is then
    // a short vector, ((b x v) x v) / |v|^2 with b = base - o, taken
    // without subtracting two points far from the eye, and qc does not
    // lose r^2 next to the squared distance from the eye (see the header).
    vec3 axis = normalize(cylinder_axis);
    vec3 b = cylinder_base - o;
    float vv = dot(v, v);
    float t0 = dot(b, v) / vv;
    vec3 w = cross(cross(b, v), v) / vv;
    vec3 dp = v - dot(v, axis) * axis;
    vec3 wp = w - dot(w, axis) * axis;
    float qa = dot(dp, dp);
    float qb = dot(wp, dp);
    float qc = dot(wp, wp) - cylinder_radius * cylinder_radius;
    float disc = qb * qb - qa * qc;
    if (qa < 1e-12 || disc < 0.0)
        discard;
    float s = (-qb - sqrt(disc)) / qa;
    vec3 rel = w + s * v;  // the hit less cylinder_base
    float h = dot(rel, axis);
    if (h < 0.0 || h > cylinder_length)
        discard;
    vec3 ipoint = o + (t0 + s) * v;
    vec3 N = normalize(rel - h * axis);

    // Window depth of the surface point.
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
}
