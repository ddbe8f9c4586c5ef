//! Texture internal formats and the texels stored for them (GL 2.1
//! Tables 3.15, 3.16, 3.20).
//!
//! Contract: texture images are stored as RGBA `f32` texels in the form
//! sampling returns them (LUMINANCE → (L, L, L, 1), ALPHA → (0, 0, 0, A),
//! INTENSITY → (I, I, I, I)...), quantized to the internal format's
//! precision (8 bits per component for the unsized and `*8` formats, 16
//! for `*16`, none for float formats). Depth images keep the depth,
//! clamped to [0, 1], in every color component and alpha 1.
//! [`texel_for`] is the one conversion from an RGBA value to a stored
//! texel (image specification, render-to-texture write-back).

use crate::enums::*;

/// The base internal format (GL 2.1 Table 3.15/3.16) of an internal format.
pub fn base_format(internal: i32) -> Option<u32> {
    let f = internal as u32;
    Some(match f {
        1 | GL_LUMINANCE | GL_LUMINANCE4 | GL_LUMINANCE8 | GL_LUMINANCE12 | GL_LUMINANCE16
        | GL_LUMINANCE32F_ARB | GL_LUMINANCE16F_ARB | GL_SLUMINANCE | GL_SLUMINANCE8 => {
            GL_LUMINANCE
        }
        2
        | GL_LUMINANCE_ALPHA
        | GL_LUMINANCE4_ALPHA4
        | GL_LUMINANCE6_ALPHA2
        | GL_LUMINANCE8_ALPHA8
        | GL_LUMINANCE12_ALPHA4
        | GL_LUMINANCE12_ALPHA12
        | GL_LUMINANCE16_ALPHA16
        | GL_LUMINANCE_ALPHA32F_ARB
        | GL_LUMINANCE_ALPHA16F_ARB
        | GL_SLUMINANCE_ALPHA
        | GL_SLUMINANCE8_ALPHA8 => GL_LUMINANCE_ALPHA,
        3 | GL_RGB | GL_R3_G3_B2 | GL_RGB4 | GL_RGB5 | GL_RGB8 | GL_RGB10 | GL_RGB12 | GL_RGB16
        | GL_RGB32F | GL_RGB16F | GL_SRGB | GL_SRGB8 => GL_RGB,
        4 | GL_RGBA | GL_RGBA2 | GL_RGBA4 | GL_RGB5_A1 | GL_RGBA8 | GL_RGB10_A2 | GL_RGBA12
        | GL_RGBA16 | GL_RGBA32F | GL_RGBA16F | GL_SRGB_ALPHA | GL_SRGB8_ALPHA8 => GL_RGBA,
        GL_ALPHA | GL_ALPHA4 | GL_ALPHA8 | GL_ALPHA12 | GL_ALPHA16 | GL_ALPHA32F_ARB
        | GL_ALPHA16F_ARB => GL_ALPHA,
        GL_INTENSITY | GL_INTENSITY4 | GL_INTENSITY8 | GL_INTENSITY12 | GL_INTENSITY16
        | GL_INTENSITY32F_ARB | GL_INTENSITY16F_ARB => GL_INTENSITY,
        GL_RED | GL_R8 | GL_R16 | GL_R16F | GL_R32F => GL_RED,
        GL_RG | GL_RG8 | GL_RG16 | GL_RG16F | GL_RG32F => GL_RG,
        GL_DEPTH_COMPONENT
        | GL_DEPTH_COMPONENT16
        | GL_DEPTH_COMPONENT24
        | GL_DEPTH_COMPONENT32
        | GL_DEPTH_COMPONENT32F => GL_DEPTH_COMPONENT,
        GL_DEPTH_STENCIL | GL_DEPTH24_STENCIL8 | GL_DEPTH32F_STENCIL8 => GL_DEPTH_STENCIL,
        _ => return None,
    })
}

/// Quantization of an internal format: `Some(bits)` for normalized fixed
/// point, `None` for float formats.
fn format_bits(internal: i32) -> Option<u32> {
    let f = internal as u32;
    match f {
        GL_RGBA32F
        | GL_RGB32F
        | GL_RGBA16F
        | GL_RGB16F
        | GL_ALPHA32F_ARB
        | GL_ALPHA16F_ARB
        | GL_LUMINANCE32F_ARB
        | GL_LUMINANCE16F_ARB
        | GL_LUMINANCE_ALPHA32F_ARB
        | GL_LUMINANCE_ALPHA16F_ARB
        | GL_INTENSITY32F_ARB
        | GL_INTENSITY16F_ARB
        | GL_R16F
        | GL_R32F
        | GL_RG16F
        | GL_RG32F
        | GL_DEPTH_COMPONENT32F
        | GL_DEPTH32F_STENCIL8 => None,
        GL_RGBA16
        | GL_RGB16
        | GL_ALPHA16
        | GL_LUMINANCE16
        | GL_LUMINANCE16_ALPHA16
        | GL_INTENSITY16
        | GL_R16
        | GL_RG16
        | GL_DEPTH_COMPONENT16 => Some(16),
        GL_DEPTH_COMPONENT | GL_DEPTH_COMPONENT24 | GL_DEPTH24_STENCIL8 | GL_DEPTH_STENCIL => {
            Some(24)
        }
        GL_DEPTH_COMPONENT32 => None,
        _ => Some(8),
    }
}

/// True for depth and depth-stencil internal formats.
pub fn is_depth_format(internal: i32) -> bool {
    matches!(
        base_format(internal),
        Some(GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL)
    )
}

/// True for formats whose texels are not clamped to [0, 1].
pub fn is_float_format(internal: i32) -> bool {
    format_bits(internal).is_none() && base_format(internal) != Some(GL_DEPTH_COMPONENT)
}

fn quantize(x: f32, bits: Option<u32>) -> f32 {
    match bits {
        None => x,
        Some(b) => {
            let x = if x > 0.0 { x.min(1.0) } else { 0.0 };
            let max = ((1u64 << b) - 1) as f64;
            ((x as f64 * max + 0.5).floor() / max) as f32
        }
    }
}

/// RGBA to the texel sampling returns for a base internal format (GL 2.1
/// Table 3.20), quantized.
pub fn texel_for(rgba: [f32; 4], internal: i32) -> [f32; 4] {
    let bits = format_bits(internal);
    let q = |x: f32| quantize(x, bits);
    let [r, g, b, a] = rgba;
    match base_format(internal).unwrap_or(GL_RGBA) {
        GL_ALPHA => [0.0, 0.0, 0.0, q(a)],
        GL_LUMINANCE => [q(r), q(r), q(r), 1.0],
        GL_LUMINANCE_ALPHA => [q(r), q(r), q(r), q(a)],
        GL_INTENSITY => [q(r); 4],
        GL_RED => [q(r), 0.0, 0.0, 1.0],
        GL_RG => [q(r), q(g), 0.0, 1.0],
        GL_RGB => [q(r), q(g), q(b), 1.0],
        GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL => {
            // Depth is always clamped to [0, 1] (GL 2.1 §3.8.1).
            let d = quantize(r, bits);
            let d = if d.is_nan() { 0.0 } else { d.clamp(0.0, 1.0) };
            [d, d, d, 1.0]
        }
        _ => [q(r), q(g), q(b), q(a)],
    }
}

/// Re-quantizes an already expanded texel (for generated mipmaps).
pub(crate) fn texel_for_stored(t: [f32; 4], internal: i32) -> [f32; 4] {
    let bits = format_bits(internal);
    if base_format(internal) == Some(GL_DEPTH_COMPONENT) {
        return t;
    }
    t.map(|x| quantize(x, bits))
}
