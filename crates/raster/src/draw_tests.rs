//! draw() with hand-written shader stages (no exec kernels needed).

use crate::ex::{Batch, ExecError, Interface, Slot, Textures, LANES};
use crate::state::*;
use crate::texture_units::TextureUnits;
use crate::{
    draw_stages, ColorFormat, DrawError, Framebuffer, Mode, ShaderStage, VertexFetch, Workers,
};
use glsl::types::{Base, Scalar, Type};

type RunFn = dyn Fn(&mut Batch) -> Result<(), ExecError> + Send + Sync;

struct Stage {
    iface: Interface,
    f: Box<RunFn>,
}

impl ShaderStage for Stage {
    fn interface(&self) -> &Interface {
        &self.iface
    }
    fn run(&self, batch: &mut Batch, _: &[u32], _: &dyn Textures) -> Result<(), ExecError> {
        (self.f)(batch)
    }
}

fn slot(name: &str, offset: usize, components: usize) -> Slot {
    let ty = match components {
        1 => Type::FLOAT,
        n => Type::new(Base::Vector(Scalar::Float, n as u8)),
    };
    Slot {
        name: name.into(),
        ty,
        offset,
        components,
        written: true,
        location: None,
        index: None,
        interpolation: None,
        block: None,
    }
}

fn iface(inputs: Vec<Slot>, outputs: Vec<Slot>) -> Interface {
    Interface {
        input_components: inputs
            .iter()
            .map(|s| s.offset + s.components)
            .max()
            .unwrap_or(0),
        output_components: outputs
            .iter()
            .map(|s| s.offset + s.components)
            .max()
            .unwrap_or(0),
        inputs,
        outputs,
        ..Interface::default()
    }
}

fn copy(batch: &mut Batch, from: usize, to: usize, n: usize) {
    for c in 0..n {
        for l in 0..LANES {
            if batch.active & (1 << l) != 0 {
                batch.outputs[to + c][l] = batch.inputs[from + c][l];
            }
        }
    }
}

/// gl_Position = gl_Vertex; gl_FrontColor = gl_Color; gl_BackColor = gl_SecondaryColor.
fn pass_vs() -> Stage {
    Stage {
        iface: iface(
            vec![
                slot("gl_Vertex", 0, 4),
                slot("gl_Color", 4, 4),
                slot("gl_SecondaryColor", 8, 4),
            ],
            vec![
                slot("gl_Position", 0, 4),
                slot("gl_FrontColor", 4, 4),
                slot("gl_BackColor", 8, 4),
            ],
        ),
        f: Box::new(|b| {
            copy(b, 0, 0, 12);
            Ok(())
        }),
    }
}

/// gl_FragColor = gl_Color, reading nothing else ([`color_fs`]'s
/// gl_FragCoord would rule strips out).
fn strip_fs() -> Stage {
    Stage {
        iface: iface(
            vec![slot("gl_Color", 0, 4)],
            vec![slot("gl_FragColor", 0, 4)],
        ),
        f: Box::new(|b| {
            copy(b, 0, 0, 4);
            Ok(())
        }),
    }
}

/// gl_FragColor = gl_Color.
fn color_fs() -> Stage {
    Stage {
        iface: iface(
            vec![
                slot("gl_Color", 0, 4),
                slot("gl_FragCoord", 4, 4),
                slot("gl_FrontFacing", 8, 1),
            ],
            vec![slot("gl_FragColor", 0, 4)],
        ),
        f: Box::new(|b| {
            copy(b, 0, 0, 4);
            Ok(())
        }),
    }
}

/// gl_FragColor = gl_Color; gl_FragDepth = gl_FragCoord.z (forces late tests).
fn depth_writing_fs() -> Stage {
    Stage {
        iface: iface(
            vec![slot("gl_Color", 0, 4), slot("gl_FragCoord", 4, 4)],
            vec![slot("gl_FragColor", 0, 4), slot("gl_FragDepth", 4, 1)],
        ),
        f: Box::new(|b| {
            copy(b, 0, 0, 4);
            copy(b, 6, 4, 1);
            Ok(())
        }),
    }
}

#[derive(Clone, Default)]
struct Verts {
    pos: Vec<[f32; 4]>,
    color: Vec<[f32; 4]>,
    back: Vec<[f32; 4]>,
}

impl VertexFetch for Verts {
    fn fetch(&self, slot: usize, v: u32, out: &mut [f32; 4]) {
        let src = match slot {
            0 => &self.pos,
            1 => &self.color,
            _ => &self.back,
        };
        if let Some(p) = src.get(v as usize) {
            *out = *p;
        }
    }
}

fn verts(pos: &[[f32; 2]], color: &[[f32; 4]]) -> Verts {
    Verts {
        pos: pos.iter().map(|p| [p[0], p[1], 0.0, 1.0]).collect(),
        color: color.to_vec(),
        back: vec![[0.0, 0.0, 1.0, 1.0]; pos.len()],
    }
}

fn state(w: i32, h: i32) -> PipelineState {
    PipelineState {
        viewport: Rect::new(0, 0, w, h),
        ..PipelineState::default()
    }
}

fn run(
    fb: &mut Framebuffer,
    st: &PipelineState,
    fs: &Stage,
    mode: Mode,
    v: &Verts,
) -> Result<(), DrawError> {
    let idx: Vec<u32> = (0..v.pos.len() as u32).collect();
    draw_stages(
        &Workers::inline(),
        fb,
        st,
        (&pass_vs(), &[]),
        None,
        (fs, &[]),
        mode,
        &idx,
        v,
        &TextureUnits::default(),
    )
}

const RED: [f32; 4] = [1.0, 0.0, 0.0, 1.0];
const GREEN: [f32; 4] = [0.0, 1.0, 0.0, 1.0];
const BLUE: [f32; 4] = [0.0, 0.0, 1.0, 1.0];

