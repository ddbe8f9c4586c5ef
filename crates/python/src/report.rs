//! Compile and link reports as plain data: what `shaderbox.check`,
//! `shaderbox.CompileError` and `shaderbox.LinkError` carry to Python.
//!
//! The compiler's diagnostics are resolved to (line, column, source
//! string) here, and rendered both ways the compiler knows: the rich text
//! with the source line and a caret, and the GL info log.

use glsl::link::Program;
use glsl::{CompileOptions, Diagnostic, Shader, SourceMap, Stage, Version};

/// One diagnostic, located.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Located {
    /// "vertex" or "fragment"; `None` for a link diagnostic about the whole
    /// program.
    pub stage: Option<&'static str>,
    /// "error", "warning" or "note".
    pub severity: &'static str,
    /// Stable code, e.g. "E0201".
    pub code: &'static str,
    pub message: String,
    /// 1-based logical line (after `#line`); `None` without a location.
    pub line: Option<u32>,
    /// 1-based column in bytes.
    pub column: Option<u32>,
    /// GLSL source-string number.
    pub source_string: Option<u32>,
    pub notes: Vec<String>,
}

/// The result of compiling one shader or linking a program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Report {
    pub ok: bool,
    pub diagnostics: Vec<Located>,
    /// The rich rendering (source excerpt and caret), no colour.
    pub text: String,
    /// The GL info log (`0:LINE(COL): error: ...`).
    pub info_log: String,
}

/// Parses a stage name as the Python API spells it.
pub fn parse_stage(name: &str) -> Option<Stage> {
    match name.trim().to_ascii_lowercase().as_str() {
        "vertex" | "vert" | "vs" => Some(Stage::Vertex),
        "tess_control" | "tessellation control" | "tesc" | "tcs" => Some(Stage::TessControl),
        "tess_evaluation" | "tessellation evaluation" | "tese" | "tes" => {
            Some(Stage::TessEvaluation)
        }
        "geometry" | "geom" | "gs" => Some(Stage::Geometry),
        "fragment" | "frag" | "fs" => Some(Stage::Fragment),
        "compute" | "comp" | "cs" => Some(Stage::Compute),
        _ => None,
    }
}

fn locate(d: &Diagnostic, map: &SourceMap, stage: Option<Stage>) -> Located {
    let r = d.resolve(map);
    Located {
        stage: stage.map(|s| s.name()),
        severity: r.severity.as_str(),
        code: r.code,
        message: r.message.to_string(),
        line: r.loc.map(|l| l.line),
        column: r.loc.map(|l| l.column),
        source_string: r.loc.map(|l| l.source),
        notes: r.notes.to_vec(),
    }
}

/// Compiles `source` as `stage`, naming it `name` in the rendered text.
pub fn compile(source: &str, stage: Stage, version: Option<Version>, name: &str) -> Shader {
    compile_for(source, stage, version, name, true)
}

/// [`compile`] for a context that offers the compatibility profile or
/// not (a core context: `#version 140` shaders are core ones and
/// `#version 150 compatibility` is refused; see
/// `glsl::CompileOptions::compatibility_context`).
pub fn compile_for(
    source: &str,
    stage: Stage,
    version: Option<Version>,
    name: &str,
    compatibility_context: bool,
) -> Shader {
    let mut opts = CompileOptions::new(stage);
    opts.name = name.to_string();
    opts.default_version = version;
    opts.compatibility_context = compatibility_context;
    glsl::compile(&[source], &opts)
}

/// The report of one compiled shader.
pub fn compile_report(shader: &Shader) -> Report {
    Report {
        ok: shader.ok(),
        diagnostics: shader
            .diagnostics
            .iter()
            .map(|d| locate(d, &shader.source, Some(shader.stage)))
            .collect(),
        text: shader.render(false),
        info_log: shader.info_log(),
    }
}

