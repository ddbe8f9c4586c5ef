//! Macro definitions and macro expansion (GLSL 1.20 §3.3: "as is standard
//! for C++ preprocessors").
//!
//! The expander works on a stack of pending items (the input, reversed).
//! Expanding a macro pushes its replacement followed by an end marker; while
//! the replacement is being rescanned the macro is *disabled*, and a token
//! naming a disabled macro is *painted* so that it is never expanded again
//! (C++ [cpp.rescan]). Arguments of function-like macros are fully expanded
//! on their own before substitution, except beside a `##` (GLSL 1.30 on),
//! where they are pasted as written and only the result is rescanned.
//!
//! Termination and size are bounded: every replacement is charged to a
//! token [`Budget`] (as is the spelling of pasted tokens, an eighth of a
//! token per byte), and nesting (active macros, and arguments within
//! arguments) is limited by [`limits::MAX_MACRO_EXPANSION_DEPTH`].

use crate::diag::{Code, Diagnostic};
use crate::lex::{self, LexOptions, PpKind, PpToken};
use crate::limits;
use crate::source::{SourceMap, Span};
use crate::token::Punct;
use smol_str::SmolStr;
use std::collections::{BTreeMap, HashSet};

/// A preprocessing token on its way through expansion.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PTok {
    pub kind: PpKind,
    pub text: SmolStr,
    /// Where the token is in the source, or the span of the outermost macro
    /// invocation that produced it.
    pub span: Span,
    pub space_before: bool,
    /// Names a macro that was disabled when the token was scanned: it is
    /// never expanded.
    pub painted: bool,
}

impl From<PpToken> for PTok {
    fn from(t: PpToken) -> PTok {
        PTok {
            kind: t.kind,
            text: t.text,
            span: t.span,
            space_before: t.space_before,
            painted: false,
        }
    }
}

impl PTok {
    /// A number token with the given value, as the built-in macros produce.
    pub fn number(value: u64, span: Span, space_before: bool) -> PTok {
        PTok {
            kind: PpKind::Number,
            text: SmolStr::new(value.to_string()),
            span,
            space_before,
            painted: false,
        }
    }

    pub fn is_punct(&self, p: Punct) -> bool {
        self.kind == PpKind::Punct(p)
    }
}

/// A `#define`d macro.
#[derive(Clone, Debug)]
pub(crate) struct Macro {
    /// `Some` for a function-like macro.
    pub params: Option<Vec<SmolStr>>,
    pub body: Vec<PpToken>,
    /// The macro's name in its `#define`.
    pub name_span: Span,
}

impl Macro {
    /// A predefined object-like macro whose value is `1`.
    pub fn one() -> Macro {
        Macro {
            params: None,
            body: vec![PpToken {
                kind: PpKind::Number,
                text: "1".into(),
                span: Span::default(),
                space_before: true,
            }],
            name_span: Span::default(),
        }
    }

    /// Whether a redefinition is allowed: the same parameters and the same
    /// replacement list, where whitespace between tokens must agree in
    /// presence but not amount (C++ [cpp.replace]; trailing whitespace does
    /// not count, piglit redefine-04).
    pub fn same_definition(&self, other: &Macro) -> bool {
        self.params == other.params
            && self.body.len() == other.body.len()
            && self
                .body
                .iter()
                .zip(&other.body)
                .enumerate()
                .all(|(i, (a, b))| {
                    a.kind == b.kind
                        && a.text == b.text
                        && (i == 0 || a.space_before == b.space_before)
                })
    }
}

/// The defined macros, by name.
pub(crate) type MacroTable = BTreeMap<SmolStr, Macro>;

/// The macros the implementation defines, which `#define`/`#undef` may not
/// touch (§3.3). `GL_ES` is deliberately absent: this is desktop GLSL.
pub(crate) const BUILTIN_MACROS: &[&str] = &["__LINE__", "__FILE__", "__VERSION__"];

/// How many tokens macro replacement may still produce.
#[derive(Debug)]
pub(crate) struct Budget {
    pub limit: usize,
    pub remaining: usize,
    /// Set once the budget ran out (reported once); expansion stops.
    pub exhausted: bool,
}

impl Budget {
    pub fn new(tokens: usize) -> Budget {
        Budget {
            limit: tokens,
            remaining: tokens,
            exhausted: false,
        }
    }
}

/// The macros whose replacement is being rescanned, innermost last. A
/// macro is never active twice, so a set answers membership exactly.
#[derive(Default)]
struct Disabled {
    stack: Vec<SmolStr>,
    set: HashSet<SmolStr>,
}

