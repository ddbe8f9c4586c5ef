//! Parser tests. Tokens come from a small test-only front end (raw lexer,
//! keyword classification and literal conversion, preprocessor lines
//! dropped), so these tests do not depend on the preprocessor.

use super::parse;
use crate::ast::*;
use crate::diag::{Code, Diagnostic};
use crate::lang::{Language, Version};
use crate::lex::{self, PpKind};
use crate::source::Span;
use crate::token::{classify, Keyword, Token, TokenKind, WordClass};

/// The language of `#version v` in a compatibility context.
fn lang(v: Version) -> Language {
    Language::new(v, true)
}

/// Test-only tokenizer: text to parser tokens, ending with `Eof`. Lines
/// starting with `#` are dropped; characters the language does not use are
/// skipped.
pub(crate) fn tokens(src: &str, version: Version) -> Vec<Token> {
    let (pp, _) = lex::lex(src, lex::LexOptions::default());
    let mut out = Vec::new();
    let mut line_start = true;
    let mut in_directive = false;
    for t in pp {
        match &t.kind {
            PpKind::Newline => {
                line_start = true;
                in_directive = false;
                continue;
            }
            PpKind::Hash if line_start => in_directive = true,
            _ => {}
        }
        line_start = false;
        if in_directive {
            continue;
        }
        let kind = match &t.kind {
            PpKind::Ident => match classify(&t.text, lang(version)) {
                WordClass::Keyword(k) => TokenKind::Keyword(k),
                WordClass::Reserved => TokenKind::Reserved(t.text.clone()),
                WordClass::Identifier => TokenKind::Identifier(t.text.clone()),
            },
            PpKind::Number => number(&t.text),
            PpKind::Punct(p) => TokenKind::Punct(*p),
            _ => continue,
        };
        out.push(Token { kind, span: t.span });
    }
    let end = src.len() as u32;
    out.push(Token {
        kind: TokenKind::Eof,
        span: Span::new(end, end),
    });
    out
}

/// Converts a number's spelling (decimal, octal, hex, float; a `u`
/// suffix makes an unsigned literal).
fn number(text: &str) -> TokenKind {
    let lower = text.to_ascii_lowercase();
    if let Some(digits) = lower.strip_suffix('u').filter(|d| !d.contains(['.', 'e'])) {
        return match number(digits) {
            TokenKind::IntLiteral(v) => TokenKind::UintLiteral(v),
            other => other,
        };
    }
    if let Some(hex) = lower.strip_prefix("0x") {
        return TokenKind::IntLiteral(u64::from_str_radix(hex, 16).unwrap_or(0) as u32);
    }
    if lower.contains(['.', 'e']) {
        let t = lower.trim_end_matches('f');
        return TokenKind::FloatLiteral(t.parse().unwrap_or(0.0));
    }
    if lower.len() > 1 && lower.starts_with('0') {
        return TokenKind::IntLiteral(u64::from_str_radix(&lower[1..], 8).unwrap_or(0) as u32);
    }
    TokenKind::IntLiteral(lower.parse::<u64>().unwrap_or(0) as u32)
}

/// The version a test shader asks for with `#version` (1.10 without one).
pub(crate) fn version_of(src: &str) -> Version {
    for line in src.lines() {
        let l = line.trim_start();
        if let Some(rest) = l.strip_prefix('#') {
            let rest = rest.trim_start();
            if let Some(v) = rest.strip_prefix("version") {
                let n: u32 = v
                    .split_whitespace()
                    .next()
                    .and_then(|s| s.parse().ok())
                    .unwrap_or(110);
                return Version::from_number(n).unwrap_or(Version::V110);
            }
        }
    }
    Version::V110
}

fn run(src: &str, version: Version) -> (TranslationUnit, Vec<Diagnostic>) {
    parse(&tokens(src, version), lang(version))
}

/// Parses in GLSL 1.20 and asserts there are no diagnostics.
fn ok(src: &str) -> TranslationUnit {
    ok_v(src, Version::V120)
}

fn ok_v(src: &str, v: Version) -> TranslationUnit {
    let (tu, d) = run(src, v);
    assert!(d.is_empty(), "unexpected diagnostics for {src:?}: {d:#?}");
    tu
}

/// The messages of a 1.20 parse.
fn errs(src: &str) -> Vec<String> {
    errs_v(src, Version::V120)
}

fn errs_v(src: &str, v: Version) -> Vec<String> {
    run(src, v).1.into_iter().map(|d| d.message).collect()
}

/// The statements of the body of the only function in `src`.
fn body(src: &str) -> Vec<Stmt> {
    let tu = ok(src);
    for item in tu.items {
        if let ExternalDecl::FunctionDef(f) = item {
            return f.body.stmts;
        }
    }
    panic!("no function in {src:?}")
}

/// The expression of `void f() { EXPR; }`.
fn expr(e: &str) -> Expr {
    expr_v(e, Version::V120)
}

fn expr_v(e: &str, v: Version) -> Expr {
    let src = format!("void f() {{ {e}; }}");
    let tu = ok_v(&src, v);
    let Some(ExternalDecl::FunctionDef(f)) = tu.items.into_iter().next() else {
        panic!("no function");
    };
    match f.body.stmts.into_iter().next().map(|s| s.kind) {
        Some(StmtKind::Expr(Some(e))) => e,
        other => panic!("not an expression statement: {other:?}"),
    }
}

