//! The fragment stage: covered quads of a set-up primitive are shaded four
//! at a time (one [`Batch`] of 16 lanes), then sent through the
//! per-fragment operations in order.

use crate::ex::{Batch, ExecError, Textures, LANES};
use crate::fragment_ops::{self, Fragment};
use crate::framebuffer::{depth_to_fixed, Framebuffer, MAX_DRAW_BUFFERS};
use crate::linkage::FsLayout;
use crate::rasterize::{Interp, PixelRect, Shape};
use crate::state::PipelineState;
use crate::ShaderStage;

/// A primitive ready for rasterization.
pub(crate) struct Prim {
    pub shape: Shape,
    /// Pixel bounds clipped to the framebuffer and scissor box.
    pub bounds: PixelRect,
    pub back: bool,
    /// Polygon offset added to window z.
    pub z_offset: f64,
    /// Fragment varyings per vertex (`links` values each).
    pub attrs: Vec<f32>,
    /// Index of the assembled primitive this one came from (clipping may
    /// split one into several), for the debugger.
    pub source: u32,
}

impl Prim {
    fn vertices(&self) -> usize {
        match self.shape {
            Shape::Triangle { .. } => 3,
            Shape::Line { .. } => 2,
            Shape::Point { .. } => 1,
        }
    }
}

pub(crate) fn new_batch(inputs: usize, outputs: usize) -> Batch {
    Batch {
        inputs: vec![[0.0; LANES]; inputs],
        outputs: vec![[0.0; LANES]; outputs],
        active: 0,
        discarded: 0,
        helper: 0,
    }
}

fn clamp01(z: f64) -> f64 {
    if z > 0.0 {
        z.min(1.0)
    } else {
        0.0
    }
}

pub(crate) struct Quad {
    x: i64,
    y: i64,
    live: u8,
    interp: [Interp; 4],
    /// Final window z per pixel (offset and clamped).
    z: [f64; 4],
}

impl Quad {
    /// Window coordinates of pixel `k` (0–3: lane `4q + k`'s pixel, see
    /// `exec`'s lane order) of the quad.
    fn pixel(&self, k: usize) -> (i64, i64) {
        (self.x + (k as i64 & 1), self.y + (k as i64 >> 1))
    }

    /// The quad at (qx, qy) of `prim` with coverage `mask`.
    fn new(prim: &Prim, qx: i64, qy: i64, mask: u8) -> Quad {
        let mut quad = Quad {
            x: qx,
            y: qy,
            live: mask,
            interp: [Interp::default(); 4],
            z: [0.0; 4],
        };
        for k in 0..4 {
            let it = prim.shape.interp(qx + (k & 1), qy + (k >> 1));
            quad.interp[k as usize] = it;
            quad.z[k as usize] = clamp01(it.z + prim.z_offset);
        }
        quad
    }
}

/// Bit set in a lane mask for the `LANES / 4` quads of a batch.
fn quads_mask(quads: usize) -> u32 {
    if quads >= LANES / 4 {
        u32::MAX >> (32 - LANES)
    } else {
        (1u32 << (4 * quads)) - 1
    }
}

/// No primitive (in the per-pixel winner table of a deferred tile).
const NO_PRIM: u32 = u32::MAX;

pub(crate) struct FragmentStage<'a> {
    pub shader: &'a dyn ShaderStage,
    pub uniforms: &'a [u32],
    pub textures: &'a (dyn Textures + Sync),
    pub layout: &'a FsLayout,
    pub state: &'a PipelineState,
    /// Per link: flat-shaded (the value of vertex 0 is used as is).
    pub constant: Vec<bool>,
    /// Depth/stencil-test before shading (no gl_FragDepth write).
    pub early: bool,
    /// The depth-only slice of `shader`, when colors may be computed for
    /// the visible fragments only (see [`FragmentStage::shade_deferred`]).
    pub deferred: Option<Box<dyn ShaderStage>>,
    /// The debugger's pixel probe (`None` in normal draws).
    pub probe: Option<&'a crate::probe::Probe>,
}

