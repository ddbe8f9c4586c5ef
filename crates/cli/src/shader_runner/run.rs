//! Runs a parsed script on a GL context, the way piglit's `shader_runner`
//! does: requirements, then compiling every shader section, linking them
//! into one program (with `piglit_vertex` bound to attribute 0 and
//! `piglit_texcoord` to 1), or with `SSO ENABLED` each stage into a
//! separable program of its own bound in a program pipeline, the vertex
//! data, then the `[test]` commands in order.
//!
//! The verdict follows piglit's: each command line has a result; a failing
//! probe marks the test failed and the run continues ("Test failure on line
//! N"); some errors end the run at once (a shader that does not compile, a
//! uniform that does not exist, `link error` when the link succeeded, a
//! command of a later GL version, which is a skip). In addition to piglit,
//! a draw that raises a GL error or fails in the pipeline (for example a
//! shader loop over the executor's iteration budget) ends the run as a
//! failure with the reason: piglit relies on the driver never doing that.

use super::command::{self, Command, LightValues, TexParamValue, UniformType, UniformValues};
use super::gl_api::GlApi;
use super::probe::{self, ProbeMode};
use super::script::{Cmp, Requirement, Script, Stage, VersionReq};
use gl::enums::*;
mod textures;

/// piglit's verdicts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    Pass,
    Warn,
    Fail,
    Skip,
}

impl Verdict {
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Pass => "pass",
            Verdict::Warn => "warn",
            Verdict::Fail => "fail",
            Verdict::Skip => "skip",
        }
    }

    /// `piglit_report_result`'s exit status: 0 for pass, warn and skip.
    pub fn exit_code(self) -> u8 {
        match self {
            Verdict::Pass | Verdict::Warn | Verdict::Skip => 0,
            Verdict::Fail => 1,
        }
    }
}

/// The window a script asks for (`SIZE`, `depthbuffer`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WindowConfig {
    pub width: i32,
    pub height: i32,
    pub depth: bool,
    /// The context the script asks for ([`required_api`]).
    pub api: gl::Api,
}

/// piglit's default `shader_runner` window.
pub const DEFAULT_SIZE: i32 = 250;

/// The window for a script: 250x250 RGBA, a depth buffer only when
/// `depthbuffer` is required.
pub fn window_config(script: &Script) -> WindowConfig {
    let mut cfg = WindowConfig {
        width: DEFAULT_SIZE,
        height: DEFAULT_SIZE,
        depth: false,
        api: required_api(script),
    };
    for (_, r) in &script.requirements {
        match r {
            Requirement::Size(w, h) => {
                cfg.width = *w as i32;
                cfg.height = *h as i32;
            }
            Requirement::DepthBuffer => cfg.depth = true,
            _ => {}
        }
    }
    cfg
}

/// The GL version a GLSL version needs (the GL that introduced it).
fn gl_for_glsl(glsl: u32) -> u32 {
    match glsl {
        0..=110 => 20,
        111..=120 => 21,
        121..=130 => 30,
        131..=140 => 31,
        141..=150 => 32,
        v => v / 10,
    }
}

/// The context piglit's shader_runner asks for before reading the script
/// (its `get_required_config`): the `GL` requirement if it is `>=`, `>`
/// or `==` (else 1.0), raised to what the `GLSL` requirement needs; from
/// 3.1 on a core context unless the requirement says `COMPAT` (piglit's
/// framework tries core first, and gets it), below a compatibility one.
/// shaderbox answers with the API [`gl::Api::for_request`] gives.
pub fn required_api(script: &Script) -> gl::Api {
    let mut gl_req = (10, false, false);
    let mut glsl = 0;
    for (_, r) in &script.requirements {
        match r {
            Requirement::Gl(v) if !v.es && matches!(v.cmp, Cmp::Ge | Cmp::Gt | Cmp::Eq) => {
                gl_req = (v.number, v.core, v.compat)
            }
            Requirement::Glsl(v) if !v.es && matches!(v.cmp, Cmp::Ge | Cmp::Gt | Cmp::Eq) => {
                glsl = v.number
            }
            _ => {}
        }
    }
    let (mut num, core, compat) = gl_req;
    num = num.max(gl_for_glsl(glsl));
    let profile = if num >= 31 && (core || !compat) {
        gl::Profile::Core
    } else {
        gl::Profile::Compatibility
    };
    let major = (num / 10) as i32;
    let minor = (num % 10) as i32;
    // A version beyond shaderbox's: the newest context of the profile,
    // whose version check then skips the test as piglit's would.
    gl::Api::for_request(major, minor, profile).unwrap_or(match profile {
        gl::Profile::Core => gl::Api::GL33_CORE,
        gl::Profile::Compatibility => gl::Api::GL33_COMPAT,
    })
}

/// What a run printed and its verdict.
#[derive(Debug, Default)]
pub struct Report {
    pub stdout: String,
    pub stderr: String,
}

/// An early end of the run.
struct Stop(Verdict);

/// A `[geometry layout]` line as glProgramParameteriEXT's (pname,
/// value).
fn geometry_parameter(text: &str) -> Option<(u32, i32)> {
    let mode = |name: &str| {
        super::command::draw_mode(name.trim())
            .ok()
            .map(|m| m as i32)
    };
    if let Some(m) = text.strip_prefix("input type ") {
        return Some((GL_GEOMETRY_INPUT_TYPE_EXT, mode(m)?));
    }
    if let Some(m) = text.strip_prefix("output type ") {
        return Some((GL_GEOMETRY_OUTPUT_TYPE_EXT, mode(m)?));
    }
    let n = text.strip_prefix("vertices out ")?.trim().parse().ok()?;
    Some((GL_GEOMETRY_VERTICES_OUT_EXT, n))
}

/// piglit's fixed passthrough vertex shader.
const PASSTHROUGH_VS: &str = "#if __VERSION__ >= 130\n\
in vec4 piglit_vertex;\n\
#else\n\
attribute vec4 piglit_vertex;\n\
#endif\n\
void main() { gl_Position = piglit_vertex; }\n";

/// Attribute locations piglit binds before linking.
const PIGLIT_ATTRIB_POS: u32 = 0;
const PIGLIT_ATTRIB_TEX: u32 = 1;

/// Upper bound on the pixels one probe reads (4096x4096, 256 MiB of
/// floats): bounds the memory a script can make a probe allocate.
const MAX_PROBE_PIXELS: i64 = 1 << 24;

