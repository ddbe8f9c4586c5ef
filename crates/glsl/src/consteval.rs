//! Constant folding of typed IR expressions.
//!
//! GLSL needs compile-time values for array sizes, `const` initializers and
//! (in the piglit suite) for checking built-in functions. [`fold`] evaluates
//! an IR expression whose leaves are all constants; it returns `None` as soon
//! as something is not constant (a variable, a call of a user function, an
//! assignment) or cannot be evaluated (integer division by zero).
//!
//! Semantic analysis substitutes references to `const` variables with
//! [`ExprKind::Const`] before folding, so this module never looks variables
//! up. The arithmetic is the same the executor performs: IEEE-754 single
//! precision without contraction, integer arithmetic wrapping at 32 bits,
//! conversions as GLSL 1.30 §5.4.1 defines them. Integer operators whose
//! result the spec leaves undefined fold to the executor's values: shift
//! amounts are taken modulo 32, `i32::MIN % -1` is 0; a remainder or
//! quotient by zero is not folded (the executor gives 0).

use crate::builtins;
use crate::ir::{BinaryOp, ConstScalar, ConstValue, Expr, ExprKind, UnaryOp};
use crate::types::{ArraySize, Base, Scalar, StructDef, Type};

/// Number of scalar components of `ty` in the flattened layout of
/// [`ConstValue`]. Unsized arrays count as empty.
pub fn flat_size(ty: Type, structs: &[StructDef]) -> usize {
    let elem = match ty.base {
        Base::Void | Base::Error | Base::Sampler(_) => 0,
        Base::Scalar(_) => 1,
        Base::Vector(_, n) => n as usize,
        Base::Matrix { cols, rows } => cols as usize * rows as usize,
        Base::Struct(id) => structs
            .get(id.0 as usize)
            .map(|s| s.members.iter().map(|m| flat_size(m.ty, structs)).sum())
            .unwrap_or(0),
    };
    match ty.array {
        None => elem,
        Some(ArraySize::Sized(n)) => elem.saturating_mul(n as usize),
        Some(ArraySize::Unsized) => 0,
    }
}

/// Folds `expr` to a constant, if it is one.
pub fn fold(expr: &Expr, structs: &[StructDef]) -> Option<ConstValue> {
    let ty = expr.ty;
    let components = match &expr.kind {
        ExprKind::Const(v) => return Some(v.clone()),
        ExprKind::Unary { op, operand } => {
            let v = fold(operand, structs)?;
            v.components
                .iter()
                .map(|c| unary(*op, *c))
                .collect::<Option<Vec<_>>>()?
        }
        ExprKind::Binary { op, left, right } => {
            let l = fold(left, structs)?;
            let r = fold(right, structs)?;
            binary(*op, &l, &r, ty)?
        }
        ExprKind::Ternary {
            cond,
            accept,
            reject,
        } => {
            let c = fold(cond, structs)?;
            let a = fold(accept, structs)?;
            let b = fold(reject, structs)?;
            match c.components.first() {
                Some(ConstScalar::Bool(true)) => a.components,
                Some(ConstScalar::Bool(false)) => b.components,
                _ => return None,
            }
        }
        ExprKind::Index { base, index } => {
            let b = fold(base, structs)?;
            let i = match fold(index, structs)?.components.first() {
                Some(ConstScalar::Int(i)) => *i,
                Some(ConstScalar::Uint(u)) => i32::try_from(*u).ok()?,
                _ => return None,
            };
            let width = flat_size(ty, structs);
            if i < 0 || width == 0 {
                return None;
            }
            let start = (i as usize).checked_mul(width)?;
            b.components.get(start..start.checked_add(width)?)?.to_vec()
        }
        ExprKind::Swizzle {
            base,
            components,
            count,
        } => {
            let b = fold(base, structs)?;
            components[..(*count as usize).min(4)]
                .iter()
                .map(|&c| b.components.get(c as usize).copied())
                .collect::<Option<Vec<_>>>()?
        }
        ExprKind::Member { base, index } => {
            let b = fold(base, structs)?;
            let Base::Struct(id) = base.ty.base else {
                return None;
            };
            let def = structs.get(id.0 as usize)?;
            let start: usize = def
                .members
                .iter()
                .take(*index as usize)
                .map(|m| flat_size(m.ty, structs))
                .sum();
            let width = flat_size(def.members.get(*index as usize)?.ty, structs);
            b.components.get(start..start + width)?.to_vec()
        }
        ExprKind::Construct { args } => {
            let args = args
                .iter()
                .map(|a| fold(a, structs))
                .collect::<Option<Vec<_>>>()?;
            construct(ty, &args, structs)?
        }
        ExprKind::Convert { operand } => {
            let v = fold(operand, structs)?;
            let to = ty.scalar()?;
            v.components.iter().map(|c| convert(*c, to)).collect()
        }
        ExprKind::Builtin { function, args } => {
            let args = args
                .iter()
                .map(|a| fold(a, structs))
                .collect::<Option<Vec<_>>>()?;
            return builtins::eval_builtin(*function, &args, ty);
        }
        ExprKind::Global(_)
        | ExprKind::Local(_)
        | ExprKind::Assign { .. }
        | ExprKind::IncDec { .. }
        | ExprKind::Call { .. }
        | ExprKind::DebugPrintf { .. }
        | ExprKind::ArrayLength { .. }
        | ExprKind::Comma { .. } => return None,
    };
    if components.len() != flat_size(ty, structs) {
        return None;
    }
    Some(ConstValue { ty, components })
}

