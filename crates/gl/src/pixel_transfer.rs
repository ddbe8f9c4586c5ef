//! Pixel transfer between client images and RGBA values (GL 2.1 §3.6
//! unpacking, §4.3.2 packing): the layout of a client image (components
//! and bytes per pixel of a format/type pair, row stride at an alignment),
//! unpacking it to RGBA values or to texels, packing RGBA values into it,
//! and the transfer operations (scale, bias, index shift) that apply to
//! pixel rectangles.
//!
//! Contract: pure functions of their arguments (no context state). Rows
//! are bottom row first and padded to the alignment; a short client
//! buffer reads as zero bytes and a short destination drops what does not
//! fit. Unpacking converts as §3.6.4 "Conversion to RGB" says (missing
//! color components 0, missing alpha 1); packing as §4.3.2 and Table 4.7
//! (luminance is R + G + B, clamped). Every client-image conversion of the
//! crate, and the C layer's image sizes, go through here.

use crate::enums::*;
use crate::texture_format::{integer_texel, texel_for, Unorm8Texels};

/// Components per pixel of a client format.
pub fn format_components(format: u32) -> Option<usize> {
    if let Some(plain) = integer_client_format(format) {
        return format_components(plain);
    }
    Some(match format {
        GL_RED | GL_GREEN | GL_BLUE | GL_ALPHA | GL_LUMINANCE | GL_DEPTH_COMPONENT
        | GL_STENCIL_INDEX | GL_COLOR_INDEX => 1,
        GL_LUMINANCE_ALPHA | GL_RG | GL_DEPTH_STENCIL => 2,
        GL_RGB | GL_BGR => 3,
        GL_RGBA | GL_BGRA => 4,
        _ => return None,
    })
}

/// The plain format of an integer client format (GL 3.0 Table 3.6:
/// RED_INTEGER is RED with integer components...), `None` for the others.
pub fn integer_client_format(format: u32) -> Option<u32> {
    Some(match format {
        GL_RED_INTEGER => GL_RED,
        GL_GREEN_INTEGER => GL_GREEN,
        GL_BLUE_INTEGER => GL_BLUE,
        GL_ALPHA_INTEGER => GL_ALPHA,
        GL_RG_INTEGER => GL_RG,
        GL_RGB_INTEGER => GL_RGB,
        GL_RGBA_INTEGER => GL_RGBA,
        GL_BGR_INTEGER => GL_BGR,
        GL_BGRA_INTEGER => GL_BGRA,
        _ => return None,
    })
}

/// Decodes one pixel of client data of an integer format into its
/// components as integers (unnormalized; 0 for those it lacks).
fn decode_pixel_int(b: &[u8], n: usize, ty: u32) -> [i64; 4] {
    let mut out = [0i64; 4];
    let rd = |i: usize, s: usize| -> u32 {
        let mut v = [0u8; 4];
        if let Some(src) = b.get(i * s..i * s + s) {
            v[..s].copy_from_slice(src);
        }
        u32::from_le_bytes(v)
    };
    let fields = |word: u32, f: [(u32, u32); 4]| {
        f.map(|(shift, bits)| ((word >> shift) & ((1u32 << bits) - 1)) as i64)
    };
    match ty {
        GL_UNSIGNED_INT_8_8_8_8 => return fields(rd(0, 4), [(24, 8), (16, 8), (8, 8), (0, 8)]),
        GL_UNSIGNED_INT_8_8_8_8_REV => return fields(rd(0, 4), [(0, 8), (8, 8), (16, 8), (24, 8)]),
        GL_UNSIGNED_INT_2_10_10_10_REV => {
            return fields(rd(0, 4), [(0, 10), (10, 10), (20, 10), (30, 2)])
        }
        GL_UNSIGNED_SHORT_5_6_5 => {
            let v = fields(rd(0, 2), [(11, 5), (5, 6), (0, 5), (0, 1)]);
            return [v[0], v[1], v[2], 0];
        }
        GL_UNSIGNED_SHORT_5_6_5_REV => {
            let v = fields(rd(0, 2), [(0, 5), (5, 6), (11, 5), (0, 1)]);
            return [v[0], v[1], v[2], 0];
        }
        GL_UNSIGNED_SHORT_4_4_4_4 => return fields(rd(0, 2), [(12, 4), (8, 4), (4, 4), (0, 4)]),
        GL_UNSIGNED_SHORT_4_4_4_4_REV => {
            return fields(rd(0, 2), [(0, 4), (4, 4), (8, 4), (12, 4)])
        }
        GL_UNSIGNED_SHORT_5_5_5_1 => return fields(rd(0, 2), [(11, 5), (6, 5), (1, 5), (0, 1)]),
        GL_UNSIGNED_SHORT_1_5_5_5_REV => {
            return fields(rd(0, 2), [(0, 5), (5, 5), (10, 5), (15, 1)])
        }
        _ => {}
    }
    for (i, o) in out.iter_mut().enumerate().take(n) {
        *o = match ty {
            GL_UNSIGNED_BYTE => rd(i, 1) as i64,
            GL_BYTE => rd(i, 1) as u8 as i8 as i64,
            GL_UNSIGNED_SHORT => rd(i, 2) as i64,
            GL_SHORT => rd(i, 2) as u16 as i16 as i64,
            GL_UNSIGNED_INT => rd(i, 4) as i64,
            GL_INT => rd(i, 4) as i32 as i64,
            _ => 0,
        };
    }
    out
}

