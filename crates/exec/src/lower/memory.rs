//! Storage blocks and shared variables: places in memory
//! ([`crate::Memory`]) rather than registers. A [`MemPlace`] is a byte
//! address in one memory space (a storage block element, or the work
//! group's shared variables), laid out by std140 or std430
//! (`glsl::layout`): indexing adds a stride (constant, or clamped per lane
//! as register arrays are), members add their offsets, and a read or a
//! write is one word per scalar component. Floats read from memory are
//! flushed and bools normalized to 0/1, as every value entering a run.

use super::{kind_of, unsupported, GlobalLoc, Lowerer, Place, Root, Val, R};
use crate::memory::{buffer_space, AtomicOp, SHARED_SPACE};
use crate::program::{Op, Reg, F1};
use glsl::builtin_fn::BuiltinFn;
use glsl::ir::{BlockId, Expr, Module, Storage};
use glsl::layout::{array_layout, block_offsets, matrix_stride, size_align, Rules};
use glsl::types::{ArraySize, Base, Scalar, Type};

/// Where a global in memory starts (decided once per module).
#[derive(Clone, Copy, Debug)]
pub(super) struct MemGlobal {
    /// Its block's first space ([`SHARED_SPACE`] for shared variables).
    pub space: u32,
    /// Its byte offset in the space.
    pub byte: u32,
    pub rules: Rules,
    pub row_major: bool,
    /// A block's named instance: its members are the block's (their
    /// offsets and row-major flags), and indexing an arrayed instance
    /// selects the space.
    pub instance: Option<BlockId>,
}

/// A place in memory (see the module docs).
#[derive(Clone, Copy, Debug)]
pub(super) struct MemPlace {
    /// The space, per lane.
    pub space: Reg,
    pub byte: u32,
    /// A per-lane byte offset added to `byte`.
    pub addr: Option<Reg>,
    /// Bytes between the components of a vector (4, or a row-major
    /// matrix's row stride for one of its columns).
    pub comp_stride: u32,
    pub rules: Rules,
    pub row_major: bool,
    pub instance: Option<BlockId>,
}

/// The spaces of a module's storage blocks and where its memory globals
/// start: (the block names GL gives each space, by space; per global,
/// its start if in memory; the bytes of shared variables).
pub(super) fn layout_memory(m: &Module) -> (Vec<String>, Vec<Option<MemGlobal>>, u32) {
    let mut names = Vec::new();
    let mut first = vec![0u32; m.blocks.len()];
    for (i, b) in m.blocks.iter().enumerate() {
        if b.storage != Storage::Buffer {
            continue;
        }
        first[i] = names.len() as u32;
        for e in 0..b.elements().max(1) {
            names.push(format!("{}{}", b.name, b.element_suffix(e)));
        }
    }
    let mut shared = 0u32;
    let globals = m
        .globals
        .iter()
        .enumerate()
        .map(|(gi, g)| match g.storage {
            Storage::Buffer => {
                let b = g.block?;
                let blk = m.blocks.get(b.0 as usize)?;
                let rules = Rules::of(blk.layout);
                if blk.instance.is_some() {
                    return Some(MemGlobal {
                        space: buffer_space(m.stage, first[b.0 as usize]),
                        byte: 0,
                        rules,
                        row_major: false,
                        instance: Some(b),
                    });
                }
                let k = blk.globals.iter().position(|x| x.0 as usize == gi)?;
                let members: Vec<(Type, bool)> =
                    blk.members.iter().map(|x| (x.ty, x.row_major)).collect();
                let (offsets, _) = block_offsets(&members, &m.structs, rules);
                Some(MemGlobal {
                    space: buffer_space(m.stage, first[b.0 as usize]),
                    byte: *offsets.get(k)? as u32,
                    rules,
                    row_major: blk.members.get(k)?.row_major,
                    instance: None,
                })
            }
            Storage::Shared => {
                let (align, size) = size_align(g.ty, &m.structs, false, Rules::Std430);
                let align = align.max(4) as u32;
                let at = shared.div_ceil(align) * align;
                shared = at.saturating_add(size as u32);
                Some(MemGlobal {
                    space: SHARED_SPACE,
                    byte: at,
                    rules: Rules::Std430,
                    row_major: false,
                    instance: None,
                })
            }
            _ => None,
        })
        .collect();
    (names, globals, shared)
}

