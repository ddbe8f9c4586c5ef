//! Statements and control flow (GLSL 1.30 §6). Loops are lowered to
//! [`ir::Stmt::Loop`] with their conditions as explicit `if (!c) break;`;
//! `switch` to [`ir::Stmt::Switch`], its labels grouped into cases.

use super::Analyzer;
use crate::ast::{self, Condition, StmtKind};
use crate::diag::{Code, Label};
use crate::ir::{self, CaseLabel, ConstScalar, ExprKind, Stage};
use crate::lang::Feature;
use crate::limits::MAX_NESTING_DEPTH;
use crate::source::Span;
use crate::types::Type;

impl Analyzer {
    /// Statements of a block in the current scope.
    pub fn block_stmts(&mut self, stmts: &[ast::Stmt]) -> ir::Block {
        let mut out = Vec::with_capacity(stmts.len());
        for s in stmts {
            self.stmt(s, &mut out);
        }
        out
    }

    /// A statement as a block of its own (loop and `if` bodies).
    fn sub_block(&mut self, s: &ast::Stmt) -> ir::Block {
        let mut out = Vec::new();
        self.stmt(s, &mut out);
        match out.len() {
            1 if matches!(out[0], ir::Stmt::Block(_)) => match out.pop() {
                Some(ir::Stmt::Block(b)) => b,
                _ => Vec::new(),
            },
            _ => out,
        }
    }

    fn stmt(&mut self, s: &ast::Stmt, out: &mut ir::Block) {
        if self.depth >= MAX_NESTING_DEPTH {
            self.error(Code::Unsupported, s.span, "statements nested too deeply");
            return;
        }
        self.depth += 1;
        self.stmt_inner(s, out);
        self.depth -= 1;
    }

    fn stmt_inner(&mut self, s: &ast::Stmt, out: &mut ir::Block) {
        let span = s.span;
        match &s.kind {
            StmtKind::Declaration(d) => out.extend(self.declaration(d)),
            StmtKind::Expr(None) => {}
            StmtKind::Expr(Some(e)) => {
                let v = self.rvalue(e);
                out.push(ir::Stmt::Expr(v));
            }
            StmtKind::Block { block, new_scope } => {
                if *new_scope {
                    self.scopes.push();
                }
                let b = self.block_stmts(&block.stmts);
                if *new_scope {
                    self.scopes.pop();
                }
                out.push(ir::Stmt::Block(b));
            }
            StmtKind::If { cond, then, else_ } => {
                let c = self.condition_expr(cond, "if");
                if let Some(f) = self.cur.as_mut() {
                    f.if_depth += 1;
                }
                let then = self.scoped_sub_block(then);
                let else_ = match else_ {
                    Some(e) => self.scoped_sub_block(e),
                    None => Vec::new(),
                };
                if let Some(f) = self.cur.as_mut() {
                    f.if_depth -= 1;
                }
                out.push(ir::Stmt::If {
                    cond: c,
                    then,
                    else_,
                    span,
                });
            }
            StmtKind::While { cond, body } => {
                self.scopes.push();
                let mut lbody = Vec::new();
                self.loop_condition(cond, &mut lbody);
                lbody.extend(self.loop_body(body));
                self.scopes.pop();
                out.push(ir::Stmt::Loop {
                    body: lbody,
                    continuing: Vec::new(),
                    span,
                });
            }
            StmtKind::DoWhile { body, cond } => {
                let lbody = self.loop_body(body);
                let c = self.condition_expr(cond, "do-while");
                let continuing = vec![break_unless(c)];
                out.push(ir::Stmt::Loop {
                    body: lbody,
                    continuing,
                    span,
                });
            }
            StmtKind::For {
                init,
                cond,
                step,
                body,
            } => {
                self.scopes.push();
                let mut block = Vec::new();
                self.stmt(init, &mut block);
                let mut lbody = Vec::new();
                if let Some(c) = cond {
                    self.loop_condition(c, &mut lbody);
                }
                let continuing = match step {
                    Some(e) => vec![ir::Stmt::Expr(self.rvalue(e))],
                    None => Vec::new(),
                };
                lbody.extend(self.loop_body(body));
                self.scopes.pop();
                block.push(ir::Stmt::Loop {
                    body: lbody,
                    continuing,
                    span,
                });
                out.push(ir::Stmt::Block(block));
            }
            StmtKind::Switch { selector, body } => self.switch(selector, body, span, out),
            StmtKind::Case(e) => {
                // Only the statements directly in a switch body are labels
                // (`switch` handles those); this one is elsewhere.
                let _ = self.rvalue(e);
                self.misplaced_label("case", span);
            }
            StmtKind::Default => self.misplaced_label("default", span),
            StmtKind::Break | StmtKind::Continue => {
                let is_break = matches!(s.kind, StmtKind::Break);
                let in_loop = self
                    .cur
                    .as_ref()
                    .is_some_and(|f| f.loop_depth > 0 || (is_break && f.switch_depth > 0));
                if !in_loop {
                    let (w, place) = if is_break && self.lang.allows(Feature::Switch) {
                        ("break", "a loop or switch")
                    } else if is_break {
                        ("break", "a loop")
                    } else {
                        ("continue", "a loop")
                    };
                    self.error(Code::BadControlFlow, span, format!("`{w}' outside {place}"));
                } else if is_break {
                    out.push(ir::Stmt::Break(span));
                } else {
                    out.push(ir::Stmt::Continue(span));
                }
            }
            StmtKind::Return(v) => {
                out.push(self.return_stmt(v.as_ref(), span));
                if let Some(f) = self.cur.as_mut() {
                    f.returned = true;
                }
            }
            StmtKind::Discard => {
                if self.stage != Stage::Fragment {
                    self.error(
                        Code::StageMismatch,
                        span,
                        "`discard' is only allowed in fragment shaders",
                    );
                }
                out.push(ir::Stmt::Discard(span));
            }
        }
    }

