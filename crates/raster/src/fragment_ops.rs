//! Per-fragment operations in GL 2.1 §4.1 order: pixel ownership, scissor,
//! alpha test, stencil test, depth test, blending, (dithering: off),
//! logic op, then the masked write to each draw buffer.

use crate::framebuffer::{depth_to_fixed, float_to_unorm8, ColorBuffer};
use crate::framebuffer::{Framebuffer, MAX_DRAW_BUFFERS};
use crate::state::{
    Blend, BlendEquation, BlendFactor, CompareFunc, PipelineState, Rect, StencilFace, StencilOp,
};
#[cfg(target_arch = "x86_64")]
use exec::lanes16::{Lanes16, X256, X512};

/// One shaded fragment ready for the per-fragment operations.
pub(crate) struct Fragment {
    pub x: u32,
    pub y: u32,
    /// Window z, already clamped to [0, 1].
    pub z: f32,
    /// Selects the back stencil state (polygons only).
    pub back_facing: bool,
    /// Color of fragment output `i` (gl_FragData[i], or gl_FragColor for
    /// every `i`).
    pub colors: [[f32; 4]; MAX_DRAW_BUFFERS],
}

fn stencil_face(state: &PipelineState, back: bool) -> Option<StencilFace> {
    state.stencil.map(|s| if back { s.back } else { s.front })
}

/// Whether the stencil test passes for a fragment over `stored` (`None`
/// when there is no stencil test).
pub(crate) fn stencil_passes(
    state: &PipelineState,
    back: bool,
    stored: Option<u8>,
) -> Option<bool> {
    let face = stencil_face(state, back)?;
    Some(stencil_test(&face, stored?))
}

fn stencil_ref(face: &StencilFace) -> u8 {
    face.reference.clamp(0, 255) as u8
}

/// GL 2.1 §4.1.5: `(ref & mask) func (stored & mask)`.
pub(crate) fn stencil_test(face: &StencilFace, stored: u8) -> bool {
    let m = face.value_mask as u8;
    face.func.test(stencil_ref(face) & m, stored & m)
}

/// The stencil value after `op` (before the write mask).
pub(crate) fn stencil_op(op: StencilOp, stored: u8, reference: u8) -> u8 {
    match op {
        StencilOp::Keep => stored,
        StencilOp::Zero => 0,
        StencilOp::Replace => reference,
        StencilOp::Incr => stored.saturating_add(1),
        StencilOp::Decr => stored.saturating_sub(1),
        StencilOp::Invert => !stored,
        StencilOp::IncrWrap => stored.wrapping_add(1),
        StencilOp::DecrWrap => stored.wrapping_sub(1),
    }
}

fn op_has_effect(face: &StencilFace, op: StencilOp) -> bool {
    op != StencilOp::Keep && face.write_mask as u8 != 0
}

/// For early depth testing: true when the fragment at `index` with fixed
/// depth `zf` will certainly be dropped by the stencil or depth test
/// *without any side effect*, whatever the fragment shader produces
/// (the shader does not write gl_FragDepth). Such lanes need no shading;
/// everything else goes through [`process`] after shading, so results are
/// identical to late testing.
pub(crate) fn early_reject(
    fb: &Framebuffer,
    state: &PipelineState,
    index: usize,
    zf: u32,
    back: bool,
) -> bool {
    let face = match (stencil_face(state, back), fb.stencil.as_ref()) {
        (Some(face), Some(s)) => {
            let stored = s.get(index).copied().unwrap_or(0);
            if !stencil_test(&face, stored) {
                return !op_has_effect(&face, face.fail);
            }
            Some(face)
        }
        _ => None,
    };
    if let (Some(func), Some(d)) = (state.depth_test, fb.depth.as_ref()) {
        let stored = d.get(index).copied().unwrap_or(0);
        if !func.test(zf, stored) {
            return !matches!(face, Some(f) if op_has_effect(&f, f.depth_fail));
        }
    }
    false
}

/// Runs the per-fragment operations for one fragment and writes the
/// result. `fb` holds the pixels from `origin` on (a tile of the whole
/// framebuffer, or all of it with origin (0, 0)); the fragment's x, y are
/// window coordinates. Fragments outside `fb` or the scissor box are dropped.
/// Returns whether the fragment passed every test (its colour was written,
/// through the masks).
pub(crate) fn process(
    fb: &mut Framebuffer,
    origin: (u32, u32),
    state: &PipelineState,
    frag: &Fragment,
) -> bool {
    match tests(fb, origin, state, frag) {
        Some(index) => {
            write_colors(fb, index, state, &frag.colors);
            true
        }
        None => false,
    }
}

