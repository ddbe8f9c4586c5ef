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
//! instruction, see [`floor_of`]). Both also pick the *_MIPMAP_LINEAR
//! levels in vector registers and, for RGBA8 levels with REPEAT or
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

use crate::ex::{Lod, SampleRequest, LANES};
use crate::texture::levels::{lod_log2, select_levels, wrap_coord, Levels, MAX_LOD_BIAS};
use crate::texture::{
    Image, MagFilter, MinFilter, Texels, Texture, TextureTarget, TextureUnit, Wrap, MISSING,
};
use crate::unorm8_filter;
use glsl::types::SamplerKind;
use std::sync::{Arc, OnceLock};

#[cfg(target_arch = "x86_64")]
mod wide;
#[cfg(target_arch = "x86_64")]
use exec::lanes16::{Lanes16, X256, X512};

/// Levels a request can address on this path (absolute level numbers):
/// more is a 2^31-texel texture, which takes the general path.
const MAX_LEVELS: usize = 32;

/// An instruction set the fast path is compiled for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Isa {
    /// The target's baseline (SSE2 on x86-64).
    Portable,
    /// x86-64 with AVX2 and FMA.
    Avx2,
    /// x86-64 with AVX-512 F/BW/DQ/VL and FMA.
    Avx512,
}

impl Isa {
    /// Whether this CPU runs `self`.
    pub(crate) fn supported(self) -> bool {
        match self {
            Isa::Portable => true,
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2 => X256::supported(),
            #[cfg(target_arch = "x86_64")]
            Isa::Avx512 => X512::supported(),
            #[cfg(not(target_arch = "x86_64"))]
            _ => false,
        }
    }

    /// The instruction set of the executor's variant
    /// (`exec::kernel_variant`, `SHADERBOX_KERNEL`); for the native-code
    /// executor, the fastest one this CPU supports.
    pub(crate) fn current() -> Isa {
        match exec::kernel_variant() {
            exec::Variant::Portable => Isa::Portable,
            exec::Variant::Avx2 => Isa::Avx2,
            exec::Variant::Avx512 => Isa::Avx512,
            exec::Variant::Jit => {
                if Isa::Avx512.supported() {
                    Isa::Avx512
                } else if Isa::Avx2.supported() {
                    Isa::Avx2
                } else {
                    Isa::Portable
                }
            }
        }
    }
}

/// Samples `req` through the fast path when it applies (see the module
/// documentation) and returns true; false leaves `out` untouched. The
/// code is compiled for several instruction sets, `isa` chosen at run
/// time (the executor's, [`Isa::current`], which `TextureUnits` finds
/// once; the baseline one when the CPU lacks it); all compute the same
/// IEEE operations (Rust never fuses a multiply and an add), so the same
/// bits.
#[inline]
pub(crate) fn sample_with(
    isa: Isa,
    units: &[TextureUnit],
    checked_2d: &CheckedUnits,
    req: &SampleRequest,
    out: &mut [[f32; LANES]; 4],
) -> bool {
    match Lookup2D::of(req) {
        Some(lookup) => sample_lookup(isa, units, checked_2d, &lookup, out) != Sampled::No,
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
/// ([`exec::lane::quad_diffs`]) with no bias, compiled for `isa` (the
/// baseline one when the CPU lacks it): what [`sample_with`] gives the
/// request `exec::Textures::sample_2d_implicit` describes, without the
/// request ([`Sampled::No`], with nothing written, when the fast path
/// does not apply).
#[inline]
pub(crate) fn sample_implicit_with(
    isa: Isa,
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
    sample_lookup(isa, units, checked_2d, &lookup, out)
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
        if req.target != SamplerKind::Sampler2D || req.compare.is_some() || req.mask == 0 {
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
        };
        Some(Lookup2D {
            unit,
            mask: req.mask,
            st: [&req.coord[0], &req.coord[1]],
            lod,
        })
    }
}

/// [`sample_in`] of `lookup` compiled for `isa` (the baseline one when
/// the CPU lacks it). Inlined into its callers, a dispatch to the
/// variants (each its own function).
#[inline(always)]
fn sample_lookup(
    isa: Isa,
    units: &[TextureUnit],
    checked_2d: &CheckedUnits,
    lookup: &Lookup2D,
    out: &mut [[f32; LANES]; 4],
) -> Sampled {
    #[cfg(not(target_arch = "x86_64"))]
    let _ = isa;
    #[cfg(target_arch = "x86_64")]
    match isa {
        // SAFETY: the CPU supports the instruction set (checked first).
        Isa::Avx512 if isa.supported() => {
            return unsafe { sample_avx512(units, checked_2d, lookup, out) }
        }
        // SAFETY: as above.
        Isa::Avx2 if isa.supported() => {
            return unsafe { sample_avx2(units, checked_2d, lookup, out) }
        }
        _ => {}
    }
    sample_portable(units, checked_2d, lookup, out)
}

/// [`sample_in`] compiled for the baseline instruction set.
#[inline(never)]
fn sample_portable(
    units: &[TextureUnit],
    checked_2d: &CheckedUnits,
    lookup: &Lookup2D,
    out: &mut [[f32; LANES]; 4],
) -> Sampled {
    sample_in::<false, NO_WIDE>(units, checked_2d, lookup, out)
}

/// [`sample_in`] compiled for AVX2 and FMA.
///
/// # Safety
/// The CPU must support AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn sample_avx2(
    units: &[TextureUnit],
    checked_2d: &CheckedUnits,
    lookup: &Lookup2D,
    out: &mut [[f32; LANES]; 4],
) -> Sampled {
    sample_in::<true, WIDE_AVX2>(units, checked_2d, lookup, out)
}

