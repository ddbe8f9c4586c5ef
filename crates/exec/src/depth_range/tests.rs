//! The bound holds what the kernels compute: the sphere programs' depth
//! slices run on pixels of random regions, every depth they write inside
//! [`DepthRange::eval`]'s range, and the range close to the depths (else
//! it rejects nothing).

use super::*;
use crate::{Batch, NoTextures, LANES};
use glsl::ir::Stage;

/// A fixed pseudo-random sequence (xorshift64*), floats in `[lo, hi)`.
struct Rng(u64);

impl Rng {
    fn next(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let x = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11;
        lo + (hi - lo) * (x as f64 / (1u64 << 53) as f64)
    }
}

fn root() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The depth-only slice of a fragment shader file (GLSL 1.20).
fn slice_of(path: &str) -> Kernel {
    let text = std::fs::read_to_string(root().join(path)).expect("shader file");
    let src = format!("#version 120\n{text}");
    let sh = glsl::compile(&[&src], &glsl::CompileOptions::new(Stage::Fragment));
    assert!(sh.ok(), "{}", sh.info_log());
    let program = glsl::link::link(&[&sh]);
    assert!(program.ok(), "{}", program.info_log());
    let stage = program.stage(Stage::Fragment).expect("fragment stage");
    Kernel::new(stage)
        .expect("kernel")
        .depth_only()
        .expect("a depth slice")
}

/// Sets the uniform `path` (a float or the components of a vector or
/// matrix) in `words`.
fn set(k: &Kernel, words: &mut [u32], path: &str, values: &[f32]) {
    let Some((at, _)) = k.interface.locate_uniform(path) else {
        return;
    };
    for (i, v) in values.iter().enumerate() {
        words[at + i] = v.to_bits();
    }
}

/// A camera: the projection (column-major) and whether it is perspective.
fn projection(perspective: bool) -> [f32; 16] {
    let (n, f) = (40.0f32, 160.0f32);
    match perspective {
        true => [
            2.0,
            0.0,
            0.0,
            0.0,
            0.0,
            2.0,
            0.0,
            0.0,
            0.0,
            0.0,
            -(f + n) / (f - n),
            -1.0,
            0.0,
            0.0,
            -2.0 * f * n / (f - n),
            0.0,
        ],
        false => [
            0.05,
            0.0,
            0.0,
            0.0,
            0.0,
            0.05,
            0.0,
            0.0,
            0.0,
            0.0,
            -2.0 / (f - n),
            0.0,
            0.0,
            0.0,
            -(f + n) / (f - n),
            1.0,
        ],
    }
}

/// One impostor as the seed's vertex shader sets it up, over a region of
/// `size` pixels of its quad: each input component's value at the
/// region's centre and its steps along `u` and `v` (the region's
/// half-widths), as interpolation gives them.
fn sphere_inputs(rng: &mut Rng, perspective: bool, k: &Kernel) -> Vec<(usize, [f64; 3])> {
    let centre = [
        rng.next(-20.0, 20.0),
        rng.next(-20.0, 20.0),
        rng.next(-130.0, -70.0),
    ];
    let r = rng.next(1.0, 2.0);
    // The region: a part of the quad (from a whole quad to a few pixels),
    // in the quad's plane: point = centre + r·(a + s·u, b + t·v).
    let s = rng.next(0.05, 1.0);
    let (a, b) = (rng.next(-1.0 + s, 1.0 - s), rng.next(-1.0 + s, 1.0 - s));
    let point = |u: f64, v: f64| {
        [
            centre[0] + r * (a + s * u),
            centre[1] + r * (b + s * v),
            centre[2],
        ]
    };
    let norm = |p: [f64; 3]| {
        let l = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
        [p[0] / l, p[1] / l, p[2] / l]
    };
    let mut out = Vec::new();
    let mut put = |name: &str, f: &dyn Fn(f64, f64) -> Vec<f64>| {
        if let Some(slot) = k.interface.inputs.iter().find(|s| s.name == name) {
            let (c, du, dv) = (f(0.0, 0.0), f(1.0, 0.0), f(0.0, 1.0));
            for i in 0..c.len() {
                out.push((slot.offset + i, [c[i], du[i] - c[i], dv[i] - c[i]]));
            }
        }
    };
    put("sphere_center", &|_, _| centre.to_vec());
    put("radius2", &|_, _| vec![r * r]);
    put("point", &|u, v| point(u, v).to_vec());
    // The corners' view directions interpolated (affine over the quad).
    let p0 = point(0.0, 0.0);
    let (pu, pv) = (norm(point(1.0, 0.0)), norm(point(0.0, 1.0)));
    let n0 = norm(p0);
    put("view_direction", &|u, v| {
        (0..3)
            .map(|i| n0[i] + (pu[i] - n0[i]) * u + (pv[i] - n0[i]) * v)
            .collect()
    });
    // The same part of the sphere's square on the screen (a 1024² viewport,
    // the projections of `projection`), for programs casting the ray from
    // gl_FragCoord.
    let (k, w) = match perspective {
        true => (2.0, -centre[2]),
        false => (0.05, 1.0),
    };
    let pixel = |x: f64| (k * x / w + 1.0) * 512.0;
    let (px, py, pr) = (pixel(centre[0]), pixel(centre[1]), k * r / w * 512.0);
    put("gl_FragCoord", &|u, v| {
        vec![px + pr * (a + s * u), py + pr * (b + s * v), 0.5, 1.0]
    });
    out
}

