//! The language a shader is written in: its version, profile and enabled
//! extensions ([`Language`]), and the one table that says which version,
//! profile or extension each language feature needs ([`Feature`],
//! [`Language::gate`]).
//!
//! Every version check of the front end goes through [`Language::gate`]
//! (or, for keywords, the `since` column of [`crate::token`]'s keyword
//! table), so that a feature's availability is stated once and its
//! diagnostic ("`switch' needs GLSL 1.30") is worded once.

use serde::Serialize;

/// A language version this front end accepts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub enum Version {
    V110,
    V120,
    V130,
    V140,
    V150,
    V330,
}

impl Version {
    /// Every version, oldest first.
    pub const ALL: [Version; 6] = [
        Version::V110,
        Version::V120,
        Version::V130,
        Version::V140,
        Version::V150,
        Version::V330,
    ];

    /// The number as written after `#version`.
    pub fn number(self) -> u32 {
        match self {
            Version::V110 => 110,
            Version::V120 => 120,
            Version::V130 => 130,
            Version::V140 => 140,
            Version::V150 => 150,
            Version::V330 => 330,
        }
    }

    pub fn from_number(n: u32) -> Option<Version> {
        Version::ALL.into_iter().find(|v| v.number() == n)
    }

    /// "1.10", "3.30", as error messages spell it.
    pub fn dotted(self) -> &'static str {
        match self {
            Version::V110 => "1.10",
            Version::V120 => "1.20",
            Version::V130 => "1.30",
            Version::V140 => "1.40",
            Version::V150 => "1.50",
            Version::V330 => "3.30",
        }
    }

    /// Whether `#version N core|compatibility` may name a profile (from
    /// 1.50 on; GLSL 1.50 §3.3).
    pub fn has_profiles(self) -> bool {
        self >= Version::V150
    }
}

/// Which of a version's two profiles a shader is compiled for.
///
/// Versions up to 1.30 have one language, the whole of it: they are
/// `Compatibility` here. GLSL 1.40 removes the fixed-function interface
/// (its §1.2.5) unless the context has `GL_ARB_compatibility`, so a 1.40
/// shader takes the context's profile. From 1.50 on the `#version` line
/// names the profile, and its absence means core (GLSL 1.50 §3.3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub enum Profile {
    Core,
    Compatibility,
}

impl Profile {
    /// The word after the version number in `#version`.
    pub fn name(self) -> &'static str {
        match self {
            Profile::Core => "core",
            Profile::Compatibility => "compatibility",
        }
    }
}

macro_rules! extensions {
    ($($variant:ident = $name:literal;)*) => {
        /// The extensions the front end implements: `#extension` accepts
        /// them and each defines a macro of its name with value 1.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
        pub enum Extension { $($variant),* }

        impl Extension {
            pub const ALL: &'static [Extension] = &[$(Extension::$variant),*];

            pub fn name(self) -> &'static str {
                match self { $(Extension::$variant => $name),* }
            }

            pub fn from_name(name: &str) -> Option<Extension> {
                match name { $($name => Some(Extension::$variant),)* _ => None }
            }
        }
    };
}

