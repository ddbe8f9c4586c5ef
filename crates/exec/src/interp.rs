//! The lane-parallel interpreter of a lowered [`Program`].

use crate::lane::match_op;
use crate::program::{Op, Program, TexKind, TexLod};
use crate::{
    Batch, ExecError, FetchRequest, Kernel, LaneMask, Lod, PrintSink, SampleRequest, Textures,
    Trace, LANES,
};
use glsl::math::flush_denormal;
use glsl::types::Scalar;

/// Loop iterations (summed over every loop, counted once per iteration of
/// the lane group), plus subroutine calls when functions are not inlined,
/// that one `Kernel::run` may execute before it fails with
/// [`ExecError::LoopBudget`]. Counted loops that lowering unrolls (at most
/// 32 iterations, see `lower`) have no iterations left to count. GLSL sets
/// no bound; 2^20 is far past what a shader that ends needs (llvmpipe stops
/// each loop at 65,535 iterations) and keeps a loop that never ends to a
/// fraction of a second before the draw reports it.
pub const LOOP_BUDGET: u64 = 1 << 20;

/// All lanes.
pub(crate) use crate::lane::FULL;

type Regs = Vec<[u32; LANES]>;

/// Hook called while running; the no-op implementation compiles away.
pub(crate) trait Hook {
    fn before(&mut self, _p: &Program, _pc: usize, _cur: LaneMask, _regs: &Regs) {}
    /// `debugPrintfEXT` site `index` runs on the lanes of `cur`.
    fn printf(&mut self, _p: &Program, _index: usize, _cur: LaneMask, _regs: &Regs) {}
}

/// Keeps, per lane, the last value stored into each register of a range
/// (the debugger's false-colour views).
pub(crate) struct WatchHook<'o> {
    pub first: u32,
    pub out: &'o mut [[u32; LANES]],
}

impl Hook for WatchHook<'_> {
    fn before(&mut self, p: &Program, pc: usize, cur: LaneMask, regs: &Regs) {
        let (d, a) = match p.ops.get(pc) {
            Some(Op::Store { d, a }) => (*d, *a),
            Some(Op::Scatter { base, off, max, a }) => {
                // Per lane: the element each lane writes.
                for lane in 0..LANES {
                    if cur & (1 << lane) == 0 {
                        continue;
                    }
                    let o = regs.get(*off as usize).map_or(0, |r| r[lane]).min(*max);
                    let d = base.saturating_add(o);
                    if let Some(slot) = d
                        .checked_sub(self.first)
                        .and_then(|i| self.out.get_mut(i as usize))
                    {
                        slot[lane] = regs.get(*a as usize).map_or(0, |r| r[lane]);
                    }
                }
                return;
            }
            _ => return,
        };
        let Some(slot) = d
            .checked_sub(self.first)
            .and_then(|i| self.out.get_mut(i as usize))
        else {
            return;
        };
        let Some(v) = regs.get(a as usize) else {
            return;
        };
        for lane in 0..LANES {
            if cur & (1 << lane) != 0 {
                slot[lane] = v[lane];
            }
        }
    }
}

/// The text `debugPrintfEXT` site `index` prints for `lane`.
pub(crate) fn printf_text(p: &Program, index: usize, lane: usize, regs: &Regs) -> Option<String> {
    let site = p.printfs.get(index)?;
    let values: Vec<u32> = site
        .args
        .iter()
        .map(|&r| regs.get(r as usize).map_or(0, |v| v[lane]))
        .collect();
    Some(glsl::printf::format_values(&site.format, &values))
}

/// Reports every `debugPrintfEXT` of the lanes in `lanes` to a
/// [`PrintSink`].
pub(crate) struct PrintHook<'s> {
    pub lanes: LaneMask,
    pub sink: &'s mut dyn PrintSink,
}

