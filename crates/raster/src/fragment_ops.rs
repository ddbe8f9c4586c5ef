//! Per-fragment operations in GL 2.1 §4.1 order: pixel ownership, scissor,
//! alpha test, stencil test, depth test, blending, (dithering: off),
//! logic op, then the masked write to each draw buffer.
//!
//! This module is the general driver, one fragment at a time
//! ([`process`] = [`tests`] then [`write_colors`]), and early rejection
//! before shading ([`early_reject`]). Its parts: `stencil` (the stencil
//! test and writes), `color` (blending, logic op, conversion, masks),
//! `depth` (a quad's four depth tests at once), `quick` (the common
//! states decided once per tile: [`QuickOps`], [`QuickTarget`]) and
//! `wide` (16 colours at once in AVX2 / AVX-512 registers).

mod color;
mod depth;
mod quick;
mod stencil;
mod wide;

pub(crate) use depth::depth_live_in;
pub(crate) use quick::{QuickOps, QuickTarget};
pub(crate) use stencil::stencil_passes;
pub(crate) use wide::unorm8_batch;

use crate::framebuffer::{Framebuffer, MAX_DRAW_BUFFERS};

/// The colours a fragment carries: one per fragment output (draw buffer
/// slot), then [`SRC1`].
pub(crate) const FRAG_COLORS: usize = MAX_DRAW_BUFFERS + 1;
/// The slot of [`Fragment::colors`] holding the second source colour of
/// output 0 (`layout(location = 0, index = 1)`): what the SRC1 blend
/// factors read (dual-source blending, GL 3.3 §4.1.8; one dual-source
/// draw buffer).
pub(crate) const SRC1: usize = MAX_DRAW_BUFFERS;
use crate::state::PipelineState;
use color::{clamp01, write_color};
use stencil::{op_has_effect, stencil_face, stencil_test, write_stencil};

/// One shaded fragment ready for the per-fragment operations.
pub(crate) struct Fragment {
    pub x: u32,
    pub y: u32,
    /// Window z, already clamped to [0, 1].
    pub z: f32,
    /// Selects the back stencil state (polygons only).
    pub back_facing: bool,
    /// Color of fragment output `i` (`gl_FragData[i]`, or gl_FragColor for
    /// every `i`), and at [`SRC1`] output 0's second source colour.
    pub colors: [[f32; 4]; FRAG_COLORS],
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
                let zf = fb.depth_format.to_fixed(frag.z);
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
    colors: &[[f32; 4]; FRAG_COLORS],
) {
    for (output, target) in state.draw_buffers.iter().enumerate() {
        let Some(target) = *target else { continue };
        let Some(src) = colors.get(output) else {
            continue;
        };
        let Some(buf) = fb.color.get_mut(target) else {
            continue;
        };
        let (blend, mask) = match &state.per_buffer {
            Some(per) => {
                let (on, mask) = per[output % per.len()];
                (state.blend.as_ref().filter(|_| on), mask)
            }
            None => (state.blend.as_ref(), state.color_mask),
        };
        // Only output 0 has a second source colour (one dual-source draw
        // buffer); elsewhere the SRC1 factors read zeros.
        let src1 = if output == 0 { colors[SRC1] } else { [0.0; 4] };
        write_color(buf, index, state, (*src, src1), (blend, mask));
    }
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

#[cfg(test)]
mod tests;
