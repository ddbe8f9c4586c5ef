//! The GL 2.1 primitive pipeline on the CPU: vertex fetch, primitive
//! assembly, clipping, rasterization, interpolation, per-fragment
//! operations, framebuffers and texture sampling.
//!
//! # Contract
//! [`draw()`] runs the vertex kernel once per distinct index (batches of
//! `exec::LANES` vertices), assembles primitives for every [`Mode`], clips
//! them in clip space against the view volume and the enabled user clip
//! planes (GL 2.1 §2.12), maps them to window space (§2.11), determines
//! facing from the window-space area (§3.5.1), culls, and rasterizes
//! (fill, line or point polygon modes). Fragments are shaded in 2×2 quads,
//! four quads per `exec::Batch` (quads of consecutive primitives share a
//! batch when early depth rejection against a depth buffer without the
//! batch's pending fragments stays exact: no stencil test, a depth
//! function that moves stored depths one way), and go through the GL 2.1
//! §4.1 per-fragment operations in primitive order. The framebuffer is
//! processed in 64×64 tiles, each seeing the primitives in draw order.
//! Results are bit-identical on every machine: f64/f32 IEEE arithmetic
//! without fused operations, `glsl::math` for the few functions needed,
//! fixed iteration orders.
//!
//! # Threads
//! [`draw_on`] runs on a [`Workers`] (1 thread = inline on the caller; more
//! = a rayon pool owned by the `Workers`, no global state). Groups of 64
//! vertices (four batches of `exec::LANES`) are tasks writing their own
//! vertices' outputs in place; primitive set-up runs in chunks of 2,048
//! primitives whose results are taken in primitive order, each chunk also
//! listing its primitives per tile; each 64×64 tile is a task that owns a
//! copy of its pixels and runs its primitives in draw order (the chunks'
//! lists in chunk order), and the tiles are written back by bands of tile
//! rows (disjoint rows of the framebuffer), each band a task, up to the
//! first failed tile; a fragment program that cannot fail
//! ([`ShaderStage::always_completes`]) has each task write its tile back
//! through its own rows as soon as it is done. A [`DrawQueue`] keeps such
//! draws set up and binned until its flush, where each tile task runs
//! every waiting draw's primitives, draw after draw, on one copy of the
//! tile (the same bytes as the draws one by one). No value is combined across tasks, and
//! textures are read-only, so the framebuffer is bit-identical whatever the
//! thread count. A shader error (`exec::ExecError`, e.g. the loop budget)
//! ends the draw as running the tiles one after the other would: tiles
//! before the first failing tile (in row-major tile order) are complete,
//! that tile keeps the fragments written before the error, later tiles are
//! untouched, and that tile's error is returned. (A vertex-stage error
//! draws nothing and reports the first failing vertex batch's error.)
//!
//! # Costs around the shader
//! Per draw, not per batch or primitive: the uniform-only values of both
//! stages (`ShaderStage::prepare`, `exec::Kernel::prepare`), the vertex
//! input layout, which fragment inputs the shader reads (unread varyings
//! are left zero; the depth-only pass fills those its slice's interface
//! marks read) and which colour outputs go to draw buffers. Set-up
//! allocates nothing per primitive: the planes of its varyings
//! (`interpolate`: set up once per primitive, evaluated per pixel as
//! `(c + Y·dy) + X·dx` in f32, times 1/(1/w) when the vertices' 1/w
//! differ) go to one array per set-up chunk (used where they are), triangles and quads inside every clip
//! plane skip the clipper, and when vertices are shared (indexed meshes)
//! each vertex's clip outcode and window position are computed once, on
//! the workers, instead of per primitive. The set-up chunks' arrays and the vertex
//! outputs are kept by the [`Workers`] for its next draws (up to 256 MiB),
//! so a steady stream of draws does not pay page faults on fresh memory.
//! A quad (or a clipped polygon of four corners), or two consecutive
//! triangles of a list, strip or fan sharing an edge, that is strictly
//! convex and whose values the fragment stage reads are the same bits at
//! its four vertices (billboards: sphere impostors; window z only where
//! it is read, gl_FragDepth making it unread) is set up as one primitive
//! of four edges instead of two triangles, covering exactly their pixels
//! with the same (constant) planes (`Setup::one_quadrilateral`,
//! `Setup::triangle_pair`, `rasterize::Shape::quadrilateral_snapped`).
//! Triangle coverage steps integer edge forms (exactly the edge function
//! values, four pixels and three edges (four for a quadrilateral) per 2×2 quad, kept in vector
//! registers, a row ending at the first quad an edge rules out for the
//! rest of the row) into a buffer reused per tile; a quad's window z
//! (from its f64 plane) is computed only when something reads it (a depth
//! test of interpolated depths, gl_FragCoord or the debugger's probe),
//! its varyings only when its batch is filled; a batch's quads are built in place in four per-tile slots, and
//! the varyings and set-up of primitives a few ahead in the tile's bin
//! (and the pointers to those further ahead) are prefetched while one is
//! rasterized. When no input is per pixel beyond gl_FragCoord and
//! gl_FrontFacing, four whole quads side by side of one triangle (a
//! *strip*) make a batch without per-quad entries (the coverage walk lists
//! a strip as one entry and steps over its quads at once,
//! `Shape::quads_into_strips`; quads waiting for a batch are shaded
//! before it): their window z and inputs are evaluated from the planes
//! over the 16 lanes at once (each quad's bits), the early depth test
//! drops pixels as for single quads; with AVX-512 and no depth test, the
//! strip's colour write (opaque or SRC_ALPHA / ONE_MINUS_SRC_ALPHA) covers
//! its two rows of eight pixels at once with the per-pixel write's
//! operations. Any batch of four quads that form a strip fills its inputs
//! the same way, and the deferred depth pass runs a wide triangle's
//! strips as batches of their own.
//!
//! Filling a batch's inputs and a quad's interpolation are compiled for
//! every CPU level (`exec::cpu::Level`: baseline, AVX2, AVX-512, by
//! `exec::multiversion!`) and picked at run time (so are set-up and the
//! batched quad loop of coverage, quad set-up, early depth test and
//! writes; the highest level the CPU runs, or
//! `SHADERBOX_RASTER_ISA=portable|avx2|avx512`: `simd`); they
//! use plain IEEE operations, so every variant gives the same bits (tests
//! compare them). With no alpha or stencil test, the per-fragment tests
//! run with the state's choices made once per tile (a quad's four pixels
//! at once when it lies inside the tile), and with one RGBA8
//! draw buffer written on every channel and no logic op so does the
//! colour write (blending included); other states go through the general
//! per-fragment functions. Both give the same bytes (tests compare them).
//!
//! # Colors for visible fragments only
//! When the fragment stage has a depth-only slice
//! ([`ShaderStage::depth_only`]: `exec` offers one to kernels writing
//! `gl_FragDepth`, where early depth testing is impossible, and to costly
//! kernels, where shading each pixel once pays for a second pass) and the
//! per-fragment operations let the last fragment to pass the depth test
//! decide a pixel (no alpha test, blending, logic op or stencil test),
//! each tile runs the slice on every fragment (without `gl_FragDepth`: on
//! those early depth rejection keeps; a slice that
//! [`ShaderStage::does_nothing`] is not run, each covered quad is only
//! depth-tested), depth-tests in draw
//! order and remembers the winning primitive per pixel, then runs the full
//! stage once per winning (primitive, 2×2 quad), with the same inputs,
//! coverage and helper lanes as the straightforward path, and writes the
//! colors. A pass whose stage has independent lanes
//! ([`ShaderStage::lanes_independent`]) packs the pixels it runs of up to
//! 16 quads into each batch, without helper lanes (a lane's results do
//! not depend on its neighbours then). With `gl_FragDepth`, a slice
//! offering a bound on it ([`ShaderStage::depth_range`]) lets the depth
//! pass drop, before running the slice, the pixels of a primitive whose
//! every possible depth the depth test rejects (LESS, LEQUAL: the bound's
//! near end against the stored depths; GREATER, GEQUAL: its far end; no
//! stencil test): they would fail later and change nothing. The bytes
//! are those of the straightforward path (tests compare
//! both); on a shader error the tile is redrawn the straightforward way so
//! errors and partial results are unchanged. The debugger's probe always
//! takes the straightforward path.
//!
//! Vertex → fragment linkage is by name (user varyings, gl_TexCoord,
//! gl_FogFragCoord); gl_Color / gl_SecondaryColor come from
//! gl_FrontColor / gl_FrontSecondaryColor, or from the back colors for
//! back-facing polygons when `two_sided_color` is on. Vertex colors are
//! clamped to [0, 1] (§2.14.6). Flat shading applies to those two colors
//! only and uses the provoking vertex of GL 2.1 table 2.12 (last vertex of
//! lines, triangles and quads; first of a GL_POLYGON).
//!
//! Textures ([`Texture`], [`TextureUnits`]) implement `exec::Textures`
//! following GL 2.1 §3.8. A level whose every component is exactly
//! `k / 255` is stored as RGBA8 ([`Image::is_unorm8`]) and read back as
//! those exact values, so storage never changes a result. 2D lookups with
//! one unit for the whole request, no depth comparison and REPEAT,
//! CLAMP_TO_EDGE or MIRRORED_REPEAT wrapping take a fast path that works
//! over the 16 lanes at once with the general path's operations in the
//! same order (the same bits; `texture_2d` tests compare the two), its
//! x86 variants filtering RGBA8 levels in vector registers
//! (`texture_2d/wide.rs`, over `exec::lanes16::Lanes16`: AVX-512, or two
//! AVX2 registers per value); docs/PERFORMANCE.md has its share of the
//! profile. Level of detail: λ_base once
//! per 2×2 quad, from the derivatives of the quad's first pixel (GL 2.1
//! §3.8.8 lets ρ be approximated; llvmpipe does the same), biases and
//! clamps per fragment. LINEAR on RGBA8 levels of 2D textures and cube
//! faces is computed in fixed point (`unorm8_filter.rs`: 7-bit texel
//! weights, 16-bit sums with rounding, the result m/32640 correctly
//! rounded, so a texel read alone is exactly k/255), the same definition
//! in every path and instruction set; f32 levels, 1D and 3D textures,
//! depth textures and lookups touching the border colour filter in f32.
//! The GL 3.x targets and lookups take the general path: 1D and 2D
//! arrays (layer = clamp(RNE(r))), rectangles (texel coordinates),
//! buffer textures, texel offsets, explicit gradients (each lane's own),
//! integer textures (nearest texel, the integers' bits returned), sRGB
//! decoding before filtering, swizzles; `texelFetch` and `textureSize`
//! are `Textures::fetch` and `Textures::size`.
//! Blending with FUNC_ADD and SRC_ALPHA/ONE_MINUS_SRC_ALPHA, ONE/ZERO or
//! ONE/ONE into an RGBA8 buffer runs as straight-line code with the
//! general equations' bits. Dual-source blending (GL 3.3): a user output
//! at location 0 with `index` 1 is draw buffer 0's second source colour,
//! carried beside the draw buffers' colours and read by the SRC1 factors
//! (the per-tile colour path steps aside for them); other draw buffers'
//! SRC1 factors read zeros.
//!
//! # Modules, stage by stage
//! - vertex fetch and the vertex stage: `vertex` (`run_vertices`);
//! - primitive assembly: `assembly` (`primitive`, `small_polygon`, and
//!   `geometry_input` with the adjacent vertices);
//! - shaded vertices passed between the stages: `shaded` (`Vertices`);
//! - the geometry stage: `geometry` (`run_geometry`: a geometry kernel
//!   per assembled primitive, 16 per batch, its emitted strips made a
//!   point, line or triangle list for set-up; [`draw_stages`]);
//! - clipping: `clip` (`Planes::clip_polygon`, `clip_line`);
//! - set-up (window transform, facing, culling, polygon offset, planes):
//!   `setup` (`Setup::chunk`), giving `prim::Prim`s;
//! - binning into tiles: `binning` (`ChunkBins::new`, `Bins`);
//! - rasterization (coverage): `rasterize` (`Shape`);
//! - interpolation: `interpolate` (`PrimPlanes`, `Plane`);
//! - fragment shading: `shade` (`FragmentStage::shade`; the faster loops
//!   with the same bytes in `shade/batched.rs`, `shade/deferred.rs`);
//! - per-fragment operations: `fragment_ops` (`process`, one fragment at
//!   a time), its parts `stencil`, `depth` (a quad's four depth tests),
//!   `color` (blending, logic op, masks), `quick` (`QuickOps`: the common
//!   states decided once per tile) and `wide` (16 colours in vector
//!   registers);
//! - textures, in layers: `texture` (storage, completeness; in
//!   `texture/levels.rs` λ, level selection and wrapping, shared by both
//!   paths), beside each other above it `texture_general` (every lookup,
//!   lane by lane) and `texture_2d` (the 2D fast path, same bits; its
//!   parts `storage`, `lod`, `address`, `filter`, `lanes` and the x86
//!   register filter `wide`), and on top `texture_units`
//!   (`TextureUnits`, handing each lookup to one of the two);
//!   `unorm8_filter` (fixed-point RGBA8 filtering);
//! - framebuffers: `framebuffer`, clears in `clear`;
//! - the draw driver and threads: `draw` (`draw_probed`, `SetUp`,
//!   `shade_tiles`), `queue` ([`DrawQueue`]: draws whose fragment stages
//!   wait for one pass over the tiles), `workers`, `spare` (buffers kept
//!   between draws);
//! - the debugger: `probe` (recorder, report types), `replay`
//!   ([`probe_draw`], [`view_draw`]).
//!
//! # Limitations and choices where GL leaves things undefined
//! - When the vertex shader writes neither gl_ClipDistance nor
//!   gl_ClipVertex, user clip planes are evaluated against gl_Position
//!   (GL 2.1 §2.12 leaves it undefined); an enabled plane past the end of
//!   the gl_ClipDistance it writes does not clip (GL 3.3 §2.20 leaves it
//!   undefined).
//! - Polygons in line or point mode draw the edges / vertices of the
//!   unclipped polygon (clipped as lines / points); no edges appear along
//!   clip boundaries.
//! - Lines use a "center in half-open span" rule that agrees with the
//!   diamond-exit rule except at some endpoints; no antialiasing,
//!   stippling or multisampling. Points ignore distance attenuation.
//! - No texture borders (border width 0; the border color is used).
//! - Depth buffers are 24-bit fixed point, stencil 8 bits; color buffers
//!   are RGBA8 unorm or RGBA32F. Dithering is off.
//! - Fragment outputs that the shader never writes are written as zeros.

