//! End to end: GLSL compiled and linked by `glsl`, lowered by `exec`, drawn
//! by `draw()`.

use std::sync::Arc;

use crate::ex::Kernel;
use crate::state::*;
use crate::texture::{Image, MagFilter, MinFilter, Texture, TextureTarget, TextureUnit};
use crate::texture_units::TextureUnits;
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
    let units = TextureUnits::new(vec![
        TextureUnit::default(),
        TextureUnit {
            tex_2d: Some(Arc::new(t)),
            ..TextureUnit::default()
        },
    ]);
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

/// Attributes by name for [`scene`]: `pos` (clip-space xyzw), `col`, `tc`;
/// drawn as `mode`'s primitives.
struct SceneAttribs {
    mode: Mode,
    names: Vec<String>,
    pos: Vec<[f32; 4]>,
    col: Vec<[f32; 4]>,
    tc: Vec<[f32; 4]>,
}

impl SceneAttribs {
    /// No vertices yet, for the inputs of vertex kernel `vs`.
    fn for_kernel(vs: &Kernel) -> SceneAttribs {
        SceneAttribs {
            mode: Mode::Triangles,
            names: vs
                .interface()
                .inputs
                .iter()
                .map(|s| s.name.clone())
                .collect(),
            pos: Vec::new(),
            col: Vec::new(),
            tc: Vec::new(),
        }
    }

    /// Draws every vertex of `self`, in order, as `self.mode`'s
    /// primitives through the stages `vs` and `fs` onto `fb`.
    fn draw(
        &self,
        workers: &crate::Workers,
        fb: &mut Framebuffer,
        state: &PipelineState,
        (vs, fs): (&Kernel, &dyn crate::ShaderStage),
        (fs_uniforms, units): (&[u32], &TextureUnits),
    ) -> Result<(), crate::DrawError> {
        let idx: Vec<u32> = (0..self.pos.len() as u32).collect();
        crate::draw_stages(
            workers,
            fb,
            state,
            (vs, &[]),
            None,
            (fs, fs_uniforms),
            self.mode,
            &idx,
            self,
            units,
        )
    }
}

/// The scenes' pseudo-random floats in [0, 1) from `seed` (a 32-bit
/// linear congruential generator, the C library's constants).
fn unit_floats(mut seed: u32) -> impl FnMut() -> f32 {
    move || {
        seed = seed.wrapping_mul(1103515245).wrapping_add(12345);
        (seed >> 8) as f32 / (1u32 << 24) as f32
    }
}

impl VertexFetch for SceneAttribs {
    fn fetch(&self, slot: usize, v: u32, out: &mut [f32; 4]) {
        let src = match self.names.get(slot).map(String::as_str) {
            Some("pos") => &self.pos,
            Some("col") => &self.col,
            Some("tc") => &self.tc,
            _ => return,
        };
        if let Some(value) = src.get(v as usize) {
            *out = *value;
        }
    }
}

/// Everything a scene leaves behind: color bytes, depth, stencil and the
/// draw errors as text.
type SceneResult = (Vec<[u8; 4]>, Vec<f32>, Vec<u8>, Vec<String>);