fn full_screen() -> Vec<[f32; 2]> {
    vec![
        [-1.0, -1.0],
        [1.0, -1.0],
        [1.0, 1.0],
        [-1.0, -1.0],
        [1.0, 1.0],
        [-1.0, 1.0],
    ]
}

#[test]
fn two_triangles_cover_every_pixel_once_across_tiles() {
    // 130×70 spans several 64×64 tiles; additive blending exposes double writes.
    let (w, h) = (130, 70);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    let mut st = state(w as i32, h as i32);
    st.blend = Some(Blend {
        dst_rgb: BlendFactor::One,
        dst_alpha: BlendFactor::One,
        ..Blend::default()
    });
    let c = [0.25, 0.5, 0.0, 0.25];
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Triangles,
        &verts(&full_screen(), &[c; 6]),
    )
    .unwrap();
    let px = fb.read_pixels_u8(0, 0, 0, w, h);
    assert!(
        px.iter().all(|p| *p == [64, 128, 0, 64]),
        "{:?}",
        px.iter().find(|p| **p != [64, 128, 0, 64])
    );
}

#[test]
fn smooth_interpolation_across_the_screen() {
    let (w, h) = (16, 4);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba32F, false, false);
    let st = state(w as i32, h as i32);
    let c = [RED, GREEN, GREEN, RED, GREEN, RED];
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Triangles,
        &verts(&full_screen(), &c),
    )
    .unwrap();
    let px = fb.read_pixels(0, 0, 0, w, h);
    for y in 0..h as usize {
        for x in 0..w as usize {
            let want = (x as f32 + 0.5) / w as f32;
            let got = px[y * w as usize + x];
            assert!((got[1] - want).abs() < 1e-6, "{x},{y}: {got:?}");
            assert!((got[0] - (1.0 - want)).abs() < 1e-6);
        }
    }
}

#[test]
fn perspective_correct_varyings() {
    // A triangle whose right vertices are 3 times farther (w = 3): at the
    // horizontal middle of the screen the varying is not the linear mix.
    let (w, h) = (32, 32);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba32F, false, false);
    let st = state(w as i32, h as i32);
    let mut v = verts(
        &[[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0]],
        &[RED, GREEN, GREEN],
    );
    for p in &mut v.pos[1..] {
        *p = [p[0] * 3.0, p[1] * 3.0, 0.0, 3.0];
    }
    run(&mut fb, &st, &color_fs(), Mode::Triangles, &v).unwrap();
    // Pixel (x, 0): screen-space barycentric of vertex 0 is b0 = 1 - (x+0.5)/32 -
    // small; perspective weight = b0 / (b0 + (1 - b0)/3).
    let px = fb.read_pixels(0, 16, 0, 1, 1)[0];
    let b0 = 1.0 - 16.5 / 32.0;
    let red = b0 / (b0 + (1.0 - b0) / 3.0);
    assert!((px[0] - red).abs() < 1e-5, "{px:?} vs {red}");
}

#[test]
fn strips_give_the_bytes_of_quads() {
    // Tilted, perspective, blended triangles across tiles: rows of whole
    // quads go through strips; the bytes must be those of the quads one
    // by one, for every instruction set.
    let (w, h) = (150, 90);
    let mut v = verts(
        &[
            [-0.9, -0.95],
            [0.97, -0.6],
            [0.8, 0.93],
            [-0.9, -0.95],
            [0.8, 0.93],
            [-0.7, 0.6],
        ],
        &[RED, GREEN, BLUE, RED, BLUE, [0.3, 0.6, 0.9, 0.5]],
    );
    for (i, p) in v.pos.iter_mut().enumerate() {
        let w = 1.0 + 0.7 * i as f32;
        *p = [p[0] * w, p[1] * w, 0.25 * w, w];
    }
    let fs = strip_fs();
    let blended = Blend {
        src_rgb: BlendFactor::SrcAlpha,
        dst_rgb: BlendFactor::OneMinusSrcAlpha,
        ..Blend::default()
    };
    // A second pair of triangles crossing the first in depth, for the
    // depth-tested runs.
    let mut crossing = v.clone();
    for p in &mut crossing.pos {
        *p = [-p[1], p[0], 0.5 * p[3] - p[2], p[3]];
    }
    // Flat shading makes the colour a constant varying (which strips of
    // one primitive leave in place, and the other triangle's replace).
    for (blend, depth, flat) in [
        (None, false, false),
        (Some(blended), false, false),
        (None, true, false),
        (Some(blended), true, false),
        (Some(blended), false, true),
        (None, true, true),
    ] {
        let mut st = state(w as i32, h as i32);
        st.blend = blend;
        st.flat_shading = flat;
        if depth {
            st.depth_test = Some(CompareFunc::Less);
        }
        let draw = || {
            let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, depth, false);
            fb.clear_color(&[0], [0.2, 0.4, 0.6, 0.8], [true; 4], None);
            fb.clear_depth(1.0, true, None);
            run(&mut fb, &st, &fs, Mode::Triangles, &v).unwrap();
            if depth {
                run(&mut fb, &st, &fs, Mode::Triangles, &crossing).unwrap();
            }
            fb.read_pixels_u8(0, 0, 0, w, h)
        };
        for isa in crate::simd::Level::all_supported() {
            let (with, without) =
                crate::simd::with_level(isa, || (draw(), crate::shade::without_strips(draw)));
            assert_eq!(
                with, without,
                "{isa:?}, {blend:?}, depth {depth}, flat {flat}"
            );
            assert!(with.iter().filter(|p| **p != [51, 102, 153, 204]).count() > w as usize * 30);
        }
    }
}

