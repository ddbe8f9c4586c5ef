// A vertex shader: ftransform, a normal transformed by gl_NormalMatrix,
// a texture-coordinate copy and a point size.
varying vec3 normal;
uniform float size;

void main()
{
    gl_Position = ftransform();
    normal = normalize(gl_NormalMatrix * gl_Normal);
    gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_PointSize = size / max(gl_Position.w, 1.0);
}
