//! Helpers the gl integration tests share (each test file is its own
//! crate and takes this module with `mod common;`).

use gl::enums::*;
use gl::{ArrayData, Context};

/// A new program with shader objects of the kinds given compiled and
/// attached ((GL kind, source)), not linked yet, so that the caller may
/// bind locations or set parameters first; panics with the info log when
/// a stage does not compile.
pub fn attached_stages(ctx: &mut Context, stages: &[(u32, &str)]) -> u32 {
    let p = ctx.create_program();
    for &(kind, src) in stages {
        let s = ctx.create_shader(kind);
        ctx.shader_source(s, &[src]);
        ctx.compile_shader(s);
        assert_eq!(
            ctx.get_shaderiv(s, GL_COMPILE_STATUS),
            1,
            "{}",
            ctx.get_shader_info_log(s)
        );
        ctx.attach_shader(p, s);
    }
    p
}

/// [`attached_stages`] of a vertex and a fragment stage (a stage left
/// out is fixed function).
pub fn attached(ctx: &mut Context, vs: Option<&str>, fs: Option<&str>) -> u32 {
    let stages: Vec<(u32, &str)> = [(GL_VERTEX_SHADER, vs), (GL_FRAGMENT_SHADER, fs)]
        .into_iter()
        .filter_map(|(kind, src)| Some((kind, src?)))
        .collect();
    attached_stages(ctx, &stages)
}

/// [`attached_stages`], linked and made current.
#[allow(dead_code)]
pub fn linked_stages(ctx: &mut Context, stages: &[(u32, &str)]) -> u32 {
    let p = attached_stages(ctx, stages);
    link_and_use(ctx, p)
}

/// Links `p` and makes it current; panics with the info log when it does
/// not link.
pub fn link_and_use(ctx: &mut Context, p: u32) -> u32 {
    ctx.link_program(p);
    assert_eq!(
        ctx.get_programiv(p, GL_LINK_STATUS),
        1,
        "{}",
        ctx.get_program_info_log(p)
    );
    ctx.use_program(p);
    p
}

/// Compiles the stages given (a stage left out is fixed function), links
/// them and makes the program current; panics with the info log when a
/// stage does not compile or the program does not link.
pub fn linked_program(ctx: &mut Context, vs: Option<&str>, fs: Option<&str>) -> u32 {
    let p = attached(ctx, vs, fs);
    link_and_use(ctx, p)
}

/// [`linked_program`] of a vertex and a fragment shader.
#[allow(dead_code)]
pub fn program(ctx: &mut Context, vs: &str, fs: &str) -> u32 {
    linked_program(ctx, Some(vs), Some(fs))
}

/// The corners of a full-window triangle strip.
#[allow(dead_code)]
pub const FULL_QUAD: [f32; 8] = [-1.0, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0];

/// A new vertex array object, left bound, whose attribute `name` of
/// program `p` (two floats) reads [`FULL_QUAD`] from a buffer object.
#[allow(dead_code)]
pub fn quad_vertex_array(ctx: &mut Context, p: u32, name: &str) -> u32 {
    let vao = ctx.gen_vertex_arrays(1)[0];
    ctx.bind_vertex_array(vao);
    let b = ctx.gen_buffers(1)[0];
    ctx.bind_buffer(GL_ARRAY_BUFFER, b);
    let bytes: Vec<u8> = FULL_QUAD.iter().flat_map(|f| f.to_le_bytes()).collect();
    let len = bytes.len() as isize;
    ctx.buffer_data(GL_ARRAY_BUFFER, len, Some(&bytes), GL_STATIC_DRAW);
    let loc = ctx.get_attrib_location(p, name);
    assert!(loc >= 0, "{name}");
    ctx.vertex_attrib_pointer(loc as u32, 2, GL_FLOAT, false, 0, ArrayData::Offset(0));
    ctx.enable_vertex_attrib_array(loc as u32);
    vao
}

/// A new framebuffer object, left bound, whose colour attachment 0 is a
/// `w`×`h` RGBA32F renderbuffer (exact floats to read back).
#[allow(dead_code)]
pub fn float_framebuffer(ctx: &mut Context, w: i32, h: i32) -> u32 {
    let rb = ctx.gen_renderbuffers(1)[0];
    ctx.bind_renderbuffer(GL_RENDERBUFFER, rb);
    ctx.renderbuffer_storage(GL_RENDERBUFFER, GL_RGBA32F, w, h);
    let fb = ctx.gen_framebuffers(1)[0];
    ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
    ctx.framebuffer_renderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    fb
}

/// Points attribute `loc` at the client array `data` of `size`-component
/// floats, tightly packed, and enables it.
#[allow(dead_code)]
pub fn float_array(ctx: &mut Context, loc: u32, size: i32, data: &[f32]) {
    ctx.vertex_attrib_pointer(loc, size, GL_FLOAT, false, 0, ArrayData::from_f32(data));
    ctx.enable_vertex_attrib_array(loc);
}

/// A buffer of `bytes` zero bytes bound to feedback binding `index`.
#[allow(dead_code)]
pub fn feedback_buffer(ctx: &mut Context, index: u32, bytes: usize) -> u32 {
    let b = ctx.gen_buffers(1)[0];
    ctx.bind_buffer(GL_TRANSFORM_FEEDBACK_BUFFER, b);
    ctx.buffer_data(
        GL_TRANSFORM_FEEDBACK_BUFFER,
        bytes as isize,
        None,
        GL_STREAM_READ,
    );
    ctx.bind_buffer_base(GL_TRANSFORM_FEEDBACK_BUFFER, index, b);
    b
}

#[allow(dead_code)]
pub fn floats(ctx: &mut Context, b: u32, n: usize) -> Vec<f32> {
    ctx.bind_buffer(GL_TRANSFORM_FEEDBACK_BUFFER, b);
    ctx.get_buffer_sub_data(GL_TRANSFORM_FEEDBACK_BUFFER, 0, (n * 4) as isize)
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect()
}
