//! The built-in environment of a shader, as GLSL source.
//!
//! [`prelude`] returns the declarations of everything GLSL 1.10 / 1.20 make
//! visible to a shader of one stage before its first line: the constants of
//! §7.4, the uniform state of §7.5 (with its struct types), the stage's
//! special variables, attributes and varyings (§7.1-7.3, §7.6) and the
//! prototypes of every built-in function of §8. The semantic analyzer parses
//! it in a privileged mode (where `gl_` names, `varying bool` and bodiless
//! prototypes of built-ins are accepted) before the user's shader.
//!
//! Access rules are expressed with ordinary qualifiers:
//! - stage outputs (`gl_Position`, `gl_FragColor`, ...) are plain globals:
//!   readable and writable;
//! - vertex inputs are `attribute`s (read-only);
//! - fragment inputs, including `gl_FragCoord` and `gl_FrontFacing`, are
//!   `varying`s (read-only in a fragment shader);
//! - vertex outputs to the fragment stage are `varying`s (writable in a
//!   vertex shader).
//!
//! Nothing else is declared: a name missing from this text is not a
//! built-in of that version and stage. The text starts with the matching
//! `#version` line and has no other preprocessor directive.

use crate::ir::Stage;
use crate::lang::{Language, Version};
use crate::limits;
use std::fmt::Write;

/// The built-in declarations for `lang` and `stage` (the semantic
/// analyzer caches what it makes of them).
pub fn prelude(lang: Language, stage: Stage) -> String {
    build(lang, stage)
}

/// `genType` of §8: the argument and result types of component-wise
/// functions.
const GEN_TYPES: [&str; 4] = ["float", "vec2", "vec3", "vec4"];

fn build(lang: Language, stage: Stage) -> String {
    let version = lang.version;
    let mut out = String::with_capacity(32 * 1024);
    // The preprocessor classifies keywords by the `#version` it sees, so the
    // prelude states its own (`mat2x3` is a type only in 1.20).
    if version.has_profiles() {
        let _ = writeln!(out, "#version {} {}", version.number(), lang.profile.name());
    } else {
        let _ = writeln!(out, "#version {}", version.number());
    }
    let _ = writeln!(
        out,
        "// Built-in declarations of GLSL {} ({} shader).",
        version.dotted(),
        stage.name()
    );
    constants(&mut out);
    uniform_state(&mut out, version);
    match stage {
        Stage::Vertex => vertex_variables(&mut out),
        Stage::Fragment => fragment_variables(&mut out, version),
    }
    functions(&mut out, version, stage);
    out
}

/// §7.4, the same list in 1.10 and 1.20.
fn constants(out: &mut String) {
    let list: [(&str, u32); 12] = [
        ("gl_MaxLights", limits::MAX_LIGHTS),
        ("gl_MaxClipPlanes", limits::MAX_CLIP_PLANES),
        ("gl_MaxTextureUnits", limits::MAX_TEXTURE_UNITS),
        ("gl_MaxTextureCoords", limits::MAX_TEXTURE_COORDS),
        ("gl_MaxVertexAttribs", limits::MAX_VERTEX_ATTRIBS),
        (
            "gl_MaxVertexUniformComponents",
            limits::MAX_VERTEX_UNIFORM_COMPONENTS,
        ),
        ("gl_MaxVaryingFloats", limits::MAX_VARYING_FLOATS),
        (
            "gl_MaxVertexTextureImageUnits",
            limits::MAX_VERTEX_TEXTURE_IMAGE_UNITS,
        ),
        (
            "gl_MaxCombinedTextureImageUnits",
            limits::MAX_COMBINED_TEXTURE_IMAGE_UNITS,
        ),
        ("gl_MaxTextureImageUnits", limits::MAX_TEXTURE_IMAGE_UNITS),
        (
            "gl_MaxFragmentUniformComponents",
            limits::MAX_FRAGMENT_UNIFORM_COMPONENTS,
        ),
        ("gl_MaxDrawBuffers", limits::MAX_DRAW_BUFFERS),
    ];
    out.push_str("// section 7.4 built-in constants\n");
    for (name, value) in list {
        let _ = writeln!(out, "const int {name} = {value};");
    }
}

