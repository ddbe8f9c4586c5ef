//! Expressions (GLSL 1.20 §5 and §9, `expression` down to
//! `primary_expression`), with C precedence. Binary operators use precedence
//! climbing; the operators reserved in 1.10/1.20 (`%`, shifts, bitwise ops
//! and their assignments, `~`) are parsed so analysis can reject them with
//! a clear message.

use super::{PResult, Parser};
use crate::ast::*;
use crate::lang::Version;
use crate::source::Span;
use crate::token::{Keyword, Punct, TokenKind};

/// Expressions are returned boxed: on the deeply recursive expression path
/// a `Box` is much cheaper to pass around than the node itself (unoptimized
/// builds keep every temporary), and the tree stores boxes anyway.
pub(super) type PExpr = PResult<Box<Expr>>;

/// A binary operator and its precedence (higher binds tighter).
fn binary_op(p: Punct) -> Option<(BinaryOp, u8)> {
    use BinaryOp::*;
    Some(match p {
        Punct::PipePipe => (LogicalOr, 1),
        Punct::CaretCaret => (LogicalXor, 2),
        Punct::AmpAmp => (LogicalAnd, 3),
        Punct::Pipe => (BitOr, 4),
        Punct::Caret => (BitXor, 5),
        Punct::Amp => (BitAnd, 6),
        Punct::EqEq => (Eq, 7),
        Punct::NotEq => (NotEq, 7),
        Punct::Less => (Less, 8),
        Punct::Greater => (Greater, 8),
        Punct::LessEq => (LessEq, 8),
        Punct::GreaterEq => (GreaterEq, 8),
        Punct::Shl => (Shl, 9),
        Punct::Shr => (Shr, 9),
        Punct::Plus => (Add, 10),
        Punct::Minus => (Sub, 10),
        Punct::Star => (Mul, 11),
        Punct::Slash => (Div, 11),
        Punct::Percent => (Mod, 11),
        _ => return None,
    })
}

fn assign_op(p: Punct) -> Option<AssignOp> {
    use BinaryOp::*;
    Some(AssignOp(match p {
        Punct::Equal => None,
        Punct::PlusEq => Some(Add),
        Punct::MinusEq => Some(Sub),
        Punct::StarEq => Some(Mul),
        Punct::SlashEq => Some(Div),
        Punct::PercentEq => Some(Mod),
        Punct::ShlEq => Some(Shl),
        Punct::ShrEq => Some(Shr),
        Punct::AmpEq => Some(BitAnd),
        Punct::CaretEq => Some(BitXor),
        Punct::PipeEq => Some(BitOr),
        _ => return None,
    }))
}

fn prefix_op(p: Punct) -> Option<UnaryOp> {
    Some(match p {
        Punct::Plus => UnaryOp::Plus,
        Punct::Minus => UnaryOp::Minus,
        Punct::Bang => UnaryOp::Not,
        Punct::Tilde => UnaryOp::BitNot,
        Punct::PlusPlus => UnaryOp::PreInc,
        Punct::MinusMinus => UnaryOp::PreDec,
        _ => return None,
    })
}

