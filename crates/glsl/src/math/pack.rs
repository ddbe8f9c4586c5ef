//! The packing functions of GL_ARB_shading_language_packing (GLSL 4.20
//! §8.4 in core): one component at a time, as bits of a `u32`.
//!
//! Contract (what constant folding and the executor both compute):
//! - `pack_unorm(x, bits)` is `round(clamp(x, 0, 1) · (2^bits − 1))` and
//!   `pack_snorm(x, bits)` is `round(clamp(x, −1, 1) · (2^(bits−1) − 1))`
//!   as a two's-complement field of `bits` bits. `round` is
//!   [`round_even`] (the spec lets halves go either way; Mesa rounds them to
//!   even), `clamp` is [`clamp`], so a NaN component packs as the low bound
//!   (0 for unorm, −(2^(bits−1) − 1) for snorm).
//! - `unpack_unorm(f, bits)` is `f / (2^bits − 1)`, `unpack_snorm(f, bits)`
//!   is `clamp(f / (2^(bits−1) − 1), −1, 1)` of the field read as signed:
//!   one correctly rounded division each.
//! - `half_from_float` converts to IEEE binary16 rounding to nearest, ties
//!   to even: magnitudes from 65520 on (and infinities) become ±inf, NaN
//!   becomes the quiet NaN `0x7e00` with the input's sign, values below
//!   2^-14 become binary16 subnormals (or ±0). The sign of −0.0 is kept.
//!   (Subnormal `f32` inputs never reach it: floats are flushed.)
//! - `float_from_half` is exact: every binary16 value is an `f32` (its
//!   subnormals are normal `f32`s), NaN payloads move to the top of the
//!   `f32` mantissa.

use super::{clamp, round_even};

/// `2^bits − 1` as a float: the unorm scale.
fn unorm_scale(bits: u32) -> f32 {
    ((1u32 << bits) - 1) as f32
}

/// `2^(bits−1) − 1` as a float: the snorm scale.
fn snorm_scale(bits: u32) -> f32 {
    ((1u32 << (bits - 1)) - 1) as f32
}

/// One unorm field of `bits` bits (8 or 16).
pub fn pack_unorm(x: f32, bits: u32) -> u32 {
    // The product is in [0, scale] and integral after rounding, so the
    // conversion is exact.
    round_even(clamp(x, 0.0, 1.0) * unorm_scale(bits)) as u32
}

/// One snorm field of `bits` bits (8 or 16), its two's complement masked
/// to the field.
pub fn pack_snorm(x: f32, bits: u32) -> u32 {
    let v = round_even(clamp(x, -1.0, 1.0) * snorm_scale(bits)) as i32;
    v as u32 & ((1u32 << bits) - 1)
}

/// The float of a unorm field (the low `bits` bits of `field`).
pub fn unpack_unorm(field: u32, bits: u32) -> f32 {
    (field & ((1u32 << bits) - 1)) as f32 / unorm_scale(bits)
}

/// The float of an snorm field (the low `bits` bits of `field`, signed).
pub fn unpack_snorm(field: u32, bits: u32) -> f32 {
    let shift = 32 - bits;
    let v = ((field << shift) as i32) >> shift;
    clamp(v as f32 / snorm_scale(bits), -1.0, 1.0)
}

/// Bits of the smallest `f32` magnitude that rounds to binary16 infinity
/// (65520, halfway between 65504 and 2^16).
pub const HALF_INF_FROM: u32 = 0x477f_f000;
/// Bits of 2^-14, the smallest normal binary16 magnitude.
pub const HALF_NORMAL_FROM: u32 = 0x3880_0000;

/// binary16 bits of `x` (see the module docs).
pub fn half_from_float(x: f32) -> u32 {
    let b = x.to_bits();
    let sign = (b >> 16) & 0x8000;
    let a = b & 0x7fff_ffff;
    let magnitude = if a > 0x7f80_0000 {
        0x7e00
    } else if a >= HALF_INF_FROM {
        0x7c00
    } else if a >= HALF_NORMAL_FROM {
        // Rebias the exponent (127 − 15 = 112) and drop 13 mantissa
        // bits, adding just under half an ulp plus the kept lowest bit:
        // ties to even, a carry into the exponent where it belongs.
        let r = a - (112 << 23);
        (r + 0x0fff + ((r >> 13) & 1)) >> 13
    } else {
        // A subnormal binary16 counts units of 2^-24; the scaling is
        // exact and the rounding the one of `round_even` (1024 = the
        // smallest normal, the carry again).
        round_even(f32::from_bits(a) * 16_777_216.0) as u32
    };
    sign | magnitude
}

