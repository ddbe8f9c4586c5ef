//! Separable programs and program pipeline objects
//! (GL_ARB_separate_shader_objects, core in GL 4.1): GL_PROGRAM_SEPARABLE,
//! glCreateShaderProgramv, glGen/Delete/Is/BindProgramPipeline,
//! glUseProgramStages, glActiveShaderProgram, glValidateProgramPipeline,
//! glGetProgramPipelineiv/InfoLog, and which program is current for each
//! stage of a draw.
//!
//! Contract:
//! - The program current for a stage (`Context::stage_program`) is the
//!   one glUseProgram made current, for every stage; without one, the
//!   bound pipeline's program for that stage; else none. A stage's
//!   program is *active* when its executable has that stage
//!   (`Context::stage_executable`); the draw path takes every stage's
//!   kernel, uniforms, attribute locations and transform feedback
//!   varyings from that stage's active program.
//! - glUniform* update the current program, else the bound pipeline's
//!   active program (glActiveShaderProgram); glProgramUniform* name the
//!   program ([`crate::program`]).
//! - A pipeline name from glGenProgramPipelines holds no object until it
//!   is first bound or named by glUseProgramStages, glActiveShaderProgram,
//!   glValidateProgramPipeline or glGetProgramPipelineiv; glIsProgramPipeline
//!   is true only from then on. Names never generated (or deleted) are
//!   GL_INVALID_OPERATION for all of those, GL_INVALID_VALUE for
//!   glGetProgramPipelineInfoLog.
//! - A draw through a pipeline first validates it (the rules of
//!   [`Context::validate_program_pipeline`]); an invalid pipeline draws
//!   nothing and records GL_INVALID_OPERATION.
//! - shaderbox has no tessellation stages: GL_TESS_CONTROL_SHADER_BIT and
//!   GL_TESS_EVALUATION_SHADER_BIT are GL_INVALID_ENUM in glUseProgramStages
//!   (the extension's "Dependencies on ARB_tessellation_shader"), except
//!   as part of GL_ALL_SHADER_BITS.
//! - A program referenced by a pipeline stays alive after glDeleteProgram
//!   until no pipeline and no context binding refers to it.
//! - GL_EXT_separate_shader_objects (compatibility contexts, whose
//!   geometry shaders it needs): glUseShaderProgramEXT and
//!   glActiveProgramEXT set the context's own attachment points, which
//!   glUseProgram sets all at once ([`ExtBindings`]); while any holds a
//!   program they take precedence over a bound pipeline, as the ARB
//!   extension's "Dependencies on EXT_separate_shader_objects" says.
//!   GL_CURRENT_PROGRAM (its GL_ACTIVE_PROGRAM_EXT) is the active program.
//!   A program linked on such a context may hold a geometry stage without
//!   a vertex stage when the geometry shader declares no user-defined
//!   inputs (the extension's change to glLinkProgram).

use crate::enums::*;
use crate::program::Executable;
use crate::Context;
use glsl::Stage;
use std::collections::BTreeMap;

/// The stages a pipeline holds programs for, in pipeline order.
pub const STAGES: [Stage; 3] = [Stage::Vertex, Stage::Geometry, Stage::Fragment];

/// GL_TESS_CONTROL_SHADER_BIT | GL_TESS_EVALUATION_SHADER_BIT.
const TESS_BITS: u32 = GL_TESS_CONTROL_SHADER_BIT | GL_TESS_EVALUATION_SHADER_BIT;

/// The index of `stage` in [`STAGES`]; compute and tessellation stages
/// have none (no pipeline holds one yet).
fn stage_index(stage: Stage) -> Option<usize> {
    match stage {
        Stage::Vertex => Some(0),
        Stage::Geometry => Some(1),
        Stage::Fragment => Some(2),
        Stage::Compute | Stage::TessControl | Stage::TessEvaluation => None,
    }
}

