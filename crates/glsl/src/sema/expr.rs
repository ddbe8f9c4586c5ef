//! Expressions: names, operators, implicit conversions, constructors,
//! swizzles, indexing and l-values (GLSL 1.20 §5).

use super::scope::{Symbol, Var};
use super::{const_expr, const_int, error_expr, Analyzer};
use crate::ast::{self, AssignOp, Callee, ExprKind as A, UnaryOp as AU};
use crate::diag::{did_you_mean, Code};
use crate::ir::{self, BinaryOp as B, ExprKind as K, IncDec, Stage, Storage};
use crate::limits::{MAX_NESTING_DEPTH, MAX_TEXTURE_COORDS};
use crate::source::Span;
use crate::token::Version;
use crate::types::{ArraySize, Base, Scalar, Type};

/// GLSL 1.20 §4.1.10: int → float, ivecN → vecN, nothing else (never for
/// arrays or structs as wholes).
pub(crate) fn implicitly_converts(from: Type, to: Type) -> bool {
    if from.is_array() || to.is_array() {
        return false;
    }
    match (from.base, to.base) {
        (Base::Scalar(Scalar::Int), Base::Scalar(Scalar::Float)) => true,
        (Base::Vector(Scalar::Int, n), Base::Vector(Scalar::Float, m)) => n == m,
        _ => false,
    }
}

fn mk(kind: K, ty: Type, span: Span) -> ir::Expr {
    ir::Expr { kind, ty, span }
}

/// True for int/float scalars, vectors and matrices (not arrays).
fn is_numeric(t: Type) -> bool {
    matches!(t.scalar(), Some(Scalar::Int | Scalar::Float))
}

/// Parses a swizzle: one naming set, 1 to 4 components, each within `size`.
fn parse_swizzle(name: &str, size: u8) -> Result<([u8; 4], u8), String> {
    const SETS: [&str; 3] = ["xyzw", "rgba", "stpq"];
    if name.len() > 4 {
        return Err(format!("swizzle `{name}' has more than 4 components"));
    }
    let mut set = None;
    let mut comps = [0u8; 4];
    for (i, c) in name.chars().enumerate() {
        let found = SETS
            .iter()
            .enumerate()
            .find_map(|(s, letters)| letters.find(c).map(|p| (s, p)));
        let Some((s, p)) = found else {
            return Err(format!(
                "`{c}' is not a vector component (use xyzw, rgba or stpq)"
            ));
        };
        if *set.get_or_insert(s) != s {
            return Err(format!(
                "swizzle `{name}' mixes component sets (xyzw, rgba, stpq)"
            ));
        }
        if p as u8 >= size {
            return Err(format!(
                "swizzle `{name}' selects component `{c}' of a {size}-component vector"
            ));
        }
        if i < 4 {
            comps[i] = p as u8;
        }
    }
    if name.is_empty() {
        return Err("empty swizzle".into());
    }
    Ok((comps, name.len() as u8))
}

impl Analyzer {
    /// An expression used for its value. Unsized arrays are only usable
    /// indexed with a constant.
    pub fn rvalue(&mut self, e: &ast::Expr) -> ir::Expr {
        let v = self.expr_any(e);
        self.reject_unsized(v)
    }

    fn reject_unsized(&mut self, v: ir::Expr) -> ir::Expr {
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

    fn expr_any(&mut self, e: &ast::Expr) -> ir::Expr {
        if self.depth >= MAX_NESTING_DEPTH {
            self.error(Code::Unsupported, e.span, "expression nested too deeply");
            return error_expr(e.span);
        }
        self.depth += 1;
        let r = self.expr_kind(e);
        self.depth -= 1;
        r
    }

    fn expr_kind(&mut self, e: &ast::Expr) -> ir::Expr {
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
        }
    }

