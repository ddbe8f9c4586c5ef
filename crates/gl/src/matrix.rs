//! 4x4 matrices as GL stores them (column-major: element (row r, column c)
//! is `m[c * 4 + r]`) and the transformations of GL 2.1 §2.11.2.
//!
//! Products use plain `a * b + c` (never fused) in a fixed order, so every
//! machine computes the same bits: Mesa's order (each element summed from
//! its first product), and glRotate as Mesa builds it, so that the matrices
//! a program's shaders read are Mesa's bits too (a ray grazing a silhouette
//! through an interpolated eye-space point depends on their last bits).
//! Inverses are computed in `f64` from the cofactor expansion and rounded
//! once.

use glsl::math;

/// A column-major 4x4 matrix.
pub type Mat4 = [f32; 16];

pub const IDENTITY: Mat4 = [
    1.0, 0.0, 0.0, 0.0, //
    0.0, 1.0, 0.0, 0.0, //
    0.0, 0.0, 1.0, 0.0, //
    0.0, 0.0, 0.0, 1.0,
];

/// `a * b` (apply `b` first, then `a`): each element `a(r, 0)·b(0, c) +
/// a(r, 1)·b(1, c) + …` from the left.
pub fn mul(a: &Mat4, b: &Mat4) -> Mat4 {
    let mut out = [0.0f32; 16];
    for c in 0..4 {
        for r in 0..4 {
            let mut s = a[r] * b[c * 4];
            for k in 1..4 {
                s += a[k * 4 + r] * b[c * 4 + k];
            }
            out[c * 4 + r] = s;
        }
    }
    out
}

/// `m * v`.
pub fn mul_vec(m: &Mat4, v: [f32; 4]) -> [f32; 4] {
    let mut out = [0.0f32; 4];
    for (r, o) in out.iter_mut().enumerate() {
        let mut s = 0.0f32;
        for (k, vk) in v.iter().enumerate() {
            s += m[k * 4 + r] * vk;
        }
        *o = s;
    }
    out
}

/// `v^T * m` (a row vector times the matrix), used for planes: a plane `p`
/// transformed by the inverse of `M` is `p * M^-1` (GL 2.1 §2.12).
pub fn vec_mul(v: [f32; 4], m: &Mat4) -> [f32; 4] {
    let mut out = [0.0f32; 4];
    for (c, o) in out.iter_mut().enumerate() {
        let mut s = 0.0f32;
        for (k, vk) in v.iter().enumerate() {
            s += vk * m[c * 4 + k];
        }
        *o = s;
    }
    out
}

pub fn transpose(m: &Mat4) -> Mat4 {
    let mut out = [0.0f32; 16];
    for c in 0..4 {
        for r in 0..4 {
            out[r * 4 + c] = m[c * 4 + r];
        }
    }
    out
}

/// The inverse, or `None` for a singular matrix.
pub fn inverse(m: &Mat4) -> Option<Mat4> {
    let a: Vec<f64> = m.iter().map(|&x| x as f64).collect();
    let at = |r: usize, c: usize| a[c * 4 + r];
    // Cofactor C(r, c) = (-1)^(r+c) * det(minor without row r, column c).
    let minor = |r: usize, c: usize| {
        let rows: Vec<usize> = (0..4).filter(|&i| i != r).collect();
        let cols: Vec<usize> = (0..4).filter(|&i| i != c).collect();
        let e = |i: usize, j: usize| at(rows[i], cols[j]);
        e(0, 0) * (e(1, 1) * e(2, 2) - e(1, 2) * e(2, 1))
            - e(0, 1) * (e(1, 0) * e(2, 2) - e(1, 2) * e(2, 0))
            + e(0, 2) * (e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0))
    };
    let mut cof = [[0.0f64; 4]; 4];
    for (r, row) in cof.iter_mut().enumerate() {
        for (c, x) in row.iter_mut().enumerate() {
            let sign = if (r + c) % 2 == 0 { 1.0 } else { -1.0 };
            *x = sign * minor(r, c);
        }
    }
    let det: f64 = (0..4).map(|c| at(0, c) * cof[0][c]).sum();
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    // inverse(r, c) = C(c, r) / det.
    let mut out = [0.0f32; 16];
    for r in 0..4 {
        for c in 0..4 {
            out[c * 4 + r] = (cof[c][r] / det) as f32;
        }
    }
    Some(out)
}

