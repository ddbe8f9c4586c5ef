//! Deterministic scalar math for GLSL's built-in functions.
//!
//! Constant folding, the reference interpreter and the fast executor all
//! evaluate built-ins with these functions, so a shader computes
//! bit-identical values on every machine, folded or executed. Nothing here
//! calls the platform's C math library (which is what `f32::sin` and
//! friends do): `exp`, `exp2`, `log`, `log2` and `pow` are the project's
//! own ([`exp_log`]: `f64` polynomials rounded once, branch-free so the
//! executor's lane loops vectorize), the other transcendental functions
//! come from the pure-Rust [`libm`] crate, everything else is IEEE-754
//! `f32` arithmetic, which Rust performs without excess precision or fused
//! multiply-adds.
//!
//! ## Accuracy
//! - `sqrt`, `floor`, `ceil`, `abs`, `sign`, `min`, `max`, `clamp`, `step`
//!   are exact (correctly rounded where rounding applies).
//! - `exp`, `exp2`, `log`, `log2`: the correctly rounded `f32` for all
//!   but a handful of the 2^32 inputs (`log2`: none; `exp2`: 1; `log`: 2;
//!   `exp`: 3), those off by at most 0.50000005 ulp (a near-tie rounded the
//!   other way). Checked on every `f32` input against `libm`'s `f64`
//!   routines (the ignored test `exp_log::tests::exhaustive`, about 14
//!   minutes on 2 busy cores); the default
//!   tests check ~520,000 inputs spread over every binade, and the special
//!   cases against C's `expf`/`logf`.
//! - `pow`: at most 0.50000008 ulp from the exact result (116 of the 200
//!   million checked pairs are not the correctly rounded `f32`): the
//!   exhaustive test's 100 million positive bases over every binade with
//!   exponents spanning the whole result range, and 100 million negative
//!   bases with integer exponents, against `libm::pow` in `f64`. The
//!   special cases (zeros, infinities, NaN, negative bases, `pow(0, 0)`,
//!   `pow(x, 0)`, `pow(1, y)`, subnormal inputs) give C's `powf` results;
//!   a NaN result is always the canonical quiet NaN (`0x7fc00000`), since
//!   which of two NaN operands' payloads a product carries depends on how
//!   the compiler ordered it.
//! - `sin`, `cos`, `tan`, `asin`, `acos`, `atan`, `atan2` are libm's
//!   single-precision routines (ports of musl): at most 1 ulp from the
//!   exact result (checked against libm's `f64` routines by a test below).
//! - All of these are far inside what GLSL asks (1.20 sets no bound; the
//!   GLSL 4.x bounds are 3 ulp for `exp`/`log`, `2 + 2|x|` ulp for `pow`).
//!   Subnormal inputs are used as they are here; the executor and the
//!   constant folder never pass one (float literals, inputs, uniforms and
//!   every result are flushed: [`flush_denormal`]).
//! - The composite functions (`radians`, `degrees`, `inversesqrt`, `fract`,
//!   `modulo`, `mix`, `smoothstep`) are evaluated exactly as the formulas in
//!   their doc comments, one rounding per operation, and the intermediates
//!   that can be subnormal flushed, so each is the sequence of flushed
//!   operations native code runs with subnormal operands read as zero.
//! - Results outside a function's domain (`log(-1)`, `sqrt(-1)`,
//!   `asin(2)`) are NaN; GLSL leaves them undefined, we make them
//!   repeatable.

pub mod exp_log;
pub mod matrix;
pub mod noise;
pub mod pack;

pub use exp_log::{exp, exp2, log, log2, pow};
pub use noise::{noise1, noise2, noise3, noise4};

/// π rounded to `f32`.
pub const PI: f32 = core::f32::consts::PI;

/// `radians(d) = d · (π / 180)` (GLSL 1.20 §8.1).
pub fn radians(degrees: f32) -> f32 {
    degrees * (PI / 180.0)
}

