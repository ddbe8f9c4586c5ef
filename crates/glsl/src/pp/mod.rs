//! The GLSL preprocessor (GLSL 1.20 §3.3; GLSL 1.30 adds `##`).
//!
//! [`preprocess`] lexes the shader's text ([`crate::lex`]), runs the
//! directives line by line, expands macros in the remaining text and turns
//! the result into parser [`Token`]s, ending with one `Eof`.
//!
//! Choices where the specs leave room (each follows piglit and Mesa):
//! - Line continuation (`\` before a newline) is accepted in every version,
//!   although §3.1 says there is none: piglit's 1.10 tests use it in
//!   `#define`s. It is removed before comments and tokens are recognized,
//!   so a token or a comment's end may span it (GLSL 4.20 §3.1,
//!   GL_ARB_shading_language_420pack).
//! - `#line N` makes the *next* line number N+1 (§3.3 of both specs; GLSL
//!   3.30 later changed this to N).
//! - An identifier left in an `#if` expression after macro expansion is 0
//!   with a warning (C behavior; §3.3 restricts operands to literals).
//! - Macro names containing `__` draw a warning ("reserved", but allowed,
//!   as piglit expects); names starting with `GL_`, `defined` and the
//!   built-in macros cannot be defined or undefined.
//! - The `#` operator never exists (GLSL has no strings): a `#` in a
//!   macro body is an error. The `##` operator exists from GLSL 1.30 on
//!   (its §3.3; 1.10 and 1.20 say "There are no number sign based
//!   operators"), as C++'s: operands are pasted before they are expanded,
//!   the result must be one token and is rescanned, an empty argument
//!   pastes as nothing; `##` may not begin or end a replacement list.
//! - Integer literals that do not fit 32 bits draw a warning and wrap.

mod directives;
mod expr;
mod literal;
mod macros;
#[cfg(test)]
mod tests;

use crate::diag::{Code, Diagnostic};
use crate::ir::{ExtensionBehavior, Stage};
use crate::lang::{Extension, ExtensionSet, Feature, Language, Profile, Version};
use crate::lex::{self, LexOptions, PpKind, PpToken};
use crate::limits;
use crate::source::{SourceMap, Span};
use crate::token::{classify, Punct, Token, TokenKind, WordClass};
use literal::{parse_number, Literal};
use macros::{Budget, Expander, MacroTable, PTok};

pub struct PpOptions {
    pub stage: Stage,
    /// The version of a shader without `#version` (GLSL says 1.10;
    /// `shaderbox check --glsl-version` can choose another).
    pub default_version: Version,
    /// Whether the context offers the compatibility profile (GL 2.1 and
    /// compatibility contexts do): it decides a 1.40 shader's profile and
    /// whether `#version 150 compatibility` is accepted.
    pub compatibility_context: bool,
    /// Extensions the context does not offer although the compiler knows
    /// them ([`crate::CompileOptions::withheld`]).
    pub withheld: ExtensionSet,
}

impl PpOptions {
    pub fn new(stage: Stage) -> PpOptions {
        PpOptions {
            stage,
            default_version: Version::V110,
            compatibility_context: true,
            withheld: ExtensionSet::EMPTY,
        }
    }
}

/// An `#extension name : behavior` directive.
#[derive(Clone, Debug, PartialEq)]
pub struct ExtensionDirective {
    pub name: String,
    pub behavior: ExtensionBehavior,
    pub span: Span,
}

pub struct PpOutput {
    /// Parser tokens, ending with one `Eof` token.
    pub tokens: Vec<Token>,
    /// The shader's language: `#version` (or the default), its profile,
    /// and the supported extensions enabled at the end of the text.
    pub language: Language,
    /// Every well-formed `#extension` directive in source order, supported
    /// or not (the name `all` included); unsupported ones were warned about.
    pub extensions: Vec<ExtensionDirective>,
    pub diagnostics: Vec<Diagnostic>,
    /// `#pragma STDGL invariant(all)` was seen (GLSL 1.20 §4.6.1).
    pub invariant_all: bool,
    /// The text has a `#version` directive (else the language's version
    /// is [`PpOptions::default_version`]).
    pub has_version: bool,
}

