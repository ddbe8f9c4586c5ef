//! Interpolation planes: what a fragment interpolates (its varyings,
//! window z and 1/w) as planes over window space, set up once per
//! primitive and evaluated per pixel with one fixed sequence of
//! operations.
//!
//! GL 2.1 asks for perspective-correct varyings (§3.5.1 eq. 3.9 for
//! polygons, §3.4.1 eq. 3.6 for lines): `f = (Σ a_j f_j / w_j) / (Σ a_j /
//! w_j)` with the pixel's barycentrics `a_j`, and window z linear in
//! window space (eq. 3.10). The numerator, the denominator and z are each
//! affine in the pixel's window position, so set-up turns each into a
//! plane: its value `c` at the center of the primitive's *origin* pixel
//! `(x0, y0)` (the first pixel of its clipped bounds) and its steps `dx`,
//! `dy` per pixel, computed in f64 from the vertices' window positions
//! (a triangle's as the vertex stage made them, not the coverage's
//! snapped ones, as llvmpipe does; vertex 0's value plus the others'
//! differences times their barycentrics' planes), then rounded: to f32 for varyings and 1/w, kept in f64 for window z
//! (depth keeps more than a depth buffer's 24 bits). At pixel `(x, y)`,
//! with `X = x − x0` and `Y = y − y0` (small integers, exact in f32):
//!
//! ```text
//! P = (c + Y·dy) + X·dx          (f32; f64 for z)
//! ```
//!
//! and a varying is [`Kind::Constant`]: `c` itself (the same value at
//! every vertex, or flat-shaded: exact), [`Kind::Linear`]: `P` (all the
//! primitive's vertices have the same 1/w, as under orthographic
//! projections, where the division cancels exactly, or the varying is
//! `noperspective`, GLSL 1.30 §4.3.7: its plane is of the values
//! themselves, [`PrimPlanes::screen_linear`]), or
//! [`Kind::Perspective`]: `P · (1 / Q)` with `Q` the 1/w plane at the
//! pixel. These are the operations of llvmpipe and of GPUs (f32 plane
//! equations); results differ from exact barycentrics by a few f32 ulps
//! of the plane's terms. Every path (quads, strips of 16 lanes, packed
//! batches, every instruction set) performs them per lane in this order,
//! without fused multiply-adds, so the values are the same bits
//! everywhere.

use crate::ex;

/// How a varying's plane gives its value ([`Plane::values`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) enum Kind {
    /// `c` at every pixel.
    #[default]
    Constant,
    /// The plane's value.
    Linear,
    /// The plane's value (of f/w) times 1 over the 1/w plane's.
    Perspective,
}

/// One varying component of a primitive as a plane (see the module doc).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Plane {
    pub c: f32,
    pub dx: f32,
    pub dy: f32,
    pub kind: Kind,
}

/// The planes of a primitive's barycentrics of vertices 1 and 2, relative
/// to its origin: `[c, dx, dy]` each (zeros for vertices a primitive does
/// not have). Vertex 0's is one minus their sum; every other plane is
/// built from these ([`Basis::plane`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Basis {
    pub b: [[f64; 3]; 2],
}

impl Basis {
    /// The barycentric planes of a triangle from its window positions
    /// `v` as the vertex stage made them (not snapped to the coverage's
    /// grid), relative to the center of pixel `(x0, y0)`; `None` when
    /// they enclose no area. llvmpipe builds its planes from the same
    /// unsnapped positions: varyings that decide a silhouette (a ray
    /// cast from an interpolated point) then agree with it to an ulp
    /// instead of to a snap step's worth of the varying's gradient.
    #[inline]
    pub fn of_triangle(v: [(f64, f64); 3], (x0, y0): (i64, i64)) -> Option<Basis> {
        let [(ax, ay), (bx, by), (cx, cy)] = v;
        let (e1x, e1y, e2x, e2y) = (bx - ax, by - ay, cx - ax, cy - ay);
        let area2 = e1x * e2y - e1y * e2x;
        if area2 == 0.0 || !area2.is_finite() {
            return None;
        }
        let inv = 1.0 / area2;
        let (px, py) = (x0 as f64 + 0.5 - ax, y0 as f64 + 0.5 - ay);
        // b1: the area of (v0, p, v2), b2: of (v0, v1, p), over the whole.
        let b1 = [(px * e2y - py * e2x) * inv, e2y * inv, -e2x * inv];
        let b2 = [(e1x * py - e1y * px) * inv, -e1y * inv, e1x * inv];
        Some(Basis { b: [b1, b2] })
    }

