//! The draw calls: glDrawArrays, glMultiDrawArrays, glDrawElements,
//! glDrawRangeElements, their instanced and base-vertex forms (GL 3.3
//! §2.8.2-2.8.3), primitive restart (§2.8.1, the `restart` module), the
//! glBegin/glEnd vertices, and glClear.
//!
//! A draw checks its arguments and the draw framebuffer's completeness,
//! then puts the stages together: the kernels and their uniform words
//! ([`crate::kernels`]; the fixed-function fragment stage runs as
//! [`crate::ff_fragment`] where it can), the vertex fetch
//! ([`crate::fetch`]), the GL state as [`raster::PipelineState`]
//! ([`crate::pipeline_state`]), the bound textures
//! ([`crate::texture_units`]) and the render target
//! ([`crate::render_target`]), and runs [`raster::draw_on`], or, for a
//! draw into the default framebuffer whose fragment stage cannot fail,
//! pushes it on the context's [`raster::DrawQueue`] (`draw_waits` says
//! when). Debug probes and views ([`crate::debug`]) replay the same draw.
//!
//! A draw the executor stops (loop budget) keeps the fragments already
//! written; the message is kept for [`Context::take_draw_error`] (GL has
//! no error code for it).

use crate::enums::*;
use crate::fetch::{Fetcher, InstanceBatch};
use crate::pipeline_state::{raster_mode, rect};
use crate::vertex::{ArrayData, ImmVertex};
use crate::Context;
use raster::PrimitiveIds;
use std::sync::Arc;

impl Context {
    /// Takes the message of the last draw that stopped early.
    pub fn take_draw_error(&mut self) -> Option<String> {
        self.cache.error.take()
    }

    /// Checks shared by the draw calls (GL 2.1 §2.8).
    fn check_draw(&mut self, mode: u32, count: i32, instances: i32) -> bool {
        if self.reject_in_begin() {
            return false;
        }
        // The core profile removes quads and polygons (GL 3.3 core
        // appendix E.2.2); the adjacency modes come with geometry shaders.
        let adjacency = (GL_LINES_ADJACENCY..=GL_TRIANGLE_STRIP_ADJACENCY).contains(&mode);
        let known = match mode {
            GL_QUADS | GL_QUAD_STRIP | GL_POLYGON => !self.is_core(),
            _ if adjacency => self.has_geometry_shaders(),
            m => m <= GL_TRIANGLE_FAN,
        };
        if !known {
            self.set_error(GL_INVALID_ENUM);
            return false;
        }
        if !self.geometry_takes(mode) {
            self.set_error(GL_INVALID_OPERATION);
            return false;
        }
        if count < 0 {
            self.set_error(GL_INVALID_VALUE);
            return false;
        }
        if count > crate::MAX_DRAW_VERTICES
            || count as i64 * instances as i64 > crate::MAX_DRAW_INVOCATIONS
        {
            self.set_error(GL_OUT_OF_MEMORY);
            return false;
        }
        if !self.feedback_allows(mode) {
            return false;
        }
        // Core draws need a vertex array object (the default one is
        // removed: GL 3.3 core appendix E.2.2).
        if self.is_core() && self.vertex_array_binding() == 0 {
            self.set_error(GL_INVALID_OPERATION);
            return false;
        }
        if !self.check_fbo_complete() {
            return false;
        }
        // A pipeline that cannot run is GL_INVALID_OPERATION
        // (GL_ARB_separate_shader_objects, "Validation").
        if !self.pipeline_draw_check() {
            return false;
        }
        // Without a program the results of a core draw are undefined
        // (§2.11, §3.9), not an error: there is no fixed-function stage
        // to run, so nothing is drawn (as Mesa does).
        !self.is_core() || self.any_stage_program()
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
        self.draw_arrays_instanced(mode, first, count, 1);
    }

