//! `draw()`: vertex stage, primitive assembly, clipping, viewport
//! transform, face determination and culling, then tiled rasterization and
//! fragment shading.

use std::collections::HashMap;
use std::sync::Mutex;

use crate::clip::{ClipVertex, Planes};
use crate::ex::{ExecError, Interface, Textures, LANES};
use crate::framebuffer::{Band, Framebuffer};
use crate::interpolate::{Plane, PrimPlanes};
use crate::linkage::{FsLayout, VsLayout};
use crate::rasterize::{max_depth_slope, snap, vertex_depths, PixelRect, Shape, WinVertex};
use crate::shade::{new_batch, plane_origin, FragmentStage, Prim};
use crate::simd::Isa;
use crate::state::{CullFace, FrontFace, PipelineState, PolygonMode};
use crate::workers::Workers;
use crate::{DrawError, ShaderStage};

/// Tile size: fragments are produced tile by tile, each tile seeing the
/// primitives in draw order; tiles run in parallel.
pub const TILE: i64 = 64;

/// Vertices one vertex-stage task takes (batches of `LANES`).
const VERTICES_PER_TASK: usize = 4 * LANES;

/// Primitives one set-up task takes.
const SETUP_CHUNK: usize = 2048;

/// Largest point size used (points are clamped to [1, MAX_POINT_SIZE]).
pub const MAX_POINT_SIZE: f32 = 2048.0;

/// Viewport coordinates are clamped to ±2^19 so window positions fit the
/// rasterizer's fixed-point range.
const VIEWPORT_LIMIT: i64 = 1 << 19;

/// Supplies vertex attributes (from several threads at once when the draw
/// runs on more than one).
pub trait VertexFetch: Sync {
    /// Writes the attribute of vertex-kernel input slot `input_slot`
    /// (an index into `Interface::inputs`) for `vertex_index`. `out` starts
    /// as (0, 0, 0, 1); components the array does not provide stay so.
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

/// Begin/End modes (GL 2.1 §2.6.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Points,
    Lines,
    LineStrip,
    LineLoop,
    Triangles,
    TriangleStrip,
    TriangleFan,
    Quads,
    QuadStrip,
    Polygon,
}

/// One assembled primitive; vertex numbers are positions in `indices`.
#[derive(Debug, PartialEq)]
pub(crate) enum Assembled {
    Point(usize),
    /// (first, second); the second is the provoking vertex (§2.14.7).
    Line(usize, usize),
    /// Vertices in order and the provoking vertex (GL 2.1 table 2.12).
    Polygon(Vec<usize>, usize),
}

/// How many primitives `count` vertices of `mode` make (incomplete
/// trailing primitives are dropped, GL 2.1 §2.6.1).
pub(crate) fn primitive_count(mode: Mode, count: usize) -> usize {
    let n = count;
    match mode {
        Mode::Points => n,
        Mode::Lines => n / 2,
        Mode::LineStrip => n.saturating_sub(1),
        Mode::LineLoop => {
            if n >= 2 {
                n
            } else {
                0
            }
        }
        Mode::Triangles => n / 3,
        Mode::TriangleStrip | Mode::TriangleFan => n.saturating_sub(2),
        Mode::Quads => n / 4,
        Mode::QuadStrip => (n / 2).saturating_sub(1),
        Mode::Polygon => usize::from(n >= 3),
    }
}

/// Primitive `k` (below [`primitive_count`]) of `count` vertices of `mode`.
pub(crate) fn primitive(mode: Mode, count: usize, k: usize) -> Assembled {
    let n = count;
    match mode {
        Mode::Points => Assembled::Point(k),
        Mode::Lines => Assembled::Line(2 * k, 2 * k + 1),
        Mode::LineStrip => Assembled::Line(k, k + 1),
        Mode::LineLoop => {
            if k + 1 < n {
                Assembled::Line(k, k + 1)
            } else {
                Assembled::Line(n - 1, 0)
            }
        }
        Mode::Polygon => Assembled::Polygon((0..n).collect(), 0),
        _ => match small_polygon(mode, k) {
            Some((v, len, provoking)) => Assembled::Polygon(v[..len].to_vec(), provoking),
            None => Assembled::Polygon(Vec::new(), 0),
        },
    }
}

/// Primitive `k` of the triangle and quad modes without allocating:
/// vertices (the first `len` of them) and the provoking vertex (GL 2.1
/// table 2.12). `None` for the other modes.
fn small_polygon(mode: Mode, k: usize) -> Option<([usize; 4], usize, usize)> {
    Some(match mode {
        Mode::Triangles => ([3 * k, 3 * k + 1, 3 * k + 2, 0], 3, 3 * k + 2),
        Mode::TriangleStrip => {
            let i = k + 2;
            // Every other triangle is reversed to keep a common winding.
            let v = if i.is_multiple_of(2) {
                [i - 2, i - 1, i, 0]
            } else {
                [i - 1, i - 2, i, 0]
            };
            (v, 3, i)
        }
        Mode::TriangleFan => ([0, k + 1, k + 2, 0], 3, k + 2),
        Mode::Quads => {
            let b = 4 * k;
            ([b, b + 1, b + 2, b + 3], 4, b + 3)
        }
        Mode::QuadStrip => {
            let b = 2 * k;
            ([b, b + 1, b + 3, b + 2], 4, b + 3)
        }
        _ => return None,
    })
}