/// Bytes per pixel and per component of a client format/type pair (packed
/// types count as one component), or `None` if the pair is invalid.
pub fn pixel_size(format: u32, ty: u32) -> Option<(usize, usize)> {
    let n = format_components(format)?;
    let packed = |comps: usize, bytes: usize| (n == comps).then_some((bytes, bytes));
    match ty {
        GL_UNSIGNED_BYTE | GL_BYTE => Some((n, 1)),
        GL_UNSIGNED_SHORT | GL_SHORT | GL_HALF_FLOAT => Some((2 * n, 2)),
        GL_UNSIGNED_INT | GL_INT | GL_FLOAT => Some((4 * n, 4)),
        GL_UNSIGNED_INT_8_8_8_8 | GL_UNSIGNED_INT_8_8_8_8_REV | GL_UNSIGNED_INT_2_10_10_10_REV => {
            packed(4, 4)
        }
        GL_UNSIGNED_INT_24_8 => (format == GL_DEPTH_STENCIL).then_some((4, 4)),
        GL_UNSIGNED_SHORT_5_6_5 | GL_UNSIGNED_SHORT_5_6_5_REV => packed(3, 2),
        GL_UNSIGNED_SHORT_4_4_4_4
        | GL_UNSIGNED_SHORT_4_4_4_4_REV
        | GL_UNSIGNED_SHORT_5_5_5_1
        | GL_UNSIGNED_SHORT_1_5_5_5_REV => packed(4, 2),
        _ => None,
    }
}

/// Row stride in bytes under an alignment (GL 2.1 §3.6.4, Unpacking).
pub fn row_stride(width: usize, format: u32, ty: u32, alignment: usize) -> usize {
    let Some((px, comp)) = pixel_size(format, ty) else {
        return 0;
    };
    let raw = px.saturating_mul(width);
    let a = alignment.max(1);
    if comp >= a {
        raw
    } else {
        raw.div_ceil(a).saturating_mul(a)
    }
}

pub(crate) fn half_to_f32(h: u16) -> f32 {
    let sign = if h & 0x8000 != 0 { -1.0f32 } else { 1.0 };
    let e = ((h >> 10) & 0x1f) as i32;
    let m = (h & 0x3ff) as f32;
    let v = match e {
        0 => m * (2.0f32).powi(-24),
        31 => {
            if m == 0.0 {
                f32::INFINITY
            } else {
                f32::NAN
            }
        }
        _ => (1.0 + m / 1024.0) * (2.0f32).powi(e - 15),
    };
    sign * v
}

