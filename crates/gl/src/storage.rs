//! Shader storage buffers and compute dispatches
//! (GL_ARB_shader_storage_buffer_object and GL_ARB_compute_shader, GL
//! 4.3's, offered on 3.3 contexts): a program's storage blocks and their
//! binding points (glShaderStorageBlockBinding), the memory a draw or a
//! dispatch reads and writes, glDispatchCompute(Indirect),
//! glMemoryBarrier, and the limits.
//!
//! Contract: a command's memory (`BufferMemory`) copies the bound range
//! of every buffer a kernel's blocks name when the command starts, the
//! kernels read and write the copy (each stage its own spaces,
//! `exec::buffer_space`), and the buffers written get their new bytes
//! when it ends; two blocks bound to one buffer share one copy. A
//! command whose program writes memory shades on one thread, in a fixed
//! order, so its results (atomics included) are the same on every run
//! and machine. Work groups run one after the other, in x, then y, then
//! z order. Memory is coherent: glMemoryBarrier has nothing to wait for.
//! A dispatch of more than [`MAX_DISPATCH_INVOCATIONS`] invocations
//! ([`MAX_THREADED_DISPATCH_INVOCATIONS`] when its groups run on threads
//! of their own, `exec::Kernel::threads_per_group`) is not run (the draw
//! error says so): GL sets no bound, and one such call would take hours
//! on the CPU.

use crate::enums::*;
use crate::objects::IndexedBinding;
use crate::Context;
use glsl::ir::{Module, Storage};
use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

/// One active storage block element of a program (GL names an arrayed
/// instance's elements `B[0]`, `B[1]`...).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StorageBlock {
    pub name: String,
    /// The indexed GL_SHADER_STORAGE_BUFFER binding point it reads.
    pub binding: u32,
}

/// The storage blocks of a program's stages, each name once, in the
/// order the stages and their blocks come: their binding points start as
/// `layout(binding)` says (consecutive for an arrayed instance), else 0.
pub(crate) fn storage_blocks(modules: &[&Module]) -> Vec<StorageBlock> {
    let mut out: Vec<StorageBlock> = Vec::new();
    for m in modules {
        for b in m.blocks.iter().filter(|b| b.storage == Storage::Buffer) {
            for e in 0..b.elements().max(1) {
                let name = format!("{}{}", b.name, b.element_suffix(e));
                if out.iter().any(|x| x.name == name) {
                    continue;
                }
                let binding = b.binding.map_or(0, |first| first.saturating_add(e as u32));
                out.push(StorageBlock { name, binding });
            }
        }
    }
    out
}

/// The most invocations one dispatch runs (2^26: seconds of work).
pub const MAX_DISPATCH_INVOCATIONS: u64 = 1 << 26;
/// The most when every group starts a thread per batch (2^20: a second
/// of thread starts).
pub const MAX_THREADED_DISPATCH_INVOCATIONS: u64 = 1 << 20;

/// GL_MAX_SHADER_STORAGE_BLOCK_SIZE: 128 MiB (GL 4.3's minimum is
/// 16 MiB; llvmpipe's is 128 MiB).
const MAX_SHADER_STORAGE_BLOCK_SIZE: i64 = 1 << 27;

