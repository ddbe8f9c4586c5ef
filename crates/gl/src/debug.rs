//! Debugging draws: the pixel probe of `raster` on every draw of a context.
//!
//! [`Context::set_debug`] names a window pixel (and optionally one draw and
//! a `debugPrintfEXT` rectangle); every later draw that matches is replayed
//! with [`raster::probe_draw`] before it runs, and its [`DrawRecord`] —
//! the probe plus what is needed to explain it (the kernels with their
//! variable tables, the compiled shader objects with their source text) —
//! waits in the context until [`Context::take_debug_records`]. A draw a
//! geometry shader spreads over the layers of a layered framebuffer is
//! replayed on the layer [`DebugRequest::layer`] names, with the
//! primitives sent there. With no request set, a draw pays one `Option`
//! check.

use crate::Context;
use std::sync::Arc;

/// What to debug.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DebugRequest {
    /// Window pixel of the draw framebuffer.
    pub pixel: (u32, u32),
    /// Only this draw (0-based count of draw calls since the request was
    /// set); all draws when `None`.
    pub draw: Option<usize>,
    /// Collect `debugPrintfEXT` output of this rectangle
    /// `[x0, x1) × [y0, y1)` too.
    pub print_rect: Option<(u32, u32, u32, u32)>,
    /// Trace the vertex shader for this position of each debugged draw's
    /// vertex list.
    pub vertex: Option<usize>,
    /// Collect every primitive's window-space outline.
    pub outlines: bool,
    /// In a draw whose geometry shader writes `gl_Layer` into a layered
    /// framebuffer, the layer to replay (a cube map's face, an array
    /// texture's layer); other draws have one.
    pub layer: i32,
    /// Show this fragment-shader input or variable for the whole frame
    /// ([`DrawRecord::view`]).
    pub view: Option<String>,
}

impl DebugRequest {
    /// Every draw, at `pixel`, nothing else.
    pub fn pixel(x: u32, y: u32) -> DebugRequest {
        DebugRequest {
            pixel: (x, y),
            draw: None,
            print_rect: None,
            vertex: None,
            outlines: false,
            view: None,
            layer: 0,
        }
    }
}

/// A fragment-shader value over the whole frame: for each pixel the draw
/// wrote, the value in the fragment that wrote it last.
#[derive(Clone, Debug)]
pub struct ViewRecord {
    pub name: String,
    /// The kind of each component (at most 4 are kept).
    pub kinds: Vec<glsl::types::Scalar>,
    /// Raw bits as [`raster::ViewImage`] keeps them; inputs are floats.
    pub image: raster::ViewImage,
}

/// One stage of a debugged draw.
#[derive(Clone, Debug)]
pub struct StageInfo {
    pub kernel: Arc<exec::Kernel>,
    /// The program's shader objects of this stage; empty for the
    /// fixed-function stage (generated GLSL, not the application's).
    pub shaders: Vec<Arc<glsl::Shader>>,
}

/// One debugged draw.
#[derive(Clone, Debug)]
pub struct DrawRecord {
    /// Index of the draw since the request was set.
    pub draw: usize,
    /// The primitive mode (`GL_TRIANGLES`...) and the number of indices.
    pub mode: u32,
    pub count: usize,
    /// The current program (0: fixed function).
    pub program: u32,
    /// The draw framebuffer (0: the default one).
    pub framebuffer: u32,
    pub vertex: StageInfo,
    /// The geometry stage, when the program has one.
    pub geometry: Option<StageInfo>,
    pub fragment: StageInfo,
    /// What happened at the pixel (a draw that failed part-way included).
    pub probe: raster::DrawProbe,
    /// The requested view, or why it could not be made.
    pub view: Option<Result<ViewRecord, String>>,
}

/// Where `name` lives in a fragment kernel: an input slot or a variable's
/// registers, with its component kinds.
pub(crate) fn resolve_view(
    fs: &exec::Kernel,
    name: &str,
) -> Result<(raster::View, Vec<glsl::types::Scalar>), String> {
    let iface = fs.interface();
    if let Some(slot) = iface.input(name) {
        let n = slot.components.clamp(1, 4);
        return Ok((
            raster::View::Input {
                offset: slot.offset,
                components: n,
            },
            vec![glsl::types::Scalar::Float; n],
        ));
    }
    if let Some(v) = fs.variables().iter().find(|v| v.name == name) {
        let kinds = exec::kinds(v.ty, &iface.structs);
        let n = (v.registers as usize).clamp(1, 4);
        return Ok((
            raster::View::Variable {
                first: v.first_register,
                components: n,
            },
            kinds.into_iter().take(n).collect(),
        ));
    }
    let mut known: Vec<&str> = iface.inputs.iter().map(|s| s.name.as_str()).collect();
    known.extend(fs.variables().iter().map(|v| v.name.as_str()));
    known.sort_unstable();
    known.dedup();
    Err(format!(
        "the fragment shader has no input or variable `{name}' (it has: {})",
        known.join(", ")
    ))
}

