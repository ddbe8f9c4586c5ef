//! The fast path of texture lookups: 2D, no depth comparison, a complete
//! colour texture whose S and T wrap modes never select the border
//! (REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT), one texture unit for every
//! lane of the request. That covers fixed-function texturing and nearly
//! every `texture2D` call.
//!
//! It computes exactly what the general path (`texture::sample`) computes,
//! operation for operation and in the same order (λ, level selection,
//! wrapping, weights, the sum over the four texels, the blend of two
//! levels), so the results are the same bits; what it saves is the general
//! path's per-lane dispatch: completeness and state are looked at once per
//! request, texel indices are plain integers (no border case), the
//! storage (RGBA8 or f32) is matched once per level, and the bilinear sum
//! is straight-line code. A test compares the two paths on random lookups.

use crate::ex::{Lod, SampleRequest, LANES};
use crate::texture::{
    floor, index, lambda, mix_levels, select_levels, wrap_coord, Image, Levels, LodBase, Texels,
    Texture, TextureTarget, TextureUnits, Wrap, MISSING, UNORM8,
};
use glsl::types::SamplerKind;

/// Samples `req` through the fast path when it applies (see the module
/// documentation) and returns true; false leaves `out` untouched.
pub(crate) fn sample(
    units: &TextureUnits,
    req: &SampleRequest,
    out: &mut [[f32; LANES]; 4],
) -> bool {
    if req.target != SamplerKind::Sampler2D || req.compare.is_some() || req.mask == 0 {
        return false;
    }
    let first = req.mask.trailing_zeros() as usize;
    let Some(&unit_index) = req.unit.get(first) else {
        return false;
    };
    for lane in 0..LANES {
        if req.mask & (1 << lane) != 0 && req.unit[lane] != unit_index {
            return false;
        }
    }
    let Some(unit) = units.units.get(unit_index as usize) else {
        return false;
    };
    let Some(tex) = unit.tex_2d.as_deref() else {
        return false;
    };
    let borderless = |w: Wrap| matches!(w, Wrap::Repeat | Wrap::ClampToEdge | Wrap::MirroredRepeat);
    if tex.target != TextureTarget::Tex2D
        || tex.depth_format
        || !borderless(tex.wrap[0])
        || !borderless(tex.wrap[1])
    {
        return false;
    }
    // Incomplete textures take the general path (which samples black).
    let Some(q) = tex.last_level() else {
        return false;
    };
    let Some(base_img) = tex.levels.get(tex.base_level as usize) else {
        return false;
    };
    let unit_bias = unit.lod_bias;
    for lane in 0..LANES {
        if req.mask & (1 << lane) == 0 {
            continue;
        }
        // As `TextureUnits::sample_lane` and `texture::sample` build them.
        let (lod, shader_bias) = match &req.lod {
            Lod::Explicit(l) => (LodBase::Value(l[lane]), 0.0),
            Lod::Derivatives { ddx, ddy, bias } => (
                LodBase::Derivatives(
                    [ddx[0][lane], ddx[1][lane], ddx[2][lane]],
                    [ddy[0][lane], ddy[1][lane], ddy[2][lane]],
                ),
                bias[lane],
            ),
        };
        let l = lambda(tex, base_img, lod, unit_bias + shader_bias);
        let st = (req.coord[0][lane], req.coord[1][lane]);
        let one = |level: usize, linear: bool| match tex.levels.get(level) {
            Some(img) => filter(tex, img, st, linear),
            None => MISSING,
        };
        let rgba = match select_levels(tex, q, l) {
            Levels::One(level, linear) => one(level, linear),
            Levels::Two(d1, d2, f, linear) => mix_levels(one(d1, linear), one(d2, linear), f),
        };
        for (o, v) in out.iter_mut().zip(rgba) {
            o[lane] = v;
        }
    }
    true
}

/// Reads texel `index` of a level's storage.
trait Fetch {
    fn fetch(&self, index: usize) -> [f32; 4];
}

impl Fetch for [[f32; 4]] {
    #[inline(always)]
    fn fetch(&self, index: usize) -> [f32; 4] {
        self.get(index).copied().unwrap_or(MISSING)
    }
}

impl Fetch for [[u8; 4]] {
    #[inline(always)]
    fn fetch(&self, index: usize) -> [f32; 4] {
        match self.get(index) {
            Some(t) => t.map(|b| UNORM8[b as usize]),
            None => MISSING,
        }
    }
}

