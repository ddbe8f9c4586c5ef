//! Bounds on what a fragment kernel writes to `gl_FragDepth` over a region
//! of the window, before running it: the renderer rejects the fragments
//! whose every possible depth fails the depth test (a sphere impostor
//! behind the surface already drawn) without shading them.
//!
//! The bound is computed by affine arithmetic: every value is a form
//! `c + gx·u + gy·v ± err` in the region's coordinates `u, v ∈ [−1, 1]`
//! (the pixel position mapped linearly), which holds the value the
//! executor computes at every pixel of the region. Interpolated inputs are
//! affine in the pixel position, so the forms keep what plain intervals
//! lose: that the components of one ray vary together, and `b² − |c|²`
//! of a ray-sphere test cancels instead of spreading. Products keep their
//! quadratic part as error; division and square root are replaced by
//! their best linear approximation over the operand's range plus its
//! largest deviation (Chebyshev); every op adds the f32 rounding and
//! subnormal flush of the executor's result (`2⁻²⁴·|x| + 2⁻¹²⁶`) and the
//! f64 arithmetic of the coefficients adds `2⁻⁵⁰` of the magnitudes, so
//! the form is rigorous for the executor's bits (`crate` docs,
//! "Semantics"), not only for real arithmetic.
//!
//! ## Contract
//! - [`Kernel::depth_range`] accepts a kernel whose ops are float
//!   arithmetic (`+ − × ÷`, negation, multiply-add, dot products, `sqrt`,
//!   `inversesqrt`, `abs`, `min`, `max`, `clamp`, `mix`), comparisons,
//!   selects, copies, constants and uniform words, under `if`s and
//!   `discard`s (masks and forward jumps: no loops, calls or early
//!   returns), and that writes `gl_FragDepth`; any other kernel gives
//!   `None`.
//! - [`DepthRange::eval`] gives `[lo, hi]` such that every fragment of the
//!   region that is not discarded writes a `gl_FragDepth` in it (a finite
//!   f32), given input forms that hold the inputs at every pixel of the
//!   region. `None` when some value may be infinite or NaN (a division by a
//!   range holding zero, a square root of a range reaching below zero,
//!   magnitudes near f32's largest), or an input has no form.
//! - A register written in a block that a jump may skip, or under a mask
//!   that may not hold every lane, is the hull of its values before and
//!   after. A `discard` under one comparison `a < b` (or `a ≤ b`) leaves
//!   the lanes where it is false, and narrows `a` and `b` for the ops
//!   after it: that is how a square root after `if (d < 0.0) discard;`
//!   stays defined.

use crate::program::{Op, Reg, Role, F1, F2, F3};
use crate::Kernel;
use glsl::math::flush_denormal;
use std::sync::Arc;

/// The relative error of rounding a real to the nearest f32.
const F32_REL: f64 = 1.0 / 16_777_216.0;
/// The largest change flushing makes: subnormals are below 2⁻¹²⁶.
const FLUSH: f64 = f32::MIN_POSITIVE as f64;
/// The relative error allowed for the f64 arithmetic of the coefficients
/// (a few operations of 2⁻⁵³ each).
const F64_REL: f64 = 1.0 / (1u64 << 50) as f64;
/// Magnitudes from which a value might overflow f32 in the next op.
const LIMIT: f64 = 1.0e30;

/// Whether a magnitude `m` stays clear of f32's overflow (`false` for NaN).
#[inline(always)]
fn fits(m: f64) -> bool {
    m < LIMIT
}

/// A value over a region: `c + gx·u + gy·v ± err` for `u, v ∈ [−1, 1]`
/// (see the module docs), and at least `lo` (a sign the form cannot
/// show: a square, a product or sum of such, what a `discard` kept).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Affine {
    pub c: f64,
    pub gx: f64,
    pub gy: f64,
    pub err: f64,
    lo: f64,
}

impl Affine {
    /// The value `v` everywhere, exactly, as a run reads it (a subnormal
    /// flushed): also its own lower bound, so that a sum of constants
    /// and squares (`dot(v, v)` with a constant component, in whatever
    /// order) stays known to be at least zero.
    #[inline]
    pub fn exact(v: f32) -> Affine {
        let c = flush_denormal(v) as f64;
        Affine {
            lo: if c.is_nan() { f64::NEG_INFINITY } else { c },
            ..Affine::new(c, 0.0, 0.0, 0.0)
        }
    }

    #[inline]
    pub fn new(c: f64, gx: f64, gy: f64, err: f64) -> Affine {
        Affine {
            c,
            gx,
            gy,
            err,
            lo: f64::NEG_INFINITY,
        }
    }

    /// The form, known to be at least zero when `nonneg`.
    #[inline(always)]
    fn nonneg_if(mut self, nonneg: bool) -> Affine {
        if nonneg {
            self.lo = self.lo.max(0.0);
        }
        self
    }

