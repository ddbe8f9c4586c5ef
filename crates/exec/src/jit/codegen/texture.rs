//! Texture ops: a call to `jit_texture` (which runs every lookup and size
//! query with the engine's own code), and for a texel fetch whose lanes
//! read one plain level (`jit::View`: the draw's, prepared with the pool,
//! or the one `jit_texture` found) the texels loaded here instead:
//! per lane a bounds check, an index and a load, the texels transposed
//! into the result registers. The values are `engine::texture`'s: the
//! stored texel inside the level, (0, 0, 0, 1) outside it, 0 on lanes
//! not running, float results flushed.

use super::super::{jit_texture, Ctx, View};
use super::{mem, Emit, ONE, QUARTERS};
use crate::program::{Op, Reg, TexKind, TexOp};
use cranelift_codegen::ir::condcodes::IntCC;
use cranelift_codegen::ir::types::{F32X4, I32, I32X4};
use cranelift_codegen::ir::{Block, BlockArg, InstBuilder, Value};
use glsl::types::SamplerResult;
use std::mem::offset_of;

impl<'a, 'b> Emit<'a, 'b> {
    /// Texture op `index` of the program, run by op `op` of the body (or
    /// the prologue: `PROLOGUE_OP` set).
    pub(super) fn texture(&mut self, index: u32, op: u32) -> Result<(), String> {
        let t = *self
            .code
            .prog
            .textures
            .get(index as usize)
            .ok_or("texture op out of range")?;
        // The callback reads and writes registers in memory.
        self.flush_all();
        if t.kind != TexKind::Fetch {
            self.call_texture(index);
            return Ok(());
        }
        let (native, call, join) = (
            self.b.create_block(),
            self.b.create_block(),
            self.b.create_block(),
        );
        let view = self.b.append_block_param(native, self.ptr);
        // The draw's view of this op, when the run has one.
        let n = self
            .b
            .ins()
            .load(I32, mem(), self.ctx, offset_of!(Ctx, views_len) as i32);
        let has = self
            .b
            .ins()
            .icmp_imm_u(IntCC::UnsignedGreaterThan, n, index as i64);
        let check = self.b.create_block();
        self.b.ins().brif(has, check, &[], call, &[]);
        self.b.switch_to_block(check);
        let all = self
            .b
            .ins()
            .load(self.ptr, mem(), self.ctx, offset_of!(Ctx, views) as i32);
        let at = self
            .b
            .ins()
            .iadd_imm_s(all, index as i64 * std::mem::size_of::<View>() as i64);
        let texels = self
            .b
            .ins()
            .load(self.ptr, mem(), at, offset_of!(View, texels) as i32);
        self.branch_to_view(texels, native, at, call);
        // Else the callback, which finds the level or runs the fetch.
        self.b.switch_to_block(call);
        let ok = self.call_texture(index);
        let own = self
            .b
            .ins()
            .iadd_imm_s(self.ctx, offset_of!(Ctx, view) as i64);
        self.branch_to_view(ok, native, own, join);
        self.b.switch_to_block(native);
        // One block per storage the view may have (16-bit red only for
        // integer results: `jit::fetch_view`).
        let mut formats = vec![View::RGBA32, View::UNORM8];
        if t.target.result() != SamplerResult::Float {
            formats.extend([View::RED16, View::RED16_SIGNED]);
        }
        let format = self.view_word(view, offset_of!(View, format));
        let blocks: Vec<Block> = formats.iter().map(|_| self.b.create_block()).collect();
        // A chain of tests, the last format taken without one.
        for (k, (&f, &block)) in formats.iter().zip(&blocks).enumerate() {
            if k + 1 == blocks.len() {
                self.b.ins().jump(block, &[]);
                break;
            }
            let is = self.b.ins().icmp_imm_u(IntCC::Equal, format, f as i64);
            let next = self.b.create_block();
            self.b.ins().brif(is, block, &[], next, &[]);
            self.b.switch_to_block(next);
        }
        for (&f, &block) in formats.iter().zip(&blocks) {
            self.b.switch_to_block(block);
            self.fetch_texels(&t, view, f, op);
            // Only loads were held: nothing to store, nothing valid at
            // the join.
            self.cache = Default::default();
            self.b.ins().jump(join, &[]);
        }
        self.b.switch_to_block(join);
        Ok(())
    }

