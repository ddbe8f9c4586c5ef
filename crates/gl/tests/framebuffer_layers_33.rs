//! Layers of 3D and array textures as framebuffer attachments (GL 3.3
//! §4.4.2, §4.4.4): glFramebufferTexture3D and glFramebufferTextureLayer
//! attach one layer, which clears, draws and reads touch alone;
//! glFramebufferTexture attaches a whole level, layered: drawn at layer 0
//! without a geometry stage choosing layers, every layer cleared;
//! the attachment queries, completeness and errors.

use gl::enums::*;
use gl::Context;

/// A 2×2×`layers` RGBA8 texture of `target` (3D or 2D array), all zero.
fn layered_texture(ctx: &mut Context, target: u32, layers: i32) -> u32 {
    let t = ctx.gen_textures(1)[0];
    ctx.bind_texture(target, t);
    let zeros = vec![0u8; (2 * 2 * layers * 4) as usize];
    ctx.tex_image(
        target,
        0,
        GL_RGBA8 as i32,
        [2, 2, layers],
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&zeros),
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    t
}

/// Each layer's first texel (the texture bound to `target`, level 0).
fn layer_texels(ctx: &mut Context, target: u32, layers: usize) -> Vec<[u8; 4]> {
    let bytes = ctx.get_tex_image(target, 0, GL_RGBA, GL_UNSIGNED_BYTE);
    (0..layers)
        .map(|l| bytes[l * 16..l * 16 + 4].try_into().unwrap())
        .collect()
}

fn clear_to(ctx: &mut Context, c: [f32; 4]) {
    ctx.clear_color(c[0], c[1], c[2], c[3]);
    ctx.clear(GL_COLOR_BUFFER_BIT);
}

#[test]
fn one_layer_of_an_array_or_3d_texture_is_the_image_drawn() {
    for (target, layer) in [(GL_TEXTURE_2D_ARRAY, 1), (GL_TEXTURE_3D, 2)] {
        let mut ctx = Context::with_api(4, 4, gl::Api::GL33_CORE);
        let t = layered_texture(&mut ctx, target, 3);
        let fb = ctx.gen_framebuffers(1)[0];
        ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
        if target == GL_TEXTURE_3D {
            ctx.framebuffer_texture_3d(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target, t, 0, layer);
        } else {
            ctx.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t, 0, layer);
        }
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(
            ctx.check_framebuffer_status(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_COMPLETE
        );
        let q = |ctx: &mut Context, pname| {
            ctx.get_framebuffer_attachment_parameter(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, pname)
        };
        assert_eq!(
            q(&mut ctx, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER),
            Some(layer)
        );
        assert_eq!(q(&mut ctx, GL_FRAMEBUFFER_ATTACHMENT_LAYERED), Some(0));
        clear_to(&mut ctx, [0.0, 1.0, 0.0, 1.0]);
        let mut want = vec![[0u8; 4]; 3];
        want[layer as usize] = [0, 255, 0, 255];
        assert_eq!(layer_texels(&mut ctx, target, 3), want, "{target:#x}");
        // glReadPixels reads that layer.
        let mut px = [0u8; 4];
        ctx.read_pixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
        assert_eq!(px, [0, 255, 0, 255]);
        // Another layer: the first keeps its contents.
        ctx.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t, 0, 0);
        clear_to(&mut ctx, [0.0, 0.0, 1.0, 1.0]);
        want[0] = [0, 0, 255, 255];
        assert_eq!(layer_texels(&mut ctx, target, 3), want, "{target:#x}");
        // A layer the level does not have: incomplete attachment.
        ctx.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t, 0, 3);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(
            ctx.check_framebuffer_status(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT
        );
    }
}

#[test]
fn a_layer_of_a_1d_array_is_one_row() {
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_CORE);
    let t = ctx.gen_textures(1)[0];
    ctx.bind_texture(GL_TEXTURE_1D_ARRAY, t);
    let zeros = vec![0u8; 2 * 3 * 4];
    ctx.tex_image(
        GL_TEXTURE_1D_ARRAY,
        0,
        GL_RGBA8 as i32,
        [2, 3],
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&zeros),
    );
    let fb = ctx.gen_framebuffers(1)[0];
    ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
    ctx.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t, 0, 2);
    assert_eq!(
        ctx.check_framebuffer_status(GL_FRAMEBUFFER),
        GL_FRAMEBUFFER_COMPLETE
    );
    clear_to(&mut ctx, [1.0, 0.0, 0.0, 1.0]);
    let bytes = ctx.get_tex_image(GL_TEXTURE_1D_ARRAY, 0, GL_RGBA, GL_UNSIGNED_BYTE);
    let mut want = vec![0u8; 2 * 3 * 4];
    for x in 0..2 {
        want[(2 * 2 + x) * 4..(2 * 2 + x) * 4 + 4].copy_from_slice(&[255, 0, 0, 255]);
    }
    assert_eq!(bytes, want);
}

