//! The stencil test and its writes (GL 2.1 §4.1.5): the face a fragment
//! uses, the comparison against the reference under the value mask, the
//! operations on the stored value and the masked write.

use crate::framebuffer::Framebuffer;
use crate::state::{PipelineState, StencilFace, StencilOp};

pub(super) fn stencil_face(state: &PipelineState, back: bool) -> Option<StencilFace> {
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

pub(super) fn op_has_effect(face: &StencilFace, op: StencilOp) -> bool {
    op != StencilOp::Keep && face.write_mask as u8 != 0
}

pub(super) fn write_stencil(
    fb: &mut Framebuffer,
    index: usize,
    face: &StencilFace,
    op: StencilOp,
    old: u8,
) {
    let new = stencil_op(op, old, stencil_ref(face));
    let m = face.write_mask as u8;
    if let Some(p) = fb.stencil.as_mut().and_then(|s| s.get_mut(index)) {
        *p = (old & !m) | (new & m);
    }
}
