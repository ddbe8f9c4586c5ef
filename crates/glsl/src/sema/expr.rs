//! Expressions: names, operators, implicit conversions, assignments and
//! the conditional operator (GLSL 1.20 §5); indexing, fields, swizzles
//! and l-values are [`super::access`], constructors [`super::construct`].

use super::scope::{Symbol, Var};
use super::{const_expr, error_expr, Analyzer};
use crate::ast::{self, AssignOp, Callee, ExprKind as A, UnaryOp as AU};
use crate::diag::Code;
use crate::ir::{self, BinaryOp as B, ExprKind as K, IncDec};
use crate::lang::{Feature, Version};
use crate::limits::MAX_NESTING_DEPTH;
use crate::source::Span;
use crate::types::{ArraySize, Base, Scalar, Type};

/// §4.1.10 of GLSL 1.20 to 3.30: int or uint → float, ivecN or uvecN →
/// vecN, nothing else (never int ↔ uint, never for arrays or structs as
/// wholes). uint exists only from 1.30 on, so one table serves every
/// version; 1.10 has no implicit conversions at all (see `coerce`).
pub(crate) fn implicitly_converts(from: Type, to: Type) -> bool {
    if from.is_array() || to.is_array() {
        return false;
    }
    match (from.base, to.base) {
        (Base::Scalar(Scalar::Int | Scalar::Uint), Base::Scalar(Scalar::Float)) => true,
        (Base::Vector(Scalar::Int | Scalar::Uint, n), Base::Vector(Scalar::Float, m)) => n == m,
        _ => false,
    }
}

/// The scalar kind of an int or uint scalar or vector (the operands of the
/// integer operators, GLSL 1.30 §5.9).
fn int_kind(t: Type) -> Option<Scalar> {
    match (t.array, t.base) {
        (None, Base::Scalar(s) | Base::Vector(s, _)) if matches!(s, Scalar::Int | Scalar::Uint) => {
            Some(s)
        }
        _ => None,
    }
}

/// The result type of `%`, `&`, `|`, `^` (§5.9: one signedness, vectors of
/// one size, a scalar applied to every component) or of a shift (any
/// signedness, the left operand's type; a scalar left operand needs a
/// scalar amount, a vector one a scalar or a vector of its size).
fn int_op_type(shift: bool, l: Type, r: Type) -> Option<Type> {
    let (ls, rs) = (int_kind(l)?, int_kind(r)?);
    if shift {
        let ok = r.is_scalar() || (l.is_vector() && r.vector_size() == l.vector_size());
        return ok.then_some(l);
    }
    if ls != rs {
        return None;
    }
    if l.is_scalar() {
        Some(r)
    } else if r.is_scalar() || l == r {
        Some(l)
    } else {
        None
    }
}

pub(super) fn mk(kind: K, ty: Type, span: Span) -> ir::Expr {
    ir::Expr { kind, ty, span }
}

/// True for int/uint/float scalars, vectors and matrices (not arrays).
fn is_numeric(t: Type) -> bool {
    matches!(t.scalar(), Some(Scalar::Int | Scalar::Uint | Scalar::Float))
}

impl Analyzer {
    /// An expression used for its value. Unsized arrays are only usable
    /// indexed with a constant.
    pub fn rvalue(&mut self, e: &ast::Expr) -> ir::Expr {
        let v = self.expr_any(e);
        self.check_memory_access(&v, false, true);
        self.reject_unsized(v)
    }

    pub(super) fn reject_unsized(&mut self, v: ir::Expr) -> ir::Expr {
        if v.ty.array == Some(ArraySize::Unsized) {
            self.error(
                Code::BadArraySize,
                v.span,
                "an array without a size can only be indexed with constants",
            )
            .notes
            .push("declare the array with an explicit size".into());
            return error_expr(v.span);
        }
        v
    }

    pub(super) fn expr_any(&mut self, e: &ast::Expr) -> ir::Expr {
        if self.depth >= MAX_NESTING_DEPTH {
            self.error(Code::Unsupported, e.span, "expression nested too deeply");
            return error_expr(e.span);
        }
        self.depth += 1;
        let r = self.expr_kind(e);
        self.depth -= 1;
        r
    }

