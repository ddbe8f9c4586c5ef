//! Interface blocks (GLSL 1.40 §4.3.5.1 uniform blocks, 1.50 §4.3.7 in
//! and out blocks): their qualifiers and layouts, members and instance
//! names, arrays of blocks, unsized members sized by use, and the
//! redeclaration of `gl_PerVertex` (1.50 §7.1).

use super::interface::LayoutQuals;
use super::scope::{Symbol, Var};
use super::Analyzer;
use crate::ast::{InterfaceBlock, Qualifier, TypeName};
use crate::diag::Code;
use crate::ir::{self, BlockId, BlockMember, Global, Interpolation, Stage, Storage};
use crate::lang::Feature;
use crate::source::Span;
use crate::types::{ArraySize, Base, Scalar, StructDef, StructMember, Type};

impl Analyzer {
    /// An interface block: checks it and declares its members (without an
    /// instance name) or its instance.
    pub(crate) fn interface_block(&mut self, b: &InterfaceBlock) {
        let q = self.var_qualifiers(&b.qualifiers);
        let (storage, input) = match q.storage {
            Some(Qualifier::Uniform) => {
                if !self.require(Feature::UniformBlocks, "uniform blocks", b.name.span) {
                    return;
                }
                (Storage::Uniform, false)
            }
            Some(Qualifier::Buffer) => {
                if !self.require(
                    Feature::StorageBuffers,
                    "shader storage blocks",
                    b.name.span,
                ) {
                    return;
                }
                (Storage::Buffer, false)
            }
            Some(Qualifier::In) | Some(Qualifier::Out) => {
                if !self.require(Feature::InOutBlocks, "input and output blocks", b.name.span) {
                    return;
                }
                let is_in = q.storage == Some(Qualifier::In);
                // Vertex shaders have output blocks, fragment shaders
                // input blocks, geometry shaders both (GLSL 1.50 §4.3.7).
                let allowed = match self.stage {
                    Stage::Vertex => !is_in,
                    Stage::TessControl | Stage::TessEvaluation | Stage::Geometry => true,
                    Stage::Fragment => is_in,
                    // Compute shaders have no user inputs or outputs.
                    Stage::Compute => false,
                };
                if !allowed {
                    self.error(
                        Code::StageMismatch,
                        b.name.span,
                        format!(
                            "{} blocks are not allowed in a {} shader",
                            if is_in { "input" } else { "output" },
                            self.stage.name()
                        ),
                    );
                    return;
                }
                (self.global_storage(&q), is_in)
            }
            _ => {
                self.error(
                    Code::BadQualifier,
                    b.name.span,
                    "a block must be declared `uniform', `in' or `out'",
                );
                return;
            }
        };
        if !self.scopes.is_global() {
            self.error(
                Code::BadQualifier,
                b.span,
                "blocks must be declared at global scope",
            );
            return;
        }
        let mut layout = self.default_block_layout;
        let mut row_major = self.default_row_major;
        let mut binding = None;
        let memory_block = storage == Storage::Buffer;
        if matches!(storage, Storage::Uniform | Storage::Buffer) {
            binding = q.layout.binding;
            if let Some((l, span)) = q.layout.block_layout {
                if l == ir::BlockLayout::Std430 && !memory_block {
                    self.error(
                        Code::BadQualifier,
                        span,
                        "`std430' applies only to shader storage blocks (`buffer')",
                    )
                    .notes
                    .push("a uniform block's layouts are std140, shared and packed".into());
                } else {
                    layout = l;
                }
            }
            if let Some((r, _)) = q.layout.row_major {
                row_major = r;
            }
            let l = &q.layout;
            if l.location.is_some()
                || l.origin_upper_left.is_some()
                || l.pixel_center_integer.is_some()
                || !l.primitive.is_empty()
            {
                self.error(
                    Code::BadQualifier,
                    l.span.unwrap_or(b.span),
                    "a uniform or shader storage block takes only std140, std430 (storage), shared, packed, row_major, column_major and binding",
                );
            }
        } else if let Some(s) = q.layout.span {
            self.error(
                Code::BadQualifier,
                s,
                "input and output blocks take no layout",
            )
            .notes
            .push(
                "a geometry shader's primitive layouts stand alone: `layout(triangles) in;'".into(),
            );
        }
        let per_vertex = matches!(storage, Storage::PerVertexInput | Storage::PerVertexOutput);
        if b.name.name == "gl_PerVertex" && !self.builtin_mode {
            if per_vertex {
                self.redeclare_per_vertex_array(b, storage);
            } else if !input {
                self.redeclare_per_vertex(b);
            } else {
                self.error(
                    Code::Redeclared,
                    b.name.span,
                    format!(
                        "a {} shader has no input block `gl_PerVertex' to redeclare",
                        self.stage.name()
                    ),
                );
            }
            return;
        }
        if per_vertex && b.instance.as_ref().is_none_or(|(_, a)| a.is_none()) {
            let (dir, kw) = if input {
                ("input", "in")
            } else {
                ("output", "out")
            };
            let note = if self.stage == Stage::Geometry {
                "GLSL 1.50 §4.3.4: a geometry shader has one input per vertex of its primitive"
            } else if input {
                "GL_ARB_tessellation_shader §4.3.4: a tessellation shader has one input per vertex of the patch (write `patch in' in an evaluation shader for one per patch)"
            } else {
                "GL_ARB_tessellation_shader §4.3.6: a control shader has one output per vertex of the output patch (write `patch out' for one per patch)"
            };
            self.error(
                Code::TypeMismatch,
                b.name.span,
                format!(
                    "{} shader {dir} block `{}' must be declared as an array: `{kw} {} {{ ... }} name[];'",
                    self.stage.name(), b.name.name, b.name.name
                ),
            )
            .notes
            .push(note.into());
            return;
        }
        if b.name.name.starts_with("gl_") && !self.builtin_mode {
            self.error(
                Code::Redeclared,
                b.name.span,
                format!(
                    "`{}': names starting with `gl_' are reserved for the implementation",
                    b.name.name
                ),
            );
            return;
        }
        if self
            .module
            .blocks
            .iter()
            .any(|x| x.name == b.name.name.as_str() && (x.storage == storage && x.input == input))
        {
            self.error(
                Code::Redeclared,
                b.name.span,
                format!("block `{}' is already declared", b.name.name),
            );
            return;
        }
        // A block name is a global name: nothing else at global scope may
        // take it (GLSL 1.40 §4.3.5.1, 1.50 §4.3.7). Block names live per
        // interface, though: a uniform, an input and an output block may
        // share one (1.50 §4.3.7), and the name keeps meaning the first.
        let other_interface = self
            .module
            .blocks
            .iter()
            .any(|x| x.name == b.name.name.as_str());
        if !other_interface && self.scopes.lookup_current(&b.name.name).is_some() {
            self.error(
                Code::Redeclared,
                b.name.span,
                format!(
                    "block name `{}' is already declared at global scope",
                    b.name.name
                ),
            );
            return;
        }
        let block_interp = q.interpolation.map(|(i, _)| i);
        let mut members = self.block_members(b, storage, row_major, block_interp);
        // A block's memory qualifiers hold for every member.
        for m in &mut members {
            m.readonly |= q.memory.readonly.is_some();
            m.writeonly |= q.memory.writeonly.is_some();
        }
        let id = BlockId(self.module.blocks.len() as u32);
        // The block's members as a struct: the type of a named instance,
        // and what the block name stands for in the global scope.
        let sid = crate::types::StructId(self.module.structs.len() as u32);
        self.module.structs.push(StructDef {
            name: b.name.name.to_string(),
            members: members
                .iter()
                .map(|m| StructMember {
                    name: m.name.clone(),
                    ty: m.ty,
                })
                .collect(),
            builtin: self.builtin_mode,
            array_row: false,
        });
        if !other_interface {
            self.scopes.insert(b.name.name.clone(), Symbol::Struct(sid));
        }
        let mut globals = Vec::new();
        let mut array = None;
        let mut inner = Vec::new();
        match &b.instance {
            None => {
                for m in &members {
                    if self.scopes.lookup_current(&m.name).is_some() {
                        self.error(
                            Code::Redeclared,
                            b.span,
                            format!(
                                "block member `{}' is already declared at global scope",
                                m.name
                            ),
                        );
                        continue;
                    }
                    let gid =
                        self.push_block_global(&m.name, m.ty, storage, Some(m), id, b.name.span);
                    self.scopes
                        .insert(m.name.as_str().into(), Symbol::Var(Var::Global(gid)));
                    globals.push(gid);
                }
            }
            Some((inst, arr)) => {
                let ty = self.apply_array(
                    Type {
                        base: Base::Struct(sid),
                        array: None,
                    },
                    arr.as_ref(),
                );
                // Geometry input arrays take their size from the input
                // primitive (GLSL 1.50 §4.3.8.1).
                if ty.array == Some(ArraySize::Unsized) && !per_vertex {
                    self.error(
                        Code::BadArraySize,
                        inst.span,
                        format!("block instance `{}' needs an array size", inst.name),
                    );
                }
                if let Some(ArraySize::Sized(n)) = ty.array {
                    array = Some(n);
                }
                // The inner sizes of an array of arrays of instances.
                let mut row = ty.element();
                while let Some(r) = self.array_row_member(row) {
                    if let Some(ArraySize::Sized(n)) = r.array {
                        inner.push(n);
                    }
                    row = r.element();
                    if inner.len() > 64 {
                        break;
                    }
                }
                if !self.check_reserved_name(&inst.name, inst.span) {
                    return;
                }
                if self.scopes.lookup_current(&inst.name).is_some() {
                    self.error(
                        Code::Redeclared,
                        inst.span,
                        format!("`{}' is already declared in this scope", inst.name),
                    );
                    return;
                }
                let gid = self.push_block_global(&inst.name, ty, storage, None, id, inst.span);
                self.scopes
                    .insert(inst.name.clone(), Symbol::Var(Var::Global(gid)));
                globals.push(gid);
                if per_vertex {
                    if storage == Storage::PerVertexInput {
                        self.size_per_vertex_input(gid, inst.span);
                    } else {
                        self.size_per_vertex_output(gid, inst.span);
                    }
                    if let Some(ArraySize::Sized(n)) = self.module.globals[gid.0 as usize].ty.array
                    {
                        array = Some(n);
                    }
                }
            }
        }
        if q.patch.is_some() {
            for g in &globals {
                self.module.globals[g.0 as usize].patch = true;
            }
        }
        let binding = binding.and_then(|(v, span)| {
            let count = array.unwrap_or(1) * inner.iter().product::<u32>();
            if storage == Storage::Buffer {
                self.binding_in_range(
                    v,
                    count,
                    crate::limits::MAX_SHADER_STORAGE_BUFFER_BINDINGS,
                    "shader storage buffer binding points",
                    span,
                )
                .then_some(v)
            } else {
                self.block_binding(v, count, span)
            }
        });
        self.module.blocks.push(ir::InterfaceBlock {
            name: b.name.name.to_string(),
            storage,
            input,
            instance: b.instance.as_ref().map(|(i, _)| i.name.to_string()),
            array,
            inner,
            layout,
            binding,
            members,
            globals,
            span: b.name.span,
        });
    }

