//! The lowered program: a flat list of decoded instructions over a register
//! file of `LANES`-wide registers.
//!
//! Every register holds one scalar component per lane as a `u32` bit pattern
//! (`f32::to_bits` for floats, two's complement for ints, 0/1 for bools, the
//! texture unit for samplers). Instructions name registers by index; the
//! lowering guarantees every index is below [`Program::registers`] (and
//! [`Program::validate`] checks it once, so the interpreter's indexing
//! cannot fail).
//!
//! Data instructions compute every lane unconditionally (temporaries of
//! inactive lanes are computed and never observed); only [`Op::Store`] and
//! [`Op::Scatter`] (writes to variables) respect the current execution mask.
//! Control flow is structured by mask slots: see the `lower` module.

use glsl::types::SamplerKind;
use glsl::Span;

/// A register index.
pub(crate) type Reg = u32;

/// Most registers a program may use (each is `4 * LANES` bytes).
pub const MAX_REGISTERS: u32 = 1 << 18;

/// Most instructions a lowered program may have (after inlining).
pub const MAX_OPS: usize = 1 << 21;

/// A `glsl::math` function of one float.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum F1 {
    Radians,
    Degrees,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Exp,
    Log,
    Exp2,
    Log2,
    Sqrt,
    InverseSqrt,
    Abs,
    Sign,
    Floor,
    Ceil,
    Fract,
}

/// A `glsl::math` function of two floats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum F2 {
    Atan2,
    Pow,
    Mod,
    Min,
    Max,
    Step,
}

/// A `glsl::math` function of three floats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum F3 {
    Clamp,
    Mix,
    SmoothStep,
}

impl F1 {
    /// The scalar function (the reference the executor matches bit for bit).
    pub fn eval(self, x: f32) -> f32 {
        use glsl::math as m;
        match self {
            F1::Radians => m::radians(x),
            F1::Degrees => m::degrees(x),
            F1::Sin => m::sin(x),
            F1::Cos => m::cos(x),
            F1::Tan => m::tan(x),
            F1::Asin => m::asin(x),
            F1::Acos => m::acos(x),
            F1::Atan => m::atan(x),
            F1::Exp => m::exp(x),
            F1::Log => m::log(x),
            F1::Exp2 => m::exp2(x),
            F1::Log2 => m::log2(x),
            F1::Sqrt => m::sqrt(x),
            F1::InverseSqrt => m::inversesqrt(x),
            F1::Abs => m::abs(x),
            F1::Sign => m::sign(x),
            F1::Floor => m::floor(x),
            F1::Ceil => m::ceil(x),
            F1::Fract => m::fract(x),
        }
    }
}

impl F2 {
    pub fn eval(self, x: f32, y: f32) -> f32 {
        use glsl::math as m;
        match self {
            F2::Atan2 => m::atan2(x, y),
            F2::Pow => m::pow(x, y),
            F2::Mod => m::modulo(x, y),
            F2::Min => m::min(x, y),
            F2::Max => m::max(x, y),
            F2::Step => m::step(x, y),
        }
    }
}

impl F3 {
    pub fn eval(self, x: f32, y: f32, z: f32) -> f32 {
        use glsl::math as m;
        match self {
            F3::Clamp => m::clamp(x, y, z),
            F3::Mix => m::mix(x, y, z),
            F3::SmoothStep => m::smoothstep(x, y, z),
        }
    }
}

#[derive(Clone, Copy, Debug)]
pub(crate) enum Op {
    /// `d = bits` on every lane.
    Const {
        d: Reg,
        bits: u32,
    },
    /// `d = a` on every lane.
    Mov {
        d: Reg,
        a: Reg,
    },
    /// `d = a` on the lanes of the current mask.
    Store {
        d: Reg,
        a: Reg,
    },
    /// `d = uniforms[word]` on every lane (0 past the end of the words);
    /// a `float` word's subnormal is read as zero.
    Uniform {
        d: Reg,
        word: u32,
        float: bool,
    },

