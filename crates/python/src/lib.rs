//! # shaderbox-python: the native module of the `shaderbox` Python package
//!
//! Built by maturin (`pip install .` at the repository root, which reads
//! `pyproject.toml`) as the extension module `shaderbox._shaderbox`, with
//! the `python` feature on. The Python package in `python/shaderbox`
//! (beside this crate's `src/`) is the public API: contexts, programs,
//! uniforms, buffers, textures, fixed-function state, images, `check`,
//! `render_molecule` and `shaderbox.pyopengl`. This crate is the layer
//! under it:
//!
//! - [`report`]: compile and link reports as plain data (located
//!   diagnostics, the rich text, the GL info log) — what `check`,
//!   `CompileError` and `LinkError` carry.
//! - [`molecule`]: `render_molecule`'s options checked by name and handed
//!   to [`render::render`], the same library `shaderbox render` uses.
//! - `bindings` (feature `python`): the PyO3 module — `RawContext`, a
//!   checked wrapper of [`gl::Context`] whose methods mirror the GL calls
//!   the package needs, plus module functions over the two modules above
//!   and PNG encoding.
//!
//! The extension also links `shaderbox-capi` (the OSMesa + gl* C ABI), so
//! the loaded module exports `OSMesaCreateContextExt`, `glDrawArrays`, ...
//! with C linkage: `import shaderbox.pyopengl` points PyOpenGL's OSMesa
//! platform at this very file, so PyOpenGL code runs on shaderbox without
//! environment variables or a separate `libOSMesa.so`. It links
//! `shaderbox-egl` too (the EGL 1.5 C ABI: `eglGetDisplay`, ...), which
//! `import shaderbox.egl` points PyOpenGL's EGL platform at the same way.
//!
//! ## Contract
//! - No call panics on any Python input: sizes, names, enums and lengths
//!   are checked here or by `gl` (which records a GL error and does
//!   nothing); the Python layer turns GL errors into exceptions.
//! - Draws, clears and molecule renders release the GIL; a context is
//!   locked for the duration of each call (a `Context` may be used from
//!   several Python threads, one call at a time).
//! - Deterministic: images are the pipeline's, the same bytes on every
//!   machine and thread count.
//!
//! ## Limitations
//! - One default framebuffer per context (RGBA8, 24-bit depth, 8-bit
//!   stencil); no framebuffer objects, no 1D/3D/cube textures through the
//!   Python API yet (the GL context has them; the C ABI through
//!   `shaderbox.pyopengl` reaches them).
//! - The C ABI's current context is per thread and separate from the
//!   Python `Context` objects: the two APIs do not share state.

pub mod molecule;
pub mod report;

#[cfg(feature = "python")]
mod bindings;
