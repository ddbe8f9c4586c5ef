//! The IR validator: checks that a [`Module`] keeps the contract written at
//! the top of [`crate::ir`], so later stages (the executor, the linker) can
//! rely on it without re-checking.
//!
//! A violation is a bug in the front end, never the user's fault; it is
//! reported as a [`Code::Internal`] diagnostic (the shader then fails to
//! compile with a message asking for a bug report) instead of a panic.

use crate::diag::{Code, Diagnostic};
use crate::ir::{
    BinaryOp, Block, CaseLabel, ConstScalar, Expr, ExprKind, Function, Module, ParamQualifier,
    Stmt, UnaryOp,
};
use crate::source::Span;
use crate::types::{Base, Scalar, Type};

/// Validates a module; returns one diagnostic per violation found.
pub fn validate(m: &Module) -> Vec<Diagnostic> {
    let mut v = Validator {
        m,
        func: None,
        diags: Vec::new(),
        loop_depth: 0,
        switch_depth: 0,
    };
    for g in &m.globals {
        if g.ty.is_error() || g.ty.base == Base::Void {
            v.fail(g.span, format!("global `{}' has no valid type", g.name));
        }
        if let Some(e) = &g.init_expr {
            v.expr(e);
        }
    }
    for f in &m.functions {
        v.func = Some(f);
        if let Some(b) = &f.body {
            v.block(b);
        }
        for p in &f.params {
            if p.local.0 as usize >= f.locals.len() {
                v.fail(f.span, format!("parameter of `{}' has no local", f.name));
            }
        }
    }
    v.diags
}

struct Validator<'a> {
    m: &'a Module,
    func: Option<&'a Function>,
    diags: Vec<Diagnostic>,
    loop_depth: u32,
    switch_depth: u32,
}

