#version 130
#extension GL_ARB_shading_language_420pack : enable
#extension GL_ARB_arrays_of_arrays : enable
struct S { float a; ivec2 b[2]; };
const mat2 m = { { 1.0, 2.0 }, vec2(3.0, 4.0) };
const S s = { 1.5, { { 1, 2 }, ivec2(3) } };
float g[2][2] = { { 1.0, 2.0 }, { 3.0, 4.0 }, };
layout(binding = 2) uniform sampler2D t[2];
in flat float from_vertex;
uniform float u;
float f(in const float x) { return x.x; }
void main() {
    const float k = u * 2.0;
    vec4 v = (1.0).xxxx;
    gl_FragColor = from_vertex * v * float(v.length() + m.length()) + vec4(f(k), s.a, g[1][0], 0.0) + texture2D(t[1], vec2(0.0));
}
