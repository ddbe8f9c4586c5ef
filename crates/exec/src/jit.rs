//! The native-code backend: a kernel's optimized program ([`Code`], `opt`: the
//! prologue and the executor's ops) compiled by Cranelift into one machine
//! function, run instead of the interpreter loop of `engine`.
//!
//! Why Cranelift: it is maintained (the Bytecode Alliance's code generator
//! of Wasmtime), pure Rust (no LLVM to install, builds with cargo alone),
//! generates x86-64 and aarch64 (and riscv64, s390x), compiles a function
//! in milliseconds, and never contracts `a * b + c` into a fused
//! multiply-add, so IEEE results are those of the interpreter.
//!
//! ## Shape of the generated code
//! The register file stays in memory (the thread's `dispatch` file, the same
//! layout: a register is 16 `u32` lanes, 64 bytes), each register handled
//! as four 4-lane vectors (quarters; Cranelift's x86-64 vectors are 128
//! bits). A run of lane-wise data ops inside a basic block (arithmetic,
//! comparisons, conversions, selects, the inline built-ins, uniform words,
//! derivatives: every op whose quarter `q` depends only on quarter `q` of
//! its operands) is emitted quarter by quarter: the whole run on lanes
//! 0-3, then on lanes 4-7, ..., so only a quarter of its values is live at
//! once. Inside a run the registers are SSA values: loaded at the first
//! read, and stored only by the run's last write to a register that is
//! read afterwards (per-op liveness, `crate::liveness`, with fused masked
//! stores as partial writes); temporaries never reach memory. Other ops
//! (calls, gathers, scatters) work on all four quarters, and everything is
//! in memory at block ends. The pool registers (`engine`'s per-draw
//! values) are read where a prepared pool is, not copied into the file,
//! unless an op run by a callback reads them. A fused masked store blends with the
//! current-mask vectors; a run with masked writes also has a copy without
//! the blends, taken when all 16 lanes run. Vector constants are loads from a per-kernel table
//! (`Native::consts`), which x86 folds into the instruction using them. The
//! current mask (a lane bit set plus its four expanded vectors), the mask
//! slots, the discarded lanes and the loop counter live in SSA variables;
//! the program's structured jumps become branches between blocks. The
//! function takes one pointer, to a [`Ctx`], and returns 0, or 1 when the
//! loop budget ran out.
//!
//! ## Same bits as the interpreter
//! Arithmetic, comparisons, conversions (float→int saturating as Rust `as`
//! does), integer division and remainder (through `f64`, as `lane::idiv`
//! and its kin; by a pool register, one value for the run, as a product
//! with its reciprocal computed once, then corrected to the same
//! quotient), selects, `min`/`max` with their NaN rule, `abs`, `sign`,
//! `floor`/`ceil`/`fract`/`mod`, `sqrt`, `inversesqrt`, `step`, `clamp`,
//! `mix`, `smoothstep` and dot products are emitted inline as the same IEEE
//! operations in the same order, each result flushed as `engine::ftz` does
//! or, on x86-64 with SSE4.1 ([`daz`]), left as the hardware gives it and
//! read as zero by the next op (MXCSR.DAZ, `crate::float_env`): the same
//! values without four instructions per op; code that would flush in few
//! places and calls no math helper keeps its flushes and runs without DAZ
//! (`Native::daz`), sparing a run the two MXCSR writes, which wait for
//! the operations in flight. Unflushed bits never leave the
//! code: float outputs are flushed by `engine::store_outputs`, the
//! operands of callbacks by the callbacks, which run in Rust's environment.
//! Everything else (the transcendental functions, uniform reads outside
//! the prologue, noise, texture lookups) calls back into Rust:
//! `jit_f1`/`jit_f2` run the engine's own lane functions (compiled for
//! AVX-512 or AVX2 when the CPU has them, where their lane loops vectorize
//! wider), `jit_texture` the engine's own `texture`, `jit_step` the
//! engine's own `step` on the op, so those compute the interpreter's bits
//! by construction. A texel fetch whose lanes read one level that
//! [`crate::Textures::texel_level`] gives as stored texels loads them
//! itself (bounds, index, load, as `Textures::fetch` defines them).
//!
//! ## When it is used
//! With the `jit` variant (the default where Cranelift supports the CPU), a
//! kernel's compilation starts on its [`COMPILE_AFTER_RUNS`]-th run, on a
//! thread of its own (the runs keep interpreting meanwhile), and the code
//! is cached for the kernel and its clones. Programs with subroutine calls, or over [`MAX_OPS`] ops,
//! stay on the interpreter, as does any kernel Cranelift fails on (the
//! reason is kept: [`crate::Kernel::native_code`]; `SHADERBOX_JIT_LOG=1`
//! prints it).

