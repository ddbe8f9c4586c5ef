//! Every executor variant the CPU supports computes the same bytes as the
//! portable one (and as the reference interpreter).

use super::{bits_of, link_one};
use crate::{supported_variants, Batch, Kernel, NoTextures, Variant};
use glsl::ir::Stage;

const SPHERE_FRAG: &str = include_str!("../../../../shaders/sphere.frag");
const SPHERE_VERT: &str = include_str!("../../../../shaders/sphere.vert");

/// Shaders touching every kind of op: float/int/bool arithmetic and
/// comparisons, conversions, every built-in, dynamic indexing (gather,
/// scatter, uniform gather), derivatives, noise, loops, discard, texture
/// lookups (NoTextures), subroutine mode via the sphere shaders.
const SHADERS: &[(Stage, &str)] = &[
    (Stage::Fragment, SPHERE_FRAG),
    (Stage::Vertex, SPHERE_VERT),
    (
        Stage::Fragment,
        "#version 120
        uniform float u[4]; varying vec4 v; uniform sampler2D s;
        void main() {
            vec4 a = v * 3.7 - 1.2;
            vec4 r = vec4(0.0);
            r += sin(a) + cos(a) + tan(a * 0.1) + asin(clamp(a, -1.0, 1.0)) + acos(clamp(a * 0.5, -1.0, 1.0));
            r += atan(a) + atan(a, a.yzwx) + pow(abs(a), a.wzyx) + exp(a) + log(abs(a)) + exp2(a) + log2(abs(a));
            r += sqrt(abs(a)) + inversesqrt(abs(a)) + abs(a) + sign(a) + floor(a) + ceil(a) + fract(a);
            r += mod(a, a.yzwx) + min(a, a.zwxy) + max(a, 0.5) + clamp(a, -0.5, 0.75);
            r += mix(a, a.wzyx, v.x) + step(0.1, a) + smoothstep(-1.0, 1.0, a);
            r += radians(a) + degrees(a) + vec4(dot(a, v), length(a), distance(a, v), 0.0);
            r.xyz += cross(a.xyz, v.zyx) + normalize(a.xyz) + reflect(a.xyz, normalize(v.xyz))
                + refract(normalize(a.xyz), normalize(v.xyz), 0.7) + faceforward(a.xyz, v.xyz, a.zyx);
            r += dFdx(a) + dFdy(a) + fwidth(a) + noise4(a) + vec4(noise1(a), noise2(a), noise1(v.x));
            mat3 m = mat3(a.xyz, a.yzw, v.xyz);
            r.xyz += m * a.xyz + a.xyz * m + (m * matrixCompMult(m, m))[1];
            int i = int(a.x * 10.0);
            ivec2 iv = ivec2(i / 3, i * i - 7) + ivec2(-i, i / (i - i + 1));
            bool b = any(lessThan(a, v)) ^^ all(greaterThanEqual(a, v)) || !(i == 3) && iv.x < iv.y;
            float arr[6];
            for (int k = 0; k < 6; k++) arr[k] = float(k) * a.y;
            arr[int(abs(v.y) * 6.0)] = u[int(abs(v.z) * 4.0)];
            for (int k = 0; k < 8; k++) {
                if (arr[k / 2] > 1.0) break;
                if (k == 2) continue;
                r.w += arr[k - k / 2] * float(b);
                if (r.w > 100.0 && v.w > 0.9) discard;
            }
            r += texture2D(s, a.xy) + texture2DProj(s, a.xyz) + texture2D(s, v.xy, 0.5);
            gl_FragColor = r + vec4(iv, float(b), 0.0);
        }",
    ),
    // Arrays of arrays: dynamic indices on each level of locals and
    // uniforms, rows copied and compared.
    (
        Stage::Vertex,
        "#version 120
        #extension GL_ARB_arrays_of_arrays : enable
        uniform vec2 u[3][2][2]; attribute vec4 p;
        void main() {
            ivec3 i = ivec3(abs(p.xyz) * 4.0);
            vec2 a[2][2] = u[i.x];
            vec2[2] r = u[i.y][i.z];
            a[i.z][i.y] += r[i.x] * p.w;
            float m[4][3];
            for (int k = 0; k < 4; k++)
                for (int n = 0; n < 3; n++) m[k][n] = float(k * 3 + n) * p.x;
            m[i.x][i.y] = p.y;
            gl_Position = vec4(a[i.y][i.x] + a[1][0], m[i.z][i.x] + m[3][2], float(a == u[i.x]) + float(m[1] == m[i.x]));
        }",
    ),
];

