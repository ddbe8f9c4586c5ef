//! Data ops: [`Emit::data`] emits one op of the program (inline where it
//! is lane-wise, else a call back into the interpreter's own code,
//! `jit_step`, or its math helpers), with the uniform reads, gathers,
//! scatters and quad differences it needs.

use super::super::{jit_step, math_helpers, Ctx, F1_CALLED, F2_CALLED};
use super::{mem, Emit, ONE, QUARTERS, SIGN};
use crate::lane::match_op;
use crate::opt::Ins;
use crate::program::{Op, Reg};
use cranelift_codegen::ir::condcodes::{FloatCC, IntCC};
use cranelift_codegen::ir::types::{F32X4, I32, I32X4};
use cranelift_codegen::ir::{BlockArg, InstBuilder, Value};
use cranelift_frontend::FunctionBuilder;
use std::mem::offset_of;

impl<'a, 'b> Emit<'a, 'b> {
    pub(super) fn call_step(&mut self, index: u32) {
        // The engine's step reads and writes registers in memory.
        self.flush_all();
        let f = self.b.ins().iconst(self.ptr, jit_step as *const () as i64);
        let i = self.b.ins().iconst(I32, index as i32 as i64);
        let cur = self.b.use_var(self.cur);
        let ctx = self.ctx;
        self.b.ins().call_indirect(self.sig_step, f, &[ctx, i, cur]);
    }

    /// Where register `r` is read (pool registers: at `Ctx::pool`).
    pub(super) fn reg_ptr(&mut self, r: Reg) -> Value {
        if r >= self.code.pool_base {
            let off = (r - self.code.pool_base) as i64 * 64;
            self.b.ins().iadd_imm_s(self.pool, off)
        } else {
            self.b.ins().iadd_imm_s(self.regs, r as i64 * 64)
        }
    }

    /// Calls `jit_f1`/`jit_f2` into the scratch register, then copies it
    /// to `d` (under the mask when `masked`).
    pub(super) fn call_math(
        &mut self,
        two: bool,
        func: usize,
        d: Reg,
        a: Reg,
        b: Reg,
        masked: bool,
    ) {
        self.uses.math_calls += 1;
        let out = self
            .b
            .ins()
            .iadd_imm_s(self.ctx, offset_of!(Ctx, scratch) as i64);
        self.flush_range(a, a);
        self.flush_range(b, b);
        let fi = self.b.ins().iconst(I32, func as i64);
        let pa = self.reg_ptr(a);
        if two {
            let pb = self.reg_ptr(b);
            let f = self.b.ins().iconst(self.ptr, math_helpers().1 as i64);
            self.b
                .ins()
                .call_indirect(self.sig_f2, f, &[fi, out, pa, pb]);
        } else {
            let f = self.b.ins().iconst(self.ptr, math_helpers().0 as i64);
            self.b.ins().call_indirect(self.sig_f1, f, &[fi, out, pa]);
        }
        for q in 0..QUARTERS {
            let v = self.b.ins().load(I32X4, mem(), out, (q * 16) as i32);
            self.put(d, q, v, masked);
        }
    }

    pub(super) fn uniforms(&mut self) -> (Value, Value) {
        let p = self.b.ins().load(
            self.ptr,
            mem(),
            self.ctx,
            offset_of!(Ctx, uniforms_ptr) as i32,
        );
        let n = self
            .b
            .ins()
            .load(I32, mem(), self.ctx, offset_of!(Ctx, uniforms_len) as i32);
        (p, n)
    }

    /// `uniforms[word]`, 0 past the end (scalar I32).
    pub(super) fn uniform_word(&mut self, word: u32) -> Value {
        let (p, n) = self.uniforms();
        let w = self.b.ins().iconst(I32, word as i32 as i64);
        let inside = self.b.ins().icmp(IntCC::UnsignedLessThan, w, n);
        let zero = self.b.ins().iconst(I32, 0);
        let safe = self.b.ins().select(inside, w, zero);
        let v = self.load_word(p, safe);
        self.b.ins().select(inside, v, zero)
    }

    /// `p[i]` for an I32 index.
    pub(super) fn load_word(&mut self, p: Value, i: Value) -> Value {
        let i = self.b.ins().uextend(self.ptr, i);
        let off = self.b.ins().ishl_imm_u(i, 2);
        let addr = self.b.ins().iadd(p, off);
        self.b.ins().load(I32, mem(), addr, 0)
    }

