// phong-lighting-lib.frag: library object of per-pixel Phong lighting by
// directional, point and spot lights (fragment stage; linked with
// one-sided-lighting.frag or two-sided-lighting.frag; vertex stage
// lighting.vert).
//
// What it provides:
//   void calculateLighting(in int numLights, in vec3 N, in vec3 V,
//                          in float shininess, inout vec4 ambient,
//                          inout vec4 diffuse, inout vec4 specular)
// adds to ambient/diffuse/specular the light colours (not yet multiplied
// by a material) of GL lights 0 .. numLights-1 at the eye-space point V
// with unit normal N:
// - a light counts as on unless its ambient is (0,0,0,1) and its diffuse
//   and specular are (0,0,0,0), GL's defaults for lights 1-7 (GLSL has no
//   built-in "enabled" flag): a program switches a light off for these
//   shaders by setting those colours, not only by glDisable;
// - position.w == 0: directional light, Blinn-Phong specular with the
//   light's half vector, no attenuation;
// - spotCutoff == 180: point light; else spot light (spotDirection,
//   spotCosCutoff, spotExponent); both attenuated by
//   1 / (constant + linear d + quadratic d^2) and with Phong specular
//   (reflect(-L, N) against the direction to the eye, the eye at the
//   origin: a local viewer).
//
// State it reads: gl_LightSource[0 .. numLights-1] (all fields).
//
// Fixes of the seed ("Creating a GLSL Library", PhongLighting.frag):
// - The seed's calculateLighting calls directionalLight, pointLight and
//   spotLight before they are declared (it does not compile); prototypes
//   are added at the top.
// - The half vector of directional lights is normalised (the seed uses it
//   as given; GL does not promise a unit vector there).
// - Spot lights: the seed adds the attenuated ambient even outside the
//   cone or for surfaces facing away; GL's spotlight factor (0 outside the
//   cone, (cos)^exponent inside) applies to all three terms, and the
//   cone test does not depend on the surface, so it is computed first.

const vec4 AMBIENT_BLACK = vec4(0.0, 0.0, 0.0, 1.0);
const vec4 DEFAULT_BLACK = vec4(0.0, 0.0, 0.0, 0.0);

void directionalLight(in int i, in vec3 N, in float shininess,
                      inout vec4 ambient, inout vec4 diffuse, inout vec4 specular);
void pointLight(in int i, in vec3 N, in vec3 V, in float shininess,
                inout vec4 ambient, inout vec4 diffuse, inout vec4 specular);
void spotLight(in int i, in vec3 N, in vec3 V, in float shininess,
               inout vec4 ambient, inout vec4 diffuse, inout vec4 specular);

bool isLightEnabled(in int i)
{
    return !(gl_LightSource[i].ambient == AMBIENT_BLACK &&
             gl_LightSource[i].diffuse == DEFAULT_BLACK &&
             gl_LightSource[i].specular == DEFAULT_BLACK);
}

void calculateLighting(in int numLights, in vec3 N, in vec3 V, in float shininess,
                       inout vec4 ambient, inout vec4 diffuse, inout vec4 specular)
{
    for (int i = 0; i < numLights; i++) {
        if (isLightEnabled(i)) {
            if (gl_LightSource[i].position.w == 0.0)
                directionalLight(i, N, shininess, ambient, diffuse, specular);
            else if (gl_LightSource[i].spotCutoff == 180.0)
                pointLight(i, N, V, shininess, ambient, diffuse, specular);
            else
                spotLight(i, N, V, shininess, ambient, diffuse, specular);
        }
    }
}

float calculateAttenuation(in int i, in float dist)
{
    return 1.0 / (gl_LightSource[i].constantAttenuation +
                  gl_LightSource[i].linearAttenuation * dist +
                  gl_LightSource[i].quadraticAttenuation * dist * dist);
}

void directionalLight(in int i, in vec3 N, in float shininess,
                      inout vec4 ambient, inout vec4 diffuse, inout vec4 specular)
{
    vec3 L = normalize(gl_LightSource[i].position.xyz);
    float n_dot_l = dot(N, L);
    if (n_dot_l > 0.0) {
        vec3 H = normalize(gl_LightSource[i].halfVector.xyz);
        float pf = pow(max(dot(N, H), 0.0), shininess);
        diffuse += gl_LightSource[i].diffuse * n_dot_l;
        specular += gl_LightSource[i].specular * pf;
    }
    ambient += gl_LightSource[i].ambient;
}

// Diffuse and Phong specular of a local light at eye-space direction L,
// scaled by `factor` (attenuation times spotlight factor).
void localLight(in int i, in vec3 N, in vec3 V, in vec3 L, in float shininess,
                in float factor, inout vec4 ambient, inout vec4 diffuse,
                inout vec4 specular)
{
    float n_dot_l = dot(N, L);
    if (n_dot_l > 0.0) {
        vec3 E = normalize(-V);
        vec3 R = reflect(-L, N);
        float pf = pow(max(dot(R, E), 0.0), shininess);
        diffuse += gl_LightSource[i].diffuse * factor * n_dot_l;
        specular += gl_LightSource[i].specular * factor * pf;
    }
    ambient += gl_LightSource[i].ambient * factor;
}

void pointLight(in int i, in vec3 N, in vec3 V, in float shininess,
                inout vec4 ambient, inout vec4 diffuse, inout vec4 specular)
{
    vec3 D = gl_LightSource[i].position.xyz - V;
    float attenuation = calculateAttenuation(i, length(D));
    localLight(i, N, V, normalize(D), shininess, attenuation, ambient, diffuse, specular);
}

void spotLight(in int i, in vec3 N, in vec3 V, in float shininess,
               inout vec4 ambient, inout vec4 diffuse, inout vec4 specular)
{
    vec3 D = gl_LightSource[i].position.xyz - V;
    vec3 L = normalize(D);
    float attenuation = calculateAttenuation(i, length(D));
    float spot_effect = dot(normalize(gl_LightSource[i].spotDirection), -L);
    float spot = 0.0;
    if (spot_effect >= gl_LightSource[i].spotCosCutoff)
        spot = pow(max(spot_effect, 0.0), gl_LightSource[i].spotExponent);
    localLight(i, N, V, L, shininess, attenuation * spot, ambient, diffuse, specular);
}
