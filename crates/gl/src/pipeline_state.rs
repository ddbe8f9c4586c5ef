//! The GL state as raster's plain data: [`raster::PipelineState`] for a
//! draw (viewport, clipping, culling, rasterization controls and every
//! per-fragment operation) and the enum translations it and the sampler
//! conversion use.
//!
//! Contract: a pure reading of the context; an enum raster has no value
//! for (already rejected by its setter) maps to raster's default.

use crate::enums::*;
use crate::per_fragment::clamp_applies;
use crate::Context;

pub(crate) fn raster_mode(mode: u32) -> raster::Mode {
    use raster::Mode::*;
    match mode {
        GL_POINTS => Points,
        GL_LINES => Lines,
        GL_LINE_STRIP => LineStrip,
        GL_LINE_LOOP => LineLoop,
        GL_TRIANGLES => Triangles,
        GL_TRIANGLE_STRIP => TriangleStrip,
        GL_TRIANGLE_FAN => TriangleFan,
        GL_QUADS => Quads,
        GL_QUAD_STRIP => QuadStrip,
        GL_LINES_ADJACENCY => LinesAdjacency,
        GL_LINE_STRIP_ADJACENCY => LineStripAdjacency,
        GL_TRIANGLES_ADJACENCY => TrianglesAdjacency,
        GL_TRIANGLE_STRIP_ADJACENCY => TriangleStripAdjacency,
        _ => Polygon,
    }
}

pub(crate) fn compare_func(f: u32) -> raster::CompareFunc {
    use raster::CompareFunc::*;
    match f {
        GL_NEVER => Never,
        GL_LESS => Less,
        GL_EQUAL => Equal,
        GL_LEQUAL => LessEqual,
        GL_GREATER => Greater,
        GL_NOTEQUAL => NotEqual,
        GL_GEQUAL => GreaterEqual,
        _ => Always,
    }
}

fn stencil_op(op: u32) -> raster::StencilOp {
    use raster::StencilOp::*;
    match op {
        GL_ZERO => Zero,
        GL_REPLACE => Replace,
        GL_INCR => Incr,
        GL_DECR => Decr,
        GL_INVERT => Invert,
        GL_INCR_WRAP => IncrWrap,
        GL_DECR_WRAP => DecrWrap,
        _ => Keep,
    }
}

fn blend_factor(f: u32) -> raster::BlendFactor {
    use raster::BlendFactor::*;
    match f {
        GL_ZERO => Zero,
        GL_SRC_COLOR => SrcColor,
        GL_ONE_MINUS_SRC_COLOR => OneMinusSrcColor,
        GL_DST_COLOR => DstColor,
        GL_ONE_MINUS_DST_COLOR => OneMinusDstColor,
        GL_SRC_ALPHA => SrcAlpha,
        GL_ONE_MINUS_SRC_ALPHA => OneMinusSrcAlpha,
        GL_DST_ALPHA => DstAlpha,
        GL_ONE_MINUS_DST_ALPHA => OneMinusDstAlpha,
        GL_CONSTANT_COLOR => ConstantColor,
        GL_ONE_MINUS_CONSTANT_COLOR => OneMinusConstantColor,
        GL_CONSTANT_ALPHA => ConstantAlpha,
        GL_ONE_MINUS_CONSTANT_ALPHA => OneMinusConstantAlpha,
        GL_SRC_ALPHA_SATURATE => SrcAlphaSaturate,
        GL_SRC1_COLOR => Src1Color,
        GL_ONE_MINUS_SRC1_COLOR => OneMinusSrc1Color,
        GL_SRC1_ALPHA => Src1Alpha,
        GL_ONE_MINUS_SRC1_ALPHA => OneMinusSrc1Alpha,
        _ => One,
    }
}

fn blend_eq(e: u32) -> raster::BlendEquation {
    use raster::BlendEquation::*;
    match e {
        GL_FUNC_SUBTRACT => Subtract,
        GL_FUNC_REVERSE_SUBTRACT => ReverseSubtract,
        GL_MIN => Min,
        GL_MAX => Max,
        _ => Add,
    }
}

fn logic_op(op: u32) -> raster::LogicOp {
    raster::LogicOp::ALL
        .get(op.wrapping_sub(GL_CLEAR) as usize)
        .copied()
        .unwrap_or(raster::LogicOp::Copy)
}

pub(crate) fn rect(r: [i32; 4]) -> raster::Rect {
    raster::Rect::new(r[0], r[1], r[2], r[3])
}

