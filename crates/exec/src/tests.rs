//! Unit tests: small GLSL programs compiled with `glsl::compile`, linked,
//! lowered and run; built-ins checked against constant folding.

#![allow(clippy::needless_range_loop)]

use super::*;
use glsl::ir::{ConstScalar, ConstValue, Stage};
use glsl::types::{Scalar, Type};
use glsl::{compile, CompileOptions};

mod builtins;
mod depth_slice;
mod geometry;
mod integers;
#[cfg(feature = "jit")]
mod jit;
mod memory;
mod packing;
mod piglit;
mod texel_fetch;
mod variants;

/// A small deterministic generator (xorshift) for the randomized tests;
/// each test module adds the draws it needs.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
}

pub(crate) fn link_one(stage: Stage, src: &str) -> Result<glsl::link::LinkedStage, String> {
    let sh = compile(&[src], &CompileOptions::new(stage));
    if !sh.ok() {
        return Err(sh.info_log());
    }
    let prog = glsl::link::link(&[&sh]);
    if !prog.ok() {
        return Err(prog.info_log().to_string());
    }
    prog.stage(stage)
        .cloned()
        .ok_or_else(|| "no stage".to_string())
}

pub(crate) fn kernel(stage: Stage, src: &str) -> Kernel {
    let s = link_one(stage, src).unwrap_or_else(|e| panic!("compile failed: {e}\n{src}"));
    Kernel::new(&s).unwrap_or_else(|e| panic!("lowering failed: {e}\n{src}"))
}

/// Uniform words with the named uniforms set.
pub(crate) fn uniforms(k: &Kernel, values: &[(&str, &[u32])]) -> Vec<u32> {
    let mut words = vec![0u32; k.interface().uniform_words];
    for (name, v) in values {
        let (off, _) = k
            .interface()
            .locate_uniform(name)
            .unwrap_or_else(|| panic!("no uniform {name}"));
        words[off..off + v.len()].copy_from_slice(v);
    }
    words
}

fn fbits(v: &[f32]) -> Vec<u32> {
    v.iter().map(|f| f.to_bits()).collect()
}

/// A fragment batch whose gl_FragCoord is (lane, 0) + 0.5.
fn frag_batch(k: &Kernel) -> Batch {
    let mut b = Batch::for_kernel(k, FULL_MASK);
    if let Some(s) = k.interface().input("gl_FragCoord") {
        for l in 0..LANES {
            b.inputs[s.offset][l] = l as f32 + 0.5;
            b.inputs[s.offset + 1][l] = 0.5;
            b.inputs[s.offset + 3][l] = 1.0;
        }
    }
    b
}

pub(crate) fn bits_of(v: &[[f32; LANES]]) -> Vec<[u32; LANES]> {
    v.iter().map(|c| c.map(f32::to_bits)).collect()
}

const FULL_MASK: LaneMask = crate::interp::FULL;

/// Output `name` per component per lane.
fn output(k: &Kernel, b: &Batch, name: &str) -> Vec<[f32; LANES]> {
    let s = k.interface().output(name).expect("output");
    b.outputs[s.offset..s.offset + s.components].to_vec()
}

/// Runs a fragment shader over lanes with gl_FragCoord.x = lane + 0.5 and
/// returns gl_FragColor per lane.
fn frag_colors(src: &str, unis: &[(&str, &[u32])]) -> (Vec<[f32; 4]>, LaneMask) {
    let k = kernel(Stage::Fragment, src);
    let u = uniforms(&k, unis);
    let mut b = frag_batch(&k);
    let mut reference = b.clone();
    k.run(&mut b, &u, &NoTextures).expect("runs");
    let c = output(&k, &b, "gl_FragColor");
    // The reference interpreter computes the same bits.
    k.run_reference(&mut reference, &u, &NoTextures)
        .expect("runs");
    assert_eq!(reference.discarded, b.discarded, "reference: discarded");
    assert_eq!(
        bits_of(&reference.outputs),
        bits_of(&b.outputs),
        "reference: outputs"
    );
    // So does native code.
    if Variant::Jit.supported() {
        let mut nb = frag_batch(&k);
        k.run_variant(Variant::Jit, &mut nb, &u, &NoTextures)
            .expect("runs");
        assert_eq!(nb.discarded, b.discarded, "native: discarded");
        assert_eq!(bits_of(&nb.outputs), bits_of(&b.outputs), "native: outputs");
    }
    // The same program with every function as a subroutine agrees.
    let stage = link_one(Stage::Fragment, src).unwrap();
    let sk = Kernel::with_inline_limit(&stage, 0).expect("lowers");
    let mut sb = frag_batch(&sk);
    sk.run(&mut sb, &u, &NoTextures).expect("runs");
    assert_eq!(sb.discarded, b.discarded, "subroutine mode: discarded");
    assert_eq!(
        output(&sk, &sb, "gl_FragColor"),
        c,
        "subroutine mode: gl_FragColor"
    );
    (
        (0..LANES)
            .map(|l| [c[0][l], c[1][l], c[2][l], c[3][l]])
            .collect(),
        b.discarded,
    )
}

/// A chain of `n` functions, each adding one to its callee's result,
/// called from `main`: `n + 1` frames deep.
fn call_chain(n: usize) -> String {
    let mut src = String::from("float f0(float x) { return x + 1.0; }\n");
    for i in 1..n {
        src.push_str(&format!(
            "float f{i}(float x) {{ return f{}(x) + 1.0; }}\n",
            i - 1
        ));
    }
    src.push_str(&format!(
        "void main() {{ gl_FragColor = vec4(f{}(0.0) / 4096.0); }}\n",
        n - 1
    ));
    src
}

#[test]
fn call_chains_as_deep_as_the_front_end_allows_inline_and_run() {
    // The deepest chain that compiles: every call inlined (no subroutine,
    // so native code can run it), and the subroutine form agrees.
    let n = crate::limits::MAX_CALL_DEPTH - 1;
    let src = call_chain(n);
    let k = kernel(Stage::Fragment, &src);
    assert_eq!(k.program.subroutines, 0, "the chain is inlined");
    let mut b = frag_batch(&k);
    k.run(&mut b, &[], &NoTextures).expect("runs");
    let c = output(&k, &b, "gl_FragColor");
    assert_eq!(c[0][0], n as f32 / 4096.0);
    let sk = Kernel::with_inline_limit(&link_one(Stage::Fragment, &src).unwrap(), 0)
        .expect("lowers as subroutines");
    assert_eq!(sk.program.subroutines as usize, n);
    let mut sb = frag_batch(&sk);
    sk.run(&mut sb, &[], &NoTextures).expect("runs");
    assert_eq!(output(&sk, &sb, "gl_FragColor")[0][0], n as f32 / 4096.0);
    // One more function is refused by the front end, with the limit named
    // (it used to run as 3,000 subroutines, seconds per draw).
    let e = link_one(Stage::Fragment, &call_chain(n + 1)).unwrap_err();
    assert!(e.contains("function calls nested too deeply"), "{e}");
}

