//! `#if`/`#elif`/`#line` expressions (GLSL 1.20 §3.3 operator table).
//!
//! Operands are integer literals; the operators are those of the table:
//! `defined`, unary `+ - ~ !`, `* / %`, `+ -`, `<< >>`, relational,
//! equality, `& ^ |`, `&& ||`. Arithmetic follows the C++ preprocessor on a
//! 64-bit host (`intmax_t`), wrapping on overflow instead of trapping.
//! Division or modulus by zero is an error only when that operand is
//! actually evaluated (`0 && 1/0` is fine), as in C.
//!
//! An identifier left after macro expansion evaluates to 0, as in C and
//! Mesa's desktop GLSL; since §3.3 restricts expressions to literals and
//! `defined`, it draws a warning.

use super::literal::{parse_number, Literal};
use super::macros::PTok;
use crate::diag::{Code, Diagnostic};
use crate::lex::PpKind;
use crate::limits;
use crate::source::Span;
use crate::token::Punct;

/// Parses and evaluates expressions from a token list.
pub(crate) struct ExprParser<'a> {
    toks: &'a [PTok],
    pos: usize,
    /// Where "end of line" errors point.
    end: Span,
    is_defined: &'a dyn Fn(&str) -> bool,
    warnings: Vec<Diagnostic>,
    nesting: u32,
    /// Identifiers evaluate to 0 (`#if`) instead of being errors (`#line`).
    idents_are_zero: bool,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum BinOp {
    Mul,
    Div,
    Rem,
    Add,
    Sub,
    Shl,
    Shr,
    Lt,
    Gt,
    Le,
    Ge,
    Eq,
    Ne,
    BitAnd,
    BitXor,
    BitOr,
    And,
    Or,
}

/// Precedence (higher binds tighter) of a binary operator token.
fn binop(t: &PTok) -> Option<(u8, BinOp)> {
    let PpKind::Punct(p) = t.kind else {
        return None;
    };
    Some(match p {
        Punct::Star => (10, BinOp::Mul),
        Punct::Slash => (10, BinOp::Div),
        Punct::Percent => (10, BinOp::Rem),
        Punct::Plus => (9, BinOp::Add),
        Punct::Minus => (9, BinOp::Sub),
        Punct::Shl => (8, BinOp::Shl),
        Punct::Shr => (8, BinOp::Shr),
        Punct::Less => (7, BinOp::Lt),
        Punct::Greater => (7, BinOp::Gt),
        Punct::LessEq => (7, BinOp::Le),
        Punct::GreaterEq => (7, BinOp::Ge),
        Punct::EqEq => (6, BinOp::Eq),
        Punct::NotEq => (6, BinOp::Ne),
        Punct::Amp => (5, BinOp::BitAnd),
        Punct::Caret => (4, BinOp::BitXor),
        Punct::Pipe => (3, BinOp::BitOr),
        Punct::AmpAmp => (2, BinOp::And),
        Punct::PipePipe => (1, BinOp::Or),
        _ => return None,
    })
}

impl<'a> ExprParser<'a> {
    pub fn new(toks: &'a [PTok], end: Span, is_defined: &'a dyn Fn(&str) -> bool) -> Self {
        ExprParser {
            toks,
            pos: 0,
            end,
            is_defined,
            warnings: Vec::new(),
            nesting: 0,
            idents_are_zero: true,
        }
    }

    /// Makes identifiers errors rather than 0 (for `#line`, whose operands
    /// must be integers after macro expansion).
    pub fn strict(mut self) -> Self {
        self.idents_are_zero = false;
        self
    }

    /// Warnings collected so far (identifiers evaluated as 0).
    pub fn take_warnings(&mut self) -> Vec<Diagnostic> {
        std::mem::take(&mut self.warnings)
    }

    /// True when every token has been consumed.
    pub fn at_end(&self) -> bool {
        self.pos >= self.toks.len()
    }

