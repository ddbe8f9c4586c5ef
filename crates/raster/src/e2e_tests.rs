//! End to end: GLSL compiled and linked by `glsl`, lowered by `exec`, drawn
//! by `draw()`.

use std::sync::Arc;

use crate::ex::Kernel;
use crate::state::*;
use crate::texture::{
    Image, MagFilter, MinFilter, Texture, TextureTarget, TextureUnit, TextureUnits,
};
use crate::{draw, ColorFormat, Framebuffer, Mode, VertexFetch};
use glsl::ir::Stage;
use glsl::{compile, CompileOptions};

fn program(vs: &str, fs: &str) -> (Kernel, Kernel) {
    let v = compile(&[vs], &CompileOptions::new(Stage::Vertex));
    let f = compile(&[fs], &CompileOptions::new(Stage::Fragment));
    assert!(v.ok(), "{}", v.info_log());
    assert!(f.ok(), "{}", f.info_log());
    let prog = glsl::link::link(&[&v, &f]);
    assert!(prog.ok(), "{}", prog.info_log());
    let k = |s: Stage| Kernel::new(prog.stage(s).expect("stage")).expect("lowering");
    (k(Stage::Vertex), k(Stage::Fragment))
}

/// Attributes by name: `pos` (xy) and `col`.
struct Attribs<'a> {
    names: Vec<String>,
    pos: &'a [[f32; 2]],
    col: &'a [[f32; 4]],
}

impl VertexFetch for Attribs<'_> {
    fn fetch(&self, slot: usize, v: u32, out: &mut [f32; 4]) {
        match self.names.get(slot).map(String::as_str) {
            Some("pos") => {
                if let Some(p) = self.pos.get(v as usize) {
                    out[0] = p[0];
                    out[1] = p[1];
                }
            }
            Some("col") => {
                if let Some(c) = self.col.get(v as usize) {
                    *out = *c;
                }
            }
            _ => {}
        }
    }
}

const QUAD: [[f32; 2]; 6] = [
    [-1.0, -1.0],
    [1.0, -1.0],
    [1.0, 1.0],
    [-1.0, -1.0],
    [1.0, 1.0],
    [-1.0, 1.0],
];

fn words(k: &Kernel, values: &[(&str, &[u32])]) -> Vec<u32> {
    let mut w = vec![0u32; k.interface().uniform_words];
    for (name, v) in values {
        let (off, _) = k.interface().locate_uniform(name).expect("uniform");
        w[off..off + v.len()].copy_from_slice(v);
    }
    w
}

#[test]
fn two_triangles_covering_the_viewport() {
    let (vs, fs) = program(
        "attribute vec4 pos; attribute vec4 col; varying vec4 v;\n\
         void main() { gl_Position = pos; v = col; gl_FrontColor = col.bgra; }",
        "varying vec4 v; uniform vec4 scale;\n\
         void main() { gl_FragColor = gl_FragCoord.x < 4.0 ? v * scale : gl_Color; }",
    );
    let (w, h) = (8, 8);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    let state = PipelineState {
        viewport: Rect::new(0, 0, w as i32, h as i32),
        ..PipelineState::default()
    };
    let col = [[1.0, 0.5, 0.0, 1.0]; 6];
    let fetch = Attribs {
        names: vs
            .interface()
            .inputs
            .iter()
            .map(|s| s.name.clone())
            .collect(),
        pos: &QUAD,
        col: &col,
    };
    let fsu = words(
        &fs,
        &[("scale", &[0.5f32, 1.0, 1.0, 1.0].map(f32::to_bits))],
    );
    let idx: Vec<u32> = (0..6).collect();
    let tex = TextureUnits::default();
    draw(
        &mut fb,
        &state,
        &vs,
        &[],
        &fs,
        &fsu,
        Mode::Triangles,
        &idx,
        &fetch,
        &tex,
    )
    .unwrap();
    let px = fb.read_pixels_u8(0, 0, 0, w, h);
    for y in 0..8 {
        for x in 0..8 {
            let want = if x < 4 {
                [128, 128, 0, 255]
            } else {
                [0, 128, 255, 255]
            };
            assert_eq!(px[y * 8 + x], want, "{x},{y}");
        }
    }
}

#[test]
fn textured_quad_with_implicit_lod() {
    // A 4×4 texture, level 0 red, level 1 green, level 2 blue, over 8×8
    // pixels with coordinates in [0, k]: du/dx = 4k/8, so k = 1 magnifies
    // (λ = -1), k = 4 gives λ = 1 and k = 8 gives λ = 2
    // (NEAREST_MIPMAP_NEAREST).
    let (vs, fs) = program(
        "attribute vec4 pos; varying vec2 tc; uniform float k;\n\
         void main() { gl_Position = pos; tc = (pos.xy * 0.5 + 0.5) * k; }",
        "varying vec2 tc; uniform sampler2D s;\n\
         void main() { gl_FragColor = texture2D(s, tc); }",
    );
    let level = |n: u32, c: [f32; 4]| Image::new(n, n, 1, vec![c; (n * n) as usize]);
    let mut t = Texture::new(
        TextureTarget::Tex2D,
        vec![
            level(4, [1.0, 0.0, 0.0, 1.0]),
            level(2, [0.0, 1.0, 0.0, 1.0]),
            level(1, [0.0, 0.0, 1.0, 1.0]),
        ],
    );
    t.min_filter = MinFilter::NearestMipmapNearest;
    t.mag_filter = MagFilter::Nearest;
    let units = TextureUnits {
        units: vec![
            TextureUnit::default(),
            TextureUnit {
                tex_2d: Some(Arc::new(t)),
                ..TextureUnit::default()
            },
        ],
    };
    let (w, h) = (8, 8);
    let state = PipelineState {
        viewport: Rect::new(0, 0, w as i32, h as i32),
        ..PipelineState::default()
    };
    let fetch = Attribs {
        names: vs
            .interface()
            .inputs
            .iter()
            .map(|s| s.name.clone())
            .collect(),
        pos: &QUAD,
        col: &[],
    };
    let idx: Vec<u32> = (0..6).collect();
    let fsu = words(&fs, &[("s", &[1])]);
    for (k, want) in [
        (1.0f32, [255, 0, 0, 255]),
        (4.0, [0, 255, 0, 255]),
        (8.0, [0, 0, 255, 255]),
    ] {
        let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
        let vsu = words(&vs, &[("k", &[k.to_bits()])]);
        draw(
            &mut fb,
            &state,
            &vs,
            &vsu,
            &fs,
            &fsu,
            Mode::Triangles,
            &idx,
            &fetch,
            &units,
        )
        .unwrap();
        let px = fb.read_pixels_u8(0, 0, 0, w, h);
        assert!(px.iter().all(|p| *p == want), "k = {k}: {:?}", &px[..8]);
    }
}
