//! Clipping in clip space (GL 2.1 §2.12, GL 3.3 §2.20): against the view
//! volume `-w <= x, y, z <= w` and the enabled user clip planes. A user
//! plane's distance at a vertex is either its plane equation dotted with
//! the eye-space clip vertex (gl_ClipVertex, or gl_Position without it)
//! or, when the vertex shader writes `gl_ClipDistance`, that array's
//! element for the plane ([`UserPlane`]). Every vertex carries its whole
//! vertex-shader output vector, interpolated linearly in clip space,
//! except the components named `noperspective`, interpolated at the
//! parameter that is linear in window space (GL 3.3 §2.20).
//!
//! New vertices on an edge are always computed from the inside vertex
//! towards the outside one, so an edge shared by two primitives is cut at
//! bit-identical points whatever the primitives' winding.
//!
//! Where a new vertex lies is computed in `f64` and rounded once, and a
//! vertex made on a view-volume plane is put exactly on it: in `f32` the
//! cut's rounding grows with the coordinates (at 10⁶ it is a sixteenth of
//! the view volume's half-width), which moved the clipped edges of very
//! large primitives by pixels. The carried values are interpolated in
//! `f32` at the same parameter.

use std::ops::{Add, Sub};

/// A vertex during clipping.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ClipVertex {
    /// gl_Position.
    pub pos: [f32; 4],
    /// Eye-space position for the user clip planes.
    pub eye: [f32; 4],
    /// All vertex-shader outputs.
    pub data: Vec<f32>,
}

/// Where an enabled user clip plane's distance comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum UserPlane {
    /// The plane equation dotted with the eye-space clip vertex.
    Equation([f32; 4]),
    /// This component of the vertex data (an element of
    /// `gl_ClipDistance`).
    Distance(usize),
}

/// The clip planes of one draw.
pub(crate) struct Planes {
    user: Vec<UserPlane>,
    /// The vertex-data components interpolated linearly in window space
    /// (`noperspective` varyings), ascending.
    noperspective: Vec<usize>,
    /// GL_DEPTH_CLAMP: no near and far planes (planes 4 and 5).
    depth_clamp: bool,
}

const VIEW_PLANES: usize = 6;

/// The distance of clip-space `[x, y, z, w]` inside view plane `p`
/// (`w ± x`, `w ± y`, `w ± z` for planes 0 to 5), in the type it is given
/// in; `None` for a user plane.
#[inline]
fn view_distance<T: Copy + Add<Output = T> + Sub<Output = T>>(p: usize, pos: [T; 4]) -> Option<T> {
    let [x, y, z, w] = pos;
    match p {
        0 => Some(w + x),
        1 => Some(w - x),
        2 => Some(w + y),
        3 => Some(w - y),
        4 => Some(w + z),
        5 => Some(w - z),
        _ => None,
    }
}

impl Planes {
    /// The planes of a draw with user clip planes `user` (their
    /// equations when enabled), the vertex shader writing
    /// `clip_distance` (its first component and length) when it writes
    /// `gl_ClipDistance`: then enabled plane `i` clips against element
    /// `i`, and is ignored when the array is shorter (GL 3.3 §2.20
    /// leaves that undefined). Carried components in `noperspective`
    /// are interpolated linearly in window space.
    pub fn new(
        user: &[Option<[f32; 4]>; 8],
        clip_distance: Option<(usize, usize)>,
        noperspective: Vec<usize>,
    ) -> Planes {
        let user = user
            .iter()
            .enumerate()
            .filter_map(|(i, eq)| {
                let eq = (*eq)?;
                match clip_distance {
                    Some((at, len)) => (i < len).then_some(UserPlane::Distance(at + i)),
                    None => Some(UserPlane::Equation(eq)),
                }
            })
            .collect();
        Planes {
            user,
            noperspective,
            depth_clamp: false,
        }
    }

    /// These planes without the near and far ones when `on` (GL 3.3
    /// §2.20 depth clamping: depths are clamped per fragment instead).
    pub fn with_depth_clamp(self, on: bool) -> Planes {
        Planes {
            depth_clamp: on,
            ..self
        }
    }

