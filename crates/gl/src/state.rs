//! Fixed-function state and its setters: capabilities (glEnable), matrix
//! stacks (GL 2.1 §2.11.2), viewport and depth range (§2.11.1), clip planes
//! (§2.12), lighting and materials (§2.14), fog (§3.10), texture environment
//! and coordinate generation (§3.8.13, §2.11.4), per-fragment operations
//! (§4.1), rasterization controls (§3.3-3.5) and pixel storage (§3.6.1).

use crate::enums::*;
use crate::matrix::{self, Mat4};
use crate::{Context, MAX_CLIP_PLANES, MAX_LIGHTS, MAX_TEXTURE_UNITS};
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
    pub color_mask: [bool; 4],
    pub cull_face: u32,
    pub front_face: u32,
    /// Front, back.
    pub polygon_mode: [u32; 2],
    pub polygon_offset: [f32; 2],
    pub shade_model: u32,
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
    pub unpack_alignment: i32,
    pub pack_alignment: i32,
    pub draw_buffers: Vec<u32>,
    pub read_buffer: u32,
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
            color_mask: [true; 4],
            cull_face: GL_BACK,
            front_face: GL_CCW,
            polygon_mode: [GL_FILL; 2],
            polygon_offset: [0.0; 2],
            shade_model: GL_SMOOTH,
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
            unpack_alignment: 4,
            pack_alignment: 4,
            draw_buffers: vec![GL_BACK],
            read_buffer: GL_BACK,
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
    GL_CLAMP_VERTEX_COLOR,
    GL_CLAMP_FRAGMENT_COLOR,
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

fn valid_func(f: u32) -> bool {
    (GL_NEVER..=GL_ALWAYS).contains(&f)
}

fn valid_stencil_op(op: u32) -> bool {
    matches!(
        op,
        GL_KEEP
            | GL_ZERO
            | GL_REPLACE
            | GL_INCR
            | GL_DECR
            | GL_INVERT
            | GL_INCR_WRAP
            | GL_DECR_WRAP
    )
}

fn valid_blend_factor(f: u32, is_src: bool) -> bool {
    matches!(
        f,
        GL_ZERO
            | GL_ONE
            | GL_SRC_COLOR
            | GL_ONE_MINUS_SRC_COLOR
            | GL_DST_COLOR
            | GL_ONE_MINUS_DST_COLOR
            | GL_SRC_ALPHA
            | GL_ONE_MINUS_SRC_ALPHA
            | GL_DST_ALPHA
            | GL_ONE_MINUS_DST_ALPHA
            | GL_CONSTANT_COLOR
            | GL_ONE_MINUS_CONSTANT_COLOR
            | GL_CONSTANT_ALPHA
            | GL_ONE_MINUS_CONSTANT_ALPHA
    ) || (f == GL_SRC_ALPHA_SATURATE && is_src)
}

fn valid_blend_eq(e: u32) -> bool {
    matches!(
        e,
        GL_FUNC_ADD | GL_FUNC_SUBTRACT | GL_FUNC_REVERSE_SUBTRACT | GL_MIN | GL_MAX
    )
}

fn clamp01(x: f32) -> f32 {
    if x.is_nan() {
        0.0
    } else {
        x.clamp(0.0, 1.0)
    }
}

/// The number of values a light/material/fog/light-model parameter takes.
fn light_param_len(pname: u32) -> usize {
    match pname {
        GL_AMBIENT
        | GL_DIFFUSE
        | GL_SPECULAR
        | GL_POSITION
        | GL_EMISSION
        | GL_AMBIENT_AND_DIFFUSE
        | GL_LIGHT_MODEL_AMBIENT
        | GL_FOG_COLOR => 4,
        GL_SPOT_DIRECTION | GL_COLOR_INDEXES => 3,
        _ => 1,
    }
}

impl Context {
    // ---- capabilities ----