impl<'m> Lowerer<'m> {
    pub(super) fn mem_global_place(&mut self, g: MemGlobal, ty: Type) -> R<Place> {
        let space = self.konst(g.space)?;
        Ok(Place {
            root: Root::Memory,
            size: 0,
            ty,
            off: 0,
            dynamic: None,
            comps: None,
            mem: Some(MemPlace {
                space,
                byte: g.byte,
                addr: None,
                comp_stride: 4,
                rules: g.rules,
                row_major: g.row_major,
                instance: g.instance,
            }),
        })
    }

    /// `p[i]` of a place in memory; `i` a constant, or a per-lane int
    /// register.
    pub(super) fn mem_index(&mut self, mut p: Place, i: Result<i32, Reg>) -> R<Place> {
        let Some(mut mp) = p.mem else {
            return unsupported("not a place in memory");
        };
        if let Some(comps) = &p.comps {
            // A component of a swizzle.
            let Ok(i) = i else {
                return unsupported("a dynamic index into a swizzle of a storage block vector");
            };
            let k = (i.max(0) as usize).min(comps.len().saturating_sub(1));
            p.comps = Some(vec![comps.get(k).copied().unwrap_or(0)]);
            p.ty = Type::vec(kind_of(p.ty), 1);
            return Ok(p);
        }
        let structs = &self.m.structs;
        // (element type, count or None when unknown, stride, the element's
        // own component stride)
        let (elem, n, stride, comp_stride) = match (p.ty.array, p.ty.base) {
            (Some(size), _) => {
                let n = match size {
                    ArraySize::Sized(n) => Some(n),
                    ArraySize::Unsized => None,
                };
                let elem = p.ty.element();
                if mp.instance.is_some() {
                    // An element of an arrayed block instance: another
                    // space.
                    let n = n.unwrap_or(1).max(1);
                    let base = mp.space;
                    mp.space = match i {
                        Ok(i) => {
                            let s = self.konst((i.max(0) as u32).min(n - 1))?;
                            self.emit_temp(|d| Op::IAdd { d, a: base, b: s })?
                        }
                        Err(r) => {
                            let s = self.emit_temp(|d| Op::ClampIdx {
                                d,
                                a: r,
                                max: n - 1,
                                stride: 1,
                            })?;
                            self.emit_temp(|d| Op::IAdd { d, a: base, b: s })?
                        }
                    };
                    p.ty = elem;
                    p.mem = Some(mp);
                    return Ok(p);
                }
                let (_, stride) = array_layout(elem, structs, mp.row_major, mp.rules);
                (elem, n, stride as u32, 4)
            }
            (None, Base::Vector(s, n)) => (Type::vec(s, 1), Some(n as u32), mp.comp_stride, 4),
            (None, Base::Matrix { cols, rows }) => {
                let col = Type::vec(Scalar::Float, rows);
                if mp.row_major {
                    // A column of a row-major matrix: its components are
                    // a row stride apart, columns 4 bytes apart.
                    let rs = matrix_stride(cols, mp.rules) as u32;
                    (col, Some(cols as u32), 4, rs)
                } else {
                    let cs = matrix_stride(rows, mp.rules) as u32;
                    (col, Some(cols as u32), cs, 4)
                }
            }
            _ => return unsupported("indexing a value that is not an array, vector or matrix"),
        };
        match i {
            Ok(i) => {
                let i = i.max(0) as u32;
                let i = match n {
                    Some(n) => i.min(n.saturating_sub(1)),
                    None => i,
                };
                mp.byte = mp.byte.saturating_add(i.saturating_mul(stride));
            }
            Err(r) => {
                // An array of unknown size takes any index: the memory
                // bounds the address.
                let max = match n {
                    Some(n) => n.saturating_sub(1),
                    None => (i32::MAX as u32) / stride.max(1),
                };
                let off = self.emit_temp(|d| Op::ClampIdx {
                    d,
                    a: r,
                    max,
                    stride,
                })?;
                mp.addr = Some(match mp.addr {
                    None => off,
                    Some(prev) => self.emit_temp(|d| Op::IAdd { d, a: prev, b: off })?,
                });
            }
        }
        mp.comp_stride = comp_stride;
        p.ty = elem;
        p.mem = Some(mp);
        Ok(p)
    }