    /// The plane `[c, dx, dy]` of a quantity with values `v` at the
    /// vertices: `v0 + Σ (v_j − v0)·b_j`, in f64. Exactly `[v0, 0, 0]`
    /// when the three are the same bits (also for infinities, whose
    /// differences would be NaN).
    #[inline(always)]
    pub fn plane(&self, v: [f64; 3]) -> [f64; 3] {
        if v[1].to_bits() == v[0].to_bits() && v[2].to_bits() == v[0].to_bits() {
            return [v[0], 0.0, 0.0];
        }
        let (d1, d2) = (v[1] - v[0], v[2] - v[0]);
        let [b1, b2] = &self.b;
        [
            v[0] + (d1 * b1[0] + d2 * b2[0]),
            d1 * b1[1] + d2 * b2[1],
            d1 * b1[2] + d2 * b2[2],
        ]
    }
}

/// A primitive's window z and 1/w planes (relative to its origin
/// pixel, which the primitive keeps: the first of its clipped bounds).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct PrimPlanes {
    /// Window z (before polygon offset): `[c, dx, dy]` in f64.
    pub z: [f64; 3],
    /// 1 / w_clip (gl_FragCoord.w), rounded to f32.
    pub inv_w: [f32; 3],
    /// Whether the vertices' 1/w differ (then non-constant varyings are
    /// [`Kind::Perspective`]).
    pub perspective: bool,
}

fn to_f32(p: [f64; 3]) -> [f32; 3] {
    p.map(|x| x as f32)
}

impl PrimPlanes {
    /// The planes of a primitive whose vertices have window z `z` and
    /// 1/w `inv_w` (a missing vertex repeats vertex 0), `basis` relative
    /// to its origin.
    #[inline]
    pub fn new(basis: &Basis, z: [f64; 3], inv_w: [f64; 3]) -> PrimPlanes {
        let w = inv_w.map(f64::to_bits);
        PrimPlanes {
            z: basis.plane(z),
            inv_w: to_f32(basis.plane(inv_w)),
            perspective: w[1] != w[0] || w[2] != w[0],
        }
    }

    /// The plane of a varying component with values `v` at the vertices
    /// (1/w `inv_w`, as given to [`PrimPlanes::new`]).
    #[inline(always)]
    pub fn varying(&self, basis: &Basis, v: [f32; 3], inv_w: [f64; 3]) -> Plane {
        let b = v.map(f32::to_bits);
        let [c, dx, dy] = if b[1] == b[0] && b[2] == b[0] {
            return Plane::constant(v[0]);
        } else if self.perspective {
            to_f32(basis.plane(std::array::from_fn(|j| v[j] as f64 * inv_w[j])))
        } else {
            to_f32(basis.plane(v.map(f64::from)))
        };
        let kind = match self.perspective {
            true => Kind::Perspective,
            false => Kind::Linear,
        };
        Plane { c, dx, dy, kind }
    }

    /// The plane of a `noperspective` varying component with values `v`
    /// at the vertices (GLSL 1.30 §4.3.7): linear in window space.
    #[inline(always)]
    pub fn screen_linear(&self, basis: &Basis, v: [f32; 3]) -> Plane {
        let b = v.map(f32::to_bits);
        if b[1] == b[0] && b[2] == b[0] {
            return Plane::constant(v[0]);
        }
        let [c, dx, dy] = to_f32(basis.plane(v.map(f64::from)));
        Plane {
            c,
            dx,
            dy,
            kind: Kind::Linear,
        }
    }

    /// Window z (before offset) at the pixels of `offsets` (exact as f64).
    #[inline(always)]
    pub fn z_at<const N: usize>(&self, x: &[f32; N], y: &[f32; N]) -> [f64; N] {
        let [c, dx, dy] = self.z;
        let mut out = [0.0f64; N];
        for l in 0..N {
            out[l] = (c + y[l] as f64 * dy) + x[l] as f64 * dx;
        }
        out
    }