/// [`sample_in`] compiled for AVX-512 (F, BW, DQ, VL) and FMA.
///
/// # Safety
/// The CPU must support those AVX-512 subsets and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512bw,avx512dq,avx512vl,avx2,fma")]
unsafe fn sample_avx512(
    units: &[TextureUnit],
    checked_2d: &CheckedUnits,
    lookup: &Lookup2D,
    out: &mut [[f32; LANES]; 4],
) -> Sampled {
    sample_in::<true, WIDE_AVX512>(units, checked_2d, lookup, out)
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
        let lam = lambdas::<SIMD>(tex, base_img, unit.lod_bias, lookup.lod, lookup.st);
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
        let lam = lambdas::<SIMD>(tex, base_img, unit.lod_bias, lookup.lod, lookup.st);
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
        let lam = lambdas::<SIMD>(tex, base_img, unit.lod_bias, lookup.lod, lookup.st);
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

/// The f32 levels' part of [`sample_in`]: LINEAR or NEAREST (on the lanes
/// in `nearest`) on `level[0]`, blended with `level[1]` by `f` on the
/// lanes in `two`, into the lanes `mask` of `out`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn sample_f32<const SIMD: bool>(
    tex: &Texture,
    table: (&LevelTable, &[Image]),
    level: &[[i32; LANES]; 2],
    f: &[f32; LANES],
    st: &[[f32; LANES]; 2],
    nearest: u32,
    two: u32,
    mask: u32,
    out: &mut [[f32; LANES]; 4],
) {
    let near = lanes(nearest);
    let mut first = [[0.0f32; LANES]; 4];
    filter_lanes::<SIMD>(tex, table, &level[0], st, &near, &mut first);
    if two != 0 {
        let mut second = [[0.0f32; LANES]; 4];
        filter_lanes::<SIMD>(tex, table, &level[1], st, &near, &mut second);
        // `mix_levels` on the lanes in `two`, as a select over all lanes.
        let two = lanes(two);
        #[cfg(target_arch = "x86_64")]
        if SIMD {
            // SAFETY: `SIMD` is only set in code compiled for AVX2, which
            // runs only on CPUs that have it.
            unsafe { mix_avx2(&mut first, &second, f, &two) };
        }
        if !SIMD {
            for c in 0..4 {
                for l in 0..LANES {
                    let (t1, t2, fl) = (first[c][l], second[c][l], f[l]);
                    let mixed = (1.0 - fl) * t1 + fl * t2;
                    first[c][l] = if two[l] { mixed } else { t1 };
                }
            }
        }
    }
    let mask = lanes(mask);
    #[cfg(target_arch = "x86_64")]
    if SIMD {
        // SAFETY: as above.
        unsafe { select_avx2(out, &first, &mask) };
        return;
    }
    for c in 0..4 {
        for l in 0..LANES {
            out[c][l] = if mask[l] { first[c][l] } else { out[c][l] };
        }
    }
}

