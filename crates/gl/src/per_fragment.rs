//! Per-fragment operation state (GL 2.1 §4.1, §4.2.3): clear values,
//! blending, logic op, depth, stencil and alpha tests, and the write
//! masks.
//!
//! Contract: functions, operations and factors are checked against GL
//! 2.1's lists (Tables 4.1-4.2; GL_SRC_ALPHA_SATURATE is a source factor
//! only), with GL 3.3's SRC1 factors (dual-source blending) in 3.3
//! contexts; colors and depth values are clamped to [0, 1] when set.

use crate::enums::*;
use crate::state::clamp01;
use crate::Context;

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

/// Whether `f` is a blend factor; the second source colour's (GL 3.3
/// dual-source blending) only when `dual`.
fn valid_blend_factor(f: u32, is_src: bool, dual: bool) -> bool {
    (dual
        && matches!(
            f,
            GL_SRC1_COLOR | GL_ONE_MINUS_SRC1_COLOR | GL_SRC1_ALPHA | GL_ONE_MINUS_SRC1_ALPHA
        ))
        || matches!(
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
        )
        || (f == GL_SRC_ALPHA_SATURATE && is_src)
}

fn valid_blend_eq(e: u32) -> bool {
    matches!(
        e,
        GL_FUNC_ADD | GL_FUNC_SUBTRACT | GL_FUNC_REVERSE_SUBTRACT | GL_MIN | GL_MAX
    )
}

/// Whether a glClampColor setting `mode` clamps when the buffers it
/// concerns are all fixed-point (`fixed`) or not.
pub(crate) fn clamp_applies(mode: u32, fixed: bool) -> bool {
    match mode {
        GL_FIXED_ONLY => fixed,
        m => m != GL_FALSE,
    }
}

impl Context {
    /// glClampColor (GL 3.0 §3.7.5, §4.3.2, §2.13.6): `clamp` is GL_TRUE,
    /// GL_FALSE or GL_FIXED_ONLY; the targets are GL_CLAMP_READ_COLOR and,
    /// outside the core profile (GL 3.3 core E.2.2), GL_CLAMP_VERTEX_COLOR
    /// and GL_CLAMP_FRAGMENT_COLOR. Anything else is GL_INVALID_ENUM, as
    /// is every target in a GL 2.1 context (which clamps colours always
    /// and reads them as stored).
    pub fn clamp_color(&mut self, target: u32, clamp: u32) {
        if self.reject_in_begin() {
            return;
        }
        if !self.api.at_least(3, 0) || !matches!(clamp, GL_FIXED_ONLY | GL_TRUE | GL_FALSE) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let core = self.api.is_core();
        match target {
            GL_CLAMP_READ_COLOR => self.st.clamp_read_color = clamp,
            GL_CLAMP_VERTEX_COLOR if !core => self.st.clamp_vertex_color = clamp,
            GL_CLAMP_FRAGMENT_COLOR if !core => self.st.clamp_fragment_color = clamp,
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glClearColor: clamped to [0, 1] in a GL 2.1 context (GL 2.1
    /// §4.2.3); from GL 3.0 on stored as given (GL 3.3 compatibility
    /// §4.2.3: "stored as floating-point values"), so that a floating-point
    /// buffer clears to any value. Clearing a normalized buffer clamps
    /// each component then.
    pub fn clear_color(&mut self, r: f32, g: f32, b: f32, a: f32) {
        if self.reject_in_begin() {
            return;
        }
        let c = [r, g, b, a];
        self.st.clear_color = if self.api.at_least(3, 0) {
            c
        } else {
            c.map(clamp01)
        };
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

    /// glBlendFunc.
    pub fn blend_func(&mut self, src: u32, dst: u32) {
        self.blend_func_separate(src, dst, src, dst);
    }

    /// glBlendFuncSeparate.
    pub fn blend_func_separate(&mut self, src_rgb: u32, dst_rgb: u32, src_a: u32, dst_a: u32) {
        let dual = self.api.at_least(3, 3);
        let valid = valid_blend_factor(src_rgb, true, dual)
            && valid_blend_factor(dst_rgb, false, dual)
            && valid_blend_factor(src_a, true, dual)
            && valid_blend_factor(dst_a, false, dual);
        if self.setter_accepts(valid, GL_INVALID_ENUM) {
            self.st.blend_src = [src_rgb, src_a];
            self.st.blend_dst = [dst_rgb, dst_a];
        }
    }

    /// glBlendEquation.
    pub fn blend_equation(&mut self, mode: u32) {
        self.blend_equation_separate(mode, mode);
    }

    /// glBlendEquationSeparate.
    pub fn blend_equation_separate(&mut self, rgb: u32, alpha: u32) {
        let valid = valid_blend_eq(rgb) && valid_blend_eq(alpha);
        if self.setter_accepts(valid, GL_INVALID_ENUM) {
            self.st.blend_eq = [rgb, alpha];
        }
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
        if self.setter_accepts((GL_CLEAR..=GL_SET).contains(&op), GL_INVALID_ENUM) {
            self.st.logic_op = op;
        }
    }

    /// glDepthFunc.
    pub fn depth_func(&mut self, func: u32) {
        if self.setter_accepts(valid_func(func), GL_INVALID_ENUM) {
            self.st.depth_func = func;
        }
    }

    /// glDepthMask.
    pub fn depth_mask(&mut self, flag: bool) {
        if self.reject_in_begin() {
            return;
        }
        self.st.depth_mask = flag;
    }

    /// glStencilFunc.
    pub fn stencil_func(&mut self, func: u32, reference: i32, mask: u32) {
        self.stencil_func_separate(GL_FRONT_AND_BACK, func, reference, mask);
    }

    /// glStencilFuncSeparate.
    pub fn stencil_func_separate(&mut self, face: u32, func: u32, reference: i32, mask: u32) {
        let faces = Self::faces(face).filter(|_| valid_func(func));
        if !self.setter_accepts(faces.is_some(), GL_INVALID_ENUM) {
            return;
        }
        for &f in faces.unwrap_or_default() {
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
        let valid_ops = [fail, zfail, zpass].iter().all(|&o| valid_stencil_op(o));
        let faces = Self::faces(face).filter(|_| valid_ops);
        if !self.setter_accepts(faces.is_some(), GL_INVALID_ENUM) {
            return;
        }
        for &f in faces.unwrap_or_default() {
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
        if self.setter_accepts(valid_func(func), GL_INVALID_ENUM) {
            self.st.alpha_func = func;
            self.st.alpha_ref = clamp01(reference);
        }
    }

    /// glColorMask.
    pub fn color_mask(&mut self, r: bool, g: bool, b: bool, a: bool) {
        if self.reject_in_begin() {
            return;
        }
        self.st.color_masks = [[r, g, b, a]; crate::MAX_DRAW_BUFFERS];
    }
}
