//! The draw queue: draws whose fragment stage waits, so that one pass
//! over the tiles shades several draws.
//!
//! A draw pushed ([`DrawQueue::push`]) runs its vertex (and geometry)
//! stage, set-up and binning at once, as [`crate::draw_stages`] does, and
//! keeps what its fragment stage needs: the shader, its uniform words,
//! the textures and the pipeline state as they were at the push. A flush
//! ([`DrawQueue::flush`]) shades every tile through the queued draws in
//! the order they were pushed, each tile loaded and written back once:
//! the pixels of a frame of many full-screen draws stay in the cache
//! instead of crossing memory once per draw. Per pixel the draws run in
//! the same order as one after another, so the bytes are the same.
//!
//! Contract: only draws whose fragment stage always completes
//! ([`ShaderStage::always_completes`]) wait; a push of any other draw
//! flushes the queue and draws at once, so a failing draw stops at the
//! fragment the draw-by-draw contract names. Until the flush the
//! framebuffer's pixels lag behind the draws pushed; whoever owns it
//! flushes before anything reads or replaces them, and draws into that
//! framebuffer only (a flush into one of another size is refused).

use std::sync::Arc;

use crate::assembly::Mode;
use crate::binning::TileGrid;
use crate::draw::{shade_tiles, DrawTiles, SetUp};
use crate::ex::Textures;
use crate::framebuffer::Framebuffer;
use crate::shade::FragmentStage;
use crate::state::PipelineState;
use crate::texture_units::TextureUnits;
use crate::vertex::VertexFetch;
use crate::workers::Workers;
use crate::{DrawError, ShaderStage};

/// Most draws waiting at once: past it a push flushes.
const MAX_DRAWS: usize = 256;

/// Most primitives waiting at once (their planes are kept until the
/// flush): past it a push flushes.
const MAX_PRIMITIVES: usize = 1 << 20;

/// A draw's fragment stage as the queue keeps it: owned, as it runs after
/// the caller's state has moved on.
pub struct QueuedFragments {
    pub shader: Arc<dyn ShaderStage + Send + Sync>,
    pub uniforms: Vec<u32>,
    pub textures: TextureUnits,
}

/// One draw waiting for its fragment stage.
struct Waiting {
    fragments: QueuedFragments,
    state: PipelineState,
    set_up: SetUp,
}

/// Draws set up and binned whose fragment stages have not run (see the
/// module documentation).
#[derive(Default)]
pub struct DrawQueue {
    draws: Vec<Waiting>,
    /// The tiles of the framebuffer the waiting draws were set up for.
    grid: Option<TileGrid>,
    primitives: usize,
}

impl DrawQueue {
    /// Whether no draw waits.
    pub fn is_empty(&self) -> bool {
        self.draws.is_empty()
    }

    /// How many draws wait.
    pub fn len(&self) -> usize {
        self.draws.len()
    }

    /// Draws `indices` (vertex numbers passed to `fetch`) as `mode`
    /// primitives into `fb` through the vertex stage `vs` (with its
    /// uniform words), the geometry stage `gs` when given, and `fs`, as
    /// [`crate::draw_stages`] does, except that `fs` runs at the next
    /// [`DrawQueue::flush`] when it always completes. Flushes first when
    /// `fb` is not the framebuffer of the waiting draws, and after the
    /// push when the queue is full. An error of the vertex or geometry
    /// stage leaves the queue as it was.
    #[allow(clippy::too_many_arguments)]
    pub fn push(
        &mut self,
        workers: &Workers,
        fb: &mut Framebuffer,
        state: &PipelineState,
        vs: (&dyn ShaderStage, &[u32]),
        gs: Option<(&dyn ShaderStage, &[u32])>,
        fs: QueuedFragments,
        (mode, indices): (Mode, &[u32]),
        fetch: &dyn VertexFetch,
    ) -> Result<(), DrawError> {
        let grid = TileGrid::new(fb);
        if self.grid.is_some_and(|g| g != grid) {
            self.flush(workers, fb)?;
        }
        // A depth-only slice takes ops away from its shader: it completes
        // whenever the shader does.
        if !fs.shader.always_completes() {
            self.flush(workers, fb)?;
            return crate::draw_stages(
                workers,
                fb,
                state,
                vs,
                gs,
                (&*fs.shader, &fs.uniforms),
                mode,
                indices,
                fetch,
                &fs.textures,
            );
        }
        let vertices = crate::geometry::vertex_and_geometry_stages(
            workers,
            vs,
            gs,
            &fs.textures,
            (indices, fetch),
            (mode, state),
            None,
        )?;
        let last = gs.map_or(vs.0, |(g, _)| g);
        let set_up = SetUp::new(
            workers,
            fb,
            state,
            last.interface(),
            &*fs.shader,
            &vertices,
            None,
        );
        workers.spare().keep_vertices(vertices);
        let primitives = set_up.primitives();
        if primitives == 0 {
            set_up.keep(workers);
            return Ok(());
        }
        self.grid = Some(grid);
        self.primitives += primitives;
        self.draws.push(Waiting {
            fragments: fs,
            state: state.clone(),
            set_up,
        });
        if self.draws.len() >= MAX_DRAWS || self.primitives >= MAX_PRIMITIVES {
            self.flush(workers, fb)?;
        }
        Ok(())
    }

    /// Runs the waiting draws' fragment stages into `fb`, the framebuffer
    /// they were pushed with, and empties the queue. The error is the
    /// first in tile order; with several draws waiting it does not say
    /// which draw failed (none can, by the contract: see the module
    /// documentation). A framebuffer of another size than the draws were
    /// set up for is refused, and the draws are dropped.
    pub fn flush(&mut self, workers: &Workers, fb: &mut Framebuffer) -> Result<(), DrawError> {
        let draws = std::mem::take(&mut self.draws);
        let grid = self.grid.take();
        self.primitives = 0;
        if draws.is_empty() {
            return Ok(());
        }
        let result = if grid == Some(TileGrid::new(fb)) {
            let stages: Vec<FragmentStage> = draws
                .iter()
                .map(|w| {
                    let f = &w.fragments;
                    let fs = (&*f.shader as &dyn ShaderStage, &f.uniforms[..]);
                    let textures: &(dyn Textures + Sync) = &f.textures;
                    w.set_up.fragment_stage(fb, &w.state, fs, textures, None)
                })
                .collect();
            let prims: Vec<_> = draws.iter().map(|w| w.set_up.prims()).collect();
            let tiles: Vec<DrawTiles> = (stages.iter().zip(&prims).zip(&draws))
                .map(|((stage, prims), w)| DrawTiles {
                    stage,
                    prims,
                    bins: &w.set_up.bins,
                })
                .collect();
            shade_tiles(workers, fb, &tiles)
        } else {
            Err(DrawError::QueueTarget)
        };
        for w in draws {
            w.set_up.keep(workers);
        }
        result
    }
}