mod codegen;

use crate::engine::{self, Lanes};
use crate::float_env;
use crate::interp::FULL;
use crate::opt::{Code, Ins};
use crate::program::{TexKind, F1, F2};
use crate::{Batch, ExecError, Kernel, Textures};
use std::any::Any;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::{Arc, Mutex, OnceLock, TryLockError};

/// Programs with more executor ops than this stay on the interpreter
/// (compile time grows with the size; such programs are rare).
pub(crate) const MAX_OPS: usize = 6000;

/// A kernel's native code is started on its run number this, on a thread
/// of its own, while the runs go on in the interpreter; they switch to the
/// native code once it is there (compiling takes milliseconds to tenths of
/// a second). Kernels of tiny draws (under 1,024 batches: 16,384 lanes)
/// never pay for it; a draw that stops before the code is ready has lost
/// only the compiling thread's time.
pub(crate) const COMPILE_AFTER_RUNS: u32 = 1024;

/// The run count of [`compile_after`] when set by [`set_compile_after`]
/// (0: not set).
static COMPILE_AFTER_SET: AtomicU32 = AtomicU32::new(0);

/// Makes kernels compile on their `runs`-th run from now on (at least 1),
/// on the thread of that run (the later runs are native whatever the
/// timing), overriding [`COMPILE_AFTER_RUNS`] and `SHADERBOX_JIT_AFTER`;
/// for tests that want native code in short draws.
pub(crate) fn set_compile_after(runs: u32) {
    COMPILE_AFTER_SET.store(runs.max(1), Ordering::Relaxed);
}

/// The run count a kernel compiles at on the thread of that run: what
/// [`set_compile_after`] set, else `SHADERBOX_JIT_AFTER` (a run count, at
/// least 1; 1 = native code from the first run), else 0 (neither: the
/// default, [`COMPILE_AFTER_RUNS`] on a thread of its own). Compiling
/// where the count is reached makes the later runs native whatever the
/// timing: for tests, and for instruction counts under valgrind, whose
/// serialized threads would leave a compiling thread behind.
fn compile_after_set() -> u32 {
    let set = COMPILE_AFTER_SET.load(Ordering::Relaxed);
    if set != 0 {
        return set;
    }
    static ENV: OnceLock<u32> = OnceLock::new();
    *ENV.get_or_init(|| {
        std::env::var("SHADERBOX_JIT_AFTER")
            .ok()
            .and_then(|s| s.trim().parse::<u32>().ok())
            .map_or(0, |n| n.max(1))
    })
}

/// The run count a kernel's compilation starts at ([`compile_after_set`],
/// else [`COMPILE_AFTER_RUNS`]).
fn compile_after() -> u32 {
    match compile_after_set() {
        0 => COMPILE_AFTER_RUNS,
        n => n,
    }
}

/// What the generated function receives. `#[repr(C)]`: the native code
/// reads and writes the fields before `code` at their offsets.
#[repr(C)]
pub(crate) struct Ctx<'a> {
    /// The register file (`code.prog.registers` registers).
    regs: *mut Lanes,
    /// Loop budget of the run.
    budget: u64,
    /// Out: the iteration count when the budget ran out.
    iterations: u64,
    /// Lanes running at the start.
    start: u32,
    /// Out: lanes that executed `discard`.
    discarded: u32,
    /// Whether to run the prologue (no prepared pool).
    prologue: u32,
    /// Number of uniform words (at most `i32::MAX`).
    uniforms_len: u32,
    /// The uniform words; a static zero word when there are none, so the
    /// native code may always read word 0.
    uniforms_ptr: *const u32,
    /// The vector constants of the native code (`Native::consts`).
    consts: *const [u32; 4],
    /// The pool registers (`code.pool_base..`): the prepared pool, or the
    /// file's own when the prologue runs or a callback reads them there.
    pool: *const Lanes,
    /// Where `jit_f1`/`jit_f2` put their result.
    scratch: Lanes,
    /// Where `jit_texture` describes the level a texel fetch reads.
    view: View,
    /// Per texture op, the level a texel fetch reads for the whole draw
    /// ([`prepared_views`]; no texels: ask `jit_texture`), and their
    /// count.
    views: *const View,
    views_len: u32,
    code: &'a Code,
    uniforms: &'a [u32],
    textures: &'a dyn Textures,
    /// A panic caught in a helper, resumed after the native code returns.
    panic: Option<Box<dyn Any + Send>>,
    /// The code runs under DAZ (`Native::daz`): callbacks into Rust
    /// switch the environment.
    daz: bool,
}

