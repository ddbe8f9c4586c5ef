//! Semantic analysis: the syntax tree of one shader to the typed IR.
//!
//! One pass over the [`TranslationUnit`] in source order, as the GLSL
//! specifications define visibility (a name is usable from the end of its
//! declarator on). The result obeys the contract at the top of
//! [`crate::ir`]. Errors recover: an expression that fails gets
//! [`Type::ERROR`], and nothing that involves an error type is reported
//! again, so one mistake gives one diagnostic.
//!
//! The built-ins (GLSL 1.20 §7, §8) are GLSL text from
//! [`crate::builtins::prelude`], analyzed once per (version, stage) in a
//! privileged mode and cached in a `BuiltinEnv`; a user shader sees them
//! in a scope outside its global scope (§4.2.6).
//!
//! Submodules: `scope` (symbol tables), `types` (type specifiers,
//! structs, array sizes), `decl` (variable declarations and qualifiers),
//! `func` (functions, calls, overloads), `expr` (names, operators,
//! conversions, assignment), `access` (indexing, fields, swizzles,
//! l-values), `construct` (constructors), `stmt` (statements).

mod access;
mod blocks;
mod compute;
mod construct;
mod decl;
mod expr;
mod func;
mod geometry;
mod interface;
mod scope;
mod stmt;
mod tessellation;
mod types;

use crate::ast::{self, TranslationUnit};
use crate::builtins::BuiltinFn;
use crate::diag::{Code, Diagnostic};
use crate::ir::{
    self, ConstScalar, ConstValue, FunctionId, GlobalId, LocalId, Module, ParamQualifier, Stage,
};
use crate::lang::{Language, Profile, Unavailable, Version};
use crate::pp::ExtensionDirective;
use crate::source::{SourceMap, Span};
use crate::types::{Base, StructDef, Type};
use scope::{FnRef, Scopes, Symbol, Var};
use smol_str::SmolStr;
// FxHash: symbol names are short and trusted to be few; SipHash showed
// up at 4% of compile time.
use rustc_hash::FxHashMap as HashMap;
use std::sync::{Mutex, OnceLock};

/// What the analysis needs to know about the shader besides its text.
pub struct Context {
    pub language: Language,
    pub stage: Stage,
    pub extensions: Vec<ExtensionDirective>,
    /// `#pragma STDGL invariant(all)`: every output is invariant.
    pub invariant_all: bool,
    /// A GL_EXT_geometry_shader4 geometry shader's input primitive (the
    /// program's GEOMETRY_INPUT_TYPE): it sizes the input arrays and gives
    /// `gl_VerticesIn` its value. `None` is GL_TRIANGLES, the parameter's
    /// initial value. Ignored by every other language and stage.
    pub geometry_input: Option<ir::InputPrimitive>,
    /// For a GL_EXT_geometry_shader4 geometry shader compiled without its
    /// program's input primitive: a constant index past every input
    /// primitive's vertex count (`gl_PositionIn[6]`) is the link error of
    /// the extension's §4.3.6, reported when the linker compiles the
    /// object again with the program's primitive; here it is a warning.
    pub defer_input_index: bool,
}

