//! The x86 variants' register code: each lane's quad derivatives for λ
//! ([`quad_derivatives`]), the *_MIPMAP_LINEAR levels
//! ([`mipmap_linear_levels`]), and the filtering of RGBA8 levels: the
//! fixed-point filter
//! of [`crate::unorm8_filter`] for requests whose lanes read one level per
//! level pass (the lanes that matter: the request's for the first level,
//! those blending two levels for the second) and whose S and T wrap modes
//! are REPEAT or CLAMP_TO_EDGE. Those are nearly all lookups of a
//! trilinear texture: level selection is per quad and varies slowly.
//!
//! The coordinates, texel indices and weights are computed over
//! [`Lanes16`] (one AVX-512 register or two AVX2 ones per value) with the
//! portable code's operations (floors by the rounding instruction as
//! [`super::lanes::floor_of`] allows), so the same values; the level's size is
//! a scalar (REPEAT of a power-of-two size wraps by a mask). The filter
//! itself works on AVX2 registers of four pixels × four channels × 16
//! bits (both instruction sets have AVX2). The texels are read from the
//! level's padded copy ([`crate::texture::Image::padded`], built on the
//! first lookup: rows one texel longer and one more row, holding the wrap
//! neighbours), so the two texels of a footprint's row are always one
//! 64-bit load and its second row one row on: no wrap to apply past the
//! first texel, no lane to treat apart (levels without a copy go to the
//! lane by lane code). A row is
//! one `vpmaddubsw` of the texel bytes (offset to signed) by the weight
//! bytes, the blends of rows and of levels one `vpmulhrsw` each, and the
//! result is transposed to one value per channel and converted to f32
//! (m / 32640 by a multiply and one fused correction: the division's
//! bits, tested for every m). Every step is exact integer arithmetic, so
//! the same bits as the portable code.

use super::storage::{LevelTable, Store};
use crate::ex::LANES;
use crate::texture::{Texture, Wrap};
use crate::unorm8_filter;
use exec::lanes16::Lanes16;
use std::arch::x86_64::*;

