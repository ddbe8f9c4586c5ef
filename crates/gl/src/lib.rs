//! # shaderbox-gl: the OpenGL state machine
//!
//! [`Context`] holds the state of one context and its objects: OpenGL 2.1,
//! or 3.3 core or compatibility ([`version::Api`]; the core profile
//! refuses what it removes, [`version`]); its methods are the GL entry points in snake case: `glFooBar4fv`
//! is `foo_bar_4fv` (`glCreateShader` → [`Context::create_shader`],
//! `glUniformMatrix2x3fv` → [`Context::uniform_matrix_2x3fv`]), except
//! that a parameter family whose forms differ only in how the values are
//! passed is one method over a [`param::Param`] (`glFogf`, `glFogiv` →
//! [`Context::fog`]). Enum values are GL's, in [`enums`].
//!
//! ## Contract
//! - Every invalid call records the GL 2.1 error (`GL_INVALID_ENUM`,
//!   `GL_INVALID_VALUE`, `GL_INVALID_OPERATION`) and has no other effect;
//!   [`Context::get_error`] returns and clears the first one recorded. No
//!   call panics, whatever its arguments.
//! - Shaders compile with [`glsl::compile`] and link with
//!   [`glsl::link::link_with`] (a program's GL_EXT_geometry_shader4
//!   parameters); info logs are theirs.
//! - Uniforms: every uniform a program's stages declare is active (even if
//!   unused, which is generous but allowed: GL 2.1 §2.15.3 only requires
//!   the used ones). Locations number every element of every basic-typed
//!   leaf (`s[1].a[2]`), in declaration order; `glUniform*` checks size and
//!   type as §2.15.3 says. Built-in `gl_*` uniforms are derived from the GL
//!   state at draw time ([`builtins`]).
//! - Client vertex arrays are byte copies ([`ArrayData::Client`]) since a
//!   Rust context cannot keep raw pointers; a C ABI maps pointers onto them.
//! - Deterministic: no platform math (matrices use [`glsl::math`]), no
//!   hash-order dependence.
//!
//! - Draws run the program's `exec` kernels (or generated fixed-function
//!   stages, [`ffgen`]; the fixed-function fragment stage directly when
//!   it can, [`ff_fragment`], with the kernel's bits; the program's
//!   geometry stage between them when it has one) through
//!   `raster::draw_stages` ([`draw`]) on the
//!   context's threads: [`Context::set_threads`], by default the
//!   environment variable `SHADERBOX_THREADS` ([`THREADS_ENV`]) or else the
//!   machine's available parallelism. Images do not depend on the count.
//!   Draws into the default framebuffer whose fragment stage cannot fail
//!   wait in a `raster::DrawQueue` ([`Context::waiting_draws`]) and are
//!   shaded together, one pass over the tiles, when anything reads or
//!   replaces its pixels, another render target or a draw that cannot
//!   wait comes, a timer query starts or ends, or at glFinish/glFlush.
//!
//! - Attribute stacks ([`attrib_stack`]): glPushAttrib/glPopAttrib restore
//!   per group; glPushClientAttrib/glPopClientAttrib the pixel-store and
//!   vertex-array state.
//! - Buffer objects follow GL 3.3 §2.9 ([`buffers`]): the GL 3.x targets,
//!   indexed uniform and transform-feedback binding points, mapping
//!   ranges (the caller holds the client's copy), copies.
//! - Pixel buffer objects: the GL_PIXEL_PACK_BUFFER / GL_PIXEL_UNPACK_BUFFER
//!   bindings are kept ([`Context::bound_buffer`]); a C layer moves the
//!   bytes (reads and writes of the buffer store through
//!   [`Context::get_buffer_sub_data`] / [`Context::buffer_sub_data`]).
//!
//! ## Modules
//! One job each; the [`Context`] entry points live with their job.
//! - The API: [`version`] (version and profile, their strings and
//!   queries, what the core profile removes).
//! - Objects: [`objects`] (the tables, glGen* names), [`buffers`],
//!   [`textures`] (glTex*, texture queries), [`mipmap`],
//!   [`texture_format`] (internal formats, stored texels),
//!   [`texture_buffer`] (glTexBuffer, buffer textures' texels),
//!   [`samplers`] (sampler objects),
//!   [`framebuffer`] (renderbuffers, FBOs, completeness, draw/read
//!   buffers), [`blit`] (glBlitFramebuffer).
//! - Client images: [`pixel_store`] (the glPixelStore modes: where a
//!   client image's pixels lie, copies to and from the packed layout),
//!   [`pixel_transfer`] (packed layout, unpack, pack, scale and
//!   bias), [`readback`] (glReadPixels), [`pixel_path`] (raster position,
//!   glDrawPixels, glBitmap, glCopyPixels).
//! - Shaders: [`program`], [`geometry_program`] (which contexts have
//!   geometry shaders, glProgramParameteriEXT, the geometry queries, the
//!   draw mode against the input primitive), [`program_blocks`] (uniform-block queries,
//!   blocks read from uniform buffers at draw time), [`program_outputs`]
//!   (fragment-output locations), [`program_pipeline`] (separable
//!   programs, program pipeline objects, the program of each stage), [`transform_feedback`], [`uniform`],
//!   [`uniform_block`] (std140 layout), [`builtins`] (the `gl_*`
//!   uniforms), [`ffgen`] (fixed-function stages as GLSL), [`storage`]
//!   (shader storage buffers, the memory of a draw or dispatch, compute
//!   dispatches).
//! - State: [`state`] (the fixed-function state, capabilities),
//!   [`transform`], [`shading`], [`rasterization`], [`per_fragment`],
//!   [`vertex`] (the vertex state, array pointers, fetch of one element),
//!   [`vertex_format`] (attribute types and their decoding),
//!   [`immediate`] (current values, glBegin/glEnd),
//!   [`vertex_array`] (vertex array objects), [`matrix`],
//!   [`param`] (the values of the glFog/glLight/glTexEnv... call families),
//!   [`attrib_stack`], [`get`] (glGet*), [`occlusion`], [`sync`] (fences),
//!   [`per_buffer`] (per-draw-buffer blending and masks, glClearBuffer*).
//! - A draw: [`draw`] (the calls, glClear; `restart` splits at
//!   primitive-restart indices) puts together [`kernels`],
//!   [`fetch`], [`pipeline_state`], [`texture_units`] and
//!   [`render_target`], with [`ff_fragment`] for the fixed-function
//!   fragment stage, [`layered`] for a geometry stage's gl_Layer (and
//!   clears of every layer) and [`debug`] for probes.
//!
//! ## Limitations
//! - No display lists (a C layer records them), selection/feedback,
//!   accumulation buffer, color index mode, evaluators.
//! - Occlusion queries ([`occlusion`]) and the raster-position pixel path
//!   ([`pixel_path`]) are implemented; pixel-rectangle fragments are not
//!   shaded (no texturing, fog or fragment shader on them).
//! - GL_COMBINE texture-environment parameters are kept for queries
//!   ([`Context::get_tex_envfv`]) but GL_COMBINE draws as GL_MODULATE.
//! - glPushAttrib does not save texture-object parameters or hints.
//! - GL_DEPTH_CLAMP turns off near/far clipping and clamps fragment
//!   depths to [0, 1] as they are stored; with a glDepthRange narrower
//!   than [0, 1] they are not clamped to that range. GL 3.3 allows
//!   GL_TEXTURE_CUBE_MAP_SEAMLESS to be enabled, but cube maps are still
//!   filtered face by face.

