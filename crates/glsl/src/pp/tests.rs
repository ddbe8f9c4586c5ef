use super::*;
use crate::diag::Severity;

fn run(src: &str) -> (PpOutput, SourceMap) {
    let mut map = SourceMap::new("t", src);
    let out = preprocess(&mut map, &PpOptions::new(Stage::Vertex));
    assert_eq!(
        out.tokens
            .iter()
            .filter(|t| t.kind == TokenKind::Eof)
            .count(),
        1,
        "exactly one Eof"
    );
    assert_eq!(out.tokens.last().map(|t| &t.kind), Some(&TokenKind::Eof));
    (out, map)
}

fn render(out: &PpOutput) -> String {
    let words: Vec<String> = out
        .tokens
        .iter()
        .filter_map(|t| match &t.kind {
            TokenKind::Identifier(s) | TokenKind::Reserved(s) => Some(s.to_string()),
            TokenKind::Keyword(k) => Some(k.as_str().to_string()),
            TokenKind::IntLiteral(v) => Some(v.to_string()),
            TokenKind::UintLiteral(v) => Some(format!("{v}u")),
            TokenKind::FloatLiteral(v) => Some(format!("{v:?}")),
            TokenKind::Punct(p) => Some(p.as_str().to_string()),
            TokenKind::StringLiteral(s) => Some(format!("{s:?}")),
            TokenKind::Eof => None,
        })
        .collect();
    words.join(" ")
}

fn messages(out: &PpOutput, severity: Severity) -> Vec<String> {
    out.diagnostics
        .iter()
        .filter(|d| d.severity == severity)
        .map(|d| d.message.clone())
        .collect()
}

/// Preprocesses `src`, which must have no errors, and renders the tokens.
fn ok(src: &str) -> String {
    let (out, _) = run(src);
    let errs = messages(&out, Severity::Error);
    assert!(errs.is_empty(), "unexpected errors for {src:?}: {errs:?}");
    render(&out)
}

/// Asserts that `src` has an error whose message contains `needle`.
fn err(src: &str, needle: &str) {
    let (out, _) = run(src);
    let errs = messages(&out, Severity::Error);
    assert!(
        errs.iter().any(|m| m.contains(needle)),
        "expected an error containing {needle:?} for {src:?}, got {errs:?}"
    );
}

fn warns(src: &str, needle: &str) {
    let (out, _) = run(src);
    assert!(
        messages(&out, Severity::Error).is_empty(),
        "{:?}",
        out.diagnostics
    );
    let w = messages(&out, Severity::Warning);
    assert!(
        w.iter().any(|m| m.contains(needle)),
        "expected a warning containing {needle:?} for {src:?}, got {w:?}"
    );
}

// ---- Object-like and function-like macros ----

#[test]
fn object_macros() {
    assert_eq!(ok("#define A 1 + 2\nA * A"), "1 + 2 * 1 + 2");
    assert_eq!(ok("#define A B\n#define B 3\nA"), "3");
    assert_eq!(ok("#define E\nE x E"), "x");
    assert_eq!(ok("#define X X + 1\nX"), "X + 1");
    assert_eq!(ok("#define A B\n#define B A\nA B"), "A B");
    assert_eq!(ok("#define F (x)\nF"), "( x )");
}

#[test]
fn function_macros() {
    assert_eq!(ok("#define F(a, b) a + b\nF(1, 2)"), "1 + 2");
    assert_eq!(ok("#define F(a,b) a+b\nF(F(1,2),3)"), "1 + 2 + 3");
    assert_eq!(ok("#define F(a) [a]\nF((1, 2))"), "[ ( 1 , 2 ) ]");
    assert_eq!(ok("#define F(a) a\nF(\n  x\n)"), "x");
    assert_eq!(ok("#define F(a) [a]\nF()"), "[ ]");
    assert_eq!(ok("#define F(a, b) [a|b]\nF(,)"), "[ | ]");
    assert_eq!(ok("#define Z() 7\nZ()"), "7");
    assert_eq!(ok("#define F(a) a\nF; F (1)"), "F ; 1");
    assert_eq!(ok("#define F(x) x\n#define G F\nG(5)"), "5");
}

#[test]
fn argument_prescan_and_rescan() {
    // C++ [cpp.rescan] example.
    assert_eq!(
        ok("#define f(a) a*g\n#define g(a) f(a)\nf(2)(9)"),
        "2 * 9 * g"
    );
    assert_eq!(ok("#define f(x) x g\n#define g(y) [y]\nf(1)(2)"), "1 [ 2 ]");
    assert_eq!(ok("#define h(x) x\n#define M h(M)\nM"), "M");
    assert_eq!(ok("#define f(x) f(x)\nf(1)"), "f ( 1 )");
    assert_eq!(ok("#define f(x) x\n#define g(x) x(1)\ng(f)"), "1");
    assert_eq!(ok("#define ID(x) x\n#define A ID(B)\n#define B 4\nA"), "4");
}

