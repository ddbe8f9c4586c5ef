//! Allocation and emission: registers (a bump allocator whose mark each
//! block and statement resets), mask slots, uniform words, the registers of
//! a function's locals, constants, and appending ops within the program's
//! size limits ([`crate::program::MAX_REGISTERS`], [`crate::program::MAX_OPS`]). Every other
//! module emits through these.

use super::visit::visit_block;
use super::{const_index, unsupported, GlobalLoc, Lowerer, Val, R};
use crate::interface::{kinds, size_of};
use crate::program::{Op, Reg, StatementMark, VarInfo, MAX_OPS, MAX_REGISTERS};
use glsl::ir::{ExprKind, FunctionId, GlobalId};
use glsl::types::{ArraySize, Scalar, Type};
use glsl::Span;

impl<'m> Lowerer<'m> {
    pub(super) fn size(&self, ty: Type) -> R<usize> {
        let n = size_of(ty, &self.m.structs);
        if n > MAX_REGISTERS as usize {
            return unsupported("a variable is too large for the executor");
        }
        Ok(n)
    }

    pub(super) fn alloc(&mut self, n: usize) -> R<Reg> {
        let r = self.next_reg;
        let next = (r as u64) + n as u64;
        if next > MAX_REGISTERS as u64 {
            return unsupported(format!(
                "the program needs more than {MAX_REGISTERS} registers"
            ));
        }
        self.next_reg = next as u32;
        self.p.registers = self.p.registers.max(self.next_reg);
        Ok(r)
    }

    pub(super) fn temps(&mut self, n: usize) -> R<Val> {
        let r = self.alloc(n)?;
        Ok((r..r + n as u32).collect())
    }

    pub(super) fn temp(&mut self) -> R<Reg> {
        self.alloc(1)
    }

    /// Emits the op `op` makes for a fresh register and gives that register.
    pub(super) fn emit_temp(&mut self, op: impl FnOnce(Reg) -> Op) -> R<Reg> {
        let d = self.temp()?;
        self.emit(op(d))?;
        Ok(d)
    }

    pub(super) fn new_slot(&mut self) -> u32 {
        self.p.mask_slots += 1;
        self.p.mask_slots - 1
    }

    pub(super) fn emit(&mut self, op: Op) -> R<()> {
        if self.p.ops.len() >= MAX_OPS {
            return unsupported(format!(
                "the program is larger than {MAX_OPS} instructions after inlining"
            ));
        }
        self.p.ops.push(op);
        Ok(())
    }

    pub(super) fn pc(&self) -> u32 {
        self.p.ops.len() as u32
    }

    pub(super) fn patch(&mut self, at: u32, to: u32) {
        match self.p.ops.get_mut(at as usize) {
            Some(Op::JumpIfNone { target }) | Some(Op::Jump { target }) => *target = to,
            _ => {}
        }
    }

    pub(super) fn mark_statement(&mut self, span: Span) {
        let op = self.pc();
        match self.p.statements.last_mut() {
            Some(last) if last.op == op => last.span = span,
            _ => self.p.statements.push(StatementMark { op, span }),
        }
    }

    pub(super) fn konst(&mut self, bits: u32) -> R<Reg> {
        let d = self.temp()?;
        self.emit(Op::Const { d, bits })?;
        Ok(d)
    }

    pub(super) fn fconst(&mut self, f: f32) -> R<Reg> {
        self.konst(glsl::math::flush_denormal(f).to_bits())
    }

    pub(super) fn copy(&mut self, v: &[Reg]) -> R<Val> {
        let out = self.temps(v.len())?;
        for (&d, &a) in out.iter().zip(v) {
            self.emit(Op::Mov { d, a })?;
        }
        Ok(out)
    }

    /// `v` in consecutive registers (copied unless it already is).
    pub(super) fn consecutive(&mut self, v: &[Reg]) -> R<Reg> {
        let ok = v.windows(2).all(|w| w[1] == w[0].wrapping_add(1));
        match v.first() {
            Some(&first) if ok => Ok(first),
            _ => Ok(self.copy(v)?.first().copied().unwrap_or(0)),
        }
    }

    pub(super) fn uniform_word(&mut self, g: GlobalId) -> R<u32> {
        let i = g.0 as usize;
        match self.globals.get(i) {
            Some(GlobalLoc::Uniform(Some(w))) => Ok(*w),
            Some(GlobalLoc::Uniform(None)) => {
                let n = self.size(self.m.globals[i].ty)? as u64;
                let w = self.next_word;
                if w as u64 + n > u32::MAX as u64 / 2 {
                    return unsupported("too many uniform components");
                }
                self.next_word = w + n as u32;
                let ks = kinds(self.m.globals[i].ty, &self.m.structs);
                self.uniform_float.resize(w as usize, false);
                self.uniform_float
                    .extend(ks.iter().map(|&k| k == Scalar::Float));
                self.globals[i] = GlobalLoc::Uniform(Some(w));
                self.uniform_order.push(g);
                Ok(w)
            }
            _ => unsupported("not a uniform"),
        }
    }

    pub(super) fn uniform_is_float(&self, word: u32) -> bool {
        self.uniform_float
            .get(word as usize)
            .copied()
            .unwrap_or(false)
    }

    pub(super) fn alloc_locals(&mut self, f: FunctionId) -> R<Vec<(Reg, Type)>> {
        let m = self.m;
        let func = &m.functions[f.0 as usize];
        let mut out = Vec::with_capacity(func.locals.len());
        let mut implicit: Vec<u32> = Vec::new();
        if func
            .locals
            .iter()
            .any(|l| l.ty.array == Some(ArraySize::Unsized))
        {
            // A local array declared without a size takes the largest
            // constant index used plus one (GLSL 1.10 §4.1.9), as the
            // linker does for globals.
            implicit = vec![0; func.locals.len()];
            if let Some(body) = &func.body {
                visit_block(body, &mut |e| {
                    if let ExprKind::Index { base, index } = &e.kind {
                        if let (ExprKind::Local(l), Some(i)) = (&base.kind, const_index(index)) {
                            if let Some(n) = implicit.get_mut(l.0 as usize) {
                                *n = (*n).max(i.max(0) as u32 + 1);
                            }
                        }
                    }
                });
            }
        }
        for (i, l) in func.locals.iter().enumerate() {
            let mut ty = l.ty;
            if ty.array == Some(ArraySize::Unsized) {
                let n = implicit.get(i).copied().unwrap_or(0).max(1);
                ty.array = Some(ArraySize::Sized(n));
            }
            let n = self.size(ty)?;
            let r = self.alloc(n)?;
            if self.p.vars.len() < 1 << 16 {
                self.p.vars.push(VarInfo {
                    name: l.name.clone(),
                    ty,
                    first_register: r,
                    registers: n as u32,
                });
            }
            out.push((r, ty));
        }
        Ok(out)
    }
}