#[derive(Default)]
pub(crate) struct DebugSession {
    pub request: Option<DebugRequest>,
    pub draws: usize,
    pub records: Vec<DrawRecord>,
}

impl DebugSession {
    /// The probe request for the next draw, if it is to be debugged.
    /// The view asked for the next draw, if it is debugged.
    pub fn view(&self) -> Option<&str> {
        self.wants()?;
        self.request.as_ref()?.view.as_deref()
    }

    /// The layer of a layered draw to replay.
    pub fn layer(&self) -> i32 {
        self.request.as_ref().map_or(0, |r| r.layer)
    }

    /// Replays `replay` on `fb` for the probe `req` and the view asked
    /// for, `fs` being its fragment kernel.
    pub fn replay(
        &self,
        fb: &raster::Framebuffer,
        replay: &raster::Replay,
        req: raster::ProbeRequest,
        fs: &exec::Kernel,
    ) -> (
        Option<raster::DrawProbe>,
        Option<Result<ViewRecord, String>>,
    ) {
        let probe = raster::probe_draw(fb, replay, req);
        let view = self.view().map(|name| {
            let (v, kinds) = resolve_view(fs, name)?;
            let image = raster::view_draw(fb, replay, v).map_err(|e| e.to_string())?;
            Ok(ViewRecord {
                name: name.to_string(),
                kinds,
                image,
            })
        });
        (Some(probe), view)
    }

    /// The record of a layered draw asked about a layer its framebuffer
    /// does not have (`layers` of them).
    pub fn missing_layer(
        &self,
        req: raster::ProbeRequest,
        layer: i32,
        layers: i32,
    ) -> (
        Option<raster::DrawProbe>,
        Option<Result<ViewRecord, String>>,
    ) {
        let why = format!("the draw is layered and its framebuffer has {layers} layers: there is no layer {layer}");
        let probe = raster::DrawProbe {
            pixel: req.pixel,
            layer: Some(layer),
            unreachable: Some(why.clone()),
            ..raster::DrawProbe::default()
        };
        (Some(probe), self.view().map(|_| Err(why)))
    }

    pub fn wants(&self) -> Option<raster::ProbeRequest> {
        let r = self.request.as_ref()?;
        if r.draw.is_some_and(|d| d != self.draws) {
            return None;
        }
        Some(raster::ProbeRequest {
            pixel: r.pixel,
            print_rect: r.print_rect,
            vertex: r.vertex,
            outlines: r.outlines,
        })
    }
}

impl Context {
    /// Starts (or, with `None`, stops) debugging draws; resets the draw
    /// count and drops records not yet taken.
    pub fn set_debug(&mut self, request: Option<DebugRequest>) {
        self.debug = DebugSession {
            request,
            ..DebugSession::default()
        };
    }

    /// The records of the draws debugged since the last call.
    pub fn take_debug_records(&mut self) -> Vec<DrawRecord> {
        std::mem::take(&mut self.debug.records)
    }

    /// The compiled shader objects of the current program for `stage`.
    pub(crate) fn stage_shaders(&self, stage: glsl::Stage) -> Vec<Arc<glsl::Shader>> {
        self.stage_executable(stage)
            .map(|e| {
                e.shaders
                    .iter()
                    .filter(|s| s.stage == stage)
                    .cloned()
                    .collect()
            })
            .unwrap_or_default()
    }

    /// A debugged draw's `stage`: its kernel, and the application's shader
    /// objects when the stage is the program's (`user`), none for the
    /// fixed-function one.
    pub(crate) fn stage_info(
        &self,
        stage: glsl::Stage,
        user: bool,
        kernel: Arc<exec::Kernel>,
    ) -> StageInfo {
        StageInfo {
            shaders: if user {
                self.stage_shaders(stage)
            } else {
                Vec::new()
            },
            kernel,
        }
    }

    /// Records a debugged draw (`probe`, `view`) of `mode` and `count`
    /// indices into `framebuffer` with its stages (kernel, whether it is
    /// the program's), and counts the draw while a request is set.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn record_draw(
        &mut self,
        (mode, count, framebuffer): (u32, usize, u32),
        (vs, vs_user): (Arc<exec::Kernel>, bool),
        gs: Option<Arc<exec::Kernel>>,
        (fs, fs_user): (Arc<exec::Kernel>, bool),
        probe: Option<raster::DrawProbe>,
        view: Option<Result<ViewRecord, String>>,
    ) {
        if let Some(probe) = probe {
            let record = DrawRecord {
                draw: self.debug.draws,
                mode,
                count,
                program: self.current_program,
                framebuffer,
                vertex: self.stage_info(glsl::Stage::Vertex, vs_user, vs),
                geometry: gs.map(|g| self.stage_info(glsl::Stage::Geometry, true, g)),
                fragment: self.stage_info(glsl::Stage::Fragment, fs_user, fs),
                probe,
                view,
            };
            self.debug.records.push(record);
        }
        if self.debug.request.is_some() {
            self.debug.draws += 1;
        }
    }
}
