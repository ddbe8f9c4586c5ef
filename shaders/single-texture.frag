// single-texture.frag: one texture combined with the vertex colour
// (fragment stage; link with texturing-lib.frag; vertex: texturing.vert).
//
// What it does: starts from gl_Color and applies texture unit TexUnit0 at
// coordinate set 0 with the environment mode TexturingType (0 REPLACE,
// 1 MODULATE, 2 DECAL, 3 BLEND, 4 ADD, 5 COMBINE; see texturing-lib.frag).
//
// State it reads: uniform sampler2D TexUnit0; uniform int TexturingType;
// gl_Color, gl_TexCoord[0] (and gl_TextureEnvColor[0] for BLEND).
//
// After the seed ("Creating a GLSL Library", SingleTexture.frag), which
// has no slips: the forward declaration of the library function is what
// lets this object compile alone and link with the library.

void applyTexture2D(in sampler2D unit, in int mode, in int index, inout vec4 color);

uniform sampler2D TexUnit0;
uniform int TexturingType;

void main(void)
{
    vec4 color = gl_Color;
    applyTexture2D(TexUnit0, TexturingType, 0, color);
    gl_FragColor = color;
}
