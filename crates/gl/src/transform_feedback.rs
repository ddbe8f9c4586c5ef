//! Transform feedback (GL 3.3 §2.16, §2.11.6, §6.1.15): the outputs of
//! the last stage before rasterization (the geometry stage if the
//! program has one, else the vertex stage) named by
//! glTransformFeedbackVaryings written, per assembled or emitted
//! primitive, into the buffers bound to the GL_TRANSFORM_FEEDBACK_BUFFER
//! binding points, between glBeginTransformFeedback and
//! glEndTransformFeedback.
//!
//! Contract:
//! - glTransformFeedbackVaryings takes effect at the next link; the link
//!   fails when a name is not an output of the vertex stage (a whole
//!   variable, an element `v[i]` of an array, or one of the built-ins
//!   `gl_Position`, `gl_PointSize`, `gl_ClipVertex` the stage writes), when
//!   a name repeats, or when the components exceed
//!   GL_MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS (interleaved) or
//!   GL_MAX_TRANSFORM_FEEDBACK_SEPARATE_COMPONENTS per varying (separate).
//! - What is written: the vertex stage's outputs after vertex colour
//!   clamping, before clipping, for every primitive the draw assembles, in
//!   order, each as independent points, lines or triangles (strips, loops
//!   and fans decomposed, keeping each triangle's winding and the
//!   provoking vertex's place as the `restart` module does; quads and
//!   polygons of the compatibility profile as triangle fans). Each
//!   component is 4 bytes: a float's bits, or an integer's. Interleaved:
//!   one record of every varying in order per vertex into binding 0;
//!   separate: varying i into binding i. A primitive that does not fit in
//!   every buffer's bound range is not written, nor counted by
//!   GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, and neither is any later
//!   one of the same glBeginTransformFeedback.
//! - The draw path pays nothing when feedback is inactive; when active it
//!   runs the vertex stage once more for the capture (before the draw's
//!   own, skipped with GL_RASTERIZER_DISCARD).

use crate::enums::*;
use crate::uniform::gl_type;
use crate::Context;
use glsl::types::{ArraySize, Base, Scalar, Type};

/// GL_MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS (GL 3.3's minimum).
pub const MAX_INTERLEAVED_COMPONENTS: usize = 64;
/// GL_MAX_TRANSFORM_FEEDBACK_SEPARATE_COMPONENTS (GL 3.3's minimum).
pub const MAX_SEPARATE_COMPONENTS: usize = 4;

/// One captured varying of a linked program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FeedbackVarying {
    /// As glTransformFeedbackVaryings named it.
    pub name: String,
    /// Its GL type (glGetTransformFeedbackVarying) and array size.
    pub ty: u32,
    pub size: i32,
    /// Its components in the vertex stage's outputs.
    pub offset: usize,
    pub components: usize,
    /// The scalar type of its components (how a value is written).
    pub scalar: Scalar,
}

/// The active transform feedback (GL 3.3 §2.16).
#[derive(Clone, Debug, Default)]
pub struct Feedback {
    /// Between glBeginTransformFeedback and glEndTransformFeedback.
    pub active: bool,
    /// GL_POINTS, GL_LINES or GL_TRIANGLES.
    pub mode: u32,
    /// Bytes written since glBeginTransformFeedback, per binding point.
    pub written: [usize; crate::buffers::MAX_TRANSFORM_FEEDBACK_BUFFERS],
    /// A primitive did not fit: nothing more is written.
    pub full: bool,
}

