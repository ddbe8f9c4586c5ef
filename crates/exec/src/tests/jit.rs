//! Random programs of every data op, mask op and masked store, run by the
//! interpreter and by native code: the same bits, the same discarded
//! lanes, the same loop-budget errors.
//!
//! The programs are typed as GLSL's are: float ops work on the float
//! registers (the lower half), integer, bool and index ops on the others,
//! conversions and comparisons cross over. Integer ops never see a float's
//! bits, so a NaN's payload (which depends on the order compiled code puts
//! two NaN operands in) can only reach a float output, where it becomes
//! the canonical NaN.

use super::{bits_of, Rng};
use crate::opt::{Code, Ins};
use crate::program::{Op, Program, Reg, F1, F2, F3};
use crate::{Batch, Interface, Kernel, NoTextures, Variant, LANES};
use glsl::types::Scalar;

const REGS: u32 = 24;

impl Rng {
    fn below(&mut self, n: u32) -> u32 {
        (self.next() >> 20) as u32 % n
    }
    fn reg(&mut self) -> u32 {
        self.below(REGS)
    }
    /// A float register.
    fn f(&mut self) -> u32 {
        self.below(FLOAT_REGS)
    }
    /// An integer (or bool) register.
    fn i(&mut self) -> u32 {
        FLOAT_REGS + self.below(REGS - FLOAT_REGS)
    }
    /// A register of the same class as `d`.
    fn like(&mut self, d: u32) -> u32 {
        if d < FLOAT_REGS {
            self.f()
        } else {
            self.i()
        }
    }
    /// `(base, max)` of a run of `max + 1` registers of one class, `max < 4`.
    fn run(&mut self) -> (u32, u32) {
        let max = self.below(4);
        let (lo, n) = if self.below(2) == 0 {
            (0, FLOAT_REGS)
        } else {
            (FLOAT_REGS, REGS - FLOAT_REGS)
        };
        (lo + self.below(n - max), max)
    }
}

/// Registers `0..FLOAT_REGS` hold floats, the rest ints and bools.
const FLOAT_REGS: u32 = REGS / 2;

const F1S: [F1; 30] = [
    F1::Radians,
    F1::Degrees,
    F1::Sin,
    F1::Cos,
    F1::Tan,
    F1::Asin,
    F1::Acos,
    F1::Atan,
    F1::Exp,
    F1::Log,
    F1::Exp2,
    F1::Log2,
    F1::Sqrt,
    F1::InverseSqrt,
    F1::Abs,
    F1::Sign,
    F1::Floor,
    F1::Ceil,
    F1::Fract,
    F1::Sinh,
    F1::Cosh,
    F1::Tanh,
    F1::Asinh,
    F1::Acosh,
    F1::Atanh,
    F1::Trunc,
    F1::Round,
    F1::RoundEven,
    F1::ModfFract,
    F1::FlushBits,
];
const F2S: [F2; 6] = [F2::Atan2, F2::Pow, F2::Mod, F2::Min, F2::Max, F2::Step];
const F3S: [F3; 3] = [F3::Clamp, F3::Mix, F3::SmoothStep];

/// A value worth testing: specials, subnormals, small ints, bools, any
/// bits.
fn value(r: &mut Rng) -> u32 {
    const SPECIAL: [f32; 16] = [
        0.0,
        -0.0,
        1.0,
        -1.0,
        0.5,
        -2.5,
        8_388_608.5,
        -1e-45,
        1.1754942e-38,
        f32::MAX,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        3e9,
        -3e9,
        1e-20,
    ];
    match r.below(5) {
        0 => SPECIAL[r.below(16) as usize].to_bits(),
        1 => (r.below(11) as i32 - 5) as u32,
        2 => r.below(2),
        3 => ((r.next() >> 30) as u32 as f32 / 1e8 - 20.0).to_bits(),
        _ => (r.next() >> 11) as u32,
    }
}

