//! # shaderbox-debugger: why a pixel is what it is
//!
//! Turns the pipeline's pixel probe ([`raster::probe_draw`], collected per
//! draw by [`gl::Context::set_debug`]) into a report a person reads or a
//! tool parses: for each draw that touched the pixel, each fragment in
//! order with its primitive (the vertices after the vertex shader with
//! every output; with a geometry stage, the vertices it emitted and the
//! input primitive whose invocation emitted them), its interpolated inputs, each statement its shader
//! executed with the source line and the values it stored (loop
//! iterations appear as repeated statements), `debugPrintfEXT` output,
//! `discard`, its outputs, and what the per-fragment operations did (alpha,
//! stencil and depth tests with the values compared, blending, the stored
//! result). With a geometry stage, each invocation that emitted a
//! fragment's primitive is traced too: its input primitive (number,
//! `gl_PrimitiveIDIn`, input vertices), inputs, statements and stores,
//! prints, and every vertex it emitted with its strip, those of the
//! fragments' primitives marked.
//!
//! [`Report::from_records`] builds the report; [`Report::text`] renders it
//! with source lines, `serde_json` renders [`Report`] as JSON.
//!
//! ## Limitations
//! - Statements of a stage with several shader objects are shown against
//!   the first object's text (spans do not name their object yet).
//! - Fixed-function stages are generated GLSL: their statements are listed
//!   without source text.
//! - Values of struct members and arrays are named by flat component
//!   (`v[+3]`) beyond the first level.

use exec::Kernel;
use gl::debug::{DrawRecord, StageInfo};
use glsl::types::{Base, Scalar, Type};
use raster::{Event, FragmentProbe, OpsProbe, PixelState};
use serde::Serialize;
use std::fmt::Write;

/// The debugger's answer for one pixel.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    pub pixel: (u32, u32),
    pub draws: Vec<DrawReport>,
}

#[derive(Clone, Debug, Serialize)]
pub struct DrawReport {
    pub draw: usize,
    pub mode: String,
    pub count: usize,
    pub program: u32,
    pub framebuffer: u32,
    /// Why no fragment could reach the pixel, or the error that stopped the
    /// draw (what it recorded before is still reported).
    pub note: Option<String>,
    pub fragments: Vec<FragmentReport>,
    /// `debugPrintfEXT` output of the print rectangle (other pixels).
    pub prints: Vec<PrintReport>,
    /// `debugPrintfEXT` output of the vertex shader, per vertex index.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub vertex_prints: Vec<VertexPrint>,
    /// The pixel after the draw.
    pub after: Option<PixelReport>,
    /// The traced vertex, when one was asked for.
    pub vertex: Option<VertexTrace>,
    /// With a geometry stage: the invocations that emitted the fragments'
    /// primitives, by input primitive.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub geometry: Vec<GeometryTrace>,
    /// Every primitive's window-space corners, when asked for.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub outlines: Vec<Vec<[f64; 2]>>,
}

/// One vertex shader invocation.
#[derive(Clone, Debug, Serialize)]
pub struct VertexTrace {
    pub position: usize,
    pub index: u32,
    pub inputs: Vec<Named>,
    pub steps: Vec<Step>,
    /// The steps stop short: the draw's trace limit was reached.
    pub truncated: bool,
    pub outputs: Vec<Named>,
    pub error: Option<String>,
}

/// One geometry shader invocation: the one of input primitive
/// `primitive`.
#[derive(Clone, Debug, Serialize)]
pub struct GeometryTrace {
    pub primitive: u32,
    /// `gl_PrimitiveIDIn`.
    pub primitive_id: u32,
    /// Its input vertices: positions in the draw's vertex list, and the
    /// vertex indices there.
    pub vertices: Vec<usize>,
    pub indices: Vec<u32>,
    pub inputs: Vec<Named>,
    pub steps: Vec<Step>,
    /// The steps stop short: the draw's trace limit was reached.
    pub truncated: bool,
    pub emitted: Vec<EmittedReport>,
    pub error: Option<String>,
}

/// A vertex a geometry shader invocation emitted.
#[derive(Clone, Debug, Serialize)]
pub struct EmittedReport {
    /// Its number among the invocation's emitted vertices (from 0).
    pub vertex: u32,
    pub strip: u32,
    pub outputs: Vec<Named>,
    /// The fragments (numbered from 1, as the text report counts them)
    /// whose primitive it is a vertex of.
    pub fragments: Vec<usize>,
}

#[derive(Clone, Debug, Serialize)]
pub struct VertexPrint {
    pub vertex: u32,
    pub line: Option<u32>,
    pub text: String,
}

#[derive(Clone, Debug, Serialize)]
pub struct PrintReport {
    pub x: u32,
    pub y: u32,
    pub primitive: u32,
    pub line: Option<u32>,
    pub text: String,
}

