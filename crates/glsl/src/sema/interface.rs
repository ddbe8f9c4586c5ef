//! Qualifiers of GLSL 1.30-3.30 declarations and the stage interface:
//! their order (§4.7), storage `in`/`out` (§4.3.4, §4.3.6),
//! interpolation (§4.3.7), precision (§4.5), `layout(...)` (1.40
//! §4.3.5.2, 1.50 §4.3.8, GL_ARB_explicit_attrib_location,
//! GL_ARB_fragment_coord_conventions), default precision statements and
//! qualifier-only declarations (interface blocks are `blocks`'). Every
//! version check goes through [`crate::lang::Language::gate`].

use super::Analyzer;
use crate::ast::{LayoutId, Qualifier, SpannedQualifier, TypeName};
use crate::diag::Code;
use crate::ir::{BlockLayout, Interpolation, Stage};
use crate::lang::Feature;
use crate::source::Span;
use crate::types::{Base, Scalar, Type};

/// What `layout(...)` qualifiers said, checked one by one; where they
/// may appear is judged by the declaration.
#[derive(Clone, Debug, Default)]
pub(crate) struct LayoutQuals {
    /// The span of the first `layout(...)`.
    pub span: Option<Span>,
    pub location: Option<(u32, Span)>,
    /// `index = N` (accepted on fragment outputs with a location).
    pub index: Option<(u32, Span)>,
    pub block_layout: Option<(BlockLayout, Span)>,
    pub row_major: Option<(bool, Span)>,
    pub origin_upper_left: Option<Span>,
    pub pixel_center_integer: Option<Span>,
    /// `binding = N` (GL_ARB_shading_language_420pack): samplers and
    /// uniform blocks.
    pub binding: Option<(u32, Span)>,
    /// `local_size_x`, `_y`, `_z` (GL_ARB_compute_shader): only a compute
    /// shader's `layout(...) in;` takes them ([`Analyzer::compute_layout`]).
    pub local_size: [Option<(u32, Span)>; 3],
    /// Primitive identifiers of geometry and tessellation shaders
    /// (`triangles`, `max_vertices`, `vertices`, `quads`, `cw`...) in
    /// order, with the value of `max_vertices` and `vertices`: only
    /// `layout(...) in;` and `layout(...) out;` of those stages take them
    /// ([`Analyzer::geometry_layout`], [`Analyzer::tess_layout`]).
    pub primitive: Vec<(String, Option<u32>, Span)>,
}

/// The qualifiers of a variable declaration, checked.
#[derive(Clone, Debug, Default)]
pub(crate) struct VarQuals {
    /// `const`, `attribute`, `uniform`, `varying`, `in` or `out`.
    pub storage: Option<Qualifier>,
    pub storage_span: Span,
    pub invariant: bool,
    pub centroid: bool,
    /// `patch` (GL_ARB_tessellation_shader), with where it was written.
    pub patch: Option<Span>,
    pub interpolation: Option<(Interpolation, Span)>,
    pub precision: Option<Span>,
    pub layout: LayoutQuals,
    /// Memory qualifiers (GL_ARB_shader_storage_buffer_object).
    pub memory: MemoryQuals,
}

/// The memory qualifiers of a buffer variable or block (GLSL 4.30 §4.10),
/// each with where it was written.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct MemoryQuals {
    pub coherent: Option<Span>,
    pub volatile: Option<Span>,
    pub restrict: Option<Span>,
    pub readonly: Option<Span>,
    pub writeonly: Option<Span>,
}

impl MemoryQuals {
    /// The first memory qualifier written, if any.
    pub fn first(&self) -> Option<Span> {
        [
            self.coherent,
            self.volatile,
            self.restrict,
            self.readonly,
            self.writeonly,
        ]
        .into_iter()
        .flatten()
        .min_by_key(|s| s.start)
    }

    /// Records memory qualifier `sq`; false (nothing recorded) for any
    /// other qualifier. Repeating one is allowed (§4.10: "multiple memory
    /// qualifiers can be used"), and so is `readonly` with `writeonly`
    /// (memory neither read nor written, only queried).
    pub fn record(&mut self, sq: &SpannedQualifier) -> bool {
        let slot = match sq.qualifier {
            Qualifier::Coherent => &mut self.coherent,
            Qualifier::Volatile => &mut self.volatile,
            Qualifier::Restrict => &mut self.restrict,
            Qualifier::Readonly => &mut self.readonly,
            Qualifier::Writeonly => &mut self.writeonly,
            _ => return false,
        };
        slot.get_or_insert(sq.span);
        true
    }
}