/// Runs `k` on the pixels `(u, v)` with the inputs `forms` (affine, as
/// f32 the nearest), returning each non-discarded pixel's depth.
fn depths(
    k: &Kernel,
    words: &[u32],
    forms: &[(usize, [f64; 3])],
    pixels: &[(f64, f64)],
) -> Vec<f32> {
    let out = k
        .interface
        .output("gl_FragDepth")
        .expect("gl_FragDepth")
        .offset;
    let mut got = Vec::new();
    for chunk in pixels.chunks(LANES) {
        let mut batch = Batch::for_kernel(k, (1 << chunk.len()) - 1);
        for &(c, [v0, du, dv]) in forms {
            for (l, &(u, v)) in chunk.iter().enumerate() {
                batch.inputs[c][l] = (v0 + du * u + dv * v) as f32;
            }
        }
        k.run(&mut batch, words, &NoTextures).expect("run");
        for l in 0..chunk.len() {
            if batch.discarded & (1 << l) == 0 {
                got.push(batch.outputs[out][l]);
            }
        }
    }
    got
}

/// For random spheres and regions of the seed's impostors: every depth
/// written lies in the range, and the range's near end is within
/// `slack` of the nearest depth written (in window z).
fn check(path: &str, perspective: bool, slack: f64) {
    let k = slice_of(path);
    let mut words = vec![0u32; k.interface.uniform_words];
    set(&k, &mut words, "perspective", &[perspective as u32 as f32]);
    set(
        &k,
        &mut words,
        "gl_ProjectionMatrix",
        &projection(perspective),
    );
    set(&k, &mut words, "gl_DepthRange.near", &[0.0]);
    set(&k, &mut words, "gl_DepthRange.far", &[1.0]);
    set(&k, &mut words, "gl_DepthRange.diff", &[1.0]);
    set(&k, &mut words, "viewport", &[0.0, 0.0, 1024.0, 1024.0]);
    let range = k.depth_range(&words).expect("a bound for the sphere slice");
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut scratch = RangeScratch::default();
    let mut bounded = 0;
    for _ in 0..200 {
        let forms = sphere_inputs(&mut rng, perspective, &k);
        let mut input = |c: usize| {
            let &(_, [v0, du, dv]) = forms.iter().find(|f| f.0 == c)?;
            let mag = v0.abs() + du.abs() + dv.abs();
            Some(Affine::new(v0, du, dv, mag * F32_REL))
        };
        let Some((lo, hi)) = range.eval(&mut scratch, &mut input) else {
            continue;
        };
        bounded += 1;
        let grid: Vec<(f64, f64)> = (0..33 * 33)
            .map(|i| ((i % 33) as f64 / 16.0 - 1.0, (i / 33) as f64 / 16.0 - 1.0))
            .collect();
        let got = depths(&k, &words, &forms, &grid);
        for &z in &got {
            assert!(lo <= z && z <= hi, "{path}: depth {z} outside [{lo}, {hi}]");
        }
        if let Some(near) = got.iter().copied().reduce(f32::min) {
            let gap = near as f64 - lo as f64;
            assert!(
                gap <= slack,
                "{path}: range starts {gap} before the nearest depth {near}"
            );
        }
    }
    assert!(
        bounded >= 190,
        "{path}: only {bounded} of 200 regions bounded"
    );
}

#[test]
fn the_library_spheres_depths_lie_in_the_range() {
    // The ray from gl_FragCoord and the projection: tight in both.
    check("shaders/sphere.frag", false, 0.012);
    check("shaders/sphere.frag", true, 0.025);
}

