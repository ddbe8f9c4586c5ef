//! The table of live EGL objects (surfaces, contexts, syncs) and of which
//! displays are initialized, behind one lock. Handles are ids from one
//! counter, so a handle of one kind passed as another, a destroyed one or
//! one of another display is found missing and refused with the spec's
//! error instead of dereferenced.

use crate::handles::{Config, DISPLAY_COUNT};
use crate::types::*;
use std::collections::BTreeMap;
use std::sync::{Mutex, MutexGuard};
use std::thread::ThreadId;

/// A pbuffer surface. Its buffers live here while it is not current and
/// in its context's `gl::Context` (as the default framebuffer) while it is.
pub struct Surface {
    pub display: usize,
    pub config: &'static Config,
    pub width: i32,
    pub height: i32,
    pub largest: bool,
    pub swap_behavior: EGLint,
    /// None while moved into the context it is current to.
    pub buffers: Option<raster::Framebuffer>,
    /// The context it is current to (0: none).
    pub bound_to: usize,
    /// eglDestroySurface was called while it was current: freed on release.
    pub destroyed: bool,
}

/// An OpenGL context: capi's OSMesa-layer context (the GL state and the C
/// layer's display lists and client arrays), without a client buffer.
pub struct Context {
    pub display: usize,
    pub config: &'static Config,
    /// `Box<capi::context::OsContext>` as an address (the table is shared
    /// between threads; the context is used by the thread it is current to
    /// only).
    pub gl: usize,
    pub version: (i32, i32),
    pub flags: EGLint,
    /// The thread it is current to.
    pub thread: Option<ThreadId>,
    pub draw: usize,
    pub read: usize,
    /// The viewport and scissor box were set to a surface's size (the
    /// first time it was made current with one).
    pub sized: bool,
    pub destroyed: bool,
}

impl Context {
    /// The GL context, for the thread it is current to (or while no
    /// thread has it current).
    #[allow(clippy::mut_from_ref)]
    pub fn os(&self) -> &mut capi::context::OsContext {
        // SAFETY: `gl` came from Box::into_raw and is freed only when the
        // context leaves the table; the caller holds the table's lock, and
        // only the thread the context is current to runs GL on it.
        unsafe { &mut *(self.gl as *mut capi::context::OsContext) }
    }
}

impl Drop for Context {
    fn drop(&mut self) {
        // SAFETY: created by Box::into_raw in eglCreateContext, freed once.
        drop(unsafe { Box::from_raw(self.gl as *mut capi::context::OsContext) });
    }
}

/// The buffers of a `width` x `height` surface of `config`.
pub fn buffers(config: &Config, width: i32, height: i32) -> raster::Framebuffer {
    raster::Framebuffer::new(
        width.max(1) as u32,
        height.max(1) as u32,
        raster::ColorFormat::Rgba8,
        config.depth > 0,
        config.stencil > 0,
    )
}

/// The default framebuffer of a context with no surface (surfaceless, or
/// between surfaces): one pixel, nothing else.
pub fn placeholder() -> raster::Framebuffer {
    raster::Framebuffer::new(1, 1, raster::ColorFormat::Rgba8, false, false)
}

/// A fence sync (signaled when created: every GL call completes before it
/// returns).
pub struct Sync {
    pub display: usize,
}

#[derive(Default)]
pub struct Objects {
    pub initialized: [bool; DISPLAY_COUNT],
    pub surfaces: BTreeMap<usize, Surface>,
    pub contexts: BTreeMap<usize, Context>,
    pub syncs: BTreeMap<usize, Sync>,
    next: usize,
}

// SAFETY: the raw state in the table (a context's GL state, behind an
// address) is only touched by the thread the context is current to, or
// under the lock while it is current to none.
unsafe impl Send for Objects {}

static OBJECTS: Mutex<Option<Objects>> = Mutex::new(None);

/// The table, locked (a panic while it was held does not poison it for
/// later calls).
pub fn lock() -> Guard {
    let mut g = OBJECTS.lock().unwrap_or_else(|e| e.into_inner());
    g.get_or_insert_with(Objects::default);
    Guard(g)
}

pub struct Guard(MutexGuard<'static, Option<Objects>>);

impl std::ops::Deref for Guard {
    type Target = Objects;
    fn deref(&self) -> &Objects {
        self.0.as_ref().expect("initialized by lock")
    }
}

impl std::ops::DerefMut for Guard {
    fn deref_mut(&mut self) -> &mut Objects {
        self.0.as_mut().expect("initialized by lock")
    }
}

impl Objects {
    /// A fresh handle id (never 0, never reused).
    pub fn new_id(&mut self) -> usize {
        self.next += 1;
        // Small odd multiples keep ids off addresses and off null.
        self.next * 16 + 1
    }

    /// `dpy` as a display index, initialized: EGL_BAD_DISPLAY for a
    /// handle that is none of ours, EGL_NOT_INITIALIZED before
    /// eglInitialize or after eglTerminate.
    pub fn initialized(&self, dpy: EGLDisplay) -> Result<usize, EGLint> {
        let d = crate::handles::display_index(dpy).ok_or(EGL_BAD_DISPLAY)?;
        if self.initialized[d] {
            Ok(d)
        } else {
            Err(EGL_NOT_INITIALIZED)
        }
    }

    /// A live surface of display `d` (EGL_BAD_SURFACE otherwise).
    pub fn surface(&mut self, d: usize, s: EGLSurface) -> Result<&mut Surface, EGLint> {
        match self.surfaces.get_mut(&(s as usize)) {
            Some(x) if x.display == d && !x.destroyed => Ok(x),
            _ => Err(EGL_BAD_SURFACE),
        }
    }

    /// A live context of display `d` (EGL_BAD_CONTEXT otherwise).
    pub fn context(&mut self, d: usize, c: EGLContext) -> Result<&mut Context, EGLint> {
        match self.contexts.get_mut(&(c as usize)) {
            Some(x) if x.display == d && !x.destroyed => Ok(x),
            _ => Err(EGL_BAD_CONTEXT),
        }
    }

    /// Frees a destroyed surface once no context has it current.
    pub fn reap_surface(&mut self, id: usize) {
        if matches!(self.surfaces.get(&id), Some(s) if s.destroyed && s.bound_to == 0) {
            self.surfaces.remove(&id);
        }
    }

    /// Frees a destroyed context once no thread has it current.
    pub fn reap_context(&mut self, id: usize) {
        if matches!(self.contexts.get(&id), Some(c) if c.destroyed && c.thread.is_none()) {
            self.contexts.remove(&id);
        }
    }
}