/// The `f32` of the binary16 bits in the low 16 bits of `h`.
pub fn float_from_half(h: u32) -> f32 {
    let sign = (h & 0x8000) << 16;
    let exponent = (h >> 10) & 0x1f;
    let mantissa = h & 0x3ff;
    let magnitude = match exponent {
        0 => (mantissa as f32 * (1.0 / 16_777_216.0)).to_bits(),
        31 => 0x7f80_0000 | (mantissa << 13),
        _ => ((h & 0x7fff) << 13) + (112 << 23),
    };
    f32::from_bits(sign | magnitude)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unorm_and_snorm_fields() {
        assert_eq!(pack_unorm(0.0, 16), 0);
        assert_eq!(pack_unorm(1.0, 16), 0xffff);
        assert_eq!(pack_unorm(2.0, 16), 0xffff);
        assert_eq!(pack_unorm(-1.0, 16), 0);
        assert_eq!(pack_unorm(f32::NAN, 16), 0);
        // 0.5 · 65535 = 32767.5: the tie goes to the even 32768.
        assert_eq!(pack_unorm(0.5, 16), 32768);
        // 0.5 · 255 = 127.5 → 128; 1.5/255 · 255 lands near 1.5 → 2.
        assert_eq!(pack_unorm(0.5, 8), 128);
        assert_eq!(pack_snorm(-1.0, 16), 0x8001);
        assert_eq!(pack_snorm(-2.0, 8), 0x81);
        assert_eq!(pack_snorm(1.0, 8), 0x7f);
        assert_eq!(pack_snorm(-0.0, 16), 0);
        assert_eq!(pack_snorm(f32::NAN, 8), 0x81);
        // 0.5 · 127 = 63.5 → 64; −0.5 · 127 → −64.
        assert_eq!(pack_snorm(0.5, 8), 64);
        assert_eq!(pack_snorm(-0.5, 8), 0xc0);
        assert_eq!(unpack_unorm(0xffff, 16), 1.0);
        assert_eq!(unpack_unorm(0x1_0000, 16), 0.0);
        assert_eq!(unpack_unorm(51, 8), 0.2);
        assert_eq!(unpack_snorm(0x8000, 16), -1.0);
        assert_eq!(unpack_snorm(0x8001, 16), -1.0);
        assert_eq!(unpack_snorm(0x80, 8), -1.0);
        assert_eq!(unpack_snorm(0x7f, 8), 1.0);
        assert_eq!(unpack_snorm(0xc0, 8), -64.0 / 127.0);
    }

    #[test]
    fn half_conversions() {
        let h = half_from_float;
        assert_eq!(h(0.0), 0);
        assert_eq!(h(-0.0), 0x8000);
        assert_eq!(h(1.0), 0x3c00);
        assert_eq!(h(-2.0), 0xc000);
        assert_eq!(h(65504.0), 0x7bff);
        // Just below the tie with 2^16 rounds down; the tie rounds to the
        // even 2^16, which is infinity.
        assert_eq!(h(65519.996), 0x7bff);
        assert_eq!(h(65520.0), 0x7c00);
        assert_eq!(h(f32::INFINITY), 0x7c00);
        assert_eq!(h(f32::NEG_INFINITY), 0xfc00);
        assert_eq!(h(f32::NAN), 0x7e00);
        assert_eq!(h(-f32::NAN), 0xfe00);
        // 1 + 2^-11 is halfway between 1 and 1 + 2^-10: to even, 1.
        assert_eq!(h(1.0 + 1.0 / 2048.0), 0x3c00);
        // 1 + 3·2^-11 is halfway between odd and even: up, to even.
        assert_eq!(h(1.0 + 3.0 / 2048.0), 0x3c02);
        // Subnormals: 2^-24 is 1, 2^-25 a tie to 0, 3·2^-25 a tie to 2.
        assert_eq!(h(5.960_464_5e-8), 1);
        assert_eq!(h(2.980_232_2e-8), 0);
        assert_eq!(h(8.940_697e-8), 2);
        assert_eq!(h(-1023.0 / 16_777_216.0), 0x83ff);
        // 2^-14 − 2^-25 rounds up to the smallest normal.
        assert_eq!(h(6.103_515_6e-5 - 2.980_232_2e-8), 0x0400);
        let f = float_from_half;
        assert_eq!(f(0x3c00), 1.0);
        assert_eq!(f(0x8000).to_bits(), 0x8000_0000);
        assert_eq!(f(0x0001), 5.960_464_5e-8);
        assert_eq!(f(0x83ff), -1023.0 / 16_777_216.0);
        assert_eq!(f(0x7bff), 65504.0);
        assert_eq!(f(0xfc00), f32::NEG_INFINITY);
        assert_eq!(f(0x7e00).to_bits(), 0x7fc0_0000);
        assert_eq!(f(0x7c01).to_bits(), 0x7f80_2000);
        // Every binary16 value survives the round trip (NaNs as quiet
        // NaNs of their sign).
        for bits in 0..0x1_0000u32 {
            let back = h(f(bits));
            if bits & 0x7c00 == 0x7c00 && bits & 0x3ff != 0 {
                assert_eq!(back, (bits & 0x8000) | 0x7e00);
            } else {
                assert_eq!(back, bits, "{bits:#x}");
            }
        }
    }
}