pub mod attrib_stack;
pub mod blit;
pub mod buffers;
pub mod builtins;
pub mod debug;
pub mod draw;
pub mod enums;
pub mod fetch;
pub mod ff_fragment;
pub mod ffgen;
pub mod framebuffer;
pub mod geometry_program;
pub mod get;
pub mod immediate;
pub mod kernels;
pub mod layered;
pub mod matrix;
pub mod mipmap;
pub mod objects;
pub mod occlusion;
pub mod param;
pub mod per_buffer;
pub mod per_fragment;
pub mod pipeline_state;
pub mod pixel_path;
pub mod pixel_store;
pub mod pixel_transfer;
pub mod program;
pub mod program_blocks;
pub mod program_outputs;
pub mod program_pipeline;
pub mod rasterization;
pub mod readback;
pub mod render_target;
pub(crate) mod restart;
pub mod samplers;
pub mod shading;
pub mod state;
pub mod storage;
pub mod sync;
pub mod texture_buffer;
pub mod texture_format;
pub mod texture_units;
pub mod textures;
pub mod transform;
pub mod transform_feedback;
pub mod uniform;
pub mod uniform_block;
pub mod version;
pub mod vertex;
pub mod vertex_array;
pub mod vertex_format;

use enums::*;
use std::collections::BTreeMap;

