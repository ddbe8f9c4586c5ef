//! Uniform storage of a linked program, locations and `glUniform*` checks
//! (GL 2.1 §2.15.3 "Uniform Variables").
//!
//! Every uniform global of the program gets a block of 32-bit words in
//! [`UniformTable::values`], flattened as `glsl::ir::ConstValue` is
//! (vectors in order, matrices column by column, arrays element by element,
//! structs member by member) with one word per sampler (its texture unit).
//! Words hold `f32::to_bits` for floats, `i32 as u32` for ints, 0/1 for
//! bools. At draw time each kernel's uniform slots are copied from here by
//! name.
//!
//! Locations index [`UniformTable::locations`]: one per element of every
//! leaf of basic type (scalar, vector, matrix, sampler), leaves found by
//! expanding structs and arrays of structs member by member.

use crate::uniform_block::{block_offsets, ActiveBlock, BlockGlobal, BlockLeaf};
use glsl::ir::{ConstScalar, InterfaceBlock, Module, Storage};
use glsl::types::{ArraySize, Base, Scalar, StructDef, Type};

/// Words a value of `ty` occupies: the executor's flattened layout
/// (samplers take one word), so the program's uniform storage and each
/// kernel's uniform words line up.
pub fn words(ty: Type, structs: &[StructDef]) -> usize {
    exec::size_of(ty, structs)
}

/// The element count of an array type.
pub fn array_len(ty: Type) -> Option<u32> {
    match ty.array {
        Some(ArraySize::Sized(n)) => Some(n),
        Some(ArraySize::Unsized) => Some(0),
        None => None,
    }
}

/// One uniform global of the program.
#[derive(Clone, Debug)]
pub struct UniformGlobal {
    pub name: String,
    pub ty: Type,
    /// Index of the stage whose module declares the type (for structs).
    pub stage: usize,
    pub offset: usize,
    pub words: usize,
    pub builtin: bool,
}

/// An active uniform as glGetActiveUniform reports it: a leaf of basic type
/// (or an array of one).
#[derive(Clone, Debug)]
pub struct Leaf {
    /// `"s[1].a"` (arrays without `"[0]"`).
    pub name: String,
    /// The element type (no array).
    pub ty: Type,
    /// Array length, if the leaf is an array.
    pub array: Option<u32>,
    pub offset: usize,
    /// Words per element.
    pub elem_words: usize,
    /// Index of the first location of this leaf ([`NO_LOCATION`] for a
    /// block member).
    pub first_location: usize,
    /// Where a member of a uniform block lives in its buffer (`None` in
    /// the default block).
    pub block: Option<BlockLeaf>,
}

/// The `first_location` and `offset` of a block member leaf: block members
/// have neither a location nor words of their own in
/// [`UniformTable::values`].
pub const NO_LOCATION: usize = usize::MAX;

/// A uniform location: element `element` of leaf `leaf`.
#[derive(Clone, Copy, Debug)]
pub struct Location {
    pub leaf: usize,
    pub element: u32,
}

#[derive(Clone, Debug, Default)]
pub struct UniformTable {
    pub globals: Vec<UniformGlobal>,
    /// The active uniforms: default-block leaves and block members.
    pub leaves: Vec<Leaf>,
    pub locations: Vec<Location>,
    pub values: Vec<u32>,
    /// The active uniform blocks ([`crate::uniform_block`]).
    pub blocks: Vec<ActiveBlock>,
    /// The executor globals whose words come from uniform buffers.
    pub block_globals: Vec<BlockGlobal>,
}

/// Scalar kind of a value passed to glUniform*.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SetterKind {
    Float,
    Int,
    /// glUniform*ui (GL 3.0).
    Uint,
    /// glUniformMatrix{cols}x{rows}fv.
    Matrix {
        cols: u8,
        rows: u8,
    },
}

/// Why a glUniform call was refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum UniformError {
    #[error("GL_INVALID_OPERATION")]
    InvalidOperation,
    #[error("GL_INVALID_VALUE")]
    InvalidValue,
}

/// The initial texture units of a sampler uniform declared with
/// `layout(binding = N)` (GL_ARB_shading_language_420pack): N, and N + i
/// for element i of an array (a sampler takes one word per element).
fn set_binding(g: &glsl::ir::Global, words: &mut [u32]) {
    if let Some(b) = g.binding {
        for (i, w) in words.iter_mut().enumerate() {
            *w = b.saturating_add(i as u32);
        }
    }
}