    /// Whether the form is known to be at least zero.
    #[inline(always)]
    fn nonneg(&self) -> bool {
        self.lo >= 0.0
    }

    /// Every value in `[lo, hi]`, without correlation with the position:
    /// `c ± err` with `c − err ≤ lo` and `c + err ≥ hi` in real numbers.
    pub fn interval(lo: f64, hi: f64) -> Affine {
        let c = 0.5 * lo + 0.5 * hi;
        let err = (hi - c).max(c - lo);
        Affine::new(c, 0.0, 0.0, if err > 0.0 { err.next_up() } else { err })
    }

    /// The executor's `a + b` of values within `a` and `b` (rounded to
    /// f32 and flushed), or `None` if it may overflow.
    #[inline]
    pub fn add_f32(a: Affine, b: Affine) -> Option<Affine> {
        fadd(a, b)
    }

    /// The executor's `a · b`.
    #[inline]
    pub fn mul_f32(a: Affine, b: Affine) -> Option<Affine> {
        fmul(a, b)
    }

    /// The executor's `a / b`, or `None` if `b` may be zero.
    #[inline]
    pub fn div_f32(a: Affine, b: Affine) -> Option<Affine> {
        fdiv(a, b)
    }

    /// The smallest and largest value the form holds (NaN for a value
    /// that is not a float).
    pub fn bounds(&self) -> (f64, f64) {
        let r = self.gx.abs() + self.gy.abs() + self.err;
        let low = self.c - r;
        (if low < self.lo { self.lo } else { low }, self.c + r)
    }

    /// The largest magnitude the form holds.
    #[inline(always)]
    fn magnitude(&self) -> f64 {
        self.c.abs() + self.gx.abs() + self.gy.abs() + self.err
    }

    /// The f32 the form is exactly, if it is one.
    #[inline(always)]
    fn as_exact(&self) -> Option<f32> {
        let v = self.c as f32;
        (self.gx == 0.0 && self.gy == 0.0 && self.err == 0.0 && v as f64 == self.c).then_some(v)
    }

    /// An exact f32 value, or `None` when it is not finite.
    fn exact_finite(v: f32) -> Option<Affine> {
        v.is_finite().then(|| Affine::exact(v))
    }

    /// The form with the f32 rounding and flush of a result whose
    /// magnitude is at most `m` added, or `None` when `m` may overflow.
    #[inline(always)]
    fn rounded(mut self, m: f64) -> Option<Affine> {
        if !fits(m) {
            return None;
        }
        self.err += m * F32_REL + FLUSH;
        Some(self)
    }

    fn neg(self) -> Affine {
        Affine::new(-self.c, -self.gx, -self.gy, self.err)
    }

    /// `k` times the form, in real numbers (the f64 products' rounding
    /// added).
    fn scale(self, k: f64) -> Affine {
        let k_abs = k.abs();
        let slack = self.magnitude() * k_abs * 2.0 * F64_REL;
        Affine::new(
            self.c * k,
            self.gx * k,
            self.gy * k,
            self.err * k_abs + slack,
        )
    }

    /// The real product. The quadratic terms in `u`, `v` are centred
    /// (`u² ∈ [0, 1]` is `1/2 ± 1/2`) and kept as error with the cross
    /// terms and the errors' products; the f64 arithmetic's rounding is
    /// within `4·2⁻⁵⁰` of the magnitudes' product.
    #[inline(always)]
    fn mul(a: Affine, b: Affine) -> Affine {
        let (ga, gb) = (a.gx.abs() + a.gy.abs(), b.gx.abs() + b.gy.abs());
        let uu = a.gx * b.gx;
        let vv = a.gy * b.gy;
        let uv = a.gx * b.gy + a.gy * b.gx;
        let c = a.c * b.c + 0.5 * (uu + vv);
        let err = 0.5 * (uu.abs() + vv.abs())
            + uv.abs()
            + (a.c.abs() + ga) * b.err
            + (b.c.abs() + gb) * a.err
            + a.err * b.err
            + 4.0 * a.magnitude() * b.magnitude() * F64_REL;
        Affine::new(c, a.c * b.gx + b.c * a.gx, a.c * b.gy + b.c * a.gy, err)
    }

    /// `f` over the form's range as `alpha·x + (zeta ± delta)`: the form
    /// scaled, shifted and widened.
    fn linear(self, alpha: f64, zeta: f64, delta: f64) -> Affine {
        let mut r = self.scale(alpha);
        r.c += zeta;
        r.err += delta.abs() + (r.c.abs() + zeta.abs() + delta.abs()) * F64_REL;
        r
    }

