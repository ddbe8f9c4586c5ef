//! What this CPU supports, and the one way every crate compiles code for
//! it.
//!
//! The detection: the x86-64 features, detected once per process and
//! read with one atomic load ([`supports`] with a [`Features`] set). It is
//! this module's alone. Other targets support none of them.
//!
//! The levels: every SIMD variant of every crate (the executor's interpreter
//! and math callbacks, [`crate::lanes16`], the rasterizer's set-up, shading
//! loops, fragment operations and texture fast path, `gl`'s fixed-function
//! fragment stage) is compiled for one [`Level`]: the baseline target, AVX2 or
//! AVX-512, each with ONE feature set ([`Level::features`], and the same set as
//! `#[target_feature]` string in [`compiled_for!`](crate::compiled_for)). The
//! sets are what the variants need together (AVX2 with FMA and the bit-count
//! instructions every AVX2 CPU has; AVX-512 F/BW/DQ/VL on top). Enabling FMA
//! changes no bits: Rust never contracts `a * b + c` into a fused operation,
//! and nothing here calls `mul_add`, so every level computes the same IEEE
//! operations and the portable level is the oracle of the tests.
//!
//! The dispatch: [`multiversion!`](crate::multiversion) writes a function once
//! (a body `#[inline(always)]` into each level's copy) and generates the
//! `#[target_feature]` copies and the `match` on a [`Level`] that calls them.
//! Who chooses the level is the caller's policy (the executor's
//! [`crate::Variant`], the rasterizer's `SHADERBOX_RASTER_ISA`), never a second
//! detection.

use std::sync::atomic::{AtomicU32, Ordering};

/// A set of CPU features (bits).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Features(u32);

impl Features {
    pub const AVX2: Features = Features(1 << 0);
    pub const FMA: Features = Features(1 << 1);
    pub const POPCNT: Features = Features(1 << 2);
    pub const BMI1: Features = Features(1 << 3);
    pub const LZCNT: Features = Features(1 << 4);
    pub const SSE41: Features = Features(1 << 5);
    pub const AVX512F: Features = Features(1 << 6);
    pub const AVX512BW: Features = Features(1 << 7);
    pub const AVX512DQ: Features = Features(1 << 8);
    pub const AVX512VL: Features = Features(1 << 9);

    /// Both sets.
    pub const fn and(self, other: Features) -> Features {
        Features(self.0 | other.0)
    }
}

/// An instruction-set level the SIMD variants are compiled for (see the
/// module documentation). Ordered: a higher level's features include the
/// lower ones'.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Level {
    /// The target's baseline (SSE2 on x86-64).
    Portable,
    /// x86-64 with AVX2, FMA, POPCNT, BMI1 and LZCNT.
    Avx2,
    /// [`Level::Avx2`]'s features and AVX-512 F, BW, DQ and VL.
    Avx512,
}

/// [`Level::Avx2`]'s features (the string in
/// [`compiled_for!`](crate::compiled_for)).
const AVX2_FEATURES: Features = Features::AVX2
    .and(Features::FMA)
    .and(Features::POPCNT)
    .and(Features::BMI1)
    .and(Features::LZCNT);

/// [`Level::Avx512`]'s features (the string in
/// [`compiled_for!`](crate::compiled_for)).
const AVX512_FEATURES: Features = AVX2_FEATURES
    .and(Features::AVX512F)
    .and(Features::AVX512BW)
    .and(Features::AVX512DQ)
    .and(Features::AVX512VL);

impl Level {
    /// Every level, lowest first.
    pub const ALL: [Level; 3] = [Level::Portable, Level::Avx2, Level::Avx512];

