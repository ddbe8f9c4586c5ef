//! The filters of the fast path over the 16 lanes: NEAREST or LINEAR on
//! each lane's level, RGBA8 levels in fixed point (`unorm8_filter`) from
//! texels gathered by scalar loads or the AVX2 gather instruction, f32
//! levels by the general path's float sum ([`filter_lanes`]) and, for
//! those, the blend of two levels and the write of the lanes of the
//! request ([`sample_f32`]; the x86 variants in AVX2 registers).

use super::address::{axis, axis_unorm8, corner_indices, level_sizes, wrap_scale};
use super::lanes::lanes;
use super::storage::{f32_level, unorm8_level, LevelTable};
use crate::ex::LANES;
use crate::texture::{Image, Texture, MISSING};
use crate::unorm8_filter;

/// The f32 levels' part of [`sample_in`](super::sample_in): LINEAR or NEAREST (on the lanes
/// in `nearest`) on `level[0]`, blended with `level[1]` by `f` on the
/// lanes in `two`, into the lanes `mask` of `out`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(super) fn sample_f32<const SIMD: bool>(
    tex: &Texture,
    table: (&LevelTable, &[Image]),
    level: &[[i32; LANES]; 2],
    f: &[f32; LANES],
    st: &[[f32; LANES]; 2],
    nearest: u32,
    two: u32,
    mask: u32,
    out: &mut [[f32; LANES]; 4],
) {
    let near = lanes(nearest);
    let mut first = [[0.0f32; LANES]; 4];
    filter_lanes::<SIMD>(tex, table, &level[0], st, &near, &mut first);
    if two != 0 {
        let mut second = [[0.0f32; LANES]; 4];
        filter_lanes::<SIMD>(tex, table, &level[1], st, &near, &mut second);
        // `mix_levels` on the lanes in `two`, as a select over all lanes.
        let two = lanes(two);
        #[cfg(target_arch = "x86_64")]
        if SIMD {
            // SAFETY: `SIMD` is only set in code compiled for AVX2, which
            // runs only on CPUs that have it.
            unsafe { mix_avx2(&mut first, &second, f, &two) };
        }
        if !SIMD {
            for c in 0..4 {
                for l in 0..LANES {
                    let (t1, t2, fl) = (first[c][l], second[c][l], f[l]);
                    let mixed = (1.0 - fl) * t1 + fl * t2;
                    first[c][l] = if two[l] { mixed } else { t1 };
                }
            }
        }
    }
    let mask = lanes(mask);
    #[cfg(target_arch = "x86_64")]
    if SIMD {
        // SAFETY: as above.
        unsafe { select_avx2(out, &first, &mask) };
        return;
    }
    for c in 0..4 {
        for l in 0..LANES {
            out[c][l] = if mask[l] { first[c][l] } else { out[c][l] };
        }
    }
}

/// All ones in the 32-bit lanes `o..o + 8` whose flag is set.
///
/// # Safety
/// The CPU must support AVX2; `o <= LANES - 8`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn flags_avx2(flags: &[bool; LANES], o: usize) -> std::arch::x86_64::__m256 {
    use std::arch::x86_64::*;
    debug_assert!(o + 8 <= LANES);
    // SAFETY: 8 bytes (a bool is one byte, 0 or 1) inside `flags`.
    unsafe {
        let bytes = _mm_loadl_epi64(flags.as_ptr().add(o).cast());
        _mm256_castsi256_ps(_mm256_cmpgt_epi32(
            _mm256_cvtepu8_epi32(bytes),
            _mm256_setzero_si256(),
        ))
    }
}

/// The blend of two levels' values on the lanes in `two`, as the portable
/// code computes it, eight lanes at a time.
///
/// # Safety
/// The CPU must support AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn mix_avx2(
    first: &mut [[f32; LANES]; 4],
    second: &[[f32; LANES]; 4],
    f: &[f32; LANES],
    two: &[bool; LANES],
) {
    use std::arch::x86_64::*;
    // SAFETY: every pointer is to 8 consecutive elements inside one of
    // the arrays (offset 0 or 8 of 16).
    unsafe {
        for o in [0, 8] {
            let fl = _mm256_loadu_ps(f.as_ptr().add(o));
            let one_minus = _mm256_sub_ps(_mm256_set1_ps(1.0), fl);
            let sel = flags_avx2(two, o);
            for (t1, t2) in first.iter_mut().zip(second) {
                let a = _mm256_loadu_ps(t1.as_ptr().add(o));
                let b = _mm256_loadu_ps(t2.as_ptr().add(o));
                let mixed = _mm256_add_ps(_mm256_mul_ps(one_minus, a), _mm256_mul_ps(fl, b));
                _mm256_storeu_ps(t1.as_mut_ptr().add(o), _mm256_blendv_ps(a, mixed, sel));
            }
        }
    }
}