#[derive(Clone, Debug, Serialize)]
pub struct FragmentReport {
    pub primitive: u32,
    /// With a geometry stage: the input primitive whose invocation
    /// emitted this primitive (`DrawReport::geometry`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub input_primitive: Option<u32>,
    pub facing: &'static str,
    /// The primitive's vertices: index position in the draw and the vertex
    /// shader's outputs (with a geometry stage: position in the list of
    /// emitted vertices and the geometry shader's outputs).
    pub vertices: Vec<VertexReport>,
    pub window_z: f64,
    pub inputs: Vec<Named>,
    pub early_rejected: bool,
    pub steps: Vec<Step>,
    /// The steps stop short: the draw's trace limit was reached.
    pub truncated: bool,
    pub discarded: Option<Step>,
    pub error: Option<String>,
    pub outputs: Vec<Named>,
    pub operations: Option<OpsReport>,
}

#[derive(Clone, Debug, Serialize)]
pub struct VertexReport {
    pub position: usize,
    /// With a geometry stage: its number among the emitted vertices of
    /// its invocation.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub emitted_vertex: Option<u32>,
    pub outputs: Vec<Named>,
}

/// A variable's value: `values` are numbers (floats, ints, bools as 0/1).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Named {
    pub name: String,
    pub values: Vec<Number>,
}

/// A value as its type says: float, int, uint or bool.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Number {
    Float(f32),
    Int(i32),
    Uint(u32),
    Bool(bool),
}

impl Number {
    fn from_bits(kind: Scalar, bits: u32) -> Number {
        match kind {
            Scalar::Float => Number::Float(f32::from_bits(bits)),
            Scalar::Int => Number::Int(bits as i32),
            Scalar::Uint => Number::Uint(bits),
            Scalar::Bool => Number::Bool(bits != 0),
        }
    }

    /// An interface component: integers carry their bits when
    /// `integer_bits` (every stage's inputs, the varyings a vertex shader
    /// outputs: `exec::Batch`), else their values as floats (fragment
    /// outputs).
    fn from_slot(kind: Scalar, v: f32, integer_bits: bool) -> Number {
        match kind {
            Scalar::Int if integer_bits => Number::Int(v.to_bits() as i32),
            Scalar::Uint if integer_bits => Number::Uint(v.to_bits()),
            _ => Number::from_f32(kind, v),
        }
    }

    fn from_f32(kind: Scalar, v: f32) -> Number {
        match kind {
            Scalar::Float => Number::Float(v),
            Scalar::Int => Number::Int(v as i32),
            Scalar::Uint => Number::Uint(v as u32),
            Scalar::Bool => Number::Bool(v != 0.0),
        }
    }
}

impl std::fmt::Display for Number {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Number::Float(v) if *v != 0.0 && (v.abs() < 1e-4 || v.abs() >= 1e7) => {
                write!(f, "{v:e}")
            }
            Number::Float(v) => write!(f, "{v}"),
            Number::Int(v) => write!(f, "{v}"),
            Number::Uint(v) => write!(f, "{v}u"),
            Number::Bool(v) => write!(f, "{v}"),
        }
    }
}

/// One executed statement and what it stored or printed.
#[derive(Clone, Debug, Serialize)]
pub struct Step {
    pub line: Option<u32>,
    pub column: Option<u32>,
    pub source: String,
    pub stores: Vec<Named>,
    pub prints: Vec<String>,
}

