//! Lane arithmetic emitted inline, on one 4-lane quarter: subnormal
//! flushes, `min`/`max`, `floor`/`ceil`, booleans, and the inline
//! functions of one, two and three floats ([`crate::program::Op::F1`], `F2`,
//! `F3`), each the same IEEE operations in the same order as the
//! interpreter (`engine::step`, `engine::f1`/`f2`).

use super::{Emit, ONE, SIGN};
use crate::program::{Reg, F1, F2, F3};
use cranelift_codegen::ir::condcodes::{FloatCC, IntCC};
use cranelift_codegen::ir::types::{F64, F64X2, I32, I32X4, I64X2};
use cranelift_codegen::ir::{ConstantData, InstBuilder, Value};

/// A lane-uniform divisor's values for [`Emit::int_div_by`], computed
/// once per run.
#[derive(Clone, Copy)]
pub(super) struct Divisor {
    /// The divisor with 0 (and −1, signed) replaced by 1.
    safe: Value,
    /// −`safe`.
    neg: Value,
    /// 1 / `safe` in `f64`.
    recip: Value,
    /// All ones where the divisor is 0.
    by_zero: Value,
    /// All ones where a signed divisor is −1 (zero for unsigned ones).
    by_minus_one: Value,
}

impl<'a, 'b> Emit<'a, 'b> {
    /// `engine::ftz` of an F32X4, as I32X4: a subnormal keeps only its
    /// sign. Under DAZ, `x` as it is: every float op reads it as the
    /// flushed value, and it is flushed where it leaves the code (outputs,
    /// callback operands).
    pub(super) fn ftz(&mut self, x: Value) -> Value {
        if self.daz {
            self.uses.daz_flushes += 1;
            return self.iv(x);
        }
        self.flushed(x)
    }

    /// `engine::ftz` of an F32X4 whatever the environment, as I32X4 (for
    /// values stored the way a callback stores them).
    pub(super) fn flushed(&mut self, x: Value) -> Value {
        let b = self.iv(x);
        let exp = self.splat(0x7f80_0000);
        let e = self.b.ins().band(b, exp);
        let zero = self.splat(0);
        let z = self.b.ins().icmp(IntCC::Equal, e, zero);
        let mag = self.splat(!SIGN);
        let drop = self.b.ins().band(z, mag);
        self.b.ins().band_not(b, drop)
    }

    /// [`Self::ftz`] as an F32X4: an intermediate result flushed before
    /// the next op uses it.
    pub(super) fn fz(&mut self, x: Value) -> Value {
        let v = self.ftz(x);
        self.fv(v)
    }

    /// Uniform words (I32X4) as read: [`Self::ftz`] for a float's.
    pub(super) fn ftz_word(&mut self, float: bool, v: Value) -> Value {
        if float {
            let x = self.fv(v);
            self.ftz(x)
        } else {
            v
        }
    }

    /// Integer op `k` of a quarter: 0 `IDiv`, 1 `IMod`, 2 `UDiv`, 3 `UMod`
    /// (`lane::idiv` ... `lane::umod`: truncated quotients, wrapping, 0
    /// for a division by zero). The quotient is exact in `f64`, as there:
    /// operands and divisor converted, divided, truncated, two lanes at a
    /// time (the conversion patterns Cranelift lowers to single
    /// instructions).
    pub(super) fn int_div(&mut self, k: usize, x: Value, y: Value) -> Value {
        let signed = k < 2;
        let zero = self.splat(0);
        let one = self.splat(1);
        let by_zero = self.b.ins().icmp(IntCC::Equal, y, zero);
        // Divisors 0 (and −1, signed) replaced by 1: finite quotients
        // inside the integer's range.
        let (replaced, by_minus_one) = if signed {
            let minus_one = self.splat(u32::MAX);
            let m1 = self.b.ins().icmp(IntCC::Equal, y, minus_one);
            (self.b.ins().bor(by_zero, m1), Some(m1))
        } else {
            (by_zero, None)
        };
        let safe = self.b.ins().bitselect(replaced, one, y);
        let halves = [false, true].map(|high| {
            let (xs, ys) = (self.half(x, high), self.half(safe, high));
            let (xd, yd) = (self.widen_f64(xs, signed), self.widen_f64(ys, signed));
            let qd = self.b.ins().fdiv(xd, yd);
            self.truncate_f64(qd, signed)
        });
        let mut q = self.lanes_of2(halves[0], halves[1], [0, 1, 4, 5]);
        if let Some(m1) = by_minus_one {
            // The one quotient past i32::MAX (−2³¹ / −1) wraps.
            let neg = self.b.ins().ineg(x);
            q = self.b.ins().bitselect(m1, neg, q);
        }
        let v = if k.is_multiple_of(2) {
            q
        } else {
            let p = self.b.ins().imul(q, y);
            self.b.ins().isub(x, p)
        };
        self.b.ins().bitselect(by_zero, zero, v)
    }