fn random_op(r: &mut Rng, i: u32, n: u32) -> Op {
    // Float operands and result; integer ones; any destination.
    let (d, a, b, c) = (r.f(), r.f(), r.f(), r.f());
    let (id, ia, ib, ic) = (r.i(), r.i(), r.i(), r.i());
    let any = r.reg();
    match r.below(61) {
        // Float constants are flushed, as lowering makes them.
        0 => Op::Const {
            d: any,
            bits: if any < FLOAT_REGS {
                glsl::math::flush_denormal(f32::from_bits(value(r))).to_bits()
            } else {
                value(r)
            },
        },
        1 => Op::Mov {
            d: any,
            a: r.like(any),
        },
        2 | 3 => Op::Store {
            d: any,
            a: r.like(any),
        },
        4 => Op::FAdd { d, a, b },
        5 => Op::FSub { d, a, b },
        6 => Op::FMul { d, a, b },
        7 => Op::FDiv { d, a, b },
        8 => Op::FNeg { d, a },
        9 => Op::FMac { d, a, b },
        10 => Op::Dot {
            d,
            n: 1 + r.below(4) as u8,
            a: [a, b, c, r.f()],
            b: [r.f(), r.f(), r.f(), r.f()],
        },
        11 | 12 => Op::F1 {
            f: F1S[r.below(19) as usize],
            d,
            a,
        },
        13 | 14 => Op::F2 {
            f: F2S[r.below(6) as usize],
            d,
            a,
            b,
        },
        15 => Op::F3 {
            f: F3S[r.below(3) as usize],
            d,
            a,
            b,
            c,
        },
        16 => Op::FLt { d: id, a, b },
        17 => Op::FLe { d: id, a, b },
        18 => Op::FEq { d: id, a, b },
        19 => Op::IAdd {
            d: id,
            a: ia,
            b: ib,
        },
        20 => Op::ISub {
            d: id,
            a: ia,
            b: ib,
        },
        21 => Op::IMul {
            d: id,
            a: ia,
            b: ib,
        },
        22 => Op::IDiv {
            d: id,
            a: ia,
            b: ib,
        },
        23 => Op::INeg { d: id, a: ia },
        24 => Op::ILt {
            d: id,
            a: ia,
            b: ib,
        },
        25 => Op::ILe {
            d: id,
            a: ia,
            b: ib,
        },
        26 => Op::IEq {
            d: id,
            a: ia,
            b: ib,
        },
        27 => Op::And {
            d: id,
            a: ia,
            b: ib,
        },
        28 => Op::Or {
            d: id,
            a: ia,
            b: ib,
        },
        29 => Op::Xor {
            d: id,
            a: ia,
            b: ib,
        },
        30 => Op::Not { d: id, a: ia },
        31 => Op::FToI { d: id, a },
        32 => Op::IToF { d, a: ia },
        33 => Op::FToB { d: id, a },
        34 => Op::IToB { d: id, a: ia },
        35 => Op::BToF { d, a: ia },
        36 => Op::Select {
            d: any,
            c: ic,
            a: r.like(any),
            b: r.like(any),
        },
        37 => Op::ClampIdx {
            d: id,
            a: ia,
            max: r.below(5),
            stride: 1 + r.below(3),
        },
        38 => {
            let (base, max) = r.run();
            Op::Gather {
                d: r.like(base),
                base,
                off: ia,
                max,
            }
        }
        39 => {
            let (base, max) = r.run();
            Op::Scatter {
                base,
                off: ib,
                max,
                a: r.like(base),
            }
        }
        40 => Op::GatherUniform {
            d: any,
            word: r.below(4),
            off: ia,
            max: r.below(6),
            float: any < FLOAT_REGS,
        },
        41 => Op::Uniform {
            d: any,
            word: r.below(6),
            float: any < FLOAT_REGS,
        },
        42 => Op::DdX { d, a },
        43 => Op::DdY { d, a },
        44 => match r.below(6) {
            0 => Op::SaveMask { slot: r.below(2) },
            1 => Op::RestoreMask { slot: r.below(2) },
            2 | 3 => Op::AndMask { c: ic },
            _ => Op::AndNotMask {
                slot: r.below(2),
                c: ic,
            },
        },
        45 => match r.below(4) {
            0 => Op::Kill { start: 0, end: 1 },
            1 => Op::Discard { start: 0, end: 2 },
            _ => Op::SyncDiscard { start: 0, end: 2 },
        },
        46 => Op::LoopIter,
        47 => Op::UDiv {
            d: id,
            a: ia,
            b: ib,
        },
        48 => Op::IMod {
            d: id,
            a: ia,
            b: ib,
        },
        49 => Op::UMod {
            d: id,
            a: ia,
            b: ib,
        },
        50 => Op::ULt {
            d: id,
            a: ia,
            b: ib,
        },
        51 => Op::ULe {
            d: id,
            a: ia,
            b: ib,
        },
        52 => Op::Shl {
            d: id,
            a: ia,
            b: ib,
        },
        53 => Op::ShrS {
            d: id,
            a: ia,
            b: ib,
        },
        54 => Op::ShrU {
            d: id,
            a: ia,
            b: ib,
        },
        55 => Op::BitAnd {
            d: id,
            a: ia,
            b: ib,
        },
        56 => Op::BitOr {
            d: id,
            a: ia,
            b: ib,
        },
        57 => Op::BitXor {
            d: id,
            a: ia,
            b: ib,
        },
        58 => Op::BitNot { d: id, a: ia },
        59 => match r.below(2) {
            0 => Op::FToU { d: id, a },
            _ => Op::UToF { d, a: ia },
        },
        _ => {
            // Forward jumps only: every program ends.
            let target = (i + 1 + r.below(8)).min(n);
            if r.below(2) == 0 {
                Op::JumpIfNone { target }
            } else {
                Op::Jump { target }
            }
        }
    }
}

