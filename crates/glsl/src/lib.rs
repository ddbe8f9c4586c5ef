//! # shaderbox-glsl: the GLSL front end (1.10 to 3.30)
//!
//! Source text in, a typed and validated IR ([`ir::Module`]) or a list of
//! [`diag::Diagnostic`]s out; then the link-time checks of a GL program
//! ([`link`]).
//!
//! ```text
//! strings ─► pp (preprocess) ─► parse (AST) ─► sema (typed IR) ─► validate
//!                                                   shader objects ─► link
//! ```
//!
//! ## Contract
//! - Follows the GLSL specification of the shader's language
//!   ([`lang::Language`]: `#version`, default 110, the profile and the
//!   enabled extensions). A shader that the spec allows compiles; one it
//!   forbids gets at least one error with a location. Which version,
//!   profile or extension each construct needs is stated once, in
//!   [`lang::Language::gate`] and the keyword table of [`token`].
//! - Never panics on any input and always terminates: macro expansion,
//!   nesting depth and token counts are bounded ([`limits`]).
//! - Reports every independent error of a compile, not only the first.
//! - Deterministic: the same input gives the same IR and diagnostics on
//!   every machine (constant folding uses the project's own math, not the
//!   platform's).
//!
//! ## Limitations
//! - GLSL ES is rejected. `#version 130` to `330` are accepted and read
//!   with the GLSL 1.20 language plus what [`lang::Feature`] lists:
//!   `uint`/`uvec*` with the `u` suffix and the int/uint→float implicit
//!   conversions, the integer operators (`%`, shifts, bitwise), `switch`,
//!   storage, interpolation, precision and layout qualifiers, uniform and
//!   input/output blocks. Their built-ins follow each version, profile and
//!   stage ([`builtins`]), the overloads on `uint`/`uvec` and the
//!   `usampler*` lookups included.
//! - Geometry shaders (GLSL 1.50): `gl_in[]`, `gl_PrimitiveIDIn`, the
//!   outputs, `EmitVertex`/`EndPrimitive`, `layout(...) in;` /
//!   `layout(..., max_vertices = N) out;` (recorded in
//!   [`ir::Module::geometry`]), input arrays sized by the input primitive,
//!   and the link rules (a vertex shader, all three layouts, the
//!   vertex → geometry → fragment interfaces, the uniforms of the vertex
//!   and fragment stages around a geometry stage). The output and input
//!   `gl_PerVertex` blocks are redeclared with a subset of their members
//!   ([`ir::Module::per_vertex_out`], [`ir::Module::per_vertex_in`]: the
//!   objects of a stage agree, and the vertex stage's output block matches
//!   the one `gl_in[]` reads); `gl_in[]`'s unsized members take the vertex
//!   stage's size at link time.
//! - GL_EXT_geometry_shader4 (and GL_ARB_geometry_shader4, the same
//!   extension) on GLSL 1.10 to 1.40: `varying in` arrays and `varying
//!   out`, `gl_PositionIn[]`... `gl_PrimitiveIDIn`, `gl_VerticesIn`, the
//!   outputs and `EmitVertex`/`EndPrimitive`. The primitives and the
//!   vertex count are the program's parameters: [`link::link_with`] takes
//!   them ([`link::GeometryParams`]) and compiles each such object again
//!   with the input primitive, so input sizes, `gl_VerticesIn` and
//!   constant indices are judged then; the linked stage carries the
//!   parameters in [`ir::Module::geometry`] as a 1.50 shader's layouts.
//!   Compiled alone ([`CompileOptions::geometry_input`] `None`), such a
//!   shader is accepted when valid for some input primitive; a constant
//!   index past every primitive's vertex count is a warning then and the
//!   link's error (the extension's §4.3.6). Its two-dimensional inputs
//!   (`varying in float v[][4]`, `gl_TexCoordIn[][]`,
//!   `gl_ClipDistanceIn[][]`) are arrays of a per-vertex row struct
//!   holding the vertex output's array (`sema::geometry`), as every array
//!   of arrays is.
//! - GL_ARB_arrays_of_arrays on GLSL 1.20 and later: more than one size in
//!   every declaration form (`float a[2][3]`, `float[2][3] a`, `float[3]
//!   a[2]`, parameters, returns, constructors, struct and block members,
//!   block instances), only the outermost unsized. The type system keeps
//!   one array level per [`types::Type`]: an array of arrays is an array
//!   of one-member row structs ([`types::StructDef::array_row`]) whose
//!   member is the inner array, one row type per inner array type, so
//!   equal dimensions are equal types; indexing the outer level yields the
//!   member (`a[i]` is the row, with `.length()`, assignment, comparison
//!   and passing as any array), and [`ir::Module::type_name`] spells the
//!   whole as `float[2][3]`. A block instance array of arrays records its
//!   inner sizes in [`ir::InterfaceBlock::inner`]. Without the extension
//!   a second size is an error naming it.
//! - Integer operations the spec leaves undefined have the executor's
//!   defined results when folded ([`consteval`]): shift amounts modulo 32,
//!   `i32::MIN % -1` is 0; division and `%` by zero are not constant.
//! - Extensions: those of [`lang::Extension`]; others are accepted by
//!   `#extension` only with `warn`/`disable`. The texture extensions whose
//!   sampler types a later version brings are offered from that version
//!   on ([`lang::Extension::since`]: GL_EXT_texture_array from 1.30,
//!   GL_ARB_texture_rectangle from 1.40, GL_ARB_texture_multisample from
//!   1.50); before it, `#extension` refuses them and their macros are
//!   not defined.

