//! Enabling and disabling capabilities, hints, the error flag and the
//! general state queries (GL 2.1 §2.5, §5.6, §6.1): glEnable / glDisable /
//! glIsEnabled, glHint, glGetError, glGetString and glGet{Integer,
//! Integer64, Float, Double, Boolean}v. The queries answer for the state this layer keeps
//! ([`crate::layer_state::Legacy::get`]) before asking the context.

use crate::abi::*;
use crate::context::{record_call, with_ctx};
use gl::enums::*;
use std::ffi::CString;

gl_entry_points! {
    // Not among the commands GL 2.1 §2.6.3 allows between glBegin and
    // glEnd: there it records GL_INVALID_OPERATION and returns no error
    // (the flag is read after glEnd), as Mesa does.
    fn glGetError() -> GLenum [GL_NO_ERROR] => |c| {
        if c.gl.reject_in_begin() {
            return GL_NO_ERROR;
        }
        c.gl.get_error()
    }
    fn glGetString(name: GLenum) -> *const GLubyte [std::ptr::null()] => |c| {
        if !c.strings.contains_key(&name) {
            let s = c.gl.get_string(name);
            let s = match name {
                // A core context has no GL_EXTENSIONS string (the context
                // recorded GL_INVALID_ENUM).
                GL_EXTENSIONS if c.gl.is_core() => return std::ptr::null(),
                GL_VENDOR | GL_SHADING_LANGUAGE_VERSION | GL_EXTENSIONS => s,
                GL_RENDERER => "shaderbox (CPU)".to_string(),
                GL_VERSION => format!("{s} {}", env!("CARGO_PKG_VERSION")),
                _ => return std::ptr::null(),
            };
            let Ok(cs) = CString::new(s) else { return std::ptr::null() };
            c.strings.insert(name, cs);
        }
        c.strings.get(&name).map_or(std::ptr::null(), |s| s.as_ptr() as *const GLubyte)
    }
    fn glGetStringi(name: GLenum, index: GLuint) -> *const GLubyte [std::ptr::null()] => |c| {
        let Some(ext) = c.gl.get_stringi(name, index) else { return std::ptr::null() };
        let cs = c.extension_strings.entry(index).or_insert_with(|| {
            CString::new(ext).unwrap_or_default()
        });
        cs.as_ptr() as *const GLubyte
    }
    fn glGetIntegerv(pname: GLenum, params: *mut GLint) => |c| {
        if let Some(v) = c.legacy.get(pname).filter(|_| !c.gl.is_removed_state(pname)) {
            if !c.gl.reject_in_begin() {
                let v: Vec<GLint> = v.iter().map(|&x| (x + 0.5).floor().clamp(i32::MIN as f64, i32::MAX as f64) as GLint).collect();
                wr(params, &v);
            }
            return;
        }
        let v = c.gl.get_integerv(pname);
        wr(params, &v);
    }
    fn glGetInteger64v(pname: GLenum, params: *mut i64) => |c| {
        if let Some(v) = c.legacy.get(pname) {
            if !c.gl.reject_in_begin() {
                let v: Vec<i64> = v.iter().map(|&x| (x + 0.5).floor() as i64).collect();
                wr(params, &v);
            }
            return;
        }
        let v = c.gl.get_integer64v(pname);
        wr(params, &v);
    }
    fn glGetFloatv(pname: GLenum, params: *mut GLfloat) => |c| {
        if let Some(v) = c.legacy.get(pname).filter(|_| !c.gl.is_removed_state(pname)) {
            if !c.gl.reject_in_begin() {
                let v: Vec<GLfloat> = v.iter().map(|&x| x as f32).collect();
                wr(params, &v);
            }
            return;
        }
        let v = c.gl.get_floatv(pname);
        wr(params, &v);
    }
    fn glGetDoublev(pname: GLenum, params: *mut GLdouble) => |c| {
        if let Some(v) = c.legacy.get(pname).filter(|_| !c.gl.is_removed_state(pname)) {
            if !c.gl.reject_in_begin() {
                wr(params, &v);
            }
            return;
        }
        let v = c.gl.get_doublev(pname);
        wr(params, &v);
    }
    fn glGetBooleanv(pname: GLenum, params: *mut GLboolean) => |c| {
        if let Some(v) = c.legacy.get(pname).filter(|_| !c.gl.is_removed_state(pname)) {
            if !c.gl.reject_in_begin() {
                let v: Vec<GLboolean> = v.iter().map(|&x| (x != 0.0) as GLboolean).collect();
                wr(params, &v);
            }
            return;
        }
        let v: Vec<GLboolean> = c.gl.get_booleanv(pname).iter().map(|&x| x as GLboolean).collect();
        wr(params, &v);
    }
    [list] fn glEnable(cap: GLenum) => |c| { c.gl.enable(cap) }
    [list] fn glDisable(cap: GLenum) => |c| { c.gl.disable(cap) }
    fn glIsEnabled(cap: GLenum) -> GLboolean [0] => |c| { c.gl.is_enabled(cap) as GLboolean }
    [list] fn glEnablei(cap: GLenum, index: GLuint) => |c| { c.gl.enablei(cap, index) }
    [list] fn glDisablei(cap: GLenum, index: GLuint) => |c| { c.gl.disablei(cap, index) }
    fn glIsEnabledi(cap: GLenum, index: GLuint) -> GLboolean [0] => |c| {
        c.gl.is_enabledi(cap, index) as GLboolean
    }
    [list] fn glHint(target: GLenum, mode: GLenum) => |c| { c.gl.hint(target, mode) }
}
