#version 150
#extension GL_ARB_tessellation_shader : require
layout(quads, fractional_even_spacing) in;
layout(cw, point_mode) in;
in vec4 tc[];
in Block { vec2 uv[2]; } blk[];
patch in vec3 center;
out vec4 color;
void main() {
    vec4 a = mix(gl_in[0].gl_Position, gl_in[1].gl_Position, gl_TessCoord.x);
    vec4 b = mix(gl_in[3].gl_Position, gl_in[2].gl_Position, gl_TessCoord.x);
    gl_Position = mix(a, b, gl_TessCoord.y) + vec4(center, 0.0);
    color = tc[gl_PatchVerticesIn - 1] * gl_TessLevelOuter[0] + vec4(blk[2].uv[1], gl_TessLevelInner[1], float(gl_PrimitiveID));
}
