//! The per-fragment operations of the common states, decided once per
//! tile ([`QuickOps`]) and applied to a tile's buffers ([`QuickTarget`]):
//! ownership, scissor and depth test without alpha or stencil test, and
//! the colour write to one RGBA8 draw buffer with every channel written
//! and no logic op, single fragments, whole quads and strips. Every step
//! gives the bytes of the general functions of `fragment_ops` (tests
//! compare them).

use super::color::{blend_unit, clamp01, to_unorm8};
use super::depth::{blend_pair, depth_live_in, depth_quad};
#[cfg(target_arch = "x86_64")]
use super::wide::{write_strip_avx2, write_strip_avx512};
use crate::framebuffer::{ColorBuffer, DepthFormat, Framebuffer};
use crate::state::{Blend, BlendEquation, BlendFactor, CompareFunc, PipelineState, Rect};

/// The per-fragment operations of the common states, for a batch of
/// fragments at a time: the tests of [`tests`](fn@super::tests) when there is no alpha
/// test and no stencil test (only ownership, scissor and depth), and the
/// colour write of [`write_colors`](super::write_colors) when exactly one draw buffer is
/// written, it is RGBA8, every channel is written and there is no logic
/// op. Decided once per tile ([`QuickOps::new`]); each step gives the
/// bytes of the general function it replaces (the same operations in the
/// same order, with the state's choices made once instead of per
/// fragment).
#[derive(Clone, Copy, Debug)]
pub(crate) struct QuickOps {
    /// The depth function, when the depth test applies (enabled and a
    /// depth buffer present).
    depth: Option<CompareFunc>,
    depth_write: bool,
    scissor: Option<Rect>,
    /// The one colour write, when it qualifies: (colour buffer, fragment
    /// output, blend).
    color: Option<(usize, usize, QuickBlend)>,
}

/// Blending of [`QuickOps`]' colour write.
#[derive(Clone, Copy, Debug)]
pub(super) enum QuickBlend {
    /// No blending, or ONE / ZERO with FUNC_ADD (which gives the source).
    Off,
    /// SRC_ALPHA / ONE_MINUS_SRC_ALPHA with FUNC_ADD for colour and alpha.
    Over,
    /// Any other blend state, through [`blend_unit`].
    Other(Blend),
}

impl QuickOps {
    /// The quick operations for `state` on `fb` (a tile or the whole
    /// framebuffer), where `colors` lists the (draw buffer, fragment
    /// output) pairs the fragments carry. `None` when the tests do not
    /// qualify (alpha or stencil test).
    pub fn new(
        fb: &Framebuffer,
        state: &PipelineState,
        colors: &[(usize, usize)],
    ) -> Option<QuickOps> {
        // (Per-buffer blending and masks: the general path.)
        if state.alpha_test.is_some()
            || (state.stencil.is_some() && fb.stencil.is_some())
            || state.per_buffer.is_some()
        {
            return None;
        }
        let depth = state.depth_test.filter(|_| fb.depth.is_some());
        let mut targets = state
            .draw_buffers
            .iter()
            .enumerate()
            .filter_map(|(i, t)| Some((i, (*t)?)));
        let color = match (targets.next(), targets.next()) {
            (Some((output, target)), None)
                if state.logic_op.is_none()
                    && !state.blend.as_ref().is_some_and(Blend::uses_src1)
                    && state.color_mask == [true; 4]
                    && matches!(fb.color.get(target), Some(ColorBuffer::Rgba8(_))) =>
            {
                // The fragment carries this output (else it writes zeros:
                // the general path).
                colors
                    .iter()
                    .find(|&&(i, _)| i == output)
                    .map(|&(_, offset)| {
                        let blend = match &state.blend {
                            None => QuickBlend::Off,
                            Some(b) => {
                                use BlendFactor::{One, OneMinusSrcAlpha, SrcAlpha, Zero};
                                let add = b.equation_rgb == BlendEquation::Add
                                    && b.equation_alpha == BlendEquation::Add
                                    && b.src_rgb == b.src_alpha
                                    && b.dst_rgb == b.dst_alpha;
                                match (b.src_rgb, b.dst_rgb) {
                                    (One, Zero) if add => QuickBlend::Off,
                                    (SrcAlpha, OneMinusSrcAlpha) if add => QuickBlend::Over,
                                    _ => QuickBlend::Other(*b),
                                }
                            }
                        };
                        (target, offset, blend)
                    })
            }
            _ => None,
        };
        Some(QuickOps {
            depth,
            depth_write: state.depth_mask,
            scissor: state.scissor,
            color,
        })
    }

