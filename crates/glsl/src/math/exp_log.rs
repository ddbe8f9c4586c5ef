//! `exp`, `exp2`, `log`, `log2` and `pow` for `f32`, computed in `f64` and
//! rounded once.
//!
//! Each function widens its `f32` arguments to `f64` (exact, subnormals
//! included), evaluates a short polynomial there and rounds the result to
//! `f32` with one `as f32`. The `f64` value is within about 2^-43 (relative)
//! of the exact result, so the `f32` result is the correctly rounded one
//! unless the exact value lies that close to a rounding boundary (then it
//! may be the neighbour). Measured (see `math`'s docs): over all 2^32
//! inputs `log2` is always correctly rounded and `exp2`/`log`/`exp` all but
//! 1/2/3 times; `pow` is within 0.50000008 ulp on 200 million pairs.
//!
//! Only IEEE-754 `+ - * /`, comparisons, conversions and integer bit
//! operations are used, each rounded once (Rust never fuses `a * b + c`), so
//! the bits are the same on every CPU and in every instruction-set variant
//! of the executor. There are no branches on the value and no tables: the
//! special cases (zero, infinity, NaN, negative bases) are selects applied
//! after the general path, which is what lets the executor's 16-lane loops
//! over these functions vectorize.
//!
//! ## Method
//! - `2^t`: `t = k + r` with `k` the nearest integer (the `1.5 · 2^52`
//!   shifter, ties to even) and `|r| ≤ 1/2`; `2^r` is its Taylor polynomial
//!   of degree 11 (coefficients `ln(2)^n / n!`, truncation error below
//!   2^-47 relative, evaluated by Estrin's scheme for a short dependency
//!   chain), `2^k` is built in the exponent field. `t` is first
//!   clamped to ±200, past which every `f32` result is 0 or infinity.
//! - `log(a)`: `a = 2^e · m` with `m` in [√½, √2) (integer arithmetic on the
//!   bits, no branch); `ln(m) = 2 atanh(s)`, `s = (m - 1) / (m + 1)`,
//!   `|s| ≤ 0.1716`, by the series `2s (1 + s²/3 + s⁴/5 + …)` to the `s^18`
//!   term (truncation error below 2^-50 relative). `log2 = e + ln(m) · log2(e)`
//!   and `ln = e · ln(2) + ln(m)` have no cancellation: `|ln(m)| ≤ ln(2)/2`.
//! - `pow(x, y) = 2^(y · log2|x|)`: the product is formed in `f64` (exact to
//!   2^-53 relative), so the error of `log2` (about 2^-50 relative) grows to
//!   at most about 2^-42 in the result before the final rounding.

/// `ln(2)^n / n!` for n = 0..=11, each rounded to `f64`.
const EXP2_POLY: [f64; 12] = [
    1.0,
    LN2,
    0.24022650695910072,
    0.05550410866482158,
    0.009618129107628477,
    0.0013333558146428443,
    0.0001540353039338161,
    1.5252733804059841e-05,
    1.321548679014431e-06,
    1.01780860092397e-07,
    7.054911620801123e-09,
    4.4455382718708116e-10,
];

/// `1 / (2k + 1)` for k = 0..=9.
const ATANH_POLY: [f64; 10] = [
    1.0,
    1.0 / 3.0,
    1.0 / 5.0,
    1.0 / 7.0,
    1.0 / 9.0,
    1.0 / 11.0,
    1.0 / 13.0,
    1.0 / 15.0,
    1.0 / 17.0,
    1.0 / 19.0,
];

const LN2: f64 = core::f64::consts::LN_2;
const LOG2_E: f64 = core::f64::consts::LOG2_E;