/// A compact rendering of an expression's structure, for precedence tests.
fn show(e: &Expr) -> String {
    match &e.kind {
        ExprKind::Ident(i) => i.name.to_string(),
        ExprKind::IntLit(v) => v.to_string(),
        ExprKind::UintLit(v) => format!("{v}u"),
        ExprKind::FloatLit(v) => format!("{v:?}"),
        ExprKind::BoolLit(b) => b.to_string(),
        ExprKind::Unary(op, a) => match op {
            UnaryOp::PostInc => format!("({}++)", show(a)),
            UnaryOp::PostDec => format!("({}--)", show(a)),
            UnaryOp::Plus => format!("(+{})", show(a)),
            UnaryOp::Minus => format!("(-{})", show(a)),
            UnaryOp::Not => format!("(!{})", show(a)),
            UnaryOp::BitNot => format!("(~{})", show(a)),
            UnaryOp::PreInc => format!("(++{})", show(a)),
            UnaryOp::PreDec => format!("(--{})", show(a)),
        },
        ExprKind::Binary(op, a, b) => format!("({} {} {})", show(a), op.as_str(), show(b)),
        ExprKind::Assign(AssignOp(op), a, b) => {
            let o = op.map_or(String::new(), |o| o.as_str().to_string());
            format!("({} {o}= {})", show(a), show(b))
        }
        ExprKind::Ternary(c, a, b) => format!("({} ? {} : {})", show(c), show(a), show(b)),
        ExprKind::Index(a, i) => format!("{}[{}]", show(a), show(i)),
        ExprKind::Field(a, f) => format!("{}.{}", show(a), f.name),
        ExprKind::Call(callee, args) => {
            let name = match callee {
                Callee::Function(i) => i.name.to_string(),
                Callee::Constructor(t) => show_type(t),
            };
            let args: Vec<_> = args.iter().map(show).collect();
            format!("{name}({})", args.join(", "))
        }
        ExprKind::Method(a, m, args) => {
            let args: Vec<_> = args.iter().map(show).collect();
            format!("{}.{}({})", show(a), m.name, args.join(", "))
        }
        ExprKind::Comma(a, b) => format!("({}, {})", show(a), show(b)),
        ExprKind::InitList(items) => {
            let items: Vec<_> = items.iter().map(show).collect();
            format!("{{{}}}", items.join(", "))
        }
        ExprKind::StringLit(s) => format!("{s:?}"),
        ExprKind::Error => "<error>".into(),
    }
}

fn show_type(t: &TypeSpecifier) -> String {
    let base = match &t.name {
        TypeName::Builtin(k) => k.as_str().to_string(),
        TypeName::Named(i) => i.name.to_string(),
        TypeName::Struct(s) => {
            format!("struct {}", s.name.as_ref().map_or("", |n| n.name.as_str()))
        }
    };
    let mut out = base;
    for d in t.array.iter().flat_map(|a| &a.dims) {
        match &d.size {
            None => out.push_str("[]"),
            Some(e) => out.push_str(&format!("[{}]", show(e))),
        }
    }
    out
}

fn vars(item: &ExternalDecl) -> &InitDeclaratorList {
    match item {
        ExternalDecl::Declaration(Declaration::Variables(v)) => v,
        other => panic!("not a variable declaration: {other:?}"),
    }
}

fn quals(q: &[SpannedQualifier]) -> Vec<Qualifier> {
    q.iter().map(|q| q.qualifier).collect()
}

// ---- Declarations ---------------------------------------------------------

#[test]
fn empty_input_and_missing_eof() {
    // The grammar's translation_unit needs one external declaration: an
    // empty shader (or one of only directives) is an error, as in Mesa.
    for src in ["", "#version 110\n", "// nothing\n#define A 1\n"] {
        let (tu, d) = run(src, Version::V110);
        assert!(tu.items.is_empty());
        assert_eq!(d.len(), 1, "{src:?}: {d:?}");
        assert_eq!(d[0].message, "the shader is empty: it declares nothing");
    }
    let (tu, d) = parse(&[], lang(Version::V110));
    assert!(tu.items.is_empty() && d.len() == 1);
    // Without the final Eof the parser still terminates and reports.
    let mut t = tokens("float x", Version::V110);
    t.pop();
    let (tu, d) = parse(&t, lang(Version::V110));
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].message, "expected `;', found end of input");
    assert_eq!(tu.items.len(), 0);
}

#[test]
fn global_variables_with_qualifiers_arrays_and_initializers() {
    let src = "uniform vec4 a, b[2], c = vec4(1.0);\nconst float k = 2.0;";
    let tu = ok(src);
    assert_eq!(tu.items.len(), 2);
    let v = vars(&tu.items[0]);
    assert_eq!(quals(&v.ty.qualifiers), [Qualifier::Uniform]);
    assert_eq!(v.ty.ty.name, TypeName::Builtin(Keyword::Vec4));
    let names: Vec<_> = v.declarators.iter().map(|d| d.name.name.as_str()).collect();
    assert_eq!(names, ["a", "b", "c"]);
    assert!(v.declarators[1].array.is_some());
    assert_eq!(show(v.declarators[2].init.as_ref().unwrap()), "vec4(1.0)");
    assert_eq!(
        &src[v.span.start as usize..v.span.end as usize],
        "uniform vec4 a, b[2], c = vec4(1.0);"
    );
    assert_eq!(
        &src[v.declarators[1].span.start as usize..v.declarators[1].span.end as usize],
        "b[2]"
    );
}

#[test]
fn qualifier_sequences_are_kept_as_written() {
    let tu = ok("invariant centroid varying vec2 t; varying centroid const uniform float x;");
    assert_eq!(
        quals(&vars(&tu.items[0]).ty.qualifiers),
        [
            Qualifier::Invariant,
            Qualifier::Centroid,
            Qualifier::Varying
        ]
    );
    assert_eq!(
        quals(&vars(&tu.items[1]).ty.qualifiers),
        [
            Qualifier::Varying,
            Qualifier::Centroid,
            Qualifier::Const,
            Qualifier::Uniform
        ]
    );
    // `in`/`out` at global scope parse; analysis rejects them.
    ok("in float a; out float b; inout float c;");
}

#[test]
fn invariant_redeclaration_list() {
    let tu = ok("invariant gl_Position, v;");
    match &tu.items[0] {
        ExternalDecl::Declaration(Declaration::Invariant { names, .. }) => {
            let n: Vec<_> = names.iter().map(|n| n.name.as_str()).collect();
            assert_eq!(n, ["gl_Position", "v"]);
        }
        other => panic!("{other:?}"),
    }
    // In 1.10 `invariant` is an ordinary identifier: not a type.
    assert_eq!(
        errs_v("invariant gl_Position;", Version::V110),
        ["expected declaration, found `invariant'"]
    );
}

#[test]
fn structs_named_anonymous_and_nested() {
    let src = "struct S { float a, b[2]; vec3 c; } s1;\n\
               struct { S inner; struct T { int i; } t; } anon;\n\
               S s2; T t2;\n\
               struct U { float x; };";
    let tu = ok(src);
    assert_eq!(tu.items.len(), 5);
    let v = vars(&tu.items[0]);
    let TypeName::Struct(st) = &v.ty.ty.name else {
        panic!()
    };
    assert_eq!(st.name.as_ref().unwrap().name, "S");
    assert_eq!(st.members.len(), 2);
    assert_eq!(st.members[0].declarators.len(), 2);
    assert!(st.members[0].declarators[1].array.is_some());
    let v = vars(&tu.items[1]);
    let TypeName::Struct(anon) = &v.ty.ty.name else {
        panic!()
    };
    assert!(anon.name.is_none());
    assert!(matches!(&anon.members[0].ty.name, TypeName::Named(n) if n.name == "S"));
    assert!(matches!(&anon.members[1].ty.name, TypeName::Struct(_)));
    // A struct declared inside a struct is a type afterwards.
    assert!(matches!(&vars(&tu.items[3]).ty.ty.name, TypeName::Named(n) if n.name == "T"));
    // A bare struct declaration has no declarators.
    assert!(vars(&tu.items[4]).declarators.is_empty());
}

