//! Function prototypes and definitions, calls, overload resolution, and the
//! static recursion check.

use super::scope::{FnRef, Symbol};
use super::{error_expr, Analyzer, FnInfo, FnState};
use crate::ast::{self, FunctionDef, FunctionProto, Qualifier};
use crate::diag::{did_you_mean, Code, Diagnostic};
use crate::ir::{self, ExprKind, FunctionId, LocalId, Param, ParamQualifier};
use crate::lang::Version;
use crate::limits;
use crate::source::Span;
use crate::types::{ArraySize, Type};

/// A callable signature, user or built-in.
struct Sig {
    f: FnRef,
    params: Vec<(Type, ParamQualifier)>,
    ret: Type,
}

impl Analyzer {
    /// Checks a parameter's qualifiers: `[const] [in|out|inout]`.
    fn param_qualifiers(&mut self, p: &ast::ParamDecl) -> (ParamQualifier, bool) {
        let mut q = None;
        let mut is_const = false;
        let mut precision: Option<Span> = None;
        // GL_ARB_shading_language_420pack §4.11: parameter qualifiers in
        // any order, each at most once.
        let any_order = self.lang.allows(crate::lang::Feature::LanguagePack420);
        for sq in &p.qualifiers {
            let misplaced = precision.filter(|_| !any_order && !sq.qualifier.is_precision());
            if let Some(prec) = misplaced {
                // GLSL 1.30 §4.7: the precision qualifier comes last.
                self.error(
                    Code::BadQualifier,
                    prec,
                    format!(
                        "a precision qualifier must come after `{}'",
                        sq.qualifier.as_str()
                    ),
                );
                precision = None;
            }
            match sq.qualifier {
                q if q.is_precision() => {
                    self.precision_qualifier(sq, &mut precision);
                }
                Qualifier::Const => {
                    if is_const {
                        self.error(Code::BadQualifier, sq.span, "`const' given twice");
                    } else if q.is_some() && !any_order {
                        self.error(
                            Code::BadQualifier,
                            sq.span,
                            "`const' must come before `in', `out' or `inout'",
                        )
                        .notes
                        .push(
                            "GL_ARB_shading_language_420pack allows qualifiers in any order".into(),
                        );
                    } else if q.is_some_and(|q| q != ParamQualifier::In) {
                        self.error(
                            Code::BadQualifier,
                            sq.span,
                            "a const parameter cannot be written: `const' with `out' or `inout'",
                        );
                    }
                    is_const = true;
                }
                Qualifier::In | Qualifier::Out | Qualifier::Inout => {
                    if q.is_some() {
                        self.error(
                            Code::BadQualifier,
                            sq.span,
                            "only one of `in', `out', `inout' is allowed",
                        );
                        continue;
                    }
                    q = Some(match sq.qualifier {
                        Qualifier::In => ParamQualifier::In,
                        Qualifier::Out => ParamQualifier::Out,
                        _ => ParamQualifier::InOut,
                    });
                    if is_const && sq.qualifier != Qualifier::In {
                        self.error(
                            Code::BadQualifier,
                            sq.span,
                            format!(
                                "`const {}': a const parameter cannot be written",
                                sq.qualifier.as_str()
                            ),
                        )
                        .notes
                        .push("use `const in', or drop `const'".into());
                    }
                }
                other => {
                    self.error(
                        Code::BadQualifier,
                        sq.span,
                        format!("`{}' is not allowed on function parameters", other.as_str()),
                    );
                }
            }
        }
        (q.unwrap_or(ParamQualifier::In), is_const)
    }