fn stage_bit(stage: Stage) -> u32 {
    match stage {
        Stage::Vertex => GL_VERTEX_SHADER_BIT,
        Stage::Geometry => GL_GEOMETRY_SHADER_BIT,
        Stage::Fragment => GL_FRAGMENT_SHADER_BIT,
        Stage::Compute => GL_COMPUTE_SHADER_BIT,
        Stage::TessControl => GL_TESS_CONTROL_SHADER_BIT,
        Stage::TessEvaluation => GL_TESS_EVALUATION_SHADER_BIT,
    }
}

/// One program pipeline object's state.
#[derive(Clone, Debug, Default)]
pub struct Pipeline {
    /// The program of each stage of [`STAGES`] (0: none).
    pub stages: [u32; 3],
    /// glActiveShaderProgram's program (GL_ACTIVE_PROGRAM).
    pub active: u32,
    pub validate_status: bool,
    pub info_log: String,
}

/// GL_EXT_separate_shader_objects' attachment points, once
/// glUseShaderProgramEXT or glActiveProgramEXT made them differ from one
/// glUseProgram program: the program of each stage of [`STAGES`] and the
/// active program (glUniform*'s, GL_ACTIVE_PROGRAM_EXT).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ExtBindings {
    pub stages: [u32; 3],
    pub active: u32,
}

impl ExtBindings {
    /// Whether any attachment point holds a program (they then take
    /// precedence over a bound pipeline).
    fn any(&self) -> bool {
        self.active != 0 || self.stages.iter().any(|&p| p != 0)
    }

    fn references(&self, program: u32) -> bool {
        self.active == program || self.stages.contains(&program)
    }
}

/// The context's pipeline names and the bound pipeline.
#[derive(Default)]
pub struct Pipelines {
    /// Generated names; `None` until the object is created (first bound
    /// or used).
    objects: BTreeMap<u32, Option<Pipeline>>,
    next: u32,
    /// GL_PROGRAM_PIPELINE_BINDING.
    pub bound: u32,
    /// GL_EXT_separate_shader_objects' attachment points while they
    /// differ from one program (else `None`, and `Context::current_program`
    /// is every stage's and the active program).
    pub ext: Option<ExtBindings>,
}

impl Pipelines {
    /// Whether `program` is a stage or the active program of any pipeline.
    fn references(&self, program: u32) -> bool {
        self.objects
            .values()
            .flatten()
            .any(|p| p.active == program || p.stages.contains(&program))
    }

    fn get(&self, name: u32) -> Option<&Pipeline> {
        self.objects.get(&name).and_then(Option::as_ref)
    }
}

impl Context {
    /// The program current for `stage`: glUseProgram's, else the bound
    /// pipeline's for the stage, else 0.
    pub(crate) fn stage_program(&self, stage: Stage) -> u32 {
        if self.current_program != 0 {
            return self.current_program;
        }
        let Some(i) = stage_index(stage) else {
            return 0;
        };
        if let Some(b) = self.pipelines.ext.filter(ExtBindings::any) {
            return b.stages[i];
        }
        self.pipelines
            .get(self.pipelines.bound)
            .map_or(0, |p| p.stages[i])
    }

    /// The executable active for `stage`: the linked executable of the
    /// stage's current program when it has the stage.
    pub(crate) fn stage_executable(&self, stage: Stage) -> Option<&Executable> {
        self.programs
            .get(&self.stage_program(stage))
            .filter(|p| p.link_status)
            .and_then(|p| p.exe.as_ref())
            .filter(|e| e.has_stage(stage))
    }

    /// The executable whose kernel `k` is, among the active stages.
    pub(crate) fn kernel_executable(&self, k: &exec::Kernel) -> Option<&Executable> {
        STAGES.into_iter().find_map(|stage| {
            let e = self.stage_executable(stage)?;
            let kernels = &e.kernels;
            let own = match stage {
                Stage::Vertex => kernels.vs.as_deref(),
                Stage::Geometry => kernels.gs.as_deref(),
                Stage::Fragment => kernels.fs.as_deref(),
                Stage::Compute | Stage::TessControl | Stage::TessEvaluation => None,
            };
            own.is_some_and(|o| std::ptr::eq(o, k)).then_some(e)
        })
    }

