//! A readable, stable text form of an [`ir::Module`](crate::ir::Module)
//! (its [`Display`](std::fmt::Display) implementation), for snapshot tests
//! and for reading what the front end made of a shader.
//!
//! The text is GLSL-like but shows the IR as it is, not the source:
//!
//! ```text
//! // fragment shader, #version 120
//! #extension GL_SHADERBOX_debug_printf : enable
//!
//! // built-in structs: s0 gl_DepthRangeParameters, ..., s7 gl_FogParameters
//!
//! struct S {                          // s8
//!     vec3 a;
//! };
//!
//! uniform vec4 viewport;              // g0, read
//! const float k = 0.5;                // g1
//! vec4 gl_FragColor;                  // g2, builtin, written
//!
//! // f0
//! vec3 shade(in vec3 n#0, const in float k#1) {
//!     vec3 c#2 = (n#0 * k#1);
//!     loop {
//!         if (!(i#3 < 4)) {
//!             break;
//!         }
//!         ...
//!     } continuing {
//!         i#3++;
//!     }
//!     return c#2;
//! }
//! ```
//!
//! - The header names the stage and version, then one `#extension` line
//!   per directive, in source order, then a geometry shader's layouts
//!   (`layout(triangles) in;`, `layout(line_strip, max_vertices = 4) out;`)
//!   as far as it declares them.
//! - The built-in structs (`gl_LightSourceParameters`...: every module
//!   has them, their members are the spec's) on one line, then the
//!   shader's struct declarations (`sN` is the
//!   [`StructId`](crate::types::StructId)), then globals in [`GlobalId`](crate::ir::GlobalId) order (`gN`): the
//!   qualifiers `invariant`, `centroid` and the storage (`uniform`,
//!   `attribute`, `varying`, `const`; none for a private global), the type,
//!   the name, the constant initializer (`= value`) or the initializer
//!   expression run at the start of `main` (`= expr`); the comment gives
//!   the id and the flags `builtin`, `read`, `written`, and
//!   `implicit size N` for unsized arrays.
//! - Functions in [`FunctionId`](crate::ir::FunctionId) order, each after
//!   a `// fN` line; a prototype without a body ends with `;`. Parameters
//!   always show their qualifier (`in`, `out`, `inout`, `const in`) and the
//!   local holding them.
//! - Locals are `name#N` (`N` the [`LocalId`](crate::ir::LocalId), unique
//!   within a function); globals print their (unique) name. A call prints
//!   the callee's name, with `#fN` appended when several functions share
//!   that name (overloads).
//! - Statements: `T x#N = e;` / `T x#N;` (declarations, `const T` for
//!   const locals), `e;`, `{ ... }`, `if (c) { ... } else { ... }` (no
//!   `else` when empty), `loop { ... } continuing { ... }` (no `continuing`
//!   when empty; every `while`/`for`/`do` is such a loop with explicit
//!   `if (...) { break; }`), `break;`, `continue;`, `return;`,
//!   `return e;`, `discard;`. Four spaces of indentation per level.
//! - Expressions are fully parenthesized (unary, binary, ternary,
//!   assignment and comma expressions inside another expression): `(a + b)`.
//!   `*` is the component-wise product (with scalar broadcasting) and
//!   `matmul(a, b)` the linear-algebra one; `^^` is the logical xor;
//!   `convert<T>(e)` is an implicit int→float conversion; `T(args)` a
//!   constructor; built-ins print their GLSL name; `debugPrintfEXT` its
//!   format string re-spelled.
//! - Constants: a float is Rust's shortest round-trip decimal (`{:?}`:
//!   `1.0`, `0.1`, `1e-6`, `-0.0`, `NaN`, `inf`), an int in decimal, a bool
//!   `true`/`false`; other types `T(c0, c1, ...)` with the flattened
//!   components of [`ConstValue`] (matrices column-major, arrays and
//!   structs flattened too).
//! - Source spans are not printed, so the text does not change when only
//!   comments or whitespace of the source do.

use super::{
    BinaryOp, CaseLabel, ConstScalar, ConstValue, Expr, ExprKind, IncDec, Module, ParamQualifier,
    Stmt, Storage, UnaryOp,
};
use crate::printf::Piece;
use crate::types::{Base, Type};
use std::fmt::{self, Write};

