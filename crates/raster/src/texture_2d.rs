//! The fast path of texture lookups: 2D, no depth comparison, a complete
//! colour texture whose S and T wrap modes never select the border
//! (REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT), one texture unit for every
//! lane of the request. That covers fixed-function texturing and nearly
//! every `texture2D` call.
//!
//! It computes exactly what the general path (`texture_general::sample`) computes,
//! operation for operation and in the same order (λ, level selection,
//! wrapping, weights; for RGBA8 levels the fixed-point filter of
//! [`crate::unorm8_filter`], for f32 levels the float sum over the four
//! texels and the blend of two levels), so the results are the same bits;
//! what it saves is the general path's per-lane dispatch: completeness
//! and storage are found once per set of units (`TextureUnits::checked_2d`,
//! an entry per unit holding the texture it describes) and the state is
//! looked at once per request, texel indices are plain integers (no
//! border case), and every step works on arrays of the 16 lanes: λ (its
//! base once per quad, from the quad's first lane, as the general path
//! defines it: `levels::quad_first`), levels, wrapping, the four
//! corners' indices and weights, then the texels (scalar loads per lane,
//! or the AVX2 gather instruction when every lane reads one level), the
//! filter over all lanes (nearest lanes take corner 0) and the blend of
//! two levels. Textures whose levels mix RGBA8 and f32 storage take the
//! general path.
//!
//! The code is compiled for the baseline instruction set, for AVX2 + FMA
//! and for AVX-512 + FMA, the one matching the executor's variant chosen
//! at run time (`SHADERBOX_KERNEL`; the native-code executor gets the
//! best the CPU has). The two x86 variants run some steps as explicit
//! AVX2 code (the f32 levels' blend and output select, the per-lane level
//! sizes, the gather, the quad comparison; floors by the rounding
//! instruction, see [`lanes::floor_of`]). Both also take each lane's quad
//! derivatives for λ in vector registers, pick the *_MIPMAP_LINEAR
//! levels there and, for RGBA8 levels with REPEAT or
//! CLAMP_TO_EDGE wrapping whose lanes read one level per level pass,
//! filter, blend the two levels and convert there too (module `wide`:
//! coordinates over `exec::lanes16::Lanes16`, one AVX-512 register or
//! two AVX2 ones per value; the fixed-point steps on four pixels' 16-bit
//! channels per AVX2 register), the two texels of each row read by one
//! 64-bit load when no lane is at a wrap edge.
//! Tests compare every variant the CPU has with the general path on
//! random lookups and on runs of nearby quads like the executor's.
//!
//! `exec::Textures::sample_2d_implicit` (the fixed-function stage's
//! lookups: s and t, derivatives their quad differences, no bias) enters
//! here without a `SampleRequest` ([`sample_implicit_with`]); the results are
//! the request's (tested).
//!
//! This module is the entry points and the driver (`sample_in`, once per
//! instruction set), which checks the request and the texture and picks
//! every lane's level(s); its parts: `storage` ([`Checked`] per texture,
//! `LevelTable` per request: what is known of the levels' sizes and
//! storage), `lod` (λ over the lanes), `address` (wrapping, texel
//! indices, LINEAR's weights), `filter` (NEAREST / LINEAR over the lanes,
//! the f32 levels' blend), `lanes` (branch-free floors and masks) and
//! `wide` (the x86 register filter of RGBA8 levels).

use crate::ex::{Lod, SampleRequest, LANES};
use crate::texture::levels::{select_levels, Levels};
use crate::texture::{MagFilter, MinFilter, Texture, TextureTarget, TextureUnit, Wrap};
use crate::unorm8_filter;
use glsl::types::SamplerKind;
use std::sync::Arc;

mod address;
mod filter;
mod lanes;
mod lod;
mod storage;
#[cfg(target_arch = "x86_64")]
mod wide;

pub(crate) use storage::{Checked, CheckedUnits};

use filter::{filter_unorm8_lanes, sample_f32};
use lanes::{floor_index, floor_of, lanes};
use lod::lambdas;
use storage::{LevelTable, Store};

#[cfg(target_arch = "x86_64")]
use exec::lanes16::{X256, X512};

pub(crate) use exec::cpu::Level;

/// The level the fast path runs at: the executor's variant's
/// (`exec::Variant::level`, `SHADERBOX_KERNEL`), since it runs inside the
/// kernel's texture calls; for the native-code executor, the highest this
/// CPU runs.
pub(crate) fn current_level() -> Level {
    exec::kernel_variant().level()
}

