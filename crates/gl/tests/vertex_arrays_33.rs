//! GL 3.0-3.3 vertex arrays and draws, end to end: vertex array objects,
//! integer attributes, instancing with divisors, `gl_VertexID` and
//! `gl_InstanceID`, base-vertex and range draws, primitive restart.

use gl::enums::*;
use gl::{ArrayData, Context};

mod common;
use common::{float_array, program};

/// The colour buffer, RGBA8, bottom row first.
fn image(ctx: &mut Context) -> Vec<[u8; 4]> {
    let (w, h) = (
        ctx.get_integerv(GL_VIEWPORT)[2],
        ctx.get_integerv(GL_VIEWPORT)[3],
    );
    ctx.read_pixels_f32(0, 0, w, h)
        .iter()
        .map(|p| p.map(|c| (c * 255.0).round() as u8))
        .collect()
}

fn pixel(ctx: &mut Context, x: i32, y: i32) -> [u8; 4] {
    ctx.read_pixels_f32(x, y, 1, 1)[0].map(|c| (c * 255.0).round() as u8)
}

fn clear(ctx: &mut Context) {
    ctx.clear_color(0.0, 0.0, 0.0, 0.0);
    ctx.clear(GL_COLOR_BUFFER_BIT);
}

fn attrib(ctx: &mut Context, p: u32, name: &str) -> u32 {
    let l = ctx.get_attrib_location(p, name);
    assert!(l >= 0, "{name}");
    l as u32
}

fn i32_bytes(v: &[i32]) -> ArrayData {
    ArrayData::from_bytes(&v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>())
}

/// A buffer object holding `bytes`, bound to `target`.
fn buffer(ctx: &mut Context, target: u32, bytes: &[u8]) -> u32 {
    let b = ctx.gen_buffers(1)[0];
    ctx.bind_buffer(target, b);
    ctx.buffer_data(target, bytes.len() as isize, Some(bytes), GL_STATIC_DRAW);
    b
}

fn f32_bytes(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_le_bytes()).collect()
}

const FULL_QUAD: [f32; 8] = [-1.0, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0];
const GREEN: [u8; 4] = [0, 255, 0, 255];
const RED: [u8; 4] = [255, 0, 0, 255];