    /// 1/w at the pixels of `offsets`.
    #[inline(always)]
    pub fn inv_w_at<const N: usize>(&self, x: &[f32; N], y: &[f32; N]) -> [f32; N] {
        let [c, dx, dy] = self.inv_w;
        at(c, dx, dy, x, y)
    }

    /// 1 over [`PrimPlanes::inv_w_at`] (what perspective varyings are
    /// multiplied by); ones when the primitive has none.
    #[inline(always)]
    pub fn reciprocal_w<const N: usize>(&self, x: &[f32; N], y: &[f32; N]) -> [f32; N] {
        if !self.perspective {
            return [1.0; N];
        }
        let q = self.inv_w_at(x, y);
        let mut out = [0.0f32; N];
        for l in 0..N {
            out[l] = 1.0 / q[l];
        }
        out
    }
}

/// The offsets `(X, Y)` from the origin `(x0, y0)` of the pixels `(x + ox[l], y +
/// oy[l])` (`ox`, `oy`: small whole numbers), as f32: the offset of
/// `(x, y)` converted, plus `ox[l]`, `oy[l]` (exact: coordinates stay
/// below 2^21).
#[inline(always)]
pub(crate) fn offsets<const N: usize>(
    (x0, y0): (i64, i64),
    (x, y): (i64, i64),
    ox: &[f32; N],
    oy: &[f32; N],
) -> ([f32; N], [f32; N]) {
    let (bx, by) = ((x - x0) as i32 as f32, (y - y0) as i32 as f32);
    let mut fx = [0.0f32; N];
    let mut fy = [0.0f32; N];
    for l in 0..N {
        fx[l] = bx + ox[l];
        fy[l] = by + oy[l];
    }
    (fx, fy)
}

/// `(c + y·dy) + x·dx` per lane.
#[inline(always)]
fn at<const N: usize>(c: f32, dx: f32, dy: f32, x: &[f32; N], y: &[f32; N]) -> [f32; N] {
    let mut out = [0.0f32; N];
    for l in 0..N {
        out[l] = (c + y[l] * dy) + x[l] * dx;
    }
    out
}

impl Plane {
    /// A varying with value `v` everywhere.
    pub fn constant(v: f32) -> Plane {
        Plane {
            c: v,
            dx: 0.0,
            dy: 0.0,
            kind: Kind::Constant,
        }
    }

    /// The varying at the pixels of [`offsets`] `(x, y)`,
    /// `rw` their [`PrimPlanes::reciprocal_w`].
    #[inline(always)]
    pub fn values<const N: usize>(&self, x: &[f32; N], y: &[f32; N], rw: &[f32; N]) -> [f32; N] {
        match self.kind {
            Kind::Constant => [self.c; N],
            Kind::Linear => at(self.c, self.dx, self.dy, x, y),
            Kind::Perspective => {
                let mut p = at(self.c, self.dx, self.dy, x, y);
                for l in 0..N {
                    p[l] *= rw[l];
                }
                p
            }
        }
    }
}

/// The pixel offsets from a primitive's origin of a rectangle of its
/// pixels, `X ∈ [x.0, x.1]`, `Y ∈ [y.0, y.1]`, as the region of
/// [`ex::Affine`] forms (`X = mid + half·u`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Region {
    pub x: (f64, f64),
    pub y: (f64, f64),
}

impl Region {
    /// `X` (`Y`: [`Region::y`]) as a form: exact.
    pub fn x(&self) -> ex::Affine {
        let (a, b) = self.x;
        ex::Affine::new(0.5 * (a + b), 0.5 * (b - a), 0.0, 0.0)
    }

    pub fn y(&self) -> ex::Affine {
        let (a, b) = self.y;
        ex::Affine::new(0.5 * (a + b), 0.0, 0.5 * (b - a), 0.0)
    }

