// one-sided-lighting.frag: per-pixel Phong lighting of front faces with
// the front material (fragment stage; link with phong-lighting-lib.frag;
// vertex: lighting.vert).
//
// What it does: lights the renormalised interpolated normal at the
// eye-space point `vertex` with every GL light the library counts as on
// (see phong-lighting-lib.frag), and writes
//   sceneColor + ambient * Ma + diffuse * Md + specular * Ms
// (front material, gl_FrontLightModelProduct.sceneColor = emission +
// model ambient * Ma), clamped to [0, 1]. Back faces get the same
// front-side lighting (their normal faces away from the light: dark).
//
// State it reads: gl_LightSource[0..gl_MaxLights-1], gl_FrontMaterial,
// gl_FrontLightModelProduct, `varying vec3 normal, vertex`.
//
// After the seed ("Creating a GLSL Library", OneSidedLighting.frag), which
// has no slips.

void calculateLighting(in int numLights, in vec3 N, in vec3 V, in float shininess,
                       inout vec4 ambient, inout vec4 diffuse, inout vec4 specular);

varying vec3 normal;
varying vec3 vertex;

void main(void)
{
    vec3 n = normalize(normal);
    vec4 ambient = vec4(0.0);
    vec4 diffuse = vec4(0.0);
    vec4 specular = vec4(0.0);

    calculateLighting(gl_MaxLights, n, vertex, gl_FrontMaterial.shininess,
                      ambient, diffuse, specular);

    vec4 color = gl_FrontLightModelProduct.sceneColor +
                 ambient * gl_FrontMaterial.ambient +
                 diffuse * gl_FrontMaterial.diffuse +
                 specular * gl_FrontMaterial.specular;
    gl_FragColor = clamp(color, 0.0, 1.0);
}
