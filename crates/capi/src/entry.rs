//! The gl* entry points, C ABI, on the current context.
//!
//! Each function runs on the thread's current context (none: it does
//! nothing and returns 0/null), with panics caught. Pointer arguments GL
//! allows to be null are checked; a null pointer where GL requires memory
//! makes the call a no-op instead of a crash. Commands that can change
//! pixels mark the context dirty; glFinish, glFlush and glReadPixels copy
//! the default framebuffer into the client's buffer ([`OsContext::sync`]).

use crate::abi::*;
use crate::context::{record_call, record_vector, with_ctx, OsContext};
use gl::enums::*;
use gl::vertex::AttribSource;
use gl::ArrayData;
use std::ffi::{c_void, CStr, CString};
use std::sync::Arc;

/// Largest glBufferData/glBufferSubData copy (larger: GL_OUT_OF_MEMORY
/// from the context, or GL_INVALID_VALUE).
const MAX_BUFFER_BYTES: usize = 1 << 31;

/// Most array elements read from client memory by one glUniform*v call.
const MAX_UNIFORM_ELEMENTS: i32 = 4096;

/// glGet*InfoLog / glGetShaderSource output: at most `buf_size - 1` bytes
/// and a NUL; `length` gets the bytes written without the NUL.
unsafe fn wr_string(
    c: &mut OsContext,
    s: &str,
    buf_size: GLsizei,
    length: *mut GLsizei,
    out: *mut GLchar,
) {
    if buf_size < 0 {
        c.gl.record_error(GL_INVALID_VALUE);
        return;
    }
    let n = if out.is_null() || buf_size == 0 {
        0
    } else {
        let n = s.len().min(buf_size as usize - 1);
        // SAFETY: the caller's buffer holds buf_size bytes.
        unsafe {
            std::ptr::copy_nonoverlapping(s.as_ptr() as *const GLchar, out, n);
            *out.add(n) = 0;
        }
        n
    };
    // SAFETY: out pointer or null.
    unsafe { wr(length, &[n as GLsizei]) };
}

/// The client image a glTexImage*/glTexSubImage* call reads: `w*h*d`
/// pixels of `format`/`ty` at the unpack alignment, from client memory or,
/// with a buffer bound to GL_PIXEL_UNPACK_BUFFER, from that buffer at the
/// offset `data` (GL 2.1 §4.3.5). Ok(None): no data (null pointer, an
/// unknown format/type or an empty image: the context validates those).
/// Err: an error was recorded (the range read lies outside the buffer, or
/// the buffer is mapped: GL_INVALID_OPERATION); the call must do nothing.
pub(crate) unsafe fn image_bytes(
    c: &mut OsContext,
    w: GLsizei,
    h: GLsizei,
    d: GLsizei,
    format: GLenum,
    ty: GLenum,
    data: *const c_void,
) -> Result<Option<Vec<u8>>, crate::buffers::Recorded> {
    let pbo = c.gl.bound_buffer(GL_PIXEL_UNPACK_BUFFER);
    if (data.is_null() && pbo == 0) || w <= 0 || h <= 0 || d <= 0 {
        return Ok(None);
    }
    if gl::objects::pixel_size(format, ty).is_none() {
        return Ok(None);
    }
    let align =
        c.gl.get_integerv(GL_UNPACK_ALIGNMENT)
            .first()
            .copied()
            .unwrap_or(4);
    let row = gl::objects::row_stride(w as usize, format, ty, align.max(1) as usize);
    let Some(len) = row
        .checked_mul(h as usize)
        .and_then(|x| x.checked_mul(d as usize))
    else {
        return Ok(None);
    };
    if len > MAX_BUFFER_BYTES {
        return Ok(None);
    }
    if pbo != 0 {
        return crate::buffers::read_pixel_buffer(c, GL_PIXEL_UNPACK_BUFFER, data as usize, len)
            .map(Some);
    }
    // SAFETY: GL's contract: the client image holds w x h x d pixels of
    // format/type laid out per the unpack state.
    Ok(Some(unsafe { bytes(data, len) }.to_vec()))
}

/// glDrawElements' index array as the context takes it (an offset into the
/// bound element buffer, or a copy of client memory) and, with `read`, the
/// indices themselves (else none: a draw from buffers reads them once,
/// in the context).
pub(crate) unsafe fn element_source(
    c: &mut OsContext,
    count: GLsizei,
    ty: GLenum,
    indices: *const c_void,
    read: bool,
) -> (ArrayData, Vec<u32>) {
    let size = match ty {
        GL_UNSIGNED_BYTE => 1,
        GL_UNSIGNED_SHORT => 2,
        GL_UNSIGNED_INT => 4,
        _ => return (ArrayData::Offset(0), Vec::new()),
    };
    if count <= 0 {
        return (ArrayData::Offset(0), Vec::new());
    }
    let n = (count as usize).min(1 << 24) * size;
    let convert = |bytes: &[u8]| -> Vec<u32> {
        bytes
            .chunks_exact(size)
            .map(|ch| match ch {
                [a] => *a as u32,
                [a, b] => u16::from_ne_bytes([*a, *b]) as u32,
                [a, b, c, d] => u32::from_ne_bytes([*a, *b, *c, *d]),
                _ => 0,
            })
            .collect()
    };
    if c.gl.vertex_state().element_buffer != 0 {
        let data = ArrayData::Offset(indices as usize);
        if !read {
            return (data, Vec::new());
        }
        // Read the bound buffer without disturbing the error flag (the
        // draw reports range errors itself).
        let saved = c.gl.get_error();
        let bytes =
            c.gl.get_buffer_sub_data(GL_ELEMENT_ARRAY_BUFFER, indices as isize, n as isize);
        let _ = c.gl.get_error();
        c.gl.record_error(saved);
        (data, convert(&bytes))
    } else if indices.is_null() {
        (ArrayData::Client(Arc::from(Vec::new())), Vec::new())
    } else {
        // SAFETY: GL's contract: `count` indices of `ty` at `indices`.
        let data = unsafe { bytes(indices, n) };
        let idx = if read { convert(data) } else { Vec::new() };
        (ArrayData::Client(Arc::from(data)), idx)
    }
}

