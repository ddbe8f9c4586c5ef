//! Uniform blocks end to end: std140 offsets and the block queries of a
//! linked program, and draws that read block members from the buffers
//! bound to the blocks' binding points.

use gl::enums::*;
use gl::uniform_block::INVALID_INDEX;
use gl::Context;

mod common;
use common::program;

const VS: &str = "#version 150\nin vec4 pos;\nvoid main() { gl_Position = pos; }\n";
const FS: &str = "#version 150
layout(std140) uniform Colors {
    vec4 colour;
    mat4 m;
    float weights[3];
    layout(row_major) mat2 r;
};
uniform Extra { vec4 add; } extra;
out vec4 result;
void main() {
    vec4 c = m * colour;
    result = vec4(c.x, c.y * weights[2], (r * vec2(1.0, 0.0)).y, 1.0) + extra.add;
}
";

fn f32_bytes(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|f| f.to_ne_bytes()).collect()
}

/// The Colors block's bytes (160) followed, at 256, by Extra's add.
fn buffer_bytes(colour: [f32; 4], add: [f32; 4]) -> Vec<u8> {
    let mut w = vec![0f32; 68];
    w[0..4].copy_from_slice(&colour);
    // m swaps x and z: columns (0,0,1,0) (0,1,0,0) (1,0,0,0) (0,0,0,1).
    let m = [
        0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ];
    w[4..20].copy_from_slice(&m);
    // weights[i] at 80 + 16 i.
    w[20] = 9.0;
    w[24] = 9.0;
    w[28] = 0.5;
    // r, row-major at 128: row 0 (0.9, 0.1), row 1 (0.6, 0.3).
    w[32..34].copy_from_slice(&[0.9, 0.1]);
    w[36..38].copy_from_slice(&[0.6, 0.3]);
    w[64..68].copy_from_slice(&add);
    f32_bytes(&w)
}

fn pixel(ctx: &mut Context) -> [f32; 4] {
    ctx.read_pixels_f32(4, 4, 1, 1)[0]
}

fn assert_close(a: [f32; 4], b: [f32; 4]) {
    assert!(
        a.iter().zip(b).all(|(x, y)| (x - y).abs() < 0.01),
        "{a:?} != {b:?}"
    );
}

