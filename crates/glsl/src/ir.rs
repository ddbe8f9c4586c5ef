//! The typed intermediate representation.
//!
//! Contract (what [`crate::validate`] checks and later stages rely on):
//! - every [`Expr`] carries its resolved [`Type`]; no expression has the
//!   error type in a module that compiled without errors;
//! - every implicit conversion is explicit: the int→float (1.20 on) and
//!   uint→float (1.30 on) conversions of §4.1.10 appear as
//!   [`ExprKind::Convert`]; GLSL 1.10 has none;
//! - operands of binary operators already have the shapes the spec allows
//!   (scalar⊗vector broadcasting is left to the executor, matrix products are
//!   [`BinaryOp::MatMul`], everything else is component-wise); the
//!   integer operators take int/uint scalars and vectors: `%`, `&`, `|`,
//!   `^` two operands of one signedness, the shifts any signedness with
//!   the left operand's type as result and a scalar right operand for a
//!   scalar left one;
//! - constant expressions are folded: array sizes are numbers, `const`
//!   variables have [`ConstValue`] initializers, `.length()` is a constant;
//! - control flow is structured: `while`, `do`/`while` and `for` are all
//!   [`Stmt::Loop`] with the condition as an explicit `if (!c) break;`;
//!   `switch` is [`Stmt::Switch`], whose labels are distinct constants of
//!   the selector's type (int or uint scalar) with at most one default;
//!   `break` leaves the innermost loop or switch, `continue` the innermost
//!   loop;
//! - expressions may have side effects (assignments, `++`, calls) and are
//!   evaluated left to right; `&&`, `||` and `?:` evaluate lazily;
//! - the stage interface is in [`Global::storage`], whatever the keywords
//!   were: vertex inputs (`attribute`, vertex `in`) are
//!   [`Storage::Attribute`], vertex outputs and fragment inputs (`varying`,
//!   vertex `out`, fragment `in`) are [`Storage::Varying`], user fragment
//!   outputs (fragment `out`) are [`Storage::FragOutput`]; the inputs of
//!   the stages that see whole primitives or patches (geometry `in`,
//!   `varying in`, tessellation control and evaluation `in`) are
//!   [`Storage::PerVertexInput`], a tessellation control shader's
//!   per-vertex `out` arrays [`Storage::PerVertexOutput`], and the other
//!   outputs of those stages, and the per-patch `patch out` / `patch in`
//!   ([`Global::patch`]), [`Storage::Varying`]; their
//!   qualifiers are [`Global::interpolation`], [`Global::centroid`],
//!   [`Global::invariant`] and [`Global::location`]. Precision qualifiers
//!   leave no trace;
//! - interface blocks ([`Module::blocks`]) are made of ordinary globals of
//!   the block's storage (see [`InterfaceBlock`]), each naming its block in
//!   [`Global::block`];
//! - a geometry shader's input and output layouts are in
//!   [`Module::geometry`]: the input primitive, the output primitive and
//!   `max_vertices`, each as the shader object declared it (at most one
//!   value each; the linker requires all three in the program, GLSL 1.50
//!   §4.3.8.1-2). User geometry inputs are arrays, sized (by their
//!   declaration or the input primitive) or still unsized when the object
//!   declares no input primitive. A GL_EXT_geometry_shader4 object
//!   declares no layout (its primitives are the program's parameters);
//!   compiled alone its input arrays have the size of the primitive it
//!   was found valid with, and the linker compiles it again with the
//!   program's, the linked module's `geometry` then holding the
//!   parameters;
//! - the tessellation stages' layouts are in [`Module::tessellation`]:
//!   the output patch's vertex count of a control shader and the
//!   primitive mode, spacing, vertex order and point mode of an
//!   evaluation shader, each as the object declared it (the linker
//!   requires the vertex count and the mode in the program,
//!   GL_ARB_tessellation_shader §4.3.8). Per-vertex inputs of both
//!   stages have gl_MaxPatchVertices elements; a control shader's
//!   per-vertex outputs have the output patch's size once the object
//!   declares it (unsized before).

pub mod print;

use crate::builtin_fn::BuiltinFn;
use crate::lang::Language;
use crate::source::Span;
use crate::types::{StructDef, Type};
use serde::Serialize;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub enum Stage {
    Vertex,
    /// GL_ARB_tessellation_shader: one invocation per vertex of the output
    /// patch, reading the whole input patch. The front end compiles and
    /// links it; the GL layer does not draw patches.
    TessControl,
    /// GL_ARB_tessellation_shader: one invocation per vertex the
    /// primitive generator makes of a patch.
    TessEvaluation,
    /// GLSL 1.50 §2.2, and GL_EXT/ARB_geometry_shader4 on 1.10/1.20.
    Geometry,
    Fragment,
    /// GL_ARB_compute_shader (GLSL 4.30 §2.6): a program of its own,
    /// run in work groups by a dispatch rather than by drawing.
    Compute,
}

