//! Surfaces: pbuffers (their own RGBA8 color buffer, plus depth and
//! stencil buffers when the config has them). Windows and pixmaps need a
//! native window system and are refused as EGL 1.5 §3.5 says for a config
//! without EGL_WINDOW_BIT / EGL_PIXMAP_BIT (EGL_BAD_MATCH).
//! eglSwapBuffers on a pbuffer has no effect (§3.10.1) beyond the implicit
//! flush (every GL call has completed when it returns).

use crate::config::{self, MAX_PBUFFER};
use crate::current;
use crate::error::api;
use crate::objects::{self, buffers, Surface};
use crate::types::*;
use std::ffi::c_void;

/// eglCreatePbufferSurface.
#[no_mangle]
pub unsafe extern "C" fn eglCreatePbufferSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    attribs: *const EGLint,
) -> EGLSurface {
    // SAFETY: EGL's contract for the list.
    let list = unsafe { config::pairs(attribs) };
    api(std::ptr::null_mut(), || {
        let mut o = objects::lock();
        let d = o.initialized(dpy)?;
        let c = config::lookup(d, config)?;
        let (mut w, mut h, mut largest) = (0, 0, false);
        for (a, v) in list {
            match a {
                EGL_WIDTH | EGL_HEIGHT if v < 0 => return Err(EGL_BAD_PARAMETER),
                EGL_WIDTH => w = v,
                EGL_HEIGHT => h = v,
                EGL_LARGEST_PBUFFER => largest = v != 0,
                EGL_TEXTURE_FORMAT | EGL_TEXTURE_TARGET if v != EGL_NO_TEXTURE => {
                    return Err(EGL_BAD_MATCH)
                }
                EGL_TEXTURE_FORMAT | EGL_TEXTURE_TARGET | EGL_MIPMAP_TEXTURE => {}
                EGL_GL_COLORSPACE if v != EGL_GL_COLORSPACE_LINEAR => return Err(EGL_BAD_MATCH),
                EGL_GL_COLORSPACE | EGL_VG_COLORSPACE | EGL_VG_ALPHA_FORMAT => {}
                _ => return Err(EGL_BAD_ATTRIBUTE),
            }
        }
        if w > MAX_PBUFFER || h > MAX_PBUFFER {
            if !largest {
                return Err(EGL_BAD_ALLOC);
            }
            w = w.min(MAX_PBUFFER);
            h = h.min(MAX_PBUFFER);
        }
        let id = o.new_id();
        o.surfaces.insert(
            id,
            Surface {
                display: d,
                config: c,
                width: w,
                height: h,
                largest,
                swap_behavior: EGL_BUFFER_PRESERVED,
                buffers: Some(buffers(c, w, h)),
                bound_to: 0,
                destroyed: false,
            },
        );
        Ok(id as EGLSurface)
    })
}

/// A window or pixmap surface: the display and config are checked, then
/// refused (no config supports them).
fn native_surface(dpy: EGLDisplay, config: EGLConfig) -> EGLSurface {
    api(std::ptr::null_mut(), || {
        let d = objects::lock().initialized(dpy)?;
        config::lookup(d, config)?;
        Err(EGL_BAD_MATCH)
    })
}

/// eglCreateWindowSurface: EGL_BAD_MATCH (no window configs).
#[no_mangle]
pub extern "C" fn eglCreateWindowSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    _win: EGLNativeWindowType,
    _attribs: *const EGLint,
) -> EGLSurface {
    native_surface(dpy, config)
}

/// eglCreatePlatformWindowSurface: EGL_BAD_MATCH.
#[no_mangle]
pub extern "C" fn eglCreatePlatformWindowSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    _win: *mut c_void,
    _attribs: *const EGLAttrib,
) -> EGLSurface {
    native_surface(dpy, config)
}

/// eglCreatePlatformWindowSurfaceEXT: EGL_BAD_MATCH.
#[no_mangle]
pub extern "C" fn eglCreatePlatformWindowSurfaceEXT(
    dpy: EGLDisplay,
    config: EGLConfig,
    _win: *mut c_void,
    _attribs: *const EGLint,
) -> EGLSurface {
    native_surface(dpy, config)
}