    /// glDrawArraysInstanced (GL 3.3 §2.8.2): `instances` draws of the
    /// arrays, instance `i` with `gl_InstanceID` = i and the instanced
    /// arrays at element i / divisor.
    pub fn draw_arrays_instanced(&mut self, mode: u32, first: i32, count: i32, instances: i32) {
        if first < 0 || instances < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if !self.check_draw(mode, count, instances) {
            return;
        }
        let count = count as u32;
        let indices: Vec<u32> = (0..count).map(|i| i.saturating_add(first as u32)).collect();
        self.draw_list(mode, &indices, None, 0, instances as u32);
    }

    /// glMultiDrawArrays: one glDrawArrays per pair (a negative count is
    /// GL_INVALID_VALUE before anything is drawn).
    pub fn multi_draw_arrays(&mut self, mode: u32, first: &[i32], count: &[i32]) {
        if count.iter().chain(first).any(|&c| c < 0) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        for (f, c) in first.iter().zip(count) {
            self.draw_arrays(mode, *f, *c);
        }
    }

    /// glDrawElements: `indices` is an offset into the bound element
    /// buffer or client index data.
    pub fn draw_elements(&mut self, mode: u32, count: i32, ty: u32, indices: ArrayData) {
        self.draw_elements_instanced_base_vertex(mode, count, ty, indices, 1, 0);
    }

    /// glDrawRangeElements: the range is a hint; indices outside it are
    /// drawn as any others.
    pub fn draw_range_elements(
        &mut self,
        mode: u32,
        start: u32,
        end: u32,
        count: i32,
        ty: u32,
        indices: ArrayData,
    ) {
        self.draw_range_elements_base_vertex(mode, start, end, count, ty, indices, 0);
    }

    /// glDrawElementsBaseVertex (GL 3.3 §2.8.3): `basevertex` is added
    /// to every index (after the primitive-restart comparison).
    pub fn draw_elements_base_vertex(
        &mut self,
        mode: u32,
        count: i32,
        ty: u32,
        indices: ArrayData,
        basevertex: i32,
    ) {
        self.draw_elements_instanced_base_vertex(mode, count, ty, indices, 1, basevertex);
    }