/// The inverse, or the identity for a singular matrix (what the built-in
/// uniforms report then; the GL leaves the value undefined).
pub fn inverse_or_identity(m: &Mat4) -> Mat4 {
    inverse(m).unwrap_or(IDENTITY)
}

/// The upper-left 3x3 of the inverse transpose (gl_NormalMatrix, GLSL 1.20
/// §7.5; GL 2.1 §2.11.3 transforms normals by the inverse of the upper
/// 3x3 of the model-view matrix), column-major.
pub fn normal_matrix(mv: &Mat4) -> [f32; 9] {
    let a: Vec<f64> = [0, 1, 2, 4, 5, 6, 8, 9, 10]
        .iter()
        .map(|&i| mv[i] as f64)
        .collect();
    let e = |r: usize, c: usize| a[c * 3 + r];
    let cof = |r: usize, c: usize| {
        let (r0, r1) = ((r + 1) % 3, (r + 2) % 3);
        let (c0, c1) = ((c + 1) % 3, (c + 2) % 3);
        e(r0, c0) * e(r1, c1) - e(r0, c1) * e(r1, c0)
    };
    let det = e(0, 0) * cof(0, 0) + e(0, 1) * cof(0, 1) + e(0, 2) * cof(0, 2);
    let mut out = [0.0f32; 9];
    if det == 0.0 || !det.is_finite() {
        out[0] = 1.0;
        out[4] = 1.0;
        out[8] = 1.0;
        return out;
    }
    // (M^-1)^T (r, c) = M^-1 (c, r) = C(r, c) / det.
    for r in 0..3 {
        for c in 0..3 {
            out[c * 3 + r] = (cof(r, c) / det) as f32;
        }
    }
    out
}

