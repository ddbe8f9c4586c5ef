//! The fast executor: a lowered [`Program`] rewritten once per kernel
//! ([`compile`]) and run over a reused register file ([`run`]).
//!
//! The rewrite keeps the program's meaning bit for bit (the reference is
//! `interp`, which `Kernel::run_traced` uses; tests compare the two):
//! - **Invariant hoisting**: constants, uniform words and pure data ops whose
//!   operands are all such values go to a *prologue* computing them once per
//!   run (or once per draw, [`crate::Prepared`]) into extra *pool*
//!   registers; later readers read the pool register instead. The original
//!   op stays where it was unless nothing reads it any more.
//! - **Dead code**: ops whose results nobody reads ([`crate::liveness`],
//!   with every output live at the end) are dropped.
//! - **Store fusion**: `t = op(...)` followed by `var = t` (a masked store,
//!   or a copy: stores in full flow become copies, [`crate::mask_flow`])
//!   with `t` dead afterwards becomes one op writing `var` (under the mask
//!   for a store).
//! - **Initialization**: only the registers live at the entry (read before
//!   written on some path) are zeroed at the start of a run.
//!
//! The interpreter loop indexes registers without bounds checks: every
//! register index of the rewritten program and prologue is checked once by
//! [`Program::validate`] when the kernel is built (a program that fails the
//! check runs unrewritten through the same checks).

use crate::interp::FULL;
use crate::liveness::{analyze, effects};
use crate::program::{Op, Program, Reg, TexLod, F1, F2, F3};
use crate::{Batch, ExecError, Kernel, LaneMask, Lod, SampleRequest, Textures, LANES};
use glsl::math;
use glsl::types::Scalar;
use std::cell::RefCell;
use std::collections::BTreeMap;

/// One instruction of the rewritten program: the op and whether its
/// destination is written under the current mask (fused store).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ins {
    pub op: Op,
    pub masked: bool,
}

/// A program ready for [`run`].
#[derive(Clone, Debug)]
pub(crate) struct Code {
    /// The rewritten program (its `registers` include the pool).
    pub prog: Program,
    pub ins: Vec<Ins>,
    /// Pure data ops filling the pool registers, in order.
    pub prologue: Vec<Op>,
    /// First pool register; the pool ends at `prog.registers`.
    pub pool_base: u32,
    /// Registers to zero at the start of a run.
    pub zero: Vec<Reg>,
    /// The output registers (live at the end of a run).
    pub live_out: Vec<Reg>,
}

/// Programs with more ops than this are run unrewritten (the analysis
/// would cost more than it saves).
const MAX_REWRITE_OPS: usize = 1 << 16;

/// Rewrites `p` (see the module docs); `live_out`: the output registers.
pub(crate) fn compile(p: &Program, live_out: &[Reg]) -> Code {
    if p.ops.len() <= MAX_REWRITE_OPS {
        if let Some(c) = rewrite(p, live_out) {
            return c;
        }
    }
    plain(p, live_out)
}

/// The program as it is, every register zeroed at the start.
fn plain(p: &Program, live_out: &[Reg]) -> Code {
    Code {
        prog: p.clone(),
        ins: p.ops.iter().map(|&op| Ins { op, masked: false }).collect(),
        prologue: Vec::new(),
        pool_base: p.registers,
        zero: (0..p.registers).collect(),
        live_out: live_out.to_vec(),
    }
}

fn leaders(ops: &[Op]) -> Vec<bool> {
    let n = ops.len();
    let mut leader = vec![false; n + 1];
    leader[0] = true;
    for (i, op) in ops.iter().enumerate() {
        match *op {
            Op::Jump { target } | Op::JumpIfNone { target } | Op::Call { target, .. } => {
                leader[(target as usize).min(n)] = true;
                leader[i + 1] = true;
            }
            Op::Ret { .. } => leader[i + 1] = true,
            _ => {}
        }
    }
    leader
}

/// Ops that compute every lane from their register operands alone (no
/// mask, no other lanes, no ranges), so they may run in the prologue.
pub(crate) fn pure(op: &Op) -> bool {
    !matches!(
        op,
        Op::Store { .. }
            | Op::Scatter { .. }
            | Op::Gather { .. }
            | Op::Noise { .. }
            | Op::Texture { .. }
            | Op::Printf { .. }
            | Op::DdX { .. }
            | Op::DdY { .. }
            | Op::FMac { .. }
            | Op::SaveMask { .. }
            | Op::RestoreMask { .. }
            | Op::AndMask { .. }
            | Op::AndNotMask { .. }
            | Op::JumpIfNone { .. }
            | Op::Jump { .. }
            | Op::LoopIter
            | Op::Kill { .. }
            | Op::Discard { .. }
            | Op::Call { .. }
            | Op::Ret { .. }
            | Op::SyncDiscard { .. }
    )
}

/// Replaces the single-register reads of `op` through `f` (ranges, the
/// accumulator of `FMac` and destinations are left alone). Returns whether
/// every read register was replaced by one satisfying `is_pool`.
fn map_reads(op: &mut Op, f: &mut dyn FnMut(Reg) -> Reg, is_pool: &dyn Fn(Reg) -> bool) -> bool {
    let mut all = true;
    let mut m = |r: &mut Reg| {
        *r = f(*r);
        all &= is_pool(*r);
    };
    use Op::*;
    match op {
        Const { .. } | Uniform { .. } => {}
        Mov { a, .. }
        | Store { a, .. }
        | FNeg { a, .. }
        | INeg { a, .. }
        | Not { a, .. }
        | FToI { a, .. }
        | IToF { a, .. }
        | FToB { a, .. }
        | IToB { a, .. }
        | BToF { a, .. }
        | DdX { a, .. }
        | DdY { a, .. }
        | F1 { a, .. }
        | ClampIdx { a, .. } => m(a),
        FAdd { a, b, .. }
        | FSub { a, b, .. }
        | FMul { a, b, .. }
        | FDiv { a, b, .. }
        | FMac { a, b, .. }
        | F2 { a, b, .. }
        | FLt { a, b, .. }
        | FLe { a, b, .. }
        | FEq { a, b, .. }
        | IAdd { a, b, .. }
        | ISub { a, b, .. }
        | IMul { a, b, .. }
        | IDiv { a, b, .. }
        | ILt { a, b, .. }
        | ILe { a, b, .. }
        | IEq { a, b, .. }
        | And { a, b, .. }
        | Or { a, b, .. }
        | Xor { a, b, .. } => {
            m(a);
            m(b)
        }
        F3 { a, b, c, .. } | Select { a, b, c, .. } => {
            m(a);
            m(b);
            m(c)
        }
        Dot { n, a, b, .. } => {
            for k in 0..(*n as usize).min(4) {
                m(&mut a[k]);
                m(&mut b[k]);
            }
        }
        Gather { off, .. } | GatherUniform { off, .. } => m(off),
        Scatter { off, a, .. } => {
            m(off);
            m(a)
        }
        AndMask { c } | AndNotMask { c, .. } => m(c),
        Noise { .. } | Texture { .. } => all = false,
        Printf { .. }
        | SaveMask { .. }
        | RestoreMask { .. }
        | JumpIfNone { .. }
        | Jump { .. }
        | LoopIter
        | Kill { .. }
        | Discard { .. }
        | Call { .. }
        | Ret { .. }
        | SyncDiscard { .. } => {}
    }
    all
}

