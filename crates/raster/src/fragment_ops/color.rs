//! The colour of a fragment that passed the tests, into one draw buffer:
//! clamping, blending (GL 2.1 §4.1.8; the common factor pairs as
//! straight-line code with the general equations' bits), logic op
//! (§4.1.10), the conversion to unorm8 and the colour mask (§4.2.2).

use crate::framebuffer::{float_to_unorm8, ColorBuffer};
use crate::state::{Blend, BlendEquation, BlendFactor, PipelineState};

/// Writes `src` to pixel `index` of `buf`, blending with `blend` (whose
/// SRC1 factors read `src1`, the second source colour) and masking with
/// `mask` (the draw buffer's, [`PipelineState::per_buffer`]).
pub(super) fn write_color(
    buf: &mut ColorBuffer,
    index: usize,
    state: &PipelineState,
    (src, src1): ([f32; 4], [f32; 4]),
    (blend, mask): (Option<&Blend>, [bool; 4]),
) {
    match buf {
        ColorBuffer::Rgba8(v) => {
            let Some(p) = v.get_mut(index) else { return };
            // Fixed-point buffers always see clamped colors (§4.1.8).
            let s = src.map(clamp01);
            let out: [u8; 4] = if let Some(op) = state.logic_op {
                let sb = s.map(float_to_unorm8);
                std::array::from_fn(|c| op.apply(sb[c], p[c]))
            } else if let Some(blend) = blend {
                // `unorm8_to_float`, four at a time.
                let d = p.map(|b| b as f32 / 255.0);
                if blend.uses_src1() {
                    to_unorm8(blend_dual(blend, s, src1.map(clamp01), d))
                } else {
                    to_unorm8(blend_unit(blend, s, d))
                }
            } else {
                to_unorm8(s)
            };
            if mask == [true; 4] {
                *p = out;
            } else {
                for c in 0..4 {
                    if mask[c] {
                        p[c] = out[c];
                    }
                }
            }
        }
        ColorBuffer::Rgba32F(v) => {
            let Some(p) = v.get_mut(index) else { return };
            let (s, s1) = if state.clamp_fragment_color {
                (src.map(clamp01), src1.map(clamp01))
            } else {
                (src, src1)
            };
            // Logic ops do not apply to float buffers (§4.1.10).
            let out = match blend {
                Some(blend) if state.logic_op.is_none() => blend_dual(blend, s, s1, *p),
                _ => s,
            };
            for c in 0..4 {
                if mask[c] {
                    p[c] = out[c];
                }
            }
        }
    }
}

pub(super) fn clamp01(x: f32) -> f32 {
    if x > 0.0 {
        x.min(1.0)
    } else {
        0.0
    }
}

/// `float_to_unorm8` of four channels, branch-free so that it vectorizes:
/// NaN and values ≤ 0 give 0, values ≥ 1 give 255.
#[inline(always)]
// Not `clamp`: NaN must become 0 (`max` drops it; `clamp` keeps it).
#[allow(clippy::manual_clamp)]
pub(super) fn to_unorm8(c: [f32; 4]) -> [u8; 4] {
    c.map(|x| {
        let y = x.max(0.0).min(1.0) * 255.0 + 0.5;
        // SAFETY: `max` turns NaN into 0, so `y` is finite and in
        // [0.5, 255.5]: representable in i32 (truncation, as `as i32`
        // would give, without its saturation checks).
        unsafe { y.to_int_unchecked::<i32>() as u8 }
    })
}

/// What [`QuickTarget::write`](super::QuickTarget::write) stores without blending, for every lane of
/// a batch's colour output (`rgba`: its four components): the clamped
/// colour in unorm8.
#[inline(always)]
pub(crate) fn unorm8_lanes<const N: usize>(rgba: [&[f32; N]; 4]) -> [[u8; 4]; N] {
    let [r, g, b, a] = rgba;
    let mut out = [[0u8; 4]; N];
    for (l, o) in out.iter_mut().enumerate() {
        *o = to_unorm8([clamp01(r[l]), clamp01(g[l]), clamp01(b[l]), clamp01(a[l])]);
    }
    out
}

