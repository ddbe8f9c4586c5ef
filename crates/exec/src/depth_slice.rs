//! The depth-and-discard slice of a fragment program
//! ([`crate::Kernel::depth_only`]).
//!
//! A backward liveness analysis over the op list's control-flow graph (basic
//! blocks; jumps, conditional jumps, subroutine calls and returns), iterated
//! to a fixpoint so loops are covered, starting from the registers of
//! `gl_FragDepth` at the end of the program. Every control-flow op (mask
//! bookkeeping, jumps, loop counting, `discard`, calls) is kept with the
//! registers it reads; a data op is kept when it writes a register that is
//! live after it. Ops that write every lane kill their destinations; masked
//! writes (`Store`, `Scatter`) do not (the other lanes keep the old value).
//! The kept ops therefore compute, at every kept op, the very bits the full
//! program computes in the registers they read, on every lane: the same
//! execution masks, the same loop iteration counts (and loop-budget error),
//! the same `discard`s and the same `gl_FragDepth`.

use crate::program::{Op, Program, Reg, TexLod};

/// The analysis keeps one bit per register per basic block; beyond this many
/// bits it declines (returns `None`) rather than use a lot of memory.
const MAX_BITS: u64 = 1 << 27;

/// A slice is worth having only if it drops at least this share of the ops
/// (in 1/100).
const MIN_SAVING_PERCENT: usize = 20;