/// §7.5, visible to both stages.
fn uniform_state(out: &mut String, version: Version) {
    out.push_str(
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
uniform float gl_NormalScale;
struct gl_DepthRangeParameters {
    float near;
    float far;
    float diff;
};
uniform gl_DepthRangeParameters gl_DepthRange;
uniform vec4 gl_ClipPlane[gl_MaxClipPlanes];
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
uniform gl_LightProducts gl_BackLightProduct[gl_MaxLights];
",
    );
    // 1.10 §7.5 sizes gl_TextureEnvColor by the texture image units, 1.20
    // §7.5 (and later) by the fixed-function texture units.
    let env_size = if version >= Version::V120 {
        "gl_MaxTextureUnits"
    } else {
        "gl_MaxTextureImageUnits"
    };
    let _ = writeln!(out, "uniform vec4 gl_TextureEnvColor[{env_size}];");
    for plane in ["Eye", "Object"] {
        for coord in ["S", "T", "R", "Q"] {
            let _ = writeln!(
                out,
                "uniform vec4 gl_{plane}Plane{coord}[gl_MaxTextureCoords];"
            );
        }
    }
    out.push_str(
        "struct gl_FogParameters {
    vec4 color;
    float density;
    float start;
    float end;
    float scale;
};
uniform gl_FogParameters gl_Fog;
",
    );
}

/// §7.1 special variables, §7.3 attributes, §7.6 vertex varyings.
fn vertex_variables(out: &mut String) {
    out.push_str(
        "// section 7.1 vertex shader special variables
vec4 gl_Position;
float gl_PointSize;
vec4 gl_ClipVertex;
// section 7.3 built-in attributes
attribute vec4 gl_Color;
attribute vec4 gl_SecondaryColor;
attribute vec3 gl_Normal;
attribute vec4 gl_Vertex;
",
    );
    for i in 0..8 {
        let _ = writeln!(out, "attribute vec4 gl_MultiTexCoord{i};");
    }
    out.push_str(
        "attribute float gl_FogCoord;
// section 7.6 varying outputs
varying vec4 gl_FrontColor;
varying vec4 gl_BackColor;
varying vec4 gl_FrontSecondaryColor;
varying vec4 gl_BackSecondaryColor;
varying vec4 gl_TexCoord[];
varying float gl_FogFragCoord;
",
    );
}

/// §7.2 special variables, §7.6 fragment varyings.
fn fragment_variables(out: &mut String, version: Version) {
    out.push_str(
        "// section 7.2 fragment shader special variables
varying vec4 gl_FragCoord;
varying bool gl_FrontFacing;
vec4 gl_FragColor;
vec4 gl_FragData[gl_MaxDrawBuffers];
float gl_FragDepth;
// section 7.6 varying inputs
varying vec4 gl_Color;
varying vec4 gl_SecondaryColor;
varying vec4 gl_TexCoord[];
varying float gl_FogFragCoord;
",
    );
    if version >= Version::V120 {
        out.push_str("varying vec2 gl_PointCoord;\n");
    }
}

/// Writes `ret name(params);`.
fn proto(out: &mut String, ret: &str, name: &str, params: &[&str]) {
    let _ = writeln!(out, "{ret} {name}({});", params.join(", "));
}

/// One prototype per `genType`, with `G` in `ret` and `params` replaced by
/// the type. Parameters spelled `float` stay scalar.
fn gen(out: &mut String, ret: &str, name: &str, params: &[&str]) {
    for t in GEN_TYPES {
        let ret = if ret == "G" { t } else { ret };
        let params: Vec<&str> = params
            .iter()
            .map(|&p| if p == "G" { t } else { p })
            .collect();
        proto(out, ret, name, &params);
    }
}

/// The `genType f(genType, float)`-style variants: like [`gen`] but without
/// the `float` instance, which the all-`genType` overload already declares.
fn gen_vec(out: &mut String, name: &str, params: &[&str]) {
    for t in &GEN_TYPES[1..] {
        let params: Vec<&str> = params
            .iter()
            .map(|&p| if p == "G" { *t } else { p })
            .collect();
        proto(out, t, name, &params);
    }
}