/// A kernel running `ins` (not rewritten) with every register an input,
/// and the registers of `outputs` as outputs (the others are dead at the
/// end, so native code may leave them unstored).
fn kernel_of(ins: Vec<Ins>, budget: u64, outputs: &[Reg]) -> Kernel {
    let prog = Program {
        ops: ins.iter().map(|i| i.op).collect(),
        kill_slots: vec![0, 1],
        registers: REGS,
        mask_slots: 2,
        ..Program::default()
    };
    prog.validate().expect("valid random program");
    let code = Code {
        prog,
        ins,
        prologue: Vec::new(),
        pool_base: REGS,
        zero: Vec::new(),
        live_out: outputs.to_vec(),
    };
    kernel_of_code(code, budget, outputs)
}

/// The kernel running `code` ([`kernel_of`]'s interface: the first
/// [`REGS`] registers are inputs, `outputs` outputs).
fn kernel_of_code(code: Code, budget: u64, outputs: &[Reg]) -> Kernel {
    let prog = code.prog.clone();
    let interface = Interface {
        input_components: REGS as usize,
        output_components: REGS as usize,
        uniform_words: 4,
        ..Interface::default()
    };
    Kernel {
        stage: glsl::Stage::Fragment,
        program: prog,
        interface,
        inputs: (0..REGS)
            .map(|r| {
                let kind = if r < FLOAT_REGS {
                    Scalar::Float
                } else {
                    Scalar::Int
                };
                (r as usize, r, kind)
            })
            .collect(),
        outputs: outputs
            .iter()
            .map(|&r| {
                let kind = if r < FLOAT_REGS {
                    Scalar::Float
                } else {
                    Scalar::Int
                };
                (r, r as usize, kind)
            })
            .collect(),
        loop_budget: budget,
        writes_memory: code.prog.writes_memory(),
        calls_barrier: code.prog.calls_barrier(),
        read_inputs: vec![true; REGS as usize],
        code: std::sync::Arc::new(code),
        depth: Default::default(),
        range_plan: Default::default(),
        jit: Default::default(),
    }
}

