//! `shaderbox`: the command-line front of the project.
//!
//! Subcommands, one module each:
//! - `check` ([`check`]): compile (and optionally link) shader files and
//!   print their diagnostics as a rich report, a GL info log or JSON;
//! - `glslparsertest` ([`glslparsertest`]): piglit's `glslparsertest`
//!   program contract, so piglit's own framework can run its compiler tests
//!   against shaderbox;
//! - `shader-runner` ([`shader_runner`]): piglit's `shader_runner` program
//!   contract, running `.shader_test` files on shaderbox's OpenGL 2.1.
//!
//! - `render` ([`render`]): draw a molecule with the shader library and
//!   write a PNG;
//! - `gallery` ([`gallery`]): every library program on a fitting scene,
//!   PNGs and an index.html.
//!
//! - `debug` ([`debug`]): explain one pixel of a `.shader_test`: every
//!   fragment, the statements its shader ran with their values, and the
//!   per-fragment operations.
//!
//! Exit codes are shared by the subcommands ([`Exit`]); `glslparsertest`
//! follows piglit's conventions instead (see its module).

mod check;
mod debug;
mod gallery;
mod glslparsertest;
mod guard;
mod input;
mod render;
mod shader_runner;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

// mimalloc: the compiler allocates many small nodes, which the system
// allocator serves more slowly (docs/PERFORMANCE.md, design decisions).
// The `mimalloc` feature (default) selects it: memory checkers build without
// it, since they track only the system allocator's blocks.
#[cfg(feature = "mimalloc")]
#[global_allocator]
static ALLOC: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// The command line; its `about` (the first line of `--help`) is the
/// crate's description in Cargo.toml.
#[derive(Parser, Debug)]
#[command(name = "shaderbox", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Compile shader files and report their diagnostics.
    Check(check::Args),
    /// Run one piglit compiler test (the contract of piglit's
    /// `glslparsertest` program).
    #[command(name = "glslparsertest")]
    GlslParserTest(glslparsertest::Args),
    /// Run one piglit `.shader_test` file (the contract of piglit's
    /// `shader_runner` program).
    #[command(name = "shader-runner")]
    ShaderRunner(shader_runner::Args),
    /// Draw a molecule (a PDB file, or the embedded crambin) with the
    /// shader library's sphere impostors and write a PNG.
    Render(render::Args),
    /// Draw every program of the shader library on a fitting scene: PNGs
    /// and an index.html.
    Gallery(gallery::Args),
    /// Explain one pixel of a `.shader_test`: the fragments that reached
    /// it, each statement their shader ran with its values, `discard`,
    /// and the depth/stencil/blend decisions.
    Debug(debug::Args),
}

/// Exit statuses of `shaderbox` (except `glslparsertest` and
/// `shader-runner`, which speak piglit's protocol).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Exit {
    /// Everything compiled (and linked, when asked).
    Ok = 0,
    /// A shader failed to compile or the program failed to link.
    Failed = 1,
    /// Bad command line or unreadable input.
    Misuse = 2,
    /// The compiler panicked: a bug in shaderbox, reported instead of a
    /// crash.
    Internal = 3,
}

impl From<Exit> for ExitCode {
    fn from(e: Exit) -> ExitCode {
        ExitCode::from(e as u8)
    }
}

fn main() -> ExitCode {
    // Usage errors exit with 2 (clap's convention, and ours for misuse).
    let cli = Cli::parse();
    match cli.command {
        Command::Check(args) => check::run(&args).into(),
        Command::GlslParserTest(args) => glslparsertest::run(&args),
        Command::ShaderRunner(args) => shader_runner::run(&args),
        Command::Render(args) => render::run(&args).into(),
        Command::Gallery(args) => gallery::run(&args).into(),
        Command::Debug(args) => debug::run(&args).into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn cli_definition_is_consistent() {
        Cli::command().debug_assert();
    }
}