/// Decodes one pixel of client data into component values (before the
/// format's conversion to RGBA).
fn decode_pixel(b: &[u8], n: usize, ty: u32) -> [f32; 4] {
    let mut out = [0.0f32; 4];
    let rd = |i: usize, s: usize| -> u32 {
        let mut v = [0u8; 4];
        if let Some(src) = b.get(i * s..i * s + s) {
            v[..s].copy_from_slice(src);
        }
        u32::from_le_bytes(v)
    };
    let unpack = |word: u32, shifts: [(u32, u32); 4]| -> [f32; 4] {
        shifts.map(|(shift, bits)| {
            let max = (1u32 << bits) - 1;
            ((word >> shift) & max) as f32 / max as f32
        })
    };
    match ty {
        GL_UNSIGNED_BYTE => (0..n).for_each(|i| out[i] = rd(i, 1) as f32 / 255.0),
        GL_BYTE => (0..n).for_each(|i| out[i] = ((rd(i, 1) as u8 as i8) as f32 / 127.0).max(-1.0)),
        GL_UNSIGNED_SHORT => (0..n).for_each(|i| out[i] = rd(i, 2) as f32 / 65535.0),
        GL_SHORT => {
            (0..n).for_each(|i| out[i] = ((rd(i, 2) as u16 as i16) as f32 / 32767.0).max(-1.0))
        }
        GL_UNSIGNED_INT => (0..n).for_each(|i| out[i] = (rd(i, 4) as f64 / 4294967295.0) as f32),
        GL_INT => {
            (0..n).for_each(|i| out[i] = ((rd(i, 4) as i32) as f64 / 2147483647.0).max(-1.0) as f32)
        }
        GL_FLOAT => (0..n).for_each(|i| out[i] = f32::from_bits(rd(i, 4))),
        GL_HALF_FLOAT => (0..n).for_each(|i| out[i] = half_to_f32(rd(i, 2) as u16)),
        GL_UNSIGNED_INT_8_8_8_8 => out = unpack(rd(0, 4), [(24, 8), (16, 8), (8, 8), (0, 8)]),
        GL_UNSIGNED_INT_8_8_8_8_REV => out = unpack(rd(0, 4), [(0, 8), (8, 8), (16, 8), (24, 8)]),
        GL_UNSIGNED_INT_2_10_10_10_REV => {
            out = unpack(rd(0, 4), [(0, 10), (10, 10), (20, 10), (30, 2)])
        }
        GL_UNSIGNED_INT_24_8 => out[0] = (rd(0, 4) >> 8) as f32 / 16777215.0,
        GL_UNSIGNED_SHORT_5_6_5 => {
            let v = unpack(rd(0, 2), [(11, 5), (5, 6), (0, 5), (0, 1)]);
            out = [v[0], v[1], v[2], 0.0];
        }
        GL_UNSIGNED_SHORT_5_6_5_REV => {
            let v = unpack(rd(0, 2), [(0, 5), (5, 6), (11, 5), (0, 1)]);
            out = [v[0], v[1], v[2], 0.0];
        }
        GL_UNSIGNED_SHORT_4_4_4_4 => out = unpack(rd(0, 2), [(12, 4), (8, 4), (4, 4), (0, 4)]),
        GL_UNSIGNED_SHORT_4_4_4_4_REV => out = unpack(rd(0, 2), [(0, 4), (4, 4), (8, 4), (12, 4)]),
        GL_UNSIGNED_SHORT_5_5_5_1 => out = unpack(rd(0, 2), [(11, 5), (6, 5), (1, 5), (0, 1)]),
        GL_UNSIGNED_SHORT_1_5_5_5_REV => out = unpack(rd(0, 2), [(0, 5), (5, 5), (10, 5), (15, 1)]),
        _ => {}
    }
    out
}

/// Client pixel components to RGBA (GL 2.1 §3.6.4, "Conversion to RGB"):
/// missing color components are 0, missing alpha 1; luminance goes to red.
fn to_rgba(c: [f32; 4], format: u32) -> [f32; 4] {
    match format {
        GL_RED | GL_LUMINANCE | GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL => [c[0], 0.0, 0.0, 1.0],
        GL_GREEN => [0.0, c[0], 0.0, 1.0],
        GL_BLUE => [0.0, 0.0, c[0], 1.0],
        GL_ALPHA => [0.0, 0.0, 0.0, c[0]],
        GL_LUMINANCE_ALPHA => [c[0], 0.0, 0.0, c[1]],
        GL_RG => [c[0], c[1], 0.0, 1.0],
        GL_RGB => [c[0], c[1], c[2], 1.0],
        GL_BGR => [c[2], c[1], c[0], 1.0],
        GL_BGRA => [c[2], c[1], c[0], c[3]],
        _ => c,
    }
}

