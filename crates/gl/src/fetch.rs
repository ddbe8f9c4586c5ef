//! Vertex fetch: where each vertex input of a draw reads its values
//! (enabled arrays in buffer objects or client memory, instanced arrays,
//! current values, the glBegin/glEnd vertices, `gl_VertexID` and
//! `gl_InstanceID`), and the element indices of glDrawElements.
//!
//! Contract: `Fetcher` is raster's [`raster::VertexFetch`]; in a draw
//! from arrays each input's source is resolved once per draw, so the
//! per-vertex read is a bounds-checked load. Reads past the end of an
//! array give (0, 0, 0, 1); indices past the end of the index data are
//! dropped. Integer inputs (`int`, `uint` and their vectors) get the
//! integers' bits, as `exec::Batch::inputs` says: from integer arrays
//! (glVertexAttribIPointer) and integer current values unconverted.

use crate::enums::*;
use crate::vertex::{ArrayData, AttribSource, ImmVertex};
use crate::vertex_format::{
    element_size, float_view, integer_bits, read_element, read_integer_element, ValueKind,
};
use crate::Context;
use std::sync::Arc;

/// What feeds one vertex input slot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum InputSource {
    Attrib(AttribSource),
    /// `gl_VertexID`: the element index fetched (after the base vertex).
    VertexId,
    /// `gl_InstanceID`: the instance number.
    InstanceId,
}

/// Which instances a draw's vertices belong to. A draw of one instance
/// (`stride` 0) fetches its element indices as they are; a batch of
/// instances drawn at once numbers its vertices so that vertex `v` is
/// element `lo + v % stride` of instance `first + v / stride`
/// (`crate::draw`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct InstanceBatch {
    pub(crate) first: u32,
    pub(crate) lo: u32,
    pub(crate) stride: u32,
}

impl InstanceBatch {
    /// Instance `instance` alone.
    pub(crate) fn one(instance: u32) -> InstanceBatch {
        InstanceBatch {
            first: instance,
            lo: 0,
            stride: 0,
        }
    }

    /// (element index, instance) of vertex `v`.
    #[inline]
    fn decode(self, v: u32) -> (u32, u32) {
        match self.stride {
            0 => (v, self.first),
            s => (self.lo.wrapping_add(v % s), self.first.wrapping_add(v / s)),
        }
    }
}

/// Vertex input slots mapped to their sources.
pub(crate) struct Fetcher<'a> {
    pub(crate) ctx: &'a Context,
    pub(crate) slots: Vec<Option<InputSource>>,
    /// Per slot: how the shader reads it (integer inputs take bits,
    /// `exec::Batch::inputs`).
    kinds: Vec<ValueKind>,
    pub(crate) immediate: Option<&'a [ImmVertex]>,
    batch: InstanceBatch,
    /// Per slot, per column (one for non-matrix slots): the attribute's
    /// array or current value, resolved once per draw (array draws only).
    resolved: Vec<Vec<ResolvedAttrib>>,
}

/// How an array's elements become an input's components.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Convert {
    /// To float values (normalized when the array says so).
    Float,
    /// An integer array (glVertexAttribIPointer) into an integer input:
    /// the integers' bits.
    Bits,
    /// A float-converting array into an integer input (undefined in GL):
    /// the values' integer parts, as bits.
    FloatToBits(ValueKind),
}

/// Where one attribute's values come from during a draw.
enum ResolvedAttrib {
    /// Every vertex reads this value (the array is disabled: the current
    /// value; or enabled without bytes: the defaults). Already in the
    /// input's form.
    Value([f32; 4]),
    /// An instanced array: element instance / divisor of `array`
    /// (GL 3.3 §2.8.2).
    PerInstance {
        array: Box<ResolvedAttrib>,
        divisor: u32,
    },
    /// An enabled array.
    Array {
        bytes: std::sync::Arc<[u8]>,
        base: usize,
        stride: usize,
        size: usize,
        ty: u32,
        normalized: bool,
        convert: Convert,
    },
}

