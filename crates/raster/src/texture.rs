//! Texture storage (GL 2.1 §3.8, GL 3.3 §3.8): the texture objects
//! ([`Texture`]: 1D, 2D, 3D, cube, 1D and 2D array, cube map array,
//! rectangle and buffer targets, mipmap levels, filters, wrap modes, LOD
//! parameters, depth comparison), their levels ([`Image`]), what a
//! texture unit binds ([`TextureUnit`]) and completeness
//! ([`Texture::last_level`]). Sampling lives above this module: the
//! definitions both sampling paths share (λ, level selection, wrapping)
//! in [`levels`], the general path in `texture_general`, the 2D fast
//! path in `texture_2d`, and `texture_units` hands each lookup to one of
//! them.
//!
//! Texels arrive as RGBA f32 (the gl layer converts formats: LUMINANCE
//! becomes (L, L, L, 1) and so on; depth textures keep the depth in
//! component 0). A level whose every component is exactly `k / 255` for
//! an integer k (every unorm8 format: RGBA8, LUMINANCE8, ...) is stored as
//! RGBA8 bytes instead (a quarter of the memory traffic) and read back
//! through a table of those exact values, so the two storages sample to
//! the same bits. Integer textures hold the integers' bits instead
//! ([`Texture::integer`]); a level of one 8- or 16-bit integer channel
//! keeps only those 16 bits per texel ([`Red16`]). Texture borders are not supported (border width 0);
//! CLAMP and CLAMP_TO_BORDER sample the border color.
//!
//! The 2D fast path's x86 variants read an RGBA8 level through a padded
//! copy with the wrap neighbours appended ([`Image::padded`]), built by
//! the first lookup and kept with the level: such a level takes twice its
//! memory.

use std::sync::Arc;

use crate::state::CompareFunc;

pub(crate) mod levels;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextureTarget {
    Tex1D,
    Tex2D,
    Tex3D,
    /// Six faces stored as the layers of each level, in the order
    /// +X, −X, +Y, −Y, +Z, −Z.
    Cube,
    /// Layers stored as the rows of each level (its height is the layer
    /// count).
    Tex1DArray,
    /// Layers stored as the depth of each level.
    Tex2DArray,
    /// GL_ARB_texture_cube_map_array: cubes of six faces stored as the
    /// layers of each level, layer-face `6 · cube + face` (faces in
    /// [`TextureTarget::Cube`]'s order); the depth is six times the cube
    /// count.
    CubeArray,
    /// One level addressed in texels (GL 3.1 §3.8.8: coordinates not
    /// scaled by the size, no mipmaps; only the clamping wrap modes).
    Rect,
    /// One row of texels, reached by `texelFetch` only.
    Buffer,
}

/// `k / 255` for every byte k, as `unorm8_to_float` computes it.
pub(crate) const UNORM8: [f32; 256] = {
    let mut t = [0.0f32; 256];
    let mut k = 0;
    while k < 256 {
        t[k] = k as f32 / 255.0;
        k += 1;
    }
    t
};

/// A level's texels: RGBA f32, or RGBA8 or [`Red16`] when that is
/// exact.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Texels {
    F32(Vec<[f32; 4]>),
    Unorm8(Vec<[u8; 4]>),
    Red16(Red16),
}

/// Texels whose green, blue and alpha bits are the same everywhere and
/// whose red bits are a 16-bit integer (zero- or sign-extended): the
/// one-channel integer formats of 8 and 16 bits (R8UI, R16UI, R16I ...),
/// at an eighth of the f32 texels' memory.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Red16 {
    pub(crate) red: Vec<u16>,
    /// Whether `red` is sign-extended to 32 bits (else zero-extended).
    pub(crate) signed: bool,
    /// The bits of green, blue and alpha.
    pub(crate) rest: [u32; 3],
}

