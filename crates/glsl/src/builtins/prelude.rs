//! The built-in environment of a shader, as GLSL source.
//!
//! [`prelude`] returns the declarations of everything a language
//! ([`Language`]: version and profile) makes visible to a shader of one
//! stage before its first line: the constants of §7.4, the uniform state of
//! §7.5 (with its struct types), the stage's special variables, inputs and
//! outputs (§7.1-7.3, §7.6) and the prototypes of every built-in function
//! of §8. The semantic analyzer parses it in a privileged mode (where `gl_`
//! names, `varying bool`, `attribute int` and bodiless prototypes of
//! built-ins are accepted) before the user's shader.
//!
//! Where each built-in exists is stated once, beside its declaration, as
//! a [`Where`] (first version, last version, stage, profile) in one of
//! three tables: [`VARIABLES`] (constants, uniforms, stage variables),
//! [`FUNCTIONS`] (§8.1-8.6, 8.8, 8.9 and the pre-1.30 lookups of §8.7) and
//! [`SAMPLERS`] (the lookups of §8.7 from 1.30 on, one row per sampler
//! type). The text of a language is those tables filtered by it, in table
//! order. [`REPLACEMENTS`] says what to write instead of what the core
//! profile removes.
//!
//! Access rules are expressed with ordinary qualifiers (the same in every
//! version, since a built-in is never redeclared with another storage):
//! - stage outputs (`gl_Position`, `gl_FragColor`, ...) are plain globals:
//!   readable and writable;
//! - vertex inputs are `attribute`s (read-only);
//! - fragment inputs, including `gl_FragCoord` and `gl_FrontFacing`, are
//!   `varying`s (read-only in a fragment shader);
//! - vertex outputs to the fragment stage are `varying`s (writable in a
//!   vertex shader);
//! - geometry inputs are `in` (read-only: `gl_in[]`, `gl_PrimitiveIDIn`),
//!   or `varying in` in GL_EXT_geometry_shader4's form (`gl_PositionIn[]`
//!   ..., unsized: the analyzer sizes them by the input primitive, and
//!   `gl_VerticesIn` is [`prelude_for_input`]'s);
//!   its outputs are plain globals like the vertex stage's, or `varying`s
//!   (`gl_PrimitiveID`, `gl_Layer`, the compatibility colours).
//!
//! Nothing else is declared: a name missing from this text is not a
//! built-in of that language and stage. The text starts with the matching
//! `#version` line, then, when the language enables
//! GL_ARB_texture_cube_map_array or GL_ARB_tessellation_shader, their
//! `#extension` lines (the sampler type names, and `patch`, are keywords
//! only where they are enabled), and has no other preprocessor directive.
//!
//! The unsigned overloads are those the specs list and no more: `min`,
//! `max` and `clamp` on `genUType` (with the `uvec, uint` forms), the six
//! relational functions on `uvec` (1.30), `floatBitsToUint` and
//! `uintBitsToFloat` (3.30), and every lookup on `usampler*` (a `"u"` in
//! [`G_PREFIXES`]: the same rows as the float and int samplers, results
//! `uvec4`, `textureSize` still `int`/`ivec`). `abs` and `sign` have no
//! unsigned form, and `mix` with a `bvec` selector takes `genType` only
//! until GLSL 4.50 adds the integer and bool forms.

use crate::ir::{InputPrimitive, Stage};
use crate::lang::{Extension, Feature, Language, Version};
use crate::limits;
use std::fmt::Write;

/// The built-in declarations for `lang` and `stage` (the semantic
/// analyzer caches what it makes of them).
pub fn prelude(lang: Language, stage: Stage) -> String {
    build(lang, stage, InputPrimitive::Triangles)
}

/// [`prelude`] for a GL_EXT_geometry_shader4 geometry shader whose
/// program takes `input` primitives: `gl_VerticesIn` is their vertex
/// count. Other languages and stages ignore `input`.
pub fn prelude_for_input(lang: Language, stage: Stage, input: InputPrimitive) -> String {
    build(lang, stage, input)
}

/// Which stages a built-in exists in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Stages {
    All,
    Vertex,
    Geometry,
    Fragment,
    /// The vertex and geometry stages (the explicit-LOD lookups of
    /// 1.10/1.20, which GL_EXT_geometry_shader4 gives geometry shaders).
    VertexGeometry,
    Compute,
    TessControl,
    TessEvaluation,
    /// Both tessellation stages.
    Tess,
}

/// Where a built-in exists: from `since`, up to but not including `until`,
/// in `stages`, and in both profiles or only the compatibility one.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Where {
    since: Version,
    until: Option<Version>,
    stages: Stages,
    /// Part of the fixed-function interface GLSL 1.40 removes from the
    /// core profile ([`Feature::CompatibilityInterface`]).
    compat_only: bool,
    /// The core profile's form of something the compatibility profile
    /// extends (`gl_in[]`'s members, GLSL 1.50 §7.1 and §7.1.1).
    core_only: bool,
    /// Only in GL_EXT_geometry_shader4's form of the geometry stage
    /// ([`Language::ext_geometry_shader4`]).
    ext_gs: bool,
    /// Only with this extension enabled.
    needs: Option<Extension>,
    /// Or else: in any stage of this version or later with this extension
    /// enabled (built-ins two extensions bring, such as the atomic
    /// functions of compute shaders and of shader storage blocks).
    or_with: Option<(Version, Extension)>,
}

impl Where {
    /// Every version, stage and profile.
    const ALL: Where = Where {
        since: Version::V110,
        until: None,
        stages: Stages::All,
        compat_only: false,
        core_only: false,
        ext_gs: false,
        needs: None,
        or_with: None,
    };

    const fn since(v: Version) -> Where {
        Where {
            since: v,
            ..Where::ALL
        }
    }

    const fn until(self, v: Version) -> Where {
        Where {
            until: Some(v),
            ..self
        }
    }

    const fn vs(self) -> Where {
        Where {
            stages: Stages::Vertex,
            ..self
        }
    }

    const fn gs(self) -> Where {
        Where {
            stages: Stages::Geometry,
            ..self
        }
    }

    const fn ext_gs(self) -> Where {
        Where {
            ext_gs: true,
            ..self
        }
    }

    const fn or_with(self, v: Version, e: Extension) -> Where {
        Where {
            or_with: Some((v, e)),
            ..self
        }
    }

    const fn needs(self, e: Extension) -> Where {
        Where {
            needs: Some(e),
            ..self
        }
    }

    const fn core(self) -> Where {
        Where {
            core_only: true,
            ..self
        }
    }

    const fn tcs(self) -> Where {
        Where {
            stages: Stages::TessControl,
            ..self
        }
    }

    const fn tes(self) -> Where {
        Where {
            stages: Stages::TessEvaluation,
            ..self
        }
    }

    const fn tess(self) -> Where {
        Where {
            stages: Stages::Tess,
            ..self
        }
    }

    const fn cs(self) -> Where {
        Where {
            stages: Stages::Compute,
            ..self
        }
    }

    const fn fs(self) -> Where {
        Where {
            stages: Stages::Fragment,
            ..self
        }
    }

    const fn compat(self) -> Where {
        Where {
            compat_only: true,
            ..self
        }
    }

    fn holds(self, lang: Language, stage: Stage) -> bool {
        if let Some((v, e)) = self.or_with {
            if lang.version >= v && lang.has(e) {
                return true;
            }
        }
        lang.version >= self.since
            && self.until.is_none_or(|u| lang.version < u)
            && match self.stages {
                Stages::All => true,
                Stages::Vertex => stage == Stage::Vertex,
                Stages::Geometry => stage == Stage::Geometry,
                Stages::Fragment => stage == Stage::Fragment,
                Stages::VertexGeometry => matches!(stage, Stage::Vertex | Stage::Geometry),
                Stages::Compute => stage == Stage::Compute,
                Stages::TessControl => stage == Stage::TessControl,
                Stages::TessEvaluation => stage == Stage::TessEvaluation,
                Stages::Tess => matches!(stage, Stage::TessControl | Stage::TessEvaluation),
            }
            && (!self.compat_only || lang.allows(Feature::CompatibilityInterface))
            && (!self.core_only || !lang.allows(Feature::CompatibilityInterface))
            && (!self.ext_gs || lang.ext_geometry_shader4())
            && self.needs.is_none_or(|e| lang.has(e))
    }
}

const COMPAT: Where = Where::ALL.compat();
/// GL_EXT_geometry_shader4's geometry stage (before GLSL 1.50).
const EXT_GS: Where = Where::ALL.gs().ext_gs();
const VS: Where = Where::ALL.vs();
const FS: Where = Where::ALL.fs();
const V120: Version = Version::V120;
const V130: Version = Version::V130;
const V140: Version = Version::V140;
const V150: Version = Version::V150;
const V330: Version = Version::V330;

