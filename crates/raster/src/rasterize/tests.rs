use super::*;
use crate::interpolate::{offsets, Bases, PrimPlanes};

fn wv(x: f64, y: f64) -> WinVertex {
    WinVertex {
        x,
        y,
        z: 0.5,
        inv_w: 1.0,
    }
}

fn coverage(shapes: &[Shape], size: i64) -> Vec<u32> {
    let mut hits = vec![0u32; (size * size) as usize];
    for s in shapes {
        for (qx, qy, mask) in s.quads((0, 0, size, size)) {
            for bit in 0..4 {
                if mask & (1 << bit) != 0 {
                    let (x, y) = (qx + (bit & 1), qy + (bit >> 1));
                    hits[(y * size + x) as usize] += 1;
                }
            }
        }
    }
    hits
}

/// The walk visits the quads `quads_into` lists, with their masks.
#[test]
fn quads_each_visits_the_listed_quads() {
    let triangles = random_triangles(0x5DEE_CE66_D1CE_4E5B, 3000);
    let mut seen = 0;
    for (v, t, qx, qy) in triangles {
        let clip = (qx - 6, qy - 6, qx + 10, qy + 8);
        let mut quads = Vec::new();
        let mut got = Vec::new();
        t.quads_each(t.area(clip), &mut quads, |x, y, m| got.push((x, y, m)));
        assert_eq!(got, t.quads(clip), "{v:?}");
        seen += got.len();
    }
    assert!(seen > 1000, "{seen} quads");
}

/// Strip entries stand for four whole quads side by side: expanded,
/// the list is `quads_into`'s; big triangles have them.
#[test]
fn strip_entries_expand_to_the_quads() {
    let mut strips = 0;
    for (v, t, qx, qy) in random_triangles(0x0DDB_1A5E_5BAD_5EED, 2000) {
        let clip = (qx - 40, qy - 30, qx + 64, qy + 64);
        let mut list = Vec::new();
        t.quads_into_strips(t.area(clip), &mut list, true);
        let mut expanded = Vec::new();
        for &(x, y, m) in &list {
            if m & STRIP != 0 {
                assert_eq!(m, STRIP | 0xf);
                strips += 1;
                expanded.extend((0..4).map(|k| (x + 2 * k, y, 0xf)));
            } else {
                expanded.push((x, y, m));
            }
        }
        assert_eq!(expanded, t.quads(clip), "{v:?}");
    }
    assert!(strips > 5000, "{strips} strips");
}

/// Narrow areas evaluated four quads at a time cover what the
/// quad-by-quad walk covers; areas whose values would not fit in i32
/// (huge triangles, far coordinates) are declined.
#[test]
fn narrow_areas_cover_as_the_walk_does() {
    let (mut ran, mut declined) = (0, 0);
    for (i, (v, t, _, _)) in random_triangles(0x7F4A_7C15_9E37_79B9, 8000)
        .into_iter()
        .enumerate()
    {
        let Shape::Triangle { p, sign, .. } = t else {
            unreachable!()
        };
        let i = i as i64;
        // Widths 1 to 18 pixels from odd and even columns, 1 to 23
        // tall, near a vertex.
        let corner = v[i as usize % 3];
        let (x, y) = (corner.x as i64 - 6 + i % 3, corner.y as i64 - 5 + i % 2);
        let clip = (x, y, x + 1 + i % 18, y + 1 + i % 23);
        let area = t.area(clip);
        if area.0 >= area.2 || area.1 >= area.3 {
            continue;
        }
        let [a, b, c, threshold] = triangle_edges(&p, sign);
        let edges = (&a, &b, &c, &threshold);
        let mut narrow = Vec::new();
        let took = narrow_quads_each(edges, area, &mut |x, y, m, w: &WalkQuad| {
            assert_eq!(w.whole_strips(), 0);
            narrow.push((x, y, m));
            0
        });
        let mut wide = Vec::new();
        wide_quads_each(edges, area, |x, y, m, _| {
            if m != 0 {
                wide.push((x, y, m));
            }
            0
        });
        if took {
            assert_eq!(narrow, wide, "{v:?} in {area:?}");
            assert!(narrow.iter().all(|q| q.2 != 0));
            ran += 1;
        } else {
            assert!(narrow.is_empty());
            declined += usize::from(area.2 - (area.0 & !1) <= NARROW);
        }
    }
    assert!(
        ran > 2000 && declined > 1000,
        "{ran} ran, {declined} declined"
    );
}