pub(super) fn fill(b: &mut Batch, seed: u32) {
    let mut s = seed.wrapping_mul(2_654_435_761) | 1;
    for c in b.inputs.iter_mut() {
        for x in c.iter_mut() {
            s ^= s << 13;
            s ^= s >> 17;
            s ^= s << 5;
            *x = (s >> 8) as f32 / (1u32 << 23) as f32 - 1.0;
        }
    }
}

#[test]
fn every_variant_computes_the_same_bytes() {
    let variants = supported_variants();
    assert_eq!(variants.first(), Some(&Variant::Portable));
    for (n, (stage, src)) in SHADERS.iter().enumerate() {
        let linked = link_one(*stage, src).unwrap_or_else(|e| panic!("shader {n}: {e}"));
        for limit in [crate::limits::INLINE_LIMIT, 0] {
            let k = Kernel::with_inline_limit(&linked, limit).expect("lowers");
            let u: Vec<u32> = (0..k.interface().uniform_words)
                .map(|w| (0.25 + w as f32 * 0.125).to_bits())
                .collect();
            for round in 0..40u32 {
                let active = if round % 4 == 3 { 0x0ff0 } else { 0xffff };
                let mut base = Batch::for_kernel(&k, active);
                fill(&mut base, round + 1);
                let mut want = base.clone();
                let r0 = k.run_reference(&mut want, &u, &NoTextures);
                for &v in &variants {
                    let mut got = base.clone();
                    let r = k.run_variant(v, &mut got, &u, &NoTextures);
                    assert_eq!(r, r0, "shader {n} {}: result", v.name());
                    assert_eq!(got.discarded, want.discarded, "shader {n} {}", v.name());
                    assert_eq!(
                        bits_of(&got.outputs),
                        bits_of(&want.outputs),
                        "shader {n} {} round {round}: outputs",
                        v.name()
                    );
                }
            }
            if variants.contains(&Variant::Jit) {
                // Inlined programs run as native code; subroutines are
                // interpreted.
                let calls = k
                    .code
                    .ins
                    .iter()
                    .any(|i| matches!(i.op, crate::program::Op::Call { .. }));
                match (calls, k.native_code()) {
                    (true, Some(Err(_))) | (false, Some(Ok(_))) => {}
                    (_, s) => panic!("shader {n} limit {limit}: native code {s:?}"),
                }
            }
        }
    }
}

/// Runs with the uniforms prepared once ([`Kernel::prepare`]: the pool
/// computed ahead) compute the same bytes as the reference, in every
/// variant; native code reads the prepared pool where it is.
#[test]
fn prepared_runs_compute_the_same_bytes() {
    for (n, (stage, src)) in SHADERS.iter().enumerate() {
        let linked = link_one(*stage, src).unwrap_or_else(|e| panic!("shader {n}: {e}"));
        let k = Kernel::new(&linked).expect("lowers");
        k.compile_native();
        let u: Vec<u32> = (0..k.interface().uniform_words)
            .map(|w| (0.5 + w as f32 * 0.25).to_bits())
            .collect();
        let prepared = k.prepare(&u, &NoTextures);
        for round in 0..8u32 {
            let active = if round % 2 == 1 { 0x0ff0 } else { 0xffff };
            let mut base = Batch::for_kernel(&k, active);
            fill(&mut base, round + 7);
            let mut want = base.clone();
            let r0 = k.run_reference(&mut want, &u, &NoTextures);
            for v in supported_variants() {
                // Garbage in the thread's register file: what a run reads
                // must come from the batch and the prepared pool.
                crate::dispatch::FILE.with(|f| {
                    for r in f.borrow_mut().iter_mut() {
                        *r = [0x7fc0_dead; crate::LANES];
                    }
                });
                let mut got = base.clone();
                let r = crate::dispatch::run_on(
                    v,
                    &k,
                    &k.code,
                    &mut got,
                    &prepared.uniforms,
                    &NoTextures,
                    Some(&prepared),
                );
                assert_eq!(r, r0, "shader {n} {}: result", v.name());
                assert_eq!(got.discarded, want.discarded, "shader {n} {}", v.name());
                assert_eq!(
                    bits_of(&got.outputs),
                    bits_of(&want.outputs),
                    "shader {n} {} round {round}: outputs",
                    v.name()
                );
            }
        }
    }
}

