//! User function calls and the inlining policy: [`inlined_cost`] decides
//! (against `inline_limit`) whether every call is inlined or every function
//! is lowered once as a subroutine; a call is then either inlined (a new
//! frame, parameters copied in and `out`/`inout` l-values written back, GLSL
//! 1.20 §6.1.1) or a jump to its subroutine.

use super::visit::{visit_live_block, writes_local};
use super::{unsupported, CtxKind, Frame, Lowerer, Place, Sub, Val, MAX_CALL_DEPTH, R};
use crate::program::{Op, Reg};
use glsl::ir::{Expr, ExprKind, FunctionId, Module, ParamQualifier, Stage};
use glsl::types::Type;

/// Expression nodes of `f` once every call is inlined (saturating).
pub(super) fn inlined_cost(
    m: &Module,
    f: FunctionId,
    memo: &mut Vec<Option<u64>>,
    depth: usize,
) -> u64 {
    if let Some(Some(c)) = memo.get(f.0 as usize) {
        return *c;
    }
    // `depth` counts the frames below this one (main's is 0).
    if depth >= MAX_CALL_DEPTH {
        return u64::MAX;
    }
    let Some(body) = m.functions.get(f.0 as usize).and_then(|f| f.body.as_ref()) else {
        return 0;
    };
    let mut calls = Vec::new();
    let mut nodes = 0u64;
    visit_live_block(body, &mut |e| {
        nodes += 1;
        if let ExprKind::Call { function, .. } = &e.kind {
            calls.push(*function);
        }
    });
    let mut total = nodes;
    for c in calls {
        total = total.saturating_add(inlined_cost(m, c, memo, depth + 1));
    }
    if let Some(slot) = memo.get_mut(f.0 as usize) {
        *slot = Some(total);
    }
    total
}

impl<'m> Lowerer<'m> {
    /// Fresh registers for a function's return value (none for void).
    fn return_regs(&mut self, ty: Type) -> R<Val> {
        if ty.is_void() {
            Ok(Vec::new())
        } else {
            let n = self.size(ty)?;
            self.temps(n)
        }
    }

    pub(super) fn call(&mut self, fid: FunctionId, args: &[Expr]) -> R<Val> {
        super::with_stack(|| self.call_here(fid, args))
    }

    fn call_here(&mut self, fid: FunctionId, args: &[Expr]) -> R<Val> {
        let m = self.m;
        let Some(f) = m.functions.get(fid.0 as usize) else {
            return unsupported("call of an unknown function");
        };
        let Some(body) = &f.body else {
            return unsupported(format!("`{}' has no body", f.name));
        };
        if self.frames.iter().any(|fr| fr.func == fid) {
            return unsupported(format!("`{}' is recursive", f.name));
        }
        if self.frames.len() >= MAX_CALL_DEPTH {
            return unsupported(format!(
                "function calls nested more than {MAX_CALL_DEPTH} deep"
            ));
        }
        if f.params.len() != args.len() {
            return unsupported(format!("`{}' called with the wrong arguments", f.name));
        }
        let sub = match &self.subs {
            Some(subs) => match subs.get(fid.0 as usize) {
                Some(Some(sub)) => Some(sub.clone()),
                _ => return unsupported(format!("`{}' was not lowered", f.name)),
            },
            None => None,
        };
        let locals = match &sub {
            Some(s) => s.locals.clone(),
            None => self.alloc_locals(fid)?,
        };
        // Arguments, left to right (§6.1.1).
        let mut outs: Vec<(Place, Reg, u32)> = Vec::new();
        let mut bound = vec![None; locals.len()];
        for (param, arg) in f.params.iter().zip(args) {
            let Some(&(preg, _)) = locals.get(param.local.0 as usize) else {
                return unsupported("parameter without a local");
            };
            let n = self.size(param.ty)? as u32;
            // The value the parameter starts with: `in` and `inout` ones.
            let value = match param.qualifier {
                ParamQualifier::In => {
                    // An int argument known here, in a parameter the body
                    // never writes: the callee's indexing by it is static
                    // (`gl_LightSource[light]` with a constant `light`).
                    if sub.is_none() && param.ty == Type::INT && !writes_local(m, body, param.local)
                    {
                        if let Some(slot) = bound.get_mut(param.local.0 as usize) {
                            *slot = self.const_int(arg);
                        }
                    }
                    Some(self.expr(arg)?)
                }
                ParamQualifier::Out | ParamQualifier::InOut => {
                    let p = self.place(arg)?;
                    let v = if param.qualifier == ParamQualifier::InOut {
                        Some(self.read(&p)?)
                    } else {
                        None
                    };
                    outs.push((p, preg, n));
                    v
                }
            };
            if let Some(v) = value {
                if v.len() as u32 != n {
                    return unsupported("argument of the wrong size");
                }
                for (k, a) in v.into_iter().enumerate() {
                    self.emit(Op::Store {
                        d: preg + k as u32,
                        a,
                    })?;
                }
            }
        }
        if let Some(sub) = sub {
            self.emit(Op::Call {
                target: sub.entry,
                slot: sub.slot,
            })?;
            if self.stage == Stage::Fragment {
                // Lanes the callee discarded leave the caller's masks too.
                let slots: Vec<u32> = self.ctx.iter().map(|c| c.1).collect();
                let start = self.p.kill_slots.len() as u32;
                self.p.kill_slots.extend(slots);
                let end = self.p.kill_slots.len() as u32;
                self.emit(Op::SyncDiscard { start, end })?;
            }
            // The result is copied: another call would overwrite it.
            let ret = self.copy(&sub.ret)?;
            for (p, preg, n) in outs {
                let v: Val = (preg..preg + n).collect();
                self.write(&p, &v)?;
            }
            return Ok(ret);
        }
        let ret = self.return_regs(f.return_type)?;
        let fs = self.new_slot();
        self.emit(Op::SaveMask { slot: fs })?;
        self.ctx.push((CtxKind::Function, fs));
        self.frames.push(Frame {
            func: fid,
            consts: bound,
            locals,
            ret: ret.clone(),
        });
        let r = self.block(body);
        self.frames.pop();
        self.ctx.pop();
        r?;
        self.emit(Op::RestoreMask { slot: fs })?;
        for (p, preg, n) in outs {
            let v: Val = (preg..preg + n).collect();
            self.write(&p, &v)?;
        }
        Ok(ret)
    }

