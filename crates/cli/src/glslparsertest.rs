//! `shaderbox glslparsertest`: piglit's `glslparsertest` program contract.
//!
//! piglit's framework (`framework/test/glsl_parser_test.py`) runs, for each
//! compiler test,
//!
//! ```text
//! glslparsertest FILE pass|fail VERSION [--check-link] [EXTENSION...]
//! ```
//!
//! and reads back (`framework/test/piglit_test.py`, `base.py`):
//! - the line `PIGLIT: {"result": "pass"|"fail"|"skip"}` on stdout, which
//!   sets the verdict; everything else on stdout/stderr is kept as the
//!   test's output;
//! - the exit status: 0 keeps the verdict, any other status turns "pass"
//!   into "warn" and anything else into "fail"; death by a signal (a
//!   negative return code) is a "crash" whatever was printed.
//!
//! So this command prints what piglit's program prints and exits like
//! `piglit_report_result`: 0 for pass and skip, 1 for fail. A compiler
//! panic aborts the process (SIGABRT) so piglit records a crash, not a
//! plain failure.
//!
//! The verdict: the test passes when "compiled (and, with `--check-link`,
//! linked on its own into a program)" equals "expected pass". It is
//! skipped when it needs what shaderbox does not have: a GLSL version
//! other than 1.10 to 3.30 (GLSL ES included), a tessellation stage, a GL
//! extension outside `SUPPORTED_EXTENSIONS` (or the absence of one in
//! it), or shader includes.

use crate::guard::guarded;
use crate::input::{read_source, stage_from_path, StageGuess};
use glsl::{CompileOptions, Shader, Stage, Version};
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

/// GL extensions whose compiler side shaderbox implements. A test
/// requiring any other is skipped, and so is one requiring one of these
/// to be absent (`!NAME`).
const SUPPORTED_EXTENSIONS: &[&str] = &[
    "GL_ARB_explicit_attrib_location",
    "GL_ARB_fragment_coord_conventions",
    "GL_ARB_uniform_buffer_object",
    "GL_ARB_geometry_shader4",
    "GL_EXT_geometry_shader4",
    "GL_ARB_texture_rectangle",
    "GL_ARB_texture_multisample",
    "GL_EXT_texture_array",
    "GL_ARB_shader_texture_lod",
    "GL_ARB_arrays_of_arrays",
    "GL_ARB_shading_language_packing",
    "GL_ARB_texture_cube_map_array",
    "GL_ARB_shading_language_420pack",
    "GL_ARB_separate_shader_objects",
    "GL_ARB_compute_shader",
    "GL_ARB_shader_storage_buffer_object",
    "GL_ARB_tessellation_shader",
];

/// Whether a test of GLSL `version` can use extension `name`: one of
/// [`SUPPORTED_EXTENSIONS`], in a version the compiler offers it in
/// (`glsl::lang::Extension::since`).
fn supported(name: &str, version: Version) -> bool {
    SUPPORTED_EXTENSIONS.contains(&name)
        && glsl::lang::Extension::from_name(name).is_none_or(|e| version >= e.since())
}

/// The extension of a context with the compatibility profile: a test
/// requiring it runs in one.
const COMPATIBILITY: &str = "GL_ARB_compatibility";

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The shader: .vert, .geom, .frag or .comp (.tesc and .tese are
    /// skipped).
    #[arg(value_name = "FILE")]
    pub file: PathBuf,

    /// Whether the shader is expected to compile (and link).
    #[arg(value_enum, value_name = "pass|fail")]
    pub expect: Expect,

    /// The GLSL version the test needs, as piglit writes it: 1.10, 1.20,
    /// "1.50", "3.00 es"... Versions shaderbox does not implement (4.00 and
    /// later, GLSL ES) are skipped.
    #[arg(value_name = "VERSION")]
    pub version: String,

    /// Also link the shader on its own into a program.
    #[arg(long)]
    pub check_link: bool,

    /// Needs GL_ARB_shading_language_include: the test is skipped.
    #[arg(long)]
    pub dummy_shader_include: bool,

    /// Needs GL_ARB_shading_language_include: the test is skipped.
    #[arg(long, value_name = "PATH")]
    pub shader_include_path: Option<String>,

    /// GL extensions the test needs (`!NAME`: needs NAME to be absent).
    #[arg(value_name = "EXT")]
    pub extensions: Vec<String>,
}

