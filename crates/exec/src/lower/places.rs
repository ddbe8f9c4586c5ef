//! L-values and indexed reads: a [`Place`] names the storage an
//! expression denotes (a variable's registers or uniform words, an offset,
//! a dynamic per-lane offset clamped to the array, a swizzle); reading and
//! writing one (masked stores, gathers and scatters for dynamic indices,
//! uniform reads for uniforms).

use super::{kind_of, unsupported, GlobalLoc, Lowerer, Place, Root, Val, R};
use crate::program::{Op, Reg};
use glsl::ir::{Expr, ExprKind, GlobalId, LocalId};
use glsl::types::{ArraySize, Base, Scalar, Type};

impl<'m> Lowerer<'m> {
    pub(super) fn local_place(&mut self, l: LocalId) -> R<Place> {
        let Some(frame) = self.frames.last() else {
            return unsupported("local variable outside a function");
        };
        let Some(&(r, ty)) = frame.locals.get(l.0 as usize) else {
            return unsupported("unknown local variable");
        };
        let size = self.size(ty)? as u32;
        Ok(Place {
            root: Root::Reg(r),
            size,
            ty,
            off: 0,
            dynamic: None,
            comps: None,
            mem: None,
        })
    }

    fn global_place(&mut self, g: GlobalId) -> R<Place> {
        let i = g.0 as usize;
        let Some(global) = self.m.globals.get(i) else {
            return unsupported("unknown global variable");
        };
        self.used[i] = true;
        let ty = global.ty;
        if let Some(mg) = self.mem_global(i) {
            return self.mem_global_place(mg, ty);
        }
        let size = self.size(ty)? as u32;
        let root = match self.globals[i] {
            GlobalLoc::Reg(r) => Root::Reg(r),
            GlobalLoc::Uniform(_) => Root::Uniform(self.uniform_word(g)?),
            GlobalLoc::Memory(_) => return unsupported("a global in memory"),
        };
        Ok(Place {
            root,
            size,
            ty,
            off: 0,
            dynamic: None,
            comps: None,
            mem: None,
        })
    }

    pub(super) fn global_by_name(&mut self, name: &str) -> R<Place> {
        match self.m.globals.iter().position(|g| g.name == name) {
            Some(i) => self.global_place(GlobalId(i as u32)),
            None => unsupported(format!("`{name}' is not declared")),
        }
    }

    pub(super) fn place(&mut self, e: &Expr) -> R<Place> {
        match &e.kind {
            ExprKind::Global(g) => self.global_place(*g),
            ExprKind::Local(l) => self.local_place(*l),
            ExprKind::Index { base, index } => {
                let p = self.place(base)?;
                if let Some(i) = self.const_int(index) {
                    if p.mem.is_some() {
                        return self.mem_index(p, Ok(i));
                    }
                    return self.index_const(p, i);
                }
                let i = self.expr(index)?;
                let Some(&i) = i.first() else {
                    return unsupported("index without a value");
                };
                let i = if index.ty.scalar() == Some(glsl::types::Scalar::Uint) {
                    self.uint_index(i)?
                } else {
                    i
                };
                if p.mem.is_some() {
                    return self.mem_index(p, Err(i));
                }
                self.index_dynamic(p, i)
            }
            ExprKind::Member { base, index } => {
                let mut p = self.place(base)?;
                if p.mem.is_some() {
                    return self.mem_member(p, *index);
                }
                let Base::Struct(id) = p.ty.base else {
                    return unsupported("member of a non-struct");
                };
                let Some(def) = self.m.structs.get(id.0 as usize) else {
                    return unsupported("unknown struct");
                };
                if p.ty.is_array() || p.comps.is_some() {
                    return unsupported("member of an array");
                }
                let mut off = 0u32;
                let mut found = None;
                for (k, mb) in def.members.iter().enumerate() {
                    if k as u32 == *index {
                        found = Some(mb.ty);
                        break;
                    }
                    off += self.size(mb.ty)? as u32;
                }
                let Some(ty) = found else {
                    return unsupported("unknown struct member");
                };
                p.off += off;
                p.ty = ty;
                Ok(p)
            }
            ExprKind::Swizzle {
                base,
                components,
                count,
            } => {
                let mut p = self.place(base)?;
                let n = (*count as usize).min(4);
                let width = p.ty.vector_size().unwrap_or(1) as u32;
                let sel: Vec<u32> = components[..n]
                    .iter()
                    .map(|&c| (c as u32).min(width.saturating_sub(1)))
                    .collect();
                let comps = match &p.comps {
                    Some(prev) => sel
                        .iter()
                        .map(|&c| prev.get(c as usize).copied().unwrap_or(0))
                        .collect(),
                    None => sel,
                };
                p.comps = Some(comps);
                p.ty = Type::vec(kind_of(p.ty), n as u8);
                Ok(p)
            }
            _ => {
                let v = self.expr(e)?;
                self.temp_place(&v, e.ty)
            }
        }
    }

