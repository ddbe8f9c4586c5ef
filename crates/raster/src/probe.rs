//! The debugger's pixel probe: what one draw did at one pixel, recorded
//! as the stages run ([`Probe`], carried by a replayed draw; the replays
//! themselves are `crate::replay`), and the report types it fills
//! ([`DrawProbe`], [`ViewImage`]).
//!
//! The vertex stage reports prints, the geometry stage (when the draw
//! has one) which input primitive emitted each vertex, set-up each
//! primitive's vertices and window outline, and the fragment stage, for
//! each fragment that reaches the pixel: its primitive, its inputs, every statement and store
//! of its shader invocation ([`exec::Kernel::run_traced`]), `discard`, its
//! outputs and each per-fragment operation's decision with the values it
//! compared. Normal draws carry no probe and pay one `Option` check per
//! batch of 16 lanes.

use crate::assembly::Assembled;
use crate::ex::{self, Batch, ExecError, PrintSink, Trace};
use crate::fragment_ops::{self, Fragment};
use crate::framebuffer::{ColorBuffer, Framebuffer};
use crate::linkage::VsLayout;
use crate::prim::Prim;
use crate::rasterize::WinVertex;
use crate::shaded::{LayerSelect, Vertices};
use crate::state::PipelineState;
use crate::ShaderStage;
use glsl::Span;
use std::sync::Mutex;

/// Trace events (statements, stores, prints) one replayed draw records
/// over all its traced invocations. A shader that loops until the loop
/// budget stops it would otherwise record without bound; past the limit
/// the shaders run on unrecorded and the trace says it was truncated.
pub const MAX_TRACE_EVENTS: usize = 1 << 20;

/// A value to show for the whole frame as a false-colour image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// Components `offset..offset + components` of the fragment shader's
    /// inputs (a varying, gl_FragCoord...).
    Input { offset: usize, components: usize },
    /// The last value stored into registers `first..first + components`
    /// (a local or global variable: `exec::Kernel::variables`).
    Variable { first: u32, components: usize },
}

/// The viewed value of the last fragment written at each pixel (bottom
/// row first): up to 4 components as raw bits (`f32` bits for inputs;
/// the variable's own kinds for variables).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ViewImage {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<Option<[u32; 4]>>,
}

/// One vertex shader invocation, traced.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct VertexProbe {
    /// Position in the draw's index list, and the vertex index there.
    pub position: usize,
    pub index: u32,
    /// The vertex shader's inputs and outputs (laid out as its interface;
    /// outputs as the shader wrote them, before the colour clamp of GL 2.1
    /// §2.14.6 that `DrawProbe::vertex_outputs` shows).
    pub inputs: Vec<f32>,
    pub events: Vec<Event>,
    /// `events` stopped at [`MAX_TRACE_EVENTS`]; the shader ran on.
    pub truncated: bool,
    pub outputs: Vec<f32>,
    pub error: Option<String>,
}

/// Where an emitted vertex comes from: the geometry shader invocation of
/// input primitive `primitive` (its number in the draw's assembly order)
/// emitted it as its `vertex`th vertex (from 0).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EmittedBy {
    pub primitive: u32,
    pub vertex: u32,
}

/// One geometry shader invocation, traced: the one of an input primitive
/// that emitted a vertex of a fragment's primitive at the probed pixel.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GeometryProbe {
    /// The input primitive's number in the draw's assembly order, and
    /// the `gl_PrimitiveIDIn` it ran with.
    pub primitive: u32,
    pub primitive_id: u32,
    /// Its vertices (adjacent ones included, in the order the shader takes
    /// them): positions in the draw's index list, and the vertex indices
    /// there.
    pub positions: Vec<usize>,
    pub indices: Vec<u32>,
    /// The geometry shader's inputs (laid out as its interface).
    pub inputs: Vec<f32>,
    /// Statements, stores and prints of the invocation, in order.
    pub events: Vec<Event>,
    /// `events` stopped at the draw's [`MAX_TRACE_EVENTS`]; the shader ran
    /// on.
    pub truncated: bool,
    /// The vertices it emitted, in order (as the shader wrote them, before
    /// the colour clamp that `DrawProbe::vertex_outputs` shows).
    pub emitted: Vec<EmittedVertex>,
    pub error: Option<String>,
}