/// A scene over several tiles (200×150: partial tiles on two sides):
/// overlapping blended, depth-tested, stencil-counting triangles in
/// perspective; a mipmapped, trilinear-filtered textured quad; a shader
/// with derivatives and discard; and a draw stopped by the loop budget in
/// some tiles only.
fn scene(workers: &crate::Workers) -> SceneResult {
    // Native code from a kernel's 32nd batch on, compiled by that batch's
    // thread, so these short draws run it whatever the timing.
    crate::ex::set_native_after(32);
    let (w, h) = (200u32, 150u32);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, true, true);
    fb.clear_color(&[0], [0.1, 0.2, 0.3, 1.0], [true; 4], None);
    fb.clear_depth(1.0, true, None);
    let mut errors = Vec::new();
    let names = |k: &Kernel| SceneAttribs::for_kernel(k).names;
    let base = PipelineState {
        viewport: Rect::new(0, 0, w as i32, h as i32),
        ..PipelineState::default()
    };
    let draw_all = |fb: &mut Framebuffer,
                    st: &PipelineState,
                    (vs, fs): &(Kernel, Kernel),
                    fsu: &[u32],
                    fetch: &SceneAttribs,
                    units: &TextureUnits| {
        fetch
            .draw(workers, fb, st, (vs, fs), (fsu, units))
            .err()
            .map(|e| e.to_string())
    };
    let no_textures = TextureUnits::default();

    // 1. Blended, depth-tested triangles with a stencil count.
    let flat = program(
        "attribute vec4 pos; attribute vec4 col; varying vec4 c;\n\
         void main() { gl_Position = pos; c = col; }",
        "varying vec4 c; void main() { gl_FragColor = c; }",
    );
    let mut seed = 0x1234_5678u32;
    let mut rnd = move || {
        seed = crate::lcg_step(seed);
        (seed >> 8) as f32 / (1u32 << 24) as f32
    };
    let mut tris = SceneAttribs::for_kernel(&flat.0);
    for _ in 0..60 * 3 {
        let wc = 0.5 + 1.5 * rnd();
        let (x, y, z) = (rnd() * 2.4 - 1.2, rnd() * 2.4 - 1.2, rnd() * 2.0 - 1.0);
        tris.pos.push([x * wc, y * wc, z * wc, wc]);
        tris.col.push([rnd(), rnd(), rnd(), 0.3 + 0.6 * rnd()]);
    }
    let mut st = base.clone();
    st.depth_test = Some(CompareFunc::Less);
    st.blend = Some(Blend {
        src_rgb: BlendFactor::SrcAlpha,
        dst_rgb: BlendFactor::OneMinusSrcAlpha,
        src_alpha: BlendFactor::One,
        dst_alpha: BlendFactor::OneMinusSrcAlpha,
        ..Blend::default()
    });
    let count = StencilFace {
        depth_pass: StencilOp::Incr,
        depth_fail: StencilOp::Decr,
        ..StencilFace::default()
    };
    st.stencil = Some(StencilState {
        front: count,
        back: count,
    });
    errors.extend(draw_all(&mut fb, &st, &flat, &[], &tris, &no_textures));

    // 2. A textured quad in perspective, trilinear mipmapping.
    let textured = program(
        "attribute vec4 pos; attribute vec4 tc; varying vec2 t;\n\
         void main() { gl_Position = pos; t = tc.xy; }",
        "varying vec2 t; uniform sampler2D s;\n\
         void main() { gl_FragColor = texture2D(s, t) * vec4(1.0, 1.0, 1.0, 0.8); }",
    );
    let mut levels = Vec::new();
    let mut n = 16u32;
    loop {
        let texels = (0..n * n)
            .map(|i| {
                let (x, y) = (i % n, i / n);
                let on = ((x + y) % 2) as f32;
                [on, 1.0 - on, n as f32 / 16.0, 1.0]
            })
            .collect();
        levels.push(Image::new(n, n, 1, texels));
        if n == 1 {
            break;
        }
        n /= 2;
    }
    let mut tex = Texture::new(TextureTarget::Tex2D, levels);
    tex.min_filter = MinFilter::LinearMipmapLinear;
    tex.mag_filter = MagFilter::Linear;
    let units = TextureUnits::new(vec![TextureUnit {
        tex_2d: Some(Arc::new(tex)),
        ..TextureUnit::default()
    }]);
    let corners = [
        ([-0.9f32, -0.8], 0.4f32, [0.0f32, 0.0]),
        ([0.95, -0.9], 1.0, [6.0, 0.0]),
        ([0.8, 0.9], 3.0, [6.0, 6.0]),
        ([-0.7, 0.85], 1.5, [0.0, 6.0]),
    ];
    let mut quad = SceneAttribs::for_kernel(&textured.0);
    for i in [0, 1, 2, 0, 2, 3] {
        let (p, wc, t) = corners[i];
        quad.pos.push([p[0] * wc, p[1] * wc, 0.2 * wc, wc]);
        quad.tc.push([t[0], t[1], 0.0, 1.0]);
    }
    let mut st = base.clone();
    st.depth_test = Some(CompareFunc::LessEqual);
    st.blend = Some(Blend {
        src_rgb: BlendFactor::SrcAlpha,
        dst_rgb: BlendFactor::OneMinusSrcAlpha,
        ..Blend::default()
    });
    let fsu = words(&textured.1, &[("s", &[0])]);
    errors.extend(draw_all(&mut fb, &st, &textured, &fsu, &quad, &units));

    // 3. Derivatives and discard, additive blending, no depth test.
    let deriv = program(
        "attribute vec4 pos; attribute vec4 tc; varying vec2 t;\n\
         void main() { gl_Position = pos; t = tc.xy; }",
        "varying vec2 t;\n\
         void main() {\n\
           vec2 d = vec2(dFdx(t.x * t.y), dFdy(t.x * t.x));\n\
           if (fract(t.x * 7.0 + t.y * 3.0) < 0.3) discard;\n\
           gl_FragColor = vec4(abs(d) * 40.0, fwidth(t.x) * 50.0, 0.5);\n\
         }",
    );
    quad.names = names(&deriv.0);
    let mut st = base.clone();
    st.blend = Some(Blend {
        dst_rgb: BlendFactor::One,
        ..Blend::default()
    });
    errors.extend(draw_all(&mut fb, &st, &deriv, &[], &quad, &no_textures));

    // 4. A loop that exceeds the budget in the top-right tiles only.
    let mut looping = program(
        "attribute vec4 pos; void main() { gl_Position = pos; }",
        "void main() {\n\
           int n = gl_FragCoord.x > 150.0 && gl_FragCoord.y > 70.0 ? 100000 : 3;\n\
           float acc = 0.0;\n\
           for (int i = 0; i < n; i++) acc += 0.125;\n\
           gl_FragColor = vec4(acc, 0.0, 1.0, 1.0);\n\
         }",
    );
    looping.1.set_loop_budget(1000);
    let mut full = SceneAttribs::for_kernel(&looping.0);
    full.pos = QUAD.iter().map(|p| [p[0], p[1], 0.0, 1.0]).collect();
    errors.extend(draw_all(&mut fb, &base, &looping, &[], &full, &no_textures));

    (
        fb.read_pixels_u8(0, 0, 0, w, h),
        fb.read_depth(0, 0, w, h),
        fb.read_stencil(0, 0, w, h),
        errors,
    )
}

#[test]
fn images_are_identical_whatever_the_thread_count() {
    let one = scene(&crate::Workers::new(1));
    let (color, _, stencil, errors) = &one;
    // The scene is not trivial: the loop draw failed in tile (2, 1) (the
    // first in tile order), earlier tiles were completed, later ones kept
    // what the earlier draws left.
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert!(
        errors[0].contains("1000") || errors[0].contains("loop"),
        "{errors:?}"
    );
    let at = |x: usize, y: usize| color[y * 200 + x];
    assert_eq!(at(10, 10), [96, 0, 255, 255], "tile 0 ran the loop draw");
    assert_eq!(
        at(140, 66),
        [96, 0, 255, 255],
        "the failing tile wrote before the error"
    );
    assert_ne!(
        at(199, 149)[..3],
        [96, 0, 255],
        "tiles after the failure were not drawn"
    );
    assert!(stencil.iter().any(|&s| s >= 2), "triangles overlap");
    let distinct: std::collections::BTreeSet<[u8; 4]> = color.iter().copied().collect();
    assert!(distinct.len() > 500, "{} colors", distinct.len());
    for threads in [2, 4] {
        let many = scene(&crate::Workers::new(threads));
        assert!(one.0 == many.0, "color differs with {threads} threads");
        assert!(one.1 == many.1, "depth differs with {threads} threads");
        assert!(one.2 == many.2, "stencil differs with {threads} threads");
        assert_eq!(one.3, many.3, "errors differ with {threads} threads");
    }
}

