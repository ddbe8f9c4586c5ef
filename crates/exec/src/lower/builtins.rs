//! Built-in functions other than texture lookups: component-wise
//! application with scalar broadcasting, the geometric functions expanded
//! into ops (`dot`, `length`, `normalize`, `reflect`, `refract`...), matrix
//! and vector-relational functions, derivatives, noise, `ftransform`; the
//! integer and bool-selector overloads of GLSL 1.30 as compares and
//! selects (signed for `int`, unsigned for `uint`, as folding compares);
//! the bit casts of GLSL 3.30 as copies (a float from bits is flushed, as
//! every float entering a run is); `determinant`/`inverse` through
//! `glsl::math::matrix`, the formulas constant folding uses.

use super::textures::is_texture;
use super::{kind_of, unsupported, Lowerer, Val, R};
use crate::program::{Op, Reg, F1, F2, F3};
use crate::ExecError;
use glsl::builtins::BuiltinFn;
use glsl::ir::Expr;
use glsl::types::{Base, Scalar, Type};

fn fsub_op(d: Reg, x: &[Reg]) -> Op {
    Op::FSub {
        d,
        a: x[0],
        b: x[1],
    }
}

fn fmul_op(d: Reg, x: &[Reg]) -> Op {
    Op::FMul {
        d,
        a: x[0],
        b: x[1],
    }
}

fn fadd_op(d: Reg, x: &[Reg]) -> Op {
    Op::FAdd {
        d,
        a: x[0],
        b: x[1],
    }
}

/// One op per operation of `glsl::math::matrix`'s formulas.
struct EmitArith<'a, 'm>(&'a mut Lowerer<'m>);

impl glsl::math::matrix::Arith for EmitArith<'_, '_> {
    type V = Reg;
    type E = ExecError;
    fn mul(&mut self, a: Reg, b: Reg) -> R<Reg> {
        self.0.fbin(|d, a, b| Op::FMul { d, a, b }, a, b)
    }
    fn add(&mut self, a: Reg, b: Reg) -> R<Reg> {
        self.0.fbin(|d, a, b| Op::FAdd { d, a, b }, a, b)
    }
    fn sub(&mut self, a: Reg, b: Reg) -> R<Reg> {
        self.0.fbin(|d, a, b| Op::FSub { d, a, b }, a, b)
    }
    fn div(&mut self, a: Reg, b: Reg) -> R<Reg> {
        self.0.fbin(|d, a, b| Op::FDiv { d, a, b }, a, b)
    }
    fn neg(&mut self, a: Reg) -> R<Reg> {
        let d = self.0.temp()?;
        self.0.emit(Op::FNeg { d, a })?;
        Ok(d)
    }
}

impl<'m> Lowerer<'m> {
    fn iconst(&mut self, i: i32) -> R<Reg> {
        self.konst(i as u32)
    }

    /// `c ? a : b` component-wise.
    fn select(&mut self, c: &Val, a: &Val, b: &Val) -> R<Val> {
        self.map(&[c, a, b], |d, x| Op::Select {
            d,
            c: x[0],
            a: x[1],
            b: x[2],
        })
    }

    /// `a < b` component-wise: unsigned for `uint`s, signed for `int`s.
    fn ilt(&mut self, a: &Val, b: &Val, unsigned: bool) -> R<Val> {
        self.map(&[a, b], |d, x| {
            let (a, b) = (x[0], x[1]);
            if unsigned {
                Op::ULt { d, a, b }
            } else {
                Op::ILt { d, a, b }
            }
        })
    }

    /// `min` of integers: `b < a ? b : a` (GLSL 1.30 §8.3).
    fn imin(&mut self, a: &Val, b: &Val, unsigned: bool) -> R<Val> {
        let c = self.ilt(b, a, unsigned)?;
        self.select(&c, b, a)
    }

    /// `max` of integers: `a < b ? b : a`.
    fn imax(&mut self, a: &Val, b: &Val, unsigned: bool) -> R<Val> {
        let c = self.ilt(a, b, unsigned)?;
        self.select(&c, b, a)
    }