/// All ones in the 32-bit lanes `o..o + 8` whose flag is set.
///
/// # Safety
/// The CPU must support AVX2; `o <= LANES - 8`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn flags_avx2(flags: &[bool; LANES], o: usize) -> std::arch::x86_64::__m256 {
    use std::arch::x86_64::*;
    debug_assert!(o + 8 <= LANES);
    // SAFETY: 8 bytes (a bool is one byte, 0 or 1) inside `flags`.
    unsafe {
        let bytes = _mm_loadl_epi64(flags.as_ptr().add(o).cast());
        _mm256_castsi256_ps(_mm256_cmpgt_epi32(
            _mm256_cvtepu8_epi32(bytes),
            _mm256_setzero_si256(),
        ))
    }
}

/// The blend of two levels' values on the lanes in `two`, as the portable
/// code computes it, eight lanes at a time.
///
/// # Safety
/// The CPU must support AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn mix_avx2(
    first: &mut [[f32; LANES]; 4],
    second: &[[f32; LANES]; 4],
    f: &[f32; LANES],
    two: &[bool; LANES],
) {
    use std::arch::x86_64::*;
    // SAFETY: every pointer is to 8 consecutive elements inside one of
    // the arrays (offset 0 or 8 of 16).
    unsafe {
        for o in [0, 8] {
            let fl = _mm256_loadu_ps(f.as_ptr().add(o));
            let one_minus = _mm256_sub_ps(_mm256_set1_ps(1.0), fl);
            let sel = flags_avx2(two, o);
            for (t1, t2) in first.iter_mut().zip(second) {
                let a = _mm256_loadu_ps(t1.as_ptr().add(o));
                let b = _mm256_loadu_ps(t2.as_ptr().add(o));
                let mixed = _mm256_add_ps(_mm256_mul_ps(one_minus, a), _mm256_mul_ps(fl, b));
                _mm256_storeu_ps(t1.as_mut_ptr().add(o), _mm256_blendv_ps(a, mixed, sel));
            }
        }
    }
}

/// `out` takes `value` on the lanes in `mask`, eight lanes at a time.
///
/// # Safety
/// The CPU must support AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn select_avx2(
    out: &mut [[f32; LANES]; 4],
    value: &[[f32; LANES]; 4],
    mask: &[bool; LANES],
) {
    use std::arch::x86_64::*;
    // SAFETY: as in `mix_avx2`.
    unsafe {
        for o in [0, 8] {
            let sel = flags_avx2(mask, o);
            for (out, v) in out.iter_mut().zip(value) {
                let old = _mm256_loadu_ps(out.as_ptr().add(o));
                let new = _mm256_loadu_ps(v.as_ptr().add(o));
                _mm256_storeu_ps(out.as_mut_ptr().add(o), _mm256_blendv_ps(old, new, sel));
            }
        }
    }
}

/// The lanes of a mask, one flag each (for selects over all lanes).
#[inline(always)]
fn lanes(mask: u32) -> [bool; LANES] {
    let mut flags = [false; LANES];
    for (l, flag) in flags.iter_mut().enumerate() {
        *flag = mask & (1 << l) != 0;
    }
    flags
}

/// `levels::lambda` for every lane (the lanes outside the request's
/// mask get some value): with derivatives, λ_base once per quad from the
/// derivatives of its first lane (`levels::quad_first`), computed for the
/// quads' first lanes (eight lanes, the four twice: four-lane loops
/// compile to scalar code) and spread, then each lane's biases and
/// clamps.
#[inline(always)]
fn lambdas<const SIMD: bool>(
    tex: &Texture,
    base_img: &Image,
    unit_bias: f32,
    lod: LodRef,
    st: [&[f32; LANES]; 2],
) -> [f32; LANES] {
    // (Loops, not closures: a closure is compiled without the caller's
    // target features.)
    const HALF: usize = LANES / 2;
    // The quads' first lanes' derivatives (S along x, T along x, S along
    // y, T along y), the four quads twice.
    let mut first = [[0.0f32; HALF]; 4];
    let bias = match lod {
        LodRef::Explicit(v) => {
            // The general path adds a shader bias of 0.
            return clamp_lambdas(tex, v, &[unit_bias + 0.0; LANES]);
        }
        LodRef::Derivatives { ddx, ddy, bias } => {
            for (f, a) in first.iter_mut().zip([ddx[0], ddx[1], ddy[0], ddy[1]]) {
                for k in 0..HALF {
                    f[k] = a[4 * (k % (LANES / 4))];
                }
            }
            bias
        }
        LodRef::Implicit => {
            let [s, t] = st;
            let [sx, tx, sy, ty] = &mut first;
            let rows = sx
                .iter_mut()
                .zip(tx.iter_mut())
                .zip(sy.iter_mut().zip(ty.iter_mut()));
            for (k, ((sx, tx), (sy, ty))) in rows.enumerate() {
                let q = 4 * (k % (LANES / 4));
                (*sx, *tx) = (s[q + 1] - s[q], t[q + 1] - t[q]);
                (*sy, *ty) = (s[q + 2] - s[q], t[q + 2] - t[q]);
            }
            &[0.0; LANES]
        }
    };
    let quads = lambda_bases(base_img, [&first[0], &first[1]], [&first[2], &first[3]]);
    let mut base = [0.0f32; LANES];
    let mut extra = [0.0f32; LANES];
    for l in 0..LANES {
        base[l] = quads[l / 4];
        extra[l] = unit_bias + bias[l];
    }
    clamp_lambdas(tex, &base, &extra)
}