/// The ops of `p` needed to compute the registers `live_out` at the end of
/// the program and every control-flow decision, or `None` when the analysis
/// would be too large or the slice keeps more than
/// `100 - MIN_SAVING_PERCENT` % of the ops.
pub(crate) fn slice(p: &Program, live_out: &[Reg]) -> Option<Program> {
    let n = p.ops.len();
    let nregs = p.registers as usize;
    if n == 0 {
        return None;
    }
    let words = nregs.div_ceil(64).max(1);

    // Basic blocks: leaders are op 0, every jump/call target and every op
    // after a jump, conditional jump, call or return.
    let mut leader = vec![false; n + 1];
    leader[0] = true;
    leader[n] = true;
    for (i, op) in p.ops.iter().enumerate() {
        match *op {
            Op::Jump { target } | Op::JumpIfNone { target } | Op::Call { target, .. } => {
                leader[(target as usize).min(n)] = true;
                leader[i + 1] = true;
            }
            Op::Ret { .. } => leader[i + 1] = true,
            _ => {}
        }
    }
    let starts: Vec<usize> = (0..n).filter(|&i| leader[i]).collect();
    let nblocks = starts.len();
    if (nblocks as u64).saturating_mul(words as u64 * 64) > MAX_BITS {
        return None;
    }
    // Block of each leader op.
    let mut block_of = vec![usize::MAX; n + 1];
    for (b, &s) in starts.iter().enumerate() {
        block_of[s] = b;
    }
    let end_of = |b: usize| starts.get(b + 1).copied().unwrap_or(n);
    // Where each return slot's subroutine returns to: the op after each call.
    let mut returns: Vec<Vec<usize>> = vec![Vec::new(); p.subroutines as usize];
    for (i, op) in p.ops.iter().enumerate() {
        if let Op::Call { slot, .. } = *op {
            if let Some(r) = returns.get_mut(slot as usize) {
                r.push(i + 1);
            }
        }
    }
    // Successor ops (n = the exit) of each block.
    let succs: Vec<Vec<usize>> = (0..nblocks)
        .map(|b| {
            let last = end_of(b) - 1;
            match p.ops[last] {
                Op::Jump { target } | Op::Call { target, .. } => vec![(target as usize).min(n)],
                Op::JumpIfNone { target } => vec![(target as usize).min(n), last + 1],
                Op::Ret { slot } => returns.get(slot as usize).cloned().unwrap_or_default(),
                _ => vec![last + 1],
            }
        })
        .collect();

    let eff: Vec<Effects> = p.ops.iter().map(|op| effects(p, op)).collect();
    let mut exit = vec![0u64; words];
    for &r in live_out {
        set(&mut exit, r);
    }
    let mut live_in = vec![vec![0u64; words]; nblocks];
    let mut live = vec![0u64; words];
    // Round-robin in reverse order until nothing changes. Each pass can
    // only add bits, so this ends after at most nblocks * nregs passes (in
    // practice a few).
    loop {
        let mut changed = false;
        for b in (0..nblocks).rev() {
            live.iter_mut().for_each(|w| *w = 0);
            for &s in &succs[b] {
                let src = if s >= n {
                    &exit
                } else {
                    match block_of.get(s) {
                        Some(&sb) if sb < nblocks => &live_in[sb],
                        _ => continue,
                    }
                };
                for (w, x) in live.iter_mut().zip(src) {
                    *w |= x;
                }
            }
            for i in (starts[b]..end_of(b)).rev() {
                transfer(&eff[i], &mut live);
            }
            if live != live_in[b] {
                live_in[b].clone_from(&live);
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }

    // Mark the kept ops with the final live-out sets.
    let mut keep = vec![false; n];
    for b in 0..nblocks {
        live.iter_mut().for_each(|w| *w = 0);
        for &s in &succs[b] {
            let src = if s >= n {
                &exit
            } else {
                match block_of.get(s) {
                    Some(&sb) if sb < nblocks => &live_in[sb],
                    _ => continue,
                }
            };
            for (w, x) in live.iter_mut().zip(src) {
                *w |= x;
            }
        }
        for i in (starts[b]..end_of(b)).rev() {
            keep[i] = needed(&eff[i], &live);
            transfer(&eff[i], &mut live);
        }
    }
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

fn set(bits: &mut [u64], r: Reg) {
    if let Some(w) = bits.get_mut(r as usize / 64) {
        *w |= 1 << (r % 64);
    }
}

fn clear(bits: &mut [u64], r: Reg) {
    if let Some(w) = bits.get_mut(r as usize / 64) {
        *w &= !(1 << (r % 64));
    }
}

fn get(bits: &[u64], r: Reg) -> bool {
    bits.get(r as usize / 64)
        .is_some_and(|w| w & (1 << (r % 64)) != 0)
}

/// How an op touches registers: `(first, count)` ranges it writes on every
/// lane, writes on some lanes, and reads.
struct Effects {
    full_defs: Vec<(Reg, u32)>,
    partial_defs: Vec<(Reg, u32)>,
    uses: Vec<(Reg, u32)>,
    control: bool,
}

fn effects(p: &Program, op: &Op) -> Effects {
    let mut e = Effects {
        full_defs: Vec::new(),
        partial_defs: Vec::new(),
        uses: Vec::new(),
        control: false,
    };
    match *op {
        Op::FMac { d, a, b } => {
            // d = d + a * b reads its destination.
            e.full_defs.push((d, 1));
            e.uses.extend([(d, 1), (a, 1), (b, 1)]);
        }
        Op::Store { d, a } => {
            e.partial_defs.push((d, 1));
            e.uses.push((a, 1));
        }
        Op::Scatter { base, off, max, a } => {
            e.partial_defs.push((base, max.saturating_add(1)));
            e.uses.push((off, 1));
            e.uses.push((a, 1));
        }
        Op::Gather { d, base, off, max } => {
            e.full_defs.push((d, 1));
            e.uses.push((off, 1));
            e.uses.push((base, max.saturating_add(1)));
        }
        Op::Noise { d, n, a, dims } => {
            e.full_defs.push((d, n as u32));
            e.uses.push((a, dims as u32));
        }
        Op::Texture { index } => {
            if let Some(t) = p.textures.get(index as usize) {
                e.full_defs.push((t.d, 4));
                e.uses.push((t.unit, 1));
                e.uses.extend(t.coord.iter().map(|&c| (c, 1)));
                if let Some(c) = t.compare {
                    e.uses.push((c, 1));
                }
                if let TexLod::Implicit { bias: Some(b) } | TexLod::Explicit(Some(b)) = t.lod {
                    e.uses.push((b, 1));
                }
            }
        }
        Op::AndMask { c } | Op::AndNotMask { c, .. } => {
            e.control = true;
            e.uses.push((c, 1));
        }
        Op::SaveMask { .. }
        | Op::RestoreMask { .. }
        | Op::JumpIfNone { .. }
        | Op::Jump { .. }
        | Op::LoopIter
        | Op::Kill { .. }
        | Op::Discard { .. }
        | Op::Call { .. }
        | Op::Ret { .. }
        | Op::SyncDiscard { .. } => e.control = true,
        _ => {
            // Plain data ops: the first register operand is the
            // destination, written on every lane.
            let mut first = true;
            op.for_each_reg(&mut |r, n| {
                if first {
                    e.full_defs.push((r, n));
                    first = false;
                } else {
                    e.uses.push((r, n));
                }
            });
        }
    }
    e
}

fn range(r: Reg, n: u32) -> impl Iterator<Item = Reg> {
    (0..n.max(1)).map(move |k| r.saturating_add(k))
}

fn needed(e: &Effects, live: &[u64]) -> bool {
    e.control
        || e.full_defs
            .iter()
            .chain(&e.partial_defs)
            .any(|&(r, n)| range(r, n).any(|r| get(live, r)))
}

/// `live` before `op`, given `live` after it.
fn transfer(e: &Effects, live: &mut [u64]) {
    if !needed(e, live) {
        return;
    }
    for &(r, n) in &e.full_defs {
        range(r, n).for_each(|r| clear(live, r));
    }
    for &(r, n) in &e.uses {
        range(r, n).for_each(|r| set(live, r));
    }
}