/// eglCreatePixmapSurface: EGL_BAD_MATCH (no pixmap configs).
#[no_mangle]
pub extern "C" fn eglCreatePixmapSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    _pixmap: EGLNativePixmapType,
    _attribs: *const EGLint,
) -> EGLSurface {
    native_surface(dpy, config)
}

/// eglCreatePlatformPixmapSurface: EGL_BAD_MATCH.
#[no_mangle]
pub extern "C" fn eglCreatePlatformPixmapSurface(
    dpy: EGLDisplay,
    config: EGLConfig,
    _pixmap: *mut c_void,
    _attribs: *const EGLAttrib,
) -> EGLSurface {
    native_surface(dpy, config)
}

/// eglCreatePlatformPixmapSurfaceEXT: EGL_BAD_MATCH.
#[no_mangle]
pub extern "C" fn eglCreatePlatformPixmapSurfaceEXT(
    dpy: EGLDisplay,
    config: EGLConfig,
    _pixmap: *mut c_void,
    _attribs: *const EGLint,
) -> EGLSurface {
    native_surface(dpy, config)
}

/// eglCreatePbufferFromClientBuffer: no client buffer type is supported
/// (EGL_BAD_PARAMETER).
#[no_mangle]
pub extern "C" fn eglCreatePbufferFromClientBuffer(
    dpy: EGLDisplay,
    _buftype: EGLenum,
    _buffer: EGLClientBuffer,
    config: EGLConfig,
    _attribs: *const EGLint,
) -> EGLSurface {
    api(std::ptr::null_mut(), || {
        let d = objects::lock().initialized(dpy)?;
        config::lookup(d, config)?;
        Err(EGL_BAD_PARAMETER)
    })
}

/// eglDestroySurface: freed now, or when released if current.
#[no_mangle]
pub extern "C" fn eglDestroySurface(dpy: EGLDisplay, surface: EGLSurface) -> EGLBoolean {
    api(EGL_FALSE, || {
        let mut o = objects::lock();
        let d = o.initialized(dpy)?;
        o.surface(d, surface)?.destroyed = true;
        o.reap_surface(surface as usize);
        Ok(EGL_TRUE)
    })
}

/// eglQuerySurface.
#[no_mangle]
pub unsafe extern "C" fn eglQuerySurface(
    dpy: EGLDisplay,
    surface: EGLSurface,
    attribute: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    api(EGL_FALSE, || {
        let mut o = objects::lock();
        let d = o.initialized(dpy)?;
        let s = o.surface(d, surface)?;
        let v = match attribute {
            EGL_CONFIG_ID => s.config.id,
            EGL_WIDTH => s.width,
            EGL_HEIGHT => s.height,
            EGL_LARGEST_PBUFFER => s.largest as EGLint,
            EGL_RENDER_BUFFER => EGL_BACK_BUFFER,
            EGL_SWAP_BEHAVIOR => s.swap_behavior,
            EGL_TEXTURE_FORMAT | EGL_TEXTURE_TARGET => EGL_NO_TEXTURE,
            EGL_MIPMAP_TEXTURE | EGL_MIPMAP_LEVEL => 0,
            EGL_MULTISAMPLE_RESOLVE => EGL_MULTISAMPLE_RESOLVE_DEFAULT,
            EGL_HORIZONTAL_RESOLUTION | EGL_VERTICAL_RESOLUTION | EGL_PIXEL_ASPECT_RATIO => {
                EGL_UNKNOWN
            }
            EGL_GL_COLORSPACE => EGL_GL_COLORSPACE_LINEAR,
            EGL_VG_ALPHA_FORMAT => EGL_VG_ALPHA_FORMAT_NONPRE,
            EGL_VG_COLORSPACE => EGL_VG_COLORSPACE_SRGB,
            _ => return Err(EGL_BAD_ATTRIBUTE),
        };
        if value.is_null() {
            return Err(EGL_BAD_PARAMETER);
        }
        // SAFETY: one EGLint.
        unsafe { *value = v };
        Ok(EGL_TRUE)
    })
}

