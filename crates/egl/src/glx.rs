//! The GLX entry points a libGL.so.1 must export for programs linked
//! against it (piglit's libpiglitutil_gl.so.0 binds 16 of them at load
//! time): glXGetProcAddress(ARB) ([`crate::procs`]) return every GL and
//! EGL entry point; the rest need an X display, which a headless library does not have, and
//! fail as GLX says for one (null, False, 0, GLX_NO_EXTENSION).

use std::ffi::{c_char, c_int, c_ulong, c_void};

/// GLX's "no GLX extension on this display" error code.
pub const GLX_NO_EXTENSION: c_int = 3;

#[no_mangle]
pub extern "C" fn glXChooseVisual(
    _dpy: *mut c_void,
    _screen: c_int,
    _attribs: *mut c_int,
) -> *mut c_void {
    std::ptr::null_mut()
}

#[no_mangle]
pub extern "C" fn glXCreateContext(
    _dpy: *mut c_void,
    _vis: *mut c_void,
    _share: *mut c_void,
    _direct: c_int,
) -> *mut c_void {
    std::ptr::null_mut()
}

#[no_mangle]
pub extern "C" fn glXCreateNewContext(
    _dpy: *mut c_void,
    _config: *mut c_void,
    _render_type: c_int,
    _share: *mut c_void,
    _direct: c_int,
) -> *mut c_void {
    std::ptr::null_mut()
}

#[no_mangle]
pub extern "C" fn glXCreatePixmap(
    _dpy: *mut c_void,
    _config: *mut c_void,
    _pixmap: c_ulong,
    _attribs: *const c_int,
) -> c_ulong {
    0
}

#[no_mangle]
pub extern "C" fn glXDestroyContext(_dpy: *mut c_void, _ctx: *mut c_void) {}

#[no_mangle]
pub extern "C" fn glXGetCurrentDisplay() -> *mut c_void {
    std::ptr::null_mut()
}

#[no_mangle]
pub extern "C" fn glXGetCurrentDrawable() -> c_ulong {
    0
}

#[no_mangle]
pub extern "C" fn glXGetCurrentContext() -> *mut c_void {
    std::ptr::null_mut()
}

#[no_mangle]
pub extern "C" fn glXGetFBConfigAttrib(
    _dpy: *mut c_void,
    _config: *mut c_void,
    _attribute: c_int,
    _value: *mut c_int,
) -> c_int {
    GLX_NO_EXTENSION
}

#[no_mangle]
pub unsafe extern "C" fn glXGetFBConfigs(
    _dpy: *mut c_void,
    _screen: c_int,
    nelements: *mut c_int,
) -> *mut c_void {
    if !nelements.is_null() {
        // SAFETY: one int (GLX's contract).
        unsafe { *nelements = 0 };
    }
    std::ptr::null_mut()
}

#[no_mangle]
pub extern "C" fn glXGetVisualFromFBConfig(_dpy: *mut c_void, _config: *mut c_void) -> *mut c_void {
    std::ptr::null_mut()
}

#[no_mangle]
pub extern "C" fn glXMakeCurrent(
    _dpy: *mut c_void,
    _drawable: c_ulong,
    _ctx: *mut c_void,
) -> c_int {
    0
}

#[no_mangle]
pub extern "C" fn glXQueryExtension(
    _dpy: *mut c_void,
    _error_base: *mut c_int,
    _event_base: *mut c_int,
) -> c_int {
    0
}

#[no_mangle]
pub extern "C" fn glXQueryExtensionsString(_dpy: *mut c_void, _screen: c_int) -> *const c_char {
    std::ptr::null()
}

#[no_mangle]
pub extern "C" fn glXQueryVersion(
    _dpy: *mut c_void,
    _major: *mut c_int,
    _minor: *mut c_int,
) -> c_int {
    0
}

#[no_mangle]
pub extern "C" fn glXSwapBuffers(_dpy: *mut c_void, _drawable: c_ulong) {}
