//! Where every live lane runs: a forward analysis of the execution masks,
//! for turning masked stores into plain copies.
//!
//! A lane is *live* while its results can still be observed: it started
//! the run (active or helper) and has not executed `discard`. An op runs
//! *in full flow* when its current mask holds every live lane, as at the
//! top of `main`, and again after an `if` whose body discarded lanes. A
//! store there leaves only dead lanes unwritten, so in a program where no
//! lane reads another's registers (no derivatives, no texture lookups with
//! an implicit level of detail, which reads the quad) it may write every lane: the
//! values of dead lanes are never read, and outputs are not stored for
//! discarded lanes (`engine::store_outputs`). A plain copy needs no blend
//! with the old value, and the old value no zeroing at the start of a run
//! (liveness no longer sees it read).
//!
//! The state per program point: whether the current mask holds every live
//! lane, and the same for each mask slot. `discard` keeps the property of
//! the slots (its lanes are dead), `break`, `continue` and `return`
//! (`Kill`) lose it for the slots they remove lanes from (those lanes are
//! live), `AndMask`/`AndNotMask` lose it for the current mask unless the
//! condition is uniform (computed from uniforms and constants only: then
//! every live lane runs the branch or none does, and inside it, past the
//! jump taken when none runs, all do). Joins keep a property only where
//! every predecessor has it; the analysis iterates to a fixed point over
//! the loops' back edges.

use crate::liveness::effects;
use crate::program::{Op, Program, Reg, TexLod};

/// What is known of a mask (the current one or a slot's).
const PARTIAL: u8 = 0;
/// Every live lane, or none.
const FULL_OR_EMPTY: u8 = 1;
/// Every live lane.
const FULL: u8 = 2;

/// The analysis states at the jump targets (where paths meet), flat:
/// per target, the current mask's and each slot's [`PARTIAL`],
/// [`FULL_OR_EMPTY`] or [`FULL`] (`slots + 1` bytes), and a bit per
/// register holding one value on every live lane (computed from uniforms
/// and constants only: an `if` on such a condition runs every live lane or
/// none). Between targets the state is carried op by op.
struct States {
    m: usize,
    w: usize,
    masks: Vec<u8>,
    uniform: Vec<u64>,
    reached: Vec<bool>,
}

/// One state being carried through the ops.
struct Cur {
    masks: Vec<u8>,
    uniform: Vec<u64>,
}

impl Cur {
    fn is_uniform(&self, r: Reg) -> bool {
        self.uniform
            .get(r as usize / 64)
            .is_some_and(|w| w & (1 << (r % 64)) != 0)
    }

    fn set_uniform(&mut self, r: Reg, u: bool) {
        if let Some(w) = self.uniform.get_mut(r as usize / 64) {
            if u {
                *w |= 1 << (r % 64);
            } else {
                *w &= !(1 << (r % 64));
            }
        }
    }

    /// The current mask after `AndMask`/`AndNotMask` from a mask known as
    /// `from`, with condition `c`.
    fn narrowed(&self, from: u8, c: Reg) -> u8 {
        if from >= FULL_OR_EMPTY && self.is_uniform(c) {
            FULL_OR_EMPTY
        } else {
            PARTIAL
        }
    }
}

impl States {
    /// The state at target `t`, if some path reached it.
    fn load(&self, t: usize, into: &mut Cur) -> bool {
        if !self.reached.get(t).copied().unwrap_or(false) {
            return false;
        }
        into.masks
            .copy_from_slice(&self.masks[t * self.m..(t + 1) * self.m]);
        into.uniform
            .copy_from_slice(&self.uniform[t * self.w..(t + 1) * self.w]);
        true
    }

    /// Meets `s` into the state at target `t`; whether it changed.
    fn meet(&mut self, t: usize, s: &Cur) -> bool {
        let (m, w) = (self.m, self.w);
        let (Some(masks), Some(uniform)) = (
            self.masks.get_mut(t * m..(t + 1) * m),
            self.uniform.get_mut(t * w..(t + 1) * w),
        ) else {
            return false;
        };
        if !self.reached[t] {
            self.reached[t] = true;
            masks.copy_from_slice(&s.masks);
            uniform.copy_from_slice(&s.uniform);
            return true;
        }
        let mut changed = false;
        for (a, &b) in masks.iter_mut().zip(&s.masks) {
            if b < *a {
                *a = b;
                changed = true;
            }
        }
        for (a, &b) in uniform.iter_mut().zip(&s.uniform) {
            if *a & b != *a {
                *a &= b;
                changed = true;
            }
        }
        changed
    }
}

