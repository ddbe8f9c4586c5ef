//! Linking shader objects into a program (what `glLinkProgram` checks).
//!
//! For each stage the shader objects of that stage are merged into one
//! [`Module`] (GLSL 1.20 §4.3: "shared globals" of one language share one
//! name space; §6.1: a function declared in one object may be defined in
//! another), then the two stages' interfaces are checked against each other
//! (§4.3.5 uniforms, §4.3.6 varyings) and against the limits of
//! [`crate::limits`].
//!
//! Link errors are [`Diagnostic`]s like compile errors; those that point into
//! a shader object carry its index in [`LinkDiagnostic::shader`].
//!
//! A GL_EXT_geometry_shader4 geometry shader (GLSL before 1.50 with the
//! extension enabled) takes its input primitive, output primitive and
//! vertex count from the program's parameters ([`GeometryParams`], passed
//! by [`link_with`]): each such object is compiled again with the input
//! primitive (its input arrays sized, `gl_VerticesIn` its vertex count,
//! errors of that compile being link errors), and its module's
//! [`Module::geometry`] then holds the three parameters as a GLSL 1.50
//! object's layouts would, so the linked stage is the same for both forms.
//! GLSL 1.50 geometry shaders ignore the parameters.
//!
//! The parts: `merge` (one stage's objects into one module, with `remap`
//! moving each object's ids and `types` deciding when declarations agree),
//! `calls` (call depth across objects), `redeclarations` (built-in
//! redeclarations every object must agree on), `blocks` (interface and
//! uniform blocks) and `interface` (locations, the stages' interface,
//! limits).

mod blocks;
mod calls;
mod interface;
mod merge;
mod redeclarations;
mod remap;
mod types;

use self::interface::{check_interface, check_limits, check_locations, check_uniforms};
use self::merge::merge_stage;
use crate::diag::{render_info_log, Code, Diagnostic};
use crate::ir::{FunctionId, GeometryLayout, InputPrimitive, Module, OutputPrimitive, Stage};
use crate::{CompileOptions, Profile, Shader};

/// A program's geometry shader parameters (GL_EXT_geometry_shader4
/// §2.16: `glProgramParameteriEXT` with GEOMETRY_INPUT_TYPE_EXT,
/// GEOMETRY_OUTPUT_TYPE_EXT, GEOMETRY_VERTICES_OUT_EXT), used by the
/// extension's form of geometry shader only. The default is the spec's
/// initial state: triangles in, a triangle strip out, 0 vertices (which
/// fails the link of such a shader until the program sets a count).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GeometryParams {
    pub input: InputPrimitive,
    pub output: OutputPrimitive,
    pub vertices_out: u32,
}

impl Default for GeometryParams {
    fn default() -> GeometryParams {
        GeometryParams {
            input: InputPrimitive::Triangles,
            output: OutputPrimitive::TriangleStrip,
            vertices_out: 0,
        }
    }
}

/// What a link takes besides the shader objects: the program's
/// parameters.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LinkOptions {
    pub geometry: GeometryParams,
    /// GL_PROGRAM_SEPARABLE (GL_ARB_separate_shader_objects): the program
    /// may hold any subset of the stages, a geometry stage without a
    /// vertex stage included, its other stages coming from other programs
    /// at draw time.
    pub separable: bool,
    /// GL_EXT_separate_shader_objects: a geometry stage without a vertex
    /// stage links when the geometry shader declares no user-defined
    /// inputs (only built-in ones, which a fixed-function or another
    /// program's vertex stage provides).
    pub lone_geometry: bool,
}

/// A link diagnostic and the shader object it points into, if any.
#[derive(Clone, Debug)]
pub struct LinkDiagnostic {
    pub shader: Option<usize>,
    pub diagnostic: Diagnostic,
}

/// The executable of one stage: every shader object of the stage merged.
#[derive(Clone, Debug)]
pub struct LinkedStage {
    pub stage: Stage,
    pub module: Module,
    /// The entry point (`main`) in `module`.
    pub main: FunctionId,
}

/// The result of linking (`GL_LINK_STATUS` is [`Program::ok`]).
#[derive(Clone, Debug, Default)]
pub struct Program {
    /// Linked stages, vertex before fragment; a stage without shader
    /// objects is absent (fixed function).
    pub stages: Vec<LinkedStage>,
    pub diagnostics: Vec<LinkDiagnostic>,
    /// The GL info log, rendered at link time.
    pub info_log: String,
}

impl Program {
    pub fn ok(&self) -> bool {
        !self.diagnostics.iter().any(|d| d.diagnostic.is_error())
    }

    pub fn stage(&self, stage: Stage) -> Option<&LinkedStage> {
        self.stages.iter().find(|s| s.stage == stage)
    }

