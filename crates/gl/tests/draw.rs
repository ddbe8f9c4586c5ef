//! End-to-end: GL calls in, pixels out.

use gl::enums::*;
use gl::{ArrayData, Context, Param};

mod common;
use common::linked_program as program;

/// piglit_draw_rect: a quad from client arrays (positions and texcoords).
fn draw_rect(ctx: &mut Context, x: f32, y: f32, w: f32, h: f32) {
    let verts = [
        x,
        y,
        0.0,
        1.0,
        x + w,
        y,
        0.0,
        1.0,
        x,
        y + h,
        0.0,
        1.0,
        x + w,
        y + h,
        0.0,
        1.0,
    ];
    let tex = [0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0];
    ctx.vertex_pointer(4, GL_FLOAT, 0, ArrayData::from_f32(&verts));
    ctx.enable_client_state(GL_VERTEX_ARRAY);
    ctx.client_active_texture(GL_TEXTURE0);
    ctx.tex_coord_pointer(2, GL_FLOAT, 0, ArrayData::from_f32(&tex));
    ctx.enable_client_state(GL_TEXTURE_COORD_ARRAY);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    ctx.disable_client_state(GL_VERTEX_ARRAY);
    ctx.disable_client_state(GL_TEXTURE_COORD_ARRAY);
}

fn pixel(ctx: &mut Context, x: i32, y: i32) -> [f32; 4] {
    ctx.read_pixels_f32(x, y, 1, 1)[0]
}

fn close(a: [f32; 4], b: [f32; 4]) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() < 0.01)
}

#[test]
fn user_program_quad_and_uniform() {
    let mut ctx = Context::new(32, 32);
    let p = program(
        &mut ctx,
        Some("void main() { gl_Position = gl_Vertex; }"),
        Some("uniform vec4 color; void main() { gl_FragColor = color; }"),
    );
    ctx.clear_color(0.0, 0.0, 1.0, 1.0);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    let loc = ctx.get_uniform_location(p, "color");
    ctx.uniform_4f(loc, 0.0, 1.0, 0.0, 1.0);
    draw_rect(&mut ctx, -1.0, -1.0, 1.0, 2.0);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.take_draw_error(), None);
    assert!(close(pixel(&mut ctx, 4, 4), [0.0, 1.0, 0.0, 1.0]));
    assert!(close(pixel(&mut ctx, 28, 4), [0.0, 0.0, 1.0, 1.0]));
    let mut bytes = [0u8; 4];
    ctx.read_pixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut bytes);
    assert_eq!(bytes, [0, 255, 0, 255]);
}

#[test]
fn fragment_only_program_uses_fixed_vertex_stage() {
    let mut ctx = Context::new(20, 20);
    program(
        &mut ctx,
        None,
        Some("void main() { gl_FragColor = vec4(gl_TexCoord[0].xy, 0.0, 1.0); }"),
    );
    ctx.matrix_mode(GL_PROJECTION);
    ctx.ortho(0.0, 20.0, 0.0, 20.0, -1.0, 1.0);
    draw_rect(&mut ctx, 0.0, 0.0, 20.0, 20.0);
    assert_eq!(ctx.take_draw_error(), None);
    let c = pixel(&mut ctx, 15, 5);
    assert!(close(c, [15.5 / 20.0, 5.5 / 20.0, 0.0, 1.0]), "{c:?}");
}

#[test]
fn program_without_shaders_links_to_fixed_function() {
    // GL 2.1 gives an empty program no reason to fail: both stages are
    // fixed function, as Mesa's compatibility contexts link it.
    let mut ctx = Context::new(8, 8);
    program(&mut ctx, None, None);
    ctx.color_4f(1.0, 0.5, 0.0, 1.0);
    draw_rect(&mut ctx, -1.0, -1.0, 2.0, 2.0);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.take_draw_error(), None);
    assert!(close(pixel(&mut ctx, 4, 4), [1.0, 0.5, 0.0, 1.0]));
}

#[test]
fn immediate_mode_without_program() {
    let mut ctx = Context::new(16, 16);
    ctx.shade_model(GL_FLAT);
    ctx.begin(GL_QUADS);
    ctx.color_3f(1.0, 0.0, 0.0);
    ctx.vertex_2f(-1.0, -1.0);
    ctx.vertex_2f(1.0, -1.0);
    ctx.vertex_2f(1.0, 1.0);
    ctx.color_3f(1.0, 1.0, 0.0);
    ctx.vertex_2f(-1.0, 1.0);
    ctx.end();
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.take_draw_error(), None);
    assert!(close(pixel(&mut ctx, 8, 8), [1.0, 1.0, 0.0, 1.0]));
}