impl fmt::Display for Module {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&print(self))
    }
}

/// The text of `m` (see the module docs); the same as `m.to_string()`.
pub fn print(m: &Module) -> String {
    let mut p = Printer {
        m,
        out: String::new(),
        function: None,
    };
    p.module();
    p.out
}

struct Printer<'a> {
    m: &'a Module,
    out: String,
    /// The function whose body is being printed (names its locals).
    function: Option<&'a super::Function>,
}

/// Writing into a `String` cannot fail.
macro_rules! w {
    ($p:expr, $($arg:tt)*) => {{
        let _ = write!($p.out, $($arg)*);
    }};
}

impl<'a> Printer<'a> {
    fn ty(&self, ty: Type) -> String {
        self.m.type_name(ty)
    }

    fn module(&mut self) {
        let m = self.m;
        w!(
            self,
            "// {} shader, #version {}{}\n",
            m.stage.name(),
            m.language.version.number(),
            if m.language.version.has_profiles() {
                format!(" {}", m.language.profile.name())
            } else {
                String::new()
            }
        );
        for (name, behavior) in &m.extensions {
            let b = match behavior {
                super::ExtensionBehavior::Require => "require",
                super::ExtensionBehavior::Enable => "enable",
                super::ExtensionBehavior::Warn => "warn",
                super::ExtensionBehavior::Disable => "disable",
            };
            w!(self, "#extension {name} : {b}\n");
        }
        let g = m.geometry;
        if let Some(p) = g.input {
            w!(self, "layout({}) in;\n", p.name());
        }
        let out: Vec<String> = (g.output.map(|p| p.name().to_string()).into_iter())
            .chain(g.max_vertices.map(|n| format!("max_vertices = {n}")))
            .collect();
        if !out.is_empty() {
            w!(self, "layout({}) out;\n", out.join(", "));
        }
        // The built-in structs (members fixed by the spec) on one line.
        let builtins: Vec<String> = (m.structs.iter().enumerate())
            .filter(|(_, s)| s.builtin)
            .map(|(i, s)| format!("s{i} {}", s.name))
            .collect();
        if !builtins.is_empty() {
            w!(self, "// built-in structs: {}\n", builtins.join(", "));
        }
        for (i, s) in m.structs.iter().enumerate() {
            if s.builtin {
                continue;
            }
            w!(self, "\nstruct {} {{ // s{i}\n", s.name);
            for member in &s.members {
                w!(self, "    {} {};\n", self.ty(member.ty), member.name);
            }
            self.out.push_str("};\n");
        }
        if !m.globals.is_empty() {
            self.out.push('\n');
        }
        for (i, g) in m.globals.iter().enumerate() {
            let mut line = String::new();
            if g.invariant {
                line.push_str("invariant ");
            }
            if let Some(i) = g.interpolation {
                let _ = write!(line, "{} ", i.as_str());
            }
            if let Some(l) = g.location {
                let _ = write!(line, "layout(location = {l}) ");
            }
            if let Some(b) = g.binding {
                let _ = write!(line, "layout(binding = {b}) ");
            }
            if g.centroid {
                line.push_str("centroid ");
            }
            line.push_str(match g.storage {
                Storage::Private => "",
                Storage::Const => "const ",
                Storage::Uniform => "uniform ",
                Storage::Attribute => "attribute ",
                Storage::Varying => "varying ",
                Storage::FragOutput => "out ",
                Storage::PerVertexInput => "in ",
                Storage::PerVertexOutput => "out ",
                Storage::Shared => "shared ",
                Storage::Buffer => "buffer ",
            });
            let _ = write!(line, "{} {}", self.ty(g.ty), g.name);
            if let Some(c) = &g.init {
                let _ = write!(line, " = {}", self.constant(c));
            } else if let Some(e) = &g.init_expr {
                let _ = write!(line, " = {}", self.expr_top(e));
            }
            let _ = write!(line, "; // g{i}");
            for (flag, name) in [
                (g.builtin, "builtin"),
                (g.read, "read"),
                (g.written, "written"),
            ] {
                if flag {
                    let _ = write!(line, ", {name}");
                }
            }
            if g.ty.array == Some(crate::types::ArraySize::Unsized) {
                let _ = write!(line, ", implicit size {}", g.implicit_size);
            }
            if let Some(b) = g.block.and_then(|b| m.blocks.get(b.0 as usize)) {
                let _ = write!(line, ", block {}", b.name);
            }
            self.out.push_str(&line);
            self.out.push('\n');
        }
        for (i, func) in m.functions.iter().enumerate() {
            self.function = Some(func);
            w!(
                self,
                "\n// f{i}\n{} {}(",
                self.ty(func.return_type),
                func.name
            );
            for (k, p) in func.params.iter().enumerate() {
                if k > 0 {
                    self.out.push_str(", ");
                }
                let q = match (p.is_const, p.qualifier) {
                    (true, _) => "const in",
                    (false, ParamQualifier::In) => "in",
                    (false, ParamQualifier::Out) => "out",
                    (false, ParamQualifier::InOut) => "inout",
                };
                w!(self, "{q} {} {}", self.ty(p.ty), self.local(p.local));
            }
            self.out.push(')');
            match &func.body {
                None => self.out.push_str(";\n"),
                Some(body) => {
                    self.out.push(' ');
                    self.block(body, 0);
                    self.out.push('\n');
                }
            }
        }
        self.function = None;
    }

