//! Client-memory vertex arrays: the C pointers given to gl*Pointer with no
//! buffer object bound, and their copy into the [`gl::Context`] at draw time.
//!
//! Safety argument: GL 2.1 §2.8 says a client array's pointer is read when
//! a draw command (glDrawArrays, glDrawElements, glArrayElement...)
//! executes, and that the client must keep the memory valid and unchanged
//! until then; OSMesa draws synchronously, so the memory is only read
//! inside the draw call that needs it. At each draw we copy exactly the
//! bytes of the vertices that draw reads (vertices `lo..=hi`, `size`
//! components of `type` at `stride`) out of the pointers of *enabled*
//! arrays, so memory the GL contract does not cover (disabled arrays,
//! vertices outside the draw) is never touched.

use gl::vertex::{ArrayState, AttribSource, VertexState};
use gl::vertex_format::element_size;
use gl::ArrayData;
use std::collections::BTreeMap;
use std::sync::Arc;

/// Largest copy made for one array in one draw (larger draws raise
/// GL_OUT_OF_MEMORY instead of allocating).
pub const MAX_ARRAY_COPY: usize = 1 << 30;

/// The client pointers of the arrays whose pointer was last specified
/// with no buffer bound.
#[derive(Clone, Default)]
pub struct ClientArrays {
    pointers: BTreeMap<AttribSource, usize>,
}

/// The array state `src` names (whether enabled or not).
pub fn array_state(va: &VertexState, src: AttribSource) -> Option<&ArrayState> {
    match src {
        AttribSource::Position => Some(&va.vertex_array),
        AttribSource::Color => Some(&va.color_array),
        AttribSource::SecondaryColor => Some(&va.secondary_array),
        AttribSource::Normal => Some(&va.normal_array),
        AttribSource::FogCoord => Some(&va.fog_array),
        AttribSource::TexCoord(u) => va.tex_arrays.get(u as usize),
        AttribSource::Generic(i) => va.generic_arrays.get(i as usize),
    }
}

impl ClientArrays {
    /// The client pointer last given for `src` (None: none, or the array
    /// is in a buffer object).
    pub fn pointer(&self, src: AttribSource) -> Option<usize> {
        self.pointers.get(&src).copied()
    }

    /// The pointer value glGetPointerv/glGetVertexAttribPointerv return
    /// for `src`: the client pointer, or the offset into the array's
    /// buffer object.
    pub fn pointer_value(&self, va: &VertexState, src: AttribSource) -> usize {
        match array_state(va, src) {
            // The pointers kept are the default object's; another object's
            // arrays are offsets (null, or into their buffers).
            Some(a) if a.buffer != 0 || va.vao != 0 => match a.data {
                gl::ArrayData::Offset(o) => o,
                _ => 0,
            },
            _ => self.pointer(src).unwrap_or(0),
        }
    }

    /// A gl*Pointer call: with a buffer bound to GL_ARRAY_BUFFER the
    /// pointer is an offset into it; otherwise remember the C pointer and
    /// hand the context a placeholder that draws replace. `call` makes the
    /// gl call (which validates the arguments); the pointer is recorded
    /// only if the call changed the array.
    pub fn set_pointer(
        &mut self,
        gl: &mut gl::Context,
        src: AttribSource,
        ptr: *const u8,
        call: impl FnOnce(&mut gl::Context, ArrayData),
    ) {
        // A vertex array object other than the default one holds no
        // client memory (the context refuses a non-null pointer with no
        // buffer bound): the pointers kept are the default object's.
        if gl.vertex_array_binding() != 0 {
            call(gl, ArrayData::Offset(ptr as usize));
            return;
        }
        if gl.vertex_state().array_buffer != 0 {
            call(gl, ArrayData::Offset(ptr as usize));
            if let Some(a) = array_state(gl.vertex_state(), src) {
                if a.buffer != 0 {
                    self.pointers.remove(&src);
                }
            }
            return;
        }
        let marker: Arc<[u8]> = Arc::from(Vec::new());
        call(gl, ArrayData::Client(marker.clone()));
        let taken = matches!(
            array_state(gl.vertex_state(), src).map(|a| &a.data),
            Some(ArrayData::Client(d)) if Arc::ptr_eq(d, &marker)
        );
        if taken {
            if ptr.is_null() {
                self.pointers.remove(&src);
            } else {
                self.pointers.insert(src, ptr as usize);
            }
        }
    }