pub use param::Param;
pub use program::{ActiveInfo, ProgramObj, ShaderObj};
pub use state::{Light, Material};
pub use version::{Api, Profile};
pub use vertex::{ArrayData, ArrayState};

/// Maximum depth of every matrix stack.
pub const MAX_MATRIX_STACK_DEPTH: usize = 32;
/// Fixed-function texture units (texture coordinate sets and matrices).
pub const MAX_TEXTURE_UNITS: usize = glsl::limits::MAX_TEXTURE_UNITS as usize;
/// Texture image units (samplers).
pub const MAX_TEXTURE_IMAGE_UNITS: usize = glsl::limits::MAX_COMBINED_TEXTURE_IMAGE_UNITS as usize;
pub const MAX_LIGHTS: usize = glsl::limits::MAX_LIGHTS as usize;
pub const MAX_CLIP_PLANES: usize = glsl::limits::MAX_CLIP_PLANES as usize;
pub const MAX_VERTEX_ATTRIBS: usize = glsl::limits::MAX_VERTEX_ATTRIBS as usize;
pub const MAX_DRAW_BUFFERS: usize = glsl::limits::MAX_DRAW_BUFFERS as usize;
/// Largest texture / renderbuffer / viewport dimension.
pub const MAX_TEXTURE_SIZE: i32 = 8192;
/// Most vertices (array elements or indices) one draw call takes: a
/// larger draw is GL_OUT_OF_MEMORY, not an allocation or a run without end.
pub const MAX_DRAW_VERTICES: i32 = 1 << 24;
/// Most vertices times instances of one draw call (GL_OUT_OF_MEMORY
/// beyond, as for [`MAX_DRAW_VERTICES`]).
pub const MAX_DRAW_INVOCATIONS: i64 = 1 << 28;
/// Largest extent of a three-dimensional image (3D textures, and the
/// layers and sides of array textures): GL_MAX_3D_TEXTURE_SIZE and
/// GL_MAX_ARRAY_TEXTURE_LAYERS.
pub const MAX_3D_TEXTURE_SIZE: i32 = 2048;
/// Most texels one image or multisample buffer may hold (2^26, 1 GiB of
/// float RGBA): a larger one is GL_OUT_OF_MEMORY, not an attempted
/// allocation.
pub const MAX_TEXELS: usize = 1 << 26;

