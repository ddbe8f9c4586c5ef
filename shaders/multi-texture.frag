// multi-texture.frag: two textures applied in turn to the vertex colour
// (fragment stage; link with texturing-lib.frag; vertex: texturing.vert).
//
// What it does: starts from gl_Color, applies TexUnit0 at coordinate set 0
// with mode TexturingType0, then TexUnit1 at coordinate set 1 with mode
// TexturingType1 (modes as in texturing-lib.frag), like two
// fixed-function texture units.
//
// State it reads: uniform sampler2D TexUnit0, TexUnit1; uniform int
// TexturingType0, TexturingType1; gl_Color, gl_TexCoord[0..1]
// (gl_TextureEnvColor[0..1] for BLEND).
//
// Fixes of the seed ("Creating a GLSL Library", MultiTexture.frag):
// - The seed calls applyTexture2D without declaring it (it does not
//   compile alone); the forward declaration is added.
// - The seed reads both textures at coordinate set 0; the second unit uses
//   set 1 here, as fixed-function multitexturing does (pass the same
//   coordinates in gl_MultiTexCoord1 to get the seed's behaviour).

void applyTexture2D(in sampler2D unit, in int mode, in int index, inout vec4 color);

uniform sampler2D TexUnit0;
uniform int TexturingType0;
uniform sampler2D TexUnit1;
uniform int TexturingType1;

void main(void)
{
    vec4 color = gl_Color;
    applyTexture2D(TexUnit0, TexturingType0, 0, color);
    applyTexture2D(TexUnit1, TexturingType1, 1, color);
    gl_FragColor = color;
}
