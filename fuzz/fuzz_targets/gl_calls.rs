//! Fuzzes GL call sequences through the C ABI (libOSMesa.so's entry points,
//! linked in as the `shaderbox-capi` rlib). The bytes are a program: each
//! call is one byte choosing the entry point, then one byte per argument
//! choosing from tables of hostile values (bad enums, negative and huge
//! sizes, stale names, NaN and infinite floats); the input ends when the
//! bytes do. Each input runs on a fresh 24x16 RGBA context. Afterwards no
//! panic may have been caught at the C boundary (the entry points turn one
//! into a GL error, which would hide it), and the context must still clear
//! its framebuffer.
//!
//! The decoder (the calls, the argument tables, the buffers the pointers
//! point into) is `crates/capi/tests/common/hostile_calls.rs`, which the
//! capi test `fuzz_calls` drives with a fixed pseudo-random program.
#![no_main]

use capi::*;
use gl::enums::*;
use libfuzzer_sys::fuzz_target;

#[path = "../../crates/capi/tests/common/hostile_calls.rs"]
mod hostile_calls;
use hostile_calls::{Buffers, Choices, H, W};

/// The input as a source of argument choices; zeros once it ends.
struct Bytes<'a> {
    data: &'a [u8],
    pos: usize,
}

impl Bytes<'_> {
    fn done(&self) -> bool {
        self.pos >= self.data.len()
    }
}

impl Choices for Bytes<'_> {
    fn byte(&mut self) -> u8 {
        let b = self.data.get(self.pos).copied().unwrap_or(0);
        self.pos += 1;
        b
    }
}

/// Most calls one input makes.
const MAX_CALLS: usize = 256;

fuzz_target!(
    init: {
        std::env::set_var(gl::THREADS_ENV, "1");
    },
    |data: &[u8]| {
        let panics_before = capi::context::caught_panics();
        let mut framebuffer = vec![0u8; (W * H * 4) as usize];
        let mut bufs = Buffers::default();
        let mut input = Bytes { data, pos: 0 };
        // SAFETY: every pointer handed to an entry point points into
        // `framebuffer` or `bufs`, which outlive the context, with room
        // for what the clamped arguments make the call read or write (the
        // decoder's module docs).
        unsafe {
            let (ctx, draw_buffer) = hostile_calls::current_context(&mut framebuffer);
            let mut names: Vec<u32> = vec![0, 1, 2, 9999];
            let mut calls = 0;
            while !input.done() && calls < MAX_CALLS {
                hostile_calls::call(&mut input, &mut names, &mut bufs);
                calls += 1;
            }
            hostile_calls::assert_still_clears(&framebuffer, draw_buffer);
            OSMesaDestroyContext(ctx);
        }
        assert_eq!(
            capi::context::caught_panics(),
            panics_before,
            "a panic was caught at the C boundary (its message is on stderr)"
        );
    }
);