/// The deepest call chain and nearly the deepest expression the front end
/// accepts lower on a thread with a small stack: the lowering continues on
/// fresh stack segments (`lower::with_stack`) instead of needing a large
/// stack of its own.
#[test]
fn deep_programs_lower_on_a_small_stack() {
    let chain = call_chain(crate::limits::MAX_CALL_DEPTH - 1);
    let depth = 120;
    let nested = format!(
        "void main() {{ float x = 1.0; gl_FragColor = vec4({}x{}); }}\n",
        "0.5 * (1.0 + ".repeat(depth),
        ")".repeat(depth)
    );
    let stages: Vec<_> = [chain, nested]
        .iter()
        .map(|src| link_one(Stage::Fragment, src).expect("links"))
        .collect();
    let lowered = std::thread::Builder::new()
        .stack_size(256 << 10)
        .spawn(move || {
            stages
                .iter()
                .map(|st| Kernel::new(st).is_ok())
                .collect::<Vec<_>>()
        })
        .expect("thread")
        .join()
        .expect("no stack overflow");
    assert_eq!(lowered, [true, true]);
}

#[test]
fn many_subroutines_lower_and_run() {
    // 3,000 functions as subroutines, each called once: liveness over
    // their returns must not sweep every block once per call.
    let n = 3000;
    let mut src = String::new();
    for i in 0..n {
        src.push_str(&format!("float f{i}(float x) {{ return x + 1.0; }}\n"));
    }
    src.push_str("void main() { float x = 0.0;\n");
    for i in 0..n {
        src.push_str(&format!("x = f{i}(x);\n"));
    }
    src.push_str("gl_FragColor = vec4(x / 4096.0); }\n");
    let k = Kernel::with_inline_limit(&link_one(Stage::Fragment, &src).unwrap(), 0)
        .expect("lowers as subroutines");
    let mut b = frag_batch(&k);
    k.run(&mut b, &[], &NoTextures).expect("runs");
    assert_eq!(output(&k, &b, "gl_FragColor")[0][0], n as f32 / 4096.0);
}

#[test]
fn divergent_if_else() {
    let (c, _) = frag_colors(
        "void main() {
            float x = gl_FragCoord.x;
            vec4 c = vec4(0.0);
            if (x < 4.0) { c.r = 1.0; } else if (x < 8.0) { c.g = 1.0; } else { c.b = x; }
            if (mod(x - 0.5, 2.0) == 0.0) c.a = 1.0; else c.a = 0.5;
            gl_FragColor = c;
        }",
        &[],
    );
    for (l, c) in c.iter().enumerate() {
        let x = l as f32 + 0.5;
        let want = if x < 4.0 {
            [1.0, 0.0, 0.0]
        } else if x < 8.0 {
            [0.0, 1.0, 0.0]
        } else {
            [0.0, 0.0, x]
        };
        assert_eq!(&c[..3], &want, "lane {l}");
        assert_eq!(c[3], if l % 2 == 0 { 1.0 } else { 0.5 }, "lane {l}");
    }
}

#[test]
fn loops_with_break_and_continue() {
    let (c, _) = frag_colors(
        "void main() {
            int n = int(gl_FragCoord.x);
            float sum = 0.0; float odd = 0.0; int i;
            for (i = 0; i < 100; i++) {
                if (i >= n) break;
                sum += 1.0;
                if (i - (i / 2) * 2 == 0) continue;
                odd += 1.0;
            }
            int j = 0;
            do { j++; } while (j < n);
            float w = 0.0;
            while (true) { w += 2.0; if (w > float(n)) break; }
            gl_FragColor = vec4(sum, odd, float(j), w);
        }",
        &[],
    );
    for (l, c) in c.iter().enumerate() {
        let n = l as f32;
        let j = (l as f32).max(1.0);
        let w = ((l / 2) * 2 + 2) as f32;
        assert_eq!(*c, [n, (l / 2) as f32, j, w], "lane {l}");
    }
}

/// Counted loops are unrolled and constant int arguments bound, so
/// indexing by the counter or the parameter is static; loops that write
/// their counter, leave early or run too long stay loops. Either way the
/// values are the loop's.
#[test]
fn counted_loops_unroll_with_static_indexing() {
    let src = "uniform float w[4];
        uniform vec4 v[3];
        float pick(in int k, float x) { return w[k] * x + v[k].y; }
        void main() {
            float x = gl_FragCoord.x;
            float a = 0.0;
            for (int i = 0; i < 4; i++) a += pick(i > 2 ? 2 : i, x) + float(i);
            float b = 0.0;
            for (int i = 3; i >= 0; i -= 2) { if (x > w[i] * 8.0) b += w[i]; }
            float c = 0.0;
            for (int i = 0; i < 4; i++) { c += 1.0; if (float(i) > x) break; }
            float d = 0.0;
            for (int i = 0; i < 6; i++) { d += float(i); i++; }
            gl_FragColor = vec4(a, b, c, d);
        }";
    let w = [0.25f32, 0.5, 1.0, 1.5];
    let v: Vec<f32> = (0..12).map(|i| i as f32 * 0.125).collect();
    let (colors, _) = frag_colors(src, &[("w", &fbits(&w)), ("v", &fbits(&v))]);
    for (l, c) in colors.iter().enumerate() {
        let x = l as f32 + 0.5;
        let mut a = 0.0f32;
        for i in 0..4usize {
            let k = if i > 2 { 2 } else { i };
            a += (w[k] * x + v[4 * k + 1]) + i as f32;
        }
        let b = [3usize, 1]
            .iter()
            .filter(|&&i| x > w[i] * 8.0)
            .fold(0.0f32, |b, &i| b + w[i]);
        let c2 = (0..4)
            .position(|i| i as f32 > x)
            .map_or(4.0, |p| p as f32 + 1.0);
        assert_eq!(*c, [a, b, c2, 0.0 + 2.0 + 4.0], "lane {l}");
    }
    // The first two loops left no loop behind; the other two did.
    let k = kernel(Stage::Fragment, src);
    let iters = k
        .program
        .ops
        .iter()
        .filter(|op| matches!(op, program::Op::LoopIter))
        .count();
    assert_eq!(iters, 2, "loops left: {iters}");
}

/// Prepared runs (the pool read in place by native code) of a kernel
/// whose unrolled loop branches on pool values and calls `pow` on them
/// compute the reference interpreter's bits.
#[test]
fn prepared_runs_branching_on_uniforms() {
    let src = "uniform float on[4];
        uniform float e[4];
        void main() {
            float x = gl_FragCoord.x * 0.0625;
            vec4 c = vec4(0.0);
            for (int i = 0; i < 4; i++) {
                if (on[i] > 0.5) c[i] = pow(x, e[i]) + on[i];
            }
            gl_FragColor = c;
        }";
    let k = kernel(Stage::Fragment, src);
    let u = uniforms(
        &k,
        &[
            ("on", &fbits(&[1.0, 0.0, 1.0, 0.0])),
            ("e", &fbits(&[2.0, 3.0, 0.5, 7.0])),
        ],
    );
    let mut want = frag_batch(&k);
    k.run_reference(&mut want, &u, &NoTextures).expect("runs");
    k.compile_native();
    let prepared = k.prepare(&u, &NoTextures);
    for round in 0..3 {
        let mut got = frag_batch(&k);
        k.run_prepared(&mut got, &prepared, &NoTextures)
            .expect("runs");
        assert_eq!(
            bits_of(&got.outputs),
            bits_of(&want.outputs),
            "round {round}"
        );
    }
}