impl Red16 {
    /// The texels as [`Red16`], when they all fit.
    fn pack(texels: &[[f32; 4]]) -> Option<Red16> {
        let first = texels.first()?;
        let rest = [first[1].to_bits(), first[2].to_bits(), first[3].to_bits()];
        let same = |t: &[f32; 4]| [t[1].to_bits(), t[2].to_bits(), t[3].to_bits()] == rest;
        let bits = |t: &[f32; 4]| t[0].to_bits();
        let signed = !texels.iter().all(|t| bits(t) <= 0xffff);
        let fits = |t: &[f32; 4]| match signed {
            false => bits(t) <= 0xffff,
            true => i16::try_from(bits(t) as i32).is_ok(),
        };
        if !texels.iter().all(|t| same(t) && fits(t)) {
            return None;
        }
        Some(Red16 {
            red: texels.iter().map(|t| bits(t) as u16).collect(),
            signed,
            rest,
        })
    }

    /// The texel at `index`, if there is one.
    #[inline]
    pub(crate) fn get(&self, index: usize) -> Option<[f32; 4]> {
        let r = *self.red.get(index)?;
        let r = if self.signed {
            r as i16 as i32 as u32
        } else {
            r as u32
        };
        let [g, b, a] = self.rest;
        Some([r, g, b, a].map(f32::from_bits))
    }
}

impl Texels {
    /// RGBA8 when every component is one of the 256 values of [`UNORM8`]
    /// (bit for bit: −0.0 and NaN stay f32), else [`Red16`] when the
    /// texels fit it, else the f32 texels.
    fn pack(texels: Vec<[f32; 4]>) -> Texels {
        let byte = |x: f32| -> Option<u8> {
            if !(0.0..=1.0).contains(&x) {
                return None;
            }
            // x is in [0, 1]: the nearest k is in [0, 255].
            let k = (x * 255.0 + 0.5) as u8;
            (UNORM8[k as usize].to_bits() == x.to_bits()).then_some(k)
        };
        let mut packed = Vec::with_capacity(texels.len());
        for t in &texels {
            match (byte(t[0]), byte(t[1]), byte(t[2]), byte(t[3])) {
                (Some(r), Some(g), Some(b), Some(a)) => packed.push([r, g, b, a]),
                _ => return Red16::pack(&texels).map_or(Texels::F32(texels), Texels::Red16),
            }
        }
        Texels::Unorm8(packed)
    }

    fn len(&self) -> usize {
        match self {
            Texels::F32(v) => v.len(),
            Texels::Unorm8(v) => v.len(),
            Texels::Red16(v) => v.red.len(),
        }
    }

    #[inline]
    pub(crate) fn get(&self, index: usize) -> [f32; 4] {
        match self {
            Texels::F32(v) => v.get(index).copied().unwrap_or(MISSING),
            Texels::Unorm8(v) => v
                .get(index)
                .map(|t| t.map(|b| UNORM8[b as usize]))
                .unwrap_or(MISSING),
            Texels::Red16(v) => v.get(index).unwrap_or(MISSING),
        }
    }
}

/// One mipmap level: `width × height × depth` texels, row-major from the
/// bottom row of the first layer (`(k * height + j) * width + i`).
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub depth: u32,
    pub(crate) texels: Texels,
    /// The level with its wrap neighbours appended, built by the first
    /// lookup that wants it (see [`Padded`]).
    pub(crate) padded: PaddedCell,
}

/// An RGBA8 2D level laid out `(width + 1) × (height + 1)`: texel (i, j)
/// of the level at `j·(width + 1) + i`, plus a last column and a last row
/// holding the texels a bilinear footprint reads past the level's edge
/// under the wrap modes `wrap` (REPEAT: column / row 0; CLAMP_TO_EDGE:
/// the last column / row again). Every 2×2 footprint is then two pairs of
/// neighbours in memory, with no wrap to apply to the second texel of a
/// row or to the second row ([`crate::texture_2d`]'s x86 filter).
pub(crate) struct Padded {
    pub(crate) wrap: [Wrap; 2],
    pub(crate) width: u32,
    pub(crate) height: u32,
    pub(crate) texels: Box<[[u8; 4]]>,
}

/// [`Padded`] once built (or `None` when the level cannot have one). A
/// level's texels never change after [`Image::new`] (the field is private
/// to the crate and nothing writes it), a clone starts empty, and the
/// layout is checked against the level's size and the lookup's wrap
/// modes on every use, so a stale copy is never read.
#[derive(Default)]
pub(crate) struct PaddedCell(std::sync::OnceLock<Option<Padded>>);

