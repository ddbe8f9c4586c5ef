//! Layered rendering (GL 3.3 §2.12.4, §4.4.7): a geometry shader writing
//! `gl_Layer` into a framebuffer whose attachments are layered
//! (glFramebufferTexture of a 3D, array or cube map texture) sends each
//! primitive it emits to the layer its provoking vertex names.
//!
//! The vertex and geometry stages run once for the draw
//! ([`raster::shade_geometry`]); the emitted primitives are grouped by
//! layer, in draw order within each, and each layer's are drawn into
//! that layer's images ([`raster::draw_emitted`], the render target
//! assembled for the layer: `Context::draw_layer`). Primitives naming a
//! layer the framebuffer does not have are not drawn (GL leaves the
//! result undefined).

use crate::enums::*;
use crate::objects::Attachment;
use crate::Context;
use std::collections::BTreeMap;

/// The stages of a layered draw: (stage, uniform words) of the vertex,
/// geometry and fragment stages.
pub(crate) struct LayeredStages<'a> {
    pub vs: (&'a exec::Kernel, &'a [u32]),
    pub gs: (&'a exec::Kernel, &'a [u32]),
    pub fs: (&'a dyn raster::ShaderStage, &'a [u32]),
}

impl Context {
    /// Runs `f` once per layer of a layered draw framebuffer, with
    /// `draw_layer` set to it, or once: clears clear every layer (GL 3.3
    /// §4.4.7).
    pub(crate) fn on_every_layer(&mut self, mut f: impl FnMut(&mut Context)) {
        let layers = self.layer_count().unwrap_or(1).max(1);
        for layer in 0..layers {
            self.draw_layer = layer;
            f(self);
        }
        self.draw_layer = 0;
    }

    /// The number of layers of the draw framebuffer's layered
    /// attachments (the fewest of them), or `None` when no attachment is
    /// layered (then a geometry stage's gl_Layer is ignored).
    pub(crate) fn layer_count(&self) -> Option<i32> {
        let f = self
            .objects
            .framebuffers
            .get(&self.objects.draw_framebuffer)?;
        let all = f.color.iter().flatten().chain(&f.depth).chain(&f.stencil);
        all.filter_map(|a| match *a {
            Attachment::Texture {
                texture,
                level,
                layered: true,
                ..
            } => {
                let t = self.objects.textures.get(&texture)?;
                let img = t.image(0, level.max(0) as usize)?;
                Some(match t.target {
                    GL_TEXTURE_CUBE_MAP => 6,
                    GL_TEXTURE_1D_ARRAY => img.height,
                    _ => img.depth,
                })
            }
            _ => None,
        })
        .min()
    }

    /// Draws `indices` of `mode` through the stages, each emitted
    /// primitive into the layer its gl_Layer names (see the module docs).
    /// `gl_layer` is the geometry stage's gl_Layer output component.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn draw_layered(
        &mut self,
        stages: LayeredStages,
        (mode, indices): (u32, &[u32]),
        (immediate, batch): (
            Option<&[crate::vertex::ImmVertex]>,
            crate::fetch::InstanceBatch,
        ),
        state: &raster::PipelineState,
        units: &raster::TextureUnits,
        (gl_layer, layers): (usize, i32),
    ) -> Result<(), String> {
        let (gs, gs_words) = stages.gs;
        let fetch = crate::fetch::Fetcher::new(self, stages.vs.0, immediate, batch);
        let shaded = raster::shade_geometry(
            &self.workers,
            (stages.vs.0, stages.vs.1),
            (gs, gs_words),
            units,
            indices,
            &fetch,
            crate::pipeline_state::raster_mode(mode),
            state,
        );
        drop(fetch);
        let (out_mode, vertex_of, outputs, stride) = shaded.map_err(|e| e.to_string())?;
        let mut by_layer: BTreeMap<i32, Vec<u32>> = BTreeMap::new();
        let primitives = raster::layered_primitives(
            (out_mode, &vertex_of, &outputs),
            stride,
            gl_layer,
            state.provoking_first,
        );
        for (layer, prim) in primitives {
            if (0..layers).contains(&layer) {
                by_layer.entry(layer).or_default().extend_from_slice(prim);
            }
        }
        let mut result = Ok(());
        for (layer, list) in by_layer {
            self.draw_layer = layer;
            let Some(mut target) = self.draw_target() else {
                continue;
            };
            let r = raster::draw_emitted(
                &self.workers,
                &mut target.fb,
                state,
                gs.interface(),
                stages.fs,
                (out_mode, list, outputs.clone()),
                units,
            );
            self.store_target(target);
            if let Err(e) = r {
                result = Err(e.to_string());
                break;
            }
        }
        self.draw_layer = 0;
        result
    }
}