mod assembly;
mod binning;
mod clear;
mod clip;
mod draw;
#[cfg(test)]
mod draw_tests;
mod fragment_ops;
mod framebuffer;
mod geometry;
mod interpolate;
mod linkage;
mod pixel_fragments;
mod prim;
mod probe;
mod queue;
mod rasterize;
mod replay;
mod setup;
mod shade;
mod shaded;
mod simd;
mod spare;
mod state;
mod texture;
mod texture_2d;
mod texture_general;
mod texture_units;
mod unorm8_filter;
mod vertex;
mod workers;

#[cfg(test)]
mod e2e_tests;

/// One step of the tests' pseudo-random sequence (a 32-bit linear
/// congruential generator, Numerical Recipes' constants): the next state.
#[cfg(test)]
pub(crate) fn lcg_step(state: u32) -> u32 {
    state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223)
}

/// The tests' pseudo-random 24-bit values from `seed` ([`lcg_step`], the
/// state's top 24 bits).
#[cfg(test)]
pub(crate) fn lcg_bits(mut seed: u32) -> impl FnMut() -> u32 {
    move || {
        seed = lcg_step(seed);
        seed >> 8
    }
}
pub(crate) use ::exec as ex;

pub use assembly::Mode;
pub use binning::TILE;
pub use draw::{draw_emitted, draw_stages};
pub use framebuffer::{
    depth16_to_fixed, depth_to_fixed, fixed_to_depth, float_to_unorm8, unorm8_to_float,
    ColorBuffer, ColorFormat, DepthFormat, Framebuffer, DEPTH_MAX, MAX_DRAW_BUFFERS,
    MAX_FRAMEBUFFER_SIZE,
};
pub use geometry::shade_geometry;
pub use pixel_fragments::{write_pixel_fragments, PixelFragment};
pub use probe::{
    DrawProbe, EmittedBy, EmittedVertex, Event, FragmentProbe, GeometryProbe, OpsProbe, PixelState,
    PrintLine, VertexProbe, View, ViewImage, MAX_TRACE_EVENTS,
};
pub use queue::{DrawQueue, QueuedFragments};
pub use rasterize::SUBPIXEL_BITS;
pub use replay::{probe_draw, view_draw, ProbeRequest, Replay};
pub use setup::MAX_POINT_SIZE;
pub use shaded::{layered_primitives, LayerSelect};
pub use state::{
    Blend, BlendEquation, BlendFactor, CompareFunc, CullFace, FrontFace, LogicOp, PipelineState,
    PolygonMode, PolygonOffset, PrimitiveIds, Rect, StencilFace, StencilOp, StencilState,
};
pub use texture::{
    DepthTextureMode, Image, MagFilter, MinFilter, Swizzle, Texture, TextureTarget, TextureUnit,
    Wrap,
};
pub use texture_units::TextureUnits;
pub use vertex::{fetch_column_each, fetch_vertex, shade_vertices, VertexFetch};
pub use workers::{Workers, MAX_THREADS};