#[test]
fn the_seed_spheres_depths_lie_in_the_range_orthographic() {
    // Window z is eye z over 120: 0.012 is 1.4 units (the radii are 1-2).
    check("crates/glsl/tests/seeds/000-sphere.frag", false, 0.012);
}

#[test]
fn the_seed_spheres_depths_lie_in_the_range_perspective() {
    // Window z moves about 0.005 per eye unit at these distances: 0.025
    // is about 5 units, a few radii.
    check("crates/glsl/tests/seeds/000-sphere.frag", true, 0.025);
}

#[test]
#[ignore]
fn bench_eval() {
    let k = slice_of("crates/glsl/tests/seeds/000-sphere.frag");
    let mut words = vec![0u32; k.interface.uniform_words];
    set(&k, &mut words, "gl_ProjectionMatrix", &projection(false));
    let range = k.depth_range(&words).unwrap();
    let mut rng = Rng(7);
    let forms = sphere_inputs(&mut rng, false, &k);
    let mut scratch = RangeScratch::default();
    let t = std::time::Instant::now();
    let n = 400000;
    let mut ok = 0;
    for _ in 0..n {
        let mut input = |c: usize| {
            let &(_, [v0, du, dv]) = forms.iter().find(|f| f.0 == c)?;
            Some(Affine::new(v0, du, dv, 1e-6))
        };
        ok += range.eval(&mut scratch, &mut input).is_some() as usize;
    }
    eprintln!(
        "{} ns per eval, {ok} bounded, {} steps",
        t.elapsed().as_nanos() / n,
        range.steps.len()
    );
}

/// Whether the form holds `v` at `(u, v)` of the region.
fn holds(f: &Affine, (u, w): (f64, f64), v: f32) -> bool {
    let at = f.c + f.gx * u + f.gy * w;
    (v as f64 - at).abs() <= f.err && v as f64 >= f.lo
}

/// A random form and a value it holds at `(u, v)`: affine parts of
/// magnitudes from 1e-3 to 1e3, sometimes exact or constant.
fn random_form(rng: &mut Rng, p: (f64, f64)) -> (Affine, f32) {
    let scale = 10f64.powf(rng.next(-3.0, 3.0));
    let c = rng.next(-1.0, 1.0) * scale;
    let kind = rng.next(0.0, 1.0);
    if kind < 0.15 {
        let v = c as f32;
        return (Affine::exact(v), glsl::math::flush_denormal(v));
    }
    let (gx, gy) = match kind < 0.3 {
        true => (0.0, 0.0),
        false => (rng.next(-1.0, 1.0) * scale, rng.next(-1.0, 1.0) * scale),
    };
    let err = rng.next(0.0, 0.1) * scale;
    let exact = c + gx * p.0 + gy * p.1 + rng.next(-1.0, 1.0) * err;
    let v = exact as f32;
    // The f32 nearest may lie just outside: widen by its rounding.
    let err = err + (v as f64 - exact).abs();
    (Affine::new(c, gx, gy, err), v)
}

#[test]
fn every_op_holds_the_executors_value() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    let mut checked = 0;
    for _ in 0..20000 {
        let p = (rng.next(-1.0, 1.0), rng.next(-1.0, 1.0));
        let (a, x) = random_form(&mut rng, p);
        let (b, y) = random_form(&mut rng, p);
        let (t, z) = random_form(&mut rng, p);
        let f = flush_denormal;
        let cases: [(Option<Affine>, f32); 9] = [
            (apply(&[a], &[], 1, Fun::Mul(0, 0)), f(x * x)),
            (fadd(a, b), f(x + y)),
            (fadd(a, b.neg()), f(x - y)),
            (fmul(a, b), f(x * y)),
            (fdiv(a, b), f(x / y)),
            (fsqrt(a), f(glsl::math::sqrt(x))),
            (apply_mix(a, b, t), glsl::math::mix(x, y, z)),
            (fmin(a, b), glsl::math::min(x, y)),
            (fabs(a), x.abs()),
        ];
        for (i, (form, want)) in cases.into_iter().enumerate() {
            if let Some(form) = form {
                checked += 1;
                assert!(
                    holds(&form, p, want),
                    "op {i}: {want} outside {form:?} at {p:?} (a {a:?} = {x}, b {b:?} = {y})"
                );
            }
        }
    }
    assert!(checked > 100_000, "{checked} results checked");
}

/// `mix` as the analysis computes it ([`apply`]'s `Fun::Mix`).
fn apply_mix(a: Affine, b: Affine, t: Affine) -> Option<Affine> {
    let regs = [a, b, t];
    apply(&regs, &[], 3, Fun::Mix(0, 1, 2))
}
