//! Debugging draws: the pixel probe of `raster` on every draw of a context.
//!
//! [`Context::set_debug`] names a window pixel (and optionally one draw and
//! a `debugPrintfEXT` rectangle); every later draw that matches is replayed
//! with [`raster::probe_draw`] before it runs, and its [`DrawRecord`] —
//! the probe plus what is needed to explain it (the kernels with their
//! variable tables, the compiled shader objects with their source text) —
//! waits in the context until [`Context::take_debug_records`]. With no
//! request set, a draw pays one `Option` check.

use crate::Context;
use std::sync::Arc;

/// What to debug.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DebugRequest {
    /// Window pixel of the draw framebuffer.
    pub pixel: (u32, u32),
    /// Only this draw (0-based count of draw calls since the request was
    /// set); all draws when `None`.
    pub draw: Option<usize>,
    /// Collect `debugPrintfEXT` output of this rectangle
    /// `[x0, x1) × [y0, y1)` too.
    pub print_rect: Option<(u32, u32, u32, u32)>,
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
    pub fragment: StageInfo,
    /// What happened at the pixel, or why the replay failed.
    pub probe: Result<raster::DrawProbe, String>,
}

#[derive(Default)]
pub(crate) struct DebugSession {
    pub request: Option<DebugRequest>,
    pub draws: usize,
    pub records: Vec<DrawRecord>,
}

impl DebugSession {
    /// The probe request for the next draw, if it is to be debugged.
    pub fn wants(&self) -> Option<raster::ProbeRequest> {
        let r = self.request?;
        if r.draw.is_some_and(|d| d != self.draws) {
            return None;
        }
        Some(raster::ProbeRequest {
            pixel: r.pixel,
            print_rect: r.print_rect,
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
        self.programs
            .get(&self.current_program)
            .and_then(|p| p.exe.as_ref())
            .map(|e| {
                e.shaders
                    .iter()
                    .filter(|s| s.stage == stage)
                    .cloned()
                    .collect()
            })
            .unwrap_or_default()
    }
}
