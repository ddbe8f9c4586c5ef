//! Buffer objects (GL 3.3 §2.9): glGenBuffers, glBindBuffer, the indexed
//! binding points (glBindBufferBase / glBindBufferRange), glBufferData,
//! glBufferSubData, glGetBufferSubData, mapping (glMapBufferRange,
//! glFlushMappedBufferRange, glUnmapBuffer), glCopyBufferSubData and the
//! buffer queries.
//!
//! Contract: a store is an `Arc<[u8]>` replaced whole on every write, so a
//! draw (or a client-array copy) that holds the old store keeps it
//! unchanged. GL_ARRAY_BUFFER and GL_ELEMENT_ARRAY_BUFFER bindings live in
//! the vertex-array state; the pixel pack/unpack bindings are only kept
//! (a C layer moves pixels through them); GL_TEXTURE_BUFFER and
//! GL_TRANSFORM_FEEDBACK_BUFFER bindings (general and indexed) are kept for
//! queries; GL_UNIFORM_BUFFER indexed bindings feed uniform blocks at draw
//! time, GL_SHADER_STORAGE_BUFFER ones storage blocks (`crate::storage`),
//! GL_DISPATCH_INDIRECT_BUFFER indirect dispatches.
//!
//! Mapping: the context records the mapped range and access bits and hands
//! out a copy of the range's bytes; the caller (a C layer holding the
//! client's pointer) gives the edited bytes back to
//! [`Context::flush_mapped_buffer_range`] and [`Context::unmap_buffer`],
//! which write them into the store as the access bits say (GL_MAP_WRITE_BIT
//! without GL_MAP_FLUSH_EXPLICIT_BIT: the whole range at unmap; with it:
//! only the flushed subranges). Drawing is synchronous, so
//! GL_MAP_UNSYNCHRONIZED_BIT changes nothing, and the invalidate bits keep
//! the old contents (allowed: invalidated data are undefined).

use crate::enums::*;
use crate::objects::{delete_names, BufferObj};
use crate::Context;
use std::sync::Arc;

pub use crate::objects::{
    BufferMap, BufferTargets, IndexedBinding, MAX_SHADER_STORAGE_BUFFER_BINDINGS,
    MAX_TRANSFORM_FEEDBACK_BUFFERS, MAX_UNIFORM_BUFFER_BINDINGS,
    SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, UNIFORM_BUFFER_OFFSET_ALIGNMENT,
};

/// Every GL_MAP_*_BIT (GL 3.3 §2.9.3).
const MAP_BITS: u32 = GL_MAP_READ_BIT
    | GL_MAP_WRITE_BIT
    | GL_MAP_INVALIDATE_RANGE_BIT
    | GL_MAP_INVALIDATE_BUFFER_BIT
    | GL_MAP_FLUSH_EXPLICIT_BIT
    | GL_MAP_UNSYNCHRONIZED_BIT;

impl Context {
    /// glGenBuffers.
    pub fn gen_buffers(&mut self, n: i32) -> Vec<u32> {
        self.gen_objects(
            n,
            |o| (&mut o.buffers, &mut o.next_buffer),
            BufferObj::default,
        )
    }

    /// glDeleteBuffers (unbinds them from every general and indexed
    /// binding point).
    pub fn delete_buffers(&mut self, names: &[u32]) {
        let o = &mut self.objects;
        let t = &mut o.buffer_targets;
        for ib in t
            .uniform_bindings
            .iter_mut()
            .chain(t.feedback_bindings.iter_mut())
            .chain(t.storage_bindings.iter_mut())
        {
            if ib.buffer != 0 && names.contains(&ib.buffer) {
                *ib = IndexedBinding::default();
            }
        }
        let bindings = &mut [
            &mut self.va.array_buffer,
            &mut self.va.element_buffer,
            &mut o.pack_buffer,
            &mut o.unpack_buffer,
            &mut t.uniform,
            &mut t.copy_read,
            &mut t.copy_write,
            &mut t.texture,
            &mut t.transform_feedback,
            &mut t.storage,
            &mut t.dispatch_indirect,
        ];
        delete_names(&mut o.buffers, names, bindings);
    }

    /// The general binding point of a buffer target, `None` for another
    /// enum.
    fn target_slot(&mut self, target: u32) -> Option<&mut u32> {
        let t = &mut self.objects.buffer_targets;
        Some(match target {
            GL_ARRAY_BUFFER => &mut self.va.array_buffer,
            GL_ELEMENT_ARRAY_BUFFER => &mut self.va.element_buffer,
            GL_PIXEL_PACK_BUFFER => &mut self.objects.pack_buffer,
            GL_PIXEL_UNPACK_BUFFER => &mut self.objects.unpack_buffer,
            GL_UNIFORM_BUFFER => &mut t.uniform,
            GL_COPY_READ_BUFFER => &mut t.copy_read,
            GL_COPY_WRITE_BUFFER => &mut t.copy_write,
            GL_TEXTURE_BUFFER => &mut t.texture,
            GL_TRANSFORM_FEEDBACK_BUFFER => &mut t.transform_feedback,
            GL_SHADER_STORAGE_BUFFER if self.api.at_least(3, 3) => &mut t.storage,
            GL_DISPATCH_INDIRECT_BUFFER if self.api.at_least(3, 3) => &mut t.dispatch_indirect,
            _ => return None,
        })
    }

