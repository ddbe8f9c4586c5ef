//! GL 3.0-3.3 textures, end to end: integer formats sampled by
//! `isampler*`/`usampler*`, 1D and 2D array textures, rectangle
//! textures, and the GLSL 1.30 lookups (`texelFetch`, `textureSize`,
//! `textureOffset`, `textureGrad`) on them; each draw checks the values
//! in the shader and the test reads the verdict's colour.

use gl::enums::*;
use gl::param::Param;
use gl::Context;

mod common;

const UB: u32 = GL_UNSIGNED_BYTE;

/// The texture set-up these tests repeat, as methods of the context:
/// a new bound texture, level 0 images without a border, and nearest
/// filtering.
trait TextureSetup {
    fn ctx(&mut self) -> &mut Context;

    /// A new texture name bound to `target`.
    fn new_texture(&mut self, target: u32) -> u32 {
        let ctx = self.ctx();
        let t = ctx.gen_textures(1)[0];
        ctx.bind_texture(target, t);
        t
    }

    /// glTexImage of level 0 without a border, the only kind these tests
    /// make.
    fn level0<const D: usize>(
        &mut self,
        target: u32,
        internal: u32,
        size: [i32; D],
        format: u32,
        ty: u32,
        data: Option<&[u8]>,
    ) {
        let internal = internal as i32;
        (self.ctx()).tex_image(target, 0, internal, size, 0, format, ty, data);
    }

    /// Checks that the image just given to `target` was accepted, then
    /// filters it nearest, so that lookups return texels unblended.
    fn accepted_nearest(&mut self, target: u32) {
        assert_eq!(self.ctx().get_error(), GL_NO_ERROR, "{target:#x}");
        self.nearest(target);
    }

    /// Nearest minification and magnification on `target`.
    fn nearest(&mut self, target: u32) {
        for p in [GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER] {
            (self.ctx()).tex_parameter(target, p, Param::I(GL_NEAREST as i32));
        }
    }
}

impl TextureSetup for Context {
    fn ctx(&mut self) -> &mut Context {
        self
    }
}

const VS: &str = "#version 130\n\
    in vec2 pos;\n\
    out vec2 tc;\n\
    void main() { gl_Position = vec4(pos, 0.0, 1.0); tc = pos * 0.5 + 0.5; }";

const FULL_QUAD: [f32; 8] = [-1.0, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0];
const GREEN: [u8; 4] = [0, 255, 0, 255];
const RED: [u8; 4] = [255, 0, 0, 255];

/// A fragment shader of `header` (the `#version` line and declarations)
/// whose `main` runs `lets`, then writes green when the GLSL condition
/// `ok` holds and red when it does not.
fn checking_fs_after(header: &str, lets: &str, ok: &str) -> String {
    format!(
        "{header}\nout vec4 color;\nvoid main() {{\n{lets}\n  bool ok = {ok};\n  \
         color = ok ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0);\n}}\n"
    )
}

/// [`checking_fs_after`] with nothing to run before the condition.
fn checking_fs(header: &str, ok: &str) -> String {
    checking_fs_after(header, "", ok)
}

/// Links `fs` (which writes green when its checks pass, red otherwise)
/// with [`VS`], draws the full quad into an 8×8 context and returns the
/// pixel at (x, y).
fn draw(ctx: &mut Context, fs: &str, at: (i32, i32)) -> [u8; 4] {
    let p = common::program(ctx, VS, fs);
    let pos = ctx.get_attrib_location(p, "pos");
    assert!(pos >= 0);
    common::float_array(ctx, pos as u32, 2, &FULL_QUAD);
    ctx.clear_color(0.0, 0.0, 0.0, 0.0);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.take_draw_error(), None);
    ctx.read_pixels_f32(at.0, at.1, 1, 1)[0].map(|c| (c * 255.0).round() as u8)
}

/// Values as the little-endian bytes a client hands the GL.
trait LeBytes: Copy {
    fn le_bytes(self) -> Vec<u8>;
}

macro_rules! le_bytes {
    ($($t:ty),*) => {$(
        impl LeBytes for $t {
            fn le_bytes(self) -> Vec<u8> {
                self.to_le_bytes().to_vec()
            }
        }
    )*};
}
le_bytes!(i32, u16, f32);

fn bytes<T: LeBytes>(v: &[T]) -> Vec<u8> {
    v.iter().flat_map(|&x| x.le_bytes()).collect()
}

