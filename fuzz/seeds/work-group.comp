#version 330
#extension GL_ARB_compute_shader : enable
#extension GL_ARB_shader_storage_buffer_object : enable
layout(local_size_x = 8, local_size_y = 2) in;
layout(std430, binding = 1) buffer Data { readonly uint count; writeonly uint hits[]; } data;
shared uint tile[gl_WorkGroupSize.x * gl_WorkGroupSize.y];
void main() {
    tile[gl_LocalInvocationIndex] = gl_GlobalInvocationID.x;
    barrier();
    memoryBarrierShared();
    uint before = atomicAdd(tile[0], 1u);
    int n = data.hits.length();
    data.hits[gl_WorkGroupID.x % uint(n)] = before + data.count;
}