/// Samples `req` through the fast path when it applies (see the module
/// documentation) and returns true; false leaves `out` untouched. The
/// code is compiled for every level, `level` chosen at run
/// time (the executor's, [`current_level`], which `TextureUnits` finds
/// once; the baseline one when the CPU lacks it); all compute the same
/// IEEE operations (Rust never fuses a multiply and an add), so the same
/// bits.
#[inline]
pub(crate) fn sample_with(
    level: Level,
    units: &[TextureUnit],
    checked_2d: &CheckedUnits,
    req: &SampleRequest,
    out: &mut [[f32; LANES]; 4],
) -> bool {
    match Lookup2D::of(req) {
        Some(lookup) => sample_lookup(level, units, checked_2d, &lookup, out) != Sampled::No,
        None => false,
    }
}

/// What the fast path did with a lookup.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Sampled {
    /// Not taken: `out` untouched (the general path samples).
    No,
    /// Sampled.
    Yes,
    /// Sampled from RGBA8 levels in fixed point: every value written is
    /// m / 32640 for a whole m (`unorm8_filter::value`), 0 or normal, so
    /// none needs flushing.
    Unorm8,
}

/// The 2D lookup of unit `unit` on the lanes `mask` at (s, t), the
/// implicit LOD from the quad differences of s and t
/// ([`exec::lane::quad_diffs`]) with no bias, compiled for `level` (the
/// baseline one when the CPU lacks it): what [`sample_with`] gives the
/// request `exec::Textures::sample_2d_implicit` describes, without the
/// request ([`Sampled::No`], with nothing written, when the fast path
/// does not apply).
#[inline]
pub(crate) fn sample_implicit_with(
    level: Level,
    units: &[TextureUnit],
    checked_2d: &CheckedUnits,
    unit: u32,
    st: [&[f32; LANES]; 2],
    mask: u32,
    out: &mut [[f32; LANES]; 4],
) -> Sampled {
    if mask == 0 {
        return Sampled::No;
    }
    let lookup = Lookup2D {
        unit,
        mask,
        st,
        lod: LodRef::Implicit,
    };
    sample_lookup(level, units, checked_2d, &lookup, out)
}

/// A 2D lookup without depth comparison of one unit for every lane of
/// its mask, as the fast path reads it (from a request, or given).
pub(crate) struct Lookup2D<'a> {
    unit: u32,
    /// The lanes to sample (not empty).
    mask: u32,
    /// s and t (after the projective divide).
    st: [&'a [f32; LANES]; 2],
    lod: LodRef<'a>,
}