impl Clone for PaddedCell {
    fn clone(&self) -> PaddedCell {
        PaddedCell::default()
    }
}

impl PartialEq for PaddedCell {
    /// A cache: never part of an image's value.
    fn eq(&self, _: &PaddedCell) -> bool {
        true
    }
}

impl std::fmt::Debug for PaddedCell {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("PaddedCell")
    }
}

impl Image {
    /// A level from its RGBA texels (stored as RGBA8 when that is exact,
    /// see the module documentation).
    pub fn new(width: u32, height: u32, depth: u32, texels: Vec<[f32; 4]>) -> Image {
        Image {
            width,
            height,
            depth,
            texels: Texels::pack(texels),
            padded: PaddedCell::default(),
        }
    }

    /// Number of texels stored.
    pub fn len(&self) -> usize {
        self.texels.len()
    }

    /// Whether the level holds no texels.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Whether the level is stored as RGBA8 (see the module documentation).
    pub fn is_unorm8(&self) -> bool {
        matches!(self.texels, Texels::Unorm8(_))
    }

    /// Whether the level stores `width × height × depth` texels.
    #[inline]
    pub(crate) fn holds_texels(&self) -> bool {
        // (u128: the product of three u32 does not overflow.)
        self.len() as u128 == self.width as u128 * self.height as u128 * self.depth as u128
    }

    /// Texel `index` (see the layout above), (0, 0, 0, 1) out of range.
    pub fn texel_at(&self, index: usize) -> [f32; 4] {
        self.texels.get(index)
    }

    #[inline]
    pub(crate) fn texel(&self, i: usize, j: usize, k: usize) -> [f32; 4] {
        let (w, h) = (self.width as usize, self.height as usize);
        self.texels.get((k * h + j) * w + i)
    }

    /// This RGBA8 2D level as [`Padded`] for the wrap modes `wrap` (each
    /// REPEAT or CLAMP_TO_EDGE), built on first use; `None` for other
    /// levels (f32, 3D, empty or too large for 32-bit indices) or when
    /// the copy was built for other wrap modes.
    pub(crate) fn padded(&self, wrap: [Wrap; 2]) -> Option<&[[u8; 4]]> {
        let p = self.padded.0.get_or_init(|| self.pad(wrap)).as_ref()?;
        let fits = p.wrap == wrap && p.width == self.width && p.height == self.height;
        fits.then_some(&p.texels[..])
    }