    /// `d = uniforms[word + min(off, max)]` per lane (0 past the end);
    /// `word + max` fits in an `i32`. When every lane reads the same word
    /// (an array indexed by a loop counter), one load.
    pub(super) fn gather_uniform(
        &mut self,
        d: Reg,
        word: u32,
        off: Reg,
        max: u32,
        float: bool,
        masked: bool,
    ) {
        let (p, n) = self.uniforms();
        let mut idx = [p; QUARTERS];
        for (q, x) in idx.iter_mut().enumerate() {
            let o = self.ld(off, q);
            let mx = self.splat(max);
            let o = self.b.ins().umin(o, mx);
            let w = self.splat(word);
            *x = self.b.ins().iadd(o, w);
        }
        let first = self.b.ins().extractlane(idx[0], 0);
        let fs = self.b.ins().splat(I32X4, first);
        let mut same = self.b.ins().icmp(IntCC::Equal, idx[0], fs);
        for &x in &idx[1..] {
            let e = self.b.ins().icmp(IntCC::Equal, x, fs);
            same = self.b.ins().band(same, e);
        }
        let bits = self.b.ins().vhigh_bits(I32, same);
        let all = self.b.ins().icmp_imm_u(IntCC::Equal, bits, 0xf);
        let nv = self.b.ins().splat(I32X4, n);
        let (one, many, merge) = (
            self.b.create_block(),
            self.b.create_block(),
            self.b.create_block(),
        );
        let params: Vec<Value> = (0..QUARTERS)
            .map(|_| self.b.append_block_param(merge, I32X4))
            .collect();
        self.b.ins().brif(all, one, &[], many, &[]);

        // No `ld` below: what the cache holds must be defined before the
        // branch.
        self.b.switch_to_block(one);
        let inside = self.b.ins().icmp(IntCC::UnsignedLessThan, first, n);
        let z = self.b.ins().iconst(I32, 0);
        let safe = self.b.ins().select(inside, first, z);
        let x = self.load_word(p, safe);
        let x = self.b.ins().select(inside, x, z);
        let v = self.b.ins().splat(I32X4, x);
        let args = [BlockArg::from(v); QUARTERS];
        self.b.ins().jump(merge, &args);

        // Every index is at most `word + max`: when the uniforms reach
        // past it (the usual case), no lane needs the bounds check.
        self.b.switch_to_block(many);
        let (fits, checked) = (self.b.create_block(), self.b.create_block());
        let last = (word as u64 + max as u64) as i64;
        let all_inside = self.b.ins().icmp_imm_u(IntCC::UnsignedGreaterThan, n, last);
        self.b.ins().brif(all_inside, fits, &[], checked, &[]);

        self.b.switch_to_block(fits);
        let args: Vec<BlockArg> = idx
            .iter()
            .map(|&x| BlockArg::from(self.gather_words(p, x)))
            .collect();
        self.b.ins().jump(merge, &args);

        self.b.switch_to_block(checked);
        let mut args = Vec::with_capacity(QUARTERS);
        for &x in &idx {
            let outside = self.b.ins().icmp(IntCC::UnsignedGreaterThanOrEqual, x, nv);
            let safe = self.b.ins().band_not(x, outside);
            let v = self.gather_words(p, safe);
            args.push(BlockArg::from(self.b.ins().band_not(v, outside)));
        }
        self.b.ins().jump(merge, &args);

        self.b.switch_to_block(merge);
        for (q, &v) in params.iter().enumerate() {
            let v = self.ftz_word(float, v);
            self.put(d, q, v, masked);
        }
    }

    /// `p[x[l]]` for the four lanes of I32X4 `x`.
    fn gather_words(&mut self, p: Value, x: Value) -> Value {
        let mut v = self.splat(0);
        for l in 0..4u8 {
            let i = self.b.ins().extractlane(x, l);
            let w = self.load_word(p, i);
            v = self.b.ins().insertlane(v, w, l);
        }
        v
    }

    /// Byte offsets in the file of lanes `4q..4q+4` of registers
    /// `base + min(off, max)` (I32X4); they fit: registers < 2^18.
    pub(super) fn lane_addresses(&mut self, base: Reg, off: Reg, max: u32, q: usize) -> Value {
        let o = self.ld(off, q);
        let mx = self.splat(max);
        let o = self.b.ins().umin(o, mx);
        let o = self.b.ins().ishl_imm_u(o, 6);
        let l0 = (base as usize * 64 + q * 16) as u32;
        let lanes = self.vconst([l0, l0 + 4, l0 + 8, l0 + 12]);
        self.b.ins().iadd(o, lanes)
    }