/// Why a draw stopped. Fragments written before the error stay written
/// (see the crate documentation for which, with several threads).
#[derive(Debug, thiserror::Error)]
pub enum DrawError {
    #[error(transparent)]
    Exec(#[from] ex::ExecError),
    /// A draw of 2^32 − 1 indices or more (GL's own calls send at most
    /// 2^24).
    #[error("a draw takes fewer than 2^32 - 1 indices ({0} given)")]
    TooManyIndices(usize),
    /// Queued draws flushed into a framebuffer of another size than they
    /// were set up for (`DrawQueue::flush`): they are dropped.
    #[error("queued draws were set up for a framebuffer of another size")]
    QueueTarget,
}

/// A shader stage the pipeline can run: `exec::Kernel`, or anything else
/// with the same interface (tests use hand-written stages). Stages run on
/// several threads at once when the draw does. A stage reads the batch's
/// inputs and writes its outputs and `discarded`, never its inputs (the
/// fragment stage keeps inputs that no stage of the draw reads zero from
/// one batch to the next instead of clearing them).
pub trait ShaderStage: Sync {
    fn interface(&self) -> &ex::Interface;
    fn run(
        &self,
        batch: &mut ex::Batch,
        uniforms: &[u32],
        textures: &dyn ex::Textures,
    ) -> Result<(), ex::ExecError>;

