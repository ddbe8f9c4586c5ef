//! The interface between the stages and the program's limits: locations,
//! varyings matched by name and type (GLSL 1.20 §4.3.6), the built-in
//! colours' interpolation (1.30 §4.3.7), and the resource limits of
//! `crate::limits`.

use super::blocks::{check_blocks, check_uniform_blocks};
use super::types::{components, same_type_across, same_type_by_location};
use super::{push, LinkDiagnostic, LinkedStage};
use crate::diag::Code;
use crate::ir::{self, Stage, Storage};
use crate::limits;
use crate::types::{ArraySize, Base, Type};

/// Slots a vertex input or fragment output takes from its location on: one
/// per array element, and per matrix column.
pub(super) fn location_slots(ty: Type) -> u32 {
    let per = match ty.base {
        Base::Matrix { cols, .. } => cols as u32,
        _ => 1,
    };
    match ty.array {
        Some(ArraySize::Sized(n)) => per * n,
        _ => per,
    }
}

/// Explicit locations (GL_ARB_explicit_attrib_location, GLSL 3.30
/// §4.3.8): within the limits; fragment outputs may not share a location
/// and index (vertex inputs may: GL 2.0 allows aliasing attributes).
pub(super) fn check_locations(s: &LinkedStage, diags: &mut Vec<LinkDiagnostic>) {
    check_varying_locations(s, diags);
    let (storage, max, what) = match s.stage {
        Stage::Vertex => (
            Storage::Attribute,
            limits::MAX_VERTEX_ATTRIBS,
            "vertex input",
        ),
        Stage::Fragment => (
            Storage::FragOutput,
            limits::MAX_DRAW_BUFFERS,
            "fragment output",
        ),
        // Geometry inputs and outputs take no location before GLSL 4.10
        // (GL_ARB_separate_shader_objects); compute shaders have neither.
        Stage::TessControl | Stage::TessEvaluation | Stage::Geometry | Stage::Compute => return,
    };
    // Per `layout(index)` (0, or 1 for a second source colour).
    let mut used: [Vec<Option<&str>>; 2] = [vec![None; max as usize], vec![None; max as usize]];
    for g in s.module.globals.iter().filter(|g| g.storage == storage) {
        let Some(loc) = g.location else { continue };
        let used = &mut used[g.index.unwrap_or(0).min(1) as usize];
        let n = location_slots(g.ty);
        if u64::from(loc) + u64::from(n) > u64::from(max) {
            push(
                diags,
                None,
                Code::LinkTooMany,
                format!(
                    "{what} `{}' at location {loc} does not fit: there are {max} locations",
                    g.name
                ),
            );
            continue;
        }
        if s.stage == Stage::Fragment {
            if let Some(other) = claim(used, loc, n, &g.name) {
                push(
                    diags,
                    None,
                    Code::LinkInterfaceMismatch,
                    format!(
                        "fragment outputs `{other}' and `{}' are both assigned location {loc}{}",
                        g.name,
                        if g.index == Some(1) { ", index 1" } else { "" }
                    ),
                );
            }
        }
    }
    // GLSL 1.30 §7.2: user outputs and gl_FragColor/gl_FragData exclude
    // each other (checked here across the stage's shader objects).
    if s.stage == Stage::Fragment {
        let user = s
            .module
            .globals
            .iter()
            .find(|g| g.storage == Storage::FragOutput && g.written);
        let builtin = s.module.globals.iter().find(|g| {
            g.builtin && g.written && matches!(g.name.as_str(), "gl_FragColor" | "gl_FragData")
        });
        if let (Some(u), Some(b)) = (user, builtin) {
            push(
                diags,
                None,
                Code::LinkInterfaceMismatch,
                format!(
                    "the fragment shader writes both `{}' and the user output `{}'",
                    b.name, u.name
                ),
            );
        }
    }
}

/// Assigns locations `loc..loc + n` (within `used`) to `name`, up to the
/// first one another name holds: that name.
fn claim<'a>(used: &mut [Option<&'a str>], loc: u32, n: u32, name: &'a str) -> Option<&'a str> {
    for slot in &mut used[loc as usize..(loc + n) as usize] {
        if let Some(other) = *slot {
            return Some(other);
        }
        *slot = Some(name);
    }
    None
}

