//! `Renderer`, one context for many renders: each image and each recorded
//! scene is the same as a fresh `render_scene` gives, whatever was drawn
//! before on the context (other molecules, effects, styles, fog,
//! projections, backgrounds, atom paths, sizes), and a failed render
//! leaves the renderer usable.

use render::{
    crambin, parse_pdb, render_scene, Atoms, Background, Effect, Fog, Projection, RenderError,
    RenderOptions, Renderer, Structure, Style,
};

fn small(n: u32) -> RenderOptions {
    RenderOptions {
        width: n,
        height: n,
        ..RenderOptions::default()
    }
}

/// A short chain of `n` atoms of three elements (bonded by distance).
fn chain(n: usize) -> Structure {
    let mut text = String::new();
    for i in 0..n {
        let e = ["C", "O", "N"][i % 3];
        let (x, y, z) = (1.4 * i as f32, (i as f32 * 0.7).sin(), 0.3 * i as f32);
        text += &format!(
            "HETATM{:>5} {:<4} LIG A   1    {x:>8.3}{y:>8.3}{z:>8.3}  1.00  0.00          {e:>2}\n",
            i + 1,
            format!(" {e}{}", i + 1)
        );
    }
    parse_pdb(text.as_bytes(), "chain.pdb").unwrap()
}

#[test]
fn renders_in_sequence_equal_fresh_renders() {
    let protein = crambin();
    let ligand = chain(7);
    let runs: Vec<(&str, &Structure, RenderOptions)> = vec![
        ("crambin, defaults", &protein, small(64)),
        (
            "ligand, ball-and-stick, outline, perspective, exp fog",
            &ligand,
            RenderOptions {
                style: Style::BallAndStick,
                effect: Effect::Outline,
                projection: Projection::Perspective,
                fog: Fog::Exp,
                lights: vec![0, 3, 6],
                ..small(64)
            },
        ),
        (
            "crambin, x-red points, linear fog, transparent background",
            &protein,
            RenderOptions {
                effect: Effect::XRed,
                atoms: Atoms::Points,
                fog: Fog::Linear,
                background: Background::Transparent,
                rotate: [10.0, 40.0, 5.0],
                ..small(64)
            },
        ),
        (
            "ligand, transparent effect, supersampled (another size)",
            &ligand,
            RenderOptions {
                effect: Effect::Transparent,
                supersample: 2,
                ..small(48)
            },
        ),
        (
            "ligand, defaults at the first size again",
            &ligand,
            small(64),
        ),
        ("crambin, defaults again", &protein, small(64)),
    ];
    let mut renderer = Renderer::new();
    for (what, s, o) in &runs {
        let (image, scene) = renderer.render_scene(s, o).unwrap();
        let (fresh, fresh_scene) = render_scene(s, o).unwrap();
        assert!(image.pixels == fresh.pixels, "{what}: image differs");
        assert!(scene == fresh_scene, "{what}: recorded scene differs");
        let bg = image.pixels[0];
        let drawn = image.pixels.iter().filter(|p| **p != bg).count();
        assert!(drawn > 0, "{what}: nothing drawn");
    }
}

#[test]
fn a_failed_render_leaves_it_usable() {
    let mut renderer = Renderer::new();
    let before = renderer.render(&crambin(), &small(32)).unwrap();
    let bad = RenderOptions {
        lights: vec![8],
        ..small(32)
    };
    assert!(matches!(
        renderer.render(&crambin(), &bad),
        Err(RenderError::Light(8))
    ));
    let after = renderer.render(&crambin(), &small(32)).unwrap();
    assert!(before.pixels == after.pixels);
}