/// λ_base (`levels::lambda`'s log2 ρ) from the derivatives of S and T,
/// for N lanes at once.
#[inline(always)]
fn lambda_bases<const N: usize>(
    base_img: &Image,
    ddx: [&[f32; N]; 2],
    ddy: [&[f32; N]; 2],
) -> [f32; N] {
    let (w, h) = (base_img.width as f32, base_img.height as f32);
    let mut rho = [0.0f32; N];
    for l in 0..N {
        let (ux, uy) = (ddx[0][l] * w, ddy[0][l] * w);
        let mut sx = 0.0f32 + ux * ux;
        let mut sy = 0.0f32 + uy * uy;
        let (ux, uy) = (ddx[1][l] * h, ddy[1][l] * h);
        sx += ux * ux;
        sy += uy * uy;
        // `math::max(math::sqrt(sx), math::sqrt(sy))` as one square root
        // of the larger sum: a correctly rounded square root (the
        // instruction, as `math::sqrt`) never decreases, so the same
        // value; a NaN sum picks the other as `math::max` picks the other
        // root, and a NaN here makes λ NaN whatever its bits.
        let m = if sx.is_nan() || sx < sy { sy } else { sx };
        rho[l] = m.sqrt();
    }
    // Every lane (`lod_log2` is branch-free and total), so that the loop
    // vectorizes.
    let mut base = [0.0f32; N];
    for l in 0..N {
        base[l] = lod_log2(rho[l]);
    }
    base
}