    /// The level's name in the environment variables and messages.
    pub fn name(self) -> &'static str {
        match self {
            Level::Portable => "portable",
            Level::Avx2 => "avx2",
            Level::Avx512 => "avx512",
        }
    }

    /// The level [`Level::name`] names (`base` is an old name of
    /// `portable`).
    pub fn parse(name: &str) -> Option<Level> {
        match name.trim() {
            "portable" | "base" => Some(Level::Portable),
            "avx2" => Some(Level::Avx2),
            "avx512" => Some(Level::Avx512),
            _ => None,
        }
    }

    /// The features code compiled for the level may use.
    pub const fn features(self) -> Features {
        match self {
            Level::Portable => Features(0),
            Level::Avx2 => AVX2_FEATURES,
            Level::Avx512 => AVX512_FEATURES,
        }
    }

    /// Whether this CPU runs code compiled for the level.
    #[inline(always)]
    pub fn supported(self) -> bool {
        match self {
            Level::Portable => true,
            #[cfg(target_arch = "x86_64")]
            level => supports(level.features()),
            #[cfg(not(target_arch = "x86_64"))]
            _ => false,
        }
    }

    /// The highest level this CPU runs.
    #[inline]
    pub fn best() -> Level {
        if Level::Avx512.supported() {
            Level::Avx512
        } else if Level::Avx2.supported() {
            Level::Avx2
        } else {
            Level::Portable
        }
    }

    /// Every level this CPU runs, the portable one (the tests' oracle)
    /// first.
    pub fn all_supported() -> Vec<Level> {
        Level::ALL.into_iter().filter(|l| l.supported()).collect()
    }

    /// The level of [`Level::code`] (0 is none).
    pub const fn from_code(code: u8) -> Option<Level> {
        match code {
            1 => Some(Level::Portable),
            2 => Some(Level::Avx2),
            3 => Some(Level::Avx512),
            _ => None,
        }
    }

    /// A non-zero byte for the level (for a choice kept in an atomic).
    pub const fn code(self) -> u8 {
        self as u8 + 1
    }
}

/// `item` (a function) compiled for the level `avx2` or `avx512`: the
/// item with that level's `#[target_feature]` set, the one string per
/// level in the workspace ([`Level::features`] is the same set). The item
/// must be an `unsafe fn`, callable only when the level is
/// [`Level::supported`].
#[macro_export]
macro_rules! compiled_for {
    (avx2, $item:item) => {
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx2,fma,popcnt,bmi1,lzcnt")]
        $item
    };
    (avx512, $item:item) => {
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx2,fma,popcnt,bmi1,lzcnt,avx512f,avx512bw,avx512dq,avx512vl")]
        $item
    };
}

