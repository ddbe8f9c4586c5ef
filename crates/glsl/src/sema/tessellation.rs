//! The tessellation stages' language (GL_ARB_tessellation_shader): the
//! control shader's `layout(vertices = N) out;`, which sizes its
//! per-vertex outputs (declared before or after it), the evaluation
//! shader's `layout(triangles|quads|isolines, spacing, order, point_mode)
//! in;`, the rule that an invocation writes only its own output vertex
//! (`[gl_InvocationID]`, §4.3.6), and where `barrier()` may be called
//! (§8.X: in `main`, outside all control flow, before any `return`).
//! The layouts are recorded in [`ir::Module::tessellation`].

use super::interface::VarQuals;
use super::Analyzer;
use crate::ast;
use crate::diag::Code;
use crate::ir::{self, GlobalId, Stage, Storage, TessMode, TessSpacing, VertexOrder};
use crate::limits;
use crate::source::Span;
use crate::types::ArraySize;

impl Analyzer {
    /// `layout(...) out;` of a control shader (`input` false) or
    /// `layout(...) in;` of an evaluation shader.
    pub(crate) fn tess_layout(&mut self, q: &VarQuals, input: bool) {
        let l = &q.layout;
        let others = [
            l.location.map(|(_, s)| s),
            l.index.map(|(_, s)| s),
            l.block_layout.map(|(_, s)| s),
            l.row_major.map(|(_, s)| s),
            l.binding.map(|(_, s)| s),
            l.origin_upper_left,
            l.pixel_center_integer,
        ];
        let takes = if input {
            "triangles, quads, isolines, equal_spacing, fractional_even_spacing, fractional_odd_spacing, cw, ccw and point_mode"
        } else {
            "vertices = N"
        };
        let what = if input {
            "a tessellation evaluation shader's `layout(...) in;'"
        } else {
            "a tessellation control shader's `layout(...) out;'"
        };
        for s in others.into_iter().flatten() {
            self.error(Code::BadQualifier, s, format!("{what} takes only {takes}"));
        }
        if let Some((_, s)) = l.local_size.iter().flatten().next() {
            self.misplaced_local_size(*s);
        }
        // GL_ARB_shading_language_420pack: within one declaration, the
        // last `vertices = N` overrides the earlier ones.
        let mut vertices = None;
        for (name, value, s) in l.primitive.clone() {
            let known = if input {
                name != "vertices" && super::interface::TESS_LAYOUTS.contains(&name.as_str())
            } else {
                name == "vertices"
            };
            if !known {
                self.error(
                    Code::BadQualifier,
                    s,
                    format!("`{name}' is not a layout of {what}"),
                )
                .notes
                .push(format!("it takes {takes}"));
                continue;
            }
            if name == "vertices" {
                vertices = Some((value.unwrap_or(0), s));
                continue;
            }
            let t = &mut self.module.tessellation;
            let clash = match name.as_str() {
                "triangles" | "quads" | "isolines" => {
                    let m = match name.as_str() {
                        "triangles" => TessMode::Triangles,
                        "quads" => TessMode::Quads,
                        _ => TessMode::Isolines,
                    };
                    replace(&mut t.mode, m).map(TessMode::name)
                }
                "equal_spacing" | "fractional_even_spacing" | "fractional_odd_spacing" => {
                    let sp = match name.as_str() {
                        "equal_spacing" => TessSpacing::Equal,
                        "fractional_even_spacing" => TessSpacing::FractionalEven,
                        _ => TessSpacing::FractionalOdd,
                    };
                    replace(&mut t.spacing, sp).map(TessSpacing::name)
                }
                "cw" | "ccw" => {
                    let o = if name == "cw" {
                        VertexOrder::Cw
                    } else {
                        VertexOrder::Ccw
                    };
                    replace(&mut t.order, o).map(VertexOrder::name)
                }
                _ => {
                    t.point_mode = true;
                    None
                }
            };
            if let Some(old) = clash {
                self.error(
                    Code::Redeclared,
                    s,
                    format!("`{name}' contradicts the earlier `{old}'"),
                )
                .notes
                .push("GL_ARB_tessellation_shader §4.3.8.1: every declaration of the primitive mode, spacing or vertex order in a program names the same one".into());
            }
        }
        if let Some((n, s)) = vertices {
            self.declare_output_vertices(n, s);
        }
    }

