//! Primitive restart (GL 3.3 §2.8.1): an element index equal to the
//! restart index is not a vertex; the draw behaves as if it ended before
//! it and a new draw of the same mode started after it.
//!
//! Contract: [`split`] turns one index list with restart indices into
//! draws that make the same primitives in the same order, with the same
//! vertices in the same order (up to a rotation, which keeps the winding)
//! and the same provoking vertices under the convention given: the list
//! modes keep their mode with each piece's incomplete last primitive
//! dropped; strips, fans and loops become the independent primitives of
//! their pieces (GL 3.3 §2.6.1 gives the vertices of each); quad strips
//! and polygons, which the pipeline assembles as a whole, become one draw
//! per piece.

use crate::enums::*;

/// The draws (mode, indices) equivalent to `indices` of `mode` with
/// `restart` ending each primitive; `first`: the first-vertex provoking
/// convention (GL 3.3 table 2.15) is in effect, else the last-vertex one.
pub(crate) fn split(mode: u32, indices: &[u32], restart: u32, first: bool) -> Vec<(u32, Vec<u32>)> {
    let pieces = indices.split(|&i| i == restart).filter(|p| !p.is_empty());
    let mut out = Vec::new();
    let one = |m: u32, f: &dyn Fn(&[u32], &mut Vec<u32>)| {
        let mut list = Vec::with_capacity(indices.len());
        for p in pieces.clone() {
            f(p, &mut list);
        }
        vec![(m, list)]
    };
    let whole = |n: usize| {
        move |p: &[u32], list: &mut Vec<u32>| list.extend_from_slice(&p[..p.len() - p.len() % n])
    };
    match mode {
        GL_POINTS => out = one(GL_POINTS, &whole(1)),
        GL_LINES => out = one(GL_LINES, &whole(2)),
        GL_TRIANGLES => out = one(GL_TRIANGLES, &whole(3)),
        GL_QUADS => out = one(GL_QUADS, &whole(4)),
        GL_LINE_STRIP => {
            out = one(GL_LINES, &|p, list| {
                for w in p.windows(2) {
                    list.extend_from_slice(w);
                }
            })
        }
        GL_LINE_LOOP => {
            out = one(GL_LINES, &|p, list| {
                for w in p.windows(2) {
                    list.extend_from_slice(w);
                }
                if let (true, Some(&last), Some(&first)) = (p.len() >= 2, p.last(), p.first()) {
                    list.extend_from_slice(&[last, first]);
                }
            })
        }
        GL_TRIANGLE_STRIP => {
            out = one(GL_TRIANGLES, &|p, list| {
                // Every other triangle reversed, as the strip's own
                // assembly does; the strip's provoking vertex (its last
                // or first) is put last or first.
                for (k, w) in p.windows(3).enumerate() {
                    if k % 2 == 0 {
                        list.extend_from_slice(w);
                    } else if first {
                        list.extend_from_slice(&[w[0], w[2], w[1]]);
                    } else {
                        list.extend_from_slice(&[w[1], w[0], w[2]]);
                    }
                }
            })
        }
        GL_TRIANGLE_FAN => {
            out = one(GL_TRIANGLES, &|p, list| {
                // The first-vertex convention's provoking vertex is the
                // one after the centre: rotated to the front.
                for w in p.get(1..).unwrap_or(&[]).windows(2) {
                    if first {
                        list.extend_from_slice(&[w[0], w[1], p[0]]);
                    } else {
                        list.extend_from_slice(&[p[0], w[0], w[1]]);
                    }
                }
            })
        }
        _ => out.extend(pieces.map(|p| (mode, p.to_vec()))),
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    const R: u32 = 0xffff;

    #[test]
    fn pieces_become_independent_primitives() {
        let strip = [0, 1, 2, 3, R, 4, 5, 6, R, 7, 8];
        assert_eq!(
            split(GL_TRIANGLE_STRIP, &strip, R, false),
            vec![(GL_TRIANGLES, vec![0, 1, 2, 2, 1, 3, 4, 5, 6])]
        );
        assert_eq!(
            split(GL_TRIANGLE_FAN, &[0, 1, 2, 3, R, 4, 5, 6], R, false),
            vec![(GL_TRIANGLES, vec![0, 1, 2, 0, 2, 3, 4, 5, 6])]
        );
        assert_eq!(
            split(GL_LINE_LOOP, &[0, 1, 2, R, 3, R, 4, 5], R, false),
            vec![(GL_LINES, vec![0, 1, 1, 2, 2, 0, 4, 5, 5, 4])]
        );
        assert_eq!(
            split(GL_LINE_STRIP, &[R, 0, 1, 2, R, R, 3, 4], R, false),
            vec![(GL_LINES, vec![0, 1, 1, 2, 3, 4])]
        );
        assert_eq!(
            split(GL_TRIANGLES, &[0, 1, 2, 3, R, 4, 5, 6, 7, 8], R, false),
            vec![(GL_TRIANGLES, vec![0, 1, 2, 4, 5, 6])]
        );
        assert_eq!(
            split(GL_POINTS, &[0, R, 1], R, false),
            vec![(GL_POINTS, vec![0, 1])]
        );
        assert_eq!(
            split(GL_POLYGON, &[0, 1, 2, R, 3, 4, 5, 6], R, false),
            vec![(GL_POLYGON, vec![0, 1, 2]), (GL_POLYGON, vec![3, 4, 5, 6])]
        );
    }

    #[test]
    fn first_vertex_convention_rotates_to_keep_the_provoking_vertex_first() {
        assert_eq!(
            split(GL_TRIANGLE_STRIP, &[0, 1, 2, 3, R, 4, 5, 6], R, true),
            vec![(GL_TRIANGLES, vec![0, 1, 2, 1, 3, 2, 4, 5, 6])]
        );
        assert_eq!(
            split(GL_TRIANGLE_FAN, &[0, 1, 2, 3, R, 4, 5, 6], R, true),
            vec![(GL_TRIANGLES, vec![1, 2, 0, 2, 3, 0, 5, 6, 4])]
        );
    }
}
