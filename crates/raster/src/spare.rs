//! The big buffers of a draw (vertex outputs, index tables, the
//! per-vertex set-up table, set-up chunks' primitives and planes), kept
//! by the [`crate::Workers`] a draw ran on for its next draws.
//!
//! Takes the buffers a draw is done with ([`Spare::keep_chunks`] and friends);
//! gives them back, emptied or as they are, to the next draw. Nothing in
//! them carries over as a value: each draw overwrites or clears what it
//! reuses.

use crate::interpolate::Plane;
use crate::prim::Prim;
use crate::setup::Corner;
use crate::shaded::Vertices;

/// Buffers of an earlier draw, kept (emptied) for the next draws on the
/// same [`crate::Workers`]: a draw that fits in them allocates no fresh
/// memory, whose first touch costs a page fault per 4 KiB. At most
/// [`Spare::LIMIT`] bytes of capacity are kept.
#[derive(Default)]
pub(crate) struct Spare {
    /// Set-up chunks' primitives and varyings.
    pub chunks: Vec<(Vec<Prim>, Vec<Plane>)>,
    /// Vertex outputs (kept with their values: a draw overwrites them).
    pub outputs: Vec<f32>,
    /// A geometry stage's emitted vertices (emptied). The vertex stage of
    /// a draw with a geometry stage takes `outputs` and leaves its buffer
    /// here; the emitted vertices' buffer ends the draw in `outputs`: the
    /// two trade places, so steady draws allocate neither.
    pub emitted: Vec<f32>,
    /// The per-vertex set-up table (kept with its length: a draw of as
    /// many vertices overwrites it without clearing it first).
    pub corners: Vec<Corner>,
    /// The vertex stage's index tables (distinct indices, each index's
    /// vertex, the index-to-vertex table).
    pub tables: Vec<Vec<u32>>,
}

impl Spare {
    /// Most bytes of capacity kept.
    const LIMIT: usize = 256 << 20;

    /// Bytes of capacity of a set-up chunk's buffers.
    fn chunk_bytes((p, a): &(Vec<Prim>, Vec<Plane>)) -> usize {
        p.capacity() * std::mem::size_of::<Prim>() + a.capacity() * std::mem::size_of::<Plane>()
    }

    fn bytes(&self) -> usize {
        self.chunks.iter().map(Spare::chunk_bytes).sum::<usize>()
            + self.outputs.capacity() * 4
            + self.emitted.capacity() * 4
            + self.corners.capacity() * std::mem::size_of::<Corner>()
            + self.tables.iter().map(|t| t.capacity() * 4).sum::<usize>()
    }

    /// A vertex-stage index table (empty) from an earlier draw, or a new
    /// one.
    pub fn table(&mut self) -> Vec<u32> {
        self.tables.pop().unwrap_or_default()
    }

    /// Keeps the per-vertex set-up table (as it is) as far as the limit
    /// allows.
    pub fn keep_corners(&mut self, corners: Vec<Corner>) {
        let mut bytes = self.bytes();
        keep_larger(&mut self.corners, corners, &mut bytes);
    }

    /// Keeps `emitted` (emptied) as the next geometry stage's buffer, as
    /// far as the limit allows.
    pub fn keep_emitted(&mut self, mut emitted: Vec<f32>) {
        let mut bytes = self.bytes();
        emitted.clear();
        keep_larger(&mut self.emitted, emitted, &mut bytes);
    }

    /// Keeps the index tables (emptied) as far as the limit allows.
    pub fn keep_tables(&mut self, tables: impl IntoIterator<Item = Vec<u32>>) {
        let mut bytes = self.bytes();
        for mut t in tables {
            if bytes + t.capacity() * 4 > Spare::LIMIT {
                break;
            }
            bytes += t.capacity() * 4;
            t.clear();
            self.tables.push(t);
        }
    }

    /// Keeps a draw's set-up chunks (emptied) as far as the limit allows.
    pub fn keep_chunks(&mut self, chunks: Vec<(Vec<Prim>, Vec<Plane>)>) {
        let mut bytes = self.bytes();
        for mut c in chunks {
            let more = Spare::chunk_bytes(&c);
            if bytes + more > Spare::LIMIT {
                break;
            }
            bytes += more;
            c.0.clear();
            c.1.clear();
            self.chunks.push(c);
        }
    }

    /// Keeps a draw's vertex outputs (as they are) and its index table
    /// (emptied) as far as the limit allows.
    pub fn keep_vertices(&mut self, vertices: Vertices) {
        let mut bytes = self.bytes();
        keep_larger(&mut self.outputs, vertices.outputs, &mut bytes);
        self.keep_tables([vertices.vertex_of]);
    }
}

/// Puts `v` in `slot` when it has more capacity than `slot` and the kept
/// bytes (`*bytes`, which count `slot`'s, updated) stay within
/// [`Spare::LIMIT`].
fn keep_larger<T>(slot: &mut Vec<T>, v: Vec<T>, bytes: &mut usize) {
    let size = std::mem::size_of::<T>();
    let after = *bytes - slot.capacity() * size + v.capacity() * size;
    if v.capacity() > slot.capacity() && after <= Spare::LIMIT {
        *bytes = after;
        *slot = v;
    }
}
