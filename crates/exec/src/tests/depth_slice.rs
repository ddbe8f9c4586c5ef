//! `Kernel::depth_only`: the slice writes the same `gl_FragDepth` bits and
//! discards the same lanes as the full kernel, with fewer ops.

use super::{kernel, link_one, uniforms, Rng};
use crate::{Batch, ExecError, Kernel, NoTextures, LANES};
use glsl::ir::Stage;

const SPHERE_FRAG: &str = include_str!("../../../../shaders/sphere.frag");

impl Rng {
    /// Uniform in [lo, hi).
    fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * ((self.next() >> 40) as f32 / (1u64 << 24) as f32)
    }
}

/// Runs `k` and its depth slice on `rounds` batches of random inputs in
/// [lo, hi) and compares gl_FragDepth and the discarded lanes; returns how
/// many lanes were discarded (to check the test exercised both outcomes).
fn compare(k: &Kernel, u: &[u32], rounds: usize, lo: f32, hi: f32, seed: u64) -> (usize, usize) {
    let slice = k.depth_only().expect("a depth slice");
    assert!(
        slice.op_count() < k.op_count(),
        "{} ops in the slice, {} in the kernel",
        slice.op_count(),
        k.op_count()
    );
    let depth = k.interface().output("gl_FragDepth").filter(|s| s.written);
    let mut rng = Rng(seed);
    let (mut discarded, mut kept) = (0, 0);
    for round in 0..rounds {
        let active = if round % 3 == 2 {
            (rng.next() as u32) & 0xffff
        } else {
            0xffff
        };
        let mut full = Batch::for_kernel(k, active);
        for c in full.inputs.iter_mut() {
            for x in c.iter_mut() {
                *x = rng.range(lo, hi);
            }
        }
        let mut sliced = full.clone();
        let r1 = k.run(&mut full, u, &NoTextures);
        let r2 = slice.run(&mut sliced, u, &NoTextures);
        assert_eq!(r1, r2, "round {round}: results");
        assert_eq!(full.discarded, sliced.discarded, "round {round}: discarded");
        for l in 0..LANES {
            if active & (1 << l) == 0 || full.discarded & (1 << l) != 0 {
                continue;
            }
            kept += 1;
            if let Some(depth) = depth {
                assert_eq!(
                    full.outputs[depth.offset][l].to_bits(),
                    sliced.outputs[depth.offset][l].to_bits(),
                    "round {round} lane {l}: gl_FragDepth"
                );
            }
        }
        discarded += (full.discarded & active).count_ones() as usize;
    }
    (discarded, kept)
}

fn fbits(v: &[f32]) -> Vec<u32> {
    v.iter().map(|f| f.to_bits()).collect()
}