/// A kernel's sizes for the benchmarks' headers: ops, executor
/// instructions, prologue, registers.
fn sizes(k: &Kernel) -> String {
    format!(
        "{} ops (executor: {}, prologue {}, {} registers",
        k.op_count(),
        k.code.ins.len(),
        k.code.prologue.len(),
        k.code.prog.registers
    )
}

/// The benchmarks' workload: 64 batches of 16 live lanes with
/// pseudo-random inputs, each timed pass running a kernel over all of them.
struct Bench {
    batches: Vec<Batch>,
}

impl Bench {
    fn new(k: &Kernel) -> Self {
        let batches = (0..64)
            .map(|i| {
                let mut b = Batch::for_kernel(k, 0xffff);
                fill(&mut b, i + 1);
                b
            })
            .collect();
        Bench { batches }
    }

    /// Nanoseconds per batch of `f`: the best of 7 rounds of 20 passes.
    fn time(&mut self, f: &mut dyn FnMut(&mut Batch)) -> f64 {
        let mut best = f64::MAX;
        for _ in 0..7 {
            let t = std::time::Instant::now();
            for _ in 0..20 {
                for b in self.batches.iter_mut() {
                    f(b);
                }
            }
            best = best.min(t.elapsed().as_secs_f64() / (20.0 * 64.0));
        }
        best * 1e9
    }

    /// For profiling one variant: with `BENCH_ONLY` naming it, times only
    /// that one, for a few seconds, and says so (true).
    fn only(&mut self, k: &Kernel, u: &[u32]) -> bool {
        let Ok(only) = std::env::var("BENCH_ONLY") else {
            return false;
        };
        let v = supported_variants()
            .into_iter()
            .find(|v| v.name() == only)
            .expect("BENCH_ONLY names a supported variant");
        for _ in 0..20 {
            let t = self.time(&mut |b| k.run_variant(v, b, u, &NoTextures).unwrap());
            eprintln!("  {:8} {t:.0} ns/batch", v.name());
        }
        true
    }

    /// Prints each supported variant's time and its speed-up over
    /// `reference`.
    fn variants(&mut self, k: &Kernel, u: &[u32], reference: f64) {
        for v in supported_variants() {
            let t = self.time(&mut |b| k.run_variant(v, b, u, &NoTextures).unwrap());
            eprintln!("  {:8} {t:.0} ns/batch ({:.2}x)", v.name(), reference / t);
        }
    }

    /// Prints the time of the kernel's own variant run on the uniforms `u`
    /// prepared once.
    fn prepared(&mut self, k: &Kernel, u: &[u32], reference: f64) {
        let prepared = k.prepare(u, &NoTextures);
        let t = self.time(&mut |b| k.run_prepared(b, &prepared, &NoTextures).unwrap());
        eprintln!(
            "  {:8} {t:.0} ns/batch with run_prepared ({:.2}x)",
            crate::kernel_variant().name(),
            reference / t
        );
    }
}

/// Time per 16-lane batch of the sphere-impostor fragment shader with the
/// reference interpreter and each executor variant, best of 7 rounds
/// (run with `cargo test --release -p shaderbox-exec bench_sphere --
/// --ignored --nocapture`).
#[test]
#[ignore = "benchmark"]
fn bench_sphere() {
    let linked = link_one(Stage::Fragment, SPHERE_FRAG).unwrap();
    let k = Kernel::new(&linked).unwrap();
    let u = super::depth_slice::sphere_uniforms(&k, 0.0);
    let mut bench = Bench::new(&k);
    if bench.only(&k, &u) {
        return;
    }
    let reference = bench.time(&mut |b| k.run_reference(b, &u, &NoTextures).unwrap());
    eprintln!(
        "sphere.frag: {}, {} zeroed per run); reference interpreter {reference:.0} ns/batch",
        sizes(&k),
        k.code.zero.len()
    );
    bench.variants(&k, &u, reference);
    bench.prepared(&k, &u, reference);
    if let Some(d) = k.depth_only() {
        let t = bench.time(&mut |b| d.run(b, &u, &NoTextures).unwrap());
        eprintln!(
            "  depth_only: {} ops, {} zeroed per run, {t:.0} ns/batch ({:.2}x)",
            d.op_count(),
            d.code.zero.len(),
            reference / t
        );
    }
}

