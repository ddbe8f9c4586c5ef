//! Vertex attribute formats (GL 3.3 §2.8, Tables 2.5-2.7 and 2.9): the
//! size of an element of each type, reading one element from array bytes
//! (normalized or not, BGRA order, half floats, packed 2_10_10_10 words)
//! as floats or as integer bits, and the float view of a stored integer
//! value. Pure functions over bytes: the arrays and buffers that hold the
//! bytes are `vertex`'s.

use crate::enums::*;
use crate::pixel_transfer::half_to_f32;

/// How a current generic attribute value was specified (GL 3.3 §2.7:
/// glVertexAttrib*, glVertexAttribI* with signed or unsigned values).
/// Integer values are kept as their bits in the `f32` slots.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ValueKind {
    #[default]
    Float,
    Int,
    Uint,
}

/// A stored value as floats: integer values (kept as bits) converted.
pub fn float_view(v: [f32; 4], kind: ValueKind) -> [f32; 4] {
    match kind {
        ValueKind::Float => v,
        ValueKind::Int => v.map(|x| x.to_bits() as i32 as f32),
        ValueKind::Uint => v.map(|x| x.to_bits() as f32),
    }
}

/// A stored value as the bits of an integer shader input of `want`
/// (Int or Uint): integer values as they are, float values converted
/// (GL leaves a float value read by an integer input undefined; this is
/// the value's integer part, saturated).
pub fn integer_bits(v: [f32; 4], kind: ValueKind, want: ValueKind) -> [u32; 4] {
    match kind {
        ValueKind::Int | ValueKind::Uint => v.map(f32::to_bits),
        ValueKind::Float if want == ValueKind::Uint => v.map(|x| x as u32),
        ValueKind::Float => v.map(|x| x as i32 as u32),
    }
}

/// Reads one element of an integer array (glVertexAttribIPointer):
/// `size` components of `ty` at `at`, signed types sign-extended, missing
/// components from (0, 0, 0, 1). Out-of-range reads give the defaults.
pub fn read_integer_element(bytes: &[u8], at: usize, size: usize, ty: u32) -> [u32; 4] {
    let mut out = [0, 0, 0, 1];
    let Some(cs) = type_size(ty) else {
        return out;
    };
    for (c, o) in out.iter_mut().enumerate().take(size.min(4)) {
        let start = at.saturating_add(c * cs);
        let Some(b) = bytes.get(start..start.saturating_add(cs)) else {
            return [0, 0, 0, 1];
        };
        *o = match (ty, b) {
            (GL_BYTE, [x]) => *x as i8 as i32 as u32,
            (GL_UNSIGNED_BYTE, [x]) => *x as u32,
            (GL_SHORT, [x, y]) => i16::from_le_bytes([*x, *y]) as i32 as u32,
            (GL_UNSIGNED_SHORT, [x, y]) => u16::from_le_bytes([*x, *y]) as u32,
            (_, [x, y, z, w]) => u32::from_le_bytes([*x, *y, *z, *w]),
            _ => 0,
        };
    }
    out
}

/// Bytes per component of an array type (none for the packed types,
/// [`element_size`]).
pub fn type_size(ty: u32) -> Option<usize> {
    Some(match ty {
        GL_BYTE | GL_UNSIGNED_BYTE => 1,
        GL_SHORT | GL_UNSIGNED_SHORT | GL_HALF_FLOAT => 2,
        GL_INT | GL_UNSIGNED_INT | GL_FLOAT => 4,
        GL_DOUBLE => 8,
        _ => return None,
    })
}

/// Whether `ty` packs a whole element into one 32-bit word (GL 3.3 §2.8:
/// GL_INT_2_10_10_10_REV, GL_UNSIGNED_INT_2_10_10_10_REV).
pub fn is_packed(ty: u32) -> bool {
    matches!(ty, GL_INT_2_10_10_10_REV | GL_UNSIGNED_INT_2_10_10_10_REV)
}

