//! Vertex transformation state (GL 2.1 §2.11, §2.12): the matrix stacks
//! and their operations, the viewport and depth range, user clip planes,
//! and the scissor box.
//!
//! Contract: matrix operations compose as GL specifies (the new matrix on
//! the right) in [`glsl::math`]'s deterministic arithmetic; clip planes
//! are stored in eye coordinates (transformed by the inverse modelview at
//! the call); stack overflow and underflow are GL_STACK_OVERFLOW /
//! GL_STACK_UNDERFLOW.

use crate::enums::*;
use crate::matrix::{self, Mat4};
use crate::state::clamp01;
use crate::{Context, MAX_CLIP_PLANES, MAX_TEXTURE_UNITS};

impl Context {
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
    fn clip_plane_in_eye_space() {
        let mut ctx = Context::new(4, 4);
        ctx.translatef(0.0, 0.0, 2.0);
        ctx.clip_plane(GL_CLIP_PLANE0 + 1, &[0.0, 0.0, 1.0, -1.0]);
        assert_eq!(ctx.get_clip_plane(GL_CLIP_PLANE1), [0.0, 0.0, 1.0, -3.0]);
        ctx.clip_plane(GL_CLIP_PLANE0 + 8, &[0.0; 4]);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    }
}
