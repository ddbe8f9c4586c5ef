//! Sixteen 32-bit lanes in vector registers, one API over two x86
//! instruction sets: [`X512`] (one AVX-512 register per value, masks in
//! mask registers) and [`X256`] (two AVX2 registers per value, masks as
//! all-ones lanes). Code written once against [`Lanes16`] and inlined
//! into a `#[target_feature]` function of the matching set keeps its
//! values in registers between steps; `raster`'s texture filter and
//! strip write and `gl`'s fixed-function fragment stage are written this
//! way.
//!
//! Every operation is the same IEEE operation in both sets (a lane's
//! result never depends on which set computed it), so the bits agree;
//! the floating-point ones are the portable code's (`max`/`min` give the
//! second operand when one is NaN, floors round toward −∞ without
//! exceptions, conversions truncate).
//!
//! The methods are `unsafe`: the CPU must have the set
//! ([`Lanes16::supported`]: [`Level::Avx512`] for [`X512`],
//! [`Level::Avx2`] for [`X256`]) and they must be inlined into code
//! compiled for that level (they are `#[inline(always)]`; callers are the
//! copies of [`crate::multiversion!`]; a closure calling them is compiled
//! without the features, so callers use loops and functions, never
//! closures).

#![allow(clippy::missing_safety_doc)]

use crate::cpu::Level;
use std::arch::x86_64::*;

/// Sixteen lanes of f32 ([`Lanes16::F`]), i32 ([`Lanes16::I`]) and
/// lane masks ([`Lanes16::M`]); see the module documentation.
pub trait Lanes16 {
    type F: Copy;
    type I: Copy;
    type M: Copy;

    /// Whether this CPU has the instruction set the methods need (the
    /// features of the `#[target_feature]` functions they are inlined
    /// into).
    fn supported() -> bool;

    unsafe fn load(p: &[f32; 16]) -> Self::F;
    unsafe fn load_i(p: &[i32; 16]) -> Self::I;
    unsafe fn store(p: &mut [f32; 16], v: Self::F);
    unsafe fn store_i(p: &mut [i32; 16], v: Self::I);
    /// `p[l] = v[l]` on the lanes of `m`, the others untouched.
    unsafe fn store_masked(p: &mut [f32; 16], m: Self::M, v: Self::F);
    unsafe fn splat(x: f32) -> Self::F;
    unsafe fn splat_i(x: i32) -> Self::I;
    unsafe fn zero() -> Self::F;

    unsafe fn add(a: Self::F, b: Self::F) -> Self::F;
    unsafe fn sub(a: Self::F, b: Self::F) -> Self::F;
    unsafe fn mul(a: Self::F, b: Self::F) -> Self::F;
    unsafe fn div(a: Self::F, b: Self::F) -> Self::F;
    /// `a` if `a > b`, else `b` (so `b` when either is NaN).
    unsafe fn max(a: Self::F, b: Self::F) -> Self::F;
    /// `a` if `a < b`, else `b`.
    unsafe fn min(a: Self::F, b: Self::F) -> Self::F;
    unsafe fn floor(a: Self::F) -> Self::F;
    unsafe fn to_f(a: Self::I) -> Self::F;
    /// Truncation (the caller keeps values in range).
    unsafe fn trunc_i(a: Self::F) -> Self::I;

    /// `!(a > b)`: a ≤ b, or either NaN.
    unsafe fn not_gt(a: Self::F, b: Self::F) -> Self::M;
    unsafe fn ge(a: Self::F, b: Self::F) -> Self::M;
    unsafe fn lt(a: Self::F, b: Self::F) -> Self::M;
    unsafe fn gt(a: Self::F, b: Self::F) -> Self::M;
    /// Neither NaN.
    unsafe fn ordered(a: Self::F, b: Self::F) -> Self::M;
    /// `!(a >= b)`: a < b, or either NaN.
    unsafe fn lt_or_nan(a: Self::F, b: Self::F) -> Self::M;
    /// `!(a <= b)`: a > b, or either NaN.
    unsafe fn gt_or_nan(a: Self::F, b: Self::F) -> Self::M;
    /// A subnormal made zero of its sign ([`crate::lane::flush`]).
    unsafe fn flush(a: Self::F) -> Self::F;
    /// `yes` on the lanes of `m`, else `no`.
    unsafe fn select(m: Self::M, yes: Self::F, no: Self::F) -> Self::F;
    /// `a` on the lanes of `m`, else +0.
    unsafe fn keep(m: Self::M, a: Self::F) -> Self::F;