    pub(super) fn lane_pointer(&mut self, offsets: Value, l: u8) -> Value {
        let i = self.b.ins().extractlane(offsets, l);
        let i = self.b.ins().uextend(self.ptr, i);
        self.b.ins().iadd(self.regs, i)
    }

    /// Quarter `q` of `r[base + min(off, max)]` per lane.
    pub(super) fn gather(&mut self, base: Reg, off: Reg, max: u32, q: usize) -> Value {
        self.flush_range(base, base.saturating_add(max));
        let at = self.lane_addresses(base, off, max, q);
        let mut v = self.splat(0);
        for l in 0..4u8 {
            let p = self.lane_pointer(at, l);
            let x = self.b.ins().load(I32, mem(), p, 0);
            v = self.b.ins().insertlane(v, x, l);
        }
        v
    }

    /// `r[base + min(off, max)] = a` on the current lanes of quarter `q`
    /// (each lane writes only its own lane of a register, so the lanes
    /// may go one after the other).
    pub(super) fn scatter(&mut self, base: Reg, off: Reg, max: u32, a: Reg, q: usize) {
        let at = self.lane_addresses(base, off, max, q);
        let av = self.ld(a, q);
        let hi = base.saturating_add(max);
        self.flush_range(base, hi);
        self.forget(base, hi);
        let mk = self.b.use_var(self.mk[q]);
        for l in 0..4u8 {
            let p = self.lane_pointer(at, l);
            let old = self.b.ins().load(I32, mem(), p, 0);
            let x = self.b.ins().extractlane(av, l);
            let on = self.b.ins().extractlane(mk, l);
            let v = self.b.ins().select(on, x, old);
            self.b.ins().store(mem(), v, p, 0);
        }
    }

    /// `a(hi lane) - a(lo lane)` within each quad (a quarter is a quad),
    /// not flushed (as `engine::step`).
    pub(super) fn quad_diff(&mut self, a: Reg, q: usize, hi: [u8; 4], lo: [u8; 4]) -> Value {
        let v = self.ld(a, q);
        let (h, l) = (self.lanes_of(v, hi), self.lanes_of(v, lo));
        let (h, l) = (self.fv(h), self.fv(l));
        let r = self.b.ins().fsub(h, l);
        self.ftz(r)
    }

    /// `-x` (`FNeg`): the sign bit flipped.
    fn fneg(&mut self, x: Value) -> Value {
        let s = self.splat(SIGN);
        self.b.ins().bxor(x, s)
    }

    fn ineg(&mut self, x: Value) -> Value {
        self.b.ins().ineg(x)
    }

    /// `x == 0` as 0/1 (`Not`).
    fn not01(&mut self, x: Value) -> Value {
        let z = self.is_zero(x);
        self.bool01(z)
    }

    fn ftoi(&mut self, x: Value) -> Value {
        self.b.ins().fcvt_to_sint_sat(I32X4, x)
    }

    fn itof(&mut self, x: Value) -> Value {
        let f = self.b.ins().fcvt_from_sint(F32X4, x);
        self.iv(f)
    }

    /// Truncating, saturating at 0 and `u32::MAX`, NaN → 0 (`FToU`, as
    /// Rust's `as u32`).
    fn ftou(&mut self, x: Value) -> Value {
        self.b.ins().fcvt_to_uint_sat(I32X4, x)
    }

    /// The lanes as unsigned (`UToF`), correctly rounded.
    fn utof(&mut self, x: Value) -> Value {
        let f = self.b.ins().fcvt_from_uint(F32X4, x);
        self.iv(f)
    }

    fn bit_not(&mut self, x: Value) -> Value {
        self.b.ins().bnot(x)
    }

    /// `x` shifted per lane by `y`'s lane modulo 32: a vector shift takes
    /// one amount for all lanes, so each lane goes through the scalar
    /// shift (which takes its amount modulo 32, as the interpreter does).
    fn lane_shift(
        &mut self,
        x: Value,
        y: Value,
        op: fn(&mut FunctionBuilder, Value, Value) -> Value,
    ) -> Value {
        let mut out = x;
        for l in 0..4u8 {
            let xl = self.b.ins().extractlane(x, l);
            let yl = self.b.ins().extractlane(y, l);
            let r = op(&mut self.b, xl, yl);
            out = self.b.ins().insertlane(out, r, l);
        }
        out
    }

