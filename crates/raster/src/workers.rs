//! Worker threads for [`crate::draw_on`]: an optional rayon pool and the
//! ordered, cancellable task map the vertex and fragment stages use.
//!
//! Results never depend on the number of threads: tasks write only their
//! own data (a vertex chunk, a framebuffer tile), results come back in task
//! order, and when tasks fail the failure of the *lowest* task index is the
//! one reported. Tasks after a failed one may be skipped (that is the only
//! thing scheduling changes), and their results are then dropped by the
//! caller whether or not they ran, so the outcome is the same as running
//! the tasks one after the other and stopping at the first failure.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, MutexGuard, OnceLock};

use crate::spare::Spare;

use rayon::prelude::*;

/// Most threads a [`Workers`] uses.
pub const MAX_THREADS: usize = 256;

/// The threads a draw runs on: 1 = inline on the calling thread (no pool);
/// more = a rayon pool of that many threads, built at the first parallel
/// use and kept for later draws. It also keeps the draws' big buffers
/// (`spare::Spare`) from one draw to the next: it is the object a caller keeps
/// across draws.
pub struct Workers {
    threads: usize,
    pool: OnceLock<Option<rayon::ThreadPool>>,
    spare: Mutex<Spare>,
}

impl Workers {
    /// `threads` workers (clamped to [1, MAX_THREADS]); 0 means the
    /// machine's available parallelism.
    pub fn new(threads: usize) -> Workers {
        let threads = if threads == 0 {
            std::thread::available_parallelism().map_or(1, |n| n.get())
        } else {
            threads
        };
        Workers {
            threads: threads.clamp(1, MAX_THREADS),
            pool: OnceLock::new(),
            spare: Mutex::new(Spare::default()),
        }
    }

    /// The buffers kept from earlier draws.
    pub(crate) fn spare(&self) -> MutexGuard<'_, Spare> {
        self.spare.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Everything on the calling thread.
    pub fn inline() -> Workers {
        Workers::new(1)
    }

    /// The number of threads draws use.
    pub fn threads(&self) -> usize {
        self.threads
    }

    /// The pool, or None to run inline (one thread, or the pool could not
    /// be created: drawing then simply runs on the calling thread).
    fn pool(&self) -> Option<&rayon::ThreadPool> {
        if self.threads <= 1 {
            return None;
        }
        self.pool
            .get_or_init(|| {
                rayon::ThreadPoolBuilder::new()
                    .num_threads(self.threads)
                    .thread_name(|i| format!("shaderbox-raster-{i}"))
                    .build()
                    .ok()
            })
            .as_ref()
    }

    /// Runs `task(i, &cancel)` for every `i` in `0..n` and returns the
    /// results in index order. `min_len` is the fewest tasks one worker
    /// takes at a time (amortises scheduling for small tasks).
    pub(crate) fn map<T: Send>(
        &self,
        n: usize,
        min_len: usize,
        task: impl Fn(usize, &Cancel) -> T + Sync + Send,
    ) -> Vec<T> {
        let cancel = Cancel::new();
        // Tasks run kernels in a known floating-point environment, which
        // each native run then only switches DAZ on and off in.
        match self.pool() {
            None => {
                let _env = exec::FloatEnv::enter();
                (0..n).map(|i| task(i, &cancel)).collect()
            }
            Some(pool) => pool.install(|| {
                (0..n)
                    .into_par_iter()
                    .with_min_len(min_len.max(1))
                    // Every `min_len` tasks their own job: rayon otherwise
                    // stops splitting a range once each thread has a part,
                    // and a thread that finishes early cannot take tasks
                    // from the part another one is running (the end of a
                    // frame would run on one thread).
                    .with_max_len(min_len.max(1))
                    .map(|i| {
                        let _env = exec::FloatEnv::enter();
                        task(i, &cancel)
                    })
                    .collect()
            }),
        }
    }

    /// Runs `task(i, chunk)` on each `chunk_len`-element chunk of `data`
    /// (chunk `i` starts at element `i · chunk_len`; the last may be
    /// shorter), in parallel: for work such as copies, whose chunks are
    /// disjoint and whose result does not depend on their order.
    pub fn for_each_chunk<T: Send>(
        &self,
        data: &mut [T],
        chunk_len: usize,
        task: impl Fn(usize, &mut [T]) + Sync + Send,
    ) {
        let chunk_len = chunk_len.max(1);
        match self.pool() {
            None => data
                .chunks_mut(chunk_len)
                .enumerate()
                .for_each(|(i, c)| task(i, c)),
            Some(pool) => pool.install(|| {
                data.par_chunks_mut(chunk_len)
                    .enumerate()
                    .for_each(|(i, c)| task(i, c))
            }),
        }
    }
}

impl Default for Workers {
    /// The machine's available parallelism.
    fn default() -> Workers {
        Workers::new(0)
    }
}

impl std::fmt::Debug for Workers {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Workers")
            .field("threads", &self.threads)
            .finish()
    }
}

/// The lowest index of a failed task, shared by the tasks of one
/// [`Workers::map`].
pub(crate) struct Cancel {
    first_failed: AtomicUsize,
}

impl Cancel {
    fn new() -> Cancel {
        Cancel {
            first_failed: AtomicUsize::new(usize::MAX),
        }
    }

    /// Task `i` failed.
    pub fn fail(&self, i: usize) {
        self.first_failed.fetch_min(i, Ordering::Relaxed);
    }

    /// True when a task before `i` failed: task `i`'s result will be
    /// dropped, so it may stop. Never true for the lowest failing task or
    /// any task before it.
    pub fn skip(&self, i: usize) -> bool {
        i > self.first_failed.load(Ordering::Relaxed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_come_back_in_order_and_the_lowest_failure_wins() {
        for threads in [1, 2, 4] {
            let w = Workers::new(threads);
            assert_eq!(w.threads(), threads);
            let out = w.map(100, 3, |i, _| i * 2);
            assert_eq!(out, (0..100).map(|i| i * 2).collect::<Vec<_>>());
            // Tasks 37 and 80 fail; every task up to 37 must complete.
            let out = w.map(100, 1, |i, c| {
                if c.skip(i) {
                    return None;
                }
                if i == 37 || i == 80 {
                    c.fail(i);
                    return Some(Err(i));
                }
                Some(Ok(i))
            });
            for (i, r) in out.iter().enumerate().take(37) {
                assert_eq!(*r, Some(Ok(i)));
            }
            let first = out.iter().flatten().find_map(|r| r.err());
            assert_eq!(first, Some(37));
        }
    }

    #[test]
    fn zero_means_available_parallelism() {
        assert!(Workers::new(0).threads() >= 1);
        assert_eq!(Workers::new(100_000).threads(), MAX_THREADS);
        assert_eq!(Workers::inline().threads(), 1);
    }
}
