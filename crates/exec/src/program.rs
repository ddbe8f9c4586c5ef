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
//!
//! Each op's operands are declared once, with what the op does with each
//! (`define_ops!`): the analyses (validation, liveness, the optimizer)
//! walk them through [`Op::for_each_operand`] and its siblings rather than
//! naming every op. What the lane-wise ops compute is in `lane::match_op!`.

use crate::memory::AtomicOp;
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
    Sinh,
    Cosh,
    Tanh,
    Asinh,
    Acosh,
    Atanh,
    Trunc,
    Round,
    RoundEven,
    /// The fraction `modf` returns (`glsl::math::modf_fract`).
    ModfFract,
    /// `intBitsToFloat`: the bits as they are, a subnormal flushed.
    FlushBits,
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
            F1::Sinh => m::sinh(x),
            F1::Cosh => m::cosh(x),
            F1::Tanh => m::tanh(x),
            F1::Asinh => m::asinh(x),
            F1::Acosh => m::acosh(x),
            F1::Atanh => m::atanh(x),
            F1::Trunc => m::trunc(x),
            F1::Round => m::round(x),
            F1::RoundEven => m::round_even(x),
            F1::ModfFract => m::modf_fract(x),
            F1::FlushBits => x,
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

/// What an op is, for the analyses: the flag each row of `define_ops!`
/// starts with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Class {
    /// Computes every lane from its register operands alone (no mask, no
    /// other lanes, no ranges, no side tables): may run in the prologue.
    Pure,
    /// Any other op on registers (masked writes, ranges, other lanes,
    /// side tables, the hook).
    Data,
    /// Changes the mask, the pc or the run's counters: always needed.
    Control,
}

/// How an op uses a register operand.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Role {
    /// Written on every lane.
    Def,
    /// Read, then written on every lane (an accumulator).
    Acc,
    /// Written on the lanes of the current mask only.
    Masked,
    /// Read.
    Read,
}

