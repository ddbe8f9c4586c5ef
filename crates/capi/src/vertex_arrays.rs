//! Vertex array specification and its queries (GL 2.1 §2.8, §6.1.12,
//! §6.1.14; GL 3.3 §2.8, §2.10): vertex array objects, enabling arrays,
//! the gl*Pointer calls (glVertexAttribIPointer, glVertexAttribDivisor
//! among them; client pointers are
//! kept by [`crate::arrays`], the data copied at draw time),
//! glInterleavedArrays, and glGetVertexAttrib*v / glGetPointerv. Array
//! state is client state: none of these is compiled into display lists.
//! Drawing from the arrays is [`crate::drawing`].

use crate::abi::*;
use crate::context::{guard, record_call, vector_call, with_ctx, OsContext};
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

/// glGetVertexAttrib{i,f,d}v as doubles (GL 2.1 §6.1.12; GL 3.3 adds
/// GL_VERTEX_ATTRIB_ARRAY_INTEGER and _DIVISOR): the bound vertex array
/// object's state, or the current value.
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
    match c.gl.get_vertex_attrib_array(index, pname) {
        Some(v) => vec![v as f64],
        None => Vec::new(),
    }
}

/// glGetVertexAttribI{i,ui}v: the current value's integers, or the
/// array state as for glGetVertexAttribiv.
fn vertex_attrib_integer(
    c: &mut OsContext,
    index: GLuint,
    pname: GLenum,
    unsigned: bool,
) -> Vec<u32> {
    if c.gl.reject_in_begin() {
        return Vec::new();
    }
    if pname == GL_CURRENT_VERTEX_ATTRIB {
        return c
            .gl
            .get_current_vertex_attrib_integer(index, unsigned)
            .to_vec();
    }
    match c.gl.get_vertex_attrib_array(index, pname) {
        Some(v) => vec![v as u32],
        None => Vec::new(),
    }
}

/// A packed 2_10_10_10 word's four values (GL 3.3 §2.7), or
/// GL_INVALID_ENUM for another type.
fn packed(c: &mut OsContext, ty: GLenum, value: GLuint, normalized: bool) -> Option<[f32; 4]> {
    if !gl::vertex_format::is_packed(ty) {
        c.gl.record_error(GL_INVALID_ENUM);
        return None;
    }
    Some(gl::vertex_format::unpack_2_10_10_10(value, ty, normalized))
}