    /// The uniform-only values of the stage for `uniforms` and `textures`
    /// (the draw's), computed once per draw for
    /// [`ShaderStage::run_prepared`] (`exec::Kernel::prepare`). `None`
    /// (the default): nothing to prepare.
    fn prepare<'t>(
        &self,
        _uniforms: &[u32],
        _textures: &'t dyn ex::Textures,
    ) -> Option<ex::Prepared<'t>> {
        None
    }

    /// [`ShaderStage::run`] with what [`ShaderStage::prepare`] returned for
    /// the same `uniforms`; the same results, bit for bit.
    fn run_prepared(
        &self,
        batch: &mut ex::Batch,
        _prepared: &ex::Prepared<'_>,
        uniforms: &[u32],
        textures: &dyn ex::Textures,
    ) -> Result<(), ex::ExecError> {
        self.run(batch, uniforms, textures)
    }

    /// A stage with the same interface that computes only what decides a
    /// fragment's fate (`gl_FragDepth` and discard), bit for bit as this
    /// stage does; see `exec::Kernel::depth_only`. When the fragment stage
    /// has one and the per-fragment operations allow it, the pipeline runs
    /// it on every fragment and this stage only on the fragments that end
    /// up visible. `None` (the default): always run this stage.
    fn depth_only(&self) -> Option<Box<dyn ShaderStage>> {
        None
    }

    /// A bound on the `gl_FragDepth` the stage writes over a region of a
    /// primitive, prepared for the uniform words `uniforms`
    /// (`exec::Kernel::depth_range`): the fragment stage then rejects the
    /// fragments whose every possible depth fails the depth test before
    /// running the stage on them. `None` (the default): no bound.
    fn depth_range(&self, _uniforms: &[u32]) -> Option<ex::DepthRange> {
        None
    }

    /// Whether running the stage leaves a batch's outputs as they were
    /// and discards nothing (a kernel without ops, such as the depth-only
    /// slice of a shader that neither writes `gl_FragDepth` nor discards):
    /// the pipeline then need not run it. `false` (the default): run it.
    fn does_nothing(&self) -> bool {
        false
    }

    /// Whether a run reads input component `c` (`exec::Kernel::reads_input`).
    /// The default: whether the interface marks the input slot holding it
    /// read.
    fn reads_input(&self, c: usize) -> bool {
        (self.interface().inputs.iter())
            .any(|s| s.written && (s.offset..s.offset + s.components).contains(&c))
    }

    /// Whether every run returns `Ok` (`exec::Kernel::always_completes`):
    /// the fragment stage may then write each tile back as soon as it is
    /// shaded, as no later failure can ask for the tiles after a failing
    /// one to be left untouched. `false` (the default): tiles are kept
    /// until every tile has run.
    fn always_completes(&self) -> bool {
        false
    }

    /// Whether every run writes every output component on every active
    /// lane and discards none: the fragment stage then need not clear a
    /// batch's outputs before it (outputs a shader leaves unwritten read
    /// 0). `false` (the default): they are cleared.
    fn writes_every_output(&self) -> bool {
        false
    }

    /// Whether each lane's outputs and discard depend only on its own
    /// inputs (no derivatives or other quad-wide operations; see
    /// `exec::Kernel::lanes_independent`): the fragment stage may then
    /// pack the covered pixels of several quads into one batch and run
    /// no helper lanes. `false` (the default): lanes run in whole quads.
    fn lanes_independent(&self) -> bool {
        false
    }

    /// [`ShaderStage::run`], reporting `lane`'s statements, stores and
    /// prints to `trace` (the debugger). Stages that cannot trace run
    /// plainly.
    fn run_probed(
        &self,
        batch: &mut ex::Batch,
        uniforms: &[u32],
        textures: &dyn ex::Textures,
        _lane: usize,
        _trace: &mut dyn ex::Trace,
    ) -> Result<(), ex::ExecError> {
        self.run(batch, uniforms, textures)
    }

    /// [`ShaderStage::run`], keeping the last value each lane stored into
    /// registers `first..` in `out` (stages without registers run plainly).
    fn run_watching(
        &self,
        batch: &mut ex::Batch,
        uniforms: &[u32],
        textures: &dyn ex::Textures,
        _first: u32,
        _out: &mut [[u32; ex::LANES]],
    ) -> Result<(), ex::ExecError> {
        self.run(batch, uniforms, textures)
    }

    /// [`ShaderStage::run`], reporting `debugPrintfEXT` output to `sink`.
    fn run_printing(
        &self,
        batch: &mut ex::Batch,
        uniforms: &[u32],
        textures: &dyn ex::Textures,
        _sink: &mut dyn ex::PrintSink,
    ) -> Result<(), ex::ExecError> {
        self.run(batch, uniforms, textures)
    }
}

