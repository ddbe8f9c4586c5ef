//! Expressions: constants, variable reads, assignments and `++`/`--`,
//! operators (arithmetic with scalar broadcasting, matrix products,
//! comparisons, `&&`/`||`/`?:` with side-effecting operands run under a
//! narrowed mask), conversions and constructors. Calls and built-ins are
//! handed to [`super::calls`] and [`super::builtins`].

use super::visit::has_effects;
use super::{const_bits, kind_of, unsupported, CtxKind, Lowerer, Val, R};
use crate::interface::kinds;
use crate::program::{Op, PrintfSite, Reg};
use glsl::ir::{BinaryOp, Expr, ExprKind, IncDec, UnaryOp};
use glsl::types::{ArraySize, Base, Scalar, Type};

impl<'m> Lowerer<'m> {
    /// Evaluates one operand of `?:` under the current mask and stores it
    /// into the result registers.
    fn store_operand(&mut self, e: &Expr, result: &[Reg]) -> R<()> {
        let v = self.expr(e)?;
        if v.len() != result.len() {
            return unsupported("?: operand of the wrong size");
        }
        for (&d, &a) in result.iter().zip(&v) {
            self.emit(Op::Store { d, a })?;
        }
        Ok(())
    }

    /// Evaluates operands left to right; a value is copied to temporaries
    /// when a later operand has side effects (which could change it).
    pub(super) fn operands(&mut self, es: &[&Expr]) -> R<Vec<Val>> {
        let mut out = Vec::with_capacity(es.len());
        for (i, e) in es.iter().enumerate() {
            let v = self.expr(e)?;
            let later = es[i + 1..].iter().any(|e| has_effects(e));
            out.push(if later { self.copy(&v)? } else { v });
        }
        Ok(out)
    }

    pub(super) fn expr(&mut self, e: &Expr) -> R<Val> {
        super::with_stack(|| self.expr_here(e))
    }

