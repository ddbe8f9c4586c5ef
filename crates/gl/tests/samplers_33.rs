//! Sampler objects (GL 3.3 §3.8.2): a bound sampler's state replaces the
//! texture's for shader lookups and leaves the texture's parameters as
//! they were; names, bindings, parameter values and their errors.

use gl::enums::*;
use gl::param::Param;
use gl::Context;

mod common;

const VS: &str = "#version 330\n\
    in vec2 pos;\n\
    void main() { gl_Position = vec4(pos, 0.0, 1.0); }";

/// A context with a 2×1 RGBA8 texture on unit 1 (texel 0 red, texel 1
/// green; the texture's own filters LINEAR, wraps REPEAT) and a program
/// drawing the lookup at `uniform vec2 at` over the whole 4×4 target.
fn setup() -> (Context, u32) {
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_CORE);
    let t = ctx.gen_textures(1)[0];
    ctx.active_texture(GL_TEXTURE1);
    ctx.bind_texture(GL_TEXTURE_2D, t);
    let texels = [255u8, 0, 0, 255, 0, 255, 0, 255];
    ctx.tex_image(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        [2, 1],
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&texels),
    );
    ctx.tex_parameter(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        Param::I(GL_LINEAR as i32),
    );
    ctx.active_texture(GL_TEXTURE0);
    let fs = "#version 330\n\
        uniform sampler2D s;\n\
        uniform vec2 at;\n\
        out vec4 color;\n\
        void main() { color = texture(s, at); }";
    let p = common::program(&mut ctx, VS, fs);
    let s = ctx.get_uniform_location(p, "s");
    ctx.uniform_1i(s, 1);
    common::quad_vertex_array(&mut ctx, p, "pos");
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    (ctx, p)
}

/// The colour drawn for a lookup at `at` (0-255 per channel).
fn look(ctx: &mut Context, p: u32, at: [f32; 2]) -> [u8; 4] {
    let l = ctx.get_uniform_location(p, "at");
    ctx.uniform_2f(l, at[0], at[1]);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.take_draw_error(), None);
    ctx.read_pixels_f32(1, 1, 1, 1)[0].map(|c| (c * 255.0).round() as u8)
}

#[test]
fn a_bound_sampler_overrides_the_textures_sampling_state() {
    let (mut ctx, p) = setup();
    // The texture's own state: linear between the two texels, repeating.
    let linear = look(&mut ctx, p, [0.4, 0.5]);
    assert!(linear[0] > 100 && linear[1] > 30, "{linear:?}");
    assert_eq!(look(&mut ctx, p, [1.25, 0.5]), [255, 0, 0, 255]);

    let s = ctx.gen_samplers(1)[0];
    assert!(ctx.is_sampler(s));
    for pname in [GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER] {
        ctx.sampler_parameter(s, pname, Param::I(GL_NEAREST as i32));
    }
    ctx.sampler_parameter(s, GL_TEXTURE_WRAP_S, Param::I(GL_CLAMP_TO_EDGE as i32));
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // Bound to another unit: no effect on unit 1.
    ctx.bind_sampler(0, s);
    assert_eq!(look(&mut ctx, p, [0.4, 0.5]), linear);
    ctx.bind_sampler(1, s);
    ctx.active_texture(GL_TEXTURE1);
    assert_eq!(ctx.get_integerv(GL_SAMPLER_BINDING), vec![s as i32]);
    assert_eq!(look(&mut ctx, p, [0.4, 0.5]), [255, 0, 0, 255]);
    // CLAMP_TO_EDGE: past the right edge is the last texel.
    assert_eq!(look(&mut ctx, p, [1.25, 0.5]), [0, 255, 0, 255]);
    // The texture's parameters are untouched and queryable.
    assert_eq!(
        ctx.get_tex_parameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER),
        GL_LINEAR as i32
    );
    assert_eq!(
        ctx.get_tex_parameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S),
        GL_REPEAT as i32
    );
    // A change of the sampler's state shows at the next draw.
    ctx.sampler_parameter(s, GL_TEXTURE_WRAP_S, Param::I(GL_REPEAT as i32));
    assert_eq!(look(&mut ctx, p, [1.25, 0.5]), [255, 0, 0, 255]);
    // Sampler 0: the texture's own state again.
    ctx.bind_sampler(1, 0);
    assert_eq!(look(&mut ctx, p, [0.4, 0.5]), linear);
    // Deleting a bound sampler unbinds it.
    ctx.bind_sampler(1, s);
    assert_eq!(look(&mut ctx, p, [0.4, 0.5]), [255, 0, 0, 255]);
    ctx.delete_samplers(&[s]);
    assert!(!ctx.is_sampler(s));
    assert_eq!(ctx.get_integerv(GL_SAMPLER_BINDING), vec![0]);
    assert_eq!(look(&mut ctx, p, [0.4, 0.5]), linear);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}