/// gl_FragColor from gl_Color, every component of gl_FragCoord and
/// gl_FrontFacing: what strips give each lane of those must be what
/// quads give it.
fn pixel_inputs_fs() -> Stage {
    Stage {
        iface: iface(
            vec![
                slot("gl_Color", 0, 4),
                slot("gl_FragCoord", 4, 4),
                slot("gl_FrontFacing", 8, 1),
            ],
            vec![slot("gl_FragColor", 0, 4)],
        ),
        f: Box::new(|b| {
            for l in 0..LANES {
                let i = |c: usize| b.inputs[c][l];
                let mix =
                    (i(4) * 0.013 + i(5) * 0.007 + i(6) * 3.1 + i(7) * 0.7 + i(8) * 0.3).fract();
                for c in 0..4 {
                    b.outputs[c][l] = 0.5 * i(c) + 0.5 * mix;
                }
            }
            Ok(())
        }),
    }
}

#[test]
fn strips_give_pixel_inputs_of_quads() {
    // Perspective triangles facing both ways across tiles, read through
    // gl_FragCoord (x, y, window z, 1/w) and gl_FrontFacing: the bytes of
    // strips are those of quads, for every instruction set.
    let (w, h) = (150, 90);
    let mut v = verts(
        &[
            [-0.9, -0.95],
            [0.97, -0.6],
            [0.8, 0.93],
            [-0.9, -0.95],
            [-0.7, 0.6],
            [0.8, 0.93],
        ],
        &[RED, GREEN, BLUE, RED, BLUE, [0.3, 0.6, 0.9, 0.5]],
    );
    for (i, p) in v.pos.iter_mut().enumerate() {
        let w = 1.0 + 0.7 * i as f32;
        *p = [p[0] * w, p[1] * w, (0.1 * i as f32 - 0.2) * w, w];
    }
    let fs = pixel_inputs_fs();
    for depth in [false, true] {
        let mut st = state(w as i32, h as i32);
        if depth {
            st.depth_test = Some(CompareFunc::Less);
        }
        let draw = || {
            let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, depth, false);
            fb.clear_color(&[0], [0.2, 0.4, 0.6, 0.8], [true; 4], None);
            fb.clear_depth(1.0, true, None);
            run(&mut fb, &st, &fs, Mode::Triangles, &v).unwrap();
            fb.read_pixels_u8(0, 0, 0, w, h)
        };
        for isa in crate::simd::Level::all_supported() {
            let (with, without) =
                crate::simd::with_level(isa, || (draw(), crate::shade::without_strips(draw)));
            assert_eq!(with, without, "{isa:?}, depth {depth}");
            assert!(with.iter().filter(|p| **p != [51, 102, 153, 204]).count() > w as usize * 30);
        }
    }
}

#[test]
fn strips_of_consecutive_primitives_take_their_own_constants() {
    // Two flat-shaded triangles covering the whole framebuffer (a corner
    // of the viewport, four times its size: no clipping, no edge inside),
    // one after the other: every quad is whole, so the tile runs the
    // first one's strips, then the second one's, with no quad between to
    // refill the batch; the second's constant colour must replace the
    // first's.
    let (w, h) = (64, 64);
    let big = [[-1.0, -1.0], [1.0, -1.0], [-1.0, 1.0]];
    let colors = [
        RED,
        RED,
        [0.3, 0.6, 0.9, 0.5],
        GREEN,
        GREEN,
        [0.8, 0.1, 0.4, 0.25],
    ];
    let v = verts(&[big, big].concat(), &colors);
    let mut st = state(4 * w as i32, 4 * h as i32);
    st.flat_shading = true;
    st.blend = Some(Blend {
        src_rgb: BlendFactor::SrcAlpha,
        dst_rgb: BlendFactor::OneMinusSrcAlpha,
        ..Blend::default()
    });
    let draw = || {
        let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
        fb.clear_color(&[0], [0.2, 0.4, 0.6, 0.8], [true; 4], None);
        run(&mut fb, &st, &strip_fs(), Mode::Triangles, &v).unwrap();
        fb.read_pixels_u8(0, 0, 0, w, h)
    };
    for isa in crate::simd::Level::all_supported() {
        let (with, without) =
            crate::simd::with_level(isa, || (draw(), crate::shade::without_strips(draw)));
        assert_eq!(with, without, "{isa:?}");
        // Both layers are in every pixel: not the clear colour, nor the
        // first triangle's colour blended alone.
        assert!(with.iter().all(|p| *p == with[0]), "{:?}", with[0]);
    }
}

#[test]
fn flat_shading_uses_the_provoking_vertex() {
    let (w, h) = (8, 8);
    let mut st = state(w as i32, h as i32);
    st.flat_shading = true;
    // Triangles: last vertex.
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    let tri = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0]];
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Triangles,
        &verts(&tri, &[RED, GREEN, BLUE]),
    )
    .unwrap();
    assert_eq!(fb.read_pixels_u8(0, 6, 1, 1, 1)[0], [0, 0, 255, 255]);
    // GL_POLYGON: first vertex.
    let quad = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Polygon,
        &verts(&quad, &[GREEN, RED, RED, BLUE]),
    )
    .unwrap();
    assert!(fb
        .read_pixels_u8(0, 0, 0, w, h)
        .iter()
        .all(|p| *p == [0, 255, 0, 255]));
    // GL_QUADS: fourth vertex.
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Quads,
        &verts(&quad, &[GREEN, RED, RED, BLUE]),
    )
    .unwrap();
    assert!(fb
        .read_pixels_u8(0, 0, 0, w, h)
        .iter()
        .all(|p| *p == [0, 0, 255, 255]));
}