#[test]
fn macro_argument_errors() {
    err(
        "#define F(a, b) a\nF(1)",
        "takes 2 arguments, but 1 was given",
    );
    err(
        "#define F(a) a\nF(1, 2)",
        "takes 1 argument, but 2 were given",
    );
    err("#define Z() 0\nZ(1)", "takes 0 arguments");
    err("#define F(a) a\nF(1", "unterminated argument list");
    err("#define F(a, a) a", "duplicate macro parameter");
    err("#define F(a b) a", "expected `,' or `)'");
    err("#define F(1) a", "expected a parameter name");
    err("#define F(a", "expected `,' or `)'");
}

#[test]
fn invocation_cannot_span_directive() {
    err(
        "#define F(a) a\nF(1,\n#define X\n2)",
        "unterminated argument list",
    );
}

#[test]
fn spans_of_expansions() {
    let src = "#define F(a) a + 1\nx = F(  y );";
    let (out, map) = run(src);
    let start = src.rfind("F(").unwrap() as u32;
    let end = src.find(");").unwrap() as u32 + 1;
    let plus = out
        .tokens
        .iter()
        .find(|t| t.kind == TokenKind::Punct(Punct::Plus))
        .unwrap();
    assert_eq!(plus.span, Span::new(start, end));
    assert_eq!(map.slice(plus.span), "F(  y )");
    let x = &out.tokens[0];
    assert_eq!(map.slice(x.span), "x");
    let src = "#define A B\n#define B 3\n  A";
    let (out, map) = run(src);
    assert_eq!(map.slice(out.tokens[0].span), "A");
}

#[test]
fn redefinition() {
    ok("#define A 1\n#define A 1");
    ok("#define A 1 \n#define A 1\t");
    ok("#define A\n#define A   ");
    ok("#define F(x) x  + 1\n#define F(x) x + 1");
    err("#define A\n#define A 1", "redefined");
    err("#define A 1\n#define A", "redefined");
    err("#define A 1+2\n#define A 1 + 2", "redefined");
    err("#define F(x) x\n#define F(y) y", "redefined");
    err("#define F(x) x\n#define F x", "redefined");
    assert_eq!(ok("#define A 1\n#undef A\n#define A 2\nA"), "2");
}

#[test]
fn reserved_macro_names() {
    err("#define GL_FOO 1", "reserved");
    err("#undef GL_FOO", "reserved");
    err("#define __LINE__ 1", "built-in macro");
    err("#undef __VERSION__", "built-in macro");
    err("#define defined 1", "`defined' cannot be used");
    warns("#define __FOO 1", "contains `__'");
    warns("#define A__B 1", "contains `__'");
    assert_eq!(ok("GL_ES"), "GL_ES");
    assert_eq!(ok("#ifdef GL_ES\nbad\n#endif\nok"), "ok");
    err("#define", "expected a macro name");
    err("#define 3 x", "expected a macro name");
}

#[test]
fn no_hash_operators() {
    // `#' (stringizing) never exists: GLSL has no strings.
    err(
        "#define S(a) #a",
        "`#' is not allowed in a macro definition",
    );
    err(
        "#version 130\n#define S(a) #a",
        "`#' is not allowed in a macro definition",
    );
    err("#version 330\n#define S #", "`#' is not allowed");
    // `##' exists from GLSL 1.30 on.
    err(
        "#define P(a, b) a ## b",
        "`##' needs GLSL 1.30 (this shader is GLSL 1.10)",
    );
    err(
        "#version 120\n#define P(a, b) a ## b",
        "`##' needs GLSL 1.30 (this shader is GLSL 1.20)",
    );
    err("a # b", "unexpected `#'");
    err("a ## b", "unexpected `##'");
    err("#version 130\na ## b", "unexpected `##'");
    // Skipped blocks may contain anything.
    ok("#ifdef X\n#define S(a) #a\n#define P(a) a ## a\n@ $ \"\n#endif");
}

/// `ok` for a GLSL 1.30 shader.
fn ok130(src: &str) -> String {
    ok(&format!("#version 130\n{src}"))
}

fn err130(src: &str, needle: &str) {
    err(&format!("#version 130\n{src}"), needle);
}

#[test]
fn token_pasting() {
    // piglit concat-01..03: with and without spaces, object-like and
    // function-like.
    assert_eq!(ok130("#define INT i##n##t\nINT x;"), "int x ;");
    assert_eq!(ok130("#define INT i ## n ## t\nINT x;"), "int x ;");
    assert_eq!(
        ok130("#define CONCAT(x, y, z) x ## y ## z\nCONCAT(i, n, t) x;"),
        "int x ;"
    );
    assert_eq!(ok130("#define P(a, b) a ## b\nP(x, 1) P(1, 2)"), "x1 12");
    assert_eq!(ok130("#define P(a, b) a ## b\nP(+, =) P(<, <=)"), "+= <<=");
    assert_eq!(
        ok130("#define P(a, b) a ## b\nP(1, .5) P(1e, 3)"),
        "1.5 1000.0"
    );
    // Only the tokens next to `##' are pasted.
    assert_eq!(ok130("#define P(a, b) [a ## b]\nP(x y, z w)"), "[ x yz w ]");
    assert_eq!(ok130("#define P(a) q a ## _s r\nP(v)"), "q v_s r");
}