    unsafe fn add_i(a: Self::I, b: Self::I) -> Self::I;
    unsafe fn sub_i(a: Self::I, b: Self::I) -> Self::I;
    unsafe fn mullo_i(a: Self::I, b: Self::I) -> Self::I;
    unsafe fn max_i(a: Self::I, b: Self::I) -> Self::I;
    unsafe fn min_i(a: Self::I, b: Self::I) -> Self::I;
    /// Unsigned minimum.
    unsafe fn min_u(a: Self::I, b: Self::I) -> Self::I;
    unsafe fn eq_i(a: Self::I, b: Self::I) -> Self::M;
    unsafe fn lt_i(a: Self::I, b: Self::I) -> Self::M;
    unsafe fn ge_i(a: Self::I, b: Self::I) -> Self::M;
    unsafe fn select_i(m: Self::M, yes: Self::I, no: Self::I) -> Self::I;
    /// Byte `c` (0–3) of each lane, zero-extended (a channel of RGBA8
    /// words).
    unsafe fn byte(a: Self::I, c: usize) -> Self::I;
    /// `a << 8c` (c in 0–3).
    unsafe fn shl_bytes(a: Self::I, c: usize) -> Self::I;
    unsafe fn or_i(a: Self::I, b: Self::I) -> Self::I;
    unsafe fn and_i(a: Self::I, b: Self::I) -> Self::I;
    /// `a << n` (n in 0–31; a constant, folded into the instruction).
    unsafe fn shl_i(a: Self::I, n: u32) -> Self::I;
    /// `a >> n`, arithmetic (n in 0–31, a constant).
    unsafe fn sra_i(a: Self::I, n: u32) -> Self::I;

    /// Lanes 0–7 and 8–15 as two AVX2 registers (for code that works on
    /// 256-bit registers in either set; the CPU has AVX2 in both).
    unsafe fn halves_i(a: Self::I) -> [__m256i; 2];
    /// The inverse of [`Lanes16::halves_i`] for f32 lanes.
    unsafe fn from_halves(h: [__m256; 2]) -> Self::F;

    /// The mask of the set bits of `bits` (lane l: bit l).
    unsafe fn mask(bits: u32) -> Self::M;
    /// The lanes of `m` as bits.
    unsafe fn bits(m: Self::M) -> u32;

    /// A 2×8-pixel block of RGBA8 words: lanes 0–7 from `row0`, 8–15
    /// from `row1` (eight words each).
    ///
    /// # Safety
    /// Eight words readable at each pointer.
    unsafe fn load_rows(row0: *const u32, row1: *const u32) -> Self::I;
    /// The inverse of [`Lanes16::load_rows`].
    ///
    /// # Safety
    /// Eight words writable at each pointer.
    unsafe fn store_rows(row0: *mut u32, row1: *mut u32, v: Self::I);
    /// A strip's lanes (quad q's pixel k in lane 4q + k, k = 2·row +
    /// column) in the pixel order of [`Lanes16::load_rows`]: lanes 0, 1,
    /// 4, 5, 8, 9, 12, 13, then 2, 3, 6, 7, 10, 11, 14, 15.
    unsafe fn quads_to_rows(a: Self::F) -> Self::F;
    /// Element `k` (0–3) of each quad (lanes 4q–4q + 3) in all four of
    /// its lanes.
    unsafe fn quad_lane(a: Self::F, k: i32) -> Self::F;
}

/// [`Lanes16`] in one AVX-512 register per value.
pub struct X512;

impl Lanes16 for X512 {
    type F = __m512;
    type I = __m512i;
    type M = __mmask16;

    #[inline]
    fn supported() -> bool {
        Level::Avx512.supported()
    }

