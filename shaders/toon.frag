// toon.frag: cartoon (cel) shading in four flat bands (fragment stage;
// vertex: lighting.vert).
//
// What it does: takes the cosine between the renormalised normal and the
// direction of GL light 0 (a directional light: position = eye-space
// direction) and quantises it into four bands of the vertex colour:
//   cos > 0.95: 1.0    cos > 0.5: 0.6    cos > 0.25: 0.4    else: 0.2
// (alpha from gl_Color). No specular, no other lights: the flat bands are
// the look.
//
// State it reads: gl_LightSource[0].position, gl_Color,
// `varying vec3 normal` (lighting.vert's `vertex` is unused).
//
// Written by the project for the toon shading that seed 002's tutorial
// index lists and seed 003's conclusion suggests; no seed gives its code,
// so there is nothing to fix.

varying vec3 normal;
varying vec3 vertex;

void main(void)
{
    vec3 L = normalize(gl_LightSource[0].position.xyz);
    float intensity = dot(normalize(normal), L);
    float band;
    if (intensity > 0.95)
        band = 1.0;
    else if (intensity > 0.5)
        band = 0.6;
    else if (intensity > 0.25)
        band = 0.4;
    else
        band = 0.2;
    gl_FragColor = vec4(gl_Color.rgb * band, gl_Color.a);
}