/// A built-in constant: `const int NAME = VALUE;`.
enum Item {
    Const(&'static str, u32),
    /// A constant that may be negative.
    IntConst(&'static str, i32),
    /// `const int gl_VerticesIn`, whose value is the vertex count of the
    /// program's input primitive (GL_EXT_geometry_shader4 §7.4).
    VerticesIn,
    /// Declarations written out.
    Text(&'static str),
    /// GL_ARB_compute_shader's `gl_MaxCompute*` constants, from
    /// [`limits`].
    ComputeConstants,
    /// GL_ARB_tessellation_shader's `gl_MaxTess*`, `gl_MaxPatchVertices`
    /// and `gl_MaxTessGenLevel` constants, from [`limits`].
    TessConstants,
}

/// Built-in constants (§7.4), uniform state (§7.5) and stage variables
/// (§7.1-7.3, §7.6), in the order the prelude declares them (a constant
/// before the arrays it sizes, a struct before its uniforms).
const VARIABLES: &[(Where, Item)] = {
    use Item::{Const, Text};
    &[
        (COMPAT, Const("gl_MaxLights", limits::MAX_LIGHTS)),
        // GL_ARB_compute_shader's constants (every stage) and the compute
        // stage's inputs; `gl_WorkGroupSize` is the size the shader
        // declares (`sema::compute`).
        (COMPUTE_EXT, Item::ComputeConstants),
        (TESS, Item::TessConstants),
        (
            COMPUTE_EXT.cs(),
            Text(
                "in uvec3 gl_NumWorkGroups;
in uvec3 gl_WorkGroupID;
in uvec3 gl_LocalInvocationID;
in uvec3 gl_GlobalInvocationID;
in uint gl_LocalInvocationIndex;",
            ),
        ),
        // GL_ARB_shading_language_420pack's (GLSL 4.20's) texel offsets.
        (
            Where::ALL.needs(Extension::ArbShadingLanguage420pack),
            Item::IntConst("gl_MinProgramTexelOffset", limits::MIN_PROGRAM_TEXEL_OFFSET),
        ),
        (
            Where::ALL.needs(Extension::ArbShadingLanguage420pack),
            Item::IntConst("gl_MaxProgramTexelOffset", limits::MAX_PROGRAM_TEXEL_OFFSET),
        ),
        (COMPAT, Const("gl_MaxClipPlanes", limits::MAX_CLIP_PLANES)),
        // GLSL 1.40 §7.4 still lists it, by mistake: it counts
        // fixed-function texture units, and 1.50 moves it to the
        // compatibility profile (piglit's glsl-1.40 tests expect it gone).
        (
            COMPAT,
            Const("gl_MaxTextureUnits", limits::MAX_TEXTURE_UNITS),
        ),
        (
            COMPAT,
            Const("gl_MaxTextureCoords", limits::MAX_TEXTURE_COORDS),
        ),
        (
            Where::ALL,
            Const("gl_MaxVertexAttribs", limits::MAX_VERTEX_ATTRIBS),
        ),
        (
            Where::ALL,
            Const(
                "gl_MaxVertexUniformComponents",
                limits::MAX_VERTEX_UNIFORM_COMPONENTS,
            ),
        ),
        (
            Where::ALL,
            Const("gl_MaxVaryingFloats", limits::MAX_VARYING_FLOATS),
        ),
        (
            Where::ALL,
            Const(
                "gl_MaxVertexTextureImageUnits",
                limits::MAX_VERTEX_TEXTURE_IMAGE_UNITS,
            ),
        ),
        (
            Where::ALL,
            Const(
                "gl_MaxCombinedTextureImageUnits",
                limits::MAX_COMBINED_TEXTURE_IMAGE_UNITS,
            ),
        ),
        (
            Where::ALL,
            Const("gl_MaxTextureImageUnits", limits::MAX_TEXTURE_IMAGE_UNITS),
        ),
        (
            Where::ALL,
            Const(
                "gl_MaxFragmentUniformComponents",
                limits::MAX_FRAGMENT_UNIFORM_COMPONENTS,
            ),
        ),
        (
            Where::ALL,
            Const("gl_MaxDrawBuffers", limits::MAX_DRAW_BUFFERS),
        ),
        (
            Where::since(V130),
            Const("gl_MaxVaryingComponents", limits::MAX_VARYING_FLOATS),
        ),
        (
            Where::since(V130),
            Const("gl_MaxClipDistances", limits::MAX_CLIP_DISTANCES),
        ),
        (
            Where::since(V150),
            Const(
                "gl_MaxVertexOutputComponents",
                limits::MAX_VERTEX_OUTPUT_COMPONENTS,
            ),
        ),
        (
            Where::since(V150),
            Const(
                "gl_MaxFragmentInputComponents",
                limits::MAX_FRAGMENT_INPUT_COMPONENTS,
            ),
        ),
        (
            Where::since(V150),
            Const(
                "gl_MaxGeometryInputComponents",
                limits::MAX_GEOMETRY_INPUT_COMPONENTS,
            ),
        ),
        (
            Where::since(V150),
            Const(
                "gl_MaxGeometryOutputComponents",
                limits::MAX_GEOMETRY_OUTPUT_COMPONENTS,
            ),
        ),
        (
            Where::since(V150),
            Const(
                "gl_MaxGeometryTextureImageUnits",
                limits::MAX_GEOMETRY_TEXTURE_IMAGE_UNITS,
            ),
        ),
        (
            Where::since(V150),
            Const(
                "gl_MaxGeometryOutputVertices",
                limits::MAX_GEOMETRY_OUTPUT_VERTICES,
            ),
        ),
        (
            Where::since(V150),
            Const(
                "gl_MaxGeometryTotalOutputComponents",
                limits::MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS,
            ),
        ),
        (
            Where::since(V150),
            Const(
                "gl_MaxGeometryUniformComponents",
                limits::MAX_GEOMETRY_UNIFORM_COMPONENTS,
            ),
        ),
        (
            Where::since(V150),
            Const(
                "gl_MaxGeometryVaryingComponents",
                limits::MAX_GEOMETRY_VARYING_COMPONENTS,
            ),
        ),
        (
            COMPAT,
            Text(
                "// section 7.5 built-in uniform state
uniform mat4 gl_ModelViewMatrix;
uniform mat4 gl_ProjectionMatrix;
uniform mat4 gl_ModelViewProjectionMatrix;
uniform mat4 gl_TextureMatrix[gl_MaxTextureCoords];
uniform mat3 gl_NormalMatrix;
uniform mat4 gl_ModelViewMatrixInverse;
uniform mat4 gl_ProjectionMatrixInverse;
uniform mat4 gl_ModelViewProjectionMatrixInverse;
uniform mat4 gl_TextureMatrixInverse[gl_MaxTextureCoords];
uniform mat4 gl_ModelViewMatrixTranspose;
uniform mat4 gl_ProjectionMatrixTranspose;
uniform mat4 gl_ModelViewProjectionMatrixTranspose;
uniform mat4 gl_TextureMatrixTranspose[gl_MaxTextureCoords];
uniform mat4 gl_ModelViewMatrixInverseTranspose;
uniform mat4 gl_ProjectionMatrixInverseTranspose;
uniform mat4 gl_ModelViewProjectionMatrixInverseTranspose;
uniform mat4 gl_TextureMatrixInverseTranspose[gl_MaxTextureCoords];
uniform float gl_NormalScale;",
            ),
        ),
        // The one uniform the core profile keeps (GLSL 1.40 §7.5).
        (
            Where::ALL,
            Text(
                "struct gl_DepthRangeParameters {
    float near;
    float far;
    float diff;
};
uniform gl_DepthRangeParameters gl_DepthRange;",
            ),
        ),
        (
            COMPAT,
            Text(
                "uniform vec4 gl_ClipPlane[gl_MaxClipPlanes];
struct gl_PointParameters {
    float size;
    float sizeMin;
    float sizeMax;
    float fadeThresholdSize;
    float distanceConstantAttenuation;
    float distanceLinearAttenuation;
    float distanceQuadraticAttenuation;
};
uniform gl_PointParameters gl_Point;
struct gl_MaterialParameters {
    vec4 emission;
    vec4 ambient;
    vec4 diffuse;
    vec4 specular;
    float shininess;
};
uniform gl_MaterialParameters gl_FrontMaterial;
uniform gl_MaterialParameters gl_BackMaterial;
struct gl_LightSourceParameters {
    vec4 ambient;
    vec4 diffuse;
    vec4 specular;
    vec4 position;
    vec4 halfVector;
    vec3 spotDirection;
    float spotExponent;
    float spotCutoff;
    float spotCosCutoff;
    float constantAttenuation;
    float linearAttenuation;
    float quadraticAttenuation;
};
uniform gl_LightSourceParameters gl_LightSource[gl_MaxLights];
struct gl_LightModelParameters {
    vec4 ambient;
};
uniform gl_LightModelParameters gl_LightModel;
struct gl_LightModelProducts {
    vec4 sceneColor;
};
uniform gl_LightModelProducts gl_FrontLightModelProduct;
uniform gl_LightModelProducts gl_BackLightModelProduct;
struct gl_LightProducts {
    vec4 ambient;
    vec4 diffuse;
    vec4 specular;
};
uniform gl_LightProducts gl_FrontLightProduct[gl_MaxLights];
uniform gl_LightProducts gl_BackLightProduct[gl_MaxLights];",
            ),
        ),
        // 1.10 §7.5 sizes it by the texture image units, 1.20 §7.5 (and
        // later) by the fixed-function texture units.
        (
            COMPAT.until(V120),
            Text("uniform vec4 gl_TextureEnvColor[gl_MaxTextureImageUnits];"),
        ),
        (
            Where::since(V120).compat(),
            Text("uniform vec4 gl_TextureEnvColor[gl_MaxTextureUnits];"),
        ),
        (
            COMPAT,
            Text(
                "uniform vec4 gl_EyePlaneS[gl_MaxTextureCoords];
uniform vec4 gl_EyePlaneT[gl_MaxTextureCoords];
uniform vec4 gl_EyePlaneR[gl_MaxTextureCoords];
uniform vec4 gl_EyePlaneQ[gl_MaxTextureCoords];
uniform vec4 gl_ObjectPlaneS[gl_MaxTextureCoords];
uniform vec4 gl_ObjectPlaneT[gl_MaxTextureCoords];
uniform vec4 gl_ObjectPlaneR[gl_MaxTextureCoords];
uniform vec4 gl_ObjectPlaneQ[gl_MaxTextureCoords];
struct gl_FogParameters {
    vec4 color;
    float density;
    float start;
    float end;
    float scale;
};
uniform gl_FogParameters gl_Fog;",
            ),
        ),
        // §7.1 vertex shader special variables.
        (
            VS,
            Text(
                "vec4 gl_Position;
float gl_PointSize;",
            ),
        ),
        (VS.compat(), Text("vec4 gl_ClipVertex;")),
        (
            Where::since(V130).vs(),
            Text(
                "float gl_ClipDistance[];
attribute int gl_VertexID;",
            ),
        ),
        (
            Where::since(V140).vs(),
            Text("attribute int gl_InstanceID;"),
        ),
        // §7.3 built-in vertex attributes, §7.6 varying outputs.
        (
            VS.compat(),
            Text(
                "attribute vec4 gl_Color;
attribute vec4 gl_SecondaryColor;
attribute vec3 gl_Normal;
attribute vec4 gl_Vertex;
attribute vec4 gl_MultiTexCoord0;
attribute vec4 gl_MultiTexCoord1;
attribute vec4 gl_MultiTexCoord2;
attribute vec4 gl_MultiTexCoord3;
attribute vec4 gl_MultiTexCoord4;
attribute vec4 gl_MultiTexCoord5;
attribute vec4 gl_MultiTexCoord6;
attribute vec4 gl_MultiTexCoord7;
attribute float gl_FogCoord;
varying vec4 gl_FrontColor;
varying vec4 gl_BackColor;
varying vec4 gl_FrontSecondaryColor;
varying vec4 gl_BackSecondaryColor;
varying vec4 gl_TexCoord[];
varying float gl_FogFragCoord;",
            ),
        ),
        // §7.2 fragment shader special variables. `gl_FragColor` and
        // `gl_FragData` are deprecated from 1.30 on, not removed: the core
        // profiles of 1.40 to 3.30 keep them.
        (
            FS,
            Text(
                "varying vec4 gl_FragCoord;
varying bool gl_FrontFacing;
vec4 gl_FragColor;
vec4 gl_FragData[gl_MaxDrawBuffers];
float gl_FragDepth;",
            ),
        ),
        // §7.6 varying inputs.
        (
            FS.compat(),
            Text(
                "varying vec4 gl_Color;
varying vec4 gl_SecondaryColor;
varying vec4 gl_TexCoord[];
varying float gl_FogFragCoord;",
            ),
        ),
        (Where::since(V120).fs(), Text("varying vec2 gl_PointCoord;")),
        (
            Where::since(V130).fs(),
            Text("varying float gl_ClipDistance[];"),
        ),
        (Where::since(V150).fs(), Text("varying int gl_PrimitiveID;")),
        // GLSL 1.50 §7.1 geometry shader special variables: the inputs,
        // one `gl_PerVertex' per vertex of the input primitive (sized by
        // `layout(...) in;'), and the outputs of the vertex being emitted.
        (
            Where::since(V150).gs().core(),
            Text(
                "in gl_PerVertex {
    vec4 gl_Position;
    float gl_PointSize;
    float gl_ClipDistance[];
} gl_in[];",
            ),
        ),
        // §7.1.1: the compatibility profile's `gl_in[]' adds the vertex
        // stage's fixed-function outputs.
        (
            Where::since(V150).gs().compat(),
            Text(
                "in gl_PerVertex {
    vec4 gl_Position;
    float gl_PointSize;
    float gl_ClipDistance[];
    vec4 gl_ClipVertex;
    vec4 gl_FrontColor;
    vec4 gl_BackColor;
    vec4 gl_FrontSecondaryColor;
    vec4 gl_BackSecondaryColor;
    vec4 gl_TexCoord[];
    float gl_FogFragCoord;
} gl_in[];",
            ),
        ),
        (
            Where::since(V150).gs(),
            Text(
                "in int gl_PrimitiveIDIn;
vec4 gl_Position;
float gl_PointSize;
float gl_ClipDistance[];
varying int gl_PrimitiveID;
varying int gl_Layer;",
            ),
        ),
        (
            Where::since(V150).gs().compat(),
            Text(
                "vec4 gl_ClipVertex;
varying vec4 gl_FrontColor;
varying vec4 gl_BackColor;
varying vec4 gl_FrontSecondaryColor;
varying vec4 gl_BackSecondaryColor;
varying vec4 gl_TexCoord[];
varying float gl_FogFragCoord;",
            ),
        ),
        // GL_ARB_tessellation_shader §7.1: the control stage reads the
        // whole input patch (`gl_in[]', sized gl_MaxPatchVertices) and
        // writes its output vertex in `gl_out[]' (sized by
        // `layout(vertices = N) out;') and the levels per patch; the
        // evaluation stage reads both patches and writes one vertex, as
        // the vertex stage does. The blocks need GLSL 1.50's input and
        // output blocks; a 1.40 shader has the rest.
        (
            TESS_BLOCKS.core(),
            Text(
                "in gl_PerVertex {
    vec4 gl_Position;
    float gl_PointSize;
    float gl_ClipDistance[];
} gl_in[gl_MaxPatchVertices];",
            ),
        ),
        (
            TESS_BLOCKS.compat(),
            Text(
                "in gl_PerVertex {
    vec4 gl_Position;
    float gl_PointSize;
    float gl_ClipDistance[];
    vec4 gl_ClipVertex;
    vec4 gl_FrontColor;
    vec4 gl_BackColor;
    vec4 gl_FrontSecondaryColor;
    vec4 gl_BackSecondaryColor;
    vec4 gl_TexCoord[];
    float gl_FogFragCoord;
} gl_in[gl_MaxPatchVertices];",
            ),
        ),
        (
            TESS,
            Text("in int gl_PatchVerticesIn;\nin int gl_PrimitiveID;"),
        ),
        (TESS.tcs(), Text("in int gl_InvocationID;")),
        (
            TESS_BLOCKS.tcs().core(),
            Text(
                "out gl_PerVertex {
    vec4 gl_Position;
    float gl_PointSize;
    float gl_ClipDistance[];
} gl_out[];",
            ),
        ),
        (
            TESS_BLOCKS.tcs().compat(),
            Text(
                "out gl_PerVertex {
    vec4 gl_Position;
    float gl_PointSize;
    float gl_ClipDistance[];
    vec4 gl_ClipVertex;
    vec4 gl_FrontColor;
    vec4 gl_BackColor;
    vec4 gl_FrontSecondaryColor;
    vec4 gl_BackSecondaryColor;
    vec4 gl_TexCoord[];
    float gl_FogFragCoord;
} gl_out[];",
            ),
        ),
        (
            TESS.tcs(),
            Text(
                "patch out float gl_TessLevelOuter[4];
patch out float gl_TessLevelInner[2];",
            ),
        ),
        (
            TESS.tes(),
            Text(
                "in vec3 gl_TessCoord;
patch in float gl_TessLevelOuter[4];
patch in float gl_TessLevelInner[2];
vec4 gl_Position;
float gl_PointSize;
float gl_ClipDistance[];",
            ),
        ),
        (
            TESS.tes().compat(),
            Text(
                "vec4 gl_ClipVertex;
varying vec4 gl_FrontColor;
varying vec4 gl_BackColor;
varying vec4 gl_FrontSecondaryColor;
varying vec4 gl_BackSecondaryColor;
varying vec4 gl_TexCoord[];
varying float gl_FogFragCoord;",
            ),
        ),
        // GL_EXT_geometry_shader4 §7.1, §7.4, §7.6: the geometry stage
        // before GLSL 1.50. The inputs are arrays with one element per
        // vertex of the input primitive: unsized here, sized by the
        // analyzer from the input primitive as user inputs are (the
        // extension writes `[gl_VerticesIn]', the same size). The
        // outputs are the vertex stage's.
        (EXT_GS, Item::VerticesIn),
        (
            EXT_GS,
            Text(
                "varying in vec4 gl_PositionIn[];
varying in float gl_PointSizeIn[];
varying in int gl_PrimitiveIDIn;
vec4 gl_Position;
float gl_PointSize;
varying int gl_PrimitiveID;
varying int gl_Layer;",
            ),
        ),
        (
            EXT_GS.compat(),
            Text(
                "varying in vec4 gl_ClipVertexIn[];
varying in vec4 gl_FrontColorIn[];
varying in vec4 gl_BackColorIn[];
varying in vec4 gl_FrontSecondaryColorIn[];
varying in vec4 gl_BackSecondaryColorIn[];
varying in float gl_FogFragCoordIn[];
varying in vec4 gl_TexCoordIn[][];
vec4 gl_ClipVertex;
varying vec4 gl_FrontColor;
varying vec4 gl_BackColor;
varying vec4 gl_FrontSecondaryColor;
varying vec4 gl_BackSecondaryColor;
varying vec4 gl_TexCoord[];
varying float gl_FogFragCoord;",
            ),
        ),
        (
            Where::since(V130).gs().ext_gs(),
            Text(
                "float gl_ClipDistance[];
varying in float gl_ClipDistanceIn[][];",
            ),
        ),
    ]
};