/// `2^t` in `f64` for any `t` (NaN gives NaN); accurate to about 2^-47
/// relative where the result is an `f32` normal or subnormal.
#[inline(always)]
pub(crate) fn exp2_f64(t: f64) -> f64 {
    // Past ±200 every f32 result is 0 or infinity; the clamp keeps 2^k
    // inside f64's range. NaN fails both comparisons and stays NaN.
    let t = if t > 200.0 { 200.0 } else { t };
    let t = if t < -200.0 { -200.0 } else { t };
    // 1.5 · 2^52: adding it rounds t to an integer (ties to even) held in
    // the low mantissa bits.
    const SHIFT: f64 = 6_755_399_441_055_744.0;
    let shifted = t + SHIFT;
    let k = shifted - SHIFT;
    let r = t - k; // exact, |r| <= 1/2
                   // Estrin's scheme: four dependent steps instead of Horner's eleven.
    let c = &EXP2_POLY;
    let r2 = r * r;
    let r4 = r2 * r2;
    let r8 = r4 * r4;
    let q0 = c[0] + c[1] * r;
    let q1 = c[2] + c[3] * r;
    let q2 = c[4] + c[5] * r;
    let q3 = c[6] + c[7] * r;
    let q4 = c[8] + c[9] * r;
    let q5 = c[10] + c[11] * r;
    let p = (q0 + q1 * r2) + (q2 + q3 * r2) * r4 + (q4 + q5 * r2) * r8;
    // The low bits of `shifted` are 2^51 + k; adding 1023 and keeping 12
    // bits gives the biased exponent of 2^k (k + 1023 in [823, 1223]).
    let scale = f64::from_bits(shifted.to_bits().wrapping_add(1023) << 52);
    p * scale
}

/// `(e, ln(m))` with `a = 2^e · m`, `m` in [√½, √2), for a positive finite
/// `a` (any other input gives finite garbage, which the callers replace).
#[inline(always)]
fn log_parts(a: f64) -> (f64, f64) {
    // Subtracting the bits of √½ moves the exponent boundary from 1 to √½;
    // adding 1023 << 52 keeps the shifted exponent positive for every
    // positive `f64` that is a widened `f32`.
    const BIAS: u64 = (1023u64 << 52).wrapping_sub(0x3fe6_a09e_667f_3bcd);
    let ix = a.to_bits();
    let eb = ix.wrapping_add(BIAS) >> 52; // e + 1023
    let m = f64::from_bits(ix.wrapping_sub(eb << 52).wrapping_add(1023u64 << 52));
    // e exactly, as f64, without an integer-to-float conversion.
    let e = f64::from_bits(0x4330_0000_0000_0000 | eb) - (4_503_599_627_370_496.0 + 1023.0);
    let s = (m - 1.0) / (m + 1.0);
    let z = s * s;
    // Estrin's scheme, as in exp2_f64.
    let c = &ATANH_POLY;
    let z2 = z * z;
    let z4 = z2 * z2;
    let z8 = z4 * z4;
    let q0 = c[0] + c[1] * z;
    let q1 = c[2] + c[3] * z;
    let q2 = c[4] + c[5] * z;
    let q3 = c[6] + c[7] * z;
    let q4 = c[8] + c[9] * z;
    let p = (q0 + q1 * z2) + (q2 + q3 * z2) * z4 + q4 * z8;
    (e, 2.0 * s * p)
}

/// `log2(a)` in `f64` for `a >= 0` (a widened `f32`): -inf for 0, inf for
/// inf, NaN for NaN.
#[inline(always)]
fn log2_nonneg(a: f64) -> f64 {
    let (e, ln_m) = log_parts(a);
    let r = e + ln_m * LOG2_E;
    let r = if a == 0.0 { f64::NEG_INFINITY } else { r };
    let r = if a == f64::INFINITY { a } else { r };
    if a.is_nan() {
        a
    } else {
        r
    }
}

