//! The floating-point environment kernels run in (x86-64: the SSE control
//! and status register, MXCSR).
//!
//! Native code that would flush in many places runs with DAZ set
//! (subnormal operands read as zero of their sign; code with few flushes
//! keeps them and runs in Rust's environment, see `jit::Native::daz`),
//! FTZ clear, rounding to nearest and every exception masked: each
//! IEEE operation then gives the value the interpreter computes by flushing
//! every result (`engine::ftz`), without the four instructions per
//! operation that the flush costs in software. FTZ would not do: x86 tests
//! tininess after rounding, so a product just below 2^-126 that rounds to
//! 2^-126 would become 0. What DAZ cannot cover, subnormal values entering
//! from outside and results leaving the code, is flushed where they cross:
//! inputs, uniforms, constants and texture results are flushed for every
//! variant; outputs and the operands of callbacks on the way out.
//!
//! Rust code assumes the default environment, so the callbacks into Rust
//! switch back to it for their duration ([`callback`]), and a native run
//! restores the environment it found. The caller's own setting (an
//! application that turned FTZ on, say) never reaches a kernel: both
//! environments are set in full. Reading MXCSR (`stmxcsr`) waits for the
//! floating-point operations in flight, which cost about 1 % of a frame
//! when done around every batch; a [`FloatEnv`] held around many runs (the
//! rasterizer holds one per task) reads it once and lets each run set
//! and reset DAZ with two writes.
//!
//! Elsewhere (aarch64) native code flushes in software and nothing here
//! does anything.

use std::cell::Cell;

/// Rust's environment: exceptions masked, round to nearest, no FTZ or DAZ.
#[cfg(target_arch = "x86_64")]
const RUST: u32 = 0x1f80;

/// [`RUST`] with DAZ (bit 6).
#[cfg(target_arch = "x86_64")]
const NATIVE: u32 = RUST | 0x40;

/// The exception flag bits (sticky status, not control).
#[cfg(target_arch = "x86_64")]
const FLAGS: u32 = 0x3f;

thread_local! {
    /// How many [`FloatEnv`]s this thread holds: inside one, MXCSR's
    /// control bits are [`RUST`] outside native code.
    static HELD: Cell<u32> = const { Cell::new(0) };
}

/// Rust's default floating-point environment on this thread until dropped
/// (then the one found is restored): hold one around many kernel runs and
/// each native run only switches DAZ on and off. Nests.
pub struct FloatEnv {
    #[cfg(target_arch = "x86_64")]
    saved: Option<u32>,
}

impl FloatEnv {
    /// Sets Rust's default environment (every exception masked, round to
    /// nearest, no FTZ or DAZ) on this thread until the value is dropped.
    pub fn enter() -> FloatEnv {
        HELD.with(|h| h.set(h.get() + 1));
        #[cfg(target_arch = "x86_64")]
        {
            let now = get();
            let saved = (now & !FLAGS != RUST).then(|| {
                put(RUST);
                now
            });
            FloatEnv { saved }
        }
        #[cfg(not(target_arch = "x86_64"))]
        FloatEnv {}
    }
}

impl Drop for FloatEnv {
    fn drop(&mut self) {
        HELD.with(|h| h.set(h.get().saturating_sub(1)));
        #[cfg(target_arch = "x86_64")]
        if let Some(v) = self.saved {
            put(v);
        }
    }
}

/// Runs native code `f`, compiled for DAZ when `daz`, in its environment.
#[inline(always)]
pub(crate) fn native<R>(daz: bool, f: impl FnOnce() -> R) -> R {
    #[cfg(target_arch = "x86_64")]
    {
        if HELD.with(|h| h.get()) > 0 {
            // MXCSR is RUST: two writes.
            if !daz {
                return f();
            }
            put(NATIVE);
            let _back = Reset(RUST);
            return f();
        }
        let _back = Reset(get());
        put(if daz { NATIVE } else { RUST });
        f()
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = daz;
        f()
    }
}

/// Runs Rust code `f` called back from native code compiled for DAZ when
/// `daz`, in Rust's environment.
#[inline(always)]
pub(crate) fn callback<R>(daz: bool, f: impl FnOnce() -> R) -> R {
    #[cfg(target_arch = "x86_64")]
    if daz {
        put(RUST);
        let _back = Reset(NATIVE);
        return f();
    }
    let _ = daz;
    f()
}

/// Writes its value to MXCSR when dropped (also when unwinding).
#[cfg(target_arch = "x86_64")]
struct Reset(u32);

#[cfg(target_arch = "x86_64")]
impl Drop for Reset {
    #[inline(always)]
    fn drop(&mut self) {
        put(self.0);
    }
}

#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn get() -> u32 {
    let mut v: u32 = 0;
    // SAFETY: `stmxcsr` stores the 4-byte register at a valid address.
    unsafe {
        std::arch::asm!(
            "stmxcsr [{p}]",
            p = in(reg) &mut v as *mut u32,
            options(nostack, preserves_flags)
        )
    };
    v
}

#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn put(v: u32) {
    // SAFETY: `ldmxcsr` loads a value whose reserved bits (16 and up) are
    // zero: [`RUST`], [`NATIVE`] or one read by [`get`].
    unsafe {
        std::arch::asm!(
            "ldmxcsr [{p}]",
            p = in(reg) &v as *const u32,
            options(nostack, preserves_flags, readonly)
        )
    };
}

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use super::*;

    #[test]
    fn environments_are_set_and_restored() {
        let before = get() & !FLAGS;
        for held in [false, true] {
            let scope = held.then(FloatEnv::enter);
            native(true, || {
                assert_eq!(get() & !FLAGS, NATIVE);
                callback(true, || assert_eq!(get() & !FLAGS, RUST));
                assert_eq!(get() & !FLAGS, NATIVE);
            });
            native(false, || assert_eq!(get() & !FLAGS, RUST));
            drop(scope);
            assert_eq!(get() & !FLAGS, before);
        }
    }
}