#[test]
fn struct_member_errors_recover_per_member() {
    let e = errs("struct S { float a = 1.0; int b c; vec2 d; }; S s;");
    assert_eq!(e, ["expected `;', found `='", "expected `;', found `c'"]);
    assert_eq!(
        errs("struct S { };"),
        ["expected member declaration, found `}'"]
    );
}

#[test]
fn array_types_and_constructors_in_120() {
    let tu = ok("float[3] a = float[3](1., 2., 3.);\nfloat b[] = float[](1.0, 2.0);\nvec4[2] f(float[2] p);");
    let v = vars(&tu.items[0]);
    assert_eq!(show_type(&v.ty.ty), "float[3]");
    assert_eq!(
        show(v.declarators[0].init.as_ref().unwrap()),
        "float[3](1.0, 2.0, 3.0)"
    );
    let v = vars(&tu.items[1]);
    assert!(v.declarators[0].array.as_ref().unwrap().dims[0]
        .size
        .is_none());
    assert_eq!(
        show(v.declarators[0].init.as_ref().unwrap()),
        "float[](1.0, 2.0)"
    );
    let ExternalDecl::Declaration(Declaration::Prototype(p)) = &tu.items[2] else {
        panic!()
    };
    assert_eq!(show_type(&p.return_type.ty), "vec4[2]");
    assert_eq!(show_type(&p.params[0].ty), "float[2]");
    // As statements: a declaration and an expression statement.
    let b = body("void main() { float[2] x; float[2](1.0, 2.0); }");
    assert!(matches!(b[0].kind, StmtKind::Declaration(_)));
    assert!(matches!(&b[1].kind, StmtKind::Expr(Some(e)) if show(e) == "float[2](1.0, 2.0)"));
}

#[test]
fn syntax_of_120_parses_in_110_for_analysis_to_judge() {
    let v = Version::V110;
    ok_v("float[3] a;", v);
    ok_v("float a[2] = float[2](1.0, 2.0);", v);
    ok_v("void f() { float a[2]; int n = a.length(); }", v);
    // The 1.10 grammar allows an unnamed array parameter, `float[3]`; its
    // size is kept with the parameter, not the type.
    let tu = ok_v("void f(float[3]);", v);
    let ExternalDecl::Declaration(Declaration::Prototype(p)) = &tu.items[0] else {
        panic!()
    };
    assert!(p.params[0].name.is_none() && p.params[0].ty.array.is_none());
    assert!(p.params[0].array.is_some());
    assert_eq!(p.params[0].ty.span, Span::new(7, 12));
    ok_v("void f(out float x[2]);", v);
}

#[test]
fn function_prototypes_and_definitions() {
    let src = "float f(void);\nvoid g(const in vec3 n, out float x[2], inout mat2, S);\n\
               vec4 h() { return vec4(0.0); }";
    let src = format!("struct S {{ float a; }};\n{src}");
    let tu = ok(&src);
    let ExternalDecl::Declaration(Declaration::Prototype(f)) = &tu.items[1] else {
        panic!()
    };
    assert_eq!(f.name.name, "f");
    assert!(f.params.is_empty());
    let ExternalDecl::Declaration(Declaration::Prototype(g)) = &tu.items[2] else {
        panic!()
    };
    assert_eq!(g.params.len(), 4);
    assert_eq!(
        quals(&g.params[0].qualifiers),
        [Qualifier::Const, Qualifier::In]
    );
    assert_eq!(g.params[0].name.as_ref().unwrap().name, "n");
    assert!(g.params[1].array.is_some());
    assert!(g.params[2].name.is_none());
    assert!(matches!(&g.params[3].ty.name, TypeName::Named(n) if n.name == "S"));
    let ExternalDecl::FunctionDef(h) = &tu.items[3] else {
        panic!()
    };
    assert_eq!(h.body.stmts.len(), 1);
    assert!(matches!(h.body.stmts[0].kind, StmtKind::Return(Some(_))));
    assert_eq!(
        &src[h.span.start as usize..h.span.end as usize],
        "vec4 h() { return vec4(0.0); }"
    );
    // `void` in a list with others is kept for analysis to reject.
    let tu = ok("void f(void, float);");
    let ExternalDecl::Declaration(Declaration::Prototype(f)) = &tu.items[0] else {
        panic!()
    };
    assert_eq!(f.params.len(), 2);
}

#[test]
fn local_prototype_allowed_local_definition_rejected() {
    let b = body("void main() { float g(float x); }");
    assert!(matches!(
        b[0].kind,
        StmtKind::Declaration(Declaration::Prototype(_))
    ));
    let (_, d) = run(
        "void main() { float g() { return 1.0; } float y; y = 2.0; }",
        Version::V120,
    );
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].message, "expected `;', found `{'");
    assert_eq!(
        d[0].notes,
        ["a function cannot be defined inside another function"]
    );
}

// ---- Statements -----------------------------------------------------------

