//! `shaderbox check`: compile shader files (and optionally link them into
//! one program) and report the diagnostics.
//!
//! Exit status ([`Exit`]): 0 when every file compiles (and the program
//! links, with `--link`), 1 when one does not, 2 on misuse (bad arguments,
//! unreadable file, unknown stage), 3 when the compiler panicked (a bug,
//! reported as an internal error instead of a crash).
//!
//! Output goes to stdout in the chosen format; problems with the command
//! itself go to stderr.

use crate::guard::guarded;
use crate::input::{read_source, stage_from_path, StageGuess};
use crate::Exit;
use glsl::ir::{InputPrimitive, OutputPrimitive};
use glsl::link::{LinkDiagnostic, LinkOptions, Program};
use glsl::{CompileOptions, Diagnostic, Severity, Shader, SourceMap, Stage, Version};
use serde::Serialize;
use std::io::{IsTerminal, Write};
use std::path::PathBuf;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Also link all the files into one program (vertex, geometry and
    /// fragment stages, each made of one or more shader objects).
    #[arg(long)]
    pub link: bool,

    /// The GLSL version of files without a `#version` directive: 110, 120,
    /// 130, 140, 150 or 330.
    #[arg(long, value_parser = parse_glsl_version, value_name = "VERSION")]
    pub glsl_version: Option<Version>,

    /// The stage of every file, instead of guessing it from the extension
    /// (.vert/.vs: vertex, .frag/.fs: fragment).
    #[arg(long, value_enum)]
    pub stage: Option<StageArg>,

    /// How to print diagnostics: a rich report with source excerpts, the
    /// GL info log (`0:LINE(COL): error: ...`), or a JSON array.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,

    /// Colours in the text format (auto: when stdout is a terminal and
    /// NO_COLOR is unset).
    #[arg(long, value_enum, default_value_t = ColorChoice::Auto)]
    pub color: ColorChoice,

    /// With `--link`: the program's GEOMETRY_INPUT_TYPE_EXT for a
    /// geometry shader in GL_EXT/ARB_geometry_shader4's form (as
    /// glProgramParameteriEXT sets it): points, lines, lines_adjacency,
    /// triangles (the initial value) or triangles_adjacency.
    #[arg(long, value_parser = parse_input_primitive, value_name = "PRIMITIVE", requires = "link")]
    pub geometry_input: Option<InputPrimitive>,

    /// With `--link`: GEOMETRY_OUTPUT_TYPE_EXT: points, line_strip or
    /// triangle_strip (the initial value).
    #[arg(long, value_parser = parse_output_primitive, value_name = "PRIMITIVE", requires = "link")]
    pub geometry_output: Option<OutputPrimitive>,

    /// With `--link`: GEOMETRY_VERTICES_OUT_EXT (initially 0, which such a
    /// program cannot link with).
    #[arg(long, value_name = "N", requires = "link")]
    pub geometry_vertices_out: Option<u32>,

    /// Shader files to compile.
    #[arg(required = true, value_name = "FILE")]
    pub files: Vec<PathBuf>,
}

impl Args {
    /// The program parameters the link uses: the initial ones, changed
    /// by the `--geometry-*` options.
    fn link_options(&self) -> LinkOptions {
        let mut o = LinkOptions::default();
        if let Some(p) = self.geometry_input {
            o.geometry.input = p;
        }
        if let Some(p) = self.geometry_output {
            o.geometry.output = p;
        }
        if let Some(n) = self.geometry_vertices_out {
            o.geometry.vertices_out = n;
        }
        o
    }
}

fn parse_input_primitive(text: &str) -> Result<InputPrimitive, String> {
    InputPrimitive::from_name(text).ok_or_else(|| {
        let names: Vec<&str> = InputPrimitive::ALL.iter().map(|p| p.name()).collect();
        format!("`{text}' is not one of: {}", names.join(", "))
    })
}

