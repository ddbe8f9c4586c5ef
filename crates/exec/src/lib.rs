//! # shaderbox-exec: running GLSL programs on the CPU
//!
//! [`Kernel::new`] lowers one linked stage ([`glsl::link::LinkedStage`]) to
//! a flat register program; [`Kernel::run`] executes it on up to [`LANES`]
//! invocations at once (16 vertices, or 4 quads of 2×2 fragments) held in
//! a structure-of-arrays [`Batch`].
//!
//! ## Contract
//! - **Semantics** are those of the IR (`glsl::ir`) and of constant folding
//!   (`glsl::consteval`, `glsl::builtins::eval_builtin`): IEEE-754 `f32`
//!   arithmetic without contraction, int and uint arithmetic wrapping at
//!   32 bits, float→int and float→uint conversion truncating toward zero
//!   and saturating (NaN → 0; negative → 0 for uint), int↔uint keeping
//!   the bits, uint→float rounding to nearest,
//!   the sums of products in the orders Mesa's compiler gives them (a
//!   `dot` from its last component down, `matrix · x` as its scaled
//!   columns in index order, `x · matrix` as a `dot` with each column;
//!   `normalize(x)` is `x · inversesqrt(dot(x, x))`), so that a program
//!   grazing a silhouette draws what it draws on Mesa, built-in functions
//!   through `glsl::math`, so a shader computes the very bits constant
//!   folding would.
//! - **Defined results where GLSL leaves them undefined** (documented
//!   choices): integer division and remainder (`%`) by zero give 0, and
//!   `i32::MIN % -1` gives 0; shift amounts are taken modulo 32 (their low
//!   five bits, so negative amounts too); a dynamic index out of
//!   range is clamped to the nearest element (negative → element 0, too
//!   large → the last element), for reads and writes; uninitialized
//!   variables hold unspecified but deterministic values (0 at the start of
//!   a run); subnormal floats are zero of their sign
//!   (`glsl::math::flush_denormal`): every result of float arithmetic, of a
//!   built-in (and the intermediates of `mix`, `smoothstep` and `mod`) and
//!   of a derivative is flushed, as folding does, and so is every float
//!   entering a run: literals, inputs, uniforms and texture results. Values
//!   are then those of IEEE arithmetic with subnormal operands read as zero,
//!   which is how native code computes them on x86-64 (MXCSR.DAZ, no per-op
//!   flush); `min`/`max` with one NaN
//!   operand give the other operand; a NaN written to a float output is
//!   the canonical quiet NaN `0x7fc00000` (inside a run a NaN's payload
//!   depends on operand order, which compiled code may swap; GLSL 1.20
//!   observes payloads only through outputs).
//! - An `if` whose condition is a constant `bool` is lowered to the taken
//!   branch only (the other may call a function that has no body, which
//!   the linker accepts there); a call of a body-less function anywhere
//!   else is [`ExecError::Unsupported`].
//! - Limitation: built-ins the lowering expands into several ops (`dot`,
//!   `length`, `normalize`, ...) flush each intermediate result, folding
//!   flushes only the final one: they can differ when an intermediate is
//!   subnormal.
//! - **Control flow** runs under per-lane execution masks: `if`/`else`,
//!   loops with `break`/`continue` per lane (a loop ends when no lane is
//!   left in it), early `return` (per inlined function), `discard` (sets
//!   [`Batch::discarded`] and stops the lane for the rest of `main`).
//!   `&&`, `||` and `?:` evaluate their later operands only on the lanes
//!   that need them when those operands have side effects.
//! - **User functions are inlined** (GLSL forbids recursion); `in`
//!   arguments are copied in, `out`/`inout` l-values are evaluated at the
//!   call and written back when the callee returns, left to right
//!   (GLSL 1.20 §6.1.1). When inlining would exceed
//!   [`limits::INLINE_LIMIT`] expression nodes (call trees that double at
//!   every level), every function is lowered once as a subroutine with
//!   static registers instead (same results).
//! - **Interface**: inputs are the attributes (vertex) or varyings
//!   (fragment, including `gl_FragCoord`, `gl_FrontFacing`,
//!   `gl_PointCoord`, `gl_ClipDistance`) the shader reads; outputs are
//!   `gl_Position`, `gl_PointSize`, `gl_ClipVertex`, `gl_ClipDistance`
//!   and every varying (vertex) or
//!   `gl_FragColor`, `gl_FragData`, `gl_FragDepth` (fragment); the
//!   instance of a named input or output block is one slot per member
//!   (per element), named `Block.member` (`Block[i].member`) after the
//!   block, with the member's interpolation qualifier; a member of a
//!   block without an instance name is a slot of its own name that
//!   records its block ([`Slot::block`]), and both kinds match between
//!   stages as `Block.member` ([`Slot::link_name`]). Built-ins
//!   the shader never names do not exist in the module and are absent;
//!   [`Slot::written`] tells whether an output is statically written.
//!   Uniforms: every uniform the shader reads, in declaration order (plus
//!   `gl_ModelViewProjectionMatrix` and the attribute `gl_Vertex` when only
//!   `ftransform()` uses them). Uniform initializers are the caller's to
//!   put into the words. Unsized arrays: globals were sized by the linker;
//!   unsized local arrays take their largest constant index plus one.
//! - **Never hangs, never panics**: loops count iterations against
//!   [`LOOP_BUDGET`] per `run` ([`ExecError::LoopBudget`]); programs larger
//!   than the limits of [`limits`] are refused by [`Kernel::new`]
//!   ([`ExecError::Unsupported`]); missing uniform words read as 0 and
//!   missing input components as 0.0.
//! - **Deterministic**: a lane's results depend only on its own inputs and
//!   (for `dFdx`/`dFdy`/`fwidth` and implicit texture LOD) on the other
//!   lanes of its 2×2 quad, never on [`LANES`] or on which other lanes are
//!   active.
//!
//! - [`lane`]: the engine's float operations on one lane (flushes,
//!   `clamp`, `mix`, float outputs, implicit-LOD derivatives), which the
//!   engine itself runs, for stages computed outside it that must give
//!   its bits.
//! - **Memory** ([`Memory`], `memory`): storage blocks and a compute
//!   shader's `shared` variables are read and written by byte, in std140
//!   or std430 layout, through the run's [`Textures::memory`], the lanes
//!   of a batch one after the other in lane order (helper lanes write
//!   nothing); a program's spaces are [`Interface::buffers`] and
//!   [`SHARED_SPACE`]. Kernels that touch memory run on the interpreter.
//!   [`run_work_group`] (`compute`) runs a compute kernel's work group:
//!   its IDs, a fresh shared region, and `barrier()` across the batches
//!   of a group by taking turns, so results are the same everywhere.
//!
//! ## Lanes
//! Fragment lanes: lane `4q+0` = (x, y), `4q+1` = (x+1, y), `4q+2` =
//! (x, y+1), `4q+3` = (x+1, y+1). `dFdx = v(lane|1) - v(lane&!1)` (the same
//! for both pixels of a row of the quad), `dFdy = v(lane|2) - v(lane&!2)`.
//! Derivatives inside non-uniform control flow use whatever the inactive
//! lanes of the quad computed (GLSL 1.20 §8.8 leaves them undefined there).
//! [`Batch::helper`] lanes run with the active ones (so derivatives see
//! them) but their outputs are not written (they may appear in
//! [`Batch::discarded`]). Texture lookups are requested for the lanes
//! executing the call, helper lanes included.
//!
//! ## Layout
//! Values are flattened as `glsl::ir::ConstValue` is (vectors in order,
//! matrices column-major, arrays element by element, structs member by
//! member); a sampler takes one component (its texture unit). An array
//! of arrays (GL_ARB_arrays_of_arrays, GL_EXT_geometry_shader4's
//! two-dimensional inputs) reaches the executor as an array of
//! one-member row structs (`glsl::types::StructDef::array_row`), so it is
//! flattened row after row, the inner dimension fastest, exactly as the
//! C-style array it stands for: indexing a level is indexing an array,
//! and no op knows arrays of arrays. Uniform
//! words are `u32` bit patterns: `f32::to_bits` for floats, `i32 as u32`
//! for ints, the value for uints, 0/1 for bools, the unit number for
//! samplers. Inputs and outputs are `f32` (bool `gl_FrontFacing` is
//! 1.0/0.0); int and uint inputs and outputs convert to and from `f32` by
//! value, so integers beyond 2^24 in magnitude lose their low bits on the
//! way between stages (see Limitations).
//!
//! ## Debugging hooks
//! [`Kernel::run_traced`] reports, for one lane, every statement start
//! (source span) and every store (register, bits); [`Kernel::variables`]
//! names the registers of globals and (inlined) locals.
//!
//! ## Execution
//! [`Kernel::new`] also rewrites the program for the executor (`opt`):
//! constants, uniform words and what is computed from them alone move to a
//! prologue run once per `run` (or once per draw: [`Kernel::prepare`] and
//! [`Kernel::run_prepared`]); dead ops go; `t = op(..); var = t` becomes one
//! op writing `var` under the mask; the register file is reused per thread
//! and only registers read before written are zeroed. `min`, `max`,
//! `clamp`, `mix`, `step`, `smoothstep`, `abs`, `sign`, `floor`, `ceil`,
//! `fract`, `mod`, `sqrt`, `inversesqrt` run inline over the 16 lanes (the
//! same bits as `glsl::math`, tested on over a million inputs each); the
//! transcendental functions call `glsl::math` per lane. The executor is
//! compiled once per CPU level ([`cpu::Level`]: baseline, AVX2, AVX-512,
//! by [`multiversion!`], the one dispatch every crate's SIMD variants
//! use), chosen at run time
//! ([`Variant`], [`kernel_variant`], [`set_kernel_variant`]; environment
//! variable `SHADERBOX_KERNEL=jit|portable|avx2|avx512`); every variant
//! computes the same bits (tested).
//!
//! [`lanes16`] (x86-64) is the 16 lanes in AVX2 or AVX-512 registers
//! behind one trait, for code outside the engine written once for both
//! (raster's texture filter and strip write, gl's fixed-function stage).
//!
//! ## Native code
//! The default variant, `jit` (cargo feature `jit`, on by default), turns a
//! kernel's rewritten program into one machine function with Cranelift
//! (chosen because it is maintained, pure Rust, compiles in milliseconds,
//! targets x86-64 and aarch64, and never fuses a multiply and an add).
//! The function works on the same register file as the interpreter, four
//! 4-lane vectors per register; runs of lane-wise ops are emitted one
//! 4-lane quarter at a time with their values in machine registers, and
//! only the registers read later are stored; masks, mask slots and the
//! loop count are SSA values. It emits the same IEEE
//! operations in the same order as the interpreter, with subnormals read
//! as zero in hardware on x86-64 (MXCSR.DAZ, set around each run of code
//! that would flush in many places: see `float_env`) and flushed after
//! each op elsewhere, and calls back into the interpreter's own lane
//! code for the transcendental functions, integer division and remainder,
//! noise and
//! texture lookups, so it computes the same bits (tests compare it with
//! the interpreter on random programs of every op, on every unit-test
//! shader, and on piglit's execution and built-in function shaders).
//! A kernel's native code is started on its 1,024th run on a thread of
//! its own while the runs go on interpreted, and used once ready, so
//! compiling and linking a program costs no code generation, kernels of
//! tiny draws never pay for it and no draw waits for it;
//! `SHADERBOX_JIT_AFTER=n` or [`set_native_after`] make it compile on its
//! n-th run, on that run's thread (the later runs native whatever the
//! timing); [`Kernel::compile_native`] compiles at once.
//! Limitations: kernels with subroutine calls (inlining limit exceeded)
//! or over 6000 executor ops stay on the interpreter, as does everything
//! when Cranelift does not support the CPU or fails (the reason:
//! [`Kernel::native_code`]; `SHADERBOX_JIT_LOG=1` prints it, and each
//! compilation's size and time); hooked runs
//! (`run_traced`, `run_printing`, `run_watching`) always use the
//! reference interpreter. `SHADERBOX_JIT_DUMP=dir` writes each function's
//! machine code to `dir/jit-ADDRESS.bin` for profiling.
//! [`Kernel::run_traced`] runs the unrewritten program with the reference
//! interpreter (`interp`, which tests compare the executor against), so
//! tracing costs nothing when off.
//!
//! [`Kernel::depth_only`] slices a fragment kernel down to `gl_FragDepth`
//! and `discard`, for renderers that depth-test before shading colour.
//!
//! ## Limitations
//! - Derivatives are coarse per row/column of a quad.
//! - The interpreter variants: one dispatch per op per 16-lane batch (an
//!   enum of 44 bytes). In every variant `pow`, `exp`, `exp2`, `log` and
//!   `log2` are vectorized over the lanes (`glsl::math`'s branch-free
//!   versions); `sin`, `cos`, `tan`, `asin`, `acos`, `atan` are still scalar
//!   `libm` calls per lane. Subroutine calls count against
//!   [`LOOP_BUDGET`] like loop iterations.
//! - Integer inputs and outputs travel as `f32` values (the interface's
//!   type): an int or uint varying or attribute beyond 2^24 in magnitude
//!   is rounded. Uniforms are exact.
//! - `switch` computes each lane's starting case with one compare and
//!   select per label: no jump table.
//! - Programs beyond [`limits::MAX_REGISTERS`] registers or
//!   [`limits::MAX_OPS`] instructions are refused.
//!
//! ## Modules, in the order a kernel goes through them
//! - `lower` ([`Kernel::new`] → `lower::lower`): IR to a register program
//!   (`program`: the ops), the interface (`interface`); its submodules
//!   hold unrolling, calls, places, expressions, built-ins, textures.
//! - `opt` (`opt::optimize`): the program rewritten for the executors
//!   (hoisting, dead code, store fusion; `opt::mask_flow`), using
//!   `liveness`.
//! - `dispatch` (`dispatch::run`): which executor runs, per run, as
//!   `variant` selects.
//! - `engine` (`engine::run_in`): the interpreter over 16 lanes, built per
//!   CPU level (`cpu`: the levels, their detection and the
//!   `multiversion!`/`compiled_for!` macros; `lane` for its per-lane float
//!   operations).
//! - `jit` (`jit::run`, `jit::codegen::compile`): native code with
//!   Cranelift, sharing `engine`'s loading, output copy and callbacks, with
//!   `float_env` for the subnormal mode.
//! - `interp` (`interp::run`): the reference interpreter of the unrewritten
//!   program, for hooked runs and tests.
//! - `depth_slice` ([`Kernel::depth_only`]): a fragment kernel sliced to
//!   its depth and discards.
//! - `depth_range` ([`Kernel::depth_range`]): bounds on a fragment
//!   kernel's `gl_FragDepth` over a region of the window, by affine
//!   arithmetic on its rewritten program, for rejecting fragments before
//!   running it.

