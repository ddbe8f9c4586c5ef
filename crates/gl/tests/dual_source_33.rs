//! Dual-source blending (GL 3.3 §4.1.8, §3.9.2; ARB_blend_func_extended):
//! a fragment output at `layout(location = 0, index = 1)`, or bound there
//! with glBindFragDataLocationIndexed, is the second source colour the
//! SRC1 blend factors read; glGetFragDataIndex, the limit and the errors.

use gl::enums::*;
use gl::Context;

mod common;

const VS: &str = "#version 330 core\n\
    in vec2 pos;\n\
    void main() { gl_Position = vec4(pos, 0.0, 1.0); }";

/// Colour 0 and the second source colour the shaders write.
const C0: [f32; 4] = [0.25, 0.5, 0.125, 0.5];
const C1: [f32; 4] = [0.5, 0.25, 1.0, 0.5];
/// The colour the target is cleared to.
const DST: [f32; 4] = [0.2, 0.4, 0.6, 0.8];

const FS_LAYOUT: &str = "#version 330 core\n\
    layout(location = 0, index = 0) out vec4 c0;\n\
    layout(location = 0, index = 1) out vec4 c1;\n\
    void main() { c0 = vec4(0.25, 0.5, 0.125, 0.5); c1 = vec4(0.5, 0.25, 1.0, 0.5); }";

/// A 4×4 context drawing into an RGBA32F renderbuffer (exact floats).
fn float_target() -> Context {
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_CORE);
    common::float_framebuffer(&mut ctx, 4, 4);
    ctx
}

/// Links `fs` (with `bind` run between attaching and linking), clears to
/// [`DST`], draws a full quad with blending `src`/`dst` and returns the
/// pixel.
fn draw(ctx: &mut Context, fs: &str, bind: impl Fn(&mut Context, u32), f: (u32, u32)) -> [f32; 4] {
    let p = common::attached(ctx, Some(VS), Some(fs));
    bind(ctx, p);
    common::link_and_use(ctx, p);
    common::quad_vertex_array(ctx, p, "pos");
    ctx.clear_color(DST[0], DST[1], DST[2], DST[3]);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    ctx.enable(GL_BLEND);
    ctx.blend_func(f.0, f.1);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.take_draw_error(), None);
    ctx.read_pixels_f32(1, 1, 1, 1)[0]
}

fn no_binding(_: &mut Context, _: u32) {}

#[test]
fn src1_factors_read_the_second_colour() {
    let mut ctx = float_target();
    // ONE, SRC1_COLOR: c0 + dst · c1.
    let got = draw(&mut ctx, FS_LAYOUT, no_binding, (GL_ONE, GL_SRC1_COLOR));
    let want: [f32; 4] = std::array::from_fn(|i| C0[i] + DST[i] * C1[i]);
    assert_eq!(got, want);
    // SRC1_ALPHA, ONE_MINUS_SRC1_ALPHA: a mix by the second alpha.
    let got = draw(
        &mut ctx,
        FS_LAYOUT,
        no_binding,
        (GL_SRC1_ALPHA, GL_ONE_MINUS_SRC1_ALPHA),
    );
    let want: [f32; 4] = std::array::from_fn(|i| C0[i] * C1[3] + DST[i] * (1.0 - C1[3]));
    assert_eq!(got, want);
    // ONE_MINUS_SRC1_COLOR as the source factor.
    let got = draw(
        &mut ctx,
        FS_LAYOUT,
        no_binding,
        (GL_ONE_MINUS_SRC1_COLOR, GL_ZERO),
    );
    let want: [f32; 4] = std::array::from_fn(|i| C0[i] * (1.0 - C1[i]));
    assert_eq!(got, want);
    // Without SRC1 factors the second colour changes nothing.
    let got = draw(&mut ctx, FS_LAYOUT, no_binding, (GL_ONE, GL_ZERO));
    assert_eq!(got, C0);
}

#[test]
fn the_default_framebuffer_blends_in_fixed_point() {
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_CORE);
    let got = draw(&mut ctx, FS_LAYOUT, no_binding, (GL_ONE, GL_SRC1_COLOR));
    let dst = DST.map(|c| (c * 255.0).round() / 255.0);
    for i in 0..4 {
        let want = C0[i] + dst[i] * C1[i];
        assert!((got[i] - want).abs() <= 1.0 / 255.0, "{got:?}");
    }
}