extensions! {
    // Its GLSL side is `gl_FragData`, which GLSL 1.10 already has;
    // `#extension` must accept it since the GL layer reports it.
    ArbDrawBuffers = "GL_ARB_draw_buffers";
    // shaderbox's `debugPrintfEXT` (see `crate::printf`).
    ShaderboxDebugPrintf = "GL_SHADERBOX_debug_printf";
    // In a compatibility context, enabling it gives a core-profile shader
    // (`#version 140`, or `150` without a profile word) the compatibility
    // profile's built-ins, as the context's GL_ARB_compatibility promises.
    ArbCompatibility = "GL_ARB_compatibility";
    // `layout(location = N)` on vertex inputs and fragment outputs.
    ArbExplicitAttribLocation = "GL_ARB_explicit_attrib_location";
    // Uniform blocks and their layout qualifiers.
    ArbUniformBufferObject = "GL_ARB_uniform_buffer_object";
    // `layout(origin_upper_left, pixel_center_integer)` on `gl_FragCoord`.
    ArbFragmentCoordConventions = "GL_ARB_fragment_coord_conventions";
    // Dual-source blending. Its GLSL side is `layout(index)`, taken
    // wherever `layout(location)` is (GLSL 3.30, or with
    // GL_ARB_explicit_attrib_location); `#extension` must accept it since
    // the GL layer reports it.
    ArbBlendFuncExtended = "GL_ARB_blend_func_extended";
    // Geometry shaders before GLSL 1.50 (`varying in`, `gl_PositionIn[]`,
    // `gl_VerticesIn`...), the two names of one extension.
    ExtGeometryShader4 = "GL_EXT_geometry_shader4";
    ArbGeometryShader4 = "GL_ARB_geometry_shader4";
    // `sampler2DRect`, `sampler2DRectShadow` and their lookups
    // (`texture2DRect`...): GLSL 1.40 has them, so the extension is
    // offered from 1.40 on ([`Extension::since`]).
    ArbTextureRectangle = "GL_ARB_texture_rectangle";
    // `sampler2DMS`, `sampler2DMSArray` (and the `i`/`u` forms) and
    // `texelFetch` with a sample number: GLSL 1.50's, offered from 1.50.
    ArbTextureMultisample = "GL_ARB_texture_multisample";
    // The lookups of array textures under their extension names
    // (`texture2DArray`, `shadow1DArrayLod`...) on the sampler types GLSL
    // 1.30 has, offered from 1.30 on.
    ExtTextureArray = "GL_EXT_texture_array";
    // The explicit-LOD lookups in fragment shaders before GLSL 1.30, and
    // the `*GradARB` lookups with explicit derivatives.
    ArbShaderTextureLod = "GL_ARB_shader_texture_lod";
    // Arrays of arrays (`float a[2][3]`, `float[2][3]`, `float[3] a[2]`),
    // which GLSL 4.30 made core. Its "GLSL 1.2 is required" asks the
    // implementation for GLSL 1.20, which every context has, so shaders
    // of every version may enable it (as Mesa offers it); a 1.10 shader
    // still has no array type syntax or constructors.
    ArbArraysOfArrays = "GL_ARB_arrays_of_arrays";
    // `packUnorm2x16`... and `packHalf2x16`/`unpackHalf2x16`. Their
    // `uint`s need GLSL 1.30, so the functions exist from 1.30 on; the
    // extension (its macro, `#extension`) is accepted in every version,
    // as the spec names no version and Mesa accepts it.
    ArbShadingLanguagePacking = "GL_ARB_shading_language_packing";
    // `samplerCubeArray`, `samplerCubeArrayShadow`, `isamplerCubeArray`,
    // `usamplerCubeArray` and their lookups under GLSL 1.30's names
    // (`texture`, `textureLod`...), which exist from 1.30 on; the
    // directive and macro are accepted in every version, as Mesa does.
    ArbTextureCubeMapArray = "GL_ARB_texture_cube_map_array";
    // Separable programs: `layout(location = N)` on the inputs and
    // outputs between stages (vertex outputs, geometry inputs and
    // outputs, fragment inputs), matched by location across programs;
    // global `in`/`out` in the versions before 1.30, as with
    // GL_ARB_explicit_attrib_location. Its redeclarations of
    // `gl_PerVertex` are GLSL 1.50's, which every version here allows
    // wherever it has blocks.
    ArbSeparateShaderObjects = "GL_ARB_separate_shader_objects";
    // GLSL 4.20's language pack: initializer lists, `.length()` of
    // vectors and matrices, swizzles of scalars, `const` locals with
    // initializers that are not constant, implicit conversion of return
    // values, qualifiers in any order, `layout(binding = N)` on samplers
    // and uniform blocks. Its "GLSL 1.3 is required" asks the
    // implementation for GLSL 1.30, which the 3.3 contexts offering it
    // have, so shaders of every version may enable it (as Mesa offers it).
    ArbShadingLanguage420pack = "GL_ARB_shading_language_420pack";
    // Compute shaders: the stage, `layout(local_size_*) in;`, `shared`
    // variables, their built-ins and the barrier and atomic functions.
    // Written against GLSL 4.20, which no version here reaches: shaders
    // of every version may enable it (as Mesa offers it to 3.3 ones).
    ArbComputeShader = "GL_ARB_compute_shader";
    // Shader storage blocks (`buffer B { ... };`), their memory
    // qualifiers, `std430`, a last member of unknown size and the atomic
    // functions on buffer variables. Written against GLSL 4.20: shaders
    // of every version may enable it, as Mesa offers it.
    ArbShaderStorageBufferObject = "GL_ARB_shader_storage_buffer_object";
    // The tessellation control and evaluation stages: `patch` inputs and
    // outputs, `layout(vertices = N) out;`, the evaluation layouts,
    // `gl_in[]`/`gl_out[]`, the tessellation levels and `barrier()`.
    // Written against GLSL 1.50; its stages exist from 1.40 on here, as
    // Mesa (and piglit's generated tests) take `#version 140` with it.
    ArbTessellationShader = "GL_ARB_tessellation_shader";
}