type Entry = unsafe extern "C" fn(*mut Ctx) -> u32;

/// A compiled kernel: the code memory and its entry point.
pub(crate) struct Native {
    module: Option<cranelift_jit::JITModule>,
    entry: Entry,
    /// The vector constants the code loads (one entry per distinct
    /// constant; loads fold into the instructions using them, where a
    /// constant materialized once per function would be spilled).
    consts: Box<[Const16]>,
    /// Whether an op run by a callback (`jit_step`) reads pool registers
    /// from the file (then a prepared pool is copied there).
    pub(crate) pool_in_file: bool,
    /// Size of the machine code in bytes.
    pub bytes: usize,
    /// Compiled to run under DAZ ([`daz`]): when the code would flush
    /// in more than a few places otherwise (`codegen::compile`).
    daz: bool,
}

// SAFETY: after `finalize_definitions` the module's code memory is never
// written again; the entry point is a plain function whose only state is
// its `Ctx` argument, so it may run on several threads at once. The module
// itself is only touched again by `Drop`, which has exclusive access.
unsafe impl Send for Native {}
// SAFETY: as above; `&Native` only gives access to `entry` and `bytes`.
unsafe impl Sync for Native {}

impl Drop for Native {
    fn drop(&mut self) {
        if let Some(m) = self.module.take() {
            // SAFETY: the function pointer dies with `self`; no run can be
            // executing it (runs borrow the kernel that owns `self`).
            unsafe { m.free_memory() };
        }
    }
}

/// A texture level whose texels native code fetches itself
/// ([`crate::TexelLevel`] checked and flattened for it).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct View {
    /// The first texel.
    texels: *const u8,
    /// Width, height and depth; their product fits in an `i32` and the
    /// texels hold that many.
    size: [u32; 3],
    /// Per coordinate: all ones when the fetch reads it, else 0.
    keep: [u32; 3],
    /// [`View::RGBA32`], [`View::UNORM8`], [`View::RED16`] or
    /// [`View::RED16_SIGNED`].
    format: u32,
    /// The green, blue and alpha bits of every texel of a `RED16` view.
    rest: [u32; 3],
}

impl View {
    /// 16 bytes per texel: RGBA as `f32` bits.
    const RGBA32: u32 = 0;
    /// 4 bytes per texel: RGBA bytes, each `b / 255`.
    const UNORM8: u32 = 1;
    /// 2 bytes per texel: red's bits zero-extended, the rest `rest`
    /// (`TexelSlice::Red16`); only for integer results.
    const RED16: u32 = 2;
    /// As `RED16`, red sign-extended.
    const RED16_SIGNED: u32 = 3;
}

impl Default for View {
    fn default() -> View {
        View {
            texels: std::ptr::null(),
            size: [0; 3],
            keep: [0; 3],
            format: View::RGBA32,
            rest: [0; 3],
        }
    }
}

/// A 16-byte aligned vector constant.
#[repr(C, align(16))]
#[derive(Clone, Copy)]
pub(crate) struct Const16(pub [u32; 4]);

/// The compiled code of one kernel (shared by its clones), made on demand.
#[derive(Default)]
pub(crate) struct Cache {
    runs: AtomicU32,
    /// Whether a background compilation was started.
    started: std::sync::atomic::AtomicBool,
    /// Held while compiling.
    compiling: Mutex<()>,
    slot: OnceLock<Result<Native, String>>,
}

impl std::fmt::Debug for Cache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.slot.get() {
            None => write!(f, "Cache(not compiled)"),
            Some(Ok(n)) => write!(f, "Cache({} bytes)", n.bytes),
            Some(Err(e)) => write!(f, "Cache(interpreted: {e})"),
        }
    }
}

