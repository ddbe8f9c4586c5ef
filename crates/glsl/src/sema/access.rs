//! Access to parts of values (GLSL 1.20 §5.5-5.7): array and vector
//! indexing, struct fields, swizzles, `.length()`, and the l-value checks
//! of everything that is written.

use super::expr::mk;
use super::scope::{Symbol, Var};
use super::{const_expr, const_int, error_expr, Analyzer};
use crate::ast::{self, ExprKind as A};
use crate::diag::{did_you_mean, Code};
use crate::ir::{self, ExprKind as K, Stage, Storage};
use crate::lang::Version;
use crate::limits::MAX_TEXTURE_COORDS;
use crate::source::Span;
use crate::types::{ArraySize, Base, Scalar, Type};

/// Parses a swizzle: one naming set, 1 to 4 components, each within `size`.
fn parse_swizzle(name: &str, size: u8) -> Result<([u8; 4], u8), String> {
    const SETS: [&str; 3] = ["xyzw", "rgba", "stpq"];
    if name.len() > 4 {
        return Err(format!("swizzle `{name}' has more than 4 components"));
    }
    let mut set = None;
    let mut comps = [0u8; 4];
    for (i, c) in name.chars().enumerate() {
        let found = SETS
            .iter()
            .enumerate()
            .find_map(|(s, letters)| letters.find(c).map(|p| (s, p)));
        let Some((s, p)) = found else {
            return Err(format!(
                "`{c}' is not a vector component (use xyzw, rgba or stpq)"
            ));
        };
        if *set.get_or_insert(s) != s {
            return Err(format!(
                "swizzle `{name}' mixes component sets (xyzw, rgba, stpq)"
            ));
        }
        if p as u8 >= size {
            return Err(format!(
                "swizzle `{name}' selects component `{c}' of a {size}-component vector"
            ));
        }
        if i < 4 {
            comps[i] = p as u8;
        }
    }
    if name.is_empty() {
        return Err("empty swizzle".into());
    }
    Ok((comps, name.len() as u8))
}

impl Analyzer {
    /// The bound a constant index must respect for an unsized built-in
    /// array (`gl_TexCoord[]`: gl_MaxTextureCoords; `gl_ClipDistance[]`
    /// and `gl_in[i]`'s members: their limits, GLSL 1.50 §7.1).
    pub(super) fn builtin_unsized_bound(&self, base: &ir::Expr) -> Option<u32> {
        match base.kind {
            K::Global(g) => {
                let g = self.module.globals.get(g.0 as usize)?;
                (g.builtin && g.ty.array == Some(ArraySize::Unsized)).then_some(MAX_TEXTURE_COORDS)
            }
            // `gl_in[i].gl_ClipDistance[]' (and the compatibility
            // profile's `gl_in[i].gl_TexCoord[]'): bounded by the limit of
            // the output it reads.
            K::Member { ref base, index } => {
                let Base::Struct(sid) = base.ty.base else {
                    return None;
                };
                let def = self.module.structs.get(sid.0 as usize)?;
                let m = def.members.get(index as usize)?;
                if !def.builtin || m.ty.array != Some(ArraySize::Unsized) {
                    return None;
                }
                Some(if m.name == "gl_TexCoord" {
                    MAX_TEXTURE_COORDS
                } else {
                    crate::limits::MAX_CLIP_DISTANCES
                })
            }
            _ => None,
        }
    }