    /// `layout(vertices = n) out;`: records the output patch size and
    /// sizes the per-vertex outputs declared so far (an unsized one takes
    /// it; a sized one must agree, §4.3.8.2).
    fn declare_output_vertices(&mut self, n: u32, span: Span) {
        if n == 0 || n > limits::MAX_PATCH_VERTICES {
            self.error(
                Code::BadQualifier,
                span,
                format!(
                    "`vertices = {n}' is out of range: an output patch has 1 to gl_MaxPatchVertices ({}) vertices",
                    limits::MAX_PATCH_VERTICES
                ),
            );
            return;
        }
        if let Some(old) = self.module.tessellation.vertices {
            if old != n {
                self.error(
                    Code::Redeclared,
                    span,
                    format!("`vertices = {n}' contradicts the earlier `vertices = {old}'"),
                );
            }
            return;
        }
        self.module.tessellation.vertices = Some(n);
        if let Some((len, name)) = self.tess_output_len.clone() {
            if len != n {
                self.error(
                    Code::BadArraySize,
                    span,
                    format!("`layout(vertices = {n}) out;' gives per-vertex outputs {n} elements, but `{name}' is declared with {len}"),
                );
            }
        }
        let layout = format!("`layout(vertices = {n}) out;'");
        self.size_declared_per_vertex(Storage::PerVertexOutput, n, &layout, span);
    }

    /// A control shader's per-vertex output array just declared (a
    /// variable or block instance): sized by the output patch if declared,
    /// else checked against the other sized outputs.
    pub(crate) fn size_per_vertex_output(&mut self, id: GlobalId, span: Span) {
        let Some(g) = self.module.globals.get(id.0 as usize) else {
            return;
        };
        let name = g.name.clone();
        match (g.ty.array, self.module.tessellation.vertices) {
            (Some(ArraySize::Unsized), Some(n)) => self.resize_per_vertex_array(id, n),
            (Some(ArraySize::Sized(len)), Some(n)) if len != n => {
                self.error(
                    Code::BadArraySize,
                    span,
                    format!("output `{name}' has {len} elements, but `layout(vertices = {n}) out;' gives per-vertex outputs {n}"),
                )
                .notes
                .push("a per-vertex output has one element per vertex of the output patch; leave the size out (`[]') to take it".into());
            }
            (Some(ArraySize::Sized(len)), None) => match &self.tess_output_len {
                Some((first, other)) if *first != len => {
                    let msg = format!(
                        "output `{name}' has {len} elements, but `{other}' has {first}; per-vertex outputs have one size"
                    );
                    self.error(Code::BadArraySize, span, msg);
                }
                Some(_) => {}
                None => self.tess_output_len = Some((len, name)),
            },
            _ => {}
        }
    }

    /// Gives the unsized per-vertex arrays of `storage` declared so far
    /// `n` elements, as `layout` (just declared) says; an error for one
    /// already indexed past them.
    pub(crate) fn size_declared_per_vertex(
        &mut self,
        storage: Storage,
        n: u32,
        layout: &str,
        span: Span,
    ) {
        let ids: Vec<GlobalId> = (0..self.module.globals.len())
            .map(|i| GlobalId(i as u32))
            .filter(|g| {
                let g = &self.module.globals[g.0 as usize];
                g.storage == storage && g.ty.array == Some(ArraySize::Unsized)
            })
            .collect();
        for id in ids {
            let g = &self.module.globals[id.0 as usize];
            if g.implicit_size > n {
                let msg = format!(
                    "{layout} gives `{}' {n} elements, but index {} is already used",
                    g.name,
                    g.implicit_size - 1
                );
                self.error(Code::IndexOutOfRange, span, msg);
            }
            self.resize_per_vertex_array(id, n);
        }
    }

    /// Gives a per-vertex array (and its block instance) `n` elements.
    pub(crate) fn resize_per_vertex_array(&mut self, id: GlobalId, n: u32) {
        let Some(g) = self.module.globals.get_mut(id.0 as usize) else {
            return;
        };
        g.ty.array = Some(ArraySize::Sized(n));
        if let Some(b) = g.block {
            if let Some(blk) = self.module.blocks.get_mut(b.0 as usize) {
                if blk.instance.is_some() {
                    blk.array = Some(n);
                }
            }
        }
    }