impl Cache {
    /// The native code of `code` (this cache's kernel's) if it is ready;
    /// on the [`compile_after`]-th call, starts compiling it on a thread
    /// of its own (or here, if no thread can be started).
    pub(crate) fn get_or_start(self: &Arc<Self>, code: &Arc<Code>) -> Option<&Native> {
        if let Some(r) = self.slot.get() {
            return r.as_ref().ok();
        }
        if compile_after_set() != 0 {
            // Compiled by the run that reaches the count, so the runs
            // after it are native whatever the timing.
            return self.get(code, false);
        }
        if self.runs.fetch_add(1, Ordering::Relaxed) + 1 < compile_after()
            || self.started.swap(true, Ordering::AcqRel)
        {
            return None;
        }
        let (cache, own) = (Arc::clone(self), Arc::clone(code));
        let thread = std::thread::Builder::new()
            .name("shaderbox-jit".to_string())
            .spawn(move || {
                cache.get(&own, true);
            });
        if thread.is_err() {
            return self.get(code, true);
        }
        None
    }

    /// The native code for `code`, compiling it now if `force` (waiting
    /// for a compilation in progress) or this is the
    /// [`COMPILE_AFTER_RUNS`]-th call and no other thread is at it.
    pub(crate) fn get(&self, code: &Code, force: bool) -> Option<&Native> {
        if let Some(r) = self.slot.get() {
            return r.as_ref().ok();
        }
        if !force && self.runs.fetch_add(1, Ordering::Relaxed) + 1 < compile_after() {
            return None;
        }
        // Another thread compiling: a forced caller waits for it, the
        // others keep interpreting.
        let _guard = if force {
            self.compiling.lock().unwrap_or_else(|e| e.into_inner())
        } else {
            match self.compiling.try_lock() {
                Ok(g) => g,
                Err(TryLockError::Poisoned(e)) => e.into_inner(),
                Err(TryLockError::WouldBlock) => return None,
            }
        };
        if let Some(r) = self.slot.get() {
            return r.as_ref().ok();
        }
        let started = std::time::Instant::now();
        let r = catch_unwind(AssertUnwindSafe(|| codegen::compile(code)))
            .unwrap_or_else(|_| Err("the code generator panicked".to_string()));
        if std::env::var_os("SHADERBOX_JIT_LOG").is_some_and(|v| v == "1") {
            match &r {
                Ok(n) => eprintln!(
                    "shaderbox: kernel of {} ops compiled to {} bytes in {:.1} ms{}",
                    code.ins.len(),
                    n.bytes,
                    started.elapsed().as_secs_f64() * 1e3,
                    if n.daz { " (runs under DAZ)" } else { "" }
                ),
                Err(e) => eprintln!("shaderbox: kernel stays on the interpreter: {e}"),
            }
        }
        let _ = self.slot.set(r);
        self.slot.get().and_then(|r| r.as_ref().ok())
    }

    /// `None` before compilation, else `Ok(code size)` or why the kernel
    /// stays on the interpreter.
    pub(crate) fn status(&self) -> Option<Result<usize, String>> {
        self.slot.get().map(|r| match r {
            Ok(n) => Ok(n.bytes),
            Err(e) => Err(e.clone()),
        })
    }

    /// Whether the compiled code runs under DAZ (`None`: not compiled).
    #[cfg(test)]
    pub(crate) fn runs_under_daz(&self) -> Option<bool> {
        self.slot.get()?.as_ref().ok().map(|n| n.daz)
    }
}

/// Whether native code runs with subnormal operands read as zero (MXCSR.DAZ,
/// [`float_env`]) instead of flushing each result in software: on x86-64 with
/// SSE4.1 (Cranelift's `floor`/`ceil` are then `roundps`, which honours
/// DAZ; without it they are calls into Rust).
pub(crate) fn daz() -> bool {
    crate::cpu::supports(crate::cpu::Features::SSE41)
}

/// Whether Cranelift generates code for this CPU (checked once).
pub(crate) fn supported() -> bool {
    static OK: OnceLock<bool> = OnceLock::new();
    *OK.get_or_init(|| codegen::isa().is_ok())
}

