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
//! plane: its value `c` at the centre of pixel (0, 0) and its steps `dx`,
//! `dy` per pixel. At pixel `(x, y)` (whole numbers, exact in f32):
//!
//! ```text
//! P = fma(dy, y, fma(dx, x, c))     (f32)
//! ```
//!
//! and a varying is [`Kind::Constant`]: `c` itself, [`Kind::Linear`]: `P`
//! (every vertex has 1/w = 1, as under orthographic projections, where
//! the division is exact, or the varying is `noperspective`, GLSL 1.30
//! §4.3.7: its plane is of the values themselves,
//! [`PrimPlanes::screen_linear`]), or [`Kind::Perspective`]: `P · (1 /
//! Q)`, `P` the plane of the values times their vertices' 1/w (each
//! product rounded to f32) and `Q` the 1/w plane at the pixel.
//!
//! A triangle's varying and 1/w planes are set up as llvmpipe sets them
//! up ([`TriangleSetup`]), so that a program whose picture rests on the
//! last bits of an interpolated value (a ray cast from an interpolated
//! point grazing a sphere) draws what it draws on Mesa: llvmpipe's f32
//! operations in its order, from the f32 window positions of its viewport
//! transform, with its choice of the vertex order (whose rounding the
//! bits depend on), the plane's value at pixel (0, 0) and its fused
//! evaluation. Measured against Mesa 22.3.6 (`scripts/interpolation-bits.py`):
//! the same bits at every pixel. GL leaves this rounding to the
//! implementation (GL 2.1 §2.1.1); llvmpipe's is as good a choice as any
//! and the one other programs' reference images were drawn with. Window z
//! too is llvmpipe's (its plane and its value at the pixel; polygon offset
//! is then added in f64), so a depth test ties where Mesa's does. Lines and
//! points take planes computed in f64 from their own bases ([`Basis`]),
//! rounded to f32 and evaluated the same way.
//!
//! Every path (quads, strips of 16 lanes, packed batches, every instruction
//! set) performs these operations per lane in this order. The fused
//! multiply-add is `f32::mul_add`, one rounding on every level (an FMA
//! instruction where the level has one, the C library's correctly rounded
//! `fmaf` on the portable level), so the values are the same bits
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

/// The planes of a primitive's barycentrics of vertices 1 and 2, in f64
/// (`[c, dx, dy]` each, `c` at the centre of pixel (0, 0); zeros for
/// vertices a primitive does not have). Vertex 0's is one minus their
/// sum; window z's plane, and a line's or a point's varyings', are built
/// from these ([`Basis::plane`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Basis {
    pub b: [[f64; 3]; 2],
}

impl Basis {
    /// The barycentric planes of a triangle from its window positions
    /// `v` as the vertex stage made them (not snapped to the coverage's
    /// grid); `None` when they enclose no area.
    #[inline]
    pub fn of_triangle(v: [(f64, f64); 3]) -> Option<Basis> {
        let [(ax, ay), (bx, by), (cx, cy)] = v;
        let (e1x, e1y, e2x, e2y) = (bx - ax, by - ay, cx - ax, cy - ay);
        let area2 = e1x * e2y - e1y * e2x;
        if area2 == 0.0 || !area2.is_finite() {
            return None;
        }
        let inv = 1.0 / area2;
        let (px, py) = (0.5 - ax, 0.5 - ay);
        // b1: the area of (v0, p, v2), b2: of (v0, v1, p), over the whole.
        let b1 = [(px * e2y - py * e2x) * inv, e2y * inv, -e2x * inv];
        let b2 = [(e1x * py - e1y * px) * inv, -e1y * inv, e1x * inv];
        Some(Basis { b: [b1, b2] })
    }