    /// The real reciprocal, or `None` when the range holds zero.
    fn recip(self) -> Option<Affine> {
        let (lo, hi) = self.bounds();
        if lo > 0.0 {
            Some(recip_positive(self, lo, hi))
        } else if hi < 0.0 {
            Some(recip_positive(self.neg(), -hi, -lo).neg())
        } else {
            None
        }
    }

    /// The real square root, or `None` when the range reaches below zero.
    fn sqrt(self) -> Option<Affine> {
        let (lo, hi) = self.bounds();
        if lo.is_nan() || lo < 0.0 {
            return None;
        }
        if hi - lo <= hi * F64_REL {
            // Too narrow for a slope: the square root of the range.
            let (a, b) = (lo.sqrt(), hi.sqrt());
            return Some(Affine::interval(a * (1.0 - F64_REL), b * (1.0 + F64_REL)));
        }
        // Concave: the secant's slope, below the curve between the ends;
        // the curve's largest distance above it where the slope is
        // the derivative's, √x = 1 / (2α): there it is 1 / (4α).
        let (sl, sh) = (lo.sqrt(), hi.sqrt());
        let alpha = (sh - sl) / (hi - lo);
        let low = sl - alpha * lo;
        let high = 0.25 / alpha;
        let low = low.min(high);
        Some(self.linear(alpha, 0.5 * (low + high), 0.5 * (high - low)))
    }

    /// The hull of two forms: every value of either.
    pub fn hull(a: Affine, b: Affine) -> Affine {
        if a == b {
            return a;
        }
        let nonneg = a.nonneg() && b.nonneg();
        let mid = |x: f64, y: f64| 0.5 * x + 0.5 * y;
        let half = |x: f64, y: f64| 0.5 * (x - y).abs();
        Affine::new(
            mid(a.c, b.c),
            mid(a.gx, b.gx),
            mid(a.gy, b.gy),
            half(a.c, b.c)
                + half(a.gx, b.gx)
                + half(a.gy, b.gy)
                + a.err.max(b.err)
                + (a.magnitude() + b.magnitude()) * F64_REL,
        )
        .nonneg_if(nonneg)
    }

    /// The values of the form at least `lo` (those the lanes keep after a
    /// `discard` of the others), without correlation with the position
    /// when that cuts the form. From zero: `c = err`, so that the lower
    /// bound is zero exactly (a square root's domain).
    fn at_least(self, lo: f64) -> Affine {
        let (a, b) = self.bounds();
        if lo.is_nan() || a.is_nan() || lo <= a {
            return self;
        }
        let b = b.max(lo);
        if lo == 0.0 {
            // b / 2 is exact (b is normal or zero here).
            let h = 0.5 * b;
            return Affine::new(h, 0.0, 0.0, h).nonneg_if(true);
        }
        Affine::interval(lo, b).nonneg_if(lo >= 0.0)
    }

    /// The values of the form at most `hi`.
    fn at_most(self, hi: f64) -> Affine {
        self.neg().at_least(-hi).neg()
    }
}

/// `1/x` of the positive form `x` with range `[lo, hi]`: convex, so below
/// the secant, whose slope is `−1/(lo·hi)`, and at least the tangent of
/// that slope, touching at `√(lo·hi)`.
fn recip_positive(x: Affine, lo: f64, hi: f64) -> Affine {
    if hi - lo <= hi * F64_REL {
        return Affine::interval((1.0 / hi) * (1.0 - F64_REL), (1.0 / lo) * (1.0 + F64_REL));
    }
    let alpha = -1.0 / (lo * hi);
    let high = 1.0 / lo + 1.0 / hi;
    let low = 2.0 / (lo * hi).sqrt();
    let low = low.min(high);
    x.linear(alpha, 0.5 * (low + high), 0.5 * (high - low))
}

/// An operation of the analysis: the executor's op on the forms.
#[derive(Clone, Copy, Debug)]
enum Fun {
    /// A value known before the region (a constant).
    Value(Affine),
    /// A uniform word, read as a float when the flag says it is one (else
    /// unknown).
    Uniform(u32, bool),
    Mov(Reg),
    Add(Reg, Reg),
    Sub(Reg, Reg),
    Mul(Reg, Reg),
    Div(Reg, Reg),
    Neg(Reg),
    /// `d + a·b`.
    Mac(Reg, Reg),
    Dot(u8, [Reg; 4], [Reg; 4]),
    Sqrt(Reg),
    InverseSqrt(Reg),
    Abs(Reg),
    Min(Reg, Reg),
    Max(Reg, Reg),
    Mix(Reg, Reg, Reg),
    Clamp(Reg, Reg, Reg),
    /// Either operand (a select whose condition is not followed).
    Either(Reg, Reg),
    /// Not a float (a comparison's result).
    Unknown,
}