    /// Whether a draw reads an enabled array from client memory (then
    /// [`ClientArrays::prepare`] has vertices to copy).
    pub fn reads_client_memory(&self, gl: &gl::Context) -> bool {
        if gl.vertex_array_binding() != 0 {
            return false;
        }
        self.pointers.keys().any(|&src| {
            array_state(gl.vertex_state(), src).is_some_and(|a| a.enabled && a.buffer == 0)
        })
    }

    /// Before a draw reading vertices `lo..=hi`: copies those vertices of
    /// every enabled client array into the context.
    pub fn prepare(&self, gl: &mut gl::Context, lo: u32, hi: u32) {
        self.prepare_instanced(gl, lo, hi, 1);
    }

    /// [`ClientArrays::prepare`] for `instances` instances: an instanced
    /// array (divisor d) is read at elements 0..=(instances - 1) / d
    /// instead of the vertices.
    pub fn prepare_instanced(&self, gl: &mut gl::Context, lo: u32, hi: u32, instances: u32) {
        if gl.vertex_array_binding() != 0 {
            return;
        }
        for (&src, &ptr) in &self.pointers {
            let Some(a) = array_state(gl.vertex_state(), src) else {
                continue;
            };
            if !a.enabled || a.buffer != 0 {
                continue;
            }
            let (lo, hi) = match a.divisor {
                0 => (lo, hi),
                d => (0, instances.saturating_sub(1) / d),
            };
            let Some(bytes) = copy_range(ptr as *const u8, a, lo, hi) else {
                gl.record_error(gl::enums::GL_OUT_OF_MEMORY);
                continue;
            };
            gl.replace_client_array_data(src, ArrayData::Client(Arc::from(bytes)));
        }
    }
}

/// The bytes of vertices `lo..=hi` of array `a` at `ptr`, at their offsets
/// from `ptr` (bytes before vertex `lo` are zero, never read).
fn copy_range(ptr: *const u8, a: &ArrayState, lo: u32, hi: u32) -> Option<Vec<u8>> {
    let elem = element_size(a.size, a.ty)?;
    let stride = if a.stride > 0 {
        a.stride as usize
    } else {
        elem
    };
    let start = (lo as usize).checked_mul(stride)?;
    let end = (hi as usize).checked_mul(stride)?.checked_add(elem)?;
    if end > MAX_ARRAY_COPY || start > end {
        return None;
    }
    let mut v = vec![0u8; end];
    // SAFETY: see the module docs: the array is enabled and the draw reads
    // vertices lo..=hi, so GL's contract makes ptr[start..end] valid.
    let src = unsafe { std::slice::from_raw_parts(ptr.add(start), end - start) };
    v[start..end].copy_from_slice(src);
    Some(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn copies_only_the_vertices_drawn() {
        let data: Vec<u8> = (0..64).collect();
        let a = ArrayState {
            enabled: true,
            size: 2,
            ty: gl::enums::GL_UNSIGNED_BYTE,
            normalized: false,
            stride: 8,
            buffer: 0,
            data: ArrayData::default(),
            integer: false,
            divisor: 0,
        };
        let v = copy_range(data.as_ptr(), &a, 2, 3).unwrap();
        assert_eq!(v.len(), 3 * 8 + 2);
        assert!(v[..16].iter().all(|&b| b == 0));
        assert_eq!(&v[16..], &data[16..26]);
        let huge = ArrayState {
            stride: i32::MAX,
            ..a
        };
        assert!(copy_range(data.as_ptr(), &huge, 0, u32::MAX).is_none());
    }
}
