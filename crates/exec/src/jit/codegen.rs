//! Cranelift IR for a [`Code`]: one function `fn(*mut Ctx) -> u32`.

use super::PROLOGUE_OP;
use super::{jit_step, math_helpers, Const16, Ctx, Entry, Native, F1_CALLED, F2_CALLED, MAX_OPS};
use crate::opt::{Code, Ins};
use crate::program::{Op, Reg, F1, F2, F3};
use cranelift_codegen::ir::condcodes::{FloatCC, IntCC};
use cranelift_codegen::ir::types::{F32X4, I32, I32X4, I64, I8X16};
use cranelift_codegen::ir::{
    AbiParam, Block, BlockArg, ConstantData, Endianness, InstBuilder, MemFlagsData, SigRef,
    Signature, Type, UserFuncName, Value,
};
use cranelift_codegen::isa::OwnedTargetIsa;
use cranelift_codegen::settings::{self, Configurable};
use cranelift_frontend::{FunctionBuilder, FunctionBuilderContext, Variable};
use cranelift_jit::{JITBuilder, JITModule};
use cranelift_module::{default_libcall_names, Linkage, Module};
use std::mem::offset_of;

/// The host's instruction set, as Cranelift targets it.
pub(super) fn isa() -> Result<OwnedTargetIsa, String> {
    let mut flags = settings::builder();
    let set = |f: &mut settings::Builder, k: &str, v: &str| {
        f.set(k, v)
            .map_err(|e| format!("cranelift setting {k}={v}: {e}"))
    };
    set(&mut flags, "opt_level", "speed")?;
    set(&mut flags, "use_colocated_libcalls", "false")?;
    set(&mut flags, "is_pic", "false")?;
    set(
        &mut flags,
        "enable_verifier",
        if cfg!(debug_assertions) {
            "true"
        } else {
            "false"
        },
    )?;
    let builder = cranelift_native::builder()
        .map_err(|e| format!("Cranelift does not support this CPU: {e}"))?;
    builder
        .finish(settings::Flags::new(flags))
        .map_err(|e| format!("Cranelift does not support this CPU: {e}"))
}

/// Compiles `code`; `Err` says why it stays on the interpreter.
pub(super) fn compile(code: &Code) -> Result<Native, String> {
    if code.ins.len() > MAX_OPS {
        return Err(format!(
            "{} ops (native code is made for at most {MAX_OPS})",
            code.ins.len()
        ));
    }
    for i in &code.ins {
        if let Op::Call { .. } | Op::Ret { .. } = i.op {
            return Err("subroutine calls are interpreted".to_string());
        }
    }
    let isa = isa()?;
    let mut module = JITModule::new(JITBuilder::with_isa(isa, default_libcall_names()));
    let r = define(&mut module, code);
    match r {
        Ok((id, bytes, consts)) => {
            if let Err(e) = module.finalize_definitions() {
                // SAFETY: nothing of the module was handed out.
                unsafe { module.free_memory() };
                return Err(format!("cranelift: {e}"));
            }
            let ptr = module.get_finalized_function(id);
            if let Some(dir) = std::env::var_os("SHADERBOX_JIT_DUMP") {
                // For profiling: the machine code, named by its address.
                // SAFETY: the function's `bytes` bytes of code start there.
                let text = unsafe { std::slice::from_raw_parts(ptr, bytes) };
                let path = std::path::Path::new(&dir).join(format!("jit-{:x}.bin", ptr as usize));
                let _ = std::fs::write(path, text);
            }
            // SAFETY: the function was defined with the signature
            // `fn(ptr) -> i32` in the host's C calling convention.
            let entry = unsafe { std::mem::transmute::<*const u8, Entry>(ptr) };
            Ok(Native {
                module: Some(module),
                entry,
                consts,
                pool_in_file: pool_in_file(code),
                bytes,
                daz: super::daz(),
            })
        }
        Err(e) => {
            // SAFETY: as above.
            unsafe { module.free_memory() };
            Err(e)
        }
    }
}

/// Defines the function; returns it, its code size and its constants.
fn define(
    module: &mut JITModule,
    code: &Code,
) -> Result<(cranelift_module::FuncId, usize, Box<[Const16]>), String> {
    let ptr = module.target_config().pointer_type();
    let mut sig = module.make_signature();
    sig.params.push(AbiParam::new(ptr));
    sig.returns.push(AbiParam::new(I32));
    let id = module
        .declare_function("kernel", Linkage::Local, &sig)
        .map_err(|e| format!("cranelift: {e}"))?;
    let mut ctx = module.make_context();
    ctx.func.signature = sig;
    ctx.func.name = UserFuncName::user(0, id.as_u32());
    let mut fctx = FunctionBuilderContext::new();
    let consts = {
        let b = FunctionBuilder::new(&mut ctx.func, &mut fctx);
        let mut e = Emit::new(b, module, code, ptr);
        e.after = live_after(code);
        e.body()?;
        e.b.seal_all_blocks();
        e.b.finalize(module.target_config());
        e.consts.table
    };
    // At least one entry: the pointer the code receives is never dangling.
    let consts: Box<[Const16]> = if consts.is_empty() {
        vec![Const16([0; 4])].into()
    } else {
        consts.into_iter().map(Const16).collect()
    };
    module
        .define_function(id, &mut ctx)
        .map_err(|e| format!("cranelift: {e:?}"))?;
    let bytes = ctx
        .compiled_code()
        .map(|c| c.code_buffer().len())
        .unwrap_or(0);
    Ok((id, bytes, consts))
}

/// Whether an op of `code.ins` that native code runs through `jit_step`
/// (or a gather, which addresses the file) reads a pool register.
fn pool_in_file(code: &Code) -> bool {
    code.ins.iter().any(|ins| {
        let inline = separable(ins)
            || match ins.op {
                // Mask ops read their condition with `ld`, which knows
                // where pool registers are.
                Op::F1 { .. }
                | Op::F2 { .. }
                | Op::Scatter { .. }
                | Op::AndMask { .. }
                | Op::AndNotMask { .. } => true,
                Op::GatherUniform { word, max, .. } => word as u64 + max as u64 <= i32::MAX as u64,
                _ => false,
            };
        !inline
            && crate::liveness::effects(&code.prog, &ins.op)
                .uses
                .iter()
                .any(|&(r, n)| r as u64 + n.max(1) as u64 > code.pool_base as u64)
    })
}

/// Registers live after each op of `code.ins` (empty when the analysis
/// declines or would take more than 4 MiB).
fn live_after(code: &Code) -> Vec<Vec<u64>> {
    let words = (code.prog.registers as usize).div_ceil(64);
    if code.ins.len().saturating_mul(words) > (1 << 19) {
        return Vec::new();
    }
    let masked: Vec<bool> = code.ins.iter().map(|i| i.masked).collect();
    crate::liveness::analyze_after(
        &code.prog,
        &code.prog.ops,
        &masked,
        code.prog.registers,
        &code.live_out,
    )
    .map(|l| l.after)
    .unwrap_or_default()
}

fn helper_sig(module: &JITModule, ptr: Type, params: &[Type]) -> Signature {
    let mut s = module.make_signature();
    for &p in params {
        s.params.push(AbiParam::new(if p == I64 { ptr } else { p }));
    }
    s
}

/// Lane `l` of vector `q` is lane `4q + l` of a register.
const QUARTERS: usize = 4;
const SIGN: u32 = 0x8000_0000;
const ONE: u32 = 0x3f80_0000;

