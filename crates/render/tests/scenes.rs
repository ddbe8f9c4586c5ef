//! End-to-end renders through gl::Context: the embedded molecule, sphere
//! intersections by per-pixel depth, fog modes. Small images (debug builds
//! interpret every fragment).

use render::{
    parse_pdb, render, Background, Camera, Fog, Image, Projection, RenderOptions, Structure,
    FOG_AT_BACK,
};

/// A PDB ATOM line for `element` at (x, y, z).
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

fn opts(size: u32) -> RenderOptions {
    RenderOptions {
        width: size,
        height: size,
        ..RenderOptions::default()
    }
}

/// Pixel of the orthographic image at object-space (x, y) (no rotation).
fn pixel_at(s: &Structure, img: &Image, o: &RenderOptions, x: f32, y: f32) -> [u8; 4] {
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
    let px = ((x - cam.center[0]) / cam.half_width * 0.5 + 0.5) * img.width as f32;
    let py = (0.5 - (y - cam.center[1]) / cam.half_height * 0.5) * img.height as f32;
    img.pixel(px as u32, py as u32).unwrap()
}

#[test]
fn embedded_molecule_is_drawn_lit_in_cpk_colours() {
    let s = render::crambin();
    let img = render(&s, &opts(96)).unwrap();
    let covered = img.pixels.iter().filter(|p| p[..3] != [0, 0, 0]).count();
    let total = img.pixels.len();
    assert!(covered * 4 > total, "{covered} of {total} pixels drawn");
    assert!(covered < total, "background visible around the molecule");
    // Red (oxygen), blue (nitrogen) and grey (carbon) pixels are there.
    let red = img
        .pixels
        .iter()
        .filter(|p| p[0] > 120 && p[1] < 40 && p[2] < 40)
        .count();
    let blue = img
        .pixels
        .iter()
        .filter(|p| p[2] > 120 && p[0] < 60)
        .count();
    let grey = img
        .pixels
        .iter()
        .filter(|p| p[0] > 60 && p[0].abs_diff(p[1]) < 8 && p[1].abs_diff(p[2]) < 8)
        .count();
    assert!(
        red > 50 && blue > 20 && grey > 200,
        "red {red} blue {blue} grey {grey}"
    );
    // Lit: shading varies across the picture (not flat colours).
    let mut levels: Vec<u8> = img.pixels.iter().map(|p| p[0]).collect();
    levels.sort_unstable();
    levels.dedup();
    assert!(levels.len() > 40, "{} distinct red levels", levels.len());
}

#[test]
fn spheres_intersect_by_surface_depth_not_draw_order() {
    // Potassium (r 2.75, purple) centred at z = 0 and hydrogen (r 1.2,
    // white) at x = 2, z = 0.5: the hydrogen's centre is nearer, but over
    // it the potassium surface (z = sqrt(2.75^2 - 2^2) = 1.89) is in front
    // of the hydrogen's (0.5 + 1.2 = 1.7). At x = 3 only hydrogen is there.
    let k = ("K", [0.0, 0.0, 0.0]);
    let h = ("H", [2.0, 0.0, 0.5]);
    let o = opts(96);
    for atoms in [[k, h], [h, k]] {
        let s = structure(&atoms);
        let img = render(&s, &o).unwrap();
        let over_h = pixel_at(&s, &img, &o, 2.0, 0.0);
        assert!(
            over_h[2] > over_h[1] + 40,
            "potassium purple wins over the hydrogen centre: {over_h:?}"
        );
        let h_only = pixel_at(&s, &img, &o, 2.9, 0.0);
        assert!(
            h_only[0].abs_diff(h_only[2]) < 25 && h_only[1] > 60,
            "hydrogen white beyond the potassium: {h_only:?}"
        );
        let k_only = pixel_at(&s, &img, &o, -1.5, 0.0);
        assert!(k_only[2] > k_only[1] + 40, "{k_only:?}");
    }
    // Same picture whichever atom is drawn first.
    let a = render(&structure(&[k, h]), &o).unwrap();
    let b = render(&structure(&[h, k]), &o).unwrap();
    assert_eq!(a, b);
}

/// Three carbons side by side at eye depths front/middle/back.
fn fog_row() -> Structure {
    structure(&[
        ("C", [-5.0, 0.0, 5.0]),
        ("C", [0.0, 0.0, 0.0]),
        ("C", [5.0, 0.0, -5.0]),
    ])
}

