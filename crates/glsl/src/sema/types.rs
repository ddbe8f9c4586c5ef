//! Type specifiers, struct declarations and array sizes.

use super::scope::Symbol;
use super::{const_int, Analyzer};
use crate::ast::{ArrayDim, ArraySpec, StructSpecifier, TypeName, TypeSpecifier};
use crate::diag::{did_you_mean, Code};
use crate::lang::{Feature, Version};
use crate::limits::MAX_ARRAY_SIZE;
use crate::token::Keyword;
use crate::types::{
    ArraySize, Base, SamplerKind, Scalar, StructDef, StructId, StructMember, Type, ARRAY_ROW_MEMBER,
};

/// The type a built-in type keyword names.
pub(crate) fn keyword_type(k: Keyword) -> Option<Type> {
    use Keyword as K;
    use Scalar::*;
    Some(match k {
        K::Void => Type::VOID,
        K::Float => Type::FLOAT,
        K::Int => Type::INT,
        K::Bool => Type::BOOL,
        K::Vec2 => Type::vec(Float, 2),
        K::Vec3 => Type::vec(Float, 3),
        K::Vec4 => Type::vec(Float, 4),
        K::Ivec2 => Type::vec(Int, 2),
        K::Ivec3 => Type::vec(Int, 3),
        K::Ivec4 => Type::vec(Int, 4),
        K::Uint => Type::UINT,
        K::Uvec2 => Type::vec(Uint, 2),
        K::Uvec3 => Type::vec(Uint, 3),
        K::Uvec4 => Type::vec(Uint, 4),
        K::Bvec2 => Type::vec(Bool, 2),
        K::Bvec3 => Type::vec(Bool, 3),
        K::Bvec4 => Type::vec(Bool, 4),
        K::Mat2 | K::Mat2x2 => Type::mat(2, 2),
        K::Mat3 | K::Mat3x3 => Type::mat(3, 3),
        K::Mat4 | K::Mat4x4 => Type::mat(4, 4),
        K::Mat2x3 => Type::mat(2, 3),
        K::Mat2x4 => Type::mat(2, 4),
        K::Mat3x2 => Type::mat(3, 2),
        K::Mat3x4 => Type::mat(3, 4),
        K::Mat4x2 => Type::mat(4, 2),
        K::Mat4x3 => Type::mat(4, 3),
        // Every sampler keyword spells its type's name.
        k => return SamplerKind::from_name(k.as_str()).map(|s| Type::new(Base::Sampler(s))),
    })
}

impl Analyzer {
    /// Resolves a type specifier, declaring an in-place struct. Reports and
    /// returns the error type for unknown names.
    pub fn resolve_type(&mut self, ts: &TypeSpecifier) -> Type {
        let base = match &ts.name {
            TypeName::Builtin(k) => match keyword_type(*k) {
                Some(t) => t,
                None => {
                    self.error(
                        Code::Syntax,
                        ts.span,
                        format!("`{}' is not a type", k.as_str()),
                    );
                    return Type::ERROR;
                }
            },
            TypeName::Named(id) => match self.lookup(&id.name) {
                Some(Symbol::Struct(s)) => Type::new(Base::Struct(s)),
                Some(_) => {
                    self.error(
                        Code::Undeclared,
                        id.span,
                        format!("`{}' is not a type", id.name),
                    )
                    .notes
                    .push("only struct names and the built-in type keywords name types".into());
                    return Type::ERROR;
                }
                None => {
                    if let Some(hint) = crate::parse::type_name_hint(&id.name, self.lang) {
                        self.error(
                            Code::Undeclared,
                            id.span,
                            format!("type `{}' undeclared", id.name),
                        )
                        .notes
                        .push(hint);
                        return Type::ERROR;
                    }
                    let sugg = if self.may_suggest(&id.name) {
                        let names = self.struct_names();
                        did_you_mean(&id.name, names.iter().map(|s| s.as_str())).map(str::to_string)
                    } else {
                        None
                    };
                    let d = self.error(
                        Code::Undeclared,
                        id.span,
                        format!("type `{}' undeclared", id.name),
                    );
                    if let Some(s) = sugg {
                        d.notes.push(format!("did you mean `{s}'?"));
                    }
                    return Type::ERROR;
                }
            },
            TypeName::Struct(s) => Type::new(Base::Struct(self.declare_struct(s))),
        };
        match &ts.array {
            None => base,
            Some(spec) => {
                if self.lang.version < Version::V120 {
                    self.error(
                        Code::VersionTooLow,
                        spec.span,
                        "array type syntax (`float[3] x') requires GLSL 1.20",
                    )
                    .notes
                    .push(
                        "put the size after the name (`float x[3]'), or add `#version 120'".into(),
                    );
                }
                self.apply_array(base, Some(spec))
            }
        }
    }

    fn struct_names(&self) -> Vec<String> {
        let mut v: Vec<String> = self
            .visible_names()
            .into_iter()
            .filter(|n| matches!(self.lookup(n), Some(Symbol::Struct(_))))
            .collect();
        v.extend(["float", "int", "bool", "vec4", "mat4"].map(String::from));
        v
    }