    pub(super) fn expr_kind(&mut self, e: &ast::Expr) -> ir::Expr {
        let span = e.span;
        match &e.kind {
            A::Error => error_expr(span),
            A::StringLit(_) => {
                self.error(
                    Code::TypeMismatch,
                    span,
                    "a string literal can only be the format of `debugPrintfEXT'",
                );
                error_expr(span)
            }
            A::IntLit(v) => const_expr(
                ir::ConstValue {
                    ty: Type::INT,
                    components: vec![ir::ConstScalar::Int(*v as i32)],
                },
                span,
            ),
            A::UintLit(v) => const_expr(
                ir::ConstValue {
                    ty: Type::UINT,
                    components: vec![ir::ConstScalar::Uint(*v)],
                },
                span,
            ),
            A::FloatLit(v) => const_expr(
                ir::ConstValue {
                    ty: Type::FLOAT,
                    // Subnormal literals are zero, as every float value is
                    // (`math::flush_denormal`).
                    components: vec![ir::ConstScalar::Float(crate::math::flush_denormal(*v))],
                },
                span,
            ),
            A::BoolLit(v) => const_expr(
                ir::ConstValue {
                    ty: Type::BOOL,
                    components: vec![ir::ConstScalar::Bool(*v)],
                },
                span,
            ),
            A::Ident(id) => self.ident(id),
            A::Unary(op, x) => self.unary(*op, x, span),
            A::Binary(..) | A::Comma(..) => self.binary_chain(e),
            A::Assign(op, t, v) => self.assign(*op, t, v, span),
            A::Ternary(c, a, b) => self.ternary(c, a, b, span),
            A::Index(b, i) => {
                let base = self.expr_any(b);
                self.index(base, i, span)
            }
            A::Field(b, name) => {
                let base = self.rvalue(b);
                self.field(base, name, span, false)
            }
            A::Call(Callee::Function(name), args) => self.call(name, args, span),
            A::Call(Callee::Constructor(ts), args) => {
                let ty = self.resolve_type(ts);
                self.construct(ty, args, span)
            }
            A::Method(b, name, args) => self.method(b, name, args, span),
            A::InitList(_) => {
                // The parser makes lists only as initializers, which
                // `declarator` analyzes against their variable's type.
                self.error(
                    Code::Syntax,
                    span,
                    "an initializer list `{...}' is only allowed as the initializer of a declaration",
                );
                error_expr(span)
            }
        }
    }

    /// A variable reference as a value; `const` variables become constants.
    pub(super) fn ident(&mut self, id: &ast::Ident) -> ir::Expr {
        if id.name == "gl_WorkGroupSize" && self.stage == crate::ir::Stage::Compute {
            return self.work_group_size(id.span);
        }
        match self.lookup(&id.name) {
            Some(Symbol::Var(v)) => {
                let ty = self.var_type(v);
                if let Some(c) = self.var_const(v) {
                    return const_expr(c, id.span);
                }
                let kind = match v {
                    Var::Local(l) => K::Local(l),
                    _ => match self.global_of(v) {
                        Some(g) => {
                            self.module.globals[g.0 as usize].read = true;
                            K::Global(g)
                        }
                        None => return error_expr(id.span),
                    },
                };
                mk(kind, ty, id.span)
            }
            Some(Symbol::Funcs(_)) => {
                self.error(
                    Code::TypeMismatch,
                    id.span,
                    format!(
                        "`{}' is a function; call it with `{}(...)'",
                        id.name, id.name
                    ),
                );
                error_expr(id.span)
            }
            Some(Symbol::Struct(_)) => {
                self.error(
                    Code::TypeMismatch,
                    id.span,
                    format!("`{}' is a type, not a variable", id.name),
                );
                error_expr(id.span)
            }
            None => {
                self.undeclared(id, false);
                error_expr(id.span)
            }
        }
    }

