// two-sided-lighting.frag: per-pixel Phong lighting of both faces, back
// faces with the back material and the flipped normal (fragment stage;
// link with phong-lighting-lib.frag; vertex: lighting.vert).
//
// What it does: front-facing fragments (gl_FrontFacing) are lit as in
// one-sided-lighting.frag; back-facing ones with -normal, the back
// material and gl_BackLightModelProduct, which is what fixed-function
// GL_LIGHT_MODEL_TWO_SIDE does per vertex. Draw with face culling off.
// The output is clamped to [0, 1].
//
// State it reads: gl_LightSource[0..gl_MaxLights-1], gl_FrontMaterial,
// gl_BackMaterial, gl_FrontLightModelProduct, gl_BackLightModelProduct,
// gl_FrontFacing, `varying vec3 normal, vertex`.
//
// Fix of the seed ("Creating a GLSL Library", TwoSidedLighting.frag): the
// seed lights every fragment twice, with n and the front material and
// with -n and the back material, and adds the two results, so each side
// also gets the other side's ambient and scene colour and any light
// between the two is counted on both. Two-sided lighting chooses one side
// per fragment; gl_FrontFacing makes that choice here (the method of the
// "Shaders" slides, seed 004: if (!gl_FrontFacing) n = -n).

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
    vec4 color;

    if (gl_FrontFacing) {
        calculateLighting(gl_MaxLights, n, vertex, gl_FrontMaterial.shininess,
                          ambient, diffuse, specular);
        color = gl_FrontLightModelProduct.sceneColor +
                ambient * gl_FrontMaterial.ambient +
                diffuse * gl_FrontMaterial.diffuse +
                specular * gl_FrontMaterial.specular;
    } else {
        calculateLighting(gl_MaxLights, -n, vertex, gl_BackMaterial.shininess,
                          ambient, diffuse, specular);
        color = gl_BackLightModelProduct.sceneColor +
                ambient * gl_BackMaterial.ambient +
                diffuse * gl_BackMaterial.diffuse +
                specular * gl_BackMaterial.specular;
    }
    gl_FragColor = clamp(color, 0.0, 1.0);
}
