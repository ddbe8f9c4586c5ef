//! Shaded vertices: what the stages before rasterization give a draw
//! (the vertex stage's results, or the geometry stage's emitted
//! primitives), the data the geometry stage, set-up and the debugger's
//! probe pass between them, and which of a layered draw's primitives go
//! to which layer ([`layered_primitives`]).

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

/// One layer of a layered draw (GL 3.3 §2.12.4): the geometry stage's
/// `gl_Layer` output component and the layer whose primitives are kept.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LayerSelect {
    pub component: usize,
    pub layer: i32,
}

/// Each emitted primitive of a list of `mode` (points, lines or
/// triangles; `vertex_of` and `outputs`, `stride` values per vertex, as
/// [`crate::shade_geometry`] gives them) with the layer its provoking vertex's
/// `gl_Layer` (output component `gl_layer`) sends it to (GL 3.3
/// §2.12.4), in draw order.
pub fn layered_primitives<'a>(
    (mode, vertex_of, outputs): (Mode, &'a [u32], &'a [f32]),
    stride: usize,
    gl_layer: usize,
    provoking_first: bool,
) -> impl Iterator<Item = (i32, &'a [u32])> + 'a {
    let per = match mode {
        Mode::Points => 1,
        Mode::Lines => 2,
        _ => 3,
    };
    let provoking = if provoking_first { 0 } else { per - 1 };
    vertex_of.chunks_exact(per).map(move |prim| {
        let v = prim[provoking] as usize;
        let layer = outputs
            .get(v * stride + gl_layer)
            .map_or(0, |x| x.to_bits() as i32);
        (layer, prim)
    })
}