#[test]
fn fixed_function_lighting_and_texture() {
    let mut ctx = Context::new(8, 8);
    // Directional light straight on: diffuse 0.8 material x white light
    // plus 0.2 x 0.2 scene ambient.
    ctx.enable(GL_LIGHTING);
    ctx.enable(GL_LIGHT0);
    ctx.rectf(-1.0, -1.0, 1.0, 1.0);
    assert_eq!(ctx.take_draw_error(), None);
    let c = pixel(&mut ctx, 4, 4);
    assert!(close(c, [0.84, 0.84, 0.84, 1.0]), "{c:?}");
    ctx.disable(GL_LIGHTING);
    // A 2x2 RGBW texture, NEAREST, MODULATE with white.
    let t = ctx.gen_textures(1)[0];
    ctx.bind_texture(GL_TEXTURE_2D, t);
    let texels = [
        255u8, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255,
    ];
    ctx.tex_image(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        [2, 2],
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texels),
    );
    for filter in [GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER] {
        ctx.tex_parameter(GL_TEXTURE_2D, filter, Param::I(GL_NEAREST as i32));
    }
    ctx.enable(GL_TEXTURE_2D);
    ctx.color_3f(1.0, 1.0, 1.0);
    draw_rect(&mut ctx, -1.0, -1.0, 2.0, 2.0);
    assert_eq!(ctx.take_draw_error(), None);
    assert!(close(pixel(&mut ctx, 1, 1), [1.0, 0.0, 0.0, 1.0]));
    assert!(close(pixel(&mut ctx, 6, 1), [0.0, 1.0, 0.0, 1.0]));
    assert!(close(pixel(&mut ctx, 1, 6), [0.0, 0.0, 1.0, 1.0]));
    assert!(close(pixel(&mut ctx, 6, 6), [1.0, 1.0, 1.0, 1.0]));
}

#[test]
fn render_to_texture_then_sample_it() {
    let mut ctx = Context::new(8, 8);
    let t = ctx.gen_textures(1)[0];
    ctx.bind_texture(GL_TEXTURE_2D, t);
    ctx.tex_image(
        GL_TEXTURE_2D,
        0,
        GL_RGBA32F as i32,
        [4, 4],
        0,
        GL_RGBA,
        GL_FLOAT,
        None,
    );
    ctx.tex_parameter(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        Param::I(GL_NEAREST as i32),
    );
    let fb = ctx.gen_framebuffers(1)[0];
    ctx.bind_framebuffer(GL_FRAMEBUFFER_EXT, fb);
    ctx.framebuffer_texture_2d(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_TEXTURE_2D,
        t,
        0,
    );
    assert_eq!(
        ctx.check_framebuffer_status(GL_FRAMEBUFFER_EXT),
        GL_FRAMEBUFFER_COMPLETE_EXT
    );
    ctx.viewport(0, 0, 4, 4);
    program(
        &mut ctx,
        Some("void main() { gl_Position = gl_Vertex; }"),
        Some("void main() { gl_FragColor = vec4(2.0, 0.5, -1.0, 1.0); }"),
    );
    draw_rect(&mut ctx, -1.0, -1.0, 2.0, 2.0);
    assert_eq!(ctx.take_draw_error(), None);
    // Float color buffer: written unclamped? GL 2.1 clamps fragment colors.
    let c = pixel(&mut ctx, 1, 1);
    assert!(close(c, [1.0, 0.5, 0.0, 1.0]), "{c:?}");
    ctx.bind_framebuffer(GL_FRAMEBUFFER_EXT, 0);
    ctx.viewport(0, 0, 8, 8);
    program(
        &mut ctx,
        Some("void main() { gl_Position = gl_Vertex; gl_TexCoord[0] = gl_MultiTexCoord0; }"),
        Some(
            "uniform sampler2D s; void main() { gl_FragColor = texture2D(s, gl_TexCoord[0].xy); }",
        ),
    );
    draw_rect(&mut ctx, -1.0, -1.0, 2.0, 2.0);
    assert_eq!(ctx.take_draw_error(), None);
    assert!(close(pixel(&mut ctx, 3, 3), [1.0, 0.5, 0.0, 1.0]));
}