/// One vertex a geometry shader invocation emitted.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct EmittedVertex {
    /// Its outputs, laid out as the geometry shader's output interface.
    pub outputs: Vec<f32>,
    /// The strip it belongs to: `EndPrimitive()` starts a new number.
    pub strip: u32,
}

/// What one draw did at the probed pixel.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DrawProbe {
    pub pixel: (u32, u32),
    /// The pixel is outside the framebuffer or the scissor box: no fragment
    /// can reach it (or, set by the caller, why the draw was not replayed).
    pub unreachable: Option<String>,
    /// The replayed draw stopped with this error (a shader's loop
    /// budget...); what it recorded up to then is kept.
    pub stopped: Option<String>,
    /// Every assembled primitive's vertices, as positions in the draw's
    /// index list (only primitives that produced a fragment here are
    /// referenced by [`FragmentProbe::primitive`]).
    pub primitives: Vec<Vec<usize>>,
    /// The vertex stage's outputs per index position (`vertex_outputs`
    /// floats each, laid out as the vertex shader's interface).
    pub vertex_outputs: Vec<Vec<f32>>,
    /// The fragments that reached the pixel, in the order they were
    /// processed.
    pub fragments: Vec<FragmentProbe>,
    /// `debugPrintfEXT` output of fragments in the print rectangle other
    /// than the probed pixel, in execution order.
    pub prints: Vec<PrintLine>,
    /// `debugPrintfEXT` output of the vertex shader (every vertex, when a
    /// print rectangle is asked for): vertex index, call, text.
    pub vertex_prints: Vec<(u32, Span, String)>,
    /// `debugPrintfEXT` output of the geometry shader (every invocation,
    /// when a print rectangle is asked for): input primitive number, call,
    /// text.
    pub geometry_prints: Vec<(u32, Span, String)>,
    /// The layer replayed, in a draw whose geometry shader writes
    /// `gl_Layer` into a layered framebuffer (only that layer's primitives
    /// are drawn, into that layer's images).
    pub layer: Option<i32>,
    /// The pixel after the draw.
    pub after: PixelState,
    /// The traced vertex ([`crate::ProbeRequest::vertex`]).
    pub vertex: Option<VertexProbe>,
    /// Window-space (x, y) corners of every primitive set up for
    /// rasterization (after clipping), when [`crate::ProbeRequest::outlines`].
    pub outlines: Vec<Vec<[f64; 2]>>,
    /// With a geometry stage, `primitives` and `vertex_outputs` are those
    /// of the emitted primitives (positions in the list of emitted
    /// vertices they make); this says, per position there, which input
    /// primitive's invocation emitted the vertex. Empty without one.
    pub emitted_by: Vec<EmittedBy>,
    /// With a geometry stage, the invocations that emitted the primitives
    /// of [`DrawProbe::fragments`], traced, by input primitive number.
    pub geometry: Vec<GeometryProbe>,
}

/// One `debugPrintfEXT` line.
#[derive(Clone, Debug, PartialEq)]
pub struct PrintLine {
    pub x: u32,
    pub y: u32,
    pub primitive: u32,
    pub span: Span,
    pub text: String,
}

/// One fragment at the probed pixel.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FragmentProbe {
    /// Index of the assembled primitive (in `DrawProbe::primitives`).
    pub primitive: u32,
    pub back_facing: bool,
    /// The (clipped) primitive's window-space vertices: x, y, z, 1/w.
    pub window_vertices: Vec<[f64; 4]>,
    /// Window z of the fragment before the shader (after polygon offset).
    pub window_z: f64,
    /// The fragment shader's inputs (laid out as its interface).
    pub inputs: Vec<f32>,
    /// Statements, stores and prints of the invocation, in order.
    pub events: Vec<Event>,
    /// `events` stopped at the draw's [`MAX_TRACE_EVENTS`]; the shader ran
    /// on.
    pub truncated: bool,
    pub discarded: bool,
    /// The shader failed (loop budget...).
    pub error: Option<String>,
    /// The fragment shader's outputs (laid out as its interface).
    pub outputs: Vec<f32>,
    /// Rejected by the early depth/stencil test: the shader did not run.
    pub early_rejected: bool,
    /// The per-fragment operations (absent when discarded or early
    /// rejected... or when the shader failed).
    pub ops: Option<OpsProbe>,
}

