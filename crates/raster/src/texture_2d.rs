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
    mix_levels, select_levels, wrap_coord, Levels, MagFilter, MinFilter, Texels, Texture,
    TextureTarget, TextureUnits, Wrap, MAX_LOD_BIAS, MISSING,
};
use glsl::types::SamplerKind;

/// Levels a request can address on this path (absolute level numbers):
/// more is a 2^31-texel texture, which takes the general path.
const MAX_LEVELS: usize = 32;

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
    let base = tex.base_level as usize;
    let Some(base_img) = tex.levels.get(base) else {
        return false;
    };
    if q >= MAX_LEVELS {
        return false;
    }
    // The levels' sizes, `filter`'s `img.width.max(1)` and so on (sizes
    // up to 2^24, so that they and texel indices are exact in f32 and i32).
    let mut sizes = [(1i32, 1i32); MAX_LEVELS];
    for (d, size) in sizes.iter_mut().enumerate().take(q + 1).skip(base) {
        let Some(img) = tex.levels.get(d) else {
            return false;
        };
        let (w, h) = (img.width.max(1), img.height.max(1));
        if w > 1 << 24 || h > 1 << 24 {
            return false;
        }
        *size = (w as i32, h as i32);
    }

    // λ of every lane, as `texture::lambda` computes it.
    let lam = lambdas(tex, base_img, unit.lod_bias, &req.lod);

    // The level(s) of every lane, as `texture::select_levels` picks them.
    let mask = req.mask;
    let mut level = [[base as i32; LANES]; 2];
    let mut f = [0.0f32; LANES];
    let mut two: u32 = 0;
    let mut nearest: u32 = 0;
    if matches!(
        tex.min_filter,
        MinFilter::LinearMipmapLinear | MinFilter::NearestMipmapLinear
    ) {
        // Eq. 3.28/3.29 over the lanes, branch-free.
        let c = if tex.mag_filter == MagFilter::Linear
            && tex.min_filter == MinFilter::NearestMipmapLinear
        {
            0.5
        } else {
            0.0
        };
        let mag_nearest = tex.mag_filter == MagFilter::Nearest;
        let min_nearest = tex.min_filter == MinFilter::NearestMipmapLinear;
        let (base_i, q_i) = (base as i32, q as i32);
        let (base_f, q_f) = (base as f32, q as f32);
        let mut is_two = [false; LANES];
        let mut is_nearest = [false; LANES];
        for l in 0..LANES {
            let lambda = lam[l];
            let mag = lambda.is_nan() || lambda <= c;
            let lb = base_f + lambda;
            let top = lb >= q_f;
            let d1 = floor_index(floor_lane(lb)).max(base_i).min(q_i);
            level[0][l] = if mag {
                base_i
            } else if top {
                q_i
            } else {
                d1
            };
            level[1][l] = (d1 + 1).min(q_i);
            f[l] = lambda - floor_lane(lambda);
            is_two[l] = !mag && !top;
            is_nearest[l] = if mag { mag_nearest } else { min_nearest };
        }
        for l in 0..LANES {
            two |= (is_two[l] as u32) << l;
            nearest |= (is_nearest[l] as u32) << l;
        }
        two &= mask;
    } else {
        for lane in 0..LANES {
            if mask & (1 << lane) == 0 {
                continue;
            }
            let linear = match select_levels(tex, q, lam[lane]) {
                Levels::One(d, linear) => {
                    level[0][lane] = d as i32;
                    linear
                }
                Levels::Two(d1, d2, fl, linear) => {
                    level[0][lane] = d1 as i32;
                    level[1][lane] = d2 as i32;
                    f[lane] = fl;
                    two |= 1 << lane;
                    linear
                }
            };
            if !linear {
                nearest |= 1 << lane;
            }
        }
    }

    let st = [req.coord[0], req.coord[1]];
    let mut first = [[0.0f32; 4]; LANES];
    filter_lanes(tex, &sizes, &level[0], &st, nearest, mask, &mut first);
    if two != 0 {
        let mut second = [[0.0f32; 4]; LANES];
        filter_lanes(tex, &sizes, &level[1], &st, nearest, two, &mut second);
        for lane in 0..LANES {
            if two & (1 << lane) != 0 {
                first[lane] = mix_levels(first[lane], second[lane], f[lane]);
            }
        }
    }
    for (lane, rgba) in first.iter().enumerate() {
        if mask & (1 << lane) != 0 {
            for (o, &v) in out.iter_mut().zip(rgba) {
                o[lane] = v;
            }
        }
    }
    true
}

