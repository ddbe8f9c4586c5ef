// seed: 004_fff4468e34e76a89.txt lines 78-101
// expect: pass
// version: 110
// stage: fragment
// note: OCR restored: "vec4d"/"vecd" -> vec4, "=" and "x" between the light and material colours -> * (the same products read "x"/"=«" for * on the PP Specular slide), "gl LightSource"/"gl _LightSource"/"gl _FrontMaterial" -> gl_..., scrambled last statement reassembled in the order of the identical statement on the PP Specular slide (source line 154), closing } of main lost in OCR restored
varying float albedo, specular;

void main()
{
    vec4 ambientp = gl_LightSource[0].ambient * gl_FrontMaterial.ambient;
    vec4 diffusep = gl_LightSource[0].diffuse * gl_FrontMaterial.diffuse;
    vec4 specularp = gl_LightSource[0].specular * gl_FrontMaterial.specular;

    gl_FragColor = ambientp + albedo * diffusep + specular * specularp;
}
