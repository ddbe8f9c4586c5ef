//! What the fast path knows of a texture's storage: per texture, found
//! once per set of units ([`Checked`], kept in [`CheckedUnits`]):
//! completeness and the last level as `Texture::last_level` finds them,
//! and whether the levels are all RGBA8, all f32 or mixed; per request,
//! the sizes and texels of the levels it may read ([`LevelTable`],
//! [`Store`]), with the RGBA8 or f32 texels of one level by number.

use crate::texture::{Image, Texels, Texture, TextureTarget};
use std::sync::{Arc, OnceLock};

/// Levels a request can address on this path (absolute level numbers):
/// more is a 2^31-texel texture, which takes the general path.
const MAX_LEVELS: usize = 32;

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
    pub(super) tex: Arc<Texture>,
    /// Its last level, as [`Texture::last_level`] finds it.
    pub(super) q: usize,
    /// How the levels base..=q are stored.
    pub(super) kind: Kind,
}

/// The storage of a texture's levels base..=q (see [`Store`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    Unorm8,
    F32,
    Mixed,
}

impl Checked {
    /// The description of `tex` (a 2D texture) and q, its last level as
    /// [`Texture::last_level`] finds it, which this checks the same way;
    /// `None` when the texture is incomplete or a level is too large for
    /// 32-bit texel indices (the general path takes those).
    pub(super) fn new(tex: &Arc<Texture>) -> Option<Checked> {
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
                // Integer levels: the general path's.
                Texels::Red16(_) => short = true,
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
pub(super) struct LevelTable<'a> {
    /// The base level and its width and height; level base + s is
    /// `max(1, width >> s)` by `max(1, height >> s)` texels.
    pub(super) base: i32,
    pub(super) width: u32,
    pub(super) height: u32,
    pub(super) store: Store<'a>,
}

/// The texel storage of the levels base..=q (all the texture's levels,
/// by level number).
pub(super) enum Store<'a> {
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
pub(super) fn unorm8_level(levels: &[Image], d: i32) -> &[[u8; 4]] {
    match levels.get(d as usize).map(|img| &img.texels) {
        Some(Texels::Unorm8(t)) if !t.is_empty() => t,
        _ => &ONE_TEXEL,
    }
}

/// The f32 texels of level `d` of `levels`, or none.
#[inline(always)]
pub(super) fn f32_level(levels: &[Image], d: i32) -> &[[f32; 4]] {
    match levels.get(d as usize).map(|img| &img.texels) {
        Some(Texels::F32(t)) => t,
        _ => &[],
    }
}

impl<'a> LevelTable<'a> {
    /// The table of the levels `base..=q` of `tex` (a 2D texture), which
    /// `checked` describes.
    #[inline(always)]
    pub(super) fn new(tex: &'a Texture, checked: &Checked) -> LevelTable<'a> {
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
