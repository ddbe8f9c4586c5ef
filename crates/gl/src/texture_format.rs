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
//! texel (image specification, render-to-texture write-back). Integer
//! formats (GL 3.0) store the integers' bits ([`integer_texel`]).

use crate::enums::*;

/// The base internal format (GL 2.1 Table 3.15/3.16) of an internal format.
pub fn base_format(internal: i32) -> Option<u32> {
    let f = internal as u32;
    Some(match f {
        1
        | GL_LUMINANCE
        | GL_LUMINANCE4
        | GL_LUMINANCE8
        | GL_LUMINANCE12
        | GL_LUMINANCE16
        | GL_LUMINANCE32F_ARB
        | GL_LUMINANCE16F_ARB
        | GL_SLUMINANCE
        | GL_SLUMINANCE8
        | GL_COMPRESSED_SLUMINANCE => GL_LUMINANCE,
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
        | GL_SLUMINANCE8_ALPHA8
        | GL_COMPRESSED_SLUMINANCE_ALPHA => GL_LUMINANCE_ALPHA,
        3 | GL_RGB | GL_R3_G3_B2 | GL_RGB4 | GL_RGB5 | GL_RGB8 | GL_RGB10 | GL_RGB12 | GL_RGB16
        | GL_RGB32F | GL_RGB16F | GL_SRGB | GL_SRGB8 | GL_R11F_G11F_B10F | GL_RGB9_E5
        | GL_COMPRESSED_SRGB => GL_RGB,
        4
        | GL_RGBA
        | GL_RGBA2
        | GL_RGBA4
        | GL_RGB5_A1
        | GL_RGBA8
        | GL_RGB10_A2
        | GL_RGBA12
        | GL_RGBA16
        | GL_RGBA32F
        | GL_RGBA16F
        | GL_SRGB_ALPHA
        | GL_SRGB8_ALPHA8
        | GL_COMPRESSED_SRGB_ALPHA => GL_RGBA,
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
        _ => return integer_format(internal).map(|(base, _, _)| base),
    })
}

/// An integer internal format (GL 3.0 Table 3.16): its base format, its
/// bits per component and whether it is signed.
pub fn integer_format(internal: i32) -> Option<(u32, u32, bool)> {
    Some(match internal as u32 {
        GL_R8I => (GL_RED, 8, true),
        GL_R8UI => (GL_RED, 8, false),
        GL_R16I => (GL_RED, 16, true),
        GL_R16UI => (GL_RED, 16, false),
        GL_R32I => (GL_RED, 32, true),
        GL_R32UI => (GL_RED, 32, false),
        GL_RG8I => (GL_RG, 8, true),
        GL_RG8UI => (GL_RG, 8, false),
        GL_RG16I => (GL_RG, 16, true),
        GL_RG16UI => (GL_RG, 16, false),
        GL_RG32I => (GL_RG, 32, true),
        GL_RG32UI => (GL_RG, 32, false),
        GL_RGB8I => (GL_RGB, 8, true),
        GL_RGB8UI => (GL_RGB, 8, false),
        GL_RGB16I => (GL_RGB, 16, true),
        GL_RGB16UI => (GL_RGB, 16, false),
        GL_RGB32I => (GL_RGB, 32, true),
        GL_RGB32UI => (GL_RGB, 32, false),
        GL_RGBA8I => (GL_RGBA, 8, true),
        GL_RGBA8UI => (GL_RGBA, 8, false),
        GL_RGBA16I => (GL_RGBA, 16, true),
        GL_RGBA16UI => (GL_RGBA, 16, false),
        GL_RGBA32I => (GL_RGBA, 32, true),
        GL_RGBA32UI => (GL_RGBA, 32, false),
        _ => return None,
    })
}

