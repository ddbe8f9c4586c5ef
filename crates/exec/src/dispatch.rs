//! Which executor runs a kernel's optimized code, per run: native code
//! (`jit`) when the kernel has it (compiled on demand), else the
//! interpreter (`engine`) built for the selected [`crate::Variant`]; and
//! the per-thread register file both work on.
//!
//! It sits above the executors so that they need not know of each other
//! or of the variant selection.

use crate::engine::{run_at, Lanes};
use crate::opt::Code;
use crate::{Batch, ExecError, Kernel, Prepared, Textures};
use std::cell::RefCell;

thread_local! {
    /// The register file, reused across runs on this thread.
    pub(crate) static FILE: RefCell<Vec<Lanes>> = const { RefCell::new(Vec::new()) };
}

/// Runs `k` (whose compiled code is `code`) on `batch`. `pool`: the
/// prepared pool registers, or `None` to run the prologue.
pub(crate) fn run(
    k: &Kernel,
    code: &Code,
    batch: &mut Batch,
    uniforms: &[u32],
    textures: &dyn Textures,
    prepared: Option<&Prepared<'_>>,
) -> Result<(), ExecError> {
    run_on(
        crate::variant::current(),
        k,
        code,
        batch,
        uniforms,
        textures,
        prepared,
    )
}

/// [`run`] with the given variant, which must be supported (else the
/// portable one runs).
pub(crate) fn run_on(
    variant: crate::Variant,
    k: &Kernel,
    code: &Code,
    batch: &mut Batch,
    uniforms: &[u32],
    textures: &dyn Textures,
    prepared: Option<&Prepared<'_>>,
) -> Result<(), ExecError> {
    // A prepared pool is this code's (made by the kernel or a clone).
    let prepared = prepared.filter(|p| std::ptr::eq(code, &*p.code));
    let pool = prepared.map(|p| &p.pool[..]);
    let variant = if variant.supported() {
        variant
    } else {
        crate::Variant::Portable
    };
    // Native code when the kernel has it (compiled on demand), else the
    // best interpreter.
    #[cfg(feature = "jit")]
    let native = match variant {
        // The kernel's cache holds the native code of its own `code`
        // (what every caller passes); any other code is interpreted.
        crate::Variant::Jit if std::ptr::eq(code, &*k.code) => k.jit.get_or_start(&k.code),
        _ => None,
    };
    let variant = match variant {
        crate::Variant::Jit => crate::variant::best_interpreter(),
        v => v,
    };
    FILE.with(|cell| {
        // A textures implementation that runs a kernel on this thread
        // finds the file borrowed: it then gets its own.
        let mut own;
        let mut guard;
        let file: &mut Vec<Lanes> = match cell.try_borrow_mut() {
            Ok(g) => {
                guard = g;
                &mut guard
            }
            Err(_) => {
                own = Vec::new();
                &mut own
            }
        };
        #[cfg(feature = "jit")]
        if let Some(n) = native {
            // The views only with the textures they were made from.
            let views = prepared
                .filter(|p| p.made_with(textures))
                .map_or(&[][..], |p| &p.views[..]);
            return crate::jit::run(n, k, code, file, batch, uniforms, textures, pool, views);
        }
        run_at(
            variant.level(),
            k,
            code,
            file,
            batch,
            uniforms,
            textures,
            pool,
        )
    })
}
