//! Memory that invocations share: the shader storage buffers of a draw
//! or dispatch (GL_ARB_shader_storage_buffer_object) and a compute work
//! group's `shared` variables (GL_ARB_compute_shader), which a program
//! addresses by byte ([`Memory`]), and the atomic operations on it.
//!
//! A program names a buffer by a *space*: the storage blocks of its
//! stage, one space per block element, numbered in the order of
//! [`crate::Interface::buffers`] ([`buffer_space`]); [`SHARED_SPACE`] is the work group's
//! shared variables, laid out by std430 in declaration order
//! ([`crate::Interface::shared_bytes`]). Every access is one 32-bit word
//! at a byte address that is a multiple of 4: the layouts of GLSL
//! (std140, std430) place every scalar so. The lanes of a batch access
//! memory one after the other in lane order, so atomics and overlapping
//! stores have one outcome on every machine.

/// The space of a compute work group's `shared` variables.
pub const SHARED_SPACE: u32 = u32::MAX;

/// The space of a stage's storage block element `index` (its position in
/// [`crate::Interface::buffers`]): the stage in the high byte, so the
/// stages of one draw, which share a [`Memory`], have spaces of their own.
pub fn buffer_space(stage: glsl::Stage, index: u32) -> u32 {
    let tag: u32 = match stage {
        glsl::Stage::Vertex => 1,
        glsl::Stage::TessControl => 2,
        glsl::Stage::TessEvaluation => 3,
        glsl::Stage::Geometry => 4,
        glsl::Stage::Fragment => 5,
        glsl::Stage::Compute => 6,
    };
    (tag << 24) | (index & 0x00FF_FFFF)
}

/// An atomic function of GLSL 4.30 §8.11 (GL_ARB_shader_storage_buffer_object,
/// GL_ARB_compute_shader).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AtomicOp {
    Add,
    /// Minimum and maximum of `int`s.
    MinI,
    MaxI,
    /// Of `uint`s.
    MinU,
    MaxU,
    And,
    Or,
    Xor,
    Exchange,
    /// `atomicCompSwap(mem, compare, data)`: `data` when `mem == compare`.
    CompSwap,
}

impl AtomicOp {
    /// The new value of a word holding `old` (`a` the data, `b` the data
    /// of `atomicCompSwap` whose `a` is the comparison).
    pub fn apply(self, old: u32, a: u32, b: u32) -> u32 {
        match self {
            AtomicOp::Add => old.wrapping_add(a),
            AtomicOp::MinI => (old as i32).min(a as i32) as u32,
            AtomicOp::MaxI => (old as i32).max(a as i32) as u32,
            AtomicOp::MinU => old.min(a),
            AtomicOp::MaxU => old.max(a),
            AtomicOp::And => old & a,
            AtomicOp::Or => old | a,
            AtomicOp::Xor => old ^ a,
            AtomicOp::Exchange => a,
            AtomicOp::CompSwap => {
                if old == a {
                    b
                } else {
                    old
                }
            }
        }
    }
}

/// The memory of a run: reads and writes of 32-bit words by byte
/// address. Addresses past the end of a buffer (or a space with no
/// buffer) read 0 and drop writes, the robust behaviour GL leaves to the
/// implementation (GL 4.3 §7.8: such accesses have undefined results).
/// Implementations synchronize internally: a run may be shared between
/// the threads of a work group ([`Memory::barrier`]).
pub trait Memory: Sync + std::fmt::Debug {
    fn load(&self, space: u32, addr: u32) -> u32;
    fn store(&self, space: u32, addr: u32, value: u32);
    /// Replaces the word with `op.apply(old, a, b)` and returns `old`, as
    /// one step no other access comes between.
    fn atomic(&self, space: u32, addr: u32, op: AtomicOp, a: u32, b: u32) -> u32;
    /// The size in bytes of the buffer of `space` (the bound range), for
    /// `.length()` of a block's last member of unknown size.
    fn size(&self, space: u32) -> u32;
    /// `barrier()`: returns once every invocation of the work group has
    /// reached it (the compute runner's business; a work group of one
    /// batch runs its lanes in step and needs nothing).
    fn barrier(&self) {}
}

/// One growable byte buffer per space, behind a lock: the memory of a
/// compute work group's shared variables, and a [`Memory`] for tests.
#[derive(Debug, Default)]
pub struct Words {
    spaces: std::sync::Mutex<Vec<(u32, Vec<u32>)>>,
}

impl Words {
    /// Memory with `space` holding `words`.
    pub fn with(spaces: Vec<(u32, Vec<u32>)>) -> Words {
        Words {
            spaces: std::sync::Mutex::new(spaces),
        }
    }

    /// The words of `space` (empty without it).
    pub fn words(&self, space: u32) -> Vec<u32> {
        let s = self.spaces.lock().unwrap_or_else(|e| e.into_inner());
        s.iter()
            .find(|(k, _)| *k == space)
            .map(|(_, w)| w.clone())
            .unwrap_or_default()
    }

    fn with_word<T>(&self, space: u32, addr: u32, f: impl FnOnce(Option<&mut u32>) -> T) -> T {
        let mut s = self.spaces.lock().unwrap_or_else(|e| e.into_inner());
        let word = s
            .iter_mut()
            .find(|(k, _)| *k == space)
            .and_then(|(_, w)| w.get_mut((addr / 4) as usize));
        f(word)
    }
}

impl Memory for Words {
    fn load(&self, space: u32, addr: u32) -> u32 {
        self.with_word(space, addr, |w| w.map_or(0, |w| *w))
    }

    fn store(&self, space: u32, addr: u32, value: u32) {
        self.with_word(space, addr, |w| {
            if let Some(w) = w {
                *w = value;
            }
        })
    }

    fn atomic(&self, space: u32, addr: u32, op: AtomicOp, a: u32, b: u32) -> u32 {
        self.with_word(space, addr, |w| match w {
            Some(w) => {
                let old = *w;
                *w = op.apply(old, a, b);
                old
            }
            None => 0,
        })
    }

    fn size(&self, space: u32) -> u32 {
        let s = self.spaces.lock().unwrap_or_else(|e| e.into_inner());
        s.iter()
            .find(|(k, _)| *k == space)
            .map_or(0, |(_, w)| (w.len() as u32).saturating_mul(4))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn atomic_ops_follow_glsl() {
        assert_eq!(AtomicOp::Add.apply(u32::MAX, 2, 0), 1);
        assert_eq!(AtomicOp::MinI.apply(-3i32 as u32, 2, 0), -3i32 as u32);
        assert_eq!(AtomicOp::MinU.apply(-3i32 as u32, 2, 0), 2);
        assert_eq!(AtomicOp::MaxI.apply(-3i32 as u32, 2, 0), 2);
        assert_eq!(AtomicOp::CompSwap.apply(5, 5, 9), 9);
        assert_eq!(AtomicOp::CompSwap.apply(5, 4, 9), 5);
        let m = Words::with(vec![(0, vec![1, 2])]);
        assert_eq!(m.atomic(0, 4, AtomicOp::Add, 3, 0), 2);
        assert_eq!(m.load(0, 4), 5);
        assert_eq!(m.load(0, 8), 0);
        m.store(0, 8, 7);
        assert_eq!(m.words(0), vec![1, 5]);
        assert_eq!(m.size(0), 8);
        assert_eq!(m.size(3), 0);
    }
}
