//! Cranelift IR for a [`Code`]: one function `fn(*mut Ctx) -> u32`.
//!
//! This file: the code generator's set-up ([`isa`], [`compile`]), the
//! emitter's state ([`Emit`]) and the control flow (blocks, masks, loops,
//! runs of lane-wise ops emitted quarter by quarter). [`regs`]: register
//! values in memory and in SSA; [`ops`]: one data op; [`math`]: inline
//! lane arithmetic; [`texture`]: texture ops and native texel fetches.

mod math;
mod ops;
mod regs;
mod texture;

use super::PROLOGUE_OP;
use super::{Const16, Ctx, Entry, Native, F1_CALLED, F2_CALLED, MAX_OPS};
use crate::opt::{Code, Ins};
use crate::program::{Op, Reg};
use cranelift_codegen::ir::condcodes::IntCC;
use cranelift_codegen::ir::types::{I32, I32X4, I64};
use cranelift_codegen::ir::{
    AbiParam, Block, BlockArg, InstBuilder, MemFlagsData, SigRef, Signature, Type, UserFuncName,
    Value,
};
use cranelift_codegen::isa::OwnedTargetIsa;
use cranelift_codegen::settings::{self, Configurable};
use cranelift_frontend::{FunctionBuilder, FunctionBuilderContext, Variable};
use cranelift_jit::{JITBuilder, JITModule};
use cranelift_module::{default_libcall_names, Linkage, Module};
use std::mem::offset_of;

use regs::{Cache, Consts};

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
        // Stores to memory skip a fragment batch's helper lanes, which
        // the interpreter knows of and native code does not.
        if i.op.touches_memory() {
            return Err("memory accesses are interpreted".to_string());
        }
    }
    let mut daz = super::daz();
    let isa = isa()?;
    let mut module = JITModule::new(JITBuilder::with_isa(isa.clone(), default_libcall_names()));
    let mut r = define(&mut module, code, daz);
    // Setting and resetting DAZ around a run waits for the operations in
    // flight twice; code that relies on it in few places (each a 4-lane
    // flush of a few instructions otherwise) and calls no math helper
    // (which would switch the environment) runs faster without it.
    if let Ok((_, _, _, uses)) = &r {
        if daz && uses.math_calls == 0 && uses.daz_flushes <= NO_DAZ_FLUSHES {
            // SAFETY: nothing of the module was handed out.
            unsafe { module.free_memory() };
            module = JITModule::new(JITBuilder::with_isa(isa, default_libcall_names()));
            daz = false;
            r = define(&mut module, code, daz);
        }
    }
    match r {
        Ok((id, bytes, consts, _)) => {
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
                daz,
            })
        }
        Err(e) => {
            // SAFETY: as above.
            unsafe { module.free_memory() };
            Err(e)
        }
    }
}

/// Flush sites (4 lanes each) up to which code runs without DAZ
/// ([`compile`]): an estimate, about 64 × 4 instructions against the two
/// MXCSR writes of a run. core-itex (3 float uniform gathers, 12 sites)
/// measured faster without DAZ; no scene near the bound was measured.
const NO_DAZ_FLUSHES: u32 = 64;

/// What compiled code relies on, for [`compile`]'s choice of DAZ.
#[derive(Clone, Copy, Debug, Default)]
struct Uses {
    /// 4-lane flushes left out because DAZ does them.
    daz_flushes: u32,
    /// Calls of the math helpers (`jit_f1`, `jit_f2`).
    math_calls: u32,
}

/// A defined function: its id, code size, constants and [`Uses`].
type Defined = (cranelift_module::FuncId, usize, Box<[Const16]>, Uses);

