//! Which instruction set the fragment back end's hot loops are compiled
//! for, chosen once per process from the CPU: the same Rust code built for
//! the baseline target, for AVX2 (with the bit-count instructions every
//! AVX2 CPU has: POPCNT, BMI1, LZCNT) or for AVX-512 (F/DQ/VL) through
//! `#[target_feature]` wrappers. Only plain IEEE operations are used (no
//! fused multiply-add: Rust never contracts `a * b + c`), so every variant
//! computes the same bits; tests compare them.
//!
//! `SHADERBOX_RASTER_ISA=base|avx2|avx512` picks a variant (one the CPU
//! does not run is ignored).

use std::sync::atomic::{AtomicU8, Ordering};

/// An instruction set the hot loops are compiled for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Isa {
    /// The target's baseline (SSE2 on x86-64).
    Base,
    /// x86-64 with AVX2.
    Avx2,
    /// x86-64 with AVX2 and AVX-512 F, DQ and VL.
    Avx512,
}

impl Isa {
    /// Whether this CPU runs code compiled for `self` (`exec::cpu`'s
    /// detection).
    pub fn supported(self) -> bool {
        use crate::ex::cpu::{supports, Features};
        let avx2 = Features::AVX2
            .and(Features::POPCNT)
            .and(Features::BMI1)
            .and(Features::LZCNT);
        match self {
            Isa::Base => true,
            Isa::Avx2 => supports(avx2),
            Isa::Avx512 => supports(
                avx2.and(Features::AVX512F)
                    .and(Features::AVX512DQ)
                    .and(Features::AVX512VL),
            ),
        }
    }

    /// Every variant this CPU runs, the baseline first (for tests).
    #[cfg(test)]
    pub fn all_supported() -> Vec<Isa> {
        [Isa::Base, Isa::Avx2, Isa::Avx512]
            .into_iter()
            .filter(|i| i.supported())
            .collect()
    }
}

static CHOSEN: AtomicU8 = AtomicU8::new(0);

/// The variant to use: the best the CPU runs, or the one
/// `SHADERBOX_RASTER_ISA` names when the CPU runs it.
pub(crate) fn detect() -> Isa {
    #[cfg(test)]
    if let Some(isa) = FORCED.with(|f| f.get()) {
        return isa;
    }
    let code = CHOSEN.load(Ordering::Relaxed);
    let isa = match code {
        1 => return Isa::Base,
        2 => return Isa::Avx2,
        3 => return Isa::Avx512,
        _ => {
            let named = match std::env::var("SHADERBOX_RASTER_ISA").as_deref() {
                Ok("base") => Some(Isa::Base),
                Ok("avx2") => Some(Isa::Avx2),
                Ok("avx512") => Some(Isa::Avx512),
                _ => None,
            };
            named.filter(|i| i.supported()).unwrap_or_else(|| {
                [Isa::Avx512, Isa::Avx2]
                    .into_iter()
                    .find(|i| i.supported())
                    .unwrap_or(Isa::Base)
            })
        }
    };
    let code = match isa {
        Isa::Base => 1,
        Isa::Avx2 => 2,
        Isa::Avx512 => 3,
    };
    CHOSEN.store(code, Ordering::Relaxed);
    isa
}

#[cfg(test)]
thread_local! {
    /// Tests: the variant [`detect`] returns on this thread.
    static FORCED: std::cell::Cell<Option<Isa>> = const { std::cell::Cell::new(None) };
}

/// Tests: runs `f` with [`detect`] returning `isa` on this thread (draws
/// on one thread run there).
#[cfg(test)]
pub(crate) fn with_isa<T>(isa: Isa, f: impl FnOnce() -> T) -> T {
    let old = FORCED.with(|c| c.replace(Some(isa)));
    let out = f();
    FORCED.with(|c| c.set(old));
    out
}