impl Extension {
    /// The first GLSL version whose shaders may enable the extension:
    /// the ones whose built-ins shaderbox has only where the language has
    /// them in core are offered from that version on (no `#extension`
    /// and no macro before it).
    pub fn since(self) -> Version {
        match self {
            Extension::ArbTextureRectangle => Version::V140,
            Extension::ArbTextureMultisample => Version::V150,
            Extension::ExtTextureArray => Version::V130,
            _ => Version::V110,
        }
    }
}

/// A set of [`Extension`]s.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
pub struct ExtensionSet(u64);

impl ExtensionSet {
    pub const EMPTY: ExtensionSet = ExtensionSet(0);

    pub fn contains(self, e: Extension) -> bool {
        self.0 & (1 << e as u32) != 0
    }

    pub fn set(&mut self, e: Extension, on: bool) {
        if on {
            self.0 |= 1 << e as u32;
        } else {
            self.0 &= !(1 << e as u32);
        }
    }
}

/// Version, profile and enabled extensions: everything that decides which
/// words are keywords and which constructs and built-ins exist.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub struct Language {
    pub version: Version,
    pub profile: Profile,
    /// Extensions enabled by `#extension` (`enable`, `require` or `warn`)
    /// at the point of the shader being looked at.
    pub extensions: ExtensionSet,
}

