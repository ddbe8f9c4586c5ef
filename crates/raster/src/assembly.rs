//! Primitive assembly (GL 2.1 §2.6.1, GL 3.3 §2.6.1): which vertices of
//! a draw make each primitive of a [`Mode`], and its provoking vertex
//! (GL 3.3 table 2.14).
//!
//! Takes a mode, a vertex count and a primitive number; gives that
//! primitive ([`primitive`], or [`small_polygon`] for triangles and quads
//! without allocating), or the vertices a geometry shader takes for it
//! ([`geometry_input`]: the adjacent vertices included, which the other
//! forms leave out). Vertex numbers are positions in the index list.

/// The drawing modes (GL 2.1 §2.6.1, and the adjacency modes of GL 3.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Points,
    Lines,
    LineStrip,
    LineLoop,
    Triangles,
    TriangleStrip,
    TriangleFan,
    Quads,
    QuadStrip,
    Polygon,
    LinesAdjacency,
    LineStripAdjacency,
    TrianglesAdjacency,
    TriangleStripAdjacency,
}

impl Mode {
    /// How a polygon of this mode is cut into triangles ([`Fan`]).
    pub(crate) fn fan(self) -> Fan {
        match self {
            Mode::QuadStrip | Mode::Polygon => Fan::Last,
            _ => Fan::First,
        }
    }

    /// How many primitives `vertices` vertices of this mode make
    /// (incomplete trailing primitives dropped).
    pub fn primitives(self, vertices: usize) -> usize {
        primitive_count(self, vertices)
    }
}

/// One assembled primitive; vertex numbers are positions in `indices`.
#[derive(Debug, PartialEq)]
pub(crate) enum Assembled {
    Point(usize),
    /// (first, second); the second is the provoking vertex (§2.14.7).
    Line(usize, usize),
    /// Vertices in order and the provoking vertex (GL 2.1 table 2.12).
    Polygon(Vec<usize>, usize),
}

/// How many primitives `count` vertices of `mode` make (incomplete
/// trailing primitives are dropped, GL 2.1 §2.6.1).
pub(crate) fn primitive_count(mode: Mode, count: usize) -> usize {
    let n = count;
    match mode {
        Mode::Points => n,
        Mode::Lines => n / 2,
        Mode::LineStrip => n.saturating_sub(1),
        Mode::LineLoop => {
            if n >= 2 {
                n
            } else {
                0
            }
        }
        Mode::Triangles => n / 3,
        Mode::TriangleStrip | Mode::TriangleFan => n.saturating_sub(2),
        Mode::Quads => n / 4,
        Mode::QuadStrip => (n / 2).saturating_sub(1),
        Mode::Polygon => usize::from(n >= 3),
        Mode::LinesAdjacency => n / 4,
        Mode::LineStripAdjacency => n.saturating_sub(3),
        Mode::TrianglesAdjacency => n / 6,
        // 2(p + 2) + k vertices for p triangles, k 0 or 1 (§2.6.1).
        Mode::TriangleStripAdjacency => (n / 2).saturating_sub(2),
    }
}

/// How a polygon of `n` vertices is cut into triangles: the fan of
/// vertex 0, triangle `i` (from 1 to `n − 2`) made of vertices 0, `i` and
/// `i + 1`, set up in this order ([`Fan::First`]: vertex 0 first) or as
/// `i`, `i + 1`, 0 ([`Fan::Last`]). Which vertex comes last decides how
/// the planes round (`crate::interpolate::TriangleSetup`), so each mode
/// takes llvmpipe's: quads (0, 1, 2) and (0, 2, 3); quad strips, listed
/// from vertex 2k + 3 ([`small_polygon`]), (2k + 2, 2k, 2k + 3) and (2k,
/// 2k + 1, 2k + 3); polygons (i, i + 1, 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Fan {
    First,
    Last,
}

impl Fan {
    /// Triangle `i` of the fan (vertex positions in the polygon).
    #[inline(always)]
    pub fn triangle(self, i: usize) -> [usize; 3] {
        match self {
            Fan::First => [0, i, i + 1],
            Fan::Last => [i, i + 1, 0],
        }
    }
}

