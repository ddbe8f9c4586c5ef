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
