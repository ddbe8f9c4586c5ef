//! GL_ARB_separate_shader_objects through the C ABI: its entry points by
//! name, a draw through a program pipeline of two separable programs
//! (one made by glCreateShaderProgramv), glProgramUniform*, the pipeline
//! queries, and hostile arguments.

use gl::enums::*;
use std::ffi::CString;
use OSMesa::*;

mod common;

const NAMES: &[&str] = &[
    "glUseProgramStages",
    "glActiveShaderProgram",
    "glCreateShaderProgramv",
    "glBindProgramPipeline",
    "glDeleteProgramPipelines",
    "glGenProgramPipelines",
    "glIsProgramPipeline",
    "glProgramParameteri",
    "glGetProgramPipelineiv",
    "glValidateProgramPipeline",
    "glGetProgramPipelineInfoLog",
    "glProgramUniform1i",
    "glProgramUniform2i",
    "glProgramUniform3i",
    "glProgramUniform4i",
    "glProgramUniform1ui",
    "glProgramUniform2ui",
    "glProgramUniform3ui",
    "glProgramUniform4ui",
    "glProgramUniform1f",
    "glProgramUniform2f",
    "glProgramUniform3f",
    "glProgramUniform4f",
    "glProgramUniform1iv",
    "glProgramUniform2iv",
    "glProgramUniform3iv",
    "glProgramUniform4iv",
    "glProgramUniform1uiv",
    "glProgramUniform2uiv",
    "glProgramUniform3uiv",
    "glProgramUniform4uiv",
    "glProgramUniform1fv",
    "glProgramUniform2fv",
    "glProgramUniform3fv",
    "glProgramUniform4fv",
    "glProgramUniformMatrix2fv",
    "glProgramUniformMatrix3fv",
    "glProgramUniformMatrix4fv",
    "glProgramUniformMatrix2x3fv",
    "glProgramUniformMatrix3x2fv",
    "glProgramUniformMatrix2x4fv",
    "glProgramUniformMatrix4x2fv",
    "glProgramUniformMatrix3x4fv",
    "glProgramUniformMatrix4x3fv",
    "glUseShaderProgramEXT",
    "glActiveProgramEXT",
    "glCreateShaderProgramEXT",
];

#[test]
fn entry_points_are_exported_by_name() {
    common::assert_exported(NAMES);
}

const VS: &str = "#version 150
in vec2 pos;
out vec4 color;
void main() { gl_Position = vec4(pos, 0.0, 1.0); color = vec4(0.0, 1.0, 0.0, 1.0); }";

const FS: &str = "#version 150
uniform vec4 tint;
in vec4 color;
out vec4 frag;
void main() { frag = color + tint; }";

#[test]
fn a_pipeline_draws_through_the_c_abi() {
    common::with_context(8, 8, Some(OSMESA_CORE_PROFILE), |_| unsafe {
        // The vertex program by hand, the fragment one from
        // glCreateShaderProgramv.
        let vs = common::attached(&[(GL_VERTEX_SHADER, VS)]);
        glProgramParameteri(vs, GL_PROGRAM_SEPARABLE, 1);
        glLinkProgram(vs);
        let src = CString::new(FS).unwrap();
        let ptr = src.as_ptr();
        let fs = glCreateShaderProgramv(GL_FRAGMENT_SHADER, 1, &ptr);
        let mut v = 0;
        glGetProgramiv(fs, GL_LINK_STATUS, &mut v);
        assert_eq!(v, 1);
        glGetProgramiv(fs, GL_PROGRAM_SEPARABLE, &mut v);
        assert_eq!(v, 1);
        let mut pipe = 0;
        glGenProgramPipelines(1, &mut pipe);
        glUseProgramStages(pipe, GL_VERTEX_SHADER_BIT, vs);
        glUseProgramStages(pipe, GL_FRAGMENT_SHADER_BIT, fs);
        glBindProgramPipeline(pipe);
        assert_eq!(glIsProgramPipeline(pipe), 1);
        glGetIntegerv(GL_PROGRAM_PIPELINE_BINDING, &mut v);
        assert_eq!(v, pipe as i32);
        glGetProgramPipelineiv(pipe, GL_FRAGMENT_SHADER, &mut v);
        assert_eq!(v, fs as i32);
        common::quad_vertex_array(vs, "pos");
        let name = CString::new("tint").unwrap();
        let tint = glGetUniformLocation(fs, name.as_ptr());
        glProgramUniform4fv(fs, tint, 1, [1.0f32, 0.0, 0.0, 0.0].as_ptr());
        assert_eq!(glGetError(), GL_NO_ERROR);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        assert_eq!(glGetError(), GL_NO_ERROR);
        assert_eq!(common::pixel_at(4, 4), [255, 255, 0, 255]);
        // glUniform* go to the active program.
        glActiveShaderProgram(pipe, fs);
        glUniform4f(tint, 0.0, 0.0, 1.0, 0.0);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        assert_eq!(common::pixel_at(4, 4), [0, 255, 255, 255]);
        // Validation and its log.
        glValidateProgramPipeline(pipe);
        glGetProgramPipelineiv(pipe, GL_VALIDATE_STATUS, &mut v);
        assert_eq!(v, 1);
        glUseProgramStages(pipe, GL_VERTEX_SHADER_BIT, 0);
        glUseProgramStages(pipe, GL_GEOMETRY_SHADER_BIT, fs);
        let gs = common::attached(&[(
            GL_GEOMETRY_SHADER,
            "#version 150\nlayout(points) in;\nlayout(points, max_vertices = 1) out;\nvoid main() { EmitVertex(); }",
        )]);
        glProgramParameteri(gs, GL_PROGRAM_SEPARABLE, 1);
        glLinkProgram(gs);
        glUseProgramStages(pipe, GL_GEOMETRY_SHADER_BIT, gs);
        glValidateProgramPipeline(pipe);
        glGetProgramPipelineiv(pipe, GL_VALIDATE_STATUS, &mut v);
        assert_eq!(v, 0);
        let mut log = [0u8; 256];
        let mut len = 0;
        glGetProgramPipelineInfoLog(pipe, 256, &mut len, log.as_mut_ptr() as *mut GLchar);
        assert!(len > 0);
        assert_eq!(glGetError(), GL_NO_ERROR);
        glDeleteProgramPipelines(1, &pipe);
        assert_eq!(glIsProgramPipeline(pipe), 0);
        glGetIntegerv(GL_PROGRAM_PIPELINE_BINDING, &mut v);
        assert_eq!(v, 0);
    });
}

