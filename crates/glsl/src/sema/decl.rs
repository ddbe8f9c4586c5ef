//! Variable declarations, storage qualifiers and `invariant` redeclarations.

use super::scope::{Symbol, Var};
use super::Analyzer;
use crate::ast::{Declaration, InitDeclarator, InitDeclaratorList, Qualifier, SpannedQualifier};
use crate::diag::{Code, Diagnostic};
use crate::ir::{self, ExprKind, Global, Stage, Storage};
use crate::lang::Version;
use crate::limits::MAX_TEXTURE_COORDS;
use crate::source::Span;
use crate::types::{ArraySize, Base, Type};

/// The qualifiers of a variable declaration, checked.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct VarQuals {
    pub storage: Option<Qualifier>,
    pub invariant: bool,
    pub centroid: bool,
}

impl Analyzer {
    /// Analyzes a declaration; at function scope returns the statements that
    /// introduce its locals.
    pub fn declaration(&mut self, d: &Declaration) -> Vec<ir::Stmt> {
        match d {
            Declaration::Prototype(p) => {
                if !self.scopes.is_global() {
                    self.error(
                        Code::BadQualifier,
                        p.span,
                        "function prototypes must be at global scope",
                    )
                    .notes
                    .push("GLSL 1.20 §4.2.6: move the prototype out of the function".into());
                    return Vec::new();
                }
                self.function_proto(p, false);
                Vec::new()
            }
            Declaration::Variables(list) => self.variables(list),
            Declaration::Invariant { names, span } => {
                self.invariant_redeclaration(names, *span);
                Vec::new()
            }
            Declaration::_Reserved => Vec::new(),
        }
    }

    /// Checks a variable's qualifier list (GLSL 1.20 §4.3, §4.6.1).
    fn var_qualifiers(&mut self, quals: &[SpannedQualifier]) -> VarQuals {
        let mut q = VarQuals::default();
        let global = self.scopes.is_global();
        for (i, sq) in quals.iter().enumerate() {
            let name = sq.qualifier.as_str();
            match sq.qualifier {
                Qualifier::Const
                | Qualifier::Attribute
                | Qualifier::Uniform
                | Qualifier::Varying => {
                    if let Some(prev) = q.storage {
                        self.error(
                            Code::BadQualifier,
                            sq.span,
                            format!(
                                "`{name}' after `{}': only one storage qualifier is allowed",
                                prev.as_str()
                            ),
                        );
                        continue;
                    }
                    q.storage = Some(sq.qualifier);
                }
                Qualifier::In | Qualifier::Out | Qualifier::Inout => {
                    self.error(
                        Code::BadQualifier,
                        sq.span,
                        format!(
                            "`{name}' is only allowed on function parameters in GLSL {}",
                            self.lang.version.dotted()
                        ),
                    )
                    .notes
                    .push("use `attribute'/`varying' for stage inputs and outputs".into());
                }
                Qualifier::Centroid => {
                    let next = quals.get(i + 1).map(|n| n.qualifier);
                    if next != Some(Qualifier::Varying) {
                        self.error(
                            Code::BadQualifier,
                            sq.span,
                            "`centroid' must be followed by `varying'",
                        );
                    }
                    q.centroid = true;
                }
                Qualifier::Invariant => {
                    if i != 0 {
                        self.error(
                            Code::BadQualifier,
                            sq.span,
                            "`invariant' must come before the other qualifiers",
                        );
                    }
                    if q.invariant {
                        self.error(Code::BadQualifier, sq.span, "`invariant' given twice");
                    }
                    q.invariant = true;
                }
            }
        }
        if !global {
            if let Some(s) = q.storage.filter(|s| *s != Qualifier::Const) {
                let span = quals
                    .iter()
                    .find(|x| x.qualifier == s)
                    .map_or(Span::default(), |x| x.span);
                self.error(
                    Code::BadQualifier,
                    span,
                    format!(
                        "`{}' is not allowed on local variables; declare it at global scope",
                        s.as_str()
                    ),
                );
                q.storage = None;
            }
            if q.invariant {
                let span = quals
                    .iter()
                    .find(|x| x.qualifier == Qualifier::Invariant)
                    .map_or(Span::default(), |x| x.span);
                self.error(
                    Code::BadQualifier,
                    span,
                    "`invariant' is only allowed on global varyings",
                );
                q.invariant = false;
            }
        } else if q.invariant && q.storage != Some(Qualifier::Varying) && !self.builtin_mode {
            let span = quals
                .iter()
                .find(|x| x.qualifier == Qualifier::Invariant)
                .map_or(Span::default(), |x| x.span);
            self.error(
                Code::BadQualifier,
                span,
                "`invariant' applies only to varyings (GLSL 1.20 §4.6.1)",
            );
            q.invariant = false;
        }
        if q.storage == Some(Qualifier::Attribute) && self.stage != Stage::Vertex {
            let span = quals
                .iter()
                .find(|x| x.qualifier == Qualifier::Attribute)
                .map_or(Span::default(), |x| x.span);
            self.error(
                Code::StageMismatch,
                span,
                "`attribute' is only allowed in vertex shaders",
            )
            .notes
            .push("fragment shaders read per-vertex data through `varying'".into());
            q.storage = None;
        }
        q
    }