mod compute;
pub mod cpu;
mod depth_range;
mod depth_slice;
mod dispatch;
mod engine;
mod float_env;
mod interface;
mod interp;
#[cfg(feature = "jit")]
mod jit;
pub mod lane;
#[cfg(target_arch = "x86_64")]
pub mod lanes16;
mod liveness;
mod lower;
mod memory;
mod memory_ops;
mod opt;
pub mod print;
mod program;
mod variant;

pub use compute::{run_work_group, WorkGroup};
pub use depth_range::{Affine, DepthRange, RangeScratch};
pub use float_env::FloatEnv;
pub use interface::{kinds, size_of, Emitted, Interface, Slot, VertexInput};
pub use interp::LOOP_BUDGET;
pub use memory::{buffer_space, AtomicOp, Memory, Words, SHARED_SPACE};
pub use program::{StatementMark, VarInfo};
pub use variant::{
    current as kernel_variant, set_variant as set_kernel_variant, supported_variants, Variant,
};

/// Fragment kernels without `gl_FragDepth` get a [`Kernel::depth_only`]
/// slice (their discards) from this many executor ops on: below, a
/// renderer's extra depth pass costs more than the shading it saves.
/// The threshold is where the two cross on overlapping sheets
/// (`bench/scene.py`): a fixed-function stage with smooth colour and fog
/// gains from the deferred pass, flat colour alone does not.
pub const DEFER_MIN_OPS: usize = 20;

