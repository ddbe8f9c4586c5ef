//! What this CPU supports, detected once per process and read with one
//! atomic load: the x86-64 features that the variants compiled with
//! `#[target_feature]` need, here and in the rasterizer (the executor's
//! AVX2 and AVX-512 variants, [`crate::lanes16`], the rasterizer's hot
//! loops). Each caller states which features its variant needs
//! ([`supports`] with a [`Features`] set); the detection itself is this
//! module's alone. Other targets support none of them.

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
