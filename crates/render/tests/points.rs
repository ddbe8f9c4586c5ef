//! The geometry-shader path (`Atoms::Points`: one point per atom, expanded
//! by shaders/sphere.geom) against the quad path (`Atoms::Quads`): the same
//! image, byte for byte, on the embedded molecule and on synthetic ones,
//! for every effect, both projections, fog, ball-and-stick, supersampling
//! and a transparent background. A difference prints its pixel count and
//! largest channel difference before failing.
//!
//! Also: the scene recorder keeps the geometry stage (a replayed points
//! scene draws the same pixels), and scene JSON written before geometry
//! stages existed still loads.

use render::{
    crambin, parse_pdb, render, render_scene, Atoms, Background, Effect, Fog, Image, Projection,
    RenderOptions, Scene, Structure, Style,
};

/// `(pixels that differ, largest channel difference)`.
fn difference(a: &Image, b: &Image) -> (usize, u8) {
    assert_eq!((a.width, a.height), (b.width, b.height));
    let mut count = 0;
    let mut max = 0;
    for (p, q) in a.pixels.iter().zip(&b.pixels) {
        if p != q {
            count += 1;
            for c in 0..4 {
                max = max.max(p[c].abs_diff(q[c]));
            }
        }
    }
    (count, max)
}

fn same_image(s: &Structure, o: &RenderOptions, what: &str) -> Image {
    let quads = render(
        s,
        &RenderOptions {
            atoms: Atoms::Quads,
            ..o.clone()
        },
    )
    .unwrap();
    let points = render(
        s,
        &RenderOptions {
            atoms: Atoms::Points,
            ..o.clone()
        },
    )
    .unwrap();
    let (count, max) = difference(&quads, &points);
    println!("{what}: {count} pixels differ, max {max}/255");
    assert_eq!((count, max), (0, 0), "{what}");
    // Not a blank picture that would match anything.
    let bg = quads.pixels[0];
    let drawn = quads.pixels.iter().filter(|p| **p != bg).count();
    assert!(drawn * 10 > quads.pixels.len(), "{what}: {drawn} drawn");
    quads
}

fn size(n: u32) -> RenderOptions {
    RenderOptions {
        width: n,
        height: n,
        ..RenderOptions::default()
    }
}

/// A PDB of `n` atoms of four elements on a deterministic pseudo-random
/// cloud (a linear congruential generator: no dependency).
fn cloud(n: usize, spread: f32) -> Structure {
    let mut state = 12345u32;
    let mut next = || {
        state = state.wrapping_mul(1664525).wrapping_add(1013904223);
        (state >> 8) as f32 / (1u32 << 24) as f32
    };
    let mut text = String::new();
    for i in 0..n {
        let [x, y, z] = [0; 3].map(|_| (next() * 2.0 - 1.0) * spread);
        let e = ["C", "N", "O", "S"][(next() * 4.0) as usize % 4];
        text += &format!(
            "ATOM  {:>5} {:<4} UNK A   1    {x:>8.3}{y:>8.3}{z:>8.3}  1.00  0.00          {e:>2}\n",
            i + 1,
            format!(" {e}")
        );
    }
    parse_pdb(text.as_bytes(), "cloud.pdb").unwrap()
}

#[test]
fn the_default_molecule_is_the_same_image() {
    same_image(&crambin(), &size(128), "crambin, defaults");
}

#[test]
fn every_effect_in_perspective_with_fog() {
    let s = crambin();
    for effect in Effect::ALL {
        let o = RenderOptions {
            effect,
            projection: Projection::Perspective,
            fog: Fog::Linear,
            rotate: [20.0, 30.0, 0.0],
            ..size(96)
        };
        same_image(&s, &o, &format!("crambin, {}", effect.name()));
    }
}

#[test]
fn other_molecules_styles_and_options() {
    let near = RenderOptions {
        projection: Projection::Perspective,
        fog: Fog::Exp2,
        lights: vec![0, 1, 2, 5],
        ..size(96)
    };
    same_image(&cloud(300, 12.0), &near, "300-atom cloud, perspective");
    let o = RenderOptions {
        style: Style::BallAndStick,
        fog: Fog::Exp,
        rotate: [-40.0, 10.0, 70.0],
        ..size(96)
    };
    same_image(&crambin(), &o, "crambin, ball-and-stick");
    let o = RenderOptions {
        supersample: 2,
        background: Background::Transparent,
        width: 64,
        height: 48,
        ..RenderOptions::default()
    };
    same_image(&cloud(40, 5.0), &o, "40-atom cloud, 2x2 supersampled");
}

#[test]
fn a_points_scene_records_and_replays_its_geometry_stage() {
    let o = RenderOptions {
        atoms: Atoms::Points,
        ..size(48)
    };
    let (image, scene) = render_scene(&crambin(), &o).unwrap();
    let json = scene.to_json();
    assert!(json.contains("--atoms points"));
    assert!(json.contains("#extension GL_EXT_geometry_shader4"));
    assert!(json.contains("\"parameters\":[[36315,0],[36316,5],[36314,4]]"));
    let back = Scene::from_json(&json).unwrap();
    assert_eq!(back, scene);
    let mut ctx = back
        .replay_on(gl::Context::new(scene.width as i32, scene.height as i32))
        .unwrap();
    let px = ctx.read_pixels_f32(0, 0, 48, 48);
    let replayed = render::image::downsample(&px, 48, 48, 1, false);
    assert_eq!(replayed, image);
    // One vertex per atom.
    let draws: Vec<_> = scene
        .calls
        .iter()
        .filter_map(|c| match c {
            render::scene::Call::Draw { mode, count, .. } => Some((*mode, *count)),
            _ => None,
        })
        .collect();
    assert_eq!(draws, [(gl::enums::GL_POINTS, crambin().atoms.len())]);
}

#[test]
fn quads_scenes_keep_their_json_and_old_scenes_load() {
    let (_, scene) = render_scene(&crambin(), &size(8)).unwrap();
    let json = scene.to_json();
    assert!(!json.contains("\"geometry\""));
    assert!(!json.contains("\"parameters\""));
    // A program call as scenes were written before geometry stages.
    let old = r#"{"width":4,"height":4,"description":"old","calls":[
        {"call":"Program","args":{"id":0,"vertex":["void main(){gl_Position=gl_Vertex;}"],
         "fragment":["void main(){gl_FragColor=vec4(1.0);}"]}}]}"#;
    let scene = Scene::from_json(old).unwrap();
    match &scene.calls[0] {
        render::scene::Call::Program {
            geometry,
            parameters,
            ..
        } => assert!(geometry.is_empty() && parameters.is_empty()),
        c => panic!("{c:?}"),
    }
    assert!(scene.replay_on(gl::Context::new(4, 4)).is_ok());
}
