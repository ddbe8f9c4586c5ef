//! Per-draw-buffer state and clears (GL 3.0–3.3 §4.1.8, §4.2.2, §4.2.3):
//! glEnablei / glDisablei / glIsEnabledi (GL_BLEND, per draw buffer),
//! glColorMaski, their indexed queries, and glClearBuffer{iv,uiv,fv,fi}.
//!
//! Draw buffer `i` is fragment output `i`'s destination (glDrawBuffers);
//! blending on it is the key (GL_BLEND, i) of the capability set, its
//! mask [`crate::state::State::color_masks`]`[i]`. A draw passes them to
//! the rasterizer as one state for all buffers when they agree, else per
//! buffer ([`raster::PipelineState::per_buffer`]).

use crate::enums::*;
use crate::pipeline_state::rect;
use crate::{Context, MAX_DRAW_BUFFERS};

impl Context {
    /// Sets (GL_BLEND, `index`) without checks.
    pub(crate) fn set_indexed_cap(&mut self, cap: u32, index: u32, on: bool) {
        if on {
            self.st.enabled.insert((cap, index));
        } else {
            self.st.enabled.remove(&(cap, index));
        }
    }

    /// Whether blending is on for any draw buffer.
    pub(crate) fn any_buffer_blends(&self) -> bool {
        (0..MAX_DRAW_BUFFERS as u32).any(|i| self.st.is_on_unit(GL_BLEND, i))
    }

    /// The rasterizer's per-buffer blending and masks: `None` when all
    /// draw buffers agree.
    pub(crate) fn per_buffer_ops(&self) -> Option<[(bool, [bool; 4]); 8]> {
        let per: [(bool, [bool; 4]); 8] = std::array::from_fn(|i| {
            let i = i % MAX_DRAW_BUFFERS;
            (
                self.st.is_on_unit(GL_BLEND, i as u32),
                self.st.color_masks[i],
            )
        });
        per.iter().any(|p| *p != per[0]).then_some(per)
    }

    /// Whether `cap`, `index` name an indexed capability; records
    /// GL_INVALID_ENUM (cap) or GL_INVALID_VALUE (index) when not.
    fn indexed_cap_ok(&mut self, cap: u32, index: u32) -> bool {
        if self.reject_in_begin() {
            return false;
        }
        if cap != GL_BLEND || !self.api.at_least(3, 0) {
            self.set_error(GL_INVALID_ENUM);
            return false;
        }
        if index as usize >= MAX_DRAW_BUFFERS {
            self.set_error(GL_INVALID_VALUE);
            return false;
        }
        true
    }

    /// glEnablei (GL_BLEND for draw buffer `index`).
    pub fn enablei(&mut self, cap: u32, index: u32) {
        if self.indexed_cap_ok(cap, index) {
            self.set_indexed_cap(cap, index, true);
        }
    }

    /// glDisablei.
    pub fn disablei(&mut self, cap: u32, index: u32) {
        if self.indexed_cap_ok(cap, index) {
            self.set_indexed_cap(cap, index, false);
        }
    }

    /// glIsEnabledi.
    pub fn is_enabledi(&mut self, cap: u32, index: u32) -> bool {
        self.indexed_cap_ok(cap, index) && self.st.is_on_unit(cap, index)
    }

    /// glColorMaski: draw buffer `index`'s mask (GL_INVALID_VALUE past
    /// GL_MAX_DRAW_BUFFERS).
    pub fn color_maski(&mut self, index: u32, r: bool, g: bool, b: bool, a: bool) {
        if self.reject_in_begin() {
            return;
        }
        match self.st.color_masks.get_mut(index as usize) {
            Some(m) => *m = [r, g, b, a],
            None => self.set_error(GL_INVALID_VALUE),
        }
    }

    /// glGet{Integer,Integer64,Boolean}i_v: GL_BLEND and
    /// GL_COLOR_WRITEMASK per draw buffer, and the indexed buffer
    /// bindings ([`Context::get_integer64_indexed`]). `None` after an
    /// error (GL_INVALID_ENUM, GL_INVALID_VALUE for an index past the
    /// draw buffers or binding points).
    pub fn get_indexed(&mut self, pname: u32, index: u32) -> Option<Vec<i64>> {
        match pname {
            GL_BLEND | GL_COLOR_WRITEMASK if self.api.at_least(3, 0) => {
                if self.reject_in_begin() {
                    return None;
                }
                let Some(mask) = self.st.color_masks.get(index as usize).copied() else {
                    self.set_error(GL_INVALID_VALUE);
                    return None;
                };
                Some(if pname == GL_BLEND {
                    vec![self.st.is_on_unit(GL_BLEND, index) as i64]
                } else {
                    mask.iter().map(|&m| m as i64).collect()
                })
            }
            // The mask's bits as a GLint (-1 for all ones), as Mesa.
            GL_SAMPLE_MASK_VALUE if self.api.at_least(3, 2) => {
                if self.reject_in_begin() {
                    return None;
                }
                if index >= crate::rasterization::MAX_SAMPLE_MASK_WORDS {
                    self.set_error(GL_INVALID_VALUE);
                    return None;
                }
                Some(vec![self.st.sample_mask as i32 as i64])
            }
            _ => self.get_integer64_indexed(pname, index).map(|v| vec![v]),
        }
    }