    /// The per-run values of a lane-uniform divisor held in pool register
    /// `r` (its lane 0, read once before the body: [`Emit::divisors`]).
    pub(super) fn divisor(&mut self, r: Reg, signed: bool) -> Divisor {
        let off = (r - self.code.pool_base) as i32 * 64;
        let y = self.b.ins().load(I32, super::mem(), self.pool, off);
        let one = self.b.ins().iconst(I32, 1);
        let by_zero = self.b.ins().icmp_imm_s(IntCC::Equal, y, 0);
        let by_minus_one = match signed {
            true => self.b.ins().icmp_imm_s(IntCC::Equal, y, -1),
            false => self.b.ins().iconst(cranelift_codegen::ir::types::I8, 0),
        };
        let replaced = self.b.ins().bor(by_zero, by_minus_one);
        let safe = self.b.ins().select(replaced, one, y);
        let neg = self.b.ins().ineg(safe);
        let yd = match signed {
            true => self.b.ins().fcvt_from_sint(F64, safe),
            false => self.b.ins().fcvt_from_uint(F64, safe),
        };
        let unit = self.b.ins().f64const(1.0);
        let recip = self.b.ins().fdiv(unit, yd);
        let mask = |e: &mut Self, m: Value| {
            let v = e.b.ins().bmask(I32, m);
            e.b.ins().splat(I32X4, v)
        };
        Divisor {
            safe: self.b.ins().splat(I32X4, safe),
            neg: self.b.ins().splat(I32X4, neg),
            recip: self.b.ins().splat(F64X2, recip),
            by_zero: mask(self, by_zero),
            by_minus_one: mask(self, by_minus_one),
        }
    }

    /// [`Self::int_div`] by a lane-uniform divisor whose [`Divisor`] is
    /// `by`: the quotient from a product with the reciprocal instead of
    /// a division, then corrected. The product is within 2⁻⁵² of the
    /// quotient relatively, so its truncation is the truncated quotient
    /// except where the quotient is a whole number that the product
    /// misses from the side of zero (one too close to zero: the
    /// remainder is then ±y); the remainder tells, and the step back is
    /// exact.
    pub(super) fn int_div_by(&mut self, k: usize, x: Value, by: Divisor) -> Value {
        let signed = k < 2;
        let halves = [false, true].map(|high| {
            let xs = self.half(x, high);
            let xd = self.widen_f64(xs, signed);
            let qd = self.b.ins().fmul(xd, by.recip);
            self.truncate_f64(qd, signed)
        });
        let mut q = self.lanes_of2(halves[0], halves[1], [0, 1, 4, 5]);
        let p = self.b.ins().imul(q, by.safe);
        let mut rem = self.b.ins().isub(x, p);
        // One short of a whole quotient: the remainder is y (−y when the
        // quotient is negative).
        let mut short = self.b.ins().icmp(IntCC::Equal, rem, by.safe);
        q = self.b.ins().isub(q, short);
        if signed {
            let over = self.b.ins().icmp(IntCC::Equal, rem, by.neg);
            q = self.b.ins().iadd(q, over);
            short = self.b.ins().bor(short, over);
        }
        rem = self.b.ins().band_not(rem, short);
        let v = if k.is_multiple_of(2) {
            if signed {
                // Divisor −1 (run as 1): the quotient −x, wrapping.
                let neg = self.b.ins().ineg(x);
                q = self.b.ins().bitselect(by.by_minus_one, neg, q);
            }
            q
        } else {
            rem
        };
        // Division by zero gives 0.
        self.b.ins().band_not(v, by.by_zero)
    }

    /// Lanes 0 and 1 (`high`: 2 and 3) of an I32X4 in its lanes 0 and 1,
    /// for [`Self::widen_f64`].
    fn half(&mut self, v: Value, high: bool) -> Value {
        match high {
            false => v,
            true => self.lanes_of(v, [2, 3, 2, 3]),
        }
    }

