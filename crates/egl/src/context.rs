//! Rendering contexts: OpenGL only (the API eglBindAPI(EGL_OPENGL_API)
//! selects), EGL_KHR_create_context's attributes. Versions 1.0 to 3.3 are
//! made 3.3 contexts: core when 3.2 or 3.3 core is asked for (the profile
//! mask counts from 3.2 on, as the extension says), compatibility
//! otherwise. EGL 1.5 §3.7.1.1 lets a context implement any later version
//! that is backward compatible with the one requested, and the 3.3
//! compatibility profile contains all of OpenGL 1.0-2.1; Mesa answers such
//! requests with its newest compatibility context too, so programs that ask
//! for nothing (piglit's, with version 1.0) get GLSL 1.30 and later as
//! they do there. A later version, a forward-compatible or robust
//! context, or a reset strategy other than none is EGL_BAD_MATCH, the
//! error the extension names for a version and feature set the config
//! does not support. Objects are not shared: `share_context` is checked
//! and otherwise ignored.

use crate::config;
use crate::current;
use crate::error::api;
use crate::objects::{self, Context};
use crate::types::*;

/// The newest OpenGL version a context can be.
pub const MAX_VERSION: (i32, i32) = (3, 3);

/// A context request: version and flags.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Request {
    pub version: (i32, i32),
    pub flags: EGLint,
    pub profile: EGLint,
}

impl Request {
    /// The context API that satisfies the request ([`parse`] refused
    /// versions beyond [`MAX_VERSION`]): the newest context of the
    /// requested profile (module docs).
    pub fn api(&self) -> gl::Api {
        if self.version >= (3, 2) && self.profile == EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT {
            gl::Api::GL33_CORE
        } else {
            gl::Api::GL33_COMPAT
        }
    }
}

/// Whether `(major, minor)` is a defined OpenGL version.
fn defined(major: i32, minor: i32) -> bool {
    match major {
        1 => (0..=5).contains(&minor),
        2 => (0..=1).contains(&minor),
        3 => (0..=3).contains(&minor),
        4 => (0..=6).contains(&minor),
        _ => false,
    }
}

/// Reads a context attribute list (EGL_KHR_create_context and EGL 1.5
/// §3.7.1) into a request, with the errors the extension names.
pub fn parse(list: &[(EGLint, EGLint)]) -> Result<Request, EGLint> {
    let mut r = Request {
        version: (1, 0),
        flags: 0,
        profile: EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
    };
    let mut reset = EGL_NO_RESET_NOTIFICATION;
    let known_flags = EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR
        | EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR
        | EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR;
    let boolean = |v: EGLint| match v {
        0 | 1 => Ok(v == 1),
        _ => Err(EGL_BAD_ATTRIBUTE),
    };
    let set = |flags: &mut EGLint, bit: EGLint, on: bool| {
        if on {
            *flags |= bit
        } else {
            *flags &= !bit
        }
    };
    for &(a, v) in list {
        match a {
            EGL_CONTEXT_MAJOR_VERSION => r.version.0 = v,
            EGL_CONTEXT_MINOR_VERSION => r.version.1 = v,
            EGL_CONTEXT_FLAGS_KHR if v & !known_flags != 0 => return Err(EGL_BAD_ATTRIBUTE),
            EGL_CONTEXT_FLAGS_KHR => r.flags = v,
            EGL_CONTEXT_OPENGL_PROFILE_MASK => r.profile = v,
            EGL_CONTEXT_OPENGL_DEBUG => {
                set(&mut r.flags, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR, boolean(v)?)
            }
            EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE => set(
                &mut r.flags,
                EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR,
                boolean(v)?,
            ),
            EGL_CONTEXT_OPENGL_ROBUST_ACCESS => set(
                &mut r.flags,
                EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR,
                boolean(v)?,
            ),
            EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY => reset = v,
            _ => return Err(EGL_BAD_ATTRIBUTE),
        }
    }
    let (major, minor) = r.version;
    if !defined(major, minor) {
        return Err(EGL_BAD_MATCH);
    }
    if r.flags & EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR != 0 && major < 3 {
        return Err(EGL_BAD_MATCH);
    }
    // The profile matters from 3.2 on: exactly one known bit.
    if (major, minor) >= (3, 2)
        && r.profile != EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT
        && r.profile != EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT
    {
        return Err(EGL_BAD_MATCH);
    }
    // What the renderer cannot do: later versions, robustness, resets.
    if (major, minor) > MAX_VERSION
        || r.flags & EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR != 0
        || reset != EGL_NO_RESET_NOTIFICATION
    {
        return Err(EGL_BAD_MATCH);
    }
    Ok(r)
}