    fn count(&self) -> usize {
        VIEW_PLANES + self.user.len()
    }

    /// Signed distance of `v` to plane `p` (inside when >= 0; NaN is outside).
    fn distance(&self, p: usize, v: &ClipVertex) -> f32 {
        self.distance_of(p, &v.pos, &v.eye, &v.data)
    }

    /// [`Planes::distance`] in `f64`, for placing a cut: the sum of a
    /// view plane's two `f32` terms is exact in `f64` for every finite
    /// input that matters (their exponents differ by less than 29).
    fn distance_f64(&self, p: usize, v: &ClipVertex) -> f64 {
        view_distance(p, v.pos.map(f64::from)).unwrap_or_else(|| f64::from(self.distance(p, v)))
    }

    /// Where along `from → to` plane `p` cuts (0 at `from`, 1 at `to`).
    fn cut(&self, p: usize, from: &ClipVertex, to: &ClipVertex) -> f64 {
        let (df, dt) = (self.distance_f64(p, from), self.distance_f64(p, to));
        df / (df - dt)
    }

    /// [`Planes::distance`] of a vertex at `pos` (eye-space `eye`, data
    /// `data`).
    fn distance_of(&self, p: usize, pos: &[f32; 4], eye: &[f32; 4], data: &[f32]) -> f32 {
        if self.depth_clamp && (p == 4 || p == 5) {
            return 1.0;
        }
        view_distance(p, *pos).unwrap_or_else(|| match self.user.get(p - VIEW_PLANES) {
            Some(UserPlane::Equation(pl)) => {
                pl[0] * eye[0] + pl[1] * eye[1] + pl[2] * eye[2] + pl[3] * eye[3]
            }
            Some(&UserPlane::Distance(at)) => data.get(at).copied().unwrap_or(0.0),
            None => 0.0,
        })
    }

    /// Bit p set when `v` is outside plane p.
    fn outcode(&self, v: &ClipVertex) -> u32 {
        self.outcode_of(&v.pos, &v.eye, &v.data)
    }

    /// [`Planes::outcode`] of a vertex at `pos` (eye-space `eye`, data
    /// `data`): 0 when inside every plane.
    pub fn outcode_of(&self, pos: &[f32; 4], eye: &[f32; 4], data: &[f32]) -> u32 {
        let mut code = 0;
        for p in 0..self.count() {
            if !inside(self.distance_of(p, pos, eye, data)) {
                code |= 1 << p;
            }
        }
        code
    }

    /// Is a point inside every plane (GL 2.1 §2.12: points are discarded
    /// when their vertex is outside)?
    pub fn point_inside(&self, v: &ClipVertex) -> bool {
        self.outcode(v) == 0
    }

    /// Clips a line segment; `None` when nothing is left.
    pub fn clip_line(&self, a: &ClipVertex, b: &ClipVertex) -> Option<(ClipVertex, ClipVertex)> {
        let (ca, cb) = (self.outcode(a), self.outcode(b));
        if ca & cb != 0 {
            return None;
        }
        if ca | cb == 0 {
            return Some((a.clone(), b.clone()));
        }
        // Parametric: keep t in [t0, t1] along a → b, each end with the
        // plane that set it.
        let (mut t0, mut t1) = ((0.0f64, None), (1.0f64, None));
        for p in 0..self.count() {
            let (da, db) = (self.distance(p, a), self.distance(p, b));
            match (inside(da), inside(db)) {
                (true, true) => {}
                (false, false) => return None,
                (true, false) => {
                    let t = self.cut(p, a, b);
                    if t < t1.0 {
                        t1 = (t, Some(p));
                    }
                }
                (false, true) => {
                    let t = self.cut(p, a, b);
                    if t > t0.0 {
                        t0 = (t, Some(p));
                    }
                }
            }
        }
        if t0.0.is_nan() || t1.0.is_nan() || t0.0 > t1.0 {
            return None;
        }
        let end = |t: (f64, Option<usize>), at: &ClipVertex| match t.1 {
            Some(p) => on_plane(p, self.lerp(a, b, t.0)),
            None => at.clone(),
        };
        Some((end(t0, a), end(t1, b)))
    }

