//! The geometry stage (GL 3.3 §2.12): between the vertex stage and
//! set-up, a geometry kernel runs once per assembled primitive and its
//! emitted strips become the primitives the rest of the pipeline draws.
//!
//! Takes the vertex stage's results (per position in the index list a
//! vertex number, and the vertices' outputs), the draw's mode and the
//! geometry kernel; gives the same three things for the emitted
//! primitives: a list mode ([`Mode::Points`], [`Mode::Lines`] or
//! [`Mode::Triangles`]), the vertex number of each of their vertices and
//! the emitted vertices' outputs (laid out as the geometry kernel's
//! [`crate::ex::Interface::outputs`] say, one vertex's worth). Set-up,
//! clipping, rasterization and the fragment stage then run on those as
//! on a vertex stage's.
//!
//! Primitives are assembled as the geometry shader takes them
//! ([`geometry_input`]: adjacent vertices included), `LANES` primitives
//! per kernel run (one per lane, `gl_PrimitiveIDIn` the primitive's ID),
//! tasks of [`PRIMITIVES_PER_TASK`] on the [`Workers`]; each task keeps
//! its lanes' emitted vertices in primitive order, and the tasks' results
//! are joined in task order, so the output is the same whatever the
//! thread count. A strip of `n` vertices is `n - 1` lines or `n - 2`
//! triangles; odd triangles of a strip are reordered to keep the strip's
//! winding with the provoking vertex where the state's convention wants
//! it (the strip's last vertex, or with the first-vertex convention its
//! first).
//!
//! Under the debugger's probe the stage also notes which input primitive
//! emitted each vertex and leaves the vertex stage's results with the
//! probe, which `crate::replay` traces invocations again from
//! ([`PrimitiveSource`], [`load_primitive`]: what fills a lane).

use crate::assembly::{geometry_input, primitive_count, Mode};
use crate::ex::{Batch, Emitted, Interface, LANES};
use crate::linkage::{new_batch, VsLayout};
use crate::probe::{EmittedBy, Probe};
use crate::shaded::{layered_primitives, Vertices};
use crate::state::PipelineState;
use crate::vertex::run_vertices;
use crate::workers::Workers;
use crate::{DrawError, ShaderStage};
use glsl::ir::OutputPrimitive;

/// The stages before rasterization as a draw runs them: the vertex
/// stage, then the geometry stage when there is one (vertex colours
/// clamped after the last of them, when the state says so): the
/// primitives to set up.
pub(crate) fn vertex_and_geometry_stages(
    workers: &Workers,
    (vs, vs_uniforms): (&dyn ShaderStage, &[u32]),
    gs: Option<(&dyn ShaderStage, &[u32])>,
    textures: &(dyn crate::ex::Textures + Sync),
    (indices, fetch): (&[u32], &dyn crate::VertexFetch),
    (mode, state): (Mode, &PipelineState),
    probe: Option<&crate::probe::Probe>,
) -> Result<Vertices, DrawError> {
    let vertex_layout = VsLayout::new(vs.interface());
    let (vertex_of, outputs) = run_vertices(
        workers,
        vs,
        vs_uniforms,
        textures,
        indices,
        fetch,
        &vertex_layout,
        state.clamp_vertex_color && gs.is_none(),
        probe,
    )?;
    let Some(gs) = gs else {
        return Ok(Vertices {
            mode,
            vertex_of,
            outputs,
        });
    };
    let shaded = Vertices {
        mode,
        vertex_of,
        outputs,
    };
    let emitted = run_geometry(
        workers,
        gs,
        textures,
        vs.interface(),
        vertex_layout.outputs,
        &shaded,
        state,
        &VsLayout::new(gs.0.interface()),
        probe,
    );
    // The debugger traces invocations again from the vertex stage's
    // results after the draw; a replay of one layer of a layered draw
    // keeps only the primitives that layer gets.
    if let Some(p) = probe {
        p.keep_geometry_input(shaded, vertex_layout.outputs);
        let mut emitted = emitted?;
        if let Some(select) = p.layer() {
            let stride = VsLayout::new(gs.0.interface()).outputs;
            emitted.vertex_of = layered_primitives(
                (emitted.mode, &emitted.vertex_of, &emitted.outputs),
                stride,
                select.component,
                state.provoking_first,
            )
            .filter(|&(layer, _)| layer == select.layer)
            .flat_map(|(_, prim)| prim.iter().copied())
            .collect();
        }
        return Ok(emitted);
    }
    // The vertex stage's outputs are the next draw's emitted-vertex
    // buffer (the two trade places from draw to draw, `Spare::emitted`).
    let mut spare = workers.spare();
    spare.keep_tables([shaded.vertex_of]);
    spare.keep_emitted(shaded.outputs);
    emitted
}