/// The probe's view of a pixel where two triangles overlap agrees with the
/// real draw: both fragments, the depth test of the second, the stored
/// result; a discarded fragment names the discard.
#[test]
fn probe_reports_every_fragment_of_a_pixel() {
    use crate::{probe_draw, Event, ProbeRequest};
    let (vs, fs) = program(
        "attribute vec4 pos; attribute vec4 col;\n\
         void main() { gl_Position = vec4(pos.xy, col.a, 1.0); gl_FrontColor = col; }",
        "void main() {\n\
           if (gl_Color.r > 0.9 && gl_FragCoord.x < 2.0) discard;\n\
           gl_FragColor = gl_Color;\n\
         }",
    );
    let (w, h) = (8, 8);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, true, false);
    if let Some(d) = fb.depth.as_mut() {
        d.fill(crate::DEPTH_MAX);
    }
    let state = PipelineState {
        viewport: Rect::new(0, 0, w as i32, h as i32),
        depth_test: Some(CompareFunc::Less),
        ..PipelineState::default()
    };
    // Two full-screen quads: red at z = 0.5 (window 0.75), then green
    // nearer (z = -0.5, window 0.25).
    let pos: Vec<[f32; 2]> = QUAD.iter().chain(QUAD.iter()).copied().collect();
    let mut col = vec![[1.0, 0.0, 0.0, 0.5]; 6];
    col.extend([[0.0, 1.0, 0.0, -0.5]; 6]);
    let fetch = Attribs {
        names: vs
            .interface()
            .inputs
            .iter()
            .map(|s| s.name.clone())
            .collect(),
        pos: &pos,
        col: &col,
    };
    let indices: Vec<u32> = (0..12).collect();
    let units = TextureUnits::default();
    let before = fb.clone();
    let probe = |x: u32, y: u32| {
        let replay = crate::Replay {
            state: &state,
            vs: &vs,
            vs_uniforms: &[],
            gs: None,
            fs: &fs,
            fs_uniforms: &[],
            mode: Mode::Triangles,
            indices: &indices,
            fetch: &fetch,
            textures: &units,
            layer: None,
        };
        probe_draw(
            &before,
            &replay,
            ProbeRequest {
                vertex: Some(7),
                outlines: true,
                ..ProbeRequest::pixel(x, y)
            },
        )
    };
    draw(
        &mut fb,
        &state,
        &vs,
        &[],
        &fs,
        &[],
        Mode::Triangles,
        &indices,
        &fetch,
        &units,
    )
    .expect("draw");
    let at = |x: u32, y: u32| match &fb.color[0] {
        crate::ColorBuffer::Rgba8(v) => v[(y * w + x) as usize],
        _ => unreachable!(),
    };

    let p = probe(5, 5);
    assert_eq!(p.after.color_bytes[0], Some(at(5, 5)));
    assert_eq!(p.fragments.len(), 2, "{p:#?}");
    let (red, green) = (&p.fragments[0], &p.fragments[1]);
    assert_eq!(red.primitive / 2, 0);
    assert_eq!(green.primitive / 2, 1);
    let ops = green.ops.as_ref().expect("ops");
    assert_eq!(ops.depth_test, Some(true));
    assert_eq!(
        ops.before.depth,
        red.ops.as_ref().and_then(|o| o.after.depth)
    );
    assert!(ops.after.depth < ops.before.depth);
    assert!(red.events.iter().any(|e| matches!(e, Event::Statement(_))));
    assert_eq!(p.primitives.len(), 4);
    assert_eq!(p.vertex_outputs.len(), 12);
    // No geometry stage: no emitted vertices, no invocations.
    assert!(p.emitted_by.is_empty() && p.geometry.is_empty());
    // The traced vertex gives the outputs the draw used; every triangle
    // has an outline.
    let v = p.vertex.as_ref().expect("vertex trace");
    assert_eq!(v.index, 7);
    // (The trace has the shader's own outputs; the draw clamps colours.)
    assert_eq!(v.outputs[..4], p.vertex_outputs[7][..4]);
    assert_eq!(v.outputs[7], -0.5);
    assert_eq!(p.vertex_outputs[7][7], 0.0);
    assert!(v.events.iter().any(|e| matches!(e, Event::Store { .. })));
    assert_eq!(p.outlines.len(), 4);
    assert!(p.outlines.iter().all(|o| o.len() == 3));

    // At x < 2 the red fragment is discarded; the trace shows it.
    let p = probe(1, 5);
    assert_eq!(p.after.color_bytes[0], Some(at(1, 5)));
    assert!(p.fragments[0].discarded);
    assert!(p.fragments[0].ops.is_none());
    assert!(!p.fragments[1].discarded);

    // Outside the framebuffer: a reason, no fragments.
    let p = probe(8, 0);
    assert!(p.unreachable.is_some() && p.fragments.is_empty());
}

/// A fragment stage that hides its depth-only slice, so the pipeline
/// takes the straightforward path (every fragment fully shaded).
struct Straightforward<'a>(&'a Kernel);

impl crate::ShaderStage for Straightforward<'_> {
    fn interface(&self) -> &crate::ex::Interface {
        self.0.interface()
    }
    fn run(
        &self,
        batch: &mut crate::ex::Batch,
        uniforms: &[u32],
        textures: &dyn crate::ex::Textures,
    ) -> Result<(), crate::ex::ExecError> {
        self.0.run(batch, uniforms, textures)
    }
    fn reads_input(&self, c: usize) -> bool {
        crate::ex::Kernel::reads_input(self.0, c)
    }
}

/// Overlapping sphere impostors (quads whose fragment shader ray-casts a
/// sphere, writes gl_FragDepth and uses derivatives) over several tiles,
/// drawn with `fs` as given (colors only for visible fragments) or
/// through [`Straightforward`]; returns color and depth bytes and the
/// samples that passed the depth test (an occlusion query's count).
fn impostors(
    workers: &crate::Workers,
    discard: bool,
    deferred: bool,
    spheres: usize,
    state_change: impl Fn(&mut PipelineState),
) -> (Vec<[u8; 4]>, Vec<f32>, u64) {
    let scene = Impostors {
        discard,
        deferred,
        spheres,
        ..Impostors::default()
    };
    scene.draw(workers, state_change)
}

/// The scenes of [`impostors`].
#[derive(Clone, Copy)]
struct Impostors {
    discard: bool,
    deferred: bool,
    spheres: usize,
    /// The colours computed with derivatives, or without (then every lane
    /// of the shader is independent of the others and the pipeline packs
    /// the covered pixels of several quads into a batch).
    quad_ops: bool,
    /// Each sphere one GL quad (a polygon set up as the two triangles of
    /// its fan) instead of two triangles.
    quads: bool,
    /// Each sphere drawn twice, the second time in another colour at the
    /// same depths: every fragment of it ties with the first's.
    twice: bool,
    clear_depth: f32,
}

impl Default for Impostors {
    fn default() -> Impostors {
        Impostors {
            discard: true,
            deferred: true,
            spheres: 60,
            quad_ops: true,
            quads: false,
            twice: false,
            clear_depth: 1.0,
        }
    }
}