#[test]
fn token_pasting_expands_after_pasting() {
    // piglit concat-04: the operands are not expanded, the result is.
    assert_eq!(
        ok130(
            "#define I i\n#define N n\n#define T t\n#define INT invalid_type\n\
             #define X I ## N ## T\nX"
        ),
        "invalid_type"
    );
    // An argument beside `##' is used as written; elsewhere, expanded.
    assert_eq!(ok130("#define A 1\n#define P(x) x x ## 2\nP(A)"), "1 A2");
    assert_eq!(ok130("#define A 1\n#define P(x) x ## 2 x\nP(A)"), "A2 1");
    assert_eq!(ok130("#define AB 7\n#define P(x, y) x ## y\nP(A, B)"), "7");
    // The result may name a function-like macro invoked by what follows.
    assert_eq!(
        ok130("#define f_1(x) <x>\n#define CALL(n, x) f_ ## n(x)\nCALL(1, 2)"),
        "< 2 >"
    );
    // piglit nested_concat: an indirection expands the arguments first.
    assert_eq!(
        ok130(
            "#define STEP_ONE() done\n#define GLUE(x,y) x ## _ ## y\n\
             #define EVALUATE(x,y) GLUE(x,y)\n#define STEP(s) EVALUATE(STEP, s)()\n\
             #define PERFORM STEP(ONE)\nPERFORM;"
        ),
        "done ;"
    );
    // A pasted name of the macro being expanded is not expanded again.
    assert_eq!(ok130("#define M(x) M ## x\nM()"), "M");
    assert_eq!(ok130("#define MM MM ## M\n#define MMM 1\nMM"), "1");
}

#[test]
fn token_pasting_empty_operands() {
    let d = "#define P(a, b) [a ## b]\n";
    assert_eq!(ok130(&format!("{d}P(, x) P(x, ) P(, )")), "[ x ] [ x ] [ ]");
    let d = "#define C(a, b, c) a ## b ## c\n";
    assert_eq!(
        ok130(&format!("{d}C(, , z) C(x, , z) C(x, y, ) C(, , )")),
        "z xz xy"
    );
    // An empty operand does not paste its neighbours' other tokens.
    assert_eq!(ok130("#define P(a) + a ## = \nP()"), "+ =");
}

#[test]
fn token_pasting_errors() {
    err130("#define P(a) ## a", "`##' cannot be at the start");
    err130("#define P(a) a ##", "`##' cannot be at the end");
    err130("#define X ##", "`##' cannot be at the start");
    err130("#define X x ##", "`##' cannot be at the end");
    let d = "#define P(a, b) a ## b\n";
    err130(
        &format!("{d}P(x, +)"),
        "pasting `x' and `+' in macro `P' does not give a valid token",
    );
    err130(&format!("{d}P(/, /)"), "pasting `/' and `/'");
    err130(&format!("{d}P(+, -)"), "pasting `+' and `-'");
    err130(&format!("{d}P(x, 1.5)"), "pasting `x' and `1.5'");
    err130("#define X a ## ## b\nX", "pasting `a' and `##'");
    // `#'s in arguments paste to a `##' token, which is not an operator.
    err130(&format!("{d}P(#, #)"), "unexpected `##'");
}

#[test]
fn token_pasting_is_bounded() {
    // Each level doubles the pasted spelling while the tokens stay few:
    // the spelling is charged to the budget.
    let mut src = String::from("#version 130\n#define D(x) x ## x\n#define L0(x) D(x)\n");
    for i in 1..60 {
        src.push_str(&format!("#define L{i}(x) L{}(D(x))\n", i - 1));
    }
    src.push_str("L59(a)\n");
    let mut map = SourceMap::new("t", src);
    let opts = PpOptions::new(Stage::Vertex);
    let out = preprocess_with_limit(&mut map, &opts, 10_000);
    let errs = messages(&out, Severity::Error);
    assert!(
        errs.iter().any(|m| m.contains("too many tokens")),
        "{errs:?}"
    );
}

#[test]
fn builtin_macros() {
    assert_eq!(ok("__LINE__\n\n__LINE__"), "1 3");
    assert_eq!(ok("__FILE__ __VERSION__"), "0 110");
    assert_eq!(ok("#version 120\n__VERSION__"), "120");
    assert_eq!(ok("#line 10\n__LINE__\n__LINE__"), "11 12");
    assert_eq!(ok("#line 10 3\n__LINE__ __FILE__"), "11 3");
    // From GLSL 3.30 the line after `#line L` is L itself (3.30 §3.3);
    // up to 1.50 it is L + 1.
    assert_eq!(ok("#version 330\n#line 10\n__LINE__\n__LINE__"), "10 11");
    assert_eq!(ok("#version 150\n#line 10\n__LINE__"), "11");
    assert_eq!(ok("#define L __LINE__\n\nL"), "3");
    assert_eq!(
        ok("#if defined(__LINE__) && defined __FILE__\nyes\n#endif"),
        "yes"
    );
    assert_eq!(ok("#if __LINE__ == 1\nyes\n#endif"), "yes");
}

#[test]
fn several_source_strings() {
    let mut map = SourceMap::from_strings("t", &["a\n", "__LINE__ __FILE__"]);
    let out = preprocess(&mut map, &PpOptions::new(Stage::Fragment));
    assert_eq!(render(&out), "a 1 1");
}