pub mod ast;
pub mod builtin_fn;
pub mod builtins;
pub mod consteval;
pub mod diag;
pub mod ir;
pub mod lang;
pub mod layout;
pub mod lex;
pub mod limits;
pub mod link;
pub mod math;
pub mod parse;
pub mod pp;
pub mod printf;
pub mod sema;
pub mod source;
pub mod token;
pub mod types;
pub mod validate;

pub use diag::{Code, Diagnostic, Severity};
pub use ir::Stage;
pub use lang::{Language, Profile, Version};
pub use source::{Loc, SourceMap, Span};

/// What to compile and how.
#[derive(Clone, Debug)]
pub struct CompileOptions {
    pub stage: Stage,
    /// Name shown by the terminal renderer (a file path).
    pub name: String,
    /// The version of a shader without `#version`; `None` means 1.10, as
    /// the spec says.
    pub default_version: Option<Version>,
    /// Whether the context offers the compatibility profile: it decides the
    /// profile of a `#version 140` shader (GL_ARB_compatibility) and
    /// whether `#version 150 compatibility` is accepted. GL 2.1 contexts
    /// and `shaderbox check` say yes.
    pub compatibility_context: bool,
    /// For a GL_EXT_geometry_shader4 geometry shader (before GLSL 1.50,
    /// with the extension enabled): the program's GEOMETRY_INPUT_TYPE,
    /// which sizes the input arrays and is `gl_VerticesIn`'s value. The
    /// linker sets it when it compiles such an object again for its
    /// program ([`link::link_with`]). `None` (what `glCompileShader` has):
    /// the shader compiles if it is valid for at least one input
    /// primitive, tried in the order GL_TRIANGLES (the parameter's initial
    /// value), points, lines, lines with adjacency, triangles with
    /// adjacency; its diagnostics are those of GL_TRIANGLES when none is.
    /// Ignored by every other language and stage.
    pub geometry_input: Option<ir::InputPrimitive>,
    /// Extensions the compiler knows but the context does not offer
    /// (those whose stages or resources the GL layer cannot run): as in
    /// a driver without them, `#extension NAME : require` fails, `enable`
    /// warns and the macro is undefined. Empty by default (`shaderbox
    /// check`, glslparsertest: the compiler's whole language).
    pub withheld: lang::ExtensionSet,
}