/// Unpacks `w * h` client pixels of `format`/`ty` (rows at `alignment`,
/// bottom row first) into RGBA values before any texture-format
/// conversion (GL 2.1 §3.6.4 "Conversion to RGB": missing color
/// components 0, missing alpha 1, luminance L to (L, L, L); depth and
/// stencil values in red).
pub fn unpack_rgba(
    data: &[u8],
    w: usize,
    h: usize,
    format: u32,
    ty: u32,
    alignment: usize,
) -> Vec<[f32; 4]> {
    let (px, _) = pixel_size(format, ty).unwrap_or((4, 1));
    let n = format_components(format).unwrap_or(4);
    let stride = row_stride(w, format, ty, alignment);
    let mut out = Vec::with_capacity(w.saturating_mul(h).min(1 << 24));
    for y in 0..h {
        let row = y.saturating_mul(stride);
        for x in 0..w {
            let at = row.saturating_add(x * px);
            let b = data.get(at..at.saturating_add(px)).unwrap_or(&[]);
            let c = to_rgba(decode_pixel(b, n, ty), format);
            out.push(match format {
                // Conversion to RGB: L becomes (L, L, L).
                GL_LUMINANCE | GL_LUMINANCE_ALPHA => [c[0], c[0], c[0], c[3]],
                _ => c,
            });
        }
    }
    out
}

/// Unpacks a client image into texels for `internal`.
#[allow(clippy::too_many_arguments)]
pub fn unpack_image(
    data: Option<&[u8]>,
    w: usize,
    h: usize,
    d: usize,
    format: u32,
    ty: u32,
    internal: i32,
    alignment: usize,
) -> Vec<[f32; 4]> {
    let len = w.saturating_mul(h).saturating_mul(d);
    let Some(data) = data else {
        return vec![texel_for([0.0; 4], internal); len];
    };
    let (px, _) = pixel_size(format, ty).unwrap_or((4, 1));
    let n = format_components(format).unwrap_or(4);
    let stride = row_stride(w, format, ty, alignment);
    // Each pixel's bytes in turn (empty past the end of the data): rows
    // `stride` bytes apart, `d` images of `h` rows.
    let pixels = (0..d.saturating_mul(h)).flat_map(|row| {
        let row = row.saturating_mul(stride);
        (0..w).map(move |x| {
            let at = row.saturating_add(x * px);
            data.get(at..at.saturating_add(px)).unwrap_or(&[])
        })
    });
    if let Some(plain) = integer_client_format(format) {
        // Integer data for an integer texture: components kept as
        // integers, placed as the plain format places them.
        return pixels
            .map(|b| {
                let c = decode_pixel_int(b, n, ty);
                let rgba = match plain {
                    GL_GREEN => [0, c[0], 0, 1],
                    GL_BLUE => [0, 0, c[0], 1],
                    GL_ALPHA => [0, 0, 0, c[0]],
                    GL_RED => [c[0], 0, 0, 1],
                    GL_RG => [c[0], c[1], 0, 1],
                    GL_RGB => [c[0], c[1], c[2], 1],
                    GL_BGR => [c[2], c[1], c[0], 1],
                    GL_BGRA => [c[2], c[1], c[0], c[3]],
                    _ => c,
                };
                integer_texel(rgba, internal)
            })
            .collect();
    }
    if let (GL_UNSIGNED_BYTE, Some(order), Some(conv)) =
        (ty, unorm8_order(format), Unorm8Texels::new(internal))
    {
        // Bytes straight to texels by table: the same values as below
        // (to_rgba's 0 and 1 are the bytes 0 and 255 here).
        return pixels
            .map(|b| {
                conv.texel(order.map(|o| match o {
                    Byte::At(i) => b.get(i).copied().unwrap_or(0),
                    Byte::Zero => 0,
                    Byte::Full => 255,
                }))
            })
            .collect();
    }
    pixels
        .map(|b| texel_for(to_rgba(decode_pixel(b, n, ty), format), internal))
        .collect()
}