#[test]
fn line_directive_sets_locations() {
    // The operands are "constant integer expressions" after macro
    // substitution (GLSL 1.10 §3.3 to 3.30 §3.3), so `TWO+3` is line 5
    // (Mesa's preprocessor wants an integer literal there).
    let src = "a\n#line 20 4\nb\n#define TWO 2\n#line TWO+3\nc";
    let (out, map) = run(src);
    assert!(out.diagnostics.is_empty(), "{:?}", out.diagnostics);
    let loc = |i: usize| map.loc(out.tokens[i].span.start);
    assert_eq!((loc(0).source, loc(0).line), (0, 1));
    assert_eq!((loc(1).source, loc(1).line), (4, 21));
    assert_eq!((loc(2).source, loc(2).line), (4, 6));
    err("#line", "needs a line number");
    err("#line x y z", "expected an integer, found `x'");
    err("#line 3 c", "expected an integer, found `c'");
    err("#line \"\"", "expected an integer expression");
    err("#line -1", "out of range");
    err("#line 1 2 3", "end of the #line");
}

// ---- Conditionals ----

#[test]
fn conditionals() {
    assert_eq!(ok("#if 1\na\n#else\nb\n#endif"), "a");
    assert_eq!(ok("#if 0\na\n#else\nb\n#endif"), "b");
    assert_eq!(ok("#if 0\na\n#elif 2 > 1\nb\n#else\nc\n#endif"), "b");
    assert_eq!(
        ok("#define F 2\n#if F == 1\na\n#elif F == 2\nb\n#endif"),
        "b"
    );
    assert_eq!(
        ok("#define X\n#ifdef X\na\n#endif\n#ifndef X\nb\n#endif"),
        "a"
    );
    assert_eq!(ok("#if 1\n#if 0\na\n#else\nb\n#endif\n#endif"), "b");
    assert_eq!(
        ok("#if 0\n#if 1\na\n#else\nb\n#endif\n#else\nc\n#endif"),
        "c"
    );
    assert_eq!(ok("  #  if 1\nx\n  # endif"), "x");
}

#[test]
fn skipped_blocks_ignore_junk() {
    assert_eq!(
        ok("#if 0\n#bogus\n#if garbage (\n#endif\n@\n#endif\nz"),
        "z"
    );
    // Not evaluated: the outer group is skipped (piglit preprocessor-01).
    assert_eq!(
        ok("#ifdef FOO\n#if FOO == 4\n#elif SAMP == 5\n#endif\n#endif\nz"),
        "z"
    );
    // Not evaluated: an earlier branch was taken.
    assert_eq!(ok("#if 1\na\n#elif\nb\n#elif 1/0\nc\n#endif"), "a");
    ok("#ifdef X\n#define A_MACRO(x) \\\n\tif (x)\n#endif\nvoid");
}

#[test]
fn conditional_errors() {
    err("#endif", "#endif without");
    err("#else", "#else without");
    err("#elif 1", "#elif without");
    err("#if 1\n", "unterminated conditional");
    err("#ifdef X\nvoid main() {}", "unterminated conditional");
    err("#if 1\n#else\n#else\n#endif", "#else after #else");
    err("#if 1\n#else\n#elif 1\n#endif", "#elif after #else");
    err("#if\n#endif", "needs an expression");
    err("#if 0\n#elif\n#endif", "needs an expression");
    err("#ifdef\n#endif", "expected a macro name");
    err("#ifdef 3\n#endif", "expected a macro name");
    err("#if 1 +\n#endif", "found the end of the line");
    err("#if (1\n#endif", "expected `)'");
    err("#if 1 2\n#endif", "expected an operator");
    err("#if 1.5\n#endif", "floating-point");
    err("#if 'd'\n#endif", "expected an integer expression");
    err("#define E\n#if E\n#endif", "found the end of the line");
    err(
        "#if defined\n#endif",
        "expected a macro name after `defined'",
    );
    err("#if defined(X\n#endif", "expected `)'");
}

#[test]
fn if_expressions() {
    let t = |e: &str| ok(&format!("#if {e}\nyes\n#else\nno\n#endif"));
    assert_eq!(t("1 + 2 * 3 == 7"), "yes");
    assert_eq!(t("(1 + 2) * 3 == 9"), "yes");
    assert_eq!(t("-1 < 0"), "yes");
    assert_eq!(t("~0 == -1"), "yes");
    assert_eq!(t("!0 && !!5"), "yes");
    assert_eq!(t("7 / 2 == 3 && 7 % 2 == 1 && -7 / 2 == -3"), "yes");
    assert_eq!(t("1 << 4 == 16 && 256 >> 4 == 16"), "yes");
    assert_eq!(t("(6 & 3) == 2 && (6 | 3) == 7 && (6 ^ 3) == 5"), "yes");
    assert_eq!(t("1 < 2 && 2 <= 2 && 3 > 2 && 3 >= 3 && 1 != 2"), "yes");
    assert_eq!(t("0 || 0"), "no");
    assert_eq!(t("0x10 == 16 && 010 == 8"), "yes");
    assert_eq!(t("2 - 1 - 1"), "no");
    assert_eq!(t("defined X || defined(Y)"), "no");
    assert_eq!(t("+3 == 3"), "yes");
    assert_eq!(t("0 && 1 / 0"), "no");
    assert_eq!(t("1 || 1 % 0"), "yes");
    assert_eq!(t("9223372036854775807 + 1 < 0"), "yes");
    assert_eq!(t("1 << 64 == 0"), "yes");
    assert_eq!(
        ok("#define X\n#if defined X && defined(X)\nyes\n#endif"),
        "yes"
    );
    assert_eq!(
        ok("#define D defined(X)\n#define X\n#if D\nyes\n#endif"),
        "yes"
    );
    assert_eq!(ok("#define M(a) a * 2\n#if M(3) == 6\nyes\n#endif"), "yes");
}