    /// Sutherland–Hodgman clipping of a convex polygon; returns fewer than
    /// three vertices when nothing is left.
    pub fn clip_polygon(&self, poly: Vec<ClipVertex>) -> Vec<ClipVertex> {
        let mut all = 0;
        let mut any = !0;
        for v in &poly {
            let c = self.outcode(v);
            all |= c;
            any &= c;
        }
        if any != 0 {
            return Vec::new();
        }
        if all == 0 {
            return poly;
        }
        let mut poly = poly;
        for p in 0..self.count() {
            if all & (1 << p) == 0 {
                continue;
            }
            let n = poly.len();
            if n < 3 {
                return Vec::new();
            }
            let dist: Vec<f32> = poly.iter().map(|v| self.distance(p, v)).collect();
            let mut out = Vec::with_capacity(n + 1);
            for i in 0..n {
                let j = (i + 1) % n;
                let (cur, next) = (&poly[i], &poly[j]);
                let (dc, dn) = (dist[i], dist[j]);
                let (ci, ni) = (inside(dc), inside(dn));
                if ci {
                    out.push(cur.clone());
                }
                if ci != ni {
                    // From the inside vertex towards the outside one.
                    let v = if ci {
                        self.lerp(cur, next, self.cut(p, cur, next))
                    } else {
                        self.lerp(next, cur, self.cut(p, next, cur))
                    };
                    out.push(on_plane(p, v));
                }
            }
            poly = out;
        }
        if poly.len() < 3 {
            Vec::new()
        } else {
            poly
        }
    }
}

fn inside(d: f32) -> bool {
    d >= 0.0
}

/// `a + t (b - a)` in `f64`, rounded once.
fn lerp4(a: &[f32; 4], b: &[f32; 4], t: f64) -> [f32; 4] {
    std::array::from_fn(|i| {
        let (x, y) = (f64::from(a[i]), f64::from(b[i]));
        (x + t * (y - x)) as f32
    })
}

impl Planes {
    /// `a + t (b - a)` for every carried value: positions in `f64`, the
    /// vertex shader's outputs in `f32`; the `noperspective` ones at the
    /// parameter `s = t w_b / (w_a + t (w_b - w_a))` where the new
    /// vertex lies between the two in window space (`t` itself when that
    /// is not a number in [0, 1], as for a vertex at w = 0).
    fn lerp(&self, a: &ClipVertex, b: &ClipVertex, t: f64) -> ClipVertex {
        let tf = t as f32;
        let mut data: Vec<f32> = a
            .data
            .iter()
            .zip(&b.data)
            .map(|(&x, &y)| x + tf * (y - x))
            .collect();
        if !self.noperspective.is_empty() {
            let (wa, wb) = (f64::from(a.pos[3]), f64::from(b.pos[3]));
            let s = t * wb / (wa + t * (wb - wa));
            let sf = if (0.0..=1.0).contains(&s) {
                s as f32
            } else {
                tf
            };
            for &c in &self.noperspective {
                if let (Some(d), Some(&x), Some(&y)) =
                    (data.get_mut(c), a.data.get(c), b.data.get(c))
                {
                    *d = x + sf * (y - x);
                }
            }
        }
        ClipVertex {
            pos: lerp4(&a.pos, &b.pos, t),
            eye: lerp4(&a.eye, &b.eye, t),
            data,
        }
    }
}

