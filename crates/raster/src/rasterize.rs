//! Set-up primitives in window space: which pixels they cover (grouped in
//! 2×2 quads) and the planes of their barycentrics.
//!
//! - Triangles: fixed-point edge functions with [`SUBPIXEL_BITS`] bits of
//!   subpixel precision, sampled at pixel centers (x + ½, y + ½), with a
//!   bottom-left fill rule so that a pixel on an edge shared by two
//!   triangles is drawn exactly once: a pixel centre on an edge belongs
//!   to the triangle on its right, or on a horizontal edge to the one
//!   above it, as llvmpipe decides for GL's lower-left origin (the
//!   top-left rule of a y-down window). In GL's y-up window space, with
//!   the triangle oriented counter-clockwise, an edge is *left* when it
//!   runs downwards and *bottom* when it is horizontal and runs towards
//!   +x.
//! - Lines (GL 2.1 §3.4): for an x-major segment, each pixel column whose
//!   center lies in the half-open span from the first to the last endpoint
//!   produces the pixel row `floor(y)` at that center (a column of
//!   `round(width)` pixels for wide lines); y-major lines likewise. This
//!   matches the diamond-exit rule except at some endpoints.
//! - Points (GL 2.1 §3.3): the non-antialiased square of the rounded
//!   width, or for point sprites the square of the exact size whose pixel
//!   centers lie inside it.
//!
//! Interpolation: each primitive gives the planes of its barycentrics
//! ([`Shape::basis`]) from which set-up builds the planes of everything
//! a fragment interpolates (`crate::interpolate`): a triangle's are its
//! exact integer edge forms (those of the coverage) times the f64
//! reciprocal of twice its area; pixels outside the primitive (quad
//! helpers) get the extrapolated values.

use crate::interpolate::Basis;

/// Bits of subpixel precision of triangle vertices.
pub const SUBPIXEL_BITS: u32 = 8;
const ONE: i64 = 1 << SUBPIXEL_BITS;
const HALF: i64 = ONE / 2;
/// Fixed-point coordinates are clamped to ±2^28 (±2^20 pixels) so edge
/// function products stay within i64.
const FIXED_LIMIT: i64 = 1 << 28;

/// The mask bit of [`Shape::quads_into_strips`]'s entries of four whole
/// quads side by side.
pub(crate) const STRIP: u8 = 0x10;

/// Half-open pixel rectangle `(x0, y0, x1, y1)`.
pub(crate) type PixelRect = (i64, i64, i64, i64);

/// A vertex after the viewport transform.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct WinVertex {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    /// 1 / w_clip.
    pub inv_w: f64,
}

impl WinVertex {
    /// The window position alone.
    pub fn xy(&self) -> WinXy {
        WinXy {
            x: self.x,
            y: self.y,
        }
    }
}

/// A window position: what rasterizing a line or a point reads of its
/// vertices (their z and 1/w are in the primitive's planes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct WinXy {
    pub x: f64,
    pub y: f64,
}

/// The vertices' window z and 1/w, three of each (a point's or a line's
/// last vertex repeated; zeros for none).
pub(crate) fn vertex_depths(win: &[WinVertex]) -> ([f64; 3], [f64; 3]) {
    let v = |j: usize| win.get(j).or(win.last()).copied();
    let v = [v(0), v(1), v(2)];
    (
        v.map(|w| w.map_or(0.0, |w| w.z)),
        v.map(|w| w.map_or(0.0, |w| w.inv_w)),
    )
}

/// What rasterization needs of a primitive: its coverage (the
/// interpolated values are in its planes, `crate::interpolate`). Kept
/// small: a draw's primitives are written at set-up and read again by
/// every tile they overlap, so their bytes are memory traffic.
#[derive(Clone, Debug)]
pub(crate) enum Shape {
    Triangle {
        /// Fixed-point window positions.
        p: [(i64, i64); 3],
        /// +1 when counter-clockwise in window space, −1 otherwise.
        sign: i64,
    },
    /// A strictly convex quadrilateral covering exactly the pixels of its
    /// fan's two triangles (vertices 0, 1, 2 and 0, 2, 3): see
    /// [`Shape::quadrilateral_snapped`]. Its planes are its first
    /// triangle's.
    Quadrilateral {
        /// Fixed-point window positions (below [`FIXED_LIMIT`] in
        /// magnitude: i32 keeps the shape as small as a triangle).
        p: [[i32; 2]; 4],
        sign: i32,
    },
    Line {
        v: [WinXy; 2],
        width: i64,
    },
    Point {
        v: WinXy,
        /// The size used for gl_PointCoord.
        size: f64,
        /// Covered pixels `[x0, x1) × [y0, y1)`.
        square: PixelRect,
    },
}

/// The ends of edge k of a triangle: from vertex k+1 to vertex k+2
/// (opposite vertex k).
fn ends(p: &[(i64, i64); 3], k: usize) -> ((i64, i64), (i64, i64)) {
    (p[(k + 1) % 3], p[(k + 2) % 3])
}

/// The edge function of the edge from `a` to `b` at `(x, y)`: twice the
/// signed area of `a`, `b`, `(x, y)`.
fn edge_at((a, b): ((i64, i64), (i64, i64)), x: i64, y: i64) -> i64 {
    (b.0 - a.0) * (y - a.1) - (b.1 - a.1) * (x - a.0)
}

/// The pixels whose centers lie within the bounding box of the corners
/// `p` (fixed point).
fn corner_bounds(p: &[(i64, i64)]) -> PixelRect {
    let minx = p.iter().map(|q| q.0).min().unwrap_or(0);
    let maxx = p.iter().map(|q| q.0).max().unwrap_or(0);
    let miny = p.iter().map(|q| q.1).min().unwrap_or(0);
    let maxy = p.iter().map(|q| q.1).max().unwrap_or(0);
    let lo = |m: i64| (m - HALF + ONE - 1).div_euclid(ONE);
    let hi = |m: i64| (m - HALF).div_euclid(ONE) + 1;
    (lo(minx), lo(miny), hi(maxx), hi(maxy))
}

