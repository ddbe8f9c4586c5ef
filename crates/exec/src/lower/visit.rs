//! Read-only walks over the IR that lowering and its policies share:
//! visiting every expression of a block (optionally only the branches a
//! constant `if` leaves live), whether an expression has side effects, the
//! value of a constant `bool` condition. No code is emitted here.

use glsl::ir::{ConstScalar, ConstValue, Expr, ExprKind, LocalId, Module, ParamQualifier, Stmt};

/// Whether evaluating `e` may write a variable (assignments, `++`/`--`,
/// user function calls).
pub(super) fn has_effects(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Const(_) | ExprKind::Global(_) | ExprKind::Local(_) => false,
        ExprKind::Assign { .. }
        | ExprKind::IncDec { .. }
        | ExprKind::Call { .. }
        | ExprKind::DebugPrintf { .. } => true,
        ExprKind::Index { base, index } => has_effects(base) || has_effects(index),
        ExprKind::Swizzle { base, .. } | ExprKind::Member { base, .. } => has_effects(base),
        ExprKind::Unary { operand, .. } | ExprKind::Convert { operand } => has_effects(operand),
        ExprKind::ArrayLength { array } => has_effects(array),
        ExprKind::Binary { left, right, .. } | ExprKind::Comma { left, right } => {
            has_effects(left) || has_effects(right)
        }
        ExprKind::Ternary {
            cond,
            accept,
            reject,
        } => has_effects(cond) || has_effects(accept) || has_effects(reject),
        ExprKind::Builtin { args, .. } | ExprKind::Construct { args } => {
            args.iter().any(has_effects)
        }
    }
}

/// Calls `f` on every expression of `b`, outer before inner.
pub(super) fn visit_block(b: &[Stmt], f: &mut dyn FnMut(&Expr)) {
    visit_block_with(b, false, f)
}

/// Calls `f` on every expression of `b` that lowering reaches: not the
/// branch a constant `if` condition rules out (see [`const_bool`]).
pub(super) fn visit_live_block(b: &[Stmt], f: &mut dyn FnMut(&Expr)) {
    visit_block_with(b, true, f)
}

fn visit_block_with(b: &[Stmt], live_only: bool, f: &mut dyn FnMut(&Expr)) {
    for s in b {
        match s {
            Stmt::Expr(e) | Stmt::Return(Some(e), _) => visit_expr(e, f),
            Stmt::Declare { init: Some(e), .. } => visit_expr(e, f),
            Stmt::Block(b) => visit_block_with(b, live_only, f),
            Stmt::If {
                cond, then, else_, ..
            } => match const_bool(cond).filter(|_| live_only) {
                Some(true) => visit_block_with(then, live_only, f),
                Some(false) => visit_block_with(else_, live_only, f),
                None => {
                    visit_expr(cond, f);
                    visit_block_with(then, live_only, f);
                    visit_block_with(else_, live_only, f);
                }
            },
            Stmt::Loop {
                body, continuing, ..
            } => {
                visit_block_with(body, live_only, f);
                visit_block_with(continuing, live_only, f);
            }
            Stmt::Switch {
                selector, cases, ..
            } => {
                visit_expr(selector, f);
                for c in cases {
                    visit_block_with(&c.body, live_only, f);
                }
            }
            _ => {}
        }
    }
}

/// The value of a constant `bool` condition. An `if` on one is lowered to
/// the taken branch only (the linker likewise ignores calls in the other,
/// which may name a function without a body).
pub(super) fn const_bool(e: &Expr) -> Option<bool> {
    match &e.kind {
        ExprKind::Const(ConstValue { components, .. }) => match components.first() {
            Some(ConstScalar::Bool(b)) => Some(*b),
            _ => None,
        },
        _ => None,
    }
}

fn visit_expr(e: &Expr, f: &mut dyn FnMut(&Expr)) {
    f(e);
    match &e.kind {
        ExprKind::Const(_) | ExprKind::Global(_) | ExprKind::Local(_) => {}
        ExprKind::Index { base, index } => {
            visit_expr(base, f);
            visit_expr(index, f);
        }
        ExprKind::Swizzle { base, .. } | ExprKind::Member { base, .. } => visit_expr(base, f),
        ExprKind::Unary { operand, .. } | ExprKind::Convert { operand } => visit_expr(operand, f),
        ExprKind::ArrayLength { array } => visit_expr(array, f),
        ExprKind::Binary { left, right, .. } | ExprKind::Comma { left, right } => {
            visit_expr(left, f);
            visit_expr(right, f);
        }
        ExprKind::Ternary {
            cond,
            accept,
            reject,
        } => {
            visit_expr(cond, f);
            visit_expr(accept, f);
            visit_expr(reject, f);
        }
        ExprKind::Assign { target, value, .. } => {
            visit_expr(target, f);
            visit_expr(value, f);
        }
        ExprKind::IncDec { target, .. } => visit_expr(target, f),
        ExprKind::Call { args, .. }
        | ExprKind::Builtin { args, .. }
        | ExprKind::DebugPrintf { args, .. }
        | ExprKind::Construct { args } => args.iter().for_each(|a| visit_expr(a, f)),
    }
}

/// The local an l-value expression writes into (through indexing,
/// swizzles and members).
pub(super) fn root_local(e: &Expr) -> Option<LocalId> {
    match &e.kind {
        ExprKind::Local(l) => Some(*l),
        ExprKind::Index { base, .. }
        | ExprKind::Swizzle { base, .. }
        | ExprKind::Member { base, .. } => root_local(base),
        _ => None,
    }
}

/// Whether `b` may write `local`: an assignment, `++`/`--`, or an `out` /
/// `inout` argument rooted at it.
pub(super) fn writes_local(m: &Module, b: &[Stmt], local: LocalId) -> bool {
    let mut writes = false;
    visit_block(b, &mut |e| match &e.kind {
        ExprKind::Assign { target, .. } | ExprKind::IncDec { target, .. } => {
            writes |= root_local(target) == Some(local);
        }
        ExprKind::Call { function, args } => {
            let params = m.functions.get(function.0 as usize).map(|f| &f.params[..]);
            for (k, a) in args.iter().enumerate() {
                let by_value = params
                    .and_then(|p| p.get(k))
                    .is_some_and(|p| p.qualifier == ParamQualifier::In);
                writes |= !by_value && root_local(a) == Some(local);
            }
        }
        _ => {}
    });
    writes
}
