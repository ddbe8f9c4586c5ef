//! GLSL 1.30 clipping and interpolation end to end: `gl_ClipDistance`
//! with `GL_CLIP_DISTANCEi` (GL 3.3 §2.20), `noperspective` and the
//! interpolation qualifiers against the shade model (GLSL 1.30 §4.3.7),
//! checked pixel by pixel.

use gl::enums::*;
use gl::Context;

mod common;
use common::program;

const SIZE: i32 = 32;

/// Draws a triangle strip whose vertices have clip positions `pos` and
/// the values `val` (a vec4 each) with program `p` (inputs `pos` and,
/// when the program reads it, `val`).
fn draw_strip(ctx: &mut Context, p: u32, pos: &[[f32; 4]], val: &[[f32; 4]]) {
    ctx.clear_color(0.0, 0.0, 0.0, 0.0);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    for (name, data) in [("pos", pos), ("val", val)] {
        let loc = ctx.get_attrib_location(p, name);
        if loc < 0 && name == "val" {
            continue;
        }
        assert!(loc >= 0, "{name}");
        let flat: Vec<f32> = data.iter().flatten().copied().collect();
        common::float_array(ctx, loc as u32, 4, &flat);
    }
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, pos.len() as i32);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.take_draw_error(), None);
}

/// The framebuffer as floats, row by row from the bottom.
fn image(ctx: &mut Context) -> Vec<[f32; 4]> {
    ctx.read_pixels_f32(0, 0, SIZE, SIZE)
}

/// Pixel `(x, y)`'s center in normalized device coordinates.
fn ndc(i: i32) -> f32 {
    (i as f32 + 0.5) / SIZE as f32 * 2.0 - 1.0
}

/// Within a unorm8 step (and a little) of `want`.
fn near(got: f32, want: f32) -> bool {
    (got - want).abs() <= 1.5 / 255.0
}

/// The whole window as a strip, `w` at the left and `4w` at the right
/// edge: window x is linear in the `val` attribute only for
/// noperspective.
fn slanted_quad() -> ([[f32; 4]; 4], [[f32; 4]; 4]) {
    let corner = |x: f32, y: f32, w: f32| [x * w, y * w, 0.0, w];
    let pos = [
        corner(-1.0, -1.0, 1.0),
        corner(1.0, -1.0, 4.0),
        corner(-1.0, 1.0, 1.0),
        corner(1.0, 1.0, 4.0),
    ];
    let val = [
        [0.0, 0.0, 0.0, 1.0],
        [1.0, 0.0, 0.0, 1.0],
        [0.0, 0.0, 0.0, 1.0],
        [1.0, 0.0, 0.0, 1.0],
    ];
    (pos, val)
}

fn interpolation_program(ctx: &mut Context, qualifier: &str, clip: bool) -> u32 {
    let clip_line = if clip {
        // Keep window x >= -0.5: a clip-space plane, cutting the strip's
        // triangles between vertices of different w.
        "gl_ClipDistance[0] = pos.x + 0.5 * pos.w;"
    } else {
        ""
    };
    let vs = format!(
        "#version 130\n\
         in vec4 pos; in vec4 val;\n\
         {qualifier} out vec4 v;\n\
         void main() {{ gl_Position = pos; v = val; {clip_line} }}"
    );
    let fs = format!(
        "#version 130\n\
         {qualifier} in vec4 v;\n\
         void main() {{ gl_FragColor = v; }}"
    );
    program(ctx, &vs, &fs)
}

/// The value a perspective-correct varying has at window position `x`
/// (in [-1, 1]) across [`slanted_quad`]: 0 at w = 1, 1 at w = 4.
fn perspective_value(x: f32) -> f32 {
    let s = (x + 1.0) / 2.0;
    (s / 4.0) / ((1.0 - s) / 1.0 + s / 4.0)
}

#[test]
fn noperspective_is_linear_in_window_space() {
    let mut ctx = Context::new(SIZE, SIZE);
    let (pos, val) = slanted_quad();
    for clip in [false, true] {
        let p = interpolation_program(&mut ctx, "noperspective", clip);
        if clip {
            ctx.enable(GL_CLIP_DISTANCE0);
        }
        draw_strip(&mut ctx, p, &pos, &val);
        ctx.disable(GL_CLIP_DISTANCE0);
        let img = image(&mut ctx);
        for y in 0..SIZE {
            for x in 0..SIZE {
                let got = img[(y * SIZE + x) as usize];
                let want = if clip && ndc(x) < -0.5 {
                    0.0
                } else {
                    (ndc(x) + 1.0) / 2.0
                };
                assert!(
                    near(got[0], want),
                    "clip {clip}, ({x}, {y}): {got:?} want {want}"
                );
            }
        }
    }
}