/// An `ivec4`/`uvec4` input reads the integers exactly, extremes
/// included, from integer arrays (32-bit and sign-extended 16-bit) and
/// from integer current values.
#[test]
fn integer_attributes_arrive_unconverted() {
    let vs = "#version 130\n\
        in vec2 pos;\n\
        in ivec4 code;\n\
        in uvec4 ucode;\n\
        flat out int ok;\n\
        void main() {\n\
          gl_Position = vec4(pos, 0.0, 1.0);\n\
          ok = int(code == ivec4(-2147483647 - 1, 2147483647, -1, 16777217)\n\
                   && ucode == uvec4(4294967295u, 2147483648u, 0u, 16777219u));\n\
        }";
    let fs = "#version 130\n\
        flat in int ok;\n\
        out vec4 color;\n\
        void main() { color = ok == 1 ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0); }";
    let mut ctx = Context::new(8, 8);
    let p = program(&mut ctx, vs, fs);
    let (pos, code, ucode) = (
        attrib(&mut ctx, p, "pos"),
        attrib(&mut ctx, p, "code"),
        attrib(&mut ctx, p, "ucode"),
    );
    float_array(&mut ctx, pos, 2, &FULL_QUAD);
    let codes: Vec<i32> = [i32::MIN, i32::MAX, -1, 16777217].repeat(4);
    let ucodes: Vec<u32> = [u32::MAX, 1 << 31, 0, 16777219].repeat(4);
    // Arrays.
    ctx.vertex_attrib_i_pointer(code, 4, GL_INT, 0, i32_bytes(&codes));
    ctx.vertex_attrib_i_pointer(ucode, 4, GL_UNSIGNED_INT, 0, ArrayData::from_u32(&ucodes));
    ctx.enable_vertex_attrib_array(code);
    ctx.enable_vertex_attrib_array(ucode);
    clear(&mut ctx);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.take_draw_error(), None);
    assert_eq!(pixel(&mut ctx, 4, 4), GREEN);
    assert_eq!(
        ctx.get_vertex_attrib_array(code, GL_VERTEX_ATTRIB_ARRAY_INTEGER),
        Some(1)
    );
    // The same values as current values.
    ctx.disable_vertex_attrib_array(code);
    ctx.disable_vertex_attrib_array(ucode);
    ctx.vertex_attrib_i4i(code, [i32::MIN, i32::MAX, -1, 16777217]);
    ctx.vertex_attrib_i4ui(ucode, [u32::MAX, 1 << 31, 0, 16777219]);
    assert_eq!(
        ctx.get_current_vertex_attrib_integer(ucode, true),
        [u32::MAX, 1 << 31, 0, 16777219]
    );
    clear(&mut ctx);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(pixel(&mut ctx, 4, 4), GREEN);
    // A wrong value is seen as wrong (the test can fail).
    ctx.vertex_attrib_i4i(code, [i32::MIN + 1, i32::MAX, -1, 16777217]);
    clear(&mut ctx);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(pixel(&mut ctx, 4, 4), RED);
    // 16-bit signed components are sign-extended.
    let vs16 = "#version 130\n\
        in vec2 pos;\n\
        in ivec2 code;\n\
        flat out int ok;\n\
        void main() { gl_Position = vec4(pos, 0.0, 1.0); ok = int(code == ivec2(-32768, -1)); }";
    let p = program(&mut ctx, vs16, fs);
    let (pos, code) = (attrib(&mut ctx, p, "pos"), attrib(&mut ctx, p, "code"));
    float_array(&mut ctx, pos, 2, &FULL_QUAD);
    let shorts: Vec<u16> = [0x8000u16, 0xffff].repeat(4);
    ctx.vertex_attrib_i_pointer(code, 2, GL_SHORT, 0, ArrayData::from_u16(&shorts));
    ctx.enable_vertex_attrib_array(code);
    clear(&mut ctx);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(pixel(&mut ctx, 4, 4), GREEN);
}

const INSTANCED_FS: &str = "#version 140\n\
    flat in vec4 c;\n\
    out vec4 color;\n\
    void main() { color = c; }";

/// The vertex shaders (inputs `pos` and `tint`, flat output `c`) of an
/// instanced draw and of the separate draws it must equal: the same
/// `main` body, which reads the instance number from `instance`, taken
/// from `gl_InstanceID` in the first and from a uniform set before each
/// draw in the second.
fn instanced_and_separate_vs(body: &str) -> [String; 2] {
    let io = "in vec2 pos;\nin vec4 tint;\nflat out vec4 c;\n";
    [
        format!("#version 140\n{io}void main() {{\nint instance = gl_InstanceID;\n{body}\n}}"),
        format!("#version 140\nuniform int instance;\n{io}void main() {{\n{body}\n}}"),
    ]
}

/// A draw of N instances renders what N draws render, with
/// `gl_InstanceID` and a divisor-2 colour array standing for a uniform
/// and a current value changed between the draws.
#[test]
fn instanced_draw_equals_separate_draws() {
    let [instanced_vs, separate_vs] = instanced_and_separate_vs(
        "vec2 o = vec2(-0.75 + 0.5 * float(instance), 0.0);
        gl_Position = vec4(pos * 0.2 + o, 0.0, 1.0);
        c = tint;",
    );
    let tints = [
        1.0, 0.0, 0.0, 1.0, //
        0.0, 0.0, 1.0, 1.0,
    ];
    let instanced = {
        let mut ctx = Context::new(32, 16);
        let p = program(&mut ctx, &instanced_vs, INSTANCED_FS);
        let (pos, tint) = (attrib(&mut ctx, p, "pos"), attrib(&mut ctx, p, "tint"));
        float_array(&mut ctx, pos, 2, &FULL_QUAD);
        float_array(&mut ctx, tint, 4, &tints);
        ctx.vertex_attrib_divisor(tint, 2);
        assert_eq!(
            ctx.get_vertex_attrib_array(tint, GL_VERTEX_ATTRIB_ARRAY_DIVISOR),
            Some(2)
        );
        clear(&mut ctx);
        ctx.draw_arrays_instanced(GL_TRIANGLE_STRIP, 0, 4, 4);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(ctx.take_draw_error(), None);
        image(&mut ctx)
    };
    let separate = {
        let mut ctx = Context::new(32, 16);
        let p = program(&mut ctx, &separate_vs, INSTANCED_FS);
        let (pos, tint) = (attrib(&mut ctx, p, "pos"), attrib(&mut ctx, p, "tint"));
        let u = ctx.get_uniform_location(p, "instance");
        float_array(&mut ctx, pos, 2, &FULL_QUAD);
        clear(&mut ctx);
        for i in 0..4 {
            ctx.uniform_1i(u, i);
            let t = &tints[4 * (i as usize / 2)..][..4];
            ctx.vertex_attrib_4f(tint, t[0], t[1], t[2], t[3]);
            ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
        }
        image(&mut ctx)
    };
    assert!(instanced == separate);
    // Four squares: red, red, blue, blue, centred at x = 4, 12, 20, 28.
    let at = |x: usize| instanced[8 * 32 + x];
    assert_eq!(
        [at(4), at(12), at(20), at(28), at(8)],
        [RED, RED, [0, 0, 255, 255], [0, 0, 255, 255], [0; 4]]
    );
}

