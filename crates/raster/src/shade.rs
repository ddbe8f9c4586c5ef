//! The fragment stage: covered quads of a set-up primitive are shaded four
//! at a time (one [`Batch`] of 16 lanes), then sent through the
//! per-fragment operations in order.
//!
//! Takes a tile's copy of the framebuffer, the draw's set-up primitives
//! and the tile's bin (their indices, in draw order); gives the tile after
//! them, or the shader's error. [`FragmentStage`] holds what a draw's
//! tiles share; this file has its set-up, the straightforward loop (one
//! primitive at a time, [`FragmentStage::shade`]: coverage from
//! `crate::rasterize`, inputs from `crate::interpolate`'s planes, the
//! shader, then `crate::fragment_ops`) and what the other loops share
//! besides filling a batch's inputs (`fill`): early depth rejection and
//! the writes. The loops that give the same bytes faster are `batched`
//! (quads of several primitives per batch, strips) and `deferred`
//! (depth-only slice first, colours for visible fragments only).

use crate::ex::{Batch, ExecError, Textures, LANES};
use crate::fragment_ops::{self, Fragment, QuickOps, QuickTarget, FRAG_COLORS, SRC1};
use crate::framebuffer::{DepthFormat, Framebuffer, MAX_DRAW_BUFFERS};
use crate::interpolate::{Kind, Plane, QUAD_X, QUAD_Y, STRIP_X, STRIP_Y};
use crate::linkage::{new_batch, FsLayout};
use crate::prim::Prim;
use crate::probe::Probe;
use crate::rasterize::{PixelRect, Shape, STRIP};
use crate::simd::Level;
use crate::state::PipelineState;
use crate::ShaderStage;

mod batched;
mod deferred;
mod fill;

#[cfg(test)]
pub(crate) use deferred::BOUND_USES;
use fill::{quads_mask, FillKind, FillLink};

/// The final window z of four pixels from their interpolated z and the
/// primitive's polygon offset (offset, clamped), and its fixed point.
#[inline(always)]
fn window_depths(iz: &[f64; 4], offset: f64, format: DepthFormat) -> ([f64; 4], [u32; 4]) {
    let z = window_z(iz, offset);
    (z, format.to_fixed4(z))
}

/// The final window z of four pixels (see [`window_depths`]).
#[inline(always)]
fn window_z(iz: &[f64; 4], offset: f64) -> [f64; 4] {
    iz.map(|iz| clamp01(iz + offset))
}

fn clamp01(z: f64) -> f64 {
    if z > 0.0 {
        z.min(1.0)
    } else {
        0.0
    }
}

#[derive(Default)]
pub(crate) struct Quad {
    x: i64,
    y: i64,
    live: u8,
    /// Final window z per pixel (offset and clamped).
    z: [f64; 4],
    /// Those depths in the depth buffer's fixed point
    /// (`DepthFormat::to_fixed(z as f32)`).
    zf: [u32; 4],
}

impl Quad {
    /// Window coordinates of pixel `k` (0–3: lane `4q + k`'s pixel, see
    /// `exec`'s lane order) of the quad.
    fn pixel(&self, k: usize) -> (i64, i64) {
        (self.x + (k as i64 & 1), self.y + (k as i64 >> 1))
    }

    /// Makes this the quad at (qx, qy) of `prim` with coverage `mask`,
    /// its window z computed with `window_z` (else `z` and `zf` keep
    /// what they held: see [`FragmentStage::window_z`]).
    #[inline(always)]
    fn set(&mut self, prim: &Prim, (qx, qy, mask): (i64, i64, u8), window_z: Option<DepthFormat>) {
        (self.x, self.y, self.live) = (qx, qy, mask);
        if let Some(format) = window_z {
            (self.z, self.zf) = quad_depths(prim, (qx, qy), format);
        }
    }
}

/// The final window z of the quad at `(qx, qy)` of `prim` (its z plane,
/// the polygon offset, clamped) and its fixed point.
#[inline(always)]
fn quad_depths(prim: &Prim, (qx, qy): (i64, i64), format: DepthFormat) -> ([f64; 4], [u32; 4]) {
    let (x, y) = prim.offsets((qx, qy), &QUAD_X, &QUAD_Y);
    window_depths(&prim.planes.z_at(&x, &y), prim.z_offset, format)
}