/// Primitive `k` (below [`primitive_count`]) of `count` vertices of `mode`.
pub(crate) fn primitive(mode: Mode, count: usize, k: usize) -> Assembled {
    let n = count;
    match mode {
        Mode::Points => Assembled::Point(k),
        Mode::Lines => Assembled::Line(2 * k, 2 * k + 1),
        Mode::LineStrip => Assembled::Line(k, k + 1),
        Mode::LineLoop => {
            if k + 1 < n {
                Assembled::Line(k, k + 1)
            } else {
                Assembled::Line(n - 1, 0)
            }
        }
        Mode::Polygon => Assembled::Polygon((0..n).collect(), 0),
        // Without a geometry shader the adjacent vertices are ignored.
        Mode::LinesAdjacency => Assembled::Line(4 * k + 1, 4 * k + 2),
        Mode::LineStripAdjacency => Assembled::Line(k + 1, k + 2),
        _ => match small_polygon(mode, k) {
            Some((v, len, provoking)) => Assembled::Polygon(v[..len].to_vec(), provoking),
            None => Assembled::Polygon(Vec::new(), 0),
        },
    }
}

/// Primitive `k` of the triangle and quad modes without allocating:
/// vertices (the first `len` of them) and the provoking vertex (GL 2.1
/// table 2.12). `None` for the other modes.
pub(crate) fn small_polygon(mode: Mode, k: usize) -> Option<([usize; 4], usize, usize)> {
    Some(match mode {
        Mode::Triangles => ([3 * k, 3 * k + 1, 3 * k + 2, 0], 3, 3 * k + 2),
        Mode::TriangleStrip => {
            let i = k + 2;
            // Every other triangle is reversed to keep a common winding.
            let v = if i.is_multiple_of(2) {
                [i - 2, i - 1, i, 0]
            } else {
                [i - 1, i - 2, i, 0]
            };
            (v, 3, i)
        }
        Mode::TriangleFan => ([0, k + 1, k + 2, 0], 3, k + 2),
        Mode::Quads => {
            let b = 4 * k;
            ([b, b + 1, b + 2, b + 3], 4, b + 3)
        }
        Mode::QuadStrip => {
            // The quad b, b + 1, b + 3, b + 2 from its last vertex (see
            // Fan): its diagonal from b to b + 3.
            let b = 2 * k;
            ([b + 3, b + 2, b, b + 1], 4, b + 3)
        }
        Mode::TrianglesAdjacency => ([6 * k, 6 * k + 2, 6 * k + 4, 0], 3, 6 * k + 4),
        Mode::TriangleStripAdjacency => {
            let [a, _, b, _, c, _] = strip_adjacency(k, usize::MAX);
            ([a, b, c, 0], 3, 2 * k + 4)
        }
        _ => return None,
    })
}

/// Triangle `k` of a triangle strip with adjacency of `count` vertices
/// as a geometry shader takes it: its vertices in drawing order, each
/// followed by the vertex adjacent to the edge from it to the next
/// (GL 3.3 table 2.4, numbered from 0 here). The triangle's own vertices
/// do not depend on `count`; the adjacent ones of the first and last
/// triangles do.
fn strip_adjacency(k: usize, count: usize) -> [usize; 6] {
    let triangles = primitive_count(Mode::TriangleStripAdjacency, count);
    let last = k + 1 == triangles;
    let b = 2 * k;
    if k == 0 {
        // The first triangle: (1, 3, 5), adjacent 2, then 6 or 7, then 4.
        return [0, 1, 2, if last { 5 } else { 6 }, 4, 3];
    }
    // Odd triangles are drawn (2i+3, 2i+1, 2i+5), even ones
    // (2i+1, 2i+3, 2i+5) (1-based), keeping one winding.
    let far = if last { b + 5 } else { b + 6 };
    if k % 2 == 1 {
        [b + 2, b.wrapping_sub(2), b, b + 3, b + 4, far]
    } else {
        [b, b.wrapping_sub(2), b + 2, far, b + 4, b + 3]
    }
}

