//! Where the emitted code keeps register values: loads and stores of
//! register quarters in the in-memory file, the per-block [`Cache`] of
//! quarters held in SSA values (written back at block ends, before calls,
//! or when liveness says a value is read later), and the table of vector
//! constants ([`Consts`]).

use super::{mem, Emit, QUARTERS};
use crate::program::Reg;
use cranelift_codegen::ir::types::{F32X4, I32X4, I8X16};
use cranelift_codegen::ir::{ConstantData, Endianness, InstBuilder, MemFlagsData, Value};

/// Vector constants in a table the code loads from: a load used once is
/// folded into the instruction using it, and loads of one entry between
/// two stores become one value (Cranelift would otherwise compute each
/// constant once for the whole function and spill it).
#[derive(Default)]
pub(super) struct Consts {
    pub(super) table: Vec<[u32; 4]>,
    index: std::collections::HashMap<[u32; 4], u32>,
    /// `Ctx::consts`, loaded at the entry.
    pub(super) base: Option<Value>,
}

/// A quarter of a register held in an SSA value: `dirty` when memory does
/// not have it yet; `used`: when last touched (for eviction).
#[derive(Clone, Copy)]
pub(super) struct Held {
    v: Value,
    dirty: bool,
    used: u64,
}

/// The register quarters of the current block kept in SSA values, so an op
/// reading what an earlier op of the block wrote needs no load, and a
/// register written several times is stored once. Memory is brought up to
/// date (`flush`) before branches, before calls, and for the registers a
/// gather reads; a scatter's registers are dropped (`forget`).
#[derive(Default, Clone)]
pub(super) struct Cache {
    held: std::collections::BTreeMap<(Reg, usize), Held>,
    clock: u64,
}

/// At most this many quarters are held (more only makes Cranelift spill).
pub(super) const HELD: usize = 48;

impl<'a, 'b> Emit<'a, 'b> {
    pub(super) fn splat(&mut self, bits: u32) -> Value {
        self.vconst([bits; 4])
    }

    pub(super) fn vconst(&mut self, lanes: [u32; 4]) -> Value {
        let c = &mut self.consts;
        let next = c.table.len() as u32;
        let i = *c.index.entry(lanes).or_insert(next);
        if i == next {
            c.table.push(lanes);
        }
        match (c.base, i32::try_from(i as u64 * 16)) {
            (Some(base), Ok(off)) => self.b.ins().load(I32X4, mem().with_aligned(), base, off),
            _ => {
                let bytes: Vec<u8> = lanes.iter().flat_map(|l| l.to_le_bytes()).collect();
                let c = self.b.func.dfg.constants.insert(ConstantData::from(bytes));
                self.b.ins().vconst(I32X4, c)
            }
        }
    }

    /// Lanes `lanes` of the eight of `a` then `b` (I32X4).
    /// Lanes `lanes` of `v` (I32X4).
    pub(super) fn lanes_of(&mut self, v: Value, lanes: [u8; 4]) -> Value {
        self.lanes_of2(v, v, lanes)
    }

    pub(super) fn lanes_of2(&mut self, a: Value, b: Value, lanes: [u8; 4]) -> Value {
        let flags = MemFlagsData::new().with_endianness(Endianness::Little);
        let (a, b) = (
            self.b.ins().bitcast(I8X16, flags, a),
            self.b.ins().bitcast(I8X16, flags, b),
        );
        let bytes: Vec<u8> = lanes
            .iter()
            .flat_map(|&s| (0..4).map(move |k| 4 * s + k))
            .collect();
        let imm = self.b.func.dfg.immediates.push(ConstantData::from(bytes));
        let s = self.b.ins().shuffle(a, b, imm);
        self.b.ins().bitcast(I32X4, flags, s)
    }

    pub(super) fn fv(&mut self, v: Value) -> Value {
        self.b.ins().bitcast(F32X4, MemFlagsData::new(), v)
    }

    pub(super) fn iv(&mut self, v: Value) -> Value {
        self.b.ins().bitcast(I32X4, MemFlagsData::new(), v)
    }

    pub(super) fn offset(r: Reg, q: usize) -> i32 {
        (r as usize * 64 + q * 16) as i32
    }

    /// Quarter `q` of register `r` (as I32X4).
    pub(super) fn ld(&mut self, r: Reg, q: usize) -> Value {
        self.cache.clock += 1;
        let now = self.cache.clock;
        if let Some(h) = self.cache.held.get_mut(&(r, q)) {
            h.used = now;
            return h.v;
        }
        let v = if r >= self.code.pool_base {
            let off = Self::offset(r - self.code.pool_base, q);
            self.b.ins().load(I32X4, mem(), self.pool, off)
        } else {
            self.b
                .ins()
                .load(I32X4, mem(), self.regs, Self::offset(r, q))
        };
        self.hold(r, q, v, false);
        v
    }