/// The rank of a qualifier in §4.7's strict order: invariant,
/// interpolation, layout, storage, precision.
fn rank(q: Qualifier) -> u8 {
    match q {
        Qualifier::Invariant => 0,
        Qualifier::Flat | Qualifier::Smooth | Qualifier::Noperspective => 1,
        Qualifier::Layout => 2,
        Qualifier::Const
        | Qualifier::Attribute
        | Qualifier::Uniform
        | Qualifier::Varying
        | Qualifier::Centroid
        | Qualifier::Patch
        | Qualifier::In
        | Qualifier::Out
        | Qualifier::Inout
        | Qualifier::Shared
        | Qualifier::Buffer
        | Qualifier::Coherent
        | Qualifier::Volatile
        | Qualifier::Restrict
        | Qualifier::Readonly
        | Qualifier::Writeonly => 3,
        Qualifier::Lowp | Qualifier::Mediump | Qualifier::Highp => 4,
    }
}

/// The primitive identifiers of geometry shader layouts.
pub(crate) const GEOMETRY_LAYOUTS: &[&str] = &[
    "points",
    "lines",
    "lines_adjacency",
    "triangles",
    "triangles_adjacency",
    "line_strip",
    "triangle_strip",
    "max_vertices",
];

/// The identifiers of tessellation shader layouts
/// (GL_ARB_tessellation_shader §4.3.8.1-2); `triangles` is also a
/// geometry one.
pub(crate) const TESS_LAYOUTS: &[&str] = &[
    "vertices",
    "triangles",
    "quads",
    "isolines",
    "equal_spacing",
    "fractional_even_spacing",
    "fractional_odd_spacing",
    "cw",
    "ccw",
    "point_mode",
];

/// Whether a type can take a precision qualifier (§4.5.2: floating-point
/// and integer types, samplers, and arrays of them).
fn takes_precision(ty: Type) -> bool {
    ty.is_sampler()
        || matches!(ty.base, Base::Matrix { .. })
        || matches!(ty.base, Base::Scalar(s) | Base::Vector(s, _) if s != Scalar::Bool)
}

impl Analyzer {
    /// Reports `what` unless `feature` exists in this shader's language.
    pub(crate) fn require(&mut self, feature: Feature, what: &str, span: Span) -> bool {
        match self.lang.gate(feature) {
            Ok(()) => true,
            Err(why) => {
                let lang = self.lang;
                self.error(Code::VersionTooLow, span, why.message(what, lang))
                    .notes
                    .push(why.fix());
                false
            }
        }
    }

