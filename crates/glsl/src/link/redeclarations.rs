//! Built-in redeclarations that every object of a stage must agree on:
//! `gl_FragCoord`'s layout (GLSL 1.50 §7.2), the output and input
//! `gl_PerVertex` blocks (1.50 §7.1, also between the vertex and geometry
//! stages, and the sizes of `gl_in[]`'s unsized members), and the
//! geometry shader's input and output layouts.

use super::{push, LinkDiagnostic};
use crate::diag::Code;
use crate::ir::{self, Expr, ExprKind, Global, Module, Storage};
use crate::limits;
use crate::types::{ArraySize, Base, StructId, Type};

/// GLSL 1.50 §4.3.8.1: once one fragment shader object redeclares
/// `gl_FragCoord`, every object that statically uses it redeclares it.
pub(super) fn check_frag_coord_redeclared(
    objects: &[(usize, &ir::Module)],
    diags: &mut Vec<LinkDiagnostic>,
) -> bool {
    if !objects.iter().any(|(_, m)| m.frag_coord.redeclared) {
        return true;
    }
    let mut ok = true;
    for &(obj, m) in objects {
        let uses = m
            .globals
            .iter()
            .any(|g| g.builtin && g.name == "gl_FragCoord" && (g.read || g.written));
        if uses && !m.frag_coord.redeclared {
            ok = false;
            push(
                diags,
                Some(obj),
                Code::LinkInterfaceMismatch,
                "this fragment shader object uses `gl_FragCoord' without redeclaring it, while another redeclares it; redeclare it the same way in every object that uses it",
            );
        }
    }
    ok
}

/// GLSL 1.50 §7.1: once one object of a stage redeclares the output
/// `gl_PerVertex`, every object that uses a member of it redeclares it,
/// all the same way. The stage's redeclaration, or `None` after an error.
pub(super) fn check_per_vertex_redeclared(
    objects: &[(usize, &ir::Module)],
    diags: &mut Vec<LinkDiagnostic>,
) -> Option<Option<Vec<ir::BlockMember>>> {
    let Some(&(_, first)) = objects.iter().find(|(_, m)| m.per_vertex_out.is_some()) else {
        return Some(None);
    };
    let members = first.per_vertex_out.as_ref()?;
    // The built-in outputs a redeclaration can name; a shader that uses
    // one without redeclaring sees the whole built-in block.
    let block_member = |g: &Global| {
        g.builtin
            && matches!(
                g.name.as_str(),
                "gl_Position"
                    | "gl_PointSize"
                    | "gl_ClipDistance"
                    | "gl_ClipVertex"
                    | "gl_FrontColor"
                    | "gl_BackColor"
                    | "gl_FrontSecondaryColor"
                    | "gl_BackSecondaryColor"
                    | "gl_TexCoord"
                    | "gl_FogFragCoord"
                    | "gl_out"
            )
    };
    let mut ok = true;
    for &(obj, m) in objects {
        let stage = m.stage.name();
        match &m.per_vertex_out {
            Some(other) => {
                let same = other.len() == members.len()
                    && other.iter().zip(members).all(|(a, b)| {
                        a.name == b.name && m.type_name(a.ty) == first.type_name(b.ty)
                    });
                if !same {
                    ok = false;
                    push(
                        diags,
                        Some(obj),
                        Code::LinkInterfaceMismatch,
                        format!("this {stage} shader object redeclares `gl_PerVertex' with other members than another object of the stage"),
                    );
                }
            }
            None => {
                if let Some(g) = m
                    .globals
                    .iter()
                    .find(|g| block_member(g) && (g.read || g.written))
                {
                    ok = false;
                    push(
                        diags,
                        Some(obj),
                        Code::LinkInterfaceMismatch,
                        format!(
                            "this {stage} shader object uses `{}' without redeclaring `gl_PerVertex', while another object of the stage redeclares it; redeclare it the same way in every object that uses its members",
                            g.name
                        ),
                    );
                }
            }
        }
    }
    ok.then(|| Some(members.clone()))
}