#[test]
fn statements_of_every_kind() {
    let b = body(
        "void main() {\n\
           int i = 0;\n\
           if (i < 1) i++; else { i--; }\n\
           if (true) ;\n\
           while (i < 10) { i += 2; }\n\
           while (bool b = i > 3) break;\n\
           do { continue; } while (false);\n\
           for (int j = 0; j < 4; ++j) { }\n\
           for (i = 0; ; ) { discard; }\n\
           for (;;) return;\n\
           { }\n\
           ;\n\
         }",
    );
    assert_eq!(b.len(), 11);
    let StmtKind::If {
        then,
        else_: Some(e),
        ..
    } = &b[1].kind
    else {
        panic!()
    };
    assert!(matches!(then.kind, StmtKind::Expr(Some(_))));
    assert!(matches!(
        e.kind,
        StmtKind::Block {
            new_scope: true,
            ..
        }
    ));
    assert!(
        matches!(&b[2].kind, StmtKind::If { else_: None, then, .. } if then.kind == StmtKind::Expr(None))
    );
    let StmtKind::While {
        cond: Condition::Expr(_),
        body,
    } = &b[3].kind
    else {
        panic!()
    };
    assert!(matches!(
        body.kind,
        StmtKind::Block {
            new_scope: false,
            ..
        }
    ));
    let StmtKind::While {
        cond: Condition::Decl { name, .. },
        body,
    } = &b[4].kind
    else {
        panic!()
    };
    assert_eq!(name.name, "b");
    assert_eq!(body.kind, StmtKind::Break);
    let StmtKind::DoWhile { body, .. } = &b[5].kind else {
        panic!()
    };
    assert!(matches!(
        body.kind,
        StmtKind::Block {
            new_scope: true,
            ..
        }
    ));
    let StmtKind::For {
        init,
        cond: Some(_),
        step: Some(_),
        body,
    } = &b[6].kind
    else {
        panic!()
    };
    assert!(matches!(init.kind, StmtKind::Declaration(_)));
    assert!(matches!(
        body.kind,
        StmtKind::Block {
            new_scope: false,
            ..
        }
    ));
    let StmtKind::For {
        init,
        cond: None,
        step: None,
        body,
    } = &b[7].kind
    else {
        panic!()
    };
    assert!(matches!(init.kind, StmtKind::Expr(Some(_))));
    assert!(
        matches!(&body.kind, StmtKind::Block { block, .. } if block.stmts[0].kind == StmtKind::Discard)
    );
    let StmtKind::For { init, body, .. } = &b[8].kind else {
        panic!()
    };
    assert_eq!(init.kind, StmtKind::Expr(None));
    assert_eq!(body.kind, StmtKind::Return(None));
    assert!(matches!(
        b[9].kind,
        StmtKind::Block {
            new_scope: true,
            ..
        }
    ));
    assert_eq!(b[10].kind, StmtKind::Expr(None));
}

#[test]
fn dangling_else_binds_to_nearest_if() {
    let b = body("void main() { if (a) if (b) x = 1; else x = 2; }");
    let StmtKind::If {
        then, else_: None, ..
    } = &b[0].kind
    else {
        panic!()
    };
    assert!(matches!(then.kind, StmtKind::If { else_: Some(_), .. }));
}

// ---- Expressions ----------------------------------------------------------

#[test]
fn binary_precedence_and_associativity() {
    assert_eq!(
        show(&expr("a + b * c - d / e % f")),
        "((a + (b * c)) - ((d / e) % f))"
    );
    assert_eq!(show(&expr("a || b ^^ c && d")), "(a || (b ^^ (c && d)))");
    assert_eq!(show(&expr("a | b ^ c & d")), "(a | (b ^ (c & d)))");
    assert_eq!(
        show(&expr("a == b < c << d + e")),
        "(a == (b < (c << (d + e))))"
    );
    assert_eq!(show(&expr("a != b >= c >> d")), "(a != (b >= (c >> d)))");
    assert_eq!(show(&expr("a <= b > c")), "((a <= b) > c)");
    assert_eq!(show(&expr("a - b - c")), "((a - b) - c)");
    assert_eq!(show(&expr("a && b || c && d")), "((a && b) || (c && d))");
}

#[test]
fn assignment_ternary_and_comma() {
    assert_eq!(show(&expr("a = b += c")), "(a = (b += c))");
    assert_eq!(
        show(&expr("a %= b <<= c >>= d")),
        "(a %= (b <<= (c >>= d)))"
    );
    assert_eq!(
        show(&expr("a &= b ^= c |= d -= e *= f /= g")),
        "(a &= (b ^= (c |= (d -= (e *= (f /= g))))))"
    );
    assert_eq!(show(&expr("a ? b : c ? d : e")), "(a ? b : (c ? d : e))");
    assert_eq!(show(&expr("a ? b, c : d")), "(a ? (b, c) : d)");
    assert_eq!(
        show(&expr("x = a || b ? c : d")),
        "(x = ((a || b) ? c : d))"
    );
    assert_eq!(show(&expr("a = 1, b = 2, c")), "(((a = 1), (b = 2)), c)");
    // After `:` 1.20 takes an assignment, 1.10 a conditional expression.
    assert_eq!(show(&expr("a ? b : c = d")), "(a ? b : (c = d))");
    assert_eq!(
        show(&expr_v("a ? b : c = d", Version::V110)),
        "((a ? b : c) = d)"
    );
}

#[test]
fn unary_and_postfix() {
    assert_eq!(show(&expr("-a * +b")), "((-a) * (+b))");
    assert_eq!(show(&expr("!~a")), "(!(~a))");
    assert_eq!(show(&expr("- -a")), "(-(-a))");
    assert_eq!(show(&expr("++a[i].x--")), "(++(a[i].x--))");
    assert_eq!(show(&expr("--a++")), "(--(a++))");
    assert_eq!(show(&expr("a.xyz.y")), "a.xyz.y");
    assert_eq!(show(&expr("m[1][2]")), "m[1][2]");
    assert_eq!(show(&expr("f(a, b)[0].x")), "f(a, b)[0].x");
    assert_eq!(show(&expr("f() + g(void)")), "(f() + g())");
    assert_eq!(show(&expr("a.length()")), "a.length()");
    assert_eq!(show(&expr("s.a[1].length()")), "s.a[1].length()");
    assert_eq!(show(&expr("vec3(1.0).xy")), "vec3(1.0).xy");
    assert_eq!(show(&expr("mat2x3(1)")), "mat2x3(1)");
    assert_eq!(show(&expr("(a + b) * c")), "((a + b) * c)");
    assert_eq!(
        show(&expr("x = true && !false")),
        "(x = (true && (!false)))"
    );
    assert_eq!(show(&expr("a = 0x1F + 010 + 7")), "(a = ((31 + 8) + 7))");
}

#[test]
fn expression_spans_cover_their_text() {
    let src = "void f() { x = (a + b) * c.yz[i]; }";
    let tu = ok(src);
    let ExternalDecl::FunctionDef(f) = &tu.items[0] else {
        panic!()
    };
    let StmtKind::Expr(Some(e)) = &f.body.stmts[0].kind else {
        panic!()
    };
    let text = |s: Span| &src[s.start as usize..s.end as usize];
    assert_eq!(text(e.span), "x = (a + b) * c.yz[i]");
    let ExprKind::Assign(_, _, rhs) = &e.kind else {
        panic!()
    };
    assert_eq!(text(rhs.span), "(a + b) * c.yz[i]");
    let ExprKind::Binary(_, l, r) = &rhs.kind else {
        panic!()
    };
    assert_eq!(text(l.span), "(a + b)");
    assert_eq!(text(r.span), "c.yz[i]");
    assert_eq!(text(f.body.stmts[0].span), "x = (a + b) * c.yz[i];");
    assert_eq!(text(f.body.span), "{ x = (a + b) * c.yz[i]; }");
}