/// [`engine::run_in`]'s body with native code: same register file set-up and
/// output copy, the interpreter loop replaced by `native`.
#[allow(clippy::too_many_arguments)]
pub(crate) fn run(
    native: &Native,
    k: &Kernel,
    code: &Code,
    file: &mut Vec<Lanes>,
    batch: &mut Batch,
    uniforms: &[u32],
    textures: &dyn Textures,
    pool: Option<&[Lanes]>,
    views: &[View],
) -> Result<(), ExecError> {
    // A prepared pool is read where it is unless callbacks need it in the
    // file.
    let pool_base = code.pool_base as usize;
    let prepared = pool.filter(|p| p.len() == code.prog.registers as usize - pool_base);
    let (run_prologue, pool_ptr) = match prepared {
        Some(p) if !native.pool_in_file => {
            engine::load_inputs(k, code, file, batch);
            (false, p.as_ptr())
        }
        _ => {
            let run = engine::load(k, code, file, batch, pool);
            // `load` gave the file at least `code.prog.registers` registers.
            (run, file.get(pool_base..).unwrap_or_default().as_ptr())
        }
    };
    batch.discarded = 0;
    let mut ctx = Ctx {
        regs: file.as_mut_ptr(),
        budget: k.loop_budget,
        iterations: 0,
        start: (batch.active | batch.helper) & FULL,
        discarded: 0,
        prologue: run_prologue as u32,
        uniforms_len: uniforms.len().min(i32::MAX as usize) as u32,
        uniforms_ptr: if uniforms.is_empty() {
            &NO_WORD
        } else {
            uniforms.as_ptr()
        },
        consts: native.consts.as_ptr().cast(),
        pool: pool_ptr,
        scratch: [0; crate::LANES],
        view: View::default(),
        views: views.as_ptr(),
        views_len: views.len().min(u32::MAX as usize) as u32,
        code,
        uniforms,
        textures,
        panic: None,
        daz: native.daz,
    };
    // SAFETY: `native` was compiled from `code` (the kernel's cache), whose
    // registers and side tables were validated; `load` sized the file to
    // `code.prog.registers`; `ctx` outlives the call.
    let status = float_env::native(native.daz, || unsafe { (native.entry)(&mut ctx) });
    if let Some(p) = ctx.panic.take() {
        std::panic::resume_unwind(p);
    }
    if status != 0 {
        return Err(ExecError::LoopBudget {
            iterations: ctx.iterations,
        });
    }
    batch.discarded = ctx.discarded;
    engine::store_outputs(k, file, batch);
    Ok(())
}

static NO_WORD: u32 = 0;

/// Flag of `jit_step`'s index: an op of the prologue, not of the body.
const PROLOGUE_OP: u32 = 1 << 31;

/// Runs op `index` of the body (or of the prologue, with [`PROLOGUE_OP`])
/// with the engine's own `step`, on the lanes of `cur`.
///
/// # Safety
/// `ctx` must be the live context of a run of native code compiled from
/// `ctx.code`, and `index` an op of it.
unsafe extern "C" fn jit_step(ctx: *mut Ctx, index: u32, cur: u32) {
    let ctx = &mut *ctx;
    if ctx.panic.is_some() {
        return;
    }
    let code = ctx.code;
    let ins = if index & PROLOGUE_OP != 0 {
        code.prologue
            .get((index & !PROLOGUE_OP) as usize)
            .map(|&op| Ins { op, masked: false })
    } else {
        code.ins.get(index as usize).copied()
    };
    let Some(ins) = ins else { return };
    let (regs, uniforms, textures) = (ctx.regs, ctx.uniforms, ctx.textures);
    // SAFETY: the op was validated against the file's register count.
    // Float operands are read flushed by the ops called for (texture
    // lookups, noise, derivatives; `engine::floats`).
    let r = float_env::callback(ctx.daz, || {
        catch_unwind(AssertUnwindSafe(|| unsafe {
            engine::step_data(code, regs, &ins, cur, uniforms, textures)
        }))
    });
    if let Err(p) = r {
        ctx.panic = Some(p);
    }
}