/// Built-in functions other than the lookups of [`SAMPLERS`], as
/// prototypes with the spec's placeholders, each expanded over its types
/// ([`expand`]): `genType` (`float`, `vec2`...`vec4`), `genIType`,
/// `genUType`, `genBType`; `vec`, `ivec`, `uvec`, `bvec` (sizes 2 to 4); `mat` (every matrix
/// type of the version) with `matT` its transpose and `colvec`/`rowvec`
/// the vectors of its column and row; `sqmat` (`mat2`...`mat4`). All
/// placeholders of one line vary together.
const FUNCTIONS: &[(Where, &str)] = &[
    // §8.1 angle and trigonometry functions
    (Where::ALL, "genType radians(genType)"),
    (Where::ALL, "genType degrees(genType)"),
    (Where::ALL, "genType sin(genType)"),
    (Where::ALL, "genType cos(genType)"),
    (Where::ALL, "genType tan(genType)"),
    (Where::ALL, "genType asin(genType)"),
    (Where::ALL, "genType acos(genType)"),
    (Where::ALL, "genType atan(genType, genType)"),
    (Where::ALL, "genType atan(genType)"),
    (Where::since(V130), "genType sinh(genType)"),
    (Where::since(V130), "genType cosh(genType)"),
    (Where::since(V130), "genType tanh(genType)"),
    (Where::since(V130), "genType asinh(genType)"),
    (Where::since(V130), "genType acosh(genType)"),
    (Where::since(V130), "genType atanh(genType)"),
    // §8.2 exponential functions
    (Where::ALL, "genType pow(genType, genType)"),
    (Where::ALL, "genType exp(genType)"),
    (Where::ALL, "genType log(genType)"),
    (Where::ALL, "genType exp2(genType)"),
    (Where::ALL, "genType log2(genType)"),
    (Where::ALL, "genType sqrt(genType)"),
    (Where::ALL, "genType inversesqrt(genType)"),
    // §8.3 common functions
    (Where::ALL, "genType abs(genType)"),
    (Where::ALL, "genType sign(genType)"),
    (Where::ALL, "genType floor(genType)"),
    (Where::ALL, "genType ceil(genType)"),
    (Where::ALL, "genType fract(genType)"),
    (Where::ALL, "genType mod(genType, genType)"),
    (Where::ALL, "vec mod(vec, float)"),
    (Where::ALL, "genType min(genType, genType)"),
    (Where::ALL, "vec min(vec, float)"),
    (Where::ALL, "genType max(genType, genType)"),
    (Where::ALL, "vec max(vec, float)"),
    (Where::ALL, "genType clamp(genType, genType, genType)"),
    (Where::ALL, "vec clamp(vec, float, float)"),
    (Where::ALL, "genType mix(genType, genType, genType)"),
    (Where::ALL, "vec mix(vec, vec, float)"),
    (Where::ALL, "genType step(genType, genType)"),
    (Where::ALL, "vec step(float, vec)"),
    (Where::ALL, "genType smoothstep(genType, genType, genType)"),
    (Where::ALL, "vec smoothstep(float, float, vec)"),
    (Where::since(V130), "genIType abs(genIType)"),
    (Where::since(V130), "genIType sign(genIType)"),
    (Where::since(V130), "genType trunc(genType)"),
    (Where::since(V130), "genType round(genType)"),
    (Where::since(V130), "genType roundEven(genType)"),
    (Where::since(V130), "genType modf(genType, out genType)"),
    (Where::since(V130), "genIType min(genIType, genIType)"),
    (Where::since(V130), "ivec min(ivec, int)"),
    (Where::since(V130), "genIType max(genIType, genIType)"),
    (Where::since(V130), "ivec max(ivec, int)"),
    (
        Where::since(V130),
        "genIType clamp(genIType, genIType, genIType)",
    ),
    (Where::since(V130), "ivec clamp(ivec, int, int)"),
    (Where::since(V130), "genUType min(genUType, genUType)"),
    (Where::since(V130), "uvec min(uvec, uint)"),
    (Where::since(V130), "genUType max(genUType, genUType)"),
    (Where::since(V130), "uvec max(uvec, uint)"),
    (
        Where::since(V130),
        "genUType clamp(genUType, genUType, genUType)",
    ),
    (Where::since(V130), "uvec clamp(uvec, uint, uint)"),
    (
        Where::since(V130),
        "genType mix(genType, genType, genBType)",
    ),
    (Where::since(V130), "genBType isnan(genType)"),
    (Where::since(V130), "genBType isinf(genType)"),
    (Where::since(V330), "genIType floatBitsToInt(genType)"),
    (Where::since(V330), "genType intBitsToFloat(genIType)"),
    (Where::since(V330), "genUType floatBitsToUint(genType)"),
    (Where::since(V330), "genType uintBitsToFloat(genUType)"),
    // GL_ARB_shading_language_packing, every stage.
    (PACKING, "uint packUnorm2x16(vec2)"),
    (PACKING, "uint packSnorm2x16(vec2)"),
    (PACKING, "uint packUnorm4x8(vec4)"),
    (PACKING, "uint packSnorm4x8(vec4)"),
    (PACKING, "vec2 unpackUnorm2x16(uint)"),
    (PACKING, "vec2 unpackSnorm2x16(uint)"),
    (PACKING, "vec4 unpackUnorm4x8(uint)"),
    (PACKING, "vec4 unpackSnorm4x8(uint)"),
    (PACKING, "uint packHalf2x16(vec2)"),
    (PACKING, "vec2 unpackHalf2x16(uint)"),
    // §8.4 geometric functions
    (Where::ALL, "float length(genType)"),
    (Where::ALL, "float distance(genType, genType)"),
    (Where::ALL, "float dot(genType, genType)"),
    (Where::ALL, "vec3 cross(vec3, vec3)"),
    (Where::ALL, "genType normalize(genType)"),
    (VS.compat(), "vec4 ftransform()"),
    (Where::ALL, "genType faceforward(genType, genType, genType)"),
    (Where::ALL, "genType reflect(genType, genType)"),
    (Where::ALL, "genType refract(genType, genType, float)"),
    // §8.5 matrix functions
    (Where::ALL, "mat matrixCompMult(mat, mat)"),
    (Where::since(V120), "mat outerProduct(colvec, rowvec)"),
    (Where::since(V120), "matT transpose(mat)"),
    (Where::since(V150), "float determinant(sqmat)"),
    (Where::since(V140), "sqmat inverse(sqmat)"),
    // §8.6 vector relational functions
    (Where::ALL, "bvec lessThan(vec, vec)"),
    (Where::ALL, "bvec lessThan(ivec, ivec)"),
    (Where::since(V130), "bvec lessThan(uvec, uvec)"),
    (Where::ALL, "bvec lessThanEqual(vec, vec)"),
    (Where::ALL, "bvec lessThanEqual(ivec, ivec)"),
    (Where::since(V130), "bvec lessThanEqual(uvec, uvec)"),
    (Where::ALL, "bvec greaterThan(vec, vec)"),
    (Where::ALL, "bvec greaterThan(ivec, ivec)"),
    (Where::since(V130), "bvec greaterThan(uvec, uvec)"),
    (Where::ALL, "bvec greaterThanEqual(vec, vec)"),
    (Where::ALL, "bvec greaterThanEqual(ivec, ivec)"),
    (Where::since(V130), "bvec greaterThanEqual(uvec, uvec)"),
    (Where::ALL, "bvec equal(vec, vec)"),
    (Where::ALL, "bvec equal(ivec, ivec)"),
    (Where::since(V130), "bvec equal(uvec, uvec)"),
    (Where::ALL, "bvec equal(bvec, bvec)"),
    (Where::ALL, "bvec notEqual(vec, vec)"),
    (Where::ALL, "bvec notEqual(ivec, ivec)"),
    (Where::since(V130), "bvec notEqual(uvec, uvec)"),
    (Where::ALL, "bvec notEqual(bvec, bvec)"),
    (Where::ALL, "bool any(bvec)"),
    (Where::ALL, "bool all(bvec)"),
    (Where::ALL, "bvec not(bvec)"),
    // §8.7 texture lookup functions of 1.10 and 1.20, deprecated (not
    // removed) from 1.30 on. The bias forms are the fragment stage's; the
    // `Lod` forms are the vertex stage's until 1.30 names them for every
    // stage.
    (Where::ALL, "vec4 texture1D(sampler1D, float)"),
    (FS, "vec4 texture1D(sampler1D, float, float)"),
    (Where::ALL, "vec4 texture1DProj(sampler1D, vec2)"),
    (FS, "vec4 texture1DProj(sampler1D, vec2, float)"),
    (Where::ALL, "vec4 texture1DProj(sampler1D, vec4)"),
    (FS, "vec4 texture1DProj(sampler1D, vec4, float)"),
    (Where::ALL, "vec4 texture2D(sampler2D, vec2)"),
    (FS, "vec4 texture2D(sampler2D, vec2, float)"),
    (Where::ALL, "vec4 texture2DProj(sampler2D, vec3)"),
    (FS, "vec4 texture2DProj(sampler2D, vec3, float)"),
    (Where::ALL, "vec4 texture2DProj(sampler2D, vec4)"),
    (FS, "vec4 texture2DProj(sampler2D, vec4, float)"),
    (Where::ALL, "vec4 texture3D(sampler3D, vec3)"),
    (FS, "vec4 texture3D(sampler3D, vec3, float)"),
    (Where::ALL, "vec4 texture3DProj(sampler3D, vec4)"),
    (FS, "vec4 texture3DProj(sampler3D, vec4, float)"),
    (Where::ALL, "vec4 textureCube(samplerCube, vec3)"),
    (FS, "vec4 textureCube(samplerCube, vec3, float)"),
    (Where::ALL, "vec4 shadow1D(sampler1DShadow, vec3)"),
    (FS, "vec4 shadow1D(sampler1DShadow, vec3, float)"),
    (Where::ALL, "vec4 shadow2D(sampler2DShadow, vec3)"),
    (FS, "vec4 shadow2D(sampler2DShadow, vec3, float)"),
    (Where::ALL, "vec4 shadow1DProj(sampler1DShadow, vec4)"),
    (FS, "vec4 shadow1DProj(sampler1DShadow, vec4, float)"),
    (Where::ALL, "vec4 shadow2DProj(sampler2DShadow, vec4)"),
    (FS, "vec4 shadow2DProj(sampler2DShadow, vec4, float)"),
    (LOD, "vec4 texture1DLod(sampler1D, float, float)"),
    (LOD, "vec4 texture1DProjLod(sampler1D, vec2, float)"),
    (LOD, "vec4 texture1DProjLod(sampler1D, vec4, float)"),
    (LOD, "vec4 texture2DLod(sampler2D, vec2, float)"),
    (LOD, "vec4 texture2DProjLod(sampler2D, vec3, float)"),
    (LOD, "vec4 texture2DProjLod(sampler2D, vec4, float)"),
    (LOD, "vec4 texture3DLod(sampler3D, vec3, float)"),
    (LOD, "vec4 texture3DProjLod(sampler3D, vec4, float)"),
    (LOD, "vec4 textureCubeLod(samplerCube, vec3, float)"),
    (LOD, "vec4 shadow1DLod(sampler1DShadow, vec3, float)"),
    (LOD, "vec4 shadow2DLod(sampler2DShadow, vec3, float)"),
    (LOD, "vec4 shadow1DProjLod(sampler1DShadow, vec4, float)"),
    (LOD, "vec4 shadow2DProjLod(sampler2DShadow, vec4, float)"),
    (LOD_130, "vec4 texture1DLod(sampler1D, float, float)"),
    (LOD_130, "vec4 texture1DProjLod(sampler1D, vec2, float)"),
    (LOD_130, "vec4 texture1DProjLod(sampler1D, vec4, float)"),
    (LOD_130, "vec4 texture2DLod(sampler2D, vec2, float)"),
    (LOD_130, "vec4 texture2DProjLod(sampler2D, vec3, float)"),
    (LOD_130, "vec4 texture2DProjLod(sampler2D, vec4, float)"),
    (LOD_130, "vec4 texture3DLod(sampler3D, vec3, float)"),
    (LOD_130, "vec4 texture3DProjLod(sampler3D, vec4, float)"),
    (LOD_130, "vec4 textureCubeLod(samplerCube, vec3, float)"),
    (LOD_130, "vec4 shadow1DLod(sampler1DShadow, vec3, float)"),
    (LOD_130, "vec4 shadow2DLod(sampler2DShadow, vec3, float)"),
    (
        LOD_130,
        "vec4 shadow1DProjLod(sampler1DShadow, vec4, float)",
    ),
    (
        LOD_130,
        "vec4 shadow2DProjLod(sampler2DShadow, vec4, float)",
    ),
    // GL_ARB_texture_rectangle's lookups, on the sampler types GLSL 1.40
    // makes part of the language.
    (
        Where::since(V140),
        "vec4 texture2DRect(sampler2DRect, vec2)",
    ),
    (
        Where::since(V140),
        "vec4 texture2DRectProj(sampler2DRect, vec3)",
    ),
    (
        Where::since(V140),
        "vec4 texture2DRectProj(sampler2DRect, vec4)",
    ),
    (
        Where::since(V140),
        "vec4 shadow2DRect(sampler2DRectShadow, vec3)",
    ),
    (
        Where::since(V140),
        "vec4 shadow2DRectProj(sampler2DRectShadow, vec4)",
    ),
    // GL_EXT_texture_array's lookups (from GLSL 1.30, which has the
    // sampler types and the explicit-LOD lookups in every stage).
    (TEX_ARRAY, "vec4 texture1DArray(sampler1DArray, vec2)"),
    (
        TEX_ARRAY_FS,
        "vec4 texture1DArray(sampler1DArray, vec2, float)",
    ),
    (
        TEX_ARRAY,
        "vec4 texture1DArrayLod(sampler1DArray, vec2, float)",
    ),
    (TEX_ARRAY, "vec4 texture2DArray(sampler2DArray, vec3)"),
    (
        TEX_ARRAY_FS,
        "vec4 texture2DArray(sampler2DArray, vec3, float)",
    ),
    (
        TEX_ARRAY,
        "vec4 texture2DArrayLod(sampler2DArray, vec3, float)",
    ),
    (TEX_ARRAY, "vec4 shadow1DArray(sampler1DArrayShadow, vec3)"),
    (
        TEX_ARRAY_FS,
        "vec4 shadow1DArray(sampler1DArrayShadow, vec3, float)",
    ),
    (
        TEX_ARRAY,
        "vec4 shadow1DArrayLod(sampler1DArrayShadow, vec3, float)",
    ),
    (TEX_ARRAY, "vec4 shadow2DArray(sampler2DArrayShadow, vec4)"),
    // GL_ARB_shader_texture_lod: the explicit-LOD lookups in fragment
    // shaders before 1.30 (the other stages have them), and the lookups
    // with explicit derivatives in every stage (those of rectangles where
    // the language has their samplers).
    (LOD_FS_ARB, "vec4 texture1DLod(sampler1D, float, float)"),
    (LOD_FS_ARB, "vec4 texture1DProjLod(sampler1D, vec2, float)"),
    (LOD_FS_ARB, "vec4 texture1DProjLod(sampler1D, vec4, float)"),
    (LOD_FS_ARB, "vec4 texture2DLod(sampler2D, vec2, float)"),
    (LOD_FS_ARB, "vec4 texture2DProjLod(sampler2D, vec3, float)"),
    (LOD_FS_ARB, "vec4 texture2DProjLod(sampler2D, vec4, float)"),
    (LOD_FS_ARB, "vec4 texture3DLod(sampler3D, vec3, float)"),
    (LOD_FS_ARB, "vec4 texture3DProjLod(sampler3D, vec4, float)"),
    (LOD_FS_ARB, "vec4 textureCubeLod(samplerCube, vec3, float)"),
    (LOD_FS_ARB, "vec4 shadow1DLod(sampler1DShadow, vec3, float)"),
    (LOD_FS_ARB, "vec4 shadow2DLod(sampler2DShadow, vec3, float)"),
    (
        LOD_FS_ARB,
        "vec4 shadow1DProjLod(sampler1DShadow, vec4, float)",
    ),
    (
        LOD_FS_ARB,
        "vec4 shadow2DProjLod(sampler2DShadow, vec4, float)",
    ),
    (
        GRAD_ARB,
        "vec4 texture1DGradARB(sampler1D, float, float, float)",
    ),
    (
        GRAD_ARB,
        "vec4 texture1DProjGradARB(sampler1D, vec2, float, float)",
    ),
    (
        GRAD_ARB,
        "vec4 texture1DProjGradARB(sampler1D, vec4, float, float)",
    ),
    (
        GRAD_ARB,
        "vec4 texture2DGradARB(sampler2D, vec2, vec2, vec2)",
    ),
    (
        GRAD_ARB,
        "vec4 texture2DProjGradARB(sampler2D, vec3, vec2, vec2)",
    ),
    (
        GRAD_ARB,
        "vec4 texture2DProjGradARB(sampler2D, vec4, vec2, vec2)",
    ),
    (
        GRAD_ARB,
        "vec4 texture3DGradARB(sampler3D, vec3, vec3, vec3)",
    ),
    (
        GRAD_ARB,
        "vec4 texture3DProjGradARB(sampler3D, vec4, vec3, vec3)",
    ),
    (
        GRAD_ARB,
        "vec4 textureCubeGradARB(samplerCube, vec3, vec3, vec3)",
    ),
    (
        GRAD_ARB,
        "vec4 shadow1DGradARB(sampler1DShadow, vec3, float, float)",
    ),
    (
        GRAD_ARB,
        "vec4 shadow1DProjGradARB(sampler1DShadow, vec4, float, float)",
    ),
    (
        GRAD_ARB,
        "vec4 shadow2DGradARB(sampler2DShadow, vec3, vec2, vec2)",
    ),
    (
        GRAD_ARB,
        "vec4 shadow2DProjGradARB(sampler2DShadow, vec4, vec2, vec2)",
    ),
    (
        GRAD_ARB_RECT,
        "vec4 texture2DRectGradARB(sampler2DRect, vec2, vec2, vec2)",
    ),
    (
        GRAD_ARB_RECT,
        "vec4 texture2DRectProjGradARB(sampler2DRect, vec3, vec2, vec2)",
    ),
    (
        GRAD_ARB_RECT,
        "vec4 texture2DRectProjGradARB(sampler2DRect, vec4, vec2, vec2)",
    ),
    (
        GRAD_ARB_RECT,
        "vec4 shadow2DRectGradARB(sampler2DRectShadow, vec3, vec2, vec2)",
    ),
    (
        GRAD_ARB_RECT,
        "vec4 shadow2DRectProjGradARB(sampler2DRectShadow, vec4, vec2, vec2)",
    ),
    // §8.8 fragment processing functions
    (FS, "genType dFdx(genType)"),
    (FS, "genType dFdy(genType)"),
    (FS, "genType fwidth(genType)"),
    // §8.9 noise functions
    (Where::ALL, "float noise1(genType)"),
    (Where::ALL, "vec2 noise2(genType)"),
    (Where::ALL, "vec3 noise3(genType)"),
    (Where::ALL, "vec4 noise4(genType)"),
    // §8.10 geometry shader functions
    (Where::since(V150).gs(), "void EmitVertex()"),
    (Where::since(V150).gs(), "void EndPrimitive()"),
    (EXT_GS, "void EmitVertex()"),
    (EXT_GS, "void EndPrimitive()"),
    // GL_ARB_compute_shader: barriers (GLSL 4.30 §8.15-8.16) and the
    // atomic functions on shared variables (§8.11).
    (COMPUTE_EXT.cs(), "void barrier()"),
    // GL_ARB_tessellation_shader §8.X: the control stage's invocations
    // of one patch synchronize.
    (TESS.tcs(), "void barrier()"),
    (COMPUTE_EXT.cs(), "void memoryBarrier()"),
    (COMPUTE_EXT.cs(), "void memoryBarrierAtomicCounter()"),
    (COMPUTE_EXT.cs(), "void memoryBarrierBuffer()"),
    (COMPUTE_EXT.cs(), "void memoryBarrierImage()"),
    (COMPUTE_EXT.cs(), "void memoryBarrierShared()"),
    (COMPUTE_EXT.cs(), "void groupMemoryBarrier()"),
    (ATOMIC_UINT, "uint atomicAdd(inout uint, uint)"),
    (ATOMIC_INT, "int atomicAdd(inout int, int)"),
    (ATOMIC_UINT, "uint atomicMin(inout uint, uint)"),
    (ATOMIC_INT, "int atomicMin(inout int, int)"),
    (ATOMIC_UINT, "uint atomicMax(inout uint, uint)"),
    (ATOMIC_INT, "int atomicMax(inout int, int)"),
    (ATOMIC_UINT, "uint atomicAnd(inout uint, uint)"),
    (ATOMIC_INT, "int atomicAnd(inout int, int)"),
    (ATOMIC_UINT, "uint atomicOr(inout uint, uint)"),
    (ATOMIC_INT, "int atomicOr(inout int, int)"),
    (ATOMIC_UINT, "uint atomicXor(inout uint, uint)"),
    (ATOMIC_INT, "int atomicXor(inout int, int)"),
    (ATOMIC_UINT, "uint atomicExchange(inout uint, uint)"),
    (ATOMIC_INT, "int atomicExchange(inout int, int)"),
    (
        COMPUTE_EXT.cs(),
        "uint atomicCompSwap(inout uint, uint, uint)",
    ),
    (ATOMIC_INT, "int atomicCompSwap(inout int, int, int)"),
];

