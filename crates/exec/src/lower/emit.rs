//! A geometry shader's `EmitVertex()` and `EndPrimitive()` (GLSL 1.50
//! §8.10) as register writes, so that every executor runs them with the
//! ops it already has.
//!
//! Each lane (one input primitive) owns an emit buffer of registers laid
//! out as [`crate::Emitted`] says: `max_vertices` copies of the output
//! variables, a strip number per copy, the count of vertices emitted and
//! the current strip number. `EmitVertex()` scatters the output
//! variables into copy `count` on the lanes whose count is below
//! `max_vertices` (later calls are dropped, as the spec allows) and
//! counts; `EndPrimitive()` moves the lanes to a new strip number. The
//! buffer registers are the kernel's outputs: the pipeline reads the
//! emitted strips from the batch after the run.

use super::{unsupported, Lowerer, R};
use crate::interface::Emitted;
use crate::program::{Op, Reg};
use glsl::types::Scalar;

/// Geometry kernels emit at most this many output components per
/// invocation (the vertices times the components of one), far above
/// GL's `MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS` (1,024) that the linker
/// enforces for programs through GL.
pub const MAX_EMITTED_COMPONENTS: usize = 1 << 16;

/// The registers of a geometry kernel's emit buffer.
pub(super) struct EmitBuffer {
    /// The output variables' registers, in interface order: what one
    /// `EmitVertex()` copies.
    vertex: Vec<Reg>,
    /// `max_vertices * vertex.len()` registers: the emitted copies.
    copies: Reg,
    /// `max_vertices` registers: each copy's strip number.
    strips: Reg,
    count: Reg,
    strip: Reg,
    layout: Emitted,
}

impl<'m> Lowerer<'m> {
    /// Allocates the emit buffer of a geometry kernel whose output
    /// variables live in `vertex` (their registers, in interface order).
    pub(super) fn alloc_emit_buffer(&mut self, vertex: Vec<Reg>) -> R<EmitBuffer> {
        let g = self.m.geometry;
        let (Some(input), Some(output), Some(max)) = (g.input, g.output, g.max_vertices) else {
            return unsupported(
                "a geometry shader needs its input and output primitives and max_vertices",
            );
        };
        let max_vertices = max as usize;
        let per = vertex.len();
        if max_vertices.saturating_mul(per + 1) > MAX_EMITTED_COMPONENTS {
            return unsupported(format!(
                "a geometry shader emitting {max_vertices} vertices of {per} components is \
                 beyond the executor's {MAX_EMITTED_COMPONENTS} components"
            ));
        }
        let copies = self.alloc(max_vertices * per)?;
        let strips = self.alloc(max_vertices)?;
        let count = self.alloc(1)?;
        let strip = self.alloc(1)?;
        // Registers start at 0 on every run; said explicitly for the
        // counters, which the program reads before writing.
        self.p.init.push((count, 0));
        self.p.init.push((strip, 0));
        Ok(EmitBuffer {
            vertex,
            copies,
            strips,
            count,
            strip,
            layout: Emitted {
                input,
                output,
                max_vertices,
                vertex_components: per,
            },
        })
    }

    /// `EmitVertex()`: on the active lanes that have room, the output
    /// variables into the next copy, with the current strip number.
    pub(super) fn emit_vertex(&mut self) -> R<()> {
        let Some(e) = self.emitter.as_ref() else {
            return unsupported("EmitVertex outside a geometry shader");
        };
        let (count, strip, copies, strips) = (e.count, e.strip, e.copies, e.strips);
        let max_vertices = e.layout.max_vertices as u32;
        let vertex = e.vertex.clone();
        if max_vertices == 0 {
            return Ok(());
        }
        let per = vertex.len() as u32;
        let mark = self.next_reg;
        let slot = self.new_slot();
        self.emit(Op::SaveMask { slot })?;
        let limit = self.konst(max_vertices)?;
        let room = self.emit_temp(|d| Op::ILt {
            d,
            a: count,
            b: limit,
        })?;
        self.emit(Op::AndMask { c: room })?;
        if per > 0 {
            let stride = self.konst(per)?;
            let at = self.emit_temp(|d| Op::IMul {
                d,
                a: count,
                b: stride,
            })?;
            for (c, &a) in vertex.iter().enumerate() {
                self.emit(Op::Scatter {
                    base: copies + c as u32,
                    off: at,
                    max: (max_vertices - 1) * per,
                    a,
                })?;
            }
        }
        self.emit(Op::Scatter {
            base: strips,
            off: count,
            max: max_vertices - 1,
            a: strip,
        })?;
        self.increment(count)?;
        self.emit(Op::RestoreMask { slot })?;
        self.next_reg = mark;
        Ok(())
    }

    /// `EndPrimitive()`: the active lanes' next vertices start a new strip.
    pub(super) fn end_primitive(&mut self) -> R<()> {
        let Some(strip) = self.emitter.as_ref().map(|e| e.strip) else {
            return unsupported("EndPrimitive outside a geometry shader");
        };
        let mark = self.next_reg;
        self.increment(strip)?;
        self.next_reg = mark;
        Ok(())
    }

    /// `r += 1` on the active lanes.
    fn increment(&mut self, r: Reg) -> R<()> {
        let one = self.konst(1)?;
        let next = self.emit_temp(|d| Op::IAdd { d, a: r, b: one })?;
        self.emit(Op::Store { d: r, a: next })
    }
}

impl EmitBuffer {
    /// The kernel's outputs, given those of one vertex (register, output
    /// component, kind), and its layout: every copy, the strip numbers,
    /// the count.
    pub(super) fn outputs(&self, vertex: &[(Reg, usize, Scalar)]) -> Vec<(Reg, usize, Scalar)> {
        let l = self.layout;
        let per = l.vertex_components as u32;
        let mut out = Vec::with_capacity(l.components());
        for v in 0..l.max_vertices {
            let base = self.copies + v as u32 * per;
            out.extend(
                vertex
                    .iter()
                    .map(|&(_, oc, kind)| (base + oc as u32, l.vertex(v) + oc, kind)),
            );
        }
        out.extend((0..l.max_vertices).map(|v| (self.strips + v as u32, l.strip(v), Scalar::Int)));
        out.push((self.count, l.count(), Scalar::Int));
        out
    }

    pub(super) fn layout(&self) -> Emitted {
        self.layout
    }
}
