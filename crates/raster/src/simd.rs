//! Which CPU level ([`Level`], `exec::cpu`) the rasterizer's hot loops run
//! at: set-up, the shading loops, the fragment operations' register
//! paths. Each is one function compiled for every level by
//! `exec::multiversion!`; only plain IEEE operations are used (no fused
//! multiply-add: Rust never contracts `a * b + c`), so every level
//! computes the same bits; tests compare each with the portable one
//! (`with_level`).
//!
//! The level is the highest the CPU runs; `SHADERBOX_RASTER_ISA=
//! portable|avx2|avx512` (`base` is an old name of `portable`) overrides
//! it for these loops only, when the CPU runs the level named (else it is
//! ignored). The texture fast path does not read it: it follows the
//! executor's variant (`SHADERBOX_KERNEL`, `exec::Variant::level`), since
//! it runs inside the kernel's texture calls.

pub(crate) use exec::cpu::Level;
use std::sync::atomic::{AtomicU8, Ordering};

static CHOSEN: AtomicU8 = AtomicU8::new(0);

/// The level of the hot loops: the highest the CPU runs, or the one
/// `SHADERBOX_RASTER_ISA` names when the CPU runs it.
pub(crate) fn detect() -> Level {
    #[cfg(test)]
    if let Some(level) = FORCED.with(|f| f.get()) {
        return level;
    }
    if let Some(level) = Level::from_code(CHOSEN.load(Ordering::Relaxed)) {
        return level;
    }
    let named = std::env::var("SHADERBOX_RASTER_ISA")
        .ok()
        .and_then(|s| Level::parse(&s));
    let level = named.filter(|l| l.supported()).unwrap_or_else(Level::best);
    CHOSEN.store(level.code(), Ordering::Relaxed);
    level
}

#[cfg(test)]
thread_local! {
    /// Tests: the level [`detect`] returns on this thread.
    static FORCED: std::cell::Cell<Option<Level>> = const { std::cell::Cell::new(None) };
}

/// Tests: runs `f` with [`detect`] returning `level` on this thread
/// (draws on one thread run there).
#[cfg(test)]
pub(crate) fn with_level<T>(level: Level, f: impl FnOnce() -> T) -> T {
    let old = FORCED.with(|c| c.replace(Some(level)));
    let out = f();
    FORCED.with(|c| c.set(old));
    out
}