/// A GL context.
pub struct Context {
    /// The version and profile ([`version`]).
    pub(crate) api: Api,
    pub(crate) error: u32,
    pub(crate) width: i32,
    pub(crate) height: i32,
    // Objects.
    pub(crate) next_name: u32,
    pub(crate) shaders: BTreeMap<u32, ShaderObj>,
    pub(crate) programs: BTreeMap<u32, ProgramObj>,
    pub(crate) current_program: u32,
    /// Program pipeline objects and the bound one ([`program_pipeline`]).
    pub(crate) pipelines: program_pipeline::Pipelines,
    pub(crate) objects: objects::Objects,
    // Transformation state.
    pub(crate) matrix_mode: u32,
    pub(crate) modelview: Vec<matrix::Mat4>,
    pub(crate) projection: Vec<matrix::Mat4>,
    pub(crate) texture_matrix: Vec<Vec<matrix::Mat4>>,
    pub(crate) viewport: [i32; 4],
    pub(crate) depth_range: [f32; 2],
    pub(crate) clip_planes: [[f32; 4]; MAX_CLIP_PLANES],
    // Everything else fixed-function.
    pub(crate) st: state::State,
    // Vertex arrays and current values.
    pub(crate) va: vertex::VertexState,
    /// The default framebuffer. Its pixels lag behind the draws in
    /// `queued`: read or replace it after [`Context::flush_draws`].
    pub(crate) fb: raster::Framebuffer,
    /// Draws into the default framebuffer whose fragment stages wait
    /// ([`raster::DrawQueue`]; see `draw`).
    pub(crate) queued: raster::DrawQueue,
    pub(crate) cache: kernels::DrawCache,
    /// The threads draws run on ([`Context::set_threads`]).
    pub(crate) workers: raster::Workers,
    /// glPushAttrib / glPushClientAttrib stacks.
    pub(crate) attrib_stack: Vec<attrib_stack::ServerAttribs>,
    pub(crate) client_attrib_stack: Vec<attrib_stack::ClientAttribs>,
    /// Draw debugging ([`Context::set_debug`]).
    pub(crate) debug: debug::DebugSession,
    /// Occlusion query objects ([`occlusion`]).
    pub(crate) queries: occlusion::Queries,
    /// The current raster position ([`pixel_path`]).
    pub(crate) raster: pixel_path::RasterPos,
    /// Sync objects ([`sync`]).
    pub(crate) syncs: sync::Syncs,
    /// The active transform feedback ([`transform_feedback`]).
    pub(crate) feedback: transform_feedback::Feedback,
    /// The layer of layered framebuffer attachments that draws write
    /// (chosen per primitive by a geometry stage's gl_Layer; 0 otherwise).
    pub(crate) draw_layer: i32,
}

/// The environment variable giving the default number of draw threads.
pub const THREADS_ENV: &str = "SHADERBOX_THREADS";

/// [`THREADS_ENV`] as a thread count; 0 (available parallelism) when unset
/// or not a number.
fn threads_from_env() -> usize {
    std::env::var(THREADS_ENV)
        .ok()
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(0)
}

impl Default for Context {
    fn default() -> Self {
        Context::new(1, 1)
    }
}

impl Context {
    /// A GL 2.1 context whose default framebuffer is `width` x `height`
    /// RGBA8 with a 24-bit depth and an 8-bit stencil buffer.
    pub fn new(width: i32, height: i32) -> Context {
        Context::with_api(width, height, Api::GL21)
    }

    /// [`Context::new`] implementing `api` (one of [`Api::GL21`],
    /// [`Api::GL33_CORE`], [`Api::GL33_COMPAT`]; [`Api::for_request`]
    /// maps a requested version onto them).
    pub fn with_api(width: i32, height: i32, api: Api) -> Context {
        let (w, h) = (
            width.clamp(1, MAX_TEXTURE_SIZE),
            height.clamp(1, MAX_TEXTURE_SIZE),
        );
        Context {
            api,
            error: GL_NO_ERROR,
            width: w,
            height: h,
            next_name: 1,
            shaders: BTreeMap::new(),
            programs: BTreeMap::new(),
            current_program: 0,
            pipelines: program_pipeline::Pipelines::default(),
            objects: objects::Objects::new(w, h),
            matrix_mode: GL_MODELVIEW,
            modelview: vec![matrix::IDENTITY],
            projection: vec![matrix::IDENTITY],
            texture_matrix: vec![vec![matrix::IDENTITY]; MAX_TEXTURE_UNITS],
            viewport: [0, 0, w, h],
            depth_range: [0.0, 1.0],
            clip_planes: [[0.0; 4]; MAX_CLIP_PLANES],
            st: state::State::new(w, h),
            va: vertex::VertexState::new(),
            fb: raster::Framebuffer::new(
                w as u32,
                h as u32,
                raster::ColorFormat::Rgba8,
                true,
                true,
            ),
            queued: raster::DrawQueue::default(),
            cache: kernels::DrawCache::default(),
            workers: raster::Workers::new(threads_from_env()),
            attrib_stack: Vec::new(),
            client_attrib_stack: Vec::new(),
            debug: debug::DebugSession::default(),
            queries: occlusion::Queries::default(),
            raster: pixel_path::RasterPos::default(),
            syncs: sync::Syncs::default(),
            feedback: transform_feedback::Feedback::default(),
            draw_layer: 0,
        }
    }

