//! Textures and sampling (GL 2.1 §3.8): 1D/2D/3D/cube textures with mipmaps,
//! level-of-detail selection from derivatives, NEAREST/LINEAR and the four
//! mipmap filters, the five wrap modes, cube face selection and depth
//! texture comparison.
//!
//! Texels arrive as RGBA f32 (the gl layer converts formats: LUMINANCE
//! becomes (L, L, L, 1) and so on; depth textures keep the depth in
//! component 0). A level whose every component is exactly `k / 255` for
//! an integer k (every unorm8 format: RGBA8, LUMINANCE8, ...) is stored as
//! RGBA8 bytes instead (a quarter of the memory traffic) and read back
//! through a table of those exact values, so the two storages sample to
//! the same bits. Texture borders are not supported (border width 0);
//! CLAMP and CLAMP_TO_BORDER sample the border color.
//!
//! 2D lookups without depth comparison on a texture with REPEAT,
//! CLAMP_TO_EDGE or MIRRORED_REPEAT wrapping take a specialised path
//! ([`crate::texture_2d`]) computing the same operations in the same order
//! as the general one (tests compare the two bit for bit). Its x86
//! variants read an RGBA8 level through a padded copy with the wrap
//! neighbours appended ([`Image::padded`]), built by the first lookup and
//! kept with the level: such a level takes twice its memory.

use std::sync::Arc;

use crate::ex::{Lod, SampleRequest, Textures, LANES};
use crate::state::CompareFunc;
use crate::unorm8_filter;
use glsl::math;
use glsl::types::SamplerKind;

/// `floor(x)`, exact like `glsl::math::floor` (same bits, −0.0 and NaN
/// included) but without the software rounding for the common case
/// |x| < 2^23, where truncation to an integer is exact.
#[inline(always)]
pub(crate) fn floor(x: f32) -> f32 {
    let small = math::abs(x) < 8_388_608.0;
    if !small {
        return math::floor(x);
    }
    let t = x as i32 as f32;
    let f = if t > x { t - 1.0 } else { t };
    // Integral inputs (and ±0.0) are their own floor, sign of zero kept.
    if f == x {
        x
    } else {
        f
    }
}

/// `x - floor(x)`, as `glsl::math::fract`.
#[inline(always)]
pub(crate) fn fract(x: f32) -> f32 {
    x - floor(x)
}

/// MAX_TEXTURE_LOD_BIAS.
pub const MAX_LOD_BIAS: f32 = 16.0;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextureTarget {
    Tex1D,
    Tex2D,
    Tex3D,
    /// Six faces stored as the layers of each level, in the order
    /// +X, −X, +Y, −Y, +Z, −Z.
    Cube,
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

/// A level's texels: RGBA f32, or RGBA8 when that is exact.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Texels {
    F32(Vec<[f32; 4]>),
    Unorm8(Vec<[u8; 4]>),
}