    /// Whether any stage has a current program (glUseProgram's, or one in
    /// the bound pipeline).
    pub(crate) fn any_stage_program(&self) -> bool {
        STAGES.into_iter().any(|s| self.stage_program(s) != 0)
    }

    /// The program glUniform* update: the current program, else the bound
    /// pipeline's active program (0: none).
    pub(crate) fn uniform_program(&self) -> u32 {
        if self.current_program != 0 {
            return self.current_program;
        }
        if let Some(b) = self.pipelines.ext.filter(ExtBindings::any) {
            return b.active;
        }
        self.pipelines
            .get(self.pipelines.bound)
            .map_or(0, |p| p.active)
    }

    /// Whether `program` is referenced by any pipeline or
    /// GL_EXT_separate_shader_objects attachment point (so glDeleteProgram
    /// only flags it).
    pub(crate) fn pipeline_references(&self, program: u32) -> bool {
        self.pipelines.references(program)
            || self.pipelines.ext.is_some_and(|b| b.references(program))
    }

    /// GL_CURRENT_PROGRAM, which is GL_ACTIVE_PROGRAM_EXT: the active
    /// program (glUseProgram's unless glActiveProgramEXT changed it).
    pub(crate) fn current_program_query(&self) -> u32 {
        match self.pipelines.ext {
            Some(b) => b.active,
            None => self.current_program,
        }
    }

    /// glUseProgram's effect on GL_EXT_separate_shader_objects' attachment
    /// points: all of them become `program` (`current_program`).
    pub(crate) fn clear_ext_bindings(&mut self) -> Vec<u32> {
        self.pipelines
            .ext
            .take()
            .map(|b| b.stages.into_iter().chain([b.active]).collect())
            .unwrap_or_default()
    }

    /// Checks glUseShaderProgramEXT's and glActiveProgramEXT's common
    /// conditions: a compatibility context (the extension's), no
    /// glBegin/glEnd, no active transform feedback, and `program` 0 or
    /// linked (GL_INVALID_VALUE for an unknown name, GL_INVALID_OPERATION
    /// otherwise).
    fn ext_call_accepts(&mut self, program: u32) -> bool {
        if self.reject_in_begin() {
            return false;
        }
        if !self.api.compatibility() || self.feedback_active() {
            self.set_error(GL_INVALID_OPERATION);
            return false;
        }
        self.check_pipeline_program(program, false)
    }

    /// Changes GL_EXT_separate_shader_objects' attachment points with
    /// `f`, folding them back into `current_program` when they agree.
    fn update_ext(&mut self, f: impl FnOnce(&mut ExtBindings)) {
        let cur = self.current_program;
        let before = self.pipelines.ext.unwrap_or(ExtBindings {
            stages: [cur; 3],
            active: cur,
        });
        let mut b = before;
        f(&mut b);
        let one = b.stages.iter().all(|&p| p == b.active);
        if one {
            self.pipelines.ext = None;
            self.current_program = b.active;
        } else {
            self.pipelines.ext = Some(b);
            self.current_program = 0;
        }
        for old in before.stages.into_iter().chain([before.active, cur]) {
            self.release_program(old);
        }
    }

    /// glUseShaderProgramEXT (GL_EXT_separate_shader_objects, compatibility
    /// contexts): `program`'s executable for the stage of shader type
    /// `kind` (GL_INVALID_ENUM for another type).
    pub fn use_shader_program_ext(&mut self, kind: u32, program: u32) {
        let i = match kind {
            GL_VERTEX_SHADER => 0,
            GL_GEOMETRY_SHADER => 1,
            GL_FRAGMENT_SHADER => 2,
            _ => {
                if !self.reject_in_begin() {
                    self.set_error(GL_INVALID_ENUM);
                }
                return;
            }
        };
        if self.ext_call_accepts(program) {
            self.update_ext(|b| b.stages[i] = program);
        }
    }