    /// Folds a node whose operands are all constants.
    pub fn fold(&mut self, e: ir::Expr) -> ir::Expr {
        let all_const = match &e.kind {
            K::Index { base, index } => is_const(base) && is_const(index),
            K::Swizzle { base, .. } | K::Member { base, .. } => is_const(base),
            K::Unary { operand, .. } | K::Convert { operand } => is_const(operand),
            K::Binary { left, right, .. } => is_const(left) && is_const(right),
            K::Ternary {
                cond,
                accept,
                reject,
            } => is_const(cond) && is_const(accept) && is_const(reject),
            K::Builtin { args, .. } | K::Construct { args } => args.iter().all(is_const),
            _ => false,
        };
        if !all_const || e.ty.is_error() {
            return e;
        }
        match crate::consteval::fold(&e, &self.module.structs) {
            Some(mut c) => {
                c.ty = e.ty;
                const_expr(c, e.span)
            }
            None => e,
        }
    }

    /// Converts an expression to `to` (which it must equal or implicitly
    /// convert to).
    pub fn convert(&mut self, e: ir::Expr, to: Type) -> ir::Expr {
        if e.ty == to || e.ty.is_error() || to.is_error() {
            return e;
        }
        let span = e.span;
        self.fold(mk(
            K::Convert {
                operand: Box::new(e),
            },
            to,
            span,
        ))
    }

    /// Converts `e` to `to` with the version's implicit conversions, or
    /// reports "`what` with `<found type>`".
    pub fn coerce(&mut self, e: ir::Expr, to: Type, span: Span, what: &str) -> ir::Expr {
        if e.ty == to || e.ty.is_error() || to.is_error() {
            return e;
        }
        if implicitly_converts(e.ty, to) {
            if self.lang.version >= Version::V120 {
                return self.convert(e, to);
            }
            self.error(
                Code::TypeMismatch,
                span,
                format!(
                    "{what} with {}; GLSL 1.10 has no implicit conversions (write 1.0, or use #version 120)",
                    self.tn(e.ty)
                ),
            );
            return error_expr(span);
        }
        self.error(
            Code::TypeMismatch,
            span,
            format!("{what} with {}", self.tn(e.ty)),
        );
        error_expr(span)
    }

    /// GLSL 1.20 on: converts the int (or uint) side of a mixed pair with
    /// float to float.
    pub(super) fn balance(&mut self, l: ir::Expr, r: ir::Expr) -> (ir::Expr, ir::Expr) {
        if self.lang.version < Version::V120 || l.ty.is_array() || r.ty.is_array() {
            return (l, r);
        }
        match (l.ty.scalar(), r.ty.scalar()) {
            (Some(Scalar::Int | Scalar::Uint), Some(Scalar::Float)) => {
                let to = l.ty.with_scalar(Scalar::Float);
                (self.convert(l, to), r)
            }
            (Some(Scalar::Float), Some(Scalar::Int | Scalar::Uint)) => {
                let to = r.ty.with_scalar(Scalar::Float);
                (l, self.convert(r, to))
            }
            _ => (l, r),
        }
    }

    /// Whether the integer operators exist (GLSL 1.30 on; reserved
    /// before); reports `op` when they do not.
    pub(super) fn integer_ops_allowed(&mut self, op: &str, span: Span) -> bool {
        let Err(why) = self.lang.gate(Feature::IntegerOperators) else {
            return true;
        };
        let lang = self.lang;
        let d = self.error(
            Code::ReservedWord,
            span,
            why.message(&format!("operator `{op}'"), lang),
        );
        d.notes.push(why.fix());
        if op.starts_with('%') {
            d.notes.push("for floats, use mod()".into());
        }
        false
    }

