//! Diagnostics as data, and their two renderings.
//!
//! Every stage reports problems as [`Diagnostic`] values and keeps going, so
//! one compile lists every independent error. A diagnostic has a stable
//! [`Code`] (tests and tools match on it, never on the wording), a primary
//! span, optional secondary labels and free-form notes ("did you mean",
//! candidate overloads, the version a feature needs).
//!
//! Two renderers:
//! - [`render_info_log`]: the GL info-log format that drivers print and tools
//!   parse, `0:LINE(COL): error: MESSAGE` (Mesa's layout);
//! - [`render_terminal`]: a rich report with the source line and a caret,
//!   through `codespan-reporting` (chosen over hand-written code for its
//!   correct handling of tabs, wide characters and multi-line spans).

use crate::source::{Loc, SourceMap, Span};
use serde::Serialize;

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    Note,
    Warning,
    Error,
}

impl Severity {
    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Note => "note",
            Severity::Warning => "warning",
            Severity::Error => "error",
        }
    }
}

/// Stable identifiers of diagnostics, grouped by stage. The string form
/// (`E0101`...) appears in JSON output and golden tests.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum Code {
    // Preprocessor.
    PpSyntax,
    PpVersion,
    PpExtension,
    PpUserError,
    PpMacro,
    PpConditional,
    PpUnterminated,
    // Lexer and parser.
    LexInvalidChar,
    LexBadNumber,
    ReservedWord,
    Syntax,
    // Semantic analysis.
    Undeclared,
    Redeclared,
    TypeMismatch,
    NoMatchingOverload,
    AmbiguousOverload,
    NotAnLvalue,
    ReadOnly,
    BadQualifier,
    NotConstant,
    BadArraySize,
    IndexOutOfRange,
    BadSwizzle,
    BadConstructor,
    VersionTooLow,
    StageMismatch,
    MissingReturn,
    BadReturn,
    BadControlFlow,
    Unsupported,
    // Linker.
    LinkNoMain,
    LinkDuplicateMain,
    LinkUndefinedFunction,
    LinkDuplicateDefinition,
    LinkInterfaceMismatch,
    LinkVaryingNotWritten,
    LinkTooMany,
    LinkVersionMismatch,
    // Anything else (internal validation failures are reported, never panicked).
    Internal,
}

impl Code {
    /// A short stable string for the code.
    pub fn as_str(self) -> &'static str {
        use Code::*;
        match self {
            PpSyntax => "E0001",
            PpVersion => "E0002",
            PpExtension => "E0003",
            PpUserError => "E0004",
            PpMacro => "E0005",
            PpConditional => "E0006",
            PpUnterminated => "E0007",
            LexInvalidChar => "E0101",
            LexBadNumber => "E0102",
            ReservedWord => "E0103",
            Syntax => "E0104",
            Undeclared => "E0201",
            Redeclared => "E0202",
            TypeMismatch => "E0203",
            NoMatchingOverload => "E0204",
            AmbiguousOverload => "E0205",
            NotAnLvalue => "E0206",
            ReadOnly => "E0207",
            BadQualifier => "E0208",
            NotConstant => "E0209",
            BadArraySize => "E0210",
            IndexOutOfRange => "E0211",
            BadSwizzle => "E0212",
            BadConstructor => "E0213",
            VersionTooLow => "E0214",
            StageMismatch => "E0215",
            MissingReturn => "E0216",
            BadReturn => "E0217",
            BadControlFlow => "E0218",
            Unsupported => "E0219",
            LinkNoMain => "E0301",
            LinkDuplicateMain => "E0302",
            LinkUndefinedFunction => "E0303",
            LinkDuplicateDefinition => "E0304",
            LinkInterfaceMismatch => "E0305",
            LinkVaryingNotWritten => "E0306",
            LinkTooMany => "E0307",
            LinkVersionMismatch => "E0308",
            Internal => "E0900",
        }
    }
}