/// [`blend_color`] for `s` and `d` in [0, 1] (a fixed-point buffer's
/// clamped source and stored destination): the common factor pairs with
/// FUNC_ADD (SRC_ALPHA / ONE_MINUS_SRC_ALPHA, ONE / ZERO, ONE / ONE, the
/// same for colour and alpha) as straight-line code giving the same bits,
/// the rest through [`blend_color`]. (With values in [0, 1], `x · 1 = x`,
/// `x · 0 = +0` and `x + 0 = x` exactly.)
#[inline]
pub(super) fn blend_unit(b: &Blend, s: [f32; 4], d: [f32; 4]) -> [f32; 4] {
    use BlendFactor::{One, OneMinusSrcAlpha, SrcAlpha, Zero};
    if b.equation_rgb == BlendEquation::Add
        && b.equation_alpha == BlendEquation::Add
        && b.src_rgb == b.src_alpha
        && b.dst_rgb == b.dst_alpha
    {
        match (b.src_rgb, b.dst_rgb) {
            (SrcAlpha, OneMinusSrcAlpha) => {
                let (fs, fd) = (s[3], 1.0 - s[3]);
                return [
                    s[0] * fs + d[0] * fd,
                    s[1] * fs + d[1] * fd,
                    s[2] * fs + d[2] * fd,
                    s[3] * fs + d[3] * fd,
                ];
            }
            (One, Zero) => return s,
            (One, One) => return [s[0] + d[0], s[1] + d[1], s[2] + d[2], s[3] + d[3]],
            _ => {}
        }
    }
    blend_color(b, s, d)
}

/// GL 2.1 §4.1.8 blend of source `s` over destination `d`
/// (table 4.1 equations, table 4.2 factors), with no second source colour
/// (the SRC1 factors read zeros).
pub(crate) fn blend_color(b: &Blend, s: [f32; 4], d: [f32; 4]) -> [f32; 4] {
    blend_dual(b, s, [0.0; 4], d)
}

/// GL 3.3 §4.1.8 blend of source `s` over destination `d`, the SRC1
/// factors reading the second source colour `s1` (dual-source blending).
pub(crate) fn blend_dual(b: &Blend, s: [f32; 4], s1: [f32; 4], d: [f32; 4]) -> [f32; 4] {
    let factor = |f: BlendFactor, c: usize| -> f32 {
        let k = b.color;
        match f {
            BlendFactor::Zero => 0.0,
            BlendFactor::One => 1.0,
            BlendFactor::SrcColor => s[c],
            BlendFactor::OneMinusSrcColor => 1.0 - s[c],
            BlendFactor::DstColor => d[c],
            BlendFactor::OneMinusDstColor => 1.0 - d[c],
            BlendFactor::SrcAlpha => s[3],
            BlendFactor::OneMinusSrcAlpha => 1.0 - s[3],
            BlendFactor::DstAlpha => d[3],
            BlendFactor::OneMinusDstAlpha => 1.0 - d[3],
            BlendFactor::ConstantColor => k[c],
            BlendFactor::OneMinusConstantColor => 1.0 - k[c],
            BlendFactor::ConstantAlpha => k[3],
            BlendFactor::OneMinusConstantAlpha => 1.0 - k[3],
            BlendFactor::Src1Color => s1[c],
            BlendFactor::OneMinusSrc1Color => 1.0 - s1[c],
            BlendFactor::Src1Alpha => s1[3],
            BlendFactor::OneMinusSrc1Alpha => 1.0 - s1[3],
            BlendFactor::SrcAlphaSaturate => {
                if c == 3 {
                    1.0
                } else {
                    glsl::math::min(s[3], 1.0 - d[3])
                }
            }
        }
    };
    std::array::from_fn(|c| {
        let (eq, sf, df) = if c < 3 {
            (b.equation_rgb, b.src_rgb, b.dst_rgb)
        } else {
            (b.equation_alpha, b.src_alpha, b.dst_alpha)
        };
        match eq {
            BlendEquation::Add => s[c] * factor(sf, c) + d[c] * factor(df, c),
            BlendEquation::Subtract => s[c] * factor(sf, c) - d[c] * factor(df, c),
            BlendEquation::ReverseSubtract => d[c] * factor(df, c) - s[c] * factor(sf, c),
            BlendEquation::Min => glsl::math::min(s[c], d[c]),
            BlendEquation::Max => glsl::math::max(s[c], d[c]),
        }
    })
}