    /// The parameters and return type of a prototype, checked.
    fn signature(&mut self, p: &FunctionProto) -> (Vec<Param>, Type) {
        let mut precision = None;
        for sq in &p.return_type.qualifiers {
            if sq.qualifier.is_precision() {
                self.precision_qualifier(sq, &mut precision);
            } else if !(self.builtin_mode && sq.qualifier == Qualifier::Const) {
                self.error(
                    Code::BadQualifier,
                    sq.span,
                    format!(
                        "`{}' is not allowed on a return type",
                        sq.qualifier.as_str()
                    ),
                );
            }
        }
        let ret = self.resolve_type(&p.return_type.ty);
        if !ret.is_error() {
            if self.contains_sampler(ret) {
                self.error(
                    Code::TypeMismatch,
                    p.return_type.span,
                    "functions cannot return samplers",
                );
            } else if ret.array == Some(ArraySize::Unsized) {
                self.error(
                    Code::BadArraySize,
                    p.return_type.span,
                    "a returned array must have a size",
                );
            }
        }
        let mut params = Vec::new();
        for (i, pd) in p.params.iter().enumerate() {
            let (qualifier, is_const) = self.param_qualifiers(pd);
            let base = self.resolve_type(&pd.ty);
            let ty = self.apply_array(base, pd.array.as_ref());
            if !ty.is_error() {
                if ty.base == crate::types::Base::Void {
                    self.error(Code::TypeMismatch, pd.span, "parameters cannot be void");
                } else if ty.array == Some(ArraySize::Unsized) {
                    self.error(
                        Code::BadArraySize,
                        pd.span,
                        "array parameters must have a size",
                    );
                } else if qualifier != ParamQualifier::In && self.contains_sampler(ty) {
                    self.error(
                        Code::BadQualifier,
                        pd.span,
                        "samplers can only be `in' parameters",
                    );
                } else if qualifier != ParamQualifier::In
                    && ty.is_array()
                    && self.lang.version < Version::V120
                {
                    self.error(
                        Code::VersionTooLow,
                        pd.span,
                        "arrays cannot be `out' or `inout' parameters in GLSL 1.10 (arrays are not assignable)",
                    )
                    .notes
                    .push("use `#version 120'".into());
                }
            }
            if let Some(n) = &pd.name {
                self.check_reserved_name(&n.name, n.span);
            }
            params.push(Param {
                name: pd.name.as_ref().map(|n| n.name.to_string()),
                ty,
                qualifier,
                is_const,
                local: LocalId(i as u32),
            });
        }
        (params, ret)
    }

    /// Declares (or finds the earlier declaration of) a function; checks that
    /// declarations agree (GLSL 1.20 §6.1).
    pub fn function_proto(&mut self, p: &FunctionProto, is_def: bool) -> Option<FunctionId> {
        let (params, ret) = self.signature(p);
        let name = &p.name.name;
        if !self.builtin_mode {
            self.check_reserved_name(name, p.name.span);
        }
        if name == "main" && (!params.is_empty() || !ret.is_void()) && !ret.is_error() {
            self.error(
                Code::TypeMismatch,
                p.name.span,
                "`main' must be declared `void main()'",
            );
        }
        let existing: Vec<FunctionId> = match self.scopes.lookup_current(name) {
            None => Vec::new(),
            Some(Symbol::Funcs(v)) => v
                .iter()
                .filter_map(|f| match f {
                    FnRef::User(id) => Some(*id),
                    FnRef::Builtin(_) => None,
                })
                .collect(),
            Some(_) => {
                self.error(
                    Code::Redeclared,
                    p.name.span,
                    format!("`{name}' is already declared as a variable or type"),
                );
                return None;
            }
        };
        for id in existing {
            let f = &self.module.functions[id.0 as usize];
            let same = f.params.len() == params.len()
                && f.params.iter().zip(&params).all(|(a, b)| a.ty == b.ty);
            if !same {
                continue;
            }
            if f.return_type != ret && !ret.is_error() && !f.return_type.is_error() {
                let prev = self.tn(f.return_type);
                let span = f.span;
                self.push(
                    Diagnostic::error(
                        Code::Redeclared,
                        p.name.span,
                        format!(
                            "`{name}' redeclared with return type {}, earlier {prev}",
                            self.tn(ret)
                        ),
                    )
                    .with_label(span, "earlier declaration")
                    .with_note("functions cannot be overloaded by return type alone"),
                );
                return None;
            }
            let f = &self.module.functions[id.0 as usize];
            let quals_differ = f
                .params
                .iter()
                .zip(&params)
                .any(|(a, b)| a.qualifier != b.qualifier || a.is_const != b.is_const);
            if quals_differ {
                let span = f.span;
                self.push(
                    Diagnostic::error(
                        Code::Redeclared,
                        p.name.span,
                        format!("`{name}' redeclared with different parameter qualifiers"),
                    )
                    .with_label(span, "earlier declaration"),
                );
                return None;
            }
            if is_def {
                if self.fns[id.0 as usize].defined {
                    let span = self.module.functions[id.0 as usize].span;
                    self.push(
                        Diagnostic::error(
                            Code::Redeclared,
                            p.name.span,
                            format!("`{name}' is already defined"),
                        )
                        .with_label(span, "first definition"),
                    );
                    return None;
                }
                let f = &mut self.module.functions[id.0 as usize];
                f.params = params;
                f.span = p.name.span;
            }
            return Some(id);
        }
        let id = FunctionId(self.module.functions.len() as u32);
        // A prototype's parameters are locals too (the IR contract wants
        // every parameter to have one); a definition rebuilds them.
        let p_span = p.name.span;
        let locals = params
            .iter()
            .map(|p| ir::Local {
                name: p.name.clone().unwrap_or_default(),
                ty: p.ty,
                is_const: p.is_const,
                span: p_span,
            })
            .collect();
        self.module.functions.push(ir::Function {
            name: name.to_string(),
            params,
            return_type: ret,
            locals,
            body: None,
            span: p.name.span,
        });
        self.fns.push(FnInfo::default());
        self.scopes.add_function(name, FnRef::User(id));
        Some(id)
    }

