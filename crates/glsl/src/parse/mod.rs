//! The parser: preprocessed tokens to the syntax tree of [`crate::ast`].
//!
//! Recursive descent over the grammar of GLSL 1.10/1.20 §9, with precedence
//! climbing for the binary operators. The parser records what was written and
//! leaves meaning to semantic analysis; it only reports what the grammar of
//! the shader's version cannot parse:
//! - syntax errors, as "expected X, found Y" at the offending token;
//! - reserved words (§3.6), wherever they appear.
//!
//! The grammar is the union of 1.10 and 1.20: GLSL 1.20 syntax in a 1.10
//! shader (array types `float[3]`, array constructors and initializers,
//! method calls such as `a.length()`) is parsed, and analysis reports it
//! with the version. The one version-dependent rule here is the operand
//! after `:` in `?:` (1.10: conditional, 1.20: assignment expression).
//!
//! ## Error recovery
//! A syntax error unwinds (as `Reported`) to the enclosing statement, struct
//! member or external declaration, which skips to the end of the bad
//! construct (`Parser::recover`) and parsing continues, so independent
//! errors are all reported. After one error, further errors are suppressed
//! until the next statement starts, so one mistake gives one message. A
//! missing operand becomes `ExprKind::Error` so the surrounding statement
//! survives. Nesting deeper than [`limits::MAX_NESTING_DEPTH`] stops the
//! parse with one error instead of exhausting the stack.
//!
//! ## Type names
//! Whether an identifier names a struct type decides between declarations
//! and expressions (`S x;` vs `S(1.0);` vs `S = 1;`), so the parser tracks
//! struct declarations with their lexical scopes (`scope::Scopes`).

mod decl;
mod expr;
mod scope;
mod stmt;
#[cfg(test)]
mod tests;

use crate::ast::{ExternalDecl, TranslationUnit};
use crate::diag::{Code, Diagnostic};
use crate::lang::Language;
use crate::limits;
use crate::source::Span;
use crate::token::{Keyword, Punct, Token, TokenKind};
use scope::Scopes;

/// Parses a whole shader. `tokens` normally ends with [`TokenKind::Eof`];
/// one is assumed if it is missing, and nothing after the first `Eof` is read.
/// Never panics; every problem is in the returned diagnostics.
pub fn parse(tokens: &[Token], lang: Language) -> (TranslationUnit, Vec<Diagnostic>) {
    let owned: Vec<Token>;
    let toks = if matches!(tokens.last(), Some(t) if t.kind == TokenKind::Eof) {
        tokens
    } else {
        let end = tokens.last().map_or(0, |t| t.span.end);
        let mut v = tokens.to_vec();
        v.push(Token {
            kind: TokenKind::Eof,
            span: Span::new(end, end),
        });
        owned = v;
        &owned
    };
    let mut p = Parser::new(toks, lang);
    let tu = p.translation_unit();
    (tu, p.diags)
}

/// Marks that a syntax error has been reported and the caller must skip to
/// a synchronization point.
#[derive(Debug)]
pub(super) struct Reported;

pub(super) type PResult<T> = Result<T, Reported>;

pub(super) struct Parser<'t> {
    /// Never empty; the last token is `Eof`.
    toks: &'t [Token],
    pos: usize,
    lang: Language,
    diags: Vec<Diagnostic>,
    scopes: Scopes,
    depth: u32,
    /// An error was reported in the current statement: further errors are
    /// suppressed until the next statement starts.
    recovering: bool,
    /// The nesting limit was hit: parsing stopped and nothing more is
    /// reported.
    aborted: bool,
    /// End offset of the last token consumed.
    prev_end: u32,
    /// The closing brace of the function defined just before, if the last
    /// external declaration was a function definition.
    last_function_end: Option<crate::source::Span>,
}

impl<'t> Parser<'t> {
    fn new(toks: &'t [Token], lang: Language) -> Parser<'t> {
        Parser {
            toks,
            pos: 0,
            lang,
            diags: Vec::new(),
            scopes: Scopes::new(),
            depth: 0,
            recovering: false,
            aborted: false,
            prev_end: toks.first().map_or(0, |t| t.span.start),
            last_function_end: None,
        }
    }

    // ---- Token access -------------------------------------------------

    /// The token `n` places ahead (the final `Eof` beyond the end).
    fn nth(&self, n: usize) -> &'t Token {
        let last = self.toks.len() - 1;
        let i = self.pos.saturating_add(n).min(last);
        // The slice always ends with Eof, so the index is in range.
        &self.toks[i]
    }