#[test]
fn draw_errors() {
    let mut ctx = Context::new(4, 4);
    ctx.draw_arrays(0x99, 0, 3);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    ctx.draw_arrays(GL_TRIANGLES, 0, -1);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.draw_elements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, ArrayData::Offset(0));
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    let fb = ctx.gen_framebuffers(1)[0];
    ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    assert_eq!(ctx.get_error(), GL_INVALID_FRAMEBUFFER_OPERATION);
    ctx.read_pixels(0, 0, 1, 1, GL_RGBA, 0x1234, &mut [0; 4]);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
}

/// A scene drawn through the GL API with `threads` draw threads: color,
/// depth and stencil bytes, plus any draw error.
fn threaded_scene(threads: usize) -> (Vec<u8>, Vec<u8>, Vec<u8>, Option<String>) {
    let (w, h) = (150, 130);
    let mut ctx = Context::new(w, h);
    ctx.set_threads(threads);
    assert_eq!(ctx.threads(), threads);
    ctx.clear_color(0.2, 0.1, 0.3, 1.0);
    ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

    // Overlapping blended triangles in perspective, depth-tested, counted
    // in the stencil buffer (fixed function, immediate mode).
    ctx.enable(GL_DEPTH_TEST);
    ctx.enable(GL_BLEND);
    ctx.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    ctx.enable(GL_STENCIL_TEST);
    ctx.stencil_func(GL_ALWAYS, 0, 0xff);
    ctx.stencil_op(GL_KEEP, GL_DECR, GL_INCR);
    let mut seed = 99u32;
    let mut rnd = move || {
        seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12_345);
        (seed >> 8) as f32 / (1u32 << 24) as f32
    };
    ctx.begin(GL_TRIANGLES);
    for _ in 0..40 * 3 {
        ctx.color_4f(rnd(), rnd(), rnd(), 0.3 + 0.6 * rnd());
        let wc = 0.5 + 1.5 * rnd();
        let (x, y, z) = (rnd() * 2.4 - 1.2, rnd() * 2.4 - 1.2, rnd() * 2.0 - 1.0);
        ctx.vertex_4f(x * wc, y * wc, z * wc, wc);
    }
    ctx.end();
    ctx.disable(GL_STENCIL_TEST);

    // A mipmapped checkerboard on a quad in perspective, trilinear.
    let t = ctx.gen_textures(1)[0];
    ctx.bind_texture(GL_TEXTURE_2D, t);
    let texels: Vec<u8> = (0..32 * 32)
        .flat_map(|i| {
            let on = ((i % 32) / 4 + (i / 32) / 4) % 2 == 0;
            if on {
                [250, 40, 10, 255]
            } else {
                [20, 200, 90, 160]
            }
        })
        .collect();
    ctx.tex_image(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        [32, 32],
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texels),
    );
    ctx.generate_mipmap(GL_TEXTURE_2D);
    ctx.tex_parameter(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        Param::I(GL_LINEAR_MIPMAP_LINEAR as i32),
    );
    program(
        &mut ctx,
        Some("void main() { gl_Position = gl_Vertex; gl_TexCoord[0] = gl_MultiTexCoord0; }"),
        Some(
            "uniform sampler2D s;\n\
             void main() { gl_FragColor = texture2D(s, gl_TexCoord[0].xy); }",
        ),
    );
    ctx.depth_func(GL_LEQUAL);
    ctx.begin(GL_QUADS);
    for (x, y, wc, s, tc) in [
        (-0.9f32, -0.8f32, 0.4f32, 0.0f32, 0.0f32),
        (0.95, -0.9, 1.0, 5.0, 0.0),
        (0.8, 0.9, 3.0, 5.0, 5.0),
        (-0.7, 0.85, 1.5, 0.0, 5.0),
    ] {
        ctx.multi_tex_coord_4f(GL_TEXTURE0, s, tc, 0.0, 1.0);
        ctx.vertex_4f(x * wc, y * wc, 0.1 * wc, wc);
    }
    ctx.end();

    // Derivatives and discard, additive.
    program(
        &mut ctx,
        Some("void main() { gl_Position = gl_Vertex; gl_TexCoord[0] = gl_MultiTexCoord0; }"),
        Some(
            "void main() {\n\
               vec2 t = gl_TexCoord[0].xy;\n\
               vec2 d = vec2(dFdx(t.x * t.y), dFdy(t.x * t.x));\n\
               if (fract(t.x * 5.0 + t.y * 2.0) < 0.4) discard;\n\
               gl_FragColor = vec4(abs(d) * 30.0, fwidth(t.y) * 40.0, 0.6);\n\
             }",
        ),
    );
    ctx.disable(GL_DEPTH_TEST);
    ctx.blend_func(GL_SRC_ALPHA, GL_ONE);
    ctx.begin(GL_TRIANGLE_FAN);
    for (x, y, s, tc) in [
        (0.0f32, 0.0f32, 1.0f32, 1.0f32),
        (-1.0, -0.5, 0.0, 0.0),
        (0.6, -1.0, 2.0, 0.0),
        (1.0, 0.7, 3.0, 2.0),
        (-0.3, 1.0, 0.0, 3.0),
    ] {
        ctx.multi_tex_coord_4f(GL_TEXTURE0, s * s, tc, 0.0, 1.0);
        ctx.vertex_2f(x, y);
    }
    ctx.end();
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    let error = ctx.take_draw_error();

    let n = (w * h) as usize;
    let mut color = vec![0u8; n * 4];
    ctx.read_pixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, &mut color);
    let mut depth = vec![0u8; n * 4];
    ctx.read_pixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, &mut depth);
    let mut stencil = vec![0u8; n];
    ctx.read_pixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &mut stencil);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    (color, depth, stencil, error)
}