impl Context {
    /// The GL state as raster's plain data.
    pub(crate) fn pipeline_state(
        &self,
        target: &crate::render_target::Target,
    ) -> raster::PipelineState {
        let draw_buffers = target.draw_buffers;
        // glClampColor's FIXED_ONLY clamps when every colour buffer drawn
        // is fixed-point; GL 2.1 clamps always (its state stays TRUE and
        // FIXED_ONLY, glClampColor refused).
        let fixed_point = !self.api.at_least(3, 0)
            || target
                .fb
                .color
                .iter()
                .all(|c| matches!(c, raster::ColorBuffer::Rgba8(_)));
        let st = &self.st;
        let on = |c| st.is_on(c);
        let face = |f: usize| raster::StencilFace {
            func: compare_func(st.stencil[f].func),
            reference: st.stencil[f].reference,
            value_mask: st.stencil[f].value_mask,
            fail: stencil_op(st.stencil[f].fail),
            depth_fail: stencil_op(st.stencil[f].zfail),
            depth_pass: stencil_op(st.stencil[f].zpass),
            write_mask: st.stencil[f].write_mask,
        };
        let poly = |m: u32| match m {
            GL_POINT => raster::PolygonMode::Point,
            GL_LINE => raster::PolygonMode::Line,
            _ => raster::PolygonMode::Fill,
        };
        let mut clip_planes = [None; 8];
        for (i, p) in clip_planes.iter_mut().enumerate() {
            if on(GL_CLIP_PLANE0 + i as u32) {
                *p = Some(self.clip_planes[i]);
            }
        }
        let coord_replace = (0..crate::MAX_TEXTURE_UNITS)
            .filter(|&u| st.tex_env[u].coord_replace)
            .fold(0u32, |m, u| m | (1 << u));
        raster::PipelineState {
            viewport: rect(self.viewport),
            depth_range: (self.depth_range[0], self.depth_range[1]),
            depth_clamp: on(GL_DEPTH_CLAMP),
            scissor: on(GL_SCISSOR_TEST).then(|| rect(st.scissor)),
            cull: on(GL_CULL_FACE).then_some(match st.cull_face {
                GL_FRONT => raster::CullFace::Front,
                GL_BACK => raster::CullFace::Back,
                _ => raster::CullFace::FrontAndBack,
            }),
            front_face: if st.front_face == GL_CW {
                raster::FrontFace::Cw
            } else {
                raster::FrontFace::Ccw
            },
            polygon_mode: [poly(st.polygon_mode[0]), poly(st.polygon_mode[1])],
            flat_shading: st.shade_model == GL_FLAT,
            top_down: target.name == 0,
            provoking_first: self.provoking_first(),
            point_size: st.point.size,
            point_sprite: on(GL_POINT_SPRITE),
            coord_replace,
            point_sprite_origin_lower_left: st.point.sprite_origin == GL_LOWER_LEFT,
            vertex_program_point_size: on(GL_VERTEX_PROGRAM_POINT_SIZE),
            line_width: st.line_width,
            two_sided_color: self.two_sided_color(),
            clamp_vertex_color: clamp_applies(st.clamp_vertex_color, fixed_point),
            clamp_fragment_color: clamp_applies(st.clamp_fragment_color, fixed_point),
            clip_planes,
            alpha_test: on(GL_ALPHA_TEST).then_some((compare_func(st.alpha_func), st.alpha_ref)),
            stencil: on(GL_STENCIL_TEST).then(|| raster::StencilState {
                front: face(0),
                back: face(1),
            }),
            depth_test: on(GL_DEPTH_TEST).then_some(compare_func(st.depth_func)),
            depth_mask: st.depth_mask,
            blend: self.any_buffer_blends().then_some(raster::Blend {
                src_rgb: blend_factor(st.blend_src[0]),
                dst_rgb: blend_factor(st.blend_dst[0]),
                src_alpha: blend_factor(st.blend_src[1]),
                dst_alpha: blend_factor(st.blend_dst[1]),
                equation_rgb: blend_eq(st.blend_eq[0]),
                equation_alpha: blend_eq(st.blend_eq[1]),
                color: st.blend_color,
            }),
            color_mask: st.color_masks[0],
            per_buffer: self.per_buffer_ops(),
            logic_op: on(GL_COLOR_LOGIC_OP).then_some(logic_op(st.logic_op)),
            polygon_offset: raster::PolygonOffset {
                factor: st.polygon_offset[0],
                units: st.polygon_offset[1],
                fill: on(GL_POLYGON_OFFSET_FILL),
                line: on(GL_POLYGON_OFFSET_LINE),
                point: on(GL_POLYGON_OFFSET_POINT),
            },
            draw_buffers,
            // Numbered per draw by the draw call.
            primitive_ids: raster::PrimitiveIds::default(),
            // SAMPLES_PASSED and ANY_SAMPLES_PASSED count what passes.
            count_samples: self.queries.active[..2] != [0, 0],
        }
    }

    /// Two-sided color selection: VERTEX_PROGRAM_TWO_SIDE with a user
    /// vertex shader, LIGHT_MODEL_TWO_SIDE with fixed-function lighting.
    fn two_sided_color(&self) -> bool {
        let user_vs = self.stage_executable(glsl::Stage::Vertex).is_some();
        if user_vs {
            self.st.is_on(GL_VERTEX_PROGRAM_TWO_SIDE)
        } else {
            self.st.is_on(GL_LIGHTING) && self.st.light_model_two_side
        }
    }
}
