//! Helpers the capi integration tests share (each test file is its own
//! crate and takes this module with `mod common;`).

use gl::enums::*;
use std::ffi::{c_void, CString};
use OSMesa::*;

/// Asserts OSMesaGetProcAddress finds every name.
#[allow(dead_code)]
pub fn assert_exported(names: &[&str]) {
    for name in names {
        let c = CString::new(*name).unwrap();
        assert!(
            unsafe { OSMesaGetProcAddress(c.as_ptr()) }.is_some(),
            "{name}"
        );
    }
}

/// The current context's RGBA8 pixel at (x, y), through glReadPixels.
///
/// # Safety
/// A context is current.
#[allow(dead_code)]
pub unsafe fn pixel_at(x: i32, y: i32) -> [u8; 4] {
    let mut p = [0u8; 4];
    glReadPixels(
        x,
        y,
        1,
        1,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        p.as_mut_ptr() as *mut c_void,
    );
    p
}

/// A context made current on `buf` (resized to `w`×`h` RGBA8): with
/// `profile` None a compatibility context from OSMesaCreateContextExt
/// (24 depth bits, 8 stencil bits), with Some(OSMESA_CORE_PROFILE or
/// OSMESA_COMPAT_PROFILE) a 3.3 context of that profile from
/// OSMesaCreateContextAttribs (the same buffers).
///
/// # Safety
/// `buf` outlives the context's use.
#[allow(dead_code)]
pub unsafe fn current_context(
    buf: &mut Vec<u8>,
    w: i32,
    h: i32,
    profile: Option<i32>,
) -> OSMesaContext {
    *buf = vec![0u8; (w * h * 4) as usize];
    let ctx = match profile {
        None => OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, std::ptr::null_mut()),
        Some(profile) => {
            let attribs = [
                OSMESA_FORMAT,
                OSMESA_RGBA as i32,
                OSMESA_DEPTH_BITS,
                24,
                OSMESA_STENCIL_BITS,
                8,
                OSMESA_PROFILE,
                profile,
                OSMESA_CONTEXT_MAJOR_VERSION,
                3,
                OSMESA_CONTEXT_MINOR_VERSION,
                3,
                0,
            ];
            OSMesaCreateContextAttribs(attribs.as_ptr(), std::ptr::null_mut())
        }
    };
    assert!(!ctx.is_null());
    let made = OSMesaMakeCurrent(ctx, buf.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, w, h);
    assert_eq!(made, OSMesa::GL_TRUE);
    ctx
}
