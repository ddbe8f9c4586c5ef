//! Buffer-object entry points (GL 3.3 §2.9, §6.1.8): the objects, the
//! indexed binding points, glCopyBufferSubData, mapping (the context
//! validates and records a mapping; this layer holds the copy of the range
//! the client edits, handing it back at glFlushMappedBufferRange and
//! glUnmapBuffer), the buffer queries, and the pixel buffer (PBO)
//! transfers glReadPixels / glTexImage* / glGetTexImage make through
//! GL_PIXEL_PACK_BUFFER and GL_PIXEL_UNPACK_BUFFER (GL 2.1 §4.3.5).

use crate::abi::*;
use crate::arrays::array_state;
use crate::context::{with_ctx, OsContext};
use crate::layer_state::Mapping;
use gl::enums::*;
use gl::vertex::AttribSource;
use std::ffi::c_void;

/// Largest glBufferData/glBufferSubData copy (larger: GL_OUT_OF_MEMORY
/// from the context, or GL_INVALID_VALUE).
pub(crate) const MAX_BUFFER_BYTES: usize = 1 << 31;

/// A failed transfer whose GL error has been recorded.
#[derive(Debug)]
pub struct Recorded;

/// The bytes `offset..offset + len` of the buffer bound to `target` (a
/// pixel buffer target) for an unpack. GL_INVALID_OPERATION when the range
/// lies outside the buffer or the buffer is mapped (GL 2.1 §4.3.5.2).
pub fn read_pixel_buffer(
    c: &mut OsContext,
    target: u32,
    offset: usize,
    len: usize,
) -> Result<Vec<u8>, Recorded> {
    let b = c.gl.bound_buffer(target);
    let size = c.gl.buffer_info(b).map_or(0, |i| i.0);
    if c.mapped.contains_key(&b) || offset.checked_add(len).is_none_or(|e| e > size) {
        c.gl.record_error(GL_INVALID_OPERATION);
        return Err(Recorded);
    }
    Ok(c.gl.get_buffer_sub_data(target, offset as isize, len as isize))
}

/// Writes `bytes` at `offset` into the GL_PIXEL_PACK_BUFFER (a pack);
/// GL_INVALID_OPERATION when it does not fit or the buffer is mapped.
pub fn write_pixel_buffer(c: &mut OsContext, offset: usize, bytes: &[u8]) {
    let b = c.gl.bound_buffer(GL_PIXEL_PACK_BUFFER);
    let size = c.gl.buffer_info(b).map_or(0, |i| i.0);
    if c.mapped.contains_key(&b) || offset.checked_add(bytes.len()).is_none_or(|e| e > size) {
        c.gl.record_error(GL_INVALID_OPERATION);
        return;
    }
    c.gl.buffer_sub_data(GL_PIXEL_PACK_BUFFER, offset as isize, bytes);
}

/// The client image a glTexImage*/glTexSubImage*/glDrawPixels call reads:
/// `w*h*d` pixels of `format`/`ty` laid out per the unpack modes
/// (glPixelStore; `volume`: a three-dimensional image, which the image
/// modes apply to), from client memory or, with a buffer bound to
/// GL_PIXEL_UNPACK_BUFFER, from that buffer at the offset `data` (GL 2.1
/// §4.3.5); returned in the packed layout the context takes
/// ([`gl::pixel_store`]). Ok(None): no data (null pointer, an unknown
/// format/type or an empty image: the context validates those). Err: an
/// error was recorded (the range read lies outside the buffer, or the
/// buffer is mapped: GL_INVALID_OPERATION); the call must do nothing.
#[allow(clippy::too_many_arguments)]
pub(crate) unsafe fn image_bytes(
    c: &mut OsContext,
    w: GLsizei,
    h: GLsizei,
    d: GLsizei,
    volume: bool,
    format: GLenum,
    ty: GLenum,
    data: *const c_void,
) -> Result<Option<Vec<u8>>, crate::buffers::Recorded> {
    let pbo = c.gl.bound_buffer(GL_PIXEL_UNPACK_BUFFER);
    if (data.is_null() && pbo == 0) || w <= 0 || h <= 0 || d <= 0 {
        return Ok(None);
    }
    let store = c.gl.unpack_modes();
    let dims = [w as usize, h as usize, d as usize];
    let Some(len) = store.image_extent(dims, volume, format, ty) else {
        return Ok(None);
    };
    if len > MAX_BUFFER_BYTES {
        return Ok(None);
    }
    let raw = if pbo != 0 {
        crate::buffers::read_pixel_buffer(c, GL_PIXEL_UNPACK_BUFFER, data as usize, len)?
    } else {
        // SAFETY: GL's contract: the client image's pixels, laid out per
        // the unpack modes, lie within `len` bytes of `data`.
        unsafe { bytes(data, len) }.to_vec()
    };
    Ok(Some(match store.is_packed() {
        true => raw,
        false => store.gather(&raw, dims, volume, format, ty),
    }))
}