/// Splits `count` vertices of `mode` into primitives, in order.
#[cfg(test)]
pub(crate) fn assemble(mode: Mode, count: usize, mut emit: impl FnMut(Assembled)) {
    for k in 0..primitive_count(mode, count) {
        emit(primitive(mode, count, k));
    }
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
fn run_vertices(
    workers: &Workers,
    vs: &dyn ShaderStage,
    uniforms: &[u32],
    textures: &(dyn Textures + Sync),
    indices: &[u32],
    fetch: &dyn VertexFetch,
    layout: &VsLayout,
    clamp_colors: bool,
    probe: Option<&crate::probe::Probe>,
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
    probe: Option<&crate::probe::Probe>,
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
        vs.prepare(uniforms)
    } else {
        None
    };
    // Each task runs its vertices' batches with one batch and writes their
    // outputs straight into its own part of the draw's output array.
    // Every value is written by the tasks (a batch's outputs the shader
    // leaves unwritten are zero): the array kept from the last draw is
    // not cleared first (7 MB of memset on this thread for 150k
    // vertices).
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

/// Turns assembled primitives into set-up [`Prim`]s.
struct Setup<'a> {
    state: &'a PipelineState,
    vs: &'a VsLayout,
    fs: &'a FsLayout,
    outputs: &'a [f32],
    planes: Planes,
    clip_rect: PixelRect,
    /// Viewport transform (px/2, ox, py/2, oy, (f-n)/2, (n+f)/2).
    vp: [f64; 6],
    probe: Option<&'a crate::probe::Probe>,
    /// Per vertex (when vertices are shared enough to be worth it, else
    /// empty): its clip-plane outcode and window position, what
    /// [`Setup::polygon`] computes for each primitive's vertices.
    corners: &'a [Corner],
}

/// A vertex's [`Planes::outcode_of`], [`Setup::window`] and that
/// position in fixed point ([`snap`]).
#[derive(Clone, Copy)]
pub(crate) struct Corner {
    outcode: u32,
    win: Option<(WinVertex, (i64, i64))>,
}

/// Below this many primitive vertices per vertex the set-up computes each
/// vertex's outcode and window position where it is used (no table).
const CORNER_REUSE: usize = 2;

/// Where set-up primitives go: the primitives of one chunk, their
/// fragment varyings' planes (`Prim::index` × links locates a primitive's in `planes`), and the index of
/// the assembled primitive being set up.
struct Out {
    prims: Vec<Prim>,
    planes: Vec<Plane>,
    source: u32,
    /// The set-up chunk (its index in the draw's chunks).
    chunk: u32,
}

/// The frame's 64×64 tiles.
#[derive(Clone, Copy)]
struct TileGrid {
    w: i64,
    h: i64,
    tiles_x: i64,
    tiles: usize,
}

impl TileGrid {
    fn new(fb: &Framebuffer) -> TileGrid {
        let (w, h) = (fb.width as i64, fb.height as i64);
        let tiles_x = (w + TILE - 1) / TILE;
        let tiles_y = (h + TILE - 1) / TILE;
        TileGrid {
            w,
            h,
            tiles_x,
            tiles: (tiles_x * tiles_y).max(0) as usize,
        }
    }

    /// The tile row of tile `t`.
    fn row(&self, t: usize) -> usize {
        t / self.tiles_x.max(1) as usize
    }

    /// Tile `t`'s pixels, clipped to the frame.
    fn rect(&self, t: usize) -> PixelRect {
        let tiles_x = self.tiles_x.max(1);
        let (tx, ty) = (t as i64 % tiles_x, t as i64 / tiles_x);
        let (x, y) = (tx * TILE, ty * TILE);
        (x, y, (x + TILE).min(self.w), (y + TILE).min(self.h))
    }

    /// Calls `f` with each tile a primitive's bounds overlap, row by row
    /// (most primitives of a big mesh overlap one: no loop for those).
    #[inline(always)]
    fn tiles_each(&self, prim: &Prim, mut f: impl FnMut(usize)) {
        let (w, h, tiles_x) = (self.w, self.h, self.tiles_x);
        let b = prim.bounds;
        let (x0, y0) = (b.0.clamp(0, w), b.1.clamp(0, h));
        let (x1, y1) = (b.2.clamp(x0, w), b.3.clamp(y0, h));
        if x0 >= x1 || y0 >= y1 {
            return;
        }
        let (tx0, tx1) = (x0 / TILE, (x1 - 1) / TILE);
        let (ty0, ty1) = (y0 / TILE, (y1 - 1) / TILE);
        if tx0 == tx1 && ty0 == ty1 {
            return f((ty0 * tiles_x + tx0) as usize);
        }
        for ty in ty0..=ty1 {
            for tx in tx0..=tx1 {
                f((ty * tiles_x + tx) as usize);
            }
        }
    }
}