/// The vertices a geometry shader takes for primitive `k` of `count`
/// vertices of `mode` (GL 3.3 §2.12.1): the first `n` entries of the
/// array, `n` the input primitive's vertex count (1 for points, 2 for
/// lines, 4 for lines with adjacency, 3 for triangles, 6 for triangles
/// with adjacency). `None` for the quad and polygon modes, which no
/// geometry shader takes. `provoking_first`: odd triangles of a strip
/// start from their first vertex in draw order (the same winding), as
/// they are drawn under the first-vertex convention.
pub(crate) fn geometry_input(
    mode: Mode,
    count: usize,
    k: usize,
    provoking_first: bool,
) -> Option<[usize; 6]> {
    Some(match mode {
        Mode::Points => [k, 0, 0, 0, 0, 0],
        Mode::Lines | Mode::LineStrip | Mode::LineLoop => match primitive(mode, count, k) {
            Assembled::Line(a, b) => [a, b, 0, 0, 0, 0],
            _ => return None,
        },
        Mode::LinesAdjacency => [4 * k, 4 * k + 1, 4 * k + 2, 4 * k + 3, 0, 0],
        Mode::LineStripAdjacency => [k, k + 1, k + 2, k + 3, 0, 0],
        Mode::TriangleStrip if provoking_first && k % 2 == 1 => [k, k + 2, k + 1, 0, 0, 0],
        Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan => {
            let (v, _, _) = small_polygon(mode, k)?;
            [v[0], v[1], v[2], 0, 0, 0]
        }
        Mode::TrianglesAdjacency => std::array::from_fn(|i| 6 * k + i),
        Mode::TriangleStripAdjacency => strip_adjacency(k, count),
        Mode::Quads | Mode::QuadStrip | Mode::Polygon => return None,
    })
}

/// The provoking vertex of primitive `k` of `mode` under the first-vertex
/// convention (GL 3.3 table 2.15): the primitive's first vertex in the
/// order the draw gives them — for a fan, the first after the centre; a
/// polygon keeps its first vertex under either convention.
pub(crate) fn first_vertex_provoking(mode: Mode, k: usize) -> usize {
    match mode {
        Mode::Points | Mode::LineStrip | Mode::LineLoop | Mode::TriangleStrip => k,
        Mode::Lines | Mode::QuadStrip => 2 * k,
        Mode::Triangles => 3 * k,
        Mode::TriangleFan => k + 1,
        Mode::Quads => 4 * k,
        Mode::Polygon => 0,
        Mode::LinesAdjacency => 4 * k + 1,
        Mode::LineStripAdjacency => k + 1,
        Mode::TrianglesAdjacency => 6 * k,
        Mode::TriangleStripAdjacency => 2 * k,
    }
}