    fn expr_here(&mut self, e: &Expr) -> R<Val> {
        if e.ty.is_error() {
            return unsupported("expression with an error type");
        }
        match &e.kind {
            ExprKind::Const(v) => {
                let mut out = Vec::with_capacity(v.components.len());
                for c in &v.components {
                    out.push(self.konst(const_bits(*c))?);
                }
                Ok(out)
            }
            ExprKind::Global(_)
            | ExprKind::Local(_)
            | ExprKind::Index { .. }
            | ExprKind::Member { .. }
            | ExprKind::Swizzle { .. } => {
                let p = self.place(e)?;
                self.read(&p)
            }
            ExprKind::Unary { op, operand } => {
                let v = self.expr(operand)?;
                let kind = kind_of(operand.ty);
                let out = self.temps(v.len())?;
                for (&d, &a) in out.iter().zip(&v) {
                    self.emit(match (op, kind) {
                        (UnaryOp::Neg, Scalar::Float) => Op::FNeg { d, a },
                        (UnaryOp::Neg, _) => Op::INeg { d, a },
                        (UnaryOp::Not, _) => Op::Not { d, a },
                        (UnaryOp::BitNot, _) => Op::BitNot { d, a },
                    })?;
                }
                Ok(out)
            }
            ExprKind::Binary { op, left, right } => self.binary(*op, left, right, e.ty),
            ExprKind::Ternary {
                cond,
                accept,
                reject,
            } => self.ternary(cond, accept, reject, e.ty),
            ExprKind::Assign { op, target, value } => {
                let p = self.place(target)?;
                let v = match op {
                    None => self.expr(value)?,
                    Some(op) => {
                        let old = self.read(&p)?;
                        let old = if has_effects(value) {
                            self.copy(&old)?
                        } else {
                            old
                        };
                        let v = self.expr(value)?;
                        self.arith(*op, &old, p.ty, &v, value.ty, target.ty)?
                    }
                };
                self.write(&p, &v)?;
                Ok(v)
            }
            ExprKind::IncDec { op, target } => {
                let p = self.place(target)?;
                let old = self.read(&p)?;
                let old = self.copy(&old)?;
                let kind = kind_of(p.ty);
                let one = match kind {
                    Scalar::Float => self.fconst(1.0)?,
                    _ => self.konst(1)?,
                };
                let new = self.temps(old.len())?;
                let inc = matches!(op, IncDec::PreInc | IncDec::PostInc);
                for (&d, &a) in new.iter().zip(&old) {
                    self.emit(match (kind, inc) {
                        (Scalar::Float, true) => Op::FAdd { d, a, b: one },
                        (Scalar::Float, false) => Op::FSub { d, a, b: one },
                        (_, true) => Op::IAdd { d, a, b: one },
                        (_, false) => Op::ISub { d, a, b: one },
                    })?;
                }
                self.write(&p, &new)?;
                Ok(match op {
                    IncDec::PreInc | IncDec::PreDec => new,
                    IncDec::PostInc | IncDec::PostDec => old,
                })
            }
            ExprKind::Call { function, args } => self.call(*function, args),
            ExprKind::Builtin { function, args } => self.builtin(*function, args, e.ty),
            ExprKind::Construct { args } => self.construct(e.ty, args),
            // An implicitly sized array's length is the size its uses
            // gave it; a storage block's last member's is the buffer's.
            ExprKind::ArrayLength { array } => {
                let p = self.place(array)?;
                match p.ty.array {
                    Some(ArraySize::Sized(n)) => Ok(vec![self.konst(n)?]),
                    _ if p.mem.is_some() => Ok(vec![self.mem_length(&p)?]),
                    _ => unsupported("the length of an array whose size is not known"),
                }
            }
            ExprKind::DebugPrintf { format, args } => {
                let mut regs = Vec::new();
                for a in args {
                    regs.extend(self.expr(a)?);
                }
                let index = self.p.printfs.len() as u32;
                self.p.printfs.push(PrintfSite {
                    format: format.clone(),
                    args: regs,
                    span: e.span,
                });
                self.emit(Op::Printf { index })?;
                Ok(Vec::new())
            }
            ExprKind::Convert { operand } => {
                let v = self.expr(operand)?;
                let from = kinds(operand.ty, &self.m.structs);
                let to = kind_of(e.ty);
                let mut out = Vec::with_capacity(v.len());
                for (k, &a) in v.iter().enumerate() {
                    let f = from.get(k).copied().unwrap_or(Scalar::Float);
                    out.push(self.convert(a, f, to)?);
                }
                Ok(out)
            }
            ExprKind::Comma { left, right } => {
                self.expr(left)?;
                self.expr(right)
            }
        }
    }

    /// Converts one scalar register (GLSL 1.30 §5.4.1; int ↔ uint keep
    /// the bits).
    fn convert(&mut self, a: Reg, from: Scalar, to: Scalar) -> R<Reg> {
        use Scalar::*;
        let op: fn(Reg, Reg) -> Op = match (from, to) {
            (Float, Float) | (Int | Uint, Int | Uint) | (Bool, Bool) | (Bool, Int | Uint) => {
                return Ok(a)
            }
            (Float, Int) => |d, a| Op::FToI { d, a },
            (Float, Uint) => |d, a| Op::FToU { d, a },
            (Float, Bool) => |d, a| Op::FToB { d, a },
            (Int, Float) => |d, a| Op::IToF { d, a },
            (Uint, Float) => |d, a| Op::UToF { d, a },
            (Int | Uint, Bool) => |d, a| Op::IToB { d, a },
            (Bool, Float) => |d, a| Op::BToF { d, a },
        };
        let d = self.temp()?;
        self.emit(op(d, a))?;
        Ok(d)
    }