/// Links compiled shaders (each must have compiled) and reports.
pub fn link_report(shaders: &[&Shader]) -> Report {
    let program: Program = glsl::link::link(shaders);
    let empty = SourceMap::default();
    let mut diagnostics = Vec::new();
    let mut text = String::new();
    for d in &program.diagnostics {
        let shader = d.shader.and_then(|i| shaders.get(i));
        let map = shader.map_or(&empty, |s| &s.source);
        let mut located = locate(&d.diagnostic, map, shader.map(|s| s.stage));
        if shader.is_none() {
            (located.line, located.column, located.source_string) = (None, None, None);
        }
        diagnostics.push(located);
        text.push_str(&glsl::diag::render_terminal(
            std::slice::from_ref(&d.diagnostic),
            map,
            false,
        ));
    }
    Report {
        ok: program.ok(),
        diagnostics,
        text,
        info_log: program.info_log().to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compile_error_is_located_and_rendered() {
        let src = "void main() {\n  gl_FragColor = vec4(1.0) + undefined_thing;\n}\n";
        let s = compile(src, Stage::Fragment, None, "fragment_shader");
        let r = compile_report(&s);
        assert!(!r.ok);
        let d = r.diagnostics.first().expect("a diagnostic");
        assert_eq!(d.severity, "error");
        assert_eq!(d.stage, Some("fragment"));
        assert_eq!(d.line, Some(2));
        assert!(d.column.is_some_and(|c| c > 1), "{d:?}");
        assert!(d.message.contains("undefined_thing"), "{}", d.message);
        assert!(r.text.contains("fragment_shader"), "{}", r.text);
        assert!(r.text.contains("undefined_thing"), "{}", r.text);
        assert!(r.info_log.starts_with("0:2("), "{}", r.info_log);
    }

    #[test]
    fn version_default_changes_what_compiles() {
        // Array constructors are GLSL 1.20.
        let src = "void main() { float a[2] = float[2](1.0, 2.0); gl_FragColor = vec4(a[1]); }";
        let v110 = compile(src, Stage::Fragment, Some(Version::V110), "f");
        let v120 = compile(src, Stage::Fragment, Some(Version::V120), "f");
        assert!(!v110.ok());
        assert!(v120.ok(), "{}", v120.info_log());
    }

    #[test]
    fn link_error_names_the_problem() {
        let vs = compile(
            "void main() { gl_Position = ftransform(); }",
            Stage::Vertex,
            None,
            "vertex_shader",
        );
        let fs = compile(
            "varying vec3 never_written;\nvoid main() { gl_FragColor = vec4(never_written, 1.0); }",
            Stage::Fragment,
            None,
            "fragment_shader",
        );
        assert!(vs.ok() && fs.ok());
        let r = link_report(&[&vs, &fs]);
        assert!(!r.ok);
        assert!(!r.diagnostics.is_empty());
        assert!(
            r.diagnostics
                .iter()
                .any(|d| d.message.contains("never_written")),
            "{:?}",
            r.diagnostics
        );
        assert!(!r.info_log.is_empty());
        assert!(r.text.contains("never_written"), "{}", r.text);
        let fine = link_report(&[&vs]);
        assert!(fine.ok, "{:?}", fine.diagnostics);
    }

    #[test]
    fn limits_give_the_compilers_errors() {
        // What `shaderbox.check` and `CompileError` carry for the limits is
        // the compiler's own message, as on the command line and in the C
        // ABI's info log: a source over the size limit, a call chain past
        // the call depth, nesting past the parser's depth.
        let big = " ".repeat(glsl::limits::MAX_SOURCE_BYTES + 1);
        let r = compile_report(&compile(&big, Stage::Fragment, None, "f"));
        assert!(!r.ok);
        assert_eq!(r.diagnostics[0].message, glsl::source_too_large_message());
        assert_eq!(r.diagnostics[0].line, None);
        assert!(
            r.info_log.contains(&glsl::source_too_large_message()),
            "{}",
            r.info_log
        );

        let mut chain = String::from("float f0() { return 1.0; }\n");
        for i in 1..200 {
            chain += &format!("float f{i}() {{ return f{}(); }}\n", i - 1);
        }
        chain += "void main() { gl_FragColor = vec4(f199()); }\n";
        let r = compile_report(&compile(&chain, Stage::Fragment, None, "f"));
        assert!(!r.ok);
        assert!(
            r.diagnostics[0]
                .message
                .starts_with("function calls nested too deeply"),
            "{:?}",
            r.diagnostics
        );

        let deep = format!(
            "void main() {{ float x = {}1.0{}; }}",
            "(".repeat(100_000),
            ")".repeat(100_000)
        );
        let r = compile_report(&compile(&deep, Stage::Fragment, None, "f"));
        assert!(!r.ok);
        assert_eq!(r.diagnostics[0].message, "nesting too deep");
    }

    #[test]
    fn stage_names() {
        assert_eq!(parse_stage("Vertex"), Some(Stage::Vertex));
        assert_eq!(parse_stage("frag"), Some(Stage::Fragment));
        assert_eq!(parse_stage("geometry"), Some(Stage::Geometry));
        assert_eq!(parse_stage("comp"), Some(Stage::Compute));
        assert_eq!(parse_stage("tess_control"), Some(Stage::TessControl));
        assert_eq!(parse_stage("TESE"), Some(Stage::TessEvaluation));
        assert_eq!(parse_stage("tessellation"), None);
    }
}