/// `texture::lambda` for every lane (the lanes outside the request's
/// mask get some value), over all lanes at once.
#[inline(always)]
fn lambdas(
    tex: &Texture,
    base_img: &crate::texture::Image,
    unit_bias: f32,
    lod: &Lod,
) -> [f32; LANES] {
    let mut base = [0.0f32; LANES];
    let mut extra = [0.0f32; LANES];
    match lod {
        Lod::Explicit(v) => {
            base = *v;
            // The general path adds a shader bias of 0.
            extra = [unit_bias + 0.0; LANES];
        }
        Lod::Derivatives { ddx, ddy, bias } => {
            let (w, h) = (base_img.width as f32, base_img.height as f32);
            let mut rho = [0.0f32; LANES];
            for l in 0..LANES {
                let (ux, uy) = (ddx[0][l] * w, ddy[0][l] * w);
                let mut sx = 0.0f32 + ux * ux;
                let mut sy = 0.0f32 + uy * uy;
                let (ux, uy) = (ddx[1][l] * h, ddy[1][l] * h);
                sx += ux * ux;
                sy += uy * uy;
                // `math::sqrt` is correctly rounded, as the instruction is;
                // a NaN here makes λ NaN whatever its bits.
                let (rx, ry) = (sx.sqrt(), sy.sqrt());
                // `math::max`.
                rho[l] = if rx.is_nan() || rx < ry { ry } else { rx };
            }
            // Every lane (`log2` is branch-free and total), so that the
            // loop vectorizes.
            for l in 0..LANES {
                base[l] = glsl::math::log2(rho[l]);
                extra[l] = unit_bias + bias[l];
            }
        }
    }
    let (tex_bias, min_lod, max_lod) = (tex.lod_bias, tex.min_lod, tex.max_lod);
    let mut lam = [0.0f32; LANES];
    for l in 0..LANES {
        let b = tex_bias + extra[l];
        // (Constant bounds: the clamp's assertion folds away.)
        let b = b.clamp(-MAX_LOD_BIAS, MAX_LOD_BIAS);
        let mut x = base[l] + b;
        if x > max_lod {
            x = max_lod;
        }
        if x < min_lod {
            x = min_lod;
        }
        lam[l] = x;
    }
    lam
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
            // `UNORM8`'s values, computed four at a time.
            Some(t) => t.map(|b| b as f32 / 255.0),
            None => MISSING,
        }
    }
}

/// `texture::floor` without a branch (so loops over lanes vectorize):
/// |x| ≥ 2^23, infinities and NaN are their own floor.
#[inline(always)]
fn floor_lane(x: f32) -> f32 {
    let small = x.abs() < 8_388_608.0;
    let t = to_i32(if small { x } else { 0.0 }) as f32;
    let fl = if t > x { t - 1.0 } else { t };
    if small && fl != x {
        fl
    } else {
        x
    }
}

/// `x as i32` for |x| < 2^31, without the saturating conversion's NaN and
/// range fix-ups (which keep loops from vectorizing).
#[inline(always)]
fn to_i32(x: f32) -> i32 {
    debug_assert!(x.abs() < 2_147_483_648.0);
    // SAFETY: every caller passes a value with |x| < 2^31 (an integral
    // f32 below 2^23 in magnitude, or a floor clamped to ±2^30), which
    // truncates to an i32 exactly.
    unsafe { x.to_int_unchecked::<i32>() }
}

/// `floor_lane(x) as i64` as an i32 for a floor in [−2^30, 2^30] (every
/// wrapped coordinate's); NaN gives 0 like `as`.
#[inline(always)]
fn floor_index(fl: f32) -> i32 {
    let bounded = if fl.is_nan() {
        0.0
    } else {
        fl.clamp(-1_073_741_824.0, 1_073_741_824.0)
    };
    to_i32(bounded)
}

/// `wrap_coord(s, wrap, n) * n` for every lane.
#[inline(always)]
fn wrap_scale(wrap: Wrap, s: &[f32; LANES], n: &[i32; LANES]) -> [f32; LANES] {
    let mut u = [0.0f32; LANES];
    match wrap {
        Wrap::Repeat => {
            for l in 0..LANES {
                u[l] = (s[l] - floor_lane(s[l])) * n[l] as f32;
            }
        }
        Wrap::ClampToEdge => {
            for l in 0..LANES {
                let nf = n[l] as f32;
                let half = 0.5 / nf;
                // f32::clamp without its (here impossible) panic.
                let mut x = s[l];
                if x < half {
                    x = half;
                }
                if x > 1.0 - half {
                    x = 1.0 - half;
                }
                u[l] = x * nf;
            }
        }
        _ => {
            for l in 0..LANES {
                u[l] = wrap_coord(s[l], wrap, n[l] as u32) * n[l] as f32;
            }
        }
    }
    u
}