/// `gl_VertexID` is the index fetched, base vertex added; instanced
/// element draws repeat the elements per instance.
#[test]
fn vertex_id_with_base_vertex_and_instanced_elements() {
    // Points at x = -0.875 + 0.25 * id, y from gl_InstanceID; the colour
    // says which vertex drew.
    let vs = "#version 140\n\
        flat out vec4 c;\n\
        void main() {\n\
          gl_Position = vec4(-0.875 + 0.25 * float(gl_VertexID), -0.5 + float(gl_InstanceID), 0.0, 1.0);\n\
          c = vec4(float(gl_VertexID) / 255.0, float(gl_InstanceID) / 255.0, 0.0, 1.0);\n\
        }";
    let mut ctx = Context::new(8, 2);
    program(&mut ctx, vs, INSTANCED_FS);
    clear(&mut ctx);
    let elements: Vec<u8> = vec![0, 2, 3];
    let eb = buffer(&mut ctx, GL_ELEMENT_ARRAY_BUFFER, &elements);
    assert_ne!(eb, 0);
    ctx.draw_elements_instanced_base_vertex(
        GL_POINTS,
        3,
        GL_UNSIGNED_BYTE,
        ArrayData::Offset(0),
        2,
        2,
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.take_draw_error(), None);
    for inst in 0..2 {
        for x in 0..8 {
            let want = if [2, 4, 5].contains(&x) {
                [x as u8, inst as u8, 0, 255]
            } else {
                [0; 4]
            };
            assert_eq!(pixel(&mut ctx, x, inst), want, "x {x} instance {inst}");
        }
    }
    // glDrawRangeElementsBaseVertex and glMultiDrawElementsBaseVertex
    // draw the same vertices.
    let want = image(&mut ctx);
    clear(&mut ctx);
    ctx.draw_range_elements_base_vertex(
        GL_POINTS,
        0,
        3,
        3,
        GL_UNSIGNED_BYTE,
        ArrayData::Offset(0),
        2,
    );
    ctx.draw_elements_instanced(GL_POINTS, 3, GL_UNSIGNED_BYTE, ArrayData::Offset(0), 0);
    assert_eq!(pixel(&mut ctx, 2, 0), [2, 0, 0, 255]);
    assert_eq!(pixel(&mut ctx, 2, 1), [0; 4]);
    clear(&mut ctx);
    ctx.multi_draw_elements_base_vertex(
        GL_POINTS,
        &[1, 2],
        GL_UNSIGNED_BYTE,
        &[ArrayData::Offset(0), ArrayData::Offset(1)],
        &[2, 2],
    );
    // No vertices: nothing drawn.
    ctx.draw_elements_instanced(GL_POINTS, 0, GL_UNSIGNED_BYTE, ArrayData::Offset(0), 2);
    let img = image(&mut ctx);
    assert_eq!(&img[..8], &want[..8]);
    assert!(img[8..].iter().all(|p| *p == [0; 4]));
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}

