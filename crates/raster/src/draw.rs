//! The draw driver: runs a draw's stages in order on the [`Workers`] and
//! keeps their big buffers for the next draws.
//!
//! Takes a framebuffer, the pipeline state, both shader stages, the mode,
//! the index list and the vertex source ([`draw_stages`], and
//! [`draw_probed`] for the debugger's replays); runs the vertex stage
//! (`crate::vertex`), the geometry stage when there is one
//! (`crate::geometry`), then set-up (`crate::setup`, assembling with
//! `crate::assembly`) in chunks of [`SETUP_CHUNK`] primitives, each chunk
//! binned (`crate::binning`) where it was set up, then the fragment stage
//! (`crate::shade`) tile by tile ([`shade_tiles`]), and gives the
//! framebuffer written, or the first error in the order of the contract
//! (crate docs, "Threads"). Set-up and binning ([`SetUp`]) and the pass
//! over the tiles also serve the draw queue (`crate::queue`), whose pass
//! runs several draws' primitives per tile.

use std::sync::Mutex;

use crate::assembly::{primitive_count, Mode};
use crate::binning::{Bins, ChunkBins, TileGrid, TILE};
use crate::ex::{ExecError, Textures};
use crate::framebuffer::{Band, Framebuffer, TileView};
use crate::interpolate::Plane;
use crate::linkage::{FsLayout, VsLayout};
use crate::prim::Prim;
use crate::probe::Probe;
use crate::rasterize::PixelRect;
use crate::setup::{Corner, Out, Setup, CORNER_REUSE};
use crate::shade::FragmentStage;
use crate::shaded::Vertices;
use crate::state::PipelineState;
use crate::vertex::VertexFetch;
use crate::workers::{Cancel, Workers};
use crate::{DrawError, ShaderStage};

/// Primitives one set-up task takes.
pub(crate) const SETUP_CHUNK: usize = 2048;

/// [`crate::draw_on`] over any [`ShaderStage`]s: the vertex stage and the
/// fragment stage (each with its uniform words), with a geometry stage
/// between them when `gs` is given (a geometry kernel and its uniform
/// words; see `crate::geometry`).
#[allow(clippy::too_many_arguments)]
pub fn draw_stages(
    workers: &Workers,
    fb: &mut Framebuffer,
    state: &PipelineState,
    vs: (&dyn ShaderStage, &[u32]),
    gs: Option<(&dyn ShaderStage, &[u32])>,
    fs: (&dyn ShaderStage, &[u32]),
    mode: Mode,
    indices: &[u32],
    fetch: &dyn VertexFetch,
    textures: &(dyn Textures + Sync),
) -> Result<(), DrawError> {
    draw_probed(
        workers, fb, state, vs, gs, fs, mode, indices, fetch, textures, None,
    )
}

/// [`draw_stages`], reporting to
/// `probe` what happens at its pixel.
#[allow(clippy::too_many_arguments)]
pub(crate) fn draw_probed(
    workers: &Workers,
    fb: &mut Framebuffer,
    state: &PipelineState,
    (vs, vs_uniforms): (&dyn ShaderStage, &[u32]),
    gs: Option<(&dyn ShaderStage, &[u32])>,
    (fs, fs_uniforms): (&dyn ShaderStage, &[u32]),
    mode: Mode,
    indices: &[u32],
    fetch: &dyn VertexFetch,
    textures: &(dyn Textures + Sync),
    probe: Option<&Probe>,
) -> Result<(), DrawError> {
    let vertices = crate::geometry::vertex_and_geometry_stages(
        workers,
        (vs, vs_uniforms),
        gs,
        textures,
        (indices, fetch),
        (mode, state),
        probe,
    )?;
    // The last stage before set-up: its outputs are the vertices drawn.
    let last = gs.map_or(vs, |(g, _)| g);
    draw_vertices(
        workers,
        fb,
        state,
        last.interface(),
        (fs, fs_uniforms),
        vertices,
        textures,
        probe,
    )
}

/// Draws vertices already shaded by the last stage before rasterization
/// (laid out as `last`'s outputs say, `VsLayout::new(last).outputs`
/// values each) as `vertices.mode` primitives: a geometry stage's
/// emitted primitives drawn one layer at a time, and the tail of every
/// draw.
pub fn draw_emitted(
    workers: &Workers,
    fb: &mut Framebuffer,
    state: &PipelineState,
    last: &crate::ex::Interface,
    fs: (&dyn ShaderStage, &[u32]),
    (mode, vertex_of, outputs): (Mode, Vec<u32>, Vec<f32>),
    textures: &(dyn Textures + Sync),
) -> Result<(), DrawError> {
    let vertices = Vertices {
        mode,
        vertex_of,
        outputs,
    };
    draw_vertices(workers, fb, state, last, fs, vertices, textures, None)
}

