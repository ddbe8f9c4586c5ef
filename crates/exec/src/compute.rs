//! Running a compute kernel's work groups (GL_ARB_compute_shader): each
//! invocation's built-in IDs as its inputs, batches of [`LANES`]
//! invocations, a fresh region for the group's `shared` variables, and
//! `barrier()`.
//!
//! A work group of one batch runs its lanes in step, so a barrier in it
//! (which GLSL allows only in uniform control flow) holds by itself. A
//! larger group that calls `barrier()` runs each batch on a thread of its
//! own, in turns: batch 0 runs until its first barrier (or its end), then
//! batch 1, ..., then batch 0 again past that barrier. Every batch has
//! then reached the barrier before any goes on, as GLSL requires, and the
//! order of every memory access is fixed, so the results (atomics
//! included) are the same on every machine. Batches of a group without
//! barriers run one after the other on the caller's thread.

use crate::memory::{AtomicOp, Memory, Words, SHARED_SPACE};
use crate::{Batch, ExecError, FetchRequest, Kernel, LaneMask, SampleRequest, Textures, LANES};
use glsl::types::SamplerKind;
use std::sync::{Condvar, Mutex};

/// One dispatch's work-group counts and this group's ID.
#[derive(Clone, Copy, Debug)]
pub struct WorkGroup {
    pub id: [u32; 3],
    pub count: [u32; 3],
}

/// Runs work group `group` of compute kernel `k` with `uniforms` and
/// `textures` (whose [`Textures::memory`] holds the storage buffers).
pub fn run_work_group(
    k: &Kernel,
    group: WorkGroup,
    uniforms: &[u32],
    textures: &(dyn Textures + Sync),
) -> Result<(), ExecError> {
    let size = k.interface.local_size.unwrap_or([1, 1, 1]);
    let n = size.iter().map(|&s| s as usize).product::<usize>();
    let shared = Words::with(vec![(
        SHARED_SPACE,
        vec![0; k.interface.shared_bytes.div_ceil(4) as usize],
    )]);
    let batches: Vec<Batch> = (0..n.div_ceil(LANES))
        .map(|b| group_batch(k, group, size, b * LANES, n))
        .collect();
    if !k.threads_per_group() {
        let view = GroupView {
            inner: textures,
            shared: &shared,
            turns: None,
        };
        for mut b in batches {
            k.run(&mut b, uniforms, &view)?;
        }
        return Ok(());
    }
    let turns = Turns::new(batches.len());
    std::thread::scope(|s| {
        let handles: Vec<_> = batches
            .into_iter()
            .enumerate()
            .map(|(me, mut b)| {
                let (turns, shared) = (&turns, &shared);
                s.spawn(move || {
                    // Passes the turn on however the run ends.
                    let _done = Done { turns, me };
                    turns.wait(me);
                    let view = GroupView {
                        inner: textures,
                        shared,
                        turns: Some((turns, me)),
                    };
                    k.run(&mut b, uniforms, &view)
                })
            })
            .collect();
        let mut result = Ok(());
        for h in handles {
            let r = h.join().unwrap_or_else(|_| {
                Err(ExecError::Unsupported(
                    "a work group's invocation panicked".into(),
                ))
            });
            if result.is_ok() {
                result = r;
            }
        }
        result
    })
}

/// The batch of invocations `first..first + LANES` (those below `n`) of
/// a work group of `size`, its built-in IDs filled in.
fn group_batch(k: &Kernel, group: WorkGroup, size: [u32; 3], first: usize, n: usize) -> Batch {
    let count = (n - first).min(LANES);
    let active: LaneMask = if count == LANES {
        !0 >> (32 - LANES)
    } else {
        (1 << count) - 1
    };
    let mut batch = Batch::for_kernel(k, active);
    for slot in &k.interface.inputs {
        for l in 0..count {
            let i = (first + l) as u32;
            let local = [
                i % size[0],
                (i / size[0]) % size[1],
                i / (size[0] * size[1]),
            ];
            let global: [u32; 3] =
                std::array::from_fn(|c| group.id[c].wrapping_mul(size[c]).wrapping_add(local[c]));
            let value: &[u32] = match slot.name.as_str() {
                "gl_LocalInvocationID" => &local,
                "gl_GlobalInvocationID" => &global,
                "gl_WorkGroupID" => &group.id,
                "gl_NumWorkGroups" => &group.count,
                "gl_LocalInvocationIndex" => std::slice::from_ref(&i),
                _ => &[],
            };
            for (c, &v) in value.iter().enumerate().take(slot.components) {
                if let Some(input) = batch.inputs.get_mut(slot.offset + c) {
                    input[l] = f32::from_bits(v);
                }
            }
        }
    }
    batch
}