impl UniformTable {
    /// Builds the table from the linked stages' modules: every uniform
    /// global, vertex stage first, each name once. Every one gets storage;
    /// only those some stage reads or initializes are active (leaves and
    /// locations): GL 2.1 §2.15.3 leaves it to the implementation to call
    /// an unused uniform active, and Mesa's linker drops one no stage
    /// reads unless a stage gives it an initializer, which programs
    /// written against it expect (vispy warns of "unset variables" for an
    /// active uniform it never sets; piglit's uniform-initializer tests
    /// set unread initialized ones).
    pub fn build(stages: &[&Module]) -> UniformTable {
        let mut t = UniformTable::default();
        let active = |name: &str| {
            stages.iter().any(|m| {
                m.globals.iter().any(|g| {
                    g.storage == Storage::Uniform
                        && g.name == name
                        && (g.read || g.init.is_some() || g.location.is_some())
                })
            })
        };
        for (si, m) in stages.iter().enumerate() {
            for g in &m.globals {
                if g.storage != Storage::Uniform {
                    continue;
                }
                if let Some(b) = g.block.and_then(|b| m.blocks.get(b.0 as usize)) {
                    t.add_block(b, si, m, &g.name);
                    continue;
                }
                if let Some(u) = t.globals.iter().find(|u| u.name == g.name) {
                    // Declared by an earlier stage: this stage's initializer
                    // or binding still sets the shared value (the linker
                    // checked that those present in both stages agree).
                    let (offset, n) = (u.offset, u.words);
                    if let Some(init) = &g.init {
                        for (i, c) in init.components.iter().take(n).enumerate() {
                            if let Some(w) = t.values.get_mut(offset + i) {
                                *w = scalar_word(*c);
                            }
                        }
                    }
                    set_binding(g, &mut t.values[offset..offset + n]);
                    continue;
                }
                let n = words(g.ty, &m.structs);
                let offset = t.values.len();
                t.values.resize(offset + n, 0);
                if let Some(init) = &g.init {
                    for (i, c) in init.components.iter().take(n).enumerate() {
                        t.values[offset + i] = scalar_word(*c);
                    }
                }
                set_binding(g, &mut t.values[offset..offset + n]);
                t.globals.push(UniformGlobal {
                    name: g.name.clone(),
                    ty: g.ty,
                    stage: si,
                    offset,
                    words: n,
                    builtin: g.builtin,
                });
                if !g.builtin && active(&g.name) {
                    let mut leaves = Vec::new();
                    collect_leaves(&g.name, g.ty, offset, &m.structs, &mut leaves, 0);
                    for mut leaf in leaves {
                        leaf.first_location = t.locations.len();
                        let li = t.leaves.len();
                        for e in 0..leaf.array.unwrap_or(1) {
                            t.locations.push(Location {
                                leaf: li,
                                element: e,
                            });
                        }
                        t.leaves.push(leaf);
                    }
                }
            }
        }
        t
    }