/// One step of the analysis, with the program's control flow resolved.
#[derive(Clone, Copy, Debug)]
enum Step {
    /// `d = f(...)`; with `hull`, on some lanes or runs only: the hull of
    /// the old and the new value.
    Set { d: Reg, hull: bool, f: Fun },
    /// After a `discard` of the lanes where `a < b` (or `a ≤ b`) is
    /// `discarded_if`: the others keep `a ≥ b` (`discarded_if`) or
    /// `a ≤ b`.
    Narrow { a: Reg, b: Reg, discarded_if: bool },
    /// No bound unless `r` is finite (what an op dropped for the draw
    /// still asks of its operand: `mix(x, y, 0)` is `x` for a finite
    /// `y` only).
    Finite { r: Reg },
}

/// A kernel's program as steps of the analysis, found once per kernel.
#[derive(Debug)]
pub(crate) struct Plan {
    steps: Vec<Step>,
    /// (input component, register) of each float input.
    inputs: Vec<(usize, Reg)>,
    /// The register holding gl_FragDepth at the end.
    output: Reg,
    registers: usize,
    /// The registers the steps read before writing them (not inputs).
    entry: Vec<Reg>,
    /// Per register: whether no step writes it (it keeps its start value
    /// throughout).
    kept: Vec<bool>,
}

/// The lanes of an execution mask, for the analysis: all lanes still
/// running, those where one condition register holds `true`
/// (`Some((register, true))`) or `false`, or fewer (`deeper`).
#[derive(Clone, Copy, Debug, Default)]
struct Mask {
    cond: Option<(Reg, bool)>,
    deeper: bool,
}

impl Mask {
    fn all(&self) -> bool {
        self.cond.is_none() && !self.deeper
    }

    /// The lanes of this mask where `c` is `positive`.
    fn and(self, c: Reg, positive: bool) -> Mask {
        match self.all() {
            true => Mask {
                cond: Some((c, positive)),
                deeper: false,
            },
            false => Mask {
                cond: None,
                deeper: true,
            },
        }
    }
}

/// The function of a pure float op (`None`: not followed).
fn fun(op: &Op) -> Option<(Reg, Fun)> {
    Some(match *op {
        Op::Const { d, bits } => (d, constant(bits)),
        Op::Uniform { d, word, float } => (d, Fun::Uniform(word, float)),
        Op::Mov { d, a } => (d, Fun::Mov(a)),
        Op::FAdd { d, a, b } => (d, Fun::Add(a, b)),
        Op::FSub { d, a, b } => (d, Fun::Sub(a, b)),
        Op::FMul { d, a, b } => (d, Fun::Mul(a, b)),
        Op::FDiv { d, a, b } => (d, Fun::Div(a, b)),
        Op::FNeg { d, a } => (d, Fun::Neg(a)),
        Op::FMac { d, a, b } => (d, Fun::Mac(a, b)),
        Op::Dot { d, n, a, b } => (d, Fun::Dot(n.min(4), a, b)),
        Op::F1 { f, d, a } => match f {
            F1::Sqrt => (d, Fun::Sqrt(a)),
            F1::InverseSqrt => (d, Fun::InverseSqrt(a)),
            F1::Abs => (d, Fun::Abs(a)),
            _ => return None,
        },
        Op::F2 { f, d, a, b } => match f {
            F2::Min => (d, Fun::Min(a, b)),
            F2::Max => (d, Fun::Max(a, b)),
            _ => return None,
        },
        Op::F3 { f, d, a, b, c } => match f {
            F3::Mix => (d, Fun::Mix(a, b, c)),
            F3::Clamp => (d, Fun::Clamp(a, b, c)),
            _ => return None,
        },
        Op::Select { d, a, b, .. } => (d, Fun::Either(a, b)),
        Op::FLt { d, .. } | Op::FLe { d, .. } => (d, Fun::Unknown),
        _ => return None,
    })
}

/// The registers `f` reads (`d`: its destination, which `Mac` reads).
fn reads(d: Reg, f: &Fun, out: &mut Vec<Reg>) {
    match *f {
        Fun::Value(_) | Fun::Uniform(..) | Fun::Unknown => {}
        Fun::Mov(a) | Fun::Neg(a) | Fun::Sqrt(a) | Fun::InverseSqrt(a) | Fun::Abs(a) => out.push(a),
        Fun::Add(a, b)
        | Fun::Sub(a, b)
        | Fun::Mul(a, b)
        | Fun::Div(a, b)
        | Fun::Min(a, b)
        | Fun::Max(a, b)
        | Fun::Either(a, b) => out.extend([a, b]),
        Fun::Mac(a, b) => out.extend([d, a, b]),
        Fun::Dot(n, a, b) => {
            out.extend(&a[..n as usize]);
            out.extend(&b[..n as usize]);
        }
        Fun::Mix(a, b, c) | Fun::Clamp(a, b, c) => out.extend([a, b, c]),
    }
}

