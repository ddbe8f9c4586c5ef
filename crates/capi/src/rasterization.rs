//! Rasterization and per-fragment state (GL 2.1 §3.3–§3.5, §4.1): point
//! size and parameters, line width, culling, polygon mode and offset, and
//! the scissor, alpha, stencil, depth, blending and logic-op tests and
//! functions.

use crate::abi::*;
use crate::context::{record_call, with_ctx};
use gl::enums::*;
use gl::Param;

gl_entry_points! {
    // ---- multisampling (GL 3.2) ----
    fn glSampleMaski(index: GLuint, mask: GLbitfield) => |c| { c.gl.sample_maski(index, mask) }
    fn glGetMultisamplefv(pname: GLenum, index: GLuint, val: *mut GLfloat) => |c| {
        if let Some(v) = c.gl.get_multisamplefv(pname, index) { wr(val, &v) }
    }
    // ---- points, lines, polygons ----
    [list] fn glPointSize(size: GLfloat) => |c| { c.gl.point_size(size) }
    [list] fn glPointParameterf(pname: GLenum, v: GLfloat) => |c| { c.gl.point_parameter(pname, Param::F(v)) }
    [list] fn glPointParameteri(pname: GLenum, v: GLint) => |c| { c.gl.point_parameter(pname, Param::I(v)) }
    fn glPointParameterfv(pname: GLenum, v: *const GLfloat) => |c| {
        let n = if pname == GL_POINT_DISTANCE_ATTENUATION { 3 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glPointParameterfv(pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.point_parameter(pname, Param::Fv(&rd_vec(v, n))) }
    }
    fn glPointParameteriv(pname: GLenum, v: *const GLint) => |c| {
        let n = if pname == GL_POINT_DISTANCE_ATTENUATION { 3 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glPointParameteriv(pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.point_parameter(pname, Param::Iv(&rd_vec(v, n))) }
    }
    [list] fn glLineWidth(width: GLfloat) => |c| { c.gl.line_width(width) }
    [list] fn glCullFace(mode: GLenum) => |c| { c.gl.cull_face(mode) }
    [list] fn glFrontFace(mode: GLenum) => |c| { c.gl.front_face(mode) }
    [list] fn glPolygonMode(face: GLenum, mode: GLenum) => |c| { c.gl.polygon_mode(face, mode) }
    [list] fn glPolygonOffset(factor: GLfloat, units: GLfloat) => |c| { c.gl.polygon_offset(factor, units) }

    // ---- per-fragment operations ----
    [list] fn glScissor(x: GLint, y: GLint, w: GLsizei, h: GLsizei) => |c| { c.gl.scissor(x, y, w, h) }
    [list] fn glAlphaFunc(func: GLenum, reference: GLclampf) => |c| { c.gl.alpha_func(func, reference) }
    [list] fn glStencilFunc(func: GLenum, reference: GLint, mask: GLuint) => |c| {
        c.gl.stencil_func(func, reference, mask)
    }
    [list] fn glStencilFuncSeparate(face: GLenum, func: GLenum, reference: GLint, mask: GLuint) => |c| {
        c.gl.stencil_func_separate(face, func, reference, mask)
    }
    [list] fn glStencilOp(fail: GLenum, zfail: GLenum, zpass: GLenum) => |c| { c.gl.stencil_op(fail, zfail, zpass) }
    [list] fn glStencilOpSeparate(face: GLenum, fail: GLenum, zfail: GLenum, zpass: GLenum) => |c| {
        c.gl.stencil_op_separate(face, fail, zfail, zpass)
    }
    [list] fn glDepthFunc(func: GLenum) => |c| { c.gl.depth_func(func) }
    [list] fn glBlendFunc(src: GLenum, dst: GLenum) => |c| { c.gl.blend_func(src, dst) }
    [list] fn glBlendFuncSeparate(sr: GLenum, dr: GLenum, sa: GLenum, da: GLenum) => |c| {
        c.gl.blend_func_separate(sr, dr, sa, da)
    }
    [list] fn glBlendEquation(mode: GLenum) => |c| { c.gl.blend_equation(mode) }
    [list] fn glBlendEquationSeparate(rgb: GLenum, alpha: GLenum) => |c| {
        c.gl.blend_equation_separate(rgb, alpha)
    }
    [list] fn glBlendColor(r: GLclampf, g: GLclampf, bl: GLclampf, a: GLclampf) => |c| {
        c.gl.blend_color(r, g, bl, a)
    }
    [list] fn glLogicOp(op: GLenum) => |c| { c.gl.logic_op(op) }
}