    /// Quarter `q` of register `r` as F32X4.
    pub(super) fn ldf(&mut self, r: Reg, q: usize) -> Value {
        let v = self.ld(r, q);
        self.fv(v)
    }

    /// Writes `v` (I32X4) into quarter `q` of `d`, under the current mask
    /// when `masked`.
    pub(super) fn put(&mut self, d: Reg, q: usize, v: Value, masked: bool) {
        let v = if masked && !self.full {
            let old = self.ld(d, q);
            let m = self.b.use_var(self.mk[q]);
            self.b.ins().bitselect(m, v, old)
        } else {
            v
        };
        // The last write of a run to a register read after it is stored
        // here, not at the run's end: Cranelift computes a value where
        // its first side-effecting use is, so a store at the end would
        // move the run's arithmetic there, away from its loads. Later
        // reads load it again (holding it made Cranelift spill it).
        if let Some(end) = self.store_now {
            if self.live_after(end, d) {
                self.b.ins().store(mem(), v, self.regs, Self::offset(d, q));
                self.cache.held.remove(&(d, q));
                return;
            }
        }
        self.hold(d, q, v, true);
    }

    pub(super) fn hold(&mut self, r: Reg, q: usize, v: Value, dirty: bool) {
        self.cache.clock += 1;
        let used = self.cache.clock;
        self.cache.held.insert((r, q), Held { v, dirty, used });
        if self.cache.held.len() > HELD {
            let oldest = self
                .cache
                .held
                .iter()
                .min_by_key(|(_, h)| h.used)
                .map(|(&k, _)| k);
            if let Some(k) = oldest {
                self.evict(k);
            }
        }
    }

    pub(super) fn evict(&mut self, k: (Reg, usize)) {
        if let Some(h) = self.cache.held.remove(&k) {
            if h.dirty {
                self.b
                    .ins()
                    .store(mem(), h.v, self.regs, Self::offset(k.0, k.1));
            }
        }
    }

    /// Stores the held quarters of registers `lo..=hi` that memory lacks.
    pub(super) fn flush_range(&mut self, lo: Reg, hi: Reg) {
        let dirty: Vec<((Reg, usize), Value)> = self
            .cache
            .held
            .range((lo, 0)..=(hi, QUARTERS))
            .filter(|(_, h)| h.dirty)
            .map(|(&k, h)| (k, h.v))
            .collect();
        for ((r, q), v) in dirty {
            self.b.ins().store(mem(), v, self.regs, Self::offset(r, q));
            if let Some(h) = self.cache.held.get_mut(&(r, q)) {
                h.dirty = false;
            }
        }
    }

    /// Memory up to date, nothing held (block ends, calls).
    pub(super) fn flush_all(&mut self) {
        self.flush_range(0, Reg::MAX);
        self.cache.held.clear();
    }

    /// Drops what is held of registers `lo..=hi` (memory is written behind
    /// the cache's back); flush them first.
    pub(super) fn forget(&mut self, lo: Reg, hi: Reg) {
        let keys: Vec<_> = self
            .cache
            .held
            .range((lo, 0)..=(hi, QUARTERS))
            .map(|(&k, _)| k)
            .collect();
        for k in keys {
            self.cache.held.remove(&k);
        }
    }

    /// The quarters the current op emits (see `only`).
    pub(super) fn quarters(&self) -> std::ops::Range<usize> {
        match self.only {
            Some(q) => q..q + 1,
            None => 0..QUARTERS,
        }
    }

    /// Whether register `r` may be read after op `i` (a pool register, or
    /// live by the analysis; everything when there is none).
    pub(super) fn live_after(&self, i: usize, r: Reg) -> bool {
        r >= self.code.pool_base
            || self
                .after
                .get(i)
                .is_none_or(|bits| crate::liveness::is_live(bits, r))
    }

    /// Ends the held values of quarter `q` (every quarter: `None`): stores
    /// the dirty ones that are live after op `i` (all dirty ones: `i` =
    /// `None`) and drops them all.
    pub(super) fn retire(&mut self, q: Option<usize>, i: Option<usize>) {
        let keys: Vec<(Reg, usize)> = self
            .cache
            .held
            .keys()
            .filter(|k| q.is_none_or(|q| k.1 == q))
            .copied()
            .collect();
        for k in keys {
            let Some(h) = self.cache.held.remove(&k) else {
                continue;
            };
            if h.dirty && i.is_none_or(|i| self.live_after(i, k.0)) {
                self.b
                    .ins()
                    .store(mem(), h.v, self.regs, Self::offset(k.0, k.1));
            }
        }
    }
}