/// Matrix types of the version: square ones always, non-square from 1.20
/// (as `(name, cols, rows)`).
fn matrices(version: Version) -> Vec<(String, u8, u8)> {
    let mut list = Vec::new();
    for cols in 2u8..=4 {
        for rows in 2u8..=4 {
            if cols == rows {
                list.push((format!("mat{cols}"), cols, rows));
            } else if version >= Version::V120 {
                list.push((format!("mat{cols}x{rows}"), cols, rows));
            }
        }
    }
    list
}

fn mat_name(cols: u8, rows: u8) -> String {
    if cols == rows {
        format!("mat{cols}")
    } else {
        format!("mat{cols}x{rows}")
    }
}

fn functions(out: &mut String, version: Version, stage: Stage) {
    out.push_str("// section 8.1 angle and trigonometry functions\n");
    for f in ["radians", "degrees", "sin", "cos", "tan", "asin", "acos"] {
        gen(out, "G", f, &["G"]);
    }
    gen(out, "G", "atan", &["G", "G"]);
    gen(out, "G", "atan", &["G"]);

    out.push_str("// section 8.2 exponential functions\n");
    gen(out, "G", "pow", &["G", "G"]);
    for f in ["exp", "log", "exp2", "log2", "sqrt", "inversesqrt"] {
        gen(out, "G", f, &["G"]);
    }

    out.push_str("// section 8.3 common functions\n");
    for f in ["abs", "sign", "floor", "ceil", "fract"] {
        gen(out, "G", f, &["G"]);
    }
    for f in ["mod", "min", "max"] {
        gen(out, "G", f, &["G", "G"]);
        gen_vec(out, f, &["G", "float"]);
    }
    gen(out, "G", "clamp", &["G", "G", "G"]);
    gen_vec(out, "clamp", &["G", "float", "float"]);
    gen(out, "G", "mix", &["G", "G", "G"]);
    gen_vec(out, "mix", &["G", "G", "float"]);
    gen(out, "G", "step", &["G", "G"]);
    gen_vec(out, "step", &["float", "G"]);
    gen(out, "G", "smoothstep", &["G", "G", "G"]);
    gen_vec(out, "smoothstep", &["float", "float", "G"]);

    out.push_str("// section 8.4 geometric functions\n");
    gen(out, "float", "length", &["G"]);
    gen(out, "float", "distance", &["G", "G"]);
    gen(out, "float", "dot", &["G", "G"]);
    proto(out, "vec3", "cross", &["vec3", "vec3"]);
    gen(out, "G", "normalize", &["G"]);
    if stage == Stage::Vertex {
        proto(out, "vec4", "ftransform", &[]);
    }
    gen(out, "G", "faceforward", &["G", "G", "G"]);
    gen(out, "G", "reflect", &["G", "G"]);
    gen(out, "G", "refract", &["G", "G", "float"]);

    out.push_str("// section 8.5 matrix functions\n");
    for (m, _, _) in matrices(version) {
        proto(out, &m, "matrixCompMult", &[&m, &m]);
    }
    if version >= Version::V120 {
        for (m, cols, rows) in matrices(version) {
            // Column vector c (rows components) times row vector r (cols).
            let c = format!("vec{rows}");
            let r = format!("vec{cols}");
            proto(out, &m, "outerProduct", &[&c, &r]);
        }
        for (m, cols, rows) in matrices(version) {
            proto(out, &mat_name(rows, cols), "transpose", &[&m]);
        }
    }

    out.push_str("// section 8.6 vector relational functions\n");
    for f in [
        "lessThan",
        "lessThanEqual",
        "greaterThan",
        "greaterThanEqual",
    ] {
        for n in 2..=4 {
            let (b, v, i) = (format!("bvec{n}"), format!("vec{n}"), format!("ivec{n}"));
            proto(out, &b, f, &[&v, &v]);
            proto(out, &b, f, &[&i, &i]);
        }
    }
    for f in ["equal", "notEqual"] {
        for n in 2..=4 {
            let (b, v, i) = (format!("bvec{n}"), format!("vec{n}"), format!("ivec{n}"));
            proto(out, &b, f, &[&v, &v]);
            proto(out, &b, f, &[&i, &i]);
            proto(out, &b, f, &[&b, &b]);
        }
    }
    for n in 2..=4 {
        let b = format!("bvec{n}");
        proto(out, "bool", "any", &[&b]);
        proto(out, "bool", "all", &[&b]);
        proto(out, &b, "not", &[&b]);
    }

    texture_functions(out, stage);

    if stage == Stage::Fragment {
        out.push_str("// section 8.8 fragment processing functions\n");
        for f in ["dFdx", "dFdy", "fwidth"] {
            gen(out, "G", f, &["G"]);
        }
    }

    out.push_str("// section 8.9 noise functions\n");
    gen(out, "float", "noise1", &["G"]);
    gen(out, "vec2", "noise2", &["G"]);
    gen(out, "vec3", "noise3", &["G"]);
    gen(out, "vec4", "noise4", &["G"]);
}

