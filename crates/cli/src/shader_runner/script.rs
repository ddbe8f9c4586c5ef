//! The `.shader_test` file format: sections, requirements, vertex data.
//!
//! A script is a sequence of sections, each opened by a line starting with
//! `[`; text before the first section is ignored (piglit uses it for
//! comments). The sections shaderbox runs:
//!
//! - `[require]`: one requirement per line (see [`Requirement`]);
//! - `[vertex shader]`, `[geometry shader]`, `[fragment shader]`,
//!   `[compute shader]`: GLSL source, up to the next line that starts with
//!   `[`; several sections of one stage are several shader objects linked
//!   together;
//! - `[vertex shader passthrough]`: piglit's built-in vertex shader
//!   (`gl_Position = piglit_vertex`);
//! - `[vertex data]`: a table whose header names the attributes
//!   (`name/type/count`) and whose rows hold their values;
//! - `[test]`: the commands (parsed by [`super::command`]), to the end of the
//!   file.
//!
//! - `[geometry layout]`: GL_ARB_geometry_shader4's program parameters,
//!   one per line (`input type MODE`, `output type MODE`, `vertices out
//!   N`), set before the link;
//!
//! The sections of later GL versions or extensions (tessellation,
//! SPIR-V, ARB programs, shader includes, element lists) make the test a
//! skip: shaderbox implements OpenGL 3.3 (and GL 4.3's compute stage).

use super::scan;
use gl::enums::{GL_FLOAT, GL_INT, GL_UNSIGNED_INT};

/// A shader stage section.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    Vertex,
    Geometry,
    Fragment,
    Compute,
}

/// One shader section: its stage, source text and the line of its header.
#[derive(Clone, Debug, PartialEq)]
pub struct ShaderSection {
    pub stage: Stage,
    /// `None` for `[vertex shader passthrough]` (piglit's own source).
    pub source: Option<String>,
    pub line: usize,
}

/// A comparison operator of a requirement (`<`, `<=`, `==`/`=`, ...).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cmp {
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
}

impl Cmp {
    /// piglit's `compare(ref, value, cmp)`: `value CMP reference`.
    pub fn holds<T: PartialOrd>(self, reference: T, value: T) -> bool {
        match self {
            Cmp::Eq => value == reference,
            Cmp::Ne => value != reference,
            Cmp::Lt => value < reference,
            Cmp::Le => value <= reference,
            Cmp::Gt => value > reference,
            Cmp::Ge => value >= reference,
        }
    }

    pub fn as_str(self) -> &'static str {
        match self {
            Cmp::Eq => "==",
            Cmp::Ne => "!=",
            Cmp::Lt => "<",
            Cmp::Le => "<=",
            Cmp::Gt => ">",
            Cmp::Ge => ">=",
        }
    }

    /// An operator written alone (`probe ssbo`'s).
    pub fn parse(s: &str) -> Option<Cmp> {
        Cmp::scan(s)
            .filter(|(_, rest)| rest.is_empty())
            .map(|(c, _)| c)
    }

    /// Reads an operator as piglit does (`=` alone is not one).
    fn scan(s: &str) -> Option<(Cmp, &str)> {
        let s = scan::skip_space(s);
        for (text, cmp) in [
            ("==", Cmp::Eq),
            ("!=", Cmp::Ne),
            ("<=", Cmp::Le),
            (">=", Cmp::Ge),
            ("<", Cmp::Lt),
            (">", Cmp::Gt),
        ] {
            if let Some(rest) = s.strip_prefix(text) {
                return Some((cmp, rest));
            }
        }
        None
    }
}

/// A version requirement: `GL[ ES|CORE|COMPAT] CMP M.m` or `GLSL[ ES] CMP M.mm`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VersionReq {
    pub cmp: Cmp,
    /// GL: major * 10 + minor; GLSL: major * 100 + minor.
    pub number: u32,
    pub es: bool,
    pub core: bool,
    pub compat: bool,
}

