//! GL 3.0-3.3 state, end to end: the provoking-vertex convention for flat
//! values (plain, restarted and instanced draws), fragment-output
//! locations, glClearBuffer*, indexed capabilities and colour masks.

use gl::enums::*;
use gl::{ArrayData, Context};

mod common;
use common::program;

fn read_depth(ctx: &mut Context, x: i32, y: i32) -> f32 {
    let mut b = [0u8; 4];
    ctx.read_pixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &mut b);
    f32::from_le_bytes(b)
}

fn pixel(ctx: &mut Context, x: i32, y: i32) -> [u8; 4] {
    ctx.read_pixels_f32(x, y, 1, 1)[0].map(|c| (c * 255.0).round() as u8)
}

/// Vertex k of a strip along x carries the colour `k / 8` in red, flat.
const FLAT_VS: &str = "#version 130\n\
    in vec2 pos;\n\
    flat out float k;\n\
    void main() { gl_Position = vec4(pos, 0.0, 1.0); k = float(gl_VertexID) / 8.0; }";
const FLAT_FS: &str = "#version 130\n\
    flat in float k;\n\
    out vec4 color;\n\
    void main() { color = vec4(k, 0.0, 0.0, 1.0); }";

/// A strip of 4 vertices: triangle 0 (vertices 0, 1, 2) over the left
/// of the window, triangle 1 (1, 2, 3) over the right.
const STRIP: [f32; 8] = [-1.0, -1.0, -1.0, 1.0, 1.0, -1.0, 1.0, 1.0];

fn red_at(ctx: &mut Context, x: i32, y: i32) -> u8 {
    pixel(ctx, x, y)[0]
}

#[test]
fn provoking_vertex_picks_the_flat_value() {
    let mut ctx = Context::with_api(16, 16, gl::Api::GL33_COMPAT);
    let p = program(&mut ctx, FLAT_VS, FLAT_FS);
    let pos = ctx.get_attrib_location(p, "pos") as u32;
    common::float_array(&mut ctx, pos, 2, &STRIP);
    assert_eq!(
        ctx.get_integerv(GL_PROVOKING_VERTEX),
        vec![GL_LAST_VERTEX_CONVENTION as i32]
    );
    assert_eq!(
        ctx.get_booleanv(GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION),
        vec![true]
    );
    let v = |k: u8| (k as f32 / 8.0 * 255.0).round() as u8;
    for (conv, left, right) in [
        (GL_LAST_VERTEX_CONVENTION, v(2), v(3)),
        (GL_FIRST_VERTEX_CONVENTION, v(0), v(1)),
    ] {
        ctx.provoking_vertex(conv);
        assert_eq!(ctx.get_integerv(GL_PROVOKING_VERTEX), vec![conv as i32]);
        // The strip itself.
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
        assert_eq!(
            (red_at(&mut ctx, 1, 8), red_at(&mut ctx, 14, 8)),
            (left, right)
        );
        // The same strip with a restart index at its end: the draw is
        // split into independent triangles.
        ctx.enable(GL_PRIMITIVE_RESTART);
        ctx.primitive_restart_index(9);
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.draw_elements(
            GL_TRIANGLE_STRIP,
            5,
            GL_UNSIGNED_INT,
            ArrayData::from_u32(&[0, 1, 2, 3, 9]),
        );
        ctx.disable(GL_PRIMITIVE_RESTART);
        assert_eq!(
            (red_at(&mut ctx, 1, 8), red_at(&mut ctx, 14, 8)),
            (left, right)
        );
        // Two instances: batched into one draw of independent triangles.
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.draw_arrays_instanced(GL_TRIANGLE_STRIP, 0, 4, 2);
        assert_eq!(
            (red_at(&mut ctx, 1, 8), red_at(&mut ctx, 14, 8)),
            (left, right)
        );
        // A fan 0, 1, 3, 2 covers the window with triangles (0, 1, 3)
        // and (0, 3, 2): first convention 1 and 3, last 3 and 2.
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.draw_elements(
            GL_TRIANGLE_FAN,
            4,
            GL_UNSIGNED_INT,
            ArrayData::from_u32(&[0, 1, 3, 2]),
        );
        let fan = (red_at(&mut ctx, 2, 12), red_at(&mut ctx, 12, 2));
        if conv == GL_FIRST_VERTEX_CONVENTION {
            assert_eq!(fan, (v(1), v(3)));
        } else {
            assert_eq!(fan, (v(3), v(2)));
        }
    }
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    ctx.provoking_vertex(GL_FLAT);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    assert_eq!(
        ctx.get_integerv(GL_PROVOKING_VERTEX),
        vec![GL_FIRST_VERTEX_CONVENTION as i32]
    );
}