/// Makes kernels of the `jit` variant compile to native code on their
/// `runs`-th run (at least 1), on the thread of that run, instead of from
/// the default 1,024th on a thread of their own (see the crate docs): the
/// runs after it are native whatever the timing.
/// Affects every kernel of the process; no effect on results (native code
/// computes the interpreter's bits) or in a build without the `jit`
/// feature. For tests that want native code in short draws.
pub fn set_native_after(runs: u32) {
    #[cfg(feature = "jit")]
    jit::set_compile_after(runs);
    #[cfg(not(feature = "jit"))]
    let _ = runs;
}

use glsl::types::SamplerKind;
use glsl::Span;

/// Lanes per batch: 4 quads of 2×2 fragments, or 16 vertices.
pub const LANES: usize = 16;

/// Bit `i` = lane `i`.
pub type LaneMask = u32;

/// Size limits of lowered programs.
pub mod limits {
    pub use crate::lower::{INLINE_LIMIT, MAX_CALL_DEPTH, MAX_EMITTED_COMPONENTS};
    pub use crate::program::{MAX_OPS, MAX_REGISTERS};
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExecError {
    #[error("shader exceeded {iterations} loop iterations in one invocation")]
    LoopBudget { iterations: u64 },
    #[error("the executor cannot run this program: {0}")]
    Unsupported(String),
}

/// Structure-of-arrays invocation data.
#[derive(Clone, Debug, Default)]
pub struct Batch {
    /// One entry per input component (see [`Interface::inputs`]). The
    /// components of `int`/`uint` inputs (a vertex shader's attributes,
    /// `gl_VertexID`, `gl_InstanceID`; other stages' flat varyings) are
    /// the integers' bits (`f32::from_bits`), so that every 32-bit value
    /// arrives exactly.
    pub inputs: Vec<[f32; LANES]>,
    /// One entry per output component (see [`Interface::outputs`]); grown
    /// to the interface's size by `run` if shorter. Only the active lanes
    /// that did not discard are written. The `int`/`uint` outputs of a
    /// vertex or geometry shader (varyings) are the integers' bits, as
    /// the next stage's inputs take them; a fragment shader's are the
    /// values as floats (`bool`s are 0.0 or 1.0 in every stage).
    pub outputs: Vec<[f32; LANES]>,
    /// Lanes to run.
    pub active: LaneMask,
    /// Out: lanes that executed `discard`.
    pub discarded: LaneMask,
    /// Fragment: lanes that only exist to complete a quad (run for
    /// derivatives, outputs not written).
    pub helper: LaneMask,
}

impl Batch {
    /// A batch sized for `k`'s interface with the given lanes active.
    pub fn for_kernel(k: &Kernel, active: LaneMask) -> Batch {
        Batch {
            inputs: vec![[0.0; LANES]; k.interface.input_components],
            outputs: vec![[0.0; LANES]; k.interface.output_components],
            active,
            discarded: 0,
            helper: 0,
        }
    }