fn parse_output_primitive(text: &str) -> Result<OutputPrimitive, String> {
    OutputPrimitive::from_name(text)
        .ok_or_else(|| format!("`{text}' is not one of: points, line_strip, triangle_strip"))
}

/// `--glsl-version N`: one of the versions the compiler knows.
fn parse_glsl_version(text: &str) -> Result<Version, String> {
    text.parse::<u32>()
        .ok()
        .and_then(Version::from_number)
        .ok_or_else(|| {
            let known: Vec<String> = Version::ALL
                .iter()
                .map(|v| v.number().to_string())
                .collect();
            format!(
                "`{text}' is not a GLSL version shaderbox knows ({})",
                known.join(", ")
            )
        })
}

#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum StageArg {
    Vertex,
    TessControl,
    TessEvaluation,
    Geometry,
    Fragment,
    Compute,
}

impl From<StageArg> for Stage {
    fn from(s: StageArg) -> Stage {
        match s {
            StageArg::Vertex => Stage::Vertex,
            StageArg::TessControl => Stage::TessControl,
            StageArg::TessEvaluation => Stage::TessEvaluation,
            StageArg::Geometry => Stage::Geometry,
            StageArg::Fragment => Stage::Fragment,
            StageArg::Compute => Stage::Compute,
        }
    }
}

#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Text,
    Json,
    Infolog,
}

#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorChoice {
    Auto,
    Always,
    Never,
}

/// One file to compile.
struct Input {
    path: PathBuf,
    stage: Stage,
    text: String,
}

/// Everything `check` found, ready to print.
pub struct Report {
    pub shaders: Vec<Shader>,
    /// `None` without `--link` or when a shader failed to compile.
    pub linked: Option<Program>,
}

impl Report {
    fn ok(&self) -> bool {
        self.shaders.iter().all(Shader::ok) && self.linked.as_ref().is_none_or(Program::ok)
    }
}

/// Runs `shaderbox check`.
pub fn run(args: &Args) -> Exit {
    match check(args) {
        Ok(report) => {
            let color = use_color(args.color);
            let out = match guarded(|| render(&report, args.format, args.link, color)) {
                Ok(out) => out,
                Err(p) => {
                    eprintln!(
                        "shaderbox: internal error while rendering diagnostics: {}\nThis is a \
                         bug in shaderbox; please report it with the shaders.",
                        p.message
                    );
                    return Exit::Internal;
                }
            };
            let mut stdout = std::io::stdout().lock();
            // A closed pipe (`shaderbox check ... | head`) is not an error
            // worth reporting; the exit status still says what happened.
            let _ = stdout.write_all(out.as_bytes());
            let _ = stdout.flush();
            if report.ok() {
                Exit::Ok
            } else {
                Exit::Failed
            }
        }
        Err((exit, message)) => {
            eprintln!("shaderbox: {message}");
            exit
        }
    }
}

/// Reads, compiles and links; an `Err` is the exit status and a message
/// for stderr.
fn check(args: &Args) -> Result<Report, (Exit, String)> {
    let inputs = read_inputs(args)?;
    let mut shaders = Vec::with_capacity(inputs.len());
    for input in &inputs {
        let name = input.path.display().to_string();
        let opts = CompileOptions {
            name: name.clone(),
            default_version: args.glsl_version,
            ..CompileOptions::new(input.stage)
        };
        let shader = guarded(|| glsl::compile(&[input.text.as_str()], &opts)).map_err(|p| {
            (
                Exit::Internal,
                format!(
                    "internal error while compiling `{name}': {}\nThis is a bug in shaderbox; \
                     please report it with the shader.",
                    p.message
                ),
            )
        })?;
        shaders.push(shader);
    }
    let mut linked = None;
    if args.link && shaders.iter().all(Shader::ok) {
        let refs: Vec<&Shader> = shaders.iter().collect();
        let options = args.link_options();
        let program = guarded(|| glsl::link::link_with(&refs, &options)).map_err(|p| {
            (
                Exit::Internal,
                format!(
                    "internal error while linking: {}\nThis is a bug in shaderbox; please report \
                     it with the shaders.",
                    p.message
                ),
            )
        })?;
        linked = Some(program);
    }
    Ok(Report { shaders, linked })
}