#[test]
fn culling_and_two_sided_color() {
    let (w, h) = (8, 8);
    // Clockwise in window space: back-facing with the default CCW front face.
    let cw = [[-1.0, -1.0], [1.0, 1.0], [1.0, -1.0]];
    let mut st = state(w as i32, h as i32);
    st.cull = Some(CullFace::Back);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Triangles,
        &verts(&cw, &[RED; 3]),
    )
    .unwrap();
    assert!(fb
        .read_pixels_u8(0, 0, 0, w, h)
        .iter()
        .all(|p| *p == [0; 4]));
    st.cull = Some(CullFace::Front);
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Triangles,
        &verts(&cw, &[RED; 3]),
    )
    .unwrap();
    assert_eq!(fb.read_pixels_u8(0, 6, 1, 1, 1)[0], [255, 0, 0, 255]);
    // Two-sided: the back color (blue) for the back face.
    st.cull = None;
    st.two_sided_color = true;
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Triangles,
        &verts(&cw, &[RED; 3]),
    )
    .unwrap();
    assert_eq!(fb.read_pixels_u8(0, 6, 1, 1, 1)[0], [0, 0, 255, 255]);
    // front_face = CW makes it front-facing again.
    st.front_face = FrontFace::Cw;
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Triangles,
        &verts(&cw, &[RED; 3]),
    )
    .unwrap();
    assert_eq!(fb.read_pixels_u8(0, 6, 1, 1, 1)[0], [255, 0, 0, 255]);
}

#[test]
fn gl_front_facing_input() {
    let fs = Stage {
        iface: iface(
            vec![slot("gl_FrontFacing", 0, 1)],
            vec![slot("gl_FragColor", 0, 4)],
        ),
        f: Box::new(|b| {
            for l in 0..LANES {
                b.outputs[0][l] = b.inputs[0][l];
                b.outputs[3][l] = 1.0;
            }
            Ok(())
        }),
    };
    let mut fb = Framebuffer::new(4, 4, ColorFormat::Rgba8, false, false);
    let st = state(4, 4);
    let cw = [[-1.0, -1.0], [1.0, 1.0], [1.0, -1.0]];
    run(&mut fb, &st, &fs, Mode::Triangles, &verts(&cw, &[RED; 3])).unwrap();
    assert_eq!(fb.read_pixels_u8(0, 3, 0, 1, 1)[0], [0, 0, 0, 255]);
    let ccw = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0]];
    run(&mut fb, &st, &fs, Mode::Triangles, &verts(&ccw, &[RED; 3])).unwrap();
    assert_eq!(fb.read_pixels_u8(0, 3, 0, 1, 1)[0], [255, 0, 0, 255]);
}

#[test]
fn triangle_through_the_near_plane_is_clipped_not_dropped() {
    let (w, h) = (16, 16);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, true, false);
    fb.clear_depth(1.0, true, None);
    let mut st = state(w as i32, h as i32);
    st.depth_test = Some(CompareFunc::Always);
    let mut v = verts(&[[-1.0, -1.0], [1.0, -1.0], [0.0, 1.0]], &[RED; 3]);
    v.pos[2] = [0.0, 1.0, -3.0, 1.0]; // behind the near plane
    run(&mut fb, &st, &color_fs(), Mode::Triangles, &v).unwrap();
    let px = fb.read_pixels_u8(0, 0, 0, w, h);
    let drawn = px.iter().filter(|p| **p == [255, 0, 0, 255]).count();
    // z_ndc = -3 (y + 1) / 2 reaches the near plane z = -1 at y_ndc = -1/3,
    // window y = 16/3: rows 0..=4 are covered.
    assert!(drawn > 0 && drawn < (w * h / 2) as usize, "{drawn}");
    assert_eq!(px[(4 * w + 8) as usize], [255, 0, 0, 255]);
    assert_eq!(px[(5 * w + 8) as usize], [0, 0, 0, 0]);
    // Depth near the cut edge is close to the near value 0.
    let d = fb.read_depth(8, 4, 1, 1)[0];
    assert!(d < 0.1, "{d}");
}

#[test]
fn early_depth_matches_late_depth() {
    let (w, h) = (16, 16);
    let mut st = state(w as i32, h as i32);
    st.depth_test = Some(CompareFunc::Less);
    st.stencil = Some(StencilState {
        front: StencilFace {
            depth_fail: StencilOp::Incr,
            depth_pass: StencilOp::Replace,
            reference: 7,
            ..StencilFace::default()
        },
        back: StencilFace::default(),
    });
    let mut results = Vec::new();
    for fs in [color_fs(), depth_writing_fs()] {
        let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, true, true);
        fb.clear_depth(1.0, true, None);
        // A slanted near triangle, then a full-screen quad at mid depth.
        let mut v = verts(&[[-1.0, -1.0], [1.0, -1.0], [0.0, 1.0]], &[RED; 3]);
        v.pos[0][2] = -0.5;
        v.pos[1][2] = 0.5;
        v.pos[2][2] = 0.9;
        run(&mut fb, &st, &fs, Mode::Triangles, &v).unwrap();
        let v = verts(&full_screen(), &[GREEN; 6]);
        run(&mut fb, &st, &fs, Mode::Triangles, &v).unwrap();
        results.push((
            fb.read_pixels_u8(0, 0, 0, w, h),
            fb.read_depth(0, 0, w, h),
            fb.read_stencil(0, 0, w, h),
        ));
    }
    assert_eq!(results[0], results[1]);
    let (color, _, stencil) = &results[0];
    assert!(color.contains(&[255, 0, 0, 255]) && color.contains(&[0, 255, 0, 255]));
    assert!(stencil.contains(&8), "depth-fail incremented");
}

#[test]
fn shader_errors_stop_the_draw() {
    let fs = Stage {
        iface: color_fs().iface,
        f: Box::new(|_| Err(ExecError::LoopBudget { iterations: 5 })),
    };
    let mut fb = Framebuffer::new(4, 4, ColorFormat::Rgba8, false, false);
    let err = run(
        &mut fb,
        &state(4, 4),
        &fs,
        Mode::Triangles,
        &verts(&full_screen(), &[RED; 6]),
    );
    assert!(matches!(
        err,
        Err(DrawError::Exec(ExecError::LoopBudget { iterations: 5 }))
    ));
}