/// True for the sRGB internal formats (EXT_texture_sRGB, GL 2.1 §3.8.15):
/// their colour components are stored encoded and decoded on sampling.
/// The generic compressed ones are stored uncompressed, 8 bits a
/// component, as §3.8.3 allows.
pub fn is_srgb_format(internal: i32) -> bool {
    matches!(
        internal as u32,
        GL_SRGB
            | GL_SRGB8
            | GL_SRGB_ALPHA
            | GL_SRGB8_ALPHA8
            | GL_SLUMINANCE
            | GL_SLUMINANCE8
            | GL_SLUMINANCE_ALPHA
            | GL_SLUMINANCE8_ALPHA8
            | GL_COMPRESSED_SRGB
            | GL_COMPRESSED_SRGB_ALPHA
            | GL_COMPRESSED_SLUMINANCE
            | GL_COMPRESSED_SLUMINANCE_ALPHA
    )
}

/// `x` rounded to the nearest value of an unsigned float with `mantissa`
/// bits and a 5-bit exponent (GL 3.0 §2.1.3's 11- and 10-bit floats):
/// negative values and NaN become 0, values past the largest finite one
/// (65024 for 6 bits, 64512 for 5) that largest one.
fn small_float(x: f32, mantissa: u32) -> f32 {
    if x.is_nan() || x <= 0.0 {
        return 0.0;
    }
    let max = (2.0 - (-(mantissa as f64)).exp2()) * 32768.0;
    let v = (x as f64).min(max);
    // Below 2^-14 the values are denormal: steps of 2^(-14 - mantissa).
    let e = v.log2().floor().max(-14.0);
    let step = (e - mantissa as f64).exp2();
    ((v / step).round() * step).min(max) as f32
}

/// GL 3.0 §3.8.1's RGB9_E5: a shared 5-bit exponent and 9-bit mantissas
/// (components clamped to [0, 65408] first).
fn rgb9e5(rgb: [f32; 3]) -> [f32; 3] {
    const N: i32 = 9;
    const B: i32 = 15;
    let max = (511.0 / 512.0) * 65536.0f64;
    let c = rgb.map(|x| {
        if x.is_nan() {
            0.0
        } else {
            (x as f64).clamp(0.0, max)
        }
    });
    let m = c[0].max(c[1]).max(c[2]);
    // The shared exponent's scale: the largest component's, one more
    // when its mantissa would round up to 2^N.
    let e = (m.log2().floor() as i32).max(-B - 1) + 1 + B;
    let mut scale = ((e - B - N) as f64).exp2();
    if (m / scale + 0.5).floor() as i32 == 1 << N {
        scale *= 2.0;
    }
    c.map(|x| ((x / scale + 0.5).floor() * scale) as f32)
}

/// What `glGetTexLevelParameteriv` reports of an internal format's colour
/// components (GL 3.0 Table 6.17): their bits (8 for the unsized and `*8`
/// formats, as stored) and their type (GL_INT, GL_UNSIGNED_INT, GL_FLOAT
/// or GL_UNSIGNED_NORMALIZED).
pub fn component_info(internal: i32) -> (u32, u32) {
    if let Some((_, bits, signed)) = integer_format(internal) {
        return (bits, if signed { GL_INT } else { GL_UNSIGNED_INT });
    }
    match internal as u32 {
        GL_R11F_G11F_B10F => (11, GL_FLOAT),
        GL_RGB9_E5 => (9, GL_FLOAT),
        GL_RGBA16F
        | GL_RGB16F
        | GL_R16F
        | GL_RG16F
        | GL_ALPHA16F_ARB
        | GL_LUMINANCE16F_ARB
        | GL_LUMINANCE_ALPHA16F_ARB
        | GL_INTENSITY16F_ARB => (16, GL_FLOAT),
        GL_DEPTH_COMPONENT32F | GL_DEPTH32F_STENCIL8 => (32, GL_FLOAT),
        _ if is_float_format(internal) => (32, GL_FLOAT),
        _ => match format_bits(internal) {
            Some(b) => (b, GL_UNSIGNED_NORMALIZED),
            None => (32, GL_UNSIGNED_NORMALIZED),
        },
    }
}

/// True for the integer internal formats.
pub fn is_integer_format(internal: i32) -> bool {
    integer_format(internal).is_some()
}