    /// A variable reference as a value; `const` variables become constants.
    fn ident(&mut self, id: &ast::Ident) -> ir::Expr {
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
    /// reports "`what` with <found type>".
    pub fn coerce(&mut self, e: ir::Expr, to: Type, span: Span, what: &str) -> ir::Expr {
        if e.ty == to || e.ty.is_error() || to.is_error() {
            return e;
        }
        if implicitly_converts(e.ty, to) {
            if self.version >= Version::V120 {
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

    /// GLSL 1.20: converts the int side of a mixed int/float pair to float.
    fn balance(&mut self, l: ir::Expr, r: ir::Expr) -> (ir::Expr, ir::Expr) {
        if self.version < Version::V120 || l.ty.is_array() || r.ty.is_array() {
            return (l, r);
        }
        match (l.ty.scalar(), r.ty.scalar()) {
            (Some(Scalar::Int), Some(Scalar::Float)) => {
                let to = l.ty.with_scalar(Scalar::Float);
                (self.convert(l, to), r)
            }
            (Some(Scalar::Float), Some(Scalar::Int)) => {
                let to = r.ty.with_scalar(Scalar::Float);
                (l, self.convert(r, to))
            }
            _ => (l, r),
        }
    }

    fn reserved_op(&mut self, op: &str, span: Span) {
        self.error(
            Code::ReservedWord,
            span,
            format!(
                "operator `{op}' is reserved in GLSL {}",
                self.version.dotted()
            ),
        )
        .notes
        .push("integer bit operations and `%' arrive in GLSL 1.30; use mod() for floats".into());
    }

    fn unary(&mut self, op: AU, x: &ast::Expr, span: Span) -> ir::Expr {
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
                            "`++'/`--' need an int or float operand, found {}",
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
                let _ = self.rvalue(x);
                self.reserved_op("~", span);
                error_expr(span)
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
                            "unary `{o}' needs an int or float operand, found {}",
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
    fn arith_type(&self, op: ast::BinaryOp, l: Type, r: Type) -> Option<(Type, B)> {
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
    fn binary_chain(&mut self, e: &ast::Expr) -> ir::Expr {
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

    fn binary(&mut self, op: ast::BinaryOp, lv: ir::Expr, rv: ir::Expr, span: Span) -> ir::Expr {
        use ast::BinaryOp as O;
        if matches!(
            op,
            O::Mod | O::Shl | O::Shr | O::BitAnd | O::BitOr | O::BitXor
        ) {
            self.reserved_op(op.as_str(), span);
            return error_expr(span);
        }
        if lv.ty.is_error() || rv.ty.is_error() {
            return error_expr(span);
        }
        let (lv, rv) = self.balance(lv, rv);
        let (lt, rt) = (lv.ty, rv.ty);
        let mismatch = |a: &mut Analyzer, expected: &str| {
            let (l, r) = (a.tn(lt), a.tn(rt));
            let v110 = a.version < Version::V120;
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
                None => {
                    return mismatch(
                        self,
                        "it needs int or float scalars, vectors or matrices of matching shapes",
                    )
                }
            },
            O::Less | O::Greater | O::LessEq | O::GreaterEq => {
                if lt != rt || !(lt == Type::INT || lt == Type::FLOAT) {
                    return mismatch(
                        self,
                        "it needs two int or two float scalars (use lessThan() etc. for vectors)",
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
                if self.version < Version::V120 && (self.contains_array(lt)) {
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

    fn assign(&mut self, op: AssignOp, t: &ast::Expr, v: &ast::Expr, span: Span) -> ir::Expr {
        use ast::BinaryOp as O;
        let target = self.lvalue(t, op.0.is_some(), "assign to");
        let value = self.rvalue(v);
        if let Some(o) = op.0 {
            if matches!(
                o,
                O::Mod | O::Shl | O::Shr | O::BitAnd | O::BitOr | O::BitXor
            ) {
                self.reserved_op(&format!("{}=", o.as_str()), span);
                return error_expr(span);
            }
        }
        if target.ty.is_error() || value.ty.is_error() {
            return error_expr(span);
        }
        let tt = target.ty;
        if tt.is_array() && self.version < Version::V120 {
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
                let value = if self.version >= Version::V120
                    && tt.scalar() == Some(Scalar::Float)
                    && value.ty.scalar() == Some(Scalar::Int)
                    && !value.ty.is_array()
                {
                    let to = value.ty.with_scalar(Scalar::Float);
                    self.convert(value, to)
                } else {
                    value
                };
                match self.arith_type(o, tt, value.ty) {
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
        }
    }

    fn ternary(&mut self, c: &ast::Expr, a: &ast::Expr, b: &ast::Expr, span: Span) -> ir::Expr {
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
        if av.ty.is_array() && self.version < Version::V120 {
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

    /// The bound a constant index must respect for an unsized built-in
    /// array (`gl_TexCoord[]`: gl_MaxTextureCoords).
    fn builtin_unsized_bound(&self, base: &ir::Expr) -> Option<u32> {
        match base.kind {
            K::Global(g) => {
                let g = self.module.globals.get(g.0 as usize)?;
                (g.builtin && g.ty.array == Some(ArraySize::Unsized)).then_some(MAX_TEXTURE_COORDS)
            }
            _ => None,
        }
    }

    fn note_implicit_index(&mut self, base: &ir::Expr, i: u32) {
        match base.kind {
            K::Global(g) => {
                if let Some(g) = self.module.globals.get_mut(g.0 as usize) {
                    g.implicit_size = g.implicit_size.max(i + 1);
                }
            }
            K::Local(l) => {
                if let Some(s) = self
                    .cur
                    .as_mut()
                    .and_then(|f| f.implicit.get_mut(l.0 as usize))
                {
                    *s = (*s).max(i + 1);
                }
            }
            _ => {}
        }
    }

    /// `base[index]` on an array, vector or matrix.
    fn index(&mut self, base: ir::Expr, i: &ast::Expr, span: Span) -> ir::Expr {
        let iv = self.rvalue(i);
        if base.ty.is_error() || iv.ty.is_error() {
            return error_expr(span);
        }
        if iv.ty != Type::INT {
            self.error(
                Code::TypeMismatch,
                i.span,
                format!("an index must be an int scalar, found {}", self.tn(iv.ty)),
            );
            return error_expr(span);
        }
        let cidx = match &iv.kind {
            K::Const(c) => const_int(c),
            _ => None,
        };
        let t = base.ty;
        let (len, ty, what) = match (t.array, t.base) {
            (Some(ArraySize::Sized(n)), _) => (Some(n), t.element(), "array"),
            (Some(ArraySize::Unsized), _) => (None, t.element(), "array"),
            (None, Base::Vector(s, n)) => (Some(n as u32), Type::new(Base::Scalar(s)), "vector"),
            (None, Base::Matrix { cols, rows }) => {
                (Some(cols as u32), Type::vec(Scalar::Float, rows), "matrix")
            }
            _ => {
                self.error(
                    Code::TypeMismatch,
                    span,
                    format!("cannot index a value of type {}", self.tn(t)),
                )
                .notes
                .push("only arrays, vectors and matrices can be indexed".into());
                return error_expr(span);
            }
        };
        if let Some(c) = cidx {
            if c < 0 {
                self.error(
                    Code::IndexOutOfRange,
                    i.span,
                    format!("{what} index {c} is negative"),
                );
                return error_expr(span);
            }
            let bound = len.or_else(|| self.builtin_unsized_bound(&base));
            if let Some(n) = bound {
                if c as u32 >= n {
                    self.error(
                        Code::IndexOutOfRange,
                        i.span,
                        format!("{what} index {c} is out of range for {}", self.tn(t)),
                    )
                    .notes
                    .push(format!("valid indices are 0 to {}", n.saturating_sub(1)));
                    return error_expr(span);
                }
            }
            if len.is_none() {
                self.note_implicit_index(&base, c as u32);
            }
        } else if len.is_none() {
            // GLSL 1.20 §4.1.9 and, for gl_TexCoord, §7.6: "indices used to
            // subscript gl_TexCoord must either be an integral constant
            // expression, or this array must be re-declared with a size".
            let hint = match base.kind {
                K::Global(g)
                    if self
                        .module
                        .globals
                        .get(g.0 as usize)
                        .is_some_and(|g| g.builtin) =>
                {
                    "redeclare it with a size first, e.g. `varying vec4 gl_TexCoord[4];'"
                }
                _ => "declare the array with an explicit size",
            };
            self.error(
                Code::BadArraySize,
                i.span,
                "an array without a size can only be indexed with constants",
            )
            .notes
            .push(hint.into());
            return error_expr(span);
        }
        self.fold(mk(
            K::Index {
                base: Box::new(base),
                index: Box::new(iv),
            },
            ty,
            span,
        ))
    }

    /// `base.name`: a struct member or a swizzle.
    fn field(&mut self, base: ir::Expr, name: &ast::Ident, span: Span, lvalue: bool) -> ir::Expr {
        let t = base.ty;
        if t.is_error() {
            return error_expr(span);
        }
        if let (None, Base::Struct(id)) = (t.array, t.base) {
            let members = self
                .module
                .structs
                .get(id.0 as usize)
                .map(|s| s.members.clone())
                .unwrap_or_default();
            match members.iter().position(|m| m.name == name.name.as_str()) {
                Some(i) => {
                    let ty = members[i].ty;
                    return self.fold(mk(
                        K::Member {
                            base: Box::new(base),
                            index: i as u32,
                        },
                        ty,
                        span,
                    ));
                }
                None => {
                    let sugg = if self.may_suggest(&name.name) {
                        did_you_mean(&name.name, members.iter().map(|m| m.name.as_str()))
                            .map(str::to_string)
                    } else {
                        None
                    };
                    let d = self.error(
                        Code::Undeclared,
                        name.span,
                        format!(
                            "struct {} has no member `{}'",
                            self.module.type_name(t),
                            name.name
                        ),
                    );
                    if let Some(s) = sugg {
                        d.notes.push(format!("did you mean `{s}'?"));
                    }
                    return error_expr(span);
                }
            }
        }
        let Some(n) = t.vector_size().filter(|_| t.is_vector()) else {
            let msg = if t.is_scalar() {
                format!(
                    "cannot select `.{}' of a scalar {} in GLSL {}",
                    name.name,
                    self.tn(t),
                    self.version.dotted()
                )
            } else {
                format!(
                    "cannot select `.{}' of a value of type {}",
                    name.name,
                    self.tn(t)
                )
            };
            self.error(Code::BadSwizzle, name.span, msg);
            return error_expr(span);
        };
        match parse_swizzle(&name.name, n) {
            Ok((components, count)) => {
                if lvalue {
                    let c = &components[..count as usize];
                    if (1..c.len()).any(|i| c[..i].contains(&c[i])) {
                        self.error(
                            Code::NotAnLvalue,
                            name.span,
                            format!(
                                "swizzle `{}' repeats a component and cannot be assigned",
                                name.name
                            ),
                        );
                        return error_expr(span);
                    }
                }
                let s = t.scalar().unwrap_or(Scalar::Float);
                let ty = Type::vec(s, count);
                self.fold(mk(
                    K::Swizzle {
                        base: Box::new(base),
                        components,
                        count,
                    },
                    ty,
                    span,
                ))
            }
            Err(msg) => {
                self.error(Code::BadSwizzle, name.span, msg);
                error_expr(span)
            }
        }
    }

    /// `a.length()` (GLSL 1.20 §5.7 for arrays).
    fn method(
        &mut self,
        b: &ast::Expr,
        name: &ast::Ident,
        args: &[ast::Expr],
        span: Span,
    ) -> ir::Expr {
        let base = self.rvalue(b);
        for a in args {
            let _ = self.rvalue(a);
        }
        if base.ty.is_error() {
            return error_expr(span);
        }
        if name.name != "length" {
            self.error(
                Code::Undeclared,
                name.span,
                format!("unknown method `{}'", name.name),
            )
            .notes
            .push("the only method is `.length()' on arrays".into());
            return error_expr(span);
        }
        if self.version < Version::V120 {
            self.error(
                Code::VersionTooLow,
                name.span,
                "`.length()' requires GLSL 1.20",
            );
            return error_expr(span);
        }
        let Some(ArraySize::Sized(n)) = base.ty.array else {
            self.error(
                Code::TypeMismatch,
                name.span,
                format!("`.length()' needs an array, found {}", self.tn(base.ty)),
            );
            return error_expr(span);
        };
        if !args.is_empty() {
            self.error(Code::TypeMismatch, span, "`.length()' takes no arguments");
            return error_expr(span);
        }
        const_expr(
            ir::ConstValue {
                ty: Type::INT,
                components: vec![ir::ConstScalar::Int(n as i32)],
            },
            span,
        )
    }

    /// A constructor call `T(args)` (GLSL 1.20 §5.4).
    pub fn construct(&mut self, ty: Type, args: &[ast::Expr], span: Span) -> ir::Expr {
        let vals: Vec<ir::Expr> = args.iter().map(|a| self.rvalue(a)).collect();
        if ty.is_error() || vals.iter().any(|v| v.ty.is_error()) {
            return error_expr(span);
        }
        let tn = self.tn(ty);
        if vals.is_empty() {
            self.error(
                Code::BadConstructor,
                span,
                format!("constructor `{tn}' needs arguments"),
            );
            return error_expr(span);
        }
        let mut ty = ty;
        let args_out = if ty.is_array() {
            let et = ty.element();
            if let Some(ArraySize::Sized(n)) = ty.array {
                if n as usize != vals.len() {
                    self.error(
                        Code::BadConstructor,
                        span,
                        format!(
                            "array constructor `{tn}' has {} arguments, expected {n}",
                            vals.len()
                        ),
                    );
                    return error_expr(span);
                }
            } else {
                ty = et.array_of(ArraySize::Sized(vals.len() as u32));
            }
            let what = format!("cannot construct an element of {}", self.tn(ty));
            let mut out = Vec::new();
            for v in vals {
                let sp = v.span;
                let c = self.coerce(v, et, sp, &what);
                if c.ty.is_error() {
                    return error_expr(span);
                }
                out.push(c);
            }
            out
        } else if let Base::Struct(id) = ty.base {
            let members = self
                .module
                .structs
                .get(id.0 as usize)
                .map(|s| s.members.clone())
                .unwrap_or_default();
            if members.len() != vals.len() {
                self.error(
                    Code::BadConstructor,
                    span,
                    format!(
                        "constructor `{tn}' has {} arguments, expected {} (one per member)",
                        vals.len(),
                        members.len()
                    ),
                );
                return error_expr(span);
            }
            let mut out = Vec::new();
            for (v, m) in vals.into_iter().zip(&members) {
                let sp = v.span;
                let what = format!(
                    "cannot initialize member `{}' of type {}",
                    m.name,
                    self.tn(m.ty)
                );
                let c = self.coerce(v, m.ty, sp, &what);
                if c.ty.is_error() {
                    return error_expr(span);
                }
                out.push(c);
            }
            out
        } else {
            match self.check_basic_ctor(ty, &vals, span) {
                true => vals,
                false => return error_expr(span),
            }
        };
        self.fold(mk(K::Construct { args: args_out }, ty, span))
    }

    /// Argument checks of scalar, vector and matrix constructors.
    fn check_basic_ctor(&mut self, ty: Type, vals: &[ir::Expr], span: Span) -> bool {
        let tn = self.tn(ty);
        let Some(need) = ty.component_count() else {
            self.error(
                Code::BadConstructor,
                span,
                format!("there is no constructor for type {tn}"),
            );
            return false;
        };
        for v in vals {
            if v.ty.component_count().is_none() {
                self.error(
                    Code::BadConstructor,
                    v.span,
                    format!(
                        "constructor `{tn}' cannot take an argument of type {}",
                        self.tn(v.ty)
                    ),
                );
                return false;
            }
        }
        let first = vals[0].ty;
        if ty.is_matrix() {
            if let Some(m) = vals.iter().find(|v| v.ty.is_matrix()) {
                if self.version < Version::V120 {
                    self.error(
                        Code::VersionTooLow,
                        m.span,
                        "constructing a matrix from a matrix requires GLSL 1.20",
                    );
                    return false;
                }
                if vals.len() > 1 {
                    self.error(
                        Code::BadConstructor,
                        m.span,
                        format!("a matrix argument of `{tn}' must be its only argument"),
                    );
                    return false;
                }
                return true;
            }
        }
        if vals.len() == 1 && (first.is_scalar() || ty.is_scalar()) {
            return true;
        }
        let mut left = need;
        for v in vals {
            if left == 0 {
                self.error(
                    Code::BadConstructor,
                    v.span,
                    format!("too many arguments to constructor `{tn}'; it needs {need} components"),
                );
                return false;
            }
            left = left.saturating_sub(v.ty.component_count().unwrap_or(1));
        }
        if left > 0 {
            self.error(
                Code::BadConstructor,
                span,
                format!(
                    "not enough components for constructor `{tn}': it needs {need}, {} given",
                    need - left
                ),
            );
            return false;
        }
        true
    }

    /// An expression that is written (assignment target, `++`, out
    /// argument): checks it is an l-value and marks the variable written
    /// (and read when `also_read`).
    pub fn lvalue(&mut self, e: &ast::Expr, also_read: bool, what: &str) -> ir::Expr {
        let span = e.span;
        match &e.kind {
            A::Error => error_expr(span),
            A::Ident(id) => {
                let v = match self.lookup(&id.name) {
                    Some(Symbol::Var(v)) => v,
                    _ => return self.ident(id),
                };
                let ty = self.var_type(v);
                match v {
                    Var::Local(l) => {
                        let is_const = self
                            .cur
                            .as_ref()
                            .and_then(|f| f.locals.get(l.0 as usize))
                            .is_some_and(|l| l.is_const);
                        if is_const {
                            self.error(
                                Code::ReadOnly,
                                span,
                                format!("cannot {what} `{}': it is read-only (const)", id.name),
                            );
                            return error_expr(span);
                        }
                        mk(K::Local(l), ty, span)
                    }
                    _ => {
                        let Some(g) = self.global_of(v) else {
                            return error_expr(span);
                        };
                        let gl = &self.module.globals[g.0 as usize];
                        let ro = match gl.storage {
                            Storage::Const => Some("const"),
                            Storage::Uniform => Some("a uniform"),
                            Storage::Attribute => Some("an attribute"),
                            Storage::Varying if self.stage == Stage::Fragment => {
                                Some("a fragment shader input")
                            }
                            _ => None,
                        };
                        if let Some(kind) = ro {
                            self.error(
                                Code::ReadOnly,
                                span,
                                format!("cannot {what} `{}': it is {kind} and read-only", id.name),
                            );
                            return error_expr(span);
                        }
                        let builtin = gl.builtin;
                        let gl = &mut self.module.globals[g.0 as usize];
                        gl.written = true;
                        gl.read |= also_read;
                        if builtin && self.stage == Stage::Fragment {
                            if id.name == "gl_FragColor" {
                                self.frag_color_write.get_or_insert(span);
                            } else if id.name == "gl_FragData" {
                                self.frag_data_write.get_or_insert(span);
                            }
                        }
                        mk(K::Global(g), ty, span)
                    }
                }
            }
            A::Index(b, i) => {
                let base = self.lvalue(b, also_read, what);
                self.index(base, i, span)
            }
            A::Field(b, name) => {
                let base = self.lvalue(b, also_read, what);
                self.field(base, name, span, true)
            }
            _ => {
                let v = self.rvalue(e);
                if !v.ty.is_error() {
                    self.error(Code::NotAnLvalue, span, format!("cannot {what} this expression: it is not a variable"))
                        .notes
                        .push("only variables, their elements, members and swizzles without repeats can be written".into());
                }
                error_expr(span)
            }
        }
    }
}

fn is_const(e: &ir::Expr) -> bool {
    matches!(e.kind, K::Const(_))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn swizzles() {
        assert_eq!(parse_swizzle("xy", 2), Ok(([0, 1, 0, 0], 2)));
        assert_eq!(parse_swizzle("bgra", 4), Ok(([2, 1, 0, 3], 4)));
        assert!(parse_swizzle("xg", 4).is_err());
        assert!(parse_swizzle("z", 2).is_err());
        assert!(parse_swizzle("xxxxx", 4).is_err());
    }

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