#[test]
fn quad4_keeps_values_and_sign_bits() {
    let values = [i64::MIN, -(1 << 40), -2, -1, 0, 1, 2, 1 << 40, i64::MAX];
    for a in values {
        for b in values {
            let x = [a, b, b / 3, a / 5];
            let q = Quad4::new(x);
            let want = (0..4).fold(0u8, |m, i| m | (u8::from(x[i] < 0) << i));
            assert_eq!(q.negative(), want, "{x:?}");
            assert_eq!(q.to_array(), x);
            let sum = q.add(Quad4::splat(7)).to_array();
            assert_eq!(sum, x.map(|v| v.wrapping_add(7)));
        }
    }
}

#[test]
fn shared_edges_cover_each_pixel_once() {
    // A square split along its diagonal, with edges through pixel centers.
    let a = wv(0.5, 0.5);
    let b = wv(6.5, 0.5);
    let c = wv(6.5, 6.5);
    let d = wv(0.5, 6.5);
    for (t1, t2) in [([a, b, c], [a, c, d]), ([c, b, a], [d, c, a])] {
        let shapes = [Shape::triangle(t1).unwrap(), Shape::triangle(t2).unwrap()];
        let hits = coverage(&shapes, 8);
        for y in 0..8 {
            for x in 0..8 {
                // Left and bottom edges are owned, right and top not.
                let want = u32::from((0..6).contains(&x) && (0..6).contains(&y));
                assert_eq!(hits[(y * 8 + x) as usize], want, "pixel {x},{y}");
            }
        }
    }
    // A fan of odd slopes around a shared center: still no double hits
    // and no holes inside.
    let center = wv(5.3, 4.7);
    let ring = [
        wv(0.1, 0.2),
        wv(9.7, 0.9),
        wv(9.9, 8.8),
        wv(4.4, 9.6),
        wv(0.3, 7.1),
    ];
    let shapes: Vec<Shape> = (0..5)
        .filter_map(|i| Shape::triangle([center, ring[i], ring[(i + 1) % 5]]))
        .collect();
    let hits = coverage(&shapes, 10);
    assert!(hits.iter().all(|&h| h <= 1));
    assert_eq!(hits[4 * 10 + 5], 1);
}

/// The coverage rule pixel by pixel, as [`edge`] and [`owns_edge`]
/// state it.
fn reference_quads(s: &Shape, clip: PixelRect) -> Vec<(i64, i64, u8)> {
    let Shape::Triangle { p, sign, .. } = s else {
        unreachable!()
    };
    let r = intersect(s.bounds(), clip);
    let mut out = Vec::new();
    if r.0 >= r.2 || r.1 >= r.3 {
        return out;
    }
    let covered = |x: i64, y: i64| {
        let (cx, cy) = (x * ONE + HALF, y * ONE + HALF);
        (0..3).all(|k| {
            let e = sign * edge(p, k, cx, cy);
            e > 0 || (e == 0 && owns_edge(p, k, *sign))
        })
    };
    for_each_quad(r, |qx, qy| {
        let mut mask = 0u8;
        for bit in 0..4 {
            let (x, y) = (qx + (bit & 1), qy + (bit >> 1));
            if inside(r, x, y) && covered(x, y) {
                mask |= 1 << bit;
            }
        }
        if mask != 0 {
            out.push((qx, qy, mask));
        }
    });
    out
}

#[test]
fn triangle_quads_match_the_per_pixel_rule() {
    let mut next = unit_floats(0x9E37_79B9_7F4A_7C15);
    let mut coord = |range: f64| next() * range - 8.0;
    let mut checked = 0;
    for i in 0..4000 {
        // Sizes from sub-pixel to larger than a tile; snapped to pixel
        // centers now and then so edges pass through centers.
        let range = [3.0, 12.0, 40.0, 150.0][i % 4];
        let mut v = [0; 3].map(|_| wv(coord(range), coord(range)));
        if i % 5 == 0 {
            for w in &mut v {
                w.x = w.x.floor() + 0.5;
                w.y = w.y.floor() + 0.5;
            }
        }
        let Some(t) = Shape::triangle(v) else {
            continue;
        };
        for clip in [
            (0, 0, 64, 64),
            (-8, -8, 200, 200),
            (3, 5, 17, 10),
            (-3, 1, 64, 63),
        ] {
            assert_eq!(
                t.quads(clip),
                reference_quads(&t, clip),
                "{v:?} in {clip:?}"
            );
            checked += 1;
        }
    }
    assert!(checked > 10_000);
}

