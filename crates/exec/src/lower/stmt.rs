//! Statements and structured control flow: blocks, `if` (constant
//! conditions lowered to the taken branch), loops, `switch`, `break`, `continue`,
//! `return` and `discard` as execution-mask operations on the mask slots of
//! the enclosing contexts (see the module docs of [`super`]).

use super::visit::const_bool;
use super::{const_bits, unsupported, CtxKind, Lowerer, R};
use crate::program::Op;
use glsl::ir::{Block, CaseLabel, Expr, Stmt, SwitchCase};

impl<'m> Lowerer<'m> {
    pub(super) fn block(&mut self, b: &Block) -> R<()> {
        let mark = self.next_reg;
        self.statements(b)?;
        self.next_reg = mark;
        Ok(())
    }

    /// Lowers `b`'s statements up to the first that always leaves it;
    /// `true` when there is one (the rest is unreachable).
    pub(super) fn statements(&mut self, b: &[Stmt]) -> R<bool> {
        let mut i = 0;
        while let Some(s) = b.get(i) {
            // `for (int i = A; i < B; i++)` with a few iterations and a
            // body that leaves `i` alone: unrolled (see `unroll_plan`).
            if let (Stmt::Declare { local, .. }, Some(next)) = (s, b.get(i + 1)) {
                if let Some(plan) = self.unroll_plan(*local, s, next) {
                    self.unroll_left -= plan.extra;
                    if self.stmt(s)? || self.unrolled(plan)? {
                        return Ok(true);
                    }
                    i += 2;
                    continue;
                }
            }
            if self.stmt(s)? {
                return Ok(true);
            }
            i += 1;
        }
        Ok(false)
    }

    /// Lowers one statement; `true` when it always leaves the block
    /// (the rest of the block is unreachable).
    fn stmt(&mut self, s: &Stmt) -> R<bool> {
        super::with_stack(|| self.stmt_here(s))
    }

    fn stmt_here(&mut self, s: &Stmt) -> R<bool> {
        let mark = self.next_reg;
        let ends = match s {
            Stmt::Expr(e) => {
                self.mark_statement(e.span);
                self.expr(e)?;
                false
            }
            Stmt::Declare { local, init, span } => {
                if let Some(e) = init {
                    self.mark_statement(*span);
                    let v = self.expr(e)?;
                    let p = self.local_place(*local)?;
                    self.write(&p, &v)?;
                }
                false
            }
            Stmt::Block(b) => {
                self.block(b)?;
                false
            }
            Stmt::If {
                cond,
                then,
                else_,
                span,
            } => {
                if let Some(taken) = const_bool(cond) {
                    // Only the taken branch exists (it may call functions
                    // that have no body in the other).
                    self.block(if taken { then } else { else_ })?;
                    self.next_reg = mark;
                    return Ok(false);
                }
                self.mark_statement(*span);
                let c = self.expr(cond)?;
                let c = self.copy(&c[..1.min(c.len())])?;
                let Some(&c) = c.first() else {
                    return unsupported("if condition has no value");
                };
                let s = self.new_slot();
                self.emit(Op::SaveMask { slot: s })?;
                self.ctx.push((CtxKind::If, s));
                self.emit(Op::AndMask { c })?;
                let j1 = self.pc();
                self.emit(Op::JumpIfNone { target: 0 })?;
                self.block(then)?;
                if else_.is_empty() {
                    let end = self.pc();
                    self.patch(j1, end);
                } else {
                    let else_at = self.pc();
                    self.patch(j1, else_at);
                    self.emit(Op::AndNotMask { slot: s, c })?;
                    let j2 = self.pc();
                    self.emit(Op::JumpIfNone { target: 0 })?;
                    self.block(else_)?;
                    let end = self.pc();
                    self.patch(j2, end);
                }
                self.emit(Op::RestoreMask { slot: s })?;
                self.ctx.pop();
                false
            }
            Stmt::Loop {
                body, continuing, ..
            } => {
                let entry = self.new_slot();
                self.emit(Op::SaveMask { slot: entry })?;
                self.ctx.push((CtxKind::LoopEntry, entry));
                let run = self.new_slot();
                self.emit(Op::SaveMask { slot: run })?;
                self.ctx.push((CtxKind::LoopRun, run));
                let head = self.pc();
                self.emit(Op::RestoreMask { slot: run })?;
                let jexit = self.pc();
                self.emit(Op::JumpIfNone { target: 0 })?;
                self.emit(Op::LoopIter)?;
                self.block(body)?;
                self.emit(Op::RestoreMask { slot: run })?;
                self.block(continuing)?;
                self.emit(Op::Jump { target: head })?;
                let exit = self.pc();
                self.patch(jexit, exit);
                self.ctx.pop();
                self.ctx.pop();
                self.emit(Op::RestoreMask { slot: entry })?;
                false
            }
            Stmt::Switch {
                selector,
                cases,
                span,
            } => {
                self.mark_statement(*span);
                self.switch(selector, cases)?;
                false
            }
            Stmt::Break(span) => {
                self.mark_statement(*span);
                let slots =
                    self.kill_list(|k| k == CtxKind::LoopRun || k == CtxKind::SwitchRun, true)?;
                self.kill(slots, false)?;
                true
            }
            Stmt::Continue(span) => {
                self.mark_statement(*span);
                let slots = self.kill_list(|k| k == CtxKind::LoopRun, false)?;
                self.kill(slots, false)?;
                true
            }
            Stmt::Return(value, span) => {
                self.mark_statement(*span);
                if let Some(e) = value {
                    let v = self.expr(e)?;
                    let ret = self
                        .frames
                        .last()
                        .map(|f| f.ret.clone())
                        .unwrap_or_default();
                    if ret.len() != v.len() {
                        return unsupported("return value of the wrong size");
                    }
                    for (d, a) in ret.into_iter().zip(v) {
                        self.emit(Op::Store { d, a })?;
                    }
                }
                let slots = self.kill_list(|k| k == CtxKind::Function, false)?;
                self.kill(slots, false)?;
                true
            }
            Stmt::Discard(span) => {
                self.mark_statement(*span);
                let slots: Vec<u32> = self.ctx.iter().map(|c| c.1).collect();
                self.kill(slots, true)?;
                true
            }
        };
        self.next_reg = mark;
        Ok(ends)
    }