struct Emit<'a, 'b> {
    b: FunctionBuilder<'b>,
    code: &'a Code,
    ptr: Type,
    ctx: Value,
    regs: Value,
    /// `Ctx::pool`: where the pool registers are read.
    pool: Value,
    budget: Value,
    cur: Variable,
    mk: [Variable; QUARTERS],
    masks: Vec<Variable>,
    discarded: Variable,
    iterations: Variable,
    sig_step: SigRef,
    sig_f1: SigRef,
    sig_f2: SigRef,
    /// Where the loop budget ran out (block parameter: the count).
    fail: Block,
    /// Register quarters held in SSA values in the current block.
    cache: Cache,
    /// While emitting a run of lane-wise ops quarter by quarter: the
    /// quarter; `None`: every op emits all four.
    only: Option<usize>,
    /// Per op of `code.ins`: the registers live after it (empty when the
    /// analysis declined: then everything is stored).
    after: Vec<Vec<u64>>,
    /// The vector constants, loaded from `Ctx::consts`.
    consts: Consts,
    /// In a quarter-by-quarter run: the op after which liveness decides
    /// what is stored, when the op being emitted is the run's last writer
    /// of its destination (which it then stores at once).
    store_now: Option<usize>,
    /// Emitting for a current mask known to hold all [`crate::LANES`] lanes:
    /// masked writes write every lane.
    full: bool,
    /// The code runs with subnormal operands read as zero ([`super::daz`]):
    /// results are left unflushed.
    daz: bool,
}

/// Vector constants in a table the code loads from: a load used once is
/// folded into the instruction using it, and loads of one entry between
/// two stores become one value (Cranelift would otherwise compute each
/// constant once for the whole function and spill it).
#[derive(Default)]
struct Consts {
    table: Vec<[u32; 4]>,
    index: std::collections::HashMap<[u32; 4], u32>,
    /// `Ctx::consts`, loaded at the entry.
    base: Option<Value>,
}

/// A quarter of a register held in an SSA value: `dirty` when memory does
/// not have it yet; `used`: when last touched (for eviction).
#[derive(Clone, Copy)]
struct Held {
    v: Value,
    dirty: bool,
    used: u64,
}

/// The register quarters of the current block kept in SSA values, so an op
/// reading what an earlier op of the block wrote needs no load, and a
/// register written several times is stored once. Memory is brought up to
/// date (`flush`) before branches, before calls, and for the registers a
/// gather reads; a scatter's registers are dropped (`forget`).
#[derive(Default, Clone)]
struct Cache {
    held: std::collections::BTreeMap<(Reg, usize), Held>,
    clock: u64,
}

/// At most this many quarters are held (more only makes Cranelift spill).
const HELD: usize = 48;

/// Data ops emitted inline whose lanes `4q..4q + 4` of the result depend
/// only on lanes `4q..4q + 4` of their operands and of the mask, with no
/// call, branch or memory access besides their registers' (and uniform
/// words).
fn separable(ins: &Ins) -> bool {
    match ins.op {
        Op::F1 { f, .. } => !F1_CALLED.contains(&f),
        Op::F2 { f, .. } => !F2_CALLED.contains(&f),
        Op::ClampIdx { max, .. } => max <= i32::MAX as u32,
        Op::Const { .. }
        | Op::Mov { .. }
        | Op::Store { .. }
        | Op::FAdd { .. }
        | Op::FSub { .. }
        | Op::FMul { .. }
        | Op::FDiv { .. }
        | Op::FNeg { .. }
        | Op::FMac { .. }
        | Op::Dot { .. }
        | Op::F3 { .. }
        | Op::FLt { .. }
        | Op::FLe { .. }
        | Op::FEq { .. }
        | Op::IAdd { .. }
        | Op::ISub { .. }
        | Op::IMul { .. }
        | Op::INeg { .. }
        | Op::ILt { .. }
        | Op::ILe { .. }
        | Op::IEq { .. }
        | Op::And { .. }
        | Op::Or { .. }
        | Op::Xor { .. }
        | Op::Not { .. }
        | Op::FToI { .. }
        | Op::IToF { .. }
        | Op::FToB { .. }
        | Op::IToB { .. }
        | Op::BToF { .. }
        | Op::Select { .. }
        | Op::Uniform { .. }
        | Op::DdX { .. }
        | Op::DdY { .. }
        | Op::Printf { .. } => true,
        _ => false,
    }
}

fn mem() -> MemFlagsData {
    MemFlagsData::new().with_notrap()
}

impl<'a, 'b> Emit<'a, 'b> {
    fn new(mut b: FunctionBuilder<'b>, module: &JITModule, code: &'a Code, ptr: Type) -> Self {
        let entry = b.create_block();
        b.append_block_params_for_function_params(entry);
        b.switch_to_block(entry);
        let ctx = b.block_params(entry)[0];
        let regs = b.ins().load(ptr, mem(), ctx, offset_of!(Ctx, regs) as i32);
        let pool = b.ins().load(ptr, mem(), ctx, offset_of!(Ctx, pool) as i32);
        let budget = b
            .ins()
            .load(I64, mem(), ctx, offset_of!(Ctx, budget) as i32);
        let cur = b.declare_var(I32);
        let mk = [(); QUARTERS].map(|_| b.declare_var(I32X4));
        let masks = (0..code.prog.mask_slots)
            .map(|_| b.declare_var(I32))
            .collect::<Vec<_>>();
        let discarded = b.declare_var(I32);
        let iterations = b.declare_var(I64);
        let sig_step = b.import_signature(helper_sig(module, ptr, &[I64, I32, I32]));
        let sig_f1 = b.import_signature(helper_sig(module, ptr, &[I32, I64, I64]));
        let sig_f2 = b.import_signature(helper_sig(module, ptr, &[I32, I64, I64, I64]));
        let fail = b.create_block();
        b.append_block_param(fail, I64);
        let mut e = Emit {
            b,
            code,
            ptr,
            ctx,
            regs,
            pool,
            budget,
            cur,
            mk,
            masks,
            discarded,
            iterations,
            sig_step,
            sig_f1,
            sig_f2,
            fail,
            cache: Cache::default(),
            only: None,
            after: Vec::new(),
            consts: Consts::default(),
            store_now: None,
            full: false,
            daz: super::daz(),
        };
        let base =
            e.b.ins()
                .load(ptr, mem(), ctx, offset_of!(Ctx, consts) as i32);
        e.consts.base = Some(base);
        let zero = e.b.ins().iconst(I32, 0);
        for &m in &e.masks {
            e.b.def_var(m, zero);
        }
        e.b.def_var(e.discarded, zero);
        let zero64 = e.b.ins().iconst(I64, 0);
        e.b.def_var(e.iterations, zero64);
        let start =
            e.b.ins()
                .load(I32, mem(), ctx, offset_of!(Ctx, start) as i32);
        e.set_cur(start);
        e
    }

    // ---- values -------------------------------------------------------

    fn splat(&mut self, bits: u32) -> Value {
        self.vconst([bits; 4])
    }

    fn vconst(&mut self, lanes: [u32; 4]) -> Value {
        let c = &mut self.consts;
        let next = c.table.len() as u32;
        let i = *c.index.entry(lanes).or_insert(next);
        if i == next {
            c.table.push(lanes);
        }
        match (c.base, i32::try_from(i as u64 * 16)) {
            (Some(base), Ok(off)) => self.b.ins().load(I32X4, mem().with_aligned(), base, off),
            _ => {
                let bytes: Vec<u8> = lanes.iter().flat_map(|l| l.to_le_bytes()).collect();
                let c = self.b.func.dfg.constants.insert(ConstantData::from(bytes));
                self.b.ins().vconst(I32X4, c)
            }
        }
    }