/// Edge k of a triangle ([`ends`]).
fn edge(p: &[(i64, i64); 3], k: usize, x: i64, y: i64) -> i64 {
    edge_at(ends(p, k), x, y)
}

/// Bottom-left rule for the edge from `a` to `b` of a polygon of
/// orientation `sign`.
fn owns((a, b): ((i64, i64), (i64, i64)), sign: i64) -> bool {
    let (dx, dy) = (sign * (b.0 - a.0), sign * (b.1 - a.1));
    dy < 0 || (dy == 0 && dx > 0)
}

/// Bottom-left rule for edge k of a triangle of orientation `sign`.
#[cfg(test)]
fn owns_edge(p: &[(i64, i64); 3], k: usize, sign: i64) -> bool {
    owns(ends(p, k), sign)
}

/// A window coordinate in fixed point: `c · ONE` rounded half away from
/// zero (as `f64::round`, without its library call), NaN as 0, clamped
/// to ±`FIXED_LIMIT`.
#[inline]
pub(crate) fn to_fixed(c: f64) -> i64 {
    let f = c * ONE as f64;
    // The truncation (saturating, NaN 0) and the fraction left, exact
    // below 2^53 (above, f is whole and the fraction 0; infinities and
    // NaN give an infinite or NaN fraction).
    let t = f as i64;
    let frac = f - t as f64;
    let r = if frac >= 0.5 {
        t.saturating_add(1)
    } else if frac <= -0.5 {
        t.saturating_sub(1)
    } else {
        t
    };
    r.clamp(-FIXED_LIMIT, FIXED_LIMIT)
}

/// A window position in fixed point ([`to_fixed`] of x and y).
#[inline]
pub(crate) fn snap(w: &WinVertex) -> (i64, i64) {
    (to_fixed(w.x), to_fixed(w.y))
}

#[cfg(test)]
fn intersect(a: PixelRect, b: PixelRect) -> PixelRect {
    (a.0.max(b.0), a.1.max(b.1), a.2.min(b.2), a.3.min(b.3))
}

impl Shape {
    /// A triangle; `None` when it has no area after snapping (set-up
    /// snaps its vertices once: [`Shape::triangle_snapped`]).
    #[cfg(test)]
    pub fn triangle(v: [WinVertex; 3]) -> Option<Shape> {
        Shape::triangle_snapped(v.map(|w| snap(&w)))
    }

    /// A triangle of vertices already in fixed point ([`snap`]).
    #[inline]
    pub fn triangle_snapped(p: [(i64, i64); 3]) -> Option<Shape> {
        let a = edge(&p, 0, p[0].0, p[0].1);
        if a == 0 {
            return None;
        }
        Some(Shape::Triangle {
            p,
            sign: a.signum(),
        })
    }

    /// The quadrilateral of vertices `p` (fixed point, [`snap`]) as one
    /// shape, when it covers exactly the pixels of its fan's two
    /// triangles, (0, 1, 2) and (0, 2, 3): when it is strictly convex
    /// (every corner turns the same way). Then a pixel centre strictly on
    /// one side of the diagonal is in that side's triangle exactly when
    /// it is inside the four outer edges (the triangle's third outer
    /// edge holds it strictly), one on the diagonal between its ends is
    /// owned by exactly one triangle and lies strictly inside the outer
    /// edges, and an outer edge's own pixels follow the same rule in
    /// both. At an end of the diagonal, where two outer edges meet, the
    /// bottom-left rule owns a half-turn of directions, and the diagonal
    /// leaves the corner within its angle (under a half-turn): when only
    /// the edge leaving the corner is owned the diagonal is owned
    /// leaving it too, so the triangle that tests that edge does not own
    /// the diagonal, and likewise for the arriving edge; the triangles
    /// then cover the corner exactly when both outer edges are owned,
    /// as the quadrilateral does. `None` otherwise: the caller sets up
    /// the two triangles.
    pub fn quadrilateral_snapped(p: [(i64, i64); 4]) -> Option<Shape> {
        // Twice the signed area of the corner at vertex k + 1.
        let turn = |k: usize| {
            let c = p[(k + 2) % 4];
            edge_at((p[k], p[(k + 1) % 4]), c.0, c.1).signum()
        };
        let sign = turn(0);
        if sign == 0 || (1..4).any(|k| turn(k) != sign) {
            return None;
        }
        let mut q = [[0i32; 2]; 4];
        for (q, &(x, y)) in q.iter_mut().zip(&p) {
            *q = [i32::try_from(x).ok()?, i32::try_from(y).ok()?];
        }
        Some(Shape::Quadrilateral {
            p: q,
            sign: sign as i32,
        })
    }

    pub fn line(v: [WinVertex; 2], width: f32) -> Shape {
        let w = if width.is_nan() {
            1.0
        } else {
            width.clamp(1.0, 64.0)
        };
        Shape::Line {
            v: v.map(|w| w.xy()),
            width: (w as f64).round().max(1.0) as i64,
        }
    }

    /// A point of `size` (already clamped to a sane range).
    pub fn point(v: WinVertex, size: f64, sprite: bool) -> Shape {
        let square = if sprite {
            // Pixel centers inside [x - s/2, x + s/2).
            let lo = |c: f64| (c - size / 2.0 - 0.5).ceil() as i64;
            let hi = |c: f64| (c + size / 2.0 - 0.5).ceil() as i64;
            (lo(v.x), lo(v.y), hi(v.x), hi(v.y))
        } else {
            let w = size.round().max(1.0) as i64;
            let start = |c: f64| {
                if w % 2 == 1 {
                    c.floor() as i64 - (w - 1) / 2
                } else {
                    (c + 0.5).floor() as i64 - w / 2
                }
            };
            let (x0, y0) = (start(v.x), start(v.y));
            (x0, y0, x0 + w, y0 + w)
        };
        Shape::Point {
            v: v.xy(),
            size,
            square,
        }
    }

