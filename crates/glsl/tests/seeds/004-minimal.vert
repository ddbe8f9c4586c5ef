// seed: 004_fff4468e34e76a89.txt lines 6-10
// expect: pass
// version: 110
// stage: vertex
// note: OCR restored: "gl Position" -> gl_Position; closing } of main lost in OCR (listing cut off, "A O PN" noise) restored
void main()
{
    gl_Position = ftransform();
}