    /// A `case`/`default` label that is not directly in a switch body.
    fn misplaced_label(&mut self, word: &str, span: Span) {
        let inside = self.cur.as_ref().is_some_and(|f| f.switch_depth > 0);
        let d = self.error(
            Code::BadControlFlow,
            span,
            if inside {
                format!("`{word}' label nested inside other statements of its switch")
            } else {
                format!("`{word}' label outside a switch statement")
            },
        );
        if inside {
            d.notes.push(
                "labels must be statements of the switch body itself, not inside a loop, `if' \
                 or block in it (GLSL 1.30 §6.2)"
                    .into(),
            );
        }
    }

    /// `switch (selector) { body }` (GLSL 1.30 §6.2): the selector an int or
    /// uint scalar, labels constant expressions of its type, distinct, at
    /// most one `default`, no statement before the first label and at
    /// least one after the last.
    fn switch(&mut self, selector: &ast::Expr, body: &ast::Block, span: Span, out: &mut ir::Block) {
        let sel = self.rvalue(selector);
        let sel_ty = sel.ty;
        let sel_ok = sel_ty == Type::INT || sel_ty == Type::UINT;
        if !sel_ty.is_error() && !sel_ok {
            self.error(
                Code::TypeMismatch,
                selector.span,
                format!(
                    "the selector of `switch' must be an int or uint scalar, found {}",
                    self.tn(sel_ty)
                ),
            );
        }
        self.scopes.push();
        if let Some(f) = self.cur.as_mut() {
            f.switch_depth += 1;
        }
        let mut cases: Vec<ir::SwitchCase> = Vec::new();
        // Whether the last case has a statement after its labels (an empty
        // statement counts: it is a statement of the grammar).
        let mut last_has_stmt = true;
        let mut last_label = None;
        let mut seen: Vec<(ConstScalar, Span)> = Vec::new();
        let mut default_at: Option<Span> = None;
        let mut reported_first = false;
        for st in &body.stmts {
            let label = match &st.kind {
                StmtKind::Case(e) => self.case_value(e, sel_ty, sel_ok, &mut seen),
                StmtKind::Default => {
                    if let Some(first) = default_at {
                        self.error(
                            Code::BadControlFlow,
                            st.span,
                            "more than one `default' label in a switch",
                        )
                        .labels
                        .push(Label {
                            span: first,
                            message: "the first `default' is here".into(),
                        });
                    } else {
                        default_at = Some(st.span);
                    }
                    Some(CaseLabel::Default)
                }
                _ => {
                    if cases.is_empty() && !reported_first {
                        reported_first = true;
                        self.error(
                            Code::BadControlFlow,
                            st.span,
                            "a statement before the first `case' or `default' label of a switch",
                        )
                        .notes
                        .push("every statement of a switch body follows a label".into());
                    }
                    if cases.is_empty() {
                        cases.push(ir::SwitchCase {
                            labels: Vec::new(),
                            body: Vec::new(),
                        });
                    }
                    last_has_stmt = true;
                    let mut b = Vec::new();
                    self.stmt(st, &mut b);
                    if let Some(c) = cases.last_mut() {
                        c.body.extend(b);
                    }
                    continue;
                }
            };
            last_label = Some(st.span);
            // Consecutive labels share a case; a label after statements
            // starts a new one.
            match cases.last_mut() {
                Some(c) if !last_has_stmt => c.labels.extend(label),
                _ => cases.push(ir::SwitchCase {
                    labels: label.into_iter().collect(),
                    body: Vec::new(),
                }),
            }
            last_has_stmt = false;
        }
        if let (false, Some(at)) = (last_has_stmt, last_label) {
            self.error(
                Code::BadControlFlow,
                at,
                "a label at the end of a switch needs a statement after it",
            )
            .notes
            .push(
                "GLSL 1.30 §6.2: it is an error to have no statement between a label and the end \
                 of the switch; add `break;'"
                    .into(),
            );
        }
        if let Some(f) = self.cur.as_mut() {
            f.switch_depth -= 1;
        }
        self.scopes.pop();
        out.push(ir::Stmt::Switch {
            selector: sel,
            cases,
            span,
        });
    }