    /// Whether `target` is a buffer target (GL 3.3 Table 2.8).
    pub fn is_buffer_target(target: u32) -> bool {
        matches!(
            target,
            GL_ARRAY_BUFFER
                | GL_ELEMENT_ARRAY_BUFFER
                | GL_PIXEL_PACK_BUFFER
                | GL_PIXEL_UNPACK_BUFFER
                | GL_UNIFORM_BUFFER
                | GL_COPY_READ_BUFFER
                | GL_COPY_WRITE_BUFFER
                | GL_TEXTURE_BUFFER
                | GL_TRANSFORM_FEEDBACK_BUFFER
                | GL_SHADER_STORAGE_BUFFER
                | GL_DISPATCH_INDIRECT_BUFFER
        )
    }

    /// The buffer bound to `target` (0: none or not a buffer target).
    pub fn bound_buffer(&self, target: u32) -> u32 {
        let t = &self.objects.buffer_targets;
        match target {
            GL_ARRAY_BUFFER => self.va.array_buffer,
            GL_ELEMENT_ARRAY_BUFFER => self.va.element_buffer,
            GL_PIXEL_PACK_BUFFER => self.objects.pack_buffer,
            GL_PIXEL_UNPACK_BUFFER => self.objects.unpack_buffer,
            GL_UNIFORM_BUFFER => t.uniform,
            GL_COPY_READ_BUFFER => t.copy_read,
            GL_COPY_WRITE_BUFFER => t.copy_write,
            GL_TEXTURE_BUFFER => t.texture,
            GL_TRANSFORM_FEEDBACK_BUFFER => t.transform_feedback,
            GL_SHADER_STORAGE_BUFFER => t.storage,
            GL_DISPATCH_INDIRECT_BUFFER => t.dispatch_indirect,
            _ => 0,
        }
    }

    /// Size in bytes and usage of buffer `name`.
    pub fn buffer_info(&self, name: u32) -> Option<(usize, u32)> {
        self.objects
            .buffers
            .get(&name)
            .map(|b| (b.data.len(), b.usage))
    }

    /// The mapped range of buffer `name`, if it is mapped.
    pub fn buffer_mapping(&self, name: u32) -> Option<BufferMap> {
        self.objects.buffers.get(&name).and_then(|b| b.map)
    }

    /// The store of buffer `name` (empty for no buffer).
    pub fn buffer_store(&self, name: u32) -> Arc<[u8]> {
        self.objects
            .buffers
            .get(&name)
            .map_or_else(|| Arc::from(Vec::new()), |b| b.data.clone())
    }

    /// glIsBuffer.
    pub fn is_buffer(&self, name: u32) -> bool {
        name != 0 && self.objects.buffers.get(&name).is_some_and(|b| b.bound)
    }

    /// glBindBuffer (creates the object on first bind).
    pub fn bind_buffer(&mut self, target: u32, buffer: u32) {
        if self.reject_in_begin() {
            return;
        }
        let Some(slot) = self.target_slot(target) else {
            self.set_error(GL_INVALID_ENUM);
            return;
        };
        *slot = buffer;
        if buffer != 0 {
            self.objects.buffers.entry(buffer).or_default().bound = true;
        }
    }