/// A function compiled for every [`Level`] and a dispatch to them.
///
/// ```ignore
/// exec::multiversion! {
///     /// Docs of the dispatching function.
///     pub fn sum(xs: &[f32]) -> f32;
///     level = exec::cpu::Level::best(),
///     copies = [sum_portable, sum_avx2, sum_avx512],
///     body = sum_with(xs)
/// }
/// ```
///
/// generates the three copies (`sum_portable` plain and `#[inline(never)]`,
/// `sum_avx2` and `sum_avx512` through [`compiled_for!`](crate::compiled_for)),
/// each calling the body (an `#[inline(always)]` function, so that it is
/// compiled into each copy with the copy's features), and `sum`, which calls
/// the copy of the `level` expression when the CPU runs it
/// ([`Level::supported`], one atomic load), else the portable one: a caller
/// cannot run a level the CPU lacks. Methods take `&self` first (`level =
/// self.level` then reads a field); a first parameter marked `#[level]` is the
/// level itself and is not passed to the copies; lifetimes go in `<..>`. When
/// the levels' bodies differ (a generic over [`crate::lanes16`]'s types), `body
/// = { portable: .., avx2: .., avx512: .. }` gives one each; those bodies may
/// use the `unsafe` operations the copy's level allows.
///
/// Why a macro rather than the `multiversion` or `pulp` crates: both
/// detect the CPU themselves and pick the widest level they find, while
/// here the level is a policy (`SHADERBOX_KERNEL`, the texture path
/// following the kernel's variant, tests forcing each level in turn
/// against the portable oracle); `multiversion` does not take methods
/// (`self`), and `pulp` has its own levels (`V3`, `V4`) with their own
/// feature sets and dispatches through a `WithSimd` value per call site.
/// The macro expands to the wrappers the crates had written by hand (in
/// a release build the copies kept the byte sizes of the wrappers they
/// replaced where the feature set's union changed no code), so it costs
/// nothing the hand-written code did not but the `supported` check: one
/// relaxed load per call, which makes a safe dispatch sound whatever
/// level it is given.
#[macro_export]
macro_rules! multiversion {
    // A method: `level` an expression (of `self`).
    (
        $(#[$attr:meta])*
        $vis:vis fn $name:ident $(<$($lt:lifetime),*>)?
            (&$this:ident $(, $arg:ident : $ty:ty)* $(,)?) $(-> $ret:ty)?;
        level = $level:expr,
        copies = [$portable:ident, $avx2:ident, $avx512:ident],
        body = $($body:tt)+
    ) => {
        $crate::multiversion!(@copies
            [$(<$($lt),*>)? (&$this $(, $arg: $ty)*) $(-> $ret)?]
            [$portable, $avx2, $avx512] $($body)+);

        $(#[$attr])*
        $vis fn $name $(<$($lt),*>)? (&$this $(, $arg: $ty)*) $(-> $ret)? {
            $crate::multiversion!(@match $level,
                $this.$portable($($arg),*),
                $this.$avx2($($arg),*),
                $this.$avx512($($arg),*))
        }
    };
    // A method whose first parameter after `self` is the level.
    (
        $(#[$attr:meta])*
        $vis:vis fn $name:ident $(<$($lt:lifetime),*>)?
            (&$this:ident, #[level] $lv:ident : $lvty:ty $(, $arg:ident : $ty:ty)* $(,)?)
            $(-> $ret:ty)?;
        copies = [$portable:ident, $avx2:ident, $avx512:ident],
        body = $($body:tt)+
    ) => {
        $crate::multiversion!(@copies
            [$(<$($lt),*>)? (&$this $(, $arg: $ty)*) $(-> $ret)?]
            [$portable, $avx2, $avx512] $($body)+);

        $(#[$attr])*
        $vis fn $name $(<$($lt),*>)? (&$this, $lv: $lvty $(, $arg: $ty)*) $(-> $ret)? {
            $crate::multiversion!(@match $lv,
                $this.$portable($($arg),*),
                $this.$avx2($($arg),*),
                $this.$avx512($($arg),*))
        }
    };
    // A function whose first parameter is the level.
    (
        $(#[$attr:meta])*
        $vis:vis fn $name:ident $(<$($lt:lifetime),*>)?
            (#[level] $lv:ident : $lvty:ty $(, $arg:ident : $ty:ty)* $(,)?) $(-> $ret:ty)?;
        copies = [$portable:ident, $avx2:ident, $avx512:ident],
        body = $($body:tt)+
    ) => {
        $crate::multiversion!(@copies
            [$(<$($lt),*>)? ($($arg: $ty),*) $(-> $ret)?]
            [$portable, $avx2, $avx512] $($body)+);

        $(#[$attr])*
        $vis fn $name $(<$($lt),*>)? ($lv: $lvty $(, $arg: $ty)*) $(-> $ret)? {
            $crate::multiversion!(@match $lv,
                $portable($($arg),*),
                $avx2($($arg),*),
                $avx512($($arg),*))
        }
    };
    // A function: `level` an expression.
    (
        $(#[$attr:meta])*
        $vis:vis fn $name:ident $(<$($lt:lifetime),*>)?
            ($($arg:ident : $ty:ty),* $(,)?) $(-> $ret:ty)?;
        level = $level:expr,
        copies = [$portable:ident, $avx2:ident, $avx512:ident],
        body = $($body:tt)+
    ) => {
        $crate::multiversion!(@copies
            [$(<$($lt),*>)? ($($arg: $ty),*) $(-> $ret)?]
            [$portable, $avx2, $avx512] $($body)+);

        $(#[$attr])*
        $vis fn $name $(<$($lt),*>)? ($($arg: $ty),*) $(-> $ret)? {
            $crate::multiversion!(@match $level,
                $portable($($arg),*),
                $avx2($($arg),*),
                $avx512($($arg),*))
        }
    };
    (@match $level:expr, $portable:expr, $avx2:expr, $avx512:expr) => {
        match $level {
            // SAFETY: the CPU runs the level (checked).
            #[cfg(target_arch = "x86_64")]
            l @ $crate::cpu::Level::Avx512 if l.supported() => unsafe { $avx512 },
            // SAFETY: likewise.
            #[cfg(target_arch = "x86_64")]
            l @ $crate::cpu::Level::Avx2 if l.supported() => unsafe { $avx2 },
            _ => $portable,
        }
    };
    (@copies [$($sig:tt)*] [$portable:ident, $avx2:ident, $avx512:ident]
        { portable: $p:expr, avx2: $a2:expr, avx512: $a5:expr $(,)? }) => {
        /// The portable copy (generated by `multiversion!`).
        #[inline(never)]
        fn $portable $($sig)* { $p }
        $crate::compiled_for!(avx2,
            /// The AVX2 copy (generated by `multiversion!`).
            ///
            /// # Safety
            /// The CPU must run `Level::Avx2`.
            unsafe fn $avx2 $($sig)* { $a2 }
        );
        $crate::compiled_for!(avx512,
            /// The AVX-512 copy (generated by `multiversion!`).
            ///
            /// # Safety
            /// The CPU must run `Level::Avx512`.
            unsafe fn $avx512 $($sig)* { $a5 }
        );
    };
    // One body for every level (after the arm above: a block is an
    // expression too).
    (@copies [$($sig:tt)*] [$portable:ident, $avx2:ident, $avx512:ident] $body:expr) => {
        $crate::multiversion!(@copies [$($sig)*] [$portable, $avx2, $avx512]
            { portable: $body, avx2: $body, avx512: $body });
    };
}

/// Set once the features are known (so that 0 means "not yet").
const KNOWN: u32 = 1 << 31;

static DETECTED: AtomicU32 = AtomicU32::new(0);

/// Whether this CPU has every feature of `set`.
#[inline(always)]
pub fn supports(set: Features) -> bool {
    let known = match DETECTED.load(Ordering::Relaxed) {
        0 => detect(),
        known => known,
    };
    known & set.0 == set.0
}

/// Each feature and whether the standard library finds it on this CPU.
#[cfg(target_arch = "x86_64")]
fn each_detected() -> [(Features, bool); 10] {
    [
        (Features::AVX2, std::is_x86_feature_detected!("avx2")),
        (Features::FMA, std::is_x86_feature_detected!("fma")),
        (Features::POPCNT, std::is_x86_feature_detected!("popcnt")),
        (Features::BMI1, std::is_x86_feature_detected!("bmi1")),
        (Features::LZCNT, std::is_x86_feature_detected!("lzcnt")),
        (Features::SSE41, std::is_x86_feature_detected!("sse4.1")),
        (Features::AVX512F, std::is_x86_feature_detected!("avx512f")),
        (
            Features::AVX512BW,
            std::is_x86_feature_detected!("avx512bw"),
        ),
        (
            Features::AVX512DQ,
            std::is_x86_feature_detected!("avx512dq"),
        ),
        (
            Features::AVX512VL,
            std::is_x86_feature_detected!("avx512vl"),
        ),
    ]
}

/// Other targets: none of them.
#[cfg(not(target_arch = "x86_64"))]
fn each_detected() -> [(Features, bool); 2] {
    [(Features::AVX2, false), (Features::SSE41, false)]
}

/// The features, detected (threads racing here store the same value).
#[cold]
fn detect() -> u32 {
    let mut bits = KNOWN;
    for (f, has) in each_detected() {
        if has {
            bits |= f.0;
        }
    }
    DETECTED.store(bits, Ordering::Relaxed);
    bits
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each level's features include the lower levels' (so a level is
    /// supported only when the lower ones are), the names parse back, and
    /// `best` is the last supported level.
    #[test]
    fn levels_are_ordered_sets() {
        for pair in Level::ALL.windows(2) {
            let (lo, hi) = (pair[0].features(), pair[1].features());
            assert_eq!(lo.and(hi), hi, "{:?} within {:?}", pair[0], pair[1]);
            assert!(!pair[1].supported() || pair[0].supported());
        }
        for l in Level::ALL {
            assert_eq!(Level::parse(l.name()), Some(l));
            assert_eq!(Level::from_code(l.code()), Some(l));
        }
        assert_eq!(Level::parse("base"), Some(Level::Portable));
        assert_eq!(Level::from_code(0), None);
        let all = Level::all_supported();
        assert_eq!(all.first(), Some(&Level::Portable));
        assert_eq!(all.last(), Some(&Level::best()));
    }

    crate::multiversion! {
        /// A test of the macro: the sum in f32, left to right.
        fn sum_at(#[level] level: Level, xs: &[f32]) -> f32;
        copies = [sum_portable, sum_avx2, sum_avx512],
        body = xs.iter().fold(0.0, |a, &x| a + x)
    }

    /// Every supported level's copy gives the portable bits (no
    /// reassociation, no fused operations), and a level the CPU lacks
    /// runs the portable copy instead.
    #[test]
    fn multiversion_copies_agree() {
        let xs: Vec<f32> = (0..1000).map(|i| (i as f32).sqrt() * 1e-3 + 1e7).collect();
        let want = sum_at(Level::Portable, &xs);
        for l in Level::ALL {
            assert_eq!(sum_at(l, &xs).to_bits(), want.to_bits(), "{l:?}");
        }
    }

    /// Each feature's bit says what the standard library's detection
    /// says, alone and in sets, and no two share a bit.
    #[test]
    fn features_match_the_detection() {
        let each = each_detected();
        for (f, has) in each {
            assert_eq!(supports(f), has, "{f:?}");
        }
        for (a, has_a) in each {
            for (b, has_b) in each {
                assert_eq!(supports(a.and(b)), has_a && has_b, "{a:?} and {b:?}");
            }
        }
        // Distinct bits, none of them the "known" mark.
        let mut seen = KNOWN;
        for (f, _) in each {
            assert_eq!(seen & f.0, 0, "{f:?}");
            seen |= f.0;
        }
    }
}