/// Splits `count` vertices of `mode` into primitives, in order.
#[cfg(test)]
pub(crate) fn assemble(mode: Mode, count: usize, mut emit: impl FnMut(Assembled)) {
    for k in 0..primitive_count(mode, count) {
        emit(primitive(mode, count, k));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn collect(mode: Mode, n: usize) -> Vec<Assembled> {
        let mut v = Vec::new();
        assemble(mode, n, |p| v.push(p));
        v
    }

    #[test]
    fn assembly_and_provoking_vertices() {
        use Assembled::*;
        assert_eq!(collect(Mode::Lines, 5), vec![Line(0, 1), Line(2, 3)]);
        assert_eq!(
            collect(Mode::LineLoop, 3),
            vec![Line(0, 1), Line(1, 2), Line(2, 0)]
        );
        assert_eq!(
            collect(Mode::TriangleStrip, 5),
            vec![
                Polygon(vec![0, 1, 2], 2),
                Polygon(vec![2, 1, 3], 3),
                Polygon(vec![2, 3, 4], 4)
            ]
        );
        assert_eq!(
            collect(Mode::TriangleFan, 4),
            vec![Polygon(vec![0, 1, 2], 2), Polygon(vec![0, 2, 3], 3)]
        );
        assert_eq!(collect(Mode::Quads, 7), vec![Polygon(vec![0, 1, 2, 3], 3)]);
        assert_eq!(
            collect(Mode::QuadStrip, 6),
            vec![Polygon(vec![3, 2, 0, 1], 3), Polygon(vec![5, 4, 2, 3], 5)]
        );
        assert_eq!(
            collect(Mode::Polygon, 5),
            vec![Polygon(vec![0, 1, 2, 3, 4], 0)]
        );
        assert_eq!(collect(Mode::Polygon, 2), vec![]);
        assert_eq!(collect(Mode::Triangles, 2), vec![]);
        assert_eq!(
            collect(Mode::LinesAdjacency, 9),
            vec![Line(1, 2), Line(5, 6)]
        );
        assert_eq!(
            collect(Mode::LineStripAdjacency, 5),
            vec![Line(1, 2), Line(2, 3)]
        );
        assert_eq!(
            collect(Mode::TrianglesAdjacency, 13),
            vec![Polygon(vec![0, 2, 4], 4), Polygon(vec![6, 8, 10], 10)]
        );
    }

    /// GL 3.3 table 2.4, with vertices numbered from 1 as there.
    #[test]
    fn triangle_strips_with_adjacency() {
        let gs = |count: usize, k: usize| {
            geometry_input(Mode::TriangleStripAdjacency, count, k, false).map(|v| v.map(|x| x + 1))
        };
        // Only: 1 3 5, adjacent 2 6 4; in shader order v1 a12 v2 a23 v3 a31.
        assert_eq!(gs(6, 0), Some([1, 2, 3, 6, 5, 4]));
        assert_eq!(gs(7, 0), Some([1, 2, 3, 6, 5, 4]));
        // Four triangles (12 vertices): first, odd middle, even middle,
        // last odd.
        assert_eq!(gs(12, 0), Some([1, 2, 3, 7, 5, 4]));
        let i = 1;
        assert_eq!(
            gs(12, 1),
            Some([
                2 * i + 3,
                2 * i - 1,
                2 * i + 1,
                2 * i + 4,
                2 * i + 5,
                2 * i + 7
            ])
        );
        let i = 2;
        assert_eq!(
            gs(12, 2),
            Some([
                2 * i + 1,
                2 * i - 1,
                2 * i + 3,
                2 * i + 7,
                2 * i + 5,
                2 * i + 4
            ])
        );
        let i = 3;
        assert_eq!(
            gs(12, 3),
            Some([
                2 * i + 3,
                2 * i - 1,
                2 * i + 1,
                2 * i + 4,
                2 * i + 5,
                2 * i + 6
            ])
        );
        // Last and even (three triangles).
        let i = 2;
        assert_eq!(
            gs(10, 2),
            Some([
                2 * i + 1,
                2 * i - 1,
                2 * i + 3,
                2 * i + 6,
                2 * i + 5,
                2 * i + 4
            ])
        );
        assert_eq!(primitive_count(Mode::TriangleStripAdjacency, 5), 0);
        assert_eq!(primitive_count(Mode::TriangleStripAdjacency, 13), 4);
        // Drawn without a geometry shader: the triangle's own vertices.
        assert_eq!(
            small_polygon(Mode::TriangleStripAdjacency, 1),
            Some(([4, 2, 6, 0], 3, 6))
        );
    }

    /// The first-vertex convention's provoking vertex is the lowest
    /// vertex of the primitive in draw order, except a fan's centre and a
    /// polygon's (GL 3.3 table 2.15).
    #[test]
    fn first_vertex_convention() {
        for mode in [
            Mode::Points,
            Mode::Lines,
            Mode::LineStrip,
            Mode::Triangles,
            Mode::TriangleStrip,
            Mode::Quads,
            Mode::QuadStrip,
        ] {
            for k in 0..primitive_count(mode, 12) {
                let lowest = match primitive(mode, 12, k) {
                    Assembled::Point(i) => i,
                    Assembled::Line(a, b) => a.min(b),
                    Assembled::Polygon(v, _) => v.into_iter().min().unwrap_or(0),
                };
                assert_eq!(first_vertex_provoking(mode, k), lowest, "{mode:?} {k}");
            }
        }
        assert_eq!(first_vertex_provoking(Mode::TriangleFan, 3), 4);
        assert_eq!(first_vertex_provoking(Mode::LineLoop, 5), 5);
        assert_eq!(primitive(Mode::LineLoop, 6, 5), Assembled::Line(5, 0));
        assert_eq!(first_vertex_provoking(Mode::Polygon, 0), 0);
    }
}