/// The locations of the inputs and outputs between stages
/// (GL_ARB_separate_shader_objects, GLSL 4.10 §4.3.8): within
/// [`limits::MAX_VARYING_LOCATIONS`], and no two outputs, nor two inputs,
/// of the stage on one location (a geometry input's locations are those
/// of one vertex's element).
fn check_varying_locations(s: &LinkedStage, diags: &mut Vec<LinkDiagnostic>) {
    let max = limits::MAX_VARYING_LOCATIONS;
    for storage in [Storage::Varying, Storage::PerVertexInput] {
        let mut used: Vec<Option<&str>> = vec![None; max as usize];
        for g in s.module.globals.iter().filter(|g| g.storage == storage) {
            let Some(loc) = g.location.filter(|_| !g.builtin) else {
                continue;
            };
            let ty = if storage == Storage::PerVertexInput {
                g.ty.element()
            } else {
                g.ty
            };
            let n = location_slots(ty);
            if u64::from(loc) + u64::from(n) > u64::from(max) {
                push(
                    diags,
                    None,
                    Code::LinkTooMany,
                    format!(
                        "`{}' at location {loc} does not fit: there are {max} locations between stages",
                        g.name
                    ),
                );
                continue;
            }
            if let Some(other) = claim(&mut used, loc, n, &g.name) {
                push(
                    diags,
                    None,
                    Code::LinkInterfaceMismatch,
                    format!(
                        "`{other}' and `{}' of the {} shader are both assigned location {loc}",
                        g.name,
                        s.stage.name()
                    ),
                );
            }
        }
    }
}

