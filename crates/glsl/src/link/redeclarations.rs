//! Built-in redeclarations that every object of a stage must agree on:
//! `gl_FragCoord`'s layout (GLSL 1.50 §7.2), `gl_PerVertex` (1.50 §7.1),
//! and the geometry shader's input and output layouts.

use super::{push, LinkDiagnostic};
use crate::diag::Code;
use crate::ir::{self, Global, Module, Storage};
use crate::types::ArraySize;

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
    let mut ok = true;
    for gl in merged
        .globals
        .iter_mut()
        .filter(|x| x.storage == Storage::GeometryInput)
    {
        match gl.ty.array {
            Some(ArraySize::Unsized) => gl.ty.array = Some(ArraySize::Sized(n)),
            Some(ArraySize::Sized(len)) if len != n => {
                ok = false;
                push(
                    diags,
                    None,
                    Code::LinkInterfaceMismatch,
                    format!(
                        "geometry input `{}' has {len} elements, but the input primitive has {n} vertices",
                        gl.name
                    ),
                );
            }
            _ => {}
        }
    }
    for b in merged.blocks.iter_mut() {
        if b.storage == Storage::GeometryInput && b.instance.is_some() {
            b.array = Some(n);
        }
    }
    ok
}
