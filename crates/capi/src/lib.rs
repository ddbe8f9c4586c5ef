//! # shaderbox-capi: a drop-in `libOSMesa.so`
//!
//! Built as `libOSMesa.so` (`cargo build --release -p shaderbox-capi`), this
//! crate exports Mesa's off-screen context API (`OSMesaCreateContext*`,
//! `OSMesaMakeCurrent`, ... — [`osmesa`]) and OpenGL 2.1 entry points
//! (the modules below) with their C signatures, over [`gl::Context`]. Programs
//! written against OSMesa (PyOpenGL with `PYOPENGL_PLATFORM=osmesa`, C
//! tools' off-screen paths) run unchanged:
//!
//! ```sh
//! PYOPENGL_PLATFORM=osmesa LD_LIBRARY_PATH=target/release python3 script.py
//! ```
//!
//! ## Contract
//! - One current context per thread (thread-local), as OSMesa.
//! - Rendering goes to the context's own framebuffer (RGBA8, 24-bit depth,
//!   8-bit stencil), copied into the client's buffer (when drawing changed
//!   it) by glFinish, glFlush, glReadPixels, OSMesaMakeCurrent switching
//!   away or releasing, OSMesaGetColorBuffer, OSMesaPixelStore and
//!   OSMesaDestroyContext — as with Mesa's llvmpipe, which bins draws and
//!   rasterizes at flush, the buffer is complete only after glFinish or
//!   glFlush (copying after every draw would cost a full-buffer copy per
//!   draw).
//!   The copy is in the client's format (RGBA, BGRA, ARGB, RGB, BGR, RGB_565)
//!   and type (GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_FLOAT,
//!   GL_UNSIGNED_SHORT_5_6_5) given, bottom row first unless
//!   `OSMesaPixelStore(OSMESA_Y_UP, 0)`, rows `OSMESA_ROW_LENGTH` apart.
//! - Display lists are recorded at the C level ([`lists`]); vertex-array
//!   draws and pixel images (glDrawPixels, glBitmap) are dereferenced at
//!   compile time (GL 2.1 §5.4).
//! - Query objects ([`occlusion`]: occlusion, primitive and timer queries)
//!   count exactly, whatever the thread count; results are available when
//!   glEndQuery returns. Sync objects ([`sync`]) are signaled when created.
//! - The raster-position pixel path ([`pixel_path`]): glRasterPos runs the
//!   current vertex stage (lighting, texture matrices, a user vertex
//!   shader) on one vertex; glDrawPixels / glBitmap / glCopyPixels
//!   fragments go through the per-fragment operations.
//! - Client vertex arrays: pointers are kept as given and the bytes a draw
//!   reads are copied at draw time (safety argument in [`arrays`]).
//! - No entry point unwinds into C: panics are caught (the call then does
//!   nothing and returns 0/null). Invalid arguments raise the GL error;
//!   null pointers where GL requires memory make the call a no-op.
//!
//! ## Safety
//! The `unsafe extern "C"` functions trust what C's GL/OSMesa contract
//! makes the caller promise: pointers designate as much memory as the
//! call's arguments say (a buffer of `width*height` pixels for
//! OSMesaMakeCurrent, 16 values for glLoadMatrixf, `count` strings for
//! glShaderSource...). Context handles are checked against the set of live
//! contexts before use.
//!
//! ## Modules
//! From the C boundary inwards:
//! - [`abi`]: the C types, reading/writing C memory, and
//!   `gl_entry_points!`, which every entry-point module uses; it depends
//!   on no other module.
//! - [`context`]: [`context::OsContext`] (a [`gl::Context`] plus the
//!   client buffer), the thread's current context, the copy into the
//!   client buffer, and recording into display lists; [`layer_state`],
//!   [`arrays`] and [`debug_env`] are the state it holds.
//! - The gl* entry points, by GL 2.1 chapter: [`variants`] (generated: the
//!   type/arity variants — glVertex*, glColor*, glTexCoord*,
//!   glVertexAttrib*, glRasterPos*...), [`drawing`] (glBegin/glEnd, array
//!   draws), [`vertex_arrays`], [`buffers`], [`transform`],
//!   [`fixed_function`] (lighting, texgen, texture environment, fog),
//!   [`rasterization`] (and per-fragment state), [`pixel_path`]
//!   (glDrawPixels, glBitmap, glCopyPixels), [`textures`], [`pixels`]
//!   (texture read-back and copies), [`framebuffer`] (clears, masks,
//!   glReadPixels, glFinish), [`framebuffer_objects`], [`shaders`],
//!   [`uniforms`], [`lists`], [`attribs`], [`occlusion`] (query objects,
//!   conditional rendering), [`sync`] (fences), [`queries`] and
//!   [`legacy`] (GL 1.x calls kept as state).
//! - [`osmesa`]: the OSMesa context API; [`procs`]: OSMesaGetProcAddress
//!   and its table, naming every entry-point module.
//! - [`allocator`] (feature `mimalloc`): the global allocator, mimalloc
//!   with small address-space reservations (hosts that set `RLIMIT_AS`).
//!
//! No module depends back on one that depends on it
//! (`scripts/module-graph.py capi`).
//!
//! ## Limitations
//! - Missing entry points (README.md lists all 55 of GL 1.0–2.1's 583):
//!   the ARB_imaging subset and evaluators, left out on purpose.
//! - Pixel rectangles (glDrawPixels, glBitmap, glCopyPixels) are not
//!   shaded: texturing, fog, color sum and a bound fragment shader do not
//!   apply to their fragments (GL 2.1 applies them). Of the pixel
//!   transfer state only color/depth scale and bias, index shift/offset
//!   (stencil) and the zoom apply; pixel maps do not. GL_COLOR_INDEX data
//!   and GL_BITMAP-typed rectangles raise GL_INVALID_OPERATION.
//! - Kept as state, not applied when drawing ([`legacy`]): line and
//!   polygon stipples, edge flags, pixel maps, GL_COMBINE texture-environment parameters (GL_COMBINE draws as
//!   GL_MODULATE), texture priorities. glRenderMode(GL_SELECT /
//!   GL_FEEDBACK) raises GL_INVALID_OPERATION (selection and feedback are
//!   not implemented); the name stack and glPassThrough are ignored, as in
//!   GL_RENDER mode. There is no accumulation buffer (glAccum:
//!   GL_INVALID_OPERATION) and no compressed texture format
//!   (glCompressedTex*: GL_INVALID_ENUM). Texture borders are not
//!   implemented (border 1: GL_INVALID_VALUE).
//! - glPushAttrib does not save texture-object parameters or hints.
//! - glGetTexImage and glReadPixels do not write packed pixel types
//!   (GL_UNSIGNED_SHORT_5_6_5...: GL_INVALID_OPERATION).
//! - A mapping (glMapBuffer, glMapBufferRange) is a copy of the mapped
//!   range, written back by glUnmapBuffer (or, with
//!   GL_MAP_FLUSH_EXPLICIT_BIT, by each glFlushMappedBufferRange): writes
//!   through the pointer are not seen by GL before then. Drawing from a
//!   mapped vertex or element buffer, glGetBufferSubData on a mapped
//!   buffer and glBufferSubData into the mapped range raise
//!   GL_INVALID_OPERATION (GL 3.3 §2.9).
//! - The client buffer's contents are loaded as the framebuffer's at
//!   OSMesaMakeCurrent and OSMesaPixelStore (Mesa renders in place); what
//!   the client writes into it later, between GL calls, is not seen by GL
//!   and is overwritten by the next flush if GL drew since.
//! - Depth/stencil sizes requested at creation only matter for
//!   OSMesaGetDepthBuffer; the context always has 24-bit depth and 8-bit
//!   stencil. `sharelist` is accepted but nothing is shared.
#![allow(non_snake_case, clippy::missing_safety_doc)]