    /// Pixel bounds of the primitive (before clipping to the framebuffer).
    #[inline]
    pub fn bounds(&self) -> PixelRect {
        match self {
            Shape::Triangle { p, .. } => corner_bounds(p),
            Shape::Quadrilateral { p, .. } => corner_bounds(&corners(p)),
            Shape::Line { v, width } => {
                let pad = width / 2 + 2;
                let minx = v[0].x.min(v[1].x).floor() as i64 - pad;
                let maxx = v[0].x.max(v[1].x).ceil() as i64 + pad;
                let miny = v[0].y.min(v[1].y).floor() as i64 - pad;
                let maxy = v[0].y.max(v[1].y).ceil() as i64 + pad;
                (minx, miny, maxx, maxy)
            }
            Shape::Point { square, .. } => *square,
        }
    }

    /// Covered quads inside `clip` (half-open, even-aligned origin not
    /// required): `(qx, qy, mask)` with mask bit `(y - qy) * 2 + (x - qx)`,
    /// quads in row-major order.
    #[cfg(test)]
    pub fn quads(&self, clip: PixelRect) -> Vec<(i64, i64, u8)> {
        let mut out = Vec::new();
        self.quads_into(self.area(clip), &mut out);
        out
    }

    /// The part of `clip` inside the primitive's bounds: an `area` the
    /// rasterizing methods take (the tiles' callers pass a primitive's
    /// clipped bounds inside the tile, one already: no intersection per
    /// tile).
    #[cfg(test)]
    pub fn area(&self, clip: PixelRect) -> PixelRect {
        intersect(self.bounds(), clip)
    }

    /// The covered quads inside `area` (half-open, inside the primitive's
    /// bounds, e.g. its clipped bounds inside a tile), `(qx, qy, mask)`
    /// with mask bit `(y - qy) * 2 + (x - qx)`, quads in row-major order,
    /// into `out` (cleared first), so that a caller can reuse one buffer
    /// for every primitive.
    #[inline(always)]
    pub fn quads_into(&self, area: PixelRect, out: &mut Vec<(i64, i64, u8)>) {
        out.clear();
        if area.0 >= area.2 || area.1 >= area.3 {
            return;
        }
        match self {
            Shape::Triangle { p, sign } => quads_list(&triangle_edges(p, *sign), area, out),
            Shape::Quadrilateral { p, sign } => {
                quads_list(&quadrilateral_edges(p, *sign), area, out)
            }
            _ => self.other_quads_into(area, out),
        }
    }

    /// [`Shape::quads_into`] of points and lines, `r` their bounds inside
    /// the clip rectangle (not empty).
    fn other_quads_into(&self, r: PixelRect, out: &mut Vec<(i64, i64, u8)>) {
        match self {
            Shape::Triangle { .. } | Shape::Quadrilateral { .. } => {}
            Shape::Point { .. } => {
                for_each_quad(r, |qx, qy| {
                    let mut mask = 0u8;
                    for bit in 0..4 {
                        if inside(r, qx + (bit & 1), qy + (bit >> 1)) {
                            mask |= 1 << bit;
                        }
                    }
                    if mask != 0 {
                        out.push((qx, qy, mask));
                    }
                });
            }
            Shape::Line { .. } => {
                let mut pixels = self.line_pixels(r);
                pixels.sort_by_key(|&(x, y)| (y.div_euclid(2), x.div_euclid(2), y, x));
                for (x, y) in pixels {
                    let (qx, qy) = (x & !1, y & !1);
                    let bit = ((y - qy) * 2 + (x - qx)) as u8;
                    match out.last_mut() {
                        Some(last) if last.0 == qx && last.1 == qy => last.2 |= 1 << bit,
                        _ => out.push((qx, qy, 1 << bit)),
                    }
                }
            }
        }
    }

    /// The pixels of a line inside `r`.
    fn line_pixels(&self, r: PixelRect) -> Vec<(i64, i64)> {
        let Shape::Line { v, width } = self else {
            return Vec::new();
        };
        let (a, b) = (v[0], v[1]);
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let x_major = dx.abs() >= dy.abs();
        // Major axis coordinate, minor axis coordinate.
        let (a0, a1, b0, b1) = if x_major {
            (a.x, a.y, b.x, b.y)
        } else {
            (a.y, a.x, b.y, b.x)
        };
        let (lo_r, hi_r) = if x_major { (r.0, r.2) } else { (r.1, r.3) };
        let mut out = Vec::new();
        if a0 == b0 || !(a0.is_finite() && b0.is_finite()) {
            return out;
        }
        // Centers c = i + ½ in [a0, b0) (or (b0, a0] going backwards).
        let (first, last) = if a0 < b0 {
            ((a0 - 0.5).ceil() as i64, (b0 - 0.5).ceil() as i64 - 1)
        } else {
            ((b0 - 0.5).floor() as i64 + 1, (a0 - 0.5).floor() as i64)
        };
        let first = first.max(lo_r);
        let last = last.min(hi_r - 1);
        let slope = (b1 - a1) / (b0 - a0);
        for i in first..=last {
            let c = i as f64 + 0.5;
            let m = a1 + (c - a0) * slope;
            let j0 = (m - (*width - 1) as f64 / 2.0).floor() as i64;
            for j in j0..j0.saturating_add(*width) {
                let (x, y) = if x_major { (i, j) } else { (j, i) };
                if inside(r, x, y) {
                    out.push((x, y));
                }
            }
        }
        out
    }