// ---- Type names and scopes ----------------------------------------------

#[test]
fn struct_names_declare_and_construct() {
    let b = body("struct S { float a; };\nvoid main() { S s = S(1.0); S(2.0); s = S(3.0); }");
    assert!(matches!(b[0].kind, StmtKind::Declaration(_)));
    assert!(matches!(&b[1].kind, StmtKind::Expr(Some(e)) if show(e) == "S(2.0)"));
    assert!(matches!(&b[2].kind, StmtKind::Expr(Some(e)) if show(e) == "(s = S(3.0))"));
    let b = body("struct S { float a; };\nvoid main() { S[2] a = S[2](S(1.0), S(2.0)); S[2](S(1.0), S(2.0)); }");
    assert!(matches!(b[0].kind, StmtKind::Declaration(_)));
    assert!(matches!(b[1].kind, StmtKind::Expr(Some(_))));
}

#[test]
fn variable_in_inner_scope_hides_struct_name() {
    // piglit glsl-1.20/compiler/scoping-struct-vs-variable.vert
    let b = body(
        "struct Name { float a; };\nvoid main() { vec4 Name = vec4(1.0); gl_Position = Name; }",
    );
    assert!(matches!(&b[1].kind, StmtKind::Expr(Some(e)) if show(e) == "(gl_Position = Name)"));
    // The type is back once the hiding scope ends.
    let tu = ok("struct S { float a; };\nvoid f() { { float S; S = 1.0; } S s; }\nS g;");
    let ExternalDecl::FunctionDef(f) = &tu.items[1] else {
        panic!()
    };
    assert!(matches!(f.body.stmts[1].kind, StmtKind::Declaration(_)));
    // A parameter hides a type in the function body.
    let b = body("struct S { float a; };\nvoid f(float S) { S = 2.0; }");
    assert!(matches!(b[0].kind, StmtKind::Expr(Some(_))));
    // A local struct is not a type outside its block.
    assert_eq!(
        errs("void f() { { struct T { int i; } t; T u; } T v; }"),
        ["expected `;', found `v'"]
    );
    // A for header opens a scope for the header and body.
    assert_eq!(
        errs("struct S { float a; };\nvoid f() { for (float S = 0.0; S < 1.0; S += 1.0) { S = 2.0; } S x; }"),
        Vec::<String>::new()
    );
    // Using a type as a value is a syntax error.
    assert_eq!(
        errs("struct S { float a; };\nvoid f() { S = 1.0; }"),
        ["expected identifier, found `='"]
    );
}

#[test]
fn declaration_name_scope_starts_after_initializer() {
    // `S S = S(1.0);`: the initializer still sees the type.
    let b = body("struct S { float a; };\nvoid f() { S S = S(1.0); S = S; }");
    assert!(matches!(b[0].kind, StmtKind::Declaration(_)));
    assert!(matches!(&b[1].kind, StmtKind::Expr(Some(e)) if show(e) == "(S = S)"));
}

// ---- Errors and recovery -------------------------------------------------

#[test]
fn reserved_words_are_reported_and_parsing_continues() {
    let (tu, d) = run(
        "void main() { switch (x) { case 1: break; } float y = 1.0; }\nfloat half = 1.0;\nvoid g() {}",
        Version::V120,
    );
    let m: Vec<_> = d.iter().map(|d| d.message.as_str()).collect();
    assert_eq!(
        m,
        [
            "`switch' is reserved in GLSL 1.20",
            "`half' is reserved in GLSL 1.20"
        ]
    );
    assert_eq!(d[0].code, Code::ReservedWord);
    assert_eq!(d[0].notes, ["`switch' statements require GLSL 1.30"]);
    assert_eq!(tu.items.len(), 2);
    let ExternalDecl::FunctionDef(f) = &tu.items[0] else {
        panic!()
    };
    assert_eq!(f.body.stmts.len(), 1);
    assert_eq!(
        errs("precision mediump float;"),
        ["`precision' is reserved in GLSL 1.20"]
    );
    // `precision` is only reserved from 1.20 on.
    assert_eq!(
        errs_v("precision mediump float;", Version::V110),
        ["expected declaration, found `precision'"]
    );
}

#[test]
fn independent_syntax_errors_are_all_reported_once() {
    let src = "void main() {\n  x = 1 2;\n  y = (3;\n  float z = ;\n  w = 4;\n}\nvoid g() { a b; }\nfloat k = 1.0";
    let (tu, d) = run(src, Version::V120);
    let m: Vec<_> = d.iter().map(|d| d.message.as_str()).collect();
    assert_eq!(
        m,
        [
            "expected `;', found integer `2'",
            "expected `)', found `;'",
            "expected expression, found `;'",
            "expected `;', found `b'",
            "expected `;', found end of input",
        ]
    );
    assert!(d.iter().all(|d| d.code == Code::Syntax));
    // The error points at the offending token.
    let two = src.find("2;").unwrap() as u32;
    assert_eq!(d[0].span, Some(Span::new(two, two + 1)));
    // The good statements, the one missing a `)` and the declaration with a
    // missing operand survive.
    let ExternalDecl::FunctionDef(f) = &tu.items[0] else {
        panic!()
    };
    assert_eq!(f.body.stmts.len(), 3);
    let StmtKind::Declaration(Declaration::Variables(v)) = &f.body.stmts[1].kind else {
        panic!()
    };
    assert_eq!(
        v.declarators[0].init.as_ref().unwrap().kind,
        ExprKind::Error
    );
    assert_eq!(tu.items.len(), 2);
}

#[test]
fn missing_semicolon_before_keyword_keeps_next_statement() {
    let (tu, d) = run(
        "void main() { float a = 1.0\n float b = a;\n return\n }",
        Version::V120,
    );
    let m: Vec<_> = d.iter().map(|d| d.message.as_str()).collect();
    assert_eq!(
        m,
        [
            "expected `;', found `float'",
            "expected expression, found `}'"
        ]
    );
    let ExternalDecl::FunctionDef(f) = &tu.items[0] else {
        panic!()
    };
    assert_eq!(f.body.stmts.len(), 3);
    assert!(
        matches!(&f.body.stmts[2].kind, StmtKind::Return(Some(e)) if e.kind == ExprKind::Error)
    );
}

