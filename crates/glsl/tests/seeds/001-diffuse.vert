// seed: 001_59bddf836d92c59d.txt lines 678-685
// expect: fail: line 7: `out vec3 normal;` uses `out` as a global storage qualifier, which GLSL 1.10/1.20 do not have (GLSL 1.30+ form; 1.10 declares it `varying vec3 normal;`)
// version: 110
// stage: vertex
// note: no #version in the document, so this compiles as GLSL 1.10 (the slides mix GLSL 1.30+/3.x syntax with 1.10 built-ins)
// vertex shader
out vec3 normal;
void main(void)
{
 gl_Position = gl_ModelViewProjectionMatrix * (gl_Vertex);
 normal = normalize(gl_NormalMatrix * gl_Normal).xyz;
 gl_FrontColor = vec4(1,0,0,1); // Red
}
