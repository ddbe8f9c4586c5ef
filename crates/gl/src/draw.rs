//! The draw calls: glDrawArrays, glMultiDrawArrays, glDrawElements,
//! glDrawRangeElements, the glBegin/glEnd vertices, and glClear.
//!
//! A draw checks its arguments and the draw framebuffer's completeness,
//! then puts the stages together: the kernels and their uniform words
//! ([`crate::kernels`]; the fixed-function fragment stage runs as
//! [`crate::ff_fragment`] where it can), the vertex fetch
//! ([`crate::fetch`]), the GL state as [`raster::PipelineState`]
//! ([`crate::pipeline_state`]), the bound textures
//! ([`crate::texture_units`]) and the render target
//! ([`crate::render_target`]), and runs [`raster::draw_on`]. Debug probes
//! and views ([`crate::debug`]) replay the same draw.
//!
//! A draw the executor stops (loop budget) keeps the fragments already
//! written; the message is kept for [`Context::take_draw_error`] (GL has
//! no error code for it).

use crate::enums::*;
use crate::fetch::Fetcher;
use crate::pipeline_state::{raster_mode, rect};
use crate::vertex::{ArrayData, ImmVertex};
use crate::Context;

impl Context {
    /// Takes the message of the last draw that stopped early.
    pub fn take_draw_error(&mut self) -> Option<String> {
        self.cache.error.take()
    }

    /// Checks shared by the draw calls (GL 2.1 §2.8).
    fn check_draw(&mut self, mode: u32, count: i32) -> bool {
        if self.reject_in_begin() {
            return false;
        }
        // The core profile removes quads and polygons (GL 3.3 core
        // appendix E.2.2).
        let last_mode = if self.is_core() {
            GL_TRIANGLE_FAN
        } else {
            GL_POLYGON
        };
        if mode > last_mode {
            self.set_error(GL_INVALID_ENUM);
            return false;
        }
        if count < 0 {
            self.set_error(GL_INVALID_VALUE);
            return false;
        }
        // Core draws need a program: there is no fixed-function vertex
        // stage to fall back on.
        if self.is_core() && self.current_program == 0 {
            self.set_error(GL_INVALID_OPERATION);
            return false;
        }
        self.check_fbo_complete()
    }

    pub(crate) fn check_fbo_complete(&mut self) -> bool {
        let fb = self.objects.draw_framebuffer;
        if self.framebuffer_status(fb) != GL_FRAMEBUFFER_COMPLETE {
            self.set_error(GL_INVALID_FRAMEBUFFER_OPERATION);
            return false;
        }
        true
    }

    /// glDrawArrays.
    pub fn draw_arrays(&mut self, mode: u32, first: i32, count: i32) {
        if first < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if !self.check_draw(mode, count) {
            return;
        }
        let count = count.min(1 << 24) as u32;
        let indices: Vec<u32> = (0..count).map(|i| i.saturating_add(first as u32)).collect();
        self.run_draw(mode, &indices, None);
    }

    /// glMultiDrawArrays.
    pub fn multi_draw_arrays(&mut self, mode: u32, first: &[i32], count: &[i32]) {
        for (f, c) in first.iter().zip(count) {
            self.draw_arrays(mode, *f, *c);
        }
    }

    /// glDrawElements: `indices` is an offset into the bound element
    /// buffer or client index data.
    pub fn draw_elements(&mut self, mode: u32, count: i32, ty: u32, indices: ArrayData) {
        if !matches!(ty, GL_UNSIGNED_BYTE | GL_UNSIGNED_SHORT | GL_UNSIGNED_INT) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if !self.check_draw(mode, count) {
            return;
        }
        let Some(idx) = self.read_indices(count as usize, ty, &indices) else {
            return;
        };
        self.run_draw(mode, idx.as_slice(), None);
    }