/// A framebuffer object with `n` RGBA8 colour renderbuffers of 8x8,
/// drawing to all of them (output i to attachment i).
fn fbo(ctx: &mut Context, n: usize) -> u32 {
    let f = ctx.gen_framebuffers(1)[0];
    ctx.bind_framebuffer(GL_FRAMEBUFFER, f);
    let rbs = ctx.gen_renderbuffers(n as i32);
    let mut bufs = Vec::new();
    for (i, rb) in rbs.into_iter().enumerate() {
        ctx.bind_renderbuffer(GL_RENDERBUFFER, rb);
        ctx.renderbuffer_storage(GL_RENDERBUFFER, GL_RGBA8, 8, 8);
        let at = GL_COLOR_ATTACHMENT0 + i as u32;
        ctx.framebuffer_renderbuffer(GL_FRAMEBUFFER, at, GL_RENDERBUFFER, rb);
        bufs.push(at);
    }
    ctx.draw_buffers(&bufs);
    assert_eq!(
        ctx.check_framebuffer_status(GL_FRAMEBUFFER),
        GL_FRAMEBUFFER_COMPLETE
    );
    f
}

/// Reads attachment `i` at (4, 4).
fn attachment_pixel(ctx: &mut Context, i: u32) -> [u8; 4] {
    ctx.read_buffer(GL_COLOR_ATTACHMENT0 + i);
    pixel(ctx, 4, 4)
}

const QUAD_VS: &str = "#version 130\n\
    in vec2 pos;\n\
    void main() { gl_Position = vec4(pos, 0.0, 1.0); }";

fn quad_program(ctx: &mut Context, fs: &str, bind: &[(&str, u32)]) -> Result<u32, String> {
    let p = common::attached(ctx, Some(QUAD_VS), Some(fs));
    ctx.bind_attrib_location(p, 0, "pos");
    for &(name, loc) in bind {
        ctx.bind_frag_data_location(p, loc, name);
    }
    ctx.link_program(p);
    if ctx.get_programiv(p, GL_LINK_STATUS) != 1 {
        return Err(ctx.get_program_info_log(p));
    }
    ctx.use_program(p);
    common::float_array(ctx, 0, 2, &STRIP);
    Ok(p)
}

const TWO_OUTPUTS: &str = "#version 130\n\
    out vec4 a;\n\
    out vec4 b;\n\
    void main() { a = vec4(1.0, 0.0, 0.0, 1.0); b = vec4(0.0, 1.0, 0.0, 1.0); }";

const RED: [u8; 4] = [255, 0, 0, 255];
const GREEN: [u8; 4] = [0, 255, 0, 255];