/// A construct or built-in whose existence depends on the language.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Feature {
    /// The `f`/`F` suffix on floating-point literals.
    FloatSuffix,
    /// Array constructors, `.length()`, array assignment and comparison,
    /// initializers of uniforms, non-square matrices, implicit int→float.
    Glsl120Core,
    /// `uint`, `uvec*` and the `u` literal suffix.
    Unsigned,
    /// `switch`, `case`, `default`.
    Switch,
    /// `%`, `<<`, `>>`, `&`, `|`, `^`, `~` and their assignments.
    IntegerOperators,
    /// `flat`, `smooth`, `noperspective`.
    InterpolationQualifiers,
    /// `in`/`out`/`centroid in`/`centroid out` at global scope.
    StageInOut,
    /// `lowp`, `mediump`, `highp`, `precision` (accepted, no effect).
    Precision,
    /// The preprocessor's token-pasting operator `##` in a macro's
    /// replacement list (GLSL 1.30 §3.3).
    TokenPasting,
    /// Indexing an array of samplers with an expression that is not
    /// constant: GLSL 1.10 and 1.20 say nothing against it, 1.30 §4.1.7
    /// allows "integral constant expressions" only.
    NonConstantSamplerIndex,
    /// Uniform blocks (`uniform B { ... };`) and their layout qualifiers
    /// `std140`, `shared`, `packed`, `row_major`, `column_major`.
    UniformBlocks,
    /// Input and output interface blocks (`out B { ... } b;`).
    InOutBlocks,
    /// `layout(location = N)` on vertex inputs and fragment outputs.
    ExplicitLocation,
    /// `layout(origin_upper_left)`, `layout(pixel_center_integer)` on a
    /// redeclared `gl_FragCoord`.
    FragCoordConventions,
    /// The fixed-function interface GLSL 1.40 removes (its §1.2.5):
    /// built-in vertex inputs (`gl_Vertex`...), built-in uniforms other
    /// than `gl_DepthRange`, `gl_TexCoord`, `gl_FogFragCoord` and the
    /// colour varyings, `gl_ClipVertex`, `ftransform()`.
    CompatibilityInterface,
    /// The geometry stage: its inputs, outputs, layouts and built-ins
    /// (GLSL 1.50 §2.2), or before 1.50 GL_EXT_geometry_shader4's form
    /// (also named GL_ARB_geometry_shader4; see
    /// [`Language::ext_geometry_shader4`]).
    GeometryShader,
    /// An array whose elements are arrays (GL_ARB_arrays_of_arrays; no
    /// version shaderbox implements has them in core).
    ArraysOfArrays,
    /// `layout(location = N)` on the inputs and outputs between stages
    /// (GL_ARB_separate_shader_objects; GLSL 4.10 has it in core).
    VaryingLocation,
    /// GL_ARB_shading_language_420pack's language changes (GLSL 4.20 has
    /// them in core): initializer lists `{...}`, `.length()` of vectors
    /// and matrices, swizzles of scalars, `const` locals initialized by
    /// expressions that are not constant, implicit conversion of return
    /// values, qualifiers in any order and repeated `layout`s, `const`
    /// parameters after other parameter qualifiers, `layout(binding)`.
    LanguagePack420,
    /// The compute stage and its `shared` variables (GL_ARB_compute_shader).
    ComputeShader,
    /// Shader storage blocks, memory qualifiers and `std430`
    /// (GL_ARB_shader_storage_buffer_object).
    StorageBuffers,
    /// The tessellation control and evaluation stages and their `patch`
    /// qualifier (GL_ARB_tessellation_shader).
    TessellationShader,
}

/// Why a feature is not available to a shader.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unavailable {
    /// It exists from this version on.
    NeedsVersion(Version),
    /// It exists from this version on, or earlier with the extension.
    NeedsVersionOrExtension(Version, Extension),
    /// It exists only with the extension enabled.
    NeedsExtension(Extension),
    /// The core profile of this version (and later) removes it.
    RemovedInCore(Version),
    /// This version (and later) removes it from both profiles.
    Removed(Version),
}

impl Unavailable {
    /// One sentence for a diagnostic: "`switch' needs GLSL 1.30 (this
    /// shader is GLSL 1.20)". `what` names the construct, quoted.
    pub fn message(self, what: &str, lang: Language) -> String {
        let this = format!(
            "this shader is GLSL {}{}",
            lang.version.dotted(),
            if lang.version >= Version::V140 {
                format!(", {} profile", lang.profile.name())
            } else {
                String::new()
            }
        );
        match self {
            Unavailable::NeedsVersion(v) => format!("{what} needs GLSL {} ({this})", v.dotted()),
            Unavailable::NeedsVersionOrExtension(v, e) => format!(
                "{what} needs GLSL {} or `#extension {} : enable' ({this})",
                v.dotted(),
                e.name()
            ),
            Unavailable::NeedsExtension(e) => {
                format!("{what} needs `#extension {} : enable' ({this})", e.name())
            }
            Unavailable::RemovedInCore(v) => format!(
                "{what} is removed in the core profile of GLSL {} and later ({this})",
                v.dotted()
            ),
            Unavailable::Removed(v) => {
                format!("{what} is not allowed from GLSL {} on ({this})", v.dotted())
            }
        }
    }