impl ShaderStage for ex::Kernel {
    fn interface(&self) -> &ex::Interface {
        ex::Kernel::interface(self)
    }
    fn run(
        &self,
        batch: &mut ex::Batch,
        uniforms: &[u32],
        textures: &dyn ex::Textures,
    ) -> Result<(), ex::ExecError> {
        ex::Kernel::run(self, batch, uniforms, textures)
    }
    fn depth_only(&self) -> Option<Box<dyn ShaderStage>> {
        ex::Kernel::depth_only(self).map(|k| Box::new(k) as Box<dyn ShaderStage>)
    }
    fn does_nothing(&self) -> bool {
        self.op_count() == 0
    }
    fn depth_range(&self, uniforms: &[u32]) -> Option<ex::DepthRange> {
        ex::Kernel::depth_range(self, uniforms)
    }
    fn always_completes(&self) -> bool {
        ex::Kernel::always_completes(self)
    }
    fn reads_input(&self, c: usize) -> bool {
        ex::Kernel::reads_input(self, c)
    }
    fn lanes_independent(&self) -> bool {
        ex::Kernel::lanes_independent(self)
    }
    fn prepare<'t>(
        &self,
        uniforms: &[u32],
        textures: &'t dyn ex::Textures,
    ) -> Option<ex::Prepared<'t>> {
        Some(ex::Kernel::prepare(self, uniforms, textures))
    }
    fn run_prepared(
        &self,
        batch: &mut ex::Batch,
        prepared: &ex::Prepared<'_>,
        _uniforms: &[u32],
        textures: &dyn ex::Textures,
    ) -> Result<(), ex::ExecError> {
        ex::Kernel::run_prepared(self, batch, prepared, textures)
    }

    fn run_probed(
        &self,
        batch: &mut ex::Batch,
        uniforms: &[u32],
        textures: &dyn ex::Textures,
        lane: usize,
        trace: &mut dyn ex::Trace,
    ) -> Result<(), ex::ExecError> {
        ex::Kernel::run_traced(self, batch, uniforms, textures, lane, trace)
    }
    fn run_printing(
        &self,
        batch: &mut ex::Batch,
        uniforms: &[u32],
        textures: &dyn ex::Textures,
        sink: &mut dyn ex::PrintSink,
    ) -> Result<(), ex::ExecError> {
        ex::Kernel::run_printing(self, batch, uniforms, textures, sink)
    }
    fn run_watching(
        &self,
        batch: &mut ex::Batch,
        uniforms: &[u32],
        textures: &dyn ex::Textures,
        first: u32,
        out: &mut [[u32; ex::LANES]],
    ) -> Result<(), ex::ExecError> {
        ex::Kernel::run_watching(self, batch, uniforms, textures, first, out)
    }
}