/// Vertices no index names may run (every vertex of a small index range
/// does), but only a named vertex's failure stops the draw.
#[test]
fn only_named_vertices_fail_a_draw() {
    // The pass-through vertex stage, failing on a vertex at x = 99.
    let vs = Stage {
        iface: pass_vs().iface,
        f: Box::new(|b| {
            let bad = b.inputs[0]
                .iter()
                .enumerate()
                .any(|(l, &x)| b.active >> l & 1 == 1 && x == 99.0);
            if bad {
                return Err(ExecError::LoopBudget { iterations: 5 });
            }
            copy(b, 0, 0, 12);
            Ok(())
        }),
    };
    // Vertex 1 fails; 0, 2 and 3 cover the lower right half.
    let v = verts(
        &[[-1.0, -1.0], [99.0, 0.0], [1.0, -1.0], [1.0, 1.0]],
        &[RED; 4],
    );
    let draw = |indices: &[u32]| {
        let mut fb = Framebuffer::new(8, 8, ColorFormat::Rgba8, false, false);
        let r = draw_stages(
            &Workers::inline(),
            &mut fb,
            &state(8, 8),
            (&vs, &[]),
            None,
            (&color_fs(), &[]),
            Mode::Triangles,
            indices,
            &v,
            &TextureUnits::default(),
        );
        r.map(|()| fb.read_pixels_u8(0, 0, 0, 8, 8))
    };
    // Six indices over the range 0..=3: the whole range may run.
    let px = draw(&[0, 2, 3, 0, 2, 3]).expect("vertex 1 is not named");
    assert_eq!(px.iter().filter(|p| **p == [255, 0, 0, 255]).count(), 36);
    assert!(matches!(
        draw(&[0, 1, 2, 0, 2, 3]),
        Err(DrawError::Exec(ExecError::LoopBudget { iterations: 5 }))
    ));
}

#[test]
fn helper_lanes_are_run_but_not_written() {
    // A one-pixel triangle: its quad runs 4 lanes, only one is written.
    let seen = std::sync::Arc::new(std::sync::Mutex::new((0u32, 0u32)));
    let s2 = seen.clone();
    let fs = Stage {
        iface: color_fs().iface,
        f: Box::new(move |b| {
            *s2.lock().unwrap() = (b.active, b.helper);
            copy(b, 0, 0, 4);
            Ok(())
        }),
    };
    let mut fb = Framebuffer::new(8, 8, ColorFormat::Rgba8, false, false);
    // Covers only the center of pixel (2, 2) in an 8×8 viewport.
    let p = |x: f32, y: f32| [x / 4.0 - 1.0, y / 4.0 - 1.0];
    let tri = [p(2.2, 2.2), p(2.9, 2.2), p(2.2, 2.9)];
    run(
        &mut fb,
        &state(8, 8),
        &fs,
        Mode::Triangles,
        &verts(&tri, &[RED; 3]),
    )
    .unwrap();
    assert_eq!(*seen.lock().unwrap(), (0b1111, 0b1110));
    let px = fb.read_pixels_u8(0, 0, 0, 8, 8);
    assert_eq!(px.iter().filter(|p| **p != [0; 4]).count(), 1);
    assert_eq!(px[2 * 8 + 2], [255, 0, 0, 255]);
}

#[test]
fn points_lines_and_polygon_modes() {
    let (w, h) = (8, 8);
    let st = state(w as i32, h as i32);
    let p = |x: f32, y: f32| [x / 4.0 - 1.0, y / 4.0 - 1.0];
    let count = |fb: &Framebuffer| {
        fb.read_pixels_u8(0, 0, 0, w, h)
            .iter()
            .filter(|p| **p != [0; 4])
            .count()
    };
    // Points of size 1 and 3.
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Points,
        &verts(&[p(1.5, 1.5), p(5.5, 5.5)], &[RED; 2]),
    )
    .unwrap();
    assert_eq!(count(&fb), 2);
    let mut st3 = st.clone();
    st3.point_size = 3.0;
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    run(
        &mut fb,
        &st3,
        &color_fs(),
        Mode::Points,
        &verts(&[p(3.5, 3.5)], &[RED]),
    )
    .unwrap();
    assert_eq!(count(&fb), 9);
    // A point outside the view volume is dropped entirely.
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    run(
        &mut fb,
        &st3,
        &color_fs(),
        Mode::Points,
        &verts(&[[1.01, 0.0]], &[RED]),
    )
    .unwrap();
    assert_eq!(count(&fb), 0);
    // A horizontal line across the screen: 8 pixels.
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Lines,
        &verts(&[p(0.0, 3.5), p(8.0, 3.5)], &[RED; 2]),
    )
    .unwrap();
    assert_eq!(count(&fb), 8);
    // Line loop around a rectangle, as polygon mode LINE would draw it.
    let rect = [p(1.5, 1.5), p(6.5, 1.5), p(6.5, 6.5), p(1.5, 6.5)];
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::LineLoop,
        &verts(&rect, &[RED; 4]),
    )
    .unwrap();
    let loop_px = fb.read_pixels_u8(0, 0, 0, w, h);
    let mut stl = st.clone();
    stl.polygon_mode = [PolygonMode::Line; 2];
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    run(
        &mut fb,
        &stl,
        &color_fs(),
        Mode::Quads,
        &verts(&rect, &[RED; 4]),
    )
    .unwrap();
    assert_eq!(fb.read_pixels_u8(0, 0, 0, w, h), loop_px);
    assert_eq!(count(&fb), 20);
    // Polygon mode POINT: the four corners.
    stl.polygon_mode = [PolygonMode::Point; 2];
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    run(
        &mut fb,
        &stl,
        &color_fs(),
        Mode::Quads,
        &verts(&rect, &[RED; 4]),
    )
    .unwrap();
    assert_eq!(count(&fb), 4);
}