    fn pad(&self, wrap: [Wrap; 2]) -> Option<Padded> {
        let Texels::Unorm8(texels) = &self.texels else {
            return None;
        };
        let (w, h) = (self.width as usize, self.height as usize);
        let plain = |m: Wrap| matches!(m, Wrap::Repeat | Wrap::ClampToEdge);
        if self.depth != 1
            || w == 0
            || h == 0
            || texels.len() < w * h
            || !wrap.iter().all(|&m| plain(m))
        {
            return None;
        }
        if (w as u64 + 1) * (h as u64 + 1) > i32::MAX as u64 {
            return None;
        }
        // The texel past the last one (index n) of an axis of size n.
        let past = |m: Wrap, n: usize| if m == Wrap::Repeat { 0 } else { n - 1 };
        let mut out = Vec::with_capacity((w + 1) * (h + 1));
        for j in 0..=h {
            let row = if j < h { j } else { past(wrap[1], h) };
            let src = texels.get(row * w..row * w + w)?;
            out.extend_from_slice(src);
            out.push(*src.get(past(wrap[0], w))?);
        }
        Some(Padded {
            wrap,
            width: self.width,
            height: self.height,
            texels: out.into_boxed_slice(),
        })
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MinFilter {
    Nearest,
    Linear,
    NearestMipmapNearest,
    LinearMipmapNearest,
    NearestMipmapLinear,
    LinearMipmapLinear,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MagFilter {
    Nearest,
    Linear,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Wrap {
    Repeat,
    Clamp,
    ClampToEdge,
    ClampToBorder,
    MirroredRepeat,
}

/// DEPTH_TEXTURE_MODE: how a depth (or comparison) value r becomes RGBA.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DepthTextureMode {
    /// (r, r, r, 1)
    Luminance,
    /// (r, r, r, r)
    Intensity,
    /// (0, 0, 0, r)
    Alpha,
    /// (r, 0, 0, 1) (GL 3.0)
    Red,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    pub target: TextureTarget,
    /// Mipmap levels by level number (level 0 first).
    pub levels: Vec<Image>,
    pub min_filter: MinFilter,
    pub mag_filter: MagFilter,
    /// TEXTURE_WRAP_S, _T, _R.
    pub wrap: [Wrap; 3],
    pub border_color: [f32; 4],
    pub min_lod: f32,
    pub max_lod: f32,
    /// TEXTURE_LOD_BIAS of the texture object.
    pub lod_bias: f32,
    pub base_level: u32,
    pub max_level: u32,
    /// The internal format is DEPTH_COMPONENT (depth in component 0).
    pub depth_format: bool,
    /// TEXTURE_COMPARE_MODE = COMPARE_R_TO_TEXTURE with this function.
    pub compare: Option<CompareFunc>,
    pub depth_mode: DepthTextureMode,
    /// The internal format is an integer one (GL 3.0 §3.8.1): texels hold
    /// the integers' bits (`f32::from_bits`), lookups read the nearest
    /// texel of one level and return them unconverted.
    pub integer: bool,
    /// The internal format is an sRGB one (GL 2.1 §3.8.15, EXT_texture_sRGB):
    /// each texel's red, green and blue are decoded to linear before
    /// filtering (`srgb_to_linear`).
    pub srgb: bool,
    /// TEXTURE_SWIZZLE_R/G/B/A (GL 3.3 §3.9.8): what each component of a
    /// lookup's result is, from the value after the depth texture mode.
    pub swizzle: [Swizzle; 4],
}

/// One component's texture swizzle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Swizzle {
    R,
    G,
    B,
    A,
    Zero,
    One,
}

/// The identity swizzle.
pub const NO_SWIZZLE: [Swizzle; 4] = [Swizzle::R, Swizzle::G, Swizzle::B, Swizzle::A];

impl Texture {
    /// `v` through the texture's swizzle (ONE is 1.0, or integer 1 for an
    /// integer texture).
    #[inline]
    pub(crate) fn swizzled(&self, v: [f32; 4]) -> [f32; 4] {
        if self.swizzle == NO_SWIZZLE {
            return v;
        }
        let one = if self.integer { f32::from_bits(1) } else { 1.0 };
        self.swizzle.map(|s| match s {
            Swizzle::R => v[0],
            Swizzle::G => v[1],
            Swizzle::B => v[2],
            Swizzle::A => v[3],
            Swizzle::Zero => 0.0,
            Swizzle::One => one,
        })
    }
}

/// The sRGB decoding of a stored component c in [0, 1] (GL 2.1 eq. 3.30):
/// c / 12.92 up to 0.04045, ((c + 0.055) / 1.055)^2.4 above, in
/// `glsl::math`'s `pow`, so every machine computes the same bits.
pub fn srgb_to_linear(c: f32) -> f32 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        glsl::math::pow((c + 0.055) / 1.055, 2.4)
    }
}

impl Texture {
    /// A texture with GL's initial parameters (NEAREST_MIPMAP_LINEAR,
    /// LINEAR, REPEAT, ...).
    pub fn new(target: TextureTarget, levels: Vec<Image>) -> Texture {
        Texture {
            target,
            levels,
            min_filter: MinFilter::NearestMipmapLinear,
            mag_filter: MagFilter::Linear,
            wrap: [Wrap::Repeat; 3],
            border_color: [0.0; 4],
            min_lod: -1000.0,
            max_lod: 1000.0,
            lod_bias: 0.0,
            base_level: 0,
            max_level: 1000,
            depth_format: false,
            compare: None,
            depth_mode: DepthTextureMode::Luminance,
            integer: false,
            srgb: false,
            swizzle: NO_SWIZZLE,
        }
    }

