//! glClampColor (GL 3.0 §3.7.5, §4.3.2): fragment colours written to a
//! float colour buffer are clamped only as CLAMP_FRAGMENT_COLOR says, and
//! glReadPixels clamps them as CLAMP_READ_COLOR says; the state queries
//! and the core profile's refusals.

use gl::enums::*;
use gl::{ArrayData, Context};

mod common;

const VS: &str = "#version 330 compatibility\n\
    in vec2 pos;\n\
    void main() { gl_Position = vec4(pos, 0.0, 1.0); }";
const FS: &str = "#version 330 compatibility\n\
    out vec4 c;\n\
    void main() { c = vec4(2.0, -1.0, 0.5, 1.0); }";

/// Draws [`FS`]'s out-of-range colour into an RGBA32F renderbuffer of a
/// new framebuffer object and reads it back as floats.
fn draw_float(ctx: &mut Context) -> [f32; 4] {
    let rb = ctx.gen_renderbuffers(1)[0];
    ctx.bind_renderbuffer(GL_RENDERBUFFER, rb);
    ctx.renderbuffer_storage(GL_RENDERBUFFER, GL_RGBA32F, 4, 4);
    let fb = ctx.gen_framebuffers(1)[0];
    ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
    ctx.framebuffer_renderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    assert_eq!(
        ctx.check_framebuffer_status(GL_FRAMEBUFFER),
        GL_FRAMEBUFFER_COMPLETE
    );
    let p = common::program(ctx, VS, FS);
    let pos = ctx.get_attrib_location(p, "pos") as u32;
    let quad = [-1.0f32, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0];
    ctx.vertex_attrib_pointer(pos, 2, GL_FLOAT, false, 0, ArrayData::from_f32(&quad));
    ctx.enable_vertex_attrib_array(pos);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.take_draw_error(), None);
    ctx.read_pixels_f32(1, 1, 1, 1)[0]
}

#[test]
fn float_buffers_are_clamped_as_clamp_color_says() {
    // The defaults: FIXED_ONLY for fragments and reads, so a float buffer
    // keeps and returns the values as they are.
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_COMPAT);
    assert_eq!(
        ctx.get_integerv(GL_CLAMP_READ_COLOR),
        vec![GL_FIXED_ONLY as i32]
    );
    assert_eq!(
        ctx.get_integerv(GL_CLAMP_FRAGMENT_COLOR),
        vec![GL_FIXED_ONLY as i32]
    );
    assert_eq!(
        ctx.get_integerv(GL_CLAMP_VERTEX_COLOR),
        vec![GL_TRUE as i32]
    );
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
    assert_eq!(
        ctx.get_integerv(GL_CLAMP_READ_COLOR),
        vec![GL_FIXED_ONLY as i32]
    );
    assert_eq!(
        ctx.get_integerv(GL_CLAMP_FRAGMENT_COLOR),
        vec![GL_FIXED_ONLY as i32]
    );
    assert_eq!(
        ctx.get_integerv(GL_CLAMP_VERTEX_COLOR),
        vec![GL_TRUE as i32]
    );
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