    fn variables(&mut self, list: &InitDeclaratorList) -> Vec<ir::Stmt> {
        let quals = self.var_qualifiers(&list.ty.qualifiers);
        let base = self.resolve_type(&list.ty.ty);
        let mut out = Vec::new();
        if list.declarators.is_empty() {
            if !matches!(list.ty.ty.name, crate::ast::TypeName::Struct(_)) && !base.is_error() {
                self.push(Diagnostic::warning(
                    Code::Syntax,
                    list.span,
                    "declaration declares nothing",
                ));
            }
            return out;
        }
        for d in &list.declarators {
            if let Some(s) = self.declarator(quals, base, d, list.ty.span) {
                out.push(s);
            }
        }
        out
    }

    /// Checks what a storage qualifier allows for a type.
    fn check_storage_type(&mut self, q: VarQuals, ty: Type, d: &InitDeclarator) {
        if ty.is_error() {
            return;
        }
        let name = &d.name.name;
        let tn = self.tn(ty);
        if ty.base == Base::Void {
            self.error(
                Code::TypeMismatch,
                d.name.span,
                format!("variable `{name}' cannot be void"),
            );
            return;
        }
        let float_based = matches!(
            ty.base,
            Base::Scalar(crate::types::Scalar::Float)
                | Base::Vector(crate::types::Scalar::Float, _)
                | Base::Matrix { .. }
        );
        match q.storage {
            // The prelude's inputs (`gl_VertexID`, `gl_FrontFacing`,
            // `gl_PrimitiveID`) have types user attributes and varyings
            // may not.
            Some(Qualifier::Attribute | Qualifier::Varying) if self.builtin_mode => {}
            Some(Qualifier::Attribute) => {
                if !float_based || ty.is_array() {
                    self.error(
                        Code::TypeMismatch,
                        d.name.span,
                        format!("attribute `{name}' has type {tn}; attributes must be float, vec or mat (no arrays or structs)"),
                    );
                }
            }
            Some(Qualifier::Varying) => {
                if !float_based {
                    self.error(
                        Code::TypeMismatch,
                        d.name.span,
                        format!("varying `{name}' has type {tn}; varyings must be float, vec or mat, or arrays of them"),
                    );
                }
            }
            Some(Qualifier::Uniform) => {}
            _ => {
                if self.contains_sampler(ty) {
                    self.error(
                        Code::BadQualifier,
                        d.name.span,
                        format!("`{name}' has type {tn}; samplers can only be uniforms or function parameters"),
                    )
                    .notes
                    .push("declare it `uniform' at global scope".into());
                }
            }
        }
    }

