//! The debugger's entry points: [`probe_draw`] and [`view_draw`] replay a
//! draw ([`Replay`]: what [`crate::draw_on`] takes) on a copy of the
//! framebuffer, on one thread, with a [`Probe`] attached, and return what
//! it recorded ([`DrawProbe`], [`ViewImage`]).
//!
//! With a geometry stage, [`probe_draw`] then runs the geometry shader
//! again, traced, for each input primitive whose invocation emitted a
//! fragment's primitive ([`DrawProbe::geometry`]), on the vertex stage's
//! results the draw kept.
//!
//! [`probe_draw`] narrows the scissor box to the probed pixel (and the
//! `debugPrintfEXT` rectangle, if any). Narrowing the scissor does not
//! change any value the pixel sees: quads are still whole 2×2 quads
//! (helper lanes included, so derivatives are those of the real draw),
//! interpolation is per pixel, and per-fragment operations run in
//! primitive order on the same stored values.

use crate::draw::draw_probed;
use crate::ex;
use crate::framebuffer::Framebuffer;
use crate::geometry::{load_primitive, PrimitiveSource};
use crate::linkage::new_batch;
use crate::probe::{
    DrawProbe, EmittedVertex, FragmentProbe, GeometryProbe, PixelState, Probe, Recording,
    VertexProbe, View, ViewImage, MAX_TRACE_EVENTS,
};
use crate::shaded::LayerSelect;
use crate::state::{PipelineState, Rect};
use crate::vertex::fetch_vertex;
use crate::{DrawError, Mode, VertexFetch};

/// What the debugger asks of one draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ProbeRequest {
    /// The window pixel to trace.
    pub pixel: (u32, u32),
    /// Also collect `debugPrintfEXT` output of fragments in
    /// `[x0, x1) × [y0, y1)` (the pixel's own prints are always in its
    /// trace).
    pub print_rect: Option<(u32, u32, u32, u32)>,
    /// Also trace the vertex shader for this position of the draw's index
    /// list.
    pub vertex: Option<usize>,
    /// Also collect every primitive's window-space outline.
    pub outlines: bool,
}

/// One draw's inputs, as [`crate::draw_on`] takes them, for the debugger's
/// replays ([`probe_draw`], [`view_draw`]).
#[derive(Clone, Copy)]
pub struct Replay<'a> {
    pub state: &'a PipelineState,
    pub vs: &'a ex::Kernel,
    pub vs_uniforms: &'a [u32],
    /// The geometry kernel and its uniform words, if the draw has one.
    pub gs: Option<(&'a ex::Kernel, &'a [u32])>,
    pub fs: &'a ex::Kernel,
    pub fs_uniforms: &'a [u32],
    pub mode: Mode,
    pub indices: &'a [u32],
    pub fetch: &'a dyn VertexFetch,
    pub textures: &'a (dyn ex::Textures + Sync),
    /// One layer of a layered draw: only the primitives the geometry
    /// shader sends to it are drawn (the framebuffer is that layer's).
    pub layer: Option<LayerSelect>,
}

impl Replay<'_> {
    /// Runs the draw on one thread into `fb` with `probe` attached (and
    /// `state` in place of the draw's own).
    fn run(
        &self,
        fb: &mut Framebuffer,
        state: &PipelineState,
        probe: &Probe,
    ) -> Result<(), DrawError> {
        draw_probed(
            &crate::Workers::inline(),
            fb,
            state,
            (self.vs, self.vs_uniforms),
            self.gs.map(|(k, u)| (k as &dyn crate::ShaderStage, u)),
            (self.fs, self.fs_uniforms),
            self.mode,
            self.indices,
            self.fetch,
            self.textures,
            Some(probe),
        )
    }
}

/// Replays a draw on a copy of `fb` and returns, for every pixel a
/// fragment of this draw wrote, the value `view` had in that fragment.
pub fn view_draw(fb: &Framebuffer, draw: &Replay, view: View) -> Result<ViewImage, DrawError> {
    let probe = Probe::for_view(view, fb.width, fb.height).on_layer(draw.layer);
    let mut copy = fb.clone();
    draw.run(&mut copy, draw.state, &probe)?;
    Ok(probe.into_image())
}

impl ProbeRequest {
    /// A request for `pixel` only.
    pub fn pixel(x: u32, y: u32) -> ProbeRequest {
        ProbeRequest {
            pixel: (x, y),
            print_rect: None,
            vertex: None,
            outlines: false,
        }
    }
}

