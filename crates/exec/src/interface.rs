//! The stage interface: where inputs, outputs and uniforms live, and the
//! flattened layout of values shared by registers, inputs, outputs and
//! uniform words.
//!
//! Layout: the one of [`glsl::ir::ConstValue`] (vectors in order, matrices
//! column-major, arrays element by element, structs member by member), with
//! one difference: a sampler occupies one component (its texture unit),
//! where `glsl::consteval::flat_size` counts none (constants never hold
//! samplers).

use glsl::types::{ArraySize, Base, Scalar, StructDef, Type};

/// One interface variable.
#[derive(Clone, Debug, PartialEq)]
pub struct Slot {
    pub name: String,
    pub ty: Type,
    /// Index of the first component in `Batch::inputs`, `Batch::outputs` or
    /// the uniform words.
    pub offset: usize,
    pub components: usize,
    /// Outputs: statically written by the shader. Inputs and uniforms:
    /// `true` when the program reads them.
    pub written: bool,
    /// `layout(location = N)` of a user fragment output (its draw buffer)
    /// or vertex input.
    pub location: Option<u32>,
    /// `layout(index = N)` of a user fragment output: 1 is the second
    /// source colour of its location's draw buffer (dual-source blending).
    pub index: Option<u32>,
    /// The interpolation qualifier of a varying (`flat`: the provoking
    /// vertex's value, not interpolated).
    pub interpolation: Option<glsl::ir::Interpolation>,
    /// For a member of an input or output block without an instance name:
    /// the block's name. The slot keeps the member's own name (its name
    /// in the GL API), while stages match it as `Block.member`, as they
    /// do the members of a named instance (see [`Slot::link_name`]).
    pub block: Option<String>,
}

impl Slot {
    /// The name by which a vertex output feeds the fragment input of the
    /// same name: blocks match by block name whatever their instance names,
    /// or whether they have one (GLSL 1.50 §4.3.7), so a member of a block
    /// is `Block.member` either way.
    pub fn link_name(&self) -> std::borrow::Cow<'_, str> {
        match &self.block {
            Some(b) => format!("{b}.{}", self.name).into(),
            None => self.name.as_str().into(),
        }
    }
}

/// Where each interface variable lives (see the crate docs).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Interface {
    pub inputs: Vec<Slot>,
    pub outputs: Vec<Slot>,
    pub uniforms: Vec<Slot>,
    /// Length of the uniform word array `Kernel::run` expects.
    pub uniform_words: usize,
    /// Number of `Batch::inputs` / `Batch::outputs` entries.
    pub input_components: usize,
    pub output_components: usize,
    /// The module's struct table (for [`Interface::locate_uniform`] and to
    /// spell struct types).
    pub structs: Vec<StructDef>,
    /// A geometry kernel's emitted vertices: where they are among the
    /// outputs (`None` for the other stages).
    pub emitted: Option<Emitted>,
    /// The memory spaces of the stage's shader storage blocks, by space
    /// number ([`crate::Memory`]): each block element's name as GL names
    /// it (`Block`, `Block[2]`), whose binding gives the buffer.
    pub buffers: Vec<String>,
    /// The bytes a compute work group's `shared` variables take
    /// ([`crate::SHARED_SPACE`], laid out by std430).
    pub shared_bytes: u32,
    /// A compute kernel's work-group size.
    pub local_size: Option<[u32; 3]>,
}

/// One vertex's share of a geometry kernel's input array: the input
/// components `offset..offset + components` take vertex `vertex`'s
/// output whose [`Slot::link_name`] is `name`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VertexInput {
    pub vertex: usize,
    pub name: String,
    /// The input array's `layout(location = N)`
    /// (GL_ARB_separate_shader_objects), which it matches outputs by
    /// instead of `name`.
    pub location: Option<u32>,
    pub offset: usize,
    pub components: usize,
}

