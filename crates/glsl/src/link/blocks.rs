//! Interface and uniform blocks at link time (GLSL 1.50 §4.3.7): the same
//! block across objects and stages, members sized by use, array sizes and
//! instance names compared.

use super::remap::{remap_type, Remap};
use super::types::compatible_types;
use super::{push, LinkDiagnostic};
use crate::diag::{Code, Diagnostic};
use crate::ir::{self, Module, Storage};
use crate::types::{ArraySize, Base};

/// Adds the interface blocks of object `obj` (module `m`, its globals
/// already merged through `map`) to `merged`: a block of the same name and
/// kind in another object must have the same members (GLSL 1.50 §4.3.7).
pub(super) fn merge_blocks(
    merged: &mut Module,
    m: &Module,
    map: &Remap,
    obj: usize,
    diags: &mut Vec<LinkDiagnostic>,
    errors: &mut bool,
) {
    for (bi, b) in m.blocks.iter().enumerate() {
        let members: Vec<ir::BlockMember> = b
            .members
            .iter()
            .map(|mb| ir::BlockMember {
                ty: remap_type(mb.ty, map),
                ..mb.clone()
            })
            .collect();
        let same_kind = |x: &ir::InterfaceBlock| {
            x.name == b.name && x.storage == b.storage && x.input == b.input
        };
        let id = match merged.blocks.iter().position(same_kind) {
            Some(i) => {
                let x = &merged.blocks[i];
                // The same block in two objects of a stage is one block:
                // an array in one is the same array in the other (GLSL
                // 1.50 §4.3.7); instance names may differ. A geometry
                // input array left unsized in an object without the input
                // layout takes the size the others give it (§4.3.8.1).
                let arrays_match = x.dims() == b.dims()
                    || (b.storage == Storage::PerVertexInput
                        && x.inner == b.inner
                        && (x.array.is_none() || b.array.is_none()));
                let bindings_differ = x.binding.zip(b.binding).is_some_and(|(p, q)| p != q);
                if !same_members(&x.members, &members, merged)
                    || x.layout != b.layout
                    || !arrays_match
                    || bindings_differ
                {
                    *errors = true;
                    diags.push(LinkDiagnostic {
                        shader: Some(obj),
                        diagnostic: Diagnostic::error(
                            Code::LinkInterfaceMismatch,
                            b.span,
                            format!(
                                "block `{}' is declared with different members, layout, binding or array size in two shader objects",
                                b.name
                            ),
                        ),
                    });
                }
                if merged.blocks[i].binding.is_none() {
                    merged.blocks[i].binding = b.binding;
                }
                for (x, y) in merged.blocks[i].members.iter_mut().zip(&members) {
                    x.implicit_size = x.implicit_size.max(y.implicit_size);
                }
                if merged.blocks[i].array.is_none() {
                    merged.blocks[i].array = b.array;
                }
                ir::BlockId(i as u32)
            }
            None => {
                merged.blocks.push(ir::InterfaceBlock {
                    members,
                    globals: Vec::new(),
                    ..b.clone()
                });
                ir::BlockId(merged.blocks.len() as u32 - 1)
            }
        };
        for (gi, g) in m.globals.iter().enumerate() {
            if g.block != Some(ir::BlockId(bi as u32)) {
                continue;
            }
            let Some(&mg) = map.globals.get(gi) else {
                continue;
            };
            merged.globals[mg.0 as usize].block = Some(id);
            let blk = &mut merged.blocks[id.0 as usize];
            if !blk.globals.contains(&mg) {
                blk.globals.push(mg);
            }
        }
    }
}

/// Unsized array members of input and output blocks take their size from
/// their use (GLSL 1.50 §4.3.7): without an instance name the member's
/// global is sized like any unsized array (before this runs); with one, the
/// largest constant index through the instance sizes the member in the
/// block and in the instance's struct. So do a shader storage block's
/// members but its last (GLSL 4.30 §4.3.9: the buffer sizes that one),
/// which must be indexed with a constant somewhere: the messages of the
/// ones that are not.
pub(super) fn size_block_members(merged: &mut Module) -> Vec<String> {
    let mut errors = Vec::new();
    for b in merged.blocks.iter_mut() {
        let buffer = b.storage == Storage::Buffer;
        let last = b.members.len().saturating_sub(1);
        for (k, mb) in b.members.iter_mut().enumerate() {
            if mb.ty.array != Some(ArraySize::Unsized) || (buffer && k == last) {
                continue;
            }
            match &b.instance {
                None => {
                    let gid = b
                        .globals
                        .iter()
                        .find(|g| merged.globals[g.0 as usize].name == mb.name)
                        .copied();
                    if let Some(g) = gid.map(|g| &mut merged.globals[g.0 as usize]) {
                        if buffer && g.ty.array == Some(ArraySize::Unsized) {
                            if g.implicit_size == 0 {
                                errors.push(unsized_member(&b.name, &mb.name));
                            }
                            g.ty.array = Some(ArraySize::Sized(g.implicit_size.max(1)));
                        }
                        mb.ty = g.ty;
                    }
                }
                Some(_) => {
                    if buffer && mb.implicit_size == 0 {
                        errors.push(unsized_member(&b.name, &mb.name));
                    }
                    let n = mb.implicit_size.max(1);
                    mb.ty.array = Some(ArraySize::Sized(n));
                    let mut instance = b.globals.first().map(|g| merged.globals[g.0 as usize].ty);
                    // An array of arrays of instances: its rows hold the
                    // block's struct.
                    for _ in 0..64 {
                        let row = instance.and_then(|t| ir::row_member(&merged.structs, t));
                        match row {
                            Some(r) => instance = Some(r),
                            None => break,
                        }
                    }
                    if let Some(Base::Struct(sid)) = instance.map(|t| t.base) {
                        if let Some(m) = merged
                            .structs
                            .get_mut(sid.0 as usize)
                            .and_then(|s| s.members.get_mut(k))
                        {
                            m.ty.array = Some(ArraySize::Sized(n));
                        }
                    }
                }
            }
        }
    }
    errors
}

