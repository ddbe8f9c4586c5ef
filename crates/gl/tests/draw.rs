//! End-to-end: GL calls in, pixels out.

use gl::enums::*;
use gl::{ArrayData, Context};

fn program(ctx: &mut Context, vs: Option<&str>, fs: Option<&str>) -> u32 {
    let p = ctx.create_program();
    for (kind, src) in [(GL_VERTEX_SHADER, vs), (GL_FRAGMENT_SHADER, fs)] {
        let Some(src) = src else { continue };
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
    ctx.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        2,
        2,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texels),
    );
    ctx.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    ctx.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
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
    ctx.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA32F as i32,
        4,
        4,
        0,
        GL_RGBA,
        GL_FLOAT,
        None,
    );
    ctx.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    let fb = ctx.gen_framebuffers_ext(1)[0];
    ctx.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, fb);
    ctx.framebuffer_texture_2d_ext(
        GL_FRAMEBUFFER_EXT,
        GL_COLOR_ATTACHMENT0_EXT,
        GL_TEXTURE_2D,
        t,
        0,
    );
    assert_eq!(
        ctx.check_framebuffer_status_ext(GL_FRAMEBUFFER_EXT),
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
    ctx.bind_framebuffer_ext(GL_FRAMEBUFFER_EXT, 0);
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