    fn fv(&mut self, v: Value) -> Value {
        self.b.ins().bitcast(F32X4, MemFlagsData::new(), v)
    }

    fn iv(&mut self, v: Value) -> Value {
        self.b.ins().bitcast(I32X4, MemFlagsData::new(), v)
    }

    fn offset(r: Reg, q: usize) -> i32 {
        (r as usize * 64 + q * 16) as i32
    }

    /// Quarter `q` of register `r` (as I32X4).
    fn ld(&mut self, r: Reg, q: usize) -> Value {
        self.cache.clock += 1;
        let now = self.cache.clock;
        if let Some(h) = self.cache.held.get_mut(&(r, q)) {
            h.used = now;
            return h.v;
        }
        let v = if r >= self.code.pool_base {
            let off = Self::offset(r - self.code.pool_base, q);
            self.b.ins().load(I32X4, mem(), self.pool, off)
        } else {
            self.b
                .ins()
                .load(I32X4, mem(), self.regs, Self::offset(r, q))
        };
        self.hold(r, q, v, false);
        v
    }

    /// Quarter `q` of register `r` as F32X4.
    fn ldf(&mut self, r: Reg, q: usize) -> Value {
        let v = self.ld(r, q);
        self.fv(v)
    }

    /// Writes `v` (I32X4) into quarter `q` of `d`, under the current mask
    /// when `masked`.
    fn put(&mut self, d: Reg, q: usize, v: Value, masked: bool) {
        let v = if masked && !self.full {
            let old = self.ld(d, q);
            let m = self.b.use_var(self.mk[q]);
            self.b.ins().bitselect(m, v, old)
        } else {
            v
        };
        // The last write of a run to a register read after it is stored
        // here, not at the run's end: Cranelift computes a value where
        // its first side-effecting use is, so a store at the end would
        // move the run's arithmetic there, away from its loads. Later
        // reads load it again (holding it made Cranelift spill it).
        if let Some(end) = self.store_now {
            if self.live_after(end, d) {
                self.b.ins().store(mem(), v, self.regs, Self::offset(d, q));
                self.cache.held.remove(&(d, q));
                return;
            }
        }
        self.hold(d, q, v, true);
    }

    fn hold(&mut self, r: Reg, q: usize, v: Value, dirty: bool) {
        self.cache.clock += 1;
        let used = self.cache.clock;
        self.cache.held.insert((r, q), Held { v, dirty, used });
        if self.cache.held.len() > HELD {
            let oldest = self
                .cache
                .held
                .iter()
                .min_by_key(|(_, h)| h.used)
                .map(|(&k, _)| k);
            if let Some(k) = oldest {
                self.evict(k);
            }
        }
    }

    fn evict(&mut self, k: (Reg, usize)) {
        if let Some(h) = self.cache.held.remove(&k) {
            if h.dirty {
                self.b
                    .ins()
                    .store(mem(), h.v, self.regs, Self::offset(k.0, k.1));
            }
        }
    }

    /// Stores the held quarters of registers `lo..=hi` that memory lacks.
    fn flush_range(&mut self, lo: Reg, hi: Reg) {
        let dirty: Vec<((Reg, usize), Value)> = self
            .cache
            .held
            .range((lo, 0)..=(hi, QUARTERS))
            .filter(|(_, h)| h.dirty)
            .map(|(&k, h)| (k, h.v))
            .collect();
        for ((r, q), v) in dirty {
            self.b.ins().store(mem(), v, self.regs, Self::offset(r, q));
            if let Some(h) = self.cache.held.get_mut(&(r, q)) {
                h.dirty = false;
            }
        }
    }

    /// Memory up to date, nothing held (block ends, calls).
    fn flush_all(&mut self) {
        self.flush_range(0, Reg::MAX);
        self.cache.held.clear();
    }

    /// Drops what is held of registers `lo..=hi` (memory is written behind
    /// the cache's back); flush them first.
    fn forget(&mut self, lo: Reg, hi: Reg) {
        let keys: Vec<_> = self
            .cache
            .held
            .range((lo, 0)..=(hi, QUARTERS))
            .map(|(&k, _)| k)
            .collect();
        for k in keys {
            self.cache.held.remove(&k);
        }
    }

    /// The quarters the current op emits (see `only`).
    fn quarters(&self) -> std::ops::Range<usize> {
        match self.only {
            Some(q) => q..q + 1,
            None => 0..QUARTERS,
        }
    }

    /// Whether register `r` may be read after op `i` (a pool register, or
    /// live by the analysis; everything when there is none).
    fn live_after(&self, i: usize, r: Reg) -> bool {
        r >= self.code.pool_base
            || self
                .after
                .get(i)
                .is_none_or(|bits| crate::liveness::is_live(bits, r))
    }

    /// Ends the held values of quarter `q` (every quarter: `None`): stores
    /// the dirty ones that are live after op `i` (all dirty ones: `i` =
    /// `None`) and drops them all.
    fn retire(&mut self, q: Option<usize>, i: Option<usize>) {
        let keys: Vec<(Reg, usize)> = self
            .cache
            .held
            .keys()
            .filter(|k| q.is_none_or(|q| k.1 == q))
            .copied()
            .collect();
        for k in keys {
            let Some(h) = self.cache.held.remove(&k) else {
                continue;
            };
            if h.dirty && i.is_none_or(|i| self.live_after(i, k.0)) {
                self.b
                    .ins()
                    .store(mem(), h.v, self.regs, Self::offset(k.0, k.1));
            }
        }
    }

    /// `engine::ftz` of an F32X4, as I32X4: a subnormal keeps only its
    /// sign. Under DAZ, `x` as it is: every float op reads it as the
    /// flushed value, and it is flushed where it leaves the code (outputs,
    /// callback operands).
    fn ftz(&mut self, x: Value) -> Value {
        if self.daz {
            return self.iv(x);
        }
        let b = self.iv(x);
        let exp = self.splat(0x7f80_0000);
        let e = self.b.ins().band(b, exp);
        let zero = self.splat(0);
        let z = self.b.ins().icmp(IntCC::Equal, e, zero);
        let mag = self.splat(!SIGN);
        let drop = self.b.ins().band(z, mag);
        self.b.ins().band_not(b, drop)
    }

    /// [`Self::ftz`] as an F32X4: an intermediate result flushed before
    /// the next op uses it.
    fn fz(&mut self, x: Value) -> Value {
        let v = self.ftz(x);
        self.fv(v)
    }

    /// Uniform words (I32X4) as read: [`Self::ftz`] for a float's.
    fn ftz_word(&mut self, float: bool, v: Value) -> Value {
        if float && !self.daz {
            let x = self.fv(v);
            self.ftz(x)
        } else {
            v
        }
    }

    /// 0/1 from an all-ones/zero lane mask.
    fn bool01(&mut self, m: Value) -> Value {
        let one = self.splat(1);
        self.b.ins().band(m, one)
    }

    /// All-ones where `v` is 0 (one compare; `!= 0` would take three).
    fn is_zero(&mut self, v: Value) -> Value {
        let zero = self.splat(0);
        self.b.ins().icmp(IntCC::Equal, v, zero)
    }

