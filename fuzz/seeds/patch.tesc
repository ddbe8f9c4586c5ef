#version 150
#extension GL_ARB_tessellation_shader : require
layout(vertices = 4) out;
in vec4 color[];
out vec4 tc[];
out Block { vec2 uv[2]; } blk[];
patch out vec3 center;
out gl_PerVertex { vec4 gl_Position; float gl_ClipDistance[2]; } gl_out[];
void main() {
    tc[gl_InvocationID] = color[gl_InvocationID % gl_PatchVerticesIn];
    blk[gl_InvocationID].uv[1] = vec2(gl_PrimitiveID);
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
    barrier();
    center = tc[0].xyz + gl_out[1].gl_Position.xyz;
    gl_TessLevelOuter = float[4](2.0, 2.0, 2.0, 2.0);
    gl_TessLevelInner[0] = float(gl_out.length());
}