/// The plan of `k`'s rewritten program (see the module contract), or
/// `None` when it does what the analysis does not follow.
pub(crate) fn plan(k: &Kernel) -> Option<Plan> {
    if k.stage != glsl::Stage::Fragment {
        return None;
    }
    let slot = k.interface.output("gl_FragDepth").filter(|s| s.written)?;
    let output = k.outputs.iter().find(|o| o.1 == slot.offset)?.0;
    let code = &k.code;
    let registers = code.prog.registers as usize;
    let mut steps = Vec::new();
    let mut cur = Mask::default();
    let mut slots: Vec<Mask> = Vec::new();
    // The ends of the blocks a jump met so far may skip.
    let mut skip: Vec<usize> = Vec::new();
    // Per register: the op that last wrote it, and the comparison it
    // holds (its operands, and the op that computed it).
    let mut written = vec![usize::MAX; registers];
    let mut compare: Vec<Option<(Reg, Reg, usize)>> = vec![None; registers];
    for (i, ins) in code.ins.iter().enumerate() {
        skip.retain(|&end| end > i);
        let op = &ins.op;
        match *op {
            Op::Store { d, a } => {
                let hull = !skip.is_empty() || !cur.all();
                steps.push(Step::Set {
                    d,
                    hull,
                    f: Fun::Mov(a),
                });
                *written.get_mut(d as usize)? = i;
                *compare.get_mut(d as usize)? = None;
            }
            Op::SaveMask { slot } => {
                let slot = slot as usize;
                if slots.len() <= slot {
                    slots.resize(slot + 1, Mask::default());
                }
                slots[slot] = cur;
            }
            Op::RestoreMask { slot } => cur = *slots.get(slot as usize)?,
            Op::AndMask { c } => cur = cur.and(c, true),
            Op::AndNotMask { slot, c } => cur = slots.get(slot as usize)?.and(c, false),
            Op::JumpIfNone { target } if target as usize > i => skip.push(target as usize),
            Op::Discard { .. } => {
                // The kept lanes narrow a comparison's operands when the
                // mask is that comparison's lanes and neither operand
                // changed since it ran.
                if let Some((c, positive)) = cur.cond {
                    if let Some((a, b, at)) = *compare.get(c as usize)? {
                        let unchanged = |r: Reg| {
                            written
                                .get(r as usize)
                                .is_some_and(|&w| w == usize::MAX || w < at)
                        };
                        if unchanged(a) && unchanged(b) {
                            steps.push(Step::Narrow {
                                a,
                                b,
                                discarded_if: positive,
                            });
                        }
                    }
                }
            }
            _ => {
                let (d, f) = fun(op)?;
                let hull = !skip.is_empty() || (ins.masked && !cur.all());
                steps.push(Step::Set { d, hull, f });
                *written.get_mut(d as usize)? = i;
                *compare.get_mut(d as usize)? = match *op {
                    Op::FLt { a, b, .. } | Op::FLe { a, b, .. } => Some((a, b, i)),
                    _ => None,
                };
            }
        }
    }
    let inputs: Vec<(usize, Reg)> = k
        .inputs
        .iter()
        .filter(|i| i.2 == glsl::types::Scalar::Float)
        .map(|i| (i.0, i.1))
        .collect();
    // The registers read before the steps write them (hulls read the
    // old value too), other than the float inputs.
    let mut set = vec![false; registers];
    for &(_, r) in &inputs {
        *set.get_mut(r as usize)? = true;
    }
    let mut entry = Vec::new();
    let mut read = Vec::new();
    for step in &steps {
        read.clear();
        match *step {
            Step::Set { d, hull, f } => {
                reads(d, &f, &mut read);
                if hull {
                    read.push(d);
                }
                for &r in &read {
                    if !*set.get(r as usize)? {
                        *set.get_mut(r as usize)? = true;
                        entry.push(r);
                    }
                }
                *set.get_mut(d as usize)? = true;
            }
            Step::Narrow { a, b, .. } | Step::Finite { r: a @ b } => {
                for r in [a, b] {
                    if !*set.get(r as usize)? {
                        *set.get_mut(r as usize)? = true;
                        entry.push(r);
                    }
                }
            }
        }
    }
    if !*set.get(output as usize)? {
        entry.push(output);
    }
    let mut kept = vec![true; registers];
    for step in &steps {
        let written: &[Reg] = match step {
            Step::Set { d, .. } => std::slice::from_ref(d),
            Step::Narrow { a, b, .. } => &[*a, *b],
            Step::Finite { .. } => &[],
        };
        for &r in written {
            *kept.get_mut(r as usize)? = false;
        }
    }
    Some(Plan {
        steps,
        inputs,
        output,
        registers,
        entry,
        kept,
    })
}