/// An integer texel (GL 3.3 §3.9.3: each component clamped to the
/// internal format's range, not converted) from RGBA integer components:
/// the integers' bits as `f32::from_bits`, missing components 0 and alpha
/// 1 (Table 3.20).
pub fn integer_texel(rgba: [i64; 4], internal: i32) -> [f32; 4] {
    let (base, bits, signed) = integer_format(internal).unwrap_or((GL_RGBA, 32, false));
    let (lo, hi) = if signed {
        (-(1i64 << (bits - 1)), (1i64 << (bits - 1)) - 1)
    } else {
        (0, (1i64 << bits) - 1)
    };
    let c = rgba.map(|x| f32::from_bits(x.clamp(lo, hi) as u32));
    let (zero, one) = (f32::from_bits(0), f32::from_bits(1));
    match base {
        GL_RED => [c[0], zero, zero, one],
        GL_RG => [c[0], c[1], zero, one],
        GL_RGB => [c[0], c[1], c[2], one],
        _ => c,
    }
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
        | GL_DEPTH32F_STENCIL8
        | GL_R11F_G11F_B10F
        | GL_RGB9_E5 => None,
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
        f if is_integer_format(f as i32) => None,
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
    format_bits(internal).is_none()
        && base_format(internal) != Some(GL_DEPTH_COMPONENT)
        && !is_integer_format(internal)
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
    if is_integer_format(internal) {
        // Colour values reaching an integer texture (a default image, a
        // write-back) are taken as integers.
        return integer_texel(
            rgba.map(|x| if x.is_nan() { 0 } else { x as i64 }),
            internal,
        );
    }
    let [r, g, b, _] = rgba;
    match internal as u32 {
        GL_R11F_G11F_B10F => {
            return [small_float(r, 6), small_float(g, 6), small_float(b, 5), 1.0];
        }
        GL_RGB9_E5 => {
            let [r, g, b] = rgb9e5([r, g, b]);
            return [r, g, b, 1.0];
        }
        _ => {}
    }
    let bits = format_bits(internal);
    let base = base_format(internal).unwrap_or(GL_RGBA);
    if matches!(base, GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL) {
        // Depth is always clamped to [0, 1] (GL 2.1 §3.8.1).
        let d = quantize(r, bits);
        let d = if d.is_nan() { 0.0 } else { d.clamp(0.0, 1.0) };
        return [d, d, d, 1.0];
    }
    channel_sources(base).map(|c| match c {
        Channel::Of(i) => quantize(rgba[i], bits),
        Channel::Zero => 0.0,
        Channel::One => 1.0,
    })
}

/// What a stored channel of a colour format holds ([`texel_for`]).
#[derive(Clone, Copy)]
enum Channel {
    /// The (quantized) value of an RGBA component.
    Of(usize),
    Zero,
    One,
}

/// Where each channel of a texel of the (non-depth) base format `base`
/// comes from (GL 2.1 Table 3.20).
fn channel_sources(base: u32) -> [Channel; 4] {
    use Channel::{Of, One, Zero};
    match base {
        GL_ALPHA => [Zero, Zero, Zero, Of(3)],
        GL_LUMINANCE => [Of(0), Of(0), Of(0), One],
        GL_LUMINANCE_ALPHA => [Of(0), Of(0), Of(0), Of(3)],
        GL_INTENSITY => [Of(0); 4],
        GL_RED => [Of(0), Zero, Zero, One],
        GL_RG => [Of(0), Of(1), Zero, One],
        GL_RGB => [Of(0), Of(1), Of(2), One],
        _ => [Of(0), Of(1), Of(2), Of(3)],
    }
}

/// [`texel_for`] over 8-bit unsigned normalized values (a raster colour
/// buffer's, read as [`raster::unorm8_to_float`] reads them), by table:
/// for the formats whose channels convert one by one (not integer, depth,
/// packed-float or shared-exponent formats). Every result is
/// [`texel_for`]'s own: the table holds its quantization of each of the
/// 256 values.
pub struct Unorm8Texels {
    sources: [Channel; 4],
    table: [f32; 256],
}