#[test]
fn integer_textures_sample_their_integers() {
    let mut ctx = Context::new(8, 8);
    ctx.new_texture(GL_TEXTURE_2D);
    // 2×1 RGBA32I texels with extremes, and an RGBA16UI level of the
    // second texture from bytes.
    let data = bytes(&[i32::MIN, -1, 7, i32::MAX, 1, 2, 3, 4]);
    ctx.level0(
        GL_TEXTURE_2D,
        GL_RGBA32I,
        [2, 1],
        GL_RGBA_INTEGER,
        GL_INT,
        Some(&data),
    );
    ctx.accepted_nearest(GL_TEXTURE_2D);
    let fs = checking_fs(
        "#version 130\nuniform isampler2D s;\nin vec2 tc;",
        "texture(s, vec2(0.25, 0.5)) == ivec4(-2147483647 - 1, -1, 7, 2147483647)
            && texelFetch(s, ivec2(1, 0), 0) == ivec4(1, 2, 3, 4)
            && textureSize(s, 0) == ivec2(2, 1)",
    );
    assert_eq!(draw(&mut ctx, &fs, (4, 4)), GREEN);
    // Unsigned, 8-bit red only: missing components 0, alpha 1; values
    // clamped to the format's range.
    let data = bytes(&[300u16, 65535]);
    let short = GL_UNSIGNED_SHORT;
    ctx.level0(
        GL_TEXTURE_2D,
        GL_R8UI,
        [2, 1],
        GL_RED_INTEGER,
        short,
        Some(&data),
    );
    ctx.accepted_nearest(GL_TEXTURE_2D);
    let fs = checking_fs(
        "#version 130\nuniform usampler2D s;",
        "texelFetch(s, ivec2(0, 0), 0) == uvec4(255u, 0u, 0u, 1u)",
    );
    assert_eq!(draw(&mut ctx, &fs, (4, 4)), GREEN);
    // A wrong expectation is seen as wrong (the check can fail).
    let fs_wrong = fs.replace("uvec4(255u, 0u, 0u, 1u)", "uvec4(254u, 0u, 0u, 1u)");
    assert_eq!(draw(&mut ctx, &fs_wrong, (4, 4)), RED);
}