/// Works out every file's stage and reads them all before compiling
/// anything, so misuse is reported before any output.
fn read_inputs(args: &Args) -> Result<Vec<Input>, (Exit, String)> {
    let mut inputs = Vec::with_capacity(args.files.len());
    for path in &args.files {
        let stage = match (args.stage, stage_from_path(path)) {
            (Some(s), _) => s.into(),
            (None, StageGuess::Known(s)) => s,
            (None, StageGuess::Unknown) => {
                return Err((
                    Exit::Misuse,
                    format!(
                    "cannot tell the stage of `{}' from its name; name it .vert, .tesc, .tese, .geom, .frag or .comp, \
                         or pass --stage vertex|tess-control|tess-evaluation|geometry|fragment|compute",
                    path.display()
                ),
                ))
            }
        };
        let text = read_source(path).map_err(|e| (Exit::Misuse, e))?;
        inputs.push(Input {
            path: path.clone(),
            stage,
            text,
        });
    }
    Ok(inputs)
}

fn use_color(choice: ColorChoice) -> bool {
    match choice {
        ColorChoice::Always => true,
        ColorChoice::Never => false,
        ColorChoice::Auto => {
            std::io::stdout().is_terminal()
                && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
                && std::env::var("TERM").map_or(true, |t| t != "dumb")
        }
    }
}

/// Renders a report in the chosen format.
pub fn render(report: &Report, format: Format, link_requested: bool, color: bool) -> String {
    match format {
        Format::Text => render_text(report, link_requested, color),
        Format::Infolog => render_infolog(report),
        Format::Json => render_json(report),
    }
}

fn count(diags: &[Diagnostic], severity: Severity) -> usize {
    diags.iter().filter(|d| d.severity == severity).count()
}

fn plural(n: usize, what: &str) -> String {
    if n == 1 {
        format!("1 {what}")
    } else {
        format!("{n} {what}s")
    }
}

/// The rich rendering of every shader's diagnostics, then one status line
/// per file (and for the program).
fn render_text(report: &Report, link_requested: bool, color: bool) -> String {
    let mut out = String::new();
    for s in &report.shaders {
        out.push_str(&s.render(color));
    }
    if let Some(program) = &report.linked {
        for d in &program.diagnostics {
            let source = link_source(report, d);
            out.push_str(&glsl::diag::render_terminal(
                std::slice::from_ref(&d.diagnostic),
                source.map_or(&SourceMap::default(), |s| &s.source),
                color,
            ));
        }
    }
    for s in &report.shaders {
        let errors = count(&s.diagnostics, Severity::Error);
        let warnings = count(&s.diagnostics, Severity::Warning);
        let status = if s.ok() { "ok" } else { "failed" };
        let mut line = format!(
            "{status}: {} ({} shader, GLSL {})",
            s.source.name,
            s.stage.name(),
            s.language.version.dotted()
        );
        if errors > 0 || warnings > 0 {
            let mut parts = Vec::new();
            if errors > 0 {
                parts.push(plural(errors, "error"));
            }
            if warnings > 0 {
                parts.push(plural(warnings, "warning"));
            }
            line.push_str(&format!(": {}", parts.join(", ")));
        }
        out.push_str(&line);
        out.push('\n');
    }
    if link_requested {
        match &report.linked {
            Some(p) if p.ok() => out.push_str("ok: program linked\n"),
            Some(_) => out.push_str("failed: program did not link\n"),
            None => out.push_str("not linked: a shader failed to compile\n"),
        }
    }
    out
}

