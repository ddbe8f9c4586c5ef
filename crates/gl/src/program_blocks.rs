//! The uniform-block entry points of a program (GL 3.3 §2.11.4):
//! glGetUniformBlockIndex, glGetActiveUniformBlockiv,
//! glGetActiveUniformBlockName, glUniformBlockBinding,
//! glGetUniformIndices, glGetActiveUniformsiv, glGetActiveUniformName;
//! and the words of block members for a draw, read from the buffers bound
//! to the blocks' binding points ([`crate::uniform_block`] has the layout).

use crate::buffers::MAX_UNIFORM_BUFFER_BINDINGS;
use crate::enums::*;
use crate::uniform::{gl_type, UniformTable};
use crate::uniform_block::{decode, BlockGlobal, INVALID_INDEX};
use crate::Context;
use glsl::types::StructDef;

impl Context {
    /// The words of a block global for a draw, read from the buffers bound
    /// to its blocks' binding points.
    pub(crate) fn block_global_words(
        &self,
        table: &UniformTable,
        g: &BlockGlobal,
        structs: &[StructDef],
    ) -> Vec<u32> {
        let mut out = Vec::new();
        for e in 0..g.elements {
            let binding = table
                .blocks
                .get(g.first_block + e)
                .map_or(u32::MAX, |b| b.binding);
            let (store, start, end) = self.uniform_binding_bytes(binding as usize);
            let bytes = &store[start..end];
            for &(ty, off, rm) in &g.members {
                decode(ty, structs, rm, off, bytes, &mut out);
            }
        }
        out
    }
}

impl Context {
    /// `f` of a program's uniform table (empty before a successful link);
    /// `None` after the program name's error.
    fn uniform_table_query<R>(
        &mut self,
        program: u32,
        f: impl FnOnce(&UniformTable) -> R,
    ) -> Option<R> {
        let empty = UniformTable::default();
        self.program_query(program, |p| match &p.exe {
            Some(e) => f(&e.uniforms),
            None => f(&empty),
        })
    }

    /// glGetUniformBlockIndex ([`INVALID_INDEX`] for a name that is not an
    /// active block's, or after an error).
    pub fn get_uniform_block_index(&mut self, program: u32, name: &str) -> u32 {
        self.uniform_table_query(program, |t| {
            t.blocks
                .iter()
                .position(|b| b.name == name)
                .map_or(INVALID_INDEX, |i| i as u32)
        })
        .unwrap_or(INVALID_INDEX)
    }

    /// glGetActiveUniformBlockName (`GL_INVALID_VALUE` for an index past
    /// the active blocks).
    pub fn get_active_uniform_block_name(&mut self, program: u32, index: u32) -> Option<String> {
        let r = self.uniform_table_query(program, |t| {
            t.blocks.get(index as usize).map(|b| b.name.clone())
        })?;
        if r.is_none() {
            self.set_error(GL_INVALID_VALUE);
        }
        r
    }

    /// glGetActiveUniformBlockiv: the values of `pname` for block `index`
    /// (several for GL_UNIFORM_BLOCK_ACTIVE_UNIFORM_INDICES).
    pub fn get_active_uniform_blockiv(
        &mut self,
        program: u32,
        index: u32,
        pname: u32,
    ) -> Option<Vec<i32>> {
        let r = self.uniform_table_query(program, |t| {
            let Some(b) = t.blocks.get(index as usize) else {
                return Err(GL_INVALID_VALUE);
            };
            Ok(match pname {
                GL_UNIFORM_BLOCK_BINDING => vec![b.binding as i32],
                GL_UNIFORM_BLOCK_DATA_SIZE => vec![b.data_size as i32],
                GL_UNIFORM_BLOCK_NAME_LENGTH => vec![b.name.len() as i32 + 1],
                GL_UNIFORM_BLOCK_ACTIVE_UNIFORMS => vec![b.uniforms.len() as i32],
                GL_UNIFORM_BLOCK_ACTIVE_UNIFORM_INDICES => {
                    b.uniforms.iter().map(|&u| u as i32).collect()
                }
                GL_UNIFORM_BLOCK_REFERENCED_BY_VERTEX_SHADER => vec![b.referenced[0] as i32],
                GL_UNIFORM_BLOCK_REFERENCED_BY_GEOMETRY_SHADER => vec![b.referenced[1] as i32],
                GL_UNIFORM_BLOCK_REFERENCED_BY_FRAGMENT_SHADER => vec![b.referenced[2] as i32],
                _ => return Err(GL_INVALID_ENUM),
            })
        })?;
        r.map_err(|e| self.set_error(e)).ok()
    }