/// Writes the packed image `packed` (`dims` pixels of `format`/`ty`, as
/// the context returns it) where a glReadPixels/glGetTexImage call puts
/// it: client memory at `pixels`, or the GL_PIXEL_PACK_BUFFER at that
/// offset, laid out per the pack modes (only the pixels' bytes change;
/// `volume`: a three-dimensional image). Records GL_INVALID_OPERATION when
/// the range lies outside the buffer or the buffer is mapped.
pub(crate) unsafe fn pack_image(
    c: &mut OsContext,
    packed: &[u8],
    dims: [usize; 3],
    volume: bool,
    format: GLenum,
    ty: GLenum,
    pixels: *mut c_void,
) {
    let store = c.gl.pack_modes();
    let pbo = c.gl.bound_buffer(GL_PIXEL_PACK_BUFFER) != 0;
    if store.is_packed() {
        if pbo {
            write_pixel_buffer(c, pixels as usize, packed);
        } else if !pixels.is_null() {
            // SAFETY: GL's contract: the client's buffer holds the packed
            // image of format/type at the pack alignment.
            unsafe {
                std::ptr::copy_nonoverlapping(packed.as_ptr(), pixels as *mut u8, packed.len())
            };
        }
        return;
    }
    let Some(len) = store.image_extent(dims, volume, format, ty) else {
        return;
    };
    if pbo {
        // The buffer's bytes between the pixels keep their values.
        let Ok(mut range) = read_pixel_buffer(c, GL_PIXEL_PACK_BUFFER, pixels as usize, len) else {
            return;
        };
        store.scatter(packed, &mut range, dims, volume, format, ty);
        write_pixel_buffer(c, pixels as usize, &range);
    } else if !pixels.is_null() {
        // SAFETY: GL's contract: the client image's pixels, laid out per
        // the pack modes, lie within `len` bytes of `pixels`.
        let dst = unsafe { std::slice::from_raw_parts_mut(pixels as *mut u8, len) };
        store.scatter(packed, dst, dims, volume, format, ty);
    }
}

/// Whether a draw would source data from a mapped buffer (enabled arrays
/// and the element buffer): GL_INVALID_OPERATION (GL 2.1 §2.9.1).
pub fn sources_mapped(c: &OsContext, elements: bool) -> bool {
    if c.mapped.is_empty() {
        return false;
    }
    let va = c.gl.vertex_state();
    if elements && c.mapped.contains_key(&va.element_buffer) {
        return true;
    }
    let mut srcs = vec![
        AttribSource::Position,
        AttribSource::Color,
        AttribSource::SecondaryColor,
        AttribSource::Normal,
        AttribSource::FogCoord,
    ];
    srcs.extend((0..va.tex_arrays.len()).map(|u| AttribSource::TexCoord(u as u8)));
    srcs.extend((0..va.generic_arrays.len()).map(|i| AttribSource::Generic(i as u8)));
    srcs.into_iter().any(|s| {
        array_state(va, s)
            .is_some_and(|a| a.enabled && a.buffer != 0 && c.mapped.contains_key(&a.buffer))
    })
}

/// The buffer bound to a buffer target, GL_INVALID_ENUM for another
/// target and GL_INVALID_OPERATION for none bound.
fn bound(c: &mut OsContext, target: u32) -> Option<u32> {
    if !gl::Context::is_buffer_target(target) {
        c.gl.record_error(GL_INVALID_ENUM);
        return None;
    }
    let b = c.gl.bound_buffer(target);
    if b == 0 {
        c.gl.record_error(GL_INVALID_OPERATION);
        return None;
    }
    Some(b)
}

/// Hands the copy of a range the context just mapped to the client: kept
/// in [`OsContext::mapped`] until unmapped.
fn hand_out(c: &mut OsContext, target: u32, bytes: Option<Vec<u8>>) -> *mut c_void {
    let Some(bytes) = bytes else {
        return std::ptr::null_mut();
    };
    let b = c.gl.bound_buffer(target);
    let access = c.gl.buffer_mapping(b).map_or(0, |m| m.access);
    // A fresh copy always: the context just started this mapping.
    let data = bytes.into_boxed_slice();
    c.mapped.insert(b, Mapping { data, access });
    c.mapped
        .get_mut(&b)
        .map_or(std::ptr::null_mut(), map_pointer)
}

/// The client's pointer to a mapping.
fn map_pointer(m: &mut Mapping) -> *mut c_void {
    if m.data.is_empty() {
        // An empty range: a valid, unique, never-dereferenced pointer.
        return std::ptr::NonNull::<u8>::dangling().as_ptr() as *mut c_void;
    }
    m.data.as_mut_ptr() as *mut c_void
}