    pub(super) fn note_implicit_index(&mut self, base: &ir::Expr, i: u32) {
        match base.kind {
            K::Global(g) => {
                if let Some(g) = self.module.globals.get_mut(g.0 as usize) {
                    g.implicit_size = g.implicit_size.max(i + 1);
                }
            }
            K::Local(l) => {
                if let Some(s) = self
                    .cur
                    .as_mut()
                    .and_then(|f| f.implicit.get_mut(l.0 as usize))
                {
                    *s = (*s).max(i + 1);
                }
            }
            // `inst.m[i]', `inst[k].m[i]' or `inst[k][l].m[i]': the member
            // of a block's named instance.
            K::Member { ref base, index } => {
                let mut root = &**base;
                for _ in 0..64 {
                    match &root.kind {
                        K::Index { base, .. } => root = base,
                        // The row of an array of arrays of instances.
                        K::Member { base, .. } if self.array_row_member(base.ty).is_some() => {
                            root = base
                        }
                        _ => break,
                    }
                }
                let K::Global(g) = root.kind else { return };
                let Some(b) = self
                    .module
                    .globals
                    .get(g.0 as usize)
                    .filter(|g| !g.builtin)
                    .and_then(|g| g.block)
                else {
                    return;
                };
                if let Some(m) = self
                    .module
                    .blocks
                    .get_mut(b.0 as usize)
                    .and_then(|b| b.members.get_mut(index as usize))
                {
                    m.implicit_size = m.implicit_size.max(i + 1);
                }
            }
            _ => {}
        }
    }

    /// Whether a constant index past the end of `base` is left to the
    /// link ([`super::Context::defer_input_index`]): `base` is a geometry
    /// input array itself, not one of its elements.
    fn defers_input_index(&self, base: &ir::Expr) -> bool {
        let K::Global(g) = base.kind else {
            return false;
        };
        self.defer_input_index
            && self
                .module
                .globals
                .get(g.0 as usize)
                .is_some_and(|g| g.storage == ir::Storage::PerVertexInput)
    }