/// Before a glDrawElements-like draw: copies the vertices its indices use
/// of every enabled client array into the context
/// ([`ClientArrays::prepare`]), reading the indices only when there is such
/// an array; returns the index data for the context.
///
/// [`ClientArrays::prepare`]: crate::arrays::ClientArrays::prepare
pub(crate) unsafe fn prepare_elements(
    c: &mut OsContext,
    count: GLsizei,
    ty: GLenum,
    indices: *const c_void,
) -> ArrayData {
    let read = c.arrays.reads_client_memory(&c.gl);
    // SAFETY: the caller's.
    let (data, idx) = unsafe { element_source(c, count, ty, indices, read) };
    if let (Some(lo), Some(hi)) = (idx.iter().min(), idx.iter().max()) {
        c.arrays.prepare(&mut c.gl, *lo, *hi);
    }
    data
}

gl_entry_points! {
    // ---- errors, strings, queries ----
    fn glGetError() -> GLenum [GL_NO_ERROR] => |c| { c.gl.get_error() }
    fn glGetString(name: GLenum) -> *const GLubyte [std::ptr::null()] => |c| {
        if !c.strings.contains_key(&name) {
            let s = c.gl.get_string(name);
            let s = match name {
                GL_VENDOR | GL_SHADING_LANGUAGE_VERSION | GL_EXTENSIONS => s,
                GL_RENDERER => "shaderbox (CPU)".to_string(),
                GL_VERSION => format!("2.1 shaderbox {}", env!("CARGO_PKG_VERSION")),
                _ => return std::ptr::null(),
            };
            let Ok(cs) = CString::new(s) else { return std::ptr::null() };
            c.strings.insert(name, cs);
        }
        c.strings.get(&name).map_or(std::ptr::null(), |s| s.as_ptr() as *const GLubyte)
    }
    fn glGetIntegerv(pname: GLenum, params: *mut GLint) => |c| {
        if let Some(v) = crate::legacy::get(c, pname) {
            if !c.gl.reject_in_begin() {
                let v: Vec<GLint> = v.iter().map(|&x| (x + 0.5).floor().clamp(i32::MIN as f64, i32::MAX as f64) as GLint).collect();
                wr(params, &v);
            }
            return;
        }
        let v = c.gl.get_integerv(pname);
        wr(params, &v);
    }
    fn glGetFloatv(pname: GLenum, params: *mut GLfloat) => |c| {
        if let Some(v) = crate::legacy::get(c, pname) {
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
        if let Some(v) = crate::legacy::get(c, pname) {
            if !c.gl.reject_in_begin() {
                wr(params, &v);
            }
            return;
        }
        let v = c.gl.get_doublev(pname);
        wr(params, &v);
    }
    fn glGetBooleanv(pname: GLenum, params: *mut GLboolean) => |c| {
        if let Some(v) = crate::legacy::get(c, pname) {
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
    fn glFinish() => |c| { c.gl.finish(); c.sync(); }
    fn glFlush() => |c| { c.gl.flush(); c.sync(); }
    [list] fn glHint(target: GLenum, mode: GLenum) => |c| { c.gl.hint(target, mode) }
    fn glPixelStorei(pname: GLenum, param: GLint) => |c| { c.gl.pixel_storei(pname, param) }

    // ---- framebuffer ----
    [list] fn glViewport(x: GLint, y: GLint, w: GLsizei, h: GLsizei) => |c| { c.gl.viewport(x, y, w, h) }
    [list] fn glScissor(x: GLint, y: GLint, w: GLsizei, h: GLsizei) => |c| { c.gl.scissor(x, y, w, h) }
    [list] fn glDepthRange(n: GLclampd, f: GLclampd) => |c| { c.gl.depth_range(n, f) }
    [list] fn glClearColor(r: GLclampf, g: GLclampf, b: GLclampf, a: GLclampf) => |c| {
        c.gl.clear_color(r, g, b, a)
    }
    [list] fn glClearDepth(d: GLclampd) => |c| { c.gl.clear_depth(d) }
    [list] fn glClearStencil(s: GLint) => |c| { c.gl.clear_stencil(s) }
    [list] fn glClear(mask: GLbitfield) => |c| { c.gl.clear(mask); c.dirty = true; }
    [list] fn glColorMask(r: GLboolean, g: GLboolean, bl: GLboolean, a: GLboolean) => |c| {
        c.gl.color_mask(as_bool(r), as_bool(g), as_bool(bl), as_bool(a))
    }
    [list] fn glDepthMask(flag: GLboolean) => |c| { c.gl.depth_mask(as_bool(flag)) }
    [list] fn glDepthFunc(func: GLenum) => |c| { c.gl.depth_func(func) }
    [list] fn glBlendFunc(src: GLenum, dst: GLenum) => |c| { c.gl.blend_func(src, dst) }
    [list] fn glBlendEquation(mode: GLenum) => |c| { c.gl.blend_equation(mode) }
    [list] fn glAlphaFunc(func: GLenum, reference: GLclampf) => |c| { c.gl.alpha_func(func, reference) }
    [list] fn glCullFace(mode: GLenum) => |c| { c.gl.cull_face(mode) }
    [list] fn glFrontFace(mode: GLenum) => |c| { c.gl.front_face(mode) }
    [list] fn glShadeModel(mode: GLenum) => |c| { c.gl.shade_model(mode) }
    [list] fn glPolygonMode(face: GLenum, mode: GLenum) => |c| { c.gl.polygon_mode(face, mode) }
    [list] fn glPolygonOffset(factor: GLfloat, units: GLfloat) => |c| { c.gl.polygon_offset(factor, units) }
    [list] fn glPointSize(size: GLfloat) => |c| { c.gl.point_size(size) }
    [list] fn glLineWidth(width: GLfloat) => |c| { c.gl.line_width(width) }
    fn glReadPixels(
        x: GLint, y: GLint, w: GLsizei, h: GLsizei, format: GLenum, ty: GLenum,
        pixels: *mut c_void
    ) => |c| {
        if let Some(d) = &c.debug {
            crate::debug_env::flush(&mut c.gl, d);
        }
        let align = c.gl.get_integerv(GL_PACK_ALIGNMENT).first().copied().unwrap_or(4).max(1);
        let len = if w > 0 && h > 0 && gl::objects::pixel_size(format, ty).is_some() {
            gl::objects::row_stride(w as usize, format, ty, align as usize)
                .saturating_mul(h as usize)
        } else {
            0
        };
        if c.gl.bound_buffer(GL_PIXEL_PACK_BUFFER) != 0 {
            // Into the pack buffer at offset `pixels` (GL 2.1 §4.3.5).
            if len > MAX_BUFFER_BYTES {
                c.gl.record_error(GL_OUT_OF_MEMORY);
                return;
            }
            let mut out = vec![0u8; len];
            let before = c.gl.get_error();
            c.gl.read_pixels(x, y, w, h, format, ty, &mut out);
            let e = c.gl.get_error();
            c.gl.record_error(if before != GL_NO_ERROR { before } else { e });
            if e == GL_NO_ERROR && len > 0 {
                crate::buffers::write_pixel_buffer(c, pixels as usize, &out);
            }
            return;
        }
        if pixels.is_null() && len > 0 {
            return;
        }
        let out: &mut [u8] = if len == 0 {
            &mut []
        } else {
            // SAFETY: GL's contract: the client's buffer holds the packed
            // w x h image of format/type at the pack alignment.
            std::slice::from_raw_parts_mut(pixels as *mut u8, len)
        };
        c.gl.read_pixels(x, y, w, h, format, ty, out);
        c.sync();
    }

    // ---- matrices ----
    [list] fn glMatrixMode(mode: GLenum) => |c| { c.gl.matrix_mode(mode) }
    [list] fn glLoadIdentity() => |c| { c.gl.load_identity() }
    [list] fn glPushMatrix() => |c| { c.gl.push_matrix() }
    [list] fn glPopMatrix() => |c| { c.gl.pop_matrix() }
    [list] fn glOrtho(l: GLdouble, r: GLdouble, bo: GLdouble, t: GLdouble, n: GLdouble, f: GLdouble) => |c| {
        c.gl.ortho(l, r, bo, t, n, f)
    }
    [list] fn glFrustum(l: GLdouble, r: GLdouble, bo: GLdouble, t: GLdouble, n: GLdouble, f: GLdouble) => |c| {
        c.gl.frustum(l, r, bo, t, n, f)
    }
    [list] fn glTranslatef(x: GLfloat, y: GLfloat, z: GLfloat) => |c| { c.gl.translatef(x, y, z) }
    [list] fn glTranslated(x: GLdouble, y: GLdouble, z: GLdouble) => |c| {
        c.gl.translatef(x as f32, y as f32, z as f32)
    }
    [list] fn glScalef(x: GLfloat, y: GLfloat, z: GLfloat) => |c| { c.gl.scalef(x, y, z) }
    [list] fn glScaled(x: GLdouble, y: GLdouble, z: GLdouble) => |c| {
        c.gl.scalef(x as f32, y as f32, z as f32)
    }
    [list] fn glRotatef(a: GLfloat, x: GLfloat, y: GLfloat, z: GLfloat) => |c| { c.gl.rotatef(a, x, y, z) }
    [list] fn glRotated(a: GLdouble, x: GLdouble, y: GLdouble, z: GLdouble) => |c| {
        c.gl.rotatef(a as f32, x as f32, y as f32, z as f32)
    }
    fn glLoadMatrixf(m: *const GLfloat) => |c| {
        if record_vector::<16, f32>(c, m, move |p| unsafe { glLoadMatrixf(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f32>(m) { c.gl.load_matrixf(&m) }
    }
    fn glLoadMatrixd(m: *const GLdouble) => |c| {
        if record_vector::<16, f64>(c, m, move |p| unsafe { glLoadMatrixd(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f64>(m) { c.gl.load_matrixf(&m.map(|x| x as f32)) }
    }
    fn glMultMatrixf(m: *const GLfloat) => |c| {
        if record_vector::<16, f32>(c, m, move |p| unsafe { glMultMatrixf(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f32>(m) { c.gl.mult_matrixf(&m) }
    }
    fn glMultMatrixd(m: *const GLdouble) => |c| {
        if record_vector::<16, f64>(c, m, move |p| unsafe { glMultMatrixd(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f64>(m) { c.gl.mult_matrixf(&m.map(|x| x as f32)) }
    }

    // ---- immediate mode ----
    [list] fn glBegin(mode: GLenum) => |c| { c.gl.begin(mode) }
    [list] fn glEnd() => |c| { c.gl.end(); c.dirty = true; }

    // ---- lighting, fog ----
    [list] fn glLightf(light: GLenum, pname: GLenum, v: GLfloat) => |c| { c.gl.lightf(light, pname, v) }
    [list] fn glLighti(light: GLenum, pname: GLenum, v: GLint) => |c| { c.gl.lighti(light, pname, v) }
    fn glLightfv(light: GLenum, pname: GLenum, v: *const GLfloat) => |c| {
        let n = match pname {
            GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_POSITION => 4,
            GL_SPOT_DIRECTION => 3,
            _ => 1,
        };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glLightfv(light, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.lightfv(light, pname, &rd_vec(v, n)) }
    }
    [list] fn glMaterialf(face: GLenum, pname: GLenum, v: GLfloat) => |c| { c.gl.materialf(face, pname, v) }
    [list] fn glMateriali(face: GLenum, pname: GLenum, v: GLint) => |c| { c.gl.materiali(face, pname, v) }
    fn glMaterialfv(face: GLenum, pname: GLenum, v: *const GLfloat) => |c| {
        let n = match pname {
            GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE => 4,
            GL_COLOR_INDEXES => 3,
            _ => 1,
        };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glMaterialfv(face, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.materialfv(face, pname, &rd_vec(v, n)) }
    }
    [list] fn glColorMaterial(face: GLenum, mode: GLenum) => |c| { c.gl.color_material(face, mode) }
    [list] fn glLightModelf(pname: GLenum, v: GLfloat) => |c| { c.gl.light_modelf(pname, v) }
    [list] fn glLightModeli(pname: GLenum, v: GLint) => |c| { c.gl.light_modeli(pname, v) }
    fn glLightModelfv(pname: GLenum, v: *const GLfloat) => |c| {
        let n = if pname == GL_LIGHT_MODEL_AMBIENT { 4 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glLightModelfv(pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.light_modelfv(pname, &rd_vec(v, n)) }
    }
    [list] fn glFogf(pname: GLenum, v: GLfloat) => |c| { c.gl.fogf(pname, v) }
    [list] fn glFogi(pname: GLenum, v: GLint) => |c| { c.gl.fogi(pname, v) }
    fn glFogfv(pname: GLenum, v: *const GLfloat) => |c| {
        let n = if pname == GL_FOG_COLOR { 4 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glFogfv(pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.fogfv(pname, &rd_vec(v, n)) }
    }
    fn glFogiv(pname: GLenum, v: *const GLint) => |c| {
        let n = if pname == GL_FOG_COLOR { 4 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glFogiv(pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.fogiv(pname, &rd_vec(v, n)) }
    }

    // ---- shaders and programs ----
    fn glCreateShader(kind: GLenum) -> GLuint [0] => |c| { c.gl.create_shader(kind) }
    fn glShaderSource(
        shader: GLuint, count: GLsizei, strings: *const *const GLchar, lengths: *const GLint
    ) => |c| {
        if count < 0 || (count > 0 && strings.is_null()) {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        let mut parts = Vec::with_capacity(count as usize);
        for i in 0..count as usize {
            let s = *strings.add(i);
            let len = if lengths.is_null() { -1 } else { *lengths.add(i) };
            let text = if s.is_null() {
                String::new()
            } else if len < 0 {
                CStr::from_ptr(s).to_string_lossy().into_owned()
            } else {
                String::from_utf8_lossy(bytes(s, len as usize)).into_owned()
            };
            parts.push(text);
        }
        let refs: Vec<&str> = parts.iter().map(|s| s.as_str()).collect();
        c.gl.shader_source(shader, &refs);
    }
    fn glCompileShader(shader: GLuint) => |c| { c.gl.compile_shader(shader) }
    fn glDeleteShader(shader: GLuint) => |c| { c.gl.delete_shader(shader) }
    fn glIsShader(shader: GLuint) -> GLboolean [0] => |c| { c.gl.is_shader(shader) as GLboolean }
    fn glGetShaderiv(shader: GLuint, pname: GLenum, params: *mut GLint) => |c| {
        let v = c.gl.get_shaderiv(shader, pname);
        wr(params, &[v]);
    }
    fn glGetShaderInfoLog(
        shader: GLuint, buf_size: GLsizei, length: *mut GLsizei, log: *mut GLchar
    ) => |c| {
        let s = c.gl.get_shader_info_log(shader);
        wr_string(c, &s, buf_size, length, log);
    }
    fn glGetShaderSource(
        shader: GLuint, buf_size: GLsizei, length: *mut GLsizei, source: *mut GLchar
    ) => |c| {
        let s = c.gl.get_shader_source(shader);
        wr_string(c, &s, buf_size, length, source);
    }
    fn glCreateProgram() -> GLuint [0] => |c| { c.gl.create_program() }
    fn glDeleteProgram(program: GLuint) => |c| { c.gl.delete_program(program) }
    fn glIsProgram(program: GLuint) -> GLboolean [0] => |c| {
        c.gl.is_program(program) as GLboolean
    }
    fn glAttachShader(program: GLuint, shader: GLuint) => |c| { c.gl.attach_shader(program, shader) }
    fn glDetachShader(program: GLuint, shader: GLuint) => |c| { c.gl.detach_shader(program, shader) }
    fn glLinkProgram(program: GLuint) => |c| { c.gl.link_program(program) }
    fn glValidateProgram(program: GLuint) => |c| { c.gl.validate_program(program) }
    [list] fn glUseProgram(program: GLuint) => |c| { c.gl.use_program(program) }
    fn glGetProgramiv(program: GLuint, pname: GLenum, params: *mut GLint) => |c| {
        let v = c.gl.get_programiv(program, pname);
        wr(params, &[v]);
    }
    fn glGetProgramInfoLog(
        program: GLuint, buf_size: GLsizei, length: *mut GLsizei, log: *mut GLchar
    ) => |c| {
        let s = c.gl.get_program_info_log(program);
        wr_string(c, &s, buf_size, length, log);
    }
    fn glGetUniformLocation(program: GLuint, name: *const GLchar) -> GLint [-1] => |c| {
        match cstr(name) {
            Some(n) => c.gl.get_uniform_location(program, &n),
            None => -1,
        }
    }
    fn glGetAttribLocation(program: GLuint, name: *const GLchar) -> GLint [-1] => |c| {
        match cstr(name) {
            Some(n) => c.gl.get_attrib_location(program, &n),
            None => -1,
        }
    }
    fn glBindAttribLocation(program: GLuint, index: GLuint, name: *const GLchar) => |c| {
        if let Some(n) = cstr(name) { c.gl.bind_attrib_location(program, index, &n) }
    }
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
    fn glUniform1fv(loc: GLint, count: GLsizei, v: *const GLfloat) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_1fv(loc, n, &rd_vec(v, n as i64));
    }
    fn glUniform2fv(loc: GLint, count: GLsizei, v: *const GLfloat) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_2fv(loc, n, &rd_vec(v, n as i64 * 2));
    }
    fn glUniform3fv(loc: GLint, count: GLsizei, v: *const GLfloat) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_3fv(loc, n, &rd_vec(v, n as i64 * 3));
    }
    fn glUniform4fv(loc: GLint, count: GLsizei, v: *const GLfloat) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_4fv(loc, n, &rd_vec(v, n as i64 * 4));
    }
    fn glUniform1iv(loc: GLint, count: GLsizei, v: *const GLint) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_1iv(loc, n, &rd_vec(v, n as i64));
    }
    fn glUniform2iv(loc: GLint, count: GLsizei, v: *const GLint) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_2iv(loc, n, &rd_vec(v, n as i64 * 2));
    }
    fn glUniform3iv(loc: GLint, count: GLsizei, v: *const GLint) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_3iv(loc, n, &rd_vec(v, n as i64 * 3));
    }
    fn glUniform4iv(loc: GLint, count: GLsizei, v: *const GLint) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_4iv(loc, n, &rd_vec(v, n as i64 * 4));
    }
    fn glUniformMatrix2fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_matrix_2fv(loc, n, as_bool(transpose), &rd_vec(v, n as i64 * 4));
    }
    fn glUniformMatrix3fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_matrix_3fv(loc, n, as_bool(transpose), &rd_vec(v, n as i64 * 9));
    }
    fn glUniformMatrix4fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_matrix_4fv(loc, n, as_bool(transpose), &rd_vec(v, n as i64 * 16));
    }

    // ---- more state ----
    [list] fn glBlendFuncSeparate(sr: GLenum, dr: GLenum, sa: GLenum, da: GLenum) => |c| {
        c.gl.blend_func_separate(sr, dr, sa, da)
    }
    [list] fn glBlendEquationSeparate(rgb: GLenum, alpha: GLenum) => |c| {
        c.gl.blend_equation_separate(rgb, alpha)
    }
    [list] fn glBlendColor(r: GLclampf, g: GLclampf, bl: GLclampf, a: GLclampf) => |c| {
        c.gl.blend_color(r, g, bl, a)
    }
    [list] fn glLogicOp(op: GLenum) => |c| { c.gl.logic_op(op) }
    [list] fn glStencilFunc(func: GLenum, reference: GLint, mask: GLuint) => |c| {
        c.gl.stencil_func(func, reference, mask)
    }
    [list] fn glStencilOp(fail: GLenum, zfail: GLenum, zpass: GLenum) => |c| { c.gl.stencil_op(fail, zfail, zpass) }
    [list] fn glStencilMask(mask: GLuint) => |c| { c.gl.stencil_mask(mask) }
    [list] fn glStencilFuncSeparate(face: GLenum, func: GLenum, reference: GLint, mask: GLuint) => |c| {
        c.gl.stencil_func_separate(face, func, reference, mask)
    }
    [list] fn glStencilOpSeparate(face: GLenum, fail: GLenum, zfail: GLenum, zpass: GLenum) => |c| {
        c.gl.stencil_op_separate(face, fail, zfail, zpass)
    }
    [list] fn glStencilMaskSeparate(face: GLenum, mask: GLuint) => |c| { c.gl.stencil_mask_separate(face, mask) }
    fn glClipPlane(plane: GLenum, eq: *const GLdouble) => |c| {
        if record_vector::<4, f64>(c, eq, move |p| unsafe { glClipPlane(plane, p) }) {
            return;
        }
        if let Some(e) = rd::<4, f64>(eq) { c.gl.clip_plane(plane, &e) }
    }
    fn glGetClipPlane(plane: GLenum, eq: *mut GLdouble) => |c| {
        let e = c.gl.get_clip_plane(plane);
        wr(eq, &e);
    }
    fn glLoadTransposeMatrixf(m: *const GLfloat) => |c| {
        if record_vector::<16, f32>(c, m, move |p| unsafe { glLoadTransposeMatrixf(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f32>(m) { c.gl.load_transpose_matrixf(&m) }
    }
    fn glMultTransposeMatrixf(m: *const GLfloat) => |c| {
        if record_vector::<16, f32>(c, m, move |p| unsafe { glMultTransposeMatrixf(p) }) {
            return;
        }
        if let Some(m) = rd::<16, f32>(m) { c.gl.mult_transpose_matrixf(&m) }
    }
    [list] fn glPointParameterf(pname: GLenum, v: GLfloat) => |c| { c.gl.point_parameterf(pname, v) }
    [list] fn glPointParameteri(pname: GLenum, v: GLint) => |c| { c.gl.point_parameteri(pname, v) }
    fn glPointParameterfv(pname: GLenum, v: *const GLfloat) => |c| {
        let n = if pname == GL_POINT_DISTANCE_ATTENUATION { 3 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glPointParameterfv(pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.point_parameterfv(pname, &rd_vec(v, n)) }
    }
    fn glGetLightfv(light: GLenum, pname: GLenum, v: *mut GLfloat) => |c| {
        let r = c.gl.get_lightfv(light, pname);
        wr(v, &r);
    }
    fn glGetMaterialfv(face: GLenum, pname: GLenum, v: *mut GLfloat) => |c| {
        let r = c.gl.get_materialfv(face, pname);
        wr(v, &r);
    }
    fn glLightiv(light: GLenum, pname: GLenum, v: *const GLint) => |c| {
        let n = match pname {
            GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_POSITION => 4,
            GL_SPOT_DIRECTION => 3,
            _ => 1,
        };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glLightiv(light, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.lightiv(light, pname, &rd_vec(v, n)) }
    }
    fn glMaterialiv(face: GLenum, pname: GLenum, v: *const GLint) => |c| {
        let n = match pname {
            GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE => 4,
            GL_COLOR_INDEXES => 3,
            _ => 1,
        };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glMaterialiv(face, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.materialiv(face, pname, &rd_vec(v, n)) }
    }
    fn glLightModeliv(pname: GLenum, v: *const GLint) => |c| {
        let n = if pname == GL_LIGHT_MODEL_AMBIENT { 4 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glLightModeliv(pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.light_modeliv(pname, &rd_vec(v, n)) }
    }
    [list] fn glTexEnvi(target: GLenum, pname: GLenum, v: GLint) => |c| { c.gl.tex_envi(target, pname, v) }
    [list] fn glTexEnvf(target: GLenum, pname: GLenum, v: GLfloat) => |c| { c.gl.tex_envf(target, pname, v) }
    fn glTexEnvfv(target: GLenum, pname: GLenum, v: *const GLfloat) => |c| {
        let n = if pname == GL_TEXTURE_ENV_COLOR { 4 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glTexEnvfv(target, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.tex_envfv(target, pname, &rd_vec(v, n)) }
    }
    fn glTexEnviv(target: GLenum, pname: GLenum, v: *const GLint) => |c| {
        let n = if pname == GL_TEXTURE_ENV_COLOR { 4 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glTexEnviv(target, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.tex_enviv(target, pname, &rd_vec(v, n)) }
    }
    [list] fn glTexGeni(coord: GLenum, pname: GLenum, v: GLint) => |c| { c.gl.tex_geni(coord, pname, v) }
    [list] fn glTexGenf(coord: GLenum, pname: GLenum, v: GLfloat) => |c| { c.gl.tex_genf(coord, pname, v) }
    fn glTexGenfv(coord: GLenum, pname: GLenum, v: *const GLfloat) => |c| {
        let n = if pname == GL_TEXTURE_GEN_MODE { 1 } else { 4 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glTexGenfv(coord, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.tex_genfv(coord, pname, &rd_vec(v, n)) }
    }

    // ---- textures ----
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
    [list] fn glTexParameteri(target: GLenum, pname: GLenum, v: GLint) => |c| { c.gl.tex_parameteri(target, pname, v) }
    [list] fn glTexParameterf(target: GLenum, pname: GLenum, v: GLfloat) => |c| { c.gl.tex_parameterf(target, pname, v) }
    fn glTexParameterfv(target: GLenum, pname: GLenum, v: *const GLfloat) => |c| {
        let n = if pname == GL_TEXTURE_BORDER_COLOR { 4 } else { 1 };
        if c.compiling() && !v.is_null() {
            let arr = rd_vec(v, n);
            if c.record(move || unsafe { glTexParameterfv(target, pname, arr.as_ptr()) }) {
                return;
            }
        }
        if !v.is_null() { c.gl.tex_parameterfv(target, pname, &rd_vec(v, n)) }
    }
    fn glTexParameteriv(target: GLenum, pname: GLenum, v: *const GLint) => |c| {
        if pname == GL_TEXTURE_BORDER_COLOR {
            let f: Vec<f32> = rd_vec(v, 4).iter().map(|&x| gl::state::int_to_unit(x)).collect();
            if !v.is_null() { c.gl.tex_parameterfv(target, pname, &f) }
        } else if let Some([x]) = rd::<1, i32>(v) {
            c.gl.tex_parameteri(target, pname, x)
        }
    }
    fn glGetTexParameteriv(target: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        let r = c.gl.get_tex_parameteriv(target, pname);
        wr(v, &[r]);
    }
    fn glGetTexLevelParameteriv(target: GLenum, level: GLint, pname: GLenum, v: *mut GLint) => |c| {
        let r = c.gl.get_tex_level_parameteriv(target, level, pname);
        wr(v, &[r]);
    }
    fn glTexImage1D(
        target: GLenum, level: GLint, internal: GLint, w: GLsizei, border: GLint,
        format: GLenum, ty: GLenum, data: *const c_void
    ) => |c| {
        let Ok(bytes) = image_bytes(c, w, 1, 1, format, ty, data) else { return };
        c.gl.tex_image_1d(target, level, internal, w, border, format, ty, bytes.as_deref());
    }
    fn glTexImage2D(
        target: GLenum, level: GLint, internal: GLint, w: GLsizei, h: GLsizei, border: GLint,
        format: GLenum, ty: GLenum, data: *const c_void
    ) => |c| {
        let Ok(bytes) = image_bytes(c, w, h, 1, format, ty, data) else { return };
        c.gl.tex_image_2d(target, level, internal, w, h, border, format, ty, bytes.as_deref());
    }
    fn glTexImage3D(
        target: GLenum, level: GLint, internal: GLint, w: GLsizei, h: GLsizei, d: GLsizei,
        border: GLint, format: GLenum, ty: GLenum, data: *const c_void
    ) => |c| {
        let Ok(bytes) = image_bytes(c, w, h, d, format, ty, data) else { return };
        c.gl.tex_image_3d(target, level, internal, w, h, d, border, format, ty, bytes.as_deref());
    }
    fn glTexSubImage2D(
        target: GLenum, level: GLint, xoff: GLint, yoff: GLint, w: GLsizei, h: GLsizei,
        format: GLenum, ty: GLenum, data: *const c_void
    ) => |c| {
        let Ok(bytes) = image_bytes(c, w, h, 1, format, ty, data) else { return };
        let bytes = bytes.unwrap_or_default();
        c.gl.tex_sub_image_2d(target, level, xoff, yoff, w, h, format, ty, &bytes);
    }
    fn glGenerateMipmap(target: GLenum) => |c| { c.gl.generate_mipmap(target) }
    fn glGenerateMipmapEXT(target: GLenum) => |c| { c.gl.generate_mipmap_ext(target) }

    // ---- buffer objects ----
    fn glGenBuffers(n: GLsizei, names: *mut GLuint) => |c| {
        let v = c.gl.gen_buffers(n);
        wr(names, &v);
    }
    fn glDeleteBuffers(n: GLsizei, names: *const GLuint) => |c| {
        if n < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        if !c.gl.reject_in_begin() { crate::buffers::forget_mappings(c, &rd_vec(names, n as i64)) }
        c.gl.delete_buffers(&rd_vec(names, n as i64));
    }
    fn glIsBuffer(name: GLuint) -> GLboolean [0] => |c| { c.gl.is_buffer(name) as GLboolean }
    fn glBindBuffer(target: GLenum, name: GLuint) => |c| { c.gl.bind_buffer(target, name) }
    fn glBufferData(target: GLenum, size: GLsizeiptr, data: *const c_void, usage: GLenum) => |c| {
        // Re-specifying the store ends a mapping (not an error, GL 2.1 §2.9).
        let b = c.gl.bound_buffer(target);
        if !c.gl.in_begin_end() { c.mapped.remove(&b); }
        let bytes = if data.is_null() || size <= 0 || size as usize > MAX_BUFFER_BYTES {
            None
        } else {
            // SAFETY: GL's contract: `size` bytes at `data`.
            Some(bytes(data, size as usize))
        };
        c.gl.buffer_data(target, size, bytes, usage);
    }
    fn glBufferSubData(target: GLenum, offset: GLintptr, size: GLsizeiptr, data: *const c_void) => |c| {
        if !c.gl.in_begin_end() && c.mapped.contains_key(&c.gl.bound_buffer(target)) {
            c.gl.record_error(GL_INVALID_OPERATION);
            return;
        }
        if size < 0 || data.is_null() || size as usize > MAX_BUFFER_BYTES {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        // SAFETY: GL's contract: `size` bytes at `data`.
        c.gl.buffer_sub_data(target, offset, bytes(data, size as usize));
    }

    // ---- framebuffer objects ----
    fn glGenFramebuffers(n: GLsizei, names: *mut GLuint) => |c| {
        let v = c.gl.gen_framebuffers(n);
        wr(names, &v);
    }
    fn glGenFramebuffersEXT(n: GLsizei, names: *mut GLuint) => |c| {
        let v = c.gl.gen_framebuffers_ext(n);
        wr(names, &v);
    }
    fn glBindFramebuffer(target: GLenum, fb: GLuint) => |c| { c.gl.bind_framebuffer(target, fb) }
    fn glBindFramebufferEXT(target: GLenum, fb: GLuint) => |c| { c.gl.bind_framebuffer_ext(target, fb) }
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
        c.gl.check_framebuffer_status_ext(target)
    }
    fn glFramebufferTexture2D(
        target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint
    ) => |c| { c.gl.framebuffer_texture_2d(target, attachment, textarget, texture, level) }
    fn glFramebufferTexture2DEXT(
        target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint
    ) => |c| { c.gl.framebuffer_texture_2d_ext(target, attachment, textarget, texture, level) }
    fn glGenRenderbuffers(n: GLsizei, names: *mut GLuint) => |c| {
        let v = c.gl.gen_renderbuffers(n);
        wr(names, &v);
    }
    fn glGenRenderbuffersEXT(n: GLsizei, names: *mut GLuint) => |c| {
        let v = c.gl.gen_renderbuffers_ext(n);
        wr(names, &v);
    }
    fn glBindRenderbuffer(target: GLenum, rb: GLuint) => |c| { c.gl.bind_renderbuffer(target, rb) }
    fn glBindRenderbufferEXT(target: GLenum, rb: GLuint) => |c| { c.gl.bind_renderbuffer_ext(target, rb) }
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
        c.gl.renderbuffer_storage_ext(target, internal, w, h)
    }
    fn glFramebufferRenderbuffer(
        target: GLenum, attachment: GLenum, rbtarget: GLenum, rb: GLuint
    ) => |c| { c.gl.framebuffer_renderbuffer(target, attachment, rbtarget, rb) }
    fn glFramebufferRenderbufferEXT(
        target: GLenum, attachment: GLenum, rbtarget: GLenum, rb: GLuint
    ) => |c| { c.gl.framebuffer_renderbuffer_ext(target, attachment, rbtarget, rb) }
    [list] fn glDrawBuffer(buf: GLenum) => |c| { c.gl.draw_buffer(buf) }
    fn glDrawBuffers(n: GLsizei, bufs: *const GLenum) => |c| {
        if n < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        c.gl.draw_buffers(&rd_vec(bufs, (n as i64).min(64)));
    }
    [list] fn glReadBuffer(buf: GLenum) => |c| { c.gl.read_buffer(buf) }

    // ---- program queries ----
    fn glGetAttachedShaders(
        program: GLuint, max: GLsizei, count: *mut GLsizei, shaders: *mut GLuint
    ) => |c| {
        if max < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        let v = c.gl.get_attached_shaders(program);
        let n = v.len().min(max as usize);
        wr(shaders, &v[..n]);
        wr(count, &[n as GLsizei]);
    }
    fn glGetActiveUniform(
        program: GLuint, index: GLuint, buf_size: GLsizei, length: *mut GLsizei,
        size: *mut GLint, ty: *mut GLenum, name: *mut GLchar
    ) => |c| {
        if let Some(info) = c.gl.get_active_uniform(program, index) {
            wr(size, &[info.size]);
            wr(ty, &[info.ty]);
            wr_string(c, &info.name, buf_size, length, name);
        }
    }
    fn glGetActiveAttrib(
        program: GLuint, index: GLuint, buf_size: GLsizei, length: *mut GLsizei,
        size: *mut GLint, ty: *mut GLenum, name: *mut GLchar
    ) => |c| {
        if let Some(info) = c.gl.get_active_attrib(program, index) {
            wr(size, &[info.size]);
            wr(ty, &[info.ty]);
            wr_string(c, &info.name, buf_size, length, name);
        }
    }
    fn glGetUniformfv(program: GLuint, loc: GLint, v: *mut GLfloat) => |c| {
        let r = c.gl.get_uniformfv(program, loc);
        wr(v, &r);
    }
    fn glGetUniformiv(program: GLuint, loc: GLint, v: *mut GLint) => |c| {
        let r = c.gl.get_uniformiv(program, loc);
        wr(v, &r);
    }
    fn glGetVertexAttribfv(index: GLuint, pname: GLenum, v: *mut GLfloat) => |c| {
        if pname == GL_CURRENT_VERTEX_ATTRIB {
            let r = c.gl.get_current_vertex_attrib(index);
            wr(v, &r);
        } else {
            c.gl.record_error(GL_INVALID_ENUM);
        }
    }
    fn glUniformMatrix2x3fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_matrix_2x3fv(loc, n, as_bool(transpose), &rd_vec(v, n as i64 * 6));
    }
    fn glUniformMatrix3x2fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_matrix_3x2fv(loc, n, as_bool(transpose), &rd_vec(v, n as i64 * 6));
    }
    fn glUniformMatrix2x4fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_matrix_2x4fv(loc, n, as_bool(transpose), &rd_vec(v, n as i64 * 8));
    }
    fn glUniformMatrix4x2fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_matrix_4x2fv(loc, n, as_bool(transpose), &rd_vec(v, n as i64 * 8));
    }
    fn glUniformMatrix3x4fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_matrix_3x4fv(loc, n, as_bool(transpose), &rd_vec(v, n as i64 * 12));
    }
    fn glUniformMatrix4x3fv(loc: GLint, count: GLsizei, transpose: GLboolean, v: *const GLfloat) => |c| {
        let n = count.min(MAX_UNIFORM_ELEMENTS);
        c.gl.uniform_matrix_4x3fv(loc, n, as_bool(transpose), &rd_vec(v, n as i64 * 12));
    }
    fn glSecondaryColorPointer(size: GLint, ty: GLenum, stride: GLsizei, pointer: *const c_void) => |c| {
        c.arrays.set_pointer(&mut c.gl, AttribSource::SecondaryColor, pointer as *const u8, |g, d| {
            g.secondary_color_pointer(size, ty, stride, d)
        });
    }
    fn glFogCoordPointer(ty: GLenum, stride: GLsizei, pointer: *const c_void) => |c| {
        c.arrays.set_pointer(&mut c.gl, AttribSource::FogCoord, pointer as *const u8, |g, d| {
            g.fog_coord_pointer(ty, stride, d)
        });
    }
    fn glDrawRangeElements(
        mode: GLenum, start: GLuint, end: GLuint, count: GLsizei, ty: GLenum,
        indices: *const c_void
    ) => |c| {
        if c.compiling() {
            let idx = if end < start {
                Err(GL_INVALID_VALUE)
            } else {
                crate::array_draws::compiled_element_indices(c, count, ty, indices)
            };
            if crate::array_draws::compile_draw(c, mode, idx) {
                return;
            }
        }
        if end < start {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        if crate::buffers::sources_mapped(c, true) && !c.gl.in_begin_end() {
            c.gl.record_error(GL_INVALID_OPERATION);
            return;
        }
        let data = prepare_elements(c, count, ty, indices);
        c.gl.draw_range_elements(mode, start, end, count, ty, data);
        c.dirty = true;
    }
    fn glMultiDrawArrays(mode: GLenum, first: *const GLint, count: *const GLsizei, n: GLsizei) => |c| {
        if c.compiling() && n >= 0 {
            let f = rd_vec(first, n as i64);
            let k = rd_vec(count, n as i64);
            let mut skip = false;
            for (f, k) in f.iter().zip(&k) {
                skip = crate::array_draws::compile_draw(c, mode, crate::array_draws::array_indices(*f, *k));
            }
            if skip || n == 0 {
                return;
            }
        }
        if n < 0 { c.gl.record_error(GL_INVALID_VALUE); return; }
        if crate::buffers::sources_mapped(c, false) && !c.gl.in_begin_end() {
            c.gl.record_error(GL_INVALID_OPERATION);
            return;
        }
        let f = rd_vec(first, n as i64);
        let k = rd_vec(count, n as i64);
        for (f, k) in f.iter().zip(&k) {
            if *f >= 0 && *k > 0 {
                let last = (*f as i64 + (*k).min(1 << 24) as i64 - 1).min(u32::MAX as i64);
                c.arrays.prepare(&mut c.gl, *f as u32, last as u32);
            }
            c.gl.draw_arrays(mode, *f, *k);
        }
        c.dirty = true;
    }

    // ---- vertex arrays and draws ----
    fn glEnableClientState(cap: GLenum) => |c| { c.gl.enable_client_state(cap) }
    fn glDisableClientState(cap: GLenum) => |c| { c.gl.disable_client_state(cap) }
    fn glClientActiveTexture(unit: GLenum) => |c| { c.gl.client_active_texture(unit) }
    [list] fn glActiveTexture(unit: GLenum) => |c| { c.gl.active_texture(unit) }
    fn glEnableVertexAttribArray(index: GLuint) => |c| { c.gl.enable_vertex_attrib_array(index) }
    fn glDisableVertexAttribArray(index: GLuint) => |c| { c.gl.disable_vertex_attrib_array(index) }
    fn glVertexAttribPointer(
        index: GLuint, size: GLint, ty: GLenum, normalized: GLboolean, stride: GLsizei,
        pointer: *const c_void
    ) => |c| {
        let src = AttribSource::Generic(index.min(255) as u8);
        c.arrays.set_pointer(&mut c.gl, src, pointer as *const u8, |g, d| {
            g.vertex_attrib_pointer(index, size, ty, as_bool(normalized), stride, d)
        });
    }
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
    fn glNormalPointer(ty: GLenum, stride: GLsizei, pointer: *const c_void) => |c| {
        c.arrays.set_pointer(&mut c.gl, AttribSource::Normal, pointer as *const u8, |g, d| {
            g.normal_pointer(ty, stride, d)
        });
    }
    fn glTexCoordPointer(size: GLint, ty: GLenum, stride: GLsizei, pointer: *const c_void) => |c| {
        let unit = c.gl.vertex_state().client_active_texture.min(255) as u8;
        c.arrays.set_pointer(&mut c.gl, AttribSource::TexCoord(unit), pointer as *const u8, |g, d| {
            g.tex_coord_pointer(size, ty, stride, d)
        });
    }
    fn glDrawArrays(mode: GLenum, first: GLint, count: GLsizei) => |c| {
        if crate::buffers::sources_mapped(c, false) && !c.gl.in_begin_end() {
            c.gl.record_error(GL_INVALID_OPERATION);
            return;
        }
        if c.compiling()
            && crate::array_draws::compile_draw(c, mode, crate::array_draws::array_indices(first, count))
        {
            return;
        }
        if first >= 0 && count > 0 {
            let last = (first as i64 + count.min(1 << 24) as i64 - 1).min(u32::MAX as i64);
            c.arrays.prepare(&mut c.gl, first as u32, last as u32);
        }
        c.gl.draw_arrays(mode, first, count);
        c.dirty = true;
    }
    fn glDrawElements(mode: GLenum, count: GLsizei, ty: GLenum, indices: *const c_void) => |c| {
        if crate::buffers::sources_mapped(c, true) && !c.gl.in_begin_end() {
            c.gl.record_error(GL_INVALID_OPERATION);
            return;
        }
        if c.compiling() {
            let idx = crate::array_draws::compiled_element_indices(c, count, ty, indices);
            if crate::array_draws::compile_draw(c, mode, idx) {
                return;
            }
        }
        let data = prepare_elements(c, count, ty, indices);
        c.gl.draw_elements(mode, count, ty, data);
        c.dirty = true;
    }
}