impl Stage {
    pub fn name(self) -> &'static str {
        match self {
            Stage::Vertex => "vertex",
            Stage::TessControl => "tessellation control",
            Stage::TessEvaluation => "tessellation evaluation",
            Stage::Geometry => "geometry",
            Stage::Fragment => "fragment",
            Stage::Compute => "compute",
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub struct GlobalId(pub u32);

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub struct FunctionId(pub u32);

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub struct LocalId(pub u32);

/// One scalar of a constant.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum ConstScalar {
    Float(f32),
    Int(i32),
    Uint(u32),
    Bool(bool),
}

/// A constant of any type, flattened to scalars: vectors in order, matrices
/// column by column, arrays element by element, structs member by member.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ConstValue {
    pub ty: Type,
    pub components: Vec<ConstScalar>,
}

/// Where a global variable lives.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum Storage {
    /// A plain global (read/write, private to one invocation). Also the
    /// stage outputs `gl_Position`, `gl_PointSize`, `gl_ClipVertex`,
    /// `gl_FragColor`, `gl_FragData`, `gl_FragDepth`.
    Private,
    /// A `const` global; its value is in [`Global::init`].
    Const,
    Uniform,
    /// Vertex-stage input.
    Attribute,
    /// Written by the vertex, tessellation or geometry stage, read (only)
    /// by the next stage: `varying`, vertex and geometry `out`, fragment `in` (GLSL
    /// 1.30 §4.3.4, §4.3.6). Also the read-only fragment inputs
    /// `gl_FragCoord`, `gl_FrontFacing`, and the geometry stage's
    /// `gl_PrimitiveID`, `gl_Layer` outputs.
    Varying,
    /// An input of a stage that sees a whole primitive or patch: geometry
    /// (GLSL 1.50 §4.3.4, GL_EXT_geometry_shader4 `varying in`),
    /// tessellation control and evaluation (GL_ARB_tessellation_shader
    /// §4.3.4): read-only; a user input is an array with one element per
    /// vertex of the input primitive or patch, matched by name with the
    /// previous stage's output of the element type. Also those stages'
    /// built-in inputs: `gl_in[]`, the EXT form's `gl_PositionIn[]`...,
    /// and the scalars `gl_PrimitiveIDIn`, `gl_InvocationID`,
    /// `gl_PatchVerticesIn`, `gl_TessCoord`.
    PerVertexInput,
    /// A tessellation control shader's per-vertex output (`out` arrays and
    /// `gl_out[]`, GL_ARB_tessellation_shader §4.3.6): one element per
    /// vertex of the output patch, readable by every invocation, written
    /// by each only at its own vertex (`[gl_InvocationID]`).
    PerVertexOutput,
    /// A member of a shader storage block (`buffer B { ... };`,
    /// GL_ARB_shader_storage_buffer_object): memory every invocation of a
    /// draw or dispatch reads and writes.
    Buffer,
    /// A `shared` variable of a compute shader (GL_ARB_compute_shader,
    /// GLSL 4.30 §4.3.8): one per work group, read and written by all of
    /// its invocations.
    Shared,
    /// A user-declared fragment output (`out` in a fragment shader, GLSL
    /// 1.30 §4.3.6): written like a private global, its value goes to the
    /// draw buffer of [`Global::location`] (0 when absent and it is the
    /// only output; the GL layer may bind others).
    FragOutput,
}

/// How a varying is interpolated (GLSL 1.30 §4.3.7). `None` in
/// [`Global::interpolation`] means no qualifier: smooth, or the GL shade
/// model for the built-in colours.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum Interpolation {
    Smooth,
    Flat,
    NoPerspective,
}

impl Interpolation {
    pub fn as_str(self) -> &'static str {
        match self {
            Interpolation::Smooth => "smooth",
            Interpolation::Flat => "flat",
            Interpolation::NoPerspective => "noperspective",
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub struct BlockId(pub u32);

/// How a uniform block's members are laid out in its buffer (GLSL 1.40
/// §4.3.5.2). `Shared` is the default.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum BlockLayout {
    Shared,
    Packed,
    Std140,
    /// Shader storage blocks only (GL_ARB_shader_storage_buffer_object):
    /// std140 without rounding arrays and structs up to vec4 alignment.
    Std430,
}

/// A member of an interface block.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct BlockMember {
    pub name: String,
    pub ty: Type,
    /// Matrices (and arrays and structs of them) are stored row by row
    /// in the buffer (`row_major`).
    pub row_major: bool,
    pub interpolation: Option<Interpolation>,
    pub centroid: bool,
    pub invariant: bool,
    /// For an input or output block's array member declared without a
    /// size: the largest constant index used through a named instance,
    /// plus one (GLSL 1.50 §4.3.7 sizes it as an unsized array global;
    /// the linker does).
    /// Memory qualifiers of a shader storage block's member (its own or
    /// the block's): `readonly` members are never written, `writeonly`
    /// ones never read.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub readonly: bool,
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub writeonly: bool,
    pub implicit_size: u32,
}

