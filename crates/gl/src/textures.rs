//! Texture objects' entry points (GL 2.1 §3.8, GL 3.3 §3.9): glGenTextures,
//! glBindTexture (1D, 2D, 3D, cube, 1D and 2D array, rectangle and buffer
//! targets), glDeleteTextures, image specification (glTexImage*,
//! glTexSubImage*: one method each for the 1D, 2D and 3D forms; integer
//! formats take integer data only), sampler parameters (glTexParameter*,
//! swizzles included; rectangles refuse repeating wraps and mipmap
//! filters) and the queries (glGetTexParameter*,
//! glGetTexLevelParameteriv, glGetTexImage).
//!
//! Contract: images are given and returned in the packed layout at the
//! unpack / pack alignment (the caller applies the other glPixelStore
//! modes: [`crate::pixel_store`]); every image specification unpacks the
//! client image through [`crate::pixel_transfer`] into the stored texel form of
//! [`crate::texture_format`]; with GL_GENERATE_MIPMAP set, a change to the
//! base level regenerates the levels below it ([`crate::mipmap`]). Each
//! change bumps the texture's generation, which keys the draw path's
//! converted-texture cache.

use crate::enums::*;
use crate::mipmap::generate_mipmaps;
use crate::objects::{
    clear_image, image_target, proxy_target, set_image, target_index, Attachment, Image, TexParams,
    TextureObj, MAX_LEVELS,
};
use crate::param::Param;
use crate::pixel_transfer::{
    format_components, integer_client_format, pack_integer_pixels, pack_pixels, pixel_size,
    unpack_image,
};
use crate::texture_format::{
    base_format, component_info, integer_format, is_depth_format, is_integer_format,
};
use crate::{Context, MAX_3D_TEXTURE_SIZE, MAX_TEXELS, MAX_TEXTURE_SIZE};

/// The first three of `v`'s entries, `pad` for those it lacks: the
/// extent or offset of a 1D, 2D or 3D image as a 3D one.
fn extent<const D: usize>(v: [i32; D], pad: i32) -> [i32; 3] {
    std::array::from_fn(|i| v.get(i).copied().unwrap_or(pad))
}

/// GL 3.3 §3.9.3: integer internal formats take integer client data
/// only, and integer data no FLOAT or HALF_FLOAT type; other formats no
/// integer data.
fn integer_data_matches(internal: i32, format: u32, ty: u32) -> bool {
    let int_data = integer_client_format(format).is_some();
    is_integer_format(internal) == int_data && !(int_data && matches!(ty, GL_FLOAT | GL_HALF_FLOAT))
}

/// GL 3.3 §3.9.8: what a texture swizzle may select.
fn valid_swizzle(s: u32) -> bool {
    matches!(s, GL_RED | GL_GREEN | GL_BLUE | GL_ALPHA | GL_ZERO | GL_ONE)
}

fn valid_filter(f: u32, min: bool) -> bool {
    matches!(f, GL_NEAREST | GL_LINEAR)
        || (min
            && matches!(
                f,
                GL_NEAREST_MIPMAP_NEAREST
                    | GL_LINEAR_MIPMAP_NEAREST
                    | GL_NEAREST_MIPMAP_LINEAR
                    | GL_LINEAR_MIPMAP_LINEAR
            ))
}

