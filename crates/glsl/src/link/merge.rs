//! Merging the shader objects of one stage into one module (GLSL 1.20
//! §4.3 "shared globals", §6.1 functions across objects): ids remapped,
//! globals, structs and functions unified, `gl_FragCoord` and geometry
//! layouts combined.

use super::blocks::{merge_blocks, size_block_members};
use super::calls::{call_depth, collect_calls};
use super::redeclarations::{
    check_frag_coord_redeclared, check_geometry_layout, check_per_vertex_in_redeclared,
    check_per_vertex_redeclared, size_per_vertex_globals,
};
use super::remap::{remap_block, remap_const, remap_expr, remap_type, Remap};
use super::types::{compatible_types, same_struct};
use super::{push, LinkDiagnostic, LinkedStage};
use crate::diag::{Code, Diagnostic};
use crate::ir::{
    self, ConstScalar, Function, FunctionId, Global, GlobalId, Module, Stage, Storage,
};
use crate::limits;
use crate::types::{ArraySize, StructDef, StructId, StructMember, Type};
use std::collections::{BTreeMap, BTreeSet};

pub(super) fn merge_stage(
    stage: Stage,
    objects: &[(usize, &Module)],
    names: &[String],
    diags: &mut Vec<LinkDiagnostic>,
) -> Option<LinkedStage> {
    let first = objects[0].1;
    let language = objects
        .iter()
        .map(|(_, m)| m.language)
        .max_by_key(|l| l.version)
        .unwrap_or(first.language);
    let mut merged = Module::empty(language, stage);
    let mut errors = false;
    // Global name -> (merged id, object that declared it first).
    let mut global_names: BTreeMap<String, (GlobalId, usize)> = BTreeMap::new();
    // The object whose non-constant initializer a global keeps.
    let mut init_origin: BTreeMap<GlobalId, usize> = BTreeMap::new();
    // The first initializer seen for a global: its value, if constant.
    let mut init_seen: BTreeMap<GlobalId, Option<Vec<ConstScalar>>> = BTreeMap::new();
    // Function signature -> merged id.
    let mut func_sigs: BTreeMap<(String, Vec<Type>), FunctionId> = BTreeMap::new();
    let mut func_origin: Vec<usize> = Vec::new();
    let mut remaps = Vec::new();

    for &(obj, m) in objects {
        let mut map = Remap {
            structs: Vec::new(),
            globals: Vec::new(),
            functions: Vec::new(),
        };
        // Structs: reuse an identical definition, else append.
        for s in &m.structs {
            let members: Vec<StructMember> = s
                .members
                .iter()
                .map(|mb| StructMember {
                    name: mb.name.clone(),
                    ty: remap_type(mb.ty, &map),
                })
                .collect();
            let candidate = StructDef {
                name: s.name.clone(),
                members,
                builtin: s.builtin,
                array_row: s.array_row,
            };
            let id = match merged
                .structs
                .iter()
                .position(|x| same_struct(x, &candidate))
            {
                Some(i) => StructId(i as u32),
                None => {
                    merged.structs.push(candidate);
                    StructId(merged.structs.len() as u32 - 1)
                }
            };
            map.structs.push(id);
        }
        // Globals: shared by name.
        for g in &m.globals {
            let ty = remap_type(g.ty, &map);
            if let Some(&(id, other)) = global_names.get(&g.name) {
                let existing = &mut merged.globals[id.0 as usize];
                if !compatible_types(existing.ty, ty) || existing.storage != g.storage {
                    errors = true;
                    diags.push(LinkDiagnostic {
                        shader: Some(obj),
                        diagnostic: Diagnostic::error(
                            Code::LinkInterfaceMismatch,
                            g.span,
                            format!(
                                "`{}' is declared as {} here but differently in {}",
                                g.name,
                                m.type_name(g.ty),
                                names[other]
                            ),
                        ),
                    });
                    map.globals.push(id);
                    continue;
                }
                let existing = &mut merged.globals[id.0 as usize];
                let mut problems = Vec::new();
                // §4.3: "All initializers for a shared global must have the
                // same value": two constant initializers must agree, and a
                // non-constant one cannot be compared with anything.
                if let Some(mine) = initial_value(g, &m.structs) {
                    match init_seen.get(&id) {
                        None => {
                            init_seen.insert(id, mine);
                        }
                        Some(Some(a)) if mine.as_ref() == Some(a) => {}
                        Some(Some(_)) if mine.is_some() => problems.push(format!(
                            "`{}' has different initializers here and in {}",
                            g.name, names[other]
                        )),
                        Some(_) => problems.push(format!(
                            "`{}' is initialized here and in {}; several initializers of a shared global must be the same constant",
                            g.name, names[other]
                        )),
                    }
                }
                if existing.location != g.location || existing.interpolation != g.interpolation {
                    problems.push(format!(
                        "`{}' has a different location or interpolation qualifier here and in {}",
                        g.name, names[other]
                    ));
                }
                // GLSL 4.20 §4.4.5: different bindings of one name are
                // a link error; a binding given in one object holds for
                // all.
                match (existing.binding, g.binding) {
                    (Some(a), Some(b)) if a != b => problems.push(format!(
                        "`{}' has `binding = {b}' here and `binding = {a}' in {}",
                        g.name, names[other]
                    )),
                    (None, b) => existing.binding = b,
                    _ => {}
                }
                // §4.3.6: centroid and invariant must match; within one
                // stage the objects share the variable, so the same holds.
                if existing.centroid != g.centroid || existing.invariant != g.invariant {
                    problems.push(format!(
                        "`{}' has different `centroid'/`invariant' qualifiers here and in {}",
                        g.name, names[other]
                    ));
                }
                for msg in problems {
                    errors = true;
                    diags.push(LinkDiagnostic {
                        shader: Some(obj),
                        diagnostic: Diagnostic::error(Code::LinkInterfaceMismatch, g.span, msg),
                    });
                }
                if existing.init.is_none() {
                    existing.init = g.init.clone();
                    if let Some(v) = &mut existing.init {
                        remap_const(v, &map);
                    }
                }
                if g.init_expr.is_some() {
                    init_origin.entry(id).or_insert(obj);
                }
                if let Some(ArraySize::Sized(n)) = ty.array {
                    existing.ty.array = Some(ArraySize::Sized(n));
                }
                existing.read |= g.read;
                existing.written |= g.written;
                existing.invariant |= g.invariant;
                existing.implicit_size = existing.implicit_size.max(g.implicit_size);
                map.globals.push(id);
            } else {
                let id = GlobalId(merged.globals.len() as u32);
                let mut ng: Global = g.clone();
                ng.ty = ty;
                if let Some(v) = &mut ng.init {
                    remap_const(v, &map);
                }
                // Filled in, with remapped ids, with the function bodies.
                ng.init_expr = None;
                if g.init_expr.is_some() {
                    init_origin.insert(id, obj);
                }
                if let Some(v) = initial_value(g, &m.structs) {
                    init_seen.insert(id, v);
                }
                global_names.insert(g.name.clone(), (id, obj));
                merged.globals.push(ng);
                map.globals.push(id);
            }
        }
        merge_blocks(&mut merged, m, &map, obj, diags, &mut errors);
        merge_geometry_layout(&mut merged.geometry, &m.geometry, obj, diags, &mut errors);
        merge_tess_layout(
            &mut merged.tessellation,
            &m.tessellation,
            obj,
            diags,
            &mut errors,
        );
        match (merged.local_size, m.local_size) {
            (Some(a), Some(b)) if a != b => {
                errors = true;
                push(
                    diags,
                    Some(obj),
                    Code::LinkInterfaceMismatch,
                    format!(
                        "the compute shader objects declare different work-group sizes ({} and {})",
                        size_text(a),
                        size_text(b)
                    ),
                );
            }
            (None, b) => merged.local_size = b,
            _ => {}
        }
        merge_frag_coord(
            &mut merged.frag_coord,
            &m.frag_coord,
            obj,
            diags,
            &mut errors,
        );
        remaps.push((obj, m, map));
    }
    let objects: Vec<(usize, &ir::Module)> = remaps.iter().map(|(o, m, _)| (*o, *m)).collect();
    if !check_frag_coord_redeclared(&objects, diags) {
        errors = true;
    }
    match check_per_vertex_redeclared(&objects, diags) {
        Some(members) => merged.per_vertex_out = members,
        None => errors = true,
    }
    match check_per_vertex_in_redeclared(&objects, diags) {
        Some(members) => merged.per_vertex_in = members,
        None => errors = true,
    }

    // Functions: definitions first, so prototypes resolve to them.
    for pass_defs in [true, false] {
        for (obj, m, map) in remaps.iter_mut() {
            if pass_defs {
                map.functions = vec![FunctionId(u32::MAX); m.functions.len()];
            }
            for (i, f) in m.functions.iter().enumerate() {
                if f.body.is_some() != pass_defs {
                    continue;
                }
                let sig = (
                    f.name.clone(),
                    f.params
                        .iter()
                        .map(|p| remap_type(p.ty, map))
                        .collect::<Vec<_>>(),
                );
                match func_sigs.get(&sig) {
                    Some(&id) if pass_defs => {
                        errors = true;
                        let code = if f.name == "main" {
                            Code::LinkDuplicateMain
                        } else {
                            Code::LinkDuplicateDefinition
                        };
                        let prev = func_origin[id.0 as usize];
                        diags.push(LinkDiagnostic {
                            shader: Some(*obj),
                            diagnostic: Diagnostic::error(
                                code,
                                f.span,
                                format!(
                                    "function `{}' is defined in two {} shader objects, {} and {}",
                                    f.name,
                                    stage.name(),
                                    names[prev],
                                    names[*obj]
                                ),
                            )
                            .with_note("a function may be declared in many shader objects but defined in only one"),
                        });
                        map.functions[i] = id;
                    }
                    Some(&id) => map.functions[i] = id,
                    None => {
                        let id = FunctionId(merged.functions.len() as u32);
                        func_sigs.insert(sig, id);
                        func_origin.push(*obj);
                        let mut nf: Function = f.clone();
                        nf.body = None;
                        merged.functions.push(nf);
                        map.functions[i] = id;
                    }
                }
            }
        }
    }
    // Bodies, with every id remapped.
    for (obj, m, map) in &remaps {
        for (i, f) in m.functions.iter().enumerate() {
            let id = map.functions[i];
            if f.body.is_none() || func_origin.get(id.0 as usize) != Some(obj) {
                continue;
            }
            let target = &mut merged.functions[id.0 as usize];
            if target.body.is_some() {
                continue;
            }
            let mut nf = f.clone();
            nf.return_type = remap_type(nf.return_type, map);
            for p in &mut nf.params {
                p.ty = remap_type(p.ty, map);
            }
            for l in &mut nf.locals {
                l.ty = remap_type(l.ty, map);
            }
            if let Some(b) = &mut nf.body {
                remap_block(b, map);
            }
            *target = nf;
        }
        for (gi, g) in m.globals.iter().enumerate() {
            let id = map.globals[gi];
            if let (Some(e), Some(origin)) = (&g.init_expr, init_origin.get(&id)) {
                if origin == obj {
                    let mut e = e.clone();
                    remap_expr(&mut e, map);
                    merged.globals[id.0 as usize].init_expr = Some(e);
                }
            }
        }
        for ext in &m.extensions {
            if !merged.extensions.contains(ext) {
                merged.extensions.push(ext.clone());
            }
        }
    }

    // Exactly one main.
    let mains: Vec<FunctionId> = merged
        .functions
        .iter()
        .enumerate()
        .filter(|(_, f)| f.name == "main" && f.body.is_some())
        .map(|(i, _)| FunctionId(i as u32))
        .collect();
    let Some(&main) = mains.first() else {
        if !errors {
            push(
                diags,
                None,
                Code::LinkNoMain,
                format!(
                    "the {} shaders have no `main' function; one {} shader object must define `void main()'",
                    stage.name(),
                    stage.name()
                ),
            );
        }
        return None;
    };

    // Every function reachable from main must be defined.
    let mut seen = BTreeSet::new();
    let mut work = vec![main];
    while let Some(f) = work.pop() {
        if !seen.insert(f) {
            continue;
        }
        let func = &merged.functions[f.0 as usize];
        match &func.body {
            Some(b) => {
                let mut calls = BTreeSet::new();
                collect_calls(b, &mut calls);
                work.extend(calls);
            }
            None => {
                errors = true;
                let origin = func_origin.get(f.0 as usize).copied();
                diags.push(LinkDiagnostic {
                    shader: origin,
                    diagnostic: Diagnostic::error(
                        Code::LinkUndefinedFunction,
                        func.span,
                        format!(
                            "function `{}' is called but no {} shader defines it",
                            signature(&merged, func),
                            stage.name()
                        ),
                    )
                    .with_note("attach the shader object that defines it, or define it"),
                });
            }
        }
    }

    // Each object's chains were bounded when it compiled; one that crosses
    // objects is bounded here, against the same limit.
    if !errors {
        let depth = call_depth(&merged, main);
        if depth > limits::MAX_CALL_DEPTH {
            errors = true;
            push(
                diags,
                None,
                Code::LinkTooMany,
                format!(
                    "function calls nested too deeply: the {} shader's `main' starts a chain of \
                     {depth} nested calls across its shader objects; the limit is {}",
                    stage.name(),
                    limits::MAX_CALL_DEPTH
                ),
            );
        }
    }

    // gl_FragColor and gl_FragData are exclusive across the stage (§7.2).
    if stage == Stage::Fragment {
        let written = |n: &str| {
            merged
                .globals
                .iter()
                .any(|g| g.builtin && g.name == n && g.written)
        };
        if written("gl_FragColor") && written("gl_FragData") {
            errors = true;
            push(
                diags,
                None,
                Code::LinkInterfaceMismatch,
                "the fragment shaders write both `gl_FragColor' and `gl_FragData'; write only one of them",
            );
        }
    }

    if stage == Stage::Geometry {
        errors |= !check_geometry_layout(&mut merged, diags);
    }
    if matches!(stage, Stage::TessControl | Stage::TessEvaluation) {
        errors |= !check_tess_layout(&mut merged, diags);
    }
    if stage == Stage::Compute && merged.local_size.is_none() {
        // GL_ARB_compute_shader: "at least one ... must declare a fixed
        // local group size".
        errors = true;
        push(
            diags,
            None,
            Code::LinkInterfaceMismatch,
            "no compute shader object declares its work-group size (`layout(local_size_x = 64) in;')",
        );
    }

    // Unsized arrays take their largest implicit size; an explicit size
    // elsewhere must cover every index used (§4.3, shared globals).
    for g in &mut merged.globals {
        match g.ty.array {
            // A shader storage block's last member keeps its unknown
            // size: the bound buffer gives it (the others are sized by
            // `size_block_members').
            Some(ArraySize::Unsized) if g.storage == ir::Storage::Buffer => {}
            Some(ArraySize::Unsized) => {
                g.ty.array = Some(ArraySize::Sized(g.implicit_size.max(1)));
            }
            Some(ArraySize::Sized(n)) if g.implicit_size > n => {
                errors = true;
                diags.push(LinkDiagnostic {
                    shader: None,
                    diagnostic: Diagnostic::error(
                        Code::LinkInterfaceMismatch,
                        None,
                        format!(
                            "array `{}' is declared with size {n} in one {} shader object but indexed with {} in another",
                            g.name,
                            stage.name(),
                            g.implicit_size - 1
                        ),
                    ),
                });
            }
            _ => {}
        }
    }
    for msg in size_block_members(&mut merged) {
        errors = true;
        push(diags, None, Code::LinkInterfaceMismatch, msg);
    }

    // GLSL 1.10 §7.1: "All executions of a well-formed vertex shader must
    // write a value into [gl_Position]"; a vertex stage that never does is
    // rejected.
    // From GLSL 1.40 (GL 3.1) on, a vertex shader that does not write
    // gl_Position links; its position is undefined.
    if stage == Stage::Vertex
        && merged.language.version < crate::lang::Version::V140
        && !merged
            .globals
            .iter()
            .any(|g| g.builtin && g.name == "gl_Position" && g.written)
    {
        errors = true;
        push(
            diags,
            None,
            Code::LinkVaryingNotWritten,
            "the vertex shader never writes `gl_Position'; every vertex shader must set it (e.g. `gl_Position = ftransform();')",
        );
    }

    (!errors).then_some(LinkedStage {
        stage,
        module: merged,
        main,
    })
}

