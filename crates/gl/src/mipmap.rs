//! Mipmap generation (GL 2.1 §3.8.8 GENERATE_MIPMAP; glGenerateMipmap).
//!
//! Contract: levels base+1 down to 1x1(x1) are rebuilt from the base level
//! by averaging 2x2(x2) blocks (a dimension already 1 is not halved, nor
//! the layers of an array texture), then
//! re-quantized to the internal format (depth values are kept as
//! averaged), at most down to level [`crate::objects`]' `MAX_LEVELS`;
//! nothing happens without a base image.

use crate::enums::*;
use crate::objects::{set_image, Image, TextureObj, MAX_LEVELS};
use crate::texture_format::{is_integer_format, texel_for_stored};
use crate::Context;

impl Context {
    /// glGenerateMipmap / glGenerateMipmapEXT: box-filtered levels down to
    /// 1x1 from the base level.
    pub fn generate_mipmap(&mut self, target: u32) {
        if self.reject_in_begin() {
            return;
        }
        if !matches!(
            target,
            GL_TEXTURE_1D
                | GL_TEXTURE_2D
                | GL_TEXTURE_3D
                | GL_TEXTURE_CUBE_MAP
                | GL_TEXTURE_1D_ARRAY
                | GL_TEXTURE_2D_ARRAY
                | GL_TEXTURE_CUBE_MAP_ARRAY_ARB
        ) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let unit = self.st.active_texture as usize;
        // Integer texels have no average (GL 4.x makes this an error; GL
        // 3.3 leaves the result undefined).
        let integer = self
            .objects
            .bound_texture(unit, target)
            .and_then(|t| t.base_image())
            .is_some_and(|i| is_integer_format(i.internal_format as i32));
        if integer {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if let Some(tex) = self.objects.bound_texture_mut(unit, target) {
            for face in 0..tex.faces.len() {
                generate_mipmaps(tex, face);
            }
        }
    }
}

/// Box-filters levels base+1.. from the base level (GL 2.1 §3.8.8,
/// GENERATE_MIPMAP: any filter that averages 2x2(x2) blocks is allowed).
pub(crate) fn generate_mipmaps(tex: &mut TextureObj, face: usize) {
    let base = tex.params.base_level.max(0) as usize;
    let Some(mut cur) = tex.image(face, base).cloned() else {
        return;
    };
    let mut level = base;
    // An array's layers (a 1D array's rows, a 2D array's slices) are
    // filtered apart, never halved.
    let (rows_are_layers, slices_are_layers) = match tex.target {
        GL_TEXTURE_1D_ARRAY => (true, false),
        GL_TEXTURE_2D_ARRAY | GL_TEXTURE_CUBE_MAP_ARRAY_ARB => (false, true),
        _ => (false, false),
    };
    let halves = |n: i32, layers: bool| n > 1 && !layers;
    while (cur.width > 1
        || halves(cur.height, rows_are_layers)
        || halves(cur.depth, slices_are_layers))
        && level < MAX_LEVELS as usize
    {
        let (w, h, d) = (cur.width as usize, cur.height as usize, cur.depth as usize);
        let half = |n: usize, layers: bool| if layers { n } else { (n / 2).max(1) };
        let (nw, nh, nd) = (
            half(w, false),
            half(h, rows_are_layers),
            half(d, slices_are_layers),
        );
        // Per axis: the block size averaged and the source of index x.
        let step = |n: usize, layers: bool| if n > 1 && !layers { 2 } else { 1 };
        let (sw, sh, sd) = (
            step(w, false),
            step(h, rows_are_layers),
            step(d, slices_are_layers),
        );
        let mut texels = Vec::with_capacity(nw * nh * nd);
        for z in 0..nd {
            for y in 0..nh {
                for x in 0..nw {
                    let mut sum = [0.0f32; 4];
                    let mut n = 0.0f32;
                    for dz in 0..sd {
                        for dy in 0..sh {
                            for dx in 0..sw {
                                let (sx, sy, sz) = (sw * x + dx, sh * y + dy, sd * z + dz);
                                if let Some(t) = cur.texels.get((sz * h + sy) * w + sx) {
                                    for c in 0..4 {
                                        sum[c] += t[c];
                                    }
                                    n += 1.0;
                                }
                            }
                        }
                    }
                    let avg = sum.map(|s| if n > 0.0 { s / n } else { 0.0 });
                    texels.push(texel_for_stored(avg, cur.internal_format as i32));
                }
            }
        }
        cur = Image {
            width: nw as i32,
            height: nh as i32,
            depth: nd as i32,
            internal_format: cur.internal_format,
            texels,
        };
        level += 1;
        set_image(tex, face, level, cur.clone());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn float_texels_unclamped_and_mipmaps() {
        let mut ctx = Context::new(4, 4);
        let t = ctx.gen_textures(1)[0];
        ctx.bind_texture(GL_TEXTURE_2D, t);
        let px: Vec<f32> = vec![
            2.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 2.0, 0.0, 0.0, 1.0,
        ];
        let bytes: Vec<u8> = px.iter().flat_map(|f| f.to_le_bytes()).collect();
        ctx.tex_image(
            GL_TEXTURE_2D,
            0,
            GL_RGBA32F as i32,
            [2, 2],
            0,
            GL_RGBA,
            GL_FLOAT,
            Some(&bytes),
        );
        ctx.generate_mipmap(GL_TEXTURE_2D);
        let tex = &ctx.objects.textures[&t];
        assert_eq!(tex.image(0, 0).unwrap().texels[0][0], 2.0);
        assert_eq!(tex.image(0, 1).unwrap().texels, vec![[1.0, 0.0, 0.0, 1.0]]);
    }
}