    /// The same planes over rows numbered from the top, `top` the last
    /// row's number: `y = top − y'`.
    pub fn top_down(self, top: f64) -> Basis {
        Basis {
            b: self.b.map(|[c, dx, dy]| [c + dy * top, dx, -dy]),
        }
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

/// llvmpipe's set-up of a triangle's planes (its `lp_state_setup.c`),
/// in f32: vertex 0 relative to the centre of pixel (0, 0), and the edges
/// from vertex 1 to 0 and from 0 to 2 divided by the doubled signed area.
/// The vertex order is the primitive's, except that vertices 0 and 1 trade
/// places when the area is negative (llvmpipe's rule for clockwise
/// triangles, which it rasterizes as counter-clockwise ones): the planes'
/// rounding depends on the order, not their exact values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct TriangleSetup {
    x0: f32,
    y0: f32,
    dx01: f32,
    dy01: f32,
    dx20: f32,
    dy20: f32,
}

impl TriangleSetup {
    /// The set-up of the triangle of window positions `v` (f32, as the
    /// viewport transform made them) and the vertex order it uses (`[0,
    /// 1, 2]` or `[1, 0, 2]`); `None` when the area is zero or not finite.
    #[inline]
    pub fn new(v: [(f32, f32); 3]) -> Option<(TriangleSetup, [usize; 3])> {
        // The edges from vertex 1 to 0 and from 0 to 2, and the doubled
        // signed area they span, in the order given.
        let edges = |[a, b, c]: [(f32, f32); 3]| {
            let (dx01, dy01, dx20, dy20) = (a.0 - b.0, a.1 - b.1, c.0 - a.0, c.1 - a.1);
            ([dx01, dy01, dx20, dy20], dx01 * dy20 - dy01 * dx20)
        };
        let (mut v, mut order) = (v, [0, 1, 2]);
        let (mut e, mut area) = edges(v);
        if area == 0.0 || !area.is_finite() {
            return None;
        }
        if area < 0.0 {
            (v, order) = ([v[1], v[0], v[2]], [1, 0, 2]);
            (e, area) = edges(v);
        }
        let ooa = 1.0 / area;
        if !ooa.is_finite() {
            return None;
        }
        let [dx01, dy01, dx20, dy20] = e.map(|d| d * ooa);
        let setup = TriangleSetup {
            x0: v[0].0 - 0.5,
            y0: v[0].1 - 0.5,
            dx01,
            dy01,
            dx20,
            dy20,
        };
        Some((setup, order))
    }

    /// The plane `[c, dx, dy]` of values `a` at the vertices (in the
    /// set-up's order).
    #[inline(always)]
    pub fn plane(&self, a: [f32; 3]) -> [f32; 3] {
        let (da01, da20) = (a[0] - a[1], a[2] - a[0]);
        let dx = da01 * self.dy20 - da20 * self.dy01;
        let dy = da20 * self.dx01 - da01 * self.dx20;
        [a[0] - (dx * self.x0 + dy * self.y0), dx, dy]
    }
}

/// How a primitive's planes are built: a triangle's from its
/// [`TriangleSetup`] (values taken in the set-up's vertex order), a line's,
/// a point's or a degenerate triangle's from its f64 [`Basis`], rounded.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Bases {
    Triangle(TriangleSetup, [usize; 3]),
    General(Basis),
}

impl Bases {
    /// The f32 plane of values `v` at the primitive's vertices.
    #[inline(always)]
    fn plane(&self, v: [f32; 3]) -> [f32; 3] {
        match self {
            Bases::Triangle(t, o) => t.plane(o.map(|j| v[j])),
            Bases::General(b) => to_f32(b.plane(v.map(f64::from))),
        }
    }
}

/// A primitive's window z and 1/w planes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct PrimPlanes {
    /// Window z (before polygon offset).
    pub z: [f32; 3],
    /// 1 / w_clip (gl_FragCoord.w).
    pub inv_w: [f32; 3],
    /// Whether some vertex's 1/w is not 1 (then non-constant varyings are
    /// [`Kind::Perspective`]).
    pub perspective: bool,
    /// The last row's number when the planes number rows from the top
    /// (`PipelineState::top_down`); see [`offsets`].
    pub top: Option<f32>,
}

fn to_f32(p: [f64; 3]) -> [f32; 3] {
    p.map(|x| x as f32)
}

impl PrimPlanes {
    /// The planes of a primitive whose vertices have window z `z` and
    /// 1/w `inv_w` (a missing vertex repeats vertex 0), over rows from the
    /// top when `top` is the last row's number.
    #[inline]
    pub fn new(bases: &Bases, z: [f32; 3], inv_w: [f32; 3], top: Option<f32>) -> PrimPlanes {
        PrimPlanes {
            z: bases.plane(z),
            inv_w: bases.plane(inv_w),
            perspective: inv_w.iter().any(|&w| w.to_bits() != 1.0f32.to_bits()),
            top,
        }
    }