    /// The planes of the primitive's barycentrics of vertices 1 and 2
    /// (see [`Basis`]: values at the center of pixel (0, 0)): for a
    /// triangle its exact integer edge forms times one over twice its
    /// area (so the barycentrics of the coverage's snapped vertices: set-up
    /// uses them only when [`Basis::of_triangle`] finds no area in the
    /// unsnapped positions), for a quadrilateral its first triangle's;
    /// for a line the parameter `t` of GL 2.1 eq. 3.1 of each pixel center
    /// (the projection onto the segment); zeros for a point.
    #[inline]
    pub fn basis(&self) -> Basis {
        match self {
            Shape::Triangle { p, sign } => triangle_basis(p, *sign),
            Shape::Quadrilateral { p, sign } => {
                let c = corners(p);
                triangle_basis(&[c[0], c[1], c[2]], *sign as i64)
            }
            Shape::Line { v, .. } => {
                // GL 2.1 eq. 3.1: t = (p - pa)·(pb - pa) / |pb - pa|².
                let (dx, dy) = (v[1].x - v[0].x, v[1].y - v[0].y);
                let len2 = dx * dx + dy * dy;
                let t = if len2 > 0.0 && len2.is_finite() {
                    let (px, py) = (0.5 - v[0].x, 0.5 - v[0].y);
                    [(px * dx + py * dy) / len2, dx / len2, dy / len2]
                } else {
                    [0.0; 3]
                };
                Basis { b: [t, [0.0; 3]] }
            }
            Shape::Point { .. } => Basis::default(),
        }
    }

    /// The covered quads inside `area` (see [`Shape::quads_into`]) in
    /// its order: `f(qx, qy, mask)`. Triangles without a list in between
    /// (from the coverage walk itself); the other shapes go through
    /// `quads`.
    #[inline(always)]
    pub fn quads_each(
        &self,
        area: PixelRect,
        quads: &mut Vec<(i64, i64, u8)>,
        mut f: impl FnMut(i64, i64, u8),
    ) {
        let walked = self.walk(
            area,
            #[inline(always)]
            |qx, qy, mask, _| {
                if mask != 0 {
                    f(qx, qy, mask);
                }
                0
            },
        );
        if !walked {
            self.quads_into(area, quads);
            for &(qx, qy, mask) in quads.iter() {
                f(qx, qy, mask);
            }
        }
    }

    /// [`walk_in`] of a triangle or a quadrilateral over `area`: false
    /// (nothing done) for the other shapes.
    #[inline(always)]
    fn walk(&self, area: PixelRect, f: impl FnMut(i64, i64, u8, &WalkQuad) -> i64) -> bool {
        match self {
            Shape::Triangle { p, sign } => walk_in(&triangle_edges(p, *sign), area, f),
            Shape::Quadrilateral { p, sign } => walk_in(&quadrilateral_edges(p, *sign), area, f),
            _ => return false,
        }
        true
    }

    /// [`Shape::quads_into`], and with `strips` a triangle's four whole
    /// quads side by side (each quad's pixels covered and inside the
    /// area) from where the walk meets them as one entry: the first
    /// quad's position with mask `STRIP | 0xf` (a strip's entry is
    /// followed by the quad after its fourth).
    #[inline(always)]
    pub fn quads_into_strips(&self, area: PixelRect, out: &mut Vec<(i64, i64, u8)>, strips: bool) {
        if !strips || !matches!(self, Shape::Triangle { .. } | Shape::Quadrilateral { .. }) {
            return self.quads_into(area, out);
        }
        out.clear();
        self.walk(
            area,
            #[inline(always)]
            |qx, qy, mask, walk| {
                // The run of whole strips from here, pushed at once (one
                // visit of the walk instead of one a strip).
                let n = if mask == 0xf { walk.whole_strips() } else { 0 };
                if n > 0 {
                    out.extend((0..n).map(|k| (qx + 8 * k, qy, STRIP | 0xf)));
                    return 4 * n - 1;
                }
                if mask != 0 {
                    out.push((qx, qy, mask));
                }
                0
            },
        );
    }

    /// GL 2.1 eq. 3.3/3.4: gl_PointCoord at pixel (x, y) (zeros for
    /// primitives other than points).
    pub fn point_coord(&self, x: i64, y: i64, lower_left: bool) -> (f32, f32) {
        match self {
            Shape::Point { v, size, .. } => {
                let s = 0.5 + (x as f64 + 0.5 - v.x) / size;
                let dt = (y as f64 + 0.5 - v.y) / size;
                let t = if lower_left { 0.5 + dt } else { 0.5 - dt };
                (s as f32, t as f32)
            }
            _ => (0.0, 0.0),
        }
    }
}

/// max(|∂z/∂x|, |∂z/∂y|) of the plane through three window vertices
/// (polygon offset).
pub(crate) fn max_depth_slope(v: &[WinVertex; 3]) -> f64 {
    let (x1, y1, z1) = (v[1].x - v[0].x, v[1].y - v[0].y, v[1].z - v[0].z);
    let (x2, y2, z2) = (v[2].x - v[0].x, v[2].y - v[0].y, v[2].z - v[0].z);
    let det = x1 * y2 - x2 * y1;
    if det == 0.0 {
        return 0.0;
    }
    let dzdx = (z1 * y2 - z2 * y1) / det;
    let dzdy = (x1 * z2 - x2 * z1) / det;
    let m = dzdx.abs().max(dzdy.abs());
    if m.is_finite() {
        m
    } else {
        0.0
    }
}