    /// The integer overloads of `abs`, `sign` (`int` only), `min`, `max`,
    /// `clamp` (`int` and `uint`, `unsigned` telling which).
    fn int_builtin(&mut self, f: BuiltinFn, v: &[Val], unsigned: bool) -> R<Val> {
        use BuiltinFn as B;
        let arg = |i: usize| -> R<&Val> {
            match v.get(i) {
                Some(x) if !x.is_empty() => Ok(x),
                _ => unsupported(format!("{} is missing an argument", f.name())),
            }
        };
        let zero = vec![self.iconst(0)?];
        match f {
            // GLSL has no unsigned abs or sign: the analyzer never picks one.
            B::Abs | B::Sign if unsigned => {
                unsupported(format!("unsigned {} is not a built-in", f.name()))
            }
            B::Abs => {
                let x = arg(0)?.clone();
                let neg = self.map(&[&x], |d, a| Op::INeg { d, a: a[0] })?;
                let c = self.ilt(&x, &zero, false)?;
                self.select(&c, &neg, &x)
            }
            B::Sign => {
                let x = arg(0)?.clone();
                let (one, minus) = (vec![self.iconst(1)?], vec![self.iconst(-1)?]);
                let pos = self.ilt(&zero, &x, false)?;
                let neg = self.ilt(&x, &zero, false)?;
                let low = self.select(&neg, &minus, &zero)?;
                self.select(&pos, &one, &low)
            }
            B::Min => self.imin(arg(0)?, arg(1)?, unsigned),
            B::Max => self.imax(arg(0)?, arg(1)?, unsigned),
            B::Clamp => {
                let m = self.imax(arg(0)?, arg(1)?, unsigned)?;
                self.imin(&m, arg(2)?, unsigned)
            }
            _ => unsupported(format!("integer {} is not implemented", f.name())),
        }
    }

    /// One field of `pack{U,S}norm*`: `glsl::math::pack::pack_unorm` /
    /// `pack_snorm`, op for op (clamp, product, round to even, conversion,
    /// the snorm's two's complement masked to the field).
    fn norm_field(&mut self, x: Reg, bits: u32, snorm: bool) -> R<Reg> {
        let (lo, scale) = if snorm {
            (-1.0, ((1u32 << (bits - 1)) - 1) as f32)
        } else {
            (0.0, ((1u32 << bits) - 1) as f32)
        };
        let (lo, hi, scale) = (self.fconst(lo)?, self.fconst(1.0)?, self.fconst(scale)?);
        let c = self.emit_temp(|d| Op::F3 {
            f: F3::Clamp,
            d,
            a: x,
            b: lo,
            c: hi,
        })?;
        let p = self.fbin(|d, a, b| Op::FMul { d, a, b }, c, scale)?;
        let r = self.emit_temp(|d| Op::F1 {
            f: F1::RoundEven,
            d,
            a: p,
        })?;
        if snorm {
            let i = self.emit_temp(|d| Op::FToI { d, a: r })?;
            let mask = self.konst((1u32 << bits) - 1)?;
            self.fbin(|d, a, b| Op::BitAnd { d, a, b }, i, mask)
        } else {
            self.emit_temp(|d| Op::FToU { d, a: r })
        }
    }

    /// `fields[0] | fields[1] << bits | ...`: the first component lowest.
    fn join_fields(&mut self, fields: &[Reg], bits: u32) -> R<Reg> {
        let mut word = fields[0];
        for (i, &f) in fields.iter().enumerate().skip(1) {
            let n = self.konst(i as u32 * bits)?;
            let shifted = self.fbin(|d, a, b| Op::Shl { d, a, b }, f, n)?;
            word = self.fbin(|d, a, b| Op::BitOr { d, a, b }, word, shifted)?;
        }
        Ok(word)
    }

    /// The float of the `bits`-wide field at bit `at` of `w`:
    /// `glsl::math::pack::unpack_unorm` / `unpack_snorm`, op for op.
    fn norm_float(&mut self, w: Reg, at: u32, bits: u32, snorm: bool) -> R<Reg> {
        let ibin = |l: &mut Self, mk: fn(Reg, Reg, Reg) -> Op, a: Reg, b: u32| -> R<Reg> {
            let b = l.konst(b)?;
            l.fbin(mk, a, b)
        };
        if snorm {
            // Shifted up to the top of the word, then down with the sign.
            let up = ibin(self, |d, a, b| Op::Shl { d, a, b }, w, 32 - bits - at)?;
            let v = ibin(self, |d, a, b| Op::ShrS { d, a, b }, up, 32 - bits)?;
            let f = self.emit_temp(|d| Op::IToF { d, a: v })?;
            let scale = self.fconst(((1u32 << (bits - 1)) - 1) as f32)?;
            let q = self.fbin(|d, a, b| Op::FDiv { d, a, b }, f, scale)?;
            let (lo, hi) = (self.fconst(-1.0)?, self.fconst(1.0)?);
            self.emit_temp(|d| Op::F3 {
                f: F3::Clamp,
                d,
                a: q,
                b: lo,
                c: hi,
            })
        } else {
            let down = ibin(self, |d, a, b| Op::ShrU { d, a, b }, w, at)?;
            let v = ibin(
                self,
                |d, a, b| Op::BitAnd { d, a, b },
                down,
                (1u32 << bits) - 1,
            )?;
            let f = self.emit_temp(|d| Op::UToF { d, a: v })?;
            let scale = self.fconst(((1u32 << bits) - 1) as f32)?;
            self.fbin(|d, a, b| Op::FDiv { d, a, b }, f, scale)
        }
    }

