//! The raw lexer: source text to preprocessing tokens.
//!
//! Comments become whitespace, words and numbers are kept as text (the
//! preprocessor needs their spelling; keywords are classified only after
//! `#version` is known, see [`crate::token::classify`]). Newlines are tokens
//! because preprocessor directives end at them.

use crate::diag::{Code, Diagnostic};
use crate::source::Span;
use crate::token::Punct;
use smol_str::SmolStr;

#[derive(Clone, Debug, PartialEq)]
pub enum PpKind {
    /// A word: letters, digits and `_`, not starting with a digit.
    Ident,
    /// A preprocessing number: digits, letters, `.`, `_` and exponent signs.
    Number,
    Punct(Punct),
    /// `#`
    Hash,
    /// `##`
    HashHash,
    /// `"text"` on one line (the text keeps its quotes). Only
    /// `debugPrintfEXT` of the `GL_SHADERBOX_debug_printf` extension takes
    /// one; anywhere else the preprocessor reports it.
    Str,
    Newline,
    /// A character the language does not use (`@`, `$`, `"`, a non-ASCII
    /// letter...). The preprocessor may skip it in a skipped block; anywhere
    /// else it is an error.
    Other(char),
}

#[derive(Clone, Debug, PartialEq)]
pub struct PpToken {
    pub kind: PpKind,
    pub text: SmolStr,
    pub span: Span,
    /// Whitespace (or a comment) precedes the token on its line. Needed to
    /// tell `#define F(x)` (function-like) from `#define F (x)`.
    pub space_before: bool,
}

/// Options that depend on the language version.
#[derive(Clone, Copy, Debug, Default)]
pub struct LexOptions {
    /// Join a line ending in `\` with the next one.
    pub line_continuation: bool,
}

/// Splits `text` into preprocessing tokens. Never fails: problems are
/// reported in the returned diagnostics and lexing continues.
pub fn lex(text: &str, opts: LexOptions) -> (Vec<PpToken>, Vec<Diagnostic>) {
    let mut lexer = Lexer::new(text, opts);
    let toks = lexer.by_ref().collect();
    (toks, lexer.into_diagnostics())
}

/// The lexer as an iterator of tokens, so that a caller can consume a
/// line at a time and hold no more than that: memory stays proportional
/// to the longest line, not to the text. Its diagnostics are kept until
/// [`Lexer::into_diagnostics`].
pub struct Lexer<'a> {
    text: &'a str,
    i: usize,
    /// Whitespace (or a comment) since the last token on this line.
    space: bool,
    opts: LexOptions,
    diags: Vec<Diagnostic>,
}

impl<'a> Lexer<'a> {
    pub fn new(text: &'a str, opts: LexOptions) -> Lexer<'a> {
        Lexer {
            text,
            i: 0,
            space: false,
            opts,
            diags: Vec::new(),
        }
    }

    /// The problems found in the text consumed so far.
    pub fn into_diagnostics(self) -> Vec<Diagnostic> {
        self.diags
    }

    /// The token `start..self.i`, taking the pending whitespace flag.
    fn token(&mut self, kind: PpKind, text: SmolStr, start: usize) -> PpToken {
        let t = PpToken {
            kind,
            text,
            span: Span::new(start as u32, self.i as u32),
            space_before: self.space,
        };
        self.space = false;
        t
    }

    /// The spelling of `start..self.i`.
    fn spelling(&self, start: usize) -> SmolStr {
        SmolStr::new(&self.text[start..self.i])
    }
}

impl Iterator for Lexer<'_> {
    type Item = PpToken;

