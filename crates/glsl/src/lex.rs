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
    let bytes = text.as_bytes();
    let mut toks = Vec::new();
    let mut diags = Vec::new();
    let mut i = 0usize;
    let mut space = false;
    while i < bytes.len() {
        let c = bytes[i];
        // Line continuation.
        if opts.line_continuation {
            let n = continuation_len(bytes, i);
            if n > 0 {
                i += n;
                continue;
            }
        }
        match c {
            b' ' | b'\t' | b'\r' | 0x0b | 0x0c => {
                space = true;
                i += 1;
            }
            b'\n' => {
                toks.push(PpToken {
                    kind: PpKind::Newline,
                    text: SmolStr::new_static("\n"),
                    span: Span::new(i as u32, i as u32 + 1),
                    space_before: space,
                });
                space = false;
                i += 1;
            }
            b'/' if bytes.get(i + 1) == Some(&b'/') => {
                // Line comment, up to (not including) the newline.
                // Continuations are removed before comments are recognized,
                // so a `\` at the end continues the comment.
                while i < bytes.len() && bytes[i] != b'\n' {
                    let n = if opts.line_continuation {
                        continuation_len(bytes, i)
                    } else {
                        0
                    };
                    i += n.max(1);
                }
                space = true;
            }
            b'/' if bytes.get(i + 1) == Some(&b'*') => {
                let start = i;
                i += 2;
                let mut closed = false;
                while i < bytes.len() {
                    if bytes[i] == b'*' && bytes.get(i + 1) == Some(&b'/') {
                        i += 2;
                        closed = true;
                        break;
                    }
                    // Newlines inside a comment still end directive lines
                    // for line counting; the span table handles numbering,
                    // so nothing is emitted here.
                    i += 1;
                }
                if !closed {
                    diags.push(Diagnostic::error(
                        Code::PpUnterminated,
                        Span::new(start as u32, start as u32 + 2),
                        "unterminated comment",
                    ));
                }
                space = true;
            }
            b'a'..=b'z' | b'A'..=b'Z' | b'_' => {
                let start = i;
                while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                    i += 1;
                }
                toks.push(PpToken {
                    kind: PpKind::Ident,
                    text: SmolStr::new(&text[start..i]),
                    span: Span::new(start as u32, i as u32),
                    space_before: space,
                });
                space = false;
            }
            b'0'..=b'9' => {
                let start = i;
                i = scan_number(bytes, i);
                toks.push(PpToken {
                    kind: PpKind::Number,
                    text: SmolStr::new(&text[start..i]),
                    span: Span::new(start as u32, i as u32),
                    space_before: space,
                });
                space = false;
            }
            b'.' if bytes.get(i + 1).is_some_and(|b| b.is_ascii_digit()) => {
                let start = i;
                i = scan_number(bytes, i);
                toks.push(PpToken {
                    kind: PpKind::Number,
                    text: SmolStr::new(&text[start..i]),
                    span: Span::new(start as u32, i as u32),
                    space_before: space,
                });
                space = false;
            }
            b'"' if string_end(bytes, i).is_some() => {
                let start = i;
                i = string_end(bytes, i).unwrap_or(i + 1);
                toks.push(PpToken {
                    kind: PpKind::Str,
                    text: SmolStr::new(&text[start..i]),
                    span: Span::new(start as u32, i as u32),
                    space_before: space,
                });
                space = false;
            }
            b'#' => {
                let start = i;
                let (kind, len) = if bytes.get(i + 1) == Some(&b'#') {
                    (PpKind::HashHash, 2)
                } else {
                    (PpKind::Hash, 1)
                };
                i += len;
                toks.push(PpToken {
                    kind,
                    text: SmolStr::new(&text[start..i]),
                    span: Span::new(start as u32, i as u32),
                    space_before: space,
                });
                space = false;
            }
            _ => {
                let start = i;
                let rest = &text[i..];
                if let Some(p) = punct_at(rest.as_bytes()) {
                    i += p.as_str().len();
                    toks.push(PpToken {
                        kind: PpKind::Punct(p),
                        text: SmolStr::new_static(p.as_str()),
                        span: Span::new(start as u32, i as u32),
                        space_before: space,
                    });
                } else {
                    let ch = rest.chars().next().unwrap_or('\u{fffd}');
                    i += ch.len_utf8();
                    toks.push(PpToken {
                        kind: PpKind::Other(ch),
                        text: SmolStr::new(&text[start..i]),
                        span: Span::new(start as u32, i as u32),
                        space_before: space,
                    });
                }
                space = false;
            }
        }
    }
    (toks, diags)
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
        let (t, _) = lex("a\\\nb", opts);
        assert_eq!(t.len(), 2);
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
