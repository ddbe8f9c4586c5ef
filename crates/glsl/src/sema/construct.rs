//! Constructors (GLSL 1.20 §5.4): `T(args)` for scalars, vectors,
//! matrices, structs and arrays, with the argument checks of §5.4.1-5.4.3.

use super::expr::mk;
use super::{error_expr, Analyzer};
use crate::ast;
use crate::diag::Code;
use crate::ir::{self, ExprKind as K};
use crate::lang::Version;
use crate::source::Span;
use crate::types::{ArraySize, Base, Type};

impl Analyzer {
    /// A constructor call `T(args)` (GLSL 1.20 §5.4).
    pub fn construct(&mut self, ty: Type, args: &[ast::Expr], span: Span) -> ir::Expr {
        let vals: Vec<ir::Expr> = args.iter().map(|a| self.rvalue(a)).collect();
        if ty.is_error() || vals.iter().any(|v| v.ty.is_error()) {
            return error_expr(span);
        }
        let tn = self.tn(ty);
        if vals.is_empty() {
            self.error(
                Code::BadConstructor,
                span,
                format!("constructor `{tn}' needs arguments"),
            );
            return error_expr(span);
        }
        let mut ty = ty;
        let args_out = if ty.is_array() {
            let et = ty.element();
            if let Some(ArraySize::Sized(n)) = ty.array {
                if n as usize != vals.len() {
                    self.error(
                        Code::BadConstructor,
                        span,
                        format!(
                            "array constructor `{tn}' has {} arguments, expected {n}",
                            vals.len()
                        ),
                    );
                    return error_expr(span);
                }
            } else {
                ty = et.array_of(ArraySize::Sized(vals.len() as u32));
            }
            let what = format!("cannot construct an element of {}", self.tn(ty));
            // The elements of an array of arrays are rows: each argument
            // is the row's array, wrapped in its row struct.
            let row = self.array_row_member(et);
            let mut out = Vec::new();
            for v in vals {
                let sp = v.span;
                let c = self.coerce(v, row.unwrap_or(et), sp, &what);
                if c.ty.is_error() {
                    return error_expr(span);
                }
                out.push(match row {
                    Some(_) => self.fold(mk(K::Construct { args: vec![c] }, et, sp)),
                    None => c,
                });
            }
            out
        } else if let Base::Struct(id) = ty.base {
            let members = self.struct_members(id);
            if members.len() != vals.len() {
                self.error(
                    Code::BadConstructor,
                    span,
                    format!(
                        "constructor `{tn}' has {} arguments, expected {} (one per member)",
                        vals.len(),
                        members.len()
                    ),
                );
                return error_expr(span);
            }
            let mut out = Vec::new();
            for (v, m) in vals.into_iter().zip(&members) {
                let sp = v.span;
                let what = format!(
                    "cannot initialize member `{}' of type {}",
                    m.name,
                    self.tn(m.ty)
                );
                let c = self.coerce(v, m.ty, sp, &what);
                if c.ty.is_error() {
                    return error_expr(span);
                }
                out.push(c);
            }
            out
        } else {
            match self.check_basic_ctor(ty, &vals, span) {
                true => vals,
                false => return error_expr(span),
            }
        };
        self.fold(mk(K::Construct { args: args_out }, ty, span))
    }