    /// Adds uniform block `b` of stage `si` (module `m`) when first seen;
    /// a block another stage declared already is marked referenced by this
    /// one (the linker checked both declare it alike). `global` is the
    /// executor global of `b` being added: an instance or a member. Every
    /// one gets its [`BlockGlobal`], as the instance names of one block
    /// may differ between shader objects and stages (GLSL 1.50 §4.3.7).
    fn add_block(&mut self, b: &InterfaceBlock, si: usize, m: &Module, global: &str) {
        let stage_slot = match m.stage {
            glsl::Stage::Vertex => 0,
            glsl::Stage::Geometry => 1,
            _ => 2,
        };
        let elements = b.elements();
        let names: Vec<String> = (0..elements)
            .map(|e| format!("{}{}", b.name, b.element_suffix(e)))
            .collect();
        let members: Vec<(Type, bool)> = b.members.iter().map(|mb| (mb.ty, mb.row_major)).collect();
        let (offsets, data_size) = block_offsets(&members, &m.structs);
        let member = |i: usize| {
            let mb = &b.members[i];
            (mb.ty, offsets[i], mb.row_major)
        };
        if let Some(first) = self.blocks.iter().position(|x| x.name == names[0]) {
            for (e, blk) in self
                .blocks
                .iter_mut()
                .skip(first)
                .take(elements)
                .enumerate()
            {
                blk.referenced[stage_slot] = true;
                // A binding given only in a later stage holds for all
                // (the linker refused two different ones).
                if let Some(b) = b.binding {
                    blk.binding = b + e as u32;
                }
            }
            if self.block_globals.iter().any(|x| x.name == global) {
                return;
            }
            let bg = match &b.instance {
                Some(_) => BlockGlobal {
                    name: global.to_string(),
                    stage: si,
                    first_block: first,
                    elements,
                    members: (0..b.members.len()).map(member).collect(),
                },
                None => {
                    let Some(i) = b.members.iter().position(|mb| mb.name == global) else {
                        return;
                    };
                    BlockGlobal {
                        name: global.to_string(),
                        stage: si,
                        first_block: first,
                        elements: 1,
                        members: vec![member(i)],
                    }
                }
            };
            self.block_globals.push(bg);
            return;
        }
        let first_block = self.blocks.len();
        let mut leaves = Vec::new();
        for (mb, &off) in b.members.iter().zip(&offsets) {
            let name = match &b.instance {
                Some(_) => format!("{}.{}", b.name, mb.name),
                None => mb.name.clone(),
            };
            collect_block_leaves(
                &name,
                mb.ty,
                off,
                &m.structs,
                mb.row_major,
                first_block,
                &mut leaves,
                0,
            );
        }
        let first_leaf = self.leaves.len();
        let uniforms: Vec<usize> = (first_leaf..first_leaf + leaves.len()).collect();
        self.leaves.extend(leaves);
        for (e, name) in names.into_iter().enumerate() {
            let mut referenced = [false; 3];
            referenced[stage_slot] = true;
            self.blocks.push(ActiveBlock {
                name,
                data_size,
                // `layout(binding = N)`: element e of an arrayed
                // instance takes N + e; without one, binding point 0.
                binding: b.binding.map_or(0, |b| b + e as u32),
                referenced,
                uniforms: uniforms.clone(),
            });
        }
        match &b.instance {
            Some(_) => self.block_globals.push(BlockGlobal {
                name: global.to_string(),
                stage: si,
                first_block,
                elements,
                members: (0..b.members.len()).map(member).collect(),
            }),
            None => {
                for (i, mb) in b.members.iter().enumerate() {
                    self.block_globals.push(BlockGlobal {
                        name: mb.name.clone(),
                        stage: si,
                        first_block,
                        elements: 1,
                        members: vec![member(i)],
                    });
                }
            }
        }
    }

    /// The block global of an executor uniform, by name.
    pub fn block_global(&self, name: &str) -> Option<&BlockGlobal> {
        self.block_globals.iter().find(|g| g.name == name)
    }

    /// The index of the active uniform `name` (glGetUniformIndices): a
    /// leaf's name, or for an array leaf also `"name[0]"`.
    pub fn uniform_index(&self, name: &str) -> Option<usize> {
        self.leaves.iter().position(|l| {
            l.name == name
                || (l.array.is_some() && name.strip_suffix("[0]").is_some_and(|n| n == l.name))
        })
    }

    /// The GL name of leaf `i` (`"a[0]"` for arrays), as glGetActiveUniform
    /// and glGetActiveUniformName report it.
    pub fn leaf_name(&self, i: usize) -> Option<String> {
        let l = self.leaves.get(i)?;
        Some(if l.array.is_some() {
            format!("{}[0]", l.name)
        } else {
            l.name.clone()
        })
    }

