//! Texel addressing over the 16 lanes, for the levels a request reads
//! (no border: REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT): each lane's level
//! size, the wrapped and scaled coordinates (`levels::wrap_coord`), the
//! texels of each axis and LINEAR's weights (in f32, or in 128ths for
//! the fixed-point filter of `unorm8_filter`), and the four corners'
//! texel indices.

use super::lanes::{floor_index, floor_of};
use super::storage::LevelTable;
use crate::ex::LANES;
use crate::texture::levels::wrap_coord;
use crate::texture::Wrap;
use crate::unorm8_filter;

/// The per-lane sizes of `level` (level base + s is `max(1, size >> s)`
/// texels wide and high, `Checked::new` checks it; s in 0..=31).
#[inline(always)]
pub(super) fn level_sizes(
    table: &LevelTable,
    level: &[i32; LANES],
) -> ([i32; LANES], [i32; LANES]) {
    let mut w = [1i32; LANES];
    let mut h = [1i32; LANES];
    for l in 0..LANES {
        let s = (level[l].wrapping_sub(table.base) as u32).min(31);
        w[l] = (table.width >> s).max(1) as i32;
        h[l] = (table.height >> s).max(1) as i32;
    }
    (w, h)
}

/// `wrap_coord(s, wrap, n) * n` for every lane.
#[inline(always)]
pub(super) fn wrap_scale<const SIMD: bool>(
    wrap: Wrap,
    s: &[f32; LANES],
    n: &[i32; LANES],
) -> [f32; LANES] {
    let mut u = [0.0f32; LANES];
    match wrap {
        Wrap::Repeat => {
            for l in 0..LANES {
                u[l] = (s[l] - floor_of::<SIMD>(s[l])) * n[l] as f32;
            }
        }
        Wrap::ClampToEdge => {
            for l in 0..LANES {
                let nf = n[l] as f32;
                let half = 0.5 / nf;
                // f32::clamp without its (here impossible) panic.
                let mut x = s[l];
                if x < half {
                    x = half;
                }
                if x > 1.0 - half {
                    x = 1.0 - half;
                }
                u[l] = x * nf;
            }
        }
        _ => {
            for l in 0..LANES {
                u[l] = wrap_coord(s[l], wrap, n[l] as u32) * n[l] as f32;
            }
        }
    }
    u
}

/// `index(i, wrap, n)` for the borderless modes and i in [−1, n], the
/// only values a wrapped coordinate gives (`fract` is in [0, 1]), clamped
/// into the level for safety.
#[inline(always)]
fn wrap_index(i: i32, wrap: Wrap, n: i32) -> i32 {
    let i = match wrap {
        Wrap::Repeat => {
            if i < 0 {
                i + n
            } else if i >= n {
                i - n
            } else {
                i
            }
        }
        _ => i,
    };
    // (Not `clamp`: its assertion keeps the lane loops from vectorizing.)
    i.max(0).min(n - 1)
}

/// Per axis and lane: texel 0, texel 1 and the weight of texel 1 for
/// LINEAR, or the texel (in texel 0) for the lanes in `nearest`. Computes
/// both for every lane and selects (so the loop vectorizes).
#[inline(always)]
pub(super) fn axis<const SIMD: bool>(
    u: &[f32; LANES],
    n: &[i32; LANES],
    wrap: Wrap,
    nearest: &[bool; LANES],
) -> ([i32; LANES], [i32; LANES], [f32; LANES]) {
    let mut i0 = [0i32; LANES];
    let mut i1 = [0i32; LANES];
    let mut alpha = [0.0f32; LANES];
    for l in 0..LANES {
        let v = u[l] - 0.5;
        let fl = floor_of::<SIMD>(v);
        alpha[l] = v - fl;
        (i0[l], i1[l]) = texels::<SIMD>(floor_index(fl), u[l], n[l], wrap, nearest[l]);
    }
    (i0, i1, alpha)
}

/// The two texels of a LINEAR axis whose first is `i` (unwrapped), or the
/// NEAREST texel of coordinate `u` first when `nearest`, wrapped into a
/// level `n` texels long.
#[inline(always)]
fn texels<const SIMD: bool>(i: i32, u: f32, n: i32, wrap: Wrap, nearest: bool) -> (i32, i32) {
    let near = wrap_index(floor_index(floor_of::<SIMD>(u)), wrap, n);
    let i0 = if nearest {
        near
    } else {
        wrap_index(i, wrap, n)
    };
    (i0, wrap_index(i.saturating_add(1), wrap, n))
}

/// [`axis`] for the fixed-point filter ([`unorm8_filter`]): texel 0
/// (the NEAREST texel on the lanes in `nearest`), texel 1 and the weight
/// of texel 1 in 128ths (0 for NEAREST).
#[inline(always)]
pub(super) fn axis_unorm8<const SIMD: bool>(
    u: &[f32; LANES],
    n: &[i32; LANES],
    wrap: Wrap,
    nearest: &[bool; LANES],
) -> ([i32; LANES], [i32; LANES], [i32; LANES]) {
    let mut i0 = [0i32; LANES];
    let mut i1 = [0i32; LANES];
    let mut weight = [0i32; LANES];
    for l in 0..LANES {
        let (i, a) = unorm8_filter::split(unorm8_filter::coord(floor_of::<SIMD>(u[l] * 128.0)));
        (i0[l], i1[l]) = texels::<SIMD>(i, u[l], n[l], wrap, nearest[l]);
        weight[l] = if nearest[l] { 0 } else { a };
    }
    (i0, i1, weight)
}

/// Texel indices of the corners (S varies fastest), `j * width + i`:
/// below width × height ≤ 2^31 − 1 (`Checked::new`).
#[inline(always)]
pub(super) fn corner_indices(
    w: &[i32; LANES],
    (i0, i1): (&[i32; LANES], &[i32; LANES]),
    (j0, j1): (&[i32; LANES], &[i32; LANES]),
) -> [[u32; LANES]; 4] {
    let mut idx = [[0u32; LANES]; 4];
    for l in 0..LANES {
        let (r0, r1) = (j0[l].wrapping_mul(w[l]), j1[l].wrapping_mul(w[l]));
        idx[0][l] = r0.wrapping_add(i0[l]) as u32;
        idx[1][l] = r0.wrapping_add(i1[l]) as u32;
        idx[2][l] = r1.wrapping_add(i0[l]) as u32;
        idx[3][l] = r1.wrapping_add(i1[l]) as u32;
    }
    idx
}