    /// The plane of a varying component with values `v` at the vertices
    /// (1/w `inv_w`, as given to [`PrimPlanes::new`]).
    #[inline(always)]
    pub fn varying(&self, bases: &Bases, v: [f32; 3], inv_w: [f32; 3]) -> Plane {
        let b = v.map(f32::to_bits);
        let same = b[1] == b[0] && b[2] == b[0];
        if !self.perspective {
            return match same {
                true => Plane::constant(v[0]),
                false => Plane::of(bases.plane(v), Kind::Linear),
            };
        }
        let p: [f32; 3] = std::array::from_fn(|j| v[j] * inv_w[j]);
        let w = inv_w.map(f32::to_bits);
        if same && w[1] == w[0] && w[2] == w[0] {
            // The plane is [p, ±0, ±0] and Q is 1/w everywhere: the value
            // is the same product at every pixel (infinities kept).
            return Plane::constant(if v[0].is_finite() {
                p[0] * (1.0 / inv_w[0])
            } else {
                v[0]
            });
        }
        Plane::of(bases.plane(p), Kind::Perspective)
    }

    /// The plane of a `noperspective` varying component with values `v`
    /// at the vertices (GLSL 1.30 §4.3.7): linear in window space.
    #[inline(always)]
    pub fn screen_linear(&self, bases: &Bases, v: [f32; 3]) -> Plane {
        let b = v.map(f32::to_bits);
        if b[1] == b[0] && b[2] == b[0] {
            return Plane::constant(v[0]);
        }
        Plane::of(bases.plane(v), Kind::Linear)
    }

    /// Window z (before offset) at the pixels `(x, y)`, as f64 (what
    /// polygon offset and the depth conversion take).
    #[inline(always)]
    pub fn z_at<const N: usize>(&self, x: &[f32; N], y: &[f32; N]) -> [f64; N] {
        let [c, dx, dy] = self.z;
        at(c, dx, dy, x, y).map(f64::from)
    }