    /// Runs draws on `threads` threads (1: on the calling thread; 0: the
    /// machine's available parallelism, the default unless the environment
    /// variable `SHADERBOX_THREADS` says otherwise). Images are
    /// bit-identical whatever the number.
    pub fn set_threads(&mut self, threads: usize) {
        if threads != self.workers.threads() || threads == 0 {
            self.flush_draws();
            self.workers = raster::Workers::new(threads);
        }
    }

    /// The number of threads draws run on.
    pub fn threads(&self) -> usize {
        self.workers.threads()
    }

    /// The threads draws run on, for other parallel work on the
    /// context's pixels (the OSMesa layer's copy to the client buffer).
    pub fn workers(&self) -> &raster::Workers {
        &self.workers
    }

    /// Width of the default framebuffer.
    pub fn width(&self) -> i32 {
        self.width
    }

    /// Height of the default framebuffer.
    pub fn height(&self) -> i32 {
        self.height
    }

    /// The default framebuffer (window-system buffer) with every draw
    /// done, and the threads, for wrappers such as an OSMesa C ABI that
    /// copy it into client memory.
    pub fn default_framebuffer(&mut self) -> (&raster::Framebuffer, &raster::Workers) {
        self.flush_draws();
        (&self.fb, &self.workers)
    }

    /// How many draws wait in the draw queue: their fragment stages run
    /// at the next flush (glFinish, glFlush, a read of the framebuffer,
    /// another render target...).
    pub fn waiting_draws(&self) -> usize {
        self.queued.len()
    }

    /// Runs the fragment stages of the draws waiting in the queue into the
    /// default framebuffer (`draw`): before anything reads or replaces
    /// its pixels. A failure is kept for [`Context::take_draw_error`].
    pub(crate) fn flush_draws(&mut self) {
        if self.queued.is_empty() {
            return;
        }
        if let Err(e) = self.queued.flush(&self.workers, &mut self.fb) {
            self.cache.error = Some(e.to_string());
        }
    }

    /// Resizes the default framebuffer to `width` x `height` (clamped to
    /// 1..=[`MAX_TEXTURE_SIZE`]); its contents become zero. The viewport and
    /// scissor box are left as they are (a window-system resize).
    pub fn resize_default_framebuffer(&mut self, width: i32, height: i32) {
        let (w, h) = (
            width.clamp(1, MAX_TEXTURE_SIZE),
            height.clamp(1, MAX_TEXTURE_SIZE),
        );
        if (w, h) == (self.width, self.height) {
            return;
        }
        self.flush_draws();
        self.width = w;
        self.height = h;
        self.fb =
            raster::Framebuffer::new(w as u32, h as u32, raster::ColorFormat::Rgba8, true, true);
    }

    /// Replaces the default framebuffer with `fb` and returns the one it
    /// held: a window system whose surfaces own their pixels (EGL) moves a
    /// surface's buffers in when a context is made current to it and out
    /// when it is released. The size follows `fb`; the viewport and scissor
    /// box are left as they are.
    pub fn replace_default_framebuffer(&mut self, fb: raster::Framebuffer) -> raster::Framebuffer {
        self.flush_draws();
        self.width = (fb.width as i32).clamp(1, MAX_TEXTURE_SIZE);
        self.height = (fb.height as i32).clamp(1, MAX_TEXTURE_SIZE);
        std::mem::replace(&mut self.fb, fb)
    }