    /// An initializer (GLSL 4.20 §4.1.11, GL_ARB_shading_language_420pack)
    /// for a variable of type `ty`: an expression, converted as an
    /// assignment would be, or a brace-enclosed list that must match the
    /// aggregate exactly, one initializer per vector component, matrix
    /// column, array element or struct member, each applied in turn (a
    /// nested list to the element it initializes). An unsized array takes
    /// its size from the list. The result is the constructor the list
    /// stands for, folded when every initializer is constant.
    pub(super) fn initializer(&mut self, ty: Type, init: &ast::Expr, what: &str) -> ir::Expr {
        let span = init.span;
        let ast::ExprKind::InitList(items) = &init.kind else {
            let v = self.rvalue(init);
            let ty = match ty.array {
                Some(ArraySize::Unsized) if v.ty.is_array() && v.ty.base == ty.base => v.ty,
                _ => ty,
            };
            return self.coerce(v, ty, span, what);
        };
        if !self.require(
            crate::lang::Feature::LanguagePack420,
            "an initializer list `{...}'",
            span,
        ) || ty.is_error()
        {
            return error_expr(span);
        }
        let tn = self.tn(ty);
        let mut ty = ty;
        // The type each initializer of the list initializes (with a struct
        // member's name), what one is called, and how the value is
        // wrapped (the row struct of an array of arrays).
        let (parts, unit, row_of) = if ty.is_array() {
            let et = ty.element();
            let n = match ty.array {
                Some(ArraySize::Sized(n)) => n as usize,
                _ => {
                    ty = et.array_of(ArraySize::Sized(items.len() as u32));
                    items.len()
                }
            };
            let row = self.array_row_member(et);
            (
                vec![(row.unwrap_or(et), None); n],
                "element",
                row.map(|_| et),
            )
        } else {
            match ty.base {
                Base::Vector(s, n) => {
                    (vec![(Type::vec(s, 1), None); n as usize], "component", None)
                }
                Base::Matrix { cols, rows } => (
                    vec![(Type::vec(crate::types::Scalar::Float, rows), None); cols as usize],
                    "column",
                    None,
                ),
                Base::Struct(id) => (
                    self.struct_members(id)
                        .into_iter()
                        .map(|m| (m.ty, Some(m.name)))
                        .collect(),
                    "member",
                    None,
                ),
                _ => {
                    self.error(
                            Code::BadConstructor,
                            span,
                            format!("an initializer list needs a vector, matrix, array or struct; `{tn}' is none"),
                        )
                        .notes
                        .push("initialize it with an expression".into());
                    return error_expr(span);
                }
            }
        };
        if parts.len() != items.len() {
            self.error(
                Code::BadConstructor,
                span,
                format!(
                    "the initializer list of `{tn}' has {} initializers, expected {} (one per {unit})",
                    items.len(),
                    parts.len()
                ),
            )
            .notes
            .push("an initializer list must initialize every part of its aggregate exactly once".into());
            return error_expr(span);
        }
        let mut args = Vec::new();
        for ((part, member), item) in parts.iter().zip(items) {
            let which = match member {
                Some(name) => format!("member `{name}'"),
                None => unit.to_string(),
            };
            let what = format!(
                "cannot initialize {which} of {tn} (type {})",
                self.tn(*part)
            );
            let v = self.initializer(*part, item, &what);
            if v.ty.is_error() {
                return error_expr(span);
            }
            args.push(match row_of {
                Some(et) => self.fold(mk(K::Construct { args: vec![v] }, et, item.span)),
                None => v,
            });
        }
        self.fold(mk(K::Construct { args }, ty, span))
    }

    /// Argument checks of scalar, vector and matrix constructors.
    pub(super) fn check_basic_ctor(&mut self, ty: Type, vals: &[ir::Expr], span: Span) -> bool {
        let tn = self.tn(ty);
        let Some(need) = ty.component_count() else {
            self.error(
                Code::BadConstructor,
                span,
                format!("there is no constructor for type {tn}"),
            );
            return false;
        };
        for v in vals {
            if v.ty.component_count().is_none() {
                self.error(
                    Code::BadConstructor,
                    v.span,
                    format!(
                        "constructor `{tn}' cannot take an argument of type {}",
                        self.tn(v.ty)
                    ),
                );
                return false;
            }
        }
        let first = vals[0].ty;
        if ty.is_matrix() {
            if let Some(m) = vals.iter().find(|v| v.ty.is_matrix()) {
                if self.lang.version < Version::V120 {
                    self.error(
                        Code::VersionTooLow,
                        m.span,
                        "constructing a matrix from a matrix requires GLSL 1.20",
                    );
                    return false;
                }
                if vals.len() > 1 {
                    self.error(
                        Code::BadConstructor,
                        m.span,
                        format!("a matrix argument of `{tn}' must be its only argument"),
                    );
                    return false;
                }
                return true;
            }
        }
        if vals.len() == 1 && (first.is_scalar() || ty.is_scalar()) {
            return true;
        }
        let mut left = need;
        for v in vals {
            if left == 0 {
                self.error(
                    Code::BadConstructor,
                    v.span,
                    format!("too many arguments to constructor `{tn}'; it needs {need} components"),
                );
                return false;
            }
            left = left.saturating_sub(v.ty.component_count().unwrap_or(1));
        }
        if left > 0 {
            self.error(
                Code::BadConstructor,
                span,
                format!(
                    "not enough components for constructor `{tn}': it needs {need}, {} given",
                    need - left
                ),
            );
            return false;
        }
        true
    }
}
