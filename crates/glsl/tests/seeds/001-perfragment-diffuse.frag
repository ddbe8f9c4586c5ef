// seed: 001_59bddf836d92c59d.txt lines 806-816
// expect: fail: `vec' (lines 6-9, 12, 14) and `Vec' (line 13) are not GLSL types: the slide writes vec as shorthand for vec3/vec4, and `Vec' is also in the wrong case; line 9 uses `in' as a global storage qualifier, which GLSL 1.10 does not have
// version: 110
// stage: fragment
// note: no #version in the document, so this compiles as GLSL 1.10
uniform vec lightpos;
uniform vec Kd; // Material property
uniform vec Ld; // Light property
in vec normal;
void main()
{
 vec n = normalize(normal);
 Vec l = normalize(lightpos); // distance light
 vec diffuse = max(dot(l,n),0) * Kd * Ld;
 gl_FragColor = diffuse;
}
