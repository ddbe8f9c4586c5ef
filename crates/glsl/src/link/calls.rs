//! The call graph across a stage's objects: the depth of the deepest call
//! chain, against `limits::MAX_CALL_DEPTH`.

use crate::ir::{self, Block, ConstScalar, Expr, ExprKind, FunctionId, Module, Stmt};
use crate::limits;
use std::collections::BTreeSet;

/// Functions on the call stack at the deepest point of a call from
/// `root` (`root` counts 1), capped just past [`limits::MAX_CALL_DEPTH`].
/// The call graph has no cycles (each object was checked); a cycle made
/// across objects is cut where it closes.
pub(super) fn call_depth(m: &Module, root: FunctionId) -> u32 {
    let n = m.functions.len();
    let callees = |f: FunctionId| {
        let mut out = BTreeSet::new();
        if let Some(b) = m.functions.get(f.0 as usize).and_then(|f| f.body.as_ref()) {
            collect_calls(b, &mut out);
        }
        out.into_iter()
            .filter(|c| (c.0 as usize) < n)
            .collect::<Vec<_>>()
    };
    // depth[f]: 0 while unknown; an iterative post-order walk.
    let mut depth = vec![0u32; n];
    let mut open = vec![false; n];
    let mut stack = vec![(root, callees(root), 0u32)];
    open[root.0 as usize] = true;
    loop {
        let height = stack.len() as u32;
        let Some((f, pending, deepest)) = stack.last_mut() else {
            break;
        };
        match pending.pop() {
            Some(c) if depth[c.0 as usize] > 0 => *deepest = (*deepest).max(depth[c.0 as usize]),
            Some(c) if open[c.0 as usize] => {}
            // Past the limit already: no need to know how much further.
            Some(_) if height > limits::MAX_CALL_DEPTH => *deepest = (*deepest).max(1),
            Some(c) => {
                open[c.0 as usize] = true;
                let cs = callees(c);
                stack.push((c, cs, 0));
            }
            None => {
                let (f, d) = (*f, *deepest);
                depth[f.0 as usize] = (d + 1).min(limits::MAX_CALL_DEPTH + 1);
                open[f.0 as usize] = false;
                stack.pop();
                if let Some((_, _, parent)) = stack.last_mut() {
                    *parent = (*parent).max(depth[f.0 as usize]);
                }
            }
        }
    }
    depth[root.0 as usize]
}

/// Calls a block can make: every call except those in an `if` branch whose
/// condition is a constant that rules the branch out (GLSL 1.20 constant
/// expressions fold `if (degrees(0.0) != 0.0)`; a function called only there
/// need not be defined, as Mesa's compile-time folding allows).
pub(super) fn collect_calls(b: &Block, out: &mut BTreeSet<FunctionId>) {
    fn expr(e: &Expr, out: &mut BTreeSet<FunctionId>) {
        if let ExprKind::Call { function, .. } = &e.kind {
            out.insert(*function);
        }
        e.for_each_child(|c| expr(c, out));
    }
    for s in b {
        match s {
            Stmt::If {
                cond, then, else_, ..
            } => match &cond.kind {
                ExprKind::Const(c) => match c.components.first() {
                    Some(ConstScalar::Bool(true)) => collect_calls(then, out),
                    Some(ConstScalar::Bool(false)) => collect_calls(else_, out),
                    _ => {
                        collect_calls(then, out);
                        collect_calls(else_, out);
                    }
                },
                _ => {
                    expr(cond, out);
                    collect_calls(then, out);
                    collect_calls(else_, out);
                }
            },
            Stmt::Block(inner) => collect_calls(inner, out),
            Stmt::Loop {
                body, continuing, ..
            } => {
                collect_calls(body, out);
                collect_calls(continuing, out);
            }
            Stmt::Switch {
                selector, cases, ..
            } => {
                expr(selector, out);
                for c in cases {
                    collect_calls(&c.body, out);
                }
            }
            other => ir::for_each_block_expr(std::slice::from_ref(other), &mut |e| expr(e, out)),
        }
    }
}
