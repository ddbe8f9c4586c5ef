//! What the `pdb` and `mmcif` targets do with a structure that parsed:
//! check the reader's contract and run the steps `shaderbox render` runs on
//! it before drawing (bonds by distance, framing the camera).

use render::bonds::find_bonds;
use render::{Camera, Projection, Structure};

pub fn check(s: &Structure) {
    let n = s.atoms.len();
    assert!(n > 0, "a structure that parsed has atoms");
    for a in &s.atoms {
        assert!(
            a.position.iter().all(|p| p.is_finite()),
            "atom on line {} has a coordinate that is not finite: {:?}",
            a.line,
            a.position
        );
    }
    for w in s.conect.windows(2) {
        assert!(w[0] < w[1], "CONECT bonds sorted, without duplicates");
    }
    for &(a, b) in &s.conect {
        assert!(a < b && b < n, "CONECT bond ({a}, {b}) of {n} atoms");
    }
    let bonds = find_bonds(s);
    for &(a, b) in &bonds {
        assert!(a < b && b < n, "bond ({a}, {b}) of {n} atoms");
    }
    let spheres: Vec<([f32; 3], f32)> = s
        .atoms
        .iter()
        .map(|a| (a.position, a.element.covalent_radius()))
        .collect();
    for projection in [Projection::Perspective, Projection::Orthographic] {
        let camera = Camera::fit(&spheres, projection, 64, 48, [15.0, 30.0, 0.0]);
        let (near, far) = camera.depth_span();
        assert!(
            near.is_finite() && far.is_finite(),
            "camera depth span {near}..{far}"
        );
    }
}