/// `degrees(r) = r · (180 / π)` (GLSL 1.20 §8.1).
pub fn degrees(radians: f32) -> f32 {
    radians * (180.0 / PI)
}

pub fn sin(x: f32) -> f32 {
    libm::sinf(x)
}

pub fn cos(x: f32) -> f32 {
    libm::cosf(x)
}

pub fn tan(x: f32) -> f32 {
    libm::tanf(x)
}

/// Arc sine in [-π/2, π/2]; NaN when |x| > 1.
pub fn asin(x: f32) -> f32 {
    libm::asinf(x)
}

/// Arc cosine in [0, π]; NaN when |x| > 1.
pub fn acos(x: f32) -> f32 {
    libm::acosf(x)
}

/// Arc tangent of `y_over_x` in [-π/2, π/2].
pub fn atan(y_over_x: f32) -> f32 {
    libm::atanf(y_over_x)
}

/// `atan(y, x)`: the angle of (x, y) in [-π, π], quadrant from the signs.
pub fn atan2(y: f32, x: f32) -> f32 {
    libm::atan2f(y, x)
}

/// Correctly rounded square root.
pub fn sqrt(x: f32) -> f32 {
    libm::sqrtf(x)
}

/// `1 / sqrt(x)`, two roundings.
pub fn inversesqrt(x: f32) -> f32 {
    1.0 / sqrt(x)
}

pub fn abs(x: f32) -> f32 {
    libm::fabsf(x)
}

/// 1.0 if x > 0, -1.0 if x < 0, else 0.0 (also for -0.0 and NaN).
pub fn sign(x: f32) -> f32 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        0.0
    }
}

/// Hyperbolic sine, `(e^x - e^-x) / 2` (GLSL 1.30 §8.1), libm's routine.
pub fn sinh(x: f32) -> f32 {
    libm::sinhf(x)
}

pub fn cosh(x: f32) -> f32 {
    libm::coshf(x)
}

pub fn tanh(x: f32) -> f32 {
    libm::tanhf(x)
}

pub fn asinh(x: f32) -> f32 {
    libm::asinhf(x)
}

/// NaN when x < 1.
pub fn acosh(x: f32) -> f32 {
    libm::acoshf(x)
}

/// NaN when |x| > 1, ±inf at ±1.
pub fn atanh(x: f32) -> f32 {
    libm::atanhf(x)
}

/// The integer nearest `x` no larger in magnitude (exact).
pub fn trunc(x: f32) -> f32 {
    libm::truncf(x)
}

/// GLSL `round`: the nearest integer, halves away from zero (GLSL 1.30
/// §8.3 leaves the direction of a half to the implementation; this is C's
/// `roundf`). Exact.
pub fn round(x: f32) -> f32 {
    libm::roundf(x)
}

/// GLSL `roundEven`: the nearest integer, halves to the even one. Exact:
/// below 2^23 adding and subtracting 2^23 rounds to an integer in the
/// default (nearest-even) mode; from 2^23 on every `f32` is an integer.
pub fn round_even(x: f32) -> f32 {
    let a = x.abs();
    // NaN and infinities included.
    if a >= 8_388_608.0 || a.is_nan() {
        return x;
    }
    ((a + 8_388_608.0) - 8_388_608.0).copysign(x)
}

/// The fractional part `modf` returns, `x - trunc(x)` with the sign of
/// `x` (0 for infinities, as C's `modff`); the whole part is [`trunc`].
pub fn modf_fract(x: f32) -> f32 {
    if x.is_infinite() {
        0.0f32.copysign(x)
    } else {
        (x - trunc(x)).copysign(x)
    }
}

pub fn floor(x: f32) -> f32 {
    libm::floorf(x)
}

pub fn ceil(x: f32) -> f32 {
    libm::ceilf(x)
}