fn centre_pixels(fog: Fog, background: Background) -> ([[u8; 4]; 3], Camera) {
    let s = fog_row();
    let o = RenderOptions {
        fog,
        background,
        lights: vec![0],
        ..opts(64)
    };
    let img = render(&s, &o).unwrap();
    let spheres: Vec<_> = s
        .atoms
        .iter()
        .map(|a| (a.position, a.element.radius()))
        .collect();
    let cam = Camera::fit(&spheres, Projection::Orthographic, 64, 64, [0.0; 3]);
    let px = [-5.0, 0.0, 5.0].map(|x| pixel_at(&s, &img, &o, x, 0.0));
    (px, cam)
}

fn sum(p: [u8; 4]) -> u32 {
    p[0] as u32 + p[1] as u32 + p[2] as u32
}

#[test]
fn fog_darkens_or_lightens_with_distance_as_the_mode_says() {
    let black = Background::Color([0.0; 3]);
    let white = Background::Color([1.0; 3]);
    // No fog: orthographic + directional lights light all three alike
    // (up to where in its pixel each centre falls).
    let (none, cam) = centre_pixels(Fog::None, black);
    for p in &none[1..] {
        assert!(sum(*p).abs_diff(sum(none[0])) < 30, "{none:?}");
    }
    let (front, _) = cam.depth_span();
    let back = front + 2.0 * cam.radius;
    // Eye distances of the three centres: distance - 5, distance, + 5.
    let dist = [cam.distance - 5.0, cam.distance, cam.distance + 5.0];
    let k = -(FOG_AT_BACK.ln());
    let end = (back - FOG_AT_BACK * front) / (1.0 - FOG_AT_BACK);
    type FogFn = Box<dyn Fn(f32) -> f32>;
    let modes: [(Fog, FogFn); 3] = [
        (
            Fog::Linear,
            Box::new(move |c| ((end - c) / (end - front)).clamp(0.0, 1.0)),
        ),
        (Fog::Exp, Box::new(move |c| (-(k / back) * c).exp())),
        // GL_EXP2: exp(-(density * c)^2); the seed's slip (density * c^3)
        // would give a factor near 0 here.
        (
            Fog::Exp2,
            Box::new(move |c| {
                let d = k.sqrt() / back;
                (-(d * c) * (d * c)).exp()
            }),
        ),
    ];
    for (mode, factor) in modes {
        let (dark, _) = centre_pixels(mode, black);
        assert!(
            sum(dark[0]) > sum(dark[1]) && sum(dark[1]) > sum(dark[2]),
            "{mode:?} on black darkens with distance: {dark:?}"
        );
        for i in 0..3 {
            let f = factor(dist[i]);
            for ch in 0..3 {
                let expect = none[i][ch] as f32 * f;
                assert!(
                    (dark[i][ch] as f32 - expect).abs() <= 3.0,
                    "{mode:?} atom {i} channel {ch}: {} vs {expect} (factor {f})",
                    dark[i][ch]
                );
            }
        }
        let (light, _) = centre_pixels(mode, white);
        assert!(
            sum(light[0]) < sum(light[1]) && sum(light[1]) < sum(light[2]),
            "{mode:?} on white lightens with distance: {light:?}"
        );
    }
}

#[test]
fn transparent_background_and_supersampling() {
    let s = structure(&[("O", [0.0, 0.0, 0.0])]);
    let o = RenderOptions {
        background: Background::Transparent,
        supersample: 2,
        ..opts(32)
    };
    let img = render(&s, &o).unwrap();
    assert_eq!((img.width, img.height), (32, 32));
    assert!(img.has_alpha);
    assert_eq!(img.pixel(0, 0), Some([0, 0, 0, 0]), "corner is transparent");
    let centre = img.pixel(16, 16).unwrap();
    assert_eq!(centre[3], 255);
    assert!(centre[0] > 150 && centre[1] < 60, "red oxygen: {centre:?}");
    // Edge pixels are partly covered: alpha strictly between 0 and 255.
    assert!(img.pixels.iter().any(|p| p[3] > 0 && p[3] < 255));
    let png = img.to_png().unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
}

#[test]
fn perspective_and_rotation_render() {
    let s = structure(&[("C", [0.0, 0.0, 0.0]), ("O", [3.0, 0.0, 0.0])]);
    let base = RenderOptions {
        projection: Projection::Perspective,
        ..opts(48)
    };
    let a = render(&s, &base).unwrap();
    let drawn = |img: &Image| img.pixels.iter().filter(|p| p[..3] != [0, 0, 0]).count();
    assert!(drawn(&a) > 200);
    // Turned 90 degrees about Y, the two atoms line up along the view
    // axis (x becomes -z): the front one hides most of the other, so fewer
    // pixels are covered.
    let turned = RenderOptions {
        rotate: [0.0, 90.0, 0.0],
        ..base.clone()
    };
    let b = render(&s, &turned).unwrap();
    assert!(drawn(&b) < drawn(&a), "{} vs {}", drawn(&b), drawn(&a));
}