/// A strip with restart indices draws as the strips between them; the
/// comparison is made before the base vertex is added; with restart off
/// the index is a vertex like any other.
#[test]
fn primitive_restart_splits_strips() {
    let vs = "#version 140\n\
        in vec2 pos;\n\
        void main() { gl_Position = vec4(pos, 0.0, 1.0); }";
    let fs = "#version 140\n\
        out vec4 color;\n\
        void main() { color = vec4(0.0, 1.0, 0.0, 1.0); }";
    // Two separate squares (left and right halves, a gap between), and a
    // last vertex (index 0xff, far away) that only a strip without
    // restart reaches.
    let mut pos = vec![0.0f32; 2 * 256];
    let squares = [
        -1.0, -1.0, -0.2, -1.0, -1.0, 1.0, -0.2, 1.0, //
        0.2, -1.0, 1.0, -1.0, 0.2, 1.0, 1.0, 1.0,
    ];
    pos[..16].copy_from_slice(&squares);
    pos[2 * 255] = 1.0;
    pos[2 * 255 + 1] = -1.0;
    let draw = |restart: bool, base: i32, elements: &[u8]| {
        let mut ctx = Context::new(20, 10);
        let p = program(&mut ctx, vs, fs);
        let a = attrib(&mut ctx, p, "pos");
        let shifted: Vec<f32> = std::iter::repeat_n(0.0, 2 * base.max(0) as usize)
            .chain(pos.iter().copied())
            .collect();
        float_array(&mut ctx, a, 2, &shifted);
        if restart {
            ctx.enable(GL_PRIMITIVE_RESTART);
        }
        ctx.primitive_restart_index(0xff);
        clear(&mut ctx);
        let eb = buffer(&mut ctx, GL_ELEMENT_ARRAY_BUFFER, elements);
        assert_ne!(eb, 0);
        ctx.draw_elements_base_vertex(
            GL_TRIANGLE_STRIP,
            elements.len() as i32,
            GL_UNSIGNED_BYTE,
            ArrayData::Offset(0),
            base,
        );
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        image(&mut ctx)
    };
    let restarted = draw(true, 0, &[0, 1, 2, 3, 0xff, 4, 5, 6, 7]);
    let separate = {
        let mut a = draw(false, 0, &[0, 1, 2, 3]);
        let b = draw(false, 0, &[4, 5, 6, 7]);
        for (x, y) in a.iter_mut().zip(b) {
            if y != [0; 4] {
                *x = y;
            }
        }
        a
    };
    assert!(restarted == separate);
    // The gap between the squares stays clear.
    assert_eq!(restarted[5 * 20 + 10], [0; 4]);
    assert_eq!(restarted[5 * 20 + 2], GREEN);
    // Restart compares before the base vertex: 0xff still restarts.
    assert!(draw(true, 3, &[0, 1, 2, 3, 0xff, 4, 5, 6, 7]) == separate);
    // Without restart, 0xff is vertex 255: triangles across the gap.
    let plain = draw(false, 0, &[0, 1, 2, 3, 0xff, 4, 5, 6, 7]);
    assert!(plain != separate);
    // Queries.
    let mut ctx = Context::new(4, 4);
    assert_eq!(ctx.get_integerv(GL_PRIMITIVE_RESTART), vec![0]);
    ctx.enable(GL_PRIMITIVE_RESTART);
    ctx.primitive_restart_index(65535);
    assert!(ctx.is_enabled(GL_PRIMITIVE_RESTART));
    assert_eq!(ctx.get_integerv(GL_PRIMITIVE_RESTART_INDEX), vec![65535]);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}

