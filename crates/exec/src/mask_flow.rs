//! Where every live lane runs: a forward analysis of the execution masks,
//! for turning masked stores into plain copies.
//!
//! A lane is *live* while its results can still be observed: it started
//! the run (active or helper) and has not executed `discard`. An op runs
//! *in full flow* when its current mask holds every live lane, as at the
//! top of `main`, and again after an `if` whose body discarded lanes. A
//! store there leaves only dead lanes unwritten, so in a program where no
//! lane reads another's registers (no derivatives, no texture lookups: the
//! implicit level of detail reads the quad) it may write every lane: the
//! values of dead lanes are never read, and outputs are not stored for
//! discarded lanes (`engine::store_outputs`). A plain copy needs no blend
//! with the old value, and the old value no zeroing at the start of a run
//! (liveness no longer sees it read).
//!
//! The state per program point: whether the current mask holds every live
//! lane, and the same for each mask slot. `discard` keeps the property of
//! the slots (its lanes are dead), `break`, `continue` and `return`
//! (`Kill`) lose it for the slots they remove lanes from (those lanes are
//! live), `AndMask`/`AndNotMask` lose it for the current mask. Joins keep
//! the property only where every predecessor has it; the analysis iterates
//! to a fixed point over the loops' back edges.

use crate::program::{Op, Program};

/// Per op: whether it runs in full flow. All false for programs with
/// subroutine calls (not analyzed).
fn full_flow(p: &Program) -> Vec<bool> {
    let n = p.ops.len();
    let slots = p.mask_slots as usize;
    if p.ops
        .iter()
        .any(|op| matches!(op, Op::Call { .. } | Op::Ret { .. }))
    {
        return vec![false; n];
    }
    // State: [current mask, slot 0, slot 1, ...]; `None`: not reached.
    let mut at: Vec<Option<Vec<bool>>> = vec![None; n + 1];
    let mut entry = vec![false; slots + 1];
    entry[0] = true;
    at[0] = Some(entry);
    let mut work = vec![0usize];
    let join = |at: &mut Vec<Option<Vec<bool>>>, i: usize, s: &[bool]| -> bool {
        match at.get_mut(i) {
            Some(slot @ None) => {
                *slot = Some(s.to_vec());
                true
            }
            Some(Some(old)) => {
                let mut changed = false;
                for (o, &v) in old.iter_mut().zip(s) {
                    if *o && !v {
                        *o = false;
                        changed = true;
                    }
                }
                changed
            }
            None => false,
        }
    };
    while let Some(i) = work.pop() {
        let Some(mut s) = at.get(i).cloned().flatten() else {
            continue;
        };
        let Some(op) = p.ops.get(i) else { continue };
        let slot = |k: u32| k as usize + 1;
        let mut next = vec![i + 1];
        match *op {
            Op::SaveMask { slot: k } => {
                let cur = s[0];
                if let Some(v) = s.get_mut(slot(k)) {
                    *v = cur;
                }
            }
            Op::RestoreMask { slot: k } => s[0] = s.get(slot(k)).copied().unwrap_or(false),
            Op::AndMask { .. } | Op::AndNotMask { .. } => s[0] = false,
            // The discarded lanes are dead: the slots keep every live one.
            Op::Discard { .. } => s[0] = false,
            Op::Kill { start, end } => {
                let ks = p
                    .kill_slots
                    .get(start as usize..end as usize)
                    .unwrap_or(&[]);
                for &k in ks {
                    if let Some(v) = s.get_mut(slot(k)) {
                        *v = false;
                    }
                }
                s[0] = false;
            }
            Op::Jump { target } => next = vec![target as usize],
            Op::JumpIfNone { target } => next.push(target as usize),
            _ => {}
        }
        for t in next {
            if t <= n && join(&mut at, t, &s) {
                work.push(t);
            }
        }
    }
    (0..n)
        .map(|i| at[i].as_ref().is_some_and(|s| s[0]))
        .collect()
}

/// Whether some lane of `p` reads another lane's registers (derivatives,
/// texture lookups).
fn reads_other_lanes(p: &Program) -> bool {
    p.ops
        .iter()
        .any(|op| matches!(op, Op::DdX { .. } | Op::DdY { .. } | Op::Texture { .. }))
}

/// `ops` (the ops of `p`, being rewritten) with the stores that run in
/// full flow turned into plain copies, when no lane of `p` reads another
/// lane's registers.
pub(crate) fn unmask_stores(p: &Program, ops: &mut [Op]) {
    if reads_other_lanes(p) {
        return;
    }
    for (op, full) in ops.iter_mut().zip(full_flow(p)) {
        if let (true, Op::Store { d, a }) = (full, *op) {
            *op = Op::Mov { d, a };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::program::Op::*;

    fn prog(ops: Vec<Op>, slots: u32, kill_slots: Vec<u32>) -> Program {
        Program {
            ops,
            mask_slots: slots,
            kill_slots,
            registers: 8,
            ..Program::default()
        }
    }

    #[test]
    fn stores_after_an_if_that_discards_run_in_full_flow() {
        // s0 = cur; if (r1) { discard } cur = s0; r2 = r3; if (r1) { r4 = r3 }
        let p = prog(
            vec![
                SaveMask { slot: 0 },
                SaveMask { slot: 1 },
                AndMask { c: 1 },
                JumpIfNone { target: 5 },
                Discard { start: 0, end: 2 },
                RestoreMask { slot: 1 },
                Store { d: 2, a: 3 },
                SaveMask { slot: 1 },
                AndMask { c: 1 },
                Store { d: 4, a: 3 },
                RestoreMask { slot: 1 },
                Store { d: 5, a: 3 },
            ],
            2,
            vec![0, 1],
        );
        let f = full_flow(&p);
        assert!(f[6], "after the discarding if");
        assert!(!f[9], "inside an if");
        assert!(f[11], "after it");
    }

    #[test]
    fn a_return_or_a_loop_break_leaves_partial_flow() {
        // s0 = cur (function); if (r1) { return } cur = s1; r2 = r3
        let p = prog(
            vec![
                SaveMask { slot: 0 },
                SaveMask { slot: 1 },
                AndMask { c: 1 },
                Kill { start: 0, end: 2 },
                RestoreMask { slot: 1 },
                Store { d: 2, a: 3 },
                RestoreMask { slot: 0 },
                Store { d: 2, a: 3 },
            ],
            2,
            vec![0, 1],
        );
        let f = full_flow(&p);
        assert!(!f[5], "returned lanes are live but not running");
        assert!(!f[7], "the function's slot lost them too");
        // A loop: the store after a back edge from a partial state.
        let p = prog(
            vec![
                Store { d: 2, a: 3 },
                AndMask { c: 1 },
                Store { d: 2, a: 3 },
                Jump { target: 0 },
            ],
            0,
            Vec::new(),
        );
        let f = full_flow(&p);
        assert!(!f[0] && !f[2]);
    }

    #[test]
    fn programs_reading_other_lanes_keep_their_stores() {
        let ops = vec![Store { d: 2, a: 3 }, DdX { d: 4, a: 2 }];
        let p = prog(ops.clone(), 0, Vec::new());
        let mut out = ops.clone();
        unmask_stores(&p, &mut out);
        assert!(matches!(out[0], Store { .. }));
        let p = prog(vec![Store { d: 2, a: 3 }], 0, Vec::new());
        let mut out = p.ops.clone();
        unmask_stores(&p, &mut out);
        assert!(matches!(out[0], Mov { d: 2, a: 3 }));
    }
}
