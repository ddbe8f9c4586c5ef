// materials.frag: per-pixel Blinn-Phong lighting by GL lights 0 and 1
// with the front material (fragment stage; pair: materials.vert).
//
// What it does: renormalises the interpolated normal, sums the ambient,
// diffuse (N.L) and specular ((N.H)^shininess) terms of lights 0 and 1,
// both treated as directional lights whose position is their eye-space
// direction, and writes
//   gl_Color * (diffuse + ambient + emission) + specular,
// with the alpha of gl_Color. The vertex colour thus plays the part of
// the ambient and diffuse material colour (as with glColorMaterial).
//
// State it reads: gl_LightSource[0..1].position and .halfVector,
// gl_FrontLightProduct[0..1].ambient/.diffuse/.specular,
// gl_FrontMaterial.emission/.shininess, gl_Color, `varying vec3 normal`.
//
// After the seed talk ("GLSL v1.20", Example 02, materials fragment
// shader), which has no slips. Its lights must be directional (w = 0):
// the shader ignores attenuation and spot cones, as the seed does.

varying vec3 normal;

void addLight(in int light, in vec3 N, inout vec4 ambient, inout vec4 diffuse,
              inout vec4 specular)
{
    vec3 L = normalize(gl_LightSource[light].position.xyz);
    vec3 H = normalize(gl_LightSource[light].halfVector.xyz);
    float n_dot_l = max(0.0, dot(N, L));
    float n_dot_h = max(0.0, dot(N, H));
    ambient += gl_FrontLightProduct[light].ambient;
    diffuse += n_dot_l * gl_FrontLightProduct[light].diffuse;
    specular += pow(n_dot_h, gl_FrontMaterial.shininess) *
                gl_FrontLightProduct[light].specular;
}

void main(void)
{
    vec3 N = normalize(normal);
    vec4 ambient = vec4(0.0, 0.0, 0.0, 1.0);
    vec4 diffuse = vec4(0.0, 0.0, 0.0, 1.0);
    vec4 specular = vec4(0.0, 0.0, 0.0, 1.0);

    addLight(0, N, ambient, diffuse, specular);
    addLight(1, N, ambient, diffuse, specular);

    ambient.w = 1.0;
    diffuse.w = 1.0;
    specular.w = 1.0;
    vec4 lit = gl_Color * (diffuse + ambient + gl_FrontMaterial.emission) + specular;
    gl_FragColor = vec4(lit.rgb, gl_Color.a);
}