impl Hook for PrintHook<'_> {
    fn printf(&mut self, p: &Program, index: usize, cur: LaneMask, regs: &Regs) {
        let span = p.printfs.get(index).map(|s| s.span).unwrap_or_default();
        for lane in 0..LANES {
            if cur & self.lanes & (1 << lane) != 0 {
                if let Some(text) = printf_text(p, index, lane, regs) {
                    self.sink.print(lane, span, &text);
                }
            }
        }
    }
}

#[cfg(test)]
pub(crate) struct NoHook;
#[cfg(test)]
impl Hook for NoHook {}

/// Reports statements and stores of one lane to a [`Trace`].
pub(crate) struct TraceHook<'t> {
    pub lane: usize,
    pub trace: &'t mut dyn Trace,
    /// Statement index per op (u32::MAX: none starts there).
    pub stmt_at: Vec<u32>,
}

impl Hook for TraceHook<'_> {
    fn before(&mut self, p: &Program, pc: usize, cur: LaneMask, regs: &Regs) {
        if cur & (1 << self.lane) == 0 {
            return;
        }
        if let Some(&s) = self.stmt_at.get(pc) {
            if let Some(mark) = p.statements.get(s as usize) {
                self.trace.statement(mark.span);
            }
        }
        // Stores report the value they are about to write.
        match p.ops.get(pc) {
            Some(Op::Store { d, a }) => {
                let v = regs[*a as usize][self.lane];
                self.trace.store(*d, v);
            }
            Some(Op::Scatter { base, off, max, a }) => {
                let o = regs[*off as usize][self.lane].min(*max);
                let v = regs[*a as usize][self.lane];
                self.trace.store(base + o, v);
            }
            _ => {}
        }
    }

    fn printf(&mut self, p: &Program, index: usize, cur: LaneMask, regs: &Regs) {
        if cur & (1 << self.lane) != 0 {
            if let Some(text) = printf_text(p, index, self.lane, regs) {
                self.trace.printf(&text);
            }
        }
    }
}

#[inline(always)]
fn f(x: u32) -> f32 {
    f32::from_bits(x)
}

/// The bits of `x` with a subnormal flushed to zero: the result of every
/// float arithmetic op and built-in function (as constant folding does;
/// see `glsl::math::flush_denormal`).
#[inline(always)]
fn ftz(x: f32) -> u32 {
    flush_denormal(x).to_bits()
}

#[inline(always)]
fn lanes(mut g: impl FnMut(usize) -> u32) -> [u32; LANES] {
    let mut o = [0u32; LANES];
    for (l, v) in o.iter_mut().enumerate() {
        *v = g(l);
    }
    o
}