    pub fn info_log(&self) -> &str {
        &self.info_log
    }
}

/// Links shader objects into a program whose parameters are the initial
/// ones ([`LinkOptions::default`]).
pub fn link(shaders: &[&Shader]) -> Program {
    link_with(shaders, &LinkOptions::default())
}

/// Links shader objects into a program with the program's parameters.
pub fn link_with(shaders: &[&Shader], opts: &LinkOptions) -> Program {
    let mut diags: Vec<LinkDiagnostic> = Vec::new();
    let mut program = Program::default();
    if shaders.is_empty() {
        push(
            &mut diags,
            None,
            Code::LinkNoMain,
            "no shaders attached to the program",
        );
    }
    for (i, s) in shaders.iter().enumerate() {
        if !s.ok() {
            push(
                &mut diags,
                None,
                Code::LinkNoMain,
                format!("{} shader {} did not compile", s.stage.name(), i),
            );
        }
    }
    // How messages name a shader object: its name, or its index.
    let names: Vec<String> = shaders
        .iter()
        .enumerate()
        .map(|(i, s)| {
            if s.source.name.is_empty() || s.source.name == "<shader>" {
                format!("shader {i}")
            } else {
                format!("`{}'", s.source.name)
            }
        })
        .collect();
    let ext_geometry = if diags.is_empty() {
        ext_geometry_modules(shaders, &opts.geometry, &mut diags)
    } else {
        Vec::new()
    };
    // GL_ARB_compute_shader: a program with a compute shader has no other
    // stage.
    let compute = shaders.iter().any(|s| s.stage == Stage::Compute);
    if compute && shaders.iter().any(|s| s.stage != Stage::Compute) {
        push(
            &mut diags,
            None,
            Code::LinkInterfaceMismatch,
            "a program with a compute shader can have no other stage",
        );
    }
    if diags.is_empty() {
        for stage in [
            Stage::Vertex,
            Stage::TessControl,
            Stage::TessEvaluation,
            Stage::Geometry,
            Stage::Fragment,
            Stage::Compute,
        ] {
            let objects: Vec<(usize, &Module)> = shaders
                .iter()
                .enumerate()
                .filter(|(_, s)| s.stage == stage)
                .filter_map(|(i, s)| {
                    let again = ext_geometry.iter().find(|(j, _)| *j == i);
                    again.map(|(_, m)| m).or(s.module.as_ref()).map(|m| (i, m))
                })
                .collect();
            if objects.is_empty() {
                continue;
            }
            if let Some(linked) = merge_stage(stage, &objects, &names, &mut diags) {
                check_limits(&linked, &mut diags);
                check_locations(&linked, &mut diags);
                program.stages.push(linked);
            }
        }
        // The stages that read `gl_in[]' size its unsized members from
        // the stage before (only the vertex stage's are loose globals).
        for i in 0..program.stages.len() {
            if matches!(
                program.stages[i].stage,
                Stage::TessControl | Stage::TessEvaluation | Stage::Geometry
            ) {
                let mut s = program.stages.remove(i);
                let prev = (i > 0)
                    .then(|| &program.stages[i - 1].module)
                    .filter(|m| m.stage == Stage::Vertex);
                redeclarations::size_gl_in_members(&mut s.module, prev);
                program.stages.insert(i, s);
            }
        }
        check_stage_chain(&program, opts, &mut diags);
    }
    program.info_log = render_link_log(&diags, shaders);
    program.diagnostics = diags;
    if !program.ok() {
        program.stages.clear();
    }
    program
}

/// The interfaces between the program's stages, in pipeline order (its
/// stages are sorted so): each consecutive pair matches as
/// [`check_interface`] says, stages further apart share their uniforms
/// ([`check_uniforms`]). GL 3.2 §2.12.2, GL_EXT_geometry_shader4 and
/// GL_ARB_tessellation_shader §2.14.2: a program with a geometry or
/// tessellation stage has a vertex stage (unless separable).
fn check_stage_chain(program: &Program, opts: &LinkOptions, diags: &mut Vec<LinkDiagnostic>) {
    let chain: Vec<&LinkedStage> = program
        .stages
        .iter()
        .filter(|s| s.stage != Stage::Compute)
        .collect();
    let has_vertex = chain.iter().any(|s| s.stage == Stage::Vertex);
    if !has_vertex && !opts.separable {
        if let Some(s) = chain.iter().find(|s| {
            matches!(s.stage, Stage::TessControl | Stage::TessEvaluation)
                || (s.stage == Stage::Geometry && !lone_geometry_ok(s, opts))
        }) {
            push(
                diags,
                None,
                Code::LinkNoMain,
                format!(
                    "the program has a {} shader but no vertex shader; attach one",
                    s.stage.name()
                ),
            );
            return;
        }
    }
    for (i, pair) in chain.windows(2).enumerate() {
        let (v, f) = (pair[0], pair[1]);
        check_interface(v, f, diags);
        if matches!(
            f.stage,
            Stage::TessControl | Stage::TessEvaluation | Stage::Geometry
        ) {
            redeclarations::check_per_vertex_interface(&v.module, &f.module, diags);
        }
        for earlier in &chain[..i] {
            check_uniforms(earlier, f, diags);
        }
    }
}