/// Per edge `j`, the orientation times [`edge`] `j` at the center of
/// pixel (0, 0) and its steps per pixel in x and y (integers).
#[inline(always)]
fn edge_forms(p: &[(i64, i64); 3], sign: i64) -> [(i64, i64, i64); 3] {
    let (cx, cy) = (HALF, HALF);
    std::array::from_fn(|j| {
        let (pa, pb) = (p[(j + 1) % 3], p[(j + 2) % 3]);
        let (ex, ey) = (pb.0 - pa.0, pb.1 - pa.1);
        let e0 = ex * (cy - pa.1) - ey * (cx - pa.0);
        (sign * e0, sign * -ey * ONE, sign * ex * ONE)
    })
}

/// [`Shape::basis`] of a triangle.
#[inline]
fn triangle_basis(p: &[(i64, i64); 3], sign: i64) -> Basis {
    // 1 / twice the area in fixed-point units² (positive).
    let inv_area2 = 1.0 / edge(p, 0, p[0].0, p[0].1).unsigned_abs() as f64;
    let e = edge_forms(p, sign);
    let b = |j: usize| {
        let (c, dx, dy) = e[j];
        [c as f64, dx as f64, dy as f64].map(|v| v * inv_area2)
    };
    Basis { b: [b(1), b(2)] }
}

/// The corners of a [`Shape::Quadrilateral`] as the other shapes keep
/// them.
#[inline(always)]
fn corners(p: &[[i32; 2]; 4]) -> [(i64, i64); 4] {
    p.map(|[x, y]| (i64::from(x), i64::from(y)))
}

/// The covered quads of a polygon of edges `edges` ([`walk_edges`])
/// inside `r` (non-empty, within the primitive's bounds), row-major
/// ([`polygon_quads_each`]).
#[inline(always)]
fn quads_list<const E: usize>(edges: &[[i64; E]; 4], r: PixelRect, out: &mut Vec<(i64, i64, u8)>) {
    // The row's quads are written in place without a branch on their
    // coverage (which does not predict at a triangle's edges): each is
    // stored at the end, which moves past it only when it covers a pixel;
    // the slot is made first and an unused one dropped at the end.
    let mut n = out.len();
    polygon_quads_each(
        edges,
        r,
        #[inline(always)]
        |qx, qy, mask, _| {
            if n == out.len() {
                out.push((qx, qy, mask));
            } else if let Some(slot) = out.get_mut(n) {
                *slot = (qx, qy, mask);
            }
            n += usize::from(mask != 0);
            0
        },
    );
    out.truncate(n);
}

/// [`polygon_quads_each`] of a polygon of edges `edges` over `area`
/// (inside its bounds; nothing when empty).
#[inline(always)]
fn walk_in<const E: usize>(
    edges: &[[i64; E]; 4],
    area: PixelRect,
    f: impl FnMut(i64, i64, u8, &WalkQuad) -> i64,
) {
    if area.0 < area.2 && area.1 < area.3 {
        polygon_quads_each(edges, area, f);
    }
}

/// Visits the quads of a convex polygon (a triangle or a
/// quadrilateral) of edges `E` inside `r` (non-empty, within the
/// primitive's bounds), row-major: `f(qx, qy, mask, walk)` with the pixels
/// covered (mask bit `(y - qy) * 2 + (x - qx)`; every quad with a pixel
/// covered is visited, some without any: callers skip a zero mask),
/// returning how many of the following quads to pass over (see
/// [`WalkQuad`]). Each edge is the integer linear form `s(x, y) = a·x +
/// b·y + c` (the orientation times [`edge`] at the pixel center); a pixel
/// is covered when every edge is at least its threshold there: 0 on an
/// edge the triangle owns (bottom-left rule), else 1. Areas a few quads wide
/// (small triangles, tile borders) are evaluated a row at a time in i32
/// lanes ([`narrow_quads_each`]); the others by [`wide_quads_each`]'s
/// steps.
#[inline(always)]
fn polygon_quads_each<const E: usize>(
    [a, b, c, threshold]: &[[i64; E]; 4],
    r: PixelRect,
    mut f: impl FnMut(i64, i64, u8, &WalkQuad) -> i64,
) {
    let edges = (a, b, c, threshold);
    if !narrow_quads_each(edges, r, &mut f) {
        wide_quads_each(edges, r, f);
    }
}

/// Per edge k from `ends[k].0` to `ends[k].1` of a convex polygon of
/// orientation `sign`, its integer linear form `a·x + b·y + c` at pixel
/// centers (the orientation times [`edge_at`]) and its threshold (0 on
/// an edge the polygon owns, else 1): `[a, b, c, threshold]`.
#[inline(always)]
fn walk_edges<const E: usize>(ends: [((i64, i64), (i64, i64)); E], sign: i64) -> [[i64; E]; 4] {
    let mut e = [[0i64; E]; 4];
    for (k, &(pa, pb)) in ends.iter().enumerate() {
        let (ex, ey) = (pb.0 - pa.0, pb.1 - pa.1);
        e[0][k] = -sign * ey * ONE;
        e[1][k] = sign * ex * ONE;
        e[2][k] = sign * (ex * (HALF - pa.1) - ey * (HALF - pa.0));
        e[3][k] = 1 - owns((pa, pb), sign) as i64;
    }
    e
}

/// [`walk_edges`] of a triangle (edge k opposite vertex k, [`ends`]).
#[inline(always)]
fn triangle_edges(p: &[(i64, i64); 3], sign: i64) -> [[i64; 3]; 4] {
    walk_edges(std::array::from_fn(|k| ends(p, k)), sign)
}

/// [`walk_edges`] of a [`Shape::Quadrilateral`] (edge k from vertex k to
/// vertex k + 1).
#[inline(always)]
fn quadrilateral_edges(p: &[[i32; 2]; 4], sign: i32) -> [[i64; 4]; 4] {
    let c = corners(p);
    walk_edges(
        std::array::from_fn(|k| (c[k], c[(k + 1) % 4])),
        i64::from(sign),
    )
}