impl CompileOptions {
    pub fn new(stage: Stage) -> CompileOptions {
        CompileOptions {
            stage,
            name: String::from("<shader>"),
            default_version: None,
            compatibility_context: true,
            geometry_input: None,
            withheld: lang::ExtensionSet::EMPTY,
        }
    }
}

/// A compiled shader object (what `glCompileShader` produces).
#[derive(Clone, Debug)]
pub struct Shader {
    pub stage: Stage,
    pub source: SourceMap,
    /// The version from `#version` (or 1.10 without one), the profile, and
    /// the extensions the shader enables.
    pub language: Language,
    /// The analyzed module; present only when there are no errors.
    pub module: Option<ir::Module>,
    pub diagnostics: Vec<Diagnostic>,
}

impl Shader {
    /// True when the shader compiled (`GL_COMPILE_STATUS`).
    pub fn ok(&self) -> bool {
        self.module.is_some()
    }

    /// The GL info log.
    pub fn info_log(&self) -> String {
        diag::render_info_log(&self.diagnostics, &self.source)
    }

    /// The rich terminal rendering of the diagnostics.
    pub fn render(&self, color: bool) -> String {
        diag::render_terminal(&self.diagnostics, &self.source, color)
    }
}

/// Compiles one shader object from its source strings.
pub fn compile(strings: &[&str], opts: &CompileOptions) -> Shader {
    let bytes = strings
        .iter()
        .fold(0usize, |n, s| n.saturating_add(s.len()));
    if bytes > limits::MAX_SOURCE_BYTES {
        return too_large(opts);
    }
    let mut source = SourceMap::from_strings(opts.name.clone(), strings);
    // A shader without #version is GLSL 1.10 (GLSL 1.50 §3.3), but a core
    // profile context has no GLSL 1.10 (GL 3.2 core, appendix E.2) and
    // 1.10 has no geometry stage: such a geometry shader is compiled as
    // the first version that has one, as Mesa does, and told so.
    let implicit_150 = opts.default_version.is_none()
        && opts.stage == Stage::Geometry
        && !opts.compatibility_context;
    let default_version = match opts.default_version {
        Some(v) => v,
        None if implicit_150 => Version::V150,
        None => Version::V110,
    };
    let pp_out = pp::preprocess(
        &mut source,
        &pp::PpOptions {
            stage: opts.stage,
            default_version,
            compatibility_context: opts.compatibility_context,
            withheld: opts.withheld,
        },
    );
    let mut diagnostics = pp_out.diagnostics;
    if implicit_150 && !pp_out.has_version {
        diagnostics.push(
            Diagnostic::warning(
                Code::PpVersion,
                Span::new(0, 0),
                "this geometry shader has no #version directive: compiled as GLSL 1.50",
            )
            .with_note(
                "without #version a shader is GLSL 1.10, which a core profile context does not \
                 have and which has no geometry stage; start the shader with `#version 150'",
            ),
        );
    }
    let language = pp_out.language;
    let pp_failed = diagnostics.iter().any(Diagnostic::is_error);
    let mut module = None;
    if !pp_failed {
        let (tu, parse_diags) = parse::parse(&pp_out.tokens, language);
        let parse_failed = parse_diags.iter().any(Diagnostic::is_error);
        diagnostics.extend(parse_diags);
        let analyze = |input: Option<ir::InputPrimitive>, defer_input_index: bool| {
            let ctx = sema::Context {
                language,
                stage: opts.stage,
                extensions: pp_out.extensions.clone(),
                invariant_all: pp_out.invariant_all,
                geometry_input: input,
                defer_input_index,
            };
            let (m, mut diags) = sema::analyze(&tu, &ctx);
            let mut ok = !parse_failed && !diags.iter().any(Diagnostic::is_error);
            if ok {
                diags.extend(validate::validate(&m));
                ok = !diags.iter().any(Diagnostic::is_error);
            }
            (ok.then_some(m), diags)
        };
        let ext_gs = opts.stage == Stage::Geometry && language.ext_geometry_shader4();
        let (m, sema_diags) = if ext_gs && opts.geometry_input.is_none() {
            ext_geometry_trials(analyze, parse_failed)
        } else {
            analyze(opts.geometry_input, false)
        };
        diagnostics.extend(sema_diags);
        module = m;
    }
    // In source order, as a reader goes through the shader (parse errors
    // and analysis errors otherwise come in two runs).
    diagnostics.sort_by_key(|d| d.span.map_or(u32::MAX, |s| s.start));
    if diagnostics.len() > limits::MAX_DIAGNOSTICS {
        let rest = diagnostics.split_off(limits::MAX_DIAGNOSTICS);
        let errors = rest.iter().filter(|d| d.is_error()).count();
        diagnostics.push(Diagnostic {
            severity: Severity::Note,
            code: Code::Internal,
            message: format!(
                "{} more diagnostics ({errors} errors) not shown; fix the ones above first",
                rest.len()
            ),
            span: None,
            labels: Vec::new(),
            notes: Vec::new(),
        });
    }
    Shader {
        stage: opts.stage,
        source,
        language,
        module,
        diagnostics,
    }
}