/// An interface block (GLSL 1.40 §4.3.5.1 uniform blocks, 1.50 §4.3.7
/// input and output blocks). Its members are ordinary globals of the
/// block's storage, so the executor sees uniforms and varyings: without
/// an instance name one global per member, named as the member; with one,
/// a single global of the instance's name whose type is an (array of an)
/// anonymous struct of the members ([`InterfaceBlock::globals`] holds
/// it). Offsets in a buffer are the GL layer's business; the block keeps
/// what decides them (layout, member types, row-major flags).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct InterfaceBlock {
    pub name: String,
    /// [`Storage::Uniform`], or [`Storage::Varying`] / [`Storage::Attribute`]
    /// for the output / input blocks of 1.50.
    pub storage: Storage,
    /// An input block of a fragment shader (its storage is `Varying`, as
    /// is an output block of a vertex shader).
    pub input: bool,
    pub instance: Option<String>,
    /// Arrayed instance: `uniform B { ... } b[4];`; the outermost size of
    /// an array of arrays of instances.
    pub array: Option<u32>,
    /// The inner sizes of an array of arrays of instances
    /// (GL_ARB_arrays_of_arrays: `uniform B { ... } b[2][3];` has `array`
    /// 2 and `inner` `[3]`), outermost first; empty otherwise. The
    /// instance's elements are numbered row after row, the inner
    /// dimension fastest, as its global's flattened layout has them.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub inner: Vec<u32>,
    pub layout: BlockLayout,
    /// `layout(binding = N)` of a uniform block (GL_ARB_shading_language_420pack):
    /// its first binding point; an arrayed instance's elements take the
    /// next ones.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub binding: Option<u32>,
    pub members: Vec<BlockMember>,
    pub globals: Vec<GlobalId>,
    pub span: Span,
}

impl InterfaceBlock {
    /// The instance array's sizes, outermost first (empty without one).
    pub fn dims(&self) -> Vec<u32> {
        self.array
            .into_iter()
            .chain(self.inner.iter().copied())
            .collect()
    }

    /// The number of block elements: 1 without an instance array.
    pub fn elements(&self) -> usize {
        self.dims().iter().map(|&n| n as usize).product()
    }