/// One RGBA component of a byte pixel ([`unorm8_order`]).
#[derive(Clone, Copy)]
enum Byte {
    /// The pixel's byte `i` (0 past the end of the data, as
    /// [`decode_pixel`] reads it).
    At(usize),
    /// The constant 0.
    Zero,
    /// The constant 1 (the byte 255).
    Full,
}

/// For [`unpack_image`]'s byte path: where each RGBA component of a pixel
/// of `format` comes from, as [`to_rgba`] places them; None for formats
/// other than the colour ones.
fn unorm8_order(format: u32) -> Option<[Byte; 4]> {
    use Byte::{At, Full, Zero};
    Some(match format {
        GL_RED | GL_LUMINANCE => [At(0), Zero, Zero, Full],
        GL_GREEN => [Zero, At(0), Zero, Full],
        GL_BLUE => [Zero, Zero, At(0), Full],
        GL_ALPHA => [Zero, Zero, Zero, At(0)],
        GL_LUMINANCE_ALPHA => [At(0), Zero, Zero, At(1)],
        GL_RG => [At(0), At(1), Zero, Full],
        GL_RGB => [At(0), At(1), At(2), Full],
        GL_BGR => [At(2), At(1), At(0), Full],
        GL_BGRA => [At(2), At(1), At(0), At(3)],
        GL_RGBA => [At(0), At(1), At(2), At(3)],
        _ => return None,
    })
}

/// Packs `w * h` RGBA values (bottom row first) as `format`/`ty` rows at
/// `align` (GL 2.1 §4.3.2's conversions, as glReadPixels).
pub(crate) fn pack_pixels(
    block: &[[f32; 4]],
    w: usize,
    h: usize,
    format: u32,
    ty: u32,
    align: usize,
) -> Vec<u8> {
    if format_components(format).is_none() || pixel_size(format, ty).is_none() {
        return Vec::new();
    }
    let stride = row_stride(w, format, ty, align);
    let mut out = vec![0u8; stride.saturating_mul(h)];
    pack_into(block, w, h, format, ty, align, &mut out);
    out
}

/// Packs `w * h` integer texels (the integers' bits, signed or not) as an
/// integer client format `format`/`ty` at `align`: each component the
/// plain format takes, clamped to the type's range (EXT_texture_integer's
/// final conversion for integer colours).
pub(crate) fn pack_integer_pixels(
    block: &[[f32; 4]],
    signed: bool,
    w: usize,
    h: usize,
    format: u32,
    ty: u32,
    align: usize,
) -> Vec<u8> {
    let (Some(plain), Some((px, comp))) = (integer_client_format(format), pixel_size(format, ty))
    else {
        return Vec::new();
    };
    let stride = row_stride(w, format, ty, align);
    let mut out = vec![0u8; stride.saturating_mul(h)];
    let (lo, hi): (i64, i64) = match ty {
        GL_UNSIGNED_BYTE => (0, u8::MAX as i64),
        GL_BYTE => (i8::MIN as i64, i8::MAX as i64),
        GL_UNSIGNED_SHORT => (0, u16::MAX as i64),
        GL_SHORT => (i16::MIN as i64, i16::MAX as i64),
        GL_UNSIGNED_INT => (0, u32::MAX as i64),
        _ => (i32::MIN as i64, i32::MAX as i64),
    };
    for row in 0..h {
        for col in 0..w {
            let Some(p) = block.get(row * w + col) else {
                continue;
            };
            let v = p.map(|x| {
                if signed {
                    x.to_bits() as i32 as i64
                } else {
                    x.to_bits() as i64
                }
            });
            let [r, g, b, a] = v;
            let vals: &[i64] = match plain {
                GL_RED => &[r],
                GL_GREEN => &[g],
                GL_BLUE => &[b],
                GL_ALPHA => &[a],
                GL_RG => &[r, g],
                GL_RGB => &[r, g, b],
                GL_BGR => &[b, g, r],
                GL_BGRA => &[b, g, r, a],
                _ => &[r, g, b, a],
            };
            let at = row * stride + col * px;
            for (c, &x) in vals.iter().enumerate() {
                let o = at + c * comp;
                let bytes = x.clamp(lo, hi).to_le_bytes();
                if let Some(dst) = out.get_mut(o..o + comp) {
                    dst.copy_from_slice(&bytes[..comp]);
                }
            }
        }
    }
    out
}