    /// 1/w at the pixels `(x, y)`.
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

/// The positions the planes are evaluated at for the pixels `(x + ox[l],
/// y + oy[l])` (`ox`, `oy`: small whole numbers), as f32 (exact:
/// coordinates stay below 2^21): the pixel itself, or with `top` (the
/// last row's number) its row counted from the top, `top − y`.
#[inline(always)]
pub(crate) fn offsets<const N: usize>(
    (x, y): (i64, i64),
    ox: &[f32; N],
    oy: &[f32; N],
    top: Option<f32>,
) -> ([f32; N], [f32; N]) {
    let (bx, by) = (x as i32 as f32, y as i32 as f32);
    let mut fx = [0.0f32; N];
    let mut fy = [0.0f32; N];
    for l in 0..N {
        fx[l] = bx + ox[l];
    }
    match top {
        Some(t) => {
            let by = t - by;
            for l in 0..N {
                fy[l] = by - oy[l];
            }
        }
        None => {
            for l in 0..N {
                fy[l] = by + oy[l];
            }
        }
    }
    (fx, fy)
}

/// `fma(dy, y, fma(dx, x, c))` per lane.
#[inline(always)]
fn at<const N: usize>(c: f32, dx: f32, dy: f32, x: &[f32; N], y: &[f32; N]) -> [f32; N] {
    let mut out = [0.0f32; N];
    for l in 0..N {
        out[l] = dy.mul_add(y[l], dx.mul_add(x[l], c));
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

    fn of([c, dx, dy]: [f32; 3], kind: Kind) -> Plane {
        Plane { c, dx, dy, kind }
    }

    /// The varying at the pixels `(x, y)`, `rw` their
    /// [`PrimPlanes::reciprocal_w`].
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

/// The pixels of a rectangle, `x ∈ [x.0, x.1]`, `y ∈ [y.0, y.1]`, as the
/// region of [`ex::Affine`] forms (`x = mid + half·u`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Region {
    pub x: (f64, f64),
    pub y: (f64, f64),
}

impl Region {
    /// `x` (`y`: [`Region::y`]) as a form: exact.
    pub fn x(&self) -> ex::Affine {
        let (a, b) = self.x;
        ex::Affine::new(0.5 * (a + b), 0.5 * (b - a), 0.0, 0.0)
    }

    pub fn y(&self) -> ex::Affine {
        let (a, b) = self.y;
        ex::Affine::new(0.5 * (a + b), 0.0, 0.5 * (b - a), 0.0)
    }

    /// A form holding the values [`at`] gives over the region. Each fused
    /// operation rounds once; the form rounds its product and its sum
    /// apart, whose error bound holds the fused result too.
    fn at(&self, c: f32, dx: f32, dy: f32) -> Option<ex::Affine> {
        use ex::Affine as A;
        let x = A::mul_f32(self.x(), A::exact(dx))?;
        let y = A::mul_f32(self.y(), A::exact(dy))?;
        A::add_f32(y, A::add_f32(x, A::exact(c))?)
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

    fn basis_of(b1: [f64; 3], b2: [f64; 3]) -> Bases {
        Bases::General(Basis { b: [b1, b2] })
    }

    /// A triangle's barycentric planes from unsnapped window positions:
    /// each vertex's own weight is 1 at it and 0 at the others, and a
    /// collinear triangle has none.
    #[test]
    fn triangle_planes_come_from_the_window_positions() {
        let v = [(10.3, 4.1), (40.77, 9.02), (18.2, 33.9)];
        let basis = Basis::of_triangle(v).unwrap();
        let at = |b: [f64; 3], (x, y): (f64, f64)| b[0] + (x - 0.5) * b[1] + (y - 0.5) * b[2];
        for (j, want) in [(0, [0.0, 0.0]), (1, [1.0, 0.0]), (2, [0.0, 1.0])] {
            for (k, b) in basis.b.iter().enumerate() {
                assert!(
                    (at(*b, v[j]) - want[k]).abs() < 1e-12,
                    "vertex {j}, weight {k}"
                );
            }
        }
        assert!(Basis::of_triangle([(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)]).is_none());
        // Rows from the top: the same values at the same pixels.
        let top = basis.top_down(63.0);
        for (x, y) in [(10.0, 4.0), (25.0, 17.0)] {
            for (b, t) in basis.b.iter().zip(&top.b) {
                let down = t[0] + x * t[1] + (63.0 - y) * t[2];
                assert!((b[0] + x * b[1] + y * b[2] - down).abs() < 1e-12);
            }
        }
    }

    /// What llvmpipe (Mesa 22.3.6) interpolates, bit for bit: one of the
    /// seed talk's sphere impostors in perspective (crambin at 256×256,
    /// the billboard of vertices 860-863 of `shaderbox render
    /// --export-scene`), its `view_direction` at pixel (84, 115) of a
    /// framebuffer object, read back from Mesa as floats. The quad's
    /// first triangle is clockwise in llvmpipe's terms: set up from
    /// vertex 1.
    #[test]
    fn planes_round_as_llvmpipe_s() {
        let f = f32::from_bits;
        let win = [
            (0x4284bbd6, 0x42e23cc7),
            (0x42b19ffd, 0x42e23cc7),
            (0x42b19ffd, 0x43079078),
        ]
        .map(|(x, y)| (f(x), f(y)));
        let inv_w = [f(0x3c7d3ba3); 3];
        let view = [
            [0xbe02f7c4, 0xbcfcfa1b, 0xbf7dc643],
            [0xbda75c74, 0xbcfe37fb, 0xbf7f0523],
            [0xbda76bc2, 0x3c8144b0, 0xbf7f1c76],
        ];
        let (setup, order) = TriangleSetup::new(win).unwrap();
        assert_eq!(order, [1, 0, 2]);
        let bases = Bases::Triangle(setup, order);
        let planes = PrimPlanes::new(&bases, [0.5; 3], inv_w, None);
        let (x, y) = offsets((84, 115), &[0.0], &[0.0], None);
        let rw = planes.reciprocal_w(&x, &y);
        let mesa = [0xbdb989c3u32, 0xbcd54b93, 0xbf7eca58];
        for (c, want) in mesa.iter().enumerate() {
            let v = planes.varying(&bases, view.map(|v| f(v[c])), inv_w);
            assert_eq!(v.kind, Kind::Perspective);
            assert_eq!(v.values(&x, &y, &rw)[0].to_bits(), *want, "component {c}");
        }
        // The same constant at the three vertices, as llvmpipe gives it:
        // the product with 1/w, then with 1 over it (not the value).
        let r2 = planes.varying(&bases, [2.3104; 3], inv_w);
        assert_eq!(r2.values(&x, &y, &rw)[0].to_bits(), 0x4013dd97);
    }

    #[test]
    fn constants_and_orthographic_planes_stay_exact() {
        let bases = basis_of([0.3, 0.01, -0.02], [0.1, -0.03, 0.05]);
        // Every 1/w 1: constants exact, and a plane's values too.
        let p = PrimPlanes::new(&bases, [0.25; 3], [1.0; 3], None);
        assert_eq!(p.z, [0.25, 0.0, 0.0]);
        assert!(!p.perspective);
        assert_eq!(p.varying(&bases, [0.7; 3], [1.0; 3]), Plane::constant(0.7));
        let ortho = basis_of([0.0, 0.5, 0.0], [0.0, 0.0, 0.5]);
        let p = PrimPlanes::new(&ortho, [0.0, 1.0, 0.5], [1.0; 3], None);
        let v = p.varying(&ortho, [1.0, 3.0, 5.0], [1.0; 3]);
        assert_eq!(v.kind, Kind::Linear);
        let (x, y) = offsets((2, 1), &QUAD_X, &QUAD_Y, None);
        assert_eq!(x, [2.0, 3.0, 2.0, 3.0]);
        assert_eq!(y, [1.0, 1.0, 2.0, 2.0]);
        let rw = p.reciprocal_w(&x, &y);
        assert_eq!(rw, [1.0; 4]);
        assert_eq!(v.values(&x, &y, &rw), [5.0, 6.0, 7.0, 8.0]);
        // A constant under one 1/w: one value everywhere; infinities kept.
        let w = [0.5; 3];
        let p = PrimPlanes::new(&bases, [0.25; 3], w, None);
        assert!(p.perspective);
        let c = p.varying(&bases, [0.7; 3], w);
        assert_eq!(c.kind, Kind::Constant);
        assert_eq!(c.c, 0.7 * 0.5 * (1.0 / 0.5));
        let inf = p.varying(&bases, [f32::INFINITY; 3], w);
        assert_eq!(inf, Plane::constant(f32::INFINITY));
        // Under different 1/w a constant is a perspective plane.
        let w = [0.5, 0.25, 0.125];
        let p = PrimPlanes::new(&bases, [0.25; 3], w, None);
        assert_eq!(p.varying(&bases, [0.7; 3], w).kind, Kind::Perspective);
    }

    #[test]
    fn noperspective_planes_ignore_w() {
        let bases = basis_of([0.0, 0.5, 0.0], [0.0, 0.0, 0.5]);
        let inv_w = [1.0, 0.5, 0.25];
        let p = PrimPlanes::new(&bases, [0.0, 1.0, 0.5], inv_w, None);
        assert!(p.perspective);
        let smooth = p.varying(&bases, [1.0, 3.0, 5.0], inv_w);
        assert_eq!(smooth.kind, Kind::Perspective);
        let linear = p.screen_linear(&bases, [1.0, 3.0, 5.0]);
        assert_eq!(linear.kind, Kind::Linear);
        assert_eq!((linear.c, linear.dx, linear.dy), (1.0, 1.0, 2.0));
        let (x, y) = offsets((2, 1), &QUAD_X, &QUAD_Y, None);
        let rw = p.reciprocal_w(&x, &y);
        assert_eq!(linear.values(&x, &y, &rw), [5.0, 6.0, 7.0, 8.0]);
        assert_ne!(smooth.values(&x, &y, &rw), [5.0, 6.0, 7.0, 8.0]);
        assert_eq!(p.screen_linear(&bases, [0.5; 3]), Plane::constant(0.5));
    }

    /// Rows from the top: a pixel's position is `top − y`, its quad's
    /// lower row one less.
    #[test]
    fn top_down_rows() {
        let (x, y) = offsets((6, 10), &QUAD_X, &QUAD_Y, Some(63.0));
        assert_eq!(x, [6.0, 7.0, 6.0, 7.0]);
        assert_eq!(y, [53.0, 53.0, 52.0, 52.0]);
    }

    #[test]
    fn strips_and_quads_give_the_same_bits() {
        let win = [(3.2, 7.9), (61.7, 12.4), (20.05, 40.6)];
        let inv_w = [0.31, 0.07, 0.9];
        let (setup, order) = TriangleSetup::new(win).unwrap();
        let bases = Bases::Triangle(setup, order);
        for top in [None, Some(63.0)] {
            let p = PrimPlanes::new(&bases, [0.1, 0.7, 0.3], inv_w, top);
            let v = p.varying(&bases, [0.3, -2.5, 7.25], inv_w);
            assert_eq!(v.kind, Kind::Perspective);
            let origin = (40, 18);
            let (x, y) = offsets(origin, &STRIP_X, &STRIP_Y, top);
            let strip = v.values(&x, &y, &p.reciprocal_w(&x, &y));
            let z16 = p.z_at(&x, &y);
            for q in 0..4 {
                let at = (origin.0 + 2 * q as i64, origin.1);
                let (qx, qy) = offsets(at, &QUAD_X, &QUAD_Y, top);
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
}