    pub fn function_def(&mut self, def: &FunctionDef) {
        let id = self.function_proto(&def.proto, true);
        let (params, ret) = match id {
            Some(id) => {
                let f = &self.module.functions[id.0 as usize];
                (f.params.clone(), f.return_type)
            }
            None => self.signature(&def.proto),
        };
        self.cur = Some(FnState {
            id: id.unwrap_or(FunctionId(u32::MAX)),
            ret,
            locals: Vec::new(),
            consts: Vec::new(),
            implicit: Vec::new(),
            loop_depth: 0,
            switch_depth: 0,
            if_depth: 0,
            returned: false,
        });
        self.scopes.push();
        let mut params_out = Vec::with_capacity(params.len());
        for mut p in params {
            let span = def.proto.span;
            let name = p.name.clone().unwrap_or_default();
            p.local = self.new_local(&name, p.ty, p.is_const, span);
            if !name.is_empty() {
                if self.scopes.lookup_current(&name).is_some() {
                    self.error(
                        Code::Redeclared,
                        span,
                        format!("parameter `{name}' declared twice"),
                    );
                } else {
                    self.scopes.insert(
                        name.as_str().into(),
                        Symbol::Var(super::scope::Var::Local(p.local)),
                    );
                }
            }
            params_out.push(p);
        }
        let body = self.block_stmts(&def.body.stmts);
        self.scopes.pop();
        let state = self.cur.take();
        if let (Some(id), Some(state)) = (id, state) {
            self.fns[id.0 as usize].defined = true;
            let f = &mut self.module.functions[id.0 as usize];
            f.params = params_out;
            f.locals = state.locals;
            f.body = Some(body);
        }
    }

    /// The candidate signatures a call name resolves to, or `None` after
    /// reporting why there are none.
    fn candidates(&mut self, name: &ast::Ident) -> Option<Vec<Sig>> {
        let refs = match self.lookup(&name.name) {
            Some(Symbol::Funcs(v)) => v,
            Some(Symbol::Var(_)) => {
                self.error(
                    Code::TypeMismatch,
                    name.span,
                    format!("`{}' is a variable, not a function", name.name),
                );
                return None;
            }
            Some(Symbol::Struct(_)) => return Some(Vec::new()),
            None => {
                self.undeclared(name, true);
                return None;
            }
        };
        let mut sigs = Vec::new();
        for f in refs {
            match f {
                FnRef::User(id) => {
                    let func = &self.module.functions[id.0 as usize];
                    sigs.push(Sig {
                        f,
                        params: func.params.iter().map(|p| (p.ty, p.qualifier)).collect(),
                        ret: func.return_type,
                    });
                }
                FnRef::Builtin(i) => {
                    if let Some(b) = self.env.and_then(|e| e.functions.get(i as usize)) {
                        sigs.push(Sig {
                            f,
                            params: b.params.clone(),
                            ret: b.ret,
                        });
                    }
                }
            }
        }
        Some(sigs)
    }

