//! Per-lane arithmetic of the fast path, written so that loops over the
//! 16 lanes vectorize: the floor with `levels::floor`'s bits but no
//! branch ([`floor_lane`], or the rounding instruction in AVX2 code:
//! [`floor_of`]), its conversion to a texel index, and a lane mask as
//! flags for selects.

use crate::ex::LANES;

/// The floor of `x` for the fast path's uses: with `SIMD` (code compiled
/// for AVX2, so SSE4.1), the rounding instruction, else [`floor_lane`].
/// Both give `levels::floor`'s bits except on signaling NaNs, which the
/// instruction quiets; no use tells them apart: a NaN floor becomes
/// index 0 ([`floor_index`]), or is subtracted from the NaN it is the
/// floor of, and a NaN minuend gives itself, quieted, whatever the
/// subtrahend.
#[inline(always)]
pub(super) fn floor_of<const SIMD: bool>(x: f32) -> f32 {
    if SIMD {
        x.floor()
    } else {
        floor_lane(x)
    }
}

/// `levels::floor` without a branch (so loops over lanes vectorize):
/// |x| ≥ 2^23, infinities and NaN are their own floor.
#[inline(always)]
pub(super) fn floor_lane(x: f32) -> f32 {
    let small = x.abs() < 8_388_608.0;
    let t = to_i32(if small { x } else { 0.0 }) as f32;
    let fl = if t > x { t - 1.0 } else { t };
    if small && fl != x {
        fl
    } else {
        x
    }
}

/// `x as i32` for |x| < 2^31, without the saturating conversion's NaN and
/// range fix-ups (which keep loops from vectorizing).
#[inline(always)]
fn to_i32(x: f32) -> i32 {
    debug_assert!(x.abs() < 2_147_483_648.0);
    // SAFETY: every caller passes a value with |x| < 2^31 (an integral
    // f32 below 2^23 in magnitude, or a floor clamped to ±2^30), which
    // truncates to an i32 exactly.
    unsafe { x.to_int_unchecked::<i32>() }
}

/// `floor_lane(x) as i64` as an i32 for a floor in [−2^30, 2^30] (every
/// wrapped coordinate's); NaN gives 0 like `as`.
#[inline(always)]
pub(super) fn floor_index(fl: f32) -> i32 {
    let bounded = if fl.is_nan() {
        0.0
    } else {
        fl.clamp(-1_073_741_824.0, 1_073_741_824.0)
    };
    to_i32(bounded)
}

/// The lanes of a mask, one flag each (for selects over all lanes).
#[inline(always)]
pub(super) fn lanes(mask: u32) -> [bool; LANES] {
    let mut flags = [false; LANES];
    for (l, flag) in flags.iter_mut().enumerate() {
        *flag = mask & (1 << l) != 0;
    }
    flags
}
