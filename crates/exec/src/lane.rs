//! The engine's float operations on one lane, public so that a stage
//! computed outside the engine gets the engine's bits (`gl`'s
//! fixed-function fragment stage runs its fixed programs with these):
//! each function is what the interpreter runs for the op it names, and
//! the interpreter itself calls them.
//!
//! Values entering an op are flushed (subnormals read as zero, see the
//! crate documentation); every result is flushed again.

use crate::{LaneMask, LANES};

/// Every lane of a batch.
pub const FULL: LaneMask = if LANES >= 32 { !0 } else { (1u32 << LANES) - 1 };

/// `x` with a subnormal made zero of its sign, as bits (no branch).
#[inline(always)]
pub fn flush_bits(x: f32) -> u32 {
    let b = x.to_bits();
    let keep = if b & 0x7f80_0000 == 0 {
        0x8000_0000
    } else {
        !0
    };
    b & keep
}

/// [`flush_bits`] as a float.
#[inline(always)]
pub fn flush(x: f32) -> f32 {
    f32::from_bits(flush_bits(x))
}

/// `x + y` (`FAdd`).
#[inline(always)]
pub fn add(x: f32, y: f32) -> f32 {
    flush(x + y)
}

/// `x - y` (`FSub`).
#[inline(always)]
pub fn sub(x: f32, y: f32) -> f32 {
    flush(x - y)
}

/// `x * y` (`FMul`).
#[inline(always)]
pub fn mul(x: f32, y: f32) -> f32 {
    flush(x * y)
}

/// `x / y` (`FDiv`).
#[inline(always)]
pub fn div(x: f32, y: f32) -> f32 {
    flush(x / y)
}

/// The quotient of two ints (`IDiv`), wrapping (`i32::MIN / -1` is
/// `i32::MIN`), 0 for a division by zero.
///
/// Divided in f64, which vectorizes where the integer division does not
/// (one `idiv` of 14–30 cycles per lane): the f64 quotient is exact
/// enough. For |x|, |y| ≤ 2³¹ its rounding error is at most
/// |x / y|·2⁻⁵³ < 2⁻²²/|y|, less than the distance 1/|y| from a
/// non-integer x / y to the nearest integer, so truncating it gives the
/// integer quotient.
#[inline(always)]
pub(crate) fn idiv(x: u32, y: u32) -> u32 {
    let (x, y) = (x as i32, y as i32);
    // Divisors 0 and −1 replaced by 1 (their lanes are set below), so the
    // quotient is finite and inside i32: the conversion needs no
    // saturation or NaN handling, which would keep it off vectors.
    let safe = if y == 0 || y == -1 { 1 } else { y };
    // SAFETY: x / safe is finite and |x / safe| ≤ 2³¹ (−2³¹ only when
    // safe is 1, exactly representable), so it truncates into i32.
    let q = unsafe { (x as f64 / safe as f64).to_int_unchecked::<i32>() };
    // The one quotient past i32::MAX (−2³¹ / −1) wraps.
    let q = if y == -1 { x.wrapping_neg() } else { q };
    (if y == 0 { 0 } else { q }) as u32
}

/// The remainder of two ints (`IMod`): the sign of `x`, wrapping
/// (`i32::MIN % -1` is 0), 0 for a division by zero.
#[inline(always)]
pub(crate) fn imod(x: u32, y: u32) -> u32 {
    let r = x.wrapping_sub(idiv(x, y).wrapping_mul(y));
    if y == 0 {
        0
    } else {
        r
    }
}

/// The quotient of two uints (`UDiv`), 0 for a division by zero; in f64
/// as [`idiv`] (x < 2³² keeps the error below 2⁻²¹/y).
#[inline(always)]
pub(crate) fn udiv(x: u32, y: u32) -> u32 {
    let safe = if y == 0 { 1 } else { y };
    // SAFETY: 0 ≤ x / safe < 2³², finite: it truncates into i64.
    let q = unsafe { (x as f64 / safe as f64).to_int_unchecked::<i64>() } as u32;
    if y == 0 {
        0
    } else {
        q
    }
}