/// The shader object a link diagnostic points into, if any.
fn link_source<'a>(report: &'a Report, d: &LinkDiagnostic) -> Option<&'a Shader> {
    d.shader.and_then(|i| report.shaders.get(i))
}

/// The GL info logs; with several files, each log that is not empty comes
/// after a `==> FILE <==` header.
fn render_infolog(report: &Report) -> String {
    let several = report.shaders.len() > 1 || report.linked.is_some();
    let mut out = String::new();
    let mut section = |title: &str, log: &str| {
        if log.is_empty() {
            return;
        }
        if several {
            out.push_str(&format!("==> {title} <==\n"));
        }
        out.push_str(log);
        if !log.ends_with('\n') {
            out.push('\n');
        }
    };
    for s in &report.shaders {
        section(&s.source.name, &s.info_log());
    }
    if let Some(l) = &report.linked {
        section("program", l.info_log());
    }
    out
}

/// One diagnostic in the JSON format.
#[derive(Serialize)]
struct JsonDiagnostic<'a> {
    /// The file, or `null` for a link diagnostic about the whole program.
    file: Option<&'a str>,
    /// "vertex" or "fragment"; `null` with `file`.
    stage: Option<&'static str>,
    severity: Severity,
    code: &'static str,
    message: &'a str,
    /// 1-based logical line (after `#line`), `null` without a location.
    line: Option<u32>,
    /// 1-based column in bytes.
    column: Option<u32>,
    /// The GLSL source-string number (0 unless `#line` changes it).
    source_string: Option<u32>,
    notes: &'a [String],
}

/// A JSON array of every diagnostic, files in command-line order.
fn render_json(report: &Report) -> String {
    let mut all = Vec::new();
    for s in &report.shaders {
        for d in &s.diagnostics {
            let r = d.resolve(&s.source);
            all.push(JsonDiagnostic {
                file: Some(r.file),
                stage: Some(s.stage.name()),
                severity: r.severity,
                code: r.code,
                message: r.message,
                line: r.loc.map(|l| l.line),
                column: r.loc.map(|l| l.column),
                source_string: r.loc.map(|l| l.source),
                notes: r.notes,
            });
        }
    }
    if let Some(program) = &report.linked {
        for d in &program.diagnostics {
            let shader = link_source(report, d);
            let loc = shader.and_then(|s| d.diagnostic.resolve(&s.source).loc);
            all.push(JsonDiagnostic {
                file: shader.map(|s| s.source.name.as_str()),
                stage: shader.map(|s| s.stage.name()),
                severity: d.diagnostic.severity,
                code: d.diagnostic.code.as_str(),
                message: &d.diagnostic.message,
                line: loc.map(|l| l.line),
                column: loc.map(|l| l.column),
                source_string: loc.map(|l| l.source),
                notes: &d.diagnostic.notes,
            });
        }
    }
    // Serializing plain strings and numbers cannot fail.
    let mut text = serde_json::to_string_pretty(&all).unwrap_or_else(|_| String::from("[]"));
    text.push('\n');
    text
}

#[cfg(test)]
mod tests {
    use super::*;
    use glsl::{Code, SourceMap, Span};

    /// A shader as the compiler would return it, built by hand so the
    /// renderers can be tested on their own.
    fn shader(name: &str, text: &str, diagnostics: Vec<Diagnostic>) -> Shader {
        Shader {
            stage: Stage::Fragment,
            source: SourceMap::new(name, text),
            language: glsl::Language::new(Version::V110, true),
            module: None,
            diagnostics,
        }
    }

    fn broken() -> Shader {
        let text = "void main()\n{\n  x = 1.0;\n}\n";
        let at = text.find('x').unwrap() as u32;
        let d = Diagnostic::error(Code::Undeclared, Span::new(at, at + 1), "`x' undeclared")
            .with_note("did you mean `y'?");
        shader("bad.frag", text, vec![d])
    }

