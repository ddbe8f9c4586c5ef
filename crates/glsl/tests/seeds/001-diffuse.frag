// seed: 001_59bddf836d92c59d.txt lines 689-696
// expect: fail: line 7: `in vec3 normal;` uses `in` as a global storage qualifier, which GLSL 1.10/1.20 do not have (1.10 declares it `varying vec3 normal;`); and line 12: `max(dot(l,n),0)` calls max(float, int), which matches no overload in GLSL 1.10 (no implicit int->float conversion; 1.20 would accept it)
// version: 110
// stage: fragment
// note: no #version in the document, so this compiles as GLSL 1.10 (the slides mix GLSL 1.30+/3.x syntax with 1.10 built-ins)
// fragment shader
in vec3 normal;
void main(void)
{
 vec3 n = normalize(normal);
 vec3 l = normalize(gl_LightSource[0].position.xyz);
 gl_FragColor = max(dot(l,n),0)*gl_Color;
}