impl Texels {
    /// RGBA8 when every component is one of the 256 values of [`UNORM8`]
    /// (bit for bit: −0.0 and NaN stay f32), else the f32 texels.
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
                _ => return Texels::F32(texels),
            }
        }
        Texels::Unorm8(packed)
    }

    fn len(&self) -> usize {
        match self {
            Texels::F32(v) => v.len(),
            Texels::Unorm8(v) => v.len(),
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

    fn texel(&self, i: usize, j: usize, k: usize) -> [f32; 4] {
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
        }
    }

    fn dims(&self) -> usize {
        match self.target {
            TextureTarget::Tex1D => 1,
            TextureTarget::Tex2D | TextureTarget::Cube => 2,
            TextureTarget::Tex3D => 3,
        }
    }

    pub(crate) fn mipmapped(&self) -> bool {
        !matches!(self.min_filter, MinFilter::Nearest | MinFilter::Linear)
    }

    /// Size of an image along `axis` as it matters for this target.
    fn size(&self, img: &Image, axis: usize) -> u32 {
        match (axis, self.target) {
            (0, _) => img.width,
            (1, TextureTarget::Tex1D) => 1,
            (1, _) => img.height,
            (2, TextureTarget::Tex3D) => img.depth,
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
        if self.target == TextureTarget::Cube && b.width != b.height {
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
            let sizes_ok = img.width == want(0)
                && (nd < 2 || img.height == want(1))
                && (nd < 3 || img.depth == want(2));
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
    /// TEXTURE_LOD_BIAS of the texture environment.
    pub lod_bias: f32,
}

/// All texture units; samples for the exec crate.
#[derive(Clone, Debug)]
pub struct TextureUnits {
    pub units: Vec<TextureUnit>,
    /// What the fast path of 2D lookups finds out about each unit's 2D
    /// texture that depends on the texture alone (completeness, last
    /// level, storage), at the first lookup through these units; each
    /// entry holds the texture it describes and is used only for that
    /// texture (`units` may change after it is filled).
    pub(crate) checked_2d: std::sync::OnceLock<Vec<Option<crate::texture_2d::Checked>>>,
    /// The instruction set the fast path of 2D lookups runs in (the
    /// executor's, `texture_2d::Isa::current`), found once per set of
    /// units rather than per lookup.
    pub(crate) isa: crate::texture_2d::Isa,
}

impl TextureUnits {
    /// The units `units` (the texture units of a draw).
    pub fn new(units: Vec<TextureUnit>) -> TextureUnits {
        TextureUnits {
            units,
            checked_2d: std::sync::OnceLock::new(),
            isa: crate::texture_2d::Isa::current(),
        }
    }
}

impl Default for TextureUnits {
    /// No units.
    fn default() -> TextureUnits {
        TextureUnits::new(Vec::new())
    }
}

pub(crate) const MISSING: [f32; 4] = [0.0, 0.0, 0.0, 1.0];

impl Textures for TextureUnits {
    fn sample(&self, req: &SampleRequest, out: &mut [[f32; LANES]; 4]) {
        if !crate::texture_2d::sample_with(self.isa, self, req, out) {
            self.sample_general(req, out);
        }
    }

    fn sample_2d_implicit(
        &self,
        unit: u32,
        st: [&[f32; LANES]; 2],
        mask: u32,
        out: &mut [[f32; LANES]; 4],
    ) -> bool {
        use crate::texture_2d::{sample_implicit_with, Sampled};
        match sample_implicit_with(self.isa, self, unit, st, mask, out) {
            Sampled::Unorm8 => true,
            Sampled::Yes => false,
            Sampled::No => {
                self.sample(&exec::implicit_2d_request(unit, st, mask), out);
                false
            }
        }
    }
}

impl TextureUnits {
    /// Every lookup, lane by lane (`texture_2d` is the fast path of the
    /// common case, with the same results).
    pub(crate) fn sample_general(&self, req: &SampleRequest, out: &mut [[f32; LANES]; 4]) {
        // (unit, texture and its last level) of the previous lane: lanes
        // almost always share them, and completeness costs a walk over
        // every level.
        let mut cache: Option<(u32, Option<(&Texture, usize)>)> = None;
        for lane in 0..LANES {
            if req.mask & (1 << lane) == 0 {
                continue;
            }
            let unit = req.unit[lane];
            let tex = match cache {
                Some((u, t)) if u == unit => t,
                _ => {
                    let t = self.complete_texture(req, unit);
                    cache = Some((unit, t));
                    t
                }
            };
            let rgba = match tex {
                Some((tex, q)) => self.sample_lane(req, lane, tex, q),
                None => MISSING,
            };
            for (o, v) in out.iter_mut().zip(rgba) {
                o[lane] = v;
            }
        }
    }

    /// The texture of `req`'s target bound to `unit` and its last level,
    /// or `None` (no such unit, nothing bound, incomplete).
    fn complete_texture(&self, req: &SampleRequest, unit: u32) -> Option<(&Texture, usize)> {
        let unit = self.units.get(unit as usize)?;
        let tex = match req.target {
            SamplerKind::Sampler1D | SamplerKind::Sampler1DShadow => &unit.tex_1d,
            SamplerKind::Sampler2D | SamplerKind::Sampler2DShadow => &unit.tex_2d,
            SamplerKind::Sampler3D => &unit.tex_3d,
            SamplerKind::SamplerCube => &unit.cube,
        };
        let tex = tex.as_deref()?;
        Some((tex, tex.last_level()?))
    }

    fn sample_lane(&self, req: &SampleRequest, lane: usize, tex: &Texture, q: usize) -> [f32; 4] {
        let Some(unit) = self.units.get(req.unit[lane] as usize) else {
            return MISSING;
        };
        let coord = [0, 1, 2].map(|c| req.coord[c][lane]);
        let (lod_base, shader_bias) = match &req.lod {
            Lod::Explicit(l) => (LodBase::Value(l[lane]), 0.0),
            Lod::Derivatives { ddx, ddy, bias } => {
                let first = quad_first(lane);
                (
                    LodBase::Derivatives(
                        [0, 1, 2].map(|c| ddx[c][first]),
                        [0, 1, 2].map(|c| ddy[c][first]),
                    ),
                    bias[lane],
                )
            }
        };
        let reference = req.compare.map(|r| r[lane]);
        sample(
            tex,
            q,
            coord,
            lod_base,
            unit.lod_bias + shader_bias,
            reference,
        )
    }
}

/// The first lane of `lane`'s 2×2 quad, whose derivatives give the whole
/// quad's level of detail: GL 2.1 §3.8.8 lets ρ be approximated, and one
/// λ_base per quad (as llvmpipe and GPUs compute it) keeps a quad on one
/// level pair and costs a quarter of the logarithms. The bias is still
/// each lane's.
#[inline(always)]
pub(crate) fn quad_first(lane: usize) -> usize {
    lane & !3
}

/// λ_base source (GL 2.1 eq. 3.18): the scale factor from derivatives, or
/// an explicit value (texture*Lod, or 0 outside fragment shaders).
#[derive(Clone, Copy, Debug)]
pub(crate) enum LodBase {
    Derivatives([f32; 3], [f32; 3]),
    Value(f32),
}

/// Cube face selection (GL 2.1 §3.8.6, table 3.19): face index and
/// (sc, tc, ma). Ties prefer x over y over z.
pub(crate) fn cube_face(r: [f32; 3]) -> (usize, f32, f32, f32) {
    let [x, y, z] = r;
    let (ax, ay, az) = (math::abs(x), math::abs(y), math::abs(z));
    if ax >= ay && ax >= az {
        if x >= 0.0 {
            (0, -z, -y, x)
        } else {
            (1, z, -y, x)
        }
    } else if ay >= az {
        if y >= 0.0 {
            (2, x, z, y)
        } else {
            (3, x, -z, y)
        }
    } else if z >= 0.0 {
        (4, x, -y, z)
    } else {
        (5, -x, -y, z)
    }
}

/// Derivative of `sc / |ma|` given the derivatives of the direction.
fn cube_deriv(face: usize, r: [f32; 3], d: [f32; 3]) -> (f32, f32) {
    // Same table applied to the derivative vector.
    let pick = |v: [f32; 3]| -> (f32, f32, f32) {
        let [x, y, z] = v;
        match face {
            0 => (-z, -y, x),
            1 => (z, -y, x),
            2 => (x, z, y),
            3 => (x, -z, y),
            4 => (x, -y, z),
            _ => (-x, -y, z),
        }
    };
    let (sc, tc, ma) = pick(r);
    let (dsc, dtc, dma) = pick(d);
    let ama = math::abs(ma);
    let dama = if ma >= 0.0 { dma } else { -dma };
    let m2 = ama * ama;
    (
        0.5 * (dsc * ama - sc * dama) / m2,
        0.5 * (dtc * ama - tc * dama) / m2,
    )
}

/// Samples `tex` (complete, last level `q`) at `coord` (s, t, r).
pub(crate) fn sample(
    tex: &Texture,
    q: usize,
    coord: [f32; 3],
    lod: LodBase,
    extra_bias: f32,
    reference: Option<f32>,
) -> [f32; 4] {
    let base = tex.base_level as usize;
    let Some(base_img) = tex.levels.get(base) else {
        return MISSING;
    };
    // Face selection turns a cube lookup into a 2D one on layer `face`.
    let (st, layer, derivs) = if tex.target == TextureTarget::Cube {
        let (face, sc, tc, ma) = cube_face(coord);
        let ama = math::abs(ma);
        let s = 0.5 * (sc / ama + 1.0);
        let t = 0.5 * (tc / ama + 1.0);
        let derivs = match lod {
            LodBase::Derivatives(dx, dy) => {
                let (sx, tx) = cube_deriv(face, coord, dx);
                let (sy, ty) = cube_deriv(face, coord, dy);
                LodBase::Derivatives([sx, tx, 0.0], [sy, ty, 0.0])
            }
            other => other,
        };
        ([s, t, 0.0], Some(face), derivs)
    } else {
        (coord, None, lod)
    };

    let lambda = lambda(tex, base_img, derivs, extra_bias);
    let reference = reference.map(|r| r.clamp(0.0, 1.0));
    let one = |level: usize, linear: bool| -> [f32; 4] {
        match tex.levels.get(level) {
            Some(img) => filter(tex, img, st, layer, linear, reference),
            None => MISSING,
        }
    };
    // RGBA8 levels in fixed point when they qualify (`unorm8_filter`).
    let fixed = |level: usize, linear: bool| -> Option<[i32; 4]> {
        filter_unorm8(tex, tex.levels.get(level)?, st, layer, linear)
    };
    let value = match select_levels(tex, q, lambda) {
        Levels::One(level, linear) => match fixed(level, linear) {
            Some(v) => v.map(unorm8_filter::value),
            None => one(level, linear),
        },
        Levels::Two(d1, d2, f, linear) => match (fixed(d1, linear), fixed(d2, linear)) {
            (Some(v1), Some(v2)) => {
                let w = unorm8_filter::level_weight(f);
                std::array::from_fn(|c| {
                    unorm8_filter::value(unorm8_filter::levels(v1[c], v2[c], w))
                })
            }
            _ => {
                let (t1, t2) = (one(d1, linear), one(d2, linear));
                mix_levels(t1, t2, f)
            }
        },
    };
    if tex.depth_format {
        let r = value[0];
        match tex.depth_mode {
            DepthTextureMode::Luminance => [r, r, r, 1.0],
            DepthTextureMode::Intensity => [r, r, r, r],
            DepthTextureMode::Alpha => [0.0, 0.0, 0.0, r],
        }
    } else {
        value
    }
}

/// Eq. 3.29's blend of two levels' values, `(1 − f)·t1 + f·t2`.
#[inline]
pub(crate) fn mix_levels(t1: [f32; 4], t2: [f32; 4], f: f32) -> [f32; 4] {
    std::array::from_fn(|i| (1.0 - f) * t1[i] + f * t2[i])
}

/// log2(ρ) for the level of detail (λ_base of GL 2.1 eq. 3.18), in f32:
/// ρ = 2^e·m with m in [√½, √2), log2(m) from the series of
/// 2·atanh(s), s = (m − 1)/(m + 1), |s| ≤ 0.172, to s⁹ (truncation below
/// 2·10⁻⁸). Exact at powers of two (m = 1 gives s = 0), so a texture
/// minified by exactly 2^n reads level n; within a few 10⁻⁷ elsewhere,
/// which λ's uses (the level and its fraction) cannot tell from a
/// correctly rounded log2. Branch-free (selects), so that loops over
/// lanes vectorize; only f32 additions, multiplications and one
/// division, each rounded once, so every instruction set gives the same
/// bits. log2(0) = −∞, log2(+∞) = +∞, NaN and negative ρ give NaN
/// (ρ is a square root: never negative).
#[inline(always)]
pub(crate) fn lod_log2(x: f32) -> f32 {
    // Subnormals scaled into the normal range first (exactly).
    let small = x < f32::MIN_POSITIVE;
    let xs = if small { x * 16_777_216.0 } else { x };
    // Subtracting the bits of √½ moves the exponent boundary from 1 to
    // √½ (as `glsl::math`'s log does).
    const SQRT_HALF: u32 = 0x3f35_04f3;
    let bits = xs.to_bits();
    let k = (bits.wrapping_sub(SQRT_HALF) as i32) >> 23;
    let m = f32::from_bits(bits.wrapping_sub((k as u32) << 23));
    let e = k as f32 - if small { 24.0 } else { 0.0 };
    let s = (m - 1.0) / (m + 1.0);
    let z = s * s;
    let p = 1.0 + z * (1.0 / 3.0 + z * (1.0 / 5.0 + z * (1.0 / 7.0 + z * (1.0 / 9.0))));
    let r = e + (2.0 * s * p) * std::f32::consts::LOG2_E;
    let r = if x == 0.0 { f32::NEG_INFINITY } else { r };
    let r = if x == f32::INFINITY { x } else { r };
    if x.is_nan() || x < 0.0 {
        f32::NAN
    } else {
        r
    }
}

/// GL 2.1 §3.8.8: λ = clamp(λ_base + clamp(biases), lod_min, lod_max),
/// λ_base from the derivatives of the (face) coordinates scaled by the
/// base level's size, or given. `extra_bias` is the unit's bias plus the
/// shader's.
#[inline(always)]
pub(crate) fn lambda(tex: &Texture, base_img: &Image, derivs: LodBase, extra_bias: f32) -> f32 {
    let lambda_base = match derivs {
        LodBase::Value(v) => v,
        LodBase::Derivatives(dx, dy) => {
            let mut sx = 0.0f32;
            let mut sy = 0.0f32;
            for a in 0..tex.dims() {
                let size = tex.size(base_img, a) as f32;
                let (ux, uy) = (dx[a] * size, dy[a] * size);
                sx += ux * ux;
                sy += uy * uy;
            }
            let rho = math::max(math::sqrt(sx), math::sqrt(sy));
            lod_log2(rho)
        }
    };
    let bias = (tex.lod_bias + extra_bias).clamp(-MAX_LOD_BIAS, MAX_LOD_BIAS);
    let mut lambda = lambda_base + bias;
    if lambda > tex.max_lod {
        lambda = tex.max_lod;
    }
    if lambda < tex.min_lod {
        lambda = tex.min_lod;
    }
    lambda
}

/// The level(s) a lookup reads and whether each is filtered LINEAR.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Levels {
    One(usize, bool),
    /// Levels d1 and d2 blended with weight f on d2 ([`mix_levels`]).
    Two(usize, usize, f32, bool),
}

/// GL 2.1 §3.8.8–3.8.9: the levels for λ (from [`lambda`]) on `tex`,
/// complete with last level `q`.
#[inline(always)]
pub(crate) fn select_levels(tex: &Texture, q: usize, lambda: f32) -> Levels {
    let base = tex.base_level as usize;
    // §3.8.9: the magnification / minification switch-over point c.
    let c = if tex.mag_filter == MagFilter::Linear
        && matches!(
            tex.min_filter,
            MinFilter::NearestMipmapNearest | MinFilter::NearestMipmapLinear
        ) {
        0.5
    } else {
        0.0
    };
    if lambda.is_nan() || lambda <= c {
        return Levels::One(base, tex.mag_filter == MagFilter::Linear);
    }
    let lb = base as f32 + lambda;
    match tex.min_filter {
        MinFilter::Nearest => Levels::One(base, false),
        MinFilter::Linear => Levels::One(base, true),
        MinFilter::NearestMipmapNearest | MinFilter::LinearMipmapNearest => {
            let linear = tex.min_filter == MinFilter::LinearMipmapNearest;
            // Eq. 3.27.
            let d = if lambda <= 0.5 {
                base
            } else if lb <= q as f32 + 0.5 {
                ((math::ceil(lb + 0.5) - 1.0) as i64).clamp(base as i64, q as i64) as usize
            } else {
                q
            };
            Levels::One(d, linear)
        }
        MinFilter::NearestMipmapLinear | MinFilter::LinearMipmapLinear => {
            let linear = tex.min_filter == MinFilter::LinearMipmapLinear;
            // Eq. 3.28/3.29.
            if lb >= q as f32 {
                Levels::One(q, linear)
            } else {
                let d1 = (floor(lb) as i64).clamp(base as i64, q as i64) as usize;
                let d2 = (d1 + 1).min(q);
                Levels::Two(d1, d2, fract(lambda), linear)
            }
        }
    }
}

/// A wrapped texel coordinate: `None` selects the border color.
type Texel = Option<usize>;

fn mirror(f: f32) -> f32 {
    let fl = floor(f);
    let fr = f - fl;
    if math::modulo(fl, 2.0) == 0.0 {
        fr
    } else {
        1.0 - fr
    }
}

/// GL 2.1 §3.8.7: the coordinate after wrapping (before scaling by size).
#[inline(always)]
pub(crate) fn wrap_coord(s: f32, wrap: Wrap, n: u32) -> f32 {
    let half = 0.5 / n as f32;
    match wrap {
        Wrap::Repeat => fract(s),
        Wrap::Clamp => s.clamp(0.0, 1.0),
        Wrap::ClampToEdge => s.clamp(half, 1.0 - half),
        Wrap::ClampToBorder => s.clamp(-half, 1.0 + half),
        Wrap::MirroredRepeat => mirror(s).clamp(half, 1.0 - half),
    }
}

#[inline(always)]
pub(crate) fn index(i: i64, wrap: Wrap, n: u32) -> Texel {
    let n = n as i64;
    match wrap {
        // Linear filtering asks for -1 and n at the edges, otherwise the
        // index is in range: no division for those.
        Wrap::Repeat if (0..n).contains(&i) => Some(i as usize),
        Wrap::Repeat if i == -1 => Some((n - 1) as usize),
        Wrap::Repeat if i == n => Some(0),
        Wrap::Repeat => Some(i.rem_euclid(n) as usize),
        Wrap::ClampToEdge | Wrap::MirroredRepeat => Some(i.clamp(0, n - 1) as usize),
        Wrap::Clamp | Wrap::ClampToBorder => (0..n).contains(&i).then_some(i as usize),
    }
}

/// The NEAREST texel (eq. 3.23–3.25) of the scaled coordinate `u` on an
/// axis `n` texels long.
#[inline(always)]
fn nearest_texel(u: f32, wrap: Wrap, n: u32) -> Texel {
    let i = floor(u) as i64;
    let i = match wrap {
        // s = 1 selects the last texel (eq. 3.23).
        Wrap::Clamp => i.min(n as i64 - 1),
        _ => i,
    };
    index(i, wrap, n)
}

/// [`filter`] of a level stored as RGBA8 in fixed point
/// ([`unorm8_filter`]), as values ×128: for 2D lookups (2D textures and
/// cube faces) of colour textures whose texels are all inside the level;
/// `None` for the others (1D, 3D, depth, f32 storage, a border texel),
/// which [`filter`] takes.
fn filter_unorm8(
    tex: &Texture,
    img: &Image,
    st: [f32; 3],
    layer: Option<usize>,
    linear: bool,
) -> Option<[i32; 4]> {
    let Texels::Unorm8(texels) = &img.texels else {
        return None;
    };
    if tex.depth_format || (layer.is_none() && tex.target != TextureTarget::Tex2D) {
        return None;
    }
    let (w, h) = (img.width.max(1), img.height.max(1));
    // Per axis: texel 0, texel 1, weight of texel 1 (in 128ths).
    let mut axes = [(0usize, 0usize, 0i32); 2];
    for (a, n) in [(0, w), (1, h)] {
        let wrap = tex.wrap[a];
        let u = wrap_coord(st[a], wrap, n) * n as f32;
        axes[a] = if linear {
            let (i0, weight) = unorm8_filter::split(unorm8_filter::coord(floor(u * 128.0)));
            let i0 = i64::from(i0);
            (index(i0, wrap, n)?, index(i0 + 1, wrap, n)?, weight)
        } else {
            (nearest_texel(u, wrap, n)?, 0, 0)
        };
    }
    let base = layer.unwrap_or(0) * h as usize;
    let at = |i: usize, j: usize| -> Option<[u8; 4]> {
        texels.get((base + j) * w as usize + i).copied()
    };
    let ((i0, i1, a), (j0, j1, b)) = (axes[0], axes[1]);
    if !linear {
        return Some(unorm8_filter::nearest(at(i0, j0)?));
    }
    let t = [at(i0, j0)?, at(i1, j0)?, at(i0, j1)?, at(i1, j1)?];
    Some(unorm8_filter::bilinear(t, a, b))
}

/// NEAREST (eq. 3.23–3.25) or LINEAR (eq. 3.26) on one level. For depth
/// textures the result's component 0 is the depth, or the comparison
/// result against `reference` (GL 2.1 §3.8.14), filtered.
fn filter(
    tex: &Texture,
    img: &Image,
    st: [f32; 3],
    layer: Option<usize>,
    linear: bool,
    reference: Option<f32>,
) -> [f32; 4] {
    let dims = if layer.is_some() { 2 } else { tex.dims() };
    let sizes = [img.width, img.height, img.depth].map(|s| s.max(1));
    // Per axis: (texel 0, texel 1, weight of texel 1).
    let mut axes: [(Texel, Texel, f32); 3] = [(Some(0), Some(0), 0.0); 3];
    for a in 0..dims {
        let n = sizes[a];
        let wrap = tex.wrap[a];
        let u = wrap_coord(st[a], wrap, n) * n as f32;
        axes[a] = if linear {
            let v = u - 0.5;
            let i0 = floor(v);
            let alpha = v - i0;
            let i0 = i0 as i64;
            (
                index(i0, wrap, n),
                index(i0.saturating_add(1), wrap, n),
                alpha,
            )
        } else {
            (nearest_texel(u, wrap, n), None, 0.0)
        };
    }
    if let Some(face) = layer {
        axes[2] = (Some(face), None, 0.0);
    }
    let fetch = |i: Texel, j: Texel, k: Texel| -> [f32; 4] {
        let t = match (i, j, k) {
            (Some(i), Some(j), Some(k)) => img.texel(i, j, k),
            _ => tex.border_color,
        };
        match (tex.depth_format, tex.compare, reference) {
            (true, Some(func), Some(r)) => {
                let d = t[0];
                let pass = if func.test(r, d) { 1.0 } else { 0.0 };
                [pass, pass, pass, pass]
            }
            _ => t,
        }
    };
    if !linear {
        return fetch(axes[0].0, axes[1].0, axes[2].0);
    }
    let mut acc = [0.0f32; 4];
    let corners = 1usize << dims;
    for corner in 0..corners {
        let mut w = 1.0f32;
        let mut idx = [None; 3];
        for a in 0..3 {
            let (t0, t1, alpha) = axes[a];
            if a < dims {
                let hi = corner & (1 << a) != 0;
                idx[a] = if hi { t1 } else { t0 };
                w *= if hi { alpha } else { 1.0 - alpha };
            } else {
                idx[a] = t0;
            }
        }
        let t = fetch(idx[0], idx[1], idx[2]);
        for c in 0..4 {
            acc[c] += w * t[c];
        }
    }
    acc
}

#[cfg(test)]
mod tests;
