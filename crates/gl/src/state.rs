//! The fixed-function state ([`State`]: lights, materials, fog, texture
//! environments, stencil, points, and the rest GL 2.1 Tables 6.5-6.31
//! list) with its initial values, and the capabilities glEnable,
//! glDisable and glIsEnabled switch.
//!
//! Contract: the setters live with their job — [`crate::transform`]
//! (matrices, viewport, clip planes), [`crate::per_fragment`] (clear
//! values and per-fragment operations), [`crate::rasterization`] (points,
//! lines, polygons, pixel storage, hints) and [`crate::shading`]
//! (lighting, fog, texture environment and coordinate generation); each
//! validates as GL 2.1 says and changes nothing on error.

use crate::enums::*;
use crate::{Context, MAX_CLIP_PLANES, MAX_DRAW_BUFFERS, MAX_LIGHTS, MAX_TEXTURE_UNITS};
use std::collections::BTreeSet;

/// One light source (GL 2.1 Table 6.9 defaults). Position and spot
/// direction are in eye coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    pub ambient: [f32; 4],
    pub diffuse: [f32; 4],
    pub specular: [f32; 4],
    pub position: [f32; 4],
    pub spot_direction: [f32; 3],
    pub spot_exponent: f32,
    pub spot_cutoff: f32,
    pub attenuation: [f32; 3],
}

impl Light {
    fn new(index: usize) -> Light {
        let bright = if index == 0 {
            [1.0; 4]
        } else {
            [0.0, 0.0, 0.0, 1.0]
        };
        Light {
            ambient: [0.0, 0.0, 0.0, 1.0],
            diffuse: bright,
            specular: bright,
            position: [0.0, 0.0, 1.0, 0.0],
            spot_direction: [0.0, 0.0, -1.0],
            spot_exponent: 0.0,
            spot_cutoff: 180.0,
            attenuation: [1.0, 0.0, 0.0],
        }
    }
}

/// Material parameters of one face (GL 2.1 Table 6.8 defaults).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    pub ambient: [f32; 4],
    pub diffuse: [f32; 4],
    pub specular: [f32; 4],
    pub emission: [f32; 4],
    pub shininess: f32,
}

