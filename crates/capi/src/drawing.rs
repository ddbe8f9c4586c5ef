//! Drawing (GL 2.1 §2.6, §2.8; GL 3.3 §2.8.1-2.8.3): glBegin / glEnd,
//! the vertex-array draws (glDrawArrays, glDrawElements,
//! glDrawRangeElements, glMultiDraw*, the instanced and base-vertex
//! forms, glPrimitiveRestartIndex, glArrayElement), and their
//! compilation into display lists (not the instanced ones), which
//! dereferences the arrays when the list is compiled (§5.4). A draw copies
//! the client-memory vertices it reads first ([`crate::arrays`]), and one
//! that would read a mapped buffer raises GL_INVALID_OPERATION (§2.9).

use crate::abi::*;
use crate::context::{record_call, with_ctx, OsContext};
use gl::enums::*;
use gl::vertex::AttribSource;
use gl::ArrayData;
use std::ffi::c_void;
use std::sync::Arc;

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
    // SAFETY: the caller's.
    unsafe { prepare_elements_with(c, (count, ty, indices), 0, 1) }
}

/// [`prepare_elements`] for a base-vertex or instanced draw: the vertices
/// are the indices plus `basevertex` (primitive-restart indices are no
/// vertex), the instanced arrays' elements those `instances` read.
pub(crate) unsafe fn prepare_elements_with(
    c: &mut OsContext,
    (count, ty, indices): (GLsizei, GLenum, *const c_void),
    basevertex: GLint,
    instances: GLsizei,
) -> ArrayData {
    let read = c.arrays.reads_client_memory(&c.gl);
    // SAFETY: the caller's.
    let (data, idx) = unsafe { element_source(c, count, ty, indices, read) };
    let restart = c.gl.primitive_restart();
    let vertices = idx
        .iter()
        .filter(|&&i| Some(i) != restart)
        .map(|&i| i.wrapping_add(basevertex as u32));
    let (lo, hi) = vertices.fold((u32::MAX, None), |(lo, hi), i| {
        (lo.min(i), Some(hi.map_or(i, |h: u32| h.max(i))))
    });
    if let Some(hi) = hi {
        c.arrays
            .prepare_instanced(&mut c.gl, lo, hi, instances.max(0) as u32);
    }
    data
}

/// glDrawElementsInstancedBaseVertex (glDrawElementsInstanced with
/// `basevertex` 0).
unsafe fn draw_elements_instanced(
    c: &mut OsContext,
    mode: GLenum,
    elements: (GLsizei, GLenum, *const c_void),
    instances: GLsizei,
    basevertex: GLint,
) {
    if refuse_in_list(c) {
        return;
    }
    if crate::buffers::sources_mapped(c, true) && !c.gl.in_begin_end() {
        c.gl.record_error(GL_INVALID_OPERATION);
        return;
    }
    // SAFETY: the caller's (GL's contract for the index pointer).
    let data = unsafe { prepare_elements_with(c, elements, basevertex, instances) };
    let (count, ty, _) = elements;
    c.gl.draw_elements_instanced_base_vertex(mode, count, ty, data, instances, basevertex);
    c.dirty = true;
}

/// The instanced draws are not compiled into display lists: compiling
/// one is GL_INVALID_OPERATION and it does not execute (as Mesa does).
fn refuse_in_list(c: &mut OsContext) -> bool {
    if c.compiling() {
        c.gl.record_error(GL_INVALID_OPERATION);
        return true;
    }
    false
}

/// The attribute values array element `i` gives, position last (None for
/// the position when neither the vertex array nor generic array 0 is
/// enabled: then no vertex is emitted).
fn element_values(c: &mut OsContext, i: u32) -> Vec<(AttribSource, [f32; 4])> {
    c.arrays.prepare(&mut c.gl, i, i);
    let va = c.gl.vertex_state();
    let mut srcs: Vec<AttribSource> = (1..va.generic_arrays.len())
        .map(|g| AttribSource::Generic(g as u8))
        .collect();
    srcs.extend([
        AttribSource::SecondaryColor,
        AttribSource::FogCoord,
        AttribSource::Normal,
        AttribSource::Color,
    ]);
    srcs.extend((0..va.tex_arrays.len()).map(|u| AttribSource::TexCoord(u as u8)));
    srcs.push(AttribSource::Position);
    srcs.retain(|&s| va.array_for(s).is_some());
    srcs.into_iter()
        .map(|s| (s, c.gl.fetch_attrib(s, i)))
        .collect()
}