/// One set-up chunk's primitives by tile (a counting sort):
/// `items[starts[t]..starts[t + 1]]` are the chunk indices of the
/// primitives overlapping tile `t`, in order.
struct ChunkBins {
    starts: Vec<u32>,
    items: Vec<u32>,
}

impl ChunkBins {
    fn new(prims: &[Prim], grid: &TileGrid) -> ChunkBins {
        let mut starts = vec![0u32; grid.tiles + 1];
        for prim in prims {
            grid.tiles_each(prim, |t| {
                if let Some(c) = starts.get_mut(t + 1) {
                    *c += 1;
                }
            });
        }
        for t in 0..grid.tiles {
            starts[t + 1] += starts[t];
        }
        let mut next = starts.clone();
        let mut items = vec![0u32; starts[grid.tiles] as usize];
        for (i, prim) in prims.iter().enumerate() {
            grid.tiles_each(prim, |t| {
                if let Some(n) = next.get_mut(t) {
                    if let Some(slot) = items.get_mut(*n as usize) {
                        *slot = i as u32;
                    }
                    *n += 1;
                }
            });
        }
        ChunkBins { starts, items }
    }

    fn tile(&self, t: usize) -> &[u32] {
        let (a, b) = (self.starts.get(t), self.starts.get(t + 1));
        match (a, b) {
            (Some(&a), Some(&b)) => self.items.get(a as usize..b as usize).unwrap_or(&[]),
            _ => &[],
        }
    }
}

/// The draw's primitives by tile: each chunk's bins and the index of its
/// first primitive in the draw.
struct Bins {
    grid: TileGrid,
    chunks: Vec<(ChunkBins, u32)>,
}

impl Bins {
    fn new(chunks: Vec<ChunkBins>, parts: &[(Vec<Prim>, Vec<Plane>)], grid: TileGrid) -> Bins {
        let mut base = 0u32;
        let chunks = chunks
            .into_iter()
            .zip(parts)
            .map(|(b, part)| {
                let first = base;
                base = base.saturating_add(part.0.len() as u32);
                (b, first)
            })
            .collect();
        Bins { grid, chunks }
    }

    /// The tiles some primitive overlaps, in order.
    fn occupied(&self) -> Vec<usize> {
        (0..self.grid.tiles)
            .filter(|&t| self.chunks.iter().any(|(b, _)| !b.tile(t).is_empty()))
            .collect()
    }

    /// The draw indices of tile `t`'s primitives, in draw order.
    fn tile(&self, t: usize) -> Vec<u32> {
        let n = self.chunks.iter().map(|(b, _)| b.tile(t).len()).sum();
        let mut out = Vec::with_capacity(n);
        for (b, first) in &self.chunks {
            out.extend(b.tile(t).iter().map(|&i| first + i));
        }
        out
    }
}

const NO_WIN: WinVertex = WinVertex {
    x: 0.0,
    y: 0.0,
    z: 0.0,
    inv_w: 0.0,
};