/// `out` takes `value` on the lanes in `mask`, eight lanes at a time.
///
/// # Safety
/// The CPU must support AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn select_avx2(
    out: &mut [[f32; LANES]; 4],
    value: &[[f32; LANES]; 4],
    mask: &[bool; LANES],
) {
    use std::arch::x86_64::*;
    // SAFETY: as in `mix_avx2`.
    unsafe {
        for o in [0, 8] {
            let sel = flags_avx2(mask, o);
            for (out, v) in out.iter_mut().zip(value) {
                let old = _mm256_loadu_ps(out.as_ptr().add(o));
                let new = _mm256_loadu_ps(v.as_ptr().add(o));
                _mm256_storeu_ps(out.as_mut_ptr().add(o), _mm256_blendv_ps(old, new, sel));
            }
        }
    }
}

/// NEAREST or LINEAR on f32 level `level[lane]` of every lane (NEAREST
/// for those in `nearest`), as `texture_general::filter` for a 2D texture without
/// border texels, into `out` (RGBA, lane-major). Every lane's level must
/// be one of the table's (those outside the request give some value).
///
/// All four corners of every lane are fetched (the indices are always in
/// the level), and the sum is computed over all lanes, the nearest lanes
/// then selecting corner 0: straight-line code over arrays of 16 lanes;
/// only the texel loads are per lane.
#[inline(always)]
fn filter_lanes<const SIMD: bool>(
    tex: &Texture,
    (table, levels): (&LevelTable, &[Image]),
    level: &[i32; LANES],
    st: &[[f32; LANES]; 2],
    nearest: &[bool; LANES],
    out: &mut [[f32; LANES]; 4],
) {
    let (ws, wt) = (tex.wrap[0], tex.wrap[1]);
    let (w, h) = level_sizes(table, level);
    let us = wrap_scale::<SIMD>(ws, &st[0], &w);
    let ut = wrap_scale::<SIMD>(wt, &st[1], &h);
    let (i0, i1, a) = axis::<SIMD>(&us, &w, ws, nearest);
    let (j0, j1, b) = axis::<SIMD>(&ut, &h, wt, nearest);
    let idx = corner_indices(&w, (&i0, &i1), (&j0, &j1));
    // The general path's sum over the four texels, each weight the
    // product of the two axes' weights.
    let mut wgt = [[0.0f32; LANES]; 4];
    for l in 0..LANES {
        let (a, b) = (a[l], b[l]);
        let (a0, b0) = (1.0 - a, 1.0 - b);
        wgt[0][l] = a0 * b0;
        wgt[1][l] = a * b0;
        wgt[2][l] = a0 * b;
        wgt[3][l] = a * b;
    }
    // Texels `idx[k][lane]` (corner k) of level `level[lane]`, MISSING
    // out of range, as `t[k][component][lane]`.
    let mut t = [[[0.0f32; LANES]; 4]; 4];
    for l in 0..LANES {
        let texels = f32_level(levels, level[l]);
        for k in 0..4 {
            let v = texels.get(idx[k][l] as usize).copied().unwrap_or(MISSING);
            for c in 0..4 {
                t[k][c][l] = v[c];
            }
        }
    }
    combine(&t, &wgt, nearest, out);
}

/// NEAREST or LINEAR on RGBA8 level `level[lane]` (of `levels`) of every
/// lane (NEAREST for those in `nearest`) in fixed point
/// ([`unorm8_filter`]): the values ×128 (RGBA, lane-major). Every lane's
/// level must be one of the table's (those outside the request give some
/// value).
#[inline(always)]
pub(super) fn filter_unorm8_lanes<const SIMD: bool>(
    tex: &Texture,
    table: &LevelTable,
    levels: &[Image],
    level: &[i32; LANES],
    st: &[[f32; LANES]; 2],
    nearest: &[bool; LANES],
) -> [[i32; LANES]; 4] {
    let (ws, wt) = (tex.wrap[0], tex.wrap[1]);
    let (w, h) = level_sizes(table, level);
    let us = wrap_scale::<SIMD>(ws, &st[0], &w);
    let ut = wrap_scale::<SIMD>(wt, &st[1], &h);
    let (i0, i1, a) = axis_unorm8::<SIMD>(&us, &w, ws, nearest);
    let (j0, j1, b) = axis_unorm8::<SIMD>(&ut, &h, wt, nearest);
    let idx = corner_indices(&w, (&i0, &i1), (&j0, &j1));
    let mut raw = [[0u32; LANES]; 4];
    gather::<SIMD, 4>(levels, level, &idx, &mut raw);
    let mut out = [[0i32; LANES]; 4];
    for l in 0..LANES {
        let t: [[u8; 4]; 4] = std::array::from_fn(|k| raw[k][l].to_le_bytes());
        let v = if nearest[l] {
            unorm8_filter::nearest(t[0])
        } else {
            unorm8_filter::bilinear(t, a[l], b[l])
        };
        for c in 0..4 {
            out[c][l] = v[c];
        }
    }
    out
}