#[test]
fn block_queries_report_std140() {
    let mut ctx = Context::new(8, 8);
    let p = program(&mut ctx, VS, FS);
    assert_eq!(ctx.get_programiv(p, GL_ACTIVE_UNIFORM_BLOCKS), 2);
    assert_eq!(
        ctx.get_programiv(p, GL_ACTIVE_UNIFORM_BLOCK_MAX_NAME_LENGTH),
        7
    );
    let colors = ctx.get_uniform_block_index(p, "Colors");
    let extra = ctx.get_uniform_block_index(p, "Extra");
    assert_eq!((colors, extra), (0, 1));
    assert_eq!(ctx.get_uniform_block_index(p, "extra"), INVALID_INDEX);
    assert_eq!(
        ctx.get_active_uniform_block_name(p, 1).as_deref(),
        Some("Extra")
    );
    let iv = |ctx: &mut Context, b, pname| ctx.get_active_uniform_blockiv(p, b, pname).unwrap();
    assert_eq!(iv(&mut ctx, colors, GL_UNIFORM_BLOCK_DATA_SIZE), vec![160]);
    assert_eq!(iv(&mut ctx, extra, GL_UNIFORM_BLOCK_DATA_SIZE), vec![16]);
    assert_eq!(iv(&mut ctx, colors, GL_UNIFORM_BLOCK_NAME_LENGTH), vec![7]);
    assert_eq!(
        iv(&mut ctx, colors, GL_UNIFORM_BLOCK_ACTIVE_UNIFORMS),
        vec![4]
    );
    assert_eq!(iv(&mut ctx, colors, GL_UNIFORM_BLOCK_BINDING), vec![0]);
    assert_eq!(
        iv(
            &mut ctx,
            colors,
            GL_UNIFORM_BLOCK_REFERENCED_BY_FRAGMENT_SHADER
        ),
        vec![1]
    );
    assert_eq!(
        iv(
            &mut ctx,
            colors,
            GL_UNIFORM_BLOCK_REFERENCED_BY_VERTEX_SHADER
        ),
        vec![0]
    );
    let names = [
        "colour",
        "m",
        "weights",
        "r",
        "Extra.add",
        "weights[0]",
        "add",
    ];
    let idx = ctx.get_uniform_indices(p, &names).unwrap();
    assert_eq!(idx[5], idx[2]);
    assert_eq!(idx[6], INVALID_INDEX);
    let idx = &idx[..5];
    let mut members = iv(&mut ctx, colors, GL_UNIFORM_BLOCK_ACTIVE_UNIFORM_INDICES);
    members.sort();
    let mut expected: Vec<i32> = idx[..4].iter().map(|&i| i as i32).collect();
    expected.sort();
    assert_eq!(members, expected);
    let q = |ctx: &mut Context, pname| ctx.get_active_uniformsiv(p, idx, pname).unwrap();
    assert_eq!(q(&mut ctx, GL_UNIFORM_OFFSET), vec![0, 16, 80, 128, 0]);
    assert_eq!(q(&mut ctx, GL_UNIFORM_ARRAY_STRIDE), vec![0, 0, 16, 0, 0]);
    assert_eq!(q(&mut ctx, GL_UNIFORM_MATRIX_STRIDE), vec![0, 16, 0, 16, 0]);
    assert_eq!(q(&mut ctx, GL_UNIFORM_IS_ROW_MAJOR), vec![0, 0, 0, 1, 0]);
    assert_eq!(q(&mut ctx, GL_UNIFORM_BLOCK_INDEX), vec![0, 0, 0, 0, 1]);
    assert_eq!(q(&mut ctx, GL_UNIFORM_SIZE), vec![1, 1, 3, 1, 1]);
    assert_eq!(
        q(&mut ctx, GL_UNIFORM_TYPE),
        vec![
            GL_FLOAT_VEC4 as i32,
            GL_FLOAT_MAT4 as i32,
            GL_FLOAT as i32,
            GL_FLOAT_MAT2 as i32,
            GL_FLOAT_VEC4 as i32
        ]
    );
    assert_eq!(q(&mut ctx, GL_UNIFORM_NAME_LENGTH), vec![7, 2, 11, 2, 10]);
    assert_eq!(
        ctx.get_active_uniform_name(p, idx[2]).as_deref(),
        Some("weights[0]")
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // Block members have no location; glUniform* cannot reach them.
    assert_eq!(ctx.get_uniform_location(p, "colour"), -1);
    assert_eq!(ctx.get_uniform_location(p, "Extra.add"), -1);
    assert_eq!(ctx.get_uniform_location(p, "extra.add"), -1);
    // Errors.
    assert_eq!(
        ctx.get_active_uniform_blockiv(p, 2, GL_UNIFORM_BLOCK_DATA_SIZE),
        None
    );
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    assert_eq!(ctx.get_active_uniform_blockiv(p, 0, GL_UNIFORM_SIZE), None);
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    assert_eq!(
        ctx.get_active_uniformsiv(p, &[0, 99], GL_UNIFORM_OFFSET),
        None
    );
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    assert_eq!(
        ctx.get_active_uniformsiv(p, &[0], GL_UNIFORM_BLOCK_BINDING),
        None
    );
    assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    assert_eq!(ctx.get_active_uniform_block_name(p, 7), None);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    assert_eq!(ctx.get_active_uniform_name(p, 99), None);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.uniform_block_binding(p, 2, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.uniform_block_binding(p, 0, 36);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.uniform_block_binding(p, 0, 35);
    assert_eq!(iv(&mut ctx, 0, GL_UNIFORM_BLOCK_BINDING), vec![35]);
    assert_eq!(ctx.get_uniform_block_index(12345, "Colors"), INVALID_INDEX);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    // Relinking resets the bindings.
    ctx.link_program(p);
    assert_eq!(iv(&mut ctx, 0, GL_UNIFORM_BLOCK_BINDING), vec![0]);
}

#[test]
fn draws_read_blocks_from_their_binding_points() {
    let mut ctx = Context::new(8, 8);
    let p = program(&mut ctx, VS, FS);
    ctx.use_program(p);
    let quad = [
        -1.0, -1.0, 0.0, 1.0, 1.0, -1.0, 0.0, 1.0, -1.0, 1.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0,
    ];
    let pos = ctx.get_attrib_location(p, "pos") as u32;
    common::float_array(&mut ctx, pos, 4, &quad);
    let buf = ctx.gen_buffers(1)[0];
    ctx.bind_buffer(GL_UNIFORM_BUFFER, buf);
    let bytes = buffer_bytes([0.25, 0.5, 0.75, 1.0], [0.1, 0.1, 0.1, 0.0]);
    ctx.buffer_data(
        GL_UNIFORM_BUFFER,
        bytes.len() as isize,
        Some(&bytes),
        GL_DYNAMIC_DRAW,
    );
    // Colors on binding point 2 (the whole buffer), Extra on 5 (the range
    // at 256).
    ctx.uniform_block_binding(p, 0, 2);
    ctx.uniform_block_binding(p, 1, 5);
    ctx.bind_buffer_base(GL_UNIFORM_BUFFER, 2, buf);
    ctx.bind_buffer_range(GL_UNIFORM_BUFFER, 5, buf, 256, 16);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.take_draw_error(), None);
    // m * colour = (0.75, 0.5, 0.25, 1); weights[2] halves green; r's
    // column 0 is (0.9, 0.6) (row-major: 0.1 if read column-major).
    assert_close(pixel(&mut ctx), [0.85, 0.35, 0.7, 1.0]);
    // New buffer contents, same bindings: a new picture.
    ctx.buffer_sub_data(GL_UNIFORM_BUFFER, 0, &f32_bytes(&[0.0, 1.0, 0.0, 1.0]));
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_close(pixel(&mut ctx), [0.1, 0.6, 0.7, 1.0]);
    // Nothing bound to Extra's point: its members read as zeros.
    ctx.bind_buffer_base(GL_UNIFORM_BUFFER, 5, 0);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_close(pixel(&mut ctx), [0.0, 0.5, 0.6, 1.0]);
    // A range too short for the block: members past it read as zeros
    // (r lives at 128..160).
    ctx.bind_buffer_range(GL_UNIFORM_BUFFER, 2, buf, 0, 128);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_close(pixel(&mut ctx), [0.0, 0.5, 0.0, 1.0]);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
}

#[test]
fn vertex_stage_blocks_and_arrays_of_blocks() {
    let vs = "#version 150
uniform Xform { mat4 mvp; };
in vec4 pos;
void main() { gl_Position = mvp * pos; }
";
    let fs = "#version 150
uniform Xform { mat4 mvp; };
uniform Pal { vec4 c; } pal[2];
out vec4 o;
void main() { o = pal[0].c + pal[1].c + vec4(0.0, 0.0, mvp[0][0], 0.0); }
";
    let mut ctx = Context::new(8, 8);
    let p = program(&mut ctx, vs, fs);
    ctx.use_program(p);
    assert_eq!(ctx.get_programiv(p, GL_ACTIVE_UNIFORM_BLOCKS), 3);
    let xform = ctx.get_uniform_block_index(p, "Xform");
    let pal0 = ctx.get_uniform_block_index(p, "Pal[0]");
    let pal1 = ctx.get_uniform_block_index(p, "Pal[1]");
    assert_eq!(ctx.get_uniform_block_index(p, "Pal"), INVALID_INDEX);
    assert_eq!(ctx.get_uniform_block_index(p, "Pal[2]"), INVALID_INDEX);
    assert_ne!(pal0, pal1);
    let iv = |ctx: &mut Context, b, pname| ctx.get_active_uniform_blockiv(p, b, pname).unwrap()[0];
    let (by_vs, by_fs) = (
        GL_UNIFORM_BLOCK_REFERENCED_BY_VERTEX_SHADER,
        GL_UNIFORM_BLOCK_REFERENCED_BY_FRAGMENT_SHADER,
    );
    // Both stages declare Xform; only the fragment stage has Pal.
    assert_eq!(iv(&mut ctx, xform, by_vs), 1);
    assert_eq!(iv(&mut ctx, xform, by_fs), 1);
    assert_eq!(iv(&mut ctx, pal0, by_vs), 0);
    assert_eq!(iv(&mut ctx, pal1, by_fs), 1);
    assert_eq!(iv(&mut ctx, pal1, GL_UNIFORM_BLOCK_NAME_LENGTH), 7);
    assert_eq!(iv(&mut ctx, xform, GL_UNIFORM_BLOCK_DATA_SIZE), 64);
    assert_eq!(
        ctx.get_uniform_indices(p, &["mvp", "Pal.c"]).unwrap().len(),
        2
    );
    assert!(!ctx
        .get_uniform_indices(p, &["mvp", "Pal.c"])
        .unwrap()
        .contains(&INVALID_INDEX));

    // Xform: a scale by 0.5 (the quad covers the middle 4x4 pixels).
    let mut bytes = Vec::new();
    for (i, v) in [0.5f32, 0.5, 0.5, 1.0].iter().enumerate() {
        let mut col = [0.0f32; 4];
        col[i] = *v;
        bytes.extend(f32_bytes(&col));
    }
    // Pal[0] at 256, Pal[1] at 512.
    bytes.resize(256, 0);
    bytes.extend(f32_bytes(&[0.25, 0.0, 0.0, 0.5]));
    bytes.resize(512, 0);
    bytes.extend(f32_bytes(&[0.0, 0.75, 0.0, 0.5]));
    let b = ctx.gen_buffers(1)[0];
    ctx.bind_buffer(GL_UNIFORM_BUFFER, b);
    ctx.buffer_data(
        GL_UNIFORM_BUFFER,
        bytes.len() as isize,
        Some(&bytes),
        GL_STATIC_DRAW,
    );
    for (block, binding, offset) in [(xform, 0, 0), (pal0, 1, 256), (pal1, 2, 512)] {
        ctx.uniform_block_binding(p, block, binding);
        ctx.bind_buffer_range(
            GL_UNIFORM_BUFFER,
            binding,
            b,
            offset,
            16.max(64 - offset.min(64)),
        );
    }
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    let quad = [
        -1.0, -1.0, 0.0, 1.0, 1.0, -1.0, 0.0, 1.0, -1.0, 1.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0,
    ];
    let pos = ctx.get_attrib_location(p, "pos") as u32;
    common::float_array(&mut ctx, pos, 4, &quad);
    ctx.clear_color(0.0, 0.0, 1.0, 1.0);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.take_draw_error(), None);
    // Blue: the fragment stage's view of Xform (mvp[0][0] = 0.5).
    assert_close(pixel(&mut ctx), [0.25, 0.75, 0.5, 1.0]);
    assert_close(ctx.read_pixels_f32(0, 0, 1, 1)[0], [0.0, 0.0, 1.0, 1.0]);
}

