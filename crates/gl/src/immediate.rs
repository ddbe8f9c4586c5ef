//! Current attribute values and immediate mode (GL 2.1 §2.7, §2.10, GL
//! 3.3 §2.7): glColor/glNormal/glTexCoord/glMultiTexCoord/glFogCoord/
//! glSecondaryColor, glVertexAttrib* and glVertexAttribI* current values
//! and their queries, and glBegin/glVertex/glEnd/glRect, which collect
//! vertices with the current values and draw them at glEnd.

use crate::enums::*;
use crate::vertex::MAX_IMMEDIATE_VERTICES;
use crate::vertex_format::{float_view, integer_bits, ValueKind};
use crate::{Context, MAX_VERTEX_ATTRIBS};

impl Context {
    /// glVertexAttribI4i (the other glVertexAttribI* forms fill in
    /// (0, 0, 0, 1) and call this or [`Context::vertex_attrib_i4ui`]).
    /// Index 0 inside glBegin/glEnd emits a vertex, as glVertexAttrib4f.
    pub fn vertex_attrib_i4i(&mut self, index: u32, v: [i32; 4]) {
        self.set_integer_attrib(index, v.map(|x| x as u32), ValueKind::Int);
    }

    /// glVertexAttribI4ui.
    pub fn vertex_attrib_i4ui(&mut self, index: u32, v: [u32; 4]) {
        self.set_integer_attrib(index, v, ValueKind::Uint);
    }

