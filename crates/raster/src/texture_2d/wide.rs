//! The AVX-512 variant's filtering of RGBA8 levels: [`super::filter_lanes`]
//! and the level blend and output select of [`super::sample_in`] in
//! 512-bit registers, for requests whose lanes read one level per level
//! pass (the lanes that matter: the request's for the first level, those
//! blending two levels for the second) and whose S and T wrap modes are
//! REPEAT or CLAMP_TO_EDGE. Those are nearly all lookups of a trilinear
//! texture: level selection is per quad and varies slowly.
//!
//! The operations are the portable code's, in its order (floors by the
//! rounding instruction as [`super::floor_of`] allows, the RGBA8
//! conversion by [`super::combine_unorm8_avx2`]'s fused correction), so
//! the same bits; what differs is that the level's size is a scalar, all
//! sixteen lanes sit in one register, no array goes through memory
//! between the steps, and when the two texels of each row are neighbours
//! in memory (every lane's i1 = i0 + 1, i.e. no lane at the wrap edge),
//! each row is read by one 64-bit gather per eight lanes instead of two
//! 32-bit gathers per sixteen.

use super::{LevelTable, Store, LANES, UNORM8_INV};
use crate::simd::byte;
use crate::texture::{Texture, Wrap};
use std::arch::x86_64::*;

/// Samples level `level[0]` (and `level[1]`, blended by `f` on the lanes
/// in `two`) at `st` into the lanes `mask` of `out` (LINEAR, or NEAREST
/// on the lanes in `nearest`), as the portable code does; false (nothing
/// written) when the request does not qualify (see the module
/// documentation).
///
/// # Safety
/// The CPU must support AVX-512 F and BW and FMA.
#[target_feature(enable = "avx512f,avx512bw,avx512dq,avx512vl,avx2,fma")]
#[allow(clippy::too_many_arguments)]
pub(super) unsafe fn sample_unorm8(
    tex: &Texture,
    table: &LevelTable,
    level: &[[i32; LANES]; 2],
    f: &[f32; LANES],
    st: [&[f32; LANES]; 2],
    nearest: u32,
    two: u32,
    mask: u32,
    out: &mut [[f32; LANES]; 4],
) -> bool {
    let Store::Unorm8(levels) = &table.store else {
        return false;
    };
    let wraps = [tex.wrap[0], tex.wrap[1]];
    if !wraps
        .iter()
        .all(|w| matches!(w, Wrap::Repeat | Wrap::ClampToEdge))
    {
        return false;
    }
    let (mask, two, nearest) = (mask & 0xffff, two & 0xffff, nearest & 0xffff);
    if mask == 0 {
        return false;
    }
    // SAFETY: the CPU supports the features (the caller's contract).
    let Some(d0) = (unsafe { uniform(&level[0], mask) }) else {
        return false;
    };
    let d1 = if two != 0 {
        // SAFETY: as above.
        match unsafe { uniform(&level[1], two) } {
            Some(d) => Some(d),
            None => return false,
        }
    } else {
        None
    };
    // SAFETY: the CPU supports the features (the caller's contract); the
    // loads and stores are of 16 consecutive elements of 16-element
    // arrays.
    unsafe {
        let s = _mm512_loadu_ps(st[0].as_ptr());
        let t = _mm512_loadu_ps(st[1].as_ptr());
        let near = nearest as __mmask16;
        // Both levels' reads first, then the sums (the sums wait on the
        // gathers' latency: the second level's reads overlap it).
        let c0 = corners(table, levels, d0, wraps, s, t, near, mask as __mmask16);
        // (Not `Option::map`: a closure is compiled without the target
        // features, and the intrinsics in it would not be inlined.)
        #[allow(clippy::manual_map)]
        let c1 = match d1 {
            Some(d1) => Some(corners(
                table,
                levels,
                d1,
                wraps,
                s,
                t,
                near,
                two as __mmask16,
            )),
            None => None,
        };
        let mut first = combine(&c0, near);
        if let Some(c1) = &c1 {
            let second = combine(c1, near);
            // `mix_levels` on the lanes in `two`.
            let fl = _mm512_loadu_ps(f.as_ptr());
            let one_minus = _mm512_sub_ps(_mm512_set1_ps(1.0), fl);
            for (a, b) in first.iter_mut().zip(second) {
                let mixed = _mm512_add_ps(_mm512_mul_ps(one_minus, *a), _mm512_mul_ps(fl, b));
                *a = _mm512_mask_mov_ps(*a, two as __mmask16, mixed);
            }
        }
        for (o, v) in out.iter_mut().zip(first) {
            _mm512_mask_storeu_ps(o.as_mut_ptr(), mask as __mmask16, v);
        }
    }
    true
}

