//! Primitive assembly (GL 2.1 §2.6.1): which vertices of a draw make
//! each primitive of a Begin/End [`Mode`], and its provoking vertex (GL 2.1
//! table 2.12).
//!
//! Takes a mode, a vertex count and a primitive number; gives that
//! primitive ([`primitive`], or [`small_polygon`] for triangles and quads
//! without allocating). Vertex numbers are positions in the index list.

/// Begin/End modes (GL 2.1 §2.6.1).
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
}

impl Mode {
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
            let b = 2 * k;
            ([b, b + 1, b + 3, b + 2], 4, b + 3)
        }
        _ => return None,
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
            vec![Polygon(vec![0, 1, 3, 2], 3), Polygon(vec![2, 3, 5, 4], 5)]
        );
        assert_eq!(
            collect(Mode::Polygon, 5),
            vec![Polygon(vec![0, 1, 2, 3, 4], 0)]
        );
        assert_eq!(collect(Mode::Polygon, 2), vec![]);
        assert_eq!(collect(Mode::Triangles, 2), vec![]);
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
