//! Linking compiled shader objects into a program, for `check --link` and
//! `glslparsertest --check-link`.
//!
//! LEAD: the compiler's linker (`glsl::link::link(&[&Shader]) -> Program`
//! with `ok()` and `info_log()`) is not on `main` yet, so [`link`] reports
//! [`Unavailable`]. When it lands, replace the body of [`link`] with
//!
//! ```text
//! let program = glsl::link::link(shaders);
//! Ok(Linked { ok: program.ok(), info_log: program.info_log(),
//!             diagnostics: program.diagnostics.clone() /* if it has them */ })
//! ```
//!
//! and nothing else in the CLI needs to change.

use glsl::{Diagnostic, Shader};

/// The outcome of linking (`GL_LINK_STATUS` and the program info log).
#[derive(Clone, Debug)]
pub struct Linked {
    pub ok: bool,
    pub info_log: String,
    /// Whole-program diagnostics (their spans, if any, are not shown: a
    /// program spans several sources).
    pub diagnostics: Vec<Diagnostic>,
}

/// The linker is not wired in yet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Unavailable;

impl std::fmt::Display for Unavailable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(
            "linking is not implemented yet (the compiler library has no linker on this branch)",
        )
    }
}

/// Links `shaders` (all compiled) into one program.
pub fn link(shaders: &[&Shader]) -> Result<Linked, Unavailable> {
    let _ = shaders;
    Err(Unavailable)
}