#[test]
fn bind_frag_data_location_indexed_and_get_frag_data_index() {
    let mut ctx = float_target();
    let fs = "#version 330 core\n\
        out vec4 a;\n\
        out vec4 b;\n\
        void main() { a = vec4(0.5, 0.25, 1.0, 0.5); b = vec4(0.25, 0.5, 0.125, 0.5); }";
    // b is colour 0, a its second colour.
    let bind = |ctx: &mut Context, p: u32| {
        ctx.bind_frag_data_location_indexed(p, 0, 0, "b");
        ctx.bind_frag_data_location_indexed(p, 0, 1, "a");
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
    };
    let got = draw(&mut ctx, fs, bind, (GL_ONE, GL_SRC1_COLOR));
    let want: [f32; 4] = std::array::from_fn(|i| C0[i] + DST[i] * C1[i]);
    assert_eq!(got, want);
    let p = ctx.get_integerv(GL_CURRENT_PROGRAM)[0] as u32;
    assert_eq!(ctx.get_frag_data_index(p, "a"), 1);
    assert_eq!(ctx.get_frag_data_index(p, "b"), 0);
    assert_eq!(ctx.get_frag_data_location(p, "a"), 0);
    assert_eq!(ctx.get_frag_data_index(p, "nothing"), -1);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // The shader's layout wins over a binding.
    let mut ctx = float_target();
    let bind = |ctx: &mut Context, p: u32| ctx.bind_frag_data_location_indexed(p, 0, 0, "c1");
    draw(&mut ctx, FS_LAYOUT, bind, (GL_ONE, GL_ZERO));
    let p = ctx.get_integerv(GL_CURRENT_PROGRAM)[0] as u32;
    assert_eq!(ctx.get_frag_data_index(p, "c1"), 1);
    assert_eq!(ctx.get_frag_data_index(p, "c0"), 0);
}

#[test]
fn dual_source_limits_and_errors() {
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_CORE);
    assert_eq!(ctx.get_integerv(GL_MAX_DUAL_SOURCE_DRAW_BUFFERS), vec![1]);
    let p = ctx.create_program();
    ctx.bind_frag_data_location_indexed(p, 1, 1, "x");
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.bind_frag_data_location_indexed(p, 0, 2, "x");
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.bind_frag_data_location_indexed(p, gl::MAX_DRAW_BUFFERS as u32, 0, "x");
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.bind_frag_data_location_indexed(p, 0, 1, "gl_FragColor");
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.bind_frag_data_location_indexed(9999, 0, 1, "x");
    assert_ne!(ctx.get_error(), GL_NO_ERROR);
    // Not linked yet.
    assert_eq!(ctx.get_frag_data_index(p, "x"), -1);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    // Index 1 past location 0 fails the link; two outputs on one
    // location and index too.
    for fs in [
        "#version 330 core\n\
         layout(location = 1, index = 1) out vec4 c1;\n\
         layout(location = 0) out vec4 c0;\n\
         void main() { c0 = vec4(1.0); c1 = vec4(1.0); }",
        "#version 330 core\n\
         layout(location = 0, index = 1) out vec4 a;\n\
         layout(location = 0, index = 1) out vec4 b;\n\
         void main() { a = vec4(1.0); b = vec4(1.0); }",
    ] {
        let p = ctx.create_program();
        for (kind, src) in [(GL_VERTEX_SHADER, VS), (GL_FRAGMENT_SHADER, fs)] {
            let s = ctx.create_shader(kind);
            ctx.shader_source(s, &[src]);
            ctx.compile_shader(s);
            assert_eq!(ctx.get_shaderiv(s, GL_COMPILE_STATUS), 1);
            ctx.attach_shader(p, s);
        }
        ctx.link_program(p);
        assert_eq!(ctx.get_programiv(p, GL_LINK_STATUS), 0, "{fs}");
    }
    // The SRC1 factors are 3.3's: a 2.1 context refuses them.
    ctx.blend_func(GL_ONE, GL_SRC1_COLOR);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    let mut old = Context::new(4, 4);
    old.blend_func(GL_ONE, GL_SRC1_COLOR);
    assert_eq!(old.get_error(), GL_INVALID_ENUM);
    // The extension is advertised.
    let n = ctx.get_integerv(GL_NUM_EXTENSIONS)[0];
    assert!((0..n)
        .any(|i| ctx.get_stringi(GL_EXTENSIONS, i as u32) == Some("GL_ARB_blend_func_extended")));
}