    /// 1 where `v` is nonzero, else 0.
    fn bool_of(&mut self, v: Value) -> Value {
        let z = self.is_zero(v);
        let one = self.splat(1);
        self.b.ins().band_not(one, z)
    }

    /// `engine::fmin`: `y` if `x` is NaN or `y < x`, else `x` (F32X4 in,
    /// F32X4 out).
    fn fmin(&mut self, x: Value, y: Value) -> Value {
        let nan = self.b.ins().fcmp(FloatCC::Unordered, x, x);
        let lt = self.b.ins().fcmp(FloatCC::LessThan, y, x);
        let c = self.b.ins().bor(nan, lt);
        let (xi, yi) = (self.iv(x), self.iv(y));
        let r = self.b.ins().bitselect(c, yi, xi);
        self.fv(r)
    }

    /// `engine::fmax`: `y` if `x` is NaN or `x < y`, else `x`.
    fn fmax(&mut self, x: Value, y: Value) -> Value {
        let nan = self.b.ins().fcmp(FloatCC::Unordered, x, x);
        let lt = self.b.ins().fcmp(FloatCC::LessThan, x, y);
        let c = self.b.ins().bor(nan, lt);
        let (xi, yi) = (self.iv(x), self.iv(y));
        let r = self.b.ins().bitselect(c, yi, xi);
        self.fv(r)
    }

    /// `engine::floor`: IEEE floor, NaN returned as it is (bits kept).
    fn floor(&mut self, x: Value) -> Value {
        let r = self.b.ins().floor(x);
        self.keep_nan(x, r)
    }

    fn ceil(&mut self, x: Value) -> Value {
        let r = self.b.ins().ceil(x);
        self.keep_nan(x, r)
    }

    fn keep_nan(&mut self, x: Value, r: Value) -> Value {
        let nan = self.b.ins().fcmp(FloatCC::Unordered, x, x);
        let (xi, ri) = (self.iv(x), self.iv(r));
        let v = self.b.ins().bitselect(nan, xi, ri);
        self.fv(v)
    }

    fn fconst(&mut self, x: f32) -> Value {
        let v = self.splat(x.to_bits());
        self.fv(v)
    }

    // ---- masks ---------------------------------------------------------

    /// `cur = v` and its expanded vectors.
    fn set_cur(&mut self, v: Value) {
        self.b.def_var(self.cur, v);
        let s = self.b.ins().splat(I32X4, v);
        for q in 0..QUARTERS {
            let s4 = (4 * q) as u32;
            let bits = self.vconst([1 << s4, 2 << s4, 4 << s4, 8 << s4]);
            let m = self.b.ins().band(s, bits);
            let m = self.b.ins().icmp(IntCC::Equal, m, bits);
            self.b.def_var(self.mk[q], m);
        }
    }

    /// Lane bits where register `c` is zero, and the per-quarter masks of
    /// those lanes.
    fn zero_bits(&mut self, c: Reg) -> (Value, [Value; QUARTERS]) {
        let mut bits = self.b.ins().iconst(I32, 0);
        let mut ms = [bits; QUARTERS];
        for (q, m_out) in ms.iter_mut().enumerate() {
            let v = self.ld(c, q);
            let m = self.is_zero(v);
            *m_out = m;
            let hb = self.b.ins().vhigh_bits(I32, m);
            let hb = if q > 0 {
                self.b.ins().ishl_imm_u(hb, (4 * q) as i64)
            } else {
                hb
            };
            bits = self.b.ins().bor(bits, hb);
        }
        (bits, ms)
    }

    fn mask_var(&self, slot: u32) -> Result<Variable, String> {
        self.masks
            .get(slot as usize)
            .copied()
            .ok_or_else(|| format!("mask slot {slot} out of range"))
    }

    fn kill_slots(&self, start: u32, end: u32) -> Result<Vec<Variable>, String> {
        let slots = self
            .code
            .prog
            .kill_slots
            .get(start as usize..end as usize)
            .ok_or("kill slots out of range")?;
        slots.iter().map(|&s| self.mask_var(s)).collect()
    }

    // ---- calls ---------------------------------------------------------

    fn call_step(&mut self, index: u32) {
        // The engine's step reads and writes registers in memory.
        self.flush_all();
        let f = self.b.ins().iconst(self.ptr, jit_step as *const () as i64);
        let i = self.b.ins().iconst(I32, index as i32 as i64);
        let cur = self.b.use_var(self.cur);
        let ctx = self.ctx;
        self.b.ins().call_indirect(self.sig_step, f, &[ctx, i, cur]);
    }

    /// Where register `r` is read (pool registers: at `Ctx::pool`).
    fn reg_ptr(&mut self, r: Reg) -> Value {
        if r >= self.code.pool_base {
            let off = (r - self.code.pool_base) as i64 * 64;
            self.b.ins().iadd_imm_s(self.pool, off)
        } else {
            self.b.ins().iadd_imm_s(self.regs, r as i64 * 64)
        }
    }

    /// Calls `jit_f1`/`jit_f2` into the scratch register, then copies it
    /// to `d` (under the mask when `masked`).
    fn call_math(&mut self, two: bool, func: usize, d: Reg, a: Reg, b: Reg, masked: bool) {
        let out = self
            .b
            .ins()
            .iadd_imm_s(self.ctx, offset_of!(Ctx, scratch) as i64);
        self.flush_range(a, a);
        self.flush_range(b, b);
        let fi = self.b.ins().iconst(I32, func as i64);
        let pa = self.reg_ptr(a);
        if two {
            let pb = self.reg_ptr(b);
            let f = self.b.ins().iconst(self.ptr, math_helpers().1 as i64);
            self.b
                .ins()
                .call_indirect(self.sig_f2, f, &[fi, out, pa, pb]);
        } else {
            let f = self.b.ins().iconst(self.ptr, math_helpers().0 as i64);
            self.b.ins().call_indirect(self.sig_f1, f, &[fi, out, pa]);
        }
        for q in 0..QUARTERS {
            let v = self.b.ins().load(I32X4, mem(), out, (q * 16) as i32);
            self.put(d, q, v, masked);
        }
    }

    // ---- gathers -------------------------------------------------------

    fn uniforms(&mut self) -> (Value, Value) {
        let p = self.b.ins().load(
            self.ptr,
            mem(),
            self.ctx,
            offset_of!(Ctx, uniforms_ptr) as i32,
        );
        let n = self
            .b
            .ins()
            .load(I32, mem(), self.ctx, offset_of!(Ctx, uniforms_len) as i32);
        (p, n)
    }

    /// `uniforms[word]`, 0 past the end (scalar I32).
    fn uniform_word(&mut self, word: u32) -> Value {
        let (p, n) = self.uniforms();
        let w = self.b.ins().iconst(I32, word as i32 as i64);
        let inside = self.b.ins().icmp(IntCC::UnsignedLessThan, w, n);
        let zero = self.b.ins().iconst(I32, 0);
        let safe = self.b.ins().select(inside, w, zero);
        let v = self.load_word(p, safe);
        self.b.ins().select(inside, v, zero)
    }

    /// `p[i]` for an I32 index.
    fn load_word(&mut self, p: Value, i: Value) -> Value {
        let i = self.b.ins().uextend(self.ptr, i);
        let off = self.b.ins().ishl_imm_u(i, 2);
        let addr = self.b.ins().iadd(p, off);
        self.b.ins().load(I32, mem(), addr, 0)
    }