/// [`pack_pixels`] into the client buffer `out` (bytes past its end are
/// dropped; bytes between pixels are left as they are).
pub(crate) fn pack_into(
    block: &[[f32; 4]],
    w: usize,
    h: usize,
    format: u32,
    ty: u32,
    align: usize,
    out: &mut [u8],
) {
    let (Some(n), Some((px, comp))) = (format_components(format), pixel_size(format, ty)) else {
        return;
    };
    let stride = row_stride(w, format, ty, align);
    for row in 0..h {
        for col in 0..w {
            let Some(p) = block.get(row * w + col) else {
                continue;
            };
            let vals = pack_components(*p, format);
            let at = row * stride + col * px;
            for (c, v) in vals.iter().take(n).enumerate() {
                let o = at + c * comp;
                if let Some(dst) = out.get_mut(o..o + comp) {
                    encode(*v, ty, format == GL_STENCIL_INDEX, dst);
                }
            }
        }
    }
}

/// The components a client format takes from an RGBA (or depth/stencil in
/// component 0) value; luminance is R + G + B (GL 2.1 §4.3.2).
fn pack_components(p: [f32; 4], format: u32) -> Vec<f32> {
    let [r, g, b, a] = p;
    match format {
        GL_RED | GL_DEPTH_COMPONENT | GL_STENCIL_INDEX => vec![r],
        GL_GREEN => vec![g],
        GL_BLUE => vec![b],
        GL_ALPHA => vec![a],
        GL_LUMINANCE => vec![(r + g + b).min(1.0)],
        GL_LUMINANCE_ALPHA => vec![(r + g + b).min(1.0), a],
        GL_RG => vec![r, g],
        GL_RGB => vec![r, g, b],
        GL_BGR => vec![b, g, r],
        GL_BGRA => vec![b, g, r, a],
        _ => vec![r, g, b, a],
    }
}

/// Writes one component (GL 2.1 Table 4.7 conversions; stencil indices
/// are written as integers).
fn encode(v: f32, ty: u32, index: bool, dst: &mut [u8]) {
    let unorm = |max: f64| -> u64 {
        let c = if v > 0.0 { (v as f64).min(1.0) } else { 0.0 };
        (c * max + 0.5).floor() as u64
    };
    let snorm = |max: f64| -> i64 {
        let c = (v as f64).clamp(-1.0, 1.0);
        let c = if v.is_nan() { 0.0 } else { c };
        (c * max).round() as i64
    };
    // Little-endian bytes of the converted value, `n` of them (no
    // allocation: this runs per component of every pixel read).
    let mut bytes = [0u8; 8];
    let mut put = |b: &[u8]| {
        let n = b.len().min(8);
        bytes[..n].copy_from_slice(&b[..n]);
        n
    };
    let n = match ty {
        GL_FLOAT => put(&v.to_le_bytes()),
        _ if index => put(&(v as i64).to_le_bytes()).min(dst.len()),
        GL_UNSIGNED_BYTE => put(&[unorm(255.0) as u8]),
        GL_BYTE => put(&[snorm(127.0) as i8 as u8]),
        GL_UNSIGNED_SHORT => put(&(unorm(65535.0) as u16).to_le_bytes()),
        GL_SHORT => put(&(snorm(32767.0) as i16).to_le_bytes()),
        GL_UNSIGNED_INT => put(&(unorm(4294967295.0) as u32).to_le_bytes()),
        GL_INT => put(&(snorm(2147483647.0) as i32).to_le_bytes()),
        _ => {
            dst.fill(0);
            return;
        }
    };
    for (d, s) in dst.iter_mut().zip(&bytes[..n]) {
        *d = *s;
    }
}