#[test]
fn integer_formats_take_integer_data_only() {
    let mut ctx = Context::new(8, 8);
    ctx.new_texture(GL_TEXTURE_2D);
    let data = [0u8; 16];
    for (internal, format, ty) in [
        (GL_RGBA8I, GL_RGBA, GL_BYTE),
        (GL_RGBA8, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE),
        (GL_RGBA32UI, GL_RGBA_INTEGER, GL_FLOAT),
    ] {
        ctx.level0(GL_TEXTURE_2D, internal, [1, 1], format, ty, Some(&data));
        assert_eq!(
            ctx.get_error(),
            GL_INVALID_OPERATION,
            "{internal:#x} {format:#x} {ty:#x}"
        );
    }
    ctx.level0(
        GL_TEXTURE_2D,
        GL_RG16I,
        [1, 1],
        GL_RG_INTEGER,
        GL_SHORT,
        Some(&data),
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // A sub-image of an integer texture needs integer data too.
    ctx.tex_sub_image(GL_TEXTURE_2D, 0, [0, 0], [1, 1], GL_RG, GL_SHORT, &data);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
}

#[test]
fn array_textures_select_a_layer() {
    let mut ctx = Context::new(8, 8);
    let t = ctx.new_texture(GL_TEXTURE_2D_ARRAY);
    // Three 2×2 layers: red, green, blue.
    let mut texels = Vec::new();
    for layer in 0..3 {
        for _ in 0..4 {
            let mut c = [0u8, 0, 0, 255];
            c[layer] = 255;
            texels.extend(c);
        }
    }
    ctx.level0(
        GL_TEXTURE_2D_ARRAY,
        GL_RGBA8,
        [2, 2, 3],
        GL_RGBA,
        UB,
        Some(&texels),
    );
    ctx.accepted_nearest(GL_TEXTURE_2D_ARRAY);
    assert_eq!(ctx.get_integerv(GL_TEXTURE_BINDING_2D_ARRAY)[0], t as i32);
    let fs = checking_fs(
        "#version 130\nuniform sampler2DArray s;\nin vec2 tc;",
        "texture(s, vec3(tc, 0.4)) == vec4(1.0, 0.0, 0.0, 1.0)
            && texture(s, vec3(tc, 1.5)) == vec4(0.0, 0.0, 1.0, 1.0)
            && texture(s, vec3(tc, 7.0)) == vec4(0.0, 0.0, 1.0, 1.0)
            && texelFetch(s, ivec3(1, 1, 1), 0) == vec4(0.0, 1.0, 0.0, 1.0)
            && textureSize(s, 0) == ivec3(2, 2, 3)",
    );
    assert_eq!(draw(&mut ctx, &fs, (3, 5)), GREEN);
    // A 1D array from a 2D image: each row a layer.
    ctx.new_texture(GL_TEXTURE_1D_ARRAY);
    ctx.level0(
        GL_TEXTURE_1D_ARRAY,
        GL_RGBA8,
        [4, 3],
        GL_RGBA,
        UB,
        Some(&texels),
    );
    ctx.accepted_nearest(GL_TEXTURE_1D_ARRAY);
    let fs = checking_fs(
        "#version 130\nuniform sampler1DArray s;",
        "texture(s, vec2(0.1, 2.0)) == vec4(0.0, 0.0, 1.0, 1.0)
            && texture(s, vec2(0.9, 1.0)) == vec4(0.0, 1.0, 0.0, 1.0)
            && textureSize(s, 0) == ivec2(4, 3)",
    );
    assert_eq!(draw(&mut ctx, &fs, (3, 5)), GREEN);
}

#[test]
fn rectangle_textures_take_texel_coordinates() {
    let mut ctx = Context::new(8, 8);
    ctx.new_texture(GL_TEXTURE_RECTANGLE);
    // Rectangles start CLAMP_TO_EDGE and LINEAR; they take neither
    // repeating wraps nor mipmap filters nor a second level.
    assert_eq!(
        ctx.get_tex_parameteriv(GL_TEXTURE_RECTANGLE, GL_TEXTURE_WRAP_S),
        GL_CLAMP_TO_EDGE as i32
    );
    assert_eq!(
        ctx.get_tex_parameteriv(GL_TEXTURE_RECTANGLE, GL_TEXTURE_MIN_FILTER),
        GL_LINEAR as i32
    );
    for (pname, value) in [
        (GL_TEXTURE_WRAP_S, GL_REPEAT),
        (GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR),
    ] {
        ctx.tex_parameter(GL_TEXTURE_RECTANGLE, pname, Param::I(value as i32));
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM, "{pname:#x}");
    }
    let texels: Vec<u8> = (0..4 * 2).flat_map(|i| [i as u8 * 30, 0, 0, 255]).collect();
    let (rgba8, rect) = (GL_RGBA8 as i32, GL_TEXTURE_RECTANGLE);
    ctx.tex_image(rect, 1, rgba8, [4, 2], 0, GL_RGBA, UB, Some(&texels));
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.level0(rect, GL_RGBA8, [4, 2], GL_RGBA, UB, Some(&texels));
    ctx.accepted_nearest(rect);
    let fs = checking_fs(
        "#version 140\nuniform sampler2DRect s;",
        "texture(s, vec2(2.5, 1.5)).r == 180.0 / 255.0
            && texture(s, vec2(9.0, -3.0)).r == 90.0 / 255.0
            && texelFetch(s, ivec2(1, 1)).r == 150.0 / 255.0
            && textureOffset(s, vec2(0.5, 0.5), ivec2(3, 1)).r == 210.0 / 255.0
            && textureSize(s) == ivec2(4, 2)",
    );
    assert_eq!(draw(&mut ctx, &fs, (3, 5)), GREEN);
}