/// Resolves `names` against the vertex stage's outputs (see the module
/// docs); the error is the link's message.
pub(crate) fn resolve(
    vs: Option<&exec::Interface>,
    names: &[String],
    separate: bool,
) -> Result<Vec<FeedbackVarying>, String> {
    if names.is_empty() {
        return Ok(Vec::new());
    }
    let Some(iface) = vs else {
        return Err("transform feedback varyings need a vertex shader".into());
    };
    let mut out: Vec<FeedbackVarying> = Vec::new();
    for name in names {
        if out.iter().any(|v| &v.name == name) {
            return Err(format!(
                "transform feedback varying `{name}' is named twice"
            ));
        }
        let (base, index) = match name.strip_suffix(']').and_then(|n| n.split_once('[')) {
            Some((b, i)) => (b, Some(i.parse::<usize>().ok())),
            None => (name.as_str(), None),
        };
        let slot = iface
            .outputs
            .iter()
            .find(|s| s.name == base && (!s.name.starts_with("gl_") || s.written))
            .ok_or_else(|| {
                format!("transform feedback varying `{name}' is not a vertex shader output")
            })?;
        let elems = match slot.ty.array {
            Some(ArraySize::Sized(n)) => n as usize,
            _ => 1,
        };
        let element = Type {
            array: None,
            ..slot.ty
        };
        let per = slot.components / elems.max(1);
        let scalar = match slot.ty.base {
            Base::Scalar(s) | Base::Vector(s, _) => s,
            _ => Scalar::Float,
        };
        let v = match index {
            None => FeedbackVarying {
                name: name.clone(),
                ty: gl_type(element),
                size: elems as i32,
                offset: slot.offset,
                components: slot.components,
                scalar,
            },
            Some(Some(i)) if slot.ty.array.is_some() && i < elems => FeedbackVarying {
                name: name.clone(),
                ty: gl_type(element),
                size: 1,
                offset: slot.offset + i * per,
                components: per,
                scalar,
            },
            _ => {
                return Err(format!(
                    "transform feedback varying `{name}' is not a vertex shader output"
                ))
            }
        };
        if separate && v.components > MAX_SEPARATE_COMPONENTS {
            return Err(format!(
                "transform feedback varying `{name}' has more than {MAX_SEPARATE_COMPONENTS} components"
            ));
        }
        out.push(v);
    }
    let total: usize = out.iter().map(|v| v.components).sum();
    if !separate && total > MAX_INTERLEAVED_COMPONENTS {
        return Err(format!(
            "transform feedback varyings take {total} components, more than {MAX_INTERLEAVED_COMPONENTS}"
        ));
    }
    Ok(out)
}

/// The vertices (positions in the draw's index list) of each primitive
/// of `n` vertices of `mode`, as feedback writes them: independent
/// points, lines or triangles (`first`: the first-vertex provoking
/// convention).
pub(crate) fn decompose(mode: u32, n: usize, first: bool) -> Vec<usize> {
    let mut v = Vec::new();
    match mode {
        GL_POINTS => v.extend(0..n),
        GL_LINES => v.extend(0..n - n % 2),
        GL_LINE_STRIP | GL_LINE_LOOP if n >= 2 => {
            for k in 0..n - 1 {
                v.extend([k, k + 1]);
            }
            if mode == GL_LINE_LOOP {
                v.extend([n - 1, 0]);
            }
        }
        GL_TRIANGLES => v.extend(0..n - n % 3),
        GL_TRIANGLE_STRIP => {
            for k in 0..n.saturating_sub(2) {
                v.extend(match (k % 2, first) {
                    (0, _) => [k, k + 1, k + 2],
                    (_, true) => [k, k + 2, k + 1],
                    (_, false) => [k + 1, k, k + 2],
                });
            }
        }
        GL_TRIANGLE_FAN => {
            for k in 1..n.saturating_sub(1) {
                v.extend(if first { [k, k + 1, 0] } else { [0, k, k + 1] });
            }
        }
        GL_QUADS => {
            for q in 0..n / 4 {
                let b = 4 * q;
                v.extend([b, b + 1, b + 2, b, b + 2, b + 3]);
            }
        }
        GL_QUAD_STRIP => {
            for q in 0..(n / 2).saturating_sub(1) {
                let b = 2 * q;
                v.extend([b, b + 1, b + 3, b, b + 3, b + 2]);
            }
        }
        GL_POLYGON if n >= 3 => {
            for k in 1..n - 1 {
                v.extend([0, k, k + 1]);
            }
        }
        _ => {}
    }
    v
}

/// The feedback primitive mode a draw mode makes (GL 3.3 table 2.12).
pub(crate) fn feedback_mode(mode: u32) -> u32 {
    match mode {
        GL_POINTS => GL_POINTS,
        GL_LINES | GL_LINE_STRIP | GL_LINE_LOOP => GL_LINES,
        _ => GL_TRIANGLES,
    }
}

impl Context {
    /// Whether transform feedback is active.
    pub fn feedback_active(&self) -> bool {
        self.feedback.active
    }

