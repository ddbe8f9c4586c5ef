//! The x86 variants' filtering of RGBA8 levels: [`super::filter_lanes`]
//! and the level blend and output select of [`super::sample_in`] in
//! vector registers (one AVX-512 register or two AVX2 ones per value,
//! [`Lanes16`]), for requests whose lanes read one level per level pass
//! (the lanes that matter: the request's for the first level, those
//! blending two levels for the second) and whose S and T wrap modes are
//! REPEAT or CLAMP_TO_EDGE. Those are nearly all lookups of a trilinear
//! texture: level selection is per quad and varies slowly.
//!
//! The operations are the portable code's, in its order (floors by the
//! rounding instruction as [`super::floor_of`] allows, the RGBA8
//! conversion by [`Lanes16::unorm8`]'s fused correction), so
//! the same bits; what differs is that the level's size is a scalar, all
//! sixteen lanes stay in registers, no array goes through memory between
//! the steps, and when the two texels of each row are neighbours in
//! memory (every lane's i1 = i0 + 1, i.e. no lane at the wrap edge), each
//! row is read by one 64-bit gather per lane instead of two 32-bit ones.

use super::{LevelTable, Store, LANES};
use crate::texture::{Texture, Wrap};
use exec::lanes16::Lanes16;

/// Samples level `level[0]` (and `level[1]`, blended by `f` on the lanes
/// in `two`) at `st` into the lanes `mask` of `out` (LINEAR, or NEAREST
/// on the lanes in `nearest`), as the portable code does; false (nothing
/// written) when the request does not qualify (see the module
/// documentation).
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
        // Both levels' reads first, then the sums (the sums wait on the
        // gathers' latency: the second level's reads overlap it).
        let c0 = corners::<V>(table, levels, d0, wraps, (s, t), nearest, mask);
        // (Not `Option::map`: a closure is compiled without the target
        // features, and the intrinsics in it would not be inlined.)
        #[allow(clippy::manual_map)]
        let c1 = match d1 {
            Some(d1) => Some(corners::<V>(table, levels, d1, wraps, (s, t), nearest, two)),
            None => None,
        };
        let near = V::mask(nearest);
        let mut first = combine::<V>(&c0, nearest, near);
        if let Some(c1) = &c1 {
            let second = combine::<V>(c1, nearest, near);
            // `mix_levels` on the lanes in `two`.
            let fl = V::load(f);
            let one_minus = V::sub(V::splat(1.0), fl);
            let two = V::mask(two);
            for (a, b) in first.iter_mut().zip(second) {
                let mixed = V::add(V::mul(one_minus, *a), V::mul(fl, b));
                *a = V::select(two, mixed, *a);
            }
        }
        let m = V::mask(mask);
        for (o, v) in out.iter_mut().zip(first) {
            if mask == 0xffff {
                V::store(o, v);
            } else {
                V::store_masked(o, m, v);
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

/// `wrap_index(i, wrap, n)` per lane.
#[inline(always)]
unsafe fn wrap_index<V: Lanes16>(i: V::I, wrap: Wrap, n: V::I) -> V::I {
    unsafe {
        let i = if wrap == Wrap::Repeat {
            let below = V::lt_i(i, V::splat_i(0));
            let above = V::ge_i(i, n);
            let i2 = V::select_i(below, V::add_i(i, n), i);
            V::select_i(above, V::sub_i(i, n), i2)
        } else {
            i
        };
        let i = V::max_i(i, V::splat_i(0));
        V::min_i(i, V::sub_i(n, V::splat_i(1)))
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

/// `axis` with the level's size `n`: texel 0 (the NEAREST texel on the
/// lanes in `nearest`), texel 1 and the weight of texel 1.
#[inline(always)]
unsafe fn axis<V: Lanes16>(u: V::F, n: i32, wrap: Wrap, nearest: V::M) -> (V::I, V::I, V::F) {
    unsafe {
        let nv = V::splat_i(n);
        let v = V::sub(u, V::splat(0.5));
        let fl = V::floor(v);
        let i = floor_index::<V>(fl);
        let near = wrap_index::<V>(floor_index::<V>(V::floor(u)), wrap, nv);
        let alpha = V::sub(v, fl);
        let i0 = V::select_i(nearest, near, wrap_index::<V>(i, wrap, nv));
        // (i ≤ 2^30: the add does not overflow.)
        let i1 = wrap_index::<V>(V::add_i(i, V::splat_i(1)), wrap, nv);
        (i0, i1, alpha)
    }
}

/// Texels `idx` of `texels` (not empty) as RGBA8 words, the indices
/// clamped to the last texel.
#[inline(always)]
unsafe fn gather<V: Lanes16>(texels: &[[u8; 4]], idx: V::I) -> V::I {
    let last = texels.len().saturating_sub(1).min(i32::MAX as usize) as i32;
    // SAFETY: every index is in 0..=last: 4-byte reads of texels.
    unsafe {
        let idx = V::min_u(idx, V::splat_i(last));
        V::gather(texels.as_ptr().cast(), idx)
    }
}

/// Texels `idx` and `idx + 1` of `texels` (at least two), as two
/// vectors of RGBA8 words, by one 64-bit read per lane; `idx` clamped to
/// the last but one texel.
#[inline(always)]
unsafe fn gather_pairs<V: Lanes16>(texels: &[[u8; 4]], idx: V::I) -> (V::I, V::I) {
    debug_assert!(texels.len() >= 2);
    let last = texels.len().saturating_sub(2).min(i32::MAX as usize) as i32;
    // SAFETY: every index is in 0..=len − 2: 8-byte reads of two texels.
    unsafe {
        let idx = V::min_u(idx, V::splat_i(last));
        V::gather_pairs(texels.as_ptr().cast(), idx)
    }
}

/// The four corners of every lane on one level (RGBA8 words) and their
/// weights: the first half of `filter_lanes`.
struct Corners<V: Lanes16> {
    raw: [V::I; 4],
    wgt: [V::F; 4],
}

/// The corners of `filter_lanes` on level `d` for every lane (see the
/// module documentation); only the lanes in `used` are meant (the others
/// get some value). With NEAREST on every lane, only corner 0 is read.
#[inline(always)]
unsafe fn corners<V: Lanes16>(
    table: &LevelTable,
    levels: &[crate::texture::Image],
    d: i32,
    wraps: [Wrap; 2],
    (s, t): (V::F, V::F),
    nearest: u32,
    used: u32,
) -> Corners<V> {
    let texels = super::unorm8_level(levels, d);
    let sh = (d.wrapping_sub(table.base) as u32).min(31);
    let w = (table.width >> sh).max(1) as i32;
    let h = (table.height >> sh).max(1) as i32;
    unsafe {
        let near = V::mask(nearest);
        let us = wrap_scale::<V>(wraps[0], s, w);
        let ut = wrap_scale::<V>(wraps[1], t, h);
        let (i0, i1, a) = axis::<V>(us, w, wraps[0], near);
        let (j0, j1, b) = axis::<V>(ut, h, wraps[1], near);
        let wv = V::splat_i(w);
        let (r0, r1) = (V::mullo_i(j0, wv), V::mullo_i(j1, wv));
        let idx0 = V::add_i(r0, i0);
        let idx2 = V::add_i(r1, i0);
        let one = V::splat(1.0);
        let (a0, b0) = (V::sub(one, a), V::sub(one, b));
        let wgt = [V::mul(a0, b0), V::mul(a, b0), V::mul(a0, b), V::mul(a, b)];
        if nearest == 0xffff {
            let raw0 = gather::<V>(texels, idx0);
            return Corners {
                raw: [raw0; 4],
                wgt,
            };
        }
        // Both texels of each row neighbours in memory on every lane used
        // (the others read some two texels of the level).
        let next = V::bits(V::eq_i(i1, V::add_i(i0, V::splat_i(1))));
        let pairs = texels.len() >= 2 && (next | !used) & 0xffff == 0xffff;
        let raw = if pairs {
            let (t0, t1) = gather_pairs::<V>(texels, idx0);
            let (t2, t3) = gather_pairs::<V>(texels, idx2);
            [t0, t1, t2, t3]
        } else {
            [
                gather::<V>(texels, idx0),
                gather::<V>(texels, V::add_i(r0, i1)),
                gather::<V>(texels, idx2),
                gather::<V>(texels, V::add_i(r1, i1)),
            ]
        };
        Corners { raw, wgt }
    }
}

/// The second half of `filter_lanes`: the bilinear sum of the corners,
/// or corner 0 on the lanes in `nearest` (`near` as a mask); RGBA, one
/// value per component.
#[inline(always)]
unsafe fn combine<V: Lanes16>(corners: &Corners<V>, nearest: u32, near: V::M) -> [V::F; 4] {
    let (raw, wgt) = (&corners.raw, &corners.wgt);
    // (Loops, not closures: a closure is compiled without the target
    // features, and the intrinsics in it would not be inlined.)
    unsafe {
        let mut out = [V::zero(); 4];
        if nearest == 0xffff {
            for (c, o) in out.iter_mut().enumerate() {
                *o = V::unorm8(V::byte(raw[0], c));
            }
            return out;
        }
        for (c, o) in out.iter_mut().enumerate() {
            let t0 = V::unorm8(V::byte(raw[0], c));
            // The sum starts at 0 in the portable code: 0 + x is x for
            // every product here (a weight and a texel are +0 or more, or
            // NaN).
            let mut acc = V::mul(wgt[0], t0);
            for k in 1..4 {
                let tk = V::unorm8(V::byte(raw[k], c));
                acc = V::add(acc, V::mul(wgt[k], tk));
            }
            *o = if nearest == 0 {
                acc
            } else {
                V::select(near, t0, acc)
            };
        }
        out
    }
}