/// Analyzes one shader. The module is complete only when no error was
/// reported; with errors it is a best effort (error types inside).
pub fn analyze(tu: &TranslationUnit, ctx: &Context) -> (Module, Vec<Diagnostic>) {
    let ext_gs = ctx.stage == Stage::Geometry && ctx.language.ext_geometry_shader4();
    let input = ctx.geometry_input.unwrap_or(ir::InputPrimitive::Triangles);
    let env = builtin_env_for_input(ctx.language, ctx.stage, input);
    let mut a = Analyzer::new(ctx.language, ctx.stage, Some(env));
    a.defer_input_index = ext_gs && ctx.defer_input_index;
    if ext_gs {
        // The EXT form has no input layout: the primitive is known from
        // the first line, so every input array is sized as it is declared.
        a.module.geometry.input = Some(input);
    }
    a.module.extensions = ctx
        .extensions
        .iter()
        .map(|e| (e.name.clone(), e.behavior))
        .collect();
    a.declared_functions = tu
        .items
        .iter()
        .filter_map(|item| match item {
            ast::ExternalDecl::FunctionDef(f) => Some(&f.proto.name),
            ast::ExternalDecl::Declaration(ast::Declaration::Prototype(p)) => Some(&p.name),
            _ => None,
        })
        .map(|n| (n.name.clone(), n.span))
        .collect();
    if ctx.stage == Stage::Geometry {
        // Reported at the start of the source: the whole shader is the
        // construct.
        a.require(
            crate::lang::Feature::GeometryShader,
            "a geometry shader",
            crate::source::Span::default(),
        );
    }
    if ctx.stage == Stage::Compute {
        a.require(
            crate::lang::Feature::ComputeShader,
            "a compute shader",
            crate::source::Span::default(),
        );
    }
    if matches!(ctx.stage, Stage::TessControl | Stage::TessEvaluation) {
        let what = format!("a {} shader", ctx.stage.name());
        a.require(
            crate::lang::Feature::TessellationShader,
            &what,
            crate::source::Span::default(),
        );
    }
    a.translation_unit(tu);
    if ctx.invariant_all && ctx.stage == Stage::Vertex {
        // GLSL 1.20 §4.6.1: "#pragma STDGL invariant(all)" makes all
        // outputs invariant; the vertex outputs are the varyings and
        // gl_Position/gl_PointSize/gl_ClipVertex.
        for g in &mut a.module.globals {
            if g.storage == ir::Storage::Varying
                || (g.builtin
                    && matches!(
                        g.name.as_str(),
                        "gl_Position" | "gl_PointSize" | "gl_ClipVertex"
                    ))
            {
                g.invariant = true;
            }
        }
    }
    a.finish()
}

/// A built-in function signature.
#[derive(Clone, Debug)]
pub(crate) struct BuiltinSig {
    pub function: BuiltinFn,
    pub params: Vec<(Type, ParamQualifier)>,
    pub ret: Type,
}

/// The analyzed built-ins of one (version, stage).
#[derive(Debug)]
pub(crate) struct BuiltinEnv {
    pub structs: Vec<StructDef>,
    pub globals: Vec<ir::Global>,
    pub functions: Vec<BuiltinSig>,
    pub names: HashMap<SmolStr, Symbol>,
    /// Problems found in the prelude itself (a bug in the tables); kept so a
    /// test can check there are none.
    #[cfg_attr(not(test), allow(dead_code))]
    pub diagnostics: Vec<Diagnostic>,
}

impl BuiltinEnv {
    pub fn lookup(&self, name: &str) -> Option<&Symbol> {
        self.names.get(name)
    }
}

/// The cached built-in environment of a language and stage, built once
/// per combination (there are few: versions × profiles × stages × the
/// extension sets shaders enable) and then shared.
pub(crate) fn builtin_env(lang: Language, stage: Stage) -> &'static BuiltinEnv {
    builtin_env_for_input(lang, stage, ir::InputPrimitive::Triangles)
}

/// [`builtin_env`] of a GL_EXT_geometry_shader4 geometry shader whose
/// program takes `input` primitives (`gl_VerticesIn`'s value); the same
/// as `builtin_env` for every other language and stage.
pub(crate) fn builtin_env_for_input(
    lang: Language,
    stage: Stage,
    input: ir::InputPrimitive,
) -> &'static BuiltinEnv {
    type Key = (Language, Stage, Option<ir::InputPrimitive>);
    type Cache = Mutex<HashMap<Key, &'static BuiltinEnv>>;
    let input = (stage == Stage::Geometry && lang.ext_geometry_shader4()).then_some(input);
    let key = (lang, stage, input);
    static CACHE: OnceLock<Cache> = OnceLock::new();
    let cache = CACHE.get_or_init(Default::default);
    if let Some(env) = cache.lock().unwrap_or_else(|e| e.into_inner()).get(&key) {
        return env;
    }
    // Built outside the lock: the prelude's analysis may itself look up
    // other environments (availability notes are not made in built-in
    // mode, but nothing here should rely on that).
    let env: &'static BuiltinEnv = Box::leak(Box::new(build_env(lang, stage, input)));
    cache
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .entry(key)
        .or_insert(env)
}

