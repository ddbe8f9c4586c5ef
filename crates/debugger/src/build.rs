//! The report built from the pipeline's probe records: each draw's
//! fragments, primitives, traces, prints and geometry invocations, values
//! named after the stages' interfaces and statements located in the
//! shaders' text.

use crate::*;
use exec::Kernel;
use gl::debug::{DrawRecord, StageInfo};
use glsl::types::{Base, Scalar, Type};
use raster::{Event, FragmentProbe, OpsProbe};

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

pub(crate) fn draw_report(r: &DrawRecord) -> DrawReport {
    let mut d = DrawReport {
        draw: r.draw,
        mode: mode_name(r.mode),
        count: r.count,
        program: r.program,
        framebuffer: r.framebuffer,
        layer: r.probe.layer,
        note: None,
        fragments: Vec::new(),
        prints: Vec::new(),
        vertex_prints: Vec::new(),
        geometry_prints: Vec::new(),
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
            .map(|g| geometry_trace((gs, r.vertex.kernel.interface()), g, &d.fragments))
            .collect();
    }
    for (vertex, span, text) in &probe.vertex_prints {
        d.vertex_prints.push(VertexPrint {
            vertex: *vertex,
            line: locate(&r.vertex, *span).0,
            text: text.clone(),
        });
    }
    if let Some(gs) = &r.geometry {
        for (primitive, span, text) in &probe.geometry_prints {
            d.geometry_prints.push(GeometryPrint {
                primitive: *primitive,
                line: locate(gs, *span).0,
                text: text.clone(),
            });
        }
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
    (stage, vs): (&StageInfo, &exec::Interface),
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
        inputs: geometry_inputs(iface, vs, &g.inputs),
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
/// at a time (`gl_in[1].gl_Position`, `v[2]`...); the built-in members of
/// `gl_in` that the vertex stage `vs` does not write (undefined, read as
/// 0) are left out.
fn geometry_inputs(iface: &exec::Interface, vs: &exec::Interface, values: &[f32]) -> Vec<Named> {
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
                            .map(|m| (m.name.as_str(), exec::size_of(m.ty, structs)))
                            .collect()
                    })
                    .unwrap_or_default(),
                _ => vec![("", per)],
            };
            let mut at = first;
            for (member, n) in members {
                let unwritten =
                    member.starts_with("gl_") && !vs.output(member).is_some_and(|o| o.written);
                // An unsized member (gl_ClipDistance nobody sized) has no
                // value to show, an unwritten one no defined value.
                if n == 0 || unwritten {
                    at += n;
                    continue;
                }
                let member = if member.is_empty() {
                    String::new()
                } else {
                    format!(".{member}")
                };
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