#[test]
fn images_are_identical_whatever_the_thread_count() {
    let one = threaded_scene(1);
    assert_eq!(one.3, None);
    let distinct: std::collections::BTreeSet<&[u8]> = one.0.chunks(4).collect();
    assert!(distinct.len() > 300, "{} colors", distinct.len());
    assert!(one.2.iter().any(|&s| s >= 2), "triangles overlap");
    for threads in [2, 4] {
        let many = threaded_scene(threads);
        assert!(one.0 == many.0, "color differs with {threads} threads");
        assert!(one.1 == many.1, "depth differs with {threads} threads");
        assert!(one.2 == many.2, "stencil differs with {threads} threads");
        assert_eq!(one.3, many.3);
    }
}

/// The same triangles drawn from element indices of every type, from an
/// element buffer (32-bit ones at an aligned offset, read in place, and at
/// an unaligned one, converted) and from client memory, give the image of
/// the draw_arrays of their vertices.
#[test]
fn element_indices_of_every_type_and_place_draw_the_same() {
    let mut ctx = Context::new(16, 16);
    program(
        &mut ctx,
        Some("void main() { gl_Position = gl_Vertex; gl_FrontColor = gl_Color; }"),
        None,
    );
    // Four vertices, two triangles with a shared edge, distinct colours.
    let verts = [
        -0.9f32, -0.8, 0.0, 1.0, 0.7, -0.9, 0.0, 1.0, -0.6, 0.9, 0.0, 1.0, 0.8, 0.6, 0.0, 1.0,
    ];
    let colors = [
        1.0f32, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 0.0, 1.0,
    ];
    let order = [0u32, 1, 2, 2, 1, 3];
    let expanded: Vec<f32> = order
        .iter()
        .flat_map(|&i| verts[4 * i as usize..4 * i as usize + 4].to_vec())
        .collect();
    let expanded_colors: Vec<f32> = order
        .iter()
        .flat_map(|&i| colors[4 * i as usize..4 * i as usize + 4].to_vec())
        .collect();
    ctx.enable_client_state(GL_VERTEX_ARRAY);
    ctx.enable_client_state(GL_COLOR_ARRAY);
    let image = |ctx: &mut Context, draw: &dyn Fn(&mut Context)| {
        ctx.clear(GL_COLOR_BUFFER_BIT);
        draw(ctx);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(ctx.take_draw_error(), None);
        let mut px = vec![0u8; 16 * 16 * 4];
        ctx.read_pixels(0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
        px
    };
    ctx.vertex_pointer(4, GL_FLOAT, 0, ArrayData::from_f32(&expanded));
    ctx.color_pointer(4, GL_FLOAT, 0, ArrayData::from_f32(&expanded_colors));
    let want = image(&mut ctx, &|c| c.draw_arrays(GL_TRIANGLES, 0, 6));
    assert!(want.chunks(4).any(|p| p != [0, 0, 0, 0]), "nothing drawn");

    ctx.vertex_pointer(4, GL_FLOAT, 0, ArrayData::from_f32(&verts));
    ctx.color_pointer(4, GL_FLOAT, 0, ArrayData::from_f32(&colors));
    let bytes = |ty: u32| -> Vec<u8> {
        order
            .iter()
            .flat_map(|&i| match ty {
                GL_UNSIGNED_BYTE => vec![i as u8],
                GL_UNSIGNED_SHORT => (i as u16).to_le_bytes().to_vec(),
                _ => i.to_le_bytes().to_vec(),
            })
            .collect()
    };
    let buffer = ctx.gen_buffers(1)[0];
    ctx.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, buffer);
    for ty in [GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT] {
        for pad in [0usize, 4, 2] {
            let mut data = vec![0xee; pad];
            data.extend(bytes(ty));
            ctx.buffer_data(
                GL_ELEMENT_ARRAY_BUFFER,
                data.len() as isize,
                Some(&data),
                GL_STATIC_DRAW,
            );
            let got = image(&mut ctx, &|c| {
                c.draw_elements(GL_TRIANGLES, 6, ty, ArrayData::Offset(pad))
            });
            assert!(got == want, "type {ty:#x}, buffer offset {pad}");
        }
    }
    ctx.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    for ty in [GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT] {
        let data: std::sync::Arc<[u8]> = bytes(ty).into();
        let got = image(&mut ctx, &|c| {
            c.draw_elements(GL_TRIANGLES, 6, ty, ArrayData::Client(data.clone()))
        });
        assert!(got == want, "type {ty:#x}, client memory");
    }
}