/// [`polygon_quads_each`] by stepping from quad to quad (any area; the
/// edges as [`narrow_quads_each`] takes them). The walk keeps each edge's
/// value minus its threshold at a quad's four pixels in a [`Quad4`]
/// (vector registers on x86-64), so that a pixel is outside an edge
/// exactly where that difference is negative (its sign bit); the quads a
/// row starts with that lie wholly outside an edge are passed over, and a
/// row ends as soon as one edge that only decreases to the right is below
/// its threshold on the whole quad.
#[inline(always)]
fn wide_quads_each<const E: usize>(
    (a, b, c, threshold): (&[i64; E], &[i64; E], &[i64; E], &[i64; E]),
    r: PixelRect,
    mut f: impl FnMut(i64, i64, u8, &WalkQuad) -> i64,
) {
    // Pixel i of a quad from its first: (i & 1, i >> 1).
    let offset: [[i64; 4]; E] = std::array::from_fn(|k| [0, a[k], b[k], a[k] + b[k]]);
    let step: [Quad4; E] = std::array::from_fn(|k| Quad4::splat(2 * a[k]));
    // The edges that only decrease to the right (bit k); the others
    // grow.
    let decreasing = (0..E).fold(0u8, |m, k| m | (u8::from(a[k] <= 0) << k));
    let (x0, y0) = (r.0 & !1, r.1 & !1);
    let mut qy = y0;
    while qy < r.3 {
        // Pixel rows of the quad row inside r: bits 0–1 and 2–3.
        let rows = (if qy >= r.1 { 0b0011u8 } else { 0 }) | (if qy + 1 < r.3 { 0b1100 } else { 0 });
        let mut over: [Quad4; E] = std::array::from_fn(|k| {
            let g = a[k] * x0 + b[k] * qy + c[k] - threshold[k];
            Quad4::new(offset[k].map(|o| g + o))
        });
        let mut qx = x0;
        // In wide areas, the quads the row starts with that lie wholly
        // outside a growing edge are passed over at once (quads that
        // cover nothing; narrow areas have few, not worth the look).
        let ahead = match r.2 - x0 >= WIDE_ROW {
            true => row_start(&over, a, !decreasing),
            false => 0,
        };
        if ahead > 0 {
            let ahead = ahead.min((r.2 - qx + 1) / 2);
            for (o, &a) in over.iter_mut().zip(a) {
                *o = o.add(Quad4::splat(2 * a * ahead));
            }
            qx += 2 * ahead;
        }
        while qx < r.2 {
            let cols =
                (if qx >= r.0 { 0b0101u8 } else { 0 }) | (if qx + 1 < r.2 { 0b1010 } else { 0 });
            // Per edge, the pixels where it is below its threshold.
            let outside = over.map(Quad4::negative);
            let mask = !outside.iter().fold(0, |m, o| m | o) & rows & cols;
            // Outside on the whole quad: nothing covered here or further
            // right.
            let whole = (0..E).fold(0u8, |m, k| m | (u8::from(outside[k] == 0xf) << k));
            if whole & decreasing != 0 {
                break;
            }
            let walk = WalkQuad {
                over: Some(&over[..]),
                a: &a[..],
                qx,
                x_end: r.2,
            };
            // The caller's quads to pass over (whole ones it took at once),
            // at most the rest of the row.
            let skip = f(qx, qy, mask, &walk);
            if skip > 0 {
                // (Checked first: callers that never skip compile none of
                // this.)
                let skip = skip.min((r.2 - qx) / 2);
                for (o, &a) in over.iter_mut().zip(a) {
                    *o = o.add(Quad4::splat(2 * a * skip));
                }
                qx += 2 * skip;
            }
            for (o, s) in over.iter_mut().zip(&step) {
                *o = o.add(*s);
            }
            qx += 2;
        }
        qy += 2;
    }
}

/// The widest area, in pixels from its first quad's column, that
/// [`narrow_quads_each`] takes: two groups of four quads a row.
const NARROW: i64 = 16;