    fn local(&self, id: super::LocalId) -> String {
        let name = self
            .function
            .and_then(|f| f.locals.get(id.0 as usize))
            .map_or("<local>", |l| l.name.as_str());
        format!("{name}#{}", id.0)
    }

    fn indent(&mut self, depth: usize) {
        for _ in 0..depth {
            self.out.push_str("    ");
        }
    }

    /// `{`, the statements one level deeper, `}` at `depth` (no newline
    /// after the brace).
    fn block(&mut self, b: &[Stmt], depth: usize) {
        self.out.push_str("{\n");
        for s in b {
            self.stmt(s, depth + 1);
        }
        self.indent(depth);
        self.out.push('}');
    }

    fn stmt(&mut self, s: &Stmt, depth: usize) {
        self.indent(depth);
        match s {
            Stmt::Expr(e) => w!(self, "{};", self.expr_top(e)),
            Stmt::Declare { local, init, .. } => {
                let l = self.function.and_then(|f| f.locals.get(local.0 as usize));
                let (ty, is_const) = l.map_or((Type::ERROR, false), |l| (l.ty, l.is_const));
                if is_const {
                    self.out.push_str("const ");
                }
                w!(self, "{} {}", self.ty(ty), self.local(*local));
                if let Some(e) = init {
                    w!(self, " = {}", self.expr_top(e));
                }
                self.out.push(';');
            }
            Stmt::Block(b) => self.block(b, depth),
            Stmt::If {
                cond, then, else_, ..
            } => {
                w!(self, "if ({}) ", self.expr_top(cond));
                self.block(then, depth);
                if !else_.is_empty() {
                    self.out.push_str(" else ");
                    self.block(else_, depth);
                }
            }
            Stmt::Loop {
                body, continuing, ..
            } => {
                self.out.push_str("loop ");
                self.block(body, depth);
                if !continuing.is_empty() {
                    self.out.push_str(" continuing ");
                    self.block(continuing, depth);
                }
            }
            Stmt::Switch {
                selector, cases, ..
            } => {
                w!(self, "switch ({}) {{\n", self.expr_top(selector));
                for c in cases {
                    for l in &c.labels {
                        self.indent(depth);
                        match l {
                            CaseLabel::Value(v) => w!(self, "case {}:\n", scalar(*v)),
                            CaseLabel::Default => self.out.push_str("default:\n"),
                        }
                    }
                    for st in &c.body {
                        self.stmt(st, depth + 1);
                    }
                }
                self.indent(depth);
                self.out.push('}');
            }
            Stmt::Break(_) => self.out.push_str("break;"),
            Stmt::Continue(_) => self.out.push_str("continue;"),
            Stmt::Return(None, _) => self.out.push_str("return;"),
            Stmt::Return(Some(e), _) => w!(self, "return {};", self.expr_top(e)),
            Stmt::Discard(_) => self.out.push_str("discard;"),
        }
        self.out.push('\n');
    }

