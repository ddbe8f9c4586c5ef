//! Linking shader objects into a program (what `glLinkProgram` checks).
//!
//! For each stage the shader objects of that stage are merged into one
//! [`Module`] (GLSL 1.20 §4.3: "shared globals" of one language share one
//! name space; §6.1: a function declared in one object may be defined in
//! another), then the two stages' interfaces are checked against each other
//! (§4.3.5 uniforms, §4.3.6 varyings) and against the limits of
//! [`crate::limits`].
//!
//! Link errors are [`Diagnostic`]s like compile errors; those that point into
//! a shader object carry its index in [`LinkDiagnostic::shader`].

use crate::diag::{render_info_log, Code, Diagnostic};
use crate::ir::{
    self, Block, ConstScalar, ConstValue, Expr, ExprKind, Function, FunctionId, Global, GlobalId,
    Module, Stage, Stmt, Storage,
};
use crate::limits;
use crate::types::{ArraySize, Base, StructDef, StructId, StructMember, Type};
use crate::Shader;
use std::collections::{BTreeMap, BTreeSet};

/// A link diagnostic and the shader object it points into, if any.
#[derive(Clone, Debug)]
pub struct LinkDiagnostic {
    pub shader: Option<usize>,
    pub diagnostic: Diagnostic,
}

/// The executable of one stage: every shader object of the stage merged.
#[derive(Clone, Debug)]
pub struct LinkedStage {
    pub stage: Stage,
    pub module: Module,
    /// The entry point (`main`) in `module`.
    pub main: FunctionId,
}

/// The result of linking (`GL_LINK_STATUS` is [`Program::ok`]).
#[derive(Clone, Debug, Default)]
pub struct Program {
    /// Linked stages, vertex before fragment; a stage without shader
    /// objects is absent (fixed function).
    pub stages: Vec<LinkedStage>,
    pub diagnostics: Vec<LinkDiagnostic>,
    /// The GL info log, rendered at link time.
    pub info_log: String,
}

impl Program {
    pub fn ok(&self) -> bool {
        !self.diagnostics.iter().any(|d| d.diagnostic.is_error())
    }

    pub fn stage(&self, stage: Stage) -> Option<&LinkedStage> {
        self.stages.iter().find(|s| s.stage == stage)
    }

    pub fn info_log(&self) -> &str {
        &self.info_log
    }
}

/// Links shader objects into a program.
pub fn link(shaders: &[&Shader]) -> Program {
    let mut diags: Vec<LinkDiagnostic> = Vec::new();
    let mut program = Program::default();
    if shaders.is_empty() {
        push(
            &mut diags,
            None,
            Code::LinkNoMain,
            "no shaders attached to the program",
        );
    }
    for (i, s) in shaders.iter().enumerate() {
        if !s.ok() {
            push(
                &mut diags,
                None,
                Code::LinkNoMain,
                format!("{} shader {} did not compile", s.stage.name(), i),
            );
        }
    }
    // How messages name a shader object: its name, or its index.
    let names: Vec<String> = shaders
        .iter()
        .enumerate()
        .map(|(i, s)| {
            if s.source.name.is_empty() || s.source.name == "<shader>" {
                format!("shader {i}")
            } else {
                format!("`{}'", s.source.name)
            }
        })
        .collect();
    if diags.is_empty() {
        for stage in [Stage::Vertex, Stage::Geometry, Stage::Fragment] {
            let objects: Vec<(usize, &Module)> = shaders
                .iter()
                .enumerate()
                .filter(|(_, s)| s.stage == stage)
                .filter_map(|(i, s)| s.module.as_ref().map(|m| (i, m)))
                .collect();
            if objects.is_empty() {
                continue;
            }
            if let Some(linked) = merge_stage(stage, &objects, &names, &mut diags) {
                check_limits(&linked, &mut diags);
                check_locations(&linked, &mut diags);
                program.stages.push(linked);
            }
        }
        let v = program.stage(Stage::Vertex);
        let f = program.stage(Stage::Fragment);
        match program.stage(Stage::Geometry) {
            // GL 3.2 §2.12.2 (and GL_EXT_geometry_shader4): linking fails
            // when a program has a geometry shader but no vertex shader.
            Some(_) if v.is_none() => push(
                &mut diags,
                None,
                Code::LinkNoMain,
                "the program has a geometry shader but no vertex shader; attach one",
            ),
            Some(g) => {
                if let Some(v) = v {
                    check_interface(v, g, &mut diags);
                }
                if let Some(f) = f {
                    check_interface(g, f, &mut diags);
                }
            }
            None => {
                if let (Some(v), Some(f)) = (v, f) {
                    check_interface(v, f, &mut diags);
                }
            }
        }
    }
    program.info_log = render_link_log(&diags, shaders);
    program.diagnostics = diags;
    if !program.ok() {
        program.stages.clear();
    }
    program
}