/// `v`, made on plane `p`, put exactly on it when `p` is a view-volume
/// plane (its coordinate `±w`).
fn on_plane(p: usize, mut v: ClipVertex) -> ClipVertex {
    let w = v.pos[3];
    match p {
        0 => v.pos[0] = -w,
        1 => v.pos[0] = w,
        2 => v.pos[1] = -w,
        3 => v.pos[1] = w,
        4 => v.pos[2] = -w,
        5 => v.pos[2] = w,
        _ => {}
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(pos: [f32; 4], value: f32) -> ClipVertex {
        ClipVertex {
            pos,
            eye: pos,
            data: vec![value],
        }
    }

    #[test]
    fn triangle_crossing_the_near_plane() {
        let planes = Planes::new(&[None; 8], None, Vec::new());
        // One vertex behind the near plane (z < -w).
        let tri = vec![
            v([0.0, 0.0, -3.0, 1.0], 0.0),
            v([0.5, 0.0, 0.0, 1.0], 1.0),
            v([0.0, 0.5, 0.0, 1.0], 1.0),
        ];
        let out = planes.clip_polygon(tri);
        assert_eq!(out.len(), 4);
        for c in &out {
            assert!(c.pos[2] >= -c.pos[3], "{:?}", c.pos);
        }
        // The new vertices sit on z = -w, a third of the way from the
        // inside vertex; the carried value follows.
        let cut: Vec<_> = out.iter().filter(|c| c.pos[2] == -1.0).collect();
        assert_eq!(cut.len(), 2);
        for c in cut {
            assert!((c.data[0] - 2.0 / 3.0).abs() < 1e-6);
        }
    }

    #[test]
    fn fully_outside_and_inside() {
        let planes = Planes::new(&[None; 8], None, Vec::new());
        let outside = vec![
            v([2.0, 0.0, 0.0, 1.0], 0.0),
            v([3.0, 0.0, 0.0, 1.0], 0.0),
            v([2.0, 1.0, 0.0, 1.0], 0.0),
        ];
        assert!(planes.clip_polygon(outside).is_empty());
        let inside = vec![
            v([0.0, 0.0, 0.0, 1.0], 0.0),
            v([0.5, 0.0, 0.0, 1.0], 0.0),
            v([0.0, 0.5, 0.0, 1.0], 0.0),
        ];
        assert_eq!(planes.clip_polygon(inside.clone()), inside);
    }

    #[test]
    fn user_plane_uses_eye_coordinates() {
        let mut user = [None; 8];
        user[3] = Some([1.0, 0.0, 0.0, 0.0]); // keep x_eye >= 0
        let planes = Planes::new(&user, None, Vec::new());
        let mut a = v([0.0, 0.0, 0.0, 1.0], 0.0);
        a.eye = [-1.0, 0.0, 0.0, 1.0];
        let mut b = v([0.0, 0.0, 0.0, 1.0], 1.0);
        b.eye = [3.0, 0.0, 0.0, 1.0];
        let (na, nb) = planes.clip_line(&a, &b).unwrap();
        assert_eq!(na.eye[0], 0.0);
        assert_eq!(na.data[0], 0.25);
        assert_eq!(nb, b);
        assert!(!planes.point_inside(&a));
        assert!(planes.point_inside(&b));
    }

    #[test]
    fn clip_distances_replace_the_plane_equations() {
        // Planes 1 and 4 enabled; the vertex data holds gl_ClipDistance[0..2]
        // at components 1 and 2, so plane 1 reads component 2 and plane 4
        // (beyond the array) does not clip.
        let mut user = [None; 8];
        user[1] = Some([0.0, 0.0, 0.0, -1.0]);
        user[4] = Some([0.0, 0.0, 0.0, -1.0]);
        let planes = Planes::new(&user, Some((1, 2)), Vec::new());
        let mut a = v([0.0, 0.0, 0.0, 1.0], 0.0);
        a.data.extend([5.0, -1.0]);
        let mut b = v([0.5, 0.0, 0.0, 1.0], 1.0);
        b.data.extend([5.0, 3.0]);
        assert!(!planes.point_inside(&a));
        assert!(planes.point_inside(&b));
        let (na, nb) = planes.clip_line(&a, &b).unwrap();
        // Cut where the distance, interpolated linearly, is 0.
        assert_eq!(na.pos[0], 0.125);
        assert_eq!(na.data, vec![0.25, 5.0, 0.0]);
        assert_eq!(nb, b);
        // The plane equations (every vertex outside) are not used.
        let equations = Planes::new(&user, None, Vec::new());
        assert!(!equations.point_inside(&b));
    }

    #[test]
    fn noperspective_values_are_cut_linearly_in_window_space() {
        // x = -w/2 cuts the segment from (-w, w = 1) to (w, w = 3) at
        // t = 1/10 in clip space: window x -1 to 1, cut at window x -0.5,
        // a quarter of the way in window space.
        let mut user = [None; 8];
        user[0] = Some([1.0, 0.0, 0.0, 0.5]);
        let planes = Planes::new(&user, None, vec![1]);
        let mut a = v([-1.0, 0.0, 0.0, 1.0], 0.0);
        a.data.push(0.0);
        let mut b = v([3.0, 0.0, 0.0, 3.0], 1.0);
        b.data.push(1.0);
        let (na, _) = planes.clip_line(&a, &b).unwrap();
        assert_eq!(na.pos[0] / na.pos[3], -0.5);
        assert_eq!(na.data, vec![0.1, 0.25]);
    }

    #[test]
    fn shared_edge_cut_identically() {
        let planes = Planes::new(&[None; 8], None, Vec::new());
        let p = [
            v([-2.0, -0.5, 0.0, 1.0], 0.0),
            v([0.5, 0.7, 0.1, 1.0], 1.0),
            v([0.3, -0.9, 0.2, 1.0], 2.0),
            v([-3.0, 0.9, 0.3, 1.0], 3.0),
        ];
        // Triangles (0,1,2) and (1,0,3) share edge 0-1 in opposite directions.
        let t1 = planes.clip_polygon(vec![p[0].clone(), p[1].clone(), p[2].clone()]);
        let t2 = planes.clip_polygon(vec![p[1].clone(), p[0].clone(), p[3].clone()]);
        // The cut of edge 0-1 carries 0.4; t1's other cut on x = -w (edge
        // 2-0) carries about 0.87.
        let on_edge = |t: &[ClipVertex]| -> Vec<[f32; 4]> {
            t.iter()
                .filter(|c| c.pos[0] == -1.0 && c.data[0] < 0.5)
                .map(|c| c.pos)
                .collect()
        };
        let (e1, e2) = (on_edge(&t1), on_edge(&t2));
        assert_eq!(e1.len(), 1);
        assert_eq!(e1, e2);
    }

    #[test]
    fn nan_is_outside() {
        let planes = Planes::new(&[None; 8], None, Vec::new());
        assert!(!planes.point_inside(&v([f32::NAN, 0.0, 0.0, 1.0], 0.0)));
    }

    #[test]
    fn huge_polygon_cut_on_the_view_planes() {
        // A quad reaching 10⁶ in every direction: every new vertex lies on
        // the view volume's boundary exactly, so the clipped quad is the
        // whole view square.
        let planes = Planes::new(&[None; 8], None, Vec::new());
        let big = 1.0e6;
        let quad = vec![
            v([-big, -big, 0.0, 1.0], 0.0),
            v([big, -big, 0.0, 1.0], 1.0),
            v([big, big, 0.0, 1.0], 2.0),
            v([-big, big, 0.0, 1.0], 3.0),
        ];
        let out = planes.clip_polygon(quad);
        let mut corners: Vec<[f32; 2]> = out.iter().map(|c| [c.pos[0], c.pos[1]]).collect();
        corners.sort_by(|a, b| a.partial_cmp(b).unwrap());
        corners.dedup();
        assert_eq!(
            corners,
            vec![[-1.0, -1.0], [-1.0, 1.0], [1.0, -1.0], [1.0, 1.0]]
        );
    }

    #[test]
    fn huge_line_cut_on_the_view_planes() {
        let planes = Planes::new(&[None; 8], None, Vec::new());
        let a = v([-3.0e6, 0.25, 0.0, 1.0], 0.0);
        let b = v([5.0e6, 0.25, 0.0, 1.0], 1.0);
        let (na, nb) = planes.clip_line(&a, &b).unwrap();
        assert_eq!((na.pos[0], nb.pos[0]), (-1.0, 1.0));
        assert_eq!((na.pos[1], nb.pos[1]), (0.25, 0.25));
    }
}