/// Adds one geometry shader object's layouts to the stage's: every object
/// that declares one declares the same (GLSL 1.50 §4.3.8.1-2).
/// GLSL 1.50 §4.3.8.1: every redeclaration of `gl_FragCoord` in a
/// program's fragment shader objects has the same qualifiers (checked
/// here, object by object); the objects that use it without redeclaring
/// it while another redeclares it are found by
/// [`check_frag_coord_redeclared`].
pub(super) fn merge_frag_coord(
    merged: &mut ir::FragCoordConventions,
    m: &ir::FragCoordConventions,
    obj: usize,
    diags: &mut Vec<LinkDiagnostic>,
    errors: &mut bool,
) {
    if !m.redeclared {
        return;
    }
    if merged.redeclared && merged != m {
        *errors = true;
        push(
            diags,
            Some(obj),
            Code::LinkInterfaceMismatch,
            "the fragment shader objects redeclare `gl_FragCoord' with different layout qualifiers",
        );
        return;
    }
    *merged = *m;
}

/// A work-group size as a layout spells it.
fn size_text(s: [u32; 3]) -> String {
    format!("{} x {} x {}", s[0], s[1], s[2])
}

pub(super) fn merge_geometry_layout(
    merged: &mut ir::GeometryLayout,
    m: &ir::GeometryLayout,
    obj: usize,
    diags: &mut Vec<LinkDiagnostic>,
    errors: &mut bool,
) {
    let mut differ = |what: String| {
        *errors = true;
        push(
            diags,
            Some(obj),
            Code::LinkInterfaceMismatch,
            format!("the geometry shader objects declare different {what}"),
        );
    };
    match (merged.input, m.input) {
        (Some(a), Some(b)) if a != b => differ(format!(
            "input primitives (`{}' and `{}')",
            a.name(),
            b.name()
        )),
        (None, b) => merged.input = b,
        _ => {}
    }
    match (merged.output, m.output) {
        (Some(a), Some(b)) if a != b => differ(format!(
            "output primitives (`{}' and `{}')",
            a.name(),
            b.name()
        )),
        (None, b) => merged.output = b,
        _ => {}
    }
    match (merged.max_vertices, m.max_vertices) {
        (Some(a), Some(b)) if a != b => differ(format!("`max_vertices' ({a} and {b})")),
        (None, b) => merged.max_vertices = b,
        _ => {}
    }
}

