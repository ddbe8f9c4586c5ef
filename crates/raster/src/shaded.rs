//! Shaded vertices: what the stages before rasterization give a draw
//! (the vertex stage's results, or the geometry stage's emitted
//! primitives), the data the geometry stage, set-up and the debugger's
//! probe pass between them.

use crate::assembly::Mode;

/// A draw's vertices after a stage: its primitives' mode, per position in
/// their (index) list the vertex number, and the vertices' outputs.
pub(crate) struct Vertices {
    pub mode: Mode,
    /// Per position in the (index) list, the vertex number.
    pub vertex_of: Vec<u32>,
    /// The vertices' outputs, `stride` values each (the stride of the
    /// stage that wrote them).
    pub outputs: Vec<f32>,
}