impl Setup<'_> {
    fn data(&self, v: usize) -> &[f32] {
        let s = self.vs.outputs;
        self.outputs.get(v * s..(v + 1) * s).unwrap_or(&[])
    }

    fn clip_vertex(&self, v: usize) -> ClipVertex {
        let data = self.data(v);
        ClipVertex {
            pos: self.vs.position(data),
            eye: self.vs.eye(data),
            data: data.to_vec(),
        }
    }

    /// Perspective division and viewport transform (GL 2.1 §2.11) of a
    /// clip-space position.
    fn window(&self, pos: [f32; 4]) -> Option<WinVertex> {
        let w = pos[3] as f64;
        if w.is_nan() || w <= 0.0 {
            return None;
        }
        let [sx, ox, sy, oy, sz, oz] = self.vp;
        let xd = pos[0] as f64 / w;
        let yd = pos[1] as f64 / w;
        let zd = pos[2] as f64 / w;
        let win = WinVertex {
            x: sx * xd + ox,
            y: sy * yd + oy,
            z: sz * zd + oz,
            inv_w: 1.0 / w,
        };
        (win.x.is_finite() && win.y.is_finite() && win.z.is_finite() && win.inv_w.is_finite())
            .then_some(win)
    }

    /// Appends the planes of the fragment varyings of `shape` (`win` and
    /// `vertices`: the window positions and the data of its vertices) to
    /// `out.planes`, flat-shaded colours constant at `provoking`'s,
    /// origin pixel `origin`; returns the primitive's own planes (window
    /// z, 1/w).
    #[inline(always)]
    fn planes(
        &self,
        out: &mut Out,
        (shape, win): (&Shape, &[WinVertex]),
        origin: (i64, i64),
        vertices: &[&[f32]],
        (back, provoking): (bool, &[f32]),
    ) -> PrimPlanes {
        let basis = shape.basis(origin);
        let (z, inv_w) = vertex_depths(win);
        let prim = PrimPlanes::new(&basis, z, inv_w);
        // A line's or a point's missing vertices repeat its last.
        let data = |j: usize| vertices.get(j).or(vertices.last()).copied().unwrap_or(&[]);
        let (d0, d1, d2) = (data(0), data(1), data(2));
        let flat = self.state.flat_shading;
        for link in &self.fs.links {
            let src = if back { link.back } else { link.front };
            let get = |d: &[f32]| src.and_then(|o| d.get(o)).copied().unwrap_or(0.0);
            out.planes.push(match flat && link.color {
                true => Plane::constant(get(provoking)),
                false => prim.varying(&basis, [get(d0), get(d1), get(d2)], inv_w),
            });
        }
        prim
    }

    /// Sets up `shape`, whose vertices are `win` (window positions) and
    /// `vertices` (their data).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn push(
        &self,
        out: &mut Out,
        (shape, win): (Shape, &[WinVertex]),
        back: bool,
        z_offset: f64,
        vertices: &[&[f32]],
        provoking: &[f32],
    ) {
        if let Some(p) = self.probe {
            p.note_shape(win);
        }
        let b = shape.bounds();
        let c = self.clip_rect;
        let bounds = (b.0.max(c.0), b.1.max(c.1), b.2.min(c.2), b.3.min(c.3));
        if bounds.0 >= bounds.2 || bounds.1 >= bounds.3 {
            return;
        }
        let origin = plane_origin(bounds);
        let planes = self.planes(out, (&shape, win), origin, vertices, (back, provoking));
        if let Some(p) = self.probe {
            p.note_window(win);
        }
        out.prims.push(Prim {
            shape,
            bounds,
            back,
            z_offset,
            planes,
            index: out.prims.len() as u32,
            chunk: out.chunk,
            source: out.source,
        });
    }

    fn point_size(&self, data: &[f32]) -> f32 {
        let size = match (self.state.vertex_program_point_size, self.vs.point_size) {
            (true, Some(o)) => data.get(o).copied().unwrap_or(1.0),
            _ => self.state.point_size,
        };
        if size.is_nan() {
            1.0
        } else {
            size.clamp(1.0, MAX_POINT_SIZE)
        }
    }

    fn point(&self, out: &mut Out, v: &ClipVertex, back: bool, z_offset: f64, provoking: &[f32]) {
        if !self.planes.point_inside(v) {
            return;
        }
        let Some(win) = self.window(v.pos) else {
            return;
        };
        let size = self.point_size(&v.data) as f64;
        let shape = Shape::point(win, size, self.state.point_sprite);
        self.push(out, (shape, &[win]), back, z_offset, &[&v.data], provoking);
    }

    fn line(
        &self,
        out: &mut Out,
        a: &ClipVertex,
        b: &ClipVertex,
        back: bool,
        z_offset: f64,
        provoking: &[f32],
    ) {
        let Some((a, b)) = self.planes.clip_line(a, b) else {
            return;
        };
        let (Some(wa), Some(wb)) = (self.window(a.pos), self.window(b.pos)) else {
            return;
        };
        let shape = Shape::line([wa, wb], self.state.line_width);
        self.push(
            out,
            (shape, &[wa, wb]),
            back,
            z_offset,
            &[&a.data, &b.data],
            provoking,
        );
    }

    /// Vertex `v`'s outcode and window position: from the table when
    /// there is one, else computed.
    #[inline(always)]
    fn corner(&self, v: usize) -> Corner {
        match self.corners.get(v) {
            Some(&c) => c,
            None => self.compute_corner(v),
        }
    }

    fn compute_corner(&self, v: usize) -> Corner {
        let d = self.data(v);
        let pos = self.vs.position(d);
        let outcode = self.planes.outcode_of(&pos, &self.vs.eye(d));
        Corner {
            outcode,
            // Only read for vertices inside every plane.
            win: match outcode {
                0 => self.window(pos).map(|w| (w, snap(&w))),
                _ => None,
            },
        }
    }

    /// Sets up a polygon (`vertices`, `provoking`: vertex numbers):
    /// clipped, culled, offset, filled as triangles or outlined.
    fn polygon(&self, out: &mut Out, vertices: &[usize], provoking: usize) {
        self.polygon_with(out, vertices, provoking)
    }

    /// [`Setup::polygon`] compiled for AVX2 with the bit-count
    /// instructions (the set-up inlined into it: the same f64 operations,
    /// none fused, so the same values).
    ///
    /// # Safety
    /// The CPU must have those features ([`crate::simd::Isa::Avx2`]).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt,bmi1,lzcnt")]
    unsafe fn polygon_avx2(&self, out: &mut Out, vertices: &[usize], provoking: usize) {
        self.polygon_with(out, vertices, provoking)
    }

    #[inline(always)]
    fn polygon_with(&self, out: &mut Out, vertices: &[usize], provoking: usize) {
        // Line and point modes draw the unclipped polygon's edges/vertices.
        let filled_only = self.state.polygon_mode == [PolygonMode::Fill; 2];
        let prov = self.data(provoking);
        if filled_only && (3..=4).contains(&vertices.len()) {
            // Triangles and quads inside every plane (the usual case) skip
            // the clipper and its copies: what it would return unchanged.
            let mut corners = [Corner {
                outcode: 0,
                win: None,
            }; 4];
            let (mut all, mut any) = (0u32, !0u32);
            for (c, &v) in corners.iter_mut().zip(vertices) {
                *c = self.corner(v);
                all |= c.outcode;
                any &= c.outcode;
            }
            if any != 0 {
                return;
            }
            if all == 0 {
                let mut win = [NO_WIN; 4];
                let mut fixed = [(0, 0); 4];
                let mut data: [&[f32]; 4] = [&[]; 4];
                for (i, (&v, c)) in vertices.iter().zip(&corners).enumerate() {
                    let Some((w, f)) = c.win else {
                        return;
                    };
                    (win[i], fixed[i]) = (w, f);
                    data[i] = self.data(v);
                }
                let n = vertices.len();
                let polygon = (&win[..n], &fixed[..n]);
                self.set_up_polygon(out, polygon, &data[..n], &[], prov);
                return;
            }
        }
        let original: Vec<ClipVertex> = vertices.iter().map(|&v| self.clip_vertex(v)).collect();
        let (original, clipped) = if filled_only {
            (Vec::new(), self.planes.clip_polygon(original))
        } else {
            let clipped = self.planes.clip_polygon(original.clone());
            (original, clipped)
        };
        if clipped.len() < 3 {
            return;
        }
        let Some(win) = clipped
            .iter()
            .map(|v| self.window(v.pos))
            .collect::<Option<Vec<_>>>()
        else {
            return;
        };
        let data: Vec<&[f32]> = clipped.iter().map(|v| &v.data[..]).collect();
        let fixed: Vec<(i64, i64)> = win.iter().map(snap).collect();
        self.set_up_polygon(out, (&win, &fixed), &data, &original, prov);
    }

    /// Facing, culling, polygon offset and the polygon mode of a clipped
    /// polygon (`win`, its [`snap`] `fixed` and `data` per vertex, at
    /// least three; `original`: the unclipped polygon, for line and point
    /// modes).
    #[inline(always)]
    fn set_up_polygon(
        &self,
        out: &mut Out,
        (win, fixed): (&[WinVertex], &[(i64, i64)]),
        data: &[&[f32]],
        original: &[ClipVertex],
        prov: &[f32],
    ) {
        // GL 2.1 §3.5.1 eq. 3.6: the sign of the window-space area.
        let mut area = 0.0f64;
        for i in 0..win.len() {
            let j = (i + 1) % win.len();
            area += win[i].x * win[j].y - win[j].x * win[i].y;
        }
        let ccw = area > 0.0;
        let front = ccw == (self.state.front_face == FrontFace::Ccw);
        let back = !front;
        match self.state.cull {
            Some(CullFace::FrontAndBack) => return,
            Some(CullFace::Front) if front => return,
            Some(CullFace::Back) if back => return,
            _ => {}
        }
        let mode = self.state.polygon_mode[back as usize];
        let po = self.state.polygon_offset;
        let offset_on = match mode {
            PolygonMode::Fill => po.fill,
            PolygonMode::Line => po.line,
            PolygonMode::Point => po.point,
        };
        // Fan triangle i (vertices 0, i, i + 1), from the snapped
        // positions; `None` when it has no area.
        let fan = |i: usize| {
            let corner = |j: usize| fixed.get(j).copied().unwrap_or_default();
            Shape::triangle_snapped([corner(0), corner(i), corner(i + 1)])
        };
        let z_offset = if offset_on {
            // §3.5.5: o = m · factor + r · units.
            let m = (1..win.len() - 1)
                .find(|&i| fan(i).is_some())
                .map_or(0.0, |i| max_depth_slope(&[win[0], win[i], win[i + 1]]));
            m * po.factor as f64 + po.units as f64 / crate::framebuffer::DEPTH_MAX as f64
        } else {
            0.0
        };
        match mode {
            PolygonMode::Fill => {
                for i in 1..win.len() - 1 {
                    let Some(shape) = fan(i) else {
                        continue;
                    };
                    let tri = [win[0], win[i], win[i + 1]];
                    let (Some(&d0), Some(&di), Some(&dj)) =
                        (data.first(), data.get(i), data.get(i + 1))
                    else {
                        continue;
                    };
                    self.push(out, (shape, &tri), back, z_offset, &[d0, di, dj], prov);
                }
            }
            PolygonMode::Line => {
                for i in 0..original.len() {
                    let j = (i + 1) % original.len();
                    self.line(out, &original[i], &original[j], back, z_offset, prov);
                }
            }
            PolygonMode::Point => {
                for v in original {
                    self.point(out, v, back, z_offset, prov);
                }
            }
        }
    }
}