/// A kernel's `gl_FragDepth` bound, prepared for one draw's uniforms
/// ([`Kernel::depth_range`]).
#[derive(Clone, Debug)]
pub struct DepthRange {
    plan: Arc<Plan>,
    /// The draw's uniform words (for uniform reads the rewrite did not
    /// hoist).
    uniforms: Arc<[u32]>,
    /// The value of each of the plan's entry registers before the first
    /// op: initializers, zeros, the prologue's values for the uniforms.
    start: Vec<(Reg, Affine)>,
    /// The plan's steps for these uniforms ([`for_draw`]).
    steps: Vec<Step>,
}

/// `steps` with what the draw's constant registers `consts` (their
/// values; registers no step writes) make simple: `mix(x, y, t)` by a
/// constant `t` of 0 or 1 (a uniform switch, as the seed's `perspective`)
/// becomes a copy of `x` or `y`, the other checked finite, exactly as the
/// executor computes it (`x·1 + y·0 = x`).
fn for_draw(steps: &[Step], consts: &dyn Fn(Reg) -> Option<f32>) -> Vec<Step> {
    let mut out = Vec::with_capacity(steps.len());
    for &step in steps {
        if let Step::Set {
            d,
            hull,
            f: Fun::Mix(a, b, t),
        } = step
        {
            let (keep, check) = match consts(t) {
                Some(0.0) => (a, b),
                Some(1.0) => (b, a),
                _ => {
                    out.push(step);
                    continue;
                }
            };
            out.push(Step::Finite { r: check });
            out.push(Step::Set {
                d,
                hull,
                f: Fun::Mov(keep),
            });
            continue;
        }
        out.push(step);
    }
    out
}

/// Reusable registers for [`DepthRange::eval`].
#[derive(Clone, Debug, Default)]
pub struct RangeScratch {
    regs: Vec<Affine>,
}

/// Not a float: NaN, which every op passes on and every bound refuses.
const UNKNOWN: Affine = Affine {
    c: f64::NAN,
    gx: 0.0,
    gy: 0.0,
    err: 0.0,
    lo: f64::NEG_INFINITY,
};

impl Kernel {
    /// The bound on `gl_FragDepth` of this fragment kernel for the
    /// uniform words `uniforms` (see the `depth_range` module), or `None`
    /// when the kernel does not write it or does what the analysis does
    /// not follow.
    pub fn depth_range(&self, uniforms: &[u32]) -> Option<DepthRange> {
        let plan = self
            .range_plan
            .get_or_init(|| plan(self).map(Arc::new))
            .clone()?;
        let code = &self.code;
        // The registers as a run starts: zeros, initializers, then the
        // prologue's pure ops on them and the uniforms.
        let mut regs = vec![UNKNOWN; plan.registers];
        for &r in &code.zero {
            if let Some(v) = regs.get_mut(r as usize) {
                *v = Affine::exact(0.0);
            }
        }
        for &(r, bits) in &code.prog.init {
            if let (Some(v), Fun::Value(a)) = (regs.get_mut(r as usize), constant(bits)) {
                *v = a;
            }
        }
        for &(_, r, _) in &self.inputs {
            if let Some(v) = regs.get_mut(r as usize) {
                *v = UNKNOWN;
            }
        }
        for op in &code.prologue {
            let value = fun(op).map(|(d, f)| (d, apply(&regs, uniforms, d, f)));
            match value {
                Some((d, v)) => {
                    if let Some(slot) = regs.get_mut(d as usize) {
                        *slot = v.unwrap_or(UNKNOWN);
                    }
                }
                // A value the analysis cannot follow: its destinations
                // are unknown.
                None => op.for_each_operand(&mut |role, r, n| {
                    if matches!(role, Role::Def | Role::Acc | Role::Masked) {
                        for r in r..r.saturating_add(n) {
                            if let Some(v) = regs.get_mut(r as usize) {
                                *v = UNKNOWN;
                            }
                        }
                    }
                }),
            }
        }
        let start: Vec<(Reg, Affine)> = plan
            .entry
            .iter()
            .map(|&r| (r, regs.get(r as usize).copied().unwrap_or(UNKNOWN)))
            .collect();
        // Entry registers no step writes hold their start value
        // throughout.
        let consts = |r: Reg| -> Option<f32> {
            let (_, v) = start.iter().find(|e| e.0 == r)?;
            match plan.kept.get(r as usize) {
                Some(true) => v.as_exact(),
                _ => None,
            }
        };
        let steps = for_draw(&plan.steps, &consts);
        Some(DepthRange {
            plan,
            uniforms: uniforms.into(),
            start,
            steps,
        })
    }
}