/// Whose turn it is among a work group's batches, and which have ended.
struct Turns {
    state: Mutex<(usize, Vec<bool>)>,
    changed: Condvar,
}

impl Turns {
    fn new(n: usize) -> Turns {
        Turns {
            state: Mutex::new((0, vec![false; n])),
            changed: Condvar::new(),
        }
    }

    /// Blocks until it is batch `me`'s turn.
    fn wait(&self, me: usize) {
        let mut s = self.state.lock().unwrap_or_else(|e| e.into_inner());
        while s.0 != me {
            s = self.changed.wait(s).unwrap_or_else(|e| e.into_inner());
        }
    }

    /// Batch `me` stops (at a barrier, or `ended`): the next batch still
    /// running goes on.
    fn pass(&self, me: usize, ended: bool) {
        let mut s = self.state.lock().unwrap_or_else(|e| e.into_inner());
        let n = s.1.len();
        if ended {
            s.1[me] = true;
        }
        if let Some(next) = (1..=n).map(|k| (me + k) % n).find(|&j| !s.1[j]) {
            s.0 = next;
        }
        self.changed.notify_all();
    }
}

/// Passes the turn on when a batch's thread ends (returning, failing or
/// unwinding), so the others never wait for it.
struct Done<'a> {
    turns: &'a Turns,
    me: usize,
}

impl Drop for Done<'_> {
    fn drop(&mut self) {
        self.turns.pass(self.me, true);
    }
}

/// The textures of a dispatch with its memory and the group's shared
/// variables; a barrier passes the turn (see the module docs).
struct GroupView<'a> {
    inner: &'a (dyn Textures + Sync),
    shared: &'a Words,
    turns: Option<(&'a Turns, usize)>,
}

impl Textures for GroupView<'_> {
    fn sample(&self, req: &SampleRequest, out: &mut [[f32; LANES]; 4]) {
        self.inner.sample(req, out)
    }

    fn sample_2d_implicit(
        &self,
        unit: u32,
        st: [&[f32; LANES]; 2],
        mask: LaneMask,
        out: &mut [[f32; LANES]; 4],
    ) -> bool {
        self.inner.sample_2d_implicit(unit, st, mask, out)
    }

    fn fetch(&self, req: &FetchRequest, out: &mut [[f32; LANES]; 4]) {
        self.inner.fetch(req, out)
    }

    fn size(&self, unit: u32, target: SamplerKind, lod: i32) -> [i32; 3] {
        self.inner.size(unit, target, lod)
    }

    fn memory(&self) -> Option<&dyn Memory> {
        Some(self)
    }
}

impl std::fmt::Debug for GroupView<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("GroupView")
            .field("shared", &self.shared)
            .finish_non_exhaustive()
    }
}

impl Memory for GroupView<'_> {
    fn load(&self, space: u32, addr: u32) -> u32 {
        match (space, self.inner.memory()) {
            (SHARED_SPACE, _) => self.shared.load(space, addr),
            (_, Some(m)) => m.load(space, addr),
            (_, None) => 0,
        }
    }

    fn store(&self, space: u32, addr: u32, value: u32) {
        match (space, self.inner.memory()) {
            (SHARED_SPACE, _) => self.shared.store(space, addr, value),
            (_, Some(m)) => m.store(space, addr, value),
            (_, None) => {}
        }
    }

    fn atomic(&self, space: u32, addr: u32, op: AtomicOp, a: u32, b: u32) -> u32 {
        match (space, self.inner.memory()) {
            (SHARED_SPACE, _) => self.shared.atomic(space, addr, op, a, b),
            (_, Some(m)) => m.atomic(space, addr, op, a, b),
            (_, None) => 0,
        }
    }

    fn size(&self, space: u32) -> u32 {
        match (space, self.inner.memory()) {
            (SHARED_SPACE, _) => self.shared.size(space),
            (_, Some(m)) => m.size(space),
            (_, None) => 0,
        }
    }

    fn barrier(&self) {
        if let Some((turns, me)) = self.turns {
            turns.pass(me, false);
            turns.wait(me);
        }
    }
}