/// glOrtho (GL 2.1 §2.11.2).
pub fn ortho(l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> Mat4 {
    let mut m = IDENTITY;
    m[0] = (2.0 / (r - l)) as f32;
    m[5] = (2.0 / (t - b)) as f32;
    m[10] = (-2.0 / (f - n)) as f32;
    m[12] = (-(r + l) / (r - l)) as f32;
    m[13] = (-(t + b) / (t - b)) as f32;
    m[14] = (-(f + n) / (f - n)) as f32;
    m
}

/// glFrustum (GL 2.1 §2.11.2).
pub fn frustum(l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> Mat4 {
    let mut m = [0.0f32; 16];
    m[0] = (2.0 * n / (r - l)) as f32;
    m[5] = (2.0 * n / (t - b)) as f32;
    m[8] = ((r + l) / (r - l)) as f32;
    m[9] = ((t + b) / (t - b)) as f32;
    m[10] = (-(f + n) / (f - n)) as f32;
    m[11] = -1.0;
    m[14] = (-2.0 * f * n / (f - n)) as f32;
    m
}

pub fn translate(x: f32, y: f32, z: f32) -> Mat4 {
    let mut m = IDENTITY;
    m[12] = x;
    m[13] = y;
    m[14] = z;
    m
}

pub fn scale(x: f32, y: f32, z: f32) -> Mat4 {
    let mut m = IDENTITY;
    m[0] = x;
    m[5] = y;
    m[10] = z;
    m
}

/// glRotate: `angle` degrees counter-clockwise about the axis (x, y, z)
/// (GL 2.1 §2.11.2), rounded as Mesa computes it: θ in radians rounded to
/// f32, its sine and cosine rounded to f32; a rotation about a coordinate axis written exactly
/// (c and ±s, the axis' sign choosing the direction); any other axis
/// normalized in f32 (no rotation when its length is at most 10⁻⁴) and
/// each element `(1 − c)·u_r u_c ± u_k s`, or `+ c` on the diagonal.
pub fn rotate(angle: f32, x: f32, y: f32, z: f32) -> Mat4 {
    // θ rounded to f32, its sine and cosine rounded to f32 (computed in f64).
    let th = (angle as f64 * std::f64::consts::PI / 180.0) as f32 as f64;
    let (s, c) = (libm::sin(th) as f32, libm::cos(th) as f32);
    // Element (row, column).
    let at = |r: usize, col: usize| col * 4 + r;
    let mut m = IDENTITY;
    let axis = |v: f32, r: usize, col: usize, m: &mut Mat4| {
        let s = if v < 0.0 { -s } else { s };
        (m[at(r, r)], m[at(col, col)]) = (c, c);
        (m[at(r, col)], m[at(col, r)]) = (-s, s);
    };
    match (x == 0.0, y == 0.0, z == 0.0) {
        (true, true, false) => axis(z, 0, 1, &mut m),
        (true, false, true) => axis(y, 2, 0, &mut m),
        (false, true, true) => axis(x, 1, 2, &mut m),
        _ => {
            let mag = math::sqrt(x * x + y * y + z * z);
            if mag.is_nan() || mag <= 1.0e-4 {
                return IDENTITY;
            }
            let (x, y, z) = (x / mag, y / mag, z / mag);
            let (xx, yy, zz) = (x * x, y * y, z * z);
            let (xy, yz, zx) = (x * y, y * z, z * x);
            let (xs, ys, zs) = (x * s, y * s, z * s);
            let one_c = 1.0 - c;
            m[at(0, 0)] = (one_c * xx) + c;
            m[at(0, 1)] = (one_c * xy) - zs;
            m[at(0, 2)] = (one_c * zx) + ys;
            m[at(1, 0)] = (one_c * xy) + zs;
            m[at(1, 1)] = (one_c * yy) + c;
            m[at(1, 2)] = (one_c * yz) - xs;
            m[at(2, 0)] = (one_c * zx) - ys;
            m[at(2, 1)] = (one_c * yz) + xs;
            m[at(2, 2)] = (one_c * zz) + c;
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: &[f32], b: &[f32]) -> bool {
        a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-5)
    }

    #[test]
    fn ortho_maps_corners() {
        let m = ortho(0.0, 10.0, 0.0, 20.0, -1.0, 1.0);
        assert!(close(
            &mul_vec(&m, [10.0, 20.0, 0.0, 1.0]),
            &[1.0, 1.0, 0.0, 1.0]
        ));
        assert!(close(
            &mul_vec(&m, [0.0, 0.0, 1.0, 1.0]),
            &[-1.0, -1.0, -1.0, 1.0]
        ));
    }

    #[test]
    fn frustum_near_plane_maps_to_minus_one() {
        let m = frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
        let v = mul_vec(&m, [1.0, 1.0, -1.0, 1.0]);
        assert!(close(
            &[v[0] / v[3], v[1] / v[3], v[2] / v[3]],
            &[1.0, 1.0, -1.0]
        ));
        let v = mul_vec(&m, [0.0, 0.0, -10.0, 1.0]);
        assert!(close(&[v[2] / v[3]], &[1.0]));
    }

    #[test]
    fn rotate_z_90() {
        let m = rotate(90.0, 0.0, 0.0, 2.0);
        assert!(close(
            &mul_vec(&m, [1.0, 0.0, 0.0, 1.0]),
            &[0.0, 1.0, 0.0, 1.0]
        ));
    }

    #[test]
    fn inverse_roundtrip() {
        let m = mul(
            &translate(1.0, 2.0, 3.0),
            &mul(&rotate(30.0, 1.0, 1.0, 0.0), &scale(2.0, 3.0, 4.0)),
        );
        let i = inverse(&m).unwrap();
        assert!(close(&mul(&m, &i), &IDENTITY));
        assert!(inverse(&[0.0; 16]).is_none());
    }

    #[test]
    fn normal_matrix_of_scale() {
        let n = normal_matrix(&scale(2.0, 4.0, 0.5));
        assert!(close(&n, &[0.5, 0.0, 0.0, 0.0, 0.25, 0.0, 0.0, 0.0, 2.0]));
        // A rotation is its own inverse transpose.
        let r = rotate(40.0, 0.0, 1.0, 0.0);
        let n = normal_matrix(&r);
        assert!(close(
            &n,
            &[r[0], r[1], r[2], r[4], r[5], r[6], r[8], r[9], r[10]]
        ));
    }

    #[test]
    fn plane_transform() {
        // Plane z = 1 (0,0,1,-1) in object space under a translation by +2 in
        // z becomes z = 3 in eye space: p * M^-1.
        let m = translate(0.0, 0.0, 2.0);
        let p = vec_mul([0.0, 0.0, 1.0, -1.0], &inverse(&m).unwrap());
        assert!(close(&p, &[0.0, 0.0, 1.0, -3.0]));
    }
}