#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expect {
    Pass,
    Fail,
}

/// A piglit verdict.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    Pass,
    Fail,
    Skip,
}

impl Verdict {
    fn as_str(self) -> &'static str {
        match self {
            Verdict::Pass => "pass",
            Verdict::Fail => "fail",
            Verdict::Skip => "skip",
        }
    }

    /// `piglit_report_result`'s exit status.
    fn exit_code(self) -> u8 {
        match self {
            Verdict::Pass | Verdict::Skip => 0,
            Verdict::Fail => 1,
        }
    }
}

/// The version a test asks for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Requested {
    /// A version of desktop GLSL shaderbox implements, and whether the
    /// context is a compatibility one: `compatibility` asks for one, and
    /// so does a version below 1.40 (a GL 2.1 or 3.0 context); a bare
    /// 1.40 or later gets the core context piglit's program creates for it
    /// (GL 3.1 without `GL_ARB_compatibility`, 3.2+ core), where `#version
    /// 140` is the core language.
    Supported {
        version: Version,
        compatibility_context: bool,
    },
    /// A well-formed version shaderbox does not implement.
    Other,
}

/// Parses piglit's version argument: `MAJOR.MINOR` with two minor digits,
/// optionally followed (with or without a space) by `es`, `core` or
/// `compatibility`.
pub fn parse_version(text: &str) -> Result<Requested, String> {
    let ill_formed = || format!("Ill-formed GLSL version number: {text}");
    let mut words = text.split_whitespace();
    let first = words.next().ok_or_else(ill_formed)?;
    // piglit writes `1.50 core` but also `1.50compatibility`.
    let (number, glued) = match first.find(|c: char| c.is_ascii_alphabetic()) {
        Some(i) => (&first[..i], Some(&first[i..])),
        None => (first, None),
    };
    let profile = match glued {
        Some(p) => Some(p),
        None => words.next(),
    };
    if words.next().is_some() || !matches!(profile, None | Some("es" | "core" | "compatibility")) {
        return Err(ill_formed());
    }
    let (major, minor) = number.split_once('.').ok_or_else(ill_formed)?;
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    if !digits(major) || minor.len() != 2 || !digits(minor) || major.len() > 2 {
        return Err(ill_formed());
    }
    let n = major.parse::<u32>().map_err(|_| ill_formed())? * 100
        + minor.parse::<u32>().map_err(|_| ill_formed())?;
    match (Version::from_number(n), profile) {
        (Some(version), None | Some("compatibility" | "core")) => Ok(Requested::Supported {
            version,
            compatibility_context: match profile {
                Some(p) => p == "compatibility",
                None => version < Version::V140,
            },
        }),
        _ => Ok(Requested::Other),
    }
}

/// What the command prints before the `PIGLIT:` line, and the verdict.
#[derive(Debug)]
struct Outcome {
    verdict: Verdict,
    message: String,
}

impl Outcome {
    fn new(verdict: Verdict, message: impl Into<String>) -> Outcome {
        Outcome {
            verdict,
            message: message.into(),
        }
    }
}

/// Runs one test and reports it the way piglit's program does.
pub fn run(args: &Args) -> ExitCode {
    let outcome = evaluate(args);
    let mut stdout = std::io::stdout().lock();
    if !outcome.message.is_empty() {
        let _ = writeln!(stdout, "{}", outcome.message.trim_end());
    }
    let _ = writeln!(
        stdout,
        "PIGLIT: {{\"result\": \"{}\" }}",
        outcome.verdict.as_str()
    );
    let _ = stdout.flush();
    ExitCode::from(outcome.verdict.exit_code())
}