/// Converts one scalar as constructors do (GLSL 1.30 §5.4.1): float→int
/// and float→uint truncate toward zero, int↔uint keep the bit pattern,
/// anything→bool is "not zero", bool→number is 0/1.
pub fn convert(c: ConstScalar, to: Scalar) -> ConstScalar {
    use ConstScalar as C;
    match (c, to) {
        (C::Float(f), Scalar::Float) => C::Float(f),
        (C::Float(f), Scalar::Int) => C::Int(float_to_int(f)),
        (C::Float(f), Scalar::Uint) => C::Uint(float_to_uint(f)),
        (C::Float(f), Scalar::Bool) => C::Bool(f != 0.0),
        (C::Int(i), Scalar::Float) => C::Float(i as f32),
        (C::Int(i), Scalar::Int) => C::Int(i),
        (C::Int(i), Scalar::Uint) => C::Uint(i as u32),
        (C::Int(i), Scalar::Bool) => C::Bool(i != 0),
        (C::Uint(u), Scalar::Float) => C::Float(u as f32),
        (C::Uint(u), Scalar::Int) => C::Int(u as i32),
        (C::Uint(u), Scalar::Uint) => C::Uint(u),
        (C::Uint(u), Scalar::Bool) => C::Bool(u != 0),
        (C::Bool(b), Scalar::Float) => C::Float(if b { 1.0 } else { 0.0 }),
        (C::Bool(b), Scalar::Int) => C::Int(b as i32),
        (C::Bool(b), Scalar::Uint) => C::Uint(b as u32),
        (C::Bool(b), Scalar::Bool) => C::Bool(b),
    }
}

/// float→int with truncation; NaN gives 0 and out-of-range values saturate
/// (GLSL leaves them undefined; this choice is the executor's too).
pub fn float_to_int(f: f32) -> i32 {
    // `as` saturates and maps NaN to 0 in Rust, on every platform.
    f as i32
}

/// float→uint with truncation; NaN and negative values give 0, values
/// from 2^32 on give `u32::MAX` (undefined in GLSL; the executor's choice
/// too).
pub fn float_to_uint(f: f32) -> u32 {
    f as u32
}

/// A shift amount of either signedness, modulo 32 (see [`BinaryOp::Shl`]).
fn shift_amount(c: ConstScalar) -> Option<u32> {
    match c {
        ConstScalar::Int(i) => Some(i as u32 & 31),
        ConstScalar::Uint(u) => Some(u & 31),
        _ => None,
    }
}

fn shift(op: BinaryOp, a: ConstScalar, b: ConstScalar) -> Option<ConstScalar> {
    let n = shift_amount(b)?;
    Some(match (op, a) {
        (BinaryOp::Shl, ConstScalar::Int(x)) => ConstScalar::Int(x << n),
        (BinaryOp::Shl, ConstScalar::Uint(x)) => ConstScalar::Uint(x << n),
        (BinaryOp::Shr, ConstScalar::Int(x)) => ConstScalar::Int(x >> n),
        (BinaryOp::Shr, ConstScalar::Uint(x)) => ConstScalar::Uint(x >> n),
        _ => return None,
    })
}