#[test]
fn missing_closing_paren_before_semicolon_keeps_the_declaration() {
    let (tu, d) = run(
        "void main() { vec4 c = vec4(1.0;\n float a = b[2;\n x = (1 + 2; }",
        Version::V120,
    );
    let m: Vec<_> = d.iter().map(|d| d.message.as_str()).collect();
    assert_eq!(
        m,
        [
            "expected `)', found `;'",
            "expected `]', found `;'",
            "expected `)', found `;'"
        ]
    );
    let ExternalDecl::FunctionDef(f) = &tu.items[0] else {
        panic!()
    };
    assert_eq!(f.body.stmts.len(), 3);
    let StmtKind::Declaration(Declaration::Variables(v)) = &f.body.stmts[0].kind else {
        panic!()
    };
    assert_eq!(show(v.declarators[0].init.as_ref().unwrap()), "vec4(1.0)");
}

#[test]
fn errors_in_headers_skip_the_whole_construct() {
    // One error for a broken loop header; the body is skipped with it.
    assert_eq!(
        errs("void main() { for (int i = 0 i < 3; i++) { x = 1; } y = 2; }"),
        ["expected `;', found `i'"]
    );
    assert_eq!(
        errs("void main() { if (a b) { x = 1; } y = 2; }"),
        ["expected `)', found `b'"]
    );
    assert_eq!(
        errs("void f(float x,) { x = 1; }\nvoid g() {}"),
        ["expected type, found `)'"]
    );
    assert_eq!(
        errs("void main() { while (x) { y = 1 } }"),
        ["expected `;', found `}'"]
    );
}

#[test]
fn top_level_errors() {
    assert_eq!(
        errs("x = 1;\nvoid main() {}"),
        ["expected declaration, found `x'"]
    );
    assert_eq!(
        errs("void main() {} }"),
        ["expected declaration, found `}'"]
    );
    assert_eq!(errs("void main() {};"), ["expected declaration, found `;'"]);
    // Statements outside a function: one error for the run.
    assert_eq!(
        errs("  gl_Position = ftransform();\n  x = 1;\n}\nvoid main() {}\ny = 2;"),
        [
            "expected declaration, found `gl_Position'",
            "expected declaration, found `y'"
        ]
    );
    assert_eq!(errs("void main() {"), ["expected `}', found end of input"]);
    assert_eq!(
        errs("void main() { { {"),
        ["expected `}', found end of input"]
    );
    let e = run("uniform foo x;", Version::V120).1;
    assert_eq!(e[0].message, "expected type, found `foo'");
    assert_eq!(e[0].notes, ["`foo' is not the name of a type here"]);
    // Any number of sizes parses; analysis judges them.
    assert!(errs("float a[2][3]; float[1][2] b[3][4];").is_empty());
    assert_eq!(errs("void main() { float; vec4; }"), Vec::<String>::new());
    assert_eq!(
        errs("void main() { x = float; }"),
        ["expected `(', found `;'"]
    );
}

// ---- Nesting limit --------------------------------------------------------

/// Tokens of `prefix`, `unit` repeated `n` times, then `suffix`, with
/// consistent spans (lexing 100000 copies as text would be slow).
fn repeated(prefix: &str, unit: &str, n: usize, suffix: &str, v: Version) -> Vec<Token> {
    let lexed = |text: &str| {
        let mut t = tokens(text, v);
        t.pop(); // Eof
        t
    };
    let unit_toks = lexed(unit);
    let mut out = Vec::new();
    let mut offset = 0u32;
    let mut add = |toks: &[Token], len: usize, out: &mut Vec<Token>| {
        for t in toks {
            let span = Span::new(t.span.start + offset, t.span.end + offset);
            out.push(Token {
                kind: t.kind.clone(),
                span,
            });
        }
        offset += len as u32;
    };
    add(&lexed(prefix), prefix.len(), &mut out);
    for _ in 0..n {
        add(&unit_toks, unit.len(), &mut out);
    }
    add(&lexed(suffix), suffix.len(), &mut out);
    out.push(Token {
        kind: TokenKind::Eof,
        span: Span::new(offset, offset),
    });
    out
}

/// Nesting `unit` 100000 times gives exactly one "nesting too deep" error.
fn too_deep(prefix: &str, unit: &str, suffix: &str) {
    for v in [Version::V110, Version::V120] {
        let toks = repeated(prefix, unit, 100_000, suffix, v);
        let (_, d) = parse(&toks, lang(v));
        assert_eq!(d.len(), 1, "{unit:?}: {d:?}");
        assert_eq!(d[0].message, "nesting too deep");
    }
}

#[test]
fn deep_nesting_is_an_error_not_a_crash() {
    too_deep("void main() { x = ", "(", "1);}");
    too_deep("void main() ", "{", "");
    too_deep("void main() { ", "{", "}");
    too_deep("void main() { x = ", "-", "1; }");
    too_deep("void main() { x = ", "a = ", "1; }");
    too_deep("void main() { x = ", "a ? b : ", "1; }");
    too_deep("void main() { x = ", "f(", "1); }");
    too_deep("void main() { x = a", "[a", "]; }");
    too_deep("void main() { ", "if (a) ", "; }");
    too_deep("void main() { ", "while (a) ", "; }");
    too_deep("void main() { ", "for (;;) ", "; }");
    too_deep("void main() { ", "do ", "; }");
    too_deep("", "struct { ", "float x; } s;");
    too_deep("float a[", "(", "1];");
    // Just below the limit is fine.
    let depth = crate::limits::MAX_NESTING_DEPTH as usize / 4;
    let toks = repeated("void main() { x = ", "(", depth, "", Version::V120);
    let mut toks = toks;
    toks.pop();
    toks.extend(repeated("1", ")", depth, "; }", Version::V120));
    let (_, d) = parse(&toks, lang(Version::V120));
    assert!(d.is_empty(), "{d:?}");
}

#[test]
fn garbage_never_panics() {
    let inputs = [
        "",
        ";",
        "}",
        "{",
        ")",
        "(",
        "]",
        "[",
        "float",
        "struct",
        "struct {",
        "struct S {",
        "void main(",
        "void main() { for (",
        "void main() { for (;",
        "void main() { do",
        "void main() { do x; while",
        "void main() { if",
        "int f(int a, ",
        "uniform",
        "invariant",
        "invariant x",
        "float[",
        "float[](",
        "x.",
        "vec4 a = vec4(1.0).;",
        "void main() { a ? b }",
        "void main() { a ? b : }",
        "void main() { ++; }",
        "void main() { f(void, 1); }",
        "void main() { else x; }",
        "void main() { while (float x) ; }",
    ];
    for src in inputs {
        for v in [Version::V110, Version::V120] {
            let _ = run(src, v);
            // Every prefix and a truncation at every token must terminate too.
            let toks = tokens(src, v);
            for n in 0..toks.len() {
                let _ = parse(&toks[..n], lang(v));
            }
        }
    }
}