/// `index(i, wrap, n)` for the borderless modes and i in [−1, n], the
/// only values a wrapped coordinate gives (`fract` is in [0, 1]), clamped
/// into the level for safety.
#[inline(always)]
fn wrap_index(i: i32, wrap: Wrap, n: i32) -> i32 {
    let i = match wrap {
        Wrap::Repeat => {
            if i < 0 {
                i + n
            } else if i >= n {
                i - n
            } else {
                i
            }
        }
        _ => i,
    };
    // (Not `clamp`: its assertion keeps the lane loops from vectorizing.)
    i.max(0).min(n - 1)
}

/// NEAREST or LINEAR on level `level[lane]` for the lanes in `mask`
/// (NEAREST for those in `nearest`), as `texture::filter` for a 2D
/// texture without border texels. Other lanes' values are unspecified.
fn filter_lanes(
    tex: &Texture,
    sizes: &[(i32, i32); MAX_LEVELS],
    level: &[i32; LANES],
    st: &[[f32; LANES]; 2],
    nearest: u32,
    mask: u32,
    out: &mut [[f32; 4]; LANES],
) {
    let (ws, wt) = (tex.wrap[0], tex.wrap[1]);
    let mut w = [1i32; LANES];
    let mut h = [1i32; LANES];
    for l in 0..LANES {
        let (lw, lh) = sizes.get(level[l] as usize).copied().unwrap_or((1, 1));
        w[l] = lw;
        h[l] = lh;
    }
    let us = wrap_scale(ws, &st[0], &w);
    let ut = wrap_scale(wt, &st[1], &h);
    let (i0, i1, a) = axis(&us, &w, ws, nearest);
    let (j0, j1, b) = axis(&ut, &h, wt, nearest);
    for l in 0..LANES {
        if mask & (1 << l) == 0 {
            continue;
        }
        let Some(img) = tex.levels.get(level[l] as usize) else {
            out[l] = MISSING;
            continue;
        };
        let row = w[l] as usize;
        let at = |i: i32, j: i32| j as usize * row + i as usize;
        let corners = [
            at(i0[l], j0[l]),
            at(i1[l], j0[l]),
            at(i0[l], j1[l]),
            at(i1[l], j1[l]),
        ];
        out[l] = if nearest & (1 << l) != 0 {
            img.texels.get(corners[0])
        } else {
            match &img.texels {
                Texels::Unorm8(v) => bilinear(v.as_slice(), corners, a[l], b[l]),
                Texels::F32(v) => bilinear(v.as_slice(), corners, a[l], b[l]),
            }
        };
    }
}

/// Per axis and lane: texel 0, texel 1 and the weight of texel 1 for
/// LINEAR, or the texel (in texel 0) for the lanes in `nearest`. Computes
/// both for every lane and selects (so the loop vectorizes).
#[inline(always)]
fn axis(
    u: &[f32; LANES],
    n: &[i32; LANES],
    wrap: Wrap,
    nearest: u32,
) -> ([i32; LANES], [i32; LANES], [f32; LANES]) {
    let mut i0 = [0i32; LANES];
    let mut i1 = [0i32; LANES];
    let mut alpha = [0.0f32; LANES];
    for l in 0..LANES {
        let n = n[l];
        let v = u[l] - 0.5;
        let fl = floor_lane(v);
        let i = floor_index(fl);
        let near = wrap_index(floor_index(floor_lane(u[l])), wrap, n);
        let is_near = nearest & (1 << l) != 0;
        alpha[l] = v - fl;
        i0[l] = if is_near {
            near
        } else {
            wrap_index(i, wrap, n)
        };
        i1[l] = wrap_index(i.saturating_add(1), wrap, n);
    }
    (i0, i1, alpha)
}

