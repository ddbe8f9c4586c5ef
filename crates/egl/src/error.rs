//! The thread's EGL error (eglGetError) and the wrapper every entry point
//! runs its body in: the body returns `Result<T, EGLint>`; `Ok` records
//! EGL_SUCCESS, `Err(code)` records `code` and returns the call's failure
//! value. Panics are caught (recorded as EGL_BAD_ALLOC, counted by
//! capi's panic counter): nothing unwinds into C.

use crate::types::*;
use std::cell::Cell;

thread_local! {
    static ERROR: Cell<EGLint> = const { Cell::new(EGL_SUCCESS) };
}

/// Records `code` as the thread's last error.
pub fn set(code: EGLint) {
    ERROR.with(|e| e.set(code));
}

/// Runs `body`; records its error (or EGL_SUCCESS) and returns its value,
/// or `fail` on error or panic.
pub fn api<T>(fail: T, body: impl FnOnce() -> Result<T, EGLint>) -> T {
    let r = capi::context::guard(Err(EGL_BAD_ALLOC), body);
    match r {
        Ok(v) => {
            set(EGL_SUCCESS);
            v
        }
        Err(code) => {
            set(code);
            fail
        }
    }
}

/// eglGetError: the last error of the calling thread, then EGL_SUCCESS.
#[no_mangle]
pub extern "C" fn eglGetError() -> EGLint {
    ERROR.with(|e| e.replace(EGL_SUCCESS))
}

/// An EGL boolean from a Rust one.
pub fn boolean(b: bool) -> EGLBoolean {
    if b {
        EGL_TRUE
    } else {
        EGL_FALSE
    }
}
