//! The depth test of a 2×2 quad's four pixels at once (its stored
//! depths two pairs of neighbours in memory): the pixels that pass, the
//! passing depths written without branching on coverage; on x86-64 in
//! SSE2 registers, elsewhere in scalar code, with the same results as
//! the per-fragment test (tests compare them).

use crate::state::CompareFunc;

/// The depth test of the lanes `lanes` of a quad whose stored depths are
/// the pixel pairs `d[r0..r0 + 2]` and `d[r1..r1 + 2]` (its rows), against
/// its fixed-point depths `zf`: the lanes that pass, whose new depths are
/// stored when `write`. (Other pixels are stored unchanged: no branch on
/// coverage patterns, which do not predict.) On x86-64 in SSE2 registers
/// (integer operations: the same results).
#[inline(always)]
pub(super) fn depth_quad(
    func: CompareFunc,
    d: &mut [u32],
    (r0, r1): (usize, usize),
    zf: [u32; 4],
    lanes: u8,
    write: bool,
) -> u8 {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::*;
        let Some((stored, pass)) = depth_quad_mask(func, d, (r0, r1), zf) else {
            return 0;
        };
        let pass = pass & lanes & 0xf;
        if write {
            // SAFETY: SSE2 is part of the x86-64 baseline; the stores are
            // of the two pairs `depth_quad_mask` found in bounds.
            unsafe {
                let new = _mm_loadu_si128(zf.as_ptr().cast());
                // Lane k all ones when bit k of `pass` is set.
                let lane_bits = _mm_setr_epi32(1, 2, 4, 8);
                let bits = _mm_and_si128(_mm_set1_epi32(i32::from(pass)), lane_bits);
                let on = _mm_cmpeq_epi32(bits, lane_bits);
                let v = _mm_or_si128(_mm_and_si128(on, new), _mm_andnot_si128(on, stored));
                _mm_storel_epi64(d.as_mut_ptr().add(r0).cast(), v);
                _mm_storel_epi64(d.as_mut_ptr().add(r1).cast(), _mm_unpackhi_epi64(v, v));
            }
        }
        pass
    }
    #[cfg(not(target_arch = "x86_64"))]
    depth_quad_portable(func, d, (r0, r1), zf, lanes, write)
}

/// The stored depths of a quad (rows `d[r0..r0 + 2]`, `d[r1..r1 + 2]`)
/// in one register and the pixels `func` passes against `zf` (bits 0–3);
/// `None` when a row is out of `d`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn depth_quad_mask(
    func: CompareFunc,
    d: &[u32],
    (r0, r1): (usize, usize),
    zf: [u32; 4],
) -> Option<(std::arch::x86_64::__m128i, u8)> {
    use std::arch::x86_64::*;
    d.get(r0..r0 + 2)?;
    d.get(r1..r1 + 2)?;
    // SAFETY: SSE2 is part of the x86-64 baseline; the loads are of the
    // two pairs just found in bounds.
    unsafe {
        let row = |r: usize| _mm_loadl_epi64(d.as_ptr().add(r).cast());
        let stored = _mm_unpacklo_epi64(row(r0), row(r1));
        let new = _mm_loadu_si128(zf.as_ptr().cast());
        // Unsigned order as signed order of the values less 2^31.
        let bias = _mm_set1_epi32(i32::MIN);
        let (a, b) = (_mm_xor_si128(new, bias), _mm_xor_si128(stored, bias));
        let ones = _mm_set1_epi32(-1);
        let m = match func {
            CompareFunc::Never => _mm_setzero_si128(),
            CompareFunc::Less => _mm_cmplt_epi32(a, b),
            CompareFunc::Equal => _mm_cmpeq_epi32(a, b),
            CompareFunc::LessEqual => _mm_xor_si128(_mm_cmpgt_epi32(a, b), ones),
            CompareFunc::Greater => _mm_cmpgt_epi32(a, b),
            CompareFunc::NotEqual => _mm_xor_si128(_mm_cmpeq_epi32(a, b), ones),
            CompareFunc::GreaterEqual => _mm_xor_si128(_mm_cmplt_epi32(a, b), ones),
            CompareFunc::Always => ones,
        };
        Some((stored, _mm_movemask_ps(_mm_castsi128_ps(m)) as u8))
    }
}

/// The stored depths of a quad whose rows are the pixel pairs
/// `d[r0..r0 + 2]` and `d[r1..r1 + 2]` (pixel order); `None` when a row
/// is out of `d`.
#[cfg_attr(target_arch = "x86_64", allow(dead_code))]
#[inline(always)]
fn quad_stored(d: &[u32], (r0, r1): (usize, usize)) -> Option<[u32; 4]> {
    match (d.get(r0..r0 + 2), d.get(r1..r1 + 2)) {
        (Some(&[s0, s1]), Some(&[s2, s3])) => Some([s0, s1, s2, s3]),
        _ => None,
    }
}

