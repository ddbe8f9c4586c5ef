//! Displays and platforms: EGL_DEFAULT_DISPLAY, the surfaceless platform
//! (EGL_MESA_platform_surfaceless) and the device platform
//! (EGL_EXT_platform_device over the one device of EGL_EXT_device_base);
//! eglInitialize, eglTerminate, eglQueryString.
//!
//! The three displays are the same renderer (shaderbox on the CPU, no
//! native windows) with the same configs; each is initialized and
//! terminated on its own ([`crate::handles`] has their handles).

use crate::error::api;
use crate::objects;
use crate::types::*;
use std::ffi::{c_char, c_void};

pub const VENDOR: &std::ffi::CStr = c"shaderbox";
pub const VERSION: &std::ffi::CStr = c"1.5 shaderbox";
pub const CLIENT_APIS: &std::ffi::CStr = c"OpenGL";
/// Client extensions (eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)).
pub const CLIENT_EXTENSIONS: &std::ffi::CStr = c"EGL_EXT_client_extensions EGL_EXT_platform_base EGL_EXT_platform_device EGL_MESA_platform_surfaceless EGL_EXT_device_base EGL_EXT_device_enumeration EGL_EXT_device_query EGL_KHR_client_get_all_proc_addresses";
/// Display extensions.
pub const DISPLAY_EXTENSIONS: &std::ffi::CStr =
    c"EGL_KHR_create_context EGL_KHR_surfaceless_context EGL_KHR_get_all_proc_addresses";
/// The device's extensions (eglQueryDeviceStringEXT).
pub const DEVICE_EXTENSIONS: &std::ffi::CStr = c"EGL_MESA_device_software";

use crate::handles::{device, display as handle, display_index as index};

/// eglGetDisplay: EGL_DEFAULT_DISPLAY only (there is no native display
/// system); anything else is EGL_NO_DISPLAY, with no error (EGL 1.5 §3.2).
#[no_mangle]
pub extern "C" fn eglGetDisplay(native: EGLNativeDisplayType) -> EGLDisplay {
    api(std::ptr::null_mut(), || {
        Ok(if native.is_null() {
            handle(0)
        } else {
            std::ptr::null_mut()
        })
    })
}

/// eglGetPlatformDisplay with the attribute list already checked.
fn platform_display(
    platform: EGLenum,
    native: *mut c_void,
    has_attribs: bool,
) -> Result<EGLDisplay, EGLint> {
    let d = match platform {
        EGL_PLATFORM_SURFACELESS_MESA if native.is_null() => 1,
        EGL_PLATFORM_DEVICE_EXT if native == device() => 2,
        EGL_PLATFORM_SURFACELESS_MESA | EGL_PLATFORM_DEVICE_EXT => return Err(EGL_BAD_PARAMETER),
        _ => return Err(EGL_BAD_PARAMETER),
    };
    // Neither platform defines display attributes.
    if has_attribs {
        return Err(EGL_BAD_ATTRIBUTE);
    }
    Ok(handle(d))
}

/// eglGetPlatformDisplay (EGL 1.5).
#[no_mangle]
pub unsafe extern "C" fn eglGetPlatformDisplay(
    platform: EGLenum,
    native: *mut c_void,
    attribs: *const EGLAttrib,
) -> EGLDisplay {
    // SAFETY: an EGL_NONE-terminated list or null (EGL's contract).
    let has = !attribs.is_null() && unsafe { *attribs } != EGL_NONE as EGLAttrib;
    api(std::ptr::null_mut(), || {
        platform_display(platform, native, has)
    })
}

/// eglGetPlatformDisplayEXT (EGL_EXT_platform_base: EGLint attributes).
#[no_mangle]
pub unsafe extern "C" fn eglGetPlatformDisplayEXT(
    platform: EGLenum,
    native: *mut c_void,
    attribs: *const EGLint,
) -> EGLDisplay {
    // SAFETY: an EGL_NONE-terminated list or null (EGL's contract).
    let has = !attribs.is_null() && unsafe { *attribs } != EGL_NONE;
    api(std::ptr::null_mut(), || {
        platform_display(platform, native, has)
    })
}

/// eglInitialize: version 1.5.
#[no_mangle]
pub unsafe extern "C" fn eglInitialize(
    dpy: EGLDisplay,
    major: *mut EGLint,
    minor: *mut EGLint,
) -> EGLBoolean {
    api(EGL_FALSE, || {
        let d = index(dpy).ok_or(EGL_BAD_DISPLAY)?;
        objects::lock().initialized[d] = true;
        // SAFETY: out pointers or null (EGL's contract).
        unsafe {
            if !major.is_null() {
                *major = 1;
            }
            if !minor.is_null() {
                *minor = 5;
            }
        }
        Ok(EGL_TRUE)
    })
}