/// GL_ARB_tessellation_shader's built-ins: from GLSL 1.40 (as the stages,
/// [`Feature::TessellationShader`]), with the extension enabled; its
/// `gl_in[]`/`gl_out[]` blocks from 1.50, which has input and output
/// blocks.
const TESS: Where = Where::since(V140)
    .needs(Extension::ArbTessellationShader)
    .tess();
const TESS_BLOCKS: Where = Where::since(V150)
    .needs(Extension::ArbTessellationShader)
    .tess();

/// GL_ARB_compute_shader's built-ins: GLSL 1.30 on (they are `uvec3`s and
/// `ivec3`s), with the extension enabled.
const COMPUTE_EXT: Where = Where::since(V130).needs(Extension::ArbComputeShader);
/// The atomic functions: compute shaders' (on shared variables), and every
/// stage's with GL_ARB_shader_storage_buffer_object (on buffer
/// variables); the `uint` forms from GLSL 1.30.
const ATOMIC_INT: Where = COMPUTE_EXT
    .cs()
    .or_with(Version::V110, Extension::ArbShaderStorageBufferObject);
const ATOMIC_UINT: Where = COMPUTE_EXT
    .cs()
    .or_with(V130, Extension::ArbShaderStorageBufferObject);

/// GL_ARB_shader_texture_lod's lookups (see [`FUNCTIONS`]).
const LOD_FS_ARB: Where = Where {
    stages: Stages::Fragment,
    ..Where::ALL
}
.until(V130)
.needs(Extension::ArbShaderTextureLod);
const GRAD_ARB: Where = Where::ALL.needs(Extension::ArbShaderTextureLod);
const GRAD_ARB_RECT: Where = Where::since(V140).needs(Extension::ArbShaderTextureLod);