/// [`depth_quad`] without vector registers (other targets; the tests
/// compare the two).
#[cfg_attr(target_arch = "x86_64", allow(dead_code))]
pub(super) fn depth_quad_portable(
    func: CompareFunc,
    d: &mut [u32],
    (r0, r1): (usize, usize),
    zf: [u32; 4],
    lanes: u8,
    write: bool,
) -> u8 {
    let Some(stored) = quad_stored(d, (r0, r1)) else {
        return 0;
    };
    let pass = lanes & 0xf & depth_pass_mask(func, zf, stored);
    if write {
        let zf = zf.map(u32::to_ne_bytes);
        let stored = stored.map(u32::to_ne_bytes);
        for (r, at) in [r0, r1].into_iter().enumerate() {
            if let Some([d0, d1]) = d.get_mut(at..at + 2) {
                let [n0, n1] = blend_pair(
                    [stored[2 * r], stored[2 * r + 1]],
                    [zf[2 * r], zf[2 * r + 1]],
                    pass >> (2 * r),
                );
                [*d0, *d1] = [u32::from_ne_bytes(n0), u32::from_ne_bytes(n1)];
            }
        }
    }
    pass
}

/// The lanes of `live` of the quad at (lx, ly) of a `w`×`h` depth buffer
/// `depth` (pixel `k` at `(lx + (k & 1), ly + (k >> 1))`, fixed-point
/// depth `zf[k]`) that `func` does not reject against the stored depths;
/// pixels outside the buffer are kept. The whole quad inside: its four
/// depths at once.
#[inline(always)]
pub(crate) fn depth_live_in(
    func: CompareFunc,
    depth: &[u32],
    (w, h): (u32, u32),
    (lx, ly): (i64, i64),
    live: u8,
    zf: [u32; 4],
) -> u8 {
    let (w, h) = (w as i64, h as i64);
    if lx >= 0 && ly >= 0 && lx + 1 < w && ly + 1 < h {
        let i0 = (ly * w + lx) as usize;
        let rows = (i0, i0 + w as usize);
        #[cfg(target_arch = "x86_64")]
        if let Some((_, pass)) = depth_quad_mask(func, depth, rows, zf) {
            return live & pass;
        }
        #[cfg(not(target_arch = "x86_64"))]
        if let Some(stored) = quad_stored(depth, rows) {
            return live & depth_pass_mask(func, zf, stored);
        }
    }
    let mut live = live;
    for (k, &zf) in zf.iter().enumerate() {
        let (lx, ly) = (lx + (k as i64 & 1), ly + (k as i64 >> 1));
        if live & (1 << k) == 0 || lx < 0 || ly < 0 || lx >= w || ly >= h {
            continue;
        }
        let stored = depth.get((ly * w + lx) as usize).copied().unwrap_or(0);
        if !func.test(zf, stored) {
            live &= !(1 << k);
        }
    }
    live
}

/// The lanes `k` where `func.test(zf[k], stored[k])`, the comparison
/// chosen once for the four.
#[inline(always)]
pub(crate) fn depth_pass_mask(func: CompareFunc, zf: [u32; 4], stored: [u32; 4]) -> u8 {
    let m =
        |f: fn(u32, u32) -> bool| (0..4).fold(0u8, |m, k| m | (u8::from(f(zf[k], stored[k])) << k));
    match func {
        CompareFunc::Never => 0,
        CompareFunc::Less => m(|a, b| a < b),
        CompareFunc::Equal => m(|a, b| a == b),
        CompareFunc::LessEqual => m(|a, b| a <= b),
        CompareFunc::Greater => m(|a, b| a > b),
        CompareFunc::NotEqual => m(|a, b| a != b),
        CompareFunc::GreaterEqual => m(|a, b| a >= b),
        CompareFunc::Always => 0xf,
    }
}

/// Two adjacent 4-byte pixels: `new[k]` where bit `k` of `bits` is set,
/// else `old[k]`, selected with one 64-bit mask (no branch, which the
/// compiler makes of a per-pixel select when it can sink the load of
/// `old` into it).
#[inline(always)]
pub(super) fn blend_pair(old: [[u8; 4]; 2], new: [[u8; 4]; 2], bits: u8) -> [[u8; 4]; 2] {
    let wide = |p: [[u8; 4]; 2]| {
        let [[a, b, c, d], [e, f, g, h]] = p;
        u64::from_ne_bytes([a, b, c, d, e, f, g, h])
    };
    let lane = |k: u8| 0u32.wrapping_sub(u32::from((bits >> k) & 1)).to_ne_bytes();
    let m = wide([lane(0), lane(1)]);
    let [a, b, c, d, e, f, g, h] = ((wide(new) & m) | (wide(old) & !m)).to_ne_bytes();
    [[a, b, c, d], [e, f, g, h]]
}

/// Depth test helper used by tests: does `z` pass `func` against `stored`?
#[cfg(test)]
pub(super) fn depth_passes(func: crate::state::CompareFunc, z: f32, stored: f32) -> bool {
    use crate::framebuffer::depth_to_fixed;
    func.test(depth_to_fixed(z), depth_to_fixed(stored))
}