/// eglCreateContext.
#[no_mangle]
pub unsafe extern "C" fn eglCreateContext(
    dpy: EGLDisplay,
    config: EGLConfig,
    share: EGLContext,
    attribs: *const EGLint,
) -> EGLContext {
    // SAFETY: EGL's contract for the list.
    let list = unsafe { config::pairs(attribs) };
    api(std::ptr::null_mut(), || {
        let mut o = objects::lock();
        let d = o.initialized(dpy)?;
        if current::thread().api != EGL_OPENGL_API {
            return Err(EGL_BAD_MATCH);
        }
        let c = config::lookup(d, config)?;
        if !share.is_null() {
            o.context(d, share)?;
        }
        let r = parse(&list)?;
        let os = capi::context::OsContext::new(
            r.api(),
            capi::osmesa_enums::OSMESA_RGBA,
            c.depth,
            c.stencil,
            0,
        );
        let gl = Box::into_raw(Box::new(os)) as usize;
        let id = o.new_id();
        let ctx = Context {
            display: d,
            config: c,
            gl,
            version: r.version,
            flags: r.flags,
            thread: None,
            draw: 0,
            read: 0,
            sized: false,
            destroyed: false,
        };
        ctx.os()
            .gl
            .replace_default_framebuffer(objects::placeholder());
        o.contexts.insert(id, ctx);
        Ok(id as EGLContext)
    })
}

/// eglDestroyContext: freed now, or when released if current.
#[no_mangle]
pub extern "C" fn eglDestroyContext(dpy: EGLDisplay, ctx: EGLContext) -> EGLBoolean {
    api(EGL_FALSE, || {
        let mut o = objects::lock();
        let d = o.initialized(dpy)?;
        o.context(d, ctx)?.destroyed = true;
        o.reap_context(ctx as usize);
        Ok(EGL_TRUE)
    })
}

/// eglQueryContext.
#[no_mangle]
pub unsafe extern "C" fn eglQueryContext(
    dpy: EGLDisplay,
    ctx: EGLContext,
    attribute: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    api(EGL_FALSE, || {
        let mut o = objects::lock();
        let d = o.initialized(dpy)?;
        let c = o.context(d, ctx)?;
        let v = match attribute {
            EGL_CONFIG_ID => c.config.id,
            EGL_CONTEXT_CLIENT_TYPE => EGL_OPENGL_API as EGLint,
            EGL_CONTEXT_CLIENT_VERSION => c.version.0,
            EGL_RENDER_BUFFER if c.draw != 0 => EGL_BACK_BUFFER,
            EGL_RENDER_BUFFER => EGL_NONE,
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn versions() {
        let v = |maj, min| {
            parse(&[
                (EGL_CONTEXT_MAJOR_VERSION, maj),
                (EGL_CONTEXT_MINOR_VERSION, min),
            ])
        };
        assert_eq!(v(2, 1).map(|r| r.version), Ok((2, 1)));
        assert_eq!(v(1, 5).map(|r| r.version), Ok((1, 5)));
        assert_eq!(v(2, 2), Err(EGL_BAD_MATCH));
        assert_eq!(v(3, 3).map(|r| r.api()), Ok(gl::Api::GL33_CORE));
        assert_eq!(v(3, 4), Err(EGL_BAD_MATCH));
        assert_eq!(v(4, 1), Err(EGL_BAD_MATCH));
        // Every version up to 3.1 is a compatibility context of the
        // newest version, as the profile mask counts from 3.2 on (its
        // default, core, is ignored below).
        assert_eq!(v(2, 1).map(|r| r.api()), Ok(gl::Api::GL33_COMPAT));
        assert_eq!(v(1, 0).map(|r| r.api()), Ok(gl::Api::GL33_COMPAT));
        assert_eq!(parse(&[]).map(|r| r.api()), Ok(gl::Api::GL33_COMPAT));
        assert_eq!(v(3, 1).map(|r| r.api()), Ok(gl::Api::GL33_COMPAT));
        assert_eq!(
            parse(&[
                (EGL_CONTEXT_MAJOR_VERSION, 3),
                (EGL_CONTEXT_MINOR_VERSION, 2),
                (
                    EGL_CONTEXT_OPENGL_PROFILE_MASK,
                    EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT
                ),
            ])
            .map(|r| r.api()),
            Ok(gl::Api::GL33_COMPAT)
        );
        assert_eq!(v(0, 0), Err(EGL_BAD_MATCH));
        assert_eq!(parse(&[]).map(|r| r.version), Ok((1, 0)));
        assert_eq!(parse(&[(0x3333, 1)]), Err(EGL_BAD_ATTRIBUTE));
        assert_eq!(parse(&[(EGL_CONTEXT_FLAGS_KHR, 8)]), Err(EGL_BAD_ATTRIBUTE));
        assert_eq!(
            parse(&[(
                EGL_CONTEXT_FLAGS_KHR,
                EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR
            )]),
            Err(EGL_BAD_MATCH)
        );
        assert!(parse(&[(EGL_CONTEXT_OPENGL_DEBUG, 1)]).is_ok());
        assert_eq!(
            parse(&[(EGL_CONTEXT_OPENGL_DEBUG, 7)]),
            Err(EGL_BAD_ATTRIBUTE)
        );
        assert_eq!(
            parse(&[(
                EGL_CONTEXT_OPENGL_PROFILE_MASK,
                EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT
            )])
            .map(|r| r.version),
            Ok((1, 0))
        );
    }
}
