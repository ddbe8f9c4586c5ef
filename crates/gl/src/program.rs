//! Shader and program objects (GL 2.1 §2.15): creation, sources,
//! compilation, attachment, linking, deletion semantics, attribute
//! locations, glGetShaderiv/glGetProgramiv and the info logs.

use crate::enums::*;
use crate::uniform::{gl_type, SetterKind, UniformError, UniformTable, Word};
use crate::Context;
use glsl::ir::{Module, Storage};
use glsl::types::{Base, Type};
use glsl::{CompileOptions, Stage};
use std::collections::BTreeMap;
use std::sync::Arc;

/// A shader object.
#[derive(Clone, Debug)]
pub struct ShaderObj {
    pub kind: u32,
    pub source: Vec<String>,
    /// The result of the last glCompileShader.
    pub compiled: Option<Arc<glsl::Shader>>,
    pub delete_pending: bool,
}

impl ShaderObj {
    pub fn stage(&self) -> Stage {
        match self.kind {
            GL_VERTEX_SHADER => Stage::Vertex,
            GL_GEOMETRY_SHADER => Stage::Geometry,
            GL_COMPUTE_SHADER => Stage::Compute,
            _ => Stage::Fragment,
        }
    }

    pub fn compile_status(&self) -> bool {
        self.compiled.as_ref().is_some_and(|s| s.ok())
    }

    pub fn info_log(&self) -> String {
        self.compiled
            .as_ref()
            .map(|s| s.info_log())
            .unwrap_or_default()
    }
}

/// An active attribute or uniform as glGetActive* report it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ActiveInfo {
    pub name: String,
    pub size: i32,
    pub ty: u32,
}

/// A user attribute of a linked program and its location.
#[derive(Clone, Debug)]
pub struct AttribInfo {
    pub name: String,
    pub ty: Type,
    /// -1 for built-in attributes.
    pub location: i32,
}

/// The result of a successful link.
pub struct Executable {
    pub program: glsl::link::Program,
    pub uniforms: UniformTable,
    pub attribs: Vec<AttribInfo>,
    /// Lowered stages, built at link time; see [`crate::draw`].
    pub kernels: crate::kernels::Kernels,
    /// The compiled shader objects linked, in attachment order (the
    /// debugger maps source spans back to their text).
    pub shaders: Vec<Arc<glsl::Shader>>,
    /// The transform feedback varyings ([`crate::transform_feedback`])
    /// and GL_INTERLEAVED_ATTRIBS or GL_SEPARATE_ATTRIBS.
    pub feedback: Vec<crate::transform_feedback::FeedbackVarying>,
    pub feedback_mode: u32,
    /// The storage blocks and their binding points ([`crate::storage`]).
    pub storage_blocks: Vec<crate::storage::StorageBlock>,
}

impl Executable {
    pub fn modules(&self) -> Vec<&Module> {
        self.program.stages.iter().map(|s| &s.module).collect()
    }

    pub fn has_stage(&self, stage: Stage) -> bool {
        self.program.stage(stage).is_some()
    }
}

/// glBindFragDataLocation(Indexed) bindings: output name to (location,
/// index).
pub type FragBindings = BTreeMap<String, (u32, u32)>;

/// A program object.
#[derive(Default)]
pub struct ProgramObj {
    pub attached: Vec<u32>,
    pub bindings: BTreeMap<String, u32>,
    /// glBindFragDataLocation bindings ([`crate::program_outputs`]).
    pub frag_bindings: FragBindings,
    /// glTransformFeedbackVaryings' names and buffer mode (0 until set:
    /// GL_INTERLEAVED_ATTRIBS), for the next link.
    pub feedback_names: Vec<String>,
    pub feedback_mode: u32,
    /// glProgramParameteriEXT's geometry parameters (GL_EXT_geometry_shader4),
    /// for the next link of an EXT-form geometry shader.
    pub geometry: glsl::link::GeometryParams,
    /// GL_PROGRAM_SEPARABLE as set, for the next link, and as the last
    /// successful link took it ([`crate::program_pipeline`]).
    pub separable: bool,
    pub linked_separable: bool,
    pub link_status: bool,
    pub validate_status: bool,
    pub info_log: String,
    pub exe: Option<Executable>,
    pub delete_pending: bool,
}

/// The language extensions the compiler has that a context does not
/// offer (`GL_EXTENSIONS` does not list them and shaders cannot enable
/// them): the tessellation stages, which no context draws, and before
/// 3.3 compute shaders and shader storage blocks (GL 4.3's, offered on
/// 3.3 contexts, whose GLSL 1.30 the compute built-ins need).
fn withheld_extensions(gl33: bool) -> glsl::lang::ExtensionSet {
    let mut set = glsl::lang::ExtensionSet::EMPTY;
    set.set(glsl::lang::Extension::ArbTessellationShader, true);
    if !gl33 {
        set.set(glsl::lang::Extension::ArbComputeShader, true);
        set.set(glsl::lang::Extension::ArbShaderStorageBufferObject, true);
    }
    set
}

impl Context {
    /// glCreateShader.
    pub fn create_shader(&mut self, kind: u32) -> u32 {
        if self.reject_in_begin() {
            return 0;
        }
        let known = match kind {
            GL_VERTEX_SHADER | GL_FRAGMENT_SHADER => true,
            GL_GEOMETRY_SHADER => self.has_geometry_shaders(),
            GL_COMPUTE_SHADER => self.api.at_least(3, 3),
            _ => false,
        };
        if !known {
            self.set_error(GL_INVALID_ENUM);
            return 0;
        }
        let n = self.fresh_name();
        self.shaders.insert(
            n,
            ShaderObj {
                kind,
                source: Vec::new(),
                compiled: None,
                delete_pending: false,
            },
        );
        n
    }

    /// glCreateProgram.
    pub fn create_program(&mut self) -> u32 {
        if self.reject_in_begin() {
            return 0;
        }
        let n = self.fresh_name();
        self.programs.insert(n, ProgramObj::default());
        n
    }

    /// Checks a shader name: `GL_INVALID_VALUE` if unknown,
    /// `GL_INVALID_OPERATION` if it names a program (the C layer checks the
    /// name before it looks at glShaderSource's strings, as Mesa does).
    pub fn check_shader(&mut self, shader: u32) -> bool {
        self.check_name(shader, true)
    }