    /// Lanes 0 and 1 of an I32X4 as F64X2.
    fn widen_f64(&mut self, v: Value, signed: bool) -> Value {
        if signed {
            let w = self.b.ins().swiden_low(v);
            self.b.ins().fcvt_from_sint(F64X2, w)
        } else {
            let w = self.b.ins().uwiden_low(v);
            self.b.ins().fcvt_from_uint(F64X2, w)
        }
    }

    /// An F64X2 of integral-range values truncated to lanes 0 and 1 of an
    /// I32X4 (lanes 2 and 3 zero).
    fn truncate_f64(&mut self, v: Value, signed: bool) -> Value {
        let zero = self
            .b
            .func
            .dfg
            .constants
            .insert(ConstantData::from(vec![0u8; 16]));
        let zero = self.b.ins().vconst(I64X2, zero);
        if signed {
            // Every quotient here is finite and inside i32's range (the
            // divisor −1 is run as 1), so the plain conversion is exact:
            // no NaN or bounds fixes.
            let t = self.b.ins().x86_cvtt2dq(I64X2, v);
            self.b.ins().snarrow(t, zero)
        } else {
            let t = self.b.ins().fcvt_to_uint_sat(I64X2, v);
            self.b.ins().uunarrow(t, zero)
        }
    }

    /// 0/1 from an all-ones/zero lane mask.
    pub(super) fn bool01(&mut self, m: Value) -> Value {
        let one = self.splat(1);
        self.b.ins().band(m, one)
    }

    /// All-ones where `v` is 0 (one compare; `!= 0` would take three).
    pub(super) fn is_zero(&mut self, v: Value) -> Value {
        let zero = self.splat(0);
        self.b.ins().icmp(IntCC::Equal, v, zero)
    }

    /// 1 where `v` is nonzero, else 0.
    pub(super) fn bool_of(&mut self, v: Value) -> Value {
        let z = self.is_zero(v);
        let one = self.splat(1);
        self.b.ins().band_not(one, z)
    }

    /// `engine::fmin`: `y` if `x` is NaN or `y < x`, else `x` (F32X4 in,
    /// F32X4 out).
    pub(super) fn fmin(&mut self, x: Value, y: Value) -> Value {
        let nan = self.b.ins().fcmp(FloatCC::Unordered, x, x);
        let lt = self.b.ins().fcmp(FloatCC::LessThan, y, x);
        let c = self.b.ins().bor(nan, lt);
        let (xi, yi) = (self.iv(x), self.iv(y));
        let r = self.b.ins().bitselect(c, yi, xi);
        self.fv(r)
    }

    /// `engine::fmax`: `y` if `x` is NaN or `x < y`, else `x`.
    pub(super) fn fmax(&mut self, x: Value, y: Value) -> Value {
        let nan = self.b.ins().fcmp(FloatCC::Unordered, x, x);
        let lt = self.b.ins().fcmp(FloatCC::LessThan, x, y);
        let c = self.b.ins().bor(nan, lt);
        let (xi, yi) = (self.iv(x), self.iv(y));
        let r = self.b.ins().bitselect(c, yi, xi);
        self.fv(r)
    }

    /// `engine::floor`: IEEE floor, NaN returned as it is (bits kept).
    pub(super) fn floor(&mut self, x: Value) -> Value {
        let r = self.b.ins().floor(x);
        self.keep_nan(x, r)
    }

    pub(super) fn ceil(&mut self, x: Value) -> Value {
        let r = self.b.ins().ceil(x);
        self.keep_nan(x, r)
    }

    pub(super) fn keep_nan(&mut self, x: Value, r: Value) -> Value {
        let nan = self.b.ins().fcmp(FloatCC::Unordered, x, x);
        let (xi, ri) = (self.iv(x), self.iv(r));
        let v = self.b.ins().bitselect(nan, xi, ri);
        self.fv(v)
    }

    pub(super) fn fconst(&mut self, x: f32) -> Value {
        let v = self.splat(x.to_bits());
        self.fv(v)
    }