/// Texture op `index` of `ctx.code` on the lanes of `cur`: a texel fetch
/// whose lanes all read one plain level ([`fetch_view`]) returns 1
/// having put the level in `ctx.view`, for the native code to load the
/// texels; every other op is run here by the engine's own `texture`
/// (returning 0). The registers are read where they are (pool registers
/// at `ctx.pool`), so these ops never need the pool copied into the file.
///
/// # Safety
/// `ctx` must be the live context of a run of native code compiled from
/// `ctx.code`.
unsafe extern "C" fn jit_texture(ctx: *mut Ctx, index: u32, cur: u32) -> u32 {
    let ctx = &mut *ctx;
    if ctx.panic.is_some() {
        return 0;
    }
    let code = ctx.code;
    let Some(t) = code.prog.textures.get(index as usize) else {
        return 0;
    };
    let regs = engine::Registers {
        file: ctx.regs,
        base: code.pool_base,
        at: ctx.pool,
    };
    let (textures, daz) = (ctx.textures, ctx.daz);
    // SAFETY: the op's registers were validated against the file and the
    // pool; the native code holds none of them while this runs.
    let r = catch_unwind(AssertUnwindSafe(|| unsafe {
        if t.kind == TexKind::Fetch {
            if let Some(v) = fetch_view(regs, t, cur, textures) {
                return Some(v);
            }
        }
        // Filtering, decoding and depth comparison compute in floats:
        // in Rust's environment. A size is integers only.
        if t.kind == TexKind::Size {
            engine::texture_size(regs, t, cur, textures);
        } else {
            float_env::callback(daz, || engine::texture(regs, t, cur, textures));
        }
        None
    }));
    match r {
        Ok(Some(v)) => {
            ctx.view = v;
            1
        }
        Ok(None) => 0,
        Err(p) => {
            ctx.panic = Some(p);
            0
        }
    }
}

/// The level texel fetch `t` reads on the lanes of `cur`, when they all
/// read the same unit and level and the textures give it as a
/// [`crate::TexelLevel`] whose texel count fits native code's 32-bit
/// indices.
///
/// # Safety
/// The registers `t` reads must be in `regs`.
unsafe fn fetch_view(
    regs: engine::Registers,
    t: &crate::program::TexOp,
    cur: u32,
    textures: &dyn Textures,
) -> Option<View> {
    let lod = t.level().map(|l| regs.get(l));
    let (unit, lod) = engine::shared_pair(cur, regs.get(t.unit), lod)?;
    let level = textures.texel_level(unit, t.target, lod as i32)?;
    let count = level
        .size
        .iter()
        .try_fold(1u64, |n, &s| n.checked_mul(s as u64))?;
    if count == 0 || count > i32::MAX as u64 || (level.texels.len() as u64) < count {
        return None;
    }
    let (texels, format, rest) = match level.texels {
        crate::TexelSlice::Rgba32(t) => (t.as_ptr().cast(), View::RGBA32, [0; 3]),
        crate::TexelSlice::Unorm8(t) => (t.as_ptr().cast(), View::UNORM8, [0; 3]),
        // (Float results take the callback: their code reads no such
        // view.)
        crate::TexelSlice::Red16 { .. }
            if t.target.result() == glsl::types::SamplerResult::Float =>
        {
            return None
        }
        crate::TexelSlice::Red16 { red, signed, rest } => {
            let format = if signed {
                View::RED16_SIGNED
            } else {
                View::RED16
            };
            (red.as_ptr().cast(), format, rest)
        }
    };
    Some(View {
        texels,
        size: level.size,
        keep: std::array::from_fn(|a| if (a as u32) < level.axes { u32::MAX } else { 0 }),
        format,
        rest,
    })
}

/// Per texture op of `code`, the level a texel fetch reads on every lane
/// of a run with the prepared `pool` and `textures`, when its unit and
/// level are pool registers (a uniform sampler, a constant or uniform
/// level) and the textures give the level ([`fetch_view`]); an empty view
/// (no texels) for the others. Native code reads these instead of asking
/// `jit_texture` per batch, in runs with those textures.
pub(crate) fn prepared_views(code: &Code, pool: &[Lanes], textures: &dyn Textures) -> Vec<View> {
    let base = code.pool_base;
    // (Inside the pool too: the reads below are unchecked.)
    let inside = |r: crate::program::Reg| ((r - base) as usize) < pool.len();
    let regs = engine::Registers {
        file: std::ptr::null_mut(),
        base,
        at: pool.as_ptr(),
    };
    code.prog
        .textures
        .iter()
        .map(|t| {
            let pooled =
                t.unit_and_level_from(base) && inside(t.unit) && t.level().is_none_or(inside);
            if t.kind != TexKind::Fetch || !pooled {
                return View::default();
            }
            // SAFETY: the registers read (unit and level) are pool
            // registers inside `pool`, read where they are.
            let v = catch_unwind(AssertUnwindSafe(|| unsafe {
                fetch_view(regs, t, crate::interp::FULL, textures)
            }));
            v.ok().flatten().unwrap_or_default()
        })
        .collect()
}