    /// glDrawRangeElementsBaseVertex.
    #[allow(clippy::too_many_arguments)]
    pub fn draw_range_elements_base_vertex(
        &mut self,
        mode: u32,
        start: u32,
        end: u32,
        count: i32,
        ty: u32,
        indices: ArrayData,
        basevertex: i32,
    ) {
        if end < start {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        self.draw_elements_instanced_base_vertex(mode, count, ty, indices, 1, basevertex);
    }

    /// glDrawElementsInstanced.
    pub fn draw_elements_instanced(
        &mut self,
        mode: u32,
        count: i32,
        ty: u32,
        indices: ArrayData,
        instances: i32,
    ) {
        self.draw_elements_instanced_base_vertex(mode, count, ty, indices, instances, 0);
    }

    /// glDrawElementsInstancedBaseVertex: the element draws' common
    /// path. With primitive restart on (GL 3.3 §2.8.1), an index equal to
    /// the restart index ends the primitive and starts a new one
    /// (the `restart` module).
    pub fn draw_elements_instanced_base_vertex(
        &mut self,
        mode: u32,
        count: i32,
        ty: u32,
        indices: ArrayData,
        instances: i32,
        basevertex: i32,
    ) {
        if self.reject_in_begin() {
            return;
        }
        if mode > GL_POLYGON
            || !matches!(ty, GL_UNSIGNED_BYTE | GL_UNSIGNED_SHORT | GL_UNSIGNED_INT)
        {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if instances < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if !self.check_draw(mode, count, instances) {
            return;
        }
        let Some(idx) = self.read_indices(count as usize, ty, &indices) else {
            return;
        };
        let restart = self.primitive_restart();
        self.draw_list(mode, idx.as_slice(), restart, basevertex, instances as u32);
    }

    /// Draws the element indices `list` (`restart`: the restart index
    /// when restart is on; `basevertex` added after the comparison)
    /// `instances` times. Instances are drawn in batches, each batch as
    /// one draw whose vertices number (instance, element) pairs
    /// ([`InstanceBatch`]) and whose primitives are those of each
    /// instance in turn (strips and loops as their independent
    /// primitives, [`crate::restart`]): the primitives, their order and
    /// their vertices are those of one draw per instance.
    fn draw_list(
        &mut self,
        mode: u32,
        list: &[u32],
        restart: Option<u32>,
        basevertex: i32,
        instances: u32,
    ) {
        let restart = restart.filter(|r| list.contains(r));
        let base = basevertex as u32;
        let vertices = || {
            list.iter()
                .filter(move |&&i| Some(i) != restart)
                .map(move |&i| i.wrapping_add(base))
        };
        // (The index range only for several instances: a single draw
        // does not pay the passes.)
        let range = match instances {
            0 => return,
            1 => None,
            _ => match (vertices().min(), vertices().max()) {
                (Some(lo), Some(hi)) => Some((lo, hi)),
                _ => return,
            },
        };
        let per_instance = list.len() as u64 + 1;
        // Virtual vertex numbers stay below the separator (u32::MAX); a
        // batch's list stays below 2^22 indices.
        let batch = range.map_or(0, |(lo, hi)| {
            ((u32::MAX as u64 - 1) / ((hi - lo) as u64 + 1))
                .min((1 << 22) / per_instance)
                .min(instances as u64) as u32
        });
        let whole = PrimitiveIds::default();
        let Some((lo, hi)) = range.filter(|_| batch >= 2) else {
            for instance in 0..instances {
                let one = InstanceBatch::one(instance);
                match restart {
                    Some(r) => {
                        // A restart leaves the primitive ID counter alone.
                        let mut first = 0u32;
                        for (m, l) in crate::restart::split(mode, list, r, self.provoking_first()) {
                            let ids = PrimitiveIds { first, ..whole };
                            first = first.wrapping_add(primitives(m, l.len()));
                            self.run_draw(m, &with_base(l, basevertex), None, one, ids);
                        }
                    }
                    None if basevertex != 0 => self.run_draw(
                        mode,
                        &with_base(list.to_vec(), basevertex),
                        None,
                        one,
                        whole,
                    ),
                    None => self.run_draw(mode, list, None, one, whole),
                }
            }
            return;
        };
        // The draws one instance makes (as `split` makes them) and their
        // primitives: a batch's draws are these, instance after instance
        // (one draw when `split` joins the pieces: the primitive IDs
        // restart every instance's worth).
        let pieces: Vec<u32> = match restart {
            Some(r) => crate::restart::split(mode, list, r, self.provoking_first())
                .iter()
                .map(|(m, l)| primitives(*m, l.len()))
                .collect(),
            None => vec![primitives(mode, list.len())],
        };
        let per_instance = pieces.iter().fold(0u32, |a, &p| a.wrapping_add(p));
        const SEPARATOR: u32 = u32::MAX;
        let stride = hi - lo + 1;
        let mut first = 0u32;
        while first < instances {
            let n = batch.min(instances - first);
            let mut combined = Vec::with_capacity(n as usize * per_instance as usize);
            for k in 0..n {
                if k > 0 {
                    combined.push(SEPARATOR);
                }
                combined.extend(list.iter().map(|&i| {
                    if Some(i) == restart {
                        SEPARATOR
                    } else {
                        k * stride + i.wrapping_add(base).wrapping_sub(lo)
                    }
                }));
            }
            let b = InstanceBatch { first, lo, stride };
            let draws = crate::restart::split(mode, &combined, SEPARATOR, self.provoking_first());
            let joined = draws.len() == 1 && n > 1;
            for (j, (m, l)) in draws.into_iter().enumerate() {
                let ids = if joined {
                    PrimitiveIds {
                        first: 0,
                        period: per_instance.max(1),
                    }
                } else {
                    let k = j % pieces.len().max(1);
                    PrimitiveIds {
                        first: pieces[..k].iter().fold(0u32, |a, &p| a.wrapping_add(p)),
                        ..whole
                    }
                };
                self.run_draw(m, &l, None, b, ids);
            }
            first += n;
        }
    }

    /// glMultiDrawElements: one glDrawElements per count (a negative count
    /// is GL_INVALID_VALUE before anything is drawn).
    pub fn multi_draw_elements(
        &mut self,
        mode: u32,
        count: &[i32],
        ty: u32,
        indices: &[ArrayData],
    ) {
        let zeros = vec![0; count.len()];
        self.multi_draw_elements_base_vertex(mode, count, ty, indices, &zeros);
    }

    /// glMultiDrawElementsBaseVertex.
    pub fn multi_draw_elements_base_vertex(
        &mut self,
        mode: u32,
        count: &[i32],
        ty: u32,
        indices: &[ArrayData],
        basevertex: &[i32],
    ) {
        if count.iter().any(|&c| c < 0) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        for ((c, i), b) in count.iter().zip(indices).zip(basevertex) {
            self.draw_elements_base_vertex(mode, *c, ty, i.clone(), *b);
        }
    }

    /// The primitive restart index when restart is enabled.
    pub fn primitive_restart(&self) -> Option<u32> {
        self.st
            .is_on(GL_PRIMITIVE_RESTART)
            .then_some(self.va.restart_index)
    }

    /// glPrimitiveRestartIndex.
    pub fn primitive_restart_index(&mut self, index: u32) {
        if self.reject_in_begin() {
            return;
        }
        self.va.restart_index = index;
    }

    /// Draws the vertices recorded between glBegin and glEnd.
    pub(crate) fn draw_immediate(&mut self, mode: u32, verts: &[ImmVertex]) {
        if !self.check_fbo_complete() {
            return;
        }
        let indices: Vec<u32> = (0..verts.len() as u32).collect();
        let ids = PrimitiveIds::default();
        self.run_draw(mode, &indices, Some(verts), InstanceBatch::one(0), ids);
    }

    /// The vertex stage, and the geometry stage when there is one, of a
    /// draw, alone (what transform feedback captures and the primitive
    /// queries count): the GL list mode of the primitives (the draw's
    /// `mode` without a geometry stage), per position in their list the
    /// vertex number, the vertices' outputs and the values per vertex.
    #[allow(clippy::type_complexity)]
    fn shade_before_rasterization(
        &mut self,
        (vs, vs_user, gs): (
            &std::sync::Arc<exec::Kernel>,
            bool,
            Option<&std::sync::Arc<exec::Kernel>>,
        ),
        mode: u32,
        indices: &[u32],
        (immediate, batch): (Option<&[ImmVertex]>, InstanceBatch),
        ids: PrimitiveIds,
    ) -> Result<(u32, Vec<u32>, Vec<f32>, usize), String> {
        let words = self.uniform_words(vs, vs_user);
        let mut units = self.texture_units();
        // The stages run again to rasterize, which writes their memory;
        // this pass reads a copy unless nothing is rasterized.
        let stages: Vec<&exec::Kernel> = [Some(&**vs), gs.map(|g| &**g)]
            .into_iter()
            .flatten()
            .collect();
        let mem = self.storage_memory(&stages);
        let last_pass = self.st.is_on(GL_RASTERIZER_DISCARD);
        units.memory = match &mem {
            Some(m) if last_pass => Some(m.clone()),
            Some(m) => Some(Arc::new(m.snapshot())),
            None => None,
        }
        .map(|m| m as Arc<dyn exec::Memory + Send>);
        let inline = raster::Workers::inline();
        let serial = stages.iter().any(|k| k.writes_memory());
        let Some(gs) = gs else {
            let fetch = Fetcher::new(self, vs, immediate, batch);
            let r = raster::shade_vertices(
                if serial { &inline } else { &self.workers },
                &**vs,
                &words,
                &units,
                indices,
                &fetch,
                true,
            )
            .map(|(vertex_of, outputs, stride)| (mode, vertex_of, outputs, stride))
            .map_err(|e| e.to_string());
            if let (Some(m), true) = (&mem, last_pass) {
                self.store_storage_memory(m);
            }
            return r;
        };
        // The geometry stage reads the provoking-vertex convention,
        // colour clamping and primitive IDs from the pipeline state.
        let target = self.draw_target().ok_or("no draw framebuffer")?;
        let mut state = self.pipeline_state(&target);
        self.store_target(target);
        state.primitive_ids = ids;
        let gs_words = self.uniform_words(gs, true);
        let fetch = Fetcher::new(self, vs, immediate, batch);
        let r = raster::shade_geometry(
            if serial { &inline } else { &self.workers },
            (&**vs, &words),
            (&**gs, &gs_words),
            &units,
            indices,
            &fetch,
            raster_mode(mode),
            &state,
        )
        .map(|(m, vertex_of, outputs, stride)| (gl_list_mode(m), vertex_of, outputs, stride))
        .map_err(|e| e.to_string());
        if let (Some(m), true) = (&mem, last_pass) {
            self.store_storage_memory(m);
        }
        r
    }

    /// Draws `indices`, vertices of the instances `batch`, its primitives
    /// numbered `ids` for gl_PrimitiveID.
    fn run_draw(
        &mut self,
        mode: u32,
        indices: &[u32],
        immediate: Option<&[ImmVertex]>,
        batch: InstanceBatch,
        ids: PrimitiveIds,
    ) {
        // Conditional rendering discards the whole command (GL 3.3 §2.15).
        if indices.is_empty() || self.render_discarded() {
            return;
        }
        let crate::kernels::DrawKernels {
            vs,
            vs_user,
            gs,
            fs,
            ff_shape,
        } = match self.draw_kernels() {
            Ok(k) => k,
            Err(e) => {
                self.cache.error = Some(e);
                return;
            }
        };
        // GL_PRIMITIVES_GENERATED counts what the last stage before
        // rasterization makes: with a geometry stage, its primitives
        // (GL 3.3 §2.16).
        let count_emitted = gs.is_some() && self.queries.active[2] != 0;
        if gs.is_none() {
            self.count_primitives(mode, indices.len());
        }
        let discard = self.st.is_on(GL_RASTERIZER_DISCARD);
        if self.feedback_active() || count_emitted {
            let stages = (&vs, vs_user, gs.as_ref());
            let shaded =
                self.shade_before_rasterization(stages, mode, indices, (immediate, batch), ids);
            match shaded {
                Ok((mode, vertex_of, outputs, stride)) => {
                    if count_emitted {
                        self.count_primitives(mode, vertex_of.len());
                    }
                    if self.feedback_active() {
                        self.capture_feedback(mode, (&vertex_of, &outputs, stride));
                    }
                }
                Err(e) => {
                    self.cache.error = Some(e);
                    return;
                }
            }
        }
        // GL_RASTERIZER_DISCARD: the primitives end before rasterization
        // (after transform feedback).
        if discard {
            return;
        }
        let fs_user = ff_shape.is_none();
        // The fixed-function fragment stage runs without the engine where
        // it can (the same bits: `ff_fragment`).
        let shader: Arc<dyn raster::ShaderStage + Send + Sync> = match &ff_shape {
            Some(shape) => Arc::new(crate::ff_fragment::FixedFragment::new(fs.clone(), shape)),
            None => fs.clone(),
        };
        let fs_stage = &*shader;
        let vs_words = self.uniform_words(&vs, vs_user);
        let gs_words = gs.as_ref().map(|g| self.uniform_words(g, true));
        let gs_stage = gs.as_deref().zip(gs_words.as_deref());
        let fs_words = self.uniform_words(&fs, fs_user);
        let mut units = self.texture_units();
        // Storage blocks: the stages' memory, written back after the draw;
        // a draw that writes memory shades on one thread (`storage`).
        let stages: Vec<&exec::Kernel> = [Some(&*vs), gs.as_deref(), fs_user.then_some(&*fs)]
            .into_iter()
            .flatten()
            .collect();
        let mem = self.storage_memory(&stages);
        let serial = stages.iter().any(|k| k.writes_memory());
        units.memory = mem.clone().map(|m| m as Arc<dyn exec::Memory + Send>);
        if self.draw_waits(gs.is_some(), mem.is_some()) {
            let mut target = self.default_target();
            let mut state = self.pipeline_state(&target);
            state.primitive_ids = ids;
            let mut queue = std::mem::take(&mut self.queued);
            let fetch = Fetcher::new(self, &vs, immediate, batch);
            let fragments = raster::QueuedFragments {
                shader: shader.clone(),
                uniforms: fs_words,
                textures: units,
            };
            let r = queue.push(
                &self.workers,
                &mut target.fb,
                &state,
                (&*vs, &vs_words),
                None,
                fragments,
                (raster_mode(mode), indices),
                &fetch,
            );
            self.queued = queue;
            if let Err(e) = r {
                self.cache.error = Some(e.to_string());
            }
            self.store_target(target);
            return;
        }
        let Some(mut target) = self.draw_target() else {
            return;
        };
        let mut state = self.pipeline_state(&target);
        state.primitive_ids = ids;
        // A geometry stage writing gl_Layer into layered attachments
        // draws layer by layer (`layered`).
        let layered = gs_stage.and_then(|(g, _)| {
            let slot = g.interface().output("gl_Layer").filter(|s| s.written)?;
            Some((slot.offset, self.layer_count()?))
        });
        // The debugger replays the draw on its target; a layered one on
        // the layer asked for (that layer's images and primitives).
        let wants = self.debug.wants();
        let select = layered.map(|(component, _)| raster::LayerSelect {
            component,
            layer: self.debug.layer(),
        });
        let layer_target = match (wants, layered, select) {
            (Some(_), Some((_, layers)), Some(s)) if s.layer < layers => {
                self.draw_layer = s.layer;
                let t = self.draw_target();
                self.draw_layer = 0;
                t
            }
            _ => None,
        };
        let fetch = Fetcher::new(self, &vs, immediate, batch);
        // The debugger's replay runs the stages once more, on a copy of
        // the memory.
        let mut replay_units = units.clone();
        replay_units.memory = mem
            .as_ref()
            .map(|m| Arc::new(m.snapshot()) as Arc<dyn exec::Memory + Send>);
        let replay = raster::Replay {
            state: &state,
            vs: &vs,
            vs_uniforms: &vs_words,
            gs: gs_stage,
            fs: &fs,
            fs_uniforms: &fs_words,
            mode: raster_mode(mode),
            indices,
            fetch: &fetch,
            textures: &replay_units,
            layer: select,
        };
        let (probe, view) = match (wants, layered, &layer_target) {
            (None, ..) => (None, None),
            (Some(req), None, _) => self.debug.replay(&target.fb, &replay, req, &fs),
            (Some(req), Some(_), Some(t)) => self.debug.replay(&t.fb, &replay, req, &fs),
            (Some(req), Some((_, layers)), None) => {
                self.debug
                    .missing_layer(req, select.map_or(0, |s| s.layer), layers)
            }
        };
        if let (Some((gs_kernel, gs_words)), Some(layer)) = (gs_stage, layered) {
            self.record_draw(
                (mode, indices.len(), target.name),
                (vs.clone(), vs_user),
                gs.clone(),
                (fs.clone(), fs_user),
                probe,
                view,
            );
            self.store_target(target);
            let stages = crate::layered::LayeredStages {
                vs: (&vs, &vs_words),
                gs: (gs_kernel, gs_words),
                fs: (fs_stage, &fs_words),
            };
            if let Err(e) = self.draw_layered(
                stages,
                (mode, indices),
                (immediate, batch),
                &state,
                &units,
                layer,
            ) {
                self.cache.error = Some(e);
            }
            if let Some(m) = &mem {
                self.store_storage_memory(m);
            }
            return;
        }
        let samples_before = target.fb.samples_passed;
        let inline = raster::Workers::inline();
        let r = raster::draw_stages(
            if serial { &inline } else { &self.workers },
            &mut target.fb,
            &state,
            (&*vs, &vs_words),
            gs_stage.map(|(g, w)| (g as &dyn raster::ShaderStage, w)),
            (fs_stage, &fs_words),
            raster_mode(mode),
            indices,
            &fetch,
            &units,
        );
        if let Err(e) = r {
            self.cache.error = Some(e.to_string());
        }
        if let Some(m) = &mem {
            self.store_storage_memory(m);
        }
        let samples = target.fb.samples_passed.wrapping_sub(samples_before);
        self.count_samples(samples);
        self.record_draw(
            (mode, indices.len(), target.name),
            (vs.clone(), vs_user),
            gs.clone(),
            (fs.clone(), fs_user),
            probe,
            view,
        );
        self.store_target(target);
    }

    /// Whether a draw may wait in the draw queue ([`raster::DrawQueue`],
    /// which runs its fragment stage at the next flush): one into the
    /// default framebuffer, with no geometry stage (`has_gs`) and no
    /// storage blocks (`has_memory`, read when the draw runs), while no
    /// occlusion query counts its samples and the debugger watches no
    /// draw. The queue itself draws at once what may fail.
    fn draw_waits(&self, has_gs: bool, has_memory: bool) -> bool {
        self.objects.draw_framebuffer == 0
            && !has_gs
            && !has_memory
            && self.queries.active[..2] == [0, 0]
            && self.debug.request.is_none()
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
        // Clears are rendering commands: conditional rendering and
        // rasterizer discard skip them (as Mesa does for the latter).
        if !self.check_fbo_complete()
            || self.render_discarded()
            || self.st.is_on(GL_RASTERIZER_DISCARD)
        {
            return;
        }
        self.on_every_layer(|ctx| ctx.clear_layer(mask));
    }

    /// glClear of the draw framebuffer's layer `draw_layer`.
    fn clear_layer(&mut self, mask: u32) {
        let Some(mut t) = self.draw_target() else {
            return;
        };
        let scissor = self
            .st
            .is_on(GL_SCISSOR_TEST)
            .then(|| rect(self.st.scissor));
        if mask & GL_COLOR_BUFFER_BIT != 0 {
            // Each draw buffer with its own mask (glColorMaski).
            let color = self.st.clear_color;
            for (i, buf) in t.draw_buffers.iter().enumerate() {
                let Some(buf) = *buf else { continue };
                let write = self.st.color_masks[i % crate::MAX_DRAW_BUFFERS];
                t.fb.clear_color_on(&self.workers, &[buf], color, write, scissor);
            }
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

/// The GL mode of the point, line and triangle lists a geometry stage
/// emits.
fn gl_list_mode(mode: raster::Mode) -> u32 {
    match mode {
        raster::Mode::Points => GL_POINTS,
        raster::Mode::Lines => GL_LINES,
        _ => GL_TRIANGLES,
    }
}

/// `list` with `basevertex` added to every index (wrapping: an index
/// below 0 reads past the arrays, which gives the defaults).
/// The primitives `vertices` vertices of GL mode `mode` make.
fn primitives(mode: u32, vertices: usize) -> u32 {
    raster_mode(mode).primitives(vertices) as u32
}

fn with_base(mut list: Vec<u32>, basevertex: i32) -> Vec<u32> {
    if basevertex != 0 {
        for i in &mut list {
            *i = i.wrapping_add(basevertex as u32);
        }
    }
    list
}
