//! What both sampling paths (`texture_general`, `texture_2d`) compute
//! the same way, defined once here: the level of detail λ (GL 2.1
//! §3.8.8; [`lambda`], its log2 [`lod_log2`], one λ_base per 2×2 quad
//! from [`quad_first`]), the level(s) λ selects ([`select_levels`],
//! blended by [`mix_levels`]), wrapped coordinates ([`wrap_coord`],
//! §3.8.7) and the exact fast [`floor`] they use. The fast path
//! restates some of these over 16 lanes at once; its tests compare it
//! with the general path, which calls these.

use super::{Image, MagFilter, MinFilter, Texture, Wrap};
use glsl::math;

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
                // A rectangle's coordinates are in texels already.
                let size = if tex.target == super::TextureTarget::Rect {
                    1.0
                } else {
                    tex.size(base_img, a) as f32
                };
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