#[test]
fn the_border_colour_comes_from_the_sampler() {
    let (mut ctx, p) = setup();
    let s = ctx.gen_samplers(1)[0];
    ctx.sampler_parameter(s, GL_TEXTURE_WRAP_S, Param::I(GL_CLAMP_TO_BORDER as i32));
    ctx.sampler_parameter(s, GL_TEXTURE_BORDER_COLOR, Param::Fv(&[0.0, 0.0, 1.0, 1.0]));
    ctx.sampler_parameter(s, GL_TEXTURE_MIN_FILTER, Param::I(GL_NEAREST as i32));
    ctx.sampler_parameter(s, GL_TEXTURE_MAG_FILTER, Param::I(GL_NEAREST as i32));
    ctx.bind_sampler(1, s);
    assert_eq!(look(&mut ctx, p, [1.5, 0.5]), [0, 0, 255, 255]);
    assert_eq!(
        ctx.get_sampler_parameter(s, GL_TEXTURE_BORDER_COLOR),
        vec![0.0, 0.0, 1.0, 1.0]
    );
    // The texture's border colour stays the default.
    ctx.active_texture(GL_TEXTURE1);
    assert_eq!(
        ctx.get_tex_parameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR),
        vec![0.0; 4]
    );
}

#[test]
fn a_rectangle_texture_under_a_repeating_sampler_is_incomplete() {
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_CORE);
    let t = ctx.gen_textures(1)[0];
    ctx.bind_texture(GL_TEXTURE_RECTANGLE, t);
    ctx.tex_image(
        GL_TEXTURE_RECTANGLE,
        0,
        GL_RGBA8 as i32,
        [1, 1],
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&[0, 255, 0, 255]),
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    let fs = "#version 330\n\
        uniform sampler2DRect s;\n\
        out vec4 color;\n\
        void main() { color = texture(s, vec2(0.5)); }";
    let p = common::program(&mut ctx, VS, fs);
    common::quad_vertex_array(&mut ctx, p, "pos");
    let draw = |ctx: &mut Context| {
        ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
        assert_eq!(ctx.take_draw_error(), None);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.read_pixels_f32(1, 1, 1, 1)[0].map(|c| (c * 255.0).round() as u8)
    };
    assert_eq!(draw(&mut ctx), [0, 255, 0, 255]);
    let s = ctx.gen_samplers(1)[0];
    ctx.sampler_parameter(s, GL_TEXTURE_MIN_FILTER, Param::I(GL_LINEAR as i32));
    ctx.sampler_parameter(s, GL_TEXTURE_WRAP_S, Param::I(GL_CLAMP_TO_EDGE as i32));
    ctx.sampler_parameter(s, GL_TEXTURE_WRAP_T, Param::I(GL_CLAMP_TO_EDGE as i32));
    ctx.bind_sampler(0, s);
    assert_eq!(draw(&mut ctx), [0, 255, 0, 255]);
    // REPEAT on s or t is refused for rectangles: the texture is
    // incomplete and samples (0, 0, 0, 1). (The r wrap, still the default
    // REPEAT, is no axis of a rectangle.)
    ctx.sampler_parameter(s, GL_TEXTURE_WRAP_T, Param::I(GL_REPEAT as i32));
    assert_eq!(draw(&mut ctx), [0, 0, 0, 255]);
    ctx.sampler_parameter(s, GL_TEXTURE_WRAP_T, Param::I(GL_CLAMP_TO_EDGE as i32));
    assert_eq!(draw(&mut ctx), [0, 255, 0, 255]);
    ctx.sampler_parameter(
        s,
        GL_TEXTURE_MIN_FILTER,
        Param::I(GL_LINEAR_MIPMAP_NEAREST as i32),
    );
    assert_eq!(draw(&mut ctx), [0, 0, 0, 255]);
}

