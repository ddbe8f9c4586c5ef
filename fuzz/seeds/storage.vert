#version 120
#extension GL_ARB_shader_storage_buffer_object : enable
coherent restrict buffer B { ivec4 v; float tail[]; } b;
void main() {
    atomicMin(b.v.x, 2);
    b.tail[b.v.y] = float(b.tail.length());
    gl_Position = vec4(b.tail[0]);
}
