// seed: 002_22480d9e1aebe196.txt lines 105-115
// expect: pass
// version: 110
// stage: vertex
// note: Lighthouse3D GLSL tutorial, `Combine Texture + Fragment` (GL_MODULATE) vertex shader
varying vec3 lightDir,normal;

void main()
{

	normal = normalize(gl_NormalMatrix * gl_Normal);
	lightDir = normalize(vec3(gl_LightSource[0].position));

	gl_TexCoord[0] = gl_MultiTexCoord0;
	gl_Position = ftransform();
}