    /// Whether `e` is a control shader's per-vertex output array whose
    /// size (the output patch's) is not declared yet.
    pub(crate) fn is_unsized_output_patch(&self, e: &ir::Expr) -> bool {
        let ir::ExprKind::Global(g) = e.kind else {
            return false;
        };
        e.ty.array == Some(ArraySize::Unsized)
            && self
                .module
                .globals
                .get(g.0 as usize)
                .is_some_and(|g| g.storage == Storage::PerVertexOutput)
    }

    /// §4.3.6: a per-vertex output written through `base[index]` must be
    /// indexed by the identifier `gl_InvocationID` itself.
    pub(crate) fn check_output_vertex_index(&mut self, base: &ir::Expr, index: &ast::Expr) {
        if self.stage != Stage::TessControl {
            return;
        }
        let ir::ExprKind::Global(g) = base.kind else {
            return;
        };
        let Some(g) = self.module.globals.get(g.0 as usize) else {
            return;
        };
        if g.storage != Storage::PerVertexOutput {
            return;
        }
        let by_invocation = matches!(&index.kind, ast::ExprKind::Ident(id) if id.name == "gl_InvocationID")
            && matches!(
                self.lookup("gl_InvocationID"),
                Some(super::scope::Symbol::Var(super::scope::Var::Builtin(_)))
            );
        if !by_invocation {
            let name = g.name.clone();
            self.error(
                Code::NotAnLvalue,
                index.span,
                format!("`{name}' can only be written at this invocation's vertex: index it with `gl_InvocationID'"),
            )
            .notes
            .push("GL_ARB_tessellation_shader §4.3.6: an invocation writes only its own output vertex; the index must be the identifier gl_InvocationID itself (other vertices can be read)".into());
        }
    }

    /// A per-vertex output written whole (`x = ...` of `out float x[]`):
    /// no index names the invocation's vertex.
    pub(crate) fn check_whole_output_write(&mut self, lv: &ir::Expr) {
        let ir::ExprKind::Global(g) = lv.kind else {
            return;
        };
        let Some(g) = self.module.globals.get(g.0 as usize) else {
            return;
        };
        if g.storage == Storage::PerVertexOutput && !self.builtin_mode {
            let name = g.name.clone();
            self.error(
                Code::NotAnLvalue,
                lv.span,
                format!("`{name}' cannot be written whole: write its element `{name}[gl_InvocationID]'"),
            )
            .notes
            .push("GL_ARB_tessellation_shader §4.3.6: an invocation writes only its own output vertex".into());
        }
    }

    /// §8.X: `barrier()` of a control shader only in `main`, outside
    /// every `if`, loop and `switch`, and before any `return`.
    pub(crate) fn check_barrier_placement(&mut self, span: Span) {
        if self.stage != Stage::TessControl {
            return;
        }
        let Some(cur) = self.cur.as_ref() else {
            return;
        };
        let in_main = self
            .module
            .functions
            .get(cur.id.0 as usize)
            .is_some_and(|f| f.name == "main");
        let why = if !in_main {
            Some("outside `main'")
        } else if cur.loop_depth > 0 {
            Some("inside a loop")
        } else if cur.switch_depth > 0 {
            Some("inside a `switch'")
        } else if cur.if_depth > 0 {
            Some("inside an `if'")
        } else if cur.returned {
            Some("after a `return'")
        } else {
            None
        };
        if let Some(why) = why {
            self.error(
                Code::StageMismatch,
                span,
                format!("`barrier()' cannot be called {why}"),
            )
            .notes
            .push("GL_ARB_tessellation_shader §8.X: a control shader calls barrier() only in main(), outside all control flow and before any return".into());
        }
    }
}

/// Sets `slot` to `v`; the earlier value when it was another.
fn replace<T: Copy + PartialEq>(slot: &mut Option<T>, v: T) -> Option<T> {
    match *slot {
        Some(old) if old != v => Some(old),
        _ => {
            *slot = Some(v);
            None
        }
    }
}