/// A quad waiting for its batch: its primitive (and that primitive's
/// index), and for the colour pass of a deferred tile the pixels to write.
#[derive(Default)]
pub(crate) struct Entry<'p> {
    prim: Option<&'p Prim>,
    index: u32,
    quad: Quad,
    write: u8,
}

impl<'p> Entry<'p> {
    /// Makes this the quad at (qx, qy) of primitive `index`, `prim`
    /// ([`Quad::set`]).
    #[inline(always)]
    fn set(
        &mut self,
        prim: &'p Prim,
        index: u32,
        (qx, qy, mask): (i64, i64, u8),
        write: u8,
        window_z: Option<DepthFormat>,
    ) {
        self.prim = Some(prim);
        self.index = index;
        self.write = write;
        self.quad.set(prim, (qx, qy, mask), window_z);
    }
}

/// Per-tile buffers reused by every primitive and batch of the tile: the
/// batch, its quads (built in place, `n` of them so far) and a
/// primitive's covered quads.
pub(crate) struct Scratch<'p> {
    pub batch: Batch,
    slots: [Entry<'p>; LANES / 4],
    n: usize,
    quads: Vec<(i64, i64, u8)>,
    /// The quads of a packed batch ([`FragmentStage::fill_packed_with`]): up
    /// to one per lane.
    packed: Box<[Entry<'p>; LANES]>,
}

/// Where [`FragmentStage::shade_batched`] sends a tile's fragments: quick
/// operations with a qualifying colour write over the tile's buffers
/// (and that colour's fragment output), or the tile itself.
enum Sink<'f> {
    Quick(QuickTarget<'f>, usize),
    General(&'f mut Framebuffer, Option<QuickOps>),
}

/// How many primitives of a bin ahead [`FragmentStage::prefetch_ahead`]
/// fetches varyings and set-up.
const ATTRS_AHEAD: usize = 6;
const PRIM_AHEAD: usize = 16;
const SLOT_AHEAD: usize = 2 * PRIM_AHEAD;

/// No primitive (in the per-pixel winner table of a deferred tile).
const NO_PRIM: u32 = u32::MAX;

pub(crate) struct FragmentStage<'a> {
    pub shader: &'a dyn ShaderStage,
    pub uniforms: &'a [u32],
    pub textures: &'a (dyn Textures + Sync),
    pub layout: &'a FsLayout,
    pub state: &'a PipelineState,
    /// The planes of the fragment varyings of every primitive, per
    /// set-up chunk (see [`Prim::index`]).
    pub attrs: Vec<&'a [Plane]>,
    /// The varying components the shader reads (unread inputs stay zero;
    /// every link counts as read under the debugger's probe, which shows
    /// inputs), in link order.
    fills: Vec<FillLink>,
    /// Those the depth-only slice reads (its interface's inputs).
    depth_fills: Vec<FillLink>,
    /// The instruction set of the hot loops.
    level: Level,
    /// (draw buffer, output offset) of each colour the fragment carries.
    pub colors_out: Vec<(usize, usize)>,
    /// Depth/stencil-test before shading (no gl_FragDepth write).
    pub early: bool,
    /// The depth-only slice of `shader`, when colors may be computed for
    /// the visible fragments only (see [`FragmentStage::shade_deferred`]).
    pub deferred: Option<Box<dyn ShaderStage>>,
    /// The debugger's pixel probe (`None` in normal draws).
    pub probe: Option<&'a Probe>,
    /// `shader`'s and `deferred`'s uniform-only values, once per draw.
    prepared: Option<crate::ex::Prepared<'a>>,
    deferred_prepared: Option<crate::ex::Prepared<'a>>,
    /// The bound on `deferred`'s gl_FragDepth for the draw's uniforms
    /// ([`ShaderStage::depth_range`]), when it writes one.
    depth_range: Option<crate::ex::DepthRange>,
    /// Per primitive of the draw (when `depth_range` is some and the
    /// draw sized it, [`FragmentStage::cache_bounds`]): its bound over its
    /// whole bounds once a tile found it, shared by the tiles; 0: not yet
    /// found, 1: none, `2 + z`: the fixed-point depth `z`.
    bounds: Box<[std::sync::atomic::AtomicU64]>,
    /// The primitives whose bound the tiles tried to find, and those
    /// that had none (a draw whose program mostly gives none stops
    /// trying).
    bound_stats: [std::sync::atomic::AtomicU64; 2],
    /// Whether `shader`'s and `deferred`'s lanes are independent
    /// ([`ShaderStage::lanes_independent`]), asked once per draw.
    lanes_independent: bool,
    deferred_lanes_independent: bool,
    /// Whether anything reads a quad's window z (`Quad::z`, `Quad::zf`):
    /// the depth test of interpolated depths, gl_FragCoord.z or the
    /// debugger's probe. Without them the batched and deferred loops
    /// leave it out.
    window_z: bool,
    /// Whether a stage reads gl_FragCoord's z and w (the fills leave out
    /// what none reads).
    frag_zw: [bool; 2],
    /// The precision of the target's depth buffer (its fixed-point form of
    /// a window z).
    pub depth_format: DepthFormat,
    /// Whether [`FragmentStage::shade_batched`] may run rows of four
    /// whole quads of a triangle as strips ([`FragmentStage::shade_strip`]):
    /// no input but gl_FragCoord and gl_FrontFacing is per pixel (no
    /// gl_PointCoord or gl_PrimitiveID, no probe), and every other input
    /// is interpolated or flat.
    strips: bool,
    /// Whether a batch's outputs are cleared before the shader runs (see
    /// [`ShaderStage::writes_every_output`]; always under the probe,
    /// whose traced runs take another path).
    clear_outputs: bool,
}

impl<'a> FragmentStage<'a> {
    /// Whether every run of the stage's shaders returns `Ok`
    /// ([`ShaderStage::always_completes`]).
    pub fn always_completes(&self) -> bool {
        self.shader.always_completes()
            && (self.deferred.as_ref()).is_none_or(|d| d.always_completes())
    }

    /// The fragment stage of a draw: `shader` with `layout`'s linkage
    /// under `state`.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        shader: &'a dyn ShaderStage,
        uniforms: &'a [u32],
        textures: &'a (dyn Textures + Sync),
        layout: &'a FsLayout,
        state: &'a PipelineState,
        attrs: Vec<&'a [Plane]>,
        deferred: Option<Box<dyn ShaderStage>>,
        probe: Option<&'a Probe>,
    ) -> FragmentStage<'a> {
        let read_by =
            |stage: &dyn ShaderStage, offset: usize| probe.is_some() || stage.reads_input(offset);
        let plan = |stage: &dyn ShaderStage| -> Vec<FillLink> {
            layout
                .links
                .iter()
                .enumerate()
                .filter(|&(_, l)| l.fs_offset < layout.inputs && read_by(stage, l.fs_offset))
                .map(|(li, l)| FillLink {
                    li,
                    offset: l.fs_offset,
                    kind: match l.texcoord {
                        Some((set, c)) if set < 32 && state.coord_replace & (1 << set) != 0 => {
                            FillKind::Replace(c.min(3))
                        }
                        _ => FillKind::Interp,
                    },
                })
                .collect()
        };
        let fills = plan(shader);
        // gl_FragCoord's z and w only when a stage reads them.
        let read = |c: usize| {
            read_by(shader, c) || deferred.as_ref().is_some_and(|d| read_by(d.as_ref(), c))
        };
        let frag_zw = layout
            .frag_coord
            .map_or([false; 2], |o| [read(o + 2), read(o + 3)]);
        let window_z = probe.is_some()
            || frag_zw[0]
            || (layout.frag_depth.is_none() && state.depth_test.is_some());
        let strips = strips_allowed()
            && probe.is_none()
            && layout.point_coord.is_none()
            && layout.primitive_id.is_none()
            && fills.iter().all(|f| matches!(f.kind, FillKind::Interp));
        let depth_fills = match &deferred {
            // Only what both read (the slice reads a subset of the inputs).
            Some(d) => plan(d.as_ref())
                .into_iter()
                .filter(|f| fills.iter().any(|g| g.offset == f.offset))
                .collect(),
            None => Vec::new(),
        };
        FragmentStage {
            shader,
            uniforms,
            textures,
            layout,
            state,
            attrs,
            fills,
            depth_fills,
            level: crate::simd::detect(),
            colors_out: (0..MAX_DRAW_BUFFERS)
                .filter_map(|i| match (layout.color_out[i], state.draw_buffers[i]) {
                    (Some(o), Some(_)) => Some((i, o)),
                    _ => None,
                })
                .chain(
                    layout
                        .src1_out
                        .filter(|_| state.blend.as_ref().is_some_and(|b| b.uses_src1()))
                        .map(|o| (SRC1, o)),
                )
                .collect(),
            early: layout.frag_depth.is_none(),
            window_z,
            frag_zw,
            depth_format: DepthFormat::Bits24,
            strips,
            clear_outputs: probe.is_some() || !shader.writes_every_output(),
            prepared: shader.prepare(uniforms, textures),
            deferred_prepared: deferred
                .as_ref()
                .and_then(|d| d.prepare(uniforms, textures)),
            lanes_independent: shader.lanes_independent(),
            deferred_lanes_independent: deferred.as_ref().is_some_and(|d| d.lanes_independent()),
            depth_range: deferred
                .as_ref()
                .filter(|_| layout.frag_depth.is_some() && probe.is_none())
                .and_then(|d| d.depth_range(uniforms)),
            bounds: Box::default(),
            bound_stats: Default::default(),
            deferred,
            probe,
        }
    }

    /// Asks the CPU to fetch what the primitives after `bin[i]` will
    /// need: the varyings of the one [`ATTRS_AHEAD`] later (when `attrs`:
    /// finding them reads that primitive, so not for a pass that does
    /// not interpolate), the set-up of
    /// the one [`PRIM_AHEAD`] later (far enough for a memory access when
    /// primitives cover a pixel or two: a tile's primitives lie all over
    /// the draw's), and the `prims` entry (the pointer to the set-up) of
    /// the one [`SLOT_AHEAD`] later, which is read to find that set-up
    /// (with many small primitives the pointer array does not stay in the
    /// cache either). Only a hint: no effect on results.
    #[inline(always)]
    fn prefetch_ahead(&self, prims: &[&Prim], bin: &[u32], i: usize, attrs: bool) {
        if let Some(slot) = bin
            .get(i + SLOT_AHEAD)
            .and_then(|&p| prims.get(p as usize..p as usize + 1))
        {
            prefetch(slot);
        }
        let at = |k: usize| bin.get(i + k).and_then(|&p| prims.get(p as usize));
        if let Some(&next) = at(ATTRS_AHEAD).filter(|_| attrs) {
            self.prefetch_attrs(next);
        }
        if let Some(&after) = at(PRIM_AHEAD) {
            prefetch(std::slice::from_ref(after));
        }
    }

    /// [`prefetch`] of `prim`'s varyings.
    #[inline(always)]
    fn prefetch_attrs(&self, prim: &Prim) {
        let a = self.prim_attrs(prim);
        prefetch(a.get(..self.layout.links.len()).unwrap_or(a));
    }

    /// The planes of `prim`'s varyings (and those after it in its chunk).
    #[inline(always)]
    fn prim_attrs(&self, prim: &Prim) -> &'a [Plane] {
        self.attrs
            .get(prim.chunk as usize)
            .and_then(|a| a.get(prim.index as usize * self.layout.links.len()..))
            .unwrap_or(&[])
    }

    /// Runs the shader on `batch` (with the per-draw prepared values).
    fn run_shader(&self, batch: &mut Batch) -> Result<(), ExecError> {
        match &self.prepared {
            Some(p) => self
                .shader
                .run_prepared(batch, p, self.uniforms, self.textures),
            None => self.shader.run(batch, self.uniforms, self.textures),
        }
    }

    /// Runs the depth-only slice `depth` (this stage's
    /// [`FragmentStage::deferred`]) on `batch`.
    fn run_depth(&self, depth: &dyn ShaderStage, batch: &mut Batch) -> Result<(), ExecError> {
        match &self.deferred_prepared {
            Some(p) => depth.run_prepared(batch, p, self.uniforms, self.textures),
            None => depth.run(batch, self.uniforms, self.textures),
        }
    }

    /// Zeroes `batch`'s outputs before a run, unless the stage writes
    /// them all ([`FragmentStage::clear_outputs`]).
    #[inline(always)]
    fn zero_outputs(&self, batch: &mut Batch) {
        if self.clear_outputs {
            for c in batch.outputs.iter_mut() {
                *c = [0.0; LANES];
            }
        }
    }

    /// Buffers sized for the stage, reused by one tile's primitives and
    /// batches.
    pub fn scratch<'p>(&self) -> Scratch<'p> {
        Scratch {
            batch: new_batch(self.layout.inputs, self.layout.outputs),
            slots: Default::default(),
            n: 0,
            quads: Vec::new(),
            packed: Default::default(),
        }
    }

    /// Shades and writes the part of `prim` inside `tile`. `fb` holds the
    /// pixels of `tile` only (its origin is `(tile.0, tile.1)`).
    pub fn shade<'p>(
        &self,
        fb: &mut Framebuffer,
        prim: &'p Prim,
        tile: PixelRect,
        scratch: &mut Scratch<'p>,
    ) -> Result<(), ExecError> {
        let origin = (tile.0.max(0) as u32, tile.1.max(0) as u32);
        let Scratch {
            batch,
            slots,
            n,
            quads,
            ..
        } = scratch;
        *n = 0;
        prim.shape.quads_into(clip_to(prim, tile), quads);
        for &quad in quads.iter() {
            let Some(e) = slots.get_mut(*n) else { break };
            e.set(prim, 0, quad, 0, Some(self.depth_format));
            if self.early {
                self.early_rejects(fb, origin, prim, &mut e.quad);
            }
            if e.quad.live == 0 {
                continue;
            }
            *n += 1;
            if *n == LANES / 4 {
                self.flush(fb, origin, prim, slots, batch)?;
                *n = 0;
            }
        }
        if *n > 0 {
            self.flush(fb, origin, prim, &slots[..*n], batch)?;
            *n = 0;
        }
        Ok(())
    }

    /// [`FragmentStage::write_batch`] through quick operations whose
    /// colour write qualifies (to fragment output `o`).
    #[inline(always)]
    fn write_quick(&self, target: &mut QuickTarget, o: usize, batch: &Batch, pending: &[Entry]) {
        {
            // The common states: the same operations per fragment, in the
            // same order, without the general checks; a quad's four
            // pixels (distinct) tested together, and without blending the
            // batch's colours converted together.
            let rgba = match batch.outputs.get(o..o + 4) {
                Some([r, g, b, a]) if target.opaque() => {
                    Some(fragment_ops::unorm8_batch(self.level, [r, g, b, a]))
                }
                _ => None,
            };
            for (q, e) in pending.iter().enumerate() {
                let quad = &e.quad;
                let lanes = quad.live & !(batch.discarded >> (4 * q)) as u8 & 0xf;
                if lanes == 0 {
                    continue;
                }
                let z = || std::array::from_fn(|k| self.frag_z(batch, 4 * q + k, quad, k));
                // Without gl_FragDepth, z is the quad's (in [0, 1]), its
                // fixed-point depths known (and z needed only when the
                // quad's lanes are tested one by one).
                let zf = match self.layout.frag_depth {
                    Some(_) => self.depth_format.to_fixed4_f32(z()),
                    None => quad.zf,
                };
                let (pass, index, inside) = target.test_quad_with((quad.x, quad.y), lanes, z, zf);
                match rgba.as_ref().and_then(|c| c.get(4 * q..4 * q + 4)) {
                    Some(&[c0, c1, c2, c3]) => {
                        target.write_rgba8_quad(pass, index, inside, [c0, c1, c2, c3])
                    }
                    _ => {
                        for (k, &index) in index.iter().enumerate() {
                            if pass & (1 << k) != 0 {
                                let lane = 4 * q + k;
                                target.write(index, [0, 1, 2, 3].map(|j| get(batch, o + j, lane)));
                            }
                        }
                    }
                }
            }
        }
    }

    /// Drops the lanes of `quad` that the stencil or depth test will
    /// certainly reject without side effects (no gl_FragDepth write).
    #[inline(always)]
    fn early_rejects(&self, fb: &Framebuffer, origin: (u32, u32), prim: &Prim, quad: &mut Quad) {
        if self.probe.is_none() && (self.state.stencil.is_none() || fb.stencil.is_none()) {
            // No stencil test: a lane is rejected exactly when it fails
            // the depth test (`fragment_ops::early_reject` without a
            // stencil face), and never without one.
            let (Some(func), Some(depth)) = (self.state.depth_test, fb.depth.as_deref()) else {
                return;
            };
            let at = (quad.x - origin.0 as i64, quad.y - origin.1 as i64);
            let size = (fb.width, fb.height);
            quad.live = fragment_ops::depth_live_in(func, depth, size, at, quad.live, quad.zf);
            return;
        }
        for k in 0..4usize {
            if quad.live & (1 << k) == 0 {
                continue;
            }
            let (x, y) = quad.pixel(k);
            let (lx, ly) = (x - origin.0 as i64, y - origin.1 as i64);
            if lx < 0 || ly < 0 || lx >= fb.width as i64 || ly >= fb.height as i64 {
                continue;
            }
            let index = ly as usize * fb.width as usize + lx as usize;
            let zf = quad.zf[k];
            if fragment_ops::early_reject(fb, self.state, index, zf, prim.back) {
                quad.live &= !(1 << k);
                if let Some(p) = self.probe.filter(|p| p.at(x, y)) {
                    p.early_rejected(fb, self.state, index, prim, quad.z[k]);
                }
            }
        }
    }

    /// Sets `frag` to the fragment of lane `4q + k` after shading; false
    /// when the lane is not covered, was discarded or lies left of /
    /// below the window. Only the colours of `colors_out` are written
    /// (the others stay as they were: zero).
    fn fragment_into(
        &self,
        batch: &Batch,
        quad: &Quad,
        q: usize,
        k: usize,
        back: bool,
        frag: &mut Fragment,
    ) -> bool {
        let lane = 4 * q + k;
        if quad.live & (1 << k) == 0 || batch.discarded & (1 << lane) != 0 {
            return false;
        }
        let (x, y) = quad.pixel(k);
        if x < 0 || y < 0 {
            return false;
        }
        frag.x = x as u32;
        frag.y = y as u32;
        frag.z = self.frag_z(batch, lane, quad, k);
        frag.back_facing = back;
        self.colors_into(batch, lane, &mut frag.colors);
        true
    }

    /// The fragment's window z after the shader: gl_FragDepth when the
    /// shader writes it (GL 2.1 §3.11.2, clamped to [0, 1] on conversion),
    /// else the interpolated z.
    fn frag_z(&self, batch: &Batch, lane: usize, quad: &Quad, k: usize) -> f32 {
        let z = match self.layout.frag_depth {
            Some(o) => get(batch, o, lane),
            None => quad.z[k] as f32,
        };
        clamp01(z as f64) as f32
    }

    /// Writes lane `lane`'s colours of `colors_out` into `colors`.
    fn colors_into(&self, batch: &Batch, lane: usize, colors: &mut [[f32; 4]; FRAG_COLORS]) {
        for &(i, o) in &self.colors_out {
            if let Some(c) = colors.get_mut(i) {
                for (j, v) in c.iter_mut().enumerate() {
                    *v = get(batch, o + j, lane);
                }
            }
        }
    }

    fn flush(
        &self,
        fb: &mut Framebuffer,
        origin: (u32, u32),
        prim: &Prim,
        pending: &[Entry],
        batch: &mut Batch,
    ) -> Result<(), ExecError> {
        self.fill(batch, pending, &self.fills, false);
        let live_mask = batch.active & !batch.helper;
        let probed = self.probe.and_then(|p| {
            let lane = pending.iter().enumerate().find_map(|(q, e)| {
                (0..4).find_map(|k| {
                    let (x, y) = e.quad.pixel(k);
                    (p.at(x, y) && live_mask & (1 << (4 * q + k)) != 0).then_some(4 * q + k)
                })
            })?;
            Some((p, lane))
        });
        let pixel_of = |l: usize| Some(pending.get(l / 4)?.quad.pixel(l % 4));
        let mut record = None;
        let mut watched = Vec::new();
        match probed {
            Some((p, lane)) => {
                if p.prints_others() {
                    // The other lanes' prints: the same batch run once
                    // more (runs are deterministic).
                    let mut copy = batch.clone();
                    p.print_batch(
                        (self.shader, self.uniforms, self.textures),
                        &mut copy,
                        prim.source,
                        |l| pixel_of(l).filter(|_| l != lane),
                    )?;
                }
                let z = pending.get(lane / 4).map_or(0.0, |e| e.quad.z[lane % 4]);
                let mut r = p.begin(prim, batch, lane, z);
                let result =
                    self.shader
                        .run_probed(batch, self.uniforms, self.textures, lane, &mut r);
                r.finish(batch, lane, result.as_ref().err());
                if let Err(e) = result {
                    // The failing invocation is kept: it is often the one
                    // being debugged, and its trace shows where it looped.
                    p.push(r);
                    return Err(e);
                }
                record = Some((p, lane, r));
            }
            None => {
                if let Some((p, view)) = self.probe.and_then(|p| Some((p, p.view()?))) {
                    watched =
                        p.run_view((self.shader, self.uniforms, self.textures), batch, view)?;
                } else if let Some(p) = self.probe {
                    p.print_batch(
                        (self.shader, self.uniforms, self.textures),
                        batch,
                        prim.source,
                        pixel_of,
                    )?;
                } else {
                    self.run_shader(batch)?;
                }
            }
        }

        let mut frag = Fragment {
            x: 0,
            y: 0,
            z: 0.0,
            back_facing: false,
            colors: [[0.0; 4]; FRAG_COLORS],
        };
        for (q, e) in pending.iter().enumerate() {
            for k in 0..4 {
                let lane = 4 * q + k;
                if !self.fragment_into(batch, &e.quad, q, k, prim.back, &mut frag) {
                    continue;
                }
                let passed = match record.as_mut().filter(|r| r.1 == lane) {
                    Some((p, _, r)) => p.process(fb, origin, self.state, &frag, r),
                    None => fragment_ops::process(fb, origin, self.state, &frag),
                };
                if let (true, Some(p)) = (passed && !watched.is_empty(), self.probe) {
                    p.view_store(frag.x, frag.y, &watched, lane);
                }
            }
        }
        if let Some((p, _, r)) = record {
            p.push(r);
        }
        Ok(())
    }
}