    #[inline(always)]
    unsafe fn load(p: &[f32; 16]) -> __m512 {
        unsafe { _mm512_loadu_ps(p.as_ptr()) }
    }
    #[inline(always)]
    unsafe fn load_i(p: &[i32; 16]) -> __m512i {
        unsafe { _mm512_loadu_si512(p.as_ptr().cast()) }
    }
    #[inline(always)]
    unsafe fn store(p: &mut [f32; 16], v: __m512) {
        unsafe { _mm512_storeu_ps(p.as_mut_ptr(), v) }
    }
    #[inline(always)]
    unsafe fn store_i(p: &mut [i32; 16], v: __m512i) {
        unsafe { _mm512_storeu_si512(p.as_mut_ptr().cast(), v) }
    }
    #[inline(always)]
    unsafe fn store_masked(p: &mut [f32; 16], m: __mmask16, v: __m512) {
        unsafe { _mm512_mask_storeu_ps(p.as_mut_ptr(), m, v) }
    }
    #[inline(always)]
    unsafe fn splat(x: f32) -> __m512 {
        unsafe { _mm512_set1_ps(x) }
    }
    #[inline(always)]
    unsafe fn splat_i(x: i32) -> __m512i {
        unsafe { _mm512_set1_epi32(x) }
    }
    #[inline(always)]
    unsafe fn zero() -> __m512 {
        unsafe { _mm512_setzero_ps() }
    }
    #[inline(always)]
    unsafe fn add(a: __m512, b: __m512) -> __m512 {
        unsafe { _mm512_add_ps(a, b) }
    }
    #[inline(always)]
    unsafe fn sub(a: __m512, b: __m512) -> __m512 {
        unsafe { _mm512_sub_ps(a, b) }
    }
    #[inline(always)]
    unsafe fn mul(a: __m512, b: __m512) -> __m512 {
        unsafe { _mm512_mul_ps(a, b) }
    }
    #[inline(always)]
    unsafe fn div(a: __m512, b: __m512) -> __m512 {
        unsafe { _mm512_div_ps(a, b) }
    }
    #[inline(always)]
    unsafe fn max(a: __m512, b: __m512) -> __m512 {
        unsafe { _mm512_max_ps(a, b) }
    }
    #[inline(always)]
    unsafe fn min(a: __m512, b: __m512) -> __m512 {
        unsafe { _mm512_min_ps(a, b) }
    }
    #[inline(always)]
    unsafe fn floor(a: __m512) -> __m512 {
        unsafe { _mm512_roundscale_ps::<{ _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC }>(a) }
    }
    #[inline(always)]
    unsafe fn to_f(a: __m512i) -> __m512 {
        unsafe { _mm512_cvtepi32_ps(a) }
    }
    #[inline(always)]
    unsafe fn trunc_i(a: __m512) -> __m512i {
        unsafe { _mm512_cvttps_epi32(a) }
    }
    #[inline(always)]
    unsafe fn not_gt(a: __m512, b: __m512) -> __mmask16 {
        unsafe { _mm512_cmp_ps_mask::<_CMP_NGT_UQ>(a, b) }
    }
    #[inline(always)]
    unsafe fn ge(a: __m512, b: __m512) -> __mmask16 {
        unsafe { _mm512_cmp_ps_mask::<_CMP_GE_OQ>(a, b) }
    }
    #[inline(always)]
    unsafe fn lt(a: __m512, b: __m512) -> __mmask16 {
        unsafe { _mm512_cmp_ps_mask::<_CMP_LT_OQ>(a, b) }
    }
    #[inline(always)]
    unsafe fn gt(a: __m512, b: __m512) -> __mmask16 {
        unsafe { _mm512_cmp_ps_mask::<_CMP_GT_OQ>(a, b) }
    }
    #[inline(always)]
    unsafe fn ordered(a: __m512, b: __m512) -> __mmask16 {
        unsafe { _mm512_cmp_ps_mask::<_CMP_ORD_Q>(a, b) }
    }
    #[inline(always)]
    unsafe fn lt_or_nan(a: __m512, b: __m512) -> __mmask16 {
        unsafe { _mm512_cmp_ps_mask::<_CMP_NGE_UQ>(a, b) }
    }
    #[inline(always)]
    unsafe fn gt_or_nan(a: __m512, b: __m512) -> __mmask16 {
        unsafe { _mm512_cmp_ps_mask::<_CMP_NLE_UQ>(a, b) }
    }
    #[inline(always)]
    unsafe fn flush(a: __m512) -> __m512 {
        unsafe {
            let b = _mm512_castps_si512(a);
            // Lanes with a nonzero exponent keep their bits, the others
            // their sign.
            let normal = _mm512_test_epi32_mask(b, _mm512_set1_epi32(0x7f80_0000));
            let sign = _mm512_and_si512(b, _mm512_set1_epi32(i32::MIN));
            _mm512_castsi512_ps(_mm512_mask_mov_epi32(sign, normal, b))
        }
    }
    #[inline(always)]
    unsafe fn select(m: __mmask16, yes: __m512, no: __m512) -> __m512 {
        unsafe { _mm512_mask_mov_ps(no, m, yes) }
    }
    #[inline(always)]
    unsafe fn keep(m: __mmask16, a: __m512) -> __m512 {
        unsafe { _mm512_maskz_mov_ps(m, a) }
    }
    #[inline(always)]
    unsafe fn add_i(a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_add_epi32(a, b) }
    }
    #[inline(always)]
    unsafe fn sub_i(a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_sub_epi32(a, b) }
    }
    #[inline(always)]
    unsafe fn mullo_i(a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_mullo_epi32(a, b) }
    }
    #[inline(always)]
    unsafe fn max_i(a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_max_epi32(a, b) }
    }
    #[inline(always)]
    unsafe fn min_i(a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_min_epi32(a, b) }
    }
    #[inline(always)]
    unsafe fn min_u(a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_min_epu32(a, b) }
    }
    #[inline(always)]
    unsafe fn eq_i(a: __m512i, b: __m512i) -> __mmask16 {
        unsafe { _mm512_cmpeq_epi32_mask(a, b) }
    }
    #[inline(always)]
    unsafe fn lt_i(a: __m512i, b: __m512i) -> __mmask16 {
        unsafe { _mm512_cmplt_epi32_mask(a, b) }
    }
    #[inline(always)]
    unsafe fn ge_i(a: __m512i, b: __m512i) -> __mmask16 {
        unsafe { _mm512_cmpge_epi32_mask(a, b) }
    }
    #[inline(always)]
    unsafe fn select_i(m: __mmask16, yes: __m512i, no: __m512i) -> __m512i {
        unsafe { _mm512_mask_mov_epi32(no, m, yes) }
    }
    #[inline(always)]
    unsafe fn byte(a: __m512i, c: usize) -> __m512i {
        unsafe {
            match c {
                0 => _mm512_and_si512(a, _mm512_set1_epi32(255)),
                3 => _mm512_srli_epi32::<24>(a),
                1 => _mm512_and_si512(_mm512_srli_epi32::<8>(a), _mm512_set1_epi32(255)),
                _ => _mm512_and_si512(_mm512_srli_epi32::<16>(a), _mm512_set1_epi32(255)),
            }
        }
    }
    #[inline(always)]
    unsafe fn shl_bytes(a: __m512i, c: usize) -> __m512i {
        unsafe {
            match c {
                0 => a,
                1 => _mm512_slli_epi32::<8>(a),
                2 => _mm512_slli_epi32::<16>(a),
                _ => _mm512_slli_epi32::<24>(a),
            }
        }
    }
    #[inline(always)]
    unsafe fn or_i(a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_or_si512(a, b) }
    }
    #[inline(always)]
    unsafe fn and_i(a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_and_si512(a, b) }
    }
    #[inline(always)]
    unsafe fn shl_i(a: __m512i, n: u32) -> __m512i {
        unsafe { _mm512_sll_epi32(a, _mm_cvtsi32_si128(n as i32)) }
    }
    #[inline(always)]
    unsafe fn sra_i(a: __m512i, n: u32) -> __m512i {
        unsafe { _mm512_sra_epi32(a, _mm_cvtsi32_si128(n as i32)) }
    }
    #[inline(always)]
    unsafe fn halves_i(a: __m512i) -> [__m256i; 2] {
        unsafe { [_mm512_castsi512_si256(a), _mm512_extracti64x4_epi64::<1>(a)] }
    }
    #[inline(always)]
    unsafe fn from_halves(h: [__m256; 2]) -> __m512 {
        unsafe {
            let lo = _mm512_castps256_ps512(h[0]);
            _mm512_castpd_ps(_mm512_insertf64x4::<1>(
                _mm512_castps_pd(lo),
                _mm256_castps_pd(h[1]),
            ))
        }
    }
    #[inline(always)]
    unsafe fn mask(bits: u32) -> __mmask16 {
        bits as __mmask16
    }
    #[inline(always)]
    unsafe fn bits(m: __mmask16) -> u32 {
        u32::from(m)
    }
    #[inline(always)]
    unsafe fn load_rows(row0: *const u32, row1: *const u32) -> __m512i {
        unsafe {
            let lo = _mm256_loadu_si256(row0.cast());
            let hi = _mm256_loadu_si256(row1.cast());
            _mm512_inserti64x4::<1>(_mm512_castsi256_si512(lo), hi)
        }
    }
    #[inline(always)]
    unsafe fn store_rows(row0: *mut u32, row1: *mut u32, v: __m512i) {
        unsafe {
            _mm256_storeu_si256(row0.cast(), _mm512_castsi512_si256(v));
            _mm256_storeu_si256(row1.cast(), _mm512_extracti64x4_epi64::<1>(v));
        }
    }
    #[inline(always)]
    unsafe fn quads_to_rows(a: __m512) -> __m512 {
        unsafe {
            let lane = _mm512_setr_epi32(0, 1, 4, 5, 8, 9, 12, 13, 2, 3, 6, 7, 10, 11, 14, 15);
            _mm512_permutexvar_ps(lane, a)
        }
    }
    #[inline(always)]
    unsafe fn quad_lane(a: __m512, k: i32) -> __m512 {
        unsafe {
            let lane = _mm512_add_epi32(
                _mm512_setr_epi32(0, 0, 0, 0, 4, 4, 4, 4, 8, 8, 8, 8, 12, 12, 12, 12),
                _mm512_set1_epi32(k),
            );
            _mm512_permutexvar_ps(lane, a)
        }
    }
}