    /// An expression standing alone (no outer parentheses).
    fn expr_top(&self, e: &Expr) -> String {
        let mut s = String::new();
        self.expr(e, &mut s, true);
        s
    }

    fn constant(&self, c: &ConstValue) -> String {
        let scalars: Vec<String> = c.components.iter().map(|&x| scalar(x)).collect();
        match (c.ty.array, c.ty.base) {
            (None, Base::Scalar(_)) if scalars.len() == 1 => scalars[0].clone(),
            _ => format!("{}({})", self.ty(c.ty), scalars.join(", ")),
        }
    }

    fn args(&self, args: &[Expr], out: &mut String) {
        for (i, a) in args.iter().enumerate() {
            if i > 0 {
                out.push_str(", ");
            }
            self.expr(a, out, true);
        }
    }

    /// Writes `e` to `out`; `top`: no parentheses around an operator
    /// expression.
    fn expr(&self, e: &Expr, out: &mut String, top: bool) {
        let (open, close) = if top { ("", "") } else { ("(", ")") };
        match &e.kind {
            ExprKind::Const(c) => out.push_str(&self.constant(c)),
            ExprKind::Global(id) => match self.m.globals.get(id.0 as usize) {
                Some(g) => out.push_str(&g.name),
                None => {
                    let _ = write!(out, "<g{}>", id.0);
                }
            },
            ExprKind::Local(id) => out.push_str(&self.local(*id)),
            ExprKind::Index { base, index } => {
                self.expr(base, out, false);
                out.push('[');
                self.expr(index, out, true);
                out.push(']');
            }
            ExprKind::Swizzle {
                base,
                components,
                count,
            } => {
                self.expr(base, out, false);
                out.push('.');
                for &c in &components[..(*count as usize).min(4)] {
                    out.push(['x', 'y', 'z', 'w'].get(c as usize).copied().unwrap_or('?'));
                }
            }
            ExprKind::Member { base, index } => {
                self.expr(base, out, false);
                let name = match base.ty.base {
                    Base::Struct(id) => self
                        .m
                        .structs
                        .get(id.0 as usize)
                        .and_then(|s| s.members.get(*index as usize))
                        .map(|m| m.name.clone()),
                    _ => None,
                };
                // An ARB_arrays_of_arrays row's member has no name: `a[i]`
                // is the row itself.
                let name = name.unwrap_or_else(|| format!("<member {index}>"));
                if name != crate::types::ARRAY_ROW_MEMBER {
                    out.push('.');
                    out.push_str(&name);
                }
            }
            ExprKind::Unary { op, operand } => {
                out.push_str(open);
                out.push(match op {
                    UnaryOp::Neg => '-',
                    UnaryOp::Not => '!',
                    UnaryOp::BitNot => '~',
                });
                self.expr(operand, out, false);
                out.push_str(close);
            }
            ExprKind::Binary {
                op: BinaryOp::MatMul,
                left,
                right,
            } => {
                out.push_str("matmul(");
                self.expr(left, out, true);
                out.push_str(", ");
                self.expr(right, out, true);
                out.push(')');
            }
            ExprKind::Binary { op, left, right } => {
                out.push_str(open);
                self.expr(left, out, false);
                let _ = write!(out, " {} ", binary(*op));
                self.expr(right, out, false);
                out.push_str(close);
            }
            ExprKind::Ternary {
                cond,
                accept,
                reject,
            } => {
                out.push_str(open);
                self.expr(cond, out, false);
                out.push_str(" ? ");
                self.expr(accept, out, false);
                out.push_str(" : ");
                self.expr(reject, out, false);
                out.push_str(close);
            }
            ExprKind::Assign { op, target, value } => {
                out.push_str(open);
                self.expr(target, out, false);
                match op {
                    Some(op) => {
                        let _ = write!(out, " {}= ", binary(*op));
                    }
                    None => out.push_str(" = "),
                }
                self.expr(value, out, false);
                out.push_str(close);
            }
            ExprKind::IncDec { op, target } => {
                out.push_str(open);
                match op {
                    IncDec::PreInc => out.push_str("++"),
                    IncDec::PreDec => out.push_str("--"),
                    _ => {}
                }
                self.expr(target, out, false);
                match op {
                    IncDec::PostInc => out.push_str("++"),
                    IncDec::PostDec => out.push_str("--"),
                    _ => {}
                }
                out.push_str(close);
            }
            ExprKind::Call { function, args } => {
                match self.m.functions.get(function.0 as usize) {
                    Some(callee) => {
                        out.push_str(&callee.name);
                        let overloads = self
                            .m
                            .functions
                            .iter()
                            .filter(|f| f.name == callee.name)
                            .count();
                        if overloads > 1 {
                            let _ = write!(out, "#f{}", function.0);
                        }
                    }
                    None => {
                        let _ = write!(out, "<f{}>", function.0);
                    }
                }
                out.push('(');
                self.args(args, out);
                out.push(')');
            }
            ExprKind::ArrayLength { array } => {
                self.expr(array, out, false);
                out.push_str(".length()");
            }
            ExprKind::DebugPrintf { format, args } => {
                out.push_str("debugPrintfEXT(\"");
                out.push_str(&format_string(format));
                out.push('"');
                for a in args {
                    out.push_str(", ");
                    self.expr(a, out, true);
                }
                out.push(')');
            }
            ExprKind::Builtin { function, args } => {
                out.push_str(function.name());
                out.push('(');
                self.args(args, out);
                out.push(')');
            }
            ExprKind::Construct { args } => {
                out.push_str(&self.ty(e.ty));
                out.push('(');
                self.args(args, out);
                out.push(')');
            }
            ExprKind::Convert { operand } => {
                let _ = write!(out, "convert<{}>(", self.ty(e.ty));
                self.expr(operand, out, true);
                out.push(')');
            }
            ExprKind::Comma { left, right } => {
                out.push_str(open);
                self.expr(left, out, false);
                out.push_str(", ");
                self.expr(right, out, false);
                out.push_str(close);
            }
        }
    }
}

