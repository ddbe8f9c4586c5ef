//! LINEAR filtering of RGBA8 levels in fixed point: the definition every
//! path computes (the general per-lane sampler, the fast path's portable
//! code and its AVX2 / AVX-512 code), so an RGBA8 texture gives the same
//! bits whichever path and instruction set sample it.
//!
//! For a 2D level (or cube face) stored as bytes k (the values k/255),
//! none of whose four texels is the border colour:
//! - each axis's coordinate u (wrapped, and scaled by the level's size,
//!   GL 2.1 §3.8.8) becomes `x = ⌊128·u⌋ − 64`: u − ½ with seven
//!   fractional bits ([`coord`]); texel `i₀ = x >> 7`, `i₁ = i₀ + 1`,
//!   weight `a = x & 127` (in 128ths);
//! - each row: `h = (128 − a)·t(i₀) + a·t(i₁)`, exact: the value ×128,
//!   0 ..= 32640 ([`row`]);
//! - the two rows: `v = h₀ + ⌊((h₁ − h₀)·b + 64) / 128⌋` ([`rows`]);
//! - a NEAREST texel is `v = 128·k`;
//! - two levels (the `*_MIPMAP_LINEAR` filters, eq. 3.29):
//!   `m = v₁ + ⌊((v₂ − v₁)·φ + 128) / 256⌋` with `φ = ⌊256·f⌋`, f the
//!   fraction of λ ([`level_weight`], [`levels`]);
//! - the result is `m / 32640`, correctly rounded ([`value`]): a texel
//!   read alone, or at its centre, is exactly k/255, as NEAREST gives it.
//!
//! Why fixed point: the float filter (a conversion, a product and a sum
//! per texel and channel, eight texels a lookup) was most of the cost of
//! a trilinear lookup, and for bytes it buys nothing GL asks for (the
//! filter's precision is the implementation's; llvmpipe also filters
//! 8-bit texels in 16-bit integers with 8-bit weights). These steps are
//! what two x86 instructions do on sixteen 16-bit values at once: a row
//! is one multiply-add of byte pairs (`vpmaddubsw`, whose unsigned byte
//! operand is why the weights have seven bits), the blends of rows and
//! levels a rounding high multiply (`vpmulhrsw`). Every intermediate fits
//! 16 signed bits after the row's offset of −128·128.
//!
//! Other storage (f32 levels), depth textures, 1D and 3D textures and
//! lookups touching the border colour filter in f32 as before.

/// The fixed-point value of 1.0: 128 (the row weights' unit) × 255.
pub(crate) const ONE: i32 = 128 * 255;

/// `x = ⌊128·u⌋ − 64` from `fl = ⌊128·u⌋` (the caller's floor, any
/// exact one): NaN gives −64 (u taken as 0), the floor is clamped to
/// ±2^30 first (a wrapped coordinate of a level up to 2^16 texels is far
/// inside).
#[inline(always)]
pub(crate) fn coord(fl: f32) -> i32 {
    let bounded = if fl.is_nan() {
        0.0
    } else {
        fl.clamp(-1_073_741_824.0, 1_073_741_824.0)
    };
    // SAFETY: an integral value in [−2^30, 2^30] truncates exactly.
    (unsafe { bounded.to_int_unchecked::<i32>() }) - 64
}

/// The first texel of a LINEAR axis and its partner's weight (0..=127)
/// from [`coord`]'s `x`.
#[inline(always)]
pub(crate) fn split(x: i32) -> (i32, i32) {
    (x >> 7, x & 127)
}

/// One row of the bilinear sum of a channel: `(128 − a)·t0 + a·t1`.
#[inline(always)]
pub(crate) fn row(t0: u8, t1: u8, a: i32) -> i32 {
    (128 - a) * i32::from(t0) + a * i32::from(t1)
}

/// The blend of two rows with weight `b` (0..=127) on the second,
/// rounded half up.
#[inline(always)]
pub(crate) fn rows(h0: i32, h1: i32, b: i32) -> i32 {
    h0 + (((h1 - h0) * b + 64) >> 7)
}