/// The storage and compute limits glGet answers on 3.3 contexts.
pub(crate) fn limit(pname: u32) -> Option<i64> {
    use glsl::limits as l;
    let blocks = l::MAX_SHADER_STORAGE_BUFFER_BINDINGS as i64;
    Some(match pname {
        GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS => blocks,
        GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS
        | GL_MAX_GEOMETRY_SHADER_STORAGE_BLOCKS
        | GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS
        | GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS
        | GL_MAX_COMBINED_SHADER_STORAGE_BLOCKS => blocks,
        GL_MAX_TESS_CONTROL_SHADER_STORAGE_BLOCKS
        | GL_MAX_TESS_EVALUATION_SHADER_STORAGE_BLOCKS => 0,
        GL_MAX_SHADER_STORAGE_BLOCK_SIZE => MAX_SHADER_STORAGE_BLOCK_SIZE,
        GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT => {
            crate::objects::SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT
        }
        GL_MAX_COMBINED_SHADER_OUTPUT_RESOURCES => blocks + crate::MAX_DRAW_BUFFERS as i64,
        GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS => l::MAX_COMPUTE_WORK_GROUP_INVOCATIONS as i64,
        GL_MAX_COMPUTE_SHARED_MEMORY_SIZE => l::MAX_COMPUTE_SHARED_MEMORY_SIZE as i64,
        GL_MAX_COMPUTE_UNIFORM_COMPONENTS => l::MAX_COMPUTE_UNIFORM_COMPONENTS as i64,
        GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS => l::MAX_COMPUTE_TEXTURE_IMAGE_UNITS as i64,
        GL_MAX_COMPUTE_UNIFORM_BLOCKS => l::MAX_UNIFORM_BUFFER_BINDINGS.min(14) as i64,
        GL_MAX_COMBINED_COMPUTE_UNIFORM_COMPONENTS => {
            l::MAX_COMPUTE_UNIFORM_COMPONENTS as i64 + 14 * 16384 / 4
        }
        GL_MAX_COMPUTE_IMAGE_UNIFORMS
        | GL_MAX_COMPUTE_ATOMIC_COUNTERS
        | GL_MAX_COMPUTE_ATOMIC_COUNTER_BUFFERS => 0,
        _ => return None,
    })
}

/// The memory of one draw or dispatch (see the module docs).
#[derive(Debug, Default)]
pub(crate) struct BufferMemory {
    /// Per space: (index in `buffers`, start, length) of its bound range.
    spaces: HashMap<u32, (usize, usize, usize)>,
    /// Each buffer named, with a copy of its store.
    buffers: Vec<(u32, Mutex<Vec<u8>>)>,
    written: AtomicBool,
}

impl BufferMemory {
    /// The word at `addr` of `space` as `f` sees it (`None` out of range).
    fn with_word<T>(&self, space: u32, addr: u32, f: impl FnOnce(Option<&mut [u8]>) -> T) -> T {
        let Some(&(b, start, len)) = self.spaces.get(&space) else {
            return f(None);
        };
        let addr = addr as usize;
        if addr.checked_add(4).is_none_or(|end| end > len) {
            return f(None);
        }
        let Some((_, bytes)) = self.buffers.get(b) else {
            return f(None);
        };
        let mut bytes = bytes.lock().unwrap_or_else(|e| e.into_inner());
        let at = start + addr;
        f(bytes.get_mut(at..at + 4))
    }

    /// A copy that writes nothing back (the debugger's replay).
    pub(crate) fn snapshot(&self) -> BufferMemory {
        BufferMemory {
            spaces: self.spaces.clone(),
            buffers: self
                .buffers
                .iter()
                .map(|(n, b)| {
                    let b = b.lock().unwrap_or_else(|e| e.into_inner()).clone();
                    (*n, Mutex::new(b))
                })
                .collect(),
            written: AtomicBool::new(false),
        }
    }
}

fn word(bytes: &[u8]) -> u32 {
    u32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]])
}

impl exec::Memory for BufferMemory {
    fn load(&self, space: u32, addr: u32) -> u32 {
        self.with_word(space, addr, |w| w.map_or(0, |w| word(w)))
    }

    fn store(&self, space: u32, addr: u32, value: u32) {
        self.with_word(space, addr, |w| {
            if let Some(w) = w {
                w.copy_from_slice(&value.to_le_bytes());
                self.written.store(true, Ordering::Relaxed);
            }
        })
    }

    fn atomic(&self, space: u32, addr: u32, op: exec::AtomicOp, a: u32, b: u32) -> u32 {
        self.with_word(space, addr, |w| match w {
            Some(w) => {
                let old = word(w);
                w.copy_from_slice(&op.apply(old, a, b).to_le_bytes());
                self.written.store(true, Ordering::Relaxed);
                old
            }
            None => 0,
        })
    }