    /// glActiveProgramEXT: the program glUniform* update.
    pub fn active_program_ext(&mut self, program: u32) {
        if self.ext_call_accepts(program) {
            self.update_ext(|b| b.active = program);
        }
    }

    /// glCreateShaderProgramEXT: glCreateShaderProgramv's program of one
    /// string, not flagged separable (the EXT form has no such flag).
    pub fn create_shader_program_ext(&mut self, kind: u32, source: &str) -> u32 {
        if self.reject_in_begin() {
            return 0;
        }
        if !self.api.compatibility() {
            self.set_error(GL_INVALID_OPERATION);
            return 0;
        }
        let p = self.create_shader_programv(kind, &[source]);
        if let Some(obj) = self.programs.get_mut(&p) {
            obj.separable = false;
        }
        p
    }

    /// glGenProgramPipelines: `n` fresh names (GL_INVALID_VALUE for a
    /// negative `n`).
    pub fn gen_program_pipelines(&mut self, n: i32) -> Vec<u32> {
        if self.reject_in_begin() {
            return Vec::new();
        }
        if n < 0 {
            self.set_error(GL_INVALID_VALUE);
            return Vec::new();
        }
        let mut out = Vec::with_capacity(n.min(1 << 16) as usize);
        for _ in 0..n {
            // Skip names still in use after the counter wraps.
            let mut name = self.pipelines.next.wrapping_add(1).max(1);
            while self.pipelines.objects.contains_key(&name) {
                name = name.wrapping_add(1).max(1);
            }
            self.pipelines.next = name;
            self.pipelines.objects.insert(name, None);
            out.push(name);
        }
        out
    }

    /// glDeleteProgramPipelines: unknown names and 0 are ignored; deleting
    /// the bound pipeline binds 0 (GL_INVALID_VALUE for a negative count,
    /// which the C layer checks).
    pub fn delete_program_pipelines(&mut self, names: &[u32]) {
        if self.reject_in_begin() {
            return;
        }
        for &name in names {
            if name == 0 {
                continue;
            }
            let Some(old) = self.pipelines.objects.remove(&name) else {
                continue;
            };
            if self.pipelines.bound == name {
                self.pipelines.bound = 0;
            }
            if let Some(p) = old {
                for program in p.stages.into_iter().chain([p.active]) {
                    self.release_program(program);
                }
            }
        }
    }

    /// glIsProgramPipeline: a name whose object exists.
    pub fn is_program_pipeline(&self, name: u32) -> bool {
        self.pipelines.get(name).is_some()
    }