    /// `layout(binding = N)` of a uniform block of `count` instances:
    /// GL_ARB_shading_language_420pack gives blocks a binding wherever
    /// the language has them (its "GLSL 1.4 is required" because blocks
    /// came with 1.40; GL_ARB_uniform_buffer_object brings them to 1.30 and
    /// earlier, where Mesa takes the binding too), every instance's binding
    /// point below GL_MAX_UNIFORM_BUFFER_BINDINGS.
    fn block_binding(&mut self, v: u32, count: u32, span: Span) -> Option<u32> {
        if !self.require(
            Feature::LanguagePack420,
            "`layout(binding)' on a uniform block",
            span,
        ) {
            return None;
        }
        self.binding_in_range(
            v,
            count,
            crate::limits::MAX_UNIFORM_BUFFER_BINDINGS,
            "uniform buffer binding points",
            span,
        )
        .then_some(v)
    }

    /// `out gl_PerVertex { ... };` (GLSL 1.50 §7.1): the built-in output
    /// block redeclared with a subset of its members, before any of them
    /// is used. Each member keeps being the built-in global (a sized
    /// `gl_ClipDistance[N]` or `gl_TexCoord[N]` sizes it); the members
    /// left out are no longer names. Recorded in
    /// [`ir::Module::per_vertex_out`] for the linker.
    fn redeclare_per_vertex(&mut self, b: &InterfaceBlock) {
        const MEMBERS: [&str; 10] = PER_VERTEX_OUT_MEMBERS;
        if let Some((inst, _)) = &b.instance {
            self.error(
                Code::BadQualifier,
                inst.span,
                "the output block `gl_PerVertex' is redeclared without an instance name",
            );
            return;
        }
        if self.module.per_vertex_out.is_some() {
            self.error(
                Code::Redeclared,
                b.name.span,
                "`gl_PerVertex' is already redeclared",
            );
            return;
        }
        if let Some(name) = self.per_vertex_member_redeclared.clone() {
            self.error(
                Code::Redeclared,
                b.name.span,
                format!("`gl_PerVertex' is redeclared after its member `{name}' is redeclared on its own"),
            )
            .notes
            .push("redeclare the member inside the block only".into());
            return;
        }
        // The members are built-in names: checked as the prelude's are
        // (`gl_' names and unsized arrays allowed).
        let saved = self.builtin_mode;
        self.builtin_mode = true;
        let members = self.block_members(b, Storage::Varying, false, None);
        self.builtin_mode = saved;
        let span_of = |name: &str| {
            b.members
                .iter()
                .flat_map(|m| &m.declarators)
                .find(|d| d.name.name == name)
                .map_or(b.name.span, |d| d.name.span)
        };
        let builtin_var = |a: &Analyzer, name: &str| match a.env.and_then(|e| e.lookup(name)) {
            Some(Symbol::Var(v)) if MEMBERS.contains(&name) => Some(*v),
            _ => None,
        };
        for name in MEMBERS {
            let Some(Var::Builtin(i)) = builtin_var(self, name) else {
                continue;
            };
            let used = self
                .builtin_globals
                .get(i as usize)
                .copied()
                .flatten()
                .and_then(|g| self.module.globals.get(g.0 as usize))
                .is_some_and(|g| g.read || g.written);
            if used {
                self.error(
                    Code::Redeclared,
                    b.name.span,
                    format!("`gl_PerVertex' is redeclared after `{name}' is used"),
                )
                .notes
                .push("redeclare it before the first use".into());
                return;
            }
        }
        let mut kept = Vec::new();
        for m in members {
            let span = span_of(&m.name);
            let Some(v) = builtin_var(self, &m.name) else {
                self.error(
                    Code::Redeclared,
                    span,
                    format!(
                        "`{}' is not a member of the built-in block `gl_PerVertex'",
                        m.name
                    ),
                );
                continue;
            };
            let builtin_ty = self.var_type(v);
            if !self.redeclared_member_fits(&m, builtin_ty, span) {
                continue;
            }
            if let Some(ArraySize::Sized(_)) = m.ty.array {
                self.set_var_type(v, m.ty);
            }
            if let Some(g) = self.global_of(v) {
                if let Some(gl) = self.module.globals.get_mut(g.0 as usize) {
                    gl.invariant |= m.invariant;
                    gl.centroid |= m.centroid;
                    if m.interpolation.is_some() {
                        gl.interpolation = m.interpolation;
                    }
                }
            }
            kept.push(m);
        }
        for name in MEMBERS {
            if !kept.iter().any(|m: &BlockMember| m.name == name) {
                self.hidden_builtins.push(name.into());
            }
        }
        self.module.per_vertex_out = Some(kept);
    }