#[test]
fn early_return_and_out_params() {
    let (c, _) = frag_colors(
        "float f(float x, out float y, inout float z) {
            y = 2.0 * x;
            if (x < 5.0) { z += 1.0; return -x; }
            z *= 10.0;
            return x;
        }
        void g(inout vec2 v, int i) { v[i] = 7.0; }
        void main() {
            float y, z = 1.0;
            float r = f(gl_FragCoord.x, y, z);
            vec2 v = vec2(0.0);
            g(v, int(gl_FragCoord.x) - (int(gl_FragCoord.x) / 2) * 2);
            gl_FragColor = vec4(r, y, z, v.x - v.y);
        }",
        &[],
    );
    for (l, c) in c.iter().enumerate() {
        let x = l as f32 + 0.5;
        let (r, z) = if x < 5.0 { (-x, 2.0) } else { (x, 10.0) };
        let v = if l % 2 == 0 { 7.0 } else { -7.0 };
        assert_eq!(*c, [r, 2.0 * x, z, v], "lane {l}");
    }
}

#[test]
fn discard_stops_the_lane() {
    let (c, discarded) = frag_colors(
        "void main() {
            gl_FragColor = vec4(1.0);
            if (gl_FragCoord.x > 10.0) discard;
            gl_FragColor = vec4(0.5);
        }",
        &[],
    );
    assert_eq!(discarded, 0xffff & !0x3ff);
    for (l, c) in c.iter().enumerate().take(10) {
        assert_eq!(c[0], 0.5, "lane {l}");
    }
}

#[test]
fn discard_in_a_function_inside_a_loop() {
    // Lanes whose x + i passes `limit` for some i are discarded.
    let run = |limit: &str| {
        frag_colors(
            &format!(
                "float k;
                void kill(float x) {{ if (x > {limit}) discard; k += 1.0; }}
                void main() {{
                    k = 0.0;
                    for (int i = 0; i < 4; i++) kill(gl_FragCoord.x + float(i));
                    gl_FragColor = vec4(k);
                }}"
            ),
            &[],
        )
    };
    // Lane 0 (x=0.5): i=0..3 → 0.5..3.5: killed at i=3. Only lanes with
    // x + 3 <= 3 survive: none.
    let (_, discarded) = run("3.0");
    assert_eq!(discarded, 0xffff);
    let (c, discarded) = run("5.0");
    // x + 3 <= 5 → x <= 2: lanes 0, 1 survive.
    assert_eq!(discarded, 0xffff & !0b11);
    assert_eq!(c[0][0], 4.0);
    assert_eq!(c[1][0], 4.0);
}

#[test]
fn lazy_logic_and_ternary_side_effects() {
    let (c, _) = frag_colors(
        "float n;
        bool bump() { n += 1.0; return true; }
        void main() {
            n = 0.0;
            bool big = gl_FragCoord.x > 8.0;
            bool a = big && bump();
            bool b = big || bump();
            float t = big ? (n += 10.0) : (n -= 100.0);
            gl_FragColor = vec4(n, float(a), float(b), t);
        }",
        &[],
    );
    for (l, c) in c.iter().enumerate() {
        let big = l as f32 + 0.5 > 8.0;
        let n = if big { 1.0 + 10.0 } else { 1.0 - 100.0 };
        assert_eq!(*c, [n, big as u8 as f32, 1.0, n], "lane {l}");
    }
}

#[test]
fn dynamic_indexing_clamps() {
    let (c, _) = frag_colors(
        "#version 120
        uniform float a[4];
        void main() {
            int i = int(gl_FragCoord.x) - 2;
            float b[4];
            for (int k = 0; k < 4; k++) b[k] = a[k] * 2.0;
            b[i] = -1.0;
            vec4 v = vec4(10.0, 20.0, 30.0, 40.0);
            mat3 m = mat3(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0);
            gl_FragColor = vec4(a[i], b[0] + b[3], v[i], m[i][i]);
        }",
        &[("a", &fbits(&[1.0, 2.0, 3.0, 4.0]))],
    );
    for (l, c) in c.iter().enumerate() {
        let i = (l as i32 - 2).clamp(0, 3) as usize;
        let a = [1.0, 2.0, 3.0, 4.0][i];
        let mut b = [2.0, 4.0, 6.0, 8.0];
        b[i] = -1.0;
        let v = [10.0, 20.0, 30.0, 40.0][i];
        let m = [1.0, 5.0, 9.0][i.min(2)];
        assert_eq!(*c, [a, b[0] + b[3], v, m], "lane {l}");
    }
}

#[test]
fn structs_arrays_and_equality() {
    let (c, _) = frag_colors(
        "#version 120
        struct S { vec2 p; float w[2]; };
        void main() {
            S s = S(vec2(1.0, 2.0), float[2](3.0, 4.0));
            S t = s;
            t.w[int(gl_FragCoord.x) - 7] = 9.0;
            float a[2] = float[2](1.0, 2.0);
            float b[2] = a;
            gl_FragColor = vec4(float(s == t), float(a == b), t.w[0], t.w[1]);
        }",
        &[],
    );
    for (l, c) in c.iter().enumerate() {
        let i = (l as i32 - 7).clamp(0, 1) as usize;
        let mut w = [3.0, 4.0];
        w[i] = 9.0;
        assert_eq!(*c, [0.0, 1.0, w[0], w[1]], "lane {l}");
    }
}

/// GL_ARB_arrays_of_arrays: a uniform `float[2][3]` laid out row after
/// row (inner dimension fastest), dynamic indices on each level (clamped
/// per level), whole rows copied, passed, returned and compared, and
/// constructors of rows.
#[test]
fn arrays_of_arrays_index_every_level() {
    let (c, _) = frag_colors(
        "#version 120
        #extension GL_ARB_arrays_of_arrays : enable
        uniform float u[2][3];
        float pick(float a[2][3], int i, int j) { return a[i][j]; }
        float[3] row(float a[2][3], int i) { return a[i]; }
        void main() {
            int l = int(gl_FragCoord.x);
            int i = l / 3 - 1;
            int j = l - 4;
            float a[2][3] = float[2][3](float[3](1.0, 2.0, 3.0), float[3](4.0, 5.0, 6.0));
            float b[3][2][3];
            b[2] = a;
            b[2][i][j] = 10.0 * float(l);
            float r[3] = row(u, i);
            gl_FragColor = vec4(u[i][j] + r[2], pick(b[2], 1, 2), float(b[2] == a), b[2][1][j]);
        }",
        &[("u", &fbits(&[0.5, 1.5, 2.5, 3.5, 4.5, 5.5]))],
    );
    for (l, c) in c.iter().enumerate() {
        let i = (l as i32 / 3 - 1).clamp(0, 1) as usize;
        let j = (l as i32 - 4).clamp(0, 2) as usize;
        let u = [[0.5, 1.5, 2.5], [3.5, 4.5, 5.5]];
        let mut b = [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]];
        b[i][j] = 10.0 * l as f32;
        let same = b == [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]];
        assert_eq!(
            *c,
            [
                u[i][j] + u[i][2],
                b[1][2],
                f32::from(u8::from(same)),
                b[1][j]
            ],
            "lane {l}"
        );
    }
}