#[test]
fn user_clip_plane_against_position_when_no_clip_vertex() {
    let (w, h) = (8, 8);
    let mut st = state(w as i32, h as i32);
    st.clip_planes[0] = Some([1.0, 0.0, 0.0, 0.0]); // keep x >= 0
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Triangles,
        &verts(&full_screen(), &[RED; 6]),
    )
    .unwrap();
    let px = fb.read_pixels_u8(0, 0, 0, w, h);
    for y in 0..8 {
        for x in 0..8 {
            let lit = px[y * 8 + x] != [0; 4];
            assert_eq!(lit, x >= 4, "{x},{y}");
        }
    }
}

#[test]
fn scissor_and_multiple_draw_buffers() {
    let (w, h) = (8, 8);
    let fs = Stage {
        iface: iface(
            vec![slot("gl_Color", 0, 4)],
            vec![Slot {
                name: "gl_FragData".into(),
                ty: Type::new(Base::Vector(Scalar::Float, 4))
                    .array_of(glsl::types::ArraySize::Sized(2)),
                offset: 0,
                components: 8,
                written: true,
                location: None,
                index: None,
                interpolation: None,
                block: None,
            }],
        ),
        f: Box::new(|b| {
            copy(b, 0, 0, 4);
            for l in 0..LANES {
                b.outputs[4][l] = 0.0;
                b.outputs[5][l] = 0.0;
                b.outputs[6][l] = 1.0;
                b.outputs[7][l] = 1.0;
            }
            Ok(())
        }),
    };
    let mut fb = Framebuffer::with_color_buffers(
        w,
        h,
        &[ColorFormat::Rgba8, ColorFormat::Rgba32F],
        false,
        false,
    );
    let mut st = state(w as i32, h as i32);
    st.draw_buffers[1] = Some(1);
    st.scissor = Some(Rect::new(2, 2, 2, 3));
    run(
        &mut fb,
        &st,
        &fs,
        Mode::Triangles,
        &verts(&full_screen(), &[RED; 6]),
    )
    .unwrap();
    let a = fb.read_pixels_u8(0, 0, 0, w, h);
    let b = fb.read_pixels(1, 0, 0, w, h);
    assert_eq!(a.iter().filter(|p| **p == [255, 0, 0, 255]).count(), 6);
    assert_eq!(b.iter().filter(|p| **p == [0.0, 0.0, 1.0, 1.0]).count(), 6);
    assert_eq!(a[2 * 8 + 2], [255, 0, 0, 255]);
    assert_eq!(b[4 * 8 + 3], [0.0, 0.0, 1.0, 1.0]);
}

#[test]
fn polygon_offset_units_resolve_coplanar_depth() {
    let (w, h) = (8, 8);
    let mut st = state(w as i32, h as i32);
    st.depth_test = Some(CompareFunc::Always);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, true, false);
    fb.clear_depth(1.0, true, None);
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Triangles,
        &verts(&full_screen(), &[RED; 6]),
    )
    .unwrap();
    let base = fb.clone();
    // Coplanar with LESS: rejected.
    st.depth_test = Some(CompareFunc::Less);
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Triangles,
        &verts(&full_screen(), &[GREEN; 6]),
    )
    .unwrap();
    assert!(fb
        .read_pixels_u8(0, 0, 0, w, h)
        .iter()
        .all(|p| *p == [255, 0, 0, 255]));
    // Offset by one unit towards the viewer: accepted.
    let mut fb = base;
    st.polygon_offset = PolygonOffset {
        factor: 0.0,
        units: -1.0,
        fill: true,
        line: false,
        point: false,
    };
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::Triangles,
        &verts(&full_screen(), &[GREEN; 6]),
    )
    .unwrap();
    assert!(fb
        .read_pixels_u8(0, 0, 0, w, h)
        .iter()
        .all(|p| *p == [0, 255, 0, 255]));
}

#[test]
fn depth_is_not_written_without_the_depth_test() {
    // GL 2.1 §4.1.6: with the depth test disabled the depth buffer is not updated.
    let mut fb = Framebuffer::new(4, 4, ColorFormat::Rgba8, true, false);
    fb.clear_depth(1.0, true, None);
    run(
        &mut fb,
        &state(4, 4),
        &color_fs(),
        Mode::Triangles,
        &verts(&full_screen(), &[RED; 6]),
    )
    .unwrap();
    assert!(fb.read_depth(0, 0, 4, 4).iter().all(|&d| d == 1.0));
}

#[test]
fn point_sprite_coordinates() {
    let fs = Stage {
        iface: iface(
            vec![slot("gl_PointCoord", 0, 2), slot("gl_TexCoord", 2, 4)],
            vec![slot("gl_FragColor", 0, 4)],
        ),
        f: Box::new(|b| {
            for l in 0..LANES {
                b.outputs[0][l] = b.inputs[0][l];
                b.outputs[1][l] = b.inputs[1][l];
                b.outputs[2][l] = b.inputs[2][l];
                b.outputs[3][l] = b.inputs[5][l];
            }
            Ok(())
        }),
    };
    let mut st = state(8, 8);
    st.point_sprite = true;
    st.coord_replace = 1;
    st.point_size = 4.0;
    let mut fb = Framebuffer::new(8, 8, ColorFormat::Rgba32F, false, false);
    // Point at window (4, 4): covers pixels 2..6.
    run(
        &mut fb,
        &st,
        &fs,
        Mode::Points,
        &verts(&[[0.0, 0.0]], &[RED]),
    )
    .unwrap();
    let px = fb.read_pixels(0, 0, 0, 8, 8);
    // Pixel (2, 5): s = 0.5 + (2.5 - 4)/4 = 0.125; t (upper left) = 0.5 - (5.5 - 4)/4 = 0.125.
    assert_eq!(px[5 * 8 + 2], [0.125, 0.125, 0.125, 1.0]);
    assert_eq!(px[2 * 8 + 5], [0.875, 0.875, 0.875, 1.0]);
    assert_eq!(px[6 * 8 + 2], [0.0; 4]);
}

