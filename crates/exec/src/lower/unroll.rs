//! Counted-loop unrolling and known int values.
//!
//! The policy: which `for` loops are unrolled ([`UNROLL_TRIPS`],
//! [`UNROLL_NODES`], [`UNROLL_BUDGET`]) and how the copies are lowered,
//! and the per-frame known int values (an unrolled loop's counter, a
//! constant argument of an inlined call) that let indexing be static.

use super::calls::inlined_cost;
use super::visit::{root_local, visit_live_block, writes_local};
use super::{const_index, Lowerer, R};
use glsl::ir::{BinaryOp, Block, Expr, ExprKind, IncDec, LocalId, Stmt, UnaryOp};
use glsl::types::Type;
use glsl::Span;

/// Most iterations of a loop [`Lowerer::unroll_plan`] unrolls.
const UNROLL_TRIPS: usize = 32;

/// Most expression nodes (calls inlined) of an unrolled loop, all
/// iterations together.
const UNROLL_NODES: u64 = 4096;

/// Most expression nodes unrolling adds to a whole program.
pub(super) const UNROLL_BUDGET: u64 = 16384;

/// A counted loop to unroll ([`Lowerer::unroll_plan`]).
pub(super) struct Unroll<'b> {
    /// Expression nodes the copies add.
    pub(super) extra: u64,
    local: LocalId,
    /// The counter's value in each iteration.
    values: Vec<i32>,
    /// The loop condition's negation (`!(i < n)`) and its statement.
    cond: &'b Expr,
    cond_span: Span,
    /// The body after the condition.
    body: &'b [Stmt],
    continuing: &'b Block,
}

/// Whether `b` has a `break` or `continue` of the loop it is the body of
/// (those of nested loops do not count).
fn leaves_loop(b: &[Stmt]) -> bool {
    b.iter().any(|s| match s {
        Stmt::Break(_) | Stmt::Continue(_) => true,
        Stmt::Block(b) => leaves_loop(b),
        Stmt::If { then, else_, .. } => leaves_loop(then) || leaves_loop(else_),
        // (A `break` there leaves only the switch: counted anyway, which
        // only forgoes unrolling.)
        Stmt::Switch { cases, .. } => cases.iter().any(|c| leaves_loop(&c.body)),
        _ => false,
    })
}

/// `e`, an int expression of constants and `local` (= `v`), evaluated as
/// the executor would (wrapping arithmetic).
fn eval_int(e: &Expr, local: LocalId, v: i32) -> Option<i32> {
    match &e.kind {
        ExprKind::Local(l) if *l == local => Some(v),
        ExprKind::Const(_) => const_index(e),
        ExprKind::Binary { op, left, right } => {
            let (a, b) = (eval_int(left, local, v)?, eval_int(right, local, v)?);
            match op {
                BinaryOp::Add => Some(a.wrapping_add(b)),
                BinaryOp::Sub => Some(a.wrapping_sub(b)),
                BinaryOp::Mul => Some(a.wrapping_mul(b)),
                _ => None,
            }
        }
        _ => None,
    }
}

/// `e`, a bool expression comparing such int expressions (or negating
/// one), evaluated with `local` = `v`.
fn eval_bool(e: &Expr, local: LocalId, v: i32) -> Option<bool> {
    match &e.kind {
        ExprKind::Unary {
            op: UnaryOp::Not,
            operand,
        } => Some(!eval_bool(operand, local, v)?),
        ExprKind::Binary { op, left, right } => {
            let (a, b) = (eval_int(left, local, v)?, eval_int(right, local, v)?);
            match op {
                BinaryOp::Less => Some(a < b),
                BinaryOp::LessEq => Some(a <= b),
                BinaryOp::Greater => Some(a > b),
                BinaryOp::GreaterEq => Some(a >= b),
                BinaryOp::Equal => Some(a == b),
                BinaryOp::NotEqual => Some(a != b),
                _ => None,
            }
        }
        _ => None,
    }
}

/// The counter's value after the loop step `e` (`i++`, `++i`, `i--`,
/// `--i`, `i += c`, `i -= c`, `i = i + c`...) from `v`.
fn step_value(e: &Expr, local: LocalId, v: i32) -> Option<i32> {
    match &e.kind {
        ExprKind::IncDec { op, target } if root_local(target) == Some(local) => {
            let ExprKind::Local(_) = target.kind else {
                return None;
            };
            Some(match op {
                IncDec::PreInc | IncDec::PostInc => v.wrapping_add(1),
                IncDec::PreDec | IncDec::PostDec => v.wrapping_sub(1),
            })
        }
        ExprKind::Assign { op, target, value } if matches!(target.kind, ExprKind::Local(l) if l == local) =>
        {
            let x = eval_int(value, local, v)?;
            match op {
                None => Some(x),
                Some(BinaryOp::Add) => Some(v.wrapping_add(x)),
                Some(BinaryOp::Sub) => Some(v.wrapping_sub(x)),
                Some(BinaryOp::Mul) => Some(v.wrapping_mul(x)),
                _ => None,
            }
        }
        _ => None,
    }
}