gl_entry_points! {
    // ---- client state ----
    fn glEnableClientState(cap: GLenum) => |c| { c.gl.enable_client_state(cap) }
    fn glDisableClientState(cap: GLenum) => |c| { c.gl.disable_client_state(cap) }
    fn glClientActiveTexture(unit: GLenum) => |c| { c.gl.client_active_texture(unit) }
    fn glEnableVertexAttribArray(index: GLuint) => |c| { c.gl.enable_vertex_attrib_array(index) }
    fn glDisableVertexAttribArray(index: GLuint) => |c| { c.gl.disable_vertex_attrib_array(index) }

    // ---- pointers ----
    fn glVertexPointer(size: GLint, ty: GLenum, stride: GLsizei, pointer: *const c_void) => |c| {
        c.arrays.set_pointer(&mut c.gl, AttribSource::Position, pointer as *const u8, |g, d| {
            g.vertex_pointer(size, ty, stride, d)
        });
    }
    fn glColorPointer(size: GLint, ty: GLenum, stride: GLsizei, pointer: *const c_void) => |c| {
        c.arrays.set_pointer(&mut c.gl, AttribSource::Color, pointer as *const u8, |g, d| {
            g.color_pointer(size, ty, stride, d)
        });
    }
    fn glSecondaryColorPointer(size: GLint, ty: GLenum, stride: GLsizei, pointer: *const c_void) => |c| {
        c.arrays.set_pointer(&mut c.gl, AttribSource::SecondaryColor, pointer as *const u8, |g, d| {
            g.secondary_color_pointer(size, ty, stride, d)
        });
    }
    fn glNormalPointer(ty: GLenum, stride: GLsizei, pointer: *const c_void) => |c| {
        c.arrays.set_pointer(&mut c.gl, AttribSource::Normal, pointer as *const u8, |g, d| {
            g.normal_pointer(ty, stride, d)
        });
    }
    fn glFogCoordPointer(ty: GLenum, stride: GLsizei, pointer: *const c_void) => |c| {
        c.arrays.set_pointer(&mut c.gl, AttribSource::FogCoord, pointer as *const u8, |g, d| {
            g.fog_coord_pointer(ty, stride, d)
        });
    }
    fn glTexCoordPointer(size: GLint, ty: GLenum, stride: GLsizei, pointer: *const c_void) => |c| {
        let unit = c.gl.vertex_state().client_active_texture.min(255) as u8;
        c.arrays.set_pointer(&mut c.gl, AttribSource::TexCoord(unit), pointer as *const u8, |g, d| {
            g.tex_coord_pointer(size, ty, stride, d)
        });
    }
    fn glVertexAttribPointer(
        index: GLuint, size: GLint, ty: GLenum, normalized: GLboolean, stride: GLsizei,
        pointer: *const c_void
    ) => |c| {
        let src = AttribSource::Generic(index.min(255) as u8);
        c.arrays.set_pointer(&mut c.gl, src, pointer as *const u8, |g, d| {
            g.vertex_attrib_pointer(index, size, ty, as_bool(normalized), stride, d)
        });
    }

    fn glVertexAttribIPointer(
        index: GLuint, size: GLint, ty: GLenum, stride: GLsizei, pointer: *const c_void
    ) => |c| {
        let src = AttribSource::Generic(index.min(255) as u8);
        c.arrays.set_pointer(&mut c.gl, src, pointer as *const u8, |g, d| {
            g.vertex_attrib_i_pointer(index, size, ty, stride, d)
        });
    }
    // ---- packed current values of the fixed-function attributes
    // (GL 3.3 compatibility §2.7; normals and colours normalized) ----
    [list] fn glVertexP2ui(ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, false) {
            c.gl.vertex_4f(v[0], v[1], 0.0, 1.0)
        }
    }
    fn glVertexP2uiv(ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glVertexP2uiv(ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, false) {
                    c.gl.vertex_4f(v[0], v[1], 0.0, 1.0)
                }
            },
        )
    }
    [list] fn glVertexP3ui(ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, false) {
            c.gl.vertex_4f(v[0], v[1], v[2], 1.0)
        }
    }
    fn glVertexP3uiv(ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glVertexP3uiv(ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, false) {
                    c.gl.vertex_4f(v[0], v[1], v[2], 1.0)
                }
            },
        )
    }
    [list] fn glVertexP4ui(ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, false) {
            c.gl.vertex_4f(v[0], v[1], v[2], v[3])
        }
    }
    fn glVertexP4uiv(ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glVertexP4uiv(ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, false) {
                    c.gl.vertex_4f(v[0], v[1], v[2], v[3])
                }
            },
        )
    }
    [list] fn glTexCoordP1ui(ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, false) {
            c.gl.tex_coord_4f(v[0], 0.0, 0.0, 1.0)
        }
    }
    fn glTexCoordP1uiv(ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glTexCoordP1uiv(ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, false) {
                    c.gl.tex_coord_4f(v[0], 0.0, 0.0, 1.0)
                }
            },
        )
    }
    [list] fn glTexCoordP2ui(ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, false) {
            c.gl.tex_coord_4f(v[0], v[1], 0.0, 1.0)
        }
    }
    fn glTexCoordP2uiv(ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glTexCoordP2uiv(ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, false) {
                    c.gl.tex_coord_4f(v[0], v[1], 0.0, 1.0)
                }
            },
        )
    }
    [list] fn glTexCoordP3ui(ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, false) {
            c.gl.tex_coord_4f(v[0], v[1], v[2], 1.0)
        }
    }
    fn glTexCoordP3uiv(ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glTexCoordP3uiv(ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, false) {
                    c.gl.tex_coord_4f(v[0], v[1], v[2], 1.0)
                }
            },
        )
    }
    [list] fn glTexCoordP4ui(ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, false) {
            c.gl.tex_coord_4f(v[0], v[1], v[2], v[3])
        }
    }
    fn glTexCoordP4uiv(ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glTexCoordP4uiv(ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, false) {
                    c.gl.tex_coord_4f(v[0], v[1], v[2], v[3])
                }
            },
        )
    }
    [list] fn glMultiTexCoordP1ui(texture: GLenum, ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, false) {
            c.gl.multi_tex_coord_4f(texture, v[0], 0.0, 0.0, 1.0)
        }
    }
    fn glMultiTexCoordP1uiv(texture: GLenum, ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glMultiTexCoordP1uiv(texture, ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, false) {
                    c.gl.multi_tex_coord_4f(texture, v[0], 0.0, 0.0, 1.0)
                }
            },
        )
    }
    [list] fn glMultiTexCoordP2ui(texture: GLenum, ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, false) {
            c.gl.multi_tex_coord_4f(texture, v[0], v[1], 0.0, 1.0)
        }
    }
    fn glMultiTexCoordP2uiv(texture: GLenum, ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glMultiTexCoordP2uiv(texture, ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, false) {
                    c.gl.multi_tex_coord_4f(texture, v[0], v[1], 0.0, 1.0)
                }
            },
        )
    }
    [list] fn glMultiTexCoordP3ui(texture: GLenum, ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, false) {
            c.gl.multi_tex_coord_4f(texture, v[0], v[1], v[2], 1.0)
        }
    }
    fn glMultiTexCoordP3uiv(texture: GLenum, ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glMultiTexCoordP3uiv(texture, ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, false) {
                    c.gl.multi_tex_coord_4f(texture, v[0], v[1], v[2], 1.0)
                }
            },
        )
    }
    [list] fn glMultiTexCoordP4ui(texture: GLenum, ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, false) {
            c.gl.multi_tex_coord_4f(texture, v[0], v[1], v[2], v[3])
        }
    }
    fn glMultiTexCoordP4uiv(texture: GLenum, ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glMultiTexCoordP4uiv(texture, ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, false) {
                    c.gl.multi_tex_coord_4f(texture, v[0], v[1], v[2], v[3])
                }
            },
        )
    }
    [list] fn glNormalP3ui(ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, true) {
            c.gl.normal_3f(v[0], v[1], v[2])
        }
    }
    fn glNormalP3uiv(ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glNormalP3uiv(ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, true) {
                    c.gl.normal_3f(v[0], v[1], v[2])
                }
            },
        )
    }
    [list] fn glColorP3ui(ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, true) {
            c.gl.color_4f(v[0], v[1], v[2], 1.0)
        }
    }
    fn glColorP3uiv(ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glColorP3uiv(ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, true) {
                    c.gl.color_4f(v[0], v[1], v[2], 1.0)
                }
            },
        )
    }
    [list] fn glColorP4ui(ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, true) {
            c.gl.color_4f(v[0], v[1], v[2], v[3])
        }
    }
    fn glColorP4uiv(ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glColorP4uiv(ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, true) {
                    c.gl.color_4f(v[0], v[1], v[2], v[3])
                }
            },
        )
    }
    [list] fn glSecondaryColorP3ui(ty: GLenum, value: GLuint) => |c| {
        if let Some(v) = packed(c, ty, value, true) {
            c.gl.secondary_color_3f(v[0], v[1], v[2])
        }
    }
    fn glSecondaryColorP3uiv(ty: GLenum, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glSecondaryColorP3uiv(ty, p) },
            |c, [w]| {
                if let Some(v) = packed(c, ty, w, true) {
                    c.gl.secondary_color_3f(v[0], v[1], v[2])
                }
            },
        )
    }
    // ---- packed current values (GL 3.3 §2.7) ----
    [list] fn glVertexAttribP1ui(index: GLuint, ty: GLenum, normalized: GLboolean, value: GLuint) => |c| {
        c.gl.vertex_attrib_p(index, ty, as_bool(normalized), 1, value)
    }
    fn glVertexAttribP1uiv(index: GLuint, ty: GLenum, normalized: GLboolean, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glVertexAttribP1uiv(index, ty, normalized, p) },
            |c, [v]| c.gl.vertex_attrib_p(index, ty, as_bool(normalized), 1, v),
        )
    }
    [list] fn glVertexAttribP2ui(index: GLuint, ty: GLenum, normalized: GLboolean, value: GLuint) => |c| {
        c.gl.vertex_attrib_p(index, ty, as_bool(normalized), 2, value)
    }
    fn glVertexAttribP2uiv(index: GLuint, ty: GLenum, normalized: GLboolean, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glVertexAttribP2uiv(index, ty, normalized, p) },
            |c, [v]| c.gl.vertex_attrib_p(index, ty, as_bool(normalized), 2, v),
        )
    }
    [list] fn glVertexAttribP3ui(index: GLuint, ty: GLenum, normalized: GLboolean, value: GLuint) => |c| {
        c.gl.vertex_attrib_p(index, ty, as_bool(normalized), 3, value)
    }
    fn glVertexAttribP3uiv(index: GLuint, ty: GLenum, normalized: GLboolean, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glVertexAttribP3uiv(index, ty, normalized, p) },
            |c, [v]| c.gl.vertex_attrib_p(index, ty, as_bool(normalized), 3, v),
        )
    }
    [list] fn glVertexAttribP4ui(index: GLuint, ty: GLenum, normalized: GLboolean, value: GLuint) => |c| {
        c.gl.vertex_attrib_p(index, ty, as_bool(normalized), 4, value)
    }
    fn glVertexAttribP4uiv(index: GLuint, ty: GLenum, normalized: GLboolean, value: *const GLuint) => |c| {
        vector_call::<1, u32>(
            c,
            value,
            move |p| unsafe { glVertexAttribP4uiv(index, ty, normalized, p) },
            |c, [v]| c.gl.vertex_attrib_p(index, ty, as_bool(normalized), 4, v),
        )
    }
    fn glVertexAttribDivisor(index: GLuint, divisor: GLuint) => |c| {
        c.gl.vertex_attrib_divisor(index, divisor)
    }

    // ---- vertex array objects (GL 3.3 §2.10) ----
    fn glGenVertexArrays(n: GLsizei, arrays: *mut GLuint) => |c| {
        let names = c.gl.gen_vertex_arrays(n);
        wr(arrays, &names);
    }
    fn glBindVertexArray(array: GLuint) => |c| { c.gl.bind_vertex_array(array) }
    fn glDeleteVertexArrays(n: GLsizei, arrays: *const GLuint) => |c| {
        if n < 0 {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        let names = rd_vec(arrays, n as i64);
        c.gl.delete_vertex_arrays(&names);
    }
    fn glIsVertexArray(array: GLuint) -> GLboolean [0] => |c| {
        if c.gl.reject_in_begin() {
            return 0;
        }
        c.gl.is_vertex_array(array) as GLboolean
    }

    // ---- queries ----
    fn glGetVertexAttribiv(index: GLuint, pname: GLenum, v: *mut GLint) => |c| {
        let r: Vec<GLint> = vertex_attrib(c, index, pname)
            .iter()
            .map(|&x| if pname == GL_CURRENT_VERTEX_ATTRIB { x as i32 } else { x as i64 as i32 })
            .collect();
        wr(v, &r);
    }
    fn glGetVertexAttribfv(index: GLuint, pname: GLenum, v: *mut GLfloat) => |c| {
        let r: Vec<GLfloat> = vertex_attrib(c, index, pname).iter().map(|&x| x as f32).collect();
        wr(v, &r);
    }
    fn glGetVertexAttribIiv(index: GLuint, pname: GLenum, v: *mut GLint) => |c| {
        let r: Vec<GLint> = vertex_attrib_integer(c, index, pname, false)
            .iter()
            .map(|&x| x as i32)
            .collect();
        wr(v, &r);
    }
    fn glGetVertexAttribIuiv(index: GLuint, pname: GLenum, v: *mut GLuint) => |c| {
        let r = vertex_attrib_integer(c, index, pname, true);
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
}

/// One row of GL 2.1 Table 2.5: (texcoord size, colour size, colour type,
/// normal?, vertex size).
fn interleaved_layout(format: u32) -> Option<(i32, i32, u32, bool, i32)> {
    Some(match format {
        GL_V2F => (0, 0, 0, false, 2),
        GL_V3F => (0, 0, 0, false, 3),
        GL_C4UB_V2F => (0, 4, GL_UNSIGNED_BYTE, false, 2),
        GL_C4UB_V3F => (0, 4, GL_UNSIGNED_BYTE, false, 3),
        GL_C3F_V3F => (0, 3, GL_FLOAT, false, 3),
        GL_N3F_V3F => (0, 0, 0, true, 3),
        GL_C4F_N3F_V3F => (0, 4, GL_FLOAT, true, 3),
        GL_T2F_V3F => (2, 0, 0, false, 3),
        GL_T4F_V4F => (4, 0, 0, false, 4),
        GL_T2F_C4UB_V3F => (2, 4, GL_UNSIGNED_BYTE, false, 3),
        GL_T2F_C3F_V3F => (2, 3, GL_FLOAT, false, 3),
        GL_T2F_N3F_V3F => (2, 0, 0, true, 3),
        GL_T2F_C4F_N3F_V3F => (2, 4, GL_FLOAT, true, 3),
        GL_T4F_C4F_N3F_V4F => (4, 4, GL_FLOAT, true, 4),
        _ => return None,
    })
}

/// glInterleavedArrays: sets and enables the arrays of `format` (and
/// disables the others), as the sequence of calls Table 2.5 defines.
/// Client state: never compiled into display lists.
#[no_mangle]
pub unsafe extern "C" fn glInterleavedArrays(
    format: GLenum,
    stride: GLsizei,
    pointer: *const c_void,
) {
    if crate::context::refused_in_core() {
        return;
    }
    guard((), || {
        let ok = with_ctx(false, |c| {
            if c.gl.reject_in_begin() {
                return false;
            }
            if interleaved_layout(format).is_none() {
                c.gl.record_error(GL_INVALID_ENUM);
                return false;
            }
            if stride < 0 {
                c.gl.record_error(GL_INVALID_VALUE);
                return false;
            }
            true
        });
        let Some((tsize, csize, cty, normal, vsize)) = interleaved_layout(format) else {
            return;
        };
        if !ok {
            return;
        }
        let f = 4usize; // sizeof(GLfloat)
        let pc = tsize as usize * f;
        let csize_bytes = if cty == GL_UNSIGNED_BYTE {
            4
        } else {
            csize as usize * f
        };
        let pn = pc + csize_bytes;
        let pv = pn + if normal { 3 * f } else { 0 };
        let s = pv + vsize as usize * f;
        let stride = if stride == 0 { s as GLsizei } else { stride };
        let p = pointer as *const u8;
        let at = |o: usize| p.wrapping_add(o) as *const c_void;
        // SAFETY (all calls): entry points of this library, called in
        // sequence outside any other entry point; the pointers are the
        // caller's interleaved array at the offsets Table 2.5 gives.
        unsafe {
            glDisableClientState(GL_EDGE_FLAG_ARRAY);
            glDisableClientState(GL_INDEX_ARRAY);
            glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
            glDisableClientState(GL_FOG_COORD_ARRAY);
            if tsize > 0 {
                glEnableClientState(GL_TEXTURE_COORD_ARRAY);
                glTexCoordPointer(tsize, GL_FLOAT, stride, at(0));
            } else {
                glDisableClientState(GL_TEXTURE_COORD_ARRAY);
            }
            if csize > 0 {
                glEnableClientState(GL_COLOR_ARRAY);
                glColorPointer(csize, cty, stride, at(pc));
            } else {
                glDisableClientState(GL_COLOR_ARRAY);
            }
            if normal {
                glEnableClientState(GL_NORMAL_ARRAY);
                glNormalPointer(GL_FLOAT, stride, at(pn));
            } else {
                glDisableClientState(GL_NORMAL_ARRAY);
            }
            glEnableClientState(GL_VERTEX_ARRAY);
            glVertexPointer(vsize, GL_FLOAT, stride, at(pv));
        }
    })
}

/// This module's exported functions outside the entry-point table.
pub fn lookup_extra(name: &str) -> Option<*const ()> {
    (name == "glInterleavedArrays").then_some(glInterleavedArrays as *const ())
}