    /// `d = uniforms[word + min(off, max)]` per lane (0 past the end);
    /// `word + max` fits in an `i32`. When every lane reads the same word
    /// (an array indexed by a loop counter), one load.
    fn gather_uniform(&mut self, d: Reg, word: u32, off: Reg, max: u32, float: bool, masked: bool) {
        let (p, n) = self.uniforms();
        let mut idx = [p; QUARTERS];
        for (q, x) in idx.iter_mut().enumerate() {
            let o = self.ld(off, q);
            let mx = self.splat(max);
            let o = self.b.ins().umin(o, mx);
            let w = self.splat(word);
            *x = self.b.ins().iadd(o, w);
        }
        let first = self.b.ins().extractlane(idx[0], 0);
        let fs = self.b.ins().splat(I32X4, first);
        let mut same = self.b.ins().icmp(IntCC::Equal, idx[0], fs);
        for &x in &idx[1..] {
            let e = self.b.ins().icmp(IntCC::Equal, x, fs);
            same = self.b.ins().band(same, e);
        }
        let bits = self.b.ins().vhigh_bits(I32, same);
        let all = self.b.ins().icmp_imm_u(IntCC::Equal, bits, 0xf);
        let nv = self.b.ins().splat(I32X4, n);
        let zero = self.splat(0);
        let (one, many, merge) = (
            self.b.create_block(),
            self.b.create_block(),
            self.b.create_block(),
        );
        let params: Vec<Value> = (0..QUARTERS)
            .map(|_| self.b.append_block_param(merge, I32X4))
            .collect();
        self.b.ins().brif(all, one, &[], many, &[]);

        // No `ld` below: what the cache holds must be defined before the
        // branch.
        self.b.switch_to_block(one);
        let inside = self.b.ins().icmp(IntCC::UnsignedLessThan, first, n);
        let z = self.b.ins().iconst(I32, 0);
        let safe = self.b.ins().select(inside, first, z);
        let x = self.load_word(p, safe);
        let x = self.b.ins().select(inside, x, z);
        let v = self.b.ins().splat(I32X4, x);
        let args = [BlockArg::from(v); QUARTERS];
        self.b.ins().jump(merge, &args);

        self.b.switch_to_block(many);
        let mut args = Vec::with_capacity(QUARTERS);
        for &x in &idx {
            let inside = self.b.ins().icmp(IntCC::UnsignedLessThan, x, nv);
            let safe = self.b.ins().band(x, inside);
            let mut v = zero;
            for l in 0..4u8 {
                let i = self.b.ins().extractlane(safe, l);
                let w = self.load_word(p, i);
                v = self.b.ins().insertlane(v, w, l);
            }
            args.push(BlockArg::from(self.b.ins().band(v, inside)));
        }
        self.b.ins().jump(merge, &args);

        self.b.switch_to_block(merge);
        for (q, &v) in params.iter().enumerate() {
            let v = self.ftz_word(float, v);
            self.put(d, q, v, masked);
        }
    }

    /// Byte offsets in the file of lanes `4q..4q+4` of registers
    /// `base + min(off, max)` (I32X4); they fit: registers < 2^18.
    fn lane_addresses(&mut self, base: Reg, off: Reg, max: u32, q: usize) -> Value {
        let o = self.ld(off, q);
        let mx = self.splat(max);
        let o = self.b.ins().umin(o, mx);
        let o = self.b.ins().ishl_imm_u(o, 6);
        let l0 = (base as usize * 64 + q * 16) as u32;
        let lanes = self.vconst([l0, l0 + 4, l0 + 8, l0 + 12]);
        self.b.ins().iadd(o, lanes)
    }

    fn lane_pointer(&mut self, offsets: Value, l: u8) -> Value {
        let i = self.b.ins().extractlane(offsets, l);
        let i = self.b.ins().uextend(self.ptr, i);
        self.b.ins().iadd(self.regs, i)
    }

    /// Quarter `q` of `r[base + min(off, max)]` per lane.
    fn gather(&mut self, base: Reg, off: Reg, max: u32, q: usize) -> Value {
        self.flush_range(base, base.saturating_add(max));
        let at = self.lane_addresses(base, off, max, q);
        let mut v = self.splat(0);
        for l in 0..4u8 {
            let p = self.lane_pointer(at, l);
            let x = self.b.ins().load(I32, mem(), p, 0);
            v = self.b.ins().insertlane(v, x, l);
        }
        v
    }

    /// `r[base + min(off, max)] = a` on the current lanes of quarter `q`
    /// (each lane writes only its own lane of a register, so the lanes
    /// may go one after the other).
    fn scatter(&mut self, base: Reg, off: Reg, max: u32, a: Reg, q: usize) {
        let at = self.lane_addresses(base, off, max, q);
        let av = self.ld(a, q);
        let hi = base.saturating_add(max);
        self.flush_range(base, hi);
        self.forget(base, hi);
        let mk = self.b.use_var(self.mk[q]);
        for l in 0..4u8 {
            let p = self.lane_pointer(at, l);
            let old = self.b.ins().load(I32, mem(), p, 0);
            let x = self.b.ins().extractlane(av, l);
            let on = self.b.ins().extractlane(mk, l);
            let v = self.b.ins().select(on, x, old);
            self.b.ins().store(mem(), v, p, 0);
        }
    }

    /// `a(hi lane) - a(lo lane)` within each quad (a quarter is a quad),
    /// not flushed (as `engine::step`).
    fn quad_diff(&mut self, a: Reg, q: usize, hi: [u8; 4], lo: [u8; 4]) -> Value {
        let v = self.ld(a, q);
        let bytes = self.b.ins().bitcast(
            I8X16,
            MemFlagsData::new().with_endianness(Endianness::Little),
            v,
        );
        let pick = |b: &mut FunctionBuilder, src: [u8; 4]| {
            let m: Vec<u8> = src
                .iter()
                .flat_map(|&s| (0..4).map(move |k| 4 * s + k))
                .collect();
            let imm = b.func.dfg.immediates.push(ConstantData::from(m));
            let s = b.ins().shuffle(bytes, bytes, imm);
            b.ins().bitcast(
                F32X4,
                MemFlagsData::new().with_endianness(Endianness::Little),
                s,
            )
        };
        let h = pick(&mut self.b, hi);
        let l = pick(&mut self.b, lo);
        let r = self.b.ins().fsub(h, l);
        self.ftz(r)
    }

    // ---- ops -----------------------------------------------------------

