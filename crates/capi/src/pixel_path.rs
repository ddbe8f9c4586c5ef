//! The raster-position pixel path's entry points (GL 2.1 §2.13, §3.6.4,
//! §3.7, §4.3.3) over [`gl::pixel_path`]: glRasterPos*, glWindowPos*,
//! glDrawPixels, glBitmap and glCopyPixels. Images are read from client
//! memory (or the bound GL_PIXEL_UNPACK_BUFFER) at the call — at compile
//! time inside glNewList, as §5.4 requires — and the pixel transfer scale
//! and bias, index shift/offset and zoom kept by [`crate::legacy`] apply
//! when the rectangle is drawn.

use crate::abi::*;
use crate::buffers::image_bytes;
use crate::context::{record_call, with_ctx, OsContext};
use gl::enums::*;
use gl::pixel_transfer::PixelTransfer;
use std::ffi::c_void;

/// Most bytes a glBitmap image may have.
const MAX_BITMAP_BYTES: usize = 1 << 28;

/// The pixel transfer state glPixelTransfer / glPixelZoom set.
fn transfer(c: &OsContext) -> PixelTransfer {
    let t = &c.legacy.pixel_transfer;
    let g = |p: u32, d: f32| t.get(&p).copied().unwrap_or(d);
    PixelTransfer {
        scale: [
            g(GL_RED_SCALE, 1.0),
            g(GL_GREEN_SCALE, 1.0),
            g(GL_BLUE_SCALE, 1.0),
            g(GL_ALPHA_SCALE, 1.0),
        ],
        bias: [
            g(GL_RED_BIAS, 0.0),
            g(GL_GREEN_BIAS, 0.0),
            g(GL_BLUE_BIAS, 0.0),
            g(GL_ALPHA_BIAS, 0.0),
        ],
        depth_scale: g(GL_DEPTH_SCALE, 1.0),
        depth_bias: g(GL_DEPTH_BIAS, 0.0),
        index_shift: g(GL_INDEX_SHIFT, 0.0) as i32,
        index_offset: g(GL_INDEX_OFFSET, 0.0) as i32,
        zoom: c.legacy.pixel_zoom,
    }
}

fn unpack_alignment(c: &mut OsContext) -> usize {
    c.gl.unpack_modes().alignment.max(1)
}

/// The bytes of a glBitmap image: from client memory or the unpack
/// buffer, laid out per the unpack modes (row length, skips, bit order),
/// returned packed (most significant bit first, rows at the alignment).
/// Err: an error was recorded and the call must do nothing.
pub(crate) unsafe fn bitmap_bytes(
    c: &mut OsContext,
    w: GLsizei,
    h: GLsizei,
    data: *const GLubyte,
) -> Result<Option<Vec<u8>>, crate::buffers::Recorded> {
    let pbo = c.gl.bound_buffer(GL_PIXEL_UNPACK_BUFFER);
    if (data.is_null() && pbo == 0) || w <= 0 || h <= 0 {
        return Ok(None);
    }
    let store = c.gl.unpack_modes();
    let (w, h) = (w as usize, h as usize);
    let Some(len) = store.bitmap_extent(w, h).filter(|&n| n <= MAX_BITMAP_BYTES) else {
        return Ok(None);
    };
    let raw = if pbo != 0 {
        crate::buffers::read_pixel_buffer(c, GL_PIXEL_UNPACK_BUFFER, data as usize, len)?
    } else {
        // SAFETY: GL's contract: the bitmap's bits, laid out per the
        // unpack modes, lie within `len` bytes of `data`.
        unsafe { std::slice::from_raw_parts(data, len) }.to_vec()
    };
    Ok(Some(match store.is_packed() {
        true => raw,
        false => store.gather_bitmap(&raw, w, h),
    }))
}

gl_entry_points! {
    fn glDrawPixels(w: GLsizei, h: GLsizei, format: GLenum, ty: GLenum, data: *const c_void) => |c| {
        let align = unpack_alignment(c);
        let Ok(bytes) = image_bytes(c, w, h, 1, false, format, ty, data) else {
            return;
        };
        if c.compiling() {
            // The image is unpacked now (§5.4); the transfer state applies
            // when the list runs.
            let rec = bytes.clone();
            let run = move || {
                with_ctx((), |c| {
                    let t = transfer(c);
                    c.gl.draw_pixels(w, h, format, ty, rec.as_deref(), align, &t);
                    c.dirty = true;
                })
            };
            if c.record(run) {
                return;
            }
        }
        let t = transfer(c);
        c.gl.draw_pixels(w, h, format, ty, bytes.as_deref(), align, &t);
        c.dirty = true;
    }
    fn glBitmap(
        w: GLsizei, h: GLsizei, xorig: GLfloat, yorig: GLfloat, xmove: GLfloat, ymove: GLfloat,
        bitmap: *const GLubyte
    ) => |c| {
        let align = unpack_alignment(c);
        let Ok(bytes) = bitmap_bytes(c, w, h, bitmap) else {
            return;
        };
        if c.compiling() {
            let rec = bytes.clone();
            let run = move || {
                with_ctx((), |c| {
                    c.gl.bitmap(w, h, xorig, yorig, xmove, ymove, rec.as_deref(), align);
                    c.dirty = true;
                })
            };
            if c.record(run) {
                return;
            }
        }
        c.gl.bitmap(w, h, xorig, yorig, xmove, ymove, bytes.as_deref(), align);
        c.dirty = true;
    }
    [list] fn glCopyPixels(x: GLint, y: GLint, w: GLsizei, h: GLsizei, ty: GLenum) => |c| {
        let t = transfer(c);
        c.gl.copy_pixels(x, y, w, h, ty, &t);
        c.dirty = true;
    }
}
