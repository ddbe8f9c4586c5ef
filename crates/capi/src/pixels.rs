//! Texture image transfers beyond glTexImage*/glTexSubImage2D: reading a
//! texture back (glGetTexImage, into client memory or a pixel pack
//! buffer), 1D and 3D sub-images, and copies from the read framebuffer
//! (glCopyTexImage*, glCopyTexSubImage*; GL 2.1 §3.8.2, §6.1.4).

use crate::abi::*;
use crate::buffers::image_bytes;
use crate::context::{record_call, with_ctx, OsContext};
use gl::enums::*;
use std::ffi::c_void;

/// Largest copy made by one glCopyTex* call (larger: GL_OUT_OF_MEMORY).
const MAX_COPY_PIXELS: usize = 1 << 24;

/// The framebuffer block `x, y, w, h` as tightly packed GL_FLOAT data of
/// `format` (GL_RGBA or GL_DEPTH_COMPONENT), or None with the read's error
/// recorded. Pack alignment is 4 for the read (float rows are whole
/// words) and restored after.
fn read_block(c: &mut OsContext, x: i32, y: i32, w: i32, h: i32, format: u32) -> Option<Vec<u8>> {
    if w < 0 || h < 0 {
        c.gl.record_error(GL_INVALID_VALUE);
        return None;
    }
    let n = (w as usize).saturating_mul(h as usize);
    if n > MAX_COPY_PIXELS {
        c.gl.record_error(GL_OUT_OF_MEMORY);
        return None;
    }
    let comps = if format == GL_DEPTH_COMPONENT { 1 } else { 4 };
    let mut out = vec![0u8; n * comps * 4];
    let align =
        c.gl.get_integerv(GL_PACK_ALIGNMENT)
            .first()
            .copied()
            .unwrap_or(4);
    c.gl.pixel_storei(GL_PACK_ALIGNMENT, 4);
    let before = c.gl.get_error();
    c.gl.read_pixels(x, y, w, h, format, GL_FLOAT, &mut out);
    let e = c.gl.get_error();
    c.gl.pixel_storei(GL_PACK_ALIGNMENT, align);
    let _ = c.gl.get_error();
    c.gl.record_error(if before != GL_NO_ERROR { before } else { e });
    (e == GL_NO_ERROR).then_some(out)
}

/// Runs `f` with the unpack alignment at 4 (the float data built here has
/// no row padding), restoring it after.
fn with_unpack_4(c: &mut OsContext, f: impl FnOnce(&mut OsContext)) {
    let align =
        c.gl.get_integerv(GL_UNPACK_ALIGNMENT)
            .first()
            .copied()
            .unwrap_or(4);
    c.gl.pixel_storei(GL_UNPACK_ALIGNMENT, 4);
    f(c);
    let before = c.gl.get_error();
    c.gl.pixel_storei(GL_UNPACK_ALIGNMENT, align);
    let _ = c.gl.get_error();
    c.gl.record_error(before);
}

/// The internal format of the image a sub-image copy targets (None: an
/// error was recorded, or no image).
fn target_format(c: &mut OsContext, target: u32, level: i32) -> Option<i32> {
    let before = c.gl.get_error();
    let f =
        c.gl.get_tex_level_parameteriv(target, level, GL_TEXTURE_INTERNAL_FORMAT);
    let e = c.gl.get_error();
    c.gl.record_error(if before != GL_NO_ERROR { before } else { e });
    (e == GL_NO_ERROR).then_some(f)
}

/// glCopyTexImage{1,2}D.
#[allow(clippy::too_many_arguments)]
fn copy_tex_image(
    c: &mut OsContext,
    dims: u32,
    target: u32,
    level: i32,
    internal: u32,
    x: i32,
    y: i32,
    w: i32,
    h: i32,
    border: i32,
) {
    if c.gl.reject_in_begin() {
        return;
    }
    if gl::texture_format::base_format(internal as i32).is_none() {
        c.gl.record_error(GL_INVALID_VALUE);
        return;
    }
    if border != 0 {
        c.gl.record_error(GL_INVALID_VALUE);
        return;
    }
    let format = if gl::texture_format::is_depth_format(internal as i32) {
        GL_DEPTH_COMPONENT
    } else {
        GL_RGBA
    };
    let Some(data) = read_block(c, x, y, w, h, format) else {
        return;
    };
    let (internal, data) = (internal as i32, Some(&data[..]));
    with_unpack_4(c, |c| {
        if dims == 1 {
            c.gl.tex_image(target, level, internal, [w], 0, format, GL_FLOAT, data)
        } else {
            c.gl.tex_image(target, level, internal, [w, h], 0, format, GL_FLOAT, data)
        }
    });
}