    /// `in gl_PerVertex { ... } gl_in[];` in a geometry shader (GLSL 1.50
    /// §7.1, the rules of the output block's redeclaration): a subset of
    /// the built-in input block's members, with the built-in types (a
    /// sized `gl_ClipDistance[N]` or `gl_TexCoord[N]` sizes the member),
    /// instance `gl_in`, before `gl_in` is used, once. `gl_in`'s struct
    /// type then has exactly the members redeclared, so the others are no
    /// longer fields; recorded in [`ir::Module::per_vertex_in`] for the
    /// linker.
    /// Whether member `m` of a redeclared `gl_PerVertex` block keeps the
    /// built-in member's type `builtin` (an array's size aside) and, when
    /// it gives `gl_ClipDistance` or `gl_TexCoord` a size, one within the
    /// built-in limit; else the error at `span`.
    fn redeclared_member_fits(&mut self, m: &BlockMember, builtin: Type, span: Span) -> bool {
        if builtin.base != m.ty.base || builtin.is_array() != m.ty.is_array() {
            self.error(
                Code::TypeMismatch,
                span,
                format!(
                    "`{}' is redeclared as {}, but it is {}",
                    m.name,
                    self.tn(m.ty),
                    self.tn(builtin)
                ),
            );
            return false;
        }
        if let Some(ArraySize::Sized(n)) = m.ty.array {
            let max = if m.name == "gl_TexCoord" {
                crate::limits::MAX_TEXTURE_COORDS
            } else {
                crate::limits::MAX_CLIP_DISTANCES
            };
            if n > max {
                self.error(
                    Code::BadArraySize,
                    span,
                    format!("`{}' redeclared with size {n}, larger than {max}", m.name),
                );
                return false;
            }
        }
        true
    }

