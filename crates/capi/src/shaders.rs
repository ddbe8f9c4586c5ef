//! Shader and program objects (GL 2.1 §2.15, §6.1.14): creating,
//! compiling, attaching and linking them, attribute locations, and their
//! queries (info logs, sources, active attributes and uniforms), and the
//! uniform-block queries and bindings (GL 3.3 §2.11.4). Setting uniforms
//! is [`crate::uniforms`].

use crate::abi::*;
use crate::context::{record_call, with_ctx, OsContext};
use gl::enums::*;
use std::ffi::CStr;

/// glGet*InfoLog / glGetShaderSource output: at most `buf_size - 1` bytes
/// and a NUL; `length` gets the bytes written without the NUL.
pub(crate) unsafe fn wr_string(
    c: &mut OsContext,
    s: &str,
    buf_size: GLsizei,
    length: *mut GLsizei,
    out: *mut GLchar,
) {
    if buf_size < 0 {
        c.gl.record_error(GL_INVALID_VALUE);
        return;
    }
    let n = if out.is_null() || buf_size == 0 {
        0
    } else {
        let n = s.len().min(buf_size as usize - 1);
        // SAFETY: the caller's buffer holds buf_size bytes.
        unsafe {
            std::ptr::copy_nonoverlapping(s.as_ptr() as *const GLchar, out, n);
            *out.add(n) = 0;
        }
        n
    };
    // SAFETY: out pointer or null.
    unsafe { wr(length, &[n as GLsizei]) };
}

/// GL_ARB_shader_objects' object queries.
const GL_PROGRAM_OBJECT_ARB: GLenum = 0x8B40;
const GL_SHADER_OBJECT_ARB: GLenum = 0x8B48;
const GL_OBJECT_TYPE_ARB: GLenum = 0x8B4E;
const GL_OBJECT_SUBTYPE_ARB: GLenum = 0x8B4F;

/// glGetObjectParameter*ARB: the object's type and subtype (its shader
/// type), else the shader or program query of the same number (the
/// extension's other names are GL 2.0's values: GL_OBJECT_COMPILE_STATUS_ARB
/// is GL_COMPILE_STATUS...). None after recording the error: an unknown
/// object is GL_INVALID_VALUE, a subtype of a program GL_INVALID_ENUM.
fn object_parameter(c: &mut OsContext, obj: GLuint, pname: GLenum) -> Option<GLint> {
    let shader = c.gl.is_shader(obj);
    if !shader && !c.gl.is_program(obj) {
        c.gl.record_error(GL_INVALID_VALUE);
        return None;
    }
    Some(match (pname, shader) {
        (GL_OBJECT_TYPE_ARB, true) => GL_SHADER_OBJECT_ARB as GLint,
        (GL_OBJECT_TYPE_ARB, false) => GL_PROGRAM_OBJECT_ARB as GLint,
        (GL_OBJECT_SUBTYPE_ARB, true) => c.gl.get_shaderiv(obj, GL_SHADER_TYPE),
        (GL_OBJECT_SUBTYPE_ARB, false) => {
            c.gl.record_error(GL_INVALID_ENUM);
            return None;
        }
        (_, true) => c.gl.get_shaderiv(obj, pname),
        (_, false) => c.gl.get_programiv(obj, pname),
    })
}

/// The strings of glShaderSource or glCreateShaderProgramv: `count`
/// strings at `strings`, each NUL-terminated or of its length in
/// `lengths` (null: all NUL-terminated); the GL error otherwise: a
/// negative count or a null array is GL_INVALID_VALUE, a null string
/// GL_INVALID_OPERATION (as Mesa answers: GL 2.1 leaves it undefined;
/// reading it would crash).
///
/// # Safety
/// GL's contract on the pointers.
unsafe fn source_strings(
    count: GLsizei,
    strings: *const *const GLchar,
    lengths: *const GLint,
) -> Result<Vec<String>, GLenum> {
    if count < 0 || (count > 0 && strings.is_null()) {
        return Err(GL_INVALID_VALUE);
    }
    // SAFETY: `count` string pointers at `strings`.
    if (0..count as usize).any(|i| unsafe { *strings.add(i) }.is_null()) {
        return Err(GL_INVALID_OPERATION);
    }
    let mut parts = Vec::with_capacity(count as usize);
    for i in 0..count as usize {
        // SAFETY: as above; each string NUL-terminated or `len` bytes.
        unsafe {
            let s = *strings.add(i);
            let len = if lengths.is_null() {
                -1
            } else {
                *lengths.add(i)
            };
            let text = if len < 0 {
                CStr::from_ptr(s).to_string_lossy().into_owned()
            } else {
                String::from_utf8_lossy(bytes(s, len as usize)).into_owned()
            };
            parts.push(text);
        }
    }
    Ok(parts)
}