    fn body(&mut self) -> Result<(), String> {
        let code = self.code;
        let n = code.ins.len();
        // Blocks start at jump targets and after jumps.
        let mut leader = vec![false; n + 1];
        leader[0] = true;
        leader[n] = true;
        for (i, ins) in code.ins.iter().enumerate() {
            if let Op::Jump { target } | Op::JumpIfNone { target } = ins.op {
                *leader
                    .get_mut(target as usize)
                    .ok_or("jump target out of range")? = true;
                leader[i + 1] = true;
            }
        }
        let blocks: Vec<Option<Block>> = leader
            .iter()
            .map(|&l| l.then(|| self.b.create_block()))
            .collect();
        let block = |i: usize| blocks[i].ok_or("no block at a jump target");

        // The prologue, when the run has no prepared pool.
        let flag = self
            .b
            .ins()
            .load(I32, mem(), self.ctx, offset_of!(Ctx, prologue) as i32);
        let pro = self.b.create_block();
        self.b.ins().brif(flag, pro, &[], block(0)?, &[]);
        self.b.switch_to_block(pro);
        for (i, &op) in code.prologue.iter().enumerate() {
            self.data(&Ins { op, masked: false }, PROLOGUE_OP | i as u32)?;
        }
        self.flush_all();
        self.b.ins().jump(block(0)?, &[]);

        let mut open = false;
        let mut i = 0;
        while let Some(ins) = code.ins.get(i) {
            if leader[i] {
                if open {
                    self.retire(None, i.checked_sub(1));
                    self.b.ins().jump(block(i)?, &[]);
                }
                self.b.switch_to_block(block(i)?);
                open = true;
            }
            if separable(ins) {
                let mut e = i + 1;
                while e < n && !leader[e] && code.ins.get(e).is_some_and(separable) {
                    e += 1;
                }
                self.quarter_by_quarter(i, e)?;
                i = e;
                continue;
            }
            match ins.op {
                Op::Jump { target } => {
                    self.retire(None, Some(i));
                    self.b.ins().jump(block(target as usize)?, &[]);
                    open = false;
                }
                Op::JumpIfNone { target } => {
                    self.retire(None, Some(i));
                    let cur = self.b.use_var(self.cur);
                    let (t, next) = (block(target as usize)?, block(i + 1)?);
                    self.b.ins().brif(cur, next, &[], t, &[]);
                    open = false;
                }
                Op::LoopIter => {
                    let it = self.b.use_var(self.iterations);
                    let it = self.b.ins().iadd_imm_s(it, 1);
                    self.b.def_var(self.iterations, it);
                    let over = self
                        .b
                        .ins()
                        .icmp(IntCC::UnsignedGreaterThan, it, self.budget);
                    let cont = self.b.create_block();
                    self.b
                        .ins()
                        .brif(over, self.fail, &[BlockArg::from(it)], cont, &[]);
                    self.b.switch_to_block(cont);
                }
                Op::SaveMask { slot } => {
                    let cur = self.b.use_var(self.cur);
                    let m = self.mask_var(slot)?;
                    self.b.def_var(m, cur);
                }
                Op::RestoreMask { slot } => {
                    let m = self.mask_var(slot)?;
                    let v = self.b.use_var(m);
                    self.set_cur(v);
                }
                Op::AndMask { c } => {
                    let (zero, ms) = self.zero_bits(c);
                    let cur = self.b.use_var(self.cur);
                    let cur = self.b.ins().band_not(cur, zero);
                    self.b.def_var(self.cur, cur);
                    for (q, m) in ms.into_iter().enumerate() {
                        let old = self.b.use_var(self.mk[q]);
                        let v = self.b.ins().band_not(old, m);
                        self.b.def_var(self.mk[q], v);
                    }
                }
                Op::AndNotMask { slot, c } => {
                    // cur = saved & (c == 0)
                    let (zero, _) = self.zero_bits(c);
                    let m = self.mask_var(slot)?;
                    let saved = self.b.use_var(m);
                    let cur = self.b.ins().band(saved, zero);
                    self.set_cur(cur);
                }
                Op::Kill { start, end } | Op::Discard { start, end } => {
                    let cur = self.b.use_var(self.cur);
                    if matches!(ins.op, Op::Discard { .. }) {
                        let d = self.b.use_var(self.discarded);
                        let d = self.b.ins().bor(d, cur);
                        self.b.def_var(self.discarded, d);
                    }
                    for m in self.kill_slots(start, end)? {
                        let v = self.b.use_var(m);
                        let v = self.b.ins().band_not(v, cur);
                        self.b.def_var(m, v);
                    }
                    let zero = self.b.ins().iconst(I32, 0);
                    self.set_cur(zero);
                }
                Op::SyncDiscard { start, end } => {
                    let gone = self.b.use_var(self.discarded);
                    for m in self.kill_slots(start, end)? {
                        let v = self.b.use_var(m);
                        let v = self.b.ins().band_not(v, gone);
                        self.b.def_var(m, v);
                    }
                    let cur = self.b.use_var(self.cur);
                    let cur = self.b.ins().band_not(cur, gone);
                    self.set_cur(cur);
                }
                Op::Call { .. } | Op::Ret { .. } => {
                    return Err("subroutine calls are interpreted".to_string())
                }
                _ => self.data(ins, i as u32)?,
            }
            i += 1;
        }
        let exit = block(n)?;
        if open {
            self.retire(None, n.checked_sub(1));
            self.b.ins().jump(exit, &[]);
        }
        self.b.switch_to_block(exit);
        let d = self.b.use_var(self.discarded);
        self.b
            .ins()
            .store(mem(), d, self.ctx, offset_of!(Ctx, discarded) as i32);
        let ok = self.b.ins().iconst(I32, 0);
        self.b.ins().return_(&[ok]);

        self.b.switch_to_block(self.fail);
        let it = self.b.block_params(self.fail)[0];
        self.b
            .ins()
            .store(mem(), it, self.ctx, offset_of!(Ctx, iterations) as i32);
        let one = self.b.ins().iconst(I32, 1);
        self.b.ins().return_(&[one]);
        Ok(())
    }

    /// Ops `s..e` (lane-wise, `separable`) one quarter at a time: all of
    /// them on lanes 0-3, then on 4-7, ...; each op's lanes depend only on
    /// the same lanes of its operands (derivatives: on its quad, which is a
    /// quarter), so the order computes the same bits, with a quarter of the
    /// values live at once. After each quarter its values are stored when
    /// live after op `e - 1`, and dropped. A run with masked writes is
    /// emitted twice, behind a test of the current mask: once for all
    /// [`crate::LANES`] lanes running (no blends: a masked write then writes
    /// every lane, the same bits), once with the blends.
    fn quarter_by_quarter(&mut self, s: usize, e: usize) -> Result<(), String> {
        let code = self.code;
        // Whether each op is the run's last writer of its destination.
        let mut last = vec![false; e.saturating_sub(s)];
        let mut seen = std::collections::HashSet::new();
        for j in (s..e).rev() {
            if let Some(ins) = code.ins.get(j) {
                let fx = crate::liveness::effects(&code.prog, &ins.op);
                if let ([(d, 1)], []) | ([], [(d, 1)]) =
                    (fx.full_defs.as_slice(), fx.partial_defs.as_slice())
                {
                    if seen.insert(*d) {
                        last[j - s] = true;
                    }
                }
            }
        }
        let masked = (s..e).any(|j| {
            code.ins
                .get(j)
                .is_some_and(|i| i.masked || matches!(i.op, Op::Store { .. }))
        });
        if !masked {
            return self.each_quarter(s, e, &last);
        }
        // Twice: without the blends of masked writes when every lane runs
        // (then a masked write writes every lane), and with them.
        let cur = self.b.use_var(self.cur);
        let all = self
            .b
            .ins()
            .icmp_imm_u(IntCC::Equal, cur, crate::interp::FULL as i64);
        let (fast, slow, join) = (
            self.b.create_block(),
            self.b.create_block(),
            self.b.create_block(),
        );
        self.b.ins().brif(all, fast, &[], slow, &[]);
        let held = self.cache.clone();
        self.b.switch_to_block(fast);
        self.full = true;
        let r = self.each_quarter(s, e, &last);
        self.full = false;
        r?;
        self.b.ins().jump(join, &[]);
        self.cache = held;
        self.b.switch_to_block(slow);
        self.each_quarter(s, e, &last)?;
        self.b.ins().jump(join, &[]);
        self.b.switch_to_block(join);
        Ok(())
    }