/// Parses and analyzes the prelude text in built-in mode.
fn build_env(lang: Language, stage: Stage, input: Option<ir::InputPrimitive>) -> BuiltinEnv {
    let text = match input {
        Some(p) => crate::builtins::prelude_for_input(lang, stage, p),
        None => crate::builtins::prelude(lang, stage),
    };
    let mut map = SourceMap::new("<built-ins>", text);
    let mut opts = crate::pp::PpOptions::new(stage);
    // The prelude's own #version is never refused: GLSL 1.10/1.20 exist
    // only in compatibility contexts, whatever profile the key names.
    opts.compatibility_context =
        lang.profile == Profile::Compatibility || lang.version < crate::lang::Version::V130;
    let pp = crate::pp::preprocess(&mut map, &opts);
    let (tu, parse_diags) = crate::parse::parse(&pp.tokens, lang);
    let mut a = Analyzer::new(lang, stage, None);
    a.builtin_mode = true;
    a.translation_unit(&tu);
    let mut diagnostics = pp.diagnostics;
    diagnostics.extend(parse_diags);
    diagnostics.append(&mut a.diags);
    let module = std::mem::replace(&mut a.module, Module::empty(lang, stage));
    // Prototypes without bodies become built-in functions.
    let mut fn_map: HashMap<u32, u32> = HashMap::default();
    let mut functions = Vec::new();
    for (i, f) in module.functions.iter().enumerate() {
        let Some(function) = BuiltinFn::from_name(&f.name) else {
            diagnostics.push(Diagnostic::error(
                Code::Internal,
                f.span,
                format!("built-in `{}' has no BuiltinFn", f.name),
            ));
            continue;
        };
        fn_map.insert(i as u32, functions.len() as u32);
        functions.push(BuiltinSig {
            function,
            params: f.params.iter().map(|p| (p.ty, p.qualifier)).collect(),
            ret: f.return_type,
        });
    }
    let mut names = HashMap::default();
    for (name, sym) in a.scopes.into_global() {
        let sym = match sym {
            Symbol::Var(Var::Global(g)) => Symbol::Var(Var::Builtin(g.0)),
            Symbol::Funcs(v) => Symbol::Funcs(
                v.into_iter()
                    .filter_map(|f| match f {
                        FnRef::User(id) => fn_map.get(&id.0).map(|&b| FnRef::Builtin(b)),
                        other => Some(other),
                    })
                    .collect(),
            ),
            other => other,
        };
        names.insert(name, sym);
    }
    let mut globals = module.globals;
    for g in &mut globals {
        g.builtin = true;
        g.read = false;
        g.written = false;
    }
    BuiltinEnv {
        structs: module.structs,
        globals,
        functions,
        names,
        diagnostics,
    }
}

/// Per-function analysis state.
pub(crate) struct FnState {
    pub id: FunctionId,
    pub ret: Type,
    pub locals: Vec<ir::Local>,
    /// Values of `const` locals.
    pub consts: Vec<Option<ConstValue>>,
    /// Largest constant index + 1 used on each local unsized array.
    pub implicit: Vec<u32>,
    pub loop_depth: u32,
    /// Switch statements around the current statement (for `break`).
    pub switch_depth: u32,
    /// `if` statements around the current statement.
    pub if_depth: u32,
    /// A `return` statement came before the current one (in source
    /// order).
    pub returned: bool,
}

/// Bookkeeping per module function.
#[derive(Clone, Debug, Default)]
pub(crate) struct FnInfo {
    pub defined: bool,
    pub callees: Vec<FunctionId>,
    /// Where the call graph edges were made (parallel to `callees`).
    pub call_spans: Vec<Span>,
}

