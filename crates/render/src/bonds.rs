//! Bonds for ball-and-stick: the file's CONECT records plus bonds found by
//! distance.
//!
//! Two atoms are bonded by distance when they are closer than the sum of
//! their covalent radii plus [`TOLERANCE`] and farther apart than
//! [`MIN_DISTANCE`] (closer pairs are overlapping alternate positions or
//! errors, not bonds). Hydrogens bond by distance too. A uniform grid of
//! cells as large as the longest possible bond keeps the search linear in
//! the number of atoms. The result is sorted and free of duplicates, so it
//! is the same on every machine.

use crate::structure::Structure;

/// Added to the sum of covalent radii, in Å.
pub const TOLERANCE: f32 = 0.45;
/// Pairs closer than this (Å) are never bonded.
pub const MIN_DISTANCE: f32 = 0.4;

/// Bonds of `s`: its CONECT bonds and its bonds by distance, as pairs of
/// atom indices (lower first), sorted, without duplicates.
pub fn find_bonds(s: &Structure) -> Vec<(usize, usize)> {
    let mut bonds = s.conect.clone();
    bonds.extend(distance_bonds(s));
    bonds.sort_unstable();
    bonds.dedup();
    bonds
}

/// Bonds by covalent radii (see the module docs).
pub fn distance_bonds(s: &Structure) -> Vec<(usize, usize)> {
    let atoms = &s.atoms;
    if atoms.is_empty() {
        return Vec::new();
    }
    let max_r = atoms
        .iter()
        .map(|a| a.element.covalent_radius())
        .fold(0.0f32, f32::max);
    let cell = (2.0 * max_r + TOLERANCE).max(1.0);
    let mut lo = [f32::INFINITY; 3];
    for a in atoms {
        for (l, p) in lo.iter_mut().zip(a.position) {
            *l = l.min(p);
        }
    }
    let key = |p: [f32; 3]| -> [i64; 3] {
        [0, 1, 2].map(|k| ((p[k] - lo[k]) / cell).floor().clamp(0.0, 1e9) as i64)
    };
    // Atoms sorted by cell: (cell, index).
    let mut cells: Vec<([i64; 3], usize)> = atoms
        .iter()
        .enumerate()
        .map(|(i, a)| (key(a.position), i))
        .collect();
    cells.sort_unstable();
    let range = |c: [i64; 3]| -> &[([i64; 3], usize)] {
        let start = cells.partition_point(|(k, _)| *k < c);
        let end = cells.partition_point(|(k, _)| *k <= c);
        cells.get(start..end).unwrap_or(&[])
    };
    let mut out = Vec::new();
    for (i, a) in atoms.iter().enumerate() {
        let c = key(a.position);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    for (_, j) in range([c[0] + dx, c[1] + dy, c[2] + dz]) {
                        let j = *j;
                        if j <= i {
                            continue;
                        }
                        let Some(b) = atoms.get(j) else { continue };
                        let d = [0, 1, 2].map(|k| a.position[k] - b.position[k]);
                        let d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                        let max =
                            a.element.covalent_radius() + b.element.covalent_radius() + TOLERANCE;
                        if d2 > MIN_DISTANCE * MIN_DISTANCE && d2 < max * max {
                            out.push((i, j));
                        }
                    }
                }
            }
        }
    }
    out.sort_unstable();
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::structure::crambin;

    #[test]
    fn crambin_bonds() {
        let s = crambin();
        let bonds = find_bonds(&s);
        // 327 heavy atoms in 46 residues: about one bond per atom plus
        // ring closures; every disulfide (CONECT) is among them.
        assert!((320..=360).contains(&bonds.len()), "{}", bonds.len());
        for b in &s.conect {
            assert!(bonds.contains(b));
        }
        // Matches the quadratic search.
        let mut brute = Vec::new();
        for i in 0..s.atoms.len() {
            for j in i + 1..s.atoms.len() {
                let (a, b) = (&s.atoms[i], &s.atoms[j]);
                let d2: f32 = (0..3)
                    .map(|k| (a.position[k] - b.position[k]).powi(2))
                    .sum();
                let m = a.element.covalent_radius() + b.element.covalent_radius() + TOLERANCE;
                if d2 > MIN_DISTANCE * MIN_DISTANCE && d2 < m * m {
                    brute.push((i, j));
                }
            }
        }
        assert_eq!(distance_bonds(&s), brute);
        // No atom has more than 4 bonds (heavy atoms only in 1CRN).
        for i in 0..s.atoms.len() {
            let n = bonds.iter().filter(|(a, b)| *a == i || *b == i).count();
            assert!(n <= 4, "atom {i} has {n} bonds");
        }
    }
}