/// [`polygon_quads_each`] over an area at most [`NARROW`] pixels wide
/// whose edge values (less thresholds) fit in i32 lanes: true when it ran,
/// false (nothing done) otherwise. Every quad of a quad row is evaluated,
/// four at a time and without branches: a pixel is outside an edge where
/// its value is negative, so outside some edge where the OR of the three
/// values is (one sign bit for all three); then `f` visits the covered
/// quads only, in row-major order (the quads the walk would visit with
/// pixels covered). There are no strips here ([`WalkQuad::whole_strips`]
/// is 0).
#[inline(always)]
fn narrow_quads_each<const E: usize>(
    (a, b, c, threshold): (&[i64; E], &[i64; E], &[i64; E], &[i64; E]),
    r: PixelRect,
    f: &mut impl FnMut(i64, i64, u8, &WalkQuad) -> i64,
) -> bool {
    let (x0, y0) = (r.0 & !1, r.1 & !1);
    let width = r.2 - x0;
    if width > NARROW {
        return false;
    }
    // Groups of four quads (eight pixel columns) a row; whole quad rows.
    let groups = if width > NARROW / 2 { 2 } else { 1 };
    let rows = (r.3 - y0 + 1) & !1;
    let mut g = [0i64; E];
    for k in 0..E {
        g[k] = a[k] * x0 + b[k] * y0 + c[k] - threshold[k];
    }
    // Every value reached (one step past the last column and row
    // included: offsets up to 17 pixels right and `rows` + 1 down) is
    // below 2^31 in magnitude when those at the first pixel are below
    // 2^29, the steps per pixel below 2^22 and `rows` at most 256:
    // 2^29 + 2^22 · (17 + 257) < 2^31. A value x is below 2^n in
    // magnitude when x + 2^n, as unsigned, is below 2^(n + 1), and an OR
    // of such values is below 2^(n + 1) exactly when each is.
    let near = |x: i64, n: u32| (x.wrapping_add(1 << n)) as u64;
    let firsts = g.iter().fold(0u64, |m, &g| m | near(g, 29));
    let steps = (0..E).fold(0u64, |m, k| m | near(a[k], 22) | near(b[k], 22));
    if firsts >= 1 << 30 || steps >= 1 << 23 || rows > 256 {
        return false;
    }
    let mut first = [Lanes4::splat(0); E];
    let mut right = [Lanes4::splat(0); E];
    let mut down = [Lanes4::splat(0); E];
    for k in 0..E {
        let (g, a, b) = (g[k] as i32, a[k] as i32, b[k] as i32);
        // Pixel i of a quad from its first: (i & 1, i >> 1).
        first[k] = Lanes4::new([g, g + a, g + b, g + a + b]);
        right[k] = Lanes4::splat(2 * a);
        down[k] = Lanes4::splat(2 * b);
    }
    // Nibble q: the pixels of quad q of the row inside the area's
    // columns. Bit i of `columns`: pixel column x0 + i is in r.0..r.2
    // (x0 is r.0 or r.0 − 1); its pairs spread to nibbles (bits 0–1),
    // copied to the quads' lower rows (bits 2–3).
    let columns = ((1u32 << width as u32) - 1) & !((1u32 << (r.0 - x0) as u32) - 1);
    let mut spread = (columns | (columns << 8)) & 0x00ff_00ff;
    spread = (spread | (spread << 4)) & 0x0f0f_0f0f;
    spread = (spread | (spread << 2)) & 0x3333_3333;
    let in_columns = spread | (spread << 2);
    let none = WalkQuad {
        over: None,
        a: &a[..],
        qx: x0,
        x_end: x0,
    };
    let mut row = first;
    let mut qy = y0;
    while qy < r.3 {
        // Nibble q: the pixels of quad q outside some edge.
        let mut outside = 0u32;
        let mut v = row;
        for q in 0..4 * groups {
            let m = v.iter().fold(Lanes4::splat(0), |m, &v| m.or(v)).negative();
            outside |= u32::from(m) << (4 * q);
            for (v, s) in v.iter_mut().zip(&right) {
                *v = v.add(*s);
            }
        }
        let in_rows =
            (if qy >= r.1 { 0b0011u32 } else { 0 }) | (if qy + 1 < r.3 { 0b1100 } else { 0 });
        let mut covered = !outside & in_columns & (in_rows * 0x1111_1111);
        while covered != 0 {
            let q = covered.trailing_zeros() / 4;
            let mask = ((covered >> (4 * q)) & 0xf) as u8;
            let qx = x0 + 2 * i64::from(q);
            let skip = f(
                qx,
                qy,
                mask,
                &WalkQuad {
                    qx,
                    x_end: qx,
                    ..none
                },
            );
            // The quads passed over (none without strips) and this one.
            let done = 4 * (i64::from(q) + 1 + skip.clamp(0, 8)) as u32;
            covered &= u32::MAX.checked_shl(done).unwrap_or(0);
        }
        for (v, s) in row.iter_mut().zip(&down) {
            *v = v.add(*s);
        }
        qy += 2;
    }
    true
}

/// The width in pixels from which [`polygon_quads_each`] looks for the
/// quads a row starts with that cover nothing ([`row_start`]).
const WIDE_ROW: i64 = 16;

/// How many quads from the one whose edge values (less thresholds) are
/// `over` lie wholly outside one of the `growing` edges (bit k: `a[k] >
/// 0`): quad j further right is outside edge k while its largest value
/// plus `2·a[k]·j` is negative, that is for j < `⌈−top / (2·a[k])⌉`.
#[inline(always)]
fn row_start<const E: usize>(over: &[Quad4; E], a: &[i64; E], growing: u8) -> i64 {
    let mut ahead = 0i64;
    for k in 0..E {
        if growing & (1 << k) == 0 {
            continue;
        }
        let (Some(o), Some(&a)) = (over.get(k), a.get(k)) else {
            continue;
        };
        let top = o.to_array().into_iter().max().unwrap_or(0);
        if top < 0 && a > 0 {
            let step = 2 * a;
            ahead = ahead.max((step - 1 - top) / step);
        }
    }
    ahead
}

/// A quad of [`polygon_quads_each`]'s walk, for a caller that takes
/// runs of whole quads at once ([`Shape::quads_into_strips`]).
pub(crate) struct WalkQuad<'a> {
    /// Per edge, its values less thresholds at the quad's pixels (`None`
    /// where the walk takes no strips).
    over: Option<&'a [Quad4]>,
    a: &'a [i64],
    qx: i64,
    /// The clip rectangle's right end.
    x_end: i64,
}

impl WalkQuad<'_> {
    /// For a whole quad (every pixel covered and inside the clip), how
    /// many strips of four whole quads follow one another from it: the
    /// largest k (0 if none) such that the `4k − 1` quads to its right are
    /// whole too. An edge decreasing to the right by `2|a|` per quad keeps
    /// all four pixels at or above its threshold `j` quads further when the
    /// least of its four values over the threshold is at least `j·2|a|`;
    /// the other edges only grow; and the quads must end inside the clip.
    #[inline(always)]
    pub fn whole_strips(&self) -> i64 {
        let inside = (self.x_end - self.qx) / 8;
        let Some(over) = self.over.filter(|_| inside > 0) else {
            return 0;
        };
        // Per decreasing edge, its least value and its step per quad.
        let mut least = [(i64::MAX, 0i64); 4];
        for ((l, o), &a) in least.iter_mut().zip(over).zip(self.a) {
            if a < 0 {
                *l = (o.to_array().into_iter().min().unwrap_or(0), -2 * a);
            }
        }
        let mut k = 0;
        while k < inside
            && least
                .iter()
                .all(|&(m, step)| m >= (4 * (k + 1) - 1).saturating_mul(step))
        {
            k += 1;
        }
        k
    }
}