    fn size(&self, space: u32) -> u32 {
        self.spaces
            .get(&space)
            .map_or(0, |&(_, _, len)| len.min(u32::MAX as usize) as u32)
    }
}

impl Context {
    /// The memory of a draw running `kernels` (`None` when none of them
    /// has a storage block, or none is bound).
    pub(crate) fn storage_memory(&self, kernels: &[&exec::Kernel]) -> Option<Arc<BufferMemory>> {
        self.storage_memory_of(kernels, |k| {
            self.kernel_executable(k).map(|e| &e.storage_blocks[..])
        })
    }

    /// [`Context::storage_memory`] with the storage blocks of each
    /// kernel's program from `blocks_of`.
    fn storage_memory_of<'a>(
        &'a self,
        kernels: &[&exec::Kernel],
        blocks_of: impl Fn(&exec::Kernel) -> Option<&'a [StorageBlock]>,
    ) -> Option<Arc<BufferMemory>> {
        let mut mem = BufferMemory::default();
        for k in kernels {
            let names = &k.interface().buffers;
            if names.is_empty() {
                continue;
            }
            let blocks = blocks_of(k);
            for (i, name) in names.iter().enumerate() {
                let binding = blocks
                    .and_then(|bs| bs.iter().find(|b| &b.name == name))
                    .map_or(u32::MAX, |b| b.binding);
                let Some(ib) = self.storage_binding(binding) else {
                    continue;
                };
                let store = self.buffer_store(ib.buffer);
                let start = (ib.offset.max(0) as usize).min(store.len());
                let end = match ib.size {
                    Some(s) => start.saturating_add(s.max(0) as usize).min(store.len()),
                    None => store.len(),
                };
                let slot = match mem.buffers.iter().position(|(n, _)| *n == ib.buffer) {
                    Some(s) => s,
                    None => {
                        mem.buffers.push((ib.buffer, Mutex::new(store.to_vec())));
                        mem.buffers.len() - 1
                    }
                };
                let space = exec::buffer_space(k.stage(), i as u32);
                mem.spaces.insert(space, (slot, start, end - start));
            }
        }
        (!mem.spaces.is_empty()).then(|| Arc::new(mem))
    }

    /// The buffer bound at storage binding point `index`, if any.
    fn storage_binding(&self, index: u32) -> Option<IndexedBinding> {
        self.objects
            .buffer_targets
            .storage_bindings
            .get(index as usize)
            .copied()
            .filter(|b| b.buffer != 0)
    }

    /// Gives the buffers a command wrote their new contents.
    pub(crate) fn store_storage_memory(&mut self, mem: &BufferMemory) {
        if !mem.written.load(Ordering::Relaxed) {
            return;
        }
        for (name, bytes) in &mem.buffers {
            let bytes = bytes.lock().unwrap_or_else(|e| e.into_inner());
            if let Some(b) = self.objects.buffers.get_mut(name) {
                if b.data.len() == bytes.len() {
                    b.data = Arc::from(&bytes[..]);
                }
            }
        }
    }

    /// glShaderStorageBlockBinding.
    pub fn shader_storage_block_binding(&mut self, program: u32, index: u32, binding: u32) {
        if !self.api.at_least(3, 3) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if self.linked_exe(program).is_none() {
            return;
        }
        let max = crate::objects::MAX_SHADER_STORAGE_BUFFER_BINDINGS as u32;
        let exe = self.programs.get_mut(&program).and_then(|p| p.exe.as_mut());
        match exe.and_then(|e| e.storage_blocks.get_mut(index as usize)) {
            Some(b) if binding < max => b.binding = binding,
            _ => self.set_error(GL_INVALID_VALUE),
        }
    }

    /// The index of a program's storage block `name`
    /// (glGetProgramResourceIndex with GL_SHADER_STORAGE_BLOCK);
    /// GL_INVALID_INDEX when it has none of that name.
    pub fn storage_block_index(&mut self, program: u32, name: &str) -> u32 {
        let Some(exe) = self.linked_exe(program) else {
            return u32::MAX;
        };
        let name = name
            .strip_suffix("[0]")
            .filter(|_| !exe.storage_blocks.iter().any(|b| b.name == name))
            .unwrap_or(name);
        exe.storage_blocks
            .iter()
            .position(|b| b.name == name)
            .map_or(u32::MAX, |i| i as u32)
    }

    /// glMemoryBarrier: every write is already visible (see the module
    /// docs); only the bits are checked.
    pub fn memory_barrier(&mut self, barriers: u32) {
        if !self.api.at_least(3, 3) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let _ = barriers;
    }

    /// glDispatchCompute.
    pub fn dispatch_compute(&mut self, x: u32, y: u32, z: u32) {
        self.dispatch([x, y, z]);
    }

    /// glDispatchComputeIndirect: the counts are three uints at `offset`
    /// of the buffer bound to GL_DISPATCH_INDIRECT_BUFFER.
    pub fn dispatch_compute_indirect(&mut self, offset: isize) {
        if !self.api.at_least(3, 3) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let b = self.objects.buffer_targets.dispatch_indirect;
        if offset < 0 || offset % 4 != 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let store = self.buffer_store(b);
        let at = offset as usize;
        if b == 0 || at.checked_add(12).is_none_or(|end| end > store.len()) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let counts = [0, 1, 2].map(|k| word(&store[at + 4 * k..at + 4 * k + 4]));
        self.dispatch(counts);
    }

    fn dispatch(&mut self, groups: [u32; 3]) {
        if self.reject_in_begin() {
            return;
        }
        if !self.api.at_least(3, 3) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let program = self.current_program;
        let cs = self
            .programs
            .get(&program)
            .and_then(|p| p.exe.as_ref())
            .and_then(|e| e.kernels.cs.clone());
        let Some(cs) = cs else {
            // No current program, or one without a compute stage.
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let max = glsl::limits::MAX_COMPUTE_WORK_GROUP_COUNT;
        if groups.iter().zip(max).any(|(&g, m)| g > m) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if groups.contains(&0) {
            return;
        }
        let per_group: u64 = cs
            .interface()
            .local_size
            .unwrap_or([1, 1, 1])
            .iter()
            .map(|&s| u64::from(s))
            .product();
        let total = groups.iter().map(|&g| u64::from(g)).product::<u64>() * per_group;
        let max = if cs.threads_per_group() {
            MAX_THREADED_DISPATCH_INVOCATIONS
        } else {
            MAX_DISPATCH_INVOCATIONS
        };
        if total > max {
            self.cache.error = Some(format!(
                "a dispatch of {total} invocations is more than shaderbox runs in one call ({max}{})",
                if max < MAX_DISPATCH_INVOCATIONS {
                    " for work groups larger than 16 invocations that call barrier()"
                } else {
                    ""
                }
            ));
            return;
        }
        let words = self.uniform_words(&cs, true);
        let mut units = self.texture_units();
        let blocks = self
            .programs
            .get(&program)
            .and_then(|p| p.exe.as_ref())
            .map(|e| &e.storage_blocks[..]);
        let mem = self.storage_memory_of(&[&cs], |_| blocks);
        units.memory = mem.clone().map(|m| m as Arc<dyn exec::Memory + Send>);
        let count = groups;
        'groups: for z in 0..groups[2] {
            for y in 0..groups[1] {
                for x in 0..groups[0] {
                    let group = exec::WorkGroup {
                        id: [x, y, z],
                        count,
                    };
                    if let Err(e) = exec::run_work_group(&cs, group, &words, &units) {
                        self.cache.error = Some(e.to_string());
                        break 'groups;
                    }
                }
            }
        }
        if let Some(m) = mem {
            self.store_storage_memory(&m);
        }
    }
}
