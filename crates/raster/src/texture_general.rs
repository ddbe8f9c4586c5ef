//! The general path of texture lookups (GL 2.1 §3.8): every target,
//! filter, wrap mode and depth comparison, lane by lane. Each lane finds
//! its unit's texture and its completeness, selects the cube face,
//! computes λ and the level(s) ([`crate::texture::levels`]) and filters
//! each level: RGBA8 levels of 2D lookups in fixed point
//! ([`crate::unorm8_filter`]), everything else in f32 ([`filter`]).
//! `texture_2d` computes the same bits faster for the common 2D case;
//! `texture_units` picks between them.

use crate::ex::{FetchRequest, Lod, SampleRequest, TexelLevel, TexelSlice, LANES};
use crate::texture::levels::{
    floor, lambda, mix_levels, quad_first, select_levels, wrap_coord, Levels, LodBase,
};
use crate::texture::{
    srgb_to_linear, DepthTextureMode, Image, Texels, Texture, TextureTarget, TextureUnit, Wrap,
    MISSING, NO_SWIZZLE,
};
use crate::unorm8_filter;
use glsl::math;
use glsl::types::{SamplerDim, SamplerKind};

/// Every lookup of `req` through `units`, lane by lane (`texture_2d` is
/// the fast path of the common case, with the same results).
pub(crate) fn sample_general(
    units: &[TextureUnit],
    req: &SampleRequest,
    out: &mut [[f32; LANES]; 4],
) {
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
                let t = complete_texture(units, req, unit);
                cache = Some((unit, t));
                t
            }
        };
        let rgba = match tex {
            Some((tex, q)) => sample_lane(units, req, lane, tex, q),
            None => MISSING,
        };
        for (o, v) in out.iter_mut().zip(rgba) {
            o[lane] = v;
        }
    }
}

/// The texture of `req`'s target bound to `unit` and its last level,
/// or `None` (no such unit, nothing bound, incomplete).
fn complete_texture<'a>(
    units: &'a [TextureUnit],
    req: &SampleRequest,
    unit: u32,
) -> Option<(&'a Texture, usize)> {
    let tex = unit_texture(units.get(unit as usize)?, req.target)?;
    Some((tex, tex.last_level()?))
}

/// The texture a sampler of type `target` reads on `unit`, if bound.
fn unit_texture(unit: &TextureUnit, target: SamplerKind) -> Option<&Texture> {
    let tex = match (target.dim(), target.is_array()) {
        (SamplerDim::D1, false) => &unit.tex_1d,
        (SamplerDim::D2, false) => &unit.tex_2d,
        (SamplerDim::D3, _) => &unit.tex_3d,
        (SamplerDim::Cube, false) => &unit.cube,
        (SamplerDim::D1, true) => &unit.tex_1d_array,
        (SamplerDim::D2, true) => &unit.tex_2d_array,
        (SamplerDim::Cube, true) => &unit.cube_array,
        (SamplerDim::Rect, _) => &unit.rect,
        (SamplerDim::Buffer, _) => &unit.buffer,
        // Multisample textures: none are bound; the lookup finds no
        // texture (the incomplete-texture result).
        _ => return None,
    };
    tex.as_deref()
}

/// Every texel fetch of `req` through `units` (GL 3.0 §3.8.8: the texel
/// of level base + lod at the integer coordinates, unfiltered; outside
/// the level or on an incomplete texture (0, 0, 0, 1)). Depth textures
/// give their depth as RGBA by the depth texture mode, as lookups do.
pub(crate) fn fetch_general(
    units: &[TextureUnit],
    req: &FetchRequest,
    out: &mut [[f32; LANES]; 4],
) {
    if !fetch_shared(units, req, out) {
        fetch_lanes(units, req, out);
    }
}

/// [`fetch_general`] lane by lane.
fn fetch_lanes(units: &[TextureUnit], req: &FetchRequest, out: &mut [[f32; LANES]; 4]) {
    // The texture and its last complete level, found once per unit: the
    // lanes nearly always share one, and completeness walks the levels.
    let mut found: Option<(u32, Option<(&Texture, usize)>)> = None;
    for lane in 0..LANES {
        if req.mask & (1 << lane) == 0 {
            continue;
        }
        let unit = req.unit[lane];
        let complete = match found {
            Some((u, complete)) if u == unit => complete,
            _ => {
                let complete = units
                    .get(unit as usize)
                    .and_then(|u| unit_texture(u, req.target))
                    .and_then(|tex| Some((tex, tex.last_level()?)));
                found = Some((unit, complete));
                complete
            }
        };
        let rgba = complete
            .and_then(|(tex, q)| fetch_lane(tex, q, req, lane))
            .unwrap_or(MISSING);
        for (o, v) in out.iter_mut().zip(rgba) {
            o[lane] = v;
        }
    }
}