    /// Loads `pixels` (RGBA8, bottom row first, `width * height` of them)
    /// into the default framebuffer's color buffer: a wrapper whose client
    /// memory *is* the window (OSMesa) makes it the starting contents.
    /// Missing pixels are left as they were.
    pub fn load_default_color(&mut self, pixels: &[[u8; 4]]) {
        self.flush_draws();
        if let Some(raster::ColorBuffer::Rgba8(v)) = self.fb.color.get_mut(0) {
            for (d, s) in v.iter_mut().zip(pixels) {
                *d = *s;
            }
        }
    }

    /// The vertex-array state (pointers, enables, client active texture),
    /// read-only.
    pub fn vertex_state(&self) -> &vertex::VertexState {
        &self.va
    }

    /// Replaces the bytes of the client-memory array `src` (one whose
    /// pointer was specified with no buffer bound) without touching its
    /// other state. A C ABI calls this at draw time with a copy of the
    /// memory the client's pointer designates. Returns false (and changes
    /// nothing) for a buffer-object array or an out-of-range source.
    pub fn replace_client_array_data(
        &mut self,
        src: vertex::AttribSource,
        data: ArrayData,
    ) -> bool {
        let va = &mut self.va;
        let arr = match src {
            vertex::AttribSource::Position => Some(&mut va.vertex_array),
            vertex::AttribSource::Color => Some(&mut va.color_array),
            vertex::AttribSource::SecondaryColor => Some(&mut va.secondary_array),
            vertex::AttribSource::Normal => Some(&mut va.normal_array),
            vertex::AttribSource::FogCoord => Some(&mut va.fog_array),
            vertex::AttribSource::TexCoord(u) => va.tex_arrays.get_mut(u as usize),
            vertex::AttribSource::Generic(i) => va.generic_arrays.get_mut(i as usize),
        };
        match arr {
            Some(a) if a.buffer == 0 => {
                a.data = data;
                true
            }
            _ => false,
        }
    }

    /// Records a GL error found by a wrapper (e.g. a C ABI rejecting a
    /// negative count before it can build the arguments), with the same
    /// first-error-wins rule as every other error.
    pub fn record_error(&mut self, err: u32) {
        self.set_error(err);
    }

    /// Records `err` unless an earlier error is still pending (GL 2.1 §2.5:
    /// one error flag; later errors are dropped until glGetError).
    pub(crate) fn set_error(&mut self, err: u32) {
        if self.error == GL_NO_ERROR {
            self.error = err;
        }
    }

    /// glGetError.
    pub fn get_error(&mut self) -> u32 {
        std::mem::replace(&mut self.error, GL_NO_ERROR)
    }

    /// True between glBegin and glEnd; most commands are then
    /// `GL_INVALID_OPERATION` (GL 2.1 §2.6.3).
    pub fn in_begin_end(&self) -> bool {
        self.va.begin_mode.is_some()
    }

    /// Records `GL_INVALID_OPERATION` and returns true inside glBegin/glEnd.
    pub fn reject_in_begin(&mut self) -> bool {
        if self.in_begin_end() {
            self.set_error(GL_INVALID_OPERATION);
            true
        } else {
            false
        }
    }

    /// The checks a state setter makes before it changes anything: not
    /// between glBegin and glEnd (GL_INVALID_OPERATION), then `valid`
    /// (else `error`). True when the setter may go on.
    pub(crate) fn setter_accepts(&mut self, valid: bool, error: u32) -> bool {
        if self.reject_in_begin() {
            return false;
        }
        if !valid {
            self.set_error(error);
        }
        valid
    }

    fn fresh_name(&mut self) -> u32 {
        let n = self.next_name;
        self.next_name = self.next_name.wrapping_add(1).max(1);
        n
    }

    /// glFinish: runs the draws waiting in the queue.
    pub fn finish(&mut self) {
        if !self.reject_in_begin() {
            self.flush_draws();
        }
    }

    /// glFlush: runs the draws waiting in the queue (GL 3.3 §5.2: they
    /// complete in finite time).
    pub fn flush(&mut self) {
        if !self.reject_in_begin() {
            self.flush_draws();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_error_wins_and_clears() {
        let mut ctx = Context::new(4, 4);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.enable(0xdead);
        ctx.viewport(0, 0, -1, 1);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
    }
}