/// The instance names of one block may differ between stages (GLSL 1.50
/// §4.3.7): each stage reads the block through its own instance. An
/// output block without an instance name feeds the fragment stage's
/// named instance of the block.
#[test]
fn instance_names_differ_between_stages() {
    let vs = "#version 150
uniform Col { vec4 c; } vcol;
in vec4 pos;
out Pass { vec4 v; };
void main() { gl_Position = pos; v = vcol.c; }
";
    let fs = "#version 150
uniform Col { vec4 c; } fcol;
in Pass { vec4 v; } pass;
out vec4 o;
void main() { o = pass.v * 0.5 + fcol.c.wzyx * 0.5; }
";
    let mut ctx = Context::new(8, 8);
    let p = program(&mut ctx, vs, fs);
    let quad = [
        -1.0, -1.0, 0.0, 1.0, 1.0, -1.0, 0.0, 1.0, -1.0, 1.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0,
    ];
    let pos = ctx.get_attrib_location(p, "pos") as u32;
    common::float_array(&mut ctx, pos, 4, &quad);
    let bytes = f32_bytes(&[0.2, 0.4, 0.6, 1.0]);
    let b = ctx.gen_buffers(1)[0];
    ctx.bind_buffer(GL_UNIFORM_BUFFER, b);
    ctx.buffer_data(
        GL_UNIFORM_BUFFER,
        bytes.len() as isize,
        Some(&bytes),
        GL_STATIC_DRAW,
    );
    ctx.bind_buffer_base(GL_UNIFORM_BUFFER, 0, b);
    ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
    assert_eq!(ctx.take_draw_error(), None);
    // Half the colour through the varying, half its reverse from the
    // fragment stage's instance.
    assert_close(pixel(&mut ctx), [0.6, 0.5, 0.5, 0.6]);
}