/// The remainder of two uints (`UMod`), 0 for a division by zero.
#[inline(always)]
pub(crate) fn umod(x: u32, y: u32) -> u32 {
    let r = x.wrapping_sub(udiv(x, y).wrapping_mul(y));
    if y == 0 {
        0
    } else {
        r
    }
}

/// `-x` (`FNeg`): the sign bit flipped (NaNs included; never a new
/// subnormal).
#[inline(always)]
pub fn neg(x: f32) -> f32 {
    -x
}

/// `glsl::math::min`: `y` when `x` is NaN or `y < x`.
#[inline(always)]
pub fn min(x: f32, y: f32) -> f32 {
    // (`|`, not `||`: both tests, then a select, which vectorizes.)
    if x.is_nan() | (y < x) {
        y
    } else {
        x
    }
}

/// `glsl::math::max`: `y` when `x` is NaN or `x < y`.
#[inline(always)]
pub fn max(x: f32, y: f32) -> f32 {
    if x.is_nan() | (x < y) {
        y
    } else {
        x
    }
}

/// `clamp(x, lo, hi)` (`F3::Clamp`).
#[inline(always)]
pub fn clamp(x: f32, lo: f32, hi: f32) -> f32 {
    flush(min(max(x, lo), hi))
}

/// `mix(x, y, t)` (`F3::Mix`): glsl::math's formula with its flushed
/// intermediates.
#[inline(always)]
pub fn mix(x: f32, y: f32, t: f32) -> f32 {
    flush(flush(x * (1.0 - t)) + flush(y * t))
}

/// `exp(x)` (`F1::Exp`).
#[inline(always)]
pub fn exp(x: f32) -> f32 {
    flush(glsl::math::exp(x))
}

/// `noise1` .. `noise4` of `x` (`n` 1 to 4, `Noise`), padded with zeros
/// to 4 components (unflushed).
#[inline(always)]
pub(crate) fn noise(n: u8, x: &[f32]) -> [f32; 4] {
    use glsl::math;
    match n {
        1 => [math::noise1(x), 0.0, 0.0, 0.0],
        2 => {
            let v = math::noise2(x);
            [v[0], v[1], 0.0, 0.0]
        }
        3 => {
            let v = math::noise3(x);
            [v[0], v[1], v[2], 0.0]
        }
        _ => math::noise4(x),
    }
}

/// `bits` as a float output: any NaN becomes the canonical quiet NaN, a
/// subnormal zero of its sign.
///
/// Inside a kernel a NaN's payload is not fixed: with two NaN operands an
/// IEEE operation returns one of them, and which one depends on the order
/// the compiled code (the interpreter's build, the native code) put them
/// in. GLSL 1.20 can observe a payload only through a float output (no
/// bit casts; NaN converts to int as 0 and compares unordered), so outputs
/// carry `0x7fc00000` and every variant writes the same bits. Native code
/// on x86-64 leaves subnormal results unflushed in its registers (it reads
/// them as zero: `jit`), so outputs flush them.
#[inline(always)]
pub fn float_output(bits: u32) -> u32 {
    // Selects only, so lane loops vectorize.
    let flushed = flush_bits(f32::from_bits(bits));
    if bits & 0x7fff_ffff > 0x7f80_0000 {
        0x7fc0_0000
    } else {
        flushed
    }
}

/// Word `w` of the uniforms (0 past the end), a float's subnormal read as
/// zero.
#[inline(always)]
pub fn uniform_word(uniforms: &[u32], w: usize, float: bool) -> u32 {
    let bits = uniforms.get(w).copied().unwrap_or(0);
    if float {
        flush_bits(f32::from_bits(bits))
    } else {
        bits
    }
}

/// The differences within each quad along x and y of the (flushed)
/// lanes `v`: lane l gets `v[l | bit] - v[l & !bit]` for bit 1 (x) and
/// bit 2 (y), unflushed (the derivatives of an implicit texture LOD).
/// Written per quad (a shuffle and a subtraction each) rather than per
/// lane, which the compiler turns into scalar code.
#[inline(always)]
pub fn quad_diffs(v: &[f32; LANES]) -> ([f32; LANES], [f32; LANES]) {
    let mut dx = [0f32; LANES];
    let mut dy = [0f32; LANES];
    for ((q, dx), dy) in v
        .chunks_exact(4)
        .zip(dx.chunks_exact_mut(4))
        .zip(dy.chunks_exact_mut(4))
    {
        let (x0, x1) = ([q[1], q[1], q[3], q[3]], [q[0], q[0], q[2], q[2]]);
        let (y0, y1) = ([q[2], q[3], q[2], q[3]], [q[0], q[1], q[0], q[1]]);
        for j in 0..4 {
            dx[j] = x0[j] - x1[j];
            dy[j] = y0[j] - y1[j];
        }
    }
    (dx, dy)
}