impl Interface {
    /// A geometry kernel's per-vertex inputs (its input arrays, one
    /// element per vertex of the input primitive): the members of
    /// `gl_in[]` by member name, each element of a user array (of structs
    /// too) by the array's name (GL_EXT_geometry_shader4's built-in arrays
    /// by the output they take: `gl_PositionIn` is `gl_Position`...; its
    /// two-dimensional inputs are arrays of a one-member struct laid out
    /// as the output's array, so `gl_TexCoordIn[i]` takes vertex i's
    /// `gl_TexCoord`, at most as many components as either has), each
    /// member of an arrayed input block (slots named `Block[i].member`)
    /// as `Block.member`. Inputs that are not arrays (`gl_PrimitiveIDIn`)
    /// are not listed.
    pub fn vertex_inputs(&self) -> Vec<VertexInput> {
        let mut out = Vec::new();
        for slot in &self.inputs {
            if let Some((block, rest)) = slot.name.split_once('[') {
                // A member of an arrayed block instance: `Block[i].member`,
                // vertex i's `Block.member`; of an array of arrays of
                // instances, `Block[i][j].member`, vertex i's
                // `Block[j].member`.
                if let Some((index, after)) = rest.split_once(']') {
                    if let Ok(vertex) = index.parse() {
                        out.push(VertexInput {
                            vertex,
                            name: format!("{block}{after}"),
                            location: None,
                            offset: slot.offset,
                            components: slot.components,
                        });
                    }
                }
                continue;
            }
            let Some(ArraySize::Sized(n)) = slot.ty.array else {
                continue;
            };
            let elem = slot.ty.element();
            let per = size_of(elem, &self.structs);
            for vertex in 0..n as usize {
                let at = slot.offset + vertex * per;
                match elem.base {
                    // `gl_in[]`'s members are the vertex stage's built-in
                    // outputs of their names; a user array of structs is
                    // one output per vertex, like any other.
                    Base::Struct(id) if slot.name == "gl_in" => {
                        let Some(def) = self.structs.get(id.0 as usize) else {
                            continue;
                        };
                        let mut offset = at;
                        for m in &def.members {
                            let components = size_of(m.ty, &self.structs);
                            out.push(VertexInput {
                                vertex,
                                name: m.name.clone(),
                                location: None,
                                offset,
                                components,
                            });
                            offset += components;
                        }
                    }
                    _ => out.push(VertexInput {
                        vertex,
                        name: per_vertex_name(&slot.link_name()).to_string(),
                        location: slot.location,
                        offset: at,
                        components: per,
                    }),
                }
            }
        }
        out
    }

    /// The output of this (earlier) stage that an input of the next stage
    /// reads, with the component of the output where the input starts:
    /// for an input with `layout(location = N)`, the output that holds
    /// location N (an array or matrix output takes one location per
    /// element or column from its own; GL_ARB_separate_shader_objects'
    /// matching "by location", whatever the names), else the output of
    /// the same [`Slot::link_name`].
    pub fn output_for(&self, link_name: &str, location: Option<u32>) -> Option<(&Slot, usize)> {
        let Some(l) = location else {
            return self
                .outputs
                .iter()
                .find(|s| s.link_name() == link_name)
                .map(|s| (s, 0));
        };
        self.outputs.iter().find_map(|s| {
            let first = s.location?;
            let columns = match s.ty.base {
                Base::Matrix { cols, .. } => cols as usize,
                _ => 1,
            };
            let locations = columns
                * match s.ty.array {
                    Some(ArraySize::Sized(n)) => n as usize,
                    _ => 1,
                };
            let k = l.checked_sub(first)? as usize;
            (k < locations).then(|| (s, k * (s.components / locations.max(1))))
        })
    }
}

/// The vertex output a geometry input array takes: GL_EXT_geometry_shader4
/// names its built-in inputs after the outputs with `In` appended
/// (`gl_PositionIn[]`, `gl_FrontColorIn[]`...).
fn per_vertex_name(input: &str) -> &str {
    match input.strip_suffix("In") {
        Some(output) if input.starts_with("gl_") => output,
        _ => input,
    }
}

/// Where a geometry kernel's outputs hold what each invocation emitted.
///
/// [`Interface::outputs`] describes one vertex (`vertex_components`
/// components, the output variables as `EmitVertex` found them); the
/// batch's outputs hold `max_vertices` such vertices one after the other
/// ([`Emitted::vertex`]), then each vertex's strip number
/// ([`Emitted::strip`]: vertices of one output strip share it, and
/// `EndPrimitive` moves to the next), then the number of vertices the
/// lane emitted ([`Emitted::count`], at most `max_vertices`: the
/// `EmitVertex` calls beyond it are dropped, GLSL 1.50 §8.10). Strip
/// numbers and the count are ints (their bits, as int outputs are).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Emitted {
    pub input: glsl::ir::InputPrimitive,
    pub output: glsl::ir::OutputPrimitive,
    pub max_vertices: usize,
    pub vertex_components: usize,
}

impl Emitted {
    /// The output component where emitted vertex `v` starts.
    pub fn vertex(&self, v: usize) -> usize {
        v * self.vertex_components
    }

    /// The output component holding emitted vertex `v`'s strip number.
    pub fn strip(&self, v: usize) -> usize {
        self.max_vertices * self.vertex_components + v
    }

    /// The output component holding the number of emitted vertices.
    pub fn count(&self) -> usize {
        self.max_vertices * (self.vertex_components + 1)
    }

    /// All output components of the kernel.
    pub fn components(&self) -> usize {
        self.count() + 1
    }
}