pub struct Runner<'a, G: GlApi> {
    gl: &'a mut G,
    file: String,
    width: i32,
    height: i32,
    tolerance: [f32; 4],
    probe_mode: ProbeMode,
    glsl_required: Option<u32>,
    prog: u32,
    link_ok: bool,
    prog_in_use: bool,
    prog_err_info: String,
    link_error_expected: bool,
    clear_bits: u32,
    vbo_rows: Option<usize>,
    ignore_missing_uniforms: bool,
    /// The buffer of each active uniform block of the program, bound to
    /// the binding point of the block's index (piglit's `setup_ubos`).
    ubo_buffers: Vec<u32>,
    /// `ubo array index`.
    ubo_array_index: u32,
    /// The buffers of the `ssbo` commands, by storage binding point.
    ssbos: std::collections::BTreeMap<u32, u32>,
    /// `SSO ENABLED`: the program pipeline holding one separable program
    /// per stage (0 without), and each stage's program by shader type.
    pipeline: u32,
    sso: bool,
    stage_programs: Vec<(u32, u32)>,
    /// A core-profile context, which has no fixed-function texturing to
    /// enable.
    core: bool,
    report: Report,
}

impl<'a, G: GlApi> Runner<'a, G> {
    pub fn new(gl: &'a mut G, file: &str, window: WindowConfig) -> Self {
        Runner {
            gl,
            file: file.to_string(),
            width: window.width,
            height: window.height,
            tolerance: probe::DEFAULT_TOLERANCE,
            probe_mode: ProbeMode::Float,
            glsl_required: None,
            prog: 0,
            link_ok: false,
            prog_in_use: false,
            prog_err_info: String::new(),
            link_error_expected: false,
            clear_bits: 0,
            vbo_rows: None,
            ignore_missing_uniforms: false,
            ubo_buffers: Vec::new(),
            ubo_array_index: 0,
            ssbos: Default::default(),
            pipeline: 0,
            sso: false,
            stage_programs: Vec::new(),
            core: window.api.is_core(),
            report: Report::default(),
        }
    }

    fn out(&mut self, text: impl AsRef<str>) {
        self.report.stdout.push_str(text.as_ref());
        self.report.stdout.push('\n');
    }

    fn err(&mut self, text: impl AsRef<str>) {
        self.report.stderr.push_str(text.as_ref());
        self.report.stderr.push('\n');
    }

    /// Runs the script; returns the verdict and what was printed.
    pub fn run(mut self, script: &Script) -> (Verdict, Report) {
        let verdict = match self.run_inner(script) {
            Ok(v) => v,
            Err(Stop(v)) => v,
        };
        (verdict, self.report)
    }

    fn run_inner(&mut self, script: &Script) -> Result<Verdict, Stop> {
        self.check_requirements(script)?;
        if let Some((line, header)) = script.unsupported_sections.first() {
            let msg = format!(
                "{}:{line}: section {header} needs a pipeline stage shaderbox's shader runner does not run yet",
                self.file
            );
            self.out(msg);
            return Err(Stop(Verdict::Skip));
        }
        self.compile_and_link(script)?;
        if self.link_ok {
            if let Some(vd) = &script.vertex_data {
                self.program_must_be_in_use()?;
                self.setup_vertex_data(vd)?;
            }
        }
        // Parse every command before running any: a malformed line fails
        // the test with its line number.
        let mut commands = Vec::new();
        for (number, text) in &script.test_lines {
            match command::parse(text) {
                Ok(Some(c)) => commands.push((*number, c)),
                Ok(None) => {}
                Err(e) => {
                    let msg = format!("{}:{number}: {e}", self.file);
                    self.out(msg);
                    return Err(Stop(Verdict::Fail));
                }
            }
        }
        let mut full = Verdict::Pass;
        for (number, cmd) in &commands {
            let result = self.execute(*number, cmd)?;
            if result != Verdict::Pass {
                self.out(format!("Test failure on line {number}"));
                full = result;
            }
        }
        if !self.link_ok && !self.link_error_expected {
            full = self.must_be_in_use_verdict();
        }
        Ok(full)
    }

    // ---- requirements ------------------------------------------------------

    fn context_versions(&mut self) -> (u32, u32) {
        let gl = parse_version_string(&self.gl.get_string(GL_VERSION), false).unwrap_or(21);
        let glsl = parse_version_string(&self.gl.get_string(GL_SHADING_LANGUAGE_VERSION), true)
            .unwrap_or(120);
        (gl, glsl)
    }

    fn limit_value(&mut self, name: &str, gl_version: u32) -> Option<i32> {
        let pname = match name {
            "GL_MAX_VARYING_COMPONENTS" | "GL_MAX_VARYING_FLOATS" => GL_MAX_VARYING_FLOATS,
            "GL_MAX_FRAGMENT_UNIFORM_COMPONENTS" => GL_MAX_FRAGMENT_UNIFORM_COMPONENTS,
            "GL_MAX_VERTEX_UNIFORM_COMPONENTS" => GL_MAX_VERTEX_UNIFORM_COMPONENTS,
            "GL_MAX_VERTEX_ATTRIBS" => GL_MAX_VERTEX_ATTRIBS,
            "GL_MAX_TEXTURE_IMAGE_UNITS" => GL_MAX_TEXTURE_IMAGE_UNITS,
            "GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS" => GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS,
            "GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS" => GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS,
            "GL_MAX_TEXTURE_COORDS" => GL_MAX_TEXTURE_COORDS,
            "GL_MAX_CLIP_PLANES" => GL_MAX_CLIP_PLANES,
            "GL_MAX_DRAW_BUFFERS" => GL_MAX_DRAW_BUFFERS,
            "GL_MAX_TEXTURE_SIZE" => GL_MAX_TEXTURE_SIZE,
            // GL 3.2's (piglit queries it from 3.2 on).
            "GL_MAX_VERTEX_OUTPUT_COMPONENTS" if gl_version >= 32 => {
                GL_MAX_VERTEX_OUTPUT_COMPONENTS
            }
            // Not queried below OpenGL 3.2 / without program binaries.
            "GL_MAX_VERTEX_OUTPUT_COMPONENTS" | "GL_NUM_PROGRAM_BINARY_FORMATS" => return Some(0),
            // GL_ARB_shader_storage_buffer_object and GL_ARB_compute_shader.
            "GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS" => GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS,
            "GL_MAX_GEOMETRY_SHADER_STORAGE_BLOCKS" => GL_MAX_GEOMETRY_SHADER_STORAGE_BLOCKS,
            "GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS" => GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS,
            "GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS" => GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS,
            "GL_MAX_COMBINED_SHADER_STORAGE_BLOCKS" => GL_MAX_COMBINED_SHADER_STORAGE_BLOCKS,
            "GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS" => GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS,
            "GL_MAX_SHADER_STORAGE_BLOCK_SIZE" => GL_MAX_SHADER_STORAGE_BLOCK_SIZE,
            "GL_MAX_COMPUTE_SHARED_MEMORY_SIZE" => GL_MAX_COMPUTE_SHARED_MEMORY_SIZE,
            "GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS" => GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS,
            "GL_MAX_COMPUTE_UNIFORM_COMPONENTS" => GL_MAX_COMPUTE_UNIFORM_COMPONENTS,
            "GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS" => GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS,
            _ => return None,
        };
        let mut v = [0i32; 4];
        self.gl.get_integer_v(pname, &mut v);
        Some(v[0])
    }