/// The defaults of a missing element, in the form of an input of `kind`.
fn defaults(kind: ValueKind) -> [f32; 4] {
    match kind {
        ValueKind::Float => [0.0, 0.0, 0.0, 1.0],
        _ => [0, 0, 0, 1].map(f32::from_bits),
    }
}

/// A stored value (`stored` as specified) in the form of an input of
/// `kind`.
fn as_input(v: [f32; 4], stored: ValueKind, kind: ValueKind) -> [f32; 4] {
    match kind {
        ValueKind::Float => float_view(v, stored),
        _ => integer_bits(v, stored, kind).map(f32::from_bits),
    }
}

impl ResolvedAttrib {
    fn new(ctx: &Context, src: AttribSource, kind: ValueKind) -> ResolvedAttrib {
        let Some(a) = ctx.va.array_for(src) else {
            let stored = match src {
                AttribSource::Generic(i) => ctx
                    .va
                    .generic_kind
                    .get(i as usize)
                    .copied()
                    .unwrap_or_default(),
                _ => ValueKind::Float,
            };
            let v = match src {
                AttribSource::Generic(i) => ctx.va.generic.get(i as usize).copied(),
                _ => None,
            };
            return ResolvedAttrib::Value(match v {
                Some(v) => as_input(v, stored, kind),
                None => as_input(ctx.va.current_value(src), ValueKind::Float, kind),
            });
        };
        let Some((bytes, base)) = ctx.array_bytes(a) else {
            return ResolvedAttrib::Value(defaults(kind));
        };
        // The component count (or BGRA) as `read_element` takes it.
        let size = a.size.max(1) as usize;
        let element = element_size(a.size, a.ty).unwrap_or(16);
        let convert = match (kind, a.integer) {
            (ValueKind::Float, _) => Convert::Float,
            (_, true) => Convert::Bits,
            (k, false) => Convert::FloatToBits(k),
        };
        let r = ResolvedAttrib::Array {
            bytes,
            base,
            stride: if a.stride > 0 {
                a.stride as usize
            } else {
                element
            },
            size,
            ty: a.ty,
            // An integer array is never normalized.
            normalized: a.normalized && !a.integer,
            convert,
        };
        match a.divisor {
            0 => r,
            divisor => ResolvedAttrib::PerInstance {
                array: Box::new(r),
                divisor,
            },
        }
    }

