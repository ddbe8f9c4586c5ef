// texturing-lib.frag: library object emulating the fixed-function texture
// environment modes (fragment stage; linked with single-texture.frag or
// multi-texture.frag, vertex stage texturing.vert).
//
// What it provides:
//   void applyTexture2D(in sampler2D unit, in int mode, in int index,
//                       inout vec4 color)
// reads `unit` at gl_TexCoord[index].st (index 0 or 1) and combines the
// texel (Ct, At) with `color` (Cf, Af) as GL 2.1 table 3.22 does for RGBA
// textures:
//   REPLACE  0  C = Ct                     A = At
//   MODULATE 1  C = Cf Ct                  A = Af At
//   DECAL    2  C = Cf (1 - At) + Ct At    A = Af
//   BLEND    3  C = Cf (1 - Ct) + Cc Ct    A = Af At  (Cc: the unit's
//                                                      gl_TextureEnvColor)
//   ADD      4  C = Cf + Ct                A = Af At  (clamped)
//   COMBINE  5  GL_COMBINE with its default settings (MODULATE of the
//               texture and the previous colour, clamped)
// Any other mode value behaves as COMBINE.
//
// State it reads: gl_TexCoord[0..1], gl_TextureEnvColor[index].
//
// Fixes of the seed ("Creating a GLSL Library", Texturing.frag):
// - The seed indexes gl_TexCoord with the variable `index` without giving
//   the array a size, which GLSL 1.10/1.20 forbid (sections 4.1.9 and
//   7.6; the seed does not compile). gl_TexCoord is redeclared here with
//   size 2, as in texturing.vert.
// - The local variable `texture` is renamed `texel` (texture is a built-in
//   function name in later GLSL versions).

varying vec4 gl_TexCoord[2];

const int REPLACE = 0;
const int MODULATE = 1;
const int DECAL = 2;
const int BLEND = 3;
const int ADD = 4;
const int COMBINE = 5;

void applyTexture2D(in sampler2D unit, in int mode, in int index, inout vec4 color)
{
    vec4 texel = texture2D(unit, gl_TexCoord[index].st);

    if (mode == REPLACE) {
        color = texel;
    } else if (mode == MODULATE) {
        color *= texel;
    } else if (mode == DECAL) {
        color = vec4(mix(color.rgb, texel.rgb, texel.a), color.a);
    } else if (mode == BLEND) {
        vec3 blended = mix(color.rgb, gl_TextureEnvColor[index].rgb, texel.rgb);
        color = vec4(blended, color.a * texel.a);
    } else if (mode == ADD) {
        color.rgb += texel.rgb;
        color.a *= texel.a;
        color = clamp(color, 0.0, 1.0);
    } else {
        color = clamp(texel * color, 0.0, 1.0);
    }
}