    /// A `case` label's value: a constant of the selector's type, not seen
    /// before in the switch. `None` after reporting a problem.
    fn case_value(
        &mut self,
        e: &ast::Expr,
        sel_ty: Type,
        sel_ok: bool,
        seen: &mut Vec<(ConstScalar, Span)>,
    ) -> Option<CaseLabel> {
        let v = self.rvalue(e);
        if v.ty.is_error() {
            return None;
        }
        let value = match &v.kind {
            ExprKind::Const(c) if v.ty == Type::INT || v.ty == Type::UINT => {
                c.components.first().copied()
            }
            _ => None,
        };
        let Some(value) = value else {
            self.error(
                Code::NotConstant,
                e.span,
                format!(
                    "a case label must be a constant int or uint expression, found {}{}",
                    if matches!(v.kind, ExprKind::Const(_)) {
                        ""
                    } else {
                        "a non-constant "
                    },
                    self.tn(v.ty)
                ),
            );
            return None;
        };
        if !sel_ok {
            return None;
        }
        if v.ty != sel_ty {
            let (l, s) = (self.tn(v.ty), self.tn(sel_ty));
            self.error(
                Code::TypeMismatch,
                e.span,
                format!("a case label of type {l} in a switch on {s}"),
            )
            .notes
            .push(
                "labels must have the selector's type; int and uint do not convert implicitly \
                 (write a `u' suffix or remove it)"
                    .into(),
            );
            return None;
        }
        if let Some(&(_, first)) = seen.iter().find(|(x, _)| *x == value) {
            self.error(
                Code::BadControlFlow,
                e.span,
                "a case label repeats the value of an earlier one",
            )
            .labels
            .push(Label {
                span: first,
                message: "the same value is here".into(),
            });
            return None;
        }
        seen.push((value, e.span));
        Some(CaseLabel::Value(value))
    }

    /// The body of `if`/`else`: a block statement opens its own scope as the
    /// parser says; a single statement is analyzed in a fresh scope too.
    fn scoped_sub_block(&mut self, s: &ast::Stmt) -> ir::Block {
        self.scopes.push();
        let b = self.sub_block(s);
        self.scopes.pop();
        b
    }

    fn loop_body(&mut self, body: &ast::Stmt) -> ir::Block {
        if let Some(f) = self.cur.as_mut() {
            f.loop_depth += 1;
        }
        // A compound body's scope is decided by the parser (shared with a
        // `for`/`while` header, GLSL 1.20 §6.3); a single statement gets a
        // scope of its own.
        let single = !matches!(body.kind, StmtKind::Block { .. });
        if single {
            self.scopes.push();
        }
        let b = self.sub_block(body);
        if single {
            self.scopes.pop();
        }
        if let Some(f) = self.cur.as_mut() {
            f.loop_depth -= 1;
        }
        b
    }

