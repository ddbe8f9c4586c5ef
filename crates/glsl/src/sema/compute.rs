//! The compute stage's language (GL_ARB_compute_shader, GLSL 4.30 §4.4.1.4
//! and §7.1): the work-group size a shader declares with
//! `layout(local_size_x = X, local_size_y = Y, local_size_z = Z) in;`, and
//! `gl_WorkGroupSize`, the constant it becomes.

use super::interface::VarQuals;
use super::Analyzer;
use crate::diag::Code;
use crate::ir::{self, ConstScalar, ConstValue, Stage};
use crate::limits;
use crate::source::Span;
use crate::types::{Scalar, Type};

impl Analyzer {
    /// `layout(local_size_x = X, ...) in;`: the size, each dimension left
    /// out being 1, is within the limits, and every such declaration of
    /// the shader gives the same size.
    pub(crate) fn compute_layout(&mut self, q: &VarQuals) {
        let l = &q.layout;
        let span = l.span.unwrap_or(q.storage_span);
        if l.location.is_some() || l.binding.is_some() || !l.primitive.is_empty() {
            self.error(
                Code::BadQualifier,
                span,
                "a compute shader's `layout(...) in;' takes only local_size_x, local_size_y and local_size_z",
            );
        }
        if l.local_size.iter().all(Option::is_none) {
            return;
        }
        let mut size = [1u32; 3];
        for (d, (given, max)) in l
            .local_size
            .iter()
            .zip(limits::MAX_COMPUTE_WORK_GROUP_SIZE)
            .enumerate()
        {
            let Some((v, s)) = *given else { continue };
            let name = ["local_size_x", "local_size_y", "local_size_z"][d];
            if v == 0 || v > max {
                self.error(
                    Code::BadQualifier,
                    s,
                    format!("`{name} = {v}' is out of range: a work group has 1 to {max} invocations along that axis"),
                );
                return;
            }
            size[d] = v;
        }
        let total = u64::from(size[0]) * u64::from(size[1]) * u64::from(size[2]);
        if total > u64::from(limits::MAX_COMPUTE_WORK_GROUP_INVOCATIONS) {
            self.error(
                Code::BadQualifier,
                span,
                format!(
                    "a work group of {} x {} x {} = {total} invocations is more than the {} of GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS",
                    size[0],
                    size[1],
                    size[2],
                    limits::MAX_COMPUTE_WORK_GROUP_INVOCATIONS
                ),
            );
            return;
        }
        match self.module.local_size {
            Some(prev) if prev != size => {
                self.error(
                    Code::BadQualifier,
                    span,
                    format!(
                        "the work-group size {} x {} x {} differs from the {} x {} x {} declared before",
                        size[0], size[1], size[2], prev[0], prev[1], prev[2]
                    ),
                )
                .notes
                .push("a shader may declare its size several times, always the same (a dimension left out is 1)".into());
            }
            _ => self.module.local_size = Some(size),
        }
    }

    /// A `local_size_*` identifier anywhere but a compute shader's
    /// `layout(...) in;`.
    pub(crate) fn misplaced_local_size(&mut self, span: Span) {
        let msg = if self.stage == Stage::Compute {
            "the work-group size is declared on its own: `layout(local_size_x = 64) in;'"
                .to_string()
        } else {
            format!(
                "`local_size_*' belongs to compute shaders, not to a {} shader",
                self.stage.name()
            )
        };
        self.error(Code::BadQualifier, span, msg);
    }

    /// `gl_WorkGroupSize` in a compute shader: the constant `uvec3` of the
    /// size declared so far; using it before (or without) a declaration is
    /// an error (GLSL 4.30 §7.1).
    pub(crate) fn work_group_size(&mut self, span: Span) -> ir::Expr {
        match self.module.local_size {
            Some(size) => super::const_expr(
                ConstValue {
                    ty: Type::vec(Scalar::Uint, 3),
                    components: size.iter().map(|&v| ConstScalar::Uint(v)).collect(),
                },
                span,
            ),
            None => {
                self.error(
                    Code::Undeclared,
                    span,
                    "`gl_WorkGroupSize' is used before the shader declares its work-group size",
                )
                .notes
                .push("declare the size first: `layout(local_size_x = 64) in;'".into());
                super::error_expr(span)
            }
        }
    }
}