#[test]
fn swizzle_assignment_and_incdec() {
    let (c, _) = frag_colors(
        "void main() {
            vec4 v = vec4(1.0, 2.0, 3.0, 4.0);
            v.wx = v.xw;
            v.yz += vec2(0.5);
            int i = 3;
            int j = i++ + ++i;
            float f = 1.0;
            f--;
            gl_FragColor = vec4(v.x + v.w * 10.0, v.y + v.z, float(j), f);
        }",
        &[],
    );
    assert_eq!(c[0], [4.0 + 10.0, 2.5 + 3.5, 8.0, 0.0]);
}

/// Builds `l op r` over constants and folds it (the oracle for matrix
/// products).
fn fold_matmul(l: &ConstValue, r: &ConstValue, ty: Type) -> Vec<f32> {
    use glsl::ir::{BinaryOp, Expr, ExprKind};
    let c = |v: &ConstValue| Expr {
        kind: ExprKind::Const(v.clone()),
        ty: v.ty,
        span: Span::default(),
    };
    let e = Expr {
        kind: ExprKind::Binary {
            op: BinaryOp::MatMul,
            left: Box::new(c(l)),
            right: Box::new(c(r)),
        },
        ty,
        span: Span::default(),
    };
    glsl::consteval::fold(&e, &[])
        .expect("folds")
        .components
        .iter()
        .map(|c| match c {
            ConstScalar::Float(f) => *f,
            _ => f32::NAN,
        })
        .collect()
}

fn type_name(ty: Type) -> String {
    ty.display(&|_| String::new()).to_string()
}

#[test]
fn matrices_of_every_shape() {
    let mut seed = 1u32;
    let mut next = || {
        seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12345);
        ((seed >> 8) % 2000) as f32 / 97.0 - 10.0
    };
    for c1 in 2..=4u8 {
        for r1 in 2..=4u8 {
            let a_ty = Type::mat(c1, r1);
            // matrix × vector, vector × matrix, matrix × matrix.
            let cases: Vec<(Type, Type)> = vec![
                (a_ty, Type::vec(Scalar::Float, c1)),
                (Type::vec(Scalar::Float, r1), a_ty),
                (a_ty, Type::mat(2, c1)),
                (a_ty, Type::mat(3, c1)),
                (a_ty, Type::mat(4, c1)),
            ];
            for (lt, rt) in cases {
                let lv = ConstValue {
                    ty: lt,
                    components: (0..lt.component_count().unwrap())
                        .map(|_| ConstScalar::Float(next()))
                        .collect(),
                };
                let rv = ConstValue {
                    ty: rt,
                    components: (0..rt.component_count().unwrap())
                        .map(|_| ConstScalar::Float(next()))
                        .collect(),
                };
                let (lc, lr) = match lt.base {
                    glsl::types::Base::Matrix { cols, rows } => (cols, rows),
                    _ => (lt.vector_size().unwrap(), 1),
                };
                let rc = match rt.base {
                    glsl::types::Base::Matrix { cols, .. } => cols,
                    _ => 1,
                };
                let _ = lc;
                let res_ty = if rc == 1 {
                    Type::vec(Scalar::Float, lr)
                } else if lr == 1 {
                    Type::vec(Scalar::Float, rc)
                } else {
                    Type::mat(rc, lr)
                };
                let want = fold_matmul(&lv, &rv, res_ty);
                let src = format!(
                    "#version 120
                    uniform {} l; uniform {} r;
                    varying {} o;
                    void main() {{ o = l * r; gl_Position = vec4(0.0); }}",
                    type_name(lt),
                    type_name(rt),
                    type_name(res_ty)
                );
                let k = kernel(Stage::Vertex, &src);
                let bits = |v: &ConstValue| -> Vec<u32> {
                    v.components
                        .iter()
                        .map(|c| match c {
                            ConstScalar::Float(f) => f.to_bits(),
                            _ => 0,
                        })
                        .collect()
                };
                let u = uniforms(&k, &[("l", &bits(&lv)), ("r", &bits(&rv))]);
                let mut b = Batch::for_kernel(&k, 0b1010);
                k.run(&mut b, &u, &NoTextures).unwrap();
                let o = output(&k, &b, "o");
                let got: Vec<f32> = o.iter().map(|c| c[3]).collect();
                assert_eq!(
                    fbits(&got),
                    fbits(&want),
                    "{} * {}",
                    type_name(lt),
                    type_name(rt)
                );
            }
        }
    }
}

#[test]
fn constructors() {
    let (c, _) = frag_colors(
        "#version 120
        void main() {
            mat2 m = mat2(2.0);
            mat3 n = mat3(mat2(1.0, 2.0, 3.0, 4.0));
            mat2x3 p = mat2x3(vec3(1.0), 2.0, 3.0, 4.0);
            ivec2 iv = ivec2(vec2(-1.7, 2.9));
            bvec2 bv = bvec2(0.0, 3.0);
            vec4 v = vec4(iv, bv);
            gl_FragColor = vec4(m[1][1] + m[0][1], n[2][2] + n[0][1], p[1][2], v.x + v.y * 10.0 + v.w * 100.0);
        }",
        &[],
    );
    assert_eq!(c[0], [2.0, 1.0 + 2.0, 4.0, -1.0 + 20.0 + 100.0]);
}

#[test]
fn ftransform_alone() {
    let k = kernel(Stage::Vertex, "void main() { gl_Position = ftransform(); }");
    let i = k.interface();
    assert!(i.uniform("gl_ModelViewProjectionMatrix").is_some());
    assert!(i.input("gl_Vertex").is_some());
}

#[test]
fn ftransform_matches_the_product() {
    let k = kernel(
        Stage::Vertex,
        "varying vec4 a; void main() { gl_Position = ftransform(); a = gl_ModelViewProjectionMatrix * gl_Vertex; }",
    );
    let m: Vec<f32> = (0..16).map(|i| i as f32 * 0.37 - 2.0).collect();
    let u = uniforms(&k, &[("gl_ModelViewProjectionMatrix", &fbits(&m))]);
    let mut b = Batch::for_kernel(&k, 0xffff);
    let vin = k.interface().input("gl_Vertex").unwrap().offset;
    for l in 0..LANES {
        for c in 0..4 {
            b.inputs[vin + c][l] = (l * 4 + c) as f32 * 0.13 - 1.0;
        }
    }
    k.run(&mut b, &u, &NoTextures).unwrap();
    assert_eq!(output(&k, &b, "gl_Position"), output(&k, &b, "a"));
    assert_ne!(output(&k, &b, "a")[0][0], 0.0);
}