#[test]
fn a_layered_attachment_draws_into_layer_zero() {
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_CORE);
    let t = layered_texture(&mut ctx, GL_TEXTURE_2D_ARRAY, 2);
    let fb = ctx.gen_framebuffers(1)[0];
    ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
    ctx.framebuffer_texture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t, 0);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(
        ctx.get_framebuffer_attachment_parameter(
            GL_FRAMEBUFFER,
            GL_COLOR_ATTACHMENT0,
            GL_FRAMEBUFFER_ATTACHMENT_LAYERED
        ),
        Some(1)
    );
    assert_eq!(
        ctx.check_framebuffer_status(GL_FRAMEBUFFER),
        GL_FRAMEBUFFER_COMPLETE
    );
    // A clear clears every layer (GL 3.3 §4.4.7), a draw without a
    // geometry stage layer 0.
    clear_to(&mut ctx, [1.0, 1.0, 0.0, 1.0]);
    assert_eq!(
        layer_texels(&mut ctx, GL_TEXTURE_2D_ARRAY, 2),
        vec![[255, 255, 0, 255], [255, 255, 0, 255]]
    );
    // A 2D texture is no layered attachment.
    let t2 = ctx.gen_textures(1)[0];
    ctx.bind_texture(GL_TEXTURE_2D, t2);
    ctx.tex_image(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        [2, 2],
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        None,
    );
    ctx.framebuffer_texture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, t2, 0);
    assert_eq!(
        ctx.get_framebuffer_attachment_parameter(
            GL_FRAMEBUFFER,
            GL_COLOR_ATTACHMENT1,
            GL_FRAMEBUFFER_ATTACHMENT_LAYERED
        ),
        Some(0)
    );
    // Layered beside non-layered: incomplete.
    assert_eq!(
        ctx.check_framebuffer_status(GL_FRAMEBUFFER),
        GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS
    );
    ctx.framebuffer_texture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, 0, 0);
    assert_eq!(
        ctx.check_framebuffer_status(GL_FRAMEBUFFER),
        GL_FRAMEBUFFER_COMPLETE
    );
    // A layered cube map: six layers, the faces, all cleared.
    let c = ctx.gen_textures(1)[0];
    ctx.bind_texture(GL_TEXTURE_CUBE_MAP, c);
    for f in 0..6 {
        ctx.tex_image(
            GL_TEXTURE_CUBE_MAP_POSITIVE_X + f,
            0,
            GL_RGBA8 as i32,
            [2, 2],
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&[0u8; 16]),
        );
    }
    ctx.framebuffer_texture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, c, 0);
    assert_eq!(
        ctx.check_framebuffer_status(GL_FRAMEBUFFER),
        GL_FRAMEBUFFER_COMPLETE
    );
    clear_to(&mut ctx, [0.0, 0.0, 1.0, 1.0]);
    let px = ctx.get_tex_image(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, GL_UNSIGNED_BYTE);
    assert_eq!(px[..4], [0, 0, 255, 255]);
    let px = ctx.get_tex_image(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_RGBA, GL_UNSIGNED_BYTE);
    assert_eq!(px[..4], [0, 0, 255, 255]);
}

#[test]
fn layer_attachment_errors() {
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_CORE);
    let arr = layered_texture(&mut ctx, GL_TEXTURE_2D_ARRAY, 2);
    let t2 = ctx.gen_textures(1)[0];
    ctx.bind_texture(GL_TEXTURE_2D, t2);
    // No framebuffer object bound.
    ctx.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, arr, 0, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    let fb = ctx.gen_framebuffers(1)[0];
    ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
    // A 2D texture has no layers; an unknown name is none either.
    ctx.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t2, 0, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 777, 0, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, arr, 0, -1);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, arr, -1, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_BACK, arr, 0, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    // glFramebufferTexture3D takes GL_TEXTURE_3D only.
    ctx.framebuffer_texture_3d(
        GL_FRAMEBUFFER,
        GL_COLOR_ATTACHMENT0,
        GL_TEXTURE_2D,
        t2,
        0,
        0,
    );
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.framebuffer_texture_3d(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RED, t2, 0, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    ctx.framebuffer_texture_3d(
        GL_FRAMEBUFFER,
        GL_COLOR_ATTACHMENT0,
        GL_TEXTURE_3D,
        arr,
        0,
        0,
    );
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    // glFramebufferTexture: an unknown name, a buffer texture.
    ctx.framebuffer_texture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 777, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    let tb = ctx.gen_textures(1)[0];
    ctx.bind_texture(GL_TEXTURE_BUFFER, tb);
    ctx.framebuffer_texture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, tb, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    // Texture 0 detaches, whatever the other arguments.
    ctx.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, arr, 0, 1);
    ctx.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 0, -5, -5);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(
        ctx.get_framebuffer_attachment_parameter(
            GL_FRAMEBUFFER,
            GL_COLOR_ATTACHMENT0,
            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE
        ),
        Some(GL_NONE as i32)
    );
}