    /// The buffer bound to `target`: `GL_INVALID_ENUM` for another enum,
    /// `GL_INVALID_OPERATION` for none bound.
    fn bound_buffer_name(&mut self, target: u32) -> Option<u32> {
        let Some(&mut b) = self.target_slot(target) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        if b == 0 {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        Some(b)
    }

    /// glBindBufferRange (`range` Some((offset, size))) and
    /// glBindBufferBase (`range` None) on GL_UNIFORM_BUFFER or
    /// GL_TRANSFORM_FEEDBACK_BUFFER: the indexed binding point `index` and
    /// the general one (GL 3.3 §2.9.1, §2.11.4, §2.15).
    pub fn bind_buffer_indexed(
        &mut self,
        target: u32,
        index: u32,
        buffer: u32,
        range: Option<(isize, isize)>,
    ) {
        if self.reject_in_begin() {
            return;
        }
        let (max, align, size_align) = match target {
            GL_UNIFORM_BUFFER => (
                MAX_UNIFORM_BUFFER_BINDINGS,
                UNIFORM_BUFFER_OFFSET_ALIGNMENT,
                1,
            ),
            GL_TRANSFORM_FEEDBACK_BUFFER => (MAX_TRANSFORM_FEEDBACK_BUFFERS, 4, 4),
            GL_SHADER_STORAGE_BUFFER if self.api.at_least(3, 3) => (
                MAX_SHADER_STORAGE_BUFFER_BINDINGS,
                SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT,
                1,
            ),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return;
            }
        };
        // The bindings being written stay put (GL 3.3 §2.16).
        if target == GL_TRANSFORM_FEEDBACK_BUFFER && self.feedback_active() {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if index as usize >= max {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if let (Some((offset, size)), true) = (range, buffer != 0) {
            let (offset, size) = (offset as i64, size as i64);
            let store = self.buffer_info(buffer).map_or(0, |i| i.0) as i64;
            if size <= 0
                || offset < 0
                || offset.checked_add(size).is_none_or(|e| e > store)
                || offset % align != 0
                || size % size_align != 0
            {
                self.set_error(GL_INVALID_VALUE);
                return;
            }
        }
        if buffer != 0 {
            self.objects.buffers.entry(buffer).or_default().bound = true;
        }
        let binding = match range {
            _ if buffer == 0 => IndexedBinding::default(),
            Some((offset, size)) => IndexedBinding {
                buffer,
                offset: offset as i64,
                size: Some(size as i64),
            },
            None => IndexedBinding {
                buffer,
                offset: 0,
                size: None,
            },
        };
        let t = &mut self.objects.buffer_targets;
        if target == GL_UNIFORM_BUFFER {
            t.uniform = buffer;
            t.uniform_bindings[index as usize] = binding;
        } else if target == GL_SHADER_STORAGE_BUFFER {
            t.storage = buffer;
            t.storage_bindings[index as usize] = binding;
        } else {
            t.transform_feedback = buffer;
            t.feedback_bindings[index as usize] = binding;
        }
    }

    /// glBindBufferRange.
    pub fn bind_buffer_range(
        &mut self,
        target: u32,
        index: u32,
        buffer: u32,
        offset: isize,
        size: isize,
    ) {
        self.bind_buffer_indexed(target, index, buffer, Some((offset, size)));
    }

    /// glBindBufferBase.
    pub fn bind_buffer_base(&mut self, target: u32, index: u32, buffer: u32) {
        self.bind_buffer_indexed(target, index, buffer, None);
    }

    /// The indexed binding point `index` of GL_UNIFORM_BUFFER.
    pub fn uniform_buffer_binding(&self, index: usize) -> Option<IndexedBinding> {
        self.objects
            .buffer_targets
            .uniform_bindings
            .get(index)
            .copied()
    }

    /// The bytes an indexed uniform binding point gives a uniform block:
    /// the bound range clipped to the store (empty when nothing is bound).
    pub(crate) fn uniform_binding_bytes(&self, index: usize) -> (Arc<[u8]>, usize, usize) {
        let Some(ib) = self.uniform_buffer_binding(index).filter(|b| b.buffer != 0) else {
            return (Arc::from(Vec::new()), 0, 0);
        };
        let store = self.buffer_store(ib.buffer);
        let start = (ib.offset.max(0) as usize).min(store.len());
        let end = match ib.size {
            Some(s) => start.saturating_add(s.max(0) as usize).min(store.len()),
            None => store.len(),
        };
        (store, start, end)
    }

    /// glGetIntegeri_v / glGetInteger64i_v: the indexed binding queries
    /// (GL_UNIFORM_BUFFER_BINDING/START/SIZE and the transform-feedback
    /// ones). `GL_INVALID_ENUM` for another pname, `GL_INVALID_VALUE` for
    /// an index past the binding points; `None` after an error.
    pub fn get_integer64_indexed(&mut self, pname: u32, index: u32) -> Option<i64> {
        let t = &self.objects.buffer_targets;
        let list: &[IndexedBinding] = match pname {
            GL_UNIFORM_BUFFER_BINDING | GL_UNIFORM_BUFFER_START | GL_UNIFORM_BUFFER_SIZE => {
                &t.uniform_bindings
            }
            GL_TRANSFORM_FEEDBACK_BUFFER_BINDING
            | GL_TRANSFORM_FEEDBACK_BUFFER_START
            | GL_TRANSFORM_FEEDBACK_BUFFER_SIZE => &t.feedback_bindings,
            GL_SHADER_STORAGE_BUFFER_BINDING
            | GL_SHADER_STORAGE_BUFFER_START
            | GL_SHADER_STORAGE_BUFFER_SIZE
                if self.api.at_least(3, 3) =>
            {
                &t.storage_bindings
            }
            GL_MAX_COMPUTE_WORK_GROUP_COUNT | GL_MAX_COMPUTE_WORK_GROUP_SIZE
                if self.api.at_least(3, 3) =>
            {
                let max = if pname == GL_MAX_COMPUTE_WORK_GROUP_COUNT {
                    glsl::limits::MAX_COMPUTE_WORK_GROUP_COUNT
                } else {
                    glsl::limits::MAX_COMPUTE_WORK_GROUP_SIZE
                };
                let Some(&v) = max.get(index as usize) else {
                    self.set_error(GL_INVALID_VALUE);
                    return None;
                };
                return Some(v as i64);
            }
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        let Some(b) = list.get(index as usize).copied() else {
            self.set_error(GL_INVALID_VALUE);
            return None;
        };
        Some(match pname {
            GL_UNIFORM_BUFFER_BINDING
            | GL_TRANSFORM_FEEDBACK_BUFFER_BINDING
            | GL_SHADER_STORAGE_BUFFER_BINDING => b.buffer as i64,
            GL_UNIFORM_BUFFER_START
            | GL_TRANSFORM_FEEDBACK_BUFFER_START
            | GL_SHADER_STORAGE_BUFFER_START => b.offset,
            // glBindBufferBase sets no size (Mesa reports 0 too).
            _ => b.size.unwrap_or(0),
        })
    }

    /// glGetIntegeri_v (values clamped to the int range).
    pub fn get_integeri(&mut self, pname: u32, index: u32) -> Option<i32> {
        self.get_integer64_indexed(pname, index)
            .map(|v| v.clamp(i32::MIN as i64, i32::MAX as i64) as i32)
    }

    /// glBufferData (`data` None: uninitialized, zeros here). Ends a
    /// mapping (not an error, GL 3.3 §2.9.3).
    pub fn buffer_data(&mut self, target: u32, size: isize, data: Option<&[u8]>, usage: u32) {
        if self.reject_in_begin() {
            return;
        }
        if size < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if !matches!(
            usage,
            GL_STREAM_DRAW
                | GL_STREAM_READ
                | GL_STREAM_COPY
                | GL_STATIC_DRAW
                | GL_STATIC_READ
                | GL_STATIC_COPY
                | GL_DYNAMIC_DRAW
                | GL_DYNAMIC_READ
                | GL_DYNAMIC_COPY
        ) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let Some(b) = self.bound_buffer_name(target) else {
            return;
        };
        let size = size as usize;
        if size > (1 << 30) {
            self.set_error(GL_OUT_OF_MEMORY);
            return;
        }
        let mut store = vec![0u8; size];
        if let Some(d) = data {
            let n = d.len().min(size);
            store[..n].copy_from_slice(&d[..n]);
        }
        self.objects.buffers.insert(
            b,
            BufferObj {
                data: Arc::from(store),
                usage,
                map: None,
                bound: true,
            },
        );
    }

    /// The bound buffer of `target` for a command that may not touch a
    /// mapped buffer: `GL_INVALID_OPERATION` when it is mapped.
    fn unmapped_buffer(&mut self, target: u32) -> Option<u32> {
        let b = self.bound_buffer_name(target)?;
        if self.buffer_mapping(b).is_some() {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        Some(b)
    }

    /// Writes `data` at `offset` into buffer `b`'s store (range checked
    /// by the caller).
    pub(crate) fn write_store(&mut self, b: u32, offset: usize, data: &[u8]) {
        if let Some(obj) = self.objects.buffers.get_mut(&b) {
            let mut v = obj.data.to_vec();
            if let Some(dst) = v.get_mut(offset..offset + data.len()) {
                dst.copy_from_slice(data);
                obj.data = Arc::from(v);
            }
        }
    }

    /// glBufferSubData (`GL_INVALID_OPERATION` when the range overlaps
    /// the mapped range, GL 3.3 §2.9.2).
    pub fn buffer_sub_data(&mut self, target: u32, offset: isize, data: &[u8]) {
        if self.reject_in_begin() {
            return;
        }
        let Some(b) = self.bound_buffer_name(target) else {
            return;
        };
        let len = self.buffer_info(b).map_or(0, |i| i.0);
        if offset < 0
            || (offset as usize)
                .checked_add(data.len())
                .is_none_or(|e| e > len)
        {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let (start, end) = (offset as usize, offset as usize + data.len());
        if self
            .buffer_mapping(b)
            .is_some_and(|m| start < m.offset + m.length && m.offset < end)
        {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        self.write_store(b, offset as usize, data);
    }

    /// glGetBufferSubData (`GL_INVALID_OPERATION` on a mapped buffer).
    pub fn get_buffer_sub_data(&mut self, target: u32, offset: isize, size: isize) -> Vec<u8> {
        let Some(b) = self.unmapped_buffer(target) else {
            return Vec::new();
        };
        let data = self.buffer_store(b);
        if offset < 0
            || size < 0
            || (offset as usize)
                .checked_add(size as usize)
                .is_none_or(|e| e > data.len())
        {
            self.set_error(GL_INVALID_VALUE);
            return Vec::new();
        }
        data[offset as usize..offset as usize + size as usize].to_vec()
    }

    /// glMapBufferRange (GL 3.3 §2.9.3): records the mapping and returns a
    /// copy of the range's bytes for the client to edit; `None` after an
    /// error.
    pub fn map_buffer_range(
        &mut self,
        target: u32,
        offset: isize,
        length: isize,
        access: u32,
    ) -> Option<Vec<u8>> {
        if self.reject_in_begin() {
            return None;
        }
        let b = self.bound_buffer_name(target)?;
        let size = self.buffer_info(b).map_or(0, |i| i.0);
        if offset < 0
            || length < 0
            || (offset as usize)
                .checked_add(length as usize)
                .is_none_or(|e| e > size)
            || access & !MAP_BITS != 0
        {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let read = access & GL_MAP_READ_BIT != 0;
        let write = access & GL_MAP_WRITE_BIT != 0;
        let read_only_conflict =
            GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_UNSYNCHRONIZED_BIT;
        if self.buffer_mapping(b).is_some()
            || !(read || write)
            || (read && access & read_only_conflict != 0)
            || (access & GL_MAP_FLUSH_EXPLICIT_BIT != 0 && !write)
        {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        let (offset, length) = (offset as usize, length as usize);
        let obj = self.objects.buffers.get_mut(&b)?;
        obj.map = Some(BufferMap {
            offset,
            length,
            access,
        });
        Some(obj.data[offset..offset + length].to_vec())
    }

    /// glMapBuffer: glMapBufferRange of the whole store with the bits
    /// `access` stands for; `GL_INVALID_ENUM` for another access enum.
    pub fn map_buffer(&mut self, target: u32, access: u32) -> Option<Vec<u8>> {
        if self.reject_in_begin() {
            return None;
        }
        let b = self.bound_buffer_name(target)?;
        let bits = match access {
            GL_READ_ONLY => GL_MAP_READ_BIT,
            GL_WRITE_ONLY => GL_MAP_WRITE_BIT,
            GL_READ_WRITE => GL_MAP_READ_BIT | GL_MAP_WRITE_BIT,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        let size = self.buffer_info(b).map_or(0, |i| i.0);
        self.map_buffer_range(target, 0, size as isize, bits)
    }

    /// glFlushMappedBufferRange: writes `mapped[offset..offset + length]`
    /// (`mapped` being the client's copy of the whole mapped range) into
    /// the store (GL 3.3 §2.9.3).
    pub fn flush_mapped_buffer_range(
        &mut self,
        target: u32,
        offset: isize,
        length: isize,
        mapped: &[u8],
    ) {
        if self.reject_in_begin() {
            return;
        }
        let Some(b) = self.bound_buffer_name(target) else {
            return;
        };
        if offset < 0 || length < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let Some(m) = self
            .buffer_mapping(b)
            .filter(|m| m.access & GL_MAP_FLUSH_EXPLICIT_BIT != 0)
        else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let (offset, length) = (offset as usize, length as usize);
        if offset.checked_add(length).is_none_or(|e| e > m.length) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if let Some(src) = mapped.get(offset..offset + length) {
            self.write_store(b, m.offset + offset, src);
        }
    }

    /// glUnmapBuffer: ends the mapping of the buffer bound to `target`,
    /// writing `mapped` (the client's copy of the mapped range) back unless
    /// the mapping was read-only or flushed explicitly. False and
    /// `GL_INVALID_OPERATION` when the buffer is not mapped.
    pub fn unmap_buffer(&mut self, target: u32, mapped: &[u8]) -> bool {
        if self.reject_in_begin() {
            return false;
        }
        let Some(b) = self.bound_buffer_name(target) else {
            return false;
        };
        let Some(m) = self.buffer_mapping(b) else {
            self.set_error(GL_INVALID_OPERATION);
            return false;
        };
        if let Some(obj) = self.objects.buffers.get_mut(&b) {
            obj.map = None;
        }
        let write_back =
            m.access & GL_MAP_WRITE_BIT != 0 && m.access & GL_MAP_FLUSH_EXPLICIT_BIT == 0;
        if write_back {
            if let Some(src) = mapped.get(..m.length) {
                self.write_store(b, m.offset, src);
            }
        }
        true
    }

    /// glCopyBufferSubData (GL 3.3 §2.9.5).
    pub fn copy_buffer_sub_data(
        &mut self,
        read_target: u32,
        write_target: u32,
        read_offset: isize,
        write_offset: isize,
        size: isize,
    ) {
        if self.reject_in_begin() {
            return;
        }
        if !Self::is_buffer_target(read_target) || !Self::is_buffer_target(write_target) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let Some(r) = self.unmapped_buffer(read_target) else {
            return;
        };
        let Some(w) = self.unmapped_buffer(write_target) else {
            return;
        };
        let (rs, ws) = (
            self.buffer_info(r).map_or(0, |i| i.0),
            self.buffer_info(w).map_or(0, |i| i.0),
        );
        let fits = |o: isize, len: usize| {
            o >= 0
                && (o as usize)
                    .checked_add(size as usize)
                    .is_some_and(|e| e <= len)
        };
        if size < 0 || !fits(read_offset, rs) || !fits(write_offset, ws) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let (ro, wo, n) = (read_offset as usize, write_offset as usize, size as usize);
        if r == w && ro < wo + n && wo < ro + n {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let src = self.buffer_store(r)[ro..ro + n].to_vec();
        self.write_store(w, wo, &src);
    }

    /// glGetBufferParameteri64v (glGetBufferParameteriv clamps): the
    /// state of GL 3.3 Table 2.10 for the buffer bound to `target`.
    pub fn get_buffer_parameter(&mut self, target: u32, pname: u32) -> Option<i64> {
        if self.reject_in_begin() {
            return None;
        }
        let b = self.bound_buffer_name(target)?;
        let (size, usage) = self.buffer_info(b).unwrap_or((0, GL_STATIC_DRAW));
        let m = self.buffer_mapping(b);
        Some(match pname {
            GL_BUFFER_SIZE => size as i64,
            GL_BUFFER_USAGE => usage as i64,
            GL_BUFFER_ACCESS => m.map_or(GL_READ_WRITE, |m| m.access_enum()) as i64,
            GL_BUFFER_ACCESS_FLAGS => m.map_or(0, |m| m.access) as i64,
            GL_BUFFER_MAPPED => m.is_some() as i64,
            GL_BUFFER_MAP_OFFSET => m.map_or(0, |m| m.offset) as i64,
            GL_BUFFER_MAP_LENGTH => m.map_or(0, |m| m.length) as i64,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_generated_name_is_a_buffer_from_its_first_bind() {
        let mut ctx = Context::new(4, 4);
        let b = ctx.gen_buffers(1)[0];
        assert!(!ctx.is_buffer(b));
        ctx.bind_buffer(GL_ARRAY_BUFFER, b);
        assert!(ctx.is_buffer(b));
        ctx.bind_buffer(GL_ARRAY_BUFFER, 0);
        assert!(ctx.is_buffer(b));
        let u = ctx.gen_buffers(1)[0];
        ctx.bind_buffer_base(GL_UNIFORM_BUFFER, 0, u);
        assert!(ctx.is_buffer(u));
    }

    #[test]
    fn buffers() {
        let mut ctx = Context::new(4, 4);
        ctx.buffer_data(GL_ARRAY_BUFFER, 4, None, GL_STATIC_DRAW);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        let b = ctx.gen_buffers(1)[0];
        ctx.bind_buffer(GL_ARRAY_BUFFER, b);
        ctx.buffer_data(GL_ARRAY_BUFFER, 8, Some(&[1, 2, 3]), GL_STATIC_DRAW);
        ctx.buffer_sub_data(GL_ARRAY_BUFFER, 6, &[9, 9]);
        assert_eq!(
            ctx.get_buffer_sub_data(GL_ARRAY_BUFFER, 0, 8),
            vec![1, 2, 3, 0, 0, 0, 9, 9]
        );
        ctx.buffer_sub_data(GL_ARRAY_BUFFER, 7, &[9, 9]);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.buffer_data(GL_ARRAY_BUFFER, 8, None, 0);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    }

    fn buffer(ctx: &mut Context, target: u32, bytes: &[u8]) -> u32 {
        let b = ctx.gen_buffers(1)[0];
        ctx.bind_buffer(target, b);
        ctx.buffer_data(target, bytes.len() as isize, Some(bytes), GL_STATIC_DRAW);
        b
    }

    #[test]
    fn map_buffer_range_errors() {
        let mut ctx = Context::new(4, 4);
        let t = GL_COPY_WRITE_BUFFER;
        assert_eq!(ctx.map_buffer_range(t, 0, 1, GL_MAP_READ_BIT), None);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.map_buffer_range(0x1234, 0, 1, GL_MAP_READ_BIT), None);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        buffer(&mut ctx, t, &[0, 1, 2, 3, 4, 5, 6, 7]);
        let r = GL_MAP_READ_BIT;
        let w = GL_MAP_WRITE_BIT;
        for (offset, length, access, err) in [
            (-1, 1, r, GL_INVALID_VALUE),
            (0, -1, r, GL_INVALID_VALUE),
            (4, 5, r, GL_INVALID_VALUE),
            (0, 1, r | 0x40, GL_INVALID_VALUE),
            (0, 1, 0, GL_INVALID_OPERATION),
            (0, 1, GL_MAP_INVALIDATE_RANGE_BIT, GL_INVALID_OPERATION),
            (0, 1, r | GL_MAP_INVALIDATE_RANGE_BIT, GL_INVALID_OPERATION),
            (0, 1, r | GL_MAP_INVALIDATE_BUFFER_BIT, GL_INVALID_OPERATION),
            (0, 1, r | GL_MAP_UNSYNCHRONIZED_BIT, GL_INVALID_OPERATION),
            (0, 1, r | GL_MAP_FLUSH_EXPLICIT_BIT, GL_INVALID_OPERATION),
        ] {
            assert_eq!(ctx.map_buffer_range(t, offset, length, access), None);
            assert_eq!(ctx.get_error(), err, "{offset} {length} {access:#x}");
        }
        let all_write = w
            | GL_MAP_INVALIDATE_RANGE_BIT
            | GL_MAP_INVALIDATE_BUFFER_BIT
            | GL_MAP_UNSYNCHRONIZED_BIT
            | GL_MAP_FLUSH_EXPLICIT_BIT;
        assert_eq!(
            ctx.map_buffer_range(t, 2, 3, all_write).map(|v| v.len()),
            Some(3)
        );
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        // Mapped: a second map, sub-data writes and reads, copies fail.
        assert_eq!(ctx.map_buffer_range(t, 0, 1, r), None);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        // Sub-data writes fail where they touch the mapped range 2..5.
        ctx.buffer_sub_data(t, 4, &[1, 1]);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.buffer_sub_data(t, 0, &[0, 1]);
        ctx.buffer_sub_data(t, 5, &[5]);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert!(ctx.get_buffer_sub_data(t, 0, 1).is_empty());
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.copy_buffer_sub_data(t, t, 0, 4, 1);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        let q = |ctx: &mut Context, pname| ctx.get_buffer_parameter(t, pname);
        assert_eq!(q(&mut ctx, GL_BUFFER_MAPPED), Some(1));
        assert_eq!(q(&mut ctx, GL_BUFFER_ACCESS_FLAGS), Some(all_write as i64));
        assert_eq!(q(&mut ctx, GL_BUFFER_ACCESS), Some(GL_WRITE_ONLY as i64));
        assert_eq!(q(&mut ctx, GL_BUFFER_MAP_OFFSET), Some(2));
        assert_eq!(q(&mut ctx, GL_BUFFER_MAP_LENGTH), Some(3));
        assert_eq!(q(&mut ctx, 0x1234), None);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        assert!(ctx.unmap_buffer(t, &[9, 9, 9]));
        assert!(!ctx.unmap_buffer(t, &[]));
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        assert_eq!(q(&mut ctx, GL_BUFFER_MAPPED), Some(0));
        assert_eq!(q(&mut ctx, GL_BUFFER_ACCESS_FLAGS), Some(0));
        assert_eq!(q(&mut ctx, GL_BUFFER_ACCESS), Some(GL_READ_WRITE as i64));
        assert_eq!(q(&mut ctx, GL_BUFFER_MAP_LENGTH), Some(0));
        // Explicit flushing: nothing was flushed, nothing written.
        assert_eq!(
            ctx.get_buffer_sub_data(t, 0, 8),
            vec![0, 1, 2, 3, 4, 5, 6, 7]
        );
    }

    #[test]
    fn mapped_writes_land_as_the_access_bits_say() {
        let mut ctx = Context::new(4, 4);
        let t = GL_ARRAY_BUFFER;
        buffer(&mut ctx, t, &[0; 8]);
        // Whole-range write-back.
        let mut m = ctx.map_buffer_range(t, 4, 4, GL_MAP_WRITE_BIT).unwrap();
        m.copy_from_slice(&[1, 2, 3, 4]);
        assert!(ctx.unmap_buffer(t, &m));
        assert_eq!(
            ctx.get_buffer_sub_data(t, 0, 8),
            vec![0, 0, 0, 0, 1, 2, 3, 4]
        );
        // Read-only: edits are dropped.
        let m = ctx.map_buffer_range(t, 0, 8, GL_MAP_READ_BIT).unwrap();
        assert_eq!(m, vec![0, 0, 0, 0, 1, 2, 3, 4]);
        assert!(ctx.unmap_buffer(t, &[7; 8]));
        assert_eq!(ctx.get_buffer_sub_data(t, 0, 2), vec![0, 0]);
        // Explicit flushes write their subranges only (offsets relative to
        // the mapping).
        let bits = GL_MAP_WRITE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT;
        let m = ctx
            .map_buffer_range(t, 2, 6, bits)
            .map(|_| vec![5u8; 6])
            .unwrap();
        ctx.flush_mapped_buffer_range(t, 1, 2, &m);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.flush_mapped_buffer_range(t, 4, 3, &m);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.flush_mapped_buffer_range(t, -1, 1, &m);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        assert!(ctx.unmap_buffer(t, &m));
        assert_eq!(
            ctx.get_buffer_sub_data(t, 0, 8),
            vec![0, 0, 0, 5, 5, 2, 3, 4]
        );
        // Flushing a mapping without the flush bit, or no mapping.
        ctx.map_buffer_range(t, 0, 8, GL_MAP_WRITE_BIT).unwrap();
        ctx.flush_mapped_buffer_range(t, 0, 1, &[0; 8]);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        // glBufferData ends the mapping without an error.
        ctx.buffer_data(t, 2, None, GL_STATIC_DRAW);
        assert_eq!(ctx.buffer_mapping(ctx.bound_buffer(t)), None);
        ctx.flush_mapped_buffer_range(t, 0, 1, &[0; 8]);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        // glMapBuffer is the whole store with the bits of its enum.
        assert_eq!(ctx.map_buffer(t, GL_READ_WRITE), Some(vec![0, 0]));
        assert_eq!(
            ctx.get_buffer_parameter(t, GL_BUFFER_ACCESS_FLAGS),
            Some((GL_MAP_READ_BIT | GL_MAP_WRITE_BIT) as i64)
        );
        assert!(ctx.unmap_buffer(t, &[1, 2]));
        assert_eq!(ctx.map_buffer(t, GL_LESS), None);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        assert_eq!(ctx.get_buffer_sub_data(t, 0, 2), vec![1, 2]);
    }

    #[test]
    fn copy_buffer_sub_data_and_its_errors() {
        let mut ctx = Context::new(4, 4);
        let r = buffer(&mut ctx, GL_COPY_READ_BUFFER, &[1, 2, 3, 4, 5, 6]);
        ctx.copy_buffer_sub_data(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, 1);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        let w = buffer(&mut ctx, GL_COPY_WRITE_BUFFER, &[0; 4]);
        assert_ne!(r, w);
        ctx.copy_buffer_sub_data(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 2, 1, 3);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(
            ctx.get_buffer_sub_data(GL_COPY_WRITE_BUFFER, 0, 4),
            vec![0, 3, 4, 5]
        );
        for (ro, wo, n) in [(-1, 0, 1), (0, -1, 1), (0, 0, -1), (4, 0, 3), (0, 2, 3)] {
            ctx.copy_buffer_sub_data(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, ro, wo, n);
            assert_eq!(ctx.get_error(), GL_INVALID_VALUE, "{ro} {wo} {n}");
        }
        ctx.copy_buffer_sub_data(GL_COPY_READ_BUFFER, 0x1234, 0, 0, 1);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        // Within one buffer: overlapping ranges are an error, others copy.
        ctx.copy_buffer_sub_data(GL_COPY_READ_BUFFER, GL_COPY_READ_BUFFER, 0, 2, 3);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.copy_buffer_sub_data(GL_COPY_READ_BUFFER, GL_COPY_READ_BUFFER, 0, 3, 3);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(
            ctx.get_buffer_sub_data(GL_COPY_READ_BUFFER, 0, 6),
            vec![1, 2, 3, 1, 2, 3]
        );
    }

    #[test]
    fn new_targets_and_indexed_bindings() {
        let mut ctx = Context::new(4, 4);
        for (target, binding) in [
            (GL_UNIFORM_BUFFER, GL_UNIFORM_BUFFER_BINDING),
            (GL_COPY_READ_BUFFER, GL_COPY_READ_BUFFER),
            (GL_COPY_WRITE_BUFFER, GL_COPY_WRITE_BUFFER),
            (GL_TEXTURE_BUFFER, GL_TEXTURE_BUFFER),
            (
                GL_TRANSFORM_FEEDBACK_BUFFER,
                GL_TRANSFORM_FEEDBACK_BUFFER_BINDING,
            ),
        ] {
            let b = buffer(&mut ctx, target, &[0; 64]);
            assert_eq!(ctx.get_integerv(binding), vec![b as i32]);
            assert_eq!(ctx.get_buffer_parameter(target, GL_BUFFER_SIZE), Some(64));
        }
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        let b = ctx.bound_buffer(GL_COPY_READ_BUFFER);
        let u = GL_UNIFORM_BUFFER;
        ctx.bind_buffer_range(u, 3, b, 16, 32);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(ctx.get_integerv(GL_UNIFORM_BUFFER_BINDING), vec![b as i32]);
        assert_eq!(
            ctx.get_integeri(GL_UNIFORM_BUFFER_BINDING, 3),
            Some(b as i32)
        );
        assert_eq!(ctx.get_integeri(GL_UNIFORM_BUFFER_START, 3), Some(16));
        assert_eq!(
            ctx.get_integer64_indexed(GL_UNIFORM_BUFFER_SIZE, 3),
            Some(32)
        );
        assert_eq!(ctx.get_integeri(GL_UNIFORM_BUFFER_BINDING, 2), Some(0));
        ctx.bind_buffer_base(u, 35, b);
        assert_eq!(ctx.get_integeri(GL_UNIFORM_BUFFER_SIZE, 35), Some(0));
        assert_eq!(
            ctx.get_integeri(GL_UNIFORM_BUFFER_BINDING, 35),
            Some(b as i32)
        );
        assert_eq!(ctx.get_integeri(GL_UNIFORM_BUFFER_BINDING, 36), None);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        assert_eq!(ctx.get_integeri(GL_VIEWPORT, 0), None);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        for (target, index, offset, size, err) in [
            (GL_ARRAY_BUFFER, 0, 0, 16, GL_INVALID_ENUM),
            (u, 36, 0, 16, GL_INVALID_VALUE),
            (u, 0, 0, 0, GL_INVALID_VALUE),
            (u, 0, -16, 16, GL_INVALID_VALUE),
            (u, 0, 8, 16, GL_INVALID_VALUE),
            (u, 0, 48, 32, GL_INVALID_VALUE),
            (GL_TRANSFORM_FEEDBACK_BUFFER, 4, 0, 16, GL_INVALID_VALUE),
            (GL_TRANSFORM_FEEDBACK_BUFFER, 0, 2, 16, GL_INVALID_VALUE),
            (GL_TRANSFORM_FEEDBACK_BUFFER, 0, 4, 6, GL_INVALID_VALUE),
        ] {
            ctx.bind_buffer_range(target, index, b, offset, size);
            assert_eq!(ctx.get_error(), err, "{target:#x} {index} {offset} {size}");
        }
        ctx.bind_buffer_range(GL_TRANSFORM_FEEDBACK_BUFFER, 3, b, 4, 8);
        assert_eq!(
            ctx.get_integeri(GL_TRANSFORM_FEEDBACK_BUFFER_START, 3),
            Some(4)
        );
        assert_eq!(
            ctx.get_integeri(GL_TRANSFORM_FEEDBACK_BUFFER_SIZE, 3),
            Some(8)
        );
        // Deleting the buffer clears every binding of it.
        ctx.delete_buffers(&[b]);
        assert_eq!(ctx.get_integeri(GL_UNIFORM_BUFFER_BINDING, 3), Some(0));
        assert_eq!(ctx.get_integeri(GL_UNIFORM_BUFFER_START, 3), Some(0));
        assert_eq!(
            ctx.get_integeri(GL_TRANSFORM_FEEDBACK_BUFFER_BINDING, 3),
            Some(0)
        );
        assert_eq!(ctx.get_integerv(GL_COPY_READ_BUFFER), vec![0]);
        // The limits.
        assert_eq!(ctx.get_integerv(GL_MAX_UNIFORM_BUFFER_BINDINGS), vec![36]);
        assert_eq!(
            ctx.get_integerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT),
            vec![16]
        );
        assert_eq!(ctx.get_integer64v(GL_MAX_UNIFORM_BLOCK_SIZE), vec![65536]);
        assert_eq!(ctx.get_integerv(GL_MAX_FRAGMENT_UNIFORM_BLOCKS), vec![12]);
        assert_eq!(ctx.get_integerv(GL_MAX_COMBINED_UNIFORM_BLOCKS), vec![36]);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
    }
}