    /// glGetUniformLocation's lookup (GL 2.1 §2.15.3): `name` is a leaf of
    /// basic type, optionally an element of it (`"a[2]"`); a leaf that is an
    /// array also answers to its bare name and to `"name[0]"`. Names that
    /// start with "gl_" have no location.
    pub fn location(&self, name: &str, stages: &[&Module]) -> i32 {
        if name.starts_with("gl_") {
            return -1;
        }
        let Some((head, mut rest)) = split_ident(name) else {
            return -1;
        };
        let Some(g) = self.globals.iter().find(|g| g.name == head && !g.builtin) else {
            return -1;
        };
        let Some(m) = stages.get(g.stage) else {
            return -1;
        };
        let structs = &m.structs;
        let mut ty = g.ty;
        let mut offset = g.offset;
        let mut element: u32 = 0;
        let mut indexed_leaf = false;
        while !rest.is_empty() {
            if indexed_leaf {
                return -1;
            }
            if let Some(r) = rest.strip_prefix('[') {
                let Some(end) = r.find(']') else { return -1 };
                let digits = &r[..end];
                if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
                    return -1;
                }
                let Ok(i) = digits.parse::<u32>() else {
                    return -1;
                };
                let Some(n) = array_len(ty) else { return -1 };
                if i >= n {
                    return -1;
                }
                let elem = ty.element();
                let ew = words(elem, structs);
                if let Some(row) = array_row(elem, structs) {
                    // An array of arrays: `a[i]` is the row, named without
                    // its member.
                    offset += ew * i as usize;
                    ty = row;
                } else if matches!(elem.base, Base::Struct(_)) {
                    offset += ew * i as usize;
                    ty = elem;
                } else {
                    // An element of a basic-typed array: the last part.
                    element = i;
                    ty = elem;
                    indexed_leaf = true;
                }
                rest = &r[end + 1..];
            } else if let Some(r) = rest.strip_prefix('.') {
                let Base::Struct(id) = ty.base else { return -1 };
                if ty.is_array() {
                    return -1;
                }
                let Some(s) = structs.get(id.0 as usize) else {
                    return -1;
                };
                let Some((member, r2)) = split_ident(r) else {
                    return -1;
                };
                let mut off = offset;
                let mut found = None;
                for mb in &s.members {
                    if mb.name == member {
                        found = Some(mb.ty);
                        break;
                    }
                    off += words(mb.ty, structs);
                }
                let Some(mty) = found else { return -1 };
                ty = mty;
                offset = off;
                rest = r2;
            } else {
                return -1;
            }
        }
        if matches!(ty.base, Base::Struct(_) | Base::Void | Base::Error) {
            return -1;
        }
        // `offset` is the leaf's start; find the leaf.
        match self
            .leaves
            .iter()
            .find(|l| l.offset == offset && l.block.is_none())
        {
            Some(l) => {
                if element >= l.array.unwrap_or(1) {
                    return -1;
                }
                (l.first_location + element as usize) as i32
            }
            None => -1,
        }
    }

    /// The leaf and element of a location.
    pub fn resolve(&self, loc: i32) -> Option<(&Leaf, u32)> {
        let l = self.locations.get(usize::try_from(loc).ok()?)?;
        Some((self.leaves.get(l.leaf)?, l.element))
    }

    /// glUniform*: stores `count` elements of `comps` components from
    /// `data` (already converted to words) at `loc`, after the checks of
    /// GL 2.1 §2.15.3. `raw` holds the values as f32 for bool conversion.
    pub fn set(
        &mut self,
        loc: i32,
        count: i32,
        kind: SetterKind,
        comps: usize,
        data: &[Word],
    ) -> Result<(), UniformError> {
        if count < 0 {
            return Err(UniformError::InvalidValue);
        }
        let (leaf, element) = self.resolve(loc).ok_or(UniformError::InvalidOperation)?;
        let ok = match (kind, leaf.ty.base) {
            (SetterKind::Float, Base::Scalar(s) | Base::Vector(s, _)) => {
                matches!(s, Scalar::Float | Scalar::Bool)
                    && leaf.ty.vector_size() == Some(comps as u8)
            }
            // Each setter family loads its own type and bool (GL 3.3
            // §2.11.4): glUniform*i ints, glUniform*ui uints.
            (SetterKind::Int, Base::Scalar(s) | Base::Vector(s, _)) => {
                matches!(s, Scalar::Int | Scalar::Bool)
                    && leaf.ty.vector_size() == Some(comps as u8)
            }
            (SetterKind::Uint, Base::Scalar(s) | Base::Vector(s, _)) => {
                matches!(s, Scalar::Uint | Scalar::Bool)
                    && leaf.ty.vector_size() == Some(comps as u8)
            }
            (SetterKind::Int, Base::Sampler(_)) => comps == 1,
            (SetterKind::Matrix { cols, rows }, Base::Matrix { cols: c, rows: r }) => {
                cols == c && rows == r
            }
            _ => false,
        };
        if !ok {
            return Err(UniformError::InvalidOperation);
        }
        if count > 1 && leaf.array.is_none() {
            return Err(UniformError::InvalidOperation);
        }
        let is_sampler = leaf.ty.is_sampler();
        let is_bool = leaf.ty.scalar() == Some(Scalar::Bool);
        let remaining = leaf.array.unwrap_or(1).saturating_sub(element) as usize;
        let n = (count as usize)
            .min(remaining)
            .min(data.len() / comps.max(1));
        if is_sampler
            && data[..n].iter().any(|w| match w {
                Word::Int(i) => *i < 0 || *i as usize >= crate::MAX_TEXTURE_IMAGE_UNITS,
                Word::Float(_) | Word::Uint(_) => true,
            })
        {
            return Err(UniformError::InvalidValue);
        }
        let base = leaf.offset + element as usize * leaf.elem_words;
        let total = n * comps;
        for (i, w) in data.iter().take(total).enumerate() {
            let bits = if is_bool {
                u32::from(w.is_true())
            } else {
                w.bits()
            };
            if let Some(slot) = self.values.get_mut(base + i) {
                *slot = bits;
            }
        }
        Ok(())
    }

    /// The words of one location (glGetUniform*), with its scalar kind.
    pub fn get(&self, loc: i32) -> Option<(Vec<u32>, Type)> {
        let (leaf, element) = self.resolve(loc)?;
        let base = leaf.offset + element as usize * leaf.elem_words;
        let v = self.values.get(base..base + leaf.elem_words)?.to_vec();
        Some((v, leaf.ty))
    }

    /// The words of a uniform global, by name.
    pub fn global_words(&self, name: &str) -> Option<&[u32]> {
        let g = self.globals.iter().find(|g| g.name == name)?;
        self.values.get(g.offset..g.offset + g.words)
    }
}