/// [`Lanes16`] in two AVX2 registers per value (lanes 0–7, 8–15). Texel
/// reads ([`pairs4`]) are scalar loads: AVX2's gather instructions are
/// microcoded and slower on some CPUs (measured on AMD Zen 2: 64-bit
/// gathers made the textured scene's frame 8 % longer).
pub struct X256;

/// Two halves: `f(a.0, b.0), f(a.1, b.1)`.
macro_rules! halves {
    ($f:ident, $a:expr) => {{
        let a = $a;
        [$f(a[0]), $f(a[1])]
    }};
    ($f:ident, $a:expr, $b:expr) => {{
        let (a, b) = ($a, $b);
        [$f(a[0], b[0]), $f(a[1], b[1])]
    }};
    ($f:ident, $a:expr, $b:expr, $c:expr) => {{
        let (a, b, c) = ($a, $b, $c);
        [$f(a[0], b[0], c[0]), $f(a[1], b[1], c[1])]
    }};
}

/// The 64 bits at words `idx[k]` and `idx[k + 1]` of `base` (k 0 or 2),
/// side by side.
///
/// # Safety
/// Both reads must be of readable words.
#[inline(always)]
unsafe fn pair_at(base: *const u32, idx: __m128i, k: i32) -> __m128i {
    unsafe { load_pair(base, lane_pair(idx, k)) }
}

