//! The calling thread's EGL state: the bound API (eglBindAPI; EGL_NONE
//! until the first call, as OpenGL ES is not supported, EGL 1.5 §3.7),
//! the current context and its surfaces (eglMakeCurrent, one current
//! context per thread, a context current to one thread at a time), and
//! the calls that act on it (eglGetCurrent*, eglReleaseThread, eglWait*).
//!
//! Making a context current moves the draw surface's buffers into its
//! `gl::Context` as the default framebuffer and makes capi's context
//! current for the gl* entry points; releasing it moves them back. A
//! different read surface is reserved like the draw surface but reads
//! come from the draw surface (GL 2.1 has one default framebuffer).

use crate::error::api;
use crate::handles;
use crate::objects::{self, Objects};
use crate::types::*;
use std::cell::Cell;

/// The thread's EGL state.
#[derive(Clone, Copy)]
pub struct Thread {
    pub api: EGLenum,
    pub ctx: usize,
    pub draw: usize,
    pub read: usize,
    /// Index of the current context's display.
    pub display: usize,
}

const INITIAL: Thread = Thread {
    api: EGL_NONE as EGLenum,
    ctx: 0,
    draw: 0,
    read: 0,
    display: 0,
};

thread_local! {
    static THREAD: Cell<Thread> = const { Cell::new(INITIAL) };
}

/// The calling thread's state.
pub fn thread() -> Thread {
    THREAD.with(|t| t.get())
}

fn set_thread(t: Thread) {
    THREAD.with(|c| c.set(t));
}

/// Releases the thread's current context (if any): its surface gets its
/// buffers back, destroyed objects no longer current are freed.
fn release(o: &mut Objects) {
    let t = thread();
    if t.ctx == 0 {
        return;
    }
    if let Some(c) = o.contexts.get_mut(&t.ctx) {
        // The GL layer's pending work (debug output) before leaving.
        c.os().sync();
        let fb = c
            .os()
            .gl
            .replace_default_framebuffer(objects::placeholder());
        let (draw, read) = (c.draw, c.read);
        c.thread = None;
        c.draw = 0;
        c.read = 0;
        if let Some(s) = o.surfaces.get_mut(&draw) {
            s.buffers = Some(fb);
            s.bound_to = 0;
        }
        if let Some(s) = o.surfaces.get_mut(&read) {
            s.bound_to = 0;
        }
        o.reap_surface(draw);
        o.reap_surface(read);
    }
    o.reap_context(t.ctx);
    capi::context::set_current(std::ptr::null_mut());
    set_thread(Thread {
        ctx: 0,
        draw: 0,
        read: 0,
        display: 0,
        ..t
    });
}

/// Whether surface `s` may be made current by this thread: not current to
/// a context of another thread.
fn available(o: &Objects, s: usize) -> bool {
    let me = std::thread::current().id();
    match o.surfaces.get(&s).map(|x| x.bound_to) {
        Some(0) | None => true,
        Some(c) => o.contexts.get(&c).and_then(|c| c.thread) == Some(me),
    }
}

