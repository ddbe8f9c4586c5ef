//! `determinant` and `inverse` (GLSL 1.50 and 1.40 §8.5) written once over
//! an arithmetic ([`Arith`]), so that constant folding (on `f32`) and the
//! executor (emitting one op per operation) perform the same operations
//! in the same order and get the same bits.
//!
//! Matrices are column-major slices of `n * n` values (`m[col * n + row]`,
//! the layout of `ConstValue` and of the executor's registers), `n` 2 to 4.
//! The determinant is the cofactor expansion along the first column,
//! recursively; the inverse is the adjugate divided by the determinant
//! (a singular matrix gives infinities and NaNs, which GLSL leaves
//! undefined).

/// The operations the formulas need, each one rounding.
pub trait Arith {
    type V: Copy;
    type E;
    fn mul(&mut self, a: Self::V, b: Self::V) -> Result<Self::V, Self::E>;
    fn add(&mut self, a: Self::V, b: Self::V) -> Result<Self::V, Self::E>;
    fn sub(&mut self, a: Self::V, b: Self::V) -> Result<Self::V, Self::E>;
    fn div(&mut self, a: Self::V, b: Self::V) -> Result<Self::V, Self::E>;
    fn neg(&mut self, a: Self::V) -> Result<Self::V, Self::E>;
}

/// The determinant of the `n`×`n` matrix `m`; `None` when `m` does not
/// hold `n * n` values or `n` is not 2 to 4.
pub fn determinant<A: Arith>(a: &mut A, m: &[A::V], n: usize) -> Option<Result<A::V, A::E>> {
    if !(2..=4).contains(&n) || m.len() != n * n {
        return None;
    }
    let cols: Vec<usize> = (0..n).collect();
    let rows: Vec<usize> = (0..n).collect();
    Some(minor(a, m, n, &cols, &rows))
}

/// The inverse of the `n`×`n` matrix `m`, column-major; `None` as for
/// [`determinant`].
pub fn inverse<A: Arith>(a: &mut A, m: &[A::V], n: usize) -> Option<Result<Vec<A::V>, A::E>> {
    if !(2..=4).contains(&n) || m.len() != n * n {
        return None;
    }
    Some(inverse_of(a, m, n))
}

fn inverse_of<A: Arith>(a: &mut A, m: &[A::V], n: usize) -> Result<Vec<A::V>, A::E> {
    let all: Vec<usize> = (0..n).collect();
    let det = minor(a, m, n, &all, &all)?;
    let mut out = Vec::with_capacity(n * n);
    // inverse[c][r] = cofactor of (column r, row c) / det.
    for c in 0..n {
        for r in 0..n {
            let cols: Vec<usize> = all.iter().copied().filter(|&k| k != r).collect();
            let rows: Vec<usize> = all.iter().copied().filter(|&k| k != c).collect();
            let mut cof = minor(a, m, n, &cols, &rows)?;
            if (r + c) % 2 == 1 {
                cof = a.neg(cof)?;
            }
            out.push(a.div(cof, det)?);
        }
    }
    Ok(out)
}

/// The determinant of the submatrix of `m` (size `n`) made of `cols` and
/// `rows`, expanded along its first column.
fn minor<A: Arith>(
    a: &mut A,
    m: &[A::V],
    n: usize,
    cols: &[usize],
    rows: &[usize],
) -> Result<A::V, A::E> {
    let at = |c: usize, r: usize| m[c * n + r];
    if cols.len() == 1 {
        return Ok(at(cols[0], rows[0]));
    }
    if cols.len() == 2 {
        let p = a.mul(at(cols[0], rows[0]), at(cols[1], rows[1]))?;
        let q = a.mul(at(cols[1], rows[0]), at(cols[0], rows[1]))?;
        return a.sub(p, q);
    }
    let rest = &cols[1..];
    let mut acc: Option<A::V> = None;
    for (i, &r) in rows.iter().enumerate() {
        let sub_rows: Vec<usize> = rows.iter().copied().filter(|&k| k != r).collect();
        let d = minor(a, m, n, rest, &sub_rows)?;
        let t = a.mul(at(cols[0], r), d)?;
        acc = Some(match acc {
            None => t,
            Some(s) if i % 2 == 1 => a.sub(s, t)?,
            Some(s) => a.add(s, t)?,
        });
    }
    // `rows` has at least 3 entries here.
    acc.map_or_else(|| Ok(at(cols[0], rows[0])), Ok)
}

#[cfg(test)]
mod tests {
    use super::*;

    struct F;
    impl Arith for F {
        type V = f32;
        type E = ();
        fn mul(&mut self, a: f32, b: f32) -> Result<f32, ()> {
            Ok(a * b)
        }
        fn add(&mut self, a: f32, b: f32) -> Result<f32, ()> {
            Ok(a + b)
        }
        fn sub(&mut self, a: f32, b: f32) -> Result<f32, ()> {
            Ok(a - b)
        }
        fn div(&mut self, a: f32, b: f32) -> Result<f32, ()> {
            Ok(a / b)
        }
        fn neg(&mut self, a: f32) -> Result<f32, ()> {
            Ok(-a)
        }
    }

    #[test]
    fn determinants_and_inverses() {
        // Columns (2, 0), (1, 3): det 6.
        let m2 = [2.0, 0.0, 1.0, 3.0];
        assert_eq!(determinant(&mut F, &m2, 2), Some(Ok(6.0)));
        let inv = inverse(&mut F, &m2, 2).unwrap().unwrap();
        assert_eq!(inv, vec![0.5, 0.0, -1.0 / 6.0, 1.0 / 3.0]);
        // A diagonal 4x4 and a permutation 3x3 (det -1).
        let mut d4 = [0.0f32; 16];
        for (k, v) in [1.0, 2.0, 4.0, 8.0].into_iter().enumerate() {
            d4[k * 5] = v;
        }
        assert_eq!(determinant(&mut F, &d4, 4), Some(Ok(64.0)));
        let inv = inverse(&mut F, &d4, 4).unwrap().unwrap();
        assert_eq!(inv[15], 0.125);
        let p3 = [0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];
        assert_eq!(determinant(&mut F, &p3, 3), Some(Ok(-1.0)));
        assert_eq!(inverse(&mut F, &p3, 3).unwrap().unwrap(), p3.to_vec());
        assert_eq!(determinant(&mut F, &p3, 2), None);
    }
}