#[test]
fn offsets_gradients_and_fetches_on_2d_textures() {
    let mut ctx = Context::new(8, 8);
    ctx.new_texture(GL_TEXTURE_2D);
    // Level 0: 4×4 texels whose red is 16·j + 4·i (of 255); level 1: 2×2
    // blue; level 2: 1×1 green.
    let l0: Vec<u8> = (0..16u8).flat_map(|k| [k * 4, 0, 0, 255]).collect();
    let l1: Vec<u8> = [0u8, 0, 255, 255].repeat(4);
    let l2: Vec<u8> = vec![0, 255, 0, 255];
    let rgba8 = GL_RGBA8 as i32;
    for (level, size, data) in [(0, 4, &l0), (1, 2, &l1), (2, 1, &l2)] {
        let size = [size, size];
        ctx.tex_image(
            GL_TEXTURE_2D,
            level,
            rgba8,
            size,
            0,
            GL_RGBA,
            UB,
            Some(data),
        );
    }
    ctx.nearest(GL_TEXTURE_2D);
    ctx.tex_parameter(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        Param::I(GL_NEAREST_MIPMAP_NEAREST as i32),
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    let fs = checking_fs_after(
        "#version 130\nuniform sampler2D s;",
        "vec2 c = vec2(0.375, 0.125);",
        "textureOffset(s, c, ivec2(1, 2)).r == 40.0 / 255.0
            && textureLodOffset(s, c, 0.0, ivec2(-1, 0)).r == 0.0
            && textureGrad(s, c, vec2(0.5, 0.0), vec2(0.0, 0.5)) == vec4(0.0, 0.0, 1.0, 1.0)
            && textureGrad(s, c, vec2(1.0, 0.0), vec2(0.0, 0.0)) == vec4(0.0, 1.0, 0.0, 1.0)
            && texelFetch(s, ivec2(3, 3), 0).r == 60.0 / 255.0
            && texelFetchOffset(s, ivec2(0, 0), 1, ivec2(1, 1)) == vec4(0.0, 0.0, 1.0, 1.0)
            && textureSize(s, 1) == ivec2(2) && textureSize(s, 2) == ivec2(1)",
    );
    assert_eq!(draw(&mut ctx, &fs, (1, 6)), GREEN);
}

#[test]
fn srgb_textures_decode_to_linear() {
    let mut ctx = Context::new(8, 8);
    ctx.new_texture(GL_TEXTURE_2D);
    // Encoded 0, 10, 128, 255 (alpha stays linear).
    let texels = [0u8, 10, 128, 128, 255, 255, 255, 255];
    ctx.level0(
        GL_TEXTURE_2D,
        GL_SRGB8_ALPHA8,
        [2, 1],
        GL_RGBA,
        UB,
        Some(&texels),
    );
    ctx.accepted_nearest(GL_TEXTURE_2D);
    let fs = checking_fs_after(
        "#version 130\nuniform sampler2D s;",
        "vec4 a = texelFetch(s, ivec2(0, 0), 0);
        vec4 b = texture(s, vec2(0.75, 0.5));",
        "a.r == 0.0 && abs(a.g - (10.0 / 255.0) / 12.92) < 1e-6
            && abs(a.b - 0.2158605) < 1e-5 && a.a == 128.0 / 255.0
            && abs(b.r - 1.0) < 1e-6 && b.a == 1.0",
    );
    assert_eq!(draw(&mut ctx, &fs, (4, 4)), GREEN);
    // The same bytes in RGBA8 are not decoded (the check can fail).
    ctx.level0(GL_TEXTURE_2D, GL_RGBA8, [2, 1], GL_RGBA, UB, Some(&texels));
    assert_eq!(draw(&mut ctx, &fs, (4, 4)), RED);
}

#[test]
fn packed_float_formats_keep_their_precision() {
    let mut ctx = Context::new(8, 8);
    ctx.new_texture(GL_TEXTURE_2D);
    // R11F_G11F_B10F has 6 mantissa bits: 1 + 1/256 rounds to 1; negative
    // to 0; large to the largest 10-bit float. RGB9_E5: the shared exponent
    // of 4.0 leaves 9-bit mantissas below 8, steps of 1/64, so 0.01
    // becomes 0.015625.
    for (internal, texel, want) in [
        (
            GL_R11F_G11F_B10F,
            [1.0f32 + 1.0 / 256.0, -3.0, 1e6, 0.0],
            "vec4(1.0, 0.0, 64512.0, 1.0)",
        ),
        (
            GL_RGB9_E5,
            [4.0, 0.01, 1.0, 0.0],
            "vec4(4.0, 0.015625, 1.0, 1.0)",
        ),
    ] {
        let data = bytes(&texel);
        ctx.level0(
            GL_TEXTURE_2D,
            internal,
            [1, 1],
            GL_RGBA,
            GL_FLOAT,
            Some(&data),
        );
        ctx.accepted_nearest(GL_TEXTURE_2D);
        let fs = checking_fs(
            "#version 130\nuniform sampler2D s;",
            &format!("texelFetch(s, ivec2(0), 0) == {want}"),
        );
        assert_eq!(draw(&mut ctx, &fs, (4, 4)), GREEN, "{internal:#x}");
    }
}

#[test]
fn array_mipmaps_keep_their_layers() {
    let mut ctx = Context::new(8, 8);
    let array = GL_TEXTURE_2D_ARRAY;
    ctx.new_texture(array);
    // Two 4×4 layers, each solid: 64 and 192.
    let texels: Vec<u8> = [64u8, 192]
        .iter()
        .flat_map(|&v| [v, 0, 0, 255].repeat(16))
        .collect();
    ctx.level0(array, GL_RGBA8, [4, 4, 2], GL_RGBA, UB, Some(&texels));
    ctx.generate_mipmap(array);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.get_tex_level_parameteriv(array, 2, GL_TEXTURE_DEPTH), 2);
    assert_eq!(ctx.get_tex_level_parameteriv(array, 2, GL_TEXTURE_WIDTH), 1);
    ctx.tex_parameter(
        array,
        GL_TEXTURE_MIN_FILTER,
        Param::I(GL_NEAREST_MIPMAP_NEAREST as i32),
    );
    let fs = checking_fs(
        "#version 130\nuniform sampler2DArray s;",
        "textureLod(s, vec3(0.5, 0.5, 1.0), 2.0).r == 192.0 / 255.0
            && textureLod(s, vec3(0.5, 0.5, 0.0), 2.0).r == 64.0 / 255.0
            && textureSize(s, 2) == ivec3(1, 1, 2)",
    );
    assert_eq!(draw(&mut ctx, &fs, (4, 4)), GREEN);
    // Integer textures have no mipmaps to generate.
    let data = [0u8; 4];
    ctx.level0(array, GL_R8UI, [2, 2, 1], GL_RED_INTEGER, UB, Some(&data));
    ctx.generate_mipmap(array);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
}