#[test]
fn random_programs_run_natively_as_interpreted() {
    if !Variant::Jit.supported() {
        return;
    }
    let mut r = Rng(0x9e37_79b9_7f4a_7c15);
    for p in 0..150 {
        let n = 10 + r.below(50);
        let ins: Vec<Ins> = (0..n)
            .map(|i| Ins {
                op: random_op(&mut r, i, n),
                masked: r.below(3) == 0,
            })
            // Only plain data ops may be fused with a store.
            .map(|mut i| {
                i.masked &= !matches!(
                    i.op,
                    Op::Store { .. }
                        | Op::Scatter { .. }
                        | Op::SaveMask { .. }
                        | Op::RestoreMask { .. }
                        | Op::AndMask { .. }
                        | Op::AndNotMask { .. }
                        | Op::Kill { .. }
                        | Op::Discard { .. }
                        | Op::SyncDiscard { .. }
                        | Op::LoopIter
                        | Op::Jump { .. }
                        | Op::JumpIfNone { .. }
                );
                i
            })
            .collect();
        // Every register an output, or a third of them dead at the end.
        let outputs: Vec<Reg> = (0..REGS).filter(|&x| p % 2 == 0 || x % 3 != 2).collect();
        let k = kernel_of(ins, r.below(4) as u64, &outputs);
        let uniforms: Vec<u32> = (0..4).map(|_| value(&mut r)).collect();
        for round in 0..4 {
            // Round 1: every lane active (native code skips the blends of
            // masked writes then).
            let active = if round == 1 {
                0xffff
            } else {
                (r.next() >> 7) as u32 & 0xffff
            };
            let mut base = Batch::for_kernel(&k, active);
            base.helper = if round == 3 { 0x0f0f } else { 0 };
            for (reg, c) in base.inputs.iter_mut().enumerate() {
                // Floats of any bits (subnormals enter as zero); ints as
                // the floats integer inputs arrive as.
                *c = [0; LANES].map(|_| {
                    let v = value(&mut r);
                    if (reg as u32) < FLOAT_REGS {
                        f32::from_bits(v)
                    } else {
                        v as i32 as f32
                    }
                });
                if round == 2 {
                    // The same value on every lane (uniform indices).
                    *c = [c[0]; LANES];
                }
            }
            let mut want = base.clone();
            let r0 = k.run_variant(Variant::Portable, &mut want, &uniforms, &NoTextures);
            let mut got = base.clone();
            let r1 = k.run_variant(Variant::Jit, &mut got, &uniforms, &NoTextures);
            assert!(
                matches!(k.native_code(), Some(Ok(_))),
                "program {p}: {:?}",
                k.native_code()
            );
            let ops: Vec<_> = k.code.ins.iter().map(|i| (i.op, i.masked)).collect();
            assert_eq!(r1, r0, "program {p}: result\n{ops:#?}");
            assert_eq!(
                got.discarded, want.discarded,
                "program {p}: discarded\n{ops:#?}"
            );
            let (g, w) = (bits_of(&got.outputs), bits_of(&want.outputs));
            for reg in outputs.iter().map(|&x| x as usize) {
                assert_eq!(
                    g[reg].map(|x| format!("{x:08x}")),
                    w[reg].map(|x| format!("{x:08x}")),
                    "program {p} round {round}: register {reg}\n{ops:#?}"
                );
            }
        }
    }
}