    /// The inline functions of one float (F32X4 in, I32X4 out).
    pub(super) fn f1(&mut self, f: F1, x: Value) -> Value {
        match f {
            F1::Abs => {
                let xi = self.iv(x);
                let mag = self.splat(!SIGN);
                let a = self.b.ins().band(xi, mag);
                let a = self.fv(a);
                self.ftz(a)
            }
            // Neither result is ever subnormal (a square root is at least
            // 2^-74.5 when nonzero, 1/sqrt at least 2^-64), so they need no
            // flush.
            F1::Sqrt => {
                let r = self.b.ins().sqrt(x);
                self.iv(r)
            }
            F1::InverseSqrt => {
                let s = self.b.ins().sqrt(x);
                let one = self.fconst(1.0);
                let r = self.b.ins().fdiv(one, s);
                self.iv(r)
            }
            F1::Radians | F1::Degrees => {
                let k = if f == F1::Radians {
                    glsl::math::PI / 180.0
                } else {
                    180.0 / glsl::math::PI
                };
                let k = self.fconst(k);
                let r = self.b.ins().fmul(x, k);
                self.ftz(r)
            }
            F1::Sign => {
                let zero = self.fconst(0.0);
                let gt = self.b.ins().fcmp(FloatCC::GreaterThan, x, zero);
                let lt = self.b.ins().fcmp(FloatCC::LessThan, x, zero);
                let (one, minus) = (self.splat(ONE), self.splat((-1.0f32).to_bits()));
                let p = self.b.ins().band(gt, one);
                let n = self.b.ins().band(lt, minus);
                self.b.ins().bor(p, n)
            }
            F1::Floor => {
                let r = self.floor(x);
                self.ftz(r)
            }
            F1::Ceil => {
                let r = self.ceil(x);
                self.ftz(r)
            }
            F1::Fract => {
                let fl = self.floor(x);
                let r = self.b.ins().fsub(x, fl);
                self.ftz(r)
            }
            // The rest are calls (`F1_CALLED`).
            _ => self.splat(0),
        }
    }

    /// The inline functions of two floats.
    pub(super) fn f2(&mut self, f: F2, x: Value, y: Value) -> Value {
        match f {
            F2::Min => {
                let r = self.fmin(x, y);
                self.ftz(r)
            }
            F2::Max => {
                let r = self.fmax(x, y);
                self.ftz(r)
            }
            F2::Step => {
                // step(edge = x, v = y): 0 if v < edge, else 1.
                let lt = self.b.ins().fcmp(FloatCC::LessThan, y, x);
                let one = self.splat(ONE);
                self.b.ins().band_not(one, lt)
            }
            F2::Mod => {
                let q = self.b.ins().fdiv(x, y);
                let q = self.fz(q);
                let fl = self.floor(q);
                let p = self.b.ins().fmul(y, fl);
                let r = self.b.ins().fsub(x, p);
                self.ftz(r)
            }
            // The rest are calls (`F2_CALLED`).
            _ => self.splat(0),
        }
    }

    /// The functions of three floats, as `engine::step` computes them.
    pub(super) fn f3(&mut self, f: F3, x: Value, y: Value, z: Value) -> Value {
        match f {
            // glsl::math's formulas, with its flushed intermediates.
            F3::Mix => {
                let one = self.fconst(1.0);
                let omt = self.b.ins().fsub(one, z);
                let p = self.b.ins().fmul(x, omt);
                let p = self.fz(p);
                let r = self.b.ins().fmul(y, z);
                let r = self.fz(r);
                let s = self.b.ins().fadd(p, r);
                self.ftz(s)
            }
            F3::Clamp => {
                let t = self.fmax(x, y);
                let t = self.fmin(t, z);
                self.ftz(t)
            }
            F3::SmoothStep => {
                // (e0, e1, v) = (x, y, z)
                let num = self.b.ins().fsub(z, x);
                let num = self.fz(num);
                let den = self.b.ins().fsub(y, x);
                let den = self.fz(den);
                let t = self.b.ins().fdiv(num, den);
                let t = self.fz(t);
                let (zero, one) = (self.fconst(0.0), self.fconst(1.0));
                let t = self.fmax(t, zero);
                let t = self.fmin(t, one);
                let (two, three) = (self.fconst(2.0), self.fconst(3.0));
                let tt = self.b.ins().fmul(t, t);
                let tt = self.fz(tt);
                let t2 = self.b.ins().fmul(two, t);
                let k = self.b.ins().fsub(three, t2);
                let r = self.b.ins().fmul(tt, k);
                self.ftz(r)
            }
        }
    }
}