gl_entry_points! {
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
        if size < 0 || data.is_null() || size as usize > MAX_BUFFER_BYTES {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        // SAFETY: GL's contract: `size` bytes at `data`.
        c.gl.buffer_sub_data(target, offset, bytes(data, size as usize));
    }

    // ---- mapping and queries ----
    fn glMapBuffer(target: GLenum, access: GLenum) -> *mut c_void [std::ptr::null_mut()] => |c| {
        let bytes = c.gl.map_buffer(target, access);
        hand_out(c, target, bytes)
    }
    fn glMapBufferRange(
        target: GLenum, offset: GLintptr, length: GLsizeiptr, access: GLbitfield
    ) -> *mut c_void [std::ptr::null_mut()] => |c| {
        let bytes = c.gl.map_buffer_range(target, offset, length, access);
        hand_out(c, target, bytes)
    }
    fn glFlushMappedBufferRange(target: GLenum, offset: GLintptr, length: GLsizeiptr) => |c| {
        let b = c.gl.bound_buffer(target);
        let data = c.mapped.get(&b).map_or(&[][..], |m| &m.data[..]);
        c.gl.flush_mapped_buffer_range(target, offset, length, data);
    }
    fn glUnmapBuffer(target: GLenum) -> GLboolean [0] => |c| {
        let b = c.gl.bound_buffer(target);
        let data = if c.gl.buffer_mapping(b).is_some() && !c.gl.in_begin_end() {
            c.mapped.remove(&b).map(|m| m.data)
        } else {
            None
        };
        c.gl.unmap_buffer(target, data.as_deref().unwrap_or(&[])) as GLboolean
    }
    fn glGetBufferParameteriv(target: GLenum, pname: GLenum, v: *mut GLint) => |c| {
        if let Some(r) = c.gl.get_buffer_parameter(target, pname) {
            wr(v, &[r.clamp(i32::MIN as i64, i32::MAX as i64) as GLint]);
        }
    }
    fn glGetBufferParameteri64v(target: GLenum, pname: GLenum, v: *mut i64) => |c| {
        if let Some(r) = c.gl.get_buffer_parameter(target, pname) {
            wr(v, &[r]);
        }
    }
    fn glGetBufferPointerv(target: GLenum, pname: GLenum, v: *mut *mut c_void) => |c| {
        if c.gl.reject_in_begin() {
            return;
        }
        let Some(b) = bound(c, target) else { return };
        if pname != GL_BUFFER_MAP_POINTER {
            c.gl.record_error(GL_INVALID_ENUM);
            return;
        }
        let p = match c.mapped.get_mut(&b) {
            Some(m) if !m.data.is_empty() => m.data.as_mut_ptr() as *mut c_void,
            Some(_) => std::ptr::NonNull::<u8>::dangling().as_ptr() as *mut c_void,
            None => std::ptr::null_mut(),
        };
        wr(v, &[p]);
    }
    fn glCopyBufferSubData(
        read_target: GLenum, write_target: GLenum, read_offset: GLintptr,
        write_offset: GLintptr, size: GLsizeiptr
    ) => |c| {
        c.gl.copy_buffer_sub_data(read_target, write_target, read_offset, write_offset, size)
    }

    // ---- indexed binding points (GL 3.0, 3.1) ----
    fn glBindBufferRange(
        target: GLenum, index: GLuint, buffer: GLuint, offset: GLintptr, size: GLsizeiptr
    ) => |c| { c.gl.bind_buffer_range(target, index, buffer, offset, size) }
    fn glBindBufferBase(target: GLenum, index: GLuint, buffer: GLuint) => |c| {
        c.gl.bind_buffer_base(target, index, buffer)
    }
    // The indexed buffer bindings and the per-draw-buffer GL_BLEND /
    // GL_COLOR_WRITEMASK ([`gl::Context::get_indexed`]).
    fn glGetIntegeri_v(pname: GLenum, index: GLuint, v: *mut GLint) => |c| {
        if let Some(r) = c.gl.get_indexed(pname, index) {
            let r: Vec<GLint> = r.iter().map(|&x| x.clamp(i32::MIN as i64, i32::MAX as i64) as GLint).collect();
            wr(v, &r)
        }
    }
    fn glGetInteger64i_v(pname: GLenum, index: GLuint, v: *mut i64) => |c| {
        if let Some(r) = c.gl.get_indexed(pname, index) { wr(v, &r) }
    }
    fn glGetBooleani_v(pname: GLenum, index: GLuint, v: *mut GLboolean) => |c| {
        if let Some(r) = c.gl.get_indexed(pname, index) {
            let r: Vec<GLboolean> = r.iter().map(|&x| (x != 0) as GLboolean).collect();
            wr(v, &r)
        }
    }

    fn glGetBufferSubData(target: GLenum, offset: GLintptr, size: GLsizeiptr, data: *mut c_void) => |c| {
        if c.gl.reject_in_begin() {
            return;
        }
        let Some(b) = bound(c, target) else { return };
        if c.mapped.contains_key(&b) {
            c.gl.record_error(GL_INVALID_OPERATION);
            return;
        }
        let bytes = c.gl.get_buffer_sub_data(target, offset, size);
        if !data.is_null() && !bytes.is_empty() {
            // SAFETY: GL's contract: `size` bytes at `data` (bytes.len() ==
            // size when the context accepted the range).
            std::ptr::copy_nonoverlapping(bytes.as_ptr(), data as *mut u8, bytes.len());
        }
    }
}

/// glDeleteBuffers: mappings of deleted buffers end (not an error).
pub fn forget_mappings(c: &mut OsContext, names: &[GLuint]) {
    for b in names {
        c.mapped.remove(b);
    }
}