    /// `%`, `<<`, `>>`, `&`, `|`, `^` on analyzed operands (no implicit
    /// conversions apply, §5.9).
    fn integer_binary(
        &mut self,
        op: ast::BinaryOp,
        lv: ir::Expr,
        rv: ir::Expr,
        span: Span,
    ) -> ir::Expr {
        use ast::BinaryOp as O;
        let shift = matches!(op, O::Shl | O::Shr);
        let Some(ty) = int_op_type(shift, lv.ty, rv.ty) else {
            let (l, r) = (self.tn(lv.ty), self.tn(rv.ty));
            let expected = if shift {
                "it needs int or uint scalars or vectors, and a scalar amount for a scalar"
            } else {
                "it needs int or uint scalars or vectors of one signedness and of matching sizes"
            };
            let d = self.error(
                Code::TypeMismatch,
                span,
                format!(
                    "operator `{}' cannot take {l} and {r}; {expected}",
                    op.as_str()
                ),
            );
            if !shift && int_kind(lv.ty).is_some() && int_kind(rv.ty).is_some() {
                d.notes.push(
                    "int and uint do not convert implicitly: write a `u' suffix or uint(...)"
                        .into(),
                );
            }
            return error_expr(span);
        };
        self.fold(mk(
            K::Binary {
                op: integer_ir_op(op),
                left: Box::new(lv),
                right: Box::new(rv),
            },
            ty,
            span,
        ))
    }

    pub(super) fn unary(&mut self, op: AU, x: &ast::Expr, span: Span) -> ir::Expr {
        match op {
            AU::PreInc | AU::PreDec | AU::PostInc | AU::PostDec => {
                let t = self.lvalue(x, true, "increment or decrement");
                if t.ty.is_error() {
                    return error_expr(span);
                }
                if !is_numeric(t.ty) {
                    self.error(
                        Code::TypeMismatch,
                        span,
                        format!(
                            "`++'/`--' need an int, uint or float operand, found {}",
                            self.tn(t.ty)
                        ),
                    );
                    return error_expr(span);
                }
                let op = match op {
                    AU::PreInc => IncDec::PreInc,
                    AU::PreDec => IncDec::PreDec,
                    AU::PostInc => IncDec::PostInc,
                    _ => IncDec::PostDec,
                };
                let ty = t.ty;
                mk(
                    K::IncDec {
                        op,
                        target: Box::new(t),
                    },
                    ty,
                    span,
                )
            }
            AU::BitNot => {
                let v = self.rvalue(x);
                if !self.integer_ops_allowed("~", span) || v.ty.is_error() {
                    return error_expr(span);
                }
                if int_kind(v.ty).is_none() {
                    self.error(
                        Code::TypeMismatch,
                        span,
                        format!(
                            "`~' needs an int or uint scalar or vector, found {}",
                            self.tn(v.ty)
                        ),
                    );
                    return error_expr(span);
                }
                let ty = v.ty;
                self.fold(mk(
                    K::Unary {
                        op: ir::UnaryOp::BitNot,
                        operand: Box::new(v),
                    },
                    ty,
                    span,
                ))
            }
            AU::Plus | AU::Minus => {
                let v = self.rvalue(x);
                if v.ty.is_error() {
                    return v;
                }
                if !is_numeric(v.ty) {
                    let o = if op == AU::Plus { "+" } else { "-" };
                    self.error(
                        Code::TypeMismatch,
                        span,
                        format!(
                            "unary `{o}' needs an int, uint or float operand, found {}",
                            self.tn(v.ty)
                        ),
                    );
                    return error_expr(span);
                }
                if op == AU::Plus {
                    return v;
                }
                let ty = v.ty;
                self.fold(mk(
                    K::Unary {
                        op: ir::UnaryOp::Neg,
                        operand: Box::new(v),
                    },
                    ty,
                    span,
                ))
            }
            AU::Not => {
                let v = self.rvalue(x);
                if v.ty.is_error() {
                    return v;
                }
                if v.ty != Type::BOOL {
                    self.error(
                        Code::TypeMismatch,
                        span,
                        format!("`!' needs a bool operand, found {}", self.tn(v.ty)),
                    )
                    .notes
                    .push("use not() for bool vectors".into());
                    return error_expr(span);
                }
                self.fold(mk(
                    K::Unary {
                        op: ir::UnaryOp::Not,
                        operand: Box::new(v),
                    },
                    Type::BOOL,
                    span,
                ))
            }
        }
    }