    /// The subscripts naming element `e` (`[e]`, `[i][j]` of an array of
    /// arrays; empty without an instance array), as GL names the blocks
    /// of an arrayed instance (`B[1][2]`).
    pub fn element_suffix(&self, e: usize) -> String {
        let dims = self.dims();
        let mut subs = vec![0usize; dims.len()];
        let mut rest = e;
        for (s, &n) in subs.iter_mut().zip(&dims).rev() {
            let n = (n as usize).max(1);
            *s = rest % n;
            rest /= n;
        }
        subs.iter().map(|s| format!("[{s}]")).collect()
    }
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Global {
    pub name: String,
    pub ty: Type,
    pub storage: Storage,
    /// Declared by the implementation (`gl_*`).
    pub builtin: bool,
    pub invariant: bool,
    pub centroid: bool,
    /// The interpolation qualifier of a varying, as written.
    pub interpolation: Option<Interpolation>,
    /// `layout(location = N)` of a vertex input or fragment output.
    pub location: Option<u32>,
    /// `layout(index = N)` of a fragment output (GLSL 3.30 §4.3.8.2,
    /// ARB_blend_func_extended): which of the two source colours of its
    /// location's draw buffer it is; 1 is the second (dual-source
    /// blending). `None` when absent, as 0.
    pub index: Option<u32>,
    /// The interface block this global belongs to (a member, or the
    /// instance of a named block).
    /// `patch out` of a tessellation control shader or `patch in` of an
    /// evaluation shader (GL_ARB_tessellation_shader §4.3): one value per
    /// patch rather than per vertex ([`Storage::Varying`]; a `patch in`
    /// is read-only).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub patch: bool,
    /// `layout(binding = N)` of a sampler uniform
    /// (GL_ARB_shading_language_420pack): the texture unit it starts
    /// with; an array's elements take the next ones.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub binding: Option<u32>,
    pub block: Option<BlockId>,
    /// Constant initializer (`const` globals, uniforms with an initializer).
    pub init: Option<ConstValue>,
    /// Non-constant initializer of a private global, evaluated at the start
    /// of `main`.
    pub init_expr: Option<Expr>,
    /// Statically read / written anywhere in the shader (for the linker's
    /// interface checks and for `glGetActiveUniform`).
    pub read: bool,
    pub written: bool,
    /// For arrays declared without a size: the largest constant index used,
    /// plus one (GLSL 1.10 §4.1.9).
    pub implicit_size: u32,
    pub span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum ParamQualifier {
    In,
    Out,
    InOut,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Param {
    pub name: Option<String>,
    pub ty: Type,
    pub qualifier: ParamQualifier,
    /// `const in`: the parameter cannot be written in the body.
    pub is_const: bool,
    /// The local that holds the parameter inside the body.
    pub local: LocalId,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Local {
    pub name: String,
    pub ty: Type,
    pub is_const: bool,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Function {
    pub name: String,
    pub params: Vec<Param>,
    pub return_type: Type,
    pub locals: Vec<Local>,
    /// `None` for a prototype whose body is in another shader object of the
    /// same stage (resolved by the linker).
    pub body: Option<Block>,
    pub span: Span,
}

pub type Block = Vec<Stmt>;

#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum Stmt {
    Expr(Expr),
    /// A local variable comes into scope here; `init` (if any) is assigned
    /// each time control passes.
    Declare {
        local: LocalId,
        init: Option<Expr>,
        span: Span,
    },
    Block(Block),
    If {
        cond: Expr,
        then: Block,
        else_: Block,
        span: Span,
    },
    /// A loop: run `body`, then `continuing`, forever; `Break` leaves,
    /// `Continue` jumps to `continuing`. Conditions are `if` + `Break`
    /// statements inside `body` (at its start for `while`/`for`) or in
    /// `continuing` (at its end for `do`/`while`).
    Loop {
        body: Block,
        continuing: Block,
        span: Span,
    },
    /// `switch (selector) { case ...: ... }` (GLSL 1.30 §6.2). Each lane
    /// starts at the case whose labels hold the selector's value, or at the
    /// default case, or skips the switch; it runs the cases from there on
    /// in order (fall through) until a `break`. The cases share one scope,
    /// the switch body's.
    Switch {
        selector: Expr,
        cases: Vec<SwitchCase>,
        span: Span,
    },
    /// Leaves the innermost loop or switch.
    Break(Span),
    Continue(Span),
    Return(Option<Expr>, Span),
    Discard(Span),
}

/// A case of a [`Stmt::Switch`]: one or more labels (consecutive labels
/// without statements between them), then the statements up to the next
/// label. A case other than the last may have no statements.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SwitchCase {
    pub labels: Vec<CaseLabel>,
    pub body: Block,
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum CaseLabel {
    /// `case c:`, an int or uint like the selector.
    Value(ConstScalar),
    Default,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum UnaryOp {
    /// Arithmetic negation (wrapping for int and uint).
    Neg,
    /// Logical not of a `bool`.
    Not,
    /// `~`: every bit of an int/uint scalar or vector complemented.
    BitNot,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum BinaryOp {
    /// Component-wise (with scalar broadcasting).
    Add,
    Sub,
    Mul,
    Div,
    /// Linear-algebra product: matrix×matrix, matrix×vector, vector×matrix.
    MatMul,
    /// `%` on int/uint (component-wise, scalar broadcasting). Int: the
    /// remainder of the truncating division (sign of the dividend,
    /// `i32::MIN % -1` is 0); by zero: 0 (not constant when folding,
    /// like `/`).
    Mod,
    /// `<<`: the left operand's bits shifted; the amount is taken modulo
    /// 32 (its low 5 bits), so any amount has a defined result (the spec
    /// leaves amounts below 0 or from 32 on undefined).
    Shl,
    /// `>>`: arithmetic (sign-extending) for int, logical for uint; the
    /// amount modulo 32 as for `Shl`.
    Shr,
    /// `&`, `|`, `^` on int/uint of one signedness.
    BitAnd,
    BitOr,
    BitXor,
    /// `<`, `>`, `<=`, `>=` on int, uint or float scalars.
    Less,
    Greater,
    LessEq,
    GreaterEq,
    /// Whole-value equality of any non-sampler type, giving one `bool`.
    Equal,
    NotEqual,
    /// Short-circuit.
    LogicalAnd,
    LogicalOr,
    LogicalXor,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum IncDec {
    PreInc,
    PreDec,
    PostInc,
    PostDec,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Expr {
    pub kind: ExprKind,
    pub ty: Type,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum ExprKind {
    Const(ConstValue),
    Global(GlobalId),
    Local(LocalId),
    /// Array element, vector component or matrix column. Out-of-range
    /// dynamic indices have a defined, implementation-chosen result.
    Index {
        base: Box<Expr>,
        index: Box<Expr>,
    },
    /// `v.xzy`: `count` components of `base`, selected by `components`.
    Swizzle {
        base: Box<Expr>,
        components: [u8; 4],
        count: u8,
    },
    Member {
        base: Box<Expr>,
        index: u32,
    },
    Unary {
        op: UnaryOp,
        operand: Box<Expr>,
    },
    Binary {
        op: BinaryOp,
        left: Box<Expr>,
        right: Box<Expr>,
    },
    Ternary {
        cond: Box<Expr>,
        accept: Box<Expr>,
        reject: Box<Expr>,
    },
    /// `target = value` or `target op= value`; the result is the new value.
    Assign {
        op: Option<BinaryOp>,
        target: Box<Expr>,
        value: Box<Expr>,
    },
    IncDec {
        op: IncDec,
        target: Box<Expr>,
    },
    Call {
        function: FunctionId,
        args: Vec<Expr>,
    },
    /// `array.length()` of an array declared without a size
    /// (GL_ARB_shader_storage_buffer_object): type `int`. For a shader
    /// storage block's last member, the number of whole elements the
    /// bound buffer range holds after the member's offset; for an array
    /// sized by its uses (a global the linker sizes, a local the executor
    /// does), that size. `array` is read for its place, not its value.
    ArrayLength {
        array: Box<Expr>,
    },
    /// `debugPrintfEXT(format, args...)` (GL_SHADERBOX_debug_printf): prints
    /// the arguments of the invocation, formatted by
    /// [`crate::printf::format_values`]; type `void`, no other effect.
    /// `args` match `format`'s conversions in order and type.
    DebugPrintf {
        format: Vec<crate::printf::Piece>,
        args: Vec<Expr>,
    },
    Builtin {
        function: BuiltinFn,
        args: Vec<Expr>,
    },
    /// A constructor of `ty` from `args` with the GLSL rules (§5.4):
    /// components consumed in order with per-scalar conversion, a scalar
    /// fills a vector or a matrix diagonal, a matrix from a matrix copies
    /// the overlap and fills the identity.
    Construct {
        args: Vec<Expr>,
    },
    /// Implicit int→float or uint→float conversion (§4.1.10) to `ty`.
    Convert {
        operand: Box<Expr>,
    },
    Comma {
        left: Box<Expr>,
        right: Box<Expr>,
    },
}

impl Expr {
    /// Calls `f` on each direct sub-expression, in evaluation order.
    pub fn for_each_child<'a>(&'a self, mut f: impl FnMut(&'a Expr)) {
        match &self.kind {
            ExprKind::Const(_) | ExprKind::Global(_) | ExprKind::Local(_) => {}
            ExprKind::Index { base, index } => {
                f(base);
                f(index);
            }
            ExprKind::Swizzle { base, .. } | ExprKind::Member { base, .. } => f(base),
            ExprKind::Unary { operand, .. } | ExprKind::Convert { operand } => f(operand),
            ExprKind::ArrayLength { array } => f(array),
            ExprKind::Binary { left, right, .. } | ExprKind::Comma { left, right } => {
                f(left);
                f(right);
            }
            ExprKind::Ternary {
                cond,
                accept,
                reject,
            } => {
                f(cond);
                f(accept);
                f(reject);
            }
            ExprKind::Assign { target, value, .. } => {
                f(target);
                f(value);
            }
            ExprKind::IncDec { target, .. } => f(target),
            ExprKind::Call { args, .. }
            | ExprKind::Builtin { args, .. }
            | ExprKind::DebugPrintf { args, .. }
            | ExprKind::Construct { args } => args.iter().for_each(f),
        }
    }

    /// [`Expr::for_each_child`] with mutable access.
    pub fn for_each_child_mut(&mut self, mut f: impl FnMut(&mut Expr)) {
        match &mut self.kind {
            ExprKind::Const(_) | ExprKind::Global(_) | ExprKind::Local(_) => {}
            ExprKind::Index { base, index } => {
                f(base);
                f(index);
            }
            ExprKind::Swizzle { base, .. } | ExprKind::Member { base, .. } => f(base),
            ExprKind::Unary { operand, .. } | ExprKind::Convert { operand } => f(operand),
            ExprKind::ArrayLength { array } => f(array),
            ExprKind::Binary { left, right, .. } | ExprKind::Comma { left, right } => {
                f(left);
                f(right);
            }
            ExprKind::Ternary {
                cond,
                accept,
                reject,
            } => {
                f(cond);
                f(accept);
                f(reject);
            }
            ExprKind::Assign { target, value, .. } => {
                f(target);
                f(value);
            }
            ExprKind::IncDec { target, .. } => f(target),
            ExprKind::Call { args, .. }
            | ExprKind::Builtin { args, .. }
            | ExprKind::DebugPrintf { args, .. }
            | ExprKind::Construct { args } => args.iter_mut().for_each(f),
        }
    }
}

/// Calls `f` on each expression directly held by the statements of
/// `block`, recursing into nested blocks (not into expressions).
pub fn for_each_block_expr<'a>(block: &'a [Stmt], f: &mut impl FnMut(&'a Expr)) {
    for s in block {
        match s {
            Stmt::Expr(e) | Stmt::Return(Some(e), _) => f(e),
            Stmt::Declare { init: Some(e), .. } => f(e),
            Stmt::Block(b) => for_each_block_expr(b, f),
            Stmt::If {
                cond, then, else_, ..
            } => {
                f(cond);
                for_each_block_expr(then, f);
                for_each_block_expr(else_, f);
            }
            Stmt::Loop {
                body, continuing, ..
            } => {
                for_each_block_expr(body, f);
                for_each_block_expr(continuing, f);
            }
            Stmt::Switch {
                selector, cases, ..
            } => {
                f(selector);
                for c in cases {
                    for_each_block_expr(&c.body, f);
                }
            }
            Stmt::Declare { init: None, .. }
            | Stmt::Return(None, _)
            | Stmt::Break(_)
            | Stmt::Continue(_)
            | Stmt::Discard(_) => {}
        }
    }
}

/// [`for_each_block_expr`] with mutable access.
pub fn for_each_block_expr_mut(block: &mut [Stmt], f: &mut impl FnMut(&mut Expr)) {
    for s in block {
        match s {
            Stmt::Expr(e) | Stmt::Return(Some(e), _) => f(e),
            Stmt::Declare { init: Some(e), .. } => f(e),
            Stmt::Block(b) => for_each_block_expr_mut(b, f),
            Stmt::If {
                cond, then, else_, ..
            } => {
                f(cond);
                for_each_block_expr_mut(then, f);
                for_each_block_expr_mut(else_, f);
            }
            Stmt::Loop {
                body, continuing, ..
            } => {
                for_each_block_expr_mut(body, f);
                for_each_block_expr_mut(continuing, f);
            }
            Stmt::Switch {
                selector, cases, ..
            } => {
                f(selector);
                for c in cases.iter_mut() {
                    for_each_block_expr_mut(&mut c.body, f);
                }
            }
            Stmt::Declare { init: None, .. }
            | Stmt::Return(None, _)
            | Stmt::Break(_)
            | Stmt::Continue(_)
            | Stmt::Discard(_) => {}
        }
    }
}

/// Behaviour requested by an `#extension` directive.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum ExtensionBehavior {
    Require,
    Enable,
    Warn,
    Disable,
}

/// One analyzed shader object.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Module {
    pub language: Language,
    pub stage: Stage,
    pub structs: Vec<StructDef>,
    pub globals: Vec<Global>,
    pub functions: Vec<Function>,
    pub extensions: Vec<(String, ExtensionBehavior)>,
    pub blocks: Vec<InterfaceBlock>,
    /// `layout(origin_upper_left)` / `layout(pixel_center_integer)` on a
    /// redeclared `gl_FragCoord` (GLSL 1.50 §7.2,
    /// GL_ARB_fragment_coord_conventions).
    pub frag_coord: FragCoordConventions,
    /// A geometry shader's layouts (all `None` in other stages).
    pub geometry: GeometryLayout,
    /// A tessellation shader's layouts (all `None` in other stages).
    #[serde(skip_serializing_if = "TessLayout::is_empty")]
    pub tessellation: TessLayout,
    /// A compute shader's work-group size, `layout(local_size_x = X,
    /// local_size_y = Y, local_size_z = Z) in;` (each 1 when left out),
    /// when the object declares it (GL_ARB_compute_shader).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub local_size: Option<[u32; 3]>,
    /// The members of a redeclared output `gl_PerVertex` block (GLSL 1.50
    /// §7.1), in order; `None` when the shader keeps the built-in block.
    /// The members stay the built-in globals; the linker checks that the
    /// objects of a stage agree on the redeclaration.
    pub per_vertex_out: Option<Vec<BlockMember>>,
    /// A geometry shader's redeclared input block, `in gl_PerVertex { ...
    /// } gl_in[];` (the same rules, GLSL 1.50 §7.1), its members in order;
    /// `None` when the shader keeps the built-in block. `gl_in`'s struct
    /// type then has exactly these members.
    pub per_vertex_in: Option<Vec<BlockMember>>,
}

/// The primitive a geometry shader takes (`layout(...) in;`, GLSL 1.50
/// §4.3.8.1, or GL_EXT_geometry_shader4's GEOMETRY_INPUT_TYPE).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum InputPrimitive {
    Points,
    Lines,
    LinesAdjacency,
    Triangles,
    TrianglesAdjacency,
}

impl InputPrimitive {
    pub const ALL: [InputPrimitive; 5] = [
        InputPrimitive::Points,
        InputPrimitive::Lines,
        InputPrimitive::LinesAdjacency,
        InputPrimitive::Triangles,
        InputPrimitive::TrianglesAdjacency,
    ];

    /// The layout identifier.
    pub fn name(self) -> &'static str {
        match self {
            InputPrimitive::Points => "points",
            InputPrimitive::Lines => "lines",
            InputPrimitive::LinesAdjacency => "lines_adjacency",
            InputPrimitive::Triangles => "triangles",
            InputPrimitive::TrianglesAdjacency => "triangles_adjacency",
        }
    }

    pub fn from_name(name: &str) -> Option<InputPrimitive> {
        InputPrimitive::ALL.into_iter().find(|p| p.name() == name)
    }

    /// The GL enum's name, as GL_EXT_geometry_shader4's
    /// GEOMETRY_INPUT_TYPE takes it.
    pub fn gl_name(self) -> &'static str {
        match self {
            InputPrimitive::Points => "GL_POINTS",
            InputPrimitive::Lines => "GL_LINES",
            InputPrimitive::LinesAdjacency => "GL_LINES_ADJACENCY_EXT",
            InputPrimitive::Triangles => "GL_TRIANGLES",
            InputPrimitive::TrianglesAdjacency => "GL_TRIANGLES_ADJACENCY_EXT",
        }
    }

    /// Vertices per input primitive: the size of every input array
    /// (GLSL 1.50 §4.3.8.1's table).
    pub fn vertices(self) -> u32 {
        match self {
            InputPrimitive::Points => 1,
            InputPrimitive::Lines => 2,
            InputPrimitive::LinesAdjacency => 4,
            InputPrimitive::Triangles => 3,
            InputPrimitive::TrianglesAdjacency => 6,
        }
    }
}

/// The primitive a geometry shader emits (`layout(...) out;`, §4.3.8.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum OutputPrimitive {
    Points,
    LineStrip,
    TriangleStrip,
}

impl OutputPrimitive {
    pub fn name(self) -> &'static str {
        match self {
            OutputPrimitive::Points => "points",
            OutputPrimitive::LineStrip => "line_strip",
            OutputPrimitive::TriangleStrip => "triangle_strip",
        }
    }

    /// The GL enum's name (GL_EXT_geometry_shader4's
    /// GEOMETRY_OUTPUT_TYPE).
    pub fn gl_name(self) -> &'static str {
        match self {
            OutputPrimitive::Points => "GL_POINTS",
            OutputPrimitive::LineStrip => "GL_LINE_STRIP",
            OutputPrimitive::TriangleStrip => "GL_TRIANGLE_STRIP",
        }
    }

    pub fn from_name(name: &str) -> Option<OutputPrimitive> {
        [
            OutputPrimitive::Points,
            OutputPrimitive::LineStrip,
            OutputPrimitive::TriangleStrip,
        ]
        .into_iter()
        .find(|p| p.name() == name)
    }
}

/// What a geometry shader object declares of its layouts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct GeometryLayout {
    pub input: Option<InputPrimitive>,
    pub output: Option<OutputPrimitive>,
    pub max_vertices: Option<u32>,
}