gl_entry_points! {
    // ---- shaders ----
    fn glCreateShader(kind: GLenum) -> GLuint [0] => |c| { c.gl.create_shader(kind) }
    fn glShaderSource(
        shader: GLuint, count: GLsizei, strings: *const *const GLchar, lengths: *const GLint
    ) => |c| {
        if count < 0 || (count > 0 && strings.is_null()) {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        if !c.gl.check_shader(shader) {
            return;
        }
        match source_strings(count, strings, lengths) {
            Ok(parts) => {
                let refs: Vec<&str> = parts.iter().map(|s| s.as_str()).collect();
                c.gl.shader_source(shader, &refs);
            }
            Err(e) => c.gl.record_error(e),
        }
    }
    fn glCompileShader(shader: GLuint) => |c| { c.gl.compile_shader(shader) }
    fn glDeleteShader(shader: GLuint) => |c| { c.gl.delete_shader(shader) }
    fn glIsShader(shader: GLuint) -> GLboolean [0] => |c| { c.gl.is_shader(shader) as GLboolean }
    fn glGetShaderiv(shader: GLuint, pname: GLenum, params: *mut GLint) => |c| {
        let v = c.gl.get_shaderiv(shader, pname);
        wr(params, &[v]);
    }
    fn glGetShaderInfoLog(
        shader: GLuint, buf_size: GLsizei, length: *mut GLsizei, log: *mut GLchar
    ) => |c| {
        let s = c.gl.get_shader_info_log(shader);
        wr_string(c, &s, buf_size, length, log);
    }
    fn glGetShaderSource(
        shader: GLuint, buf_size: GLsizei, length: *mut GLsizei, source: *mut GLchar
    ) => |c| {
        let s = c.gl.get_shader_source(shader);
        wr_string(c, &s, buf_size, length, source);
    }

    // ---- programs ----
    fn glCreateProgram() -> GLuint [0] => |c| { c.gl.create_program() }
    fn glDeleteProgram(program: GLuint) => |c| { c.gl.delete_program(program) }
    fn glIsProgram(program: GLuint) -> GLboolean [0] => |c| {
        c.gl.is_program(program) as GLboolean
    }
    fn glAttachShader(program: GLuint, shader: GLuint) => |c| { c.gl.attach_shader(program, shader) }
    fn glDetachShader(program: GLuint, shader: GLuint) => |c| { c.gl.detach_shader(program, shader) }
    fn glLinkProgram(program: GLuint) => |c| { c.gl.link_program(program) }
    // GL_ARB_geometry_shader4 / GL_EXT_geometry_shader4 (and GL 4.1's name).
    fn glProgramParameteri(program: GLuint, pname: GLenum, value: GLint) => |c| {
        c.gl.program_parameteri(program, pname, value)
    }
    fn glProgramParameteriARB(program: GLuint, pname: GLenum, value: GLint) => |c| {
        c.gl.program_parameteri(program, pname, value)
    }
    fn glProgramParameteriEXT(program: GLuint, pname: GLenum, value: GLint) => |c| {
        c.gl.program_parameteri(program, pname, value)
    }
    fn glValidateProgram(program: GLuint) => |c| { c.gl.validate_program(program) }

    // ---- separable programs and program pipelines
    // (GL_ARB_separate_shader_objects, GL 4.1's names) ----
    fn glCreateShaderProgramv(
        kind: GLenum, count: GLsizei, strings: *const *const GLchar
    ) -> GLuint [0] => |c| {
        match source_strings(count, strings, std::ptr::null()) {
            Ok(parts) => {
                let refs: Vec<&str> = parts.iter().map(|s| s.as_str()).collect();
                c.gl.create_shader_programv(kind, &refs)
            }
            Err(e) => {
                c.gl.record_error(e);
                0
            }
        }
    }
    // GL_EXT_separate_shader_objects (compatibility contexts).
    fn glUseShaderProgramEXT(kind: GLenum, program: GLuint) => |c| {
        c.gl.use_shader_program_ext(kind, program)
    }
    fn glActiveProgramEXT(program: GLuint) => |c| { c.gl.active_program_ext(program) }
    fn glCreateShaderProgramEXT(kind: GLenum, string: *const GLchar) -> GLuint [0] => |c| {
        match source_strings(1, &string, std::ptr::null()) {
            Ok(parts) => c.gl.create_shader_program_ext(kind, &parts[0]),
            Err(e) => {
                c.gl.record_error(e);
                0
            }
        }
    }
    fn glGenProgramPipelines(n: GLsizei, pipelines: *mut GLuint) => |c| {
        let names = c.gl.gen_program_pipelines(n);
        wr(pipelines, &names);
    }
    fn glDeleteProgramPipelines(n: GLsizei, pipelines: *const GLuint) => |c| {
        if n < 0 {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        let names = rd_vec(pipelines, n as i64);
        c.gl.delete_program_pipelines(&names);
    }
    fn glIsProgramPipeline(pipeline: GLuint) -> GLboolean [0] => |c| {
        if c.gl.reject_in_begin() {
            return 0;
        }
        c.gl.is_program_pipeline(pipeline) as GLboolean
    }
    fn glBindProgramPipeline(pipeline: GLuint) => |c| { c.gl.bind_program_pipeline(pipeline) }
    fn glUseProgramStages(pipeline: GLuint, stages: GLbitfield, program: GLuint) => |c| {
        c.gl.use_program_stages(pipeline, stages, program)
    }
    fn glActiveShaderProgram(pipeline: GLuint, program: GLuint) => |c| {
        c.gl.active_shader_program(pipeline, program)
    }
    fn glValidateProgramPipeline(pipeline: GLuint) => |c| {
        c.gl.validate_program_pipeline(pipeline)
    }
    fn glGetProgramPipelineiv(pipeline: GLuint, pname: GLenum, params: *mut GLint) => |c| {
        let v = c.gl.get_program_pipelineiv(pipeline, pname);
        wr(params, &[v]);
    }
    fn glGetProgramPipelineInfoLog(
        pipeline: GLuint, buf_size: GLsizei, length: *mut GLsizei, log: *mut GLchar
    ) => |c| {
        let s = c.gl.get_program_pipeline_info_log(pipeline);
        wr_string(c, &s, buf_size, length, log);
    }
    [list] fn glUseProgram(program: GLuint) => |c| { c.gl.use_program(program) }
    fn glGetProgramiv(program: GLuint, pname: GLenum, params: *mut GLint) => |c| {
        let v = c.gl.get_programiv(program, pname);
        wr(params, &[v]);
    }
    fn glGetProgramInfoLog(
        program: GLuint, buf_size: GLsizei, length: *mut GLsizei, log: *mut GLchar
    ) => |c| {
        let s = c.gl.get_program_info_log(program);
        wr_string(c, &s, buf_size, length, log);
    }
    fn glGetAttachedShaders(
        program: GLuint, max: GLsizei, count: *mut GLsizei, shaders: *mut GLuint
    ) => |c| {
        if max < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        let v = c.gl.get_attached_shaders(program);
        let n = v.len().min(max as usize);
        wr(shaders, &v[..n]);
        wr(count, &[n as GLsizei]);
    }

    // ---- GL_ARB_shader_objects' own names (its other functions are the
    // core ones under ARB names: crate::procs::lookup). Shader and program
    // objects share one name space, so an object name says which it is.
    fn glCreateShaderObjectARB(kind: GLenum) -> GLuint [0] => |c| { c.gl.create_shader(kind) }
    fn glCreateProgramObjectARB() -> GLuint [0] => |c| { c.gl.create_program() }
    fn glDeleteObjectARB(obj: GLuint) => |c| {
        if c.gl.is_shader(obj) {
            c.gl.delete_shader(obj)
        } else if c.gl.is_program(obj) {
            c.gl.delete_program(obj)
        } else if obj != 0 {
            c.gl.record_error(GL_INVALID_VALUE)
        }
    }
    fn glGetHandleARB(pname: GLenum) -> GLuint [0] => |c| {
        if pname == GL_PROGRAM_OBJECT_ARB {
            c.gl.get_integerv(GL_CURRENT_PROGRAM).first().copied().unwrap_or(0) as GLuint
        } else {
            c.gl.record_error(GL_INVALID_ENUM);
            0
        }
    }
    fn glAttachObjectARB(container: GLuint, obj: GLuint) => |c| {
        c.gl.attach_shader(container, obj)
    }
    fn glDetachObjectARB(container: GLuint, obj: GLuint) => |c| {
        c.gl.detach_shader(container, obj)
    }
    [list] fn glUseProgramObjectARB(program: GLuint) => |c| { c.gl.use_program(program) }
    fn glGetObjectParameterivARB(obj: GLuint, pname: GLenum, params: *mut GLint) => |c| {
        if let Some(v) = object_parameter(c, obj, pname) {
            wr(params, &[v]);
        }
    }
    fn glGetObjectParameterfvARB(obj: GLuint, pname: GLenum, params: *mut GLfloat) => |c| {
        if let Some(v) = object_parameter(c, obj, pname) {
            wr(params, &[v as GLfloat]);
        }
    }
    fn glGetInfoLogARB(
        obj: GLuint, max_length: GLsizei, length: *mut GLsizei, log: *mut GLchar
    ) => |c| {
        let s = if c.gl.is_shader(obj) {
            c.gl.get_shader_info_log(obj)
        } else if c.gl.is_program(obj) {
            c.gl.get_program_info_log(obj)
        } else {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        };
        wr_string(c, &s, max_length, length, log);
    }
    fn glGetAttachedObjectsARB(
        container: GLuint, max: GLsizei, count: *mut GLsizei, objs: *mut GLuint
    ) => |c| {
        if max < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        let v = c.gl.get_attached_shaders(container);
        let n = v.len().min(max as usize);
        wr(objs, &v[..n]);
        wr(count, &[n as GLsizei]);
    }

    // ---- attributes and active variables ----
    fn glGetAttribLocation(program: GLuint, name: *const GLchar) -> GLint [-1] => |c| {
        match cstr(name) {
            Some(n) => c.gl.get_attrib_location(program, &n),
            None => -1,
        }
    }
    fn glBindAttribLocation(program: GLuint, index: GLuint, name: *const GLchar) => |c| {
        if let Some(n) = cstr(name) { c.gl.bind_attrib_location(program, index, &n) }
    }
    fn glBindFragDataLocation(program: GLuint, color: GLuint, name: *const GLchar) => |c| {
        if let Some(n) = cstr(name) { c.gl.bind_frag_data_location(program, color, &n) }
    }
    fn glGetFragDataLocation(program: GLuint, name: *const GLchar) -> GLint [-1] => |c| {
        match cstr(name) {
            Some(n) => c.gl.get_frag_data_location(program, &n),
            None => -1,
        }
    }
    fn glBindFragDataLocationIndexed(
        program: GLuint, color: GLuint, index: GLuint, name: *const GLchar
    ) => |c| {
        if let Some(n) = cstr(name) { c.gl.bind_frag_data_location_indexed(program, color, index, &n) }
    }
    fn glGetFragDataIndex(program: GLuint, name: *const GLchar) -> GLint [-1] => |c| {
        match cstr(name) {
            Some(n) => c.gl.get_frag_data_index(program, &n),
            None => -1,
        }
    }
    fn glTransformFeedbackVaryings(
        program: GLuint, count: GLsizei, varyings: *const *const GLchar, mode: GLenum
    ) => |c| {
        if count < 0 {
            if !c.gl.reject_in_begin() {
                c.gl.record_error(gl::enums::GL_INVALID_VALUE);
            }
            return;
        }
        let names: Vec<String> = rd_vec(varyings, count as i64)
            .into_iter()
            .map(|p| cstr(p).unwrap_or_default())
            .collect();
        c.gl.transform_feedback_varyings(program, &names, mode)
    }
    fn glGetTransformFeedbackVarying(
        program: GLuint, index: GLuint, buf_size: GLsizei, length: *mut GLsizei,
        size: *mut GLsizei, ty: *mut GLenum, name: *mut GLchar
    ) => |c| {
        if let Some(info) = c.gl.get_transform_feedback_varying(program, index) {
            wr(size, &[info.size]);
            wr(ty, &[info.ty]);
            wr_string(c, &info.name, buf_size, length, name);
        }
    }
    [list] fn glBeginTransformFeedback(mode: GLenum) => |c| { c.gl.begin_transform_feedback(mode) }
    [list] fn glEndTransformFeedback() => |c| { c.gl.end_transform_feedback() }
    fn glGetActiveAttrib(
        program: GLuint, index: GLuint, buf_size: GLsizei, length: *mut GLsizei,
        size: *mut GLint, ty: *mut GLenum, name: *mut GLchar
    ) => |c| {
        if let Some(info) = c.gl.get_active_attrib(program, index) {
            wr(size, &[info.size]);
            wr(ty, &[info.ty]);
            wr_string(c, &info.name, buf_size, length, name);
        }
    }
    fn glGetActiveUniform(
        program: GLuint, index: GLuint, buf_size: GLsizei, length: *mut GLsizei,
        size: *mut GLint, ty: *mut GLenum, name: *mut GLchar
    ) => |c| {
        if let Some(info) = c.gl.get_active_uniform(program, index) {
            wr(size, &[info.size]);
            wr(ty, &[info.ty]);
            wr_string(c, &info.name, buf_size, length, name);
        }
    }

    // ---- uniform blocks (GL 3.1, ARB_uniform_buffer_object) ----
    fn glGetUniformBlockIndex(program: GLuint, name: *const GLchar) -> GLuint [u32::MAX] => |c| {
        match cstr(name) {
            Some(n) => c.gl.get_uniform_block_index(program, &n),
            None => u32::MAX,
        }
    }
    fn glGetActiveUniformBlockName(
        program: GLuint, index: GLuint, buf_size: GLsizei, length: *mut GLsizei, name: *mut GLchar
    ) => |c| {
        if let Some(s) = c.gl.get_active_uniform_block_name(program, index) {
            wr_string(c, &s, buf_size, length, name);
        }
    }
    fn glGetActiveUniformBlockiv(program: GLuint, index: GLuint, pname: GLenum, params: *mut GLint) => |c| {
        if let Some(v) = c.gl.get_active_uniform_blockiv(program, index, pname) {
            wr(params, &v);
        }
    }
    fn glUniformBlockBinding(program: GLuint, index: GLuint, binding: GLuint) => |c| {
        c.gl.uniform_block_binding(program, index, binding)
    }

    // ---- storage blocks and compute dispatch (GL_ARB_shader_storage_buffer_object,
    // GL_ARB_compute_shader) ----
    fn glShaderStorageBlockBinding(program: GLuint, index: GLuint, binding: GLuint) => |c| {
        c.gl.shader_storage_block_binding(program, index, binding)
    }
    fn glDispatchCompute(x: GLuint, y: GLuint, z: GLuint) => |c| {
        c.gl.dispatch_compute(x, y, z)
    }
    fn glDispatchComputeIndirect(offset: GLintptr) => |c| {
        c.gl.dispatch_compute_indirect(offset)
    }
    fn glMemoryBarrier(barriers: GLbitfield) => |c| {
        c.gl.memory_barrier(barriers)
    }
    fn glGetUniformIndices(
        program: GLuint, count: GLsizei, names: *const *const GLchar, indices: *mut GLuint
    ) => |c| {
        if count < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        let ptrs = rd_vec(names, count as i64);
        let owned: Vec<String> = ptrs.iter().map(|&p| cstr(p).unwrap_or_default()).collect();
        let refs: Vec<&str> = owned.iter().map(String::as_str).collect();
        if let Some(v) = c.gl.get_uniform_indices(program, &refs) {
            wr(indices, &v);
        }
    }
    fn glGetActiveUniformsiv(
        program: GLuint, count: GLsizei, indices: *const GLuint, pname: GLenum, params: *mut GLint
    ) => |c| {
        if count < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        let idx = rd_vec(indices, count as i64);
        if let Some(v) = c.gl.get_active_uniformsiv(program, &idx, pname) {
            wr(params, &v);
        }
    }
    fn glGetActiveUniformName(
        program: GLuint, index: GLuint, buf_size: GLsizei, length: *mut GLsizei, name: *mut GLchar
    ) => |c| {
        if let Some(s) = c.gl.get_active_uniform_name(program, index) {
            wr_string(c, &s, buf_size, length, name);
        }
    }
}