    /// The next unconsumed token.
    pub fn peek(&self) -> Option<&'a PTok> {
        self.toks.get(self.pos)
    }

    /// Parses one full expression (stopping at a token that cannot continue
    /// it) and returns its value.
    pub fn expression(&mut self) -> Result<i64, Diagnostic> {
        self.binary(1, true)
    }

    fn binary(&mut self, min_prec: u8, live: bool) -> Result<i64, Diagnostic> {
        let mut lhs = self.unary(live)?;
        while let Some((prec, op)) = self.peek().and_then(binop) {
            if prec < min_prec {
                break;
            }
            let op_span = self.toks[self.pos].span;
            self.pos += 1;
            let rhs_live = match op {
                BinOp::And => live && lhs != 0,
                BinOp::Or => live && lhs == 0,
                _ => live,
            };
            let rhs = self.binary(prec + 1, rhs_live)?;
            lhs = apply(op, lhs, rhs, live, op_span)?;
        }
        Ok(lhs)
    }

    fn unary(&mut self, live: bool) -> Result<i64, Diagnostic> {
        let Some(t) = self.peek() else {
            return Err(Diagnostic::error(
                Code::PpSyntax,
                self.end,
                "expected an integer expression, found the end of the line",
            ));
        };
        if self.nesting >= limits::MAX_NESTING_DEPTH {
            return Err(Diagnostic::error(
                Code::PpSyntax,
                t.span,
                "preprocessor expression nests too deeply",
            ));
        }
        self.nesting += 1;
        let result = self.unary_inner(t, live);
        self.nesting -= 1;
        result
    }

    fn unary_inner(&mut self, t: &'a PTok, live: bool) -> Result<i64, Diagnostic> {
        self.pos += 1;
        match &t.kind {
            PpKind::Punct(Punct::Plus) => self.unary(live),
            PpKind::Punct(Punct::Minus) => Ok(self.unary(live)?.wrapping_neg()),
            PpKind::Punct(Punct::Tilde) => Ok(!self.unary(live)?),
            PpKind::Punct(Punct::Bang) => Ok(i64::from(self.unary(live)? == 0)),
            PpKind::Punct(Punct::LeftParen) => {
                let v = self.binary(1, live)?;
                match self.peek() {
                    Some(c) if c.is_punct(Punct::RightParen) => {
                        self.pos += 1;
                        Ok(v)
                    }
                    other => Err(unexpected(other, self.end, "`)'")),
                }
            }
            PpKind::Number => number_value(t),
            PpKind::Ident if t.text == "defined" => self.defined(t),
            PpKind::Ident if !self.idents_are_zero => {
                self.pos -= 1;
                Err(unexpected(Some(t), self.end, "an integer"))
            }
            PpKind::Ident => {
                self.warnings.push(
                    Diagnostic::warning(
                        Code::PpSyntax,
                        t.span,
                        format!("`{}' is not a macro; it evaluates to 0 here", t.text),
                    )
                    .with_note(
                        "GLSL §3.3 allows only integer literals and `defined' in #if expressions",
                    ),
                );
                Ok(0)
            }
            _ => {
                self.pos -= 1;
                Err(unexpected(Some(t), self.end, "an integer expression"))
            }
        }
    }

    /// `defined X` or `defined ( X )`, when produced by macro expansion.
    fn defined(&mut self, kw: &PTok) -> Result<i64, Diagnostic> {
        let paren = self.peek().is_some_and(|t| t.is_punct(Punct::LeftParen));
        if paren {
            self.pos += 1;
        }
        let name = match self.peek() {
            Some(t) if t.kind == PpKind::Ident => t,
            other => return Err(unexpected(other, kw.span, "a macro name after `defined'")),
        };
        self.pos += 1;
        if paren {
            match self.peek() {
                Some(c) if c.is_punct(Punct::RightParen) => self.pos += 1,
                other => return Err(unexpected(other, self.end, "`)' after `defined(NAME'")),
            }
        }
        Ok(i64::from((self.is_defined)(&name.text)))
    }
}

/// "expected X, found Y".
pub(crate) fn unexpected(found: Option<&PTok>, end: Span, expected: &str) -> Diagnostic {
    match found {
        Some(t) => Diagnostic::error(
            Code::PpSyntax,
            t.span,
            format!("expected {expected}, found `{}'", t.text),
        ),
        None => Diagnostic::error(
            Code::PpSyntax,
            end,
            format!("expected {expected}, found the end of the line"),
        ),
    }
}

fn number_value(t: &PTok) -> Result<i64, Diagnostic> {
    match parse_number(&t.text) {
        Ok(Literal::Int {
            value,
            fits_u64: true,
            ..
        }) => Ok(value as i64),
        Ok(Literal::Int { .. }) => Err(Diagnostic::error(
            Code::PpSyntax,
            t.span,
            format!("integer `{}' is too large for a preprocessor expression", t.text),
        )),
        Ok(Literal::Float { .. }) => Err(Diagnostic::error(
            Code::PpSyntax,
            t.span,
            format!(
                "floating-point literal `{}' in a preprocessor expression (only integers are allowed)",
                t.text
            ),
        )),
        Err(msg) => Err(Diagnostic::error(Code::LexBadNumber, t.span, msg)),
    }
}

fn apply(op: BinOp, a: i64, b: i64, live: bool, span: Span) -> Result<i64, Diagnostic> {
    Ok(match op {
        BinOp::Mul => a.wrapping_mul(b),
        BinOp::Div | BinOp::Rem if b == 0 => {
            if live {
                let what = if op == BinOp::Div {
                    "division"
                } else {
                    "modulus"
                };
                return Err(Diagnostic::error(
                    Code::PpSyntax,
                    span,
                    format!("{what} by zero in preprocessor expression"),
                ));
            }
            0
        }
        BinOp::Div => a.wrapping_div(b),
        BinOp::Rem => a.wrapping_rem(b),
        BinOp::Add => a.wrapping_add(b),
        BinOp::Sub => a.wrapping_sub(b),
        BinOp::Shl => match u32::try_from(b) {
            Ok(s) if s < 64 => a.wrapping_shl(s),
            _ => 0,
        },
        BinOp::Shr => match u32::try_from(b) {
            Ok(s) if s < 64 => a >> s,
            _ => a >> 63,
        },
        BinOp::Lt => i64::from(a < b),
        BinOp::Gt => i64::from(a > b),
        BinOp::Le => i64::from(a <= b),
        BinOp::Ge => i64::from(a >= b),
        BinOp::Eq => i64::from(a == b),
        BinOp::Ne => i64::from(a != b),
        BinOp::BitAnd => a & b,
        BinOp::BitXor => a ^ b,
        BinOp::BitOr => a | b,
        BinOp::And => i64::from(a != 0 && b != 0),
        BinOp::Or => i64::from(a != 0 || b != 0),
    })
}