#[test]
fn if_division_by_zero() {
    err("#if 1 / 0\n#endif", "division by zero");
    err("#if 1 % 0\n#endif", "modulus by zero");
    err("#if 1 && 1 / 0\n#endif", "division by zero");
}

#[test]
fn if_undefined_identifier_is_zero() {
    warns("#if FOO\nx\n#endif", "evaluates to 0");
    assert_eq!(ok("#if FOO == 0\nyes\n#endif"), "yes");
}

// ---- #version ----

#[test]
fn version() {
    assert_eq!(run("void").0.language.version, Version::V110);
    assert_eq!(run("#version 120\nvoid").0.language.version, Version::V120);
    assert_eq!(run("#version 110\nvoid").0.language.version, Version::V110);
    assert_eq!(
        run("// c\n/* c\n */  #version 120\nvoid")
            .0
            .language
            .version,
        Version::V120
    );
    ok("\n\n   # version 120 // trailing comment\nvoid");
}

#[test]
fn version_errors() {
    err("#version 100\n", "`100' is not supported");
    err("#version 400\n", "not supported");
    err("#version 140 core\n", "profiles exist only from GLSL 1.50");
    err("#version 150 core core\n", "after the profile");
    err("#version 330 strict\n", "unexpected `strict'");
    err("#version 0\n", "not supported");
    err("#version 999\n", "not supported");
    err("#version 4294967295\n", "not supported");
    err("#version 18446744073709551615\n", "not supported");
    err("#version 0x6e\n", "not supported");
    err("#version 110 es\n", "GLSL ES");
    err("#version 120 core\n", "profile");
    err("#version\n", "expected a version number");
    err("#version 110\n#version 110\n", "only once");
    err("int i;\n#version 110\n", "must come before anything else");
    err(
        "#pragma debug(on)\n#version 110\n",
        "must come before anything else",
    );
    err("#define V 120\n#version V\n", "must come before");
    err("#version V\n", "expected a version number");
    let (out, _) = run("#version 999\n");
    assert_eq!(out.language.version, Version::V110);
}

#[test]
fn versions_and_profiles() {
    use crate::lang::Profile;
    for (src, version, profile) in [
        ("#version 130\n", Version::V130, Profile::Compatibility),
        ("#version 140\n", Version::V140, Profile::Compatibility),
        ("#version 150\n", Version::V150, Profile::Core),
        (
            "#version 150 compatibility\n",
            Version::V150,
            Profile::Compatibility,
        ),
        ("#version 330 core\n", Version::V330, Profile::Core),
    ] {
        let (out, _) = run(src);
        assert!(messages(&out, Severity::Error).is_empty(), "{src}");
        assert_eq!(
            (out.language.version, out.language.profile),
            (version, profile)
        );
    }
    let mut map = SourceMap::new("t", "#version 150 compatibility\n");
    let mut opts = PpOptions::new(Stage::Vertex);
    opts.compatibility_context = false;
    let out = preprocess(&mut map, &opts);
    assert!(messages(&out, Severity::Error)
        .iter()
        .any(|m| m.contains("not available in a core-profile context")));
}

#[test]
fn core_contexts_remove_glsl_110_and_120() {
    let core = |src: &str| {
        let mut map = SourceMap::new("t", src);
        let mut opts = PpOptions::new(Stage::Fragment);
        opts.compatibility_context = false;
        messages(&preprocess(&mut map, &opts), Severity::Error)
    };
    let errs = core("void main() {}\n");
    assert!(
        errs.len() == 1
            && errs[0].contains("GLSL 1.10 is not available")
            && errs[0].contains("no #version"),
        "{errs:?}"
    );
    let errs = core("#version 120\nvoid main() {}\n");
    assert!(
        errs.len() == 1 && errs[0].contains("GLSL 1.20 is not available"),
        "{errs:?}"
    );
    for v in ["130", "140", "150", "150 core", "330"] {
        assert!(
            core(&format!("#version {v}\nvoid main() {{}}\n")).is_empty(),
            "{v}"
        );
    }
    // Compatibility contexts keep them.
    assert!(messages(&run("#version 120\n").0, Severity::Error).is_empty());
}

#[test]
fn keywords_follow_version() {
    let (out, _) = run("invariant precision");
    assert_eq!(
        out.tokens[0].kind,
        TokenKind::Identifier("invariant".into())
    );
    assert_eq!(
        out.tokens[1].kind,
        TokenKind::Identifier("precision".into())
    );
    let (out, _) = run("#version 120\ninvariant precision switch");
    assert_eq!(
        out.tokens[0].kind,
        TokenKind::Keyword(crate::token::Keyword::Invariant)
    );
    assert_eq!(out.tokens[1].kind, TokenKind::Reserved("precision".into()));
    assert_eq!(out.tokens[2].kind, TokenKind::Reserved("switch".into()));
}