    /// The values [`at`] gives over the region: `(c + Y·dy) + X·dx`, each
    /// operation's rounding included.
    fn at(&self, c: f32, dx: f32, dy: f32) -> Option<ex::Affine> {
        use ex::Affine as A;
        let y = A::mul_f32(self.y(), A::exact(dy))?;
        let x = A::mul_f32(self.x(), A::exact(dx))?;
        A::add_f32(A::add_f32(A::exact(c), y)?, x)
    }
}

impl Plane {
    /// A form holding the varying's value ([`Plane::values`]) at every
    /// pixel of `region`, `planes` its primitive's; `None` when the
    /// arithmetic may overflow or divide by zero.
    pub fn form(&self, planes: &PrimPlanes, region: &Region) -> Option<ex::Affine> {
        use ex::Affine as A;
        match self.kind {
            Kind::Constant => Some(A::exact(self.c)),
            Kind::Linear => region.at(self.c, self.dx, self.dy),
            Kind::Perspective => {
                let p = region.at(self.c, self.dx, self.dy)?;
                let [c, dx, dy] = planes.inv_w;
                let rw = match planes.perspective {
                    true => A::div_f32(A::exact(1.0), region.at(c, dx, dy)?)?,
                    false => A::exact(1.0),
                };
                A::mul_f32(p, rw)
            }
        }
    }
}

/// Pixel offsets of a quad's four pixels from its first (lane order:
/// pixel `k` at `(k & 1, k >> 1)`).
pub(crate) const QUAD_X: [f32; 4] = [0.0, 1.0, 0.0, 1.0];
pub(crate) const QUAD_Y: [f32; 4] = [0.0, 0.0, 1.0, 1.0];

/// Pixel offsets of a strip's 16 lanes (four quads side by side, lane
/// `4i + k` pixel `k` of quad `i`) from its first pixel.
pub(crate) const STRIP_X: [f32; 16] = {
    let mut x = [0.0f32; 16];
    let mut l = 0;
    while l < 16 {
        x[l] = (2 * (l / 4) + (l & 1)) as f32;
        l += 1;
    }
    x
};
pub(crate) const STRIP_Y: [f32; 16] = {
    let mut y = [0.0f32; 16];
    let mut l = 0;
    while l < 16 {
        y[l] = ((l >> 1) & 1) as f32;
        l += 1;
    }
    y
};

#[cfg(test)]
mod tests {
    use super::*;

    fn basis_of(b1: [f64; 3], b2: [f64; 3]) -> Basis {
        Basis { b: [b1, b2] }
    }

    /// A triangle's barycentric planes from unsnapped window positions:
    /// each vertex's own weight is 1 at it and 0 at the others, wherever
    /// the origin pixel is, and a collinear triangle has none.
    #[test]
    fn triangle_planes_come_from_the_window_positions() {
        let v = [(10.3, 4.1), (40.77, 9.02), (18.2, 33.9)];
        let origin = (10, 4);
        let basis = Basis::of_triangle(v, origin).unwrap();
        let at = |b: [f64; 3], (x, y): (f64, f64)| {
            b[0] + (x - (origin.0 as f64 + 0.5)) * b[1] + (y - (origin.1 as f64 + 0.5)) * b[2]
        };
        for (j, want) in [(0, [0.0, 0.0]), (1, [1.0, 0.0]), (2, [0.0, 1.0])] {
            for (k, b) in basis.b.iter().enumerate() {
                assert!(
                    (at(*b, v[j]) - want[k]).abs() < 1e-12,
                    "vertex {j}, weight {k}"
                );
            }
        }
        assert!(Basis::of_triangle([(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)], origin).is_none());
    }

    #[test]
    fn constant_values_stay_exact() {
        let basis = basis_of([0.3, 0.01, -0.02], [0.1, -0.03, 0.05]);
        let p = PrimPlanes::new(&basis, [0.25; 3], [0.5, 0.25, 0.125]);
        assert_eq!(p.z, [0.25, 0.0, 0.0]);
        assert!(p.perspective);
        let v = p.varying(&basis, [0.7; 3], [0.5, 0.25, 0.125]);
        assert_eq!(v, Plane::constant(0.7));
        let (x, y) = offsets((0, 0), (37, -5), &STRIP_X, &STRIP_Y);
        let rw = p.reciprocal_w(&x, &y);
        assert_eq!(v.values(&x, &y, &rw), [0.7; 16]);
        // Infinities too.
        let inf = p.varying(&basis, [f32::INFINITY; 3], [0.5, 0.25, 0.125]);
        assert_eq!(inf.values(&x, &y, &rw), [f32::INFINITY; 16]);
    }