const MATERIALS_FRAG: &str = include_str!("../../../glsl/tests/seeds/000-materials.frag");

/// Time per 16-lane batch of the seed materials shader (normalize, two
/// lights with `pow`: the lit-mesh scene's) with each variant, prepared
/// once per draw as the renderer runs it (`cargo test --release -p
/// shaderbox-exec bench_materials -- --ignored --nocapture`).
#[test]
#[ignore = "benchmark"]
fn bench_materials() {
    let linked = link_one(Stage::Fragment, MATERIALS_FRAG).unwrap();
    let k = Kernel::new(&linked).unwrap();
    // Every uniform word a float in [0.25, 1), shininess 30.
    let mut u: Vec<u32> = (0..k.interface().uniform_words)
        .map(|i| (0.25 + (i % 7) as f32 / 9.5).to_bits())
        .collect();
    if let Some((w, _)) = k.interface().locate_uniform("gl_FrontMaterial.shininess") {
        if let Some(x) = u.get_mut(w) {
            *x = 30.0f32.to_bits();
        }
    }
    let mut bench = Bench::new(&k);
    if bench.only(&k, &u) {
        return;
    }
    let reference = bench.time(&mut |b| k.run_reference(b, &u, &NoTextures).unwrap());
    eprintln!(
        "materials.frag: {}); reference interpreter {reference:.0} ns/batch",
        sizes(&k)
    );
    bench.variants(&k, &u, reference);
    bench.prepared(&k, &u, reference);
}

/// Time per 16-lane batch of a shader made of `pow`, `exp`, `exp2`, `log`
/// and `log2` (40 calls a lane) with the reference interpreter and each
/// variant: whether those built-ins vectorize (`cargo test --release -p
/// shaderbox-exec bench_math -- --ignored --nocapture`).
#[test]
#[ignore = "benchmark"]
fn bench_math() {
    let src = "#version 120
        varying vec4 v;
        void main() {
            vec4 a = abs(v) * 4.0 + 0.01;
            vec4 r = pow(a, v.wzyx * 8.0) + pow(a.yzwx, vec4(16.0)) + exp(-a) + exp2(v * 10.0);
            r += log(a) + log2(a.zwxy) + pow(r.wxyz, v.yzwx);
            r += exp(v.zwxy) + log2(a * 3.0) + exp2(-a.xwzy);
            gl_FragColor = r;
        }";
    let linked = link_one(Stage::Fragment, src).unwrap();
    let k = Kernel::new(&linked).unwrap();
    let mut bench = Bench::new(&k);
    let reference = bench.time(&mut |b| k.run_reference(b, &[], &NoTextures).unwrap());
    eprintln!("math: reference interpreter {reference:.0} ns/batch");
    bench.variants(&k, &[], reference);
}

