//! Buffer objects (GL 2.1 §2.9): glGenBuffers, glBindBuffer,
//! glBufferData, glBufferSubData, glGetBufferSubData.
//!
//! Contract: a store is an `Arc<[u8]>` replaced whole on every write, so a
//! draw (or a client-array copy) that holds the old store keeps it
//! unchanged. GL_ARRAY_BUFFER and GL_ELEMENT_ARRAY_BUFFER bindings live in
//! the vertex-array state; the pixel pack/unpack bindings are only kept
//! (a C layer moves pixels through them).

use crate::enums::*;
use crate::objects::{delete_names, BufferObj};
use crate::Context;
use std::sync::Arc;

impl Context {
    /// glGenBuffers.
    pub fn gen_buffers(&mut self, n: i32) -> Vec<u32> {
        self.gen_objects(
            n,
            |o| (&mut o.buffers, &mut o.next_buffer),
            BufferObj::default,
        )
    }

    /// glDeleteBuffers (unbinds them).
    pub fn delete_buffers(&mut self, names: &[u32]) {
        let o = &mut self.objects;
        let bindings = &mut [
            &mut self.va.array_buffer,
            &mut self.va.element_buffer,
            &mut o.pack_buffer,
            &mut o.unpack_buffer,
        ];
        delete_names(&mut o.buffers, names, bindings);
    }

    /// The buffer bound to `target` (0: none or not a buffer target).
    pub fn bound_buffer(&self, target: u32) -> u32 {
        match target {
            GL_ARRAY_BUFFER => self.va.array_buffer,
            GL_ELEMENT_ARRAY_BUFFER => self.va.element_buffer,
            GL_PIXEL_PACK_BUFFER => self.objects.pack_buffer,
            GL_PIXEL_UNPACK_BUFFER => self.objects.unpack_buffer,
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

    /// glIsBuffer.
    pub fn is_buffer(&self, name: u32) -> bool {
        name != 0 && self.objects.buffers.contains_key(&name)
    }

    /// glBindBuffer (creates the object on first bind).
    pub fn bind_buffer(&mut self, target: u32, buffer: u32) {
        if self.reject_in_begin() {
            return;
        }
        let slot = match target {
            GL_ARRAY_BUFFER => &mut self.va.array_buffer,
            GL_ELEMENT_ARRAY_BUFFER => &mut self.va.element_buffer,
            GL_PIXEL_PACK_BUFFER => &mut self.objects.pack_buffer,
            GL_PIXEL_UNPACK_BUFFER => &mut self.objects.unpack_buffer,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return;
            }
        };
        *slot = buffer;
        if buffer != 0 {
            self.objects.buffers.entry(buffer).or_default();
        }
    }

    fn bound_buffer_name(&mut self, target: u32) -> Option<u32> {
        let b = match target {
            GL_ARRAY_BUFFER => self.va.array_buffer,
            GL_ELEMENT_ARRAY_BUFFER => self.va.element_buffer,
            GL_PIXEL_PACK_BUFFER => self.objects.pack_buffer,
            GL_PIXEL_UNPACK_BUFFER => self.objects.unpack_buffer,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        if b == 0 {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        Some(b)
    }

    /// glBufferData (`data` None: uninitialized, zeros here).
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
            },
        );
    }

    /// glBufferSubData.
    pub fn buffer_sub_data(&mut self, target: u32, offset: isize, data: &[u8]) {
        if self.reject_in_begin() {
            return;
        }
        let Some(b) = self.bound_buffer_name(target) else {
            return;
        };
        let Some(obj) = self.objects.buffers.get_mut(&b) else {
            return;
        };
        if offset < 0 || offset as usize + data.len() > obj.data.len() {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let mut v = obj.data.to_vec();
        v[offset as usize..offset as usize + data.len()].copy_from_slice(data);
        obj.data = Arc::from(v);
    }

    /// glGetBufferSubData.
    pub fn get_buffer_sub_data(&mut self, target: u32, offset: isize, size: isize) -> Vec<u8> {
        let Some(b) = self.bound_buffer_name(target) else {
            return Vec::new();
        };
        let data = self
            .objects
            .buffers
            .get(&b)
            .map(|o| o.data.clone())
            .unwrap_or_else(|| Arc::from(Vec::new()));
        if offset < 0 || size < 0 || offset as usize + size as usize > data.len() {
            self.set_error(GL_INVALID_VALUE);
            return Vec::new();
        }
        data[offset as usize..offset as usize + size as usize].to_vec()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