#[test]
fn integer_images_read_back_as_integers() {
    let mut ctx = Context::new(8, 8);
    ctx.new_texture(GL_TEXTURE_2D);
    let data = bytes(&[i32::MIN, -1, 7, i32::MAX]);
    let (t2d, int) = (GL_TEXTURE_2D, GL_RGBA_INTEGER);
    ctx.level0(t2d, GL_RGBA32I, [1, 1], int, GL_INT, Some(&data));
    assert_eq!(ctx.get_tex_image(t2d, 0, int, GL_INT), data);
    // Clamped to the type's range; BGRA order.
    assert_eq!(
        ctx.get_tex_image(t2d, 0, GL_BGRA_INTEGER, GL_BYTE),
        vec![7, 0xff, 0x80, 0x7f]
    );
    // Not as normalized colours.
    assert!(ctx.get_tex_image(t2d, 0, GL_RGBA, UB).is_empty());
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    // A missing alpha reads as 1.
    ctx.level0(t2d, GL_R8UI, [1, 1], GL_RED_INTEGER, UB, Some(&[200]));
    ctx.pixel_storei(GL_PACK_ALIGNMENT, 1);
    assert_eq!(
        ctx.get_tex_image(t2d, 0, int, GL_UNSIGNED_SHORT),
        vec![200, 0, 0, 0, 0, 0, 1, 0]
    );
    // Colour textures are not read as integers.
    ctx.level0(t2d, GL_RGBA8, [1, 1], GL_RGBA, UB, Some(&[1, 2, 3, 4]));
    assert!(ctx.get_tex_image(t2d, 0, int, UB).is_empty());
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
}

#[test]
fn buffer_textures_fetch_from_their_buffer() {
    let mut ctx = Context::new(8, 8);
    let b = ctx.gen_buffers(1)[0];
    ctx.bind_buffer(GL_TEXTURE_BUFFER, b);
    let data = bytes(&[10, -20, 30, -40, 50, -60]);
    let len = data.len() as isize;
    ctx.buffer_data(GL_TEXTURE_BUFFER, len, Some(&data), GL_STATIC_DRAW);
    let t = ctx.new_texture(GL_TEXTURE_BUFFER);
    ctx.tex_buffer(GL_TEXTURE_BUFFER, GL_RGB8, b);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM, "no RGB formats in GL 3.1");
    ctx.tex_buffer(GL_TEXTURE_BUFFER, GL_RG32I, 12345);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.tex_buffer(GL_TEXTURE_BUFFER, GL_RG32I, b);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.get_integerv(GL_TEXTURE_BINDING_BUFFER)[0], t as i32);
    assert_eq!(
        ctx.get_integerv(GL_TEXTURE_BUFFER_DATA_STORE_BINDING)[0],
        b as i32
    );
    // Buffer textures have no filters to set.
    let nearest = Param::I(GL_NEAREST as i32);
    ctx.tex_parameter(GL_TEXTURE_BUFFER, GL_TEXTURE_MIN_FILTER, nearest);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    let fs = checking_fs(
        "#version 140\nuniform isamplerBuffer s;\nuniform int want;",
        "texelFetch(s, 2) == ivec4(50, -60, 0, 1)
            && texelFetch(s, 0).y == -20 && textureSize(s) == 3
            && texelFetch(s, 1).x == want",
    );
    // The first draw sees 30; after a write to the buffer, 99.
    let want = |ctx: &mut Context, v: i32| {
        let prog = ctx.get_integerv(GL_CURRENT_PROGRAM)[0] as u32;
        let loc = ctx.get_uniform_location(prog, "want");
        ctx.uniform_1i(loc, v);
    };
    // (`want` starts 0: the check can fail.)
    assert_eq!(draw(&mut ctx, &fs, (4, 4)), RED);
    let redraw = |ctx: &mut Context| {
        ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
        ctx.read_pixels_f32(4, 4, 1, 1)[0]
    };
    want(&mut ctx, 30);
    assert_eq!(redraw(&mut ctx), [0.0, 1.0, 0.0, 1.0]);
    ctx.buffer_sub_data(GL_TEXTURE_BUFFER, 8, &99i32.to_le_bytes());
    assert_eq!(redraw(&mut ctx), [1.0, 0.0, 0.0, 1.0]);
    want(&mut ctx, 99);
    assert_eq!(redraw(&mut ctx), [0.0, 1.0, 0.0, 1.0]);
}

