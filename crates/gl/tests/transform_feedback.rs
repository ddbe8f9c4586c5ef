//! Transform feedback end to end (GL 3.3 §2.16): interleaved and separate
//! capture of vertex outputs into buffer objects, strips decomposed into
//! independent primitives, overflow, the primitive queries, rasterizer
//! discard, link errors and the API's errors.

use gl::enums::*;
use gl::{ArrayData, Context};

mod common;

const VS: &str = "#version 130\n\
    in float x;\n\
    out vec2 a;\n\
    out float b;\n\
    flat out int k;\n\
    void main() {\n\
      gl_Position = vec4(x, 0.0, 0.0, 1.0);\n\
      a = vec2(x, x * 10.0);\n\
      b = x + 100.0;\n\
      k = gl_VertexID;\n\
    }";
const FS: &str = "#version 130\n\
    out vec4 c;\n\
    void main() { c = vec4(0.0, 1.0, 0.0, 1.0); }";

/// A program over VS/FS capturing `names` in `mode`; Err: the link log.
fn program(ctx: &mut Context, names: &[&str], mode: u32) -> Result<u32, String> {
    let p = ctx.create_program();
    for (kind, src) in [(GL_VERTEX_SHADER, VS), (GL_FRAGMENT_SHADER, FS)] {
        let s = ctx.create_shader(kind);
        ctx.shader_source(s, &[src]);
        ctx.compile_shader(s);
        assert_eq!(ctx.get_shaderiv(s, GL_COMPILE_STATUS), 1);
        ctx.attach_shader(p, s);
    }
    ctx.bind_attrib_location(p, 0, "x");
    let names: Vec<String> = names.iter().map(|s| s.to_string()).collect();
    ctx.transform_feedback_varyings(p, &names, mode);
    ctx.link_program(p);
    if ctx.get_programiv(p, GL_LINK_STATUS) != 1 {
        return Err(ctx.get_program_info_log(p));
    }
    ctx.use_program(p);
    Ok(p)
}

fn xs(ctx: &mut Context, v: &[f32]) {
    ctx.vertex_attrib_pointer(0, 1, GL_FLOAT, false, 0, ArrayData::from_f32(v));
    ctx.enable_vertex_attrib_array(0);
}

#[test]
fn interleaved_capture_of_a_strip_as_triangles() {
    let mut ctx = Context::with_api(8, 8, gl::Api::GL33_COMPAT);
    let p = program(&mut ctx, &["b", "gl_Position", "k"], GL_INTERLEAVED_ATTRIBS).unwrap();
    assert_eq!(ctx.get_programiv(p, GL_TRANSFORM_FEEDBACK_VARYINGS), 3);
    assert_eq!(
        ctx.get_programiv(p, GL_TRANSFORM_FEEDBACK_BUFFER_MODE),
        GL_INTERLEAVED_ATTRIBS as i32
    );
    assert_eq!(
        ctx.get_programiv(p, GL_TRANSFORM_FEEDBACK_VARYING_MAX_LENGTH),
        12
    );
    let v = ctx.get_transform_feedback_varying(p, 1).unwrap();
    assert_eq!(
        (v.name.as_str(), v.size, v.ty),
        ("gl_Position", 1, GL_FLOAT_VEC4)
    );
    let v = ctx.get_transform_feedback_varying(p, 2).unwrap();
    assert_eq!((v.size, v.ty), (1, GL_INT));
    assert_eq!(ctx.get_transform_feedback_varying(p, 3), None);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);

    // 6 floats a vertex; room for 2 triangles of the strip's 3.
    let buf = common::feedback_buffer(&mut ctx, 0, 6 * 4 * 3 * 2 + 20);
    xs(&mut ctx, &[0.0, 0.25, 0.5, 0.75, 0.875]);
    let q = ctx.gen_queries(2);
    ctx.begin_query(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, q[0]);
    ctx.begin_query(GL_PRIMITIVES_GENERATED, q[1]);
    ctx.begin_transform_feedback(GL_TRIANGLES);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 5);
    ctx.end_transform_feedback();
    ctx.end_query(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
    ctx.end_query(GL_PRIMITIVES_GENERATED);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.take_draw_error(), None);
    assert_eq!(ctx.get_query_object(q[0], GL_QUERY_RESULT), Some(2));
    assert_eq!(ctx.get_query_object(q[1], GL_QUERY_RESULT), Some(3));
    let got = common::floats(&mut ctx, buf, 6 * 6);
    let x = [0.0f32, 0.25, 0.5, 0.75];
    // Triangles (0, 1, 2) and (2, 1, 3), the second reversed as the
    // strip's winding requires.
    for (slot, vertex) in [0usize, 1, 2, 2, 1, 3].into_iter().enumerate() {
        let r = &got[slot * 6..slot * 6 + 6];
        assert_eq!(r[0], x[vertex] + 100.0, "vertex {slot}");
        assert_eq!(&r[1..5], &[x[vertex], 0.0, 0.0, 1.0]);
        assert_eq!(r[5].to_bits(), vertex as u32);
    }
}