#[test]
fn frag_data_locations_place_outputs_on_draw_buffers() {
    let mut ctx = Context::with_api(8, 8, gl::Api::GL33_COMPAT);
    fbo(&mut ctx, 2);
    // Declaration order without bindings.
    let p = quad_program(&mut ctx, TWO_OUTPUTS, &[]).unwrap();
    assert_eq!(ctx.get_frag_data_location(p, "a"), 0);
    assert_eq!(ctx.get_frag_data_location(p, "b"), 1);
    assert_eq!(ctx.get_frag_data_location(p, "c"), -1);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(attachment_pixel(&mut ctx, 0), RED);
    assert_eq!(attachment_pixel(&mut ctx, 1), GREEN);
    // Bound the other way round.
    let p = quad_program(&mut ctx, TWO_OUTPUTS, &[("a", 1), ("b", 0)]).unwrap();
    assert_eq!(ctx.get_frag_data_location(p, "a"), 1);
    assert_eq!(ctx.get_frag_data_location(p, "b"), 0);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(attachment_pixel(&mut ctx, 0), GREEN);
    assert_eq!(attachment_pixel(&mut ctx, 1), RED);
    // Only one bound: the other takes the free location.
    let p = quad_program(&mut ctx, TWO_OUTPUTS, &[("b", 0)]).unwrap();
    assert_eq!(ctx.get_frag_data_location(p, "a"), 1);
    // A layout qualifier wins over a binding.
    let fs = "#version 330\n\
        layout(location = 1) out vec4 a;\n\
        out vec4 b[2];\n\
        void main() { a = vec4(1.0, 0.0, 0.0, 1.0); b[0] = vec4(0.0); b[1] = vec4(0.0); }";
    let p = quad_program(&mut ctx, fs, &[("a", 0)]).unwrap();
    assert_eq!(ctx.get_frag_data_location(p, "a"), 1);
    assert_eq!(ctx.get_frag_data_location(p, "b"), 2);
    assert_eq!(ctx.get_frag_data_location(p, "b[1]"), 3);
    assert_eq!(ctx.get_frag_data_location(p, "b[2]"), -1);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // Link errors: two outputs on one location, one past the draw buffers.
    assert!(quad_program(&mut ctx, TWO_OUTPUTS, &[("a", 1), ("b", 1)]).is_err());
    let fs = "#version 130\nout vec4 a[2];\nvoid main() { a[0] = vec4(1.0); a[1] = vec4(1.0); }";
    assert!(quad_program(&mut ctx, fs, &[("a", 7)]).is_err());
    // API errors.
    ctx.bind_frag_data_location(p, 8, "a");
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.bind_frag_data_location(p, 0, "gl_FragColor");
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    let unlinked = ctx.create_program();
    assert_eq!(ctx.get_frag_data_location(unlinked, "a"), -1);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
}