    fn check_requirements(&mut self, script: &Script) -> Result<(), Stop> {
        let (gl_version, glsl_version) = self.context_versions();
        let extensions = self.gl.get_string(GL_EXTENSIONS);
        let has_ext = |name: &str| extensions.split_whitespace().any(|e| e == name);
        for (line, req) in &script.requirements {
            match req {
                Requirement::Glsl(v) => {
                    self.glsl_required = Some(v.number);
                    if v.cmp != Cmp::Ge {
                        self.out(format!(
                            "{}:{line}: Unsupported GLSL version comparison",
                            self.file
                        ));
                        return Err(Stop(Verdict::Fail));
                    }
                    if v.es || !v.cmp.holds(v.number, glsl_version) {
                        self.out(format!(
                            "Test requires {} {}.  Actual version GLSL {}.{:02}.",
                            v.cmp.as_str(),
                            glsl_name(v),
                            glsl_version / 100,
                            glsl_version % 100
                        ));
                        return Err(Stop(Verdict::Skip));
                    }
                }
                Requirement::Gl(v) => {
                    if v.es || !v.cmp.holds(v.number, gl_version) {
                        self.out(format!(
                            "Test requires {} GL{} {}.{}.  Actual version is GL {}.{}.",
                            v.cmp.as_str(),
                            if v.es { " ES" } else { "" },
                            v.number / 10,
                            v.number % 10,
                            gl_version / 10,
                            gl_version % 10
                        ));
                        return Err(Stop(Verdict::Skip));
                    }
                }
                Requirement::Extension { name, present } => {
                    if has_ext(name) != *present {
                        self.out(format!("Test requires unsupported extension {name}"));
                        return Err(Stop(Verdict::Skip));
                    }
                }
                Requirement::Limit { name, cmp, value } => {
                    let Some(actual) = self.limit_value(name, gl_version) else {
                        self.err(format!(
                            "{}:{line}: Invalid comparison enum at: {name}",
                            self.file
                        ));
                        return Err(Stop(Verdict::Fail));
                    };
                    if !cmp.holds(*value, actual) {
                        self.out(format!(
                            "Test requires {name} {} {value}.  The driver supports {actual}.",
                            cmp.as_str()
                        ));
                        return Err(Stop(Verdict::Skip));
                    }
                }
                Requirement::Unsupported(what) => {
                    self.out(format!(
                        "Test requires {what}, which shaderbox does not implement"
                    ));
                    return Err(Stop(Verdict::Skip));
                }
                Requirement::IgnoreMissingUniforms => self.ignore_missing_uniforms = true,
                Requirement::SeparateShaderObjects => {
                    let name = "GL_ARB_separate_shader_objects";
                    if gl_version < 41 && !has_ext(name) {
                        self.out(format!("Test requires unsupported extension {name}"));
                        return Err(Stop(Verdict::Skip));
                    }
                    self.sso = true;
                }
                Requirement::Size(..) | Requirement::DepthBuffer | Requirement::Rlimit(_) => {}
            }
        }
        Ok(())
    }

    // ---- shaders -------------------------------------------------------------

    fn compile_and_link(&mut self, script: &Script) -> Result<(), Stop> {
        if script.shaders.is_empty() {
            return Ok(());
        }
        let mut shaders = Vec::new();
        for section in &script.shaders {
            let Some(required) = self.glsl_required else {
                self.out("GLSL version requirement missing");
                return Err(Stop(Verdict::Fail));
            };
            let (kind, short) = match section.stage {
                Stage::Vertex => (GL_VERTEX_SHADER, "VS"),
                Stage::Geometry => (GL_GEOMETRY_SHADER, "GS"),
                Stage::Fragment => (GL_FRAGMENT_SHADER, "FS"),
                Stage::Compute => (GL_COMPUTE_SHADER, "CS"),
            };
            let text = section.source.as_deref().unwrap_or(PASSTHROUGH_VS);
            let shader = self.gl.create_shader(kind);
            if text.contains("#version ") {
                self.gl.shader_source(shader, &[text]);
            } else {
                let version = format!("#version {required}\n");
                self.gl.shader_source(shader, &[&version, text]);
            }
            self.gl.compile_shader(shader);
            let mut ok = [0i32];
            self.gl.get_shader_iv(shader, GL_COMPILE_STATUS, &mut ok);
            if ok[0] == 0 {
                let log = self.gl.get_shader_info_log(shader);
                self.err(format!(
                    "Failed to compile {short} ({}:{}): {log}",
                    self.file, section.line
                ));
                return Err(Stop(Verdict::Fail));
            }
            shaders.push((kind, shader));
        }
        if self.sso {
            let result = self.link_separable(script, &shaders);
            for (_, s) in shaders {
                self.gl.delete_shader(s);
            }
            return result;
        }
        let prog = self.gl.create_program();
        self.prog = prog;
        for &(_, s) in &shaders {
            self.gl.attach_shader(prog, s);
        }
        self.program_parameters(script, prog)?;
        self.gl.link_program(prog);
        let mut ok = [0i32];
        self.gl.get_program_iv(prog, GL_LINK_STATUS, &mut ok);
        if ok[0] != 0 {
            self.link_ok = true;
            self.gl.use_program(prog);
            if self.gl.get_error() == GL_NO_ERROR {
                self.prog_in_use = true;
                self.setup_ubos(prog);
            } else {
                self.prog_err_info = self.gl.get_program_info_log(prog);
            }
        } else {
            self.prog_err_info = self.gl.get_program_info_log(prog);
        }
        for (_, s) in shaders {
            self.gl.delete_shader(s);
        }
        Ok(())
    }

    /// What the runner sets on a program before linking it: the piglit
    /// attribute bindings and the `[geometry layout]` parameters.
    fn program_parameters(&mut self, script: &Script, prog: u32) -> Result<(), Stop> {
        self.gl
            .bind_attrib_location(prog, PIGLIT_ATTRIB_POS, "piglit_vertex");
        self.gl
            .bind_attrib_location(prog, PIGLIT_ATTRIB_TEX, "piglit_texcoord");
        for (line, text) in &script.geometry_layout {
            let Some((pname, value)) = geometry_parameter(text) else {
                self.err(format!(
                    "{}:{line}: unknown [geometry layout] line `{text}' (input type MODE, output type MODE or vertices out N)",
                    self.file
                ));
                return Err(Stop(Verdict::Fail));
            };
            self.gl.program_parameter_i(prog, pname, value);
        }
        Ok(())
    }

