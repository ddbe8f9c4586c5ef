//! Buffer textures (GL 3.1 §3.8.5): glTexBuffer attaches a buffer
//! object's data store to the texture bound to GL_TEXTURE_BUFFER, read
//! as a one-row image of texels in one of Table 3.15's formats, reached
//! by `texelFetch` on `samplerBuffer` (and its integer forms).
//!
//! Contract: the texels are decoded from the buffer's current contents
//! at every draw (`buffer_texels`), so writes to the buffer show
//! without re-attaching it; a deleted buffer leaves no texels.

use crate::enums::*;
use crate::objects::TexBuffer;
use crate::pixel_transfer::half_to_f32;
use crate::texture_format::integer_texel;
use crate::Context;

/// How a buffer texture's component is stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Unorm,
    Half,
    Float,
    Int,
    Uint,
}

/// GL 3.1 Table 3.15: components, bytes per component and their kind.
fn layout(internal: u32) -> Option<(usize, usize, Kind)> {
    use Kind::*;
    Some(match internal {
        GL_R8 => (1, 1, Unorm),
        GL_R16 => (1, 2, Unorm),
        GL_R16F => (1, 2, Half),
        GL_R32F => (1, 4, Float),
        GL_R8I => (1, 1, Int),
        GL_R16I => (1, 2, Int),
        GL_R32I => (1, 4, Int),
        GL_R8UI => (1, 1, Uint),
        GL_R16UI => (1, 2, Uint),
        GL_R32UI => (1, 4, Uint),
        GL_RG8 => (2, 1, Unorm),
        GL_RG16 => (2, 2, Unorm),
        GL_RG16F => (2, 2, Half),
        GL_RG32F => (2, 4, Float),
        GL_RG8I => (2, 1, Int),
        GL_RG16I => (2, 2, Int),
        GL_RG32I => (2, 4, Int),
        GL_RG8UI => (2, 1, Uint),
        GL_RG16UI => (2, 2, Uint),
        GL_RG32UI => (2, 4, Uint),
        GL_RGBA8 => (4, 1, Unorm),
        GL_RGBA16 => (4, 2, Unorm),
        GL_RGBA16F => (4, 2, Half),
        GL_RGBA32F => (4, 4, Float),
        GL_RGBA8I => (4, 1, Int),
        GL_RGBA16I => (4, 2, Int),
        GL_RGBA32I => (4, 4, Int),
        GL_RGBA8UI => (4, 1, Uint),
        GL_RGBA16UI => (4, 2, Uint),
        GL_RGBA32UI => (4, 4, Uint),
        _ => return None,
    })
}

/// The largest number of texels a buffer texture reads
/// (GL_MAX_TEXTURE_BUFFER_SIZE).
pub const MAX_TEXTURE_BUFFER_SIZE: usize = 1 << 24;

/// The texels of a buffer texture in `internal` over `data`: as many whole
/// texels as the data holds (at most [`MAX_TEXTURE_BUFFER_SIZE`]), the
/// components the format lacks 0 and alpha 1 (integer formats: the
/// integers' bits, as integer textures store them).
pub(crate) fn buffer_texels(internal: u32, data: &[u8]) -> Vec<[f32; 4]> {
    let Some((n, size, kind)) = layout(internal) else {
        return Vec::new();
    };
    let texel_bytes = n * size;
    let count = (data.len() / texel_bytes).min(MAX_TEXTURE_BUFFER_SIZE);
    let mut out = Vec::with_capacity(count);
    for texel in data.chunks_exact(texel_bytes).take(count) {
        let raw: Vec<u32> = texel
            .chunks_exact(size)
            .map(|b| {
                let mut v = [0u8; 4];
                v[..size].copy_from_slice(b);
                u32::from_le_bytes(v)
            })
            .collect();
        let sign_extend = |x: u32| -> i64 {
            let shift = 32 - 8 * size as u32;
            ((x << shift) as i32 >> shift) as i64
        };
        out.push(match kind {
            Kind::Int | Kind::Uint => {
                let mut c = [0i64, 0, 0, 1];
                for (k, &x) in raw.iter().enumerate() {
                    c[k] = if kind == Kind::Int {
                        sign_extend(x)
                    } else {
                        x as i64
                    };
                }
                integer_texel(c, internal as i32)
            }
            _ => {
                let mut c = [0.0f32, 0.0, 0.0, 1.0];
                for (k, &x) in raw.iter().enumerate() {
                    c[k] = match kind {
                        Kind::Unorm => (x as f64 / ((1u64 << (8 * size)) - 1) as f64) as f32,
                        Kind::Half => half_to_f32(x as u16),
                        _ => f32::from_bits(x),
                    };
                }
                c
            }
        });
    }
    out
}

impl Context {
    /// glTexBuffer: attaches `buffer`'s data store (0 detaches) in format
    /// `internal` to the texture bound to GL_TEXTURE_BUFFER on the active
    /// unit. Another target or a format outside Table 3.15 is
    /// GL_INVALID_ENUM, a name that is no buffer object
    /// GL_INVALID_OPERATION.
    pub fn tex_buffer(&mut self, target: u32, internal: u32, buffer: u32) {
        if self.reject_in_begin() {
            return;
        }
        if target != GL_TEXTURE_BUFFER || layout(internal).is_none() {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if buffer != 0 && !self.objects.buffers.contains_key(&buffer) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let unit = self.st.active_texture as usize;
        let Some(tex) = self.objects.bound_texture_mut(unit, GL_TEXTURE_BUFFER) else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        tex.buffer = (buffer != 0).then_some(TexBuffer {
            buffer,
            internal_format: internal,
        });
        tex.generation += 1;
    }

    /// The buffer texture bound on the active unit, if it has a buffer.
    pub(crate) fn active_tex_buffer(&self) -> Option<TexBuffer> {
        let unit = self.st.active_texture as usize;
        self.objects.bound_texture(unit, GL_TEXTURE_BUFFER)?.buffer
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn texels_decode_by_format() {
        let bytes: Vec<u8> = [1.5f32, -2.0, 0.25, 8.0]
            .iter()
            .flat_map(|x| x.to_le_bytes())
            .collect();
        assert_eq!(
            buffer_texels(GL_RG32F, &bytes),
            vec![[1.5, -2.0, 0.0, 1.0], [0.25, 8.0, 0.0, 1.0]]
        );
        let t = buffer_texels(GL_R16I, &[0xff, 0xff, 5, 0, 7]);
        assert_eq!(t.len(), 2, "a partial texel is not read");
        assert_eq!(t[0].map(f32::to_bits), [u32::MAX, 0, 0, 1]);
        assert_eq!(t[1].map(f32::to_bits), [5, 0, 0, 1]);
        assert_eq!(
            buffer_texels(GL_RGBA8, &[255, 0, 51, 255])[0],
            [1.0, 0.0, 0.2, 1.0]
        );
        assert!(buffer_texels(GL_RGB8, &[1, 2, 3]).is_empty());
    }
}