/// `x - floor(x)`.
pub fn fract(x: f32) -> f32 {
    x - floor(x)
}

/// GLSL `mod`: `x - y * floor(x / y)` (GLSL 1.20 §8.3), unlike C's `fmod`
/// the result has the sign of `y`. `x / y` is flushed ([`flush_denormal`]);
/// the product never is subnormal (`y` times a whole number).
pub fn modulo(x: f32, y: f32) -> f32 {
    x - y * floor(flush_denormal(x / y))
}

/// GLSL `min`: `y` if `y < x`, otherwise `x`; a NaN operand gives the
/// other operand (IEEE 754 `minNum`; GLSL leaves NaN results undefined,
/// piglit's `*-nan-builtin-min` expects the number).
pub fn min(x: f32, y: f32) -> f32 {
    if x.is_nan() || y < x {
        y
    } else {
        x
    }
}

/// GLSL `max`: `y` if `x < y`, otherwise `x`; a NaN operand gives the
/// other operand (IEEE 754 `maxNum`).
pub fn max(x: f32, y: f32) -> f32 {
    if x.is_nan() || x < y {
        y
    } else {
        x
    }
}

/// A subnormal `x` becomes zero of the same sign; other values are
/// unchanged. Float arithmetic and built-in results are flushed this way,
/// both when folded and when executed (GLSL 1.20 §4.1.4 allows it: "there
/// is no requirement for [...] denormalized numbers"; piglit's
/// `fs-underflow-*-compare-zero` expect a product or `pow` below the normal
/// range to be 0, as GPUs and llvmpipe give).
pub fn flush_denormal(x: f32) -> f32 {
    if x != 0.0 && x.abs() < f32::MIN_POSITIVE {
        f32::from_bits(x.to_bits() & 0x8000_0000)
    } else {
        x
    }
}

/// `min(max(x, lo), hi)`.
pub fn clamp(x: f32, lo: f32, hi: f32) -> f32 {
    min(max(x, lo), hi)
}

/// `x · (1 - a) + y · a`, each product flushed ([`flush_denormal`]); `1 -
/// a` is never subnormal.
pub fn mix(x: f32, y: f32, a: f32) -> f32 {
    let f = flush_denormal;
    f(x * (1.0 - a)) + f(y * a)
}

/// 0.0 if `x < edge`, otherwise 1.0.
pub fn step(edge: f32, x: f32) -> f32 {
    if x < edge {
        0.0
    } else {
        1.0
    }
}

/// `t = clamp((x - e0) / (e1 - e0), 0, 1); t · t · (3 - 2 · t)`, each
/// intermediate flushed ([`flush_denormal`]; `2 · t` and `3 - 2 · t` never
/// are subnormal).
pub fn smoothstep(edge0: f32, edge1: f32, x: f32) -> f32 {
    let f = flush_denormal;
    let t = clamp(f(f(x - edge0) / f(edge1 - edge0)), 0.0, 1.0);
    f(t * t) * (3.0 - 2.0 * t)
}

/// Dot product, summed from the last component down (`x₂y₂ + x₁y₁` first,
/// then `+ x₀y₀`): the order Mesa's compiler reduces a `dot` in, so that
/// the last bit of a sum that decides a silhouette is Mesa's.
pub fn dot(x: &[f32], y: &[f32]) -> f32 {
    let mut products = x.iter().zip(y).map(|(a, b)| a * b).rev();
    let last = products.next().unwrap_or(0.0);
    products.fold(last, |acc, p| acc + p)
}