/// [`fetch_general`] when every lane of `req.mask` reads one level of
/// one texture whose texels are used as stored ([`plain_level`]), as
/// lanes nearly always do: the level found once, then per lane a bounds
/// check and a load. Returns false, having written nothing, otherwise
/// (also for a missing texture or level, which the lane path answers).
fn fetch_shared(units: &[TextureUnit], req: &FetchRequest, out: &mut [[f32; LANES]; 4]) -> bool {
    let on = |l: usize| req.mask & (1 << l) != 0;
    let Some(first) = (0..LANES).find(|&l| on(l)) else {
        return true;
    };
    let (unit, lod) = (req.unit[first], req.lod[first]);
    if (0..LANES).any(|l| on(l) && (req.unit[l] != unit || req.lod[l] != lod)) {
        return false;
    }
    let Some((img, level)) = plain_level(units, unit, req.target, lod) else {
        return false;
    };
    // As `fetch_lane`: the coordinates of the target (and its layer) must
    // be inside the level; the others read as 0 (kept by a zero mask,
    // checked against a size of 1).
    let keep: [i32; 3] = std::array::from_fn(|a| if (a as u32) < level.axes { -1 } else { 0 });
    for lane in 0..LANES {
        if !on(lane) {
            continue;
        }
        let c: [i32; 3] = std::array::from_fn(|a| req.coord[a][lane] & keep[a]);
        let inside = (0..3).all(|a| c[a] >= 0 && (c[a] as i64) < level.size[a] as i64);
        let t = if inside {
            img.texel(c[0] as usize, c[1] as usize, c[2] as usize)
        } else {
            MISSING
        };
        for (o, v) in out.iter_mut().zip(t) {
            o[lane] = v;
        }
    }
    true
}

/// Level `lod` of the texture of `target` on `unit` when a texel fetch
/// there is a plain load (`exec::Textures::texel_level`): the texture is
/// complete, its texels are used as stored (no sRGB decoding, depth
/// texture mode or swizzle), and the level exists and is not empty.
pub(crate) fn plain_level(
    units: &[TextureUnit],
    unit: u32,
    target: SamplerKind,
    lod: i32,
) -> Option<(&Image, TexelLevel<'_>)> {
    let tex = unit_texture(units.get(unit as usize)?, target)?;
    if tex.srgb || tex.depth_format || tex.swizzle != NO_SWIZZLE {
        return None;
    }
    let q = tex.last_level()?;
    let level = (tex.base_level as i64).checked_add(lod as i64)?;
    if lod < 0 || level > q as i64 {
        return None;
    }
    let img = tex.levels.get(level as usize)?;
    let axes = tex.dims() + usize::from(tex.layered());
    let sizes = [img.width, img.height, img.depth];
    let size: [u32; 3] = std::array::from_fn(|a| if a < axes { sizes[a] } else { 1 });
    let count = size
        .iter()
        .try_fold(1usize, |n, &s| n.checked_mul(s as usize))?;
    let texels = match &img.texels {
        Texels::F32(t) => TexelSlice::Rgba32(t.get(..count)?),
        Texels::Unorm8(t) => TexelSlice::Unorm8(t.get(..count)?),
        Texels::Red16(t) => TexelSlice::Red16 {
            red: t.red.get(..count)?,
            signed: t.signed,
            rest: t.rest,
        },
    };
    if count == 0 {
        return None;
    }
    let level = TexelLevel {
        size,
        axes: axes as u32,
        texels,
    };
    Some((img, level))
}

/// Lane `lane`'s texel of `tex`, whose last complete level is `q`.
fn fetch_lane(tex: &Texture, q: usize, req: &FetchRequest, lane: usize) -> Option<[f32; 4]> {
    let lod = req.lod[lane];
    let level = (tex.base_level as i64).checked_add(lod as i64)?;
    if lod < 0 || level > q as i64 {
        return None;
    }
    let img = tex.levels.get(level as usize)?;
    let [i, j, k] = [0, 1, 2].map(|c| req.coord[c][lane]);
    // Coordinates past the target's (and its layer) are 0.
    let n = tex.dims() + usize::from(tex.layered());
    let sizes = [img.width, img.height, img.depth];
    let inside = [i, j, k]
        .iter()
        .zip(sizes)
        .take(n)
        .all(|(&c, size)| c >= 0 && (c as i64) < size as i64);
    if !inside {
        return None;
    }
    let at = |c: i32, a: usize| if a < n { c as usize } else { 0 };
    let t = img.texel(at(i, 0), at(j, 1), at(k, 2));
    Some(tex.swizzled(depth_rgba(tex, decoded(tex, t))))
}