    /// `SSO ENABLED` (piglit's `link_sso`): the shader objects of each
    /// stage linked into a separable program (GL_PROGRAM_SEPARABLE), made
    /// the stage's program in a program pipeline, which is bound. A
    /// stage that does not link fails the test at once.
    fn link_separable(&mut self, script: &Script, shaders: &[(u32, u32)]) -> Result<(), Stop> {
        let pipeline = self.gl.gen_program_pipeline();
        self.pipeline = pipeline;
        for (kind, bit, short) in [
            (GL_VERTEX_SHADER, GL_VERTEX_SHADER_BIT, "VS"),
            (GL_GEOMETRY_SHADER, GL_GEOMETRY_SHADER_BIT, "GS"),
            (GL_FRAGMENT_SHADER, GL_FRAGMENT_SHADER_BIT, "FS"),
        ] {
            let objects: Vec<u32> = shaders
                .iter()
                .filter(|(k, _)| *k == kind)
                .map(|&(_, s)| s)
                .collect();
            if objects.is_empty() {
                continue;
            }
            let prog = self.gl.create_program();
            self.gl
                .program_parameter_i(prog, GL_PROGRAM_SEPARABLE, GL_TRUE as i32);
            for &s in &objects {
                self.gl.attach_shader(prog, s);
            }
            self.program_parameters(script, prog)?;
            self.gl.link_program(prog);
            let mut ok = [0i32];
            self.gl.get_program_iv(prog, GL_LINK_STATUS, &mut ok);
            if ok[0] == 0 {
                let log = self.gl.get_program_info_log(prog);
                self.err(format!("SSO glLinkProgram({short}) failed: {log}"));
                return Err(Stop(Verdict::Fail));
            }
            self.gl.use_program_stages(pipeline, bit, prog);
            self.stage_programs.push((kind, prog));
        }
        self.gl.bind_program_pipeline(pipeline);
        self.link_ok = true;
        if self.gl.get_error() == GL_NO_ERROR {
            self.prog_in_use = true;
        } else {
            self.prog_err_info = "the program pipeline could not be bound".into();
        }
        // Attribute queries ask the vertex stage's program.
        self.prog = self
            .stage_programs
            .iter()
            .find(|(k, _)| *k == GL_VERTEX_SHADER)
            .or(self.stage_programs.first())
            .map_or(0, |&(_, p)| p);
        Ok(())
    }

    /// The program `uniform` commands set: the current program, or with
    /// `SSO ENABLED` the pipeline's active program (`active shader
    /// program`).
    fn uniform_program(&mut self) -> u32 {
        if self.sso {
            self.gl
                .get_program_pipeline_iv(self.pipeline, GL_ACTIVE_PROGRAM) as u32
        } else {
            self.current_program()
        }
    }

    /// A zeroed buffer of its data size for each active uniform block,
    /// block `i` on binding point `i`.
    fn setup_ubos(&mut self, prog: u32) {
        let mut n = [0i32];
        self.gl
            .get_program_iv(prog, GL_ACTIVE_UNIFORM_BLOCKS, &mut n);
        self.ubo_buffers.clear();
        for i in 0..n[0].max(0) as u32 {
            let size = self
                .gl
                .get_active_uniform_block_iv(prog, i, GL_UNIFORM_BLOCK_DATA_SIZE);
            let b = self.gl.gen_buffer();
            self.gl.bind_buffer(GL_UNIFORM_BUFFER, b);
            self.gl.buffer_data(
                GL_UNIFORM_BUFFER,
                &vec![0; size.max(0) as usize],
                GL_STATIC_DRAW,
            );
            self.gl.uniform_block_binding(prog, i, i);
            self.gl.bind_buffer_base(GL_UNIFORM_BUFFER, i, b);
            self.ubo_buffers.push(b);
        }
    }

    /// A `uniform` command naming a member of a uniform block writes the
    /// values into the block's buffer at the member's offset, with its
    /// array and matrix strides (piglit's `set_ubo_uniform`). False when
    /// `name` is not a block member.
    fn set_ubo_uniform(&mut self, ty: UniformType, name: &str, values: &UniformValues) -> bool {
        let prog = self.current_program();
        if prog == 0 || self.ubo_buffers.is_empty() {
            return false;
        }
        // GL names arrays by their first element: `a[2]` is element 2 of
        // the uniform `a`.
        let (base, element) = match name.strip_suffix(']').and_then(|n| n.rsplit_once('[')) {
            Some((b, i)) => match i.parse::<i32>() {
                Ok(i) => (b, i),
                Err(_) => (name, 0),
            },
            None => (name, 0),
        };
        let index = self.gl.get_uniform_index(prog, base);
        if index == gl::uniform_block::INVALID_INDEX {
            return false;
        }
        let gl = &mut *self.gl;
        let block = gl.get_active_uniform_iv(prog, index, GL_UNIFORM_BLOCK_INDEX);
        if block < 0 {
            return false;
        }
        let Some(&buffer) = self
            .ubo_buffers
            .get(block as usize + self.ubo_array_index as usize)
        else {
            return false;
        };
        let offset = gl.get_active_uniform_iv(prog, index, GL_UNIFORM_OFFSET)
            + element * gl.get_active_uniform_iv(prog, index, GL_UNIFORM_ARRAY_STRIDE);
        let matrix_stride = gl.get_active_uniform_iv(prog, index, GL_UNIFORM_MATRIX_STRIDE);
        let row_major = gl.get_active_uniform_iv(prog, index, GL_UNIFORM_IS_ROW_MAJOR) != 0;
        let words: Vec<[u8; 4]> = match values {
            UniformValues::Floats(v) => v.iter().map(|f| f.to_ne_bytes()).collect(),
            UniformValues::Ints(v) => v.iter().map(|i| i.to_ne_bytes()).collect(),
            UniformValues::Uints(v) => v.iter().map(|u| u.to_ne_bytes()).collect(),
        };
        gl.bind_buffer(GL_UNIFORM_BUFFER, buffer);
        let (cols, rows) = match ty {
            UniformType::Mat(c, r) => (c as i32, r as i32),
            _ => (1, ty.components() as i32),
        };
        for (i, w) in words.iter().enumerate().take((cols * rows) as usize) {
            let (c, r) = (i as i32 / rows, i as i32 % rows);
            let at = match ty {
                UniformType::Mat(..) if row_major => offset + r * matrix_stride + 4 * c,
                UniformType::Mat(..) => offset + c * matrix_stride + 4 * r,
                _ => offset + 4 * r,
            };
            gl.buffer_sub_data(GL_UNIFORM_BUFFER, at as isize, w);
        }
        true
    }

