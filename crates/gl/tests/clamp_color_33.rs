//! glClampColor (GL 3.0 §3.7.5, §4.3.2): fragment colours written to a
//! float colour buffer are clamped only as CLAMP_FRAGMENT_COLOR says, and
//! glReadPixels clamps them as CLAMP_READ_COLOR says; the state queries
//! and the core profile's refusals.

use gl::enums::*;
use gl::Context;

mod common;

const VS: &str = "#version 330 compatibility\n\
    in vec2 pos;\n\
    void main() { gl_Position = vec4(pos, 0.0, 1.0); }";
const FS: &str = "#version 330 compatibility\n\
    out vec4 c;\n\
    void main() { c = vec4(2.0, -1.0, 0.5, 1.0); }";

/// The read, fragment and vertex colour clamps.
fn clamps(ctx: &mut Context) -> [u32; 3] {
    [
        GL_CLAMP_READ_COLOR,
        GL_CLAMP_FRAGMENT_COLOR,
        GL_CLAMP_VERTEX_COLOR,
    ]
    .map(|pname| ctx.get_integerv(pname)[0] as u32)
}

/// [`clamps`] of a new context: fixed-point buffers only for reads and
/// fragments, on for vertex colours.
const DEFAULT_CLAMPS: [u32; 3] = [GL_FIXED_ONLY, GL_FIXED_ONLY, GL_TRUE];

/// Draws [`FS`]'s out-of-range colour into an RGBA32F renderbuffer of a
/// new framebuffer object and reads it back as floats.
fn draw_float(ctx: &mut Context) -> [f32; 4] {
    common::float_framebuffer(ctx, 4, 4);
    assert_eq!(
        ctx.check_framebuffer_status(GL_FRAMEBUFFER),
        GL_FRAMEBUFFER_COMPLETE
    );
    let p = common::program(ctx, VS, FS);
    common::quad_vertex_array(ctx, p, "pos");
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.take_draw_error(), None);
    ctx.read_pixels_f32(1, 1, 1, 1)[0]
}

#[test]
fn float_buffers_are_clamped_as_clamp_color_says() {
    // The defaults: FIXED_ONLY for fragments and reads, so a float buffer
    // keeps and returns the values as they are.
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_COMPAT);
    assert_eq!(clamps(&mut ctx), DEFAULT_CLAMPS);
    assert_eq!(draw_float(&mut ctx), [2.0, -1.0, 0.5, 1.0]);
    // Read clamping on: the same buffer reads clamped.
    ctx.clamp_color(GL_CLAMP_READ_COLOR, GL_TRUE);
    assert_eq!(ctx.read_pixels_f32(1, 1, 1, 1)[0], [1.0, 0.0, 0.5, 1.0]);
    ctx.clamp_color(GL_CLAMP_READ_COLOR, GL_FALSE);
    assert_eq!(ctx.read_pixels_f32(1, 1, 1, 1)[0], [2.0, -1.0, 0.5, 1.0]);
    assert_eq!(ctx.get_integerv(GL_CLAMP_READ_COLOR), vec![GL_FALSE as i32]);

    // Fragment clamping on: the stored values are clamped.
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_COMPAT);
    ctx.clamp_color(GL_CLAMP_FRAGMENT_COLOR, GL_TRUE);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(draw_float(&mut ctx), [1.0, 0.0, 0.5, 1.0]);
    ctx.clamp_color(GL_CLAMP_FRAGMENT_COLOR, GL_FALSE);
    assert_eq!(
        ctx.get_integerv(GL_CLAMP_FRAGMENT_COLOR),
        vec![GL_FALSE as i32]
    );
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.read_pixels_f32(1, 1, 1, 1)[0], [2.0, -1.0, 0.5, 1.0]);
}

#[test]
fn push_and_pop_attrib_restore_the_clamps() {
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_COMPAT);
    ctx.push_attrib(GL_COLOR_BUFFER_BIT | GL_LIGHTING_BIT);
    ctx.clamp_color(GL_CLAMP_READ_COLOR, GL_TRUE);
    ctx.clamp_color(GL_CLAMP_FRAGMENT_COLOR, GL_FALSE);
    ctx.clamp_color(GL_CLAMP_VERTEX_COLOR, GL_FIXED_ONLY);
    ctx.pop_attrib();
    assert_eq!(clamps(&mut ctx), DEFAULT_CLAMPS);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}

#[test]
fn clamp_color_errors() {
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_CORE);
    ctx.clamp_color(GL_CLAMP_READ_COLOR, GL_RED);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    // The vertex and fragment targets are compatibility-profile state.
    for target in [GL_CLAMP_VERTEX_COLOR, GL_CLAMP_FRAGMENT_COLOR, GL_BLEND] {
        ctx.clamp_color(target, GL_TRUE);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.get_integerv(target);
        if target != GL_BLEND {
            assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        }
    }
    ctx.clamp_color(GL_CLAMP_READ_COLOR, GL_TRUE);
    assert_eq!(ctx.get_integerv(GL_CLAMP_READ_COLOR), vec![GL_TRUE as i32]);
    // A GL 2.1 context has no glClampColor: it clamps always.
    let mut old = Context::new(4, 4);
    old.clamp_color(GL_CLAMP_READ_COLOR, GL_TRUE);
    assert_eq!(old.get_error(), GL_INVALID_ENUM);
    old.get_integerv(GL_CLAMP_FRAGMENT_COLOR);
    assert_eq!(old.get_error(), GL_INVALID_ENUM);
    // They are no capabilities.
    ctx.enable(GL_CLAMP_READ_COLOR);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}