    /// [`Self::quarter_by_quarter`]'s passes; `last[j - s]`: op `j` is the
    /// run's last writer of its destination. Nothing is held after.
    fn each_quarter(&mut self, s: usize, e: usize, last: &[bool]) -> Result<(), String> {
        let code = self.code;
        for q in 0..QUARTERS {
            self.only = Some(q);
            for j in s..e {
                if let Some(ins) = code.ins.get(j) {
                    self.store_now = if last.get(j - s).copied().unwrap_or(false) {
                        e.checked_sub(1)
                    } else {
                        None
                    };
                    self.data(ins, j as u32)?;
                }
            }
            self.store_now = None;
            self.retire(Some(q), e.checked_sub(1));
        }
        self.only = None;
        Ok(())
    }

    /// A data op (no control flow); `index`: its index for `jit_step`.
    fn data(&mut self, ins: &Ins, index: u32) -> Result<(), String> {
        let m = ins.masked;
        macro_rules! each {
            ($d:expr, |$q:ident| $body:expr) => {{
                for $q in self.quarters() {
                    let v = $body;
                    self.put($d, $q, v, m);
                }
            }};
        }
        macro_rules! fbin {
            ($d:expr, $a:expr, $b:expr, $op:ident) => {
                each!($d, |q| {
                    let (x, y) = (self.ldf($a, q), self.ldf($b, q));
                    let r = self.b.ins().$op(x, y);
                    self.ftz(r)
                })
            };
        }
        macro_rules! ibin {
            ($d:expr, $a:expr, $b:expr, $op:ident) => {
                each!($d, |q| {
                    let (x, y) = (self.ld($a, q), self.ld($b, q));
                    self.b.ins().$op(x, y)
                })
            };
        }
        macro_rules! fcmp {
            ($d:expr, $a:expr, $b:expr, $cc:expr) => {
                each!($d, |q| {
                    let (x, y) = (self.ldf($a, q), self.ldf($b, q));
                    let c = self.b.ins().fcmp($cc, x, y);
                    self.bool01(c)
                })
            };
        }
        macro_rules! icmp {
            ($d:expr, $a:expr, $b:expr, $cc:expr) => {
                each!($d, |q| {
                    let (x, y) = (self.ld($a, q), self.ld($b, q));
                    let c = self.b.ins().icmp($cc, x, y);
                    self.bool01(c)
                })
            };
        }
        // Boolean ops on the "is zero" masks zx, zy: and = !(zx | zy),
        // or = !(zx & zy), xor = zx ^ zy.
        macro_rules! logic {
            ($d:expr, $a:expr, $b:expr, $op:ident, $negate:expr) => {
                each!($d, |q| {
                    let (x, y) = (self.ld($a, q), self.ld($b, q));
                    let (zx, zy) = (self.is_zero(x), self.is_zero(y));
                    let c = self.b.ins().$op(zx, zy);
                    let one = self.splat(1);
                    if $negate {
                        self.b.ins().band_not(one, c)
                    } else {
                        self.b.ins().band(c, one)
                    }
                })
            };
        }
        match ins.op {
            Op::Const { d, bits } => each!(d, |q| self.splat(bits)),
            Op::Mov { d, a } => each!(d, |q| self.ld(a, q)),
            Op::Store { d, a } => {
                for q in self.quarters() {
                    let v = self.ld(a, q);
                    self.put(d, q, v, true);
                }
            }
            Op::FAdd { d, a, b } => fbin!(d, a, b, fadd),
            Op::FSub { d, a, b } => fbin!(d, a, b, fsub),
            Op::FMul { d, a, b } => fbin!(d, a, b, fmul),
            Op::FDiv { d, a, b } => fbin!(d, a, b, fdiv),
            Op::FNeg { d, a } => each!(d, |q| {
                let x = self.ld(a, q);
                let s = self.splat(SIGN);
                self.b.ins().bxor(x, s)
            }),
            Op::FMac { d, a, b } => each!(d, |q| {
                let (x, y, acc) = (self.ldf(a, q), self.ldf(b, q), self.ldf(d, q));
                let p = self.b.ins().fmul(x, y);
                let p = self.fz(p);
                let s = self.b.ins().fadd(acc, p);
                self.ftz(s)
            }),
            Op::Dot { d, n, a, b } => each!(d, |q| {
                let mut acc = self.fconst(0.0);
                for k in 0..(n as usize).min(4) {
                    let (x, y) = (self.ldf(a[k], q), self.ldf(b[k], q));
                    let p = self.b.ins().fmul(x, y);
                    let p = self.fz(p);
                    let s = self.b.ins().fadd(acc, p);
                    acc = self.fz(s);
                }
                self.iv(acc)
            }),
            Op::F1 { f, d, a } => match F1_CALLED.iter().position(|&g| g == f) {
                Some(func) => self.call_math(false, func, d, a, a, m),
                None => each!(d, |q| {
                    let x = self.ldf(a, q);
                    self.f1(f, x)
                }),
            },
            Op::F2 { f, d, a, b } => match F2_CALLED.iter().position(|&g| g == f) {
                Some(func) => self.call_math(true, func, d, a, b, m),
                None => each!(d, |q| {
                    let (x, y) = (self.ldf(a, q), self.ldf(b, q));
                    self.f2(f, x, y)
                }),
            },
            Op::F3 { f, d, a, b, c } => each!(d, |q| {
                let (x, y, z) = (self.ldf(a, q), self.ldf(b, q), self.ldf(c, q));
                self.f3(f, x, y, z)
            }),
            Op::FLt { d, a, b } => fcmp!(d, a, b, FloatCC::LessThan),
            Op::FLe { d, a, b } => fcmp!(d, a, b, FloatCC::LessThanOrEqual),
            Op::FEq { d, a, b } => fcmp!(d, a, b, FloatCC::Equal),
            Op::IAdd { d, a, b } => ibin!(d, a, b, iadd),
            Op::ISub { d, a, b } => ibin!(d, a, b, isub),
            Op::IMul { d, a, b } => ibin!(d, a, b, imul),
            Op::INeg { d, a } => each!(d, |q| {
                let x = self.ld(a, q);
                self.b.ins().ineg(x)
            }),
            Op::ILt { d, a, b } => icmp!(d, a, b, IntCC::SignedLessThan),
            Op::ILe { d, a, b } => icmp!(d, a, b, IntCC::SignedLessThanOrEqual),
            Op::IEq { d, a, b } => icmp!(d, a, b, IntCC::Equal),
            Op::And { d, a, b } => logic!(d, a, b, bor, true),
            Op::Or { d, a, b } => logic!(d, a, b, band, true),
            Op::Xor { d, a, b } => logic!(d, a, b, bxor, false),
            Op::Not { d, a } => each!(d, |q| {
                let x = self.ld(a, q);
                let z = self.is_zero(x);
                self.bool01(z)
            }),
            Op::FToI { d, a } => each!(d, |q| {
                let x = self.ldf(a, q);
                self.b.ins().fcvt_to_sint_sat(I32X4, x)
            }),
            Op::IToF { d, a } => each!(d, |q| {
                let x = self.ld(a, q);
                let f = self.b.ins().fcvt_from_sint(F32X4, x);
                self.iv(f)
            }),
            Op::FToB { d, a } => each!(d, |q| {
                let x = self.ldf(a, q);
                let zero = self.fconst(0.0);
                // `!=` is true for NaN, as in Rust.
                let c = self.b.ins().fcmp(FloatCC::NotEqual, x, zero);
                self.bool01(c)
            }),
            Op::IToB { d, a } => each!(d, |q| {
                let x = self.ld(a, q);
                self.bool_of(x)
            }),
            Op::BToF { d, a } => each!(d, |q| {
                let x = self.ld(a, q);
                let z = self.is_zero(x);
                let one = self.splat(ONE);
                self.b.ins().band_not(one, z)
            }),
            Op::Select { d, c, a, b } => each!(d, |q| {
                let (cv, x, y) = (self.ld(c, q), self.ld(a, q), self.ld(b, q));
                let z = self.is_zero(cv);
                self.b.ins().bitselect(z, y, x)
            }),
            Op::ClampIdx { d, a, max, stride } if max <= i32::MAX as u32 => each!(d, |q| {
                let x = self.ld(a, q);
                let (lo, hi, s) = (self.splat(0), self.splat(max), self.splat(stride));
                let x = self.b.ins().smax(x, lo);
                let x = self.b.ins().smin(x, hi);
                self.b.ins().imul(x, s)
            }),
            Op::Uniform { d, word, float } => {
                let v = self.uniform_word(word);
                each!(d, |q| {
                    let v = self.b.ins().splat(I32X4, v);
                    self.ftz_word(float, v)
                })
            }
            Op::GatherUniform {
                d,
                word,
                off,
                max,
                float,
            } if word as u64 + max as u64 <= i32::MAX as u64 => {
                self.gather_uniform(d, word, off, max, float, m)
            }
            Op::Gather { d, base, off, max } => each!(d, |q| self.gather(base, off, max, q)),
            Op::Scatter { base, off, max, a } => {
                for q in 0..QUARTERS {
                    self.scatter(base, off, max, a, q)
                }
            }
            Op::DdX { d, a } => each!(d, |q| self.quad_diff(a, q, [1, 1, 3, 3], [0, 0, 2, 2])),
            Op::DdY { d, a } => each!(d, |q| self.quad_diff(a, q, [2, 3, 2, 3], [0, 1, 0, 1])),
            // Only hooked runs (the reference interpreter) print.
            Op::Printf { .. } => {}
            Op::Call { .. }
            | Op::Ret { .. }
            | Op::Jump { .. }
            | Op::JumpIfNone { .. }
            | Op::LoopIter
            | Op::SaveMask { .. }
            | Op::RestoreMask { .. }
            | Op::AndMask { .. }
            | Op::AndNotMask { .. }
            | Op::Kill { .. }
            | Op::Discard { .. }
            | Op::SyncDiscard { .. } => {
                return Err(format!("control op {:?} where data was expected", ins.op))
            }
            // Integer division, gathers, scatters, uniform reads outside
            // the prologue, derivatives, noise, texture lookups.
            _ => self.call_step(index),
        }
        Ok(())
    }