/// Native integer division and remainder on the pairs where they can go
/// wrong (zero and −1 divisors, the extremes, neighbours of powers of
/// two): the lane functions' values (themselves checked against Rust's
/// division in `lane`'s tests).
#[test]
fn native_integer_division_is_the_lane_functions() {
    if !Variant::Jit.supported() {
        return;
    }
    let (x, y) = (FLOAT_REGS, FLOAT_REGS + 1);
    let outs = [
        FLOAT_REGS + 2,
        FLOAT_REGS + 3,
        FLOAT_REGS + 4,
        FLOAT_REGS + 5,
    ];
    let ins = vec![
        Op::IDiv {
            d: outs[0],
            a: x,
            b: y,
        },
        Op::IMod {
            d: outs[1],
            a: x,
            b: y,
        },
        Op::UDiv {
            d: outs[2],
            a: x,
            b: y,
        },
        Op::UMod {
            d: outs[3],
            a: x,
            b: y,
        },
    ]
    .into_iter()
    .map(|op| Ins { op, masked: false })
    .collect();
    let mut k = kernel_of(ins, 0, &outs);
    // A vertex stage's integer outputs are their bits.
    k.stage = glsl::Stage::Vertex;
    let pairs = division_pairs();
    for chunk in pairs.chunks(LANES) {
        let mut b = Batch::for_kernel(&k, 0xffff);
        for (l, &(a, d)) in chunk.iter().enumerate() {
            // Integer inputs are their bits.
            b.inputs[x as usize][l] = f32::from_bits(a);
            b.inputs[y as usize][l] = f32::from_bits(d);
        }
        k.run_variant(Variant::Jit, &mut b, &[0; 4], &NoTextures)
            .unwrap();
        assert!(matches!(k.native_code(), Some(Ok(_))));
        for (l, &(a, d)) in chunk.iter().enumerate() {
            let got = outs.map(|r| b.outputs[r as usize][l].to_bits());
            assert_eq!(got, lane_divisions(a, d), "{a:#x} by {d:#x}");
        }
    }
}

/// What `IDiv`, `IMod`, `UDiv` and `UMod` give for `a` by `d`.
fn lane_divisions(a: u32, d: u32) -> [u32; 4] {
    [
        crate::lane::idiv(a, d),
        crate::lane::imod(a, d),
        crate::lane::udiv(a, d),
        crate::lane::umod(a, d),
    ]
}

/// Every pair of the values where integer division can go wrong (zero
/// and −1, the extremes, powers of two and their neighbours, and
/// divisors of a product, whose quotients are whole numbers).
fn division_pairs() -> Vec<(u32, u32)> {
    let mut special = vec![
        0u32,
        1,
        2,
        3,
        7,
        0x8000_0000,
        0x7fff_ffff,
        0x8000_0001,
        u32::MAX,
    ];
    for s in [1u32, 15, 16, 30, 31] {
        special.extend([
            1 << s,
            (1 << s) - 1,
            (1u32 << s).wrapping_neg(),
            0xffff_fffe,
        ]);
    }
    // Whole quotients (of either sign) that a product with the divisor's
    // reciprocal in f64 misses from the side of zero (found by search):
    // one too small before the correction of `int_div_by`.
    for (q, d) in [
        (58_916u32, 32_471u32),
        (2, 457_345_720),
        (1, 1_649_162_598),
        (1, 0xffed_9238),
        (3, 715_827_882),
    ] {
        let x = q.wrapping_mul(d);
        special.extend([d, d.wrapping_neg(), x, x.wrapping_neg()]);
    }
    special
        .iter()
        .flat_map(|&a| special.iter().map(move |&b| (a, b)))
        .collect()
}