/// [`Lod`] by reference (s and t's derivatives only).
#[derive(Clone, Copy)]
enum LodRef<'a> {
    Explicit(&'a [f32; LANES]),
    Derivatives {
        ddx: [&'a [f32; LANES]; 2],
        ddy: [&'a [f32; LANES]; 2],
        bias: &'a [f32; LANES],
    },
    /// Derivatives the quad differences of the lookup's s and t
    /// (`exec::lane::quad_diffs`), no bias: only the quads' first lanes'
    /// are read (`levels::quad_first`), `s[4q + 1] − s[4q]` along x and
    /// `s[4q + 2] − s[4q]` along y.
    Implicit,
}

impl<'a> Lookup2D<'a> {
    /// `req` as a [`Lookup2D`], or `None` when it is not one (another
    /// target, a depth comparison, no lanes, lanes on different units).
    #[inline(always)]
    fn of(req: &'a SampleRequest) -> Option<Lookup2D<'a>> {
        if req.target != SamplerKind::Sampler2D
            || req.compare.is_some()
            || req.offset.is_some()
            || req.mask == 0
        {
            return None;
        }
        let first = req.mask.trailing_zeros() as usize;
        let &unit = req.unit.get(first)?;
        // Every lane of the mask on that unit (bits of the lanes on
        // another, branch-free so that the loop vectorizes).
        let mut other = 0u32;
        for (lane, &u) in req.unit.iter().enumerate() {
            other |= u32::from(u != unit) << lane;
        }
        if other & req.mask != 0 {
            return None;
        }
        let lod = match &req.lod {
            Lod::Explicit(v) => LodRef::Explicit(v),
            Lod::Derivatives { ddx, ddy, bias } => LodRef::Derivatives {
                ddx: [&ddx[0], &ddx[1]],
                ddy: [&ddy[0], &ddy[1]],
                bias,
            },
            // Each lane's own derivatives: the general path.
            Lod::Gradients { .. } => return None,
        };
        Some(Lookup2D {
            unit,
            mask: req.mask,
            st: [&req.coord[0], &req.coord[1]],
            lod,
        })
    }
}

exec::multiversion! {
    /// [`sample_in`] of `lookup` compiled for `level` (the baseline one
    /// when the CPU lacks it). Inlined into its callers, a dispatch to
    /// the copies (each its own function): `SIMD` and `WIDE` say which
    /// registers the copy has.
    #[inline(always)]
    fn sample_lookup(
        #[level] level: Level,
        units: &[TextureUnit],
        checked_2d: &CheckedUnits,
        lookup: &Lookup2D,
        out: &mut [[f32; LANES]; 4],
    ) -> Sampled;
    copies = [sample_portable, sample_avx2, sample_avx512],
    body = {
        portable: sample_in::<false, NO_WIDE>(units, checked_2d, lookup, out),
        avx2: sample_in::<true, WIDE_AVX2>(units, checked_2d, lookup, out),
        avx512: sample_in::<true, WIDE_AVX512>(units, checked_2d, lookup, out),
    }
}

/// `sample_in`'s `WIDE`: no register filter ([`wide`]).
const NO_WIDE: u8 = 0;
/// `sample_in`'s `WIDE`: [`wide`] in AVX2 registers.
const WIDE_AVX2: u8 = 1;
/// `sample_in`'s `WIDE`: [`wide`] in AVX-512 registers.
const WIDE_AVX512: u8 = 2;

/// The fast path proper, inlined into each instruction set's variant;
/// `SIMD`: compiled for x86-64 with AVX2 and FMA, which some steps use
/// directly; `WIDE`: [`WIDE_AVX2`] or [`WIDE_AVX512`] in code compiled
/// for that set, whose registers pick the *_MIPMAP_LINEAR levels and
/// filter the RGBA8 levels of the requests [`wide`] takes.
#[inline(always)]
fn sample_in<const SIMD: bool, const WIDE: u8>(
    units: &[TextureUnit],
    checked_2d: &CheckedUnits,
    lookup: &Lookup2D,
    out: &mut [[f32; LANES]; 4],
) -> Sampled {
    let unit_index = lookup.unit;
    let Some(unit) = units.get(unit_index as usize) else {
        return Sampled::No;
    };
    let Some(tex_arc) = unit.tex_2d.as_ref() else {
        return Sampled::No;
    };
    let tex: &Texture = tex_arc;
    let borderless = |w: Wrap| matches!(w, Wrap::Repeat | Wrap::ClampToEdge | Wrap::MirroredRepeat);
    if tex.target != TextureTarget::Tex2D
        || tex.depth_format
        || tex.integer
        || tex.srgb
        || tex.swizzle != crate::texture::NO_SWIZZLE
        || !borderless(tex.wrap[0])
        || !borderless(tex.wrap[1])
    {
        return Sampled::No;
    }
    // Incomplete textures take the general path (which samples black).
    // What depends on the texture alone is found once per set of units
    // (the entry of this very texture, else found here).
    let checked = checked_2d.get_or_init(|| {
        units
            .iter()
            .map(|u| u.tex_2d.as_ref().and_then(Checked::new))
            .collect()
    });
    let found;
    let checked = match checked.get(unit_index as usize) {
        Some(Some(c)) if Arc::ptr_eq(&c.tex, tex_arc) => c,
        _ => {
            found = Checked::new(tex_arc);
            match &found {
                Some(c) => c,
                None => return Sampled::No,
            }
        }
    };
    let q = checked.q;
    let table = LevelTable::new(tex, checked);
    let base = tex.base_level as usize;
    let Some(base_img) = tex.levels.get(base) else {
        return Sampled::No;
    };

    // The level(s) of every lane, as `levels::select_levels` picks them.
    let mask = lookup.mask;
    let mut level = [[base as i32; LANES]; 2];
    let mut f = [0.0f32; LANES];
    let mut two: u32 = 0;
    let mut nearest: u32 = 0;
    let unmipmapped = matches!(tex.min_filter, MinFilter::Nearest | MinFilter::Linear);
    let min_nearest = tex.min_filter == MinFilter::Nearest;
    let mag_nearest = tex.mag_filter == MagFilter::Nearest;
    if unmipmapped && min_nearest == mag_nearest {
        // The base level with one filter whatever λ (which has no other
        // effect): λ is not computed.
        if mag_nearest {
            nearest = !0;
        }
    } else if unmipmapped {
        // Magnification (λ ≤ c = 0, or NaN) or minification of the base
        // level, over the lanes.
        let lam = lambdas::<WIDE>(tex, base_img, unit.lod_bias, lookup.lod, lookup.st);
        let mut is_nearest = [false; LANES];
        for l in 0..LANES {
            let mag = lam[l].is_nan() || lam[l] <= 0.0;
            is_nearest[l] = if mag { mag_nearest } else { min_nearest };
        }
        for (l, &near) in is_nearest.iter().enumerate() {
            nearest |= (near as u32) << l;
        }
    } else if matches!(
        tex.min_filter,
        MinFilter::LinearMipmapLinear | MinFilter::NearestMipmapLinear
    ) {
        // λ of every lane, as `levels::lambda` computes it.
        let lam = lambdas::<WIDE>(tex, base_img, unit.lod_bias, lookup.lod, lookup.st);
        // Eq. 3.28/3.29 over the lanes, branch-free.
        let c = if tex.mag_filter == MagFilter::Linear
            && tex.min_filter == MinFilter::NearestMipmapLinear
        {
            0.5
        } else {
            0.0
        };
        let min_nearest = tex.min_filter == MinFilter::NearestMipmapLinear;
        let (base_i, q_i) = (base as i32, q as i32);
        let (base_f, q_f) = (base as f32, q as f32);
        let mut is_two = [false; LANES];
        let mut is_nearest = [false; LANES];
        #[cfg(target_arch = "x86_64")]
        if WIDE != NO_WIDE {
            let bounds = (base_i, q_i);
            let filters = (mag_nearest, min_nearest);
            // SAFETY: `WIDE` names the instruction set of the code this
            // is compiled in, which runs only on CPUs that have it.
            let (t, n) = unsafe {
                if WIDE == WIDE_AVX512 {
                    wide::mipmap_linear_levels::<X512>(&lam, c, bounds, filters, &mut level, &mut f)
                } else {
                    wide::mipmap_linear_levels::<X256>(&lam, c, bounds, filters, &mut level, &mut f)
                }
            };
            (two, nearest) = (t & mask, n);
        }
        for l in 0..if WIDE != NO_WIDE { 0 } else { LANES } {
            let lambda = lam[l];
            let mag = lambda.is_nan() || lambda <= c;
            let lb = base_f + lambda;
            let top = lb >= q_f;
            let d1 = floor_index(floor_of::<SIMD>(lb)).max(base_i).min(q_i);
            level[0][l] = if mag {
                base_i
            } else if top {
                q_i
            } else {
                d1
            };
            level[1][l] = (d1 + 1).min(q_i);
            f[l] = lambda - floor_of::<SIMD>(lambda);
            is_two[l] = !mag && !top;
            is_nearest[l] = if mag { mag_nearest } else { min_nearest };
        }
        if WIDE == NO_WIDE {
            for l in 0..LANES {
                two |= (is_two[l] as u32) << l;
                nearest |= (is_nearest[l] as u32) << l;
            }
            two &= mask;
        }
    } else {
        let lam = lambdas::<WIDE>(tex, base_img, unit.lod_bias, lookup.lod, lookup.st);
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

    let levels = match table.store {
        Store::Unorm8(levels) => levels,
        Store::F32(levels) => {
            let st = [*lookup.st[0], *lookup.st[1]];
            let f32_levels = (&table, levels);
            sample_f32::<SIMD>(tex, f32_levels, &level, &f, &st, nearest, two, mask, out);
            return Sampled::Yes;
        }
        // The general path filters each level as it is stored.
        Store::Mixed => return Sampled::No,
    };
    #[cfg(target_arch = "x86_64")]
    if WIDE != NO_WIDE {
        let st = lookup.st;
        let table = &table;
        // SAFETY: as above.
        let done = unsafe {
            if WIDE == WIDE_AVX512 {
                wide::sample_unorm8::<X512>(tex, table, &level, &f, st, nearest, two, mask, out)
            } else {
                wide::sample_unorm8::<X256>(tex, table, &level, &f, st, nearest, two, mask, out)
            }
        };
        if done {
            return Sampled::Unorm8;
        }
    }
    // RGBA8 levels in fixed point (`unorm8_filter`), lane by lane.
    let st = [*lookup.st[0], *lookup.st[1]];
    let near = lanes(nearest);
    let mut m = filter_unorm8_lanes::<SIMD>(tex, &table, levels, &level[0], &st, &near);
    if two != 0 {
        let second = filter_unorm8_lanes::<SIMD>(tex, &table, levels, &level[1], &st, &near);
        for l in 0..LANES {
            if two & (1 << l) != 0 {
                let w = unorm8_filter::level_weight(f[l]);
                for c in 0..4 {
                    m[c][l] = unorm8_filter::levels(m[c][l], second[c][l], w);
                }
            }
        }
    }
    for c in 0..4 {
        for l in 0..LANES {
            if mask & (1 << l) != 0 {
                out[c][l] = unorm8_filter::value(m[c][l]);
            }
        }
    }
    Sampled::Unorm8
}

#[cfg(test)]
mod tests;

#[cfg(test)]
mod bench_tests;