    #[test]
    fn json_has_resolved_locations() {
        let report = Report {
            shaders: vec![broken()],
            linked: None,
        };
        let out = render(&report, Format::Json, false, false);
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let d = &v[0];
        assert_eq!(d["file"], "bad.frag");
        assert_eq!(d["stage"], "fragment");
        assert_eq!(d["severity"], "error");
        assert_eq!(d["code"], "E0201");
        assert_eq!(d["message"], "`x' undeclared");
        assert_eq!(d["line"], 3);
        assert_eq!(d["column"], 3);
        assert_eq!(d["source_string"], 0);
        assert_eq!(d["notes"][0], "did you mean `y'?");
        assert_eq!(v.as_array().unwrap().len(), 1);
    }

    #[test]
    fn json_link_diagnostics_name_their_shader_object() {
        let report = Report {
            shaders: vec![broken()],
            linked: Some(Program {
                info_log: String::from("error: no `main'\n"),
                diagnostics: vec![
                    LinkDiagnostic {
                        shader: None,
                        diagnostic: Diagnostic::error(Code::LinkNoMain, None, "no `main'"),
                    },
                    LinkDiagnostic {
                        shader: Some(0),
                        diagnostic: Diagnostic::error(
                            Code::LinkUndefinedFunction,
                            None,
                            "`f' undefined",
                        ),
                    },
                ],
                ..Program::default()
            }),
        };
        let v: serde_json::Value =
            serde_json::from_str(&render(&report, Format::Json, true, false)).unwrap();
        assert_eq!(v[0]["code"], "E0201");
        assert_eq!(v[1]["code"], "E0301");
        assert!(v[1]["file"].is_null());
        assert!(v[1]["line"].is_null());
        assert_eq!(v[2]["code"], "E0303");
        assert_eq!(v[2]["file"], "bad.frag");
        assert_eq!(v[2]["stage"], "fragment");
        assert_eq!(v.as_array().unwrap().len(), 3);
    }

    #[test]
    fn infolog_is_the_gl_log_and_headed_only_for_several_files() {
        let one = Report {
            shaders: vec![broken()],
            linked: None,
        };
        assert_eq!(
            render(&one, Format::Infolog, false, false),
            "0:3(3): error: `x' undeclared\n    note: did you mean `y'?\n"
        );
        let two = Report {
            shaders: vec![broken(), shader("good.frag", "void main() {}\n", vec![])],
            linked: None,
        };
        let out = render(&two, Format::Infolog, false, false);
        assert!(out.starts_with("==> bad.frag <==\n0:3(3): error"), "{out}");
        assert!(!out.contains("good.frag"), "{out}");
    }

    #[test]
    fn text_has_excerpt_and_status_lines() {
        let report = Report {
            shaders: vec![broken()],
            linked: None,
        };
        let out = render(&report, Format::Text, true, false);
        assert!(out.contains("bad.frag:3:3"), "{out}");
        assert!(
            out.contains("failed: bad.frag (fragment shader, GLSL 1.10): 1 error\n"),
            "{out}"
        );
        assert!(
            out.ends_with("not linked: a shader failed to compile\n"),
            "{out}"
        );
        assert!(!out.contains('\x1b'), "{out}");
        let colored = render(&report, Format::Text, false, true);
        assert!(colored.contains('\x1b'), "{colored}");
    }

    #[test]
    fn report_ok_needs_compile_and_link() {
        let failed_compile = Report {
            shaders: vec![broken()],
            linked: None,
        };
        assert!(!failed_compile.ok());
        let failed_link = Report {
            shaders: vec![],
            linked: Some(Program {
                diagnostics: vec![LinkDiagnostic {
                    shader: None,
                    diagnostic: Diagnostic::error(Code::LinkNoMain, None, "no `main'"),
                }],
                ..Program::default()
            }),
        };
        assert!(!failed_link.ok());
        let nothing_wrong = Report {
            shaders: vec![],
            linked: None,
        };
        assert!(nothing_wrong.ok());
    }
}
