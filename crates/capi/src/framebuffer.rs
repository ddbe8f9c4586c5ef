//! Whole-framebuffer operations and reading pixels (GL 2.1 §4.2, §4.3,
//! §5.1): clearing, the write masks, the draw and read buffers,
//! glReadPixels (into client memory or the pixel pack buffer), the pixel
//! store modes, and glFinish / glFlush — which, with glReadPixels, copy
//! the default framebuffer into the client's buffer
//! ([`crate::context::OsContext::sync`]).

use crate::abi::*;
use crate::buffers::MAX_BUFFER_BYTES;
use crate::context::{record_call, with_ctx};
use gl::enums::*;
use std::ffi::c_void;

gl_entry_points! {
    // ---- colour clamping (GL 3.0 §3.7.5, §4.3.2) ----
    [list] fn glClampColor(target: GLenum, clamp: GLenum) => |c| { c.gl.clamp_color(target, clamp) }
    [list] fn glClampColorARB(target: GLenum, clamp: GLenum) => |c| { c.gl.clamp_color(target, clamp) }

    // ---- clearing and masks ----
    [list] fn glClearColor(r: GLclampf, g: GLclampf, b: GLclampf, a: GLclampf) => |c| {
        c.gl.clear_color(r, g, b, a)
    }
    [list] fn glClearDepth(d: GLclampd) => |c| { c.gl.clear_depth(d) }
    [list] fn glClearStencil(s: GLint) => |c| { c.gl.clear_stencil(s) }
    [list] fn glClear(mask: GLbitfield) => |c| { c.gl.clear(mask); c.dirty = true; }
    [list] fn glColorMask(r: GLboolean, g: GLboolean, bl: GLboolean, a: GLboolean) => |c| {
        c.gl.color_mask(as_bool(r), as_bool(g), as_bool(bl), as_bool(a))
    }
    [list] fn glColorMaski(index: GLuint, r: GLboolean, g: GLboolean, bl: GLboolean, a: GLboolean) => |c| {
        c.gl.color_maski(index, as_bool(r), as_bool(g), as_bool(bl), as_bool(a))
    }
    // The value count follows the buffer: four for GL_COLOR, one for
    // GL_DEPTH / GL_STENCIL (an invalid buffer reads nothing).
    [list] fn glClearBufferfv(buffer: GLenum, drawbuffer: GLint, value: *const GLfloat) => |c| {
        let v = rd_vec(value, clear_buffer_values(buffer));
        c.gl.clear_bufferfv(buffer, drawbuffer, &v);
        c.dirty = true;
    }
    [list] fn glClearBufferiv(buffer: GLenum, drawbuffer: GLint, value: *const GLint) => |c| {
        let v = rd_vec(value, clear_buffer_values(buffer));
        c.gl.clear_bufferiv(buffer, drawbuffer, &v);
        c.dirty = true;
    }
    [list] fn glClearBufferuiv(buffer: GLenum, drawbuffer: GLint, value: *const GLuint) => |c| {
        let v = rd_vec(value, clear_buffer_values(buffer));
        c.gl.clear_bufferuiv(buffer, drawbuffer, &v);
        c.dirty = true;
    }
    [list] fn glClearBufferfi(buffer: GLenum, drawbuffer: GLint, depth: GLfloat, stencil: GLint) => |c| {
        c.gl.clear_bufferfi(buffer, drawbuffer, depth, stencil);
        c.dirty = true;
    }
    [list] fn glDepthMask(flag: GLboolean) => |c| { c.gl.depth_mask(as_bool(flag)) }
    [list] fn glStencilMask(mask: GLuint) => |c| { c.gl.stencil_mask(mask) }
    [list] fn glStencilMaskSeparate(face: GLenum, mask: GLuint) => |c| { c.gl.stencil_mask_separate(face, mask) }

    // ---- draw and read buffers ----
    [list] fn glDrawBuffer(buf: GLenum) => |c| { c.gl.draw_buffer(buf) }
    fn glDrawBuffers(n: GLsizei, bufs: *const GLenum) => |c| {
        if n < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        c.gl.draw_buffers(&rd_vec(bufs, (n as i64).min(64)));
    }
    [list] fn glReadBuffer(buf: GLenum) => |c| { c.gl.read_buffer(buf) }

    // ---- reading pixels ----
    fn glPixelStorei(pname: GLenum, param: GLint) => |c| { c.gl.pixel_storei(pname, param) }
    fn glPixelStoref(pname: GLenum, param: GLfloat) => |c| {
        // GL 2.1 §3.6.1: rounded to the nearest integer (booleans: != 0).
        let v = if param.is_nan() { 0 } else { (param as f64 + 0.5).floor().clamp(i32::MIN as f64, i32::MAX as f64) as i32 };
        let v = if matches!(pname, GL_PACK_SWAP_BYTES | GL_PACK_LSB_FIRST | GL_UNPACK_SWAP_BYTES | GL_UNPACK_LSB_FIRST) {
            (param != 0.0) as i32
        } else {
            v
        };
        c.gl.pixel_storei(pname, v)
    }
    fn glReadPixels(
        x: GLint, y: GLint, w: GLsizei, h: GLsizei, format: GLenum, ty: GLenum,
        pixels: *mut c_void
    ) => |c| {
        if let Some(d) = &c.debug {
            crate::debug_env::flush(&mut c.gl, d);
        }
        let store = c.gl.pack_modes();
        let len = if w > 0 && h > 0 && gl::pixel_transfer::pixel_size(format, ty).is_some() {
            gl::pixel_transfer::row_stride(w as usize, format, ty, store.alignment)
                .saturating_mul(h as usize)
        } else {
            0
        };
        if c.gl.bound_buffer(GL_PIXEL_PACK_BUFFER) != 0 || !store.is_packed() {
            // Into the pack buffer at offset `pixels` (GL 2.1 §4.3.5), or
            // laid out per the pack modes: read packed, then placed.
            if len > MAX_BUFFER_BYTES {
                c.gl.record_error(GL_OUT_OF_MEMORY);
                return;
            }
            let mut out = vec![0u8; len];
            let before = c.gl.get_error();
            c.gl.read_pixels(x, y, w, h, format, ty, &mut out);
            let e = c.gl.get_error();
            c.gl.record_error(if before != GL_NO_ERROR { before } else { e });
            if e == GL_NO_ERROR && len > 0 {
                let dims = [w as usize, h as usize, 1];
                crate::buffers::pack_image(c, &out, dims, false, format, ty, pixels);
            }
            c.sync();
            return;
        }
        if pixels.is_null() && len > 0 {
            return;
        }
        let out: &mut [u8] = if len == 0 {
            &mut []
        } else {
            // SAFETY: GL's contract: the client's buffer holds the packed
            // w x h image of format/type at the pack alignment.
            std::slice::from_raw_parts_mut(pixels as *mut u8, len)
        };
        c.gl.read_pixels(x, y, w, h, format, ty, out);
        c.sync();
    }

    // ---- flush and finish ----
    fn glFinish() => |c| { c.gl.finish(); c.sync(); }
    fn glFlush() => |c| { c.gl.flush(); c.sync(); }
}

/// The values glClearBuffer*v reads for `buffer`.
fn clear_buffer_values(buffer: GLenum) -> i64 {
    match buffer {
        GL_COLOR => 4,
        GL_DEPTH | GL_STENCIL => 1,
        _ => 0,
    }
}
