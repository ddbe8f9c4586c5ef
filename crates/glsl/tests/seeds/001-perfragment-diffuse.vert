// seed: 001_59bddf836d92c59d.txt lines 784-794
// expect: fail: `vec' and `mat' on lines 6-11 are not GLSL types: the slide writes them as shorthand ("note that vec,mat should be vec3/4 or mat3/4 in real code"), so each is an error naming the sized types; besides, line 11 uses `out' as a global storage qualifier, which GLSL 1.10 does not have
// version: 110
// stage: vertex
// note: no #version in the document, so this compiles as GLSL 1.10; the variables with a bad type are still declared, so their uses report nothing more
attribute vec vPosition;
attribute vec vNormal;
uniform mat modelViewMatrix;
uniform mat projectionMatrix;
uniform mat normalMatrix;
out vec normal;
void main(void)
{
 gl_Position = projectionMatrix*modelViewMatrix*vPosition;
 normal = normalMatrix*vNormal;
}