fn unary(op: UnaryOp, c: ConstScalar) -> Option<ConstScalar> {
    Some(match (op, c) {
        (UnaryOp::Neg, ConstScalar::Float(f)) => ConstScalar::Float(-f),
        (UnaryOp::Neg, ConstScalar::Int(i)) => ConstScalar::Int(i.wrapping_neg()),
        (UnaryOp::Neg, ConstScalar::Uint(u)) => ConstScalar::Uint(u.wrapping_neg()),
        (UnaryOp::BitNot, ConstScalar::Int(i)) => ConstScalar::Int(!i),
        (UnaryOp::BitNot, ConstScalar::Uint(u)) => ConstScalar::Uint(!u),
        (UnaryOp::Not, ConstScalar::Bool(b)) => ConstScalar::Bool(!b),
        _ => return None,
    })
}

fn scalar_op(op: BinaryOp, a: ConstScalar, b: ConstScalar) -> Option<ConstScalar> {
    use ConstScalar::*;
    Some(match (a, b) {
        (Float(x), Float(y)) => Float(crate::math::flush_denormal(match op {
            BinaryOp::Add => x + y,
            BinaryOp::Sub => x - y,
            BinaryOp::Mul => x * y,
            BinaryOp::Div => x / y,
            _ => return None,
        })),
        (Int(x), Int(y)) => Int(match op {
            BinaryOp::Add => x.wrapping_add(y),
            BinaryOp::Sub => x.wrapping_sub(y),
            BinaryOp::Mul => x.wrapping_mul(y),
            BinaryOp::Div => {
                if y == 0 {
                    return None;
                }
                x.wrapping_div(y)
            }
            BinaryOp::Mod => {
                if y == 0 {
                    return None;
                }
                x.wrapping_rem(y)
            }
            BinaryOp::BitAnd => x & y,
            BinaryOp::BitOr => x | y,
            BinaryOp::BitXor => x ^ y,
            _ => return None,
        }),
        (Uint(x), Uint(y)) => Uint(match op {
            BinaryOp::Add => x.wrapping_add(y),
            BinaryOp::Sub => x.wrapping_sub(y),
            BinaryOp::Mul => x.wrapping_mul(y),
            BinaryOp::Div => x.checked_div(y)?,
            BinaryOp::Mod => x.checked_rem(y)?,
            BinaryOp::BitAnd => x & y,
            BinaryOp::BitOr => x | y,
            BinaryOp::BitXor => x ^ y,
            _ => return None,
        }),
        _ => return None,
    })
}

fn as_f32(c: ConstScalar) -> Option<f32> {
    match c {
        ConstScalar::Float(f) => Some(f),
        _ => None,
    }
}

fn as_bool(c: ConstScalar) -> Option<bool> {
    match c {
        ConstScalar::Bool(b) => Some(b),
        _ => None,
    }
}

fn scalar_eq(a: ConstScalar, b: ConstScalar) -> bool {
    match (a, b) {
        (ConstScalar::Float(x), ConstScalar::Float(y)) => x == y,
        (ConstScalar::Int(x), ConstScalar::Int(y)) => x == y,
        (ConstScalar::Uint(x), ConstScalar::Uint(y)) => x == y,
        (ConstScalar::Bool(x), ConstScalar::Bool(y)) => x == y,
        _ => false,
    }
}

