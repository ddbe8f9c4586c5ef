//! The seed talk's effects, each checked for its defining property on a
//! small scene (orthographic, no rotation, so object x/y map to pixels):
//! outline (black interiors that erase each other, lit rims), X (dark
//! diagonals on every atom), x-red (yellow diagonals on red atoms only),
//! transparent (a screen-door checkerboard on red atoms showing what is
//! behind them).

use render::{
    parse_pdb, render, Background, Camera, Effect, Image, Projection, RenderOptions, Structure,
};

fn atom(serial: usize, element: &str, [x, y, z]: [f32; 3]) -> String {
    format!(
        "ATOM  {serial:>5} {:<4} UNK A   1    {x:>8.3}{y:>8.3}{z:>8.3}  1.00  0.00          {element:>2}\n",
        format!(" {element}")
    )
}

fn structure(atoms: &[(&str, [f32; 3])]) -> Structure {
    let text: String = atoms
        .iter()
        .enumerate()
        .map(|(i, (e, p))| atom(i + 1, e, *p))
        .collect();
    parse_pdb(text.as_bytes(), "test.pdb").unwrap()
}

fn opts(size: u32, effect: Effect) -> RenderOptions {
    RenderOptions {
        width: size,
        height: size,
        effect,
        ..RenderOptions::default()
    }
}

/// Image pixel (column, row) at object-space (x, y).
fn pixel_of(s: &Structure, o: &RenderOptions, x: f32, y: f32) -> (u32, u32) {
    let spheres: Vec<_> = s
        .atoms
        .iter()
        .map(|a| (a.position, a.element.radius()))
        .collect();
    let cam = Camera::fit(
        &spheres,
        Projection::Orthographic,
        o.width,
        o.height,
        [0.0; 3],
    );
    let px = ((x - cam.center[0]) / cam.half_width * 0.5 + 0.5) * o.width as f32;
    let py = (0.5 - (y - cam.center[1]) / cam.half_height * 0.5) * o.height as f32;
    (px as u32, py as u32)
}

fn at(s: &Structure, img: &Image, o: &RenderOptions, x: f32, y: f32) -> [u8; 4] {
    let (px, py) = pixel_of(s, o, x, y);
    img.pixel(px, py).unwrap()
}

fn sum(p: [u8; 4]) -> u32 {
    p[0] as u32 + p[1] as u32 + p[2] as u32
}

#[test]
fn outline_blackens_interiors_and_lights_rims() {
    // Carbon (r 1.7) in front, a second carbon 2 A to the right behind it.
    let s = structure(&[("C", [0.0, 0.0, 0.0]), ("C", [2.0, 0.0, -1.0])]);
    let o = RenderOptions {
        background: Background::Color([1.0; 3]),
        ..opts(96, Effect::Outline)
    };
    let img = render(&s, &o).unwrap();
    let black = |p: [u8; 4]| p[..3] == [0, 0, 0];
    let white = |p: [u8; 4]| p[..3] == [255, 255, 255];
    // Interiors black, background white.
    assert!(black(at(&s, &img, &o, 0.0, 0.0)), "front interior");
    assert!(black(at(&s, &img, &o, 0.0, 1.0)), "front interior");
    assert!(black(at(&s, &img, &o, 2.5, 0.0)), "back interior");
    assert!(white(at(&s, &img, &o, 0.0, 2.5)), "background");
    // Walking out from the centre of the front atom along -x, up and down,
    // the last covered pixel before the background is a lit rim pixel.
    let (cx, cy) = pixel_of(&s, &o, 0.0, 0.0);
    for (dx, dy) in [(-1i32, 0i32), (0, -1), (0, 1)] {
        let mut last = None;
        for k in 0..48 {
            let p = img
                .pixel((cx as i32 + dx * k) as u32, (cy as i32 + dy * k) as u32)
                .unwrap();
            if white(p) {
                break;
            }
            last = Some(p);
        }
        let rim = last.unwrap();
        assert!(
            !black(rim) && sum(rim) > 20,
            "lit rim towards ({dx}, {dy}): {rim:?}"
        );
    }
    // The back atom's rim inside the front disc is erased by the front
    // atom's black interior (quad depth at its centre plane), while its
    // rim outside (x = 3.7) is lit.
    let (bx, by) = pixel_of(&s, &o, 2.0 - 1.7, 0.0);
    for x in bx.saturating_sub(2)..=bx + 2 {
        assert!(black(img.pixel(x, by).unwrap()), "erased back rim at {x}");
    }
    let (rx, ry) = pixel_of(&s, &o, 2.0 + 1.7, 0.0);
    let lit = (rx.saturating_sub(2)..=rx + 1)
        .map(|x| img.pixel(x, ry).unwrap())
        .any(|p| !black(p) && !white(p));
    assert!(lit, "back atom's outer rim is lit");
    // Mostly black: rims are thin.
    let blacks = img.pixels.iter().filter(|p| black(**p)).count();
    let lits = img
        .pixels
        .iter()
        .filter(|p| !black(**p) && !white(**p))
        .count();
    assert!(blacks > 6 * lits, "{blacks} black, {lits} lit");
}

/// Offsets (in units of the radius) on the quad diagonals and off them.
const DIAGONAL: [(f32, f32); 4] = [(0.5, 0.5), (-0.5, 0.5), (-0.5, -0.5), (0.5, -0.5)];
const OFF_DIAGONAL: [(f32, f32); 4] = [(0.6, 0.0), (0.0, 0.6), (-0.6, 0.0), (0.0, -0.6)];