/// `textureSize` (GLSL 1.30 §8.7): the sizes of level base + `lod` of the
/// texture of `target` on `unit` (width, then height or the layers, then
/// depth or the layers), 0 past the target's; (0, 0, 0) when there is no
/// such texture or level.
pub(crate) fn size_general(
    units: &[TextureUnit],
    unit: u32,
    target: SamplerKind,
    lod: i32,
) -> [i32; 3] {
    let Some(tex) = units
        .get(unit as usize)
        .and_then(|u| unit_texture(u, target))
    else {
        return [0; 3];
    };
    let level = tex.base_level as i64 + lod as i64;
    let img = match usize::try_from(level) {
        Ok(l) if lod >= 0 => tex.levels.get(l),
        _ => None,
    };
    let Some(img) = img else {
        return [0; 3];
    };
    let n = match tex.target {
        TextureTarget::Tex1D | TextureTarget::Buffer => 1,
        TextureTarget::Tex3D | TextureTarget::Tex2DArray | TextureTarget::CubeArray => 3,
        _ => 2,
    };
    // A cube map array's third size is its cubes (GLSL 4.00 §8.9.1).
    let depth = if tex.target == TextureTarget::CubeArray {
        img.depth / 6
    } else {
        img.depth
    };
    let sizes = [img.width, img.height, depth];
    std::array::from_fn(|a| if a < n { sizes[a] as i32 } else { 0 })
}