    /// `base[index]` on an array, vector or matrix.
    pub(super) fn index(&mut self, base: ir::Expr, i: &ast::Expr, span: Span) -> ir::Expr {
        let iv = self.rvalue(i);
        if base.ty.is_error() || iv.ty.is_error() {
            return error_expr(span);
        }
        if iv.ty != Type::INT && iv.ty != Type::UINT {
            let what = if self.lang.allows(crate::lang::Feature::Unsigned) {
                "an int or uint scalar"
            } else {
                "an int scalar"
            };
            self.error(
                Code::TypeMismatch,
                i.span,
                format!("an index must be {what}, found {}", self.tn(iv.ty)),
            );
            return error_expr(span);
        }
        let cidx = match &iv.kind {
            // A uint past i32::MAX is as out of range as the largest int.
            K::Const(c) => match c.components.as_slice() {
                [ir::ConstScalar::Uint(u)] => Some(i32::try_from(*u).unwrap_or(i32::MAX)),
                _ => const_int(c),
            },
            _ => None,
        };
        if cidx.is_none() && self.is_block_instance_array(&base) {
            // GLSL 1.50 §4.3.7: arrays of uniform blocks are indexed only
            // with integral constant expressions.
            self.error(
                Code::NotConstant,
                i.span,
                "an array of uniform blocks can only be indexed with a constant expression",
            );
            return error_expr(span);
        }
        let t = base.ty;
        // An array of arrays of samplers is an array of samplers at every
        // level.
        let mut innermost = t.element();
        for _ in 0..64 {
            match self.array_row_member(innermost) {
                Some(row) => innermost = row.element(),
                None => break,
            }
        }
        if t.is_array() && innermost.is_sampler() && cidx.is_none() {
            if let Err(why) = self
                .lang
                .gate(crate::lang::Feature::NonConstantSamplerIndex)
            {
                self.error(
                    Code::NotConstant,
                    i.span,
                    why.message("indexing an array of samplers with a non-constant expression", self.lang),
                )
                .notes
                .push("GLSL 1.30 §4.1.7: samplers in arrays can only be indexed with integral constant expressions".into());
                return error_expr(span);
            }
        }
        let (len, ty, what) = match (t.array, t.base) {
            (Some(ArraySize::Sized(n)), _) => (Some(n), t.element(), "array"),
            (Some(ArraySize::Unsized), _) => (None, t.element(), "array"),
            (None, Base::Vector(s, n)) => (Some(n as u32), Type::new(Base::Scalar(s)), "vector"),
            (None, Base::Matrix { cols, rows }) => {
                (Some(cols as u32), Type::vec(Scalar::Float, rows), "matrix")
            }
            _ => {
                self.error(
                    Code::TypeMismatch,
                    span,
                    format!("cannot index a value of type {}", self.tn(t)),
                )
                .notes
                .push("only arrays, vectors and matrices can be indexed".into());
                return error_expr(span);
            }
        };
        if let Some(c) = cidx {
            if c < 0 {
                self.error(
                    Code::IndexOutOfRange,
                    i.span,
                    format!("{what} index {c} is negative"),
                );
                return error_expr(span);
            }
            let bound = len.or_else(|| self.builtin_unsized_bound(&base));
            if let Some(n) = bound.filter(|&n| c as u32 >= n && self.defers_input_index(&base)) {
                let msg = format!("{what} index {c} is out of range for {}", self.tn(t));
                self.push(
                    crate::diag::Diagnostic::warning(Code::IndexOutOfRange, i.span, msg)
                        .with_note(format!("no input primitive has more than {n} vertices (gl_VerticesIn): linking the program fails (GL_EXT_geometry_shader4 §4.3.6)")),
                );
            } else if let Some(n) = bound {
                if c as u32 >= n {
                    self.error(
                        Code::IndexOutOfRange,
                        i.span,
                        format!("{what} index {c} is out of range for {}", self.tn(t)),
                    )
                    .notes
                    .push(format!("valid indices are 0 to {}", n.saturating_sub(1)));
                    return error_expr(span);
                }
            }
            if len.is_none() {
                self.note_implicit_index(&base, c as u32);
            }
        } else if len.is_none()
            && self.buffer_member(&base).is_none()
            && !self.is_unsized_output_patch(&base)
        {
            // (A shader storage block's last member takes any index: its
            // size is the bound buffer's; so does a control shader's
            // per-vertex output before its patch size is known, as
            // `gl_InvocationID' is always within it.)
            // GLSL 1.20 §4.1.9 and, for gl_TexCoord, §7.6: "indices used to
            // subscript gl_TexCoord must either be an integral constant
            // expression, or this array must be re-declared with a size".
            let hint = match base.kind {
                K::Global(g)
                    if self
                        .module
                        .globals
                        .get(g.0 as usize)
                        .is_some_and(|g| g.builtin) =>
                {
                    "redeclare it with a size first, e.g. `varying vec4 gl_TexCoord[4];'"
                }
                _ => "declare the array with an explicit size",
            };
            self.error(
                Code::BadArraySize,
                i.span,
                "an array without a size can only be indexed with constants",
            )
            .notes
            .push(hint.into());
            return error_expr(span);
        }
        let e = self.fold(mk(
            K::Index {
                base: Box::new(base),
                index: Box::new(iv),
            },
            ty,
            span,
        ));
        // An element of an array of arrays is its row.
        match self.array_row_member(ty) {
            Some(row) => mk(
                K::Member {
                    base: Box::new(e),
                    index: 0,
                },
                row,
                span,
            ),
            None => e,
        }
    }