impl Default for Material {
    fn default() -> Self {
        Material {
            ambient: [0.2, 0.2, 0.2, 1.0],
            diffuse: [0.8, 0.8, 0.8, 1.0],
            specular: [0.0, 0.0, 0.0, 1.0],
            emission: [0.0, 0.0, 0.0, 1.0],
            shininess: 0.0,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fog {
    pub mode: u32,
    pub density: f32,
    pub start: f32,
    pub end: f32,
    pub color: [f32; 4],
    pub coord_src: u32,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexEnv {
    pub mode: u32,
    pub color: [f32; 4],
    pub lod_bias: f32,
    pub coord_replace: bool,
    /// GL_COMBINE state, indexed by pname - GL_COMBINE_RGB (GL_COMBINE_RGB
    /// ..= GL_OPERAND2_ALPHA); kept for queries, not applied by the
    /// fixed-function fragment stage (GL_COMBINE draws as GL_MODULATE).
    pub combine: [f32; COMBINE_PARAMS],
    pub alpha_scale: f32,
}

/// Parameters GL_COMBINE_RGB ..= GL_OPERAND2_ALPHA.
pub const COMBINE_PARAMS: usize = (GL_OPERAND2_ALPHA - GL_COMBINE_RGB + 1) as usize;

/// GL 2.1 Table 6.19's initial GL_COMBINE state.
fn combine_defaults() -> [f32; COMBINE_PARAMS] {
    let mut c = [0.0; COMBINE_PARAMS];
    let mut set = |p: u32, v: u32| {
        if let Some(x) = c.get_mut((p - GL_COMBINE_RGB) as usize) {
            *x = v as f32;
        }
    };
    set(GL_COMBINE_RGB, GL_MODULATE);
    set(GL_COMBINE_ALPHA, GL_MODULATE);
    set(GL_SOURCE0_RGB, GL_TEXTURE);
    set(GL_SOURCE1_RGB, GL_PREVIOUS);
    set(GL_SOURCE2_RGB, GL_CONSTANT);
    set(GL_SOURCE0_ALPHA, GL_TEXTURE);
    set(GL_SOURCE1_ALPHA, GL_PREVIOUS);
    set(GL_SOURCE2_ALPHA, GL_CONSTANT);
    set(GL_OPERAND0_RGB, GL_SRC_COLOR);
    set(GL_OPERAND1_RGB, GL_SRC_COLOR);
    set(GL_OPERAND2_RGB, GL_SRC_ALPHA);
    set(GL_OPERAND0_ALPHA, GL_SRC_ALPHA);
    set(GL_OPERAND1_ALPHA, GL_SRC_ALPHA);
    set(GL_OPERAND2_ALPHA, GL_SRC_ALPHA);
    if let Some(x) = c.get_mut((GL_RGB_SCALE - GL_COMBINE_RGB) as usize) {
        *x = 1.0;
    }
    c
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexGen {
    pub mode: u32,
    pub object_plane: [f32; 4],
    /// In eye coordinates (transformed at glTexGen time).
    pub eye_plane: [f32; 4],
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StencilFace {
    pub func: u32,
    pub reference: i32,
    pub value_mask: u32,
    pub fail: u32,
    pub zfail: u32,
    pub zpass: u32,
    pub write_mask: u32,
}

/// Point parameters (GL 2.1 §3.4).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointParams {
    pub size: f32,
    pub size_min: f32,
    pub size_max: f32,
    pub fade_threshold: f32,
    pub attenuation: [f32; 3],
    pub sprite_origin: u32,
}

/// The largest point size and line width.
pub const MAX_POINT_SIZE: f32 = 255.0;

#[derive(Clone)]
pub struct State {
    /// Enabled capabilities: (cap, texture unit for per-unit caps else 0).
    pub enabled: BTreeSet<(u32, u32)>,
    pub clear_color: [f32; 4],
    pub clear_depth: f32,
    pub clear_stencil: i32,
    pub scissor: [i32; 4],
    pub blend_src: [u32; 2],
    pub blend_dst: [u32; 2],
    pub blend_eq: [u32; 2],
    pub blend_color: [f32; 4],
    pub logic_op: u32,
    pub depth_func: u32,
    pub depth_mask: bool,
    /// Front, back.
    pub stencil: [StencilFace; 2],
    pub alpha_func: u32,
    pub alpha_ref: f32,
    /// glColorMask / glColorMaski, per draw buffer.
    pub color_masks: [[bool; 4]; MAX_DRAW_BUFFERS],
    pub cull_face: u32,
    pub front_face: u32,
    /// Front, back.
    pub polygon_mode: [u32; 2],
    pub polygon_offset: [f32; 2],
    pub shade_model: u32,
    /// glProvokingVertex (GL 3.2).
    pub provoking_vertex: u32,
    /// glSampleMaski's word 0 (GL_SAMPLE_MASK_VALUE, GL 3.2).
    pub sample_mask: u32,
    pub line_width: f32,
    pub point: PointParams,
    pub lights: [Light; MAX_LIGHTS],
    /// Front, back.
    pub material: [Material; 2],
    pub light_model_ambient: [f32; 4],
    pub light_model_local_viewer: bool,
    pub light_model_two_side: bool,
    pub light_model_color_control: u32,
    pub color_material_face: u32,
    pub color_material_mode: u32,
    pub fog: Fog,
    pub tex_env: [TexEnv; MAX_TEXTURE_UNITS],
    /// Per unit: S, T, R, Q.
    pub tex_gen: [[TexGen; 4]; MAX_TEXTURE_UNITS],
    pub active_texture: u32,
    /// glPixelStore's unpack and pack modes.
    pub unpack: crate::pixel_store::PixelStore,
    pub pack: crate::pixel_store::PixelStore,
    pub draw_buffers: Vec<u32>,
    pub read_buffer: u32,
    /// glClampColor's CLAMP_VERTEX_COLOR, CLAMP_FRAGMENT_COLOR and
    /// CLAMP_READ_COLOR: GL_TRUE, GL_FALSE or GL_FIXED_ONLY.
    pub clamp_vertex_color: u32,
    pub clamp_fragment_color: u32,
    pub clamp_read_color: u32,
}

impl State {
    pub fn new(w: i32, h: i32) -> State {
        let stencil = StencilFace {
            func: GL_ALWAYS,
            reference: 0,
            value_mask: u32::MAX,
            fail: GL_KEEP,
            zfail: GL_KEEP,
            zpass: GL_KEEP,
            write_mask: u32::MAX,
        };
        let gen = |plane: [f32; 4]| TexGen {
            mode: GL_EYE_LINEAR,
            object_plane: plane,
            eye_plane: plane,
        };
        let mut enabled = BTreeSet::new();
        enabled.insert((GL_DITHER, 0));
        enabled.insert((GL_MULTISAMPLE, 0));
        State {
            enabled,
            clear_color: [0.0; 4],
            clear_depth: 1.0,
            clear_stencil: 0,
            scissor: [0, 0, w, h],
            blend_src: [GL_ONE; 2],
            blend_dst: [GL_ZERO; 2],
            blend_eq: [GL_FUNC_ADD; 2],
            blend_color: [0.0; 4],
            logic_op: GL_COPY,
            depth_func: GL_LESS,
            depth_mask: true,
            stencil: [stencil; 2],
            alpha_func: GL_ALWAYS,
            alpha_ref: 0.0,
            color_masks: [[true; 4]; MAX_DRAW_BUFFERS],
            cull_face: GL_BACK,
            front_face: GL_CCW,
            polygon_mode: [GL_FILL; 2],
            polygon_offset: [0.0; 2],
            shade_model: GL_SMOOTH,
            provoking_vertex: GL_LAST_VERTEX_CONVENTION,
            sample_mask: !0,
            line_width: 1.0,
            point: PointParams {
                size: 1.0,
                size_min: 0.0,
                size_max: MAX_POINT_SIZE,
                fade_threshold: 1.0,
                attenuation: [1.0, 0.0, 0.0],
                sprite_origin: GL_UPPER_LEFT,
            },
            lights: std::array::from_fn(Light::new),
            material: [Material::default(); 2],
            light_model_ambient: [0.2, 0.2, 0.2, 1.0],
            light_model_local_viewer: false,
            light_model_two_side: false,
            light_model_color_control: GL_SINGLE_COLOR,
            color_material_face: GL_FRONT_AND_BACK,
            color_material_mode: GL_AMBIENT_AND_DIFFUSE,
            fog: Fog {
                mode: GL_EXP,
                density: 1.0,
                start: 0.0,
                end: 1.0,
                color: [0.0; 4],
                coord_src: GL_FRAGMENT_DEPTH,
            },
            tex_env: [TexEnv {
                mode: GL_MODULATE,
                color: [0.0; 4],
                lod_bias: 0.0,
                coord_replace: false,
                combine: combine_defaults(),
                alpha_scale: 1.0,
            }; MAX_TEXTURE_UNITS],
            tex_gen: [[
                gen([1.0, 0.0, 0.0, 0.0]),
                gen([0.0, 1.0, 0.0, 0.0]),
                gen([0.0; 4]),
                gen([0.0; 4]),
            ]; MAX_TEXTURE_UNITS],
            active_texture: 0,
            unpack: Default::default(),
            pack: Default::default(),
            draw_buffers: vec![GL_BACK],
            read_buffer: GL_BACK,
            clamp_vertex_color: GL_TRUE,
            clamp_fragment_color: GL_FIXED_ONLY,
            clamp_read_color: GL_FIXED_ONLY,
        }
    }

    pub fn is_on(&self, cap: u32) -> bool {
        self.enabled.contains(&(cap, 0))
    }

    pub fn is_on_unit(&self, cap: u32, unit: u32) -> bool {
        self.enabled.contains(&(cap, unit))
    }
}

/// Capabilities that glEnable/glDisable/glIsEnabled accept. Per-unit ones
/// are in [`UNIT_CAPS`].
const CAPS: &[u32] = &[
    GL_ALPHA_TEST,
    GL_AUTO_NORMAL,
    GL_BLEND,
    GL_COLOR_LOGIC_OP,
    GL_INDEX_LOGIC_OP,
    GL_COLOR_MATERIAL,
    GL_COLOR_SUM,
    GL_CULL_FACE,
    GL_DEPTH_TEST,
    GL_DITHER,
    GL_FOG,
    GL_LIGHTING,
    GL_LINE_SMOOTH,
    GL_LINE_STIPPLE,
    GL_MULTISAMPLE,
    GL_NORMALIZE,
    GL_POINT_SMOOTH,
    GL_POINT_SPRITE,
    GL_POLYGON_OFFSET_FILL,
    GL_POLYGON_OFFSET_LINE,
    GL_POLYGON_OFFSET_POINT,
    GL_POLYGON_SMOOTH,
    GL_POLYGON_STIPPLE,
    GL_RESCALE_NORMAL,
    GL_SAMPLE_ALPHA_TO_COVERAGE,
    GL_SAMPLE_ALPHA_TO_ONE,
    GL_SAMPLE_COVERAGE,
    GL_SCISSOR_TEST,
    GL_STENCIL_TEST,
    GL_VERTEX_PROGRAM_POINT_SIZE,
    GL_VERTEX_PROGRAM_TWO_SIDE,
    GL_MAP1_VERTEX_3,
    GL_MAP1_VERTEX_4,
    GL_MAP2_VERTEX_3,
    GL_MAP2_VERTEX_4,
    GL_FRAMEBUFFER_SRGB,
    GL_PRIMITIVE_RESTART,
];

/// Capabilities of GL 3.x, with the version that adds each: GL 2.1
/// contexts refuse them (GL_INVALID_ENUM). GL_TEXTURE_CUBE_MAP_SEAMLESS
/// is kept and queried but cube maps are still filtered face by face (as
/// GL 3.3 §3.8.8 allows only with it off).
const CAPS_3X: &[(u32, (u32, u32))] = &[
    (GL_RASTERIZER_DISCARD, (3, 0)),
    (GL_DEPTH_CLAMP, (3, 2)),
    (GL_TEXTURE_CUBE_MAP_SEAMLESS, (3, 2)),
    (GL_SAMPLE_MASK, (3, 2)),
];

/// Capabilities that apply to the active texture unit.
const UNIT_CAPS: &[u32] = &[
    GL_TEXTURE_1D,
    GL_TEXTURE_2D,
    GL_TEXTURE_3D,
    GL_TEXTURE_CUBE_MAP,
    GL_TEXTURE_GEN_S,
    GL_TEXTURE_GEN_T,
    GL_TEXTURE_GEN_R,
    GL_TEXTURE_GEN_Q,
];

/// `x` clamped to [0, 1], NaN to 0.
pub(crate) fn clamp01(x: f32) -> f32 {
    if x.is_nan() {
        0.0
    } else {
        x.clamp(0.0, 1.0)
    }
}

impl Context {
    /// Whether `cap` is a global (not per-unit) capability of this context.
    fn global_cap(&self, cap: u32) -> bool {
        CAPS.contains(&cap)
            || (GL_LIGHT0..GL_LIGHT0 + MAX_LIGHTS as u32).contains(&cap)
            || (GL_CLIP_PLANE0..GL_CLIP_PLANE0 + MAX_CLIP_PLANES as u32).contains(&cap)
            || CAPS_3X
                .iter()
                .any(|&(c, (major, minor))| c == cap && self.api.at_least(major, minor))
    }

    fn set_cap(&mut self, cap: u32, on: bool) {
        if self.reject_in_begin() || self.refuse_removed_cap(cap) {
            return;
        }
        let key = if UNIT_CAPS.contains(&cap) {
            if self.st.active_texture as usize >= MAX_TEXTURE_UNITS {
                self.set_error(GL_INVALID_OPERATION);
                return;
            }
            (cap, self.st.active_texture)
        } else if self.global_cap(cap) {
            (cap, 0)
        } else {
            self.set_error(GL_INVALID_ENUM);
            return;
        };
        if on {
            self.st.enabled.insert(key);
        } else {
            self.st.enabled.remove(&key);
        }
        // GL_BLEND is per draw buffer (key (GL_BLEND, i), GL 3.3 §4.1.8):
        // glEnable/glDisable set every buffer's.
        if cap == GL_BLEND {
            for i in 1..MAX_DRAW_BUFFERS as u32 {
                self.set_indexed_cap(cap, i, on);
            }
        }
        if cap == GL_COLOR_MATERIAL && on {
            self.track_color_material();
        }
    }

    /// glEnable.
    pub fn enable(&mut self, cap: u32) {
        self.set_cap(cap, true);
    }

    /// glDisable.
    pub fn disable(&mut self, cap: u32) {
        self.set_cap(cap, false);
    }

    /// glIsEnabled (also answers for the client array capabilities).
    pub fn is_enabled(&mut self, cap: u32) -> bool {
        if self.reject_in_begin() || self.refuse_removed_cap(cap) {
            return false;
        }
        if UNIT_CAPS.contains(&cap) {
            return self.st.is_on_unit(cap, self.st.active_texture);
        }
        if self.global_cap(cap) {
            return self.st.is_on(cap);
        }
        if let Some(on) = self.client_state_enabled(cap) {
            return on;
        }
        self.set_error(GL_INVALID_ENUM);
        false
    }

    /// The stencil / material / polygon faces a face enum names.
    pub(crate) fn faces(face: u32) -> Option<&'static [usize]> {
        match face {
            GL_FRONT => Some(&[0]),
            GL_BACK => Some(&[1]),
            GL_FRONT_AND_BACK => Some(&[0, 1]),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::param::Param;

    #[test]
    fn caps_and_enum_checks() {
        let mut ctx = Context::new(4, 4);
        ctx.enable(GL_LIGHT3);
        assert!(ctx.is_enabled(GL_LIGHT3));
        ctx.active_texture(GL_TEXTURE1);
        ctx.enable(GL_TEXTURE_2D);
        assert!(ctx.is_enabled(GL_TEXTURE_2D));
        ctx.active_texture(GL_TEXTURE0);
        assert!(!ctx.is_enabled(GL_TEXTURE_2D));
        assert!(ctx.is_enabled(GL_DITHER));
        assert!(!ctx.is_enabled(0x9999));
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.depth_func(GL_ZERO);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        // SRC_ALPHA_SATURATE is a source factor only (GL 2.1 Table 4.2).
        ctx.blend_func(GL_SRC_ALPHA_SATURATE, GL_ONE);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.blend_func(GL_ONE, GL_SRC_ALPHA_SATURATE);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.stencil_op(GL_KEEP, GL_KEEP, GL_ONE);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.point_size(0.0);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.fog(GL_FOG_MODE, Param::I(GL_LINEAR as i32));
        assert_eq!(ctx.st.fog.mode, GL_LINEAR);
        ctx.fog(GL_FOG_MODE, Param::I(GL_ONE as i32));
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.tex_gen(GL_R, GL_TEXTURE_GEN_MODE, Param::I(GL_SPHERE_MAP as i32));
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.active_texture(GL_TEXTURE0 + 40);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    }
}