/// Sets the sampler-state parameter `pname` (GL 3.3 Table 6.23: the state
/// texture objects and sampler objects share) of `p` from the call's
/// values `v` (its first value as an enum, `e`). Returns None when `pname`
/// is no sampler state, else the error the values call for
/// (GL_NO_ERROR when set); `v` holds at least as many values as `pname`
/// takes.
pub(crate) fn set_sampler_state(p: &mut TexParams, pname: u32, e: u32, v: &[f32]) -> Option<u32> {
    let mut err = GL_NO_ERROR;
    match pname {
        GL_TEXTURE_MIN_FILTER | GL_TEXTURE_MAG_FILTER => {
            let min = pname == GL_TEXTURE_MIN_FILTER;
            if !valid_filter(e, min) {
                err = GL_INVALID_ENUM;
            } else if min {
                p.min_filter = e;
            } else {
                p.mag_filter = e;
            }
        }
        GL_TEXTURE_WRAP_S | GL_TEXTURE_WRAP_T | GL_TEXTURE_WRAP_R => {
            if matches!(
                e,
                GL_REPEAT | GL_CLAMP | GL_CLAMP_TO_EDGE | GL_CLAMP_TO_BORDER | GL_MIRRORED_REPEAT
            ) {
                let i = match pname {
                    GL_TEXTURE_WRAP_S => 0,
                    GL_TEXTURE_WRAP_T => 1,
                    _ => 2,
                };
                p.wrap[i] = e;
            } else {
                err = GL_INVALID_ENUM;
            }
        }
        GL_TEXTURE_BORDER_COLOR => {
            p.border_color = [v[0], v[1], v[2], v[3]].map(|x| x.clamp(0.0, 1.0))
        }
        GL_TEXTURE_MIN_LOD => p.min_lod = v[0],
        GL_TEXTURE_MAX_LOD => p.max_lod = v[0],
        GL_TEXTURE_LOD_BIAS => p.lod_bias = v[0],
        GL_TEXTURE_COMPARE_MODE if e == GL_NONE || e == GL_COMPARE_R_TO_TEXTURE => {
            p.compare_mode = e
        }
        GL_TEXTURE_COMPARE_FUNC if (GL_NEVER..=GL_ALWAYS).contains(&e) => p.compare_func = e,
        GL_TEXTURE_COMPARE_MODE | GL_TEXTURE_COMPARE_FUNC => err = GL_INVALID_ENUM,
        _ => return None,
    }
    Some(err)
}

impl Context {
    /// glGenTextures.
    pub fn gen_textures(&mut self, n: i32) -> Vec<u32> {
        self.gen_objects(
            n,
            |o| (&mut o.textures, &mut o.next_texture),
            TextureObj::default,
        )
    }

    /// glDeleteTextures (bindings revert to 0, attachments are removed).
    pub fn delete_textures(&mut self, names: &[u32]) {
        for &t in names {
            if t == 0 || self.objects.textures.remove(&t).is_none() {
                continue;
            }
            // A later texture of the same name starts its generations
            // over: its conversions must not be taken for this one's.
            self.cache.textures.retain(|k, _| k.0 != t);
            for unit in &mut self.objects.bound {
                for b in unit.iter_mut() {
                    if *b == t {
                        *b = 0;
                    }
                }
            }
            let cur = self.objects.draw_framebuffer;
            if let Some(fb) = self.objects.framebuffers.get_mut(&cur) {
                let is_t = |a: &Option<Attachment>| matches!(a, Some(Attachment::Texture { texture, .. }) if *texture == t);
                for c in fb.color.iter_mut() {
                    if is_t(c) {
                        *c = None;
                    }
                }
                if is_t(&fb.depth) {
                    fb.depth = None;
                }
                if is_t(&fb.stencil) {
                    fb.stencil = None;
                }
            }
        }
    }

    /// glIsTexture.
    pub fn is_texture(&self, name: u32) -> bool {
        self.objects
            .textures
            .get(&name)
            .is_some_and(|t| t.target != 0)
    }

    /// glBindTexture.
    pub fn bind_texture(&mut self, target: u32, texture: u32) {
        if self.reject_in_begin() {
            return;
        }
        let Some(ti) = target_index(target) else {
            self.set_error(GL_INVALID_ENUM);
            return;
        };
        if texture != 0 {
            let t = self.objects.textures.entry(texture).or_default();
            if t.target == 0 {
                *t = TextureObj::new(target);
            } else if t.target != target {
                self.set_error(GL_INVALID_OPERATION);
                return;
            }
        }
        let unit = self.st.active_texture as usize;
        if let Some(b) = self.objects.bound.get_mut(unit) {
            b[ti] = texture;
        }
    }