/// The extension that enables string literals and `debugPrintfEXT`.
pub const PRINTF_EXTENSION: &str = "GL_SHADERBOX_debug_printf";

/// Preprocesses the text of `map`, recording `#line` directives in it.
/// Never fails: problems are diagnostics, and the token list always ends
/// with `Eof`.
pub fn preprocess(map: &mut SourceMap, opts: &PpOptions) -> PpOutput {
    preprocess_with_limit(map, opts, limits::MAX_TOKENS)
}

/// [`preprocess`] with a different token limit (tests use small ones).
pub(crate) fn preprocess_with_limit(
    map: &mut SourceMap,
    opts: &PpOptions,
    max_tokens: usize,
) -> PpOutput {
    let lex_opts = LexOptions {
        line_continuation: true,
    };
    // The lexer borrows the text while the preprocessor records `#line`
    // directives in the map, so it reads its own copy. Tokens are consumed
    // as they are lexed: only a directive line is held whole.
    let text = map.text().to_string();
    let end = text.len() as u32;
    let mut lexer = lex::Lexer::new(&text, lex_opts);
    let mut pp = Preprocessor::new(map, opts.stage, max_tokens);
    pp.compatibility_context = opts.compatibility_context;
    pp.withhold(opts.withheld);
    pp.set_language(Language::new(
        opts.default_version,
        opts.compatibility_context,
    ));
    // A directive line is gathered whole; text goes to the preprocessor
    // token by token.
    let mut directive: Option<Vec<PpToken>> = None;
    let mut line_start = true;
    for t in lexer.by_ref() {
        if t.kind == PpKind::Newline {
            if let Some(toks) = directive.take() {
                pp.line(Line {
                    toks,
                    end: t.span.start,
                });
            }
            line_start = true;
            continue;
        }
        match &mut directive {
            Some(toks) => toks.push(t),
            None if line_start && t.kind == PpKind::Hash => directive = Some(vec![t]),
            None => pp.text(t),
        }
        line_start = false;
    }
    if let Some(toks) = directive {
        pp.line(Line { toks, end });
    }
    // The lexer's problems come first, as they did when the text was
    // lexed whole before preprocessing.
    let mut diags = lexer.into_diagnostics();
    diags.append(&mut pp.diags);
    pp.diags = diags;
    pp.finish(end)
}

/// One logical line: its tokens (without the newline) and the offset of the
/// newline that ends it (or of the end of the text).
pub(crate) struct Line {
    pub toks: Vec<PpToken>,
    pub end: u32,
}

/// Pending text tokens at which they are expanded before the next
/// directive (see `Preprocessor::text`).
const FLUSH_TOKENS: usize = 4096;

/// One level of `#if` nesting.
#[derive(Clone, Debug)]
pub(crate) struct Cond {
    /// The `#if`/`#ifdef`/`#ifndef` that opened it.
    pub span: Span,
    /// The enclosing region is being compiled.
    pub parent_active: bool,
    /// The current branch is being compiled.
    pub active: bool,
    /// Some branch has been taken (later `#elif`/`#else` are skipped).
    pub taken: bool,
    /// `#else` seen (span), after which only `#endif` may follow.
    pub else_seen: Option<Span>,
}

/// Tracks braces in the output to know whether a function body is open
/// (`#pragma optimize`/`debug` are allowed only outside them, §3.3).
#[derive(Debug, Default)]
struct Braces {
    depth: u32,
    in_function: bool,
    prev_rparen: bool,
}

impl Braces {
    fn update(&mut self, kind: &TokenKind) {
        match kind {
            TokenKind::Punct(Punct::LeftBrace) => {
                if self.depth == 0 {
                    self.in_function = self.prev_rparen;
                }
                self.depth = self.depth.saturating_add(1);
            }
            TokenKind::Punct(Punct::RightBrace) => {
                self.depth = self.depth.saturating_sub(1);
                if self.depth == 0 {
                    self.in_function = false;
                }
            }
            _ => {}
        }
        self.prev_rparen = *kind == TokenKind::Punct(Punct::RightParen);
    }
}

