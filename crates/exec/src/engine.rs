//! The interpreter: runs an optimized program ([`Code`], made by
//! [`crate::opt`]) over a register file reused per thread, one op at a
//! time over all 16 lanes ([`step`]), compiled once per CPU variant
//! (each [`crate::cpu::Level`]: [`run_in`] and its copies by
//! [`crate::multiversion!`], [`run_at`]; which one runs is chosen by
//! [`crate::dispatch`]).
//!
//! Also what native code (`jit`) shares with it: loading a run's inputs
//! and pool ([`load`]), copying its outputs ([`store_outputs`]), the
//! uniform prologue ([`prepare`]), and the data ops native code calls
//! back for ([`step_data`], [`f1`], [`f2`]).
//!
//! The interpreter loop indexes registers without bounds checks: every
//! register index of `Code` was validated when the kernel was built
//! ([`crate::opt`]).

use crate::interp::FULL;
use crate::opt::{Code, Ins};
use crate::program::{Op, Reg, TexKind, TexLod, F1, F2, F3};
use crate::{
    Batch, ExecError, FetchRequest, Kernel, LaneMask, Lod, SampleRequest, Textures, LANES,
};
use glsl::math;
use glsl::types::Scalar;

pub(crate) type Lanes = [u32; LANES];

#[inline(always)]
fn f(x: u32) -> f32 {
    f32::from_bits(x)
}

use crate::lane::{self, flush as fz, flush_bits as ftz, match_op, max as fmax, min as fmin};
pub(crate) use crate::lane::{float_output, uniform_word};

/// `a` with its subnormals flushed ([`ftz`]).
pub(crate) fn flushed(a: &Lanes) -> Lanes {
    a.map(|x| ftz(f(x)))
}

#[inline(always)]
fn lanes(mut g: impl FnMut(usize) -> u32) -> Lanes {
    let mut o = [0u32; LANES];
    for (l, v) in o.iter_mut().enumerate() {
        *v = g(l);
    }
    o
}

/// Per-lane all-ones where `cur` has the lane.
#[inline(always)]
pub(crate) fn expand(cur: LaneMask) -> Lanes {
    lanes(|l| 0u32.wrapping_sub((cur >> l) & 1))
}

/// The value of every pool register for `uniforms` (the prologue's
/// results).
pub(crate) fn prepare(code: &Code, uniforms: &[u32], textures: &dyn Textures) -> Vec<Lanes> {
    let mut file = vec![[0u32; LANES]; code.prog.registers as usize];
    // SAFETY: `file` has `prog.registers` entries and the prologue was
    // validated against that count.
    unsafe { prologue(code, file.as_mut_ptr(), uniforms, textures) };
    file.split_off(code.pool_base as usize)
}

/// # Safety
/// `regs` must point to `code.prog.registers` registers.
#[inline(always)]
pub(crate) unsafe fn prologue(
    code: &Code,
    regs: *mut Lanes,
    uniforms: &[u32],
    textures: &dyn Textures,
) {
    let mut masks = [0 as LaneMask; 0];
    let mut ret = [0u32; 0];
    let mut discarded = 0;
    let mut iterations = 0;
    for op in &code.prologue {
        let i = Ins {
            op: *op,
            masked: false,
        };
        let mut st = State {
            cur: FULL,
            effects: FULL,
            mk: [!0; LANES],
            masks: &mut masks,
            ret: &mut ret,
            discarded: &mut discarded,
            iterations: &mut iterations,
        };
        // Pure data ops and size queries never jump or fail.
        let _ = step(code, regs, &i, 0, &mut st, uniforms, textures, u64::MAX);
    }
}

struct State<'a> {
    cur: LaneMask,
    /// Lanes whose writes to memory take effect: not a fragment batch's
    /// helper lanes (GL 4.3 §7.12.3: helper invocations have no side
    /// effects).
    effects: LaneMask,
    mk: Lanes,
    masks: &'a mut [LaneMask],
    ret: &'a mut [u32],
    discarded: &'a mut LaneMask,
    iterations: &'a mut u64,
}

crate::multiversion! {
    /// [`run_in`] compiled for `level` (its copies `run_portable`,
    /// `run_avx2`, `run_avx512`); the portable one when the CPU lacks it.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn run_at(
        #[level] level: crate::cpu::Level,
        k: &Kernel,
        code: &Code,
        file: &mut Vec<Lanes>,
        batch: &mut Batch,
        uniforms: &[u32],
        textures: &dyn Textures,
        pool: Option<&[Lanes]>,
    ) -> Result<(), ExecError>;
    copies = [run_portable, run_avx2, run_avx512],
    body = run_in(k, code, file, batch, uniforms, textures, pool)
}