/// A `match` over an op with the arms of the lane-wise ops of one or two
/// register operands added from one table, [`lane_ops!`]: each op computes
/// every lane of `d` from the same lane of its operands.
///
/// - `match_op!(match op { arms })` is `match op { arms, lane arms }`
///   (`engine::step`, `interp::run`): a lane arm is `Op::Name { .. } =>
///   un!(d, a, |x| formula)` or `bin!(d, a, b, |x, y| formula)`, a formula
///   over the operands' `u32` bits, with the caller's `un!`/`bin!` (how
///   registers are read and written) and `f` (bits to `f32`).
/// - `match_op!(jit match op { arms })` is `match op { jit arms, arms }`
///   (`jit::codegen::ops`, whose arms end with a catch-all): a jit arm
///   invokes the caller's macro named in the row's `jit` column, which
///   emits the op for each quarter of the lanes (or calls the engine
///   back).
///
/// Not in the table: ops reading other lanes, ranges, the mask or side
/// tables; `Select`, `FMac` and `Dot` (written on whole registers), and
/// the built-in functions (`F1`, `F2`, `F3`: the interpreter computes
/// them with the scalar `glsl::math`, the reference for the engine's
/// vectorized forms).
macro_rules! match_op {
    (match $($op:ident).+ { $($arms:tt)* }) => {
        $crate::lane::lane_ops!(lane, ($($op).+) { $($arms)* })
    };
    (jit match $($op:ident).+ { $($arms:tt)* }) => {
        $crate::lane::lane_ops!(jit, ($($op).+) { $($arms)* })
    };
}
pub(crate) use match_op;