/// Per op: whether it runs in full flow. All false for programs with
/// subroutine calls (not analyzed).
fn full_flow(p: &Program) -> Vec<bool> {
    let n = p.ops.len();
    if p.ops
        .iter()
        .any(|op| matches!(op, Op::Call { .. } | Op::Ret { .. }))
    {
        return vec![false; n];
    }
    // The jump targets, numbered.
    const NONE: u32 = u32::MAX;
    let mut target_of = vec![NONE; n + 1];
    let mut targets = 0u32;
    let mut back_edges = false;
    for (i, op) in p.ops.iter().enumerate() {
        if let Op::Jump { target } | Op::JumpIfNone { target } = *op {
            back_edges |= target as usize <= i;
            if let Some(t @ &mut NONE) = target_of.get_mut(target as usize) {
                *t = targets;
                targets += 1;
            }
        }
    }
    let (m, w) = (
        p.mask_slots as usize + 1,
        (p.registers as usize).div_ceil(64),
    );
    let k = targets as usize;
    let mut st = States {
        m,
        w,
        masks: vec![PARTIAL; k * m],
        uniform: vec![0; k * w],
        reached: vec![false; k],
    };
    let mut full = vec![false; n];
    let mut s = Cur {
        masks: vec![PARTIAL; m],
        uniform: vec![0; w],
    };
    // Sweeps in program order until the targets' states settle: forward
    // edges do in one, a loop's back edge needs another (a program without
    // loops, unrolled ones included, takes one).
    let mut changed = true;
    while changed {
        changed = false;
        s.masks.fill(PARTIAL);
        s.masks[0] = FULL;
        s.uniform.fill(0);
        let mut live = true;
        for (i, op) in p.ops.iter().enumerate() {
            if let Some(&t) = target_of.get(i).filter(|&&t| t != NONE) {
                if live {
                    changed |= st.meet(t as usize, &s);
                }
                live = st.load(t as usize, &mut s);
            }
            if !live {
                continue;
            }
            let slot = |k: u32| k as usize + 1;
            let get = |s: &Cur, k: u32| s.masks.get(slot(k)).copied().unwrap_or(PARTIAL);
            let cur = s.masks[0];
            full[i] = cur == FULL;
            let jump_to = |st: &mut States, s: &Cur, target: u32| {
                target_of
                    .get(target as usize)
                    .filter(|&&t| t != NONE)
                    .is_some_and(|&t| st.meet(t as usize, s))
            };
            match *op {
                Op::SaveMask { slot: k } => {
                    if let Some(v) = s.masks.get_mut(slot(k)) {
                        *v = cur;
                    }
                }
                Op::RestoreMask { slot: k } => s.masks[0] = get(&s, k),
                Op::AndMask { c } => s.masks[0] = s.narrowed(cur, c),
                Op::AndNotMask { slot: k, c } => s.masks[0] = s.narrowed(get(&s, k), c),
                // The discarded lanes are dead: the slots keep every live
                // one.
                Op::Discard { .. } => s.masks[0] = PARTIAL,
                Op::Kill { start, end } => {
                    let ks = p
                        .kill_slots
                        .get(start as usize..end as usize)
                        .unwrap_or(&[]);
                    for &k in ks {
                        if let Some(v) = s.masks.get_mut(slot(k)) {
                            *v = PARTIAL;
                        }
                    }
                    s.masks[0] = PARTIAL;
                }
                Op::Jump { target } => {
                    changed |= jump_to(&mut st, &s, target);
                    live = false;
                }
                Op::JumpIfNone { target } => {
                    changed |= jump_to(&mut st, &s, target);
                    // Falling through, some lane runs: "all or none" is all.
                    if cur == FULL_OR_EMPTY {
                        s.masks[0] = FULL;
                    }
                }
                _ => {
                    let e = effects(p, op);
                    let uniform = match op {
                        Op::Store { a, .. } => cur == FULL && s.is_uniform(*a),
                        _ => {
                            crate::program::pure(op)
                                && e.partial_defs.is_empty()
                                && e.uses.iter().all(|&(r, k)| {
                                    (r..r.saturating_add(k)).all(|r| s.is_uniform(r))
                                })
                        }
                    };
                    for &(r, k) in e.full_defs.iter().chain(&e.partial_defs) {
                        for r in r..r.saturating_add(k) {
                            s.set_uniform(r, uniform);
                        }
                    }
                }
            }
        }
        changed &= back_edges;
    }
    full
}

/// Whether some lane of `p` reads another lane's registers (derivatives,
/// lookups with an implicit level of detail; fetches, size queries and
/// lookups at an explicit level or with explicit gradients read their
/// own lane only).
fn reads_other_lanes(p: &Program) -> bool {
    p.ops.iter().any(|op| match op {
        Op::DdX { .. } | Op::DdY { .. } => true,
        Op::Texture { index } => p
            .textures
            .get(*index as usize)
            .is_none_or(|t| matches!(t.lod, TexLod::Implicit { .. })),
        _ => false,
    })
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
    fn a_branch_on_a_uniform_runs_every_live_lane() {
        // r1 = u[0] < 0.5; if (r1) { r2 = r3 } else { r4 = r3 } ; r5 = r0 < r1;
        // if (r5) { r2 = r3 }
        let p = prog(
            vec![
                Uniform {
                    d: 1,
                    word: 0,
                    float: true,
                },
                FLt { d: 1, a: 1, b: 6 },
                SaveMask { slot: 0 },
                AndMask { c: 1 },
                JumpIfNone { target: 6 },
                Store { d: 2, a: 3 },
                AndNotMask { slot: 0, c: 1 },
                JumpIfNone { target: 9 },
                Store { d: 4, a: 3 },
                RestoreMask { slot: 0 },
                FLt { d: 5, a: 0, b: 1 },
                SaveMask { slot: 0 },
                AndMask { c: 5 },
                JumpIfNone { target: 15 },
                Store { d: 2, a: 3 },
                RestoreMask { slot: 0 },
            ],
            1,
            Vec::new(),
        );
        let f = full_flow(&p);
        assert!(!f[5], "r6 is not uniform: neither is r1");
        let mut p = p;
        p.ops[1] = FLt { d: 1, a: 1, b: 1 };
        let f = full_flow(&p);
        assert!(f[5] && f[8], "both sides of a uniform branch");
        assert!(!f[14], "r0 is an input: r5 varies");
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