    /// Applies the sizes of a declarator or type specifier (`[2][3]`) to
    /// a type, which may be an array already (`float[3] a[2]` is
    /// `float a[2][3]`, as in C). More than one array level needs
    /// GL_ARB_arrays_of_arrays; only the outermost may be unsized.
    pub fn apply_array(&mut self, ty: Type, spec: Option<&ArraySpec>) -> Type {
        let Some(spec) = spec else { return ty };
        let sizes: Vec<ArraySize> = spec.dims.iter().map(|d| self.array_size(d)).collect();
        if ty.is_error() {
            return ty;
        }
        if (ty.is_array() || sizes.len() > 1)
            && !self.require(Feature::ArraysOfArrays, "an array of arrays", spec.span)
        {
            if self.lang.ext_geometry_shader4() {
                if let Some(d) = self.diags.last_mut() {
                    d.notes.push("GL_EXT_geometry_shader4 allows two-dimensional arrays only as geometry shader inputs (`varying in float v[][4];')".into());
                }
            }
            return Type::ERROR;
        }
        let mut t = ty;
        for (i, &size) in sizes.iter().enumerate().rev() {
            if t.is_array() {
                if t.array == Some(ArraySize::Unsized) {
                    // The inner level `t` came from the next dimension, or
                    // from the type itself when `i` is the last.
                    let span = spec.dims.get(i + 1).map_or(spec.span, |d| d.span);
                    self.error(
                        Code::BadArraySize,
                        span,
                        "only the outermost dimension of an array of arrays can be unsized",
                    );
                    return Type::ERROR;
                }
                t = self.array_row(ARRAY_ROW_MEMBER, t);
            }
            t = t.array_of(size);
        }
        t
    }

    /// The size of `[expr]`: a constant integer expression greater than zero
    /// (GLSL 1.20 §4.1.9). `[]` is unsized. Recovers with size 1.
    pub fn array_size(&mut self, spec: &ArrayDim) -> ArraySize {
        let Some(e) = &spec.size else {
            return ArraySize::Unsized;
        };
        let v = self.rvalue(e);
        if v.ty.is_error() {
            return ArraySize::Sized(1);
        }
        if v.ty != Type::INT && v.ty != Type::UINT {
            self.error(
                Code::BadArraySize,
                e.span,
                format!(
                    "array size must be an integer constant expression, found {}",
                    self.tn(v.ty)
                ),
            );
            return ArraySize::Sized(1);
        }
        let Some(n) = (match &v.kind {
            // A uint past i32::MAX is as out of range as the largest int.
            crate::ir::ExprKind::Const(c) => match c.components.as_slice() {
                [crate::ir::ConstScalar::Uint(u)] => Some(i32::try_from(*u).unwrap_or(i32::MAX)),
                _ => const_int(c),
            },
            _ => None,
        }) else {
            self.error(
                Code::NotConstant,
                e.span,
                "array size is not a constant expression",
            )
            .notes
            .push("use literals, `const' variables and built-in functions of constants".into());
            return ArraySize::Sized(1);
        };
        if n <= 0 {
            self.error(
                Code::BadArraySize,
                e.span,
                format!("array size must be greater than zero, found {n}"),
            );
            return ArraySize::Sized(1);
        }
        if n as u32 > MAX_ARRAY_SIZE {
            self.error(
                Code::BadArraySize,
                e.span,
                format!("array size {n} is larger than the supported maximum {MAX_ARRAY_SIZE}"),
            );
            return ArraySize::Sized(1);
        }
        ArraySize::Sized(n as u32)
    }

    /// The element type of an array of arrays whose elements are `row`
    /// (an array type): the one-member row struct
    /// ([`StructDef::array_row`]) with member `member`, shared by every
    /// array of such rows.
    pub(crate) fn array_row(&mut self, member: &str, row: Type) -> Type {
        let name = self.module.type_name(row);
        if let Some(i) = self.module.structs.iter().position(|s| {
            s.array_row
                && s.name == name
                && s.members
                    .first()
                    .is_some_and(|m| m.name == member && m.ty == row)
        }) {
            return Type::new(Base::Struct(StructId(i as u32)));
        }
        let id = StructId(self.module.structs.len() as u32);
        self.module.structs.push(StructDef {
            name,
            members: vec![StructMember {
                name: member.to_string(),
                ty: row,
            }],
            builtin: self.builtin_mode,
            array_row: true,
        });
        Type::new(Base::Struct(id))
    }

    /// The row an element of an array of arrays holds (`float[4]` for an
    /// element of `float a[3][4]`), for a row struct type.
    pub(crate) fn array_row_member(&self, ty: Type) -> Option<Type> {
        if ty.is_array() {
            return None;
        }
        self.module.row_member(ty)
    }