/// The vertex and geometry stages alone, as a draw runs them (transform
/// feedback reads the geometry stage's outputs before clipping): the
/// emitted primitives as a list of `mode` ([`Mode::Points`],
/// [`Mode::Lines`] or [`Mode::Triangles`]), per position in that list
/// the vertex number, and the outputs of every emitted vertex, laid out
/// as `gs.interface().outputs` says, `stride` (the last value) apart.
#[allow(clippy::too_many_arguments)]
pub fn shade_geometry(
    workers: &Workers,
    vs: (&dyn ShaderStage, &[u32]),
    gs: (&dyn ShaderStage, &[u32]),
    textures: &(dyn crate::ex::Textures + Sync),
    indices: &[u32],
    fetch: &dyn crate::VertexFetch,
    mode: Mode,
    state: &PipelineState,
) -> Result<(Mode, Vec<u32>, Vec<f32>, usize), DrawError> {
    let stride = VsLayout::new(gs.0.interface()).outputs;
    let v = vertex_and_geometry_stages(
        workers,
        vs,
        Some(gs),
        textures,
        (indices, fetch),
        (mode, state),
        None,
    )?;
    Ok((v.mode, v.vertex_of, v.outputs, stride))
}

/// Primitives one geometry task takes (batches of `LANES`).
const PRIMITIVES_PER_TASK: usize = 4 * LANES;

/// Where a geometry lane's inputs come from: (input vertex, geometry input
/// component, vertex output component, components).
type InputPlan = Vec<(usize, usize, usize, usize)>;

/// Matches the geometry kernel's per-vertex inputs with the vertex
/// kernel's outputs by name, or by location for an input with one
/// ([`Interface::output_for`]; inputs without an output stay 0).
fn input_plan(vs: &Interface, gs: &Interface) -> InputPlan {
    gs.vertex_inputs()
        .into_iter()
        .filter_map(|i| {
            let (out, at) = vs.output_for(&i.name, i.location)?;
            Some((
                i.vertex,
                i.offset,
                out.offset + at,
                i.components.min(out.components - at),
            ))
        })
        .collect()
}

