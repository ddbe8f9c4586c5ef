//! Statements (GLSL 1.30 §9: `statement`, `compound_statement`,
//! `selection_statement`, `switch_statement`, `case_label`,
//! `iteration_statement`, `jump_statement`).
//!
//! Scopes follow the grammar: a nested `{ }` and the branches of `if` open a
//! new scope; a function body shares the parameters' scope; `while` and
//! `for` open one scope for their header and body together, so a compound
//! body is `statement_no_new_scope` (GLSL 1.20 §6.3).

use super::{PResult, Parser, Reported};
use crate::ast::*;
use crate::source::Span;
use crate::token::{Keyword, Punct, TokenKind};

impl Parser<'_> {
    /// `{ statements }` without opening a scope: the caller decides. A
    /// missing `}` at the end of input is reported and the block kept.
    pub(super) fn compound_body(&mut self) -> PResult<Block> {
        let start = self.expect_punct(Punct::LeftBrace)?;
        let mut stmts = Vec::new();
        loop {
            if self.aborted {
                return Err(Reported);
            }
            if self.eat_punct(Punct::RightBrace) {
                break;
            }
            if self.at_eof() {
                let _ = self.unexpected("`}'");
                break;
            }
            let begin = self.pos;
            self.recovering = false;
            match self.statement(true) {
                Ok(s) => stmts.push(*s),
                Err(Reported) => {
                    self.recover(begin);
                    if self.pos == begin && !self.at_punct(Punct::RightBrace) {
                        self.bump();
                    }
                }
            }
        }
        Ok(Block {
            stmts,
            span: self.span_from(start),
        })
    }

    /// A statement. A compound statement opens a new scope only if
    /// `new_scope` (it is false for the grammar's `statement_no_new_scope`).
    /// Counts a nesting level.
    pub(super) fn statement(&mut self, new_scope: bool) -> PResult<Box<Stmt>> {
        self.enter()?;
        let r = self.statement_inner(new_scope);
        self.leave();
        r
    }

    /// Dispatches on the first token; each kind of statement is parsed in
    /// its own function so this frame stays small on the recursive path.
    fn statement_inner(&mut self, new_scope: bool) -> PResult<Box<Stmt>> {
        match self.kind() {
            TokenKind::Punct(Punct::LeftBrace) => self.block_statement(new_scope),
            TokenKind::Keyword(Keyword::If) => self.if_statement(),
            TokenKind::Keyword(Keyword::While) => self.while_statement(),
            TokenKind::Keyword(Keyword::Do) => self.do_statement(),
            TokenKind::Keyword(Keyword::For) => self.for_statement(),
            TokenKind::Keyword(Keyword::Switch) => self.switch_statement(),
            TokenKind::Keyword(Keyword::Case | Keyword::Default) => self.case_label(),
            TokenKind::Reserved(_) => Err(self.reserved_word()),
            _ => self.simple_statement(),
        }
    }

    fn block_statement(&mut self, new_scope: bool) -> PResult<Box<Stmt>> {
        let start = self.span();
        if new_scope {
            self.scopes.push();
        }
        let block = self.compound_body();
        if new_scope {
            self.scopes.pop();
        }
        Ok(Box::new(Stmt {
            kind: StmtKind::Block {
                block: block?,
                new_scope,
            },
            span: self.span_from(start),
        }))
    }

    /// Jumps, declarations, expression statements and `;`.
    fn simple_statement(&mut self) -> PResult<Box<Stmt>> {
        let start = self.span();
        let kind = match self.kind() {
            TokenKind::Punct(Punct::Semicolon) => {
                self.bump();
                StmtKind::Expr(None)
            }
            TokenKind::Keyword(k @ (Keyword::Break | Keyword::Continue | Keyword::Discard)) => {
                let k = *k;
                self.bump();
                self.expect_semicolon()?;
                match k {
                    Keyword::Break => StmtKind::Break,
                    Keyword::Continue => StmtKind::Continue,
                    _ => StmtKind::Discard,
                }
            }
            TokenKind::Keyword(Keyword::Return) => {
                self.bump();
                let value = if self.at_punct(Punct::Semicolon) {
                    None
                } else {
                    Some(*self.expression()?)
                };
                self.expect_semicolon()?;
                StmtKind::Return(value)
            }
            _ if self.at_declaration_start() => StmtKind::Declaration(self.local_declaration()?),
            _ => {
                let e = *self.expression()?;
                self.expect_semicolon()?;
                StmtKind::Expr(Some(e))
            }
        };
        Ok(Box::new(Stmt {
            kind,
            span: self.span_from(start),
        }))
    }

    /// `if ( expression ) statement [else statement]`; each branch that is
    /// a compound statement opens a scope.
    fn if_statement(&mut self) -> PResult<Box<Stmt>> {
        let start = self.bump().span;
        self.expect_punct(Punct::LeftParen)?;
        let cond = *self.expression()?;
        self.expect_punct(Punct::RightParen)?;
        let then = self.statement(true)?;
        let else_ = if self.at_keyword(Keyword::Else) {
            self.bump();
            Some(self.statement(true)?)
        } else {
            None
        };
        Ok(Box::new(Stmt {
            kind: StmtKind::If { cond, then, else_ },
            span: self.span_from(start),
        }))
    }

    /// `switch ( expression ) { switch_statement_list }`; the body is one
    /// scope (labels are statements of it).
    fn switch_statement(&mut self) -> PResult<Box<Stmt>> {
        let start = self.bump().span;
        self.expect_punct(Punct::LeftParen)?;
        let selector = *self.expression()?;
        self.expect_punct(Punct::RightParen)?;
        if !self.at_punct(Punct::LeftBrace) {
            return Err(self.unexpected("`{' to open the body of `switch'"));
        }
        self.scopes.push();
        let body = self.compound_body();
        self.scopes.pop();
        Ok(Box::new(Stmt {
            kind: StmtKind::Switch {
                selector,
                body: body?,
            },
            span: self.span_from(start),
        }))
    }

    /// `case expression :` or `default :`.
    fn case_label(&mut self) -> PResult<Box<Stmt>> {
        let start = self.span();
        let kind = if self.bump().kind == TokenKind::Keyword(Keyword::Case) {
            StmtKind::Case(*self.expression()?)
        } else {
            StmtKind::Default
        };
        self.expect_punct(Punct::Colon)?;
        Ok(Box::new(Stmt {
            kind,
            span: self.span_from(start),
        }))
    }

    /// `while ( condition ) statement_no_new_scope`; the condition and body
    /// share one scope.
    fn while_statement(&mut self) -> PResult<Box<Stmt>> {
        let start = self.bump().span;
        self.scopes.push();
        let r = self.while_rest(start);
        self.scopes.pop();
        r
    }

    fn while_rest(&mut self, start: Span) -> PResult<Box<Stmt>> {
        self.expect_punct(Punct::LeftParen)?;
        let cond = self.condition()?;
        self.expect_punct(Punct::RightParen)?;
        let body = self.statement(false)?;
        Ok(Box::new(Stmt {
            kind: StmtKind::While { cond, body },
            span: self.span_from(start),
        }))
    }

    /// `do statement while ( expression ) ;`.
    fn do_statement(&mut self) -> PResult<Box<Stmt>> {
        let start = self.bump().span;
        let body = self.statement(true)?;
        if !self.at_keyword(Keyword::While) {
            return Err(self.unexpected("`while'"));
        }
        self.bump();
        self.expect_punct(Punct::LeftParen)?;
        let cond = *self.expression()?;
        self.expect_punct(Punct::RightParen)?;
        self.expect_semicolon()?;
        Ok(Box::new(Stmt {
            kind: StmtKind::DoWhile { body, cond },
            span: self.span_from(start),
        }))
    }

    /// `for ( for_init_statement condition? ; expression? )
    /// statement_no_new_scope`; the header and body share one scope.
    fn for_statement(&mut self) -> PResult<Box<Stmt>> {
        let start = self.bump().span;
        self.scopes.push();
        let r = self.for_rest(start);
        self.scopes.pop();
        r
    }

    fn for_rest(&mut self, start: Span) -> PResult<Box<Stmt>> {
        self.expect_punct(Punct::LeftParen)?;
        let init = self.for_init()?;
        let cond = if self.at_punct(Punct::Semicolon) {
            None
        } else {
            Some(self.condition()?)
        };
        self.expect_punct(Punct::Semicolon)?;
        let step = if self.at_punct(Punct::RightParen) {
            None
        } else {
            Some(*self.expression()?)
        };
        self.expect_punct(Punct::RightParen)?;
        let body = self.statement(false)?;
        Ok(Box::new(Stmt {
            kind: StmtKind::For {
                init,
                cond,
                step,
                body,
            },
            span: self.span_from(start),
        }))
    }

    /// `for_init_statement`: an expression statement (maybe empty) or a
    /// declaration, with its `;`.
    fn for_init(&mut self) -> PResult<Box<Stmt>> {
        let start = self.span();
        let kind = if self.eat_punct(Punct::Semicolon) {
            StmtKind::Expr(None)
        } else if self.at_declaration_start() {
            StmtKind::Declaration(self.local_declaration()?)
        } else {
            let e = *self.expression()?;
            self.expect_punct(Punct::Semicolon)?;
            StmtKind::Expr(Some(e))
        };
        Ok(Box::new(Stmt {
            kind,
            span: self.span_from(start),
        }))
    }

    /// `condition`: an expression, or `type name = initializer` whose name
    /// is visible in the loop body.
    fn condition(&mut self) -> PResult<Condition> {
        if !self.at_declaration_start() {
            return Ok(Condition::Expr(*self.expression()?));
        }
        let start = self.span();
        let ty = self.fully_specified_type()?;
        let name = self.ident("identifier")?;
        self.expect_punct(Punct::Equal)?;
        let init = *self.assignment()?;
        self.scopes.declare(&name.name, false);
        Ok(Condition::Decl {
            ty,
            name,
            init,
            span: self.span_from(start),
        })
    }
}
