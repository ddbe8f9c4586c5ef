//! A batch's 16 colours in AVX2 or AVX-512 registers (over
//! `exec::lanes16::Lanes16`): the conversion to unorm8 of a batch
//! ([`unorm8_batch`]) and the colour write of a strip's two rows of
//! eight pixels ([`super::QuickTarget::write_strip`]), with the
//! operations of the per-pixel code, so the same bytes (tests compare
//! them).

#[cfg(target_arch = "x86_64")]
use exec::lanes16::{Lanes16, X256, X512};

use super::color::unorm8_lanes;

/// [`QuickTarget::write_strip`](super::QuickTarget::write_strip)'s pixels: rows `rows[..8]` and
/// `rows[w..w + 8]`, pixel i (row i / 8, column i % 8) from the fragment
/// of lane 4(col / 2) + 2 row + col % 2, with [`write_sse2`](super::quick::write_sse2)'s operations
/// (the clamps as `max(x, 0)` then `min(_, 1)`, the stored value over
/// 255 by division, separate products and sums), in `V`'s registers.
///
/// # Safety
/// The CPU must have `V`'s instruction set and this must be inlined into
/// code compiled for it; `rows` must hold `w + 8` pixels, `w ≥ 8`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn write_strip_in<V: Lanes16>(
    rows: &mut [[u8; 4]],
    w: usize,
    rgba: [&[f32; 16]; 4],
    over: bool,
) {
    debug_assert!(w >= 8 && rows.len() >= w + 8);
    // SAFETY (of the loads and stores): eight pixels (32 bytes) at
    // `rows[0]` and at `rows[w]`, inside `rows` (the caller's contract);
    // 16 floats of each `rgba[c]`.
    unsafe {
        let base = rows.as_mut_ptr().cast::<u32>();
        let dst = V::load_rows(base, base.add(w));
        let (zero, one) = (V::zero(), V::splat(1.0));
        let mut s = [zero; 4];
        for (sc, src) in s.iter_mut().zip(rgba) {
            *sc = V::min(V::max(V::quads_to_rows(V::load(src)), zero), one);
        }
        let mut out = s;
        if over {
            let fs = s[3];
            let fd = V::sub(one, fs);
            let k255 = V::splat(255.0);
            for (c, oc) in out.iter_mut().enumerate() {
                let d = V::div(V::to_f(V::byte(dst, c)), k255);
                *oc = V::add(V::mul(*oc, fs), V::mul(d, fd));
            }
        }
        V::store_rows(base, base.add(w), rgba8_words::<V>(out));
    }
}

/// `to_unorm8` of each lane's RGBA (clamped to [0, 1], NaN as 0), as one
/// little-endian RGBA8 word per lane.
///
/// # Safety
/// As for the [`Lanes16`] methods.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn rgba8_words<V: Lanes16>(rgba: [V::F; 4]) -> V::I {
    unsafe {
        let (zero, one) = (V::zero(), V::splat(1.0));
        let (k255, half) = (V::splat(255.0), V::splat(0.5));
        let mut word = V::splat_i(0);
        for (c, x) in rgba.iter().enumerate() {
            let clamped = V::min(V::max(*x, zero), one);
            // In [0.5, 255.5]: the truncation fits.
            let k = V::trunc_i(V::add(V::mul(clamped, k255), half));
            word = V::or_i(word, V::shl_bytes(k, c));
        }
        word
    }
}

/// [`unorm8_lanes`] of 16 lanes in `V`'s registers (the same bytes).
///
/// # Safety
/// As for the [`Lanes16`] methods.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn unorm8_lanes_in<V: Lanes16>(rgba: [&[f32; 16]; 4]) -> [[u8; 4]; 16] {
    unsafe {
        let mut words = [0i32; 16];
        let x = [
            V::load(rgba[0]),
            V::load(rgba[1]),
            V::load(rgba[2]),
            V::load(rgba[3]),
        ];
        V::store_i(&mut words, rgba8_words::<V>(x));
        let mut out = [[0u8; 4]; 16];
        for (o, w) in out.iter_mut().zip(words) {
            *o = w.to_le_bytes();
        }
        out
    }
}

exec::multiversion! {
    /// [`unorm8_lanes`] of a batch's 16 lanes at `level` (AVX2, AVX-512:
    /// [`unorm8_lanes_in`] in their registers): the same bytes (the clamp
    /// and conversion are the same operations).
    pub(crate) fn unorm8_batch(
        #[level] level: crate::simd::Level,
        rgba: [&[f32; 16]; 4],
    ) -> [[u8; 4]; 16];
    copies = [unorm8_portable, unorm8_lanes_avx2, unorm8_lanes_avx512],
    body = {
        portable: unorm8_lanes(rgba),
        // SAFETY: compiled for the level's registers.
        avx2: unsafe { unorm8_lanes_in::<X256>(rgba) },
        // SAFETY: likewise.
        avx512: unsafe { unorm8_lanes_in::<X512>(rgba) },
    }
}

exec::compiled_for!(
    avx512,
    /// [`write_strip_in`] in AVX-512 registers.
    ///
    /// # Safety
    /// The CPU must run `Level::Avx512`; `rows` as for [`write_strip_in`].
    pub(super) unsafe fn write_strip_avx512(
        rows: &mut [[u8; 4]],
        w: usize,
        rgba: [&[f32; 16]; 4],
        over: bool,
    ) {
        // SAFETY: the caller's contract.
        unsafe { write_strip_in::<X512>(rows, w, rgba, over) }
    }
);

exec::compiled_for!(
    avx2,
    /// [`write_strip_in`] in AVX2 registers.
    ///
    /// # Safety
    /// The CPU must run `Level::Avx2`; `rows` as for [`write_strip_in`].
    pub(super) unsafe fn write_strip_avx2(
        rows: &mut [[u8; 4]],
        w: usize,
        rgba: [&[f32; 16]; 4],
        over: bool,
    ) {
        // SAFETY: the caller's contract.
        unsafe { write_strip_in::<X256>(rows, w, rgba, over) }
    }
);