    /// Checks a variable's qualifier list (GLSL 1.20 §4.3, §4.6.1; 1.30
    /// §4.3-§4.7).
    pub(crate) fn var_qualifiers(&mut self, quals: &[SpannedQualifier]) -> VarQuals {
        let mut q = VarQuals::default();
        let global = self.scopes.is_global();
        let mut highest: Option<&SpannedQualifier> = None;
        // GL_ARB_shading_language_420pack §4.11: any order, one of each
        // class (the checks below), `layout` repeated.
        let any_order = self.lang.allows(Feature::LanguagePack420);
        let mut order_reported = any_order;
        for (i, sq) in quals.iter().enumerate() {
            let name = sq.qualifier.as_str();
            if let Some(h) = highest {
                if rank(sq.qualifier) < rank(h.qualifier) && !order_reported {
                    order_reported = true;
                    let msg = if sq.qualifier == Qualifier::Invariant {
                        "`invariant' must come before the other qualifiers".to_string()
                    } else {
                        format!("`{name}' must come before `{}'", h.qualifier.as_str())
                    };
                    self.error(Code::BadQualifier, sq.span, msg).notes.push(
                        "the order is: invariant, interpolation, layout, storage, precision".into(),
                    );
                }
            }
            if highest.is_none_or(|h| rank(sq.qualifier) >= rank(h.qualifier)) {
                highest = Some(sq);
            }
            match sq.qualifier {
                Qualifier::Const
                | Qualifier::Attribute
                | Qualifier::Uniform
                | Qualifier::Varying
                | Qualifier::In
                | Qualifier::Out
                | Qualifier::Inout
                | Qualifier::Shared
                | Qualifier::Buffer => {
                    let after_varying = i > 0
                        && quals[i - 1].qualifier == Qualifier::Varying
                        && q.storage == Some(Qualifier::Varying);
                    if after_varying && sq.qualifier != Qualifier::Inout {
                        self.varying_in_out(sq, quals[i - 1].span, &mut q);
                        continue;
                    }
                    if matches!(
                        sq.qualifier,
                        Qualifier::In | Qualifier::Out | Qualifier::Inout
                    ) {
                        let ok = if sq.qualifier == Qualifier::Inout || !global {
                            false
                        } else {
                            self.lang.allows(Feature::StageInOut)
                        };
                        if !ok {
                            self.in_out_misplaced(sq, global);
                            continue;
                        }
                    }
                    if let Some(prev) = q.storage {
                        self.error(
                            Code::BadQualifier,
                            sq.span,
                            format!(
                                "`{name}' after `{}': only one storage qualifier is allowed",
                                prev.as_str()
                            ),
                        );
                        continue;
                    }
                    q.storage = Some(sq.qualifier);
                    q.storage_span = sq.span;
                }
                Qualifier::Centroid => {
                    let next = quals.get(i + 1).map(|n| n.qualifier);
                    let stage_io = self.lang.allows(Feature::StageInOut);
                    let io = |q: Qualifier| match q {
                        Qualifier::Varying => true,
                        Qualifier::In | Qualifier::Out => stage_io,
                        _ => false,
                    };
                    // An auxiliary storage qualifier: with
                    // GL_ARB_shading_language_420pack anywhere among
                    // the qualifiers of an input or output.
                    let ok = if any_order {
                        quals.iter().any(|o| io(o.qualifier))
                    } else {
                        next.is_some_and(io)
                    };
                    if q.centroid {
                        self.error(Code::BadQualifier, sq.span, "`centroid' given twice");
                    }
                    if !ok {
                        let msg = if stage_io {
                            "`centroid' must be followed by `in', `out' or `varying'"
                        } else {
                            "`centroid' must be followed by `varying'"
                        };
                        self.error(Code::BadQualifier, sq.span, msg);
                    }
                    q.centroid = true;
                }
                Qualifier::Patch => {
                    // An auxiliary storage qualifier like `centroid':
                    // directly before `in' or `out' (anywhere among an
                    // input's or output's qualifiers with
                    // GL_ARB_shading_language_420pack).
                    let next = quals.get(i + 1).map(|n| n.qualifier);
                    let io = |q: Qualifier| matches!(q, Qualifier::In | Qualifier::Out);
                    let ok = if any_order {
                        quals.iter().any(|o| io(o.qualifier))
                    } else {
                        next.is_some_and(io)
                    };
                    if q.patch.is_some() {
                        self.error(Code::BadQualifier, sq.span, "`patch' given twice");
                    }
                    if !ok {
                        self.error(
                            Code::BadQualifier,
                            sq.span,
                            "`patch' must be followed by `in' or `out'",
                        );
                    }
                    q.patch = Some(sq.span);
                }
                Qualifier::Invariant => {
                    if q.invariant {
                        self.error(Code::BadQualifier, sq.span, "`invariant' given twice");
                    }
                    q.invariant = true;
                }
                Qualifier::Flat | Qualifier::Smooth | Qualifier::Noperspective => {
                    if !self.require(
                        Feature::InterpolationQualifiers,
                        &format!("`{name}'"),
                        sq.span,
                    ) {
                        continue;
                    }
                    if let Some((prev, _)) = q.interpolation {
                        self.error(
                            Code::BadQualifier,
                            sq.span,
                            format!(
                                "`{name}' after `{}': only one interpolation qualifier is allowed",
                                prev.as_str()
                            ),
                        );
                        continue;
                    }
                    let interp = match sq.qualifier {
                        Qualifier::Flat => Interpolation::Flat,
                        Qualifier::Smooth => Interpolation::Smooth,
                        _ => Interpolation::NoPerspective,
                    };
                    q.interpolation = Some((interp, sq.span));
                }
                Qualifier::Lowp | Qualifier::Mediump | Qualifier::Highp => {
                    if !self.require(Feature::Precision, &format!("`{name}'"), sq.span) {
                        continue;
                    }
                    if q.precision.is_some() {
                        self.error(
                            Code::BadQualifier,
                            sq.span,
                            "only one precision qualifier is allowed",
                        );
                    }
                    q.precision = Some(sq.span);
                }
                Qualifier::Coherent
                | Qualifier::Volatile
                | Qualifier::Restrict
                | Qualifier::Readonly
                | Qualifier::Writeonly => {
                    q.memory.record(sq);
                }
                Qualifier::Layout => {
                    if !global {
                        self.error(
                            Code::BadQualifier,
                            sq.span,
                            "`layout' qualifiers are only allowed at global scope",
                        );
                        continue;
                    }
                    if q.layout.span.is_some() && !any_order {
                        self.error(
                            Code::BadQualifier,
                            sq.span,
                            "only one `layout(...)' qualifier is allowed here",
                        )
                        .notes
                        .push("put every identifier in one `layout(...)', or enable GL_ARB_shading_language_420pack, which allows several".into());
                    }
                    self.layout_ids(sq, &mut q.layout);
                }
            }
        }
        if let Some(span) = q
            .memory
            .first()
            .filter(|_| q.storage != Some(Qualifier::Buffer))
        {
            // GLSL 4.30 §4.10: "only supported in the declarations of
            // image variables, buffer variables, and shader storage
            // blocks" (shaderbox has no image variables).
            self.error(
                Code::BadQualifier,
                span,
                "memory qualifiers apply only to shader storage blocks and their members",
            );
            q.memory = MemoryQuals::default();
        }
        if !global {
            if let Some(s) = q.storage.filter(|s| *s != Qualifier::Const) {
                self.error(
                    Code::BadQualifier,
                    q.storage_span,
                    format!(
                        "`{}' is not allowed on local variables; declare it at global scope",
                        s.as_str()
                    ),
                );
                q.storage = None;
            }
            if q.invariant {
                let span = find(quals, Qualifier::Invariant);
                self.error(
                    Code::BadQualifier,
                    span,
                    "`invariant' is only allowed on global outputs",
                );
                q.invariant = false;
            }
            if let Some((i, span)) = q.interpolation.take() {
                self.error(
                    Code::BadQualifier,
                    span,
                    format!(
                        "`{}' is only allowed on global `in' and `out' variables",
                        i.as_str()
                    ),
                );
            }
            if q.centroid {
                let span = find(quals, Qualifier::Centroid);
                self.error(
                    Code::BadQualifier,
                    span,
                    "`centroid' is only allowed on global inputs and outputs",
                );
                q.centroid = false;
            }
            if let Some(span) = q.patch.take() {
                self.error(
                    Code::BadQualifier,
                    span,
                    "`patch' is only allowed on global inputs and outputs of tessellation shaders",
                );
            }
            return q;
        }
        self.stage_qualifiers(&mut q, quals);
        q
    }