    /// glClearBuffer checks: the buffer/drawbuffer pair a variant accepts
    /// (GL 3.3 §4.2.3). `allowed`: the buffers of the variant;
    /// GL_INVALID_ENUM for another, GL_INVALID_VALUE for a draw buffer
    /// past GL_MAX_DRAW_BUFFERS (colour) or other than 0 (depth,
    /// stencil). Then the framebuffer must be complete, and conditional
    /// rendering and rasterizer discard may skip the clear (false).
    fn clear_buffer_ok(&mut self, buffer: u32, drawbuffer: i32, allowed: &[u32]) -> bool {
        if self.reject_in_begin() {
            return false;
        }
        if !allowed.contains(&buffer) {
            self.set_error(GL_INVALID_ENUM);
            return false;
        }
        let max = if buffer == GL_COLOR {
            MAX_DRAW_BUFFERS as i32
        } else {
            1
        };
        if !(0..max).contains(&drawbuffer) {
            self.set_error(GL_INVALID_VALUE);
            return false;
        }
        self.check_fbo_complete()
            && !self.render_discarded()
            && !self.st.is_on(GL_RASTERIZER_DISCARD)
    }

    /// Clears what a glClearBuffer call names: colour buffer
    /// `drawbuffer` to `color`, and/or depth and stencil, each with its
    /// mask and the scissor.
    fn clear_buffer_now(
        &mut self,
        drawbuffer: i32,
        color: Option<[f32; 4]>,
        depth: Option<f32>,
        stencil: Option<i32>,
    ) {
        self.on_every_layer(|ctx| ctx.clear_buffer_layer(drawbuffer, color, depth, stencil));
    }

    /// [`Context::clear_buffer_now`] of the layer `draw_layer`.
    fn clear_buffer_layer(
        &mut self,
        drawbuffer: i32,
        color: Option<[f32; 4]>,
        depth: Option<f32>,
        stencil: Option<i32>,
    ) {
        let Some(mut t) = self.draw_target() else {
            return;
        };
        let scissor = self
            .st
            .is_on(GL_SCISSOR_TEST)
            .then(|| rect(self.st.scissor));
        let i = drawbuffer.max(0) as usize % MAX_DRAW_BUFFERS;
        if let (Some(color), Some(buf)) = (color, t.draw_buffers.get(i).copied().flatten()) {
            let write = self.st.color_masks[i];
            t.fb.clear_color_on(&self.workers, &[buf], color, write, scissor);
        }
        if let Some(d) = depth {
            // Depth values are clamped to [0, 1] as glClearDepth's are.
            let d = if d.is_nan() { 0.0 } else { d.clamp(0.0, 1.0) };
            t.fb.clear_depth_on(&self.workers, d, self.st.depth_mask, scissor);
        }
        if let Some(s) = stencil {
            let mask = self.st.stencil[0].write_mask;
            t.fb.clear_stencil_on(&self.workers, s, mask, scissor);
        }
        self.store_target(t);
    }

    /// glClearBufferfv: GL_COLOR (draw buffer `drawbuffer`, four values)
    /// or GL_DEPTH (drawbuffer 0, one value).
    pub fn clear_bufferfv(&mut self, buffer: u32, drawbuffer: i32, value: &[f32]) {
        if !self.clear_buffer_ok(buffer, drawbuffer, &[GL_COLOR, GL_DEPTH]) {
            return;
        }
        if buffer == GL_COLOR {
            let c: [f32; 4] = std::array::from_fn(|k| value.get(k).copied().unwrap_or(0.0));
            self.clear_buffer_now(drawbuffer, Some(c), None, None);
        } else {
            let d = value.first().copied().unwrap_or(0.0);
            self.clear_buffer_now(drawbuffer, None, Some(d), None);
        }
    }

    /// glClearBufferiv: GL_COLOR (signed integers, for integer colour
    /// buffers: a fixed-point or float buffer takes them as floats, which
    /// GL leaves undefined) or GL_STENCIL (drawbuffer 0, one value).
    pub fn clear_bufferiv(&mut self, buffer: u32, drawbuffer: i32, value: &[i32]) {
        if !self.clear_buffer_ok(buffer, drawbuffer, &[GL_COLOR, GL_STENCIL]) {
            return;
        }
        if buffer == GL_COLOR {
            let c: [f32; 4] = std::array::from_fn(|k| value.get(k).copied().unwrap_or(0) as f32);
            self.clear_buffer_now(drawbuffer, Some(c), None, None);
        } else {
            let s = value.first().copied().unwrap_or(0);
            self.clear_buffer_now(drawbuffer, None, None, Some(s));
        }
    }

    /// glClearBufferuiv: GL_COLOR only (unsigned integers, as for
    /// glClearBufferiv).
    pub fn clear_bufferuiv(&mut self, buffer: u32, drawbuffer: i32, value: &[u32]) {
        if !self.clear_buffer_ok(buffer, drawbuffer, &[GL_COLOR]) {
            return;
        }
        let c: [f32; 4] = std::array::from_fn(|k| value.get(k).copied().unwrap_or(0) as f32);
        self.clear_buffer_now(drawbuffer, Some(c), None, None);
    }

    /// glClearBufferfi: GL_DEPTH_STENCIL (drawbuffer 0) to `depth` and
    /// `stencil`.
    pub fn clear_bufferfi(&mut self, buffer: u32, drawbuffer: i32, depth: f32, stencil: i32) {
        if !self.clear_buffer_ok(buffer, drawbuffer, &[GL_DEPTH_STENCIL]) {
            return;
        }
        self.clear_buffer_now(drawbuffer, None, Some(depth), Some(stencil));
    }
}