impl FragmentStage<'_> {
    /// A batch sized for the stage, reused by one tile's flushes.
    pub fn scratch(&self) -> Batch {
        new_batch(self.layout.inputs, self.layout.outputs)
    }

    /// Shades and writes the part of `prim` inside `tile`. `fb` holds the
    /// pixels of `tile` only (its origin is `(tile.0, tile.1)`).
    pub fn shade(
        &self,
        fb: &mut Framebuffer,
        prim: &Prim,
        tile: PixelRect,
        batch: &mut Batch,
    ) -> Result<(), ExecError> {
        let origin = (tile.0.max(0) as u32, tile.1.max(0) as u32);
        let clip = (
            prim.bounds.0.max(tile.0),
            prim.bounds.1.max(tile.1),
            prim.bounds.2.min(tile.2),
            prim.bounds.3.min(tile.3),
        );
        let mut pending: Vec<Quad> = Vec::with_capacity(LANES / 4);
        for (qx, qy, mask) in prim.shape.quads(clip) {
            let mut quad = Quad::new(prim, qx, qy, mask);
            if self.early {
                self.early_rejects(fb, origin, prim, &mut quad);
            }
            if quad.live == 0 {
                continue;
            }
            pending.push(quad);
            if pending.len() == LANES / 4 {
                self.flush(fb, origin, prim, &pending, batch)?;
                pending.clear();
            }
        }
        if !pending.is_empty() {
            self.flush(fb, origin, prim, &pending, batch)?;
        }
        Ok(())
    }

    /// The primitives `bin` (indices into `prims`, in draw order) inside
    /// `tile`, quads of consecutive primitives sharing batches (a
    /// primitive covering a pixel or two no longer costs a whole batch).
    /// Fragments still go through the per-fragment operations in draw
    /// order after their batch ran, so the bytes are those of
    /// [`FragmentStage::shade`] per primitive, provided early rejection
    /// against a depth buffer that misses the batch's pending fragments is
    /// still right: [`FragmentStage::batches_primitives`] says when. On an
    /// error the caller redraws the tile with [`FragmentStage::shade`].
    pub fn shade_batched(
        &self,
        fb: &mut Framebuffer,
        prims: &[Prim],
        bin: &[u32],
        tile: PixelRect,
        batch: &mut Batch,
    ) -> Result<(), ExecError> {
        let origin = (tile.0.max(0) as u32, tile.1.max(0) as u32);
        let mut pending: Vec<(&Prim, Quad)> = Vec::with_capacity(LANES / 4);
        let flush = |fb: &mut Framebuffer,
                     pending: &[(&Prim, Quad)],
                     batch: &mut Batch|
         -> Result<(), ExecError> {
            let pairs: Vec<(&Prim, &Quad)> = pending.iter().map(|(p, q)| (*p, q)).collect();
            self.fill(batch, &pairs);
            self.shader.run(batch, self.uniforms, self.textures)?;
            for (q, (prim, quad)) in pending.iter().enumerate() {
                for k in 0..4 {
                    if let Some(frag) = self.fragment(batch, quad, q, k, prim.back) {
                        fragment_ops::process(fb, origin, self.state, &frag);
                    }
                }
            }
            Ok(())
        };
        for &p in bin {
            let Some(prim) = prims.get(p as usize) else {
                continue;
            };
            let clip = (
                prim.bounds.0.max(tile.0),
                prim.bounds.1.max(tile.1),
                prim.bounds.2.min(tile.2),
                prim.bounds.3.min(tile.3),
            );
            for (qx, qy, mask) in prim.shape.quads(clip) {
                let mut quad = Quad::new(prim, qx, qy, mask);
                if self.early {
                    self.early_rejects(fb, origin, prim, &mut quad);
                }
                if quad.live == 0 {
                    continue;
                }
                pending.push((prim, quad));
                if pending.len() == LANES / 4 {
                    flush(fb, &pending, batch)?;
                    pending.clear();
                }
            }
        }
        if !pending.is_empty() {
            flush(fb, &pending, batch)?;
        }
        Ok(())
    }

    /// Whether [`FragmentStage::shade_batched`] gives the bytes of
    /// [`FragmentStage::shade`]: no early rejection at all, or one that
    /// stays right against an older depth buffer: no stencil test, and a
    /// depth function for which stored depths only move one way
    /// (LESS/LEQUAL: down, GREATER/GEQUAL: up; NEVER/ALWAYS do not look),
    /// or no depth writes. Never with the debugger's probe.
    pub fn batches_primitives(&self, fb: &Framebuffer) -> bool {
        use crate::state::CompareFunc::*;
        if self.probe.is_some() {
            return false;
        }
        if !self.early {
            return true;
        }
        let stencil = self.state.stencil.is_some() && fb.stencil.is_some();
        let monotone = match self.state.depth_test {
            None => true,
            Some(_) if !self.state.depth_mask => true,
            Some(f) => matches!(
                f,
                Less | LessEqual | Greater | GreaterEqual | Never | Always
            ),
        };
        !stencil && monotone
    }

    /// Drops the lanes of `quad` that the stencil or depth test will
    /// certainly reject without side effects (no gl_FragDepth write).
    fn early_rejects(&self, fb: &Framebuffer, origin: (u32, u32), prim: &Prim, quad: &mut Quad) {
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
            let zf = depth_to_fixed(quad.z[k] as f32);
            if fragment_ops::early_reject(fb, self.state, index, zf, prim.back) {
                quad.live &= !(1 << k);
                if let Some(p) = self.probe.filter(|p| p.at(x, y)) {
                    p.early_rejected(fb, self.state, index, prim, quad.z[k]);
                }
            }
        }
    }

    /// Clears `batch` and writes the fragment inputs of `quads` (quad `q`
    /// in lanes `4q..4q + 4`); sets the active and helper lanes.
    fn fill(&self, batch: &mut Batch, quads: &[(&Prim, &Quad)]) {
        for c in batch.inputs.iter_mut() {
            *c = [0.0; LANES];
        }
        for c in batch.outputs.iter_mut() {
            *c = [0.0; LANES];
        }
        let mut live_mask = 0u32;
        for (q, (prim, quad)) in quads.iter().enumerate() {
            live_mask |= (quad.live as u32) << (4 * q);
            self.fill_quad(batch, q, prim, quad);
        }
        let active = quads_mask(quads.len());
        batch.active = active;
        batch.helper = active & !live_mask;
        batch.discarded = 0;
    }

    fn fill_quad(&self, batch: &mut Batch, q: usize, prim: &Prim, quad: &Quad) {
        let layout = self.layout;
        let links = layout.links.len();
        let nv = prim.vertices();
        let is_point = matches!(prim.shape, Shape::Point { .. });
        let sprite = is_point && self.state.point_sprite;
        let lanes = 4 * q..4 * q + 4;
        let xy = |k: usize| quad.pixel(k);
        let pc: [(f32, f32); 4] = std::array::from_fn(|k| {
            if is_point {
                let (x, y) = xy(k);
                prim.shape
                    .point_coord(x, y, self.state.point_sprite_origin_lower_left)
            } else {
                (0.0, 0.0)
            }
        });
        for (li, link) in layout.links.iter().enumerate() {
            let Some(dst) = batch.inputs.get_mut(link.fs_offset) else {
                continue;
            };
            let Some(dst) = dst.get_mut(lanes.clone()) else {
                continue;
            };
            let attr = |j: usize| prim.attrs.get(j * links + li).copied().unwrap_or(0.0);
            let values: [f32; 3] = [attr(0), attr(1), attr(2)];
            let flat = is_point || self.constant.get(li).copied().unwrap_or(false);
            let replace = match (sprite, link.texcoord) {
                (true, Some((set, c)))
                    if set < 32 && self.state.coord_replace & (1 << set) != 0 =>
                {
                    Some(c.min(3))
                }
                _ => None,
            };
            for (k, out) in dst.iter_mut().enumerate() {
                *out = if let Some(c) = replace {
                    [pc[k].0, pc[k].1, 0.0, 1.0][c]
                } else if flat {
                    values[0]
                } else {
                    let w = &quad.interp[k].weights;
                    let mut acc = 0.0f64;
                    for j in 0..nv.min(3) {
                        acc += w[j] * values[j] as f64;
                    }
                    acc as f32
                };
            }
        }
        for (k, (it, pc)) in quad.interp.iter().zip(pc).enumerate() {
            let lane = 4 * q + k;
            let (x, y) = xy(k);
            if let Some(o) = layout.frag_coord {
                set(batch, o, lane, x as f32 + 0.5);
                set(batch, o + 1, lane, y as f32 + 0.5);
                set(batch, o + 2, lane, quad.z[k] as f32);
                set(batch, o + 3, lane, it.inv_w as f32);
            }
            if let Some(o) = layout.front_facing {
                set(batch, o, lane, if prim.back { 0.0 } else { 1.0 });
            }
            if let Some(o) = layout.point_coord {
                set(batch, o, lane, pc.0);
                set(batch, o + 1, lane, pc.1);
            }
        }
    }

    /// The fragment's window z after the shader: gl_FragDepth when the
    /// shader writes it (GL 2.1 §3.11.2, clamped to [0, 1] on conversion),
    /// else the interpolated z.
    /// The fragment of lane `4q + k` after shading, unless the lane is
    /// not covered, was discarded or lies left of / below the window.
    fn fragment(
        &self,
        batch: &Batch,
        quad: &Quad,
        q: usize,
        k: usize,
        back: bool,
    ) -> Option<Fragment> {
        let lane = 4 * q + k;
        if quad.live & (1 << k) == 0 || batch.discarded & (1 << lane) != 0 {
            return None;
        }
        let (x, y) = quad.pixel(k);
        if x < 0 || y < 0 {
            return None;
        }
        Some(Fragment {
            x: x as u32,
            y: y as u32,
            z: self.frag_z(batch, lane, quad, k),
            back_facing: back,
            colors: self.colors(batch, lane),
        })
    }

    fn frag_z(&self, batch: &Batch, lane: usize, quad: &Quad, k: usize) -> f32 {
        let z = match self.layout.frag_depth {
            Some(o) => get(batch, o, lane),
            None => quad.z[k] as f32,
        };
        clamp01(z as f64) as f32
    }

    fn colors(&self, batch: &Batch, lane: usize) -> [[f32; 4]; MAX_DRAW_BUFFERS] {
        let mut colors = [[0.0f32; 4]; MAX_DRAW_BUFFERS];
        for (i, c) in colors.iter_mut().enumerate() {
            if let (Some(o), Some(_)) = (self.layout.color_out[i], self.state.draw_buffers[i]) {
                for (j, v) in c.iter_mut().enumerate() {
                    *v = get(batch, o + j, lane);
                }
            }
        }
        colors
    }

    fn flush(
        &self,
        fb: &mut Framebuffer,
        origin: (u32, u32),
        prim: &Prim,
        quads: &[Quad],
        batch: &mut Batch,
    ) -> Result<(), ExecError> {
        let pairs: Vec<(&Prim, &Quad)> = quads.iter().map(|q| (prim, q)).collect();
        self.fill(batch, &pairs);
        let live_mask = batch.active & !batch.helper;
        let probed = self.probe.and_then(|p| {
            let lane = quads.iter().enumerate().find_map(|(q, quad)| {
                (0..4).find_map(|k| {
                    let (x, y) = quad.pixel(k);
                    (p.at(x, y) && live_mask & (1 << (4 * q + k)) != 0).then_some(4 * q + k)
                })
            })?;
            Some((p, lane))
        });
        let mut record = None;
        let mut watched = Vec::new();
        match probed {
            Some((p, lane)) => {
                if p.prints_others() {
                    // The other lanes' prints: the same batch run once
                    // more (runs are deterministic).
                    let mut copy = batch.clone();
                    p.print_batch(self, &mut copy, prim.source, |l| {
                        Some(quads.get(l / 4)?.pixel(l % 4)).filter(|_| l != lane)
                    })?;
                }
                let mut r = p.begin(prim, batch, lane, quads[lane / 4].z[lane % 4]);
                let result =
                    self.shader
                        .run_probed(batch, self.uniforms, self.textures, lane, &mut r);
                r.finish(batch, lane, result.as_ref().err());
                result?;
                record = Some((p, lane, r));
            }
            None => {
                if let Some((p, view)) = self.probe.and_then(|p| Some((p, p.view()?))) {
                    watched = p.run_view(self, batch, view)?;
                } else if let Some(p) = self.probe {
                    p.print_batch(self, batch, prim.source, |lane| {
                        Some(quads.get(lane / 4)?.pixel(lane % 4))
                    })?;
                } else {
                    self.shader.run(batch, self.uniforms, self.textures)?;
                }
            }
        }

        for (q, quad) in quads.iter().enumerate() {
            for k in 0..4 {
                let lane = 4 * q + k;
                let Some(frag) = self.fragment(batch, quad, q, k, prim.back) else {
                    continue;
                };
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

    /// The primitives `bin` (indices into `prims`, in draw order) inside
    /// `tile`, shading colors only for the fragments that end up visible.
    /// Only for a stage with [`FragmentStage::deferred`] and per-fragment
    /// operations where the last fragment to pass the depth test decides
    /// a pixel's color ([`fragment_ops::last_writer_wins`]).
    ///
    /// Pass 1 runs the depth-only slice on every fragment, four quads at a
    /// time, and sends them through the depth test in draw order, keeping
    /// per pixel the primitive of the last fragment that passed (and that
    /// quad's coverage). Pass 2 runs the full shader once per (primitive,
    /// quad) that won a pixel, with the same quad inputs, coverage and
    /// helper lanes as the straightforward path, and writes the colors of
    /// the winning pixels. The slice computes the same gl_FragDepth and
    /// discards as the full shader, and a lane depends only on its quad, so
    /// the tile ends with the same bytes as [`FragmentStage::shade`] over
    /// the bin. On an error `fb` is left partly drawn: the caller redraws
    /// the tile the straightforward way to get the same error and pixels.
    pub fn shade_deferred(
        &self,
        depth: &dyn ShaderStage,
        fb: &mut Framebuffer,
        prims: &[Prim],
        bin: &[u32],
        tile: PixelRect,
        batch: &mut Batch,
    ) -> Result<(), ExecError> {
        let origin = (tile.0.max(0) as u32, tile.1.max(0) as u32);
        let (w, h) = (fb.width as usize, fb.height as usize);
        // Per pixel: (winning primitive, its quad's coverage).
        let mut winner: Vec<(u32, u8)> = vec![(NO_PRIM, 0); w * h];
        let mut pending: Vec<(u32, Quad)> = Vec::with_capacity(LANES / 4);
        let depth_pass = |fb: &mut Framebuffer,
                          winner: &mut Vec<(u32, u8)>,
                          pending: &[(u32, Quad)],
                          batch: &mut Batch|
         -> Result<(), ExecError> {
            let pairs: Vec<(&Prim, &Quad)> = pending
                .iter()
                .filter_map(|(p, q)| Some((prims.get(*p as usize)?, q)))
                .collect();
            self.fill(batch, &pairs);
            depth.run(batch, self.uniforms, self.textures)?;
            for (q, (prim, quad)) in pairs.iter().enumerate() {
                let p = pending.get(q).map_or(NO_PRIM, |e| e.0);
                for k in 0..4 {
                    let lane = 4 * q + k;
                    if quad.live & (1 << k) == 0 || batch.discarded & (1 << lane) != 0 {
                        continue;
                    }
                    let (x, y) = quad.pixel(k);
                    if x < 0 || y < 0 {
                        continue;
                    }
                    let frag = Fragment {
                        x: x as u32,
                        y: y as u32,
                        z: self.frag_z(batch, lane, quad, k),
                        back_facing: prim.back,
                        colors: [[0.0; 4]; MAX_DRAW_BUFFERS],
                    };
                    if let Some(index) = fragment_ops::tests(fb, origin, self.state, &frag) {
                        if let Some(slot) = winner.get_mut(index) {
                            *slot = (p, quad.live);
                        }
                    }
                }
            }
            Ok(())
        };
        for &p in bin {
            let Some(prim) = prims.get(p as usize) else {
                continue;
            };
            let clip = (
                prim.bounds.0.max(tile.0),
                prim.bounds.1.max(tile.1),
                prim.bounds.2.min(tile.2),
                prim.bounds.3.min(tile.3),
            );
            for (qx, qy, mask) in prim.shape.quads(clip) {
                pending.push((p, Quad::new(prim, qx, qy, mask)));
                if pending.len() == LANES / 4 {
                    depth_pass(fb, &mut winner, &pending, batch)?;
                    pending.clear();
                }
            }
        }
        if !pending.is_empty() {
            depth_pass(fb, &mut winner, &pending, batch)?;
            pending.clear();
        }

        // Pass 2: (primitive, quad, coverage, lanes to write) per winner.
        let mut todo: Vec<(u32, Quad, u8)> = Vec::with_capacity(LANES / 4);
        let color_pass = |fb: &mut Framebuffer,
                          todo: &[(u32, Quad, u8)],
                          batch: &mut Batch|
         -> Result<(), ExecError> {
            let pairs: Vec<(&Prim, &Quad)> = todo
                .iter()
                .filter_map(|(p, q, _)| Some((prims.get(*p as usize)?, q)))
                .collect();
            self.fill(batch, &pairs);
            self.shader.run(batch, self.uniforms, self.textures)?;
            for (q, (_, quad, write)) in todo.iter().enumerate() {
                for k in 0..4 {
                    let lane = 4 * q + k;
                    if write & (1 << k) == 0 || batch.discarded & (1 << lane) != 0 {
                        continue;
                    }
                    let (x, y) = quad.pixel(k);
                    let lx = x as usize - origin.0 as usize;
                    let ly = y as usize - origin.1 as usize;
                    let index = ly * w + lx;
                    fragment_ops::write_colors(fb, index, self.state, &self.colors(batch, lane));
                }
            }
            Ok(())
        };
        for ly in (0..h).step_by(2) {
            for lx in (0..w).step_by(2) {
                // The quad's pixels (lane order) and their winners.
                let mut lanes = [(NO_PRIM, 0u8); 4];
                for (k, lane) in lanes.iter_mut().enumerate() {
                    let (x, y) = (lx + (k & 1), ly + (k >> 1));
                    if x < w && y < h {
                        *lane = winner.get(y * w + x).copied().unwrap_or((NO_PRIM, 0));
                    }
                }
                let mut done = 0u8;
                for k in 0..4 {
                    let (p, live) = lanes[k];
                    if p == NO_PRIM || done & (1 << k) != 0 {
                        continue;
                    }
                    let mut write = 0u8;
                    for (j, lane) in lanes.iter().enumerate() {
                        if lane.0 == p {
                            write |= 1 << j;
                        }
                    }
                    done |= write;
                    let Some(prim) = prims.get(p as usize) else {
                        continue;
                    };
                    let (qx, qy) = (origin.0 as i64 + lx as i64, origin.1 as i64 + ly as i64);
                    todo.push((p, Quad::new(prim, qx, qy, live), write));
                    if todo.len() == LANES / 4 {
                        color_pass(fb, &todo, batch)?;
                        todo.clear();
                    }
                }
            }
        }
        if !todo.is_empty() {
            color_pass(fb, &todo, batch)?;
        }
        Ok(())
    }
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