fn push(
    diags: &mut Vec<LinkDiagnostic>,
    shader: Option<usize>,
    code: Code,
    msg: impl Into<String>,
) {
    diags.push(LinkDiagnostic {
        shader,
        diagnostic: Diagnostic::error(code, None, msg),
    });
}

fn render_link_log(diags: &[LinkDiagnostic], shaders: &[&Shader]) -> String {
    let mut out = String::new();
    for d in diags {
        match d.shader.and_then(|i| shaders.get(i)) {
            Some(s) => out.push_str(&render_info_log(
                std::slice::from_ref(&d.diagnostic),
                &s.source,
            )),
            None => {
                let mut plain = d.diagnostic.clone();
                plain.span = None;
                out.push_str(&render_info_log(&[plain], &Default::default()));
            }
        }
    }
    out
}

/// How one object's ids map into the merged module.
struct Remap {
    structs: Vec<StructId>,
    globals: Vec<GlobalId>,
    functions: Vec<FunctionId>,
}

fn remap_type(ty: Type, map: &Remap) -> Type {
    match ty.base {
        Base::Struct(id) => Type {
            base: Base::Struct(map.structs.get(id.0 as usize).copied().unwrap_or(id)),
            ..ty
        },
        _ => ty,
    }
}

fn remap_const(v: &mut ConstValue, map: &Remap) {
    v.ty = remap_type(v.ty, map);
}

fn remap_expr(e: &mut Expr, map: &Remap) {
    e.ty = remap_type(e.ty, map);
    match &mut e.kind {
        ExprKind::Const(v) => remap_const(v, map),
        ExprKind::Global(g) => *g = map.globals.get(g.0 as usize).copied().unwrap_or(*g),
        ExprKind::Call { function, .. } => {
            *function = map
                .functions
                .get(function.0 as usize)
                .copied()
                .unwrap_or(*function)
        }
        _ => {}
    }
    e.for_each_child_mut(|c| remap_expr(c, map));
}

fn remap_block(b: &mut Block, map: &Remap) {
    ir::for_each_block_expr_mut(b, &mut |e| remap_expr(e, map));
}

/// Calls a block can make: every call except those in an `if` branch whose
/// condition is a constant that rules the branch out (GLSL 1.20 constant
/// expressions fold `if (degrees(0.0) != 0.0)`; a function called only there
/// need not be defined, as Mesa's compile-time folding allows).
/// Functions on the call stack at the deepest point of a call from
/// `root` (`root` counts 1), capped just past [`limits::MAX_CALL_DEPTH`].
/// The call graph has no cycles (each object was checked); a cycle made
/// across objects is cut where it closes.
fn call_depth(m: &Module, root: FunctionId) -> u32 {
    let n = m.functions.len();
    let callees = |f: FunctionId| {
        let mut out = BTreeSet::new();
        if let Some(b) = m.functions.get(f.0 as usize).and_then(|f| f.body.as_ref()) {
            collect_calls(b, &mut out);
        }
        out.into_iter()
            .filter(|c| (c.0 as usize) < n)
            .collect::<Vec<_>>()
    };
    // depth[f]: 0 while unknown; an iterative post-order walk.
    let mut depth = vec![0u32; n];
    let mut open = vec![false; n];
    let mut stack = vec![(root, callees(root), 0u32)];
    open[root.0 as usize] = true;
    loop {
        let height = stack.len() as u32;
        let Some((f, pending, deepest)) = stack.last_mut() else {
            break;
        };
        match pending.pop() {
            Some(c) if depth[c.0 as usize] > 0 => *deepest = (*deepest).max(depth[c.0 as usize]),
            Some(c) if open[c.0 as usize] => {}
            // Past the limit already: no need to know how much further.
            Some(_) if height > limits::MAX_CALL_DEPTH => *deepest = (*deepest).max(1),
            Some(c) => {
                open[c.0 as usize] = true;
                let cs = callees(c);
                stack.push((c, cs, 0));
            }
            None => {
                let (f, d) = (*f, *deepest);
                depth[f.0 as usize] = (d + 1).min(limits::MAX_CALL_DEPTH + 1);
                open[f.0 as usize] = false;
                stack.pop();
                if let Some((_, _, parent)) = stack.last_mut() {
                    *parent = (*parent).max(depth[f.0 as usize]);
                }
            }
        }
    }
    depth[root.0 as usize]
}