    /// `glsl::math::pack::half_from_float` as ops: each case computed on
    /// every lane, then selected.
    fn half_from_float(&mut self, x: Reg) -> R<Reg> {
        use glsl::math::pack::{HALF_INF_FROM, HALF_NORMAL_FROM};
        let ibin = |l: &mut Self, mk: fn(Reg, Reg, Reg) -> Op, a: Reg, b: u32| -> R<Reg> {
            let b = l.konst(b)?;
            l.fbin(mk, a, b)
        };
        let and = |d, a, b| Op::BitAnd { d, a, b };
        let shr = |d, a, b| Op::ShrU { d, a, b };
        let high = ibin(self, shr, x, 16)?;
        let sign = ibin(self, and, high, 0x8000)?;
        let a = ibin(self, and, x, 0x7fff_ffff)?;
        let consts = [0x7f80_0000, HALF_INF_FROM, HALF_NORMAL_FROM].map(|c| self.konst(c));
        let [inf_bits, inf_from, normal_from] = consts;
        let is_nan = self.fbin(|d, a, b| Op::ULt { d, a, b }, inf_bits?, a)?;
        let is_inf = self.fbin(|d, a, b| Op::ULe { d, a, b }, inf_from?, a)?;
        let is_normal = self.fbin(|d, a, b| Op::ULe { d, a, b }, normal_from?, a)?;
        // Normal: rebias, round to nearest even on the 13 dropped bits.
        let r = ibin(self, |d, a, b| Op::ISub { d, a, b }, a, 112 << 23)?;
        let r13 = ibin(self, shr, r, 13)?;
        let odd = ibin(self, and, r13, 1)?;
        let up = ibin(self, |d, a, b| Op::IAdd { d, a, b }, r, 0x0fff)?;
        let up = self.fbin(|d, a, b| Op::IAdd { d, a, b }, up, odd)?;
        let normal = ibin(self, shr, up, 13)?;
        // Subnormal: units of 2^-24, rounded to even.
        let scale = self.fconst(16_777_216.0)?;
        let units = self.fbin(|d, a, b| Op::FMul { d, a, b }, a, scale)?;
        let units = self.emit_temp(|d| Op::F1 {
            f: F1::RoundEven,
            d,
            a: units,
        })?;
        let small = self.emit_temp(|d| Op::FToU { d, a: units })?;
        let (h_inf, h_nan) = (self.konst(0x7c00)?, self.konst(0x7e00)?);
        let sel = |l: &mut Self, c: Reg, a: Reg, b: Reg| l.emit_temp(|d| Op::Select { d, c, a, b });
        let m = sel(self, is_normal, normal, small)?;
        let m = sel(self, is_inf, h_inf, m)?;
        let m = sel(self, is_nan, h_nan, m)?;
        self.fbin(|d, a, b| Op::BitOr { d, a, b }, sign, m)
    }