#[derive(Clone, Debug, Serialize)]
pub struct OpsReport {
    pub fragment_depth: f32,
    pub alpha_test: Option<bool>,
    pub stencil_test: Option<bool>,
    pub depth_test: Option<bool>,
    pub blended: bool,
    pub color_mask: [bool; 4],
    pub before: PixelReport,
    pub after: PixelReport,
    /// The fragment changed the pixel.
    pub written: bool,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PixelReport {
    pub color: Option<[f32; 4]>,
    pub color_bytes: Option<[u8; 4]>,
    pub depth: Option<f32>,
    pub stencil: Option<u8>,
}

impl PixelReport {
    fn new(p: &PixelState) -> PixelReport {
        PixelReport {
            color: p.colors.first().copied(),
            color_bytes: p.color_bytes.first().copied().flatten(),
            depth: p.depth.map(raster::fixed_to_depth),
            stencil: p.stencil,
        }
    }
}

/// `GL_TRIANGLES`... for a primitive mode.
fn mode_name(mode: u32) -> String {
    const NAMES: [&str; 10] = [
        "GL_POINTS",
        "GL_LINES",
        "GL_LINE_LOOP",
        "GL_LINE_STRIP",
        "GL_TRIANGLES",
        "GL_TRIANGLE_STRIP",
        "GL_TRIANGLE_FAN",
        "GL_QUADS",
        "GL_QUAD_STRIP",
        "GL_POLYGON",
    ];
    NAMES
        .get(mode as usize)
        .map_or_else(|| format!("mode 0x{mode:x}"), |s| s.to_string())
}

/// The name of component `k` of a variable of type `ty`.
fn component_name(name: &str, ty: Type, k: usize, structs: &[glsl::types::StructDef]) -> String {
    let size = exec::size_of(ty, structs);
    if size <= 1 {
        return name.to_string();
    }
    if let Some(glsl::types::ArraySize::Sized(len)) = ty.array {
        let elem = Type { array: None, ..ty };
        let es = exec::size_of(elem, structs).max(1);
        if (k / es) < len as usize {
            return component_name(&format!("{name}[{}]", k / es), elem, k % es, structs);
        }
    }
    match ty.base {
        Base::Vector(_, _) => format!("{name}.{}", ["x", "y", "z", "w"].get(k).unwrap_or(&"?")),
        Base::Matrix { rows, .. } => {
            let rows = rows.max(1) as usize;
            format!("{name}[{}][{}]", k / rows, k % rows)
        }
        _ => format!("{name}[+{k}]"),
    }
}

/// Values of interface slots, by name.
fn named_slots(
    slots: &[exec::Slot],
    values: &[f32],
    structs: &[glsl::types::StructDef],
    written_only: bool,
    integer_bits: bool,
) -> Vec<Named> {
    slots
        .iter()
        .filter(|s| !written_only || s.written)
        .map(|s| {
            let kinds = exec::kinds(s.ty, structs);
            Named {
                name: s.name.clone(),
                values: (0..s.components)
                    .map(|c| {
                        let v = values.get(s.offset + c).copied().unwrap_or(0.0);
                        let kind = kinds.get(c).copied().unwrap_or(Scalar::Float);
                        Number::from_slot(kind, v, integer_bits)
                    })
                    .collect(),
            }
        })
        .collect()
}

/// Where a span is: line, column and the text of its line.
fn locate(stage: &StageInfo, span: glsl::Span) -> (Option<u32>, Option<u32>, String) {
    let Some(sh) = stage.shaders.first() else {
        return (None, None, String::new());
    };
    let map = &sh.source;
    let text = map.text();
    if span.start as usize > text.len() {
        return (None, None, String::new());
    }
    let loc = map.loc(span.start);
    let start = text[..span.start as usize].rfind('\n').map_or(0, |i| i + 1);
    let end = text[span.start as usize..]
        .find('\n')
        .map_or(text.len(), |i| span.start as usize + i);
    (
        Some(loc.line),
        Some(loc.column),
        text[start..end].trim().to_string(),
    )
}

/// The steps of a traced invocation: one per executed statement, with the
/// stores and prints that followed it.
fn steps(kernel: &Kernel, stage: &StageInfo, events: &[Event]) -> Vec<Step> {
    let vars = kernel.variables();
    let structs = &kernel.interface().structs;
    // Per step: (variable, component, value) in store order.
    let mut raw: Vec<(Step, Vec<StoreEvent>)> = Vec::new();
    for e in events {
        match e {
            Event::Statement(span) => {
                let (line, column, source) = locate(stage, *span);
                raw.push((
                    Step {
                        line,
                        column,
                        source,
                        stores: Vec::new(),
                        prints: Vec::new(),
                    },
                    Vec::new(),
                ));
            }
            Event::Store { register, bits } => {
                let Some((_, stores)) = raw.last_mut() else {
                    continue;
                };
                // A temporary (an inlined function's result...) is not a
                // variable of the source.
                let Some((vi, v)) = vars
                    .iter()
                    .enumerate()
                    .filter(|(_, v)| {
                        *register >= v.first_register && *register < v.first_register + v.registers
                    })
                    .max_by_key(|(_, v)| v.first_register)
                else {
                    continue;
                };
                let k = (register - v.first_register) as usize;
                let kind = exec::kinds(v.ty, structs)
                    .get(k)
                    .copied()
                    .unwrap_or(Scalar::Float);
                stores.push((vi, k, Number::from_bits(kind, *bits)));
            }
            Event::Print { text, .. } => {
                if let Some((step, _)) = raw.last_mut() {
                    step.prints.push(text.clone());
                }
            }
        }
    }
    raw.into_iter()
        .map(|(mut step, stores)| {
            step.stores = group_stores(vars, structs, &stores);
            step
        })
        .collect()
}

/// A store: (variable index, component, value).
type StoreEvent = (usize, usize, Number);

/// Stores of one statement, grouped per variable in order of first store:
/// the whole variable when every component was stored in order, `v.xz`
/// for some components of a vector, else one entry per component.
fn group_stores(
    vars: &[exec::VarInfo],
    structs: &[glsl::types::StructDef],
    stores: &[StoreEvent],
) -> Vec<Named> {
    let mut order: Vec<usize> = Vec::new();
    for (vi, _, _) in stores {
        if !order.contains(vi) {
            order.push(*vi);
        }
    }
    let mut out = Vec::new();
    for vi in order {
        let Some(var) = vars.get(vi) else { continue };
        // The last value of each component, in component order.
        let mut comps: Vec<(usize, Number)> = Vec::new();
        for (_, k, value) in stores.iter().filter(|s| s.0 == vi) {
            match comps.iter_mut().find(|c| c.0 == *k) {
                Some(c) => c.1 = *value,
                None => comps.push((*k, *value)),
            }
        }
        comps.sort_by_key(|c| c.0);
        let size = exec::size_of(var.ty, structs);
        let all = comps.len() == size && comps.iter().enumerate().all(|(i, c)| c.0 == i);
        if all {
            out.push(Named {
                name: var.name.clone(),
                values: comps.into_iter().map(|c| c.1).collect(),
            });
        } else if let (Base::Vector(..), None) = (var.ty.base, var.ty.array) {
            let letters: String = comps
                .iter()
                .map(|c| ['x', 'y', 'z', 'w'].get(c.0).copied().unwrap_or('?'))
                .collect();
            out.push(Named {
                name: format!("{}.{letters}", var.name),
                values: comps.into_iter().map(|c| c.1).collect(),
            });
        } else {
            for (k, value) in comps {
                out.push(Named {
                    name: component_name(&var.name, var.ty, k, structs),
                    values: vec![value],
                });
            }
        }
    }
    out
}

impl Report {
    /// The report of the records of one debugging session (all for the
    /// same pixel).
    pub fn from_records(pixel: (u32, u32), records: &[DrawRecord]) -> Report {
        Report {
            pixel,
            draws: records.iter().map(draw_report).collect(),
        }
    }