fn set_dest(op: &mut Op, to: Reg) {
    use Op::*;
    match op {
        Const { d, .. }
        | Mov { d, .. }
        | Store { d, .. }
        | Uniform { d, .. }
        | FAdd { d, .. }
        | FSub { d, .. }
        | FMul { d, .. }
        | FDiv { d, .. }
        | FNeg { d, .. }
        | FMac { d, .. }
        | Dot { d, .. }
        | F1 { d, .. }
        | F2 { d, .. }
        | F3 { d, .. }
        | FLt { d, .. }
        | FLe { d, .. }
        | FEq { d, .. }
        | IAdd { d, .. }
        | ISub { d, .. }
        | IMul { d, .. }
        | IDiv { d, .. }
        | INeg { d, .. }
        | ILt { d, .. }
        | ILe { d, .. }
        | IEq { d, .. }
        | And { d, .. }
        | Or { d, .. }
        | Xor { d, .. }
        | Not { d, .. }
        | FToI { d, .. }
        | IToF { d, .. }
        | FToB { d, .. }
        | IToB { d, .. }
        | BToF { d, .. }
        | Select { d, .. }
        | ClampIdx { d, .. }
        | Gather { d, .. }
        | GatherUniform { d, .. }
        | DdX { d, .. }
        | DdY { d, .. } => *d = to,
        _ => {}
    }
}

/// The single full destination of a plain data op.
fn single_dest(p: &Program, op: &Op) -> Option<Reg> {
    if !pure(op) && !matches!(op, Op::Gather { .. } | Op::DdX { .. } | Op::DdY { .. }) {
        return None;
    }
    let e = effects(p, op);
    match (e.full_defs.as_slice(), e.partial_defs.is_empty()) {
        ([(d, 1)], true) => Some(*d),
        _ => None,
    }
}

fn rewrite(p: &Program, live_out: &[Reg]) -> Option<Code> {
    let n = p.ops.len();
    let leader = leaders(&p.ops);
    let pool_base = p.registers;
    let mut next = pool_base;
    let mut prologue = Vec::new();
    let mut consts: BTreeMap<u32, Reg> = BTreeMap::new();
    let mut words: BTreeMap<u32, Reg> = BTreeMap::new();
    let nregs = p.registers as usize;
    // known[r]: pool register holding what r holds now (u32::MAX: none).
    let mut known = vec![u32::MAX; nregs];
    let mut touched: Vec<Reg> = Vec::new();
    let mut ops = p.ops.clone();
    crate::mask_flow::unmask_stores(p, &mut ops);
    for i in 0..n {
        if leader[i] {
            for &r in &touched {
                known[r as usize] = u32::MAX;
            }
            touched.clear();
        }
        let op = &mut ops[i];
        let is_pool = |r: Reg| r >= pool_base;
        let all_pool = map_reads(
            op,
            &mut |r| match known.get(r as usize) {
                Some(&k) if k != u32::MAX => k,
                _ => r,
            },
            &is_pool,
        );
        let e = effects(p, op);
        let hoisted = match *op {
            Op::Const { bits, .. } => Some(*consts.entry(bits).or_insert_with(|| {
                let r = next;
                next += 1;
                prologue.push(Op::Const { d: r, bits });
                r
            })),
            Op::Uniform { word, float, .. } => Some(*words.entry(word).or_insert_with(|| {
                let r = next;
                next += 1;
                prologue.push(Op::Uniform { d: r, word, float });
                r
            })),
            _ if pure(op) && all_pool => {
                let r = next;
                next += 1;
                let mut h = *op;
                set_dest(&mut h, r);
                prologue.push(h);
                Some(r)
            }
            _ => None,
        };
        if next > crate::lower::MAX_REGISTERS {
            return None;
        }
        for &(r, c) in e.full_defs.iter().chain(&e.partial_defs) {
            for k in 0..c.max(1) {
                if let Some(x) = known.get_mut(r.saturating_add(k) as usize) {
                    *x = u32::MAX;
                }
            }
        }
        if let (Some(h), [(d, 1)]) = (hoisted, e.full_defs.as_slice()) {
            if let Some(x) = known.get_mut(*d as usize) {
                *x = h;
                touched.push(*d);
            }
        }
    }

    let live = analyze(p, &ops, next, live_out)?;
    // Store fusion: op i writes t, op i+1 is `Store { d: v, a: t }` in the
    // same block with t dead after it.
    let mut keep = live.keep.clone();
    // A copy (`Mov`, a store in full flow: `mask_flow`) fuses the same
    // way, unmasked.
    let mut new_dest: Vec<Option<(Reg, bool)>> = vec![None; n];
    for i in 0..n.saturating_sub(1) {
        if !keep[i] || !keep[i + 1] || leader[i + 1] {
            continue;
        }
        let (v, t, masked) = match ops[i + 1] {
            Op::Store { d, a } => (d, a, true),
            Op::Mov { d, a } => (d, a, false),
            _ => continue,
        };
        if live.store_source_dead[i + 1] && single_dest(p, &ops[i]) == Some(t) && v != t {
            new_dest[i] = Some((v, masked));
            keep[i + 1] = false;
        }
    }

    // Compact, remapping jump targets to the next kept op.
    let mut new_index = vec![0u32; n + 1];
    let mut count = 0u32;
    for i in 0..n {
        new_index[i] = count;
        if keep[i] {
            count += 1;
        }
    }
    new_index[n] = count;
    let remap = |t: u32| new_index[(t as usize).min(n)];
    let mut ins = Vec::with_capacity(count as usize);
    for i in 0..n {
        if !keep[i] {
            continue;
        }
        let mut op = match ops[i] {
            Op::Jump { target } => Op::Jump {
                target: remap(target),
            },
            Op::JumpIfNone { target } => Op::JumpIfNone {
                target: remap(target),
            },
            Op::Call { target, slot } => Op::Call {
                target: remap(target),
                slot,
            },
            other => other,
        };
        let masked = match new_dest[i] {
            Some((v, masked)) => {
                set_dest(&mut op, v);
                masked
            }
            None => false,
        };
        ins.push(Ins { op, masked });
    }
    let prog = Program {
        ops: ins.iter().map(|i| i.op).collect(),
        textures: p.textures.clone(),
        kill_slots: p.kill_slots.clone(),
        registers: next,
        mask_slots: p.mask_slots,
        subroutines: p.subroutines,
        init: p.init.clone(),
        statements: Vec::new(),
        vars: Vec::new(),
        printfs: p.printfs.clone(),
    };
    prog.validate().ok()?;
    let pro = Program {
        ops: prologue.clone(),
        ..prog.clone()
    };
    pro.validate().ok()?;
    let zero = (0..pool_base).filter(|&r| live.entry_live(r)).collect();
    Some(Code {
        prog,
        ins,
        prologue,
        pool_base,
        zero,
        live_out: live_out.to_vec(),
    })
}