impl Impostors {
    fn draw(
        self,
        workers: &crate::Workers,
        state_change: impl Fn(&mut PipelineState),
    ) -> (Vec<[u8; 4]>, Vec<f32>, u64) {
        let Impostors {
            discard,
            deferred,
            spheres,
            quad_ops,
            quads,
            twice,
            clear_depth,
        } = self;
        // Native code from a kernel's 32nd batch on, compiled by that batch's
        // thread, so these short draws run it whatever the timing.
        crate::ex::set_native_after(32);
        let (vs, fs) = program(
            "attribute vec4 pos; attribute vec4 sph; varying vec4 s;\n\
             void main() { gl_Position = pos; s = sph; }",
            &format!(
                "varying vec4 s; uniform float budget;\n\
                 void main() {{\n\
                   float q = 1.0 - dot(s.xy, s.xy);\n\
                   if (q < 0.0) {{ {} }}\n\
                   float h = sqrt(q);\n\
                   gl_FragDepth = s.z - 0.25 * h;\n\
                   float acc = 0.0;\n\
                   for (int i = 0; i < 4; i++) acc += 0.1 * h;\n\
                   vec3 n = vec3(s.xy, h) * 0.5 + 0.5;\n\
                   gl_FragColor = vec4(n * s.w + vec3({}, acc) * 2.0, 1.0);\n\
                 }}",
                if discard { "discard;" } else { "q = 0.0;" },
                if quad_ops {
                    "dFdx(h), dFdy(h)"
                } else {
                    "h * 0.5, fract(gl_FragCoord.x * 0.01 + gl_FragCoord.y * 0.003)"
                }
            ),
        );
        assert!(fs.depth_only().is_some(), "the shader has a depth slice");
        assert_eq!(fs.lanes_independent(), !quad_ops);
        assert!(fs.depth_only().is_some_and(|d| d.lanes_independent()));
        let (w, h) = (150u32, 130u32);
        let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, true, false);
        fb.clear_color(&[0], [0.1, 0.2, 0.3, 1.0], [true; 4], None);
        fb.clear_depth(clear_depth, true, None);
        let mut state = PipelineState {
            viewport: Rect::new(0, 0, w as i32, h as i32),
            depth_test: Some(CompareFunc::Less),
            ..PipelineState::default()
        };
        state_change(&mut state);
        let mut attribs = SceneAttribs::for_kernel(&vs);
        if quads {
            attribs.mode = Mode::Quads;
        }
        // Spheres on a pseudo-random walk, radii 0.05..0.3 (clip units),
        // depths interleaved so later ones are sometimes behind.
        let mut rnd = unit_floats(12345);
        for _ in 0..spheres {
            let (cx, cy, r, z, shade) = (
                rnd() * 2.2 - 1.1,
                rnd() * 2.2 - 1.1,
                0.05 + 0.25 * rnd(),
                0.3 + 0.5 * rnd(),
                0.4 + 0.6 * rnd(),
            );
            let corners: &[(f32, f32)] = match quads {
                true => &[(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)],
                false => &[
                    (-1.0, -1.0),
                    (1.0, -1.0),
                    (1.0, 1.0),
                    (-1.0, -1.0),
                    (1.0, 1.0),
                    (-1.0, 1.0),
                ],
            };
            for copy in 0..1 + twice as usize {
                let shade = [shade, 1.0 - 0.5 * shade][copy];
                for &(dx, dy) in corners {
                    attribs.pos.push([cx + dx * r, cy + dy * r, 0.0, 1.0]);
                    // SceneAttribs' `col` slot carries `sph`.
                    attribs.col.push([dx, dy, z, shade]);
                }
            }
        }
        attribs.names = attribs
            .names
            .iter()
            .map(|n| {
                if n == "sph" {
                    "col".to_string()
                } else {
                    n.clone()
                }
            })
            .collect();
        let straight = Straightforward(&fs);
        let fs_stage: &dyn crate::ShaderStage = if deferred { &fs } else { &straight };
        let units = TextureUnits::default();
        attribs
            .draw(workers, &mut fb, &state, (&vs, fs_stage), (&[], &units))
            .unwrap();
        (
            fb.read_pixels_u8(0, 0, 0, w, h),
            fb.read_depth(0, 0, w, h),
            fb.samples_passed,
        )
    }
}

#[test]
fn colors_for_visible_fragments_only_give_the_same_bytes() {
    for discard in [true, false] {
        let want = impostors(&crate::Workers::new(1), discard, false, 60, |_| {});
        let distinct: std::collections::BTreeSet<[u8; 4]> = want.0.iter().copied().collect();
        assert!(distinct.len() > 300, "{} colors", distinct.len());
        for threads in [1, 2] {
            let got = impostors(&crate::Workers::new(threads), discard, true, 60, |_| {});
            assert!(
                want.0 == got.0,
                "color, discard {discard}, {threads} threads"
            );
            assert!(
                want.1 == got.1,
                "depth, discard {discard}, {threads} threads"
            );
            // The depth-only pass and the colour pass count each passing
            // fragment once, as the straightforward path does.
            assert_eq!(
                want.2, got.2,
                "samples passed, discard {discard}, {threads} threads"
            );
        }
        assert!(want.2 > 0);
    }
    // Other depth functions, no depth writes, no depth test, color masks:
    // the last fragment to pass still decides the pixel.
    let changes: [fn(&mut PipelineState); 4] = [
        |s| s.depth_test = Some(CompareFunc::GreaterEqual),
        |s| s.depth_mask = false,
        |s| s.depth_test = None,
        |s| s.color_mask = [true, false, true, false],
    ];
    for change in changes {
        let want = impostors(&crate::Workers::new(1), true, false, 60, change);
        let got = impostors(&crate::Workers::new(2), true, true, 60, change);
        assert!(want == got);
    }
}

#[test]
fn packed_batches_give_the_same_bytes() {
    // Neither the slice nor the colours use derivatives: both passes run
    // the covered pixels of several quads per batch, no helper lanes.
    for discard in [true, false] {
        let scene = |deferred| Impostors {
            discard,
            deferred,
            spheres: 200,
            quad_ops: false,
            ..Impostors::default()
        };
        let want = scene(false).draw(&crate::Workers::new(1), |_| {});
        for threads in [1, 2] {
            let got = scene(true).draw(&crate::Workers::new(threads), |_| {});
            assert!(want == got, "discard {discard}, {threads} threads");
        }
    }
}

/// The counts of [`crate::shade::BOUND_USES`].
fn bound_uses() -> [u64; 3] {
    crate::shade::BOUND_USES
        .each_ref()
        .map(|u| u.load(std::sync::atomic::Ordering::Relaxed))
}

#[test]
fn depth_bounds_of_crowded_quads_give_the_same_bytes() {
    // 600 GL quads over 150×130 pixels: many lie behind spheres drawn
    // before them, so the depth pass finds their bounds (one for a
    // quad's two triangles) and drops whole primitives at them. LEQUAL
    // too (its bound must not reject a tie).
    let scene = |deferred| Impostors {
        deferred,
        spheres: 600,
        quad_ops: false,
        quads: true,
        ..Impostors::default()
    };
    let before = bound_uses();
    for func in [CompareFunc::Less, CompareFunc::LessEqual] {
        let change = |s: &mut PipelineState| s.depth_test = Some(func);
        let want = scene(false).draw(&crate::Workers::new(1), change);
        for threads in [1, 2] {
            let got = scene(true).draw(&crate::Workers::new(threads), change);
            assert!(want == got, "{func:?}, {threads} threads");
        }
    }
    let after = bound_uses();
    assert!(after[0] > before[0], "no primitive hidden whole");
    assert!(
        after[1] > before[1],
        "no bound found for a quad's two triangles"
    );
}