fn evaluate(args: &Args) -> Outcome {
    let stage = match stage_from_path(&args.file) {
        StageGuess::Known(s) => s,
        StageGuess::Unknown => {
            return Outcome::new(
                Verdict::Fail,
                format!("Couldn't determine type of program {}", args.file.display()),
            )
        }
    };
    let (version, compatibility_context) = match parse_version(&args.version) {
        Err(e) => return Outcome::new(Verdict::Fail, e),
        Ok(Requested::Other) => {
            return Outcome::new(
                Verdict::Skip,
                format!(
                    "Test requires GLSL {}; shaderbox implements desktop GLSL {}",
                    args.version,
                    Version::ALL.map(|v| v.dotted()).join(", ")
                ),
            )
        }
        Ok(Requested::Supported {
            version,
            compatibility_context,
        }) => (version, compatibility_context),
    };
    // A test that needs GL_ARB_compatibility gets a context that has it, a
    // compatibility one, as piglit's program asks for.
    let compat_required = args.extensions.iter().any(|e| e == COMPATIBILITY);
    let compatibility_context = compatibility_context || compat_required;
    if args.dummy_shader_include || args.shader_include_path.is_some() {
        return Outcome::new(
            Verdict::Skip,
            "Test requires GL_ARB_shading_language_include, which shaderbox does not support",
        );
    }
    for ext in &args.extensions {
        match ext.strip_prefix('!') {
            Some(absent) if supported(absent, version) => {
                return Outcome::new(
                    Verdict::Skip,
                    format!("Test requires {absent} to be absent, and shaderbox supports it"),
                );
            }
            None if !supported(ext, version) && ext != COMPATIBILITY => {
                let why = match glsl::lang::Extension::from_name(ext) {
                    Some(e) if SUPPORTED_EXTENSIONS.contains(&ext.as_str()) => format!(
                        "Test requires extension {ext} in GLSL {}; shaderbox offers it from GLSL {} on",
                        version.dotted(),
                        e.since().dotted()
                    ),
                    _ => format!("Test requires extension {ext}, which shaderbox does not support"),
                };
                return Outcome::new(Verdict::Skip, why);
            }
            _ => {}
        }
    }
    let text = match read_source(&args.file) {
        Ok(t) => t,
        Err(e) => return Outcome::new(Verdict::Fail, e),
    };
    let file = args.file.display().to_string();
    let result = guarded(|| {
        compile_and_link(
            &text,
            stage,
            &file,
            args.check_link,
            version,
            compatibility_context,
        )
    });
    let (ok, log) = match result {
        Ok(r) => r,
        Err(panic) => {
            // piglit records a crash only for death by a signal.
            let _ = std::io::stdout().flush();
            eprintln!(
                "shaderbox: internal error while compiling {file}: {}",
                panic.message
            );
            std::process::abort();
        }
    };
    verdict(args.expect, args.check_link, stage, &file, ok, &log)
}