#[test]
fn derivatives_from_quads() {
    let k = kernel(
        Stage::Fragment,
        "void main() { float v = gl_FragCoord.x * gl_FragCoord.x + 3.0 * gl_FragCoord.y;
          gl_FragColor = vec4(dFdx(v), dFdy(v), fwidth(v), 0.0); }",
    );
    let mut b = Batch::for_kernel(&k, 0xffff);
    let fc = k.interface().input("gl_FragCoord").unwrap().offset;
    for l in 0..LANES {
        let (q, i) = (l / 4, l % 4);
        b.inputs[fc][l] = (q * 2 + (i & 1)) as f32 + 0.5;
        b.inputs[fc + 1][l] = (i >> 1) as f32 + 0.5;
    }
    k.run(&mut b, &[], &NoTextures).unwrap();
    let c = output(&k, &b, "gl_FragColor");
    for l in 0..LANES {
        let x0 = ((l / 4) * 2) as f32 + 0.5;
        let dx = (x0 + 1.0) * (x0 + 1.0) - x0 * x0;
        assert_eq!(c[0][l], dx, "lane {l}");
        assert_eq!(c[1][l], 3.0);
        assert_eq!(c[2][l], dx.abs() + 3.0);
    }
}

struct Recorder(std::cell::RefCell<Vec<SampleRequest>>);
impl Textures for Recorder {
    fn sample(&self, req: &SampleRequest, out: &mut [[f32; LANES]; 4]) {
        for l in 0..LANES {
            out[0][l] = req.coord[0][l];
            out[1][l] = req.coord[1][l];
            out[2][l] = req.unit[l] as f32;
            out[3][l] = req.compare.map_or(-1.0, |c| c[l]);
        }
        self.0.borrow_mut().push(req.clone());
    }
}

