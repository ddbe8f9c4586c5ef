//! Vertex-array entry points built on the others: glArrayElement (one
//! array element as immediate-mode attribute calls), glMultiDrawElements,
//! and glInterleavedArrays (GL 2.1 §2.8, Table 2.5).

use crate::abi::*;
use crate::context::{guard, with_ctx, OsContext};
use crate::entry::element_source;
use gl::enums::*;
use gl::vertex::AttribSource;
use std::ffi::c_void;

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
        for (&k, &p) in counts.iter().zip(&ptrs) {
            let data = crate::entry::prepare_elements(c, k, ty, p);
            c.gl.draw_elements(mode, k, ty, data);
        }
        c.dirty = true;
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
            crate::entry::glDisableClientState(GL_EDGE_FLAG_ARRAY);
            crate::entry::glDisableClientState(GL_INDEX_ARRAY);
            crate::entry::glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
            crate::entry::glDisableClientState(GL_FOG_COORD_ARRAY);
            if tsize > 0 {
                crate::entry::glEnableClientState(GL_TEXTURE_COORD_ARRAY);
                crate::entry::glTexCoordPointer(tsize, GL_FLOAT, stride, at(0));
            } else {
                crate::entry::glDisableClientState(GL_TEXTURE_COORD_ARRAY);
            }
            if csize > 0 {
                crate::entry::glEnableClientState(GL_COLOR_ARRAY);
                crate::entry::glColorPointer(csize, cty, stride, at(pc));
            } else {
                crate::entry::glDisableClientState(GL_COLOR_ARRAY);
            }
            if normal {
                crate::entry::glEnableClientState(GL_NORMAL_ARRAY);
                crate::entry::glNormalPointer(GL_FLOAT, stride, at(pn));
            } else {
                crate::entry::glDisableClientState(GL_NORMAL_ARRAY);
            }
            crate::entry::glEnableClientState(GL_VERTEX_ARRAY);
            crate::entry::glVertexPointer(vsize, GL_FLOAT, stride, at(pv));
        }
    })
}

/// This module's exported functions outside the entry-point table.
pub fn lookup_extra(name: &str) -> Option<*const ()> {
    (name == "glInterleavedArrays").then_some(glInterleavedArrays as *const ())
}