/// The table of [`match_op!`]: a row per op, `Name { fields } => lane
/// un!/bin!(..), jit emitter!(..);`, handed to [`expand_lane_ops!`] with
/// which column to use.
macro_rules! lane_ops {
    ($column:ident, $op:tt { $($arms:tt)* }) => {
        $crate::lane::expand_lane_ops! { $column, $op { $($arms)* }
            FAdd { d, a, b } => lane bin!(d, a, b, |x, y| $crate::lane::add(f(x), f(y)).to_bits()),
                jit fbin!(d, a, b, fadd);
            FSub { d, a, b } => lane bin!(d, a, b, |x, y| $crate::lane::sub(f(x), f(y)).to_bits()),
                jit fbin!(d, a, b, fsub);
            FMul { d, a, b } => lane bin!(d, a, b, |x, y| $crate::lane::mul(f(x), f(y)).to_bits()),
                jit fbin!(d, a, b, fmul);
            FDiv { d, a, b } => lane bin!(d, a, b, |x, y| $crate::lane::div(f(x), f(y)).to_bits()),
                jit fbin!(d, a, b, fdiv);
            FNeg { d, a } => lane un!(d, a, |x| $crate::lane::neg(f(x)).to_bits()),
                jit un_ins!(d, a, ld, fneg);
            FLt { d, a, b } => lane bin!(d, a, b, |x, y| (f(x) < f(y)) as u32),
                jit fcmp!(d, a, b, FloatCC::LessThan);
            FLe { d, a, b } => lane bin!(d, a, b, |x, y| (f(x) <= f(y)) as u32),
                jit fcmp!(d, a, b, FloatCC::LessThanOrEqual);
            FEq { d, a, b } => lane bin!(d, a, b, |x, y| (f(x) == f(y)) as u32),
                jit fcmp!(d, a, b, FloatCC::Equal);
            IAdd { d, a, b } => lane bin!(d, a, b, |x, y| x.wrapping_add(y)),
                jit ibin!(d, a, b, iadd);
            ISub { d, a, b } => lane bin!(d, a, b, |x, y| x.wrapping_sub(y)),
                jit ibin!(d, a, b, isub);
            IMul { d, a, b } => lane bin!(d, a, b, |x, y| x.wrapping_mul(y)),
                jit ibin!(d, a, b, imul);
            // Wrapping, and 0 for a division by zero.
            IDiv { d, a, b } => lane bin!(d, a, b, |x, y| $crate::lane::idiv(x, y)),
                jit call_int!(d, a, b, 0);
            INeg { d, a } => lane un!(d, a, |x| (x as i32).wrapping_neg() as u32),
                jit un_ins!(d, a, ld, ineg);
            ILt { d, a, b } => lane bin!(d, a, b, |x, y| ((x as i32) < (y as i32)) as u32),
                jit icmp!(d, a, b, IntCC::SignedLessThan);
            ILe { d, a, b } => lane bin!(d, a, b, |x, y| ((x as i32) <= (y as i32)) as u32),
                jit icmp!(d, a, b, IntCC::SignedLessThanOrEqual);
            IEq { d, a, b } => lane bin!(d, a, b, |x, y| (x == y) as u32),
                jit icmp!(d, a, b, IntCC::Equal);
            // Wrapping, and 0 for a division by zero.
            UDiv { d, a, b } => lane bin!(d, a, b, |x, y| $crate::lane::udiv(x, y)),
                jit call_int!(d, a, b, 2);
            IMod { d, a, b } => lane bin!(d, a, b, |x, y| $crate::lane::imod(x, y)),
                jit call_int!(d, a, b, 1);
            UMod { d, a, b } => lane bin!(d, a, b, |x, y| $crate::lane::umod(x, y)),
                jit call_int!(d, a, b, 3);
            ULt { d, a, b } => lane bin!(d, a, b, |x, y| (x < y) as u32),
                jit icmp!(d, a, b, IntCC::UnsignedLessThan);
            ULe { d, a, b } => lane bin!(d, a, b, |x, y| (x <= y) as u32),
                jit icmp!(d, a, b, IntCC::UnsignedLessThanOrEqual);
            // Amounts modulo 32 (what `wrapping_sh*` and the native
            // code's scalar shifts do).
            Shl { d, a, b } => lane bin!(d, a, b, |x, y| x.wrapping_shl(y)),
                jit shift!(d, a, b, ishl);
            ShrS { d, a, b } => lane bin!(d, a, b, |x, y| (x as i32).wrapping_shr(y) as u32),
                jit shift!(d, a, b, sshr);
            ShrU { d, a, b } => lane bin!(d, a, b, |x, y| x.wrapping_shr(y)),
                jit shift!(d, a, b, ushr);
            BitAnd { d, a, b } => lane bin!(d, a, b, |x, y| x & y),
                jit ibin!(d, a, b, band);
            BitOr { d, a, b } => lane bin!(d, a, b, |x, y| x | y),
                jit ibin!(d, a, b, bor);
            BitXor { d, a, b } => lane bin!(d, a, b, |x, y| x ^ y),
                jit ibin!(d, a, b, bxor);
            BitNot { d, a } => lane un!(d, a, |x| !x),
                jit un_ins!(d, a, ld, bit_not);
            And { d, a, b } => lane bin!(d, a, b, |x, y| ((x != 0) & (y != 0)) as u32),
                jit logic!(d, a, b, bor, true);
            Or { d, a, b } => lane bin!(d, a, b, |x, y| ((x != 0) | (y != 0)) as u32),
                jit logic!(d, a, b, band, true);
            Xor { d, a, b } => lane bin!(d, a, b, |x, y| ((x != 0) ^ (y != 0)) as u32),
                jit logic!(d, a, b, bxor, false);
            Not { d, a } => lane un!(d, a, |x| (x == 0) as u32),
                jit un_ins!(d, a, ld, not01);
            FToI { d, a } => lane un!(d, a, |x| glsl::consteval::float_to_int(f(x)) as u32),
                jit un_ins!(d, a, ldf, ftoi);
            IToF { d, a } => lane un!(d, a, |x| (x as i32 as f32).to_bits()),
                jit un_ins!(d, a, ld, itof);
            FToU { d, a } => lane un!(d, a, |x| glsl::consteval::float_to_uint(f(x))),
                jit un_ins!(d, a, ldf, ftou);
            UToF { d, a } => lane un!(d, a, |x| (x as f32).to_bits()),
                jit un_ins!(d, a, ld, utof);
            FToB { d, a } => lane un!(d, a, |x| (f(x) != 0.0) as u32),
                jit un_ins!(d, a, ldf, ftob);
            IToB { d, a } => lane un!(d, a, |x| (x != 0) as u32),
                jit un_ins!(d, a, ld, bool_of);
            BToF { d, a } => lane un!(d, a, |x| if x != 0 { 1.0f32 } else { 0.0 }.to_bits()),
                jit un_ins!(d, a, ld, btof);
            ClampIdx { d, a, max, stride } => lane un!(d, a, |x| {
                ((x as i32).clamp(0, max as i32) as u32).wrapping_mul(stride)
            }),
                jit clamp_idx!(d, a, max, stride);
        }
    };
}
pub(crate) use lane_ops;