/// One step of a traced invocation.
#[derive(Clone, Debug, PartialEq)]
pub enum Event {
    /// A statement starts.
    Statement(Span),
    /// A store of `bits` into `register` (see `exec::Kernel::variables`).
    Store { register: u32, bits: u32 },
    /// `debugPrintfEXT` printed `text`.
    Print { span: Span, text: String },
}

/// What the per-fragment operations did with a fragment (GL 2.1 §4.1).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct OpsProbe {
    /// The fragment's depth as stored (24-bit fixed point) and as a float.
    pub fragment_depth: f32,
    pub fragment_depth_fixed: u32,
    pub before: PixelState,
    pub after: PixelState,
    /// `Some(passed)` for each enabled test, in the order GL runs them.
    pub alpha_test: Option<bool>,
    pub stencil_test: Option<bool>,
    pub depth_test: Option<bool>,
    /// Blending (or a logic op) combined the colour with the destination.
    pub blended: bool,
    /// The colour mask (r, g, b, a).
    pub color_mask: [bool; 4],
}

/// A pixel's stored values.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PixelState {
    /// Each colour buffer's RGBA (unorm buffers converted to floats in
    /// [0, 1]; `color_bytes` keeps their bytes).
    pub colors: Vec<[f32; 4]>,
    pub color_bytes: Vec<Option<[u8; 4]>>,
    /// 24-bit fixed-point depth.
    pub depth: Option<u32>,
    pub stencil: Option<u8>,
}

impl PixelState {
    pub(crate) fn read(fb: &Framebuffer, index: usize) -> PixelState {
        let mut s = PixelState {
            depth: fb.depth.as_ref().and_then(|d| d.get(index)).copied(),
            stencil: fb.stencil.as_ref().and_then(|d| d.get(index)).copied(),
            ..PixelState::default()
        };
        for c in &fb.color {
            match c {
                ColorBuffer::Rgba8(v) => {
                    let b = v.get(index).copied().unwrap_or_default();
                    s.colors.push(b.map(crate::unorm8_to_float));
                    s.color_bytes.push(Some(b));
                }
                ColorBuffer::Rgba32F(v) => {
                    s.colors.push(v.get(index).copied().unwrap_or_default());
                    s.color_bytes.push(None);
                }
            }
        }
        s
    }
}

/// The probe a draw carries (interior mutability: the fragment stage holds
/// it by shared reference; the replay runs on one thread).
pub(crate) struct Probe {
    pixel: (i64, i64),
    print_rect: Option<(u32, u32, u32, u32)>,
    outlines: bool,
    view: Option<View>,
    image: Mutex<ViewImage>,
    inner: Mutex<DrawProbe>,
    /// The window vertices (x, y, z, 1/w) of every primitive set up, by
    /// [`Prim::index`] (a probed draw sets up in one chunk): primitives
    /// keep only what rasterization reads.
    windows: Mutex<Vec<Vec<[f64; 4]>>>,
    /// Trace events the draw may still record ([`MAX_TRACE_EVENTS`]).
    events_left: Mutex<usize>,
    /// With a geometry stage: the source of each emitted vertex, by
    /// vertex number, and the vertex stage's results (and their stride)
    /// the geometry stage ran on, for tracing its invocations again.
    emitted: Mutex<Vec<EmittedBy>>,
    geometry_input: Mutex<Option<(Vertices, usize)>>,
    /// A replay of one layer of a layered draw: its primitives only.
    layer: Option<LayerSelect>,
}

/// The trace of the probed lane while its batch runs.
pub(crate) struct Recording {
    pub fragment: FragmentProbe,
    /// Events it may still record (the draw's budget).
    left: usize,
    /// The last statement recorded: the span of a print that follows.
    last_statement: Span,
}