    fn next(&mut self) -> Option<PpToken> {
        let text = self.text;
        let bytes = text.as_bytes();
        while self.i < bytes.len() {
            let i = self.i;
            let c = bytes[i];
            // Line continuation.
            if self.opts.line_continuation {
                let n = continuation_len(bytes, i);
                if n > 0 {
                    self.i += n;
                    continue;
                }
            }
            match c {
                b' ' | b'\t' | b'\r' | 0x0b | 0x0c => {
                    self.space = true;
                    self.i += 1;
                }
                b'\n' => {
                    self.i += 1;
                    return Some(self.token(PpKind::Newline, SmolStr::new_static("\n"), i));
                }
                b'/' if bytes.get(i + 1) == Some(&b'/') => {
                    // Line comment, up to (not including) the newline.
                    // Continuations are removed before comments are
                    // recognized, so a `\` at the end continues the comment.
                    let mut j = i;
                    while j < bytes.len() && bytes[j] != b'\n' {
                        let n = if self.opts.line_continuation {
                            continuation_len(bytes, j)
                        } else {
                            0
                        };
                        j += n.max(1);
                    }
                    self.i = j;
                    self.space = true;
                }
                b'/' if bytes.get(i + 1) == Some(&b'*') => {
                    let mut j = i + 2;
                    let mut closed = false;
                    while j < bytes.len() {
                        // Continuations are removed first: `*\` at a
                        // line's end and `/` on the next close it.
                        let after = self.skip_continuations(bytes, j + 1);
                        if bytes[j] == b'*' && bytes.get(after) == Some(&b'/') {
                            j = after + 1;
                            closed = true;
                            break;
                        }
                        // Newlines inside a comment emit nothing: the span
                        // table numbers the lines.
                        j += 1;
                    }
                    if !closed {
                        self.diags.push(Diagnostic::error(
                            Code::PpUnterminated,
                            Span::new(i as u32, i as u32 + 2),
                            "unterminated comment",
                        ));
                    }
                    self.i = j;
                    self.space = true;
                }
                b'a'..=b'z' | b'A'..=b'Z' | b'_' => {
                    let word = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
                    let mut j = i;
                    // An identifier continues across line continuations
                    // (removed before tokenizing: `f\` + newline + `oo`
                    // is `foo`); its spelling leaves them out.
                    let mut spliced = false;
                    loop {
                        let k = self.skip_continuations(bytes, j);
                        match bytes.get(k) {
                            Some(&b) if word(b) => {
                                spliced |= k != j;
                                j = k + 1;
                            }
                            _ => break,
                        }
                    }
                    self.i = j;
                    let spelling = if spliced {
                        let joined: String = text[i..j].split(['\\', '\r', '\n']).collect();
                        SmolStr::new(joined)
                    } else {
                        self.spelling(i)
                    };
                    return Some(self.token(PpKind::Ident, spelling, i));
                }
                b'0'..=b'9' => {
                    self.i = scan_number(bytes, i);
                    let spelling = self.spelling(i);
                    return Some(self.token(PpKind::Number, spelling, i));
                }
                b'.' if bytes.get(i + 1).is_some_and(|b| b.is_ascii_digit()) => {
                    self.i = scan_number(bytes, i);
                    let spelling = self.spelling(i);
                    return Some(self.token(PpKind::Number, spelling, i));
                }
                b'"' if string_end(bytes, i).is_some() => {
                    self.i = string_end(bytes, i).unwrap_or(i + 1);
                    let spelling = self.spelling(i);
                    return Some(self.token(PpKind::Str, spelling, i));
                }
                b'#' => {
                    let (kind, len) = if bytes.get(i + 1) == Some(&b'#') {
                        (PpKind::HashHash, 2)
                    } else {
                        (PpKind::Hash, 1)
                    };
                    self.i = i + len;
                    let spelling = self.spelling(i);
                    return Some(self.token(kind, spelling, i));
                }
                _ => {
                    let rest = &text[i..];
                    if let Some(p) = punct_at(rest.as_bytes()) {
                        self.i = i + p.as_str().len();
                        return Some(self.token(
                            PpKind::Punct(p),
                            SmolStr::new_static(p.as_str()),
                            i,
                        ));
                    }
                    let ch = rest.chars().next().unwrap_or('\u{fffd}');
                    self.i = i + ch.len_utf8();
                    let spelling = self.spelling(i);
                    return Some(self.token(PpKind::Other(ch), spelling, i));
                }
            }
        }
        None
    }
}

/// The end (after the closing quote) of a string literal starting at
/// `i`, if it closes on the same line. `\"` and `\\` do not close it.
fn string_end(bytes: &[u8], i: usize) -> Option<usize> {
    let mut j = i + 1;
    while let Some(&b) = bytes.get(j) {
        match b {
            b'"' => return Some(j + 1),
            b'\n' => return None,
            b'\\' => j += 2,
            _ => j += 1,
        }
    }
    None
}

impl Lexer<'_> {
    /// The index of the first byte at or after `j` that is not part of a
    /// line continuation (`j` itself when continuations are off).
    fn skip_continuations(&self, bytes: &[u8], mut j: usize) -> usize {
        if self.opts.line_continuation {
            while let n @ 1.. = continuation_len(bytes, j) {
                j += n;
            }
        }
        j
    }
}

/// The length of a line continuation (`\` then LF or CR LF) at `i`, or 0.
fn continuation_len(bytes: &[u8], i: usize) -> usize {
    if bytes.get(i) != Some(&b'\\') {
        return 0;
    }
    match (bytes.get(i + 1), bytes.get(i + 2)) {
        (Some(b'\n'), _) => 2,
        (Some(b'\r'), Some(b'\n')) => 3,
        _ => 0,
    }
}

