//! The optimizer: a lowered [`Program`] rewritten once per kernel
//! ([`optimize`]) into the [`Code`] the executors run (`engine`'s
//! interpreter, `jit`'s native code).
//!
//! The rewrite keeps the program's meaning bit for bit (the reference is
//! `interp`, which `Kernel::run_traced` uses; tests compare the two):
//! - **Invariant hoisting**: constants, uniform words and pure data ops whose
//!   operands are all such values go to a *prologue* computing them once per
//!   run (or once per draw, [`crate::Prepared`]) into extra *pool*
//!   registers; later readers read the pool register instead. The original
//!   op stays where it was unless nothing reads it any more. Size queries
//!   (`textureSize`) of such a unit and level are hoisted the same way:
//!   the prologue runs with the run's textures.
//! - **Dead code**: ops whose results nobody reads ([`crate::liveness`],
//!   with every output live at the end) are dropped.
//! - **Store fusion**: `t = op(...)` followed by `var = t` (a masked store,
//!   or a copy: stores in full flow become copies, [`mask_flow`])
//!   with `t` dead afterwards becomes one op writing `var` (under the mask
//!   for a store).
//! - **Initialization**: only the registers live at the entry (read before
//!   written on some path) are zeroed at the start of a run.
//!
//! Every register index of the rewritten program and prologue is checked
//! once here by [`Program::validate`], so the interpreter loop may index
//! registers without bounds checks (a program that fails the check runs
//! unrewritten through the same checks).

mod mask_flow;

use crate::liveness::{analyze, effects};
use crate::program::{leaders, pure, Op, Program, Reg, Role, TexKind};
use std::collections::BTreeMap;

/// One instruction of the rewritten program: the op and whether its
/// destination is written under the current mask (fused store).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ins {
    pub op: Op,
    pub masked: bool,
}

/// A program ready for the executors (`engine::run_in`, `jit`).
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
pub(crate) fn optimize(p: &Program, live_out: &[Reg]) -> Code {
    if p.ops.len() <= MAX_REWRITE_OPS {
        if let Some(c) = rewrite(p, live_out) {
            return c;
        }
    }
    unoptimized(p, live_out)
}

/// The program as it is, every register zeroed at the start.
pub(crate) fn unoptimized(p: &Program, live_out: &[Reg]) -> Code {
    Code {
        prog: p.clone(),
        ins: p.ops.iter().map(|&op| Ins { op, masked: false }).collect(),
        prologue: Vec::new(),
        pool_base: p.registers,
        zero: (0..p.registers).collect(),
        live_out: live_out.to_vec(),
    }
}

/// Replaces the single-register reads of `op` through `f` (ranges, the
/// accumulator of `FMac` and destinations are left alone). Returns whether
/// every read register was replaced by one satisfying `is_pool` (for a
/// pure op, whose reads are all single registers: whether it reads pool
/// registers only).
fn map_reads(op: &mut Op, f: &mut dyn FnMut(Reg) -> Reg, is_pool: &dyn Fn(Reg) -> bool) -> bool {
    let mut all = true;
    op.for_each_single_mut(&mut |role, r| {
        if role == Role::Read {
            *r = f(*r);
            all &= is_pool(*r);
        }
    });
    all
}

/// Makes `to` the single destination register of `op` (if it has one).
fn set_dest(op: &mut Op, to: Reg) {
    op.for_each_single_mut(&mut |role, r| {
        if role != Role::Read {
            *r = to;
        }
    });
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
    let mut size_known: Vec<(Reg, Reg)> = Vec::new();
    let mut ops = p.ops.clone();
    // The texture ops, with the size queries the prologue makes appended.
    let mut textures = p.textures.clone();
    mask_flow::unmask_stores(p, &mut ops);
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
            // A copy of a pool register is that register.
            Op::Mov { a, .. } if is_pool(a) => Some(a),
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
        // A texture op reads the pool registers holding its operands, as
        // other ops do (its registers are in its `TexOp`, not the op).
        if let Op::Texture { index } = op {
            if let Some(&t) = textures.get(*index as usize) {
                let mut m = t;
                m.map_reads(|r| match known.get(r as usize) {
                    Some(&k) if k != u32::MAX => k,
                    _ => r,
                });
                if m.reads() != t.reads() && textures.len() < u32::MAX as usize {
                    *index = textures.len() as u32;
                    textures.push(m);
                }
            }
        }
        // A size query of a unit and level known for the whole run (a
        // uniform sampler, a constant or uniform level: read from the
        // pool since the rewrite above): its four result registers
        // computed by the prologue too, once per draw.
        let size = match *op {
            Op::Texture { index } => textures.get(index as usize).copied(),
            _ => None,
        }
        .filter(|t| t.kind == TexKind::Size && t.unit_and_level_from(pool_base))
        .filter(|_| textures.len() < u32::MAX as usize);
        if let Some(mut t) = size {
            let d = t.d;
            t.d = next;
            next = next.saturating_add(4);
            prologue.push(Op::Texture {
                index: textures.len() as u32,
            });
            textures.push(t);
            for k in 0..4 {
                // Cleared below with the op's other definitions first.
                size_known.push((d + k, t.d + k));
            }
        }
        if next > crate::program::MAX_REGISTERS {
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
        for (d, h) in size_known.drain(..) {
            if let Some(x) = known.get_mut(d as usize) {
                *x = h;
                touched.push(d);
            }
        }
    }

    // The ops now name the texture ops appended above.
    let p = &Program {
        textures: textures.clone(),
        ..p.clone()
    };
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
        let mut op = ops[i];
        if let Some(t) = op.target_mut() {
            *t = remap(*t);
        }
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
        textures,
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
