//! A deterministic pseudo-random sequence of API calls with hostile
//! arguments (bad enums, negative sizes, stale names, nulls, calls inside
//! glBegin/glEnd): no crash, no panic caught at the C boundary, and the
//! context keeps working afterwards. The calls are decoded by the module
//! the cargo-fuzz target `gl_calls` shares (`common/hostile_calls.rs`).

use gl::enums::*;
use OSMesa::*;

#[path = "common/hostile_calls.rs"]
mod hostile_calls;
use hostile_calls::{Buffers, Choices, H, W};

/// A linear congruential generator as the program's choices.
struct Rng(u64);

impl Choices for Rng {
    fn byte(&mut self) -> u8 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 56) as u8
    }
}

#[test]
fn hostile_call_sequences_never_crash() {
    unsafe {
        let mut framebuffer = vec![0u8; (W * H * 4) as usize];
        let mut bufs = Buffers::default();
        let (ctx, draw_buffer) = hostile_calls::current_context(&mut framebuffer);
        let mut names: Vec<u32> = vec![0, 1, 2, 9999];
        for step in 0..160_000u64 {
            if step % 20_000 == 0 {
                // A new seed, and out of any glBegin left open.
                glEnd();
            }
            let mut rng = Rng(0x5eed
                ^ (step / 20_000).wrapping_mul(0x9e37_79b9)
                ^ step.wrapping_mul(0x2545_f491));
            hostile_calls::call(&mut rng, &mut names, &mut bufs);
        }
        hostile_calls::assert_still_clears(&framebuffer, draw_buffer);
        assert_eq!(OSMesa::context::caught_panics(), 0);
        OSMesaDestroyContext(ctx);
    }
}