#[test]
fn texture_requests() {
    let k = kernel(
        Stage::Fragment,
        "uniform sampler2D s; uniform sampler2DShadow sh;
        void main() {
            vec4 a = texture2DProj(s, vec3(gl_FragCoord.xy, 2.0), 1.5);
            vec4 b = shadow2DProj(sh, vec4(1.0, 2.0, 3.0, 4.0));
            gl_FragColor = a + b;
        }",
    );
    let u = uniforms(&k, &[("s", &[3]), ("sh", &[5])]);
    let mut b = frag_batch(&k);
    b.active = 0x00ff;
    let rec = Recorder(Default::default());
    k.run(&mut b, &u, &rec).unwrap();
    let reqs = rec.0.borrow();
    assert_eq!(reqs.len(), 2);
    assert_eq!(reqs[0].mask, 0x00ff);
    assert_eq!(reqs[0].unit[0], 3);
    assert_eq!(reqs[0].coord[0][3], 3.5 / 2.0);
    assert_eq!(reqs[0].compare, None);
    match &reqs[0].lod {
        Lod::Derivatives { ddx, bias, .. } => {
            assert_eq!(ddx[0][0], 0.5);
            assert_eq!(bias[0], 1.5);
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(reqs[1].coord[0][0], 0.25);
    assert_eq!(reqs[1].compare.unwrap()[0], 0.75);
    let c = output(&k, &b, "gl_FragColor");
    assert_eq!(c[2][0], 8.0);
}

/// GL_ARB_texture_cube_map_array's lookups reach the units as cube
/// requests with the layer as q: the shadow form's reference is its own
/// argument (no bias, implicit λ), `textureGrad` carries three
/// derivative components, `textureSize` three sizes.
#[test]
fn cube_map_array_requests() {
    let k = kernel(
        Stage::Fragment,
        "#version 130
        #extension GL_ARB_texture_cube_map_array : require
        uniform samplerCubeArray s;
        uniform samplerCubeArrayShadow z;
        out vec4 o;
        void main() {
            vec4 a = texture(s, vec4(1.0, 2.0, 3.0, 4.0), 0.5);
            float b = texture(z, vec4(-1.0, -2.0, -3.0, 5.0), 0.25);
            vec4 c = textureGrad(s, vec4(0.0, 0.0, 1.0, 6.0), vec3(1.0, 2.0, 3.0), vec3(4.0, 5.0, 6.0));
            o = a + vec4(b) + c + vec4(textureSize(z, 2), 0.0);
        }",
    );
    let u = uniforms(&k, &[("s", &[1]), ("z", &[2])]);
    let mut b = frag_batch(&k);
    let rec = Recorder(Default::default());
    k.run(&mut b, &u, &rec).unwrap();
    let reqs = rec.0.borrow();
    assert_eq!(reqs.len(), 3);
    let coord = |r: &SampleRequest| [0, 1, 2, 3].map(|c| r.coord[c][0]);
    assert_eq!(reqs[0].target, glsl::types::SamplerKind::SamplerCubeArray);
    assert_eq!(coord(&reqs[0]), [1.0, 2.0, 3.0, 4.0]);
    assert_eq!(reqs[0].compare, None);
    assert!(matches!(&reqs[0].lod, Lod::Derivatives { bias, .. } if bias[0] == 0.5));
    assert_eq!(reqs[1].unit[0], 2);
    assert_eq!(coord(&reqs[1]), [-1.0, -2.0, -3.0, 5.0]);
    assert_eq!(reqs[1].compare.unwrap()[0], 0.25);
    assert!(reqs[1].compare_only);
    assert!(matches!(&reqs[1].lod, Lod::Derivatives { bias, .. } if bias[0] == 0.0));
    assert_eq!(coord(&reqs[2])[3], 6.0);
    match &reqs[2].lod {
        Lod::Gradients { ddx, ddy } => {
            assert_eq!([ddx[0][0], ddx[1][0], ddx[2][0]], [1.0, 2.0, 3.0]);
            assert_eq!([ddy[0][0], ddy[1][0], ddy[2][0]], [4.0, 5.0, 6.0]);
        }
        other => panic!("{other:?}"),
    }
}

/// Integer texels (3, −2, 7, 1 as bits), texel fetches echoing their
/// integer coordinates and level, sizes echoing the unit and level.
struct IntTextures;
impl Textures for IntTextures {
    fn sample(&self, req: &SampleRequest, out: &mut [[f32; LANES]; 4]) {
        for l in 0..LANES {
            for (c, v) in [3i32, -2, 7, 1].into_iter().enumerate() {
                out[c][l] = f32::from_bits(v as u32);
            }
            assert!(req.offset.is_none_or(|o| o[0][l] == 1 && o[1][l] == -1));
        }
    }
    fn fetch(&self, req: &crate::FetchRequest, out: &mut [[f32; LANES]; 4]) {
        for l in 0..LANES {
            for c in 0..3 {
                out[c][l] = req.coord[c][l] as f32;
            }
            out[3][l] = req.lod[l] as f32;
        }
    }
    fn size(&self, unit: u32, _: glsl::types::SamplerKind, lod: i32) -> [i32; 3] {
        [unit as i32 * 10, lod, 0]
    }
}

#[test]
fn integer_lookups_fetches_and_sizes_arrive_exactly() {
    let k = kernel(
        Stage::Fragment,
        "#version 130
        uniform isampler2D si;
        uniform sampler2D s;
        out vec4 a, b, c;
        void main() {
            a = vec4(textureOffset(si, vec2(0.5), ivec2(1, -1)));
            b = texelFetchOffset(s, ivec2(gl_FragCoord.xy), 2, ivec2(5, -3));
            c = vec4(textureSize(s, 4), textureSize(si, 1));
        }",
    );
    let u = uniforms(&k, &[("si", &[2]), ("s", &[3])]);
    let mut b = frag_batch(&k);
    k.run(&mut b, &u, &IntTextures).unwrap();
    let (a, f, c) = (
        output(&k, &b, "a"),
        output(&k, &b, "b"),
        output(&k, &b, "c"),
    );
    for l in 0..LANES {
        assert_eq!([a[0][l], a[1][l], a[2][l], a[3][l]], [3.0, -2.0, 7.0, 1.0]);
        assert_eq!([f[0][l], f[1][l], f[3][l]], [l as f32 + 5.0, -3.0, 2.0]);
        assert_eq!([c[0][l], c[1][l], c[2][l], c[3][l]], [30.0, 4.0, 20.0, 1.0]);
    }
}

#[test]
fn loop_budget_ends_infinite_loops() {
    let mut k = kernel(
        Stage::Fragment,
        "void main() { float x = 0.0; while (true) { x += 1.0; } gl_FragColor = vec4(x); }",
    );
    k.set_loop_budget(10_000);
    let mut b = frag_batch(&k);
    let e = k.run(&mut b, &[], &NoTextures).unwrap_err();
    assert_eq!(e, ExecError::LoopBudget { iterations: 10_001 });
    // Finite loops under the budget run.
    let mut k = kernel(
        Stage::Fragment,
        "void main() { float x = 0.0; for (int i = 0; i < 100; i++) { x += 1.0; } gl_FragColor = vec4(x); }",
    );
    // 100 iterations plus the trip that finds the condition false.
    k.set_loop_budget(101);
    let mut b = frag_batch(&k);
    k.run(&mut b, &[], &NoTextures).unwrap();
    assert_eq!(b.outputs[0][3], 100.0);
}

#[test]
fn integer_division_by_zero_gives_zero() {
    let (c, _) = frag_colors(
        "uniform int z;
        void main() { int a = 7 / z; int b = (-2147483647 - 1) / -1; gl_FragColor = vec4(float(a), float(b), 0.0, 0.0); }",
        &[("z", &[0])],
    );
    assert_eq!(c[0][0], 0.0);
    assert_eq!(c[0][1], -2147483648.0);
}

/// Integer varyings cross stages as their bits: a vertex shader's `flat
/// out int`/`uint` (values no float holds: odd large ones, and bits that
/// spell NaNs) and a fragment shader's `flat in` arrive exactly, through
/// every executor.
#[test]
fn integer_varyings_are_their_bits() {
    let vs = kernel(
        Stage::Vertex,
        "#version 130
        uniform int a; uniform uint b;
        flat out int i; flat out uint u;
        void main() { gl_Position = vec4(0.0); i = a; u = b; }",
    );
    let fs = kernel(
        Stage::Fragment,
        "#version 130
        uniform int a; uniform uint b;
        flat in int i; flat in uint u;
        void main() { gl_FragColor = vec4(i == a ? 1.0 : 0.0, u == b ? 1.0 : 0.0, 0.0, 0.0); }",
    );
    for value in [0x7fe8_92c2u32, 0xffe3_c7cd, 0x8000_0001, 16_777_217, 1] {
        let words = [("a", &[value][..]), ("b", &[value.rotate_left(7)][..])];
        let uv = uniforms(&vs, &words);
        let mut runs: Vec<Batch> = Vec::new();
        let mut b = Batch::for_kernel(&vs, FULL_MASK);
        vs.run(&mut b, &uv, &NoTextures).unwrap();
        runs.push(b.clone());
        vs.run_reference(&mut b, &uv, &NoTextures).unwrap();
        runs.push(b.clone());
        if Variant::Jit.supported() {
            vs.run_variant(Variant::Jit, &mut b, &uv, &NoTextures)
                .unwrap();
            runs.push(b);
        }
        for b in &runs {
            assert_eq!(output(&vs, b, "i")[0][3].to_bits(), value);
            assert_eq!(output(&vs, b, "u")[0][3].to_bits(), value.rotate_left(7));
        }
        let uf = uniforms(&fs, &words);
        let mut fb = frag_batch(&fs);
        for (name, v) in [("i", value), ("u", value.rotate_left(7))] {
            let s = fs.interface().input(name).expect("input");
            fb.inputs[s.offset] = [f32::from_bits(v); LANES];
        }
        let mut reference = fb.clone();
        fs.run(&mut fb, &uf, &NoTextures).unwrap();
        fs.run_reference(&mut reference, &uf, &NoTextures).unwrap();
        for b in [&fb, &reference] {
            let c = output(&fs, b, "gl_FragColor");
            assert_eq!((c[0][5], c[1][5]), (1.0, 1.0), "{value:#x}");
        }
    }
}

#[test]
fn results_do_not_depend_on_active_lanes() {
    let src = "uniform float u;
        float f(float x) { float s = 0.0; for (int i = 0; i < 8; i++) { if (x < float(i)) break; s += sin(x * float(i)); } return s; }
        void main() { gl_FragColor = vec4(f(gl_FragCoord.x * u)); }";
    let k = kernel(Stage::Fragment, src);
    let u = uniforms(&k, &[("u", &[0.7f32.to_bits()])]);
    let mut all = frag_batch(&k);
    k.run(&mut all, &u, &NoTextures).unwrap();
    for lane in 0..LANES {
        let mut one = frag_batch(&k);
        one.active = 1 << lane;
        k.run(&mut one, &u, &NoTextures).unwrap();
        assert_eq!(
            one.outputs[0][lane].to_bits(),
            all.outputs[0][lane].to_bits()
        );
    }
}

#[test]
fn interface_layout() {
    let k = kernel(
        Stage::Vertex,
        "#version 120
        struct L { vec3 pos; float w[2]; };
        uniform L lights[2];
        uniform mat2 m;
        uniform sampler2D tex;
        attribute vec3 p;
        varying vec2 t;
        void main() { gl_Position = vec4(p + lights[1].pos, lights[0].w[1]) + texture2DLod(tex, m[0], 0.0); t = m[1]; }",
    );
    let i = k.interface();
    let l = i.uniform("lights").unwrap();
    assert_eq!(l.components, 10);
    assert_eq!(
        i.locate_uniform("lights[1].w[1]"),
        Some((l.offset + 9, Type::FLOAT))
    );
    assert_eq!(i.locate_uniform("lights[2]"), None);
    assert_eq!(i.uniform("tex").unwrap().components, 1);
    assert!(i.input("p").is_some());
    let t = i.output("t").unwrap();
    assert!(t.written);
    assert!(i.output("gl_Position").unwrap().written);
    // Built-ins the shader never mentions are not in the module at all.
    assert!(i.output("gl_PointSize").is_none_or(|s| !s.written));
}

/// A named output block's instance is one slot per member (per element),
/// named after the block with the member's interpolation qualifier; an
/// unnamed block's members are varyings of their own names that remember
/// their block.
#[test]
fn block_members_are_slots_named_after_the_block() {
    use glsl::ir::Interpolation;
    let k = kernel(
        Stage::Vertex,
        "#version 150
        in vec4 p;
        out Blk { flat float f; noperspective vec2 n; float s; } inst;
        out Arr { flat int i; } arr[2];
        out Plain { vec3 q; };
        void main() { gl_Position = p; inst.f = 1.0; inst.n = p.xy; inst.s = 2.0; arr[0].i = 1; arr[1].i = 2; q = p.xyz; }",
    );
    let i = k.interface();
    let slot = |name: &str| {
        let s = i.output(name).unwrap_or_else(|| panic!("{name}"));
        (s.components, s.interpolation)
    };
    assert_eq!(slot("Blk.f"), (1, Some(Interpolation::Flat)));
    assert_eq!(slot("Blk.n"), (2, Some(Interpolation::NoPerspective)));
    assert_eq!(slot("Blk.s"), (1, None));
    assert_eq!(slot("Arr[1].i"), (1, Some(Interpolation::Flat)));
    assert_eq!(slot("q"), (3, None));
    // The unnamed block's member keeps its name and links as `Plain.q`,
    // as a named instance's member would.
    assert_eq!(i.output("q").unwrap().link_name(), "Plain.q");
    assert_eq!(i.output("Blk.f").unwrap().link_name(), "Blk.f");
    assert!(i.output("inst").is_none());
    let (f, n) = (i.output("Blk.f").unwrap(), i.output("Blk.n").unwrap());
    assert_eq!(n.offset, f.offset + 1);
    assert_eq!(
        i.output("Arr[1].i").unwrap().offset,
        i.output("Arr[0].i").unwrap().offset + 1
    );
}

#[derive(Default)]
struct Lines(Vec<Span>, Vec<(u32, u32)>);
impl Trace for Lines {
    fn statement(&mut self, span: Span) {
        self.0.push(span);
    }
    fn store(&mut self, register: u32, bits: u32) {
        self.1.push((register, bits));
    }
}

#[test]
fn trace_reports_statements_of_one_lane() {
    let k = kernel(
        Stage::Fragment,
        "void main() {
            float a = 1.0;
            if (gl_FragCoord.x > 3.0) a = 2.0;
            gl_FragColor = vec4(a);
        }",
    );
    let mut t0 = Lines::default();
    let mut b = frag_batch(&k);
    k.run_traced(&mut b, &[], &NoTextures, 0, &mut t0).unwrap();
    let mut t5 = Lines::default();
    let mut b = frag_batch(&k);
    k.run_traced(&mut b, &[], &NoTextures, 5, &mut t5).unwrap();
    assert_eq!(t0.0.len() + 1, t5.0.len());
    let a = k.variables().iter().find(|v| v.name == "a").unwrap();
    assert!(t5.1.contains(&(a.first_register, 2.0f32.to_bits())));
}

#[test]
fn unsized_local_arrays_take_their_implicit_size() {
    let (c, _) = frag_colors(
        "void f() { float a[]; a[5] = 2.0; a[1] = 1.0; gl_FragColor = vec4(a[5], a[1], 0.0, 1.0); }
        void main() { f(); }",
        &[],
    );
    assert_eq!(c[3], [2.0, 1.0, 0.0, 1.0]);
}

#[test]
fn dynamic_index_through_a_swizzle_writes_the_variable() {
    // piglit swizzled-writemask-indexing-nonconst: `v.wzyx[i] = ...`.
    let (c, _) = frag_colors(
        "void main() {
            int i = int(gl_FragCoord.x) - (int(gl_FragCoord.x) / 4) * 4;
            vec4 v = vec4(0.0);
            v.wzyx[i] = 1.0;
            vec3 w = vec3(0.0);
            w.zx[i] += 2.0;
            gl_FragColor = v + vec4(w, 0.0) * 10.0 + vec4(v.wzyx[i] * 100.0);
        }",
        &[],
    );
    for (l, c) in c.iter().enumerate() {
        let i = l % 4;
        let mut want = [100.0f32; 4];
        want[3 - i] += 1.0;
        // `w.zx[i]` clamps i to 1 beyond the swizzle: z for 0, x otherwise.
        want[if i == 0 { 2 } else { 0 }] += 20.0;
        assert_eq!(*c, want, "lane {l}");
    }
}