#[test]
fn smooth_is_perspective_correct_and_overrides_flat_shading() {
    let mut ctx = Context::new(SIZE, SIZE);
    let (pos, val) = slanted_quad();
    for qualifier in ["", "smooth"] {
        for clip in [false, true] {
            let p = interpolation_program(&mut ctx, qualifier, clip);
            // Flat shading applies to colors only, never to a user varying.
            ctx.shade_model(GL_FLAT);
            if clip {
                ctx.enable(GL_CLIP_DISTANCE0);
            }
            draw_strip(&mut ctx, p, &pos, &val);
            ctx.disable(GL_CLIP_DISTANCE0);
            ctx.shade_model(GL_SMOOTH);
            let img = image(&mut ctx);
            for y in 0..SIZE {
                for x in 0..SIZE {
                    let got = img[(y * SIZE + x) as usize];
                    let want = if clip && ndc(x) < -0.5 {
                        0.0
                    } else {
                        perspective_value(ndc(x))
                    };
                    assert!(
                        near(got[0], want),
                        "'{qualifier}', clip {clip}, ({x}, {y}): {got:?} want {want}"
                    );
                }
            }
        }
    }
}

/// Colors follow the shade model unless qualified: `smooth` and
/// `noperspective` interpolate under `glShadeModel(GL_FLAT)`, `flat`
/// takes the provoking vertex's under `GL_SMOOTH`.
#[test]
fn color_qualifiers_override_the_shade_model() {
    let (pos, val) = slanted_quad();
    // Each strip triangle's provoking vertex is its last: (-1, 1), value
    // 0, for the first (below the diagonal), (1, 1), value 1, for the
    // second.
    for (qualifier, model, want) in [
        ("", GL_FLAT, None),
        ("flat", GL_SMOOTH, None),
        ("smooth", GL_FLAT, Some(false)),
        ("noperspective", GL_FLAT, Some(true)),
    ] {
        let mut ctx = Context::new(SIZE, SIZE);
        let vs = format!(
            "#version 130\n\
             in vec4 pos; in vec4 val;\n\
             {qualifier} out vec4 gl_FrontColor;\n\
             void main() {{ gl_Position = pos; gl_FrontColor = val; }}"
        );
        let fs = format!(
            "#version 130\n\
             {qualifier} in vec4 gl_Color;\n\
             void main() {{ gl_FragColor = gl_Color; }}"
        );
        let p = program(&mut ctx, &vs, &fs);
        ctx.shade_model(model);
        draw_strip(&mut ctx, p, &pos, &val);
        let img = image(&mut ctx);
        for y in 0..SIZE {
            for x in 0..SIZE {
                let got = img[(y * SIZE + x) as usize][0];
                let want = match want {
                    // Pixels centred on the diagonal go to either.
                    None if x + y == SIZE - 1 => continue,
                    None if x + y < SIZE - 1 => 0.0,
                    None => 1.0,
                    Some(false) => perspective_value(ndc(x)),
                    Some(true) => (ndc(x) + 1.0) / 2.0,
                };
                assert!(
                    near(got, want),
                    "'{qualifier}' ({x}, {y}): {got} want {want}"
                );
            }
        }
    }
}

/// Enabled clip distances clip (distance >= 0 kept), disabled ones do
/// not, and the fragment shader reads them interpolated.
#[test]
fn clip_distances_clip_and_interpolate() {
    let vs = "#version 130\n\
        in vec4 pos; in vec4 val;\n\
        out float gl_ClipDistance[3];\n\
        void main() {\n\
            gl_Position = pos;\n\
            gl_ClipDistance[0] = pos.x - 0.25;\n\
            gl_ClipDistance[1] = 0.5 - pos.y;\n\
            gl_ClipDistance[2] = -1.0;\n\
        }";
    let fs = "#version 130\n\
        in float gl_ClipDistance[3];\n\
        void main() { gl_FragColor = vec4(gl_ClipDistance[0], gl_ClipDistance[1], 0.0, 1.0); }";
    let corner = |x: f32, y: f32| [x, y, 0.0, 1.0];
    let pos = [
        corner(-1.0, -1.0),
        corner(1.0, -1.0),
        corner(-1.0, 1.0),
        corner(1.0, 1.0),
    ];
    let val = [[0.0; 4]; 4];
    for enabled in [0u32, 0b1, 0b10, 0b11, 0b100] {
        let mut ctx = Context::new(SIZE, SIZE);
        let p = program(&mut ctx, vs, fs);
        for i in 0..3 {
            if enabled & (1 << i) != 0 {
                ctx.enable(GL_CLIP_DISTANCE0 + i);
            }
        }
        draw_strip(&mut ctx, p, &pos, &val);
        let img = image(&mut ctx);
        for y in 0..SIZE {
            for x in 0..SIZE {
                let got = img[(y * SIZE + x) as usize];
                let (d0, d1) = (ndc(x) - 0.25, 0.5 - ndc(y));
                let clipped = [d0, d1, -1.0]
                    .iter()
                    .enumerate()
                    .any(|(i, &d)| enabled & (1 << i) != 0 && d < 0.0);
                let kept = !clipped;
                let want = if kept {
                    [d0.clamp(0.0, 1.0), d1.clamp(0.0, 1.0), 0.0, 1.0]
                } else {
                    [0.0; 4]
                };
                assert!(
                    got.iter().zip(want).all(|(&g, w)| near(g, w)),
                    "planes {enabled:#b}, ({x}, {y}): {got:?} want {want:?}"
                );
            }
        }
    }
}

