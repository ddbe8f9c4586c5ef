//! Vertex fetch: where each vertex input of a draw reads its values
//! (enabled arrays in buffer objects or client memory, current values, or
//! the glBegin/glEnd vertices), and the element indices of glDrawElements.
//!
//! Contract: `Fetcher` is raster's [`raster::VertexFetch`]; in a draw
//! from arrays each input's source is resolved once per draw, so the
//! per-vertex read is a bounds-checked load. Reads past the end of an
//! array give (0, 0, 0, 1); indices past the end of the index data are
//! dropped.

use crate::enums::*;
use crate::vertex::{ArrayData, AttribSource, ImmVertex};
use crate::Context;
use std::sync::Arc;

/// Vertex input slots mapped to attribute sources.
pub(crate) struct Fetcher<'a> {
    pub(crate) ctx: &'a Context,
    pub(crate) slots: Vec<Option<AttribSource>>,
    pub(crate) immediate: Option<&'a [ImmVertex]>,
    /// Per slot, per column (one for non-matrix slots): the attribute's
    /// array or current value, resolved once per draw (array draws only).
    resolved: Vec<Vec<ResolvedAttrib>>,
}

/// Where one attribute's values come from during a draw.
enum ResolvedAttrib {
    /// Every vertex reads this value (the array is disabled: the current
    /// value; or enabled without bytes: the defaults).
    Value([f32; 4]),
    /// An enabled array.
    Array {
        bytes: std::sync::Arc<[u8]>,
        base: usize,
        stride: usize,
        size: usize,
        ty: u32,
        normalized: bool,
    },
}

impl ResolvedAttrib {
    fn new(ctx: &Context, src: AttribSource) -> ResolvedAttrib {
        let Some(a) = ctx.va.array_for(src) else {
            return ResolvedAttrib::Value(ctx.va.current_value(src));
        };
        let Some((bytes, base)) = ctx.array_bytes(a) else {
            return ResolvedAttrib::Value([0.0, 0.0, 0.0, 1.0]);
        };
        let cs = crate::vertex::type_size(a.ty).unwrap_or(4);
        let size = a.size.max(1) as usize;
        ResolvedAttrib::Array {
            bytes,
            base,
            stride: if a.stride > 0 {
                a.stride as usize
            } else {
                cs * size
            },
            size,
            ty: a.ty,
            normalized: a.normalized,
        }
    }

    /// What `Context::fetch_attrib` gives for element `index`: float
    /// arrays read directly, other types through `read_element`.
    fn read(&self, index: u32) -> [f32; 4] {
        match self {
            ResolvedAttrib::Value(v) => *v,
            ResolvedAttrib::Array {
                bytes,
                base,
                stride,
                size,
                ty,
                normalized,
            } => {
                let at = base.saturating_add(stride.saturating_mul(index as usize));
                if *ty != GL_FLOAT {
                    return crate::vertex::read_element(bytes, at, *size, *ty, *normalized);
                }
                let n = (*size).min(4);
                let Some(b) = bytes.get(at..at.saturating_add(4 * n)) else {
                    return [0.0, 0.0, 0.0, 1.0];
                };
                let mut out = [0.0, 0.0, 0.0, 1.0];
                // Component by component with a fixed bound (a copy of a
                // run-time length would call memcpy for 12 or 16 bytes).
                for (k, o) in out.iter_mut().enumerate() {
                    if let Some(c) = b.get(4 * k..4 * k + 4) {
                        *o = f32::from_le_bytes([c[0], c[1], c[2], c[3]]);
                    }
                }
                out
            }
        }
    }
}

impl<'a> Fetcher<'a> {
    /// The resolved array (or value) of column `column` of vertex input
    /// `input_slot`, in a draw from arrays (none in immediate mode).
    fn resolved_column(&self, input_slot: usize, column: usize) -> Option<&ResolvedAttrib> {
        match self.immediate {
            None => self.resolved.get(input_slot).and_then(|c| c.get(column)),
            Some(_) => None,
        }
    }

    /// The fetcher of a draw from arrays (`immediate: None`) or from
    /// glBegin/glEnd vertices.
    pub(crate) fn new(
        ctx: &'a Context,
        slots: Vec<Option<AttribSource>>,
        immediate: Option<&'a [ImmVertex]>,
    ) -> Fetcher<'a> {
        let resolved = if immediate.is_some() {
            Vec::new()
        } else {
            slots
                .iter()
                .map(|s| match s {
                    // Matrix attributes take a location per column.
                    Some(AttribSource::Generic(l)) => (*l as usize..crate::MAX_VERTEX_ATTRIBS)
                        .take(4)
                        .map(|loc| ResolvedAttrib::new(ctx, AttribSource::Generic(loc as u8)))
                        .collect(),
                    Some(src) => vec![ResolvedAttrib::new(ctx, *src)],
                    None => Vec::new(),
                })
                .collect()
        };
        Fetcher {
            ctx,
            slots,
            immediate,
            resolved,
        }
    }

    fn value(&self, src: AttribSource, index: u32) -> [f32; 4] {
        match self.immediate {
            Some(v) => v
                .get(index as usize)
                .map(|v| v.value(src))
                .unwrap_or([0.0, 0.0, 0.0, 1.0]),
            None => self.ctx.fetch_attrib(src, index),
        }
    }
}