/// `to_fixed` rounds as `f64::round` does, at halves, at the limits
/// and for values that are not numbers.
#[test]
fn fixed_point_rounds_half_away_from_zero() {
    let reference = |c: f64| {
        let f = (c * ONE as f64).round();
        if f.is_nan() {
            0
        } else {
            (f as i64).clamp(-FIXED_LIMIT, FIXED_LIMIT)
        }
    };
    let mut values = vec![
        0.0,
        -0.0,
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::MAX,
        f64::MIN,
        f64::MIN_POSITIVE,
        1e300,
        -1e300,
        9.2e18,
        -9.2e18,
        (1u64 << 53) as f64,
        ((1u64 << 53) + 2) as f64 / ONE as f64,
    ];
    for k in -2000..2000 {
        // Halves, and the doubles either side of them.
        let h = (k as f64 + 0.5) / ONE as f64;
        values.extend([h, h.next_up(), h.next_down(), k as f64 / ONE as f64]);
    }
    let mut x = 0x9e37_79b9_7f4a_7c15u64;
    for _ in 0..200_000 {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        values.push(f64::from_bits(x));
        values.push((x >> 11) as f64 / (1u64 << 40) as f64 - 4096.0);
    }
    for c in values {
        assert_eq!(to_fixed(c), reference(c), "{c:e}");
    }
}

#[test]
fn bottom_left_rule() {
    // Right triangle with a bottom horizontal edge and a left vertical
    // edge through pixel centers: both are owned (llvmpipe's rule for
    // GL's lower-left origin)...
    let t = Shape::triangle([wv(0.5, 0.5), wv(4.5, 0.5), wv(0.5, 4.5)]).unwrap();
    let hits = coverage(&[t], 6);
    assert_eq!(hits[0], 1, "bottom edge included");
    assert_eq!(hits[6], 1, "left edge included");
    // ...and a top and a right edge through pixel centers are not.
    let t = Shape::triangle([wv(5.5, 5.5), wv(1.5, 5.5), wv(5.5, 1.5)]).unwrap();
    let hits = coverage(&[t], 6);
    assert_eq!(hits[5 * 6 + 4], 0, "top edge excluded");
    assert_eq!(hits[4 * 6 + 5], 0, "right edge excluded");
    assert_eq!(hits[4 * 6 + 4], 1, "inside");
}

/// The planes of a primitive (vertices `win`) at pixel (x, y):
/// (window z, 1/w, the varying with vertex values `a`).
fn planes_at((s, win): (&Shape, &[WinVertex]), a: [f32; 3], (x, y): (i64, i64)) -> (f64, f32, f32) {
    let bases = Bases::General(s.basis());
    let (z, inv_w) = vertex_depths(win);
    let (z, inv_w) = (z.map(|z| z as f32), inv_w.map(|w| w as f32));
    let p = PrimPlanes::new(&bases, z, inv_w, None);
    let v = p.varying(&bases, a, inv_w);
    let (fx, fy) = offsets((x, y), &[0.0], &[0.0], None);
    let rw = p.reciprocal_w(&fx, &fy);
    (
        p.z_at(&fx, &fy)[0],
        p.inv_w_at(&fx, &fy)[0],
        v.values(&fx, &fy, &rw)[0],
    )
}

/// GL 2.1 eq. 3.9 in f64 from a pixel's barycentrics `b`.
fn exact(b: [f64; 3], v: &[WinVertex; 3], a: [f32; 3]) -> (f64, f64, f64) {
    let z = (0..3).map(|j| b[j] * v[j].z).sum::<f64>();
    let inv_w = (0..3).map(|j| b[j] * v[j].inv_w).sum::<f64>();
    let num = (0..3).map(|j| b[j] * v[j].inv_w * a[j] as f64).sum::<f64>();
    (z, inv_w, num / inv_w)
}

