//! Uniform blocks (GL 3.3 §2.11.4 "Uniform Blocks", GLSL 1.40 §4.3.5.1):
//! the standard (std140) layout of block members (its rules are the
//! language's, `glsl::layout`), the active-block records
//! of a linked program, the block limits, and the decoding of block
//! members from buffer bytes. The entry points are
//! [`crate::program_blocks`].
//!
//! Contract: every block uses the std140 layout, whatever its layout
//! qualifier (`shared` and `packed` leave the layout to the
//! implementation; std140 is one). Members are read at each draw from the
//! uniform buffer binding point the block's binding selects (the bound
//! range, or the whole store after glBindBufferBase) into the words the
//! executor reads for the member's global, flattened as
//! [`crate::uniform`] describes; bytes past the end of the range or the
//! store (or no buffer bound) read as 0, which is what Mesa effectively
//! gives. Row-major matrices are transposed on the way in.

use glsl::layout::{self, Rules};
use glsl::types::{ArraySize, Base, Scalar, StructDef, Type};

/// GL_MAX_UNIFORM_BLOCK_SIZE in bytes.
pub const MAX_UNIFORM_BLOCK_SIZE: usize = 65536;
/// GL_MAX_VERTEX_UNIFORM_BLOCKS, GL_MAX_GEOMETRY_UNIFORM_BLOCKS and
/// GL_MAX_FRAGMENT_UNIFORM_BLOCKS (GL 3.3's minimum).
pub const MAX_STAGE_UNIFORM_BLOCKS: usize = 12;
/// GL_MAX_COMBINED_UNIFORM_BLOCKS (GL 3.3's minimum).
pub const MAX_COMBINED_UNIFORM_BLOCKS: usize = 36;
/// The std140 stride between matrix columns (or rows): a vec4.
pub const MATRIX_STRIDE: usize = 16;

/// GL_MAX_COMBINED_{VERTEX,FRAGMENT}_UNIFORM_COMPONENTS: a stage's
/// default-block components plus all its blocks' (GL 3.3 Table 6.43).
pub fn combined_components(default_block: i64) -> i64 {
    default_block + (MAX_STAGE_UNIFORM_BLOCKS * MAX_UNIFORM_BLOCK_SIZE / 4) as i64
}

/// The element count of an array type.
fn array_len(ty: Type) -> Option<u32> {
    match ty.array {
        Some(ArraySize::Sized(n)) => Some(n),
        Some(ArraySize::Unsized) => Some(0),
        None => None,
    }
}

/// Base alignment and size of a value of `ty` in std140, the layout every
/// uniform block gets (`glsl::layout`).
pub fn std140(ty: Type, structs: &[StructDef], row_major: bool) -> (usize, usize) {
    layout::size_align(ty, structs, row_major, Rules::Std140)
}

/// Alignment and stride of the elements of an array of `elem` in std140.
pub fn array_layout(elem: Type, structs: &[StructDef], row_major: bool) -> (usize, usize) {
    layout::array_layout(elem, structs, row_major, Rules::Std140)
}

/// Offsets of a block's members (each with its own row-major flag) and
/// the block's data size (GL_UNIFORM_BLOCK_DATA_SIZE), in std140.
pub fn block_offsets(members: &[(Type, bool)], structs: &[StructDef]) -> (Vec<usize>, usize) {
    layout::block_offsets(members, structs, Rules::Std140)
}

/// Appends the executor words of a value of `ty` stored at byte `off` of
/// `bytes` in std140 (0 for bytes outside `bytes`).
pub fn decode(
    ty: Type,
    structs: &[StructDef],
    row_major: bool,
    off: usize,
    bytes: &[u8],
    out: &mut Vec<u32>,
) {
    let rd = |o: usize| {
        o.checked_add(4)
            .and_then(|e| bytes.get(o..e))
            .map_or(0, |b| u32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
    };
    if let Some(n) = array_len(ty) {
        let elem = ty.element();
        let (_, stride) = array_layout(elem, structs, row_major);
        for i in 0..n as usize {
            decode(elem, structs, row_major, off + i * stride, bytes, out);
        }
        return;
    }
    match ty.base {
        Base::Scalar(s) | Base::Vector(s, _) => {
            let n = ty.vector_size().unwrap_or(1) as usize;
            for c in 0..n {
                let w = rd(off + 4 * c);
                // Bools are read as uints: any non-zero value is true.
                out.push(if s == Scalar::Bool {
                    u32::from(w != 0)
                } else {
                    w
                });
            }
        }
        Base::Matrix { cols, rows } => {
            for c in 0..cols as usize {
                for r in 0..rows as usize {
                    out.push(rd(if row_major {
                        off + r * MATRIX_STRIDE + 4 * c
                    } else {
                        off + c * MATRIX_STRIDE + 4 * r
                    }));
                }
            }
        }
        Base::Struct(id) => {
            let Some(s) = structs.get(id.0 as usize) else {
                return;
            };
            let members: Vec<(Type, bool)> = s.members.iter().map(|m| (m.ty, row_major)).collect();
            let (offsets, _) = block_offsets(&members, structs);
            for ((ty, _), o) in members.into_iter().zip(offsets) {
                decode(ty, structs, row_major, off + o, bytes, out);
            }
        }
        _ => out.resize(out.len() + exec::size_of(ty, structs), 0),
    }
}

/// An active uniform block of a program (an array of blocks gives one per
/// element, GL 3.3 §2.11.4).
#[derive(Clone, Debug)]
pub struct ActiveBlock {
    /// `"B"`, or `"B[2]"` for an element of an array of blocks.
    pub name: String,
    /// GL_UNIFORM_BLOCK_DATA_SIZE.
    pub data_size: usize,
    /// The uniform buffer binding point (glUniformBlockBinding; 0 after
    /// a link).
    pub binding: u32,
    /// Declared by the vertex, geometry, fragment stage.
    pub referenced: [bool; 3],
    /// The active uniforms (leaf indices) of the block.
    pub uniforms: Vec<usize>,
}

/// Where a block member leaf lives in its buffer (glGetActiveUniformsiv).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BlockLeaf {
    /// The active block (the first element, for an array of blocks).
    pub block: usize,
    pub offset: usize,
    /// Bytes between array elements (0 for a non-array).
    pub array_stride: usize,
    /// Bytes between matrix columns or rows (0 for a non-matrix).
    pub matrix_stride: usize,
    pub row_major: bool,
}

