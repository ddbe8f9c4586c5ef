//! Uniform variables of the current program (GL 2.1 §2.15.3, §6.1.14):
//! locations, the glUniform* setters and the glProgramUniform* ones that
//! name their program (GL_ARB_separate_shader_objects) (glUniform* scalars
//! compiled into display lists;
//! the array forms read `count` elements, at most
//! `MAX_UNIFORM_ELEMENTS`, and execute at once) and glGetUniform*v.

use crate::abi::*;
use crate::context::{record_call, with_ctx};

/// Most array elements read from client memory by one glUniform*v call.
const MAX_UNIFORM_ELEMENTS: i32 = 4096;

/// The body of a glUniform*v call: reads `count` elements (at most
/// [`MAX_UNIFORM_ELEMENTS`]) of `per` values each at `v` and hands `set`
/// the element count and the values.
unsafe fn uniform_array<T: Copy>(
    gl: &mut gl::Context,
    count: GLsizei,
    v: *const T,
    per: i64,
    set: impl FnOnce(&mut gl::Context, GLsizei, &[T]),
) {
    let n = count.min(MAX_UNIFORM_ELEMENTS);
    // SAFETY: GL's contract: `count` elements of `per` values at v.
    let values = unsafe { rd_vec(v, n as i64 * per) };
    set(gl, n, &values);
}