/// [`crate::draw_on`] over any [`ShaderStage`] pair.
#[allow(clippy::too_many_arguments)]
pub fn draw_stages(
    workers: &Workers,
    fb: &mut Framebuffer,
    state: &PipelineState,
    vs: &dyn ShaderStage,
    vs_uniforms: &[u32],
    fs: &dyn ShaderStage,
    fs_uniforms: &[u32],
    mode: Mode,
    indices: &[u32],
    fetch: &dyn VertexFetch,
    textures: &(dyn Textures + Sync),
) -> Result<(), DrawError> {
    draw_probed(
        workers,
        fb,
        state,
        (vs, vs_uniforms),
        (fs, fs_uniforms),
        mode,
        indices,
        fetch,
        textures,
        None,
    )
}

/// [`draw_stages`], reporting to `probe` what happens at its pixel.
#[allow(clippy::too_many_arguments)]
pub(crate) fn draw_probed(
    workers: &Workers,
    fb: &mut Framebuffer,
    state: &PipelineState,
    (vs, vs_uniforms): (&dyn ShaderStage, &[u32]),
    (fs, fs_uniforms): (&dyn ShaderStage, &[u32]),
    mode: Mode,
    indices: &[u32],
    fetch: &dyn VertexFetch,
    textures: &(dyn Textures + Sync),
    probe: Option<&crate::probe::Probe>,
) -> Result<(), DrawError> {
    let vs_layout = VsLayout::new(vs.interface());
    let fs_layout = FsLayout::new(vs.interface(), fs.interface(), state.two_sided_color);
    let (vertex_of, outputs) = run_vertices(
        workers,
        vs,
        vs_uniforms,
        textures,
        indices,
        fetch,
        &vs_layout,
        state.clamp_vertex_color,
        probe,
    )?;

    let vp = state.viewport;
    let lim = |v: i32| (v as i64).clamp(-VIEWPORT_LIMIT, VIEWPORT_LIMIT) as f64;
    let (vw, vh) = (lim(vp.w.max(0)), lim(vp.h.max(0)));
    let (n, f) = (state.depth_range.0 as f64, state.depth_range.1 as f64);
    let mut clip_rect = (0, 0, fb.width as i64, fb.height as i64);
    if let Some(s) = state.scissor {
        let (x0, y0) = (s.x as i64, s.y as i64);
        clip_rect = (
            clip_rect.0.max(x0),
            clip_rect.1.max(y0),
            clip_rect.2.min(x0 + s.w.max(0) as i64),
            clip_rect.3.min(y0 + s.h.max(0) as i64),
        );
    }
    let setup = Setup {
        state,
        vs: &vs_layout,
        fs: &fs_layout,
        outputs: &outputs,
        planes: Planes::new(&state.clip_planes),
        clip_rect,
        vp: [
            vw / 2.0,
            lim(vp.x) + vw / 2.0,
            vh / 2.0,
            lim(vp.y) + vh / 2.0,
            (f - n) / 2.0,
            (n + f) / 2.0,
        ],
        probe,
        corners: &[],
    };
    // Shared vertices (indexed meshes): each vertex's outcode and window
    // position once, on the workers, instead of once per primitive using
    // it (the same values either way).
    let vertices = outputs.len() / vs_layout.outputs.max(1);
    let mut corners = std::mem::take(&mut workers.spare().corners);
    if probe.is_none() && vertex_of.len() >= CORNER_REUSE * vertices {
        // Written in place, chunk by chunk, into the table kept from the
        // last draw (a new table, or one collected from the chunks, cost a
        // copy and page faults on the calling thread).
        let blank = Corner {
            outcode: 0,
            win: None,
        };
        corners.resize(vertices, blank);
        let chunk = 4096;
        let parts: Vec<Mutex<&mut [Corner]>> = corners.chunks_mut(chunk).map(Mutex::new).collect();
        workers.map(parts.len(), 1, |c, _| {
            let Some(part) = parts.get(c) else { return };
            let mut part = part.lock().unwrap_or_else(|e| e.into_inner());
            for (k, slot) in part.iter_mut().enumerate() {
                *slot = setup.compute_corner(c * chunk + k);
            }
        });
    } else {
        corners.clear();
    }
    let setup = Setup {
        corners: &corners,
        ..setup
    };
    // Primitive set-up in chunks of primitives on the workers, the
    // chunks' primitives concatenated in order (one chunk, in order, for
    // the debugger's probe, which notes primitives as they come).
    let setup = &setup;
    let grid = TileGrid::new(fb);
    let count = vertex_of.len();
    let n_prims = primitive_count(mode, count);
    let chunk = if probe.is_some() {
        n_prims.max(1)
    } else {
        SETUP_CHUNK
    };
    let chunks = n_prims.div_ceil(chunk);
    let isa = crate::simd::detect();
    let parts = workers.map(chunks, 1, |c, _| {
        let first = c * chunk;
        let n = chunk.min(n_prims.saturating_sub(first));
        let (mut prims, mut planes) = workers.spare().chunks.pop().unwrap_or_default();
        prims.reserve(n);
        planes.reserve(n * fs_layout.links.len());
        let mut out = Out {
            prims,
            planes,
            source: 0,
            chunk: c as u32,
        };
        let v = |i: usize| vertex_of.get(i).map_or(0, |&v| v as usize);
        for k in c * chunk..((c + 1) * chunk).min(n_prims) {
            out.source = k as u32;
            if probe.is_none() {
                if let Some((vs, n, prov)) = small_polygon(mode, k) {
                    let vs = vs.map(v);
                    match isa {
                        #[cfg(target_arch = "x86_64")]
                        // SAFETY: `isa` is one of these only when the CPU
                        // has their features (`simd::detect`).
                        Isa::Avx2 | Isa::Avx512 => unsafe {
                            setup.polygon_avx2(&mut out, &vs[..n], v(prov))
                        },
                        _ => setup.polygon(&mut out, &vs[..n], v(prov)),
                    }
                    continue;
                }
            }
            let p = primitive(mode, count, k);
            if let Some(probe) = probe {
                probe.note_primitive(out.source, &p);
            }
            match p {
                Assembled::Point(i) => {
                    let cv = setup.clip_vertex(v(i));
                    setup.point(&mut out, &cv, false, 0.0, setup.data(v(i)));
                }
                Assembled::Line(a, b) => {
                    let (ca, cb) = (setup.clip_vertex(v(a)), setup.clip_vertex(v(b)));
                    setup.line(&mut out, &ca, &cb, false, 0.0, setup.data(v(b)));
                }
                Assembled::Polygon(vs, prov) => {
                    let vs: Vec<usize> = vs.into_iter().map(v).collect();
                    setup.polygon(&mut out, &vs, v(prov));
                }
            }
        }
        // Binned here, on the workers: the chunks' bins read in chunk
        // order list each tile's primitives in draw order.
        let bins = ChunkBins::new(&out.prims, &grid);
        ((out.prims, out.planes), bins)
    });
    let (parts, chunk_bins): (Vec<_>, Vec<_>) = parts.into_iter().unzip();
    // The chunks' primitives in order and their varyings, referenced
    // where they are (not moved).
    let attrs: Vec<&[Plane]> = parts.iter().map(|p| &p.1[..]).collect();
    // Sized first: collected from `flat_map` the vector grew by doubling
    // (copies and fresh pages, ~10 ms of a million-triangle draw).
    let mut prims: Vec<&Prim> = Vec::with_capacity(parts.iter().map(|p| p.0.len()).sum());
    prims.extend(parts.iter().flat_map(|p| p.0.iter()));
    let bins = Bins::new(chunk_bins, &parts, grid);

    // The probe replays every fragment: never deferred.
    let deferred = if probe.is_none() && crate::fragment_ops::last_writer_wins(fb, state) {
        fs.depth_only()
    } else {
        None
    };
    let stage = FragmentStage::new(
        fs,
        fs_uniforms,
        textures,
        &fs_layout,
        state,
        attrs,
        deferred,
        probe,
    );
    if let Some(p) = probe {
        p.set_vertices(&vs_layout, &outputs, &vertex_of);
    }
    let result = shade_tiles(workers, fb, &stage, &prims, &bins);
    // The draw's big buffers, for the next draws.
    drop(stage);
    drop(prims);
    let mut spare = workers.spare();
    spare.keep(parts, outputs);
    spare.keep_corners(corners);
    spare.keep_tables([vertex_of]);
    result
}