/// One line of `[require]`.
#[derive(Clone, Debug, PartialEq)]
pub enum Requirement {
    Gl(VersionReq),
    Glsl(VersionReq),
    /// `GL_FOO` (needs the extension) or `!GL_FOO` (needs it absent).
    Extension {
        name: String,
        present: bool,
    },
    /// `GL_MAX_... CMP N` (the limits shader_runner checks by name) and
    /// `INT GL_ENUM CMP N`.
    Limit {
        name: String,
        cmp: Cmp,
        value: i32,
    },
    /// `SIZE W H`: the window size.
    Size(u32, u32),
    /// `depthbuffer`: the window needs a depth buffer.
    DepthBuffer,
    /// `rlimit N`: an address-space limit for the process (not applied).
    Rlimit(u64),
    /// `ignore_missing_uniforms`.
    IgnoreMissingUniforms,
    /// `SSO ENABLED`: each stage is linked into a separable program of
    /// its own and the programs are bound in a program pipeline
    /// (GL_ARB_separate_shader_objects, needed below GL 4.1).
    SeparateShaderObjects,
    /// Something shaderbox cannot provide (SPIR-V only, `SEPARABLE
    /// PROGRAM`, ...).
    Unsupported(String),
}

/// The `[vertex data]` table.
#[derive(Clone, Debug, PartialEq)]
pub struct VertexData {
    pub columns: Vec<Column>,
    /// Row-major values, `rows * stride` of them.
    pub values: Vec<f32>,
    pub rows: usize,
    pub line: usize,
}

/// A `[vertex data]` column: `name/type/count`.
#[derive(Clone, Debug, PartialEq)]
pub struct Column {
    pub name: String,
    /// GL_FLOAT, GL_INT or GL_UNSIGNED_INT; integer values are stored as
    /// their bits in [`VertexData::values`].
    pub ty: u32,
    pub components: usize,
    /// Offset of the column's first value within a row.
    pub offset: usize,
}

impl VertexData {
    /// Values per row.
    pub fn stride(&self) -> usize {
        self.columns.iter().map(|c| c.components).sum()
    }

    /// The values of one column, tightly packed.
    pub fn column_values(&self, column: &Column) -> Vec<f32> {
        let stride = self.stride();
        let mut out = Vec::with_capacity(self.rows * column.components);
        for r in 0..self.rows {
            let start = r * stride + column.offset;
            if let Some(vals) = self.values.get(start..start + column.components) {
                out.extend_from_slice(vals);
            }
        }
        out
    }
}

/// A parsed script, before its `[test]` commands are interpreted.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Script {
    pub requirements: Vec<(usize, Requirement)>,
    pub shaders: Vec<ShaderSection>,
    pub vertex_data: Option<VertexData>,
    /// The `[test]` lines: (line number, text).
    pub test_lines: Vec<(usize, String)>,
    /// Whether a `[test]` section exists.
    pub has_test: bool,
    /// Sections of later GL versions, with their line: the test is a skip.
    pub unsupported_sections: Vec<(usize, String)>,
    /// The `[geometry layout]` lines (GL_ARB_geometry_shader4's program
    /// parameters: `input type GL_TRIANGLES`, `output type GL_POINTS`,
    /// `vertices out 3`), with their line numbers.
    pub geometry_layout: Vec<(usize, String)>,
}

/// A malformed script: the message names the line.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{line}: {message}")]
pub struct ScriptError {
    pub line: usize,
    pub message: String,
}