// ---- running -----------------------------------------------------------

pub(crate) type Lanes = [u32; LANES];

thread_local! {
    /// The register file, reused across runs on this thread.
    pub(crate) static FILE: RefCell<Vec<Lanes>> = const { RefCell::new(Vec::new()) };
}

#[inline(always)]
fn f(x: u32) -> f32 {
    f32::from_bits(x)
}

use crate::lane::{self, flush as fz, flush_bits as ftz, max as fmax, min as fmin};
pub(crate) use crate::lane::{float_output, uniform_word};

/// `a` with its subnormals flushed ([`ftz`]).
pub(crate) fn flushed(a: &Lanes) -> Lanes {
    a.map(|x| ftz(f(x)))
}

#[inline(always)]
fn lanes(mut g: impl FnMut(usize) -> u32) -> Lanes {
    let mut o = [0u32; LANES];
    for (l, v) in o.iter_mut().enumerate() {
        *v = g(l);
    }
    o
}

/// Per-lane all-ones where `cur` has the lane.
#[inline(always)]
pub(crate) fn expand(cur: LaneMask) -> Lanes {
    lanes(|l| 0u32.wrapping_sub((cur >> l) & 1))
}

/// The value of every pool register for `uniforms` (the prologue's
/// results).
pub(crate) fn prepare(code: &Code, uniforms: &[u32]) -> Vec<Lanes> {
    let mut file = vec![[0u32; LANES]; code.prog.registers as usize];
    // SAFETY: `file` has `prog.registers` entries and the prologue was
    // validated against that count.
    unsafe { prologue(code, file.as_mut_ptr(), uniforms) };
    file.split_off(code.pool_base as usize)
}

/// # Safety
/// `regs` must point to `code.prog.registers` registers.
#[inline(always)]
pub(crate) unsafe fn prologue(code: &Code, regs: *mut Lanes, uniforms: &[u32]) {
    let mut masks = [0 as LaneMask; 0];
    let mut ret = [0u32; 0];
    let mut discarded = 0;
    let mut iterations = 0;
    for op in &code.prologue {
        let i = Ins {
            op: *op,
            masked: false,
        };
        let mut st = State {
            cur: FULL,
            mk: [!0; LANES],
            masks: &mut masks,
            ret: &mut ret,
            discarded: &mut discarded,
            iterations: &mut iterations,
        };
        // Pure data ops never jump or fail.
        let _ = step(
            code,
            regs,
            &i,
            0,
            &mut st,
            uniforms,
            &crate::NoTextures,
            u64::MAX,
        );
    }
}

struct State<'a> {
    cur: LaneMask,
    mk: Lanes,
    masks: &'a mut [LaneMask],
    ret: &'a mut [u32],
    discarded: &'a mut LaneMask,
    iterations: &'a mut u64,
}

/// Runs `k` (whose compiled code is `code`) on `batch`. `pool`: the
/// prepared pool registers, or `None` to run the prologue.
pub(crate) fn run(
    k: &Kernel,
    code: &Code,
    batch: &mut Batch,
    uniforms: &[u32],
    textures: &dyn Textures,
    pool: Option<&[Lanes]>,
) -> Result<(), ExecError> {
    run_on(
        crate::variant::current(),
        k,
        code,
        batch,
        uniforms,
        textures,
        pool,
    )
}

/// [`run`] with the given variant, which must be supported (else the
/// portable one runs).
pub(crate) fn run_on(
    variant: crate::Variant,
    k: &Kernel,
    code: &Code,
    batch: &mut Batch,
    uniforms: &[u32],
    textures: &dyn Textures,
    pool: Option<&[Lanes]>,
) -> Result<(), ExecError> {
    let variant = if variant.supported() {
        variant
    } else {
        crate::Variant::Portable
    };
    // Native code when the kernel has it (compiled on demand), else the
    // best interpreter.
    #[cfg(feature = "jit")]
    let native = match variant {
        // The kernel's cache holds the native code of its own `code`
        // (what every caller passes); any other code is interpreted.
        crate::Variant::Jit if std::ptr::eq(code, &*k.code) => k.jit.get_or_start(&k.code),
        _ => None,
    };
    let variant = match variant {
        crate::Variant::Jit => crate::variant::best_interpreter(),
        v => v,
    };
    FILE.with(|cell| {
        // A textures implementation that runs a kernel on this thread
        // finds the file borrowed: it then gets its own.
        let mut own;
        let mut guard;
        let file: &mut Vec<Lanes> = match cell.try_borrow_mut() {
            Ok(g) => {
                guard = g;
                &mut guard
            }
            Err(_) => {
                own = Vec::new();
                &mut own
            }
        };
        #[cfg(feature = "jit")]
        if let Some(n) = native {
            return crate::jit::run(n, k, code, file, batch, uniforms, textures, pool);
        }
        match variant {
            #[cfg(target_arch = "x86_64")]
            crate::Variant::Avx512 => {
                // SAFETY: checked supported above.
                unsafe { run_avx512(k, code, file, batch, uniforms, textures, pool) }
            }
            #[cfg(target_arch = "x86_64")]
            crate::Variant::Avx2 => {
                // SAFETY: as above.
                unsafe { run_avx2(k, code, file, batch, uniforms, textures, pool) }
            }
            _ => run_in(k, code, file, batch, uniforms, textures, pool),
        }
    })
}