/// §8.7 (the same in 1.10 and 1.20): every lookup takes an optional `bias`
/// in fragment shaders only; the `Lod` variants exist in vertex shaders
/// only.
fn texture_functions(out: &mut String, stage: Stage) {
    // (name without suffix, sampler, coordinate types)
    let lookups: [(&str, &str, &[&str]); 9] = [
        ("texture1D", "sampler1D", &["float"]),
        ("texture1DProj", "sampler1D", &["vec2", "vec4"]),
        ("texture2D", "sampler2D", &["vec2"]),
        ("texture2DProj", "sampler2D", &["vec3", "vec4"]),
        ("texture3D", "sampler3D", &["vec3"]),
        ("texture3DProj", "sampler3D", &["vec4"]),
        ("textureCube", "samplerCube", &["vec3"]),
        ("shadow1D", "sampler1DShadow", &["vec3"]),
        ("shadow2D", "sampler2DShadow", &["vec3"]),
    ];
    let shadow_proj: [(&str, &str, &[&str]); 2] = [
        ("shadow1DProj", "sampler1DShadow", &["vec4"]),
        ("shadow2DProj", "sampler2DShadow", &["vec4"]),
    ];
    out.push_str("// section 8.7 texture lookup functions\n");
    for (name, sampler, coords) in lookups.iter().chain(shadow_proj.iter()) {
        for coord in coords.iter() {
            proto(out, "vec4", name, &[sampler, coord]);
            match stage {
                Stage::Fragment => proto(out, "vec4", name, &[sampler, coord, "float"]),
                Stage::Vertex => {
                    let lod = format!("{name}Lod");
                    proto(out, "vec4", &lod, &[sampler, coord, "float"]);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::builtins::BuiltinFn;

    /// The prelude of a version in a compatibility context.
    fn prelude(v: Version, s: Stage) -> String {
        super::prelude(Language::new(v, true), s)
    }

    const ALL: [(Version, Stage); 4] = [
        (Version::V110, Stage::Vertex),
        (Version::V110, Stage::Fragment),
        (Version::V120, Stage::Vertex),
        (Version::V120, Stage::Fragment),
    ];

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
        for f in BuiltinFn::ALL {
            assert!(
                ALL.iter().any(|&(v, s)| has(v, s, f.name())),
                "no prototype of `{}'",
                f.name()
            );
        }
    }

    #[test]
    fn every_prototype_names_a_builtin_fn() {
        for (v, s) in ALL {
            for line in prelude(v, s).lines().filter(|l| l.ends_with(");")) {
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
        for (v, s) in ALL {
            let text = &prelude(v, s);
            assert!(text.is_ascii());
            assert!(text.starts_with(&format!("#version {}\n", v.number())));
            assert_eq!(text.matches('#').count(), 1);
            let (tokens, diags) = lex(text, LexOptions::default());
            assert!(diags.is_empty(), "{v:?} {s:?}: {diags:?}");
            for t in &tokens {
                assert!(!matches!(t.kind, PpKind::Other(_)));
                if t.kind == PpKind::Ident {
                    assert_ne!(
                        classify(&t.text, Language::new(v, true)),
                        WordClass::Reserved,
                        "{}",
                        t.text
                    );
                }
            }
        }
    }
}