    /// glTexImage1D, glTexImage2D and glTexImage3D: `size` holds one extent
    /// per dimension (`[w]`, `[w, h]`, `[w, h, d]`), which selects the call
    /// and so the targets it takes (GL 2.1 §3.8.1).
    #[allow(clippy::too_many_arguments)]
    pub fn tex_image<const D: usize>(
        &mut self,
        target: u32,
        level: i32,
        internal: i32,
        size: [i32; D],
        border: i32,
        format: u32,
        ty: u32,
        data: Option<&[u8]>,
    ) {
        if self.reject_in_begin() {
            return;
        }
        let (dims, size) = (D as u32, extent(size, 1));
        // A proxy target is checked as the target it stands for, but an
        // image too large to hold leaves the proxy level empty instead of
        // setting an error (GL 3.3 §3.8.15).
        let proxy = proxy_target(target, dims);
        let Some((bind_target, face)) =
            proxy.map(|t| (t, 0)).or_else(|| image_target(target, dims))
        else {
            self.set_error(GL_INVALID_ENUM);
            return;
        };
        if format_components(format).is_none() {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if !matches!(
            ty,
            GL_UNSIGNED_BYTE
                | GL_BYTE
                | GL_UNSIGNED_SHORT
                | GL_SHORT
                | GL_UNSIGNED_INT
                | GL_INT
                | GL_FLOAT
                | GL_HALF_FLOAT
                | GL_UNSIGNED_INT_8_8_8_8
                | GL_UNSIGNED_INT_8_8_8_8_REV
                | GL_UNSIGNED_INT_2_10_10_10_REV
                | GL_UNSIGNED_INT_24_8
                | GL_UNSIGNED_SHORT_5_6_5
                | GL_UNSIGNED_SHORT_5_6_5_REV
                | GL_UNSIGNED_SHORT_4_4_4_4
                | GL_UNSIGNED_SHORT_4_4_4_4_REV
                | GL_UNSIGNED_SHORT_5_5_5_1
                | GL_UNSIGNED_SHORT_1_5_5_5_REV
        ) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let Some(base) = base_format(internal) else {
            self.set_error(GL_INVALID_VALUE);
            return;
        };
        let too_large = size.iter().any(|&s| s > MAX_TEXTURE_SIZE)
            || (dims == 3 && size.iter().any(|&s| s > MAX_3D_TEXTURE_SIZE));
        if !(0..MAX_LEVELS).contains(&level)
            || size.iter().any(|&s| s < 0)
            || border != 0
            || (too_large && proxy.is_none())
        {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if bind_target == GL_TEXTURE_CUBE_MAP && size[0] != size[1] {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        // GL_ARB_texture_cube_map_array: square faces, whole cubes of six
        // layer-faces.
        if bind_target == GL_TEXTURE_CUBE_MAP_ARRAY_ARB && (size[0] != size[1] || size[2] % 6 != 0)
        {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if pixel_size(format, ty).is_none() {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        // Depth formats need depth data and vice versa (GL 2.1 §3.8.1).
        let depth_fmt = matches!(base, GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL);
        let depth_data = matches!(format, GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL);
        let depth_target = matches!(
            bind_target,
            GL_TEXTURE_1D
                | GL_TEXTURE_2D
                | GL_TEXTURE_CUBE_MAP
                | GL_TEXTURE_1D_ARRAY
                | GL_TEXTURE_2D_ARRAY
                | GL_TEXTURE_CUBE_MAP_ARRAY_ARB
                | GL_TEXTURE_RECTANGLE
        );
        if depth_fmt != depth_data || (depth_fmt && !depth_target) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if !integer_data_matches(internal, format, ty) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        // A rectangle texture has one level (GL 3.1 §3.8.1).
        if bind_target == GL_TEXTURE_RECTANGLE && level != 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let (w, h, d) = (size[0] as usize, size[1] as usize, size[2] as usize);
        let out_of_memory = w.saturating_mul(h).saturating_mul(d) > MAX_TEXELS;
        if let Some(bind) = proxy {
            let img = (!too_large && !out_of_memory).then(|| Image {
                width: size[0],
                height: size[1],
                depth: size[2],
                internal_format: internal as u32,
                texels: Vec::new(),
            });
            let tex = self
                .objects
                .proxies
                .entry(bind)
                .or_insert_with(|| TextureObj::new(bind));
            match img {
                Some(img) => set_image(tex, 0, level as usize, img),
                None => clear_image(tex, 0, level as usize),
            }
            return;
        }
        if out_of_memory {
            self.set_error(GL_OUT_OF_MEMORY);
            return;
        }
        let alignment = self.st.unpack.alignment;
        let texels = unpack_image(data, w, h, d, format, ty, internal, alignment);
        let unit = self.st.active_texture as usize;
        let Some(tex) = self.objects.bound_texture_mut(unit, bind_target) else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let img = Image {
            width: size[0],
            height: size[1],
            depth: size[2],
            internal_format: internal as u32,
            texels,
        };
        set_image(tex, face, level as usize, img);
        if tex.params.generate_mipmap && level == tex.params.base_level {
            generate_mipmaps(tex, face);
        }
    }

    /// glTexSubImage1D, glTexSubImage2D and glTexSubImage3D: replaces the
    /// `size` block at `off` of an existing image, one entry per dimension
    /// as for [`Context::tex_image`] (`data`: the client image, already
    /// validated in size by the caller, or empty for a null pointer).
    #[allow(clippy::too_many_arguments)]
    pub fn tex_sub_image<const D: usize>(
        &mut self,
        target: u32,
        level: i32,
        off: [i32; D],
        size: [i32; D],
        format: u32,
        ty: u32,
        data: &[u8],
    ) {
        if self.reject_in_begin() {
            return;
        }
        let (dims, off, size) = (D as u32, extent(off, 0), extent(size, 1));
        let Some((bind_target, face)) = image_target(target, dims) else {
            self.set_error(GL_INVALID_ENUM);
            return;
        };
        if format_components(format).is_none() {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if pixel_size(format, ty).is_none() {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if !(0..MAX_LEVELS).contains(&level) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let alignment = self.st.unpack.alignment;
        let unit = self.st.active_texture as usize;
        let internal = self
            .objects
            .bound_texture(unit, bind_target)
            .and_then(|t| t.image(face, level as usize))
            .map(|i| i.internal_format as i32);
        if internal.is_some_and(|i| !integer_data_matches(i, format, ty)) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let Some(tex) = self.objects.bound_texture_mut(unit, bind_target) else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let Some(img) = tex
            .faces
            .get_mut(face)
            .and_then(|f| f.get_mut(level as usize))
            .and_then(|i| i.as_mut())
        else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let dim = [img.width, img.height, img.depth];
        let fits = (0..3).all(|i| {
            off[i] >= 0 && size[i] >= 0 && off[i].checked_add(size[i]).is_some_and(|e| e <= dim[i])
        });
        if !fits {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let (w, h, d) = (size[0] as usize, size[1] as usize, size[2] as usize);
        if w == 0 || h == 0 || d == 0 || data.is_empty() {
            return;
        }
        let internal = img.internal_format as i32;
        let texels = unpack_image(Some(data), w, h, d, format, ty, internal, alignment);
        let (iw, ih) = (img.width as usize, img.height as usize);
        for z in 0..d {
            for y in 0..h {
                for x in 0..w {
                    let dst = ((off[2] as usize + z) * ih + off[1] as usize + y) * iw
                        + off[0] as usize
                        + x;
                    if let (Some(t), Some(src)) =
                        (img.texels.get_mut(dst), texels.get((z * h + y) * w + x))
                    {
                        *t = *src;
                    }
                }
            }
        }
        tex.generation += 1;
        if tex.params.generate_mipmap && level == tex.params.base_level {
            generate_mipmaps(tex, face);
        }
    }

    /// glTexParameter{f,i,fv,iv} (a scalar form of
    /// GL_TEXTURE_BORDER_COLOR is too few values: GL_INVALID_VALUE).
    pub fn tex_parameter(&mut self, target: u32, pname: u32, v: Param) {
        if self.reject_in_begin() {
            return;
        }
        let (e, v) = (v.as_enum(), &v.floats(pname)[..]);
        // Buffer textures have no sampler parameters (GL 3.1 §3.8.4).
        if target_index(target).is_none() || target == GL_TEXTURE_BUFFER {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let need = if matches!(pname, GL_TEXTURE_BORDER_COLOR | GL_TEXTURE_SWIZZLE_RGBA) {
            4
        } else {
            1
        };
        if v.len() < need {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let unit = self.st.active_texture as usize;
        let Some(tex) = self.objects.bound_texture_mut(unit, target) else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let rect = tex.target == GL_TEXTURE_RECTANGLE;
        let p = &mut tex.params;
        let mut err = GL_NO_ERROR;
        match pname {
            // GL 3.1 §3.8.4: a rectangle texture has no mipmaps and does
            // not repeat.
            GL_TEXTURE_MIN_FILTER if rect && !matches!(e, GL_NEAREST | GL_LINEAR) => {
                err = GL_INVALID_ENUM
            }
            GL_TEXTURE_WRAP_S | GL_TEXTURE_WRAP_T | GL_TEXTURE_WRAP_R
                if rect && matches!(e, GL_REPEAT | GL_MIRRORED_REPEAT) =>
            {
                err = GL_INVALID_ENUM
            }
            GL_TEXTURE_BASE_LEVEL if rect && v[0] as i32 != 0 => err = GL_INVALID_OPERATION,
            GL_TEXTURE_BASE_LEVEL | GL_TEXTURE_MAX_LEVEL => {
                let l = v[0] as i32;
                if l < 0 {
                    err = GL_INVALID_VALUE;
                } else if pname == GL_TEXTURE_BASE_LEVEL {
                    p.base_level = l;
                } else {
                    p.max_level = l;
                }
            }
            GL_DEPTH_TEXTURE_MODE
                if matches!(e, GL_LUMINANCE | GL_INTENSITY | GL_ALPHA | GL_RED) =>
            {
                p.depth_mode = e
            }
            GL_GENERATE_MIPMAP => p.generate_mipmap = v[0] != 0.0,
            GL_TEXTURE_SWIZZLE_R..=GL_TEXTURE_SWIZZLE_RGBA => {
                let all = pname == GL_TEXTURE_SWIZZLE_RGBA;
                let values: Vec<u32> = v
                    .iter()
                    .take(if all { 4 } else { 1 })
                    .map(|&x| x as u32)
                    .collect();
                if values.iter().all(|&s| valid_swizzle(s)) {
                    if all {
                        p.swizzle.copy_from_slice(&values);
                    } else {
                        p.swizzle[(pname - GL_TEXTURE_SWIZZLE_R) as usize] = values[0];
                    }
                } else {
                    err = GL_INVALID_ENUM;
                }
            }
            GL_TEXTURE_PRIORITY => {}
            _ => err = set_sampler_state(p, pname, e, v).unwrap_or(GL_INVALID_ENUM),
        }
        tex.generation += 1;
        if err != GL_NO_ERROR {
            self.set_error(err);
        }
    }

    /// glGetTexParameteriv (single-valued parameters).
    pub fn get_tex_parameteriv(&mut self, target: u32, pname: u32) -> i32 {
        let unit = self.st.active_texture as usize;
        let Some(t) = self.objects.bound_texture(unit, target) else {
            self.set_error(GL_INVALID_ENUM);
            return 0;
        };
        let p = t.params;
        match pname {
            GL_TEXTURE_MIN_FILTER => p.min_filter as i32,
            GL_TEXTURE_MAG_FILTER => p.mag_filter as i32,
            GL_TEXTURE_WRAP_S => p.wrap[0] as i32,
            GL_TEXTURE_WRAP_T => p.wrap[1] as i32,
            GL_TEXTURE_WRAP_R => p.wrap[2] as i32,
            GL_TEXTURE_BASE_LEVEL => p.base_level,
            GL_TEXTURE_MAX_LEVEL => p.max_level,
            GL_TEXTURE_COMPARE_MODE => p.compare_mode as i32,
            GL_TEXTURE_COMPARE_FUNC => p.compare_func as i32,
            GL_DEPTH_TEXTURE_MODE => p.depth_mode as i32,
            GL_GENERATE_MIPMAP => p.generate_mipmap as i32,
            GL_TEXTURE_SWIZZLE_R..=GL_TEXTURE_SWIZZLE_A => {
                p.swizzle[(pname - GL_TEXTURE_SWIZZLE_R) as usize] as i32
            }
            _ => {
                self.set_error(GL_INVALID_ENUM);
                0
            }
        }
    }

    /// glGetTexLevelParameteriv: sizes, internal format, border, component
    /// sizes (8 bits per stored component, 24 for depth), compression.
    pub fn get_tex_level_parameteriv(&mut self, target: u32, level: i32, pname: u32) -> i32 {
        let Some(img) = self.level_image(target, level, true) else {
            return 0;
        };
        let info = img.map(|i| {
            (
                [i.width, i.height, i.depth],
                i.internal_format,
                base_format(i.internal_format as i32).unwrap_or(GL_RGBA),
            )
        });
        let bits = |has: &[u32]| match info {
            Some((_, internal, base)) if has.contains(&base) => {
                if base == GL_DEPTH_COMPONENT && internal != GL_DEPTH_COMPONENT32F {
                    24
                } else {
                    component_info(internal as i32).0 as i32
                }
            }
            _ => 0,
        };
        // GL 3.0's component types: NONE for a component the format lacks.
        let kind = |has: &[u32]| match info {
            Some((_, internal, base)) if has.contains(&base) => {
                component_info(internal as i32).1 as i32
            }
            _ => GL_NONE as i32,
        };
        match pname {
            GL_TEXTURE_WIDTH => info.map_or(0, |i| i.0[0]),
            GL_TEXTURE_HEIGHT => info.map_or(0, |i| i.0[1]),
            GL_TEXTURE_DEPTH => info.map_or(0, |i| i.0[2]),
            GL_TEXTURE_INTERNAL_FORMAT => info.map_or(1, |i| i.1 as i32),
            GL_TEXTURE_BORDER | GL_TEXTURE_COMPRESSED => 0,
            GL_TEXTURE_RED_SIZE => bits(&[GL_RGB, GL_RGBA, GL_RED, GL_RG]),
            GL_TEXTURE_GREEN_SIZE => bits(&[GL_RGB, GL_RGBA, GL_RG]),
            // R11F_G11F_B10F's blue has one bit less.
            GL_TEXTURE_BLUE_SIZE => match info {
                Some((_, GL_R11F_G11F_B10F, _)) => 10,
                _ => bits(&[GL_RGB, GL_RGBA]),
            },
            GL_TEXTURE_ALPHA_SIZE => bits(&[GL_RGBA, GL_ALPHA, GL_LUMINANCE_ALPHA]),
            GL_TEXTURE_LUMINANCE_SIZE => bits(&[GL_LUMINANCE, GL_LUMINANCE_ALPHA]),
            GL_TEXTURE_INTENSITY_SIZE => bits(&[GL_INTENSITY]),
            GL_TEXTURE_DEPTH_SIZE => bits(&[GL_DEPTH_COMPONENT]),
            GL_TEXTURE_RED_TYPE => kind(&[GL_RGB, GL_RGBA, GL_RED, GL_RG]),
            GL_TEXTURE_GREEN_TYPE => kind(&[GL_RGB, GL_RGBA, GL_RG]),
            GL_TEXTURE_BLUE_TYPE => kind(&[GL_RGB, GL_RGBA]),
            GL_TEXTURE_ALPHA_TYPE => kind(&[GL_RGBA, GL_ALPHA, GL_LUMINANCE_ALPHA]),
            GL_TEXTURE_LUMINANCE_TYPE => kind(&[GL_LUMINANCE, GL_LUMINANCE_ALPHA]),
            GL_TEXTURE_INTENSITY_TYPE => kind(&[GL_INTENSITY]),
            GL_TEXTURE_DEPTH_TYPE => kind(&[GL_DEPTH_COMPONENT, GL_DEPTH_STENCIL]),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                0
            }
        }
    }

    /// glGetTexParameterfv: the float parameters (border colour, LOD
    /// range, priority, residency) and the others as floats.
    pub fn get_tex_parameterfv(&mut self, target: u32, pname: u32) -> Vec<f32> {
        let unit = self.st.active_texture as usize;
        let Some(t) = self.objects.bound_texture(unit, target) else {
            self.set_error(GL_INVALID_ENUM);
            return Vec::new();
        };
        let p = t.params;
        match pname {
            GL_TEXTURE_BORDER_COLOR => p.border_color.to_vec(),
            GL_TEXTURE_MIN_LOD => vec![p.min_lod],
            GL_TEXTURE_MAX_LOD => vec![p.max_lod],
            GL_TEXTURE_LOD_BIAS => vec![p.lod_bias],
            GL_TEXTURE_PRIORITY | GL_TEXTURE_RESIDENT => vec![1.0],
            GL_TEXTURE_SWIZZLE_RGBA => p.swizzle.iter().map(|&s| s as f32).collect(),
            _ => vec![self.get_tex_parameteriv(target, pname) as f32],
        }
    }

    /// The image `level` of the texture `target` names (a 1D/2D/3D target
    /// or a cube face) on the active unit, or with `proxies` of a proxy
    /// target; None with GL_INVALID_ENUM or GL_INVALID_VALUE set for a bad
    /// target or level, Some(None) for an undefined image.
    fn level_image(&mut self, target: u32, level: i32, proxies: bool) -> Option<Option<&Image>> {
        let proxy = (1..=3)
            .find_map(|dims| proxy_target(target, dims))
            .filter(|_| proxies);
        if let Some(bind) = proxy {
            if !(0..MAX_LEVELS).contains(&level) {
                self.set_error(GL_INVALID_VALUE);
                return None;
            }
            return Some(
                self.objects
                    .proxies
                    .get(&bind)
                    .and_then(|t| t.image(0, level as usize)),
            );
        }
        let Some((bind, face)) = image_target(target, 2)
            .or_else(|| image_target(target, 1))
            .or_else(|| image_target(target, 3))
        else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        if !(0..MAX_LEVELS).contains(&level) {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let unit = self.st.active_texture as usize;
        Some(
            self.objects
                .bound_texture(unit, bind)
                .and_then(|t| t.image(face, level as usize)),
        )
    }

    /// glGetTexImage: the image as `format`/`ty` rows at the pack
    /// alignment (empty for an undefined image). Components are taken per
    /// GL 2.1 Table 6.1 (luminance and intensity to red).
    pub fn get_tex_image(&mut self, target: u32, level: i32, format: u32, ty: u32) -> Vec<u8> {
        if self.reject_in_begin() {
            return Vec::new();
        }
        if format_components(format).is_none()
            || matches!(format, GL_STENCIL_INDEX | GL_DEPTH_STENCIL | GL_COLOR_INDEX)
        {
            self.set_error(GL_INVALID_ENUM);
            return Vec::new();
        }
        let Some((px, comp)) = pixel_size(format, ty) else {
            self.set_error(GL_INVALID_ENUM);
            return Vec::new();
        };
        let align = self.st.pack.alignment.max(1);
        let Some(img) = self.level_image(target, level, false) else {
            return Vec::new();
        };
        let Some(img) = img.cloned() else {
            return Vec::new();
        };
        let base = base_format(img.internal_format as i32).unwrap_or(GL_RGBA);
        if is_depth_format(img.internal_format as i32) != (format == GL_DEPTH_COMPONENT) {
            self.set_error(GL_INVALID_OPERATION);
            return Vec::new();
        }
        // Integer images go to integer formats only, and back (GL 3.3
        // §6.1.4).
        let integer = integer_format(img.internal_format as i32);
        if integer.is_some() != integer_client_format(format).is_some() {
            self.set_error(GL_INVALID_OPERATION);
            return Vec::new();
        }
        let n = format_components(format).unwrap_or(4);
        if comp != px / n.max(1) {
            // Packed types are not implemented for reads.
            self.set_error(GL_INVALID_OPERATION);
            return Vec::new();
        }
        let (w, h, d) = (
            img.width.max(0) as usize,
            img.height.max(0) as usize,
            img.depth.max(0) as usize,
        );
        let texels: Vec<[f32; 4]> = img
            .texels
            .iter()
            .map(|&[r, g, b, a]| match base {
                GL_ALPHA => [0.0, 0.0, 0.0, a],
                GL_LUMINANCE | GL_INTENSITY | GL_RED => [r, 0.0, 0.0, 1.0],
                GL_LUMINANCE_ALPHA => [r, 0.0, 0.0, a],
                GL_RG => [r, g, 0.0, 1.0],
                GL_RGB => [r, g, b, 1.0],
                _ => [r, g, b, a],
            })
            .collect();
        if let Some((_, _, signed)) = integer {
            // Stored integer texels already hold 0 and 1 for the
            // components their format lacks.
            let rows = h.saturating_mul(d);
            return pack_integer_pixels(&img.texels, signed, w, rows, format, ty, align);
        }
        pack_pixels(&texels, w, h.saturating_mul(d), format, ty, align)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn luminance_and_alignment() {
        let mut ctx = Context::new(4, 4);
        let t = ctx.gen_textures(1)[0];
        ctx.bind_texture(GL_TEXTURE_2D, t);
        // 3x2 luminance bytes with 4-byte row alignment: rows are 4 bytes.
        let data = [10u8, 20, 30, 0, 40, 50, 60, 0];
        ctx.tex_image(
            GL_TEXTURE_2D,
            0,
            GL_LUMINANCE as i32,
            [3, 2],
            0,
            GL_LUMINANCE,
            GL_UNSIGNED_BYTE,
            Some(&data),
        );
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        let img = ctx.objects.textures[&t].image(0, 0).unwrap().clone();
        assert_eq!(
            img.texels[3],
            [40.0 / 255.0, 40.0 / 255.0, 40.0 / 255.0, 1.0]
        );
        ctx.tex_image(
            GL_TEXTURE_2D,
            0,
            GL_ALPHA as i32,
            [1, 1],
            0,
            GL_RGBA,
            GL_FLOAT,
            Some(&[0u8; 16]),
        );
        let img = ctx.objects.textures[&t].image(0, 0).unwrap().clone();
        assert_eq!(img.texels[0], [0.0; 4]);
        ctx.tex_image(GL_TEXTURE_2D, 0, 0x1234, [1, 1], 0, GL_RGBA, GL_FLOAT, None);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.tex_image(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            [1, 1],
            1,
            GL_RGBA,
            GL_FLOAT,
            None,
        );
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.tex_image(
            GL_TEXTURE_2D,
            0,
            GL_DEPTH_COMPONENT as i32,
            [1, 1],
            0,
            GL_RGBA,
            GL_FLOAT,
            None,
        );
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.bind_texture(GL_TEXTURE_3D, t);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    }
}