/// Issues the values as the immediate-mode calls (the position last).
fn apply(c: &mut OsContext, vals: &[(AttribSource, [f32; 4])]) {
    for &(s, [x, y, z, w]) in vals {
        match s {
            AttribSource::Generic(g) => c.gl.vertex_attrib_4f(g as u32, x, y, z, w),
            AttribSource::SecondaryColor => c.gl.secondary_color_3f(x, y, z),
            AttribSource::FogCoord => c.gl.fog_coordf(x),
            AttribSource::Normal => c.gl.normal_3f(x, y, z),
            AttribSource::Color => c.gl.color_4f(x, y, z, w),
            AttribSource::TexCoord(u) => {
                c.gl.multi_tex_coord_4f(GL_TEXTURE0 + u as u32, x, y, z, w)
            }
            AttribSource::Position => c.gl.vertex_4f(x, y, z, w),
        }
    }
}

/// The attribute values of one array element ([`element_values`]).
type ElementValues = Vec<(AttribSource, [f32; 4])>;

/// Most array elements one draw compiled into a display list may have
/// (more: GL_OUT_OF_MEMORY when the list runs).
pub const MAX_COMPILED_ELEMENTS: usize = 1 << 20;

/// Compiles a vertex-array draw into the display list being compiled
/// (GL 2.1 §5.4: array data is dereferenced at compile time): the
/// elements `indices` are fetched now, and the list replays them as
/// glBegin(mode), each element's attribute calls, glEnd. `Err(error)`:
/// the call is invalid; the list raises the error when it runs (as Mesa
/// does). True when the call must not also execute now (GL_COMPILE).
pub(crate) fn compile_draw(c: &mut OsContext, mode: u32, indices: Result<Vec<u32>, u32>) -> bool {
    let rec: Result<Vec<ElementValues>, u32> = match indices {
        Err(e) => Err(e),
        Ok(_) if mode > GL_POLYGON => Err(GL_INVALID_ENUM),
        Ok(idx) if idx.len() > MAX_COMPILED_ELEMENTS => Err(GL_OUT_OF_MEMORY),
        Ok(idx) => Ok(idx.iter().map(|&i| element_values(c, i)).collect()),
    };
    c.record(move || {
        with_ctx((), |c| match &rec {
            Err(e) => {
                if !c.gl.reject_in_begin() {
                    c.gl.record_error(*e)
                }
            }
            Ok(elements) => {
                if c.gl.reject_in_begin() || elements.is_empty() {
                    return;
                }
                c.gl.begin(mode);
                for vals in elements {
                    apply(c, vals);
                }
                c.gl.end();
                c.dirty = true;
            }
        })
    })
}

/// The indices glDrawArrays(first, count) draws, or its error.
pub(crate) fn array_indices(first: GLint, count: GLsizei) -> Result<Vec<u32>, u32> {
    if first < 0 || count < 0 {
        return Err(GL_INVALID_VALUE);
    }
    let n = (count as usize).min(MAX_COMPILED_ELEMENTS + 1) as u32;
    Ok((0..n).map(|i| (first as u32).saturating_add(i)).collect())
}

/// The indices glDrawElementsBaseVertex draws, or its error.
pub(crate) unsafe fn compiled_base_vertex_indices(
    c: &mut OsContext,
    count: GLsizei,
    ty: GLenum,
    indices: *const c_void,
    basevertex: GLint,
) -> Result<Vec<u32>, u32> {
    // SAFETY: the caller's.
    let idx = unsafe { compiled_element_indices(c, count, ty, indices) }?;
    Ok(idx
        .into_iter()
        .map(|i| i.wrapping_add(basevertex as u32))
        .collect())
}

