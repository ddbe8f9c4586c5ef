//! The syntax tree the parser builds.
//!
//! The grammar stays thin: the parser records what was written (qualifier
//! lists in source order, type names as written, array sizes as
//! expressions), and semantic analysis ([`crate::sema`]) judges it. Every
//! node carries the [`Span`] of the text it came from.

use crate::source::Span;
use crate::token::Keyword;
use smol_str::SmolStr;

#[derive(Clone, Debug, PartialEq)]
pub struct Ident {
    pub name: SmolStr,
    pub span: Span,
}

/// A whole shader: its external declarations in order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TranslationUnit {
    pub items: Vec<ExternalDecl>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ExternalDecl {
    Declaration(Declaration),
    FunctionDef(FunctionDef),
}

/// A qualifier as written. The parser accepts any sequence; analysis checks
/// which combinations and orders the version allows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Qualifier {
    Const,
    Attribute,
    Uniform,
    Varying,
    Centroid,
    Invariant,
    In,
    Out,
    Inout,
    /// Interpolation qualifiers (GLSL 1.30 §4.3.7).
    Flat,
    Smooth,
    Noperspective,
    /// Precision qualifiers (GLSL 1.30 §4.5): accepted, no effect.
    Lowp,
    Mediump,
    Highp,
    /// `layout(...)`: its identifiers are in [`SpannedQualifier::layout`].
    Layout,
    /// `shared` (GL_ARB_compute_shader): a variable of the work group.
    Shared,
    /// `buffer` (GL_ARB_shader_storage_buffer_object): a shader storage
    /// block.
    Buffer,
    /// Memory qualifiers of buffer variables (GLSL 4.30 §4.10).
    Coherent,
    Volatile,
    Restrict,
    Readonly,
    Writeonly,
    /// `patch` (GL_ARB_tessellation_shader): an auxiliary storage
    /// qualifier of per-patch `in` and `out` variables.
    Patch,
}