/// The `log`/`log2` special cases for `x`, else `r`: NaN for x < 0 or NaN,
/// -inf for ±0, inf for inf.
#[inline(always)]
fn log_special(x: f32, r: f32) -> f32 {
    let r = if x < 0.0 { f32::NAN } else { r };
    let r = if x == 0.0 { f32::NEG_INFINITY } else { r };
    let r = if x == f32::INFINITY { x } else { r };
    if x.is_nan() {
        x
    } else {
        r
    }
}

/// `2^x`.
#[inline(always)]
pub fn exp2(x: f32) -> f32 {
    exp2_f64(x as f64) as f32
}

/// `e^x`.
#[inline(always)]
pub fn exp(x: f32) -> f32 {
    exp2_f64(x as f64 * LOG2_E) as f32
}

/// Base-2 logarithm; NaN for x < 0, -inf for ±0.
#[inline(always)]
pub fn log2(x: f32) -> f32 {
    let (e, ln_m) = log_parts(x as f64);
    log_special(x, (e + ln_m * LOG2_E) as f32)
}

/// Natural logarithm; NaN for x < 0, -inf for ±0.
#[inline(always)]
pub fn log(x: f32) -> f32 {
    let (e, ln_m) = log_parts(x as f64);
    log_special(x, (e * LN2 + ln_m) as f32)
}