/// How the primitive generator subdivides a patch (an evaluation
/// shader's `layout(triangles|quads|isolines) in;`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum TessMode {
    Triangles,
    Quads,
    Isolines,
}

/// How edges are split (`equal_spacing`, `fractional_even_spacing`,
/// `fractional_odd_spacing`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum TessSpacing {
    Equal,
    FractionalEven,
    FractionalOdd,
}

/// The winding of generated triangles (`cw`, `ccw`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum VertexOrder {
    Cw,
    Ccw,
}

impl TessMode {
    pub fn name(self) -> &'static str {
        match self {
            TessMode::Triangles => "triangles",
            TessMode::Quads => "quads",
            TessMode::Isolines => "isolines",
        }
    }
}

impl TessSpacing {
    pub fn name(self) -> &'static str {
        match self {
            TessSpacing::Equal => "equal_spacing",
            TessSpacing::FractionalEven => "fractional_even_spacing",
            TessSpacing::FractionalOdd => "fractional_odd_spacing",
        }
    }
}

impl VertexOrder {
    pub fn name(self) -> &'static str {
        match self {
            VertexOrder::Cw => "cw",
            VertexOrder::Ccw => "ccw",
        }
    }
}

/// What a tessellation shader object declares of its layouts
/// (GL_ARB_tessellation_shader §4.3.8): a control shader's output patch
/// size (`layout(vertices = N) out;`), an evaluation shader's primitive
/// mode, spacing, vertex order and point mode (`layout(...) in;`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct TessLayout {
    pub vertices: Option<u32>,
    pub mode: Option<TessMode>,
    pub spacing: Option<TessSpacing>,
    pub order: Option<VertexOrder>,
    pub point_mode: bool,
}