/// GLSL 1.30 `in`/`out` draw like their `attribute`/`varying` equivalents:
/// a vertex input at an explicit location, a smooth and a flat varying
/// (an integer one among them), and a user fragment output.
#[test]
fn glsl_130_inputs_outputs_and_flat_varyings() {
    let vs = "#version 130\n\
        #extension GL_ARB_explicit_attrib_location : require\n\
        layout(location = 3) in vec4 pos;\n\
        in vec4 col;\n\
        out vec3 v;\n\
        flat out int band;\n\
        void main() { gl_Position = pos; v = col.rgb; band = pos.x < 0.0 ? 1 : 2; }";
    let fs = "#version 130\n\
        in vec3 v;\n\
        flat in int band;\n\
        out vec4 color;\n\
        void main() { color = vec4(v, 1.0) * (band == 1 ? 1.0 : 0.5); }";
    let attribute_vs = "attribute vec4 pos; attribute vec4 col; varying vec3 v;\n\
        void main() { gl_Position = pos; v = col.rgb; }";
    let varying_fs = "varying vec3 v; void main() { gl_FragColor = vec4(v, 1.0); }";
    let quad = [
        -1.0, -1.0, 0.0, 1.0, 1.0, -1.0, 0.0, 1.0, -1.0, 1.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0,
    ];
    let cols = [
        0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0,
    ];
    let mut images = Vec::new();
    for (vs, fs) in [(attribute_vs, varying_fs), (vs, fs)] {
        let mut ctx = Context::new(16, 16);
        let p = program(&mut ctx, Some(vs), Some(fs));
        let pos = ctx.get_attrib_location(p, "pos");
        let col = ctx.get_attrib_location(p, "col");
        assert!(pos >= 0 && col >= 0 && pos != col);
        if vs.contains("layout") {
            assert_eq!(pos, 3);
        }
        ctx.clear_color(0.0, 0.0, 0.0, 0.0);
        ctx.clear(GL_COLOR_BUFFER_BIT);
        ctx.vertex_attrib_pointer(
            pos as u32,
            4,
            GL_FLOAT,
            false,
            0,
            ArrayData::from_f32(&quad),
        );
        ctx.vertex_attrib_pointer(
            col as u32,
            4,
            GL_FLOAT,
            false,
            0,
            ArrayData::from_f32(&cols),
        );
        ctx.enable_vertex_attrib_array(pos as u32);
        ctx.enable_vertex_attrib_array(col as u32);
        ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(ctx.take_draw_error(), None);
        images.push((pixel(&mut ctx, 2, 8), pixel(&mut ctx, 13, 8)));
    }
    // attribute/varying: green everywhere.
    assert!(close(images[0].0, [0.0, 1.0, 0.0, 1.0]), "{:?}", images[0]);
    assert!(close(images[0].1, [0.0, 1.0, 0.0, 1.0]), "{:?}", images[0]);
    // in/out: the same green, halved in the triangle whose provoking
    // vertex (the last) has x > 0: the strip's second, (1,-1) (-1,1) (1,1).
    assert!(close(images[1].0, [0.0, 1.0, 0.0, 1.0]), "{:?}", images[1]);
    assert!(close(images[1].1, [0.0, 0.5, 0.0, 0.5]), "{:?}", images[1]);
}