// ---- Literals and characters ----

#[test]
fn literals() {
    let (out, _) = run("07 0x1F 42 1.5 .5 1. 1e3 2E-1");
    let kinds: Vec<_> = out.tokens.iter().map(|t| t.kind.clone()).collect();
    assert_eq!(
        kinds,
        vec![
            TokenKind::IntLiteral(7),
            TokenKind::IntLiteral(31),
            TokenKind::IntLiteral(42),
            TokenKind::FloatLiteral(1.5),
            TokenKind::FloatLiteral(0.5),
            TokenKind::FloatLiteral(1.0),
            TokenKind::FloatLiteral(1000.0),
            TokenKind::FloatLiteral(0.2),
            TokenKind::Eof,
        ]
    );
    assert_eq!(ok("4294967295"), "4294967295");
    assert_eq!(ok("#version 120\n1.0f 1e5F"), "1.0 100000.0");
}

#[test]
fn literal_errors() {
    err("int i = 08;", "octal");
    err("int i = 0xg;", "hexadecimal");
    err("float f = 1.0f;", "not allowed in GLSL 1.10");
    err("float f = 1e;", "exponent");
    err("int i = 1u;", "`u' suffix");
    warns("int i = 4294967296;", "does not fit in 32 bits");
    warns(
        "int i = 99999999999999999999999;",
        "does not fit in 32 bits",
    );
    warns("float f = 1e99;", "infinity");
}

#[test]
fn invalid_characters() {
    err("int i = \"1\";", "GLSL has no string literals");
    err("a @ b", "invalid character `@'");
    err("a $", "invalid character `$'");
    err("a \\ b", "invalid character `\\'");
    err("int é;", "invalid character");
}

// ---- Other directives ----

#[test]
fn error_directive() {
    let (out, _) = run("#error this is   bad\nvoid");
    assert_eq!(
        messages(&out, Severity::Error),
        vec!["#error this is   bad"]
    );
    err("#error\n", "#error");
    ok("#if 0\n#error no\n#endif");
}

#[test]
fn pragmas() {
    ok("#pragma optimize(on)\n#pragma debug(off)\nvoid main() {}\n#pragma debug(on)");
    ok("void main() {\n#pragma unlikely_to_be_recognized\n}");
    ok("#pragma STDGL invariant(all)\n#pragma optionNV(fastmath on)");
    err(
        "void main() {\n#pragma debug(off)\n}",
        "outside function definitions",
    );
    err(
        "void main() { if (x) {\n#pragma optimize(on)\n} }",
        "outside function",
    );
    ok("struct S {\n#pragma optimize(on)\n int a; };");
    warns("#pragma debug off", "malformed");
}

#[test]
fn extensions() {
    let (out, _) = run("#extension all : warn\n#extension foo : enable\n#extension all:disable\n");
    assert!(messages(&out, Severity::Error).is_empty());
    assert_eq!(out.extensions.len(), 3);
    assert_eq!(out.extensions[1].name, "foo");
    assert_eq!(out.extensions[1].behavior, ExtensionBehavior::Enable);
    assert_eq!(out.extensions[2].behavior, ExtensionBehavior::Disable);
    warns("#extension foo : warn", "not supported");
    warns("#extension foo : disable", "not supported");
    warns("void f();\n#extension all : warn", "before any shader code");
}

#[test]
fn extension_errors() {
    err(
        "#extension GL_FOO_bar: require",
        "required but not supported",
    );
    err("#extension all : require", "`warn' or `disable'");
    err("#extension all : enable", "`warn' or `disable'");
    err("#extension all : ddisablee", "expected `require'");
    err("#extension", "expected an extension name");
    err("#extension foo", "expected `:'");
    err("#extension foo :", "expected `require'");
    err("#extension foo behavior", "expected `:'");
    err("#extension GL_ARB_x : enable;", "unexpected `;'");
    // No macro expansion on #extension lines (piglit extension-macro-expansion).
    err(
        "#define FOO disable\n#extension all : FOO",
        "expected `require'",
    );
}

#[test]
fn texture_extensions_are_offered_from_the_version_that_has_them() {
    // GL_ARB_texture_rectangle from 1.40, GL_ARB_texture_multisample from
    // 1.50, GL_EXT_texture_array from 1.30: enabled, and their macros
    // defined, only there.
    for (name, since) in [
        ("GL_ARB_texture_rectangle", 140),
        ("GL_ARB_texture_multisample", 150),
        ("GL_EXT_texture_array", 130),
    ] {
        for v in [110, 120, 130, 140, 150, 330] {
            let src =
                format!("#version {v}\n#extension {name} : require\n#ifdef {name}\nyes\n#endif\n");
            let (out, _) = run(&src);
            let errs = messages(&out, Severity::Error);
            if v >= since {
                assert!(errs.is_empty(), "{v} {name}: {errs:?}");
                assert!(render(&out).contains("yes"), "{v} {name}");
            } else {
                assert!(
                    errs.iter()
                        .any(|m| m.contains("required but not supported")),
                    "{v} {name}: {errs:?}"
                );
                assert!(!render(&out).contains("yes"), "{v} {name}");
            }
        }
    }
    // Without #version (GLSL 1.10), no macro either.
    assert!(!ok("#ifdef GL_ARB_texture_rectangle\nyes\n#endif\n").contains("yes"));
}