/// GL_ARB_shading_language_packing's functions: from GLSL 1.30, the first
/// version with `uint`.
const PACKING: Where = Where::since(V130).needs(Extension::ArbShadingLanguagePacking);

/// GL_EXT_texture_array's lookups; the bias forms in fragment shaders.
const TEX_ARRAY: Where = Where::since(V130).needs(Extension::ExtTextureArray);
const TEX_ARRAY_FS: Where = Where {
    stages: Stages::Fragment,
    ..TEX_ARRAY
};

/// The explicit-LOD lookups of 1.10 and 1.20: vertex shaders only (and
/// geometry shaders, GL_EXT_geometry_shader4).
const LOD: Where = Where {
    stages: Stages::VertexGeometry,
    ..Where::ALL
}
.until(V130);
/// The same from 1.30 on, in every stage (GLSL 1.30 §8.7 lists them
/// without a stage restriction).
const LOD_130: Where = Where::since(V130);

/// The lookups of GLSL 1.30 §8.7 (and 1.40, 1.50) on one sampler type.
/// `g` rows stand for the float, int and unsigned samplers alike (`gsampler2D`, result `gvec4`); shadow rows return one
/// `float`. A `None` column: no such lookup on that sampler.
struct SamplerRow {
    /// The sampler's name without the `g`/`i`/`u` prefix.
    name: &'static str,
    since: Version,
    /// `gsampler` (float and integer forms) or one shadow sampler.
    g: bool,
    /// `textureSize`'s result, and whether it takes a `lod`.
    size: (&'static str, bool),
    /// `P` of `texture`, `textureLod`, `textureGrad`...
    p: Option<&'static str>,
    /// `P` of the projective forms.
    proj: &'static [&'static str],
    /// Whether `texture`/`textureProj`/`textureOffset` take a `bias` (in
    /// the fragment stage).
    bias: bool,
    /// Whether `textureLod` (and its offset and projective forms) exist.
    lod: bool,
    /// The `offset` type of the `Offset` forms.
    offset: Option<&'static str>,
    /// Whether `textureOffset` is missing though other `Offset` forms
    /// exist (`sampler2DArrayShadow` has `textureGradOffset` only).
    grad_offset_only: bool,
    /// The type of `dPdx`/`dPdy` of the `Grad` forms.
    grad: Option<&'static str>,
    /// `P` of `texelFetch`, and its last parameter (`lod`, `sample`, or
    /// none for rectangles and buffers).
    fetch: Option<(&'static str, Option<&'static str>)>,
    /// The shadow sampler's `texture` takes the reference as a separate
    /// `float` after `P` (in every stage), instead of a bias
    /// (`samplerCubeArrayShadow`, whose `P` has no room for it).
    compare_arg: bool,
    /// The extension the sampler type needs.
    needs: Option<Extension>,
}