    /// Before a run stores `k`'s outputs: makes room for all of them and
    /// gives the lanes stored, the active ones not discarded (whose
    /// registers may hold anything, `mask_flow`).
    #[inline]
    pub(crate) fn output_lanes(&mut self, k: &Kernel) -> LaneMask {
        if self.outputs.len() < k.interface.output_components {
            self.outputs
                .resize(k.interface.output_components, [0.0; LANES]);
        }
        self.active & lane::FULL & !self.discarded
    }
}

/// A texture lookup for the lanes of `mask`.
#[derive(Clone, Debug, PartialEq)]
pub struct SampleRequest {
    /// Texture unit per lane (the sampler's value).
    pub unit: [u32; LANES],
    pub target: SamplerKind,
    /// s, t, r, q after the projective divide (unused coordinates are 0,
    /// q is 1).
    pub coord: [[f32; LANES]; 4],
    /// Shadow samplers: the depth reference (r, divided by q in the Proj
    /// forms).
    pub compare: Option<[f32; LANES]>,
    pub lod: Lod,
    /// The texel offsets of the `*Offset` lookups (u, v, w per lane),
    /// added to the scaled coordinates before wrapping (GLSL 1.30 §8.7,
    /// GL 3.0 §3.8.8); `None` for the others.
    pub offset: Option<[[i32; LANES]; 3]>,
    /// The lookups of GLSL 1.30 and later on shadow samplers, which
    /// return the comparison result as one `float` (§8.7): component 0
    /// of `out` is that result whatever the texture's depth texture mode.
    pub compare_only: bool,
    pub mask: LaneMask,
}

/// A `texelFetch`/`texelFetchOffset` for the lanes of `mask`: the texel
/// at integer coordinates of one level, no filtering, wrapping or
/// comparison (GL 3.0 §3.8.8's texel fetch).
#[derive(Clone, Debug, PartialEq)]
pub struct FetchRequest {
    pub unit: [u32; LANES],
    pub target: SamplerKind,
    /// i, j, k per lane (the array layer in the coordinate after the
    /// target's own; unused coordinates 0), offsets already added.
    pub coord: [[i32; LANES]; 3],
    /// The level, relative to the base level (0 for targets without
    /// levels).
    pub lod: [i32; LANES],
    pub mask: LaneMask,
}

/// One level of a texture whose texel fetches are plain loads
/// ([`Textures::texel_level`]).
#[derive(Clone, Copy, Debug)]
pub struct TexelLevel<'a> {
    /// Width, height and depth (or layers) of the level; 1 on the axes
    /// past [`TexelLevel::axes`].
    pub size: [u32; 3],
    /// How many coordinates a fetch reads (the target's dimensions, then
    /// its layer); the others count as 0.
    pub axes: u32,
    /// Texel `(i, j, k)` at `(k·height + j)·width + i`.
    pub texels: TexelSlice<'a>,
}

