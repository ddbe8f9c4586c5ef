//! The OSMesa context API (Mesa's `GL/osmesa.h`), C ABI.

use crate::abi::*;
use crate::context::{self, guard, with_ctx, OsContext};
use crate::osmesa_enums::*;
use std::ffi::c_void;

/// Largest buffer width/height accepted (OSMESA_MAX_WIDTH/HEIGHT).
pub const MAX_SIZE: i32 = gl::MAX_TEXTURE_SIZE;

/// Most attribute pairs read from an OSMesaCreateContextAttribs list.
const MAX_ATTRIBS: usize = 256;

/// An opaque OSMesa context handle.
pub type OSMesaContext = *mut OsContext;

/// OSMesa's `OSMESAproc`.
pub type OSMESAproc = Option<unsafe extern "C" fn()>;

fn create(api: gl::Api, format: u32, depth: i32, stencil: i32, accum: i32) -> OSMesaContext {
    if !matches!(
        format,
        OSMESA_RGBA | OSMESA_BGRA | OSMESA_ARGB | OSMESA_RGB | OSMESA_BGR | OSMESA_RGB_565
    ) {
        return std::ptr::null_mut();
    }
    let p = Box::into_raw(Box::new(OsContext::new(api, format, depth, stencil, accum)));
    context::register(p);
    p
}

/// OSMesaCreateContext: `format` with a depth, stencil (and no accum)
/// buffer. `sharelist` is accepted but objects are not shared.
#[no_mangle]
pub extern "C" fn OSMesaCreateContext(format: GLenum, _sharelist: OSMesaContext) -> OSMesaContext {
    guard(std::ptr::null_mut(), || {
        create(gl::Api::GL21, format, 24, 8, 0)
    })
}

/// OSMesaCreateContextExt.
#[no_mangle]
pub extern "C" fn OSMesaCreateContextExt(
    format: GLenum,
    depth_bits: GLint,
    stencil_bits: GLint,
    accum_bits: GLint,
    _sharelist: OSMesaContext,
) -> OSMesaContext {
    guard(std::ptr::null_mut(), || {
        create(gl::Api::GL21, format, depth_bits, stencil_bits, accum_bits)
    })
}

/// OSMesaCreateContextAttribs: a 0-terminated list of (name, value) pairs.
/// The version and profile asked for choose the context's API as
/// [`gl::Api::for_request`] says (the default, 1.0 compatibility, is a 2.1
/// context); a version beyond 3.3, an unknown profile or attribute, or a
/// bad format gives NULL, as Mesa's OSMesa does.
#[no_mangle]
pub unsafe extern "C" fn OSMesaCreateContextAttribs(
    attrib_list: *const GLint,
    _sharelist: OSMesaContext,
) -> OSMesaContext {
    guard(std::ptr::null_mut(), || {
        let (mut format, mut depth, mut stencil, mut accum) = (OSMESA_RGBA, 24, 8, 0);
        let (mut major, mut minor) = (1, 0);
        let mut profile = gl::Profile::Compatibility;
        if !attrib_list.is_null() {
            for i in 0..MAX_ATTRIBS {
                // SAFETY: the caller's list is 0-terminated (osmesa.h).
                let name = unsafe { *attrib_list.add(2 * i) };
                if name == 0 {
                    break;
                }
                let value = unsafe { *attrib_list.add(2 * i + 1) };
                match name {
                    OSMESA_FORMAT => format = value as u32,
                    OSMESA_DEPTH_BITS => depth = value,
                    OSMESA_STENCIL_BITS => stencil = value,
                    OSMESA_ACCUM_BITS => accum = value,
                    OSMESA_PROFILE => {
                        profile = match value {
                            OSMESA_COMPAT_PROFILE => gl::Profile::Compatibility,
                            OSMESA_CORE_PROFILE => gl::Profile::Core,
                            _ => return std::ptr::null_mut(),
                        }
                    }
                    OSMESA_CONTEXT_MAJOR_VERSION => major = value,
                    OSMESA_CONTEXT_MINOR_VERSION => minor = value,
                    _ => return std::ptr::null_mut(),
                }
            }
        }
        let Some(api) = gl::Api::for_request(major, minor, profile) else {
            return std::ptr::null_mut();
        };
        create(api, format, depth, stencil, accum)
    })
}

/// OSMesaDestroyContext.
#[no_mangle]
pub unsafe extern "C" fn OSMesaDestroyContext(ctx: OSMesaContext) {
    guard((), || {
        if ctx.is_null() || !context::unregister(ctx) {
            return;
        }
        if context::current() == ctx {
            context::set_current(std::ptr::null_mut());
        }
        // SAFETY: `ctx` is live; the client's buffer is still valid.
        unsafe { &mut *ctx }.sync();
        // SAFETY: `ctx` was live (created by Box::into_raw, not yet freed).
        drop(unsafe { Box::from_raw(ctx) });
    })
}