    /// Reports an undeclared name with suggestions.
    pub fn undeclared(&mut self, name: &ast::Ident, function: bool) {
        let what = if function { "function " } else { "" };
        if !function && self.hidden_builtins.contains(&name.name) {
            self.error(
                Code::Undeclared,
                name.span,
                format!(
                    "`{}' undeclared: the redeclared `gl_PerVertex' block leaves it out",
                    name.name
                ),
            )
            .notes
            .push(format!(
                "add `{}' to the `gl_PerVertex' redeclaration to use it",
                name.name
            ));
            return;
        }
        if let Some((code, note)) = self.availability_note(&name.name) {
            self.error(code, name.span, format!("{what}`{}' undeclared", name.name))
                .notes
                .push(note);
            return;
        }
        if function {
            // GLSL 1.20 §6.1: a function must be declared before it is
            // called; a definition further down does not count.
            let later = self
                .declared_functions
                .iter()
                .find(|(n, s)| *n == name.name && s.start > name.span.start)
                .map(|(_, s)| *s);
            if let Some(later) = later {
                let d = self.error(
                    Code::Undeclared,
                    name.span,
                    format!("function `{}' is called before it is declared", name.name),
                );
                d.labels.push(crate::diag::Label {
                    span: later,
                    message: "declared here, after the call".into(),
                });
                d.notes.push(format!(
                    "GLSL requires a declaration before a call: move the function up, or add its prototype (`... {}(...);') above the first call",
                    name.name
                ));
                return;
            }
        }
        let sugg = if self.may_suggest(&name.name) {
            let names = self.visible_names();
            did_you_mean(&name.name, names.iter().map(|s| s.as_str())).map(str::to_string)
        } else {
            None
        };
        let d = self.error(
            Code::Undeclared,
            name.span,
            format!("{what}`{}' undeclared", name.name),
        );
        if let Some(s) = sugg {
            d.notes.push(format!("did you mean `{s}'?"));
        } else if function {
            d.notes.push(format!(
                "declare it before the call; if another shader object defines it, a prototype is enough: `... {}(...);'",
                name.name
            ));
        }
    }