/// The texels of a [`TexelLevel`], as stored.
#[derive(Clone, Copy, Debug)]
pub enum TexelSlice<'a> {
    /// RGBA floats (an integer texture's integers as their bits,
    /// `f32::from_bits`).
    Rgba32(&'a [[f32; 4]]),
    /// RGBA unsigned normalized bytes: component `b` is `b as f32 / 255.0`.
    Unorm8(&'a [[u8; 4]]),
    /// Red as 16 bits, zero-extended (sign-extended when `signed`) to
    /// the red component's 32 bits; green, blue and alpha the bits
    /// `rest` in every texel.
    Red16 {
        red: &'a [u16],
        signed: bool,
        rest: [u32; 3],
    },
}

impl TexelSlice<'_> {
    pub fn len(&self) -> usize {
        match self {
            TexelSlice::Rgba32(t) => t.len(),
            TexelSlice::Unorm8(t) => t.len(),
            TexelSlice::Red16 { red, .. } => red.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

// The variants are plain per-lane arrays by design (docs/ARCHITECTURE.md,
// cross-crate rules): boxing would cost an allocation per lookup.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq)]
pub enum Lod {
    /// Fragment-shader implicit LOD: per-lane derivatives of the (divided)
    /// coordinates along x and y (from the quad; unused coordinates 0),
    /// plus a bias (0 when the call has none). A sampler may take one
    /// λ_base per 2×2 quad (raster's: from each quad's first lane, the
    /// bias still per lane).
    Derivatives {
        ddx: [[f32; LANES]; 3],
        ddy: [[f32; LANES]; 3],
        bias: [f32; LANES],
    },
    /// `*Lod` lookups, and vertex-shader lookups (level 0 plus the bias
    /// argument if any).
    Explicit([f32; LANES]),
    /// `textureGrad`: each lane's own derivatives of the (divided)
    /// coordinates along x and y (not one λ per quad: they are the
    /// shader's values, not differences between the quad's lanes).
    Gradients {
        ddx: [[f32; LANES]; 3],
        ddy: [[f32; LANES]; 3],
    },
}

pub trait Textures {
    /// Samples for the lanes in `req.mask`, writing RGBA into `out`
    /// (component-major: `out[c][lane]`). The lookups of integer
    /// samplers (`isampler*`, `usampler*`) give the integers' bits
    /// (`f32::from_bits`), which the executors store unflushed.
    fn sample(&self, req: &SampleRequest, out: &mut [[f32; LANES]; 4]);

    /// [`Textures::sample`] of a `sampler2D` lookup of unit `unit` on the
    /// lanes `mask` at `(s, t)` (after any projective divide) with the
    /// implicit LOD: derivatives the quad differences of s and t
    /// ([`lane::quad_diffs`]), no bias. The same results as the request;
    /// an implementation may sample without building it. Returns true
    /// when no value written is subnormal (the caller need not flush
    /// them); false promises nothing.
    fn sample_2d_implicit(
        &self,
        unit: u32,
        st: [&[f32; LANES]; 2],
        mask: LaneMask,
        out: &mut [[f32; LANES]; 4],
    ) -> bool {
        self.sample(&implicit_2d_request(unit, st, mask), out);
        false
    }

    /// Texel fetches for the lanes in `req.mask` (`out` as in
    /// [`Textures::sample`]). Integer textures give the integers' bits
    /// (`f32::from_bits`), as [`Textures::sample`] does for them. A
    /// texel outside the level (undefined in GL 3.0 §3.8.8), or a missing
    /// or incomplete texture, gives (0, 0, 0, 1).
    fn fetch(&self, req: &FetchRequest, out: &mut [[f32; LANES]; 4]) {
        for (c, value) in out.iter_mut().zip([0.0, 0.0, 0.0, 1.0]) {
            for (l, x) in c.iter_mut().enumerate() {
                if req.mask & (1 << l) != 0 {
                    *x = value;
                }
            }
        }
    }

    /// Level `lod` (relative to the base level) of the texture of
    /// `target` on `unit`, when [`Textures::fetch`] there gives each
    /// texel as stored (inside the level; (0, 0, 0, 1) outside, with the
    /// coordinates past [`TexelLevel::axes`] taken as 0) with nothing
    /// applied after the load: no sRGB decoding, depth texture mode or
    /// swizzle. Executors may then read the texels themselves, the same
    /// values as [`Textures::fetch`]. `None` (the default): ask `fetch`.
    fn texel_level(&self, unit: u32, target: SamplerKind, lod: i32) -> Option<TexelLevel<'_>> {
        let _ = (unit, target, lod);
        None
    }

    /// `textureSize`: the width, height and depth (or layer count) of
    /// level `lod` (relative to the base level) of the texture of
    /// `target` bound to `unit`, the sizes the target does not have 0;
    /// (0, 0, 0) with no such texture or level.
    fn size(&self, unit: u32, target: SamplerKind, lod: i32) -> [i32; 3] {
        let _ = (unit, target, lod);
        [0; 3]
    }

    /// The memory of the run ([`Memory`]: storage buffers, a work
    /// group's shared variables); without one, loads give 0 and stores
    /// and atomics do nothing.
    fn memory(&self) -> Option<&dyn Memory> {
        None
    }
}

/// The request [`Textures::sample_2d_implicit`] describes.
pub fn implicit_2d_request(unit: u32, st: [&[f32; LANES]; 2], mask: LaneMask) -> SampleRequest {
    let mut req = SampleRequest {
        unit: [unit; LANES],
        target: SamplerKind::Sampler2D,
        coord: [*st[0], *st[1], [0.0; LANES], [1.0; LANES]],
        compare: None,
        lod: Lod::Derivatives {
            ddx: [[0.0; LANES]; 3],
            ddy: [[0.0; LANES]; 3],
            bias: [0.0; LANES],
        },
        offset: None,
        compare_only: false,
        mask,
    };
    if let Lod::Derivatives { ddx, ddy, .. } = &mut req.lod {
        for k in 0..2 {
            (ddx[k], ddy[k]) = lane::quad_diffs(&req.coord[k]);
        }
    }
    req
}

/// A [`Textures`] with no texture bound: every lookup gives (0, 0, 0, 1).
pub struct NoTextures;

impl Textures for NoTextures {
    fn sample(&self, req: &SampleRequest, out: &mut [[f32; LANES]; 4]) {
        for (c, value) in out.iter_mut().zip([0.0, 0.0, 0.0, 1.0]) {
            for (l, x) in c.iter_mut().enumerate() {
                if req.mask & (1 << l) != 0 {
                    *x = value;
                }
            }
        }
    }
}

/// Receives a single lane's execution from [`Kernel::run_traced`].
pub trait Trace {
    /// A statement (or a global initializer) starts on the traced lane.
    fn statement(&mut self, span: Span);
    /// The traced lane stores `bits` into `register` (see
    /// [`Kernel::variables`] to name registers).
    fn store(&mut self, register: u32, bits: u32);
    /// The traced lane runs `debugPrintfEXT`, printing `text`.
    fn printf(&mut self, _text: &str) {}
}

/// Receives what `debugPrintfEXT` prints ([`Kernel::run_printing`]).
pub trait PrintSink {
    /// `lane` printed `text` at the call at `span`.
    fn print(&mut self, lane: usize, span: Span, text: &str);
}

/// A lowered stage, ready to run.
#[derive(Clone, Debug)]
pub struct Kernel {
    stage: glsl::Stage,
    program: program::Program,
    interface: Interface,
    inputs: Vec<(usize, u32, glsl::types::Scalar)>,
    outputs: Vec<(u32, usize, glsl::types::Scalar)>,
    loop_budget: u64,
    /// Whether the program writes memory, and calls `barrier()` (found
    /// once: draws and dispatches ask every time).
    writes_memory: bool,
    calls_barrier: bool,
    /// Per input component: whether an op reads it ([`Kernel::reads_input`],
    /// found once: each draw asks).
    read_inputs: Vec<bool>,
    /// The program optimized for the executors ([`dispatch::run`]).
    code: std::sync::Arc<opt::Code>,
    /// [`Kernel::depth_only`], computed on first use (shared by clones).
    depth: std::sync::Arc<std::sync::OnceLock<Option<Kernel>>>,
    /// The analysis of [`Kernel::depth_range`], found on first use.
    range_plan: std::sync::Arc<std::sync::OnceLock<Option<std::sync::Arc<depth_range::Plan>>>>,
    /// Native code for `code`, made on demand (shared by clones).
    #[cfg(feature = "jit")]
    jit: std::sync::Arc<jit::Cache>,
}

/// Per input component of `inputs` (component, register, kind): whether
/// an op of `code` reads its register ([`Kernel::reads_input`]).
fn read_inputs(code: &opt::Code, inputs: &[(usize, u32, glsl::types::Scalar)]) -> Vec<bool> {
    let mut read = vec![false; code.prog.registers as usize];
    let ops = code.ins.iter().map(|i| &i.op).chain(&code.prologue);
    for op in ops {
        for &(u, n) in &liveness::effects(&code.prog, op).uses {
            let (u, n) = (u as usize, n.max(1) as usize);
            if let Some(r) = read.get_mut(u..(u + n).min(code.prog.registers as usize)) {
                r.fill(true);
            }
        }
    }
    let components = inputs.iter().map(|i| i.0 + 1).max().unwrap_or(0);
    let mut out = vec![false; components];
    for &(c, r, _) in inputs {
        if let (Some(o), Some(&true)) = (out.get_mut(c), read.get(r as usize)) {
            *o = true;
        }
    }
    out
}

/// A kernel's uniform-only values, computed once for a set of uniform
/// words and textures ([`Kernel::prepare`]) and reused by
/// [`Kernel::run_prepared`]; it borrows the textures (`'t`), whose levels
/// native code may read through it.
#[derive(Clone)]
pub struct Prepared<'t> {
    pub(crate) code: std::sync::Arc<opt::Code>,
    pub(crate) pool: Vec<[u32; LANES]>,
    uniforms: Vec<u32>,
    /// The textures it was made with (compared with a run's: the views
    /// are theirs).
    textures: *const (dyn Textures + 't),
    /// Per texture op: the level a texel fetch of a uniform sampler and
    /// level reads, for native code (no texels: ask at each run).
    #[cfg(feature = "jit")]
    pub(crate) views: Vec<jit::View>,
}

impl std::fmt::Debug for Prepared<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Prepared")
            .field("pool", &self.pool.len())
            .field("uniforms", &self.uniforms.len())
            .finish()
    }
}