#[test]
fn separate_capture_lines_and_rasterizer_discard() {
    let mut ctx = Context::with_api(8, 8, gl::Api::GL33_COMPAT);
    program(&mut ctx, &["a", "b"], GL_SEPARATE_ATTRIBS).unwrap();
    let (ba, bb) = (
        common::feedback_buffer(&mut ctx, 0, 64),
        common::feedback_buffer(&mut ctx, 1, 64),
    );
    // Binding 1 over a range that starts 8 bytes in.
    ctx.bind_buffer_range(GL_TRANSFORM_FEEDBACK_BUFFER, 1, bb, 8, 16);
    xs(&mut ctx, &[0.5, -0.5, 0.25]);
    ctx.clear_color(0.0, 0.0, 0.0, 0.0);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    ctx.enable(GL_RASTERIZER_DISCARD);
    ctx.begin_transform_feedback(GL_LINES);
    // A line loop: 3 lines, of which the range of binding 1 (4 floats)
    // takes 2.
    ctx.draw_arrays(GL_LINE_LOOP, 0, 3);
    // Triangles do not match the feedback's lines, drawn or begun.
    ctx.draw_arrays(GL_TRIANGLES, 0, 3);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.begin(GL_QUADS);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    assert!(!ctx.in_begin_end());
    ctx.end_transform_feedback();
    ctx.disable(GL_RASTERIZER_DISCARD);
    let a = common::floats(&mut ctx, ba, 8);
    assert_eq!(a, vec![0.5, 5.0, -0.5, -5.0, -0.5, -5.0, 0.25, 2.5]);
    let b = common::floats(&mut ctx, bb, 6);
    assert_eq!(b, vec![0.0, 0.0, 100.5, 99.5, 99.5, 100.25]);
    // Nothing was drawn.
    assert_eq!(
        ctx.read_pixels_f32(0, 4, 8, 1)
            .iter()
            .map(|p| p[3])
            .sum::<f32>(),
        0.0
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}

#[test]
fn feedback_errors() {
    let mut ctx = Context::with_api(8, 8, gl::Api::GL33_COMPAT);
    // Link errors.
    assert!(program(&mut ctx, &["nope"], GL_INTERLEAVED_ATTRIBS).is_err());
    assert!(program(&mut ctx, &["a", "a"], GL_INTERLEAVED_ATTRIBS).is_err());
    assert!(program(&mut ctx, &["a[0]"], GL_INTERLEAVED_ATTRIBS).is_err());
    assert!(program(&mut ctx, &["gl_Position"], GL_SEPARATE_ATTRIBS).is_ok());
    // API errors.
    let p = ctx.create_program();
    ctx.transform_feedback_varyings(p, &["a".into()], GL_INTERLEAVED_ATTRIBS + 7);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    let five: Vec<String> = (0..5).map(|i| format!("v{i}")).collect();
    ctx.transform_feedback_varyings(p, &five, GL_SEPARATE_ATTRIBS);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.begin_transform_feedback(GL_TRIANGLE_STRIP);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    // No buffer bound at binding 0.
    program(&mut ctx, &["a"], GL_INTERLEAVED_ATTRIBS).unwrap();
    ctx.begin_transform_feedback(GL_POINTS);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.end_transform_feedback();
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    let b = common::feedback_buffer(&mut ctx, 0, 16);
    ctx.begin_transform_feedback(GL_POINTS);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    ctx.begin_transform_feedback(GL_POINTS);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.use_program(0);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.bind_buffer_base(GL_TRANSFORM_FEEDBACK_BUFFER, 0, b);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.end_transform_feedback();
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // A program without varyings cannot begin.
    program(&mut ctx, &[], GL_INTERLEAVED_ATTRIBS).unwrap();
    ctx.begin_transform_feedback(GL_POINTS);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
}

/// A GLSL 3.30 core vertex stage: gl_Position (a member of the
/// gl_PerVertex block there) and user outputs are captured.
#[test]
fn core_profile_outputs_and_gl_position() {
    let mut ctx = Context::with_api(8, 8, gl::Api::GL33_CORE);
    let vs = "#version 330 core\n\
        layout(location = 0) in vec4 pos;\n\
        out vec2 a;\n\
        out float b;\n\
        void main() { gl_Position = pos; a = pos.xy * 10.0; b = pos.x + 100.0; }";
    let fs = "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }";
    let p = ctx.create_program();
    for (kind, src) in [(GL_VERTEX_SHADER, vs), (GL_FRAGMENT_SHADER, fs)] {
        let s = ctx.create_shader(kind);
        ctx.shader_source(s, &[src]);
        ctx.compile_shader(s);
        ctx.attach_shader(p, s);
    }
    let names: Vec<String> = ["b", "gl_Position", "a"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    ctx.transform_feedback_varyings(p, &names, GL_INTERLEAVED_ATTRIBS);
    ctx.link_program(p);
    assert_eq!(
        ctx.get_programiv(p, GL_LINK_STATUS),
        1,
        "{}",
        ctx.get_program_info_log(p)
    );
}