pub(crate) fn run<H: Hook>(
    k: &Kernel,
    batch: &mut Batch,
    uniforms: &[u32],
    textures: &dyn Textures,
    hook: &mut H,
) -> Result<(), ExecError> {
    let p = &k.program;
    let mut r: Regs = vec![[0u32; LANES]; p.registers as usize];
    for &(reg, bits) in &p.init {
        r[reg as usize] = [bits; LANES];
    }
    // Integer inputs are their bits (`Batch::inputs`).
    for &(ic, reg, kind) in &k.inputs {
        let src = batch.inputs.get(ic).copied().unwrap_or([0.0; LANES]);
        r[reg as usize] = lanes(|l| match kind {
            Scalar::Float => ftz(src[l]),
            Scalar::Int | Scalar::Uint => src[l].to_bits(),
            Scalar::Bool => (src[l] != 0.0) as u32,
        });
    }
    let mut masks = vec![0 as LaneMask; p.mask_slots as usize];
    let start = (batch.active | batch.helper) & FULL;
    let mut cur: LaneMask = start;
    batch.discarded = 0;
    let mut iterations: u64 = 0;
    let mut return_address = vec![0u32; p.subroutines as usize];
    let ops = &p.ops[..];
    let mut pc = 0usize;
    let uni = |w: usize, float: bool| crate::lane::uniform_word(uniforms, w, float);

    macro_rules! un {
        ($d:expr, $a:expr, |$x:ident| $body:expr) => {{
            let a = r[$a as usize];
            r[$d as usize] = lanes(|l| {
                let $x = a[l];
                $body
            });
        }};
    }
    macro_rules! bin {
        ($d:expr, $a:expr, $b:expr, |$x:ident, $y:ident| $body:expr) => {{
            let (a, b) = (r[$a as usize], r[$b as usize]);
            r[$d as usize] = lanes(|l| {
                let ($x, $y) = (a[l], b[l]);
                $body
            });
        }};
    }

    while let Some(&op) = ops.get(pc) {
        hook.before(p, pc, cur, &r);
        pc += 1;
        match_op!(match op {
            Op::Const { d, bits } => r[d as usize] = [bits; LANES],
            Op::Mov { d, a } => r[d as usize] = r[a as usize],
            Op::Store { d, a } => {
                let a = r[a as usize];
                let dst = &mut r[d as usize];
                for (l, v) in dst.iter_mut().enumerate() {
                    if cur & (1 << l) != 0 {
                        *v = a[l];
                    }
                }
            }
            Op::Uniform { d, word, float } => r[d as usize] = [uni(word as usize, float); LANES],
            Op::FMac { d, a, b } => {
                let (a, b, acc) = (r[a as usize], r[b as usize], r[d as usize]);
                r[d as usize] = lanes(|l| {
                    let prod = flush_denormal(f(a[l]) * f(b[l]));
                    ftz(f(acc[l]) + prod)
                });
            }
            Op::Dot { d, n, a, b } => {
                let n = (n as usize).clamp(1, 4);
                let prod = |k: usize, l: usize| {
                    flush_denormal(f(r[a[k] as usize][l]) * f(r[b[k] as usize][l]))
                };
                let mut acc = lanes(|l| prod(n - 1, l).to_bits());
                for k in (0..n - 1).rev() {
                    acc = lanes(|l| ftz(f(acc[l]) + prod(k, l)));
                }
                r[d as usize] = acc;
            }
            Op::F1 { f: func, d, a } => un!(d, a, |x| ftz(func.eval(f(x)))),
            Op::F2 { f: func, d, a, b } => bin!(d, a, b, |x, y| ftz(func.eval(f(x), f(y)))),
            Op::F3 {
                f: func,
                d,
                a,
                b,
                c,
            } => {
                let (a, b, c) = (r[a as usize], r[b as usize], r[c as usize]);
                r[d as usize] = lanes(|l| ftz(func.eval(f(a[l]), f(b[l]), f(c[l]))));
            }
            Op::Select { d, c, a, b } => {
                let (c, a, b) = (r[c as usize], r[a as usize], r[b as usize]);
                r[d as usize] = lanes(|l| if c[l] != 0 { a[l] } else { b[l] });
            }
            Op::Gather { d, base, off, max } => {
                let o = r[off as usize];
                let v = lanes(|l| r[(base + o[l].min(max)) as usize][l]);
                r[d as usize] = v;
            }
            Op::Scatter { base, off, max, a } => {
                let (o, a) = (r[off as usize], r[a as usize]);
                for l in 0..LANES {
                    if cur & (1 << l) != 0 {
                        r[(base + o[l].min(max)) as usize][l] = a[l];
                    }
                }
            }
            Op::GatherUniform {
                d,
                word,
                off,
                max,
                float,
            } => {
                let o = r[off as usize];
                r[d as usize] = lanes(|l| uni(word as usize + o[l].min(max) as usize, float));
            }
            Op::DdX { d, a } => un_quad(&mut r, d, a, 1),
            Op::DdY { d, a } => un_quad(&mut r, d, a, 2),
            Op::Noise { d, n, a, dims } => {
                let mut out = [[0u32; LANES]; 4];
                for (l, _) in (0..LANES).enumerate() {
                    let mut x = [0f32; 4];
                    for (k, xk) in x.iter_mut().enumerate().take(dims as usize) {
                        *xk = f(r[a as usize + k][l]);
                    }
                    let v = crate::lane::noise(n, &x[..dims as usize]);
                    for k in 0..4 {
                        out[k][l] = ftz(v[k]);
                    }
                }
                for (k, o) in out.iter().enumerate().take(n as usize) {
                    r[d as usize + k] = *o;
                }
            }
            Op::Printf { index } => hook.printf(p, index as usize, cur, &r),
            Op::Load { .. }
            | Op::StoreMem { .. }
            | Op::Atomic { .. }
            | Op::MemSize { .. }
            | Op::Barrier => {
                // Helper lanes have no side effects (GL 4.3 §7.12.3).
                let lanes = if op.writes_memory() {
                    cur & !batch.helper
                } else {
                    cur
                };
                let out =
                    crate::memory_ops::run_op(&op, lanes, |x| r[x as usize], textures.memory());
                if let Some(Some((d, v))) = out {
                    r[d as usize] = v;
                }
            }
            Op::Texture { index } => {
                if let Some(t) = p.textures.get(index as usize) {
                    texture(&mut r, t, cur, textures);
                }
            }
            Op::SaveMask { slot } => masks[slot as usize] = cur,
            Op::RestoreMask { slot } => cur = masks[slot as usize],
            Op::AndMask { c } => {
                let c = r[c as usize];
                for (l, &v) in c.iter().enumerate() {
                    if v == 0 {
                        cur &= !(1 << l);
                    }
                }
            }
            Op::AndNotMask { slot, c } => {
                let c = r[c as usize];
                cur = masks[slot as usize];
                for (l, &v) in c.iter().enumerate() {
                    if v != 0 {
                        cur &= !(1 << l);
                    }
                }
            }
            Op::JumpIfNone { target } => {
                if cur == 0 {
                    pc = target as usize;
                }
            }
            Op::Jump { target } => pc = target as usize,
            Op::LoopIter => {
                iterations += 1;
                if iterations > k.loop_budget {
                    return Err(ExecError::LoopBudget { iterations });
                }
            }
            Op::Call { target, slot } => {
                return_address[slot as usize] = pc as u32;
                pc = target as usize;
            }
            Op::Ret { slot } => pc = return_address[slot as usize] as usize,
            Op::SyncDiscard { start, end } => {
                let gone = batch.discarded;
                for &s in &p.kill_slots[start as usize..end as usize] {
                    masks[s as usize] &= !gone;
                }
                cur &= !gone;
            }
            Op::Kill { start, end } | Op::Discard { start, end } => {
                if matches!(op, Op::Discard { .. }) {
                    batch.discarded |= cur;
                }
                for &s in &p.kill_slots[start as usize..end as usize] {
                    masks[s as usize] &= !cur;
                }
                cur = 0;
            }
        });
    }

    let active = batch.output_lanes(k);
    // Varyings' integers are their bits (`Batch::outputs`).
    let bits = k.stage != glsl::Stage::Fragment;
    for &(reg, oc, kind) in &k.outputs {
        let src = r[reg as usize];
        if let Some(dst) = batch.outputs.get_mut(oc) {
            for (l, v) in dst.iter_mut().enumerate() {
                if active & (1 << l) != 0 {
                    *v = match kind {
                        Scalar::Float => f(crate::lane::float_output(src[l])),
                        Scalar::Int | Scalar::Uint if bits => f(src[l]),
                        Scalar::Int => src[l] as i32 as f32,
                        Scalar::Uint => src[l] as f32,
                        Scalar::Bool => (src[l] != 0) as u32 as f32,
                    };
                }
            }
        }
    }
    Ok(())
}