    /// `varying in` / `varying out` (`sq` is the `in` or `out`): a
    /// GL_EXT_geometry_shader4 geometry shader's input and output, the
    /// same as `in` and `out` in a geometry shader of 1.30 and later.
    fn varying_in_out(&mut self, sq: &SpannedQualifier, varying: Span, q: &mut VarQuals) {
        let what = format!("varying {}", sq.qualifier.as_str());
        let span = varying.to(sq.span);
        if self.stage == Stage::Geometry && self.lang.ext_geometry_shader4() {
            q.storage = Some(sq.qualifier);
            q.storage_span = span;
            return;
        }
        if self.stage != Stage::Geometry {
            let note = if self.stage == Stage::Vertex {
                "a vertex shader's outputs are `varying'; a geometry shader reads them as `varying in' arrays"
            } else {
                "a fragment shader's inputs are `varying'"
            };
            self.error(
                Code::StageMismatch,
                span,
                format!("`{what}' is only allowed in geometry shaders (GL_EXT_geometry_shader4)"),
            )
            .notes
            .push(note.into());
        } else if self.lang.version >= crate::lang::Version::V150 {
            self.error(
                Code::BadQualifier,
                span,
                format!("`{what}' is GL_EXT_geometry_shader4's form; a GLSL {} geometry shader writes `{}'", self.lang.version.dotted(), sq.qualifier.as_str()),
            )
            .notes
            .push("inputs: `in vec4 v[];' sized by `layout(triangles) in;'; outputs: `out vec4 v;'".into());
        } else {
            self.error(
                Code::VersionTooLow,
                span,
                format!("`{what}' needs `#extension GL_EXT_geometry_shader4 : enable' (or GL_ARB_geometry_shader4)"),
            );
        }
    }

    /// `in`/`out`/`inout` where a global storage qualifier is not allowed.
    fn in_out_misplaced(&mut self, sq: &SpannedQualifier, global: bool) {
        let name = sq.qualifier.as_str();
        if sq.qualifier == Qualifier::Inout {
            self.error(
                Code::BadQualifier,
                sq.span,
                "`inout' is only allowed on function parameters",
            )
            .notes
            .push("a shader's inputs and outputs are separate `in' and `out' variables".into());
        } else if !global {
            self.error(
                Code::BadQualifier,
                sq.span,
                format!("`{name}' is not allowed on local variables; declare it at global scope"),
            );
        } else if let Err(why) = self.lang.gate(Feature::StageInOut) {
            let lang = self.lang;
            let d = self.error(
                Code::BadQualifier,
                sq.span,
                format!(
                    "`{name}' at global scope needs GLSL 1.30 (this shader is GLSL {}); before, `{name}' is only allowed on function parameters",
                    lang.version.dotted()
                ),
            );
            d.notes
                .push("use `attribute'/`varying' for stage inputs and outputs".into());
            d.notes.push(why.fix());
        }
    }