/// Each vertex array object draws with its own arrays and element
/// buffer; the default object keeps client arrays.
#[test]
fn vertex_array_objects_draw_their_own_arrays() {
    let vs = "#version 140\n\
        in vec2 pos;\n\
        in vec4 col;\n\
        flat out vec4 c;\n\
        void main() { gl_Position = vec4(pos, 0.0, 1.0); c = col; }";
    let mut ctx = Context::new(8, 8);
    let p = program(&mut ctx, vs, INSTANCED_FS);
    let (pos, col) = (attrib(&mut ctx, p, "pos"), attrib(&mut ctx, p, "col"));
    let vaos = ctx.gen_vertex_arrays(2);
    let left = [-1.0, -1.0, 0.0, -1.0, -1.0, 1.0, 0.0, 1.0];
    let right = [0.0, -1.0, 1.0, -1.0, 0.0, 1.0, 1.0, 1.0];
    for (&vao, (quad, colour)) in vaos
        .iter()
        .zip([(left, [1.0, 0.0, 0.0, 1.0]), (right, [0.0, 0.0, 1.0, 1.0])])
    {
        ctx.bind_vertex_array(vao);
        buffer(&mut ctx, GL_ARRAY_BUFFER, &f32_bytes(&quad));
        ctx.vertex_attrib_pointer(pos, 2, GL_FLOAT, false, 0, ArrayData::Offset(0));
        ctx.enable_vertex_attrib_array(pos);
        let colours: Vec<f32> = colour.repeat(4);
        buffer(&mut ctx, GL_ARRAY_BUFFER, &f32_bytes(&colours));
        ctx.vertex_attrib_pointer(col, 4, GL_FLOAT, false, 0, ArrayData::Offset(0));
        ctx.enable_vertex_attrib_array(col);
        buffer(&mut ctx, GL_ELEMENT_ARRAY_BUFFER, &[0u8, 1, 2, 3]);
    }
    ctx.bind_buffer(GL_ARRAY_BUFFER, 0);
    ctx.bind_vertex_array(0);
    clear(&mut ctx);
    // Nothing enabled in the default object: no position array.
    assert!(!ctx.vertex_state().generic_arrays[pos as usize].enabled);
    ctx.bind_vertex_array(vaos[1]);
    ctx.draw_elements(GL_TRIANGLE_STRIP, 4, GL_UNSIGNED_BYTE, ArrayData::Offset(0));
    assert_eq!(pixel(&mut ctx, 1, 4), [0; 4]);
    assert_eq!(pixel(&mut ctx, 6, 4), [0, 0, 255, 255]);
    ctx.bind_vertex_array(vaos[0]);
    assert_eq!(ctx.vertex_array_binding(), vaos[0]);
    assert_eq!(
        ctx.get_vertex_attrib_array(pos, GL_VERTEX_ATTRIB_ARRAY_ENABLED),
        Some(1)
    );
    ctx.draw_elements(GL_TRIANGLE_STRIP, 4, GL_UNSIGNED_BYTE, ArrayData::Offset(0));
    assert_eq!(pixel(&mut ctx, 1, 4), RED);
    assert_eq!(pixel(&mut ctx, 6, 4), [0, 0, 255, 255]);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // Client arrays in the default object after the others.
    ctx.bind_vertex_array(0);
    float_array(&mut ctx, pos, 2, &FULL_QUAD);
    ctx.vertex_attrib_4f(col, 0.0, 1.0, 0.0, 1.0);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(pixel(&mut ctx, 6, 4), GREEN);
    // glPushClientAttrib keeps the binding and the object's arrays.
    ctx.bind_vertex_array(vaos[0]);
    ctx.push_client_attrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    ctx.disable_vertex_attrib_array(pos);
    ctx.bind_vertex_array(vaos[1]);
    ctx.pop_client_attrib();
    assert_eq!(ctx.vertex_array_binding(), vaos[0]);
    assert!(ctx.vertex_state().generic_arrays[pos as usize].enabled);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}