#[test]
fn unknown_and_null_directives() {
    err("#foo", "unknown preprocessor directive `#foo'");
    err("#defin X", "unknown preprocessor directive");
    err("#linekfj", "unknown");
    err("#3", "expected a directive name");
    assert_eq!(ok("#\n  #  \nx"), "x");
    err("## define X", "unexpected `##'");
}

#[test]
fn undef() {
    assert_eq!(ok("#define A 1\n#undef A\nA"), "A");
    ok("#undef NEVER_DEFINED");
    err("#undef", "expected a macro name");
    warns("#define A\n#undef A B", "extra tokens");
}

#[test]
fn line_continuation() {
    assert_eq!(
        ok("#define FOO(x) \\\n\t((x) + (x))\nFOO(1)"),
        "( ( 1 ) + ( 1 ) )"
    );
    assert_eq!(ok("#define A 1 \\\r\n + 2\nA"), "1 + 2");
    // Continuation is removed before comments (piglit comment-continuation).
    assert_eq!(ok("a // comment \\\n b\nc"), "a c");
    // Line numbers still count physical lines.
    assert_eq!(ok("#define A 1 \\\n + 2\n__LINE__"), "3");
}

#[test]
fn comments_are_whitespace() {
    assert_eq!(ok("a/**/b // c\n/* d\ne */f"), "a b f");
    assert_eq!(ok("#define A 1 /* multi\nline */ + 2\nA"), "1 + 2");
    err("/* open", "unterminated comment");
}

// ---- Limits ----

fn bomb() -> String {
    let mut src = String::from("#define a0 x x\n");
    for i in 1..40 {
        src.push_str(&format!("#define a{i} a{p} a{p}\n", p = i - 1));
    }
    src.push_str("a39\n");
    src
}

#[test]
fn macro_bomb_is_an_error() {
    let mut map = SourceMap::new("t", bomb());
    let opts = PpOptions::new(Stage::Vertex);
    let out = preprocess_with_limit(&mut map, &opts, 10_000);
    assert_eq!(out.tokens.len(), 1);
    let errs = messages(&out, Severity::Error);
    assert!(
        errs.iter().any(|m| m.contains("too many tokens")),
        "{errs:?}"
    );
    // The output limit applies to plain text too.
    let mut map = SourceMap::new("t", "x ".repeat(20));
    let out = preprocess_with_limit(&mut map, &opts, 10);
    assert_eq!(out.tokens.len(), 11);
    assert!(messages(&out, Severity::Error)[0].contains("too many tokens"));
}

/// The real limit (slow in debug builds).
#[test]
#[ignore]
fn macro_bomb_at_full_limit() {
    err(&bomb(), "too many tokens");
}

#[test]
fn deep_nesting_is_an_error() {
    let n = 2000;
    let src = format!("#define F(x) x\n{}1{}", "F(".repeat(n), ")".repeat(n));
    err(&src, "nests too deeply");
    let src = format!("#if {}1{}\n#endif", "(".repeat(n), ")".repeat(n));
    err(&src, "nests too deeply");
    let src = format!("#if {}1\n#endif", "- ".repeat(n));
    err(&src, "nests too deeply");
    let src = "#if 1\n".repeat(300);
    err(&src, "nest too deeply");
}

#[test]
fn long_macro_chain() {
    let mut src = String::new();
    for i in 0..400 {
        src.push_str(&format!("#define m{i} m{}\n", i + 1));
    }
    src.push_str("m0\n");
    err(&src, "nests too deeply");
    let mut src = String::new();
    for i in 0..100 {
        src.push_str(&format!("#define m{i} m{}\n", i + 1));
    }
    src.push_str("m0\n");
    assert_eq!(ok(&src), "m100");
}

#[test]
fn never_panics() {
    let inputs = [
        "",
        "#",
        "##",
        "#if",
        "#if (",
        "#if )",
        "#elif",
        "#define",
        "#define F(",
        "#define F(,",
        "#define F(x,",
        "#define F() ",
        "F(",
        "#define F(x) x\nF(",
        "#define F(x) x\nF((",
        "#line 4294967295\nx",
        "#line 4294967296",
        "#line 99999999999999999999999",
        "#if 99999999999999999999999\n#endif",
        "#if -9223372036854775807-1 / -1\n#endif",
        "#if -9223372036854775807-1 % -1\n#endif",
        "\\",
        "\\\n",
        "/*",
        "//",
        "\r\n#\r\n",
        "#version",
        "#version 1.10",
        "#extension :",
        "#extension a : b : c",
        "#pragma",
        "#error",
        "0x",
        "1e+",
        ".",
        "..",
        "1.e",
        "#undef",
        "#ifdef",
        "\u{0}",
        "é#define",
        "#if defined",
        "#if defined(",
        "#if defined()",
        "#line 1 -1",
        "#line (",
        "#version 130\n#define P(a, b) a ## b\nP(",
        "#version 130\n#define P(a, b) a ## b\nP(#, #) P(\"x, \"y) P(@, $) P(1e, +)",
        "#version 130\n#define P(a, b) a ## b\nP(P, (1, 2)) P(P(1, 2), 3)",
        "#version 130\n#define P a ##",
        "#version 130\n#define P ## ##",
        "#version 130\n#define P(a) a ## ## a\nP(x)",
        "#version 130\n#define P(a) a ##b\n#if P(1)\n#endif",
    ];
    for src in inputs {
        let _ = run(src);
    }
    // Every prefix of a realistic shader.
    let shader = "#version 120\n#define F(a, b) ((a) * (b))\n#if defined(F) && __LINE__ > 1\n\
                  uniform vec4 c;\n#elif 0\n#else\n#endif\n#line 7 2\nvoid main() {\n\
                  gl_FragColor = F(c, 2.0f) + vec4(0x1, 07, 1e3, .5);\n}\n";
    for i in 0..=shader.len() {
        let _ = run(&shader[..i]);
    }
}