impl Parser<'_> {
    fn punct(&self) -> Option<Punct> {
        match self.kind() {
            TokenKind::Punct(p) => Some(*p),
            _ => None,
        }
    }

    /// `expression`: assignments separated by commas.
    pub(super) fn expression(&mut self) -> PExpr {
        let first = self.assignment()?;
        if !self.at_punct(Punct::Comma) {
            return Ok(first);
        }
        self.comma_rest(first)
    }

    fn comma_rest(&mut self, mut e: Box<Expr>) -> PExpr {
        while self.eat_punct(Punct::Comma) {
            let rhs = self.assignment()?;
            let span = e.span.to(rhs.span);
            e = node(ExprKind::Comma(e, rhs), span);
        }
        Ok(e)
    }

    /// `assignment_expression`. The grammar wants a unary expression on the
    /// left; any conditional expression is accepted and analysis reports a
    /// left side that is not an lvalue.
    ///
    /// This is the recursion point of nested expressions, so it counts a
    /// nesting level. (The functions on the recursive path keep their
    /// frames small: rarely taken work is in separate functions.)
    pub(super) fn assignment(&mut self) -> PExpr {
        self.enter()?;
        let r = self.assignment_inner();
        self.leave();
        r
    }

    fn assignment_inner(&mut self) -> PExpr {
        let lhs = self.conditional()?;
        match self.punct().and_then(assign_op) {
            None => Ok(lhs),
            Some(op) => self.assignment_rest(lhs, op),
        }
    }

    fn assignment_rest(&mut self, lhs: Box<Expr>, op: AssignOp) -> PExpr {
        self.bump();
        let rhs = self.assignment()?;
        let span = lhs.span.to(rhs.span);
        Ok(node(ExprKind::Assign(op, lhs, rhs), span))
    }

    /// `conditional_expression`.
    pub(super) fn conditional(&mut self) -> PExpr {
        let cond = self.binary(0)?;
        if !self.at_punct(Punct::Question) {
            return Ok(cond);
        }
        self.ternary_rest(cond)
    }

    /// `? expression : ...`. After `:` GLSL 1.20 takes an
    /// `assignment_expression`, 1.10 a `conditional_expression`.
    fn ternary_rest(&mut self, cond: Box<Expr>) -> PExpr {
        self.bump();
        let then = self.expression()?;
        self.expect_punct(Punct::Colon)?;
        let else_ = if self.lang.version >= Version::V120 {
            self.assignment()?
        } else {
            self.enter()?;
            let r = self.conditional();
            self.leave();
            r?
        };
        let span = cond.span.to(else_.span);
        Ok(node(ExprKind::Ternary(cond, then, else_), span))
    }

    /// Binary operators binding at least as tightly as `min_prec`, left
    /// associative.
    fn binary(&mut self, min_prec: u8) -> PExpr {
        let lhs = self.unary()?;
        self.binary_rest(lhs, min_prec)
    }

    fn binary_rest(&mut self, mut lhs: Box<Expr>, min_prec: u8) -> PExpr {
        while let Some((op, prec)) = self.punct().and_then(binary_op) {
            if prec < min_prec {
                break;
            }
            self.bump();
            let rhs = self.binary(prec + 1)?;
            let span = lhs.span.to(rhs.span);
            lhs = node(ExprKind::Binary(op, lhs, rhs), span);
        }
        Ok(lhs)
    }

    /// `unary_expression`: prefix operators, then a postfix expression.
    fn unary(&mut self) -> PExpr {
        match self.punct().and_then(prefix_op) {
            None => self.postfix(),
            Some(op) => self.prefix(op),
        }
    }

    fn prefix(&mut self, op: UnaryOp) -> PExpr {
        let start = self.bump().span;
        self.enter()?;
        let operand = self.unary();
        self.leave();
        let operand = operand?;
        let span = start.to(operand.span);
        Ok(node(ExprKind::Unary(op, operand), span))
    }

    /// `postfix_expression`: indexing, field selection, method calls and
    /// postfix `++`/`--` after a primary expression.
    fn postfix(&mut self) -> PExpr {
        let e = self.primary()?;
        self.postfix_rest(e)
    }

    fn postfix_rest(&mut self, mut e: Box<Expr>) -> PExpr {
        loop {
            e = match self.punct() {
                Some(Punct::LeftBracket) => self.index_suffix(e)?,
                Some(Punct::Dot) => self.dot_suffix(e)?,
                Some(Punct::PlusPlus) => self.postfix_op(e, UnaryOp::PostInc),
                Some(Punct::MinusMinus) => self.postfix_op(e, UnaryOp::PostDec),
                _ => return Ok(e),
            };
        }
    }

    /// `e[index]`.
    fn index_suffix(&mut self, e: Box<Expr>) -> PExpr {
        self.bump();
        let index = self.expression()?;
        self.expect_close(Punct::RightBracket)?;
        let span = self.span_from(e.span);
        Ok(node(ExprKind::Index(e, index), span))
    }

    /// `e.field` or the method call `e.name(args)`.
    fn dot_suffix(&mut self, e: Box<Expr>) -> PExpr {
        self.bump();
        let name = self.ident("field name")?;
        if !self.at_punct(Punct::LeftParen) {
            let span = self.span_from(e.span);
            return Ok(node(ExprKind::Field(e, name), span));
        }
        let args = self.call_args()?;
        let span = self.span_from(e.span);
        Ok(node(ExprKind::Method(e, name, args), span))
    }

    /// `e++` / `e--`.
    fn postfix_op(&mut self, e: Box<Expr>, op: UnaryOp) -> Box<Expr> {
        self.bump();
        let span = self.span_from(e.span);
        node(ExprKind::Unary(op, e), span)
    }

    /// `primary_expression` and `function_call` (a call or constructor).
    fn primary(&mut self) -> PExpr {
        match self.kind() {
            TokenKind::Identifier(name) if self.scopes.is_type(name) => self.constructor(),
            TokenKind::Identifier(_) => self.identifier_or_call(),
            TokenKind::Keyword(k) if super::decl::is_type_keyword(*k) => self.constructor(),
            TokenKind::Punct(Punct::LeftParen) => self.parenthesized(),
            TokenKind::Reserved(_) => Err(self.reserved_word()),
            _ => self.literal_or_missing(),
        }
    }

    /// `( expression )`; the span covers the parentheses.
    fn parenthesized(&mut self) -> PExpr {
        let start = self.bump().span;
        let mut inner = self.expression()?;
        self.expect_close(Punct::RightParen)?;
        inner.span = self.span_from(start);
        Ok(inner)
    }

    /// A variable or a function call `f(args)`.
    fn identifier_or_call(&mut self) -> PExpr {
        let ident = self.ident("identifier")?;
        if !self.at_punct(Punct::LeftParen) {
            let span = ident.span;
            return Ok(node(ExprKind::Ident(ident), span));
        }
        let args = self.call_args()?;
        let span = self.span_from(ident.span);
        Ok(node(ExprKind::Call(Callee::Function(ident), args), span))
    }

    /// A literal. Where no expression starts but the token can follow one
    /// (`;`, `)`, ...), the missing operand is reported and becomes
    /// [`ExprKind::Error`] so the statement survives.
    fn literal_or_missing(&mut self) -> PExpr {
        let start = self.span();
        let kind = match self.kind() {
            TokenKind::IntLiteral(v) => ExprKind::IntLit(*v),
            TokenKind::UintLiteral(v) => ExprKind::UintLit(*v),
            TokenKind::FloatLiteral(v) => ExprKind::FloatLit(*v),
            TokenKind::StringLiteral(s) => ExprKind::StringLit(s.clone()),
            TokenKind::Keyword(Keyword::True) => ExprKind::BoolLit(true),
            TokenKind::Keyword(Keyword::False) => ExprKind::BoolLit(false),
            TokenKind::Eof
            | TokenKind::Punct(
                Punct::Semicolon
                | Punct::RightParen
                | Punct::RightBracket
                | Punct::RightBrace
                | Punct::Comma
                | Punct::Colon,
            ) => {
                let _ = self.unexpected("expression");
                return Ok(node(ExprKind::Error, Span::new(start.start, start.start)));
            }
            _ => return Err(self.unexpected("expression")),
        };
        self.bump();
        Ok(node(kind, start))
    }

    /// A constructor call: `vec3(...)`, `S(...)`, GLSL 1.20 `float[3](...)`
    /// and `float[](...)`.
    fn constructor(&mut self) -> PExpr {
        let start = self.span();
        let ty = self.type_specifier()?;
        if !self.at_punct(Punct::LeftParen) {
            return Err(self.unexpected_with_note(
                "`('",
                "a type name in an expression must be a constructor call, as in `vec3(1.0)'",
            ));
        }
        let args = self.call_args()?;
        let span = self.span_from(start);
        Ok(node(ExprKind::Call(Callee::Constructor(ty), args), span))
    }

    /// `( args )` of a call: `()` and `(void)` have no arguments.
    fn call_args(&mut self) -> PResult<Vec<Expr>> {
        self.expect_punct(Punct::LeftParen)?;
        let mut args = Vec::new();
        if self.eat_punct(Punct::RightParen) {
            return Ok(args);
        }
        if self.at_keyword(Keyword::Void) && self.nth_is_punct(1, Punct::RightParen) {
            self.bump();
            self.bump();
            return Ok(args);
        }
        loop {
            args.push(*self.assignment()?);
            if !self.eat_punct(Punct::Comma) {
                break;
            }
        }
        self.expect_close(Punct::RightParen)?;
        Ok(args)
    }
}

fn node(kind: ExprKind, span: Span) -> Box<Expr> {
    Box::new(Expr { kind, span })
}