/// glCopyTexSubImage{1,2,3}D: `off` is the texel offset (z: the slice).
#[allow(clippy::too_many_arguments)]
fn copy_tex_sub_image(
    c: &mut OsContext,
    dims: u32,
    target: u32,
    level: i32,
    off: [i32; 3],
    x: i32,
    y: i32,
    w: i32,
    h: i32,
) {
    if c.gl.reject_in_begin() {
        return;
    }
    let Some(internal) = target_format(c, target, level) else {
        return;
    };
    let format = if gl::texture_format::is_depth_format(internal) {
        GL_DEPTH_COMPONENT
    } else {
        GL_RGBA
    };
    let Some(data) = read_block(c, x, y, w, h, format) else {
        return;
    };
    with_unpack_4(c, |c| match dims {
        1 => {
            c.gl.tex_sub_image(target, level, [off[0]], [w], format, GL_FLOAT, &data)
        }
        2 => c.gl.tex_sub_image(
            target,
            level,
            [off[0], off[1]],
            [w, h],
            format,
            GL_FLOAT,
            &data,
        ),
        _ => {
            c.gl.tex_sub_image(target, level, off, [w, h, 1], format, GL_FLOAT, &data)
        }
    });
    c.dirty = true;
}

gl_entry_points! {
    fn glGetTexImage(target: GLenum, level: GLint, format: GLenum, ty: GLenum, pixels: *mut c_void) => |c| {
        let bytes = c.gl.get_tex_image(target, level, format, ty);
        if bytes.is_empty() {
            return;
        }
        // The level's size, for the pack modes' layout; three-dimensional
        // targets' images are volumes (GL 2.1 §6.1.4).
        let mut dims = [0usize; 3];
        for (d, pname) in dims.iter_mut().zip([GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_DEPTH]) {
            *d = c.gl.get_tex_level_parameteriv(target, level, pname).max(1) as usize;
        }
        let volume = matches!(target, GL_TEXTURE_3D | GL_TEXTURE_2D_ARRAY);
        crate::buffers::pack_image(c, &bytes, dims, volume, format, ty, pixels);
    }
    fn glTexSubImage1D(
        target: GLenum, level: GLint, xoff: GLint, w: GLsizei, format: GLenum, ty: GLenum,
        data: *const c_void
    ) => |c| {
        let Ok(bytes) = image_bytes(c, w, 1, 1, false, format, ty, data) else { return };
        let bytes = bytes.unwrap_or_default();
        c.gl.tex_sub_image(target, level, [xoff], [w], format, ty, &bytes);
    }
    fn glTexSubImage3D(
        target: GLenum, level: GLint, xoff: GLint, yoff: GLint, zoff: GLint, w: GLsizei,
        h: GLsizei, d: GLsizei, format: GLenum, ty: GLenum, data: *const c_void
    ) => |c| {
        let Ok(bytes) = image_bytes(c, w, h, d, true, format, ty, data) else { return };
        let bytes = bytes.unwrap_or_default();
        c.gl.tex_sub_image(target, level, [xoff, yoff, zoff], [w, h, d], format, ty, &bytes);
    }
    [list] fn glCopyTexImage1D(
        target: GLenum, level: GLint, internal: GLenum, x: GLint, y: GLint, w: GLsizei,
        border: GLint
    ) => |c| { copy_tex_image(c, 1, target, level, internal, x, y, w, 1, border) }
    [list] fn glCopyTexImage2D(
        target: GLenum, level: GLint, internal: GLenum, x: GLint, y: GLint, w: GLsizei,
        h: GLsizei, border: GLint
    ) => |c| { copy_tex_image(c, 2, target, level, internal, x, y, w, h, border) }
    [list] fn glCopyTexSubImage1D(
        target: GLenum, level: GLint, xoff: GLint, x: GLint, y: GLint, w: GLsizei
    ) => |c| { copy_tex_sub_image(c, 1, target, level, [xoff, 0, 0], x, y, w, 1) }
    [list] fn glCopyTexSubImage2D(
        target: GLenum, level: GLint, xoff: GLint, yoff: GLint, x: GLint, y: GLint,
        w: GLsizei, h: GLsizei
    ) => |c| { copy_tex_sub_image(c, 2, target, level, [xoff, yoff, 0], x, y, w, h) }
    [list] fn glCopyTexSubImage3D(
        target: GLenum, level: GLint, xoff: GLint, yoff: GLint, zoff: GLint, x: GLint,
        y: GLint, w: GLsizei, h: GLsizei
    ) => |c| { copy_tex_sub_image(c, 3, target, level, [xoff, yoff, zoff], x, y, w, h) }
}