/// A secondary label: another place that explains the error.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Label {
    pub span: Span,
    pub message: String,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Diagnostic {
    pub severity: Severity,
    pub code: Code,
    pub message: String,
    /// Where the problem is. `None` for whole-program problems (link errors
    /// such as "no main").
    pub span: Option<Span>,
    pub labels: Vec<Label>,
    pub notes: Vec<String>,
}

impl Diagnostic {
    pub fn error(code: Code, span: impl Into<Option<Span>>, message: impl Into<String>) -> Self {
        Diagnostic {
            severity: Severity::Error,
            code,
            message: message.into(),
            span: span.into(),
            labels: Vec::new(),
            notes: Vec::new(),
        }
    }

    pub fn warning(code: Code, span: impl Into<Option<Span>>, message: impl Into<String>) -> Self {
        Diagnostic {
            severity: Severity::Warning,
            ..Diagnostic::error(code, span, message)
        }
    }

    pub fn with_label(mut self, span: Span, message: impl Into<String>) -> Self {
        self.labels.push(Label {
            span,
            message: message.into(),
        });
        self
    }

    pub fn with_note(mut self, note: impl Into<String>) -> Self {
        self.notes.push(note.into());
        self
    }

    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}

/// A diagnostic with its location resolved, ready to serialize (the JSON
/// format of `shaderbox check --format json`).
#[derive(Clone, Debug, Serialize)]
pub struct ResolvedDiagnostic<'a> {
    pub file: &'a str,
    pub severity: Severity,
    pub code: &'static str,
    pub message: &'a str,
    pub loc: Option<Loc>,
    pub notes: &'a [String],
}

impl Diagnostic {
    pub fn resolve<'a>(&'a self, map: &'a SourceMap) -> ResolvedDiagnostic<'a> {
        ResolvedDiagnostic {
            file: &map.name,
            severity: self.severity,
            code: self.code.as_str(),
            message: &self.message,
            loc: self.span.map(|s| map.loc(s.start)),
            notes: &self.notes,
        }
    }
}

/// The GL info-log format, one line per diagnostic plus indented notes:
/// `0:12(5): error: ...`.
pub fn render_info_log(diags: &[Diagnostic], map: &SourceMap) -> String {
    let mut out = String::new();
    for d in diags {
        if let Some(span) = d.span {
            let loc = map.loc(span.start);
            out.push_str(&format!("{}:{}({}): ", loc.source, loc.line, loc.column));
        }
        out.push_str(d.severity.as_str());
        out.push_str(": ");
        out.push_str(&d.message);
        out.push('\n');
        for n in &d.notes {
            out.push_str("    note: ");
            out.push_str(n);
            out.push('\n');
        }
    }
    out
}

/// A rich terminal rendering with source lines and carets.
pub fn render_terminal(diags: &[Diagnostic], map: &SourceMap, color: bool) -> String {
    use codespan_reporting::diagnostic as cs;
    use codespan_reporting::files::SimpleFile;
    use codespan_reporting::term::{self, termcolor};

    let file = SimpleFile::new(map.name.as_str(), map.text());
    let config = term::Config::default();
    let mut buf = if color {
        termcolor::Buffer::ansi()
    } else {
        termcolor::Buffer::no_color()
    };
    for d in diags {
        let sev = match d.severity {
            Severity::Error => cs::Severity::Error,
            Severity::Warning => cs::Severity::Warning,
            Severity::Note => cs::Severity::Note,
        };
        let mut labels = Vec::new();
        let text_len = map.text().len();
        let clamp = |s: Span| {
            let a = (s.start as usize).min(text_len);
            let b = (s.end as usize).clamp(a, text_len);
            a..b
        };
        if let Some(span) = d.span {
            labels.push(cs::Label::primary((), clamp(span)));
        }
        for l in &d.labels {
            labels.push(cs::Label::secondary((), clamp(l.span)).with_message(l.message.clone()));
        }
        let mut notes = d.notes.clone();
        if let Some(span) = d.span {
            let loc = map.loc(span.start);
            let physical = map.physical_line(span.start) + 1;
            if loc.line != physical || loc.source != 0 {
                notes.push(format!(
                    "#line maps this to source {} line {}",
                    loc.source, loc.line
                ));
            }
        }
        let cd = cs::Diagnostic::new(sev)
            .with_message(d.message.clone())
            .with_code(d.code.as_str())
            .with_labels(labels)
            .with_notes(notes);
        // Writing into an in-memory buffer cannot fail; an error would only
        // lose this one rendering, so it is ignored rather than unwrapped.
        let _ = term::emit(&mut buf, &config, &file, &cd);
    }
    String::from_utf8_lossy(buf.as_slice()).into_owned()
}