impl Disabled {
    fn push(&mut self, name: SmolStr) {
        self.set.insert(name.clone());
        self.stack.push(name);
    }

    fn pop(&mut self) {
        if let Some(name) = self.stack.pop() {
            self.set.remove(&name);
        }
    }

    fn contains(&self, name: &SmolStr) -> bool {
        self.set.contains(name)
    }

    fn len(&self) -> usize {
        self.stack.len()
    }
}

enum Item {
    Tok(PTok),
    /// The end of the replacement of the innermost active macro.
    End,
}

/// Expands macros in token lists. Borrows what expansion needs from the
/// preprocessor.
pub(crate) struct Expander<'a> {
    pub macros: &'a MacroTable,
    pub map: &'a SourceMap,
    /// Value of `__VERSION__`.
    pub version: u32,
    pub diags: &'a mut Vec<Diagnostic>,
    pub budget: &'a mut Budget,
    /// Expanding an `#if`/`#elif` line: the operand of a `defined` produced
    /// by expansion is not expanded (what GCC and Mesa do; C++ leaves it
    /// undefined).
    pub in_condition: bool,
}

impl Expander<'_> {
    /// Fully macro-expands `input`. A function-like macro invocation must be
    /// complete within `input`.
    pub fn expand(&mut self, input: Vec<PTok>) -> Vec<PTok> {
        self.expand_at(input, 0)
    }

    fn expand_at(&mut self, input: Vec<PTok>, depth: u32) -> Vec<PTok> {
        let macros = self.macros;
        let mut stack: Vec<Item> = input.into_iter().rev().map(Item::Tok).collect();
        let mut disabled = Disabled::default();
        let mut out = Vec::new();
        while let Some(item) = stack.pop() {
            let tok = match item {
                Item::End => {
                    disabled.pop();
                    continue;
                }
                Item::Tok(t) => t,
            };
            if self.budget.exhausted {
                break;
            }
            if tok.kind != PpKind::Ident || tok.painted {
                out.push(tok);
                continue;
            }
            if self.in_condition && tok.text == "defined" {
                out.push(tok);
                pass_defined_operand(&mut stack, &mut disabled, &mut out);
                continue;
            }
            if let Some(t) = self.builtin(&tok) {
                out.push(t);
                continue;
            }
            let Some(mac) = macros.get(&tok.text) else {
                out.push(tok);
                continue;
            };
            if disabled.contains(&tok.text) {
                out.push(PTok {
                    painted: true,
                    ..tok
                });
                continue;
            }
            if disabled.len() >= limits::MAX_MACRO_EXPANSION_DEPTH as usize {
                self.too_deep(&tok);
                break;
            }
            let Some(params) = &mac.params else {
                let Some(body) = self.instantiate(mac, &tok, tok.span, &[], depth) else {
                    break;
                };
                self.push_replacement(&mut stack, &mut disabled, &tok, body);
                continue;
            };
            // A function-like macro name not followed by `(` is an
            // ordinary identifier.
            if !next_is_lparen(&mut stack, &mut disabled) {
                out.push(tok);
                continue;
            }
            let Some((args, close)) = collect_args(&mut stack, &mut disabled) else {
                self.diags.push(
                    Diagnostic::error(
                        Code::PpMacro,
                        tok.span,
                        format!("unterminated argument list invoking macro `{}'", tok.text),
                    )
                    .with_note("the invocation needs a closing `)' before the next directive"),
                );
                break;
            };
            let span = tok.span.to(close);
            if !arity_ok(params.len(), &args) {
                self.diags
                    .push(wrong_arity(&tok.text, params.len(), args.len(), span, mac));
                continue;
            }
            if depth >= limits::MAX_MACRO_EXPANSION_DEPTH {
                self.too_deep(&tok);
                break;
            }
            let Some(body) = self.instantiate(mac, &tok, span, &args, depth) else {
                break;
            };
            self.push_replacement(&mut stack, &mut disabled, &tok, body);
        }
        out
    }

    /// The replacement list of `mac` invoked as `name` with `args` (raw):
    /// a parameter is replaced by its argument fully expanded, or as
    /// written when it is an operand of `##`; then each `a ## b` pastes the
    /// last token of its left operand and the first of its right one into
    /// one token (GLSL 1.30 §3.3: "macro expansion happens after token
    /// pasting and does not happen before"). An empty operand pastes as
    /// nothing (C++'s placemarker). Every token gets the invocation's
    /// `span`. `None` when the budget ran out (already reported).
    fn instantiate(
        &mut self,
        mac: &Macro,
        name: &PTok,
        span: Span,
        args: &[Vec<PTok>],
        depth: u32,
    ) -> Option<Vec<PTok>> {
        let body = &mac.body;
        let param = |t: &PpToken| match (&mac.params, &t.kind) {
            (Some(params), PpKind::Ident) => params.iter().position(|p| *p == t.text),
            _ => None,
        };
        let is_paste = |i: usize| body.get(i).is_some_and(|t| t.kind == PpKind::HashHash);
        // Arguments expanded on demand: one used only beside `##` is never
        // expanded.
        let mut expanded: Vec<Option<Vec<PTok>>> = vec![None; args.len()];
        let mut out: Vec<PTok> = Vec::with_capacity(body.len());
        // The space before the operand just substituted, when it was empty
        // (a placemarker): a following `##` then has nothing to paste to.
        let mut placemarker: Option<bool> = None;
        let mut i = 0;
        while i < body.len() {
            let bt = &body[i];
            let sb = if i == 0 {
                name.space_before
            } else {
                bt.space_before
            };
            let pasting = is_paste(i) && i + 1 < body.len() && (i > 0);
            let (operand_index, toks) = if pasting {
                (i + 1, &body[i + 1])
            } else {
                (i, bt)
            };
            // The operand's tokens, with the invocation's span.
            let mut operand: Vec<PTok> = match param(toks).and_then(|p| args.get(p).map(|a| (p, a)))
            {
                Some((p, raw)) => {
                    let beside_paste = pasting || is_paste(operand_index + 1);
                    let arg = if beside_paste {
                        raw.clone()
                    } else {
                        if expanded[p].is_none() {
                            let e = self.expand_at(raw.clone(), depth + 1);
                            if self.budget.exhausted {
                                return None;
                            }
                            expanded[p] = Some(e);
                        }
                        expanded[p].clone().unwrap_or_default()
                    };
                    arg.into_iter().map(|at| PTok { span, ..at }).collect()
                }
                None => vec![PTok {
                    kind: toks.kind.clone(),
                    text: toks.text.clone(),
                    span,
                    space_before: toks.space_before,
                    painted: false,
                }],
            };
            if !pasting {
                if let Some(first) = operand.first_mut() {
                    first.space_before = sb;
                }
                placemarker = operand.is_empty().then_some(sb);
                out.extend(operand);
                i += 1;
                continue;
            }
            i += 2;
            if let Some(psb) = placemarker {
                // Nothing on the left: the right operand stands alone.
                if let Some(first) = operand.first_mut() {
                    first.space_before = psb;
                }
                placemarker = operand.is_empty().then_some(psb);
                out.extend(operand);
                continue;
            }
            if operand.is_empty() {
                continue;
            }
            let right = operand.remove(0);
            let Some(left) = out.pop() else {
                out.push(right);
                out.extend(operand);
                continue;
            };
            let text = format!("{}{}", left.text, right.text);
            // Long pasted spellings are charged to the budget, so that
            // pasting through nested macros cannot grow text without bound.
            let cost = text.len() / 8;
            if cost > self.budget.remaining {
                self.out_of_budget(name);
                return None;
            }
            self.budget.remaining -= cost;
            match lex_one(&text) {
                Some((kind, text)) => out.push(PTok {
                    kind,
                    text,
                    span,
                    space_before: left.space_before,
                    painted: false,
                }),
                None => {
                    self.diags.push(
                        Diagnostic::error(
                            Code::PpMacro,
                            span,
                            format!(
                                "pasting `{}' and `{}' in macro `{}' does not give a valid token",
                                left.text, right.text, name.text
                            ),
                        )
                        .with_note(format!(
                            "`{text}' is not one token; `##' must produce a single token \
                             (GLSL 1.30 §3.3)"
                        ))
                        .with_label(mac.name_span, "macro defined here"),
                    );
                    // Keep both tokens, unpasted.
                    out.push(left);
                    out.push(right);
                }
            }
            out.extend(operand);
        }
        Some(out)
    }

    /// `__LINE__`, `__FILE__` and `__VERSION__` (§3.3).
    fn builtin(&self, tok: &PTok) -> Option<PTok> {
        let value = match tok.text.as_str() {
            "__LINE__" => u64::from(self.map.loc(tok.span.start).line),
            "__FILE__" => u64::from(self.map.loc(tok.span.start).source),
            "__VERSION__" => u64::from(self.version),
            _ => return None,
        };
        Some(PTok::number(value, tok.span, tok.space_before))
    }

    fn push_replacement(
        &mut self,
        stack: &mut Vec<Item>,
        disabled: &mut Disabled,
        name: &PTok,
        body: Vec<PTok>,
    ) {
        if body.len() > self.budget.remaining {
            self.out_of_budget(name);
            return;
        }
        self.budget.remaining -= body.len();
        stack.push(Item::End);
        stack.extend(body.into_iter().rev().map(Item::Tok));
        disabled.push(name.text.clone());
    }

    fn out_of_budget(&mut self, name: &PTok) {
        self.budget.exhausted = true;
        self.diags.push(
            Diagnostic::error(
                Code::PpMacro,
                name.span,
                format!(
                    "expanding macro `{}' produces too many tokens (the limit is {})",
                    name.text, self.budget.limit
                ),
            )
            .with_note("the macros probably expand exponentially; simplify them"),
        );
    }

    fn too_deep(&mut self, tok: &PTok) {
        self.budget.exhausted = true;
        self.diags.push(Diagnostic::error(
            Code::PpMacro,
            tok.span,
            format!(
                "macro expansion nests too deeply at `{}' (the limit is {} levels)",
                tok.text,
                limits::MAX_MACRO_EXPANSION_DEPTH
            ),
        ));
    }
}

