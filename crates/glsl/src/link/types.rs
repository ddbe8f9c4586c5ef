//! When declarations in different shader objects or stages have the same
//! type (GLSL 1.20 §4.3 "shared globals", 1.50 §4.3.7 blocks), and how many
//! components a type takes against the limits.

use crate::ir::Module;
use crate::types::{ArraySize, StructDef, Type};

/// Two struct definitions are the same type if names, member names and
/// member types match (§4.3, "shared globals").
pub(super) fn same_struct(a: &StructDef, b: &StructDef) -> bool {
    a.name == b.name
        && a.members.len() == b.members.len()
        && a.members
            .iter()
            .zip(&b.members)
            .all(|(x, y)| x.name == y.name && x.ty == y.ty)
}

/// Array types of shared globals agree when the base types are equal and
/// explicit sizes, if both have one, are equal.
pub(super) fn compatible_types(a: Type, b: Type) -> bool {
    if a.base != b.base {
        return false;
    }
    match (a.array, b.array) {
        (None, None) => true,
        (Some(ArraySize::Sized(x)), Some(ArraySize::Sized(y))) => x == y,
        (Some(_), Some(_)) => true,
        _ => false,
    }
}

/// Components a value of this type occupies, for the limits.
pub(super) fn components(m: &Module, ty: Type) -> u32 {
    crate::consteval::flat_size(ty, &m.structs).min(u32::MAX as usize) as u32
}