/// The functions of one float the native code calls (index = argument).
/// The functions of GLSL 1.30 and later are calls too: `engine::f1`
/// evaluates them with `glsl::math`, the bits of constant folding.
const F1_CALLED: [F1; 21] = [
    F1::Sin,
    F1::Cos,
    F1::Tan,
    F1::Asin,
    F1::Acos,
    F1::Atan,
    F1::Exp,
    F1::Log,
    F1::Exp2,
    F1::Log2,
    F1::Sinh,
    F1::Cosh,
    F1::Tanh,
    F1::Asinh,
    F1::Acosh,
    F1::Atanh,
    F1::Trunc,
    F1::Round,
    F1::RoundEven,
    F1::ModfFract,
    F1::FlushBits,
];

/// The functions of two floats the native code calls.
const F2_CALLED: [F2; 2] = [F2::Atan2, F2::Pow];

/// `out = engine::f1(F1_CALLED[func], a)`, compiled for the baseline
/// instruction set.
///
/// # Safety
/// `out` and `a` must point to registers (`a` may equal `out`).
unsafe extern "C" fn jit_f1(func: u32, out: *mut Lanes, a: *const Lanes) {
    if let Some(&f) = F1_CALLED.get(func as usize) {
        *out = float_env::callback(daz(), || engine::f1(f, &engine::flushed(&*a)));
    }
}

/// `out = engine::f2(F2_CALLED[func], a, b)`, compiled for the baseline
/// instruction set.
///
/// # Safety
/// As for [`jit_f1`].
unsafe extern "C" fn jit_f2(func: u32, out: *mut Lanes, a: *const Lanes, b: *const Lanes) {
    if let Some(&f) = F2_CALLED.get(func as usize) {
        *out = float_env::callback(daz(), || {
            engine::f2(f, &engine::flushed(&*a), &engine::flushed(&*b))
        });
    }
}

/// [`jit_f1`] and [`jit_f2`] compiled for a [`crate::cpu::Level`]:
/// `engine::f1`/`f2`'s lane loops over the branch-free `glsl::math`
/// functions vectorize wider there (Rust never contracts into fused
/// multiply-adds, so the bits are those of the baseline build). Native
/// code calls them through pointers, so they are copies without a
/// dispatch ([`crate::compiled_for!`]).
#[cfg(target_arch = "x86_64")]
macro_rules! math_helpers_for {
    ($level:ident, $f1:ident, $f2:ident) => {
        crate::compiled_for!(
            $level,
            /// # Safety
            /// As for [`jit_f1`], and the CPU must run the level.
            unsafe extern "C" fn $f1(func: u32, out: *mut Lanes, a: *const Lanes) {
                if let Some(&f) = F1_CALLED.get(func as usize) {
                    *out = float_env::callback(daz(), || engine::f1(f, &engine::flushed(&*a)));
                }
            }
        );

        crate::compiled_for!(
            $level,
            /// # Safety
            /// As for [`jit_f2`], and the CPU must run the level.
            unsafe extern "C" fn $f2(func: u32, out: *mut Lanes, a: *const Lanes, b: *const Lanes) {
                if let Some(&f) = F2_CALLED.get(func as usize) {
                    *out = float_env::callback(daz(), || {
                        engine::f2(f, &engine::flushed(&*a), &engine::flushed(&*b))
                    });
                }
            }
        );
    };
}
#[cfg(target_arch = "x86_64")]
math_helpers_for!(avx2, jit_f1_avx2, jit_f2_avx2);
#[cfg(target_arch = "x86_64")]
math_helpers_for!(avx512, jit_f1_avx512, jit_f2_avx512);

/// The math helpers native code calls: those of the highest level the CPU
/// runs (AVX-512: 16 lanes of `f64` are two 512-bit registers instead of
/// four 256-bit ones, so it takes less time per batch than AVX2).
fn math_helpers() -> (*const (), *const ()) {
    use crate::cpu::Level;
    match Level::best() {
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => (jit_f1_avx512 as *const (), jit_f2_avx512 as *const ()),
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 => (jit_f1_avx2 as *const (), jit_f2_avx2 as *const ()),
        _ => (jit_f1 as *const (), jit_f2 as *const ()),
    }
}