    /// `glsl::math::pack::float_from_half` of the 16 bits at `at` of `w`,
    /// as ops: each exponent case computed, then selected.
    fn float_from_half(&mut self, w: Reg, at: u32) -> R<Reg> {
        let ibin = |l: &mut Self, mk: fn(Reg, Reg, Reg) -> Op, a: Reg, b: u32| -> R<Reg> {
            let b = l.konst(b)?;
            l.fbin(mk, a, b)
        };
        let and = |d, a, b| Op::BitAnd { d, a, b };
        let shl = |d, a, b| Op::Shl { d, a, b };
        let down = ibin(self, |d, a, b| Op::ShrU { d, a, b }, w, at)?;
        let h = ibin(self, and, down, 0xffff)?;
        let s = ibin(self, and, h, 0x8000)?;
        let sign = ibin(self, shl, s, 16)?;
        let e = ibin(self, and, h, 0x7c00)?;
        let m = ibin(self, and, h, 0x3ff)?;
        let mf = self.emit_temp(|d| Op::UToF { d, a: m })?;
        let unit = self.fconst(1.0 / 16_777_216.0)?;
        let sub = self.fbin(|d, a, b| Op::FMul { d, a, b }, mf, unit)?;
        let m13 = ibin(self, shl, m, 13)?;
        let special = ibin(self, |d, a, b| Op::BitOr { d, a, b }, m13, 0x7f80_0000)?;
        let em = ibin(self, and, h, 0x7fff)?;
        let em = ibin(self, shl, em, 13)?;
        let normal = ibin(self, |d, a, b| Op::IAdd { d, a, b }, em, 112 << 23)?;
        let is_zero = ibin(self, |d, a, b| Op::IEq { d, a, b }, e, 0)?;
        let is_max = ibin(self, |d, a, b| Op::IEq { d, a, b }, e, 0x7c00)?;
        let sel = |l: &mut Self, c: Reg, a: Reg, b: Reg| l.emit_temp(|d| Op::Select { d, c, a, b });
        let mag = sel(self, is_max, special, normal)?;
        let mag = sel(self, is_zero, sub, mag)?;
        self.fbin(|d, a, b| Op::BitOr { d, a, b }, sign, mag)
    }

    /// `modf(x, out i)`: writes `trunc(x)` to `i`, returns the fraction.
    fn modf(&mut self, args: &[Expr]) -> R<Val> {
        let [x, whole] = args else {
            return unsupported("modf takes two arguments");
        };
        let x = self.expr(x)?;
        let place = self.place(whole)?;
        let w = self.map1(&x, F1::Trunc)?;
        let fract = self.map1(&x, F1::ModfFract)?;
        self.write(&place, &w)?;
        Ok(fract)
    }

    /// Component-wise application with scalar broadcasting.
    pub(super) fn map(&mut self, args: &[&Val], mut f: impl FnMut(Reg, &[Reg]) -> Op) -> R<Val> {
        let n = args.iter().map(|a| a.len()).max().unwrap_or(0);
        if n == 0 || args.iter().any(|a| a.len() != n && a.len() != 1) {
            return unsupported("built-in arguments of different sizes");
        }
        let out = self.temps(n)?;
        let mut ins = Vec::with_capacity(args.len());
        for (i, &d) in out.iter().enumerate() {
            ins.clear();
            ins.extend(args.iter().map(|a| a[if a.len() == 1 { 0 } else { i }]));
            let op = f(d, &ins);
            self.emit(op)?;
        }
        Ok(out)
    }

    fn map1(&mut self, a: &Val, f: F1) -> R<Val> {
        self.map(&[a], |d, x| Op::F1 { f, d, a: x[0] })
    }

    fn map2(&mut self, a: &Val, b: &Val, f: F2) -> R<Val> {
        self.map(&[a, b], |d, x| Op::F2 {
            f,
            d,
            a: x[0],
            b: x[1],
        })
    }

    fn map3(&mut self, a: &Val, b: &Val, c: &Val, f: F3) -> R<Val> {
        self.map(&[a, b, c], |d, x| Op::F3 {
            f,
            d,
            a: x[0],
            b: x[1],
            c: x[2],
        })
    }

    /// `dot`, summed from the last component like `glsl::math::dot`.
    fn dot(&mut self, a: &[Reg], b: &[Reg]) -> R<Reg> {
        let d = self.temp()?;
        let pairs: Vec<(Reg, Reg)> = a.iter().copied().zip(b.iter().copied()).collect();
        self.emit_dot(d, &pairs)?;
        Ok(d)
    }

    /// The sum of the pairs' products from the last pair to the first
    /// ([`Op::Dot`]'s order): one [`Op::Dot`] for up to 4 pairs, else a
    /// [`Op::FMac`] chain from 0.0.
    pub(super) fn emit_dot(&mut self, d: Reg, pairs: &[(Reg, Reg)]) -> R<()> {
        if (1..=4).contains(&pairs.len()) {
            let mut a = [0; 4];
            let mut b = [0; 4];
            for (k, &(x, y)) in pairs.iter().enumerate() {
                a[k] = x;
                b[k] = y;
            }
            return self.emit(Op::Dot {
                d,
                n: pairs.len() as u8,
                a,
                b,
            });
        }
        self.emit(Op::Const {
            d,
            bits: 0.0f32.to_bits(),
        })?;
        for &(x, y) in pairs.iter().rev() {
            self.emit(Op::FMac { d, a: x, b: y })?;
        }
        Ok(())
    }