    fn tok(&self) -> &'t Token {
        self.nth(0)
    }

    fn kind(&self) -> &'t TokenKind {
        &self.tok().kind
    }

    fn span(&self) -> Span {
        self.tok().span
    }

    fn at_eof(&self) -> bool {
        matches!(self.kind(), TokenKind::Eof)
    }

    fn at_punct(&self, p: Punct) -> bool {
        matches!(self.kind(), TokenKind::Punct(q) if *q == p)
    }

    fn at_keyword(&self, k: Keyword) -> bool {
        matches!(self.kind(), TokenKind::Keyword(q) if *q == k)
    }

    fn nth_is_punct(&self, n: usize, p: Punct) -> bool {
        matches!(&self.nth(n).kind, TokenKind::Punct(q) if *q == p)
    }

    /// Consumes the current token (never moves past `Eof`).
    fn bump(&mut self) -> &'t Token {
        let t = self.tok();
        if t.kind != TokenKind::Eof {
            self.pos += 1;
            self.prev_end = t.span.end;
        }
        t
    }

    fn eat_punct(&mut self, p: Punct) -> bool {
        if self.at_punct(p) {
            self.bump();
            true
        } else {
            false
        }
    }

    fn expect_punct(&mut self, p: Punct) -> PResult<Span> {
        if self.at_punct(p) {
            Ok(self.bump().span)
        } else {
            Err(self.unexpected(&format!("`{}'", p.as_str())))
        }
    }

    /// Expects the `)` or `]` closing a group inside an expression. When the
    /// statement ends first (`;`, `}` or end of input), the closing token is
    /// taken as forgotten: the error is reported and the expression kept, so
    /// a declaration such as `vec4 c = vec4(1.0;` still declares `c`.
    fn expect_close(&mut self, p: Punct) -> PResult<()> {
        if self.eat_punct(p) {
            return Ok(());
        }
        let err = self.unexpected(&format!("`{}'", p.as_str()));
        match self.kind() {
            TokenKind::Eof | TokenKind::Punct(Punct::Semicolon | Punct::RightBrace) => Ok(()),
            _ => Err(err),
        }
    }

    /// Expects the `;` ending a statement or declaration. When it is missing
    /// but the next token clearly starts something new (a keyword such as
    /// `float` or `return`, `else`, or `}`), the `;` is taken as forgotten
    /// and parsing goes on from there, which keeps the rest of the
    /// statement's work (the declared names) without a cascade.
    fn expect_semicolon(&mut self) -> PResult<()> {
        if self.eat_punct(Punct::Semicolon) {
            return Ok(());
        }
        let err = self.unexpected("`;'");
        let resumable = match self.kind() {
            TokenKind::Punct(Punct::RightBrace) => true,
            TokenKind::Keyword(k) => !matches!(k, Keyword::True | Keyword::False),
            _ => false,
        };
        if resumable {
            Ok(())
        } else {
            Err(err)
        }
    }

    /// The span from `start` to the end of the last consumed token.
    fn span_from(&self, start: Span) -> Span {
        Span::new(start.start, self.prev_end.max(start.start))
    }

    // ---- Diagnostics ----------------------------------------------------

    /// Records an error unless one was already reported for this statement.
    fn report(&mut self, d: Diagnostic) {
        if !self.recovering && !self.aborted {
            self.diags.push(d);
        }
        self.recovering = true;
    }

    /// Reports "expected X, found Y" at the current token (or the reserved
    /// word error if the current token is a reserved word).
    fn unexpected(&mut self, expected: &str) -> Reported {
        if let TokenKind::Reserved(_) = self.kind() {
            return self.reserved_word();
        }
        let found = self.kind().describe();
        let mut d = Diagnostic::error(
            Code::Syntax,
            self.span(),
            format!("expected {expected}, found {found}"),
        );
        if let TokenKind::Identifier(name) = self.kind() {
            if expected == "type" {
                d = d.with_note(
                    type_name_hint(name, self.lang)
                        .unwrap_or_else(|| format!("`{name}' is not the name of a type here")),
                );
            }
        }
        self.report(d);
        Reported
    }

    /// [`Self::unexpected`] with a note explaining what was wrong.
    fn unexpected_with_note(&mut self, expected: &str, note: &str) -> Reported {
        let before = self.diags.len();
        let r = self.unexpected(expected);
        if self.diags.len() > before {
            if let Some(d) = self.diags.last_mut() {
                d.notes.push(note.to_string());
            }
        }
        r
    }

    /// Reports the current token, a reserved word (GLSL 1.20 §3.6).
    fn reserved_word(&mut self) -> Reported {
        let word = match self.kind() {
            TokenKind::Reserved(w) => w.clone(),
            other => smol_str::SmolStr::new(other.describe()),
        };
        let d = Diagnostic::error(
            Code::ReservedWord,
            self.span(),
            format!(
                "`{word}' is reserved in GLSL {}",
                self.lang.version.dotted()
            ),
        )
        .with_note(reserved_note(&word));
        self.report(d);
        Reported
    }

    // ---- Nesting limit --------------------------------------------------

    /// Enters one nesting level; every successful `enter` is paired with a
    /// [`Self::leave`]. Past [`limits::MAX_NESTING_DEPTH`] reports "nesting
    /// too deep" once and abandons the rest of the input.
    ///
    /// The recursive paths (statement, assignment, unary) call this
    /// directly rather than through a closure, and keep their frames small,
    /// so that the maximum depth fits a 2 MiB thread stack even in an
    /// unoptimized build.
    fn enter(&mut self) -> PResult<()> {
        if self.aborted {
            return Err(Reported);
        }
        if self.depth >= limits::MAX_NESTING_DEPTH {
            let d = Diagnostic::error(Code::Syntax, self.span(), "nesting too deep").with_note(
                format!(
                    "parentheses, blocks and operators may nest at most {} levels",
                    limits::MAX_NESTING_DEPTH
                ),
            );
            self.diags.push(d);
            self.aborted = true;
            self.recovering = true;
            self.pos = self.toks.len() - 1;
            return Err(Reported);
        }
        self.depth += 1;
        #[cfg(test)]
        tests::note_stack_depth();
        Ok(())
    }

    fn leave(&mut self) {
        self.depth = self.depth.saturating_sub(1);
    }

    /// Runs `f` in a new scope for type names.
    fn scoped<T>(&mut self, f: impl FnOnce(&mut Self) -> T) -> T {
        self.scopes.push();
        let r = f(self);
        self.scopes.pop();
        r
    }

    // ---- Recovery ---------------------------------------------------------

    /// Skips the rest of a construct that failed to parse: up to and
    /// including the next `;` or balanced `{ ... }` at its level, or up to
    /// (not including) a `}` that closes an enclosing block. `start` is
    /// where the construct began; in a `for` header the parentheses opened
    /// since then count, so the header's own `;`s do not end the skip.
    fn recover(&mut self, start: usize) {
        let mut parens: u32 = 0;
        if matches!(self.toks.get(start), Some(t) if t.kind == TokenKind::Keyword(Keyword::For)) {
            for t in self.toks.get(start..self.pos).unwrap_or(&[]) {
                match t.kind {
                    TokenKind::Punct(Punct::LeftParen) => parens += 1,
                    TokenKind::Punct(Punct::RightParen) => parens = parens.saturating_sub(1),
                    _ => {}
                }
            }
        }
        let mut braces: u32 = 0;
        loop {
            match self.kind() {
                TokenKind::Eof => return,
                TokenKind::Punct(Punct::LeftParen | Punct::LeftBracket) => parens += 1,
                TokenKind::Punct(Punct::RightParen | Punct::RightBracket) => {
                    parens = parens.saturating_sub(1)
                }
                TokenKind::Punct(Punct::LeftBrace) => braces += 1,
                TokenKind::Punct(Punct::RightBrace) => {
                    if braces == 0 {
                        return;
                    }
                    braces -= 1;
                    if braces == 0 && parens == 0 {
                        self.bump();
                        return;
                    }
                }
                TokenKind::Punct(Punct::Semicolon) if braces == 0 && parens == 0 => {
                    self.bump();
                    return;
                }
                _ => {}
            }
            self.bump();
        }
    }

    // ---- Translation unit -------------------------------------------------

    /// `translation_unit`. A run of tokens that cannot start a declaration
    /// (statements outside any function, say) is reported once, at its
    /// first token.
    fn translation_unit(&mut self) -> TranslationUnit {
        let mut items = Vec::new();
        let mut in_junk = false;
        while !self.at_eof() && !self.aborted {
            let start = self.pos;
            let junk = !self.at_declaration_keyword_or_type();
            if !(junk && in_junk) {
                self.recovering = false;
            }
            in_junk = junk;
            match self.external_declaration() {
                Ok(item) => items.push(item),
                Err(Reported) => self.recover(start),
            }
            if self.pos == start {
                // A stray `}` (recover stops before it): skip it.
                self.bump();
            }
        }
        // The grammar's translation_unit (GLSL 1.10 §9 and every later
        // version) is one or more external declarations: a shader that
        // preprocesses to nothing is a syntax error (Mesa says so too).
        if items.is_empty() && self.diags.is_empty() {
            let d = Diagnostic::error(
                Code::Syntax,
                self.span(),
                "the shader is empty: it declares nothing",
            )
            .with_note(
                "the grammar's translation_unit needs at least one external declaration; \
                 a shader stage needs `void main()'",
            );
            self.diags.push(d);
        }
        TranslationUnit { items }
    }

    fn external_declaration(&mut self) -> PResult<ExternalDecl> {
        if self.at_punct(Punct::Semicolon) {
            // §9 has no empty declaration at global scope.
            return Err(self.unexpected_with_note("declaration", "remove the extra `;'"));
        }
        if !self.at_declaration_keyword_or_type() {
            let after_function = self.last_function_end;
            let before = self.diags.len();
            let r = self.unexpected("declaration");
            if let (Some(end), Some(d)) = (after_function, self.diags.get_mut(before)) {
                // Statements right after a function body: most often an
                // extra `}' closed the function early.
                d.labels.push(crate::diag::Label {
                    span: end,
                    message: "the function body ends here".into(),
                });
                d.notes.push(
                    "statements must be inside a function body; check the braces before this \
                     line: an extra `}' may have closed the function too early"
                        .into(),
                );
            }
            return Err(r);
        }
        let item = self.declaration(true)?;
        if let ExternalDecl::FunctionDef(f) = &item {
            self.last_function_end = Some(crate::source::Span::new(
                f.span.end.saturating_sub(1),
                f.span.end,
            ));
        }
        Ok(item)
    }
}