/// OSMesaMakeCurrent: renders into `buffer` (`width` x `height` pixels of
/// the context's format and `ty`) from now on. A null context releases the
/// current one.
#[no_mangle]
pub unsafe extern "C" fn OSMesaMakeCurrent(
    ctx: OSMesaContext,
    buffer: *mut c_void,
    ty: GLenum,
    width: GLsizei,
    height: GLsizei,
) -> GLboolean {
    guard(GL_FALSE, || {
        let old = context::current();
        if ctx.is_null() {
            if !old.is_null() {
                with_ctx((), |c| c.sync());
            }
            context::set_current(std::ptr::null_mut());
            return GL_TRUE;
        }
        if !context::is_live(ctx)
            || buffer.is_null()
            || !(1..=MAX_SIZE).contains(&width)
            || !(1..=MAX_SIZE).contains(&height)
        {
            return GL_FALSE;
        }
        // SAFETY: live context (checked above), used by this thread only.
        let c = unsafe { &mut *ctx };
        if OsContext::pixel_bytes(c.format, ty).is_none() {
            return GL_FALSE;
        }
        if !old.is_null() && old != ctx {
            with_ctx((), |o| o.sync());
        }
        c.buffer = buffer;
        c.ty = ty;
        c.width = width;
        c.height = height;
        c.gl.resize_default_framebuffer(width, height);
        if !c.sized {
            c.sized = true;
            c.gl.viewport(0, 0, width, height);
            c.gl.scissor(0, 0, width, height);
        }
        context::set_current(ctx);
        c.upload();
        GL_TRUE
    })
}

/// OSMesaGetCurrentContext.
#[no_mangle]
pub extern "C" fn OSMesaGetCurrentContext() -> OSMesaContext {
    context::current()
}

/// OSMesaPixelStore: OSMESA_ROW_LENGTH (pixels, >= 0) and OSMESA_Y_UP.
#[no_mangle]
pub extern "C" fn OSMesaPixelStore(pname: GLint, value: GLint) {
    with_ctx((), |c| {
        c.sync();
        match pname {
            OSMESA_ROW_LENGTH if value >= 0 => c.row_length = value,
            OSMESA_Y_UP => c.y_up = value != 0,
            OSMESA_ROW_LENGTH => c.gl.record_error(gl::enums::GL_INVALID_VALUE),
            _ => c.gl.record_error(gl::enums::GL_INVALID_ENUM),
        }
        c.upload();
    })
}

/// OSMesaGetIntegerv.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetIntegerv(pname: GLint, value: *mut GLint) {
    with_ctx((), |c| {
        let v = match pname {
            OSMESA_WIDTH => c.width,
            OSMESA_HEIGHT => c.height,
            OSMESA_FORMAT => c.format as i32,
            OSMESA_TYPE => c.ty as i32,
            OSMESA_ROW_LENGTH => c.row_length,
            OSMESA_Y_UP => c.y_up as i32,
            OSMESA_MAX_WIDTH | OSMESA_MAX_HEIGHT => MAX_SIZE,
            _ => {
                c.gl.record_error(gl::enums::GL_INVALID_ENUM);
                return;
            }
        };
        if !value.is_null() {
            // SAFETY: the caller passes a pointer to one GLint.
            unsafe { *value = v };
        }
    })
}

/// OSMesaGetDepthBuffer: a copy of the depth buffer, refreshed by this
/// call (2 bytes per value for <= 16 requested bits, else 4, unsigned
/// normalized), bottom row first.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetDepthBuffer(
    ctx: OSMesaContext,
    width: *mut GLint,
    height: *mut GLint,
    bytes_per_value: *mut GLint,
    buffer: *mut *mut c_void,
) -> GLboolean {
    guard(GL_FALSE, || {
        let got = if context::is_live(ctx) {
            // SAFETY: live context.
            let c = unsafe { &mut *ctx };
            c.depth_buffer().map(|(p, b)| (c.width, c.height, b, p))
        } else {
            None
        };
        let (w, h, b, p) = got.unwrap_or((0, 0, 0, std::ptr::null_mut()));
        // SAFETY: out pointers per osmesa.h (null ones skipped).
        unsafe {
            write_opt(width, w);
            write_opt(height, h);
            write_opt(bytes_per_value, b);
            if !buffer.is_null() {
                *buffer = p;
            }
        }
        if got.is_some() {
            GL_TRUE
        } else {
            GL_FALSE
        }
    })
}

/// OSMesaGetColorBuffer: the client buffer, brought up to date.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetColorBuffer(
    ctx: OSMesaContext,
    width: *mut GLint,
    height: *mut GLint,
    format: *mut GLint,
    buffer: *mut *mut c_void,
) -> GLboolean {
    guard(GL_FALSE, || {
        let got = if context::is_live(ctx) {
            // SAFETY: live context.
            let c = unsafe { &mut *ctx };
            c.sync();
            (!c.buffer.is_null()).then_some((c.width, c.height, c.format as i32, c.buffer))
        } else {
            None
        };
        let (w, h, f, p) = got.unwrap_or((0, 0, 0, std::ptr::null_mut()));
        // SAFETY: out pointers per osmesa.h (null ones skipped).
        unsafe {
            write_opt(width, w);
            write_opt(height, h);
            write_opt(format, f);
            if !buffer.is_null() {
                *buffer = p;
            }
        }
        if got.is_some() {
            GL_TRUE
        } else {
            GL_FALSE
        }
    })
}

/// OSMesaColorClamp: colors are always clamped (fixed-point buffers).
#[no_mangle]
pub extern "C" fn OSMesaColorClamp(_enable: GLboolean) {}

unsafe fn write_opt(p: *mut GLint, v: GLint) {
    if !p.is_null() {
        // SAFETY: caller's out pointer.
        unsafe { *p = v };
    }
}