/// Four i64, one per pixel of a quad: two SSE2 registers on x86-64 (the
/// baseline, so every variant keeps them in registers and the AVX ones
/// may join them), an array elsewhere. Wrapping additions, as the
/// walk's values never overflow (coordinates are below `FIXED_LIMIT`).
#[derive(Clone, Copy)]
struct Quad4 {
    #[cfg(target_arch = "x86_64")]
    v: [std::arch::x86_64::__m128i; 2],
    #[cfg(not(target_arch = "x86_64"))]
    v: [i64; 4],
}

impl Quad4 {
    #[inline(always)]
    fn new(x: [i64; 4]) -> Quad4 {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::x86_64::*;
            // SAFETY: SSE2 is part of the x86-64 baseline.
            unsafe {
                Quad4 {
                    v: [_mm_set_epi64x(x[1], x[0]), _mm_set_epi64x(x[3], x[2])],
                }
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            Quad4 { v: x }
        }
    }

    #[inline(always)]
    fn splat(x: i64) -> Quad4 {
        Quad4::new([x; 4])
    }

    #[inline(always)]
    fn add(self, o: Quad4) -> Quad4 {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::x86_64::*;
            // SAFETY: SSE2 is part of the x86-64 baseline.
            unsafe {
                Quad4 {
                    v: [
                        _mm_add_epi64(self.v[0], o.v[0]),
                        _mm_add_epi64(self.v[1], o.v[1]),
                    ],
                }
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            Quad4 {
                v: std::array::from_fn(|i| self.v[i].wrapping_add(o.v[i])),
            }
        }
    }

    /// Bit `i` set where element `i` is negative: the sign bits, taken
    /// by the instruction that collects them where there is one.
    #[inline(always)]
    fn negative(self) -> u8 {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::x86_64::*;
            // SAFETY: SSE2 is part of the x86-64 baseline.
            unsafe {
                let lo = _mm_movemask_pd(_mm_castsi128_pd(self.v[0]));
                let hi = _mm_movemask_pd(_mm_castsi128_pd(self.v[1]));
                (lo | (hi << 2)) as u8
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            (0..4).fold(0u8, |m, i| m | (u8::from(self.v[i] < 0) << i))
        }
    }

    #[inline(always)]
    fn to_array(self) -> [i64; 4] {
        #[cfg(target_arch = "x86_64")]
        {
            let mut out = [0i64; 4];
            // SAFETY: SSE2 is part of the x86-64 baseline; the stores
            // write the four elements of `out`, two at a time.
            unsafe {
                use std::arch::x86_64::*;
                _mm_storeu_si128(out.as_mut_ptr().cast(), self.v[0]);
                _mm_storeu_si128(out.as_mut_ptr().add(2).cast(), self.v[1]);
            }
            out
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            self.v
        }
    }
}

/// Four i32, one per pixel of a quad ([`narrow_quads_each`]): one SSE2
/// register on x86-64, an array elsewhere. Wrapping additions (the
/// values used never overflow: the walk checks their reach first).
#[derive(Clone, Copy)]
struct Lanes4 {
    #[cfg(target_arch = "x86_64")]
    v: std::arch::x86_64::__m128i,
    #[cfg(not(target_arch = "x86_64"))]
    v: [i32; 4],
}

impl Lanes4 {
    #[inline(always)]
    fn new(x: [i32; 4]) -> Lanes4 {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::x86_64::*;
            // SAFETY: SSE2 is part of the x86-64 baseline.
            unsafe {
                Lanes4 {
                    v: _mm_setr_epi32(x[0], x[1], x[2], x[3]),
                }
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            Lanes4 { v: x }
        }
    }

    #[inline(always)]
    fn splat(x: i32) -> Lanes4 {
        Lanes4::new([x; 4])
    }

    #[inline(always)]
    fn add(self, o: Lanes4) -> Lanes4 {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::x86_64::*;
            // SAFETY: SSE2 is part of the x86-64 baseline.
            unsafe {
                Lanes4 {
                    v: _mm_add_epi32(self.v, o.v),
                }
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            Lanes4 {
                v: std::array::from_fn(|i| self.v[i].wrapping_add(o.v[i])),
            }
        }
    }

    #[inline(always)]
    fn or(self, o: Lanes4) -> Lanes4 {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::x86_64::*;
            // SAFETY: SSE2 is part of the x86-64 baseline.
            unsafe {
                Lanes4 {
                    v: _mm_or_si128(self.v, o.v),
                }
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            Lanes4 {
                v: std::array::from_fn(|i| self.v[i] | o.v[i]),
            }
        }
    }

    /// Bit `i` set where element `i` is negative (its sign bit).
    #[inline(always)]
    fn negative(self) -> u8 {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::x86_64::*;
            // SAFETY: SSE2 is part of the x86-64 baseline.
            unsafe { _mm_movemask_ps(_mm_castsi128_ps(self.v)) as u8 }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            (0..4).fold(0u8, |m, i| m | (u8::from(self.v[i] < 0) << i))
        }
    }
}

fn inside(r: PixelRect, x: i64, y: i64) -> bool {
    x >= r.0 && x < r.2 && y >= r.1 && y < r.3
}

fn for_each_quad(r: PixelRect, mut f: impl FnMut(i64, i64)) {
    let (x0, y0) = (r.0 & !1, r.1 & !1);
    let mut qy = y0;
    while qy < r.3 {
        let mut qx = x0;
        while qx < r.2 {
            f(qx, qy);
            qx += 2;
        }
        qy += 2;
    }
}

#[cfg(test)]
mod tests;