fn scalar(c: ConstScalar) -> String {
    match c {
        ConstScalar::Float(x) => format!("{x:?}"),
        ConstScalar::Int(i) => i.to_string(),
        ConstScalar::Uint(u) => format!("{u}u"),
        ConstScalar::Bool(b) => b.to_string(),
    }
}

fn binary(op: BinaryOp) -> &'static str {
    match op {
        BinaryOp::Add => "+",
        BinaryOp::Sub => "-",
        BinaryOp::Mul => "*",
        BinaryOp::Div => "/",
        BinaryOp::MatMul => "matmul",
        BinaryOp::Mod => "%",
        BinaryOp::Shl => "<<",
        BinaryOp::Shr => ">>",
        BinaryOp::BitAnd => "&",
        BinaryOp::BitOr => "|",
        BinaryOp::BitXor => "^",
        BinaryOp::Less => "<",
        BinaryOp::Greater => ">",
        BinaryOp::LessEq => "<=",
        BinaryOp::GreaterEq => ">=",
        BinaryOp::Equal => "==",
        BinaryOp::NotEqual => "!=",
        BinaryOp::LogicalAnd => "&&",
        BinaryOp::LogicalOr => "||",
        BinaryOp::LogicalXor => "^^",
    }
}

/// The format string of `debugPrintfEXT` spelled back, without the
/// quotes (escapes for `"`, `\`, newlines and tabs; `%%` for a literal
/// percent sign): [`crate::printf::parse`] of it gives `pieces` again.
pub fn format_string(pieces: &[Piece]) -> String {
    let mut s = String::new();
    for p in pieces {
        match p {
            Piece::Text(t) => {
                for c in t.chars() {
                    match c {
                        '%' => s.push_str("%%"),
                        '"' => s.push_str("\\\""),
                        '\\' => s.push_str("\\\\"),
                        '\n' => s.push_str("\\n"),
                        '\t' => s.push_str("\\t"),
                        c => s.push(c),
                    }
                }
            }
            Piece::Arg(c) => {
                s.push('%');
                for (on, flag) in [
                    (c.left, '-'),
                    (c.plus, '+'),
                    (c.space, ' '),
                    (c.zero, '0'),
                    (c.alt, '#'),
                ] {
                    if on {
                        s.push(flag);
                    }
                }
                if let Some(w) = c.width {
                    let _ = write!(s, "{w}");
                }
                if let Some(p) = c.precision {
                    let _ = write!(s, ".{p}");
                }
                if c.components > 1 {
                    let _ = write!(s, "v{}", c.components);
                }
                s.push(c.kind);
            }
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use crate::{compile, CompileOptions, Stage};

    fn ir(stage: Stage, src: &str) -> String {
        let sh = compile(&[src], &CompileOptions::new(stage));
        assert!(sh.ok(), "{}", sh.info_log());
        sh.module.unwrap().to_string()
    }

    #[test]
    fn prints_globals_functions_and_statements() {
        let text = ir(
            Stage::Fragment,
            "#version 120\n\
             uniform vec4 tint;\n\
             const float k = 0.5;\n\
             struct S { vec3 a; int n; };\n\
             float f(in vec3 v, out int m) { m = 2; return v.y * k; }\n\
             void main() {\n\
                 S s = S(vec3(1.0), 3);\n\
                 int m;\n\
                 float x = 0.0;\n\
                 for (int i = 0; i < s.n; i++) { x += f(s.a, m); if (x > 2.0) break; }\n\
                 if (x < 0.0) discard;\n\
                 gl_FragColor = tint * x + float(m);\n\
             }\n",
        );
        let want = "\
// fragment shader, #version 120
// built-in structs: s0 gl_DepthRangeParameters, s1 gl_PointParameters, s2 gl_MaterialParameters, s3 gl_LightSourceParameters, s4 gl_LightModelParameters, s5 gl_LightModelProducts, s6 gl_LightProducts, s7 gl_FogParameters

struct S { // s8
    vec3 a;
    int n;
};

uniform vec4 tint; // g0, read
const float k = 0.5; // g1
vec4 gl_FragColor; // g2, builtin, written

// f0
float f(in vec3 v#0, out int m#1) {
    m#1 = 2;
    return v#0.y * 0.5;
}

// f1
void main() {
    S s#0 = S(1.0, 1.0, 1.0, 3);
    int m#1;
    float x#2 = 0.0;
    {
        int i#3 = 0;
        loop {
            if (!(i#3 < s#0.n)) {
                break;
            }
            x#2 += f(s#0.a, m#1);
            if (x#2 > 2.0) {
                break;
            }
        } continuing {
            i#3++;
        }
    }
    if (x#2 < 0.0) {
        discard;
    }
    gl_FragColor = ((tint * x#2) + float(m#1));
}
";
        assert_eq!(text, want);
    }

    #[test]
    fn prints_qualifiers_conversions_and_printf() {
        let text = ir(
            Stage::Vertex,
            "#version 120\n\
             #extension GL_SHADERBOX_debug_printf : enable\n\
             attribute vec4 pos;\n\
             uniform mat4 m;\n\
             uniform float w[2];\n\
             invariant varying vec3 c;\n\
             vec3 g(vec3 v);\n\
             float h(float x) { return x; }\n\
             float h(int x) { return float(x); }\n\
             void main() {\n\
                 float a = 1;\n\
                 int j = 2;\n\
                 float b = j;\n\
                 gl_Position = m * pos;\n\
                 c = pos.x > 0.0 ? vec3(h(a), h(2), w[1]) : vec3(-a);\n\
                 debugPrintfEXT(\"%d%% \\\"%-4.2v3f\\\"\\n\", 3, c);\n\
             }\n",
        );
        for want in [
            "// vertex shader, #version 120\n#extension GL_SHADERBOX_debug_printf : enable\n",
            "attribute vec4 pos; // g0, read\n",
            "uniform float[2] w; // g2, read\n",
            "invariant varying vec3 c; // g3, read, written\n",
            "vec3 g(in vec3 v#0);\n",
            "float h(in int x#0) {\n    return float(x#0);\n}\n",
            "    float a#0 = 1.0;\n",
            "    int j#1 = 2;\n    float b#2 = convert<float>(j#1);\n",
            "    gl_Position = matmul(m, pos);\n",
            "    c = ((pos.x > 0.0) ? vec3(h#f1(a#0), h#f2(2), w[1]) : vec3(-a#0));\n",
            "    debugPrintfEXT(\"%d%% \\\"%-4.2v3f\\\"\\n\", 3, c);\n",
        ] {
            assert!(text.contains(want), "missing {want:?} in\n{text}");
        }
    }
}