    /// Component-wise arithmetic with scalar broadcasting, or a
    /// linear-algebra product.
    fn arith(
        &mut self,
        op: BinaryOp,
        a: &[Reg],
        aty: Type,
        b: &[Reg],
        bty: Type,
        rty: Type,
    ) -> R<Val> {
        if op == BinaryOp::MatMul {
            return self.matmul(a, aty, b, bty);
        }
        let n = a.len().max(b.len());
        if !(a.len() == b.len() || a.len() == 1 || b.len() == 1) || n == 0 {
            return unsupported("operands of different sizes");
        }
        let kind = kind_of(rty);
        let out = self.temps(n)?;
        for (i, &d) in out.iter().enumerate() {
            let x = a[if a.len() == 1 { 0 } else { i }];
            let y = b[if b.len() == 1 { 0 } else { i }];
            self.emit(match (op, kind) {
                (BinaryOp::Add, Scalar::Float) => Op::FAdd { d, a: x, b: y },
                (BinaryOp::Sub, Scalar::Float) => Op::FSub { d, a: x, b: y },
                (BinaryOp::Mul, Scalar::Float) => Op::FMul { d, a: x, b: y },
                (BinaryOp::Div, Scalar::Float) => Op::FDiv { d, a: x, b: y },
                (BinaryOp::Add, _) => Op::IAdd { d, a: x, b: y },
                (BinaryOp::Sub, _) => Op::ISub { d, a: x, b: y },
                (BinaryOp::Mul, _) => Op::IMul { d, a: x, b: y },
                (BinaryOp::Div, Scalar::Uint) => Op::UDiv { d, a: x, b: y },
                (BinaryOp::Div, _) => Op::IDiv { d, a: x, b: y },
                (BinaryOp::Mod, Scalar::Uint) => Op::UMod { d, a: x, b: y },
                (BinaryOp::Mod, _) => Op::IMod { d, a: x, b: y },
                (BinaryOp::Shl, _) => Op::Shl { d, a: x, b: y },
                (BinaryOp::Shr, Scalar::Uint) => Op::ShrU { d, a: x, b: y },
                (BinaryOp::Shr, _) => Op::ShrS { d, a: x, b: y },
                (BinaryOp::BitAnd, _) => Op::BitAnd { d, a: x, b: y },
                (BinaryOp::BitOr, _) => Op::BitOr { d, a: x, b: y },
                (BinaryOp::BitXor, _) => Op::BitXor { d, a: x, b: y },
                _ => return unsupported(format!("{op:?} is not arithmetic")),
            })?;
        }
        Ok(out)
    }

    /// Matrix products without fused multiply-add, in the orders of
    /// Mesa's compiler (and of `glsl::consteval`): a product with a
    /// matrix on the left sums its columns scaled by the right side's
    /// components in index order (`m[0]·v.x + m[1]·v.y + …`); a vector
    /// times a matrix is a `dot` of the vector with each column (summed
    /// from the last component, [`Op::Dot`]).
    pub(super) fn matmul(&mut self, a: &[Reg], aty: Type, b: &[Reg], bty: Type) -> R<Val> {
        let (lc, lr) = match aty.base {
            Base::Matrix { cols, rows } => (cols as usize, rows as usize),
            Base::Vector(_, n) => (n as usize, 1),
            _ => return unsupported("matrix product of a non-matrix"),
        };
        let (rc, rr) = match bty.base {
            Base::Matrix { cols, rows } => (cols as usize, rows as usize),
            Base::Vector(_, n) => (1, n as usize),
            _ => return unsupported("matrix product of a non-matrix"),
        };
        if lc != rr || a.len() != lc * lr || b.len() != rc * rr {
            return unsupported("matrix product of mismatched shapes");
        }
        let out = self.temps(rc * lr)?;
        for c in 0..rc {
            for row in 0..lr {
                let d = out[c * lr + row];
                let mut pairs: Vec<(Reg, Reg)> =
                    (0..lc).map(|k| (a[k * lr + row], b[c * rr + k])).collect();
                if matches!(aty.base, Base::Matrix { .. }) {
                    pairs.reverse();
                }
                self.emit_dot(d, &pairs)?;
            }
        }
        Ok(out)
    }

    /// Whole-value equality: one bool register.
    fn equal(&mut self, a: &[Reg], b: &[Reg], ty: Type) -> R<Reg> {
        let ks = kinds(ty, &self.m.structs);
        if a.len() != b.len() {
            return unsupported("comparing values of different sizes");
        }
        let mut acc: Option<Reg> = None;
        for (i, (&x, &y)) in a.iter().zip(b).enumerate() {
            let d = self.temp()?;
            self.emit(match ks.get(i) {
                Some(Scalar::Float) => Op::FEq { d, a: x, b: y },
                _ => Op::IEq { d, a: x, b: y },
            })?;
            acc = Some(match acc {
                None => d,
                Some(prev) => self.emit_temp(|dst| Op::And {
                    d: dst,
                    a: prev,
                    b: d,
                })?,
            });
        }
        match acc {
            Some(r) => Ok(r),
            None => self.konst(1),
        }
    }