    /// A function call `name(args)` (GLSL 1.20 §6.1 overload resolution).
    pub fn call(&mut self, name: &ast::Ident, args: &[ast::Expr], span: Span) -> ir::Expr {
        if name.name == "debugPrintfEXT" && self.printf_enabled() {
            return self.debug_printf(args, span);
        }
        if let Some(Symbol::Struct(id)) = self.lookup(&name.name) {
            let ty = Type::new(crate::types::Base::Struct(id));
            return self.construct(ty, args, span);
        }
        let sigs = self.candidates(name);
        let vals: Vec<ir::Expr> = args.iter().map(|a| self.rvalue(a)).collect();
        let Some(sigs) = sigs else {
            return error_expr(span);
        };
        if vals.iter().any(|v| v.ty.is_error()) {
            return error_expr(span);
        }
        let arg_tys: Vec<Type> = vals.iter().map(|v| v.ty).collect();
        let mut exact = Vec::new();
        let mut convertible = Vec::new();
        for (i, s) in sigs.iter().enumerate() {
            match self.match_sig(s, &arg_tys) {
                Some(true) => exact.push(i),
                Some(false) => convertible.push(i),
                None => {}
            }
        }
        let chosen = if let Some(&i) = exact.first() {
            i
        } else if convertible.len() == 1 {
            convertible[0]
        } else if convertible.len() > 1 {
            let mut d = Diagnostic::error(
                Code::AmbiguousOverload,
                name.span,
                format!("call to `{}' is ambiguous", name.name),
            );
            for &i in &convertible {
                d.notes.push(format!(
                    "candidate: {}",
                    self.sig_string(&name.name, &sigs[i])
                ));
            }
            self.push(d.with_note("convert the arguments explicitly (e.g. `float(i)')"));
            return error_expr(span);
        } else {
            let found: Vec<String> = arg_tys.iter().map(|t| self.tn(*t)).collect();
            let mut d = Diagnostic::error(
                Code::NoMatchingOverload,
                name.span,
                format!(
                    "no matching overload for `{}({})'",
                    name.name,
                    found.join(", ")
                ),
            );
            for s in sigs.iter().take(16) {
                d.notes
                    .push(format!("candidate: {}", self.sig_string(&name.name, s)));
            }
            if self.lang.version < Version::V120
                && sigs.iter().any(|s| self.match_sig_120(s, &arg_tys))
            {
                d.notes.push("GLSL 1.10 has no implicit int→float conversions: write float literals (`1.0'), or use `#version 120'".into());
            }
            self.push(d);
            return error_expr(span);
        };
        let sig = &sigs[chosen];
        let mut out_args = Vec::with_capacity(vals.len());
        // Out arguments converted on the way back (GLSL 1.20: an `out int'
        // parameter may write a float variable) go through a temporary.
        let mut copy_back = Vec::new();
        // Dynamic indices of those targets, evaluated before the call.
        let mut hoisted = Vec::new();
        for (k, v) in vals.into_iter().enumerate() {
            let (pty, q) = sig.params[k];
            match q {
                ParamQualifier::In => out_args.push(self.convert(v, pty)),
                ParamQualifier::Out | ParamQualifier::InOut => {
                    let lv = self.lvalue(
                        &args[k],
                        q == ParamQualifier::InOut,
                        "pass as an `out' argument",
                    );
                    if lv.ty != pty && !lv.ty.is_error() && self.cur.is_some() {
                        let t = self.new_local("<out temporary>", pty, false, lv.span);
                        out_args.push(ir::Expr {
                            kind: ExprKind::Local(t),
                            ty: pty,
                            span: lv.span,
                        });
                        let mut lv = lv;
                        self.hoist_indices(&mut lv, &mut hoisted);
                        copy_back.push((lv, t, pty));
                    } else {
                        out_args.push(lv);
                    }
                }
            }
        }
        let ret = sig.ret;
        let kind = match sig.f {
            FnRef::User(id) => {
                if let Some(cur) = &self.cur {
                    let caller = cur.id;
                    if let Some(info) = self.fns.get_mut(caller.0 as usize) {
                        info.callees.push(id);
                        info.call_spans.push(name.span);
                    }
                }
                ExprKind::Call {
                    function: id,
                    args: out_args,
                }
            }
            FnRef::Builtin(i) => {
                let function = self
                    .env
                    .and_then(|e| e.functions.get(i as usize))
                    .map(|b| b.function);
                match function {
                    Some(function) => {
                        self.check_texel_offset(function, &out_args);
                        self.check_atomic_memory(function, &out_args);
                        if function == crate::builtin_fn::BuiltinFn::Barrier {
                            self.check_barrier_placement(span);
                        }
                        ExprKind::Builtin {
                            function,
                            args: out_args,
                        }
                    }
                    None => return error_expr(span),
                }
            }
        };
        let e = ir::Expr {
            kind,
            ty: ret,
            span,
        };
        if matches!(e.kind, ExprKind::Builtin { .. }) {
            return self.fold(e);
        }
        if copy_back.is_empty() {
            return e;
        }
        let seq = self.copy_back(e, copy_back);
        hoisted.into_iter().rev().fold(seq, |seq, pre| {
            let (ty, span) = (seq.ty, seq.span);
            ir::Expr {
                kind: ExprKind::Comma {
                    left: Box::new(pre),
                    right: Box::new(seq),
                },
                ty,
                span,
            }
        })
    }

    /// GLSL 1.30 §8.7: "The offset value must be a constant expression"
    /// (the `offset` of the `*Offset` lookups: the third argument of
    /// `textureOffset` and `textureProjOffset`, which a `bias` may follow,
    /// the last of the others).
    fn check_texel_offset(&mut self, f: crate::builtin_fn::BuiltinFn, args: &[ir::Expr]) {
        use crate::builtin_fn::BuiltinFn as B;
        let at = match f {
            B::TextureOffset | B::TextureProjOffset => 2,
            B::TexelFetchOffset
            | B::TextureLodOffset
            | B::TextureProjLodOffset
            | B::TextureGradOffset
            | B::TextureProjGradOffset => args.len().saturating_sub(1),
            _ => return,
        };
        if let Some(a) = args.get(at) {
            if !matches!(a.kind, ExprKind::Const(_)) && !a.ty.is_error() {
                self.error(
                    Code::NotConstant,
                    a.span,
                    format!("the offset of `{}' must be a constant expression", f.name()),
                );
            }
        }
    }