/// What one tile task produced.
enum TileResult {
    /// The tile's pixels after its primitives, and the error that stopped
    /// it, if one did (the pixels are then those written before it).
    Ran(Framebuffer, Option<ExecError>),
    /// Not run or abandoned: an earlier tile failed.
    Skipped,
}

/// The fragment stage over 64×64 tiles. Each tile is a task that owns a
/// copy of its pixels and runs the primitives overlapping it in draw
/// order; the copies are written back in tile order. When tiles fail, the
/// result is that of running the tiles in order and stopping at the first
/// failure: earlier tiles complete, the failing tile keeps what it wrote
/// before the error, later tiles are left untouched, and that error is
/// returned.
fn shade_tiles(
    workers: &Workers,
    fb: &mut Framebuffer,
    stage: &FragmentStage,
    prims: &[&Prim],
    bins: &Bins,
) -> Result<(), DrawError> {
    let grid = bins.grid;
    let occupied = bins.occupied();
    let rect = |t: usize| grid.rect(t);
    let source: &Framebuffer = fb;
    // The depth and stencil buffers only when the draw tests them (or
    // the debugger's probe reports what a fragment leaves in them).
    let all = stage.probe.is_some();
    let tests = (
        all || stage.state.depth_test.is_some(),
        all || stage.state.stencil.is_some(),
    );
    let results = workers.map(occupied.len(), 1, |i, cancel| {
        if cancel.skip(i) {
            return TileResult::Skipped;
        }
        let Some(&t) = occupied.get(i) else {
            return TileResult::Skipped;
        };
        let r = rect(t);
        let area = (r.0 as u32, r.1 as u32, r.2 as u32, r.3 as u32);
        let copy = || source.copy_tile(area, tests.0, tests.1);
        let mut local = copy();
        let bin = &bins.tile(t)[..];
        let mut scratch = stage.scratch();
        if let Some(depth) = &stage.deferred {
            match stage.shade_deferred(depth.as_ref(), &mut local, prims, bin, r, &mut scratch) {
                Ok(()) => return TileResult::Ran(local, None),
                // Redraw the tile the straightforward way: it stops at the
                // same fragment with the same error.
                Err(_) => local = copy(),
            }
        } else if stage.batches_primitives(source) {
            match stage.shade_batched(&mut local, prims, bin, r, &mut scratch) {
                Ok(()) => return TileResult::Ran(local, None),
                // The same: one primitive at a time gives the error and
                // the partial tile of the contract.
                Err(_) => local = copy(),
            }
        }
        for &p in bin {
            if cancel.skip(i) {
                return TileResult::Skipped;
            }
            let Some(&prim) = prims.get(p as usize) else {
                continue;
            };
            if let Err(e) = stage.shade(&mut local, prim, r, &mut scratch) {
                cancel.fail(i);
                return TileResult::Ran(local, Some(e));
            }
        }
        TileResult::Ran(local, None)
    });
    // Written back up to the first failed tile (later ones are dropped),
    // each band of tile rows by a worker: the bands are disjoint.
    let failed = results
        .iter()
        .position(|r| matches!(r, TileResult::Ran(_, Some(_))));
    let kept = failed.map_or(results.len(), |i| i + 1);
    let mut passed = 0u64;
    for r in &results[..kept] {
        if let TileResult::Ran(local, _) = r {
            passed = passed.wrapping_add(local.samples_passed);
        }
    }
    fb.samples_passed = fb.samples_passed.wrapping_add(passed);
    let bands: Vec<Mutex<Band>> = fb.bands(TILE as u32).into_iter().map(Mutex::new).collect();
    let row_of = |i: usize| occupied.get(i).map_or(usize::MAX, |&t| grid.row(t));
    workers.map(bands.len(), 1, |b, _| {
        let Some(band) = bands.get(b) else { return };
        let mut band = band.lock().unwrap_or_else(|e| e.into_inner());
        // The band's tiles: a run of `occupied` (sorted by tile).
        let first = occupied.partition_point(|&t| grid.row(t) < b);
        for i in first..kept {
            if row_of(i) != b {
                break;
            }
            if let (Some(TileResult::Ran(local, _)), Some(&t)) = (results.get(i), occupied.get(i)) {
                let r = rect(t);
                band.store_tile(r.0 as u32, r.1 as u32, local);
            }
        }
    });
    match failed.and_then(|i| results.into_iter().nth(i)) {
        Some(TileResult::Ran(_, Some(e))) => Err(e.into()),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn collect(mode: Mode, n: usize) -> Vec<Assembled> {
        let mut v = Vec::new();
        assemble(mode, n, |p| v.push(p));
        v
    }

    #[test]
    fn assembly_and_provoking_vertices() {
        use Assembled::*;
        assert_eq!(collect(Mode::Lines, 5), vec![Line(0, 1), Line(2, 3)]);
        assert_eq!(
            collect(Mode::LineLoop, 3),
            vec![Line(0, 1), Line(1, 2), Line(2, 0)]
        );
        assert_eq!(
            collect(Mode::TriangleStrip, 5),
            vec![
                Polygon(vec![0, 1, 2], 2),
                Polygon(vec![2, 1, 3], 3),
                Polygon(vec![2, 3, 4], 4)
            ]
        );
        assert_eq!(
            collect(Mode::TriangleFan, 4),
            vec![Polygon(vec![0, 1, 2], 2), Polygon(vec![0, 2, 3], 3)]
        );
        assert_eq!(collect(Mode::Quads, 7), vec![Polygon(vec![0, 1, 2, 3], 3)]);
        assert_eq!(
            collect(Mode::QuadStrip, 6),
            vec![Polygon(vec![0, 1, 3, 2], 3), Polygon(vec![2, 3, 5, 4], 5)]
        );
        assert_eq!(
            collect(Mode::Polygon, 5),
            vec![Polygon(vec![0, 1, 2, 3, 4], 0)]
        );
        assert_eq!(collect(Mode::Polygon, 2), vec![]);
        assert_eq!(collect(Mode::Triangles, 2), vec![]);
    }
}