/// eglSurfaceAttrib: EGL_SWAP_BEHAVIOR (either value: swapping a pbuffer
/// changes nothing), EGL_MIPMAP_LEVEL (no effect), EGL_MULTISAMPLE_RESOLVE
/// (the default only).
#[no_mangle]
pub extern "C" fn eglSurfaceAttrib(
    dpy: EGLDisplay,
    surface: EGLSurface,
    attribute: EGLint,
    value: EGLint,
) -> EGLBoolean {
    api(EGL_FALSE, || {
        let mut o = objects::lock();
        let d = o.initialized(dpy)?;
        let s = o.surface(d, surface)?;
        match (attribute, value) {
            (EGL_SWAP_BEHAVIOR, EGL_BUFFER_PRESERVED | EGL_BUFFER_DESTROYED) => {
                s.swap_behavior = value
            }
            (EGL_MIPMAP_LEVEL, _) => {}
            (EGL_MULTISAMPLE_RESOLVE, EGL_MULTISAMPLE_RESOLVE_DEFAULT) => {}
            (EGL_SWAP_BEHAVIOR | EGL_MULTISAMPLE_RESOLVE, _) => return Err(EGL_BAD_PARAMETER),
            _ => return Err(EGL_BAD_ATTRIBUTE),
        }
        Ok(EGL_TRUE)
    })
}

/// eglSwapBuffers: `surface` must be the calling thread's current draw
/// surface (EGL_BAD_SURFACE otherwise); a pbuffer's contents stay.
#[no_mangle]
pub extern "C" fn eglSwapBuffers(dpy: EGLDisplay, surface: EGLSurface) -> EGLBoolean {
    api(EGL_FALSE, || {
        let mut o = objects::lock();
        let d = o.initialized(dpy)?;
        o.surface(d, surface)?;
        // EGL 1.5 §3.10.4: a surface that is not the draw surface of the
        // thread's current context (none current included) is
        // EGL_BAD_SURFACE.
        let t = current::thread();
        if t.ctx == 0 || t.draw != surface as usize {
            return Err(EGL_BAD_SURFACE);
        }
        Ok(EGL_TRUE)
    })
}

/// eglSwapInterval: accepted and ignored (pbuffers are not presented).
#[no_mangle]
pub extern "C" fn eglSwapInterval(dpy: EGLDisplay, _interval: EGLint) -> EGLBoolean {
    api(EGL_FALSE, || {
        objects::lock().initialized(dpy)?;
        let t = current::thread();
        if t.ctx == 0 {
            return Err(EGL_BAD_CONTEXT);
        }
        if t.draw == 0 {
            return Err(EGL_BAD_SURFACE);
        }
        Ok(EGL_TRUE)
    })
}

/// eglBindTexImage / eglReleaseTexImage: no surface has a texture format
/// (EGL_BAD_MATCH).
#[no_mangle]
pub extern "C" fn eglBindTexImage(
    dpy: EGLDisplay,
    surface: EGLSurface,
    _buffer: EGLint,
) -> EGLBoolean {
    api(EGL_FALSE, || {
        let mut o = objects::lock();
        let d = o.initialized(dpy)?;
        o.surface(d, surface)?;
        Err(EGL_BAD_MATCH)
    })
}

/// eglReleaseTexImage: EGL_BAD_MATCH, as eglBindTexImage.
#[no_mangle]
pub extern "C" fn eglReleaseTexImage(
    dpy: EGLDisplay,
    surface: EGLSurface,
    buffer: EGLint,
) -> EGLBoolean {
    eglBindTexImage(dpy, surface, buffer)
}

/// eglCopyBuffers: there are no native pixmaps (EGL_BAD_NATIVE_PIXMAP).
#[no_mangle]
pub extern "C" fn eglCopyBuffers(
    dpy: EGLDisplay,
    surface: EGLSurface,
    _target: EGLNativePixmapType,
) -> EGLBoolean {
    api(EGL_FALSE, || {
        let mut o = objects::lock();
        let d = o.initialized(dpy)?;
        o.surface(d, surface)?;
        Err(EGL_BAD_NATIVE_PIXMAP)
    })
}