thread_local! {
    /// The lowest stack address seen at a nesting level (see `enter`).
    static STACK_LOW: std::cell::Cell<usize> = const { std::cell::Cell::new(usize::MAX) };
}

/// Records how deep the stack is at the current nesting level.
pub(super) fn note_stack_depth() {
    let probe = 0u8;
    let addr = std::hint::black_box(&probe) as *const u8 as usize;
    STACK_LOW.with(|c| c.set(c.get().min(addr)));
}

/// Stack bytes used per nesting level when parsing `src`, nested `levels`
/// deep.
fn stack_per_level(src: &str, levels: usize) -> usize {
    STACK_LOW.with(|c| c.set(usize::MAX));
    let probe = 0u8;
    let top = std::hint::black_box(&probe) as *const u8 as usize;
    let _ = run(src, Version::V120);
    let low = STACK_LOW.with(|c| c.get());
    top.saturating_sub(low) / levels
}

/// The maximum nesting must fit a 2 MiB thread stack (the default for
/// spawned threads and for tests) even in a debug build.
#[test]
fn nesting_fits_a_small_stack() {
    let n = 100;
    let cases = [
        (
            "parentheses",
            format!("void main() {{ x = {}1{}; }}", "(".repeat(n), ")".repeat(n)),
        ),
        (
            "calls",
            format!(
                "void main() {{ x = {}1{}; }}",
                "f(".repeat(n),
                ")".repeat(n)
            ),
        ),
        (
            "indexing",
            format!("void main() {{ x = a{}; }}", "[a".repeat(n)),
        ),
        ("blocks", format!("void main() {{ {} }}", "{".repeat(n))),
        (
            "negation",
            format!("void main() {{ x = {}1; }}", "-".repeat(n)),
        ),
        ("if", format!("void main() {{ {} }}", "if (a) ".repeat(n))),
        (
            "while",
            format!("void main() {{ {} }}", "while (a) ".repeat(n)),
        ),
        (
            "for",
            format!("void main() {{ {} }}", "for (;;) ".repeat(n)),
        ),
        ("struct", format!("{} }};", "struct { ".repeat(n))),
    ];
    let budget = 2 * 1024 * 1024 - 256 * 1024;
    for (name, src) in cases {
        let per = stack_per_level(&src, n);
        eprintln!("{name}: {per} bytes per level");
        assert!(
            per * crate::limits::MAX_NESTING_DEPTH as usize <= budget,
            "{name}: {per} bytes per level"
        );
    }
}

// ---- Corpus sweep ----------------------------------------------------------

/// Runs the preprocessor and parser over the piglit GLSL 1.10/1.20 compiler
/// tests listed in `/tmp/glslparser_list.txt`: nothing may panic, and every
/// test expected to compile must parse without errors.
/// `cargo test -p shaderbox-glsl piglit_sweep -- --ignored --nocapture`
#[test]
#[ignore]
fn piglit_sweep() {
    use crate::ir::Stage;
    use crate::pp::{preprocess, PpOptions};
    use crate::source::SourceMap;
    let root = "/tmp/piglit/usr/lib/x86_64-linux-gnu/piglit/";
    let Ok(list) = std::fs::read_to_string("/tmp/glslparser_list.txt") else {
        eprintln!("no /tmp/glslparser_list.txt; skipped");
        return;
    };
    let (mut total, mut pass_total, mut fail_total, mut pp_rejected) = (0, 0, 0, 0);
    let mut panics = Vec::new();
    let mut bad_pass = Vec::new();
    let mut fail_rejected = 0;
    let verbose = std::env::var_os("SWEEP_VERBOSE").is_some();
    for line in list.lines() {
        let Some(cmd) = line.split('\t').nth(1) else {
            continue;
        };
        let quoted: Vec<&str> = cmd.split('\'').skip(1).step_by(2).collect();
        let (Some(path), Some(expect)) = (quoted.get(1), quoted.get(2)) else {
            continue;
        };
        let Ok(src) = std::fs::read_to_string(format!("{root}{path}")) else {
            continue;
        };
        total += 1;
        let stage = if path.ends_with(".vert") {
            Stage::Vertex
        } else {
            Stage::Fragment
        };
        let mut map = SourceMap::new(*path, src.as_str());
        let pp = preprocess(&mut map, &PpOptions::new(stage));
        if pp.diagnostics.iter().any(|d| d.is_error()) {
            pp_rejected += 1;
            continue;
        }
        let result = std::panic::catch_unwind(|| parse(&pp.tokens, pp.language));
        let Ok((_, diags)) = result else {
            panics.push(path.to_string());
            continue;
        };
        let errors: Vec<_> = diags.iter().filter(|d| d.is_error()).collect();
        if *expect == "pass" {
            pass_total += 1;
            if let Some(e) = errors.first() {
                bad_pass.push(format!("{path}: {}", e.message));
            }
        } else {
            fail_total += 1;
            fail_rejected += !errors.is_empty() as usize;
            if let (Some(e), true) = (errors.first(), verbose) {
                eprintln!("  fail-rejected {path}: {}", e.message);
            }
        }
    }
    eprintln!(
        "piglit: {total} files; {pp_rejected} rejected by the preprocessor; \
         parsed {pass_total} expected to pass, {fail_total} expected to fail"
    );
    eprintln!("panics: {}", panics.len());
    eprintln!("expected-pass with parse errors: {}", bad_pass.len());
    for b in &bad_pass {
        eprintln!("  {b}");
    }
    eprintln!("expected-fail rejected by the parser: {fail_rejected}");
    assert!(panics.is_empty(), "{panics:?}");
    assert!(bad_pass.is_empty());
}

/// Parses every file in `$GLSL_SWEEP_DIR` (real-world shaders, which may
/// contain transcription errors) and prints the diagnostics; only panics
/// fail. `GLSL_SWEEP_DIR=dir cargo test -p shaderbox-glsl dir_sweep -- --ignored --nocapture`
#[test]
#[ignore]
fn dir_sweep() {
    let Some(dir) = std::env::var_os("GLSL_SWEEP_DIR") else {
        eprintln!("GLSL_SWEEP_DIR not set; skipped");
        return;
    };
    let mut paths: Vec<_> = std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| e.path())
        .collect();
    paths.sort();
    let mut clean = 0;
    for path in &paths {
        let Ok(src) = std::fs::read_to_string(path) else {
            continue;
        };
        let v = version_of(&src);
        let toks = tokens(&src, v);
        let (_, diags) = parse(&toks, lang(v));
        if diags.is_empty() {
            clean += 1;
        }
        for d in diags {
            let at = d.span.map_or(0, |s| s.start as usize);
            let line = src[..at.min(src.len())].lines().count();
            eprintln!("{}:{line}: {}", path.display(), d.message);
        }
    }
    eprintln!("{} files, {clean} without diagnostics", paths.len());
}