    /// Member `index` of a struct (or block instance) in memory.
    pub(super) fn mem_member(&mut self, mut p: Place, index: u32) -> R<Place> {
        let Some(mut mp) = p.mem else {
            return unsupported("not a place in memory");
        };
        let Base::Struct(id) = p.ty.base else {
            return unsupported("member of a non-struct");
        };
        let m = self.m;
        let members: Vec<(Type, bool)> = match mp.instance.and_then(|b| m.blocks.get(b.0 as usize))
        {
            Some(blk) => blk.members.iter().map(|x| (x.ty, x.row_major)).collect(),
            None => match m.structs.get(id.0 as usize) {
                Some(def) => def.members.iter().map(|x| (x.ty, mp.row_major)).collect(),
                None => return unsupported("unknown struct"),
            },
        };
        let (offsets, _) = block_offsets(&members, &m.structs, mp.rules);
        let (Some(&off), Some(&(ty, rm))) =
            (offsets.get(index as usize), members.get(index as usize))
        else {
            return unsupported("unknown struct member");
        };
        mp.byte = mp.byte.saturating_add(off as u32);
        mp.row_major = rm;
        mp.instance = None;
        mp.comp_stride = 4;
        p.ty = ty;
        p.mem = Some(mp);
        Ok(p)
    }

    /// The byte offsets of the scalar components of a value of `ty` in
    /// memory, in the executor's flattening order.
    fn mem_offsets(&self, ty: Type, mp: &MemPlace, out: &mut Vec<(u32, Scalar)>, at: u32) -> R<()> {
        let structs = &self.m.structs;
        if let Some(size) = ty.array {
            let ArraySize::Sized(n) = size else {
                return unsupported("reading or writing a whole array of unknown size");
            };
            let elem = ty.element();
            let (_, stride) = array_layout(elem, structs, mp.row_major, mp.rules);
            for e in 0..n {
                self.mem_offsets(elem, mp, out, at + e * stride as u32)?;
            }
            return Ok(());
        }
        match ty.base {
            Base::Scalar(s) => out.push((at, s)),
            Base::Vector(s, n) => {
                for c in 0..n as u32 {
                    out.push((at + c * mp.comp_stride, s));
                }
            }
            Base::Matrix { cols, rows } => {
                for c in 0..cols as u32 {
                    for r in 0..rows as u32 {
                        let off = if mp.row_major {
                            r * matrix_stride(cols, mp.rules) as u32 + c * 4
                        } else {
                            c * matrix_stride(rows, mp.rules) as u32 + r * 4
                        };
                        out.push((at + off, Scalar::Float));
                    }
                }
            }
            Base::Struct(id) => {
                let Some(def) = structs.get(id.0 as usize) else {
                    return unsupported("unknown struct");
                };
                let members: Vec<(Type, bool)> =
                    def.members.iter().map(|x| (x.ty, mp.row_major)).collect();
                let (offsets, _) = block_offsets(&members, structs, mp.rules);
                let inner = MemPlace {
                    comp_stride: 4,
                    ..*mp
                };
                for (k, &(mty, _)) in members.iter().enumerate() {
                    self.mem_offsets(mty, &inner, out, at + offsets[k] as u32)?;
                }
            }
            _ => return unsupported("a value of this type in memory"),
        }
        Ok(())
    }

    /// (address register, scalar kind) of each component of `p`.
    fn mem_components(&mut self, p: &Place) -> R<Vec<(Reg, Scalar)>> {
        let Some(mp) = p.mem else {
            return unsupported("not a place in memory");
        };
        if mp.instance.is_some() {
            return unsupported("reading or writing a whole storage block");
        }
        let mut offs = Vec::new();
        match &p.comps {
            Some(comps) => {
                let s = kind_of(p.ty);
                offs.extend(comps.iter().map(|&c| (c * mp.comp_stride, s)));
            }
            None => self.mem_offsets(p.ty, &mp, &mut offs, 0)?,
        }
        let mut out = Vec::with_capacity(offs.len());
        for (off, s) in offs {
            let c = self.konst(mp.byte.saturating_add(off))?;
            let a = match mp.addr {
                None => c,
                Some(a) => self.emit_temp(|d| Op::IAdd { d, a, b: c })?,
            };
            out.push((a, s));
        }
        Ok(out)
    }