    /// A place over a computed value (for indexing r-values).
    fn temp_place(&mut self, v: &[Reg], ty: Type) -> R<Place> {
        let r = self.consecutive(v)?;
        Ok(Place {
            root: Root::Reg(r),
            size: v.len() as u32,
            ty,
            off: 0,
            dynamic: None,
            comps: None,
            mem: None,
        })
    }

    /// (element type, element count, stride) of an indexable type.
    fn index_shape(&self, ty: Type) -> R<(Type, u32, u32)> {
        match (ty.array, ty.base) {
            (Some(ArraySize::Sized(n)), _) => {
                let e = ty.element();
                Ok((e, n, self.size(e)? as u32))
            }
            (Some(ArraySize::Unsized), _) => unsupported("indexing an unsized array"),
            (None, Base::Vector(s, n)) => Ok((Type::vec(s, 1), n as u32, 1)),
            (None, Base::Matrix { cols, rows }) => {
                Ok((Type::vec(Scalar::Float, rows), cols as u32, rows as u32))
            }
            _ => unsupported("indexing a value that is not an array, vector or matrix"),
        }
    }

    fn index_const(&mut self, mut p: Place, i: i32) -> R<Place> {
        if let Some(comps) = &p.comps {
            let k = (i.max(0) as usize).min(comps.len().saturating_sub(1));
            p.comps = Some(vec![comps.get(k).copied().unwrap_or(0)]);
            p.ty = Type::vec(kind_of(p.ty), 1);
            return Ok(p);
        }
        let (elem, n, stride) = self.index_shape(p.ty)?;
        if n == 0 {
            return unsupported("indexing an empty array");
        }
        let i = (i.max(0) as u32).min(n - 1);
        p.off += i * stride;
        p.ty = elem;
        Ok(p)
    }

    /// A uint index as an int one for [`Op::ClampIdx`] (which reads it
    /// signed): values from 2^31 on become `i32::MAX`, so they too select
    /// the last element.
    fn uint_index(&mut self, i: Reg) -> R<Reg> {
        let limit = self.konst(0x8000_0000)?;
        let small = self.emit_temp(|d| Op::ULt { d, a: i, b: limit })?;
        let largest = self.konst(i32::MAX as u32)?;
        self.emit_temp(|d| Op::Select {
            d,
            c: small,
            a: i,
            b: largest,
        })
    }