    /// The members of struct `id` (none for an unknown id, which only a
    /// front-end bug could give).
    pub(crate) fn struct_members(&self, id: crate::types::StructId) -> Vec<StructMember> {
        self.module
            .structs
            .get(id.0 as usize)
            .map(|s| s.members.clone())
            .unwrap_or_default()
    }

    /// The innermost element type of an array (of arrays) and how many
    /// of them it holds: `(sampler2D, 8)` for `sampler2D t[2][2][2]`,
    /// `(ty, 1)` for a type that is not an array. An unsized dimension
    /// counts 1.
    pub(crate) fn array_leaf(&self, mut ty: Type) -> (Type, u32) {
        let mut count = 1u32;
        while let Some(size) = ty.array {
            if let ArraySize::Sized(n) = size {
                count = count.saturating_mul(n);
            }
            let et = ty.element();
            ty = self.array_row_member(et).unwrap_or(et);
        }
        (ty, count)
    }

    /// Declares a struct type (GLSL 1.20 §4.1.8) in the current scope.
    pub fn declare_struct(&mut self, s: &StructSpecifier) -> StructId {
        let mut members: Vec<StructMember> = Vec::new();
        for m in &s.members {
            // Precision qualifiers are the only ones a member may have
            // (GLSL 1.30 §4.5.2).
            let mut precision = None;
            for q in m.qualifiers.iter().filter(|q| q.qualifier.is_precision()) {
                self.precision_qualifier(q, &mut precision);
            }
            if let Some(q) = m.qualifiers.iter().find(|q| !q.qualifier.is_precision()) {
                self.error(
                    Code::BadQualifier,
                    q.span,
                    format!(
                        "struct members cannot have qualifiers, found `{}'",
                        q.qualifier.as_str()
                    ),
                );
            }
            if let TypeName::Struct(inner) = &m.ty.name {
                if !self.builtin_mode {
                    self.error(
                        Code::BadQualifier,
                        inner.span,
                        "struct definitions cannot be nested inside a struct",
                    )
                    .notes
                    .push("declare the inner struct first, then use its name".into());
                }
            }
            let ty = self.resolve_type(&m.ty);
            for d in &m.declarators {
                let mty = self.apply_array(ty, d.array.as_ref());
                self.check_precision(precision, mty);
                if mty.base == Base::Void {
                    self.error(
                        Code::TypeMismatch,
                        d.name.span,
                        format!("struct member `{}' cannot be void", d.name.name),
                    );
                }
                if mty.array == Some(ArraySize::Unsized) {
                    self.error(
                        Code::BadArraySize,
                        d.span,
                        format!("struct member `{}' must have an array size", d.name.name),
                    );
                }
                self.check_reserved_name(&d.name.name, d.name.span);
                if members.iter().any(|x| x.name == d.name.name.as_str()) {
                    self.error(
                        Code::Redeclared,
                        d.name.span,
                        format!("struct member `{}' declared twice", d.name.name),
                    );
                    continue;
                }
                members.push(StructMember {
                    name: d.name.name.to_string(),
                    ty: mty,
                });
            }
        }
        let id = StructId(self.module.structs.len() as u32);
        let name = s
            .name
            .as_ref()
            .map_or_else(|| "<anonymous>".to_string(), |n| n.name.to_string());
        self.module.structs.push(StructDef {
            name,
            members,
            builtin: self.builtin_mode,
            array_row: false,
        });
        if let Some(n) = &s.name {
            self.check_reserved_name(&n.name, n.span);
            if self.scopes.lookup_current(&n.name).is_some() {
                self.error(
                    Code::Redeclared,
                    n.span,
                    format!("`{}' is already declared in this scope", n.name),
                );
            } else {
                self.scopes.insert(n.name.clone(), Symbol::Struct(id));
            }
        }
        id
    }

    /// True when the type is or contains a sampler (uniform-only types).
    pub fn contains_sampler(&self, ty: Type) -> bool {
        self.contains(ty, &|t| t.is_sampler(), 0)
    }

    /// True when the type is or contains an array (no `==`/`=` in 1.10).
    pub fn contains_array(&self, ty: Type) -> bool {
        self.contains(ty, &|t| t.is_array(), 0)
    }

    fn contains(&self, ty: Type, pred: &dyn Fn(Type) -> bool, depth: u32) -> bool {
        if pred(ty) {
            return true;
        }
        if depth > 64 {
            return false;
        }
        match ty.base {
            Base::Struct(id) => self.module.structs.get(id.0 as usize).is_some_and(|s| {
                s.members
                    .iter()
                    .any(|m| self.contains(m.ty, pred, depth + 1))
            }),
            _ => false,
        }
    }

    /// User names may not start with `gl_` (GLSL 1.20 §3.7).
    pub fn check_reserved_name(&mut self, name: &str, span: crate::source::Span) -> bool {
        if !self.builtin_mode && name.starts_with("gl_") {
            self.error(
                Code::Redeclared,
                span,
                format!("`{name}': names starting with `gl_' are reserved for the implementation"),
            )
            .notes
            .push("rename it".into());
            return false;
        }
        true
    }
}
