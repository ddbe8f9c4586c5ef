//! EGL 1.5 sync objects and images. A fence is signaled when created
//! (every GL call has completed when it returns), so waits return at once.
//! No image source (GL textures, renderbuffers) is supported: eglCreateImage
//! is EGL_BAD_PARAMETER.

use crate::config;
use crate::current;
use crate::error::api;
use crate::objects::{self, Sync};
use crate::types::*;

/// eglCreateSync: EGL_SYNC_FENCE with no attributes, on the display of the
/// current context (EGL_BAD_MATCH without one).
#[no_mangle]
pub unsafe extern "C" fn eglCreateSync(
    dpy: EGLDisplay,
    ty: EGLenum,
    attribs: *const EGLAttrib,
) -> EGLSync {
    // SAFETY: EGL's contract for the list.
    let list = unsafe { config::attrib_pairs(attribs) };
    api(std::ptr::null_mut(), || {
        let mut o = objects::lock();
        let d = o.initialized(dpy)?;
        if ty as EGLint != EGL_SYNC_FENCE {
            return Err(EGL_BAD_PARAMETER);
        }
        if !list.is_empty() {
            return Err(EGL_BAD_ATTRIBUTE);
        }
        let t = current::thread();
        if t.ctx == 0 || t.display != d {
            return Err(EGL_BAD_MATCH);
        }
        let id = o.new_id();
        o.syncs.insert(id, Sync { display: d });
        Ok(id as EGLSync)
    })
}

fn check_sync(dpy: EGLDisplay, sync: EGLSync) -> Result<(), EGLint> {
    let o = objects::lock();
    let d = o.initialized(dpy)?;
    match o.syncs.get(&(sync as usize)) {
        Some(s) if s.display == d => Ok(()),
        _ => Err(EGL_BAD_PARAMETER),
    }
}

/// eglDestroySync.
#[no_mangle]
pub extern "C" fn eglDestroySync(dpy: EGLDisplay, sync: EGLSync) -> EGLBoolean {
    api(EGL_FALSE, || {
        check_sync(dpy, sync)?;
        objects::lock().syncs.remove(&(sync as usize));
        Ok(EGL_TRUE)
    })
}

/// eglClientWaitSync: EGL_CONDITION_SATISFIED.
#[no_mangle]
pub extern "C" fn eglClientWaitSync(
    dpy: EGLDisplay,
    sync: EGLSync,
    _flags: EGLint,
    _timeout: EGLTime,
) -> EGLint {
    api(EGL_FALSE as EGLint, || {
        check_sync(dpy, sync)?;
        Ok(EGL_CONDITION_SATISFIED)
    })
}

/// eglWaitSync: flags must be 0.
#[no_mangle]
pub extern "C" fn eglWaitSync(dpy: EGLDisplay, sync: EGLSync, flags: EGLint) -> EGLBoolean {
    api(EGL_FALSE, || {
        check_sync(dpy, sync)?;
        if flags != 0 {
            return Err(EGL_BAD_PARAMETER);
        }
        Ok(EGL_TRUE)
    })
}

/// eglGetSyncAttrib.
#[no_mangle]
pub unsafe extern "C" fn eglGetSyncAttrib(
    dpy: EGLDisplay,
    sync: EGLSync,
    attribute: EGLint,
    value: *mut EGLAttrib,
) -> EGLBoolean {
    api(EGL_FALSE, || {
        check_sync(dpy, sync)?;
        let v = match attribute {
            EGL_SYNC_TYPE => EGL_SYNC_FENCE,
            EGL_SYNC_STATUS => EGL_SIGNALED,
            EGL_SYNC_CONDITION => EGL_SYNC_PRIOR_COMMANDS_COMPLETE,
            _ => return Err(EGL_BAD_ATTRIBUTE),
        };
        if value.is_null() {
            return Err(EGL_BAD_PARAMETER);
        }
        // SAFETY: one EGLAttrib.
        unsafe { *value = v as EGLAttrib };
        Ok(EGL_TRUE)
    })
}

/// eglCreateImage: no supported target (EGL_BAD_PARAMETER).
#[no_mangle]
pub extern "C" fn eglCreateImage(
    dpy: EGLDisplay,
    _ctx: EGLContext,
    _target: EGLenum,
    _buffer: EGLClientBuffer,
    _attribs: *const EGLAttrib,
) -> EGLImage {
    api(std::ptr::null_mut(), || {
        objects::lock().initialized(dpy)?;
        Err(EGL_BAD_PARAMETER)
    })
}

/// eglDestroyImage: there are no images (EGL_BAD_PARAMETER).
#[no_mangle]
pub extern "C" fn eglDestroyImage(dpy: EGLDisplay, _image: EGLImage) -> EGLBoolean {
    api(EGL_FALSE, || {
        objects::lock().initialized(dpy)?;
        Err(EGL_BAD_PARAMETER)
    })
}