    /// `active uniform`: finds NAME among the active uniforms and compares
    /// glGetActiveUniformsiv (and, for the type, size and name length,
    /// glGetActiveUniform) with the expected value (piglit's
    /// `active_uniform`).
    fn active_uniform(&mut self, name: &str, pname: u32, expected: i32) -> bool {
        let prog = self.prog;
        let mut n = [0i32];
        self.gl.get_program_iv(prog, GL_ACTIVE_UNIFORMS, &mut n);
        for i in 0..n[0].max(0) as u32 {
            let Some((got_name, size, ty)) = self.gl.get_active_uniform(prog, i) else {
                self.err("glGetActiveUniform error");
                return false;
            };
            if got_name != name {
                continue;
            }
            let mut pass = true;
            let from_active = match pname {
                GL_UNIFORM_TYPE => Some(ty as i32),
                GL_UNIFORM_SIZE => Some(size),
                GL_UNIFORM_NAME_LENGTH => Some(got_name.len() as i32),
                _ => None,
            };
            if let Some(got) = from_active.filter(|&g| g != expected) {
                self.err(format!(
                    "glGetActiveUniform({name}, {pname:#06x}): expected {expected} ({expected:#06x}), got {got} ({got:#06x})"
                ));
                pass = false;
            }
            let got = self.gl.get_active_uniform_iv(prog, i, pname);
            if self.gl.get_error() != GL_NO_ERROR {
                self.err("glGetActiveUniformsiv error");
                return false;
            }
            if got != expected {
                self.err(format!(
                    "glGetActiveUniformsiv({name}, {pname:#06x}): expected {expected} ({expected:#06x}), got {got} ({got:#06x})"
                ));
                pass = false;
            }
            return pass;
        }
        self.err(format!("No active uniform named \"{name}\""));
        false
    }

    fn must_be_in_use_verdict(&mut self) -> Verdict {
        if !self.link_ok {
            let info = self.prog_err_info.clone();
            self.err(format!("Failed to link:\n{info}"));
            Verdict::Fail
        } else if !self.prog_in_use {
            let info = self.prog_err_info.clone();
            self.err(format!("Failed to use program: {info}"));
            Verdict::Fail
        } else {
            Verdict::Pass
        }
    }

    fn program_must_be_in_use(&mut self) -> Result<(), Stop> {
        match self.must_be_in_use_verdict() {
            Verdict::Pass => Ok(()),
            v => Err(Stop(v)),
        }
    }

    fn current_program(&self) -> u32 {
        if self.prog_in_use {
            self.prog
        } else {
            0
        }
    }

    fn setup_vertex_data(&mut self, vd: &super::script::VertexData) -> Result<(), Stop> {
        for col in &vd.columns {
            let values = vd.column_values(col);
            let size = col.components as i32;
            if col.name == "gl_Vertex" {
                self.gl.vertex_pointer(size, GL_FLOAT, 0, &values);
                self.gl.enable_client_state(GL_VERTEX_ARRAY);
                continue;
            }
            let prog = self.current_program();
            let loc = self.gl.get_attrib_location(prog, &col.name);
            if loc < 0 {
                self.out(format!(
                    "{}:{}: Unexpected vbo column name.  Got: {}",
                    self.file, vd.line, col.name
                ));
                return Err(Stop(Verdict::Fail));
            }
            if col.ty == GL_FLOAT {
                self.gl
                    .vertex_attrib_pointer(loc as u32, size, GL_FLOAT, false, 0, &values);
            } else {
                self.gl
                    .vertex_attrib_i_pointer(loc as u32, size, col.ty, 0, &values);
            }
            self.gl.enable_vertex_attrib_array(loc as u32);
        }
        self.vbo_rows = Some(vd.rows);
        Ok(())
    }

    // ---- commands ------------------------------------------------------------