    /// The rules that depend on the stage and the storage: interpolation,
    /// `centroid` and `invariant` placement (§4.3.4-§4.3.7, §4.6.1).
    fn stage_qualifiers(&mut self, q: &mut VarQuals, quals: &[SpannedQualifier]) {
        let vertex = self.stage == Stage::Vertex;
        let fragment = self.stage == Stage::Fragment;
        let storage = q.storage;
        // GL_ARB_compute_shader: `shared' variables belong to compute
        // shaders.
        match storage {
            Some(Qualifier::Shared) if self.stage != Stage::Compute => {
                self.error(
                    Code::StageMismatch,
                    q.storage_span,
                    format!(
                        "`shared' variables exist only in compute shaders, not in a {} shader",
                        self.stage.name()
                    ),
                );
            }
            _ => {}
        }
        // GL_ARB_tessellation_shader §4.3.4, §4.3.6: `patch out' in
        // control shaders, `patch in' in evaluation shaders.
        if let Some(span) = q.patch {
            let ok = match storage {
                Some(Qualifier::Out) => self.stage == Stage::TessControl,
                Some(Qualifier::In) => self.stage == Stage::TessEvaluation,
                _ => false,
            };
            if !ok {
                let what = match storage {
                    Some(Qualifier::In) => {
                        "`patch in' is allowed only in tessellation evaluation shaders"
                    }
                    Some(Qualifier::Out) => {
                        "`patch out' is allowed only in tessellation control shaders"
                    }
                    _ => "`patch' applies only to `in' and `out' variables",
                };
                let stage = self.stage.name();
                self.error(Code::BadQualifier, span, what.to_string())
                    .notes
                    .push(format!(
                        "a control shader writes per-patch outputs (`patch out'), the evaluation shader reads them (`patch in'); this is a {stage} shader"
                    ));
                q.patch = None;
            }
        }
        // A geometry shader's inputs and outputs both take interpolation
        // and `centroid' (GLSL 1.50 §4.3.4, §4.3.6).
        if let Some((i, span)) = q.interpolation {
            let msg = match storage {
                Some(Qualifier::In) if vertex => Some("vertex shader inputs"),
                Some(Qualifier::Out) if fragment => Some("fragment shader outputs"),
                Some(Qualifier::In | Qualifier::Out) => None,
                Some(Qualifier::Varying) => Some("`varying' (use `in'/`out')"),
                Some(Qualifier::Attribute) => Some("`attribute'"),
                _ => Some("variables that are not `in' or `out'"),
            };
            if let Some(m) = msg {
                self.error(
                    Code::BadQualifier,
                    span,
                    format!("`{}' does not apply to {m}", i.as_str()),
                )
                .notes
                .push("GLSL 1.30 §4.3: interpolation qualifiers apply to vertex outputs and fragment inputs".into());
                q.interpolation = None;
            }
        }
        if q.centroid {
            let bad = match storage {
                Some(Qualifier::In) => vertex,
                Some(Qualifier::Out) => fragment,
                _ => false,
            };
            if bad {
                let span = find(quals, Qualifier::Centroid);
                let what = if vertex {
                    "centroid in"
                } else {
                    "centroid out"
                };
                self.error(
                    Code::BadQualifier,
                    span,
                    format!("`{what}' is not allowed in a {} shader", self.stage.name()),
                );
                q.centroid = false;
            }
        }
        if q.invariant && !self.builtin_mode {
            let ok = match storage {
                Some(Qualifier::Varying) => true,
                Some(Qualifier::Out) => !fragment,
                // GLSL 1.50 §4.6.1: outputs "including those that are then
                // input to a subsequent shader", a geometry shader's too.
                Some(Qualifier::In) => !vertex,
                _ => false,
            };
            if !ok {
                let span = find(quals, Qualifier::Invariant);
                let msg = if self.stage == Stage::Geometry {
                    "`invariant' applies only to a shader's inputs and outputs (GLSL 1.50 §4.6.1)"
                } else if self.lang.allows(Feature::StageInOut) {
                    "`invariant' applies only to vertex outputs and fragment inputs (GLSL 1.30 §4.6.1)"
                } else {
                    "`invariant' applies only to varyings (GLSL 1.20 §4.6.1)"
                };
                self.error(Code::BadQualifier, span, msg);
                q.invariant = false;
            }
        }
        if storage == Some(Qualifier::Attribute) && !vertex {
            self.error(
                Code::StageMismatch,
                q.storage_span,
                "`attribute' is only allowed in vertex shaders",
            )
            .notes
            .push("fragment shaders read per-vertex data through `varying'".into());
            q.storage = None;
        }
    }

    /// Reads the identifiers of one `layout(...)` into `out`.
    pub(super) fn layout_ids(&mut self, sq: &SpannedQualifier, out: &mut LayoutQuals) {
        out.span.get_or_insert(sq.span);
        for id in &sq.layout {
            self.layout_id(id, out);
        }
    }

