//! When declarations in different shader objects or stages have the same
//! type (GLSL 1.20 §4.3 "shared globals", 1.50 §4.3.7 blocks), and how many
//! components a type takes against the limits.

use crate::ir::Module;
use crate::types::{ArraySize, Base, StructDef, Type};

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

/// [`compatible_types`] for declarations in two modules (two stages),
/// whose struct ids differ: structs are the same type when their names,
/// member names and member types are (GLSL 1.50 §4.3.4: matching
/// interfaces), compared member by member.
pub(super) fn same_type_across(am: &Module, a: Type, bm: &Module, b: Type) -> bool {
    let arrays = match (a.array, b.array) {
        (None, None) => true,
        (Some(ArraySize::Sized(x)), Some(ArraySize::Sized(y))) => x == y,
        (Some(_), Some(_)) => true,
        _ => false,
    };
    arrays && same_base_across(am, a.base, bm, b.base, (true, 0))
}

/// [`same_type_across`] for an input and the output of another stage
/// matched by location (GL_ARB_separate_shader_objects, "Shader Interface
/// Matching"): structures match when their members match in name, type
/// and order, whatever the structures' names.
pub(super) fn same_type_by_location(am: &Module, a: Type, bm: &Module, b: Type) -> bool {
    a.array == b.array && same_base_across(am, a.base, bm, b.base, (false, 0))
}

fn same_base_across(
    am: &Module,
    a: Base,
    bm: &Module,
    b: Base,
    (names, depth): (bool, u32),
) -> bool {
    match (a, b) {
        (Base::Struct(x), Base::Struct(y)) => {
            let (Some(x), Some(y)) = (am.structs.get(x.0 as usize), bm.structs.get(y.0 as usize))
            else {
                return false;
            };
            // Struct nesting is bounded by the compiler; the depth guard
            // only keeps a malformed module from recursing forever.
            depth < 64
                && (!names || x.name == y.name)
                && x.members.len() == y.members.len()
                && x.members.iter().zip(&y.members).all(|(p, q)| {
                    p.name == q.name
                        && p.ty.array == q.ty.array
                        && same_base_across(am, p.ty.base, bm, q.ty.base, (names, depth + 1))
                })
        }
        _ => a == b,
    }
}

/// Components a value of this type occupies, for the limits.
pub(super) fn components(m: &Module, ty: Type) -> u32 {
    crate::consteval::flat_size(ty, &m.structs).min(u32::MAX as usize) as u32
}
