// seed: 001_59bddf836d92c59d.txt lines 712-726
// expect: fail: line 8: `out vec3 normal;` uses `out` as a global storage qualifier, which GLSL 1.10/1.20 do not have (GLSL 1.30+ form; 1.10 declares it `varying vec3 normal;`)
// version: 110
// stage: vertex
// note: no #version in the document, so this compiles as GLSL 1.10 (the slides mix GLSL 1.30+/3.x syntax with 1.10 built-ins)
// vertex shader
uniform float m_Scale;
out vec3 normal;
void main(void)
{
 vec4 P_obj = gl_Vertex;
 P_obj.x = P_obj.x * m_Scale;
 P_obj.y = P_obj.y * m_Scale;
 P_obj.z = P_obj.z * m_Scale;

 // Clip Coordinate
 gl_Position = gl_ModelViewProjectionMatrix * (P_obj);
 normal = normalize(gl_NormalMatrix * gl_Normal).xyz;
 gl_FrontColor = vec4(1,0,0,1); // Red
}