impl TessLayout {
    pub fn is_empty(&self) -> bool {
        *self == TessLayout::default()
    }
}

/// The conventions of `gl_FragCoord`: the default is a lower-left origin
/// and pixel centres at half-integers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct FragCoordConventions {
    pub origin_upper_left: bool,
    pub pixel_center_integer: bool,
    /// The shader redeclares `gl_FragCoord` (with these qualifiers or
    /// none): the linker compares the redeclarations of a program's
    /// fragment shader objects.
    pub redeclared: bool,
}

impl Module {
    /// A module of `language` and `stage` that declares nothing yet.
    pub fn empty(language: Language, stage: Stage) -> Module {
        Module {
            language,
            stage,
            structs: Vec::new(),
            globals: Vec::new(),
            functions: Vec::new(),
            extensions: Vec::new(),
            blocks: Vec::new(),
            frag_coord: Default::default(),
            geometry: Default::default(),
            tessellation: Default::default(),
            local_size: None,
            per_vertex_out: None,
            per_vertex_in: None,
        }
    }

    pub fn global(&self, id: GlobalId) -> &Global {
        &self.globals[id.0 as usize]
    }

    pub fn function(&self, id: FunctionId) -> &Function {
        &self.functions[id.0 as usize]
    }

    /// The defined `main`, if any.
    pub fn main(&self) -> Option<FunctionId> {
        self.functions
            .iter()
            .position(|f| f.name == "main" && f.body.is_some())
            .map(|i| FunctionId(i as u32))
    }