// SAFETY: the only non-Send/Sync parts are the textures' address (only
// compared, never dereferenced) and the views' pointers into the
// textures' levels, which stay valid and unchanged while `'t` borrows
// them (`Textures::texel_level`'s contract) and are only read.
unsafe impl Send for Prepared<'_> {}
// SAFETY: as above.
unsafe impl Sync for Prepared<'_> {}

impl Prepared<'_> {
    /// Whether `textures` is the object this was made with (then its
    /// views describe it): the same address and type.
    #[cfg(feature = "jit")]
    pub(crate) fn made_with(&self, textures: &dyn Textures) -> bool {
        std::ptr::eq(self.textures, textures)
    }
}

impl Kernel {
    /// Lowers a linked stage. Errors only for IR the executor cannot run
    /// (a front-end bug) or programs beyond [`limits`].
    pub fn new(stage: &glsl::link::LinkedStage) -> Result<Kernel, ExecError> {
        Kernel::with_inline_limit(stage, lower::INLINE_LIMIT)
    }

    /// Like [`Kernel::new`], inlining calls only while `main` stays under
    /// `limit` expression nodes (else every function becomes a subroutine).
    pub(crate) fn with_inline_limit(
        stage: &glsl::link::LinkedStage,
        limit: u64,
    ) -> Result<Kernel, ExecError> {
        let l = lower::lower(stage, limit)?;
        Ok(Kernel::assemble(stage.stage, l, LOOP_BUDGET))
    }

    fn assemble(stage: glsl::Stage, l: lower::Lowered, loop_budget: u64) -> Kernel {
        let lower::Lowered {
            program,
            interface,
            inputs,
            outputs,
        } = l;
        let live_out: Vec<u32> = outputs.iter().map(|&(r, _, _)| r).collect();
        let code = std::sync::Arc::new(opt::optimize(&program, &live_out));
        let (writes_memory, calls_barrier) = (code.prog.writes_memory(), code.prog.calls_barrier());
        let read_inputs = read_inputs(&code, &inputs);
        Kernel {
            stage,
            program,
            interface,
            inputs,
            outputs,
            loop_budget,
            writes_memory,
            calls_barrier,
            read_inputs,
            code,
            depth: Default::default(),
            range_plan: Default::default(),
            #[cfg(feature = "jit")]
            jit: Default::default(),
        }
    }

    /// Sets the loop iteration budget of each `run` (default
    /// [`LOOP_BUDGET`]).
    pub fn set_loop_budget(&mut self, iterations: u64) {
        self.loop_budget = iterations;
    }

    pub fn stage(&self) -> glsl::Stage {
        self.stage
    }