/// A linked geometry stage has an input primitive, an output primitive
/// and `max_vertices` (GL 3.2 §2.12.2); its input arrays take the input
/// primitive's size, which a sized one must have. False on an error.
pub(super) fn check_geometry_layout(merged: &mut Module, diags: &mut Vec<LinkDiagnostic>) -> bool {
    let g = merged.geometry;
    let missing: Vec<&str> = [
        g.input
            .is_none()
            .then_some("an input primitive (`layout(triangles) in;')"),
        g.output
            .is_none()
            .then_some("an output primitive (`layout(triangle_strip) out;')"),
        g.max_vertices
            .is_none()
            .then_some("`max_vertices' (`layout(max_vertices = 3) out;')"),
    ]
    .into_iter()
    .flatten()
    .collect();
    if !missing.is_empty() {
        push(
            diags,
            None,
            Code::LinkInterfaceMismatch,
            format!(
                "no geometry shader object declares {}",
                missing.join(", nor ")
            ),
        );
        return false;
    }
    let Some(n) = g.input.map(ir::InputPrimitive::vertices) else {
        return false;
    };
    size_per_vertex_globals(merged, Storage::PerVertexInput, n, diags, |name, len| {
        format!(
            "geometry input `{name}' has {len} elements, but the input primitive has {n} vertices"
        )
    })
}

/// Gives the unsized per-vertex arrays of `storage` (and their block
/// instances) `n` elements at link; false, with `message(name, len)`
/// pushed, for one sized otherwise.
pub(super) fn size_per_vertex_globals(
    merged: &mut Module,
    storage: Storage,
    n: u32,
    diags: &mut Vec<LinkDiagnostic>,
    message: impl Fn(&str, u32) -> String,
) -> bool {
    let mut ok = true;
    for gl in merged.globals.iter_mut().filter(|x| x.storage == storage) {
        match gl.ty.array {
            Some(ArraySize::Unsized) => gl.ty.array = Some(ArraySize::Sized(n)),
            Some(ArraySize::Sized(len)) if len != n => {
                ok = false;
                push(
                    diags,
                    None,
                    Code::LinkInterfaceMismatch,
                    message(&gl.name, len),
                );
            }
            _ => {}
        }
    }
    for b in merged.blocks.iter_mut() {
        if b.storage == storage && b.instance.is_some() {
            b.array = Some(n);
        }
    }
    ok
}

/// Whether a geometry module statically uses the built-in `gl_in[]`.
pub(super) fn reads_gl_in(m: &ir::Module) -> bool {
    m.globals
        .iter()
        .any(|g| g.builtin && g.storage == Storage::PerVertexInput && g.name == "gl_in" && g.read)
}

/// GLSL 1.50 §7.1, for the geometry stage's input block: once one object
/// redeclares `in gl_PerVertex { ... } gl_in[];`, every object that uses
/// `gl_in` redeclares it, all the same way. The stage's redeclaration, or
/// `None` after an error.
pub(super) fn check_per_vertex_in_redeclared(
    objects: &[(usize, &ir::Module)],
    diags: &mut Vec<LinkDiagnostic>,
) -> Option<Option<Vec<ir::BlockMember>>> {
    let Some(&(_, first)) = objects.iter().find(|(_, m)| m.per_vertex_in.is_some()) else {
        return Some(None);
    };
    let members = first.per_vertex_in.as_ref()?;
    let mut ok = true;
    for &(obj, m) in objects {
        let stage = m.stage.name();
        match &m.per_vertex_in {
            Some(other) if !same_per_vertex(other, members) => {
                ok = false;
                push(
                    diags,
                    Some(obj),
                    Code::LinkInterfaceMismatch,
                    format!("this {stage} shader object redeclares the input block `gl_PerVertex' with other members than another object of the stage"),
                );
            }
            Some(_) => {}
            None if reads_gl_in(m) => {
                ok = false;
                push(
                    diags,
                    Some(obj),
                    Code::LinkInterfaceMismatch,
                    format!("this {stage} shader object uses `gl_in' without redeclaring the input block `gl_PerVertex', while another object of the stage redeclares it; redeclare it the same way in every object that uses `gl_in'"),
                );
            }
            None => {}
        }
    }
    ok.then(|| Some(members.clone()))
}

/// Two redeclarations of `gl_PerVertex` are the same block: the same
/// members, in order, of the same types (an unsized array matching any
/// size).
pub(super) fn same_per_vertex(a: &[ir::BlockMember], b: &[ir::BlockMember]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(x, y)| x.name == y.name && super::types::compatible_types(x.ty, y.ty))
}