#[test]
fn eof_span_is_end_of_text() {
    let (out, _) = run("a b ");
    assert_eq!(out.tokens.last().map(|t| t.span), Some(Span::new(4, 4)));
}

#[test]
fn builtin_prelude_preprocesses_cleanly() {
    for v in [Version::V110, Version::V120] {
        for s in [Stage::Vertex, Stage::Fragment] {
            let mut map = SourceMap::new(
                "prelude",
                crate::builtins::prelude(crate::Language::new(v, true), s),
            );
            let out = preprocess(&mut map, &PpOptions::new(s));
            assert!(
                out.diagnostics.is_empty(),
                "{v:?} {s:?}: {:?}",
                out.diagnostics
            );
            assert_eq!(out.language.version, v);
            assert!(out.tokens.len() > 100);
        }
    }
}

#[test]
fn strings_need_the_printf_extension() {
    let with = ok("#extension GL_SHADERBOX_debug_printf : enable\nf(\"a %d\\n\", 1);\n");
    assert!(with.contains("\"a %d\\\\n\""), "{with}");
    err("f(\"text\");\n", "GLSL has no string literals");
    // After `disable` strings are errors again; an unterminated quote is a
    // stray character as before.
    err(
        "#extension GL_SHADERBOX_debug_printf : enable\n\
         #extension GL_SHADERBOX_debug_printf : disable\nf(\"x\");\n",
        "no string literals",
    );
    err("f(\"x);\n", "invalid character `\"'");
}

#[test]
fn long_text_expands_the_same_in_pieces() {
    // Longer than the early-expansion threshold, on one line and on many,
    // with object-like macros: the same tokens as expanding it whole.
    let n = FLUSH_TOKENS * 2 + 7;
    let one_line = format!("#define X a\n{}\n", "X ".repeat(n));
    assert_eq!(ok(&one_line), vec!["a"; n].join(" "));
    let lines = format!("#define X a\n{}", "X\n".repeat(n));
    assert_eq!(ok(&lines), vec!["a"; n].join(" "));
}

#[test]
fn function_like_invocation_spans_a_long_text() {
    // With a function-like macro defined, text is not cut early: an
    // invocation whose name is the threshold's last token still expands.
    let pad = "b ".repeat(FLUSH_TOKENS - 1);
    let src = format!("#define F(x) x + x\n{pad}F\n(\n1\n)\n");
    let out = ok(&src);
    assert!(out.ends_with("b 1 + 1"), "{}", &out[out.len() - 20..]);
}

#[test]
fn language_macros_follow_the_version_and_profile() {
    let defined = |src: &str, name: &str| {
        let text = format!("{src}#ifdef {name}\nint yes;\n#endif\n");
        ok(&text).contains("yes")
    };
    assert!(!defined("#version 120\n", "GL_FRAGMENT_PRECISION_HIGH"));
    assert!(defined("#version 130\n", "GL_FRAGMENT_PRECISION_HIGH"));
    assert!(!defined("#version 140\n", "GL_core_profile"));
    assert!(defined("#version 150\n", "GL_core_profile"));
    assert!(defined("#version 150 compatibility\n", "GL_core_profile"));
    assert!(!defined("#version 150\n", "GL_compatibility_profile"));
    assert!(defined(
        "#version 150 compatibility\n",
        "GL_compatibility_profile"
    ));
    assert!(defined(
        "#version 330 compatibility\n",
        "GL_compatibility_profile"
    ));
}

#[test]
fn arb_compatibility_gives_a_core_shader_the_compatibility_profile() {
    use crate::lang::Profile;
    let (out, _) = run("#version 150\n#extension GL_ARB_compatibility : enable\n");
    assert_eq!(out.language.profile, Profile::Compatibility);
    let mut map = SourceMap::new(
        "t",
        "#version 150\n#extension GL_ARB_compatibility : require\n",
    );
    let mut opts = PpOptions::new(Stage::Vertex);
    opts.compatibility_context = false;
    let out = preprocess(&mut map, &opts);
    assert_eq!(out.language.profile, Profile::Core);
    assert!(messages(&out, Severity::Error)
        .iter()
        .any(|m| m.contains("required but not supported")));
}