/// The interpreter proper; inlined into each CPU variant, which compile
/// the same IEEE operations (Rust never contracts `a * b + c` into a fused
/// multiply-add), so every variant computes the same bits.
#[inline(always)]
pub(crate) fn run_in(
    k: &Kernel,
    code: &Code,
    file: &mut Vec<Lanes>,
    batch: &mut Batch,
    uniforms: &[u32],
    textures: &dyn Textures,
    pool: Option<&[Lanes]>,
) -> Result<(), ExecError> {
    let regs = if load(k, code, file, batch, pool) {
        let regs = file.as_mut_ptr();
        // SAFETY: `load` gave the file `code.prog.registers` registers.
        unsafe { prologue(code, regs, uniforms, textures) };
        regs
    } else {
        file.as_mut_ptr()
    };

    let mut masks = vec![0 as LaneMask; code.prog.mask_slots as usize];
    let mut ret = vec![0u32; code.prog.subroutines as usize];
    let start = (batch.active | batch.helper) & FULL;
    batch.discarded = 0;
    let mut discarded = 0;
    let mut iterations: u64 = 0;
    let mut st = State {
        cur: start,
        effects: !batch.helper,
        mk: expand(start),
        masks: &mut masks,
        ret: &mut ret,
        discarded: &mut discarded,
        iterations: &mut iterations,
    };
    let mut pc = 0usize;
    while let Some(i) = code.ins.get(pc) {
        // SAFETY: `regs` has `code.prog.registers` registers, against
        // which `code.ins` was validated.
        pc = unsafe {
            step(
                code,
                regs,
                i,
                pc,
                &mut st,
                uniforms,
                textures,
                k.loop_budget,
            )?
        };
    }
    batch.discarded = discarded;
    store_outputs(k, file, batch);
    Ok(())
}

/// Prepares `file` for a run of `code`: at least `code.prog.registers`
/// registers, the live-at-entry ones zeroed, initializers, inputs, and the
/// pool from `pool` when it fits. Returns whether the prologue still has to
/// fill the pool.
pub(crate) fn load(
    k: &Kernel,
    code: &Code,
    file: &mut Vec<Lanes>,
    batch: &Batch,
    pool: Option<&[Lanes]>,
) -> bool {
    load_inputs(k, code, file, batch);
    let nregs = code.prog.registers as usize;
    let pool_len = nregs - code.pool_base as usize;
    match pool {
        Some(values) if values.len() == pool_len => {
            file[code.pool_base as usize..nregs].copy_from_slice(values);
            false
        }
        _ => true,
    }
}

/// [`load`] without the pool: at least `code.prog.registers` registers,
/// the live-at-entry ones zeroed, initializers and inputs. Copies, exact
/// conversions and the flush of subnormal float inputs (integer selects):
/// compiled for the widest vectors the CPU has, the same values.
pub(crate) fn load_inputs(k: &Kernel, code: &Code, file: &mut Vec<Lanes>, batch: &Batch) {
    load_inputs_at(crate::cpu::Level::best(), k, code, file, batch)
}

crate::multiversion! {
    /// [`load_inputs_with`] at `level` (AVX2: a register in two stores;
    /// AVX-512: in one).
    fn load_inputs_at(
        #[level] level: crate::cpu::Level,
        k: &Kernel,
        code: &Code,
        file: &mut Vec<Lanes>,
        batch: &Batch,
    );
    copies = [load_inputs_portable, load_inputs_avx2, load_inputs_avx512],
    body = load_inputs_with(k, code, file, batch)
}

#[inline(always)]
fn load_inputs_with(k: &Kernel, code: &Code, file: &mut Vec<Lanes>, batch: &Batch) {
    let nregs = code.prog.registers as usize;
    if file.len() < nregs {
        file.resize(nregs, [0; LANES]);
    }
    for &r in &code.zero {
        if let Some(x) = file.get_mut(r as usize) {
            *x = [0; LANES];
        }
    }
    for &(reg, bits) in &code.prog.init {
        if let Some(x) = file.get_mut(reg as usize) {
            *x = [bits; LANES];
        }
    }
    // Integer inputs are their bits (see `Batch::inputs`).
    for &(ic, reg, kind) in &k.inputs {
        let src = batch.inputs.get(ic).copied().unwrap_or([0.0; LANES]);
        if let Some(x) = file.get_mut(reg as usize) {
            *x = match kind {
                // Subnormal inputs enter as zero, as every float value.
                Scalar::Float => lanes(|l| ftz(src[l])),
                Scalar::Int | Scalar::Uint => src.map(f32::to_bits),
                Scalar::Bool => src.map(|v| (v != 0.0) as u32),
            };
        }
    }
}

/// Copies the output registers of the active lanes into `batch.outputs`.
pub(crate) fn store_outputs(k: &Kernel, file: &[Lanes], batch: &mut Batch) {
    store_outputs_at(crate::cpu::Level::best(), k, file, batch)
}

crate::multiversion! {
    /// [`store_outputs_with`] at `level` (integer selects only: the same
    /// bits).
    fn store_outputs_at(
        #[level] level: crate::cpu::Level,
        k: &Kernel,
        file: &[Lanes],
        batch: &mut Batch,
    );
    copies = [store_outputs_portable, store_outputs_avx2, store_outputs_avx512],
    body = store_outputs_with(k, file, batch)
}