/// Subnormal values are zero in every variant, wherever they arise: float
/// literals, inputs, uniforms, the intermediates of built-ins, derivatives,
/// results read by native code's callbacks and written to outputs. Native
/// code reads them as zero in hardware (DAZ) without flushing each result;
/// a product that rounds up to the smallest normal stays normal (which
/// flush-to-zero hardware would not give).
#[test]
fn subnormals_are_zero_in_every_variant() {
    let src = "#version 120
        uniform float us; uniform int ui;
        varying vec4 a, b, c;
        void main() {
            float t = a.y - b.y;
            gl_FragData[0] = vec4(a.x * b.x, t + a.z, mod(b.z, a.w), pow(t, 0.5));
            gl_FragData[1] = vec4(us + a.z, float(ui), 1e-40 * 1e10 + dFdx(b.w) * 1e30, t);
            gl_FragData[2] = vec4(mix(c.x, c.y, 0.5), smoothstep(0.0, 1.0, c.z), c.w, c.w * 1e30);
        }";
    let linked = link_one(Stage::Fragment, src).unwrap();
    let k = Kernel::new(&linked).expect("lowers");
    k.compile_native();
    let min = f32::MIN_POSITIVE;
    let (x0, x1) = (f32::from_bits(0x2000_0800), f32::from_bits(0x1fff_f000));
    // 2^-126 (1 - 2^-24), a tie rounded to even: 2^-126.
    assert_eq!((x0 * x1).to_bits(), min.to_bits());
    let iface = k.interface().clone();
    let mut u = vec![0u32; iface.uniform_words];
    u[iface.uniform("us").unwrap().offset] = 1; // 2^-149
    u[iface.uniform("ui").unwrap().offset] = 1; // the int 1, not a subnormal
    let mut batch = Batch::for_kernel(&k, 0xffff);
    let tiny = f32::from_bits(1);
    let next_up = f32::from_bits(min.to_bits() + 1);
    let inputs = [
        ("a", [x0, next_up, min, 1_073_741_824.0]),
        ("b", [x1, min, -(2f32.powi(-100)), min]),
        ("c", [min, 2.0 * min, 0.8 * 2f32.powi(-63), tiny]),
    ];
    for (name, v) in inputs {
        let off = iface.input(name).unwrap().offset;
        for (k, x) in v.iter().enumerate() {
            batch.inputs[off + k] = [*x; crate::LANES];
        }
    }
    // b.w differs by 2^-149 between the columns of each quad.
    let bw = iface.input("b").unwrap().offset + 3;
    for l in (1..crate::LANES).step_by(2) {
        batch.inputs[bw][l] = next_up;
    }
    let out = iface.output("gl_FragData").unwrap().offset;
    let want: [f32; 12] = [
        min,
        min,
        -(2f32.powi(-100)),
        0.0,
        min,
        1.0,
        0.0,
        0.0,
        min,
        0.0,
        0.0,
        0.0,
    ];
    let mut reference = batch.clone();
    k.run_reference(&mut reference, &u, &NoTextures).unwrap();
    for (i, w) in want.iter().enumerate() {
        assert_eq!(
            reference.outputs[out + i].map(f32::to_bits),
            [w.to_bits(); crate::LANES],
            "reference, output component {i}"
        );
    }
    for v in supported_variants() {
        let mut got = batch.clone();
        k.run_variant(v, &mut got, &u, &NoTextures).unwrap();
        assert_eq!(
            bits_of(&got.outputs),
            bits_of(&reference.outputs),
            "{}",
            v.name()
        );
    }
    if Variant::Jit.supported() {
        assert!(matches!(k.native_code(), Some(Ok(_))));
    }
}

/// Textures whose every answer is a function of the request (its
/// coordinates, level or derivatives, offsets, unit): integer samplers
/// get small integers' bits, which no executor may flush.
struct Encoder;

impl crate::Textures for Encoder {
    fn sample(&self, req: &crate::SampleRequest, out: &mut [[f32; crate::LANES]; 4]) {
        use crate::Lod;
        let integer = req.target.result() != glsl::types::SamplerResult::Float;
        for l in (0..crate::LANES).filter(|l| req.mask & (1 << l) != 0) {
            let lod = match &req.lod {
                Lod::Explicit(v) => v[l],
                Lod::Derivatives { ddx, ddy, bias } => ddx[0][l] - ddy[1][l] + bias[l],
                Lod::Gradients { ddx, ddy } => ddx[0][l] * 3.0 + ddy[1][l] * 5.0 + ddx[2][l],
            };
            let off = req.offset.map_or([0; 3], |o| [o[0][l], o[1][l], o[2][l]]);
            let v = [
                req.coord[0][l] + off[0] as f32 * 10.0,
                req.coord[1][l] + off[1] as f32 * 100.0 + req.coord[2][l],
                lod,
                req.compare.map_or(req.unit[l] as f32, |c| c[l]),
            ];
            for c in 0..4 {
                out[c][l] = if integer {
                    f32::from_bits((v[c] * 8.0) as i32 as u32)
                } else {
                    v[c]
                };
            }
        }
    }