fn collect_calls(b: &Block, out: &mut BTreeSet<FunctionId>) {
    fn expr(e: &Expr, out: &mut BTreeSet<FunctionId>) {
        if let ExprKind::Call { function, .. } = &e.kind {
            out.insert(*function);
        }
        e.for_each_child(|c| expr(c, out));
    }
    for s in b {
        match s {
            Stmt::If {
                cond, then, else_, ..
            } => match &cond.kind {
                ExprKind::Const(c) => match c.components.first() {
                    Some(ConstScalar::Bool(true)) => collect_calls(then, out),
                    Some(ConstScalar::Bool(false)) => collect_calls(else_, out),
                    _ => {
                        collect_calls(then, out);
                        collect_calls(else_, out);
                    }
                },
                _ => {
                    expr(cond, out);
                    collect_calls(then, out);
                    collect_calls(else_, out);
                }
            },
            Stmt::Block(inner) => collect_calls(inner, out),
            Stmt::Loop {
                body, continuing, ..
            } => {
                collect_calls(body, out);
                collect_calls(continuing, out);
            }
            Stmt::Switch {
                selector, cases, ..
            } => {
                expr(selector, out);
                for c in cases {
                    collect_calls(&c.body, out);
                }
            }
            other => ir::for_each_block_expr(std::slice::from_ref(other), &mut |e| expr(e, out)),
        }
    }
}

/// Two struct definitions are the same type if names, member names and
/// member types match (§4.3, "shared globals").
fn same_struct(a: &StructDef, b: &StructDef) -> bool {
    a.name == b.name
        && a.members.len() == b.members.len()
        && a.members
            .iter()
            .zip(&b.members)
            .all(|(x, y)| x.name == y.name && x.ty == y.ty)
}

/// Array types of shared globals agree when the base types are equal and
/// explicit sizes, if both have one, are equal.
fn compatible_types(a: Type, b: Type) -> bool {
    if a.base != b.base {
        return false;
    }
    match (a.array, b.array) {
        (None, None) => true,
        (Some(ArraySize::Sized(x)), Some(ArraySize::Sized(y))) => x == y,
        (Some(_), Some(_)) => true,
        _ => false,
    }
}