/// A new framebuffer bound to GL_FRAMEBUFFER with level 0 of texture `t`
/// (of `target`) as its colour attachment 0; its completeness status.
fn texture_framebuffer(ctx: &mut Context, target: u32, t: u32) -> u32 {
    let fb = ctx.gen_framebuffers(1)[0];
    ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
    ctx.framebuffer_texture_2d(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target, t, 0);
    ctx.check_framebuffer_status(GL_FRAMEBUFFER)
}

#[test]
fn red_green_and_rectangle_textures_are_drawn_into() {
    let mut ctx = Context::new(8, 8);
    let fs_write = "#version 130\n\
        out vec4 color;\n\
        void main() { color = vec4(0.25, 0.75, 1.0, 0.5); }";
    for (target, internal, want) in [
        (GL_TEXTURE_2D, GL_RG8, [64u8, 191, 0, 255]),
        (GL_TEXTURE_2D, GL_R8, [64, 0, 0, 255]),
        (GL_TEXTURE_RECTANGLE, GL_RGBA8, [64, 191, 255, 128]),
    ] {
        let t = ctx.new_texture(target);
        ctx.level0(target, internal, [8, 8], GL_RGBA, UB, None);
        ctx.nearest(target);
        let status = texture_framebuffer(&mut ctx, target, t);
        assert_eq!(status, GL_FRAMEBUFFER_COMPLETE);
        draw(&mut ctx, fs_write, (2, 2));
        ctx.bind_framebuffer(GL_FRAMEBUFFER, 0);
        let got = ctx.get_tex_image(target, 0, GL_RGBA, GL_UNSIGNED_BYTE);
        assert_eq!(got[..4], want, "{internal:#x}");
    }
    // Integer colour buffers are not drawn into.
    let t = ctx.new_texture(GL_TEXTURE_2D);
    let int = GL_RGBA_INTEGER;
    ctx.level0(GL_TEXTURE_2D, GL_RGBA8UI, [8, 8], int, UB, None);
    let status = texture_framebuffer(&mut ctx, GL_TEXTURE_2D, t);
    assert_eq!(status, GL_FRAMEBUFFER_UNSUPPORTED);
    // A 1D array is attached by layer only.
    let t = ctx.new_texture(GL_TEXTURE_1D_ARRAY);
    ctx.framebuffer_texture_2d(
        GL_FRAMEBUFFER,
        GL_COLOR_ATTACHMENT0,
        GL_TEXTURE_1D_ARRAY,
        t,
        0,
    );
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
}

#[test]
fn depth_cube_maps_compare_through_sampler_cube_shadow() {
    let mut ctx = Context::new(8, 8);
    ctx.new_texture(GL_TEXTURE_CUBE_MAP);
    // Every face at depth 0.5 except +X at 0.25.
    for face in 0..6u32 {
        let d: f32 = if face == 0 { 0.25 } else { 0.5 };
        let (target, data) = (GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, bytes(&[d; 4]));
        let depth = GL_DEPTH_COMPONENT;
        ctx.level0(
            target,
            GL_DEPTH_COMPONENT32F,
            [2, 2],
            depth,
            GL_FLOAT,
            Some(&data),
        );
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
    }
    ctx.nearest(GL_TEXTURE_CUBE_MAP);
    for (pname, value) in [
        (GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE),
        (GL_TEXTURE_COMPARE_FUNC, GL_LESS),
    ] {
        ctx.tex_parameter(GL_TEXTURE_CUBE_MAP, pname, Param::I(value as i32));
    }
    let fs = checking_fs(
        "#version 130\nuniform samplerCubeShadow s;",
        "texture(s, vec4(1.0, 0.1, 0.1, 0.3)) == 0.0
            && texture(s, vec4(-1.0, 0.1, 0.1, 0.3)) == 1.0
            && texture(s, vec4(0.1, 0.1, 1.0, 0.6)) == 0.0",
    );
    assert_eq!(draw(&mut ctx, &fs, (4, 4)), GREEN);
}