fn err(line: usize, message: impl Into<String>) -> ScriptError {
    ScriptError {
        line,
        message: message.into(),
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Section {
    None,
    Require,
    Shader(Stage),
    Passthrough,
    VertexData,
    GeometryLayout,
    Test,
    Ignored,
}

/// Splits a script into its sections.
pub fn parse(text: &str) -> Result<Script, ScriptError> {
    let mut script = Script::default();
    let mut section = Section::None;
    let mut body = String::new();
    let mut body_line = 0;
    let mut vertex_data_lines: Vec<(usize, &str)> = Vec::new();
    let mut saw_require = false;

    // Lines keep their terminators so shader text is reproduced exactly.
    let mut number = 0;
    for raw in text.split_inclusive('\n') {
        number += 1;
        if raw.starts_with('[') {
            finish(
                &mut script,
                section,
                &mut body,
                body_line,
                &vertex_data_lines,
            )?;
            vertex_data_lines.clear();
            body_line = number;
            section = open_section(&mut script, raw, number)?;
            if section == Section::Require {
                saw_require = true;
            }
            if section == Section::Test {
                script.has_test = true;
                // Everything after [test] is commands, even lines with '['.
                let rest_start = text
                    .split_inclusive('\n')
                    .take(number)
                    .map(str::len)
                    .sum::<usize>();
                for (i, l) in text[rest_start..].split_inclusive('\n').enumerate() {
                    script
                        .test_lines
                        .push((number + 1 + i, l.trim_end_matches(['\n', '\r']).to_string()));
                }
                return finish_script(script, saw_require);
            }
            continue;
        }
        match section {
            Section::None | Section::Passthrough | Section::Ignored | Section::Test => {}
            Section::Require => {
                if let Some(req) = parse_requirement(raw, number)? {
                    script.requirements.push((number, req));
                }
            }
            Section::Shader(_) => body.push_str(raw),
            Section::VertexData => vertex_data_lines.push((number, raw)),
            Section::GeometryLayout => {
                let line = raw.trim();
                if !line.is_empty() && !line.starts_with('#') {
                    script.geometry_layout.push((number, line.to_string()));
                }
            }
        }
    }
    finish(
        &mut script,
        section,
        &mut body,
        body_line,
        &vertex_data_lines,
    )?;
    finish_script(script, saw_require)
}

fn finish_script(script: Script, saw_require: bool) -> Result<Script, ScriptError> {
    if !saw_require {
        return Err(err(1, "[require] section missing"));
    }
    Ok(script)
}

fn open_section(script: &mut Script, raw: &str, number: usize) -> Result<Section, ScriptError> {
    let header = raw.trim_end();
    let known = |name: &str| header.starts_with(name);
    Ok(if known("[require]") {
        Section::Require
    } else if known("[vertex shader passthrough]") {
        script.shaders.push(ShaderSection {
            stage: Stage::Vertex,
            source: None,
            line: number,
        });
        Section::Passthrough
    } else if known("[vertex shader]") {
        Section::Shader(Stage::Vertex)
    } else if known("[geometry shader]") {
        Section::Shader(Stage::Geometry)
    } else if known("[fragment shader]") {
        Section::Shader(Stage::Fragment)
    } else if known("[compute shader]") {
        Section::Shader(Stage::Compute)
    } else if known("[vertex data]") {
        Section::VertexData
    } else if known("[geometry layout]") {
        Section::GeometryLayout
    } else if known("[test]") {
        Section::Test
    } else if known("[vertex shader specializations]")
        || known("[fragment shader specializations]")
        || known("[vertex shader spirv]")
        || known("[fragment shader spirv]")
        || known("[geometry shader specializations]")
        || known("[geometry shader spirv]")
        || known("[compute shader specializations]")
        || known("[compute shader spirv]")
    {
        // Used only when running SPIR-V; the GLSL sections are run.
        Section::Ignored
    } else if [
        "[vertex program]",
        "[fragment program]",
        "[tessellation control shader",
        "[tessellation evaluation shader",
        "[shader include]",
        "[shader include paths]",
        "[elements]",
    ]
    .iter()
    .any(|n| known(n))
    {
        script
            .unsupported_sections
            .push((number, header.to_string()));
        Section::Ignored
    } else {
        return Err(err(
            number,
            format!("unknown section `{header}' in test script (missing closing ']'?)"),
        ));
    })
}

fn finish(
    script: &mut Script,
    section: Section,
    body: &mut String,
    body_line: usize,
    vertex_data_lines: &[(usize, &str)],
) -> Result<(), ScriptError> {
    match section {
        Section::Shader(stage) => script.shaders.push(ShaderSection {
            stage,
            source: Some(std::mem::take(body)),
            line: body_line,
        }),
        Section::VertexData => {
            if script.vertex_data.is_some() {
                return Err(err(body_line, "more than one [vertex data] section"));
            }
            script.vertex_data = parse_vertex_data(vertex_data_lines, body_line)?;
        }
        _ => {}
    }
    body.clear();
    Ok(())
}

/// Reads `M.m` (GL) or `M.mm` (GLSL) after an operator.
fn parse_version(rest: &str, line: usize, glsl: bool) -> Result<VersionReq, ScriptError> {
    let mut s = scan::skip_space(rest);
    let mut core = false;
    let mut compat = false;
    let mut es = false;
    for (word, flag) in [("CORE", 0), ("COMPAT", 1), ("ES", 2)] {
        let t = scan::skip_space(s);
        if let Some(r) = t.strip_prefix(word) {
            s = r;
            match flag {
                0 => core = true,
                1 => compat = true,
                _ => es = true,
            }
        }
    }
    let (cmp, s) = Cmp::scan(s).ok_or_else(|| {
        err(
            line,
            format!("invalid comparison operation at: {}", rest.trim()),
        )
    })?;
    let s = scan::skip_space(s);
    let digits = |t: &str| t.bytes().take_while(u8::is_ascii_digit).count();
    let nmaj = digits(s);
    let bad = || err(line, format!("invalid version string: {}", s.trim()));
    if nmaj == 0 || nmaj > 3 || s.as_bytes().get(nmaj) != Some(&b'.') {
        return Err(bad());
    }
    let minor_text = &s[nmaj + 1..];
    let nmin = digits(minor_text);
    if nmin == 0 || nmin > 3 {
        return Err(bad());
    }
    let major: u32 = s[..nmaj].parse().map_err(|_| bad())?;
    let minor: u32 = minor_text[..nmin].parse().map_err(|_| bad())?;
    if !minor_text[nmin..].trim().is_empty() {
        return Err(err(
            line,
            "unexpected characters following version comparison",
        ));
    }
    let number = if glsl {
        major * 100 + minor
    } else {
        major * 10 + minor
    };
    Ok(VersionReq {
        cmp,
        number,
        es,
        core,
        compat,
    })
}

/// Largest `SIZE` accepted (piglit's tests use at most a few hundred).
pub const MAX_WINDOW: i32 = 4096;

/// The limits `[require]` may name directly (piglit's table).
const LIMITS: &[&str] = &[
    "GL_MAX_VERTEX_OUTPUT_COMPONENTS",
    "GL_MAX_FRAGMENT_UNIFORM_COMPONENTS",
    "GL_MAX_VERTEX_UNIFORM_COMPONENTS",
    "GL_MAX_VERTEX_ATTRIBS",
    "GL_MAX_VARYING_COMPONENTS",
    "GL_NUM_PROGRAM_BINARY_FORMATS",
];

fn parse_requirement(raw: &str, line: usize) -> Result<Option<Requirement>, ScriptError> {
    let s = scan::skip_space(raw);
    let bad_limit = |rest: &str| {
        err(
            line,
            format!("invalid comparison value at: {}", rest.trim()),
        )
    };
    if let Some(rest) = s.strip_prefix("INT ") {
        let (name, rest) = scan::word(rest).ok_or_else(|| bad_limit(rest))?;
        let (cmp, rest) = Cmp::scan(rest).ok_or_else(|| {
            err(
                line,
                format!("invalid comparison operation at: {}", rest.trim()),
            )
        })?;
        let (value, _) = scan::scan_i32_base0(rest).ok_or_else(|| bad_limit(rest))?;
        return Ok(Some(Requirement::Limit {
            name: name.to_string(),
            cmp,
            value,
        }));
    }
    for name in LIMITS {
        if let Some(rest) = s.strip_prefix(name) {
            let (cmp, rest) = Cmp::scan(rest).ok_or_else(|| {
                err(
                    line,
                    format!("invalid comparison operation at: {}", rest.trim()),
                )
            })?;
            // atoi: no number reads as 0.
            let value = scan::scan_i32_dec(rest).map_or(0, |v| v.0);
            return Ok(Some(Requirement::Limit {
                name: (*name).to_string(),
                cmp,
                value,
            }));
        }
    }
    if s.starts_with("GL_") {
        let (name, _) = scan::word(s).unwrap_or((s.trim(), ""));
        return Ok(Some(Requirement::Extension {
            name: name.to_string(),
            present: true,
        }));
    }
    if let Some(rest) = s.strip_prefix('!') {
        if rest.starts_with("GL_") {
            let (name, _) = scan::word(rest).unwrap_or((rest.trim(), ""));
            return Ok(Some(Requirement::Extension {
                name: name.to_string(),
                present: false,
            }));
        }
        return Ok(None);
    }
    if let Some(rest) = s.strip_prefix("GLSL") {
        return parse_version(rest, line, true).map(|v| Some(Requirement::Glsl(v)));
    }
    if let Some(rest) = s.strip_prefix("GL") {
        return parse_version(rest, line, false).map(|v| Some(Requirement::Gl(v)));
    }
    if let Some(rest) = s.strip_prefix("SIZE") {
        let (v, _) = scan::scan_list(rest, 2, scan::scan_i32_base0);
        return match v.as_slice() {
            [w, h] if (1..=MAX_WINDOW).contains(w) && (1..=MAX_WINDOW).contains(h) => {
                Ok(Some(Requirement::Size(*w as u32, *h as u32)))
            }
            _ => Err(err(line, format!("invalid SIZE: {}", rest.trim()))),
        };
    }
    if s.starts_with("depthbuffer") {
        return Ok(Some(Requirement::DepthBuffer));
    }
    if let Some(rest) = s.strip_prefix("rlimit") {
        let (v, _) = scan::scan_i32_base0(rest)
            .ok_or_else(|| err(line, format!("invalid rlimit argument at: {}", rest.trim())))?;
        return Ok(Some(Requirement::Rlimit(u64::from(v as u32))));
    }
    if let Some(rest) = s.strip_prefix("SSO") {
        // piglit reads `SSO` followed by `ENABLED` (spaces between) and
        // ignores any other `SSO` line.
        if scan::skip_space(rest).starts_with("ENABLED") {
            return Ok(Some(Requirement::SeparateShaderObjects));
        }
        return Ok(None);
    }
    // Later piglit's one program flagged GL_PROGRAM_SEPARABLE, whose tests
    // check the gl_PerVertex redeclaration rule of separable programs,
    // which shaderbox's link does not apply: piglit's `SSO ENABLED`
    // script clip-distance-vs-gs-out-sso, which Mesa passes, uses the
    // built-in blocks without redeclaring them.
    if s.starts_with("SEPARABLE PROGRAM") {
        return Ok(Some(Requirement::Unsupported(
            "a separable program checked for gl_PerVertex redeclarations".into(),
        )));
    }
    if let Some(rest) = s.strip_prefix("SPIRV") {
        let rest = scan::skip_space(rest);
        if rest.starts_with("ONLY") {
            return Ok(Some(Requirement::Unsupported(
                "SPIR-V shaders (GL_ARB_gl_spirv)".into(),
            )));
        }
        if rest.starts_with("YES") || rest.starts_with("NO") {
            return Ok(None);
        }
        return Err(err(line, "unknown SPIRV line in [require]"));
    }
    if s.starts_with("ignore_missing_uniforms") {
        return Ok(Some(Requirement::IgnoreMissingUniforms));
    }
    // Anything else (comments included) is ignored, as piglit does.
    Ok(None)
}

fn parse_vertex_data(
    lines: &[(usize, &str)],
    section_line: usize,
) -> Result<Option<VertexData>, ScriptError> {
    let mut rows = lines.iter().filter_map(|&(n, l)| {
        let l = l.split('#').next().unwrap_or("").trim();
        (!l.is_empty()).then_some((n, l))
    });
    let Some((header_line, header)) = rows.next() else {
        return Ok(None);
    };
    let mut columns = Vec::new();
    let mut offset = 0;
    for text in header.split_whitespace() {
        let parts: Vec<&str> = text.split('/').collect();
        let (name, ty, count) = match parts.as_slice() {
            [name, ty, count] => (*name, *ty, *count),
            [name, count] => (*name, "float", *count),
            _ => {
                return Err(err(
                    header_line,
                    format!("vertex data column `{text}' is not name/type/count"),
                ))
            }
        };
        let gl_ty = match ty {
            "float" => GL_FLOAT,
            "int" => GL_INT,
            "uint" => GL_UNSIGNED_INT,
            _ => {
                return Err(err(
                    header_line,
                    format!("vertex data type `{ty}' is not supported (float, int, uint)"),
                ))
            }
        };
        let components = match count {
            "1" | "2" | "3" | "4" => count.parse::<usize>().unwrap_or(4),
            "vec2" => 2,
            "vec3" => 3,
            "vec4" => 4,
            _ => {
                return Err(err(
                    header_line,
                    format!("unsupported vertex data count `{count}' in `{text}'"),
                ))
            }
        };
        if name.is_empty() {
            return Err(err(
                header_line,
                format!("vertex data column `{text}' has no name"),
            ));
        }
        columns.push(Column {
            name: name.to_string(),
            ty: gl_ty,
            components,
            offset,
        });
        offset += components;
    }
    let stride = offset;
    let mut values = Vec::new();
    let mut count = 0;
    // The type of each value of a row.
    let types: Vec<u32> = columns
        .iter()
        .flat_map(|c| std::iter::repeat_n(c.ty, c.components))
        .collect();
    for (n, row) in rows {
        let before = values.len();
        for (i, tok) in row.split_whitespace().enumerate() {
            let v = match types.get(i).copied().unwrap_or(GL_FLOAT) {
                GL_INT => scan::scan_i32_base0(tok).map(|(v, r)| (f32::from_bits(v as u32), r)),
                GL_UNSIGNED_INT => scan::scan_u32_base0(tok).map(|(v, r)| (f32::from_bits(v), r)),
                _ => scan::scan_f32_or_bits(tok),
            };
            let v = match v {
                Some((v, "")) => v,
                _ => return Err(err(n, format!("bad vertex data value `{tok}'"))),
            };
            values.push(v);
        }
        if values.len() - before != stride {
            return Err(err(
                n,
                format!(
                    "vertex data row has {} values, the header names {stride}",
                    values.len() - before
                ),
            ));
        }
        count += 1;
        if count > 1_000_000 {
            return Err(err(n, "too many vertex data rows"));
        }
    }
    Ok(Some(VertexData {
        columns,
        values,
        rows: count,
        line: section_line,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    const SAMPLE: &str = "\
# comment before sections
[require]
GLSL >= 1.10
GL >= 2.0
GL_MAX_VARYING_COMPONENTS >= 52
GL_ARB_foo
!GL_ARB_bar
SIZE 20 30
# comment

[vertex shader]
void main() { gl_Position = gl_Vertex; }

[fragment shader]
void main() { gl_FragColor = vec4(1); }
[vertex data]
vertex/float/2  color/float/3
-1 -1  1 0 0
 1 -1  0 1 0   # trailing comment

[test]
draw rect -1 -1 2 2
[not a section]
";

    #[test]
    fn sections() {
        let s = parse(SAMPLE).unwrap();
        assert_eq!(s.shaders.len(), 2);
        assert_eq!(s.shaders[0].stage, Stage::Vertex);
        assert_eq!(
            s.shaders[0].source.as_deref(),
            Some("void main() { gl_Position = gl_Vertex; }\n\n")
        );
        assert_eq!(s.shaders[1].stage, Stage::Fragment);
        assert_eq!(s.shaders[1].line, 14);
        assert!(s.has_test);
        assert_eq!(
            s.test_lines,
            vec![
                (22, "draw rect -1 -1 2 2".to_string()),
                (23, "[not a section]".to_string())
            ]
        );
    }

    #[test]
    fn requirements() {
        let s = parse(SAMPLE).unwrap();
        let reqs: Vec<&Requirement> = s.requirements.iter().map(|r| &r.1).collect();
        assert_eq!(
            reqs,
            vec![
                &Requirement::Glsl(VersionReq {
                    cmp: Cmp::Ge,
                    number: 110,
                    es: false,
                    core: false,
                    compat: false,
                }),
                &Requirement::Gl(VersionReq {
                    cmp: Cmp::Ge,
                    number: 20,
                    es: false,
                    core: false,
                    compat: false,
                }),
                &Requirement::Limit {
                    name: "GL_MAX_VARYING_COMPONENTS".into(),
                    cmp: Cmp::Ge,
                    value: 52
                },
                &Requirement::Extension {
                    name: "GL_ARB_foo".into(),
                    present: true
                },
                &Requirement::Extension {
                    name: "GL_ARB_bar".into(),
                    present: false
                },
                &Requirement::Size(20, 30),
            ]
        );
        assert_eq!(s.requirements[0].0, 3);
        assert!(parse("[require]\nSIZE 0 10\n").is_err());
        assert!(parse("[require]\nSIZE 5000 10\n").is_err());
    }

    #[test]
    fn version_forms() {
        let v = |t: &str| parse_version(t, 1, true);
        assert!(v(" ES >= 3.00").unwrap().es);
        assert_eq!(v(" >= 1.20").unwrap().number, 120);
        assert_eq!(v(" < 1.30").unwrap().cmp, Cmp::Lt);
        assert!(v(" >= 1.20 x").is_err());
        assert!(v(" 1.20").is_err());
        assert!(v(" >= one").is_err());
        assert_eq!(parse_version(" >= 2.1", 1, false).unwrap().number, 21);
        assert!(parse_version(" CORE >= 3.2", 1, false).unwrap().core);
    }

    #[test]
    fn vertex_data() {
        let s = parse(SAMPLE).unwrap();
        let vd = s.vertex_data.unwrap();
        assert_eq!(vd.rows, 2);
        assert_eq!(vd.stride(), 5);
        assert_eq!(vd.columns[1].name, "color");
        assert_eq!(vd.columns[1].offset, 2);
        assert_eq!(
            vd.column_values(&vd.columns[1]),
            vec![1., 0., 0., 0., 1., 0.]
        );
        assert_eq!(vd.column_values(&vd.columns[0]), vec![-1., -1., 1., -1.]);
    }

    #[test]
    fn errors_name_the_line() {
        let e = parse("[require]\nGLSL >= 1.10\n[vertex shadr]\n").unwrap_err();
        assert_eq!(e.line, 3);
        assert!(e.message.contains("unknown section"), "{}", e.message);
        let e = parse("[require]\nGLSL >= 1.10\n[vertex data]\na/float/2\n1 2 3\n").unwrap_err();
        assert_eq!(e.line, 5);
        let e = parse("[vertex shader]\nvoid main(){}\n").unwrap_err();
        assert!(e.message.contains("[require]"));
        let e = parse("[require]\nGLSL >= x\n").unwrap_err();
        assert_eq!(e.line, 2);
    }

    #[test]
    fn later_gl_sections_are_recorded() {
        let s = parse(
            "[require]\nGLSL >= 1.50\n[tessellation control shader]\nvoid main(){}\n[test]\n",
        )
        .unwrap();
        assert_eq!(s.unsupported_sections.len(), 1);
        assert!(s.shaders.is_empty());
        let s =
            parse("[require]\nGLSL >= 1.50\n[compute shader]\nvoid main(){}\n[test]\n").unwrap();
        assert!(s.unsupported_sections.is_empty());
        assert_eq!(s.shaders[0].stage, Stage::Compute);
        let s =
            parse("[require]\nGLSL >= 1.50\n[geometry shader]\nvoid main(){}\n[test]\n").unwrap();
        assert!(s.unsupported_sections.is_empty());
        assert_eq!(s.shaders[0].stage, Stage::Geometry);
    }

    #[test]
    fn passthrough() {
        let s =
            parse("[require]\nGLSL >= 1.10\n[vertex shader passthrough]\n[fragment shader]\nx\n")
                .unwrap();
        assert_eq!(s.shaders[0].source, None);
        assert_eq!(s.shaders[1].source.as_deref(), Some("x\n"));
        assert!(!s.has_test);
    }

    #[test]
    fn sso_enabled_is_a_requirement() {
        assert_eq!(
            parse_requirement("SSO   ENABLED", 3).unwrap(),
            Some(Requirement::SeparateShaderObjects)
        );
        assert_eq!(parse_requirement("SSO DISABLED", 3).unwrap(), None);
        assert!(matches!(
            parse_requirement("SEPARABLE PROGRAM ENABLED", 3).unwrap(),
            Some(Requirement::Unsupported(_))
        ));
    }
}
