//! Texture objects as raster's textures: the bound texture of every
//! target on every image unit, converted to [`raster::Texture`] (levels,
//! cube faces, sampler parameters) for a draw.
//!
//! Contract: a conversion is cached per (name, target, sampler object) and
//! reused while the texture's and the sampler's generations are unchanged,
//! except for buffer textures, decoded from their buffer at every draw; an
//! incomplete cube level becomes an empty image. A sampler object bound to
//! the unit ([`crate::samplers`]) supplies the sampler state in place of
//! the texture's; a rectangle texture under a sampler whose state
//! glTexParameter would refuse for it samples as no texture (incomplete).
//! The base level's internal format says whether the texture is a depth,
//! integer or sRGB one.

use crate::enums::*;
use crate::objects;
use crate::pipeline_state::compare_func;
use crate::samplers::{invalid_for_rectangle, with_sampler};
use crate::texture_buffer::buffer_texels;
use crate::texture_format::{is_depth_format, is_integer_format, is_srgb_format};
use crate::Context;
use std::sync::Arc;

impl Context {
    /// A texture object as raster's texture (cached per generation).
    fn raster_texture(
        &mut self,
        name: u32,
        target: u32,
        unit: usize,
    ) -> Option<Arc<raster::Texture>> {
        let t = self.objects.bound_texture(unit, target)?;
        let sampler = self.objects.bound_sampler(unit);
        let params = match sampler {
            Some((_, s)) => {
                if t.target == GL_TEXTURE_RECTANGLE && invalid_for_rectangle(&s.params) {
                    return None;
                }
                with_sampler(&t.params, &s.params)
            }
            None => t.params,
        };
        let (sampler_name, sampler_gen) = sampler.map_or((0, 0), |(n, s)| (n, s.generation));
        let key = (name, target, sampler_name);
        if let Some((gen, sgen, tex)) = self.cache.textures.get(&key) {
            if *gen == t.generation && *sgen == sampler_gen {
                return Some(tex.clone());
            }
        }
        let tex = Arc::new(convert_texture(t, &params));
        self.cache
            .textures
            .insert(key, (t.generation, sampler_gen, tex.clone()));
        Some(tex)
    }

    /// The buffer texture bound on `unit` as raster's texture, decoded
    /// from its buffer's current contents (never cached: the buffer may
    /// change without the texture knowing).
    fn buffer_texture(&self, unit: usize) -> Option<Arc<raster::Texture>> {
        let t = self.objects.bound_texture(unit, GL_TEXTURE_BUFFER)?;
        let texels = match t.buffer {
            Some(b) => self
                .objects
                .buffers
                .get(&b.buffer)
                .map(|o| buffer_texels(b.internal_format, &o.data))
                .unwrap_or_default(),
            None => Vec::new(),
        };
        let width = texels.len() as u32;
        let mut tex = raster::Texture::new(
            raster::TextureTarget::Buffer,
            vec![raster::Image::new(width, 1, 1, texels)],
        );
        tex.min_filter = raster::MinFilter::Nearest;
        tex.mag_filter = raster::MagFilter::Nearest;
        tex.integer = t
            .buffer
            .is_some_and(|b| is_integer_format(b.internal_format as i32));
        Some(Arc::new(tex))
    }

    /// Raster's texture units: the texture bound to each target on every
    /// image unit, and the unit's LOD bias.
    pub(crate) fn texture_units(&mut self) -> raster::TextureUnits {
        let mut units = Vec::with_capacity(crate::MAX_TEXTURE_IMAGE_UNITS);
        for u in 0..crate::MAX_TEXTURE_IMAGE_UNITS {
            let names = self
                .objects
                .bound
                .get(u)
                .copied()
                .unwrap_or([0; objects::TEXTURE_TARGET_COUNT]);
            let mut get = |i: usize| self.raster_texture(names[i], objects::TEXTURE_TARGETS[i], u);
            let unit = raster::TextureUnit {
                tex_1d: get(0),
                tex_2d: get(1),
                tex_3d: get(2),
                cube: get(3),
                tex_1d_array: get(4),
                tex_2d_array: get(5),
                cube_array: get(10),
                rect: get(6),
                buffer: self.buffer_texture(u),
                lod_bias: self.st.tex_env.get(u).map_or(0.0, |e| e.lod_bias),
            };
            units.push(unit);
        }
        raster::TextureUnits::new(units)
    }
}

