//! State queries added after the first increment: vertex attribute and
//! array pointers (glGetVertexAttrib*, glGetPointerv), texture parameters,
//! environment and coordinate generation (glGetTex*), integer forms of the
//! light/material queries, and the few setters whose only other form was
//! already there (glTexGen{d,i}v, transpose double matrices,
//! glPointParameteriv).

use crate::abi::*;
use crate::context::{record_call, record_vector, with_ctx, OsContext};
use gl::enums::*;
use gl::vertex::AttribSource;
use std::ffi::c_void;

/// The generic array `index`, GL_INVALID_VALUE past the last.
fn generic(c: &mut OsContext, index: GLuint) -> Option<gl::ArrayState> {
    match c.gl.vertex_state().generic_arrays.get(index as usize) {
        Some(a) => Some(a.clone()),
        None => {
            c.gl.record_error(GL_INVALID_VALUE);
            None
        }
    }
}

/// glGetVertexAttrib{i,f,d}v as doubles (GL 2.1 §6.1.12).
fn vertex_attrib(c: &mut OsContext, index: GLuint, pname: GLenum) -> Vec<f64> {
    if c.gl.reject_in_begin() {
        return Vec::new();
    }
    if pname == GL_CURRENT_VERTEX_ATTRIB {
        return c
            .gl
            .get_current_vertex_attrib(index)
            .iter()
            .map(|&x| x as f64)
            .collect();
    }
    let Some(a) = generic(c, index) else {
        return Vec::new();
    };
    let v = match pname {
        GL_VERTEX_ATTRIB_ARRAY_ENABLED => a.enabled as i64,
        GL_VERTEX_ATTRIB_ARRAY_SIZE => a.size as i64,
        GL_VERTEX_ATTRIB_ARRAY_STRIDE => a.stride as i64,
        GL_VERTEX_ATTRIB_ARRAY_TYPE => a.ty as i64,
        GL_VERTEX_ATTRIB_ARRAY_NORMALIZED => a.normalized as i64,
        GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING => a.buffer as i64,
        _ => {
            c.gl.record_error(GL_INVALID_ENUM);
            return Vec::new();
        }
    };
    vec![v as f64]
}

/// Integer form of a float query: colours (ranges [0, 1] or [-1, 1]) map
/// linearly to the integer range, the rest round (GL 2.1 §6.1.2).
fn to_int(v: f32, color: bool) -> i32 {
    if color {
        let x = (v as f64 * 2147483647.0).clamp(i32::MIN as f64, i32::MAX as f64);
        if x >= 0.0 {
            (x + 0.5).floor() as i32
        } else {
            (x - 0.5).ceil() as i32
        }
    } else {
        let x = (v as f64).clamp(i32::MIN as f64, i32::MAX as f64);
        (x + 0.5).floor() as i32
    }
}