    /// `f(a)` into a new temporary.
    fn f1(&mut self, f: F1, a: Reg) -> R<Reg> {
        self.emit_temp(|d| Op::F1 { f, d, a })
    }

    pub(super) fn fbin(&mut self, mk: fn(Reg, Reg, Reg) -> Op, a: Reg, b: Reg) -> R<Reg> {
        let d = self.temp()?;
        self.emit(mk(d, a, b))?;
        Ok(d)
    }

    pub(super) fn builtin(&mut self, f: BuiltinFn, args: &[Expr], ty: Type) -> R<Val> {
        use BuiltinFn as B;
        if is_texture(f) {
            return self.texture(f, args);
        }
        if f == B::Ftransform {
            let mvp = self.global_by_name("gl_ModelViewProjectionMatrix")?;
            let vertex = self.global_by_name("gl_Vertex")?;
            let a = self.read(&mvp)?;
            let b = self.read(&vertex)?;
            return self.matmul(&a, mvp.ty, &b, vertex.ty);
        }
        if f == B::Modf {
            return self.modf(args);
        }
        if f == B::EmitVertex {
            self.emit_vertex()?;
            return Ok(Vec::new());
        }
        if f == B::EndPrimitive {
            self.end_primitive()?;
            return Ok(Vec::new());
        }
        if f.is_atomic() {
            return self.atomic(f, args);
        }
        match f {
            B::Barrier => {
                self.emit(Op::Barrier)?;
                return Ok(Vec::new());
            }
            // Memory is coherent: every write is seen by the next read.
            B::MemoryBarrier
            | B::MemoryBarrierAtomicCounter
            | B::MemoryBarrierBuffer
            | B::MemoryBarrierImage
            | B::MemoryBarrierShared
            | B::GroupMemoryBarrier => return Ok(Vec::new()),
            _ => {}
        }
        let refs: Vec<&Expr> = args.iter().collect();
        let v = self.operands(&refs)?;
        let first_kind = args.first().map(|a| kind_of(a.ty));
        let int_form = matches!(f, B::Abs | B::Sign | B::Min | B::Max | B::Clamp)
            && matches!(first_kind, Some(Scalar::Int | Scalar::Uint));
        if int_form {
            return self.int_builtin(f, &v, first_kind == Some(Scalar::Uint));
        }
        let arg = |i: usize| -> R<&Val> {
            match v.get(i) {
                Some(x) if !x.is_empty() => Ok(x),
                _ => unsupported(format!("{} is missing an argument", f.name())),
            }
        };
        let fmul = |d, a, b| Op::FMul { d, a, b };
        let fsub = |d, a, b| Op::FSub { d, a, b };
        let fadd = |d, a, b| Op::FAdd { d, a, b };
        let flt = |d, a, b| Op::FLt { d, a, b };
        match f {
            B::Radians => self.map1(arg(0)?, F1::Radians),
            B::Degrees => self.map1(arg(0)?, F1::Degrees),
            B::Sin => self.map1(arg(0)?, F1::Sin),
            B::Cos => self.map1(arg(0)?, F1::Cos),
            B::Tan => self.map1(arg(0)?, F1::Tan),
            B::Asin => self.map1(arg(0)?, F1::Asin),
            B::Acos => self.map1(arg(0)?, F1::Acos),
            B::Atan if args.len() == 1 => self.map1(arg(0)?, F1::Atan),
            B::Atan => self.map2(arg(0)?, arg(1)?, F2::Atan2),
            B::Sinh => self.map1(arg(0)?, F1::Sinh),
            B::Cosh => self.map1(arg(0)?, F1::Cosh),
            B::Tanh => self.map1(arg(0)?, F1::Tanh),
            B::Asinh => self.map1(arg(0)?, F1::Asinh),
            B::Acosh => self.map1(arg(0)?, F1::Acosh),
            B::Atanh => self.map1(arg(0)?, F1::Atanh),
            B::Trunc => self.map1(arg(0)?, F1::Trunc),
            B::Round => self.map1(arg(0)?, F1::Round),
            B::RoundEven => self.map1(arg(0)?, F1::RoundEven),
            B::IsNan => {
                // NaN is the one value unequal to itself.
                let x = arg(0)?.clone();
                let eq = self.map(&[&x, &x], |d, v| Op::FEq {
                    d,
                    a: v[0],
                    b: v[1],
                })?;
                self.map(&[&eq], |d, v| Op::Not { d, a: v[0] })
            }
            B::IsInf => {
                let a = self.map1(arg(0)?, F1::Abs)?;
                let inf = vec![self.fconst(f32::INFINITY)?];
                self.map(&[&a, &inf], |d, v| Op::FEq {
                    d,
                    a: v[0],
                    b: v[1],
                })
            }
            // Registers hold bits: the float's bits are the int's (or
            // uint's), and back, flushed as folding flushes.
            B::FloatBitsToInt | B::FloatBitsToUint => {
                let x = arg(0)?.clone();
                self.copy(&x)
            }
            B::IntBitsToFloat | B::UintBitsToFloat => self.map1(arg(0)?, F1::FlushBits),
            B::PackUnorm2x16 | B::PackSnorm2x16 | B::PackUnorm4x8 | B::PackSnorm4x8 => {
                let x = arg(0)?.clone();
                let bits = 32 / x.len() as u32;
                let snorm = matches!(f, B::PackSnorm2x16 | B::PackSnorm4x8);
                let mut fields = Vec::with_capacity(x.len());
                for &c in &x {
                    fields.push(self.norm_field(c, bits, snorm)?);
                }
                Ok(vec![self.join_fields(&fields, bits)?])
            }
            B::PackHalf2x16 => {
                let x = arg(0)?.clone();
                let mut fields = Vec::with_capacity(2);
                for &c in &x {
                    fields.push(self.half_from_float(c)?);
                }
                Ok(vec![self.join_fields(&fields, 16)?])
            }
            B::UnpackUnorm2x16 | B::UnpackSnorm2x16 | B::UnpackUnorm4x8 | B::UnpackSnorm4x8 => {
                let [w] = arg(0)?[..] else {
                    return unsupported(format!("{} of a vector", f.name()));
                };
                let bits = if matches!(f, B::UnpackUnorm4x8 | B::UnpackSnorm4x8) {
                    8
                } else {
                    16
                };
                let snorm = matches!(f, B::UnpackSnorm2x16 | B::UnpackSnorm4x8);
                (0..32 / bits)
                    .map(|i| self.norm_float(w, i * bits, bits, snorm))
                    .collect()
            }
            B::UnpackHalf2x16 => {
                let [w] = arg(0)?[..] else {
                    return unsupported("unpackHalf2x16 of a vector");
                };
                (0..2).map(|i| self.float_from_half(w, i * 16)).collect()
            }
            // mix(x, y, bvec a): y where a is true.
            B::Mix if args.get(2).is_some_and(|a| kind_of(a.ty) == Scalar::Bool) => {
                let (x, y, a) = (arg(0)?.clone(), arg(1)?.clone(), arg(2)?.clone());
                self.select(&a, &y, &x)
            }
            B::Determinant | B::Inverse => {
                let m = arg(0)?.clone();
                let n = match args[0].ty.base {
                    Base::Matrix { cols, rows } if cols == rows => cols as usize,
                    _ => return unsupported(format!("{} of a non-square matrix", f.name())),
                };
                let mut a = EmitArith(self);
                let r = if f == B::Determinant {
                    glsl::math::matrix::determinant(&mut a, &m, n).map(|r| r.map(|d| vec![d]))
                } else {
                    glsl::math::matrix::inverse(&mut a, &m, n)
                };
                match r {
                    Some(r) => r,
                    None => unsupported(format!("{} of a malformed matrix", f.name())),
                }
            }
            B::Pow => self.map2(arg(0)?, arg(1)?, F2::Pow),
            B::Exp => self.map1(arg(0)?, F1::Exp),
            B::Log => self.map1(arg(0)?, F1::Log),
            B::Exp2 => self.map1(arg(0)?, F1::Exp2),
            B::Log2 => self.map1(arg(0)?, F1::Log2),
            B::Sqrt => self.map1(arg(0)?, F1::Sqrt),
            B::InverseSqrt => self.map1(arg(0)?, F1::InverseSqrt),
            B::Abs => self.map1(arg(0)?, F1::Abs),
            B::Sign => self.map1(arg(0)?, F1::Sign),
            B::Floor => self.map1(arg(0)?, F1::Floor),
            B::Ceil => self.map1(arg(0)?, F1::Ceil),
            B::Fract => self.map1(arg(0)?, F1::Fract),
            B::Mod => self.map2(arg(0)?, arg(1)?, F2::Mod),
            B::Min => self.map2(arg(0)?, arg(1)?, F2::Min),
            B::Max => self.map2(arg(0)?, arg(1)?, F2::Max),
            B::Clamp => self.map3(arg(0)?, arg(1)?, arg(2)?, F3::Clamp),
            B::Mix => self.map3(arg(0)?, arg(1)?, arg(2)?, F3::Mix),
            B::Step => self.map2(arg(0)?, arg(1)?, F2::Step),
            B::SmoothStep => self.map3(arg(0)?, arg(1)?, arg(2)?, F3::SmoothStep),
            B::Length => {
                let x = arg(0)?.clone();
                let d = self.dot(&x, &x)?;
                Ok(vec![self.f1(F1::Sqrt, d)?])
            }
            B::Distance => {
                let (x, y) = (arg(0)?.clone(), arg(1)?.clone());
                if x.len() != y.len() {
                    return unsupported("distance of different sizes");
                }
                let diff = self.map(&[&x, &y], fsub_op)?;
                let d = self.dot(&diff, &diff)?;
                Ok(vec![self.f1(F1::Sqrt, d)?])
            }
            B::Dot => {
                let (x, y) = (arg(0)?.clone(), arg(1)?.clone());
                Ok(vec![self.dot(&x, &y)?])
            }
            B::Cross => {
                let (x, y) = (arg(0)?.clone(), arg(1)?.clone());
                if x.len() != 3 || y.len() != 3 {
                    return unsupported("cross of non-vec3");
                }
                let mut out = Vec::with_capacity(3);
                for (i, j) in [(1, 2), (2, 0), (0, 1)] {
                    // x[i] * y[j] - y[i] * x[j]
                    let p = self.fbin(fmul, x[i], y[j])?;
                    let q = self.fbin(fmul, y[i], x[j])?;
                    out.push(self.fbin(fsub, p, q)?);
                }
                Ok(out)
            }
            B::Normalize => {
                // x · inversesqrt(dot(x, x)), Mesa's form
                // (`glsl::builtins::eval`'s too).
                let x = arg(0)?.clone();
                let d = self.dot(&x, &x)?;
                let inv = self.f1(F1::InverseSqrt, d)?;
                self.map(&[&x, &vec![inv]], fmul_op)
            }
            B::FaceForward => {
                let (n, i, nref) = (arg(0)?.clone(), arg(1)?.clone(), arg(2)?.clone());
                let d = self.dot(&nref, &i)?;
                let zero = self.fconst(0.0)?;
                let c = self.fbin(flt, d, zero)?;
                let neg = self.temps(n.len())?;
                for (&d, &a) in neg.iter().zip(&n) {
                    self.emit(Op::FNeg { d, a })?;
                }
                self.map(&[&vec![c], &n, &neg], |d, x| Op::Select {
                    d,
                    c: x[0],
                    a: x[1],
                    b: x[2],
                })
            }
            B::Reflect => {
                let (i, n) = (arg(0)?.clone(), arg(1)?.clone());
                let dt = self.dot(&n, &i)?;
                let two = self.fconst(2.0)?;
                let d = self.fbin(fmul, two, dt)?;
                let dn = self.map(&[&vec![d], &n], fmul_op)?;
                self.map(&[&i, &dn], fsub_op)
            }
            B::Refract => {
                let (i, n, eta) = (arg(0)?.clone(), arg(1)?.clone(), arg(2)?[0]);
                let d = self.dot(&n, &i)?;
                let one = self.fconst(1.0)?;
                let e2 = self.fbin(fmul, eta, eta)?;
                let dd = self.fbin(fmul, d, d)?;
                let om = self.fbin(fsub, one, dd)?;
                let t = self.fbin(fmul, e2, om)?;
                let k = self.fbin(fsub, one, t)?;
                let zero = self.fconst(0.0)?;
                let neg = self.fbin(flt, k, zero)?;
                let sk = self.f1(F1::Sqrt, k)?;
                let ed = self.fbin(fmul, eta, d)?;
                let s = self.fbin(fadd, ed, sk)?;
                let ei = self.map(&[&vec![eta], &i], fmul_op)?;
                let sn = self.map(&[&vec![s], &n], fmul_op)?;
                let r = self.map(&[&ei, &sn], fsub_op)?;
                self.map(&[&vec![neg], &vec![zero], &r], |d, x| Op::Select {
                    d,
                    c: x[0],
                    a: x[1],
                    b: x[2],
                })
            }
            B::MatrixCompMult => self.map(&[arg(0)?, arg(1)?], fmul_op),
            B::OuterProduct => {
                let (c, r) = (arg(0)?.clone(), arg(1)?.clone());
                let mut out = Vec::with_capacity(c.len() * r.len());
                for &rj in &r {
                    for &ci in &c {
                        out.push(self.fbin(fmul, ci, rj)?);
                    }
                }
                Ok(out)
            }
            B::Transpose => {
                let Base::Matrix { cols, rows } = args[0].ty.base else {
                    return unsupported("transpose of a non-matrix");
                };
                let (cols, rows) = (cols as usize, rows as usize);
                let m = arg(0)?;
                if m.len() != cols * rows {
                    return unsupported("transpose of a malformed matrix");
                }
                Ok((0..rows)
                    .flat_map(|j| (0..cols).map(move |i| i * rows + j))
                    .map(|k| m[k])
                    .collect())
            }
            B::LessThan | B::LessThanEqual | B::GreaterThan | B::GreaterThanEqual => {
                let kind = kind_of(args[0].ty);
                let (x, y) = (arg(0)?.clone(), arg(1)?.clone());
                let (x, y) = if matches!(f, B::GreaterThan | B::GreaterThanEqual) {
                    (y, x)
                } else {
                    (x, y)
                };
                let strict = matches!(f, B::LessThan | B::GreaterThan);
                self.map(&[&x, &y], |d, v| {
                    let (a, b) = (v[0], v[1]);
                    match (kind, strict) {
                        (Scalar::Float, true) => Op::FLt { d, a, b },
                        (Scalar::Float, false) => Op::FLe { d, a, b },
                        (Scalar::Uint, true) => Op::ULt { d, a, b },
                        (Scalar::Uint, false) => Op::ULe { d, a, b },
                        (_, true) => Op::ILt { d, a, b },
                        (_, false) => Op::ILe { d, a, b },
                    }
                })
            }
            B::Equal | B::NotEqual => {
                let float = kind_of(args[0].ty) == Scalar::Float;
                let eq = self.map(&[arg(0)?, arg(1)?], |d, v| {
                    if float {
                        Op::FEq {
                            d,
                            a: v[0],
                            b: v[1],
                        }
                    } else {
                        Op::IEq {
                            d,
                            a: v[0],
                            b: v[1],
                        }
                    }
                })?;
                if f == B::Equal {
                    Ok(eq)
                } else {
                    self.map(&[&eq], |d, v| Op::Not { d, a: v[0] })
                }
            }
            B::Any | B::All => {
                let x = arg(0)?.clone();
                let mut acc = x[0];
                for &c in &x[1..] {
                    let d = self.temp()?;
                    self.emit(if f == B::Any {
                        Op::Or { d, a: acc, b: c }
                    } else {
                        Op::And { d, a: acc, b: c }
                    })?;
                    acc = d;
                }
                Ok(vec![acc])
            }
            B::Not => self.map(&[arg(0)?], |d, v| Op::Not { d, a: v[0] }),
            B::DFdx => self.map(&[arg(0)?], |d, v| Op::DdX { d, a: v[0] }),
            B::DFdy => self.map(&[arg(0)?], |d, v| Op::DdY { d, a: v[0] }),
            B::Fwidth => {
                let x = arg(0)?.clone();
                let dx = self.map(&[&x], |d, v| Op::DdX { d, a: v[0] })?;
                let dy = self.map(&[&x], |d, v| Op::DdY { d, a: v[0] })?;
                let ax = self.map1(&dx, F1::Abs)?;
                let ay = self.map1(&dy, F1::Abs)?;
                self.map(&[&ax, &ay], fadd_op)
            }
            B::Noise1 | B::Noise2 | B::Noise3 | B::Noise4 => {
                let x = arg(0)?.clone();
                let dims = x.len().min(4) as u8;
                let a = self.consecutive(&x[..dims as usize])?;
                let n = match f {
                    B::Noise1 => 1,
                    B::Noise2 => 2,
                    B::Noise3 => 3,
                    _ => 4,
                };
                let out = self.temps(n as usize)?;
                self.emit(Op::Noise {
                    d: out[0],
                    n,
                    a,
                    dims,
                })?;
                Ok(out)
            }
            _ => {
                let _ = ty;
                unsupported(format!("built-in {} is not implemented", f.name()))
            }
        }
    }
}