    FAdd {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    FSub {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    FMul {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    FDiv {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    FNeg {
        d: Reg,
        a: Reg,
    },
    /// `d = d + a * b`, two roundings (never fused).
    FMac {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    /// `d = 0.0`, then `d += a[k] * b[k]` for `k < n` (1..=4), each
    /// product and sum rounded and flushed (an [`Op::FMac`] chain in one
    /// op).
    Dot {
        d: Reg,
        n: u8,
        a: [Reg; 4],
        b: [Reg; 4],
    },
    F1 {
        f: F1,
        d: Reg,
        a: Reg,
    },
    F2 {
        f: F2,
        d: Reg,
        a: Reg,
        b: Reg,
    },
    F3 {
        f: F3,
        d: Reg,
        a: Reg,
        b: Reg,
        c: Reg,
    },
    FLt {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    FLe {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    FEq {
        d: Reg,
        a: Reg,
        b: Reg,
    },

    IAdd {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    ISub {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    IMul {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    /// Wrapping division; division by zero gives 0.
    IDiv {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    INeg {
        d: Reg,
        a: Reg,
    },
    ILt {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    ILe {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    /// Bit equality (ints, bools, samplers).
    IEq {
        d: Reg,
        a: Reg,
        b: Reg,
    },

    And {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    Or {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    Xor {
        d: Reg,
        a: Reg,
        b: Reg,
    },
    Not {
        d: Reg,
        a: Reg,
    },

    FToI {
        d: Reg,
        a: Reg,
    },
    IToF {
        d: Reg,
        a: Reg,
    },
    FToB {
        d: Reg,
        a: Reg,
    },
    IToB {
        d: Reg,
        a: Reg,
    },
    BToF {
        d: Reg,
        a: Reg,
    },

    /// `d = c != 0 ? a : b` per lane.
    Select {
        d: Reg,
        c: Reg,
        a: Reg,
        b: Reg,
    },

    /// `d = clamp(a as i32, 0, max) * stride` (a dynamic index made safe:
    /// out-of-range indices select the nearest element).
    ClampIdx {
        d: Reg,
        a: Reg,
        max: u32,
        stride: u32,
    },
    /// `d = r[base + min(off, max)]` per lane.
    Gather {
        d: Reg,
        base: Reg,
        off: Reg,
        max: u32,
    },
    /// `r[base + min(off, max)] = a` on the lanes of the current mask.
    Scatter {
        base: Reg,
        off: Reg,
        max: u32,
        a: Reg,
    },
    /// `d = uniforms[word + min(off, max)]` per lane; `float` as for
    /// [`Op::Uniform`] (the words `word + k * stride` are elements of one
    /// array, all of one kind).
    GatherUniform {
        d: Reg,
        word: u32,
        off: Reg,
        max: u32,
        float: bool,
    },

    /// `d = a(lane | 1) - a(lane & !1)`.
    DdX {
        d: Reg,
        a: Reg,
    },
    /// `d = a(lane | 2) - a(lane & !2)`.
    DdY {
        d: Reg,
        a: Reg,
    },
    /// `noiseN` of the `dims` consecutive registers at `a` into `n`
    /// consecutive registers at `d`.
    Noise {
        d: Reg,
        n: u8,
        a: Reg,
        dims: u8,
    },
    /// A texture lookup described by `Program::textures[index]`.
    Texture {
        index: u32,
    },
    /// `debugPrintfEXT` described by `Program::printfs[index]`: reported
    /// to the run's hook for the lanes of the current mask (no effect on
    /// the registers).
    Printf {
        index: u32,
    },

    /// `masks[slot] = cur`.
    SaveMask {
        slot: u32,
    },
    /// `cur = masks[slot]`.
    RestoreMask {
        slot: u32,
    },
    /// `cur &= (c != 0)`.
    AndMask {
        c: Reg,
    },
    /// `cur = masks[slot] & (c == 0)`.
    AndNotMask {
        slot: u32,
        c: Reg,
    },
    /// Jump when no lane is active.
    JumpIfNone {
        target: u32,
    },
    Jump {
        target: u32,
    },
    /// One loop iteration: counts against the loop budget.
    LoopIter,
    /// Removes the active lanes from the mask slots
    /// `kill_slots[start..end]`, then `cur = 0` (break, continue, return).
    Kill {
        start: u32,
        end: u32,
    },
    /// `discarded |= cur`, then like [`Op::Kill`].
    Discard {
        start: u32,
        end: u32,
    },
    /// Subroutine call: `return_address[slot] = pc + 1`, jump to `target`.
    Call {
        target: u32,
        slot: u32,
    },
    /// Jump to `return_address[slot]`.
    Ret {
        slot: u32,
    },
    /// After a subroutine call: removes the discarded lanes from `cur` and
    /// from the mask slots `kill_slots[start..end]`.
    SyncDiscard {
        start: u32,
        end: u32,
    },
}

/// How a texture lookup chooses its level of detail.
#[derive(Clone, Copy, Debug)]
pub(crate) enum TexLod {
    /// Fragment stage: derivatives of the coordinates, plus a bias.
    Implicit { bias: Option<Reg> },
    /// An explicit level (`*Lod` functions; 0 for other vertex-stage
    /// lookups).
    Explicit(Option<Reg>),
}

#[derive(Clone, Copy, Debug)]
pub(crate) struct TexOp {
    pub target: SamplerKind,
    /// Register holding the texture unit.
    pub unit: Reg,
    /// s, t, r, q after the projective divide.
    pub coord: [Reg; 4],
    /// How many of `coord` vary (for the derivatives): 1, 2 or 3.
    pub dims: u8,
    pub compare: Option<Reg>,
    pub lod: TexLod,
    /// First of 4 consecutive result registers.
    pub d: Reg,
}

/// Where a statement of the source starts in the op list (for traces).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StatementMark {
    /// Index of the statement's first op.
    pub op: u32,
    pub span: Span,
}

/// A named variable's registers (for a debugger).
#[derive(Clone, Debug, PartialEq)]
pub struct VarInfo {
    pub name: String,
    pub ty: glsl::types::Type,
    pub first_register: u32,
    pub registers: u32,
}

#[derive(Clone, Debug, Default)]
pub(crate) struct Program {
    pub ops: Vec<Op>,
    pub textures: Vec<TexOp>,
    pub kill_slots: Vec<u32>,
    pub registers: u32,
    pub mask_slots: u32,
    /// Number of subroutines (return-address slots).
    pub subroutines: u32,
    /// Registers set before the first op (constant initializers).
    pub init: Vec<(Reg, u32)>,
    pub statements: Vec<StatementMark>,
    pub vars: Vec<VarInfo>,
    /// The `debugPrintfEXT` calls.
    pub printfs: Vec<PrintfSite>,
}

/// One `debugPrintfEXT` call: its format and the registers of its
/// arguments' components, in order.
#[derive(Clone, Debug)]
pub(crate) struct PrintfSite {
    pub format: Vec<glsl::printf::Piece>,
    pub args: Vec<Reg>,
    pub span: Span,
}

impl Op {
    /// Calls `f` on every register operand, with the number of registers
    /// the operand may address from there (more than 1 for gathers).
    pub(crate) fn for_each_reg(&self, f: &mut dyn FnMut(Reg, u32)) {
        use Op::*;
        match *self {
            Const { d, .. } | Uniform { d, .. } => f(d, 1),
            Mov { d, a }
            | Store { d, a }
            | FNeg { d, a }
            | INeg { d, a }
            | Not { d, a }
            | FToI { d, a }
            | IToF { d, a }
            | FToB { d, a }
            | IToB { d, a }
            | BToF { d, a }
            | DdX { d, a }
            | DdY { d, a }
            | F1 { d, a, .. } => {
                f(d, 1);
                f(a, 1)
            }
            FAdd { d, a, b }
            | FSub { d, a, b }
            | FMul { d, a, b }
            | FDiv { d, a, b }
            | FMac { d, a, b }
            | F2 { d, a, b, .. }
            | FLt { d, a, b }
            | FLe { d, a, b }
            | FEq { d, a, b }
            | IAdd { d, a, b }
            | ISub { d, a, b }
            | IMul { d, a, b }
            | IDiv { d, a, b }
            | ILt { d, a, b }
            | ILe { d, a, b }
            | IEq { d, a, b }
            | And { d, a, b }
            | Or { d, a, b }
            | Xor { d, a, b } => {
                f(d, 1);
                f(a, 1);
                f(b, 1)
            }
            F3 { d, a, b, c, .. } | Select { d, c, a, b } => {
                f(d, 1);
                f(a, 1);
                f(b, 1);
                f(c, 1)
            }
            ClampIdx { d, a, .. } => {
                f(d, 1);
                f(a, 1)
            }
            Gather { d, base, off, max } => {
                f(d, 1);
                f(off, 1);
                f(base, max.saturating_add(1))
            }
            Scatter { base, off, max, a } => {
                f(a, 1);
                f(off, 1);
                f(base, max.saturating_add(1))
            }
            GatherUniform { d, off, .. } => {
                f(d, 1);
                f(off, 1)
            }
            Noise { d, n, a, dims } => {
                f(d, n as u32);
                f(a, dims as u32)
            }
            Dot { d, n, a, b } => {
                f(d, 1);
                for k in 0..(n as usize).min(4) {
                    f(a[k], 1);
                    f(b[k], 1);
                }
            }
            AndMask { c } | AndNotMask { c, .. } => f(c, 1),
            Texture { .. }
            | Printf { .. }
            | SaveMask { .. }
            | RestoreMask { .. }
            | JumpIfNone { .. }
            | Jump { .. }
            | LoopIter
            | Kill { .. }
            | Discard { .. }
            | Call { .. }
            | Ret { .. }
            | SyncDiscard { .. } => {}
        }
    }
}

impl Program {
    /// Checks that every register, mask slot, jump target and side-table
    /// index is in range, so that the interpreter cannot index out of
    /// bounds. Returns a description of the first problem.
    pub fn validate(&self) -> Result<(), String> {
        let nregs = self.registers as u64;
        let reg_ok = |r: Reg, n: u32| (r as u64) + (n.max(1) as u64) <= nregs;
        let opt_ok = |r: Option<Reg>| match r {
            Some(r) => reg_ok(r, 1),
            None => true,
        };
        let mut bad = None;
        for (i, op) in self.ops.iter().enumerate() {
            op.for_each_reg(&mut |r, n| {
                if !reg_ok(r, n) && bad.is_none() {
                    bad = Some(format!("op {i} ({op:?}) uses register {r}+{n} of {nregs}"));
                }
            });
            let ok = match *op {
                Op::SaveMask { slot } | Op::RestoreMask { slot } | Op::AndNotMask { slot, .. } => {
                    slot < self.mask_slots
                }
                Op::JumpIfNone { target } | Op::Jump { target } => {
                    target as usize <= self.ops.len()
                }
                Op::Call { target, slot } => {
                    target as usize <= self.ops.len() && slot < self.subroutines
                }
                Op::Ret { slot } => slot < self.subroutines,
                Op::Kill { start, end }
                | Op::Discard { start, end }
                | Op::SyncDiscard { start, end } => {
                    start <= end
                        && (end as usize) <= self.kill_slots.len()
                        && self.kill_slots[start as usize..end as usize]
                            .iter()
                            .all(|&s| s < self.mask_slots)
                }
                Op::Printf { index } => match self.printfs.get(index as usize) {
                    Some(site) => site.args.iter().all(|&r| reg_ok(r, 1)),
                    None => false,
                },
                Op::Texture { index } => match self.textures.get(index as usize) {
                    Some(t) => {
                        reg_ok(t.unit, 1)
                            && t.coord.iter().all(|&c| reg_ok(c, 1))
                            && opt_ok(t.compare)
                            && match t.lod {
                                TexLod::Implicit { bias: b } | TexLod::Explicit(b) => opt_ok(b),
                            }
                            && reg_ok(t.d, 4)
                    }
                    None => false,
                },
                Op::Noise { n, dims, .. } => (1..=4).contains(&n) && (1..=4).contains(&dims),
                Op::Dot { n, .. } => (1..=4).contains(&n),
                _ => true,
            };
            if !ok && bad.is_none() {
                bad = Some(format!("op {i} ({op:?}) is out of range"));
            }
        }
        for &(r, _) in &self.init {
            if !reg_ok(r, 1) && bad.is_none() {
                bad = Some(format!("initializer of register {r} out of range"));
            }
        }
        match bad {
            Some(b) => Err(b),
            None => Ok(()),
        }
    }
}

/// Ops that compute every lane from their register operands alone (no
/// mask, no other lanes, no ranges), so they may run in the prologue.
pub(crate) fn pure(op: &Op) -> bool {
    !matches!(
        op,
        Op::Store { .. }
            | Op::Scatter { .. }
            | Op::Gather { .. }
            | Op::Noise { .. }
            | Op::Texture { .. }
            | Op::Printf { .. }
            | Op::DdX { .. }
            | Op::DdY { .. }
            | Op::FMac { .. }
            | Op::SaveMask { .. }
            | Op::RestoreMask { .. }
            | Op::AndMask { .. }
            | Op::AndNotMask { .. }
            | Op::JumpIfNone { .. }
            | Op::Jump { .. }
            | Op::LoopIter
            | Op::Kill { .. }
            | Op::Discard { .. }
            | Op::Call { .. }
            | Op::Ret { .. }
            | Op::SyncDiscard { .. }
    )
}