impl Validator<'_> {
    fn fail(&mut self, span: Span, what: impl Into<String>) {
        // One report per module is enough to fail the compile; more would
        // only repeat the same front-end bug.
        if self.diags.len() < 8 {
            self.diags.push(
                Diagnostic::error(
                    Code::Internal,
                    span,
                    format!("internal compiler error: {}", what.into()),
                )
                .with_note("this is a bug in shaderbox; please report it with the shader"),
            );
        }
    }

    fn block(&mut self, b: &Block) {
        for s in b {
            self.stmt(s);
        }
    }

    fn stmt(&mut self, s: &Stmt) {
        match s {
            Stmt::Expr(e) => self.expr(e),
            Stmt::Declare { local, init, span } => {
                let n = self.func.map_or(0, |f| f.locals.len());
                if local.0 as usize >= n {
                    self.fail(*span, "declaration of an unknown local");
                } else if let (Some(e), Some(f)) = (init, self.func) {
                    self.expr(e);
                    let lt = f.locals[local.0 as usize].ty;
                    if !same_shape(lt, e.ty) {
                        self.fail(e.span, "initializer type differs from the variable's");
                    }
                }
            }
            Stmt::Block(b) => self.block(b),
            Stmt::If {
                cond, then, else_, ..
            } => {
                self.expr(cond);
                if cond.ty != Type::BOOL {
                    self.fail(cond.span, "`if' condition is not a scalar bool");
                }
                self.block(then);
                self.block(else_);
            }
            Stmt::Loop {
                body, continuing, ..
            } => {
                self.loop_depth += 1;
                self.block(body);
                self.block(continuing);
                self.loop_depth -= 1;
            }
            Stmt::Switch {
                selector,
                cases,
                span,
            } => {
                self.expr(selector);
                let int = match selector.ty {
                    Type::INT => Some(false),
                    Type::UINT => Some(true),
                    _ => None,
                };
                let mut seen = Vec::new();
                let mut defaults = 0;
                for c in cases {
                    for l in &c.labels {
                        let ok = match (l, int) {
                            (CaseLabel::Default, _) => {
                                defaults += 1;
                                defaults == 1
                            }
                            (CaseLabel::Value(v @ ConstScalar::Int(_)), Some(false))
                            | (CaseLabel::Value(v @ ConstScalar::Uint(_)), Some(true)) => {
                                let fresh = !seen.contains(v);
                                seen.push(*v);
                                fresh
                            }
                            _ => false,
                        };
                        if !ok {
                            self.fail(*span, "malformed switch labels");
                        }
                    }
                }
                self.switch_depth += 1;
                for c in cases {
                    self.block(&c.body);
                }
                self.switch_depth -= 1;
            }
            Stmt::Break(span) => {
                if self.loop_depth == 0 && self.switch_depth == 0 {
                    self.fail(*span, "`break' outside a loop or switch");
                }
            }
            Stmt::Continue(span) => {
                if self.loop_depth == 0 {
                    self.fail(*span, "`continue' outside a loop");
                }
            }
            Stmt::Return(value, span) => {
                let ret = self.func.map_or(Type::VOID, |f| f.return_type);
                match value {
                    Some(e) => {
                        self.expr(e);
                        if !same_shape(ret, e.ty) {
                            self.fail(*span, "returned value differs from the return type");
                        }
                    }
                    None if !ret.is_void() => self.fail(*span, "`return' without a value"),
                    None => {}
                }
            }
            Stmt::Discard(_) => {}
        }
    }

    fn expr(&mut self, e: &Expr) {
        if e.ty.is_error() {
            self.fail(e.span, "expression with the error type");
            return;
        }
        match &e.kind {
            ExprKind::Const(v) => {
                let n = crate::consteval::flat_size(v.ty, &self.m.structs);
                if v.components.len() != n {
                    self.fail(e.span, "constant with the wrong number of components");
                }
            }
            ExprKind::Global(g) => {
                if g.0 as usize >= self.m.globals.len() {
                    self.fail(e.span, "reference to an unknown global");
                }
            }
            ExprKind::Local(l) => {
                if self.func.is_none_or(|f| l.0 as usize >= f.locals.len()) {
                    self.fail(e.span, "reference to an unknown local");
                }
            }
            ExprKind::Index { base, index } => {
                self.expr(base);
                self.expr(index);
                if index.ty != Type::INT && index.ty != Type::UINT {
                    self.fail(index.span, "index is not an int or uint");
                }
            }
            ExprKind::Swizzle {
                base,
                components,
                count,
            } => {
                self.expr(base);
                let size = base.ty.vector_size().unwrap_or(0);
                if *count == 0
                    || *count > 4
                    || components[..(*count).min(4) as usize]
                        .iter()
                        .any(|&c| c >= size)
                {
                    self.fail(e.span, "swizzle out of range");
                }
            }
            ExprKind::Member { base, index } => {
                self.expr(base);
                let ok = match base.ty.base {
                    Base::Struct(id) => self
                        .m
                        .structs
                        .get(id.0 as usize)
                        .is_some_and(|s| (*index as usize) < s.members.len()),
                    _ => false,
                };
                if !ok {
                    self.fail(e.span, "member of a non-struct or out of range");
                }
            }
            ExprKind::Unary { op, operand } => {
                self.expr(operand);
                let s = operand.ty.scalar();
                let ok = operand.ty == e.ty
                    && match op {
                        UnaryOp::Neg => {
                            matches!(s, Some(Scalar::Float | Scalar::Int | Scalar::Uint))
                        }
                        UnaryOp::Not => operand.ty == Type::BOOL,
                        UnaryOp::BitNot => {
                            matches!(s, Some(Scalar::Int | Scalar::Uint)) && !operand.ty.is_matrix()
                        }
                    };
                if !ok {
                    self.fail(e.span, format!("malformed unary operation {op:?}"));
                }
            }
            ExprKind::Binary { op, left, right } => {
                self.expr(left);
                self.expr(right);
                self.binary(*op, left, right, e);
            }
            ExprKind::Ternary {
                cond,
                accept,
                reject,
            } => {
                self.expr(cond);
                self.expr(accept);
                self.expr(reject);
                if cond.ty != Type::BOOL || !same_shape(accept.ty, reject.ty) {
                    self.fail(e.span, "malformed `?:'");
                }
            }
            ExprKind::Assign { target, value, op } => {
                self.expr(target);
                self.expr(value);
                self.lvalue(target);
                if op.is_none() && !same_shape(target.ty, value.ty) {
                    self.fail(e.span, "assignment of a different type");
                }
            }
            ExprKind::IncDec { target, .. } => {
                self.expr(target);
                self.lvalue(target);
            }
            ExprKind::Call { function, args } => {
                for a in args {
                    self.expr(a);
                }
                match self.m.functions.get(function.0 as usize) {
                    None => self.fail(e.span, "call of an unknown function"),
                    Some(f) => {
                        if f.params.len() != args.len() {
                            self.fail(e.span, "call with the wrong number of arguments");
                        }
                        for (p, a) in f.params.iter().zip(args) {
                            if !same_shape(p.ty, a.ty) {
                                self.fail(a.span, "argument type differs from the parameter's");
                            }
                            if p.qualifier != ParamQualifier::In {
                                self.lvalue(a);
                            }
                        }
                    }
                }
            }
            ExprKind::Builtin { args, .. } | ExprKind::Construct { args } => {
                for a in args {
                    self.expr(a);
                }
            }
            ExprKind::DebugPrintf { format, args } => {
                let convs: Vec<_> = crate::printf::conversions(format).collect();
                if convs.len() != args.len() || !e.ty.is_void() {
                    self.fail(e.span, "debugPrintfEXT with mismatched arguments");
                }
                for (c, a) in convs.iter().zip(args) {
                    self.expr(a);
                    if !c.accepts(a.ty) {
                        self.fail(a.span, "debugPrintfEXT argument of the wrong type");
                    }
                }
            }
            ExprKind::ArrayLength { array } => {
                self.expr(array);
                if array.ty.array != Some(crate::types::ArraySize::Unsized) || e.ty != Type::INT {
                    self.fail(
                        e.span,
                        "buffer length of something other than an unsized array",
                    );
                }
            }
            ExprKind::Convert { operand } => {
                self.expr(operand);
                let ok = matches!(operand.ty.scalar(), Some(Scalar::Int | Scalar::Uint))
                    && e.ty.scalar() == Some(Scalar::Float)
                    && operand.ty.vector_size() == e.ty.vector_size();
                if !ok {
                    self.fail(e.span, "conversion other than int or uint to float");
                }
            }
            ExprKind::Comma { left, right } => {
                self.expr(left);
                self.expr(right);
            }
        }
    }

    fn binary(&mut self, op: BinaryOp, l: &Expr, r: &Expr, e: &Expr) {
        use BinaryOp::*;
        let ok = match op {
            Add | Sub | Mul | Div => {
                let (ls, rs) = (l.ty.scalar(), r.ty.scalar());
                ls.is_some()
                    && ls == rs
                    && ls != Some(Scalar::Bool)
                    && (l.ty == r.ty || l.ty.is_scalar() || r.ty.is_scalar())
            }
            MatMul => {
                (l.ty.is_matrix() || r.ty.is_matrix())
                    && l.ty.scalar() == Some(Scalar::Float)
                    && r.ty.scalar() == Some(Scalar::Float)
            }
            Less | Greater | LessEq | GreaterEq => {
                l.ty == r.ty
                    && (l.ty == Type::INT || l.ty == Type::UINT || l.ty == Type::FLOAT)
                    && e.ty == Type::BOOL
            }
            Mod | BitAnd | BitOr | BitXor => {
                let (ls, rs) = (int_kind(l.ty), int_kind(r.ty));
                ls.is_some()
                    && ls == rs
                    && (l.ty == r.ty || l.ty.is_scalar() || r.ty.is_scalar())
                    && e.ty == if l.ty.is_scalar() { r.ty } else { l.ty }
            }
            Shl | Shr => {
                int_kind(l.ty).is_some()
                    && int_kind(r.ty).is_some()
                    && (r.ty.is_scalar() || r.ty.vector_size() == l.ty.vector_size())
                    && e.ty == l.ty
            }
            Equal | NotEqual => same_shape(l.ty, r.ty) && e.ty == Type::BOOL,
            LogicalAnd | LogicalOr | LogicalXor => {
                l.ty == Type::BOOL && r.ty == Type::BOOL && e.ty == Type::BOOL
            }
        };
        if !ok {
            self.fail(e.span, format!("malformed binary operation {op:?}"));
        }
    }

    fn lvalue(&mut self, e: &Expr) {
        let ok = match &e.kind {
            ExprKind::Global(_) | ExprKind::Local(_) => true,
            ExprKind::Index { base, .. } | ExprKind::Member { base, .. } => {
                self.lvalue(base);
                true
            }
            ExprKind::Swizzle {
                base,
                components,
                count,
            } => {
                self.lvalue(base);
                let c = &components[..(*count).min(4) as usize];
                !c.iter().enumerate().any(|(i, x)| c[..i].contains(x))
            }
            _ => false,
        };
        if !ok {
            self.fail(e.span, "assignment target is not an l-value");
        }
    }
}

/// The scalar kind of an int/uint scalar or vector.
fn int_kind(t: Type) -> Option<Scalar> {
    match (t.array, t.base) {
        (None, Base::Scalar(s) | Base::Vector(s, _)) if matches!(s, Scalar::Int | Scalar::Uint) => {
            Some(s)
        }
        _ => None,
    }
}

/// Types equal up to the size of an unsized array.
fn same_shape(a: Type, b: Type) -> bool {
    a.base == b.base && a.array.is_some() == b.array.is_some()
}