/// The closest candidates to `name` among `candidates`, for "did you mean".
/// Names longer than [`crate::limits::MAX_SUGGESTED_NAME_LEN`] (on either
/// side) are not compared, so one call costs at most that length squared
/// per candidate.
pub fn did_you_mean<'a>(
    name: &str,
    candidates: impl IntoIterator<Item = &'a str>,
) -> Option<&'a str> {
    if !suggestible(name) {
        return None;
    }
    let mut best: Option<(f64, &str)> = None;
    for c in candidates {
        if c == name || !suggestible(c) {
            continue;
        }
        let score = strsim::jaro_winkler(name, c);
        let lev = strsim::levenshtein(&name.to_ascii_lowercase(), &c.to_ascii_lowercase());
        let ok = score > 0.85 || lev <= (name.len() / 4).max(1);
        if ok && best.is_none_or(|(s, _)| score > s) {
            best = Some((score, c));
        }
    }
    best.map(|(_, c)| c)
}

/// Whether a name is short enough to be compared for "did you mean"
/// ([`crate::limits::MAX_SUGGESTED_NAME_LEN`]).
pub fn suggestible(name: &str) -> bool {
    name.len() <= crate::limits::MAX_SUGGESTED_NAME_LEN
}

/// `word` with its indefinite article: "an int", "a vec3", "a uint".
pub fn with_article(word: &str) -> String {
    // `uint', `uvec3', `usampler2D' are said with a "you" sound: "a uint".
    let you = ["uint", "uvec", "usampler"]
        .iter()
        .any(|p| word.starts_with(p));
    let vowel = !you
        && word
            .chars()
            .next()
            .is_some_and(|c| matches!(c.to_ascii_lowercase(), 'a' | 'e' | 'i' | 'o' | 'u'));
    format!("{} {word}", if vowel { "an" } else { "a" })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn info_log_format() {
        let map = SourceMap::new("a.frag", "void main()\n{\n  x = 1;\n}\n");
        let at = map.text().find('x').unwrap() as u32;
        let d = Diagnostic::error(Code::Undeclared, Span::new(at, at + 1), "`x' undeclared")
            .with_note("did you mean `y'?");
        let log = render_info_log(&[d], &map);
        assert_eq!(
            log,
            "0:3(3): error: `x' undeclared\n    note: did you mean `y'?\n"
        );
    }

    #[test]
    fn terminal_has_caret() {
        let map = SourceMap::new("a.frag", "void main()\n{\n  x = 1;\n}\n");
        let d = Diagnostic::error(Code::Undeclared, Span::new(16, 17), "`x' undeclared");
        let out = render_terminal(&[d], &map, false);
        assert!(out.contains("a.frag:3:3"), "{out}");
        assert!(out.contains('^'), "{out}");
    }

    #[test]
    fn suggestions() {
        let c = ["gl_FragColor", "gl_FragCoord", "gl_FragData"];
        assert_eq!(did_you_mean("gl_FragColour", c), Some("gl_FragColor"));
        assert_eq!(did_you_mean("zzz", c), None);
    }

    #[test]
    fn long_names_get_no_suggestion() {
        let long = "a".repeat(crate::limits::MAX_SUGGESTED_NAME_LEN + 1);
        let near = format!("{long}b");
        assert_eq!(did_you_mean(&near, [long.as_str()]), None);
        assert_eq!(did_you_mean("ab", [long.as_str(), "abc"]), Some("abc"));
    }
}