    /// The current program's feedback varyings and buffer mode (none
    /// without a linked current program).
    fn current_feedback(&self) -> (&[FeedbackVarying], u32) {
        // The program of the last stage before rasterization
        // (GL_ARB_separate_shader_objects: with a pipeline, its geometry
        // stage's program, else its vertex stage's).
        match self
            .stage_executable(glsl::Stage::Geometry)
            .or_else(|| self.stage_executable(glsl::Stage::Vertex))
        {
            Some(e) => (&e.feedback, e.feedback_mode),
            None => (&[], GL_INTERLEAVED_ATTRIBS),
        }
    }

    /// glTransformFeedbackVaryings (used at the next link):
    /// GL_INVALID_VALUE for a negative count or more than
    /// GL_MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS separate varyings,
    /// GL_INVALID_ENUM for another buffer mode.
    pub fn transform_feedback_varyings(&mut self, program: u32, names: &[String], mode: u32) {
        if self.reject_in_begin() || !self.check_program(program) {
            return;
        }
        if mode != GL_INTERLEAVED_ATTRIBS && mode != GL_SEPARATE_ATTRIBS {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if mode == GL_SEPARATE_ATTRIBS
            && names.len() > crate::buffers::MAX_TRANSFORM_FEEDBACK_BUFFERS
        {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if let Some(p) = self.programs.get_mut(&program) {
            p.feedback_names = names.to_vec();
            p.feedback_mode = mode;
        }
    }

    /// glGetTransformFeedbackVarying: varying `index` of the last link
    /// (its name, array size and GL type); GL_INVALID_VALUE past them.
    pub fn get_transform_feedback_varying(
        &mut self,
        program: u32,
        index: u32,
    ) -> Option<FeedbackVarying> {
        let v = self.program_query(program, |p| {
            p.exe
                .as_ref()
                .and_then(|e| e.feedback.get(index as usize).cloned())
        })?;
        match v {
            Some(v) => Some(v),
            None => {
                self.set_error(GL_INVALID_VALUE);
                None
            }
        }
    }

    /// glBeginTransformFeedback(GL_POINTS / GL_LINES / GL_TRIANGLES):
    /// GL_INVALID_ENUM for another mode; GL_INVALID_OPERATION when active,
    /// without a current program capturing varyings, or with a binding
    /// point it writes unbound.
    pub fn begin_transform_feedback(&mut self, mode: u32) {
        if self.reject_in_begin() {
            return;
        }
        if !matches!(mode, GL_POINTS | GL_LINES | GL_TRIANGLES) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let needed = match self.current_feedback() {
            ([], _) => 0,
            (v, GL_SEPARATE_ATTRIBS) => v.len(),
            _ => 1,
        };
        let bound = &self.objects.buffer_targets.feedback_bindings;
        if self.feedback_active() || needed == 0 || bound[..needed].iter().any(|b| b.buffer == 0) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        self.feedback = Feedback {
            active: true,
            mode,
            ..Feedback::default()
        };
    }

    /// glEndTransformFeedback (GL_INVALID_OPERATION when not active).
    pub fn end_transform_feedback(&mut self) {
        if self.reject_in_begin() {
            return;
        }
        if !self.feedback_active() {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        self.feedback = Feedback::default();
    }

    /// A draw of `mode` while feedback is active must make its primitive
    /// type (GL_INVALID_OPERATION otherwise, recorded here).
    pub(crate) fn feedback_allows(&mut self, mode: u32) -> bool {
        // With a geometry stage its output primitive is what is captured
        // (GL 3.3 §2.16).
        let emitted = self.geometry_feedback_mode();
        let captured = emitted.unwrap_or_else(|| feedback_mode(mode));
        if self.feedback_active() && captured != self.feedback.mode {
            self.set_error(GL_INVALID_OPERATION);
            return false;
        }
        true
    }

    /// Writes the primitives of `indices` (of `mode`) into the feedback
    /// buffers, given the vertex stage's outputs (`vertex_of`, `outputs`,
    /// `stride`: [`raster::shade_vertices`]).
    pub(crate) fn capture_feedback(
        &mut self,
        mode: u32,
        (vertex_of, outputs, stride): (&[u32], &[f32], usize),
    ) {
        let (varyings, buffer_mode) = self.current_feedback();
        let (varyings, separate) = (varyings.to_vec(), buffer_mode == GL_SEPARATE_ATTRIBS);
        if self.feedback.full || varyings.is_empty() {
            return;
        }
        let per_prim = match self.feedback.mode {
            GL_POINTS => 1,
            GL_LINES => 2,
            _ => 3,
        };
        let order = decompose(mode, vertex_of.len(), self.provoking_first());
        // Each buffer's records: (binding, varyings written there).
        let buffers: Vec<(usize, Vec<&FeedbackVarying>)> = if separate {
            varyings
                .iter()
                .enumerate()
                .map(|(i, v)| (i, vec![v]))
                .collect()
        } else {
            vec![(0, varyings.iter().collect())]
        };
        // Room (bytes) left in each buffer's bound range.
        let mut room = Vec::new();
        let mut stores = Vec::new();
        for &(i, _) in &buffers {
            let ib = self.objects.buffer_targets.feedback_bindings[i];
            let store = self.buffer_store(ib.buffer);
            let start = (ib.offset.max(0) as usize).min(store.len());
            let end = match ib.size {
                Some(s) => start.saturating_add(s.max(0) as usize).min(store.len()),
                None => store.len(),
            };
            let at = start + self.feedback.written[i];
            room.push(end.saturating_sub(at));
            stores.push((ib.buffer, at, Vec::new()));
        }
        let mut written = 0u64;
        for prim in order.chunks_exact(per_prim) {
            let fits = buffers.iter().zip(&room).zip(&stores).all(|((b, r), s)| {
                let bytes: usize = b.1.iter().map(|v| v.components * 4).sum::<usize>() * per_prim;
                s.2.len() + bytes <= *r
            });
            if !fits {
                self.feedback.full = true;
                break;
            }
            for ((_, vars), s) in buffers.iter().zip(stores.iter_mut()) {
                for &p in prim {
                    let vertex = vertex_of.get(p).copied().unwrap_or(0) as usize;
                    let data = outputs
                        .get(vertex * stride..(vertex + 1) * stride)
                        .unwrap_or(&[]);
                    for v in vars {
                        for c in 0..v.components {
                            // The vertex stage's integer outputs are
                            // already their bits (exec's varying
                            // convention), as the buffer stores them.
                            let x = data.get(v.offset + c).copied().unwrap_or(0.0);
                            let bits = match v.scalar {
                                Scalar::Float | Scalar::Int | Scalar::Uint => x.to_bits(),
                                Scalar::Bool => (x != 0.0) as u32,
                            };
                            s.2.extend_from_slice(&bits.to_le_bytes());
                        }
                    }
                }
            }
            written += 1;
        }
        for ((i, _), (buffer, at, bytes)) in buffers.iter().zip(stores) {
            if !bytes.is_empty() {
                self.write_store(buffer, at, &bytes);
                self.feedback.written[*i] += bytes.len();
            }
        }
        self.count_primitives_written(written);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strips_loops_and_fans_decompose_into_independent_primitives() {
        assert_eq!(decompose(GL_LINE_LOOP, 3, false), vec![0, 1, 1, 2, 2, 0]);
        assert_eq!(decompose(GL_LINE_STRIP, 1, false), Vec::<usize>::new());
        assert_eq!(decompose(GL_LINES, 5, false), vec![0, 1, 2, 3]);
        assert_eq!(
            decompose(GL_TRIANGLE_STRIP, 5, false),
            vec![0, 1, 2, 2, 1, 3, 2, 3, 4]
        );
        assert_eq!(
            decompose(GL_TRIANGLE_STRIP, 4, true),
            vec![0, 1, 2, 1, 3, 2]
        );
        assert_eq!(decompose(GL_TRIANGLE_FAN, 4, false), vec![0, 1, 2, 0, 2, 3]);
        assert_eq!(decompose(GL_TRIANGLE_FAN, 4, true), vec![1, 2, 0, 2, 3, 0]);
        assert_eq!(decompose(GL_QUADS, 4, false), vec![0, 1, 2, 0, 2, 3]);
        assert_eq!(decompose(GL_POLYGON, 2, false), Vec::<usize>::new());
    }
}