/// The per-fragment operations up to and including the depth test
/// (ownership, scissor, alpha, stencil, depth), with their stencil and
/// depth writes. Returns the pixel index in `fb` when the fragment passes
/// and its colors are to be written.
pub(crate) fn tests(
    fb: &mut Framebuffer,
    origin: (u32, u32),
    state: &PipelineState,
    frag: &Fragment,
) -> Option<usize> {
    let lx = frag.x.checked_sub(origin.0)?;
    let ly = frag.y.checked_sub(origin.1)?;
    if lx >= fb.width || ly >= fb.height {
        return None;
    }
    if let Some(sc) = state.scissor {
        let (x, y) = (frag.x as i64, frag.y as i64);
        if x < sc.x as i64
            || y < sc.y as i64
            || x >= sc.x as i64 + sc.w as i64
            || y >= sc.y as i64 + sc.h as i64
        {
            return None;
        }
    }
    let index = ly as usize * fb.width as usize + lx as usize;
    let clamp = state.clamp_fragment_color;

    // §4.1.4 alpha test on fragment output 0's alpha.
    if let Some((func, reference)) = state.alpha_test {
        let a = frag.colors[0][3];
        let a = if clamp { clamp01(a) } else { a };
        if !func.test(a, clamp01(reference)) {
            return None;
        }
    }

    // §4.1.5 stencil test and §4.1.6 depth test.
    let face = match fb.stencil {
        Some(_) => stencil_face(state, frag.back_facing),
        None => None,
    };
    if face.is_none() && (state.depth_test.is_none() || fb.depth.is_none()) {
        // Neither test applies: the fragment passes (the common case of
        // 2D and blended drawing, without the tests' loads).
        fb.samples_passed = fb.samples_passed.wrapping_add(1);
        return Some(index);
    }
    let stored_stencil = fb
        .stencil
        .as_ref()
        .and_then(|s| s.get(index))
        .copied()
        .unwrap_or(0);
    if let Some(face) = face {
        if !stencil_test(&face, stored_stencil) {
            write_stencil(fb, index, &face, face.fail, stored_stencil);
            return None;
        }
    }
    let depth_pass = match (state.depth_test, fb.depth.as_mut()) {
        (Some(func), Some(d)) => match d.get_mut(index) {
            Some(stored) => {
                let zf = depth_to_fixed(frag.z);
                let pass = func.test(zf, *stored);
                if pass && state.depth_mask {
                    *stored = zf;
                }
                pass
            }
            None => true,
        },
        _ => true,
    };
    if let Some(face) = face {
        let op = if depth_pass {
            face.depth_pass
        } else {
            face.depth_fail
        };
        write_stencil(fb, index, &face, op, stored_stencil);
    }
    if depth_pass {
        fb.samples_passed = fb.samples_passed.wrapping_add(1);
    }
    depth_pass.then_some(index)
}

/// §4.1.8 blending, §4.1.10 logic op, §4.2.2 masks: writes a fragment's
/// colors (that passed [`tests`]) to pixel `index` of every draw buffer.
pub(crate) fn write_colors(
    fb: &mut Framebuffer,
    index: usize,
    state: &PipelineState,
    colors: &[[f32; 4]; MAX_DRAW_BUFFERS],
) {
    for (output, target) in state.draw_buffers.iter().enumerate() {
        let Some(target) = *target else { continue };
        let Some(src) = colors.get(output) else {
            continue;
        };
        let Some(buf) = fb.color.get_mut(target) else {
            continue;
        };
        write_color(buf, index, state, *src);
    }
}