pub(crate) struct Preprocessor<'m> {
    map: &'m mut SourceMap,
    #[allow(dead_code)]
    stage: Stage,
    lang: Language,
    compatibility_context: bool,
    /// Extensions the context does not offer: no macro, and `#extension`
    /// treats them as unknown.
    withheld: ExtensionSet,
    /// The first `#version` directive.
    version_span: Option<Span>,
    /// Something other than comments and whitespace has been seen.
    seen_content: bool,
    macros: MacroTable,
    /// How many of `macros` are function-like.
    function_like: usize,
    conds: Vec<Cond>,
    /// Text tokens waiting for macro expansion (flushed at each directive).
    pending: Vec<PTok>,
    out: Vec<Token>,
    braces: Braces,
    extensions: Vec<ExtensionDirective>,
    diags: Vec<Diagnostic>,
    budget: Budget,
    max_tokens: usize,
    /// The output token limit was hit (reported once).
    overflowed: bool,
    /// `#pragma STDGL invariant(all)` seen.
    invariant_all: bool,
}

impl<'m> Preprocessor<'m> {
    fn new(map: &'m mut SourceMap, stage: Stage, max_tokens: usize) -> Self {
        let mut macros = MacroTable::new();
        // GL_ARB_compatibility's macro depends on the context: set_language.
        // Those offered from a later version only: set_language.
        for ext in Extension::ALL
            .iter()
            .filter(|&&e| e != Extension::ArbCompatibility && e.since() == Version::V110)
        {
            macros.insert(ext.name().into(), macros::Macro::one());
        }
        Preprocessor {
            map,
            stage,
            lang: Language::new(Version::V110, true),
            compatibility_context: true,
            withheld: ExtensionSet::EMPTY,
            version_span: None,
            seen_content: false,
            macros,
            function_like: 0,
            conds: Vec::new(),
            pending: Vec::new(),
            out: Vec::new(),
            braces: Braces::default(),
            extensions: Vec::new(),
            diags: Vec::new(),
            budget: Budget::new(max_tokens),
            max_tokens,
            overflowed: false,
            invariant_all: false,
        }
    }

    /// Withholds `set`'s extensions (their macros go now).
    fn withhold(&mut self, set: ExtensionSet) {
        self.withheld = set;
        for e in Extension::ALL.iter().filter(|&&e| set.contains(e)) {
            self.macros.remove(e.name());
        }
    }

    /// Sets the shader's language and the macros that follow from it:
    /// `GL_FRAGMENT_PRECISION_HIGH` (1.30 §4.5.4, both stages),
    /// `GL_core_profile` (1.50 §3.3, every 1.50+ shader) and
    /// `GL_compatibility_profile` (1.50+ compatibility-profile shaders),
    /// and `GL_ARB_compatibility` in a context that has that profile.
    fn set_language(&mut self, lang: Language) {
        self.lang = lang;
        let v = lang.version;
        for (name, on) in [
            ("GL_FRAGMENT_PRECISION_HIGH", v >= Version::V130),
            ("GL_core_profile", v.has_profiles()),
            (
                "GL_compatibility_profile",
                v.has_profiles() && lang.profile == Profile::Compatibility,
            ),
            ("GL_ARB_compatibility", self.compatibility_context),
        ]
        .into_iter()
        .chain(
            Extension::ALL
                .iter()
                .filter(|e| e.since() > Version::V110)
                .map(|e| (e.name(), v >= e.since() && !self.withheld.contains(*e))),
        ) {
            if on {
                self.macros.insert(name.into(), macros::Macro::one());
            } else {
                self.macros.remove(name);
            }
        }
    }

    /// Whether text here is compiled (not in a skipped conditional branch).
    fn active(&self) -> bool {
        self.conds.last().is_none_or(|c| c.active)
    }

    /// A directive line (its first token is `#`).
    fn line(&mut self, line: Line) {
        if line.toks.is_empty() {
            return;
        }
        self.flush();
        self.directive(&line);
        self.seen_content = true;
    }