#[test]
fn perspective_correct_interpolation() {
    // Vertex 0 with w = 1, vertex 1 and 2 with w = 4: halfway in screen
    // space, the weight of vertex 0 is 4 times larger than linear.
    let v = |x, y, z, inv_w| WinVertex { x, y, z, inv_w };
    let vs = [
        v(0.0, 0.0, 0.0, 1.0),
        v(16.0, 0.0, 1.0, 0.25),
        v(0.0, 16.0, 1.0, 0.25),
    ];
    let t = Shape::triangle(vs).unwrap();
    // Pixel (7, 0) center is (7.5, 0.5): b = (1 - 8/16, 7.5/16, 0.5/16).
    let b = [0.5, 7.5 / 16.0, 0.5 / 16.0];
    let a = [1.0, 0.0, 0.0];
    let (z, inv_w, f) = planes_at((&t, &vs), a, (7, 0));
    let (ez, ew, ef) = exact(b, &vs, a);
    assert!((z - 0.5).abs() < 1e-12, "z is linear in window space: {z}");
    assert!((z - ez).abs() < 1e-12);
    assert!((inv_w as f64 - ew).abs() < 1e-6, "{inv_w} {ew}");
    assert!((f as f64 - ef).abs() < 1e-6, "{f} {ef}");
    assert!((ef - 0.5 / ew).abs() < 1e-12);
    // A line's and a point's.
    let l = Shape::line([vs[0], vs[1]], 1.0);
    let (z, inv_w, f) = planes_at((&l, &vs[..2]), [2.0, 4.0, 0.0], (7, 0));
    let tt = 7.5 / 16.0;
    let ew = (1.0 - tt) + tt * 0.25;
    assert!((z - tt).abs() < 1e-12);
    assert!((inv_w as f64 - ew).abs() < 1e-6);
    let ef = ((1.0 - tt) * 2.0 + tt * 0.25 * 4.0) / ew;
    assert!((f as f64 - ef).abs() < 1e-5, "{f} {ef}");
    let p = Shape::point(vs[1], 3.0, false);
    assert_eq!(
        planes_at((&p, &vs[1..2]), [0.3, 9.0, 9.0], (16, 1)),
        (1.0, 0.25, 0.3)
    );
}

/// Random triangles, perspective and not: the planes agree with
/// eq. 3.9 in f64 to f32's precision of the plane's terms.
#[test]
fn planes_agree_with_exact_barycentrics() {
    let triangles = random_triangles(0x2545_F491_4F6C_DD1D, 3000);
    assert!(triangles.len() > 2500);
    let mut worst = 0.0f64;
    for (i, (mut v, _, qx, qy)) in triangles.into_iter().enumerate() {
        if i % 2 == 0 {
            for w in &mut v {
                w.inv_w = 0.5;
            }
        }
        let Some(t) = Shape::triangle(v) else {
            continue;
        };
        let Shape::Triangle { p, .. } = &t else {
            unreachable!()
        };
        let p = *p;
        // Barycentrics of the snapped vertices at the pixel center.
        let (cx, cy) = (qx as f64 + 0.5, qy as f64 + 0.5);
        let f = |k: usize| (p[k].0 as f64 / 256.0, p[k].1 as f64 / 256.0);
        let (x0, y0) = f(0);
        let (x1, y1) = f(1);
        let (x2, y2) = f(2);
        let det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
        let b1 = ((cx - x0) * (y2 - y0) - (x2 - x0) * (cy - y0)) / det;
        let b2 = ((x1 - x0) * (cy - y0) - (cx - x0) * (y1 - y0)) / det;
        let b = [1.0 - b1 - b2, b1, b2];
        let a = [0.25f32, -3.0, 7.5];
        let (z, inv_w, val) = planes_at((&t, &v), a, (qx, qy));
        let (ez, ew, ef) = exact(b, &v, a);
        // The scale of the plane's terms: its value and its steps
        // times the distance from its origin, pixel (0, 0).
        let dist = (qx.abs() + qy.abs() + 1) as f64;
        let scale = |vals: [f64; 3]| {
            let m = vals.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            m * (1.0 + dist * b.iter().map(|x| x.abs()).fold(0.0, f64::max))
        };
        let zs = scale([v[0].z, v[1].z, v[2].z]);
        assert!((z - ez).abs() <= 1e-5 * zs.max(1.0), "{v:?} z {z} {ez}");
        let ws = scale(v.map(|w| w.inv_w));
        let rel_w = (inv_w as f64 - ew).abs() / ws;
        assert!(rel_w < 1e-5, "{v:?} 1/w {inv_w} {ew}");
        if ew.abs() > 1e-3 * ws {
            let fs = scale(std::array::from_fn(|j| a[j] as f64 * v[j].inv_w)) / ew.abs();
            let rel = (val as f64 - ef).abs() / fs.max(1.0);
            worst = worst.max(rel);
            assert!(rel < 1e-4, "{v:?} at {qx},{qy}: {val} vs {ef}");
        }
    }
    assert!(worst > 0.0);
}