pub(crate) struct Analyzer {
    pub lang: Language,
    pub stage: Stage,
    /// Analyzing the prelude: `gl_` names and built-in-only forms allowed.
    pub builtin_mode: bool,
    pub env: Option<&'static BuiltinEnv>,
    pub module: Module,
    pub diags: Vec<Diagnostic>,
    pub scopes: Scopes,
    /// Module global of each built-in global, once referenced.
    pub builtin_globals: Vec<Option<GlobalId>>,
    pub fns: Vec<FnInfo>,
    pub cur: Option<FnState>,
    pub frag_color_write: Option<Span>,
    pub frag_data_write: Option<Span>,
    /// Expression nesting depth (bounded by `limits::MAX_NESTING_DEPTH`).
    pub depth: u32,
    /// Every function the translation unit declares or defines, with where:
    /// lets "undeclared function" say when the function comes later.
    pub declared_functions: Vec<(SmolStr, Span)>,
    /// "Did you mean" searches left (`limits::MAX_SUGGESTIONS`).
    pub suggestions_left: u32,
    /// The layout of uniform blocks declared from here on, as set by
    /// `layout(...) uniform;` (GLSL 1.40 §4.3.5.2).
    pub default_block_layout: ir::BlockLayout,
    pub default_row_major: bool,
    /// The first redeclaration of `gl_FragCoord`, with its layout.
    pub frag_coord_redeclared: Option<ir::FragCoordConventions>,
    /// A geometry shader's first sized input array before any input
    /// layout: its size and name (later sizes must agree, GLSL 1.50
    /// §4.3.8.1).
    pub geometry_input_len: Option<(u32, String)>,
    /// A control shader's first sized per-vertex output before any
    /// `layout(vertices = N) out;`: its size and name (later sizes and
    /// the layout must agree, GL_ARB_tessellation_shader §4.3.8.2).
    pub tess_output_len: Option<(u32, String)>,
    /// [`Context::defer_input_index`].
    pub defer_input_index: bool,
    /// Built-in outputs a redeclared `gl_PerVertex` left out: no longer
    /// names (GLSL 1.50 §7.1).
    pub hidden_builtins: Vec<SmolStr>,
    /// A member of the output `gl_PerVertex` redeclared on its own
    /// (`out float gl_ClipDistance[4];`): the block can then not be
    /// redeclared, nor the member after the block (GLSL 1.50 §7.1).
    pub per_vertex_member_redeclared: Option<SmolStr>,
}

impl Analyzer {
    pub fn new(lang: Language, stage: Stage, env: Option<&'static BuiltinEnv>) -> Analyzer {
        let structs = env.map(|e| e.structs.clone()).unwrap_or_default();
        Analyzer {
            lang,
            stage,
            builtin_mode: false,
            env,
            module: Module {
                structs,
                ..Module::empty(lang, stage)
            },
            diags: Vec::new(),
            scopes: Scopes::new(),
            builtin_globals: vec![None; env.map_or(0, |e| e.globals.len())],
            fns: Vec::new(),
            cur: None,
            frag_color_write: None,
            frag_data_write: None,
            depth: 0,
            declared_functions: Vec::new(),
            suggestions_left: crate::limits::MAX_SUGGESTIONS,
            default_block_layout: ir::BlockLayout::Shared,
            default_row_major: false,
            frag_coord_redeclared: None,
            geometry_input_len: None,
            tess_output_len: None,
            defer_input_index: false,
            hidden_builtins: Vec::new(),
            per_vertex_member_redeclared: None,
        }
    }

    pub fn translation_unit(&mut self, tu: &TranslationUnit) {
        for item in &tu.items {
            match item {
                crate::ast::ExternalDecl::Declaration(d) => {
                    self.declaration(d);
                }
                crate::ast::ExternalDecl::FunctionDef(f) => self.function_def(f),
            }
        }
    }