/// The general path's sum over the four texels (S varies fastest), each
/// weight the product of the two axes' weights.
#[inline(always)]
fn bilinear<S: Fetch + ?Sized>(texels: &S, corners: [usize; 4], a: f32, b: f32) -> [f32; 4] {
    let (a0, b0) = (1.0 - a, 1.0 - b);
    let weights = [a0 * b0, a * b0, a0 * b, a * b];
    let mut acc = [0.0f32; 4];
    for (idx, weight) in corners.into_iter().zip(weights) {
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
    use crate::texture::{Image, TextureUnit};
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
                    tex.max_lod = if k % 3 == 2 { 1.5 } else { 1000.0 };
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
                        ddx[0][7] = f32::NAN;
                        ddy[1][8] = f32::INFINITY;
                        ddx[1][10] = 1e30;
                        let lod = if round % 3 == 0 {
                            Lod::Explicit(std::array::from_fn(|l| {
                                if l == 11 {
                                    f32::NAN
                                } else {
                                    l as f32 * 0.4 - 2.0
                                }
                            }))
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
    fn lane_floor_is_exact() {
        let mut values = vec![
            0.0f32,
            -0.0,
            0.5,
            -0.5,
            -1.0,
            8_388_607.5,
            -8_388_607.5,
            8_388_608.0,
            -8_388_609.0,
            1e30,
            -1e30,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            -1e-45,
        ];
        let mut bits = 0x9e37_79b9u32;
        for _ in 0..100_000 {
            bits = bits.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            values.push(f32::from_bits(bits));
            values.push((bits >> 8) as f32 / 4096.0 - 2048.0);
        }
        for x in values {
            let (a, b) = (floor_lane(x), glsl::math::floor(x));
            assert!(
                a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
                "floor({x:e})"
            );
        }
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

#[cfg(test)]
mod bench {
    use super::*;
    use crate::texture::{Image, MinFilter, TextureUnit};
    use std::sync::Arc;

    /// `cargo test --release -p shaderbox-raster bench_sample_2d -- --ignored --nocapture`:
    /// trilinear lookups on a 512² RGBA8 mipmapped texture, quads of
    /// lanes with derivatives like the benchmark's textured scene.
    #[test]
    #[ignore]
    fn bench_sample_2d() {
        let mut levels = Vec::new();
        let mut n = 512u32;
        loop {
            let texels = (0..n * n)
                .map(|i| {
                    [
                        (i % 251) as f32 / 255.0,
                        (i % 7) as f32 / 255.0,
                        0.5 * 0.0,
                        1.0,
                    ]
                })
                .collect();
            levels.push(Image::new(n, n, 1, texels));
            if n == 1 {
                break;
            }
            n /= 2;
        }
        let mut tex = Texture::new(TextureTarget::Tex2D, levels);
        tex.min_filter = MinFilter::LinearMipmapLinear;
        let units = TextureUnits {
            units: vec![TextureUnit {
                tex_2d: Some(Arc::new(tex)),
                ..TextureUnit::default()
            }],
        };
        let mut reqs = Vec::new();
        for k in 0..4096u32 {
            let x0 = (k % 64) as f32 * 4.0;
            let y0 = (k / 64) as f32 * 1.0;
            let d = 0.004 + 0.002 * (k % 13) as f32;
            let mut coord = [[0.0; LANES]; 4];
            let mut ddx = [[0.0; LANES]; 3];
            let mut ddy = [[0.0; LANES]; 3];
            for l in 0..LANES {
                let (x, y) = (x0 + (l % 2 + 2 * (l / 4)) as f32, y0 + ((l / 2) % 2) as f32);
                coord[0][l] = x * d;
                coord[1][l] = y * d * 1.7 + 0.1 * x * d;
                ddx[0][l] = d;
                ddx[1][l] = 0.1 * d;
                ddy[1][l] = 1.7 * d;
            }
            reqs.push(SampleRequest {
                unit: [0; LANES],
                target: SamplerKind::Sampler2D,
                coord,
                compare: None,
                lod: Lod::Derivatives {
                    ddx,
                    ddy,
                    bias: [0.0; LANES],
                },
                mask: 0xffff,
            });
        }
        let mut out = [[0.0; LANES]; 4];
        let mut sink = 0.0f32;
        // Alternating rounds, best of each (the machine is shared).
        let mut best = [f64::MAX; 2];
        for round in 0..30 {
            let fast = round % 2 == 0;
            let t = std::time::Instant::now();
            for r in &reqs {
                if fast {
                    sample(&units, r, &mut out);
                } else {
                    units.sample_general(r, &mut out);
                }
                sink += out[0][3];
            }
            let b = &mut best[round % 2];
            *b = b.min(t.elapsed().as_secs_f64());
        }
        for (name, b) in ["fast", "general"].iter().zip(best) {
            let per = b / (reqs.len() * LANES) as f64 * 1e9;
            println!("{name}: {per:.1} ns per lane");
        }
        assert!(sink.is_finite());
    }
}