    fn set_integer_attrib(&mut self, index: u32, v: [u32; 4], kind: ValueKind) {
        if index as usize >= MAX_VERTEX_ATTRIBS {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let f = float_view(v.map(f32::from_bits), kind);
        if index == 0 {
            self.vertex_4f(f[0], f[1], f[2], f[3]);
        }
        self.va.generic[index as usize] = v.map(f32::from_bits);
        self.va.generic_kind[index as usize] = kind;
    }

    /// glGetVertexAttribI{i,ui}v with GL_CURRENT_VERTEX_ATTRIB: the
    /// current value's integer bits (a float value converted).
    pub fn get_current_vertex_attrib_integer(&mut self, index: u32, unsigned: bool) -> [u32; 4] {
        if index == 0 || index as usize >= MAX_VERTEX_ATTRIBS {
            self.set_error(if index == 0 {
                GL_INVALID_OPERATION
            } else {
                GL_INVALID_VALUE
            });
            return [0; 4];
        }
        let want = if unsigned {
            ValueKind::Uint
        } else {
            ValueKind::Int
        };
        integer_bits(
            self.va.generic[index as usize],
            self.va.generic_kind[index as usize],
            want,
        )
    }

    // ---- current values ----

    /// glColor4f.
    pub fn color_4f(&mut self, r: f32, g: f32, b: f32, a: f32) {
        self.va.color = [r, g, b, a];
        self.track_color_material();
    }

    /// glColor3f.
    pub fn color_3f(&mut self, r: f32, g: f32, b: f32) {
        self.color_4f(r, g, b, 1.0);
    }

    /// glColor4fv.
    pub fn color_4fv(&mut self, v: &[f32; 4]) {
        self.color_4f(v[0], v[1], v[2], v[3]);
    }

    /// glColor3fv.
    pub fn color_3fv(&mut self, v: &[f32; 3]) {
        self.color_4f(v[0], v[1], v[2], 1.0);
    }

    /// glColor4ub.
    pub fn color_4ub(&mut self, r: u8, g: u8, b: u8, a: u8) {
        let n = |x: u8| x as f32 / 255.0;
        self.color_4f(n(r), n(g), n(b), n(a));
    }

    /// glColor3ub.
    pub fn color_3ub(&mut self, r: u8, g: u8, b: u8) {
        self.color_4ub(r, g, b, 255);
    }

    /// glSecondaryColor3f.
    pub fn secondary_color_3f(&mut self, r: f32, g: f32, b: f32) {
        self.va.secondary = [r, g, b, 1.0];
    }

    /// glNormal3f.
    pub fn normal_3f(&mut self, x: f32, y: f32, z: f32) {
        self.va.normal = [x, y, z, 1.0];
    }

    /// glNormal3fv.
    pub fn normal_3fv(&mut self, v: &[f32; 3]) {
        self.normal_3f(v[0], v[1], v[2]);
    }

    /// glFogCoordf.
    pub fn fog_coordf(&mut self, f: f32) {
        self.va.fog = [f, 0.0, 0.0, 1.0];
    }

    /// glMultiTexCoord4f.
    pub fn multi_tex_coord_4f(&mut self, target: u32, s: f32, t: f32, r: f32, q: f32) {
        let i = target.wrapping_sub(GL_TEXTURE0) as usize;
        match self.va.tex.get_mut(i) {
            Some(c) => *c = [s, t, r, q],
            None => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glMultiTexCoord1f.
    pub fn multi_tex_coord_1f(&mut self, target: u32, s: f32) {
        self.multi_tex_coord_4f(target, s, 0.0, 0.0, 1.0);
    }

    /// glMultiTexCoord2f.
    pub fn multi_tex_coord_2f(&mut self, target: u32, s: f32, t: f32) {
        self.multi_tex_coord_4f(target, s, t, 0.0, 1.0);
    }

    /// glMultiTexCoord3f.
    pub fn multi_tex_coord_3f(&mut self, target: u32, s: f32, t: f32, r: f32) {
        self.multi_tex_coord_4f(target, s, t, r, 1.0);
    }

    /// glMultiTexCoord4fv.
    pub fn multi_tex_coord_4fv(&mut self, target: u32, v: &[f32; 4]) {
        self.multi_tex_coord_4f(target, v[0], v[1], v[2], v[3]);
    }

    /// glTexCoord4f (unit 0).
    pub fn tex_coord_4f(&mut self, s: f32, t: f32, r: f32, q: f32) {
        self.va.tex[0] = [s, t, r, q];
    }

    /// glTexCoord1f.
    pub fn tex_coord_1f(&mut self, s: f32) {
        self.tex_coord_4f(s, 0.0, 0.0, 1.0);
    }

    /// glTexCoord2f.
    pub fn tex_coord_2f(&mut self, s: f32, t: f32) {
        self.tex_coord_4f(s, t, 0.0, 1.0);
    }

    /// glTexCoord3f.
    pub fn tex_coord_3f(&mut self, s: f32, t: f32, r: f32) {
        self.tex_coord_4f(s, t, r, 1.0);
    }

    /// glTexCoord4fv.
    pub fn tex_coord_4fv(&mut self, v: &[f32; 4]) {
        self.tex_coord_4f(v[0], v[1], v[2], v[3]);
    }

    /// glVertexAttrib4f. Index 0 is the vertex position: inside
    /// glBegin/glEnd it emits a vertex (GL 2.1 §2.7).
    pub fn vertex_attrib_4f(&mut self, index: u32, x: f32, y: f32, z: f32, w: f32) {
        if index as usize >= MAX_VERTEX_ATTRIBS {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if index == 0 {
            self.vertex_4f(x, y, z, w);
        }
        self.va.generic[index as usize] = [x, y, z, w];
        self.va.generic_kind[index as usize] = ValueKind::Float;
    }

    /// glVertexAttrib1f.
    pub fn vertex_attrib_1f(&mut self, index: u32, x: f32) {
        self.vertex_attrib_4f(index, x, 0.0, 0.0, 1.0);
    }

    /// glVertexAttrib2f.
    pub fn vertex_attrib_2f(&mut self, index: u32, x: f32, y: f32) {
        self.vertex_attrib_4f(index, x, y, 0.0, 1.0);
    }

    /// glVertexAttrib3f.
    pub fn vertex_attrib_3f(&mut self, index: u32, x: f32, y: f32, z: f32) {
        self.vertex_attrib_4f(index, x, y, z, 1.0);
    }

    /// glVertexAttrib4fv.
    pub fn vertex_attrib_4fv(&mut self, index: u32, v: &[f32; 4]) {
        self.vertex_attrib_4f(index, v[0], v[1], v[2], v[3]);
    }

    /// glVertexAttrib4Nub.
    pub fn vertex_attrib_4nub(&mut self, index: u32, x: u8, y: u8, z: u8, w: u8) {
        let n = |v: u8| v as f32 / 255.0;
        self.vertex_attrib_4f(index, n(x), n(y), n(z), n(w));
    }

    /// glGetVertexAttribfv with GL_CURRENT_VERTEX_ATTRIB.
    pub fn get_current_vertex_attrib(&mut self, index: u32) -> [f32; 4] {
        if index == 0 || index as usize >= MAX_VERTEX_ATTRIBS {
            self.set_error(if index == 0 {
                GL_INVALID_OPERATION
            } else {
                GL_INVALID_VALUE
            });
            return [0.0; 4];
        }
        let i = index as usize;
        float_view(self.va.generic[i], self.va.generic_kind[i])
    }

    // ---- glBegin / glEnd ----

    /// glBegin.
    pub fn begin(&mut self, mode: u32) {
        if self.in_begin_end() {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        // The adjacency modes come with geometry shaders
        // (GL_EXT_geometry_shader4 adds them to glBegin).
        let adjacency = (GL_LINES_ADJACENCY..=GL_TRIANGLE_STRIP_ADJACENCY).contains(&mode);
        if mode > GL_POLYGON && !(adjacency && self.has_geometry_shaders()) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if !self.geometry_takes(mode) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        // The mode must make transform feedback's primitives while it
        // is active (GL 3.3 compatibility §2.20).
        if !self.feedback_allows(mode) {
            return;
        }
        self.va.begin_mode = Some(mode);
        self.va.immediate.clear();
    }

    /// glVertex4f: outside glBegin/glEnd it has no effect.
    pub fn vertex_4f(&mut self, x: f32, y: f32, z: f32, w: f32) {
        if self.va.begin_mode.is_some() && self.va.immediate.len() < MAX_IMMEDIATE_VERTICES {
            let v = self.va.snapshot([x, y, z, w]);
            self.va.immediate.push(v);
        }
    }

    /// glVertex2f.
    pub fn vertex_2f(&mut self, x: f32, y: f32) {
        self.vertex_4f(x, y, 0.0, 1.0);
    }

    /// glVertex3f.
    pub fn vertex_3f(&mut self, x: f32, y: f32, z: f32) {
        self.vertex_4f(x, y, z, 1.0);
    }

    /// glVertex3fv.
    pub fn vertex_3fv(&mut self, v: &[f32; 3]) {
        self.vertex_4f(v[0], v[1], v[2], 1.0);
    }

    /// glVertex4fv.
    pub fn vertex_4fv(&mut self, v: &[f32; 4]) {
        self.vertex_4f(v[0], v[1], v[2], v[3]);
    }

    /// glEnd: draws the recorded vertices.
    pub fn end(&mut self) {
        let Some(mode) = self.va.begin_mode.take() else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let verts = std::mem::take(&mut self.va.immediate);
        self.draw_immediate(mode, &verts);
    }

    /// glRectf: a polygon (x1,y1) (x2,y1) (x2,y2) (x1,y2) (GL 2.1 §2.10).
    pub fn rectf(&mut self, x1: f32, y1: f32, x2: f32, y2: f32) {
        if self.reject_in_begin() {
            return;
        }
        self.begin(GL_POLYGON);
        self.vertex_2f(x1, y1);
        self.vertex_2f(x2, y1);
        self.vertex_2f(x2, y2);
        self.vertex_2f(x1, y2);
        self.end();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn begin_end_records() {
        let mut ctx = Context::new(4, 4);
        ctx.end();
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.begin(GL_TRIANGLES);
        ctx.begin(GL_TRIANGLES);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.color_3f(1.0, 0.0, 0.0);
        ctx.vertex_2f(0.0, 0.0);
        ctx.enable(GL_BLEND);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.va.immediate.len(), 1);
        assert_eq!(ctx.va.immediate[0].color, [1.0, 0.0, 0.0, 1.0]);
        ctx.end();
        assert!(!ctx.in_begin_end());
    }
}