#[test]
fn primitives_out_of_draw_order_give_the_same_bytes() {
    // No samples counted: crowded tiles take their primitives near ones
    // first. Each sphere is drawn twice at the same depths, so every
    // fragment of the second ties with the first's, which the depth
    // function keeps or replaces as in draw order.
    let before = bound_uses();
    for (func, clear) in [
        (CompareFunc::Less, 1.0),
        (CompareFunc::LessEqual, 1.0),
        (CompareFunc::Greater, 0.0),
        (CompareFunc::GreaterEqual, 0.0),
    ] {
        let scene = |deferred| Impostors {
            deferred,
            spheres: 400,
            quad_ops: false,
            quads: true,
            twice: true,
            clear_depth: clear,
            ..Impostors::default()
        };
        let change = |s: &mut PipelineState| {
            s.depth_test = Some(func);
            s.count_samples = false;
        };
        let want = scene(false).draw(&crate::Workers::new(1), change);
        let distinct: std::collections::BTreeSet<[u8; 4]> = want.0.iter().copied().collect();
        assert!(distinct.len() > 300, "{func:?}: {} colors", distinct.len());
        for threads in [1, 2] {
            let got = scene(true).draw(&crate::Workers::new(threads), change);
            assert!(want.0 == got.0, "colour, {func:?}, {threads} threads");
            assert!(want.1 == got.1, "depth, {func:?}, {threads} threads");
        }
    }
    let after = bound_uses();
    assert!(
        after[2] > before[2],
        "no tile took its primitives near first"
    );
}

#[test]
fn many_primitives_give_the_same_bytes_for_any_thread_count() {
    // 2,200 triangles: two primitive set-up chunks, many vertex tasks.
    let one = impostors(&crate::Workers::new(1), true, true, 1100, |_| {});
    let straight = impostors(&crate::Workers::new(1), true, false, 1100, |_| {});
    assert!(one == straight);
    for threads in [2, 3] {
        let many = impostors(&crate::Workers::new(threads), true, true, 1100, |_| {});
        assert!(one == many, "{threads} threads");
    }
}

/// Small overlapping, blended, depth-tested triangles (most cover a few
/// pixels of one quad) with derivatives in the shader. With a stencil
/// test that changes nothing (ALWAYS, KEEP) every primitive is shaded on
/// its own; without, quads of consecutive primitives share batches.
fn small_triangles(
    workers: &crate::Workers,
    stencil_noop: bool,
    func: CompareFunc,
    state_change: impl Fn(&mut PipelineState),
) -> SceneResult {
    small_triangles_with(workers, stencil_noop, func, state_change, false)
}

/// A fragment stage without gl_FragDepth, discard or loops, offering a
/// depth-only slice that does nothing (what such a slice computes), so
/// that the pipeline shades colours for the visible fragments only.
struct EmptySlice<'a>(&'a Kernel, crate::ex::Interface);

impl crate::ShaderStage for EmptySlice<'_> {
    fn interface(&self) -> &crate::ex::Interface {
        &self.1
    }
    fn run(
        &self,
        batch: &mut crate::ex::Batch,
        uniforms: &[u32],
        textures: &dyn crate::ex::Textures,
    ) -> Result<(), crate::ex::ExecError> {
        self.0.run(batch, uniforms, textures)
    }
    fn depth_only(&self) -> Option<Box<dyn crate::ShaderStage>> {
        struct Nothing(crate::ex::Interface);
        impl crate::ShaderStage for Nothing {
            fn interface(&self) -> &crate::ex::Interface {
                &self.0
            }
            fn run(
                &self,
                _: &mut crate::ex::Batch,
                _: &[u32],
                _: &dyn crate::ex::Textures,
            ) -> Result<(), crate::ex::ExecError> {
                Ok(())
            }
            fn does_nothing(&self) -> bool {
                true
            }
        }
        let mut iface = self.1.clone();
        for slot in &mut iface.inputs {
            slot.written = false;
        }
        Some(Box::new(Nothing(iface)))
    }
}

/// [`small_triangles`], through [`EmptySlice`] when `slice`.
fn small_triangles_with(
    workers: &crate::Workers,
    stencil_noop: bool,
    func: CompareFunc,
    state_change: impl Fn(&mut PipelineState),
    slice: bool,
) -> SceneResult {
    // Native code from a kernel's 32nd batch on, compiled by that batch's
    // thread, so these short draws run it whatever the timing.
    crate::ex::set_native_after(32);
    let (vs, fs) = program(
        "attribute vec4 pos; attribute vec4 col; varying vec4 v;\n\
         void main() { gl_Position = pos; v = col; }",
        "varying vec4 v;\n\
         void main() { gl_FragColor = v + vec4(dFdx(v.r), dFdy(v.g), 0.0, 0.0) * 8.0; }",
    );
    let (w, h) = (140u32, 100u32);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, true, true);
    fb.clear_color(&[0], [0.1, 0.2, 0.3, 1.0], [true; 4], None);
    let far = match func {
        CompareFunc::Greater | CompareFunc::GreaterEqual => 0.0,
        _ => 1.0,
    };
    fb.clear_depth(far, true, None);
    let mut state = PipelineState {
        viewport: Rect::new(0, 0, w as i32, h as i32),
        depth_test: Some(func),
        blend: Some(Blend {
            src_rgb: BlendFactor::SrcAlpha,
            dst_rgb: BlendFactor::OneMinusSrcAlpha,
            ..Blend::default()
        }),
        stencil: stencil_noop.then(StencilState::default),
        ..PipelineState::default()
    };
    state_change(&mut state);
    let mut rnd = unit_floats(777);
    let mut attribs = SceneAttribs::for_kernel(&vs);
    for _ in 0..2500 {
        let (x, y, z) = (rnd() * 2.0 - 1.0, rnd() * 2.0 - 1.0, rnd() * 2.0 - 1.0);
        let s = 0.01 + 0.08 * rnd() * rnd();
        let c = [rnd(), rnd(), rnd(), 0.3 + 0.7 * rnd()];
        for (dx, dy) in [(0.0, 0.0), (s, 0.2 * s), (0.3 * s, s)] {
            attribs.pos.push([x + dx, y + dy, z, 1.0]);
            attribs.col.push(c);
        }
    }
    let wrapped = EmptySlice(&fs, fs.interface().clone());
    let fs: &dyn crate::ShaderStage = if slice { &wrapped } else { &fs };
    let units = TextureUnits::default();
    let r = attribs.draw(workers, &mut fb, &state, (&vs, fs), (&[], &units));
    (
        fb.read_pixels_u8(0, 0, 0, w, h),
        fb.read_depth(0, 0, w, h),
        fb.read_stencil(0, 0, w, h),
        r.err().map(|e| e.to_string()).into_iter().collect(),
    )
}