/// Compiles the shader and, when asked, links it alone into a program
/// (a geometry or tessellation shader with piglit's dummy vertex shader,
/// `void main() { gl_Position = vec4(0.0); }` of the test's version, as a
/// program needs one): whether both succeeded, and the info logs.
fn compile_and_link(
    text: &str,
    stage: Stage,
    file: &str,
    check_link: bool,
    version: Version,
    compatibility_context: bool,
) -> (bool, String) {
    let opts = CompileOptions {
        name: file.to_string(),
        compatibility_context,
        ..CompileOptions::new(stage)
    };
    let shader: Shader = glsl::compile(&[text], &opts);
    let mut log = shader.info_log();
    if !shader.ok() || !check_link {
        return (shader.ok(), log);
    }
    let dummy;
    let mut objects = vec![&shader];
    if matches!(
        stage,
        Stage::TessControl | Stage::TessEvaluation | Stage::Geometry
    ) {
        let source = format!(
            "#version {}\nvoid main() {{ gl_Position = vec4(0.0); }}",
            version.number()
        );
        dummy = glsl::compile(
            &[&source],
            &CompileOptions {
                compatibility_context,
                ..CompileOptions::new(Stage::Vertex)
            },
        );
        objects.insert(0, &dummy);
    }
    // A GL_EXT/ARB_geometry_shader4 geometry shader takes its primitives
    // and vertex count from the program, whose initial count (0) fails
    // every link: the test's program takes triangles in, a triangle strip
    // out and 3 vertices. Other shaders ignore the parameters.
    let params = glsl::link::LinkOptions {
        geometry: glsl::link::GeometryParams {
            vertices_out: 3,
            ..Default::default()
        },
        ..Default::default()
    };
    let program = glsl::link::link_with(&objects, &params);
    log.push_str(program.info_log());
    (program.ok(), log)
}