    /// Calls `jit_texture` for texture op `index`; its result (1: a view
    /// in `Ctx::view` for the native fetch).
    fn call_texture(&mut self, index: u32) -> Value {
        let f = self
            .b
            .ins()
            .iconst(self.ptr, jit_texture as *const () as i64);
        let i = self.b.ins().iconst(I32, index as i64);
        // The prologue's size queries are made for every lane, as
        // `engine::prologue` makes them.
        let cur = if self.prologue {
            self.b.ins().iconst(I32, crate::interp::FULL as i64)
        } else {
            self.b.use_var(self.cur)
        };
        let ctx = self.ctx;
        let call = self
            .b
            .ins()
            .call_indirect(self.sig_texture, f, &[ctx, i, cur]);
        self.b.inst_results(call)[0]
    }

    /// Branches to `native` with the view at `view` when `cond` is
    /// nonzero, else to `other`.
    fn branch_to_view(&mut self, cond: Value, native: Block, view: Value, other: Block) {
        let arg = [BlockArg::from(view)];
        self.b.ins().brif(cond, native, &arg, other, &[]);
    }

    /// The `i32` at `offset` in the view at `view`.
    fn view_word(&mut self, view: Value, offset: usize) -> Value {
        self.b.ins().load(I32, mem(), view, offset as i32)
    }

    /// The texels of fetch `t` (run by op `op`) from the view at `view`
    /// (stored as `format`, a `View` format) into those of its result
    /// registers read afterwards.
    fn fetch_texels(&mut self, t: &TexOp, view: Value, format: u32, op: u32) {
        let at = offset_of!(View, texels) as i32;
        let base = self.b.ins().load(self.ptr, mem(), view, at);
        let size: [Value; 3] = std::array::from_fn(|a| {
            let w = self.view_word(view, offset_of!(View, size) + 4 * a);
            self.b.ins().splat(I32X4, w)
        });
        let keep: [Value; 3] = std::array::from_fn(|a| {
            let w = self.view_word(view, offset_of!(View, keep) + 4 * a);
            self.b.ins().splat(I32X4, w)
        });
        let float = t.target.result() == SamplerResult::Float;
        // Axes whose coordinate (and offset) the program holds at 0: no
        // bounds check (0 is inside every level) and no index term.
        let zero: [bool; 3] = std::array::from_fn(|a| {
            self.pool_zero(t.coord[a]) && t.offset.is_none_or(|o| self.pool_zero(o[a]))
        });
        for q in 0..QUARTERS {
            let mut c: [Option<Value>; 3] = [None; 3];
            for (a, c) in c.iter_mut().enumerate() {
                if zero[a] {
                    continue;
                }
                let mut v = self.ld(t.coord[a], q);
                if let Some(o) = t.offset {
                    let o = self.ld(o[a], q);
                    v = self.b.ins().iadd(v, o);
                }
                *c = Some(self.b.ins().band(v, keep[a]));
            }
            // Unsigned compares: a negative coordinate is outside too.
            let mut outside = None;
            for a in 0..3 {
                let Some(c) = c[a] else { continue };
                let ge = self
                    .b
                    .ins()
                    .icmp(IntCC::UnsignedGreaterThanOrEqual, c, size[a]);
                outside = Some(match outside {
                    Some(o) => self.b.ins().bor(o, ge),
                    None => ge,
                });
            }
            let running = self.b.use_var(self.mk[q]);
            let inside = match outside {
                Some(o) => self.b.ins().band_not(running, o),
                None => running,
            };
            // (k·height + j)·width + i, which fits in an i32 inside the
            // level; texel 0 for the other lanes.
            let k_rows = c[2].map(|k| self.b.ins().imul(k, size[1]));
            let row = match (k_rows, c[1]) {
                (Some(k), Some(j)) => Some(self.b.ins().iadd(k, j)),
                (r, None) | (None, r) => r,
            };
            let row = row.map(|r| self.b.ins().imul(r, size[0]));
            let index = match (row, c[0]) {
                (Some(row), Some(i)) => self.b.ins().iadd(row, i),
                (Some(v), None) | (None, Some(v)) => v,
                (None, None) => self.splat(0),
            };
            let index = self.b.ins().band(index, inside);
            let texel = match format {
                View::UNORM8 => self.unorm8_texels(base, index),
                View::RED16 | View::RED16_SIGNED => {
                    self.red16_texels(base, index, view, format == View::RED16_SIGNED)
                }
                _ => self.rgba32_texels(base, index),
            };
            for (k, v) in texel.into_iter().enumerate() {
                let d = t.d + k as u32;
                if !self.live_after(op as usize, d) {
                    continue;
                }
                let v = if float {
                    let x = self.fv(v);
                    self.flushed(x)
                } else {
                    v
                };
                let missing = self.splat(if k == 3 { ONE } else { 0 });
                let missing = self.b.ins().band(running, missing);
                let v = self.b.ins().bitselect(inside, v, missing);
                self.b.ins().store(mem(), v, self.regs, Self::offset(d, q));
            }
        }
    }

