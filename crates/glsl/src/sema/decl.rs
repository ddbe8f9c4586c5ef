//! Variable declarations, storage qualifiers and `invariant` redeclarations.

use super::interface::VarQuals;
use super::scope::{Symbol, Var};
use super::Analyzer;
use crate::ast::{Declaration, InitDeclarator, InitDeclaratorList, Qualifier};
use crate::diag::{Code, Diagnostic};
use crate::ir::{self, ExprKind, Global, Interpolation, Stage, Storage};
use crate::lang::{Feature, Version};
use crate::limits::{MAX_CLIP_PLANES, MAX_TEXTURE_COORDS};
use crate::source::Span;
use crate::types::{ArraySize, Base, Scalar, Type};

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
            Declaration::Precision { precision, ty, .. } => {
                self.precision_statement(precision, ty);
                Vec::new()
            }
            Declaration::Block(b) => {
                self.interface_block(b);
                Vec::new()
            }
            Declaration::Qualifiers { qualifiers, span } => {
                self.qualifiers_only(qualifiers, *span);
                Vec::new()
            }
        }
    }

    fn variables(&mut self, list: &InitDeclaratorList) -> Vec<ir::Stmt> {
        let quals = self.var_qualifiers(&list.ty.qualifiers);
        let base = self.resolve_type(&list.ty.ty);
        let mut out = Vec::new();
        if list.declarators.is_empty() {
            self.check_precision(quals.precision, base);
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
            if let Some(s) = self.declarator(&quals, base, d, list.ty.span) {
                out.push(s);
            }
        }
        out
    }

    /// The storage of a global with qualifiers `q` in this stage: a vertex
    /// `in` is an attribute, a vertex, evaluation or geometry `out`, a
    /// fragment `in` and the `patch` ones are varyings, a geometry or
    /// tessellation `in` a per-vertex input, a control shader's `out` a
    /// per-vertex output, a fragment `out` a user output (GLSL 1.30
    /// §4.3.4, §4.3.6; 1.50 §4.3.4; GL_ARB_tessellation_shader §4.3).
    pub(crate) fn global_storage(&self, q: &VarQuals) -> Storage {
        match (q.storage, self.stage) {
            (Some(Qualifier::Const), _) => Storage::Const,
            (Some(Qualifier::Uniform), _) => Storage::Uniform,
            (Some(Qualifier::Attribute), _) => Storage::Attribute,
            (Some(Qualifier::Varying), _) => Storage::Varying,
            (Some(Qualifier::Shared), _) => Storage::Shared,
            (Some(Qualifier::Buffer), _) => Storage::Buffer,
            // A compute shader's only inputs are its built-in IDs.
            (Some(Qualifier::In), Stage::Compute) => Storage::Varying,
            (Some(Qualifier::In), Stage::Vertex) => Storage::Attribute,
            (Some(Qualifier::In), Stage::Geometry) => Storage::PerVertexInput,
            // GL_ARB_tessellation_shader §4.3.4, §4.3.6: per-vertex inputs
            // of both stages and outputs of the control stage, unless
            // per-patch.
            (Some(Qualifier::In), Stage::TessControl | Stage::TessEvaluation) => {
                if q.patch.is_some() {
                    Storage::Varying
                } else {
                    Storage::PerVertexInput
                }
            }
            (Some(Qualifier::Out), Stage::TessControl) => {
                if q.patch.is_some() {
                    Storage::Varying
                } else {
                    Storage::PerVertexOutput
                }
            }
            (Some(Qualifier::In), Stage::Fragment) => Storage::Varying,
            (Some(Qualifier::Out), Stage::Vertex | Stage::TessEvaluation | Stage::Geometry) => {
                Storage::Varying
            }
            (Some(Qualifier::Out), Stage::Fragment) => Storage::FragOutput,
            _ => Storage::Private,
        }
    }

    /// Checks what a storage qualifier allows for a type (GLSL 1.20
    /// §4.3.3-§4.3.5; 1.30 §4.3.4, §4.3.6; 1.50 adds arrays of vertex
    /// inputs and structs of varyings).
    fn check_storage_type(&mut self, q: &VarQuals, ty: Type, d: &InitDeclarator) {
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
        let v130 = self.lang.allows(Feature::StageInOut);
        let v150 = self.lang.version >= Version::V150;
        // The element of an array of arrays is the innermost one: the
        // rules on arrays of a type hold for arrays of arrays of it.
        let mut elem = ty.element();
        for _ in 0..64 {
            match self.array_row_member(elem) {
                Some(row) => elem = row.element(),
                None => break,
            }
        }
        let float_based = matches!(
            elem.base,
            Base::Scalar(Scalar::Float) | Base::Vector(Scalar::Float, _) | Base::Matrix { .. }
        );
        let int_based = matches!(elem.base, Base::Scalar(s) | Base::Vector(s, _) if is_integer(s));
        let is_struct = matches!(elem.base, Base::Struct(_));
        let vertex = self.stage == Stage::Vertex;
        let storage = if q.storage.is_some() {
            Some(self.global_storage(q))
        } else {
            None
        };
        match storage {
            // The prelude's inputs (`gl_VertexID`, `gl_FrontFacing`,
            // `gl_PrimitiveID`) have types user attributes and varyings
            // may not.
            Some(
                Storage::Attribute
                | Storage::Varying
                | Storage::PerVertexInput
                | Storage::PerVertexOutput,
            ) if self.builtin_mode => {}
            Some(Storage::PerVertexInput) if self.lang.ext_geometry_shader4() => {
                // GL_EXT_geometry_shader4 §4.3.6: the types of varyings
                // (1.30 adds the integer ones), one element per input
                // vertex.
                if !(float_based || (v130 && int_based)) {
                    let allowed = if v130 {
                        "float, int or uint scalars, vectors or float matrices"
                    } else {
                        "float, vec or mat"
                    };
                    self.error(
                        Code::TypeMismatch,
                        d.name.span,
                        format!("geometry input `{name}' has type {tn}; inputs must be arrays of {allowed}"),
                    );
                } else if !ty.is_array() {
                    // As written: `varying in', or `in' from GLSL 1.30 on.
                    let kw = if q.storage_span.end.saturating_sub(q.storage_span.start) > 2 {
                        "varying in"
                    } else {
                        "in"
                    };
                    self.error(
                        Code::TypeMismatch,
                        d.name.span,
                        format!("geometry shader input `{name}' must be an array: `{kw} {tn} {name}[];'"),
                    )
                    .notes
                    .push("GL_EXT_geometry_shader4 §4.3.6: a geometry shader has one input per vertex of its primitive; the program's GEOMETRY_INPUT_TYPE sizes the array (gl_VerticesIn elements)".into());
                }
            }
            Some(s @ (Storage::PerVertexInput | Storage::PerVertexOutput)) => {
                // GLSL 1.50 §4.3.4, GL_ARB_tessellation_shader §4.3.4 and
                // §4.3.6: the types of outputs, one element per vertex of
                // the primitive or patch.
                let input = s == Storage::PerVertexInput;
                let (what, kw) = if input {
                    ("input", "in")
                } else {
                    ("output", "out")
                };
                let stage = self.stage.name();
                let struct_ok = is_struct && !self.contains_integer(elem);
                if !(float_based || int_based || struct_ok) {
                    self.error(
                        Code::TypeMismatch,
                        d.name.span,
                        format!("{stage} {what} `{name}' has type {tn}; {what}s must be float, int or uint scalars, vectors, float matrices or structs"),
                    );
                } else if !ty.is_array() {
                    let note = match self.stage {
                        Stage::Geometry => "GLSL 1.50 §4.3.4: a geometry shader has one input per vertex of its primitive; the primitive's layout sizes the array",
                        Stage::TessControl if input => "GL_ARB_tessellation_shader §4.3.4: a tessellation control shader reads the whole input patch; its inputs have gl_MaxPatchVertices elements (write `patch' for nothing here: patch inputs are evaluation shaders')",
                        Stage::TessControl => "GL_ARB_tessellation_shader §4.3.6: a tessellation control shader's outputs have one element per vertex of the output patch (`layout(vertices = N) out;' sizes them); write `patch out' for one value per patch",
                        _ => "GL_ARB_tessellation_shader §4.3.4: a tessellation evaluation shader reads the whole patch; its inputs have gl_MaxPatchVertices elements; write `patch in' for one value per patch",
                    };
                    self.error(
                        Code::TypeMismatch,
                        d.name.span,
                        format!("{stage} shader {what} `{name}' must be an array: `{kw} {tn} {name}[];'"),
                    )
                    .notes
                    .push(note.into());
                }
            }
            Some(Storage::Attribute) => {
                // GLSL 1.30 adds integer inputs; 1.50 arrays of inputs (not
                // of `attribute').
                let arrays = v150 && q.storage == Some(Qualifier::In);
                let base_ok = float_based || (v130 && int_based);
                if !base_ok || (ty.is_array() && !arrays) {
                    let allowed = if v130 {
                        "float, int or uint scalars, vectors or float matrices"
                    } else {
                        "float, vec or mat"
                    };
                    let (what, plural) = if q.storage == Some(Qualifier::Attribute) {
                        ("attribute", "attributes")
                    } else {
                        ("vertex input", "inputs")
                    };
                    self.error(
                        Code::TypeMismatch,
                        d.name.span,
                        format!(
                            "{what} `{name}' has type {tn}; {plural} must be {allowed}{}",
                            if arrays {
                                ", or arrays of them"
                            } else {
                                " (no arrays or structs)"
                            }
                        ),
                    );
                }
            }
            Some(Storage::Varying) => {
                let bool_ok = self.builtin_mode && ty.scalar() == Some(Scalar::Bool);
                let struct_ok = v150 && is_struct && q.storage != Some(Qualifier::Varying);
                let base_ok = float_based || (v130 && int_based) || struct_ok;
                if !base_ok && !bool_ok {
                    let (what, plural) = if q.storage == Some(Qualifier::Varying) {
                        ("varying", "varyings")
                    } else if vertex {
                        ("vertex output", "vertex outputs")
                    } else if self.stage == Stage::Geometry {
                        ("geometry output", "geometry outputs")
                    } else if q.patch.is_some() {
                        ("per-patch variable", "per-patch variables")
                    } else if self.stage == Stage::TessEvaluation {
                        (
                            "tessellation evaluation output",
                            "tessellation evaluation outputs",
                        )
                    } else {
                        ("fragment input", "fragment inputs")
                    };
                    let allowed = if v130 {
                        "float, int or uint scalars, vectors, float matrices or arrays of them"
                    } else {
                        "float, vec or mat, or arrays of them"
                    };
                    self.error(
                        Code::TypeMismatch,
                        d.name.span,
                        format!("{what} `{name}' has type {tn}; {plural} must be {allowed}"),
                    );
                } else if self.stage == Stage::Fragment
                    && (int_based || (is_struct && self.contains_integer(elem)))
                    && q.interpolation.map(|(i, _)| i) != Some(Interpolation::Flat)
                    && !self.builtin_mode
                {
                    // GLSL 1.50 §4.3.4 moves 1.30's rule for vertex outputs to
                    // fragment inputs; read it so in 1.30 too, as the GL
                    // conformance tests do.
                    self.error(
                        Code::BadQualifier,
                        d.name.span,
                        format!("fragment input `{name}' has integer type {tn}; it must be `flat'"),
                    )
                    .notes
                    .push("integers are not interpolated: declare it `flat in'".into());
                }
            }
            Some(Storage::FragOutput) => {
                let ok = elem.base != Base::Scalar(Scalar::Bool)
                    && (matches!(
                        elem.base,
                        Base::Scalar(Scalar::Float) | Base::Vector(Scalar::Float, _)
                    ) || int_based);
                if !ok {
                    self.error(
                        Code::TypeMismatch,
                        d.name.span,
                        format!("fragment output `{name}' has type {tn}; outputs must be float, int or uint scalars or vectors, or arrays of them"),
                    );
                }
            }
            Some(Storage::Uniform) => {}
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

    /// True when a type is or has (as a struct member, at any depth) an
    /// integer scalar or vector.
    pub(crate) fn contains_integer(&self, ty: Type) -> bool {
        let mut stack = vec![(ty, 0u32)];
        while let Some((t, depth)) = stack.pop() {
            match t.base {
                Base::Scalar(s) | Base::Vector(s, _) if is_integer(s) => return true,
                Base::Struct(id) if depth < 64 => {
                    if let Some(s) = self.module.structs.get(id.0 as usize) {
                        stack.extend(s.members.iter().map(|m| (m.ty, depth + 1)));
                    }
                }
                _ => {}
            }
        }
        false
    }

    /// One declarator of a declaration list.
    fn declarator(
        &mut self,
        q: &VarQuals,
        base: Type,
        d: &InitDeclarator,
        _tyspan: Span,
    ) -> Option<ir::Stmt> {
        let name = d.name.name.clone();
        let mut ty = match d.array.as_ref() {
            Some(spec) if spec.dims.len() == 2 && self.ext_two_dimensional_input(q, base) => {
                let outer = crate::ast::ArraySpec {
                    dims: spec.dims[..1].to_vec(),
                    span: spec.dims[0].span,
                };
                let ty = self.apply_array(base, Some(&outer));
                self.check_storage_type(q, ty, d);
                self.two_dimensional_input(ty, &spec.dims[1], d)
            }
            spec => {
                let ty = self.apply_array(base, spec);
                self.check_storage_type(q, ty, d);
                ty
            }
        };
        self.check_precision(q.precision, ty);
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
        let mut init = d.init.as_ref().map(|e| {
            let what = format!("cannot initialize `{name}' of type {}", self.tn(ty));
            let v = self.initializer(ty, e, &what);
            if ty.array == Some(ArraySize::Unsized) && v.ty.is_array() && v.ty.base == ty.base {
                ty = v.ty;
            }
            v
        });
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
                    // GL_ARB_shading_language_420pack: a `const' local
                    // may be initialized by any expression; it is then a
                    // read-only variable, not a constant (GLSL 4.20 §4.3.3).
                    _ if !self.scopes.is_global()
                        && self.lang.allows(crate::lang::Feature::LanguagePack420) => {}
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
        if matches!(
            q.storage,
            Some(Qualifier::Attribute | Qualifier::Varying | Qualifier::In | Qualifier::Out)
        ) {
            if let Some(e) = &init {
                self.error(
                    Code::BadQualifier,
                    e.span,
                    "stage inputs and outputs cannot have initializers",
                );
                init = None;
            }
        }
        if q.storage == Some(Qualifier::Shared) {
            if let Some(e) = &init {
                // GLSL 4.30 §4.3.8: the work group's invocations would
                // all initialize it.
                self.error(
                    Code::BadQualifier,
                    e.span,
                    "`shared' variables cannot have initializers",
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
            let stage_io = matches!(
                q.storage,
                Some(Qualifier::In | Qualifier::Out | Qualifier::Varying | Qualifier::Attribute)
            );
            if q.storage == Some(Qualifier::Buffer) {
                self.error(
                    Code::BadQualifier,
                    q.storage_span,
                    format!(
                        "`buffer' variable `{name}' must be a member of a shader storage block"
                    ),
                )
                .notes
                .push("declare it inside one: `buffer B { float v; };'".into());
                return None;
            }
            if self.stage == Stage::Compute && stage_io && !self.builtin_mode {
                self.error(
                    Code::StageMismatch,
                    q.storage_span,
                    format!(
                        "a compute shader has no user-defined inputs or outputs (`{name}')"
                    ),
                )
                .notes
                .push("its inputs are gl_GlobalInvocationID and the other built-in IDs; it writes its results to memory".into());
                return None;
            }
            let storage = self.global_storage(q);
            let (location, index) = self.check_var_layout(q, &name);
            let binding = self.var_binding(q, ty);
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
                interpolation: q.interpolation.map(|(i, _)| i),
                location,
                index,
                binding,
                patch: q.patch.is_some(),
                block: None,
                init: value,
                init_expr,
                read: false,
                written: false,
                implicit_size: 0,
                span: d.name.span,
            });
            self.scopes.insert(name, Symbol::Var(Var::Global(id)));
            if storage == Storage::PerVertexInput && !self.builtin_mode && ty.is_array() {
                self.size_per_vertex_input(id, d.name.span);
            }
            if storage == Storage::PerVertexOutput && ty.is_array() {
                self.size_per_vertex_output(id, d.name.span);
            }
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

    /// Whether a declarator of base type `base` with two sizes is a
    /// GL_EXT_geometry_shader4 two-dimensional geometry input (§4.3.6: a
    /// vertex shader's array output, one per input vertex), which that
    /// extension allows without GL_ARB_arrays_of_arrays.
    fn ext_two_dimensional_input(&self, q: &VarQuals, base: Type) -> bool {
        self.scopes.is_global()
            && q.storage.is_some()
            && self.global_storage(q) == Storage::PerVertexInput
            && self.lang.ext_geometry_shader4()
            && !base.is_array()
    }

    /// The type of a GL_EXT_geometry_shader4 two-dimensional geometry
    /// input ([`Self::ext_two_dimensional_input`]), whose second size is
    /// required. `ty` is the declared type with its first size (already
    /// checked as an input of its element type).
    fn two_dimensional_input(
        &mut self,
        ty: Type,
        inner: &crate::ast::ArrayDim,
        d: &InitDeclarator,
    ) -> Type {
        if ty.is_error() {
            let _ = self.array_size(inner);
            return ty;
        }
        let size = self.array_size(inner);
        if size == ArraySize::Unsized && !self.builtin_mode && !d.name.name.starts_with("gl_") {
            self.error(
                Code::BadArraySize,
                inner.span,
                format!("the second size of geometry input `{}' is required", d.name.name),
            )
            .notes
            .push("GL_EXT_geometry_shader4 §4.3.6: it is the size of the vertex shader's array output".into());
            return Type::ERROR;
        }
        let row = ty.element().array_of(size);
        let elem = self.array_row(crate::types::ARRAY_ROW_MEMBER, row);
        Type {
            array: ty.array,
            ..elem
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

    pub(crate) fn set_var_type(&mut self, v: Var, ty: Type) {
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

    /// The built-ins a shader may redeclare: `gl_TexCoord[n]` with n ≤
    /// gl_MaxTextureCoords (GLSL 1.20 §7.6); the colour varyings with an
    /// interpolation qualifier (1.30 §4.3.7); `gl_FragCoord` with its
    /// layout (1.50 §7.2, GL_ARB_fragment_coord_conventions).
    fn redeclare_builtin(&mut self, q: &VarQuals, ty: Type, d: &InitDeclarator) {
        let name = &d.name.name;
        let builtin = match self.env.and_then(|e| e.lookup(name)) {
            Some(Symbol::Var(v)) => Some(*v),
            _ => None,
        };
        let storage = self.global_storage(q);
        // A member of the output `gl_PerVertex' is redeclared either in
        // the block or on its own, not both (GLSL 1.50 §7.1).
        let output = match self.stage {
            Stage::Vertex => true,
            Stage::Geometry | Stage::TessEvaluation => q.storage != Some(Qualifier::In),
            // A control shader's outputs are `gl_out[]''s members.
            Stage::TessControl | Stage::Fragment | Stage::Compute => false,
        };
        if output && super::blocks::PER_VERTEX_OUT_MEMBERS.contains(&name.as_str()) {
            if self.module.per_vertex_out.is_some() {
                self.error(
                    Code::Redeclared,
                    d.name.span,
                    format!("`{name}' is redeclared on its own after the `gl_PerVertex' block is redeclared"),
                )
                .notes
                .push("redeclare it inside the block only".into());
                return;
            }
            self.per_vertex_member_redeclared
                .get_or_insert(name.clone());
        }
        if let (Some(v), "gl_TexCoordIn" | "gl_ClipDistanceIn", Storage::PerVertexInput) =
            (builtin, name.as_str(), storage)
        {
            self.redeclare_two_dimensional_input(v, ty, d);
            return;
        }
        let vec4 = ty.base == Type::vec(Scalar::Float, 4).base;
        let varying = storage == Storage::Varying && builtin.is_some() && vec4;
        let texcoord_ok = name == "gl_TexCoord" && varying && ty.is_array();
        // GLSL 1.30 §7.1: `out float gl_ClipDistance[N];' (vertex) and
        // `in float gl_ClipDistance[N];' (fragment) may size it.
        let clip_ok = name == "gl_ClipDistance"
            && storage == Storage::Varying
            && builtin.is_some()
            && ty.base == Base::Scalar(Scalar::Float)
            && ty.is_array()
            && q.storage != Some(Qualifier::Varying);
        let colors: &[&str] = match self.stage {
            // Compatibility-profile geometry outputs are the vertex
            // stage's (GLSL 1.50 §7.1.1).
            Stage::Vertex | Stage::TessEvaluation | Stage::Geometry => &[
                "gl_FrontColor",
                "gl_BackColor",
                "gl_FrontSecondaryColor",
                "gl_BackSecondaryColor",
            ],
            Stage::Fragment => &["gl_Color", "gl_SecondaryColor"],
            Stage::TessControl | Stage::Compute => &[],
        };
        let color_ok = colors.contains(&name.as_str()) && varying && !ty.is_array();
        let frag_coord_ok = name == "gl_FragCoord"
            && self.stage == Stage::Fragment
            && vec4
            && !ty.is_array()
            && builtin.is_some()
            && matches!(q.storage, Some(Qualifier::In | Qualifier::Varying));
        if frag_coord_ok && q.interpolation.is_none() {
            let l = &q.layout;
            let conv = ir::FragCoordConventions {
                origin_upper_left: l.origin_upper_left.is_some(),
                pixel_center_integer: l.pixel_center_integer.is_some(),
                redeclared: true,
            };
            // GL_ARB_fragment_coord_conventions: every redeclaration has
            // the same layout, and comes before any use.
            if self.frag_coord_redeclared.is_some_and(|c| c != conv) {
                self.error(
                    Code::Redeclared,
                    d.name.span,
                    "`gl_FragCoord' redeclared with a different layout",
                );
            }
            // A built-in is in the module once the shader refers to it.
            let used = match builtin {
                Some(Var::Builtin(i)) => self
                    .builtin_globals
                    .get(i as usize)
                    .copied()
                    .flatten()
                    .and_then(|g| self.module.globals.get(g.0 as usize))
                    .is_some_and(|g| g.read || g.written),
                _ => false,
            };
            if used && self.frag_coord_redeclared.is_none() {
                self.error(
                    Code::Redeclared,
                    d.name.span,
                    "`gl_FragCoord' is redeclared after it is used",
                )
                .notes
                .push("redeclare it before the first use".into());
            }
            self.frag_coord_redeclared.get_or_insert(conv);
            self.module.frag_coord = conv;
            if let Some(span) = l
                .location
                .map(|(_, s)| s)
                .or(l.block_layout.map(|(_, s)| s))
            {
                self.error(
                    Code::BadQualifier,
                    span,
                    "`gl_FragCoord' takes only `origin_upper_left' and `pixel_center_integer'",
                );
            }
            return;
        }
        if let Some(span) = q.layout.span.filter(|_| texcoord_ok || color_ok) {
            self.error(
                Code::BadQualifier,
                span,
                format!("`{name}' cannot be redeclared with a layout"),
            );
        }
        if color_ok {
            if let Some(g) = builtin.and_then(|v| self.global_of(v)) {
                if let Some(gl) = self.module.globals.get_mut(g.0 as usize) {
                    gl.interpolation = q.interpolation.map(|(i, _)| i);
                    gl.invariant |= q.invariant;
                    gl.centroid |= q.centroid;
                }
            }
            return;
        }
        let (array_ok, max, max_name) = if clip_ok {
            (true, MAX_CLIP_PLANES, "gl_MaxClipDistances")
        } else {
            (texcoord_ok, MAX_TEXTURE_COORDS, "gl_MaxTextureCoords")
        };
        if !array_ok {
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
            if n > max {
                self.error(
                    Code::BadArraySize,
                    d.name.span,
                    format!("`{name}' redeclared with size {n}, larger than {max_name} ({max})"),
                );
                return;
            }
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
        }
        self.set_var_type(v, ty);
        if let Some(g) = self.global_of(v) {
            if let Some(gl) = self.module.globals.get_mut(g.0 as usize) {
                gl.invariant |= q.invariant;
                gl.centroid |= q.centroid;
            }
        }
    }

    /// `varying in vec4 gl_TexCoordIn[][N];`, `in float
    /// gl_ClipDistanceIn[][N];` (GL_EXT_geometry_shader4 §7.1): the
    /// built-in two-dimensional inputs sized like the vertex outputs they
    /// read, at most gl_MaxTextureCoords / gl_MaxClipDistances.
    fn redeclare_two_dimensional_input(&mut self, v: Var, ty: Type, d: &InitDeclarator) {
        if ty.is_error() {
            return;
        }
        let name = &d.name.name;
        let (elem, max, max_name) = if name == "gl_TexCoordIn" {
            (
                Type::vec(Scalar::Float, 4),
                MAX_TEXTURE_COORDS,
                "gl_MaxTextureCoords",
            )
        } else {
            (Type::FLOAT, MAX_CLIP_PLANES, "gl_MaxClipDistances")
        };
        let row = self.array_row_member(ty.element());
        let Some(row) = row.filter(|r| r.element() == elem) else {
            let elem = self.tn(elem);
            self.error(
                Code::Redeclared,
                d.name.span,
                format!("`{name}' can only be redeclared as `{elem} {name}[][N]'"),
            );
            return;
        };
        if let Some(ArraySize::Sized(n)) = row.array {
            if n > max {
                self.error(
                    Code::BadArraySize,
                    d.name.span,
                    format!("`{name}' redeclared with {n} elements per vertex, more than {max_name} ({max})"),
                );
                return;
            }
        }
        let current = self.var_type(v);
        if let Some(ArraySize::Sized(n)) = ty.array {
            if current
                .array
                .is_some_and(|a| a != ArraySize::Sized(n) && a != ArraySize::Unsized)
            {
                let p = self
                    .module
                    .geometry
                    .input
                    .unwrap_or(crate::ir::InputPrimitive::Points);
                self.error(
                    Code::BadArraySize,
                    d.name.span,
                    format!(
                        "`{name}' redeclared with {n} vertices, but input primitives of type {} have {} (gl_VerticesIn)",
                        p.gl_name(),
                        p.vertices()
                    ),
                );
                return;
            }
        }
        let ty = Type {
            array: current.array.or(ty.array),
            ..ty
        };
        self.set_var_type(v, ty);
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
            // The vertex and geometry stages' built-in outputs
            // (`gl_Position'...), and a geometry shader's inputs, which
            // are the vertex stage's outputs (GLSL 1.50 §4.6.1).
            let output_builtin = gl.builtin
                && gl.storage == Storage::Private
                && matches!(self.stage, Stage::Vertex | Stage::Geometry);
            let stage_io = matches!(gl.storage, Storage::Varying | Storage::PerVertexInput);
            if !stage_io && !output_builtin {
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

/// Signed and unsigned integers (every scalar but float and bool).
pub(crate) fn is_integer(s: Scalar) -> bool {
    !matches!(s, Scalar::Float | Scalar::Bool)
}
