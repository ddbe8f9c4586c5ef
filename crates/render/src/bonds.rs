//! Bonds for ball-and-stick: the file's CONECT records plus bonds found by
//! distance.
//!
//! Two atoms are bonded by distance when they are closer than the sum of
//! their covalent radii plus [`TOLERANCE`] and farther apart than
//! [`MIN_DISTANCE`] (closer pairs are overlapping alternate positions or
//! errors, not bonds). Hydrogens bond by distance too. An atom keeps at
//! most [`bond_cap`] of its candidates, the nearest: a pair is bonded when
//! each is among the other's nearest, so atoms packed closer than any
//! molecule packs them (a corrupt file, a misread unit) give a bounded
//! number of bonds instead of every pair. A uniform grid of cells as large
//! as the longest possible bond keeps the search linear in the number of
//! atoms at any real density. The result is sorted and free of duplicates,
//! so it is the same on every machine.

use crate::elements::Element;
use crate::structure::Structure;

/// Added to the sum of covalent radii, in Å.
pub const TOLERANCE: f32 = 0.45;
/// Pairs closer than this (Å) are never bonded.
pub const MIN_DISTANCE: f32 = 0.4;
/// Most bonds by distance an atom other than hydrogen may have.
pub const MAX_BONDS: usize = 6;

/// Bonds of `s`: its CONECT bonds and its bonds by distance, as pairs of
/// atom indices (lower first), sorted, without duplicates.
pub fn find_bonds(s: &Structure) -> Vec<(usize, usize)> {
    let mut bonds = s.conect.clone();
    bonds.extend(distance_bonds(s));
    bonds.sort_unstable();
    bonds.dedup();
    bonds
}

/// Bonds one atom of this element may have at most: one for hydrogen,
/// [`MAX_BONDS`] for every other element (octahedral metals have six).
pub fn bond_cap(element: Element) -> usize {
    if element == Element::HYDROGEN {
        1
    } else {
        MAX_BONDS
    }
}

/// Bonds by covalent radii (see the module docs).
pub fn distance_bonds(s: &Structure) -> Vec<(usize, usize)> {
    let atoms = &s.atoms;
    if atoms.is_empty() {
        return Vec::new();
    }
    let radii: Vec<f32> = atoms.iter().map(|a| a.element.covalent_radius()).collect();
    let max_r = radii.iter().copied().fold(0.0f32, f32::max);
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
    // Each atom's nearest partners, at most its cap, nearest first (ties
    // by index, so the choice is the same on every machine).
    let mut nearest: Vec<Vec<usize>> = Vec::with_capacity(atoms.len());
    let mut found: Vec<(f32, usize)> = Vec::new();
    for (i, a) in atoms.iter().enumerate() {
        found.clear();
        let c = key(a.position);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    for &(_, j) in range([c[0] + dx, c[1] + dy, c[2] + dz]) {
                        let (Some(b), Some(rj)) = (atoms.get(j), radii.get(j)) else {
                            continue;
                        };
                        if j == i {
                            continue;
                        }
                        let d = [0, 1, 2].map(|k| a.position[k] - b.position[k]);
                        let d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                        let max = radii[i] + rj + TOLERANCE;
                        if d2 > MIN_DISTANCE * MIN_DISTANCE && d2 < max * max {
                            found.push((d2, j));
                        }
                    }
                }
            }
        }
        found.sort_unstable_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        found.truncate(bond_cap(a.element));
        nearest.push(found.iter().map(|&(_, j)| j).collect());
    }
    let mut out = Vec::new();
    for (i, partners) in nearest.iter().enumerate() {
        for &j in partners {
            if j > i && nearest[j].contains(&i) {
                out.push((i, j));
            }
        }
    }
    out.sort_unstable();
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::load::crambin;

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

    fn atoms_at(points: &[(Element, [f32; 3])]) -> Structure {
        Structure {
            source: "test".into(),
            atoms: points
                .iter()
                .enumerate()
                .map(|(i, &(element, position))| crate::structure::Atom {
                    element,
                    position,
                    name: String::new(),
                    residue: String::new(),
                    line: i + 1,
                    serial: None,
                })
                .collect(),
            conect: Vec::new(),
        }
    }

    #[test]
    fn packed_atoms_get_bounded_bonds() {
        // 3,000 carbons in a 3 Å cube: every pair is within bonding
        // distance, but no atom keeps more than its cap.
        let mut seed = 12345u32;
        let mut next = || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (seed >> 8) as f32 / (1u32 << 24) as f32 * 3.0
        };
        let points: Vec<_> = (0..3000)
            .map(|_| (Element::CARBON, [next(), next(), next()]))
            .collect();
        let s = atoms_at(&points);
        let bonds = find_bonds(&s);
        let mut count = vec![0usize; s.atoms.len()];
        for &(a, b) in &bonds {
            assert!(a < b);
            count[a] += 1;
            count[b] += 1;
        }
        assert!(count.iter().all(|&n| n <= MAX_BONDS));
        assert!(bonds.len() > s.atoms.len(), "{}", bonds.len());
        assert_eq!(find_bonds(&s), bonds);
    }

    #[test]
    fn hydrogen_bonds_to_its_nearest_partner() {
        let s = atoms_at(&[
            (Element::CARBON, [0.0, 0.0, 0.0]),
            (Element::HYDROGEN, [1.0, 0.0, 0.0]),
            (Element::CARBON, [2.1, 0.0, 0.0]),
        ]);
        assert_eq!(distance_bonds(&s), vec![(0, 1)]);
    }
}