fn unsized_member(block: &str, member: &str) -> String {
    format!("member `{member}' of shader storage block `{block}' has no size: only the last member takes the buffer's; give it one, or index it with constants only (its largest index sizes it)")
}

/// Block members match by name, type and qualifiers, in order.
pub(super) fn same_members(a: &[ir::BlockMember], b: &[ir::BlockMember], m: &Module) -> bool {
    a.len() == b.len()
        && a.iter().zip(b).all(|(x, y)| {
            x.name == y.name
                && compatible_types(x.ty, y.ty)
                && (x.ty == y.ty || m.type_name(x.ty) == m.type_name(y.ty))
                && x.row_major == y.row_major
                && x.interpolation == y.interpolation
                && x.centroid == y.centroid
        })
}

/// Blocks between two consecutive stages: an input block needs the
/// previous stage's output block of its name, and uniform blocks of one name have the same
/// members in both stages (GLSL 1.50 §4.3.7: matched by block name, not
/// instance name).
pub(super) fn check_blocks(vm: &Module, fm: &Module, diags: &mut Vec<LinkDiagnostic>) {
    compare_blocks(vm, fm, false, diags);
}

/// The uniform and shader storage blocks of [`check_blocks`] only: for
/// stages that are not consecutive, which share the program's uniform
/// and storage blocks but no input or output block.
pub(super) fn check_uniform_blocks(vm: &Module, fm: &Module, diags: &mut Vec<LinkDiagnostic>) {
    compare_blocks(vm, fm, true, diags);
}

fn compare_blocks(vm: &Module, fm: &Module, uniform_only: bool, diags: &mut Vec<LinkDiagnostic>) {
    let (pn, cn) = (vm.stage.name(), fm.stage.name());
    // Uniform and storage blocks are the program's: one name, one block
    // in every stage.
    let program_wide = |s: Storage| matches!(s, Storage::Uniform | Storage::Buffer);
    for fb in &fm.blocks {
        if uniform_only && !program_wide(fb.storage) {
            continue;
        }
        // An input block (a geometry shader's has its own storage)
        // matches the output block of its name.
        let kind = |x: &&ir::InterfaceBlock| {
            x.name == fb.name
                && if program_wide(fb.storage) {
                    x.storage == fb.storage
                } else {
                    matches!(x.storage, Storage::Varying | Storage::PerVertexOutput) && !x.input
                }
        };
        let vb = vm.blocks.iter().find(kind);
        let used = fb.globals.iter().any(|g| fm.global(*g).read);
        match vb {
            None if fb.input && used => push(
                diags,
                None,
                Code::LinkVaryingNotWritten,
                format!(
                    "the {cn} shader reads block `{}' but the {pn} shader has no output block of that name",
                    fb.name
                ),
            ),
            Some(vb) => {
                let same = vb.members.len() == fb.members.len()
                    && vb.members.iter().zip(&fb.members).all(|(a, b)| {
                        a.name == b.name
                            && vm.type_name(a.ty) == fm.type_name(b.ty)
                            && a.row_major == b.row_major
                            && a.interpolation == b.interpolation
                    })
                    && vb.layout == fb.layout
                    && vb.binding.zip(fb.binding).is_none_or(|(a, b)| a == b)
                    // A geometry input block is the array of the vertex
                    // stage's output block, one per vertex. Otherwise an
                    // array instance matches an array of the same size
                    // (GLSL 1.50 §4.3.7).
                    && if fb.storage == Storage::PerVertexInput {
                        // A control shader's per-vertex output block is an
                        // array of vertices too.
                        if vb.storage == Storage::PerVertexOutput {
                            vb.inner == fb.inner
                        } else {
                            vb.dims() == fb.inner
                        }
                    } else {
                        vb.dims() == fb.dims()
                    };
                if !same {
                    push(
                        diags,
                        None,
                        Code::LinkInterfaceMismatch,
                        format!(
                            "block `{}' has different members, bindings or array sizes in the {pn} and {cn} shaders",
                            fb.name
                        ),
                    );
                }
            }
            None => {}
        }
    }
}