impl Qualifier {
    pub fn as_str(self) -> &'static str {
        match self {
            Qualifier::Const => "const",
            Qualifier::Attribute => "attribute",
            Qualifier::Uniform => "uniform",
            Qualifier::Varying => "varying",
            Qualifier::Centroid => "centroid",
            Qualifier::Invariant => "invariant",
            Qualifier::In => "in",
            Qualifier::Out => "out",
            Qualifier::Inout => "inout",
            Qualifier::Flat => "flat",
            Qualifier::Smooth => "smooth",
            Qualifier::Noperspective => "noperspective",
            Qualifier::Lowp => "lowp",
            Qualifier::Mediump => "mediump",
            Qualifier::Highp => "highp",
            Qualifier::Layout => "layout",
            Qualifier::Shared => "shared",
            Qualifier::Buffer => "buffer",
            Qualifier::Coherent => "coherent",
            Qualifier::Volatile => "volatile",
            Qualifier::Restrict => "restrict",
            Qualifier::Readonly => "readonly",
            Qualifier::Writeonly => "writeonly",
            Qualifier::Patch => "patch",
        }
    }

    pub fn is_interpolation(self) -> bool {
        matches!(
            self,
            Qualifier::Flat | Qualifier::Smooth | Qualifier::Noperspective
        )
    }

    pub fn is_memory(self) -> bool {
        matches!(
            self,
            Qualifier::Coherent
                | Qualifier::Volatile
                | Qualifier::Restrict
                | Qualifier::Readonly
                | Qualifier::Writeonly
        )
    }

    pub fn is_precision(self) -> bool {
        matches!(
            self,
            Qualifier::Lowp | Qualifier::Mediump | Qualifier::Highp
        )
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct SpannedQualifier {
    pub qualifier: Qualifier,
    pub span: Span,
    /// The identifiers of `layout(...)`, in order; empty for the other
    /// qualifiers.
    pub layout: Vec<LayoutId>,
}

/// One entry of `layout(...)`: `std140`, `location = 3`. Analysis judges
/// the name (case-sensitively) and that the value is an integer literal.
#[derive(Clone, Debug, PartialEq)]
pub struct LayoutId {
    pub name: Ident,
    pub value: Option<Expr>,
    pub span: Span,
}

/// The array part of a declarator or type: one or more `[]` or `[expr]`
/// (more than one is an array of arrays, GL_ARB_arrays_of_arrays; the
/// grammar takes any number and analysis judges them).
#[derive(Clone, Debug, PartialEq)]
pub struct ArraySpec {
    /// The sizes as written, outermost (leftmost) first; never empty.
    pub dims: Vec<ArrayDim>,
    pub span: Span,
}

/// One `[]` or `[expr]` of an [`ArraySpec`].
#[derive(Clone, Debug, PartialEq)]
pub struct ArrayDim {
    /// `None` for `[]`.
    pub size: Option<Box<Expr>>,
    pub span: Span,
}

/// What a type specifier names.
#[derive(Clone, Debug, PartialEq)]
pub enum TypeName {
    /// A built-in type keyword: `void`, `float`, `vec3`, `mat2x4`, `sampler2D`...
    Builtin(Keyword),
    /// A previously declared struct name.
    Named(Ident),
    /// A struct declared in place: `struct S { ... }`.
    Struct(StructSpecifier),
}

#[derive(Clone, Debug, PartialEq)]
pub struct TypeSpecifier {
    pub name: TypeName,
    /// GLSL 1.20 array type syntax: `float[3]`.
    pub array: Option<ArraySpec>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct StructSpecifier {
    /// `None` for an anonymous struct (`struct { float x; } s;`).
    pub name: Option<Ident>,
    pub members: Vec<StructMemberDecl>,
    pub span: Span,
}

/// One member line of a struct: `vec3 a, b[2];`.
#[derive(Clone, Debug, PartialEq)]
pub struct StructMemberDecl {
    /// Qualifiers are not allowed on members; kept so analysis can say so.
    pub qualifiers: Vec<SpannedQualifier>,
    pub ty: TypeSpecifier,
    pub declarators: Vec<StructDeclarator>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct StructDeclarator {
    pub name: Ident,
    pub array: Option<ArraySpec>,
    pub span: Span,
}

/// A type with its qualifiers: `uniform vec4`, `const float`, `varying centroid vec2`.
#[derive(Clone, Debug, PartialEq)]
pub struct FullType {
    pub qualifiers: Vec<SpannedQualifier>,
    pub ty: TypeSpecifier,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Declaration {
    /// `float f(int x);`
    Prototype(FunctionProto),
    /// `uniform vec4 a, b[2] = ..., c;` or a bare `struct S {...};`
    /// (then `declarators` is empty).
    Variables(InitDeclaratorList),
    /// `invariant gl_Position, v;` (GLSL 1.20 §4.6.1).
    Invariant { names: Vec<Ident>, span: Span },
    /// `precision mediump float;` (GLSL 1.30 §4.5.3).
    Precision {
        precision: SpannedQualifier,
        ty: TypeSpecifier,
        span: Span,
    },
    /// A block: `uniform B { vec4 a; } b[2];` (GLSL 1.40 §4.3.5.1,
    /// 1.50 §4.3.7).
    Block(InterfaceBlock),
    /// Qualifiers alone: `layout(std140) uniform;` (default layout of
    /// later uniform blocks), `layout(triangles) in;`.
    Qualifiers {
        qualifiers: Vec<SpannedQualifier>,
        span: Span,
    },
}

/// An interface block as written.
#[derive(Clone, Debug, PartialEq)]
pub struct InterfaceBlock {
    pub qualifiers: Vec<SpannedQualifier>,
    pub name: Ident,
    pub members: Vec<StructMemberDecl>,
    /// The instance name and its array size, if any.
    pub instance: Option<(Ident, Option<ArraySpec>)>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct InitDeclaratorList {
    pub ty: FullType,
    pub declarators: Vec<InitDeclarator>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct InitDeclarator {
    pub name: Ident,
    /// Its sizes; two for GL_EXT_geometry_shader4's two-dimensional
    /// geometry inputs (`varying in float v[][4]`: one `float[4]` per
    /// input vertex) as for arrays of arrays.
    pub array: Option<ArraySpec>,
    pub init: Option<Expr>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct FunctionProto {
    pub return_type: FullType,
    pub name: Ident,
    pub params: Vec<ParamDecl>,
    pub span: Span,
}

/// A parameter: `const in vec3 n`, `out float x[2]`, or an unnamed `vec3`.
/// `f(void)` is parsed as no parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct ParamDecl {
    pub qualifiers: Vec<SpannedQualifier>,
    pub ty: TypeSpecifier,
    pub name: Option<Ident>,
    pub array: Option<ArraySpec>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct FunctionDef {
    pub proto: FunctionProto,
    /// The body; its statements share the parameters' scope (the grammar's
    /// `compound_statement_no_new_scope`).
    pub body: Block,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Block {
    pub stmts: Vec<Stmt>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Stmt {
    pub kind: StmtKind,
    pub span: Span,
}

/// The condition of `while` and `for`: an expression or, per the grammar,
/// a declaration with an initializer (`while (bool b = f()) ...`).
#[derive(Clone, Debug, PartialEq)]
pub enum Condition {
    Expr(Expr),
    Decl {
        ty: FullType,
        name: Ident,
        init: Expr,
        span: Span,
    },
}

#[derive(Clone, Debug, PartialEq)]
pub enum StmtKind {
    Declaration(Declaration),
    /// An expression statement; `None` for the empty statement `;`.
    Expr(Option<Expr>),
    /// `{ ... }`. `new_scope` is false where the grammar says
    /// `statement_no_new_scope` / `compound_statement_no_new_scope`
    /// (loop bodies per GLSL 1.20 §6.3 share the scope of the loop header).
    Block {
        block: Block,
        new_scope: bool,
    },
    If {
        cond: Expr,
        then: Box<Stmt>,
        else_: Option<Box<Stmt>>,
    },
    While {
        cond: Condition,
        body: Box<Stmt>,
    },
    DoWhile {
        body: Box<Stmt>,
        cond: Expr,
    },
    For {
        /// An expression statement or a declaration (never a block).
        init: Box<Stmt>,
        cond: Option<Condition>,
        step: Option<Expr>,
        body: Box<Stmt>,
    },
    /// `switch (selector) { ... }`: the body is one scope; its statements
    /// include the labels ([`StmtKind::Case`], [`StmtKind::Default`]).
    Switch {
        selector: Expr,
        body: Block,
    },
    /// `case expr:`, wherever it was written (analysis checks that it is
    /// directly in a switch body).
    Case(Expr),
    /// `default:`, likewise.
    Default,
    Break,
    Continue,
    Return(Option<Expr>),
    Discard,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    /// `+x`
    Plus,
    /// `-x`
    Minus,
    /// `!x`
    Not,
    /// `~x` (reserved in 1.10/1.20: analysis reports it)
    BitNot,
    PreInc,
    PreDec,
    PostInc,
    PostDec,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    Add,
    Sub,
    Mul,
    Div,
    /// `%` and the bitwise/shift operators are reserved in 1.10/1.20:
    /// parsed so analysis can say so.
    Mod,
    Shl,
    Shr,
    BitAnd,
    BitOr,
    BitXor,
    Less,
    Greater,
    LessEq,
    GreaterEq,
    Eq,
    NotEq,
    LogicalAnd,
    LogicalOr,
    LogicalXor,
}

impl BinaryOp {
    pub fn as_str(self) -> &'static str {
        use BinaryOp::*;
        match self {
            Add => "+",
            Sub => "-",
            Mul => "*",
            Div => "/",
            Mod => "%",
            Shl => "<<",
            Shr => ">>",
            BitAnd => "&",
            BitOr => "|",
            BitXor => "^",
            Less => "<",
            Greater => ">",
            LessEq => "<=",
            GreaterEq => ">=",
            Eq => "==",
            NotEq => "!=",
            LogicalAnd => "&&",
            LogicalOr => "||",
            LogicalXor => "^^",
        }
    }
}

/// `=` is `Assign(None)`; `+=` is `Assign(Some(Add))`, and so on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AssignOp(pub Option<BinaryOp>);

/// What a call calls: a function by name, or a constructor of a type
/// (`vec3(...)`, `S(...)`, GLSL 1.20 `float[3](...)`).
#[derive(Clone, Debug, PartialEq)]
pub enum Callee {
    Function(Ident),
    Constructor(TypeSpecifier),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    pub kind: ExprKind,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    Ident(Ident),
    IntLit(u32),
    /// `7u` (GLSL 1.30 on).
    UintLit(u32),
    FloatLit(f32),
    BoolLit(bool),
    /// `"text"` without its quotes: only the format of `debugPrintfEXT`
    /// (GL_SHADERBOX_debug_printf).
    StringLit(SmolStr),
    Unary(UnaryOp, Box<Expr>),
    Binary(BinaryOp, Box<Expr>, Box<Expr>),
    Assign(AssignOp, Box<Expr>, Box<Expr>),
    Ternary(Box<Expr>, Box<Expr>, Box<Expr>),
    /// `a[i]`
    Index(Box<Expr>, Box<Expr>),
    /// `a.b`: struct member or swizzle; analysis decides.
    Field(Box<Expr>, Ident),
    /// `f(a, b)`, `vec3(...)`. `f(void)` has no arguments.
    Call(Callee, Vec<Expr>),
    /// `a.length()` (GLSL 1.20 arrays) or any other `expr.name(args)`;
    /// analysis accepts only `length` on arrays.
    Method(Box<Expr>, Ident, Vec<Expr>),
    /// `a, b`
    Comma(Box<Expr>, Box<Expr>),
    /// `{ a, b, }`: an initializer list (GL_ARB_shading_language_420pack),
    /// only ever the initializer of a declarator or an element of one.
    InitList(Vec<Expr>),
    /// Produced by error recovery where an expression was expected; analysis
    /// gives it the error type without reporting again.
    Error,
}