    /// Whether a run writes memory ([`Memory`]: storage blocks, shared
    /// variables), which makes the order of runs matter.
    pub fn writes_memory(&self) -> bool {
        self.writes_memory
    }

    /// Whether a compute kernel's work groups run on threads of their own
    /// ([`run_work_group`]: it calls `barrier()` and a group spans more
    /// than one batch), which costs a thread per batch and group.
    pub fn threads_per_group(&self) -> bool {
        let size = self.interface.local_size.unwrap_or([1, 1, 1]);
        let n: u64 = size.iter().map(|&s| u64::from(s)).product();
        n > LANES as u64 && self.calls_barrier
    }

    pub fn interface(&self) -> &Interface {
        &self.interface
    }

    /// Runs `main` on the active (and helper) lanes of `batch`.
    pub fn run(
        &self,
        batch: &mut Batch,
        uniforms: &[u32],
        textures: &dyn Textures,
    ) -> Result<(), ExecError> {
        dispatch::run(self, &self.code, batch, uniforms, textures, None)
    }

    /// The uniform-only values of this kernel for `uniforms` (constants,
    /// uniform words and what is computed from them alone, and the sizes
    /// of `textures` that `textureSize` asks of a uniform sampler), for
    /// [`Kernel::run_prepared`]: a renderer computes them once per draw,
    /// and runs them with the same textures.
    pub fn prepare<'t>(&self, uniforms: &[u32], textures: &'t dyn Textures) -> Prepared<'t> {
        let pool = engine::prepare(&self.code, uniforms, textures);
        Prepared {
            code: self.code.clone(),
            #[cfg(feature = "jit")]
            views: jit::prepared_views(&self.code, &pool, textures),
            pool,
            uniforms: uniforms.to_vec(),
            textures,
        }
    }

    /// [`Kernel::run`] with the uniforms of `prepared` (made by
    /// [`Kernel::prepare`] of this kernel or a clone of it; with another
    /// kernel's, the values are recomputed, at the cost of a run).
    pub fn run_prepared(
        &self,
        batch: &mut Batch,
        prepared: &Prepared<'_>,
        textures: &dyn Textures,
    ) -> Result<(), ExecError> {
        dispatch::run(
            self,
            &self.code,
            batch,
            &prepared.uniforms,
            textures,
            Some(prepared),
        )
    }

    /// [`Kernel::run`] with a given executor variant, for tests.
    #[cfg(test)]
    pub(crate) fn run_variant(
        &self,
        v: Variant,
        batch: &mut Batch,
        uniforms: &[u32],
        textures: &dyn Textures,
    ) -> Result<(), ExecError> {
        #[cfg(feature = "jit")]
        if v == Variant::Jit {
            // Compile now rather than after a few runs.
            self.jit.get(&self.code, true);
        }
        dispatch::run_on(v, self, &self.code, batch, uniforms, textures, None)
    }

    /// The reference interpreter (what `run_traced` uses), for tests.
    #[cfg(test)]
    pub(crate) fn run_reference(
        &self,
        batch: &mut Batch,
        uniforms: &[u32],
        textures: &dyn Textures,
    ) -> Result<(), ExecError> {
        interp::run(self, batch, uniforms, textures, &mut interp::NoHook)
    }

    /// Like [`Kernel::run`], reporting every statement and store that
    /// `lane` executes to `trace`.
    pub fn run_traced(
        &self,
        batch: &mut Batch,
        uniforms: &[u32],
        textures: &dyn Textures,
        lane: usize,
        trace: &mut dyn Trace,
    ) -> Result<(), ExecError> {
        let mut stmt_at = vec![u32::MAX; self.program.ops.len()];
        for (i, s) in self.program.statements.iter().enumerate() {
            if let Some(x) = stmt_at.get_mut(s.op as usize) {
                *x = i as u32;
            }
        }
        let mut hook = interp::TraceHook {
            lane: lane.min(LANES - 1),
            trace,
            stmt_at,
        };
        interp::run(self, batch, uniforms, textures, &mut hook)
    }

    /// A kernel computing only what decides a fragment's fate: the
    /// `gl_FragDepth` output and [`Batch::discarded`], for a renderer that
    /// runs it on every covered fragment, depth-tests, and runs the full
    /// kernel only on the survivors (with their quads' other lanes as
    /// helpers, for derivatives).
    ///
    /// Same interface as `self` (inputs, uniform words, output slots),
    /// except that inputs the slice never reads are marked unread
    /// ([`Slot::written`] false; the renderer may leave them unset); on
    /// the active lanes it writes the bits `self` writes to `gl_FragDepth`
    /// and discards the same lanes (and fails with the same
    /// [`ExecError::LoopBudget`]); it leaves every other output as it was
    /// in the batch. All control flow is kept but branches left with
    /// nothing to do; ops whose results only feed other outputs are
    /// dropped (a backward liveness analysis over the program, loops
    /// iterated to a fixpoint). GLSL 1.10/1.20 fragment shaders have no
    /// side effect besides their outputs, so running the slice first never
    /// changes what the full kernel computes.
    ///
    /// `None` for a vertex kernel, a fragment kernel that neither writes
    /// `gl_FragDepth` nor has [`DEFER_MIN_OPS`] executor ops (its slice
    /// decides only discards, often nothing), or when the slice would keep
    /// more than 80 % of the ops (not worth a second pass).
    ///
    /// The slice is computed once per kernel (and its clones) and cached.
    pub fn depth_only(&self) -> Option<Kernel> {
        let mut k = self.depth.get_or_init(|| self.slice_depth()).clone()?;
        k.loop_budget = self.loop_budget;
        Some(k)
    }

    fn slice_depth(&self) -> Option<Kernel> {
        if self.stage != glsl::Stage::Fragment {
            return None;
        }
        let outputs: Vec<_> = match self.interface.output("gl_FragDepth") {
            Some(slot) if slot.written => {
                let range = slot.offset..slot.offset + slot.components;
                self.outputs
                    .iter()
                    .copied()
                    .filter(|&(_, oc, _)| range.contains(&oc))
                    .collect()
            }
            // Without gl_FragDepth the slice only decides discards (often
            // nothing at all): worth a depth pass before colours only when
            // the colours cost enough to shade each pixel once.
            _ if self.code.ins.len() >= DEFER_MIN_OPS => Vec::new(),
            _ => return None,
        };
        let live_out: Vec<u32> = outputs.iter().map(|&(r, _, _)| r).collect();
        let program = depth_slice::slice(&self.program, &live_out)?;
        // The input components the slice reads: those loaded into a
        // register live at its entry. The others are neither loaded nor,
        // when a whole variable goes unread, marked read in the interface
        // (so a renderer need not interpolate them for this pass).
        let live = liveness::analyze(&program, &program.ops, program.registers, &live_out)?;
        let inputs: Vec<_> = self
            .inputs
            .iter()
            .copied()
            .filter(|&(_, r, _)| live.entry_live(r))
            .collect();
        let mut interface = self.interface.clone();
        for slot in &mut interface.inputs {
            let range = slot.offset..slot.offset + slot.components;
            slot.written &= inputs.iter().any(|&(ic, _, _)| range.contains(&ic));
        }
        let l = lower::Lowered {
            program,
            interface,
            inputs,
            outputs,
        };
        Some(Kernel::assemble(self.stage, l, self.loop_budget))
    }

    /// Like [`Kernel::run`], reporting what each active (non-helper) lane
    /// prints with `debugPrintfEXT` to `sink`, in execution order (call by
    /// call, lanes in increasing order). [`Kernel::run`] ignores the calls.
    pub fn run_printing(
        &self,
        batch: &mut Batch,
        uniforms: &[u32],
        textures: &dyn Textures,
        sink: &mut dyn PrintSink,
    ) -> Result<(), ExecError> {
        let mut hook = interp::PrintHook {
            lanes: batch.active & !batch.helper,
            sink,
        };
        interp::run(self, batch, uniforms, textures, &mut hook)
    }

    /// Like [`Kernel::run`], keeping in `out[i][lane]` the last value each
    /// lane stored into register `first + i` (initially `out`'s contents;
    /// see [`Kernel::variables`] for where variables live).
    pub fn run_watching(
        &self,
        batch: &mut Batch,
        uniforms: &[u32],
        textures: &dyn Textures,
        first: u32,
        out: &mut [[u32; LANES]],
    ) -> Result<(), ExecError> {
        let mut hook = interp::WatchHook { first, out };
        interp::run(self, batch, uniforms, textures, &mut hook)
    }

    /// The state of this kernel's native code (the `jit` variant):
    /// `None` before it was compiled (a kernel's compilation starts on its
    /// 1,024th run, see [`set_native_after`], or never with another
    /// variant), `Some(Ok(bytes))` once it runs
    /// as machine code of that size, `Some(Err(reason))` when it stays on
    /// the interpreter (subroutine calls, size, a CPU or code generator
    /// failure), or always `Some(Err(..))` in a build without the `jit`
    /// feature.
    pub fn native_code(&self) -> Option<Result<usize, String>> {
        #[cfg(feature = "jit")]
        return self.jit.status();
        #[cfg(not(feature = "jit"))]
        Some(Err("built without the `jit` feature".to_string()))
    }

    /// Compiles this kernel's native code now if the `jit` variant is
    /// selected and it was not yet (normally done on demand); see
    /// [`Kernel::native_code`].
    pub fn compile_native(&self) {
        #[cfg(feature = "jit")]
        if kernel_variant() == Variant::Jit {
            self.jit.get(&self.code, true);
        }
    }

    /// Whether the shader calls `debugPrintfEXT`.
    pub fn prints(&self) -> bool {
        !self.program.printfs.is_empty()
    }

    /// Where each source statement starts in the program.
    pub fn statements(&self) -> &[StatementMark] {
        &self.program.statements
    }

    /// The registers of the globals and of every (inlined) local.
    pub fn variables(&self) -> &[VarInfo] {
        &self.program.vars
    }

    /// Whether every lane's results depend only on that lane's inputs: a
    /// fragment kernel without derivatives (`dFdx`, `dFdy`, `fwidth`),
    /// texture lookups (a fragment lookup's LOD comes from its quad) or
    /// `debugPrintfEXT` calls (reported by lane), or any vertex kernel.
    /// A renderer may then run fragments of different quads side by side
    /// in one batch, without helper lanes: each lane's outputs and
    /// discard are those it gets in its own quad, bit for bit (the
    /// module's determinism rule).
    pub fn lanes_independent(&self) -> bool {
        use program::Op;
        // (Texture and print ops refer to these tables.)
        self.stage != glsl::Stage::Fragment
            || (self.program.textures.is_empty()
                && self.program.printfs.is_empty()
                && !self
                    .program
                    .ops
                    .iter()
                    .any(|op| matches!(op, Op::DdX { .. } | Op::DdY { .. })))
    }

    /// Whether a run reads input component `c` (an index into
    /// `Batch::inputs`): some op of the optimized program reads the
    /// register it is loaded into. The others need not be filled.
    pub fn reads_input(&self, c: usize) -> bool {
        self.read_inputs.get(c).copied().unwrap_or(false)
    }

    /// Whether every run returns `Ok`: the program has no loop, so no
    /// run can exceed the loop budget ([`ExecError::LoopBudget`], the
    /// only error a compiled kernel's run gives). A renderer may then
    /// write its results in place without keeping what it overwrites.
    pub fn always_completes(&self) -> bool {
        use program::Op;
        !self.program.ops.iter().any(|op| matches!(op, Op::LoopIter))
    }

    /// Number of instructions (a size measure).
    pub fn op_count(&self) -> usize {
        self.program.ops.len()
    }

    /// Registers per run.
    pub fn register_count(&self) -> usize {
        self.program.registers as usize
    }
}

#[cfg(test)]
mod tests;
