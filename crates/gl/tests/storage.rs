//! Shader storage buffers and compute dispatches (GL_ARB_shader_storage_buffer_object,
//! GL_ARB_compute_shader on 3.3 contexts), end to end: dispatches and
//! their IDs, indirect dispatches, shared variables and barriers, block
//! bindings, storage blocks in a draw (atomics counting fragments, the
//! same on every run), and the errors.

use gl::enums::*;
use gl::{Api, ArrayData, Context};

mod common;
use common::linked_stages;

fn ctx33() -> Context {
    Context::with_api(8, 8, Api::GL33_CORE)
}

/// A storage buffer of `words` at binding `index`.
fn ssbo(ctx: &mut Context, index: u32, words: &[u32]) -> u32 {
    let b = ctx.gen_buffers(1)[0];
    ctx.bind_buffer(GL_SHADER_STORAGE_BUFFER, b);
    let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
    ctx.buffer_data(
        GL_SHADER_STORAGE_BUFFER,
        bytes.len() as isize,
        Some(&bytes),
        GL_DYNAMIC_DRAW,
    );
    ctx.bind_buffer_base(GL_SHADER_STORAGE_BUFFER, index, b);
    b
}

fn words(ctx: &mut Context, b: u32) -> Vec<u32> {
    ctx.bind_buffer(GL_SHADER_STORAGE_BUFFER, b);
    let n = ctx.buffer_info(b).map_or(0, |i| i.0);
    ctx.get_buffer_sub_data(GL_SHADER_STORAGE_BUFFER, 0, n as isize)
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect()
}

const IDS_CS: &str = "#version 330\n#extension GL_ARB_compute_shader : require\n\
    #extension GL_ARB_shader_storage_buffer_object : require\n\
    layout(local_size_x = 2, local_size_y = 2) in;\n\
    layout(std430, binding = 3) buffer Out { uint v[]; };\n\
    void main() {\n\
      uint i = gl_GlobalInvocationID.y * 8u + gl_GlobalInvocationID.x;\n\
      v[i] = gl_WorkGroupID.x * 100u + gl_LocalInvocationIndex;\n\
    }";

#[test]
fn dispatches_write_storage_buffers() {
    let mut ctx = ctx33();
    linked_stages(&mut ctx, &[(GL_COMPUTE_SHADER, IDS_CS)]);
    let b = ssbo(&mut ctx, 3, &[0; 32]);
    ctx.dispatch_compute(4, 2, 1);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.take_draw_error(), None);
    let w = words(&mut ctx, b);
    for y in 0..4u32 {
        for x in 0..8u32 {
            let expected = (x / 2) * 100 + (y % 2) * 2 + x % 2;
            assert_eq!(w[(y * 8 + x) as usize], expected, "({x}, {y})");
        }
    }
    // The counts from a buffer, and glShaderStorageBlockBinding moving
    // the block to another binding point.
    let counts = ctx.gen_buffers(1)[0];
    ctx.bind_buffer(GL_DISPATCH_INDIRECT_BUFFER, counts);
    let c: Vec<u8> = [9u32, 1, 1, 1]
        .iter()
        .flat_map(|w| w.to_le_bytes())
        .collect();
    ctx.buffer_data(GL_DISPATCH_INDIRECT_BUFFER, 16, Some(&c), GL_STATIC_DRAW);
    let other = ssbo(&mut ctx, 5, &[7; 32]);
    let p = ctx.get_integerv(GL_CURRENT_PROGRAM)[0] as u32;
    let index = ctx.storage_block_index(p, "Out");
    assert_eq!(index, 0);
    ctx.shader_storage_block_binding(p, index, 5);
    ctx.dispatch_compute_indirect(4);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // One group (1 x 1 x 1) wrote the first 2 x 2 square.
    let w = words(&mut ctx, other);
    assert_eq!(&w[..3], &[0, 1, 7]);
    assert_eq!(&w[8..11], &[2, 3, 7]);
}