// mimalloc for the library's own allocations (the host program keeps its
// allocator): the system allocator returned the worker threads' arenas to
// the OS after every large draw and faulted them in again on the next one,
// and it is slower for the compiler's many small nodes (the measurements:
// docs/PERFORMANCE.md, design decisions). [`allocator`] keeps its address
// space reservations small.
// The `mimalloc` feature (default) selects it: memory checkers build without
// it, since they track only the system allocator's blocks.
#[cfg(feature = "mimalloc")]
#[global_allocator]
static ALLOC: allocator::Allocator = allocator::Allocator;

pub mod abi;
#[cfg(feature = "mimalloc")]
pub mod allocator;
pub mod arrays;
pub mod attribs;
pub mod buffers;
pub mod context;
pub mod debug_env;
pub mod drawing;
pub mod fixed_function;
pub mod framebuffer;
pub mod framebuffer_objects;
pub mod layer_state;
pub mod legacy;
pub mod lists;
pub mod occlusion;
pub mod osmesa;
pub mod osmesa_enums;
pub mod pixel_path;
pub mod pixels;
pub mod procs;
pub mod queries;
pub mod rasterization;
pub mod shaders;
pub mod sync;
pub mod textures;
pub mod transform;
pub mod uniforms;
pub mod variants;
pub mod vertex_arrays;

// The C ABI at the crate root, as C sees it: the types, the OSMesa API
// and every gl* entry point. Each entry-point module has its own `lookup`;
// the root's is the whole OSMesaGetProcAddress table.
pub use abi::*;
pub use attribs::*;
pub use buffers::*;
pub use drawing::*;
pub use fixed_function::*;
pub use framebuffer::*;
pub use framebuffer_objects::*;
pub use legacy::*;
pub use lists::*;
pub use occlusion::*;
pub use osmesa::*;
pub use osmesa_enums::*;
pub use pixel_path::*;
pub use pixels::*;
pub use procs::{lookup, OSMesaGetProcAddress};
pub use queries::*;
pub use rasterization::*;
pub use shaders::*;
pub use sync::*;
pub use textures::*;
pub use transform::*;
pub use uniforms::*;
pub use variants::*;
pub use vertex_arrays::*;
