//! Built-in functions, variables, constants and uniforms of GLSL 1.10 to 3.30.
//!
//! [`BuiltinFn`] (defined in [`crate::builtin_fn`], the IR's vocabulary)
//! names every built-in function.
//!
//! - [`prelude()`]: the whole built-in environment of a version and stage as
//!   GLSL declarations, which the semantic analyzer reads before the shader.
//! - [`eval_builtin`]: constant folding of built-in calls.

mod eval;
#[cfg(test)]
mod eval_piglit;
mod prelude;

pub use crate::builtin_fn::BuiltinFn;
pub use eval::eval_builtin;
pub(crate) use prelude::replacement;
pub use prelude::{prelude, prelude_for_input};

/// The built-in struct types (GLSL 1.10/1.20 §7.5), in every version and
/// stage of the compatibility profile (the core profile keeps
/// `gl_DepthRangeParameters` only). User shaders may name them as types.
pub const BUILTIN_STRUCT_NAMES: &[&str] = &[
    "gl_DepthRangeParameters",
    "gl_PointParameters",
    "gl_MaterialParameters",
    "gl_LightSourceParameters",
    "gl_LightModelParameters",
    "gl_LightModelProducts",
    "gl_LightProducts",
    "gl_FogParameters",
];

#[cfg(test)]
mod struct_name_tests {
    #[test]
    fn every_builtin_struct_is_declared_by_the_preludes() {
        use crate::{ir::Stage, lang::Language, lang::Version};
        for name in super::BUILTIN_STRUCT_NAMES {
            for v in [Version::V110, Version::V120] {
                for s in [Stage::Vertex, Stage::Fragment] {
                    let text = super::prelude(Language::new(v, true), s);
                    assert!(text.contains(&format!("struct {name} {{")), "{name}");
                }
            }
        }
    }
}