/// A value given to glUniform*.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Word {
    Float(f32),
    Int(i32),
    Uint(u32),
}

impl Word {
    fn bits(self) -> u32 {
        match self {
            Word::Float(f) => f.to_bits(),
            Word::Int(i) => i as u32,
            Word::Uint(u) => u,
        }
    }

    /// GL 2.1 §2.15.3: a bool uniform set from a float or int is false for
    /// 0 and true otherwise.
    fn is_true(self) -> bool {
        match self {
            Word::Float(f) => f != 0.0,
            Word::Int(i) => i != 0,
            Word::Uint(u) => u != 0,
        }
    }
}

pub fn scalar_word(c: ConstScalar) -> u32 {
    match c {
        ConstScalar::Float(f) => f.to_bits(),
        ConstScalar::Int(i) => i as u32,
        ConstScalar::Uint(u) => u,
        ConstScalar::Bool(b) => u32::from(b),
    }
}

fn split_ident(s: &str) -> Option<(&str, &str)> {
    let end = s
        .char_indices()
        .find(|(_, c)| !(c.is_ascii_alphanumeric() || *c == '_'))
        .map(|(i, _)| i)
        .unwrap_or(s.len());
    if end == 0 {
        None
    } else {
        Some((&s[..end], &s[end..]))
    }
}

/// The row an element of an array of arrays holds, for a row struct type
/// ([`glsl::types::StructDef::array_row`]).
fn array_row(ty: Type, structs: &[StructDef]) -> Option<Type> {
    let Base::Struct(id) = ty.base else {
        return None;
    };
    let s = structs.get(id.0 as usize)?;
    if !s.array_row || ty.is_array() {
        return None;
    }
    s.members.first().map(|m| m.ty)
}

/// The name of member `member` of a value of struct `s` named `base`:
/// `base.member`, or `base` itself for the row of an array of arrays
/// (`a[1]` of `float a[2][3]`, whose elements are then `a[1][0]`...), as
/// GL 4.3 §7.3.1 names the active variables of arrays of arrays.
fn member_name(base: &str, s: &StructDef, member: &str) -> String {
    if s.array_row {
        base.to_string()
    } else {
        format!("{base}.{member}")
    }
}

fn collect_leaves(
    name: &str,
    ty: Type,
    offset: usize,
    structs: &[StructDef],
    out: &mut Vec<Leaf>,
    depth: u32,
) {
    if depth > 32 {
        return;
    }
    match ty.base {
        Base::Struct(id) => {
            let Some(s) = structs.get(id.0 as usize) else {
                return;
            };
            let elem = ty.element();
            let ew = words(elem, structs);
            let (n, arr) = match array_len(ty) {
                Some(n) => (n, true),
                None => (1, false),
            };
            for i in 0..n {
                let base_name = if arr {
                    format!("{name}[{i}]")
                } else {
                    name.to_string()
                };
                let mut off = offset + ew * i as usize;
                for mb in &s.members {
                    collect_leaves(
                        &member_name(&base_name, s, &mb.name),
                        mb.ty,
                        off,
                        structs,
                        out,
                        depth + 1,
                    );
                    off += words(mb.ty, structs);
                }
            }
        }
        Base::Void | Base::Error => {}
        _ => {
            let elem = ty.element();
            out.push(Leaf {
                name: name.to_string(),
                ty: elem,
                array: array_len(ty),
                offset,
                elem_words: words(elem, structs),
                first_location: 0,
                block: None,
            });
        }
    }
}

