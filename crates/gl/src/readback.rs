//! glReadPixels: the read framebuffer's color, depth or stencil values
//! packed into client memory ([`crate::pixel_transfer`]).
//!
//! Contract: GL 2.1 §4.3.2's checks and errors; colours clamped to
//! [0, 1] by GL_CLAMP_READ_COLOR (glClampColor) as GL 3.3 §4.3.2 says; pixels outside the
//! framebuffer read as 0; packed types and index formats are
//! GL_INVALID_OPERATION (not implemented).

use crate::enums::*;
use crate::Context;

impl Context {
    /// glReadPixels into `out`, rows packed per GL_PACK_ALIGNMENT, bottom
    /// row first (GL 2.1 §4.3.2; the packed layout: the caller applies the
    /// other glPixelStore modes, [`crate::pixel_store`]). Pixels outside the framebuffer read as 0.
    #[allow(clippy::too_many_arguments)]
    pub fn read_pixels(
        &mut self,
        x: i32,
        y: i32,
        w: i32,
        h: i32,
        format: u32,
        ty: u32,
        out: &mut [u8],
    ) {
        if self.reject_in_begin() {
            return;
        }
        if w < 0 || h < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let Some(n) = crate::pixel_transfer::format_components(format) else {
            self.set_error(GL_INVALID_ENUM);
            return;
        };
        let Some((px, comp)) = crate::pixel_transfer::pixel_size(format, ty) else {
            self.set_error(
                if matches!(
                    ty,
                    GL_UNSIGNED_BYTE
                        | GL_BYTE
                        | GL_UNSIGNED_SHORT
                        | GL_SHORT
                        | GL_UNSIGNED_INT
                        | GL_INT
                        | GL_FLOAT
                ) {
                    GL_INVALID_OPERATION
                } else {
                    GL_INVALID_ENUM
                },
            );
            return;
        };
        if matches!(format, GL_COLOR_INDEX | GL_DEPTH_STENCIL) || comp != px / n.max(1) {
            // Packed types and index formats are not implemented.
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let rb = self.objects.read_framebuffer;
        if self.framebuffer_status(rb) != GL_FRAMEBUFFER_COMPLETE {
            self.set_error(GL_INVALID_FRAMEBUFFER_OPERATION);
            return;
        }
        let what = match format {
            GL_DEPTH_COMPONENT | GL_STENCIL_INDEX => format,
            _ => GL_RGBA,
        };
        let Some(mut block) = self.read_block(x, y, w as u32, h as u32, what) else {
            return;
        };
        // Read colour clamping (GL 3.3 §4.3.2): a fixed-point buffer's
        // colours are in [0, 1] already, so only GL_TRUE on a float buffer
        // changes values; integer formats are never clamped.
        if what == GL_RGBA
            && self.st.clamp_read_color == GL_TRUE
            && crate::pixel_transfer::integer_client_format(format).is_none()
        {
            for p in block.iter_mut() {
                *p = p.map(|c| c.clamp(0.0, 1.0));
            }
        }
        let (w, h) = (w as usize, h as usize);
        let align = self.st.pack.alignment;
        crate::pixel_transfer::pack_into(&block, w, h, format, ty, align, out);
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