    fn binary(&mut self, op: BinaryOp, left: &Expr, right: &Expr, ty: Type) -> R<Val> {
        if matches!(op, BinaryOp::LogicalAnd | BinaryOp::LogicalOr) && has_effects(right) {
            // Lazy: the right operand runs only on the lanes it decides.
            let a = self.expr(left)?;
            let Some(&a) = a.first() else {
                return unsupported("logical operand without a value");
            };
            let result = self.emit_temp(|d| Op::Mov { d, a })?;
            let s = self.new_slot();
            self.emit(Op::SaveMask { slot: s })?;
            self.ctx.push((CtxKind::If, s));
            if op == BinaryOp::LogicalAnd {
                self.emit(Op::AndMask { c: result })?;
            } else {
                self.emit(Op::AndNotMask { slot: s, c: result })?;
            }
            let j = self.pc();
            self.emit(Op::JumpIfNone { target: 0 })?;
            let b = self.expr(right)?;
            let Some(&b) = b.first() else {
                return unsupported("logical operand without a value");
            };
            self.emit(Op::Store { d: result, a: b })?;
            let end = self.pc();
            self.patch(j, end);
            self.emit(Op::RestoreMask { slot: s })?;
            self.ctx.pop();
            return Ok(vec![result]);
        }
        let vals = self.operands(&[left, right])?;
        let (a, b) = (&vals[0], &vals[1]);
        let scalar = |v: &Val| v.first().copied();
        let two = |x: Option<Reg>, y: Option<Reg>| match (x, y) {
            (Some(x), Some(y)) => Ok((x, y)),
            _ => unsupported("comparison operand without a value"),
        };
        match op {
            BinaryOp::Add
            | BinaryOp::Sub
            | BinaryOp::Mul
            | BinaryOp::Div
            | BinaryOp::MatMul
            | BinaryOp::Mod
            | BinaryOp::Shl
            | BinaryOp::Shr
            | BinaryOp::BitAnd
            | BinaryOp::BitOr
            | BinaryOp::BitXor => self.arith(op, a, left.ty, b, right.ty, ty),
            BinaryOp::Less | BinaryOp::Greater | BinaryOp::LessEq | BinaryOp::GreaterEq => {
                let (x, y) = two(scalar(a), scalar(b))?;
                let d = self.temp()?;
                // `a > b` is `b < a`, `a >= b` is `b <= a`.
                let (a, b) = match op {
                    BinaryOp::Less | BinaryOp::LessEq => (x, y),
                    _ => (y, x),
                };
                let strict = matches!(op, BinaryOp::Less | BinaryOp::Greater);
                self.emit(match (kind_of(left.ty), strict) {
                    (Scalar::Float, true) => Op::FLt { d, a, b },
                    (Scalar::Float, false) => Op::FLe { d, a, b },
                    (Scalar::Uint, true) => Op::ULt { d, a, b },
                    (Scalar::Uint, false) => Op::ULe { d, a, b },
                    (_, true) => Op::ILt { d, a, b },
                    (_, false) => Op::ILe { d, a, b },
                })?;
                Ok(vec![d])
            }
            BinaryOp::Equal | BinaryOp::NotEqual => {
                let eq = self.equal(a, b, left.ty)?;
                if op == BinaryOp::Equal {
                    Ok(vec![eq])
                } else {
                    let d = self.emit_temp(|d| Op::Not { d, a: eq })?;
                    Ok(vec![d])
                }
            }
            BinaryOp::LogicalAnd | BinaryOp::LogicalOr | BinaryOp::LogicalXor => {
                let (x, y) = two(scalar(a), scalar(b))?;
                let d = self.temp()?;
                self.emit(match op {
                    BinaryOp::LogicalAnd => Op::And { d, a: x, b: y },
                    BinaryOp::LogicalOr => Op::Or { d, a: x, b: y },
                    _ => Op::Xor { d, a: x, b: y },
                })?;
                Ok(vec![d])
            }
        }
    }