    /// The fragment output written by [`QuickTarget::write`], when the
    /// colour write qualifies.
    pub fn color_output(&self) -> Option<usize> {
        self.color.map(|c| c.1)
    }

    /// The buffers of `fb` these operations touch, borrowed for a run of
    /// fragments (whose window coordinates start at `origin` in `fb`).
    /// Inlined: the deferred passes take one per batch, and the struct
    /// returned through memory cost a store-forwarding stall each time.
    #[inline(always)]
    pub fn target<'f>(&self, fb: &'f mut Framebuffer, origin: (u32, u32)) -> QuickTarget<'f> {
        let (width, height) = (fb.width, fb.height);
        let color = match self.color {
            Some((target, _, blend)) => match fb.color.get_mut(target) {
                Some(ColorBuffer::Rgba8(v)) => Some((&mut v[..], blend)),
                _ => None,
            },
            None => None,
        };
        let depth = match (self.depth, fb.depth.as_deref_mut()) {
            (Some(func), Some(d)) => Some((func, d)),
            _ => None,
        };
        // A scissor box holding the whole target tests nothing.
        let scissor = self.scissor.filter(|sc| {
            let (x0, y0) = (origin.0 as i64, origin.1 as i64);
            !(sc.x as i64 <= x0
                && sc.y as i64 <= y0
                && x0 + width as i64 <= sc.x as i64 + sc.w as i64
                && y0 + height as i64 <= sc.y as i64 + sc.h as i64)
        });
        QuickTarget {
            origin,
            width,
            height,
            scissor,
            depth,
            depth_write: self.depth_write,
            depth_format: fb.depth_format,
            color,
            passed: &mut fb.samples_passed,
        }
    }
}