gl_entry_points! {
    fn glGetUniformLocation(program: GLuint, name: *const GLchar) -> GLint [-1] => |c| {
        match cstr(name) {
            Some(n) => c.gl.get_uniform_location(program, &n),
            None => -1,
        }
    }

    // ---- scalars ----
    [list] fn glUniform1f(loc: GLint, x: GLfloat) => |c| { c.gl.uniform_1f(loc, x) }
    [list] fn glUniform2f(loc: GLint, x: GLfloat, y: GLfloat) => |c| { c.gl.uniform_2f(loc, x, y) }
    [list] fn glUniform3f(loc: GLint, x: GLfloat, y: GLfloat, z: GLfloat) => |c| { c.gl.uniform_3f(loc, x, y, z) }
    [list] fn glUniform4f(loc: GLint, x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) => |c| {
        c.gl.uniform_4f(loc, x, y, z, w)
    }
    [list] fn glUniform1i(loc: GLint, x: GLint) => |c| { c.gl.uniform_1i(loc, x) }
    [list] fn glUniform2i(loc: GLint, x: GLint, y: GLint) => |c| { c.gl.uniform_2i(loc, x, y) }
    [list] fn glUniform3i(loc: GLint, x: GLint, y: GLint, z: GLint) => |c| { c.gl.uniform_3i(loc, x, y, z) }
    [list] fn glUniform4i(loc: GLint, x: GLint, y: GLint, z: GLint, w: GLint) => |c| {
        c.gl.uniform_4i(loc, x, y, z, w)
    }
    [list] fn glUniform1ui(loc: GLint, x: GLuint) => |c| { c.gl.uniform_1ui(loc, x) }
    [list] fn glUniform2ui(loc: GLint, x: GLuint, y: GLuint) => |c| { c.gl.uniform_2ui(loc, x, y) }
    [list] fn glUniform3ui(loc: GLint, x: GLuint, y: GLuint, z: GLuint) => |c| { c.gl.uniform_3ui(loc, x, y, z) }
    [list] fn glUniform4ui(loc: GLint, x: GLuint, y: GLuint, z: GLuint, w: GLuint) => |c| {
        c.gl.uniform_4ui(loc, x, y, z, w)
    }

    // ---- arrays ----
    fn glUniform1fv(loc: GLint, count: GLsizei, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 1, |g, n, a| g.uniform_1fv(loc, n, a)) }
    fn glUniform2fv(loc: GLint, count: GLsizei, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 2, |g, n, a| g.uniform_2fv(loc, n, a)) }
    fn glUniform3fv(loc: GLint, count: GLsizei, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 3, |g, n, a| g.uniform_3fv(loc, n, a)) }
    fn glUniform4fv(loc: GLint, count: GLsizei, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 4, |g, n, a| g.uniform_4fv(loc, n, a)) }
    fn glUniform1iv(loc: GLint, count: GLsizei, v: *const GLint) => |c| { uniform_array(&mut c.gl, count, v, 1, |g, n, a| g.uniform_1iv(loc, n, a)) }
    fn glUniform2iv(loc: GLint, count: GLsizei, v: *const GLint) => |c| { uniform_array(&mut c.gl, count, v, 2, |g, n, a| g.uniform_2iv(loc, n, a)) }
    fn glUniform3iv(loc: GLint, count: GLsizei, v: *const GLint) => |c| { uniform_array(&mut c.gl, count, v, 3, |g, n, a| g.uniform_3iv(loc, n, a)) }
    fn glUniform4iv(loc: GLint, count: GLsizei, v: *const GLint) => |c| { uniform_array(&mut c.gl, count, v, 4, |g, n, a| g.uniform_4iv(loc, n, a)) }
    fn glUniform1uiv(loc: GLint, count: GLsizei, v: *const GLuint) => |c| { uniform_array(&mut c.gl, count, v, 1, |g, n, a| g.uniform_1uiv(loc, n, a)) }
    fn glUniform2uiv(loc: GLint, count: GLsizei, v: *const GLuint) => |c| { uniform_array(&mut c.gl, count, v, 2, |g, n, a| g.uniform_2uiv(loc, n, a)) }
    fn glUniform3uiv(loc: GLint, count: GLsizei, v: *const GLuint) => |c| { uniform_array(&mut c.gl, count, v, 3, |g, n, a| g.uniform_3uiv(loc, n, a)) }
    fn glUniform4uiv(loc: GLint, count: GLsizei, v: *const GLuint) => |c| { uniform_array(&mut c.gl, count, v, 4, |g, n, a| g.uniform_4uiv(loc, n, a)) }

    // ---- matrices ----
    fn glUniformMatrix2fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 4, |g, n, a| g.uniform_matrix_2fv(loc, n, as_bool(transpose), a)) }
    fn glUniformMatrix3fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 9, |g, n, a| g.uniform_matrix_3fv(loc, n, as_bool(transpose), a)) }
    fn glUniformMatrix4fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 16, |g, n, a| g.uniform_matrix_4fv(loc, n, as_bool(transpose), a)) }
    fn glUniformMatrix2x3fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 6, |g, n, a| g.uniform_matrix_2x3fv(loc, n, as_bool(transpose), a)) }
    fn glUniformMatrix3x2fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 6, |g, n, a| g.uniform_matrix_3x2fv(loc, n, as_bool(transpose), a)) }
    fn glUniformMatrix2x4fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 8, |g, n, a| g.uniform_matrix_2x4fv(loc, n, as_bool(transpose), a)) }
    fn glUniformMatrix4x2fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 8, |g, n, a| g.uniform_matrix_4x2fv(loc, n, as_bool(transpose), a)) }
    fn glUniformMatrix3x4fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 12, |g, n, a| g.uniform_matrix_3x4fv(loc, n, as_bool(transpose), a)) }
    fn glUniformMatrix4x3fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 12, |g, n, a| g.uniform_matrix_4x3fv(loc, n, as_bool(transpose), a)) }

    // ---- a named program's uniforms (GL_ARB_separate_shader_objects,
    // GL 4.1's names; executed at once, not compiled into lists) ----
    fn glProgramUniform1f(program: GLuint, loc: GLint, x: GLfloat) => |c| { c.gl.program_uniform_1f(program, loc, x) }
    fn glProgramUniform1i(program: GLuint, loc: GLint, x: GLint) => |c| { c.gl.program_uniform_1i(program, loc, x) }
    fn glProgramUniform1ui(program: GLuint, loc: GLint, x: GLuint) => |c| { c.gl.program_uniform_1ui(program, loc, x) }
    fn glProgramUniform2f(program: GLuint, loc: GLint, x: GLfloat, y: GLfloat) => |c| { c.gl.program_uniform_2f(program, loc, x, y) }
    fn glProgramUniform2i(program: GLuint, loc: GLint, x: GLint, y: GLint) => |c| { c.gl.program_uniform_2i(program, loc, x, y) }
    fn glProgramUniform2ui(program: GLuint, loc: GLint, x: GLuint, y: GLuint) => |c| { c.gl.program_uniform_2ui(program, loc, x, y) }
    fn glProgramUniform3f(program: GLuint, loc: GLint, x: GLfloat, y: GLfloat, z: GLfloat) => |c| { c.gl.program_uniform_3f(program, loc, x, y, z) }
    fn glProgramUniform3i(program: GLuint, loc: GLint, x: GLint, y: GLint, z: GLint) => |c| { c.gl.program_uniform_3i(program, loc, x, y, z) }
    fn glProgramUniform3ui(program: GLuint, loc: GLint, x: GLuint, y: GLuint, z: GLuint) => |c| { c.gl.program_uniform_3ui(program, loc, x, y, z) }
    fn glProgramUniform4f(program: GLuint, loc: GLint, x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) => |c| { c.gl.program_uniform_4f(program, loc, x, y, z, w) }
    fn glProgramUniform4i(program: GLuint, loc: GLint, x: GLint, y: GLint, z: GLint, w: GLint) => |c| { c.gl.program_uniform_4i(program, loc, x, y, z, w) }
    fn glProgramUniform4ui(program: GLuint, loc: GLint, x: GLuint, y: GLuint, z: GLuint, w: GLuint) => |c| { c.gl.program_uniform_4ui(program, loc, x, y, z, w) }
    fn glProgramUniform1fv(program: GLuint, loc: GLint, count: GLsizei, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 1, |g, n, a| g.program_uniform_1fv(program, loc, n, a)) }
    fn glProgramUniform1iv(program: GLuint, loc: GLint, count: GLsizei, v: *const GLint) => |c| { uniform_array(&mut c.gl, count, v, 1, |g, n, a| g.program_uniform_1iv(program, loc, n, a)) }
    fn glProgramUniform1uiv(program: GLuint, loc: GLint, count: GLsizei, v: *const GLuint) => |c| { uniform_array(&mut c.gl, count, v, 1, |g, n, a| g.program_uniform_1uiv(program, loc, n, a)) }
    fn glProgramUniform2fv(program: GLuint, loc: GLint, count: GLsizei, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 2, |g, n, a| g.program_uniform_2fv(program, loc, n, a)) }
    fn glProgramUniform2iv(program: GLuint, loc: GLint, count: GLsizei, v: *const GLint) => |c| { uniform_array(&mut c.gl, count, v, 2, |g, n, a| g.program_uniform_2iv(program, loc, n, a)) }
    fn glProgramUniform2uiv(program: GLuint, loc: GLint, count: GLsizei, v: *const GLuint) => |c| { uniform_array(&mut c.gl, count, v, 2, |g, n, a| g.program_uniform_2uiv(program, loc, n, a)) }
    fn glProgramUniform3fv(program: GLuint, loc: GLint, count: GLsizei, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 3, |g, n, a| g.program_uniform_3fv(program, loc, n, a)) }
    fn glProgramUniform3iv(program: GLuint, loc: GLint, count: GLsizei, v: *const GLint) => |c| { uniform_array(&mut c.gl, count, v, 3, |g, n, a| g.program_uniform_3iv(program, loc, n, a)) }
    fn glProgramUniform3uiv(program: GLuint, loc: GLint, count: GLsizei, v: *const GLuint) => |c| { uniform_array(&mut c.gl, count, v, 3, |g, n, a| g.program_uniform_3uiv(program, loc, n, a)) }
    fn glProgramUniform4fv(program: GLuint, loc: GLint, count: GLsizei, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 4, |g, n, a| g.program_uniform_4fv(program, loc, n, a)) }
    fn glProgramUniform4iv(program: GLuint, loc: GLint, count: GLsizei, v: *const GLint) => |c| { uniform_array(&mut c.gl, count, v, 4, |g, n, a| g.program_uniform_4iv(program, loc, n, a)) }
    fn glProgramUniform4uiv(program: GLuint, loc: GLint, count: GLsizei, v: *const GLuint) => |c| { uniform_array(&mut c.gl, count, v, 4, |g, n, a| g.program_uniform_4uiv(program, loc, n, a)) }
    fn glProgramUniformMatrix2fv(program: GLuint, loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 4, |g, n, a| g.program_uniform_matrix_2fv(program, loc, n, as_bool(transpose), a)) }
    fn glProgramUniformMatrix3fv(program: GLuint, loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 9, |g, n, a| g.program_uniform_matrix_3fv(program, loc, n, as_bool(transpose), a)) }
    fn glProgramUniformMatrix4fv(program: GLuint, loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 16, |g, n, a| g.program_uniform_matrix_4fv(program, loc, n, as_bool(transpose), a)) }
    fn glProgramUniformMatrix2x3fv(program: GLuint, loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 6, |g, n, a| g.program_uniform_matrix_2x3fv(program, loc, n, as_bool(transpose), a)) }
    fn glProgramUniformMatrix3x2fv(program: GLuint, loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 6, |g, n, a| g.program_uniform_matrix_3x2fv(program, loc, n, as_bool(transpose), a)) }
    fn glProgramUniformMatrix2x4fv(program: GLuint, loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 8, |g, n, a| g.program_uniform_matrix_2x4fv(program, loc, n, as_bool(transpose), a)) }
    fn glProgramUniformMatrix4x2fv(program: GLuint, loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 8, |g, n, a| g.program_uniform_matrix_4x2fv(program, loc, n, as_bool(transpose), a)) }
    fn glProgramUniformMatrix3x4fv(program: GLuint, loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 12, |g, n, a| g.program_uniform_matrix_3x4fv(program, loc, n, as_bool(transpose), a)) }
    fn glProgramUniformMatrix4x3fv(program: GLuint, loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| { uniform_array(&mut c.gl, count, v, 12, |g, n, a| g.program_uniform_matrix_4x3fv(program, loc, n, as_bool(transpose), a)) }

    // ---- queries ----
    fn glGetUniformfv(program: GLuint, loc: GLint, v: *mut GLfloat) => |c| {
        let r = c.gl.get_uniformfv(program, loc);
        wr(v, &r);
    }
    fn glGetUniformiv(program: GLuint, loc: GLint, v: *mut GLint) => |c| {
        let r = c.gl.get_uniformiv(program, loc);
        wr(v, &r);
    }
    fn glGetUniformuiv(program: GLuint, loc: GLint, v: *mut GLuint) => |c| {
        let r = c.gl.get_uniformuiv(program, loc);
        wr(v, &r);
    }
}
