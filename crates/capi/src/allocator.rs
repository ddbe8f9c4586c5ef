//! The library's global allocator: mimalloc, with its address-space
//! reservations kept small enough for a host process that limits its
//! address space.
//!
//! mimalloc reserves its heap in arenas, by default 1 GiB of address
//! space at a time (mapped `PROT_READ|PROT_WRITE` with `MAP_NORESERVE`:
//! no memory until touched, but every byte counts against `RLIMIT_AS`).
//! A host that lowers `RLIMIT_AS` after the library's first allocation
//! (piglit's `shader_runner` sets 256 MiB for its `rlimit` tests, after
//! creating the context) is then already over its limit, and its own
//! `malloc` and thread creation fail. So the first allocation sets
//! mimalloc's arena reservation to [`ARENA_RESERVE_KIB`]; mimalloc adds
//! arenas (larger ones as their count grows) when a heap outgrows it.
//!
//! Contract: [`Allocator`] allocates as `mimalloc::MiMalloc`; before the
//! process's first allocation through it returns, mimalloc's arena
//! reservation is [`ARENA_RESERVE_KIB`] KiB.

use std::alloc::{GlobalAlloc, Layout};
use std::ffi::{c_int, c_long};
use std::sync::atomic::{AtomicBool, Ordering};

/// `mi_option_arena_reserve` in mimalloc.h's `mi_option_e` (its position
/// is the same in mimalloc 2 and 3; libmimalloc-sys exports the C
/// functions but, without its `extended` feature, not their Rust
/// declarations).
const MI_OPTION_ARENA_RESERVE: c_int = 23;

/// The arena reservation, in KiB (mimalloc's unit for this option):
/// 64 MiB, two of mimalloc's minimum arenas.
pub const ARENA_RESERVE_KIB: c_long = 64 * 1024;

extern "C" {
    fn mi_option_set(option: c_int, value: c_long);
    fn mi_option_get(option: c_int) -> c_long;
}

static CONFIGURED: AtomicBool = AtomicBool::new(false);

/// Sets the arena reservation once. Two threads racing through here both
/// set the same value, which is harmless.
#[inline]
fn configure() {
    if !CONFIGURED.load(Ordering::Relaxed) {
        // SAFETY: mi_option_set takes any option number and value; it
        // allocates nothing (no reentry into this allocator).
        unsafe { mi_option_set(MI_OPTION_ARENA_RESERVE, ARENA_RESERVE_KIB) };
        CONFIGURED.store(true, Ordering::Relaxed);
    }
}

/// mimalloc's arena reservation now, in KiB (for tests).
pub fn arena_reserve_kib() -> c_long {
    // SAFETY: reads an option; allocates nothing.
    unsafe { mi_option_get(MI_OPTION_ARENA_RESERVE) }
}

/// mimalloc, configured on first use (module docs).
pub struct Allocator;

// SAFETY: every call forwards to mimalloc's GlobalAlloc with the same
// arguments; `configure` only sets an option.
unsafe impl GlobalAlloc for Allocator {
    #[inline]
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        configure();
        mimalloc::MiMalloc.alloc(layout)
    }

    #[inline]
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        configure();
        mimalloc::MiMalloc.alloc_zeroed(layout)
    }

    #[inline]
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        mimalloc::MiMalloc.dealloc(ptr, layout)
    }

    #[inline]
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        mimalloc::MiMalloc.realloc(ptr, layout, new_size)
    }
}
