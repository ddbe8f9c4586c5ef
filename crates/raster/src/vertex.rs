//! Vertex fetch and the vertex stage.
//!
//! Takes the draw's index list, a [`VertexFetch`] (the attribute source)
//! and the vertex kernel; gives, per position in the index list, a vertex
//! number, and every distinct vertex's outputs (`VsLayout::outputs`
//! values each, colours clamped when the state asks), from
//! [`run_vertices`]. The kernel runs once per distinct index, in batches of
//! `LANES` vertices, tasks of [`VERTICES_PER_TASK`] on the [`Workers`].

use std::collections::HashMap;

use crate::ex::{Interface, Textures, LANES};
use crate::linkage::{new_batch, VsLayout};
use crate::probe::Probe;
use crate::workers::Workers;
use crate::{DrawError, ShaderStage};

/// Vertices one vertex-stage task takes (batches of `LANES`).
const VERTICES_PER_TASK: usize = 4 * LANES;

/// Supplies vertex attributes (from several threads at once when the draw
/// runs on more than one).
pub trait VertexFetch: Sync {
    /// Writes the attribute of vertex-kernel input slot `input_slot`
    /// (an index into `Interface::inputs`) for `vertex_index`. `out` starts
    /// as (0, 0, 0, 1); components the array does not provide stay so.
    /// An integer input's components are the integers' bits
    /// (`exec::Batch::inputs`), which the fetcher writes, defaults
    /// included.
    fn fetch(&self, input_slot: usize, vertex_index: u32, out: &mut [f32; 4]);

    /// Column `column` of a matrix attribute (matrix attributes take one
    /// attribute location per column). The default serves column 0 with
    /// [`VertexFetch::fetch`] and leaves the others at (0, 0, 0, 1).
    fn fetch_column(
        &self,
        input_slot: usize,
        column: usize,
        vertex_index: u32,
        out: &mut [f32; 4],
    ) {
        if column == 0 {
            self.fetch(input_slot, vertex_index, out);
        }
    }

    /// [`VertexFetch::fetch_column`] of the vertices `indices` (at most
    /// [`LANES`]): component `c` of vertex `indices[l]` into `out[c][l]`,
    /// each lane starting as (0, 0, 0, 1); lanes past the list are left
    /// as they are. The default asks for one vertex at a time
    /// ([`fetch_column_each`]); a fetcher can look its source up once for
    /// the whole list.
    fn fetch_column_lanes(
        &self,
        input_slot: usize,
        column: usize,
        indices: &[u32],
        out: &mut [[f32; LANES]; 4],
    ) {
        fetch_column_each(indices, out, |ix, v| {
            self.fetch_column(input_slot, column, ix, v)
        });
    }
}

/// [`VertexFetch::fetch_column_lanes`] one vertex at a time: `column(ix,
/// v)` writes vertex `ix`'s values into `v` (which starts as (0, 0, 0,
/// 1)), then lane `l` of `out` gets them.
pub fn fetch_column_each(
    indices: &[u32],
    out: &mut [[f32; LANES]; 4],
    mut column: impl FnMut(u32, &mut [f32; 4]),
) {
    for (l, &ix) in indices.iter().enumerate().take(LANES) {
        let mut v = [0.0, 0.0, 0.0, 1.0];
        column(ix, &mut v);
        for (o, x) in out.iter_mut().zip(v) {
            o[l] = x;
        }
    }
}

/// The vertex stage alone, as a draw runs it (transform feedback reads
/// its outputs before clipping): per position in `indices`, the vertex
/// number, and the outputs of every vertex, laid out as
/// `vs.interface().outputs` says, `stride` (the second value) apart.
/// Vertex colours are clamped when `clamp_colors` is set, as for a draw.
#[allow(clippy::too_many_arguments)]
pub fn shade_vertices(
    workers: &Workers,
    vs: &dyn ShaderStage,
    uniforms: &[u32],
    textures: &(dyn Textures + Sync),
    indices: &[u32],
    fetch: &dyn VertexFetch,
    clamp_colors: bool,
) -> Result<(Vec<u32>, Vec<f32>, usize), DrawError> {
    let layout = VsLayout::new(vs.interface());
    let (vertex_of, outputs) = run_vertices(
        workers,
        vs,
        uniforms,
        textures,
        indices,
        fetch,
        &layout,
        clamp_colors,
        None,
    )?;
    Ok((vertex_of, outputs, layout.outputs))
}