/// The `match` of [`match_op!`] from the rows of [`lane_ops!`].
macro_rules! expand_lane_ops {
    (
        $column:ident, ($($op:ident).+) { $($arms:tt)* }
        $(
            $name:ident { $($field:ident),* }
                => lane $lane:ident!($($lane_args:tt)*), jit $jit:ident!($($jit_args:tt)*);
        )*
    ) => {
        $crate::lane::expand_lane_ops!(@$column ($($op).+) { $($arms)* }
            $($name { $($field),* } lane $lane!($($lane_args)*) jit $jit!($($jit_args)*);)*)
    };
    (@lane ($($op:ident).+) { $($arms:tt)* }
        $($name:ident { $($field:ident),* } lane $lane:ident!($($lane_args:tt)*)
            jit $jit:ident!($($jit_args:tt)*);)*) => {
        match $($op).+ {
            $($arms)*
            $($crate::program::Op::$name { $($field),* } => $lane!($($lane_args)*),)*
        }
    };
    (@jit ($($op:ident).+) { $($arms:tt)* }
        $($name:ident { $($field:ident),* } lane $lane:ident!($($lane_args:tt)*)
            jit $jit:ident!($($jit_args:tt)*);)*) => {
        match $($op).+ {
            // (A call back reads its operands itself.)
            $(#[allow(unused_variables)]
            $crate::program::Op::$name { $($field),* } => $jit!($($jit_args)*),)*
            $($arms)*
        }
    };
}
pub(crate) use expand_lane_ops;

#[cfg(test)]
mod tests {
    use super::*;

    /// The integer divisions in f64 against Rust's integer division on
    /// the extremes, small values and their neighbours, and random pairs.
    #[test]
    fn integer_division_in_f64_is_exact() {
        let mut special = vec![0u32, 0x8000_0000, 0x7fff_ffff, 0x8000_0001, 0xffff_ffff];
        for k in 1..=40u32 {
            special.extend([k, k.wrapping_neg(), 0x8000_0000 + k, 0x7fff_ffff - k]);
            special.extend([1 << (k % 32), (1u32 << (k % 32)).wrapping_sub(1)]);
        }
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut pairs: Vec<(u32, u32)> = special
            .iter()
            .flat_map(|&x| special.iter().map(move |&y| (x, y)))
            .collect();
        for _ in 0..1_000_000 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            // Divisors of every magnitude: shifted right by 0–31 bits.
            let y = (seed >> 32) as u32 >> (seed & 31);
            pairs.push((seed as u32, y));
        }
        for (x, y) in pairs {
            let (xs, ys) = (x as i32, y as i32);
            let (q, r) = match ys {
                0 => (0, 0),
                _ => (xs.wrapping_div(ys), xs.wrapping_rem(ys)),
            };
            assert_eq!(idiv(x, y), q as u32, "{xs} / {ys}");
            assert_eq!(imod(x, y), r as u32, "{xs} % {ys}");
            assert_eq!(udiv(x, y), x.checked_div(y).unwrap_or(0), "{x} / {y}");
            assert_eq!(umod(x, y), x.checked_rem(y).unwrap_or(0), "{x} % {y}");
        }
    }
}