#[test]
fn primitives_sharing_batches_give_the_same_bytes() {
    for func in [
        CompareFunc::Less,
        CompareFunc::GreaterEqual,
        CompareFunc::Always,
    ] {
        let want = small_triangles(&crate::Workers::new(1), true, func, |_| {});
        let distinct: std::collections::BTreeSet<[u8; 4]> = want.0.iter().copied().collect();
        assert!(distinct.len() > 300, "{} colors", distinct.len());
        for threads in [1, 2] {
            let got = small_triangles(&crate::Workers::new(threads), false, func, |_| {});
            assert!(want == got, "{func:?}, {threads} threads");
        }
    }
    // Other blends, no blending, no depth writes, the scissor test and a
    // colour mask (the general colour write), each against one primitive
    // at a time through the general per-fragment operations.
    fn blend(src: BlendFactor, dst: BlendFactor) -> Option<Blend> {
        Some(Blend {
            src_rgb: src,
            dst_rgb: dst,
            src_alpha: src,
            dst_alpha: dst,
            ..Blend::default()
        })
    }
    use BlendFactor::*;
    let changes: [fn(&mut PipelineState); 10] = [
        |s| s.blend = None,
        |s| s.blend = blend(One, Zero),
        |s| s.blend = blend(One, One),
        |s| s.blend = blend(DstColor, OneMinusSrcColor),
        |s| s.depth_mask = false,
        |s| s.scissor = Some(Rect::new(17, 9, 90, 70)),
        |s| s.color_mask = [true, false, true, true],
        |s| {
            s.blend = None;
            s.depth_test = None;
        },
        // The opaque whole-quad writes under other depth states.
        |s| {
            s.blend = None;
            s.depth_test = Some(CompareFunc::LessEqual);
        },
        |s| {
            s.blend = None;
            s.depth_mask = false;
        },
    ];
    for (i, change) in changes.iter().enumerate() {
        let want = small_triangles(&crate::Workers::new(1), true, CompareFunc::Less, change);
        for threads in [1, 2, 4] {
            let got = small_triangles(
                &crate::Workers::new(threads),
                false,
                CompareFunc::Less,
                change,
            );
            assert!(want == got, "change {i}, {threads} threads");
        }
    }
}

#[test]
fn colours_of_visible_fragments_only_without_frag_depth_give_the_same_bytes() {
    // No gl_FragDepth: the forward path rejects early (the rejected lanes
    // of a quad become helpers); shading only the visible fragments must
    // give the same bytes, derivatives included.
    let opaque: [fn(&mut PipelineState); 3] = [
        |s| s.blend = None,
        |s| {
            s.blend = None;
            s.depth_mask = false;
        },
        |s| {
            s.blend = None;
            s.scissor = Some(Rect::new(17, 9, 90, 70));
        },
    ];
    for func in [
        CompareFunc::Less,
        CompareFunc::GreaterEqual,
        CompareFunc::Always,
    ] {
        for (i, change) in opaque.iter().enumerate() {
            let want = small_triangles(&crate::Workers::new(1), false, func, change);
            let distinct: std::collections::BTreeSet<[u8; 4]> = want.0.iter().copied().collect();
            assert!(distinct.len() > 300, "{} colors", distinct.len());
            for threads in [1, 2] {
                let got =
                    small_triangles_with(&crate::Workers::new(threads), false, func, change, true);
                assert!(want == got, "{func:?}, change {i}, {threads} threads");
            }
        }
    }
}

#[test]
fn instruction_set_variants_give_the_same_bytes() {
    use crate::simd::{with_level, Level};
    let one = || crate::Workers::new(1);
    let base = with_level(Level::Portable, || {
        (
            small_triangles(&one(), false, CompareFunc::Less, |_| {}),
            impostors(&one(), true, true, 200, |_| {}),
            scene(&one()),
        )
    });
    for isa in Level::all_supported() {
        let got = with_level(isa, || {
            (
                small_triangles(&one(), false, CompareFunc::Less, |_| {}),
                impostors(&one(), true, true, 200, |_| {}),
                scene(&one()),
            )
        });
        assert!(base.0 == got.0, "small triangles, {isa:?}");
        assert!(base.1 == got.1, "impostors, {isa:?}");
        assert!(base.2 == got.2, "scene, {isa:?}");
    }
}

#[test]
fn draws_reusing_an_earlier_draws_buffers_give_the_same_bytes() {
    for threads in [1, 2] {
        let workers = crate::Workers::new(threads);
        let fresh = small_triangles(
            &crate::Workers::new(threads),
            false,
            CompareFunc::Less,
            |_| {},
        );
        // Bigger draws first, then smaller ones, on the same workers.
        let _ = impostors(&workers, true, true, 1100, |_| {});
        assert!(workers.spare().chunks.len() >= 2);
        let again = small_triangles(&workers, false, CompareFunc::Less, |_| {});
        assert!(fresh == again, "{threads} threads");
        let small = impostors(&workers, true, true, 60, |_| {});
        assert!(small == impostors(&crate::Workers::new(1), true, true, 60, |_| {}));
    }
}

