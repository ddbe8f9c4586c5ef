#version 330 core
// bench/scenes33.py's core-itex: an integer texel fetch at coordinates
// from gl_FragCoord and textureSize, indexing a uniform block's array.
uniform usampler2D indices;
uniform int layer;
layout(std140) uniform Palette { vec4 colours[64]; };
out vec4 frag;
void main() {
    ivec2 size = textureSize(indices, 0);
    ivec2 at = (ivec2(gl_FragCoord.xy) + ivec2(37, 11) * layer) % size;
    uint i = texelFetch(indices, at, 0).r;
    uint mixed = (i ^ uint(layer * 7)) & 63u;
    frag = vec4(colours[mixed].rgb, 0.25);
}