#[test]
fn layout_bindings_are_the_initial_units_and_binding_points() {
    // GL_ARB_shading_language_420pack: a sampler array's elements start
    // at its binding, an arrayed block's instances at the block's; both
    // stay settable through the API afterwards.
    let fs = "#version 150
#extension GL_ARB_shading_language_420pack : require
layout(binding = 3) uniform sampler2D t[2];
layout(std140, binding = 7) uniform B { vec4 c; } b[2];
uniform sampler2D plain;
out vec4 result;
void main() { result = texture(t[0], vec2(0.0)) + texture(t[1], vec2(0.0)) + texture(plain, vec2(0.0)) + b[0].c + b[1].c; }
";
    let mut ctx = Context::new(8, 8);
    let p = program(&mut ctx, VS, fs);
    let unit = |ctx: &mut Context, name: &str| {
        let loc = ctx.get_uniform_location(p, name);
        ctx.get_uniformiv(p, loc)
    };
    assert_eq!(unit(&mut ctx, "t[0]"), vec![3]);
    assert_eq!(unit(&mut ctx, "t[1]"), vec![4]);
    assert_eq!(unit(&mut ctx, "plain"), vec![0]);
    let binding = |ctx: &mut Context, name: &str| {
        let i = ctx.get_uniform_block_index(p, name);
        ctx.get_active_uniform_blockiv(p, i, GL_UNIFORM_BLOCK_BINDING)
            .unwrap()
    };
    assert_eq!(binding(&mut ctx, "B[0]"), vec![7]);
    assert_eq!(binding(&mut ctx, "B[1]"), vec![8]);
    let second = ctx.get_uniform_block_index(p, "B[1]");
    ctx.uniform_block_binding(p, second, 2);
    assert_eq!(binding(&mut ctx, "B[1]"), vec![2]);
}