    /// `base.name`: a struct member or a swizzle.
    pub(super) fn field(
        &mut self,
        base: ir::Expr,
        name: &ast::Ident,
        span: Span,
        lvalue: bool,
    ) -> ir::Expr {
        let t = base.ty;
        if t.is_error() {
            return error_expr(span);
        }
        if let (None, Base::Struct(id)) = (t.array, t.base) {
            let members = self.struct_members(id);
            match members.iter().position(|m| m.name == name.name.as_str()) {
                Some(i) => {
                    let ty = members[i].ty;
                    return self.fold(mk(
                        K::Member {
                            base: Box::new(base),
                            index: i as u32,
                        },
                        ty,
                        span,
                    ));
                }
                None => {
                    let sugg = if self.may_suggest(&name.name) {
                        did_you_mean(&name.name, members.iter().map(|m| m.name.as_str()))
                            .map(str::to_string)
                    } else {
                        None
                    };
                    let d = self.error(
                        Code::Undeclared,
                        name.span,
                        format!(
                            "struct {} has no member `{}'",
                            self.module.type_name(t),
                            name.name
                        ),
                    );
                    if let Some(s) = sugg {
                        d.notes.push(format!("did you mean `{s}'?"));
                    }
                    return error_expr(span);
                }
            }
        }
        // GL_ARB_shading_language_420pack: `x`, `r` and `s` name a
        // scalar's only component.
        let scalar = t.is_scalar() && self.lang.allows(crate::lang::Feature::LanguagePack420);
        let size = if scalar {
            Some(1)
        } else {
            t.vector_size().filter(|_| t.is_vector())
        };
        let Some(n) = size else {
            let msg = if t.is_scalar() {
                format!(
                    "cannot select `.{}' of a scalar {} in GLSL {}",
                    name.name,
                    self.tn(t),
                    self.lang.version.dotted()
                )
            } else {
                format!(
                    "cannot select `.{}' of a value of type {}",
                    name.name,
                    self.tn(t)
                )
            };
            self.error(Code::BadSwizzle, name.span, msg);
            return error_expr(span);
        };
        match parse_swizzle(&name.name, n) {
            Ok((components, count)) => {
                if lvalue {
                    let c = &components[..count as usize];
                    if (1..c.len()).any(|i| c[..i].contains(&c[i])) {
                        self.error(
                            Code::NotAnLvalue,
                            name.span,
                            format!(
                                "swizzle `{}' repeats a component and cannot be assigned",
                                name.name
                            ),
                        );
                        return error_expr(span);
                    }
                }
                let s = t.scalar().unwrap_or(Scalar::Float);
                let ty = Type::vec(s, count);
                if scalar {
                    // One component is the scalar itself (an l-value where
                    // the scalar is one), more the vector made from it.
                    return match count {
                        1 => ir::Expr { span, ..base },
                        _ => self.fold(mk(K::Construct { args: vec![base] }, ty, span)),
                    };
                }
                self.fold(mk(
                    K::Swizzle {
                        base: Box::new(base),
                        components,
                        count,
                    },
                    ty,
                    span,
                ))
            }
            Err(msg) => {
                self.error(Code::BadSwizzle, name.span, msg);
                error_expr(span)
            }
        }
    }

