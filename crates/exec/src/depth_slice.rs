//! The depth-and-discard slice of a fragment program
//! ([`crate::Kernel::depth_only`]): the ops [`crate::liveness`] finds
//! needed for `gl_FragDepth` and for every control-flow decision. The kept
//! ops compute, at every kept op, the very bits the full program computes
//! in the registers they read, on every lane: the same execution masks, the
//! same loop iteration counts (and loop-budget error), the same `discard`s
//! and the same `gl_FragDepth`. In programs without loops, a branch left
//! with nothing but its own mask changes (an `if` that only chose colours,
//! such as each light of an unrolled lighting loop) is dropped with the
//! condition it tested: it ends with the mask it started with.

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
    // Slice, then drop the branches left with nothing but mask changes
    // (an `if` whose body only mattered for colour) and slice again: the
    // conditions those branches tested are then unread.
    let mut keep = analyze(p, &p.ops, p.registers, live_out)?.keep;
    let mut dropped = drop_empty_regions(&p.ops, &mut keep);
    let mut out = compact(p, &keep);
    for _ in 0..4 {
        if !dropped {
            break;
        }
        keep = analyze(&out, &out.ops, out.registers, live_out)?.keep;
        dropped = drop_empty_regions(&out.ops, &mut keep);
        if keep.iter().all(|&k| k) {
            break;
        }
        out = compact(&out, &keep);
    }
    if out.ops.len() * 100 > n * (100 - MIN_SAVING_PERCENT) {
        return None;
    }
    out.validate().ok()?;
    Some(out)
}

/// Unmarks in `keep` every kept `SaveMask s … RestoreMask s` region
/// whose kept ops in between only narrow the mask (`AndMask`,
/// `AndNotMask`, `JumpIfNone`, inner such regions): the region ends with
/// the mask it started with and changed nothing else. Only in programs
/// without loops or subroutines (whose mask slots are restored more than
/// once). Returns whether any region was dropped.
fn drop_empty_regions(ops: &[Op], keep: &mut [bool]) -> bool {
    if ops.iter().zip(keep.iter()).any(|(op, &k)| {
        k && matches!(
            op,
            Op::LoopIter | Op::Jump { .. } | Op::Call { .. } | Op::Ret { .. }
        )
    }) {
        return false;
    }
    // Open regions: (slot, first op, nothing but mask changes so far).
    let mut open: Vec<(u32, usize, bool)> = Vec::new();
    let mut dropped = false;
    for (i, op) in ops.iter().enumerate() {
        if !keep.get(i).copied().unwrap_or(false) {
            continue;
        }
        match *op {
            Op::SaveMask { slot } => open.push((slot, i, true)),
            Op::RestoreMask { slot } => match open.last().copied() {
                Some((s, first, empty)) if s == slot => {
                    open.pop();
                    if empty {
                        for k in keep.iter_mut().take(i + 1).skip(first) {
                            *k = false;
                        }
                        dropped = true;
                    } else if let Some(outer) = open.last_mut() {
                        outer.2 = false;
                    }
                }
                _ => open.iter_mut().for_each(|r| r.2 = false),
            },
            Op::AndMask { .. } | Op::AndNotMask { .. } | Op::JumpIfNone { .. } => {}
            _ => open.iter_mut().for_each(|r| r.2 = false),
        }
    }
    dropped
}

/// The ops of `p` that `keep` marks, jump targets renumbered.
fn compact(p: &Program, keep: &[bool]) -> Program {
    let n = p.ops.len();
    let kept = keep.iter().filter(|&&k| k).count();
    // Renumber: an old op index maps to the first kept op at or after it.
    let mut new_index = vec![0u32; n + 1];
    let mut next = 0u32;
    for (i, slot) in new_index.iter_mut().take(n).enumerate() {
        *slot = next;
        if keep.get(i).copied().unwrap_or(false) {
            next += 1;
        }
    }
    new_index[n] = next;
    let remap = |t: u32| new_index[(t as usize).min(n)];
    let mut ops = Vec::with_capacity(kept);
    for (i, op) in p.ops.iter().enumerate() {
        if !keep.get(i).copied().unwrap_or(false) {
            continue;
        }
        let mut op = *op;
        if let Some(t) = op.target_mut() {
            *t = remap(*t);
        }
        ops.push(op);
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
    Program {
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
    }
}
