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
//! - `switch`: each lane's starting case is computed as an index (a chain
//!   of selects over the labels); case `i` runs on the lanes of the
//!   switch's running mask whose index is at most `i`, so lanes fall
//!   through until `break` removes them from the running mask.
//! - `&&`, `||` and `?:` whose later operands have side effects run those
//!   operands under a narrowed mask; pure ones are computed on every lane
//!   and selected.
//!
//! ## Modules
//! - this file: the entry ([`lower`]: globals, `main`, global
//!   initializers), the lowering state ([`Lowerer`]) and the interface
//!   ([`Lowerer::finish`]).
//! - [`regs`]: register, mask-slot and uniform-word allocation; emission.
//! - [`stmt`]: statements and control flow under execution masks.
//! - [`unroll`]: which counted loops are unrolled, and known int values.
//! - [`calls`]: user function calls, inlined or as subroutines (policy).
//! - [`places`]: l-values, indexing, reads and writes of storage.
//! - [`memory`]: storage blocks and shared variables, places in memory.
//! - [`expr`]: expressions, operators, conversions, constructors.
//! - [`builtins`]: built-in functions other than texture lookups.
//! - [`emit`]: a geometry shader's `EmitVertex`/`EndPrimitive` and the
//!   emit buffer its outputs are.
//! - [`textures`]: texture lookups.
//! - [`visit`]: read-only IR walks the others share.

mod builtins;
mod calls;
mod emit;
mod expr;
mod memory;
mod places;
mod regs;
mod stmt;
mod textures;
mod unroll;
mod visit;

use crate::interface::{kinds, size_of, Interface, Slot};
use crate::program::{Op, Program, Reg, VarInfo};
use crate::ExecError;
use calls::inlined_cost;
use glsl::ir::{
    ConstScalar, ConstValue, Expr, ExprKind, FunctionId, GlobalId, Module, Stage, Storage,
};
use glsl::link::LinkedStage;
use glsl::types::{Scalar, Type};
use glsl::Span;
use unroll::UNROLL_BUDGET;

/// Deepest chain of inlined calls, in frames (`main`'s included): the
/// front end refuses longer chains, so every program it accepts can be
/// inlined as deep as it calls.
pub const MAX_CALL_DEPTH: usize = glsl::limits::MAX_CALL_DEPTH as usize;

/// Above this many expression nodes after inlining, functions become
/// subroutines instead.
pub const INLINE_LIMIT: u64 = 200_000;

pub use emit::MAX_EMITTED_COMPONENTS;

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
    /// The lanes that entered a switch (restored after it).
    SwitchEntry,
    /// The lanes still running a switch's cases (`break` leaves it).
    SwitchRun,
    Function,
}