    fn set_cap(&mut self, cap: u32, on: bool) {
        if self.reject_in_begin() {
            return;
        }
        let key = if UNIT_CAPS.contains(&cap) {
            if self.st.active_texture as usize >= MAX_TEXTURE_UNITS {
                self.set_error(GL_INVALID_OPERATION);
                return;
            }
            (cap, self.st.active_texture)
        } else if CAPS.contains(&cap)
            || (GL_LIGHT0..GL_LIGHT0 + MAX_LIGHTS as u32).contains(&cap)
            || (GL_CLIP_PLANE0..GL_CLIP_PLANE0 + MAX_CLIP_PLANES as u32).contains(&cap)
        {
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
        if self.reject_in_begin() {
            return false;
        }
        if UNIT_CAPS.contains(&cap) {
            return self.st.is_on_unit(cap, self.st.active_texture);
        }
        if CAPS.contains(&cap)
            || (GL_LIGHT0..GL_LIGHT0 + MAX_LIGHTS as u32).contains(&cap)
            || (GL_CLIP_PLANE0..GL_CLIP_PLANE0 + MAX_CLIP_PLANES as u32).contains(&cap)
        {
            return self.st.is_on(cap);
        }
        if let Some(on) = self.client_state_enabled(cap) {
            return on;
        }
        self.set_error(GL_INVALID_ENUM);
        false
    }

    // ---- matrices ----

    /// glMatrixMode.
    pub fn matrix_mode(&mut self, mode: u32) {
        if self.reject_in_begin() {
            return;
        }
        match mode {
            GL_MODELVIEW | GL_PROJECTION | GL_TEXTURE => self.matrix_mode = mode,
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// The stack selected by the matrix mode (and the active texture unit).
    pub(crate) fn current_stack(&mut self) -> Option<&mut Vec<Mat4>> {
        match self.matrix_mode {
            GL_PROJECTION => Some(&mut self.projection),
            GL_TEXTURE => self.texture_matrix.get_mut(self.st.active_texture as usize),
            _ => Some(&mut self.modelview),
        }
    }

    fn with_top(&mut self, f: impl FnOnce(&Mat4) -> Mat4) {
        if self.reject_in_begin() {
            return;
        }
        if self.matrix_mode == GL_TEXTURE && self.st.active_texture as usize >= MAX_TEXTURE_UNITS {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if let Some(top) = self.current_stack().and_then(|s| s.last_mut()) {
            *top = f(top);
        }
    }

    /// glLoadIdentity.
    pub fn load_identity(&mut self) {
        self.with_top(|_| matrix::IDENTITY);
    }

    /// glLoadMatrixf (column-major).
    pub fn load_matrixf(&mut self, m: &[f32; 16]) {
        self.with_top(|_| *m);
    }

    /// glMultMatrixf.
    pub fn mult_matrixf(&mut self, m: &[f32; 16]) {
        self.with_top(|t| matrix::mul(t, m));
    }

    /// glLoadTransposeMatrixf.
    pub fn load_transpose_matrixf(&mut self, m: &[f32; 16]) {
        self.with_top(|_| matrix::transpose(m));
    }

    /// glMultTransposeMatrixf.
    pub fn mult_transpose_matrixf(&mut self, m: &[f32; 16]) {
        self.with_top(|t| matrix::mul(t, &matrix::transpose(m)));
    }

    /// glTranslatef.
    pub fn translatef(&mut self, x: f32, y: f32, z: f32) {
        self.with_top(|t| matrix::mul(t, &matrix::translate(x, y, z)));
    }

    /// glScalef.
    pub fn scalef(&mut self, x: f32, y: f32, z: f32) {
        self.with_top(|t| matrix::mul(t, &matrix::scale(x, y, z)));
    }

    /// glRotatef.
    pub fn rotatef(&mut self, angle: f32, x: f32, y: f32, z: f32) {
        self.with_top(|t| matrix::mul(t, &matrix::rotate(angle, x, y, z)));
    }

    /// glOrtho.
    pub fn ortho(&mut self, l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) {
        if l == r || b == t || n == f {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        self.with_top(|m| matrix::mul(m, &matrix::ortho(l, r, b, t, n, f)));
    }

    /// glFrustum.
    pub fn frustum(&mut self, l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) {
        if n <= 0.0 || f <= 0.0 || l == r || b == t || n == f {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        self.with_top(|m| matrix::mul(m, &matrix::frustum(l, r, b, t, n, f)));
    }

    /// glPushMatrix.
    pub fn push_matrix(&mut self) {
        if self.reject_in_begin() {
            return;
        }
        let overflow = match self.current_stack() {
            Some(s) if s.len() < crate::MAX_MATRIX_STACK_DEPTH => {
                let top = s.last().copied().unwrap_or(matrix::IDENTITY);
                s.push(top);
                false
            }
            _ => true,
        };
        if overflow {
            self.set_error(GL_STACK_OVERFLOW);
        }
    }

    /// glPopMatrix.
    pub fn pop_matrix(&mut self) {
        if self.reject_in_begin() {
            return;
        }
        let underflow = match self.current_stack() {
            Some(s) if s.len() > 1 => {
                s.pop();
                false
            }
            _ => true,
        };
        if underflow {
            self.set_error(GL_STACK_UNDERFLOW);
        }
    }

    /// The top of the model-view stack.
    pub fn modelview_matrix(&self) -> Mat4 {
        self.modelview.last().copied().unwrap_or(matrix::IDENTITY)
    }

    /// The top of the projection stack.
    pub fn projection_matrix(&self) -> Mat4 {
        self.projection.last().copied().unwrap_or(matrix::IDENTITY)
    }

    /// The top of texture unit `unit`'s matrix stack.
    pub fn texture_matrix(&self, unit: usize) -> Mat4 {
        self.texture_matrix
            .get(unit)
            .and_then(|s| s.last().copied())
            .unwrap_or(matrix::IDENTITY)
    }

    // ---- viewport, clipping ----

    /// glViewport.
    pub fn viewport(&mut self, x: i32, y: i32, w: i32, h: i32) {
        if self.reject_in_begin() {
            return;
        }
        if w < 0 || h < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let max = crate::MAX_TEXTURE_SIZE;
        self.viewport = [x, y, w.min(max), h.min(max)];
    }

    /// glDepthRange (clamped to [0, 1]).
    pub fn depth_range(&mut self, n: f64, f: f64) {
        if self.reject_in_begin() {
            return;
        }
        self.depth_range = [clamp01(n as f32), clamp01(f as f32)];
    }

    /// glClipPlane: the plane is stored in eye coordinates, transformed by
    /// the inverse of the current model-view matrix (GL 2.1 §2.12).
    pub fn clip_plane(&mut self, plane: u32, eq: &[f64; 4]) {
        if self.reject_in_begin() {
            return;
        }
        let i = plane.wrapping_sub(GL_CLIP_PLANE0) as usize;
        if i >= MAX_CLIP_PLANES {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let p = eq.map(|x| x as f32);
        let inv = matrix::inverse_or_identity(&self.modelview_matrix());
        self.clip_planes[i] = matrix::vec_mul(p, &inv);
    }

    /// glGetClipPlane.
    pub fn get_clip_plane(&mut self, plane: u32) -> [f64; 4] {
        let i = plane.wrapping_sub(GL_CLIP_PLANE0) as usize;
        match self.clip_planes.get(i) {
            Some(p) => p.map(|x| x as f64),
            None => {
                self.set_error(GL_INVALID_ENUM);
                [0.0; 4]
            }
        }
    }

    /// glScissor.
    pub fn scissor(&mut self, x: i32, y: i32, w: i32, h: i32) {
        if self.reject_in_begin() {
            return;
        }
        if w < 0 || h < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        self.st.scissor = [x, y, w, h];
    }

    // ---- clear values ----

    /// glClearColor (clamped, GL 2.1 §4.2.3).
    pub fn clear_color(&mut self, r: f32, g: f32, b: f32, a: f32) {
        if self.reject_in_begin() {
            return;
        }
        self.st.clear_color = [r, g, b, a].map(clamp01);
    }

    /// glClearDepth.
    pub fn clear_depth(&mut self, d: f64) {
        if self.reject_in_begin() {
            return;
        }
        self.st.clear_depth = clamp01(d as f32);
    }

    /// glClearStencil.
    pub fn clear_stencil(&mut self, s: i32) {
        if self.reject_in_begin() {
            return;
        }
        self.st.clear_stencil = s;
    }

    // ---- per-fragment operations ----

    /// glBlendFunc.
    pub fn blend_func(&mut self, src: u32, dst: u32) {
        self.blend_func_separate(src, dst, src, dst);
    }

    /// glBlendFuncSeparate.
    pub fn blend_func_separate(&mut self, src_rgb: u32, dst_rgb: u32, src_a: u32, dst_a: u32) {
        if self.reject_in_begin() {
            return;
        }
        if !(valid_blend_factor(src_rgb, true)
            && valid_blend_factor(dst_rgb, false)
            && valid_blend_factor(src_a, true)
            && valid_blend_factor(dst_a, false))
        {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.st.blend_src = [src_rgb, src_a];
        self.st.blend_dst = [dst_rgb, dst_a];
    }

    /// glBlendEquation.
    pub fn blend_equation(&mut self, mode: u32) {
        self.blend_equation_separate(mode, mode);
    }

    /// glBlendEquationSeparate.
    pub fn blend_equation_separate(&mut self, rgb: u32, alpha: u32) {
        if self.reject_in_begin() {
            return;
        }
        if !valid_blend_eq(rgb) || !valid_blend_eq(alpha) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.st.blend_eq = [rgb, alpha];
    }

    /// glBlendColor (clamped).
    pub fn blend_color(&mut self, r: f32, g: f32, b: f32, a: f32) {
        if self.reject_in_begin() {
            return;
        }
        self.st.blend_color = [r, g, b, a].map(clamp01);
    }

    /// glLogicOp.
    pub fn logic_op(&mut self, op: u32) {
        if self.reject_in_begin() {
            return;
        }
        if !(GL_CLEAR..=GL_SET).contains(&op) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.st.logic_op = op;
    }

    /// glDepthFunc.
    pub fn depth_func(&mut self, func: u32) {
        if self.reject_in_begin() {
            return;
        }
        if !valid_func(func) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.st.depth_func = func;
    }

    /// glDepthMask.
    pub fn depth_mask(&mut self, flag: bool) {
        if self.reject_in_begin() {
            return;
        }
        self.st.depth_mask = flag;
    }

    fn faces(face: u32) -> Option<&'static [usize]> {
        match face {
            GL_FRONT => Some(&[0]),
            GL_BACK => Some(&[1]),
            GL_FRONT_AND_BACK => Some(&[0, 1]),
            _ => None,
        }
    }

    /// glStencilFunc.
    pub fn stencil_func(&mut self, func: u32, reference: i32, mask: u32) {
        self.stencil_func_separate(GL_FRONT_AND_BACK, func, reference, mask);
    }

    /// glStencilFuncSeparate.
    pub fn stencil_func_separate(&mut self, face: u32, func: u32, reference: i32, mask: u32) {
        if self.reject_in_begin() {
            return;
        }
        let Some(faces) = Self::faces(face) else {
            self.set_error(GL_INVALID_ENUM);
            return;
        };
        if !valid_func(func) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        for &f in faces {
            let s = &mut self.st.stencil[f];
            s.func = func;
            s.reference = reference;
            s.value_mask = mask;
        }
    }

    /// glStencilOp.
    pub fn stencil_op(&mut self, fail: u32, zfail: u32, zpass: u32) {
        self.stencil_op_separate(GL_FRONT_AND_BACK, fail, zfail, zpass);
    }

    /// glStencilOpSeparate.
    pub fn stencil_op_separate(&mut self, face: u32, fail: u32, zfail: u32, zpass: u32) {
        if self.reject_in_begin() {
            return;
        }
        let Some(faces) = Self::faces(face) else {
            self.set_error(GL_INVALID_ENUM);
            return;
        };
        if ![fail, zfail, zpass].iter().all(|&o| valid_stencil_op(o)) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        for &f in faces {
            let s = &mut self.st.stencil[f];
            s.fail = fail;
            s.zfail = zfail;
            s.zpass = zpass;
        }
    }

    /// glStencilMask.
    pub fn stencil_mask(&mut self, mask: u32) {
        self.stencil_mask_separate(GL_FRONT_AND_BACK, mask);
    }

    /// glStencilMaskSeparate.
    pub fn stencil_mask_separate(&mut self, face: u32, mask: u32) {
        if self.reject_in_begin() {
            return;
        }
        let Some(faces) = Self::faces(face) else {
            self.set_error(GL_INVALID_ENUM);
            return;
        };
        for &f in faces {
            self.st.stencil[f].write_mask = mask;
        }
    }

    /// glAlphaFunc.
    pub fn alpha_func(&mut self, func: u32, reference: f32) {
        if self.reject_in_begin() {
            return;
        }
        if !valid_func(func) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.st.alpha_func = func;
        self.st.alpha_ref = clamp01(reference);
    }

    /// glColorMask.
    pub fn color_mask(&mut self, r: bool, g: bool, b: bool, a: bool) {
        if self.reject_in_begin() {
            return;
        }
        self.st.color_mask = [r, g, b, a];
    }

    // ---- rasterization ----

    /// glCullFace.
    pub fn cull_face(&mut self, mode: u32) {
        if self.reject_in_begin() {
            return;
        }
        if Self::faces(mode).is_none() {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.st.cull_face = mode;
    }

    /// glFrontFace.
    pub fn front_face(&mut self, mode: u32) {
        if self.reject_in_begin() {
            return;
        }
        if mode != GL_CW && mode != GL_CCW {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.st.front_face = mode;
    }

    /// glPolygonMode.
    pub fn polygon_mode(&mut self, face: u32, mode: u32) {
        if self.reject_in_begin() {
            return;
        }
        let Some(faces) = Self::faces(face) else {
            self.set_error(GL_INVALID_ENUM);
            return;
        };
        if !matches!(mode, GL_POINT | GL_LINE | GL_FILL) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        for &f in faces {
            self.st.polygon_mode[f] = mode;
        }
    }

    /// glPolygonOffset.
    pub fn polygon_offset(&mut self, factor: f32, units: f32) {
        if self.reject_in_begin() {
            return;
        }
        self.st.polygon_offset = [factor, units];
    }

    /// glShadeModel.
    pub fn shade_model(&mut self, mode: u32) {
        if self.reject_in_begin() {
            return;
        }
        if mode != GL_FLAT && mode != GL_SMOOTH {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.st.shade_model = mode;
    }

    /// glPointSize.
    pub fn point_size(&mut self, size: f32) {
        if self.reject_in_begin() {
            return;
        }
        if size.is_nan() || size <= 0.0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        self.st.point.size = size;
    }

    /// glLineWidth.
    pub fn line_width(&mut self, width: f32) {
        if self.reject_in_begin() {
            return;
        }
        if width.is_nan() || width <= 0.0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        self.st.line_width = width;
    }

    /// glPointParameterf.
    pub fn point_parameterf(&mut self, pname: u32, v: f32) {
        self.point_parameterfv(pname, &[v]);
    }

    /// glPointParameteri.
    pub fn point_parameteri(&mut self, pname: u32, v: i32) {
        self.point_parameterfv(pname, &[v as f32]);
    }

    /// glPointParameterfv.
    pub fn point_parameterfv(&mut self, pname: u32, v: &[f32]) {
        if self.reject_in_begin() {
            return;
        }
        let need = if pname == GL_POINT_DISTANCE_ATTENUATION {
            3
        } else {
            1
        };
        if v.len() < need {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let x = v[0];
        let p = &mut self.st.point;
        match pname {
            GL_POINT_SIZE_MIN | GL_POINT_SIZE_MAX | GL_POINT_FADE_THRESHOLD_SIZE if x < 0.0 => {
                self.set_error(GL_INVALID_VALUE)
            }
            GL_POINT_SIZE_MIN => p.size_min = x,
            GL_POINT_SIZE_MAX => p.size_max = x,
            GL_POINT_FADE_THRESHOLD_SIZE => p.fade_threshold = x,
            GL_POINT_DISTANCE_ATTENUATION => p.attenuation = [v[0], v[1], v[2]],
            GL_POINT_SPRITE_COORD_ORIGIN => {
                let o = x as u32;
                if o == GL_LOWER_LEFT || o == GL_UPPER_LEFT {
                    p.sprite_origin = o;
                } else {
                    self.set_error(GL_INVALID_VALUE);
                }
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glPixelStorei.
    pub fn pixel_storei(&mut self, pname: u32, v: i32) {
        if self.reject_in_begin() {
            return;
        }
        match pname {
            GL_UNPACK_ALIGNMENT | GL_PACK_ALIGNMENT => {
                if ![1, 2, 4, 8].contains(&v) {
                    self.set_error(GL_INVALID_VALUE);
                } else if pname == GL_UNPACK_ALIGNMENT {
                    self.st.unpack_alignment = v;
                } else {
                    self.st.pack_alignment = v;
                }
            }
            GL_UNPACK_ROW_LENGTH
            | GL_UNPACK_SKIP_ROWS
            | GL_UNPACK_SKIP_PIXELS
            | GL_PACK_ROW_LENGTH
            | GL_PACK_SKIP_ROWS
            | GL_PACK_SKIP_PIXELS
            | GL_UNPACK_IMAGE_HEIGHT
            | GL_UNPACK_SKIP_IMAGES
            | GL_PACK_IMAGE_HEIGHT
            | GL_PACK_SKIP_IMAGES => {
                // Accepted; only 0 (the default) is implemented.
                if v < 0 {
                    self.set_error(GL_INVALID_VALUE);
                }
            }
            GL_UNPACK_SWAP_BYTES | GL_UNPACK_LSB_FIRST | GL_PACK_SWAP_BYTES | GL_PACK_LSB_FIRST => {
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glHint (accepted and ignored).
    pub fn hint(&mut self, target: u32, mode: u32) {
        if self.reject_in_begin() {
            return;
        }
        let target_ok = matches!(
            target,
            GL_PERSPECTIVE_CORRECTION_HINT
                | GL_POINT_SMOOTH_HINT
                | GL_LINE_SMOOTH_HINT
                | GL_POLYGON_SMOOTH_HINT
                | GL_FOG_HINT
                | GL_GENERATE_MIPMAP_HINT
                | GL_TEXTURE_COMPRESSION_HINT
                | GL_FRAGMENT_SHADER_DERIVATIVE_HINT
        );
        if !target_ok || !matches!(mode, GL_FASTEST | GL_NICEST | GL_DONT_CARE) {
            self.set_error(GL_INVALID_ENUM);
        }
    }

    // ---- lighting ----

    /// glLightf.
    pub fn lightf(&mut self, light: u32, pname: u32, v: f32) {
        if light_param_len(pname) != 1 {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.lightfv(light, pname, &[v]);
    }

    /// glLighti.
    pub fn lighti(&mut self, light: u32, pname: u32, v: i32) {
        self.lightf(light, pname, v as f32);
    }

    /// glLightfv. GL_POSITION is transformed by the model-view matrix,
    /// GL_SPOT_DIRECTION by its upper 3x3 (GL 2.1 §2.14.2).
    pub fn lightfv(&mut self, light: u32, pname: u32, v: &[f32]) {
        if self.reject_in_begin() {
            return;
        }
        let i = light.wrapping_sub(GL_LIGHT0) as usize;
        if i >= MAX_LIGHTS {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if v.len() < light_param_len(pname) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let mv = self.modelview_matrix();
        let l = &mut self.st.lights[i];
        let v4 = || [v[0], v[1], v[2], v[3]];
        match pname {
            GL_AMBIENT => l.ambient = v4(),
            GL_DIFFUSE => l.diffuse = v4(),
            GL_SPECULAR => l.specular = v4(),
            GL_POSITION => l.position = matrix::mul_vec(&mv, v4()),
            GL_SPOT_DIRECTION => {
                let d = matrix::mul_vec(&mv, [v[0], v[1], v[2], 0.0]);
                l.spot_direction = [d[0], d[1], d[2]];
            }
            GL_SPOT_EXPONENT => {
                if !(0.0..=128.0).contains(&v[0]) {
                    self.set_error(GL_INVALID_VALUE);
                } else {
                    l.spot_exponent = v[0];
                }
            }
            GL_SPOT_CUTOFF => {
                if !((0.0..=90.0).contains(&v[0]) || v[0] == 180.0) {
                    self.set_error(GL_INVALID_VALUE);
                } else {
                    l.spot_cutoff = v[0];
                }
            }
            GL_CONSTANT_ATTENUATION | GL_LINEAR_ATTENUATION | GL_QUADRATIC_ATTENUATION => {
                if v[0].is_nan() || v[0] < 0.0 {
                    self.set_error(GL_INVALID_VALUE);
                } else {
                    l.attenuation[(pname - GL_CONSTANT_ATTENUATION) as usize] = v[0];
                }
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glLightiv (colors map [-2^31, 2^31-1] to [-1, 1]).
    pub fn lightiv(&mut self, light: u32, pname: u32, v: &[i32]) {
        let f = int_params(pname, v);
        self.lightfv(light, pname, &f);
    }

    /// glGetLightfv (position and direction in eye coordinates).
    pub fn get_lightfv(&mut self, light: u32, pname: u32) -> Vec<f32> {
        let i = light.wrapping_sub(GL_LIGHT0) as usize;
        let Some(l) = self.st.lights.get(i) else {
            self.set_error(GL_INVALID_ENUM);
            return Vec::new();
        };
        match pname {
            GL_AMBIENT => l.ambient.to_vec(),
            GL_DIFFUSE => l.diffuse.to_vec(),
            GL_SPECULAR => l.specular.to_vec(),
            GL_POSITION => l.position.to_vec(),
            GL_SPOT_DIRECTION => l.spot_direction.to_vec(),
            GL_SPOT_EXPONENT => vec![l.spot_exponent],
            GL_SPOT_CUTOFF => vec![l.spot_cutoff],
            GL_CONSTANT_ATTENUATION => vec![l.attenuation[0]],
            GL_LINEAR_ATTENUATION => vec![l.attenuation[1]],
            GL_QUADRATIC_ATTENUATION => vec![l.attenuation[2]],
            _ => {
                self.set_error(GL_INVALID_ENUM);
                Vec::new()
            }
        }
    }

    /// glMaterialf.
    pub fn materialf(&mut self, face: u32, pname: u32, v: f32) {
        if pname != GL_SHININESS {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.materialfv(face, pname, &[v]);
    }

    /// glMateriali.
    pub fn materiali(&mut self, face: u32, pname: u32, v: i32) {
        self.materialf(face, pname, v as f32);
    }

    /// glMaterialfv.
    pub fn materialfv(&mut self, face: u32, pname: u32, v: &[f32]) {
        let Some(faces) = Self::faces(face) else {
            self.set_error(GL_INVALID_ENUM);
            return;
        };
        if v.len() < light_param_len(pname) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let v4 = || [v[0], v[1], v[2], v[3]];
        if pname == GL_SHININESS && !(0.0..=128.0).contains(&v[0]) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        for &f in faces {
            let m = &mut self.st.material[f];
            match pname {
                GL_AMBIENT => m.ambient = v4(),
                GL_DIFFUSE => m.diffuse = v4(),
                GL_SPECULAR => m.specular = v4(),
                GL_EMISSION => m.emission = v4(),
                GL_AMBIENT_AND_DIFFUSE => {
                    m.ambient = v4();
                    m.diffuse = v4();
                }
                GL_SHININESS => m.shininess = v[0],
                GL_COLOR_INDEXES => {}
                _ => {
                    self.set_error(GL_INVALID_ENUM);
                    return;
                }
            }
        }
    }

    /// glMaterialiv.
    pub fn materialiv(&mut self, face: u32, pname: u32, v: &[i32]) {
        let f = int_params(pname, v);
        self.materialfv(face, pname, &f);
    }

    /// glGetMaterialfv.
    pub fn get_materialfv(&mut self, face: u32, pname: u32) -> Vec<f32> {
        let m = match face {
            GL_FRONT => self.st.material[0],
            GL_BACK => self.st.material[1],
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return Vec::new();
            }
        };
        match pname {
            GL_AMBIENT => m.ambient.to_vec(),
            GL_DIFFUSE => m.diffuse.to_vec(),
            GL_SPECULAR => m.specular.to_vec(),
            GL_EMISSION => m.emission.to_vec(),
            GL_SHININESS => vec![m.shininess],
            _ => {
                self.set_error(GL_INVALID_ENUM);
                Vec::new()
            }
        }
    }

    /// glColorMaterial.
    pub fn color_material(&mut self, face: u32, mode: u32) {
        if self.reject_in_begin() {
            return;
        }
        if Self::faces(face).is_none()
            || !matches!(
                mode,
                GL_EMISSION | GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_AMBIENT_AND_DIFFUSE
            )
        {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.st.color_material_face = face;
        self.st.color_material_mode = mode;
        if self.st.is_on(GL_COLOR_MATERIAL) {
            self.track_color_material();
        }
    }

    /// With GL_COLOR_MATERIAL on, the selected material colors follow the
    /// current color (GL 2.1 §2.14.3).
    pub(crate) fn track_color_material(&mut self) {
        if !self.st.is_on(GL_COLOR_MATERIAL) {
            return;
        }
        let c = self.va.current_color();
        let faces = Self::faces(self.st.color_material_face).unwrap_or(&[0, 1]);
        for &f in faces {
            let m = &mut self.st.material[f];
            match self.st.color_material_mode {
                GL_EMISSION => m.emission = c,
                GL_AMBIENT => m.ambient = c,
                GL_DIFFUSE => m.diffuse = c,
                GL_SPECULAR => m.specular = c,
                _ => {
                    m.ambient = c;
                    m.diffuse = c;
                }
            }
        }
    }

    /// glLightModelf.
    pub fn light_modelf(&mut self, pname: u32, v: f32) {
        if pname == GL_LIGHT_MODEL_AMBIENT {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.light_modelfv(pname, &[v]);
    }

    /// glLightModeli.
    pub fn light_modeli(&mut self, pname: u32, v: i32) {
        if pname == GL_LIGHT_MODEL_AMBIENT {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.light_model_values(pname, &[v as f32], v as u32);
    }

    /// glLightModelfv.
    pub fn light_modelfv(&mut self, pname: u32, v: &[f32]) {
        let e = v.first().map(|&x| x as u32).unwrap_or(0);
        self.light_model_values(pname, v, e);
    }

    /// glLightModeliv.
    pub fn light_modeliv(&mut self, pname: u32, v: &[i32]) {
        let f = int_params(pname, v);
        let e = v.first().map(|&x| x as u32).unwrap_or(0);
        self.light_model_values(pname, &f, e);
    }

    fn light_model_values(&mut self, pname: u32, v: &[f32], as_enum: u32) {
        if self.reject_in_begin() {
            return;
        }
        if v.len() < light_param_len(pname) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        match pname {
            GL_LIGHT_MODEL_AMBIENT => self.st.light_model_ambient = [v[0], v[1], v[2], v[3]],
            GL_LIGHT_MODEL_LOCAL_VIEWER => self.st.light_model_local_viewer = v[0] != 0.0,
            GL_LIGHT_MODEL_TWO_SIDE => self.st.light_model_two_side = v[0] != 0.0,
            GL_LIGHT_MODEL_COLOR_CONTROL => {
                if as_enum == GL_SINGLE_COLOR || as_enum == GL_SEPARATE_SPECULAR_COLOR {
                    self.st.light_model_color_control = as_enum;
                } else {
                    self.set_error(GL_INVALID_ENUM);
                }
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    // ---- fog ----

    /// glFogf.
    pub fn fogf(&mut self, pname: u32, v: f32) {
        if pname == GL_FOG_COLOR {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.fog_values(pname, &[v], v as u32);
    }

    /// glFogi.
    pub fn fogi(&mut self, pname: u32, v: i32) {
        if pname == GL_FOG_COLOR {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.fog_values(pname, &[v as f32], v as u32);
    }

    /// glFogfv.
    pub fn fogfv(&mut self, pname: u32, v: &[f32]) {
        let e = v.first().map(|&x| x as u32).unwrap_or(0);
        self.fog_values(pname, v, e);
    }

    /// glFogiv.
    pub fn fogiv(&mut self, pname: u32, v: &[i32]) {
        let f = int_params(pname, v);
        let e = v.first().map(|&x| x as u32).unwrap_or(0);
        self.fog_values(pname, &f, e);
    }

    fn fog_values(&mut self, pname: u32, v: &[f32], as_enum: u32) {
        if self.reject_in_begin() {
            return;
        }
        if v.len() < light_param_len(pname) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let fog = &mut self.st.fog;
        match pname {
            GL_FOG_MODE => {
                if matches!(as_enum, GL_LINEAR | GL_EXP | GL_EXP2) {
                    fog.mode = as_enum;
                } else {
                    self.set_error(GL_INVALID_ENUM);
                }
            }
            GL_FOG_DENSITY => {
                if v[0].is_nan() || v[0] < 0.0 {
                    self.set_error(GL_INVALID_VALUE);
                } else {
                    fog.density = v[0];
                }
            }
            GL_FOG_START => fog.start = v[0],
            GL_FOG_END => fog.end = v[0],
            GL_FOG_INDEX => {}
            GL_FOG_COLOR => fog.color = [v[0], v[1], v[2], v[3]].map(clamp01),
            GL_FOG_COORD_SRC => {
                if as_enum == GL_FOG_COORD || as_enum == GL_FRAGMENT_DEPTH {
                    fog.coord_src = as_enum;
                } else {
                    self.set_error(GL_INVALID_ENUM);
                }
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    // ---- texture environment and coordinate generation ----

    /// glTexEnvi.
    pub fn tex_envi(&mut self, target: u32, pname: u32, v: i32) {
        self.tex_env_values(target, pname, &[v as f32], v as u32);
    }

    /// glTexEnvf.
    pub fn tex_envf(&mut self, target: u32, pname: u32, v: f32) {
        self.tex_env_values(target, pname, &[v], v as u32);
    }

    /// glTexEnvfv.
    pub fn tex_envfv(&mut self, target: u32, pname: u32, v: &[f32]) {
        let e = v.first().map(|&x| x as u32).unwrap_or(0);
        self.tex_env_values(target, pname, v, e);
    }

    /// glTexEnviv.
    pub fn tex_enviv(&mut self, target: u32, pname: u32, v: &[i32]) {
        let f = if pname == GL_TEXTURE_ENV_COLOR {
            v.iter().map(|&x| int_to_unit(x)).collect()
        } else {
            v.iter().map(|&x| x as f32).collect::<Vec<_>>()
        };
        let e = v.first().map(|&x| x as u32).unwrap_or(0);
        self.tex_env_values(target, pname, &f, e);
    }

    fn tex_env_values(&mut self, target: u32, pname: u32, v: &[f32], as_enum: u32) {
        if self.reject_in_begin() {
            return;
        }
        let unit = self.st.active_texture as usize;
        let need = if pname == GL_TEXTURE_ENV_COLOR { 4 } else { 1 };
        if v.len() < need {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let Some(env) = self.st.tex_env.get_mut(unit) else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        match (target, pname) {
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) => {
                if matches!(
                    as_enum,
                    GL_MODULATE | GL_DECAL | GL_BLEND | GL_REPLACE | GL_ADD | GL_COMBINE
                ) {
                    env.mode = as_enum;
                } else {
                    self.set_error(GL_INVALID_ENUM);
                }
            }
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR) => {
                env.color = [v[0], v[1], v[2], v[3]].map(clamp01);
            }
            (GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS) => env.lod_bias = v[0],
            (GL_POINT_SPRITE, GL_COORD_REPLACE) => env.coord_replace = v[0] != 0.0,
            (GL_TEXTURE_ENV, GL_ALPHA_SCALE) => env.alpha_scale = v[0],
            (GL_TEXTURE_ENV, _) => {
                // GL_COMBINE's sources and operands are kept for queries
                // but not applied.
                match env
                    .combine
                    .get_mut(pname.wrapping_sub(GL_COMBINE_RGB) as usize)
                {
                    Some(x) => *x = v[0],
                    None => self.set_error(GL_INVALID_ENUM),
                }
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glGetTexEnvfv (enum values as floats).
    pub fn get_tex_envfv(&mut self, target: u32, pname: u32) -> Vec<f32> {
        if self.reject_in_begin() {
            return Vec::new();
        }
        let unit = self.st.active_texture as usize;
        let Some(env) = self.st.tex_env.get(unit).copied() else {
            self.set_error(GL_INVALID_OPERATION);
            return Vec::new();
        };
        match (target, pname) {
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) => vec![env.mode as f32],
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR) => env.color.to_vec(),
            (GL_TEXTURE_ENV, GL_ALPHA_SCALE) => vec![env.alpha_scale],
            (GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS) => vec![env.lod_bias],
            (GL_POINT_SPRITE, GL_COORD_REPLACE) => vec![env.coord_replace as i32 as f32],
            (GL_TEXTURE_ENV, _) => {
                match env.combine.get(pname.wrapping_sub(GL_COMBINE_RGB) as usize) {
                    Some(&x) => vec![x],
                    None => {
                        self.set_error(GL_INVALID_ENUM);
                        Vec::new()
                    }
                }
            }
            _ => {
                self.set_error(GL_INVALID_ENUM);
                Vec::new()
            }
        }
    }

    /// glGetTexGenfv (the eye plane as stored: in eye coordinates).
    pub fn get_tex_genfv(&mut self, coord: u32, pname: u32) -> Vec<f32> {
        if self.reject_in_begin() {
            return Vec::new();
        }
        let c = match coord {
            GL_S => 0,
            GL_T => 1,
            GL_R => 2,
            GL_Q => 3,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return Vec::new();
            }
        };
        let unit = self.st.active_texture as usize;
        let Some(g) = self.st.tex_gen.get(unit).map(|u| u[c]) else {
            self.set_error(GL_INVALID_OPERATION);
            return Vec::new();
        };
        match pname {
            GL_TEXTURE_GEN_MODE => vec![g.mode as f32],
            GL_OBJECT_PLANE => g.object_plane.to_vec(),
            GL_EYE_PLANE => g.eye_plane.to_vec(),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                Vec::new()
            }
        }
    }

    /// glTexGeni.
    pub fn tex_geni(&mut self, coord: u32, pname: u32, v: i32) {
        self.tex_gen_values(coord, pname, &[v as f32], v as u32);
    }

    /// glTexGenf.
    pub fn tex_genf(&mut self, coord: u32, pname: u32, v: f32) {
        self.tex_gen_values(coord, pname, &[v], v as u32);
    }

    /// glTexGenfv. GL_EYE_PLANE is transformed by the inverse model-view
    /// matrix (GL 2.1 §2.11.4).
    pub fn tex_genfv(&mut self, coord: u32, pname: u32, v: &[f32]) {
        let e = v.first().map(|&x| x as u32).unwrap_or(0);
        self.tex_gen_values(coord, pname, v, e);
    }

    fn tex_gen_values(&mut self, coord: u32, pname: u32, v: &[f32], as_enum: u32) {
        if self.reject_in_begin() {
            return;
        }
        let c = match coord {
            GL_S => 0,
            GL_T => 1,
            GL_R => 2,
            GL_Q => 3,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return;
            }
        };
        let unit = self.st.active_texture as usize;
        if unit >= MAX_TEXTURE_UNITS {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let need = if pname == GL_TEXTURE_GEN_MODE { 1 } else { 4 };
        if v.len() < need {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let inv = matrix::inverse_or_identity(&self.modelview_matrix());
        let g = &mut self.st.tex_gen[unit][c];
        match pname {
            GL_TEXTURE_GEN_MODE => {
                let ok = match as_enum {
                    GL_OBJECT_LINEAR | GL_EYE_LINEAR => true,
                    GL_SPHERE_MAP => c < 2,
                    GL_NORMAL_MAP | GL_REFLECTION_MAP => c < 3,
                    _ => false,
                };
                if ok {
                    g.mode = as_enum;
                } else {
                    self.set_error(GL_INVALID_ENUM);
                }
            }
            GL_OBJECT_PLANE => g.object_plane = [v[0], v[1], v[2], v[3]],
            GL_EYE_PLANE => g.eye_plane = matrix::vec_mul([v[0], v[1], v[2], v[3]], &inv),
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glActiveTexture.
    pub fn active_texture(&mut self, unit: u32) {
        if self.reject_in_begin() {
            return;
        }
        let i = unit.wrapping_sub(GL_TEXTURE0);
        if i as usize >= crate::MAX_TEXTURE_IMAGE_UNITS {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.st.active_texture = i;
    }
}

/// Integer parameters as floats: colors map the integer range linearly to
/// [-1, 1] (GL 2.1 §2.14.2, Table 2.9), everything else converts directly.
fn int_params(pname: u32, v: &[i32]) -> Vec<f32> {
    let color = matches!(
        pname,
        GL_AMBIENT
            | GL_DIFFUSE
            | GL_SPECULAR
            | GL_EMISSION
            | GL_AMBIENT_AND_DIFFUSE
            | GL_LIGHT_MODEL_AMBIENT
            | GL_FOG_COLOR
    );
    v.iter()
        .map(|&x| if color { int_to_unit(x) } else { x as f32 })
        .collect()
}

/// c = (2x + 1) / (2^32 - 1) (GL 2.1 Table 2.9).
pub fn int_to_unit(x: i32) -> f32 {
    ((2.0 * x as f64 + 1.0) / 4294967295.0) as f32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matrix_stack_errors() {
        let mut ctx = Context::new(4, 4);
        ctx.pop_matrix();
        assert_eq!(ctx.get_error(), GL_STACK_UNDERFLOW);
        for _ in 0..crate::MAX_MATRIX_STACK_DEPTH - 1 {
            ctx.push_matrix();
        }
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.push_matrix();
        assert_eq!(ctx.get_error(), GL_STACK_OVERFLOW);
        ctx.matrix_mode(GL_PROJECTION);
        ctx.ortho(0.0, 0.0, 0.0, 1.0, -1.0, 1.0);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.frustum(-1.0, 1.0, -1.0, 1.0, 0.0, 1.0);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.matrix_mode(0x1234);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn matrices_compose_in_gl_order() {
        let mut ctx = Context::new(4, 4);
        ctx.translatef(1.0, 0.0, 0.0);
        ctx.scalef(2.0, 2.0, 2.0);
        let v = matrix::mul_vec(&ctx.modelview_matrix(), [1.0, 1.0, 0.0, 1.0]);
        assert_eq!(v, [3.0, 2.0, 0.0, 1.0]);
        ctx.matrix_mode(GL_TEXTURE);
        ctx.active_texture(GL_TEXTURE0 + 2);
        ctx.scalef(3.0, 1.0, 1.0);
        assert_eq!(ctx.texture_matrix(2)[0], 3.0);
        assert_eq!(ctx.texture_matrix(0)[0], 1.0);
    }

    #[test]
    fn light_position_goes_to_eye_space() {
        let mut ctx = Context::new(4, 4);
        ctx.translatef(0.0, 0.0, -5.0);
        ctx.lightfv(GL_LIGHT1, GL_POSITION, &[1.0, 2.0, 3.0, 1.0]);
        assert_eq!(
            ctx.get_lightfv(GL_LIGHT1, GL_POSITION),
            vec![1.0, 2.0, -2.0, 1.0]
        );
        // Directions ignore the translation.
        ctx.lightfv(GL_LIGHT1, GL_SPOT_DIRECTION, &[0.0, 1.0, 0.0]);
        assert_eq!(
            ctx.get_lightfv(GL_LIGHT1, GL_SPOT_DIRECTION),
            vec![0.0, 1.0, 0.0]
        );
        ctx.lightf(GL_LIGHT1, GL_SPOT_CUTOFF, 95.0);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.lightf(GL_LIGHT1, GL_POSITION, 1.0);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.lightfv(GL_LIGHT0 + 8, GL_AMBIENT, &[0.0; 4]);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.lightfv(GL_LIGHT0, GL_AMBIENT, &[0.0; 2]);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    }

    #[test]
    fn clip_plane_in_eye_space() {
        let mut ctx = Context::new(4, 4);
        ctx.translatef(0.0, 0.0, 2.0);
        ctx.clip_plane(GL_CLIP_PLANE0 + 1, &[0.0, 0.0, 1.0, -1.0]);
        assert_eq!(ctx.get_clip_plane(GL_CLIP_PLANE1), [0.0, 0.0, 1.0, -3.0]);
        ctx.clip_plane(GL_CLIP_PLANE0 + 8, &[0.0; 4]);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    }

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
        ctx.fogi(GL_FOG_MODE, GL_LINEAR as i32);
        assert_eq!(ctx.st.fog.mode, GL_LINEAR);
        ctx.fogi(GL_FOG_MODE, GL_ONE as i32);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.tex_geni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.active_texture(GL_TEXTURE0 + 40);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn color_material_tracks_current_color() {
        let mut ctx = Context::new(4, 4);
        ctx.color_4f(0.5, 0.25, 1.0, 1.0);
        ctx.enable(GL_COLOR_MATERIAL);
        assert_eq!(ctx.st.material[0].diffuse, [0.5, 0.25, 1.0, 1.0]);
        assert_eq!(ctx.st.material[1].ambient, [0.5, 0.25, 1.0, 1.0]);
        ctx.color_material(GL_FRONT, GL_EMISSION);
        ctx.color_4f(0.0, 1.0, 0.0, 1.0);
        assert_eq!(ctx.st.material[0].emission, [0.0, 1.0, 0.0, 1.0]);
        assert_eq!(ctx.st.material[1].emission, [0.0, 0.0, 0.0, 1.0]);
    }
}