/// The size a pointer call takes for four components in B, G, R, A
/// order (GL 3.3 §2.8, ARB_vertex_array_bgra).
pub const SIZE_BGRA: i32 = GL_BGRA as i32;

/// Bytes of one element of an array of `size` components (or
/// [`SIZE_BGRA`]) of `ty`.
pub fn element_size(size: i32, ty: u32) -> Option<usize> {
    if is_packed(ty) {
        return Some(4);
    }
    let n = if size == SIZE_BGRA {
        4
    } else {
        size.clamp(1, 4) as usize
    };
    Some(n * type_size(ty)?)
}

/// The four fields of a packed 2_10_10_10 word (x in the low bits), as
/// values (GL 3.3 §2.8, Table 2.7), normalized per §2.1.6 when asked.
pub fn unpack_2_10_10_10(word: u32, ty: u32, normalized: bool) -> [f32; 4] {
    let bits = [10u32, 10, 10, 2];
    let mut out = [0.0; 4];
    let mut shift = 0;
    for (o, b) in out.iter_mut().zip(bits) {
        let field = (word >> shift) & ((1 << b) - 1);
        shift += b;
        let max = ((1u32 << b) - 1) as f32;
        *o = if ty == GL_INT_2_10_10_10_REV {
            // Sign-extended from b bits.
            let v = ((field << (32 - b)) as i32 >> (32 - b)) as f32;
            if normalized {
                (2.0 * v + 1.0) / max
            } else {
                v
            }
        } else if normalized {
            field as f32 / max
        } else {
            field as f32
        };
    }
    out
}