    pub(super) fn mem_read(&mut self, p: &Place) -> R<Val> {
        let Some(mp) = p.mem else {
            return unsupported("not a place in memory");
        };
        let comps = self.mem_components(p)?;
        let mut out = Vec::with_capacity(comps.len());
        for (addr, s) in comps {
            let w = self.emit_temp(|d| Op::Load {
                d,
                space: mp.space,
                addr,
            })?;
            out.push(match s {
                Scalar::Float => self.emit_temp(|d| Op::F1 {
                    f: F1::FlushBits,
                    d,
                    a: w,
                })?,
                Scalar::Bool => self.emit_temp(|d| Op::IToB { d, a: w })?,
                _ => w,
            });
        }
        Ok(out)
    }

    pub(super) fn mem_write(&mut self, p: &Place, v: &[Reg]) -> R<()> {
        let Some(mp) = p.mem else {
            return unsupported("not a place in memory");
        };
        let comps = self.mem_components(p)?;
        if comps.len() != v.len() {
            return unsupported(format!(
                "assigning {} components to {}",
                v.len(),
                comps.len()
            ));
        }
        for ((addr, _), &a) in comps.into_iter().zip(v) {
            self.emit(Op::StoreMem {
                space: mp.space,
                addr,
                a,
            })?;
        }
        Ok(())
    }

    /// `atomic*(mem, data)` and `atomicCompSwap(mem, compare, data)`: the
    /// old value.
    pub(super) fn atomic(&mut self, f: BuiltinFn, args: &[Expr]) -> R<Val> {
        use BuiltinFn as B;
        let (Some(target), Some(data)) = (args.first(), args.get(1)) else {
            return unsupported("an atomic function without its arguments");
        };
        let signed = kind_of(target.ty) == Scalar::Int;
        let op = match f {
            B::AtomicAdd => AtomicOp::Add,
            B::AtomicMin if signed => AtomicOp::MinI,
            B::AtomicMin => AtomicOp::MinU,
            B::AtomicMax if signed => AtomicOp::MaxI,
            B::AtomicMax => AtomicOp::MaxU,
            B::AtomicAnd => AtomicOp::And,
            B::AtomicOr => AtomicOp::Or,
            B::AtomicXor => AtomicOp::Xor,
            B::AtomicExchange => AtomicOp::Exchange,
            B::AtomicCompSwap => AtomicOp::CompSwap,
            _ => return unsupported("not an atomic function"),
        };
        let p = self.place(target)?;
        let Some(mp) = p.mem else {
            return unsupported("an atomic function on a variable outside memory");
        };
        let comps = self.mem_components(&p)?;
        let [(addr, _)] = comps[..] else {
            return unsupported("an atomic function on more than one component");
        };
        let a = self.expr(data)?;
        let b = match args.get(2) {
            Some(e) => self.expr(e)?,
            None => a.clone(),
        };
        let (Some(&a), Some(&b)) = (a.first(), b.first()) else {
            return unsupported("an atomic function without data");
        };
        let d = self.emit_temp(|d| Op::Atomic {
            f: op,
            d,
            space: mp.space,
            addr,
            a,
            b,
        })?;
        Ok(vec![d])
    }

    /// `.length()` of an array in memory whose size the buffer gives: the
    /// elements that fit in the bound range after its offset (0 when none
    /// do).
    pub(super) fn mem_length(&mut self, p: &Place) -> R<Reg> {
        let Some(mp) = p.mem else {
            return unsupported("not a place in memory");
        };
        let (_, stride) = array_layout(p.ty.element(), &self.m.structs, mp.row_major, mp.rules);
        let size = self.emit_temp(|d| Op::MemSize { d, space: mp.space })?;
        let start = self.konst(mp.byte)?;
        let before = self.emit_temp(|d| Op::ULt {
            d,
            a: size,
            b: start,
        })?;
        let rest = self.emit_temp(|d| Op::ISub {
            d,
            a: size,
            b: start,
        })?;
        let stride = self.konst(stride.max(1) as u32)?;
        let n = self.emit_temp(|d| Op::UDiv {
            d,
            a: rest,
            b: stride,
        })?;
        let zero = self.konst(0)?;
        self.emit_temp(|d| Op::Select {
            d,
            c: before,
            a: zero,
            b: n,
        })
    }

    /// The start of global `i` when it lives in memory.
    pub(super) fn mem_global(&self, i: usize) -> Option<MemGlobal> {
        match self.globals.get(i) {
            Some(GlobalLoc::Memory(g)) => Some(*g),
            _ => None,
        }
    }
}