impl<'m> Lowerer<'m> {
    /// The int value of `e` when it is known at this point of the
    /// program: an int constant, or a local bound to one (a constant
    /// argument of an inlined call, an unrolled loop's counter).
    pub(super) fn const_int(&self, e: &Expr) -> Option<i32> {
        match &e.kind {
            ExprKind::Local(l) => self
                .frames
                .last()
                .and_then(|f| f.consts.get(l.0 as usize).copied().flatten()),
            _ => const_index(e),
        }
    }

    /// Whether the statements `decl` (declaring `local`) and `next` are a
    /// counted loop to unroll: `local` an int with a constant initial
    /// value, `next` a loop whose body starts with `if (!(cond)) break;`
    /// and whose continuing part steps `local` by a constant, `cond` a
    /// comparison of `local` with a constant; no other `break` or
    /// `continue` of that loop, no other write of `local`; at most
    /// [`UNROLL_TRIPS`] iterations and [`UNROLL_NODES`] expression nodes
    /// in all (calls counted inlined), the copies within what is left of
    /// the program's [`UNROLL_BUDGET`].
    pub(super) fn unroll_plan<'b>(
        &self,
        local: LocalId,
        decl: &Stmt,
        next: &'b Stmt,
    ) -> Option<Unroll<'b>> {
        let Stmt::Declare {
            init: Some(init), ..
        } = decl
        else {
            return None;
        };
        let Stmt::Loop {
            body, continuing, ..
        } = next
        else {
            return None;
        };
        if init.ty != Type::INT {
            return None;
        }
        let first = const_index(init)?;
        let (
            Some(Stmt::If {
                cond,
                then,
                else_,
                span,
            }),
            [step],
        ) = (body.first(), continuing.as_slice())
        else {
            return None;
        };
        if !matches!(then.as_slice(), [Stmt::Break(_)]) || !else_.is_empty() {
            return None;
        }
        let Stmt::Expr(step_expr) = step else {
            return None;
        };
        let rest = &body[1..];
        if leaves_loop(rest) || writes_local(self.m, rest, local) {
            return None;
        }
        let mut values = Vec::new();
        let mut v = first;
        while !eval_bool(cond, local, v)? {
            values.push(v);
            if values.len() > UNROLL_TRIPS {
                return None;
            }
            v = step_value(step_expr, local, v)?;
        }
        let mut nodes = 0u64;
        let mut calls = Vec::new();
        visit_live_block(rest, &mut |e| {
            nodes += 1;
            if let ExprKind::Call { function, .. } = &e.kind {
                calls.push(*function);
            }
        });
        let mut memo = vec![None; self.m.functions.len()];
        for c in calls {
            nodes = nodes.saturating_add(inlined_cost(self.m, c, &mut memo, self.frames.len()));
        }
        let extra = nodes.saturating_mul(values.len().saturating_sub(1) as u64);
        if nodes.saturating_mul(values.len() as u64) > UNROLL_NODES || extra > self.unroll_left {
            return None;
        }
        Some(Unroll {
            extra,
            local,
            values,
            cond,
            cond_span: *span,
            body: rest,
            continuing,
        })
    }

    /// Lowers an unrolled loop (after its counter's declaration): per
    /// iteration the condition (its statement marked and its value
    /// computed, for traces; nothing reads it), the body with the counter
    /// bound to the iteration's value, the continuing part; then the
    /// failing condition. `true` when the body always leaves the
    /// function (the rest of the block is unreachable).
    pub(super) fn unrolled(&mut self, plan: Unroll) -> R<bool> {
        let slot = plan.local.0 as usize;
        for &v in &plan.values {
            self.check_condition(plan.cond, plan.cond_span)?;
            self.bind(slot, Some(v));
            let mark = self.next_reg;
            let ends = self.statements(plan.body)?;
            self.next_reg = mark;
            self.bind(slot, None);
            if ends {
                return Ok(true);
            }
            self.block(plan.continuing)?;
        }
        self.check_condition(plan.cond, plan.cond_span)?;
        // Where the loop's `break` ran (a statement of its own in traces).
        self.mark_statement(plan.cond_span);
        self.konst(0)?;
        Ok(false)
    }

    fn check_condition(&mut self, cond: &Expr, span: Span) -> R<()> {
        let mark = self.next_reg;
        self.mark_statement(span);
        self.expr(cond)?;
        self.next_reg = mark;
        Ok(())
    }

    fn bind(&mut self, slot: usize, v: Option<i32>) {
        if let Some(c) = self.frames.last_mut().and_then(|f| f.consts.get_mut(slot)) {
            *c = v;
        }
    }
}