pub(super) fn check_limits(s: &LinkedStage, diags: &mut Vec<LinkDiagnostic>) {
    let m = &s.module;
    let mut limit = |what: &str, used: u32, max: u32| {
        if used > max {
            push(
                diags,
                None,
                Code::LinkTooMany,
                format!(
                    "the {} shader uses {used} {what}; the limit is {max}",
                    s.stage.name()
                ),
            );
        }
    };
    let uniforms: u32 = m
        .globals
        .iter()
        .filter(|g| g.storage == Storage::Uniform && g.read && !g.ty.is_sampler())
        .map(|g| components(m, g.ty))
        .sum();
    let samplers: u32 = m
        .globals
        .iter()
        .filter(|g| g.storage == Storage::Uniform && g.read && g.ty.is_sampler())
        .map(|g| match g.ty.array {
            Some(ArraySize::Sized(n)) => n,
            _ => 1,
        })
        .sum();
    match s.stage {
        Stage::Vertex => {
            limit(
                "uniform components",
                uniforms,
                limits::MAX_VERTEX_UNIFORM_COMPONENTS,
            );
            limit("samplers", samplers, limits::MAX_VERTEX_TEXTURE_IMAGE_UNITS);
            // Generic attributes: one slot per vector, one per matrix column.
            let slots: u32 = m
                .globals
                .iter()
                .filter(|g| g.storage == Storage::Attribute && !g.builtin && g.read)
                .map(|g| match g.ty.base {
                    Base::Matrix { cols, .. } => cols as u32,
                    _ => 1,
                })
                .sum();
            limit("attribute slots", slots, limits::MAX_VERTEX_ATTRIBS);
            let varyings: u32 = m
                .globals
                .iter()
                .filter(|g| g.storage == Storage::Varying && g.written)
                .map(|g| components(m, g.ty))
                .sum();
            let max = if m.language.version >= crate::lang::Version::V150 {
                limits::MAX_VERTEX_OUTPUT_COMPONENTS
            } else {
                limits::MAX_VARYING_FLOATS
            };
            limit("varying components", varyings, max);
        }
        Stage::Geometry => {
            limit(
                "uniform components",
                uniforms,
                limits::MAX_GEOMETRY_UNIFORM_COMPONENTS,
            );
            limit(
                "samplers",
                samplers,
                limits::MAX_GEOMETRY_TEXTURE_IMAGE_UNITS,
            );
            let outputs: u32 = m
                .globals
                .iter()
                .filter(|g| g.storage == Storage::Varying && !g.builtin && g.written)
                .map(|g| components(m, g.ty))
                .sum();
            limit(
                "output components",
                outputs,
                limits::MAX_GEOMETRY_OUTPUT_COMPONENTS,
            );
        }
        Stage::Fragment => {
            limit(
                "uniform components",
                uniforms,
                limits::MAX_FRAGMENT_UNIFORM_COMPONENTS,
            );
            limit("samplers", samplers, limits::MAX_TEXTURE_IMAGE_UNITS);
            let varyings: u32 = m
                .globals
                .iter()
                .filter(|g| {
                    g.storage == Storage::Varying
                        && g.read
                        && !matches!(
                            g.name.as_str(),
                            "gl_FragCoord" | "gl_FrontFacing" | "gl_PointCoord"
                        )
                })
                .map(|g| components(m, g.ty))
                .sum();
            // GL 3.2 gives stage inputs and outputs limits of their own,
            // above GL 2.1's varying floats.
            let max = if m.language.version >= crate::lang::Version::V150 {
                limits::MAX_FRAGMENT_INPUT_COMPONENTS
            } else {
                limits::MAX_VARYING_FLOATS
            };
            limit("varying components", varyings, max);
        }
        Stage::TessControl | Stage::TessEvaluation => {
            let control = s.stage == Stage::TessControl;
            let (max_uniforms, max_samplers, max_outputs) = if control {
                (
                    limits::MAX_TESS_CONTROL_UNIFORM_COMPONENTS,
                    limits::MAX_TESS_CONTROL_TEXTURE_IMAGE_UNITS,
                    limits::MAX_TESS_CONTROL_OUTPUT_COMPONENTS,
                )
            } else {
                (
                    limits::MAX_TESS_EVALUATION_UNIFORM_COMPONENTS,
                    limits::MAX_TESS_EVALUATION_TEXTURE_IMAGE_UNITS,
                    limits::MAX_TESS_EVALUATION_OUTPUT_COMPONENTS,
                )
            };
            limit("uniform components", uniforms, max_uniforms);
            limit("samplers", samplers, max_samplers);
            // Per vertex: a per-vertex output array counts one element.
            let outputs: u32 = m
                .globals
                .iter()
                .filter(|g| {
                    !g.builtin
                        && g.written
                        && !g.patch
                        && matches!(g.storage, Storage::Varying | Storage::PerVertexOutput)
                })
                .map(|g| {
                    let ty = if g.storage == Storage::PerVertexOutput {
                        g.ty.element()
                    } else {
                        g.ty
                    };
                    components(m, ty)
                })
                .sum();
            limit("output components", outputs, max_outputs);
            let patch: u32 = m
                .globals
                .iter()
                .filter(|g| !g.builtin && g.patch && (g.written || g.read))
                .map(|g| components(m, g.ty))
                .sum();
            limit(
                "per-patch components",
                patch,
                limits::MAX_TESS_PATCH_COMPONENTS,
            );
        }
        Stage::Compute => {
            limit(
                "uniform components",
                uniforms,
                limits::MAX_COMPUTE_UNIFORM_COMPONENTS,
            );
            limit(
                "samplers",
                samplers,
                limits::MAX_COMPUTE_TEXTURE_IMAGE_UNITS,
            );
            let shared: u32 = m
                .globals
                .iter()
                .filter(|g| g.storage == Storage::Shared)
                .map(|g| components(m, g.ty).saturating_mul(4))
                .fold(0, u32::saturating_add);
            limit(
                "bytes of shared memory",
                shared,
                limits::MAX_COMPUTE_SHARED_MEMORY_SIZE,
            );
        }
    }
}