    fn redeclare_per_vertex_array(&mut self, b: &InterfaceBlock, storage: Storage) {
        let input = storage == Storage::PerVertexInput;
        let (dir, kw, array) = if input {
            ("input", "in", "gl_in")
        } else {
            ("output", "out", "gl_out")
        };
        let Some((inst, arr)) = &b.instance else {
            self.error(
                Code::BadQualifier,
                b.name.span,
                format!("the {dir} block `gl_PerVertex' is redeclared with its instance name: `{kw} gl_PerVertex {{ ... }} {array}[];'"),
            );
            return;
        };
        if inst.name != array || arr.as_ref().is_none_or(|a| a.dims.len() != 1) {
            self.error(
                Code::BadQualifier,
                inst.span,
                format!(
                    "the {dir} block `gl_PerVertex' is redeclared as `{array}[]', not `{}'",
                    inst.name
                ),
            );
            return;
        }
        let redeclared = if input {
            &self.module.per_vertex_in
        } else {
            &self.module.per_vertex_out
        };
        if redeclared.is_some() {
            self.error(
                Code::Redeclared,
                b.name.span,
                format!("the {dir} block `gl_PerVertex' is already redeclared"),
            );
            return;
        }
        let Some(&Symbol::Var(v @ Var::Builtin(i))) = self.env.and_then(|e| e.lookup(array)) else {
            self.error(
                Code::Redeclared,
                b.name.span,
                "`gl_PerVertex': names starting with `gl_' are reserved for the implementation",
            );
            return;
        };
        // Referring to `gl_in' makes its module global; one made before
        // this point is a use before the redeclaration.
        if self
            .builtin_globals
            .get(i as usize)
            .copied()
            .flatten()
            .is_some()
        {
            self.error(
                Code::Redeclared,
                b.name.span,
                format!("the {dir} block `gl_PerVertex' is redeclared after `{array}' is used"),
            )
            .notes
            .push("redeclare it before the first use".into());
            return;
        }
        let builtin_ty = self.var_type(v);
        let Base::Struct(sid) = builtin_ty.base else {
            return;
        };
        let Some(builtin_def) = self.module.structs.get(sid.0 as usize).cloned() else {
            return;
        };
        let saved = self.builtin_mode;
        self.builtin_mode = true;
        let members = self.block_members(b, storage, false, None);
        self.builtin_mode = saved;
        let span_of = |name: &str| {
            b.members
                .iter()
                .flat_map(|m| &m.declarators)
                .find(|d| d.name.name == name)
                .map_or(b.name.span, |d| d.name.span)
        };
        let mut kept = Vec::new();
        for m in members {
            let span = span_of(&m.name);
            let Some(bm) = builtin_def.members.iter().find(|x| x.name == m.name) else {
                self.error(
                    Code::Redeclared,
                    span,
                    format!(
                        "`{}' is not a member of the built-in {dir} block `gl_PerVertex'",
                        m.name
                    ),
                );
                continue;
            };
            if !self.redeclared_member_fits(&m, bm.ty, span) {
                continue;
            }
            kept.push(m);
        }
        if let Some(def) = self.module.structs.get_mut(sid.0 as usize) {
            def.members = kept
                .iter()
                .map(|m| StructMember {
                    name: m.name.clone(),
                    ty: m.ty,
                })
                .collect();
        }
        if input {
            self.module.per_vertex_in = Some(kept);
        } else {
            self.module.per_vertex_out = Some(kept);
        }
        // `gl_in[3]' as well as `gl_in[]': sized like any input array.
        let ty = self.apply_array(
            Type {
                base: Base::Struct(sid),
                array: None,
            },
            arr.as_ref(),
        );
        if let Some(g) = self.global_of(v) {
            if let Some(ArraySize::Sized(n)) = ty.array {
                if let Some(gl) = self.module.globals.get_mut(g.0 as usize) {
                    gl.ty.array = Some(ArraySize::Sized(n));
                }
                if input {
                    self.size_per_vertex_input(g, inst.span);
                } else {
                    self.size_per_vertex_output(g, inst.span);
                }
            }
        }
    }