/// Runs the geometry kernel `gs` on the primitives of `input` (the vertex
/// stage's results, `vs_stride` values per vertex of `vs`'s interface);
/// see the module docs. `layout` is the geometry kernel's
/// ([`VsLayout::new`] of its interface): its colours are clamped when
/// the state says so. A `probe` is told which input primitive emitted
/// each vertex ([`Probe::note_emitted`]).
#[allow(clippy::too_many_arguments)]
pub(crate) fn run_geometry(
    workers: &Workers,
    (gs, uniforms): (&dyn ShaderStage, &[u32]),
    textures: &(dyn crate::ex::Textures + Sync),
    vs: &Interface,
    vs_stride: usize,
    input: &Vertices,
    state: &PipelineState,
    layout: &VsLayout,
    probe: Option<&Probe>,
) -> Result<Vertices, DrawError> {
    let iface = gs.interface();
    let Some(emitted) = iface.emitted else {
        return Err(DrawError::Exec(crate::ex::ExecError::Unsupported(
            "the geometry stage is not a geometry kernel".into(),
        )));
    };
    let out_mode = match emitted.output {
        OutputPrimitive::Points => Mode::Points,
        OutputPrimitive::LineStrip => Mode::Lines,
        OutputPrimitive::TriangleStrip => Mode::Triangles,
    };
    let source = PrimitiveSource::new(vs, iface, vs_stride, input, state);
    let primitives = primitive_count(input.mode, input.vertex_of.len());
    let record = probe.is_some();
    let prepared = if primitives > LANES {
        gs.prepare(uniforms, textures)
    } else {
        None
    };
    let stride = layout.outputs;
    let tasks = primitives.div_ceil(PRIMITIVES_PER_TASK);
    // A task's emitted vertices, its primitive list and, under a probe,
    // the (input primitive, emitted vertex) of each vertex.
    type TaskOutput = (Vec<f32>, Vec<u32>, Vec<EmittedBy>);
    let run_task = |t: usize| -> Result<TaskOutput, crate::ex::ExecError> {
        let first = t * PRIMITIVES_PER_TASK;
        let last = (first + PRIMITIVES_PER_TASK).min(primitives);
        let mut batch = new_batch(iface.input_components, iface.output_components);
        // Room for what small emissions (points into quads, triangles
        // passed through) make, without growing.
        let vertices = (PRIMITIVES_PER_TASK * emitted.max_vertices).min(1 << 12);
        let mut outputs = Vec::with_capacity(vertices * stride);
        let mut list = Vec::with_capacity(vertices * 3);
        let mut sources = Vec::new();
        for start in (first..last).step_by(LANES) {
            let lanes = (last - start).min(LANES);
            for c in batch.inputs.iter_mut() {
                *c = [0.0; LANES];
            }
            for lane in 0..lanes {
                load_primitive(&mut batch, lane, start + lane, &source);
            }
            batch.active = (1u32 << lanes) - 1;
            batch.discarded = 0;
            batch.helper = 0;
            match (probe.filter(|p| p.prints_others()), &prepared) {
                (Some(p), _) => p.print_geometry((gs, uniforms, textures), &mut batch, start)?,
                (None, Some(p)) => gs.run_prepared(&mut batch, p, uniforms, textures)?,
                (None, None) => gs.run(&mut batch, uniforms, textures)?,
            }
            if state.clamp_vertex_color {
                for v in 0..emitted.max_vertices {
                    for &(o, n) in &layout.colors {
                        let at = emitted.vertex(v) + o;
                        for comp in batch.outputs.iter_mut().skip(at).take(n) {
                            for x in comp.iter_mut() {
                                *x = if *x > 0.0 { x.min(1.0) } else { 0.0 };
                            }
                        }
                    }
                }
            }
            for lane in 0..lanes {
                let n = collect_lane(
                    &batch.outputs,
                    lane,
                    &emitted,
                    stride,
                    state.provoking_first,
                    &mut outputs,
                    &mut list,
                );
                if record {
                    sources.extend((0..n as u32).map(|vertex| EmittedBy {
                        primitive: (start + lane) as u32,
                        vertex,
                    }));
                }
            }
        }
        Ok((outputs, list, sources))
    };
    let results = workers.map(tasks, 1, |t, cancel| {
        if cancel.skip(t) {
            return None;
        }
        let r = run_task(t);
        if r.is_err() {
            cancel.fail(t);
        }
        Some(r)
    });
    // Tasks up to the first failure all ran: the first error in order is
    // the same whatever the thread count.
    let mut parts = Vec::with_capacity(results.len());
    for r in results.into_iter().flatten() {
        parts.push(r?);
    }
    // Joined into buffers sized once, kept from earlier draws (growing
    // fresh ones by doubling cost a copy and a page fault per 4 KiB on
    // this thread).
    let (mut outputs, mut vertex_of) = {
        let mut spare = workers.spare();
        (std::mem::take(&mut spare.emitted), spare.table())
    };
    outputs.clear();
    outputs.reserve(parts.iter().map(|p| p.0.len()).sum());
    vertex_of.reserve(parts.iter().map(|p| p.1.len()).sum());
    let mut sources = Vec::new();
    for (part, list, from) in parts {
        let base = (outputs.len() / stride.max(1)) as u32;
        vertex_of.extend(list.iter().map(|&v| base + v));
        outputs.extend_from_slice(&part);
        sources.extend(from);
    }
    let out = Vertices {
        mode: out_mode,
        vertex_of,
        outputs,
    };
    if let Some(p) = probe {
        p.note_emitted(sources);
    }
    Ok(out)
}

/// What fills a geometry lane: the vertex stage's results and where the
/// geometry kernel takes them.
pub(crate) struct PrimitiveSource<'a> {
    input: &'a Vertices,
    vs_stride: usize,
    plan: InputPlan,
    primitive_id: Option<usize>,
    arity: usize,
    state: &'a PipelineState,
}