/// [`QuickOps`] over the buffers of one framebuffer (see
/// [`QuickOps::target`]).
pub(crate) struct QuickTarget<'f> {
    origin: (u32, u32),
    width: u32,
    height: u32,
    scissor: Option<Rect>,
    depth: Option<(CompareFunc, &'f mut [u32])>,
    depth_write: bool,
    depth_format: DepthFormat,
    color: Option<(&'f mut [[u8; 4]], QuickBlend)>,
    passed: &'f mut u64,
}

impl QuickTarget<'_> {
    /// [`tests`](fn@super::tests) for a fragment at window (x, y) with window z `z`
    /// (clamped to [0, 1]), under the qualifying state: the pixel index
    /// when it passes (the depth written, the fragment counted).
    #[inline(always)]
    pub fn test(&mut self, x: u32, y: u32, z: f32) -> Option<usize> {
        let lx = x.checked_sub(self.origin.0)?;
        let ly = y.checked_sub(self.origin.1)?;
        if lx >= self.width || ly >= self.height {
            return None;
        }
        if let Some(sc) = self.scissor {
            let (x, y) = (x as i64, y as i64);
            if x < sc.x as i64
                || y < sc.y as i64
                || x >= sc.x as i64 + sc.w as i64
                || y >= sc.y as i64 + sc.h as i64
            {
                return None;
            }
        }
        let index = ly as usize * self.width as usize + lx as usize;
        if let Some((func, d)) = &mut self.depth {
            if let Some(stored) = d.get_mut(index) {
                let zf = self.depth_format.to_fixed(z);
                if !func.test(zf, *stored) {
                    return None;
                }
                if self.depth_write {
                    *stored = zf;
                }
            }
        }
        *self.passed = self.passed.wrapping_add(1);
        Some(index)
    }

    /// The lanes of `live` of the quad at window (x, y) (pixel `k` at
    /// `(x + (k & 1), y + (k >> 1))`, fixed-point depth `zf[k]`) that the
    /// depth test does not reject against the stored depths: early
    /// rejection without a stencil test (`FragmentStage::early_rejects`),
    /// pixels outside the target kept.
    #[inline(always)]
    pub fn depth_live(&self, (x, y): (i64, i64), live: u8, zf: [u32; 4]) -> u8 {
        let Some((func, depth)) = &self.depth else {
            return live;
        };
        let at = (x - self.origin.0 as i64, y - self.origin.1 as i64);
        depth_live_in(*func, depth, (self.width, self.height), at, live, zf)
    }

    /// [`QuickTarget::test`] of the lanes `lanes` of the quad at window
    /// (x, y) (pixel `k` at `(x + (k & 1), y + (k >> 1))`, window z
    /// `z[k]`, whose [`DepthFormat::to_fixed`] is `zf[k]`): the lanes that pass,
    /// each pixel's index (meaningful for those), and whether the whole
    /// quad lies in the target (then every index is). The four pixels are
    /// distinct, so testing them together gives what testing them one
    /// after the other does. Lanes left of or below the window are not
    /// tested (as the fragment path skips them).
    #[inline(always)]
    pub fn test_quad(
        &mut self,
        at: (i64, i64),
        lanes: u8,
        z: [f32; 4],
        zf: [u32; 4],
    ) -> (u8, [usize; 4], bool) {
        self.test_quad_with(at, lanes, || z, zf)
    }

    /// [`QuickTarget::test_quad`] with the window z computed by `z` only
    /// when the lanes go one by one (a quad inside the target needs only
    /// `zf`).
    #[inline(always)]
    pub fn test_quad_with(
        &mut self,
        (x, y): (i64, i64),
        lanes: u8,
        z: impl FnOnce() -> [f32; 4],
        zf: [u32; 4],
    ) -> (u8, [usize; 4], bool) {
        let (lx, ly) = (x - self.origin.0 as i64, y - self.origin.1 as i64);
        let (w, h) = (self.width as i64, self.height as i64);
        let inside = self.scissor.is_none() && lx >= 0 && ly >= 0 && lx + 1 < w && ly + 1 < h;
        // (Meaningful only inside, where it cannot overflow.)
        let i0 = if inside { (ly * w + lx) as usize } else { 0 };
        let index = [i0, i0 + 1, i0 + w as usize, i0 + w as usize + 1];
        // Every buffer holds the whole tile (else the lanes go one by
        // one, as `test` skips the depth test of pixels it lacks).
        let fits = inside
            && self.depth.as_ref().is_none_or(|(_, d)| index[3] < d.len())
            && self.color.as_ref().is_none_or(|(v, _)| index[3] < v.len());
        if fits {
            let mut pass = lanes & 0xf;
            if let Some((func, d)) = &mut self.depth {
                let write = self.depth_write;
                pass = depth_quad(*func, d, (index[0], index[2]), zf, pass, write);
            }
            *self.passed = self.passed.wrapping_add(u64::from(pass.count_ones()));
            return (pass, index, true);
        }
        let mut pass = 0u8;
        let mut index = [0usize; 4];
        let z = z();
        for k in 0..4 {
            let (px, py) = (x + (k as i64 & 1), y + (k as i64 >> 1));
            if lanes & (1 << k) == 0 || px < 0 || py < 0 {
                continue;
            }
            if let Some(i) = self.test(px as u32, py as u32, z[k]) {
                pass |= 1 << k;
                index[k] = i;
            }
        }
        (pass, index, false)
    }

    /// The colour write of a strip's 16 fragments, all passing (lane
    /// `4q + k`: pixel `(x + 2q + (k & 1), y + (k >> 1))`, colour
    /// `rgba[c][lane]`), on its two rows of eight pixels at once in
    /// AVX-512 or AVX2 registers: the bytes [`QuickTarget::write`] gives
    /// each fragment (the same operations per pixel, a pixel per element).
    /// False, with nothing done, unless `level` is one of those, the strip lies
    /// inside the target and nothing but the colour write applies (no
    /// depth test, no scissor; no blending or SRC_ALPHA /
    /// ONE_MINUS_SRC_ALPHA).
    #[inline(always)]
    pub fn write_strip(
        &mut self,
        level: crate::simd::Level,
        (x, y): (i64, i64),
        rgba: [&[f32; 16]; 4],
    ) -> bool {
        if !level.supported()
            || level == crate::simd::Level::Portable
            || self.depth.is_some()
            || self.scissor.is_some()
        {
            return false;
        }
        let Some((v, blend)) = &mut self.color else {
            return false;
        };
        let over = match blend {
            QuickBlend::Off => false,
            QuickBlend::Over => true,
            QuickBlend::Other(_) => return false,
        };
        let (lx, ly) = (x - self.origin.0 as i64, y - self.origin.1 as i64);
        let w = self.width as i64;
        if lx < 0 || ly < 0 || lx + 8 > w || ly + 2 > self.height as i64 {
            return false;
        }
        let i0 = (ly * w + lx) as usize;
        let Some(rows) = v.get_mut(i0..i0 + w as usize + 8) else {
            return false;
        };
        #[cfg(target_arch = "x86_64")]
        {
            // SAFETY: the CPU runs `level` (checked above); `rows` holds
            // both rows of eight pixels.
            unsafe {
                if level == crate::simd::Level::Avx512 {
                    write_strip_avx512(rows, w as usize, rgba, over)
                } else {
                    write_strip_avx2(rows, w as usize, rgba, over)
                }
            }
            *self.passed = self.passed.wrapping_add(16);
            true
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let _ = (rows, rgba, over);
            false
        }
    }

    /// [`QuickTarget::write_rgba8`] of `c[k]` at `index[k]` for the lanes
    /// `pass`, after [`QuickTarget::test_quad`] found the quad inside
    /// (`inside`: then `index` holds two rows of two adjacent pixels, as
    /// `test_quad` returns it; else one lane at a time).
    #[inline(always)]
    pub fn write_rgba8_quad(&mut self, pass: u8, index: [usize; 4], inside: bool, c: [[u8; 4]; 4]) {
        let Some((v, _)) = &mut self.color else {
            return;
        };
        if inside && index[3] < v.len() {
            // In bounds: index[3] is the largest, and the quad's rows are
            // (index[0], index[0] + 1) and (index[2], index[2] + 1). Every
            // pixel stored, the passing ones' colour selected without
            // branches (coverage patterns do not predict): a row's two
            // pixels at once.
            for (r, &at) in [index[0], index[2]].iter().enumerate() {
                if let Some([p0, p1]) = v.get_mut(at..at + 2) {
                    [*p0, *p1] = blend_pair([*p0, *p1], [c[2 * r], c[2 * r + 1]], pass >> (2 * r));
                }
            }
            return;
        }
        for k in 0..4 {
            if pass & (1 << k) != 0 {
                self.write_rgba8(index[k], c[k]);
            }
        }
    }

    /// Whether [`QuickTarget::write`] stores the clamped source converted
    /// to unorm8 (no blending): then [`QuickTarget::write_rgba8`] of
    /// [`unorm8_lanes`](super::color::unorm8_lanes) writes the same bytes.
    pub fn opaque(&self) -> bool {
        matches!(self.color, Some((_, QuickBlend::Off)))
    }

    /// Stores `c` at pixel `index` of the colour buffer (see
    /// [`QuickTarget::opaque`]).
    #[inline(always)]
    pub fn write_rgba8(&mut self, index: usize, c: [u8; 4]) {
        if let Some(p) = self.color.as_mut().and_then(|(v, _)| v.get_mut(index)) {
            *p = c;
        }
    }

    /// [`write_colors`](super::write_colors) of colour `src` (the qualifying output) to pixel
    /// `index`; nothing when the colour write does not qualify.
    #[inline(always)]
    pub fn write(&mut self, index: usize, src: [f32; 4]) {
        let Some((v, blend)) = &mut self.color else {
            return;
        };
        let Some(p) = v.get_mut(index) else { return };
        #[cfg(target_arch = "x86_64")]
        if let QuickBlend::Off | QuickBlend::Over = blend {
            let over = matches!(blend, QuickBlend::Over);
            // SAFETY: SSE2 is part of the x86-64 baseline.
            *p = unsafe { write_sse2(src, *p, over) };
            return;
        }
        *p = match blend {
            QuickBlend::Off => write_scalar(src, *p, false),
            QuickBlend::Over => write_scalar(src, *p, true),
            QuickBlend::Other(b) => {
                let d = p.map(|b| b as f32 / 255.0);
                to_unorm8(blend_unit(b, src.map(clamp01), d))
            }
        };
    }
}

