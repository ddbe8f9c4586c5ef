//! Lowering of a linked stage's IR to a [`Program`].
//!
//! - Every user function call is inlined (GLSL 1.10/1.20 forbid recursion,
//!   §6.1), with the parameter rules of §6.1.1: arguments evaluated once,
//!   left to right; `in` values copied in at the call; `out`/`inout`
//!   l-values evaluated at the call and written back, in order, when the
//!   callee returns.
//! - Known int values: an `in` int parameter of an inlined call whose
//!   argument is a constant (or another known value) and that the callee
//!   never writes, and the counter of an unrolled loop, index arrays
//!   statically: `gl_LightSource[light].position` with a known `light` is a
//!   uniform read (hoisted by the executor out of every run) instead of a
//!   per-lane gather.
//! - Counted loops are unrolled: `for (int i = A; cond(i); step)` with `A`
//!   constant, `cond` a comparison of `i` with constants, `step` adding a
//!   constant, no `break`/`continue` of the loop and no other write of
//!   `i`, at most 32 iterations and 4096 expression nodes in all (nested
//!   loops: 16384 added nodes per program, outer loops first). The
//!   counter's register is still written as the loop would (traces show
//!   the same statements and values) and each iteration still evaluates
//!   the condition, whose unread value the executor drops.
//! - Variables (globals that are not uniforms, every local of every inlined
//!   call) get consecutive registers for their flattened components;
//!   uniforms are read from the uniform words where they are used.
//! - Control flow uses execution masks saved in mask slots. Each structured
//!   construct pushes a context (an `if`'s entry mask, a loop's entry and
//!   running masks, a function's entry mask); `break`, `continue`,
//!   `return` and `discard` remove the active lanes from the slots between
//!   the statement and the construct they leave, so when the construct
//!   restores its saved mask those lanes stay off.
//! - `&&`, `||` and `?:` whose later operands have side effects run those
//!   operands under a narrowed mask; pure ones are computed on every lane
//!   and selected.

use crate::interface::{kinds, size_of, Interface, Slot};
use crate::program::{
    Op, PrintfSite, Program, Reg, StatementMark, TexLod, TexOp, VarInfo, F1, F2, F3,
};
use crate::ExecError;
use glsl::builtins::BuiltinFn;
use glsl::ir::{
    BinaryOp, Block, ConstScalar, ConstValue, Expr, ExprKind, FunctionId, GlobalId, IncDec,
    LocalId, Module, ParamQualifier, Stage, Stmt, Storage, UnaryOp,
};
use glsl::link::LinkedStage;
use glsl::types::{ArraySize, Base, SamplerKind, Scalar, Type};
use glsl::Span;

/// Most registers a program may use (each is `4 * LANES` bytes).
pub const MAX_REGISTERS: u32 = 1 << 18;
/// Most instructions a lowered program may have (after inlining).
pub const MAX_OPS: usize = 1 << 21;
/// Deepest chain of inlined calls.
pub const MAX_CALL_DEPTH: usize = 128;
/// Above this many expression nodes after inlining, functions become
/// subroutines instead.
pub const INLINE_LIMIT: u64 = 200_000;

type Val = Vec<Reg>;
type R<T> = Result<T, ExecError>;

fn unsupported<T>(msg: impl Into<String>) -> R<T> {
    Err(ExecError::Unsupported(msg.into()))
}

/// What `Kernel::new` builds.
pub(crate) struct Lowered {
    pub program: Program,
    pub interface: Interface,
    /// (input component, register, kind).
    pub inputs: Vec<(usize, Reg, Scalar)>,
    /// (register, output component, kind).
    pub outputs: Vec<(Reg, usize, Scalar)>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum CtxKind {
    If,
    LoopEntry,
    LoopRun,
    Function,
}

#[derive(Clone, Copy, Debug)]
enum GlobalLoc {
    Reg(Reg),
    Uniform(Option<u32>),
}

struct Frame {
    func: FunctionId,
    /// Register and (sized) type of every local.
    locals: Vec<(Reg, Type)>,
    /// Locals known to hold one int value on every lane where they are
    /// read (see [`Lowerer::const_int`]), by local index.
    consts: Vec<Option<i32>>,
    ret: Val,
}

#[derive(Clone, Copy, Debug)]
enum Root {
    Reg(Reg),
    Uniform(u32),
}

/// A storage location being read or written: `root + off (+ dynamic
/// offset) + comps[i]`.
#[derive(Clone, Debug)]
struct Place {
    root: Root,
    /// Components of the whole variable at `root`.
    size: u32,
    ty: Type,
    off: u32,
    /// A per-lane offset register and its largest value.
    dynamic: Option<(Reg, u32)>,
    /// Swizzled components, relative to `off`.
    comps: Option<Vec<u32>>,
}

struct Lowerer<'m> {
    m: &'m Module,
    stage: Stage,
    p: Program,
    next_reg: u32,
    globals: Vec<GlobalLoc>,
    used: Vec<bool>,
    next_word: u32,
    /// Whether each allocated uniform word is a float's.
    uniform_float: Vec<bool>,
    uniform_order: Vec<GlobalId>,
    frames: Vec<Frame>,
    ctx: Vec<(CtxKind, u32)>,
    /// Subroutine mode: the lowered body of each user function.
    subs: Option<Vec<Option<Sub>>>,
    /// Expression nodes that unrolling may still add to the program
    /// (nested loops unroll within one budget).
    unroll_left: u64,
}

/// A user function lowered once as a subroutine (static registers: GLSL
/// has no recursion, so one activation at a time).
#[derive(Clone)]
struct Sub {
    entry: u32,
    slot: u32,
    locals: Vec<(Reg, Type)>,
    ret: Val,
}

pub(crate) fn lower(stage: &LinkedStage, inline_limit: u64) -> R<Lowered> {
    let owned;
    let m = match with_ftransform_inputs(&stage.module) {
        Some(patched) => {
            owned = patched;
            &owned
        }
        None => &stage.module,
    };
    let mut l = Lowerer {
        m,
        stage: stage.stage,
        p: Program::default(),
        next_reg: 0,
        globals: Vec::with_capacity(m.globals.len()),
        used: vec![false; m.globals.len()],
        next_word: 0,
        uniform_float: Vec::new(),
        uniform_order: Vec::new(),
        frames: Vec::new(),
        ctx: Vec::new(),
        subs: None,
        unroll_left: UNROLL_BUDGET,
    };
    // Globals: registers for everything but uniforms; uniform words for
    // the uniforms the shader reads (others get words if lowering finds a
    // use, e.g. ftransform's matrix).
    for (i, g) in m.globals.iter().enumerate() {
        let id = GlobalId(i as u32);
        if g.storage == Storage::Uniform {
            l.globals.push(GlobalLoc::Uniform(None));
            if g.read {
                l.uniform_word(id)?;
            }
            continue;
        }
        let n = l.size(g.ty)?;
        let r = l.alloc(n)?;
        l.globals.push(GlobalLoc::Reg(r));
        l.p.vars.push(VarInfo {
            name: g.name.clone(),
            ty: g.ty,
            first_register: r,
            registers: n as u32,
        });
        if matches!(g.storage, Storage::Const | Storage::Private) {
            if let Some(init) = &g.init {
                for (k, c) in init.components.iter().enumerate().take(n) {
                    l.p.init.push((r + k as u32, const_bits(*c)));
                }
            }
        }
    }
    let main = stage.main;
    let Some(f) = m.functions.get(main.0 as usize) else {
        return unsupported("the entry point does not exist");
    };
    let Some(body) = &f.body else {
        return unsupported("main has no body");
    };
    // Inline every call unless that would explode (a call tree with many
    // repeated calls): then each function is lowered once as a subroutine.
    if inlined_cost(m, main, &mut vec![None; m.functions.len()], 0) > inline_limit {
        l.lower_subroutines(main)?;
    }
    let locals = l.alloc_locals(main)?;
    let fs = l.new_slot();
    l.emit(Op::SaveMask { slot: fs })?;
    l.ctx.push((CtxKind::Function, fs));
    l.frames.push(Frame {
        func: main,
        consts: vec![None; locals.len()],
        locals,
        ret: Vec::new(),
    });
    // Non-constant global initializers run first, in declaration order.
    for (i, g) in m.globals.iter().enumerate() {
        if let (Some(e), GlobalLoc::Reg(r)) = (&g.init_expr, l.globals[i]) {
            let mark = l.next_reg;
            l.mark_statement(e.span);
            let v = l.expr(e)?;
            let n = l.size(g.ty)? as u32;
            if v.len() as u32 != n {
                return unsupported(format!("initializer of `{}' has the wrong size", g.name));
            }
            for (k, src) in v.into_iter().enumerate() {
                l.emit(Op::Store {
                    d: r + k as u32,
                    a: src,
                })?;
            }
            l.next_reg = mark;
        }
    }
    l.block(body)?;
    l.emit(Op::RestoreMask { slot: fs })?;
    l.frames.pop();
    l.ctx.pop();
    l.finish()
}

/// `ftransform()` reads `gl_ModelViewProjectionMatrix` and `gl_Vertex`,
/// which the analyzer only declares in a module that names them: a copy of
/// the module with the missing ones added (unread, so they enter the
/// interface only if `ftransform` is lowered).
fn with_ftransform_inputs(m: &Module) -> Option<Module> {
    if m.stage != Stage::Vertex {
        return None;
    }
    let wanted = [
        (
            "gl_ModelViewProjectionMatrix",
            Type::mat(4, 4),
            Storage::Uniform,
        ),
        ("gl_Vertex", Type::vec(Scalar::Float, 4), Storage::Attribute),
    ];
    let missing: Vec<_> = wanted
        .iter()
        .filter(|(n, ..)| !m.globals.iter().any(|g| g.name == *n))
        .collect();
    if missing.is_empty() {
        return None;
    }
    let mut out = m.clone();
    for &&(name, ty, storage) in &missing {
        out.globals.push(glsl::ir::Global {
            name: name.to_string(),
            ty,
            storage,
            builtin: true,
            invariant: false,
            centroid: false,
            init: None,
            init_expr: None,
            read: false,
            written: false,
            implicit_size: 0,
            span: Span::default(),
        });
    }
    Some(out)
}

fn const_bits(c: ConstScalar) -> u32 {
    match c {
        ConstScalar::Float(f) => glsl::math::flush_denormal(f).to_bits(),
        ConstScalar::Int(i) => i as u32,
        ConstScalar::Bool(b) => b as u32,
    }
}