/// Reads one element of an array: `size` components (or
/// [`SIZE_BGRA`], as usize) of `ty` starting at `at`, normalized per
/// GL 2.1 Table 2.9 when asked, missing components from (0, 0, 0, 1).
/// Out-of-range reads give the defaults.
pub fn read_element(bytes: &[u8], at: usize, size: usize, ty: u32, normalized: bool) -> [f32; 4] {
    let bgra = size == SIZE_BGRA as usize;
    if is_packed(ty) {
        let Some(&[a, b, c, d]) = bytes.get(at..at.saturating_add(4)) else {
            return [0.0, 0.0, 0.0, 1.0];
        };
        let mut v = unpack_2_10_10_10(u32::from_le_bytes([a, b, c, d]), ty, normalized);
        if bgra {
            v.swap(0, 2);
        }
        return v;
    }
    let mut out = [0.0, 0.0, 0.0, 1.0];
    let Some(cs) = type_size(ty) else {
        return out;
    };
    let n = if bgra { 4 } else { size.min(4) };
    for (c, o) in out.iter_mut().enumerate().take(n) {
        let start = at.saturating_add(c * cs);
        let Some(b) = bytes.get(start..start.saturating_add(cs)) else {
            return [0.0, 0.0, 0.0, 1.0];
        };
        let mut raw = [0u8; 8];
        raw[..cs].copy_from_slice(b);
        *o = match ty {
            GL_BYTE => {
                let v = raw[0] as i8 as f64;
                if normalized {
                    ((2.0 * v + 1.0) / 255.0) as f32
                } else {
                    v as f32
                }
            }
            GL_UNSIGNED_BYTE => {
                let v = raw[0] as f64;
                if normalized {
                    (v / 255.0) as f32
                } else {
                    v as f32
                }
            }
            GL_SHORT => {
                let v = i16::from_le_bytes([raw[0], raw[1]]) as f64;
                if normalized {
                    ((2.0 * v + 1.0) / 65535.0) as f32
                } else {
                    v as f32
                }
            }
            GL_UNSIGNED_SHORT => {
                let v = u16::from_le_bytes([raw[0], raw[1]]) as f64;
                if normalized {
                    (v / 65535.0) as f32
                } else {
                    v as f32
                }
            }
            GL_INT => {
                let v = i32::from_le_bytes([raw[0], raw[1], raw[2], raw[3]]) as f64;
                if normalized {
                    ((2.0 * v + 1.0) / 4294967295.0) as f32
                } else {
                    v as f32
                }
            }
            GL_UNSIGNED_INT => {
                let v = u32::from_le_bytes([raw[0], raw[1], raw[2], raw[3]]) as f64;
                if normalized {
                    (v / 4294967295.0) as f32
                } else {
                    v as f32
                }
            }
            GL_FLOAT => f32::from_le_bytes([raw[0], raw[1], raw[2], raw[3]]),
            GL_HALF_FLOAT => half_to_f32(u16::from_le_bytes([raw[0], raw[1]])),
            _ => f64::from_le_bytes(raw) as f32,
        };
    }
    if bgra {
        out.swap(0, 2);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalization_table_2_9() {
        assert_eq!(
            read_element(&[255, 0], 0, 2, GL_UNSIGNED_BYTE, true),
            [1.0, 0.0, 0.0, 1.0]
        );
        assert_eq!(read_element(&[0x7f], 0, 1, GL_BYTE, true)[0], 1.0);
        assert_eq!(read_element(&[0x80], 0, 1, GL_BYTE, true)[0], -1.0);
        assert_eq!(
            read_element(&[200], 0, 1, GL_UNSIGNED_BYTE, false)[0],
            200.0
        );
        // Out of range: defaults.
        assert_eq!(
            read_element(&[1, 2], 0, 3, GL_FLOAT, false),
            [0.0, 0.0, 0.0, 1.0]
        );
    }

    #[test]
    fn half_packed_and_bgra_elements() {
        // 1.0, -2.0, 0.5 as half floats; a subnormal; infinity.
        let halves: Vec<u8> = [0x3c00u16, 0xc000, 0x3800, 0x0001, 0x7c00]
            .iter()
            .flat_map(|h| h.to_le_bytes())
            .collect();
        assert_eq!(
            read_element(&halves, 0, 3, GL_HALF_FLOAT, false),
            [1.0, -2.0, 0.5, 1.0]
        );
        assert_eq!(
            read_element(&halves, 6, 2, GL_HALF_FLOAT, false),
            [2.0f32.powi(-24), f32::INFINITY, 0.0, 1.0]
        );
        // x = 1023, y = -512 (signed), z = 5, w = 3 / -1.
        let word: u32 = 1023 | (512 << 10) | (5 << 20) | (3 << 30);
        let b = word.to_le_bytes();
        assert_eq!(
            read_element(&b, 0, 4, GL_UNSIGNED_INT_2_10_10_10_REV, false),
            [1023.0, 512.0, 5.0, 3.0]
        );
        assert_eq!(
            read_element(&b, 0, 4, GL_INT_2_10_10_10_REV, false),
            [-1.0, -512.0, 5.0, -1.0]
        );
        assert_eq!(
            read_element(&b, 0, 4, GL_UNSIGNED_INT_2_10_10_10_REV, true),
            [1.0, 512.0 / 1023.0, 5.0 / 1023.0, 1.0]
        );
        // Signed normalization (2c + 1) / (2^b - 1): -512 gives -1.
        assert_eq!(read_element(&b, 0, 4, GL_INT_2_10_10_10_REV, true)[1], -1.0);
        assert_eq!(
            read_element(
                &b,
                0,
                SIZE_BGRA as usize,
                GL_UNSIGNED_INT_2_10_10_10_REV,
                false
            ),
            [5.0, 512.0, 1023.0, 3.0]
        );
        assert_eq!(
            read_element(
                &[255, 0, 51, 255],
                0,
                SIZE_BGRA as usize,
                GL_UNSIGNED_BYTE,
                true
            ),
            [0.2, 0.0, 1.0, 1.0]
        );
        assert_eq!(element_size(SIZE_BGRA, GL_UNSIGNED_BYTE), Some(4));
        assert_eq!(element_size(4, GL_INT_2_10_10_10_REV), Some(4));
        assert_eq!(element_size(3, GL_HALF_FLOAT), Some(6));
    }
}