/// Pseudo-random floats in [0, 1) from `seed` (an xorshift generator:
/// fixed seed, no dependency), in steps of 10^-6.
fn unit_floats(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % 1_000_000) as f64 / 1_000_000.0
    }
}

/// `count` random triangles (a few pixels to thousands across, varied
/// z and 1/w; those without area left out), each with a quad position
/// within its range: (vertices, triangle, qx, qy).
fn random_triangles(seed: u64, count: usize) -> Vec<([WinVertex; 3], Shape, i64, i64)> {
    let mut next = unit_floats(seed);
    let mut out = Vec::new();
    for i in 0..count {
        // Tiny to huge (past 2^16 pixels the strip weights take the
        // integer path, past 2^20 the coordinates are clamped).
        let range = [4.0, 60.0, 3000.0, 70_000.0, 3.0e6][i % 5];
        let v = [0; 3].map(|_| WinVertex {
            x: next() * range - 5.0,
            y: next() * range - 5.0,
            z: next(),
            inv_w: 0.01 + next() * 2.0,
        });
        let Some(t) = Shape::triangle(v) else {
            continue;
        };
        let (qx, qy) = ((next() * range) as i64 & !1, (next() * range) as i64 & !1);
        out.push((v, t, qx, qy));
    }
    out
}

#[test]
fn line_pixels_half_open() {
    let l = Shape::line([wv(0.5, 0.3), wv(4.5, 1.3)], 1.0);
    let q = l.quads((0, 0, 8, 8));
    let mut px = Vec::new();
    for (qx, qy, m) in q {
        for bit in 0..4 {
            if m & (1 << bit) != 0 {
                px.push((qx + (bit & 1), qy + (bit >> 1)));
            }
        }
    }
    px.sort();
    assert_eq!(px, vec![(0, 0), (1, 0), (2, 0), (3, 1)]);
    // Vertical line.
    let l = Shape::line([wv(2.5, 0.0), wv(2.5, 3.0)], 1.0);
    assert_eq!(l.quads((0, 0, 8, 8)), vec![(2, 0, 0b0101), (2, 2, 0b0001)]);
}

#[test]
fn point_squares() {
    let p = Shape::point(wv(3.7, 3.2), 1.0, false);
    assert_eq!(p.bounds(), (3, 3, 4, 4));
    let p = Shape::point(wv(3.7, 3.2), 2.0, false);
    assert_eq!(p.bounds(), (3, 2, 5, 4));
    let p = Shape::point(wv(3.7, 3.2), 3.0, false);
    assert_eq!(p.bounds(), (2, 2, 5, 5));
    let p = Shape::point(wv(4.0, 4.0), 2.0, true);
    assert_eq!(p.bounds(), (3, 3, 5, 5));
    assert_eq!(p.point_coord(3, 4, false), (0.25, 0.25));
    assert_eq!(p.point_coord(3, 4, true), (0.25, 0.75));
}

/// The quads of `shapes` inside `clip`, masks of one quad position
/// joined, each pixel covered by one shape at most (asserted).
fn union_quads(shapes: &[Shape], clip: PixelRect) -> Vec<(i64, i64, u8)> {
    let mut all: Vec<(i64, i64, u8)> = shapes.iter().flat_map(|s| s.quads(clip)).collect();
    all.sort_by_key(|&(x, y, _)| (y, x));
    let mut out: Vec<(i64, i64, u8)> = Vec::new();
    for (x, y, m) in all {
        match out.last_mut() {
            Some(last) if (last.0, last.1) == (x, y) => {
                assert_eq!(last.2 & m, 0, "a pixel of ({x}, {y}) covered twice");
                last.2 |= m;
            }
            _ => out.push((x, y, m)),
        }
    }
    out
}