    /// The row a value of `ty` holds when `ty`'s base is an array-of-arrays
    /// row struct ([`crate::types::StructDef::array_row`]): its one
    /// member's type (`float[4]` for the rows of `float a[3][4]`); `None`
    /// for any other type. Whether `ty` itself is an array is the
    /// caller's question.
    pub fn row_member(&self, ty: Type) -> Option<Type> {
        row_member(&self.structs, ty)
    }

    /// Spells a type using this module's struct names; an array of
    /// arrays ([`crate::types::StructDef::array_row`]) as the
    /// multi-dimensional array it stands for (`float[3][4]`: 3 rows of
    /// `float[4]`).
    pub fn type_name(&self, ty: Type) -> String {
        let size = |a: Option<crate::types::ArraySize>| match a {
            Some(crate::types::ArraySize::Sized(n)) => format!("[{n}]"),
            Some(crate::types::ArraySize::Unsized) => "[]".to_string(),
            None => String::new(),
        };
        let mut dims = String::new();
        let mut t = ty;
        // Rows nest at most as deep as the declarations that made them;
        // the bound only keeps a malformed module from looping.
        for _ in 0..64 {
            let row = t.array.and_then(|_| self.row_member(t));
            match row {
                Some(row) => {
                    dims.push_str(&size(t.array));
                    t = row;
                }
                None => break,
            }
        }
        if !dims.is_empty() {
            return format!("{}{dims}{}", self.type_name(t.element()), size(t.array));
        }
        let names = |id: crate::types::StructId| {
            self.structs
                .get(id.0 as usize)
                .map(|s| s.name.clone())
                .unwrap_or_else(|| "<struct>".into())
        };
        ty.display(&names).to_string()
    }
}

/// [`Module::row_member`] over a module's struct table alone (for callers
/// that hold another part of the module mutably).
pub fn row_member(structs: &[crate::types::StructDef], ty: Type) -> Option<Type> {
    let crate::types::Base::Struct(id) = ty.base else {
        return None;
    };
    let def = structs.get(id.0 as usize)?;
    if !def.array_row {
        return None;
    }
    def.members.first().map(|m| m.ty)
}