fn binary(op: BinaryOp, l: &ConstValue, r: &ConstValue, ty: Type) -> Option<Vec<ConstScalar>> {
    let (lc, rc) = (&l.components, &r.components);
    match op {
        BinaryOp::Add
        | BinaryOp::Sub
        | BinaryOp::Mul
        | BinaryOp::Div
        | BinaryOp::Mod
        | BinaryOp::BitAnd
        | BinaryOp::BitOr
        | BinaryOp::BitXor
        | BinaryOp::Shl
        | BinaryOp::Shr => {
            // Component-wise with broadcasting of a scalar operand.
            let n = lc.len().max(rc.len());
            if !(lc.len() == rc.len() || lc.len() == 1 || rc.len() == 1) {
                return None;
            }
            (0..n)
                .map(|i| {
                    let a = *lc.get(if lc.len() == 1 { 0 } else { i })?;
                    let b = *rc.get(if rc.len() == 1 { 0 } else { i })?;
                    match op {
                        BinaryOp::Shl | BinaryOp::Shr => shift(op, a, b),
                        _ => scalar_op(op, a, b),
                    }
                })
                .collect()
        }
        BinaryOp::MatMul => matmul(l, r, ty),
        BinaryOp::Less | BinaryOp::Greater | BinaryOp::LessEq | BinaryOp::GreaterEq => {
            let (a, b) = (*lc.first()?, *rc.first()?);
            let ord = match (a, b) {
                (ConstScalar::Float(x), ConstScalar::Float(y)) => x.partial_cmp(&y),
                (ConstScalar::Int(x), ConstScalar::Int(y)) => Some(x.cmp(&y)),
                (ConstScalar::Uint(x), ConstScalar::Uint(y)) => Some(x.cmp(&y)),
                _ => return None,
            };
            use std::cmp::Ordering::*;
            let v = match (op, ord) {
                (_, None) => false,
                (BinaryOp::Less, Some(o)) => o == Less,
                (BinaryOp::Greater, Some(o)) => o == Greater,
                (BinaryOp::LessEq, Some(o)) => o != Greater,
                (_, Some(o)) => o != Less,
            };
            Some(vec![ConstScalar::Bool(v)])
        }
        BinaryOp::Equal | BinaryOp::NotEqual => {
            let eq = lc.len() == rc.len() && lc.iter().zip(rc).all(|(a, b)| scalar_eq(*a, *b));
            Some(vec![ConstScalar::Bool(eq == (op == BinaryOp::Equal))])
        }
        BinaryOp::LogicalAnd | BinaryOp::LogicalOr | BinaryOp::LogicalXor => {
            let (a, b) = (as_bool(*lc.first()?)?, as_bool(*rc.first()?)?);
            let v = match op {
                BinaryOp::LogicalAnd => a && b,
                BinaryOp::LogicalOr => a || b,
                _ => a != b,
            };
            Some(vec![ConstScalar::Bool(v)])
        }
    }
}

/// Shape of a matrix or vector operand of a linear-algebra product:
/// (columns, rows), a vector on the left being a row and on the right a
/// column.
fn matmul(l: &ConstValue, r: &ConstValue, ty: Type) -> Option<Vec<ConstScalar>> {
    let lf: Vec<f32> = l
        .components
        .iter()
        .map(|c| as_f32(*c))
        .collect::<Option<_>>()?;
    let rf: Vec<f32> = r
        .components
        .iter()
        .map(|c| as_f32(*c))
        .collect::<Option<_>>()?;
    // (cols, rows) of each side.
    let (lc, lr) = match l.ty.base {
        Base::Matrix { cols, rows } => (cols as usize, rows as usize),
        Base::Vector(_, n) => (n as usize, 1),
        _ => return None,
    };
    let (rc, rr) = match r.ty.base {
        Base::Matrix { cols, rows } => (cols as usize, rows as usize),
        Base::Vector(_, n) => (1, n as usize),
        _ => return None,
    };
    if lc != rr || lf.len() != lc * lr || rf.len() != rc * rr {
        return None;
    }
    let mut out = Vec::with_capacity(rc * lr);
    for c in 0..rc {
        for row in 0..lr {
            // No fused multiply-add, in the executor's orders: a matrix on
            // the left sums its scaled columns in index order, a vector on
            // the left is a `dot` with each column (last component first).
            let prod = |k: usize| crate::math::flush_denormal(lf[k * lr + row] * rf[c * rr + k]);
            let mut order: Vec<usize> = (0..lc).collect();
            if !matches!(l.ty.base, Base::Matrix { .. }) {
                order.reverse();
            }
            let mut s = prod(order[0]);
            for &k in &order[1..] {
                s = crate::math::flush_denormal(s + prod(k));
            }
            out.push(ConstScalar::Float(s));
        }
    }
    let expect = match ty.base {
        Base::Matrix { cols, rows } => cols as usize * rows as usize,
        Base::Vector(_, n) => n as usize,
        _ => return None,
    };
    (out.len() == expect).then_some(out)
}