impl DepthRange {
    /// The range `[lo, hi]` of `gl_FragDepth` over a region, given the
    /// form of each float input component (`input(component)`; `None`:
    /// no bound).
    pub fn eval(
        &self,
        scratch: &mut RangeScratch,
        input: &mut dyn FnMut(usize) -> Option<Affine>,
    ) -> Option<(f32, f32)> {
        let plan = &*self.plan;
        let regs = &mut scratch.regs;
        if regs.len() < plan.registers {
            regs.resize(plan.registers, UNKNOWN);
        }
        for &(r, v) in &self.start {
            *regs.get_mut(r as usize)? = v;
        }
        for &(c, r) in &plan.inputs {
            *regs.get_mut(r as usize)? = input(c)?;
        }
        for step in &self.steps {
            match *step {
                Step::Set { d, hull, f } => {
                    let v = apply(regs, &self.uniforms, d, f)?;
                    let slot = regs.get_mut(d as usize)?;
                    *slot = match hull {
                        true => Affine::hull(*slot, v),
                        false => v,
                    };
                }
                Step::Narrow { a, b, discarded_if } => {
                    let (fa, fb) = (*regs.get(a as usize)?, *regs.get(b as usize)?);
                    let ((alo, ahi), (blo, bhi)) = (fa.bounds(), fb.bounds());
                    // Kept: `a ≥ b` (the comparison false) or `a ≤ b`.
                    let (na, nb) = match discarded_if {
                        true => (fa.at_least(blo), fb.at_most(ahi)),
                        false => (fa.at_most(bhi), fb.at_least(alo)),
                    };
                    regs[a as usize] = na;
                    if b != a {
                        regs[b as usize] = nb;
                    }
                }
                Step::Finite { r } => {
                    if !fits(regs.get(r as usize)?.magnitude()) {
                        return None;
                    }
                }
            }
        }
        let (lo, hi) = regs.get(plan.output as usize)?.bounds();
        if !(lo.is_finite() && hi.is_finite()) {
            return None;
        }
        Some((down_f32(lo), up_f32(hi)))
    }
}

/// `f` on the forms in `regs` (`d`'s old value for `Mac`); `None`: no
/// bound (an unknown or not finite value, a domain the op may leave).
#[inline(always)]
fn apply(regs: &[Affine], uniforms: &[u32], d: Reg, f: Fun) -> Option<Affine> {
    let r = |x: Reg| regs.get(x as usize).copied();
    let v = match f {
        Fun::Value(a) => a,
        Fun::Uniform(word, float) => {
            let bits = uniforms.get(word as usize).copied().unwrap_or(0);
            match (float, constant(bits)) {
                (true, Fun::Value(a)) => a,
                _ => UNKNOWN,
            }
        }
        Fun::Unknown => UNKNOWN,
        Fun::Mov(a) => r(a)?,
        Fun::Add(a, b) => fadd(r(a)?, r(b)?)?,
        Fun::Sub(a, b) => fadd(r(a)?, r(b)?.neg())?,
        // A square is at least zero.
        Fun::Mul(a, b) => fmul(r(a)?, r(b)?)?.nonneg_if(a == b),
        Fun::Div(a, b) => fdiv(r(a)?, r(b)?)?,
        Fun::Neg(a) => r(a)?.neg(),
        Fun::Mac(a, b) => fadd(r(d)?, fmul(r(a)?, r(b)?)?)?,
        Fun::Dot(n, a, b) => {
            let mut sum = Affine::exact(0.0);
            for k in (0..n as usize).rev() {
                let p = fmul(r(a[k])?, r(b[k])?)?.nonneg_if(a[k] == b[k]);
                sum = fadd(sum, p)?;
            }
            sum
        }
        Fun::Sqrt(a) => fsqrt(r(a)?)?,
        Fun::InverseSqrt(a) => fdiv(Affine::exact(1.0), fsqrt(r(a)?)?)?,
        Fun::Abs(a) => fabs(r(a)?)?,
        Fun::Min(a, b) => fmin(r(a)?, r(b)?)?,
        Fun::Max(a, b) => fmin(r(a)?.neg(), r(b)?.neg())?.neg(),
        Fun::Mix(a, b, t) => {
            let t = r(t)?;
            let s = fadd(Affine::exact(1.0), t.neg())?;
            fadd(fmul(r(a)?, s)?, fmul(r(b)?, t)?)?
        }
        Fun::Clamp(x, lo, hi) => fmin(fmin(r(x)?.neg(), r(lo)?.neg())?.neg(), r(hi)?)?,
        Fun::Either(a, b) => Affine::hull(r(a)?, r(b)?),
    };
    Some(v)
}

/// The largest f32 at most `x` (finite `x` within f32's range).
fn down_f32(x: f64) -> f32 {
    let f = x as f32;
    if f as f64 > x {
        f.next_down()
    } else {
        f
    }
}