/// Runs the vertex kernel once per distinct index. Returns, per position
/// in `indices`, the vertex number, and the outputs of every vertex
/// (`layout.outputs` values each). Batches of `LANES` vertices run as
/// separate tasks on `workers`; each writes only its own vertices.
///
/// When the index range holds at most as many vertices as there are
/// indices (arrays, and meshes whose vertices are all used), every vertex
/// of the range runs, in order, without the pass over the indices that
/// finds the distinct ones (which runs on this thread alone while the
/// workers wait): a vertex no index names costs a lane and changes
/// nothing, vertex shaders having no side effects, unless it fails (a
/// loop budget), when the draw runs again with the distinct vertices
/// only, so that only theirs can fail it. (The debugger's probe lists
/// the vertices that run: only the named ones.)
#[allow(clippy::too_many_arguments)]
pub(crate) fn run_vertices(
    workers: &Workers,
    vs: &dyn ShaderStage,
    uniforms: &[u32],
    textures: &(dyn Textures + Sync),
    indices: &[u32],
    fetch: &dyn VertexFetch,
    layout: &VsLayout,
    clamp_colors: bool,
    probe: Option<&Probe>,
) -> Result<(Vec<u32>, Vec<f32>), DrawError> {
    let run = |whole_range| {
        run_vertices_with(
            workers,
            (vs, uniforms, textures),
            indices,
            fetch,
            (layout, clamp_colors),
            probe,
            whole_range,
        )
    };
    // (The probe lists the vertices that run: only the named ones.)
    let whole_range = probe.is_none();
    match run(whole_range) {
        Err(DrawError::Exec(_)) if whole_range => run(false),
        r => r,
    }
}

/// [`run_vertices`], with every vertex of the index range when
/// `whole_range` allows it.
fn run_vertices_with(
    workers: &Workers,
    (vs, uniforms, textures): (&dyn ShaderStage, &[u32], &(dyn Textures + Sync)),
    indices: &[u32],
    fetch: &dyn VertexFetch,
    (layout, clamp_colors): (&VsLayout, bool),
    probe: Option<&Probe>,
    whole_range: bool,
) -> Result<(Vec<u32>, Vec<f32>), DrawError> {
    let iface: &Interface = vs.interface();
    if indices.len() >= u32::MAX as usize {
        return Err(DrawError::TooManyIndices(indices.len()));
    }
    // Distinct indices in order of first use; a table over the index
    // range when it is small (the usual case), else a hash map. Vertex
    // numbers are u32 (fewer than 2^32 indices): half the memory of usize
    // to write per index. The tables come from earlier draws (fresh ones
    // cost a page fault per 4 KiB on this thread).
    let (mut unique, mut vertex_of, mut slot) = {
        let mut spare = workers.spare();
        (spare.table(), spare.table(), spare.table())
    };
    vertex_of.reserve(indices.len());
    let lo = indices.iter().copied().min().unwrap_or(0);
    let hi = indices.iter().copied().max().unwrap_or(0);
    let span = (hi - lo) as usize + 1;
    if whole_range && span <= indices.len() {
        unique.extend(lo..=hi);
        vertex_of.extend(indices.iter().map(|&ix| ix - lo));
    } else if span <= 4 * indices.len() + 1024 {
        unique.reserve(span.min(indices.len()));
        slot.resize(span, u32::MAX);
        for &ix in indices {
            let Some(s) = slot.get_mut((ix - lo) as usize) else {
                continue;
            };
            if *s == u32::MAX {
                *s = unique.len() as u32;
                unique.push(ix);
            }
            vertex_of.push(*s);
        }
    } else {
        let mut seen: HashMap<u32, u32> = HashMap::new();
        for &ix in indices {
            let v = *seen.entry(ix).or_insert_with(|| {
                unique.push(ix);
                unique.len() as u32 - 1
            });
            vertex_of.push(v);
        }
    }
    let n_in = iface
        .inputs
        .iter()
        .map(|s| s.offset + s.components)
        .max()
        .unwrap_or(0);
    let stride = layout.outputs;
    // Uniform-only values once per draw, not per batch (a draw of a few
    // vertices runs them once either way).
    let prepared = if unique.len() > LANES {
        vs.prepare(uniforms, textures)
    } else {
        None
    };
    // Each task runs its vertices' batches with one batch and writes their
    // outputs straight into its own part of the draw's output array.
    // Every value is written by the tasks (a batch's outputs the shader
    // leaves unwritten are zero): the array kept from the last draw is
    // not cleared first (a memset of the whole array, on this thread
    // alone).
    let mut outputs = std::mem::take(&mut workers.spare().outputs);
    outputs.resize(unique.len() * stride, 0.0);
    let mut rest: &mut [f32] = &mut outputs;
    let mut tasks: Vec<(&[u32], std::sync::Mutex<&mut [f32]>)> = Vec::new();
    for group in unique.chunks(VERTICES_PER_TASK) {
        let len = (group.len() * stride).min(rest.len());
        let (part, tail) = std::mem::take(&mut rest).split_at_mut(len);
        tasks.push((group, std::sync::Mutex::new(part)));
        rest = tail;
    }
    let plan = input_plan(iface);
    let run_group = |group: &[u32], out: &mut [f32]| -> Result<(), crate::ex::ExecError> {
        let mut batch = new_batch(n_in, stride);
        for (c, chunk) in group.chunks(LANES).enumerate() {
            // As a fresh batch: outputs the shader leaves unwritten are 0.
            for c in batch.inputs.iter_mut().chain(batch.outputs.iter_mut()) {
                *c = [0.0; LANES];
            }
            fetch_planned(&plan, fetch, chunk, &mut batch, 0);
            batch.active = if chunk.len() >= 32 {
                u32::MAX
            } else {
                (1u32 << chunk.len()) - 1
            };
            batch.discarded = 0;
            batch.helper = 0;
            match probe.filter(|p| p.prints_others()) {
                Some(p) => p.print_vertices(vs, &mut batch, uniforms, textures, chunk)?,
                None => match &prepared {
                    Some(p) => vs.run_prepared(&mut batch, p, uniforms, textures)?,
                    None => vs.run(&mut batch, uniforms, textures)?,
                },
            }
            // Colours clamped over the lanes at once, then each vertex's
            // outputs copied out.
            if clamp_colors {
                for &(o, n) in &layout.colors {
                    for comp in batch.outputs.iter_mut().skip(o).take(n) {
                        for v in comp.iter_mut() {
                            *v = if *v > 0.0 { v.min(1.0) } else { 0.0 };
                        }
                    }
                }
            }
            let part = out.get_mut(c * LANES * stride..).unwrap_or_default();
            for (lane, vertex) in part
                .chunks_exact_mut(stride.max(1))
                .take(chunk.len())
                .enumerate()
            {
                for (dst, comp) in vertex.iter_mut().zip(&batch.outputs) {
                    *dst = comp[lane];
                }
            }
        }
        Ok(())
    };
    let results = workers.map(tasks.len(), 1, |i, cancel| {
        if cancel.skip(i) {
            return None;
        }
        let (group, part) = tasks.get(i)?;
        let mut part = part.lock().unwrap_or_else(|e| e.into_inner());
        let r = run_group(group, &mut part);
        if r.is_err() {
            cancel.fail(i);
        }
        Some(r)
    });
    drop(tasks);
    workers.spare().keep_tables([unique, slot]);
    // Groups up to the first failure all ran: the first error in order is
    // the same whatever the thread count.
    for r in results.into_iter().flatten() {
        r?;
    }
    Ok((vertex_of, outputs))
}