/// The bilinear sum of the corners `t[k][component][lane]` with weights
/// `wgt[k][lane]` (in corner order, from 0), or corner 0 for the lanes
/// in `nearest`.
#[inline(always)]
fn combine(
    t: &[[[f32; LANES]; 4]; 4],
    wgt: &[[f32; LANES]; 4],
    nearest: &[bool; LANES],
    out: &mut [[f32; LANES]; 4],
) {
    for c in 0..4 {
        for l in 0..LANES {
            let mut acc = 0.0f32;
            for k in 0..4 {
                acc += wgt[k][l] * t[k][c][l];
            }
            out[c][l] = if nearest[l] { t[0][c][l] } else { acc };
        }
    }
}

/// [`gather_unorm8`]; with `SIMD` (code compiled for AVX2), by the
/// gather instruction when every lane reads the same level (the usual
/// case).
#[inline(always)]
fn gather<const SIMD: bool, const K: usize>(
    levels: &[Image],
    level: &[i32; LANES],
    idx: &[[u32; LANES]; K],
    raw: &mut [[u32; LANES]; K],
) {
    #[cfg(target_arch = "x86_64")]
    if SIMD {
        let d0 = level[0];
        if level.iter().all(|&d| d == d0) {
            // SAFETY: `SIMD` is only set in code compiled for AVX2, which
            // runs only on CPUs that have it.
            unsafe { gather_unorm8_avx2(unorm8_level(levels, d0), idx, raw) };
            return;
        }
    }
    gather_unorm8(levels, level, idx, raw);
}

exec::compiled_for!(
    avx2,
    /// Texels `idx[k][lane]` of `texels` (never empty), as little-endian RGBA8
    /// words, by the AVX2 gather instruction, eight lanes at a time.
    ///
    /// # Safety
    /// The CPU must run `Level::Avx2` (the code calling it is compiled for
    /// it: the `SIMD` copies of the fast path).
    unsafe fn gather_unorm8_avx2<const K: usize>(
        texels: &[[u8; 4]],
        idx: &[[u32; LANES]; K],
        raw: &mut [[u32; LANES]; K],
    ) {
        use std::arch::x86_64::*;
        // Every index is below the level's width × height ≤ 2^31 − 1, which
        // it holds (`Store::Unorm8`); the clamp to the last texel keeps that
        // local (and the index non-negative as an i32).
        let last = texels.len().saturating_sub(1).min(i32::MAX as usize) as i32;
        // SAFETY: the loads and stores are of 8 consecutive elements inside
        // `idx[k]` and `raw[k]` (offset 0 or 8 of 16); each gathered index is
        // in 0..=last, so every 4-byte read is of a texel of `texels`.
        unsafe {
            let last = _mm256_set1_epi32(last);
            for k in 0..K {
                for o in [0, 8] {
                    let i = _mm256_loadu_si256(idx[k].as_ptr().add(o).cast());
                    let i = _mm256_min_epu32(i, last);
                    let v = _mm256_i32gather_epi32::<4>(texels.as_ptr().cast(), i);
                    _mm256_storeu_si256(raw[k].as_mut_ptr().add(o).cast(), v);
                }
            }
        }
    }
);

/// Texels `idx[k][lane]` of level `level[lane]` (of [`Store::Unorm8`](super::storage::Store::Unorm8)),
/// as little-endian RGBA8 words: scalar loads (from one level's texels
/// when every lane reads the same level, the usual case). Kept out of
/// line: inlined, the compiler interleaves the loads with the code
/// around them into badly vectorized code.
#[inline(never)]
fn gather_unorm8<const K: usize>(
    levels: &[Image],
    level: &[i32; LANES],
    idx: &[[u32; LANES]; K],
    raw: &mut [[u32; LANES]; K],
) {
    #[inline(always)]
    fn lane<const K: usize>(
        texels: &[[u8; 4]],
        l: usize,
        idx: &[[u32; LANES]; K],
        raw: &mut [[u32; LANES]; K],
    ) {
        // Every index is below the level's width × height, which it holds
        // (`Store::Unorm8`); the clamp only keeps that local.
        let last = texels.len().saturating_sub(1);
        for k in 0..K {
            let i = (idx[k][l] as usize).min(last);
            // SAFETY: `unorm8_level` never gives an empty slice, so
            // `i <= len - 1` is in bounds.
            raw[k][l] = u32::from_le_bytes(unsafe { *texels.get_unchecked(i) });
        }
    }
    let d0 = level[0];
    if level.iter().all(|&d| d == d0) {
        let texels = unorm8_level(levels, d0);
        for l in 0..LANES {
            lane(texels, l, idx, raw);
        }
    } else {
        for (l, &d) in level.iter().enumerate() {
            lane(unorm8_level(levels, d), l, idx, raw);
        }
    }
}
