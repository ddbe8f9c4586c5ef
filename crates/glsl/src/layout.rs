//! Where a block's members lie in its buffer: the standard layouts of
//! uniform and shader storage blocks, rules of the language the GL layer
//! (reading uniform blocks, answering offset queries) and the executor
//! (addressing storage blocks) must agree on.
//!
//! - std140: GL 3.3 §2.11.4 "Standard Uniform Block Layout", rules 1–10.
//!   The `shared` and `packed` layouts leave the layout to the
//!   implementation; shaderbox gives them std140's.
//! - std430: GL 4.3 §7.6.2.2, std140 without rounding the alignment of
//!   arrays and structures (and so of matrices' columns) up to a vec4's;
//!   shader storage blocks only (GL_ARB_shader_storage_buffer_object).
//!
//! Sizes and offsets are in bytes. An array of unknown size (a storage
//! block's last member) counts as empty: its elements begin at its offset
//! and follow at its stride.

use crate::ir::BlockLayout;
use crate::types::{ArraySize, Base, StructDef, Type};

/// The two standard rule sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rules {
    Std140,
    Std430,
}

impl Rules {
    /// The rules of a block declared with `layout`.
    pub fn of(layout: BlockLayout) -> Rules {
        match layout {
            BlockLayout::Std430 => Rules::Std430,
            BlockLayout::Std140 | BlockLayout::Shared | BlockLayout::Packed => Rules::Std140,
        }
    }

    /// The alignment an array's elements or a structure get at least
    /// (std140's rules 4 and 9: a vec4's; std430: none).
    fn aggregate_align(self) -> usize {
        match self {
            Rules::Std140 => 16,
            Rules::Std430 => 1,
        }
    }
}

fn round_up(x: usize, a: usize) -> usize {
    x.div_ceil(a.max(1)) * a.max(1)
}

/// Base alignment and size of a value of `ty` (`row_major`: matrices
/// stored row by row).
pub fn size_align(
    ty: Type,
    structs: &[StructDef],
    row_major: bool,
    rules: Rules,
) -> (usize, usize) {
    if let Some(size) = ty.array {
        let n = match size {
            ArraySize::Sized(n) => n as usize,
            ArraySize::Unsized => 0,
        };
        let (align, stride) = array_layout(ty.element(), structs, row_major, rules);
        return (align, stride * n);
    }
    match ty.base {
        Base::Scalar(_) => (4, 4),
        Base::Vector(_, 2) => (8, 8),
        Base::Vector(_, n) => (16, 4 * n as usize),
        // Rules 5 and 7: an array of column (or row) vectors.
        Base::Matrix { cols, rows } => {
            let (count, len) = if row_major {
                (rows, cols)
            } else {
                (cols, rows)
            };
            let stride = matrix_stride(len, rules);
            (stride, stride * count as usize)
        }
        Base::Struct(id) => {
            let Some(s) = structs.get(id.0 as usize) else {
                return (rules.aggregate_align(), 0);
            };
            let mut at = 0;
            let mut align = rules.aggregate_align();
            for m in &s.members {
                let (a, size) = size_align(m.ty, structs, row_major, rules);
                at = round_up(at, a) + size;
                align = align.max(a);
            }
            (align, round_up(at, align))
        }
        _ => (4, 0),
    }
}

/// The stride between a matrix's columns (rows when row-major) of `len`
/// components: std140 rounds each up to a vec4; std430 gives it its
/// vector's alignment (8 for two components, else 16).
pub fn matrix_stride(len: u8, rules: Rules) -> usize {
    match (rules, len) {
        (Rules::Std430, 2) => 8,
        _ => 16,
    }
}

/// Alignment and stride of the elements of an array of `elem`.
pub fn array_layout(
    elem: Type,
    structs: &[StructDef],
    row_major: bool,
    rules: Rules,
) -> (usize, usize) {
    let (a, size) = size_align(elem, structs, row_major, rules);
    let align = round_up(a, rules.aggregate_align());
    (align, round_up(size, align))
}

/// Offsets of a block's members (each with its own row-major flag) and
/// the block's data size (GL_UNIFORM_BLOCK_DATA_SIZE: the end of the last
/// member rounded up to the block's alignment, a vec4's in std140).
pub fn block_offsets(
    members: &[(Type, bool)],
    structs: &[StructDef],
    rules: Rules,
) -> (Vec<usize>, usize) {
    let mut offsets = Vec::with_capacity(members.len());
    let mut at = 0;
    let mut align = rules.aggregate_align();
    for &(ty, rm) in members {
        let (a, size) = size_align(ty, structs, rm, rules);
        at = round_up(at, a);
        offsets.push(at);
        at += size;
        align = align.max(a);
    }
    (offsets, round_up(at, align))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::types::{Scalar, StructMember};

    fn v(n: u8) -> Type {
        Type::vec(Scalar::Float, n)
    }

    #[test]
    fn std140_rounds_arrays_and_structs_up_to_a_vec4() {
        let r = Rules::Std140;
        assert_eq!(array_layout(Type::FLOAT, &[], false, r), (16, 16));
        assert_eq!(array_layout(v(3), &[], false, r), (16, 16));
        assert_eq!(array_layout(Type::mat(2, 4), &[], false, r), (16, 32));
        assert_eq!(size_align(Type::mat(3, 2), &[], false, r), (16, 48));
        assert_eq!(size_align(Type::mat(3, 2), &[], true, r), (16, 32));
        // float, vec3 (at 16), float[2] (at 32, stride 16), vec2 (at 64).
        let (offs, size) = block_offsets(
            &[
                (Type::FLOAT, false),
                (v(3), false),
                (Type::FLOAT.array_of(ArraySize::Sized(2)), false),
                (v(2), false),
            ],
            &[],
            r,
        );
        assert_eq!(offs, [0, 16, 32, 64]);
        assert_eq!(size, 80);
    }

    #[test]
    fn std430_packs_arrays_structs_and_matrix_columns_tighter() {
        let r = Rules::Std430;
        assert_eq!(array_layout(Type::FLOAT, &[], false, r), (4, 4));
        assert_eq!(array_layout(v(2), &[], false, r), (8, 8));
        // vec3 elements still take 16 bytes (a vec3's alignment).
        assert_eq!(array_layout(v(3), &[], false, r), (16, 16));
        assert_eq!(size_align(Type::mat(2, 2), &[], false, r), (8, 16));
        assert_eq!(size_align(Type::mat(2, 3), &[], false, r), (16, 32));
        let s = StructDef {
            name: "S".into(),
            members: vec![
                StructMember {
                    name: "a".into(),
                    ty: Type::FLOAT,
                },
                StructMember {
                    name: "b".into(),
                    ty: v(2),
                },
            ],
            builtin: false,
            array_row: false,
        };
        let st = Type::new(Base::Struct(crate::types::StructId(0)));
        assert_eq!(size_align(st, std::slice::from_ref(&s), false, r), (8, 16));
        assert_eq!(
            size_align(st, std::slice::from_ref(&s), false, Rules::Std140),
            (16, 16)
        );
        // int, float[3] (at 4, stride 4), then an array of unknown size
        // of vec2 (at 16): the block's size is where it starts.
        let (offs, size) = block_offsets(
            &[
                (Type::INT, false),
                (Type::FLOAT.array_of(ArraySize::Sized(3)), false),
                (v(2).array_of(ArraySize::Unsized), false),
            ],
            &[],
            r,
        );
        assert_eq!(offs, [0, 4, 16]);
        assert_eq!(size, 16);
    }
}