    fn fetch(&self, req: &crate::FetchRequest, out: &mut [[f32; crate::LANES]; 4]) {
        let integer = req.target.result() != glsl::types::SamplerResult::Float;
        for l in (0..crate::LANES).filter(|l| req.mask & (1 << l) != 0) {
            let v = [
                req.coord[0][l],
                req.coord[1][l],
                req.coord[2][l],
                req.lod[l],
            ];
            for c in 0..4 {
                out[c][l] = if integer {
                    f32::from_bits(v[c] as u32)
                } else {
                    v[c] as f32
                };
            }
        }
    }

    fn size(&self, unit: u32, target: glsl::types::SamplerKind, lod: i32) -> [i32; 3] {
        [unit as i32 % 7, lod, target as i32]
    }
}

#[test]
fn glsl130_lookups_are_the_same_in_every_variant() {
    let fragment = "#version 140
        uniform sampler2D s2;
        uniform isampler2D si;
        uniform usampler2DArray su;
        uniform sampler1DArrayShadow sh;
        uniform sampler3D s3;
        uniform sampler2DRect sr;
        in vec4 v;
        out vec4 c0, c1, c2, c3;
        void main() {
            ivec2 p = ivec2(v.xy * 8.0);
            c0 = textureOffset(s2, v.xy, ivec2(1, -2), v.z) + textureGrad(s3, v.xyz, v.yzw, v.wxy);
            c1 = vec4(texelFetch(si, p, 1)) + vec4(texelFetchOffset(su, ivec3(p, 2), 0, ivec2(3, 4)));
            c2 = vec4(textureSize(s3, 2), textureSize(sh, 1).x) + vec4(texture(si, v.xy))
                + vec4(texture(su, v.xyz)) + texture(sr, v.zw * 4.0);
            c3 = vec4(texture(sh, v.xyz), textureLodOffset(s2, v.xy, v.w, ivec2(-1, 1)).xyz)
                + textureProjGradOffset(s2, v.xyz, v.xy, v.zw, ivec2(2, 2))
                + vec4(texelFetch(sr, p).xy, textureSize(sr));
        }";
    let vertex = "#version 130
        uniform sampler2D s2;
        uniform usampler2D su;
        uniform sampler2DArray sa;
        in vec4 v;
        out vec4 c0, c1;
        void main() {
            c0 = textureLod(s2, v.xy, v.z) + texture(sa, v.xyz) + textureOffset(s2, v.xy, ivec2(3, 1));
            c1 = vec4(texelFetch(su, ivec2(v.xy * 16.0), 2)) + vec4(textureSize(sa, 1), 1.0)
                + textureGradOffset(sa, v.xyz, v.xy, v.zw, ivec2(-3, 0));
            gl_Position = v;
        }";
    let variants = supported_variants();
    for (stage, src) in [(Stage::Fragment, fragment), (Stage::Vertex, vertex)] {
        let linked = link_one(stage, src).unwrap_or_else(|e| panic!("{e}"));
        let k = Kernel::new(&linked).expect("lowers");
        let u: Vec<u32> = (0..k.interface().uniform_words)
            .map(|w| w as u32 + 1)
            .collect();
        for round in 0..20u32 {
            let active = if round % 4 == 3 { 0x0ff0 } else { 0xffff };
            let mut base = Batch::for_kernel(&k, active);
            fill(&mut base, round + 7);
            let mut want = base.clone();
            k.run_reference(&mut want, &u, &Encoder).expect("runs");
            // The integer lookups' small values arrive (a flush would
            // make every one 0).
            assert!(want.outputs.iter().flatten().any(|&x| x != 0.0));
            for &v in &variants {
                let mut got = base.clone();
                k.run_variant(v, &mut got, &u, &Encoder).expect("runs");
                assert_eq!(
                    bits_of(&got.outputs),
                    bits_of(&want.outputs),
                    "{stage:?} {} round {round}",
                    v.name()
                );
            }
        }
    }
}

