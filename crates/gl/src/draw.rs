//! Drawing: glDrawArrays / glDrawElements / glBegin-glEnd, glClear and
//! glReadPixels.
//!
//! The pipeline itself lives in the `exec` and `raster` crates; until
//! they provide the APIs of docs/PIPELINE.md this module validates the
//! calls (recording the GL errors) and keeps no pixels.

use crate::enums::*;
use crate::vertex::{ArrayData, ImmVertex};
use crate::Context;

/// The lowered stages of a linked program.
#[derive(Default)]
pub struct Kernels {}

impl Kernels {
    pub fn new(_program: &glsl::link::Program) -> Result<Kernels, String> {
        Ok(Kernels {})
    }
}

impl Context {
    /// Checks shared by the draw calls (GL 2.1 §2.8).
    fn check_draw(&mut self, mode: u32, count: i32) -> bool {
        if self.reject_in_begin() {
            return false;
        }
        if mode > GL_POLYGON {
            self.set_error(GL_INVALID_ENUM);
            return false;
        }
        if count < 0 {
            self.set_error(GL_INVALID_VALUE);
            return false;
        }
        let fb = self.objects.draw_framebuffer;
        if self.framebuffer_status(fb) != GL_FRAMEBUFFER_COMPLETE {
            self.set_error(GL_INVALID_FRAMEBUFFER_OPERATION);
            return false;
        }
        true
    }

    /// glDrawArrays.
    pub fn draw_arrays(&mut self, mode: u32, first: i32, count: i32) {
        if first < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if !self.check_draw(mode, count) {
            return;
        }
        let indices: Vec<u32> = (0..count as u32).map(|i| i + first as u32).collect();
        self.draw_indexed(mode, &indices);
    }

    /// glMultiDrawArrays.
    pub fn multi_draw_arrays(&mut self, mode: u32, first: &[i32], count: &[i32]) {
        for (f, c) in first.iter().zip(count) {
            self.draw_arrays(mode, *f, *c);
        }
    }

    /// glDrawElements: `indices` is an offset into the bound element
    /// buffer or client index data.
    pub fn draw_elements(&mut self, mode: u32, count: i32, ty: u32, indices: ArrayData) {
        if !matches!(ty, GL_UNSIGNED_BYTE | GL_UNSIGNED_SHORT | GL_UNSIGNED_INT) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if !self.check_draw(mode, count) {
            return;
        }
        let Some(idx) = self.read_indices(count as usize, ty, &indices) else {
            return;
        };
        self.draw_indexed(mode, &idx);
    }

    /// glDrawRangeElements.
    #[allow(clippy::too_many_arguments)]
    pub fn draw_range_elements(
        &mut self,
        mode: u32,
        start: u32,
        end: u32,
        count: i32,
        ty: u32,
        indices: ArrayData,
    ) {
        if end < start {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        self.draw_elements(mode, count, ty, indices);
    }

    fn read_indices(&mut self, count: usize, ty: u32, data: &ArrayData) -> Option<Vec<u32>> {
        let (bytes, base): (std::sync::Arc<[u8]>, usize) = match data {
            ArrayData::Client(b) => (b.clone(), 0),
            ArrayData::Offset(off) => {
                let b = self.va.element_buffer;
                match self.objects.buffers.get(&b).filter(|_| b != 0) {
                    Some(buf) => (buf.data.clone(), *off),
                    None => {
                        self.set_error(GL_INVALID_OPERATION);
                        return None;
                    }
                }
            }
        };
        let size = match ty {
            GL_UNSIGNED_BYTE => 1,
            GL_UNSIGNED_SHORT => 2,
            _ => 4,
        };
        let mut out = Vec::with_capacity(count.min(1 << 24));
        for i in 0..count {
            let at = base.saturating_add(i.saturating_mul(size));
            let Some(b) = bytes.get(at..at.saturating_add(size)) else {
                break;
            };
            out.push(match size {
                1 => b[0] as u32,
                2 => u16::from_le_bytes([b[0], b[1]]) as u32,
                _ => u32::from_le_bytes([b[0], b[1], b[2], b[3]]),
            });
        }
        Some(out)
    }

    /// Runs a draw over array elements `indices`.
    fn draw_indexed(&mut self, _mode: u32, _indices: &[u32]) {}

    /// Draws the vertices recorded between glBegin and glEnd.
    pub(crate) fn draw_immediate(&mut self, _mode: u32, _verts: &[ImmVertex]) {}

    /// glClear.
    pub fn clear(&mut self, mask: u32) {
        if self.reject_in_begin() {
            return;
        }
        let all =
            GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
        if mask & !all != 0 {
            self.set_error(GL_INVALID_VALUE);
        }
    }

    /// glReadPixels into `out` (packed per GL_PACK_ALIGNMENT).
    #[allow(clippy::too_many_arguments)]
    pub fn read_pixels(
        &mut self,
        _x: i32,
        _y: i32,
        w: i32,
        h: i32,
        format: u32,
        ty: u32,
        _out: &mut [u8],
    ) {
        if w < 0 || h < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if crate::objects::pixel_size(format, ty).is_none() {
            self.set_error(GL_INVALID_ENUM);
        }
    }

    /// glReadPixels with GL_RGBA / GL_FLOAT, as `w * h` RGBA values,
    /// bottom row first.
    pub fn read_pixels_f32(&mut self, x: i32, y: i32, w: i32, h: i32) -> Vec<[f32; 4]> {
        let n = (w.max(0) as usize).saturating_mul(h.max(0) as usize);
        let mut bytes = vec![0u8; n.saturating_mul(16)];
        self.read_pixels(x, y, w, h, GL_RGBA, GL_FLOAT, &mut bytes);
        bytes
            .chunks_exact(16)
            .map(|c| {
                let f = |i: usize| f32::from_le_bytes([c[i], c[i + 1], c[i + 2], c[i + 3]]);
                [f(0), f(4), f(8), f(12)]
            })
            .collect()
    }
}