#[test]
fn wide_lines() {
    let mut st = state(8, 8);
    st.line_width = 3.0;
    let mut fb = Framebuffer::new(8, 8, ColorFormat::Rgba8, false, false);
    let p = |x: f32, y: f32| [x / 4.0 - 1.0, y / 4.0 - 1.0];
    run(
        &mut fb,
        &st,
        &color_fs(),
        Mode::LineStrip,
        &verts(&[p(0.0, 4.2), p(8.0, 4.2)], &[RED; 2]),
    )
    .unwrap();
    let px = fb.read_pixels_u8(0, 0, 0, 8, 8);
    for y in 0..8 {
        assert_eq!(px[y * 8 + 3] != [0; 4], (3..6).contains(&y), "row {y}");
    }
}

#[test]
fn garbage_geometry_does_not_panic() {
    let specials = [
        0.0,
        -0.0,
        1.0,
        -1.0,
        1e-30,
        -1e-30,
        1e30,
        -1e30,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        f32::MAX,
        f32::MIN_POSITIVE,
        0.5,
        3.0,
    ];
    let mut seed = 0x1234_5678u32;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        seed
    };
    let modes = [
        Mode::Points,
        Mode::Lines,
        Mode::LineStrip,
        Mode::LineLoop,
        Mode::Triangles,
        Mode::TriangleStrip,
        Mode::TriangleFan,
        Mode::Quads,
        Mode::QuadStrip,
        Mode::Polygon,
    ];
    for round in 0..200 {
        let n = (next() % 9) as usize;
        let mut v = Verts::default();
        for _ in 0..n {
            let mut p = [0.0f32; 4];
            for c in &mut p {
                *c = if next() % 3 == 0 {
                    specials[(next() as usize) % specials.len()]
                } else {
                    (next() % 2000) as f32 / 500.0 - 2.0
                };
            }
            v.pos.push(p);
            v.color.push([f32::NAN, 2.0, -1.0, 0.5]);
            v.back.push([0.0; 4]);
        }
        let mut st = state(
            [0, 7, -5, 1 << 30][round % 4],
            [0, 7, 1 << 30, i32::MAX][(round / 4) % 4],
        );
        st.viewport.x = [0, -3, i32::MIN, i32::MAX][(round / 16) % 4];
        st.point_size = specials[round % specials.len()];
        st.line_width = specials[(round + 3) % specials.len()];
        st.polygon_mode = [
            [PolygonMode::Fill; 2],
            [PolygonMode::Line; 2],
            [PolygonMode::Point; 2],
        ][round % 3];
        st.point_sprite = round % 2 == 0;
        st.depth_range = (0.0, 1.0);
        st.clip_planes[1] = Some([specials[round % 15], 1.0, 0.0, 0.5]);
        st.polygon_offset = PolygonOffset {
            factor: specials[(round + 5) % 15],
            units: 1.0,
            fill: true,
            line: true,
            point: true,
        };
        st.depth_test = Some(CompareFunc::Less);
        let mut fb = Framebuffer::new(9, 7, ColorFormat::Rgba8, true, true);
        let idx: Vec<u32> = (0..n as u32).chain([u32::MAX, 0]).collect();
        let _ = draw_stages(
            &Workers::new(1 + round % 3),
            &mut fb,
            &st,
            (&pass_vs(), &[]),
            None,
            (&color_fs(), &[]),
            modes[round % modes.len()],
            &idx,
            &v,
            &TextureUnits::default(),
        );
    }
}

#[test]
fn samples_passed_counts_depth_test_survivors_whatever_the_threads() {
    // 130×70 over several tiles: a full-screen quad at depth 0, then a
    // full-screen quad behind it: only its right half passes. The
    // count is exact whatever the thread count.
    let (w, h) = (130u32, 70u32);
    let mut counts = Vec::new();
    for threads in [1, 2, 3] {
        let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, true, false);
        let mut st = state(w as i32, h as i32);
        st.depth_test = Some(CompareFunc::Less);
        fb.clear_depth(1.0, true, None);
        let idx: Vec<u32> = (0..6).collect();
        let draw = |fb: &mut Framebuffer, st: &PipelineState, z: f32, x1: f32| {
            let pos: Vec<[f32; 2]> = full_screen()
                .iter()
                .map(|p| [if p[0] > 0.0 { x1 } else { -1.0 }, p[1]])
                .collect();
            let mut v = verts(&pos, &[RED; 6]);
            for p in &mut v.pos {
                p[2] = z;
            }
            draw_stages(
                &Workers::new(threads),
                fb,
                st,
                (&pass_vs(), &[]),
                None,
                (&color_fs(), &[]),
                Mode::Triangles,
                &idx,
                &v,
                &TextureUnits::default(),
            )
            .unwrap();
        };
        draw(&mut fb, &st, 0.0, 0.0); // left half, z = 0.5 in window space
        let first = fb.samples_passed;
        draw(&mut fb, &st, 0.5, 1.0); // whole screen behind: only the right half passes
        counts.push((first, fb.samples_passed - first));
    }
    assert_eq!(counts[0], (65 * 70, 65 * 70));
    assert!(counts.iter().all(|c| *c == counts[0]), "{counts:?}");
}