/// λ = clamp(base + clamp(texture bias + `extra`), min, max), per lane.
#[inline(always)]
fn clamp_lambdas<const N: usize>(tex: &Texture, base: &[f32; N], extra: &[f32; N]) -> [f32; N] {
    let (tex_bias, min_lod, max_lod) = (tex.lod_bias, tex.min_lod, tex.max_lod);
    let mut lam = [0.0f32; N];
    for l in 0..N {
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

/// The floor of `x` for the fast path's uses: with `SIMD` (code compiled
/// for AVX2, so SSE4.1), the rounding instruction, else [`floor_lane`].
/// Both give `levels::floor`'s bits except on signaling NaNs, which the
/// instruction quiets; no use tells them apart: a NaN floor becomes
/// index 0 ([`floor_index`]), or is subtracted from the NaN it is the
/// floor of, and a NaN minuend gives itself, quieted, whatever the
/// subtrahend.
#[inline(always)]
fn floor_of<const SIMD: bool>(x: f32) -> f32 {
    if SIMD {
        x.floor()
    } else {
        floor_lane(x)
    }
}

/// `levels::floor` without a branch (so loops over lanes vectorize):
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
fn wrap_scale<const SIMD: bool>(wrap: Wrap, s: &[f32; LANES], n: &[i32; LANES]) -> [f32; LANES] {
    let mut u = [0.0f32; LANES];
    match wrap {
        Wrap::Repeat => {
            for l in 0..LANES {
                u[l] = (s[l] - floor_of::<SIMD>(s[l])) * n[l] as f32;
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

/// The per-lane sizes of `level` (level base + s is `max(1, size >> s)`
/// texels wide and high, `Checked::new` checks it; s in 0..=31).
#[inline(always)]
fn level_sizes(table: &LevelTable, level: &[i32; LANES]) -> ([i32; LANES], [i32; LANES]) {
    let mut w = [1i32; LANES];
    let mut h = [1i32; LANES];
    for l in 0..LANES {
        let s = (level[l].wrapping_sub(table.base) as u32).min(31);
        w[l] = (table.width >> s).max(1) as i32;
        h[l] = (table.height >> s).max(1) as i32;
    }
    (w, h)
}

/// Texel indices of the corners (S varies fastest), `j * width + i`:
/// below width × height ≤ 2^31 − 1 (`Checked::new`).
#[inline(always)]
fn corner_indices(
    w: &[i32; LANES],
    (i0, i1): (&[i32; LANES], &[i32; LANES]),
    (j0, j1): (&[i32; LANES], &[i32; LANES]),
) -> [[u32; LANES]; 4] {
    let mut idx = [[0u32; LANES]; 4];
    for l in 0..LANES {
        let (r0, r1) = (j0[l].wrapping_mul(w[l]), j1[l].wrapping_mul(w[l]));
        idx[0][l] = r0.wrapping_add(i0[l]) as u32;
        idx[1][l] = r0.wrapping_add(i1[l]) as u32;
        idx[2][l] = r1.wrapping_add(i0[l]) as u32;
        idx[3][l] = r1.wrapping_add(i1[l]) as u32;
    }
    idx
}

/// NEAREST or LINEAR on f32 level `level[lane]` of every lane (NEAREST
/// for those in `nearest`), as `texture_general::filter` for a 2D texture without
/// border texels, into `out` (RGBA, lane-major). Every lane's level must
/// be one of the table's (those outside the request give some value).
///
/// All four corners of every lane are fetched (the indices are always in
/// the level), and the sum is computed over all lanes, the nearest lanes
/// then selecting corner 0: straight-line code over arrays of 16 lanes;
/// only the texel loads are per lane.
#[inline(always)]
fn filter_lanes<const SIMD: bool>(
    tex: &Texture,
    (table, levels): (&LevelTable, &[Image]),
    level: &[i32; LANES],
    st: &[[f32; LANES]; 2],
    nearest: &[bool; LANES],
    out: &mut [[f32; LANES]; 4],
) {
    let (ws, wt) = (tex.wrap[0], tex.wrap[1]);
    let (w, h) = level_sizes(table, level);
    let us = wrap_scale::<SIMD>(ws, &st[0], &w);
    let ut = wrap_scale::<SIMD>(wt, &st[1], &h);
    let (i0, i1, a) = axis::<SIMD>(&us, &w, ws, nearest);
    let (j0, j1, b) = axis::<SIMD>(&ut, &h, wt, nearest);
    let idx = corner_indices(&w, (&i0, &i1), (&j0, &j1));
    // The general path's sum over the four texels, each weight the
    // product of the two axes' weights.
    let mut wgt = [[0.0f32; LANES]; 4];
    for l in 0..LANES {
        let (a, b) = (a[l], b[l]);
        let (a0, b0) = (1.0 - a, 1.0 - b);
        wgt[0][l] = a0 * b0;
        wgt[1][l] = a * b0;
        wgt[2][l] = a0 * b;
        wgt[3][l] = a * b;
    }
    // Texels `idx[k][lane]` (corner k) of level `level[lane]`, MISSING
    // out of range, as `t[k][component][lane]`.
    let mut t = [[[0.0f32; LANES]; 4]; 4];
    for l in 0..LANES {
        let texels = f32_level(levels, level[l]);
        for k in 0..4 {
            let v = texels.get(idx[k][l] as usize).copied().unwrap_or(MISSING);
            for c in 0..4 {
                t[k][c][l] = v[c];
            }
        }
    }
    combine(&t, &wgt, nearest, out);
}

/// NEAREST or LINEAR on RGBA8 level `level[lane]` (of `levels`) of every
/// lane (NEAREST for those in `nearest`) in fixed point
/// ([`unorm8_filter`]): the values ×128 (RGBA, lane-major). Every lane's
/// level must be one of the table's (those outside the request give some
/// value).
#[inline(always)]
fn filter_unorm8_lanes<const SIMD: bool>(
    tex: &Texture,
    table: &LevelTable,
    levels: &[Image],
    level: &[i32; LANES],
    st: &[[f32; LANES]; 2],
    nearest: &[bool; LANES],
) -> [[i32; LANES]; 4] {
    let (ws, wt) = (tex.wrap[0], tex.wrap[1]);
    let (w, h) = level_sizes(table, level);
    let us = wrap_scale::<SIMD>(ws, &st[0], &w);
    let ut = wrap_scale::<SIMD>(wt, &st[1], &h);
    let (i0, i1, a) = axis_unorm8::<SIMD>(&us, &w, ws, nearest);
    let (j0, j1, b) = axis_unorm8::<SIMD>(&ut, &h, wt, nearest);
    let idx = corner_indices(&w, (&i0, &i1), (&j0, &j1));
    let mut raw = [[0u32; LANES]; 4];
    gather::<SIMD, 4>(levels, level, &idx, &mut raw);
    let mut out = [[0i32; LANES]; 4];
    for l in 0..LANES {
        let t: [[u8; 4]; 4] = std::array::from_fn(|k| raw[k][l].to_le_bytes());
        let v = if nearest[l] {
            unorm8_filter::nearest(t[0])
        } else {
            unorm8_filter::bilinear(t, a[l], b[l])
        };
        for c in 0..4 {
            out[c][l] = v[c];
        }
    }
    out
}

/// The bilinear sum of the corners `t[k][component][lane]` with weights
/// `wgt[k][lane]` (in corner order, from 0), or corner 0 for the lanes
/// in `nearest`.
#[inline(always)]
fn combine(
    t: &[[[f32; LANES]; 4]; 4],
    wgt: &[[f32; LANES]; 4],
    nearest: &[bool; LANES],
    out: &mut [[f32; LANES]; 4],
) {
    for c in 0..4 {
        for l in 0..LANES {
            let mut acc = 0.0f32;
            for k in 0..4 {
                acc += wgt[k][l] * t[k][c][l];
            }
            out[c][l] = if nearest[l] { t[0][c][l] } else { acc };
        }
    }
}

/// Per axis and lane: texel 0, texel 1 and the weight of texel 1 for
/// LINEAR, or the texel (in texel 0) for the lanes in `nearest`. Computes
/// both for every lane and selects (so the loop vectorizes).
#[inline(always)]
fn axis<const SIMD: bool>(
    u: &[f32; LANES],
    n: &[i32; LANES],
    wrap: Wrap,
    nearest: &[bool; LANES],
) -> ([i32; LANES], [i32; LANES], [f32; LANES]) {
    let mut i0 = [0i32; LANES];
    let mut i1 = [0i32; LANES];
    let mut alpha = [0.0f32; LANES];
    for l in 0..LANES {
        let v = u[l] - 0.5;
        let fl = floor_of::<SIMD>(v);
        alpha[l] = v - fl;
        (i0[l], i1[l]) = texels::<SIMD>(floor_index(fl), u[l], n[l], wrap, nearest[l]);
    }
    (i0, i1, alpha)
}

/// The two texels of a LINEAR axis whose first is `i` (unwrapped), or the
/// NEAREST texel of coordinate `u` first when `nearest`, wrapped into a
/// level `n` texels long.
#[inline(always)]
fn texels<const SIMD: bool>(i: i32, u: f32, n: i32, wrap: Wrap, nearest: bool) -> (i32, i32) {
    let near = wrap_index(floor_index(floor_of::<SIMD>(u)), wrap, n);
    let i0 = if nearest {
        near
    } else {
        wrap_index(i, wrap, n)
    };
    (i0, wrap_index(i.saturating_add(1), wrap, n))
}

/// [`axis`] for the fixed-point filter ([`unorm8_filter`]): texel 0
/// (the NEAREST texel on the lanes in `nearest`), texel 1 and the weight
/// of texel 1 in 128ths (0 for NEAREST).
#[inline(always)]
fn axis_unorm8<const SIMD: bool>(
    u: &[f32; LANES],
    n: &[i32; LANES],
    wrap: Wrap,
    nearest: &[bool; LANES],
) -> ([i32; LANES], [i32; LANES], [i32; LANES]) {
    let mut i0 = [0i32; LANES];
    let mut i1 = [0i32; LANES];
    let mut weight = [0i32; LANES];
    for l in 0..LANES {
        let (i, a) = unorm8_filter::split(unorm8_filter::coord(floor_of::<SIMD>(u[l] * 128.0)));
        (i0[l], i1[l]) = texels::<SIMD>(i, u[l], n[l], wrap, nearest[l]);
        weight[l] = if nearest[l] { 0 } else { a };
    }
    (i0, i1, weight)
}

/// [`gather_unorm8`]; with `SIMD` (code compiled for AVX2), by the
/// gather instruction when every lane reads the same level (the usual
/// case).
#[inline(always)]
fn gather<const SIMD: bool, const K: usize>(
    levels: &[Image],
    level: &[i32; LANES],
    idx: &[[u32; LANES]; K],
    raw: &mut [[u32; LANES]; K],
) {
    #[cfg(target_arch = "x86_64")]
    if SIMD {
        let d0 = level[0];
        if level.iter().all(|&d| d == d0) {
            // SAFETY: `SIMD` is only set in code compiled for AVX2, which
            // runs only on CPUs that have it.
            unsafe { gather_unorm8_avx2(unorm8_level(levels, d0), idx, raw) };
            return;
        }
    }
    gather_unorm8(levels, level, idx, raw);
}

/// Texels `idx[k][lane]` of `texels` (never empty), as little-endian RGBA8
/// words, by the AVX2 gather instruction, eight lanes at a time.
///
/// # Safety
/// The CPU must support AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn gather_unorm8_avx2<const K: usize>(
    texels: &[[u8; 4]],
    idx: &[[u32; LANES]; K],
    raw: &mut [[u32; LANES]; K],
) {
    use std::arch::x86_64::*;
    // Every index is below the level's width × height ≤ 2^31 − 1, which
    // it holds (`Store::Unorm8`); the clamp to the last texel keeps that
    // local (and the index non-negative as an i32).
    let last = texels.len().saturating_sub(1).min(i32::MAX as usize) as i32;
    // SAFETY: the loads and stores are of 8 consecutive elements inside
    // `idx[k]` and `raw[k]` (offset 0 or 8 of 16); each gathered index is
    // in 0..=last, so every 4-byte read is of a texel of `texels`.
    unsafe {
        let last = _mm256_set1_epi32(last);
        for k in 0..K {
            for o in [0, 8] {
                let i = _mm256_loadu_si256(idx[k].as_ptr().add(o).cast());
                let i = _mm256_min_epu32(i, last);
                let v = _mm256_i32gather_epi32::<4>(texels.as_ptr().cast(), i);
                _mm256_storeu_si256(raw[k].as_mut_ptr().add(o).cast(), v);
            }
        }
    }
}

/// Texels `idx[k][lane]` of level `level[lane]` (of [`Store::Unorm8`]),
/// as little-endian RGBA8 words: scalar loads (from one level's texels
/// when every lane reads the same level, the usual case). Kept out of
/// line: inlined, the compiler interleaves the loads with the code
/// around them into badly vectorized code.
#[inline(never)]
fn gather_unorm8<const K: usize>(
    levels: &[Image],
    level: &[i32; LANES],
    idx: &[[u32; LANES]; K],
    raw: &mut [[u32; LANES]; K],
) {
    #[inline(always)]
    fn lane<const K: usize>(
        texels: &[[u8; 4]],
        l: usize,
        idx: &[[u32; LANES]; K],
        raw: &mut [[u32; LANES]; K],
    ) {
        // Every index is below the level's width × height, which it holds
        // (`Store::Unorm8`); the clamp only keeps that local.
        let last = texels.len().saturating_sub(1);
        for k in 0..K {
            let i = (idx[k][l] as usize).min(last);
            // SAFETY: `unorm8_level` never gives an empty slice, so
            // `i <= len - 1` is in bounds.
            raw[k][l] = u32::from_le_bytes(unsafe { *texels.get_unchecked(i) });
        }
    }
    let d0 = level[0];
    if level.iter().all(|&d| d == d0) {
        let texels = unorm8_level(levels, d0);
        for l in 0..LANES {
            lane(texels, l, idx, raw);
        }
    } else {
        for (l, &d) in level.iter().enumerate() {
            lane(unorm8_level(levels, d), l, idx, raw);
        }
    }
}

/// The [`Checked`] entry of each unit's 2D texture, found at the first
/// lookup through a set of units (`TextureUnits::checked_2d`); an entry
/// holds the texture it describes and is used only for that texture (the
/// units may change after it is filled).
pub(crate) type CheckedUnits = OnceLock<Vec<Option<Checked>>>;

/// What [`LevelTable::new`] needs to know about a texture that depends on
/// the texture alone, with the texture (found once per
/// set of units, see [`CheckedUnits`]).
#[derive(Clone, Debug)]
pub(crate) struct Checked {
    /// The texture described (its entry is used for it alone).
    tex: Arc<Texture>,
    /// Its last level, as [`Texture::last_level`] finds it.
    q: usize,
    /// How the levels base..=q are stored.
    kind: Kind,
}

/// The storage of a texture's levels base..=q (see [`Store`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Unorm8,
    F32,
    Mixed,
}

impl Checked {
    /// The description of `tex` (a 2D texture) and q, its last level as
    /// [`Texture::last_level`] finds it, which this checks the same way;
    /// `None` when the texture is incomplete or a level is too large for
    /// 32-bit texel indices (the general path takes those).
    fn new(tex: &Arc<Texture>) -> Option<Checked> {
        if tex.base_level > tex.max_level {
            return None;
        }
        let base = tex.base_level as usize;
        let first = tex.levels.get(base)?;
        let (width, height) = (first.width, first.height);
        if width == 0 || height == 0 || !first.holds_texels() {
            return None;
        }
        let q = if tex.mipmapped() {
            let p = base + (31 - width.max(height).leading_zeros()) as usize;
            p.min(tex.max_level as usize)
        } else {
            base
        };
        // Sizes up to 2^24 (exact in f32) and indices below 2^31 (the
        // other levels are smaller).
        if q >= MAX_LEVELS
            || width > 1 << 24
            || height > 1 << 24
            || width as u64 * height as u64 > i32::MAX as u64
        {
            return None;
        }
        let levels = tex.levels.get(base..=q)?;
        // Level base + s: `max(1, size >> s)` texels wide and high, and
        // holding its texels (s ≤ 31: the sizes have at most 25 bits).
        for (s, img) in (1u32..).zip(&levels[1..]) {
            let sizes_ok = img.width == (width >> s).max(1) && img.height == (height >> s).max(1);
            if !sizes_ok || !img.holds_texels() {
                return None;
            }
        }
        let (mut unorm8, mut float, mut short) = (0, 0, false);
        for img in levels {
            // (A level of depth 0 holds no texels.)
            short |= img.is_empty();
            match img.texels {
                Texels::Unorm8(_) => unorm8 += 1,
                Texels::F32(_) => float += 1,
            }
        }
        let kind = if short || (unorm8 != 0 && float != 0) {
            Kind::Mixed
        } else if float == 0 {
            Kind::Unorm8
        } else {
            Kind::F32
        };
        Some(Checked {
            tex: Arc::clone(tex),
            q,
            kind,
        })
    }
}

/// The levels a request may read (base..=q): their sizes and storage,
/// looked at once per request instead of once per lane.
struct LevelTable<'a> {
    /// The base level and its width and height; level base + s is
    /// `max(1, width >> s)` by `max(1, height >> s)` texels.
    base: i32,
    width: u32,
    height: u32,
    store: Store<'a>,
}

/// The texel storage of the levels base..=q (all the texture's levels,
/// by level number).
enum Store<'a> {
    /// Every level base..=q RGBA8 and holding at least its `w × h` texels
    /// (see [`unorm8_level`]).
    Unorm8(&'a [Image]),
    /// Every level base..=q f32.
    F32(&'a [Image]),
    /// Some of each, or a level with fewer texels than its sizes say (a
    /// 2D level of depth 0): the general path's, which filters each level
    /// as it is stored.
    Mixed,
}

/// The stand-in storage of the levels a request cannot address.
static ONE_TEXEL: [[u8; 4]; 1] = [[0, 0, 0, 255]];

/// The RGBA8 texels of level `d` of `levels`, or [`ONE_TEXEL`] (a level
/// outside [`Store::Unorm8`]'s, stored otherwise or holding none): never
/// empty.
#[inline(always)]
fn unorm8_level(levels: &[Image], d: i32) -> &[[u8; 4]] {
    match levels.get(d as usize).map(|img| &img.texels) {
        Some(Texels::Unorm8(t)) if !t.is_empty() => t,
        _ => &ONE_TEXEL,
    }
}

/// The f32 texels of level `d` of `levels`, or none.
#[inline(always)]
fn f32_level(levels: &[Image], d: i32) -> &[[f32; 4]] {
    match levels.get(d as usize).map(|img| &img.texels) {
        Some(Texels::F32(t)) => t,
        _ => &[],
    }
}

impl<'a> LevelTable<'a> {
    /// The table of the levels `base..=q` of `tex` (a 2D texture), which
    /// `checked` describes.
    #[inline(always)]
    fn new(tex: &'a Texture, checked: &Checked) -> LevelTable<'a> {
        debug_assert_eq!(tex.target, TextureTarget::Tex2D);
        debug_assert!(std::ptr::eq(tex, &*checked.tex));
        let base = tex.base_level as usize;
        let (width, height) = tex
            .levels
            .get(base)
            .map_or((1, 1), |img| (img.width, img.height));
        let store = match checked.kind {
            Kind::Unorm8 => Store::Unorm8(&tex.levels),
            Kind::F32 => Store::F32(&tex.levels),
            Kind::Mixed => Store::Mixed,
        };
        LevelTable {
            base: base as i32,
            width,
            height,
            store,
        }
    }
}

#[cfg(test)]
mod tests;

#[cfg(test)]
mod bench_tests;
