//! Ball-and-stick: bonds drawn as cylinders between smaller atoms.

use render::{parse_pdb, render, Background, RenderOptions, Style};

#[test]
fn bond_is_drawn_between_two_atoms() {
    // Two carbons 1.5 A apart on x (a bond by covalent radii), one oxygen
    // far away (no bond). Orthographic, no rotation: object x/y map to
    // pixels linearly about the centre.
    let text = "\
ATOM      1  C1  UNK A   1       0.000   0.000   0.000  1.00  0.00           C
ATOM      2  C2  UNK A   1       1.500   0.000   0.000  1.00  0.00           C
ATOM      3  O1  UNK A   1       7.000   0.000   0.000  1.00  0.00           O
";
    let s = parse_pdb(text.as_bytes(), "t.pdb").unwrap();
    let o = RenderOptions {
        width: 200,
        height: 100,
        style: Style::BallAndStick,
        background: Background::Color([0.0, 0.0, 1.0]),
        ..RenderOptions::default()
    };
    let img = render(&s, &o).unwrap();
    // Camera: centre x = 3.5; the view's half height is the bounding
    // radius (3.5 + 0.3 * 1.52) * 1.05, the half width twice that.
    let half_h = (3.5 + 0.3 * 1.52) * 1.05;
    let half_w = 2.0 * half_h;
    let px = |x: f32, y: f32| {
        let col = ((x - 3.5) / half_w * 0.5 + 0.5) * 200.0;
        let row = (0.5 - y / half_h * 0.5) * 100.0;
        img.pixel(col as u32, row as u32).unwrap()
    };
    let background = [0, 0, 255, 255];
    // The bond's middle (outside both balls of radius 0.51) is drawn and
    // lit grey; just beside the thin bond is background.
    let mid = px(0.75, 0.0);
    assert_ne!(mid, background, "bond midpoint");
    assert!(
        mid[0] == mid[1] && mid[1] == mid[2],
        "carbon-grey bond: {mid:?}"
    );
    assert_eq!(px(0.75, 0.4), background, "beside the bond");
    // Between the second carbon and the oxygen: no bond.
    assert_eq!(px(4.25, 0.0), background, "no bond to the far oxygen");
    // The balls are there.
    assert_ne!(px(0.0, 0.0), background);
    assert_ne!(px(7.0, 0.0), background);
}