/// Whether a geometry stage may link without a vertex stage under
/// [`LinkOptions::lone_geometry`]: it declares no user-defined input.
fn lone_geometry_ok(g: &LinkedStage, opts: &LinkOptions) -> bool {
    opts.lone_geometry
        && !g
            .module
            .globals
            .iter()
            .any(|x| x.storage == crate::ir::Storage::PerVertexInput && !x.builtin)
}

/// The modules of the program's GL_EXT_geometry_shader4 geometry shader
/// objects, compiled again with the program's input primitive and given
/// its three parameters as layouts (see the module docs), by object
/// index. Errors of those compiles, and a vertex count of 0 or over the
/// limit, are link errors.
fn ext_geometry_modules(
    shaders: &[&Shader],
    params: &GeometryParams,
    diags: &mut Vec<LinkDiagnostic>,
) -> Vec<(usize, Module)> {
    let ext: Vec<(usize, &Shader)> = shaders
        .iter()
        .enumerate()
        .filter(|(_, s)| s.stage == Stage::Geometry && s.language.ext_geometry_shader4())
        .map(|(i, s)| (i, *s))
        .collect();
    if ext.is_empty() {
        return Vec::new();
    }
    let count_ok = if params.vertices_out == 0 {
        push(
            diags,
            None,
            Code::LinkInterfaceMismatch,
            "the program's GEOMETRY_VERTICES_OUT is 0: a GL_EXT_geometry_shader4 geometry shader needs glProgramParameteriEXT(program, GL_GEOMETRY_VERTICES_OUT_EXT, n) with n > 0 before the link",
        );
        false
    } else if params.vertices_out > crate::limits::MAX_GEOMETRY_OUTPUT_VERTICES {
        push(
            diags,
            None,
            Code::LinkInterfaceMismatch,
            format!(
                "the program's GEOMETRY_VERTICES_OUT is {}, over GL_MAX_GEOMETRY_OUTPUT_VERTICES_EXT ({})",
                params.vertices_out,
                crate::limits::MAX_GEOMETRY_OUTPUT_VERTICES
            ),
        );
        false
    } else {
        true
    };
    let input = params.input;
    let mut out = Vec::new();
    for (i, s) in ext {
        let opts = CompileOptions {
            name: s.source.name.clone(),
            default_version: Some(s.language.version),
            compatibility_context: s.language.profile == Profile::Compatibility,
            geometry_input: Some(input),
            ..CompileOptions::new(Stage::Geometry)
        };
        let again = crate::compile(&s.source.strings(), &opts);
        match again.module {
            Some(mut m) if count_ok => {
                m.geometry = GeometryLayout {
                    input: Some(input),
                    output: Some(params.output),
                    max_vertices: Some(params.vertices_out),
                };
                out.push((i, m));
            }
            Some(_) => {}
            None => {
                for d in again.diagnostics.into_iter().filter(Diagnostic::is_error) {
                    diags.push(LinkDiagnostic {
                        shader: Some(i),
                        diagnostic: d.with_note(format!(
                            "the program's GEOMETRY_INPUT_TYPE is {}: input arrays have {} elements, and gl_VerticesIn is {}",
                            input.gl_name(),
                            input.vertices(),
                            input.vertices()
                        )),
                    });
                }
            }
        }
    }
    out
}

fn push(
    diags: &mut Vec<LinkDiagnostic>,
    shader: Option<usize>,
    code: Code,
    msg: impl Into<String>,
) {
    diags.push(LinkDiagnostic {
        shader,
        diagnostic: Diagnostic::error(code, None, msg),
    });
}

fn render_link_log(diags: &[LinkDiagnostic], shaders: &[&Shader]) -> String {
    let mut out = String::new();
    for d in diags {
        match d.shader.and_then(|i| shaders.get(i)) {
            Some(s) => out.push_str(&render_info_log(
                std::slice::from_ref(&d.diagnostic),
                &s.source,
            )),
            None => {
                let mut plain = d.diagnostic.clone();
                plain.span = None;
                out.push_str(&render_info_log(&[plain], &Default::default()));
            }
        }
    }
    out
}