    /// `a.length()` (GLSL 1.20 §5.7 for arrays; GL_ARB_shading_language_420pack
    /// for vectors, their number of components, and matrices, their number
    /// of columns).
    pub(super) fn method(
        &mut self,
        b: &ast::Expr,
        name: &ast::Ident,
        args: &[ast::Expr],
        span: Span,
    ) -> ir::Expr {
        let base = self.expr_any(b);
        for a in args {
            let _ = self.rvalue(a);
        }
        if base.ty.is_error() {
            return error_expr(span);
        }
        // An array declared without a size (GL_ARB_shader_storage_buffer_object):
        // a shader storage block's last member has the bound buffer's
        // length, any other the size its uses give it (link time).
        if base.ty.array == Some(ArraySize::Unsized) {
            let variable = matches!(base.kind, K::Global(_) | K::Local(_));
            let known = self.buffer_member(&base).is_some()
                || (variable && self.lang.allows(crate::lang::Feature::StorageBuffers));
            if name.name == "length" && args.is_empty() && known {
                return mk(
                    K::ArrayLength {
                        array: Box::new(base),
                    },
                    Type::INT,
                    span,
                );
            }
            if self.is_unsized_output_patch(&base) {
                self.error(
                    Code::BadArraySize,
                    span,
                    "the output patch size is not declared yet: `.length()' of a per-vertex output needs `layout(vertices = N) out;' before it",
                )
                .notes
                .push("GL_ARB_tessellation_shader §4.3.8.2: the layout sizes gl_out[] and every per-vertex output".into());
                return error_expr(span);
            }
            return self.reject_unsized(base);
        }
        if name.name != "length" {
            self.error(
                Code::Undeclared,
                name.span,
                format!("unknown method `{}'", name.name),
            )
            .notes
            .push("the only method is `.length()' on arrays".into());
            return error_expr(span);
        }
        if self.lang.version < Version::V120 {
            self.error(
                Code::VersionTooLow,
                name.span,
                "`.length()' requires GLSL 1.20",
            );
            return error_expr(span);
        }
        let pack = self.lang.allows(crate::lang::Feature::LanguagePack420);
        let n = match (base.ty.array, base.ty.base) {
            (Some(ArraySize::Sized(n)), _) => n,
            (None, Base::Vector(_, n)) if pack => u32::from(n),
            (None, Base::Matrix { cols, .. }) if pack => u32::from(cols),
            _ => {
                let d = self.error(
                    Code::TypeMismatch,
                    name.span,
                    format!("`.length()' needs an array, found {}", self.tn(base.ty)),
                );
                if base.ty.is_vector() || base.ty.is_matrix() {
                    d.notes.push(
                        "`.length()' of vectors and matrices needs `#extension GL_ARB_shading_language_420pack : enable'".into(),
                    );
                }
                return error_expr(span);
            }
        };
        if !args.is_empty() {
            self.error(Code::TypeMismatch, span, "`.length()' takes no arguments");
            return error_expr(span);
        }
        const_expr(
            ir::ConstValue {
                ty: Type::INT,
                components: vec![ir::ConstScalar::Int(n as i32)],
            },
            span,
        )
    }

    /// An expression that is written (assignment target, `++`, out
    /// argument): checks it is an l-value and marks the variable written
    /// (and read when `also_read`).
    pub fn lvalue(&mut self, e: &ast::Expr, also_read: bool, what: &str) -> ir::Expr {
        let lv = self.lvalue_part(e, also_read, what);
        self.check_memory_access(&lv, true, also_read);
        self.check_whole_output_write(&lv);
        lv
    }

    /// The shader storage block member `e` reads or writes (through
    /// elements, swizzles and struct members of it), if any: the member
    /// of a block without an instance name is its own global; through a
    /// named instance it is the last member selected before the
    /// instance (`buf.m`, `buf[2].m[i].x`).
    fn buffer_member(&self, e: &ir::Expr) -> Option<&ir::BlockMember> {
        let mut cur = e;
        let mut member = None;
        loop {
            match &cur.kind {
                K::Index { base, .. } | K::Swizzle { base, .. } => cur = base,
                K::Member { base, index } => {
                    member = Some(*index as usize);
                    cur = base;
                }
                K::Global(g) => {
                    let gl = self.module.globals.get(g.0 as usize)?;
                    if gl.storage != Storage::Buffer {
                        return None;
                    }
                    let b = self.module.blocks.get(gl.block?.0 as usize)?;
                    return match b.instance {
                        Some(_) => b.members.get(member?),
                        None => b.members.iter().find(|m| m.name == gl.name),
                    };
                }
                _ => return None,
            }
        }
    }

    /// GLSL 4.30 §4.10: a `readonly` buffer member is never written, a
    /// `writeonly` one never read.
    pub(super) fn check_memory_access(&mut self, e: &ir::Expr, write: bool, read: bool) {
        let Some(m) = self.buffer_member(e) else {
            return;
        };
        let (name, readonly, writeonly) = (m.name.clone(), m.readonly, m.writeonly);
        let bad = if write && readonly {
            Some(("written", "readonly"))
        } else if read && writeonly {
            Some(("read", "writeonly"))
        } else {
            None
        };
        if let Some((done, qual)) = bad {
            self.error(
                Code::ReadOnly,
                e.span,
                format!("`{name}' is `{qual}' and cannot be {done}"),
            );
        }
    }