#[test]
fn swizzles_rearrange_lookup_results() {
    let mut ctx = Context::new(8, 8);
    ctx.new_texture(GL_TEXTURE_2D);
    let texel = [255, 0, 51, 102];
    ctx.level0(GL_TEXTURE_2D, GL_RGBA8, [1, 1], GL_RGBA, UB, Some(&texel));
    ctx.accepted_nearest(GL_TEXTURE_2D);
    for (pname, value) in [
        (GL_TEXTURE_SWIZZLE_R, GL_BLUE),
        (GL_TEXTURE_SWIZZLE_G, GL_ONE),
        (GL_TEXTURE_SWIZZLE_A, GL_ZERO),
    ] {
        ctx.tex_parameter(GL_TEXTURE_2D, pname, Param::I(value as i32));
        assert_eq!(ctx.get_error(), GL_NO_ERROR, "{pname:#x}");
    }
    let rgba = Param::I(GL_RGBA as i32);
    ctx.tex_parameter(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_B, rgba);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    assert_eq!(
        ctx.get_tex_parameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_R),
        GL_BLUE as i32
    );
    assert_eq!(
        ctx.get_tex_parameterfv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA),
        [GL_BLUE, GL_ONE, GL_BLUE, GL_ZERO].map(|x| x as f32)
    );
    let fs = checking_fs(
        "#version 130\nuniform sampler2D s;",
        "texture(s, vec2(0.5)) == vec4(0.2, 1.0, 0.2, 0.0)
            && texelFetch(s, ivec2(0), 0) == vec4(0.2, 1.0, 0.2, 0.0)",
    );
    assert_eq!(draw(&mut ctx, &fs, (4, 4)), GREEN);
    // All four at once; back to the identity.
    let identity = [GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA].map(|x| x as i32);
    ctx.tex_parameter(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, Param::Iv(&identity));
    assert_eq!(draw(&mut ctx, &fs, (4, 4)), RED);
}

#[test]
fn level_queries_report_component_sizes_and_types() {
    let mut ctx = Context::new(8, 8);
    ctx.new_texture(GL_TEXTURE_2D);
    let q = |ctx: &mut Context, pname: u32| ctx.get_tex_level_parameteriv(GL_TEXTURE_2D, 0, pname);
    for (internal, format, size, ty) in [
        (GL_RGBA16I, GL_RGBA_INTEGER, 16, GL_INT),
        (GL_RGBA32UI, GL_RGBA_INTEGER, 32, GL_UNSIGNED_INT),
        (GL_RGBA16F, GL_RGBA, 16, GL_FLOAT),
        (GL_RGBA8, GL_RGBA, 8, GL_UNSIGNED_NORMALIZED),
    ] {
        ctx.level0(GL_TEXTURE_2D, internal, [1, 1], format, UB, None);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(q(&mut ctx, GL_TEXTURE_ALPHA_SIZE), size, "{internal:#x}");
        assert_eq!(q(&mut ctx, GL_TEXTURE_RED_TYPE), ty as i32, "{internal:#x}");
        assert_eq!(q(&mut ctx, GL_TEXTURE_DEPTH_TYPE), GL_NONE as i32);
    }
    ctx.level0(GL_TEXTURE_2D, GL_R8, [1, 1], GL_RED, UB, None);
    assert_eq!(q(&mut ctx, GL_TEXTURE_GREEN_TYPE), GL_NONE as i32);
    assert_eq!(q(&mut ctx, GL_TEXTURE_RED_SIZE), 8);
    let packed = GL_R11F_G11F_B10F;
    ctx.level0(GL_TEXTURE_2D, packed, [1, 1], GL_RGB, GL_FLOAT, None);
    assert_eq!(
        [
            q(&mut ctx, GL_TEXTURE_GREEN_SIZE),
            q(&mut ctx, GL_TEXTURE_BLUE_SIZE)
        ],
        [11, 10]
    );
}

