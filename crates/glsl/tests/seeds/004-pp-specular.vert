// seed: 004_fff4468e34e76a89.txt lines 104-114
// expect: pass
// version: 110
// stage: vertex
// note: OCR restored: "1" -> {, "light_ EC"/"light EC"/"pos_.EC" -> light_EC/pos_EC, "gl_-ModelViewMatrix"/"gl _LightSource" -> gl_..., "*x" -> *, em dash -> -; closing } of main lost in OCR (listing cut off) restored
varying vec3 normal_EC, light_EC, pos_EC;

void main()
{
    pos_EC = vec3(gl_ModelViewMatrix * gl_Vertex);

    normal_EC = normalize(gl_NormalMatrix * gl_Normal);
    light_EC = gl_LightSource[0].position.xyz - pos_EC;

    gl_Position = ftransform();
}