#[test]
fn per_buffer_blending_masks_and_clears() {
    let mut ctx = Context::with_api(8, 8, gl::Api::GL33_COMPAT);
    fbo(&mut ctx, 2);
    quad_program(&mut ctx, TWO_OUTPUTS, &[]).unwrap();
    // Buffer 1 keeps its alpha and blue; blending (additive) only on 0.
    ctx.clear_color(0.0, 0.0, 1.0, 0.0);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    ctx.color_maski(1, true, true, false, false);
    assert_eq!(
        ctx.get_indexed(GL_COLOR_WRITEMASK, 1),
        Some(vec![1, 1, 0, 0])
    );
    assert_eq!(ctx.get_indexed(GL_COLOR_WRITEMASK, 0), Some(vec![1; 4]));
    ctx.blend_func(GL_ONE, GL_ONE);
    ctx.enablei(GL_BLEND, 0);
    assert!(ctx.is_enabledi(GL_BLEND, 0));
    assert!(!ctx.is_enabledi(GL_BLEND, 1));
    assert!(ctx.is_enabled(GL_BLEND));
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(attachment_pixel(&mut ctx, 0), [255, 0, 255, 255]);
    assert_eq!(attachment_pixel(&mut ctx, 1), [0, 255, 255, 0]);
    // glClear honours each buffer's mask.
    ctx.clear_color(0.5, 0.5, 0.5, 0.5);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    assert_eq!(attachment_pixel(&mut ctx, 0), [128; 4]);
    assert_eq!(attachment_pixel(&mut ctx, 1), [128, 128, 255, 0]);
    // glClearBufferfv clears one draw buffer.
    ctx.color_mask(true, true, true, true);
    ctx.clear_bufferfv(GL_COLOR, 1, &[0.0, 0.0, 1.0, 1.0]);
    assert_eq!(attachment_pixel(&mut ctx, 0), [128; 4]);
    assert_eq!(attachment_pixel(&mut ctx, 1), [0, 0, 255, 255]);
    // glDisable(GL_BLEND) turns every buffer's off; glEnable every one on.
    ctx.enable(GL_BLEND);
    assert!(ctx.is_enabledi(GL_BLEND, 7));
    ctx.disable(GL_BLEND);
    assert!(!ctx.is_enabledi(GL_BLEND, 0));
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // Errors.
    ctx.enablei(GL_DEPTH_TEST, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    ctx.enablei(GL_BLEND, 8);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.color_maski(8, true, true, true, true);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    assert_eq!(ctx.get_indexed(GL_COLOR_WRITEMASK, 8), None);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
}

#[test]
fn clear_buffer_depth_stencil_and_errors() {
    let mut ctx = Context::with_api(8, 8, gl::Api::GL33_COMPAT);
    ctx.clear_bufferfi(GL_DEPTH_STENCIL, 0, 0.25, 7);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    let depth = read_depth(&mut ctx, 4, 4);
    assert!((depth - 0.25).abs() < 1e-6, "{depth}");
    ctx.clear_bufferfv(GL_DEPTH, 0, &[2.0]);
    assert_eq!(read_depth(&mut ctx, 4, 4), 1.0);
    ctx.clear_bufferiv(GL_STENCIL, 0, &[3]);
    // The stencil test passes where the value is 3.
    ctx.enable(GL_STENCIL_TEST);
    ctx.stencil_func(GL_EQUAL, 3, 0xff);
    ctx.clear_bufferfv(GL_COLOR, 0, &[0.0, 1.0, 0.0, 1.0]);
    assert_eq!(pixel(&mut ctx, 4, 4), GREEN);
    ctx.disable(GL_STENCIL_TEST);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    for (f, err) in [
        (
            Box::new(|c: &mut Context| c.clear_bufferiv(GL_DEPTH, 0, &[0]))
                as Box<dyn Fn(&mut Context)>,
            GL_INVALID_ENUM,
        ),
        (
            Box::new(|c: &mut Context| c.clear_bufferfv(GL_STENCIL, 0, &[0.0])),
            GL_INVALID_ENUM,
        ),
        (
            Box::new(|c: &mut Context| c.clear_bufferuiv(GL_DEPTH, 0, &[0])),
            GL_INVALID_ENUM,
        ),
        (
            Box::new(|c: &mut Context| c.clear_bufferfi(GL_DEPTH, 0, 0.0, 0)),
            GL_INVALID_ENUM,
        ),
        (
            Box::new(|c: &mut Context| c.clear_bufferfv(GL_DEPTH, 1, &[0.0])),
            GL_INVALID_VALUE,
        ),
        (
            Box::new(|c: &mut Context| c.clear_bufferfi(GL_DEPTH_STENCIL, 1, 0.0, 0)),
            GL_INVALID_VALUE,
        ),
        (
            Box::new(|c: &mut Context| c.clear_bufferfv(GL_COLOR, 8, &[0.0; 4])),
            GL_INVALID_VALUE,
        ),
        (
            Box::new(|c: &mut Context| c.clear_bufferfv(GL_COLOR, -1, &[0.0; 4])),
            GL_INVALID_VALUE,
        ),
    ] {
        f(&mut ctx);
        assert_eq!(ctx.get_error(), err);
    }
}

#[test]
fn depth_clamp_replaces_near_and_far_clipping() {
    let mut ctx = Context::with_api(8, 8, gl::Api::GL33_COMPAT);
    let quad = |ctx: &mut Context, z: f32| {
        ctx.begin(GL_QUADS);
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            ctx.vertex_3f(x, y, z);
        }
        ctx.end();
    };
    ctx.enable(GL_DEPTH_TEST);
    ctx.clear_depth(0.5);
    ctx.color_4f(0.0, 1.0, 0.0, 1.0);
    for (clamp, z, drawn, depth) in [
        // In front of the near plane: clipped away, or drawn at depth 0.
        (false, -3.0, false, 0.5),
        (true, -3.0, true, 0.0),
        // Behind the far plane: clipped, or at depth 1 (failing GL_LESS).
        (false, 3.0, false, 0.5),
        (true, 3.0, false, 0.5),
    ] {
        if clamp {
            ctx.enable(GL_DEPTH_CLAMP);
        } else {
            ctx.disable(GL_DEPTH_CLAMP);
        }
        assert_eq!(ctx.is_enabled(GL_DEPTH_CLAMP), clamp);
        ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        quad(&mut ctx, z);
        assert_eq!(pixel(&mut ctx, 4, 4) == GREEN, drawn, "clamp {clamp} z {z}");
        let d = read_depth(&mut ctx, 4, 4);
        assert!((d - depth).abs() < 1e-6, "clamp {clamp} z {z}: {d}");
    }
    // Behind the far plane with GL_ALWAYS: stored at depth 1.
    ctx.depth_func(GL_ALWAYS);
    ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    quad(&mut ctx, 3.0);
    assert_eq!(pixel(&mut ctx, 4, 4), GREEN);
    assert_eq!(read_depth(&mut ctx, 4, 4), 1.0);
    // A 2.1 context has no GL_DEPTH_CLAMP.
    let mut old = Context::new(4, 4);
    old.enable(GL_DEPTH_CLAMP);
    assert_eq!(old.get_error(), GL_INVALID_ENUM);
}