    /// Result type of an arithmetic operator on balanced operands.
    pub(super) fn arith_type(&self, op: ast::BinaryOp, l: Type, r: Type) -> Option<(Type, B)> {
        if !is_numeric(l) || !is_numeric(r) || l.scalar() != r.scalar() {
            return None;
        }
        let irop = match op {
            ast::BinaryOp::Add => B::Add,
            ast::BinaryOp::Sub => B::Sub,
            ast::BinaryOp::Mul => B::Mul,
            _ => B::Div,
        };
        if l.is_scalar() {
            return Some((r, irop));
        }
        if r.is_scalar() {
            return Some((l, irop));
        }
        match (l.base, r.base) {
            (Base::Vector(_, a), Base::Vector(_, b)) => (a == b).then_some((l, irop)),
            (Base::Matrix { cols: lc, rows: lr }, Base::Matrix { cols: rc, rows: rr }) => {
                if irop == B::Mul {
                    (lc == rr).then_some((Type::mat(rc, lr), B::MatMul))
                } else {
                    (lc == rc && lr == rr).then_some((l, irop))
                }
            }
            (Base::Matrix { cols, rows }, Base::Vector(_, n)) => {
                (irop == B::Mul && cols == n).then_some((Type::vec(Scalar::Float, rows), B::MatMul))
            }
            (Base::Vector(_, n), Base::Matrix { cols, rows }) => {
                (irop == B::Mul && rows == n).then_some((Type::vec(Scalar::Float, cols), B::MatMul))
            }
            _ => None,
        }
    }

    /// A left-associative chain `a op b op c ...`, analyzed iteratively so
    /// long chains (which the parser builds without nesting) cannot exhaust
    /// the stack.
    pub(super) fn binary_chain(&mut self, e: &ast::Expr) -> ir::Expr {
        let mut spine = Vec::new();
        let mut cur = e;
        loop {
            match &cur.kind {
                A::Binary(op, l, r) => {
                    spine.push((Some(*op), r.as_ref(), cur.span));
                    cur = l;
                }
                A::Comma(l, r) => {
                    spine.push((None, r.as_ref(), cur.span));
                    cur = l;
                }
                _ => break,
            }
        }
        let mut acc = self.rvalue(cur);
        for (op, r, span) in spine.into_iter().rev() {
            let rv = self.rvalue(r);
            acc = match op {
                Some(op) => self.binary(op, acc, rv, span),
                None => {
                    let ty = if acc.ty.is_error() {
                        Type::ERROR
                    } else {
                        rv.ty
                    };
                    mk(
                        K::Comma {
                            left: Box::new(acc),
                            right: Box::new(rv),
                        },
                        ty,
                        span,
                    )
                }
            };
        }
        acc
    }