#[derive(Clone, Copy, Debug)]
enum GlobalLoc {
    Reg(Reg),
    Uniform(Option<u32>),
    /// A storage block member or instance, or a shared variable.
    Memory(memory::MemGlobal),
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
    /// In memory: [`Place::mem`] says where.
    Memory,
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
    /// Where a place in memory is (its `off` and `dynamic` unused).
    mem: Option<memory::MemPlace>,
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
    /// A geometry kernel's emit buffer.
    emitter: Option<emit::EmitBuffer>,
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

/// Stack the lowering keeps free at each level of its recursion
/// (expressions, statements, inlined calls: each level bounded by the front
/// end's `MAX_NESTING_DEPTH` and `MAX_CALL_DEPTH`, together deeper than a
/// thread's stack may be; one level takes a few KiB, tens unoptimized).
const RED_ZONE: usize = 256 << 10;

/// The stack segment that continues the recursion when less than
/// [`RED_ZONE`] is left.
const STACK_SEGMENT: usize = 8 << 20;

/// Runs one level of the lowering's recursion, on a fresh stack segment
/// when this one is nearly used (`stacker`).
#[inline]
fn with_stack<T>(f: impl FnOnce() -> T) -> T {
    stacker::maybe_grow(RED_ZONE, STACK_SEGMENT, f)
}

pub(crate) fn lower(stage: &LinkedStage, inline_limit: u64) -> R<Lowered> {
    match stage.stage {
        Stage::TessControl | Stage::TessEvaluation => {
            return unsupported(format!(
                "{} shaders are not run by this implementation",
                stage.stage.name()
            ))
        }
        _ => {}
    }
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
        emitter: None,
    };
    // Globals: registers for everything but uniforms and memory; uniform
    // words for the uniforms the shader reads (others get words if
    // lowering finds a use, e.g. ftransform's matrix).
    let (buffers, in_memory, shared_bytes) = memory::layout_memory(m);
    for (i, g) in m.globals.iter().enumerate() {
        let id = GlobalId(i as u32);
        if let Some(Some(mg)) = in_memory.get(i) {
            l.globals.push(GlobalLoc::Memory(*mg));
            continue;
        }
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
    if stage.stage == Stage::Geometry {
        let mut vertex = Vec::new();
        for (i, g) in m.globals.iter().enumerate() {
            if let (true, GlobalLoc::Reg(r)) = (is_output(stage.stage, g), l.globals[i]) {
                vertex.extend((0..size_of(g.ty, &m.structs) as u32).map(|k| r + k));
            }
        }
        l.emitter = Some(l.alloc_emit_buffer(vertex)?);
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
    let mut lowered = l.finish()?;
    lowered.interface.buffers = buffers;
    lowered.interface.shared_bytes = shared_bytes;
    lowered.interface.local_size = m.local_size;
    Ok(lowered)
}

/// The interface slots of `g` (laid out from `offset`, `n` components)
/// when it is the instance of a named input or output block (GLSL 1.50
/// §4.3.7): one per member (per element of an arrayed instance), named
/// `Block.member` (`Block[i].member`) after the block, by which stages
/// match blocks whatever their instance names, each with its member's
/// interpolation qualifier. `None` for every other global, and when the
/// members do not account for the instance's components (unsized
/// members).
fn block_member_slots(
    m: &Module,
    g: &glsl::ir::Global,
    offset: usize,
    n: usize,
) -> Option<Vec<Slot>> {
    let b = m.blocks.get(g.block?.0 as usize)?;
    if b.instance.is_none() || b.storage == Storage::Uniform {
        return None;
    }
    let elements = b.elements();
    let mut slots = Vec::new();
    let mut at = offset;
    for e in 0..elements {
        for member in &b.members {
            let components = size_of(member.ty, &m.structs);
            let name = format!("{}{}.{}", b.name, b.element_suffix(e), member.name);
            slots.push(Slot {
                name,
                ty: member.ty,
                offset: at,
                components,
                written: false,
                location: None,
                index: None,
                interpolation: member.interpolation.or(g.interpolation),
                block: None,
            });
            at += components;
        }
    }
    (at == offset + n).then_some(slots)
}

/// The block of `g` when it is a member of an input or output block
/// declared without an instance name (see [`Slot::block`]).
fn unnamed_block(m: &Module, g: &glsl::ir::Global) -> Option<String> {
    let b = m.blocks.get(g.block?.0 as usize)?;
    (b.instance.is_none() && b.storage != Storage::Uniform).then(|| b.name.clone())
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
            interpolation: None,
            location: None,
            index: None,
            binding: None,
            patch: false,
            block: None,
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

/// Whether `g` is an output of a `stage` kernel (see the crate docs'
/// interface).
fn is_output(stage: Stage, g: &glsl::ir::Global) -> bool {
    match stage {
        Stage::Vertex | Stage::Geometry => {
            g.storage == Storage::Varying
                || (g.builtin
                    && g.storage == Storage::Private
                    && matches!(
                        g.name.as_str(),
                        "gl_Position" | "gl_PointSize" | "gl_ClipVertex" | "gl_ClipDistance"
                    ))
        }
        Stage::Fragment => {
            g.storage == Storage::FragOutput
                || (g.builtin
                    && g.storage == Storage::Private
                    && matches!(
                        g.name.as_str(),
                        "gl_FragColor" | "gl_FragData" | "gl_FragDepth"
                    ))
        }
        // A compute shader's results are the memory it writes; the
        // tessellation stages are refused before lowering.
        Stage::Compute | Stage::TessControl | Stage::TessEvaluation => false,
    }
}

fn const_bits(c: ConstScalar) -> u32 {
    match c {
        ConstScalar::Float(f) => glsl::math::flush_denormal(f).to_bits(),
        ConstScalar::Int(i) => i as u32,
        ConstScalar::Uint(u) => u,
        ConstScalar::Bool(b) => b as u32,
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
                Stage::Geometry | Stage::TessControl | Stage::TessEvaluation => {
                    g.storage == Storage::PerVertexInput
                }
                // Compute invocations read their built-in IDs.
                Stage::Fragment | Stage::Compute => g.storage == Storage::Varying,
            };
            let is_output = is_output(self.stage, g);
            let ks = kinds(g.ty, structs);
            let slots = |offset: usize, written: bool| match block_member_slots(m, g, offset, n) {
                Some(members) => members.into_iter().map(|s| Slot { written, ..s }).collect(),
                None => vec![Slot {
                    name: g.name.clone(),
                    ty: g.ty,
                    offset,
                    components: n,
                    written,
                    location: g.location,
                    index: g.index,
                    interpolation: g.interpolation,
                    block: unnamed_block(m, g),
                }],
            };
            if is_input && (g.read || self.used[i]) {
                for (k, &kind) in ks.iter().enumerate() {
                    inputs.push((next_in + k, r + k as u32, kind));
                }
                iface.inputs.extend(slots(next_in, true));
                next_in += n;
            }
            if is_output {
                for (k, &kind) in ks.iter().enumerate() {
                    outputs.push((r + k as u32, next_out + k, kind));
                }
                iface.outputs.extend(slots(next_out, g.written));
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
                    location: None,
                    index: None,
                    interpolation: None,
                    block: None,
                });
            }
        }
        iface.uniform_words = self.next_word as usize;
        iface.input_components = next_in;
        iface.output_components = next_out;
        if let Some(e) = &self.emitter {
            outputs = e.outputs(&outputs);
            iface.emitted = Some(e.layout());
            iface.output_components = e.layout().components();
        }
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