/// GLSL 1.30 §4.3.7: when the fragment shader uses gl_Color (or
/// gl_SecondaryColor), the front and back colors the previous stage
/// writes carry the same interpolation qualifier it does, an unqualified
/// declaration matching only an unqualified one. Only statically used
/// variables are compared.
pub(super) fn check_builtin_color_interpolation(
    v: &LinkedStage,
    f: &LinkedStage,
    diags: &mut Vec<LinkDiagnostic>,
) {
    let (vm, fm) = (&v.module, &f.module);
    let q = |i: Option<ir::Interpolation>| i.map_or("no qualifier", |i| i.as_str());
    for (input, outputs) in [
        ("gl_Color", ["gl_FrontColor", "gl_BackColor"]),
        (
            "gl_SecondaryColor",
            ["gl_FrontSecondaryColor", "gl_BackSecondaryColor"],
        ),
    ] {
        let Some(fg) = fm.globals.iter().find(|g| g.name == input && g.read) else {
            continue;
        };
        for out in outputs {
            let Some(vg) = vm.globals.iter().find(|g| g.name == out && g.written) else {
                continue;
            };
            if vg.interpolation != fg.interpolation {
                push(
                    diags,
                    None,
                    Code::LinkInterfaceMismatch,
                    format!(
                        "`{out}' is declared with {} in the {} shader but `{input}' with {} in the {} shader; GLSL 1.30 §4.3.7 requires the same interpolation qualifier",
                        q(vg.interpolation),
                        v.stage.name(),
                        q(fg.interpolation),
                        f.stage.name()
                    ),
                );
            }
        }
    }
}

/// What one vertex of a geometry input holds: the element, or the row of
/// an array of arrays ([`crate::types::StructDef::array_row`]: a
/// GL_EXT_geometry_shader4 two-dimensional input, or an
/// ARB_arrays_of_arrays input whose vertices are arrays).
fn per_vertex_row(m: &ir::Module, elem: crate::types::Type) -> crate::types::Type {
    m.row_member(elem).unwrap_or(elem)
}

pub(super) fn check_interface(v: &LinkedStage, f: &LinkedStage, diags: &mut Vec<LinkDiagnostic>) {
    let (vm, fm) = (&v.module, &f.module);
    let (pn, cn) = (v.stage.name(), f.stage.name());
    // The inputs of a geometry or tessellation shader are arrays of the
    // previous stage's outputs (a control shader's per-vertex outputs
    // are arrays themselves); an evaluation shader's `patch in' reads the
    // control shader's `patch out' of the same type.
    let is_input = |g: &ir::Global| match g.storage {
        Storage::PerVertexInput => true,
        Storage::Varying => match f.stage {
            Stage::Fragment => true,
            Stage::TessEvaluation => g.patch,
            _ => false,
        },
        _ => false,
    };
    let is_output = |g: &ir::Global| match g.storage {
        Storage::Varying => match v.stage {
            Stage::Vertex | Stage::TessEvaluation | Stage::Geometry => true,
            Stage::TessControl => g.patch,
            _ => false,
        },
        Storage::PerVertexOutput => true,
        _ => false,
    };
    check_blocks(vm, fm, diags);
    if f.stage == Stage::Fragment {
        check_builtin_color_interpolation(v, f, diags);
    }
    // Members and instances of blocks match by block (check_blocks).
    for fg in fm
        .globals
        .iter()
        .filter(|g| !g.builtin && g.block.is_none())
    {
        // An input with a location takes the output with that location
        // whatever its name (GL_ARB_separate_shader_objects, "Shader
        // Interface Matching"); the others match by name.
        let vg = match fg.location {
            Some(l) => vm
                .globals
                .iter()
                .find(|g| is_output(g) && g.location == Some(l)),
            None => vm.globals.iter().find(|g| g.name == fg.name),
        };
        let fty = if fg.storage == Storage::PerVertexInput {
            per_vertex_row(fm, fg.ty.element())
        } else {
            fg.ty
        };
        match fg.storage {
            _ if is_input(fg) => match vg {
                Some(vg) if is_output(vg) => {
                    let vty = if vg.storage == Storage::PerVertexOutput {
                        per_vertex_row(vm, vg.ty.element())
                    } else {
                        vg.ty
                    };
                    let same = if fg.location.is_some() {
                        same_type_by_location(vm, vty, fm, fty)
                    } else {
                        same_type_across(vm, vty, fm, fty)
                    };
                    if vg.patch != fg.patch {
                        push(
                            diags,
                            None,
                            Code::LinkInterfaceMismatch,
                            format!(
                                "`{}' is {} in the {pn} shader but {} in the {cn} shader",
                                fg.name,
                                if vg.patch { "per-patch" } else { "per-vertex" },
                                if fg.patch { "per-patch" } else { "per-vertex" },
                            ),
                        );
                    } else if !same {
                        push(
                            diags,
                            None,
                            Code::LinkInterfaceMismatch,
                            format!(
                                "varying `{}' is {} in the {pn} shader but {} in the {cn} shader",
                                fg.name,
                                vm.type_name(vg.ty),
                                fm.type_name(fg.ty)
                            ),
                        );
                    } else if vg.interpolation != fg.interpolation {
                        // GLSL 1.30 §4.3.7: the interpolation qualifiers of
                        // a vertex output and its fragment input match.
                        let q = |i: Option<ir::Interpolation>| i.map_or("none", |i| i.as_str());
                        push(
                            diags,
                            None,
                            Code::LinkInterfaceMismatch,
                            format!(
                                "varying `{}' is interpolated `{}' in the {pn} shader but `{}' in the {cn} shader",
                                fg.name,
                                q(vg.interpolation),
                                q(fg.interpolation)
                            ),
                        );
                    } else if vg.centroid != fg.centroid || vg.invariant != fg.invariant {
                        push(
                            diags,
                            None,
                            Code::LinkInterfaceMismatch,
                            format!(
                                "varying `{}' has different `centroid'/`invariant' qualifiers in the {pn} and {cn} shaders",
                                fg.name
                            ),
                        );
                    } else if fg.read && !vg.written {
                        push(
                            diags,
                            None,
                            Code::LinkVaryingNotWritten,
                            format!(
                                "the {cn} shader reads varying `{}' but the {pn} shader never writes it",
                                fg.name
                            ),
                        );
                    }
                }
                _ if fg.read => push(
                    diags,
                    None,
                    Code::LinkVaryingNotWritten,
                    format!(
                        "the {cn} shader reads varying `{}' but the {pn} shader does not declare it",
                        fg.name
                    ),
                ),
                _ => {}
            },
            Storage::Uniform => check_uniform(vm, fm, fg, diags),
            _ => {}
        }
    }
}