#[test]
fn shared_variables_and_barriers_in_large_groups() {
    let mut ctx = ctx33();
    let cs = "#version 330\n#extension GL_ARB_compute_shader : require\n\
        #extension GL_ARB_shader_storage_buffer_object : require\n\
        layout(local_size_x = 40) in;\n\
        shared uint s[40];\n\
        layout(std430) buffer Out { uint v[]; };\n\
        void main() {\n\
          uint i = gl_LocalInvocationIndex;\n\
          s[i] = i + gl_WorkGroupID.x * 1000u;\n\
          barrier();\n\
          v[gl_GlobalInvocationID.x] = s[39u - i];\n\
        }";
    linked_stages(&mut ctx, &[(GL_COMPUTE_SHADER, cs)]);
    let b = ssbo(&mut ctx, 0, &[0; 80]);
    ctx.dispatch_compute(2, 1, 1);
    assert_eq!(ctx.take_draw_error(), None);
    // Groups on threads of their own have a lower bound per dispatch.
    ctx.dispatch_compute(30000, 1, 1);
    let why = ctx.take_draw_error().unwrap_or_default();
    assert!(why.contains("barrier()"), "{why}");
    let w = words(&mut ctx, b);
    for g in 0..2u32 {
        for i in 0..40u32 {
            assert_eq!(w[(g * 40 + i) as usize], g * 1000 + 39 - i);
        }
    }
}

#[test]
fn fragment_atomics_count_every_fragment_the_same_way_each_run() {
    let vs = "#version 330\nin vec2 pos;\nvoid main() { gl_Position = vec4(pos, 0.0, 1.0); }";
    let fs = "#version 330\n#extension GL_ARB_shader_storage_buffer_object : require\n\
        layout(std430) buffer Count { uint n; uint order[64]; };\n\
        out vec4 c;\n\
        void main() {\n\
          uint k = atomicAdd(n, 1u);\n\
          order[k] = uint(gl_FragCoord.y) * 8u + uint(gl_FragCoord.x);\n\
          c = vec4(1.0);\n\
        }";
    let mut runs = Vec::new();
    for _ in 0..2 {
        let mut ctx = ctx33();
        linked_stages(
            &mut ctx,
            &[(GL_VERTEX_SHADER, vs), (GL_FRAGMENT_SHADER, fs)],
        );
        let b = ssbo(&mut ctx, 0, &[0; 65]);
        let vao = ctx.gen_vertex_arrays(1)[0];
        ctx.bind_vertex_array(vao);
        let vbo = ctx.gen_buffers(1)[0];
        ctx.bind_buffer(GL_ARRAY_BUFFER, vbo);
        let quad: Vec<u8> = [-1.0f32, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0]
            .iter()
            .flat_map(|f| f.to_le_bytes())
            .collect();
        ctx.buffer_data(
            GL_ARRAY_BUFFER,
            quad.len() as isize,
            Some(&quad),
            GL_STATIC_DRAW,
        );
        ctx.vertex_attrib_pointer(0, 2, GL_FLOAT, false, 0, ArrayData::Offset(0));
        ctx.enable_vertex_attrib_array(0);
        ctx.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(ctx.take_draw_error(), None);
        let w = words(&mut ctx, b);
        // Each of the 64 pixels once.
        assert_eq!(w[0], 64);
        let mut seen: Vec<u32> = w[1..].to_vec();
        seen.sort();
        assert_eq!(seen, (0..64).collect::<Vec<u32>>());
        runs.push(w);
    }
    assert_eq!(runs[0], runs[1]);
}

#[test]
fn errors() {
    // No compute program current.
    let mut ctx = ctx33();
    ctx.dispatch_compute(1, 1, 1);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    linked_stages(&mut ctx, &[(GL_COMPUTE_SHADER, IDS_CS)]);
    ctx.dispatch_compute(70000, 1, 1);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    // Legal counts past what shaderbox runs in one call: refused at once.
    ctx.dispatch_compute(65535, 65535, 1);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    let why = ctx.take_draw_error().unwrap_or_default();
    assert!(why.contains("invocations"), "{why}");
    // Indirect: no buffer, then a misaligned offset.
    ctx.dispatch_compute_indirect(0);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.dispatch_compute_indirect(2);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    let p = ctx.get_integerv(GL_CURRENT_PROGRAM)[0] as u32;
    ctx.shader_storage_block_binding(p, 1, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.shader_storage_block_binding(p, 0, 8);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    ctx.bind_buffer_base(GL_SHADER_STORAGE_BUFFER, 8, 0);
    assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    assert_eq!(
        ctx.get_integeri(GL_MAX_COMPUTE_WORK_GROUP_SIZE, 2),
        Some(64)
    );
    assert_eq!(
        ctx.get_integerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS),
        vec![8]
    );
    // A 2.1 context has neither compute shaders nor storage buffers.
    let mut old = Context::new(4, 4);
    assert_eq!(old.create_shader(GL_COMPUTE_SHADER), 0);
    assert_eq!(old.get_error(), GL_INVALID_ENUM);
    old.bind_buffer(GL_SHADER_STORAGE_BUFFER, 1);
    assert_eq!(old.get_error(), GL_INVALID_ENUM);
}