/// Set-up, binning and the fragment stage of shaded vertices.
#[allow(clippy::too_many_arguments)]
fn draw_vertices(
    workers: &Workers,
    fb: &mut Framebuffer,
    state: &PipelineState,
    last: &crate::ex::Interface,
    (fs, fs_uniforms): (&dyn ShaderStage, &[u32]),
    vertices: Vertices,
    textures: &(dyn Textures + Sync),
    probe: Option<&Probe>,
) -> Result<(), DrawError> {
    let set_up = SetUp::new(workers, fb, state, last, fs, &vertices, probe);
    let stage = set_up.fragment_stage(fb, state, (fs, fs_uniforms), textures, probe);
    if let Some(p) = probe {
        p.set_vertices(&set_up.vs_layout, &vertices.outputs, &vertices.vertex_of);
    }
    let prims = set_up.prims();
    let result = shade_tiles(
        workers,
        fb,
        &[DrawTiles {
            stage: &stage,
            prims: &prims,
            bins: &set_up.bins,
        }],
    );
    // The draw's big buffers, for the next draws.
    drop(stage);
    drop(prims);
    set_up.keep(workers);
    workers.spare().keep_vertices(vertices);
    result
}

/// A draw set up and binned: its primitives, their varyings' planes and
/// the tiles they overlap, what its fragment stage runs on.
pub(crate) struct SetUp {
    vs_layout: VsLayout,
    fs_layout: FsLayout,
    /// Each set-up chunk's primitives and planes, in draw order.
    parts: Vec<(Vec<Prim>, Vec<Plane>)>,
    pub bins: Bins,
}

impl SetUp {
    /// Sets up and bins `vertices`, laid out as `last`'s outputs say, for
    /// a fragment stage of interface `fs` drawing into `fb` (whose size
    /// and depth format count, not its pixels).
    pub fn new(
        workers: &Workers,
        fb: &Framebuffer,
        state: &PipelineState,
        last: &crate::ex::Interface,
        fs: &dyn ShaderStage,
        Vertices {
            mode,
            vertex_of,
            outputs,
        }: &Vertices,
        probe: Option<&Probe>,
    ) -> SetUp {
        let (mode, vertex_of, outputs) = (*mode, &vertex_of[..], &outputs[..]);
        let vs_layout = VsLayout::new(last);
        let fs_layout = FsLayout::new(last, fs.interface(), state.two_sided_color)
            .with_reads(|c| fs.reads_input(c));
        let setup = Setup::new(state, (&vs_layout, &fs_layout), outputs, fb, probe);
        // Shared vertices (indexed meshes): each vertex's outcode and window
        // position once, on the workers, instead of once per primitive using
        // it (the same values either way).
        let vertices = outputs.len() / vs_layout.outputs.max(1);
        let mut corners = std::mem::take(&mut workers.spare().corners);
        if probe.is_none() && vertex_of.len() >= CORNER_REUSE * vertices {
            // Written in place, chunk by chunk, into the table kept from the
            // last draw (a new table, or one collected from the chunks, cost a
            // copy and page faults on the calling thread).
            corners.resize(vertices, Corner::BLANK);
            let chunk = 4096;
            let parts: Vec<Mutex<&mut [Corner]>> =
                corners.chunks_mut(chunk).map(Mutex::new).collect();
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
        let setup = setup.with_corners(&corners);
        // Primitive set-up in chunks of primitives on the workers, the
        // chunks' primitives concatenated in order (one chunk, in order, for
        // the debugger's probe, which notes primitives as they come).
        let setup = &setup;
        let grid = TileGrid::new(fb);
        let n_prims = primitive_count(mode, vertex_of.len());
        let chunk = if probe.is_some() {
            n_prims.max(1)
        } else {
            SETUP_CHUNK
        };
        let chunks = n_prims.div_ceil(chunk);
        let level = crate::simd::detect();
        let links = fs_layout.links.len();
        let parts = workers.map(chunks, 1, |c, _| {
            let first = c * chunk;
            let n = chunk.min(n_prims.saturating_sub(first));
            let (mut prims, mut planes) = workers.spare().chunks.pop().unwrap_or_default();
            prims.reserve(n);
            planes.reserve(n * links);
            let mut out = Out {
                prims,
                planes,
                source: 0,
                chunk: c as u32,
            };
            let range = c * chunk..((c + 1) * chunk).min(n_prims);
            setup.chunk(&mut out, mode, vertex_of, range, level);
            // Binned here, on the workers: the chunks' bins read in chunk
            // order list each tile's primitives in draw order.
            let bins = ChunkBins::new(&out.prims, &grid);
            ((out.prims, out.planes), bins)
        });
        let (parts, chunk_bins): (Vec<_>, Vec<_>) = parts.into_iter().unzip();
        let bins = Bins::new(chunk_bins, &parts, grid);
        workers.spare().keep_corners(corners);
        SetUp {
            vs_layout,
            fs_layout,
            parts,
            bins,
        }
    }

    /// The primitives set up, in draw order, referenced where they are.
    pub fn prims(&self) -> Vec<&Prim> {
        // Sized first: collected from `flat_map` the vector grew by
        // doubling (copies and fresh pages on this thread).
        let mut prims = Vec::with_capacity(self.primitives());
        prims.extend(self.parts.iter().flat_map(|p| p.0.iter()));
        prims
    }

    /// How many primitives were set up (those culled or clipped away
    /// are not).
    pub fn primitives(&self) -> usize {
        self.parts.iter().map(|p| p.0.len()).sum()
    }

    /// The fragment stage of the draw: `fs` with its uniform words, on
    /// `textures`, into `fb` (its formats count, not its pixels).
    pub fn fragment_stage<'a>(
        &'a self,
        fb: &Framebuffer,
        state: &'a PipelineState,
        (fs, fs_uniforms): (&'a dyn ShaderStage, &'a [u32]),
        textures: &'a (dyn Textures + Sync),
        probe: Option<&'a Probe>,
    ) -> FragmentStage<'a> {
        // The chunks' varyings, referenced where they are (not moved).
        let attrs: Vec<&[Plane]> = self.parts.iter().map(|p| &p.1[..]).collect();
        // The probe replays every fragment: never deferred.
        let deferred = if probe.is_none() && crate::fragment_ops::last_writer_wins(fb, state) {
            fs.depth_only()
        } else {
            None
        };
        let mut stage = FragmentStage::new(
            fs,
            fs_uniforms,
            textures,
            &self.fs_layout,
            state,
            attrs,
            deferred,
            probe,
        );
        stage.depth_format = fb.depth_format;
        stage.cache_bounds(self.primitives());
        stage
    }

    /// Gives the draw's buffers to `workers` for the next draws.
    pub fn keep(self, workers: &Workers) {
        workers.spare().keep_chunks(self.parts);
    }
}

