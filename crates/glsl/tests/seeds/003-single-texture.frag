// seed: 003_227224f6d3ad0fd5.txt lines 171-203
// expect: pass
// version: 110
// stage: fragment
// note: the dump double-spaces every line; the inserted blank lines are removed
// note: calls applyTexture2D through its forward declaration; the body is in 003-texturing-lib.frag (see programs.txt)
/**
 * SingleTexture.frag
 */

void applyTexture2D(in sampler2D texUnit, in int type, in int index, inout vec4 color);

uniform sampler2D TexUnit0;
uniform int TexturingType;

void main()
{
    vec4 color = gl_Color;

    applyTexture2D(TexUnit0, TexturingType, 0, color);

    gl_FragColor = color;
}