impl Unorm8Texels {
    /// The converter for `internal`, or None for a format it does not
    /// cover.
    pub fn new(internal: i32) -> Option<Unorm8Texels> {
        let special = matches!(internal as u32, GL_R11F_G11F_B10F | GL_RGB9_E5);
        let base = base_format(internal).unwrap_or(GL_RGBA);
        if is_integer_format(internal)
            || special
            || matches!(base, GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL)
        {
            return None;
        }
        let bits = format_bits(internal);
        let mut table = [0f32; 256];
        for (k, t) in table.iter_mut().enumerate() {
            *t = quantize(raster::unorm8_to_float(k as u8), bits);
        }
        Some(Unorm8Texels {
            sources: channel_sources(base),
            table,
        })
    }

    /// The stored texel of the 8-bit RGBA value `px`.
    #[inline]
    pub fn texel(&self, px: [u8; 4]) -> [f32; 4] {
        self.sources.map(|c| match c {
            Channel::Of(i) => self.table[px[i] as usize],
            Channel::Zero => 0.0,
            Channel::One => 1.0,
        })
    }
}

/// Re-quantizes an already expanded texel (for generated mipmaps).
pub(crate) fn texel_for_stored(t: [f32; 4], internal: i32) -> [f32; 4] {
    let bits = format_bits(internal);
    if base_format(internal) == Some(GL_DEPTH_COMPONENT) || is_integer_format(internal) {
        return t;
    }
    if matches!(internal as u32, GL_R11F_G11F_B10F | GL_RGB9_E5) {
        return texel_for(t, internal);
    }
    t.map(|x| quantize(x, bits))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn packed_floats_round_to_their_precision() {
        let t = texel_for(
            [1.0 + 1.0 / 256.0, -3.0, 1e6, 0.5],
            GL_R11F_G11F_B10F as i32,
        );
        assert_eq!(t, [1.0, 0.0, 64512.0, 1.0]);
        let t = texel_for([4.0, 0.01, 1.0, 0.5], GL_RGB9_E5 as i32);
        // The shared exponent of 4.0 leaves steps of 1/64.
        assert_eq!(t, [4.0, 0.015625, 1.0, 1.0]);
        // Denormal 11-bit floats: steps of 2^-20.
        let t = texel_for(
            [3.0 * 2f32.powi(-20), 0.0, 0.0, 1.0],
            GL_R11F_G11F_B10F as i32,
        );
        assert_eq!(t[0], 3.0 * 2f32.powi(-20));
    }

    #[test]
    fn unorm8_table_gives_texel_for_results() {
        let formats = [
            GL_RGBA8,
            GL_RGBA,
            GL_RGB8,
            GL_RGB5_A1,
            GL_RGBA4,
            GL_R3_G3_B2,
            GL_RGB10_A2,
            GL_RGBA16,
            GL_ALPHA8,
            GL_LUMINANCE8,
            GL_LUMINANCE8_ALPHA8,
            GL_INTENSITY8,
            GL_R8,
            GL_RG8,
            GL_RGBA16F,
            GL_RGBA32F,
            GL_SRGB8_ALPHA8,
            GL_R16F,
        ];
        for f in formats {
            let conv = Unorm8Texels::new(f as i32).unwrap_or_else(|| panic!("{f:#x}"));
            for k in 0..=255u8 {
                let px = [k, 255 - k, k / 3, k.wrapping_mul(7)];
                let want = texel_for(px.map(raster::unorm8_to_float), f as i32);
                assert_eq!(
                    conv.texel(px).map(f32::to_bits),
                    want.map(f32::to_bits),
                    "{f:#x} {px:?}"
                );
            }
        }
        for f in [
            GL_RGBA8UI,
            GL_DEPTH_COMPONENT24,
            GL_R11F_G11F_B10F,
            GL_RGB9_E5,
        ] {
            assert!(Unorm8Texels::new(f as i32).is_none(), "{f:#x}");
        }
    }
}