impl Interface {
    pub fn input(&self, name: &str) -> Option<&Slot> {
        self.inputs.iter().find(|s| s.name == name)
    }

    pub fn output(&self, name: &str) -> Option<&Slot> {
        self.outputs.iter().find(|s| s.name == name)
    }

    pub fn uniform(&self, name: &str) -> Option<&Slot> {
        self.uniforms.iter().find(|s| s.name == name)
    }

    /// Resolves a GL uniform name such as `a`, `a[2]`, `s.m`, `l[1].pos`
    /// to the word offset and type of what it names (GL 2.1 §2.15.3: array
    /// elements and struct members; an array name alone names the whole
    /// array, i.e. its element 0 onwards). Out-of-range indices give `None`.
    pub fn locate_uniform(&self, path: &str) -> Option<(usize, Type)> {
        let path = path.trim();
        let end = path.find(['[', '.']).unwrap_or(path.len());
        let slot = self.uniform(&path[..end])?;
        let mut rest = &path[end..];
        let mut offset = slot.offset;
        let mut ty = slot.ty;
        while !rest.is_empty() {
            if let Some(r) = rest.strip_prefix('[') {
                let close = r.find(']')?;
                let index: usize = r[..close].trim().parse().ok()?;
                let n = match ty.array {
                    Some(ArraySize::Sized(n)) => n as usize,
                    _ => return None,
                };
                if index >= n {
                    return None;
                }
                let elem = ty.element();
                offset += index * size_of(elem, &self.structs);
                ty = elem;
                rest = &r[close + 1..];
            } else if let Some(r) = rest.strip_prefix('.') {
                let end = r.find(['[', '.']).unwrap_or(r.len());
                let name = &r[..end];
                let Base::Struct(id) = ty.base else {
                    return None;
                };
                if ty.is_array() {
                    return None;
                }
                let def = self.structs.get(id.0 as usize)?;
                let mut member_offset = 0;
                let mut found = None;
                for m in &def.members {
                    if m.name == name {
                        found = Some(m.ty);
                        break;
                    }
                    member_offset += size_of(m.ty, &self.structs);
                }
                ty = found?;
                offset += member_offset;
                rest = &r[end..];
            } else {
                return None;
            }
        }
        Some((offset, ty))
    }
}

/// Components of `ty` in the flattened layout (samplers count 1; unsized
/// arrays 0).
pub fn size_of(ty: Type, structs: &[StructDef]) -> usize {
    size_bounded(ty, structs, 0)
}

fn size_bounded(ty: Type, structs: &[StructDef], depth: u32) -> usize {
    if depth > 64 {
        return 0;
    }
    let elem = match ty.base {
        Base::Void | Base::Error => 0,
        Base::Sampler(_) | Base::Scalar(_) => 1,
        Base::Vector(_, n) => n as usize,
        Base::Matrix { cols, rows } => cols as usize * rows as usize,
        Base::Struct(id) => structs
            .get(id.0 as usize)
            .map(|s| {
                s.members
                    .iter()
                    .map(|m| size_bounded(m.ty, structs, depth + 1))
                    .fold(0usize, usize::saturating_add)
            })
            .unwrap_or(0),
    };
    match ty.array {
        None => elem,
        Some(ArraySize::Sized(n)) => elem.saturating_mul(n as usize),
        Some(ArraySize::Unsized) => 0,
    }
}

/// The scalar kind of each flattened component of `ty` (samplers are
/// `Int`: a unit number).
pub fn kinds(ty: Type, structs: &[StructDef]) -> Vec<Scalar> {
    let mut out = Vec::new();
    push_kinds(ty, structs, &mut out, 0);
    out
}

fn push_kinds(ty: Type, structs: &[StructDef], out: &mut Vec<Scalar>, depth: u32) {
    if depth > 64 {
        return;
    }
    let count = match ty.array {
        None => 1,
        Some(ArraySize::Sized(n)) => n as usize,
        Some(ArraySize::Unsized) => 0,
    };
    for _ in 0..count {
        match ty.base {
            Base::Void | Base::Error => {}
            Base::Sampler(_) => out.push(Scalar::Int),
            Base::Scalar(s) => out.push(s),
            Base::Vector(s, n) => out.extend(std::iter::repeat_n(s, n as usize)),
            Base::Matrix { cols, rows } => out.extend(std::iter::repeat_n(
                Scalar::Float,
                cols as usize * rows as usize,
            )),
            Base::Struct(id) => {
                if let Some(def) = structs.get(id.0 as usize) {
                    for m in &def.members {
                        push_kinds(m.ty, structs, out, depth + 1);
                    }
                }
            }
        }
    }
}