    pub(super) fn binary(
        &mut self,
        op: ast::BinaryOp,
        lv: ir::Expr,
        rv: ir::Expr,
        span: Span,
    ) -> ir::Expr {
        use ast::BinaryOp as O;
        if matches!(
            op,
            O::Mod | O::Shl | O::Shr | O::BitAnd | O::BitOr | O::BitXor
        ) {
            if !self.integer_ops_allowed(op.as_str(), span) || lv.ty.is_error() || rv.ty.is_error()
            {
                return error_expr(span);
            }
            return self.integer_binary(op, lv, rv, span);
        }
        if lv.ty.is_error() || rv.ty.is_error() {
            return error_expr(span);
        }
        let (lv, rv) = self.balance(lv, rv);
        let (lt, rt) = (lv.ty, rv.ty);
        let mismatch = |a: &mut Analyzer, expected: &str| {
            let (l, r) = (a.tn(lt), a.tn(rt));
            let v110 = a.lang.version < Version::V120;
            let d = a.error(
                Code::TypeMismatch,
                span,
                format!(
                    "operator `{}' cannot take {l} and {r}; {expected}",
                    op.as_str()
                ),
            );
            if v110 && lt.scalar().is_some() && rt.scalar().is_some() && lt.scalar() != rt.scalar()
            {
                d.notes.push(
                    "GLSL 1.10 has no implicit int→float conversions: write float literals (`1.0')"
                        .into(),
                );
            }
            error_expr(span)
        };
        let (ty, irop) = match op {
            O::Add | O::Sub | O::Mul | O::Div => match self.arith_type(op, lt, rt) {
                Some(x) => x,
                None => return mismatch(
                    self,
                    "it needs int, uint or float scalars, vectors or matrices of matching shapes",
                ),
            },
            O::Less | O::Greater | O::LessEq | O::GreaterEq => {
                if lt != rt || !(lt == Type::INT || lt == Type::UINT || lt == Type::FLOAT) {
                    return mismatch(
                        self,
                        "it needs two int, two uint or two float scalars (use lessThan() etc. for vectors)",
                    );
                }
                let irop = match op {
                    O::Less => B::Less,
                    O::Greater => B::Greater,
                    O::LessEq => B::LessEq,
                    _ => B::GreaterEq,
                };
                (Type::BOOL, irop)
            }
            O::Eq | O::NotEq => {
                if lt != rt || lt.base == Base::Void || self.contains_sampler(lt) {
                    return mismatch(self, "it needs two operands of the same type");
                }
                if self.lang.version < Version::V120 && (self.contains_array(lt)) {
                    self.error(
                        Code::VersionTooLow,
                        span,
                        "comparing arrays requires GLSL 1.20",
                    );
                    return error_expr(span);
                }
                (Type::BOOL, if op == O::Eq { B::Equal } else { B::NotEqual })
            }
            O::LogicalAnd | O::LogicalOr | O::LogicalXor => {
                if lt != Type::BOOL || rt != Type::BOOL {
                    return mismatch(self, "it needs two bool scalars");
                }
                let irop = match op {
                    O::LogicalAnd => B::LogicalAnd,
                    O::LogicalOr => B::LogicalOr,
                    _ => B::LogicalXor,
                };
                (Type::BOOL, irop)
            }
            _ => return error_expr(span),
        };
        self.fold(mk(
            K::Binary {
                op: irop,
                left: Box::new(lv),
                right: Box::new(rv),
            },
            ty,
            span,
        ))
    }

    /// `target o= value`, given the operator's result type and IR op for
    /// the operand types: an assignment when that type is the target's,
    /// otherwise the one error both operator families report.
    fn compound_assign(
        &mut self,
        o: ast::BinaryOp,
        result: Option<(Type, ir::BinaryOp)>,
        target: ir::Expr,
        value: ir::Expr,
        span: Span,
    ) -> ir::Expr {
        let tt = target.ty;
        match result {
            Some((ty, irop)) if ty == tt => mk(
                K::Assign {
                    op: Some(irop),
                    target: Box::new(target),
                    value: Box::new(value),
                },
                tt,
                span,
            ),
            _ => {
                let (a, b) = (self.tn(tt), self.tn(value.ty));
                self.error(
                    Code::TypeMismatch,
                    span,
                    format!("operator `{}=' cannot take {a} and {b}", o.as_str()),
                );
                error_expr(span)
            }
        }
    }