fn sample_lane(
    units: &[TextureUnit],
    req: &SampleRequest,
    lane: usize,
    tex: &Texture,
    q: usize,
) -> [f32; 4] {
    let Some(unit) = units.get(req.unit[lane] as usize) else {
        return MISSING;
    };
    let coord = [0, 1, 2, 3].map(|c| req.coord[c][lane]);
    let offset = req.offset.map_or([0; 3], |o| [0, 1, 2].map(|c| o[c][lane]));
    let (lod_base, shader_bias) = match &req.lod {
        Lod::Explicit(l) => (LodBase::Value(l[lane]), 0.0),
        Lod::Gradients { ddx, ddy } => (
            LodBase::Derivatives(
                [0, 1, 2].map(|c| ddx[c][lane]),
                [0, 1, 2].map(|c| ddy[c][lane]),
            ),
            0.0,
        ),
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
    let v = sample(
        tex,
        q,
        coord,
        lod_base,
        unit.lod_bias + shader_bias,
        reference,
        offset,
    );
    if req.compare_only && tex.depth_format {
        // The value before the depth texture mode spread it.
        let r = match tex.depth_mode {
            DepthTextureMode::Alpha => v[3],
            _ => v[0],
        };
        return [r; 4];
    }
    tex.swizzled(v)
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

/// Samples `tex` (complete, last level `q`) at `coord` (s, t, r, q; q is
/// read by cube map arrays only, as the cube's layer).
pub(crate) fn sample(
    tex: &Texture,
    q: usize,
    coord: [f32; 4],
    lod: LodBase,
    extra_bias: f32,
    reference: Option<f32>,
    offset: [i32; 3],
) -> [f32; 4] {
    let base = tex.base_level as usize;
    let Some(base_img) = tex.levels.get(base) else {
        return MISSING;
    };
    let [s, t, r, layer_coord] = coord;
    let coord = [s, t, r];
    // Face selection turns a cube lookup into a 2D one on layer `face`
    // (of the cube's six, for cube map arrays).
    let cubes = matches!(tex.target, TextureTarget::Cube | TextureTarget::CubeArray);
    let (st, layer, derivs) = if cubes {
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
        // GL_ARB_texture_cube_map_array: the cube is clamp(RNE(q), 0,
        // cubes − 1), as an array layer is chosen.
        let first = if tex.target == TextureTarget::CubeArray {
            6 * nearest_layer(layer_coord, (base_img.depth / 6).max(1))
        } else {
            0
        };
        ([s, t, 0.0], Some(first + face), derivs)
    } else if tex.layered() {
        // GL 3.0 §3.8.8: layer = clamp(RNE(r), 0, layers − 1), of the
        // coordinate after the target's.
        let nd = tex.dims();
        let layers = tex.size(base_img, nd).max(1);
        let mut st = coord;
        st[nd] = 0.0;
        (st, Some(nearest_layer(coord[nd], layers)), lod)
    } else {
        (coord, None, lod)
    };

    let lambda = lambda(tex, base_img, derivs, extra_bias);
    let reference = reference.map(|r| r.clamp(0.0, 1.0));
    let one = |level: usize, linear: bool| -> [f32; 4] {
        match tex.levels.get(level) {
            Some(img) => filter(tex, img, st, layer, linear, reference, offset),
            None => MISSING,
        }
    };
    if tex.integer {
        // Integer texels are not filtered: the nearest texel of one level
        // (GL 3.0 §3.8.8 leaves other filters' results undefined).
        let level = match select_levels(tex, q, lambda) {
            Levels::One(level, _) | Levels::Two(level, ..) => level,
        };
        return one(level, false);
    }
    let offset_free = offset == [0; 3];
    // RGBA8 levels in fixed point when they qualify (`unorm8_filter`).
    let fixed = |level: usize, linear: bool| -> Option<[i32; 4]> {
        if !offset_free {
            return None;
        }
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
    depth_rgba(tex, value)
}

/// The array layer a coordinate selects among `layers` (GL 3.0 §3.8.8):
/// clamp(RNE(c), 0, layers − 1), NaN the first.
fn nearest_layer(c: f32, layers: u32) -> usize {
    let l = floor(c + 0.5);
    if l.is_nan() {
        0
    } else {
        l.clamp(0.0, (layers.max(1) - 1) as f32) as usize
    }
}

/// A stored texel as filtering reads it: sRGB textures' colour decoded
/// to linear (alpha is stored linear).
#[inline(always)]
fn decoded(tex: &Texture, t: [f32; 4]) -> [f32; 4] {
    if tex.srgb {
        [
            srgb_to_linear(t[0]),
            srgb_to_linear(t[1]),
            srgb_to_linear(t[2]),
            t[3],
        ]
    } else {
        t
    }
}

/// A depth texture's value (or comparison result) in component 0 as
/// RGBA by its DEPTH_TEXTURE_MODE; other textures' values unchanged.
fn depth_rgba(tex: &Texture, value: [f32; 4]) -> [f32; 4] {
    if tex.depth_format {
        let r = value[0];
        match tex.depth_mode {
            DepthTextureMode::Luminance => [r, r, r, 1.0],
            DepthTextureMode::Intensity => [r, r, r, r],
            DepthTextureMode::Alpha => [0.0, 0.0, 0.0, r],
            DepthTextureMode::Red => [r, 0.0, 0.0, 1.0],
        }
    } else {
        value
    }
}

/// The coordinate `s` on an axis of `n` texels, wrapped and scaled to
/// texels (`u` of GL 2.1 eq. 3.17 after §3.8.7); a rectangle's
/// coordinates are texels already, clamped by the wrap mode (GL 3.1
/// §3.8.7: [0, n], [½, n − ½] or [−½, n + ½]).
#[inline(always)]
fn scaled(tex: &Texture, s: f32, wrap: Wrap, n: u32) -> f32 {
    if tex.target != TextureTarget::Rect {
        return wrap_coord(s, wrap, n) * n as f32;
    }
    let n = n as f32;
    match wrap {
        Wrap::ClampToEdge => s.clamp(0.5, n - 0.5),
        Wrap::ClampToBorder => s.clamp(-0.5, n + 0.5),
        _ => s.clamp(0.0, n),
    }
}

/// A wrapped texel coordinate: `None` selects the border color.
type Texel = Option<usize>;

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
    let two_d = matches!(
        tex.target,
        TextureTarget::Tex2D
            | TextureTarget::Cube
            | TextureTarget::CubeArray
            | TextureTarget::Tex2DArray
            | TextureTarget::Rect
    );
    if tex.depth_format || tex.srgb || !two_d {
        return None;
    }
    let (w, h) = (img.width.max(1), img.height.max(1));
    // Per axis: texel 0, texel 1, weight of texel 1 (in 128ths).
    let mut axes = [(0usize, 0usize, 0i32); 2];
    for (a, n) in [(0, w), (1, h)] {
        let wrap = tex.wrap[a];
        let u = scaled(tex, st[a], wrap, n);
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
    offset: [i32; 3],
) -> [f32; 4] {
    // A cube face or an array layer is the coordinate after the
    // target's.
    let dims = tex.dims();
    let sizes = [img.width, img.height, img.depth].map(|s| s.max(1));
    // Per axis: (texel 0, texel 1, weight of texel 1).
    let mut axes: [(Texel, Texel, f32); 3] = [(Some(0), Some(0), 0.0); 3];
    for a in 0..dims {
        let n = sizes[a];
        let wrap = tex.wrap[a];
        let u = scaled(tex, st[a], wrap, n) + offset[a] as f32;
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
    if let Some(layer) = layer {
        axes[dims] = (Some(layer), None, 0.0);
    }
    let fetch = |i: Texel, j: Texel, k: Texel| -> [f32; 4] {
        let t = match (i, j, k) {
            (Some(i), Some(j), Some(k)) => decoded(tex, img.texel(i, j, k)),
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
