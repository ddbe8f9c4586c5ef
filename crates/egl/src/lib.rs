//! # shaderbox-egl: a drop-in `libEGL.so.1` (and `libGL.so.1`, `libOpenGL.so.0`)
//!
//! EGL 1.5 for OpenGL 3.3 contexts (core and compatibility) over shaderbox, headless: built as
//! `libEGL.so` (SONAME `libEGL.so.1`, `build.rs`), it exports the EGL
//! entry points, every gl* entry point of [`capi`] (linked in as an rlib,
//! so the GL calls are the ones `libOSMesa.so` exports) and the GLX names
//! a `libGL.so.1` must have ([`glx`]). `scripts/egl-libs.sh` makes the
//! directory a program's `LD_LIBRARY_PATH` names: `libEGL.so.1`,
//! `libGL.so.1` and `libOpenGL.so.0`, three names of the one file (one
//! inode, so the dynamic loader maps it once and EGL and GL share the
//! current context). The same file is a GLVND EGL vendor library
//! ([`glvnd`]: `__egl_Main`), which the system's libglvnd `libEGL.so.1`
//! loads from a vendor JSON file (`DIR/glvnd/50_shaderbox.json`).
//! docs/EGL.md says how to run a program either way.
//!
//! ## Contract
//! - Displays ([`display`]): `EGL_DEFAULT_DISPLAY`, the surfaceless platform
//!   (`EGL_MESA_platform_surfaceless`) and the device platform
//!   (`EGL_EXT_platform_device`; `eglQueryDevicesEXT` lists one device);
//!   any other native display or platform is `EGL_NO_DISPLAY` (with
//!   `EGL_BAD_PARAMETER` from eglGetPlatformDisplay).
//! - Configs ([`config`]): RGBA8 with 24-bit depth and 8-bit stencil, and
//!   RGBA8 alone; `EGL_PBUFFER_BIT` surfaces, `EGL_OPENGL_BIT` only.
//! - Surfaces ([`surface`]): pbuffers, and none (`EGL_KHR_surfaceless_context`:
//!   the context then draws into a 1×1 placeholder; use framebuffer
//!   objects). Window and pixmap surfaces are `EGL_BAD_MATCH`.
//! - Contexts ([`context`]): `eglBindAPI(EGL_OPENGL_API)` only (the initial
//!   API is `EGL_NONE`); `EGL_KHR_create_context` versions 1.0 to 3.3,
//!   made 3.3 contexts: core for a 3.2 or 3.3 core request, compatibility
//!   (which contains OpenGL 1.0-2.1) for every other; later versions, forward-compatible
//!   and robust contexts are `EGL_BAD_MATCH`. No object sharing.
//! - One current context per thread, a context current to one thread and
//!   a surface to one context at a time ([`current`]); destroying a
//!   current object defers its deletion to its release.
//! - Every call records its EGL error (`eglGetError`, [`error`]); bad
//!   handles (null, of another kind or display, destroyed), null out
//!   pointers and unknown attributes get the error EGL 1.5 or the
//!   extension names, never a crash. No call unwinds into C.
//! - `eglGetProcAddress` ([`procs`]) returns every EGL, GLX and GL entry
//!   point exported.
//!
//! ## Modules
//! - [`types`]: the C types and enum values; [`error`]: the thread's error
//!   and the wrapper of every entry point.
//! - [`handles`]: the display, device and config handles (fixed);
//!   [`objects`]: the table of live surfaces, contexts and syncs.
//! - [`display`], [`config`], [`surface`], [`context`], [`current`],
//!   [`sync`] (fences, images): the entry points, by job.
//! - [`glx`]: the GLX names; [`procs`]: eglGetProcAddress.
//! - [`glvnd`]: `__egl_Main`, the GLVND vendor interface (on top: the
//!   same file is a vendor library of the system's libglvnd `libEGL.so.1`).
//!
//! ## Limitations
//! - A read surface different from the draw surface is reserved, but
//!   reads come from the draw surface.
//! - No EGLImage sources, no pbuffers bound to textures, no multisampled
//!   configs, no OpenGL ES or OpenVG.
#![allow(non_snake_case, clippy::missing_safety_doc)]

pub mod config;
pub mod context;
pub mod current;
pub mod display;
pub mod error;
pub mod glvnd;
pub mod glx;
pub mod handles;
pub mod objects;
pub mod procs;
pub mod surface;
pub mod sync;
pub mod types;

pub use types::*;
