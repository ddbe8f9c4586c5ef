//! eglGetProcAddress: every EGL and GL entry point this library exports
//! (EGL_KHR_get_all_proc_addresses: core functions too), and the GLX
//! names. It names every other module; nothing depends back on it.

use crate::config::*;
use crate::context::*;
use crate::current::*;
use crate::display::*;
use crate::error::*;
use crate::glx::*;
use crate::surface::*;
use crate::sync::*;
use crate::types::EglProc;
use std::ffi::{c_char, CStr};

macro_rules! table {
    ($($f:ident)*) => {
        /// The address of the EGL or GLX function `name`.
        pub fn lookup_egl(name: &str) -> Option<*const ()> {
            match name {
                $(stringify!($f) => Some($f as *const ()),)*
                _ => None,
            }
        }
        /// Every EGL and GLX function name, for tests.
        pub const EGL_NAMES: &[&str] = &[$(stringify!($f)),*];
    };
}

table! {
    eglBindAPI eglBindTexImage eglChooseConfig eglClientWaitSync eglCopyBuffers
    eglCreateContext eglCreateImage eglCreatePbufferFromClientBuffer
    eglCreatePbufferSurface eglCreatePixmapSurface eglCreatePlatformPixmapSurface
    eglCreatePlatformPixmapSurfaceEXT eglCreatePlatformWindowSurface
    eglCreatePlatformWindowSurfaceEXT eglCreateSync eglCreateWindowSurface
    eglDestroyContext eglDestroyImage eglDestroySurface eglDestroySync
    eglGetConfigAttrib eglGetConfigs eglGetCurrentContext eglGetCurrentDisplay
    eglGetCurrentSurface eglGetDisplay eglGetError eglGetPlatformDisplay
    eglGetPlatformDisplayEXT eglGetProcAddress eglGetSyncAttrib eglInitialize
    eglMakeCurrent eglQueryAPI eglQueryContext eglQueryDeviceAttribEXT
    eglQueryDeviceStringEXT eglQueryDevicesEXT eglQueryDisplayAttribEXT
    eglQueryDisplayAttribKHR eglQueryString eglQuerySurface eglReleaseTexImage
    eglReleaseThread eglSurfaceAttrib eglSwapBuffers eglSwapInterval eglTerminate
    eglWaitClient eglWaitGL eglWaitNative eglWaitSync
    glXChooseVisual glXCreateContext glXCreateNewContext glXCreatePixmap
    glXDestroyContext glXGetCurrentContext glXGetCurrentDisplay glXGetCurrentDrawable
    glXGetFBConfigAttrib glXGetFBConfigs glXGetProcAddress glXGetProcAddressARB
    glXGetVisualFromFBConfig glXMakeCurrent glXQueryExtension glXQueryExtensionsString
    glXQueryVersion glXSwapBuffers
}

/// The address of any exported function: EGL, GLX, then capi's gl* (and
/// OSMesa*) table.
pub fn lookup(name: &str) -> Option<*const ()> {
    lookup_egl(name).or_else(|| capi::lookup(name))
}

/// eglGetProcAddress: null for a name this library does not export.
#[no_mangle]
pub unsafe extern "C" fn eglGetProcAddress(name: *const c_char) -> EglProc {
    api(None, || {
        if name.is_null() {
            return Ok(None);
        }
        // SAFETY: a NUL-terminated C string (EGL's contract).
        let Ok(name) = unsafe { CStr::from_ptr(name) }.to_str() else {
            return Ok(None);
        };
        Ok(lookup(name).map(|p| {
            // SAFETY: `p` is one of our extern "C" functions; the caller
            // casts it back to its real signature.
            unsafe { std::mem::transmute::<*const (), unsafe extern "C" fn()>(p) }
        }))
    })
}

/// glXGetProcAddressARB: as eglGetProcAddress.
#[no_mangle]
pub unsafe extern "C" fn glXGetProcAddressARB(name: *const u8) -> Option<unsafe extern "C" fn()> {
    // SAFETY: a NUL-terminated name (GLX's contract).
    unsafe { eglGetProcAddress(name as *const c_char) }
}

/// glXGetProcAddress: as eglGetProcAddress.
#[no_mangle]
pub unsafe extern "C" fn glXGetProcAddress(name: *const u8) -> Option<unsafe extern "C" fn()> {
    // SAFETY: as above.
    unsafe { eglGetProcAddress(name as *const c_char) }
}