/// The errors GL 3.3 names for the new calls.
#[test]
fn draw_errors() {
    let mut ctx = Context::new(4, 4);
    ctx.draw_arrays_instanced(GL_TRIANGLES, 0, 3, -1);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.draw_arrays_instanced(GL_TRIANGLES, 0, -3, 1);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.draw_arrays_instanced(0xdead, 0, 3, 1);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    let idx = ArrayData::from_bytes(&[0, 1, 2]);
    ctx.draw_elements_instanced(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, idx.clone(), -2);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.draw_elements_instanced(GL_TRIANGLES, 3, GL_FLOAT, idx.clone(), 1);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    ctx.draw_elements_base_vertex(GL_TRIANGLES, -1, GL_UNSIGNED_BYTE, idx.clone(), 1);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.draw_range_elements_base_vertex(GL_TRIANGLES, 5, 4, 3, GL_UNSIGNED_BYTE, idx.clone(), 0);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.multi_draw_elements_base_vertex(
        GL_TRIANGLES,
        &[3, -1],
        GL_UNSIGNED_BYTE,
        &[idx.clone(), idx],
        &[0, 0],
    );
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.vertex_attrib_i_pointer(0, 4, GL_FLOAT, 0, ArrayData::Offset(0));
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    ctx.vertex_attrib_i_pointer(
        gl::MAX_VERTEX_ATTRIBS as u32,
        4,
        GL_INT,
        0,
        ArrayData::Offset(0),
    );
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.vertex_attrib_i4i(gl::MAX_VERTEX_ATTRIBS as u32, [0; 4]);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.vertex_attrib_divisor(gl::MAX_VERTEX_ATTRIBS as u32, 1);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}

/// Instanced element draws with restart and a base vertex, strips and
/// fans, render what one draw per instance renders.
#[test]
fn instanced_restart_strips_equal_separate_draws() {
    let [instanced_vs, separate_vs] = instanced_and_separate_vs(
        "vec2 o = vec2(0.0, -0.9 + 0.3 * float(instance));
        gl_Position = vec4(pos * vec2(1.0, 0.1) + o, 0.0, 1.0);
        c = tint + vec4(float(gl_VertexID) / 64.0, 0.0, 0.0, 0.0);",
    );
    // Vertices 3.. : two squares side by side (left, right), as strips.
    let mut pos = vec![0.0f32; 6];
    pos.extend([
        -0.9, -1.0, -0.1, -1.0, -0.9, 1.0, -0.1, 1.0, //
        0.1, -1.0, 0.9, -1.0, 0.1, 1.0, 0.9, 1.0,
    ]);
    let tints: Vec<f32> = (0..7)
        .flat_map(|i| [0.0, i as f32 / 8.0, 1.0 - i as f32 / 8.0, 1.0])
        .collect();
    let strip: Vec<u8> = vec![0, 1, 2, 3, 0xff, 4, 5, 6, 7];
    let fan: Vec<u8> = vec![0, 1, 3, 2, 0xff, 4, 5, 7, 6];
    for (mode, elements) in [(GL_TRIANGLE_STRIP, &strip), (GL_TRIANGLE_FAN, &fan)] {
        let setup = |vs: &str, divisor: bool| {
            let mut ctx = Context::new(24, 24);
            let p = program(&mut ctx, vs, INSTANCED_FS);
            let (a, t) = (attrib(&mut ctx, p, "pos"), attrib(&mut ctx, p, "tint"));
            float_array(&mut ctx, a, 2, &pos);
            if divisor {
                float_array(&mut ctx, t, 4, &tints);
                ctx.vertex_attrib_divisor(t, 1);
            }
            ctx.enable(GL_PRIMITIVE_RESTART);
            ctx.primitive_restart_index(0xff);
            buffer(&mut ctx, GL_ELEMENT_ARRAY_BUFFER, elements);
            clear(&mut ctx);
            (ctx, p, t)
        };
        let instanced = {
            let (mut ctx, _, _) = setup(&instanced_vs, true);
            ctx.draw_elements_instanced_base_vertex(
                mode,
                elements.len() as i32,
                GL_UNSIGNED_BYTE,
                ArrayData::Offset(0),
                7,
                3,
            );
            assert_eq!(ctx.get_error(), GL_NO_ERROR);
            image(&mut ctx)
        };
        let separate = {
            let (mut ctx, p, t) = setup(&separate_vs, false);
            let u = ctx.get_uniform_location(p, "instance");
            for i in 0..7 {
                ctx.uniform_1i(u, i);
                let c = &tints[4 * i as usize..][..4];
                ctx.vertex_attrib_4f(t, c[0], c[1], c[2], c[3]);
                ctx.draw_elements_base_vertex(
                    mode,
                    elements.len() as i32,
                    GL_UNSIGNED_BYTE,
                    ArrayData::Offset(0),
                    3,
                );
            }
            image(&mut ctx)
        };
        assert!(instanced == separate, "mode {mode:#x}");
        // Seven rows of two squares (instance 0 at rows 0-2, instance 6
        // at rows 22-23), gaps between them.
        let row = |y: usize| &instanced[y * 24..][..24];
        assert!(row(1)[4] != [0; 4] && row(1)[20] != [0; 4] && row(1)[12] == [0; 4]);
        assert!(row(3).iter().all(|p| *p == [0; 4]));
        assert!(row(22)[4] != [0; 4] && row(22)[4] != row(1)[4]);
    }
}