fn construct(ty: Type, args: &[ConstValue], structs: &[StructDef]) -> Option<Vec<ConstScalar>> {
    // Arrays and structs: the arguments are the elements / members.
    if ty.is_array() || ty.is_struct() {
        return Some(
            args.iter()
                .flat_map(|a| a.components.iter().copied())
                .collect(),
        );
    }
    let target = ty.scalar()?;
    let size = flat_size(ty, structs);
    let first = args.first()?;
    match ty.base {
        Base::Scalar(_) | Base::Vector(..) => {
            if args.len() == 1 && first.components.len() == 1 {
                let c = convert(first.components[0], target);
                return Some(vec![c; size]);
            }
        }
        Base::Matrix { cols, rows } => {
            if args.len() == 1 && first.components.len() == 1 {
                // A scalar fills the diagonal.
                let d = convert(first.components[0], Scalar::Float);
                let mut out = vec![ConstScalar::Float(0.0); size];
                for i in 0..cols.min(rows) as usize {
                    out[i * rows as usize + i] = d;
                }
                return Some(out);
            }
            if args.len() == 1 {
                if let Base::Matrix { cols: sc, rows: sr } = first.ty.base {
                    // Matrix from matrix: copy the overlap, identity elsewhere.
                    let mut out = Vec::with_capacity(size);
                    for c in 0..cols as usize {
                        for r in 0..rows as usize {
                            let v = if c < sc as usize && r < sr as usize {
                                first.components[c * sr as usize + r]
                            } else {
                                ConstScalar::Float(if c == r { 1.0 } else { 0.0 })
                            };
                            out.push(v);
                        }
                    }
                    return Some(out);
                }
            }
        }
        _ => return None,
    }
    // Components consumed in order, converted one by one.
    let out: Vec<ConstScalar> = args
        .iter()
        .flat_map(|a| a.components.iter().copied())
        .take(size)
        .map(|c| convert(c, target))
        .collect();
    (out.len() == size).then_some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::source::Span;

    fn c(ty: Type, comps: Vec<ConstScalar>) -> Expr {
        Expr {
            kind: ExprKind::Const(ConstValue {
                ty,
                components: comps,
            }),
            ty,
            span: Span::default(),
        }
    }

    fn f(x: f32) -> ConstScalar {
        ConstScalar::Float(x)
    }

    fn e(kind: ExprKind, ty: Type) -> Expr {
        Expr {
            kind,
            ty,
            span: Span::default(),
        }
    }

    #[test]
    fn matrix_times_vector() {
        // mat2(1,2,3,4) is columns (1,2) and (3,4); times vec2(1,1) = (4,6).
        let m = c(Type::mat(2, 2), vec![f(1.), f(2.), f(3.), f(4.)]);
        let v = c(Type::vec(Scalar::Float, 2), vec![f(1.), f(1.)]);
        let x = e(
            ExprKind::Binary {
                op: BinaryOp::MatMul,
                left: Box::new(m),
                right: Box::new(v),
            },
            Type::vec(Scalar::Float, 2),
        );
        assert_eq!(fold(&x, &[]).unwrap().components, vec![f(4.), f(6.)]);
    }

    #[test]
    fn vector_times_matrix() {
        let m = c(Type::mat(2, 2), vec![f(1.), f(2.), f(3.), f(4.)]);
        let v = c(Type::vec(Scalar::Float, 2), vec![f(1.), f(1.)]);
        let x = e(
            ExprKind::Binary {
                op: BinaryOp::MatMul,
                left: Box::new(v),
                right: Box::new(m),
            },
            Type::vec(Scalar::Float, 2),
        );
        assert_eq!(fold(&x, &[]).unwrap().components, vec![f(3.), f(7.)]);
    }

    #[test]
    fn constructors() {
        let one = c(Type::FLOAT, vec![f(2.)]);
        let m = e(
            ExprKind::Construct {
                args: vec![one.clone()],
            },
            Type::mat(2, 3),
        );
        assert_eq!(
            fold(&m, &[]).unwrap().components,
            vec![f(2.), f(0.), f(0.), f(0.), f(2.), f(0.)]
        );
        let i = c(Type::INT, vec![ConstScalar::Int(-3)]);
        let v = e(
            ExprKind::Construct { args: vec![i, one] },
            Type::vec(Scalar::Float, 2),
        );
        assert_eq!(fold(&v, &[]).unwrap().components, vec![f(-3.), f(2.)]);
        let b = e(
            ExprKind::Construct {
                args: vec![c(Type::FLOAT, vec![f(-0.5)])],
            },
            Type::INT,
        );
        assert_eq!(fold(&b, &[]).unwrap().components, vec![ConstScalar::Int(0)]);
    }

    #[test]
    fn integer_division_by_zero_is_not_constant() {
        let x = e(
            ExprKind::Binary {
                op: BinaryOp::Div,
                left: Box::new(c(Type::INT, vec![ConstScalar::Int(1)])),
                right: Box::new(c(Type::INT, vec![ConstScalar::Int(0)])),
            },
            Type::INT,
        );
        assert_eq!(fold(&x, &[]), None);
    }

    #[test]
    fn swizzle_and_index() {
        let v = c(Type::vec(Scalar::Float, 3), vec![f(1.), f(2.), f(3.)]);
        let s = e(
            ExprKind::Swizzle {
                base: Box::new(v.clone()),
                components: [2, 0, 0, 0],
                count: 2,
            },
            Type::vec(Scalar::Float, 2),
        );
        assert_eq!(fold(&s, &[]).unwrap().components, vec![f(3.), f(1.)]);
        let i = e(
            ExprKind::Index {
                base: Box::new(v),
                index: Box::new(c(Type::INT, vec![ConstScalar::Int(5)])),
            },
            Type::FLOAT,
        );
        assert_eq!(fold(&i, &[]), None);
    }

    fn int_op(op: BinaryOp, a: ConstScalar, b: ConstScalar, ty: Type) -> Option<ConstScalar> {
        let ta = if matches!(a, ConstScalar::Uint(_)) {
            Type::UINT
        } else {
            Type::INT
        };
        let tb = if matches!(b, ConstScalar::Uint(_)) {
            Type::UINT
        } else {
            Type::INT
        };
        let x = e(
            ExprKind::Binary {
                op,
                left: Box::new(c(ta, vec![a])),
                right: Box::new(c(tb, vec![b])),
            },
            ty,
        );
        fold(&x, &[]).map(|v| v.components[0])
    }

    #[test]
    fn integer_operators() {
        use ConstScalar::{Int, Uint};
        let i = |op, a, b| int_op(op, Int(a), Int(b), Type::INT);
        let u = |op, a, b| int_op(op, Uint(a), Uint(b), Type::UINT);
        assert_eq!(i(BinaryOp::Mod, -7, 3), Some(Int(-1)));
        assert_eq!(i(BinaryOp::Mod, i32::MIN, -1), Some(Int(0)));
        assert_eq!(i(BinaryOp::Mod, 5, 0), None);
        assert_eq!(u(BinaryOp::Mod, 7, 0), None);
        assert_eq!(u(BinaryOp::Div, 0xffff_fffe, 2), Some(Uint(0x7fff_ffff)));
        assert_eq!(u(BinaryOp::Sub, 0, 1), Some(Uint(u32::MAX)));
        assert_eq!(i(BinaryOp::Shr, -8, 1), Some(Int(-4)));
        assert_eq!(u(BinaryOp::Shr, 0x8000_0000, 31), Some(Uint(1)));
        // Amounts modulo 32, negative ones included.
        assert_eq!(i(BinaryOp::Shl, 1, 33), Some(Int(2)));
        assert_eq!(i(BinaryOp::Shl, 1, -1), Some(Int(i32::MIN)));
        assert_eq!(
            int_op(BinaryOp::Shl, Uint(1), Int(4), Type::UINT),
            Some(Uint(16))
        );
        assert_eq!(i(BinaryOp::BitXor, 6, 3), Some(Int(5)));
        assert_eq!(u(BinaryOp::BitAnd, 6, 3), Some(Uint(2)));
        assert_eq!(u(BinaryOp::BitOr, 6, 3), Some(Uint(7)));
        // Mixed signedness is not folded (analysis never builds it).
        assert_eq!(int_op(BinaryOp::BitAnd, Int(1), Uint(1), Type::INT), None);
        let not = e(
            ExprKind::Unary {
                op: UnaryOp::BitNot,
                operand: Box::new(c(Type::UINT, vec![Uint(5)])),
            },
            Type::UINT,
        );
        assert_eq!(fold(&not, &[]).unwrap().components, vec![Uint(!5)]);
    }

    #[test]
    fn unsigned_conversions() {
        use ConstScalar::*;
        assert_eq!(convert(Int(-1), Scalar::Uint), Uint(u32::MAX));
        assert_eq!(convert(Uint(u32::MAX), Scalar::Int), Int(-1));
        assert_eq!(convert(Float(-3.5), Scalar::Uint), Uint(0));
        assert_eq!(convert(Float(3.9), Scalar::Uint), Uint(3));
        assert_eq!(convert(Float(f32::NAN), Scalar::Uint), Uint(0));
        assert_eq!(convert(Float(1e20), Scalar::Uint), Uint(u32::MAX));
        assert_eq!(
            convert(Uint(u32::MAX), Scalar::Float),
            Float(4_294_967_296.0)
        );
        assert_eq!(convert(Uint(2), Scalar::Bool), Bool(true));
        assert_eq!(convert(Bool(true), Scalar::Uint), Uint(1));
    }
}