fn merge_stage(
    stage: Stage,
    objects: &[(usize, &Module)],
    names: &[String],
    diags: &mut Vec<LinkDiagnostic>,
) -> Option<LinkedStage> {
    let first = objects[0].1;
    let mut merged = Module {
        language: objects
            .iter()
            .map(|(_, m)| m.language)
            .max_by_key(|l| l.version)
            .unwrap_or(first.language),
        stage,
        structs: Vec::new(),
        globals: Vec::new(),
        functions: Vec::new(),
        extensions: Vec::new(),
        blocks: Vec::new(),
        frag_coord: Default::default(),
        geometry: Default::default(),
        per_vertex_out: None,
    };
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

    // Unsized arrays take their largest implicit size; an explicit size
    // elsewhere must cover every index used (§4.3, shared globals).
    for g in &mut merged.globals {
        match g.ty.array {
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
    size_block_members(&mut merged);

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
fn merge_frag_coord(
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

/// GLSL 1.50 §4.3.8.1: once one fragment shader object redeclares
/// `gl_FragCoord`, every object that statically uses it redeclares it.
fn check_frag_coord_redeclared(
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
fn check_per_vertex_redeclared(
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

fn merge_geometry_layout(
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

/// A linked geometry stage has an input primitive, an output primitive
/// and `max_vertices` (GL 3.2 §2.12.2); its input arrays take the input
/// primitive's size, which a sized one must have. False on an error.
fn check_geometry_layout(merged: &mut Module, diags: &mut Vec<LinkDiagnostic>) -> bool {
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

/// A global's initializer: `None` without one, `Some(None)` when it is not
/// constant, `Some(Some(value))` when it folds.
fn initial_value(g: &Global, structs: &[StructDef]) -> Option<Option<Vec<ConstScalar>>> {
    if let Some(v) = &g.init {
        return Some(Some(v.components.clone()));
    }
    let e = g.init_expr.as_ref()?;
    Some(crate::consteval::fold(e, structs).map(|v| v.components))
}

fn signature(m: &Module, f: &Function) -> String {
    let params: Vec<String> = f.params.iter().map(|p| m.type_name(p.ty)).collect();
    format!(
        "{} {}({})",
        m.type_name(f.return_type),
        f.name,
        params.join(", ")
    )
}

/// Components a value of this type occupies, for the limits.
fn components(m: &Module, ty: Type) -> u32 {
    crate::consteval::flat_size(ty, &m.structs).min(u32::MAX as usize) as u32
}

/// Adds the interface blocks of object `obj` (module `m`, its globals
/// already merged through `map`) to `merged`: a block of the same name and
/// kind in another object must have the same members (GLSL 1.50 §4.3.7).
fn merge_blocks(
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
                // 1.50 §4.3.7); instance names may differ.
                if !same_members(&x.members, &members, merged)
                    || x.layout != b.layout
                    || x.array != b.array
                {
                    *errors = true;
                    diags.push(LinkDiagnostic {
                        shader: Some(obj),
                        diagnostic: Diagnostic::error(
                            Code::LinkInterfaceMismatch,
                            b.span,
                            format!(
                                "block `{}' is declared with different members, layout or array size in two shader objects",
                                b.name
                            ),
                        ),
                    });
                }
                for (x, y) in merged.blocks[i].members.iter_mut().zip(&members) {
                    x.implicit_size = x.implicit_size.max(y.implicit_size);
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
/// block and in the instance's struct.
fn size_block_members(merged: &mut Module) {
    for b in &mut merged.blocks {
        for (k, mb) in b.members.iter_mut().enumerate() {
            if mb.ty.array != Some(ArraySize::Unsized) {
                continue;
            }
            match &b.instance {
                None => {
                    if let Some(g) = b
                        .globals
                        .iter()
                        .map(|g| &merged.globals[g.0 as usize])
                        .find(|g| g.name == mb.name)
                    {
                        mb.ty = g.ty;
                    }
                }
                Some(_) => {
                    let n = mb.implicit_size.max(1);
                    mb.ty.array = Some(ArraySize::Sized(n));
                    let instance = b.globals.first().map(|g| merged.globals[g.0 as usize].ty);
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
}

/// Block members match by name, type and qualifiers, in order.
fn same_members(a: &[ir::BlockMember], b: &[ir::BlockMember], m: &Module) -> bool {
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
fn check_blocks(vm: &Module, fm: &Module, diags: &mut Vec<LinkDiagnostic>) {
    let (pn, cn) = (vm.stage.name(), fm.stage.name());
    for fb in &fm.blocks {
        // An input block (a geometry shader's has its own storage)
        // matches the output block of its name.
        let kind = |x: &&ir::InterfaceBlock| {
            x.name == fb.name
                && if fb.storage == Storage::Uniform {
                    x.storage == Storage::Uniform
                } else {
                    x.storage == Storage::Varying && !x.input
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
                    // A geometry input block is the array of the vertex
                    // stage's output block, one per vertex. Otherwise an
                    // array instance matches an array of the same size
                    // (GLSL 1.50 §4.3.7).
                    && if fb.storage == Storage::GeometryInput {
                        vb.array.is_none()
                    } else {
                        vb.array == fb.array
                    };
                if !same {
                    push(
                        diags,
                        None,
                        Code::LinkInterfaceMismatch,
                        format!(
                            "block `{}' has different members or array sizes in the {pn} and {cn} shaders",
                            fb.name
                        ),
                    );
                }
            }
            None => {}
        }
    }
}

/// Slots a vertex input or fragment output takes from its location on: one
/// per array element, and per matrix column.
fn location_slots(ty: Type) -> u32 {
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
fn check_locations(s: &LinkedStage, diags: &mut Vec<LinkDiagnostic>) {
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
        // (GL_ARB_separate_shader_objects).
        Stage::Geometry => return,
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
            for slot in &mut used[loc as usize..(loc + n) as usize] {
                if let Some(other) = slot {
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
                    break;
                }
                *slot = Some(&g.name);
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

fn check_limits(s: &LinkedStage, diags: &mut Vec<LinkDiagnostic>) {
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
            limit("varying components", varyings, limits::MAX_VARYING_FLOATS);
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
            limit("varying components", varyings, limits::MAX_VARYING_FLOATS);
        }
    }
}

/// GLSL 1.30 §4.3.7: when the fragment shader uses gl_Color (or
/// gl_SecondaryColor), the front and back colors the previous stage
/// writes carry the same interpolation qualifier it does, an unqualified
/// declaration matching only an unqualified one. Only statically used
/// variables are compared.
fn check_builtin_color_interpolation(
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

fn check_interface(v: &LinkedStage, f: &LinkedStage, diags: &mut Vec<LinkDiagnostic>) {
    let (vm, fm) = (&v.module, &f.module);
    let (pn, cn) = (v.stage.name(), f.stage.name());
    // A geometry shader's inputs are arrays of the vertex outputs.
    let (input, per_vertex) = if f.stage == Stage::Geometry {
        (Storage::GeometryInput, true)
    } else {
        (Storage::Varying, false)
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
        let vg = vm.globals.iter().find(|g| g.name == fg.name);
        let fty = if per_vertex { fg.ty.element() } else { fg.ty };
        match fg.storage {
            s if s == input => match vg {
                Some(vg) if vg.storage == Storage::Varying => {
                    if !compatible_types(vg.ty, fty) || vm.type_name(vg.ty) != fm.type_name(fty)
                    {
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
            Storage::Uniform => {
                if let Some(vg) = vg.filter(|g| g.storage == Storage::Uniform) {
                    if !compatible_types(vg.ty, fg.ty) || vm.type_name(vg.ty) != fm.type_name(fg.ty) {
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
            }
            _ => {}
        }
    }
}
