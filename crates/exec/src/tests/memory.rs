//! Storage blocks and shared variables: layouts (std140, std430,
//! row-major), dynamic indices, `.length()` of the last member, atomics
//! in lane order, helper lanes without effects, and compute work groups
//! with their IDs and barriers.

use super::*;
use crate::memory::Words;

fn fs(k: u32) -> u32 {
    buffer_space(Stage::Fragment, k)
}

fn cs(k: u32) -> u32 {
    buffer_space(Stage::Compute, k)
}

/// Textures with no texture and `mem` as the memory.
struct WithWords<'a>(&'a Words);

impl Textures for WithWords<'_> {
    fn sample(&self, req: &SampleRequest, out: &mut [[f32; LANES]; 4]) {
        NoTextures.sample(req, out)
    }

    fn memory(&self) -> Option<&dyn Memory> {
        Some(self.0)
    }
}

const SSBO: &str = "#extension GL_ARB_shader_storage_buffer_object : require\n";
const CS: &str = "#extension GL_ARB_compute_shader : require\n";

fn run_frag(src: &str, words: &Words, active: LaneMask, helper: LaneMask) {
    let k = kernel(Stage::Fragment, src);
    let mut b = frag_batch(&k);
    b.active = active;
    b.helper = helper;
    let u = uniforms(&k, &[]);
    k.run(&mut b, &u, &WithWords(words)).expect("runs");
}

#[test]
fn std430_and_std140_layouts_address_every_component() {
    let src = format!(
        "#version 150\n{SSBO}layout(std430, binding = 0) buffer A {{ float f; vec3 v; float after; mat2 m; int i[2]; }};\n\
         layout(std140, binding = 1) buffer B {{ float g[2]; layout(row_major) mat2x3 r; }};\n\
         out vec4 c;\nvoid main() {{\n  f = 1.0; v = vec3(2.0, 3.0, 4.0); after = 5.0; m = mat2(6.0, 7.0, 8.0, 9.0); i[1] = -1;\n  g[1] = 10.0; r[1] = vec3(11.0, 12.0, 13.0);\n  c = vec4(f + v.z);\n}}\n"
    );
    let words = Words::with(vec![(fs(0), vec![0; 16]), (fs(1), vec![0; 20])]);
    run_frag(&src, &words, 1, 0);
    let a = words.words(fs(0));
    // std430: f@0, v@16, after@28, m@32 (columns 8 apart), i@48 stride 4.
    let f = |x: f32| x.to_bits();
    assert_eq!(a[0], f(1.0));
    assert_eq!(&a[4..8], &[f(2.0), f(3.0), f(4.0), f(5.0)]);
    assert_eq!(&a[8..12], &[f(6.0), f(7.0), f(8.0), f(9.0)]);
    assert_eq!(a[13], -1i32 as u32);
    let b = words.words(fs(1));
    // std140: g[] stride 16 (g[1]@16); r row-major 2 columns x 3 rows:
    // rows of 2 floats 16 apart from 32, column 1 is element 1 of each.
    assert_eq!(b[4], f(10.0));
    assert_eq!([b[9], b[13], b[17]], [f(11.0), f(12.0), f(13.0)]);
}

#[test]
fn dynamic_indices_lengths_and_reads() {
    let src = format!(
        "#version 150\n{SSBO}layout(std430) buffer A {{ uint n; uint data[]; }};\nout vec4 c;\nvoid main() {{\n  int l = int(gl_FragCoord.x);\n  data[l] = data[l] * 2u + uint(data.length());\n  if (l == 0) n = uint(data.length());\n  c = vec4(1.0);\n}}\n"
    );
    let words = Words::with(vec![(fs(0), (0..9).collect())]);
    run_frag(&src, &words, 0xffff, 0);
    // 8 elements after n: lanes 0..8 double theirs and add 8; lanes past
    // the end write nothing.
    let w = words.words(fs(0));
    assert_eq!(w[0], 8);
    assert_eq!(&w[1..], &[10, 12, 14, 16, 18, 20, 22, 24]);
}

#[test]
fn atomics_run_in_lane_order_and_helpers_have_no_effect() {
    let src = format!(
        "#version 150\n{SSBO}layout(std430) buffer A {{ uint counter; uint seen[16]; int low; }};\nout vec4 c;\nvoid main() {{\n  int l = int(gl_FragCoord.x);\n  seen[l] = atomicAdd(counter, 1u) + 100u;\n  atomicMin(low, -l);\n  c = vec4(1.0);\n}}\n"
    );
    let words = Words::with(vec![(fs(0), vec![0; 18])]);
    // Lanes 0..4 active, 4..8 helpers (no effect), the rest inactive.
    run_frag(&src, &words, 0x0f, 0xf0);
    let w = words.words(fs(0));
    assert_eq!(w[0], 4);
    assert_eq!(&w[1..5], &[100, 101, 102, 103]);
    assert_eq!(&w[5..9], &[0, 0, 0, 0]);
    assert_eq!(w[17], -3i32 as u32);
}

fn dispatch(src: &str, groups: [u32; 3], words: &Words) {
    let k = kernel(Stage::Compute, src);
    let u = uniforms(&k, &[]);
    for z in 0..groups[2] {
        for y in 0..groups[1] {
            for x in 0..groups[0] {
                let g = WorkGroup {
                    id: [x, y, z],
                    count: groups,
                };
                run_work_group(&k, g, &u, &WithWords(words)).expect("runs");
            }
        }
    }
}

#[test]
fn compute_invocations_see_their_ids() {
    let src = format!(
        "#version 330\n{CS}{SSBO}layout(local_size_x = 3, local_size_y = 2) in;\nbuffer Out {{ uvec4 v[]; }};\nvoid main() {{\n  uint i = gl_GlobalInvocationID.y * 6u + gl_GlobalInvocationID.x;\n  v[i] = uvec4(gl_LocalInvocationIndex, gl_WorkGroupID.x, gl_NumWorkGroups.x, gl_WorkGroupSize.x);\n}}\n"
    );
    let words = Words::with(vec![(cs(0), vec![0; 4 * 12])]);
    dispatch(&src, [2, 1, 1], &words);
    let w = words.words(cs(0));
    // Invocation (x, y) of group gx: index y * 6 + gx * 3 + x.
    for gx in 0..2u32 {
        for y in 0..2u32 {
            for x in 0..3u32 {
                let i = (y * 6 + gx * 3 + x) as usize;
                assert_eq!(&w[4 * i..4 * i + 4], &[y * 3 + x, gx, 2, 3], "{i}");
            }
        }
    }
}

#[test]
fn barriers_order_a_large_group() {
    // 64 invocations (four batches): each writes its shared slot, waits,
    // then reads its neighbour's; without the barrier batch 0 would read
    // slots batch 1 has not written yet.
    let src = format!(
        "#version 330\n{CS}{SSBO}layout(local_size_x = 64) in;\nshared uint slot[64];\nlayout(std430) buffer Out {{ uint v[64]; uint total; }};\nvoid main() {{\n  uint i = gl_LocalInvocationIndex;\n  slot[i] = i * 10u;\n  barrier();\n  v[i] = slot[(i + 17u) % 64u];\n  atomicAdd(total, 1u);\n}}\n"
    );
    let words = Words::with(vec![(cs(0), vec![0; 65])]);
    dispatch(&src, [1, 1, 1], &words);
    let w = words.words(cs(0));
    for i in 0..64u32 {
        assert_eq!(w[i as usize], ((i + 17) % 64) * 10, "{i}");
    }
    assert_eq!(w[64], 64);
}