/// Eq. 3.28/3.29 for every lane, as `sample_in` computes them for the
/// *_MIPMAP_LINEAR filters: from λ (`lam`), the switch-over point `c`,
/// the base and last levels and whether magnification and minification
/// are NEAREST, each lane's two levels (`level`) and the weight of the
/// second (`f`); returns the lanes that blend two levels and those
/// filtered NEAREST.
///
/// # Safety
/// The CPU must support AVX-512 F.
#[target_feature(enable = "avx512f,avx512bw,avx512dq,avx512vl,avx2,fma")]
pub(super) unsafe fn mipmap_linear_levels(
    lam: &[f32; LANES],
    c: f32,
    (base, q): (i32, i32),
    (mag_nearest, min_nearest): (bool, bool),
    level: &mut [[i32; LANES]; 2],
    f: &mut [f32; LANES],
) -> (u32, u32) {
    // SAFETY: the CPU supports the features (the caller's contract); the
    // loads and stores are of 16 consecutive elements of 16-element
    // arrays.
    unsafe {
        let lambda = _mm512_loadu_ps(lam.as_ptr());
        // λ NaN or ≤ c.
        let mag = _mm512_cmp_ps_mask::<_CMP_NGT_UQ>(lambda, _mm512_set1_ps(c));
        let lb = _mm512_add_ps(_mm512_set1_ps(base as f32), lambda);
        let top = _mm512_cmp_ps_mask::<_CMP_GE_OQ>(lb, _mm512_set1_ps(q as f32));
        let (bv, qv) = (_mm512_set1_epi32(base), _mm512_set1_epi32(q));
        let d1 = _mm512_min_epi32(_mm512_max_epi32(floor_index(floor(lb)), bv), qv);
        let l0 = _mm512_mask_mov_epi32(_mm512_mask_mov_epi32(d1, top, qv), mag, bv);
        let l1 = _mm512_min_epi32(_mm512_add_epi32(d1, _mm512_set1_epi32(1)), qv);
        _mm512_storeu_si512(level[0].as_mut_ptr().cast(), l0);
        _mm512_storeu_si512(level[1].as_mut_ptr().cast(), l1);
        _mm512_storeu_ps(f.as_mut_ptr(), _mm512_sub_ps(lambda, floor(lambda)));
        let two = !mag & !top;
        let pick = |on: bool| if on { 0xffff } else { 0 };
        let nearest = (mag & pick(mag_nearest)) | (!mag & pick(min_nearest));
        (u32::from(two), u32::from(nearest))
    }
}

/// The one level of the lanes in `lanes` (not empty), if they have one.
/// (A function, not a closure: a closure is compiled without the target
/// features and called out of line.)
#[inline(always)]
unsafe fn uniform(level: &[i32; LANES], lanes: u32) -> Option<i32> {
    let d = level[(lanes.trailing_zeros() as usize).min(LANES - 1)];
    // SAFETY: a load of the 16 elements of `level`.
    let v = unsafe { _mm512_loadu_si512(level.as_ptr().cast()) };
    let same = u32::from(_mm512_cmpeq_epi32_mask(v, _mm512_set1_epi32(d)));
    (same & lanes == lanes).then_some(d)
}

/// `floor(x)` per lane (the rounding instruction, see `floor_of`).
#[inline(always)]
unsafe fn floor(x: __m512) -> __m512 {
    // Round toward −∞, exceptions suppressed.
    _mm512_roundscale_ps::<{ _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC }>(x)
}

/// `floor_index` per lane: NaN gives 0, the rest clamped to ±2^30 and
/// truncated.
#[inline(always)]
unsafe fn floor_index(fl: __m512) -> __m512i {
    let ordered = _mm512_cmp_ps_mask::<_CMP_ORD_Q>(fl, fl);
    let x = _mm512_maskz_mov_ps(ordered, fl);
    let x = _mm512_max_ps(x, _mm512_set1_ps(-1_073_741_824.0));
    let x = _mm512_min_ps(x, _mm512_set1_ps(1_073_741_824.0));
    _mm512_cvttps_epi32(x)
}