    /// glDrawRangeElements.
    pub fn draw_range_elements(
        &mut self,
        mode: u32,
        start: u32,
        end: u32,
        count: i32,
        ty: u32,
        indices: ArrayData,
    ) {
        if end < start {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        self.draw_elements(mode, count, ty, indices);
    }

    /// Draws the vertices recorded between glBegin and glEnd.
    pub(crate) fn draw_immediate(&mut self, mode: u32, verts: &[ImmVertex]) {
        if !self.check_fbo_complete() {
            return;
        }
        let indices: Vec<u32> = (0..verts.len() as u32).collect();
        self.run_draw(mode, &indices, Some(verts));
    }

    fn run_draw(&mut self, mode: u32, indices: &[u32], immediate: Option<&[ImmVertex]>) {
        if indices.is_empty() {
            return;
        }
        let (vs, vs_user, fs, ff_shape) = match self.draw_kernels() {
            Ok(k) => k,
            Err(e) => {
                self.cache.error = Some(e);
                return;
            }
        };
        let fs_user = ff_shape.is_none();
        // The fixed-function fragment stage runs without the engine where
        // it can (the same bits: `ff_fragment`).
        let ff = ff_shape
            .as_ref()
            .map(|shape| crate::ff_fragment::FixedFragment::new(&fs, shape));
        let fs_stage: &dyn raster::ShaderStage = match &ff {
            Some(ff) => ff,
            None => &*fs,
        };
        let vs_words = self.uniform_words(&vs, vs_user);
        let fs_words = self.uniform_words(&fs, fs_user);
        let units = self.texture_units();
        let Some(mut target) = self.draw_target() else {
            return;
        };
        let state = self.pipeline_state(target.draw_buffers);
        let fetch = Fetcher::new(self, self.input_sources(&vs), immediate);
        let replay = raster::Replay {
            state: &state,
            vs: &vs,
            vs_uniforms: &vs_words,
            fs: &fs,
            fs_uniforms: &fs_words,
            mode: raster_mode(mode),
            indices,
            fetch: &fetch,
            textures: &units,
        };
        let probe = self
            .debug
            .wants()
            .map(|req| raster::probe_draw(&target.fb, &replay, req));
        let view = self.debug.view().map(|name| {
            let (v, kinds) = crate::debug::resolve_view(&fs, name)?;
            let image = raster::view_draw(&target.fb, &replay, v).map_err(|e| e.to_string())?;
            Ok(crate::debug::ViewRecord {
                name: name.to_string(),
                kinds,
                image,
            })
        });
        let samples_before = target.fb.samples_passed;
        let r = raster::draw_on(
            &self.workers,
            &mut target.fb,
            &state,
            &vs,
            &vs_words,
            fs_stage,
            &fs_words,
            raster_mode(mode),
            indices,
            &fetch,
            &units,
        );
        if let Err(e) = r {
            self.cache.error = Some(e.to_string());
        }
        let samples = target.fb.samples_passed.wrapping_sub(samples_before);
        self.count_samples(samples);
        if let Some(probe) = probe {
            let record = crate::debug::DrawRecord {
                draw: self.debug.draws,
                mode,
                count: indices.len(),
                program: self.current_program,
                framebuffer: target.name,
                vertex: self.stage_info(glsl::Stage::Vertex, vs_user, vs),
                fragment: self.stage_info(glsl::Stage::Fragment, fs_user, fs),
                probe,
                view,
            };
            self.debug.records.push(record);
        }
        if self.debug.request.is_some() {
            self.debug.draws += 1;
        }
        self.store_target(target);
    }

    /// glClear.
    pub fn clear(&mut self, mask: u32) {
        if self.reject_in_begin() {
            return;
        }
        let all =
            GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
        if mask & !all != 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if !self.check_fbo_complete() {
            return;
        }
        let Some(mut t) = self.draw_target() else {
            return;
        };
        let scissor = self
            .st
            .is_on(GL_SCISSOR_TEST)
            .then(|| rect(self.st.scissor));
        if mask & GL_COLOR_BUFFER_BIT != 0 {
            let mut bufs: Vec<usize> = t.draw_buffers.iter().flatten().copied().collect();
            bufs.dedup();
            let (color, write) = (self.st.clear_color, self.st.color_mask);
            t.fb.clear_color_on(&self.workers, &bufs, color, write, scissor);
        }
        if mask & GL_DEPTH_BUFFER_BIT != 0 {
            let (depth, write) = (self.st.clear_depth, self.st.depth_mask);
            t.fb.clear_depth_on(&self.workers, depth, write, scissor);
        }
        if mask & GL_STENCIL_BUFFER_BIT != 0 {
            t.fb.clear_stencil_on(
                &self.workers,
                self.st.clear_stencil,
                self.st.stencil[0].write_mask,
                scissor,
            );
        }
        self.store_target(t);
    }
}