    /// glUniformBlockBinding (GL 3.3 §2.11.4).
    pub fn uniform_block_binding(&mut self, program: u32, index: u32, binding: u32) {
        if self.reject_in_begin() {
            return;
        }
        let Some(n) = self.uniform_table_query(program, |t| t.blocks.len()) else {
            return;
        };
        if index as usize >= n || binding as usize >= MAX_UNIFORM_BUFFER_BINDINGS {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let block = self
            .programs
            .get_mut(&program)
            .and_then(|p| p.exe.as_mut())
            .and_then(|e| e.uniforms.blocks.get_mut(index as usize));
        if let Some(b) = block {
            b.binding = binding;
        }
    }

    /// glGetUniformIndices: the active uniform index of each name
    /// ([`INVALID_INDEX`] for the others); `None` after an error.
    pub fn get_uniform_indices(&mut self, program: u32, names: &[&str]) -> Option<Vec<u32>> {
        self.uniform_table_query(program, |t| {
            names
                .iter()
                .map(|n| t.uniform_index(n).map_or(INVALID_INDEX, |i| i as u32))
                .collect()
        })
    }

    /// glGetActiveUniformName (`GL_INVALID_VALUE` past the active
    /// uniforms).
    pub fn get_active_uniform_name(&mut self, program: u32, index: u32) -> Option<String> {
        let r = self.uniform_table_query(program, |t| t.leaf_name(index as usize))?;
        if r.is_none() {
            self.set_error(GL_INVALID_VALUE);
        }
        r
    }

    /// glGetActiveUniformsiv: `pname` of each uniform of `indices`
    /// (`GL_INVALID_VALUE` if one is past the active uniforms, and then
    /// nothing is returned). Default-block uniforms report -1 for the
    /// block index, offset and strides (GL 3.3 §2.11.4).
    pub fn get_active_uniformsiv(
        &mut self,
        program: u32,
        indices: &[u32],
        pname: u32,
    ) -> Option<Vec<i32>> {
        let r = self.uniform_table_query(program, |t| {
            if !matches!(
                pname,
                GL_UNIFORM_TYPE
                    | GL_UNIFORM_SIZE
                    | GL_UNIFORM_NAME_LENGTH
                    | GL_UNIFORM_BLOCK_INDEX
                    | GL_UNIFORM_OFFSET
                    | GL_UNIFORM_ARRAY_STRIDE
                    | GL_UNIFORM_MATRIX_STRIDE
                    | GL_UNIFORM_IS_ROW_MAJOR
            ) {
                return Err(GL_INVALID_ENUM);
            }
            let mut out = Vec::with_capacity(indices.len());
            for &i in indices {
                let Some(l) = t.leaves.get(i as usize) else {
                    return Err(GL_INVALID_VALUE);
                };
                let b = l.block;
                out.push(match pname {
                    GL_UNIFORM_TYPE => gl_type(l.ty) as i32,
                    GL_UNIFORM_SIZE => l.array.unwrap_or(1) as i32,
                    GL_UNIFORM_NAME_LENGTH => {
                        t.leaf_name(i as usize).map_or(0, |n| n.len() as i32 + 1)
                    }
                    GL_UNIFORM_BLOCK_INDEX => b.map_or(-1, |b| b.block as i32),
                    GL_UNIFORM_OFFSET => b.map_or(-1, |b| b.offset as i32),
                    GL_UNIFORM_ARRAY_STRIDE => b.map_or(-1, |b| b.array_stride as i32),
                    GL_UNIFORM_MATRIX_STRIDE => b.map_or(-1, |b| b.matrix_stride as i32),
                    _ => b.is_some_and(|b| b.row_major) as i32,
                });
            }
            Ok(out)
        })?;
        r.map_err(|e| self.set_error(e)).ok()
    }
}