/// Whether evaluating `e` may write a variable (assignments, `++`/`--`,
/// user function calls).
fn has_effects(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Const(_) | ExprKind::Global(_) | ExprKind::Local(_) => false,
        ExprKind::Assign { .. }
        | ExprKind::IncDec { .. }
        | ExprKind::Call { .. }
        | ExprKind::DebugPrintf { .. } => true,
        ExprKind::Index { base, index } => has_effects(base) || has_effects(index),
        ExprKind::Swizzle { base, .. } | ExprKind::Member { base, .. } => has_effects(base),
        ExprKind::Unary { operand, .. } | ExprKind::Convert { operand } => has_effects(operand),
        ExprKind::Binary { left, right, .. } | ExprKind::Comma { left, right } => {
            has_effects(left) || has_effects(right)
        }
        ExprKind::Ternary {
            cond,
            accept,
            reject,
        } => has_effects(cond) || has_effects(accept) || has_effects(reject),
        ExprKind::Builtin { args, .. } | ExprKind::Construct { args } => {
            args.iter().any(has_effects)
        }
    }
}

/// Expression nodes of `f` once every call is inlined (saturating).
fn inlined_cost(m: &Module, f: FunctionId, memo: &mut Vec<Option<u64>>, depth: usize) -> u64 {
    if let Some(Some(c)) = memo.get(f.0 as usize) {
        return *c;
    }
    if depth > MAX_CALL_DEPTH {
        return u64::MAX;
    }
    let Some(body) = m.functions.get(f.0 as usize).and_then(|f| f.body.as_ref()) else {
        return 0;
    };
    let mut calls = Vec::new();
    let mut nodes = 0u64;
    visit_live_block(body, &mut |e| {
        nodes += 1;
        if let ExprKind::Call { function, .. } = &e.kind {
            calls.push(*function);
        }
    });
    let mut total = nodes;
    for c in calls {
        total = total.saturating_add(inlined_cost(m, c, memo, depth + 1));
    }
    if let Some(slot) = memo.get_mut(f.0 as usize) {
        *slot = Some(total);
    }
    total
}

/// Calls `f` on every expression of `b`, outer before inner.
fn visit_block(b: &[Stmt], f: &mut dyn FnMut(&Expr)) {
    visit_block_with(b, false, f)
}

/// Calls `f` on every expression of `b` that lowering reaches: not the
/// branch a constant `if` condition rules out (see [`const_bool`]).
fn visit_live_block(b: &[Stmt], f: &mut dyn FnMut(&Expr)) {
    visit_block_with(b, true, f)
}

fn visit_block_with(b: &[Stmt], live_only: bool, f: &mut dyn FnMut(&Expr)) {
    for s in b {
        match s {
            Stmt::Expr(e) | Stmt::Return(Some(e), _) => visit_expr(e, f),
            Stmt::Declare { init: Some(e), .. } => visit_expr(e, f),
            Stmt::Block(b) => visit_block_with(b, live_only, f),
            Stmt::If {
                cond, then, else_, ..
            } => match const_bool(cond).filter(|_| live_only) {
                Some(true) => visit_block_with(then, live_only, f),
                Some(false) => visit_block_with(else_, live_only, f),
                None => {
                    visit_expr(cond, f);
                    visit_block_with(then, live_only, f);
                    visit_block_with(else_, live_only, f);
                }
            },
            Stmt::Loop {
                body, continuing, ..
            } => {
                visit_block_with(body, live_only, f);
                visit_block_with(continuing, live_only, f);
            }
            _ => {}
        }
    }
}

/// The value of a constant `bool` condition. An `if` on one is lowered to
/// the taken branch only (the linker likewise ignores calls in the other,
/// which may name a function without a body).
fn const_bool(e: &Expr) -> Option<bool> {
    match &e.kind {
        ExprKind::Const(ConstValue { components, .. }) => match components.first() {
            Some(ConstScalar::Bool(b)) => Some(*b),
            _ => None,
        },
        _ => None,
    }
}

fn visit_expr(e: &Expr, f: &mut dyn FnMut(&Expr)) {
    f(e);
    match &e.kind {
        ExprKind::Const(_) | ExprKind::Global(_) | ExprKind::Local(_) => {}
        ExprKind::Index { base, index } => {
            visit_expr(base, f);
            visit_expr(index, f);
        }
        ExprKind::Swizzle { base, .. } | ExprKind::Member { base, .. } => visit_expr(base, f),
        ExprKind::Unary { operand, .. } | ExprKind::Convert { operand } => visit_expr(operand, f),
        ExprKind::Binary { left, right, .. } | ExprKind::Comma { left, right } => {
            visit_expr(left, f);
            visit_expr(right, f);
        }
        ExprKind::Ternary {
            cond,
            accept,
            reject,
        } => {
            visit_expr(cond, f);
            visit_expr(accept, f);
            visit_expr(reject, f);
        }
        ExprKind::Assign { target, value, .. } => {
            visit_expr(target, f);
            visit_expr(value, f);
        }
        ExprKind::IncDec { target, .. } => visit_expr(target, f),
        ExprKind::Call { args, .. }
        | ExprKind::Builtin { args, .. }
        | ExprKind::DebugPrintf { args, .. }
        | ExprKind::Construct { args } => args.iter().for_each(|a| visit_expr(a, f)),
    }
}

/// Most iterations of a loop [`Lowerer::unroll_plan`] unrolls.
const UNROLL_TRIPS: usize = 32;
/// Most expression nodes (calls inlined) of an unrolled loop, all
/// iterations together.
const UNROLL_NODES: u64 = 4096;

/// Most expression nodes unrolling adds to a whole program.
const UNROLL_BUDGET: u64 = 16384;

/// A counted loop to unroll ([`Lowerer::unroll_plan`]).
struct Unroll<'b> {
    /// Expression nodes the copies add.
    extra: u64,
    local: LocalId,
    /// The counter's value in each iteration.
    values: Vec<i32>,
    /// The loop condition's negation (`!(i < n)`) and its statement.
    cond: &'b Expr,
    cond_span: Span,
    /// The body after the condition.
    body: &'b [Stmt],
    continuing: &'b Block,
}

/// The local an l-value expression writes into (through indexing,
/// swizzles and members).
fn root_local(e: &Expr) -> Option<LocalId> {
    match &e.kind {
        ExprKind::Local(l) => Some(*l),
        ExprKind::Index { base, .. }
        | ExprKind::Swizzle { base, .. }
        | ExprKind::Member { base, .. } => root_local(base),
        _ => None,
    }
}

/// Whether `b` may write `local`: an assignment, `++`/`--`, or an `out` /
/// `inout` argument rooted at it.
fn writes_local(m: &Module, b: &[Stmt], local: LocalId) -> bool {
    let mut writes = false;
    visit_block(b, &mut |e| match &e.kind {
        ExprKind::Assign { target, .. } | ExprKind::IncDec { target, .. } => {
            writes |= root_local(target) == Some(local);
        }
        ExprKind::Call { function, args } => {
            let params = m.functions.get(function.0 as usize).map(|f| &f.params[..]);
            for (k, a) in args.iter().enumerate() {
                let by_value = params
                    .and_then(|p| p.get(k))
                    .is_some_and(|p| p.qualifier == ParamQualifier::In);
                writes |= !by_value && root_local(a) == Some(local);
            }
        }
        _ => {}
    });
    writes
}

/// Whether `b` has a `break` or `continue` of the loop it is the body of
/// (those of nested loops do not count).
fn leaves_loop(b: &[Stmt]) -> bool {
    b.iter().any(|s| match s {
        Stmt::Break(_) | Stmt::Continue(_) => true,
        Stmt::Block(b) => leaves_loop(b),
        Stmt::If { then, else_, .. } => leaves_loop(then) || leaves_loop(else_),
        _ => false,
    })
}

/// `e`, an int expression of constants and `local` (= `v`), evaluated as
/// the executor would (wrapping arithmetic).
fn eval_int(e: &Expr, local: LocalId, v: i32) -> Option<i32> {
    match &e.kind {
        ExprKind::Local(l) if *l == local => Some(v),
        ExprKind::Const(_) => const_index(e),
        ExprKind::Binary { op, left, right } => {
            let (a, b) = (eval_int(left, local, v)?, eval_int(right, local, v)?);
            match op {
                BinaryOp::Add => Some(a.wrapping_add(b)),
                BinaryOp::Sub => Some(a.wrapping_sub(b)),
                BinaryOp::Mul => Some(a.wrapping_mul(b)),
                _ => None,
            }
        }
        _ => None,
    }
}

/// `e`, a bool expression comparing such int expressions (or negating
/// one), evaluated with `local` = `v`.
fn eval_bool(e: &Expr, local: LocalId, v: i32) -> Option<bool> {
    match &e.kind {
        ExprKind::Unary {
            op: UnaryOp::Not,
            operand,
        } => Some(!eval_bool(operand, local, v)?),
        ExprKind::Binary { op, left, right } => {
            let (a, b) = (eval_int(left, local, v)?, eval_int(right, local, v)?);
            match op {
                BinaryOp::Less => Some(a < b),
                BinaryOp::LessEq => Some(a <= b),
                BinaryOp::Greater => Some(a > b),
                BinaryOp::GreaterEq => Some(a >= b),
                BinaryOp::Equal => Some(a == b),
                BinaryOp::NotEqual => Some(a != b),
                _ => None,
            }
        }
        _ => None,
    }
}

/// The counter's value after the loop step `e` (`i++`, `++i`, `i--`,
/// `--i`, `i += c`, `i -= c`, `i = i + c`...) from `v`.
fn step_value(e: &Expr, local: LocalId, v: i32) -> Option<i32> {
    match &e.kind {
        ExprKind::IncDec { op, target } if root_local(target) == Some(local) => {
            let ExprKind::Local(_) = target.kind else {
                return None;
            };
            Some(match op {
                IncDec::PreInc | IncDec::PostInc => v.wrapping_add(1),
                IncDec::PreDec | IncDec::PostDec => v.wrapping_sub(1),
            })
        }
        ExprKind::Assign { op, target, value } if matches!(target.kind, ExprKind::Local(l) if l == local) =>
        {
            let x = eval_int(value, local, v)?;
            match op {
                None => Some(x),
                Some(BinaryOp::Add) => Some(v.wrapping_add(x)),
                Some(BinaryOp::Sub) => Some(v.wrapping_sub(x)),
                Some(BinaryOp::Mul) => Some(v.wrapping_mul(x)),
                _ => None,
            }
        }
        _ => None,
    }
}

fn kind_of(ty: Type) -> Scalar {
    ty.scalar().unwrap_or(Scalar::Float)
}

/// The constant int value of an index expression, if it is one.
fn const_index(e: &Expr) -> Option<i32> {
    match &e.kind {
        ExprKind::Const(ConstValue { components, .. }) => match components.first() {
            Some(ConstScalar::Int(i)) => Some(*i),
            _ => None,
        },
        _ => None,
    }
}

