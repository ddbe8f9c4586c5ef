//! `shaderbox shader-runner`: piglit's `shader_runner` program contract.
//!
//! piglit's framework (`framework/test/shader_test.py`) runs each
//! `.shader_test` file as
//!
//! ```text
//! shader_runner FILE -auto -fbo
//! ```
//!
//! and reads back (`framework/test/piglit_test.py`, `base.py`) the line
//! `PIGLIT: {"result": "pass"|"fail"|"skip"|"warn" }` on stdout and the exit
//! status: 0 keeps the verdict, any other status turns "pass" into "warn"
//! and anything else into "fail"; death by a signal is a "crash". So this
//! command exits like `piglit_report_result`: 0 for pass, warn and skip, 1
//! for fail; a panic in shaderbox aborts the process (SIGABRT) so piglit
//! records a crash.
//!
//! What it runs (see [`script`], [`command`] and [`run`](mod@run)): the OpenGL 2.1 /
//! GLSL 1.10 and 1.20 subset of the format: `[require]` (GL, GLSL and limit
//! comparisons, extensions, `SIZE`, `depthbuffer`), vertex and fragment
//! shader sections (several per stage, and piglit's passthrough vertex
//! shader), `[vertex data]`, and the `[test]` commands that OpenGL 2.1 can
//! carry out. Tests needing a later GL version, an extension, or commands
//! of those are skipped, with the reason printed. `-auto` and `-fbo` are
//! accepted and change nothing (there is no window; the default framebuffer
//! is 250x250 RGBA8, with a depth buffer when `depthbuffer` is required).
//!
//! Limitations: one test file per run (piglit's multi-file mode with
//! `-report-subtests` is not provided); `rlimit` is not applied.

pub mod command;
mod gl_api;
mod images;
pub mod png;
pub mod probe;
pub mod run;
mod scan;
pub mod script;

mod gl_context;

use crate::guard::guarded;
use run::Verdict;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(clap::Args, Debug)]
#[command(disable_help_flag = false)]
pub struct Args {
    /// FILE.shader_test, then piglit's options: -auto and -fbo (accepted,
    /// no effect), --png OUT.png (write the framebuffer at the end),
    /// --parse-only (check the script's syntax without running it).
    #[arg(
        value_name = "FILE [OPTIONS]",
        num_args = 1..,
        trailing_var_arg = true,
        allow_hyphen_values = true,
        required = true
    )]
    pub args: Vec<String>,
}

/// The command line after piglit's conventions.
#[derive(Debug, Default, PartialEq)]
pub struct Options {
    pub file: PathBuf,
    pub png: Option<PathBuf>,
    pub parse_only: bool,
}

/// Parses the arguments as piglit's programs do (single-dash long options).
pub fn parse_args(args: &[String]) -> Result<Options, String> {
    let mut opts = Options::default();
    let mut file = None;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "-auto"
            | "-fbo"
            | "-glsl"
            | "-report-subtests"
            | "-compat"
            | "-khr_no_error"
            | "-force-no-names"
            | "-get-program-binary"
            | "-ignore-missing-uniforms" => {}
            "-png" => {}
            "--png" => {
                let out = it.next().ok_or("--png needs a file name")?;
                opts.png = Some(PathBuf::from(out));
            }
            "--parse-only" => opts.parse_only = true,
            "-rlimit" => {
                it.next().ok_or("-rlimit needs a value")?;
            }
            "-spirv" => return Err("-spirv: SPIR-V shaders are not supported".into()),
            s if s.starts_with("-samples=") => {}
            s if s.starts_with('-') && s.len() > 1 => return Err(format!("unknown option `{s}'")),
            s => {
                if file.is_some() {
                    return Err("shaderbox shader-runner runs one test file at a time".into());
                }
                file = Some(PathBuf::from(s));
            }
        }
    }
    opts.file = file.ok_or(
        "usage: shaderbox shader-runner <test.shader_test> [-auto] [-fbo] [--png OUT.png]",
    )?;
    Ok(opts)
}

/// Runs one test and reports it the way piglit's program does.
pub fn run(args: &Args) -> ExitCode {
    let (verdict, out, err) = match parse_args(&args.args) {
        Ok(opts) => {
            let file = opts.file.display().to_string();
            match guarded(|| evaluate(&opts)) {
                Ok(r) => r,
                Err(panic) => {
                    let _ = std::io::stdout().flush();
                    eprintln!(
                        "shaderbox: internal error while running {file}: {}",
                        panic.message
                    );
                    std::process::abort();
                }
            }
        }
        Err(e) => (Verdict::Fail, String::new(), format!("{e}\n")),
    };
    {
        let mut stderr = std::io::stderr().lock();
        let _ = stderr.write_all(err.as_bytes());
        let _ = stderr.flush();
    }
    let mut stdout = std::io::stdout().lock();
    let _ = stdout.write_all(out.as_bytes());
    let _ = writeln!(stdout, "PIGLIT: {{\"result\": \"{}\" }}", verdict.as_str());
    let _ = stdout.flush();
    ExitCode::from(verdict.exit_code())
}

/// Reads, parses and runs a test: verdict, stdout text, stderr text.
fn evaluate(opts: &Options) -> (Verdict, String, String) {
    let name = opts.file.display().to_string();
    let text = match read_script(&opts.file) {
        Ok(t) => t,
        Err(e) => return (Verdict::Fail, format!("{e}\n"), String::new()),
    };
    let script = match script::parse(&text) {
        Ok(s) => s,
        Err(e) => return (Verdict::Fail, format!("{name}:{e}\n"), String::new()),
    };
    if opts.parse_only {
        return match check_commands(&script) {
            Ok(summary) => (Verdict::Pass, summary, String::new()),
            Err((line, e)) => (
                Verdict::Fail,
                format!("{name}:{line}: {e}\n"),
                String::new(),
            ),
        };
    }
    execute(opts, &name, &script)
}