/// A draw beyond the vertex limits is GL_OUT_OF_MEMORY at once, not a
/// truncated picture or a run without end (docs/RELIABILITY.md, Limits).
#[test]
fn draws_beyond_the_vertex_limits_are_out_of_memory() {
    let mut ctx = Context::new(4, 4);
    ctx.draw_arrays(GL_POINTS, 0, i32::MAX);
    assert_eq!(ctx.get_error(), GL_OUT_OF_MEMORY);
    ctx.draw_arrays_instanced(GL_POINTS, 0, 1 << 20, 1 << 20);
    assert_eq!(ctx.get_error(), GL_OUT_OF_MEMORY);
    ctx.draw_elements(
        GL_POINTS,
        gl::MAX_DRAW_VERTICES + 1,
        GL_UNSIGNED_INT,
        ArrayData::from_u32(&[0]),
    );
    assert_eq!(ctx.get_error(), GL_OUT_OF_MEMORY);
    // At the limits: drawn, no error.
    ctx.draw_arrays(GL_POINTS, 0, 4);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}

/// Binds a new 8 × 8 framebuffer object of two renderbuffers, colour of
/// `color_format` and depth of `depth_format`.
fn bind_renderbuffer_fbo(ctx: &mut Context, color_format: u32, depth_format: u32) {
    let rb = ctx.gen_renderbuffers(2);
    for (r, format) in rb.iter().zip([color_format, depth_format]) {
        ctx.bind_renderbuffer(GL_RENDERBUFFER, *r);
        ctx.renderbuffer_storage(GL_RENDERBUFFER, format, 8, 8);
    }
    let fb = ctx.gen_framebuffers(1)[0];
    ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
    ctx.framebuffer_renderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    ctx.framebuffer_renderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
}

/// Two quads in one draw whose depths differ by less than a 16-bit step
/// (0.99968 and 0.9996803, five 24-bit steps apart), nearer one second,
/// into a framebuffer object whose depth attachment has
/// `depth_format`; with GL_LESS, the second quad's colour where it wins.
fn second_of_close_quads(depth_format: u32) -> [f32; 4] {
    let mut ctx = Context::new(8, 8);
    bind_renderbuffer_fbo(&mut ctx, GL_RGBA8, depth_format);
    program(
        &mut ctx,
        Some("void main() { gl_Position = gl_Vertex; gl_FrontColor = gl_Color; }"),
        Some("void main() { gl_FragColor = gl_Color; }"),
    );
    ctx.clear_depth(1.0);
    ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    ctx.enable(GL_DEPTH_TEST);
    ctx.depth_func(GL_LESS);
    // Window z = (ndc + 1) / 2.
    let ndc = |z: f32| 2.0 * z - 1.0;
    ctx.begin(GL_QUADS);
    for (z, color) in [(0.9996803f32, [1.0, 0.0, 0.0]), (0.99968, [0.0, 1.0, 0.0])] {
        ctx.color_3f(color[0], color[1], color[2]);
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            ctx.vertex_3f(x, y, ndc(z));
        }
    }
    ctx.end();
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.take_draw_error(), None);
    pixel(&mut ctx, 4, 4)
}

/// GL 3.0 §4.4.2.2: a DEPTH_COMPONENT16 renderbuffer has exactly 16 bits,
/// so within one draw the nearer quad ties with the farther one (and
/// loses under GL_LESS), where 24 bits tell them apart.
#[test]
fn depth_component16_tests_at_16_bits() {
    assert!(close(
        second_of_close_quads(GL_DEPTH_COMPONENT24),
        [0.0, 1.0, 0.0, 1.0]
    ));
    assert!(close(
        second_of_close_quads(GL_DEPTH_COMPONENT16),
        [1.0, 0.0, 0.0, 1.0]
    ));
}