/// The indices glDrawElements(count, ty, indices) draws, or its error.
pub(crate) unsafe fn compiled_element_indices(
    c: &mut OsContext,
    count: GLsizei,
    ty: GLenum,
    indices: *const c_void,
) -> Result<Vec<u32>, u32> {
    if !matches!(ty, GL_UNSIGNED_BYTE | GL_UNSIGNED_SHORT | GL_UNSIGNED_INT) {
        return Err(GL_INVALID_ENUM);
    }
    if count < 0 {
        return Err(GL_INVALID_VALUE);
    }
    // SAFETY: GL's contract for the index pointer, as for the draw.
    Ok(unsafe { element_source(c, count, ty, indices, true) }.1)
}

gl_entry_points! {
    // ---- begin / end ----
    [list] fn glBegin(mode: GLenum) => |c| { c.gl.begin(mode) }
    [list] fn glEnd() => |c| { c.gl.end(); c.dirty = true; }

    // ---- vertex-array draws ----
    fn glDrawArrays(mode: GLenum, first: GLint, count: GLsizei) => |c| {
        if crate::buffers::sources_mapped(c, false) && !c.gl.in_begin_end() {
            c.gl.record_error(GL_INVALID_OPERATION);
            return;
        }
        if c.compiling()
            && compile_draw(c, mode, array_indices(first, count))
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
            let idx = compiled_element_indices(c, count, ty, indices);
            if compile_draw(c, mode, idx) {
                return;
            }
        }
        let data = prepare_elements(c, count, ty, indices);
        c.gl.draw_elements(mode, count, ty, data);
        c.dirty = true;
    }
    fn glDrawRangeElements(
        mode: GLenum, start: GLuint, end: GLuint, count: GLsizei, ty: GLenum,
        indices: *const c_void
    ) => |c| {
        if c.compiling() {
            let idx = if end < start {
                Err(GL_INVALID_VALUE)
            } else {
                compiled_element_indices(c, count, ty, indices)
            };
            if compile_draw(c, mode, idx) {
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
                skip = compile_draw(c, mode, array_indices(*f, *k));
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
        // One negative count fails the whole call, before anything is drawn
        // (GL 2.1 §2.8: MultiDrawArrays is the DrawArrays loop, an error
        // leaves the framebuffer unchanged).
        if k.iter().any(|&k| k < 0) {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        for (f, k) in f.iter().zip(&k) {
            if *f >= 0 && *k > 0 {
                let last = (*f as i64 + (*k).min(1 << 24) as i64 - 1).min(u32::MAX as i64);
                c.arrays.prepare(&mut c.gl, *f as u32, last as u32);
            }
            c.gl.draw_arrays(mode, *f, *k);
        }
        c.dirty = true;
    }
    fn glMultiDrawElements(
        mode: GLenum, count: *const GLsizei, ty: GLenum, indices: *const *const c_void,
        primcount: GLsizei
    ) => |c| {
        if c.compiling() {
            if primcount < 0 {
                c.gl.record_error(GL_INVALID_VALUE);
                return;
            }
            let counts = rd_vec(count, primcount as i64);
            let ptrs = rd_vec(indices, primcount as i64);
            let mut skip = false;
            for (&k, &p) in counts.iter().zip(&ptrs) {
                let idx = compiled_element_indices(c, k, ty, p);
                skip = compile_draw(c, mode, idx);
            }
            if skip || primcount == 0 {
                return;
            }
        }
        if primcount < 0 {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        if crate::buffers::sources_mapped(c, true) && !c.gl.in_begin_end() {
            c.gl.record_error(GL_INVALID_OPERATION);
            return;
        }
        let counts = rd_vec(count, primcount as i64);
        let ptrs = rd_vec(indices, primcount as i64);
        if counts.iter().any(|&k| k < 0) {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        for (&k, &p) in counts.iter().zip(&ptrs) {
            let data = prepare_elements(c, k, ty, p);
            c.gl.draw_elements(mode, k, ty, data);
        }
        c.dirty = true;
    }
    // ---- GL 3.1-3.3 draws ----
    fn glDrawArraysInstanced(mode: GLenum, first: GLint, count: GLsizei, instances: GLsizei) => |c| {
        if refuse_in_list(c) {
            return;
        }
        if crate::buffers::sources_mapped(c, false) && !c.gl.in_begin_end() {
            c.gl.record_error(GL_INVALID_OPERATION);
            return;
        }
        if first >= 0 && count > 0 {
            let last = (first as i64 + count.min(1 << 24) as i64 - 1).min(u32::MAX as i64);
            c.arrays
                .prepare_instanced(&mut c.gl, first as u32, last as u32, instances.max(0) as u32);
        }
        c.gl.draw_arrays_instanced(mode, first, count, instances);
        c.dirty = true;
    }
    fn glDrawElementsInstanced(
        mode: GLenum, count: GLsizei, ty: GLenum, indices: *const c_void, instances: GLsizei
    ) => |c| {
        draw_elements_instanced(c, mode, (count, ty, indices), instances, 0);
    }
    fn glDrawElementsInstancedBaseVertex(
        mode: GLenum, count: GLsizei, ty: GLenum, indices: *const c_void, instances: GLsizei,
        basevertex: GLint
    ) => |c| {
        draw_elements_instanced(c, mode, (count, ty, indices), instances, basevertex);
    }
    fn glDrawElementsBaseVertex(
        mode: GLenum, count: GLsizei, ty: GLenum, indices: *const c_void, basevertex: GLint
    ) => |c| {
        if c.compiling() {
            let idx = compiled_base_vertex_indices(c, count, ty, indices, basevertex);
            if compile_draw(c, mode, idx) {
                return;
            }
        }
        if crate::buffers::sources_mapped(c, true) && !c.gl.in_begin_end() {
            c.gl.record_error(GL_INVALID_OPERATION);
            return;
        }
        let data = prepare_elements_with(c, (count, ty, indices), basevertex, 1);
        c.gl.draw_elements_base_vertex(mode, count, ty, data, basevertex);
        c.dirty = true;
    }
    fn glDrawRangeElementsBaseVertex(
        mode: GLenum, start: GLuint, end: GLuint, count: GLsizei, ty: GLenum,
        indices: *const c_void, basevertex: GLint
    ) => |c| {
        if c.compiling() {
            let idx = if end < start {
                Err(GL_INVALID_VALUE)
            } else {
                compiled_base_vertex_indices(c, count, ty, indices, basevertex)
            };
            if compile_draw(c, mode, idx) {
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
        let data = prepare_elements_with(c, (count, ty, indices), basevertex, 1);
        c.gl
            .draw_range_elements_base_vertex(mode, start, end, count, ty, data, basevertex);
        c.dirty = true;
    }
    fn glMultiDrawElementsBaseVertex(
        mode: GLenum, count: *const GLsizei, ty: GLenum, indices: *const *const c_void,
        primcount: GLsizei, basevertex: *const GLint
    ) => |c| {
        if primcount < 0 {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        let counts = rd_vec(count, primcount as i64);
        let ptrs = rd_vec(indices, primcount as i64);
        let bases = rd_vec(basevertex, primcount as i64);
        if c.compiling() {
            let mut skip = false;
            for ((&k, &p), &b) in counts.iter().zip(&ptrs).zip(&bases) {
                let idx = compiled_base_vertex_indices(c, k, ty, p, b);
                skip = compile_draw(c, mode, idx);
            }
            if skip || primcount == 0 {
                return;
            }
        }
        if crate::buffers::sources_mapped(c, true) && !c.gl.in_begin_end() {
            c.gl.record_error(GL_INVALID_OPERATION);
            return;
        }
        if counts.iter().any(|&k| k < 0) {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        for ((&k, &p), &b) in counts.iter().zip(&ptrs).zip(&bases) {
            let data = prepare_elements_with(c, (k, ty, p), b, 1);
            c.gl.draw_elements_base_vertex(mode, k, ty, data, b);
        }
        c.dirty = true;
    }
    fn glPrimitiveRestartIndex(index: GLuint) => |c| { c.gl.primitive_restart_index(index) }

    fn glArrayElement(i: GLint) => |c| {
        if i < 0 {
            // Undefined by GL 2.1; nothing is fetched.
            return;
        }
        if crate::buffers::sources_mapped(c, false) {
            c.gl.record_error(GL_INVALID_OPERATION);
            return;
        }
        let vals = element_values(c, i as u32);
        // Compiled with the values fetched now (GL 2.1 §5.4).
        let rec = vals.clone();
        if c.record(move || with_ctx((), |c| apply(c, &rec))) {
            return;
        }
        apply(c, &vals);
    }
}