/// The shader refused for its size, before any of it is copied or read.
/// A GL_EXT_geometry_shader4 geometry shader compiled without its
/// program's input primitive: valid when valid for one of them
/// ([`CompileOptions::geometry_input`]). The module keeps the sizes of
/// the primitive that succeeded but declares no layout: the linker
/// compiles the object again with the program's primitive.
fn ext_geometry_trials(
    analyze: impl Fn(Option<ir::InputPrimitive>, bool) -> (Option<ir::Module>, Vec<Diagnostic>),
    parse_failed: bool,
) -> (Option<ir::Module>, Vec<Diagnostic>) {
    use ir::InputPrimitive as P;
    let (first, mut diags) = analyze(Some(P::Triangles), false);
    if let Some(mut m) = first {
        m.geometry = ir::GeometryLayout::default();
        return (Some(m), diags);
    }
    if parse_failed {
        return (None, diags);
    }
    for p in [
        P::Points,
        P::Lines,
        P::LinesAdjacency,
        P::TrianglesAdjacency,
    ] {
        if let (Some(mut m), d) = analyze(Some(p), false) {
            m.geometry = ir::GeometryLayout::default();
            return (Some(m), d);
        }
    }
    // A constant index past every primitive's vertices is a link error
    // (GL_EXT_geometry_shader4 §4.3.6): valid if nothing else fails with
    // the largest primitive.
    if let (Some(mut m), d) = analyze(Some(P::TrianglesAdjacency), true) {
        m.geometry = ir::GeometryLayout::default();
        return (Some(m), d);
    }
    // Errors that depend on the input primitive say which one was assumed.
    for d in diags
        .iter_mut()
        .filter(|d| d.is_error() && matches!(d.code, Code::IndexOutOfRange | Code::BadArraySize))
    {
        d.notes.push("checked with gl_VerticesIn = 3 (GL_TRIANGLES, the initial GEOMETRY_INPUT_TYPE) and every other input primitive; the program's input type decides at link time".into());
    }
    (None, diags)
}

fn too_large(opts: &CompileOptions) -> Shader {
    let source = SourceMap::from_strings(opts.name.clone(), &[]);
    let language = Language::new(
        opts.default_version.unwrap_or(Version::V110),
        opts.compatibility_context,
    );
    let d = Diagnostic::error(Code::Unsupported, None, source_too_large_message())
        .with_note("split the source, or generate less of it: shaders are rarely over 1 MiB");
    Shader {
        stage: opts.stage,
        source,
        language,
        module: None,
        diagnostics: vec![d],
    }
}

/// The error for a source over [`limits::MAX_SOURCE_BYTES`], the same
/// from every front end (a reader that stops at the limit gives it too).
pub fn source_too_large_message() -> String {
    format!(
        "the shader source is larger than {} bytes, the limit",
        limits::MAX_SOURCE_BYTES
    )
}