/// Moves the operand of `defined` (`X` or `( X )`) to the output unexpanded.
fn pass_defined_operand(stack: &mut Vec<Item>, disabled: &mut Disabled, out: &mut Vec<PTok>) {
    let paren = next_is_lparen(stack, disabled);
    let count = if paren { 2 } else { 1 };
    for _ in 0..count {
        while let Some(Item::End) = stack.last() {
            stack.pop();
            disabled.pop();
        }
        match stack.last() {
            Some(Item::Tok(t)) if t.kind == PpKind::Ident || t.is_punct(Punct::LeftParen) => {}
            _ => return,
        }
        if let Some(Item::Tok(mut t)) = stack.pop() {
            t.painted = true;
            out.push(t);
        }
    }
}

/// Whether the next token is `(`, ending the replacements that stand before
/// it (GCC-like: an invocation may take its `(` from after a replacement).
fn next_is_lparen(stack: &mut Vec<Item>, disabled: &mut Disabled) -> bool {
    loop {
        match stack.last() {
            Some(Item::End) => {
                stack.pop();
                disabled.pop();
            }
            Some(Item::Tok(t)) => return t.is_punct(Punct::LeftParen),
            None => return false,
        }
    }
}

/// Pops `( args )` from the stack: the arguments split at top-level commas,
/// and the span of the `)`. `None` when the input ends first.
fn collect_args(stack: &mut Vec<Item>, disabled: &mut Disabled) -> Option<(Vec<Vec<PTok>>, Span)> {
    stack.pop(); // the `(`
    let mut args = vec![Vec::new()];
    let mut depth = 1usize;
    while let Some(item) = stack.pop() {
        let mut t = match item {
            Item::End => {
                disabled.pop();
                continue;
            }
            Item::Tok(t) => t,
        };
        if t.is_punct(Punct::LeftParen) {
            depth += 1;
        } else if t.is_punct(Punct::RightParen) {
            depth -= 1;
            if depth == 0 {
                return Some((args, t.span));
            }
        } else if depth == 1 && t.is_punct(Punct::Comma) {
            args.push(Vec::new());
            continue;
        }
        if t.kind == PpKind::Ident && disabled.contains(&t.text) {
            t.painted = true;
        }
        if let Some(last) = args.last_mut() {
            last.push(t);
        }
    }
    None
}

fn arity_ok(params: usize, args: &[Vec<PTok>]) -> bool {
    if params == 0 {
        args.len() == 1 && args[0].is_empty()
    } else {
        args.len() == params
    }
}

fn wrong_arity(name: &str, params: usize, given: usize, span: Span, mac: &Macro) -> Diagnostic {
    let given = if params == 0 { given.max(1) } else { given };
    let plural = |n: usize| if n == 1 { "" } else { "s" };
    Diagnostic::error(
        Code::PpMacro,
        span,
        format!(
            "macro `{name}' takes {params} argument{}, but {given} {} given",
            plural(params),
            if given == 1 { "was" } else { "were" }
        ),
    )
    .with_label(mac.name_span, "macro defined here")
}

/// The one preprocessing token spelled `text`, if it is one.
fn lex_one(text: &str) -> Option<(PpKind, SmolStr)> {
    let (toks, diags) = lex::lex(text, LexOptions::default());
    match toks.as_slice() {
        [t] if diags.is_empty() && t.text.len() == text.len() && t.kind != PpKind::Newline => {
            Some((t.kind.clone(), t.text.clone()))
        }
        _ => None,
    }
}