    /// The memory an atomic function updates (GLSL 4.30 §8.11) is a
    /// `shared` variable or a part of one.
    fn check_atomic_memory(&mut self, f: crate::builtin_fn::BuiltinFn, args: &[ir::Expr]) {
        if !f.is_atomic() {
            return;
        }
        let Some(mem) = args.first().filter(|a| !a.ty.is_error()) else {
            return;
        };
        let mut root = mem;
        while let ExprKind::Index { base, .. }
        | ExprKind::Member { base, .. }
        | ExprKind::Swizzle { base, .. } = &root.kind
        {
            root = base;
        }
        let shared =
            match root.kind {
                ExprKind::Global(g) => self.module.globals.get(g.0 as usize).is_some_and(|g| {
                    matches!(g.storage, ir::Storage::Shared | ir::Storage::Buffer)
                }),
                _ => false,
            };
        if !shared {
            self.error(
                Code::TypeMismatch,
                mem.span,
                format!(
                    "the first argument of `{}' must be a `shared' or buffer variable (or an element or member of one)",
                    f.name()
                ),
            )
            .notes
            .push("atomic functions update memory the invocations share; a local or global of one invocation has nothing to be atomic about".into());
        }
    }

    /// Replaces every non-constant index inside the l-value `lv` by a new
    /// local, pushing `local = index` to `pre`: an out argument's l-value is
    /// evaluated at the call (§6.1.1), even when the converted value is
    /// copied into it after the call returns.
    fn hoist_indices(&mut self, lv: &mut ir::Expr, pre: &mut Vec<ir::Expr>) {
        match &mut lv.kind {
            ExprKind::Index { base, index } => {
                self.hoist_indices(base, pre);
                if !matches!(index.kind, ExprKind::Const(_)) && !index.ty.is_error() {
                    let (ty, span) = (index.ty, index.span);
                    let t = self.new_local("<out index>", ty, false, span);
                    let local = ir::Expr {
                        kind: ExprKind::Local(t),
                        ty,
                        span,
                    };
                    let value = std::mem::replace(&mut **index, local.clone());
                    pre.push(ir::Expr {
                        kind: ExprKind::Assign {
                            op: None,
                            target: Box::new(local),
                            value: Box::new(value),
                        },
                        ty,
                        span,
                    });
                }
            }
            ExprKind::Member { base, .. } | ExprKind::Swizzle { base, .. } => {
                self.hoist_indices(base, pre)
            }
            _ => {}
        }
    }

    /// `(r = f(t), x = float(t), r)`: the call, then the converted copies of
    /// the out temporaries into their real targets, then the result.
    fn copy_back(&mut self, call: ir::Expr, copies: Vec<(ir::Expr, LocalId, Type)>) -> ir::Expr {
        let span = call.span;
        let ret = call.ty;
        let local = |l: LocalId, ty: Type| ir::Expr {
            kind: ExprKind::Local(l),
            ty,
            span,
        };
        let result = (!ret.is_void()).then(|| self.new_local("<call result>", ret, false, span));
        let mut seq = match result {
            Some(r) => ir::Expr {
                kind: ExprKind::Assign {
                    op: None,
                    target: Box::new(local(r, ret)),
                    value: Box::new(call),
                },
                ty: ret,
                span,
            },
            None => call,
        };
        for (target, t, pty) in copies {
            let ty = target.ty;
            let value = self.convert(local(t, pty), ty);
            let assign = ir::Expr {
                kind: ExprKind::Assign {
                    op: None,
                    target: Box::new(target),
                    value: Box::new(value),
                },
                ty,
                span,
            };
            seq = ir::Expr {
                kind: ExprKind::Comma {
                    left: Box::new(seq),
                    right: Box::new(assign),
                },
                ty,
                span,
            };
        }
        if let Some(r) = result {
            seq = ir::Expr {
                kind: ExprKind::Comma {
                    left: Box::new(seq),
                    right: Box::new(local(r, ret)),
                },
                ty: ret,
                span,
            };
        }
        seq
    }