/// With a geometry stage, the probe follows a pixel back to the invocation
/// that emitted its primitive: which input primitive emitted each vertex
/// set up, and that invocation traced again with the values of the real
/// draw (its inputs, gl_PrimitiveIDIn, the vertices it emitted, whose
/// outputs are those set up).
#[test]
fn probe_follows_a_pixel_to_its_geometry_invocation() {
    use crate::{probe_draw, EmittedBy, Event, ProbeRequest};
    let opts = |s: Stage| CompileOptions::new(s);
    let v = compile(
        &["#version 150\nin vec2 pos;\nvoid main() { gl_Position = vec4(pos, 0.0, 1.0); }"],
        &opts(Stage::Vertex),
    );
    // Each point becomes a 2×2-pixel square (one strip of 4), coloured by
    // its primitive ID; a second strip far outside the viewport.
    let g = compile(
        &["#version 150
layout(points) in;
layout(triangle_strip, max_vertices = 8) out;
out vec4 c;
void main() {
    for (int i = 0; i < 4; i++) {
        c = vec4(float(gl_PrimitiveIDIn) * 0.5, 1.0, 0.0, 1.0);
        gl_Position = gl_in[0].gl_Position + vec4(vec2(i % 2, i / 2) * 0.5 - 0.25, 0.0, 0.0);
        EmitVertex();
    }
    EndPrimitive();
    for (int i = 0; i < 4; i++) {
        gl_Position = vec4(vec2(i % 2, i / 2) + 5.0, 0.0, 1.0);
        EmitVertex();
    }
}"],
        &opts(Stage::Geometry),
    );
    let f = compile(
        &["#version 150\nin vec4 c;\nout vec4 o;\nvoid main() { o = c; }"],
        &opts(Stage::Fragment),
    );
    for s in [&v, &g, &f] {
        assert!(s.ok(), "{}", s.info_log());
    }
    let prog = glsl::link::link(&[&v, &g, &f]);
    assert!(prog.ok(), "{}", prog.info_log());
    let k = |s: Stage| Kernel::new(prog.stage(s).expect("stage")).expect("lowering");
    let (vs, gs, fs) = (k(Stage::Vertex), k(Stage::Geometry), k(Stage::Fragment));
    let (w, h) = (8, 8);
    let fb = Framebuffer::new(w, h, ColorFormat::Rgba8, false, false);
    let state = PipelineState {
        viewport: Rect::new(0, 0, w as i32, h as i32),
        ..PipelineState::default()
    };
    // Points at pixel centres (2, 2) and (6, 6), and index 1 drawn first.
    let pos = [[0.5, 0.5], [-0.5, -0.5]];
    let fetch = Attribs {
        names: vs
            .interface()
            .inputs
            .iter()
            .map(|s| s.name.clone())
            .collect(),
        pos: &pos,
        col: &[],
    };
    let indices = [1u32, 0];
    let units = TextureUnits::default();
    let replay = crate::Replay {
        state: &state,
        vs: &vs,
        vs_uniforms: &[],
        gs: Some((&gs, &[])),
        fs: &fs,
        fs_uniforms: &[],
        mode: Mode::Points,
        indices: &indices,
        fetch: &fetch,
        textures: &units,
        layer: None,
    };
    let mut drawn = fb.clone();
    crate::draw_stages(
        &crate::Workers::inline(),
        &mut drawn,
        &state,
        (&vs, &[]),
        Some((&gs, &[])),
        (&fs, &[]),
        Mode::Points,
        &indices,
        &fetch,
        &units,
    )
    .expect("draw");
    let p = probe_draw(&fb, &replay, ProbeRequest::pixel(6, 6));
    assert_eq!(
        p.after,
        crate::PixelState::read(&drawn, 6 * w as usize + 6),
        "{p:#?}"
    );
    // Two points × two strips of 4 vertices, 2 triangles each.
    assert_eq!(p.primitives.len(), 8);
    assert_eq!(p.emitted_by.len(), 24);
    assert_eq!(p.fragments.len(), 1, "{p:#?}");
    let frag = &p.fragments[0];
    // The second input primitive's first strip.
    assert!(frag.primitive == 4 || frag.primitive == 5);
    let by: Vec<EmittedBy> = p.primitives[frag.primitive as usize]
        .iter()
        .map(|&pos| p.emitted_by[pos])
        .collect();
    assert!(
        by.iter().all(|b| b.primitive == 1 && b.vertex < 4),
        "{by:?}"
    );
    assert_eq!(p.geometry.len(), 1);
    let inv = &p.geometry[0];
    assert_eq!((inv.primitive, inv.primitive_id), (1, 1));
    assert_eq!((&inv.positions[..], &inv.indices[..]), (&[1][..], &[0][..]));
    let iface = gs.interface();
    let id = iface.input("gl_PrimitiveIDIn").expect("gl_PrimitiveIDIn");
    assert_eq!(inv.inputs[id.offset].to_bits(), 1);
    assert_eq!(inv.emitted.len(), 8);
    assert_eq!(inv.emitted[0].strip, 0);
    assert_ne!(inv.emitted[4].strip, inv.emitted[0].strip);
    // The invocation's emitted vertices are the ones set up.
    let n = p.vertex_outputs[0].len();
    for (&pos, b) in p.primitives[frag.primitive as usize].iter().zip(&by) {
        let traced = &inv.emitted[b.vertex as usize].outputs[..n];
        assert_eq!(traced, &p.vertex_outputs[pos][..], "vertex {pos}");
    }
    assert!(inv.events.iter().any(|e| matches!(e, Event::Store { .. })));
    assert!(!inv.truncated && inv.error.is_none());
    // No fragment, no invocation traced.
    let p = probe_draw(&fb, &replay, ProbeRequest::pixel(0, 7));
    assert!(p.fragments.is_empty() && p.geometry.is_empty());
}

/// How [`quadrilaterals_draw_as_their_two_triangles`] sends its
/// billboards (corners `c0..c3` around each).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Billboards {
    /// GL quads, `c0 c1 c2 c3`: set up as one primitive each.
    Quads,
    /// Indexed triangles sharing the edge `c1 c3`, in a strip's orders.
    StripPairs,
    /// Indexed triangles sharing the edge `c0 c2`, in a fan's orders.
    FanPairs,
    /// One triangle strip through them all, `c0 c1 c3 c2` each, joined
    /// by degenerate triangles.
    Strip,
}

impl Billboards {
    /// The mode, the vertex list and the indices of billboards `corners`;
    /// with `apart`, the same triangles (same vertex orders) as a list
    /// that shares no vertex, which set-up never joins.
    fn draw_list(self, corners: &[[usize; 4]], apart: bool) -> (Mode, Vec<usize>) {
        let mut list = Vec::new();
        let mut triangles: Vec<[usize; 3]> = Vec::new();
        for (i, &[c0, c1, c2, c3]) in corners.iter().enumerate() {
            match self {
                Billboards::Quads => {
                    list.extend([c0, c1, c2, c3]);
                    triangles.extend([[c0, c1, c2], [c0, c2, c3]]);
                }
                Billboards::StripPairs => {
                    list.extend([c0, c1, c3, c3, c1, c2]);
                    triangles.extend([[c0, c1, c3], [c3, c1, c2]]);
                }
                Billboards::FanPairs => {
                    list.extend([c0, c1, c2, c0, c2, c3]);
                    triangles.extend([[c0, c1, c2], [c0, c2, c3]]);
                }
                Billboards::Strip => {
                    if i > 0 {
                        // The previous last and this first again: four
                        // triangles without area, the parity kept.
                        let last = *list.last().unwrap_or(&c0);
                        list.extend([last, c0]);
                    }
                    list.extend([c0, c1, c3, c2]);
                    triangles.extend([[c0, c1, c3], [c3, c1, c2]]);
                }
            }
        }
        let mode = match self {
            Billboards::Quads => Mode::Quads,
            Billboards::StripPairs | Billboards::FanPairs => Mode::Triangles,
            Billboards::Strip => Mode::TriangleStrip,
        };
        match apart {
            false => (mode, list),
            true => (Mode::Triangles, triangles.concat()),
        }
    }
}

