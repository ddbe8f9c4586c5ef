//! Framebuffer and renderbuffer objects (GL 3.0 §4.4 /
//! ARB_framebuffer_object, and the EXT_framebuffer_object names, which
//! differ in the errors for names not from glGen*).

use crate::abi::*;
use crate::context::with_ctx;
use gl::enums::*;

gl_entry_points! {
    // ---- framebuffers ----
    fn glGenFramebuffers(n: GLsizei, names: *mut GLuint) => |c| {
        let v = c.gl.gen_framebuffers(n);
        wr(names, &v);
    }
    fn glGenFramebuffersEXT(n: GLsizei, names: *mut GLuint) => |c| {
        let v = c.gl.gen_framebuffers(n);
        wr(names, &v);
    }
    fn glBindFramebuffer(target: GLenum, fb: GLuint) => |c| { c.gl.bind_framebuffer(target, fb) }
    fn glBindFramebufferEXT(target: GLenum, fb: GLuint) => |c| { c.gl.bind_framebuffer(target, fb) }
    fn glDeleteFramebuffers(n: GLsizei, names: *const GLuint) => |c| {
        if n < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        c.gl.delete_framebuffers(&rd_vec(names, n as i64));
    }
    fn glDeleteFramebuffersEXT(n: GLsizei, names: *const GLuint) => |c| {
        if n < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        c.gl.delete_framebuffers(&rd_vec(names, n as i64));
    }
    fn glIsFramebuffer(name: GLuint) -> GLboolean [0] => |c| { c.gl.is_framebuffer(name) as GLboolean }
    fn glCheckFramebufferStatus(target: GLenum) -> GLenum [0] => |c| {
        c.gl.check_framebuffer_status(target)
    }
    fn glCheckFramebufferStatusEXT(target: GLenum) -> GLenum [0] => |c| {
        c.gl.check_framebuffer_status(target)
    }
    fn glFramebufferTexture2D(
        target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint
    ) => |c| { c.gl.framebuffer_texture_2d(target, attachment, textarget, texture, level) }
    fn glFramebufferTexture2DEXT(
        target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint
    ) => |c| { c.gl.framebuffer_texture_2d(target, attachment, textarget, texture, level) }
    fn glFramebufferRenderbuffer(
        target: GLenum, attachment: GLenum, rbtarget: GLenum, rb: GLuint
    ) => |c| { c.gl.framebuffer_renderbuffer(target, attachment, rbtarget, rb) }
    fn glFramebufferRenderbufferEXT(
        target: GLenum, attachment: GLenum, rbtarget: GLenum, rb: GLuint
    ) => |c| { c.gl.framebuffer_renderbuffer(target, attachment, rbtarget, rb) }
    fn glGetFramebufferAttachmentParameteriv(
        target: GLenum, attachment: GLenum, pname: GLenum, params: *mut GLint
    ) => |c| {
        if let Some(v) = c.gl.get_framebuffer_attachment_parameter(target, attachment, pname) {
            wr(params, &[v]);
        }
    }
    fn glGetFramebufferAttachmentParameterivEXT(
        target: GLenum, attachment: GLenum, pname: GLenum, params: *mut GLint
    ) => |c| {
        if let Some(v) = c.gl.get_framebuffer_attachment_parameter(target, attachment, pname) {
            wr(params, &[v]);
        }
    }

    // ---- renderbuffers ----
    fn glGenRenderbuffers(n: GLsizei, names: *mut GLuint) => |c| {
        let v = c.gl.gen_renderbuffers(n);
        wr(names, &v);
    }
    fn glGenRenderbuffersEXT(n: GLsizei, names: *mut GLuint) => |c| {
        let v = c.gl.gen_renderbuffers(n);
        wr(names, &v);
    }
    fn glBindRenderbuffer(target: GLenum, rb: GLuint) => |c| { c.gl.bind_renderbuffer(target, rb) }
    fn glBindRenderbufferEXT(target: GLenum, rb: GLuint) => |c| { c.gl.bind_renderbuffer(target, rb) }
    fn glDeleteRenderbuffers(n: GLsizei, names: *const GLuint) => |c| {
        if n < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        c.gl.delete_renderbuffers(&rd_vec(names, n as i64));
    }
    fn glDeleteRenderbuffersEXT(n: GLsizei, names: *const GLuint) => |c| {
        if n < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        c.gl.delete_renderbuffers(&rd_vec(names, n as i64));
    }
    fn glRenderbufferStorage(target: GLenum, internal: GLenum, w: GLsizei, h: GLsizei) => |c| {
        c.gl.renderbuffer_storage(target, internal, w, h)
    }
    fn glRenderbufferStorageEXT(target: GLenum, internal: GLenum, w: GLsizei, h: GLsizei) => |c| {
        c.gl.renderbuffer_storage(target, internal, w, h)
    }

    fn glFramebufferTexture1D(
        target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint
    ) => |c| { c.gl.framebuffer_texture_1d(target, attachment, textarget, texture, level) }
    fn glFramebufferTexture1DEXT(
        target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint
    ) => |c| { c.gl.framebuffer_texture_1d(target, attachment, textarget, texture, level) }
    fn glFramebufferTexture3D(
        target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint,
        layer: GLint
    ) => |c| { c.gl.framebuffer_texture_3d(target, attachment, textarget, texture, level, layer) }
    fn glFramebufferTexture3DEXT(
        target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint,
        layer: GLint
    ) => |c| { c.gl.framebuffer_texture_3d(target, attachment, textarget, texture, level, layer) }
    fn glFramebufferTextureLayer(
        target: GLenum, attachment: GLenum, texture: GLuint, level: GLint, layer: GLint
    ) => |c| { c.gl.framebuffer_texture_layer(target, attachment, texture, level, layer) }
    fn glFramebufferTexture(
        target: GLenum, attachment: GLenum, texture: GLuint, level: GLint
    ) => |c| { c.gl.framebuffer_texture(target, attachment, texture, level) }
    // GL_ARB_geometry_shader4 / GL_EXT_geometry_shader4.
    fn glFramebufferTextureARB(
        target: GLenum, attachment: GLenum, texture: GLuint, level: GLint
    ) => |c| { c.gl.framebuffer_texture(target, attachment, texture, level) }
    fn glFramebufferTextureEXT(
        target: GLenum, attachment: GLenum, texture: GLuint, level: GLint
    ) => |c| { c.gl.framebuffer_texture(target, attachment, texture, level) }
    fn glFramebufferTextureLayerARB(
        target: GLenum, attachment: GLenum, texture: GLuint, level: GLint, layer: GLint
    ) => |c| { c.gl.framebuffer_texture_layer(target, attachment, texture, level, layer) }
    fn glFramebufferTextureLayerEXT(
        target: GLenum, attachment: GLenum, texture: GLuint, level: GLint, layer: GLint
    ) => |c| { c.gl.framebuffer_texture_layer(target, attachment, texture, level, layer) }
    fn glFramebufferTextureFaceARB(
        target: GLenum, attachment: GLenum, texture: GLuint, level: GLint, face: GLenum
    ) => |c| { c.gl.framebuffer_texture_face(target, attachment, texture, level, face) }
    fn glFramebufferTextureFaceEXT(
        target: GLenum, attachment: GLenum, texture: GLuint, level: GLint, face: GLenum
    ) => |c| { c.gl.framebuffer_texture_face(target, attachment, texture, level, face) }
    fn glIsRenderbuffer(name: GLuint) -> GLboolean [0] => |c| { c.gl.is_renderbuffer(name) as GLboolean }
    fn glIsRenderbufferEXT(name: GLuint) -> GLboolean [0] => |c| { c.gl.is_renderbuffer(name) as GLboolean }
    fn glGetRenderbufferParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) => |c| {
        if let Some(v) = c.gl.get_renderbuffer_parameteriv(target, pname) { wr(params, &[v]); }
    }
    fn glGetRenderbufferParameterivEXT(target: GLenum, pname: GLenum, params: *mut GLint) => |c| {
        if let Some(v) = c.gl.get_renderbuffer_parameteriv(target, pname) { wr(params, &[v]); }
    }
    fn glRenderbufferStorageMultisample(
        target: GLenum, samples: GLsizei, internal: GLenum, w: GLsizei, h: GLsizei
    ) => |c| { c.gl.renderbuffer_storage_multisample(target, samples, internal, w, h) }
    fn glRenderbufferStorageMultisampleEXT(
        target: GLenum, samples: GLsizei, internal: GLenum, w: GLsizei, h: GLsizei
    ) => |c| { c.gl.renderbuffer_storage_multisample(target, samples, internal, w, h) }
    fn glBlitFramebuffer(
        sx0: GLint, sy0: GLint, sx1: GLint, sy1: GLint,
        dx0: GLint, dy0: GLint, dx1: GLint, dy1: GLint, mask: GLbitfield, filter: GLenum
    ) => |c| { c.gl.blit_framebuffer([sx0, sy0, sx1, sy1], [dx0, dy0, dx1, dy1], mask, filter) }
    fn glBlitFramebufferEXT(
        sx0: GLint, sy0: GLint, sx1: GLint, sy1: GLint,
        dx0: GLint, dy0: GLint, dx1: GLint, dy1: GLint, mask: GLbitfield, filter: GLenum
    ) => |c| { c.gl.blit_framebuffer([sx0, sy0, sx1, sy1], [dx0, dy0, dx1, dy1], mask, filter) }
}