/// eglMakeCurrent.
#[no_mangle]
pub extern "C" fn eglMakeCurrent(
    dpy: EGLDisplay,
    draw: EGLSurface,
    read: EGLSurface,
    ctx: EGLContext,
) -> EGLBoolean {
    api(EGL_FALSE, || {
        let d = handles::display_index(dpy).ok_or(EGL_BAD_DISPLAY)?;
        let mut o = objects::lock();
        if ctx.is_null() {
            if !draw.is_null() || !read.is_null() {
                return Err(EGL_BAD_MATCH);
            }
            // Releasing is allowed on a terminated display (EGL 1.5 §3.2).
            release(&mut o);
            return Ok(EGL_TRUE);
        }
        o.initialized(dpy)?;
        let me = std::thread::current().id();
        let c = o.context(d, ctx)?;
        if c.thread.is_some_and(|t| t != me) {
            return Err(EGL_BAD_ACCESS);
        }
        if draw.is_null() != read.is_null() {
            return Err(EGL_BAD_MATCH);
        }
        if !draw.is_null() {
            o.surface(d, draw)?;
            o.surface(d, read)?;
            if !available(&o, draw as usize) || !available(&o, read as usize) {
                return Err(EGL_BAD_ACCESS);
            }
        }
        release(&mut o);
        let (draw, read, id) = (draw as usize, read as usize, ctx as usize);
        let fb = o.surfaces.get_mut(&draw).and_then(|s| {
            s.bound_to = id;
            s.buffers.take().map(|b| (b, s.width, s.height))
        });
        if let Some(s) = o.surfaces.get_mut(&read) {
            s.bound_to = id;
        }
        let Some(c) = o.contexts.get_mut(&id) else {
            return Err(EGL_BAD_CONTEXT);
        };
        c.thread = Some(me);
        c.draw = draw;
        c.read = read;
        if let Some((fb, w, h)) = fb {
            c.os().gl.replace_default_framebuffer(fb);
            if !c.sized {
                // The first surface sets the viewport and scissor box
                // (EGL 1.5 §3.7.3).
                c.sized = true;
                c.os().gl.viewport(0, 0, w, h);
                c.os().gl.scissor(0, 0, w, h);
            }
        }
        capi::context::set_current(c.gl as *mut capi::context::OsContext);
        set_thread(Thread {
            ctx: id,
            draw,
            read,
            display: d,
            ..thread()
        });
        Ok(EGL_TRUE)
    })
}

/// eglGetCurrentContext.
#[no_mangle]
pub extern "C" fn eglGetCurrentContext() -> EGLContext {
    api(std::ptr::null_mut(), || Ok(thread().ctx as EGLContext))
}

/// eglGetCurrentDisplay.
#[no_mangle]
pub extern "C" fn eglGetCurrentDisplay() -> EGLDisplay {
    api(std::ptr::null_mut(), || {
        let t = thread();
        Ok(if t.ctx == 0 {
            std::ptr::null_mut()
        } else {
            handles::display(t.display)
        })
    })
}

/// eglGetCurrentSurface: EGL_DRAW or EGL_READ.
#[no_mangle]
pub extern "C" fn eglGetCurrentSurface(which: EGLint) -> EGLSurface {
    api(std::ptr::null_mut(), || match which {
        EGL_DRAW => Ok(thread().draw as EGLSurface),
        EGL_READ => Ok(thread().read as EGLSurface),
        _ => Err(EGL_BAD_PARAMETER),
    })
}

/// eglBindAPI: EGL_OPENGL_API only (EGL_BAD_PARAMETER otherwise).
#[no_mangle]
pub extern "C" fn eglBindAPI(which: EGLenum) -> EGLBoolean {
    api(EGL_FALSE, || {
        if which != EGL_OPENGL_API {
            return Err(EGL_BAD_PARAMETER);
        }
        set_thread(Thread {
            api: which,
            ..thread()
        });
        Ok(EGL_TRUE)
    })
}

/// eglQueryAPI.
#[no_mangle]
pub extern "C" fn eglQueryAPI() -> EGLenum {
    api(EGL_NONE as EGLenum, || Ok(thread().api))
}

/// eglReleaseThread: releases the current context and returns the
/// thread's state to its initial values.
#[no_mangle]
pub extern "C" fn eglReleaseThread() -> EGLBoolean {
    api(EGL_FALSE, || {
        release(&mut objects::lock());
        set_thread(INITIAL);
        Ok(EGL_TRUE)
    })
}

/// eglWaitClient: every GL call has completed when it returns.
#[no_mangle]
pub extern "C" fn eglWaitClient() -> EGLBoolean {
    api(EGL_FALSE, || Ok(EGL_TRUE))
}

/// eglWaitGL: as eglWaitClient.
#[no_mangle]
pub extern "C" fn eglWaitGL() -> EGLBoolean {
    eglWaitClient()
}

/// eglWaitNative: there is no native renderer to wait for.
#[no_mangle]
pub extern "C" fn eglWaitNative(_engine: EGLint) -> EGLBoolean {
    api(EGL_FALSE, || Ok(EGL_TRUE))
}
