//! The depth-and-discard slice of a fragment program
//! ([`crate::Kernel::depth_only`]): the ops [`crate::liveness`] finds
//! needed for `gl_FragDepth` and for every control-flow decision. The kept
//! ops compute, at every kept op, the very bits the full program computes
//! in the registers they read, on every lane: the same execution masks, the
//! same loop iteration counts (and loop-budget error), the same `discard`s
//! and the same `gl_FragDepth`.

use crate::liveness::analyze;
use crate::program::{Op, Program, Reg};

/// A slice is worth having only if it drops at least this share of the ops
/// (in 1/100).
const MIN_SAVING_PERCENT: usize = 20;

/// The ops of `p` needed to compute the registers `live_out` at the end of
/// the program and every control-flow decision, or `None` when the analysis
/// would be too large or the slice keeps more than
/// `100 - MIN_SAVING_PERCENT` % of the ops.
pub(crate) fn slice(p: &Program, live_out: &[Reg]) -> Option<Program> {
    let n = p.ops.len();
    if n == 0 {
        return None;
    }
    let keep = analyze(p, &p.ops, p.registers, live_out)?.keep;
    let kept = keep.iter().filter(|&&k| k).count();
    if kept * 100 > n * (100 - MIN_SAVING_PERCENT) {
        return None;
    }

    // Renumber: an old op index maps to the first kept op at or after it.
    let mut new_index = vec![0u32; n + 1];
    let mut next = 0u32;
    for i in 0..n {
        new_index[i] = next;
        if keep[i] {
            next += 1;
        }
    }
    new_index[n] = next;
    let remap = |t: u32| new_index[(t as usize).min(n)];
    let mut ops = Vec::with_capacity(kept);
    for (i, op) in p.ops.iter().enumerate() {
        if !keep[i] {
            continue;
        }
        ops.push(match *op {
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
        });
    }
    let mut statements: Vec<_> = p
        .statements
        .iter()
        .map(|s| crate::program::StatementMark {
            op: remap(s.op),
            span: s.span,
        })
        .collect();
    // Several statements may now start at the same op: keep the last.
    statements.reverse();
    statements.dedup_by_key(|s| s.op);
    statements.reverse();
    let out = Program {
        ops,
        textures: p.textures.clone(),
        kill_slots: p.kill_slots.clone(),
        registers: p.registers,
        mask_slots: p.mask_slots,
        subroutines: p.subroutines,
        init: p.init.clone(),
        statements,
        vars: p.vars.clone(),
        printfs: p.printfs.clone(),
    };
    out.validate().ok()?;
    Some(out)
}