/// Replays a draw on a copy of `fb` and reports what happened at
/// `req.pixel` (see the module docs). A draw that fails part-way is still
/// reported, with the error in [`DrawProbe::stopped`].
pub fn probe_draw(fb: &Framebuffer, draw: &Replay, req: ProbeRequest) -> DrawProbe {
    let state = draw.state;
    let (px, py) = req.pixel;
    let mut report = DrawProbe {
        pixel: req.pixel,
        layer: draw.layer.map(|l| l.layer),
        ..DrawProbe::default()
    };
    if px >= fb.width || py >= fb.height {
        report.unreachable = Some(format!(
            "pixel ({px}, {py}) is outside the {}×{} framebuffer",
            fb.width, fb.height
        ));
        return report;
    }
    // The region replayed: the pixel and the print rectangle, inside the
    // real scissor box.
    let (mut x0, mut y0, mut x1, mut y1) = (px as i64, py as i64, px as i64 + 1, py as i64 + 1);
    if let Some(r) = req.print_rect {
        x0 = x0.min(r.0 as i64);
        y0 = y0.min(r.1 as i64);
        x1 = x1.max(r.2 as i64);
        y1 = y1.max(r.3 as i64);
    }
    if let Some(s) = state.scissor {
        let inside = |x: i64, y: i64| {
            x >= s.x as i64
                && y >= s.y as i64
                && x < s.x as i64 + s.w as i64
                && y < s.y as i64 + s.h as i64
        };
        if !inside(px as i64, py as i64) {
            report.unreachable = Some(format!(
                "pixel ({px}, {py}) is outside the scissor box ({}, {}, {}×{})",
                s.x, s.y, s.w, s.h
            ));
        }
        x0 = x0.max(s.x as i64);
        y0 = y0.max(s.y as i64);
        x1 = x1.min(s.x as i64 + s.w as i64);
        y1 = y1.min(s.y as i64 + s.h as i64);
    }
    let mut narrowed = state.clone();
    narrowed.scissor = Some(Rect {
        x: x0 as i32,
        y: y0 as i32,
        w: (x1 - x0).max(0) as i32,
        h: (y1 - y0).max(0) as i32,
    });
    let probe = Probe::for_pixel((px as i64, py as i64), req.print_rect, req.outlines, report)
        .on_layer(draw.layer);
    let mut copy = fb.clone();
    let result = draw.run(&mut copy, &narrowed, &probe);
    let left = probe.events_left();
    let (mut report, geometry_input) = probe.into_parts();
    report.after = PixelState::read(&copy, (py * copy.width + px) as usize);
    if let (Some(gs), Some((shaded, stride))) = (draw.gs, geometry_input) {
        let source = PrimitiveSource::new(
            draw.vs.interface(),
            gs.0.interface(),
            stride,
            &shaded,
            state,
        );
        report.geometry = trace_geometry(draw, gs, &source, &report, left);
    }
    if let Some(position) = req.vertex {
        report.vertex = Some(trace_vertex(draw, position));
    }
    // A failed draw still shows what it recorded: the fragment whose shader
    // failed is often the one being debugged.
    report.stopped = result.err().map(|e| e.to_string());
    report
}

/// Runs the vertex shader alone for one position of the index list, traced
/// (vertices do not depend on each other, so a batch of one lane gives the
/// values of the real draw).
fn trace_vertex(draw: &Replay, position: usize) -> VertexProbe {
    let (vs, indices) = (draw.vs, draw.indices);
    let Some(&index) = indices.get(position) else {
        return VertexProbe {
            position,
            error: Some(format!(
                "the draw has {} vertices; there is no vertex at position {position}",
                indices.len()
            )),
            ..VertexProbe::default()
        };
    };
    let iface = vs.interface();
    let mut batch = new_batch(iface.input_components, iface.output_components);
    fetch_vertex(iface, draw.fetch, index, &mut batch, 0);
    batch.active = 1;
    let mut rec = Recording::new(FragmentProbe::default(), MAX_TRACE_EVENTS);
    let result = vs.run_traced(&mut batch, draw.vs_uniforms, draw.textures, 0, &mut rec);
    VertexProbe {
        position,
        index,
        inputs: batch.inputs.iter().map(|c| c[0]).collect(),
        truncated: rec.fragment.truncated,
        events: rec.fragment.events,
        outputs: batch.outputs.iter().map(|c| c[0]).collect(),
        error: result.err().map(|e| e.to_string()),
    }
}

/// Runs the geometry shader again, traced, for every input primitive that
/// emitted a vertex of a fragment's primitive in `report`, in primitive
/// order, on the vertex stage's results `source` reads (invocations do not
/// depend on each other, so a batch with the primitive in lane 0 gives
/// the values of the real draw); `left` trace events are shared by them.
fn trace_geometry(
    draw: &Replay,
    (gs, uniforms): (&ex::Kernel, &[u32]),
    source: &PrimitiveSource,
    report: &DrawProbe,
    mut left: usize,
) -> Vec<GeometryProbe> {
    let mut wanted: Vec<u32> = report
        .fragments
        .iter()
        .filter_map(|f| report.primitives.get(f.primitive as usize))
        .flatten()
        .filter_map(|&pos| report.emitted_by.get(pos))
        .map(|by| by.primitive)
        .collect();
    wanted.sort_unstable();
    wanted.dedup();
    let iface = gs.interface();
    let Some(emitted) = iface.emitted else {
        return Vec::new();
    };
    let mut traced = Vec::new();
    for k in wanted {
        let mut batch = new_batch(iface.input_components, iface.output_components);
        load_primitive(&mut batch, 0, k as usize, source);
        batch.active = 1;
        let inputs = batch.inputs.iter().map(|c| c[0]).collect();
        let mut rec = Recording::new(FragmentProbe::default(), left);
        let result = gs.run_traced(&mut batch, uniforms, draw.textures, 0, &mut rec);
        left = rec.left();
        let read = |c: usize| batch.outputs.get(c).map_or(0.0, |x| x[0]);
        let count = (read(emitted.count()).to_bits() as usize).min(emitted.max_vertices);
        let positions = source.positions(k as usize).unwrap_or_default();
        traced.push(GeometryProbe {
            primitive: k,
            primitive_id: draw.state.primitive_ids.of(k),
            indices: positions
                .iter()
                .map(|&p| draw.indices.get(p).copied().unwrap_or_default())
                .collect(),
            positions,
            inputs,
            truncated: rec.fragment.truncated,
            events: rec.fragment.events,
            emitted: (0..count)
                .map(|v| EmittedVertex {
                    outputs: (0..emitted.vertex_components)
                        .map(|c| read(emitted.vertex(v) + c))
                        .collect(),
                    strip: read(emitted.strip(v)).to_bits(),
                })
                .collect(),
            error: result.err().map(|e| e.to_string()),
        });
    }
    traced
}