/// `wrap_index(i, wrap, n)` per lane.
#[inline(always)]
unsafe fn wrap_index(i: __m512i, wrap: Wrap, n: __m512i) -> __m512i {
    let i = if wrap == Wrap::Repeat {
        let below = _mm512_cmplt_epi32_mask(i, _mm512_setzero_si512());
        let above = _mm512_cmpge_epi32_mask(i, n);
        let i2 = _mm512_mask_add_epi32(i, below, i, n);
        _mm512_mask_sub_epi32(i2, above, i, n)
    } else {
        i
    };
    let i = _mm512_max_epi32(i, _mm512_setzero_si512());
    _mm512_min_epi32(i, _mm512_sub_epi32(n, _mm512_set1_epi32(1)))
}

/// `wrap_scale` of one axis with the level's size `n` (REPEAT or
/// CLAMP_TO_EDGE).
#[inline(always)]
unsafe fn wrap_scale(wrap: Wrap, s: __m512, n: i32) -> __m512 {
    let nf = n as f32;
    let nv = _mm512_set1_ps(nf);
    if wrap == Wrap::Repeat {
        return _mm512_mul_ps(_mm512_sub_ps(s, floor(s)), nv);
    }
    let half = 0.5 / nf;
    let (lo, hi) = (_mm512_set1_ps(half), _mm512_set1_ps(1.0 - half));
    let x = _mm512_mask_mov_ps(s, _mm512_cmp_ps_mask::<_CMP_LT_OQ>(s, lo), lo);
    let x = _mm512_mask_mov_ps(x, _mm512_cmp_ps_mask::<_CMP_GT_OQ>(x, hi), hi);
    _mm512_mul_ps(x, nv)
}

/// `axis` with the level's size `n`: texel 0 (the NEAREST texel on the
/// lanes in `nearest`), texel 1 and the weight of texel 1.
#[inline(always)]
unsafe fn axis(u: __m512, n: i32, wrap: Wrap, nearest: __mmask16) -> (__m512i, __m512i, __m512) {
    let nv = _mm512_set1_epi32(n);
    let v = _mm512_sub_ps(u, _mm512_set1_ps(0.5));
    let fl = floor(v);
    let i = floor_index(fl);
    let near = wrap_index(floor_index(floor(u)), wrap, nv);
    let alpha = _mm512_sub_ps(v, fl);
    let i0 = _mm512_mask_mov_epi32(wrap_index(i, wrap, nv), nearest, near);
    // (i ≤ 2^30: the saturating add does not saturate.)
    let i1 = wrap_index(_mm512_add_epi32(i, _mm512_set1_epi32(1)), wrap, nv);
    (i0, i1, alpha)
}

/// Texels `idx` of `texels` (not empty) as RGBA8 words, the indices
/// clamped to the last texel.
#[inline(always)]
unsafe fn gather(texels: &[[u8; 4]], idx: __m512i) -> __m512i {
    let last = texels.len().saturating_sub(1).min(i32::MAX as usize) as i32;
    let idx = _mm512_min_epu32(idx, _mm512_set1_epi32(last));
    // SAFETY: every index is in 0..=last: 4-byte reads of texels.
    _mm512_i32gather_epi32::<4>(idx, texels.as_ptr().cast())
}

/// Texels `idx` and `idx + 1` of `texels` (at least two), as two
/// vectors of RGBA8 words, by one 64-bit read per lane; `idx` clamped to
/// the last but one texel.
#[inline(always)]
unsafe fn gather_pairs(texels: &[[u8; 4]], idx: __m512i) -> (__m512i, __m512i) {
    debug_assert!(texels.len() >= 2);
    let last = texels.len().saturating_sub(2).min(i32::MAX as usize) as i32;
    let idx = _mm512_min_epu32(idx, _mm512_set1_epi32(last));
    let base = texels.as_ptr().cast();
    // SAFETY: every index is in 0..=len − 2: 8-byte reads of two texels.
    let lo = _mm512_i32gather_epi64::<4>(_mm512_castsi512_si256(idx), base);
    let hi = _mm512_i32gather_epi64::<4>(_mm512_extracti64x4_epi64::<1>(idx), base);
    // Lane l's pair is 64-bit element l % 8 of `lo` (l < 8) or `hi`.
    let even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
    let odd = _mm512_add_epi32(even, _mm512_set1_epi32(1));
    (
        _mm512_permutex2var_epi32(lo, even, hi),
        _mm512_permutex2var_epi32(lo, odd, hi),
    )
}

/// The four corners of every lane on one level (RGBA8 words) and their
/// weights: the first half of `filter_lanes`.
struct Corners {
    raw: [__m512i; 4],
    wgt: [__m512; 4],
}