/// [`run_in`] compiled for AVX2.
///
/// # Safety
/// The CPU must support AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn run_avx2(
    k: &Kernel,
    code: &Code,
    file: &mut Vec<Lanes>,
    batch: &mut Batch,
    uniforms: &[u32],
    textures: &dyn Textures,
    pool: Option<&[Lanes]>,
) -> Result<(), ExecError> {
    run_in(k, code, file, batch, uniforms, textures, pool)
}

/// [`run_in`] compiled for AVX-512 (F, BW, DQ, VL).
///
/// # Safety
/// The CPU must support those AVX-512 subsets.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512bw,avx512dq,avx512vl,avx2")]
unsafe fn run_avx512(
    k: &Kernel,
    code: &Code,
    file: &mut Vec<Lanes>,
    batch: &mut Batch,
    uniforms: &[u32],
    textures: &dyn Textures,
    pool: Option<&[Lanes]>,
) -> Result<(), ExecError> {
    run_in(k, code, file, batch, uniforms, textures, pool)
}

/// The interpreter proper; inlined into each CPU variant, which compile
/// the same IEEE operations (Rust never contracts `a * b + c` into a fused
/// multiply-add), so every variant computes the same bits.
#[inline(always)]
fn run_in(
    k: &Kernel,
    code: &Code,
    file: &mut Vec<Lanes>,
    batch: &mut Batch,
    uniforms: &[u32],
    textures: &dyn Textures,
    pool: Option<&[Lanes]>,
) -> Result<(), ExecError> {
    let regs = if load(k, code, file, batch, pool) {
        let regs = file.as_mut_ptr();
        // SAFETY: `load` gave the file `code.prog.registers` registers.
        unsafe { prologue(code, regs, uniforms) };
        regs
    } else {
        file.as_mut_ptr()
    };

    let mut masks = vec![0 as LaneMask; code.prog.mask_slots as usize];
    let mut ret = vec![0u32; code.prog.subroutines as usize];
    let start = (batch.active | batch.helper) & FULL;
    batch.discarded = 0;
    let mut discarded = 0;
    let mut iterations: u64 = 0;
    let mut st = State {
        cur: start,
        mk: expand(start),
        masks: &mut masks,
        ret: &mut ret,
        discarded: &mut discarded,
        iterations: &mut iterations,
    };
    let mut pc = 0usize;
    while let Some(i) = code.ins.get(pc) {
        // SAFETY: `regs` has `code.prog.registers` registers, against
        // which `code.ins` was validated.
        pc = unsafe {
            step(
                code,
                regs,
                i,
                pc,
                &mut st,
                uniforms,
                textures,
                k.loop_budget,
            )?
        };
    }
    batch.discarded = discarded;
    store_outputs(k, file, batch);
    Ok(())
}

/// Prepares `file` for a run of `code`: at least `code.prog.registers`
/// registers, the live-at-entry ones zeroed, initializers, inputs, and the
/// pool from `pool` when it fits. Returns whether the prologue still has to
/// fill the pool.
pub(crate) fn load(
    k: &Kernel,
    code: &Code,
    file: &mut Vec<Lanes>,
    batch: &Batch,
    pool: Option<&[Lanes]>,
) -> bool {
    load_inputs(k, code, file, batch);
    let nregs = code.prog.registers as usize;
    let pool_len = nregs - code.pool_base as usize;
    match pool {
        Some(values) if values.len() == pool_len => {
            file[code.pool_base as usize..nregs].copy_from_slice(values);
            false
        }
        _ => true,
    }
}

/// [`load`] without the pool: at least `code.prog.registers` registers,
/// the live-at-entry ones zeroed, initializers and inputs. Copies, exact
/// conversions and the flush of subnormal float inputs (integer selects):
/// compiled for the widest vectors the CPU has, the same values.
pub(crate) fn load_inputs(k: &Kernel, code: &Code, file: &mut Vec<Lanes>, batch: &Batch) {
    #[cfg(target_arch = "x86_64")]
    {
        use crate::cpu::{supports, Features};
        if supports(Features::AVX512F) {
            // SAFETY: the CPU has AVX-512 F.
            return unsafe { load_inputs_avx512(k, code, file, batch) };
        }
        if supports(Features::AVX2) {
            // SAFETY: the CPU has AVX2.
            return unsafe { load_inputs_avx2(k, code, file, batch) };
        }
    }
    load_inputs_with(k, code, file, batch)
}

/// [`load_inputs_with`] compiled for AVX2 (a register in two stores).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn load_inputs_avx2(k: &Kernel, code: &Code, file: &mut Vec<Lanes>, batch: &Batch) {
    load_inputs_with(k, code, file, batch)
}

/// [`load_inputs_with`] compiled for AVX-512 (a register in one store).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,avx512f")]
unsafe fn load_inputs_avx512(k: &Kernel, code: &Code, file: &mut Vec<Lanes>, batch: &Batch) {
    load_inputs_with(k, code, file, batch)
}

#[inline(always)]
fn load_inputs_with(k: &Kernel, code: &Code, file: &mut Vec<Lanes>, batch: &Batch) {
    let nregs = code.prog.registers as usize;
    if file.len() < nregs {
        file.resize(nregs, [0; LANES]);
    }
    for &r in &code.zero {
        if let Some(x) = file.get_mut(r as usize) {
            *x = [0; LANES];
        }
    }
    for &(reg, bits) in &code.prog.init {
        if let Some(x) = file.get_mut(reg as usize) {
            *x = [bits; LANES];
        }
    }
    for &(ic, reg, kind) in &k.inputs {
        let src = batch.inputs.get(ic).copied().unwrap_or([0.0; LANES]);
        if let Some(x) = file.get_mut(reg as usize) {
            *x = match kind {
                // Subnormal inputs enter as zero, as every float value.
                Scalar::Float => lanes(|l| ftz(src[l])),
                Scalar::Int => src.map(|v| v as i32 as u32),
                Scalar::Bool => src.map(|v| (v != 0.0) as u32),
            };
        }
    }
}

/// Copies the output registers of the active lanes into `batch.outputs`.
pub(crate) fn store_outputs(k: &Kernel, file: &[Lanes], batch: &mut Batch) {
    #[cfg(target_arch = "x86_64")]
    {
        use crate::cpu::{supports, Features};
        if supports(Features::AVX512F) {
            // SAFETY: the CPU has AVX-512 F.
            return unsafe { store_outputs_avx512(k, file, batch) };
        }
        if supports(Features::AVX2) {
            // SAFETY: the CPU has AVX2.
            return unsafe { store_outputs_avx2(k, file, batch) };
        }
    }
    store_outputs_with(k, file, batch)
}