    /// Checks a program name as [`Context::check_shader`] checks a shader's.
    pub(crate) fn check_program(&mut self, program: u32) -> bool {
        self.check_name(program, false)
    }

    /// Whether `name` is a shader (`want_shader`) or a program; else
    /// records `GL_INVALID_OPERATION` if it is the other kind and
    /// `GL_INVALID_VALUE` if neither (GL 2.1 §2.15).
    fn check_name(&mut self, name: u32, want_shader: bool) -> bool {
        let is_shader = self.shaders.contains_key(&name);
        let is_program = self.programs.contains_key(&name);
        let (this_kind, other_kind) = if want_shader {
            (is_shader, is_program)
        } else {
            (is_program, is_shader)
        };
        if this_kind {
            return true;
        }
        self.set_error(if other_kind {
            GL_INVALID_OPERATION
        } else {
            GL_INVALID_VALUE
        });
        false
    }

    /// `f` of shader object `shader`; `None` after check_shader's error.
    fn shader_query<R>(&mut self, shader: u32, f: impl FnOnce(&ShaderObj) -> R) -> Option<R> {
        self.check_shader(shader)
            .then(|| self.shaders.get(&shader).map(f))
            .flatten()
    }

    /// `f` of program object `program`; `None` after check_program's error.
    pub(crate) fn program_query<R>(
        &mut self,
        program: u32,
        f: impl FnOnce(&ProgramObj) -> R,
    ) -> Option<R> {
        self.check_program(program)
            .then(|| self.programs.get(&program).map(f))
            .flatten()
    }

    /// The value of a glGet*iv query: 0 after a name's error, and
    /// `GL_INVALID_ENUM` with 0 for a pname the query does not know
    /// (`Some(None)`).
    pub(crate) fn iv_query(&mut self, v: Option<Option<i32>>) -> i32 {
        if v == Some(None) {
            self.set_error(GL_INVALID_ENUM);
        }
        v.flatten().unwrap_or(0)
    }

