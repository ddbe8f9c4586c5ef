// seed: 003_227224f6d3ad0fd5.txt lines 222-254
// expect: fail: `applyTexture2D` is called on lines 19 and 20 but never declared in this shader: the listing lacks the forward declaration `void applyTexture2D(in sampler2D texUnit, in int type, in int index, inout vec4 color);` that 003-single-texture.frag has (the article itself says the forward declaration is what makes the library work), and GLSL requires a function to be declared before it is called
// version: 110
// stage: fragment
// note: the dump double-spaces every line; the inserted blank lines are removed
// note: meant to link with 003-texturing-lib.frag (see programs.txt)
/**
 * \file MultiTexture.frag
 */
uniform sampler2D TexUnit0;
uniform int TexturingType0;
uniform sampler2D TexUnit1;
uniform int TexturingType1;

void main()
{
    vec4 color = gl_Color;

    applyTexture2D(TexUnit0, TexturingType0, 0, color);
    applyTexture2D(TexUnit1, TexturingType1, 0, color);

    gl_FragColor = color;
}