// ---- Randomized robustness ------------------------------------------------

/// A small deterministic pseudo-random generator (xorshift64*).
struct Rng(u64);

impl Rng {
    fn below(&mut self, n: usize) -> usize {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 33) as usize % n.max(1)
    }
}

/// Mutates the tokens of a valid shader (drop, duplicate, swap, insert
/// tokens) many times: the parser must terminate without panicking, and
/// every diagnostic must point inside the input.
fn mutate_and_parse(src: &str, rounds: usize, seed: u64) {
    let mut rng = Rng(seed | 1);
    for v in [Version::V110, Version::V120] {
        let base = tokens(src, v);
        let body = &base[..base.len() - 1];
        for _ in 0..rounds {
            let mut t: Vec<Token> = body.to_vec();
            for _ in 0..1 + rng.below(4) {
                if t.is_empty() {
                    break;
                }
                let i = rng.below(t.len());
                let j = rng.below(t.len());
                match rng.below(4) {
                    0 => {
                        t.remove(i);
                    }
                    1 => {
                        let x = t[i].clone();
                        t.insert(j, x);
                    }
                    2 => t.swap(i, j),
                    _ => t.truncate(i),
                }
            }
            let end = src.len() as u32;
            t.push(Token {
                kind: TokenKind::Eof,
                span: Span::new(end, end),
            });
            let (_, diags) = parse(&t, lang(v));
            for d in diags {
                assert!(d.span.is_some_and(|s| s.end <= end), "{d:?}");
            }
        }
    }
}

const SAMPLE: &str = "#version 120
struct Light { vec3 pos; float k[2]; };
uniform Light lights[4];
varying vec2 uv;
invariant gl_Position;
float[3] w = float[3](1.0, 2.0, 3.0);
float f(in float x, out vec2 y[2], Light l);
vec4 shade(const Light l, vec3 n) {
    float d = max(dot(n, normalize(l.pos)), 0.0);
    return vec4(d) * (l.k[0] + l.k.length() > 1 ? 1.0 : 0.5);
}
void main() {
    Light L = Light(vec3(1.0), float[2](0.0, 1.0));
    for (int i = 0; i < 4; ++i) { if (i == 2) continue; else L.pos += lights[i].pos; }
    while (bool b = L.pos.x > 0.0) { L.pos.x -= 1.0; }
    do { L.pos.y++; } while (L.pos.y < 3.0);
    { float Light = 1.0; Light *= 2.0; }
    gl_FragColor = shade(L, vec3(uv, 1.0)) + vec4(w[1], -w[2], !true ? 1.0 : 0.0, 1.0);
    if (gl_FragColor.a < 0.5) discard;
}
";

#[test]
fn sample_parses_and_mutations_never_panic() {
    ok(SAMPLE);
    mutate_and_parse(SAMPLE, 300, 0x5eed);
}

/// The long version: `cargo test -p shaderbox-glsl mutation_soak -- --ignored`.
#[test]
#[ignore]
fn mutation_soak() {
    for seed in 1..200 {
        mutate_and_parse(SAMPLE, 1000, seed);
    }
}

#[test]
fn near_miss_type_names_get_a_hint_and_still_declare() {
    use super::type_name_hint;
    let l = lang(Version::V120);
    assert!(type_name_hint("vec", l)
        .unwrap()
        .contains("`vec2', `vec3' or `vec4'"));
    assert!(type_name_hint("mat", l).unwrap().contains("`mat4'"));
    assert!(type_name_hint("Vec", l).unwrap().contains("lower case"));
    assert_eq!(
        type_name_hint("Vec3", l).as_deref(),
        Some("type names are lower case: write `vec3'")
    );
    assert_eq!(type_name_hint("If", l), None);
    assert_eq!(type_name_hint("uvec", l), None);
    assert!(type_name_hint("uvec", lang(Version::V130)).is_some());
    // Parsed as a declaration, so no cascade of syntax errors.
    let (tu, d) = run("void main() { vec n = vec3(1.0); }", Version::V110);
    assert!(d.is_empty(), "{d:?}");
    assert_eq!(tu.items.len(), 1);
}

#[test]
fn switch_labels_are_statements_of_the_body() {
    let src = "#version 130\nvoid f(int x) { switch (x + 1) { case 1u: case 2: x = 3; break; default: ; } }";
    let tu = ok_v(src, Version::V130);
    let Some(ExternalDecl::FunctionDef(f)) = tu.items.into_iter().next() else {
        panic!("no function");
    };
    let [Stmt {
        kind: StmtKind::Switch { selector, body },
        ..
    }] = f.body.stmts.as_slice()
    else {
        panic!("not a switch: {:?}", f.body.stmts);
    };
    assert_eq!(show(selector), "(x + 1)");
    let kinds: Vec<String> = body
        .stmts
        .iter()
        .map(|s| match &s.kind {
            StmtKind::Case(e) => format!("case {}", show(e)),
            StmtKind::Default => "default".into(),
            StmtKind::Break => "break".into(),
            StmtKind::Expr(None) => ";".into(),
            StmtKind::Expr(Some(_)) => "expr".into(),
            other => format!("{other:?}"),
        })
        .collect();
    assert_eq!(
        kinds,
        ["case 1u", "case 2", "expr", "break", "default", ";"]
    );
    // A label needs its colon; the body its braces.
    assert!(!errs_v(
        "void f(int x) { switch (x) { case 1 x = 2; } }",
        Version::V130
    )
    .is_empty());
    assert!(!errs_v("void f(int x) { switch (x) case 1: ; }", Version::V130).is_empty());
}

#[test]
fn initializer_lists_nest_and_take_a_trailing_comma() {
    let tu = ok("vec2 a[2] = { { 1.0, 2.0 }, vec2(3.0), }, b = { x, (y, z) };");
    let d = &vars(&tu.items[0]).declarators;
    let init = |i: usize| d[i].init.as_ref().map(show);
    assert_eq!(init(0).as_deref(), Some("{{1.0, 2.0}, vec2(3.0)}"));
    // A comma outside parentheses ends an initializer; inside them it is
    // the sequence operator.
    assert_eq!(init(1).as_deref(), Some("{x, (y, z)}"));
    assert!(!errs("float a[1] = { 1.0 ;").is_empty());
    assert!(!errs("void f() { vec2 v; v = { 1.0, 2.0 }; }").is_empty());
}