/// The leaves of a block member of type `ty` at byte `offset` of block
/// `block`, named from `name` as [`collect_leaves`] names them.
#[allow(clippy::too_many_arguments)]
fn collect_block_leaves(
    name: &str,
    ty: Type,
    offset: usize,
    structs: &[StructDef],
    row_major: bool,
    block: usize,
    out: &mut Vec<Leaf>,
    depth: u32,
) {
    use crate::uniform_block::{array_layout, std140, MATRIX_STRIDE};
    if depth > 32 {
        return;
    }
    let elem = ty.element();
    let (_, stride) = array_layout(elem, structs, row_major);
    match ty.base {
        Base::Struct(id) => {
            let Some(s) = structs.get(id.0 as usize) else {
                return;
            };
            let (n, arr) = match array_len(ty) {
                Some(n) => (n, true),
                None => (1, false),
            };
            for i in 0..n as usize {
                let base_name = if arr {
                    format!("{name}[{i}]")
                } else {
                    name.to_string()
                };
                // Member offsets inside the struct, as std140 places them.
                let mut at = offset + i * stride;
                for mb in &s.members {
                    let (align, size) = std140(mb.ty, structs, row_major);
                    at = at.div_ceil(align) * align;
                    collect_block_leaves(
                        &member_name(&base_name, s, &mb.name),
                        mb.ty,
                        at,
                        structs,
                        row_major,
                        block,
                        out,
                        depth + 1,
                    );
                    at += size;
                }
            }
        }
        Base::Void | Base::Error => {}
        _ => {
            let is_matrix = matches!(elem.base, Base::Matrix { .. });
            out.push(Leaf {
                name: name.to_string(),
                ty: elem,
                array: array_len(ty),
                offset: NO_LOCATION,
                elem_words: words(elem, structs),
                first_location: NO_LOCATION,
                block: Some(BlockLeaf {
                    block,
                    offset,
                    array_stride: if ty.is_array() { stride } else { 0 },
                    matrix_stride: if is_matrix { MATRIX_STRIDE } else { 0 },
                    row_major: row_major && is_matrix,
                }),
            });
        }
    }
}

