//! Backward register liveness over a program's control-flow graph, and the
//! dead code it reveals (used by [`crate::Kernel::depth_only`] and by the
//! optimizer, `crate::opt`).
//!
//! Basic blocks end at jumps, conditional jumps, subroutine calls and
//! returns; the analysis iterates to a fixpoint (loops, subroutine
//! returns) over a worklist of the blocks whose successors changed.
//! Control-flow ops (mask bookkeeping, jumps, loop counting, `discard`,
//! calls) are always needed, with the registers they read; a data op is needed when it writes
//! a register that is live after it. Ops that write every lane kill their
//! destinations; masked writes (`Store`, `Scatter`) do not (the other lanes
//! keep the old value). Dropping the unneeded ops leaves every needed op
//! reading the very bits it read before, on every lane.

use crate::program::{Class, Op, Program, Reg, Role};
use smallvec::SmallVec;

/// What [`analyze`] finds.
pub(crate) struct Liveness {
    /// Per op: needed.
    pub keep: Vec<bool>,
    /// Registers live at the entry (read before any full write on some
    /// path): the ones a run must initialize.
    pub entry: Vec<u64>,
    /// Per op: for a `Store { a, .. }` or `Mov { a, .. }`, `a` is dead
    /// after it.
    pub store_source_dead: Vec<bool>,
    /// Per op, when asked for ([`analyze_after`]): the registers live
    /// after it (one bit each), else empty.
    pub after: Vec<Vec<u64>>,
}

impl Liveness {
    pub fn entry_live(&self, r: Reg) -> bool {
        get(&self.entry, r)
    }
}

/// Whether register `r` is in the bit set `bits` (as in [`Liveness::after`]).
pub(crate) fn is_live(bits: &[u64], r: Reg) -> bool {
    get(bits, r)
}

/// The analysis keeps one bit per register per basic block; beyond this many
/// bits it declines (returns `None`) rather than use a lot of memory.
const MAX_BITS: u64 = 1 << 27;

/// Liveness of `ops` (the ops of `p`, or a rewrite of them over `nregs`
/// registers using `p`'s side tables) with `live_out` live at the end;
/// `None` when the analysis would be too large.
pub(crate) fn analyze(p: &Program, ops: &[Op], nregs: u32, live_out: &[Reg]) -> Option<Liveness> {
    analyze_with(p, ops, nregs, live_out, None)
}

/// [`analyze`], also filling [`Liveness::after`] (`ops.len()` bit sets of
/// `nregs` bits: for programs of a bounded size). `masked[i]`: op `i`
/// writes its destinations under the current mask only (a fused store of
/// the executor), so it does not kill them.
pub(crate) fn analyze_after(
    p: &Program,
    ops: &[Op],
    masked: &[bool],
    nregs: u32,
    live_out: &[Reg],
) -> Option<Liveness> {
    analyze_with(p, ops, nregs, live_out, Some(masked))
}

