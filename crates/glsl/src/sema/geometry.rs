//! A geometry shader's layouts and the sizes of its input arrays (GLSL
//! 1.50 §4.3.8.1-2): `layout(triangles) in;` names the input primitive,
//! which sizes every input array (declared before or after it);
//! `layout(triangle_strip, max_vertices = N) out;` the output primitive
//! and the vertex count. They are recorded in [`crate::ir::Module::geometry`].
//!
//! GL_EXT_geometry_shader4's form (before 1.50) has no layouts: the input
//! primitive is the program's GEOMETRY_INPUT_TYPE, which `sema::analyze`
//! records before the first declaration ([`crate::sema::Context`]), so
//! every input array is sized as it is declared.
//!
//! That form's two-dimensional inputs (`varying in float v[][4]`, the
//! built-in `gl_TexCoordIn[][]` and `gl_ClipDistanceIn[][]`) are one-level
//! arrays of a synthesized struct ([`crate::types::StructDef::array_row`],
//! as every array of arrays is) whose one member is the vertex output's
//! array: indexing the outer array yields the member
//! (`v[i]` is the row, a `float[4]` that can be indexed, passed whole and
//! asked its `.length()`), and every later stage sees an ordinary array
//! of structs whose element has the layout of the vertex output it reads.

use super::Analyzer;
use crate::diag::Code;
use crate::ir::{GlobalId, InputPrimitive, OutputPrimitive, Stage, Storage};
use crate::limits;
use crate::source::Span;
use crate::types::ArraySize;

use super::interface::{VarQuals, GEOMETRY_LAYOUTS, TESS_LAYOUTS};

impl Analyzer {
    /// A geometry or tessellation layout identifier where none is
    /// allowed.
    pub(crate) fn misplaced_primitive_layout(&mut self, g: &str, span: Span) {
        let geometry = GEOMETRY_LAYOUTS.contains(&g);
        let tess = TESS_LAYOUTS.contains(&g);
        let own = match self.stage {
            Stage::Geometry => geometry,
            Stage::TessControl | Stage::TessEvaluation => tess,
            _ => false,
        };
        let msg = if own {
            match self.stage {
                Stage::TessControl => format!("`{g}' is allowed only in `layout({g}) out;', not on a declaration"),
                Stage::TessEvaluation => format!("`{g}' is allowed only in `layout({g}) in;', not on a declaration"),
                _ => format!("`{g}' is allowed only in `layout({g}) in;' or `layout({g}) out;', not on a declaration"),
            }
        } else {
            let kind = match (geometry, tess) {
                (true, true) => "geometry or tessellation evaluation shader",
                (true, false) => "geometry shader",
                _ => "tessellation shader",
            };
            format!(
                "`{g}' is a {kind} layout qualifier; not one of a {} shader",
                self.stage.name()
            )
        };
        let code = if own {
            Code::BadQualifier
        } else {
            Code::StageMismatch
        };
        self.error(code, span, msg);
    }

    /// The size of every per-vertex input array: the vertices of a
    /// geometry shader's declared input primitive, gl_MaxPatchVertices in
    /// the tessellation stages (GL_ARB_tessellation_shader §4.3.8.1).
    pub(crate) fn per_vertex_input_size(&self) -> Option<u32> {
        match self.stage {
            Stage::TessControl | Stage::TessEvaluation => Some(limits::MAX_PATCH_VERTICES),
            _ => self.module.geometry.input.map(InputPrimitive::vertices),
        }
    }

