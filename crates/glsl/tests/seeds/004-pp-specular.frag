// seed: 004_fff4468e34e76a89.txt lines 120-157
// expect: fail: line 17 declares `vec4 h_EC` but initializes it with `normalize(l_EC - normalize(pos_EC))`, which is a vec3 (GLSL has no implicit vector-size conversion); the same mismatch makes `dot(n_EC, h_EC)` on line 20 a call dot(vec3, vec4) that matches no overload
// version: 110
// stage: fragment
// note: OCR restored: slide line numbers removed, "vecd" -> vec4, "=«"/"x" between colours -> *, "gl LightSource"/"gl _LightSource"/"gl _FrontMaterial"/"gl FrontMaterial" -> gl_..., "light_.EC"/"light EC" -> light_EC, "| _EC"/"I_.EC" -> l_EC, "n EC" -> n_EC, em dash -> -, broken lines joined
// note: "vecd h_EC" is the slide's vec4 (see 004-pv-specular.vert): a real error in the slide, kept
varying vec3 normal_EC, light_EC, pos_EC;

void main()
{
    vec4 ambientp = gl_LightSource[0].ambient * gl_FrontMaterial.ambient;
    vec4 diffusep = gl_LightSource[0].diffuse * gl_FrontMaterial.diffuse;
    vec4 specularp = gl_LightSource[0].specular * gl_FrontMaterial.specular;

    vec3 n_EC = normalize(normal_EC);
    vec3 l_EC = normalize(light_EC);
    vec4 h_EC = normalize(l_EC - normalize(pos_EC));

    float albedo = max(dot(n_EC, l_EC), 0.0);
    float specular = pow(max(dot(n_EC, h_EC), 0.0), gl_FrontMaterial.shininess);

    gl_FragColor = ambientp + albedo * diffusep + specular * specularp;
}