/// The smallest f32 at least `x`.
fn up_f32(x: f64) -> f32 {
    let f = x as f32;
    if (f as f64) < x {
        f.next_up()
    } else {
        f
    }
}

/// A constant's bits as a value: a finite float, exactly (flushed, as
/// every float entering a run); other bits are not read as floats.
fn constant(bits: u32) -> Fun {
    let v = f32::from_bits(bits);
    match v.is_finite() {
        true => Fun::Value(Affine::exact(v)),
        false => Fun::Unknown,
    }
}

/// The executor's `a + b` (exact operands: computed as it does; an
/// exact zero changes nothing). The result's magnitude is at most the
/// operands' sum `m`: its f32 rounding is within `m·2⁻²⁴`, the f64 sums'
/// within `m·2⁻⁵²` each.
#[inline(always)]
fn fadd(a: Affine, b: Affine) -> Option<Affine> {
    let m = a.magnitude() + b.magnitude();
    if !fits(m) {
        return None;
    }
    match (a.as_exact(), b.as_exact()) {
        (Some(x), Some(y)) => return Affine::exact_finite(x + y),
        (Some(0.0), None) => return Some(b),
        (None, Some(0.0)) => return Some(a),
        _ => {}
    }
    let err = a.err + b.err + m * 4.0 * F64_REL;
    let sum = Affine::new(a.c + b.c, a.gx + b.gx, a.gy + b.gy, err);
    // A sum of values at least zero rounds to one.
    Some(sum.rounded(m)?.nonneg_if(a.nonneg() && b.nonneg()))
}

/// The executor's `a · b` (exact operands: computed as it does; by an
/// exact 0, 1 or −1: exact; by a power of two: exact but for a flush).
/// The result's magnitude is at most the product `m` of the operands'.
#[inline(always)]
fn fmul(a: Affine, b: Affine) -> Option<Affine> {
    let m = a.magnitude() * b.magnitude();
    if !fits(m) {
        return None;
    }
    let (x, y) = (a.as_exact(), b.as_exact());
    if let (Some(x), Some(y)) = (x, y) {
        return Affine::exact_finite(x * y);
    }
    if let Some((k, f)) = x.map(|k| (k, b)).or(y.map(|k| (k, a))) {
        match k {
            0.0 => return Some(Affine::exact(0.0)),
            1.0 => return Some(f),
            -1.0 => return Some(f.neg()),
            _ => {}
        }
        let nonneg = k >= 0.0 && f.nonneg();
        let mut r = f.scale(k as f64);
        // A power of two scales exactly (its mantissa bits are zero).
        match k.to_bits() & 0x007f_ffff == 0 {
            true => r.err += FLUSH,
            false => r = r.rounded(m)?,
        }
        return Some(r.nonneg_if(nonneg));
    }
    Some(
        Affine::mul(a, b)
            .rounded(m)?
            .nonneg_if(a.nonneg() && b.nonneg()),
    )
}

fn fdiv(a: Affine, b: Affine) -> Option<Affine> {
    if let (Some(x), Some(y)) = (a.as_exact(), b.as_exact()) {
        return Affine::exact_finite(x / y);
    }
    let nonneg = a.nonneg() && b.bounds().0 > 0.0;
    let r = b.recip()?;
    let m = a.magnitude() * r.magnitude();
    Some(Affine::mul(a, r).rounded(m)?.nonneg_if(nonneg))
}

fn fsqrt(a: Affine) -> Option<Affine> {
    if let Some(x) = a.as_exact() {
        return Affine::exact_finite(glsl::math::sqrt(x));
    }
    let r = a.sqrt()?;
    let m = r.magnitude();
    Some(r.rounded(m)?.nonneg_if(true))
}

fn fabs(a: Affine) -> Option<Affine> {
    let (lo, hi) = a.bounds();
    if !(lo.is_finite() && hi.is_finite()) {
        return None;
    }
    let r = if lo >= 0.0 {
        a
    } else if hi <= 0.0 {
        a.neg()
    } else {
        Affine::interval(0.0, hi.max(-lo))
    };
    Some(r.nonneg_if(true))
}

/// GLSL `min` of two finite values: one of them, never rounded.
fn fmin(a: Affine, b: Affine) -> Option<Affine> {
    let ((alo, ahi), (blo, bhi)) = (a.bounds(), b.bounds());
    if !(alo.is_finite() && ahi.is_finite() && blo.is_finite() && bhi.is_finite()) {
        return None;
    }
    Some(if ahi <= blo {
        a
    } else if bhi <= alo {
        b
    } else {
        Affine::interval(alo.min(blo), ahi.min(bhi))
    })
}

#[cfg(test)]
mod tests;