#[cfg(test)]
thread_local! {
    /// Tests: whether draws on this thread may use strips.
    static NO_STRIPS: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Whether [`FragmentStage::strips`] may be set (tests turn them off to
/// compare).
fn strips_allowed() -> bool {
    #[cfg(test)]
    if NO_STRIPS.with(|c| c.get()) {
        return false;
    }
    true
}

/// Tests: runs `f` without strips on this thread (draws on one thread run
/// there).
#[cfg(test)]
pub(crate) fn without_strips<T>(f: impl FnOnce() -> T) -> T {
    let old = NO_STRIPS.with(|c| c.replace(true));
    let out = f();
    NO_STRIPS.with(|c| c.set(old));
    out
}

/// Asks the CPU to bring the cache lines of `data` closer (a hint with
/// no effect on results; nothing on targets without one).
#[inline(always)]
fn prefetch<T>(data: &[T]) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        let start = data.as_ptr() as *const i8;
        let bytes = std::mem::size_of_val(data);
        // Every line from the first byte's to the last byte's: from the
        // start of the first line, 64 bytes at a time.
        let skew = start as usize % 64;
        let mut offset = 0;
        while offset < bytes + skew {
            // SAFETY: a prefetch is a hint: it never faults and reads
            // nothing the program sees (the address may be before `data`
            // in its first line).
            unsafe { _mm_prefetch::<_MM_HINT_T0>(start.wrapping_sub(skew).wrapping_add(offset)) }
            offset += 64;
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = data;
}

/// `prim`'s bounds inside `tile` (an area of its shape:
/// `Shape::area`).
fn clip_to(prim: &Prim, tile: PixelRect) -> PixelRect {
    (
        prim.bounds.0.max(tile.0),
        prim.bounds.1.max(tile.1),
        prim.bounds.2.min(tile.2),
        prim.bounds.3.min(tile.3),
    )
}

fn set(batch: &mut Batch, component: usize, lane: usize, value: f32) {
    if let Some(c) = batch.inputs.get_mut(component) {
        if let Some(l) = c.get_mut(lane) {
            *l = value;
        }
    }
}

fn get(batch: &Batch, component: usize, lane: usize) -> f32 {
    batch
        .outputs
        .get(component)
        .and_then(|c| c.get(lane))
        .copied()
        .unwrap_or(0.0)
}