    /// What the user can write instead, as a note.
    pub fn fix(self) -> String {
        match self {
            Unavailable::NeedsVersion(v) | Unavailable::NeedsVersionOrExtension(v, _) => {
                format!("start the shader with `#version {}'", v.number())
            }
            Unavailable::NeedsExtension(e) if e.since() > Version::V110 => format!(
                "add `#extension {} : enable' (offered from GLSL {} on)",
                e.name(),
                e.since().dotted()
            ),
            Unavailable::NeedsExtension(e) => format!(
                "add `#extension {} : enable' after `#version'; no version up to GLSL 3.30 has it without the extension",
                e.name()
            ),
            Unavailable::RemovedInCore(v) if v >= Version::V150 => format!(
                "write `#version {} compatibility' to keep it, in a compatibility context",
                v.number()
            ),
            Unavailable::RemovedInCore(_) => {
                "it is kept only in a compatibility context (GL_ARB_compatibility)".to_string()
            }
            Unavailable::Removed(v) => format!(
                "it needs a version before {}; later versions have no way to keep it",
                v.dotted()
            ),
        }
    }
}

impl Language {
    /// The language of a shader with `#version` `version` (and no
    /// profile word) in a context that does (`compatibility_context`) or
    /// does not offer the compatibility profile.
    pub fn new(version: Version, compatibility_context: bool) -> Language {
        let profile = match version {
            Version::V110 | Version::V120 | Version::V130 => Profile::Compatibility,
            Version::V140 if compatibility_context => Profile::Compatibility,
            _ => Profile::Core,
        };
        Language {
            version,
            profile,
            extensions: ExtensionSet::EMPTY,
        }
    }

    pub fn has(self, e: Extension) -> bool {
        self.extensions.contains(e)
    }

    /// Whether `feature` exists in this language, or why not.
    pub fn gate(self, feature: Feature) -> Result<(), Unavailable> {
        let since = |v: Version| {
            if self.version >= v {
                Ok(())
            } else {
                Err(Unavailable::NeedsVersion(v))
            }
        };
        match feature {
            Feature::FloatSuffix | Feature::Glsl120Core => since(Version::V120),
            Feature::Unsigned
            | Feature::Switch
            | Feature::IntegerOperators
            | Feature::InterpolationQualifiers
            | Feature::Precision
            | Feature::TokenPasting => since(Version::V130),
            Feature::NonConstantSamplerIndex => {
                if self.version >= Version::V130 {
                    Err(Unavailable::Removed(Version::V130))
                } else {
                    Ok(())
                }
            }
            // GL_ARB_explicit_attrib_location's `layout(location) in`
            // needs global `in`/`out` in the versions it extends.
            Feature::StageInOut => {
                if self.has(Extension::ArbSeparateShaderObjects) {
                    Ok(())
                } else {
                    self.since_or(Version::V130, Extension::ArbExplicitAttribLocation)
                }
            }
            Feature::UniformBlocks => {
                self.since_or(Version::V140, Extension::ArbUniformBufferObject)
            }
            Feature::InOutBlocks => since(Version::V150),
            Feature::GeometryShader => {
                if self.ext_geometry_shader4() {
                    Ok(())
                } else {
                    self.since_or(Version::V150, Extension::ExtGeometryShader4)
                }
            }
            Feature::ExplicitLocation => {
                self.since_or(Version::V330, Extension::ArbExplicitAttribLocation)
            }
            Feature::FragCoordConventions => {
                self.since_or(Version::V150, Extension::ArbFragmentCoordConventions)
            }
            Feature::ArraysOfArrays => self.only_with(Extension::ArbArraysOfArrays),
            Feature::VaryingLocation => self.only_with(Extension::ArbSeparateShaderObjects),
            Feature::LanguagePack420 => self.only_with(Extension::ArbShadingLanguage420pack),
            // Its built-ins are `uvec3`s: GLSL 1.30 on, with the extension.
            Feature::StorageBuffers => self.only_with(Extension::ArbShaderStorageBufferObject),
            Feature::ComputeShader => {
                since(Version::V130).and_then(|()| self.only_with(Extension::ArbComputeShader))
            }
            Feature::TessellationShader => {
                since(Version::V140).and_then(|()| self.only_with(Extension::ArbTessellationShader))
            }
            Feature::CompatibilityInterface => {
                if self.version >= Version::V140 && self.profile == Profile::Core {
                    Err(Unavailable::RemovedInCore(Version::V140))
                } else {
                    Ok(())
                }
            }
        }
    }

