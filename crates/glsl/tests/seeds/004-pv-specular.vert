// seed: 004_fff4468e34e76a89.txt lines 47-75
// expect: fail: line 14 declares `vec4 half_EC` but initializes it with `normalize(light_EC - normalize(pos_EC))`, which is a vec3 (GLSL has no implicit vector-size conversion); the same mismatch makes `dot(normal_EC, half_EC)` on line 17 a call dot(vec3, vec4) that matches no overload
// version: 110
// stage: vertex
// note: OCR restored: slide line numbers removed, "wvarying" -> varying, "1"/")" -> { / } (listing lines 4 and 14), "x" -> *, "gl ModelViewMatrix"/"gl Vertex"/"gl FrontMaterial"/"gl _Position" -> gl_..., "pos_ EC"/"normal _EC"/"light EC"/"light_.EC"/"pos EC" -> pos_EC/normal_EC/light_EC, em dashes -> -, broken lines joined
// note: "vecd" is this OCR's consistent reading of "vec4" (vecd ambientp/diffusep/specularp, vecd4(...)), while "vec3" is read correctly everywhere (incl. listing lines 5-7 of this slide), so the slide really declares the half vector as vec4: a real error in the slide, kept
varying float albedo, specular;

void main()
{
    vec3 pos_EC = vec3(gl_ModelViewMatrix * gl_Vertex);
    vec3 normal_EC = normalize(gl_NormalMatrix * gl_Normal);
    vec3 light_EC = normalize(gl_LightSource[0].position.xyz - pos_EC);
    vec4 half_EC = normalize(light_EC - normalize(pos_EC));

    albedo = max(dot(normal_EC, light_EC), 0.0);
    specular = pow(max(dot(normal_EC, half_EC), 0.0), gl_FrontMaterial.shininess);

    gl_Position = ftransform();
}