    /// The executable of a linked program, for the queries that need one:
    /// `None` after check_program's error or, for a program not linked,
    /// `GL_INVALID_OPERATION`; inside glBegin/glEnd `GL_INVALID_OPERATION`.
    pub(crate) fn linked_exe(&mut self, program: u32) -> Option<&Executable> {
        if self.reject_in_begin() || !self.check_program(program) {
            return None;
        }
        let linked = self
            .programs
            .get(&program)
            .is_some_and(|p| p.link_status && p.exe.is_some());
        if !linked {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        self.programs.get(&program).and_then(|p| p.exe.as_ref())
    }

    /// glShaderSource (the strings are concatenated at compile time).
    pub fn shader_source(&mut self, shader: u32, strings: &[&str]) {
        if self.reject_in_begin() || !self.check_shader(shader) {
            return;
        }
        if let Some(s) = self.shaders.get_mut(&shader) {
            s.source = strings.iter().map(|s| s.to_string()).collect();
        }
    }

    /// glCompileShader.
    pub fn compile_shader(&mut self, shader: u32) {
        if self.reject_in_begin() || !self.check_shader(shader) {
            return;
        }
        if let Some(s) = self.shaders.get_mut(&shader) {
            let strs: Vec<&str> = s.source.iter().map(String::as_str).collect();
            let opts = CompileOptions {
                compatibility_context: self.api.compatibility(),
                withheld: withheld_extensions(self.api.at_least(3, 3)),
                ..CompileOptions::new(s.stage())
            };
            let compiled = glsl::compile(&strs, &opts);
            s.compiled = Some(Arc::new(compiled));
        }
    }

    /// glDeleteShader: deleted now if attached nowhere, else when the last
    /// program lets go of it (GL 2.1 §2.15.1). Name 0 is ignored.
    pub fn delete_shader(&mut self, shader: u32) {
        if shader == 0 || self.reject_in_begin() || !self.check_shader(shader) {
            return;
        }
        let attached = self.programs.values().any(|p| p.attached.contains(&shader));
        if attached {
            if let Some(s) = self.shaders.get_mut(&shader) {
                s.delete_pending = true;
            }
        } else {
            self.shaders.remove(&shader);
        }
    }

    /// glDeleteProgram: deleted now unless current or part of a program
    /// pipeline (GL 2.1 §2.15.2, GL_ARB_separate_shader_objects).
    pub fn delete_program(&mut self, program: u32) {
        if program == 0 || self.reject_in_begin() || !self.check_program(program) {
            return;
        }
        if let Some(p) = self.programs.get_mut(&program) {
            p.delete_pending = true;
        }
        self.release_program(program);
    }

    /// Deletes a program whose deletion was pending once nothing holds it:
    /// neither the context's current program nor any pipeline.
    pub(crate) fn release_program(&mut self, program: u32) {
        let pending = self
            .programs
            .get(&program)
            .is_some_and(|p| p.delete_pending);
        if pending && self.current_program != program && !self.pipeline_references(program) {
            self.destroy_program(program);
        }
    }

    fn destroy_program(&mut self, program: u32) {
        if let Some(p) = self.programs.remove(&program) {
            for s in p.attached {
                self.release_shader(s);
            }
        }
    }

    /// Deletes a shader whose deletion was pending once no program holds it.
    fn release_shader(&mut self, shader: u32) {
        let pending = self.shaders.get(&shader).is_some_and(|s| s.delete_pending);
        let attached = self.programs.values().any(|p| p.attached.contains(&shader));
        if pending && !attached {
            self.shaders.remove(&shader);
        }
    }

    /// glIsShader.
    pub fn is_shader(&self, name: u32) -> bool {
        self.shaders.contains_key(&name)
    }

    /// glIsProgram.
    pub fn is_program(&self, name: u32) -> bool {
        self.programs.contains_key(&name)
    }

    /// glAttachShader.
    pub fn attach_shader(&mut self, program: u32, shader: u32) {
        if self.reject_in_begin() || !self.check_program(program) || !self.check_shader(shader) {
            return;
        }
        if let Some(p) = self.programs.get_mut(&program) {
            if p.attached.contains(&shader) {
                self.set_error(GL_INVALID_OPERATION);
            } else {
                p.attached.push(shader);
            }
        }
    }

    /// glDetachShader.
    pub fn detach_shader(&mut self, program: u32, shader: u32) {
        if self.reject_in_begin() || !self.check_program(program) || !self.check_shader(shader) {
            return;
        }
        let Some(p) = self.programs.get_mut(&program) else {
            return;
        };
        match p.attached.iter().position(|&s| s == shader) {
            Some(i) => {
                p.attached.remove(i);
                self.release_shader(shader);
            }
            None => self.set_error(GL_INVALID_OPERATION),
        }
    }

    /// glGetAttachedShaders.
    pub fn get_attached_shaders(&mut self, program: u32) -> Vec<u32> {
        self.program_query(program, |p| p.attached.clone())
            .unwrap_or_default()
    }

    /// glBindAttribLocation (takes effect at the next link).
    pub fn bind_attrib_location(&mut self, program: u32, index: u32, name: &str) {
        if self.reject_in_begin() || !self.check_program(program) {
            return;
        }
        if index as usize >= crate::MAX_VERTEX_ATTRIBS {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if name.starts_with("gl_") {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if let Some(p) = self.programs.get_mut(&program) {
            p.bindings.insert(name.to_string(), index);
        }
    }

    /// glLinkProgram (GL_INVALID_OPERATION for the current program while
    /// transform feedback is active).
    pub fn link_program(&mut self, program: u32) {
        if self.reject_in_begin() || !self.check_program(program) {
            return;
        }
        if self.feedback_active() && program == self.current_program {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let Some(p) = self.programs.get(&program) else {
            return;
        };
        let mut not_compiled = Vec::new();
        let mut shaders = Vec::new();
        for s in &p.attached {
            match self.shaders.get(s).and_then(|s| s.compiled.clone()) {
                Some(c) => shaders.push(c),
                None => not_compiled.push(*s),
            }
        }
        let refs: Vec<&glsl::Shader> = shaders.iter().map(|s| s.as_ref()).collect();
        // GL 2.1 §2.15.2 gives no reason for a program with no shader
        // objects to fail: its executable is fixed function for both
        // stages, as for any stage without a shader (Mesa's compatibility
        // contexts link it too).
        let linked = if p.attached.is_empty() {
            glsl::link::Program::default()
        } else {
            glsl::link::link_with(
                &refs,
                &glsl::link::LinkOptions {
                    geometry: p.geometry,
                    separable: p.separable,
                    // GL_EXT_separate_shader_objects, offered where the
                    // geometry_shader4 extensions are.
                    lone_geometry: self.api.compatibility(),
                },
            )
        };
        let mut log = String::new();
        for s in &not_compiled {
            log.push_str(&format!("error: shader {s} was never compiled\n"));
        }
        log.push_str(linked.info_log());
        let mut ok = linked.ok() && not_compiled.is_empty();
        let bindings = p.bindings.clone();
        let frag_bindings = p.frag_bindings.clone();
        let feedback = (p.feedback_names.clone(), p.feedback_mode);
        let mut exe = None;
        if ok {
            match build_executable(
                linked,
                (&bindings, &frag_bindings),
                &feedback,
                shaders.clone(),
            ) {
                Ok(e) => exe = Some(e),
                Err(msg) => {
                    log.push_str(&format!("error: {msg}\n"));
                    ok = false;
                }
            }
        }
        if let Some(p) = self.programs.get_mut(&program) {
            if ok {
                p.linked_separable = p.separable;
            }
            p.link_status = ok;
            p.validate_status = false;
            p.info_log = log;
            p.exe = exe;
        }
    }

    /// glUseProgram (GL_INVALID_OPERATION while transform feedback is
    /// active).
    pub fn use_program(&mut self, program: u32) {
        if self.reject_in_begin() {
            return;
        }
        if self.feedback_active() {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if program != 0 {
            if !self.check_program(program) {
                return;
            }
            if !self.programs.get(&program).is_some_and(|p| p.link_status) {
                self.set_error(GL_INVALID_OPERATION);
                return;
            }
        }
        let old = std::mem::replace(&mut self.current_program, program);
        for ext in self.clear_ext_bindings() {
            self.release_program(ext);
        }
        self.release_program(old);
    }

    /// glValidateProgram: valid when linked and no two samplers of different
    /// types use the same texture unit (GL 2.1 §2.15.4).
    pub fn validate_program(&mut self, program: u32) {
        if self.reject_in_begin() || !self.check_program(program) {
            return;
        }
        let Some(p) = self.programs.get_mut(&program) else {
            return;
        };
        let ok = p.link_status && p.exe.as_ref().and_then(sampler_conflict).is_none();
        p.validate_status = ok;
        if !ok {
            p.info_log
                .push_str("error: program is not linked or samplers of different types share a texture unit\n");
        }
    }

    /// glGetShaderiv.
    pub fn get_shaderiv(&mut self, shader: u32, pname: u32) -> i32 {
        let v = self.shader_query(shader, |s| {
            Some(match pname {
                GL_SHADER_TYPE => s.kind as i32,
                GL_DELETE_STATUS => s.delete_pending as i32,
                GL_COMPILE_STATUS => s.compile_status() as i32,
                GL_INFO_LOG_LENGTH => with_nul(s.info_log().len()),
                GL_SHADER_SOURCE_LENGTH => with_nul(s.source.iter().map(String::len).sum()),
                _ => return None,
            })
        });
        self.iv_query(v)
    }

    /// glGetShaderInfoLog.
    pub fn get_shader_info_log(&mut self, shader: u32) -> String {
        self.shader_query(shader, ShaderObj::info_log)
            .unwrap_or_default()
    }

    /// glGetShaderSource.
    pub fn get_shader_source(&mut self, shader: u32) -> String {
        self.shader_query(shader, |s| s.source.concat())
            .unwrap_or_default()
    }

    /// glGetProgramiv.
    pub fn get_programiv(&mut self, program: u32, pname: u32) -> i32 {
        if let Some(v) = self.geometry_programiv(program, pname) {
            return v;
        }
        let v = self.program_query(program, |p| {
            let uniforms = p
                .exe
                .as_ref()
                .map(|e| e.uniforms.leaves.as_slice())
                .unwrap_or(&[]);
            let attribs = p.exe.as_ref().map(|e| e.attribs.as_slice()).unwrap_or(&[]);
            Some(match pname {
                GL_DELETE_STATUS => p.delete_pending as i32,
                GL_LINK_STATUS => p.link_status as i32,
                GL_PROGRAM_SEPARABLE => p.separable as i32,
                GL_VALIDATE_STATUS => p.validate_status as i32,
                GL_INFO_LOG_LENGTH => with_nul(p.info_log.len()),
                GL_ATTACHED_SHADERS => p.attached.len() as i32,
                GL_ACTIVE_UNIFORMS => uniforms.len() as i32,
                GL_ACTIVE_UNIFORM_MAX_LENGTH => uniforms
                    .iter()
                    .map(|l| with_nul(l.name.len() + if l.array.is_some() { 3 } else { 0 }))
                    .max()
                    .unwrap_or(0),
                GL_ACTIVE_UNIFORM_BLOCKS => {
                    p.exe.as_ref().map_or(0, |e| e.uniforms.blocks.len()) as i32
                }
                GL_ACTIVE_UNIFORM_BLOCK_MAX_NAME_LENGTH => p
                    .exe
                    .as_ref()
                    .and_then(|e| {
                        e.uniforms
                            .blocks
                            .iter()
                            .map(|b| with_nul(b.name.len()))
                            .max()
                    })
                    .unwrap_or(0),
                GL_ACTIVE_ATTRIBUTES => attribs.len() as i32,
                GL_TRANSFORM_FEEDBACK_VARYINGS => {
                    p.exe.as_ref().map_or(0, |e| e.feedback.len()) as i32
                }
                GL_TRANSFORM_FEEDBACK_VARYING_MAX_LENGTH => p
                    .exe
                    .as_ref()
                    .and_then(|e| e.feedback.iter().map(|v| with_nul(v.name.len())).max())
                    .unwrap_or(0),
                GL_TRANSFORM_FEEDBACK_BUFFER_MODE => p
                    .exe
                    .as_ref()
                    .map_or(GL_INTERLEAVED_ATTRIBS, |e| e.feedback_mode)
                    as i32,
                GL_ACTIVE_ATTRIBUTE_MAX_LENGTH => attribs
                    .iter()
                    .map(|a| with_nul(a.name.len()))
                    .max()
                    .unwrap_or(0),
                _ => return None,
            })
        });
        self.iv_query(v)
    }

    /// glGetProgramInfoLog.
    pub fn get_program_info_log(&mut self, program: u32) -> String {
        self.program_query(program, |p| p.info_log.clone())
            .unwrap_or_default()
    }

    /// glGetActiveUniform: name (`"a[0]"` for arrays), size, GL type.
    pub fn get_active_uniform(&mut self, program: u32, index: u32) -> Option<ActiveInfo> {
        self.active_info(program, |e| {
            let l = e.uniforms.leaves.get(index as usize)?;
            Some(ActiveInfo {
                name: e.uniforms.leaf_name(index as usize)?,
                size: l.array.unwrap_or(1) as i32,
                ty: gl_type(l.ty),
            })
        })
    }

    /// glGetActiveAttrib.
    pub fn get_active_attrib(&mut self, program: u32, index: u32) -> Option<ActiveInfo> {
        self.active_info(program, |e| {
            let a = e.attribs.get(index as usize)?;
            Some(ActiveInfo {
                name: a.name.clone(),
                size: 1,
                ty: gl_type(a.ty),
            })
        })
    }

    /// An active uniform or attribute that `pick` finds in the program's
    /// executable; an index past the active ones (or a program without an
    /// executable) is `GL_INVALID_VALUE`.
    fn active_info(
        &mut self,
        program: u32,
        pick: impl FnOnce(&Executable) -> Option<ActiveInfo>,
    ) -> Option<ActiveInfo> {
        let info = self.program_query(program, |p| p.exe.as_ref().and_then(pick))?;
        if info.is_none() {
            self.set_error(GL_INVALID_VALUE);
        }
        info
    }

    /// glGetAttribLocation.
    pub fn get_attrib_location(&mut self, program: u32, name: &str) -> i32 {
        self.linked_exe(program).map_or(-1, |exe| {
            exe.attribs
                .iter()
                .find(|a| a.name == name)
                .map_or(-1, |a| a.location)
        })
    }

    /// glGetUniformLocation.
    pub fn get_uniform_location(&mut self, program: u32, name: &str) -> i32 {
        self.linked_exe(program)
            .map_or(-1, |exe| exe.uniforms.location(name, &exe.modules()))
    }

    /// Shared body of every glUniform* and glProgramUniform* entry point:
    /// `program` is `Uniform::Current` for the program glUniform* update
    /// ([`Context::uniform_program`]), else the named program, which must
    /// be a linked program (GL_INVALID_VALUE for an unknown name,
    /// GL_INVALID_OPERATION for a shader or a program not linked).
    fn set_uniform(
        &mut self,
        program: Target,
        (loc, count): (i32, i32),
        kind: SetterKind,
        comps: usize,
        data: &[Word],
    ) {
        if self.reject_in_begin() {
            return;
        }
        let name = match program {
            Target::Current => self.uniform_program(),
            Target::Program(p) => {
                if !self.check_program(p) {
                    return;
                }
                p
            }
        };
        let Some(exe) = self
            .programs
            .get_mut(&name)
            .filter(|p| p.link_status)
            .and_then(|p| p.exe.as_mut())
        else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        if loc == -1 {
            return;
        }
        match exe.uniforms.set(loc, count, kind, comps, data) {
            Ok(()) => {}
            Err(UniformError::InvalidOperation) => self.set_error(GL_INVALID_OPERATION),
            Err(UniformError::InvalidValue) => self.set_error(GL_INVALID_VALUE),
        }
    }

    fn uniform_f(&mut self, t: Target, loc: i32, count: i32, comps: usize, v: &[f32]) {
        let w: Vec<Word> = v.iter().map(|&f| Word::Float(f)).collect();
        self.set_uniform(t, (loc, count), SetterKind::Float, comps, &w);
    }

    fn uniform_i(&mut self, t: Target, loc: i32, count: i32, comps: usize, v: &[i32]) {
        let w: Vec<Word> = v.iter().map(|&i| Word::Int(i)).collect();
        self.set_uniform(t, (loc, count), SetterKind::Int, comps, &w);
    }

    fn uniform_ui(&mut self, t: Target, loc: i32, count: i32, comps: usize, v: &[u32]) {
        let w: Vec<Word> = v.iter().map(|&u| Word::Uint(u)).collect();
        self.set_uniform(t, (loc, count), SetterKind::Uint, comps, &w);
    }

    /// Shared body of glUniformMatrix*fv; `transpose` input is row-major.
    #[allow(clippy::too_many_arguments)]
    fn uniform_matrix(
        &mut self,
        t: Target,
        loc: i32,
        count: i32,
        transpose: bool,
        cols: u8,
        rows: u8,
        v: &[f32],
    ) {
        let (c, r) = (cols as usize, rows as usize);
        let n = c * r;
        let mut w = Vec::with_capacity(v.len());
        for m in v.chunks_exact(n) {
            for col in 0..c {
                for row in 0..r {
                    let src = if transpose {
                        row * c + col
                    } else {
                        col * r + row
                    };
                    w.push(Word::Float(m[src]));
                }
            }
        }
        self.set_uniform(t, (loc, count), SetterKind::Matrix { cols, rows }, n, &w);
    }

    /// glGetUniformfv.
    pub fn get_uniformfv(&mut self, program: u32, loc: i32) -> Vec<f32> {
        self.get_uniform(program, loc)
            .map(|(w, ty)| {
                w.iter()
                    .map(|&b| match ty.scalar() {
                        Some(glsl::types::Scalar::Float) => f32::from_bits(b),
                        Some(glsl::types::Scalar::Bool) => b as f32,
                        Some(glsl::types::Scalar::Uint) => b as f32,
                        _ => b as i32 as f32,
                    })
                    .collect()
            })
            .unwrap_or_default()
    }

    /// glGetUniformiv.
    pub fn get_uniformiv(&mut self, program: u32, loc: i32) -> Vec<i32> {
        self.get_uniform(program, loc)
            .map(|(w, ty)| {
                w.iter()
                    .map(|&b| match ty.scalar() {
                        Some(glsl::types::Scalar::Float) => {
                            glsl::consteval::float_to_int(f32::from_bits(b))
                        }
                        _ => b as i32,
                    })
                    .collect()
            })
            .unwrap_or_default()
    }

    /// glGetUniformuiv (GL 3.0): floats convert as glGetUniformiv's do.
    pub fn get_uniformuiv(&mut self, program: u32, loc: i32) -> Vec<u32> {
        self.get_uniformiv(program, loc)
            .into_iter()
            .map(|i| i as u32)
            .collect()
    }

    fn get_uniform(&mut self, program: u32, loc: i32) -> Option<(Vec<u32>, Type)> {
        let r = self.linked_exe(program)?.uniforms.get(loc);
        if r.is_none() {
            self.set_error(GL_INVALID_OPERATION);
        }
        r
    }
}

/// Which program a uniform setter updates: glUniform*'s (the current
/// program, else the bound pipeline's active program) or the one a
/// glProgramUniform* names.
#[derive(Clone, Copy)]
enum Target {
    Current,
    Program(u32),
}

/// Generates `glUniform{1,2,3,4}{f,i,ui}[v]` and their `glProgramUniform*`
/// forms (GL_ARB_separate_shader_objects).
macro_rules! uniform_entry_points {
    ($($n:literal ($($a:ident),*) $f:ident $fv:ident $i:ident $iv:ident $ui:ident $uiv:ident
       / $pf:ident $pfv:ident $pi:ident $piv:ident $pui:ident $puiv:ident;)*) => {
        impl Context {
            $(
                #[doc = concat!("glUniform", stringify!($n), "f.")]
                pub fn $f(&mut self, loc: i32, $($a: f32),*) {
                    self.uniform_f(Target::Current, loc, 1, $n, &[$($a),*]);
                }
                #[doc = concat!("glUniform", stringify!($n), "fv.")]
                pub fn $fv(&mut self, loc: i32, count: i32, v: &[f32]) {
                    self.uniform_f(Target::Current, loc, count, $n, v);
                }
                #[doc = concat!("glUniform", stringify!($n), "i.")]
                pub fn $i(&mut self, loc: i32, $($a: i32),*) {
                    self.uniform_i(Target::Current, loc, 1, $n, &[$($a),*]);
                }
                #[doc = concat!("glUniform", stringify!($n), "iv.")]
                pub fn $iv(&mut self, loc: i32, count: i32, v: &[i32]) {
                    self.uniform_i(Target::Current, loc, count, $n, v);
                }
                #[doc = concat!("glUniform", stringify!($n), "ui (GL 3.0).")]
                pub fn $ui(&mut self, loc: i32, $($a: u32),*) {
                    self.uniform_ui(Target::Current, loc, 1, $n, &[$($a),*]);
                }
                #[doc = concat!("glUniform", stringify!($n), "uiv (GL 3.0).")]
                pub fn $uiv(&mut self, loc: i32, count: i32, v: &[u32]) {
                    self.uniform_ui(Target::Current, loc, count, $n, v);
                }
                #[doc = concat!("glProgramUniform", stringify!($n), "f.")]
                pub fn $pf(&mut self, program: u32, loc: i32, $($a: f32),*) {
                    self.uniform_f(Target::Program(program), loc, 1, $n, &[$($a),*]);
                }
                #[doc = concat!("glProgramUniform", stringify!($n), "fv.")]
                pub fn $pfv(&mut self, program: u32, loc: i32, count: i32, v: &[f32]) {
                    self.uniform_f(Target::Program(program), loc, count, $n, v);
                }
                #[doc = concat!("glProgramUniform", stringify!($n), "i.")]
                pub fn $pi(&mut self, program: u32, loc: i32, $($a: i32),*) {
                    self.uniform_i(Target::Program(program), loc, 1, $n, &[$($a),*]);
                }
                #[doc = concat!("glProgramUniform", stringify!($n), "iv.")]
                pub fn $piv(&mut self, program: u32, loc: i32, count: i32, v: &[i32]) {
                    self.uniform_i(Target::Program(program), loc, count, $n, v);
                }
                #[doc = concat!("glProgramUniform", stringify!($n), "ui.")]
                pub fn $pui(&mut self, program: u32, loc: i32, $($a: u32),*) {
                    self.uniform_ui(Target::Program(program), loc, 1, $n, &[$($a),*]);
                }
                #[doc = concat!("glProgramUniform", stringify!($n), "uiv.")]
                pub fn $puiv(&mut self, program: u32, loc: i32, count: i32, v: &[u32]) {
                    self.uniform_ui(Target::Program(program), loc, count, $n, v);
                }
            )*
        }
    };
}

uniform_entry_points! {
    1 (x) uniform_1f uniform_1fv uniform_1i uniform_1iv uniform_1ui uniform_1uiv
        / program_uniform_1f program_uniform_1fv program_uniform_1i program_uniform_1iv
          program_uniform_1ui program_uniform_1uiv;
    2 (x, y) uniform_2f uniform_2fv uniform_2i uniform_2iv uniform_2ui uniform_2uiv
        / program_uniform_2f program_uniform_2fv program_uniform_2i program_uniform_2iv
          program_uniform_2ui program_uniform_2uiv;
    3 (x, y, z) uniform_3f uniform_3fv uniform_3i uniform_3iv uniform_3ui uniform_3uiv
        / program_uniform_3f program_uniform_3fv program_uniform_3i program_uniform_3iv
          program_uniform_3ui program_uniform_3uiv;
    4 (x, y, z, w) uniform_4f uniform_4fv uniform_4i uniform_4iv uniform_4ui uniform_4uiv
        / program_uniform_4f program_uniform_4fv program_uniform_4i program_uniform_4iv
          program_uniform_4ui program_uniform_4uiv;
}

/// Generates glUniformMatrix*fv and glProgramUniformMatrix*fv.
macro_rules! uniform_matrix_entry_points {
    ($($name:ident $pname:ident $c:literal $r:literal;)*) => {
        impl Context {
            $(
                #[doc = concat!("glUniformMatrix", stringify!($c), "x", stringify!($r), "fv.")]
                pub fn $name(&mut self, loc: i32, count: i32, transpose: bool, v: &[f32]) {
                    self.uniform_matrix(Target::Current, loc, count, transpose, $c, $r, v);
                }
                #[doc = concat!("glProgramUniformMatrix", stringify!($c), "x", stringify!($r), "fv.")]
                pub fn $pname(
                    &mut self,
                    program: u32,
                    loc: i32,
                    count: i32,
                    transpose: bool,
                    v: &[f32],
                ) {
                    self.uniform_matrix(Target::Program(program), loc, count, transpose, $c, $r, v);
                }
            )*
        }
    };
}

uniform_matrix_entry_points! {
    uniform_matrix_2fv program_uniform_matrix_2fv 2 2;
    uniform_matrix_3fv program_uniform_matrix_3fv 3 3;
    uniform_matrix_4fv program_uniform_matrix_4fv 4 4;
    uniform_matrix_2x3fv program_uniform_matrix_2x3fv 2 3;
    uniform_matrix_2x4fv program_uniform_matrix_2x4fv 2 4;
    uniform_matrix_3x2fv program_uniform_matrix_3x2fv 3 2;
    uniform_matrix_3x4fv program_uniform_matrix_3x4fv 3 4;
    uniform_matrix_4x2fv program_uniform_matrix_4x2fv 4 2;
    uniform_matrix_4x3fv program_uniform_matrix_4x3fv 4 3;
}

pub(crate) fn with_nul(len: usize) -> i32 {
    if len == 0 {
        0
    } else {
        (len + 1).min(i32::MAX as usize) as i32
    }
}

/// Why an executable cannot run, if two of its samplers of different
/// types use the same texture unit (GL 2.1 §2.15.4).
pub(crate) fn sampler_conflict(exe: &Executable) -> Option<String> {
    let mut units: BTreeMap<u32, glsl::types::SamplerKind> = BTreeMap::new();
    // Block members have no words of their own (and no samplers).
    for leaf in exe.uniforms.leaves.iter().filter(|l| l.block.is_none()) {
        if let Base::Sampler(k) = leaf.ty.base {
            for e in 0..leaf.array.unwrap_or(1) as usize {
                let unit = exe
                    .uniforms
                    .values
                    .get(leaf.offset + e)
                    .copied()
                    .unwrap_or(0);
                if units.insert(unit, k).is_some_and(|prev| prev != k) {
                    return Some(format!(
                        "samplers of different types share texture unit {unit}"
                    ));
                }
            }
        }
    }
    None
}

/// Builds uniform storage, attribute locations and kernels for a linked
/// program.
fn build_executable(
    mut program: glsl::link::Program,
    (bindings, frag_bindings): (&BTreeMap<String, u32>, &FragBindings),
    (feedback_names, feedback_mode): &(Vec<String>, u32),
    shaders: Vec<Arc<glsl::Shader>>,
) -> Result<Executable, String> {
    crate::program_outputs::place_frag_outputs(&mut program, frag_bindings)?;
    let modules: Vec<&Module> = program.stages.iter().map(|s| &s.module).collect();
    let uniforms = UniformTable::build(&modules);
    let storage_blocks = crate::storage::storage_blocks(&modules);
    crate::uniform_block::check_limits(&uniforms.blocks, &modules)?;
    let attribs = assign_attribs(&program, bindings)?;
    let kernels = crate::kernels::Kernels::new(&program)?;
    let feedback_mode = match *feedback_mode {
        GL_SEPARATE_ATTRIBS => GL_SEPARATE_ATTRIBS,
        _ => GL_INTERLEAVED_ATTRIBS,
    };
    // The last stage before rasterization is the one captured.
    let feedback = crate::transform_feedback::resolve(
        kernels
            .gs
            .as_ref()
            .or(kernels.vs.as_ref())
            .map(|k| k.interface()),
        feedback_names,
        feedback_mode == GL_SEPARATE_ATTRIBS,
    )?;
    Ok(Executable {
        program,
        uniforms,
        attribs,
        kernels,
        shaders,
        feedback,
        feedback_mode,
        storage_blocks,
    })
}

/// Attribute locations: bound names keep their binding; the others take
/// the lowest free slots (a matrix takes one slot per column). Generic
/// slot 0 aliases gl_Vertex (GL 2.1 §2.7), so it is left to bound
/// attributes when the shader reads gl_Vertex.
fn assign_attribs(
    program: &glsl::link::Program,
    bindings: &BTreeMap<String, u32>,
) -> Result<Vec<AttribInfo>, String> {
    let Some(vs) = program.stage(Stage::Vertex) else {
        return Ok(Vec::new());
    };
    let globals: Vec<_> = vs
        .module
        .globals
        .iter()
        .filter(|g| g.storage == Storage::Attribute && g.read)
        .collect();
    let uses_vertex = globals.iter().any(|g| g.name == "gl_Vertex");
    let mut used = [false; crate::MAX_VERTEX_ATTRIBS];
    let slots = |ty: Type| match ty.base {
        Base::Matrix { cols, .. } => cols as usize,
        _ => 1,
    };
    let mut out = Vec::new();
    for g in &globals {
        if g.builtin {
            out.push(AttribInfo {
                name: g.name.clone(),
                ty: g.ty,
                location: -1,
            });
            continue;
        }
        // A `layout(location)` in the shader wins over glBindAttribLocation
        // (GL 3.3 §2.11.3).
        if let Some(b) = g.location.or_else(|| bindings.get(&g.name).copied()) {
            let n = slots(g.ty);
            if b as usize + n > used.len() {
                return Err(format!(
                    "attribute `{}' bound to location {b} does not fit",
                    g.name
                ));
            }
            for u in &mut used[b as usize..b as usize + n] {
                *u = true;
            }
            out.push(AttribInfo {
                name: g.name.clone(),
                ty: g.ty,
                location: b as i32,
            });
        }
    }
    for g in &globals {
        if g.builtin || g.location.is_some() || bindings.contains_key(&g.name) {
            continue;
        }
        let n = slots(g.ty);
        let start = usize::from(uses_vertex);
        let found =
            (start..=used.len().saturating_sub(n)).find(|&s| used[s..s + n].iter().all(|u| !u));
        let Some(s) = found else {
            return Err(format!(
                "too many vertex attributes (no room for `{}')",
                g.name
            ));
        };
        for u in &mut used[s..s + n] {
            *u = true;
        }
        out.push(AttribInfo {
            name: g.name.clone(),
            ty: g.ty,
            location: s as i32,
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    const VS: &str =
        "attribute vec4 pos; attribute vec3 n; void main() { gl_Position = pos + vec4(n, 0.0); }";
    const FS: &str =
        "uniform vec4 color; uniform float f[3]; void main() { gl_FragColor = color * f[1]; }";

    fn program(ctx: &mut Context, vs: &str, fs: &str) -> u32 {
        let p = ctx.create_program();
        for (kind, src) in [(GL_VERTEX_SHADER, vs), (GL_FRAGMENT_SHADER, fs)] {
            let s = ctx.create_shader(kind);
            ctx.shader_source(s, &[src]);
            ctx.compile_shader(s);
            ctx.attach_shader(p, s);
        }
        ctx.link_program(p);
        p
    }

    /// GL 4.3 §7.3.1's names for arrays of arrays (GL_ARB_arrays_of_arrays):
    /// one active uniform per innermost array, `a[i][0]` of size its
    /// length; locations of every element, consecutive along a row.
    #[test]
    fn arrays_of_arrays_uniforms_are_named_per_innermost_array() {
        let mut ctx = Context::new(8, 8);
        assert!(ctx
            .get_string(crate::enums::GL_EXTENSIONS)
            .split(' ')
            .any(|w| w == "GL_ARB_arrays_of_arrays"));
        let p = program(
            &mut ctx,
            "#version 120\n#extension GL_ARB_arrays_of_arrays : enable\nuniform vec2 a[2][3];\nstruct S { float x[2][2]; };\nuniform S s[2];\nvoid main() { gl_Position = vec4(a[1][2] + a[0][0], s[1].x[1][0] + s[0].x[0][1], 1.0); }",
            "void main() { gl_FragColor = vec4(1.0); }",
        );
        assert_eq!(
            ctx.get_programiv(p, GL_LINK_STATUS),
            1,
            "{}",
            ctx.get_program_info_log(p)
        );
        let n = ctx.get_programiv(p, GL_ACTIVE_UNIFORMS);
        let infos: Vec<ActiveInfo> = (0..n as u32)
            .map(|i| ctx.get_active_uniform(p, i).unwrap())
            .collect();
        let named = |name: &str| infos.iter().find(|i| i.name == name).cloned();
        for row in ["a[0][0]", "a[1][0]"] {
            assert_eq!(
                named(row),
                Some(ActiveInfo {
                    name: row.into(),
                    size: 3,
                    ty: GL_FLOAT_VEC2
                }),
                "{infos:?}"
            );
        }
        for row in [
            "s[0].x[0][0]",
            "s[0].x[1][0]",
            "s[1].x[0][0]",
            "s[1].x[1][0]",
        ] {
            assert_eq!(
                named(row),
                Some(ActiveInfo {
                    name: row.into(),
                    size: 2,
                    ty: GL_FLOAT
                }),
                "{infos:?}"
            );
        }
        assert_eq!(n, 6);
        let a10 = ctx.get_uniform_location(p, "a[1][0]");
        assert!(a10 >= 0);
        assert_eq!(ctx.get_uniform_location(p, "a[1]"), a10);
        assert_eq!(ctx.get_uniform_location(p, "a[1][2]"), a10 + 2);
        assert_eq!(ctx.get_uniform_location(p, "a[1][3]"), -1);
        assert_eq!(ctx.get_uniform_location(p, "a[2][0]"), -1);
        // Only the innermost `[0]' may be left out (`a[0]', not `a').
        assert_eq!(
            ctx.get_uniform_location(p, "a[0]"),
            ctx.get_uniform_location(p, "a[0][0]")
        );
        assert_eq!(ctx.get_uniform_location(p, "a"), -1);
        assert_eq!(ctx.get_uniform_location(p, "a[1]."), -1);
        let x = ctx.get_uniform_location(p, "s[1].x[1][1]");
        assert_eq!(x, ctx.get_uniform_location(p, "s[1].x[1]") + 1);
        // Values land where the shader reads them.
        ctx.use_program(p);
        let a11 = ctx.get_uniform_location(p, "a[1][1]");
        ctx.uniform_2fv(a11, 2, &[1.0, 2.0, 3.0, 4.0]);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(ctx.get_uniformfv(p, a10 + 2), vec![3.0, 4.0]);
        ctx.uniform_1f(x, 7.0);
        assert_eq!(ctx.get_uniformfv(p, x), vec![7.0]);
    }

    /// A uniform no stage reads or initializes is not active (as Mesa's
    /// linker drops it): no index, no location, glUniform on its -1
    /// ignored; one read by the other stage only, or unread with an
    /// initializer, is active.
    #[test]
    fn uniforms_no_stage_reads_are_inactive() {
        let mut ctx = Context::new(8, 8);
        let p = program(
            &mut ctx,
            "#version 120\nuniform vec4 shared; uniform float vs_unused; uniform float init = 2.0;\nattribute vec4 pos;\nvoid main() { gl_Position = pos; }",
            "uniform vec4 shared; uniform sampler2D u_texture; uniform vec4 color;\nvoid main() { gl_FragColor = color + shared; }",
        );
        assert_eq!(
            ctx.get_programiv(p, GL_LINK_STATUS),
            1,
            "{}",
            ctx.get_program_info_log(p)
        );
        assert_eq!(ctx.get_programiv(p, GL_ACTIVE_UNIFORMS), 3);
        let mut names: Vec<String> = (0..3)
            .map(|i| ctx.get_active_uniform(p, i).unwrap().name)
            .collect();
        names.sort();
        assert_eq!(names, ["color", "init", "shared"]);
        assert_eq!(ctx.get_uniform_location(p, "u_texture"), -1);
        assert_eq!(ctx.get_uniform_location(p, "vs_unused"), -1);
        assert!(ctx.get_uniform_location(p, "shared") >= 0);
        ctx.use_program(p);
        ctx.uniform_1i(-1, 3);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(ctx.get_active_uniform(p, 3), None);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    }

    #[test]
    fn compile_link_and_set_uniforms() {
        let mut ctx = Context::new(8, 8);
        let p = program(&mut ctx, VS, FS);
        assert_eq!(
            ctx.get_programiv(p, GL_LINK_STATUS),
            1,
            "{}",
            ctx.get_program_info_log(p)
        );
        let loc = ctx.get_uniform_location(p, "color");
        assert!(loc >= 0);
        // No current program yet.
        ctx.uniform_4f(loc, 1.0, 2.0, 3.0, 4.0);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.use_program(p);
        ctx.uniform_4f(loc, 1.0, 2.0, 3.0, 4.0);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(ctx.get_uniformfv(p, loc), vec![1.0, 2.0, 3.0, 4.0]);
        ctx.uniform_3f(loc, 1.0, 2.0, 3.0);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.uniform_4i(loc, 1, 2, 3, 4);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.uniform_4f(-1, 0.0, 0.0, 0.0, 0.0);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        let f = ctx.get_uniform_location(p, "f[1]");
        ctx.uniform_1fv(f, 2, &[5.0, 6.0]);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(ctx.get_uniformfv(p, f + 1), vec![6.0]);
        let info = ctx.get_active_uniform(p, 1).unwrap();
        assert_eq!(
            info,
            ActiveInfo {
                name: "f[0]".into(),
                size: 3,
                ty: GL_FLOAT
            }
        );
        assert_eq!(ctx.get_programiv(p, GL_ACTIVE_UNIFORMS), 2);
        // Attributes avoid slot 0 only when gl_Vertex is used.
        let pos = ctx.get_attrib_location(p, "pos");
        let n = ctx.get_attrib_location(p, "n");
        assert_eq!((pos, n), (0, 1));
    }

    #[test]
    fn bound_attribs_and_errors() {
        let mut ctx = Context::new(8, 8);
        let p = ctx.create_program();
        ctx.bind_attrib_location(p, 3, "n");
        ctx.bind_attrib_location(p, 99, "n");
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.bind_attrib_location(p, 1, "gl_Vertex");
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        for (kind, src) in [(GL_VERTEX_SHADER, VS), (GL_FRAGMENT_SHADER, FS)] {
            let s = ctx.create_shader(kind);
            ctx.shader_source(s, &[src]);
            ctx.compile_shader(s);
            ctx.attach_shader(p, s);
            ctx.attach_shader(p, s);
            assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        }
        ctx.link_program(p);
        assert_eq!(ctx.get_attrib_location(p, "n"), 3);
        assert_eq!(ctx.get_attrib_location(p, "pos"), 0);
        assert_eq!(ctx.create_shader(0x1234), 0);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.compile_shader(p);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.compile_shader(777);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        // The queries: a name of the other kind, an unknown name, an
        // unknown pname, an index past the active ones.
        let s = ctx.get_attached_shaders(p)[0];
        assert_eq!(ctx.get_programiv(s, GL_LINK_STATUS), 0);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.get_shader_source(p), "");
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.get_shaderiv(777, GL_SHADER_TYPE), 0);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        assert_eq!(ctx.get_shaderiv(s, GL_LINK_STATUS), 0);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.get_programiv(p, GL_ACTIVE_ATTRIBUTES), 2);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(ctx.get_active_attrib(p, 2), None);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        assert_eq!(ctx.get_active_uniform(s, 0), None);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.get_attrib_location(777, "n"), -1);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    }

    #[test]
    fn failed_compile_and_link() {
        let mut ctx = Context::new(8, 8);
        let s = ctx.create_shader(GL_FRAGMENT_SHADER);
        ctx.shader_source(s, &["void main() { gl_FragColor = vec4(1) }"]);
        ctx.compile_shader(s);
        assert_eq!(ctx.get_shaderiv(s, GL_COMPILE_STATUS), 0);
        assert!(ctx.get_shaderiv(s, GL_INFO_LOG_LENGTH) > 1);
        assert!(ctx.get_shader_info_log(s).contains("error"));
        let p = ctx.create_program();
        ctx.attach_shader(p, s);
        ctx.link_program(p);
        assert_eq!(ctx.get_programiv(p, GL_LINK_STATUS), 0);
        ctx.use_program(p);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.get_uniform_location(p, "x"), -1);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    }

    #[test]
    fn delete_semantics() {
        let mut ctx = Context::new(8, 8);
        let p = program(&mut ctx, VS, FS);
        let shaders = ctx.get_attached_shaders(p);
        assert_eq!(shaders.len(), 2);
        ctx.delete_shader(shaders[0]);
        assert!(ctx.is_shader(shaders[0]));
        assert_eq!(ctx.get_shaderiv(shaders[0], GL_DELETE_STATUS), 1);
        ctx.use_program(p);
        ctx.delete_program(p);
        assert!(ctx.is_program(p));
        assert_eq!(ctx.get_programiv(p, GL_DELETE_STATUS), 1);
        ctx.use_program(0);
        assert!(!ctx.is_program(p));
        assert!(!ctx.is_shader(shaders[0]));
        assert!(ctx.is_shader(shaders[1]));
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
    }
}