/// `count` random quadrilaterals in fixed point: convex ones (corners at
/// increasing angles around a centre), billboards (axis-aligned
/// squares), parallelograms and a few that are not convex, from under
/// a pixel to a few hundred across; every third snapped to pixel
/// centres or half-pixel positions, so that corners and edges pass
/// through pixel centres.
fn random_quadrilaterals(seed: u64, count: usize) -> Vec<[(i64, i64); 4]> {
    let mut next = unit_floats(seed);
    let mut out = Vec::new();
    for i in 0..count {
        let size = [1.5, 6.0, 20.0, 90.0, 300.0][i % 5] * (0.5 + next());
        let (cx, cy) = (next() * 80.0 - 10.0, next() * 80.0 - 10.0);
        let v: [(f64, f64); 4] = match i % 4 {
            0 => {
                let h = size / 2.0;
                [(-h, -h), (h, -h), (h, h), (-h, h)].map(|(x, y)| (cx + x, cy + y))
            }
            1 => {
                let (ax, ay) = (size * (next() - 0.5), size * (next() - 0.5));
                let (bx, by) = (size * (next() - 0.5), size * (next() - 0.5));
                [(0.0, 0.0), (ax, ay), (ax + bx, ay + by), (bx, by)].map(|(x, y)| (cx + x, cy + y))
            }
            2 => {
                let mut angles = [0; 4].map(|_| next() * std::f64::consts::TAU);
                angles.sort_by(f64::total_cmp);
                angles.map(|a| {
                    let r = size * (0.3 + 0.7 * next());
                    (cx + r * a.cos(), cy + r * a.sin())
                })
            }
            _ => [0; 4].map(|_| (cx + size * next(), cy + size * next())),
        };
        let v = match i % 3 {
            0 => v.map(|(x, y)| (x.floor() + 0.5, y.floor() + 0.5)),
            1 => v.map(|(x, y)| ((2.0 * x).round() / 2.0, (2.0 * y).round() / 2.0)),
            _ => v,
        };
        out.push(v.map(|(x, y)| snap(&wv(x, y))));
    }
    out
}

/// A quadrilateral taken as one shape covers exactly the pixels of its
/// fan's two triangles, through every way of walking it, corners on
/// pixel centres included; those it declines are not strictly convex.
#[test]
fn quadrilaterals_cover_their_two_triangles() {
    let (mut taken, mut strips, mut on_centre) = (0, 0, 0);
    for p in random_quadrilaterals(0x2545_F491_4F6C_DD1D, 6000) {
        let fan = [[p[0], p[1], p[2]], [p[0], p[2], p[3]]];
        let Some(q) = Shape::quadrilateral_snapped(p) else {
            let turns = (0..4).map(|k| {
                let c = p[(k + 2) % 4];
                edge_at((p[k], p[(k + 1) % 4]), c.0, c.1).signum()
            });
            assert!(
                turns.clone().any(|t| t == 0)
                    || turns.collect::<Vec<_>>().windows(2).any(|w| w[0] != w[1]),
                "{p:?} declined"
            );
            continue;
        };
        let triangles: Vec<Shape> = fan
            .iter()
            .filter_map(|&t| Shape::triangle_snapped(t))
            .collect();
        assert_eq!(triangles.len(), 2, "{p:?}");
        taken += 1;
        on_centre += usize::from(
            p.iter()
                .any(|&(x, y)| x.rem_euclid(ONE) == HALF && y.rem_euclid(ONE) == HALF),
        );
        for clip in [
            (-20, -20, 400, 400),
            (0, 0, 64, 64),
            (3, 5, 17, 10),
            (-3, 1, 40, 63),
        ] {
            let want = union_quads(&triangles, clip);
            assert_eq!(q.quads(clip), want, "{p:?} in {clip:?}");
            let area = q.area(clip);
            let mut scratch = Vec::new();
            let mut walked = Vec::new();
            q.quads_each(area, &mut scratch, |x, y, m| walked.push((x, y, m)));
            assert_eq!(walked, want, "{p:?} walked in {clip:?}");
            let mut list = Vec::new();
            q.quads_into_strips(area, &mut list, true);
            let mut expanded = Vec::new();
            for &(x, y, m) in &list {
                if m & STRIP != 0 {
                    strips += 1;
                    expanded.extend((0..4).map(|k| (x + 2 * k, y, 0xf)));
                } else {
                    expanded.push((x, y, m));
                }
            }
            assert_eq!(expanded, want, "{p:?} in strips in {clip:?}");
        }
        // The planes are the first triangle's.
        assert_eq!(q.basis(), triangles[0].basis());
        assert_eq!(q.bounds(), corner_bounds(&p));
    }
    assert!(taken > 2500, "{taken} taken");
    assert!(
        on_centre > 500,
        "{on_centre} with a corner on a pixel centre"
    );
    assert!(strips > 1000, "{strips} strips");
}