    /// Whether register `r` holds 0 on every run: a pool register that
    /// one `Const` of the prologue sets to 0 and no other op writes.
    fn pool_zero(&self, r: Reg) -> bool {
        if r < self.code.pool_base {
            return false;
        }
        let writes = |op: &Op| {
            let e = crate::liveness::effects(&self.code.prog, op);
            let covers = |&(d, n): &(Reg, u32)| r >= d && (r - d) < n.max(1);
            e.full_defs.iter().any(covers) || e.partial_defs.iter().any(covers)
        };
        let mut sets = self.code.prologue.iter().filter(|op| writes(op));
        matches!(sets.next(), Some(Op::Const { bits: 0, .. }))
            && sets.next().is_none()
            && !self.code.ins.iter().any(|i| writes(&i.op))
    }

    /// The address of texel `index` (lane `l`) of `size` bytes each.
    fn texel_address(&mut self, base: Value, index: Value, l: u8, shift: i64) -> Value {
        let i = self.b.ins().extractlane(index, l);
        let i = self.b.ins().uextend(self.ptr, i);
        let off = self.b.ins().ishl_imm_u(i, shift);
        self.b.ins().iadd(base, off)
    }

    /// R, G, B and A of four RGBA `f32` texels: four loads, transposed.
    fn rgba32_texels(&mut self, base: Value, index: Value) -> [Value; 4] {
        let v: [Value; 4] = std::array::from_fn(|l| {
            let p = self.texel_address(base, index, l as u8, 4);
            self.b.ins().load(I32X4, mem(), p, 0)
        });
        // [r0 r1 g0 g1], [b0 b1 a0 a1], then the same of texels 2 and 3.
        let lo01 = self.lanes_of2(v[0], v[1], [0, 4, 1, 5]);
        let hi01 = self.lanes_of2(v[0], v[1], [2, 6, 3, 7]);
        let lo23 = self.lanes_of2(v[2], v[3], [0, 4, 1, 5]);
        let hi23 = self.lanes_of2(v[2], v[3], [2, 6, 3, 7]);
        [
            self.lanes_of2(lo01, lo23, [0, 1, 4, 5]),
            self.lanes_of2(lo01, lo23, [2, 3, 6, 7]),
            self.lanes_of2(hi01, hi23, [0, 1, 4, 5]),
            self.lanes_of2(hi01, hi23, [2, 3, 6, 7]),
        ]
    }

    /// R, G, B and A of four 16-bit red texels: red widened (`signed`:
    /// sign-extended), the others the view's `rest`.
    fn red16_texels(&mut self, base: Value, index: Value, view: Value, signed: bool) -> [Value; 4] {
        let mut red = self.splat(0);
        for l in 0..4u8 {
            let p = self.texel_address(base, index, l, 1);
            let w = match signed {
                true => self.b.ins().sload16(I32, mem(), p, 0),
                false => self.b.ins().uload16(I32, mem(), p, 0),
            };
            red = self.b.ins().insertlane(red, w, l);
        }
        let [g, b, a] = std::array::from_fn(|k| {
            let w = self.view_word(view, offset_of!(View, rest) + 4 * k);
            self.b.ins().splat(I32X4, w)
        });
        [red, g, b, a]
    }

    /// R, G, B and A of four RGBA8 texels, each byte `b` as `b / 255`
    /// (correctly rounded, as the stored texels decode).
    fn unorm8_texels(&mut self, base: Value, index: Value) -> [Value; 4] {
        let mut packed = self.splat(0);
        for l in 0..4u8 {
            let p = self.texel_address(base, index, l, 2);
            let w = self.b.ins().load(I32, mem(), p, 0);
            packed = self.b.ins().insertlane(packed, w, l);
        }
        let byte = self.splat(0xff);
        let c255 = self.fconst(255.0);
        std::array::from_fn(|k| {
            let b = self.b.ins().ushr_imm_u(packed, 8 * k as i64);
            let b = self.b.ins().band(b, byte);
            let x = self.b.ins().fcvt_from_sint(F32X4, b);
            let x = self.b.ins().fdiv(x, c255);
            self.iv(x)
        })
    }
}