/// Draws `indices` (vertex numbers passed to `fetch`) as `mode` primitives
/// into `fb` on the calling thread. See the crate documentation for the
/// pipeline; [`draw_on`] runs it on several threads with the same result.
#[allow(clippy::too_many_arguments)]
pub fn draw(
    fb: &mut Framebuffer,
    state: &PipelineState,
    vs: &ex::Kernel,
    vs_uniforms: &[u32],
    fs: &ex::Kernel,
    fs_uniforms: &[u32],
    mode: Mode,
    indices: &[u32],
    fetch: &dyn VertexFetch,
    textures: &(dyn ex::Textures + Sync),
) -> Result<(), DrawError> {
    draw_on(
        &Workers::inline(),
        fb,
        state,
        vs,
        vs_uniforms,
        fs,
        fs_uniforms,
        mode,
        indices,
        fetch,
        textures,
    )
}

/// [`draw()`] on `workers`' threads. The framebuffer (and the error, if any)
/// is bit-identical whatever the number of threads.
#[allow(clippy::too_many_arguments)]
pub fn draw_on(
    workers: &Workers,
    fb: &mut Framebuffer,
    state: &PipelineState,
    vs: &ex::Kernel,
    vs_uniforms: &[u32],
    fs: &dyn ShaderStage,
    fs_uniforms: &[u32],
    mode: Mode,
    indices: &[u32],
    fetch: &dyn VertexFetch,
    textures: &(dyn ex::Textures + Sync),
) -> Result<(), DrawError> {
    draw_stages(
        workers,
        fb,
        state,
        (vs, vs_uniforms),
        None,
        (fs, fs_uniforms),
        mode,
        indices,
        fetch,
        textures,
    )
}