    /// `layout(...) in;` (`input`) or `layout(...) out;` of a geometry
    /// shader.
    pub(crate) fn geometry_layout(&mut self, q: &VarQuals, input: bool) {
        if self.lang.ext_geometry_shader4() {
            let span = q.layout.span.unwrap_or(q.storage_span);
            self.error(
                Code::BadQualifier,
                span,
                format!(
                    "a GL_EXT_geometry_shader4 geometry shader has no `layout(...) {}'",
                    if input { "in;" } else { "out;" }
                ),
            )
            .notes
            .push("its primitives and vertex count are the program's: glProgramParameteriEXT with GL_GEOMETRY_INPUT_TYPE_EXT, GL_GEOMETRY_OUTPUT_TYPE_EXT and GL_GEOMETRY_VERTICES_OUT_EXT; or write `#version 150' and the layouts".into());
            return;
        }
        let l = &q.layout;
        let others = [
            l.location.map(|(_, s)| s),
            l.index.map(|(_, s)| s),
            l.block_layout.map(|(_, s)| s),
            l.row_major.map(|(_, s)| s),
            l.origin_upper_left,
            l.pixel_center_integer,
        ];
        for s in others.into_iter().flatten() {
            self.error(
                Code::BadQualifier,
                s,
                format!(
                    "a geometry shader's `layout(...) {}' takes only {}",
                    if input { "in;" } else { "out;" },
                    if input {
                        "points, lines, lines_adjacency, triangles or triangles_adjacency"
                    } else {
                        "points, line_strip, triangle_strip and max_vertices"
                    }
                ),
            );
        }
        let mut prim: Option<(&str, Span)> = None;
        let mut max_vertices = None;
        for (name, value, s) in &l.primitive {
            let ok = if input {
                InputPrimitive::from_name(name).is_some()
            } else {
                name == "max_vertices" || OutputPrimitive::from_name(name).is_some()
            };
            if !ok {
                self.error(
                    Code::BadQualifier,
                    *s,
                    format!(
                        "`{name}' is not an {} layout of a geometry shader",
                        if input { "input" } else { "output" }
                    ),
                )
                .notes
                .push(if input {
                    "inputs: points, lines, lines_adjacency, triangles, triangles_adjacency".into()
                } else {
                    "outputs: points, line_strip, triangle_strip, max_vertices = N".into()
                });
                continue;
            }
            if name == "max_vertices" {
                max_vertices = Some((value.unwrap_or(0), *s));
            } else if let Some((first, _)) = prim {
                self.error(
                    Code::BadQualifier,
                    *s,
                    format!("`{name}' after `{first}': one layout declares one primitive"),
                );
            } else {
                prim = Some((name, *s));
            }
        }
        if input {
            if let Some((name, s)) = prim {
                let p = InputPrimitive::from_name(name).unwrap_or(InputPrimitive::Points);
                self.declare_input_primitive(p, s);
            }
            return;
        }
        if let Some((name, s)) = prim {
            let p = OutputPrimitive::from_name(name).unwrap_or(OutputPrimitive::Points);
            match self.module.geometry.output {
                Some(old) if old != p => {
                    self.error(
                        Code::Redeclared,
                        s,
                        format!(
                            "output primitive `{name}' contradicts the earlier `layout({}) out;'",
                            old.name()
                        ),
                    );
                }
                _ => self.module.geometry.output = Some(p),
            }
        }
        if let Some((n, s)) = max_vertices {
            if n > limits::MAX_GEOMETRY_OUTPUT_VERTICES {
                self.error(
                    Code::BadQualifier,
                    s,
                    format!(
                        "`max_vertices = {n}' exceeds gl_MaxGeometryOutputVertices ({})",
                        limits::MAX_GEOMETRY_OUTPUT_VERTICES
                    ),
                );
                return;
            }
            match self.module.geometry.max_vertices {
                Some(old) if old != n => {
                    self.error(
                        Code::Redeclared,
                        s,
                        format!(
                            "`max_vertices = {n}' contradicts the earlier `max_vertices = {old}'"
                        ),
                    );
                }
                _ => self.module.geometry.max_vertices = Some(n),
            }
        }
    }

    /// Records the input primitive and sizes the input arrays declared so
    /// far (§4.3.8.1: an unsized one takes the primitive's size; a sized
    /// one, or one indexed past it, must agree).
    fn declare_input_primitive(&mut self, p: InputPrimitive, span: Span) {
        if let Some(old) = self.module.geometry.input {
            if old != p {
                self.error(
                    Code::Redeclared,
                    span,
                    format!(
                        "input primitive `{}' contradicts the earlier `layout({}) in;'",
                        p.name(),
                        old.name()
                    ),
                );
            }
            return;
        }
        self.module.geometry.input = Some(p);
        let n = p.vertices();
        if let Some((len, name)) = self.geometry_input_len.clone() {
            if len != n {
                self.error(
                    Code::BadArraySize,
                    span,
                    format!(
                        "`layout({}) in;' gives input arrays {n} elements, but `{name}' is declared with {len}",
                        p.name()
                    ),
                );
            }
        }
        let layout = format!("`layout({}) in;'", p.name());
        self.size_declared_per_vertex(Storage::PerVertexInput, n, &layout, span);
    }

    /// A geometry input array just declared (a variable or a block
    /// instance): sized by the input primitive if there is one, else
    /// checked against the other sized inputs.
    pub(crate) fn size_per_vertex_input(&mut self, id: GlobalId, span: Span) {
        let Some(g) = self.module.globals.get(id.0 as usize) else {
            return;
        };
        let name = g.name.clone();
        match (g.ty.array, self.per_vertex_input_size()) {
            (Some(ArraySize::Unsized), Some(n)) => self.resize_per_vertex_array(id, n),
            (Some(ArraySize::Sized(len)), Some(n)) if len != n => {
                let p = self.module.geometry.input.unwrap_or(InputPrimitive::Points);
                let msg = if self.stage != Stage::Geometry {
                    format!(
                        "input `{name}' has {len} elements, but a {} shader's per-vertex inputs have gl_MaxPatchVertices ({n})",
                        self.stage.name()
                    )
                } else if self.lang.ext_geometry_shader4() {
                    format!(
                        "input `{name}' has {len} elements, but input primitives of type {} have {n} vertices (gl_VerticesIn)",
                        p.gl_name()
                    )
                } else {
                    format!(
                        "input `{name}' has {len} elements, but `layout({}) in;' gives input arrays {n}",
                        p.name()
                    )
                };
                self.error(Code::BadArraySize, span, msg)
                    .notes
                    .push("an input array has one element per vertex of the input primitive; leave the size out (`[]') to take it".into());
            }
            (Some(ArraySize::Sized(len)), None) => match &self.geometry_input_len {
                Some((first, other)) if *first != len => {
                    let msg = format!(
                        "input `{name}' has {len} elements, but `{other}' has {first}; geometry input arrays have one size"
                    );
                    self.error(Code::BadArraySize, span, msg);
                }
                Some(_) => {}
                None => self.geometry_input_len = Some((len, name)),
            },
            _ => {}
        }
    }
}