#[inline(always)]
fn store_outputs_with(k: &Kernel, file: &[Lanes], batch: &mut Batch) {
    let active = batch.output_lanes(k);
    // Varyings' integers are their bits (see `Batch::outputs`).
    let bits = k.stage != glsl::Stage::Fragment;
    for &(reg, oc, kind) in &k.outputs {
        let Some(src) = file.get(reg as usize).map(read_in_pieces) else {
            continue;
        };
        if let Some(dst) = batch.outputs.get_mut(oc) {
            // The kind chosen once per output, the lanes selected without
            // branches (so the loops vectorize).
            let value: Lanes = match kind {
                Scalar::Float => lanes(|l| float_output(src[l])),
                Scalar::Int | Scalar::Uint if bits => src,
                Scalar::Int => src.map(|x| (x as i32 as f32).to_bits()),
                Scalar::Uint => src.map(|x| (x as f32).to_bits()),
                Scalar::Bool => src.map(|x| ((x != 0) as u32 as f32).to_bits()),
            };
            for (l, v) in dst.iter_mut().enumerate() {
                let on = 0u32.wrapping_sub((active >> l) & 1);
                *v = f32::from_bits((value[l] & on) | (v.to_bits() & !on));
            }
        }
    }
}

/// Register `src`, read four lanes at a time. Native code stores a
/// register in four 4-lane pieces; one 16-lane load of them waits until
/// the stores reach the cache (the store buffer cannot forward several
/// stores into one load), which took 40 % of `store_outputs`' time after
/// a native run on Zen 4. Read in the same pieces, each load is
/// forwarded from its store.
#[inline(always)]
fn read_in_pieces(src: &Lanes) -> Lanes {
    #[cfg(target_arch = "x86_64")]
    if (src.as_ptr() as usize).is_multiple_of(16) {
        use std::arch::x86_64::__m128i;
        let p = src.as_ptr().cast::<__m128i>();
        // Volatile: the loads stay four (not merged into one wide load).
        // SAFETY: `p` is 16-byte aligned and `src` holds LANES / 4
        // `__m128i`s.
        let pieces: [__m128i; LANES / 4] =
            std::array::from_fn(|g| unsafe { std::ptr::read_volatile(p.add(g)) });
        // SAFETY: the same size, and every bit pattern is a valid `Lanes`.
        return unsafe { std::mem::transmute::<[__m128i; LANES / 4], Lanes>(pieces) };
    }
    *src
}

/// Runs one data instruction (no jump, no mask change, no loop count) on
/// the lanes of `cur`: what native code calls for the ops it does not
/// compile itself, so they compute what the interpreter computes by
/// construction.
///
/// # Safety
/// As for [`step`]: `regs` must point to `code.prog.registers` registers
/// and `i` must be an instruction of `code.ins` or `code.prologue`.
pub(crate) unsafe fn step_data(
    code: &Code,
    regs: *mut Lanes,
    i: &Ins,
    cur: LaneMask,
    uniforms: &[u32],
    textures: &dyn Textures,
) {
    let mut masks = [0 as LaneMask; 0];
    let mut ret = [0u32; 0];
    let mut discarded = 0;
    let mut iterations = 0;
    let mut st = State {
        cur,
        effects: FULL,
        mk: expand(cur),
        masks: &mut masks,
        ret: &mut ret,
        discarded: &mut discarded,
        iterations: &mut iterations,
    };
    // Data ops never jump or fail (the budget is not consulted).
    let _ = step(code, regs, i, 0, &mut st, uniforms, textures, u64::MAX);
}

