//! GL_ARB_separate_shader_objects through `gl::Context`: separable
//! programs, program pipeline objects and their errors, glProgramUniform*,
//! and draws whose stages come from different programs (vertex and
//! fragment; vertex, geometry and fragment; inputs matched by location).

use gl::enums::*;
use gl::{Api, ArrayData, Context};

const W: i32 = 16;
const H: i32 = 16;

/// A separable program of one stage made with glCreateShaderProgramv;
/// panics with its info log when it does not link.
fn separable(ctx: &mut Context, kind: u32, src: &str) -> u32 {
    let p = ctx.create_shader_programv(kind, &[src]);
    assert_ne!(p, 0);
    assert_eq!(
        ctx.get_programiv(p, GL_LINK_STATUS),
        1,
        "{}",
        ctx.get_program_info_log(p)
    );
    assert_eq!(ctx.get_programiv(p, GL_PROGRAM_SEPARABLE), 1);
    p
}

/// A full-window quad in attribute `pos` of program `vs_prog`, from a
/// buffer object in a vertex array object (what a core context draws).
fn quad(ctx: &mut Context, vs_prog: u32) {
    let vao = ctx.gen_vertex_arrays(1)[0];
    ctx.bind_vertex_array(vao);
    let loc = ctx.get_attrib_location(vs_prog, "pos");
    assert!(loc >= 0);
    let verts = [-1.0f32, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0];
    let bytes: Vec<u8> = verts.iter().flat_map(|v| v.to_le_bytes()).collect();
    let buf = ctx.gen_buffers(1)[0];
    ctx.bind_buffer(GL_ARRAY_BUFFER, buf);
    ctx.buffer_data(
        GL_ARRAY_BUFFER,
        bytes.len() as isize,
        Some(&bytes),
        GL_STATIC_DRAW,
    );
    ctx.vertex_attrib_pointer(loc as u32, 2, GL_FLOAT, false, 0, ArrayData::Offset(0));
    ctx.enable_vertex_attrib_array(loc as u32);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}

fn pixel(ctx: &mut Context, x: i32, y: i32) -> [u8; 4] {
    let p = ctx.read_pixels_f32(x, y, 1, 1)[0];
    p.map(|c| (c * 255.0).round() as u8)
}

const VS: &str = "#version 150
in vec2 pos;
out vec4 color;
void main() { gl_Position = vec4(pos, 0.0, 1.0); color = vec4(0.0, 1.0, 0.0, 1.0); }";

const FS: &str = "#version 150
uniform vec4 tint;
in vec4 color;
out vec4 frag;
void main() { frag = color + tint; }";

#[test]
fn extension_and_tokens_are_offered() {
    for api in [Api::GL21, Api::GL33_CORE, Api::GL33_COMPAT] {
        let mut ctx = Context::with_api(W, H, api);
        assert!(
            api.extensions().contains(&"GL_ARB_separate_shader_objects"),
            "{api:?}"
        );
        assert_eq!(ctx.get_integerv(GL_PROGRAM_PIPELINE_BINDING), vec![0]);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
    }
}