    pub(crate) fn dims(&self) -> usize {
        match self.target {
            TextureTarget::Tex1D | TextureTarget::Tex1DArray | TextureTarget::Buffer => 1,
            TextureTarget::Tex2D
            | TextureTarget::Cube
            | TextureTarget::CubeArray
            | TextureTarget::Tex2DArray
            | TextureTarget::Rect => 2,
            TextureTarget::Tex3D => 3,
        }
    }

    pub(crate) fn mipmapped(&self) -> bool {
        !matches!(self.min_filter, MinFilter::Nearest | MinFilter::Linear)
            && !matches!(self.target, TextureTarget::Rect | TextureTarget::Buffer)
    }

    /// Whether the target's levels are arrays of layers.
    pub(crate) fn layered(&self) -> bool {
        matches!(
            self.target,
            TextureTarget::Tex1DArray | TextureTarget::Tex2DArray | TextureTarget::CubeArray
        )
    }

    /// Size of an image along `axis` as it matters for this target.
    pub(crate) fn size(&self, img: &Image, axis: usize) -> u32 {
        match (axis, self.target) {
            (0, _) => img.width,
            (1, TextureTarget::Tex1D | TextureTarget::Buffer) => 1,
            (1, _) => img.height,
            (2, TextureTarget::Tex3D | TextureTarget::Tex2DArray | TextureTarget::CubeArray) => {
                img.depth
            }
            (2, TextureTarget::Cube) => 6,
            _ => 1,
        }
    }

    /// The last level used, q = min(p, level_max) (GL 2.1 §3.8.8), or
    /// `None` when the texture is incomplete (§3.8.10): the base level
    /// has no zero size and holds its texels, a cube map's is square, and
    /// with mipmapping every level to q halves the sizes of the target's
    /// axes (down to 1) and holds its texels. (A 1D texture's height,
    /// and a 2D or cube texture's depth, are not compared: they are not
    /// sizes of the target.)
    pub fn last_level(&self) -> Option<usize> {
        let base = self.base_level as usize;
        if self.base_level > self.max_level {
            return None;
        }
        let b = self.levels.get(base)?;
        let dims = [self.size(b, 0), self.size(b, 1), self.size(b, 2)];
        if dims.contains(&0) || !b.holds_texels() {
            return None;
        }
        let cubes = matches!(self.target, TextureTarget::Cube | TextureTarget::CubeArray);
        if cubes && b.width != b.height {
            return None;
        }
        if !self.mipmapped() {
            return Some(base);
        }
        let nd = self.dims();
        let largest = dims[..nd].iter().copied().max().unwrap_or(1);
        let p = base + (31 - largest.leading_zeros()) as usize;
        let q = p.min(self.max_level as usize);
        // Level base + s has the sizes `max(1, dims >> s)` on the target's
        // axes (s ≤ 31: `largest` has at most 32 bits).
        let levels = self.levels.get(base + 1..=q)?;
        for (s, img) in (1u32..).zip(levels) {
            let want = |a: usize| (dims[a] >> s).max(1);
            // An array's levels all have the base level's layers.
            let layers_ok = !self.layered() || self.size(img, nd) == dims[nd];
            let sizes_ok = img.width == want(0)
                && (nd < 2 || img.height == want(1))
                && (nd < 3 || img.depth == want(2))
                && layers_ok;
            if !sizes_ok || !img.holds_texels() {
                return None;
            }
        }
        Some(q)
    }
}

/// The textures bound to one texture unit, and the unit's LOD bias.
#[derive(Clone, Debug, Default)]
pub struct TextureUnit {
    pub tex_1d: Option<Arc<Texture>>,
    pub tex_2d: Option<Arc<Texture>>,
    pub tex_3d: Option<Arc<Texture>>,
    pub cube: Option<Arc<Texture>>,
    pub tex_1d_array: Option<Arc<Texture>>,
    pub tex_2d_array: Option<Arc<Texture>>,
    pub cube_array: Option<Arc<Texture>>,
    pub rect: Option<Arc<Texture>>,
    pub buffer: Option<Arc<Texture>>,
    /// TEXTURE_LOD_BIAS of the texture environment.
    pub lod_bias: f32,
}

pub(crate) const MISSING: [f32; 4] = [0.0, 0.0, 0.0, 1.0];

#[cfg(test)]
mod tests;
