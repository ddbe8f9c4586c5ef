//! Helpers the gl integration tests share (each test file is its own
//! crate and takes this module with `mod common;`).

use gl::enums::*;
use gl::Context;

/// Compiles the stages given (a stage left out is fixed function), links
/// them and makes the program current; panics with the info log when a
/// stage does not compile or the program does not link.
pub fn linked_program(ctx: &mut Context, vs: Option<&str>, fs: Option<&str>) -> u32 {
    let stages: Vec<(u32, &str)> = [(GL_VERTEX_SHADER, vs), (GL_FRAGMENT_SHADER, fs)]
        .into_iter()
        .filter_map(|(kind, src)| Some((kind, src?)))
        .collect();
    linked_stages(ctx, &stages)
}

/// [`linked_program`] of shader objects of any kinds: (GL kind, source).
pub fn linked_stages(ctx: &mut Context, stages: &[(u32, &str)]) -> u32 {
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

/// [`linked_program`] of a vertex and a fragment shader.
#[allow(dead_code)]
pub fn program(ctx: &mut Context, vs: &str, fs: &str) -> u32 {
    linked_program(ctx, Some(vs), Some(fs))
}