/// [`store_outputs_with`] compiled for AVX2 (integer selects only: the
/// same bits).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn store_outputs_avx2(k: &Kernel, file: &[Lanes], batch: &mut Batch) {
    store_outputs_with(k, file, batch)
}

/// [`store_outputs_with`] compiled for AVX-512.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,avx512f")]
unsafe fn store_outputs_avx512(k: &Kernel, file: &[Lanes], batch: &mut Batch) {
    store_outputs_with(k, file, batch)
}

#[inline(always)]
fn store_outputs_with(k: &Kernel, file: &[Lanes], batch: &mut Batch) {
    // Discarded lanes' registers may hold anything (`mask_flow`).
    let active = batch.active & FULL & !batch.discarded;
    if batch.outputs.len() < k.interface.output_components {
        batch
            .outputs
            .resize(k.interface.output_components, [0.0; LANES]);
    }
    for &(reg, oc, kind) in &k.outputs {
        let Some(&src) = file.get(reg as usize) else {
            continue;
        };
        if let Some(dst) = batch.outputs.get_mut(oc) {
            // The kind chosen once per output, the lanes selected without
            // branches (so the loops vectorize).
            let value: Lanes = match kind {
                Scalar::Float => lanes(|l| float_output(src[l])),
                Scalar::Int => src.map(|x| (x as i32 as f32).to_bits()),
                Scalar::Bool => src.map(|x| ((x != 0) as u32 as f32).to_bits()),
            };
            for (l, v) in dst.iter_mut().enumerate() {
                let on = 0u32.wrapping_sub((active >> l) & 1);
                *v = f32::from_bits((value[l] & on) | (v.to_bits() & !on));
            }
        }
    }
}

/// Runs one data instruction (no jump, no mask change, no loop count) on
/// the lanes of `cur`: what native code calls for the ops it does not
/// compile itself, so they compute what the interpreter computes by
/// construction.
///
/// # Safety
/// As for [`step`]: `regs` must point to `code.prog.registers` registers
/// and `i` must be an instruction of `code.ins` or `code.prologue`.
pub(crate) unsafe fn step_data(
    code: &Code,
    regs: *mut Lanes,
    i: &Ins,
    cur: LaneMask,
    uniforms: &[u32],
    textures: &dyn Textures,
) {
    let mut masks = [0 as LaneMask; 0];
    let mut ret = [0u32; 0];
    let mut discarded = 0;
    let mut iterations = 0;
    let mut st = State {
        cur,
        mk: expand(cur),
        masks: &mut masks,
        ret: &mut ret,
        discarded: &mut discarded,
        iterations: &mut iterations,
    };
    // Data ops never jump or fail (the budget is not consulted).
    let _ = step(code, regs, i, 0, &mut st, uniforms, textures, u64::MAX);
}