/// Samples level `level[0]` (and `level[1]`, blended by `f` on the lanes
/// in `two`) at `st` into the lanes `mask` of `out` (LINEAR, or NEAREST
/// on the lanes in `nearest`) in fixed point, as the portable code does
/// ([`unorm8_filter`]); false (nothing written) when the request does not
/// qualify (see the module documentation).
///
/// # Safety
/// The CPU must support `V`'s instruction set, and this must be inlined
/// into code compiled for it.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(super) unsafe fn sample_unorm8<V: Lanes16>(
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
    let Some(d0) = (unsafe { uniform::<V>(&level[0], mask) }) else {
        return false;
    };
    let d1 = if two != 0 {
        // SAFETY: as above.
        match unsafe { uniform::<V>(&level[1], two) } {
            Some(d) => Some(d),
            None => return false,
        }
    } else {
        None
    };
    // SAFETY: the CPU supports the features (the caller's contract); the
    // loads and stores are of 16-element arrays.
    unsafe {
        let s = V::load(st[0]);
        let t = V::load(st[1]);
        let near = V::mask(nearest);
        let Some(mut m) = level_fixed::<V>(table, levels, d0, wraps, (s, t), (near, nearest))
        else {
            return false;
        };
        if let Some(d1) = d1 {
            let Some(second) = level_fixed::<V>(table, levels, d1, wraps, (s, t), (near, nearest))
            else {
                return false;
            };
            // φ = ⌊256·f⌋ (`unorm8_filter::level_weight`) on the lanes in
            // `two`, 0 elsewhere (which keeps the first level's value),
            // as φ·128 for the rounding high multiply.
            let w = V::mul(V::load(f), V::splat(256.0));
            let phi = V::trunc_i(V::min(w, V::splat(255.0)));
            let on = V::bits(V::ge(w, V::splat(1.0))) & two;
            let phi = V::select_i(V::mask(on), phi, V::splat_i(0));
            let wf = spread(V::halves_i(twice16::<V>(V::shl_i(phi, 7))));
            for k in 0..4 {
                m[k] = blend(m[k], second[k], wf[k]);
            }
        }
        let rgba = to_lanes(m);
        for (o, v) in out.iter_mut().zip(rgba) {
            let v = V::from_halves(v);
            if mask == 0xffff {
                V::store(o, v);
            } else {
                V::store_masked(o, V::mask(mask), v);
            }
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
/// As for [`sample_unorm8`].
#[inline(always)]
pub(super) unsafe fn mipmap_linear_levels<V: Lanes16>(
    lam: &[f32; LANES],
    c: f32,
    (base, q): (i32, i32),
    (mag_nearest, min_nearest): (bool, bool),
    level: &mut [[i32; LANES]; 2],
    f: &mut [f32; LANES],
) -> (u32, u32) {
    // SAFETY: the CPU supports the features (the caller's contract); the
    // loads and stores are of 16-element arrays.
    unsafe {
        let lambda = V::load(lam);
        // λ NaN or ≤ c.
        let mag = V::bits(V::not_gt(lambda, V::splat(c)));
        let lb = V::add(V::splat(base as f32), lambda);
        let top_m = V::ge(lb, V::splat(q as f32));
        let top = V::bits(top_m);
        let (bv, qv) = (V::splat_i(base), V::splat_i(q));
        let d1 = V::min_i(V::max_i(floor_index::<V>(V::floor(lb)), bv), qv);
        let l0 = V::select_i(V::mask(mag), bv, V::select_i(top_m, qv, d1));
        let l1 = V::min_i(V::add_i(d1, V::splat_i(1)), qv);
        V::store_i(&mut level[0], l0);
        V::store_i(&mut level[1], l1);
        V::store(f, V::sub(lambda, V::floor(lambda)));
        let two = !mag & !top & 0xffff;
        let pick = if mag_nearest { 0xffff } else { 0 };
        let pick_min = if min_nearest { 0xffff } else { 0 };
        let nearest = (mag & pick) | (!mag & pick_min & 0xffff);
        (two, nearest)
    }
}

/// The derivatives of S and T along x and y on every lane, as its quad's
/// first lane has them (`levels::quad_first`), in that order: those of
/// `given` (the same four), or without, the implicit ones of `st`,
/// `v[4q + k] − v[4q]` (k 1 along x, 2 along y) for quad q. The arrays
/// are read whole and their lanes moved in registers, instead of a
/// scalar read per quad of arrays the caller has just stored whole
/// (the sampler's instructions −3.3 % on the textured scene).
///
/// # Safety
/// As for [`sample_unorm8`].
#[inline(always)]
pub(super) unsafe fn quad_derivatives<V: Lanes16>(
    given: Option<[&[f32; LANES]; 4]>,
    st: [&[f32; LANES]; 2],
) -> [[f32; LANES]; 4] {
    let mut d = [[0.0f32; LANES]; 4];
    // SAFETY: the CPU supports the features (the caller's contract); the
    // loads and stores are of 16-element arrays.
    unsafe {
        match given {
            Some(given) => {
                for (d, a) in d.iter_mut().zip(given) {
                    V::store(d, V::quad_lane(V::load(a), 0));
                }
            }
            None => {
                for (k, v) in st.into_iter().enumerate() {
                    let v = V::load(v);
                    let first = V::quad_lane(v, 0);
                    V::store(&mut d[k], V::sub(V::quad_lane(v, 1), first));
                    V::store(&mut d[k + 2], V::sub(V::quad_lane(v, 2), first));
                }
            }
        }
    }
    d
}

/// The one level of the lanes in `lanes` (not empty), if they have one.
/// (A function, not a closure: a closure is compiled without the target
/// features and called out of line.)
#[inline(always)]
unsafe fn uniform<V: Lanes16>(level: &[i32; LANES], lanes: u32) -> Option<i32> {
    let d = level[(lanes.trailing_zeros() as usize).min(LANES - 1)];
    // SAFETY: a load of the 16 elements of `level`.
    let same = unsafe { V::bits(V::eq_i(V::load_i(level), V::splat_i(d))) };
    (same & lanes == lanes).then_some(d)
}
/// `floor_index` per lane: NaN gives 0, the rest clamped to ±2^30 and
/// truncated.
#[inline(always)]
unsafe fn floor_index<V: Lanes16>(fl: V::F) -> V::I {
    unsafe {
        let x = V::keep(V::ordered(fl, fl), fl);
        let x = V::max(x, V::splat(-1_073_741_824.0));
        let x = V::min(x, V::splat(1_073_741_824.0));
        V::trunc_i(x)
    }
}

/// `wrap_index(i, wrap, n)` per lane, for i in [−1, n] (the only values
/// the callers pass: a wrapped coordinate is in [0, n]): REPEAT of a
/// power-of-two size is then the low bits.
#[inline(always)]
unsafe fn wrap_index<V: Lanes16>(i: V::I, wrap: Wrap, n: i32) -> V::I {
    unsafe {
        let last = V::splat_i(n - 1);
        if wrap == Wrap::Repeat && n & (n - 1) == 0 {
            return V::and_i(i, last);
        }
        let i = if wrap == Wrap::Repeat {
            let nv = V::splat_i(n);
            let below = V::lt_i(i, V::splat_i(0));
            let above = V::ge_i(i, nv);
            let i2 = V::select_i(below, V::add_i(i, nv), i);
            V::select_i(above, V::sub_i(i, nv), i2)
        } else {
            i
        };
        let i = V::max_i(i, V::splat_i(0));
        V::min_i(i, last)
    }
}

/// `wrap_scale` of one axis with the level's size `n` (REPEAT or
/// CLAMP_TO_EDGE).
#[inline(always)]
unsafe fn wrap_scale<V: Lanes16>(wrap: Wrap, s: V::F, n: i32) -> V::F {
    unsafe {
        let nf = n as f32;
        let nv = V::splat(nf);
        if wrap == Wrap::Repeat {
            return V::mul(V::sub(s, V::floor(s)), nv);
        }
        let half = 0.5 / nf;
        let (lo, hi) = (V::splat(half), V::splat(1.0 - half));
        let x = V::select(V::lt(s, lo), lo, s);
        let x = V::select(V::gt(x, hi), hi, x);
        V::mul(x, nv)
    }
}

/// `axis_unorm8` with the level's size `n`: texel 0 (the NEAREST texel
/// on the lanes in `nearest`) and the weight of texel 1 in 128ths (0 on
/// the NEAREST lanes); texel 1 is the next one of the padded level (for
/// CLAMP_TO_EDGE's texel −1, which reads texel 0 twice, weight 0).
#[inline(always)]
unsafe fn axis<V: Lanes16>(
    u: V::F,
    n: i32,
    wrap: Wrap,
    (nearest, nearest_lanes): (V::M, u32),
) -> (V::I, V::I) {
    unsafe {
        // `unorm8_filter::coord` and `split`.
        let x = V::sub_i(
            floor_index::<V>(V::floor(V::mul(u, V::splat(128.0)))),
            V::splat_i(64),
        );
        let i = V::sra_i(x, 7);
        let mut a = V::and_i(x, V::splat_i(127));
        let i0 = wrap_index::<V>(i, wrap, n);
        if wrap == Wrap::ClampToEdge {
            // i = −1 (only from a NaN coordinate: CLAMP_TO_EDGE keeps u at
            // least ½) reads texel 0 twice, where the padded row's next
            // texel is texel 1: weight 0 on it gives the same sum.
            a = V::select_i(V::lt_i(i, V::splat_i(0)), V::splat_i(0), a);
        }
        if nearest_lanes == 0 {
            return (i0, a);
        }
        let near = wrap_index::<V>(floor_index::<V>(V::floor(u)), wrap, n);
        (
            V::select_i(nearest, near, i0),
            V::select_i(nearest, V::splat_i(0), a),
        )
    }
}

/// Each lane's 16 low bits in both halves of the lane (for the 16-bit
/// steps, which see a lane's two halves as two channels).
#[inline(always)]
unsafe fn twice16<V: Lanes16>(x: V::I) -> V::I {
    unsafe { V::or_i(x, V::shl_i(x, 16)) }
}

/// The sixteen lanes' 32-bit values (two registers, lanes 0–7 and 8–15)
/// in the four-pixel registers' order (see [`exec::lanes16::pairs4`]),
/// each lane's value twice: one 64-bit element a pixel.
#[inline(always)]
unsafe fn spread(x: [__m256i; 2]) -> [__m256i; 4] {
    // (Each lane paired with itself.)
    unsafe { pair_up(x, x) }
}

/// The texel pairs (t(i₀), t(i₁)) of the lanes as four-pixel registers
/// from the two corners' words (lanes 0–7, 8–15 each).
#[inline(always)]
unsafe fn pair_up(t0: [__m256i; 2], t1: [__m256i; 2]) -> [__m256i; 4] {
    unsafe {
        [
            _mm256_unpacklo_epi32(t0[0], t1[0]),
            _mm256_unpackhi_epi32(t0[0], t1[0]),
            _mm256_unpacklo_epi32(t0[1], t1[1]),
            _mm256_unpackhi_epi32(t0[1], t1[1]),
        ]
    }
}

/// `unorm8_filter::row` of the four channels of four pixels, less
/// 128·128: the pairs' bytes interleaved by channel (t₀, t₁), offset to
/// signed bytes, multiplied by the weight bytes (128 − a, a) and summed
/// in pairs: −16384 ..= 16256, no saturation.
#[inline(always)]
unsafe fn row(pairs: __m256i, weights: __m256i) -> __m256i {
    unsafe {
        let by_channel = _mm256_setr_epi8(
            0, 4, 1, 5, 2, 6, 3, 7, 8, 12, 9, 13, 10, 14, 11, 15, 0, 4, 1, 5, 2, 6, 3, 7, 8, 12, 9,
            13, 10, 14, 11, 15,
        );
        let b = _mm256_shuffle_epi8(pairs, by_channel);
        let b = _mm256_xor_si256(b, _mm256_set1_epi8(-128));
        _mm256_maddubs_epi16(weights, b)
    }
}

/// `x + ⌊((y − x)·w + 2^14) / 2^15⌋` on 16-bit values (`w` the weight
/// scaled to 2^15): `unorm8_filter::rows` with w = b·256, `levels` with
/// w = φ·128. The offset of [`row`]'s values cancels in the difference.
#[inline(always)]
unsafe fn blend(x: __m256i, y: __m256i, w: __m256i) -> __m256i {
    unsafe { _mm256_add_epi16(x, _mm256_mulhrs_epi16(_mm256_sub_epi16(y, x), w)) }
}

/// LINEAR (NEAREST on the lanes in `nearest`) on level `d` for every lane
/// (the lanes not meant get some value), in fixed point less 16384 (the
/// rows' offset), as four-pixel registers; `None` (nothing read) when the
/// level has no padded copy ([`crate::texture::Image::padded`]: the lane
/// by lane code takes the request).
///
/// The copy's rows are `w + 1` texels with the wrap neighbours appended,
/// so each lane's footprint is the 64-bit pair at `j₀·(w + 1) + i₀` and
/// the pair one row on, whatever the wrap; a NEAREST lane reads its texel
/// and its neighbour with weight 0.
#[inline(always)]
unsafe fn level_fixed<V: Lanes16>(
    table: &LevelTable,
    levels: &[crate::texture::Image],
    d: i32,
    wraps: [Wrap; 2],
    (s, t): (V::F, V::F),
    (near, nearest): (V::M, u32),
) -> Option<[__m256i; 4]> {
    let sh = (d.wrapping_sub(table.base) as u32).min(31);
    let w = (table.width >> sh).max(1) as i32;
    let h = (table.height >> sh).max(1) as i32;
    let texels = levels
        .get(d as usize)
        .filter(|img| img.width as i32 == w && img.height as i32 == h)
        .and_then(|img| img.padded(wraps))
        .filter(|p| p.len() >= 2 * (w as usize + 1))?;
    // SAFETY: the CPU supports the features (the caller's contract); the
    // reads are bounded below.
    unsafe {
        let us = wrap_scale::<V>(wraps[0], s, w);
        let ut = wrap_scale::<V>(wraps[1], t, h);
        let (i0, a) = axis::<V>(us, w, wraps[0], (near, nearest));
        let (j0, b) = axis::<V>(ut, h, wraps[1], (near, nearest));
        // Row weights: bytes (128 − a, a) twice per lane; column weights
        // b·256 twice per lane.
        let wx = V::or_i(V::sub_i(V::splat_i(128), a), V::shl_i(a, 8));
        let wx = spread(V::halves_i(twice16::<V>(wx)));
        let wy = spread(V::halves_i(twice16::<V>(V::shl_i(b, 8))));
        // A footprint's first pair is at most at (w + 1)(h + 1) − 2 −
        // (w + 1) (i₀ < w, j₀ < h), its second one row on; the bound keeps
        // every 64-bit read inside the copy regardless.
        let stride = (w + 1) as usize;
        let at0 = V::add_i(V::mullo_i(j0, V::splat_i(w + 1)), i0);
        let last = texels
            .len()
            .saturating_sub(2 + stride)
            .min(i32::MAX as usize);
        let at0 = V::halves_i(V::min_u(at0, V::splat_i(last as i32)));
        let base = texels.as_ptr().cast::<u32>();
        if nearest == 0xffff {
            // NEAREST everywhere (a = b = 0): the first row alone.
            let p0 = exec::lanes16::pairs4(base, at0);
            let mut v = [_mm256_setzero_si256(); 4];
            for k in 0..4 {
                v[k] = row(p0[k], wx[k]);
            }
            return Some(v);
        }
        let (p0, p1) = exec::lanes16::pairs4_rows(base, at0, stride);
        let mut v = [_mm256_setzero_si256(); 4];
        for k in 0..4 {
            v[k] = blend(row(p0[k], wx[k]), row(p1[k], wx[k]), wy[k]);
        }
        Some(v)
    }
}

/// Four-pixel registers of fixed-point values less 16384 as the colour
/// values of the sixteen lanes (`unorm8_filter::value`), RGBA, each as
/// lanes 0–7 and 8–15: m / 32640 correctly rounded without a division
/// (`x · fl(1/32640)` corrected once by the exact residual, fused; a test
/// checks every value).
#[inline(always)]
unsafe fn to_lanes(m: [__m256i; 4]) -> [[__m256; 2]; 4] {
    unsafe {
        let off = _mm256_set1_epi16(16384);
        // Per 128 bits, two pixels' channels (p.r p.g p.b p.a q.r ...) as
        // (p.r q.r p.g q.g ...): one 32-bit word per channel.
        let pair = _mm256_setr_epi8(
            0, 1, 8, 9, 2, 3, 10, 11, 4, 5, 12, 13, 6, 7, 14, 15, 0, 1, 8, 9, 2, 3, 10, 11, 4, 5,
            12, 13, 6, 7, 14, 15,
        );
        let mut r = [_mm256_setzero_si256(); 4];
        for k in 0..4 {
            r[k] = _mm256_shuffle_epi8(_mm256_add_epi16(m[k], off), pair);
        }
        // Words of lanes (0, 1), (2, 3) | (4, 5), (6, 7) by channel, and
        // of lanes 8–15 likewise.
        let (rg_lo, ba_lo) = (
            _mm256_unpacklo_epi32(r[0], r[1]),
            _mm256_unpackhi_epi32(r[0], r[1]),
        );
        let (rg_hi, ba_hi) = (
            _mm256_unpacklo_epi32(r[2], r[3]),
            _mm256_unpackhi_epi32(r[2], r[3]),
        );
        // One channel of lanes 0–3, 8–11 | 4–7, 12–15 as 16-bit values.
        let channels = [
            _mm256_unpacklo_epi64(rg_lo, rg_hi),
            _mm256_unpackhi_epi64(rg_lo, rg_hi),
            _mm256_unpacklo_epi64(ba_lo, ba_hi),
            _mm256_unpackhi_epi64(ba_lo, ba_hi),
        ];
        let inv = _mm256_set1_ps(1.0 / unorm8_filter::ONE as f32);
        let one = _mm256_set1_ps(unorm8_filter::ONE as f32);
        let zero = _mm256_setzero_si256();
        let mut out = [[_mm256_setzero_ps(); 2]; 4];
        for (o, c) in out.iter_mut().zip(channels) {
            let halves = [
                _mm256_unpacklo_epi16(c, zero),
                _mm256_unpackhi_epi16(c, zero),
            ];
            for (o, x) in o.iter_mut().zip(halves) {
                let x = _mm256_cvtepi32_ps(x);
                let q = _mm256_mul_ps(x, inv);
                let residual = _mm256_fnmadd_ps(q, one, x);
                *o = _mm256_fmadd_ps(residual, inv, q);
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The lanes of the four-pixel registers, in order: register k, slot
    /// p (64-bit element) holds lane `LANE_OF[k][p]`.
    const LANE_OF: [[usize; 4]; 4] = [[0, 1, 4, 5], [2, 3, 6, 7], [8, 9, 12, 13], [10, 11, 14, 15]];

    exec::compiled_for!(
        avx2,
        /// `to_lanes` of registers holding `m[c][lane] − 16384`.
        unsafe fn to_lanes_of(m: &[[i32; LANES]; 4]) -> [[f32; LANES]; 4] {
            let mut regs = [_mm256_setzero_si256(); 4];
            for (k, r) in regs.iter_mut().enumerate() {
                let mut words = [0i16; 16];
                for (p, &lane) in LANE_OF[k].iter().enumerate() {
                    for c in 0..4 {
                        words[4 * p + c] = (m[c][lane] - 16384) as i16;
                    }
                }
                // SAFETY: 32 bytes read from a 16-element i16 array.
                *r = unsafe { _mm256_loadu_si256(words.as_ptr().cast()) };
            }
            // SAFETY: the CPU has AVX2 and FMA (this function's level).
            let out = unsafe { to_lanes(regs) };
            let mut lanes = [[0.0f32; LANES]; 4];
            for c in 0..4 {
                for (h, &v) in out[c].iter().enumerate() {
                    // SAFETY: 8 floats written inside a 16-element array.
                    unsafe { _mm256_storeu_ps(lanes[c].as_mut_ptr().add(8 * h), v) };
                }
            }
            lanes
        }
    );

    /// Every fixed-point value becomes `unorm8_filter::value`'s float in
    /// its own lane and channel.
    #[test]
    fn registers_to_lanes_is_the_division_for_every_value() {
        if !exec::lanes16::X256::supported() {
            return;
        }
        let mut m = 0;
        while m <= unorm8_filter::ONE {
            let vals: [[i32; LANES]; 4] = std::array::from_fn(|c| {
                std::array::from_fn(|l| (m + (4 * l + c) as i32).min(unorm8_filter::ONE))
            });
            // SAFETY: the CPU has AVX2 and FMA (checked above).
            let got = unsafe { to_lanes_of(&vals) };
            for c in 0..4 {
                for l in 0..LANES {
                    let want = unorm8_filter::value(vals[c][l]);
                    assert_eq!(
                        got[c][l].to_bits(),
                        want.to_bits(),
                        "m {} lane {l} c {c}",
                        vals[c][l]
                    );
                }
            }
            m += 4 * LANES as i32;
        }
    }
}