    /// Element `index` in the input's form: float arrays read directly,
    /// other types through `read_element` / `read_integer_element`.
    fn read(&self, index: u32, instance: u32) -> [f32; 4] {
        match self {
            ResolvedAttrib::Value(v) => *v,
            ResolvedAttrib::PerInstance { array, divisor } => array.read(instance / divisor, 0),
            ResolvedAttrib::Array {
                bytes,
                base,
                stride,
                size,
                ty,
                normalized,
                convert,
            } => {
                let at = base.saturating_add(stride.saturating_mul(index as usize));
                match convert {
                    Convert::Float => {}
                    Convert::Bits => {
                        return read_integer_element(bytes, at, *size, *ty).map(f32::from_bits)
                    }
                    Convert::FloatToBits(k) => {
                        let v = read_element(bytes, at, *size, *ty, *normalized);
                        return integer_bits(v, ValueKind::Float, *k).map(f32::from_bits);
                    }
                }
                if *ty != GL_FLOAT {
                    return read_element(bytes, at, *size, *ty, *normalized);
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

    /// The fetcher of the instances `batch` of a draw from arrays
    /// (`immediate: None`) or of glBegin/glEnd vertices, for the inputs
    /// of `vs`.
    pub(crate) fn new(
        ctx: &'a Context,
        vs: &exec::Kernel,
        immediate: Option<&'a [ImmVertex]>,
        batch: InstanceBatch,
    ) -> Fetcher<'a> {
        let attribs = ctx.input_sources(vs);
        let iface = vs.interface();
        let slots: Vec<Option<InputSource>> = iface
            .inputs
            .iter()
            .zip(attribs)
            .map(|(s, a)| match s.name.as_str() {
                "gl_VertexID" => Some(InputSource::VertexId),
                "gl_InstanceID" => Some(InputSource::InstanceId),
                _ => a.map(InputSource::Attrib),
            })
            .collect();
        let kinds: Vec<ValueKind> = iface
            .inputs
            .iter()
            .map(|s| match s.ty.scalar() {
                Some(glsl::types::Scalar::Int) => ValueKind::Int,
                Some(glsl::types::Scalar::Uint) => ValueKind::Uint,
                _ => ValueKind::Float,
            })
            .collect();
        let resolved = if immediate.is_some() {
            Vec::new()
        } else {
            slots
                .iter()
                .zip(&kinds)
                .map(|(s, &kind)| match s {
                    // Matrix attributes take a location per column.
                    Some(InputSource::Attrib(AttribSource::Generic(l))) => (*l as usize
                        ..crate::MAX_VERTEX_ATTRIBS)
                        .take(4)
                        .map(|loc| {
                            let src = AttribSource::Generic(loc as u8);
                            ResolvedAttrib::new(ctx, src, kind)
                        })
                        .collect(),
                    Some(InputSource::Attrib(src)) => {
                        vec![ResolvedAttrib::new(ctx, *src, kind)]
                    }
                    Some(InputSource::InstanceId | InputSource::VertexId) | None => Vec::new(),
                })
                .collect()
        };
        Fetcher {
            ctx,
            slots,
            kinds,
            immediate,
            batch,
            resolved,
        }
    }

    /// Attribute `src` of glBegin/glEnd vertex `index`, as an input of
    /// `kind`.
    fn immediate_value(&self, src: AttribSource, index: u32, kind: ValueKind) -> [f32; 4] {
        let Some(v) = self.immediate.and_then(|v| v.get(index as usize)) else {
            return defaults(kind);
        };
        let stored = match src {
            AttribSource::Generic(i) if i > 0 => self
                .ctx
                .va
                .generic_kind
                .get(i as usize)
                .copied()
                .unwrap_or_default(),
            _ => ValueKind::Float,
        };
        as_input(v.value(src), stored, kind)
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
            Some(r) => raster::fetch_column_each(indices, out, |ix, v| {
                let (index, instance) = self.batch.decode(ix);
                *v = r.read(index, instance)
            }),
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
        let kind = self.kinds.get(input_slot).copied().unwrap_or_default();
        let (index, instance) = self.batch.decode(vertex_index);
        match self.slots.get(input_slot) {
            Some(Some(InputSource::VertexId)) if column == 0 => {
                *out = [index, 0, 0, 1].map(f32::from_bits);
                return;
            }
            Some(Some(InputSource::InstanceId)) if column == 0 => {
                *out = [instance, 0, 0, 1].map(f32::from_bits);
                return;
            }
            _ => {}
        }
        if self.immediate.is_none() {
            match self.resolved_column(input_slot, column) {
                Some(r) => *out = r.read(index, instance),
                // No source: the defaults, as integers for an integer
                // input (`out` starts as float ones).
                None => *out = defaults(kind),
            }
            return;
        }
        match self.slots.get(input_slot) {
            Some(Some(InputSource::Attrib(AttribSource::Generic(l)))) => {
                let loc = *l as usize + column;
                if loc < crate::MAX_VERTEX_ATTRIBS {
                    let src = AttribSource::Generic(loc as u8);
                    *out = self.immediate_value(src, vertex_index, kind);
                }
            }
            Some(Some(InputSource::Attrib(src))) if column == 0 => {
                *out = self.immediate_value(*src, vertex_index, kind)
            }
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
            // Core contexts have no client index arrays (GL 3.3 core
            // appendix E.2.2).
            ArrayData::Client(_) if self.is_core() => {
                self.set_error(GL_INVALID_OPERATION);
                return None;
            }
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
        // The whole indices that fit in the buffer (the count is at most
        // MAX_DRAW_VERTICES, checked with the draw), converted in one pass
        // per type (the loops vectorize).
        let avail = bytes.get(base..).unwrap_or(&[]);
        let n = count
            .min(crate::MAX_DRAW_VERTICES as usize)
            .min(avail.len() / size);
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