#[test]
fn sample_mask_state_and_sample_positions() {
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_CORE);
    assert_eq!(ctx.get_integerv(GL_MAX_SAMPLE_MASK_WORDS), vec![1]);
    assert_eq!(ctx.get_indexed(GL_SAMPLE_MASK_VALUE, 0), Some(vec![-1]));
    ctx.sample_maski(0, 5);
    assert_eq!(ctx.get_indexed(GL_SAMPLE_MASK_VALUE, 0), Some(vec![5]));
    ctx.enable(GL_SAMPLE_MASK);
    assert!(ctx.is_enabled(GL_SAMPLE_MASK));
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    ctx.sample_maski(1, 5);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    assert_eq!(ctx.get_indexed(GL_SAMPLE_MASK_VALUE, 1), None);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    // Single-sampled framebuffers have no sample positions.
    assert_eq!(ctx.get_multisamplefv(GL_SAMPLE_POSITION, 0), None);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    assert_eq!(ctx.get_multisamplefv(GL_SAMPLES, 0), None);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
}

#[test]
fn contexts_withhold_the_extensions_they_cannot_run() {
    // The compiler has GL_ARB_tessellation_shader's language; no context
    // draws patches, so none offers it: `require' fails, the macro is
    // undefined, and GL_EXTENSIONS does not list it. Compute shaders and
    // storage blocks are offered from 3.3 on.
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_COMPAT);
    let compile = |ctx: &mut Context, src: &str| {
        let s = ctx.create_shader(GL_VERTEX_SHADER);
        ctx.shader_source(s, &[src]);
        ctx.compile_shader(s);
        (
            ctx.get_shaderiv(s, GL_COMPILE_STATUS),
            ctx.get_shader_info_log(s),
        )
    };
    let (ok, log) = compile(
        &mut ctx,
        "#version 330\n#extension GL_ARB_tessellation_shader : require\nvoid main() { gl_Position = vec4(0.0); }\n",
    );
    assert_eq!(ok, 0);
    assert!(log.contains("GL_ARB_tessellation_shader"), "{log}");
    let (ok, log) = compile(
        &mut ctx,
        "#version 330\n#ifdef GL_ARB_tessellation_shader\n#error defined\n#endif\nvoid main() { gl_Position = vec4(0.0); }\n",
    );
    assert_eq!(ok, 1, "{log}");
    let n = ctx.get_integerv(GL_NUM_EXTENSIONS)[0];
    let names: Vec<String> = (0..n as u32)
        .filter_map(|i| ctx.get_stringi(GL_EXTENSIONS, i).map(str::to_string))
        .collect();
    assert!(!names.iter().any(|e| e == "GL_ARB_tessellation_shader"));
    assert!(names.iter().any(|e| e == "GL_ARB_compute_shader"));
    assert!(names
        .iter()
        .any(|e| e == "GL_ARB_shader_storage_buffer_object"));
    // A 2.1 context has neither.
    let mut old = Context::new(4, 4);
    let (ok, _) = compile(
        &mut old,
        "#version 120\n#extension GL_ARB_shader_storage_buffer_object : require\nvoid main() { gl_Position = vec4(0.0); }\n",
    );
    assert_eq!(ok, 0);
    assert!(names.iter().any(|e| e == "GL_ARB_shading_language_420pack"));
}