impl<'a> PrimitiveSource<'a> {
    /// The inputs of geometry kernel `gs` from `input`, the results of
    /// vertex kernel `vs` (`vs_stride` values per vertex).
    pub(crate) fn new(
        vs: &Interface,
        gs: &Interface,
        vs_stride: usize,
        input: &'a Vertices,
        state: &'a PipelineState,
    ) -> PrimitiveSource<'a> {
        PrimitiveSource {
            input,
            vs_stride,
            plan: input_plan(vs, gs),
            primitive_id: gs.input("gl_PrimitiveIDIn").map(|s| s.offset),
            arity: gs.emitted.map_or(0, |e| e.input.vertices() as usize),
            state,
        }
    }

    /// The positions in the index list of input primitive `k`'s vertices,
    /// in the order the geometry shader takes them (the first `arity`).
    fn vertices(&self, k: usize) -> Option<[usize; 6]> {
        geometry_input(
            self.input.mode,
            self.input.vertex_of.len(),
            k,
            self.state.provoking_first,
        )
    }

    /// [`PrimitiveSource::vertices`] for the debugger, only those the
    /// shader takes.
    pub(crate) fn positions(&self, k: usize) -> Option<Vec<usize>> {
        let verts = self.vertices(k)?;
        Some(verts.iter().take(self.arity).copied().collect())
    }
}

/// Loads input primitive `k` into `lane` of a geometry batch (its
/// vertices' outputs and `gl_PrimitiveIDIn`).
pub(crate) fn load_primitive(batch: &mut Batch, lane: usize, k: usize, source: &PrimitiveSource) {
    let Some(verts) = source.vertices(k) else {
        return;
    };
    let input = source.input;
    for &(v, to, from, n) in &source.plan {
        let Some(&pos) = verts.get(v).filter(|_| v < source.arity) else {
            continue;
        };
        let Some(&vertex) = input.vertex_of.get(pos) else {
            continue;
        };
        let src = vertex as usize * source.vs_stride + from;
        let values = input.outputs.get(src..src + n).unwrap_or_default();
        for (dst, &x) in batch.inputs.iter_mut().skip(to).zip(values) {
            dst[lane] = x;
        }
    }
    if let Some(c) = source.primitive_id.and_then(|o| batch.inputs.get_mut(o)) {
        c[lane] = f32::from_bits(source.state.primitive_ids.of(k as u32));
    }
}

/// Appends what `lane` emitted to a task's vertices (`stride` values
/// each) and its primitives (as a list of `mode`'s vertices, numbered in
/// the task's vertices); gives the number of vertices appended.
fn collect_lane(
    batch: &[[f32; LANES]],
    lane: usize,
    emitted: &Emitted,
    stride: usize,
    provoking_first: bool,
    outputs: &mut Vec<f32>,
    list: &mut Vec<u32>,
) -> usize {
    let read = |c: usize| batch.get(c).map_or(0.0, |x| x[lane]);
    let n = (read(emitted.count()).to_bits() as usize).min(emitted.max_vertices);
    let base = (outputs.len() / stride.max(1)) as u32;
    for v in 0..n {
        let at = emitted.vertex(v);
        outputs.extend((0..stride).map(|c| read(at + c)));
    }
    let strip = |v: usize| read(emitted.strip(v)).to_bits();
    let mut start = 0;
    while start < n {
        let mut end = start + 1;
        while end < n && strip(end) == strip(start) {
            end += 1;
        }
        let s = base + start as u32;
        let len = (end - start) as u32;
        match emitted.output {
            OutputPrimitive::Points => list.extend(s..s + len),
            OutputPrimitive::LineStrip => {
                for i in 1..len {
                    list.extend([s + i - 1, s + i]);
                }
            }
            OutputPrimitive::TriangleStrip => {
                for i in 2..len {
                    let (a, b, c) = (s + i - 2, s + i - 1, s + i);
                    list.extend(match (i % 2 == 1, provoking_first) {
                        (false, _) => [a, b, c],
                        (true, false) => [b, a, c],
                        (true, true) => [a, c, b],
                    });
                }
            }
        }
        start = end;
    }
    n
}
