//! GL_ARB_texture_cube_map_array end to end: the target's images
//! (glTexImage3D's layer-faces, sub-images, proxies, mipmaps, the errors
//! its spec names), its binding query, layers as framebuffer attachments,
//! and the samplers' lookups in shaders (`texture`, `textureLod`,
//! `textureGrad`, `textureSize`, the shadow form, integer samplers).

use gl::enums::*;
use gl::param::Param;
use gl::version::Api;
use gl::Context;

mod common;

const CUBE_ARRAY: u32 = GL_TEXTURE_CUBE_MAP_ARRAY_ARB;
const UB: u32 = GL_UNSIGNED_BYTE;
const GREEN: [u8; 4] = [0, 255, 0, 255];

const VS: &str = "#version 130\n\
    in vec2 pos;\n\
    void main() { gl_Position = vec4(pos, 0.0, 1.0); }";

const FULL_QUAD: [f32; 8] = [-1.0, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0];

/// Draws the full quad with `fs` (GLSL 1.30 with the extension and
/// `decls`, green when `ok` holds, red otherwise) into the 8×8 default
/// framebuffer and returns a pixel.
fn verdict(ctx: &mut Context, decls: &str, ok: &str) -> [u8; 4] {
    let fs = format!(
        "#version 130\n#extension GL_ARB_texture_cube_map_array : require\n{decls}\n\
         out vec4 color;\nvoid main() {{ color = ({ok}) ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0); }}\n"
    );
    let p = common::program(ctx, VS, &fs);
    let pos = ctx.get_attrib_location(p, "pos");
    assert!(pos >= 0);
    common::float_array(ctx, pos as u32, 2, &FULL_QUAD);
    ctx.bind_framebuffer(GL_FRAMEBUFFER, 0);
    ctx.clear_color(0.0, 0.0, 0.0, 0.0);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.take_draw_error(), None);
    ctx.read_pixels_f32(2, 5, 1, 1)[0].map(|c| (c * 255.0).round() as u8)
}

/// `size`×`size` faces, 6·`cubes` layer-faces whose texels' red is
/// 10·layer-face + `plus` (of 255).
fn layer_faces(size: usize, cubes: usize, plus: u8) -> Vec<u8> {
    (0..6 * cubes)
        .flat_map(|lf| [10 * lf as u8 + plus, 0, 0, 255].repeat(size * size))
        .collect()
}

fn nearest(ctx: &mut Context, min: u32) {
    ctx.tex_parameter(CUBE_ARRAY, GL_TEXTURE_MIN_FILTER, Param::I(min as i32));
    ctx.tex_parameter(
        CUBE_ARRAY,
        GL_TEXTURE_MAG_FILTER,
        Param::I(GL_NEAREST as i32),
    );
}

#[test]
fn advertised_on_3_3_contexts() {
    for (api, has) in [
        (Api::GL21, false),
        (Api::GL33_CORE, true),
        (Api::GL33_COMPAT, true),
    ] {
        let mut ctx = Context::with_api(4, 4, api);
        // The core profile lists them through glGetStringi only.
        let ext: Vec<String> = if api.at_least(3, 0) {
            let n = ctx.get_integerv(GL_NUM_EXTENSIONS)[0] as u32;
            (0..n)
                .map(|i| ctx.get_stringi(GL_EXTENSIONS, i).unwrap().to_string())
                .collect()
        } else {
            ctx.get_string(GL_EXTENSIONS)
                .split(' ')
                .map(str::to_string)
                .collect()
        };
        for name in [
            "GL_ARB_texture_cube_map_array",
            "GL_ARB_shading_language_packing",
        ] {
            assert_eq!(ext.iter().any(|e| e == name), has, "{api:?} {name}");
        }
    }
}