/// Defines the function (for DAZ when `daz`).
fn define(module: &mut JITModule, code: &Code, daz: bool) -> Result<Defined, String> {
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
    let (consts, uses) = {
        let b = FunctionBuilder::new(&mut ctx.func, &mut fctx);
        let mut e = Emit::new(b, module, code, ptr, daz);
        e.after = live_after(code);
        e.body()?;
        e.b.seal_all_blocks();
        e.b.finalize(module.target_config());
        (e.consts.table, e.uses)
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
    Ok((id, bytes, consts, uses))
}

/// The divisors of `code.ins`'s integer divisions that are pool registers
/// (one value on every lane: computed from constants and uniforms), with
/// whether the division is signed.
fn pool_divisors(code: &Code) -> std::collections::BTreeSet<(Reg, bool)> {
    code.ins
        .iter()
        .filter_map(|i| match i.op {
            Op::IDiv { b, .. } | Op::IMod { b, .. } => Some((b, true)),
            Op::UDiv { b, .. } | Op::UMod { b, .. } => Some((b, false)),
            _ => None,
        })
        .filter(|&(b, _)| b >= code.pool_base && b < code.prog.registers)
        .collect()
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
                // `jit_texture` reads registers where they are.
                | Op::Texture { .. }
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
    sig_texture: SigRef,
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
    /// What the code relies on so far.
    uses: Uses,
    /// Emitting the prologue, which computes for every lane.
    prologue: bool,
    /// The integer divisors of the body held in pool registers (one
    /// value on every lane), by register and signedness: their
    /// [`math::Divisor`], computed once between the prologue and the
    /// body (empty while the prologue is emitted).
    divisors: std::collections::HashMap<(Reg, bool), math::Divisor>,
}

/// Data ops emitted inline whose lanes `4q..4q + 4` of the result depend
/// only on lanes `4q..4q + 4` of their operands and of the mask, with no
/// call, branch or memory access besides their registers' (and uniform
/// words).
fn separable(ins: &Ins) -> bool {
    match ins.op {
        Op::F1 { f, .. } => !F1_CALLED.contains(&f),
        Op::F2 { f, .. } => !F2_CALLED.contains(&f),
        Op::ClampIdx { max, .. } => max <= i32::MAX as u32,
        Op::IDiv { .. } | Op::IMod { .. } | Op::UDiv { .. } | Op::UMod { .. } => true,
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
        | Op::ULt { .. }
        | Op::ULe { .. }
        | Op::Shl { .. }
        | Op::ShrS { .. }
        | Op::ShrU { .. }
        | Op::BitAnd { .. }
        | Op::BitOr { .. }
        | Op::BitXor { .. }
        | Op::BitNot { .. }
        | Op::FToU { .. }
        | Op::UToF { .. }
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
    fn new(
        mut b: FunctionBuilder<'b>,
        module: &JITModule,
        code: &'a Code,
        ptr: Type,
        daz: bool,
    ) -> Self {
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
        let mut texture = helper_sig(module, ptr, &[I64, I32, I32]);
        texture.returns.push(AbiParam::new(I32));
        let sig_texture = b.import_signature(texture);
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
            sig_texture,
            fail,
            cache: Cache::default(),
            only: None,
            after: Vec::new(),
            consts: Consts::default(),
            store_now: None,
            full: false,
            daz,
            uses: Uses::default(),
            prologue: false,
            divisors: Default::default(),
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
        let ready = self.b.create_block();
        self.b.ins().brif(flag, pro, &[], ready, &[]);
        self.b.switch_to_block(pro);
        self.prologue = true;
        for (i, &op) in code.prologue.iter().enumerate() {
            self.data(&Ins { op, masked: false }, PROLOGUE_OP | i as u32)?;
        }
        self.prologue = false;
        self.flush_all();
        self.b.ins().jump(ready, &[]);
        // The pool is ready: what the body's divisions by pool registers
        // need, once (this block dominates the body).
        self.b.switch_to_block(ready);
        for (r, signed) in pool_divisors(code) {
            let d = self.divisor(r, signed);
            self.divisors.insert((r, signed), d);
        }
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
}