    /// The report as JSON.
    pub fn json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// The report as text, source lines beside the values.
    pub fn text(&self) -> String {
        let mut s = String::new();
        let (x, y) = self.pixel;
        if self.draws.is_empty() {
            let _ = writeln!(s, "pixel ({x}, {y}): no draw was debugged");
        }
        for d in &self.draws {
            let _ = writeln!(
                s,
                "draw {} ({}, {} indices, program {}, framebuffer {}) at pixel ({x}, {y}): {} fragment{}",
                d.draw,
                d.mode,
                d.count,
                d.program,
                d.framebuffer,
                d.fragments.len(),
                if d.fragments.len() == 1 { "" } else { "s" }
            );
            if let Some(n) = &d.note {
                let _ = writeln!(s, "  {n}");
            }
            for (i, f) in d.fragments.iter().enumerate() {
                write_fragment(&mut s, i + 1, f);
            }
            for g in &d.geometry {
                write_geometry(&mut s, g);
            }
            for p in &d.vertex_prints {
                let line = p.line.map_or(String::new(), |l| format!(" line {l}"));
                let _ = writeln!(
                    s,
                    "  printf vertex {}{line}: {}",
                    p.vertex,
                    p.text.trim_end()
                );
            }
            for p in &d.prints {
                let line = p.line.map_or(String::new(), |l| format!(" line {l}"));
                let _ = writeln!(
                    s,
                    "  printf ({}, {}) primitive {}{line}: {}",
                    p.x,
                    p.y,
                    p.primitive,
                    p.text.trim_end()
                );
            }
            if let Some(v) = &d.vertex {
                write_vertex(&mut s, v);
            }
            if let Some(a) = &d.after {
                let _ = writeln!(s, "  pixel after the draw: {}", pixel_text(a));
            }
        }
        s
    }
}

fn draw_report(r: &DrawRecord) -> DrawReport {
    let mut d = DrawReport {
        draw: r.draw,
        mode: mode_name(r.mode),
        count: r.count,
        program: r.program,
        framebuffer: r.framebuffer,
        note: None,
        fragments: Vec::new(),
        prints: Vec::new(),
        vertex_prints: Vec::new(),
        after: None,
        vertex: None,
        geometry: Vec::new(),
        outlines: Vec::new(),
    };
    let probe = &r.probe;
    d.note = match (&probe.unreachable, &probe.stopped) {
        (Some(u), _) => Some(u.clone()),
        (None, Some(e)) => Some(format!("the draw stopped: {e}")),
        (None, None) => None,
    };
    d.outlines = probe.outlines.clone();
    d.vertex = probe.vertex.as_ref().map(|v| {
        let k = &r.vertex.kernel;
        let iface = k.interface();
        VertexTrace {
            position: v.position,
            index: v.index,
            inputs: named_slots(&iface.inputs, &v.inputs, &iface.structs, false, true),
            steps: steps(k, &r.vertex, &v.events),
            truncated: v.truncated,
            outputs: named_slots(&iface.outputs, &v.outputs, &iface.structs, true, true),
            error: v.error.clone(),
        }
    });
    d.after = Some(PixelReport::new(&probe.after));
    let fs_iface = r.fragment.kernel.interface();
    // The vertices set up are the last stage's before rasterization.
    let last = r.geometry.as_ref().unwrap_or(&r.vertex);
    let last_iface = last.kernel.interface();
    for f in &probe.fragments {
        d.fragments
            .push(fragment_report(r, probe, f, fs_iface, last_iface));
    }
    if let Some(gs) = &r.geometry {
        d.geometry = probe
            .geometry
            .iter()
            .map(|g| geometry_trace(gs, g, &d.fragments))
            .collect();
    }
    for (vertex, span, text) in &probe.vertex_prints {
        d.vertex_prints.push(VertexPrint {
            vertex: *vertex,
            line: locate(&r.vertex, *span).0,
            text: text.clone(),
        });
    }
    for p in &probe.prints {
        let (line, _, _) = locate(&r.fragment, p.span);
        d.prints.push(PrintReport {
            x: p.x,
            y: p.y,
            primitive: p.primitive,
            line,
            text: p.text.clone(),
        });
    }
    d
}

/// The report of a traced geometry shader invocation; `fragments` are
/// the draw's, to mark the emitted vertices of their primitives.
fn geometry_trace(
    stage: &StageInfo,
    g: &raster::GeometryProbe,
    fragments: &[FragmentReport],
) -> GeometryTrace {
    let k = &stage.kernel;
    let iface = k.interface();
    GeometryTrace {
        primitive: g.primitive,
        primitive_id: g.primitive_id,
        vertices: g.positions.clone(),
        indices: g.indices.clone(),
        inputs: geometry_inputs(iface, &g.inputs),
        steps: steps(k, stage, &g.events),
        truncated: g.truncated,
        emitted: g
            .emitted
            .iter()
            .enumerate()
            .map(|(v, e)| EmittedReport {
                vertex: v as u32,
                strip: e.strip,
                outputs: named_slots(&iface.outputs, &e.outputs, &iface.structs, true, true),
                fragments: fragments
                    .iter()
                    .enumerate()
                    .filter(|(_, f)| {
                        f.input_primitive == Some(g.primitive)
                            && f.vertices
                                .iter()
                                .any(|x| x.emitted_vertex == Some(v as u32))
                    })
                    .map(|(i, _)| i + 1)
                    .collect(),
            })
            .collect(),
        error: g.error.clone(),
    }
}

/// A geometry shader's inputs by name, the per-vertex arrays one element
/// at a time (`gl_in[1].gl_Position`, `v[2]`...).
fn geometry_inputs(iface: &exec::Interface, values: &[f32]) -> Vec<Named> {
    let structs = &iface.structs;
    let mut out = Vec::new();
    for s in &iface.inputs {
        let kinds = exec::kinds(s.ty, structs);
        let value = |c: usize| {
            let v = values.get(s.offset + c).copied().unwrap_or(0.0);
            let kind = kinds.get(c).copied().unwrap_or(Scalar::Float);
            Number::from_slot(kind, v, true)
        };
        let elements = match s.ty.array {
            Some(glsl::types::ArraySize::Sized(n)) if n > 0 => n as usize,
            _ => {
                out.push(Named {
                    name: s.name.clone(),
                    values: (0..s.components).map(value).collect(),
                });
                continue;
            }
        };
        let elem = s.ty.element();
        let per = exec::size_of(elem, structs).max(1);
        for e in 0..elements {
            let first = e * per;
            let members = match elem.base {
                Base::Struct(id) => structs
                    .get(id.0 as usize)
                    .map(|d| {
                        d.members
                            .iter()
                            .map(|m| (format!(".{}", m.name), exec::size_of(m.ty, structs)))
                            .collect()
                    })
                    .unwrap_or_default(),
                _ => vec![(String::new(), per)],
            };
            let mut at = first;
            for (member, n) in members {
                // An unsized member (gl_ClipDistance nobody sized) has no
                // value to show.
                if n == 0 {
                    continue;
                }
                out.push(Named {
                    name: format!("{}[{e}]{member}", s.name),
                    values: (at..(at + n).min(s.components)).map(value).collect(),
                });
                at += n;
            }
        }
    }
    out
}

fn fragment_report(
    r: &DrawRecord,
    probe: &raster::DrawProbe,
    f: &FragmentProbe,
    fs: &exec::Interface,
    vs: &exec::Interface,
) -> FragmentReport {
    let positions = probe.primitives.get(f.primitive as usize);
    let input_primitive = positions
        .and_then(|p| p.first())
        .and_then(|&p| probe.emitted_by.get(p))
        .map(|by| by.primitive);
    let vertices = positions
        .map(|positions| {
            positions
                .iter()
                .map(|&p| VertexReport {
                    position: p,
                    emitted_vertex: probe.emitted_by.get(p).map(|by| by.vertex),
                    outputs: named_slots(
                        &vs.outputs,
                        probe.vertex_outputs.get(p).map_or(&[][..], |v| &v[..]),
                        &vs.structs,
                        true,
                        true,
                    ),
                })
                .collect()
        })
        .unwrap_or_default();
    let steps = steps(&r.fragment.kernel, &r.fragment, &f.events);
    let discarded = if f.discarded {
        steps.last().cloned()
    } else {
        None
    };
    FragmentReport {
        primitive: f.primitive,
        input_primitive,
        facing: if f.back_facing { "back" } else { "front" },
        vertices,
        window_z: f.window_z,
        inputs: named_slots(&fs.inputs, &f.inputs, &fs.structs, false, true),
        early_rejected: f.early_rejected,
        steps,
        truncated: f.truncated,
        discarded,
        error: f.error.clone(),
        outputs: if f.early_rejected {
            Vec::new()
        } else {
            named_slots(&fs.outputs, &f.outputs, &fs.structs, true, false)
        },
        operations: f.ops.as_ref().map(ops_report),
    }
}

fn ops_report(o: &OpsProbe) -> OpsReport {
    OpsReport {
        fragment_depth: o.fragment_depth,
        alpha_test: o.alpha_test,
        stencil_test: o.stencil_test,
        depth_test: o.depth_test,
        blended: o.blended,
        color_mask: o.color_mask,
        before: PixelReport::new(&o.before),
        after: PixelReport::new(&o.after),
        written: o.before != o.after,
    }
}

fn values_text(v: &[Number]) -> String {
    match v {
        [one] => one.to_string(),
        many => format!(
            "({})",
            many.iter()
                .map(|n| n.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

fn pixel_text(p: &PixelReport) -> String {
    let mut parts = Vec::new();
    if let Some(b) = p.color_bytes {
        parts.push(format!("colour ({}, {}, {}, {})", b[0], b[1], b[2], b[3]));
    } else if let Some(c) = p.color {
        parts.push(format!("colour ({}, {}, {}, {})", c[0], c[1], c[2], c[3]));
    }
    if let Some(d) = p.depth {
        parts.push(format!("depth {d}"));
    }
    if let Some(st) = p.stencil {
        parts.push(format!("stencil {st}"));
    }
    parts.join(", ")
}

/// Executed statements, source beside the values they stored.
fn write_truncated(s: &mut String, truncated: bool) {
    if truncated {
        let _ = writeln!(
            s,
            "    trace truncated: the draw recorded its limit of {} statements, stores and prints; the shader ran on",
            raster::MAX_TRACE_EVENTS
        );
    }
}

fn write_steps(s: &mut String, steps: &[Step]) {
    for st in steps {
        let at = st.line.map_or("     ".to_string(), |l| format!("{l:>4} |"));
        let stores: Vec<String> = st
            .stores
            .iter()
            .map(|o| format!("{} = {}", o.name, values_text(&o.values)))
            .collect();
        let mut line = format!("    {at} {}", st.source);
        if !stores.is_empty() {
            let pad = 48usize.saturating_sub(line.chars().count()).max(2);
            line.push_str(&" ".repeat(pad));
            line.push_str(&format!("→ {}", stores.join(", ")));
        }
        let _ = writeln!(s, "{line}");
        for p in &st.prints {
            let _ = writeln!(s, "         printf: {}", p.trim_end());
        }
    }
}

fn named_text(v: &[Named]) -> String {
    v.iter()
        .map(|o| format!("{} = {}", o.name, values_text(&o.values)))
        .collect::<Vec<_>>()
        .join("; ")
}

fn write_vertex(s: &mut String, v: &VertexTrace) {
    let _ = writeln!(
        s,
        "  vertex shader, vertex {} (index {}):",
        v.position, v.index
    );
    if !v.inputs.is_empty() {
        let _ = writeln!(s, "    inputs: {}", named_text(&v.inputs));
    }
    write_steps(s, &v.steps);
    write_truncated(s, v.truncated);
    if let Some(e) = &v.error {
        let _ = writeln!(s, "    {e}");
    } else {
        let _ = writeln!(s, "    outputs: {}", named_text(&v.outputs));
    }
}

fn write_geometry(s: &mut String, g: &GeometryTrace) {
    let list = |v: &[String]| v.join(", ");
    let (vertices, indices) = if g.vertices.len() == 1 {
        ("vertex", "index")
    } else {
        ("vertices", "indices")
    };
    let _ = writeln!(
        s,
        "  geometry shader, input primitive {} (gl_PrimitiveIDIn {}), {vertices} {} ({indices} {}):",
        g.primitive,
        g.primitive_id,
        list(&g.vertices.iter().map(|v| v.to_string()).collect::<Vec<_>>()),
        list(&g.indices.iter().map(|v| v.to_string()).collect::<Vec<_>>()),
    );
    if !g.inputs.is_empty() {
        let _ = writeln!(s, "    inputs: {}", named_text(&g.inputs));
    }
    write_steps(s, &g.steps);
    write_truncated(s, g.truncated);
    if let Some(e) = &g.error {
        let _ = writeln!(s, "    {e}");
    }
    if g.emitted.is_empty() {
        let _ = writeln!(s, "    emitted no vertex");
    }
    for e in &g.emitted {
        let of = match e.fragments.as_slice() {
            [] => String::new(),
            [one] => format!(", of fragment {one}'s primitive"),
            many => format!(
                ", of fragments {}'s primitives",
                list(&many.iter().map(|v| v.to_string()).collect::<Vec<_>>())
            ),
        };
        let _ = writeln!(
            s,
            "    emitted vertex {} (strip {}{of}): {}",
            e.vertex,
            e.strip,
            named_text(&e.outputs)
        );
    }
}

fn write_fragment(s: &mut String, n: usize, f: &FragmentReport) {
    let verts: Vec<String> = f.vertices.iter().map(|v| v.position.to_string()).collect();
    let _ = writeln!(
        s,
        "  fragment {n}: primitive {} (vertices {}), {}-facing, window z {}",
        f.primitive,
        verts.join(", "),
        f.facing,
        f.window_z
    );
    if let Some(k) = f.input_primitive {
        let _ = writeln!(
            s,
            "    emitted by the geometry shader of input primitive {k}"
        );
    }
    for v in &f.vertices {
        let outs: Vec<String> = v
            .outputs
            .iter()
            .map(|o| format!("{} = {}", o.name, values_text(&o.values)))
            .collect();
        let emitted = v
            .emitted_vertex
            .map_or(String::new(), |e| format!(" (emitted vertex {e})"));
        let _ = writeln!(s, "    vertex {}{emitted}: {}", v.position, outs.join("; "));
    }
    let ins: Vec<String> = f
        .inputs
        .iter()
        .map(|o| format!("{} = {}", o.name, values_text(&o.values)))
        .collect();
    if !ins.is_empty() {
        let _ = writeln!(s, "    inputs: {}", ins.join("; "));
    }
    if f.early_rejected {
        let _ = writeln!(
            s,
            "    rejected by the early depth/stencil test before shading"
        );
    }
    write_steps(s, &f.steps);
    write_truncated(s, f.truncated);
    if let Some(d) = &f.discarded {
        let at = d.line.map_or(String::new(), |l| format!(" at line {l}"));
        let _ = writeln!(s, "    discarded{at}: {}", d.source);
    }
    if let Some(e) = &f.error {
        let _ = writeln!(s, "    shader error: {e}");
    }
    if !f.outputs.is_empty() && f.discarded.is_none() {
        let outs: Vec<String> = f
            .outputs
            .iter()
            .map(|o| format!("{} = {}", o.name, values_text(&o.values)))
            .collect();
        let _ = writeln!(s, "    outputs: {}", outs.join("; "));
    }
    if let Some(o) = &f.operations {
        let mut tests = Vec::new();
        let word = |b: bool| if b { "passed" } else { "failed" };
        if let Some(a) = o.alpha_test {
            tests.push(format!("alpha test {}", word(a)));
        }
        if let Some(st) = o.stencil_test {
            tests.push(format!(
                "stencil test {} (stored {})",
                word(st),
                o.before.stencil.unwrap_or(0)
            ));
        }
        if let Some(dt) = o.depth_test {
            tests.push(format!(
                "depth test {}: fragment {} against stored {}",
                word(dt),
                o.fragment_depth,
                o.before.depth.unwrap_or(1.0)
            ));
        }
        if o.blended {
            tests.push(format!("blended with {}", pixel_text(&o.before)));
        }
        if o.color_mask != [true; 4] {
            tests.push(format!("colour mask {:?}", o.color_mask));
        }
        if tests.is_empty() {
            tests.push("no test enabled".into());
        }
        let _ = writeln!(s, "    per-fragment operations: {}", tests.join("; "));
        let _ = writeln!(
            s,
            "    {}: {}",
            if o.written {
                "wrote"
            } else {
                "left the pixel as"
            },
            pixel_text(&o.after)
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use gl::enums::*;

    /// A vertex shader's integer input is reported as the integer the
    /// attribute held (its bits), not as the float those bits make.
    #[test]
    fn integer_vertex_inputs_show_their_values() {
        let mut ctx = gl::Context::new(4, 4);
        let p = ctx.create_program();
        for (kind, src) in [
            (
                GL_VERTEX_SHADER,
                "#version 130\nin vec2 pos;\nin ivec2 code;\nflat out int k;\n\
                 void main() { gl_Position = vec4(pos, 0.0, 1.0); k = code.x; }",
            ),
            (
                GL_FRAGMENT_SHADER,
                "#version 130\nflat in int k;\nout vec4 c;\n\
                 void main() { c = vec4(k < 0 ? 1.0 : 0.0); }",
            ),
        ] {
            let s = ctx.create_shader(kind);
            ctx.shader_source(s, &[src]);
            ctx.compile_shader(s);
            ctx.attach_shader(p, s);
        }
        ctx.link_program(p);
        ctx.use_program(p);
        let pos = ctx.get_attrib_location(p, "pos") as u32;
        let code = ctx.get_attrib_location(p, "code") as u32;
        let quad = [-1.0, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0];
        ctx.vertex_attrib_pointer(pos, 2, GL_FLOAT, false, 0, gl::ArrayData::from_f32(&quad));
        ctx.enable_vertex_attrib_array(pos);
        ctx.vertex_attrib_i4i(code, [-123456789, 7, 0, 1]);
        let mut request = gl::debug::DebugRequest::pixel(1, 1);
        request.vertex = Some(0);
        ctx.set_debug(Some(request));
        ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
        let records = ctx.take_debug_records();
        let report = Report::from_records((1, 1), &records);
        let text = report.text();
        assert!(text.contains("-123456789"), "{text}");
        // No geometry stage: none of its keys in the JSON.
        let json = report.json();
        for key in ["\"geometry\"", "input_primitive", "emitted_vertex"] {
            assert!(!json.contains(key), "{key} in {json}");
        }
    }

    /// A 3.3 compatibility context drawing with `gs` between a
    /// pass-through vertex stage and a constant fragment stage; `pos`
    /// holds the points given.
    fn geometry_context(gs: &str, points: &[f32]) -> gl::Context {
        let mut ctx = gl::Context::with_api(8, 8, gl::Api::GL33_COMPAT);
        let p = ctx.create_program();
        for (kind, src) in [
            (
                GL_VERTEX_SHADER,
                "#version 150\nin vec2 pos;\nvoid main() { gl_Position = vec4(pos, 0.0, 1.0); }",
            ),
            (GL_GEOMETRY_SHADER, gs),
            (
                GL_FRAGMENT_SHADER,
                "#version 150\nout vec4 c;\nvoid main() { c = vec4(1.0); }",
            ),
        ] {
            let s = ctx.create_shader(kind);
            ctx.shader_source(s, &[src]);
            ctx.compile_shader(s);
            assert_eq!(ctx.get_shaderiv(s, GL_COMPILE_STATUS), 1, "{src}");
            ctx.attach_shader(p, s);
        }
        ctx.link_program(p);
        assert_eq!(ctx.get_programiv(p, GL_LINK_STATUS), 1);
        ctx.use_program(p);
        let pos = ctx.get_attrib_location(p, "pos") as u32;
        ctx.vertex_attrib_pointer(pos, 2, GL_FLOAT, false, 0, gl::ArrayData::from_f32(points));
        ctx.enable_vertex_attrib_array(pos);
        ctx
    }

    /// The JSON report of a draw with a geometry stage names the input
    /// primitive of each fragment, the emitted number of each of its
    /// vertices, and the invocation with its per-vertex inputs one element
    /// at a time and its emitted vertices marked with the fragment.
    #[test]
    fn geometry_invocations_are_in_the_json_report() {
        let gs = "#version 150
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
void main() {
    for (int i = 0; i < 4; i++) {
        gl_Position = gl_in[0].gl_Position + vec4(vec2(i % 2, i / 2) * 0.5 - 0.25, 0.0, 0.0);
        EmitVertex();
    }
}";
        let mut ctx = geometry_context(gs, &[-0.5, -0.5, 0.5, 0.5]);
        let mut request = gl::debug::DebugRequest::pixel(6, 6);
        request.vertex = Some(1);
        ctx.set_debug(Some(request));
        ctx.draw_arrays(GL_POINTS, 0, 2);
        let records = ctx.take_debug_records();
        let report = Report::from_records((6, 6), &records);
        let d = &report.draws[0];
        assert_eq!(d.fragments.len(), 1, "{}", report.text());
        let f = &d.fragments[0];
        assert_eq!(f.input_primitive, Some(1));
        assert!(f.vertices.iter().all(|v| v.emitted_vertex.is_some()));
        // The vertices are named by the geometry shader's outputs.
        assert!(f.vertices[0]
            .outputs
            .iter()
            .any(|o| o.name == "gl_Position"));
        assert_eq!(d.geometry.len(), 1);
        let g = &d.geometry[0];
        assert_eq!((g.primitive, g.primitive_id), (1, 1));
        assert_eq!((&g.vertices[..], &g.indices[..]), (&[1][..], &[1][..]));
        assert_eq!(g.inputs[0].name, "gl_in[0].gl_Position");
        assert_eq!(g.emitted.len(), 4);
        let marked = g.emitted.iter().filter(|e| e.fragments == [1]).count();
        assert_eq!(marked, 3);
        assert!(d.vertex.as_ref().is_some_and(|v| v.index == 1));
        let json = report.json();
        for key in ["\"geometry\"", "\"input_primitive\": 1", "emitted_vertex"] {
            assert!(json.contains(key), "no {key} in {json}");
        }
    }

    /// A geometry shader writing gl_Layer into a layered framebuffer: the
    /// draw is not replayed, its record says why, and the draws after it
    /// keep their numbers.
    #[test]
    fn layered_draws_say_why_they_are_not_traced() {
        let gs = "#version 150
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
void main() {
    for (int i = 0; i < 3; i++) {
        gl_Position = gl_in[i].gl_Position;
        gl_Layer = 1;
        EmitVertex();
    }
}";
        let mut ctx = geometry_context(gs, &[-1.0, -1.0, 3.0, -1.0, -1.0, 3.0]);
        let t = ctx.gen_textures(1)[0];
        ctx.bind_texture(GL_TEXTURE_2D_ARRAY, t);
        let zeros = vec![0u8; 8 * 8 * 4 * 2];
        ctx.tex_image(
            GL_TEXTURE_2D_ARRAY,
            0,
            GL_RGBA8 as i32,
            [8, 8, 2],
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&zeros),
        );
        let fb = ctx.gen_framebuffers(1)[0];
        ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
        ctx.framebuffer_texture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t, 0);
        let mut request = gl::debug::DebugRequest::pixel(2, 2);
        request.view = Some("c".into());
        ctx.set_debug(Some(request));
        ctx.draw_arrays(GL_TRIANGLES, 0, 3);
        ctx.bind_framebuffer(GL_FRAMEBUFFER, 0);
        ctx.draw_arrays(GL_TRIANGLES, 0, 3);
        let records = ctx.take_debug_records();
        assert!(matches!(&records[0].view, Some(Err(e)) if e.contains("gl_Layer")));
        let report = Report::from_records((2, 2), &records);
        let text = report.text();
        assert_eq!(report.draws.len(), 2, "{text}");
        let layered = &report.draws[0];
        assert!(layered.fragments.is_empty());
        assert!(
            layered
                .note
                .as_deref()
                .is_some_and(|n| n.contains("does not replay")),
            "{text}"
        );
        assert_eq!(report.draws[1].draw, 1);
        assert_eq!(report.draws[1].fragments.len(), 1, "{text}");
    }
}