    /// One declarator of a declaration list.
    fn declarator(
        &mut self,
        q: VarQuals,
        base: Type,
        d: &InitDeclarator,
        _tyspan: Span,
    ) -> Option<ir::Stmt> {
        let mut ty = self.apply_array(base, d.array.as_ref());
        let name = d.name.name.clone();
        self.check_storage_type(q, ty, d);
        if self.lang.version < Version::V120 && ty.is_array() && d.init.is_some() {
            self.error(
                Code::VersionTooLow,
                d.span,
                "arrays cannot be initialized in GLSL 1.10",
            )
            .notes
            .push(
                "assign the elements one by one, or use `#version 120' array constructors".into(),
            );
        }
        // The variable is not visible in its own initializer (§4.2.2).
        let init = d.init.as_ref().map(|e| {
            let v = self.rvalue(e);
            (v, e.span)
        });
        let mut init = match init {
            Some((v, sp)) => {
                if ty.array == Some(ArraySize::Unsized) && v.ty.is_array() && v.ty.base == ty.base {
                    ty = v.ty;
                }
                let what = format!("cannot initialize `{name}' of type {}", self.tn(ty));
                Some(self.coerce(v, ty, sp, &what))
            }
            None => None,
        };
        let is_const = q.storage == Some(Qualifier::Const);
        let mut value = None;
        if is_const {
            match &init {
                None => {
                    self.error(
                        Code::NotConstant,
                        d.name.span,
                        format!("`const' variable `{name}' needs an initializer"),
                    );
                }
                Some(e) if e.ty.is_error() => {}
                Some(e) => match &e.kind {
                    ExprKind::Const(c) => value = Some(c.clone()),
                    _ => {
                        self.error(Code::NotConstant, e.span, format!("initializer of `const' `{name}' is not a constant expression"))
                            .notes
                            .push("only literals, `const' variables, constructors and built-in functions of constants are constant".into());
                    }
                },
            }
        }
        if q.storage == Some(Qualifier::Uniform) {
            if let Some(e) = &init {
                if self.lang.version < Version::V120 {
                    self.error(
                        Code::VersionTooLow,
                        e.span,
                        "uniform initializers require GLSL 1.20",
                    );
                } else if !matches!(e.kind, ExprKind::Const(_)) && !e.ty.is_error() {
                    self.error(
                        Code::NotConstant,
                        e.span,
                        "a uniform initializer must be a constant expression",
                    );
                } else if let ExprKind::Const(c) = &e.kind {
                    value = Some(c.clone());
                }
            }
        }
        if matches!(q.storage, Some(Qualifier::Attribute | Qualifier::Varying)) {
            if let Some(e) = &init {
                self.error(
                    Code::BadQualifier,
                    e.span,
                    "stage inputs and outputs cannot have initializers",
                );
                init = None;
            }
        }
        if ty.array == Some(ArraySize::Unsized) && is_const {
            self.error(
                Code::BadArraySize,
                d.name.span,
                format!("`const' array `{name}' needs a size"),
            );
        }

        // gl_ names: only the permitted built-in redeclarations.
        if name.starts_with("gl_") && !self.builtin_mode {
            self.redeclare_builtin(q, ty, d);
            return None;
        }
        if !self.check_reserved_name(&name, d.name.span) {
            return None;
        }
        if let Some(prev) = self.scopes.lookup_current(&name).cloned() {
            if let Symbol::Var(v) = prev {
                if self.resize_array(v, ty, d) {
                    return self.resized_init(v, init, d.span);
                }
            }
            self.error(
                Code::Redeclared,
                d.name.span,
                format!("`{name}' is already declared in this scope"),
            );
            return None;
        }
        if self.scopes.is_global() {
            let storage = match q.storage {
                Some(Qualifier::Const) => Storage::Const,
                Some(Qualifier::Uniform) => Storage::Uniform,
                Some(Qualifier::Attribute) => Storage::Attribute,
                Some(Qualifier::Varying) => Storage::Varying,
                _ => Storage::Private,
            };
            let id = ir::GlobalId(self.module.globals.len() as u32);
            let init_expr = match (&value, storage) {
                (None, Storage::Private) => init,
                _ => None,
            };
            self.module.globals.push(Global {
                name: name.to_string(),
                ty,
                storage,
                builtin: self.builtin_mode,
                invariant: q.invariant,
                centroid: q.centroid,
                init: value,
                init_expr,
                read: false,
                written: false,
                implicit_size: 0,
                span: d.name.span,
            });
            self.scopes.insert(name, Symbol::Var(Var::Global(id)));
            None
        } else {
            let local = self.new_local(&name, ty, is_const, d.name.span);
            if let Some(f) = self.cur.as_mut() {
                if let Some(slot) = f.consts.get_mut(local.0 as usize) {
                    *slot = value.clone();
                }
            }
            self.scopes.insert(name, Symbol::Var(Var::Local(local)));
            Some(ir::Stmt::Declare {
                local,
                init,
                span: d.span,
            })
        }
    }