/// A stage that promises to complete ([`ShaderStage::always_completes`]),
/// so the draw queue keeps it waiting.
struct Completes(Stage);

impl ShaderStage for Completes {
    fn interface(&self) -> &Interface {
        self.0.interface()
    }
    fn run(&self, batch: &mut Batch, u: &[u32], t: &dyn Textures) -> Result<(), ExecError> {
        self.0.run(batch, u, t)
    }
    fn always_completes(&self) -> bool {
        true
    }
}

/// The draws of the queue tests: (state, whether the stage completes,
/// stage, vertices), several states and tiles, one of them a stage the
/// queue must not keep waiting.
fn queue_scene(w: u32, h: u32) -> Vec<(PipelineState, bool, Stage, Verts)> {
    let base = state(w as i32, h as i32);
    let blended = PipelineState {
        blend: Some(Blend {
            dst_rgb: BlendFactor::One,
            dst_alpha: BlendFactor::One,
            ..Blend::default()
        }),
        ..base.clone()
    };
    let depth = PipelineState {
        depth_test: Some(CompareFunc::Less),
        ..base.clone()
    };
    let mut slanted = verts(
        &[[-1.0, -1.0], [1.0, -0.6], [0.2, 1.0]],
        &[RED, GREEN, BLUE],
    );
    slanted.pos[0][2] = -0.5;
    slanted.pos[1][2] = 0.5;
    slanted.pos[2][2] = 0.1;
    let quarter = [0.25, 0.125, 0.0, 0.25];
    let small = verts(&[[0.1, 0.1], [0.6, 0.2], [0.3, 0.7]], &[BLUE; 3]);
    vec![
        (
            blended.clone(),
            true,
            color_fs(),
            verts(&full_screen(), &[quarter; 6]),
        ),
        (depth.clone(), true, depth_writing_fs(), slanted),
        (blended.clone(), true, strip_fs(), small.clone()),
        (base.clone(), false, color_fs(), small),
        (depth, true, color_fs(), verts(&full_screen(), &[GREEN; 6])),
        (
            blended,
            true,
            color_fs(),
            verts(&full_screen(), &[quarter; 6]),
        ),
    ]
}

/// Pushes `v` as triangles through [`pass_vs`] and `shader` (no uniforms
/// or textures) on `queue`.
fn push_triangles(
    queue: &mut crate::queue::DrawQueue,
    workers: &Workers,
    fb: &mut Framebuffer,
    st: &PipelineState,
    shader: std::sync::Arc<dyn ShaderStage + Send + Sync>,
    v: &Verts,
) {
    let fragments = crate::queue::QueuedFragments {
        shader,
        uniforms: Vec::new(),
        textures: TextureUnits::default(),
    };
    let idx: Vec<u32> = (0..v.pos.len() as u32).collect();
    let (vs, mode) = (pass_vs(), (Mode::Triangles, &idx[..]));
    queue
        .push(workers, fb, st, (&vs, &[]), None, fragments, mode, v)
        .unwrap();
}

#[test]
fn queued_draws_give_the_bytes_of_draws_one_after_another() {
    use crate::queue::DrawQueue;
    let (w, h) = (200, 130);
    let fresh = || {
        let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, true, false);
        fb.clear_depth(1.0, true, None);
        fb
    };
    let mut direct = fresh();
    for (st, _, fs, v) in queue_scene(w, h) {
        run(&mut direct, &st, &fs, Mode::Triangles, &v).unwrap();
    }
    let want = (
        direct.read_pixels_u8(0, 0, 0, w, h),
        direct.read_depth(0, 0, w, h),
    );
    for threads in [1, 2] {
        let workers = Workers::new(threads);
        let mut fb = fresh();
        let before = fb.read_pixels_u8(0, 0, 0, w, h);
        let mut queue = DrawQueue::default();
        let mut waiting = Vec::new();
        for (st, completes, fs, v) in queue_scene(w, h) {
            let shader: std::sync::Arc<dyn ShaderStage + Send + Sync> = if completes {
                std::sync::Arc::new(Completes(fs))
            } else {
                std::sync::Arc::new(fs)
            };
            push_triangles(&mut queue, &workers, &mut fb, &st, shader, &v);
            waiting.push(queue.len());
        }
        // Three wait, the stage that may fail flushes them and draws at
        // once, two more wait.
        assert_eq!(waiting, [1, 2, 3, 0, 1, 2], "{threads} threads");
        assert_ne!(fb.read_pixels_u8(0, 0, 0, w, h), before);
        queue.flush(&workers, &mut fb).unwrap();
        assert!(queue.is_empty());
        let got = (fb.read_pixels_u8(0, 0, 0, w, h), fb.read_depth(0, 0, w, h));
        assert!(got == want, "{threads} threads: the queue's bytes differ");
    }
}

#[test]
fn a_queue_is_not_flushed_into_a_framebuffer_of_another_size() {
    use crate::queue::DrawQueue;
    let workers = Workers::inline();
    let mut fb = Framebuffer::new(70, 70, ColorFormat::Rgba8, false, false);
    let mut queue = DrawQueue::default();
    let v = verts(&full_screen(), &[RED; 6]);
    let shader = std::sync::Arc::new(Completes(color_fs()));
    push_triangles(&mut queue, &workers, &mut fb, &state(70, 70), shader, &v);
    assert_eq!(queue.len(), 1);
    let mut other = Framebuffer::new(130, 70, ColorFormat::Rgba8, false, false);
    let r = queue.flush(&workers, &mut other);
    assert!(matches!(r, Err(DrawError::QueueTarget)), "{r:?}");
    assert!(queue.is_empty());
    assert!(other
        .read_pixels_u8(0, 0, 0, 130, 70)
        .iter()
        .all(|p| *p == [0, 0, 0, 0]));
}