pub(crate) fn sphere_uniforms(k: &Kernel, perspective: f32) -> Vec<u32> {
    // A projection like the renderer's (ortho or frustum), two lights.
    let proj: [f32; 16] = if perspective > 0.5 {
        [
            2.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, -1.2, -1.0, 0.0, 0.0, -2.2, 0.0,
        ]
    } else {
        [
            0.1, 0.0, 0.0, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0, 0.0, -0.05, 0.0, 0.0, 0.0, -1.0, 1.0,
        ]
    };
    let mut values: Vec<(String, Vec<u32>)> = vec![
        ("perspective".into(), fbits(&[perspective])),
        // gl_FragCoord.xy in [-1, 1) maps to ndc in [-0.1, 0.1).
        ("viewport".into(), fbits(&[-10.0, -10.0, 20.0, 20.0])),
        ("fogging".into(), fbits(&[0.0, 0.0, 1.0, 0.0])),
        (
            "light_enabled".into(),
            fbits(&[1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
        ),
        ("gl_ProjectionMatrix".into(), fbits(&proj)),
        ("gl_DepthRange.near".into(), fbits(&[0.0])),
        ("gl_DepthRange.far".into(), fbits(&[1.0])),
        ("gl_DepthRange.diff".into(), fbits(&[1.0])),
        ("gl_FrontMaterial.shininess".into(), fbits(&[30.0])),
        ("gl_Fog.density".into(), fbits(&[0.05])),
    ];
    for i in 0..2 {
        values.push((
            format!("gl_LightSource[{i}].position"),
            fbits(&[0.3, 0.4 + i as f32, 1.0, 0.0]),
        ));
        values.push((
            format!("gl_LightSource[{i}].halfVector"),
            fbits(&[0.1, 0.2, 1.0, 0.0]),
        ));
    }
    let refs: Vec<(&str, &[u32])> = values
        .iter()
        .filter(|(n, _)| k.interface().locate_uniform(n).is_some())
        .map(|(n, v)| (n.as_str(), v.as_slice()))
        .collect();
    uniforms(k, &refs)
}

#[test]
fn sphere_impostor_slice_matches_the_full_kernel() {
    for inline in [true, false] {
        let stage = link_one(Stage::Fragment, SPHERE_FRAG).expect("sphere.frag compiles");
        let k = if inline {
            Kernel::new(&stage).expect("lowers")
        } else {
            Kernel::with_inline_limit(&stage, 0).expect("lowers")
        };
        for perspective in [0.0, 1.0] {
            let u = sphere_uniforms(&k, perspective);
            let (discarded, kept) = compare(&k, &u, 300, -1.0, 1.0, 7 + perspective as u64);
            assert!(discarded > 100 && kept > 100, "{discarded} / {kept}");
        }
        let slice = k.depth_only().unwrap();
        // The lighting loop's pow/normalize work is gone.
        assert!(
            slice.op_count() * 2 < k.op_count(),
            "inline {inline}: {} of {} ops",
            slice.op_count(),
            k.op_count()
        );
    }
}

#[test]
fn loops_branches_and_discard_in_loops() {
    let shaders = [
        // Depth from a loop with a data-dependent break, colour from a
        // second loop.
        "varying vec4 v;
        void main() {
            float z = 0.0;
            for (int i = 0; i < 20; i++) {
                z += v.x * 0.1;
                if (z > v.y) break;
            }
            vec4 c = vec4(0.0);
            for (int i = 0; i < 10; i++) c += sin(v * float(i)) * cos(v.yzwx);
            gl_FragColor = c;
            gl_FragDepth = clamp(z, 0.0, 1.0);
        }",
        // Discard inside a loop, a variable carried across iterations that
        // feeds depth through a temporary reused by the colour code.
        "varying vec4 v;
        void main() {
            float acc = v.z;
            vec3 col = vec3(0.0);
            for (int i = 0; i < 8; i++) {
                acc = acc * 0.9 + v.w;
                col += normalize(v.xyz + vec3(float(i))) * pow(abs(acc), 2.5);
                if (acc > 1.5) discard;
                if (acc < -1.0) continue;
                col = mix(col, vec3(acc), 0.25);
            }
            gl_FragColor = vec4(col, 1.0);
            gl_FragDepth = acc * 0.25 + 0.5;
        }",
        // Depth written in one branch only, through a function with an
        // early return and an out parameter; a colour-only function.
        "varying vec4 v;
        float shade(vec3 n) { return pow(max(dot(n, vec3(0.6, 0.8, 0.0)), 0.0), 8.0); }
        void depth(in float a, out float z) {
            z = 0.5;
            if (a < 0.0) return;
            z = sqrt(a);
        }
        void main() {
            float z;
            depth(v.x, z);
            if (v.y > 0.25) {
                gl_FragDepth = z;
            } else {
                if (v.z > 0.5) discard;
                gl_FragDepth = 1.0 - z;
            }
            vec3 n = normalize(v.xyz);
            gl_FragColor = vec4(shade(n), shade(-n), shade(n.yzx), exp(v.w));
        }",
        // Branches that only choose colours (dropped from the slice, with
        // their conditions) beside one whose discard and depth stay.
        "varying vec4 v;
        void main() {
            vec4 c = vec4(0.0);
            if (v.x > 0.5) { c.r = 1.0; if (v.y > 0.2) c.g = v.z; else c.b = v.w; }
            else { c = v; }
            float z = v.z * 0.5 + 0.5;
            if (v.w > 1.2) { if (v.y < 0.0) discard; z = 0.25; }
            if (v.y > 1.0) c *= 2.0;
            gl_FragColor = c;
            gl_FragDepth = z;
        }",
        // A dynamically indexed array (gather/scatter) feeding depth.
        "#version 120
        varying vec4 v;
        void main() {
            float a[4] = float[](0.1, 0.2, 0.3, 0.4);
            int i = int(abs(v.x) * 4.0);
            a[i] = v.y;
            float z = a[int(abs(v.z) * 4.0)];
            vec4 c = vec4(0.0);
            for (int j = 0; j < 6; j++) c += vec4(log2(abs(v.w) + float(j)));
            gl_FragColor = c;
            gl_FragDepth = z;
        }",
    ];
    let saves = |k: &Kernel| {
        k.program
            .ops
            .iter()
            .filter(|op| matches!(op, crate::program::Op::SaveMask { .. }))
            .count()
    };
    for (n, src) in shaders.iter().enumerate() {
        let stage = link_one(Stage::Fragment, src).unwrap_or_else(|e| panic!("{n}: {e}"));
        if src.contains("c *= 2.0") {
            let k = Kernel::new(&stage).expect("lowers");
            let slice = k.depth_only().expect("a slice");
            // main's region and the discarding branch's two are left.
            assert_eq!(saves(&slice), 3, "{} of {}", saves(&slice), saves(&k));
        }
        for limit in [crate::limits::INLINE_LIMIT, 0] {
            let k = Kernel::with_inline_limit(&stage, limit).expect("lowers");
            let u = vec![0u32; k.interface().uniform_words];
            let (discarded, kept) = compare(&k, &u, 200, -1.0, 2.0, 11 + n as u64);
            assert!(kept > 0, "shader {n}: no lane kept");
            if src.contains("discard") {
                assert!(discarded > 0, "shader {n}: no lane discarded");
            }
        }
    }
}

#[test]
fn slice_fails_the_loop_budget_as_the_kernel_does() {
    let mut k = kernel(
        Stage::Fragment,
        "varying vec4 v;
        void main() {
            float z = 0.0;
            for (int i = 0; i < 1000; i++) z += v.x;
            gl_FragColor = vec4(sin(v.x), cos(v.y), exp(v.z), log(abs(v.w)));
            gl_FragColor += vec4(sin(v.y), cos(v.z), exp(v.w), log(abs(v.x)));
            gl_FragDepth = z;
        }",
    );
    k.set_loop_budget(100);
    let slice = k.depth_only().expect("a slice");
    let mut b = Batch::for_kernel(&k, 0xffff);
    let e = slice.run(&mut b, &[], &NoTextures);
    assert!(matches!(e, Err(ExecError::LoopBudget { .. })), "{e:?}");
}

#[test]
fn no_slice_without_depth_or_when_nothing_is_saved() {
    let no_depth = kernel(
        Stage::Fragment,
        "varying vec4 v; void main() { if (v.x < 0.0) discard; gl_FragColor = v; }",
    );
    assert!(no_depth.depth_only().is_none());
    let all_depth = kernel(
        Stage::Fragment,
        "varying vec4 v;
        void main() {
            float z = sin(v.x) * cos(v.y) + exp(v.z) * log(abs(v.w)) - sqrt(abs(v.x * v.y));
            z = z * z - 0.5 * z + inversesqrt(abs(v.w) + 1.0);
            gl_FragDepth = z;
            gl_FragColor = vec4(z);
        }",
    );
    assert!(all_depth.depth_only().is_none());
    let vertex = kernel(Stage::Vertex, "void main() { gl_Position = gl_Vertex; }");
    assert!(vertex.depth_only().is_none());
}

/// Without gl_FragDepth, a costly kernel's slice keeps its discards and
/// nothing of its colours; a cheap kernel gets none.
#[test]
fn slices_without_frag_depth_only_for_costly_kernels() {
    let costly = "varying vec4 v;
        void main() {
            if (v.w > 1.5) discard;
            vec4 c = v;
            for (int i = 0; i < 24; i++) c = c * 0.75 + sin(c.yzwx) * 0.5 + vec4(float(i));
            gl_FragColor = c;
        }";
    let k = kernel(Stage::Fragment, costly);
    assert!(
        k.code.ins.len() >= crate::DEFER_MIN_OPS,
        "{} ops",
        k.code.ins.len()
    );
    let u = vec![0u32; k.interface().uniform_words];
    let (discarded, kept) = compare(&k, &u, 100, -1.0, 2.0, 5);
    assert!(discarded > 0 && kept > 0, "{discarded} / {kept}");
    let slice = k.depth_only().expect("a slice");
    assert!(slice.op_count() < 16, "{} ops", slice.op_count());
    // Without discards the slice is empty: it decides nothing.
    let lit = kernel(
        Stage::Fragment,
        &costly.replace("if (v.w > 1.5) discard;", ""),
    );
    let empty = lit.depth_only().expect("a slice");
    assert_eq!(empty.op_count(), 0);
    for native in [false, true] {
        if native {
            empty.compile_native();
        }
        let mut b = Batch::for_kernel(&empty, 0xffff);
        empty.run(&mut b, &u, &NoTextures).expect("runs");
        assert_eq!(b.discarded, 0);
    }
    let cheap = kernel(
        Stage::Fragment,
        "varying vec4 v; void main() { if (v.w > 1.5) discard; gl_FragColor = v * 2.0; }",
    );
    assert!(cheap.depth_only().is_none(), "{} ops", cheap.code.ins.len());
}