#[test]
fn constant_if_lowers_only_the_taken_branch() {
    // piglit glsl-const-folding-01: a function without a body called only
    // in branches a constant condition rules out.
    let (c, _) = frag_colors(
        "#version 120
        void missing();
        void main() {
            gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0);
            if (false) missing();
            else if (sqrt(4.0) != 2.0) missing();
            if (true) gl_FragColor.b = 0.5; else missing();
        }",
        &[],
    );
    assert!(c.iter().all(|c| *c == [0.0, 1.0, 0.5, 1.0]), "{c:?}");
    // Anywhere else a body-less callee is still refused.
    let s = link_one(
        Stage::Fragment,
        "void missing();
        uniform bool u;
        void main() { if (u) missing(); gl_FragColor = vec4(1.0); }",
    );
    if let Ok(s) = s {
        assert!(Kernel::new(&s).is_err());
    }
}

#[test]
fn min_max_ignore_nan_and_underflow_flushes() {
    let (c, _) = frag_colors(
        "uniform float zero; uniform float tiny;
        void main() {
            float nan = zero / zero;
            float m = min(nan, -3.0) + min(-3.0, nan) + max(nan, 3.0) + max(3.0, nan);
            // 2^-75 * 2^-75 = 2^-150: below every subnormal is 0 anyway;
            // 2^-70 * 2^-70 = 2^-140 is subnormal, flushed to 0.
            float p = tiny * tiny;
            gl_FragColor = vec4(m, float(p > 0.0), float(tiny > 0.0), pow(2.0, -140.0));
        }",
        &[
            ("zero", &[0.0f32.to_bits()]),
            ("tiny", &[(2.0f32).powi(-70).to_bits()]),
        ],
    );
    assert!(c.iter().all(|c| *c == [0.0, 0.0, 1.0, 0.0]), "{c:?}");
}

#[test]
fn out_argument_index_is_taken_at_the_call() {
    // piglit vs-out-conversion-int-to-float-vec4-index: the converted value
    // lands in `value[1]`, the index before the callee changed `i`.
    let (c, _) = frag_colors(
        "#version 120
        void f(inout int i, out int x) { x = 4; i = 0; }
        void main() {
            vec4 value = vec4(0.0);
            int i = 1;
            f(i, value[i]);
            gl_FragColor = value;
        }",
        &[],
    );
    assert!(c.iter().all(|c| *c == [0.0, 4.0, 0.0, 0.0]), "{c:?}");
}

#[test]
fn redeclared_unsized_local_array_keeps_its_initializer() {
    // piglit glsl-fs-array-redeclaration.
    let (c, _) = frag_colors(
        "#version 120
        void main() {
            float a[];
            float a[] = float[](3.0, 1.0);
            gl_FragColor = vec4(a[0], a[1], float(a.length()), 1.0);
        }",
        &[],
    );
    assert!(c.iter().all(|c| *c == [3.0, 1.0, 2.0, 1.0]), "{c:?}");
}