/// Proxy targets (GL 3.3 §3.8.15): a supported image sets the proxy level's
/// sizes and format with no data and no error; one too large empties the
/// level, also without an error; bad arguments are errors as for the real
/// target; proxies cannot be bound or read back. VTK's volume mapper asks
/// `GL_PROXY_TEXTURE_3D` before it uploads a volume.
#[test]
fn proxy_textures_report_what_would_be_supported() {
    let mut ctx = Context::new(8, 8);
    let q = |ctx: &mut Context, target: u32, pname: u32| {
        ctx.get_tex_level_parameteriv(target, 0, pname)
    };
    // An RGBA8 image (or `ty`'s) of `size` on a proxy target, and the error.
    fn rgba<const D: usize>(ctx: &mut Context, target: u32, size: [i32; D], ty: u32) -> u32 {
        ctx.level0(target, GL_RGBA8, size, GL_RGBA, ty, None);
        ctx.get_error()
    }
    let p3d = GL_PROXY_TEXTURE_3D;
    ctx.level0(p3d, GL_R32F, [48, 40, 32], GL_RED, GL_FLOAT, None);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    let sizes = [GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_DEPTH]
        .map(|p| q(&mut ctx, GL_PROXY_TEXTURE_3D, p));
    assert_eq!(sizes, [48, 40, 32]);
    let format = q(&mut ctx, GL_PROXY_TEXTURE_3D, GL_TEXTURE_INTERNAL_FORMAT);
    assert_eq!(format, GL_R32F as i32);
    assert_eq!(q(&mut ctx, GL_PROXY_TEXTURE_3D, GL_TEXTURE_RED_SIZE), 32);
    // The real target is untouched.
    assert_eq!(q(&mut ctx, GL_TEXTURE_3D, GL_TEXTURE_WIDTH), 0);

    // Too large for a 3D texture: the proxy level empties, no error.
    assert_eq!(
        rgba(&mut ctx, GL_PROXY_TEXTURE_3D, [4096, 4, 4], UB),
        GL_NO_ERROR
    );
    assert_eq!(q(&mut ctx, GL_PROXY_TEXTURE_3D, GL_TEXTURE_WIDTH), 0);
    assert_eq!(q(&mut ctx, GL_PROXY_TEXTURE_3D, GL_TEXTURE_RED_SIZE), 0);
    // More texels than an image may hold: also unsupported, not an error.
    let huge = [2048, 2048, 32];
    assert_eq!(
        rgba(&mut ctx, GL_PROXY_TEXTURE_2D_ARRAY, huge, UB),
        GL_NO_ERROR
    );
    assert_eq!(q(&mut ctx, GL_PROXY_TEXTURE_2D_ARRAY, GL_TEXTURE_WIDTH), 0);
    assert_eq!(
        rgba(&mut ctx, GL_PROXY_TEXTURE_2D, [256, 128], UB),
        GL_NO_ERROR
    );
    assert_eq!(q(&mut ctx, GL_PROXY_TEXTURE_2D, GL_TEXTURE_HEIGHT), 128);
    assert_eq!(
        rgba(&mut ctx, GL_PROXY_TEXTURE_CUBE_MAP, [64, 64], UB),
        GL_NO_ERROR
    );
    assert_eq!(q(&mut ctx, GL_PROXY_TEXTURE_CUBE_MAP, GL_TEXTURE_WIDTH), 64);

    // Errors other than size stay errors.
    assert_eq!(
        rgba(&mut ctx, GL_PROXY_TEXTURE_2D, [-1, 4], UB),
        GL_INVALID_VALUE
    );
    assert_eq!(
        rgba(&mut ctx, GL_PROXY_TEXTURE_2D, [4, 4], 0x1234),
        GL_INVALID_ENUM
    );
    let cube = rgba(&mut ctx, GL_PROXY_TEXTURE_CUBE_MAP, [64, 32], UB);
    assert_eq!(cube, GL_INVALID_VALUE);
    // A 2D proxy target is not a 3D call's target.
    assert_eq!(
        rgba(&mut ctx, GL_PROXY_TEXTURE_2D, [4, 4, 4], UB),
        GL_INVALID_ENUM
    );
    // No binding, parameters or image of a proxy.
    ctx.bind_texture(GL_PROXY_TEXTURE_2D, 1);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    ctx.get_tex_parameteriv(GL_PROXY_TEXTURE_2D, GL_TEXTURE_MIN_FILTER);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    ctx.get_tex_image(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
}