    /// Whether `e` names the instance array of a uniform block, or a row
    /// of an array of arrays of instances (`b[1]` of `b[2][3]`).
    pub(crate) fn is_block_instance_array(&self, e: &ir::Expr) -> bool {
        let mut root = e;
        for _ in 0..64 {
            match &root.kind {
                ir::ExprKind::Member { base, .. } if self.array_row_member(base.ty).is_some() => {
                    match &base.kind {
                        ir::ExprKind::Index { base, .. } => root = base,
                        _ => return false,
                    }
                }
                _ => break,
            }
        }
        let ir::ExprKind::Global(g) = root.kind else {
            return false;
        };
        let Some(g) = self.module.globals.get(g.0 as usize) else {
            return false;
        };
        g.storage == Storage::Uniform
            && g.ty.is_array()
            && g.block
                .and_then(|b| self.module.blocks.get(b.0 as usize))
                .is_some_and(|b| b.instance.is_some())
    }

    fn push_block_global(
        &mut self,
        name: &str,
        ty: Type,
        storage: Storage,
        member: Option<&BlockMember>,
        block: BlockId,
        span: Span,
    ) -> ir::GlobalId {
        let id = ir::GlobalId(self.module.globals.len() as u32);
        self.module.globals.push(Global {
            name: name.to_string(),
            ty,
            storage,
            builtin: self.builtin_mode,
            invariant: member.is_some_and(|m| m.invariant),
            centroid: member.is_some_and(|m| m.centroid),
            interpolation: member.and_then(|m| m.interpolation),
            location: None,
            index: None,
            binding: None,
            patch: false,
            block: Some(block),
            init: None,
            init_expr: None,
            read: false,
            written: false,
            implicit_size: 0,
            span,
        });
        id
    }