impl Recording {
    /// A recording of `fragment`'s invocation that may keep `left` events.
    pub fn new(fragment: FragmentProbe, left: usize) -> Recording {
        Recording {
            fragment,
            left,
            last_statement: Span::default(),
        }
    }

    /// Events it may still record.
    pub fn left(&self) -> usize {
        self.left
    }

    fn record(&mut self, event: Event) {
        if self.left == 0 {
            self.fragment.truncated = true;
            return;
        }
        self.left -= 1;
        self.fragment.events.push(event);
    }
}

impl Trace for Recording {
    fn statement(&mut self, span: Span) {
        self.last_statement = span;
        self.record(Event::Statement(span));
    }
    fn store(&mut self, register: u32, bits: u32) {
        self.record(Event::Store { register, bits });
    }
    fn printf(&mut self, text: &str) {
        let span = self.last_statement;
        self.record(Event::Print {
            span,
            text: text.to_string(),
        });
    }
}

impl Recording {
    pub fn finish(&mut self, batch: &Batch, lane: usize, error: Option<&ExecError>) {
        let f = &mut self.fragment;
        f.discarded = batch.discarded & (1 << lane) != 0;
        f.outputs = batch.outputs.iter().map(|c| c[lane]).collect();
        f.error = error.map(|e| e.to_string());
    }
}

impl Probe {
    /// A probe of pixel `pixel` (and the prints of `print_rect`, and every
    /// primitive's outline when `outlines`), recording into `report`.
    pub fn for_pixel(
        pixel: (i64, i64),
        print_rect: Option<(u32, u32, u32, u32)>,
        outlines: bool,
        report: DrawProbe,
    ) -> Probe {
        Probe {
            pixel,
            print_rect,
            outlines,
            view: None,
            image: Mutex::new(ViewImage::default()),
            inner: Mutex::new(report),
            windows: Mutex::default(),
            events_left: Mutex::new(MAX_TRACE_EVENTS),
            emitted: Mutex::default(),
            geometry_input: Mutex::default(),
            layer: None,
        }
    }

    /// A probe recording `view` at every pixel of a `width`×`height`
    /// framebuffer.
    pub fn for_view(view: View, width: u32, height: u32) -> Probe {
        Probe {
            pixel: (-1, -1),
            print_rect: None,
            outlines: false,
            view: Some(view),
            inner: Mutex::new(DrawProbe::default()),
            image: Mutex::new(ViewImage {
                width,
                height,
                pixels: vec![None; width as usize * height as usize],
            }),
            windows: Mutex::default(),
            events_left: Mutex::new(MAX_TRACE_EVENTS),
            emitted: Mutex::default(),
            geometry_input: Mutex::default(),
            layer: None,
        }
    }

    /// What [`Probe::for_pixel`]'s probe recorded, and the vertex stage's
    /// results a geometry stage ran on ([`Probe::keep_geometry_input`]).
    pub fn into_parts(self) -> (DrawProbe, Option<(Vertices, usize)>) {
        let input = self
            .geometry_input
            .into_inner()
            .unwrap_or_else(|e| e.into_inner());
        let report = self.inner.into_inner().unwrap_or_else(|e| e.into_inner());
        (report, input)
    }

    /// Keeps the vertex stage's results (`stride` values per vertex) that
    /// the geometry stage ran on.
    pub fn keep_geometry_input(&self, shaded: Vertices, stride: usize) {
        let mut g = self
            .geometry_input
            .lock()
            .unwrap_or_else(|e| e.into_inner());
        *g = Some((shaded, stride));
    }

    /// Notes the source of every emitted vertex, by vertex number.
    pub fn note_emitted(&self, sources: Vec<EmittedBy>) {
        *self.emitted.lock().unwrap_or_else(|e| e.into_inner()) = sources;
    }

    /// The probe replaying only the primitives of layer `select` of a
    /// layered draw.
    pub fn on_layer(mut self, select: Option<LayerSelect>) -> Probe {
        self.layer = select;
        self
    }

    /// The layer replayed, when the draw is one layer of a layered one.
    pub fn layer(&self) -> Option<LayerSelect> {
        self.layer
    }