/// Texel pairs for four-pixel registers: words `idx[l]` and `idx[l] + 1`
/// of `base` for the sixteen lanes of `idx` (lanes 0–7, 8–15), one 64-bit
/// read each, the pair of lane l in a 64-bit element, lanes
/// {0, 1 | 4, 5}, {2, 3 | 6, 7}, {8, 9 | 12, 13}, {10, 11 | 14, 15} (the
/// order `_mm256_unpacklo_epi32` / `_mm256_unpackhi_epi32` give lanes
/// 0–7 of two registers, and their 128-bit halves).
///
/// # Safety
/// The CPU must have AVX2 (inlined into code compiled for it); both words
/// of every lane must be readable.
#[inline(always)]
pub unsafe fn pairs4(base: *const u32, idx: [__m256i; 2]) -> [__m256i; 4] {
    unsafe {
        let mut out = [_mm256_setzero_si256(); 4];
        for h in 0..2 {
            let lo4 = _mm256_castsi256_si128(idx[h]);
            let hi4 = _mm256_extracti128_si256::<1>(idx[h]);
            out[2 * h] = _mm256_set_m128i(pair_at(base, hi4, 0), pair_at(base, lo4, 0));
            out[2 * h + 1] = _mm256_set_m128i(pair_at(base, hi4, 2), pair_at(base, lo4, 2));
        }
        out
    }
}

/// [`pairs4`] at `idx` and at `idx + stride` (a texel footprint's two
/// rows), each lane's index taken out of its register once for both
/// reads.
///
/// # Safety
/// As for [`pairs4`], for both sets of words.
#[inline(always)]
pub unsafe fn pairs4_rows(
    base: *const u32,
    idx: [__m256i; 2],
    stride: usize,
) -> ([__m256i; 4], [__m256i; 4]) {
    unsafe {
        let mut rows = ([_mm256_setzero_si256(); 4], [_mm256_setzero_si256(); 4]);
        let next = base.add(stride);
        for (h, &half) in idx.iter().enumerate() {
            let lo4 = _mm256_castsi256_si128(half);
            let hi4 = _mm256_extracti128_si256::<1>(half);
            for (r, k) in [(0, 0), (1, 2)] {
                let (lo, hi) = (lane_pair(lo4, k), lane_pair(hi4, k));
                rows.0[2 * h + r] = _mm256_set_m128i(load_pair(base, hi), load_pair(base, lo));
                rows.1[2 * h + r] = _mm256_set_m128i(load_pair(next, hi), load_pair(next, lo));
            }
        }
        rows
    }
}

/// Elements `k` and `k + 1` (k 0 or 2) of `idx` as offsets.
#[inline(always)]
unsafe fn lane_pair(idx: __m128i, k: i32) -> (usize, usize) {
    unsafe {
        let (i, j) = if k == 0 {
            (_mm_cvtsi128_si32(idx), _mm_extract_epi32::<1>(idx))
        } else {
            (_mm_extract_epi32::<2>(idx), _mm_extract_epi32::<3>(idx))
        };
        (i as u32 as usize, j as u32 as usize)
    }
}

/// The 64 bits at words `i` and `j` of `base`, side by side.
///
/// # Safety
/// Both reads must be of readable words.
#[inline(always)]
unsafe fn load_pair(base: *const u32, (i, j): (usize, usize)) -> __m128i {
    unsafe {
        let a = _mm_loadl_epi64(base.add(i).cast());
        let b = _mm_loadl_epi64(base.add(j).cast());
        _mm_unpacklo_epi64(a, b)
    }
}

/// The all-ones lanes of an AVX2 comparison result as a float mask.
#[inline(always)]
unsafe fn fmask(m: __m256i) -> __m256 {
    unsafe { _mm256_castsi256_ps(m) }
}

impl Lanes16 for X256 {
    type F = [__m256; 2];
    type I = [__m256i; 2];
    /// All ones in the lanes of the mask.
    type M = [__m256; 2];

    #[inline]
    fn supported() -> bool {
        Level::Avx2.supported()
    }