#[test]
fn images_bindings_and_errors() {
    let mut ctx = Context::new(8, 8);
    let t = ctx.gen_textures(1)[0];
    ctx.bind_texture(CUBE_ARRAY, t);
    assert_eq!(
        ctx.get_integerv(GL_TEXTURE_BINDING_CUBE_MAP_ARRAY_ARB),
        vec![t as i32]
    );
    let rgba8 = GL_RGBA8 as i32;
    // Depth not a multiple of 6, faces not square: GL_INVALID_VALUE,
    // nothing stored; also through the proxy.
    for size in [[2, 2, 7], [2, 1, 6], [4, 2, 12]] {
        ctx.tex_image(CUBE_ARRAY, 0, rgba8, size, 0, GL_RGBA, UB, None);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE, "{size:?}");
        ctx.tex_image(
            GL_PROXY_TEXTURE_CUBE_MAP_ARRAY_ARB,
            0,
            rgba8,
            size,
            0,
            GL_RGBA,
            UB,
            None,
        );
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE, "proxy {size:?}");
    }
    assert_eq!(
        ctx.get_tex_level_parameteriv(CUBE_ARRAY, 0, GL_TEXTURE_WIDTH),
        0
    );
    // Not a 2D target: glTexImage2D refuses it.
    ctx.tex_image(CUBE_ARRAY, 0, rgba8, [2, 2], 0, GL_RGBA, UB, None);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    let p = GL_PROXY_TEXTURE_CUBE_MAP_ARRAY_ARB;
    ctx.tex_image(p, 0, rgba8, [4, 4, 12], 0, GL_RGBA, UB, None);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.get_tex_level_parameteriv(p, 0, GL_TEXTURE_DEPTH), 12);
    let data = layer_faces(2, 2, 0);
    ctx.tex_image(
        CUBE_ARRAY,
        0,
        rgba8,
        [2, 2, 12],
        0,
        GL_RGBA,
        UB,
        Some(&data),
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(
        ctx.get_tex_level_parameteriv(CUBE_ARRAY, 0, GL_TEXTURE_DEPTH),
        12
    );
    // Sub-images of any layer-faces; outside the level GL_INVALID_VALUE.
    ctx.tex_sub_image(
        CUBE_ARRAY,
        0,
        [0, 0, 11],
        [2, 2, 1],
        GL_RGBA,
        UB,
        &[200, 0, 0, 255].repeat(4),
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    ctx.tex_sub_image(CUBE_ARRAY, 0, [0, 0, 12], [2, 2, 1], GL_RGBA, UB, &[0; 16]);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    // glGenerateMipmap filters each layer-face apart, keeping all 12.
    ctx.generate_mipmap(CUBE_ARRAY);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(
        ctx.get_tex_level_parameteriv(CUBE_ARRAY, 1, GL_TEXTURE_WIDTH),
        1
    );
    assert_eq!(
        ctx.get_tex_level_parameteriv(CUBE_ARRAY, 1, GL_TEXTURE_DEPTH),
        12
    );
    // Another target's texture cannot be bound to it.
    let other = ctx.gen_textures(1)[0];
    ctx.bind_texture(GL_TEXTURE_CUBE_MAP, other);
    ctx.bind_texture(CUBE_ARRAY, other);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.bind_texture(CUBE_ARRAY, t);
    // The sampler types' enums.
    let fs = "#version 130\n#extension GL_ARB_texture_cube_map_array : require\n\
              uniform samplerCubeArrayShadow z;\nout vec4 c;\n\
              void main() { c = vec4(texture(z, vec4(1.0), 0.5)); }";
    let prog = common::program(&mut ctx, VS, fs);
    let info = ctx.get_active_uniform(prog, 0).expect("one uniform");
    assert_eq!(
        (info.ty, info.name.as_str()),
        (GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW_ARB, "z")
    );
}

#[test]
fn lookups_pick_face_cube_and_level() {
    let mut ctx = Context::new(8, 8);
    let t = ctx.gen_textures(1)[0];
    ctx.bind_texture(CUBE_ARRAY, t);
    let rgba8 = GL_RGBA8 as i32;
    ctx.tex_image(
        CUBE_ARRAY,
        0,
        rgba8,
        [2, 2, 12],
        0,
        GL_RGBA,
        UB,
        Some(&layer_faces(2, 2, 0)),
    );
    ctx.tex_image(
        CUBE_ARRAY,
        1,
        rgba8,
        [1, 1, 12],
        0,
        GL_RGBA,
        UB,
        Some(&layer_faces(1, 2, 5)),
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    nearest(&mut ctx, GL_NEAREST_MIPMAP_NEAREST);
    let red = |lf: u32, plus: u32| format!("{}.0 / 255.0", 10 * lf + plus);
    // −Z of cube 1 is layer-face 11; +Y of cube 0 is 2; layer 0.5 rounds
    // up to cube 1 (+X: 6); past the last cube clamps to it.
    let ok = format!(
        "texture(s, vec4(0.0, 0.0, -1.0, 1.0)).r == {}
         && texture(s, vec4(0.1, 3.0, 0.2, 0.0)).r == {}
         && texture(s, vec4(1.0, 0.0, 0.0, 0.5)).r == {}
         && texture(s, vec4(-1.0, 0.2, 0.0, 9.0)).r == {}
         && textureLod(s, vec4(0.0, -1.0, 0.0, 1.0), 1.0).r == {}
         && textureGrad(s, vec4(0.0, 0.0, 1.0, 0.0), vec3(4.0, 0.0, 0.0), vec3(0.0)).r == {}
         && textureSize(s, 0) == ivec3(2, 2, 2) && textureSize(s, 1) == ivec3(1, 1, 2)",
        red(11, 0),
        red(2, 0),
        red(6, 0),
        red(7, 0),
        red(9, 5),
        red(4, 5),
    );
    assert_eq!(verdict(&mut ctx, "uniform samplerCubeArray s;", &ok), GREEN);
    // Integer layer-faces through an isamplerCubeArray.
    let u = ctx.gen_textures(1)[0];
    ctx.bind_texture(CUBE_ARRAY, u);
    let ints: Vec<u8> = (0..6i32)
        .flat_map(|lf| [-lf, lf, 0, 1])
        .flat_map(i32::to_le_bytes)
        .collect();
    let rgba32i = GL_RGBA32I as i32;
    ctx.tex_image(
        CUBE_ARRAY,
        0,
        rgba32i,
        [1, 1, 6],
        0,
        GL_RGBA_INTEGER,
        GL_INT,
        Some(&ints),
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    nearest(&mut ctx, GL_NEAREST);
    let ok = "texture(s, vec4(0.0, -2.0, 0.0, 0.0)) == ivec4(-3, 3, 0, 1)
              && textureLod(s, vec4(0.0, 0.0, 5.0, -1.0), 0.0) == ivec4(-4, 4, 0, 1)";
    assert_eq!(verdict(&mut ctx, "uniform isamplerCubeArray s;", ok), GREEN);
}

#[test]
fn shadow_lookups_compare_the_separate_reference() {
    let mut ctx = Context::new(8, 8);
    let t = ctx.gen_textures(1)[0];
    ctx.bind_texture(CUBE_ARRAY, t);
    // Two cubes: depth 0.25 on every face of cube 0, 0.75 on cube 1.
    let depths: Vec<u8> = (0..12)
        .flat_map(|lf| if lf < 6 { 0.25f32 } else { 0.75 }.to_le_bytes())
        .collect();
    let dc = GL_DEPTH_COMPONENT32F as i32;
    ctx.tex_image(
        CUBE_ARRAY,
        0,
        dc,
        [1, 1, 12],
        0,
        GL_DEPTH_COMPONENT,
        GL_FLOAT,
        Some(&depths),
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    nearest(&mut ctx, GL_NEAREST);
    let mode = GL_COMPARE_R_TO_TEXTURE as i32;
    ctx.tex_parameter(CUBE_ARRAY, GL_TEXTURE_COMPARE_MODE, Param::I(mode));
    ctx.tex_parameter(
        CUBE_ARRAY,
        GL_TEXTURE_COMPARE_FUNC,
        Param::I(GL_LEQUAL as i32),
    );
    let ok = "texture(s, vec4(1.0, 0.0, 0.0, 0.0), 0.2) == 1.0
              && texture(s, vec4(1.0, 0.0, 0.0, 0.0), 0.5) == 0.0
              && texture(s, vec4(0.0, 0.0, -1.0, 1.0), 0.5) == 1.0
              && texture(s, vec4(0.0, 0.0, -1.0, 1.0), 0.8) == 0.0
              && textureSize(s, 0) == ivec3(1, 1, 2)";
    assert_eq!(
        verdict(&mut ctx, "uniform samplerCubeArrayShadow s;", ok),
        GREEN
    );
}

#[test]
fn a_layer_face_is_a_framebuffer_attachment() {
    let mut ctx = Context::new(8, 8);
    let t = ctx.gen_textures(1)[0];
    ctx.bind_texture(CUBE_ARRAY, t);
    let rgba8 = GL_RGBA8 as i32;
    ctx.tex_image(
        CUBE_ARRAY,
        0,
        rgba8,
        [4, 4, 12],
        0,
        GL_RGBA,
        UB,
        Some(&layer_faces(4, 2, 0)),
    );
    nearest(&mut ctx, GL_NEAREST);
    let fb = ctx.gen_framebuffers(1)[0];
    ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
    // Layer-face 9: −Y of cube 1. Layers past the texture's stay
    // attachable (incomplete), a negative one is GL_INVALID_VALUE.
    ctx.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t, 0, -1);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.framebuffer_texture_layer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t, 0, 9);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(
        ctx.check_framebuffer_status(GL_FRAMEBUFFER),
        GL_FRAMEBUFFER_COMPLETE
    );
    ctx.clear_color(0.0, 1.0, 0.0, 1.0);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    let ok = "texture(s, vec4(0.0, -1.0, 0.0, 1.0)) == vec4(0.0, 1.0, 0.0, 1.0)
              && texture(s, vec4(0.0, 1.0, 0.0, 1.0)).r == 80.0 / 255.0
              && texture(s, vec4(0.0, -1.0, 0.0, 0.0)).r == 30.0 / 255.0";
    assert_eq!(verdict(&mut ctx, "uniform samplerCubeArray s;", ok), GREEN);
}