/// A GL texture object as raster's texture.
/// `p` is the sampling state to apply: the texture's own parameters, or
/// those with a bound sampler's state in place.
fn convert_texture(t: &objects::TextureObj, p: &objects::TexParams) -> raster::Texture {
    use raster::{MagFilter, MinFilter, TextureTarget, Wrap};
    let target = match t.target {
        GL_TEXTURE_1D => TextureTarget::Tex1D,
        GL_TEXTURE_3D => TextureTarget::Tex3D,
        GL_TEXTURE_CUBE_MAP => TextureTarget::Cube,
        GL_TEXTURE_1D_ARRAY => TextureTarget::Tex1DArray,
        GL_TEXTURE_2D_ARRAY => TextureTarget::Tex2DArray,
        GL_TEXTURE_CUBE_MAP_ARRAY_ARB => TextureTarget::CubeArray,
        GL_TEXTURE_RECTANGLE => TextureTarget::Rect,
        _ => TextureTarget::Tex2D,
    };
    let nlevels = t.faces.iter().map(|f| f.len()).max().unwrap_or(0);
    let mut levels = Vec::with_capacity(nlevels);
    for l in 0..nlevels {
        if target == TextureTarget::Cube {
            let faces: Vec<Option<&objects::Image>> = (0..6).map(|f| t.image(f, l)).collect();
            let first = faces.iter().flatten().next();
            let img = match first {
                Some(f0)
                    if faces.iter().all(|f| {
                        f.is_some_and(|f| f.width == f0.width && f.height == f0.height)
                    }) =>
                {
                    let texels = faces
                        .iter()
                        .flatten()
                        .flat_map(|f| f.texels.iter().copied())
                        .collect();
                    raster::Image::new(f0.width as u32, f0.height as u32, 6, texels)
                }
                _ => raster::Image::new(0, 0, 0, Vec::new()),
            };
            levels.push(img);
        } else {
            match t.image(0, l) {
                Some(i) => levels.push(raster::Image::new(
                    i.width as u32,
                    i.height as u32,
                    i.depth as u32,
                    i.texels.clone(),
                )),
                None => levels.push(raster::Image::new(0, 0, 0, Vec::new())),
            }
        }
    }
    let wrap = |w: u32| match w {
        GL_CLAMP => Wrap::Clamp,
        GL_CLAMP_TO_EDGE => Wrap::ClampToEdge,
        GL_CLAMP_TO_BORDER => Wrap::ClampToBorder,
        GL_MIRRORED_REPEAT => Wrap::MirroredRepeat,
        _ => Wrap::Repeat,
    };
    let mut out = raster::Texture::new(target, levels);
    out.min_filter = match p.min_filter {
        GL_NEAREST => MinFilter::Nearest,
        GL_LINEAR => MinFilter::Linear,
        GL_NEAREST_MIPMAP_NEAREST => MinFilter::NearestMipmapNearest,
        GL_LINEAR_MIPMAP_NEAREST => MinFilter::LinearMipmapNearest,
        GL_LINEAR_MIPMAP_LINEAR => MinFilter::LinearMipmapLinear,
        _ => MinFilter::NearestMipmapLinear,
    };
    out.mag_filter = if p.mag_filter == GL_NEAREST {
        MagFilter::Nearest
    } else {
        MagFilter::Linear
    };
    out.wrap = p.wrap.map(wrap);
    out.border_color = p.border_color;
    out.min_lod = p.min_lod;
    out.max_lod = p.max_lod;
    out.lod_bias = p.lod_bias;
    out.base_level = p.base_level.max(0) as u32;
    out.max_level = p.max_level.max(0) as u32;
    // Every face and level has the base level's kind of format when the
    // texture is complete.
    let internal = t.base_image().map(|i| i.internal_format as i32);
    out.depth_format = internal.is_some_and(is_depth_format);
    out.integer = internal.is_some_and(is_integer_format);
    out.srgb = internal.is_some_and(is_srgb_format);
    out.compare = (p.compare_mode == GL_COMPARE_R_TO_TEXTURE).then(|| compare_func(p.compare_func));
    out.swizzle = p.swizzle.map(|s| match s {
        GL_RED => raster::Swizzle::R,
        GL_GREEN => raster::Swizzle::G,
        GL_BLUE => raster::Swizzle::B,
        GL_ALPHA => raster::Swizzle::A,
        GL_ZERO => raster::Swizzle::Zero,
        _ => raster::Swizzle::One,
    });
    out.depth_mode = match p.depth_mode {
        GL_INTENSITY => raster::DepthTextureMode::Intensity,
        GL_ALPHA => raster::DepthTextureMode::Alpha,
        GL_RED => raster::DepthTextureMode::Red,
        _ => raster::DepthTextureMode::Luminance,
    };
    out
}
