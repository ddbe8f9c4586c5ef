// seed: 004_fff4468e34e76a89.txt lines 22-33
// expect: pass
// version: 110
// stage: vertex
// note: OCR restored: "vec3d" -> vec3 (same statement reads "vec3 pos_EC" on the next slide), "%" -> *, "gl Vertex" -> gl_Vertex, "normal _EC"/"light EC"/"light_ EC"/"pos EC" -> normal_EC/light_EC/pos_EC, em dash -> -, broken line joined
varying float albedo;

void main()
{
    vec3 pos_EC = vec3(gl_ModelViewMatrix * gl_Vertex);
    vec3 normal_EC = normalize(gl_NormalMatrix * gl_Normal);
    vec3 light_EC = normalize(gl_LightSource[0].position.xyz - pos_EC);
    albedo = dot(normal_EC, light_EC);
    gl_Position = ftransform();
}