    pub fn finish(mut self) -> (Module, Vec<Diagnostic>) {
        self.check_recursion();
        if let (Some(c), Some(d)) = (self.frag_color_write, self.frag_data_write) {
            let at = c.max_by_start(d);
            self.diags.push(
                Diagnostic::error(
                    Code::TypeMismatch,
                    at,
                    "a shader may write `gl_FragColor' or `gl_FragData', not both",
                )
                .with_label(c.min_by_start(d), "the other one is written here")
                .with_note("GLSL 1.10 §7.2: write all outputs through `gl_FragData[i]' or only `gl_FragColor'"),
            );
        }
        // GLSL 1.30 §7.2: a shader that statically writes a user output
        // may not write gl_FragColor or gl_FragData.
        if let Some(builtin) = self.frag_color_write.or(self.frag_data_write) {
            let user = self
                .module
                .globals
                .iter()
                .find(|g| g.storage == ir::Storage::FragOutput && g.written);
            if let Some(g) = user {
                let d = Diagnostic::error(
                    Code::TypeMismatch,
                    builtin,
                    format!(
                        "a shader that writes the output `{}' cannot also write `gl_FragColor' or `gl_FragData'",
                        g.name
                    ),
                )
                .with_label(g.span, "user output declared here");
                self.diags.push(d);
            }
        }
        (self.module, self.diags)
    }

    // ----- diagnostics -----------------------------------------------------

    pub fn error(&mut self, code: Code, span: Span, msg: impl Into<String>) -> &mut Diagnostic {
        self.diags.push(Diagnostic::error(code, span, msg));
        let last = self.diags.len() - 1;
        &mut self.diags[last]
    }

    pub fn push(&mut self, d: Diagnostic) {
        self.diags.push(d);
    }

    /// A type as GLSL spells it.
    pub fn tn(&self, ty: Type) -> String {
        self.module.type_name(ty)
    }

    // ----- variables ------------------------------------------------------

    /// The module global for a variable reference, materializing built-ins.
    pub fn global_of(&mut self, v: Var) -> Option<GlobalId> {
        match v {
            Var::Global(g) => Some(g),
            Var::Local(_) => None,
            Var::Builtin(i) => {
                if let Some(Some(g)) = self.builtin_globals.get(i as usize) {
                    return Some(*g);
                }
                let mut g = self.env?.globals.get(i as usize)?.clone();
                g.ty = self.builtin_global_type(&g);
                // `gl_in`'s block id is the prelude's, not this module's.
                g.block = None;
                let id = GlobalId(self.module.globals.len() as u32);
                self.module.globals.push(g);
                if let Some(slot) = self.builtin_globals.get_mut(i as usize) {
                    *slot = Some(id);
                }
                Some(id)
            }
        }
    }

    /// The type of a built-in global as this shader sees it: `gl_in[]'
    /// (and the EXT form's `gl_PositionIn[]'...) take the input
    /// primitive's size once it is declared.
    fn builtin_global_type(&self, g: &ir::Global) -> Type {
        let size = match g.storage {
            ir::Storage::PerVertexInput => self.per_vertex_input_size(),
            ir::Storage::PerVertexOutput => self.module.tessellation.vertices,
            _ => None,
        };
        match (g.ty.array, size) {
            (Some(crate::types::ArraySize::Unsized), Some(n)) => Type {
                array: Some(crate::types::ArraySize::Sized(n)),
                ..g.ty
            },
            _ => g.ty,
        }
    }

    /// Declared type of a variable.
    pub fn var_type(&self, v: Var) -> Type {
        match v {
            Var::Global(g) => self
                .module
                .globals
                .get(g.0 as usize)
                .map_or(Type::ERROR, |g| g.ty),
            Var::Local(l) => self
                .cur
                .as_ref()
                .and_then(|f| f.locals.get(l.0 as usize))
                .map_or(Type::ERROR, |l| l.ty),
            Var::Builtin(i) => match self.builtin_globals.get(i as usize).copied().flatten() {
                // Materialized (possibly resized, `gl_TexCoord[n]`).
                Some(g) => self
                    .module
                    .globals
                    .get(g.0 as usize)
                    .map_or(Type::ERROR, |g| g.ty),
                None => self
                    .env
                    .and_then(|e| e.globals.get(i as usize))
                    .map_or(Type::ERROR, |g| self.builtin_global_type(g)),
            },
        }
    }