/// A global of the executor that holds block members: a member of a
/// block without an instance name, or a (possibly arrayed) instance.
#[derive(Clone, Debug)]
pub struct BlockGlobal {
    pub name: String,
    /// The stage whose module declares the types.
    pub stage: usize,
    /// The active block of element 0.
    pub first_block: usize,
    /// Block elements the global spans (1 unless an array of blocks).
    pub elements: usize,
    /// The members it holds: type, byte offset in the block, row-major.
    pub members: Vec<(Type, usize, bool)>,
}

/// GL_INVALID_INDEX: glGetUniformBlockIndex / glGetUniformIndices for a
/// name that is not active.
pub const INVALID_INDEX: u32 = u32::MAX;

/// The link-time limits of uniform blocks (GL 3.3 §2.11.4): blocks per
/// stage, blocks of all stages, and the size of each.
pub fn check_limits(blocks: &[ActiveBlock], modules: &[&glsl::ir::Module]) -> Result<(), String> {
    for b in blocks {
        if b.data_size > MAX_UNIFORM_BLOCK_SIZE {
            return Err(format!(
                "uniform block `{}' needs {} bytes, more than GL_MAX_UNIFORM_BLOCK_SIZE ({MAX_UNIFORM_BLOCK_SIZE})",
                b.name, b.data_size
            ));
        }
    }
    let mut total = 0;
    for m in modules {
        let slot = match m.stage {
            glsl::Stage::Vertex => 0,
            glsl::Stage::Geometry => 1,
            _ => 2,
        };
        let n = blocks.iter().filter(|b| b.referenced[slot]).count();
        if n > MAX_STAGE_UNIFORM_BLOCKS {
            return Err(format!(
                "the {} shader uses {n} uniform blocks, more than {MAX_STAGE_UNIFORM_BLOCKS}",
                m.stage.name()
            ));
        }
        total += n;
    }
    if total > MAX_COMBINED_UNIFORM_BLOCKS {
        return Err(format!(
            "the program uses {total} uniform blocks, more than GL_MAX_COMBINED_UNIFORM_BLOCKS ({MAX_COMBINED_UNIFORM_BLOCKS})"
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn std140_rules() {
        let f = Type::FLOAT;
        let v2 = Type::vec(Scalar::Float, 2);
        let v3 = Type::vec(Scalar::Float, 3);
        let m3 = Type::mat(3, 3);
        let m2x4 = Type::mat(2, 4);
        let farr = f.array_of(glsl::types::ArraySize::Sized(3));
        let (offs, size) = block_offsets(
            &[
                (f, false),
                (v2, false),
                (v3, false),
                (f, false),
                (farr, false),
                (m3, false),
                (m2x4, true),
                (v2, false),
            ],
            &[],
        );
        // float 0; vec2 at 8; vec3 at 16; float packs after it at 28; the
        // array rounds to 32 with a 16-byte stride (48 bytes); mat3 is three
        // vec4 columns at 80; row-major mat2x4 is four rows at 128; vec2 at
        // 192; the block ends at 200, rounded to 208.
        assert_eq!(offs, vec![0, 8, 16, 28, 32, 80, 128, 192]);
        assert_eq!(size, 208);
        assert_eq!(array_layout(v3, &[], false), (16, 16));
        assert_eq!(array_layout(m2x4, &[], false), (16, 32));
    }

    #[test]
    fn decode_transposes_row_major() {
        let bytes: Vec<u8> = (0..16u32)
            .flat_map(|i| (i as f32).to_bits().to_ne_bytes())
            .collect();
        let mut cm = Vec::new();
        decode(Type::mat(2, 2), &[], false, 0, &bytes, &mut cm);
        let mut rm = Vec::new();
        decode(Type::mat(2, 2), &[], true, 0, &bytes, &mut rm);
        let f = |v: Vec<u32>| v.into_iter().map(f32::from_bits).collect::<Vec<_>>();
        // Column-major: columns at 0 and 16 bytes (words 0 and 4).
        assert_eq!(f(cm), vec![0.0, 1.0, 4.0, 5.0]);
        // Row-major: rows at words 0 and 4; column c is (row0[c], row1[c]).
        assert_eq!(f(rm), vec![0.0, 4.0, 1.0, 5.0]);
        // Past the end: zeros.
        let mut short = Vec::new();
        decode(
            Type::vec(Scalar::Float, 4),
            &[],
            false,
            56,
            &bytes,
            &mut short,
        );
        assert_eq!(short, vec![14f32.to_bits(), 15f32.to_bits(), 0, 0]);
    }
}