    /// Trace events the draw may still record.
    pub fn events_left(&self) -> usize {
        *self.events_left.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// What [`Probe::for_view`]'s probe recorded.
    pub fn into_image(self) -> ViewImage {
        self.image.into_inner().unwrap_or_else(|e| e.into_inner())
    }

    fn with<R>(&self, f: impl FnOnce(&mut DrawProbe) -> R) -> R {
        let mut g = self.inner.lock().unwrap_or_else(|e| e.into_inner());
        f(&mut g)
    }

    pub fn view(&self) -> Option<View> {
        self.view
    }

    /// Runs a batch for a view and returns the viewed value's components
    /// per lane: the last values stored into a variable's registers, or an
    /// input's components as the batch held them before the run (as `f32`
    /// bits).
    pub fn run_view(
        &self,
        (shader, uniforms, textures): (&dyn ShaderStage, &[u32], &dyn ex::Textures),
        batch: &mut Batch,
        view: View,
    ) -> Result<Vec<[u32; ex::LANES]>, ExecError> {
        match view {
            View::Variable { first, components } => {
                let mut out = vec![[0u32; ex::LANES]; components.clamp(1, 4)];
                shader.run_watching(batch, uniforms, textures, first, &mut out)?;
                Ok(out)
            }
            View::Input { offset, components } => {
                let out = (offset..offset + components.clamp(1, 4))
                    .map(|c| {
                        batch
                            .inputs
                            .get(c)
                            .map_or([0; ex::LANES], |v| v.map(f32::to_bits))
                    })
                    .collect();
                shader.run(batch, uniforms, textures)?;
                Ok(out)
            }
        }
    }

    /// Records the viewed value of `lane` for pixel (x, y).
    pub fn view_store(&self, x: u32, y: u32, watched: &[[u32; ex::LANES]], lane: usize) {
        let mut img = self.image.lock().unwrap_or_else(|e| e.into_inner());
        let w = img.width as usize;
        if let Some(p) = img.pixels.get_mut(y as usize * w + x as usize) {
            let mut v = [0u32; 4];
            for (c, comp) in watched.iter().take(4).enumerate() {
                v[c] = comp[lane];
            }
            *p = Some(v);
        }
    }

    /// Whether prints of pixels other than the probed one are wanted.
    pub fn prints_others(&self) -> bool {
        self.print_rect.is_some()
    }

    pub fn at(&self, x: i64, y: i64) -> bool {
        (x, y) == self.pixel
    }

    /// Records the outline of a primitive going to set-up, its window
    /// vertices `win` (when asked for).
    pub fn note_shape(&self, win: &[WinVertex]) {
        if !self.outlines {
            return;
        }
        let corners: Vec<[f64; 2]> = win.iter().map(|w| [w.x, w.y]).collect();
        self.with(|r| r.outlines.push(corners));
    }

    /// Records the window vertices of the primitive just set up (the
    /// next [`Prim::index`]).
    pub fn note_window(&self, win: &[WinVertex]) {
        let mut windows = self.windows.lock().unwrap_or_else(|e| e.into_inner());
        windows.push(win.iter().map(|w| [w.x, w.y, w.z, w.inv_w]).collect());
    }

    pub fn note_primitive(&self, source: u32, p: &Assembled) {
        let positions = match p {
            Assembled::Point(i) => vec![*i],
            Assembled::Line(a, b) => vec![*a, *b],
            Assembled::Polygon(v, _) => v.clone(),
        };
        self.with(|r| {
            if r.primitives.len() == source as usize {
                r.primitives.push(positions);
            }
        });
    }

    pub fn set_vertices(&self, layout: &VsLayout, outputs: &[f32], vertex_of: &[u32]) {
        let n = layout.outputs;
        let per: Vec<Vec<f32>> = vertex_of
            .iter()
            .map(|&v| {
                let v = v as usize;
                outputs.get(v * n..(v + 1) * n).unwrap_or(&[]).to_vec()
            })
            .collect();
        let emitted = self.emitted.lock().unwrap_or_else(|e| e.into_inner());
        let by: Vec<EmittedBy> = if emitted.is_empty() {
            Vec::new()
        } else {
            vertex_of
                .iter()
                .map(|&v| emitted.get(v as usize).copied().unwrap_or_default())
                .collect()
        };
        self.with(|r| {
            r.vertex_outputs = per;
            r.emitted_by = by;
        });
    }

    fn fragment(&self, prim: &Prim, window_z: f64) -> FragmentProbe {
        let windows = self.windows.lock().unwrap_or_else(|e| e.into_inner());
        let verts = windows
            .get(prim.index as usize)
            .cloned()
            .unwrap_or_default();
        FragmentProbe {
            primitive: prim.source,
            back_facing: prim.back,
            window_vertices: verts,
            window_z,
            ..FragmentProbe::default()
        }
    }

    /// The early depth/stencil test dropped the probed pixel's fragment.
    pub fn early_rejected(
        &self,
        fb: &Framebuffer,
        state: &PipelineState,
        index: usize,
        prim: &Prim,
        z: f64,
    ) {
        let mut f = self.fragment(prim, z);
        f.early_rejected = true;
        let before = PixelState::read(fb, index);
        let zf = fb.depth_format.to_fixed(z as f32);
        f.ops = Some(OpsProbe {
            fragment_depth: z as f32,
            fragment_depth_fixed: zf,
            stencil_test: fragment_ops::stencil_passes(state, prim.back, before.stencil),
            depth_test: match (state.depth_test, before.depth) {
                (Some(func), Some(stored)) => Some(func.test(zf, stored)),
                _ => None,
            },
            after: before.clone(),
            before,
            color_mask: state.color_mask,
            ..OpsProbe::default()
        });
        self.with(|r| r.fragments.push(f));
    }

    /// Starts recording the probed lane of a batch about to run.
    pub fn begin(&self, prim: &Prim, batch: &Batch, lane: usize, z: f64) -> Recording {
        let mut fragment = self.fragment(prim, z);
        fragment.inputs = batch.inputs.iter().map(|c| c[lane]).collect();
        let left = *self.events_left.lock().unwrap_or_else(|e| e.into_inner());
        Recording::new(fragment, left)
    }

    /// The per-fragment operations of the probed fragment, recorded.
    pub fn process(
        &self,
        fb: &mut Framebuffer,
        origin: (u32, u32),
        state: &PipelineState,
        frag: &Fragment,
        rec: &mut Recording,
    ) -> bool {
        let (lx, ly) = (
            frag.x.saturating_sub(origin.0),
            frag.y.saturating_sub(origin.1),
        );
        let index = ly as usize * fb.width as usize + lx as usize;
        let before = PixelState::read(fb, index);
        let passed_all = fragment_ops::process(fb, origin, state, frag);
        let after = PixelState::read(fb, index);
        let zf = fb.depth_format.to_fixed(frag.z);
        let alpha = state.alpha_test.map(|(func, reference)| {
            let a = frag.colors[0][3];
            let a = if state.clamp_fragment_color {
                a.clamp(0.0, 1.0)
            } else {
                a
            };
            func.test(a, reference.clamp(0.0, 1.0))
        });
        let stencil = if alpha == Some(false) {
            None
        } else {
            fragment_ops::stencil_passes(state, frag.back_facing, before.stencil)
        };
        let depth = match (alpha, stencil, state.depth_test, before.depth) {
            (Some(false), ..) | (_, Some(false), ..) => None,
            (_, _, Some(func), Some(stored)) => Some(func.test(zf, stored)),
            _ => None,
        };
        let passed = alpha != Some(false) && stencil != Some(false) && depth != Some(false);
        rec.fragment.ops = Some(OpsProbe {
            fragment_depth: frag.z,
            fragment_depth_fixed: zf,
            before,
            after,
            alpha_test: alpha,
            stencil_test: stencil,
            depth_test: depth,
            blended: passed && (state.blend.is_some() || state.logic_op.is_some()),
            color_mask: state.color_mask,
        });
        passed_all
    }

    pub fn push(&self, rec: Recording) {
        *self.events_left.lock().unwrap_or_else(|e| e.into_inner()) = rec.left;
        self.with(|r| r.fragments.push(rec.fragment));
    }

    /// Runs a vertex batch collecting its prints (lane `l` is vertex
    /// `indices[l]`).
    pub fn print_vertices(
        &self,
        vs: &dyn ShaderStage,
        batch: &mut Batch,
        uniforms: &[u32],
        textures: &dyn ex::Textures,
        indices: &[u32],
    ) -> Result<(), ExecError> {
        let mut sink = LaneSink {
            probe: self,
            id_of: |lane: usize| indices.get(lane).copied(),
            into: |r| &mut r.vertex_prints,
        };
        vs.run_printing(batch, uniforms, textures, &mut sink)
    }

    /// Runs a geometry batch collecting its prints (lane `l` is input
    /// primitive `first + l`).
    pub fn print_geometry(
        &self,
        (gs, uniforms, textures): (&dyn ShaderStage, &[u32], &dyn ex::Textures),
        batch: &mut Batch,
        first: usize,
    ) -> Result<(), ExecError> {
        let mut sink = LaneSink {
            probe: self,
            id_of: |lane: usize| u32::try_from(first + lane).ok(),
            into: |r| &mut r.geometry_prints,
        };
        gs.run_printing(batch, uniforms, textures, &mut sink)
    }

    /// Runs a batch without the probed pixel, collecting the prints of its
    /// lanes inside the print rectangle.
    pub fn print_batch(
        &self,
        (shader, uniforms, textures): (&dyn ShaderStage, &[u32], &dyn ex::Textures),
        batch: &mut Batch,
        primitive: u32,
        pixel_of: impl Fn(usize) -> Option<(i64, i64)>,
    ) -> Result<(), ExecError> {
        struct Sink<'p, F> {
            probe: &'p Probe,
            pixel_of: F,
            primitive: u32,
        }
        impl<F: Fn(usize) -> Option<(i64, i64)>> PrintSink for Sink<'_, F> {
            fn print(&mut self, lane: usize, span: Span, text: &str) {
                let Some((x, y)) = (self.pixel_of)(lane) else {
                    return;
                };
                let inside = self.probe.print_rect.is_some_and(|r| {
                    x >= r.0 as i64 && y >= r.1 as i64 && x < r.2 as i64 && y < r.3 as i64
                });
                if inside {
                    let line = PrintLine {
                        x: x as u32,
                        y: y as u32,
                        primitive: self.primitive,
                        span,
                        text: text.to_string(),
                    };
                    self.probe.with(|r| r.prints.push(line));
                }
            }
        }
        let mut sink = Sink {
            probe: self,
            pixel_of,
            primitive,
        };
        shader.run_printing(batch, uniforms, textures, &mut sink)
    }
}