    /// The constant value of a `const` variable, if it has one.
    pub fn var_const(&self, v: Var) -> Option<ConstValue> {
        match v {
            Var::Global(g) => {
                let g = self.module.globals.get(g.0 as usize)?;
                (g.storage == ir::Storage::Const)
                    .then(|| g.init.clone())
                    .flatten()
            }
            Var::Local(l) => self.cur.as_ref()?.consts.get(l.0 as usize)?.clone(),
            Var::Builtin(i) => {
                let g = self.env?.globals.get(i as usize)?;
                (g.storage == ir::Storage::Const)
                    .then(|| g.init.clone())
                    .flatten()
            }
        }
    }

    /// Adds a local to the current function.
    pub fn new_local(&mut self, name: &str, ty: Type, is_const: bool, span: Span) -> LocalId {
        let Some(f) = self.cur.as_mut() else {
            return LocalId(0);
        };
        let id = LocalId(f.locals.len() as u32);
        f.locals.push(ir::Local {
            name: name.to_string(),
            ty,
            is_const,
            span,
        });
        f.consts.push(None);
        f.implicit.push(0);
        id
    }

    /// Whether a "did you mean" search for `name` is made: the name is
    /// short enough to compare and this shader's budget of searches is not
    /// spent (each search costs one comparison per visible name).
    pub fn may_suggest(&mut self, name: &str) -> bool {
        if !crate::diag::suggestible(name) || self.suggestions_left == 0 {
            return false;
        }
        self.suggestions_left -= 1;
        true
    }

    /// Every name visible from here, sorted (for "did you mean").
    pub fn visible_names(&self) -> Vec<String> {
        let mut v: Vec<String> = self.scopes.names().map(|s| s.to_string()).collect();
        if let Some(env) = self.env {
            v.extend(env.names.keys().map(|s| s.to_string()));
        }
        v.sort();
        v.dedup();
        v
    }

    /// Looks a name up in the user scopes, then among the built-ins.
    pub fn lookup(&self, name: &str) -> Option<Symbol> {
        if let Some(s) = self.scopes.lookup(name) {
            return Some(s.clone());
        }
        if self.hidden_builtins.iter().any(|h| h == name) {
            return None;
        }
        self.env.and_then(|e| e.lookup(name)).cloned()
    }

    /// Where a built-in is declared in other versions or stages, for notes
    /// on an undeclared name.
    pub fn availability_note(&self, name: &str) -> Option<(Code, String)> {
        if self.builtin_mode || !name.starts_with(|c: char| c.is_ascii_alphabetic()) {
            return None;
        }
        let found = |lang: Language, stage: Stage| builtin_env(lang, stage).lookup(name).is_some();
        // GL_EXT_geometry_shader4's built-ins (`gl_PositionIn'...): in a
        // geometry shader before "a later version has it", the other way
        // to get them; in other stages after every other explanation.
        if self.stage == Stage::Geometry {
            if let Some(note) = self.ext_geometry_note(name) {
                return Some(note);
            }
        }
        // A later version of the same profile has it.
        let later = Version::ALL
            .into_iter()
            .filter(|&v| v > self.lang.version)
            .find(|&v| {
                let mut l = Language::new(v, self.lang.profile == Profile::Compatibility);
                l.profile = if v.has_profiles() || v == Version::V140 {
                    self.lang.profile
                } else {
                    Profile::Compatibility
                };
                found(l, self.stage)
            });
        if let Some(v) = later {
            return Some((
                Code::VersionTooLow,
                format!(
                    "`{name}' requires GLSL {} (add `#version {}' as the first line)",
                    v.dotted(),
                    v.number()
                ),
            ));
        }
        // The compatibility profile of this version has it.
        if self.lang.profile == Profile::Core {
            let compat = Language {
                profile: Profile::Compatibility,
                ..self.lang
            };
            if found(compat, self.stage) {
                return Some((
                    Code::VersionTooLow,
                    format!(
                        "{}; {}",
                        Unavailable::RemovedInCore(Version::V140)
                            .message(&format!("`{name}'"), self.lang),
                        crate::builtins::replacement(name)
                    ),
                ));
            }
        }
        let others = [
            Stage::Vertex,
            Stage::TessControl,
            Stage::TessEvaluation,
            Stage::Geometry,
            Stage::Fragment,
        ]
        .into_iter()
        .filter(|&s| s != self.stage);
        for other in others {
            if found(self.lang, other) {
                return Some((
                    Code::StageMismatch,
                    format!("`{name}' is only available in {} shaders", other.name()),
                ));
            }
        }
        // An extension this version offers has it (GL_EXT_geometry_shader4
        // has its own note above and below).
        let extension = crate::lang::Extension::ALL.iter().find(|&&e| {
            let mut l = self.lang;
            l.extensions.set(e, true);
            !self.lang.has(e)
                && self.lang.version >= e.since()
                && !matches!(
                    e,
                    crate::lang::Extension::ExtGeometryShader4
                        | crate::lang::Extension::ArbGeometryShader4
                )
                && found(l, self.stage)
        });
        if let Some(e) = extension {
            return Some((
                Code::Undeclared,
                format!(
                    "`{name}' is a built-in of {0}: add `#extension {0} : enable' after `#version'",
                    e.name()
                ),
            ));
        }
        self.ext_geometry_note(name)
    }