/// `x` raised to `y`, with C's `powf` results for the special cases
/// (GLSL leaves x < 0, and x = 0 with y <= 0, undefined; we make them
/// repeatable): `pow(x, ±0) = 1` and `pow(1, y) = 1` even for NaN; a
/// negative base gives NaN unless `y` is an integer (then the sign follows
/// `y`'s parity); `pow(±0, y < 0) = ±inf`; `pow(-1, ±inf) = 1`.
#[inline(always)]
pub fn pow(x: f32, y: f32) -> f32 {
    let ax = f32::from_bits(x.to_bits() & 0x7fff_ffff);
    // 0 · inf (y = 0 with x = 0 or inf, or |x| = 1 with y = inf) gives NaN
    // here; the selects below replace those.
    let r = exp2_f64(y as f64 * log2_nonneg(ax as f64)) as f32;
    // Whether y is an integer, and an odd one, from its bits: with
    // exponent e, the bits below 2^0 are the low 23 - e mantissa bits
    // (none when e >= 23, every bit when e < 0).
    let yb = y.to_bits();
    let e = ((yb >> 23) & 0xff) as i32 - 127;
    let sh = e.clamp(0, 23) as u32;
    let frac = 0x007f_ffff_u32 >> sh;
    let is_int = (e >= 0) & (yb & frac == 0) | (y == 0.0);
    // The units bit: mantissa bit 23 - e, or for e = 0 the implicit one.
    let units = (yb | 0x0080_0000) >> (23 - sh) & 1 == 1;
    let is_odd = is_int & (0..=23).contains(&e) & units;
    let r = if x.is_sign_negative() & is_odd { -r } else { r };
    let r = if (x < 0.0) & (ax != f32::INFINITY) & !is_int {
        f32::NAN
    } else {
        r
    };
    let one = (y == 0.0) | (x == 1.0) | ((x == -1.0) & (y.abs() == f32::INFINITY));
    // A NaN result is the canonical quiet NaN: with two NaN operands an
    // `f64` product carries the payload of whichever the compiled code
    // put first, which differs between builds and instruction sets.
    if one {
        1.0
    } else if r.is_nan() {
        f32::NAN
    } else {
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Distance in `f32` ulps (of the exact result's binade) between `got`
    /// and the reference `want` (from `libm`'s `f64` routines, within an
    /// `f64` ulp of exact); equal values, both NaN, or the same infinity
    /// are 0.
    fn ulps(got: f32, want: f64) -> f64 {
        if got as f64 == want || (got.is_nan() && want.is_nan()) || got == want as f32 {
            return 0.0;
        }
        if got.is_nan() || want.is_nan() || want.is_infinite() {
            return f64::INFINITY;
        }
        let binade = ((want.to_bits() >> 52) & 0x7ff) as i32 - 1023;
        let ulp = 2f64.powi(binade.max(-126) - 23);
        (got as f64 - want).abs() / ulp
    }

    /// Worst error and how many results differ from the reference rounded
    /// to `f32` (the correctly rounded result, up to double rounding).
    #[derive(Default, Debug)]
    struct Stats {
        worst: f64,
        worst_at: (f32, f32),
        misrounded: u64,
        count: u64,
    }

    impl Stats {
        fn add(&mut self, x: f32, y: f32, got: f32, want: f64) {
            let u = ulps(got, want);
            if u > self.worst {
                self.worst = u;
                self.worst_at = (x, y);
            }
            self.misrounded += (u != 0.0) as u64;
            self.count += 1;
        }
        fn merge(&mut self, o: Stats) {
            if o.worst > self.worst {
                self.worst = o.worst;
                self.worst_at = o.worst_at;
            }
            self.misrounded += o.misrounded;
            self.count += o.count;
        }
    }

    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }
        fn unit(&mut self) -> f32 {
            (self.next() >> 40) as f32 / (1u64 << 24) as f32
        }
    }

    type Unary = (&'static str, fn(f32) -> f32, fn(f64) -> f64);
    const UNARY: [Unary; 4] = [
        ("exp", exp, libm::exp),
        ("exp2", exp2, libm::exp2),
        ("log", log, libm::log),
        ("log2", log2, libm::log2),
    ];

    /// Every `step`-th `f32` bit pattern from `start`.
    fn sweep(f: fn(f32) -> f32, reference: fn(f64) -> f64, start: u64, step: u64) -> Stats {
        let mut s = Stats::default();
        let mut b = start;
        while b <= u32::MAX as u64 {
            let x = f32::from_bits(b as u32);
            s.add(x, 0.0, f(x), reference(x as f64));
            b += step;
        }
        s
    }

    #[test]
    fn unary_within_one_ulp_over_sampled_floats() {
        // ~520,000 bit patterns spread over all of f32 (every binade, both
        // signs, subnormals, inf and NaN) per function.
        for (name, f, reference) in UNARY {
            let s = sweep(f, reference, 3, 8191);
            assert!(s.worst <= 1.0, "{name}: {s:?}");
            // Correctly rounded but for near-ties: at most 1 in 10,000.
            assert!(s.misrounded * 10_000 <= s.count, "{name}: {s:?}");
        }
    }

    /// Bases over every binade, exponents scaled so the results cover the
    /// whole `f32` range (and past it), plus random bit patterns.
    fn pow_samples(rng: &mut Rng, n: usize) -> Stats {
        let mut s = Stats::default();
        for i in 0..n {
            let x = f32::from_bits((rng.next() >> 33) as u32); // non-negative, any
            let y = match i % 4 {
                0 => f32::from_bits((rng.next() >> 32) as u32),
                1 => (rng.unit() - 0.5) * 64.0,
                _ => {
                    let l = (x as f64).log2().abs().max(1e-3) as f32;
                    (rng.unit() - 0.5) * 320.0 / l
                }
            };
            s.add(x, y, pow(x, y), libm::pow(x as f64, y as f64));
            // Negative bases with integer exponents.
            let yi = y.round().clamp(-300.0, 300.0);
            s.add(-x, yi, pow(-x, yi), libm::pow(-x as f64, yi as f64));
        }
        s
    }

    #[test]
    fn pow_within_one_ulp_over_sampled_pairs() {
        let s = pow_samples(&mut Rng(0x9e37_79b9_7f4a_7c15), 150_000);
        assert!(s.worst <= 1.0, "pow: {s:?}");
        assert!(s.misrounded * 10_000 <= s.count, "pow: {s:?}");
    }

    const SPECIALS: [f32; 30] = [
        0.0,
        -0.0,
        1.0,
        -1.0,
        0.5,
        -0.5,
        2.0,
        -2.0,
        3.0,
        -3.0,
        2.5,
        -2.5,
        0.3,
        1e-45,
        -1e-45,
        1.1754942e-38,
        f32::MIN_POSITIVE,
        f32::MAX,
        f32::MIN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        16_777_215.0,
        16_777_216.0,
        -16_777_217.0,
        8_388_609.0,
        -8_388_609.0,
        1.0000001,
        0.99999994,
        -150.0,
    ];

    /// The IEEE/C special cases, checked against `libm`'s `f32` routines
    /// (C semantics) on every pairing of special values: the same bits, NaN
    /// where they give NaN; where the result is an ordinary number, within
    /// an ulp of the `f64` reference instead.
    #[test]
    fn special_cases_match_c_semantics() {
        let ok = |got: f32, c: f32, exact: f64| {
            got.to_bits() == c.to_bits()
                || (got.is_nan() && c.is_nan())
                || (c.is_finite() && got.is_finite() && ulps(got, exact) <= 1.0)
        };
        type Case = (&'static str, fn(f32) -> f32, fn(f32) -> f32, fn(f64) -> f64);
        let unary: [Case; 4] = [
            ("exp", exp, libm::expf, libm::exp),
            ("exp2", exp2, libm::exp2f, libm::exp2),
            ("log", log, libm::logf, libm::log),
            ("log2", log2, libm::log2f, libm::log2),
        ];
        for x in SPECIALS {
            for (name, f, c, exact) in unary {
                assert!(
                    ok(f(x), c(x), exact(x as f64)),
                    "{name}({x:e}) = {:e}",
                    f(x)
                );
            }
            for y in SPECIALS {
                let (got, c) = (pow(x, y), libm::powf(x, y));
                let exact = libm::pow(x as f64, y as f64);
                assert!(
                    ok(got, c, exact),
                    "pow({x:e}, {y:e}) = {got:e}, C gives {c:e}"
                );
            }
        }
        assert_eq!(pow(0.0, 0.0), 1.0);
        assert_eq!(pow(f32::NAN, 0.0), 1.0);
        assert_eq!(pow(1.0, f32::NAN), 1.0);
        assert_eq!(pow(-1.0, f32::INFINITY), 1.0);
        assert_eq!(pow(-0.0, -3.0), f32::NEG_INFINITY);
        assert_eq!(pow(-0.0, 3.0).to_bits(), (-0.0f32).to_bits());
        assert_eq!(pow(-2.0, 3.0), -8.0);
        assert!(pow(-8.0, 1.0 / 3.0).is_nan());
        assert_eq!(log2(-0.0), f32::NEG_INFINITY);
        assert!(log(-1e-45).is_nan());
        // Subnormal inputs are exact in f64: no flush inside.
        assert_eq!(log2(1e-45), -149.0);
        assert_eq!(exp2(-149.0), 1e-45);
        assert_eq!(pow(2.0, -149.0), 1e-45);
        // NaN results are the canonical NaN, whatever the operands' payloads
        // (which one an f64 product would carry depends on the build).
        let (a, b) = (f32::from_bits(0xffff_fffd), f32::from_bits(0x7fc0_1234));
        for (x, y) in [(a, b), (b, a), (a, 2.5), (2.5, b), (-2.0, 0.5)] {
            assert_eq!(pow(x, y).to_bits(), f32::NAN.to_bits(), "pow({x}, {y})");
        }
    }

    #[test]
    fn exact_cases_are_exact() {
        for k in -149..=127 {
            let p = f32::from_bits(if k >= -126 {
                ((k + 127) as u32) << 23
            } else {
                1 << (k + 149)
            });
            assert_eq!(exp2(k as f32), p, "exp2({k})");
            assert_eq!(log2(p), k as f32, "log2(2^{k})");
            assert_eq!(pow(2.0, k as f32), p, "pow(2, {k})");
        }
        for x in [0.1f32, 3.0, 7.5, 1e20, 1e-20] {
            assert_eq!(pow(x, 1.0), x);
        }
        assert_eq!(exp(0.0), 1.0);
        assert_eq!(log(1.0), 0.0);
        assert_eq!(pow(3.0, 4.0), 81.0);
        assert_eq!(pow(10.0, 10.0), 1e10);
    }

    /// ns per call, scalar (each input through `black_box`, as in the
    /// texture unit's LOD) and over arrays of 16 (as the executor calls
    /// them), against `libm`'s `f32` routines: `cargo test --release -p
    /// shaderbox-glsl bench_exp_log -- --ignored --nocapture`.
    #[test]
    #[ignore = "benchmark"]
    fn bench_exp_log() {
        use std::hint::black_box;
        let mut rng = Rng(7);
        let xs: Vec<[f32; 16]> = (0..4096)
            .map(|_| core::array::from_fn(|_| rng.unit() * 8.0 + 0.01))
            .collect();
        fn time(name: &str, xs: &[[f32; 16]], f: impl Fn(f32, f32) -> f32) {
            let mut best = [f64::MAX; 2];
            for _ in 0..5 {
                let t = std::time::Instant::now();
                let mut acc = 0.0f32;
                for v in xs {
                    for &x in v {
                        acc += f(black_box(x), black_box(0.7));
                    }
                }
                black_box(acc);
                best[0] = best[0].min(t.elapsed().as_secs_f64());
                let t = std::time::Instant::now();
                let mut out = [0f32; 16];
                for v in xs {
                    for (o, &x) in out.iter_mut().zip(v) {
                        *o = f(x, 0.7);
                    }
                    black_box(&out);
                }
                best[1] = best[1].min(t.elapsed().as_secs_f64());
            }
            let n = (xs.len() * 16) as f64;
            println!(
                "{name:12} scalar {:5.1} ns, 16-lane loop {:5.1} ns per call",
                best[0] / n * 1e9,
                best[1] / n * 1e9
            );
        }
        time("pow", &xs, pow);
        time("libm powf", &xs, libm::powf);
        time("exp2", &xs, |x, _| exp2(x));
        time("libm exp2f", &xs, |x, _| libm::exp2f(x));
        time("exp", &xs, |x, _| exp(x));
        time("libm expf", &xs, |x, _| libm::expf(x));
        time("log2", &xs, |x, _| log2(x));
        time("libm log2f", &xs, |x, _| libm::log2f(x));
        time("log", &xs, |x, _| log(x));
        time("libm logf", &xs, |x, _| libm::logf(x));
    }

    /// Every `f32` for the unary functions and 200 million `pow` pairs, on
    /// two threads: `cargo test --release -p shaderbox-glsl exhaustive --
    /// --ignored --nocapture` (about 10 CPU-minutes).
    #[test]
    #[ignore]
    fn exhaustive() {
        for (name, f, reference) in UNARY {
            let mut s = Stats::default();
            std::thread::scope(|sc| {
                let h: Vec<_> = (0..2)
                    .map(|t| sc.spawn(move || sweep(f, reference, t, 2)))
                    .collect();
                for h in h {
                    s.merge(h.join().unwrap());
                }
            });
            println!("{name}: {s:?}");
            assert!(s.worst <= 1.0, "{name}: {s:?}");
        }
        let mut s = Stats::default();
        std::thread::scope(|sc| {
            let h: Vec<_> = (1..=2)
                .map(|t| {
                    sc.spawn(move || pow_samples(&mut Rng(t * 0x2545_f491_4f6c_dd1d), 50_000_000))
                })
                .collect();
            for h in h {
                s.merge(h.join().unwrap());
            }
        });
        println!("pow: {s:?}");
        assert!(s.worst <= 1.0, "pow: {s:?}");
    }
}