    /// `Some(true)` for an exact match, `Some(false)` for a match with
    /// implicit conversions (GLSL 1.20 §6.1), `None` for no match.
    fn match_sig(&self, s: &Sig, args: &[Type]) -> Option<bool> {
        if s.params.len() != args.len() {
            return None;
        }
        let mut exact = true;
        for (&(p, q), &a) in s.params.iter().zip(args) {
            if p == a {
                continue;
            }
            exact = false;
            let ok = self.lang.version >= Version::V120
                && match q {
                    ParamQualifier::In => super::expr::implicitly_converts(a, p),
                    ParamQualifier::Out => super::expr::implicitly_converts(p, a),
                    ParamQualifier::InOut => false,
                };
            if !ok {
                return None;
            }
        }
        Some(exact)
    }

    fn match_sig_120(&self, s: &Sig, args: &[Type]) -> bool {
        s.params.len() == args.len()
            && s.params.iter().zip(args).all(|(&(p, q), &a)| {
                p == a || (q == ParamQualifier::In && super::expr::implicitly_converts(a, p))
            })
    }

    fn sig_string(&self, name: &str, s: &Sig) -> String {
        let params: Vec<String> = s
            .params
            .iter()
            .map(|(t, q)| {
                let q = match q {
                    ParamQualifier::In => "",
                    ParamQualifier::Out => "out ",
                    ParamQualifier::InOut => "inout ",
                };
                format!("{q}{}", self.tn(*t))
            })
            .collect();
        format!("{} {name}({})", self.tn(s.ret), params.join(", "))
    }

    /// Static recursion is an error (GLSL 1.20 §6.1; undefined in 1.10, and
    /// not supported here either). So is a chain of calls deeper than
    /// [`limits::MAX_CALL_DEPTH`] functions (reported once, at the call
    /// that passes the limit).
    pub fn check_recursion(&mut self) {
        let n = self.fns.len();
        // 0 = unvisited, 1 = on stack, 2 = done. Iterative DFS.
        let mut state = vec![0u8; n];
        let mut reported = vec![false; n];
        // Functions on the stack in the deepest chain each one starts
        // (itself included), filled in post-order; a callee still on the
        // stack (recursion, reported above) counts as 0.
        let mut depth = vec![0u32; n];
        let mut too_deep = false;
        for root in 0..n {
            if state[root] != 0 {
                continue;
            }
            let mut stack: Vec<(usize, usize)> = vec![(root, 0)];
            state[root] = 1;
            while let Some(&mut (f, ref mut next)) = stack.last_mut() {
                let callees = &self.fns[f].callees;
                if *next < callees.len() {
                    let c = callees[*next].0 as usize;
                    let span = self.fns[f].call_spans[*next];
                    *next += 1;
                    if c >= n {
                        continue;
                    }
                    match state[c] {
                        0 => {
                            state[c] = 1;
                            stack.push((c, 0));
                        }
                        1 if !reported[c] => {
                            reported[c] = true;
                            let name = self.module.functions[c].name.clone();
                            self.error(
                                Code::BadControlFlow,
                                span,
                                format!("recursive call to `{name}': recursion is not allowed"),
                            )
                            .notes
                            .push("GLSL 1.20 §6.1: the static call graph must have no cycles; use a loop".into());
                        }
                        _ => {}
                    }
                } else {
                    state[f] = 2;
                    let callees = &self.fns[f].callees;
                    let deepest = (0..callees.len())
                        .filter_map(|i| {
                            let c = callees[i].0 as usize;
                            depth.get(c).map(|&d| (d, i))
                        })
                        .max_by_key(|&(d, i)| (d, std::cmp::Reverse(i)));
                    depth[f] = 1 + deepest.map_or(0, |(d, _)| d);
                    if depth[f] > limits::MAX_CALL_DEPTH && !too_deep {
                        too_deep = true;
                        let (_, i) = deepest.unwrap_or((0, 0));
                        let func = &self.module.functions[f];
                        let span = self.fns[f].call_spans.get(i).copied().unwrap_or(func.span);
                        let name = func.name.clone();
                        self.error(
                            Code::BadControlFlow,
                            span,
                            format!(
                                "function calls nested too deeply: `{name}' starts a chain of {} \
                                 nested calls; the limit is {}",
                                depth[f],
                                limits::MAX_CALL_DEPTH
                            ),
                        )
                        .notes
                        .push(format!(
                            "at most {} functions may be on the call stack at once, `main' included",
                            limits::MAX_CALL_DEPTH
                        ));
                    }
                    stack.pop();
                }
            }
        }
    }