    /// A `while`/`for` condition: an expression or `T x = init` (declared
    /// anew each iteration), emitted as `if (!c) break;`.
    fn loop_condition(&mut self, c: &Condition, out: &mut ir::Block) {
        match c {
            Condition::Expr(e) => {
                let v = self.condition_expr(e, "loop");
                out.push(break_unless(v));
            }
            Condition::Decl {
                ty,
                name,
                init,
                span,
            } => {
                let list = ast::InitDeclaratorList {
                    ty: ty.clone(),
                    declarators: vec![ast::InitDeclarator {
                        name: name.clone(),
                        array: None,
                        init: Some(init.clone()),
                        span: *span,
                    }],
                    span: *span,
                };
                let stmts = self.declaration(&ast::Declaration::Variables(list));
                let local = stmts.iter().find_map(|s| match s {
                    ir::Stmt::Declare { local, .. } => Some(*local),
                    _ => None,
                });
                out.extend(stmts);
                if let Some(l) = local {
                    let ty = self
                        .cur
                        .as_ref()
                        .and_then(|f| f.locals.get(l.0 as usize))
                        .map_or(Type::ERROR, |l| l.ty);
                    if !ty.is_error() && ty != Type::BOOL {
                        self.error(
                            Code::TypeMismatch,
                            name.span,
                            format!("a loop condition must be bool, found {}", self.tn(ty)),
                        );
                        return;
                    }
                    let v = ir::Expr {
                        kind: ExprKind::Local(l),
                        ty,
                        span: name.span,
                    };
                    out.push(break_unless(v));
                }
            }
        }
    }

    /// A condition: a bool scalar.
    fn condition_expr(&mut self, e: &ast::Expr, what: &str) -> ir::Expr {
        let v = self.rvalue(e);
        if !v.ty.is_error() && v.ty != Type::BOOL {
            self.error(
                Code::TypeMismatch,
                e.span,
                format!(
                    "the condition of `{what}' must be a bool scalar, found {}",
                    self.tn(v.ty)
                ),
            )
            .notes
            .push("use any()/all() to reduce a bool vector".into());
            return super::error_expr(e.span);
        }
        v
    }

    fn return_stmt(&mut self, v: Option<&ast::Expr>, span: Span) -> ir::Stmt {
        let ret = self.cur.as_ref().map_or(Type::VOID, |f| f.ret);
        let value = v.map(|e| self.rvalue(e));
        match value {
            None => {
                if !ret.is_void() && !ret.is_error() {
                    self.error(
                        Code::BadReturn,
                        span,
                        format!(
                            "`return' without a value in a function returning {}",
                            self.tn(ret)
                        ),
                    );
                }
                ir::Stmt::Return(None, span)
            }
            Some(val) => {
                if ret.is_void() {
                    if !val.ty.is_error() {
                        self.error(
                            Code::BadReturn,
                            span,
                            "`return' with a value in a function returning void",
                        );
                    }
                    return ir::Stmt::Return(None, span);
                }
                if val.ty.is_void() {
                    self.error(
                        Code::BadReturn,
                        span,
                        format!(
                            "`return' of a void expression in a function returning {}",
                            self.tn(ret)
                        ),
                    );
                    return ir::Stmt::Return(None, span);
                }
                let what = format!(
                    "cannot return {} from a function returning {}",
                    self.tn(val.ty),
                    self.tn(ret)
                );
                let sp = val.span;
                let before = self.diags.len();
                let val = self.coerce(val, ret, sp, "");
                if self.diags.len() > before {
                    // Replace the generic coerce message with a return-specific one.
                    if let Some(d) = self.diags.last_mut() {
                        d.code = Code::BadReturn;
                        let tail = d
                            .message
                            .split_once(';')
                            .map(|(_, t)| format!(";{t}"))
                            .unwrap_or_default();
                        d.message = format!("{what}{tail}");
                    }
                }
                ir::Stmt::Return(Some(val), span)
            }
        }
    }
}

/// `if (!c) break;`
fn break_unless(c: ir::Expr) -> ir::Stmt {
    let span = c.span;
    let not = ir::Expr {
        kind: ExprKind::Unary {
            op: ir::UnaryOp::Not,
            operand: Box::new(c),
        },
        ty: Type::BOOL,
        span,
    };
    ir::Stmt::If {
        cond: not,
        then: vec![ir::Stmt::Break(span)],
        else_: Vec::new(),
        span,
    }
}