impl raster::VertexFetch for Fetcher<'_> {
    fn fetch(&self, input_slot: usize, vertex_index: u32, out: &mut [f32; 4]) {
        self.fetch_column(input_slot, 0, vertex_index, out);
    }

    fn fetch_column_lanes(
        &self,
        input_slot: usize,
        column: usize,
        indices: &[u32],
        out: &mut [[f32; exec::LANES]; 4],
    ) {
        // Arrays of a draw from arrays: the source resolved once for the
        // whole list.
        match self.resolved_column(input_slot, column) {
            Some(r) => raster::fetch_column_each(indices, out, |ix, v| *v = r.read(ix)),
            None => raster::fetch_column_each(indices, out, |ix, v| {
                self.fetch_column(input_slot, column, ix, v)
            }),
        }
    }

    fn fetch_column(
        &self,
        input_slot: usize,
        column: usize,
        vertex_index: u32,
        out: &mut [f32; 4],
    ) {
        if self.immediate.is_none() {
            if let Some(r) = self.resolved_column(input_slot, column) {
                *out = r.read(vertex_index);
            }
            return;
        }
        match self.slots.get(input_slot) {
            Some(Some(AttribSource::Generic(l))) => {
                let loc = *l as usize + column;
                if loc < crate::MAX_VERTEX_ATTRIBS {
                    *out = self.value(AttribSource::Generic(loc as u8), vertex_index);
                }
            }
            Some(Some(src)) if column == 0 => *out = self.value(*src, vertex_index),
            _ => {}
        }
    }
}

impl Context {
    pub(crate) fn read_indices(
        &mut self,
        count: usize,
        ty: u32,
        data: &ArrayData,
    ) -> Option<Indices> {
        let (bytes, base): (Arc<[u8]>, usize) = match data {
            ArrayData::Client(b) => (b.clone(), 0),
            ArrayData::Offset(off) => {
                let b = self.va.element_buffer;
                match self.objects.buffers.get(&b).filter(|_| b != 0) {
                    Some(buf) => (buf.data.clone(), *off),
                    None => {
                        self.set_error(GL_INVALID_OPERATION);
                        return None;
                    }
                }
            }
        };
        let size = match ty {
            GL_UNSIGNED_BYTE => 1,
            GL_UNSIGNED_SHORT => 2,
            _ => 4,
        };
        // The whole indices that fit in the buffer, at most 2^24 of them,
        // converted in one pass per type (the loops vectorize).
        let avail = bytes.get(base..).unwrap_or(&[]);
        let n = count.min(1 << 24).min(avail.len() / size);
        let src = avail.get(..n * size).unwrap_or(&[]);
        if size == 4 && words(src).is_some() {
            // 32-bit indices read where they are (no copy of a large
            // element buffer per draw).
            return Some(Indices::Shared(bytes, base..base + n * 4));
        }
        Some(Indices::Converted(match size {
            1 => src.iter().map(|&b| b as u32).collect(),
            2 => src
                .chunks_exact(2)
                .map(|b| u16::from_le_bytes([b[0], b[1]]) as u32)
                .collect(),
            _ => src
                .chunks_exact(4)
                .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
                .collect(),
        }))
    }
}

/// A draw's element indices: converted, or 32-bit ones in their buffer
/// (bytes `range`), which [`words`] reads in place.
pub(crate) enum Indices {
    Converted(Vec<u32>),
    Shared(Arc<[u8]>, std::ops::Range<usize>),
}

impl Indices {
    pub(crate) fn as_slice(&self) -> &[u32] {
        match self {
            Indices::Converted(v) => v,
            Indices::Shared(bytes, range) => {
                bytes.get(range.clone()).and_then(words).unwrap_or(&[])
            }
        }
    }
}

/// `bytes` as little-endian 32-bit words when they can be read in place:
/// a little-endian target and 4-byte alignment.
fn words(bytes: &[u8]) -> Option<&[u32]> {
    if !cfg!(target_endian = "little") {
        return None;
    }
    // SAFETY: every bit pattern of four bytes is a valid u32, and
    // `align_to` only puts whole, aligned words in the middle slice.
    let (head, mid, tail) = unsafe { bytes.align_to::<u32>() };
    (head.is_empty() && tail.is_empty()).then_some(mid)
}