/// Uniforms of one name in two stages have the same type and the same
/// initializer (GLSL 1.50 §4.3.5); uniform blocks are compared by
/// `check_blocks`. Run between consecutive stages by `check_interface`,
/// and between the vertex and fragment stages when a geometry stage sits
/// between them ([`check_uniforms`]).
fn check_uniform(
    vm: &ir::Module,
    fm: &ir::Module,
    fg: &ir::Global,
    diags: &mut Vec<LinkDiagnostic>,
) {
    let (pn, cn) = (vm.stage.name(), fm.stage.name());
    let Some(vg) = vm
        .globals
        .iter()
        .find(|g| g.name == fg.name && g.storage == Storage::Uniform)
    else {
        return;
    };
    if !same_type_across(vm, vg.ty, fm, fg.ty) {
        push(
            diags,
            None,
            Code::LinkInterfaceMismatch,
            format!(
                "uniform `{}' is {} in the {pn} shader but {} in the {cn} shader",
                fg.name,
                vm.type_name(vg.ty),
                fm.type_name(fg.ty)
            ),
        );
    } else if let Some((a, b)) = vg.binding.zip(fg.binding).filter(|(a, b)| a != b) {
        push(
            diags,
            None,
            Code::LinkInterfaceMismatch,
            format!(
                "uniform `{}' has `binding = {a}' in the {pn} shader but `binding = {b}' in the {cn} shader",
                fg.name
            ),
        );
    } else if let (Some(a), Some(b)) = (&vg.init, &fg.init) {
        if a.components != b.components {
            push(
                diags,
                None,
                Code::LinkInterfaceMismatch,
                format!(
                    "uniform `{}' has different initializers in the {pn} and {cn} shaders",
                    fg.name
                ),
            );
        }
    }
}

/// The uniforms and uniform blocks of two stages that are not consecutive
/// (the vertex and fragment stages around a geometry stage): every stage
/// of a program shares its uniforms, so they match as between
/// consecutive stages (GLSL 1.50 §4.3.5, §4.3.7).
pub(super) fn check_uniforms(v: &LinkedStage, f: &LinkedStage, diags: &mut Vec<LinkDiagnostic>) {
    let (vm, fm) = (&v.module, &f.module);
    check_uniform_blocks(vm, fm, diags);
    for fg in fm
        .globals
        .iter()
        .filter(|g| !g.builtin && g.block.is_none() && g.storage == Storage::Uniform)
    {
        check_uniform(vm, fm, fg, diags);
    }
}
