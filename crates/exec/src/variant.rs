//! Which variant of the executor runs: the same interpreter built for one
//! of the CPU levels ([`Level`]: baseline, AVX2, AVX-512), or native code
//! generated per kernel (`jit`), chosen once per process from the CPU
//! ([`crate::cpu`], whether Cranelift supports it) and the
//! environment variable `SHADERBOX_KERNEL=jit|portable|avx2|avx512`. Every
//! variant computes the same bits (tests compare them); only speed differs.
//!
//! The variant also sets the level of the code that runs along kernels
//! ([`Variant::level`]: the rasterizer's texture fast path follows it).

use crate::cpu::Level;
use std::sync::atomic::{AtomicU8, Ordering};

/// A compiled variant of the executor: the interpreter at a [`Level`]
/// (the first three, named as their level) or native code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Variant {
    /// The interpreter at [`Level::Portable`].
    Portable,
    /// The interpreter at [`Level::Avx2`].
    Avx2,
    /// The interpreter at [`Level::Avx512`].
    Avx512,
    /// Native code per kernel (the `jit` module); kernels it does not
    /// compile, and runs before compilation, use the best interpreter.
    Jit,
}

impl From<Level> for Variant {
    /// The interpreter at `level`.
    fn from(level: Level) -> Variant {
        match level {
            Level::Portable => Variant::Portable,
            Level::Avx2 => Variant::Avx2,
            Level::Avx512 => Variant::Avx512,
        }
    }
}

impl Variant {
    pub fn name(self) -> &'static str {
        match self {
            Variant::Jit => "jit",
            v => v.level().name(),
        }
    }

    /// The level the variant's Rust code runs at (the interpreter's, the
    /// texture fast path's): its own, and for native code the highest
    /// this CPU runs.
    pub fn level(self) -> Level {
        match self {
            Variant::Portable => Level::Portable,
            Variant::Avx2 => Level::Avx2,
            Variant::Avx512 => Level::Avx512,
            Variant::Jit => Level::best(),
        }
    }

    fn code(self) -> u8 {
        match self {
            Variant::Portable => 1,
            Variant::Avx2 => 2,
            Variant::Avx512 => 3,
            Variant::Jit => 4,
        }
    }

    /// Whether this CPU can run the variant.
    pub fn supported(self) -> bool {
        match self {
            #[cfg(feature = "jit")]
            Variant::Jit => crate::jit::supported(),
            #[cfg(not(feature = "jit"))]
            Variant::Jit => false,
            v => v.level().supported(),
        }
    }
}

/// Every variant this CPU supports, the portable one first.
pub fn supported_variants() -> Vec<Variant> {
    [
        Variant::Portable,
        Variant::Avx2,
        Variant::Avx512,
        Variant::Jit,
    ]
    .into_iter()
    .filter(|v| v.supported())
    .collect()
}

static CURRENT: AtomicU8 = AtomicU8::new(0);

/// The variant `run` uses: set by [`set_variant`], else chosen on first use
/// from `SHADERBOX_KERNEL` (ignored, with a message on stderr, when it
/// names an unknown or unsupported variant), else `jit` when Cranelift
/// supports the CPU, else the best interpreter the CPU runs (`best_interpreter`).
pub fn current() -> Variant {
    match CURRENT.load(Ordering::Relaxed) {
        1 => Variant::Portable,
        2 => Variant::Avx2,
        3 => Variant::Avx512,
        4 => Variant::Jit,
        _ => {
            let v = choose();
            CURRENT.store(v.code(), Ordering::Relaxed);
            v
        }
    }
}

/// Selects `v` for the whole process; fails (keeping the current one) if
/// the CPU cannot run it.
pub fn set_variant(v: Variant) -> Result<(), String> {
    if !v.supported() {
        return Err(format!(
            "this CPU cannot run the {} executor (it supports: {})",
            v.name(),
            names()
        ));
    }
    CURRENT.store(v.code(), Ordering::Relaxed);
    Ok(())
}

fn names() -> String {
    supported_variants()
        .iter()
        .map(|v| v.name())
        .collect::<Vec<_>>()
        .join(", ")
}

/// The interpreter `jit` falls back to: AVX2 when the CPU has it
/// (measured no slower than AVX-512 on a Xeon with both: 16 lanes of `f32`
/// are two AVX2 registers, and 512-bit code lowers the clock), else
/// portable.
pub(crate) fn best_interpreter() -> Variant {
    Variant::from(Level::best().min(Level::Avx2))
}

fn choose() -> Variant {
    let best = if Variant::Jit.supported() {
        Variant::Jit
    } else {
        best_interpreter()
    };
    match std::env::var("SHADERBOX_KERNEL") {
        Ok(s) if !s.is_empty() => {
            let want = match s.trim() {
                "jit" => Some(Variant::Jit),
                // `base` is the rasterizer's name of the portable level.
                "base" => None,
                name => Level::parse(name).map(Variant::from),
            };
            match want {
                Some(v) if v.supported() => v,
                _ => {
                    eprintln!(
                        "shaderbox: SHADERBOX_KERNEL={s:?} is not a variant this CPU runs \
                         (choose one of: {}); using {}",
                        names(),
                        best.name()
                    );
                    best
                }
            }
        }
        _ => best,
    }
}