/// GL 3.0-3.3 vertex formats in a draw: half-float positions, a BGRA
/// colour array, packed 2_10_10_10 values.
#[test]
fn half_float_bgra_and_packed_arrays_draw() {
    let vs = "#version 130\n\
        in vec2 pos;\n\
        in vec4 col;\n\
        in vec4 words;\n\
        flat out vec4 c;\n\
        void main() { gl_Position = vec4(pos, 0.0, 1.0); c = col * vec4(words.xyz, 1.0); }";
    let fs = "#version 130\n\
        flat in vec4 c;\n\
        out vec4 color;\n\
        void main() { color = c; }";
    let mut ctx = Context::new(4, 4);
    let p = program(&mut ctx, vs, fs);
    let (pos, col, packed) = (
        attrib(&mut ctx, p, "pos"),
        attrib(&mut ctx, p, "col"),
        attrib(&mut ctx, p, "words"),
    );
    // -1.0 and 1.0 as half floats.
    let halves: Vec<u16> = [
        0xbc00u16, 0xbc00, 0x3c00, 0xbc00, 0xbc00, 0x3c00, 0x3c00, 0x3c00,
    ]
    .to_vec();
    ctx.vertex_attrib_pointer(
        pos,
        2,
        GL_HALF_FLOAT,
        false,
        0,
        ArrayData::from_u16(&halves),
    );
    ctx.enable_vertex_attrib_array(pos);
    let bgra: Vec<u8> = [255u8, 0, 51, 255].repeat(4);
    ctx.vertex_attrib_pointer(
        col,
        gl::vertex_format::SIZE_BGRA,
        GL_UNSIGNED_BYTE,
        true,
        0,
        ArrayData::from_bytes(&bgra),
    );
    ctx.enable_vertex_attrib_array(col);
    // x = 1023 (1.0), y = 511 (0.5), z = 1023, normalized unsigned.
    let word: u32 = 1023 | (511 << 10) | (1023 << 20);
    ctx.vertex_attrib_pointer(
        packed,
        4,
        GL_UNSIGNED_INT_2_10_10_10_REV,
        true,
        0,
        ArrayData::from_u32(&[word; 4]),
    );
    ctx.enable_vertex_attrib_array(packed);
    clear(&mut ctx);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.take_draw_error(), None);
    assert_eq!(pixel(&mut ctx, 1, 1), [51, 0, 255, 255]);
    assert_eq!(
        ctx.get_vertex_attrib_array(col, GL_VERTEX_ATTRIB_ARRAY_SIZE),
        Some(GL_BGRA as i64)
    );
}

/// A core draw needs a vertex array object (GL_INVALID_OPERATION
/// without), but not a program: without one its results are undefined
/// (GL 3.3 §2.11), which is no error, and nothing is drawn.
#[test]
fn core_draws_without_a_program_draw_nothing() {
    let mut ctx = Context::with_api(8, 8, gl::Api::GL33_CORE);
    clear(&mut ctx);
    ctx.draw_arrays(GL_TRIANGLES, 0, 3);
    assert_eq!(
        ctx.get_error(),
        GL_INVALID_OPERATION,
        "no vertex array object"
    );
    let vao = ctx.gen_vertex_arrays(1)[0];
    ctx.bind_vertex_array(vao);
    ctx.draw_arrays(GL_TRIANGLES, 0, 3);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    let blank = image(&mut ctx);
    clear(&mut ctx);
    assert_eq!(image(&mut ctx), blank);
}