/// The note for a reserved word: what it would need, or what to do.
fn reserved_note(word: &str) -> String {
    match word {
        "switch" | "default" => "`switch' statements require GLSL 1.30".into(),
        "unsigned" => "unsigned integers require GLSL 1.30".into(),
        "precision" | "lowp" | "mediump" | "highp" => {
            "precision qualifiers require GLSL 1.30 (or GLSL ES)".into()
        }
        "double" | "dvec2" | "dvec3" | "dvec4" => "double precision requires GLSL 4.00".into(),
        "sampler2DRect" | "sampler3DRect" | "sampler2DRectShadow" => {
            "rectangle textures require GLSL 1.40 or ARB_texture_rectangle".into()
        }
        _ => format!("`{word}' is reserved for future use; choose another name"),
    }
}

/// What a word that looks like a type name but is not one probably meant:
/// a vector or matrix without its size (`vec`, `mat`: slides write them as
/// shorthand for `vec3`/`mat4`), or a type in the wrong case (`Vec3`).
pub fn type_name_hint(word: &str, lang: Language) -> Option<String> {
    let lower = word.to_ascii_lowercase();
    let sized = |prefix: &str| -> Option<&'static str> {
        match prefix {
            "vec" => Some("`vec2', `vec3' or `vec4'"),
            "ivec" => Some("`ivec2', `ivec3' or `ivec4'"),
            "bvec" => Some("`bvec2', `bvec3' or `bvec4'"),
            "uvec" if lang.version >= crate::lang::Version::V130 => {
                Some("`uvec2', `uvec3' or `uvec4'")
            }
            "mat" => Some("`mat2', `mat3', `mat4' (or `matCxR' from GLSL 1.20)"),
            _ => None,
        }
    };
    if let Some(choices) = sized(&lower) {
        let case = if lower == word {
            String::new()
        } else {
            " (and type names are lower case)".to_string()
        };
        return Some(format!(
            "GLSL has no type `{word}': the size is part of the name, write {choices}{case}"
        ));
    }
    if lower != word {
        if let crate::token::WordClass::Keyword(k) = crate::token::classify(&lower, lang) {
            if decl::is_type_keyword(k) {
                return Some(format!("type names are lower case: write `{}'", k.as_str()));
            }
        }
    }
    None
}