    #[test]
    fn equal_w_gives_linear_planes() {
        let basis = basis_of([0.0, 0.5, 0.0], [0.0, 0.0, 0.5]);
        let p = PrimPlanes::new(&basis, [0.0, 1.0, 0.5], [2.0; 3]);
        assert!(!p.perspective);
        let v = p.varying(&basis, [1.0, 3.0, 5.0], [2.0; 3]);
        assert_eq!(v.kind, Kind::Linear);
        assert_eq!((v.c, v.dx, v.dy), (1.0, 1.0, 2.0));
        let (x, y) = offsets((10, 20), (12, 21), &QUAD_X, &QUAD_Y);
        assert_eq!(x, [2.0, 3.0, 2.0, 3.0]);
        assert_eq!(y, [1.0, 1.0, 2.0, 2.0]);
        let rw = p.reciprocal_w(&x, &y);
        assert_eq!(v.values(&x, &y, &rw), [5.0, 6.0, 7.0, 8.0]);
        assert_eq!(p.z_at(&x, &y), [1.25, 1.75, 1.5, 2.0]);
    }

    #[test]
    fn noperspective_planes_ignore_w() {
        // The same vertices as `equal_w_gives_linear_planes`, now with
        // different 1/w: a smooth varying turns perspective, a
        // noperspective one keeps the window-linear plane.
        let basis = basis_of([0.0, 0.5, 0.0], [0.0, 0.0, 0.5]);
        let inv_w = [1.0, 0.5, 0.25];
        let p = PrimPlanes::new(&basis, [0.0, 1.0, 0.5], inv_w);
        assert!(p.perspective);
        let smooth = p.varying(&basis, [1.0, 3.0, 5.0], inv_w);
        assert_eq!(smooth.kind, Kind::Perspective);
        let linear = p.screen_linear(&basis, [1.0, 3.0, 5.0]);
        assert_eq!(linear.kind, Kind::Linear);
        assert_eq!((linear.c, linear.dx, linear.dy), (1.0, 1.0, 2.0));
        let (x, y) = offsets((10, 20), (12, 21), &QUAD_X, &QUAD_Y);
        let rw = p.reciprocal_w(&x, &y);
        assert_eq!(linear.values(&x, &y, &rw), [5.0, 6.0, 7.0, 8.0]);
        assert_ne!(smooth.values(&x, &y, &rw), [5.0, 6.0, 7.0, 8.0]);
        assert_eq!(p.screen_linear(&basis, [0.5; 3]), Plane::constant(0.5));
    }

    #[test]
    fn strips_and_quads_give_the_same_bits() {
        let basis = basis_of([0.013, 0.0071, -0.0033], [0.41, -0.0029, 0.0117]);
        let inv_w = [0.31, 0.07, 0.9];
        let p = PrimPlanes::new(&basis, [0.1, 0.7, 0.3], inv_w);
        let v = p.varying(&basis, [0.3, -2.5, 7.25], inv_w);
        assert_eq!(v.kind, Kind::Perspective);
        let origin = (40, 18);
        let (x, y) = offsets((3, 7), origin, &STRIP_X, &STRIP_Y);
        let strip = v.values(&x, &y, &p.reciprocal_w(&x, &y));
        let z16 = p.z_at(&x, &y);
        for q in 0..4 {
            let (qx, qy) = offsets(
                (3, 7),
                (origin.0 + 2 * q as i64, origin.1),
                &QUAD_X,
                &QUAD_Y,
            );
            let quad = v.values(&qx, &qy, &p.reciprocal_w(&qx, &qy));
            assert_eq!(
                quad.map(f32::to_bits),
                std::array::from_fn(|k| strip[4 * q + k].to_bits())
            );
            let z = p.z_at(&qx, &qy);
            assert_eq!(
                z.map(f64::to_bits),
                std::array::from_fn(|k| z16[4 * q + k].to_bits())
            );
        }
    }
}