#[test]
fn texture_array_extension_lookups_are_the_glsl130_ones() {
    // GL_EXT_texture_array's names ask the texture unit for what the 1.30
    // lookups of the same sampler ask: the same answers, bit for bit.
    let uniforms = "uniform sampler1DArray s1;
        uniform sampler2DArray s2;
        uniform sampler1DArrayShadow h1;
        uniform sampler2DArrayShadow h2;
        in vec4 v;
        out vec4 c0, c1, c2;";
    let ext = format!(
        "#version 130
        #extension GL_EXT_texture_array : require
        {uniforms}
        void main() {{
            c0 = texture1DArray(s1, v.xy) + texture1DArray(s1, v.yz, v.w) + texture1DArrayLod(s1, v.zw, v.x);
            c1 = texture2DArray(s2, v.xyz) + texture2DArray(s2, v.yzw, v.x) + texture2DArrayLod(s2, v.zwx, v.y);
            c2 = vec4(shadow1DArray(h1, v.xyz).x, shadow1DArray(h1, v.yzw, v.x).x,
                      shadow1DArrayLod(h1, v.zwx, v.y).x, shadow2DArray(h2, v).x);
        }}"
    );
    let core = format!(
        "#version 130
        {uniforms}
        void main() {{
            c0 = texture(s1, v.xy) + texture(s1, v.yz, v.w) + textureLod(s1, v.zw, v.x);
            c1 = texture(s2, v.xyz) + texture(s2, v.yzw, v.x) + textureLod(s2, v.zwx, v.y);
            c2 = vec4(texture(h1, v.xyz), texture(h1, v.yzw, v.x),
                      textureLod(h1, v.zwx, v.y), texture(h2, v));
        }}"
    );
    let run = |src: &str| {
        let linked = link_one(Stage::Fragment, src).unwrap_or_else(|e| panic!("{e}"));
        let k = Kernel::new(&linked).expect("lowers");
        let u: Vec<u32> = (0..k.interface().uniform_words)
            .map(|w| w as u32 + 1)
            .collect();
        let mut b = Batch::for_kernel(&k, 0xffff);
        fill(&mut b, 11);
        k.run_reference(&mut b, &u, &Encoder).expect("runs");
        bits_of(&b.outputs)
    };
    let want = run(&core);
    assert_eq!(run(&ext), want);
}

#[test]
fn shader_texture_lod_gradient_lookups_are_the_glsl130_ones() {
    // GL_ARB_shader_texture_lod's `*GradARB' lookups ask the texture unit
    // for what textureGrad and textureProjGrad ask (the shadow ones return
    // the comparison in every component).
    let uniforms = "uniform sampler1D s1;
        uniform sampler2D s2;
        uniform sampler3D s3;
        uniform samplerCube sc;
        uniform sampler2DShadow h2;
        in vec4 v;
        out vec4 c0, c1, c2;";
    let run = |body: &str, ext: &str| {
        let src = format!("#version 130\n{ext}\n{uniforms}\nvoid main() {{ {body} }}");
        let linked = link_one(Stage::Fragment, &src).unwrap_or_else(|e| panic!("{e}"));
        let k = Kernel::new(&linked).expect("lowers");
        let u: Vec<u32> = (0..k.interface().uniform_words)
            .map(|w| w as u32 + 1)
            .collect();
        let mut b = Batch::for_kernel(&k, 0xffff);
        fill(&mut b, 5);
        k.run_reference(&mut b, &u, &Encoder).expect("runs");
        bits_of(&b.outputs)
    };
    let ext = run(
        "c0 = texture1DGradARB(s1, v.x, v.y, v.z) + texture1DProjGradARB(s1, v, v.y, v.w);
         c1 = texture2DProjGradARB(s2, v.xyz, v.xy, v.zw) + texture3DGradARB(s3, v.xyz, v.yzw, v.wxy)
            + textureCubeGradARB(sc, v.xyz, v.yzw, v.wxy);
         c2 = vec4(shadow2DGradARB(h2, v.xyz, v.xy, v.zw).x, shadow2DProjGradARB(h2, v, v.zw, v.xy).x, 0.0, 0.0);",
        "#extension GL_ARB_shader_texture_lod : require",
    );
    let core = run(
        "c0 = textureGrad(s1, v.x, v.y, v.z) + textureProjGrad(s1, v, v.y, v.w);
         c1 = textureProjGrad(s2, v.xyz, v.xy, v.zw) + textureGrad(s3, v.xyz, v.yzw, v.wxy)
            + textureGrad(sc, v.xyz, v.yzw, v.wxy);
         c2 = vec4(textureGrad(h2, v.xyz, v.xy, v.zw), textureProjGrad(h2, v, v.zw, v.xy), 0.0, 0.0);",
        "",
    );
    assert_eq!(ext, core);
}