/// A rough throughput measure (run with `--release -- --ignored`).
#[test]
#[ignore = "benchmark"]
fn bench_interpreter() {
    let k = kernel(
        Stage::Fragment,
        "uniform vec4 c; varying vec4 v;
        void main() {
            vec4 acc = vec4(0.0);
            for (int i = 0; i < 64; i++) {
                acc += sin(v * float(i)) * c + vec4(dot(v.xyz, c.xyz));
            }
            gl_FragColor = acc;
        }",
    );
    let u = uniforms(&k, &[("c", &fbits(&[0.5, 0.25, 0.125, 1.0]))]);
    let mut b = frag_batch(&k);
    let batches = 2000;
    let t = std::time::Instant::now();
    for _ in 0..batches {
        k.run(&mut b, &u, &NoTextures).unwrap();
    }
    let s = t.elapsed().as_secs_f64();
    eprintln!(
        "{} ops, {} registers: {:.0} fragments/s ({:.1} ns per op per batch)",
        k.op_count(),
        k.register_count(),
        (batches * LANES) as f64 / s,
        s * 1e9 / (batches as f64 * (k.op_count() as f64 * 64.0 * 0.8))
    );
}

#[derive(Default)]
struct Printed(Vec<(usize, String)>);
impl PrintSink for Printed {
    fn print(&mut self, lane: usize, _span: Span, text: &str) {
        self.0.push((lane, text.to_string()));
    }
}

#[test]
fn debug_printf_prints_per_lane_in_execution_order() {
    let k = kernel(
        Stage::Fragment,
        "#extension GL_SHADERBOX_debug_printf : enable
        void main() {
            for (int i = 0; i < 2; i++)
                if (gl_FragCoord.x < 2.0)
                    debugPrintfEXT(\"x=%.1f i=%d v=%v2f\\n\", gl_FragCoord.x, i, vec2(i));
            gl_FragColor = vec4(1.0);
        }",
    );
    assert!(k.prints());
    let mut out = Printed::default();
    let mut b = frag_batch(&k);
    b.helper = 1 << 1; // helper lanes do not print
    b.active &= !b.helper;
    k.run_printing(&mut b, &[], &NoTextures, &mut out).unwrap();
    let want = vec![
        (0, "x=0.5 i=0 v=0.000000, 0.000000\n".to_string()),
        (0, "x=0.5 i=1 v=1.000000, 1.000000\n".to_string()),
    ];
    assert_eq!(out.0, want);
    // The plain run ignores the call; the trace of one lane sees it.
    let mut b = frag_batch(&k);
    k.run(&mut b, &[], &NoTextures).unwrap();
    #[derive(Default)]
    struct T(Vec<String>);
    impl Trace for T {
        fn statement(&mut self, _: Span) {}
        fn store(&mut self, _: u32, _: u32) {}
        fn printf(&mut self, text: &str) {
            self.0.push(text.to_string());
        }
    }
    let mut t = T::default();
    let mut b = frag_batch(&k);
    k.run_traced(&mut b, &[], &NoTextures, 1, &mut t).unwrap();
    assert_eq!(t.0.len(), 2);
    assert!(t.0[1].starts_with("x=1.5 i=1"));
}

#[test]
fn debug_printf_prints_uints_unsigned() {
    let k = kernel(
        Stage::Fragment,
        "#version 130
        #extension GL_SHADERBOX_debug_printf : enable
        uniform uint u;
        void main() {
            if (gl_FragCoord.x < 1.0)
                debugPrintfEXT(\"%u %#x %v2u %d\\n\", u, u, uvec2(u, 7u), int(u));
            gl_FragColor = vec4(1.0);
        }",
    );
    let u = uniforms(&k, &[("u", &[0xffff_fffe])]);
    let mut out = Printed::default();
    let mut b = frag_batch(&k);
    k.run_printing(&mut b, &u, &NoTextures, &mut out).unwrap();
    assert_eq!(
        out.0,
        vec![(0, "4294967294 0xfffffffe 4294967294, 7 -2\n".to_string())]
    );
}

/// Every program of the shader library compiles to native code (a kernel
/// the JIT declines runs interpreted, slower, with no other sign).
#[test]
fn library_shaders_compile_to_native_code() {
    if !Variant::Jit.supported() || crate::kernel_variant() != Variant::Jit {
        return;
    }
    let mut bad = Vec::new();
    for entry in std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../../shaders")).unwrap() {
        let p = entry.unwrap().path();
        let stage = match p.extension().and_then(|e| e.to_str()) {
            Some("vert") => Stage::Vertex,
            Some("frag") => Stage::Fragment,
            _ => continue,
        };
        let src = std::fs::read_to_string(&p).unwrap();
        // Files that are parts of a program (the Phong library, no
        // `main`) do not link alone; render's tests link every program.
        let Ok(s) = link_one(stage, &src) else {
            continue;
        };
        let k = Kernel::new(&s).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
        k.compile_native();
        match k.native_code() {
            Some(Ok(_)) => {}
            other => bad.push(format!("{}: {:?}", p.display(), other)),
        }
    }
    assert!(bad.is_empty(), "{bad:#?}");
}

#[test]
fn lengths_of_implicitly_sized_arrays_are_their_sizes() {
    // GL_ARB_shader_storage_buffer_object's `.length()` of arrays sized by
    // their uses: the local takes its largest constant index plus one,
    // the global the linker's size.
    let (c, _) = frag_colors(
        "#version 120
#extension GL_ARB_shader_storage_buffer_object : require
float g[];
void main() {
    float a[];
    a[2] = 1.0;
    g[4] = a[2];
    gl_FragColor = vec4(float(a.length()), float(g.length()), g[4], 0.0);
}",
        &[],
    );
    assert_eq!(c[0], [3.0, 5.0, 1.0, 0.0]);
}

/// `Kernel::reads_input` names the input components some op reads: the
/// components of a vector input and of gl_FragCoord the shader never
/// uses are left out, and a component read only to be overwritten is
/// not needed either.
#[test]
fn reads_input_is_per_component() {
    let k = kernel(
        Stage::Fragment,
        "#version 130
        in vec4 v;
        in vec2 w;
        out vec4 o;
        void main() {
            vec2 t = w;
            t.y = 2.0;
            o = vec4(v.xy, gl_FragCoord.x, t.x + t.y + gl_FragCoord.w);
        }",
    );
    let offset = |name: &str| {
        let s = k.interface().inputs.iter().find(|s| s.name == name);
        s.unwrap_or_else(|| panic!("no input {name}")).offset
    };
    let (v, w, fc) = (offset("v"), offset("w"), offset("gl_FragCoord"));
    let reads = |c: usize| k.reads_input(c);
    assert_eq!(
        [0, 1, 2, 3].map(|i| reads(v + i)),
        [true, true, false, false]
    );
    assert_eq!([0, 1].map(|i| reads(w + i)), [true, false]);
    assert_eq!(
        [0, 1, 2, 3].map(|i| reads(fc + i)),
        [true, false, false, true]
    );
}