/// The per-fragment operations of the common states, for a batch of
/// fragments at a time: the tests of [`tests`] when there is no alpha
/// test and no stencil test (only ownership, scissor and depth), and the
/// colour write of [`write_colors`] when exactly one draw buffer is
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
enum QuickBlend {
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
        if state.alpha_test.is_some() || (state.stencil.is_some() && fb.stencil.is_some()) {
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
    color: Option<(&'f mut [[u8; 4]], QuickBlend)>,
    passed: &'f mut u64,
}

impl QuickTarget<'_> {
    /// [`tests`] for a fragment at window (x, y) with window z `z`
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
                let zf = depth_to_fixed(z);
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
    /// `z[k]`, whose [`depth_to_fixed`] is `zf[k]`): the lanes that pass,
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
    /// False, with nothing done, unless `isa` is one of those, the strip lies
    /// inside the target and nothing but the colour write applies (no
    /// depth test, no scissor; no blending or SRC_ALPHA /
    /// ONE_MINUS_SRC_ALPHA).
    #[inline(always)]
    pub fn write_strip(
        &mut self,
        isa: crate::simd::Isa,
        (x, y): (i64, i64),
        rgba: [&[f32; 16]; 4],
    ) -> bool {
        if isa == crate::simd::Isa::Base || self.depth.is_some() || self.scissor.is_some() {
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
            // SAFETY: `isa` is only Avx512 (Avx2) when the CPU has those
            // features (`simd::detect`); `rows` holds both rows of eight
            // pixels.
            unsafe {
                if isa == crate::simd::Isa::Avx512 {
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
    /// [`unorm8_lanes`] writes the same bytes.
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

    /// [`write_colors`] of colour `src` (the qualifying output) to pixel
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
fn write_scalar(src: [f32; 4], dst: [u8; 4], over: bool) -> [u8; 4] {
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
unsafe fn write_sse2(src: [f32; 4], dst: [u8; 4], over: bool) -> [u8; 4] {
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

/// [`QuickTarget::write_strip`]'s pixels: rows `rows[..8]` and
/// `rows[w..w + 8]`, pixel i (row i / 8, column i % 8) from the fragment
/// of lane 4(col / 2) + 2 row + col % 2, with [`write_sse2`]'s operations
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

/// [`unorm8_lanes_in`] compiled for AVX-512 (as `write_strip_avx512`).
///
/// # Safety
/// The CPU must have AVX2 and AVX-512 F, DQ and VL.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512dq,avx512vl,avx2")]
unsafe fn unorm8_lanes_avx512(rgba: [&[f32; 16]; 4]) -> [[u8; 4]; 16] {
    // SAFETY: the caller's contract.
    unsafe { unorm8_lanes_in::<X512>(rgba) }
}

/// [`unorm8_lanes_in`] compiled for AVX2.
///
/// # Safety
/// The CPU must have AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn unorm8_lanes_avx2(rgba: [&[f32; 16]; 4]) -> [[u8; 4]; 16] {
    // SAFETY: the caller's contract.
    unsafe { unorm8_lanes_in::<X256>(rgba) }
}

/// [`unorm8_lanes`] of a batch's 16 lanes in `isa`'s registers: the same
/// bytes (the clamp and conversion are the same operations).
pub(crate) fn unorm8_batch(isa: crate::simd::Isa, rgba: [&[f32; 16]; 4]) -> [[u8; 4]; 16] {
    #[cfg(target_arch = "x86_64")]
    {
        // SAFETY: `isa` is only Avx512 (Avx2) when the CPU has those
        // features (`simd::detect`).
        match isa {
            crate::simd::Isa::Avx512 => return unsafe { unorm8_lanes_avx512(rgba) },
            crate::simd::Isa::Avx2 => return unsafe { unorm8_lanes_avx2(rgba) },
            _ => {}
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = isa;
    unorm8_lanes(rgba)
}

/// [`write_strip_in`] compiled for AVX-512 (the features
/// `simd::Isa::Avx512` checks; the operations it uses are AVX-512 F's).
///
/// # Safety
/// The CPU must have AVX2 and AVX-512 F, DQ and VL; `rows` as for
/// [`write_strip_in`].
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512dq,avx512vl,avx2")]
unsafe fn write_strip_avx512(rows: &mut [[u8; 4]], w: usize, rgba: [&[f32; 16]; 4], over: bool) {
    // SAFETY: the caller's contract.
    unsafe { write_strip_in::<X512>(rows, w, rgba, over) }
}

/// [`write_strip_in`] compiled for AVX2.
///
/// # Safety
/// The CPU must have AVX2; `rows` as for [`write_strip_in`].
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn write_strip_avx2(rows: &mut [[u8; 4]], w: usize, rgba: [&[f32; 16]; 4], over: bool) {
    // SAFETY: the caller's contract.
    unsafe { write_strip_in::<X256>(rows, w, rgba, over) }
}

/// Two adjacent 4-byte pixels: `new[k]` where bit `k` of `bits` is set,
/// else `old[k]`, selected with one 64-bit mask (no branch, which the
/// compiler makes of a per-pixel select when it can sink the load of
/// `old` into it).
#[inline(always)]
fn blend_pair(old: [[u8; 4]; 2], new: [[u8; 4]; 2], bits: u8) -> [[u8; 4]; 2] {
    let wide = |p: [[u8; 4]; 2]| {
        let [[a, b, c, d], [e, f, g, h]] = p;
        u64::from_ne_bytes([a, b, c, d, e, f, g, h])
    };
    let lane = |k: u8| 0u32.wrapping_sub(u32::from((bits >> k) & 1)).to_ne_bytes();
    let m = wide([lane(0), lane(1)]);
    let [a, b, c, d, e, f, g, h] = ((wide(new) & m) | (wide(old) & !m)).to_ne_bytes();
    [[a, b, c, d], [e, f, g, h]]
}

/// The depth test of the lanes `lanes` of a quad whose stored depths are
/// the pixel pairs `d[r0..r0 + 2]` and `d[r1..r1 + 2]` (its rows), against
/// its fixed-point depths `zf`: the lanes that pass, whose new depths are
/// stored when `write`. (Other pixels are stored unchanged: no branch on
/// coverage patterns, which do not predict.) On x86-64 in SSE2 registers
/// (integer operations: the same results).
#[inline(always)]
fn depth_quad(
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
fn depth_quad_portable(
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

/// [`depth_to_fixed`] of `z[k] as f32`, four at a time.
#[inline(always)]
pub(crate) fn depth_to_fixed4(z: [f64; 4]) -> [u32; 4] {
    z.map(|z| depth_to_fixed(z as f32))
}

/// What [`QuickTarget::write`] stores without blending, for every lane of
/// a batch's colour output (`rgba`: its four components): the clamped
/// colour in unorm8.
#[inline(always)]
pub(crate) fn unorm8_lanes<const N: usize>(rgba: [&[f32; N]; 4]) -> [[u8; 4]; N] {
    let [r, g, b, a] = rgba;
    let mut out = [[0u8; 4]; N];
    for (l, o) in out.iter_mut().enumerate() {
        *o = to_unorm8([clamp01(r[l]), clamp01(g[l]), clamp01(b[l]), clamp01(a[l])]);
    }
    out
}

/// True when the outcome of a fragment's per-fragment operations does
/// not depend on its colors and what it writes replaces the pixel's
/// color entirely: no alpha test, no blending, no logic op, and no
/// stencil test. Then, per pixel, only the last fragment that passes the
/// depth test decides the color, so colors need computing only for those.
pub(crate) fn last_writer_wins(fb: &Framebuffer, state: &PipelineState) -> bool {
    state.alpha_test.is_none()
        && state.blend.is_none()
        && state.logic_op.is_none()
        && (state.stencil.is_none() || fb.stencil.is_none())
}

fn write_stencil(fb: &mut Framebuffer, index: usize, face: &StencilFace, op: StencilOp, old: u8) {
    let new = stencil_op(op, old, stencil_ref(face));
    let m = face.write_mask as u8;
    if let Some(p) = fb.stencil.as_mut().and_then(|s| s.get_mut(index)) {
        *p = (old & !m) | (new & m);
    }
}

fn clamp01(x: f32) -> f32 {
    if x > 0.0 {
        x.min(1.0)
    } else {
        0.0
    }
}

fn write_color(buf: &mut ColorBuffer, index: usize, state: &PipelineState, src: [f32; 4]) {
    let mask = state.color_mask;
    match buf {
        ColorBuffer::Rgba8(v) => {
            let Some(p) = v.get_mut(index) else { return };
            // Fixed-point buffers always see clamped colors (§4.1.8).
            let s = src.map(clamp01);
            let out: [u8; 4] = if let Some(op) = state.logic_op {
                let sb = s.map(float_to_unorm8);
                std::array::from_fn(|c| op.apply(sb[c], p[c]))
            } else if let Some(blend) = &state.blend {
                // `unorm8_to_float`, four at a time.
                let d = p.map(|b| b as f32 / 255.0);
                to_unorm8(blend_unit(blend, s, d))
            } else {
                to_unorm8(s)
            };
            if mask == [true; 4] {
                *p = out;
            } else {
                for c in 0..4 {
                    if mask[c] {
                        p[c] = out[c];
                    }
                }
            }
        }
        ColorBuffer::Rgba32F(v) => {
            let Some(p) = v.get_mut(index) else { return };
            let s = if state.clamp_fragment_color {
                src.map(clamp01)
            } else {
                src
            };
            // Logic ops do not apply to float buffers (§4.1.10).
            let out = match &state.blend {
                Some(blend) if state.logic_op.is_none() => blend_color(blend, s, *p),
                _ => s,
            };
            for c in 0..4 {
                if mask[c] {
                    p[c] = out[c];
                }
            }
        }
    }
}

/// `float_to_unorm8` of four channels, branch-free so that it vectorizes:
/// NaN and values ≤ 0 give 0, values ≥ 1 give 255.
#[inline(always)]
// Not `clamp`: NaN must become 0 (`max` drops it; `clamp` keeps it).
#[allow(clippy::manual_clamp)]
fn to_unorm8(c: [f32; 4]) -> [u8; 4] {
    c.map(|x| {
        let y = x.max(0.0).min(1.0) * 255.0 + 0.5;
        // SAFETY: `max` turns NaN into 0, so `y` is finite and in
        // [0.5, 255.5]: representable in i32 (truncation, as `as i32`
        // would give, without its saturation checks).
        unsafe { y.to_int_unchecked::<i32>() as u8 }
    })
}

/// [`blend_color`] for `s` and `d` in [0, 1] (a fixed-point buffer's
/// clamped source and stored destination): the common factor pairs with
/// FUNC_ADD (SRC_ALPHA / ONE_MINUS_SRC_ALPHA, ONE / ZERO, ONE / ONE, the
/// same for colour and alpha) as straight-line code giving the same bits,
/// the rest through [`blend_color`]. (With values in [0, 1], `x · 1 = x`,
/// `x · 0 = +0` and `x + 0 = x` exactly.)
#[inline]
fn blend_unit(b: &Blend, s: [f32; 4], d: [f32; 4]) -> [f32; 4] {
    use BlendFactor::{One, OneMinusSrcAlpha, SrcAlpha, Zero};
    if b.equation_rgb == BlendEquation::Add
        && b.equation_alpha == BlendEquation::Add
        && b.src_rgb == b.src_alpha
        && b.dst_rgb == b.dst_alpha
    {
        match (b.src_rgb, b.dst_rgb) {
            (SrcAlpha, OneMinusSrcAlpha) => {
                let (fs, fd) = (s[3], 1.0 - s[3]);
                return [
                    s[0] * fs + d[0] * fd,
                    s[1] * fs + d[1] * fd,
                    s[2] * fs + d[2] * fd,
                    s[3] * fs + d[3] * fd,
                ];
            }
            (One, Zero) => return s,
            (One, One) => return [s[0] + d[0], s[1] + d[1], s[2] + d[2], s[3] + d[3]],
            _ => {}
        }
    }
    blend_color(b, s, d)
}

/// GL 2.1 §4.1.8 blend of source `s` over destination `d`
/// (table 4.1 equations, table 4.2 factors).
pub(crate) fn blend_color(b: &Blend, s: [f32; 4], d: [f32; 4]) -> [f32; 4] {
    let factor = |f: BlendFactor, c: usize| -> f32 {
        let k = b.color;
        match f {
            BlendFactor::Zero => 0.0,
            BlendFactor::One => 1.0,
            BlendFactor::SrcColor => s[c],
            BlendFactor::OneMinusSrcColor => 1.0 - s[c],
            BlendFactor::DstColor => d[c],
            BlendFactor::OneMinusDstColor => 1.0 - d[c],
            BlendFactor::SrcAlpha => s[3],
            BlendFactor::OneMinusSrcAlpha => 1.0 - s[3],
            BlendFactor::DstAlpha => d[3],
            BlendFactor::OneMinusDstAlpha => 1.0 - d[3],
            BlendFactor::ConstantColor => k[c],
            BlendFactor::OneMinusConstantColor => 1.0 - k[c],
            BlendFactor::ConstantAlpha => k[3],
            BlendFactor::OneMinusConstantAlpha => 1.0 - k[3],
            BlendFactor::SrcAlphaSaturate => {
                if c == 3 {
                    1.0
                } else {
                    glsl::math::min(s[3], 1.0 - d[3])
                }
            }
        }
    };
    std::array::from_fn(|c| {
        let (eq, sf, df) = if c < 3 {
            (b.equation_rgb, b.src_rgb, b.dst_rgb)
        } else {
            (b.equation_alpha, b.src_alpha, b.dst_alpha)
        };
        match eq {
            BlendEquation::Add => s[c] * factor(sf, c) + d[c] * factor(df, c),
            BlendEquation::Subtract => s[c] * factor(sf, c) - d[c] * factor(df, c),
            BlendEquation::ReverseSubtract => d[c] * factor(df, c) - s[c] * factor(sf, c),
            BlendEquation::Min => glsl::math::min(s[c], d[c]),
            BlendEquation::Max => glsl::math::max(s[c], d[c]),
        }
    })
}

/// Depth test helper used by tests: does `z` pass `func` against `stored`?
#[cfg(test)]
fn depth_passes(func: crate::state::CompareFunc, z: f32, stored: f32) -> bool {
    func.test(depth_to_fixed(z), depth_to_fixed(stored))
}

#[cfg(test)]
mod tests;
