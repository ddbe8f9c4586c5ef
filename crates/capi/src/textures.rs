//! Texture objects, images and parameters (GL 2.1 §3.8, §6.1.3–§6.1.4):
//! names and bindings, the active unit, glTexImage{1,2,3}D and
//! glTexSubImage2D (images from client memory or the pixel unpack buffer,
//! `buffers::image_bytes`), parameters and their queries, and
//! mipmap generation, buffer textures (glTexBuffer). Reading images back and the other sub-image and
//! copy commands are [`crate::pixels`].

use crate::abi::*;
use crate::buffers::image_bytes;
use crate::context::{record_call, with_ctx};
use gl::enums::*;
use gl::Param;
use std::ffi::c_void;

/// How many values a glTexParameter*v call reads for `pname`.
fn tex_parameter_count(pname: GLenum) -> i64 {
    if matches!(pname, GL_TEXTURE_BORDER_COLOR | GL_TEXTURE_SWIZZLE_RGBA) {
        4
    } else {
        1
    }
}

/// A float sampler parameter as glGetSamplerParameteriv returns it: the
/// border colour's components map [-1, 1] onto the integer range (GL 3.3
/// §6.1.2), the LODs round to the nearest integer, enums are exact.
fn sampler_value_as_int(pname: GLenum, x: f32) -> GLint {
    if pname == GL_TEXTURE_BORDER_COLOR {
        let c = x.clamp(-1.0, 1.0) as f64;
        ((c * 4294967295.0 - 1.0) / 2.0).round() as i64 as GLint
    } else {
        x.round() as GLint
    }
}