    /// `float a[]; ... float a[4];`: an unsized array may be redeclared with
    /// a size in the same scope (GLSL 1.20 §4.1.9). Returns true if `d` was
    /// such a redeclaration (errors reported here).
    fn resize_array(&mut self, v: Var, ty: Type, d: &InitDeclarator) -> bool {
        let old = self.var_type(v);
        if old.array != Some(ArraySize::Unsized) || !ty.is_array() {
            return false;
        }
        let name = &d.name.name;
        if old.base != ty.base {
            self.error(
                Code::Redeclared,
                d.name.span,
                format!(
                    "`{name}' redeclared as {}, but it is an array of {}",
                    self.tn(ty),
                    self.tn(old.element())
                ),
            );
            return true;
        }
        let Some(ArraySize::Sized(n)) = ty.array else {
            return true;
        };
        let used = self.implicit_size(v);
        if n < used {
            self.error(
                Code::IndexOutOfRange,
                d.name.span,
                format!(
                    "`{name}' redeclared with size {n}, but index {} is already used",
                    used - 1
                ),
            );
        }
        self.set_var_type(v, ty);
        true
    }

    /// `float a[]; float a[] = float[](0.0, 1.0);`: the redeclaration's
    /// initializer still initializes the (now sized) array: an assignment
    /// at the redeclaration for a local, the initializer of a global.
    fn resized_init(&mut self, v: Var, init: Option<ir::Expr>, span: Span) -> Option<ir::Stmt> {
        let init = init.filter(|e| !e.ty.is_error())?;
        let ty = self.var_type(v);
        match v {
            Var::Local(local) => Some(ir::Stmt::Expr(ir::Expr {
                kind: ExprKind::Assign {
                    op: None,
                    target: Box::new(ir::Expr {
                        kind: ExprKind::Local(local),
                        ty,
                        span,
                    }),
                    value: Box::new(init),
                },
                ty,
                span,
            })),
            Var::Global(g) => {
                if let Some(g) = self.module.globals.get_mut(g.0 as usize) {
                    if g.storage == Storage::Private && g.init_expr.is_none() {
                        g.init_expr = Some(init);
                    }
                }
                None
            }
            Var::Builtin(_) => None,
        }
    }

    pub fn implicit_size(&self, v: Var) -> u32 {
        match v {
            Var::Global(g) => self
                .module
                .globals
                .get(g.0 as usize)
                .map_or(0, |g| g.implicit_size),
            Var::Local(l) => self
                .cur
                .as_ref()
                .and_then(|f| f.implicit.get(l.0 as usize))
                .copied()
                .unwrap_or(0),
            Var::Builtin(i) => self
                .builtin_globals
                .get(i as usize)
                .copied()
                .flatten()
                .and_then(|g| self.module.globals.get(g.0 as usize))
                .map_or(0, |g| g.implicit_size),
        }
    }