/// Every sampler type of GLSL 1.30-3.30 with the lookups §8.7 gives it.
const SAMPLERS: &[SamplerRow] = {
    const fn row(
        name: &'static str,
        since: Version,
        g: bool,
        size: (&'static str, bool),
    ) -> SamplerRow {
        SamplerRow {
            name,
            since,
            g,
            size,
            p: None,
            proj: &[],
            bias: false,
            lod: false,
            offset: None,
            grad_offset_only: false,
            grad: None,
            fetch: None,
            compare_arg: false,
            needs: None,
        }
    }
    &[
        SamplerRow {
            p: Some("float"),
            proj: &["vec2", "vec4"],
            bias: true,
            lod: true,
            offset: Some("int"),
            grad: Some("float"),
            fetch: Some(("int", Some("int"))),
            ..row("sampler1D", V130, true, ("int", true))
        },
        SamplerRow {
            p: Some("vec2"),
            proj: &["vec3", "vec4"],
            bias: true,
            lod: true,
            offset: Some("ivec2"),
            grad: Some("vec2"),
            fetch: Some(("ivec2", Some("int"))),
            ..row("sampler2D", V130, true, ("ivec2", true))
        },
        SamplerRow {
            p: Some("vec3"),
            proj: &["vec4"],
            bias: true,
            lod: true,
            offset: Some("ivec3"),
            grad: Some("vec3"),
            fetch: Some(("ivec3", Some("int"))),
            ..row("sampler3D", V130, true, ("ivec3", true))
        },
        SamplerRow {
            p: Some("vec3"),
            bias: true,
            lod: true,
            grad: Some("vec3"),
            ..row("samplerCube", V130, true, ("ivec2", true))
        },
        SamplerRow {
            p: Some("vec3"),
            proj: &["vec4"],
            bias: true,
            lod: true,
            offset: Some("int"),
            grad: Some("float"),
            ..row("sampler1DShadow", V130, false, ("int", true))
        },
        SamplerRow {
            p: Some("vec3"),
            proj: &["vec4"],
            bias: true,
            lod: true,
            offset: Some("ivec2"),
            grad: Some("vec2"),
            ..row("sampler2DShadow", V130, false, ("ivec2", true))
        },
        SamplerRow {
            p: Some("vec4"),
            bias: true,
            grad: Some("vec3"),
            ..row("samplerCubeShadow", V130, false, ("ivec2", true))
        },
        SamplerRow {
            p: Some("vec2"),
            bias: true,
            lod: true,
            offset: Some("int"),
            grad: Some("float"),
            fetch: Some(("ivec2", Some("int"))),
            ..row("sampler1DArray", V130, true, ("ivec2", true))
        },
        SamplerRow {
            p: Some("vec3"),
            bias: true,
            lod: true,
            offset: Some("ivec2"),
            grad: Some("vec2"),
            fetch: Some(("ivec3", Some("int"))),
            ..row("sampler2DArray", V130, true, ("ivec3", true))
        },
        SamplerRow {
            p: Some("vec3"),
            bias: true,
            lod: true,
            offset: Some("int"),
            grad: Some("float"),
            ..row("sampler1DArrayShadow", V130, false, ("ivec2", true))
        },
        SamplerRow {
            p: Some("vec4"),
            grad: Some("vec2"),
            offset: Some("ivec2"),
            grad_offset_only: true,
            ..row("sampler2DArrayShadow", V130, false, ("ivec3", true))
        },
        SamplerRow {
            p: Some("vec2"),
            proj: &["vec3", "vec4"],
            offset: Some("ivec2"),
            grad: Some("vec2"),
            fetch: Some(("ivec2", None)),
            ..row("sampler2DRect", V140, true, ("ivec2", false))
        },
        SamplerRow {
            p: Some("vec3"),
            proj: &["vec4"],
            offset: Some("ivec2"),
            grad: Some("vec2"),
            ..row("sampler2DRectShadow", V140, false, ("ivec2", false))
        },
        SamplerRow {
            fetch: Some(("int", None)),
            ..row("samplerBuffer", V140, true, ("int", false))
        },
        SamplerRow {
            fetch: Some(("ivec2", Some("int"))),
            ..row("sampler2DMS", V150, true, ("ivec2", false))
        },
        SamplerRow {
            fetch: Some(("ivec3", Some("int"))),
            ..row("sampler2DMSArray", V150, true, ("ivec3", false))
        },
        // GL_ARB_texture_cube_map_array: the cube lookups with the layer
        // as `P.w`; no offsets, projections or fetches.
        SamplerRow {
            p: Some("vec4"),
            bias: true,
            lod: true,
            grad: Some("vec3"),
            needs: Some(Extension::ArbTextureCubeMapArray),
            ..row("samplerCubeArray", V130, true, ("ivec3", true))
        },
        SamplerRow {
            compare_arg: true,
            needs: Some(Extension::ArbTextureCubeMapArray),
            ..row("samplerCubeArrayShadow", V130, false, ("ivec3", true))
        },
    ]
};

/// The prefixes a `g` row of [`SAMPLERS`] is declared with: float,
/// signed-integer and unsigned-integer samplers (results `vec4`, `ivec4`,
/// `uvec4`).
const G_PREFIXES: &[&str] = &["", "i", "u"];

fn build(lang: Language, stage: Stage, input: InputPrimitive) -> String {
    let version = lang.version;
    let mut out = String::with_capacity(48 * 1024);
    // The preprocessor classifies keywords by the `#version` it sees, so the
    // prelude states its own (`mat2x3` is a type only in 1.20).
    if version.has_profiles() {
        let _ = writeln!(out, "#version {} {}", version.number(), lang.profile.name());
    } else {
        let _ = writeln!(out, "#version {}", version.number());
    }
    // Keywords some extensions bring (the cube-map array samplers,
    // `patch`).
    for e in [
        Extension::ArbTextureCubeMapArray,
        Extension::ArbTessellationShader,
    ] {
        if lang.has(e) {
            let _ = writeln!(out, "#extension {} : enable", e.name());
        }
    }
    let _ = writeln!(
        out,
        "// Built-in declarations of GLSL {} ({} shader).",
        version.dotted(),
        stage.name()
    );
    out.push_str("// section 7 built-in variables and constants\n");
    for (at, item) in VARIABLES {
        if !at.holds(lang, stage) {
            continue;
        }
        match item {
            Item::Const(name, value) => {
                let _ = writeln!(out, "const int {name} = {value};");
            }
            Item::IntConst(name, value) => {
                let _ = writeln!(out, "const int {name} = {value};");
            }
            Item::VerticesIn => {
                let _ = writeln!(out, "const int gl_VerticesIn = {};", input.vertices());
            }
            Item::Text(text) => {
                out.push_str(text);
                out.push('\n');
            }
            Item::TessConstants => {
                for (name, value) in [
                    (
                        "gl_MaxTessControlInputComponents",
                        limits::MAX_TESS_CONTROL_INPUT_COMPONENTS,
                    ),
                    (
                        "gl_MaxTessControlOutputComponents",
                        limits::MAX_TESS_CONTROL_OUTPUT_COMPONENTS,
                    ),
                    (
                        "gl_MaxTessControlTextureImageUnits",
                        limits::MAX_TESS_CONTROL_TEXTURE_IMAGE_UNITS,
                    ),
                    (
                        "gl_MaxTessControlUniformComponents",
                        limits::MAX_TESS_CONTROL_UNIFORM_COMPONENTS,
                    ),
                    (
                        "gl_MaxTessControlTotalOutputComponents",
                        limits::MAX_TESS_CONTROL_TOTAL_OUTPUT_COMPONENTS,
                    ),
                    (
                        "gl_MaxTessEvaluationInputComponents",
                        limits::MAX_TESS_EVALUATION_INPUT_COMPONENTS,
                    ),
                    (
                        "gl_MaxTessEvaluationOutputComponents",
                        limits::MAX_TESS_EVALUATION_OUTPUT_COMPONENTS,
                    ),
                    (
                        "gl_MaxTessEvaluationTextureImageUnits",
                        limits::MAX_TESS_EVALUATION_TEXTURE_IMAGE_UNITS,
                    ),
                    (
                        "gl_MaxTessEvaluationUniformComponents",
                        limits::MAX_TESS_EVALUATION_UNIFORM_COMPONENTS,
                    ),
                    (
                        "gl_MaxTessPatchComponents",
                        limits::MAX_TESS_PATCH_COMPONENTS,
                    ),
                    ("gl_MaxPatchVertices", limits::MAX_PATCH_VERTICES),
                    ("gl_MaxTessGenLevel", limits::MAX_TESS_GEN_LEVEL),
                ] {
                    let _ = writeln!(out, "const int {name} = {value};");
                }
            }
            Item::ComputeConstants => {
                let [cx, cy, cz] = limits::MAX_COMPUTE_WORK_GROUP_COUNT;
                let [sx, sy, sz] = limits::MAX_COMPUTE_WORK_GROUP_SIZE;
                let _ = writeln!(
                    out,
                    "const ivec3 gl_MaxComputeWorkGroupCount = ivec3({cx}, {cy}, {cz});
const ivec3 gl_MaxComputeWorkGroupSize = ivec3({sx}, {sy}, {sz});
const int gl_MaxComputeUniformComponents = {};
const int gl_MaxComputeTextureImageUnits = {};
const int gl_MaxComputeImageUniforms = 0;
const int gl_MaxComputeAtomicCounters = 0;
const int gl_MaxComputeAtomicCounterBuffers = 0;",
                    limits::MAX_COMPUTE_UNIFORM_COMPONENTS,
                    limits::MAX_COMPUTE_TEXTURE_IMAGE_UNITS
                );
            }
        }
    }
    out.push_str("// section 8 built-in functions\n");
    for (at, proto) in FUNCTIONS {
        if at.holds(lang, stage) {
            expand(&mut out, proto, version);
        }
    }
    for row in SAMPLERS {
        if version >= row.since && row.needs.is_none_or(|e| lang.has(e)) {
            lookups(&mut out, row, stage);
        }
    }
    out
}

/// Replaces each identifier of `text` for which `f` gives a replacement.
fn substitute(text: &str, f: impl Fn(&str) -> Option<String>) -> String {
    let mut out = String::with_capacity(text.len() + 16);
    let mut word = String::new();
    let flush = |word: &mut String, out: &mut String| {
        match f(word) {
            Some(r) => out.push_str(&r),
            None => out.push_str(word),
        }
        word.clear();
    };
    for c in text.chars() {
        if c.is_ascii_alphanumeric() || c == '_' {
            word.push(c);
        } else {
            flush(&mut word, &mut out);
            out.push(c);
        }
    }
    flush(&mut word, &mut out);
    out
}

fn mat_name(cols: u8, rows: u8) -> String {
    if cols == rows {
        format!("mat{cols}")
    } else {
        format!("mat{cols}x{rows}")
    }
}

/// Writes the prototypes a [`FUNCTIONS`] line stands for, each `;`-ended.
fn expand(out: &mut String, proto: &str, version: Version) {
    let has = |w: &str| {
        proto
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .any(|x| x == w)
    };
    let mut lines = Vec::new();
    if ["genType", "genIType", "genUType", "genBType"]
        .iter()
        .any(|w| has(w))
    {
        for n in 1..=4u8 {
            let v = |p: &str, s: &str| {
                if n == 1 {
                    s.to_string()
                } else {
                    format!("{p}vec{n}")
                }
            };
            lines.push(substitute(proto, |w| match w {
                "genType" => Some(v("", "float")),
                "genIType" => Some(v("i", "int")),
                "genUType" => Some(v("u", "uint")),
                "genBType" => Some(v("b", "bool")),
                _ => None,
            }));
        }
    } else if ["vec", "ivec", "uvec", "bvec"].iter().any(|w| has(w)) {
        for n in 2..=4u8 {
            lines.push(substitute(proto, |w| match w {
                "vec" | "ivec" | "uvec" | "bvec" => Some(format!("{w}{n}")),
                _ => None,
            }));
        }
    } else if has("mat") {
        // Square matrices always, non-square ones from 1.20.
        for cols in 2u8..=4 {
            for rows in 2u8..=4 {
                if cols != rows && version < Version::V120 {
                    continue;
                }
                lines.push(substitute(proto, |w| match w {
                    "mat" => Some(mat_name(cols, rows)),
                    "matT" => Some(mat_name(rows, cols)),
                    // Column vector c (rows components) times row vector r.
                    "colvec" => Some(format!("vec{rows}")),
                    "rowvec" => Some(format!("vec{cols}")),
                    _ => None,
                }));
            }
        }
    } else if has("sqmat") {
        for n in 2..=4u8 {
            lines.push(substitute(proto, |w| {
                (w == "sqmat").then(|| format!("mat{n}"))
            }));
        }
    } else {
        lines.push(proto.to_string());
    }
    for line in lines {
        out.push_str(&line);
        out.push_str(";\n");
    }
}

/// The §8.7 lookups (1.30 and later) on the samplers of one row.
fn lookups(out: &mut String, row: &SamplerRow, stage: Stage) {
    let prefixes: &[&str] = if row.g { G_PREFIXES } else { &[""] };
    let fragment = stage == Stage::Fragment;
    for prefix in prefixes {
        let s = format!("{prefix}{}", row.name);
        let r = if row.g {
            format!("{prefix}vec4")
        } else {
            "float".to_string()
        };
        let mut f = |name: &str, params: &[&str]| {
            let _ = writeln!(
                out,
                "{r} {name}({s}{}{});",
                if params.is_empty() { "" } else { ", " },
                params.join(", ")
            );
        };
        // `bias` forms exist in the fragment stage only (§8.7).
        let biased = |f: &mut dyn FnMut(&str, &[&str]), name: &str, params: &[&str]| {
            f(name, params);
            if row.bias && fragment {
                let mut with = params.to_vec();
                with.push("float");
                f(name, &with);
            }
        };
        if let Some(p) = row.p {
            biased(&mut f, "texture", &[p]);
            for &q in row.proj {
                biased(&mut f, "textureProj", &[q]);
            }
            if row.lod {
                f("textureLod", &[p, "float"]);
                for &q in row.proj {
                    f("textureProjLod", &[q, "float"]);
                }
            }
            if let Some(o) = row.offset.filter(|_| !row.grad_offset_only) {
                biased(&mut f, "textureOffset", &[p, o]);
                for &q in row.proj {
                    biased(&mut f, "textureProjOffset", &[q, o]);
                }
                if row.lod {
                    f("textureLodOffset", &[p, "float", o]);
                    for &q in row.proj {
                        f("textureProjLodOffset", &[q, "float", o]);
                    }
                }
            }
            if let Some(d) = row.grad {
                f("textureGrad", &[p, d, d]);
                for &q in row.proj {
                    f("textureProjGrad", &[q, d, d]);
                }
                if let Some(o) = row.offset {
                    f("textureGradOffset", &[p, d, d, o]);
                    for &q in row.proj {
                        f("textureProjGradOffset", &[q, d, d, o]);
                    }
                }
            }
        }
        if row.compare_arg {
            f("texture", &["vec4", "float"]);
        }
        if let Some((p, last)) = row.fetch {
            let mut params = vec![p];
            params.extend(last);
            f("texelFetch", &params);
            if let Some(o) = row.offset {
                params.push(o);
                f("texelFetchOffset", &params);
            }
        }
        let (size, lod) = row.size;
        let _ = writeln!(
            out,
            "{size} textureSize({s}{});",
            if lod { ", int" } else { "" }
        );
    }
}

/// What to write instead of a built-in the core profile removes (GLSL
/// 1.40 §1.2.5), for the diagnostic of a core-profile shader that uses it.
pub(crate) const REPLACEMENTS: &[(&str, &str)] = &[
    ("gl_Vertex", "declare an `in vec4' vertex input instead"),
    ("gl_Normal", "declare an `in vec3' vertex input instead"),
    ("gl_Color", "declare an `in vec4' input instead (a vertex input, or a fragment input written by the vertex shader)"),
    ("gl_SecondaryColor", "declare an `in vec4' input instead (a vertex input, or a fragment input written by the vertex shader)"),
    ("gl_MultiTexCoord", "declare an `in vec4' vertex input instead"),
    ("gl_FogCoord", "declare an `in float' vertex input instead"),
    ("gl_FrontColor", "declare an `out vec4' of your own and read it as an `in' in the fragment shader"),
    ("gl_BackColor", "declare an `out vec4' of your own and read it as an `in' in the fragment shader"),
    ("gl_FrontSecondaryColor", "declare an `out vec4' of your own and read it as an `in' in the fragment shader"),
    ("gl_BackSecondaryColor", "declare an `out vec4' of your own and read it as an `in' in the fragment shader"),
    ("gl_TexCoord", "declare an `out' variable in the vertex shader and an `in' of the same name in the fragment shader"),
    ("gl_FogFragCoord", "declare an `out' variable in the vertex shader and an `in' of the same name in the fragment shader"),
    ("gl_ClipVertex", "write the distances to your planes to `gl_ClipDistance[]' instead"),
    ("gl_ClipPlane", "declare a `uniform vec4' plane and write its distance to `gl_ClipDistance[]'"),
    ("gl_MaxClipPlanes", "use `gl_MaxClipDistances' instead"),
    ("gl_MaxTextureCoords", "use `in'/`out' variables of your own instead (`gl_MaxVaryingComponents' bounds them)"),
    ("gl_MaxTextureUnits", "use `gl_MaxTextureImageUnits' instead"),
    ("ftransform", "declare a `uniform mat4' and an `in vec4' position and write `gl_Position = mvp * position'"),
];

/// The note for a removed built-in [`REPLACEMENTS`] does not name: the
/// uniform state of §7.5 and its struct types.
const UNIFORM_REPLACEMENT: &str =
    "declare a `uniform' (and struct type) of your own and set it from the application instead";

/// What to write instead of `name`, a built-in the core profile removes.
pub(crate) fn replacement(name: &str) -> &'static str {
    let key = if name.starts_with("gl_MultiTexCoord") {
        "gl_MultiTexCoord"
    } else {
        name
    };
    REPLACEMENTS
        .iter()
        .find(|(n, _)| *n == key)
        .map_or(UNIFORM_REPLACEMENT, |&(_, r)| r)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::builtins::BuiltinFn;

    /// The prelude of a version in a compatibility context.
    fn prelude(v: Version, s: Stage) -> String {
        super::prelude(Language::new(v, true), s)
    }

    /// 1.10 and 1.20 (one profile).
    const ALL: [(Version, Stage); 4] = [
        (Version::V110, Stage::Vertex),
        (Version::V110, Stage::Fragment),
        (Version::V120, Stage::Vertex),
        (Version::V120, Stage::Fragment),
    ];

    /// Every language (each version in each profile) and stage.
    fn every_language() -> Vec<(Language, Stage)> {
        let mut out = Vec::new();
        for v in Version::ALL {
            for p in [
                crate::lang::Profile::Core,
                crate::lang::Profile::Compatibility,
            ] {
                let mut l = Language::new(v, true);
                l.profile = p;
                // And with the extensions that add built-in functions.
                let mut e = l;
                e.extensions.set(Extension::ExtTextureArray, true);
                e.extensions.set(Extension::ArbShaderTextureLod, true);
                e.extensions.set(Extension::ArbShadingLanguagePacking, true);
                e.extensions.set(Extension::ArbTextureCubeMapArray, true);
                e.extensions.set(Extension::ArbComputeShader, true);
                e.extensions
                    .set(Extension::ArbShaderStorageBufferObject, true);
                e.extensions.set(Extension::ArbTessellationShader, true);
                for s in [
                    Stage::Vertex,
                    Stage::TessControl,
                    Stage::TessEvaluation,
                    Stage::Geometry,
                    Stage::Fragment,
                    Stage::Compute,
                ] {
                    out.push((l, s));
                    out.push((e, s));
                }
            }
        }
        out
    }

    fn core(v: Version) -> Language {
        let mut l = Language::new(v, false);
        l.profile = crate::lang::Profile::Core;
        l
    }

    /// True when `text` declares a function `name` (a prototype line
    /// `... name(`).
    fn declares_fn(text: &str, name: &str) -> bool {
        let pat = format!(" {name}(");
        text.lines().any(|l| l.contains(&pat) && l.ends_with(");"))
    }

    /// True when `text` declares a variable `name` (a line `... name;`,
    /// `... name[...];` or `... name = ...;`).
    fn declares_var(text: &str, name: &str) -> bool {
        text.lines()
            .filter(|l| l.ends_with(';') && !l.contains('(') && !l.starts_with("//"))
            .any(|l| {
                let decl = l.split(['[', '=', ';']).next().unwrap_or("");
                decl.split_whitespace().last() == Some(name)
            })
    }

    fn has(v: Version, s: Stage, name: &str) -> bool {
        declares_fn(&prelude(v, s), name)
    }

    #[test]
    fn every_builtin_fn_has_a_prototype() {
        let texts: Vec<String> = every_language()
            .into_iter()
            .map(|(l, s)| super::prelude(l, s))
            .collect();
        for f in BuiltinFn::ALL {
            assert!(
                texts.iter().any(|t| declares_fn(t, f.name())),
                "no prototype of `{}'",
                f.name()
            );
        }
    }

    #[test]
    fn every_prototype_names_a_builtin_fn() {
        for (l, s) in every_language() {
            // Prototypes; constants of vector type end in a constructor.
            let prototypes = |l: &&str| l.ends_with(");") && !l.starts_with("const ");
            for line in super::prelude(l, s).lines().filter(prototypes) {
                let name = line
                    .split('(')
                    .next()
                    .and_then(|head| head.split_whitespace().nth(1));
                assert!(
                    name.and_then(BuiltinFn::from_name).is_some(),
                    "unknown built-in in `{line}'"
                );
            }
        }
    }

    #[test]
    fn stage_and_version_gating() {
        use Stage::{Fragment, Vertex};
        use Version::{V110, V120};
        for v in [V110, V120] {
            assert!(has(v, Vertex, "texture2DLod"));
            assert!(!has(v, Fragment, "texture2DLod"));
            assert!(has(v, Fragment, "dFdx"));
            assert!(!has(v, Vertex, "fwidth"));
            assert!(has(v, Vertex, "ftransform"));
            assert!(!has(v, Fragment, "ftransform"));
            assert!(has(v, Fragment, "noise3") && has(v, Vertex, "noise3"));
        }
        for s in [Vertex, Fragment] {
            assert!(has(V120, s, "transpose") && !has(V110, s, "transpose"));
            assert!(has(V120, s, "outerProduct") && !has(V110, s, "outerProduct"));
        }
        // Bias variants only in the fragment stage.
        let bias = "vec4 texture2D(sampler2D, vec2, float);";
        assert!(prelude(V110, Fragment).contains(bias));
        assert!(!prelude(V110, Vertex).contains(bias));
        // Non-square matrices only in 1.20.
        assert!(prelude(V120, Vertex).contains("mat2x3 matrixCompMult(mat2x3, mat2x3);"));
        assert!(!prelude(V110, Vertex).contains("mat2x3"));
        assert!(prelude(V120, Vertex).contains("mat3x2 transpose(mat2x3);"));
        assert!(prelude(V120, Vertex).contains("mat3x2 outerProduct(vec2, vec3);"));
    }

    #[test]
    fn variables_per_stage() {
        use Stage::{Fragment, Vertex};
        use Version::{V110, V120};
        assert!(declares_var(&prelude(V120, Fragment), "gl_PointCoord"));
        for (v, s) in [(V110, Fragment), (V110, Vertex), (V120, Vertex)] {
            assert!(!declares_var(&prelude(v, s), "gl_PointCoord"));
        }
        for v in [V110, V120] {
            let vs = prelude(v, Vertex);
            let fs = prelude(v, Fragment);
            assert!(vs.contains("\nvec4 gl_Position;\n") && !declares_var(&fs, "gl_Position"));
            assert!(vs.contains("attribute vec4 gl_Color;"));
            assert!(fs.contains("varying vec4 gl_Color;"));
            assert!(fs.contains("\nvec4 gl_FragData[gl_MaxDrawBuffers];\n"));
            assert!(!declares_var(&vs, "gl_FragColor") && !declares_var(&vs, "gl_FrontFacing"));
            assert!(!declares_var(&fs, "gl_FrontColor") && !declares_var(&fs, "gl_MultiTexCoord0"));
            for text in [&vs, &fs] {
                assert!(text.contains("const int gl_MaxLights = 8;"));
                assert!(
                    text.contains("uniform gl_LightSourceParameters gl_LightSource[gl_MaxLights];")
                );
                assert!(text.contains(
                    "uniform mat4 gl_TextureMatrixInverseTranspose[gl_MaxTextureCoords];"
                ));
                assert!(text.contains("varying vec4 gl_TexCoord[];"));
            }
        }
    }

    #[test]
    fn lexes_cleanly_with_no_reserved_words() {
        use crate::lex::{lex, LexOptions, PpKind};
        use crate::token::{classify, WordClass};
        for (l, s) in every_language() {
            let v = l.version;
            let text = &super::prelude(l, s);
            assert!(text.is_ascii());
            assert!(text.starts_with(&format!("#version {}", v.number())));
            let directives = 1
                + l.has(Extension::ArbTextureCubeMapArray) as usize
                + l.has(Extension::ArbTessellationShader) as usize;
            assert_eq!(text.matches('#').count(), directives);
            let (tokens, diags) = lex(text, LexOptions::default());
            assert!(diags.is_empty(), "{v:?} {s:?}: {diags:?}");
            for t in &tokens {
                assert!(!matches!(t.kind, PpKind::Other(_)));
                if t.kind == PpKind::Ident {
                    assert_ne!(classify(&t.text, l), WordClass::Reserved, "{}", t.text);
                }
            }
        }
    }

    #[test]
    fn glsl130_and_later_additions() {
        use Stage::{Fragment, Vertex};
        use Version::{V120, V130, V140, V150, V330};
        let c130 = |s| super::prelude(Language::new(V130, true), s);
        let vs = c130(Vertex);
        let fs = c130(Fragment);
        for f in [
            "trunc",
            "round",
            "roundEven",
            "sinh",
            "atanh",
            "modf",
            "isnan",
            "texture",
        ] {
            assert!(declares_fn(&vs, f) && !has(V120, Vertex, f), "{f}");
        }
        assert!(vs.contains("ivec2 min(ivec2, int);"));
        assert!(vs.contains("vec3 mix(vec3, vec3, bvec3);"));
        assert!(vs.contains("float modf(float, out float);"));
        assert!(vs.contains("bvec4 isinf(vec4);"));
        assert!(vs.contains("ivec4 texelFetch(isampler2D, ivec2, int);"));
        assert!(vs.contains("ivec3 textureSize(sampler2DArray, int);"));
        assert!(vs.contains("float texture(samplerCubeShadow, vec4);"));
        assert!(!vs.contains("float texture(samplerCubeShadow, vec4, float);"));
        assert!(fs.contains("float texture(samplerCubeShadow, vec4, float);"));
        assert!(vs.contains("vec4 textureGradOffset(sampler2D, vec2, vec2, vec2, ivec2);"));
        // No 1.40 samplers in 1.30.
        assert!(!vs.contains("sampler2DRect"));
        // The Lod forms of 1.10 reach the fragment stage in 1.30.
        assert!(declares_fn(&fs, "texture2DLod") && !has(V120, Fragment, "texture2DLod"));
        assert!(declares_var(&vs, "gl_VertexID") && !declares_var(&vs, "gl_InstanceID"));
        assert!(declares_var(&fs, "gl_ClipDistance") && declares_var(&vs, "gl_ClipDistance"));
        assert!(vs.contains("const int gl_MaxClipDistances = 8;"));
        assert!(!declares_fn(&vs, "inverse") && !declares_fn(&vs, "floatBitsToInt"));
        let c140 = super::prelude(Language::new(V140, true), Vertex);
        assert!(declares_fn(&c140, "inverse") && !declares_fn(&c140, "determinant"));
        assert!(declares_var(&c140, "gl_InstanceID"));
        assert!(c140.contains("ivec2 textureSize(sampler2DRect);"));
        // GL_ARB_texture_rectangle's lookups come with the types.
        assert!(c140.contains("vec4 shadow2DRectProj(sampler2DRectShadow, vec4);"));
        assert!(c140.contains("vec4 texture2DRect(sampler2DRect, vec2);"));
        assert!(!declares_fn(&vs, "texture2DRect") && !declares_fn(&vs, "shadow2DRect"));
        assert!(c140.contains("vec4 texelFetch(samplerBuffer, int);"));
        let f150 = super::prelude(core(V150), Fragment);
        assert!(declares_fn(&f150, "determinant"));
        assert!(declares_var(&f150, "gl_PrimitiveID"));
        assert!(f150.contains("ivec4 texelFetch(isampler2DMS, ivec2, int);"));
        assert!(f150.contains("const int gl_MaxGeometryOutputVertices = 256;"));
        // textureGradOffset but no textureOffset on 2D array shadows.
        assert!(f150
            .contains("float textureGradOffset(sampler2DArrayShadow, vec4, vec2, vec2, ivec2);"));
        assert!(!f150.contains(" textureOffset(sampler2DArrayShadow"));
        let v330 = super::prelude(core(V330), Vertex);
        assert!(v330.contains("ivec3 floatBitsToInt(vec3);"));
        assert!(v330.contains("vec2 intBitsToFloat(ivec2);"));
    }

    #[test]
    fn the_core_profile_removes_the_fixed_function_interface() {
        use Stage::{Fragment, Vertex};
        for v in [Version::V140, Version::V150, Version::V330] {
            let vs = super::prelude(core(v), Vertex);
            let fs = super::prelude(core(v), Fragment);
            for name in [
                "gl_Vertex",
                "gl_MultiTexCoord3",
                "gl_FrontColor",
                "gl_TexCoord",
                "gl_ClipVertex",
                "gl_ModelViewMatrix",
                "gl_LightSource",
                "gl_MaxLights",
                "gl_MaxClipPlanes",
                "gl_MaxTextureUnits",
                "gl_MaxTextureCoords",
                "gl_FogFragCoord",
            ] {
                assert!(
                    !declares_var(&vs, name) && !declares_var(&fs, name),
                    "{v:?} {name}"
                );
            }
            assert!(!declares_fn(&vs, "ftransform"));
            assert!(!fs.contains("struct gl_LightSourceParameters"));
            // Kept: gl_DepthRange, the deprecated fragment outputs and
            // lookups, gl_Position.
            for text in [&vs, &fs] {
                assert!(declares_var(text, "gl_DepthRange"));
                assert!(declares_fn(text, "texture2D"));
            }
            assert!(declares_var(&fs, "gl_FragColor") && declares_var(&fs, "gl_FragData"));
            assert!(declares_var(&vs, "gl_Position") && declares_var(&vs, "gl_PointSize"));
            let mut compat = core(v);
            compat.profile = crate::lang::Profile::Compatibility;
            let cvs = super::prelude(compat, Vertex);
            assert!(declares_var(&cvs, "gl_Vertex") && declares_fn(&cvs, "ftransform"));
        }
        // Every removed name has a replacement note.
        assert!(super::replacement("gl_MultiTexCoord5").contains("in vec4"));
        assert!(super::replacement("gl_FrontLightProduct").contains("uniform"));
    }

    #[test]
    fn glsl110_and_120_text_is_unchanged_in_substance() {
        // The declarations of 1.10/1.20 before the table: a sample of
        // lines in their order.
        let vs = prelude(Version::V120, Stage::Vertex);
        let order = [
            "const int gl_MaxLights = 8;",
            "const int gl_MaxDrawBuffers = 8;",
            "uniform mat4 gl_ModelViewMatrix;",
            "uniform gl_DepthRangeParameters gl_DepthRange;",
            "uniform vec4 gl_TextureEnvColor[gl_MaxTextureUnits];",
            "uniform gl_FogParameters gl_Fog;",
            "vec4 gl_Position;",
            "attribute vec4 gl_MultiTexCoord7;",
            "varying float gl_FogFragCoord;",
            "float radians(float);",
            "vec4 noise4(vec4);",
        ];
        let mut at = 0;
        for line in order {
            let i = vs[at..].find(line).unwrap_or_else(|| panic!("{line}"));
            at += i;
        }
        assert!(prelude(Version::V110, Stage::Vertex)
            .contains("uniform vec4 gl_TextureEnvColor[gl_MaxTextureImageUnits];"));
        for (v, s) in ALL {
            let text = prelude(v, s);
            for absent in [
                "gl_VertexID",
                "gl_ClipDistance",
                "gl_MaxClipDistances",
                "trunc",
                "texture(",
                "isampler",
            ] {
                assert!(!text.contains(absent), "{v:?} {s:?} {absent}");
            }
        }
    }

    #[test]
    fn unsigned_overloads_by_version() {
        use Stage::{Fragment, Vertex};
        use Version::{V120, V130, V140, V150, V330};
        let c = |v, s| super::prelude(Language::new(v, true), s);
        let (v130, f130) = (c(V130, Vertex), c(V130, Fragment));
        for line in [
            "uint min(uint, uint);",
            "uvec3 min(uvec3, uvec3);",
            "uvec3 min(uvec3, uint);",
            "uvec4 max(uvec4, uvec4);",
            "uvec2 max(uvec2, uint);",
            "uint clamp(uint, uint, uint);",
            "uvec2 clamp(uvec2, uvec2, uvec2);",
            "uvec4 clamp(uvec4, uint, uint);",
            "bvec2 lessThan(uvec2, uvec2);",
            "bvec3 lessThanEqual(uvec3, uvec3);",
            "bvec4 greaterThan(uvec4, uvec4);",
            "bvec2 greaterThanEqual(uvec2, uvec2);",
            "bvec3 equal(uvec3, uvec3);",
            "bvec4 notEqual(uvec4, uvec4);",
        ] {
            assert!(v130.contains(line) && f130.contains(line), "{line}");
        }
        // `uint min(uint, uint)` once: the `uvec, uint` form starts at 2.
        assert_eq!(v130.matches("uint min(uint, uint);").count(), 1);
        // No unsigned abs, sign or bool-selector mix before GLSL 4.50, and
        // no relational function on scalars.
        for absent in [
            " abs(uint",
            " sign(uint",
            " abs(uvec",
            " mix(uint",
            " mix(uvec",
            " lessThan(uint",
        ] {
            for v in [V130, V140, V150, V330] {
                assert!(!c(v, Fragment).contains(absent), "{v:?} {absent}");
            }
        }
        // The bit casts are 3.30's.
        for v in [V130, V140, V150] {
            assert!(!declares_fn(&c(v, Vertex), "floatBitsToUint"));
            assert!(!declares_fn(&c(v, Vertex), "uintBitsToFloat"));
        }
        let v330 = super::prelude(core(V330), Vertex);
        assert!(v330.contains("uint floatBitsToUint(float);"));
        assert!(v330.contains("uvec3 floatBitsToUint(vec3);"));
        assert!(v330.contains("float uintBitsToFloat(uint);"));
        assert!(v330.contains("vec4 uintBitsToFloat(uvec4);"));
        // Nothing unsigned before 1.30.
        for (v, s) in ALL {
            let text = prelude(v, s);
            assert!(
                !text.contains("uint") && !text.contains("uvec"),
                "{v:?} {s:?}"
            );
        }
        assert!(!has(V120, Vertex, "floatBitsToUint"));
    }

    #[test]
    fn usampler_lookups_are_the_isampler_ones_with_uvec4_results() {
        use Stage::{Fragment, Vertex};
        for v in [Version::V130, Version::V140, Version::V150, Version::V330] {
            for s in [Vertex, Fragment] {
                let text = super::prelude(Language::new(v, true), s);
                let lines = |p: &str| -> Vec<String> {
                    text.lines()
                        .filter(|l| l.contains(&format!("({p}sampler")))
                        .map(|l| l.replace(&format!("({p}sampler"), "(Xsampler"))
                        .map(|l| l.replacen(&format!("{p}vec4 "), "Xvec4 ", 1))
                        .collect()
                };
                let (i, u) = (lines("i"), lines("u"));
                assert!(!u.is_empty());
                assert_eq!(i, u, "{v:?} {s:?}");
                // textureSize stays signed; everything else returns uvec4.
                for l in text.lines().filter(|l| l.contains("(usampler")) {
                    assert!(
                        l.starts_with("uvec4 ") || l.contains(" textureSize("),
                        "{l}"
                    );
                }
            }
        }
        let f130 = super::prelude(Language::new(Version::V130, true), Fragment);
        for line in [
            "uvec4 texture(usampler2D, vec2, float);",
            "uvec4 textureProj(usampler3D, vec4);",
            "uvec4 textureLod(usamplerCube, vec3, float);",
            "uvec4 textureOffset(usampler1DArray, vec2, int);",
            "uvec4 texelFetch(usampler2DArray, ivec3, int);",
            "uvec4 texelFetchOffset(usampler1D, int, int, int);",
            "uvec4 textureProjGradOffset(usampler2D, vec4, vec2, vec2, ivec2);",
            "int textureSize(usampler1D, int);",
            "ivec3 textureSize(usampler2DArray, int);",
        ] {
            assert!(f130.contains(line), "{line}");
        }
        assert!(!f130.contains("usampler2DRect") && !f130.contains("usampler2DMS"));
        let f150 = super::prelude(core(Version::V150), Fragment);
        for line in [
            "uvec4 texture(usampler2DRect, vec2);",
            "uvec4 texelFetch(usamplerBuffer, int);",
            "ivec2 textureSize(usampler2DRect);",
            "uvec4 texelFetch(usampler2DMSArray, ivec3, int);",
            "ivec3 textureSize(usampler2DMSArray);",
        ] {
            assert!(f150.contains(line), "{line}");
        }
    }

    #[test]
    fn unsigned_placeholders_expand() {
        let mut out = String::new();
        expand(&mut out, "genUType min(genUType, genUType)", Version::V130);
        expand(&mut out, "bvec lessThan(uvec, uvec)", Version::V130);
        assert_eq!(
            out,
            "uint min(uint, uint);\nuvec2 min(uvec2, uvec2);\nuvec3 min(uvec3, uvec3);\nuvec4 min(uvec4, uvec4);\n\
             bvec2 lessThan(uvec2, uvec2);\nbvec3 lessThan(uvec3, uvec3);\nbvec4 lessThan(uvec4, uvec4);\n"
        );
    }
}