    /// `x != 0.0` as 0/1 (`FToB`; true for NaN, as in Rust).
    fn ftob(&mut self, x: Value) -> Value {
        let zero = self.fconst(0.0);
        let c = self.b.ins().fcmp(FloatCC::NotEqual, x, zero);
        self.bool01(c)
    }

    /// 1.0 for a nonzero `x`, else 0.0 (`BToF`).
    fn btof(&mut self, x: Value) -> Value {
        let z = self.is_zero(x);
        let one = self.splat(ONE);
        self.b.ins().band_not(one, z)
    }

    /// A data op (no control flow); `index`: its index for `jit_step`.
    pub(super) fn data(&mut self, ins: &Ins, index: u32) -> Result<(), String> {
        let m = ins.masked;
        macro_rules! each {
            ($d:expr, |$q:ident| $body:expr) => {{
                for $q in self.quarters() {
                    let v = $body;
                    self.put($d, $q, v, m);
                }
            }};
        }
        macro_rules! fbin {
            ($d:expr, $a:expr, $b:expr, $op:ident) => {
                each!($d, |q| {
                    let (x, y) = (self.ldf($a, q), self.ldf($b, q));
                    let r = self.b.ins().$op(x, y);
                    self.ftz(r)
                })
            };
        }
        macro_rules! ibin {
            ($d:expr, $a:expr, $b:expr, $op:ident) => {
                each!($d, |q| {
                    let (x, y) = (self.ld($a, q), self.ld($b, q));
                    self.b.ins().$op(x, y)
                })
            };
        }
        macro_rules! fcmp {
            ($d:expr, $a:expr, $b:expr, $cc:expr) => {
                each!($d, |q| {
                    let (x, y) = (self.ldf($a, q), self.ldf($b, q));
                    let c = self.b.ins().fcmp($cc, x, y);
                    self.bool01(c)
                })
            };
        }
        macro_rules! icmp {
            ($d:expr, $a:expr, $b:expr, $cc:expr) => {
                each!($d, |q| {
                    let (x, y) = (self.ld($a, q), self.ld($b, q));
                    let c = self.b.ins().icmp($cc, x, y);
                    self.bool01(c)
                })
            };
        }
        // Boolean ops on the "is zero" masks zx, zy: and = !(zx | zy),
        // or = !(zx & zy), xor = zx ^ zy.
        macro_rules! logic {
            ($d:expr, $a:expr, $b:expr, $op:ident, $negate:expr) => {
                each!($d, |q| {
                    let (x, y) = (self.ld($a, q), self.ld($b, q));
                    let (zx, zy) = (self.is_zero(x), self.is_zero(y));
                    let c = self.b.ins().$op(zx, zy);
                    let one = self.splat(1);
                    if $negate {
                        self.b.ins().band_not(one, c)
                    } else {
                        self.b.ins().band(c, one)
                    }
                })
            };
        }
        macro_rules! shift {
            ($d:expr, $a:expr, $b:expr, $op:ident) => {
                each!($d, |q| {
                    let (x, y) = (self.ld($a, q), self.ld($b, q));
                    self.lane_shift(x, y, |b, x, y| b.ins().$op(x, y))
                })
            };
        }
        // The lane-wise ops whose column names a method of `Emit`.
        macro_rules! un_ins {
            ($d:expr, $a:expr, $load:ident, $method:ident) => {
                each!($d, |q| {
                    let x = self.$load($a, q);
                    self.$method(x)
                })
            };
        }
        // Integer division and remainder (`lane::idiv` ... `umod`, in
        // that order), inline.
        macro_rules! call_int {
            ($d:expr, $a:expr, $b:expr, $k:expr) => {
                each!($d, |q| {
                    let x = self.ld($a, q);
                    match self.divisors.get(&($b, $k < 2)) {
                        Some(&by) => self.int_div_by($k, x, by),
                        None => {
                            let y = self.ld($b, q);
                            self.int_div($k, x, y)
                        }
                    }
                })
            };
        }
        macro_rules! clamp_idx {
            ($d:expr, $a:expr, $max:expr, $stride:expr) => {
                if $max <= i32::MAX as u32 {
                    each!($d, |q| {
                        let x = self.ld($a, q);
                        let (lo, hi, s) = (self.splat(0), self.splat($max), self.splat($stride));
                        let x = self.b.ins().smax(x, lo);
                        let x = self.b.ins().smin(x, hi);
                        self.b.ins().imul(x, s)
                    })
                } else {
                    self.call_step(index)
                }
            };
        }
        match_op!(jit match ins.op {
            Op::Const { d, bits } => each!(d, |q| self.splat(bits)),
            Op::Mov { d, a } => each!(d, |q| self.ld(a, q)),
            Op::Store { d, a } => {
                for q in self.quarters() {
                    let v = self.ld(a, q);
                    self.put(d, q, v, true);
                }
            }
            Op::FMac { d, a, b } => each!(d, |q| {
                let (x, y, acc) = (self.ldf(a, q), self.ldf(b, q), self.ldf(d, q));
                let p = self.b.ins().fmul(x, y);
                let p = self.fz(p);
                let s = self.b.ins().fadd(acc, p);
                self.ftz(s)
            }),
            Op::Dot { d, n, a, b } => each!(d, |q| {
                let n = (n as usize).clamp(1, 4);
                let (x, y) = (self.ldf(a[n - 1], q), self.ldf(b[n - 1], q));
                let p = self.b.ins().fmul(x, y);
                let mut acc = self.fz(p);
                for k in (0..n - 1).rev() {
                    let (x, y) = (self.ldf(a[k], q), self.ldf(b[k], q));
                    let p = self.b.ins().fmul(x, y);
                    let p = self.fz(p);
                    let s = self.b.ins().fadd(acc, p);
                    acc = self.fz(s);
                }
                self.iv(acc)
            }),
            Op::F1 { f, d, a } => match F1_CALLED.iter().position(|&g| g == f) {
                Some(func) => self.call_math(false, func, d, a, a, m),
                None => each!(d, |q| {
                    let x = self.ldf(a, q);
                    self.f1(f, x)
                }),
            },
            Op::F2 { f, d, a, b } => match F2_CALLED.iter().position(|&g| g == f) {
                Some(func) => self.call_math(true, func, d, a, b, m),
                None => each!(d, |q| {
                    let (x, y) = (self.ldf(a, q), self.ldf(b, q));
                    self.f2(f, x, y)
                }),
            },
            Op::F3 { f, d, a, b, c } => each!(d, |q| {
                let (x, y, z) = (self.ldf(a, q), self.ldf(b, q), self.ldf(c, q));
                self.f3(f, x, y, z)
            }),
            Op::Select { d, c, a, b } => each!(d, |q| {
                let (cv, x, y) = (self.ld(c, q), self.ld(a, q), self.ld(b, q));
                let z = self.is_zero(cv);
                self.b.ins().bitselect(z, y, x)
            }),
            Op::Uniform { d, word, float } => {
                let v = self.uniform_word(word);
                each!(d, |q| {
                    let v = self.b.ins().splat(I32X4, v);
                    self.ftz_word(float, v)
                })
            }
            Op::GatherUniform {
                d,
                word,
                off,
                max,
                float,
            } if word as u64 + max as u64 <= i32::MAX as u64 => {
                self.gather_uniform(d, word, off, max, float, m)
            }
            Op::Gather { d, base, off, max } => each!(d, |q| self.gather(base, off, max, q)),
            Op::Scatter { base, off, max, a } => {
                for q in 0..QUARTERS {
                    self.scatter(base, off, max, a, q)
                }
            }
            Op::DdX { d, a } => each!(d, |q| self.quad_diff(a, q, [1, 1, 3, 3], [0, 0, 2, 2])),
            Op::DdY { d, a } => each!(d, |q| self.quad_diff(a, q, [2, 3, 2, 3], [0, 1, 0, 1])),
            Op::Texture { index: t } => self.texture(t, index)?,
            // Only hooked runs (the reference interpreter) print.
            Op::Printf { .. } => {}
            Op::Call { .. }
            | Op::Ret { .. }
            | Op::Jump { .. }
            | Op::JumpIfNone { .. }
            | Op::LoopIter
            | Op::SaveMask { .. }
            | Op::RestoreMask { .. }
            | Op::AndMask { .. }
            | Op::AndNotMask { .. }
            | Op::Kill { .. }
            | Op::Discard { .. }
            | Op::SyncDiscard { .. } => {
                return Err(format!("control op {:?} where data was expected", ins.op))
            }
            // Uniform reads out of the prologue's range, noise.
            _ => self.call_step(index),
        });
        Ok(())
    }
}