/// One level, NEAREST or LINEAR, as `texture::filter` for a 2D texture
/// without border texels.
#[inline]
fn filter(tex: &Texture, img: &Image, st: (f32, f32), linear: bool) -> [f32; 4] {
    match &img.texels {
        Texels::Unorm8(v) => filter_in(tex, img, v.as_slice(), st, linear),
        Texels::F32(v) => filter_in(tex, img, v.as_slice(), st, linear),
    }
}

#[inline(always)]
fn filter_in<S: Fetch + ?Sized>(
    tex: &Texture,
    img: &Image,
    texels: &S,
    st: (f32, f32),
    linear: bool,
) -> [f32; 4] {
    let (w, h) = (img.width.max(1), img.height.max(1));
    let (ws, wt) = (tex.wrap[0], tex.wrap[1]);
    let row = w as usize;
    // The wrap modes here always give an index (never the border).
    let at = |i: i64, wrap: Wrap, n: u32| index(i, wrap, n).unwrap_or(0);
    let us = wrap_coord(st.0, ws, w) * w as f32;
    let ut = wrap_coord(st.1, wt, h) * h as f32;
    if !linear {
        let i = at(floor(us) as i64, ws, w);
        let j = at(floor(ut) as i64, wt, h);
        return texels.fetch(j * row + i);
    }
    let axis = |u: f32, wrap: Wrap, n: u32| {
        let v = u - 0.5;
        let i0 = floor(v);
        let alpha = v - i0;
        let i0 = i0 as i64;
        (at(i0, wrap, n), at(i0.saturating_add(1), wrap, n), alpha)
    };
    let (i0, i1, a) = axis(us, ws, w);
    let (j0, j1, b) = axis(ut, wt, h);
    // Corners in the general path's order (S varies fastest), each weight
    // the product of the two axes' weights.
    let (a0, b0) = (1.0 - a, 1.0 - b);
    let corners = [
        (j0 * row + i0, a0 * b0),
        (j0 * row + i1, a * b0),
        (j1 * row + i0, a0 * b),
        (j1 * row + i1, a * b),
    ];
    let mut acc = [0.0f32; 4];
    for (idx, weight) in corners {
        let t = texels.fetch(idx);
        for c in 0..4 {
            acc[c] += weight * t[c];
        }
    }
    acc
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::{MagFilter, MinFilter, TextureUnit};
    use std::sync::Arc;

    /// A 2D texture with random unorm8 (or, `float`, arbitrary) texels
    /// and a full mipmap chain.
    fn random_texture(w: u32, h: u32, float: bool, seed: &mut u32) -> Texture {
        let mut next = move || {
            *seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            *seed >> 8
        };
        let mut levels = Vec::new();
        let (mut lw, mut lh) = (w, h);
        loop {
            let texels = (0..lw * lh)
                .map(|_| {
                    [0; 4].map(|_| {
                        let r = next();
                        if float {
                            r as f32 / 65536.0 - 100.0
                        } else {
                            (r & 255) as f32 / 255.0
                        }
                    })
                })
                .collect();
            let img = Image::new(lw, lh, 1, texels);
            assert_eq!(img.is_unorm8(), !float);
            levels.push(img);
            if lw == 1 && lh == 1 {
                break;
            }
            (lw, lh) = ((lw / 2).max(1), (lh / 2).max(1));
        }
        Texture::new(TextureTarget::Tex2D, levels)
    }

    /// The general path, lane by lane.
    fn general(units: &TextureUnits, req: &SampleRequest) -> [[f32; LANES]; 4] {
        let mut out = [[0.0; LANES]; 4];
        units.sample_general(req, &mut out);
        out
    }

    #[test]
    fn fast_path_matches_the_general_path_bit_for_bit() {
        let mut seed = 0x5eed_u32;
        let mut rnd = {
            let mut s = 0x1234_u32;
            move || {
                s = s.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
                s
            }
        };
        let filters = [
            MinFilter::Nearest,
            MinFilter::Linear,
            MinFilter::NearestMipmapNearest,
            MinFilter::LinearMipmapNearest,
            MinFilter::NearestMipmapLinear,
            MinFilter::LinearMipmapLinear,
        ];
        let wraps = [Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat];
        let mut checked = 0;
        for (size, float) in [((16, 8), false), ((5, 12), true), ((1, 1), false)] {
            let base = random_texture(size.0, size.1, float, &mut seed);
            for (k, &min_filter) in filters.iter().enumerate() {
                for mag_filter in [MagFilter::Nearest, MagFilter::Linear] {
                    let mut tex = base.clone();
                    tex.min_filter = min_filter;
                    tex.mag_filter = mag_filter;
                    tex.wrap = [wraps[k % 3], wraps[(k + 1) % 3], Wrap::Repeat];
                    tex.lod_bias = if k % 2 == 0 { 0.25 } else { 0.0 };
                    tex.base_level = (k % 2).min(tex.levels.len() - 1) as u32;
                    tex.min_lod = -2.0 + k as f32 * 0.1;
                    let units = TextureUnits {
                        units: vec![
                            TextureUnit::default(),
                            TextureUnit {
                                tex_2d: Some(Arc::new(tex)),
                                lod_bias: -0.5,
                                ..TextureUnit::default()
                            },
                        ],
                    };
                    for round in 0..40 {
                        let mut coord = [[0.0; LANES]; 4];
                        let mut ddx = [[0.0; LANES]; 3];
                        let mut ddy = [[0.0; LANES]; 3];
                        let mut v = |scale: f32| (rnd() >> 8) as f32 / 16_777_216.0 * scale;
                        for lane in 0..LANES {
                            coord[0][lane] = v(6.0) - 3.0;
                            coord[1][lane] = v(6.0) - 3.0;
                            for c in 0..2 {
                                ddx[c][lane] = v(0.6) - 0.3;
                                ddy[c][lane] = v(0.6) - 0.3;
                            }
                        }
                        // A few awkward values.
                        coord[0][3] = f32::NAN;
                        coord[1][4] = f32::INFINITY;
                        coord[0][5] = -1e-9;
                        ddx[0][6] = 0.0;
                        ddy[1][6] = 0.0;
                        let lod = if round % 3 == 0 {
                            Lod::Explicit(std::array::from_fn(|l| l as f32 * 0.4 - 2.0))
                        } else {
                            Lod::Derivatives {
                                ddx,
                                ddy,
                                bias: [if round % 3 == 1 { 0.0 } else { 0.75 }; LANES],
                            }
                        };
                        let req = SampleRequest {
                            unit: [1; LANES],
                            target: SamplerKind::Sampler2D,
                            coord,
                            compare: None,
                            lod,
                            mask: 0xffff & !(1 << 9),
                        };
                        let mut fast = [[7.0; LANES]; 4];
                        assert!(sample(&units, &req, &mut fast));
                        let slow = general(&units, &req);
                        for c in 0..4 {
                            for lane in 0..LANES {
                                if lane == 9 {
                                    assert_eq!(fast[c][lane], 7.0, "masked lane untouched");
                                    continue;
                                }
                                assert_eq!(
                                    fast[c][lane].to_bits(),
                                    slow[c][lane].to_bits(),
                                    "{min_filter:?} {mag_filter:?} lane {lane} c {c}: {} vs {}",
                                    fast[c][lane],
                                    slow[c][lane]
                                );
                                checked += 1;
                            }
                        }
                    }
                }
            }
        }
        assert!(checked > 10_000);
    }

    #[test]
    fn other_requests_take_the_general_path() {
        let mut seed = 7;
        let tex = random_texture(4, 4, false, &mut seed);
        let req = |unit: [u32; LANES]| SampleRequest {
            unit,
            target: SamplerKind::Sampler2D,
            coord: [[0.5; LANES]; 4],
            compare: None,
            lod: Lod::Explicit([0.0; LANES]),
            mask: 0b1111,
        };
        let units = |tex: Texture| TextureUnits {
            units: vec![TextureUnit {
                tex_2d: Some(Arc::new(tex)),
                ..TextureUnit::default()
            }],
        };
        let mut out = [[0.0; LANES]; 4];
        assert!(sample(&units(tex.clone()), &req([0; LANES]), &mut out));
        // Two units in one request.
        let mut two = [0; LANES];
        two[2] = 1;
        assert!(!sample(&units(tex.clone()), &req(two), &mut out));
        // ... unless the other unit's lane is masked off.
        let masked = SampleRequest {
            mask: 0b1011,
            ..req(two)
        };
        assert!(sample(&units(tex.clone()), &masked, &mut out));
        // Border wrapping, depth textures, incomplete textures.
        let mut border = tex.clone();
        border.wrap[1] = Wrap::ClampToBorder;
        assert!(!sample(&units(border), &req([0; LANES]), &mut out));
        let mut depth = tex.clone();
        depth.depth_format = true;
        assert!(!sample(&units(depth), &req([0; LANES]), &mut out));
        let mut incomplete = tex;
        incomplete.levels.truncate(1);
        assert!(!sample(&units(incomplete), &req([0; LANES]), &mut out));
    }
}