#[test]
fn sampler_errors_are_the_specs() {
    let mut ctx = Context::with_api(4, 4, gl::Api::GL33_CORE);
    assert!(!ctx.is_sampler(0));
    assert!(!ctx.is_sampler(7));
    ctx.gen_samplers(-1);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    let s = ctx.gen_samplers(2);
    assert_eq!(s.len(), 2);
    assert_ne!(s[0], s[1]);
    // BindSampler: an unknown name, a unit out of range.
    ctx.bind_sampler(0, 12345);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.bind_sampler(gl::MAX_TEXTURE_IMAGE_UNITS as u32, s[0]);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.bind_sampler(gl::MAX_TEXTURE_IMAGE_UNITS as u32 - 1, s[0]);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // Parameters: an unknown sampler (INVALID_OPERATION, as GL 4.x and
    // Mesa), texture state that is no sampler state, bad values.
    ctx.sampler_parameter(12345, GL_TEXTURE_MIN_FILTER, Param::I(GL_NEAREST as i32));
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    for pname in [
        GL_TEXTURE_BASE_LEVEL,
        GL_TEXTURE_MAX_LEVEL,
        GL_TEXTURE_SWIZZLE_R,
        GL_DEPTH_TEXTURE_MODE,
        GL_TEXTURE_2D,
    ] {
        ctx.sampler_parameter(s[0], pname, Param::I(0));
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM, "{pname:#x}");
        ctx.get_sampler_parameter(s[0], pname);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM, "{pname:#x}");
    }
    ctx.sampler_parameter(
        s[0],
        GL_TEXTURE_MAG_FILTER,
        Param::I(GL_LINEAR_MIPMAP_LINEAR as i32),
    );
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    ctx.sampler_parameter(s[0], GL_TEXTURE_WRAP_R, Param::I(GL_LINEAR as i32));
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    ctx.sampler_parameter(s[0], GL_TEXTURE_COMPARE_FUNC, Param::I(GL_RED as i32));
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    ctx.sampler_parameter(s[0], GL_TEXTURE_BORDER_COLOR, Param::F(1.0));
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    // Refused values leave the state as it was.
    assert_eq!(
        ctx.get_sampler_parameter(s[0], GL_TEXTURE_MAG_FILTER),
        vec![GL_LINEAR as f32]
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // Defaults (GL 3.3 Table 6.23) and set values read back.
    for (pname, want) in [
        (GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_LINEAR as f32),
        (GL_TEXTURE_WRAP_T, GL_REPEAT as f32),
        (GL_TEXTURE_MIN_LOD, -1000.0),
        (GL_TEXTURE_MAX_LOD, 1000.0),
        (GL_TEXTURE_LOD_BIAS, 0.0),
        (GL_TEXTURE_COMPARE_MODE, GL_NONE as f32),
        (GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL as f32),
    ] {
        assert_eq!(
            ctx.get_sampler_parameter(s[1], pname),
            vec![want],
            "{pname:#x}"
        );
    }
    ctx.sampler_parameter(s[1], GL_TEXTURE_MAX_LOD, Param::F(2.5));
    ctx.sampler_parameter(
        s[1],
        GL_TEXTURE_COMPARE_MODE,
        Param::I(GL_COMPARE_REF_TO_TEXTURE as i32),
    );
    assert_eq!(
        ctx.get_sampler_parameter(s[1], GL_TEXTURE_MAX_LOD),
        vec![2.5]
    );
    assert_eq!(
        ctx.get_sampler_parameter(s[1], GL_TEXTURE_COMPARE_MODE),
        vec![GL_COMPARE_REF_TO_TEXTURE as f32]
    );
    ctx.get_sampler_parameter(12345, GL_TEXTURE_MAX_LOD);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    // Deleting an unknown name or 0 is no error; deleted names are unbound
    // from every unit.
    ctx.bind_sampler(3, s[0]);
    ctx.delete_samplers(&[0, 999, s[0]]);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    ctx.active_texture(GL_TEXTURE3);
    assert_eq!(ctx.get_integerv(GL_SAMPLER_BINDING), vec![0]);
    ctx.bind_sampler(0, s[0]);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    let exts: Vec<&str> = (0..ctx.get_integerv(GL_NUM_EXTENSIONS)[0])
        .filter_map(|i| ctx.get_stringi(GL_EXTENSIONS, i as u32))
        .collect();
    assert!(exts.contains(&"GL_ARB_sampler_objects"));
}