/// Executes one instruction; returns the next pc.
///
/// # Safety
/// `regs` must point to `code.prog.registers` registers and `i` must be an
/// instruction validated against that count (part of `code.ins` or
/// `code.prologue`).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
unsafe fn step(
    code: &Code,
    regs: *mut Lanes,
    i: &Ins,
    pc: usize,
    st: &mut State,
    uniforms: &[u32],
    textures: &dyn Textures,
    budget: u64,
) -> Result<usize, ExecError> {
    macro_rules! g {
        ($r:expr) => {
            *regs.add($r as usize)
        };
    }
    let m = i.masked;
    let mk = st.mk;
    macro_rules! put {
        ($d:expr, $v:expr) => {{
            let v: Lanes = $v;
            let dst = &mut *regs.add($d as usize);
            if m {
                *dst = lanes(|l| (v[l] & mk[l]) | (dst[l] & !mk[l]));
            } else {
                *dst = v;
            }
        }};
    }
    macro_rules! un {
        ($d:expr, $a:expr, |$x:ident| $body:expr) => {{
            let a = g!($a);
            put!(
                $d,
                lanes(|l| {
                    let $x = a[l];
                    $body
                })
            )
        }};
    }
    macro_rules! bin {
        ($d:expr, $a:expr, $b:expr, |$x:ident, $y:ident| $body:expr) => {{
            let (a, b) = (g!($a), g!($b));
            put!(
                $d,
                lanes(|l| {
                    let ($x, $y) = (a[l], b[l]);
                    $body
                })
            )
        }};
    }
    macro_rules! tri {
        ($d:expr, $a:expr, $b:expr, $c:expr, |$x:ident, $y:ident, $z:ident| $body:expr) => {{
            let (a, b, c) = (g!($a), g!($b), g!($c));
            put!(
                $d,
                lanes(|l| {
                    let ($x, $y, $z) = (f(a[l]), f(b[l]), f(c[l]));
                    $body
                })
            )
        }};
    }
    let uni = |w: usize, float: bool| uniform_word(uniforms, w, float);
    let mut next = pc + 1;
    match_op!(match i.op {
        Op::Const { d, bits } => put!(d, [bits; LANES]),
        Op::Mov { d, a } => put!(d, g!(a)),
        Op::Store { d, a } => {
            let a = g!(a);
            let dst = &mut *regs.add(d as usize);
            *dst = lanes(|l| (a[l] & mk[l]) | (dst[l] & !mk[l]));
        }
        Op::Uniform { d, word, float } => put!(d, [uni(word as usize, float); LANES]),
        Op::FMac { d, a, b } => {
            let (a, b, acc) = (g!(a), g!(b), g!(d));
            put!(d, lanes(|l| ftz(f(acc[l]) + f(ftz(f(a[l]) * f(b[l]))))))
        }
        Op::Dot { d, n, a, b } => {
            let n = (n as usize).clamp(1, 4);
            let (x, y) = (g!(a[n - 1]), g!(b[n - 1]));
            let mut acc = lanes(|l| ftz(f(x[l]) * f(y[l])));
            for k in (0..n - 1).rev() {
                let (x, y) = (g!(a[k]), g!(b[k]));
                acc = lanes(|l| ftz(f(acc[l]) + f(ftz(f(x[l]) * f(y[l])))));
            }
            put!(d, acc)
        }
        Op::F1 { f: func, d, a } => {
            let a = g!(a);
            put!(d, f1(func, &a))
        }
        Op::F2 { f: func, d, a, b } => {
            let (a, b) = (g!(a), g!(b));
            put!(d, f2(func, &a, &b))
        }
        Op::F3 {
            f: func,
            d,
            a,
            b,
            c,
        } => match func {
            // The formulas of glsl::math, with its flushed intermediates.
            F3::Mix => tri!(d, a, b, c, |x, y, t| lane::mix(x, y, t).to_bits()),
            F3::Clamp => tri!(d, a, b, c, |x, lo, hi| lane::clamp(x, lo, hi).to_bits()),
            F3::SmoothStep => tri!(d, a, b, c, |e0, e1, x| {
                let t = fmin(fmax(fz(fz(x - e0) / fz(e1 - e0)), 0.0), 1.0);
                ftz(fz(t * t) * (3.0 - 2.0 * t))
            }),
        },
        Op::Select { d, c, a, b } => {
            let (c, a, b) = (g!(c), g!(a), g!(b));
            put!(d, lanes(|l| if c[l] != 0 { a[l] } else { b[l] }))
        }
        Op::Gather { d, base, off, max } => {
            let o = g!(off);
            let v = lanes(|l| (*regs.add((base + o[l].min(max)) as usize))[l]);
            put!(d, v)
        }
        Op::Scatter { base, off, max, a } => {
            let (o, a) = (g!(off), g!(a));
            for l in 0..LANES {
                if st.cur & (1 << l) != 0 {
                    (*regs.add((base + o[l].min(max)) as usize))[l] = a[l];
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
            let o = g!(off);
            put!(
                d,
                lanes(|l| uni(word as usize + o[l].min(max) as usize, float))
            )
        }
        // Operands read flushed, as in texture lookups (see `floats`).
        Op::DdX { d, a } => {
            let a = g!(a);
            put!(d, lanes(|l| ftz(fz(f(a[l | 1])) - fz(f(a[l & !1])))))
        }
        Op::DdY { d, a } => {
            let a = g!(a);
            put!(d, lanes(|l| ftz(fz(f(a[l | 2])) - fz(f(a[l & !2])))))
        }
        Op::Noise { d, n, a, dims } => {
            let mut out = [[0u32; LANES]; 4];
            #[allow(clippy::needless_range_loop)]
            for l in 0..LANES {
                let mut x = [0f32; 4];
                for (k, xk) in x.iter_mut().enumerate().take(dims as usize) {
                    *xk = fz(f(g!(a + k as u32)[l]));
                }
                let v = lane::noise(n, &x[..(dims as usize).min(4)]);
                for k in 0..4 {
                    out[k][l] = ftz(v[k]);
                }
            }
            for (k, o) in out.iter().enumerate().take(n as usize) {
                *regs.add(d as usize + k) = *o;
            }
        }
        Op::Texture { index } => {
            if let Some(t) = code.prog.textures.get(index as usize) {
                texture(Registers::file(regs), t, st.cur, textures);
            }
        }
        // Only hooked runs (the reference interpreter) print.
        Op::Printf { .. } => {}
        Op::Load { .. }
        | Op::StoreMem { .. }
        | Op::Atomic { .. }
        | Op::MemSize { .. }
        | Op::Barrier => {
            let get = |r: Reg| *regs.add(r as usize);
            let lanes = if i.op.writes_memory() {
                st.cur & st.effects
            } else {
                st.cur
            };
            if let Some(Some((d, v))) =
                crate::memory_ops::run_op(&i.op, lanes, get, textures.memory())
            {
                put!(d, v);
            }
        }
        Op::SaveMask { slot } => st.masks[slot as usize] = st.cur,
        Op::RestoreMask { slot } => {
            st.cur = st.masks[slot as usize];
            st.mk = expand(st.cur);
        }
        Op::AndMask { c } => {
            let c = g!(c);
            for (l, &v) in c.iter().enumerate() {
                if v == 0 {
                    st.cur &= !(1 << l);
                }
            }
            st.mk = expand(st.cur);
        }
        Op::AndNotMask { slot, c } => {
            let c = g!(c);
            st.cur = st.masks[slot as usize];
            for (l, &v) in c.iter().enumerate() {
                if v != 0 {
                    st.cur &= !(1 << l);
                }
            }
            st.mk = expand(st.cur);
        }
        Op::JumpIfNone { target } => {
            if st.cur == 0 {
                next = target as usize;
            }
        }
        Op::Jump { target } => next = target as usize,
        Op::LoopIter => {
            *st.iterations += 1;
            if *st.iterations > budget {
                return Err(ExecError::LoopBudget {
                    iterations: *st.iterations,
                });
            }
        }
        Op::Call { target, slot } => {
            st.ret[slot as usize] = next as u32;
            next = target as usize;
        }
        Op::Ret { slot } => next = st.ret[slot as usize] as usize,
        Op::SyncDiscard { start, end } => {
            let gone = *st.discarded;
            for &s in &code.prog.kill_slots[start as usize..end as usize] {
                st.masks[s as usize] &= !gone;
            }
            st.cur &= !gone;
            st.mk = expand(st.cur);
        }
        Op::Kill { start, end } | Op::Discard { start, end } => {
            if matches!(i.op, Op::Discard { .. }) {
                *st.discarded |= st.cur;
            }
            for &s in &code.prog.kill_slots[start as usize..end as usize] {
                st.masks[s as usize] &= !st.cur;
            }
            st.cur = 0;
            st.mk = [0; LANES];
        }
    });
    Ok(next)
}

/// `body` for every lane `l`, written as a plain loop rather than through
/// [`lanes`]' closure: LLVM leaves a closure this big un-inlined (a call per
/// lane, compiled for the baseline instruction set), while the loop is
/// inlined into each CPU variant and vectorized there. For the
/// branch-free `glsl::math` functions (`exp`, `exp2`, `log`, `log2`,
/// `pow`).
macro_rules! lane_loop {
    (|$l:ident| $body:expr) => {{
        let mut o = [0u32; LANES];
        for ($l, v) in o.iter_mut().enumerate() {
            *v = $body;
        }
        o
    }};
}

#[inline(always)]
pub(crate) fn f1(func: F1, a: &Lanes) -> Lanes {
    macro_rules! each {
        (|$x:ident| $body:expr) => {
            lanes(|l| {
                let $x = f(a[l]);
                $body
            })
        };
    }
    match func {
        F1::Abs => lanes(|l| ftz(f(a[l] & 0x7fff_ffff))),
        F1::Sqrt => each!(|x| ftz(x.sqrt())),
        F1::InverseSqrt => each!(|x| ftz(1.0 / x.sqrt())),
        F1::Radians => each!(|x| ftz(x * (math::PI / 180.0))),
        F1::Degrees => each!(|x| ftz(x * (180.0 / math::PI))),
        F1::Sign => each!(|x| if x > 0.0 {
            1.0f32.to_bits()
        } else if x < 0.0 {
            (-1.0f32).to_bits()
        } else {
            0
        }),
        F1::Floor => each!(|x| ftz(floor(x))),
        F1::Ceil => each!(|x| ftz(ceil(x))),
        F1::Fract => each!(|x| ftz(x - floor(x))),
        F1::Exp => lane_loop!(|l| lane::exp(f(a[l])).to_bits()),
        F1::Exp2 => lane_loop!(|l| ftz(math::exp2(f(a[l])))),
        F1::Log => lane_loop!(|l| ftz(math::log(f(a[l])))),
        F1::Log2 => lane_loop!(|l| ftz(math::log2(f(a[l])))),
        other => each!(|x| ftz(other.eval(x))),
    }
}

#[inline(always)]
pub(crate) fn f2(func: F2, a: &Lanes, b: &Lanes) -> Lanes {
    macro_rules! each {
        (|$x:ident, $y:ident| $body:expr) => {
            lanes(|l| {
                let ($x, $y) = (f(a[l]), f(b[l]));
                $body
            })
        };
    }
    match func {
        F2::Min => each!(|x, y| ftz(fmin(x, y))),
        F2::Max => each!(|x, y| ftz(fmax(x, y))),
        F2::Step => each!(|e, x| if x < e { 0 } else { 1.0f32.to_bits() }),
        F2::Mod => each!(|x, y| ftz(x - y * floor(fz(x / y)))),
        F2::Pow => lane_loop!(|l| ftz(math::pow(f(a[l]), f(b[l])))),
        other => each!(|x, y| ftz(other.eval(x, y))),
    }
}

/// `floor` without a library call: exact for every `f32` (the same bits as
/// `glsl::math::floor`).
#[inline(always)]
pub(crate) fn floor(x: f32) -> f32 {
    // |x| >= 2^23 (and inf, NaN): already integral.
    if x.abs() >= 8_388_608.0 || x.is_nan() {
        return x;
    }
    let t = x as i32 as f32;
    let r = if t > x { t - 1.0 } else { t };
    // A zero result keeps the sign of x (floor(-0.0) = -0.0).
    f32::from_bits(r.to_bits() | (x.to_bits() & 0x8000_0000 & (((r == 0.0) as u32) << 31)))
}

/// `ceil` without a library call (the same bits as `glsl::math::ceil`).
#[inline(always)]
pub(crate) fn ceil(x: f32) -> f32 {
    if x.abs() >= 8_388_608.0 || x.is_nan() {
        return x;
    }
    let t = x as i32 as f32;
    let r = if t < x { t + 1.0 } else { t };
    f32::from_bits(r.to_bits() | (x.to_bits() & 0x8000_0000 & (((r == 0.0) as u32) << 31)))
}

/// The lanes of `a` as floats, subnormals read as zero (operands of the
/// lookups native code calls back for may be unflushed: see `jit`).
fn floats(a: &Lanes) -> [f32; LANES] {
    a.map(|x| fz(f(x)))
}

/// Where an op run outside the interpreter loop reads its registers: the
/// file, except the pool registers (from `base` on) when they are read
/// where a prepared pool is (`jit`), at `at`.
#[derive(Clone, Copy)]
pub(crate) struct Registers {
    pub file: *mut Lanes,
    pub base: Reg,
    pub at: *const Lanes,
}

impl Registers {
    /// Registers all in the file.
    pub(crate) fn file(file: *mut Lanes) -> Registers {
        Registers {
            file,
            base: Reg::MAX,
            at: file,
        }
    }

    /// Register `x`.
    ///
    /// # Safety
    /// `x` must be a register of the file, or of the pool when at least
    /// `base` (no register is written while the reference lives).
    pub(crate) unsafe fn get<'r>(self, x: Reg) -> &'r Lanes {
        if x >= self.base {
            &*self.at.add((x - self.base) as usize)
        } else {
            &*self.file.add(x as usize)
        }
    }
}

/// The values of `a` and `b` (0 without `b`) on the lanes of `cur`,
/// when every one of those lanes has the same (a texture op's unit and
/// level, nearly always); `None` otherwise or without lanes.
#[inline]
pub(crate) fn shared_pair(cur: LaneMask, a: &Lanes, b: Option<&Lanes>) -> Option<(u32, u32)> {
    if cur == 0 {
        return None;
    }
    let f = cur.trailing_zeros() as usize;
    let b = b.unwrap_or(&[0; LANES]);
    let (x, y) = (a[f], b[f]);
    // Without branches: the lanes' differences, kept where they run.
    let mut diff = 0;
    for l in 0..LANES {
        let on = 0u32.wrapping_sub((cur >> l) & 1);
        diff |= ((a[l] ^ x) | (b[l] ^ y)) & on;
    }
    (diff == 0).then_some((x, y))
}

/// A size query (`TexKind::Size` of `Op::Texture`) on the lanes of
/// `cur`: apart from [`texture`], whose frame holds the lookups' large
/// requests, as native code calls it once per batch.
///
/// # Safety
/// As for [`texture`].
pub(crate) unsafe fn texture_size(
    regs: Registers,
    t: &crate::program::TexOp,
    cur: LaneMask,
    textures: &dyn Textures,
) {
    // SAFETY: the caller's contract, as in `texture`.
    let reg = |x: Reg| -> &Lanes { unsafe { regs.get(x) } };
    let lod = t.level().map(reg);
    let unit = reg(t.unit);
    let on = |l: usize| cur & (1 << l) != 0;
    // The fourth register too, as the reference interpreter.
    let mut sizes = [[0u32; LANES]; 4];
    // Lanes nearly always ask the same unit and level: one
    // question, its answer on every running lane.
    if let Some((u, level)) = shared_pair(cur, unit, lod) {
        let v = textures.size(u, t.target, level as i32);
        for (s, v) in sizes.iter_mut().zip(v) {
            *s = std::array::from_fn(|l| if on(l) { v as u32 } else { 0 });
        }
    } else {
        for l in (0..LANES).filter(|&l| on(l)) {
            let level = lod.map_or(0, |v| v[l] as i32);
            let v = textures.size(unit[l], t.target, level);
            for k in 0..3 {
                sizes[k][l] = v[k] as u32;
            }
        }
    }
    for (k, o) in sizes.iter().enumerate() {
        *regs.file.add(t.d as usize + k) = *o;
    }
}

/// A texture op (`Op::Texture`) on the lanes of `cur`.
///
/// # Safety
/// `regs` must hold every register `t` names (validated).
pub(crate) unsafe fn texture(
    regs: Registers,
    t: &crate::program::TexOp,
    cur: LaneMask,
    textures: &dyn Textures,
) {
    // SAFETY: the caller's contract: each register `t` names is in
    // `regs` (a reference to one, read while no register is written).
    let reg = |x: Reg| -> &Lanes { unsafe { regs.get(x) } };
    let ints = |x: Reg| -> [i32; LANES] { reg(x).map(|b| b as i32) };
    let level = |l: Option<Reg>| l.map_or([0; LANES], ints);
    let mut out = [[0f32; LANES]; 4];
    match t.kind {
        TexKind::Size => return texture_size(regs, t, cur, textures),
        TexKind::Fetch if cur != 0 => {
            let mut req = FetchRequest {
                unit: *reg(t.unit),
                target: t.target,
                coord: [0, 1, 2].map(|k| ints(t.coord[k])),
                lod: level(t.level()),
                mask: cur,
            };
            if let Some(o) = t.offset {
                for (c, &o) in req.coord.iter_mut().zip(&o) {
                    let o = ints(o);
                    for l in 0..LANES {
                        c[l] = c[l].wrapping_add(o[l]);
                    }
                }
            }
            textures.fetch(&req, &mut out);
        }
        TexKind::Fetch => {}
        TexKind::Sample if cur != 0 => {
            // Built in place, then filled: the request is large, and building
            // its parts apart and moving them in cost copies of each.
            let mut req = SampleRequest {
                unit: *reg(t.unit),
                target: t.target,
                coord: [[0.0; LANES]; 4],
                compare: None,
                lod: match t.lod {
                    TexLod::Explicit(_) => Lod::Explicit([0.0; LANES]),
                    TexLod::Implicit { .. } => Lod::Derivatives {
                        ddx: [[0.0; LANES]; 3],
                        ddy: [[0.0; LANES]; 3],
                        bias: [0.0; LANES],
                    },
                    TexLod::Grad { .. } => Lod::Gradients {
                        ddx: [[0.0; LANES]; 3],
                        ddy: [[0.0; LANES]; 3],
                    },
                },
                offset: t.offset.map(|o| o.map(ints)),
                compare_only: t.compare_only,
                mask: cur,
            };
            for (c, &x) in req.coord.iter_mut().zip(&t.coord) {
                *c = floats(reg(x));
            }
            if let Some(c) = t.compare {
                req.compare = Some(floats(reg(c)));
            }
            let dims = (t.dims as usize).min(3);
            match (&mut req.lod, t.lod) {
                (Lod::Explicit(v), TexLod::Explicit(Some(l))) => *v = floats(reg(l)),
                (Lod::Derivatives { ddx, ddy, bias }, TexLod::Implicit { bias: b }) => {
                    for k in 0..dims {
                        (ddx[k], ddy[k]) = lane::quad_diffs(&req.coord[k]);
                    }
                    if let Some(b) = b {
                        *bias = floats(reg(b));
                    }
                }
                (Lod::Gradients { ddx, ddy }, TexLod::Grad { ddx: x, ddy: y }) => {
                    for k in 0..dims {
                        ddx[k] = floats(reg(x[k]));
                        ddy[k] = floats(reg(y[k]));
                    }
                }
                _ => {}
            }
            textures.sample(&req, &mut out);
        }
        TexKind::Sample => {}
    }
    let integer = t.target.result() != glsl::types::SamplerResult::Float;
    for (k, o) in out.iter().enumerate() {
        // Subnormal results (a border colour, say) enter as zero; an
        // integer texture's texels are the integers' bits.
        *regs.file.add(t.d as usize + k) = if integer {
            o.map(f32::to_bits)
        } else {
            o.map(ftz)
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::opt::unoptimized;
    use crate::program::Program;
    use glsl::math::flush_denormal;

    #[test]
    fn quad_diffs_are_the_lane_differences() {
        for a in inputs(64, 0x51de) {
            let (dx, dy) = crate::lane::quad_diffs(&floats(&a));
            for l in 0..LANES {
                // A NaN result is any NaN: Rust leaves the payload and sign
                // of a NaN that arithmetic makes unspecified (x86 keeps the
                // first operand's; Miri picks at random), so its bits are
                // not part of the contract.
                let class = |x: f32| {
                    if x.is_nan() {
                        f32::NAN.to_bits()
                    } else {
                        x.to_bits()
                    }
                };
                let want = |bit: usize| class(fz(f(a[l | bit])) - fz(f(a[l & !bit])));
                assert_eq!(class(dx[l]), want(1), "{a:x?} lane {l}");
                assert_eq!(class(dy[l]), want(2), "{a:x?} lane {l}");
            }
        }
    }

    /// Special values and random bit patterns (xorshift), 16 at a time.
    fn inputs(count: usize, seed: u64) -> Vec<Lanes> {
        let specials = [
            0.0f32,
            -0.0,
            1.0,
            -1.0,
            0.5,
            -0.5,
            1.5,
            -1.5,
            2.5,
            -2.5,
            8_388_607.5,
            -8_388_607.5,
            8_388_608.0,
            16_777_217.0,
            -16_777_216.0,
            1e-45,
            -1e-45,
            1.1754942e-38,
            f32::MIN_POSITIVE,
            f32::MAX,
            f32::MIN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            -f32::NAN,
            0.99999994,
            -0.99999994,
            1e30,
            -1e-30,
            3.0,
            100.25,
            -7.75,
        ];
        let mut s = seed;
        let mut out = vec![
            lanes(|l| specials[l].to_bits()),
            lanes(|l| specials[16 + l].to_bits()),
        ];
        while out.len() < count {
            out.push(lanes(|_| {
                s ^= s << 13;
                s ^= s >> 7;
                s ^= s << 17;
                // Half the lanes in a moderate range, half any bits.
                if s & 1 == 0 {
                    (((s >> 8) as u32 as f32) / 4e8 - 5.0).to_bits()
                } else {
                    (s >> 16) as u32
                }
            }));
        }
        out
    }

    /// The flushed bits of `x`, a NaN as the canonical one: inside a run a
    /// NaN's payload depends on operand order (see [`float_output`]).
    fn want(x: f32) -> u32 {
        float_output(flush_denormal(x).to_bits())
    }

    #[test]
    fn inline_math_matches_glsl_math_bit_for_bit() {
        let a = inputs(70_000, 1);
        let b = inputs(70_000, 2);
        let c = inputs(70_000, 3);
        let one = [
            F1::Abs,
            F1::Sqrt,
            F1::InverseSqrt,
            F1::Radians,
            F1::Degrees,
            F1::Sign,
            F1::Floor,
            F1::Ceil,
            F1::Fract,
            F1::Exp,
            F1::Exp2,
            F1::Log,
            F1::Log2,
        ];
        let two = [F2::Min, F2::Max, F2::Step, F2::Mod, F2::Pow];
        let three = [F3::Clamp, F3::Mix, F3::SmoothStep];
        // Every pairing of specials with specials, then random vectors
        // (70,000 x 16 lanes = 1.1 million inputs per function).
        for i in 0..a.len() {
            let (x, y, z) = (&a[i], &b[(i * 7) % b.len()], &c[(i * 13) % c.len()]);
            for func in one {
                let got = f1(func, x);
                for l in 0..LANES {
                    let got = float_output(got[l]);
                    assert_eq!(got, want(func.eval(f(x[l]))), "{func:?}({:e})", f(x[l]));
                }
            }
            for func in two {
                let got = f2(func, x, y);
                for l in 0..LANES {
                    let got = float_output(got[l]);
                    assert_eq!(got, want(func.eval(f(x[l]), f(y[l]))), "{func:?}");
                }
            }
            for func in three {
                // The F3 arms are inlined in `step`: run them as an op.
                let code = unoptimized(
                    &Program {
                        ops: vec![Op::F3 {
                            f: func,
                            d: 3,
                            a: 0,
                            b: 1,
                            c: 2,
                        }],
                        registers: 4,
                        ..Program::default()
                    },
                    &[3],
                );
                let mut regs = [*x, *y, *z, [0; LANES]];
                let mut st_masks = [0; 0];
                let mut st_ret = [0; 0];
                let (mut disc, mut it) = (0, 0);
                let mut st = State {
                    cur: FULL,
                    effects: FULL,
                    mk: [!0; LANES],
                    masks: &mut st_masks,
                    ret: &mut st_ret,
                    discarded: &mut disc,
                    iterations: &mut it,
                };
                // SAFETY: 4 registers, the op names registers 0..4.
                unsafe {
                    step(
                        &code,
                        regs.as_mut_ptr(),
                        &code.ins[0],
                        0,
                        &mut st,
                        &[],
                        &crate::NoTextures,
                        0,
                    )
                    .unwrap();
                }
                for l in 0..LANES {
                    assert_eq!(
                        float_output(regs[3][l]),
                        want(func.eval(f(x[l]), f(y[l]), f(z[l]))),
                        "{func:?}({:x}, {:x}, {:x})",
                        x[l],
                        y[l],
                        z[l]
                    );
                }
            }
        }
    }

    #[test]
    fn branchless_flush_matches_flush_denormal() {
        for v in inputs(20_000, 9) {
            for x in v {
                assert_eq!(ftz(f(x)), flush_denormal(f(x)).to_bits());
            }
        }
    }
}