    fn execute(&mut self, line: usize, cmd: &Command) -> Result<Verdict, Stop> {
        let gl = &mut *self.gl;
        match cmd {
            Command::ClearColor(c) => {
                gl.clear_color(c[0], c[1], c[2], c[3]);
                self.clear_bits |= GL_COLOR_BUFFER_BIT;
            }
            Command::ClearDepth(d) => {
                gl.clear_depth(f64::from(*d));
                self.clear_bits |= GL_DEPTH_BUFFER_BIT;
            }
            Command::ClearStencil(v) => {
                gl.clear_stencil(*v);
                self.clear_bits |= GL_STENCIL_BUFFER_BIT;
            }
            Command::StencilFunc {
                func,
                reference,
                mask,
            } => gl.stencil_func(*func, *reference, *mask),
            Command::StencilOp([fail, zfail, zpass]) => gl.stencil_op(*fail, *zfail, *zpass),
            Command::Clear => gl.clear(self.clear_bits),
            Command::ClipPlane { plane, equation } => {
                gl.clip_plane(GL_CLIP_PLANE0 + plane, equation)
            }
            Command::Color(c) => gl.color_4fv(c),
            Command::DrawRect {
                rect,
                ortho,
                tex,
                instances,
            } => {
                let result = self.must_be_in_use_verdict();
                let rect = if *ortho {
                    probe::ortho_rect(*rect, self.width, self.height)
                } else {
                    *rect
                };
                if result == Verdict::Pass {
                    self.draw_rect(line, rect, *tex, *instances)?;
                }
                return Ok(result);
            }
            Command::DrawArrays {
                mode,
                first,
                count,
                instances,
            } => {
                let result = self.must_be_in_use_verdict();
                if *first < 0 {
                    self.out("draw arrays 'first' must be >= 0");
                    return Err(Stop(Verdict::Fail));
                }
                if *count <= 0 {
                    self.out("draw arrays 'count' must be > 0");
                    return Err(Stop(Verdict::Fail));
                }
                if let Some(rows) = self.vbo_rows {
                    if *first as usize >= rows {
                        self.out(format!("draw arrays 'first' must be < {rows}"));
                        return Err(Stop(Verdict::Fail));
                    }
                    if *count as usize > rows - *first as usize {
                        self.out(format!("draw arrays cannot draw beyond {rows}"));
                        return Err(Stop(Verdict::Fail));
                    }
                }
                if result == Verdict::Pass {
                    self.draw(line, |gl| {
                        gl.draw_arrays_instanced(*mode, *first, *count, *instances)
                    })?;
                }
                return Ok(result);
            }
            Command::PolygonMode { face, mode } => gl.polygon_mode(*face, *mode),
            Command::ProvokingVertex(mode) => gl.provoking_vertex(*mode),
            Command::Enable(cap) => gl.enable(*cap),
            Command::Disable(cap) => gl.disable(*cap),
            Command::Frustum(f) => {
                gl.matrix_mode(GL_PROJECTION);
                gl.load_identity();
                let d = f.map(f64::from);
                gl.frustum(d[0], d[1], d[2], d[3], d[4], d[5]);
                gl.matrix_mode(GL_MODELVIEW);
                gl.load_identity();
            }
            Command::Hint { target, mode } => gl.hint(*target, *mode),
            Command::BlendFunc { src, dst } => gl.blend_func(*src, *dst),
            Command::Ortho(bounds) => {
                let [l, r, b, t] = match bounds {
                    Some(v) => v.map(f64::from),
                    None => [0.0, f64::from(self.width), 0.0, f64::from(self.height)],
                };
                gl.matrix_mode(GL_PROJECTION);
                gl.load_identity();
                gl.ortho(l, r, b, t, -1.0, 1.0);
                gl.matrix_mode(GL_MODELVIEW);
                gl.load_identity();
            }
            Command::ProbePixel { x, y, expected } => {
                return Ok(self.probe_rect(*x, *y, 1, 1, expected, false));
            }
            Command::RelativeProbePixel { rx, ry, expected } => {
                let x = probe::relative_coord(*rx, self.width);
                let y = probe::relative_coord(*ry, self.height);
                return Ok(self.probe_rect(x, y, 1, 1, expected, false));
            }
            Command::ProbeRect { rect, expected } => {
                let [x, y, w, h] = *rect;
                return Ok(self.probe_rect(x, y, w, h, expected, true));
            }
            Command::RelativeProbeRect { rect, expected } => {
                let x = probe::relative_extent(rect[0], self.width);
                let y = probe::relative_extent(rect[1], self.height);
                let w = probe::relative_extent(rect[2], self.width);
                let h = probe::relative_extent(rect[3], self.height);
                return Ok(self.probe_rect(x, y, w, h, expected, true));
            }
            Command::ProbeAll { expected, warn } => {
                let (w, h) = (self.width, self.height);
                let r = self.probe_rect(0, 0, w, h, expected, true);
                return Ok(if *warn && r == Verdict::Fail {
                    Verdict::Warn
                } else {
                    r
                });
            }
            Command::ProbeDepth { x, y, expected } => {
                let mut v = [f32::NAN];
                self.gl
                    .read_pixels_f32(*x, *y, 1, 1, GL_DEPTH_COMPONENT, &mut v);
                if !probe::depth_matches(v[0], *expected) {
                    self.out(format!(
                        "Probe depth at ({x},{y})\n  Expected: {expected:.6}\n  Observed: {:.6}",
                        v[0]
                    ));
                    return Ok(Verdict::Fail);
                }
            }
            Command::Tolerance(t) => self.tolerance = *t,
            Command::ShadeModel(m) => gl.shade_model(*m),
            Command::Texture(t) => self.texture(t),
            Command::TexParameter {
                target,
                pname,
                value,
            } => match value {
                TexParamValue::Enum(e) => gl.tex_parameter_i(*target, *pname, *e as i32),
                TexParamValue::Int(i) => gl.tex_parameter_i(*target, *pname, *i),
                TexParamValue::Float(f) => gl.tex_parameter_f(*target, *pname, *f),
                TexParamValue::Color(c) => gl.tex_parameter_fv(*target, *pname, c),
            },
            Command::Uniform {
                ty,
                name,
                values,
                missing,
            } => {
                let result = self.must_be_in_use_verdict();
                if *missing > 0 {
                    self.err(format!(
                        "{}:{line}: note: uniform {name} is given {missing} value(s) too few; using 0",
                        self.file
                    ));
                }
                self.set_uniform(*ty, name, values)?;
                return Ok(result);
            }
            Command::LinkError => {
                self.link_error_expected = true;
                if self.link_ok {
                    self.err("shader link error expected, but it was successful!");
                    return Err(Stop(Verdict::Fail));
                }
                let info = self.prog_err_info.clone();
                self.out(format!("Failed to link (as expected):\n{info}"));
            }
            Command::LinkSuccess => return Ok(self.must_be_in_use_verdict()),
            Command::Light {
                light,
                pname,
                values,
            } => match values {
                LightValues::Float(v) if v.len() == 1 => gl.light_f(*light, *pname, v[0]),
                LightValues::Float(v) => gl.light_fv(*light, *pname, v),
                LightValues::Int(v) if v.len() == 1 => gl.light_i(*light, *pname, v[0]),
                LightValues::Int(v) => gl.light_iv(*light, *pname, v),
            },
            Command::UboArrayIndex(i) => self.ubo_array_index = *i,
            Command::ActiveUniform {
                name,
                pname,
                expected,
            } => {
                // piglit ends the test at the first mismatch.
                if !self.active_uniform(name, *pname, *expected) {
                    return Err(Stop(Verdict::Fail));
                }
            }
            Command::ActiveShaderProgram(kind) => {
                let prog = self
                    .stage_programs
                    .iter()
                    .find(|(k, _)| k == kind)
                    .map(|&(_, p)| p);
                let Some(prog) = prog.filter(|_| self.sso) else {
                    self.out(format!(
                        "{}:{line}: `active shader program' needs `SSO ENABLED' and a shader of that stage",
                        self.file
                    ));
                    return Err(Stop(Verdict::Fail));
                };
                self.gl.active_shader_program(self.pipeline, prog);
            }
            Command::Compute(groups) => {
                let result = self.must_be_in_use_verdict();
                if result == Verdict::Pass {
                    let [x, y, z] = *groups;
                    self.draw(line, |gl| {
                        gl.dispatch_compute(x, y, z);
                        gl.memory_barrier(GL_ALL_BARRIER_BITS);
                    })?;
                }
                return Ok(result);
            }
            Command::SsboCreate { binding, size } => {
                // GL refuses stores over 1 GiB (GL_OUT_OF_MEMORY).
                if *size > 1 << 30 {
                    self.out(format!(
                        "{}:{line}: ssbo size {size} is over 1 GiB",
                        self.file
                    ));
                    return Err(Stop(Verdict::Fail));
                }
                let b = gl.gen_buffer();
                gl.bind_buffer(GL_SHADER_STORAGE_BUFFER, b);
                gl.buffer_data(GL_SHADER_STORAGE_BUFFER, &vec![0; *size], GL_DYNAMIC_DRAW);
                gl.bind_buffer_base(GL_SHADER_STORAGE_BUFFER, *binding, b);
                self.ssbos.insert(*binding, b);
            }
            Command::SsboSubData {
                binding,
                offset,
                words,
            } => {
                let b = self.ssbo(line, *binding)?;
                let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
                self.gl.bind_buffer(GL_SHADER_STORAGE_BUFFER, b);
                self.gl
                    .buffer_sub_data(GL_SHADER_STORAGE_BUFFER, *offset as isize, &bytes);
            }
            Command::ProbeSsbo {
                binding,
                offset,
                ty,
                op,
                expected,
            } => {
                let b = self.ssbo(line, *binding)?;
                self.gl.bind_buffer(GL_SHADER_STORAGE_BUFFER, b);
                let bytes =
                    self.gl
                        .get_buffer_sub_data(GL_SHADER_STORAGE_BUFFER, *offset as isize, 4);
                let Ok(word) = <[u8; 4]>::try_from(&bytes[..]) else {
                    self.out(format!(
                        "{}:{line}: ssbo {binding} has no word at offset {offset}",
                        self.file
                    ));
                    return Err(Stop(Verdict::Fail));
                };
                let value = u32::from_le_bytes(word);
                if !ty.holds(*op, *expected, value) {
                    self.out(format!(
                        "SSBO {binding} at offset {offset}: expected {} {}, got {}",
                        op.as_str(),
                        ty.show(*expected),
                        ty.show(value)
                    ));
                    return Ok(Verdict::Fail);
                }
            }
            Command::NeedsLaterGl(what) => {
                let msg = format!(
                    "{}:{line}: test requires {what}, which shaderbox's shader runner does not implement yet",
                    self.file
                );
                self.out(msg);
                return Err(Stop(Verdict::Skip));
            }
        }
        Ok(Verdict::Pass)
    }