fn execute(opts: &Options, name: &str, script: &script::Script) -> (Verdict, String, String) {
    gl_context::execute(opts, name, script)
}

/// Runs a parsed script on a fresh context `gl` of the script's window
/// size, then writes `--png` if asked.
pub fn execute_on<G: gl_api::GlApi>(
    gl: &mut G,
    opts: &Options,
    name: &str,
    script: &script::Script,
) -> (Verdict, String, String) {
    let window = run::window_config(script);
    let (verdict, mut report) = run::Runner::new(gl, name, window).run(script);
    if let Some(path) = &opts.png {
        let (w, h) = (window.width, window.height);
        let mut pixels = vec![0u8; w as usize * h as usize * 4];
        gl.read_pixels(
            0,
            0,
            w,
            h,
            gl::enums::GL_RGBA,
            gl::enums::GL_UNSIGNED_BYTE,
            &mut pixels,
        );
        let png = png::encode_rgba8_bottom_up(w as u32, h as u32, &pixels);
        if let Err(e) = std::fs::write(path, png) {
            report
                .stderr
                .push_str(&format!("cannot write {}: {e}\n", path.display()));
        }
    }
    (verdict, report.stdout, report.stderr)
}

/// Reads and parses a script: its display name and commands.
pub fn load(path: &Path) -> Result<(String, script::Script), String> {
    let name = path.display().to_string();
    let text = read_script(path)?;
    let script = script::parse(&text).map_err(|e| format!("{name}:{e}"))?;
    Ok((name, script))
}

pub use gl_context::context;
pub use run::window_config;

/// Reads a script as text (bytes that are not UTF-8 become U+FFFD).
fn read_script(path: &Path) -> Result<String, String> {
    let bytes = std::fs::read(path)
        .map_err(|e| format!("could not read file \"{}\": {e}", path.display()))?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}

/// Parses every `[test]` line: a summary of the commands, or the first bad
/// line.
pub fn check_commands(script: &script::Script) -> Result<String, (usize, String)> {
    let mut n = 0;
    let mut later = Vec::new();
    for (line, text) in &script.test_lines {
        match command::parse(text) {
            Ok(Some(command::Command::NeedsLaterGl(what))) => later.push(format!("{line}: {what}")),
            Ok(Some(_)) => n += 1,
            Ok(None) => {}
            Err(e) => return Err((*line, e.to_string())),
        }
    }
    let mut s = format!("{n} commands\n");
    for l in later {
        s.push_str(&format!("needs a later GL: {l}\n"));
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn strings(v: &[&str]) -> Vec<String> {
        v.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn piglit_command_lines() {
        let o = parse_args(&strings(&["t.shader_test", "-auto", "-fbo"])).unwrap();
        assert_eq!(o.file, PathBuf::from("t.shader_test"));
        assert_eq!(o.png, None);
        let o = parse_args(&strings(&["-auto", "t.shader_test", "--png", "o.png"])).unwrap();
        assert_eq!(o.png, Some(PathBuf::from("o.png")));
        assert!(parse_args(&strings(&["-auto"])).is_err());
        assert!(parse_args(&strings(&["a", "b"])).is_err());
        assert!(parse_args(&strings(&["a", "-bogus"])).is_err());
        assert!(parse_args(&strings(&["a", "--png"])).is_err());
        assert!(parse_args(&strings(&["a", "-samples=4", "-rlimit", "100"])).is_ok());
    }

    /// piglit's data, when scripts/piglit-fetch.sh has run for this tree
    /// (or `PIGLIT_CACHE` names another cache).
    fn piglit_data() -> Option<PathBuf> {
        let cache = std::env::var_os("PIGLIT_CACHE")
            .map(PathBuf::from)
            .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../.piglit"));
        let data = cache.join("root/usr/lib/x86_64-linux-gnu/piglit");
        data.join("tests/spec/glsl-1.10").is_dir().then_some(data)
    }

    fn shader_tests(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        let mut entries: Vec<_> = entries.flatten().map(|e| e.path()).collect();
        entries.sort();
        for p in entries {
            if p.is_dir() {
                shader_tests(&p, out);
            } else if p.extension().is_some_and(|e| e == "shader_test") {
                out.push(p);
            }
        }
    }

    /// Every GLSL 1.10/1.20 execution test of piglit parses, script and
    /// commands (when piglit's data is present).
    #[test]
    fn parses_every_piglit_script() {
        let Some(data) = piglit_data() else {
            eprintln!("piglit data not found (run scripts/piglit-fetch.sh); not checked");
            return;
        };
        let mut files = Vec::new();
        for top in ["tests", "generated_tests"] {
            for v in ["glsl-1.10", "glsl-1.20"] {
                shader_tests(&data.join(top).join("spec").join(v), &mut files);
            }
        }
        assert_eq!(files.len(), 3138);
        let mut failures = Vec::new();
        let mut later = 0;
        for f in &files {
            let text = read_script(f).unwrap();
            match script::parse(&text) {
                Ok(s) => match check_commands(&s) {
                    Ok(summary) => later += summary.matches("needs a later GL").count(),
                    Err((line, e)) => failures.push(format!("{}:{line}: {e}", f.display())),
                },
                Err(e) => failures.push(format!("{}:{e}", f.display())),
            }
        }
        assert!(failures.is_empty(), "{}", failures.join("\n"));
        // Every command of the 1.10/1.20 tests is one the runner executes.
        assert_eq!(later, 0);
    }
}