/// Adds one tessellation shader object's layouts to the stage's
/// (GL_ARB_tessellation_shader §4.3.8: every declaration in a program of
/// the output patch size, primitive mode, spacing and vertex order names
/// the same one; point mode is on when any object asks for it).
fn merge_tess_layout(
    merged: &mut ir::TessLayout,
    m: &ir::TessLayout,
    obj: usize,
    diags: &mut Vec<LinkDiagnostic>,
    errors: &mut bool,
) {
    let mut differ = |what: String| {
        *errors = true;
        push(
            diags,
            Some(obj),
            Code::LinkInterfaceMismatch,
            format!("the tessellation shader objects declare different {what}"),
        );
    };
    fn agree<T: Copy + PartialEq>(
        slot: &mut Option<T>,
        new: Option<T>,
        name: fn(T) -> String,
        what: &str,
        differ: &mut dyn FnMut(String),
    ) {
        match (*slot, new) {
            (Some(a), Some(b)) if a != b => {
                differ(format!("{what} (`{}' and `{}')", name(a), name(b)))
            }
            (None, b) => *slot = b,
            _ => {}
        }
    }
    agree(
        &mut merged.vertices,
        m.vertices,
        |n| format!("vertices = {n}"),
        "output patch sizes",
        &mut differ,
    );
    agree(
        &mut merged.mode,
        m.mode,
        |x| x.name().to_string(),
        "primitive modes",
        &mut differ,
    );
    agree(
        &mut merged.spacing,
        m.spacing,
        |x| x.name().to_string(),
        "spacings",
        &mut differ,
    );
    agree(
        &mut merged.order,
        m.order,
        |x| x.name().to_string(),
        "vertex orders",
        &mut differ,
    );
    merged.point_mode |= m.point_mode;
}

