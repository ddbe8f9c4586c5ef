// seed: 004_fff4468e34e76a89.txt lines 37-44
// expect: pass
// version: 110
// stage: fragment
// note: OCR restored: "gl FragColor" -> gl_FragColor, "*x" -> *, "gl FrontMaterial" -> gl_FrontMaterial, broken line joined; closing } of main lost in OCR (listing cut off) restored
varying float albedo;

void main()
{
    gl_FragColor = vec4(albedo * gl_FrontMaterial.diffuse.rgb, 1.0);
}