/// eglTerminate: the display's objects are marked for deletion (handles
/// invalid from now on); those current to some thread are freed when
/// released (EGL 1.5 §3.2).
#[no_mangle]
pub extern "C" fn eglTerminate(dpy: EGLDisplay) -> EGLBoolean {
    api(EGL_FALSE, || {
        let d = index(dpy).ok_or(EGL_BAD_DISPLAY)?;
        let mut o = objects::lock();
        o.initialized[d] = false;
        let surfaces: Vec<usize> = o
            .surfaces
            .iter()
            .filter(|(_, s)| s.display == d)
            .map(|(k, _)| *k)
            .collect();
        for id in surfaces {
            if let Some(s) = o.surfaces.get_mut(&id) {
                s.destroyed = true;
            }
            o.reap_surface(id);
        }
        let contexts: Vec<usize> = o
            .contexts
            .iter()
            .filter(|(_, c)| c.display == d)
            .map(|(k, _)| *k)
            .collect();
        for id in contexts {
            if let Some(c) = o.contexts.get_mut(&id) {
                c.destroyed = true;
            }
            o.reap_context(id);
        }
        o.syncs.retain(|_, s| s.display != d);
        Ok(EGL_TRUE)
    })
}

/// eglQueryString. EGL_NO_DISPLAY answers EGL_EXTENSIONS (the client
/// extensions) and EGL_VERSION.
#[no_mangle]
pub extern "C" fn eglQueryString(dpy: EGLDisplay, name: EGLint) -> *const c_char {
    api(std::ptr::null(), || {
        if dpy.is_null() {
            return match name {
                EGL_EXTENSIONS => Ok(CLIENT_EXTENSIONS.as_ptr()),
                EGL_VERSION => Ok(VERSION.as_ptr()),
                _ => Err(EGL_BAD_DISPLAY),
            };
        }
        objects::lock().initialized(dpy)?;
        match name {
            EGL_VENDOR => Ok(VENDOR.as_ptr()),
            EGL_VERSION => Ok(VERSION.as_ptr()),
            EGL_EXTENSIONS => Ok(DISPLAY_EXTENSIONS.as_ptr()),
            EGL_CLIENT_APIS => Ok(CLIENT_APIS.as_ptr()),
            _ => Err(EGL_BAD_PARAMETER),
        }
    })
}

/// eglQueryDevicesEXT: one device.
#[no_mangle]
pub unsafe extern "C" fn eglQueryDevicesEXT(
    max: EGLint,
    devices: *mut EGLDeviceEXT,
    num: *mut EGLint,
) -> EGLBoolean {
    api(EGL_FALSE, || {
        if num.is_null() || (!devices.is_null() && max <= 0) {
            return Err(EGL_BAD_PARAMETER);
        }
        // SAFETY: `num` is one EGLint, `devices` holds `max` handles.
        unsafe {
            if devices.is_null() {
                *num = 1;
            } else {
                *devices = device();
                *num = 1;
            }
        }
        Ok(EGL_TRUE)
    })
}

/// eglQueryDeviceStringEXT: EGL_EXTENSIONS only (no DRM node: a CPU
/// renderer).
#[no_mangle]
pub extern "C" fn eglQueryDeviceStringEXT(dev: EGLDeviceEXT, name: EGLint) -> *const c_char {
    api(std::ptr::null(), || {
        if dev != device() {
            return Err(EGL_BAD_DEVICE_EXT);
        }
        match name {
            EGL_EXTENSIONS => Ok(DEVICE_EXTENSIONS.as_ptr()),
            _ => Err(EGL_BAD_PARAMETER),
        }
    })
}

/// eglQueryDeviceAttribEXT: the device has no attributes.
#[no_mangle]
pub extern "C" fn eglQueryDeviceAttribEXT(
    dev: EGLDeviceEXT,
    _attribute: EGLint,
    _value: *mut EGLAttrib,
) -> EGLBoolean {
    api(EGL_FALSE, || {
        if dev != device() {
            return Err(EGL_BAD_DEVICE_EXT);
        }
        Err(EGL_BAD_ATTRIBUTE)
    })
}

/// eglQueryDisplayAttribEXT / KHR / EGL 1.5's: EGL_DEVICE_EXT, the device.
#[no_mangle]
pub unsafe extern "C" fn eglQueryDisplayAttribEXT(
    dpy: EGLDisplay,
    attribute: EGLint,
    value: *mut EGLAttrib,
) -> EGLBoolean {
    api(EGL_FALSE, || {
        objects::lock().initialized(dpy)?;
        if value.is_null() {
            return Err(EGL_BAD_PARAMETER);
        }
        if attribute != EGL_DEVICE_EXT {
            return Err(EGL_BAD_ATTRIBUTE);
        }
        // SAFETY: one EGLAttrib.
        unsafe { *value = device() as EGLAttrib };
        Ok(EGL_TRUE)
    })
}

/// eglQueryDisplayAttribKHR: the same as the EXT form.
#[no_mangle]
pub unsafe extern "C" fn eglQueryDisplayAttribKHR(
    dpy: EGLDisplay,
    attribute: EGLint,
    value: *mut EGLAttrib,
) -> EGLBoolean {
    // SAFETY: forwarded contract.
    unsafe { eglQueryDisplayAttribEXT(dpy, attribute, value) }
}