/// Executes one instruction; returns the next pc.
///
/// # Safety
/// `regs` must point to `code.prog.registers` registers and `i` must be an
/// instruction validated against that count (part of `code.ins` or
/// `code.prologue`).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
unsafe fn step(
    code: &Code,
    regs: *mut Lanes,
    i: &Ins,
    pc: usize,
    st: &mut State,
    uniforms: &[u32],
    textures: &dyn Textures,
    budget: u64,
) -> Result<usize, ExecError> {
    macro_rules! g {
        ($r:expr) => {
            *regs.add($r as usize)
        };
    }
    let m = i.masked;
    let mk = st.mk;
    macro_rules! put {
        ($d:expr, $v:expr) => {{
            let v: Lanes = $v;
            let dst = &mut *regs.add($d as usize);
            if m {
                *dst = lanes(|l| (v[l] & mk[l]) | (dst[l] & !mk[l]));
            } else {
                *dst = v;
            }
        }};
    }
    macro_rules! un {
        ($d:expr, $a:expr, |$x:ident| $body:expr) => {{
            let a = g!($a);
            put!(
                $d,
                lanes(|l| {
                    let $x = a[l];
                    $body
                })
            )
        }};
    }
    macro_rules! bin {
        ($d:expr, $a:expr, $b:expr, |$x:ident, $y:ident| $body:expr) => {{
            let (a, b) = (g!($a), g!($b));
            put!(
                $d,
                lanes(|l| {
                    let ($x, $y) = (a[l], b[l]);
                    $body
                })
            )
        }};
    }
    macro_rules! tri {
        ($d:expr, $a:expr, $b:expr, $c:expr, |$x:ident, $y:ident, $z:ident| $body:expr) => {{
            let (a, b, c) = (g!($a), g!($b), g!($c));
            put!(
                $d,
                lanes(|l| {
                    let ($x, $y, $z) = (f(a[l]), f(b[l]), f(c[l]));
                    $body
                })
            )
        }};
    }
    let uni = |w: usize, float: bool| uniform_word(uniforms, w, float);
    let mut next = pc + 1;
    match i.op {
        Op::Const { d, bits } => put!(d, [bits; LANES]),
        Op::Mov { d, a } => put!(d, g!(a)),
        Op::Store { d, a } => {
            let a = g!(a);
            let dst = &mut *regs.add(d as usize);
            *dst = lanes(|l| (a[l] & mk[l]) | (dst[l] & !mk[l]));
        }
        Op::Uniform { d, word, float } => put!(d, [uni(word as usize, float); LANES]),
        Op::FAdd { d, a, b } => bin!(d, a, b, |x, y| lane::add(f(x), f(y)).to_bits()),
        Op::FSub { d, a, b } => bin!(d, a, b, |x, y| lane::sub(f(x), f(y)).to_bits()),
        Op::FMul { d, a, b } => bin!(d, a, b, |x, y| lane::mul(f(x), f(y)).to_bits()),
        Op::FDiv { d, a, b } => bin!(d, a, b, |x, y| lane::div(f(x), f(y)).to_bits()),
        Op::FNeg { d, a } => un!(d, a, |x| lane::neg(f(x)).to_bits()),
        Op::FMac { d, a, b } => {
            let (a, b, acc) = (g!(a), g!(b), g!(d));
            put!(d, lanes(|l| ftz(f(acc[l]) + f(ftz(f(a[l]) * f(b[l]))))))
        }
        Op::Dot { d, n, a, b } => {
            let mut acc = [0u32; LANES];
            for k in 0..(n as usize).min(4) {
                let (x, y) = (g!(a[k]), g!(b[k]));
                acc = lanes(|l| ftz(f(acc[l]) + f(ftz(f(x[l]) * f(y[l])))));
            }
            put!(d, acc)
        }
        Op::F1 { f: func, d, a } => {
            let a = g!(a);
            put!(d, f1(func, &a))
        }
        Op::F2 { f: func, d, a, b } => {
            let (a, b) = (g!(a), g!(b));
            put!(d, f2(func, &a, &b))
        }
        Op::F3 {
            f: func,
            d,
            a,
            b,
            c,
        } => match func {
            // The formulas of glsl::math, with its flushed intermediates.
            F3::Mix => tri!(d, a, b, c, |x, y, t| lane::mix(x, y, t).to_bits()),
            F3::Clamp => tri!(d, a, b, c, |x, lo, hi| lane::clamp(x, lo, hi).to_bits()),
            F3::SmoothStep => tri!(d, a, b, c, |e0, e1, x| {
                let t = fmin(fmax(fz(fz(x - e0) / fz(e1 - e0)), 0.0), 1.0);
                ftz(fz(t * t) * (3.0 - 2.0 * t))
            }),
        },
        Op::FLt { d, a, b } => bin!(d, a, b, |x, y| (f(x) < f(y)) as u32),
        Op::FLe { d, a, b } => bin!(d, a, b, |x, y| (f(x) <= f(y)) as u32),
        Op::FEq { d, a, b } => bin!(d, a, b, |x, y| (f(x) == f(y)) as u32),
        Op::IAdd { d, a, b } => bin!(d, a, b, |x, y| x.wrapping_add(y)),
        Op::ISub { d, a, b } => bin!(d, a, b, |x, y| x.wrapping_sub(y)),
        Op::IMul { d, a, b } => bin!(d, a, b, |x, y| x.wrapping_mul(y)),
        Op::IDiv { d, a, b } => bin!(d, a, b, |x, y| {
            if y == 0 {
                0
            } else {
                (x as i32).wrapping_div(y as i32) as u32
            }
        }),
        Op::INeg { d, a } => un!(d, a, |x| (x as i32).wrapping_neg() as u32),
        Op::ILt { d, a, b } => bin!(d, a, b, |x, y| ((x as i32) < (y as i32)) as u32),
        Op::ILe { d, a, b } => bin!(d, a, b, |x, y| ((x as i32) <= (y as i32)) as u32),
        Op::IEq { d, a, b } => bin!(d, a, b, |x, y| (x == y) as u32),
        Op::And { d, a, b } => bin!(d, a, b, |x, y| ((x != 0) & (y != 0)) as u32),
        Op::Or { d, a, b } => bin!(d, a, b, |x, y| ((x != 0) | (y != 0)) as u32),
        Op::Xor { d, a, b } => bin!(d, a, b, |x, y| ((x != 0) ^ (y != 0)) as u32),
        Op::Not { d, a } => un!(d, a, |x| (x == 0) as u32),
        Op::FToI { d, a } => un!(d, a, |x| glsl::consteval::float_to_int(f(x)) as u32),
        Op::IToF { d, a } => un!(d, a, |x| (x as i32 as f32).to_bits()),
        Op::FToB { d, a } => un!(d, a, |x| (f(x) != 0.0) as u32),
        Op::IToB { d, a } => un!(d, a, |x| (x != 0) as u32),
        Op::BToF { d, a } => un!(d, a, |x| if x != 0 { 1.0f32 } else { 0.0 }.to_bits()),
        Op::Select { d, c, a, b } => {
            let (c, a, b) = (g!(c), g!(a), g!(b));
            put!(d, lanes(|l| if c[l] != 0 { a[l] } else { b[l] }))
        }
        Op::ClampIdx { d, a, max, stride } => {
            un!(d, a, |x| ((x as i32).clamp(0, max as i32) as u32)
                .wrapping_mul(stride))
        }
        Op::Gather { d, base, off, max } => {
            let o = g!(off);
            let v = lanes(|l| (*regs.add((base + o[l].min(max)) as usize))[l]);
            put!(d, v)
        }
        Op::Scatter { base, off, max, a } => {
            let (o, a) = (g!(off), g!(a));
            for l in 0..LANES {
                if st.cur & (1 << l) != 0 {
                    (*regs.add((base + o[l].min(max)) as usize))[l] = a[l];
                }
            }
        }
        Op::GatherUniform {
            d,
            word,
            off,
            max,
            float,
        } => {
            let o = g!(off);
            put!(
                d,
                lanes(|l| uni(word as usize + o[l].min(max) as usize, float))
            )
        }
        // Operands read flushed, as in texture lookups (see `floats`).
        Op::DdX { d, a } => {
            let a = g!(a);
            put!(d, lanes(|l| ftz(fz(f(a[l | 1])) - fz(f(a[l & !1])))))
        }
        Op::DdY { d, a } => {
            let a = g!(a);
            put!(d, lanes(|l| ftz(fz(f(a[l | 2])) - fz(f(a[l & !2])))))
        }
        Op::Noise { d, n, a, dims } => {
            let mut out = [[0u32; LANES]; 4];
            #[allow(clippy::needless_range_loop)]
            for l in 0..LANES {
                let mut x = [0f32; 4];
                for (k, xk) in x.iter_mut().enumerate().take(dims as usize) {
                    *xk = fz(f(g!(a + k as u32)[l]));
                }
                let x = &x[..(dims as usize).min(4)];
                let v: [f32; 4] = match n {
                    1 => [math::noise1(x), 0.0, 0.0, 0.0],
                    2 => {
                        let v = math::noise2(x);
                        [v[0], v[1], 0.0, 0.0]
                    }
                    3 => {
                        let v = math::noise3(x);
                        [v[0], v[1], v[2], 0.0]
                    }
                    _ => math::noise4(x),
                };
                for k in 0..4 {
                    out[k][l] = ftz(v[k]);
                }
            }
            for (k, o) in out.iter().enumerate().take(n as usize) {
                *regs.add(d as usize + k) = *o;
            }
        }
        Op::Texture { index } => {
            if let Some(t) = code.prog.textures.get(index as usize) {
                texture(regs, t, st.cur, textures);
            }
        }
        // Only hooked runs (the reference interpreter) print.
        Op::Printf { .. } => {}
        Op::SaveMask { slot } => st.masks[slot as usize] = st.cur,
        Op::RestoreMask { slot } => {
            st.cur = st.masks[slot as usize];
            st.mk = expand(st.cur);
        }
        Op::AndMask { c } => {
            let c = g!(c);
            for (l, &v) in c.iter().enumerate() {
                if v == 0 {
                    st.cur &= !(1 << l);
                }
            }
            st.mk = expand(st.cur);
        }
        Op::AndNotMask { slot, c } => {
            let c = g!(c);
            st.cur = st.masks[slot as usize];
            for (l, &v) in c.iter().enumerate() {
                if v != 0 {
                    st.cur &= !(1 << l);
                }
            }
            st.mk = expand(st.cur);
        }
        Op::JumpIfNone { target } => {
            if st.cur == 0 {
                next = target as usize;
            }
        }
        Op::Jump { target } => next = target as usize,
        Op::LoopIter => {
            *st.iterations += 1;
            if *st.iterations > budget {
                return Err(ExecError::LoopBudget {
                    iterations: *st.iterations,
                });
            }
        }
        Op::Call { target, slot } => {
            st.ret[slot as usize] = next as u32;
            next = target as usize;
        }
        Op::Ret { slot } => next = st.ret[slot as usize] as usize,
        Op::SyncDiscard { start, end } => {
            let gone = *st.discarded;
            for &s in &code.prog.kill_slots[start as usize..end as usize] {
                st.masks[s as usize] &= !gone;
            }
            st.cur &= !gone;
            st.mk = expand(st.cur);
        }
        Op::Kill { start, end } | Op::Discard { start, end } => {
            if matches!(i.op, Op::Discard { .. }) {
                *st.discarded |= st.cur;
            }
            for &s in &code.prog.kill_slots[start as usize..end as usize] {
                st.masks[s as usize] &= !st.cur;
            }
            st.cur = 0;
            st.mk = [0; LANES];
        }
    }
    Ok(next)
}