/// The verdict and piglit's messages for a compile (and link) result.
fn verdict(
    expect: Expect,
    check_link: bool,
    stage: Stage,
    file: &str,
    ok: bool,
    log: &str,
) -> Outcome {
    let log = if log.trim().is_empty() {
        "(no compiler output)"
    } else {
        log.trim_end()
    };
    let expected_ok = expect == Expect::Pass;
    let stage = stage.name();
    if ok == expected_ok {
        let message = if log == "(no compiler output)" {
            String::new()
        } else {
            format!("Info log of {stage} shader {file}:\n{log}")
        };
        Outcome::new(Verdict::Pass, message)
    } else if expected_ok {
        let what = if check_link {
            "compile/link"
        } else {
            "compile"
        };
        Outcome::new(
            Verdict::Fail,
            format!("Failed to {what} {stage} shader {file}: {log}"),
        )
    } else {
        let what = if check_link {
            "compiled and linked"
        } else {
            "compiled"
        };
        Outcome::new(
            Verdict::Fail,
            format!("Successfully {what} {stage} shader {file}: {log}"),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn versions() {
        let supported = |version, compatibility_context| {
            Ok(Requested::Supported {
                version,
                compatibility_context,
            })
        };
        assert_eq!(parse_version("1.10"), supported(Version::V110, true));
        assert_eq!(parse_version("1.20"), supported(Version::V120, true));
        assert_eq!(
            parse_version("1.20 compatibility"),
            supported(Version::V120, true)
        );
        assert_eq!(parse_version("1.30"), supported(Version::V130, true));
        assert_eq!(parse_version("1.40"), supported(Version::V140, false));
        assert_eq!(parse_version("1.50"), supported(Version::V150, false));
        assert_eq!(
            parse_version("1.40compatibility"),
            supported(Version::V140, true)
        );
        assert_eq!(parse_version("3.30 core"), supported(Version::V330, false));
        assert_eq!(
            parse_version("1.50compatibility"),
            supported(Version::V150, true)
        );
        assert_eq!(parse_version("4.00"), Ok(Requested::Other));
        assert_eq!(parse_version("1.00"), Ok(Requested::Other));
        assert_eq!(parse_version("3.00 es"), Ok(Requested::Other));
        assert_eq!(parse_version("1.10 es"), Ok(Requested::Other));
        assert_eq!(parse_version("4.60 core"), Ok(Requested::Other));
        for bad in [
            "",
            "1",
            "1.1",
            "a.bc",
            "1.10 gl",
            "1.10 es x",
            "110",
            "-1.10",
            "999.10",
        ] {
            assert!(parse_version(bad).is_err(), "{bad:?}");
        }
        assert_eq!(
            parse_version("x").unwrap_err(),
            "Ill-formed GLSL version number: x"
        );
    }

    #[test]
    fn extensions_are_supported_where_the_compiler_offers_them() {
        for v in [Version::V110, Version::V120, Version::V150, Version::V330] {
            assert!(supported("GL_ARB_arrays_of_arrays", v), "{v:?}");
        }
        assert!(!supported("GL_EXT_texture_array", Version::V120));
        assert!(supported("GL_EXT_texture_array", Version::V130));
        assert!(supported("GL_ARB_shading_language_420pack", Version::V120));
        assert!(supported(
            "GL_ARB_shader_storage_buffer_object",
            Version::V110
        ));
        assert!(!supported("GL_ARB_gpu_shader5", Version::V330));
    }

    #[test]
    fn verdicts() {
        let v = |expect, ok| verdict(expect, false, Stage::Vertex, "t.vert", ok, "");
        assert_eq!(v(Expect::Pass, true).verdict, Verdict::Pass);
        assert_eq!(v(Expect::Fail, false).verdict, Verdict::Pass);
        assert_eq!(v(Expect::Pass, false).verdict, Verdict::Fail);
        assert_eq!(v(Expect::Fail, true).verdict, Verdict::Fail);
        assert_eq!(v(Expect::Pass, true).message, "");
        assert_eq!(
            v(Expect::Pass, false).message,
            "Failed to compile vertex shader t.vert: (no compiler output)"
        );
        let linked = verdict(Expect::Fail, true, Stage::Fragment, "t.frag", true, "");
        assert_eq!(
            linked.message,
            "Successfully compiled and linked fragment shader t.frag: (no compiler output)"
        );
        let logged = verdict(
            Expect::Fail,
            false,
            Stage::Fragment,
            "t.frag",
            false,
            "0:1(1): error: x\n",
        );
        assert_eq!(
            logged.message,
            "Info log of fragment shader t.frag:\n0:1(1): error: x"
        );
    }

    #[test]
    fn exit_codes_follow_piglit_report_result() {
        assert_eq!(Verdict::Pass.exit_code(), 0);
        assert_eq!(Verdict::Skip.exit_code(), 0);
        assert_eq!(Verdict::Fail.exit_code(), 1);
    }

    fn args(file: &str, version: &str, extensions: &[&str]) -> Args {
        Args {
            file: PathBuf::from(file),
            expect: Expect::Pass,
            version: version.to_string(),
            check_link: false,
            dummy_shader_include: false,
            shader_include_path: None,
            extensions: extensions.iter().map(|s| s.to_string()).collect(),
        }
    }

    #[test]
    fn skips_and_usage_failures_before_reading_the_file() {
        // None of these files exist: the verdict comes before reading.
        let e = |a: Args| evaluate(&a).verdict;
        assert_eq!(e(args("/none/t.vert", "3.00 es", &[])), Verdict::Skip);
        assert_eq!(e(args("/none/t.vert", "4.00", &[])), Verdict::Skip);
        assert_eq!(
            e(args("/none/t.vert", "1.20", &["GL_ARB_foo"])),
            Verdict::Skip
        );
        assert_eq!(e(args("/none/t.txt", "1.10", &[])), Verdict::Fail);
        assert_eq!(e(args("/none/t.vert", "one", &[])), Verdict::Fail);
        let mut inc = args("/none/t.vert", "1.20", &[]);
        inc.dummy_shader_include = true;
        assert_eq!(e(inc), Verdict::Skip);
        // `!EXT` holds, so the test proceeds to reading the file.
        let missing = evaluate(&args("/none/t.vert", "1.20", &["!GL_ARB_foo"]));
        assert_eq!(missing.verdict, Verdict::Fail);
        assert!(
            missing.message.starts_with("cannot read `/none/t.vert'"),
            "{}",
            missing.message
        );
        // Tessellation shaders are compiled (and so read) too.
        let tess = evaluate(&args(
            "/none/t.tesc",
            "1.50",
            &["GL_ARB_tessellation_shader"],
        ));
        assert_eq!(tess.verdict, Verdict::Fail);
        assert!(tess.message.starts_with("cannot read"), "{}", tess.message);
    }
}