    /// The buffer of an `ssbo` command at storage binding `binding`; a
    /// failed test when no `ssbo N SIZE` made one.
    fn ssbo(&mut self, line: usize, binding: u32) -> Result<u32, Stop> {
        match self.ssbos.get(&binding) {
            Some(&b) => Ok(b),
            None => {
                self.out(format!(
                    "{}:{line}: no ssbo at binding {binding}",
                    self.file
                ));
                Err(Stop(Verdict::Fail))
            }
        }
    }

    /// Runs a draw call and turns GL errors and pipeline failures into a
    /// failed test. Errors left by earlier calls (piglit never checks them)
    /// are reported on stderr and cleared first.
    fn draw(&mut self, line: usize, call: impl FnOnce(&mut G)) -> Result<(), Stop> {
        for _ in 0..16 {
            let e = self.gl.get_error();
            if e == GL_NO_ERROR {
                break;
            }
            self.err(format!(
                "note: GL error {} (0x{e:04x}) raised before line {line}",
                error_name(e)
            ));
        }
        let _ = self.gl.take_draw_failure();
        call(self.gl);
        if let Some(why) = self.gl.take_draw_failure() {
            self.out(format!("{}:{line}: draw failed: {why}", self.file));
            return Err(Stop(Verdict::Fail));
        }
        let e = self.gl.get_error();
        if e != GL_NO_ERROR {
            self.out(format!(
                "{}:{line}: draw raised GL error {} (0x{e:04x})",
                self.file,
                error_name(e)
            ));
            return Err(Stop(Verdict::Fail));
        }
        Ok(())
    }

    /// `piglit_draw_rect` / `piglit_draw_rect_tex`: a 4-vertex triangle
    /// strip from client arrays, through the generic attributes 0 and 1 when
    /// the program has an active `piglit_vertex`, else through the
    /// fixed-function vertex and texture coordinate arrays.
    fn draw_rect(
        &mut self,
        line: usize,
        rect: [f32; 4],
        tex: Option<[f32; 4]>,
        instances: i32,
    ) -> Result<(), Stop> {
        let verts = probe::rect_vertices(rect);
        let texcoords = tex.map(probe::rect_texcoords);
        let prog = self.current_program();
        let generic = prog != 0 && self.gl.get_attrib_location(prog, "piglit_vertex") != -1;
        if generic {
            self.gl
                .vertex_attrib_pointer(PIGLIT_ATTRIB_POS, 4, GL_FLOAT, false, 0, &verts);
            self.gl.enable_vertex_attrib_array(PIGLIT_ATTRIB_POS);
            if let Some(tc) = &texcoords {
                self.gl
                    .vertex_attrib_pointer(PIGLIT_ATTRIB_TEX, 2, GL_FLOAT, false, 0, tc);
                self.gl.enable_vertex_attrib_array(PIGLIT_ATTRIB_TEX);
            }
        } else {
            self.gl.vertex_pointer(4, GL_FLOAT, 0, &verts);
            self.gl.enable_client_state(GL_VERTEX_ARRAY);
            if let Some(tc) = &texcoords {
                self.gl.tex_coord_pointer(2, GL_FLOAT, 0, tc);
                self.gl.enable_client_state(GL_TEXTURE_COORD_ARRAY);
            }
        }
        let result = self.draw(line, |gl| {
            gl.draw_arrays_instanced(GL_TRIANGLE_STRIP, 0, 4, instances)
        });
        if generic {
            self.gl.disable_vertex_attrib_array(PIGLIT_ATTRIB_POS);
            if texcoords.is_some() {
                self.gl.disable_vertex_attrib_array(PIGLIT_ATTRIB_TEX);
            }
        } else {
            self.gl.disable_client_state(GL_VERTEX_ARRAY);
            if texcoords.is_some() {
                self.gl.disable_client_state(GL_TEXTURE_COORD_ARRAY);
            }
        }
        result
    }