/// GL 3.0 §6.1.3: GL_*_BITS are the draw framebuffer's: the default
/// one's 8-bit colour, 24-bit depth and 8-bit stencil, then a framebuffer
/// object's first draw buffer (RGB: no alpha) and depth image (16 bits,
/// no stencil).
#[test]
fn buffer_bits_follow_the_draw_framebuffer() {
    let mut ctx = Context::new(8, 8);
    let bits = |ctx: &mut Context| {
        [GL_RED_BITS, GL_ALPHA_BITS, GL_DEPTH_BITS, GL_STENCIL_BITS].map(|p| ctx.get_integerv(p)[0])
    };
    assert_eq!(bits(&mut ctx), [8, 8, 24, 8]);
    bind_renderbuffer_fbo(&mut ctx, GL_RGB8, GL_DEPTH_COMPONENT16);
    assert_eq!(bits(&mut ctx), [8, 0, 16, 0]);
    ctx.bind_framebuffer(GL_FRAMEBUFFER, 0);
    assert_eq!(bits(&mut ctx), [8, 8, 24, 8]);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}

/// Draws whose fragment stages wait in the draw queue see the uniforms and
/// textures of their own call, and a read of the framebuffer sees every
/// draw before it: the same pixels as a glFinish after every draw.
#[test]
fn waiting_draws_give_the_pixels_of_finished_draws() {
    let frame = |finish_each: bool| {
        let mut ctx = Context::new(150, 90);
        let p = program(
            &mut ctx,
            None,
            Some(
                "uniform vec4 tint; uniform sampler2D tex;
                 void main() { gl_FragColor = texture2D(tex, gl_TexCoord[0].st) * tint; }",
            ),
        );
        let tex = ctx.gen_textures(1)[0];
        ctx.bind_texture(GL_TEXTURE_2D, tex);
        for pname in [GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER] {
            ctx.tex_parameter(GL_TEXTURE_2D, pname, Param::I(GL_NEAREST as i32));
        }
        let texels: Vec<u8> = (0..16u8)
            .flat_map(|i| [i * 16, 255 - i * 8, 128, 200])
            .collect();
        ctx.tex_image(
            GL_TEXTURE_2D,
            0,
            GL_RGBA8 as i32,
            [4, 4],
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&texels),
        );
        ctx.enable(GL_BLEND);
        ctx.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        let tint = ctx.get_uniform_location(p, "tint");
        let mut waiting = Vec::new();
        let step = |ctx: &mut Context, waiting: &mut Vec<usize>, rect: [f32; 4], t: [f32; 4]| {
            ctx.uniform_4f(tint, t[0], t[1], t[2], t[3]);
            draw_rect(ctx, rect[0], rect[1], rect[2], rect[3]);
            if finish_each {
                ctx.finish();
            }
            waiting.push(ctx.waiting_draws());
        };
        step(
            &mut ctx,
            &mut waiting,
            [-1.0, -1.0, 2.0, 2.0],
            [1.0, 1.0, 1.0, 1.0],
        );
        step(
            &mut ctx,
            &mut waiting,
            [-0.5, -1.0, 1.5, 1.2],
            [0.2, 0.9, 0.5, 0.7],
        );
        // New texels for the next draws only.
        let dark: Vec<u8> = (0..16u8).flat_map(|i| [30, i * 10, 250, 160]).collect();
        ctx.tex_sub_image(
            GL_TEXTURE_2D,
            0,
            [0, 0],
            [4, 4],
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            &dark,
        );
        step(
            &mut ctx,
            &mut waiting,
            [-1.0, -0.3, 1.2, 1.3],
            [1.0, 0.5, 0.25, 0.9],
        );
        // A read in the middle sees the three draws before it.
        let middle = ctx.read_pixels_f32(0, 0, 150, 90);
        waiting.push(ctx.waiting_draws());
        step(
            &mut ctx,
            &mut waiting,
            [-0.8, -0.8, 1.6, 1.6],
            [0.6, 0.6, 1.0, 0.5],
        );
        let last = ctx.read_pixels_f32(0, 0, 150, 90);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(ctx.take_draw_error(), None);
        (middle, last, waiting)
    };
    let (middle, last, waiting) = frame(false);
    assert_eq!(waiting, [1, 2, 3, 0, 1], "the draws wait until the read");
    let (finished_middle, finished_last, none) = frame(true);
    assert_eq!(none, [0, 0, 0, 0, 0]);
    assert!(middle == finished_middle, "the read in the middle differs");
    assert!(last == finished_last, "the last frame differs");
}