    /// The pipeline object of `name`, created if the name was generated
    /// but never used; GL_INVALID_OPERATION (and `None`) for a name never
    /// generated or deleted.
    fn pipeline_mut(&mut self, name: u32) -> Option<&mut Pipeline> {
        if !self.pipelines.objects.contains_key(&name) {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        self.pipelines
            .objects
            .get_mut(&name)
            .map(|slot| slot.get_or_insert_with(Pipeline::default))
    }

    /// glBindProgramPipeline (GL_INVALID_OPERATION for a name not
    /// generated, or while transform feedback is active).
    pub fn bind_program_pipeline(&mut self, name: u32) {
        if self.reject_in_begin() {
            return;
        }
        if self.feedback_active() {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if name != 0 && self.pipeline_mut(name).is_none() {
            return;
        }
        self.pipelines.bound = name;
    }

    /// Checks the program argument of glUseProgramStages and
    /// glActiveShaderProgram: 0, or a linked program (GL_INVALID_VALUE for
    /// an unknown name, GL_INVALID_OPERATION for a shader or a program not
    /// linked, or, with `separable`, linked without GL_PROGRAM_SEPARABLE).
    fn check_pipeline_program(&mut self, program: u32, separable: bool) -> bool {
        if program == 0 {
            return true;
        }
        if !self.check_program(program) {
            return false;
        }
        let ok = self
            .programs
            .get(&program)
            .is_some_and(|p| p.link_status && (!separable || p.linked_separable));
        if !ok {
            self.set_error(GL_INVALID_OPERATION);
        }
        ok
    }

    /// glUseProgramStages: `program`'s executable for each stage of
    /// `stages` it has (0 for the others named).
    pub fn use_program_stages(&mut self, pipeline: u32, stages: u32, program: u32) {
        if self.reject_in_begin() {
            return;
        }
        let known = GL_VERTEX_SHADER_BIT | GL_GEOMETRY_SHADER_BIT | GL_FRAGMENT_SHADER_BIT;
        if stages != GL_ALL_SHADER_BITS {
            if stages & !(known | TESS_BITS) != 0 {
                self.set_error(GL_INVALID_VALUE);
                return;
            }
            if stages & TESS_BITS != 0 {
                self.set_error(GL_INVALID_ENUM);
                return;
            }
        }
        if !self.pipelines.objects.contains_key(&pipeline) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if !self.check_pipeline_program(program, true) {
            return;
        }
        if self.feedback_active() && self.pipelines.bound == pipeline {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let has: Vec<bool> = STAGES
            .iter()
            .map(|&s| {
                self.programs
                    .get(&program)
                    .and_then(|p| p.exe.as_ref())
                    .is_some_and(|e| e.has_stage(s))
            })
            .collect();
        let Some(p) = self.pipeline_mut(pipeline) else {
            return;
        };
        let mut released = Vec::new();
        for (i, &s) in STAGES.iter().enumerate() {
            if stages & stage_bit(s) != 0 {
                let new = if has[i] { program } else { 0 };
                released.push(std::mem::replace(&mut p.stages[i], new));
            }
        }
        for old in released {
            self.release_program(old);
        }
    }

    /// glActiveShaderProgram: the program glUniform* update while the
    /// pipeline is bound and no program is current.
    pub fn active_shader_program(&mut self, pipeline: u32, program: u32) {
        if self.reject_in_begin() {
            return;
        }
        if !self.pipelines.objects.contains_key(&pipeline) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if !self.check_pipeline_program(program, false) {
            return;
        }
        if let Some(p) = self.pipeline_mut(pipeline) {
            let old = std::mem::replace(&mut p.active, program);
            self.release_program(old);
        }
    }

    /// Why the pipeline `name` cannot draw, if it cannot: the rules of
    /// the extension's "Validation" list that apply without tessellation,
    /// and, with `samplers`, glValidateProgram's samplers rule for each
    /// program (which draws through glUseProgram do not check either).
    fn pipeline_invalid(&self, name: u32, samplers: bool) -> Option<String> {
        let p = self.pipelines.get(name)?;
        for (i, &prog) in p.stages.iter().enumerate() {
            if prog == 0 {
                continue;
            }
            let Some(obj) = self.programs.get(&prog) else {
                return Some(format!("program {prog} of the pipeline no longer exists"));
            };
            if !obj.linked_separable {
                return Some(format!(
                    "program {prog} was linked again without GL_PROGRAM_SEPARABLE"
                ));
            }
            let Some(exe) = obj.exe.as_ref().filter(|_| obj.link_status) else {
                return Some(format!("program {prog} is not linked"));
            };
            // Every stage the program has must be taken from it.
            for (j, &s) in STAGES.iter().enumerate() {
                if exe.has_stage(s) && p.stages[j] != prog {
                    return Some(format!(
                        "program {prog} has a {} stage but is not the pipeline's program for it",
                        s.name()
                    ));
                }
            }
            // The stages one program holds are consecutive (no other
            // program between two of them).
            for (j, &between) in p.stages.iter().enumerate().skip(i + 1) {
                let later = p.stages[j + 1..].contains(&prog);
                if between != prog && between != 0 && later {
                    return Some(format!(
                        "program {between} sits between two stages of program {prog}"
                    ));
                }
            }
            if let Some(why) = crate::program::sampler_conflict(exe).filter(|_| samplers) {
                return Some(format!("program {prog}: {why}"));
            }
        }
        if p.stages[1] != 0 && p.stages[0] == 0 {
            return Some("the pipeline has a geometry stage but no vertex stage".into());
        }
        None
    }

    /// glValidateProgramPipeline: GL_VALIDATE_STATUS and the info log of
    /// the pipeline against the current state.
    pub fn validate_program_pipeline(&mut self, name: u32) {
        if self.reject_in_begin() || self.pipeline_mut(name).is_none() {
            return;
        }
        let why = self.pipeline_invalid(name, true);
        if let Some(p) = self
            .pipelines
            .objects
            .get_mut(&name)
            .and_then(Option::as_mut)
        {
            p.validate_status = why.is_none();
            p.info_log = why.map(|w| format!("error: {w}\n")).unwrap_or_default();
        }
    }

    /// Whether a draw may use the bound pipeline: true without one (or
    /// with a current program); else its validation, GL_INVALID_OPERATION
    /// when it fails.
    pub(crate) fn pipeline_draw_check(&mut self) -> bool {
        let ext = self.pipelines.ext.is_some_and(|b| b.any());
        if self.current_program != 0 || ext || self.pipelines.bound == 0 {
            return true;
        }
        if self.pipeline_invalid(self.pipelines.bound, false).is_some() {
            self.set_error(GL_INVALID_OPERATION);
            return false;
        }
        true
    }

    /// glGetProgramPipelineiv.
    pub fn get_program_pipelineiv(&mut self, name: u32, pname: u32) -> i32 {
        if self.reject_in_begin() {
            return 0;
        }
        let Some(p) = self.pipeline_mut(name) else {
            return 0;
        };
        let v = match pname {
            GL_ACTIVE_PROGRAM => Some(p.active as i32),
            GL_VERTEX_SHADER => Some(p.stages[0] as i32),
            GL_GEOMETRY_SHADER => Some(p.stages[1] as i32),
            GL_FRAGMENT_SHADER => Some(p.stages[2] as i32),
            GL_VALIDATE_STATUS => Some(p.validate_status as i32),
            GL_INFO_LOG_LENGTH => Some(crate::program::with_nul(p.info_log.len())),
            _ => None,
        };
        self.iv_query(Some(v))
    }

    /// glGetProgramPipelineInfoLog: the last validation's log (empty for
    /// a generated name whose object does not exist yet, which this call
    /// does not create); GL_INVALID_VALUE for a name never generated (GL
    /// 4.1 §6.1.12).
    pub fn get_program_pipeline_info_log(&mut self, name: u32) -> String {
        if self.reject_in_begin() {
            return String::new();
        }
        match self.pipelines.objects.get(&name) {
            Some(p) => p.as_ref().map(|p| p.info_log.clone()).unwrap_or_default(),
            None => {
                self.set_error(GL_INVALID_VALUE);
                String::new()
            }
        }
    }

    /// glCreateShaderProgramv: a separable program linked from one shader
    /// object of `kind` made of `strings`, the shader's info log appended
    /// to the program's; 0 (and GL_INVALID_ENUM) for an unknown kind.
    pub fn create_shader_programv(&mut self, kind: u32, strings: &[&str]) -> u32 {
        if self.reject_in_begin() {
            return 0;
        }
        let shader = self.create_shader(kind);
        if shader == 0 {
            return 0;
        }
        self.shader_source(shader, strings);
        self.compile_shader(shader);
        let program = self.create_program();
        self.program_parameteri(program, GL_PROGRAM_SEPARABLE, GL_TRUE as i32);
        let compiled = self
            .shaders
            .get(&shader)
            .is_some_and(|s| s.compile_status());
        if compiled {
            self.attach_shader(program, shader);
            self.link_program(program);
            self.detach_shader(program, shader);
        }
        let shader_log = self
            .shaders
            .get(&shader)
            .map(|s| s.info_log())
            .unwrap_or_default();
        if let Some(p) = self.programs.get_mut(&program) {
            p.info_log.push_str(&shader_log);
        }
        self.delete_shader(shader);
        program
    }
}