    /// A switch: per lane the index of the case it starts at (`cases.len()`
    /// when none), then case `i` under the running mask narrowed to the
    /// lanes whose index is at most `i` (those that started there or fell
    /// through; `break` has removed the others from the running mask).
    fn switch(&mut self, selector: &Expr, cases: &[SwitchCase]) -> R<()> {
        let v = self.expr(selector)?;
        // A copy: the cases may write the selector's variable.
        let v = self.copy(&v[..1.min(v.len())])?;
        let Some(&sel) = v.first() else {
            return unsupported("switch selector has no value");
        };
        if cases.is_empty() {
            return Ok(());
        }
        let none = cases
            .iter()
            .position(|c| c.labels.contains(&CaseLabel::Default))
            .unwrap_or(cases.len());
        let mut start = self.konst(none as u32)?;
        for (i, c) in cases.iter().enumerate() {
            for l in &c.labels {
                let CaseLabel::Value(value) = l else {
                    continue;
                };
                let k = self.konst(const_bits(*value))?;
                let eq = self.emit_temp(|d| Op::IEq { d, a: sel, b: k })?;
                let here = self.konst(i as u32)?;
                let next = self.emit_temp(|d| Op::Select {
                    d,
                    c: eq,
                    a: here,
                    b: start,
                })?;
                start = next;
            }
        }
        let entry = self.new_slot();
        self.emit(Op::SaveMask { slot: entry })?;
        self.ctx.push((CtxKind::SwitchEntry, entry));
        let run = self.new_slot();
        self.emit(Op::SaveMask { slot: run })?;
        self.ctx.push((CtxKind::SwitchRun, run));
        for (i, c) in cases.iter().enumerate() {
            self.emit(Op::RestoreMask { slot: run })?;
            let here = self.konst(i as u32)?;
            let reached = self.emit_temp(|d| Op::ULe {
                d,
                a: start,
                b: here,
            })?;
            self.emit(Op::AndMask { c: reached })?;
            let skip = self.pc();
            self.emit(Op::JumpIfNone { target: 0 })?;
            self.block(&c.body)?;
            let end = self.pc();
            self.patch(skip, end);
        }
        self.ctx.pop();
        self.ctx.pop();
        self.emit(Op::RestoreMask { slot: entry })
    }

    /// The mask slots from the innermost context out to the first one for
    /// which `target` holds (included when `inclusive`).
    fn kill_list(&self, target: impl Fn(CtxKind) -> bool, inclusive: bool) -> R<Vec<u32>> {
        let mut out = Vec::new();
        for &(kind, slot) in self.ctx.iter().rev() {
            if target(kind) {
                if inclusive {
                    out.push(slot);
                }
                return Ok(out);
            }
            if kind == CtxKind::Function {
                break;
            }
            out.push(slot);
        }
        unsupported("break or continue outside a loop")
    }

    fn kill(&mut self, slots: Vec<u32>, discard: bool) -> R<()> {
        let start = self.p.kill_slots.len() as u32;
        self.p.kill_slots.extend(slots);
        let end = self.p.kill_slots.len() as u32;
        self.emit(if discard {
            Op::Discard { start, end }
        } else {
            Op::Kill { start, end }
        })
    }
}