    /// The note for a GL_EXT_geometry_shader4 built-in used where the
    /// extension's geometry stage is not.
    fn ext_geometry_note(&self, name: &str) -> Option<(Code, String)> {
        if self.lang.version >= Version::V150 || self.lang.ext_geometry_shader4() {
            return None;
        }
        let mut ext = self.lang;
        ext.extensions
            .set(crate::lang::Extension::ExtGeometryShader4, true);
        builtin_env(ext, Stage::Geometry).lookup(name)?;
        Some(if self.stage == Stage::Geometry {
            (
                Code::VersionTooLow,
                format!("`{name}' is a built-in of GL_EXT_geometry_shader4: add `#extension GL_EXT_geometry_shader4 : enable' after `#version'"),
            )
        } else {
            (
                Code::StageMismatch,
                format!("`{name}' is only available in geometry shaders (GL_EXT_geometry_shader4)"),
            )
        })
    }
}

/// Helpers on spans used for ordering two related locations.
trait SpanOrder {
    fn max_by_start(self, other: Span) -> Span;
    fn min_by_start(self, other: Span) -> Span;
}

impl SpanOrder for Span {
    fn max_by_start(self, other: Span) -> Span {
        if other.start > self.start {
            other
        } else {
            self
        }
    }
    fn min_by_start(self, other: Span) -> Span {
        if other.start > self.start {
            self
        } else {
            other
        }
    }
}

/// A constant's single int value.
pub(crate) fn const_int(c: &ConstValue) -> Option<i32> {
    match (c.ty.base, c.ty.array, c.components.as_slice()) {
        (Base::Scalar(_), None, [ConstScalar::Int(i)]) => Some(*i),
        (Base::Scalar(_), None, [ConstScalar::Uint(u)]) => i32::try_from(*u).ok(),
        _ => None,
    }
}

/// An expression of the error type, for recovery.
pub(crate) fn error_expr(span: Span) -> ir::Expr {
    ir::Expr {
        kind: ir::ExprKind::Const(ConstValue {
            ty: Type::ERROR,
            components: Vec::new(),
        }),
        ty: Type::ERROR,
        span,
    }
}

/// A constant expression.
pub(crate) fn const_expr(value: ConstValue, span: Span) -> ir::Expr {
    ir::Expr {
        ty: value.ty,
        kind: ir::ExprKind::Const(value),
        span,
    }
}

#[cfg(test)]
mod aoa_tests;
#[cfg(test)]
mod compute_tests;
#[cfg(test)]
mod ext_geometry_tests;
#[cfg(test)]
mod geometry_tests;
#[cfg(test)]
mod pack420_tests;
#[cfg(test)]
mod per_vertex_in_tests;
#[cfg(test)]
mod storage_tests;
#[cfg(test)]
mod tessellation_tests;
#[cfg(test)]
mod tests;