/// Fetches vertex `ix`'s attributes into `lane` of a vertex batch (laid
/// out as the vertex shader's inputs; matrices column by column).
pub fn fetch_vertex(
    iface: &Interface,
    fetch: &dyn VertexFetch,
    ix: u32,
    batch: &mut crate::ex::Batch,
    lane: usize,
) {
    fetch_planned(&input_plan(iface), fetch, &[ix], batch, lane);
}

/// Per vertex input slot: (slot number, first component, columns, rows).
type InputPlan = Vec<(usize, usize, usize, usize)>;

/// How [`fetch_vertex`] lays out `iface`'s inputs (matrices column by
/// column), worked out once per draw.
fn input_plan(iface: &Interface) -> InputPlan {
    iface
        .inputs
        .iter()
        .enumerate()
        .map(|(slot_no, slot)| {
            let (cols, rows) = match slot.ty.base {
                glsl::types::Base::Matrix { cols, rows } if slot.ty.array.is_none() => {
                    (cols as usize, rows as usize)
                }
                _ => (1, slot.components.min(4)),
            };
            (slot_no, slot.offset, cols, rows)
        })
        .collect()
}

/// [`fetch_vertex`] with the layout of [`input_plan`], for the vertices
/// `indices` (at most [`LANES`]) into lanes `first..` of `batch` (those
/// past the last lane dropped): a column of an input for all of them at
/// once ([`VertexFetch::fetch_column_lanes`]).
fn fetch_planned(
    plan: &InputPlan,
    fetch: &dyn VertexFetch,
    indices: &[u32],
    batch: &mut crate::ex::Batch,
    first: usize,
) {
    let n = indices.len().min(LANES);
    for &(slot_no, offset, cols, rows) in plan {
        for col in 0..cols {
            let mut v = [[0.0; LANES], [0.0; LANES], [0.0; LANES], [1.0; LANES]];
            fetch.fetch_column_lanes(slot_no, col, &indices[..n], &mut v);
            let at = offset + col * rows;
            let dst = batch.inputs.get_mut(at..).unwrap_or_default();
            for (d, value) in dst.iter_mut().zip(&v[..rows.min(4)]) {
                for (d, &x) in d.iter_mut().skip(first).zip(&value[..n]) {
                    *d = x;
                }
            }
        }
    }
}