    fn lvalue_part(&mut self, e: &ast::Expr, also_read: bool, what: &str) -> ir::Expr {
        let span = e.span;
        match &e.kind {
            A::Error => error_expr(span),
            A::Ident(id) => {
                let v = match self.lookup(&id.name) {
                    Some(Symbol::Var(v)) => v,
                    _ => return self.ident(id),
                };
                let ty = self.var_type(v);
                match v {
                    Var::Local(l) => {
                        let is_const = self
                            .cur
                            .as_ref()
                            .and_then(|f| f.locals.get(l.0 as usize))
                            .is_some_and(|l| l.is_const);
                        if is_const {
                            self.error(
                                Code::ReadOnly,
                                span,
                                format!("cannot {what} `{}': it is read-only (const)", id.name),
                            );
                            return error_expr(span);
                        }
                        mk(K::Local(l), ty, span)
                    }
                    _ => {
                        let Some(g) = self.global_of(v) else {
                            return error_expr(span);
                        };
                        let gl = &self.module.globals[g.0 as usize];
                        let ro = match gl.storage {
                            Storage::Const => Some("const"),
                            Storage::Uniform => Some("a uniform"),
                            Storage::Attribute => Some("an attribute"),
                            Storage::Varying if self.stage == Stage::Fragment => {
                                Some("a fragment shader input")
                            }
                            Storage::Varying if self.stage == Stage::Compute => {
                                Some("a compute shader input")
                            }
                            Storage::Varying if self.stage == Stage::TessEvaluation && gl.patch => {
                                Some("a per-patch input")
                            }
                            Storage::PerVertexInput if self.stage == Stage::Geometry => {
                                Some("a geometry shader input")
                            }
                            Storage::PerVertexInput => Some("a tessellation shader input"),
                            _ => None,
                        };
                        if let Some(kind) = ro {
                            self.error(
                                Code::ReadOnly,
                                span,
                                format!("cannot {what} `{}': it is {kind} and read-only", id.name),
                            );
                            return error_expr(span);
                        }
                        let builtin = gl.builtin;
                        let gl = &mut self.module.globals[g.0 as usize];
                        gl.written = true;
                        gl.read |= also_read;
                        if builtin && self.stage == Stage::Fragment {
                            if id.name == "gl_FragColor" {
                                self.frag_color_write.get_or_insert(span);
                            } else if id.name == "gl_FragData" {
                                self.frag_data_write.get_or_insert(span);
                            }
                        }
                        mk(K::Global(g), ty, span)
                    }
                }
            }
            A::Index(b, i) => {
                let base = self.lvalue_part(b, also_read, what);
                self.check_output_vertex_index(&base, i);
                self.index(base, i, span)
            }
            A::Field(b, name) => {
                let base = self.lvalue_part(b, also_read, what);
                self.field(base, name, span, true)
            }
            _ => {
                let v = self.rvalue(e);
                if !v.ty.is_error() {
                    self.error(Code::NotAnLvalue, span, format!("cannot {what} this expression: it is not a variable"))
                        .notes
                        .push("only variables, their elements, members and swizzles without repeats can be written".into());
                }
                error_expr(span)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn swizzles() {
        assert_eq!(parse_swizzle("xy", 2), Ok(([0, 1, 0, 0], 2)));
        assert_eq!(parse_swizzle("bgra", 4), Ok(([2, 1, 0, 3], 4)));
        assert!(parse_swizzle("xg", 4).is_err());
        assert!(parse_swizzle("z", 2).is_err());
        assert!(parse_swizzle("xxxxx", 4).is_err());
    }
}