    /// Whether the shader's `#extension` directives leave the printf
    /// extension enabled (see `pp::PRINTF_EXTENSION`).
    fn printf_enabled(&self) -> bool {
        self.lang.has(crate::lang::Extension::ShaderboxDebugPrintf)
    }

    /// `debugPrintfEXT("format", args...)`: the format is a string literal
    /// whose conversions take the arguments in order (`crate::printf`).
    fn debug_printf(&mut self, args: &[ast::Expr], span: Span) -> ir::Expr {
        let void = ir::Expr {
            kind: ir::ExprKind::Const(ir::ConstValue {
                ty: Type::VOID,
                components: Vec::new(),
            }),
            ty: Type::VOID,
            span,
        };
        let Some((first, rest)) = args.split_first() else {
            self.error(
                Code::NoMatchingOverload,
                span,
                "`debugPrintfEXT' needs a format string as its first argument",
            )
            .notes
            .push("for example `debugPrintfEXT(\"x = %f\\n\", x);'".into());
            return error_expr(span);
        };
        let ast::ExprKind::StringLit(text) = &first.kind else {
            self.error(
                Code::TypeMismatch,
                first.span,
                "the first argument of `debugPrintfEXT' must be a string literal",
            );
            return error_expr(span);
        };
        let format = match crate::printf::parse(text) {
            Ok(f) => f,
            Err(why) => {
                self.error(
                    Code::TypeMismatch,
                    first.span,
                    format!("bad format string: {why}"),
                );
                return error_expr(span);
            }
        };
        let vals: Vec<ir::Expr> = rest.iter().map(|a| self.rvalue(a)).collect();
        let convs: Vec<crate::printf::Conversion> =
            crate::printf::conversions(&format).copied().collect();
        if convs.len() != vals.len() {
            self.error(
                Code::NoMatchingOverload,
                span,
                format!(
                    "the format of `debugPrintfEXT' has {} conversion{} but {} value{} follow{}",
                    convs.len(),
                    if convs.len() == 1 { "" } else { "s" },
                    vals.len(),
                    if vals.len() == 1 { "" } else { "s" },
                    if vals.len() == 1 { "s" } else { "" },
                ),
            );
            return error_expr(span);
        }
        let mut ok = true;
        for (c, v) in convs.iter().zip(&vals) {
            if v.ty.is_error() {
                ok = false;
            } else if !c.accepts(v.ty) {
                let found = self.tn(v.ty);
                self.error(
                    Code::TypeMismatch,
                    v.span,
                    format!(
                        "`%{}{}' prints {}, but this argument is {}",
                        if c.components > 1 {
                            format!("v{}", c.components)
                        } else {
                            String::new()
                        },
                        c.kind,
                        crate::diag::with_article(&c.expected()),
                        crate::diag::with_article(&found)
                    ),
                )
                .notes
                .push(
                    if v.ty.scalar() == Some(crate::types::Scalar::Uint) && !c.is_float() {
                        // A uint given to %d: its own conversion prints it.
                        match c.components {
                            1 => "print a uint with `%u' (or convert it: `int(u)')".to_string(),
                            n => format!(
                                "print a uvec{n} with `%v{n}u' (or convert it: `ivec{n}(u)')"
                            ),
                        }
                    } else {
                        "convert it (e.g. `float(i)') or change the conversion".into()
                    },
                );
                ok = false;
            }
        }
        if !ok {
            return error_expr(span);
        }
        ir::Expr {
            kind: ir::ExprKind::DebugPrintf { format, args: vals },
            ..void
        }
    }
}