gl_entry_points! {
    // ---- sampler objects (GL 3.3 §3.8.2) ----
    fn glGenSamplers(n: GLsizei, names: *mut GLuint) => |c| {
        let v = c.gl.gen_samplers(n);
        wr(names, &v);
    }
    fn glDeleteSamplers(n: GLsizei, names: *const GLuint) => |c| {
        if n < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        c.gl.delete_samplers(&rd_vec(names, n as i64));
    }
    fn glIsSampler(name: GLuint) -> GLboolean [0] => |c| { c.gl.is_sampler(name) as GLboolean }
    fn glBindSampler(unit: GLuint, sampler: GLuint) => |c| { c.gl.bind_sampler(unit, sampler) }
    fn glSamplerParameteri(s: GLuint, pname: GLenum, v: GLint) => |c| { c.gl.sampler_parameter(s, pname, Param::I(v)) }
    fn glSamplerParameterf(s: GLuint, pname: GLenum, v: GLfloat) => |c| { c.gl.sampler_parameter(s, pname, Param::F(v)) }
    fn glSamplerParameteriv(s: GLuint, pname: GLenum, v: *const GLint) => |c| {
        let n = gl::samplers::sampler_parameter_count(pname).max(1) as i64;
        if !v.is_null() { c.gl.sampler_parameter(s, pname, Param::Iv(&rd_vec(v, n))) }
    }
    fn glSamplerParameterfv(s: GLuint, pname: GLenum, v: *const GLfloat) => |c| {
        let n = gl::samplers::sampler_parameter_count(pname).max(1) as i64;
        if !v.is_null() { c.gl.sampler_parameter(s, pname, Param::Fv(&rd_vec(v, n))) }
    }
    // The integer forms take the border colour's values as they are (not
    // normalized), the other parameters as glSamplerParameteriv.
    fn glSamplerParameterIiv(s: GLuint, pname: GLenum, v: *const GLint) => |c| {
        if v.is_null() { return; }
        let vals = rd_vec(v, gl::samplers::sampler_parameter_count(pname).max(1) as i64);
        if pname == GL_TEXTURE_BORDER_COLOR {
            let f: Vec<f32> = vals.iter().map(|&x| x as f32).collect();
            c.gl.sampler_parameter(s, pname, Param::Fv(&f));
        } else {
            c.gl.sampler_parameter(s, pname, Param::Iv(&vals));
        }
    }
    fn glSamplerParameterIuiv(s: GLuint, pname: GLenum, v: *const GLuint) => |c| {
        if v.is_null() { return; }
        let vals = rd_vec(v, gl::samplers::sampler_parameter_count(pname).max(1) as i64);
        if pname == GL_TEXTURE_BORDER_COLOR {
            let f: Vec<f32> = vals.iter().map(|&x| x as f32).collect();
            c.gl.sampler_parameter(s, pname, Param::Fv(&f));
        } else {
            let i: Vec<i32> = vals.iter().map(|&x| x as i32).collect();
            c.gl.sampler_parameter(s, pname, Param::Iv(&i));
        }
    }
    fn glGetSamplerParameteriv(s: GLuint, pname: GLenum, v: *mut GLint) => |c| {
        let r: Vec<GLint> = c.gl.get_sampler_parameter(s, pname).iter().map(|&x| sampler_value_as_int(pname, x)).collect();
        wr(v, &r);
    }
    fn glGetSamplerParameterfv(s: GLuint, pname: GLenum, v: *mut GLfloat) => |c| {
        wr(v, &c.gl.get_sampler_parameter(s, pname));
    }
    fn glGetSamplerParameterIiv(s: GLuint, pname: GLenum, v: *mut GLint) => |c| {
        let r: Vec<GLint> = c.gl.get_sampler_parameter(s, pname).iter().map(|&x| x.round() as GLint).collect();
        wr(v, &r);
    }
    fn glGetSamplerParameterIuiv(s: GLuint, pname: GLenum, v: *mut GLuint) => |c| {
        let r: Vec<GLuint> = c.gl.get_sampler_parameter(s, pname).iter().map(|&x| x.round() as i64 as GLuint).collect();
        wr(v, &r);
    }

    fn glTexImage2DMultisample(
        target: GLenum, samples: GLsizei, internal: GLenum, w: GLsizei, h: GLsizei, fixed: GLboolean
    ) => |c| { c.gl.tex_image_multisample(target, samples, internal, [w, h], as_bool(fixed)) }
    fn glTexImage3DMultisample(
        target: GLenum, samples: GLsizei, internal: GLenum, w: GLsizei, h: GLsizei, d: GLsizei,
        fixed: GLboolean
    ) => |c| { c.gl.tex_image_multisample(target, samples, internal, [w, h, d], as_bool(fixed)) }
    // ---- objects ----
    fn glGenTextures(n: GLsizei, names: *mut GLuint) => |c| {
        let v = c.gl.gen_textures(n);
        wr(names, &v);
    }
    fn glDeleteTextures(n: GLsizei, names: *const GLuint) => |c| {
        if n < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        c.gl.delete_textures(&rd_vec(names, n as i64));
    }
    fn glIsTexture(name: GLuint) -> GLboolean [0] => |c| { c.gl.is_texture(name) as GLboolean }
    [list] fn glBindTexture(target: GLenum, name: GLuint) => |c| { c.gl.bind_texture(target, name) }
    [list] fn glActiveTexture(unit: GLenum) => |c| { c.gl.active_texture(unit) }

    // ---- parameters ----
    [list] fn glTexParameteri(target: GLenum, pname: GLenum, v: GLint) => |c| { c.gl.tex_parameter(target, pname, Param::I(v)) }
    [list] fn glTexParameterf(target: GLenum, pname: GLenum, v: GLfloat) => |c| { c.gl.tex_parameter(target, pname, Param::F(v)) }
    fn glTexParameterfv(target: GLenum, pname: GLenum, v: *const GLfloat) => |c| {
        let n = tex_parameter_count(pname);
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glTexParameterfv(target, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.tex_parameter(target, pname, Param::Fv(&rd_vec(v, n))) }
    }
    fn glTexParameteriv(target: GLenum, pname: GLenum, v: *const GLint) => |c| {
        let n = tex_parameter_count(pname);
        if !v.is_null() { c.gl.tex_parameter(target, pname, Param::Iv(&rd_vec(v, n))) }
    }
    // GL 3.0's integer forms: the border colour's values are taken as
    // they are (not normalized), the other parameters as glTexParameteriv.
    fn glTexParameterIiv(target: GLenum, pname: GLenum, v: *const GLint) => |c| {
        if v.is_null() { return; }
        let vals = rd_vec(v, tex_parameter_count(pname));
        if pname == GL_TEXTURE_BORDER_COLOR {
            let f: Vec<f32> = vals.iter().map(|&x| x as f32).collect();
            c.gl.tex_parameter(target, pname, Param::Fv(&f));
        } else {
            c.gl.tex_parameter(target, pname, Param::Iv(&vals));
        }
    }
    fn glTexParameterIuiv(target: GLenum, pname: GLenum, v: *const GLuint) => |c| {
        if v.is_null() { return; }
        let vals = rd_vec(v, tex_parameter_count(pname));
        if pname == GL_TEXTURE_BORDER_COLOR {
            let f: Vec<f32> = vals.iter().map(|&x| x as f32).collect();
            c.gl.tex_parameter(target, pname, Param::Fv(&f));
        } else {
            let i: Vec<i32> = vals.iter().map(|&x| x as i32).collect();
            c.gl.tex_parameter(target, pname, Param::Iv(&i));
        }
    }
    fn glGetTexParameterIiv(target: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        let r: Vec<GLint> = if tex_parameter_count(pname) == 4 {
            c.gl.get_tex_parameterfv(target, pname).iter().map(|&x| x as GLint).collect()
        } else {
            vec![c.gl.get_tex_parameteriv(target, pname)]
        };
        wr(v, &r);
    }
    fn glGetTexParameterIuiv(target: GLenum, pname: GLenum, v: *mut GLuint) => |c| {
        let r: Vec<GLuint> = if tex_parameter_count(pname) == 4 {
            c.gl.get_tex_parameterfv(target, pname).iter().map(|&x| x as GLuint).collect()
        } else {
            vec![c.gl.get_tex_parameteriv(target, pname) as GLuint]
        };
        wr(v, &r);
    }
    fn glGetTexParameteriv(target: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        if pname == GL_TEXTURE_SWIZZLE_RGBA {
            // The one four-valued integer parameter.
            let r: Vec<GLint> = c.gl.get_tex_parameterfv(target, pname).iter().map(|&x| x as GLint).collect();
            wr(v, &r);
            return;
        }
        let r = c.gl.get_tex_parameteriv(target, pname);
        wr(v, &[r]);
    }
    fn glGetTexParameterfv(target: GLenum, pname: GLenum, v: *mut GLfloat) => |c| {
        let r = c.gl.get_tex_parameterfv(target, pname);
        wr(v, &r);
    }
    fn glGetTexLevelParameteriv(target: GLenum, level: GLint, pname: GLenum, v: *mut GLint) => |c| {
        let r = c.gl.get_tex_level_parameteriv(target, level, pname);
        wr(v, &[r]);
    }
    fn glGetTexLevelParameterfv(target: GLenum, level: GLint, pname: GLenum, v: *mut GLfloat) => |c| {
        let before = c.gl.get_error();
        let r = c.gl.get_tex_level_parameteriv(target, level, pname);
        let e = c.gl.get_error();
        c.gl.record_error(if before != GL_NO_ERROR { before } else { e });
        if e == GL_NO_ERROR {
            wr(v, &[r as f32]);
        }
    }

    // ---- images ----
    fn glTexImage1D(
        target: GLenum, level: GLint, internal: GLint, w: GLsizei, border: GLint,
        format: GLenum, ty: GLenum, data: *const c_void
    ) => |c| {
        let Ok(bytes) = image_bytes(c, w, 1, 1, false, format, ty, data) else { return };
        c.gl.tex_image(target, level, internal, [w], border, format, ty, bytes.as_deref());
    }
    fn glTexImage2D(
        target: GLenum, level: GLint, internal: GLint, w: GLsizei, h: GLsizei, border: GLint,
        format: GLenum, ty: GLenum, data: *const c_void
    ) => |c| {
        let Ok(bytes) = image_bytes(c, w, h, 1, false, format, ty, data) else { return };
        c.gl.tex_image(target, level, internal, [w, h], border, format, ty, bytes.as_deref());
    }
    fn glTexImage3D(
        target: GLenum, level: GLint, internal: GLint, w: GLsizei, h: GLsizei, d: GLsizei,
        border: GLint, format: GLenum, ty: GLenum, data: *const c_void
    ) => |c| {
        let Ok(bytes) = image_bytes(c, w, h, d, true, format, ty, data) else { return };
        c.gl.tex_image(target, level, internal, [w, h, d], border, format, ty, bytes.as_deref());
    }
    fn glTexSubImage2D(
        target: GLenum, level: GLint, xoff: GLint, yoff: GLint, w: GLsizei, h: GLsizei,
        format: GLenum, ty: GLenum, data: *const c_void
    ) => |c| {
        let Ok(bytes) = image_bytes(c, w, h, 1, false, format, ty, data) else { return };
        let bytes = bytes.unwrap_or_default();
        c.gl.tex_sub_image(target, level, [xoff, yoff], [w, h], format, ty, &bytes);
    }
    fn glGenerateMipmap(target: GLenum) => |c| { c.gl.generate_mipmap(target) }
    // ---- buffer textures (GL 3.1, ARB/EXT_texture_buffer_object) ----
    fn glTexBuffer(target: GLenum, internal: GLenum, buffer: GLuint) => |c| { c.gl.tex_buffer(target, internal, buffer) }
    fn glTexBufferARB(target: GLenum, internal: GLenum, buffer: GLuint) => |c| { c.gl.tex_buffer(target, internal, buffer) }
    fn glTexBufferEXT(target: GLenum, internal: GLenum, buffer: GLuint) => |c| { c.gl.tex_buffer(target, internal, buffer) }
    fn glGenerateMipmapEXT(target: GLenum) => |c| { c.gl.generate_mipmap(target) }
}