    /// One token of a text line. A long text is expanded as it goes rather
    /// than at the next directive, so memory does not grow with it; only
    /// while no function-like macro is defined, since an invocation's
    /// arguments may run on past any point (object-like expansion does not
    /// depend on where the text is cut).
    fn text(&mut self, t: PpToken) {
        if self.active() {
            self.pending.push(PTok::from(t));
            if self.pending.len() >= FLUSH_TOKENS && self.function_like == 0 {
                self.flush();
            }
        }
        self.seen_content = true;
    }

    /// An expander over the current macro table.
    fn expander(&mut self, in_condition: bool) -> Expander<'_> {
        Expander {
            in_condition,
            macros: &self.macros,
            map: &*self.map,
            version: self.lang.version.number(),
            diags: &mut self.diags,
            budget: &mut self.budget,
        }
    }

    /// Expands the pending text and converts it to parser tokens.
    fn flush(&mut self) {
        if self.pending.is_empty() {
            return;
        }
        let pending = std::mem::take(&mut self.pending);
        let expanded = self.expander(false).expand(pending);
        if self.budget.exhausted {
            // Already reported; the output would only be truncated garbage.
            return;
        }
        for t in expanded {
            self.emit(t);
        }
    }

    fn emit(&mut self, t: PTok) {
        let Some(kind) = self.convert(&t) else {
            return;
        };
        if self.out.len() >= self.max_tokens {
            if !self.overflowed {
                self.overflowed = true;
                self.diags.push(Diagnostic::error(
                    Code::PpMacro,
                    t.span,
                    format!(
                        "the shader has too many tokens after preprocessing (the limit is {})",
                        self.max_tokens
                    ),
                ));
            }
            return;
        }
        self.braces.update(&kind);
        self.out.push(Token { kind, span: t.span });
    }

    /// Whether the `#extension` directives so far leave the printf
    /// extension enabled.
    fn printf_enabled(&self) -> bool {
        self.lang.has(Extension::ShaderboxDebugPrintf)
    }

    /// A preprocessing token to a parser token kind (`None` after an error).
    fn convert(&mut self, t: &PTok) -> Option<TokenKind> {
        match &t.kind {
            PpKind::Ident => Some(match classify(&t.text, self.lang) {
                WordClass::Keyword(k) => TokenKind::Keyword(k),
                WordClass::Reserved => TokenKind::Reserved(t.text.clone()),
                WordClass::Identifier => TokenKind::Identifier(t.text.clone()),
            }),
            PpKind::Number => self.convert_number(t),
            PpKind::Str if self.printf_enabled() => {
                let inner = t.text.get(1..t.text.len().saturating_sub(1)).unwrap_or("");
                Some(TokenKind::StringLiteral(inner.into()))
            }
            PpKind::Str => {
                self.diags.push(
                    Diagnostic::error(Code::LexInvalidChar, t.span, "GLSL has no string literals")
                        .with_note(format!(
                            "for debugPrintfEXT, enable shaderbox's debug extension first: \
                             `#extension {PRINTF_EXTENSION} : enable'"
                        )),
                );
                None
            }
            PpKind::Punct(p) => Some(TokenKind::Punct(*p)),
            PpKind::Hash | PpKind::HashHash => {
                self.diags.push(
                    Diagnostic::error(
                        Code::PpSyntax,
                        t.span,
                        format!("unexpected `{}' outside a preprocessor directive", t.text),
                    )
                    .with_note(
                        "a directive's `#' must be the first thing on its line, and `##' is an \
                         operator only in a macro's replacement list (GLSL 1.30 and later)",
                    ),
                );
                None
            }
            PpKind::Other(c) => {
                // A run of invalid characters (binary garbage, a pasted
                // string) is one error, not one per byte.
                if let Some(last) = self.diags.last_mut() {
                    if last.code == Code::LexInvalidChar
                        && last.span.is_some_and(|s| s.end == t.span.start)
                    {
                        if let Some(s) = &mut last.span {
                            s.end = t.span.end;
                        }
                        if !last.message.starts_with("invalid characters") {
                            last.message = last.message.replacen(
                                "invalid character",
                                "invalid characters, from",
                                1,
                            );
                        }
                        return None;
                    }
                }
                let mut d = Diagnostic::error(
                    Code::LexInvalidChar,
                    t.span,
                    format!("invalid character `{c}'"),
                );
                if *c == '"' || *c == '\'' {
                    d = d.with_note("GLSL has no string or character literals");
                }
                self.diags.push(d);
                None
            }
            PpKind::Newline => None,
        }
    }

    fn convert_number(&mut self, t: &PTok) -> Option<TokenKind> {
        match parse_number(&t.text) {
            Ok(Literal::Int {
                value,
                fits_u64,
                unsigned,
            }) => {
                if unsigned {
                    if let Err(why) = self.lang.gate(Feature::Unsigned) {
                        self.diags.push(
                            Diagnostic::error(
                                Code::LexBadNumber,
                                t.span,
                                format!(
                                    "invalid integer literal `{}': {}",
                                    t.text,
                                    why.message("the `u' suffix", self.lang)
                                ),
                            )
                            .with_note(why.fix()),
                        );
                        return None;
                    }
                }
                let too_large = !fits_u64 || value > u64::from(u32::MAX);
                if too_large && self.lang.allows(Feature::Unsigned) {
                    // GLSL 1.30 §4.1.3: an error from 1.30 on; 1.10/1.20
                    // say nothing, so there it stays a warning.
                    self.diags.push(
                        Diagnostic::error(
                            Code::LexBadNumber,
                            t.span,
                            format!("integer literal `{}' does not fit in 32 bits", t.text),
                        )
                        .with_note(
                            "an integer literal must fit its type: 32 bits for int (as a bit \
                             pattern, up to 0xffffffff) and uint (GLSL 1.30 §4.1.3)",
                        ),
                    );
                    return None;
                }
                if too_large {
                    self.diags.push(Diagnostic::warning(
                        Code::LexBadNumber,
                        t.span,
                        format!(
                            "integer literal `{}' does not fit in 32 bits; it is truncated to {}",
                            t.text, value as u32 as i32
                        ),
                    ));
                }
                Some(if unsigned {
                    TokenKind::UintLiteral(value as u32)
                } else {
                    TokenKind::IntLiteral(value as u32)
                })
            }
            Ok(Literal::Float { value, suffix }) => {
                if suffix && !self.lang.allows(Feature::FloatSuffix) {
                    self.diags.push(
                        Diagnostic::error(
                            Code::LexBadNumber,
                            t.span,
                            format!(
                                "floating-point suffix in `{}' is not allowed in GLSL 1.10",
                                t.text
                            ),
                        )
                        .with_note("the `f'/`F' suffix needs `#version 120' (GLSL 1.20 §4.1.4)"),
                    );
                    return None;
                }
                if value.is_infinite() {
                    self.diags.push(Diagnostic::warning(
                        Code::LexBadNumber,
                        t.span,
                        format!(
                            "floating-point literal `{}' is too large; it becomes infinity",
                            t.text
                        ),
                    ));
                }
                Some(TokenKind::FloatLiteral(value))
            }
            Err(msg) => {
                self.diags
                    .push(Diagnostic::error(Code::LexBadNumber, t.span, msg));
                None
            }
        }
    }

    fn finish(mut self, end: u32) -> PpOutput {
        self.flush();
        self.check_core_version();
        for c in std::mem::take(&mut self.conds).iter().rev() {
            self.diags.push(
                Diagnostic::error(
                    Code::PpConditional,
                    c.span,
                    "unterminated conditional directive",
                )
                .with_note("add a matching `#endif'"),
            );
        }
        self.out.push(Token {
            kind: TokenKind::Eof,
            span: Span::new(end, end),
        });
        PpOutput {
            tokens: self.out,
            language: self.lang,
            extensions: self.extensions,
            diagnostics: self.diags,
            invariant_all: self.invariant_all,
            has_version: self.version_span.is_some(),
        }
    }
}