/// The longest punctuator at the start of `b` (maximal munch), decided on
/// the first bytes rather than by trying every punctuator in turn.
fn punct_at(b: &[u8]) -> Option<Punct> {
    use Punct::*;
    let c0 = *b.first()?;
    let c1 = b.get(1).copied().unwrap_or(0);
    let c2 = b.get(2).copied().unwrap_or(0);
    Some(match (c0, c1) {
        (b'<', b'<') if c2 == b'=' => ShlEq,
        (b'>', b'>') if c2 == b'=' => ShrEq,
        (b'<', b'<') => Shl,
        (b'>', b'>') => Shr,
        (b'<', b'=') => LessEq,
        (b'>', b'=') => GreaterEq,
        (b'=', b'=') => EqEq,
        (b'!', b'=') => NotEq,
        (b'&', b'&') => AmpAmp,
        (b'^', b'^') => CaretCaret,
        (b'|', b'|') => PipePipe,
        (b'+', b'=') => PlusEq,
        (b'-', b'=') => MinusEq,
        (b'*', b'=') => StarEq,
        (b'/', b'=') => SlashEq,
        (b'%', b'=') => PercentEq,
        (b'&', b'=') => AmpEq,
        (b'^', b'=') => CaretEq,
        (b'|', b'=') => PipeEq,
        (b'+', b'+') => PlusPlus,
        (b'-', b'-') => MinusMinus,
        (b'(', _) => LeftParen,
        (b')', _) => RightParen,
        (b'[', _) => LeftBracket,
        (b']', _) => RightBracket,
        (b'{', _) => LeftBrace,
        (b'}', _) => RightBrace,
        (b'.', _) => Dot,
        (b',', _) => Comma,
        (b':', _) => Colon,
        (b';', _) => Semicolon,
        (b'?', _) => Question,
        (b'+', _) => Plus,
        (b'-', _) => Minus,
        (b'*', _) => Star,
        (b'/', _) => Slash,
        (b'%', _) => Percent,
        (b'!', _) => Bang,
        (b'~', _) => Tilde,
        (b'<', _) => Less,
        (b'>', _) => Greater,
        (b'&', _) => Amp,
        (b'^', _) => Caret,
        (b'|', _) => Pipe,
        (b'=', _) => Equal,
        _ => return None,
    })
}

/// Scans a preprocessing number starting at `i`: digits, letters, `_`, `.`,
/// and a sign right after an exponent letter `e`/`E` (not in hex numbers).
fn scan_number(bytes: &[u8], mut i: usize) -> usize {
    let hex = bytes[i] == b'0' && matches!(bytes.get(i + 1), Some(b'x') | Some(b'X'));
    while i < bytes.len() {
        let c = bytes[i];
        if c.is_ascii_alphanumeric() || c == b'_' || c == b'.' {
            i += 1;
            if !hex && (c == b'e' || c == b'E') && matches!(bytes.get(i), Some(b'+') | Some(b'-')) {
                i += 1;
            }
        } else {
            break;
        }
    }
    i
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(s: &str) -> Vec<PpKind> {
        lex(s, LexOptions::default())
            .0
            .into_iter()
            .map(|t| t.kind)
            .collect()
    }

    #[test]
    fn basic() {
        let (t, d) = lex("vec4 a = 1.5e-3*b; // x\n", LexOptions::default());
        assert!(d.is_empty());
        let texts: Vec<_> = t.iter().map(|t| t.text.as_str()).collect();
        assert_eq!(texts, ["vec4", "a", "=", "1.5e-3", "*", "b", ";", "\n"]);
    }

    #[test]
    fn comments_and_hash() {
        assert_eq!(
            kinds("# define /* c */ X##Y"),
            [
                PpKind::Hash,
                PpKind::Ident,
                PpKind::Ident,
                PpKind::HashHash,
                PpKind::Ident
            ]
        );
    }

    #[test]
    fn continuation() {
        let opts = LexOptions {
            line_continuation: true,
        };
        // Removed before tokenizing: the lines' ends join into one token
        // (GLSL 4.20 §3.1; Mesa's preprocessor does so in every version).
        let (t, _) = lex("a\\\nb", opts);
        assert_eq!(t.len(), 1);
        assert_eq!(t[0].text.as_str(), "ab");
        let (t, _) = lex("/* x *\\\n/ c", opts);
        assert_eq!(t.iter().map(|t| t.text.as_str()).collect::<Vec<_>>(), ["c"]);
        let (t, _) = lex("a\\\nb", LexOptions::default());
        assert!(t.iter().any(|t| t.kind == PpKind::Other('\\')));
        let (t, _) = lex("a // c \\\r\n b\nc", opts);
        let texts: Vec<_> = t.iter().map(|t| t.text.as_str()).collect();
        assert_eq!(texts, ["a", "\n", "c"]);
        let (t, _) = lex("a \\ b \\", opts);
        assert_eq!(
            t.iter().filter(|t| t.kind == PpKind::Other('\\')).count(),
            2
        );
    }

    #[test]
    fn punctuators_agree_with_the_table() {
        // Every punctuator, alone and followed by each other one, lexes as
        // maximal munch over the table would.
        for p in Punct::ALL_LONGEST_FIRST {
            assert_eq!(punct_at(p.as_str().as_bytes()), Some(*p), "{}", p.as_str());
            for q in Punct::ALL_LONGEST_FIRST {
                let s = format!("{}{}", p.as_str(), q.as_str());
                let want = Punct::ALL_LONGEST_FIRST
                    .iter()
                    .find(|x| s.starts_with(x.as_str()))
                    .copied();
                assert_eq!(punct_at(s.as_bytes()), want, "{s}");
            }
        }
    }

    #[test]
    fn unterminated_comment() {
        let (_, d) = lex("/* abc", LexOptions::default());
        assert_eq!(d.len(), 1);
    }
}