    pub(super) fn assign(
        &mut self,
        op: AssignOp,
        t: &ast::Expr,
        v: &ast::Expr,
        span: Span,
    ) -> ir::Expr {
        use ast::BinaryOp as O;
        let target = self.lvalue(t, op.0.is_some(), "assign to");
        let value = self.rvalue(v);
        let integer_op = op.0.filter(|o| {
            matches!(
                o,
                O::Mod | O::Shl | O::Shr | O::BitAnd | O::BitOr | O::BitXor
            )
        });
        if let Some(o) = integer_op {
            if !self.integer_ops_allowed(&format!("{}=", o.as_str()), span) {
                return error_expr(span);
            }
        }
        if target.ty.is_error() || value.ty.is_error() {
            return error_expr(span);
        }
        if let Some(o) = integer_op {
            let result = int_op_type(matches!(o, O::Shl | O::Shr), target.ty, value.ty)
                .map(|ty| (ty, integer_ir_op(o)));
            return self.compound_assign(o, result, target, value, span);
        }
        let tt = target.ty;
        if tt.is_array() && self.lang.version < Version::V120 {
            self.error(
                Code::VersionTooLow,
                span,
                "assigning whole arrays requires GLSL 1.20",
            )
            .notes
            .push("assign the elements one by one".into());
            return error_expr(span);
        }
        if tt.array == Some(ArraySize::Unsized) {
            return self.reject_unsized(target);
        }
        match op.0 {
            None => {
                let what = format!("cannot assign to {}", self.tn(tt));
                let value = self.coerce(value, tt, span, &what);
                if value.ty.is_error() {
                    return value;
                }
                mk(
                    K::Assign {
                        op: None,
                        target: Box::new(target),
                        value: Box::new(value),
                    },
                    tt,
                    span,
                )
            }
            Some(o) => {
                let value = if self.lang.version >= Version::V120
                    && tt.scalar() == Some(Scalar::Float)
                    && matches!(value.ty.scalar(), Some(Scalar::Int | Scalar::Uint))
                    && !value.ty.is_array()
                {
                    let to = value.ty.with_scalar(Scalar::Float);
                    self.convert(value, to)
                } else {
                    value
                };
                let result = self.arith_type(o, tt, value.ty);
                self.compound_assign(o, result, target, value, span)
            }
        }
    }

    pub(super) fn ternary(
        &mut self,
        c: &ast::Expr,
        a: &ast::Expr,
        b: &ast::Expr,
        span: Span,
    ) -> ir::Expr {
        let cv = self.rvalue(c);
        let av = self.rvalue(a);
        let bv = self.rvalue(b);
        if !cv.ty.is_error() && cv.ty != Type::BOOL {
            self.error(
                Code::TypeMismatch,
                c.span,
                format!(
                    "the condition of `?:' must be bool, found {}",
                    self.tn(cv.ty)
                ),
            );
            return error_expr(span);
        }
        if cv.ty.is_error() || av.ty.is_error() || bv.ty.is_error() {
            return error_expr(span);
        }
        let (av, bv) = self.balance(av, bv);
        if av.ty != bv.ty {
            let (x, y) = (self.tn(av.ty), self.tn(bv.ty));
            self.error(
                Code::TypeMismatch,
                span,
                format!("the two results of `?:' differ: {x} and {y}"),
            );
            return error_expr(span);
        }
        if av.ty.is_array() && self.lang.version < Version::V120 {
            self.error(
                Code::VersionTooLow,
                span,
                "`?:' on arrays requires GLSL 1.20",
            );
            return error_expr(span);
        }
        let ty = av.ty;
        self.fold(mk(
            K::Ternary {
                cond: Box::new(cv),
                accept: Box::new(av),
                reject: Box::new(bv),
            },
            ty,
            span,
        ))
    }
}

/// The IR operator of an integer operator of the syntax.
fn integer_ir_op(op: ast::BinaryOp) -> B {
    use ast::BinaryOp as O;
    match op {
        O::Mod => B::Mod,
        O::Shl => B::Shl,
        O::Shr => B::Shr,
        O::BitAnd => B::BitAnd,
        O::BitOr => B::BitOr,
        _ => B::BitXor,
    }
}

fn is_const(e: &ir::Expr) -> bool {
    matches!(e.kind, K::Const(_))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conversions() {
        assert!(implicitly_converts(Type::INT, Type::FLOAT));
        assert!(implicitly_converts(
            Type::vec(Scalar::Int, 3),
            Type::vec(Scalar::Float, 3)
        ));
        assert!(!implicitly_converts(Type::FLOAT, Type::INT));
        assert!(!implicitly_converts(Type::BOOL, Type::FLOAT));
        let arr = Type::INT.array_of(ArraySize::Sized(2));
        assert!(!implicitly_converts(
            arr,
            Type::FLOAT.array_of(ArraySize::Sized(2))
        ));
    }
}