/// Declares [`Op`] from one row per variant: its class ([`Class`]), its
/// fields, and the role of each field (`= role`):
/// - `imm`: not a register;
/// - `def`, `acc`, `masked`, `read`: one register, in that [`Role`];
/// - `defs(n)`, `reads(n)`: the `n` registers from there (`n` a field);
/// - `span(max)`: read, the `max + 1` registers from there;
/// - `masked_span(max)`: written under the mask, `max + 1` registers;
/// - `reads4(n)`: an array of 4 registers of which the first `n` are read;
/// - `target`: not a register, the index of the op it may jump to.
///
/// Generates the enum, [`Op::class`], [`Op::for_each_operand`] (every
/// register operand, ranges included), [`Op::for_each_single_mut`] (the
/// single-register operands, to rename them) and [`Op::target_mut`]: what
/// the validator, liveness, the optimizer and the slicer know about the
/// shape of each op.
macro_rules! define_ops {
    ($(
        $(#[$meta:meta])*
        $class:ident $name:ident $({ $($field:ident: $ty:ty = $role:ident $(($arg:ident))?),* $(,)? })?,
    )*) => {
        #[derive(Clone, Copy, Debug)]
        pub(crate) enum Op {
            $($(#[$meta])* $name $({ $($field: $ty),* })?,)*
        }

        impl Op {
            pub(crate) fn class(&self) -> Class {
                match self {
                    $(Op::$name { .. } => Class::$class,)*
                }
            }

            /// Calls `f` on every register operand with its role and the
            /// number of registers it addresses from there.
            #[allow(unused_variables)]
            pub(crate) fn for_each_operand(&self, f: &mut dyn FnMut(Role, Reg, u32)) {
                match *self {
                    $(Op::$name $({ $($field),* })? => {
                        $($(operand!(f, $field, $role $(($arg))?);)*)?
                    })*
                }
            }

            /// Calls `f` on every operand naming one register (not the
            /// ranges), which it may change.
            #[allow(unused_variables)]
            pub(crate) fn for_each_single_mut(&mut self, f: &mut dyn FnMut(Role, &mut Reg)) {
                match self {
                    $(Op::$name $({ $($field),* })? => {
                        $($(operand_mut!(f, $field, $role $(($arg))?);)*)?
                    })*
                }
            }

            /// The index of the op it may jump to (a jump, conditional
            /// jump or call), to change.
            #[allow(unused_variables)]
            pub(crate) fn target_mut(&mut self) -> Option<&mut u32> {
                match self {
                    $(Op::$name $({ $($field),* })? => {
                        $($(target!($field, $role);)*)?
                    })*
                }
                None
            }
        }
    };
}

macro_rules! operand {
    ($f:ident, $x:ident, imm) => {};
    ($f:ident, $x:ident, target) => {};
    ($f:ident, $x:ident, def) => {
        $f(Role::Def, $x, 1)
    };
    ($f:ident, $x:ident, acc) => {
        $f(Role::Acc, $x, 1)
    };
    ($f:ident, $x:ident, masked) => {
        $f(Role::Masked, $x, 1)
    };
    ($f:ident, $x:ident, read) => {
        $f(Role::Read, $x, 1)
    };
    ($f:ident, $x:ident, defs($n:ident)) => {
        $f(Role::Def, $x, $n as u32)
    };
    ($f:ident, $x:ident, reads($n:ident)) => {
        $f(Role::Read, $x, $n as u32)
    };
    ($f:ident, $x:ident, span($m:ident)) => {
        $f(Role::Read, $x, $m.saturating_add(1))
    };
    ($f:ident, $x:ident, masked_span($m:ident)) => {
        $f(Role::Masked, $x, $m.saturating_add(1))
    };
    ($f:ident, $x:ident, reads4($n:ident)) => {
        for r in $x.iter().take(($n as usize).min(4)) {
            $f(Role::Read, *r, 1)
        }
    };
}

macro_rules! target {
    ($x:ident, target) => {
        return Some($x)
    };
    ($x:ident, $other:ident) => {};
}

macro_rules! operand_mut {
    ($f:ident, $x:ident, def) => {
        $f(Role::Def, $x)
    };
    ($f:ident, $x:ident, acc) => {
        $f(Role::Acc, $x)
    };
    ($f:ident, $x:ident, masked) => {
        $f(Role::Masked, $x)
    };
    ($f:ident, $x:ident, read) => {
        $f(Role::Read, $x)
    };
    ($f:ident, $x:ident, reads4($n:ident)) => {
        for r in $x.iter_mut().take((*$n as usize).min(4)) {
            $f(Role::Read, r)
        }
    };
    ($f:ident, $x:ident, $other:ident $(($arg:ident))?) => {};
}

define_ops! {
    /// `d = bits` on every lane.
    Pure Const { d: Reg = def, bits: u32 = imm },
    /// `d = a` on every lane.
    Pure Mov { d: Reg = def, a: Reg = read },
    /// `d = a` on the lanes of the current mask.
    Data Store { d: Reg = masked, a: Reg = read },
    /// `d = uniforms[word]` on every lane (0 past the end of the words);
    /// a `float` word's subnormal is read as zero.
    Pure Uniform { d: Reg = def, word: u32 = imm, float: bool = imm },

    Pure FAdd { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure FSub { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure FMul { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure FDiv { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure FNeg { d: Reg = def, a: Reg = read },
    /// `d = d + a * b`, two roundings (never fused).
    Data FMac { d: Reg = acc, a: Reg = read, b: Reg = read },
    /// `d = a[n−1]·b[n−1]`, then `d += a[k]·b[k]` for `k` from `n − 2`
    /// down to 0 (`n` in 1..=4), each product and sum rounded and flushed:
    /// the sum of a GLSL `dot` in the order Mesa's compiler reduces it
    /// (last component first; `glsl::math::dot`).
    Pure Dot { d: Reg = def, n: u8 = imm, a: [Reg; 4] = reads4(n), b: [Reg; 4] = reads4(n) },
    Pure F1 { f: F1 = imm, d: Reg = def, a: Reg = read },
    Pure F2 { f: F2 = imm, d: Reg = def, a: Reg = read, b: Reg = read },
    Pure F3 { f: F3 = imm, d: Reg = def, a: Reg = read, b: Reg = read, c: Reg = read },
    Pure FLt { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure FLe { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure FEq { d: Reg = def, a: Reg = read, b: Reg = read },

    Pure IAdd { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure ISub { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure IMul { d: Reg = def, a: Reg = read, b: Reg = read },
    /// Wrapping division; division by zero gives 0.
    Pure IDiv { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure INeg { d: Reg = def, a: Reg = read },
    Pure ILt { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure ILe { d: Reg = def, a: Reg = read, b: Reg = read },
    /// Bit equality (ints, uints, bools, samplers).
    Pure IEq { d: Reg = def, a: Reg = read, b: Reg = read },
    /// Unsigned division; division by zero gives 0.
    Pure UDiv { d: Reg = def, a: Reg = read, b: Reg = read },
    /// Signed remainder (of the truncating division: the dividend's sign;
    /// `i32::MIN % -1` is 0); by zero gives 0.
    Pure IMod { d: Reg = def, a: Reg = read, b: Reg = read },
    /// Unsigned remainder; by zero gives 0.
    Pure UMod { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure ULt { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure ULe { d: Reg = def, a: Reg = read, b: Reg = read },
    /// `a << (b mod 32)`.
    Pure Shl { d: Reg = def, a: Reg = read, b: Reg = read },
    /// `a >> (b mod 32)`, sign-extending (int).
    Pure ShrS { d: Reg = def, a: Reg = read, b: Reg = read },
    /// `a >> (b mod 32)`, zero-extending (uint).
    Pure ShrU { d: Reg = def, a: Reg = read, b: Reg = read },
    /// Bitwise and, or, xor, not of the 32 bits (the ops below them,
    /// `And`...`Not`, are the logical ones of bools).
    Pure BitAnd { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure BitOr { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure BitXor { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure BitNot { d: Reg = def, a: Reg = read },

    Pure And { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure Or { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure Xor { d: Reg = def, a: Reg = read, b: Reg = read },
    Pure Not { d: Reg = def, a: Reg = read },

    /// float→int: truncation; NaN → 0; out of range saturates.
    Pure FToI { d: Reg = def, a: Reg = read },
    Pure IToF { d: Reg = def, a: Reg = read },
    /// float→uint: truncation; NaN and negative values → 0; from 2^32 on
    /// `u32::MAX` (`glsl::consteval::float_to_uint`).
    Pure FToU { d: Reg = def, a: Reg = read },
    /// uint→float, rounded to nearest even.
    Pure UToF { d: Reg = def, a: Reg = read },
    Pure FToB { d: Reg = def, a: Reg = read },
    Pure IToB { d: Reg = def, a: Reg = read },
    Pure BToF { d: Reg = def, a: Reg = read },

    /// `d = c != 0 ? a : b` per lane.
    Pure Select { d: Reg = def, c: Reg = read, a: Reg = read, b: Reg = read },

    /// `d = clamp(a as i32, 0, max) * stride` (a dynamic index made safe:
    /// out-of-range indices select the nearest element).
    Pure ClampIdx { d: Reg = def, a: Reg = read, max: u32 = imm, stride: u32 = imm },
    /// `d = r[base + min(off, max)]` per lane.
    Data Gather { d: Reg = def, base: Reg = span(max), off: Reg = read, max: u32 = imm },
    /// `r[base + min(off, max)] = a` on the lanes of the current mask.
    Data Scatter { base: Reg = masked_span(max), off: Reg = read, max: u32 = imm, a: Reg = read },
    /// `d = uniforms[word + min(off, max)]` per lane; `float` as for
    /// [`Op::Uniform`] (the words `word + k * stride` are elements of one
    /// array, all of one kind).
    Pure GatherUniform {
        d: Reg = def,
        word: u32 = imm,
        off: Reg = read,
        max: u32 = imm,
        float: bool = imm,
    },

    /// `d = a(lane | 1) - a(lane & !1)`.
    Data DdX { d: Reg = def, a: Reg = read },
    /// `d = a(lane | 2) - a(lane & !2)`.
    Data DdY { d: Reg = def, a: Reg = read },
    /// `noiseN` of the `dims` consecutive registers at `a` into `n`
    /// consecutive registers at `d`.
    Data Noise { d: Reg = defs(n), n: u8 = imm, a: Reg = reads(dims), dims: u8 = imm },
    /// A texture lookup described by `Program::textures[index]` (its
    /// registers are there, not operands here).
    Data Texture { index: u32 = imm },
    /// `d = ` the word at byte `addr` of memory `space` ([`crate::Memory`])
    /// on the lanes of the current mask, one lane after the other; 0 on
    /// the others.
    Data Load { d: Reg = def, space: Reg = read, addr: Reg = read },
    /// The word at byte `addr` of memory `space` `= a` on the lanes of
    /// the current mask, in lane order.
    Data StoreMem { space: Reg = read, addr: Reg = read, a: Reg = read },
    /// An atomic `f` on the word at byte `addr` of memory `space` with
    /// data `a` (and `b`, `atomicCompSwap`'s), on the lanes of the current
    /// mask in lane order; `d =` the old value there (0 on the others).
    Data Atomic { f: AtomicOp = imm, d: Reg = def, space: Reg = read, addr: Reg = read, a: Reg = read, b: Reg = read },
    /// `d = ` the size in bytes of memory `space`'s buffer.
    Data MemSize { d: Reg = def, space: Reg = read },
    /// `barrier()` of a compute shader ([`crate::Memory::barrier`]).
    Data Barrier,
    /// `debugPrintfEXT` described by `Program::printfs[index]`: reported
    /// to the run's hook for the lanes of the current mask (no effect on
    /// the registers).
    Data Printf { index: u32 = imm },

    /// `masks[slot] = cur`.
    Control SaveMask { slot: u32 = imm },
    /// `cur = masks[slot]`.
    Control RestoreMask { slot: u32 = imm },
    /// `cur &= (c != 0)`.
    Control AndMask { c: Reg = read },
    /// `cur = masks[slot] & (c == 0)`.
    Control AndNotMask { slot: u32 = imm, c: Reg = read },
    /// Jump when no lane is active.
    Control JumpIfNone { target: u32 = target },
    Control Jump { target: u32 = target },
    /// One loop iteration: counts against the loop budget.
    Control LoopIter,
    /// Removes the active lanes from the mask slots
    /// `kill_slots[start..end]`, then `cur = 0` (break, continue, return).
    Control Kill { start: u32 = imm, end: u32 = imm },
    /// `discarded |= cur`, then like [`Op::Kill`].
    Control Discard { start: u32 = imm, end: u32 = imm },
    /// Subroutine call: `return_address[slot] = pc + 1`, jump to `target`.
    Control Call { target: u32 = target, slot: u32 = imm },
    /// Jump to `return_address[slot]`.
    Control Ret { slot: u32 = imm },
    /// After a subroutine call: removes the discarded lanes from `cur` and
    /// from the mask slots `kill_slots[start..end]`.
    Control SyncDiscard { start: u32 = imm, end: u32 = imm },
}

impl Op {
    /// Reads or writes memory shared between invocations
    /// ([`crate::Memory`]), or waits at a barrier.
    pub(crate) fn touches_memory(&self) -> bool {
        matches!(
            self,
            Op::Load { .. }
                | Op::StoreMem { .. }
                | Op::Atomic { .. }
                | Op::MemSize { .. }
                | Op::Barrier
        )
    }
}

impl Program {
    /// Whether some op writes memory ([`Op::writes_memory`]).
    pub(crate) fn writes_memory(&self) -> bool {
        self.ops.iter().any(|op| op.writes_memory())
    }

    /// Whether some op is `barrier()`.
    pub(crate) fn calls_barrier(&self) -> bool {
        self.ops.iter().any(|op| matches!(op, Op::Barrier))
    }
}

impl Op {
    /// Writes memory shared between invocations (what a fragment batch's
    /// helper lanes must not do).
    pub(crate) fn writes_memory(&self) -> bool {
        matches!(self, Op::StoreMem { .. } | Op::Atomic { .. })
    }
}

/// How a texture lookup chooses its level of detail.
#[derive(Clone, Copy, Debug)]
pub(crate) enum TexLod {
    /// Fragment stage: derivatives of the coordinates, plus a bias.
    Implicit { bias: Option<Reg> },
    /// An explicit level (`*Lod` functions; 0 for other vertex-stage
    /// lookups). For fetches and size queries, an integer level.
    Explicit(Option<Reg>),
    /// `textureGrad`: the derivatives along x and y of the (divided)
    /// coordinates, `dims` of each used.
    Grad { ddx: [Reg; 3], ddy: [Reg; 3] },
}

/// What a texture op computes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum TexKind {
    /// A filtered lookup (float coordinates).
    Sample,
    /// `texelFetch`: `coord` holds integer coordinates.
    Fetch,
    /// `textureSize`: the level's sizes as integers.
    Size,
}

#[derive(Clone, Copy, Debug)]
pub(crate) struct TexOp {
    pub kind: TexKind,
    pub target: SamplerKind,
    /// Register holding the texture unit.
    pub unit: Reg,
    /// s, t, r, q after the projective divide.
    pub coord: [Reg; 4],
    /// How many of `coord` vary (for the derivatives): 1, 2 or 3.
    pub dims: u8,
    pub compare: Option<Reg>,
    pub lod: TexLod,
    /// Integer texel offsets of the `*Offset` forms (unused ones hold 0).
    pub offset: Option<[Reg; 3]>,
    /// A 1.30 lookup on a shadow sampler ([`crate::SampleRequest`]'s
    /// `compare_only`).
    pub compare_only: bool,
    /// First of 4 consecutive result registers.
    pub d: Reg,
}

impl TexOp {
    /// The register holding an explicit level (a fetch's or a size
    /// query's; none: level 0, as for every other kind of level).
    pub(crate) fn level(&self) -> Option<Reg> {
        match self.lod {
            TexLod::Explicit(l) => l,
            _ => None,
        }
    }

    /// Whether the unit and the explicit level (if any) are registers from
    /// `base` on (the pool's: the same value on every lane for a whole
    /// run).
    pub(crate) fn unit_and_level_from(&self, base: Reg) -> bool {
        matches!(self.lod, TexLod::Explicit(_))
            && self.unit >= base
            && self.level().is_none_or(|l| l >= base)
    }

    /// Replaces every register the op reads by `f` of it.
    pub(crate) fn map_reads(&mut self, mut f: impl FnMut(Reg) -> Reg) {
        self.unit = f(self.unit);
        self.coord = self.coord.map(&mut f);
        self.compare = self.compare.map(&mut f);
        self.lod = match self.lod {
            TexLod::Implicit { bias } => TexLod::Implicit {
                bias: bias.map(&mut f),
            },
            TexLod::Explicit(l) => TexLod::Explicit(l.map(&mut f)),
            TexLod::Grad { ddx, ddy } => TexLod::Grad {
                ddx: ddx.map(&mut f),
                ddy: ddy.map(&mut f),
            },
        };
        self.offset = self.offset.map(|o| o.map(&mut f));
    }

    /// Every register the op reads.
    pub(crate) fn reads(&self) -> Vec<Reg> {
        let mut r = vec![self.unit];
        r.extend(self.coord);
        r.extend(self.compare);
        match self.lod {
            TexLod::Implicit { bias: b } | TexLod::Explicit(b) => r.extend(b),
            TexLod::Grad { ddx, ddy } => {
                r.extend(ddx);
                r.extend(ddy);
            }
        }
        r.extend(self.offset.into_iter().flatten());
        r
    }
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
    /// The index of the op it may jump to (a jump, conditional jump or
    /// call).
    pub(crate) fn target(&self) -> Option<u32> {
        let mut op = *self;
        op.target_mut().copied()
    }

    /// Whether the op ends a basic block: it may jump, or it returns.
    pub(crate) fn ends_block(&self) -> bool {
        self.target().is_some() || matches!(self, Op::Ret { .. })
    }
}

/// Per op, and one past the end: whether it starts a basic block (op 0,
/// every jump or call target and every op after one that ends a block;
/// the end counts as a start).
pub(crate) fn leaders(ops: &[Op]) -> Vec<bool> {
    let n = ops.len();
    let mut leader = vec![false; n + 1];
    leader[0] = true;
    leader[n] = true;
    for (i, op) in ops.iter().enumerate() {
        if let Some(t) = op.target() {
            leader[(t as usize).min(n)] = true;
        }
        if op.ends_block() {
            leader[i + 1] = true;
        }
    }
    leader
}

impl Program {
    /// Checks that every register, mask slot, jump target and side-table
    /// index is in range, so that the interpreter cannot index out of
    /// bounds. Returns a description of the first problem.
    pub fn validate(&self) -> Result<(), String> {
        let nregs = self.registers as u64;
        let reg_ok = |r: Reg, n: u32| (r as u64) + (n.max(1) as u64) <= nregs;
        let mut bad = None;
        for (i, op) in self.ops.iter().enumerate() {
            op.for_each_operand(&mut |_, r, n| {
                if !reg_ok(r, n) && bad.is_none() {
                    bad = Some(format!("op {i} ({op:?}) uses register {r}+{n} of {nregs}"));
                }
            });
            let ok = match *op {
                Op::SaveMask { slot } | Op::RestoreMask { slot } | Op::AndNotMask { slot, .. } => {
                    slot < self.mask_slots
                }
                Op::Call { slot, .. } | Op::Ret { slot } => slot < self.subroutines,
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
                    Some(t) => t.reads().iter().all(|&r| reg_ok(r, 1)) && reg_ok(t.d, 4),
                    None => false,
                },
                Op::Noise { n, dims, .. } => (1..=4).contains(&n) && (1..=4).contains(&dims),
                Op::Dot { n, .. } => (1..=4).contains(&n),
                _ => true,
            };
            let target_ok = op.target().is_none_or(|t| t as usize <= self.ops.len());
            if !(ok && target_ok) && bad.is_none() {
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
    op.class() == Class::Pure
}