impl<'m> Lowerer<'m> {
    // ---- allocation and emission -------------------------------------

    fn size(&self, ty: Type) -> R<usize> {
        let n = size_of(ty, &self.m.structs);
        if n > MAX_REGISTERS as usize {
            return unsupported("a variable is too large for the executor");
        }
        Ok(n)
    }

    fn alloc(&mut self, n: usize) -> R<Reg> {
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

    /// Evaluates one operand of `?:` under the current mask and stores it
    /// into the result registers.
    fn store_operand(&mut self, e: &Expr, result: &[Reg]) -> R<()> {
        let v = self.expr(e)?;
        if v.len() != result.len() {
            return unsupported("?: operand of the wrong size");
        }
        for (&d, &a) in result.iter().zip(&v) {
            self.emit(Op::Store { d, a })?;
        }
        Ok(())
    }

    fn temps(&mut self, n: usize) -> R<Val> {
        let r = self.alloc(n)?;
        Ok((r..r + n as u32).collect())
    }

    fn temp(&mut self) -> R<Reg> {
        self.alloc(1)
    }

    fn new_slot(&mut self) -> u32 {
        self.p.mask_slots += 1;
        self.p.mask_slots - 1
    }

    fn emit(&mut self, op: Op) -> R<()> {
        if self.p.ops.len() >= MAX_OPS {
            return unsupported(format!(
                "the program is larger than {MAX_OPS} instructions after inlining"
            ));
        }
        self.p.ops.push(op);
        Ok(())
    }

    fn pc(&self) -> u32 {
        self.p.ops.len() as u32
    }

    fn patch(&mut self, at: u32, to: u32) {
        match self.p.ops.get_mut(at as usize) {
            Some(Op::JumpIfNone { target }) | Some(Op::Jump { target }) => *target = to,
            _ => {}
        }
    }

    fn mark_statement(&mut self, span: Span) {
        let op = self.pc();
        match self.p.statements.last_mut() {
            Some(last) if last.op == op => last.span = span,
            _ => self.p.statements.push(StatementMark { op, span }),
        }
    }

    fn konst(&mut self, bits: u32) -> R<Reg> {
        let d = self.temp()?;
        self.emit(Op::Const { d, bits })?;
        Ok(d)
    }

    fn fconst(&mut self, f: f32) -> R<Reg> {
        self.konst(glsl::math::flush_denormal(f).to_bits())
    }

    fn copy(&mut self, v: &[Reg]) -> R<Val> {
        let out = self.temps(v.len())?;
        for (&d, &a) in out.iter().zip(v) {
            self.emit(Op::Mov { d, a })?;
        }
        Ok(out)
    }

    /// `v` in consecutive registers (copied unless it already is).
    fn consecutive(&mut self, v: &[Reg]) -> R<Reg> {
        let ok = v.windows(2).all(|w| w[1] == w[0].wrapping_add(1));
        match v.first() {
            Some(&first) if ok => Ok(first),
            _ => Ok(self.copy(v)?.first().copied().unwrap_or(0)),
        }
    }

    fn uniform_word(&mut self, g: GlobalId) -> R<u32> {
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

    fn uniform_is_float(&self, word: u32) -> bool {
        self.uniform_float
            .get(word as usize)
            .copied()
            .unwrap_or(false)
    }

    fn alloc_locals(&mut self, f: FunctionId) -> R<Vec<(Reg, Type)>> {
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

    // ---- statements --------------------------------------------------

    fn block(&mut self, b: &Block) -> R<()> {
        let mark = self.next_reg;
        self.statements(b)?;
        self.next_reg = mark;
        Ok(())
    }

    /// Lowers `b`'s statements up to the first that always leaves it;
    /// `true` when there is one (the rest is unreachable).
    fn statements(&mut self, b: &[Stmt]) -> R<bool> {
        let mut i = 0;
        while let Some(s) = b.get(i) {
            // `for (int i = A; i < B; i++)` with a few iterations and a
            // body that leaves `i` alone: unrolled (see `unroll_plan`).
            if let (Stmt::Declare { local, .. }, Some(next)) = (s, b.get(i + 1)) {
                if let Some(plan) = self.unroll_plan(*local, s, next) {
                    self.unroll_left -= plan.extra;
                    if self.stmt(s)? || self.unrolled(plan)? {
                        return Ok(true);
                    }
                    i += 2;
                    continue;
                }
            }
            if self.stmt(s)? {
                return Ok(true);
            }
            i += 1;
        }
        Ok(false)
    }

    /// The int value of `e` when it is known at this point of the
    /// program: an int constant, or a local bound to one (a constant
    /// argument of an inlined call, an unrolled loop's counter).
    fn const_int(&self, e: &Expr) -> Option<i32> {
        match &e.kind {
            ExprKind::Local(l) => self
                .frames
                .last()
                .and_then(|f| f.consts.get(l.0 as usize).copied().flatten()),
            _ => const_index(e),
        }
    }

    /// Whether the statements `decl` (declaring `local`) and `next` are a
    /// counted loop to unroll: `local` an int with a constant initial
    /// value, `next` a loop whose body starts with `if (!(cond)) break;`
    /// and whose continuing part steps `local` by a constant, `cond` a
    /// comparison of `local` with a constant; no other `break` or
    /// `continue` of that loop, no other write of `local`; at most
    /// [`UNROLL_TRIPS`] iterations and [`UNROLL_NODES`] expression nodes
    /// in all (calls counted inlined), the copies within what is left of
    /// the program's [`UNROLL_BUDGET`].
    fn unroll_plan<'b>(&self, local: LocalId, decl: &Stmt, next: &'b Stmt) -> Option<Unroll<'b>> {
        let Stmt::Declare {
            init: Some(init), ..
        } = decl
        else {
            return None;
        };
        let Stmt::Loop {
            body, continuing, ..
        } = next
        else {
            return None;
        };
        if init.ty != Type::INT {
            return None;
        }
        let first = const_index(init)?;
        let (
            Some(Stmt::If {
                cond,
                then,
                else_,
                span,
            }),
            [step],
        ) = (body.first(), continuing.as_slice())
        else {
            return None;
        };
        if !matches!(then.as_slice(), [Stmt::Break(_)]) || !else_.is_empty() {
            return None;
        }
        let Stmt::Expr(step_expr) = step else {
            return None;
        };
        let rest = &body[1..];
        if leaves_loop(rest) || writes_local(self.m, rest, local) {
            return None;
        }
        let mut values = Vec::new();
        let mut v = first;
        while !eval_bool(cond, local, v)? {
            values.push(v);
            if values.len() > UNROLL_TRIPS {
                return None;
            }
            v = step_value(step_expr, local, v)?;
        }
        let mut nodes = 0u64;
        let mut calls = Vec::new();
        visit_live_block(rest, &mut |e| {
            nodes += 1;
            if let ExprKind::Call { function, .. } = &e.kind {
                calls.push(*function);
            }
        });
        let mut memo = vec![None; self.m.functions.len()];
        for c in calls {
            nodes = nodes.saturating_add(inlined_cost(self.m, c, &mut memo, self.frames.len()));
        }
        let extra = nodes.saturating_mul(values.len().saturating_sub(1) as u64);
        if nodes.saturating_mul(values.len() as u64) > UNROLL_NODES || extra > self.unroll_left {
            return None;
        }
        Some(Unroll {
            extra,
            local,
            values,
            cond,
            cond_span: *span,
            body: rest,
            continuing,
        })
    }

    /// Lowers an unrolled loop (after its counter's declaration): per
    /// iteration the condition (its statement marked and its value
    /// computed, for traces; nothing reads it), the body with the counter
    /// bound to the iteration's value, the continuing part; then the
    /// failing condition. `true` when the body always leaves the
    /// function (the rest of the block is unreachable).
    fn unrolled(&mut self, plan: Unroll) -> R<bool> {
        let slot = plan.local.0 as usize;
        for &v in &plan.values {
            self.check_condition(plan.cond, plan.cond_span)?;
            self.bind(slot, Some(v));
            let mark = self.next_reg;
            let ends = self.statements(plan.body)?;
            self.next_reg = mark;
            self.bind(slot, None);
            if ends {
                return Ok(true);
            }
            self.block(plan.continuing)?;
        }
        self.check_condition(plan.cond, plan.cond_span)?;
        // Where the loop's `break` ran (a statement of its own in traces).
        self.mark_statement(plan.cond_span);
        self.konst(0)?;
        Ok(false)
    }

    fn check_condition(&mut self, cond: &Expr, span: Span) -> R<()> {
        let mark = self.next_reg;
        self.mark_statement(span);
        self.expr(cond)?;
        self.next_reg = mark;
        Ok(())
    }

    fn bind(&mut self, slot: usize, v: Option<i32>) {
        if let Some(c) = self.frames.last_mut().and_then(|f| f.consts.get_mut(slot)) {
            *c = v;
        }
    }

    /// Lowers one statement; `true` when it always leaves the block
    /// (the rest of the block is unreachable).
    fn stmt(&mut self, s: &Stmt) -> R<bool> {
        let mark = self.next_reg;
        let ends = match s {
            Stmt::Expr(e) => {
                self.mark_statement(e.span);
                self.expr(e)?;
                false
            }
            Stmt::Declare { local, init, span } => {
                if let Some(e) = init {
                    self.mark_statement(*span);
                    let v = self.expr(e)?;
                    let p = self.local_place(*local)?;
                    self.write(&p, &v)?;
                }
                false
            }
            Stmt::Block(b) => {
                self.block(b)?;
                false
            }
            Stmt::If {
                cond,
                then,
                else_,
                span,
            } => {
                if let Some(taken) = const_bool(cond) {
                    // Only the taken branch exists (it may call functions
                    // that have no body in the other).
                    self.block(if taken { then } else { else_ })?;
                    self.next_reg = mark;
                    return Ok(false);
                }
                self.mark_statement(*span);
                let c = self.expr(cond)?;
                let c = self.copy(&c[..1.min(c.len())])?;
                let Some(&c) = c.first() else {
                    return unsupported("if condition has no value");
                };
                let s = self.new_slot();
                self.emit(Op::SaveMask { slot: s })?;
                self.ctx.push((CtxKind::If, s));
                self.emit(Op::AndMask { c })?;
                let j1 = self.pc();
                self.emit(Op::JumpIfNone { target: 0 })?;
                self.block(then)?;
                if else_.is_empty() {
                    let end = self.pc();
                    self.patch(j1, end);
                } else {
                    let else_at = self.pc();
                    self.patch(j1, else_at);
                    self.emit(Op::AndNotMask { slot: s, c })?;
                    let j2 = self.pc();
                    self.emit(Op::JumpIfNone { target: 0 })?;
                    self.block(else_)?;
                    let end = self.pc();
                    self.patch(j2, end);
                }
                self.emit(Op::RestoreMask { slot: s })?;
                self.ctx.pop();
                false
            }
            Stmt::Loop {
                body, continuing, ..
            } => {
                let entry = self.new_slot();
                self.emit(Op::SaveMask { slot: entry })?;
                self.ctx.push((CtxKind::LoopEntry, entry));
                let run = self.new_slot();
                self.emit(Op::SaveMask { slot: run })?;
                self.ctx.push((CtxKind::LoopRun, run));
                let head = self.pc();
                self.emit(Op::RestoreMask { slot: run })?;
                let jexit = self.pc();
                self.emit(Op::JumpIfNone { target: 0 })?;
                self.emit(Op::LoopIter)?;
                self.block(body)?;
                self.emit(Op::RestoreMask { slot: run })?;
                self.block(continuing)?;
                self.emit(Op::Jump { target: head })?;
                let exit = self.pc();
                self.patch(jexit, exit);
                self.ctx.pop();
                self.ctx.pop();
                self.emit(Op::RestoreMask { slot: entry })?;
                false
            }
            Stmt::Break(span) => {
                self.mark_statement(*span);
                let slots = self.kill_list(|k| k == CtxKind::LoopRun, true)?;
                self.kill(slots, false)?;
                true
            }
            Stmt::Continue(span) => {
                self.mark_statement(*span);
                let slots = self.kill_list(|k| k == CtxKind::LoopRun, false)?;
                self.kill(slots, false)?;
                true
            }
            Stmt::Return(value, span) => {
                self.mark_statement(*span);
                if let Some(e) = value {
                    let v = self.expr(e)?;
                    let ret = self
                        .frames
                        .last()
                        .map(|f| f.ret.clone())
                        .unwrap_or_default();
                    if ret.len() != v.len() {
                        return unsupported("return value of the wrong size");
                    }
                    for (d, a) in ret.into_iter().zip(v) {
                        self.emit(Op::Store { d, a })?;
                    }
                }
                let slots = self.kill_list(|k| k == CtxKind::Function, false)?;
                self.kill(slots, false)?;
                true
            }
            Stmt::Discard(span) => {
                self.mark_statement(*span);
                let slots: Vec<u32> = self.ctx.iter().map(|c| c.1).collect();
                self.kill(slots, true)?;
                true
            }
        };
        self.next_reg = mark;
        Ok(ends)
    }

    /// The mask slots from the innermost context out to the first one for
    /// which `target` holds (included when `inclusive`).
    fn kill_list(&self, target: impl Fn(CtxKind) -> bool, inclusive: bool) -> R<Vec<u32>> {
        let mut out = Vec::new();
        for &(kind, slot) in self.ctx.iter().rev() {
            if target(kind) {
                if inclusive {
                    out.push(slot);
                }
                return Ok(out);
            }
            if kind == CtxKind::Function {
                break;
            }
            out.push(slot);
        }
        unsupported("break or continue outside a loop")
    }

    fn kill(&mut self, slots: Vec<u32>, discard: bool) -> R<()> {
        let start = self.p.kill_slots.len() as u32;
        self.p.kill_slots.extend(slots);
        let end = self.p.kill_slots.len() as u32;
        self.emit(if discard {
            Op::Discard { start, end }
        } else {
            Op::Kill { start, end }
        })
    }

    // ---- places --------------------------------------------------------

    fn local_place(&mut self, l: LocalId) -> R<Place> {
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
        })
    }

    fn global_place(&mut self, g: GlobalId) -> R<Place> {
        let i = g.0 as usize;
        let Some(global) = self.m.globals.get(i) else {
            return unsupported("unknown global variable");
        };
        self.used[i] = true;
        let ty = global.ty;
        let size = self.size(ty)? as u32;
        let root = match self.globals[i] {
            GlobalLoc::Reg(r) => Root::Reg(r),
            GlobalLoc::Uniform(_) => Root::Uniform(self.uniform_word(g)?),
        };
        Ok(Place {
            root,
            size,
            ty,
            off: 0,
            dynamic: None,
            comps: None,
        })
    }

    fn global_by_name(&mut self, name: &str) -> R<Place> {
        match self.m.globals.iter().position(|g| g.name == name) {
            Some(i) => self.global_place(GlobalId(i as u32)),
            None => unsupported(format!("`{name}' is not declared")),
        }
    }

    fn place(&mut self, e: &Expr) -> R<Place> {
        match &e.kind {
            ExprKind::Global(g) => self.global_place(*g),
            ExprKind::Local(l) => self.local_place(*l),
            ExprKind::Index { base, index } => {
                let p = self.place(base)?;
                if let Some(i) = self.const_int(index) {
                    return self.index_const(p, i);
                }
                let i = self.expr(index)?;
                let Some(&i) = i.first() else {
                    return unsupported("index without a value");
                };
                self.index_dynamic(p, i)
            }
            ExprKind::Member { base, index } => {
                let mut p = self.place(base)?;
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

    fn index_dynamic(&mut self, mut p: Place, i: Reg) -> R<Place> {
        let (d, span, elem) = if let Some(comps) = p.comps.take() {
            // `v.zyx[i]`: the component offset is looked up per lane from
            // the swizzle, so the place stays writable.
            let Some((&first, rest)) = comps.split_first() else {
                return unsupported("indexing an empty swizzle");
            };
            let k = self.temp()?;
            self.emit(Op::ClampIdx {
                d: k,
                a: i,
                max: rest.len() as u32,
                stride: 1,
            })?;
            let mut d = self.konst(first)?;
            for (j, &c) in rest.iter().enumerate() {
                let jr = self.konst(j as u32 + 1)?;
                let eq = self.temp()?;
                self.emit(Op::IEq { d: eq, a: k, b: jr })?;
                let cr = self.konst(c)?;
                let sel = self.temp()?;
                self.emit(Op::Select {
                    d: sel,
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
            let d = self.temp()?;
            self.emit(Op::ClampIdx {
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
                let sum = self.temp()?;
                self.emit(Op::IAdd {
                    d: sum,
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

    fn read(&mut self, p: &Place) -> R<Val> {
        let comps = self.place_comps(p)?;
        let mut out = Vec::with_capacity(comps.len());
        for c in comps {
            let pos = p.off + c;
            let r = match (p.root, p.dynamic) {
                (Root::Reg(r), None) => r + pos,
                (Root::Reg(r), Some((off, max))) => {
                    let d = self.temp()?;
                    self.emit(Op::Gather {
                        d,
                        base: r + pos,
                        off,
                        max,
                    })?;
                    d
                }
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
    fn write(&mut self, p: &Place, v: &[Reg]) -> R<()> {
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

    // ---- expressions -------------------------------------------------

    /// Evaluates operands left to right; a value is copied to temporaries
    /// when a later operand has side effects (which could change it).
    fn operands(&mut self, es: &[&Expr]) -> R<Vec<Val>> {
        let mut out = Vec::with_capacity(es.len());
        for (i, e) in es.iter().enumerate() {
            let v = self.expr(e)?;
            let later = es[i + 1..].iter().any(|e| has_effects(e));
            out.push(if later { self.copy(&v)? } else { v });
        }
        Ok(out)
    }

    fn expr(&mut self, e: &Expr) -> R<Val> {
        if e.ty.is_error() {
            return unsupported("expression with an error type");
        }
        match &e.kind {
            ExprKind::Const(v) => {
                let mut out = Vec::with_capacity(v.components.len());
                for c in &v.components {
                    out.push(self.konst(const_bits(*c))?);
                }
                Ok(out)
            }
            ExprKind::Global(_)
            | ExprKind::Local(_)
            | ExprKind::Index { .. }
            | ExprKind::Member { .. }
            | ExprKind::Swizzle { .. } => {
                let p = self.place(e)?;
                self.read(&p)
            }
            ExprKind::Unary { op, operand } => {
                let v = self.expr(operand)?;
                let kind = kind_of(operand.ty);
                let out = self.temps(v.len())?;
                for (&d, &a) in out.iter().zip(&v) {
                    self.emit(match (op, kind) {
                        (UnaryOp::Neg, Scalar::Float) => Op::FNeg { d, a },
                        (UnaryOp::Neg, _) => Op::INeg { d, a },
                        (UnaryOp::Not, _) => Op::Not { d, a },
                    })?;
                }
                Ok(out)
            }
            ExprKind::Binary { op, left, right } => self.binary(*op, left, right, e.ty),
            ExprKind::Ternary {
                cond,
                accept,
                reject,
            } => self.ternary(cond, accept, reject, e.ty),
            ExprKind::Assign { op, target, value } => {
                let p = self.place(target)?;
                let v = match op {
                    None => self.expr(value)?,
                    Some(op) => {
                        let old = self.read(&p)?;
                        let old = if has_effects(value) {
                            self.copy(&old)?
                        } else {
                            old
                        };
                        let v = self.expr(value)?;
                        self.arith(*op, &old, p.ty, &v, value.ty, target.ty)?
                    }
                };
                self.write(&p, &v)?;
                Ok(v)
            }
            ExprKind::IncDec { op, target } => {
                let p = self.place(target)?;
                let old = self.read(&p)?;
                let old = self.copy(&old)?;
                let kind = kind_of(p.ty);
                let one = match kind {
                    Scalar::Float => self.fconst(1.0)?,
                    _ => self.konst(1)?,
                };
                let new = self.temps(old.len())?;
                let inc = matches!(op, IncDec::PreInc | IncDec::PostInc);
                for (&d, &a) in new.iter().zip(&old) {
                    self.emit(match (kind, inc) {
                        (Scalar::Float, true) => Op::FAdd { d, a, b: one },
                        (Scalar::Float, false) => Op::FSub { d, a, b: one },
                        (_, true) => Op::IAdd { d, a, b: one },
                        (_, false) => Op::ISub { d, a, b: one },
                    })?;
                }
                self.write(&p, &new)?;
                Ok(match op {
                    IncDec::PreInc | IncDec::PreDec => new,
                    IncDec::PostInc | IncDec::PostDec => old,
                })
            }
            ExprKind::Call { function, args } => self.call(*function, args),
            ExprKind::Builtin { function, args } => self.builtin(*function, args, e.ty),
            ExprKind::Construct { args } => self.construct(e.ty, args),
            ExprKind::DebugPrintf { format, args } => {
                let mut regs = Vec::new();
                for a in args {
                    regs.extend(self.expr(a)?);
                }
                let index = self.p.printfs.len() as u32;
                self.p.printfs.push(PrintfSite {
                    format: format.clone(),
                    args: regs,
                    span: e.span,
                });
                self.emit(Op::Printf { index })?;
                Ok(Vec::new())
            }
            ExprKind::Convert { operand } => {
                let v = self.expr(operand)?;
                let from = kinds(operand.ty, &self.m.structs);
                let to = kind_of(e.ty);
                let mut out = Vec::with_capacity(v.len());
                for (k, &a) in v.iter().enumerate() {
                    let f = from.get(k).copied().unwrap_or(Scalar::Float);
                    out.push(self.convert(a, f, to)?);
                }
                Ok(out)
            }
            ExprKind::Comma { left, right } => {
                self.expr(left)?;
                self.expr(right)
            }
        }
    }

    /// Converts one scalar register (GLSL 1.20 §5.4.1).
    fn convert(&mut self, a: Reg, from: Scalar, to: Scalar) -> R<Reg> {
        let op = match (from, to) {
            (Scalar::Float, Scalar::Float)
            | (Scalar::Int, Scalar::Int)
            | (Scalar::Bool, Scalar::Bool)
            | (Scalar::Bool, Scalar::Int) => return Ok(a),
            (Scalar::Float, Scalar::Int) => Op::FToI { d: 0, a },
            (Scalar::Float, Scalar::Bool) => Op::FToB { d: 0, a },
            (Scalar::Int, Scalar::Float) => Op::IToF { d: 0, a },
            (Scalar::Int, Scalar::Bool) => Op::IToB { d: 0, a },
            (Scalar::Bool, Scalar::Float) => Op::BToF { d: 0, a },
        };
        let d = self.temp()?;
        self.emit(match op {
            Op::FToI { a, .. } => Op::FToI { d, a },
            Op::FToB { a, .. } => Op::FToB { d, a },
            Op::IToF { a, .. } => Op::IToF { d, a },
            Op::IToB { a, .. } => Op::IToB { d, a },
            Op::BToF { a, .. } => Op::BToF { d, a },
            other => other,
        })?;
        Ok(d)
    }

    /// Component-wise arithmetic with scalar broadcasting, or a
    /// linear-algebra product.
    fn arith(
        &mut self,
        op: BinaryOp,
        a: &[Reg],
        aty: Type,
        b: &[Reg],
        bty: Type,
        rty: Type,
    ) -> R<Val> {
        if op == BinaryOp::MatMul {
            return self.matmul(a, aty, b, bty);
        }
        let n = a.len().max(b.len());
        if !(a.len() == b.len() || a.len() == 1 || b.len() == 1) || n == 0 {
            return unsupported("operands of different sizes");
        }
        let kind = kind_of(rty);
        let out = self.temps(n)?;
        for (i, &d) in out.iter().enumerate() {
            let x = a[if a.len() == 1 { 0 } else { i }];
            let y = b[if b.len() == 1 { 0 } else { i }];
            self.emit(match (op, kind) {
                (BinaryOp::Add, Scalar::Float) => Op::FAdd { d, a: x, b: y },
                (BinaryOp::Sub, Scalar::Float) => Op::FSub { d, a: x, b: y },
                (BinaryOp::Mul, Scalar::Float) => Op::FMul { d, a: x, b: y },
                (BinaryOp::Div, Scalar::Float) => Op::FDiv { d, a: x, b: y },
                (BinaryOp::Add, _) => Op::IAdd { d, a: x, b: y },
                (BinaryOp::Sub, _) => Op::ISub { d, a: x, b: y },
                (BinaryOp::Mul, _) => Op::IMul { d, a: x, b: y },
                (BinaryOp::Div, _) => Op::IDiv { d, a: x, b: y },
                _ => return unsupported(format!("{op:?} is not arithmetic")),
            })?;
        }
        Ok(out)
    }

    /// Matrix products, summed in index order from 0.0 without fused
    /// multiply-add (the order of `glsl::consteval`).
    fn matmul(&mut self, a: &[Reg], aty: Type, b: &[Reg], bty: Type) -> R<Val> {
        let (lc, lr) = match aty.base {
            Base::Matrix { cols, rows } => (cols as usize, rows as usize),
            Base::Vector(_, n) => (n as usize, 1),
            _ => return unsupported("matrix product of a non-matrix"),
        };
        let (rc, rr) = match bty.base {
            Base::Matrix { cols, rows } => (cols as usize, rows as usize),
            Base::Vector(_, n) => (1, n as usize),
            _ => return unsupported("matrix product of a non-matrix"),
        };
        if lc != rr || a.len() != lc * lr || b.len() != rc * rr {
            return unsupported("matrix product of mismatched shapes");
        }
        let out = self.temps(rc * lr)?;
        for c in 0..rc {
            for row in 0..lr {
                let d = out[c * lr + row];
                let pairs: Vec<(Reg, Reg)> =
                    (0..lc).map(|k| (a[k * lr + row], b[c * rr + k])).collect();
                self.emit_dot(d, &pairs)?;
            }
        }
        Ok(out)
    }

    /// Whole-value equality: one bool register.
    fn equal(&mut self, a: &[Reg], b: &[Reg], ty: Type) -> R<Reg> {
        let ks = kinds(ty, &self.m.structs);
        if a.len() != b.len() {
            return unsupported("comparing values of different sizes");
        }
        let mut acc: Option<Reg> = None;
        for (i, (&x, &y)) in a.iter().zip(b).enumerate() {
            let d = self.temp()?;
            self.emit(match ks.get(i) {
                Some(Scalar::Float) => Op::FEq { d, a: x, b: y },
                _ => Op::IEq { d, a: x, b: y },
            })?;
            acc = Some(match acc {
                None => d,
                Some(prev) => {
                    let r = self.temp()?;
                    self.emit(Op::And {
                        d: r,
                        a: prev,
                        b: d,
                    })?;
                    r
                }
            });
        }
        match acc {
            Some(r) => Ok(r),
            None => self.konst(1),
        }
    }

    fn binary(&mut self, op: BinaryOp, left: &Expr, right: &Expr, ty: Type) -> R<Val> {
        if matches!(op, BinaryOp::LogicalAnd | BinaryOp::LogicalOr) && has_effects(right) {
            // Lazy: the right operand runs only on the lanes it decides.
            let a = self.expr(left)?;
            let Some(&a) = a.first() else {
                return unsupported("logical operand without a value");
            };
            let result = self.temp()?;
            self.emit(Op::Mov { d: result, a })?;
            let s = self.new_slot();
            self.emit(Op::SaveMask { slot: s })?;
            self.ctx.push((CtxKind::If, s));
            if op == BinaryOp::LogicalAnd {
                self.emit(Op::AndMask { c: result })?;
            } else {
                self.emit(Op::AndNotMask { slot: s, c: result })?;
            }
            let j = self.pc();
            self.emit(Op::JumpIfNone { target: 0 })?;
            let b = self.expr(right)?;
            let Some(&b) = b.first() else {
                return unsupported("logical operand without a value");
            };
            self.emit(Op::Store { d: result, a: b })?;
            let end = self.pc();
            self.patch(j, end);
            self.emit(Op::RestoreMask { slot: s })?;
            self.ctx.pop();
            return Ok(vec![result]);
        }
        let vals = self.operands(&[left, right])?;
        let (a, b) = (&vals[0], &vals[1]);
        let scalar = |v: &Val| v.first().copied();
        let two = |x: Option<Reg>, y: Option<Reg>| match (x, y) {
            (Some(x), Some(y)) => Ok((x, y)),
            _ => unsupported("comparison operand without a value"),
        };
        match op {
            BinaryOp::Add | BinaryOp::Sub | BinaryOp::Mul | BinaryOp::Div | BinaryOp::MatMul => {
                self.arith(op, a, left.ty, b, right.ty, ty)
            }
            BinaryOp::Less | BinaryOp::Greater | BinaryOp::LessEq | BinaryOp::GreaterEq => {
                let (x, y) = two(scalar(a), scalar(b))?;
                let d = self.temp()?;
                let float = kind_of(left.ty) == Scalar::Float;
                self.emit(match (op, float) {
                    (BinaryOp::Less, true) => Op::FLt { d, a: x, b: y },
                    (BinaryOp::Greater, true) => Op::FLt { d, a: y, b: x },
                    (BinaryOp::LessEq, true) => Op::FLe { d, a: x, b: y },
                    (_, true) => Op::FLe { d, a: y, b: x },
                    (BinaryOp::Less, false) => Op::ILt { d, a: x, b: y },
                    (BinaryOp::Greater, false) => Op::ILt { d, a: y, b: x },
                    (BinaryOp::LessEq, false) => Op::ILe { d, a: x, b: y },
                    (_, false) => Op::ILe { d, a: y, b: x },
                })?;
                Ok(vec![d])
            }
            BinaryOp::Equal | BinaryOp::NotEqual => {
                let eq = self.equal(a, b, left.ty)?;
                if op == BinaryOp::Equal {
                    Ok(vec![eq])
                } else {
                    let d = self.temp()?;
                    self.emit(Op::Not { d, a: eq })?;
                    Ok(vec![d])
                }
            }
            BinaryOp::LogicalAnd | BinaryOp::LogicalOr | BinaryOp::LogicalXor => {
                let (x, y) = two(scalar(a), scalar(b))?;
                let d = self.temp()?;
                self.emit(match op {
                    BinaryOp::LogicalAnd => Op::And { d, a: x, b: y },
                    BinaryOp::LogicalOr => Op::Or { d, a: x, b: y },
                    _ => Op::Xor { d, a: x, b: y },
                })?;
                Ok(vec![d])
            }
        }
    }

    fn ternary(&mut self, cond: &Expr, accept: &Expr, reject: &Expr, ty: Type) -> R<Val> {
        if has_effects(accept) || has_effects(reject) {
            let c = self.expr(cond)?;
            let c = self.copy(&c[..1.min(c.len())])?;
            let Some(&c) = c.first() else {
                return unsupported("condition without a value");
            };
            let n = self.size(ty)?;
            let result = self.temps(n)?;
            let s = self.new_slot();
            self.emit(Op::SaveMask { slot: s })?;
            self.ctx.push((CtxKind::If, s));
            self.emit(Op::AndMask { c })?;
            let j1 = self.pc();
            self.emit(Op::JumpIfNone { target: 0 })?;
            self.store_operand(accept, &result)?;
            let else_at = self.pc();
            self.patch(j1, else_at);
            self.emit(Op::AndNotMask { slot: s, c })?;
            let j2 = self.pc();
            self.emit(Op::JumpIfNone { target: 0 })?;
            self.store_operand(reject, &result)?;
            let end = self.pc();
            self.patch(j2, end);
            self.emit(Op::RestoreMask { slot: s })?;
            self.ctx.pop();
            return Ok(result);
        }
        let vals = self.operands(&[cond, accept, reject])?;
        let (Some(&c), a, b) = (vals[0].first(), &vals[1], &vals[2]) else {
            return unsupported("condition without a value");
        };
        if a.len() != b.len() {
            return unsupported("?: operands of different sizes");
        }
        let out = self.temps(a.len())?;
        for ((&d, &x), &y) in out.iter().zip(a).zip(b) {
            self.emit(Op::Select { d, c, a: x, b: y })?;
        }
        Ok(out)
    }

    fn call(&mut self, fid: FunctionId, args: &[Expr]) -> R<Val> {
        let m = self.m;
        let Some(f) = m.functions.get(fid.0 as usize) else {
            return unsupported("call of an unknown function");
        };
        let Some(body) = &f.body else {
            return unsupported(format!("`{}' has no body", f.name));
        };
        if self.frames.iter().any(|fr| fr.func == fid) {
            return unsupported(format!("`{}' is recursive", f.name));
        }
        if self.frames.len() >= MAX_CALL_DEPTH {
            return unsupported("calls nested too deeply");
        }
        if f.params.len() != args.len() {
            return unsupported(format!("`{}' called with the wrong arguments", f.name));
        }
        let sub = match &self.subs {
            Some(subs) => match subs.get(fid.0 as usize) {
                Some(Some(sub)) => Some(sub.clone()),
                _ => return unsupported(format!("`{}' was not lowered", f.name)),
            },
            None => None,
        };
        let locals = match &sub {
            Some(s) => s.locals.clone(),
            None => self.alloc_locals(fid)?,
        };
        // Arguments, left to right (§6.1.1).
        let mut outs: Vec<(Place, Reg, u32)> = Vec::new();
        let mut bound = vec![None; locals.len()];
        for (param, arg) in f.params.iter().zip(args) {
            let Some(&(preg, _)) = locals.get(param.local.0 as usize) else {
                return unsupported("parameter without a local");
            };
            let n = self.size(param.ty)? as u32;
            match param.qualifier {
                ParamQualifier::In => {
                    // An int argument known here, in a parameter the body
                    // never writes: the callee's indexing by it is static
                    // (`gl_LightSource[light]` with a constant `light`).
                    if sub.is_none() && param.ty == Type::INT && !writes_local(m, body, param.local)
                    {
                        if let Some(slot) = bound.get_mut(param.local.0 as usize) {
                            *slot = self.const_int(arg);
                        }
                    }
                    let v = self.expr(arg)?;
                    if v.len() as u32 != n {
                        return unsupported("argument of the wrong size");
                    }
                    for (k, a) in v.into_iter().enumerate() {
                        self.emit(Op::Store {
                            d: preg + k as u32,
                            a,
                        })?;
                    }
                }
                ParamQualifier::Out | ParamQualifier::InOut => {
                    let p = self.place(arg)?;
                    if param.qualifier == ParamQualifier::InOut {
                        let v = self.read(&p)?;
                        if v.len() as u32 != n {
                            return unsupported("argument of the wrong size");
                        }
                        for (k, a) in v.into_iter().enumerate() {
                            self.emit(Op::Store {
                                d: preg + k as u32,
                                a,
                            })?;
                        }
                    }
                    outs.push((p, preg, n));
                }
            }
        }
        if let Some(sub) = sub {
            self.emit(Op::Call {
                target: sub.entry,
                slot: sub.slot,
            })?;
            if self.stage == Stage::Fragment {
                // Lanes the callee discarded leave the caller's masks too.
                let slots: Vec<u32> = self.ctx.iter().map(|c| c.1).collect();
                let start = self.p.kill_slots.len() as u32;
                self.p.kill_slots.extend(slots);
                let end = self.p.kill_slots.len() as u32;
                self.emit(Op::SyncDiscard { start, end })?;
            }
            // The result is copied: another call would overwrite it.
            let ret = self.copy(&sub.ret)?;
            for (p, preg, n) in outs {
                let v: Val = (preg..preg + n).collect();
                self.write(&p, &v)?;
            }
            return Ok(ret);
        }
        let ret = if f.return_type.is_void() {
            Vec::new()
        } else {
            let n = self.size(f.return_type)?;
            self.temps(n)?
        };
        let fs = self.new_slot();
        self.emit(Op::SaveMask { slot: fs })?;
        self.ctx.push((CtxKind::Function, fs));
        self.frames.push(Frame {
            func: fid,
            consts: bound,
            locals,
            ret: ret.clone(),
        });
        let r = self.block(body);
        self.frames.pop();
        self.ctx.pop();
        r?;
        self.emit(Op::RestoreMask { slot: fs })?;
        for (p, preg, n) in outs {
            let v: Val = (preg..preg + n).collect();
            self.write(&p, &v)?;
        }
        Ok(ret)
    }

    /// Lowers every function reachable from `main` once, callees first,
    /// before `main`'s code (jumped over), and switches calls to them.
    fn lower_subroutines(&mut self, main: FunctionId) -> R<()> {
        let m = self.m;
        // Post-order of the call graph (an acyclic graph: no recursion).
        let n = m.functions.len();
        let mut state = vec![0u8; n]; // 0 new, 1 open, 2 done
        let mut order = Vec::new();
        let mut stack: Vec<(FunctionId, Vec<FunctionId>)> = Vec::new();
        let callees = |f: FunctionId| {
            let mut out = Vec::new();
            if let Some(b) = m.functions.get(f.0 as usize).and_then(|f| f.body.as_ref()) {
                visit_live_block(b, &mut |e| {
                    if let ExprKind::Call { function, .. } = &e.kind {
                        out.push(*function);
                    }
                });
            }
            out.reverse();
            out
        };
        stack.push((main, callees(main)));
        state[main.0 as usize] = 1;
        while let Some((f, pending)) = stack.last_mut() {
            match pending.pop() {
                Some(c) => match state.get(c.0 as usize) {
                    Some(0) => {
                        state[c.0 as usize] = 1;
                        let cs = callees(c);
                        stack.push((c, cs));
                    }
                    Some(1) => return unsupported("recursive function calls"),
                    Some(_) => {}
                    None => return unsupported("call of an unknown function"),
                },
                None => {
                    let f = *f;
                    state[f.0 as usize] = 2;
                    if f != main {
                        order.push(f);
                    }
                    stack.pop();
                }
            }
        }
        self.subs = Some(vec![None; n]);
        let jump = self.pc();
        self.emit(Op::Jump { target: 0 })?;
        for (slot, &f) in order.iter().enumerate() {
            let func = &m.functions[f.0 as usize];
            let Some(body) = &func.body else {
                return unsupported(format!("`{}' has no body", func.name));
            };
            let locals = self.alloc_locals(f)?;
            let ret = if func.return_type.is_void() {
                Vec::new()
            } else {
                let n = self.size(func.return_type)?;
                self.temps(n)?
            };
            let entry = self.pc();
            let fs = self.new_slot();
            self.emit(Op::SaveMask { slot: fs })?;
            // Calls count against the loop budget: a call tree that doubles
            // at every level (2^64 calls) must not hang.
            self.emit(Op::LoopIter)?;
            self.ctx.push((CtxKind::Function, fs));
            self.frames.push(Frame {
                func: f,
                consts: vec![None; locals.len()],
                locals: locals.clone(),
                ret: ret.clone(),
            });
            let r = self.block(body);
            self.frames.pop();
            self.ctx.pop();
            r?;
            self.emit(Op::RestoreMask { slot: fs })?;
            self.emit(Op::Ret { slot: slot as u32 })?;
            // This body's temporaries stay reserved: callers' live values
            // must not share them.
            self.next_reg = self.p.registers;
            if let Some(subs) = &mut self.subs {
                subs[f.0 as usize] = Some(Sub {
                    entry,
                    slot: slot as u32,
                    locals,
                    ret,
                });
            }
        }
        self.p.subroutines = order.len() as u32;
        let here = self.pc();
        self.patch(jump, here);
        Ok(())
    }

    fn construct(&mut self, ty: Type, args: &[Expr]) -> R<Val> {
        let refs: Vec<&Expr> = args.iter().collect();
        let vals = self.operands(&refs)?;
        if ty.is_array() || ty.is_struct() {
            return Ok(vals.into_iter().flatten().collect());
        }
        let target = kind_of(ty);
        let size = self.size(ty)?;
        // Scalar kind of every argument component.
        let mut comps: Vec<(Reg, Scalar)> = Vec::new();
        for (a, v) in args.iter().zip(&vals) {
            let ks = kinds(a.ty, &self.m.structs);
            for (k, &r) in v.iter().enumerate() {
                comps.push((r, ks.get(k).copied().unwrap_or(Scalar::Float)));
            }
        }
        let single = args.len() == 1 && comps.len() == 1;
        match ty.base {
            Base::Scalar(_) | Base::Vector(..) if single => {
                let (r, k) = comps[0];
                let c = self.convert(r, k, target)?;
                return Ok(vec![c; size]);
            }
            Base::Matrix { cols, rows } => {
                let (cols, rows) = (cols as usize, rows as usize);
                if single {
                    let (r, k) = comps[0];
                    let d = self.convert(r, k, Scalar::Float)?;
                    let zero = self.fconst(0.0)?;
                    let mut out = vec![zero; size];
                    for i in 0..cols.min(rows) {
                        out[i * rows + i] = d;
                    }
                    return Ok(out);
                }
                if let (1, Some(Base::Matrix { cols: sc, rows: sr })) =
                    (args.len(), args.first().map(|a| a.ty.base))
                {
                    let (sc, sr) = (sc as usize, sr as usize);
                    let zero = self.fconst(0.0)?;
                    let one = self.fconst(1.0)?;
                    let mut out = Vec::with_capacity(size);
                    for c in 0..cols {
                        for r in 0..rows {
                            out.push(if c < sc && r < sr {
                                vals[0].get(c * sr + r).copied().unwrap_or(zero)
                            } else if c == r {
                                one
                            } else {
                                zero
                            });
                        }
                    }
                    return Ok(out);
                }
            }
            Base::Scalar(_) | Base::Vector(..) => {}
            _ => return unsupported("constructor of an unsupported type"),
        }
        if comps.len() < size {
            return unsupported("constructor with too few components");
        }
        let mut out = Vec::with_capacity(size);
        for &(r, k) in comps.iter().take(size) {
            out.push(self.convert(r, k, target)?);
        }
        Ok(out)
    }

    // ---- built-in functions ------------------------------------------

    /// Component-wise application with scalar broadcasting.
    fn map(&mut self, args: &[&Val], mut f: impl FnMut(Reg, &[Reg]) -> Op) -> R<Val> {
        let n = args.iter().map(|a| a.len()).max().unwrap_or(0);
        if n == 0 || args.iter().any(|a| a.len() != n && a.len() != 1) {
            return unsupported("built-in arguments of different sizes");
        }
        let out = self.temps(n)?;
        let mut ins = Vec::with_capacity(args.len());
        for (i, &d) in out.iter().enumerate() {
            ins.clear();
            ins.extend(args.iter().map(|a| a[if a.len() == 1 { 0 } else { i }]));
            let op = f(d, &ins);
            self.emit(op)?;
        }
        Ok(out)
    }

    fn map1(&mut self, a: &Val, f: F1) -> R<Val> {
        self.map(&[a], |d, x| Op::F1 { f, d, a: x[0] })
    }

    fn map2(&mut self, a: &Val, b: &Val, f: F2) -> R<Val> {
        self.map(&[a, b], |d, x| Op::F2 {
            f,
            d,
            a: x[0],
            b: x[1],
        })
    }

    fn map3(&mut self, a: &Val, b: &Val, c: &Val, f: F3) -> R<Val> {
        self.map(&[a, b, c], |d, x| Op::F3 {
            f,
            d,
            a: x[0],
            b: x[1],
            c: x[2],
        })
    }

    /// `dot`, summed left to right from 0.0 like `glsl::math::dot`.
    fn dot(&mut self, a: &[Reg], b: &[Reg]) -> R<Reg> {
        let d = self.temp()?;
        let pairs: Vec<(Reg, Reg)> = a.iter().copied().zip(b.iter().copied()).collect();
        self.emit_dot(d, &pairs)?;
        Ok(d)
    }

    /// `d = 0.0`, then `d += a * b` for each pair in order: one
    /// [`Op::Dot`] for up to 4 pairs, else a [`Op::FMac`] chain.
    fn emit_dot(&mut self, d: Reg, pairs: &[(Reg, Reg)]) -> R<()> {
        if (1..=4).contains(&pairs.len()) {
            let mut a = [0; 4];
            let mut b = [0; 4];
            for (k, &(x, y)) in pairs.iter().enumerate() {
                a[k] = x;
                b[k] = y;
            }
            return self.emit(Op::Dot {
                d,
                n: pairs.len() as u8,
                a,
                b,
            });
        }
        self.emit(Op::Const {
            d,
            bits: 0.0f32.to_bits(),
        })?;
        for &(x, y) in pairs {
            self.emit(Op::FMac { d, a: x, b: y })?;
        }
        Ok(())
    }

    fn sqrt(&mut self, a: Reg) -> R<Reg> {
        let d = self.temp()?;
        self.emit(Op::F1 { f: F1::Sqrt, d, a })?;
        Ok(d)
    }

    fn fbin(&mut self, mk: fn(Reg, Reg, Reg) -> Op, a: Reg, b: Reg) -> R<Reg> {
        let d = self.temp()?;
        self.emit(mk(d, a, b))?;
        Ok(d)
    }

    fn builtin(&mut self, f: BuiltinFn, args: &[Expr], ty: Type) -> R<Val> {
        use BuiltinFn as B;
        if is_texture(f) {
            return self.texture(f, args);
        }
        if f == B::Ftransform {
            let mvp = self.global_by_name("gl_ModelViewProjectionMatrix")?;
            let vertex = self.global_by_name("gl_Vertex")?;
            let a = self.read(&mvp)?;
            let b = self.read(&vertex)?;
            return self.matmul(&a, mvp.ty, &b, vertex.ty);
        }
        let refs: Vec<&Expr> = args.iter().collect();
        let v = self.operands(&refs)?;
        let arg = |i: usize| -> R<&Val> {
            match v.get(i) {
                Some(x) if !x.is_empty() => Ok(x),
                _ => unsupported(format!("{} is missing an argument", f.name())),
            }
        };
        let fmul = |d, a, b| Op::FMul { d, a, b };
        let fsub = |d, a, b| Op::FSub { d, a, b };
        let fadd = |d, a, b| Op::FAdd { d, a, b };
        let flt = |d, a, b| Op::FLt { d, a, b };
        match f {
            B::Radians => self.map1(arg(0)?, F1::Radians),
            B::Degrees => self.map1(arg(0)?, F1::Degrees),
            B::Sin => self.map1(arg(0)?, F1::Sin),
            B::Cos => self.map1(arg(0)?, F1::Cos),
            B::Tan => self.map1(arg(0)?, F1::Tan),
            B::Asin => self.map1(arg(0)?, F1::Asin),
            B::Acos => self.map1(arg(0)?, F1::Acos),
            B::Atan if args.len() == 1 => self.map1(arg(0)?, F1::Atan),
            B::Atan => self.map2(arg(0)?, arg(1)?, F2::Atan2),
            B::Pow => self.map2(arg(0)?, arg(1)?, F2::Pow),
            B::Exp => self.map1(arg(0)?, F1::Exp),
            B::Log => self.map1(arg(0)?, F1::Log),
            B::Exp2 => self.map1(arg(0)?, F1::Exp2),
            B::Log2 => self.map1(arg(0)?, F1::Log2),
            B::Sqrt => self.map1(arg(0)?, F1::Sqrt),
            B::InverseSqrt => self.map1(arg(0)?, F1::InverseSqrt),
            B::Abs => self.map1(arg(0)?, F1::Abs),
            B::Sign => self.map1(arg(0)?, F1::Sign),
            B::Floor => self.map1(arg(0)?, F1::Floor),
            B::Ceil => self.map1(arg(0)?, F1::Ceil),
            B::Fract => self.map1(arg(0)?, F1::Fract),
            B::Mod => self.map2(arg(0)?, arg(1)?, F2::Mod),
            B::Min => self.map2(arg(0)?, arg(1)?, F2::Min),
            B::Max => self.map2(arg(0)?, arg(1)?, F2::Max),
            B::Clamp => self.map3(arg(0)?, arg(1)?, arg(2)?, F3::Clamp),
            B::Mix => self.map3(arg(0)?, arg(1)?, arg(2)?, F3::Mix),
            B::Step => self.map2(arg(0)?, arg(1)?, F2::Step),
            B::SmoothStep => self.map3(arg(0)?, arg(1)?, arg(2)?, F3::SmoothStep),
            B::Length => {
                let x = arg(0)?.clone();
                let d = self.dot(&x, &x)?;
                Ok(vec![self.sqrt(d)?])
            }
            B::Distance => {
                let (x, y) = (arg(0)?.clone(), arg(1)?.clone());
                if x.len() != y.len() {
                    return unsupported("distance of different sizes");
                }
                let diff = self.map(&[&x, &y], fsub_op)?;
                let d = self.dot(&diff, &diff)?;
                Ok(vec![self.sqrt(d)?])
            }
            B::Dot => {
                let (x, y) = (arg(0)?.clone(), arg(1)?.clone());
                Ok(vec![self.dot(&x, &y)?])
            }
            B::Cross => {
                let (x, y) = (arg(0)?.clone(), arg(1)?.clone());
                if x.len() != 3 || y.len() != 3 {
                    return unsupported("cross of non-vec3");
                }
                let mut out = Vec::with_capacity(3);
                for (i, j) in [(1, 2), (2, 0), (0, 1)] {
                    // x[i] * y[j] - y[i] * x[j]
                    let p = self.fbin(fmul, x[i], y[j])?;
                    let q = self.fbin(fmul, y[i], x[j])?;
                    out.push(self.fbin(fsub, p, q)?);
                }
                Ok(out)
            }
            B::Normalize => {
                let x = arg(0)?.clone();
                let d = self.dot(&x, &x)?;
                let len = self.sqrt(d)?;
                self.map(&[&x, &vec![len]], fdiv_op)
            }
            B::FaceForward => {
                let (n, i, nref) = (arg(0)?.clone(), arg(1)?.clone(), arg(2)?.clone());
                let d = self.dot(&nref, &i)?;
                let zero = self.fconst(0.0)?;
                let c = self.fbin(flt, d, zero)?;
                let neg = self.temps(n.len())?;
                for (&d, &a) in neg.iter().zip(&n) {
                    self.emit(Op::FNeg { d, a })?;
                }
                self.map(&[&vec![c], &n, &neg], |d, x| Op::Select {
                    d,
                    c: x[0],
                    a: x[1],
                    b: x[2],
                })
            }
            B::Reflect => {
                let (i, n) = (arg(0)?.clone(), arg(1)?.clone());
                let dt = self.dot(&n, &i)?;
                let two = self.fconst(2.0)?;
                let d = self.fbin(fmul, two, dt)?;
                let dn = self.map(&[&vec![d], &n], fmul_op)?;
                self.map(&[&i, &dn], fsub_op)
            }
            B::Refract => {
                let (i, n, eta) = (arg(0)?.clone(), arg(1)?.clone(), arg(2)?[0]);
                let d = self.dot(&n, &i)?;
                let one = self.fconst(1.0)?;
                let e2 = self.fbin(fmul, eta, eta)?;
                let dd = self.fbin(fmul, d, d)?;
                let om = self.fbin(fsub, one, dd)?;
                let t = self.fbin(fmul, e2, om)?;
                let k = self.fbin(fsub, one, t)?;
                let zero = self.fconst(0.0)?;
                let neg = self.fbin(flt, k, zero)?;
                let sk = self.sqrt(k)?;
                let ed = self.fbin(fmul, eta, d)?;
                let s = self.fbin(fadd, ed, sk)?;
                let ei = self.map(&[&vec![eta], &i], fmul_op)?;
                let sn = self.map(&[&vec![s], &n], fmul_op)?;
                let r = self.map(&[&ei, &sn], fsub_op)?;
                self.map(&[&vec![neg], &vec![zero], &r], |d, x| Op::Select {
                    d,
                    c: x[0],
                    a: x[1],
                    b: x[2],
                })
            }
            B::MatrixCompMult => self.map(&[arg(0)?, arg(1)?], fmul_op),
            B::OuterProduct => {
                let (c, r) = (arg(0)?.clone(), arg(1)?.clone());
                let mut out = Vec::with_capacity(c.len() * r.len());
                for &rj in &r {
                    for &ci in &c {
                        out.push(self.fbin(fmul, ci, rj)?);
                    }
                }
                Ok(out)
            }
            B::Transpose => {
                let Base::Matrix { cols, rows } = args[0].ty.base else {
                    return unsupported("transpose of a non-matrix");
                };
                let (cols, rows) = (cols as usize, rows as usize);
                let m = arg(0)?;
                if m.len() != cols * rows {
                    return unsupported("transpose of a malformed matrix");
                }
                Ok((0..rows)
                    .flat_map(|j| (0..cols).map(move |i| i * rows + j))
                    .map(|k| m[k])
                    .collect())
            }
            B::LessThan | B::LessThanEqual | B::GreaterThan | B::GreaterThanEqual => {
                let float = kind_of(args[0].ty) == Scalar::Float;
                let (x, y) = (arg(0)?.clone(), arg(1)?.clone());
                let (x, y) = if matches!(f, B::GreaterThan | B::GreaterThanEqual) {
                    (y, x)
                } else {
                    (x, y)
                };
                let strict = matches!(f, B::LessThan | B::GreaterThan);
                self.map(&[&x, &y], |d, v| match (float, strict) {
                    (true, true) => Op::FLt {
                        d,
                        a: v[0],
                        b: v[1],
                    },
                    (true, false) => Op::FLe {
                        d,
                        a: v[0],
                        b: v[1],
                    },
                    (false, true) => Op::ILt {
                        d,
                        a: v[0],
                        b: v[1],
                    },
                    (false, false) => Op::ILe {
                        d,
                        a: v[0],
                        b: v[1],
                    },
                })
            }
            B::Equal | B::NotEqual => {
                let float = kind_of(args[0].ty) == Scalar::Float;
                let eq = self.map(&[arg(0)?, arg(1)?], |d, v| {
                    if float {
                        Op::FEq {
                            d,
                            a: v[0],
                            b: v[1],
                        }
                    } else {
                        Op::IEq {
                            d,
                            a: v[0],
                            b: v[1],
                        }
                    }
                })?;
                if f == B::Equal {
                    Ok(eq)
                } else {
                    self.map(&[&eq], |d, v| Op::Not { d, a: v[0] })
                }
            }
            B::Any | B::All => {
                let x = arg(0)?.clone();
                let mut acc = x[0];
                for &c in &x[1..] {
                    let d = self.temp()?;
                    self.emit(if f == B::Any {
                        Op::Or { d, a: acc, b: c }
                    } else {
                        Op::And { d, a: acc, b: c }
                    })?;
                    acc = d;
                }
                Ok(vec![acc])
            }
            B::Not => self.map(&[arg(0)?], |d, v| Op::Not { d, a: v[0] }),
            B::DFdx => self.map(&[arg(0)?], |d, v| Op::DdX { d, a: v[0] }),
            B::DFdy => self.map(&[arg(0)?], |d, v| Op::DdY { d, a: v[0] }),
            B::Fwidth => {
                let x = arg(0)?.clone();
                let dx = self.map(&[&x], |d, v| Op::DdX { d, a: v[0] })?;
                let dy = self.map(&[&x], |d, v| Op::DdY { d, a: v[0] })?;
                let ax = self.map1(&dx, F1::Abs)?;
                let ay = self.map1(&dy, F1::Abs)?;
                self.map(&[&ax, &ay], fadd_op)
            }
            B::Noise1 | B::Noise2 | B::Noise3 | B::Noise4 => {
                let x = arg(0)?.clone();
                let dims = x.len().min(4) as u8;
                let a = self.consecutive(&x[..dims as usize])?;
                let n = match f {
                    B::Noise1 => 1,
                    B::Noise2 => 2,
                    B::Noise3 => 3,
                    _ => 4,
                };
                let out = self.temps(n as usize)?;
                self.emit(Op::Noise {
                    d: out[0],
                    n,
                    a,
                    dims,
                })?;
                Ok(out)
            }
            _ => {
                let _ = ty;
                unsupported(format!("built-in {} is not implemented", f.name()))
            }
        }
    }

    fn texture(&mut self, f: BuiltinFn, args: &[Expr]) -> R<Val> {
        use BuiltinFn as B;
        let refs: Vec<&Expr> = args.iter().collect();
        let v = self.operands(&refs)?;
        let Some(Base::Sampler(target)) = args.first().map(|a| a.ty.base) else {
            return unsupported("texture lookup without a sampler");
        };
        let (Some(&unit), Some(coord)) = (v.first().and_then(|u| u.first()), v.get(1)) else {
            return unsupported("texture lookup without coordinates");
        };
        let coord = coord.clone();
        let extra = v.get(2).and_then(|x| x.first()).copied();
        let proj = matches!(
            f,
            B::Texture1DProj
                | B::Texture1DProjLod
                | B::Texture2DProj
                | B::Texture2DProjLod
                | B::Texture3DProj
                | B::Texture3DProjLod
                | B::Shadow1DProj
                | B::Shadow2DProj
                | B::Shadow1DProjLod
                | B::Shadow2DProjLod
        );
        let explicit = matches!(
            f,
            B::Texture1DLod
                | B::Texture1DProjLod
                | B::Texture2DLod
                | B::Texture2DProjLod
                | B::Texture3DLod
                | B::Texture3DProjLod
                | B::TextureCubeLod
                | B::Shadow1DLod
                | B::Shadow2DLod
                | B::Shadow1DProjLod
                | B::Shadow2DProjLod
        );
        let (dims, shadow) = match target {
            SamplerKind::Sampler1D => (1usize, false),
            SamplerKind::Sampler2D => (2, false),
            SamplerKind::Sampler3D | SamplerKind::SamplerCube => (3, false),
            SamplerKind::Sampler1DShadow => (1, true),
            SamplerKind::Sampler2DShadow => (2, true),
        };
        let need = if shadow { 3 } else { dims };
        if coord.len() < need || (proj && coord.len() < need + 1) {
            return unsupported("texture coordinates too short");
        }
        let q = if proj { coord.last().copied() } else { None };
        let div = |s: &mut Self, c: Reg| -> R<Reg> {
            match q {
                Some(q) => s.fbin(|d, a, b| Op::FDiv { d, a, b }, c, q),
                None => Ok(c),
            }
        };
        let zero = self.fconst(0.0)?;
        let one = self.fconst(1.0)?;
        let mut c = [zero, zero, zero, one];
        for (k, slot) in c.iter_mut().enumerate().take(dims) {
            *slot = div(self, coord[k])?;
        }
        // Shadow lookups compare against the third coordinate (r), divided
        // by q in the Proj forms (GLSL 1.20 §8.7).
        let compare = if shadow {
            Some(div(self, coord[2])?)
        } else {
            None
        };
        let lod = if explicit {
            TexLod::Explicit(extra)
        } else if self.stage == Stage::Fragment {
            TexLod::Implicit { bias: extra }
        } else {
            TexLod::Explicit(extra)
        };
        let d = self.temps(4)?;
        let index = self.p.textures.len() as u32;
        self.p.textures.push(TexOp {
            target,
            unit,
            coord: c,
            dims: dims as u8,
            compare,
            lod,
            d: d[0],
        });
        self.emit(Op::Texture { index })?;
        Ok(d)
    }

    // ---- interface -----------------------------------------------------

    fn finish(self) -> R<Lowered> {
        let m = self.m;
        let structs = &m.structs;
        let mut iface = Interface {
            structs: m.structs.clone(),
            ..Interface::default()
        };
        let mut inputs = Vec::new();
        let mut outputs = Vec::new();
        let mut next_in = 0usize;
        let mut next_out = 0usize;
        for (i, g) in m.globals.iter().enumerate() {
            let GlobalLoc::Reg(r) = self.globals[i] else {
                continue;
            };
            let n = size_of(g.ty, structs);
            let is_input = match self.stage {
                Stage::Vertex => g.storage == Storage::Attribute,
                Stage::Fragment => g.storage == Storage::Varying,
            };
            let is_output = match self.stage {
                Stage::Vertex => {
                    g.storage == Storage::Varying
                        || (g.builtin
                            && g.storage == Storage::Private
                            && matches!(
                                g.name.as_str(),
                                "gl_Position" | "gl_PointSize" | "gl_ClipVertex"
                            ))
                }
                Stage::Fragment => {
                    g.builtin
                        && g.storage == Storage::Private
                        && matches!(
                            g.name.as_str(),
                            "gl_FragColor" | "gl_FragData" | "gl_FragDepth"
                        )
                }
            };
            let ks = kinds(g.ty, structs);
            if is_input && (g.read || self.used[i]) {
                for (k, &kind) in ks.iter().enumerate() {
                    inputs.push((next_in + k, r + k as u32, kind));
                }
                iface.inputs.push(Slot {
                    name: g.name.clone(),
                    ty: g.ty,
                    offset: next_in,
                    components: n,
                    written: true,
                });
                next_in += n;
            }
            if is_output {
                for (k, &kind) in ks.iter().enumerate() {
                    outputs.push((r + k as u32, next_out + k, kind));
                }
                iface.outputs.push(Slot {
                    name: g.name.clone(),
                    ty: g.ty,
                    offset: next_out,
                    components: n,
                    written: g.written,
                });
                next_out += n;
            }
        }
        for &g in &self.uniform_order {
            let global = &m.globals[g.0 as usize];
            if let GlobalLoc::Uniform(Some(w)) = self.globals[g.0 as usize] {
                iface.uniforms.push(Slot {
                    name: global.name.clone(),
                    ty: global.ty,
                    offset: w as usize,
                    components: size_of(global.ty, structs),
                    written: true,
                });
            }
        }
        iface.uniform_words = self.next_word as usize;
        iface.input_components = next_in;
        iface.output_components = next_out;
        self.p
            .validate()
            .map_err(|e| ExecError::Unsupported(format!("internal lowering error: {e}")))?;
        Ok(Lowered {
            program: self.p,
            interface: iface,
            inputs,
            outputs,
        })
    }
}

fn fsub_op(d: Reg, x: &[Reg]) -> Op {
    Op::FSub {
        d,
        a: x[0],
        b: x[1],
    }
}

fn fmul_op(d: Reg, x: &[Reg]) -> Op {
    Op::FMul {
        d,
        a: x[0],
        b: x[1],
    }
}

fn fdiv_op(d: Reg, x: &[Reg]) -> Op {
    Op::FDiv {
        d,
        a: x[0],
        b: x[1],
    }
}

fn fadd_op(d: Reg, x: &[Reg]) -> Op {
    Op::FAdd {
        d,
        a: x[0],
        b: x[1],
    }
}

fn is_texture(f: BuiltinFn) -> bool {
    use BuiltinFn as B;
    matches!(
        f,
        B::Texture1D
            | B::Texture1DProj
            | B::Texture1DLod
            | B::Texture1DProjLod
            | B::Texture2D
            | B::Texture2DProj
            | B::Texture2DLod
            | B::Texture2DProjLod
            | B::Texture3D
            | B::Texture3DProj
            | B::Texture3DLod
            | B::Texture3DProjLod
            | B::TextureCube
            | B::TextureCubeLod
            | B::Shadow1D
            | B::Shadow2D
            | B::Shadow1DProj
            | B::Shadow2DProj
            | B::Shadow1DLod
            | B::Shadow2DLod
            | B::Shadow1DProjLod
            | B::Shadow2DProjLod
    )
}