#[test]
fn pipeline_objects_and_their_errors() {
    let mut ctx = Context::with_api(W, H, Api::GL33_CORE);
    let names = ctx.gen_program_pipelines(2);
    assert_eq!(names.len(), 2);
    let (a, b) = (names[0], names[1]);
    assert_eq!(ctx.get_program_pipeline_info_log(a), "");
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // Generated names hold no object until first bound or used.
    assert!(!ctx.is_program_pipeline(a));
    ctx.bind_program_pipeline(a);
    assert!(ctx.is_program_pipeline(a));
    assert_eq!(
        ctx.get_integerv(GL_PROGRAM_PIPELINE_BINDING),
        vec![a as i32]
    );
    assert_eq!(ctx.get_program_pipelineiv(b, GL_VALIDATE_STATUS), 0);
    assert!(ctx.is_program_pipeline(b), "a query creates the object");
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // Names never generated.
    ctx.bind_program_pipeline(999);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.use_program_stages(999, GL_VERTEX_SHADER_BIT, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.active_shader_program(999, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.validate_program_pipeline(999);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    assert_eq!(ctx.get_program_pipelineiv(999, GL_ACTIVE_PROGRAM), 0);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    assert_eq!(ctx.get_program_pipeline_info_log(999), "");
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    assert_eq!(ctx.gen_program_pipelines(-1), Vec::<u32>::new());
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    // Bad pnames and stage bits.
    assert_eq!(ctx.get_program_pipelineiv(a, GL_LINK_STATUS), 0);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    ctx.use_program_stages(a, 0x100, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.use_program_stages(a, GL_TESS_CONTROL_SHADER_BIT, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    ctx.use_program_stages(a, GL_ALL_SHADER_BITS, 0);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // Programs: unknown names, shaders, unlinked and unseparable ones.
    ctx.use_program_stages(a, GL_VERTEX_SHADER_BIT, 12345);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    let shader = ctx.create_shader(GL_VERTEX_SHADER);
    ctx.use_program_stages(a, GL_VERTEX_SHADER_BIT, shader);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    let unlinked = ctx.create_program();
    ctx.use_program_stages(a, GL_VERTEX_SHADER_BIT, unlinked);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.active_shader_program(a, unlinked);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    let s = ctx.create_shader(GL_VERTEX_SHADER);
    ctx.shader_source(s, &[VS]);
    ctx.compile_shader(s);
    let whole = ctx.create_program();
    ctx.attach_shader(whole, s);
    ctx.link_program(whole);
    assert_eq!(ctx.get_programiv(whole, GL_LINK_STATUS), 1);
    assert_eq!(ctx.get_programiv(whole, GL_PROGRAM_SEPARABLE), 0);
    ctx.use_program_stages(a, GL_VERTEX_SHADER_BIT, whole);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    // glActiveShaderProgram takes any linked program.
    ctx.active_shader_program(a, whole);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(
        ctx.get_program_pipelineiv(a, GL_ACTIVE_PROGRAM),
        whole as i32
    );
    // GL_PROGRAM_SEPARABLE takes TRUE or FALSE only.
    ctx.program_parameteri(whole, GL_PROGRAM_SEPARABLE, 2);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.program_parameteri(whole, GL_PROGRAM_SEPARABLE, 1);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.get_programiv(whole, GL_PROGRAM_SEPARABLE), 1);
    // ...and counts from the next link.
    ctx.use_program_stages(a, GL_VERTEX_SHADER_BIT, whole);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.link_program(whole);
    ctx.use_program_stages(a, GL_ALL_SHADER_BITS, whole);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // Only the stages the program has are taken from it.
    assert_eq!(
        ctx.get_program_pipelineiv(a, GL_VERTEX_SHADER),
        whole as i32
    );
    assert_eq!(ctx.get_program_pipelineiv(a, GL_FRAGMENT_SHADER), 0);
    assert_eq!(ctx.get_program_pipelineiv(a, GL_GEOMETRY_SHADER), 0);
    // A program in a pipeline outlives glDeleteProgram until released.
    ctx.delete_program(whole);
    assert!(ctx.is_program(whole));
    assert_eq!(ctx.get_programiv(whole, GL_DELETE_STATUS), 1);
    ctx.use_program_stages(a, GL_VERTEX_SHADER_BIT, 0);
    assert!(ctx.is_program(whole), "still the active program");
    ctx.active_shader_program(a, 0);
    assert!(!ctx.is_program(whole));
    // Deleting the bound pipeline unbinds it; unknown names are ignored.
    ctx.delete_program_pipelines(&[a, 0, 4242]);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert!(!ctx.is_program_pipeline(a));
    assert_eq!(ctx.get_integerv(GL_PROGRAM_PIPELINE_BINDING), vec![0]);
    ctx.bind_program_pipeline(a);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    // Inside glBegin/glEnd (a compatibility context).
    let mut compat = Context::with_api(W, H, Api::GL33_COMPAT);
    let p = compat.gen_program_pipelines(1)[0];
    compat.begin(GL_POINTS);
    compat.bind_program_pipeline(p);
    compat.end();
    assert_eq!(compat.get_error(), GL_INVALID_OPERATION);
}

#[test]
fn create_shader_programv_keeps_the_compile_log() {
    let mut ctx = Context::with_api(W, H, Api::GL33_CORE);
    assert_eq!(ctx.create_shader_programv(0x1234, &["void main() {}"]), 0);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    let p = ctx.create_shader_programv(GL_FRAGMENT_SHADER, &["#version 150\nvoid main() { x }"]);
    assert_ne!(p, 0);
    assert_eq!(ctx.get_programiv(p, GL_LINK_STATUS), 0);
    assert!(ctx.get_program_info_log(p).contains("error"));
    assert_eq!(ctx.get_attached_shaders(p), Vec::<u32>::new());
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}

#[test]
fn a_pipeline_of_separate_vertex_and_fragment_programs_draws() {
    let mut ctx = Context::with_api(W, H, Api::GL33_CORE);
    let vs = separable(&mut ctx, GL_VERTEX_SHADER, VS);
    let fs = separable(&mut ctx, GL_FRAGMENT_SHADER, FS);
    let pipe = ctx.gen_program_pipelines(1)[0];
    ctx.use_program_stages(pipe, GL_VERTEX_SHADER_BIT, vs);
    ctx.use_program_stages(pipe, GL_FRAGMENT_SHADER_BIT, fs);
    ctx.bind_program_pipeline(pipe);
    quad(&mut ctx, vs);
    // glUniform* without an active program is an error; with one it sets
    // that program's uniform; glProgramUniform* names its program.
    let tint = ctx.get_uniform_location(fs, "tint");
    ctx.uniform_4f(tint, 1.0, 0.0, 0.0, 0.0);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.active_shader_program(pipe, fs);
    ctx.uniform_4f(tint, 1.0, 0.0, 0.0, 0.0);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.take_draw_error(), None);
    assert_eq!(pixel(&mut ctx, 8, 8), [255, 255, 0, 255]);
    ctx.program_uniform_4f(fs, tint, 0.0, 0.0, 1.0, 0.0);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(pixel(&mut ctx, 8, 8), [0, 255, 255, 255]);
    // glProgramUniform*'s own errors.
    ctx.program_uniform_4f(777, tint, 0.0, 0.0, 0.0, 0.0);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    let unlinked = ctx.create_program();
    ctx.program_uniform_4f(unlinked, tint, 0.0, 0.0, 0.0, 0.0);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.program_uniform_3f(fs, tint, 0.0, 0.0, 0.0);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.program_uniform_matrix_2fv(fs, tint, 1, false, &[0.0; 4]);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    assert_eq!(ctx.get_uniformfv(fs, tint), vec![0.0, 0.0, 1.0, 0.0]);
    // glUseProgram wins over the bound pipeline.
    let s = ctx.create_shader(GL_FRAGMENT_SHADER);
    ctx.shader_source(
        s,
        &["#version 150\nout vec4 frag;\nvoid main() { frag = vec4(1.0, 0.0, 1.0, 1.0); }"],
    );
    ctx.compile_shader(s);
    let v = ctx.create_shader(GL_VERTEX_SHADER);
    ctx.shader_source(v, &[VS]);
    ctx.compile_shader(v);
    let whole = ctx.create_program();
    ctx.attach_shader(whole, v);
    ctx.attach_shader(whole, s);
    let pos = ctx.get_attrib_location(vs, "pos") as u32;
    ctx.bind_attrib_location(whole, pos, "pos");
    ctx.link_program(whole);
    ctx.use_program(whole);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(pixel(&mut ctx, 8, 8), [255, 0, 255, 255]);
    ctx.use_program(0);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(pixel(&mut ctx, 8, 8), [0, 255, 255, 255]);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}

#[test]
fn vertex_geometry_and_fragment_stages_from_three_programs() {
    let mut ctx = Context::with_api(W, H, Api::GL33_CORE);
    let vs = separable(
        &mut ctx,
        GL_VERTEX_SHADER,
        "#version 150
in vec2 pos;
out vec4 color;
void main() { gl_ClipDistance[0] = 1.0; gl_Position = vec4(pos, 0.0, 1.0); color = vec4(0.0, 0.0, 1.0, 1.0); }",
    );
    // The geometry stage moves the quad to the right half and adds red.
    let gs = separable(
        &mut ctx,
        GL_GEOMETRY_SHADER,
        "#version 150
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec4 color[];
out vec4 c;
void main() {
    for (int i = 0; i < 3; i++) {
        vec4 p = gl_in[i].gl_Position;
        gl_Position = vec4(p.x * 0.5 + 0.5, p.yzw);
        c = color[i] + vec4(1.0, 0.0, 0.0, 0.0);
        EmitVertex();
    }
}",
    );
    let fs = separable(
        &mut ctx,
        GL_FRAGMENT_SHADER,
        "#version 150\nin vec4 c;\nout vec4 frag;\nvoid main() { frag = c; }",
    );
    let pipe = ctx.gen_program_pipelines(1)[0];
    for (bit, p) in [
        (GL_VERTEX_SHADER_BIT, vs),
        (GL_GEOMETRY_SHADER_BIT, gs),
        (GL_FRAGMENT_SHADER_BIT, fs),
    ] {
        ctx.use_program_stages(pipe, bit, p);
    }
    ctx.validate_program_pipeline(pipe);
    assert_eq!(
        ctx.get_program_pipelineiv(pipe, GL_VALIDATE_STATUS),
        1,
        "{}",
        ctx.get_program_pipeline_info_log(pipe)
    );
    ctx.bind_program_pipeline(pipe);
    quad(&mut ctx, vs);
    ctx.clear_color(0.0, 0.0, 0.0, 0.0);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(pixel(&mut ctx, 12, 8), [255, 0, 255, 255]);
    assert_eq!(pixel(&mut ctx, 3, 8), [0, 0, 0, 0]);
    // Without its vertex stage the pipeline does not validate, and a
    // draw through it is GL_INVALID_OPERATION.
    ctx.use_program_stages(pipe, GL_VERTEX_SHADER_BIT, 0);
    ctx.validate_program_pipeline(pipe);
    assert_eq!(ctx.get_program_pipelineiv(pipe, GL_VALIDATE_STATUS), 0);
    assert!(ctx.get_program_pipeline_info_log(pipe).contains("vertex"));
    assert!(ctx.get_program_pipelineiv(pipe, GL_INFO_LOG_LENGTH) > 1);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
}

#[test]
fn a_program_of_two_stages_must_supply_both() {
    let mut ctx = Context::with_api(W, H, Api::GL33_CORE);
    let p = ctx.create_program();
    ctx.program_parameteri(p, GL_PROGRAM_SEPARABLE, 1);
    for (kind, src) in [
        (GL_VERTEX_SHADER, VS),
        (
            GL_FRAGMENT_SHADER,
            "#version 150\nin vec4 color;\nout vec4 frag;\nvoid main() { frag = color; }",
        ),
    ] {
        let s = ctx.create_shader(kind);
        ctx.shader_source(s, &[src]);
        ctx.compile_shader(s);
        ctx.attach_shader(p, s);
    }
    ctx.link_program(p);
    assert_eq!(ctx.get_programiv(p, GL_LINK_STATUS), 1);
    let fs = separable(&mut ctx, GL_FRAGMENT_SHADER, FS);
    let pipe = ctx.gen_program_pipelines(1)[0];
    ctx.use_program_stages(pipe, GL_ALL_SHADER_BITS, p);
    ctx.validate_program_pipeline(pipe);
    assert_eq!(ctx.get_program_pipelineiv(pipe, GL_VALIDATE_STATUS), 1);
    ctx.use_program_stages(pipe, GL_FRAGMENT_SHADER_BIT, fs);
    ctx.validate_program_pipeline(pipe);
    assert_eq!(ctx.get_program_pipelineiv(pipe, GL_VALIDATE_STATUS), 0);
}

#[test]
fn inputs_with_a_location_match_outputs_by_location() {
    let mut ctx = Context::with_api(W, H, Api::GL33_CORE);
    let vs = separable(
        &mut ctx,
        GL_VERTEX_SHADER,
        "#version 150
#extension GL_ARB_separate_shader_objects : require
in vec2 pos;
layout(location = 0) out vec4 first;
layout(location = 1) out vec4 second[2];
void main() {
    gl_Position = vec4(pos, 0.0, 1.0);
    first = vec4(1.0, 0.0, 0.0, 1.0);
    second[0] = vec4(0.0, 1.0, 0.0, 1.0);
    second[1] = vec4(0.0, 0.0, 1.0, 1.0);
}",
    );
    // Other names, and the element of `second' at location 2.
    let fs = separable(
        &mut ctx,
        GL_FRAGMENT_SHADER,
        "#version 150
#extension GL_ARB_separate_shader_objects : require
layout(location = 2) in vec4 b;
layout(location = 0) in vec4 r;
out vec4 frag;
void main() { frag = r * 0.5 + b * 0.25; }",
    );
    let pipe = ctx.gen_program_pipelines(1)[0];
    ctx.use_program_stages(pipe, GL_VERTEX_SHADER_BIT, vs);
    ctx.use_program_stages(pipe, GL_FRAGMENT_SHADER_BIT, fs);
    ctx.bind_program_pipeline(pipe);
    quad(&mut ctx, vs);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(pixel(&mut ctx, 8, 8), [128, 0, 64, 191]);
}

/// GL_EXT_separate_shader_objects (compatibility contexts): per-stage
/// attachment points that glUseProgram sets all at once, the active
/// program as GL_CURRENT_PROGRAM, their precedence over a bound pipeline,
/// and a geometry stage linked without a vertex stage when it reads only
/// built-in inputs.
#[test]
fn ext_attachment_points() {
    assert!(!Api::GL33_CORE
        .extensions()
        .contains(&"GL_EXT_separate_shader_objects"));
    for api in [Api::GL21, Api::GL33_COMPAT] {
        assert!(api.extensions().contains(&"GL_EXT_separate_shader_objects"));
    }
    let mut core = Context::with_api(W, H, Api::GL33_CORE);
    core.use_shader_program_ext(GL_VERTEX_SHADER, 0);
    assert_eq!(core.get_error(), GL_INVALID_OPERATION);

    let mut ctx = Context::with_api(W, H, Api::GL33_COMPAT);
    let vs = ctx.create_shader_program_ext(GL_VERTEX_SHADER, VS);
    let fs = ctx.create_shader_program_ext(GL_FRAGMENT_SHADER, FS);
    assert_eq!(ctx.get_programiv(fs, GL_LINK_STATUS), 1);
    assert_eq!(ctx.get_programiv(fs, GL_PROGRAM_SEPARABLE), 0);
    ctx.use_shader_program_ext(GL_VERTEX_SHADER, vs);
    ctx.use_shader_program_ext(GL_FRAGMENT_SHADER, fs);
    assert_eq!(ctx.get_integerv(GL_CURRENT_PROGRAM), vec![0]);
    ctx.active_program_ext(fs);
    assert_eq!(ctx.get_integerv(GL_CURRENT_PROGRAM), vec![fs as i32]);
    let tint = ctx.get_uniform_location(fs, "tint");
    ctx.uniform_4f(tint, 1.0, 0.0, 0.0, 0.0);
    quad(&mut ctx, vs);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(pixel(&mut ctx, 8, 8), [255, 255, 0, 255]);
    // They take precedence over a bound pipeline (of no program).
    let pipe = ctx.gen_program_pipelines(1)[0];
    ctx.bind_program_pipeline(pipe);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // Errors: an unknown type, an unknown name, an unlinked program.
    ctx.use_shader_program_ext(0x1234, vs);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    ctx.active_program_ext(4242);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    let unlinked = ctx.create_program();
    ctx.use_shader_program_ext(GL_VERTEX_SHADER, unlinked);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    // A program deleted while attached lives until detached.
    ctx.delete_program(vs);
    assert!(ctx.is_program(vs));
    // glUseProgram sets every attachment point.
    ctx.use_program(0);
    assert!(!ctx.is_program(vs));
    assert_eq!(ctx.get_integerv(GL_CURRENT_PROGRAM), vec![0]);
    // Agreeing attachment points are one current program again.
    ctx.use_shader_program_ext(GL_VERTEX_SHADER, fs);
    ctx.use_shader_program_ext(GL_GEOMETRY_SHADER, fs);
    ctx.use_shader_program_ext(GL_FRAGMENT_SHADER, fs);
    ctx.active_program_ext(fs);
    assert_eq!(ctx.get_integerv(GL_CURRENT_PROGRAM), vec![fs as i32]);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);

    // A geometry shader reading built-in inputs only links alone.
    let gs = |user: &str| {
        format!(
            "#version 120\n#extension GL_EXT_geometry_shader4 : enable\n{user}\nvoid main() {{ for (int i = 0; i < 3; i++) {{ gl_Position = gl_PositionIn[i]; EmitVertex(); }} }}"
        )
    };
    for (decl, links) in [("", 1), ("varying in vec4 pos[3];", 0)] {
        let s = ctx.create_shader(GL_GEOMETRY_SHADER);
        ctx.shader_source(s, &[&gs(decl)]);
        ctx.compile_shader(s);
        let p = ctx.create_program();
        ctx.attach_shader(p, s);
        ctx.program_parameteri(p, GL_GEOMETRY_VERTICES_OUT_EXT, 3);
        ctx.link_program(p);
        assert_eq!(
            ctx.get_programiv(p, GL_LINK_STATUS),
            links,
            "{decl}: {}",
            ctx.get_program_info_log(p)
        );
    }
}