/// Bytes per row of a glBitmap image (GL 2.1 §3.6.4 with one bit per
/// pixel) at `alignment`.
pub fn bitmap_row_bytes(width: usize, alignment: usize) -> usize {
    let a = alignment.max(1);
    width.div_ceil(8).div_ceil(a).saturating_mul(a)
}

/// The pixel transfer state that applies to pixel rectangles (kept by the
/// caller, e.g. a C layer that stores glPixelTransfer and glPixelZoom).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelTransfer {
    /// GL_RED_SCALE .. GL_ALPHA_SCALE and GL_RED_BIAS .. GL_ALPHA_BIAS.
    pub scale: [f32; 4],
    pub bias: [f32; 4],
    pub depth_scale: f32,
    pub depth_bias: f32,
    /// GL_INDEX_SHIFT / GL_INDEX_OFFSET (stencil indices).
    pub index_shift: i32,
    pub index_offset: i32,
    /// glPixelZoom.
    pub zoom: (f32, f32),
}

impl Default for PixelTransfer {
    fn default() -> Self {
        PixelTransfer {
            scale: [1.0; 4],
            bias: [0.0; 4],
            depth_scale: 1.0,
            depth_bias: 0.0,
            index_shift: 0,
            index_offset: 0,
            zoom: (1.0, 1.0),
        }
    }
}

/// `x` clamped to [0, 1], NaN to 0.
pub(crate) fn clamp01(x: f32) -> f32 {
    if x > 0.0 {
        x.min(1.0)
    } else {
        0.0
    }
}

impl PixelTransfer {
    pub(crate) fn color(&self, c: [f32; 4]) -> [f32; 4] {
        std::array::from_fn(|i| clamp01(c[i] * self.scale[i] + self.bias[i]))
    }

    pub(crate) fn depth(&self, d: f32) -> f32 {
        clamp01(d * self.depth_scale + self.depth_bias)
    }

    pub(crate) fn index(&self, s: i64) -> u8 {
        let shifted = if self.index_shift >= 0 {
            s.checked_shl(self.index_shift.min(62) as u32).unwrap_or(0)
        } else {
            s >> (-(self.index_shift as i64)).min(63)
        };
        (shifted.wrapping_add(self.index_offset as i64) & 0xff) as u8
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn byte_images_unpack_by_table_as_by_conversion() {
        let formats = [
            GL_RED,
            GL_GREEN,
            GL_BLUE,
            GL_ALPHA,
            GL_LUMINANCE,
            GL_LUMINANCE_ALPHA,
            GL_RG,
            GL_RGB,
            GL_BGR,
            GL_BGRA,
            GL_RGBA,
        ];
        let internals = [
            GL_RGBA8,
            GL_RGB8,
            GL_RGB5_A1,
            GL_ALPHA8,
            GL_LUMINANCE8_ALPHA8,
            GL_R8,
            GL_RGBA16F,
        ];
        // 4x3 pixels of every byte value in turn, the last row short.
        let data: Vec<u8> = (0..=255u8).cycle().step_by(7).take(4 * 3 * 4 - 3).collect();
        for format in formats {
            let n = format_components(format).unwrap();
            for internal in internals {
                let got = unpack_image(
                    Some(&data),
                    4,
                    3,
                    1,
                    format,
                    GL_UNSIGNED_BYTE,
                    internal as i32,
                    1,
                );
                let want: Vec<[f32; 4]> = (0..12)
                    .map(|p| {
                        let b = data.get(p * n..p * n + n).unwrap_or(&[]);
                        texel_for(
                            to_rgba(decode_pixel(b, n, GL_UNSIGNED_BYTE), format),
                            internal as i32,
                        )
                    })
                    .collect();
                assert_eq!(got.len(), want.len());
                for (g, w) in got.iter().zip(&want) {
                    assert_eq!(
                        g.map(f32::to_bits),
                        w.map(f32::to_bits),
                        "{format:#x} {internal:#x}"
                    );
                }
            }
        }
    }
}