/// The same with the divisor one value for the whole run (a uniform: in a
/// pool register, divided through its reciprocal): with the prologue run
/// by the native code and with a prepared pool.
#[test]
fn native_division_by_a_uniform_is_the_lane_functions() {
    if !Variant::Jit.supported() {
        return;
    }
    let (x, pool) = (FLOAT_REGS, REGS);
    let outs = [
        FLOAT_REGS + 2,
        FLOAT_REGS + 3,
        FLOAT_REGS + 4,
        FLOAT_REGS + 5,
    ];
    let ops = [
        Op::IDiv {
            d: outs[0],
            a: x,
            b: pool,
        },
        Op::IMod {
            d: outs[1],
            a: x,
            b: pool,
        },
        Op::UDiv {
            d: outs[2],
            a: x,
            b: pool,
        },
        Op::UMod {
            d: outs[3],
            a: x,
            b: pool,
        },
    ];
    let prog = Program {
        ops: ops.to_vec(),
        registers: REGS + 1,
        ..Program::default()
    };
    let code = Code {
        prog,
        ins: ops.iter().map(|&op| Ins { op, masked: false }).collect(),
        prologue: vec![Op::Uniform {
            d: pool,
            word: 0,
            float: false,
        }],
        pool_base: REGS,
        zero: Vec::new(),
        live_out: outs.to_vec(),
    };
    let mut k = kernel_of_code(code, 0, &outs);
    k.stage = glsl::Stage::Vertex;
    let pairs = division_pairs();
    let mut divisors: Vec<u32> = pairs.iter().map(|p| p.1).collect();
    divisors.sort_unstable();
    divisors.dedup();
    for d in divisors {
        let uniforms = [d, 0, 0, 0];
        let prepared = k.prepare(&uniforms, &NoTextures);
        let dividends: Vec<u32> = pairs.iter().filter(|p| p.1 == d).map(|p| p.0).collect();
        for chunk in dividends.chunks(LANES) {
            for with_pool in [false, true] {
                let mut b = Batch::for_kernel(&k, 0xffff);
                for (l, &a) in chunk.iter().enumerate() {
                    b.inputs[x as usize][l] = f32::from_bits(a);
                }
                k.jit.get(&k.code, true);
                let prepared = with_pool.then_some(&prepared);
                crate::dispatch::run_on(
                    Variant::Jit,
                    &k,
                    &k.code,
                    &mut b,
                    &uniforms,
                    &NoTextures,
                    prepared,
                )
                .unwrap();
                assert!(matches!(k.native_code(), Some(Ok(_))));
                for (l, &a) in chunk.iter().enumerate() {
                    let got = outs.map(|r| b.outputs[r as usize][l].to_bits());
                    assert_eq!(
                        got,
                        lane_divisions(a, d),
                        "{a:#x} by {d:#x} (pool {with_pool})"
                    );
                }
            }
        }
    }
}

/// Native code runs under DAZ only where it relies on it in many places:
/// a palette lookup (a few float uniform words) runs without it, a
/// shader of float arithmetic and a math helper with it; both give the
/// interpreter's bits.
#[test]
fn only_float_heavy_code_runs_under_daz() {
    if !crate::supported_variants().contains(&Variant::Jit) {
        return;
    }
    let palette = super::kernel(
        glsl::ir::Stage::Fragment,
        "#version 330
        layout(std140) uniform Palette { vec4 colours[64]; };
        uniform int layer;
        flat in int index;
        out vec4 frag;
        void main() { frag = vec4(colours[(index ^ layer) & 63].rgb, 0.25); }",
    );
    let float = super::kernel(
        glsl::ir::Stage::Fragment,
        "#version 330
        uniform vec4 scale;
        in vec4 v;
        out vec4 frag;
        void main() {
            vec4 x = v * scale + vec4(1e-38);
            frag = pow(abs(x), vec4(1.5)) * x.wzyx - x * x * 0.5 + normalize(x) * length(x.xyz);
        }",
    );
    let daz = crate::jit::daz();
    for (k, want) in [(&palette, false), (&float, daz)] {
        let u: Vec<u32> = (0..k.interface().uniform_words)
            .map(|i| (i as u32).wrapping_mul(0x2f3b_5a11) & 0x80ff_ffff)
            .collect();
        for round in 0..8u32 {
            let mut base = Batch::for_kernel(k, 0xffff);
            super::variants::fill(&mut base, round + 5);
            let mut want_out = base.clone();
            assert_eq!(k.run_reference(&mut want_out, &u, &NoTextures), Ok(()));
            let mut got = base.clone();
            assert_eq!(
                k.run_variant(Variant::Jit, &mut got, &u, &NoTextures),
                Ok(())
            );
            assert_eq!(
                bits_of(&got.outputs),
                bits_of(&want_out.outputs),
                "round {round}"
            );
        }
        assert_eq!(k.jit.runs_under_daz(), Some(want));
    }
}