/// Quad difference along x (`bit` 1) or y (`bit` 2): `v(l | bit) - v(l & !bit)`.
fn quad_diff(a: &[u32; LANES], bit: usize) -> [u32; LANES] {
    lanes(|l| (f(a[l | bit]) - f(a[l & !bit])).to_bits())
}

/// `dFdx`/`dFdy`: [`quad_diff`], flushed.
fn un_quad(r: &mut Regs, d: u32, a: u32, bit: usize) {
    let v = quad_diff(&r[a as usize], bit);
    r[d as usize] = v.map(|x| ftz(f(x)));
}

fn floats(a: &[u32; LANES]) -> [f32; LANES] {
    let mut o = [0f32; LANES];
    for (x, &b) in o.iter_mut().zip(a) {
        *x = f(b);
    }
    o
}

fn texture(r: &mut Regs, t: &crate::program::TexOp, cur: LaneMask, textures: &dyn Textures) {
    let ints = |r: &Regs, x: u32| -> [i32; LANES] { r[x as usize].map(|b| b as i32) };
    let lod_reg = t.level();
    let mut out = [[0f32; LANES]; 4];
    match t.kind {
        TexKind::Size => {
            let lod = lod_reg.map_or([0; LANES], |l| ints(r, l));
            let unit = r[t.unit as usize];
            for k in 0..4 {
                r[t.d as usize + k] = [0; LANES];
            }
            for l in (0..LANES).filter(|l| cur & (1 << l) != 0) {
                let v = textures.size(unit[l], t.target, lod[l]);
                for (k, &x) in v.iter().enumerate() {
                    r[t.d as usize + k][l] = x as u32;
                }
            }
            return;
        }
        TexKind::Fetch => {
            if cur != 0 {
                let offset = t.offset.map(|o| o.map(|x| ints(r, x)));
                let coord = std::array::from_fn(|k| {
                    let c = ints(r, t.coord[k]);
                    std::array::from_fn(|l| match &offset {
                        Some(o) => c[l].wrapping_add(o[k][l]),
                        None => c[l],
                    })
                });
                let req = FetchRequest {
                    unit: r[t.unit as usize],
                    target: t.target,
                    coord,
                    lod: lod_reg.map_or([0; LANES], |l| ints(r, l)),
                    mask: cur,
                };
                textures.fetch(&req, &mut out);
            }
        }
        TexKind::Sample => {
            if cur != 0 {
                let coord = t.coord.map(|c| floats(&r[c as usize]));
                let lod = match t.lod {
                    TexLod::Explicit(l) => Lod::Explicit(match l {
                        Some(l) => floats(&r[l as usize]),
                        None => [0.0; LANES],
                    }),
                    TexLod::Implicit { bias } => {
                        let mut ddx = [[0f32; LANES]; 3];
                        let mut ddy = [[0f32; LANES]; 3];
                        for k in 0..(t.dims as usize).min(3) {
                            let c = &r[t.coord[k] as usize];
                            ddx[k] = floats(&quad_diff(c, 1));
                            ddy[k] = floats(&quad_diff(c, 2));
                        }
                        Lod::Derivatives {
                            ddx,
                            ddy,
                            bias: match bias {
                                Some(b) => floats(&r[b as usize]),
                                None => [0.0; LANES],
                            },
                        }
                    }
                    TexLod::Grad { ddx: x, ddy: y } => {
                        let mut ddx = [[0f32; LANES]; 3];
                        let mut ddy = [[0f32; LANES]; 3];
                        for k in 0..(t.dims as usize).min(3) {
                            ddx[k] = floats(&r[x[k] as usize]);
                            ddy[k] = floats(&r[y[k] as usize]);
                        }
                        Lod::Gradients { ddx, ddy }
                    }
                };
                let req = SampleRequest {
                    unit: r[t.unit as usize],
                    target: t.target,
                    coord,
                    compare: t.compare.map(|c| floats(&r[c as usize])),
                    lod,
                    offset: t.offset.map(|o| o.map(|x| ints(r, x))),
                    compare_only: t.compare_only,
                    mask: cur,
                };
                textures.sample(&req, &mut out);
            }
        }
    }
    // An integer texture's texels are the integers' bits.
    let integer = t.target.result() != glsl::types::SamplerResult::Float;
    for (k, o) in out.iter().enumerate() {
        r[t.d as usize + k] = if integer {
            o.map(f32::to_bits)
        } else {
            o.map(ftz)
        };
    }
}