/// The `gl_PerVertex` block between a stage and the next one that reads
/// `gl_in[]` (geometry, tessellation; GLSL 1.50 §7.1, §4.3.7 block
/// matching): when either stage redeclares it and the reader uses
/// `gl_in`, both redeclare it with the same members.
pub(super) fn check_per_vertex_interface(
    vm: &Module,
    gm: &Module,
    diags: &mut Vec<LinkDiagnostic>,
) {
    if !reads_gl_in(gm) {
        return;
    }
    let (p, c) = (vm.stage.name(), gm.stage.name());
    let msg = match (&vm.per_vertex_out, &gm.per_vertex_in) {
        (None, None) => return,
        (Some(a), Some(b)) if same_per_vertex(a, b) => return,
        (Some(_), Some(_)) => format!("the {p} shader's output block `gl_PerVertex' and the {c} shader's input block `gl_PerVertex' are redeclared with different members"),
        (Some(_), None) => format!("the {p} shader redeclares the output block `gl_PerVertex' but the {c} shader uses `gl_in' without redeclaring the input block the same way"),
        (None, Some(_)) => format!("the {c} shader redeclares the input block `gl_PerVertex' but the {p} shader does not redeclare its output block the same way"),
    };
    push(diags, None, Code::LinkInterfaceMismatch, msg);
}

/// The unsized arrays of `gl_in[]`'s members (the built-in block's
/// `gl_ClipDistance[]`, the compatibility profile's `gl_TexCoord[]`), and
/// the rows of GL_EXT_geometry_shader4's `gl_TexCoordIn[][]` and
/// `gl_ClipDistanceIn[][]`, take the size of the vertex stage's output of that name (GLSL 1.50
/// §7.1: an input block matches the output block it reads), else the
/// largest the output can have (gl_MaxClipDistances,
/// gl_MaxTextureCoords). Expressions reading the members take the sized
/// type.
pub(super) fn size_gl_in_members(gs: &mut Module, vs: Option<&Module>) {
    // `gl_in[]` (members named after the outputs they read), and
    // GL_EXT_geometry_shader4's `gl_TexCoordIn[][]` and
    // `gl_ClipDistanceIn[][]` (arrays of a row struct whose row reads the
    // output the input is named after, without `In`) alike.
    let sids: Vec<(StructId, Option<String>)> = gs
        .globals
        .iter()
        .filter(|g| {
            g.builtin
                && matches!(
                    g.storage,
                    Storage::PerVertexInput | Storage::PerVertexOutput
                )
        })
        .filter_map(|g| match g.ty.base {
            Base::Struct(sid) => Some((sid, g.name.strip_suffix("In").map(str::to_string))),
            _ => None,
        })
        .collect();
    for (sid, output) in sids {
        size_struct_members(gs, vs, sid, output.as_deref());
    }
}

/// Sizes the unsized members of struct `sid`, each from the vertex
/// output of its name, or, for a row struct, of `row_output`.
fn size_struct_members(
    gs: &mut Module,
    vs: Option<&Module>,
    sid: StructId,
    row_output: Option<&str>,
) {
    let Some(def) = gs.structs.get_mut(sid.0 as usize) else {
        return;
    };
    let row = def.array_row;
    let mut changed = false;
    for m in &mut def.members {
        if m.ty.array != Some(ArraySize::Unsized) {
            continue;
        }
        let name = match (row, row_output) {
            (true, Some(out)) => out.to_string(),
            (true, None) => continue,
            (false, _) => m.name.clone(),
        };
        let from_vs = vs.and_then(|v| {
            v.globals
                .iter()
                .find(|g| g.builtin && g.name == name)
                .and_then(|g| match g.ty.array {
                    Some(ArraySize::Sized(n)) => Some(n),
                    _ => None,
                })
        });
        let max = if name == "gl_TexCoord" {
            limits::MAX_TEXTURE_COORDS
        } else {
            limits::MAX_CLIP_DISTANCES
        };
        m.ty.array = Some(ArraySize::Sized(from_vs.unwrap_or(max)));
        changed = true;
    }
    if !changed {
        return;
    }
    let members: Vec<Type> = def.members.iter().map(|m| m.ty).collect();
    let fix = |e: &mut Expr| retype_members(e, sid, &members);
    for f in &mut gs.functions {
        if let Some(b) = &mut f.body {
            ir::for_each_block_expr_mut(b, &mut { fix });
        }
    }
}

fn retype_members(e: &mut Expr, sid: StructId, members: &[Type]) {
    if let ExprKind::Member { base, index } = &e.kind {
        if base.ty.base == Base::Struct(sid) && !base.ty.is_array() {
            if let Some(&ty) = members.get(*index as usize) {
                e.ty = ty;
            }
        }
    }
    e.for_each_child_mut(|c| retype_members(c, sid, members));
}