/// The GL type enum of a basic type (glGetActiveUniform / glGetActiveAttrib).
pub fn gl_type(ty: Type) -> u32 {
    use crate::enums::*;
    match ty.base {
        Base::Scalar(Scalar::Float) => GL_FLOAT,
        Base::Scalar(Scalar::Int) => GL_INT,
        Base::Scalar(Scalar::Uint) => GL_UNSIGNED_INT,
        Base::Scalar(Scalar::Bool) => GL_BOOL,
        Base::Vector(Scalar::Float, 2) => GL_FLOAT_VEC2,
        Base::Vector(Scalar::Float, 3) => GL_FLOAT_VEC3,
        Base::Vector(Scalar::Float, _) => GL_FLOAT_VEC4,
        Base::Vector(Scalar::Int, 2) => GL_INT_VEC2,
        Base::Vector(Scalar::Int, 3) => GL_INT_VEC3,
        Base::Vector(Scalar::Int, _) => GL_INT_VEC4,
        Base::Vector(Scalar::Uint, 2) => GL_UNSIGNED_INT_VEC2,
        Base::Vector(Scalar::Uint, 3) => GL_UNSIGNED_INT_VEC3,
        Base::Vector(Scalar::Uint, _) => GL_UNSIGNED_INT_VEC4,
        Base::Vector(Scalar::Bool, 2) => GL_BOOL_VEC2,
        Base::Vector(Scalar::Bool, 3) => GL_BOOL_VEC3,
        Base::Vector(Scalar::Bool, _) => GL_BOOL_VEC4,
        Base::Matrix { cols, rows } => match (cols, rows) {
            (2, 2) => GL_FLOAT_MAT2,
            (3, 3) => GL_FLOAT_MAT3,
            (4, 4) => GL_FLOAT_MAT4,
            (2, 3) => GL_FLOAT_MAT2x3,
            (2, 4) => GL_FLOAT_MAT2x4,
            (3, 2) => GL_FLOAT_MAT3x2,
            (3, 4) => GL_FLOAT_MAT3x4,
            (4, 2) => GL_FLOAT_MAT4x2,
            _ => GL_FLOAT_MAT4x3,
        },
        Base::Sampler(k) => {
            use glsl::types::SamplerKind::*;
            match k {
                Sampler1D => GL_SAMPLER_1D,
                Sampler2D => GL_SAMPLER_2D,
                Sampler3D => GL_SAMPLER_3D,
                SamplerCube => GL_SAMPLER_CUBE,
                Sampler1DShadow => GL_SAMPLER_1D_SHADOW,
                Sampler2DShadow => GL_SAMPLER_2D_SHADOW,
                SamplerCubeShadow => GL_SAMPLER_CUBE_SHADOW,
                Sampler1DArray => GL_SAMPLER_1D_ARRAY,
                Sampler2DArray => GL_SAMPLER_2D_ARRAY,
                Sampler1DArrayShadow => GL_SAMPLER_1D_ARRAY_SHADOW,
                Sampler2DArrayShadow => GL_SAMPLER_2D_ARRAY_SHADOW,
                ISampler1D => GL_INT_SAMPLER_1D,
                ISampler2D => GL_INT_SAMPLER_2D,
                ISampler3D => GL_INT_SAMPLER_3D,
                ISamplerCube => GL_INT_SAMPLER_CUBE,
                ISampler1DArray => GL_INT_SAMPLER_1D_ARRAY,
                ISampler2DArray => GL_INT_SAMPLER_2D_ARRAY,
                USampler1D => GL_UNSIGNED_INT_SAMPLER_1D,
                USampler2D => GL_UNSIGNED_INT_SAMPLER_2D,
                USampler3D => GL_UNSIGNED_INT_SAMPLER_3D,
                USamplerCube => GL_UNSIGNED_INT_SAMPLER_CUBE,
                USampler1DArray => GL_UNSIGNED_INT_SAMPLER_1D_ARRAY,
                USampler2DArray => GL_UNSIGNED_INT_SAMPLER_2D_ARRAY,
                // GL 3.1 and 3.2 values (ARB_texture_rectangle,
                // GL_EXT_texture_buffer_object, ARB_texture_multisample).
                Sampler2DRect => 0x8B63,
                Sampler2DRectShadow => 0x8B64,
                ISampler2DRect => GL_INT_SAMPLER_2D_RECT_EXT,
                USampler2DRect => GL_UNSIGNED_INT_SAMPLER_2D_RECT_EXT,
                SamplerBuffer => GL_SAMPLER_BUFFER_EXT,
                ISamplerBuffer => GL_INT_SAMPLER_BUFFER_EXT,
                USamplerBuffer => GL_UNSIGNED_INT_SAMPLER_BUFFER_EXT,
                Sampler2DMS => 0x9108,
                ISampler2DMS => 0x9109,
                USampler2DMS => 0x910A,
                Sampler2DMSArray => 0x910B,
                ISampler2DMSArray => 0x910C,
                USampler2DMSArray => 0x910D,
                SamplerCubeArray => GL_SAMPLER_CUBE_MAP_ARRAY_ARB,
                SamplerCubeArrayShadow => GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW_ARB,
                ISamplerCubeArray => GL_INT_SAMPLER_CUBE_MAP_ARRAY_ARB,
                USamplerCubeArray => GL_UNSIGNED_INT_SAMPLER_CUBE_MAP_ARRAY_ARB,
            }
        }
        _ => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glsl::{compile, CompileOptions, Stage};

    fn table(src: &str) -> (UniformTable, Module) {
        let sh = compile(&[src], &CompileOptions::new(Stage::Fragment));
        assert!(sh.ok(), "{}", sh.info_log());
        let m = sh.module.unwrap();
        (UniformTable::build(&[&m]), m)
    }

    const SRC: &str = "#version 120
struct S { float a; vec2 b[3]; };
uniform S s[2];
uniform mat2x3 m;
uniform vec4 v[4];
uniform bool flag;
uniform sampler2D tex;
uniform float init = 2.5;
void main() { gl_FragColor = vec4(s[1].b[2], v[3].x, m[0].x) + texture2D(tex, vec2(init)) * float(flag); }
";

    #[test]
    fn initializer_from_a_later_stage_sets_the_shared_uniform() {
        // piglit uniform-initializer/vs-*-set-by-other-stage.
        let vs = compile(
            &["uniform float u; void main() { gl_Position = vec4(u); }"],
            &CompileOptions::new(Stage::Vertex),
        );
        let (_, fm) =
            table("#version 120\nuniform float u = 2.5;\nvoid main() { gl_FragColor = vec4(u); }");
        let vm = vs.module.unwrap();
        let t = UniformTable::build(&[&vm, &fm]);
        let u = t.globals.iter().find(|g| g.name == "u").unwrap();
        assert_eq!(t.values[u.offset], 2.5f32.to_bits());
    }

    #[test]
    fn locations_follow_paths() {
        let (t, m) = table(SRC);
        let st = [&m];
        let s1b = t.location("s[1].b", &st);
        assert!(s1b >= 0);
        assert_eq!(t.location("s[1].b[0]", &st), s1b);
        assert_eq!(t.location("s[1].b[2]", &st), s1b + 2);
        assert_eq!(t.location("s[1].b[3]", &st), -1);
        assert_eq!(t.location("s[1]", &st), -1);
        assert_eq!(t.location("s", &st), -1);
        assert_eq!(t.location("s[2].a", &st), -1);
        assert_eq!(t.location("s.a", &st), -1);
        assert_eq!(t.location("m[0]", &st), -1);
        let v = t.location("v", &st);
        assert_eq!(t.location("v[0]", &st), v);
        assert_eq!(t.location("v[3]", &st), v + 3);
        assert_eq!(t.location("v[3]x", &st), -1);
        assert_eq!(t.location("gl_ModelViewMatrix", &st), -1);
        assert_eq!(t.location("nothing", &st), -1);
        // 2 structs x (1 + 3) + 1 + 4 + 1 + 1 + 1 locations.
        assert_eq!(t.locations.len(), 16);
        assert_eq!(t.leaves[0].name, "s[0].a");
        assert_eq!(t.leaves[1].name, "s[0].b");
    }

    #[test]
    fn setter_type_checks() {
        let (mut t, m) = table(SRC);
        let st = [&m];
        let v = t.location("v[2]", &st);
        let f4 = [Word::Float(1.0); 12];
        // Clamped to the 2 remaining elements.
        assert_eq!(t.set(v, 3, SetterKind::Float, 4, &f4), Ok(()));
        assert_eq!(
            t.set(v, 1, SetterKind::Float, 3, &f4),
            Err(UniformError::InvalidOperation)
        );
        assert_eq!(
            t.set(v, 1, SetterKind::Int, 4, &[Word::Int(1); 4]),
            Err(UniformError::InvalidOperation)
        );
        assert_eq!(
            t.set(v, -1, SetterKind::Float, 4, &f4),
            Err(UniformError::InvalidValue)
        );
        let flag = t.location("flag", &st);
        assert_eq!(
            t.set(flag, 1, SetterKind::Float, 1, &[Word::Float(0.5)]),
            Ok(())
        );
        assert_eq!(t.get(flag).unwrap().0, vec![1]);
        assert_eq!(t.set(flag, 1, SetterKind::Int, 1, &[Word::Int(0)]), Ok(()));
        assert_eq!(t.get(flag).unwrap().0, vec![0]);
        assert_eq!(
            t.set(flag, 2, SetterKind::Int, 1, &[Word::Int(0); 2]),
            Err(UniformError::InvalidOperation)
        );
        let tex = t.location("tex", &st);
        assert_eq!(t.set(tex, 1, SetterKind::Int, 1, &[Word::Int(3)]), Ok(()));
        assert_eq!(
            t.set(tex, 1, SetterKind::Float, 1, &[Word::Float(3.0)]),
            Err(UniformError::InvalidOperation)
        );
        assert_eq!(
            t.set(tex, 1, SetterKind::Int, 1, &[Word::Int(-1)]),
            Err(UniformError::InvalidValue)
        );
        let mm = t.location("m", &st);
        assert_eq!(
            t.set(
                mm,
                1,
                SetterKind::Matrix { cols: 3, rows: 2 },
                6,
                &[Word::Float(1.0); 6]
            ),
            Err(UniformError::InvalidOperation)
        );
        assert_eq!(
            t.set(
                mm,
                1,
                SetterKind::Matrix { cols: 2, rows: 3 },
                6,
                &[Word::Float(1.0); 6]
            ),
            Ok(())
        );
        assert_eq!(
            t.set(999, 1, SetterKind::Float, 1, &f4),
            Err(UniformError::InvalidOperation)
        );
        let init = t.location("init", &st);
        assert_eq!(t.get(init).unwrap().0, vec![2.5f32.to_bits()]);
    }
}
