//! Which variant of the executor runs: the same interpreter built for the
//! baseline instruction set, for AVX2 or for AVX-512, or native code
//! generated per kernel (`jit`), chosen once per process from the CPU
//! ([`crate::cpu`], whether Cranelift supports it) and the
//! environment variable `SHADERBOX_KERNEL=jit|portable|avx2|avx512`. Every
//! variant computes the same bits (tests compare them); only speed differs.

use crate::cpu::{supports, Features};
use std::sync::atomic::{AtomicU8, Ordering};

/// A compiled variant of the executor.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Variant {
    /// The target's baseline instruction set (SSE2 on x86-64).
    Portable,
    /// x86-64 with AVX2.
    Avx2,
    /// x86-64 with AVX-512 F/BW/DQ/VL.
    Avx512,
    /// Native code per kernel (the `jit` module); kernels it does not
    /// compile, and runs before compilation, use the best interpreter.
    Jit,
}

impl Variant {
    pub fn name(self) -> &'static str {
        match self {
            Variant::Portable => "portable",
            Variant::Avx2 => "avx2",
            Variant::Avx512 => "avx512",
            Variant::Jit => "jit",
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
            Variant::Portable => true,
            #[cfg(feature = "jit")]
            Variant::Jit => crate::jit::supported(),
            #[cfg(target_arch = "x86_64")]
            Variant::Avx2 => supports(Features::AVX2),
            #[cfg(target_arch = "x86_64")]
            Variant::Avx512 => supports(
                Features::AVX512F
                    .and(Features::AVX512BW)
                    .and(Features::AVX512DQ)
                    .and(Features::AVX512VL)
                    .and(Features::AVX2),
            ),
            #[cfg(not(target_arch = "x86_64"))]
            _ => false,
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
    if Variant::Avx2.supported() {
        Variant::Avx2
    } else {
        Variant::Portable
    }
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
                "portable" => Some(Variant::Portable),
                "avx2" => Some(Variant::Avx2),
                "avx512" => Some(Variant::Avx512),
                "jit" => Some(Variant::Jit),
                _ => None,
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