/// Billboards (four corners of one value per vertex attribute, some
/// rotated) drawn as GL quads, as indexed pairs of triangles and as a
/// triangle strip, which set-up takes as one primitive each, and as the
/// same triangles sharing no vertex: the same bytes, depths and sample
/// counts, with derivatives (helper lanes) or packed batches, on the
/// deferred path and the straightforward one, 1 and 2 threads. Every
/// fifth billboard varies a varying across its corners: those stay two
/// triangles.
#[test]
fn quadrilaterals_draw_as_their_two_triangles() {
    use std::sync::atomic::Ordering::Relaxed;
    crate::ex::set_native_after(32);
    // Derivatives or none; the third reads gl_FragCoord.z (amplified
    // into the colour), which the corners' differing window z then
    // interpolates: those billboards stay two triangles.
    for (quad_ops, reads_z) in [(false, false), (true, false), (false, true)] {
        let (vs, fs) = program(
            "attribute vec4 pos; attribute vec4 col;\n\
             varying vec4 c; varying float t; varying vec2 unread;\n\
             void main() { gl_Position = pos; c = col; t = pos.w - 1.0; unread = pos.xy; }",
            &format!(
                "varying vec4 c; varying float t; varying vec2 unread;\n\
                 void main() {{\n\
                   vec2 d = (gl_FragCoord.xy - c.xy) / c.z;\n\
                   float q = 1.0 - dot(d, d);\n\
                   if (q < 0.0) discard;\n\
                   float h = sqrt(q);\n\
                   gl_FragDepth = c.w - 0.1 * h + t;\n\
                   gl_FragColor = vec4(d * 0.5 + 0.5, {}, 1.0);\n\
                 }}",
                match (quad_ops, reads_z) {
                    (true, _) => "h + 4.0 * dFdx(h) + 2.0 * dFdy(h)",
                    (false, true) => "fract(gl_FragCoord.z * 65536.0)",
                    (false, false) => "h",
                }
            ),
        );
        let (w, h) = (150u32, 130u32);
        // The billboards' vertices, and each one's four.
        let mut attribs = SceneAttribs::for_kernel(&vs);
        let mut corners = Vec::new();
        let mut rnd = unit_floats(777);
        for i in 0..300 {
            // Centre and radius in pixels; corners at a random angle,
            // inside the window (the clipper would cut a quad as one
            // polygon and its triangles apart, which interpolates the
            // varying billboards differently).
            let (cx, cy, r) = (26.0 + rnd() * 98.0, 26.0 + rnd() * 78.0, 1.5 + 10.5 * rnd());
            let (z, angle) = (0.2 + 0.6 * rnd(), [0.0, rnd() * 6.3][i % 2]);
            let first = attribs.pos.len();
            for k in 0..4 {
                let a = angle + std::f32::consts::FRAC_PI_2 * k as f32;
                let (x, y) = (cx + r * 1.5 * a.cos(), cy + r * 1.5 * a.sin());
                // Every fifth: a varying (`t`, from w) that differs.
                let clip_w = if i % 5 == 0 {
                    1.0 + 0.001 * k as f32
                } else {
                    1.0
                };
                // Window z differs at the corners (read only by the
                // third shader; the others write gl_FragDepth), and so
                // does `unread`, which no shader reads.
                let corner_z = 0.001 * k as f32;
                let ndc = |v: f32, size: u32| 2.0 * v / size as f32 - 1.0;
                attribs
                    .pos
                    .push([ndc(x, w), ndc(y, h), corner_z, 1.0].map(|c| c * clip_w));
                attribs.col.push([cx, cy, r, z]);
            }
            corners.push([first, first + 1, first + 2, first + 3]);
        }
        let draw = |(mode, list): (Mode, Vec<usize>), deferred: bool, threads: usize| {
            let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba8, true, false);
            fb.clear_color(&[0], [0.1, 0.2, 0.3, 1.0], [true; 4], None);
            fb.clear_depth(1.0, true, None);
            let state = PipelineState {
                viewport: Rect::new(0, 0, w as i32, h as i32),
                depth_test: Some(CompareFunc::Less),
                ..PipelineState::default()
            };
            let straight = Straightforward(&fs);
            let stage: &dyn crate::ShaderStage = if deferred { &fs } else { &straight };
            let indices: Vec<u32> = list.iter().map(|&v| v as u32).collect();
            let units = TextureUnits::default();
            let workers = crate::Workers::new(threads);
            let fs_stage = (stage, &[][..]);
            crate::draw_stages(
                &workers,
                &mut fb,
                &state,
                (&vs, &[]),
                None,
                fs_stage,
                mode,
                &indices,
                &attribs,
                &units,
            )
            .unwrap();
            (
                fb.read_pixels_u8(0, 0, 0, w, h),
                fb.read_depth(0, 0, w, h),
                fb.samples_passed,
            )
        };
        let kinds = [
            Billboards::Quads,
            Billboards::StripPairs,
            Billboards::FanPairs,
            Billboards::Strip,
        ];
        for kind in kinds {
            let want = draw(kind.draw_list(&corners, true), false, 1);
            let distinct: std::collections::BTreeSet<[u8; 4]> = want.0.iter().copied().collect();
            assert!(distinct.len() > 500, "{} colours", distinct.len());
            for deferred in [false, true] {
                for threads in [1, 2] {
                    let before = crate::setup::QUADRILATERALS.load(Relaxed);
                    let got = draw(kind.draw_list(&corners, false), deferred, threads);
                    let merged = crate::setup::QUADRILATERALS.load(Relaxed) - before;
                    // (A strip's chunk boundaries may part a pair; other
                    // tests' draws may add to the count.)
                    if !reads_z {
                        assert!(merged >= 235, "{kind:?}: {merged} quadrilaterals");
                    }
                    let case = format!(
                        "{kind:?}, quad_ops {quad_ops}, reads_z {reads_z}, deferred {deferred}, {threads} threads"
                    );
                    assert!(want.0 == got.0, "colours, {case}");
                    assert!(want.1 == got.1, "depths, {case}");
                    assert_eq!(want.2, got.2, "samples, {case}");
                }
            }
        }
    }
}