/// `sqrt(dot(x, x))`.
pub fn length(x: &[f32]) -> f32 {
    sqrt(dot(x, x))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn known_values() {
        assert_eq!(sin(0.0), 0.0);
        assert_eq!(cos(0.0), 1.0);
        assert_eq!(tan(0.0), 0.0);
        assert_eq!(sqrt(4.0), 2.0);
        assert_eq!(exp2(3.0), 8.0);
        assert_eq!(log2(8.0), 3.0);
        assert_eq!(pow(2.0, 10.0), 1024.0);
        assert_eq!(atan2(0.0, -1.0), PI);
        assert_eq!(atan2(1.0, 0.0), PI / 2.0);
        assert!((sin(PI / 6.0) - 0.5).abs() < 1e-7);
        assert!((exp(1.0) - core::f32::consts::E).abs() < 1e-6);
        assert!(log(-1.0).is_nan());
    }

    /// Distance in ulps between an `f32` result and an exact-ish `f64`.
    fn ulps(got: f32, want: f64) -> f64 {
        let w = want as f32;
        let ulp = (f32::from_bits(w.abs().to_bits() + 1) - w.abs()) as f64;
        (got as f64 - want).abs() / ulp
    }

    #[test]
    fn within_one_ulp_of_double_precision() {
        type Pair = (fn(f32) -> f32, fn(f64) -> f64, f32, f32);
        assert_eq!(ulps(1.0 + f32::EPSILON, 1.0), 1.0);
        let cases: [(&str, Pair); 10] = [
            ("sin", (sin, libm::sin, -100.0, 100.0)),
            ("cos", (cos, libm::cos, -100.0, 100.0)),
            ("tan", (tan, libm::tan, -1.5, 1.5)),
            ("asin", (asin, libm::asin, -1.0, 1.0)),
            ("acos", (acos, libm::acos, -1.0, 1.0)),
            ("atan", (atan, libm::atan, -50.0, 50.0)),
            ("exp", (exp, libm::exp, -80.0, 80.0)),
            ("log", (log, libm::log, 1e-30, 1e30)),
            ("exp2", (exp2, libm::exp2, -120.0, 120.0)),
            ("log2", (log2, libm::log2, 1e-30, 1e30)),
        ];
        for (name, (f, reference, lo, hi)) in cases {
            let mut worst = 0.0f64;
            for i in 0..=20_000 {
                let x = lo + (hi - lo) * (i as f32 / 20_000.0);
                worst = worst.max(ulps(f(x), reference(x as f64)));
            }
            assert!(worst <= 1.0, "{name}: {worst} ulp");
        }
        let mut worst = 0.0f64;
        for i in 0..200 {
            for j in 0..100 {
                let (x, y) = (i as f32 * 0.37 + 0.01, j as f32 * 0.11 - 5.0);
                worst = worst.max(ulps(pow(x, y), libm::pow(x as f64, y as f64)));
            }
        }
        assert!(worst <= 1.0, "pow: {worst} ulp");
    }

    #[test]
    fn glsl_definitions() {
        assert_eq!(modulo(-1.5, 1.0), 0.5);
        assert_eq!(modulo(1.5, -1.0), -0.5);
        assert_eq!(fract(-0.25), 0.75);
        assert_eq!(sign(-0.0), 0.0);
        assert_eq!(sign(-3.0), -1.0);
        assert_eq!(step(1.0, 1.0), 1.0);
        assert_eq!(step(1.0, 0.5), 0.0);
        assert_eq!(clamp(5.0, 0.0, 1.0), 1.0);
        assert_eq!(mix(2.0, 4.0, 0.5), 3.0);
        assert_eq!(smoothstep(0.0, 1.0, 0.5), 0.5);
        assert_eq!(smoothstep(0.0, 1.0, -1.0), 0.0);
        assert_eq!(radians(180.0), PI);
        assert_eq!(dot(&[1.0, 2.0, 3.0], &[4.0, 5.0, 6.0]), 32.0);
        // Last component first: 1e8 − 1e8, then + 1 (left to right the 1
        // would be lost in 1 + 1e8).
        assert_eq!(dot(&[1.0, 1e8, -1e8], &[1.0; 3]), 1.0);
        assert_eq!(length(&[3.0, 4.0]), 5.0);
    }
}