/// The corners of `filter_lanes` on level `d` for every lane (see the
/// module documentation); only the lanes in `used` are meant (the others
/// get some value). With NEAREST on every lane, only corner 0 is read.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
unsafe fn corners(
    table: &LevelTable,
    levels: &[crate::texture::Image],
    d: i32,
    wraps: [Wrap; 2],
    s: __m512,
    t: __m512,
    nearest: __mmask16,
    used: __mmask16,
) -> Corners {
    let texels = super::unorm8_level(levels, d);
    let sh = (d.wrapping_sub(table.base) as u32).min(31);
    let w = (table.width >> sh).max(1) as i32;
    let h = (table.height >> sh).max(1) as i32;
    let us = wrap_scale(wraps[0], s, w);
    let ut = wrap_scale(wraps[1], t, h);
    let (i0, i1, a) = axis(us, w, wraps[0], nearest);
    let (j0, j1, b) = axis(ut, h, wraps[1], nearest);
    let wv = _mm512_set1_epi32(w);
    let (r0, r1) = (_mm512_mullo_epi32(j0, wv), _mm512_mullo_epi32(j1, wv));
    let idx0 = _mm512_add_epi32(r0, i0);
    let idx2 = _mm512_add_epi32(r1, i0);
    let one = _mm512_set1_ps(1.0);
    let (a0, b0) = (_mm512_sub_ps(one, a), _mm512_sub_ps(one, b));
    let wgt = [
        _mm512_mul_ps(a0, b0),
        _mm512_mul_ps(a, b0),
        _mm512_mul_ps(a0, b),
        _mm512_mul_ps(a, b),
    ];
    if nearest == 0xffff {
        let raw0 = gather(texels, idx0);
        return Corners {
            raw: [raw0; 4],
            wgt,
        };
    }
    // Both texels of each row neighbours in memory on every lane used
    // (the others read some two texels of the level).
    let pairs = texels.len() >= 2
        && (_mm512_cmpeq_epi32_mask(i1, _mm512_add_epi32(i0, _mm512_set1_epi32(1))) | !used)
            == 0xffff;
    let raw = if pairs {
        let (t0, t1) = gather_pairs(texels, idx0);
        let (t2, t3) = gather_pairs(texels, idx2);
        [t0, t1, t2, t3]
    } else {
        [
            gather(texels, idx0),
            gather(texels, _mm512_add_epi32(r0, i1)),
            gather(texels, idx2),
            gather(texels, _mm512_add_epi32(r1, i1)),
        ]
    };
    Corners { raw, wgt }
}

/// The second half of `filter_lanes`: the bilinear sum of the corners,
/// or corner 0 on the lanes in `nearest`; RGBA, one register per
/// component.
#[inline(always)]
unsafe fn combine(corners: &Corners, nearest: __mmask16) -> [__m512; 4] {
    let (raw, wgt) = (&corners.raw, &corners.wgt);
    // (Loops, not closures: a closure is compiled without the target
    // features, and the intrinsics in it would not be inlined.)
    let mut out = [_mm512_setzero_ps(); 4];
    if nearest == 0xffff {
        for (c, o) in out.iter_mut().enumerate() {
            *o = unorm8(byte(raw[0], c));
        }
        return out;
    }
    for (c, o) in out.iter_mut().enumerate() {
        let t0 = unorm8(byte(raw[0], c));
        // The sum starts at 0 in the portable code: 0 + x is x for every
        // product here (a weight and a texel are +0 or more, or NaN).
        let mut acc = _mm512_mul_ps(wgt[0], t0);
        for k in 1..4 {
            let tk = unorm8(byte(raw[k], c));
            acc = _mm512_add_ps(acc, _mm512_mul_ps(wgt[k], tk));
        }
        *o = _mm512_mask_mov_ps(acc, nearest, t0);
    }
    out
}

/// `unorm8` of every lane (bytes k in 0..=255): k/255 correctly rounded,
/// by `combine_unorm8_avx2`'s fused correction.
#[inline(always)]
unsafe fn unorm8(k: __m512i) -> __m512 {
    let x = _mm512_cvtepi32_ps(k);
    let inv = _mm512_set1_ps(UNORM8_INV);
    let q = _mm512_mul_ps(x, inv);
    let residual = _mm512_fnmadd_ps(q, _mm512_set1_ps(255.0), x);
    _mm512_fmadd_ps(residual, inv, q)
}