    #[inline(always)]
    unsafe fn load(p: &[f32; 16]) -> [__m256; 2] {
        unsafe {
            [
                _mm256_loadu_ps(p.as_ptr()),
                _mm256_loadu_ps(p.as_ptr().add(8)),
            ]
        }
    }
    #[inline(always)]
    unsafe fn load_i(p: &[i32; 16]) -> [__m256i; 2] {
        unsafe {
            [
                _mm256_loadu_si256(p.as_ptr().cast()),
                _mm256_loadu_si256(p.as_ptr().add(8).cast()),
            ]
        }
    }
    #[inline(always)]
    unsafe fn store(p: &mut [f32; 16], v: [__m256; 2]) {
        unsafe {
            _mm256_storeu_ps(p.as_mut_ptr(), v[0]);
            _mm256_storeu_ps(p.as_mut_ptr().add(8), v[1]);
        }
    }
    #[inline(always)]
    unsafe fn store_i(p: &mut [i32; 16], v: [__m256i; 2]) {
        unsafe {
            _mm256_storeu_si256(p.as_mut_ptr().cast(), v[0]);
            _mm256_storeu_si256(p.as_mut_ptr().add(8).cast(), v[1]);
        }
    }
    #[inline(always)]
    unsafe fn store_masked(p: &mut [f32; 16], m: [__m256; 2], v: [__m256; 2]) {
        // A half whose lanes are all stored takes a plain store (the
        // masked store instruction is slow on some CPUs; the compiler
        // would also make one of a load, blend and store).
        unsafe {
            for h in 0..2 {
                let at = p.as_mut_ptr().add(8 * h);
                match _mm256_movemask_ps(m[h]) {
                    0xff => _mm256_storeu_ps(at, v[h]),
                    0 => {}
                    _ => _mm256_maskstore_ps(at, _mm256_castps_si256(m[h]), v[h]),
                }
            }
        }
    }
    #[inline(always)]
    unsafe fn splat(x: f32) -> [__m256; 2] {
        unsafe { [_mm256_set1_ps(x); 2] }
    }
    #[inline(always)]
    unsafe fn splat_i(x: i32) -> [__m256i; 2] {
        unsafe { [_mm256_set1_epi32(x); 2] }
    }
    #[inline(always)]
    unsafe fn zero() -> [__m256; 2] {
        unsafe { [_mm256_setzero_ps(); 2] }
    }
    #[inline(always)]
    unsafe fn add(a: [__m256; 2], b: [__m256; 2]) -> [__m256; 2] {
        unsafe { halves!(_mm256_add_ps, a, b) }
    }
    #[inline(always)]
    unsafe fn sub(a: [__m256; 2], b: [__m256; 2]) -> [__m256; 2] {
        unsafe { halves!(_mm256_sub_ps, a, b) }
    }
    #[inline(always)]
    unsafe fn mul(a: [__m256; 2], b: [__m256; 2]) -> [__m256; 2] {
        unsafe { halves!(_mm256_mul_ps, a, b) }
    }
    #[inline(always)]
    unsafe fn div(a: [__m256; 2], b: [__m256; 2]) -> [__m256; 2] {
        unsafe { halves!(_mm256_div_ps, a, b) }
    }
    #[inline(always)]
    unsafe fn max(a: [__m256; 2], b: [__m256; 2]) -> [__m256; 2] {
        unsafe { halves!(_mm256_max_ps, a, b) }
    }
    #[inline(always)]
    unsafe fn min(a: [__m256; 2], b: [__m256; 2]) -> [__m256; 2] {
        unsafe { halves!(_mm256_min_ps, a, b) }
    }
    #[inline(always)]
    unsafe fn floor(a: [__m256; 2]) -> [__m256; 2] {
        #[inline(always)]
        unsafe fn f(x: __m256) -> __m256 {
            unsafe { _mm256_round_ps::<{ _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC }>(x) }
        }
        unsafe { halves!(f, a) }
    }
    #[inline(always)]
    unsafe fn to_f(a: [__m256i; 2]) -> [__m256; 2] {
        unsafe { halves!(_mm256_cvtepi32_ps, a) }
    }
    #[inline(always)]
    unsafe fn trunc_i(a: [__m256; 2]) -> [__m256i; 2] {
        unsafe { halves!(_mm256_cvttps_epi32, a) }
    }
    #[inline(always)]
    unsafe fn not_gt(a: [__m256; 2], b: [__m256; 2]) -> [__m256; 2] {
        unsafe {
            [
                _mm256_cmp_ps::<_CMP_NGT_UQ>(a[0], b[0]),
                _mm256_cmp_ps::<_CMP_NGT_UQ>(a[1], b[1]),
            ]
        }
    }
    #[inline(always)]
    unsafe fn ge(a: [__m256; 2], b: [__m256; 2]) -> [__m256; 2] {
        unsafe {
            [
                _mm256_cmp_ps::<_CMP_GE_OQ>(a[0], b[0]),
                _mm256_cmp_ps::<_CMP_GE_OQ>(a[1], b[1]),
            ]
        }
    }
    #[inline(always)]
    unsafe fn lt(a: [__m256; 2], b: [__m256; 2]) -> [__m256; 2] {
        unsafe {
            [
                _mm256_cmp_ps::<_CMP_LT_OQ>(a[0], b[0]),
                _mm256_cmp_ps::<_CMP_LT_OQ>(a[1], b[1]),
            ]
        }
    }
    #[inline(always)]
    unsafe fn gt(a: [__m256; 2], b: [__m256; 2]) -> [__m256; 2] {
        unsafe {
            [
                _mm256_cmp_ps::<_CMP_GT_OQ>(a[0], b[0]),
                _mm256_cmp_ps::<_CMP_GT_OQ>(a[1], b[1]),
            ]
        }
    }
    #[inline(always)]
    unsafe fn ordered(a: [__m256; 2], b: [__m256; 2]) -> [__m256; 2] {
        unsafe {
            [
                _mm256_cmp_ps::<_CMP_ORD_Q>(a[0], b[0]),
                _mm256_cmp_ps::<_CMP_ORD_Q>(a[1], b[1]),
            ]
        }
    }
    #[inline(always)]
    unsafe fn lt_or_nan(a: [__m256; 2], b: [__m256; 2]) -> [__m256; 2] {
        unsafe {
            [
                _mm256_cmp_ps::<_CMP_NGE_UQ>(a[0], b[0]),
                _mm256_cmp_ps::<_CMP_NGE_UQ>(a[1], b[1]),
            ]
        }
    }
    #[inline(always)]
    unsafe fn gt_or_nan(a: [__m256; 2], b: [__m256; 2]) -> [__m256; 2] {
        unsafe {
            [
                _mm256_cmp_ps::<_CMP_NLE_UQ>(a[0], b[0]),
                _mm256_cmp_ps::<_CMP_NLE_UQ>(a[1], b[1]),
            ]
        }
    }
    #[inline(always)]
    unsafe fn flush(a: [__m256; 2]) -> [__m256; 2] {
        unsafe {
            let mut out = a;
            for (o, a) in out.iter_mut().zip(a) {
                let b = _mm256_castps_si256(a);
                // A zero exponent clears every bit but the sign.
                let e = _mm256_and_si256(b, _mm256_set1_epi32(0x7f80_0000));
                let zero = _mm256_cmpeq_epi32(e, _mm256_setzero_si256());
                let clear = _mm256_and_si256(zero, _mm256_set1_epi32(i32::MAX));
                *o = _mm256_castsi256_ps(_mm256_andnot_si256(clear, b));
            }
            out
        }
    }
    #[inline(always)]
    unsafe fn select(m: [__m256; 2], yes: [__m256; 2], no: [__m256; 2]) -> [__m256; 2] {
        unsafe {
            [
                _mm256_blendv_ps(no[0], yes[0], m[0]),
                _mm256_blendv_ps(no[1], yes[1], m[1]),
            ]
        }
    }
    #[inline(always)]
    unsafe fn keep(m: [__m256; 2], a: [__m256; 2]) -> [__m256; 2] {
        unsafe { halves!(_mm256_and_ps, m, a) }
    }
    #[inline(always)]
    unsafe fn add_i(a: [__m256i; 2], b: [__m256i; 2]) -> [__m256i; 2] {
        unsafe { halves!(_mm256_add_epi32, a, b) }
    }
    #[inline(always)]
    unsafe fn sub_i(a: [__m256i; 2], b: [__m256i; 2]) -> [__m256i; 2] {
        unsafe { halves!(_mm256_sub_epi32, a, b) }
    }
    #[inline(always)]
    unsafe fn mullo_i(a: [__m256i; 2], b: [__m256i; 2]) -> [__m256i; 2] {
        unsafe { halves!(_mm256_mullo_epi32, a, b) }
    }
    #[inline(always)]
    unsafe fn max_i(a: [__m256i; 2], b: [__m256i; 2]) -> [__m256i; 2] {
        unsafe { halves!(_mm256_max_epi32, a, b) }
    }
    #[inline(always)]
    unsafe fn min_i(a: [__m256i; 2], b: [__m256i; 2]) -> [__m256i; 2] {
        unsafe { halves!(_mm256_min_epi32, a, b) }
    }
    #[inline(always)]
    unsafe fn min_u(a: [__m256i; 2], b: [__m256i; 2]) -> [__m256i; 2] {
        unsafe { halves!(_mm256_min_epu32, a, b) }
    }
    #[inline(always)]
    unsafe fn eq_i(a: [__m256i; 2], b: [__m256i; 2]) -> [__m256; 2] {
        unsafe {
            [
                fmask(_mm256_cmpeq_epi32(a[0], b[0])),
                fmask(_mm256_cmpeq_epi32(a[1], b[1])),
            ]
        }
    }
    #[inline(always)]
    unsafe fn lt_i(a: [__m256i; 2], b: [__m256i; 2]) -> [__m256; 2] {
        unsafe {
            [
                fmask(_mm256_cmpgt_epi32(b[0], a[0])),
                fmask(_mm256_cmpgt_epi32(b[1], a[1])),
            ]
        }
    }
    #[inline(always)]
    unsafe fn ge_i(a: [__m256i; 2], b: [__m256i; 2]) -> [__m256; 2] {
        unsafe {
            let ones = _mm256_set1_epi32(-1);
            [
                fmask(_mm256_xor_si256(_mm256_cmpgt_epi32(b[0], a[0]), ones)),
                fmask(_mm256_xor_si256(_mm256_cmpgt_epi32(b[1], a[1]), ones)),
            ]
        }
    }
    #[inline(always)]
    unsafe fn select_i(m: [__m256; 2], yes: [__m256i; 2], no: [__m256i; 2]) -> [__m256i; 2] {
        unsafe {
            let mut out = no;
            for h in 0..2 {
                out[h] = _mm256_castps_si256(_mm256_blendv_ps(
                    _mm256_castsi256_ps(no[h]),
                    _mm256_castsi256_ps(yes[h]),
                    m[h],
                ));
            }
            out
        }
    }
    #[inline(always)]
    unsafe fn byte(a: [__m256i; 2], c: usize) -> [__m256i; 2] {
        unsafe {
            let ff = _mm256_set1_epi32(255);
            match c {
                0 => [_mm256_and_si256(a[0], ff), _mm256_and_si256(a[1], ff)],
                3 => [_mm256_srli_epi32::<24>(a[0]), _mm256_srli_epi32::<24>(a[1])],
                1 => [
                    _mm256_and_si256(_mm256_srli_epi32::<8>(a[0]), ff),
                    _mm256_and_si256(_mm256_srli_epi32::<8>(a[1]), ff),
                ],
                _ => [
                    _mm256_and_si256(_mm256_srli_epi32::<16>(a[0]), ff),
                    _mm256_and_si256(_mm256_srli_epi32::<16>(a[1]), ff),
                ],
            }
        }
    }
    #[inline(always)]
    unsafe fn shl_bytes(a: [__m256i; 2], c: usize) -> [__m256i; 2] {
        unsafe {
            match c {
                0 => a,
                1 => [_mm256_slli_epi32::<8>(a[0]), _mm256_slli_epi32::<8>(a[1])],
                2 => [_mm256_slli_epi32::<16>(a[0]), _mm256_slli_epi32::<16>(a[1])],
                _ => [_mm256_slli_epi32::<24>(a[0]), _mm256_slli_epi32::<24>(a[1])],
            }
        }
    }
    #[inline(always)]
    unsafe fn or_i(a: [__m256i; 2], b: [__m256i; 2]) -> [__m256i; 2] {
        unsafe { halves!(_mm256_or_si256, a, b) }
    }
    #[inline(always)]
    unsafe fn and_i(a: [__m256i; 2], b: [__m256i; 2]) -> [__m256i; 2] {
        unsafe { halves!(_mm256_and_si256, a, b) }
    }
    #[inline(always)]
    unsafe fn shl_i(a: [__m256i; 2], n: u32) -> [__m256i; 2] {
        unsafe {
            let n = _mm_cvtsi32_si128(n as i32);
            [_mm256_sll_epi32(a[0], n), _mm256_sll_epi32(a[1], n)]
        }
    }
    #[inline(always)]
    unsafe fn sra_i(a: [__m256i; 2], n: u32) -> [__m256i; 2] {
        unsafe {
            let n = _mm_cvtsi32_si128(n as i32);
            [_mm256_sra_epi32(a[0], n), _mm256_sra_epi32(a[1], n)]
        }
    }
    #[inline(always)]
    unsafe fn halves_i(a: [__m256i; 2]) -> [__m256i; 2] {
        a
    }
    #[inline(always)]
    unsafe fn from_halves(h: [__m256; 2]) -> [__m256; 2] {
        h
    }
    #[inline(always)]
    unsafe fn mask(bits: u32) -> [__m256; 2] {
        unsafe {
            let bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
            let mut m = [_mm256_setzero_ps(); 2];
            for (h, m) in m.iter_mut().enumerate() {
                let v = _mm256_and_si256(_mm256_set1_epi32((bits >> (8 * h)) as i32), bit);
                *m = fmask(_mm256_cmpeq_epi32(v, bit));
            }
            m
        }
    }
    #[inline(always)]
    unsafe fn bits(m: [__m256; 2]) -> u32 {
        unsafe { (_mm256_movemask_ps(m[0]) as u32) | ((_mm256_movemask_ps(m[1]) as u32) << 8) }
    }
    #[inline(always)]
    unsafe fn load_rows(row0: *const u32, row1: *const u32) -> [__m256i; 2] {
        unsafe {
            [
                _mm256_loadu_si256(row0.cast()),
                _mm256_loadu_si256(row1.cast()),
            ]
        }
    }
    #[inline(always)]
    unsafe fn store_rows(row0: *mut u32, row1: *mut u32, v: [__m256i; 2]) {
        unsafe {
            _mm256_storeu_si256(row0.cast(), v[0]);
            _mm256_storeu_si256(row1.cast(), v[1]);
        }
    }
    #[inline(always)]
    unsafe fn quads_to_rows(a: [__m256; 2]) -> [__m256; 2] {
        unsafe {
            // Per half [q0 k0..k3, q1 k0..k3]: rows apart within each
            // 128-bit half, then the halves' rows joined.
            let split = _mm256_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7);
            let a0 = _mm256_permutevar8x32_ps(a[0], split);
            let a1 = _mm256_permutevar8x32_ps(a[1], split);
            [
                _mm256_permute2f128_ps::<0x20>(a0, a1),
                _mm256_permute2f128_ps::<0x31>(a0, a1),
            ]
        }
    }
    #[inline(always)]
    unsafe fn quad_lane(a: [__m256; 2], k: i32) -> [__m256; 2] {
        unsafe {
            let lane = _mm256_add_epi32(
                _mm256_setr_epi32(0, 0, 0, 0, 4, 4, 4, 4),
                _mm256_set1_epi32(k),
            );
            [
                _mm256_permutevar8x32_ps(a[0], lane),
                _mm256_permutevar8x32_ps(a[1], lane),
            ]
        }
    }
}