/// `body` for every lane `l`, written as a plain loop rather than through
/// [`lanes`]' closure: LLVM leaves a closure this big un-inlined (a call per
/// lane, compiled for the baseline instruction set), while the loop is
/// inlined into each CPU variant and vectorized there. For the
/// branch-free `glsl::math` functions (`exp`, `exp2`, `log`, `log2`,
/// `pow`).
macro_rules! lane_loop {
    (|$l:ident| $body:expr) => {{
        let mut o = [0u32; LANES];
        for ($l, v) in o.iter_mut().enumerate() {
            *v = $body;
        }
        o
    }};
}

#[inline(always)]
pub(crate) fn f1(func: F1, a: &Lanes) -> Lanes {
    macro_rules! each {
        (|$x:ident| $body:expr) => {
            lanes(|l| {
                let $x = f(a[l]);
                $body
            })
        };
    }
    match func {
        F1::Abs => lanes(|l| ftz(f(a[l] & 0x7fff_ffff))),
        F1::Sqrt => each!(|x| ftz(x.sqrt())),
        F1::InverseSqrt => each!(|x| ftz(1.0 / x.sqrt())),
        F1::Radians => each!(|x| ftz(x * (math::PI / 180.0))),
        F1::Degrees => each!(|x| ftz(x * (180.0 / math::PI))),
        F1::Sign => each!(|x| if x > 0.0 {
            1.0f32.to_bits()
        } else if x < 0.0 {
            (-1.0f32).to_bits()
        } else {
            0
        }),
        F1::Floor => each!(|x| ftz(floor(x))),
        F1::Ceil => each!(|x| ftz(ceil(x))),
        F1::Fract => each!(|x| ftz(x - floor(x))),
        F1::Exp => lane_loop!(|l| lane::exp(f(a[l])).to_bits()),
        F1::Exp2 => lane_loop!(|l| ftz(math::exp2(f(a[l])))),
        F1::Log => lane_loop!(|l| ftz(math::log(f(a[l])))),
        F1::Log2 => lane_loop!(|l| ftz(math::log2(f(a[l])))),
        other => each!(|x| ftz(other.eval(x))),
    }
}

#[inline(always)]
pub(crate) fn f2(func: F2, a: &Lanes, b: &Lanes) -> Lanes {
    macro_rules! each {
        (|$x:ident, $y:ident| $body:expr) => {
            lanes(|l| {
                let ($x, $y) = (f(a[l]), f(b[l]));
                $body
            })
        };
    }
    match func {
        F2::Min => each!(|x, y| ftz(fmin(x, y))),
        F2::Max => each!(|x, y| ftz(fmax(x, y))),
        F2::Step => each!(|e, x| if x < e { 0 } else { 1.0f32.to_bits() }),
        F2::Mod => each!(|x, y| ftz(x - y * floor(fz(x / y)))),
        F2::Pow => lane_loop!(|l| ftz(math::pow(f(a[l]), f(b[l])))),
        other => each!(|x, y| ftz(other.eval(x, y))),
    }
}

/// `floor` without a library call: exact for every `f32` (the same bits as
/// `glsl::math::floor`).
#[inline(always)]
pub(crate) fn floor(x: f32) -> f32 {
    // |x| >= 2^23 (and inf, NaN): already integral.
    if x.abs() >= 8_388_608.0 || x.is_nan() {
        return x;
    }
    let t = x as i32 as f32;
    let r = if t > x { t - 1.0 } else { t };
    // A zero result keeps the sign of x (floor(-0.0) = -0.0).
    f32::from_bits(r.to_bits() | (x.to_bits() & 0x8000_0000 & (((r == 0.0) as u32) << 31)))
}

/// `ceil` without a library call (the same bits as `glsl::math::ceil`).
#[inline(always)]
pub(crate) fn ceil(x: f32) -> f32 {
    if x.abs() >= 8_388_608.0 || x.is_nan() {
        return x;
    }
    let t = x as i32 as f32;
    let r = if t < x { t + 1.0 } else { t };
    f32::from_bits(r.to_bits() | (x.to_bits() & 0x8000_0000 & (((r == 0.0) as u32) << 31)))
}

/// The lanes of `a` as floats, subnormals read as zero (operands of the
/// lookups native code calls back for may be unflushed: see `jit`).
fn floats(a: &Lanes) -> [f32; LANES] {
    a.map(|x| fz(f(x)))
}

