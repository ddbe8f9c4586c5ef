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

struct Quad {
    x: i64,
    y: i64,
    live: u8,
    interp: [Interp; 4],
    /// Final window z per pixel (offset and clamped).
    z: [f64; 4],
}

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
    /// The debugger's pixel probe (`None` in normal draws).
    pub probe: Option<&'a crate::probe::Probe>,
}

impl FragmentStage<'_> {
    /// Shades and writes the part of `prim` inside `tile`. `fb` holds the
    /// pixels of `tile` only (its origin is `(tile.0, tile.1)`).
    pub fn shade(
        &self,
        fb: &mut Framebuffer,
        prim: &Prim,
        tile: PixelRect,
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
            if self.early {
                for k in 0..4usize {
                    if quad.live & (1 << k) == 0 {
                        continue;
                    }
                    let (x, y) = (qx + (k as i64 & 1), qy + (k as i64 >> 1));
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
            if quad.live == 0 {
                continue;
            }
            pending.push(quad);
            if pending.len() == LANES / 4 {
                self.flush(fb, origin, prim, &pending)?;
                pending.clear();
            }
        }
        if !pending.is_empty() {
            self.flush(fb, origin, prim, &pending)?;
        }
        Ok(())
    }

    fn flush(
        &self,
        fb: &mut Framebuffer,
        origin: (u32, u32),
        prim: &Prim,
        quads: &[Quad],
    ) -> Result<(), ExecError> {
        let layout = self.layout;
        let mut batch = new_batch(layout.inputs, layout.outputs);
        let links = layout.links.len();
        let nv = prim.vertices();
        let is_point = matches!(prim.shape, Shape::Point { .. });
        let sprite = is_point && self.state.point_sprite;
        let mut live_mask = 0u32;
        for (q, quad) in quads.iter().enumerate() {
            live_mask |= (quad.live as u32) << (4 * q);
            for k in 0..4 {
                let lane = 4 * q + k;
                let (x, y) = (quad.x + (k as i64 & 1), quad.y + (k as i64 >> 1));
                let it = &quad.interp[k];
                let pc = prim
                    .shape
                    .point_coord(x, y, self.state.point_sprite_origin_lower_left);
                for (li, link) in layout.links.iter().enumerate() {
                    let mut value = if is_point || self.constant.get(li).copied().unwrap_or(false) {
                        prim.attrs.get(li).copied().unwrap_or(0.0)
                    } else {
                        let mut acc = 0.0f64;
                        for j in 0..nv {
                            let a = prim.attrs.get(j * links + li).copied().unwrap_or(0.0);
                            acc += it.weights[j] * a as f64;
                        }
                        acc as f32
                    };
                    if let (true, Some((set, c))) = (sprite, link.texcoord) {
                        if set < 32 && self.state.coord_replace & (1 << set) != 0 {
                            value = [pc.0, pc.1, 0.0, 1.0][c.min(3)];
                        }
                    }
                    set(&mut batch, link.fs_offset, lane, value);
                }
                if let Some(o) = layout.frag_coord {
                    set(&mut batch, o, lane, x as f32 + 0.5);
                    set(&mut batch, o + 1, lane, y as f32 + 0.5);
                    set(&mut batch, o + 2, lane, quad.z[k] as f32);
                    set(&mut batch, o + 3, lane, it.inv_w as f32);
                }
                if let Some(o) = layout.front_facing {
                    set(&mut batch, o, lane, if prim.back { 0.0 } else { 1.0 });
                }
                if let Some(o) = layout.point_coord {
                    set(&mut batch, o, lane, pc.0);
                    set(&mut batch, o + 1, lane, pc.1);
                }
            }
        }
        let active = if quads.len() >= LANES / 4 {
            u32::MAX >> (32 - LANES)
        } else {
            (1u32 << (4 * quads.len())) - 1
        };
        batch.active = active;
        batch.helper = active & !live_mask;
        batch.discarded = 0;
        let probed = self.probe.and_then(|p| {
            let lane = quads.iter().enumerate().find_map(|(q, quad)| {
                (0..4).find_map(|k| {
                    let (x, y) = (quad.x + (k as i64 & 1), quad.y + (k as i64 >> 1));
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
                        let quad = quads.get(l / 4)?;
                        let k = (l % 4) as i64;
                        Some((quad.x + (k & 1), quad.y + (k >> 1))).filter(|_| l != lane)
                    })?;
                }
                let mut r = p.begin(prim, &batch, lane, quads[lane / 4].z[lane % 4]);
                let result =
                    self.shader
                        .run_probed(&mut batch, self.uniforms, self.textures, lane, &mut r);
                r.finish(&batch, lane, result.as_ref().err());
                result?;
                record = Some((p, lane, r));
            }
            None => {
                if let Some((p, view)) = self.probe.and_then(|p| Some((p, p.view()?))) {
                    watched = p.run_view(self, &mut batch, view)?;
                } else if let Some(p) = self.probe {
                    p.print_batch(self, &mut batch, prim.source, |lane| {
                        let quad = quads.get(lane / 4)?;
                        let k = (lane % 4) as i64;
                        Some((quad.x + (k & 1), quad.y + (k >> 1)))
                    })?;
                } else {
                    self.shader.run(&mut batch, self.uniforms, self.textures)?;
                }
            }
        }

        for (q, quad) in quads.iter().enumerate() {
            for k in 0..4 {
                let lane = 4 * q + k;
                if live_mask & (1 << lane) == 0 || batch.discarded & (1 << lane) != 0 {
                    continue;
                }
                let (x, y) = (quad.x + (k as i64 & 1), quad.y + (k as i64 >> 1));
                if x < 0 || y < 0 {
                    continue;
                }
                let z = match layout.frag_depth {
                    // GL 2.1 §3.11.2: gl_FragDepth replaces the window z
                    // (clamped to [0, 1] on conversion).
                    Some(o) => get(&batch, o, lane),
                    None => quad.z[k] as f32,
                };
                let mut colors = [[0.0f32; 4]; MAX_DRAW_BUFFERS];
                for (i, c) in colors.iter_mut().enumerate() {
                    if let (Some(o), Some(_)) = (layout.color_out[i], self.state.draw_buffers[i]) {
                        for (j, v) in c.iter_mut().enumerate() {
                            *v = get(&batch, o + j, lane);
                        }
                    }
                }
                let frag = Fragment {
                    x: x as u32,
                    y: y as u32,
                    z: clamp01(z as f64) as f32,
                    back_facing: prim.back,
                    colors,
                };
                let passed = match record.as_mut().filter(|r| r.1 == lane) {
                    Some((p, _, r)) => p.process(fb, origin, self.state, &frag, r),
                    None => fragment_ops::process(fb, origin, self.state, &frag),
                };
                if let (true, Some(p)) = (passed && !watched.is_empty(), self.probe) {
                    p.view_store(frag.x, frag.y, &batch, &watched, lane);
                }
            }
        }
        if let Some((p, _, r)) = record {
            p.push(r);
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
