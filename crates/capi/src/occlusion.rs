//! Query-object entry points (GL 3.3 §2.14, §2.15, §5.1, §6.1.12) over
//! [`gl::occlusion`]: occlusion, primitive and timer queries and
//! conditional rendering. glBeginQuery/glEndQuery, glQueryCounter and the
//! conditional-render calls are compiled into display lists; the object
//! calls and queries execute immediately (§5.4).

use crate::abi::*;
use crate::context::{record_call, with_ctx};
use gl::enums::*;

gl_entry_points! {
    fn glGenQueries(n: GLsizei, ids: *mut GLuint) => |c| {
        let v = c.gl.gen_queries(n);
        wr(ids, &v);
    }
    fn glDeleteQueries(n: GLsizei, ids: *const GLuint) => |c| {
        if n < 0 {
            if !c.gl.reject_in_begin() {
                c.gl.record_error(GL_INVALID_VALUE);
            }
            return;
        }
        c.gl.delete_queries(&rd_vec(ids, n as i64));
    }
    fn glIsQuery(id: GLuint) -> GLboolean [0] => |c| { c.gl.is_query(id) as GLboolean }
    [list] fn glBeginQuery(target: GLenum, id: GLuint) => |c| { c.gl.begin_query(target, id) }
    [list] fn glEndQuery(target: GLenum) => |c| { c.gl.end_query(target) }
    fn glGetQueryiv(target: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        if let Some(x) = c.gl.get_queryiv(target, pname) {
            wr(v, &[x]);
        }
    }
    fn glGetQueryObjectiv(id: GLuint, pname: GLenum, v: *mut GLint) => |c| {
        if let Some(x) = c.gl.get_query_object(id, pname) {
            wr(v, &[x.min(i32::MAX as u64) as i32]);
        }
    }
    fn glGetQueryObjectuiv(id: GLuint, pname: GLenum, v: *mut GLuint) => |c| {
        if let Some(x) = c.gl.get_query_object(id, pname) {
            wr(v, &[x.min(u32::MAX as u64) as u32]);
        }
    }
    fn glGetQueryObjecti64v(id: GLuint, pname: GLenum, v: *mut GLint64) => |c| {
        if let Some(x) = c.gl.get_query_object(id, pname) {
            wr(v, &[x.min(i64::MAX as u64) as i64]);
        }
    }
    fn glGetQueryObjectui64v(id: GLuint, pname: GLenum, v: *mut GLuint64) => |c| {
        if let Some(x) = c.gl.get_query_object(id, pname) {
            wr(v, &[x]);
        }
    }
    [list] fn glQueryCounter(id: GLuint, target: GLenum) => |c| { c.gl.query_counter(id, target) }
    [list] fn glBeginConditionalRender(id: GLuint, mode: GLenum) => |c| {
        c.gl.begin_conditional_render(id, mode)
    }
    [list] fn glEndConditionalRender() => |c| { c.gl.end_conditional_render() }
}