    fn index_dynamic(&mut self, mut p: Place, i: Reg) -> R<Place> {
        let (d, span, elem) = if let Some(comps) = p.comps.take() {
            // `v.zyx[i]`: the component offset is looked up per lane from
            // the swizzle, so the place stays writable.
            let Some((&first, rest)) = comps.split_first() else {
                return unsupported("indexing an empty swizzle");
            };
            let k = self.emit_temp(|d| Op::ClampIdx {
                d,
                a: i,
                max: rest.len() as u32,
                stride: 1,
            })?;
            let mut d = self.konst(first)?;
            for (j, &c) in rest.iter().enumerate() {
                let jr = self.konst(j as u32 + 1)?;
                let eq = self.emit_temp(|d| Op::IEq { d, a: k, b: jr })?;
                let cr = self.konst(c)?;
                let sel = self.emit_temp(|dst| Op::Select {
                    d: dst,
                    c: eq,
                    a: cr,
                    b: d,
                })?;
                d = sel;
            }
            let span = comps.iter().copied().max().unwrap_or(0);
            (d, span, Type::vec(kind_of(p.ty), 1))
        } else {
            let (elem, n, stride) = self.index_shape(p.ty)?;
            if n == 0 {
                return unsupported("indexing an empty array");
            }
            let d = self.emit_temp(|d| Op::ClampIdx {
                d,
                a: i,
                max: n - 1,
                stride,
            })?;
            (d, (n - 1) * stride, elem)
        };
        p.dynamic = match p.dynamic {
            None => Some((d, span)),
            Some((prev, max)) => {
                let sum = self.emit_temp(|dst| Op::IAdd {
                    d: dst,
                    a: prev,
                    b: d,
                })?;
                Some((sum, max + span))
            }
        };
        p.ty = elem;
        Ok(p)
    }

    fn place_comps(&self, p: &Place) -> R<Vec<u32>> {
        Ok(match &p.comps {
            Some(c) => c.clone(),
            None => (0..self.size(p.ty)? as u32).collect(),
        })
    }

    pub(super) fn read(&mut self, p: &Place) -> R<Val> {
        if p.mem.is_some() {
            return self.mem_read(p);
        }
        let comps = self.place_comps(p)?;
        let mut out = Vec::with_capacity(comps.len());
        for c in comps {
            let pos = p.off + c;
            let r = match (p.root, p.dynamic) {
                (Root::Reg(r), None) => r + pos,
                (Root::Reg(r), Some((off, max))) => self.emit_temp(|d| Op::Gather {
                    d,
                    base: r + pos,
                    off,
                    max,
                })?,
                (Root::Uniform(w), None) => {
                    let d = self.temp()?;
                    let float = self.uniform_is_float(w + pos);
                    self.emit(Op::Uniform {
                        d,
                        word: w + pos,
                        float,
                    })?;
                    d
                }
                (Root::Memory, _) => return unsupported("a place in memory without its address"),
                (Root::Uniform(w), Some((off, max))) => {
                    let d = self.temp()?;
                    let float = self.uniform_is_float(w + pos);
                    self.emit(Op::GatherUniform {
                        d,
                        word: w + pos,
                        off,
                        max,
                        float,
                    })?;
                    d
                }
            };
            out.push(r);
        }
        Ok(out)
    }

    /// Stores `v` into `p` on the active lanes.
    pub(super) fn write(&mut self, p: &Place, v: &[Reg]) -> R<()> {
        if p.mem.is_some() {
            return self.mem_write(p, v);
        }
        let Root::Reg(root) = p.root else {
            return unsupported("assignment to a uniform");
        };
        let comps = self.place_comps(p)?;
        if comps.len() != v.len() {
            return unsupported(format!(
                "assigning {} components to {}",
                v.len(),
                comps.len()
            ));
        }
        let overlaps = v.iter().any(|&r| r >= root && r < root + p.size);
        let copied;
        let v = if overlaps {
            copied = self.copy(v)?;
            &copied[..]
        } else {
            v
        };
        for (c, &a) in comps.into_iter().zip(v) {
            let d = root + p.off + c;
            match p.dynamic {
                None => self.emit(Op::Store { d, a })?,
                Some((off, max)) => self.emit(Op::Scatter {
                    base: d,
                    off,
                    max,
                    a,
                })?,
            }
        }
        Ok(())
    }
}