/// Without gl_ClipDistance the plane equations still clip against the
/// eye-space position, as in GL 2.1.
#[test]
fn clip_plane_equations_without_clip_distance() {
    let mut ctx = Context::new(SIZE, SIZE);
    let vs = "#version 130\n\
        in vec4 pos; in vec4 val;\n\
        void main() { gl_Position = pos; gl_ClipVertex = pos; }";
    let fs = "#version 130\nvoid main() { gl_FragColor = vec4(1.0); }";
    let p = program(&mut ctx, vs, fs);
    ctx.clip_plane(GL_CLIP_PLANE0, &[-1.0, 0.0, 0.0, 0.0]);
    ctx.enable(GL_CLIP_PLANE0);
    let corner = |x: f32, y: f32| [x, y, 0.0, 1.0];
    let pos = [
        corner(-1.0, -1.0),
        corner(1.0, -1.0),
        corner(-1.0, 1.0),
        corner(1.0, 1.0),
    ];
    draw_strip(&mut ctx, p, &pos, &[[0.0; 4]; 4]);
    let img = image(&mut ctx);
    for y in 0..SIZE {
        for x in 0..SIZE {
            let want = if ndc(x) <= 0.0 { 1.0 } else { 0.0 };
            assert_eq!(img[(y * SIZE + x) as usize][0], want, "({x}, {y})");
        }
    }
}

/// Many perspective triangles with smooth, noperspective and flat
/// varyings, cut by two clip distances: the same bits whatever the
/// thread count.
#[test]
fn clipped_noperspective_scene_is_identical_whatever_the_thread_count() {
    let vs = "#version 130\n\
        in vec4 pos; in vec4 val;\n\
        smooth out float s; noperspective out float n; flat out float f;\n\
        void main() {\n\
            gl_Position = pos; s = val.x; n = val.y; f = val.z;\n\
            gl_ClipDistance[0] = pos.x + 0.6 * pos.w;\n\
            gl_ClipDistance[1] = 0.7 * pos.w - pos.y;\n\
        }";
    let fs = "#version 130\n\
        smooth in float s; noperspective in float n; flat in float f;\n\
        void main() { gl_FragColor = vec4(s, n, f, 1.0); }";
    let mut seed = 7u32;
    let mut rnd = move || {
        seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12_345);
        (seed >> 8) as f32 / (1u32 << 24) as f32
    };
    let (mut pos, mut val) = (Vec::new(), Vec::new());
    for _ in 0..3 * 400 {
        let w = 0.5 + 3.0 * rnd();
        let (x, y) = (2.6 * rnd() - 1.3, 2.6 * rnd() - 1.3);
        pos.extend([x * w, y * w, 0.0, w]);
        val.extend([rnd(), rnd(), rnd(), 1.0]);
    }
    let render = |threads: usize| {
        let mut ctx = Context::new(96, 80);
        ctx.set_threads(threads);
        let p = program(&mut ctx, vs, fs);
        ctx.enable(GL_CLIP_DISTANCE0);
        ctx.enable(GL_CLIP_DISTANCE1);
        ctx.enable(GL_BLEND);
        ctx.blend_func(GL_ONE, GL_ONE);
        for (name, data) in [("pos", &pos), ("val", &val)] {
            let loc = ctx.get_attrib_location(p, name) as u32;
            common::float_array(&mut ctx, loc, 4, data);
        }
        ctx.draw_arrays(GL_TRIANGLES, 0, (pos.len() / 4) as i32);
        assert_eq!(ctx.take_draw_error(), None);
        ctx.read_pixels_f32(0, 0, 96, 80)
            .iter()
            .flat_map(|p| p.map(f32::to_bits))
            .collect::<Vec<u32>>()
    };
    let one = render(1);
    assert!(one.chunks(4).filter(|p| p[3] != 0).count() > 1000);
    for threads in [2, 4] {
        assert!(render(threads) == one, "{threads} threads");
    }
}