    /// The inline functions of one float (F32X4 in, I32X4 out).
    fn f1(&mut self, f: F1, x: Value) -> Value {
        match f {
            F1::Abs => {
                let xi = self.iv(x);
                let mag = self.splat(!SIGN);
                let a = self.b.ins().band(xi, mag);
                let a = self.fv(a);
                self.ftz(a)
            }
            // Neither result is ever subnormal (a square root is at least
            // 2^-74.5 when nonzero, 1/sqrt at least 2^-64), so they need no
            // flush.
            F1::Sqrt => {
                let r = self.b.ins().sqrt(x);
                self.iv(r)
            }
            F1::InverseSqrt => {
                let s = self.b.ins().sqrt(x);
                let one = self.fconst(1.0);
                let r = self.b.ins().fdiv(one, s);
                self.iv(r)
            }
            F1::Radians | F1::Degrees => {
                let k = if f == F1::Radians {
                    glsl::math::PI / 180.0
                } else {
                    180.0 / glsl::math::PI
                };
                let k = self.fconst(k);
                let r = self.b.ins().fmul(x, k);
                self.ftz(r)
            }
            F1::Sign => {
                let zero = self.fconst(0.0);
                let gt = self.b.ins().fcmp(FloatCC::GreaterThan, x, zero);
                let lt = self.b.ins().fcmp(FloatCC::LessThan, x, zero);
                let (one, minus) = (self.splat(ONE), self.splat((-1.0f32).to_bits()));
                let p = self.b.ins().band(gt, one);
                let n = self.b.ins().band(lt, minus);
                self.b.ins().bor(p, n)
            }
            F1::Floor => {
                let r = self.floor(x);
                self.ftz(r)
            }
            F1::Ceil => {
                let r = self.ceil(x);
                self.ftz(r)
            }
            F1::Fract => {
                let fl = self.floor(x);
                let r = self.b.ins().fsub(x, fl);
                self.ftz(r)
            }
            // The rest are calls (`F1_CALLED`).
            _ => self.splat(0),
        }
    }

    /// The inline functions of two floats.
    fn f2(&mut self, f: F2, x: Value, y: Value) -> Value {
        match f {
            F2::Min => {
                let r = self.fmin(x, y);
                self.ftz(r)
            }
            F2::Max => {
                let r = self.fmax(x, y);
                self.ftz(r)
            }
            F2::Step => {
                // step(edge = x, v = y): 0 if v < edge, else 1.
                let lt = self.b.ins().fcmp(FloatCC::LessThan, y, x);
                let one = self.splat(ONE);
                self.b.ins().band_not(one, lt)
            }
            F2::Mod => {
                let q = self.b.ins().fdiv(x, y);
                let q = self.fz(q);
                let fl = self.floor(q);
                let p = self.b.ins().fmul(y, fl);
                let r = self.b.ins().fsub(x, p);
                self.ftz(r)
            }
            // The rest are calls (`F2_CALLED`).
            _ => self.splat(0),
        }
    }

    /// The functions of three floats, as `engine::step` computes them.
    fn f3(&mut self, f: F3, x: Value, y: Value, z: Value) -> Value {
        match f {
            // glsl::math's formulas, with its flushed intermediates.
            F3::Mix => {
                let one = self.fconst(1.0);
                let omt = self.b.ins().fsub(one, z);
                let p = self.b.ins().fmul(x, omt);
                let p = self.fz(p);
                let r = self.b.ins().fmul(y, z);
                let r = self.fz(r);
                let s = self.b.ins().fadd(p, r);
                self.ftz(s)
            }
            F3::Clamp => {
                let t = self.fmax(x, y);
                let t = self.fmin(t, z);
                self.ftz(t)
            }
            F3::SmoothStep => {
                // (e0, e1, v) = (x, y, z)
                let num = self.b.ins().fsub(z, x);
                let num = self.fz(num);
                let den = self.b.ins().fsub(y, x);
                let den = self.fz(den);
                let t = self.b.ins().fdiv(num, den);
                let t = self.fz(t);
                let (zero, one) = (self.fconst(0.0), self.fconst(1.0));
                let t = self.fmax(t, zero);
                let t = self.fmin(t, one);
                let (two, three) = (self.fconst(2.0), self.fconst(3.0));
                let tt = self.b.ins().fmul(t, t);
                let tt = self.fz(tt);
                let t2 = self.b.ins().fmul(two, t);
                let k = self.b.ins().fsub(three, t2);
                let r = self.b.ins().fmul(tt, k);
                self.ftz(r)
            }
        }
    }
}