    /// Compares a rectangle of the color buffer with one color.
    fn probe_rect(
        &mut self,
        x: i32,
        y: i32,
        w: i32,
        h: i32,
        expected: &[f32],
        rect: bool,
    ) -> Verdict {
        if w <= 0 || h <= 0 {
            return Verdict::Pass;
        }
        if i64::from(w) * i64::from(h) > MAX_PROBE_PIXELS {
            self.out(format!("probe rectangle {w}x{h} is too large"));
            return Verdict::Fail;
        }
        let n = expected.len().min(4);
        let count = (w as usize) * (h as usize);
        if rect && self.probe_mode == ProbeMode::Ubyte {
            let mut px = vec![0u8; count * 4];
            self.gl
                .read_pixels(x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
            for (i, p) in px.chunks_exact(4).enumerate() {
                if !probe::pixel_matches_ubyte(&p[..n], &expected[..n], &self.tolerance) {
                    let obs: Vec<f32> = p[..n].iter().map(|&b| f32::from(b) / 255.0).collect();
                    let (px_x, px_y) = (x + (i % w as usize) as i32, y + (i / w as usize) as i32);
                    let msg = probe::report(px_x, px_y, &expected[..n], &obs);
                    self.out(msg);
                    return Verdict::Fail;
                }
            }
            return Verdict::Pass;
        }
        // Pixels the read does not write (outside the window) stay NaN and
        // fail, as nothing sensible can be said of them.
        let mut px = vec![f32::NAN; count * 4];
        self.gl.read_pixels_f32(x, y, w, h, GL_RGBA, &mut px);
        for (i, p) in px.chunks_exact(4).enumerate() {
            if !probe::pixel_matches(&p[..n], &expected[..n], &self.tolerance) {
                let (px_x, px_y) = (x + (i % w as usize) as i32, y + (i / w as usize) as i32);
                let msg = probe::report(px_x, px_y, &expected[..n], &p[..n]);
                self.out(msg);
                return Verdict::Fail;
            }
        }
        Verdict::Pass
    }

    fn set_uniform(
        &mut self,
        ty: UniformType,
        name: &str,
        values: &UniformValues,
    ) -> Result<(), Stop> {
        if !name.starts_with(|c: char| c.is_ascii_digit()) && self.set_ubo_uniform(ty, name, values)
        {
            return Ok(());
        }
        let loc = if name.starts_with(|c: char| c.is_ascii_digit()) {
            crate::shader_runner::scan::scan_i32_base0(name).map_or(-1, |v| v.0)
        } else {
            let prog = self.uniform_program();
            let loc = if prog == 0 {
                -1
            } else {
                self.gl.get_uniform_location(prog, name)
            };
            if loc < 0 {
                if self.ignore_missing_uniforms {
                    return Ok(());
                }
                self.out(format!("cannot get location of uniform \"{name}\""));
                return Err(Stop(Verdict::Fail));
            }
            loc
        };
        let gl = &mut *self.gl;
        match (ty, values) {
            (UniformType::Float(n), UniformValues::Floats(v)) => match n {
                1 => gl.uniform_1fv(loc, 1, v),
                2 => gl.uniform_2fv(loc, 1, v),
                3 => gl.uniform_3fv(loc, 1, v),
                _ => gl.uniform_4fv(loc, 1, v),
            },
            (UniformType::Int(n) | UniformType::Bool(n), UniformValues::Ints(v)) => match n {
                1 => gl.uniform_1iv(loc, 1, v),
                2 => gl.uniform_2iv(loc, 1, v),
                3 => gl.uniform_3iv(loc, 1, v),
                _ => gl.uniform_4iv(loc, 1, v),
            },
            (UniformType::Uint(n), UniformValues::Uints(v)) => match n {
                1 => gl.uniform_1uiv(loc, 1, v),
                2 => gl.uniform_2uiv(loc, 1, v),
                3 => gl.uniform_3uiv(loc, 1, v),
                _ => gl.uniform_4uiv(loc, 1, v),
            },
            (UniformType::Mat(c, r), UniformValues::Floats(v)) => match (c, r) {
                (2, 2) => gl.uniform_matrix_2fv(loc, 1, false, v),
                (2, 3) => gl.uniform_matrix_2x3fv(loc, 1, false, v),
                (2, 4) => gl.uniform_matrix_2x4fv(loc, 1, false, v),
                (3, 2) => gl.uniform_matrix_3x2fv(loc, 1, false, v),
                (3, 3) => gl.uniform_matrix_3fv(loc, 1, false, v),
                (3, 4) => gl.uniform_matrix_3x4fv(loc, 1, false, v),
                (4, 2) => gl.uniform_matrix_4x2fv(loc, 1, false, v),
                (4, 3) => gl.uniform_matrix_4x3fv(loc, 1, false, v),
                _ => gl.uniform_matrix_4fv(loc, 1, false, v),
            },
            _ => {
                self.out(format!("uniform \"{name}\": values do not match the type"));
                return Err(Stop(Verdict::Fail));
            }
        }
        Ok(())
    }
}

/// `GLSL x.yy` for messages.
fn glsl_name(v: &VersionReq) -> String {
    format!(
        "GLSL{} {}.{:02}",
        if v.es { " ES" } else { "" },
        v.number / 100,
        v.number % 100
    )
}

/// The number at the start of a `GL_VERSION` / `GL_SHADING_LANGUAGE_VERSION`
/// string (`"2.1 shaderbox"` -> 21, `"1.20"` -> 120).
pub fn parse_version_string(s: &str, glsl: bool) -> Option<u32> {
    let s = s.trim_start_matches(|c: char| !c.is_ascii_digit());
    let (major, rest) = s.split_once('.')?;
    let minor: String = rest.chars().take_while(char::is_ascii_digit).collect();
    let major: u32 = major.parse().ok()?;
    let minor_v: u32 = minor.parse().ok()?;
    Some(if glsl {
        major * 100
            + if minor.len() == 1 {
                minor_v * 10
            } else {
                minor_v
            }
    } else {
        major * 10 + minor_v
    })
}

fn error_name(e: u32) -> &'static str {
    match e {
        GL_INVALID_ENUM => "GL_INVALID_ENUM",
        GL_INVALID_VALUE => "GL_INVALID_VALUE",
        GL_INVALID_OPERATION => "GL_INVALID_OPERATION",
        GL_STACK_OVERFLOW => "GL_STACK_OVERFLOW",
        GL_STACK_UNDERFLOW => "GL_STACK_UNDERFLOW",
        GL_OUT_OF_MEMORY => "GL_OUT_OF_MEMORY",
        _ => "(unrecognized error)",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn version_strings() {
        assert_eq!(parse_version_string("2.1 shaderbox 0.1", false), Some(21));
        assert_eq!(parse_version_string("1.20", true), Some(120));
        assert_eq!(parse_version_string("1.2", true), Some(120));
        assert_eq!(parse_version_string("OpenGL ES 3.0", false), Some(30));
        assert_eq!(parse_version_string("none", false), None);
    }

    #[test]
    fn window_configs() {
        let s = super::super::script::parse("[require]\nGLSL >= 1.10\nSIZE 20 30\ndepthbuffer\n")
            .unwrap();
        assert_eq!(
            window_config(&s),
            WindowConfig {
                width: 20,
                height: 30,
                depth: true,
                api: gl::Api::GL21,
            }
        );
        let s = super::super::script::parse("[require]\nGLSL >= 1.10\n").unwrap();
        assert_eq!(
            window_config(&s),
            WindowConfig {
                width: 250,
                height: 250,
                depth: false,
                api: gl::Api::GL21,
            }
        );
    }

    #[test]
    fn contexts_follow_piglits_choice() {
        let api = |req: &str| {
            required_api(&super::super::script::parse(&format!("[require]\n{req}\n")).unwrap())
        };
        assert_eq!(api("GLSL >= 1.20"), gl::Api::GL21);
        assert_eq!(api("GLSL >= 1.30"), gl::Api::GL33_COMPAT);
        assert_eq!(api("GLSL >= 1.40"), gl::Api::GL33_CORE);
        assert_eq!(api("GLSL >= 1.50\nGL COMPAT >= 3.2"), gl::Api::GL33_COMPAT);
        assert_eq!(api("GLSL >= 1.30\nGL >= 3.1"), gl::Api::GL33_CORE);
        assert_eq!(api("GLSL >= 1.10\nGL >= 2.1"), gl::Api::GL21);
        assert_eq!(api("GLSL >= 4.00"), gl::Api::GL33_CORE);
    }

    #[test]
    fn verdict_exit_codes() {
        assert_eq!(Verdict::Pass.exit_code(), 0);
        assert_eq!(Verdict::Warn.exit_code(), 0);
        assert_eq!(Verdict::Skip.exit_code(), 0);
        assert_eq!(Verdict::Fail.exit_code(), 1);
    }
}