/// Collects a vertex or geometry batch's prints: each lane's under the
/// number `id_of` gives it (a vertex index, an input primitive), into the
/// list `into` picks.
struct LaneSink<'p, I> {
    probe: &'p Probe,
    id_of: I,
    into: fn(&mut DrawProbe) -> &mut Vec<(u32, Span, String)>,
}

impl<I: Fn(usize) -> Option<u32>> PrintSink for LaneSink<'_, I> {
    fn print(&mut self, lane: usize, span: Span, text: &str) {
        if let Some(id) = (self.id_of)(lane) {
            self.probe
                .with(|r| (self.into)(r).push((id, span, text.to_string())));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recording_stops_at_its_budget_and_says_so() {
        let mut rec = Recording::new(FragmentProbe::default(), 3);
        for i in 0..5 {
            rec.statement(Span::new(i, i + 1));
            rec.store(i, i);
        }
        rec.printf("late");
        assert_eq!(rec.fragment.events.len(), 3);
        assert!(rec.fragment.truncated);
        assert_eq!(rec.left, 0);
        let mut roomy = Recording::new(FragmentProbe::default(), 10);
        roomy.statement(Span::new(4, 9));
        roomy.printf("x");
        assert!(!roomy.fragment.truncated);
        assert_eq!(
            roomy.fragment.events[1],
            Event::Print {
                span: Span::new(4, 9),
                text: "x".into()
            }
        );
    }
}