/// GL_EXT_separate_shader_objects on a compatibility context: a vertex
/// program and a fragment program bound with glUseShaderProgramEXT,
/// uniforms through glActiveProgramEXT.
#[test]
fn ext_attachment_points_through_the_c_abi() {
    common::with_context(8, 8, Some(OSMESA_COMPAT_PROFILE), |_| unsafe {
        let vs_src = CString::new(VS).unwrap();
        let fs_src = CString::new(FS).unwrap();
        let vs = glCreateShaderProgramEXT(GL_VERTEX_SHADER, vs_src.as_ptr());
        let fs = glCreateShaderProgramEXT(GL_FRAGMENT_SHADER, fs_src.as_ptr());
        let mut v = 0;
        glGetProgramiv(fs, GL_LINK_STATUS, &mut v);
        assert_eq!(v, 1);
        glUseShaderProgramEXT(GL_VERTEX_SHADER, vs);
        glUseShaderProgramEXT(GL_FRAGMENT_SHADER, fs);
        glActiveProgramEXT(fs);
        glGetIntegerv(GL_CURRENT_PROGRAM, &mut v);
        assert_eq!(v, fs as i32);
        let name = CString::new("tint").unwrap();
        let tint = glGetUniformLocation(fs, name.as_ptr());
        glUniform4f(tint, 1.0, 0.0, 0.0, 0.0);
        common::quad_vertex_array(vs, "pos");
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        assert_eq!(glGetError(), GL_NO_ERROR);
        assert_eq!(common::pixel_at(4, 4), [255, 255, 0, 255]);
        glUseShaderProgramEXT(0xdead, vs);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glUseProgram(0);
        glGetIntegerv(GL_CURRENT_PROGRAM, &mut v);
        assert_eq!(v, 0);
    });
}

/// Bad counts, names, bits and null pointers: each records an error or
/// succeeds, none panics.
#[test]
fn hostile_arguments_never_crash() {
    common::with_context(8, 8, Some(OSMESA_COMPAT_PROFILE), |_| unsafe {
        glGenProgramPipelines(-1, std::ptr::null_mut());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glDeleteProgramPipelines(-1, std::ptr::null());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glDeleteProgramPipelines(0, std::ptr::null());
        assert_eq!(glGetError(), GL_NO_ERROR);
        assert_eq!(
            glCreateShaderProgramv(GL_VERTEX_SHADER, -1, std::ptr::null()),
            0
        );
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        let null: *const GLchar = std::ptr::null();
        assert_eq!(glCreateShaderProgramv(GL_VERTEX_SHADER, 1, &null), 0);
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        let mut pipe = 0;
        glGenProgramPipelines(1, &mut pipe);
        for (stages, program, err) in [
            (0xdead_beef, 0, GL_INVALID_VALUE),
            (GL_TESS_EVALUATION_SHADER_BIT, 0, GL_INVALID_ENUM),
            (GL_VERTEX_SHADER_BIT, 777, GL_INVALID_VALUE),
            (GL_ALL_SHADER_BITS, 0, GL_NO_ERROR),
        ] {
            glUseProgramStages(pipe, stages, program);
            assert_eq!(glGetError(), err, "{stages:#x} {program}");
        }
        glUseProgramStages(pipe + 100, GL_VERTEX_SHADER_BIT, 0);
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        let mut v = 7;
        glGetProgramPipelineiv(pipe, 0xdead, &mut v);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glGetProgramPipelineiv(pipe, GL_ACTIVE_PROGRAM, std::ptr::null_mut());
        glGetProgramPipelineInfoLog(pipe, -1, std::ptr::null_mut(), std::ptr::null_mut());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glProgramUniform4fv(0, 0, -1, std::ptr::null());
        glProgramUniformMatrix4fv(12345, 0, 1, 0, std::ptr::null());
        glProgramUniform1i(pipe, 0, 3);
        assert_ne!(glGetError(), GL_NO_ERROR);
        glBegin(GL_POINTS);
        glBindProgramPipeline(pipe);
        glEnd();
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        // Drawing still works.
        glClearColor(0.0, 1.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        assert_eq!(common::pixel_at(1, 1), [0, 255, 0, 255]);
    });
}