gl_entry_points! {
    fn glGetVertexAttribiv(index: GLuint, pname: GLenum, v: *mut GLint) => |c| {
        let r: Vec<GLint> = vertex_attrib(c, index, pname)
            .iter()
            .map(|&x| if pname == GL_CURRENT_VERTEX_ATTRIB { x as i32 } else { x as i64 as i32 })
            .collect();
        wr(v, &r);
    }
    fn glGetVertexAttribdv(index: GLuint, pname: GLenum, v: *mut GLdouble) => |c| {
        let r = vertex_attrib(c, index, pname);
        wr(v, &r);
    }
    fn glGetVertexAttribPointerv(index: GLuint, pname: GLenum, v: *mut *mut c_void) => |c| {
        if c.gl.reject_in_begin() {
            return;
        }
        if generic(c, index).is_none() {
            return;
        }
        if pname != GL_VERTEX_ATTRIB_ARRAY_POINTER {
            c.gl.record_error(GL_INVALID_ENUM);
            return;
        }
        let p = c.arrays.pointer_value(c.gl.vertex_state(), AttribSource::Generic(index as u8));
        wr(v, &[p as *mut c_void]);
    }
    fn glGetPointerv(pname: GLenum, v: *mut *mut c_void) => |c| {
        if c.gl.reject_in_begin() {
            return;
        }
        let va = c.gl.vertex_state();
        let src = match pname {
            GL_VERTEX_ARRAY_POINTER => Some(AttribSource::Position),
            GL_NORMAL_ARRAY_POINTER => Some(AttribSource::Normal),
            GL_COLOR_ARRAY_POINTER => Some(AttribSource::Color),
            GL_SECONDARY_COLOR_ARRAY_POINTER => Some(AttribSource::SecondaryColor),
            GL_FOG_COORD_ARRAY_POINTER => Some(AttribSource::FogCoord),
            GL_TEXTURE_COORD_ARRAY_POINTER => {
                Some(AttribSource::TexCoord(va.client_active_texture as u8))
            }
            GL_INDEX_ARRAY_POINTER | GL_EDGE_FLAG_ARRAY_POINTER => None,
            GL_FEEDBACK_BUFFER_POINTER | GL_SELECTION_BUFFER_POINTER => None,
            _ => {
                c.gl.record_error(GL_INVALID_ENUM);
                return;
            }
        };
        let p = match src {
            Some(s) => c.arrays.pointer_value(va, s),
            None => match pname {
                GL_INDEX_ARRAY_POINTER => c.legacy.index_pointer,
                GL_EDGE_FLAG_ARRAY_POINTER => c.legacy.edge_flag_pointer,
                GL_FEEDBACK_BUFFER_POINTER => c.legacy.feedback_buffer,
                _ => c.legacy.select_buffer,
            },
        };
        wr(v, &[p as *mut c_void]);
    }
    fn glGetTexParameterfv(target: GLenum, pname: GLenum, v: *mut GLfloat) => |c| {
        let r = c.gl.get_tex_parameterfv(target, pname);
        wr(v, &r);
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
    fn glGetTexEnvfv(target: GLenum, pname: GLenum, v: *mut GLfloat) => |c| {
        let r = c.gl.get_tex_envfv(target, pname);
        wr(v, &r);
    }
    fn glGetTexEnviv(target: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        let color = pname == GL_TEXTURE_ENV_COLOR;
        let r: Vec<GLint> = c.gl.get_tex_envfv(target, pname).iter().map(|&x| to_int(x, color)).collect();
        wr(v, &r);
    }
    fn glGetTexGenfv(coord: GLenum, pname: GLenum, v: *mut GLfloat) => |c| {
        let r = c.gl.get_tex_genfv(coord, pname);
        wr(v, &r);
    }
    fn glGetTexGendv(coord: GLenum, pname: GLenum, v: *mut GLdouble) => |c| {
        let r: Vec<f64> = c.gl.get_tex_genfv(coord, pname).iter().map(|&x| x as f64).collect();
        wr(v, &r);
    }
    fn glGetTexGeniv(coord: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        let r: Vec<GLint> = c.gl.get_tex_genfv(coord, pname).iter().map(|&x| to_int(x, false)).collect();
        wr(v, &r);
    }
    [list] fn glTexGend(coord: GLenum, pname: GLenum, v: GLdouble) => |c| { c.gl.tex_genf(coord, pname, v as f32) }
    fn glTexGendv(coord: GLenum, pname: GLenum, v: *const GLdouble) => |c| {
        let n = if pname == GL_TEXTURE_GEN_MODE { 1 } else { 4 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glTexGendv(coord, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() {
            let f: Vec<f32> = rd_vec(v, n).iter().map(|&x| x as f32).collect();
            c.gl.tex_genfv(coord, pname, &f)
        }
    }
    fn glTexGeniv(coord: GLenum, pname: GLenum, v: *const GLint) => |c| {
        let n = if pname == GL_TEXTURE_GEN_MODE { 1 } else { 4 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glTexGeniv(coord, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() {
            let f: Vec<f32> = rd_vec(v, n).iter().map(|&x| x as f32).collect();
            c.gl.tex_genfv(coord, pname, &f)
        }
    }
    fn glGetLightiv(light: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        let color = matches!(pname, GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR);
        let r: Vec<GLint> = c.gl.get_lightfv(light, pname).iter().map(|&x| to_int(x, color)).collect();
        wr(v, &r);
    }
    fn glGetMaterialiv(face: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        let color = matches!(pname, GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION);
        let r: Vec<GLint> = c.gl.get_materialfv(face, pname).iter().map(|&x| to_int(x, color)).collect();
        wr(v, &r);
    }
    fn glLoadTransposeMatrixd(m: *const GLdouble) => |c| {
        if record_vector::<16, f64>(c, m, move |p| unsafe { glLoadTransposeMatrixd(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f64>(m) { c.gl.load_transpose_matrixf(&m.map(|x| x as f32)) }
    }
    fn glMultTransposeMatrixd(m: *const GLdouble) => |c| {
        if record_vector::<16, f64>(c, m, move |p| unsafe { glMultTransposeMatrixd(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f64>(m) { c.gl.mult_transpose_matrixf(&m.map(|x| x as f32)) }
    }
    fn glPointParameteriv(pname: GLenum, v: *const GLint) => |c| {
        let n = if pname == GL_POINT_DISTANCE_ATTENUATION { 3 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glPointParameteriv(pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() {
            let f: Vec<f32> = rd_vec(v, n).iter().map(|&x| x as f32).collect();
            c.gl.point_parameterfv(pname, &f)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::to_int;

    #[test]
    fn colors_map_to_the_full_integer_range() {
        assert_eq!(to_int(1.0, true), i32::MAX);
        assert_eq!(to_int(-1.0, true), -i32::MAX);
        assert_eq!(to_int(0.0, true), 0);
        assert_eq!(to_int(2.6, false), 3);
        assert_eq!(to_int(f32::NAN, false), 0);
    }
}
