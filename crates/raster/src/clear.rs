//! glClear of a [`Framebuffer`]'s colour, depth and stencil buffers
//! inside the scissor box, under the write masks: the rows touched, in
//! bands of [`CLEAR_ROWS`] rows, in parallel on the [`Workers`] (each row's
//! pixels depend on nothing else, so the bytes are those of one thread).
//!
//! Here rather than in `crate::framebuffer` so that the framebuffer, a
//! data type, does not depend on the thread scheduler.

use crate::framebuffer::{float_to_unorm8, ColorBuffer, Framebuffer};
use crate::state::Rect;
use crate::workers::Workers;

/// Rows one task of a parallel clear fills.
const CLEAR_ROWS: usize = 32;

impl Framebuffer {
    /// `f` on each row of `buf` (`width` pixels a row) inside the scissor
    /// box `(x0, y0, x1, y1)` of [`Framebuffer::clip_rect`], the pixels
    /// `buf` lacks left out: the pixels a clear touches, a row at a time,
    /// bands of rows in parallel on `workers` (each row's pixels depend on
    /// nothing else).
    fn for_each_row<T: Send>(
        buf: &mut [T],
        width: u32,
        (x0, y0, x1, y1): (u32, u32, u32, u32),
        workers: &Workers,
        f: impl Fn(&mut [T]) + Sync + Send,
    ) {
        let (width, len) = (width as usize, buf.len());
        if width == 0 {
            return;
        }
        let (first, end) = (
            (y0 as usize * width).min(len),
            (y1 as usize * width).min(len),
        );
        let Some(rows) = buf.get_mut(first..end) else {
            return;
        };
        let (x0, x1) = (x0 as usize, x1 as usize);
        workers.for_each_chunk(rows, width * CLEAR_ROWS, |_, band| {
            for row in band.chunks_mut(width) {
                if let Some(r) = row.get_mut(x0.min(row.len())..x1.min(row.len())) {
                    f(r);
                }
            }
        });
    }

    /// glClear of the color buffers listed in `buffers` (indices into
    /// [`Framebuffer::color`]; out-of-range ones are skipped) inside the
    /// scissor box, honouring the color write mask. RGBA8 buffers convert
    /// `color` with [`float_to_unorm8`]; float buffers store it as is.
    pub fn clear_color(
        &mut self,
        buffers: &[usize],
        color: [f32; 4],
        mask: [bool; 4],
        scissor: Option<Rect>,
    ) {
        self.clear_color_on(&Workers::inline(), buffers, color, mask, scissor)
    }

    /// [`Framebuffer::clear_color`] in bands of rows on `workers`.
    pub fn clear_color_on(
        &mut self,
        workers: &Workers,
        buffers: &[usize],
        color: [f32; 4],
        mask: [bool; 4],
        scissor: Option<Rect>,
    ) {
        let rect = self.clip_rect(scissor);
        let width = self.width;
        let bytes = color.map(float_to_unorm8);
        for &b in buffers {
            let Some(buf) = self.color.get_mut(b) else {
                continue;
            };
            match buf {
                // Every channel written: whole rows filled.
                ColorBuffer::Rgba8(v) if mask == [true; 4] => {
                    Self::for_each_row(v, width, rect, workers, |row| row.fill(bytes))
                }
                ColorBuffer::Rgba8(v) => Self::for_each_row(v, width, rect, workers, |row| {
                    for p in row {
                        for c in 0..4 {
                            if mask[c] {
                                p[c] = bytes[c];
                            }
                        }
                    }
                }),
                ColorBuffer::Rgba32F(v) => Self::for_each_row(v, width, rect, workers, |row| {
                    for p in row {
                        for c in 0..4 {
                            if mask[c] {
                                p[c] = color[c];
                            }
                        }
                    }
                }),
            }
        }
    }

    /// glClear of the depth buffer (`depth` is ClearDepth, clamped to
    /// [0, 1]); nothing happens when `write` (DepthMask) is false.
    pub fn clear_depth(&mut self, depth: f32, write: bool, scissor: Option<Rect>) {
        self.clear_depth_on(&Workers::inline(), depth, write, scissor)
    }

    /// [`Framebuffer::clear_depth`] in bands of rows on `workers`.
    pub fn clear_depth_on(
        &mut self,
        workers: &Workers,
        depth: f32,
        write: bool,
        scissor: Option<Rect>,
    ) {
        if !write {
            return;
        }
        let k = self.depth_format.to_fixed(depth);
        let (rect, width) = (self.clip_rect(scissor), self.width);
        if let Some(d) = self.depth.as_mut() {
            Self::for_each_row(d, width, rect, workers, |row| row.fill(k));
        }
    }

    /// glClear of the stencil buffer: ClearStencil's low 8 bits under the
    /// stencil write mask.
    pub fn clear_stencil(&mut self, value: i32, write_mask: u32, scissor: Option<Rect>) {
        self.clear_stencil_on(&Workers::inline(), value, write_mask, scissor)
    }

    /// [`Framebuffer::clear_stencil`] in bands of rows on `workers`.
    pub fn clear_stencil_on(
        &mut self,
        workers: &Workers,
        value: i32,
        write_mask: u32,
        scissor: Option<Rect>,
    ) {
        let v = value as u8;
        let m = write_mask as u8;
        let (rect, width) = (self.clip_rect(scissor), self.width);
        if let Some(s) = self.stencil.as_mut() {
            Self::for_each_row(s, width, rect, workers, |row| {
                for p in row {
                    *p = (*p & !m) | (v & m);
                }
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::ColorFormat;

    /// Clears in bands on two threads give the one-thread result, with
    /// and without a scissor box, over more rows than one band.
    #[test]
    fn parallel_clears_match() {
        let (w, h) = (37, 3 * CLEAR_ROWS as u32 + 5);
        for scissor in [None, Some(Rect::new(3, 7, 20, 2 * CLEAR_ROWS as i32))] {
            let mut one = Framebuffer::new(w, h, ColorFormat::Rgba8, true, true);
            let mut two = one.clone();
            let workers = Workers::new(2);
            for (fb, on) in [(&mut one, &Workers::inline()), (&mut two, &workers)] {
                fb.clear_color_on(on, &[0], [0.2, 0.4, 0.6, 0.8], [true; 4], scissor);
                fb.clear_color_on(on, &[0], [1.0; 4], [false, true, false, false], scissor);
                fb.clear_depth_on(on, 0.25, true, scissor);
                fb.clear_stencil_on(on, 0x5a, 0x0f, scissor);
            }
            assert_eq!(one, two);
            let inside = one.read_pixels_u8(0, 5, 8, 1, 1);
            let outside = one.read_pixels_u8(0, 1, 1, 1, 1);
            assert_eq!(inside, vec![[51, 255, 153, 204]]);
            if scissor.is_some() {
                assert_eq!(outside, vec![[0; 4]]);
            }
        }
    }
}