fn analyze_with(
    p: &Program,
    ops: &[Op],
    nregs: u32,
    live_out: &[Reg],
    masked: Option<&[bool]>,
) -> Option<Liveness> {
    let want_after = masked.is_some();
    let n = ops.len();
    let nregs = nregs as usize;
    let words = nregs.div_ceil(64).max(1);
    if n == 0 {
        // Nothing runs: the outputs are live at the entry as they are.
        let mut entry = vec![0u64; words];
        for &r in live_out {
            set(&mut entry, r);
        }
        return Some(Liveness {
            keep: Vec::new(),
            entry,
            store_source_dead: Vec::new(),
            after: Vec::new(),
        });
    }

    let leader = crate::program::leaders(ops);
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
    for (i, op) in ops.iter().enumerate() {
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
            match ops[last] {
                Op::Jump { target } | Op::Call { target, .. } => vec![(target as usize).min(n)],
                Op::JumpIfNone { target } => vec![(target as usize).min(n), last + 1],
                Op::Ret { slot } => returns.get(slot as usize).cloned().unwrap_or_default(),
                _ => vec![last + 1],
            }
        })
        .collect();

    let eff: Vec<Effects> = ops
        .iter()
        .enumerate()
        .map(|(i, op)| {
            let mut e = effects(p, op);
            if masked.and_then(|m| m.get(i)).copied().unwrap_or(false) {
                let full = std::mem::take(&mut e.full_defs);
                e.partial_defs.extend(full);
            }
            e
        })
        .collect();
    let mut exit = vec![0u64; words];
    for &r in live_out {
        set(&mut exit, r);
    }
    let mut live_in = vec![vec![0u64; words]; nblocks];
    let mut live = vec![0u64; words];
    // Predecessor blocks of each block, for the worklist.
    let mut preds: Vec<Vec<usize>> = vec![Vec::new(); nblocks];
    for (b, ss) in succs.iter().enumerate() {
        for &s in ss {
            if let Some(&sb) = block_of.get(s).filter(|&&sb| sb < nblocks) {
                preds[sb].push(b);
            }
        }
    }
    // A worklist, last block first: a block is visited again only when a
    // successor's live-in set grew. Sets only grow, so it ends; a sweep of
    // every block until nothing changes would instead cost a whole sweep
    // per link of a long chain of subroutine returns.
    let mut pending: std::collections::VecDeque<usize> = (0..nblocks).rev().collect();
    let mut queued = vec![true; nblocks];
    while let Some(b) = pending.pop_front() {
        queued[b] = false;
        block_live_out(&mut live, &succs[b], &live_in, &exit, &block_of, n);
        for i in (starts[b]..end_of(b)).rev() {
            transfer(&eff[i], &mut live);
        }
        if live != live_in[b] {
            live_in[b].clone_from(&live);
            for &p in &preds[b] {
                if !queued[p] {
                    queued[p] = true;
                    pending.push_back(p);
                }
            }
        }
    }

    // Mark the kept ops with the final live-out sets.
    let mut keep = vec![false; n];
    let mut store_source_dead = vec![false; n];
    let mut after = if want_after {
        vec![Vec::new(); n]
    } else {
        Vec::new()
    };
    for b in 0..nblocks {
        block_live_out(&mut live, &succs[b], &live_in, &exit, &block_of, n);
        for i in (starts[b]..end_of(b)).rev() {
            if let Some(a) = after.get_mut(i) {
                a.clone_from(&live);
            }
            keep[i] = needed(&eff[i], &live);
            if let Op::Store { a, .. } | Op::Mov { a, .. } = ops[i] {
                store_source_dead[i] = !get(&live, a);
            }
            transfer(&eff[i], &mut live);
        }
    }
    let entry = live_in.first().cloned().unwrap_or_else(|| exit.clone());
    Some(Liveness {
        keep,
        entry,
        store_source_dead,
        after,
    })
}

/// The registers live at the end of a block: the union of its successors'
/// live-in sets (`exit` for the end of the program, successor op `n`).
fn block_live_out(
    live: &mut [u64],
    succs: &[usize],
    live_in: &[Vec<u64>],
    exit: &[u64],
    block_of: &[usize],
    n: usize,
) {
    live.iter_mut().for_each(|w| *w = 0);
    for &s in succs {
        let src = if s >= n {
            exit
        } else {
            match block_of.get(s).and_then(|&sb| live_in.get(sb)) {
                Some(b) => b,
                None => continue,
            }
        };
        for (w, x) in live.iter_mut().zip(src) {
            *w |= x;
        }
    }
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
pub(crate) struct Effects {
    pub full_defs: SmallVec<[(Reg, u32); 2]>,
    pub partial_defs: SmallVec<[(Reg, u32); 2]>,
    pub uses: SmallVec<[(Reg, u32); 8]>,
    pub control: bool,
}

pub(crate) fn effects(p: &Program, op: &Op) -> Effects {
    let mut e = Effects {
        full_defs: SmallVec::new(),
        partial_defs: SmallVec::new(),
        uses: SmallVec::new(),
        // Writes to memory and barriers are effects of their own.
        control: op.class() == Class::Control
            || matches!(op, Op::StoreMem { .. } | Op::Atomic { .. } | Op::Barrier),
    };
    op.for_each_operand(&mut |role, r, n| match role {
        Role::Def => e.full_defs.push((r, n)),
        Role::Acc => {
            e.full_defs.push((r, n));
            e.uses.push((r, n));
        }
        Role::Masked => e.partial_defs.push((r, n)),
        Role::Read => e.uses.push((r, n)),
    });
    // A lookup's registers are in its side table.
    if let Op::Texture { index } = *op {
        if let Some(t) = p.textures.get(index as usize) {
            e.full_defs.push((t.d, 4));
            e.uses.extend(t.reads().into_iter().map(|r| (r, 1)));
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