/// One draw's share of [`shade_tiles`]: its fragment stage, its
/// primitives and the tiles they overlap.
pub(crate) struct DrawTiles<'s, 'a> {
    pub stage: &'s FragmentStage<'a>,
    pub prims: &'s [&'a Prim],
    pub bins: &'s Bins,
}

/// What one tile task produced.
enum TileResult {
    /// The tile's pixels after its primitives, and the error that stopped
    /// it, if one did (the pixels are then those written before it).
    Ran(Framebuffer, Option<ExecError>),
    /// Not run or abandoned: an earlier tile failed.
    Skipped,
}

/// The fragment stage of `draws` over 64×64 tiles. Each tile is a task
/// that owns a copy of its pixels and runs, draw after draw, the
/// primitives overlapping it in draw order. When tiles fail, the result is
/// that of running the tiles in order and stopping at the first failure:
/// earlier tiles complete, the failing tile keeps what it wrote before the
/// error, later tiles are left untouched, and that error is returned. So
/// the copies are written back in tile order once every tile has run,
/// unless no tile can fail ([`ShaderStage::always_completes`]): each task
/// then writes its tile back as soon as it is done, while its pixels are
/// still in the cache. Several draws share a run only when none can fail
/// (the draw queue's contract): a draw that failed part way through a
/// tile others ran before could not be redone from the tile's copy.
pub(crate) fn shade_tiles(
    workers: &Workers,
    fb: &mut Framebuffer,
    draws: &[DrawTiles],
) -> Result<(), DrawError> {
    let Some(first) = draws.first() else {
        return Ok(());
    };
    let grid = first.bins.grid;
    let occupied = occupied_tiles(draws);
    let rect = |t: usize| grid.rect(t);
    // The depth and stencil buffers only when a draw tests them (or the
    // debugger's probe reports what a fragment leaves in them).
    let all = draws.iter().any(|d| d.stage.probe.is_some());
    let tests = (
        all || draws.iter().any(|d| d.stage.state.depth_test.is_some()),
        all || draws.iter().any(|d| d.stage.state.stencil.is_some()),
    );
    let batches: Vec<bool> = draws
        .iter()
        .map(|d| d.stage.batches_primitives(fb))
        .collect();
    let completes = draws.iter().all(|d| d.stage.always_completes());
    if completes && !all {
        let views: Vec<Mutex<Option<TileView>>> = fb
            .tile_views(TILE as u32, &occupied, tests.0, tests.1)
            .into_iter()
            .map(|v| Mutex::new(Some(v)))
            .collect();
        let results = workers.map(occupied.len(), 1, |i, cancel| {
            let (Some(view), Some(&t)) = (views.get(i), occupied.get(i)) else {
                return Ok(0);
            };
            let taken = view.lock().unwrap_or_else(|e| e.into_inner()).take();
            let Some(mut view) = taken else {
                return Ok(0);
            };
            let mut local = view.load();
            let ran = shade_draws(draws, &batches, &mut local, || view.load(), t, cancel, i);
            // Written back even after an error (which `always_completes`
            // rules out): the tile then holds what ran before it.
            view.store(&local);
            ran.map(|()| local.samples_passed)
        });
        // The first error in tile order is a failure, not a cancelled
        // tile (only tiles after a failed one are cancelled).
        let mut passed = 0u64;
        let mut error = None;
        for r in results {
            match r {
                Ok(n) => passed = passed.wrapping_add(n),
                Err(TileError::Exec(e)) => {
                    error.get_or_insert(e);
                }
                Err(TileError::Cancelled) => {}
            }
        }
        fb.samples_passed = fb.samples_passed.wrapping_add(passed);
        return error.map_or(Ok(()), |e| Err(e.into()));
    }
    let source: &Framebuffer = fb;
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
        match shade_draws(draws, &batches, &mut local, copy, t, cancel, i) {
            Ok(()) => TileResult::Ran(local, None),
            Err(TileError::Cancelled) => TileResult::Skipped,
            Err(TileError::Exec(e)) => TileResult::Ran(local, Some(e)),
        }
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

/// The tiles some primitive of `draws` overlaps, in order.
fn occupied_tiles(draws: &[DrawTiles]) -> Vec<usize> {
    let tiles = draws.first().map_or(0, |d| d.bins.grid.count());
    (0..tiles)
        .filter(|&t| draws.iter().any(|d| d.bins.occupies(t)))
        .collect()
}

/// Tile task `i`: every draw's primitives overlapping tile `t`, draw
/// after draw, on `local`, the tile's copy ([`shade_tile`]). Only the
/// first draw to touch the tile may be redone from a fresh copy by
/// `reload`; a later draw's error ends the tile where it stopped.
fn shade_draws(
    draws: &[DrawTiles],
    batches: &[bool],
    local: &mut Framebuffer,
    reload: impl Fn() -> Framebuffer,
    t: usize,
    cancel: &Cancel,
    i: usize,
) -> Result<(), TileError> {
    let mut touched = false;
    for (d, &batched) in draws.iter().zip(batches) {
        let bin = d.bins.tile(t);
        if bin.is_empty() {
            continue;
        }
        let r = d.bins.grid.rect(t);
        let fresh = (!touched).then_some(&reload as &dyn Fn() -> Framebuffer);
        shade_tile(d.stage, local, fresh, d.prims, &bin, r, batched, cancel, i)?;
        touched = true;
    }
    Ok(())
}

/// Why [`shade_tile`] stopped early.
enum TileError {
    /// A shader run failed (the tile holds what ran before it).
    Exec(ExecError),
    /// An earlier tile failed: this one's result will be dropped.
    Cancelled,
}

impl From<ExecError> for TileError {
    fn from(e: ExecError) -> TileError {
        TileError::Exec(e)
    }
}

/// Tile task `i`: the primitives `bin` (indices into `prims`) on `local`,
/// the copy of tile `r`, by the deferred depth pass or in batches when
/// the stage allows, else (or to redo a tile they stopped on, from a
/// fresh copy by `reload`) one primitive at a time, which stops at the
/// fragment and with the error of the contract. Without `reload`, an
/// error of the deferred or batched pass ends the tile as it is.
#[allow(clippy::too_many_arguments)]
fn shade_tile(
    stage: &FragmentStage,
    local: &mut Framebuffer,
    reload: Option<&dyn Fn() -> Framebuffer>,
    prims: &[&Prim],
    bin: &[u32],
    r: PixelRect,
    batches: bool,
    cancel: &Cancel,
    i: usize,
) -> Result<(), TileError> {
    let mut scratch = stage.scratch();
    let quick = if let Some(depth) = &stage.deferred {
        Some(stage.shade_deferred(depth.as_ref(), local, prims, bin, r, &mut scratch))
    } else if batches {
        Some(stage.shade_batched(local, prims, bin, r, &mut scratch))
    } else {
        None
    };
    match (quick, reload) {
        (None, _) => {}
        (Some(Ok(())), _) => return Ok(()),
        (Some(Err(_)), Some(reload)) => *local = reload(),
        (Some(Err(e)), None) => {
            cancel.fail(i);
            return Err(e.into());
        }
    }
    for &p in bin {
        if cancel.skip(i) {
            return Err(TileError::Cancelled);
        }
        let Some(&prim) = prims.get(p as usize) else {
            continue;
        };
        if let Err(e) = stage.shade(local, prim, r, &mut scratch) {
            cancel.fail(i);
            return Err(e.into());
        }
    }
    Ok(())
}
