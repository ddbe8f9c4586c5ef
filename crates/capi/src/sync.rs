//! Sync-object entry points (GL 3.3 §5.3, §6.1.8) over [`gl::sync`]: a
//! `GLsync` is the context's handle as a pointer value. Sync calls are not
//! compiled into display lists (GL 3.3 compatibility appendix, §5.4).

use crate::abi::*;
use crate::context::with_ctx;

gl_entry_points! {
    fn glFenceSync(condition: GLenum, flags: GLbitfield) -> GLsync [std::ptr::null()] => |c| {
        c.gl.fence_sync(condition, flags) as usize as GLsync
    }
    fn glIsSync(sync: GLsync) -> GLboolean [0] => |c| { c.gl.is_sync(sync as usize as u64) as GLboolean }
    fn glDeleteSync(sync: GLsync) => |c| { c.gl.delete_sync(sync as usize as u64) }
    fn glClientWaitSync(sync: GLsync, flags: GLbitfield, timeout: GLuint64) -> GLenum [gl::enums::GL_WAIT_FAILED] => |c| {
        c.gl.client_wait_sync(sync as usize as u64, flags, timeout)
    }
    fn glWaitSync(sync: GLsync, flags: GLbitfield, timeout: GLuint64) => |c| {
        c.gl.wait_sync(sync as usize as u64, flags, timeout)
    }
    fn glGetSynciv(sync: GLsync, pname: GLenum, buf_size: GLsizei, length: *mut GLsizei, values: *mut GLint) => |c| {
        if let Some(v) = c.gl.get_synciv(sync as usize as u64, pname) {
            // bufSize bounds what is written (GL 3.3 §6.1.8); a negative
            // one is GL_INVALID_VALUE, as Mesa and GL 4.5 say.
            if buf_size < 0 {
                c.gl.record_error(gl::enums::GL_INVALID_VALUE);
                return;
            }
            let n = (buf_size as usize).min(1);
            wr(values, &[v][..n]);
            wr(length, &[n as GLsizei]);
        }
    }
}