/// # Safety
/// `regs` must hold every register `t` names (validated).
unsafe fn texture(
    regs: *mut Lanes,
    t: &crate::program::TexOp,
    cur: LaneMask,
    textures: &dyn Textures,
) {
    // SAFETY: the caller's contract: each register `t` names is in
    // `regs` (a reference to one, read while no register is written).
    let reg = |x: Reg| -> &Lanes { unsafe { &*regs.add(x as usize) } };
    let mut out = [[0f32; LANES]; 4];
    if cur != 0 {
        // Built in place, then filled: the request is large, and building
        // its parts apart and moving them in cost copies of each.
        let mut req = SampleRequest {
            unit: *reg(t.unit),
            target: t.target,
            coord: [[0.0; LANES]; 4],
            compare: None,
            lod: match t.lod {
                TexLod::Explicit(_) => Lod::Explicit([0.0; LANES]),
                TexLod::Implicit { .. } => Lod::Derivatives {
                    ddx: [[0.0; LANES]; 3],
                    ddy: [[0.0; LANES]; 3],
                    bias: [0.0; LANES],
                },
            },
            mask: cur,
        };
        for (c, &x) in req.coord.iter_mut().zip(&t.coord) {
            *c = floats(reg(x));
        }
        if let Some(c) = t.compare {
            req.compare = Some(floats(reg(c)));
        }
        match (&mut req.lod, t.lod) {
            (Lod::Explicit(v), TexLod::Explicit(Some(l))) => *v = floats(reg(l)),
            (Lod::Derivatives { ddx, ddy, bias }, TexLod::Implicit { bias: b }) => {
                for k in 0..(t.dims as usize).min(3) {
                    (ddx[k], ddy[k]) = lane::quad_diffs(&req.coord[k]);
                }
                if let Some(b) = b {
                    *bias = floats(reg(b));
                }
            }
            _ => {}
        }
        textures.sample(&req, &mut out);
    }
    for (k, o) in out.iter().enumerate() {
        // Subnormal results (a border colour, say) enter as zero.
        *regs.add(t.d as usize + k) = o.map(ftz);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glsl::math::flush_denormal;

    #[test]
    fn quad_diffs_are_the_lane_differences() {
        for a in inputs(64, 0x51de) {
            let (dx, dy) = crate::lane::quad_diffs(&floats(&a));
            for l in 0..LANES {
                let want = |bit: usize| (fz(f(a[l | bit])) - fz(f(a[l & !bit]))).to_bits();
                assert_eq!(dx[l].to_bits(), want(1), "{a:x?} lane {l}");
                assert_eq!(dy[l].to_bits(), want(2), "{a:x?} lane {l}");
            }
        }
    }

    /// Special values and random bit patterns (xorshift), 16 at a time.
    fn inputs(count: usize, seed: u64) -> Vec<Lanes> {
        let specials = [
            0.0f32,
            -0.0,
            1.0,
            -1.0,
            0.5,
            -0.5,
            1.5,
            -1.5,
            2.5,
            -2.5,
            8_388_607.5,
            -8_388_607.5,
            8_388_608.0,
            16_777_217.0,
            -16_777_216.0,
            1e-45,
            -1e-45,
            1.1754942e-38,
            f32::MIN_POSITIVE,
            f32::MAX,
            f32::MIN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            -f32::NAN,
            0.99999994,
            -0.99999994,
            1e30,
            -1e-30,
            3.0,
            100.25,
            -7.75,
        ];
        let mut s = seed;
        let mut out = vec![
            lanes(|l| specials[l].to_bits()),
            lanes(|l| specials[16 + l].to_bits()),
        ];
        while out.len() < count {
            out.push(lanes(|_| {
                s ^= s << 13;
                s ^= s >> 7;
                s ^= s << 17;
                // Half the lanes in a moderate range, half any bits.
                if s & 1 == 0 {
                    (((s >> 8) as u32 as f32) / 4e8 - 5.0).to_bits()
                } else {
                    (s >> 16) as u32
                }
            }));
        }
        out
    }

    /// The flushed bits of `x`, a NaN as the canonical one: inside a run a
    /// NaN's payload depends on operand order (see [`float_output`]).
    fn want(x: f32) -> u32 {
        float_output(flush_denormal(x).to_bits())
    }

    #[test]
    fn inline_math_matches_glsl_math_bit_for_bit() {
        let a = inputs(70_000, 1);
        let b = inputs(70_000, 2);
        let c = inputs(70_000, 3);
        let one = [
            F1::Abs,
            F1::Sqrt,
            F1::InverseSqrt,
            F1::Radians,
            F1::Degrees,
            F1::Sign,
            F1::Floor,
            F1::Ceil,
            F1::Fract,
            F1::Exp,
            F1::Exp2,
            F1::Log,
            F1::Log2,
        ];
        let two = [F2::Min, F2::Max, F2::Step, F2::Mod, F2::Pow];
        let three = [F3::Clamp, F3::Mix, F3::SmoothStep];
        // Every pairing of specials with specials, then random vectors
        // (70,000 x 16 lanes = 1.1 million inputs per function).
        for i in 0..a.len() {
            let (x, y, z) = (&a[i], &b[(i * 7) % b.len()], &c[(i * 13) % c.len()]);
            for func in one {
                let got = f1(func, x);
                for l in 0..LANES {
                    let got = float_output(got[l]);
                    assert_eq!(got, want(func.eval(f(x[l]))), "{func:?}({:e})", f(x[l]));
                }
            }
            for func in two {
                let got = f2(func, x, y);
                for l in 0..LANES {
                    let got = float_output(got[l]);
                    assert_eq!(got, want(func.eval(f(x[l]), f(y[l]))), "{func:?}");
                }
            }
            for func in three {
                // The F3 arms are inlined in `step`: run them as an op.
                let code = plain(
                    &Program {
                        ops: vec![Op::F3 {
                            f: func,
                            d: 3,
                            a: 0,
                            b: 1,
                            c: 2,
                        }],
                        registers: 4,
                        ..Program::default()
                    },
                    &[3],
                );
                let mut regs = [*x, *y, *z, [0; LANES]];
                let mut st_masks = [0; 0];
                let mut st_ret = [0; 0];
                let (mut disc, mut it) = (0, 0);
                let mut st = State {
                    cur: FULL,
                    mk: [!0; LANES],
                    masks: &mut st_masks,
                    ret: &mut st_ret,
                    discarded: &mut disc,
                    iterations: &mut it,
                };
                // SAFETY: 4 registers, the op names registers 0..4.
                unsafe {
                    step(
                        &code,
                        regs.as_mut_ptr(),
                        &code.ins[0],
                        0,
                        &mut st,
                        &[],
                        &crate::NoTextures,
                        0,
                    )
                    .unwrap();
                }
                for l in 0..LANES {
                    assert_eq!(
                        float_output(regs[3][l]),
                        want(func.eval(f(x[l]), f(y[l]), f(z[l]))),
                        "{func:?}({:x}, {:x}, {:x})",
                        x[l],
                        y[l],
                        z[l]
                    );
                }
            }
        }
    }

    #[test]
    fn branchless_flush_matches_flush_denormal() {
        for v in inputs(20_000, 9) {
            for x in v {
                assert_eq!(ftz(f(x)), flush_denormal(f(x)).to_bits());
            }
        }
    }
}