    fn layout_id(&mut self, id: &LayoutId, out: &mut LayoutQuals) {
        // GLSL 1.50 §4.3.8: layout identifiers are not case sensitive.
        let lower = id.name.name.to_ascii_lowercase();
        let span = id.span;
        let takes_value = matches!(
            lower.as_str(),
            "location"
                | "index"
                | "max_vertices"
                | "vertices"
                | "binding"
                | "local_size_x"
                | "local_size_y"
                | "local_size_z"
        );
        if takes_value && id.value.is_none() {
            self.error(
                Code::BadQualifier,
                span,
                format!("`{}' needs a value: `{} = N'", id.name.name, lower),
            );
            return;
        }
        if !takes_value && id.value.is_some() {
            self.error(
                Code::BadQualifier,
                span,
                format!("`{}' does not take a value", id.name.name),
            );
            return;
        }
        match lower.as_str() {
            "location" => {
                // Which variables may take it is `check_var_layout`'s
                // question; here, whether the language has it at all.
                if !self.lang.allows(Feature::VaryingLocation)
                    && !self.require(Feature::ExplicitLocation, "`layout(location)'", span)
                {
                    return;
                }
                let Some(v) = id.value.as_ref().and_then(|e| self.layout_value(e)) else {
                    return;
                };
                out.location = Some((v, span));
            }
            "index" => {
                // GL_ARB_blend_func_extended's second source colour of an
                // output's draw buffer (dual-source blending).
                if !self.require(Feature::ExplicitLocation, "`layout(index)'", span) {
                    return;
                }
                if let Some(v) = id.value.as_ref().and_then(|e| self.layout_value(e)) {
                    if v > 1 {
                        self.error(Code::BadQualifier, span, "`index' must be 0 or 1");
                    }
                    out.index = Some((v.min(1), span));
                }
            }
            "binding" => {
                // Which declarations may take it is judged by the
                // declaration (`var_binding`, blocks); shader storage
                // blocks take it with their own extension.
                if !self.lang.allows(Feature::StorageBuffers)
                    && !self.require(Feature::LanguagePack420, "`layout(binding)'", span)
                {
                    return;
                }
                if let Some(v) = id.value.as_ref().and_then(|e| self.layout_value(e)) {
                    out.binding = Some((v, span));
                }
            }
            "local_size_x" | "local_size_y" | "local_size_z" => {
                if !self.require(Feature::ComputeShader, &format!("`{lower}'"), span) {
                    return;
                }
                let dim = usize::from(lower.as_bytes()[11] - b'x');
                if let Some(v) = id.value.as_ref().and_then(|e| self.layout_value(e)) {
                    if let Some(slot) = out.local_size.get_mut(dim) {
                        *slot = Some((v, span));
                    }
                }
            }
            "std430" => {
                if self.require(Feature::StorageBuffers, "`std430'", span) {
                    out.block_layout = Some((BlockLayout::Std430, span));
                }
            }
            "std140" | "shared" | "packed" => {
                if !self.lang.allows(Feature::StorageBuffers)
                    && !self.require(Feature::UniformBlocks, &format!("`{lower}'"), span)
                {
                    return;
                }
                let l = match lower.as_str() {
                    "std140" => BlockLayout::Std140,
                    "shared" => BlockLayout::Shared,
                    _ => BlockLayout::Packed,
                };
                out.block_layout = Some((l, span));
            }
            "row_major" | "column_major" => {
                if !self.lang.allows(Feature::StorageBuffers)
                    && !self.require(Feature::UniformBlocks, &format!("`{lower}'"), span)
                {
                    return;
                }
                out.row_major = Some((lower == "row_major", span));
            }
            "origin_upper_left" | "pixel_center_integer" => {
                if !self.require(Feature::FragCoordConventions, &format!("`{lower}'"), span) {
                    return;
                }
                if lower == "origin_upper_left" {
                    out.origin_upper_left = Some(span);
                } else {
                    out.pixel_center_integer = Some(span);
                }
            }
            g if GEOMETRY_LAYOUTS.contains(&g) || TESS_LAYOUTS.contains(&g) => {
                if !GEOMETRY_LAYOUTS.contains(&g)
                    && !self.require(Feature::TessellationShader, &format!("`{lower}'"), span)
                {
                    return;
                }
                let value = id.value.as_ref().and_then(|e| self.layout_value(e));
                if id.value.is_some() && value.is_none() {
                    return;
                }
                out.primitive.push((lower.clone(), value, span));
            }
            _ => {
                self.error(
                    Code::BadQualifier,
                    id.name.span,
                    format!("unknown layout qualifier `{}'", id.name.name),
                )
                .notes
                .push(
                    "known here: location, std140, shared, packed, row_major, column_major, origin_upper_left, pixel_center_integer"
                        .into(),
                );
            }
        }
    }