/// φ = ⌊256·f⌋ for a level fraction f in [0, 1) (0 for NaN, 255 at most).
#[inline(always)]
pub(crate) fn level_weight(f: f32) -> i32 {
    let w = f * 256.0;
    if w >= 1.0 {
        // (w < 2^31: a truncation toward 0 is the floor.)
        (w.min(255.0)) as i32
    } else {
        0
    }
}

/// The blend of two levels' values with weight `w` (0..=255) on the
/// second, rounded half up.
#[inline(always)]
pub(crate) fn levels(v1: i32, v2: i32, w: i32) -> i32 {
    v1 + (((v2 - v1) * w + 128) >> 8)
}

/// The colour value of a fixed-point result `m` (0..=[`ONE`]): m/32640
/// correctly rounded.
#[inline(always)]
pub(crate) fn value(m: i32) -> f32 {
    m as f32 / ONE as f32
}

/// LINEAR on one level of RGBA8 texels: the four corners (row 0: t00,
/// t01; row 1: t10, t11) with weights `a` (along S) and `b` (along T).
#[inline(always)]
pub(crate) fn bilinear(t: [[u8; 4]; 4], a: i32, b: i32) -> [i32; 4] {
    std::array::from_fn(|c| {
        let h0 = row(t[0][c], t[1][c], a);
        let h1 = row(t[2][c], t[3][c], a);
        rows(h0, h1, b)
    })
}

/// A NEAREST texel as a fixed-point value.
#[inline(always)]
pub(crate) fn nearest(t: [u8; 4]) -> [i32; 4] {
    t.map(|k| 128 * i32::from(k))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The steps stay in 0..=ONE, reproduce texels at their centres and
    /// the float filter within a step of the weights.
    #[test]
    fn fixed_point_filter_is_close_to_the_exact_one() {
        let mut seed = 7u32;
        let mut next = || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            seed >> 8
        };
        for _ in 0..20_000 {
            let t: [[u8; 4]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| next() as u8));
            let (a, b) = ((next() % 128) as i32, (next() % 128) as i32);
            let v = bilinear(t, a, b);
            let (fa, fb) = (a as f64 / 128.0, b as f64 / 128.0);
            for c in 0..4 {
                assert!((0..=ONE).contains(&v[c]));
                let k = |i: usize| t[i][c] as f64 * 128.0;
                let exact = (1.0 - fb) * ((1.0 - fa) * k(0) + fa * k(1))
                    + fb * ((1.0 - fa) * k(2) + fa * k(3));
                assert!((v[c] as f64 - exact).abs() <= 0.5, "{t:?} {a} {b}");
            }
            let w = (next() % 256) as i32;
            let u = bilinear(t, b, a);
            for c in 0..4 {
                let m = levels(v[c], u[c], w);
                let exact = v[c] as f64 + (u[c] - v[c]) as f64 * w as f64 / 256.0;
                assert!((m as f64 - exact).abs() <= 0.5);
                assert!((0..=ONE).contains(&m));
            }
        }
        for k in 0..=255u8 {
            let t = [[k, 0, 0, 255]; 4];
            for (a, b) in [(0, 0), (64, 64), (127, 127)] {
                assert_eq!(
                    bilinear(t, a, b).map(value)[0].to_bits(),
                    (k as f32 / 255.0).to_bits()
                );
            }
            assert_eq!(value(nearest([k; 4])[0]), k as f32 / 255.0);
        }
        assert_eq!(value(ONE), 1.0);
    }

    #[test]
    fn coordinates_and_level_weights() {
        assert_eq!(coord(0.0), -64);
        assert_eq!(coord(f32::NAN), -64);
        // u = 0.5 is texel 0's centre: i0 = 0, weight 0.
        assert_eq!(split(coord((0.5f32 * 128.0).floor())), (0, 0));
        // u = 1.25: between texels 0 and 1, three quarters of the way.
        assert_eq!(split(coord((1.25f32 * 128.0).floor())), (0, 96));
        // u = 0.25: texel −1 (wrapped by the caller) and 0.
        assert_eq!(split(coord((0.25f32 * 128.0).floor())), (-1, 96));
        assert_eq!(level_weight(0.0), 0);
        assert_eq!(level_weight(0.5), 128);
        assert_eq!(level_weight(0.999_999), 255);
        assert_eq!(level_weight(f32::NAN), 0);
        assert_eq!(level_weight(-0.5), 0);
    }
}
