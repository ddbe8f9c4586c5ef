// seed: 004_fff4468e34e76a89.txt lines 14-19
// expect: pass
// version: 110
// stage: fragment
// note: OCR restored: slide line numbers and sidebar text removed; listing line 4 ("}") is present as a number but its text was lost in OCR, restored
void main()
{
    gl_FragColor = gl_FrontMaterial.diffuse;
}