/// A linked control stage declares its output patch size (which its
/// unsized per-vertex outputs take), a linked evaluation stage its
/// primitive mode (GL_ARB_tessellation_shader §2.14.2). False on an
/// error.
fn check_tess_layout(merged: &mut Module, diags: &mut Vec<LinkDiagnostic>) -> bool {
    let t = merged.tessellation;
    if merged.stage == Stage::TessEvaluation {
        if t.mode.is_none() {
            push(
                diags,
                None,
                Code::LinkInterfaceMismatch,
                "no tessellation evaluation shader object declares the primitive mode (`layout(triangles) in;', `quads' or `isolines')",
            );
            return false;
        }
        return true;
    }
    let Some(n) = t.vertices else {
        push(
            diags,
            None,
            Code::LinkInterfaceMismatch,
            "no tessellation control shader object declares the output patch size (`layout(vertices = 3) out;')",
        );
        return false;
    };
    size_per_vertex_globals(merged, Storage::PerVertexOutput, n, diags, |name, len| {
        format!("tessellation control output `{name}' has {len} elements, but the output patch has {n} vertices")
    })
}

/// A global's initializer: `None` without one, `Some(None)` when it is not
/// constant, `Some(Some(value))` when it folds.
pub(super) fn initial_value(g: &Global, structs: &[StructDef]) -> Option<Option<Vec<ConstScalar>>> {
    if let Some(v) = &g.init {
        return Some(Some(v.components.clone()));
    }
    let e = g.init_expr.as_ref()?;
    Some(crate::consteval::fold(e, structs).map(|v| v.components))
}

pub(super) fn signature(m: &Module, f: &Function) -> String {
    let params: Vec<String> = f.params.iter().map(|p| m.type_name(p.ty)).collect();
    format!(
        "{} {}({})",
        m.type_name(f.return_type),
        f.name,
        params.join(", ")
    )
}