    /// Whether a geometry shader of this language is written in
    /// GL_EXT_geometry_shader4's form (GL_ARB_geometry_shader4 is the same
    /// extension): a version before 1.50 with either name enabled. Its
    /// inputs are `varying in` arrays and `gl_PositionIn[]`...,
    /// `gl_VerticesIn` is a constant, and the input and output primitives
    /// and the vertex count are the program's parameters, not layouts. A
    /// GLSL 1.50 shader is always the 1.50 form.
    pub fn ext_geometry_shader4(self) -> bool {
        self.version < Version::V150
            && (self.has(Extension::ExtGeometryShader4) || self.has(Extension::ArbGeometryShader4))
    }

    /// Available only with `e` enabled (no version up to 3.30 has it).
    fn only_with(self, e: Extension) -> Result<(), Unavailable> {
        if self.has(e) {
            Ok(())
        } else {
            Err(Unavailable::NeedsExtension(e))
        }
    }

    /// Available from `v` on, or earlier with `e` enabled.
    fn since_or(self, v: Version, e: Extension) -> Result<(), Unavailable> {
        if self.version >= v || self.has(e) {
            Ok(())
        } else {
            Err(Unavailable::NeedsVersionOrExtension(v, e))
        }
    }

    /// Whether `layout` is a keyword: from GLSL 1.40 on, and earlier when
    /// an extension that uses it is enabled.
    pub fn has_layout_keyword(self) -> bool {
        self.version >= Version::V140
            || self.has(Extension::ArbExplicitAttribLocation)
            || self.has(Extension::ArbUniformBufferObject)
            || self.has(Extension::ArbFragmentCoordConventions)
            || self.has(Extension::ArbSeparateShaderObjects)
            || self.has(Extension::ArbShadingLanguage420pack)
            || self.has(Extension::ArbShaderStorageBufferObject)
            || self.has(Extension::ArbComputeShader)
            || self.has(Extension::ArbTessellationShader)
    }

    /// `gate` as a bool.
    pub fn allows(self, feature: Feature) -> bool {
        self.gate(feature).is_ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn profiles_follow_the_version_and_context() {
        assert_eq!(
            Language::new(Version::V130, false).profile,
            Profile::Compatibility
        );
        assert_eq!(
            Language::new(Version::V140, true).profile,
            Profile::Compatibility
        );
        assert_eq!(Language::new(Version::V140, false).profile, Profile::Core);
        assert_eq!(Language::new(Version::V150, true).profile, Profile::Core);
    }

    #[test]
    fn gates_name_the_version_that_adds_a_feature() {
        let l = Language::new(Version::V120, true);
        let why = l.gate(Feature::Switch).unwrap_err();
        assert_eq!(why, Unavailable::NeedsVersion(Version::V130));
        assert_eq!(
            why.message("`switch'", l),
            "`switch' needs GLSL 1.30 (this shader is GLSL 1.20)"
        );
        let core = Language::new(Version::V150, true);
        assert_eq!(
            core.gate(Feature::CompatibilityInterface),
            Err(Unavailable::RemovedInCore(Version::V140))
        );
        let mut compat = core;
        compat.profile = Profile::Compatibility;
        assert!(compat.allows(Feature::CompatibilityInterface));
    }

    #[test]
    fn extension_names_round_trip() {
        for &e in Extension::ALL {
            assert_eq!(Extension::from_name(e.name()), Some(e));
        }
        let mut s = ExtensionSet::EMPTY;
        s.set(Extension::ShaderboxDebugPrintf, true);
        assert!(s.contains(Extension::ShaderboxDebugPrintf));
        assert!(!s.contains(Extension::ArbDrawBuffers));
        s.set(Extension::ShaderboxDebugPrintf, false);
        assert_eq!(s, ExtensionSet::EMPTY);
    }
}