#[test]
fn x_draws_dark_diagonals_on_every_atom() {
    let s = structure(&[("C", [-2.0, 0.0, 0.0]), ("O", [2.0, 0.0, 0.0])]);
    let plain = opts(96, Effect::Plain);
    let x = opts(96, Effect::X);
    let p = render(&s, &plain).unwrap();
    let img = render(&s, &x).unwrap();
    for a in &s.atoms {
        let [ax, ay, _] = a.position;
        let r = a.element.radius();
        for (dx, dy) in DIAGONAL {
            let (px, py) = (ax + dx * r, ay + dy * r);
            let on = at(&s, &img, &x, px, py);
            let lit = at(&s, &p, &plain, px, py);
            assert!(
                sum(on) * 2 < sum(lit),
                "{:?} diagonal ({dx}, {dy}) dark: {on:?} vs plain {lit:?}",
                a.element
            );
        }
        for (dx, dy) in OFF_DIAGONAL {
            let (px, py) = (ax + dx * r, ay + dy * r);
            assert_eq!(
                at(&s, &img, &x, px, py),
                at(&s, &p, &plain, px, py),
                "off the X the atom is drawn as plain"
            );
        }
    }
}

#[test]
fn x_red_draws_yellow_diagonals_on_red_atoms_only() {
    let s = structure(&[("C", [-2.0, 0.0, 0.0]), ("O", [2.0, 0.0, 0.0])]);
    let plain = opts(96, Effect::Plain);
    let xr = opts(96, Effect::XRed);
    let p = render(&s, &plain).unwrap();
    let img = render(&s, &xr).unwrap();
    for a in &s.atoms {
        let [ax, ay, _] = a.position;
        let r = a.element.radius();
        let red = a.element == render::Element::OXYGEN;
        for (dx, dy) in DIAGONAL {
            let (px, py) = (ax + dx * r, ay + dy * r);
            let on = at(&s, &img, &xr, px, py);
            if red {
                assert!(
                    on[0] > 120 && on[1] > 120 && on[2] < on[1] / 2,
                    "yellow X on oxygen at ({dx}, {dy}): {on:?}"
                );
            } else {
                assert_eq!(on, at(&s, &p, &plain, px, py), "no X on carbon");
            }
        }
        for (dx, dy) in OFF_DIAGONAL {
            let (px, py) = (ax + dx * r, ay + dy * r);
            assert_eq!(at(&s, &img, &xr, px, py), at(&s, &p, &plain, px, py));
        }
    }
}

#[test]
fn transparent_red_atoms_show_what_is_behind_through_a_checkerboard() {
    // Oxygen in front of a carbon (1 A to its right, behind), and a lone
    // carbon in front to the left that must stay solid.
    let s = structure(&[
        ("C", [3.0, 0.0, -4.0]),
        ("O", [2.0, 0.0, 0.0]),
        ("C", [-2.5, 0.0, 0.0]),
    ]);
    let o = opts(96, Effect::Transparent);
    let img = render(&s, &o).unwrap();
    let is_red = |p: [u8; 4]| p[0] as u32 > p[1] as u32 + 40 && p[0] as u32 > p[2] as u32 + 40;
    let is_grey = |p: [u8; 4]| p[0] > 30 && p[0].abs_diff(p[1]) < 10 && p[1].abs_diff(p[2]) < 10;
    // Over the oxygen (carbon behind): red and grey alternate in a
    // checkerboard.
    let (cx, cy) = pixel_of(&s, &o, 2.0, 0.0);
    let mut reds = 0;
    for y in cy - 3..=cy + 3 {
        for x in cx - 3..=cx + 3 {
            let p = img.pixel(x, y).unwrap();
            let right = img.pixel(x + 1, y).unwrap();
            let below = img.pixel(x, y + 1).unwrap();
            assert!(is_red(p) || is_grey(p), "({x}, {y}): {p:?}");
            assert_ne!(is_red(p), is_red(right), "({x}, {y}) vs right");
            assert_ne!(is_red(p), is_red(below), "({x}, {y}) vs below");
            reds += is_red(p) as u32;
        }
    }
    assert!((24..=25).contains(&reds), "{reds} of 49 red");
    // Over the oxygen's left part, beyond the carbon behind it (x < 1.3):
    // holes show the black background.
    let (ex, ey) = pixel_of(&s, &o, 0.8, 0.0);
    let pair = [img.pixel(ex, ey).unwrap(), img.pixel(ex + 1, ey).unwrap()];
    assert!(
        pair.iter().any(|p| p[..3] == [0, 0, 0]) && pair.iter().any(|p| is_red(*p)),
        "{pair:?}"
    );
    // The carbon in front is not red: solid.
    let (lx, ly) = pixel_of(&s, &o, -2.5, 0.0);
    for x in lx - 3..=lx + 3 {
        let p = img.pixel(x, ly).unwrap();
        assert!(is_grey(p), "solid carbon at {x}: {p:?}");
    }
}

#[test]
fn every_effect_renders_in_perspective_with_fog() {
    // Every effect renders in perspective and with fog, and the plain
    // effect is the default.
    assert_eq!(RenderOptions::default().effect, Effect::Plain);
    let s = structure(&[("C", [0.0, 0.0, 0.0]), ("O", [2.0, 0.5, -1.0])]);
    for effect in Effect::ALL {
        let o = RenderOptions {
            projection: Projection::Perspective,
            fog: render::Fog::Linear,
            ..opts(24, effect)
        };
        let img = render(&s, &o).unwrap();
        let drawn = img.pixels.iter().filter(|p| p[..3] != [0, 0, 0]).count();
        assert!(drawn > 20, "{effect:?}: {drawn} pixels drawn");
    }
}