    /// The members of a block, checked (§4.3.7: no initializers, no
    /// samplers, no struct definitions in uniform blocks of 1.40, member
    /// storage matching the block's).
    fn block_members(
        &mut self,
        b: &InterfaceBlock,
        storage: Storage,
        row_major: bool,
        block_interp: Option<Interpolation>,
    ) -> Vec<BlockMember> {
        let mut out: Vec<BlockMember> = Vec::new();
        let frag_input = storage == Storage::Varying && self.stage == Stage::Fragment;
        // Input or output block (a geometry shader's inputs have their own
        // storage).
        let inout = matches!(
            storage,
            Storage::Varying | Storage::PerVertexInput | Storage::PerVertexOutput
        );
        let buffer = storage == Storage::Buffer;
        let last_member = b.members.len().saturating_sub(1);
        for (mi, m) in b.members.iter().enumerate() {
            let mut memory = super::interface::MemoryQuals::default();
            let mut member_row_major = row_major;
            let mut interpolation = block_interp;
            let mut centroid = false;
            let mut invariant = false;
            let mut precision = None;
            for sq in &m.qualifiers {
                match sq.qualifier {
                    Qualifier::Layout => {
                        let mut l = LayoutQuals::default();
                        self.layout_ids(sq, &mut l);
                        if let (Some((r, _)), Storage::Uniform | Storage::Buffer) =
                            (l.row_major, storage)
                        {
                            member_row_major = r;
                        }
                        let bad = l.location.is_some()
                            || l.block_layout.is_some()
                            || l.binding.is_some()
                            || l.origin_upper_left.is_some()
                            || l.pixel_center_integer.is_some()
                            || !l.primitive.is_empty()
                            || (!matches!(storage, Storage::Uniform | Storage::Buffer)
                                && l.row_major.is_some());
                        if bad {
                            self.error(
                                Code::BadQualifier,
                                sq.span,
                                "a block member takes only `row_major' or `column_major' (in uniform blocks)",
                            );
                        }
                    }
                    Qualifier::Uniform if storage == Storage::Uniform => {}
                    Qualifier::Buffer if buffer => {}
                    q if q.is_memory() && buffer => {
                        memory.record(sq);
                    }
                    Qualifier::In if inout && b_is(b, Qualifier::In) => {}
                    Qualifier::Out if inout && b_is(b, Qualifier::Out) => {}
                    Qualifier::Flat | Qualifier::Smooth | Qualifier::Noperspective if inout => {
                        interpolation = Some(match sq.qualifier {
                            Qualifier::Flat => Interpolation::Flat,
                            Qualifier::Smooth => Interpolation::Smooth,
                            _ => Interpolation::NoPerspective,
                        });
                    }
                    Qualifier::Centroid if inout => centroid = true,
                    Qualifier::Invariant if inout => invariant = true,
                    Qualifier::Lowp | Qualifier::Mediump | Qualifier::Highp => {
                        precision = Some(sq.span);
                    }
                    other => {
                        self.error(
                            Code::BadQualifier,
                            sq.span,
                            format!(
                                "`{}' is not allowed on a member of block `{}'",
                                other.as_str(),
                                b.name.name
                            ),
                        )
                        .notes
                        .push("a member's storage qualifier, if any, must be the block's".into());
                    }
                }
            }
            // GLSL 1.50 §4.3.7: "structure definitions cannot be nested
            // inside a block" (a named struct type declared before it may
            // be a member's type).
            if let TypeName::Struct(st) = &m.ty.name {
                self.error(
                    Code::TypeMismatch,
                    st.span,
                    format!(
                        "a structure cannot be defined inside block `{}'",
                        b.name.name
                    ),
                )
                .notes
                .push("define the struct before the block and name it here".into());
            }
            let ty = self.resolve_type(&m.ty);
            let last_declarator = m.declarators.len().saturating_sub(1);
            for (di, d) in m.declarators.iter().enumerate() {
                let mty = self.apply_array(ty, d.array.as_ref());
                if mty.is_error() {
                    continue;
                }
                self.check_precision(precision, mty);
                if mty.base == Base::Void {
                    self.error(
                        Code::TypeMismatch,
                        d.name.span,
                        format!("block member `{}' cannot be void", d.name.name),
                    );
                    continue;
                }
                // Input and output blocks size an unsized member by its
                // use, as an unsized array global (GLSL 1.50 §4.3.7); a
                // uniform block's layout needs every size. The prelude's
                // `gl_PerVertex' has `gl_ClipDistance[]'.
                // A shader storage block's last member may be an array of
                // unknown size: its size is what the bound buffer holds
                // (GL_ARB_shader_storage_buffer_object).
                // GLSL 4.30 §4.3.9: the other members of one without a
                // size are sized at link time by their uses, as unsized
                // globals are.
                let _ = (mi, di, last_member, last_declarator);
                if mty.array == Some(ArraySize::Unsized) && !self.builtin_mode && !inout && !buffer
                {
                    let msg = format!(
                        "uniform block member `{}' must have an array size",
                        d.name.name
                    );
                    self.error(Code::BadArraySize, d.span, msg);
                }
                if self.contains_sampler(mty) {
                    self.error(
                        Code::TypeMismatch,
                        d.name.span,
                        format!(
                            "block member `{}' is a sampler; blocks cannot hold samplers",
                            d.name.name
                        ),
                    );
                    continue;
                }
                if inout && mty.scalar() == Some(Scalar::Bool) {
                    self.error(
                        Code::TypeMismatch,
                        d.name.span,
                        format!(
                            "member `{}' of an input or output block cannot be bool",
                            d.name.name
                        ),
                    );
                }
                // A struct member with an integer inside counts too (1.50
                // §4.3.4: the rule is on the type, at any depth).
                let integer = self.contains_integer(mty.element());
                if frag_input && integer && interpolation != Some(Interpolation::Flat) {
                    self.error(
                        Code::BadQualifier,
                        d.name.span,
                        format!(
                            "member `{}' of a fragment input block has an integer type; it must be `flat'",
                            d.name.name
                        ),
                    );
                }
                if !self.check_reserved_name(&d.name.name, d.name.span) {
                    continue;
                }
                if out.iter().any(|x| x.name == d.name.name.as_str()) {
                    self.error(
                        Code::Redeclared,
                        d.name.span,
                        format!("block member `{}' declared twice", d.name.name),
                    );
                    continue;
                }
                out.push(BlockMember {
                    name: d.name.name.to_string(),
                    ty: mty,
                    row_major: member_row_major,
                    interpolation,
                    centroid,
                    invariant,
                    readonly: memory.readonly.is_some(),
                    writeonly: memory.writeonly.is_some(),
                    implicit_size: 0,
                });
            }
        }
        out
    }
}

/// The members of the output `gl_PerVertex` block, in the order of GLSL
/// 1.50 §7.1 (the compatibility profile's last).
pub(crate) const PER_VERTEX_OUT_MEMBERS: [&str; 10] = [
    "gl_Position",
    "gl_PointSize",
    "gl_ClipDistance",
    "gl_ClipVertex",
    "gl_FrontColor",
    "gl_BackColor",
    "gl_FrontSecondaryColor",
    "gl_BackSecondaryColor",
    "gl_TexCoord",
    "gl_FogFragCoord",
];

fn b_is(b: &InterfaceBlock, q: Qualifier) -> bool {
    b.qualifiers.iter().any(|x| x.qualifier == q)
}