/// [`QuickTarget::write`] of `src` over the pixel `dst` without blending
/// (`over` false) or with [`QuickBlend::Over`], one channel at a time.
#[inline(always)]
pub(super) fn write_scalar(src: [f32; 4], dst: [u8; 4], over: bool) -> [u8; 4] {
    let s = src.map(clamp01);
    if !over {
        return to_unorm8(s);
    }
    let d = dst.map(|b| b as f32 / 255.0);
    let (fs, fd) = (s[3], 1.0 - s[3]);
    to_unorm8([
        s[0] * fs + d[0] * fd,
        s[1] * fs + d[1] * fd,
        s[2] * fs + d[2] * fd,
        s[3] * fs + d[3] * fd,
    ])
}

/// [`QuickTarget::write`] of `src` over the pixel `dst` without blending
/// (`over` false) or with [`QuickBlend::Over`], the four channels in one
/// SSE2 register: the same operations in the same order as
/// [`write_scalar`] (`clamp01`, `b / 255`, `s·fs + d·fd` and
/// [`to_unorm8`]), so the same bytes; a test compares the two.
///
/// # Safety
/// The CPU must support SSE2 (every x86-64 CPU does).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) unsafe fn write_sse2(src: [f32; 4], dst: [u8; 4], over: bool) -> [u8; 4] {
    use std::arch::x86_64::*;
    // SAFETY (of the intrinsics): SSE2 (the caller's contract); the load
    // is of the four floats of `src`.
    unsafe {
        let zero = _mm_setzero_ps();
        let one = _mm_set1_ps(1.0);
        // `clamp01`: `max` gives its second operand for NaN and for
        // −0 (equal to +0), so both become +0; `min` keeps x < 1.
        let s = _mm_min_ps(_mm_max_ps(_mm_loadu_ps(src.as_ptr()), zero), one);
        let y = if over {
            let zi = _mm_setzero_si128();
            let bytes = _mm_cvtsi32_si128(i32::from_le_bytes(dst));
            let words = _mm_unpacklo_epi16(_mm_unpacklo_epi8(bytes, zi), zi);
            let d = _mm_div_ps(_mm_cvtepi32_ps(words), _mm_set1_ps(255.0));
            let fs = _mm_shuffle_ps::<0xff>(s, s);
            let fd = _mm_sub_ps(one, fs);
            _mm_add_ps(_mm_mul_ps(s, fs), _mm_mul_ps(d, fd))
        } else {
            s
        };
        // `to_unorm8`: NaN and values ≤ 0 give 0 (`max`'s second operand
        // for NaN; ±0 both give 0.5, truncated to 0), then the scale.
        let y = _mm_min_ps(_mm_max_ps(y, zero), one);
        let y = _mm_add_ps(_mm_mul_ps(y, _mm_set1_ps(255.0)), _mm_set1_ps(0.5));
        // In [0.5, 255.5]: the truncations fit, and the packs (to i16,
        // then to u8 with saturation) keep the values.
        let k = _mm_cvttps_epi32(y);
        let k = _mm_packus_epi16(_mm_packs_epi32(k, k), k);
        _mm_cvtsi128_si32(k).to_le_bytes()
    }
}