    /// The value of `location = N`: an integer literal (the grammar's
    /// INTCONSTANT; a constant expression is not allowed).
    fn layout_value(&mut self, e: &crate::ast::Expr) -> Option<u32> {
        match e.kind {
            crate::ast::ExprKind::IntLit(v) if v <= i32::MAX as u32 => Some(v),
            crate::ast::ExprKind::IntLit(_) => {
                self.error(Code::BadQualifier, e.span, "layout value out of range");
                None
            }
            _ => {
                self.error(
                    Code::BadQualifier,
                    e.span,
                    "a layout value must be an integer literal",
                )
                .notes
                .push("GLSL 3.30 §9: `IDENTIFIER = INTCONSTANT'".into());
                None
            }
        }
    }

    /// `layout(binding = N)` of a variable of type `ty`: only uniform
    /// samplers (and arrays of them) take it, within the texture units
    /// (every element of an array, GL_ARB_shading_language_420pack).
    pub(crate) fn var_binding(&mut self, q: &VarQuals, ty: Type) -> Option<u32> {
        let (v, span) = q.layout.binding?;
        if !self.require(
            Feature::LanguagePack420,
            "`layout(binding)' on a sampler",
            span,
        ) {
            return None;
        }
        let (leaf, n) = self.array_leaf(ty);
        if q.storage != Some(Qualifier::Uniform) || !leaf.is_sampler() {
            self.error(
                Code::BadQualifier,
                span,
                "`binding' is only allowed on uniform samplers and uniform blocks",
            );
            return None;
        }
        self.binding_in_range(
            v,
            n,
            crate::limits::MAX_COMBINED_TEXTURE_IMAGE_UNITS,
            "texture units",
            span,
        )
        .then_some(v)
    }

    /// Whether bindings `first..first + count` are all below `max`;
    /// reports the error when not.
    pub(crate) fn binding_in_range(
        &mut self,
        first: u32,
        count: u32,
        max: u32,
        what: &str,
        span: Span,
    ) -> bool {
        if u64::from(first) + u64::from(count.max(1)) <= u64::from(max) {
            return true;
        }
        let msg = if count > 1 {
            format!("`binding = {first}' for {count} elements needs bindings up to {}, but there are {max} {what} (0 to {})", u64::from(first) + u64::from(count) - 1, max - 1)
        } else {
            format!(
                "`binding = {first}' is out of range: there are {max} {what} (0 to {})",
                max - 1
            )
        };
        self.error(Code::BadQualifier, span, msg);
        false
    }

    /// Reports layout identifiers a variable declaration may not have and
    /// returns its location and (fragment outputs) index.
    pub(crate) fn check_var_layout(
        &mut self,
        q: &VarQuals,
        name: &str,
    ) -> (Option<u32>, Option<u32>) {
        let l = &q.layout;
        // Vertex inputs and fragment outputs (GL_ARB_explicit_attrib_location,
        // GLSL 3.30) or the inputs and outputs between stages
        // (GL_ARB_separate_shader_objects).
        let (loc_ok, feature) = match q.storage {
            Some(Qualifier::In) if self.stage == Stage::Vertex => (true, Feature::ExplicitLocation),
            Some(Qualifier::Out) if self.stage == Stage::Fragment => {
                (true, Feature::ExplicitLocation)
            }
            Some(Qualifier::In | Qualifier::Out) => (true, Feature::VaryingLocation),
            _ => (false, Feature::ExplicitLocation),
        };
        let mut location = None;
        let mut index = None;
        if let Some((v, span)) = l.index {
            let frag_out = self.stage == Stage::Fragment && q.storage == Some(Qualifier::Out);
            if frag_out && l.location.is_some() {
                index = Some(v);
            } else {
                self.error(
                    Code::BadQualifier,
                    span,
                    "`index' is only allowed with `location' on fragment shader outputs",
                );
            }
        }
        if let Some((v, span)) = l.location {
            if !loc_ok {
                self.error(
                    Code::BadQualifier,
                    span,
                    format!(
                        "`location' is only allowed on `in' and `out' variables, not on `{name}'"
                    ),
                );
            } else if self.require(feature, "`layout(location)' on this variable", span) {
                location = Some(v);
            }
        }
        for (what, span) in [
            l.block_layout.map(|(_, s)| ("std140/shared/packed", s)),
            l.row_major.map(|(_, s)| ("row_major/column_major", s)),
        ]
        .into_iter()
        .flatten()
        {
            self.error(
                Code::BadQualifier,
                span,
                format!("`{what}' applies only to uniform blocks and their members"),
            );
        }
        let frag_coord = name == "gl_FragCoord" && self.stage == Stage::Fragment;
        for span in [l.origin_upper_left, l.pixel_center_integer]
            .into_iter()
            .flatten()
        {
            if !frag_coord {
                self.error(
                    Code::BadQualifier,
                    span,
                    "`origin_upper_left' and `pixel_center_integer' apply only to a redeclaration of `gl_FragCoord'",
                );
            }
        }
        if let Some((g, _, span)) = l.primitive.first() {
            self.misplaced_primitive_layout(g, *span);
        }
        if let Some((_, span)) = l.local_size.iter().flatten().next() {
            self.misplaced_local_size(*span);
        }
        (location, index)
    }