    /// Lowers every function reachable from `main` once, callees first,
    /// before `main`'s code (jumped over), and switches calls to them.
    pub(super) fn lower_subroutines(&mut self, main: FunctionId) -> R<()> {
        let m = self.m;
        // Post-order of the call graph (an acyclic graph: no recursion).
        let n = m.functions.len();
        let mut state = vec![0u8; n]; // 0 new, 1 open, 2 done
        let mut order = Vec::new();
        let mut stack: Vec<(FunctionId, Vec<FunctionId>)> = Vec::new();
        let callees = |f: FunctionId| {
            let mut out = Vec::new();
            if let Some(b) = m.functions.get(f.0 as usize).and_then(|f| f.body.as_ref()) {
                visit_live_block(b, &mut |e| {
                    if let ExprKind::Call { function, .. } = &e.kind {
                        out.push(*function);
                    }
                });
            }
            out.reverse();
            out
        };
        stack.push((main, callees(main)));
        state[main.0 as usize] = 1;
        while let Some((f, pending)) = stack.last_mut() {
            match pending.pop() {
                Some(c) => match state.get(c.0 as usize) {
                    Some(0) => {
                        state[c.0 as usize] = 1;
                        let cs = callees(c);
                        stack.push((c, cs));
                    }
                    Some(1) => return unsupported("recursive function calls"),
                    Some(_) => {}
                    None => return unsupported("call of an unknown function"),
                },
                None => {
                    let f = *f;
                    state[f.0 as usize] = 2;
                    if f != main {
                        order.push(f);
                    }
                    stack.pop();
                }
            }
        }
        self.subs = Some(vec![None; n]);
        let jump = self.pc();
        self.emit(Op::Jump { target: 0 })?;
        for (slot, &f) in order.iter().enumerate() {
            let func = &m.functions[f.0 as usize];
            let Some(body) = &func.body else {
                return unsupported(format!("`{}' has no body", func.name));
            };
            let locals = self.alloc_locals(f)?;
            let ret = self.return_regs(func.return_type)?;
            let entry = self.pc();
            let fs = self.new_slot();
            self.emit(Op::SaveMask { slot: fs })?;
            // Calls count against the loop budget: a call tree that doubles
            // at every level (2^64 calls) must not hang.
            self.emit(Op::LoopIter)?;
            self.ctx.push((CtxKind::Function, fs));
            self.frames.push(Frame {
                func: f,
                consts: vec![None; locals.len()],
                locals: locals.clone(),
                ret: ret.clone(),
            });
            let r = self.block(body);
            self.frames.pop();
            self.ctx.pop();
            r?;
            self.emit(Op::RestoreMask { slot: fs })?;
            self.emit(Op::Ret { slot: slot as u32 })?;
            // This body's temporaries stay reserved: callers' live values
            // must not share them.
            self.next_reg = self.p.registers;
            if let Some(subs) = &mut self.subs {
                subs[f.0 as usize] = Some(Sub {
                    entry,
                    slot: slot as u32,
                    locals,
                    ret,
                });
            }
        }
        self.p.subroutines = order.len() as u32;
        let here = self.pc();
        self.patch(jump, here);
        Ok(())
    }
}