    fn set_var_type(&mut self, v: Var, ty: Type) {
        match v {
            Var::Global(g) => {
                if let Some(g) = self.module.globals.get_mut(g.0 as usize) {
                    g.ty = ty;
                }
            }
            Var::Local(l) => {
                if let Some(l) = self
                    .cur
                    .as_mut()
                    .and_then(|f| f.locals.get_mut(l.0 as usize))
                {
                    l.ty = ty;
                }
            }
            Var::Builtin(_) => {
                if let Some(g) = self.global_of(v) {
                    self.module.globals[g.0 as usize].ty = ty;
                }
            }
        }
    }

    /// The only built-in a shader may redeclare: `varying vec4 gl_TexCoord[n]`
    /// with n ≤ gl_MaxTextureCoords (GLSL 1.20 §7.6).
    fn redeclare_builtin(&mut self, q: VarQuals, ty: Type, d: &InitDeclarator) {
        let name = &d.name.name;
        let builtin = match self.env.and_then(|e| e.lookup(name)) {
            Some(Symbol::Var(v)) => Some(*v),
            _ => None,
        };
        let texcoord_ok = name == "gl_TexCoord"
            && q.storage == Some(Qualifier::Varying)
            && ty.base == Type::vec(crate::types::Scalar::Float, 4).base
            && ty.is_array()
            && builtin.is_some();
        if !texcoord_ok {
            self.error(
                Code::Redeclared,
                d.name.span,
                format!("`{name}': names starting with `gl_' are reserved; built-in variables cannot be redeclared"),
            )
            .notes
            .push(if name == "gl_TexCoord" {
                "only `varying vec4 gl_TexCoord[N];' may redeclare it".to_string()
            } else {
                "rename the variable".to_string()
            });
            return;
        }
        let Some(v) = builtin else { return };
        if let Some(ArraySize::Sized(n)) = ty.array {
            if n > MAX_TEXTURE_COORDS {
                self.error(
                    Code::BadArraySize,
                    d.name.span,
                    format!("`gl_TexCoord' redeclared with size {n}, larger than gl_MaxTextureCoords ({MAX_TEXTURE_COORDS})"),
                );
                return;
            }
            let used = self.implicit_size(v);
            if n < used {
                self.error(
                    Code::IndexOutOfRange,
                    d.name.span,
                    format!(
                        "`gl_TexCoord' redeclared with size {n}, but index {} is already used",
                        used - 1
                    ),
                );
            }
        }
        self.set_var_type(v, ty);
        if let Some(g) = self.global_of(v) {
            if let Some(gl) = self.module.globals.get_mut(g.0 as usize) {
                gl.invariant |= q.invariant;
                gl.centroid |= q.centroid;
            }
        }
    }

    /// `invariant a, b;` (GLSL 1.20 §4.6.1): global scope only, for varyings
    /// and built-in outputs, before any use.
    fn invariant_redeclaration(&mut self, names: &[crate::ast::Ident], span: Span) {
        if !self.scopes.is_global() {
            self.error(
                Code::BadQualifier,
                span,
                "`invariant' redeclarations must be at global scope",
            );
            return;
        }
        for n in names {
            let v = match self.lookup(&n.name) {
                Some(Symbol::Var(v)) => v,
                _ => {
                    self.error(Code::Undeclared, n.span, format!("`{}' undeclared", n.name));
                    continue;
                }
            };
            let Some(g) = self.global_of(v) else {
                self.error(
                    Code::BadQualifier,
                    n.span,
                    format!("`{}' is not a global varying", n.name),
                );
                continue;
            };
            let gl = &self.module.globals[g.0 as usize];
            let output_builtin =
                gl.builtin && gl.storage == Storage::Private && self.stage == Stage::Vertex;
            if gl.storage != Storage::Varying && !output_builtin {
                self.error(
                    Code::BadQualifier,
                    n.span,
                    format!(
                        "`{}' is not a varying; only varyings can be invariant",
                        n.name
                    ),
                );
                continue;
            }
            if gl.read || gl.written {
                self.error(
                    Code::BadQualifier,
                    n.span,
                    format!("`{}' is declared invariant after it is used", n.name),
                );
                continue;
            }
            self.module.globals[g.0 as usize].invariant = true;
        }
    }
}