    /// One precision qualifier of a parameter, return type or member:
    /// checks it is available and not repeated.
    pub(crate) fn precision_qualifier(&mut self, sq: &SpannedQualifier, seen: &mut Option<Span>) {
        if !self.require(
            Feature::Precision,
            &format!("`{}'", sq.qualifier.as_str()),
            sq.span,
        ) {
            return;
        }
        if seen.is_some() {
            self.error(
                Code::BadQualifier,
                sq.span,
                "only one precision qualifier is allowed",
            );
        }
        *seen = Some(sq.span);
    }

    /// Whether a precision qualifier may be on a declaration of `ty`.
    pub(crate) fn check_precision(&mut self, span: Option<Span>, ty: Type) {
        let Some(span) = span else { return };
        if ty.is_error() {
            return;
        }
        // An array of arrays takes the precision of its innermost element.
        let mut elem = ty.element();
        for _ in 0..64 {
            match self.array_row_member(elem) {
                Some(row) => elem = row.element(),
                None => break,
            }
        }
        if !takes_precision(elem) {
            let tn = self.tn(ty);
            self.error(
                Code::BadQualifier,
                span,
                format!("precision qualifiers apply to floating-point, integer and sampler types, not {tn}"),
            );
        }
    }

    /// `precision highp float;` (GLSL 1.30 §4.5.3): the type is `float`,
    /// `int` or a sampler; no effect.
    pub(crate) fn precision_statement(
        &mut self,
        precision: &SpannedQualifier,
        ty: &crate::ast::TypeSpecifier,
    ) {
        if !self.require(Feature::Precision, "`precision'", precision.span) {
            return;
        }
        let ok = match &ty.name {
            TypeName::Builtin(crate::token::Keyword::Float | crate::token::Keyword::Int) => true,
            TypeName::Builtin(_) => self.resolve_type(ty).is_sampler(),
            _ => false,
        };
        if !ok || ty.array.is_some() {
            self.error(
                Code::BadQualifier,
                ty.span,
                "a default precision is set for `float', `int' or a sampler type",
            );
        }
    }

    /// Qualifiers alone (`layout(std140) uniform;`, `layout(triangles) in;`).
    pub(crate) fn qualifiers_only(&mut self, quals: &[SpannedQualifier], span: Span) {
        let q = self.var_qualifiers(quals);
        let l = &q.layout;
        match q.storage {
            Some(Qualifier::Uniform) if l.span.is_some() => {
                if l.location.is_some()
                    || l.binding.is_some()
                    || l.origin_upper_left.is_some()
                    || l.pixel_center_integer.is_some()
                    || !l.primitive.is_empty()
                {
                    self.error(
                        Code::BadQualifier,
                        span,
                        "a default uniform layout takes only std140, shared, packed, row_major or column_major",
                    );
                    return;
                }
                if let Some((b, _)) = l.block_layout {
                    self.default_block_layout = b;
                }
                if let Some((r, _)) = l.row_major {
                    self.default_row_major = r;
                }
            }
            Some(Qualifier::In | Qualifier::Out)
                if self.stage == Stage::Geometry && l.span.is_some() =>
            {
                let input = q.storage == Some(Qualifier::In);
                self.geometry_layout(&q, input);
            }
            Some(Qualifier::In) if self.stage == Stage::Compute && l.span.is_some() => {
                self.compute_layout(&q);
            }
            Some(Qualifier::Out) if self.stage == Stage::TessControl && l.span.is_some() => {
                self.tess_layout(&q, false);
            }
            Some(Qualifier::In) if self.stage == Stage::TessEvaluation && l.span.is_some() => {
                self.tess_layout(&q, true);
            }
            _ => {
                if let Some((g, _, s)) = l.primitive.first() {
                    self.misplaced_primitive_layout(g, *s);
                } else if let Some((_, s)) = l.local_size.iter().flatten().next() {
                    self.misplaced_local_size(*s);
                } else {
                    self.error(
                        Code::Syntax,
                        span,
                        "a declaration needs a type and a name (only `layout(...) uniform;' may stand alone)",
                    );
                }
            }
        }
    }
}

pub(super) fn find(quals: &[SpannedQualifier], q: Qualifier) -> Span {
    quals
        .iter()
        .find(|x| x.qualifier == q)
        .map_or(Span::default(), |x| x.span)
}

#[cfg(test)]
#[path = "interface_tests.rs"]
pub(crate) mod tests;