    fn ternary(&mut self, cond: &Expr, accept: &Expr, reject: &Expr, ty: Type) -> R<Val> {
        if has_effects(accept) || has_effects(reject) {
            let c = self.expr(cond)?;
            let c = self.copy(&c[..1.min(c.len())])?;
            let Some(&c) = c.first() else {
                return unsupported("condition without a value");
            };
            let n = self.size(ty)?;
            let result = self.temps(n)?;
            let s = self.new_slot();
            self.emit(Op::SaveMask { slot: s })?;
            self.ctx.push((CtxKind::If, s));
            self.emit(Op::AndMask { c })?;
            let j1 = self.pc();
            self.emit(Op::JumpIfNone { target: 0 })?;
            self.store_operand(accept, &result)?;
            let else_at = self.pc();
            self.patch(j1, else_at);
            self.emit(Op::AndNotMask { slot: s, c })?;
            let j2 = self.pc();
            self.emit(Op::JumpIfNone { target: 0 })?;
            self.store_operand(reject, &result)?;
            let end = self.pc();
            self.patch(j2, end);
            self.emit(Op::RestoreMask { slot: s })?;
            self.ctx.pop();
            return Ok(result);
        }
        let vals = self.operands(&[cond, accept, reject])?;
        let (Some(&c), a, b) = (vals[0].first(), &vals[1], &vals[2]) else {
            return unsupported("condition without a value");
        };
        if a.len() != b.len() {
            return unsupported("?: operands of different sizes");
        }
        let out = self.temps(a.len())?;
        for ((&d, &x), &y) in out.iter().zip(a).zip(b) {
            self.emit(Op::Select { d, c, a: x, b: y })?;
        }
        Ok(out)
    }

    fn construct(&mut self, ty: Type, args: &[Expr]) -> R<Val> {
        let refs: Vec<&Expr> = args.iter().collect();
        let vals = self.operands(&refs)?;
        if ty.is_array() || ty.is_struct() {
            return Ok(vals.into_iter().flatten().collect());
        }
        let target = kind_of(ty);
        let size = self.size(ty)?;
        // Scalar kind of every argument component.
        let mut comps: Vec<(Reg, Scalar)> = Vec::new();
        for (a, v) in args.iter().zip(&vals) {
            let ks = kinds(a.ty, &self.m.structs);
            for (k, &r) in v.iter().enumerate() {
                comps.push((r, ks.get(k).copied().unwrap_or(Scalar::Float)));
            }
        }
        let single = args.len() == 1 && comps.len() == 1;
        match ty.base {
            Base::Scalar(_) | Base::Vector(..) if single => {
                let (r, k) = comps[0];
                let c = self.convert(r, k, target)?;
                return Ok(vec![c; size]);
            }
            Base::Matrix { cols, rows } => {
                let (cols, rows) = (cols as usize, rows as usize);
                if single {
                    let (r, k) = comps[0];
                    let d = self.convert(r, k, Scalar::Float)?;
                    let zero = self.fconst(0.0)?;
                    let mut out = vec![zero; size];
                    for i in 0..cols.min(rows) {
                        out[i * rows + i] = d;
                    }
                    return Ok(out);
                }
                if let (1, Some(Base::Matrix { cols: sc, rows: sr })) =
                    (args.len(), args.first().map(|a| a.ty.base))
                {
                    let (sc, sr) = (sc as usize, sr as usize);
                    let zero = self.fconst(0.0)?;
                    let one = self.fconst(1.0)?;
                    let mut out = Vec::with_capacity(size);
                    for c in 0..cols {
                        for r in 0..rows {
                            out.push(if c < sc && r < sr {
                                vals[0].get(c * sr + r).copied().unwrap_or(zero)
                            } else if c == r {
                                one
                            } else {
                                zero
                            });
                        }
                    }
                    return Ok(out);
                }
            }
            Base::Scalar(_) | Base::Vector(..) => {}
            _ => return unsupported("constructor of an unsupported type"),
        }
        if comps.len() < size {
            return unsupported("constructor with too few components");
        }
        let mut out = Vec::with_capacity(size);
        for &(r, k) in comps.iter().take(size) {
            out.push(self.convert(r, k, target)?);
        }
        Ok(out)
    }
}
