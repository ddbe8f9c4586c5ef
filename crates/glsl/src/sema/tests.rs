//! Unit tests of the analyzer, through [`crate::compile`].

use crate::diag::Code;
use crate::ir::Stage;
use crate::{compile, CompileOptions, Shader};

fn frag(src: &str) -> Shader {
    compile(&[src], &CompileOptions::new(Stage::Fragment))
}

fn vert(src: &str) -> Shader {
    compile(&[src], &CompileOptions::new(Stage::Vertex))
}

fn codes(s: &Shader) -> Vec<Code> {
    s.diagnostics
        .iter()
        .filter(|d| d.is_error())
        .map(|d| d.code)
        .collect()
}

#[track_caller]
fn ok(s: Shader) {
    assert!(s.ok(), "expected success:\n{}", s.info_log());
}

#[track_caller]
fn fails(s: Shader, code: Code) {
    assert!(!s.ok(), "expected failure");
    assert_eq!(codes(&s), vec![code], "{}", s.info_log());
}

#[test]
fn builtin_envs_are_clean() {
    use crate::lang::{Profile, Version};
    for v in Version::ALL {
        for profile in [Profile::Core, Profile::Compatibility] {
            let mut lang = crate::Language::new(v, true);
            lang.profile = profile;
            for st in [Stage::Vertex, Stage::Fragment] {
                let env = super::builtin_env(lang, st);
                assert!(
                    env.diagnostics.is_empty(),
                    "{v:?} {profile:?} {st:?}: {:?}",
                    env.diagnostics
                );
                assert!(env.functions.len() > 100);
                assert!(env.lookup("gl_MaxDrawBuffers").is_some());
                let compat = profile == Profile::Compatibility || v < Version::V140;
                assert_eq!(env.lookup("gl_MaxLights").is_some(), compat);
            }
        }
    }
}

#[test]
fn removed_builtins_name_their_replacement() {
    let s = vert("#version 150\nin vec4 p;\nvoid main() { gl_Position = gl_Vertex + p; }\n");
    let log = s.info_log();
    assert!(!s.ok());
    assert!(
        log.contains("`gl_Vertex' is removed in the core profile of GLSL 1.40 and later")
            && log.contains("declare an `in vec4' vertex input instead"),
        "{log}"
    );
    let s = vert("#version 150 compatibility\nvoid main() { gl_Position = ftransform(); }\n");
    assert!(s.ok(), "{}", s.info_log());
    let s = frag("#version 120\nvoid main() { gl_FragColor = vec4(trunc(1.5)); }\n");
    assert!(
        s.info_log().contains("`trunc' requires GLSL 1.30"),
        "{}",
        s.info_log()
    );
}

#[test]
fn glsl130_builtins_type_check_and_fold() {
    let s = frag(
        "#version 130
uniform sampler2D s;
uniform isampler2D is;
uniform sampler2DArray arr;
uniform samplerCubeShadow cs;
const float t = trunc(-2.5) + round(2.5) + roundEven(2.5);
const ivec2 m = clamp(ivec2(-5, 9), 0, 4) + abs(ivec2(-1)) + sign(ivec2(-7, 0));
void main() {
    vec4 a = texture(s, vec2(0.5)) + textureLod(s, vec2(0.5), 1.0) + textureProj(s, vec3(1.0));
    ivec4 b = texture(is, vec2(0.5)) + texelFetch(is, ivec2(0), 0);
    ivec2 size = textureSize(s, 0);
    vec4 c = texture(arr, vec3(0.5, 0.5, 1.0)) + textureOffset(s, vec2(0.5), ivec2(1, -1));
    float d = texture(cs, vec4(1.0)) + textureGrad(s, vec2(0.0), vec2(1.0), vec2(1.0)).x;
    bvec2 n = isnan(vec2(0.0, sinh(1.0)));
    float whole;
    float f = modf(1.5, whole);
    vec2 sel = mix(vec2(0.0), vec2(1.0), bvec2(true, false));
    gl_FragColor = a + vec4(b) + vec4(size, t, float(m.x)) + c + vec4(d, f, sel) + vec4(n, gl_FragCoord.xy);
}
",
    );
    assert!(s.ok(), "{}", s.info_log());
    let m = s.module.as_ref().unwrap();
    let value = |name: &str| {
        m.globals
            .iter()
            .find(|g| g.name == name)
            .and_then(|g| g.init.clone())
            .map(|c| c.components)
    };
    use crate::ir::ConstScalar::{Float, Int};
    // -2 + 3 (half away from zero) + 2 (half to even).
    assert_eq!(value("t"), Some(vec![Float(3.0)]));
    // clamp + abs + sign: (0 + 1 - 1, 4 + 1 + 0).
    assert_eq!(value("m"), Some(vec![Int(0), Int(5)]));
    // inverse is 1.40, determinant 1.50.
    let s = frag("#version 140\nvoid main() { mat2 i = inverse(mat2(2.0)); gl_FragColor = vec4(i[0], i[1]); }\n");
    assert!(s.ok(), "{}", s.info_log());
    let s = frag("#version 140\nvoid main() { gl_FragColor = vec4(determinant(mat2(2.0))); }\n");
    assert!(!s.ok());
    let s = frag("#version 150\nconst float d = determinant(mat3(2.0));\nout vec4 o;\nvoid main() { o = vec4(d); }\n");
    assert!(s.ok() || s.info_log().contains("out"), "{}", s.info_log());
}
#[test]
fn unsigned_builtins_type_check_and_fold() {
    let s = frag(
        "#version 330
uniform usampler2D us;
uniform usampler2DArray ua;
const uvec2 m = min(uvec2(0x80000000u, 3u), 1u) + max(uvec2(1u), uvec2(0xfffffff0u, 0u));
const uint c = clamp(5u, 9u, 4u);
const bvec2 lt = lessThan(uvec2(0x80000000u, 1u), uvec2(1u, 2u));
const uint bits = floatBitsToUint(1.0);
const float one = uintBitsToFloat(0x3f800000u);
const float denormal = uintBitsToFloat(1u);
void main() {
    uvec4 t = texture(us, vec2(0.5)) + texelFetch(ua, ivec3(0), 0) + textureLod(us, vec2(0.0), 1.0);
    ivec2 size = textureSize(us, 0);
    bvec3 e = equal(uvec3(t.xyz), uvec3(1u));
    gl_FragColor = vec4(t) + vec4(size, 0.0, 0.0) + vec4(e, 1.0);
}
",
    );
    assert!(s.ok(), "{}", s.info_log());
    let m = s.module.as_ref().unwrap();
    let value = |name: &str| {
        m.globals
            .iter()
            .find(|g| g.name == name)
            .and_then(|g| g.init.clone())
            .map(|c| c.components)
    };
    use crate::ir::ConstScalar::{Bool, Float, Uint};
    // Unsigned: min(0x80000000, 1) is 1; max(1, 0xfffffff0) is 0xfffffff0.
    assert_eq!(value("m"), Some(vec![Uint(0xffff_fff1), Uint(2)]));
    assert_eq!(value("c"), Some(vec![Uint(4)]));
    assert_eq!(value("lt"), Some(vec![Bool(false), Bool(true)]));
    assert_eq!(value("bits"), Some(vec![Uint(0x3f80_0000)]));
    assert_eq!(value("one"), Some(vec![Float(1.0)]));
    assert_eq!(value("denormal"), Some(vec![Float(0.0)]));
    // 1.30 has the unsigned min but not the bit casts. No version of
    // these has an unsigned abs or a uint mix with a bool selector: the
    // uints convert to float and the float overload returns a float (and
    // int does not convert to uint before GLSL 4.00, so `min(1u, 2)` is
    // the float min too).
    let s = frag("#version 130\nvoid main() { uint u = min(1u, 2u); gl_FragColor = vec4(u); }\n");
    assert!(s.ok(), "{}", s.info_log());
    for bad in [
        "#version 130\nvoid main() { gl_FragColor = vec4(floatBitsToUint(1.0)); }\n",
        "#version 330\nvoid main() { uint u = abs(1u); gl_FragColor = vec4(u); }\n",
        "#version 330\nvoid main() { uint u = mix(1u, 2u, true); gl_FragColor = vec4(u); }\n",
        "#version 330\nvoid main() { uint u = min(1u, 2); gl_FragColor = vec4(u); }\n",
    ] {
        assert!(!frag(bad).ok(), "{bad}");
    }
    let s = frag("#version 330\nvoid main() { float f = min(1u, 2); gl_FragColor = vec4(f); }\n");
    assert!(s.ok(), "{}", s.info_log());
}

#[test]
fn packing_builtins_need_the_extension_and_glsl_130() {
    const EXT: &str = "#extension GL_ARB_shading_language_packing : enable\n";
    let s = vert(&format!(
        "#version 130\n{EXT}uniform vec4 v; uniform uint u;
const uint h = packHalf2x16(vec2(1.0, -2.0));
const vec4 s = unpackSnorm4x8(0x7f81u);
void main() {{
    uint a = packUnorm2x16(v.xy) + packSnorm2x16(v.zw) + packUnorm4x8(v) + packSnorm4x8(v);
    vec2 b = unpackUnorm2x16(u) + unpackSnorm2x16(u) + unpackHalf2x16(u);
    gl_Position = vec4(b, float(a), 1.0) + unpackUnorm4x8(u) + s + vec4(h);
}}
"
    ));
    assert!(s.ok(), "{}", s.info_log());
    let m = s.module.as_ref().unwrap();
    let init = |name: &str| {
        m.globals
            .iter()
            .find(|g| g.name == name)
            .and_then(|g| g.init.clone())
    };
    use crate::ir::ConstScalar::{Float, Uint};
    assert_eq!(init("h").unwrap().components, vec![Uint(0xc000_3c00)]);
    assert_eq!(
        init("s").unwrap().components,
        vec![Float(-1.0), Float(1.0), Float(0.0), Float(0.0)]
    );
    // Every stage has them.
    let g = compile(
        &[&format!("#version 150\n{EXT}layout(points) in; layout(points, max_vertices = 1) out;\nvoid main() {{ gl_Position = vec4(unpackHalf2x16(packHalf2x16(vec2(0.5))), 0.0, 1.0); EmitVertex(); }}\n")],
        &CompileOptions::new(Stage::Geometry),
    );
    assert!(g.ok(), "{}", g.info_log());
    ok(frag(&format!(
        "#version 130\n{EXT}uniform uint u;\nvoid main() {{ gl_FragColor = unpackUnorm4x8(u); }}\n"
    )));
    // Without the extension the names are not declared, and the note
    // names the extension; the wrong argument type is no overload.
    let s = frag("#version 130\nuniform vec2 v;\nvoid main() { gl_FragColor = vec4(float(packHalf2x16(v))); }\n");
    fails(s, Code::Undeclared);
    let s = frag("#version 330\nuniform vec2 v;\nvoid main() { gl_FragColor = vec4(float(packUnorm2x16(v))); }\n");
    assert!(
        s.info_log()
            .contains("#extension GL_ARB_shading_language_packing"),
        "{}",
        s.info_log()
    );
    assert!(!frag(&format!("#version 130\n{EXT}void main() {{ gl_FragColor = vec4(float(packUnorm4x8(vec2(0.0)))); }}\n")).ok());
    // 1.10 accepts the directive and defines the macro; its functions
    // need `uint`, so they are 1.30's.
    ok(frag(&format!("#version 110\n{EXT}#if GL_ARB_shading_language_packing != 1\n#error no macro\n#endif\nvoid main() {{ gl_FragColor = vec4(0.0); }}\n")));
    assert!(!frag(&format!(
        "#version 120\n{EXT}void main() {{ gl_FragColor = unpackUnorm4x8(0); }}\n"
    ))
    .ok());
}

#[test]
fn cube_map_array_samplers_need_their_extension() {
    const EXT: &str = "#extension GL_ARB_texture_cube_map_array : require\n";
    let body = "uniform samplerCubeArray s;
uniform samplerCubeArrayShadow z;
uniform isamplerCubeArray i;
uniform usamplerCubeArray u;
in vec4 p;
void main() {
    ivec3 n = textureSize(s, 0) + textureSize(z, 1) + textureSize(i, 0) + textureSize(u, 2);
    vec4 c = texture(s, p) + textureLod(s, p, 1.0) + textureGrad(s, p, p.xyz, p.zyx);
    c += vec4(texture(i, p)) + vec4(textureLod(u, p, 0.0)) + vec4(textureGrad(i, p, p.xyz, p.xyz));
    gl_Position = c + vec4(n, texture(z, p, 0.5));
}
";
    ok(vert(&format!("#version 130\n{EXT}{body}")));
    let s = compile(
        &[&format!("#version 150\n{EXT}uniform samplerCubeArray s;\nout vec4 o;\nvoid main() {{ o = texture(s, vec4(0.0), 2.0); }}\n")],
        &CompileOptions::new(Stage::Fragment),
    );
    assert!(s.ok(), "{}", s.info_log());
    // Without the extension the type names are identifiers.
    assert!(!vert(&format!("#version 130\n{body}")).ok());
    ok(vert("#version 130\nint samplerCubeArray = 1;\nvoid main() { gl_Position = vec4(samplerCubeArray); }\n"));
    // Before 1.30 the directive and macro only.
    ok(vert(&format!("#version 110\n{EXT}#if GL_ARB_texture_cube_map_array != 1\n#error no macro\n#endif\nvoid main() {{ gl_Position = vec4(0.0); }}\n")));
    assert!(!vert(&format!("#version 120\n{EXT}uniform samplerCubeArray s;\nvoid main() {{ gl_Position = vec4(0.0); }}\n")).ok());
    // What the extension does not have: a bias outside the fragment
    // stage, offsets, projections, fetches, a bias on the shadow form,
    // a vec3 coordinate.
    for bad in [
        "uniform samplerCubeArray s;\nvoid main() { gl_Position = texture(s, vec4(0.0), 1.0); }",
        "uniform samplerCubeArray s;\nvoid main() { gl_Position = textureOffset(s, vec4(0.0), ivec3(0)); }",
        "uniform samplerCubeArray s;\nvoid main() { gl_Position = textureProj(s, vec4(0.0)); }",
        "uniform samplerCubeArray s;\nvoid main() { gl_Position = texelFetch(s, ivec4(0), 0); }",
        "uniform samplerCubeArray s;\nvoid main() { gl_Position = texture(s, vec3(0.0)); }",
        "uniform samplerCubeArrayShadow s;\nvoid main() { gl_Position = vec4(texture(s, vec4(0.0))); }",
        "uniform samplerCubeArrayShadow s;\nvoid main() { gl_Position = vec4(textureLod(s, vec4(0.0), 0.0, 1.0)); }",
    ] {
        let s = vert(&format!("#version 130\n{EXT}{bad}\n"));
        assert!(!s.ok(), "{bad}");
    }
}

#[test]
fn empty_shaders_are_syntax_errors() {
    // GLSL's translation_unit is one or more external declarations.
    fails(frag(""), Code::Syntax);
    fails(frag("#version 120\n// only a comment\n"), Code::Syntax);
    ok(frag("uniform float u;"));
}

#[test]
fn sources_over_the_size_limit_are_refused_whole() {
    let max = crate::limits::MAX_SOURCE_BYTES;
    let main = "void main() {}\n";
    // One byte over, in one string or spread over two: one error, nothing
    // else looked at.
    let over = "\n".repeat(max + 1 - main.len()) + main;
    for s in [
        frag(&over),
        compile(
            &[&over[..max / 2], &over[max / 2..]],
            &CompileOptions::new(Stage::Fragment),
        ),
    ] {
        assert_eq!(codes(&s), vec![Code::Unsupported]);
        assert_eq!(s.diagnostics[0].message, crate::source_too_large_message());
        assert!(
            s.info_log().contains(&format!("larger than {max} bytes")),
            "{}",
            s.info_log()
        );
    }
}

#[test]
fn minimal_shaders() {
    ok(frag("void main() { gl_FragColor = vec4(1.0); }"));
    ok(vert("void main() { gl_Position = ftransform(); }"));
}

#[test]
fn no_implicit_conversion_in_110() {
    let s = frag("void main() { float f = 1; gl_FragColor = vec4(f); }");
    fails(s, Code::TypeMismatch);
    let s = frag("void main() { float f = 1; gl_FragColor = vec4(f); }");
    assert!(s.diagnostics[0]
        .message
        .contains("GLSL 1.10 has no implicit conversions"));
    ok(frag(
        "#version 120\nvoid main() { float f = 1; gl_FragColor = vec4(f); }",
    ));
}

#[test]
fn undeclared_with_suggestion() {
    let s = frag("void main() { vec4 color = vec4(1.0); gl_FragColor = colour; }");
    fails(s, Code::Undeclared);
    let s = frag("void main() { vec4 color = vec4(1.0); gl_FragColor = colour; }");
    assert_eq!(
        s.diagnostics[0].notes,
        vec!["did you mean `color'?".to_string()]
    );
}

/// A chain of `n` functions, each calling the one before, called from
/// `main`: `n + 1` functions on the call stack at its deepest.
fn call_chain(n: u32) -> String {
    let mut src = String::from("float f0(float x) { return x + 0.25; }\n");
    for i in 1..n {
        src.push_str(&format!(
            "float f{i}(float x) {{ return f{}(x); }}\n",
            i - 1
        ));
    }
    src + &format!("void main() {{ gl_FragColor = vec4(f{}(0.0)); }}\n", n - 1)
}

#[test]
fn call_chains_deeper_than_the_limit_are_refused() {
    let max = crate::limits::MAX_CALL_DEPTH;
    ok(frag(&call_chain(max - 1)));
    let s = frag(&call_chain(max));
    fails(s.clone(), Code::BadControlFlow);
    let d = &s.diagnostics[0];
    assert_eq!(
        d.message,
        format!(
            "function calls nested too deeply: `main' starts a chain of {} nested calls; \
             the limit is {max}",
            max + 1
        )
    );
    // A chain that main never reaches is refused too, once, where it
    // passes the limit; so is a long one, quickly.
    let s = frag(&call_chain(4000).replace(
        "void main() { gl_FragColor = vec4(f3999(0.0)); }",
        "void main() {}",
    ));
    fails(s.clone(), Code::BadControlFlow);
    assert!(s.diagnostics[0]
        .message
        .contains(&format!("`f{max}' starts a chain of {}", max + 1)));
}

#[test]
fn call_chains_across_shader_objects_are_bounded_at_link() {
    // Two objects, each within the limit, whose chain together is not.
    let max = crate::limits::MAX_CALL_DEPTH;
    let half = max / 2 + 1;
    let chain = |from: u32, to: u32, last: &str| {
        let mut src = format!("float g{to}(float x);\n");
        src += &format!("float g{from}(float x) {{ return {last}; }}\n");
        for i in from + 1..to {
            src += &format!("float g{i}(float x) {{ return g{}(x); }}\n", i - 1);
        }
        src
    };
    let low = frag(&chain(0, half, "x"));
    let high = frag(&format!(
        "float g{}(float x);\n{}void main() {{ gl_FragColor = vec4(g{}(1.0)); }}\n",
        half - 1,
        chain(half, 2 * half, &format!("g{}(x)", half - 1)),
        2 * half - 1
    ));
    ok(low.clone());
    ok(high.clone());
    let p = crate::link::link(&[&low, &high]);
    assert!(!p.ok());
    assert!(
        p.info_log().contains(&format!(
            "`main' starts a chain of {} nested calls across its shader objects; the limit is {max}",
            max + 1
        )),
        "{}",
        p.info_log()
    );
    // Within the limit, the same two objects link.
    let short = frag(&format!(
        "float g{}(float x);\nvoid main() {{ gl_FragColor = vec4(g{}(1.0)); }}\n",
        half - 1,
        half - 1
    ));
    assert!(crate::link::link(&[&low, &short]).ok());
}

#[test]
fn long_undeclared_names_get_no_suggestion() {
    // Two long names one letter apart: comparing them would cost the
    // product of their lengths, so no note is looked for.
    let a = "v".repeat(60_000);
    let src = format!("void main() {{ float {a}x = 1.0; gl_FragColor = vec4({a}y); }}");
    let s = frag(&src);
    assert_eq!(codes(&s), vec![Code::Undeclared], "{}", s.info_log());
    assert!(
        s.diagnostics[0].notes.is_empty(),
        "{:?}",
        s.diagnostics[0].notes
    );
}

#[test]
fn suggestions_are_bounded_per_shader() {
    // Every undeclared name is reported; only the first
    // MAX_SUGGESTIONS get a "did you mean" search.
    let n = crate::limits::MAX_SUGGESTIONS as usize + 10;
    let uses: String = (0..n)
        .map(|_| "colr; ")
        .map(|u| format!("f = {u}"))
        .collect();
    let src =
        format!("void main() {{ float color = 1.0; float f; {uses} gl_FragColor = vec4(f); }}");
    let s = frag(&src);
    let undeclared: Vec<_> = s
        .diagnostics
        .iter()
        .filter(|d| d.code == Code::Undeclared)
        .collect();
    assert_eq!(undeclared.len(), n, "{}", s.info_log());
    let noted = undeclared.iter().filter(|d| !d.notes.is_empty()).count();
    assert_eq!(noted, crate::limits::MAX_SUGGESTIONS as usize);
    assert_eq!(
        undeclared[0].notes,
        vec!["did you mean `color'?".to_string()]
    );
}

#[test]
fn builtin_from_newer_version() {
    let s =
        vert("void main() { mat2 m = transpose(mat2(1.0)); gl_Position = vec4(m[0], 0.0, 1.0); }");
    fails(s, Code::VersionTooLow);
}

#[test]
fn one_error_per_mistake() {
    let s = frag("void main() { gl_FragColor = vec4(nope + 1.0) * 2.0 + vec4(nope2); }");
    assert_eq!(
        codes(&s),
        vec![Code::Undeclared, Code::Undeclared],
        "{}",
        s.info_log()
    );
}

#[test]
fn operators() {
    ok(frag("void main() { mat3 m = mat3(1.0); vec3 v = m * vec3(1.0); v = v * m; gl_FragColor = vec4(v, 1.0); }"));
    fails(
        frag("void main() { vec3 v = vec3(1.0) * vec2(1.0); }"),
        Code::TypeMismatch,
    );
    fails(frag("void main() { int i = 5 % 2; }"), Code::ReservedWord);
    fails(
        frag("void main() { bool b = vec2(1.0) < vec2(2.0); }"),
        Code::TypeMismatch,
    );
    fails(frag("void main() { bool b = !1; }"), Code::TypeMismatch);
    ok(frag(
        "void main() { bool b = true ^^ false; if (b) discard; }",
    ));
}

#[test]
fn lvalues() {
    fails(
        frag("uniform float u; void main() { u = 1.0; }"),
        Code::ReadOnly,
    );
    fails(
        frag("varying vec4 v; void main() { v = vec4(1.0); }"),
        Code::ReadOnly,
    );
    ok(vert(
        "varying vec4 v; void main() { v = vec4(1.0); gl_Position = v; }",
    ));
    fails(
        frag("void main() { vec4 v; v.xx = vec2(1.0); }"),
        Code::NotAnLvalue,
    );
    fails(
        frag("void main() { const float c = 1.0; c = 2.0; }"),
        Code::ReadOnly,
    );
    fails(
        frag("void f(out float x) { x = 1.0; } void main() { f(1.0); }"),
        Code::NotAnLvalue,
    );
}

#[test]
fn constructors() {
    ok(frag(
        "void main() { vec4 v = vec4(vec2(1.0), 1.0, 1.0); mat2 m = mat2(v); gl_FragColor = v; }",
    ));
    fails(
        frag("void main() { vec3 v = vec3(1.0, 2.0, 3.0, 4.0); }"),
        Code::BadConstructor,
    );
    fails(
        frag("void main() { vec3 v = vec3(vec2(1.0)); }"),
        Code::BadConstructor,
    );
    fails(
        frag("void main() { mat3 m = mat3(mat2(1.0)); }"),
        Code::VersionTooLow,
    );
    ok(frag(
        "#version 120\nvoid main() { mat3 m = mat3(mat2(1.0)); float a[2] = float[](1, 2); }",
    ));
    fails(
        frag("struct S { float f; }; void main() { S s = S(1); }"),
        Code::TypeMismatch,
    );
}

#[test]
fn indexing_and_arrays() {
    fails(
        frag("void main() { float a[2]; a[2] = 1.0; }"),
        Code::IndexOutOfRange,
    );
    fails(
        frag("void main() { vec4 v; v[-1] = 1.0; }"),
        Code::IndexOutOfRange,
    );
    ok(frag("#version 120\nvoid main() { float a[3]; float b[a.length()]; gl_FragColor = vec4(b.length()); }"));
    fails(frag("void main() { float a[0]; }"), Code::BadArraySize);
    ok(frag(
        "uniform float a[]; void main() { gl_FragColor = vec4(a[3]); }",
    ));
    fails(
        frag("uniform float a[]; uniform int i; void main() { gl_FragColor = vec4(a[i]); }"),
        Code::BadArraySize,
    );
}

#[test]
fn functions() {
    ok(frag(
        "float f(float x); void main() { gl_FragColor = vec4(f(1.0)); }",
    ));
    fails(
        frag("float f(float x) { return x; } int f(float x) { return 1; } void main() {}"),
        Code::Redeclared,
    );
    fails(
        frag("float f(float x) { return f(x); } void main() { f(1.0); }"),
        Code::BadControlFlow,
    );
    fails(
        frag("void f() { return 1.0; } void main() {}"),
        Code::BadReturn,
    );
    fails(
        frag("float f() { return; } void main() {}"),
        Code::BadReturn,
    );
    fails(frag("int main() { return 0; }"), Code::TypeMismatch);
    fails(vert("void main() { discard; }"), Code::StageMismatch);
    fails(frag("void main() { break; }"), Code::BadControlFlow);
}

#[test]
fn overloads() {
    let s = frag("#version 120\nvoid f(float a, int b) {} void f(int a, float b) {} void main() { f(1, 1); }");
    fails(s, Code::AmbiguousOverload);
    let s = frag("void f(float a) {} void main() { f(vec2(1.0)); }");
    fails(s, Code::NoMatchingOverload);
    let s = frag("void f(float a) {} void main() { f(vec2(1.0)); }");
    assert!(
        s.diagnostics[0]
            .notes
            .iter()
            .any(|n| n.contains("void f(float)")),
        "{:?}",
        s.diagnostics
    );
}

#[test]
fn user_function_hides_builtin() {
    let s = frag("float sin(int x) { return 1.0; } void main() { gl_FragColor = vec4(sin(1.0)); }");
    fails(s, Code::NoMatchingOverload);
}

#[test]
fn loops_and_scopes() {
    ok(frag(
        "void main() { for (int i = 0; i < 4; i++) { gl_FragColor = vec4(float(i)); } }",
    ));
    ok(frag(
        "void main() { int i = 0; while (i < 3) i++; do { i--; } while (i > 0); }",
    ));
    fails(
        frag("void main() { do { int k = 1; } while (k > 0); }"),
        Code::Undeclared,
    );
    fails(frag("void main() { int x; int x; }"), Code::Redeclared);
    fails(
        frag("void f(float a) { float a; } void main() {}"),
        Code::Redeclared,
    );
    fails(
        frag("void main() { if (1.0) discard; }"),
        Code::TypeMismatch,
    );
}

#[test]
fn loop_lowering() {
    let s = frag("void main() { for (int i = 0; i < 4; i++) {} }");
    let m = s.module.expect("compiles");
    let main = &m.functions[m.main().expect("main").0 as usize];
    let body = main.body.as_ref().expect("body");
    match &body[0] {
        crate::ir::Stmt::Block(b) => {
            assert!(matches!(b[0], crate::ir::Stmt::Declare { .. }));
            match &b[1] {
                crate::ir::Stmt::Loop {
                    body, continuing, ..
                } => {
                    assert!(matches!(body[0], crate::ir::Stmt::If { .. }));
                    assert_eq!(continuing.len(), 1);
                }
                other => panic!("{other:?}"),
            }
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn declarations() {
    fails(
        frag("attribute vec4 a; void main() {}"),
        Code::StageMismatch,
    );
    fails(
        vert("attribute vec4 a[2]; void main() {}"),
        Code::TypeMismatch,
    );
    fails(vert("varying bool b; void main() {}"), Code::TypeMismatch);
    fails(frag("sampler2D s; void main() {}"), Code::BadQualifier);
    fails(frag("void main() { uniform float u; }"), Code::BadQualifier);
    fails(frag("float gl_foo; void main() {}"), Code::Redeclared);
    fails(frag("const float c; void main() {}"), Code::NotConstant);
    fails(
        frag("uniform float u = 1.0; void main() {}"),
        Code::VersionTooLow,
    );
    ok(frag("#version 120\nuniform float u = 1.0; void main() {}"));
    ok(frag(
        "varying vec4 gl_TexCoord[2]; void main() { gl_FragColor = gl_TexCoord[1]; }",
    ));
    fails(
        frag("void main() { gl_FragColor = gl_TexCoord[gl_MaxTextureCoords]; }"),
        Code::IndexOutOfRange,
    );
    ok(frag(
        "uniform vec4 u; vec4 g = u * 2.0; void main() { gl_FragColor = g; }",
    ));
}

#[test]
fn frag_color_and_data() {
    let s = frag("void main() { gl_FragColor = vec4(1.0); gl_FragData[0] = vec4(1.0); }");
    assert!(!s.ok());
}

#[test]
fn const_folding_of_sizes() {
    ok(frag(
        "const int n = 2 * 3; float a[n]; void main() { gl_FragColor = vec4(a[5]); }",
    ));
    fails(
        frag("uniform int n; float a[n]; void main() {}"),
        Code::NotConstant,
    );
}

/// Runs the piglit compiler tests listed in /tmp/glslparser_list.txt
/// (`cargo test -p shaderbox-glsl piglit -- --ignored --nocapture`).
#[test]
#[ignore]
fn piglit() {
    let root = "/tmp/piglit/usr/lib/x86_64-linux-gnu/piglit/";
    let Ok(list) = std::fs::read_to_string("/tmp/glslparser_list.txt") else {
        return;
    };
    let (mut pass, mut total, mut link_only) = (0, 0, 0);
    let mut bad = Vec::new();
    for line in list.lines() {
        let Some((_, cmd)) = line.split_once('\t') else {
            continue;
        };
        let parts: Vec<&str> = cmd.split('\'').skip(1).step_by(2).collect();
        let (Some(file), Some(expect)) = (parts.get(1), parts.get(2)) else {
            continue;
        };
        if parts.contains(&"--check-link") {
            link_only += 1;
        }
        let Ok(src) = std::fs::read_to_string(format!("{root}{file}")) else {
            continue;
        };
        let stage = if file.ends_with(".vert") {
            Stage::Vertex
        } else {
            Stage::Fragment
        };
        let sh = compile(&[&src], &CompileOptions::new(stage));
        total += 1;
        if sh.ok() == (*expect == "pass") {
            pass += 1;
        } else {
            let first = sh.info_log().lines().next().unwrap_or("").to_string();
            bad.push(format!("{expect} {file}: {first}"));
        }
    }
    for b in &bad {
        println!("{b}");
    }
    println!("piglit: {pass}/{total} ({link_only} use --check-link)");
}

fn v130(body: &str) -> Shader {
    frag(&format!("#version 130\n{body}"))
}

#[test]
fn unsigned_types_literals_and_conversions() {
    ok(v130(
        "void main() { uint a = 3u; uvec2 b = uvec2(a, 0xffffffffU); \
         float f = a; vec2 g = b; int i = int(a); uint u = uint(-1); \
         uvec3 c = uvec3(vec3(1.5)); bool t = bool(a); gl_FragColor = vec4(f, g, float(i + int(u + c.x)) + float(t)); }",
    ));
    // No implicit conversion between int and uint.
    fails(v130("void main() { uint a = 1; }"), Code::TypeMismatch);
    fails(v130("void main() { int a = 1u; }"), Code::TypeMismatch);
    fails(v130("void main() { uint a = 1u + 1; }"), Code::TypeMismatch);
    // The suffix and the type need 1.30.
    let s = frag("void main() { int a = 1u; }");
    assert!(!s.ok());
    assert!(s.info_log().contains("needs GLSL 1.30"), "{}", s.info_log());
    // Literals must fit 32 bits from 1.30 on; 0xffffffff is still an int.
    fails(
        v130("int f() { return int(0x1ffffffff); }"),
        Code::LexBadNumber,
    );
    fails(
        v130("uint f() { return 0x100000000u; }"),
        Code::LexBadNumber,
    );
    ok(v130(
        "int f() { return 0xffffffff; } void main() { gl_FragColor = vec4(f()); }",
    ));
    ok(v130(
        "uint f() { return 4294967295u; } void main() { gl_FragColor = vec4(f()); }",
    ));
}

#[test]
fn unsigned_constants_fold() {
    let s = v130(
        "const uint a = 0xfffffff0u + 0x20u; const int b = int(0xffffffffu); \
         const uint c = uint(-2); const float d = float(4000000000u); \
         float x[a]; float y[b + 2]; \
         void main() { gl_FragColor = vec4(x.length(), y.length(), float(c), d); }",
    );
    ok(s.clone());
    let text = s.module.unwrap().to_string();
    assert!(
        text.contains("vec4(16.0, 1.0, 4294967300.0, 4000000000.0)"),
        "{text}"
    );
}

#[test]
fn integer_operators_follow_1_30() {
    ok(v130(
        "void main() { int i = 7; uint u = 9u; ivec3 iv = ivec3(1); uvec2 uv = uvec2(2u); \
         i = i % 3 & 5 | 6 ^ ~i; u = u % 4u; iv = iv % 2; iv = 5 & iv; iv <<= 1; iv >>= iv; \
         uv = uv << 1; uv = uv >> uvec2(1u, 2u); i = i << u; u = u >> i; iv = iv << 2u; \
         i %= 2; u &= 3u; u |= u; u ^= 1u; uv %= 3u; \
         gl_FragColor = vec4(float(i), float(u), vec2(uv)); }",
    ));
    // Bitwise and `%' need one signedness.
    fails(v130("void main() { int i = 1 & 1u; }"), Code::TypeMismatch);
    fails(v130("void main() { uint u = 1u % 2; }"), Code::TypeMismatch);
    // Not on floats or bools; no vectors of different sizes.
    fails(
        v130("void main() { float f = 1.0 % 2.0; }"),
        Code::TypeMismatch,
    );
    fails(
        v130("void main() { bool b = true & false; }"),
        Code::TypeMismatch,
    );
    fails(
        v130("void main() { ivec2 a = ivec2(1) | ivec3(1).xyz.xy.xyy; }"),
        Code::TypeMismatch,
    );
    fails(v130("void main() { float f = ~1.0; }"), Code::TypeMismatch);
    // A scalar shifted by a vector; the result is the left operand's type.
    fails(
        v130("void main() { int i = 1 << ivec2(1); }"),
        Code::TypeMismatch,
    );
    fails(
        v130("void main() { uint u = 1u << 1; uint v = 1 << 1u; }"),
        Code::TypeMismatch,
    );
    // Compound assignments keep the target's type.
    fails(
        v130("void main() { int i = 1; i &= ivec2(1); }"),
        Code::TypeMismatch,
    );
    // Reserved before 1.30.
    let s = frag("#version 120\nvoid main() { int a = 7; a %= 2; }");
    assert!(!s.ok());
    assert!(
        s.info_log()
            .contains("operator `%=' needs GLSL 1.30 (this shader is GLSL 1.20)"),
        "{}",
        s.info_log()
    );
}

#[test]
fn integer_operators_fold() {
    let s = v130(
        "const int a = -7 % 3; const int b = -8 >> 1; const uint c = 0x80000000u >> 31; \
         const int d = 1 << 33; const uint e = ~0u ^ 0xffu; const int f = (6 & 3) | 8; \
         const uint g = 7u % 0x10u; const int h = -2147483647 - 1; const int k = h % -1; \
         void main() { gl_FragColor = vec4(float(a + b), float(c), float(d + f + k), float(e + g)); }",
    );
    let text = s.module.expect("compiles").to_string();
    // a = -1, b = -4; c = 1; d = 2 (33 mod 32), f = 10, k = 0;
    // e = 0xffffff00 + 7.
    assert!(
        text.contains("vec4(-5.0, 1.0, 12.0, 4.2949670e9)")
            || text.contains("vec4(-5.0, 1.0, 12.0, 4294967000.0)"),
        "{text}"
    );
}

#[test]
fn switch_statements() {
    let s = v130(
        "uniform int x; void main() { int r = 0; \
         switch (x) { case 0: case 1: r = 1; case 2: { r += 2; break; } default: r = 5; break; \
         case 3 + 4: for (int i = 0; i < 3; i++) { if (i == 1) break; r++; } } \
         switch (uint(x)) { case 1u: r = 2; } switch (x) { } \
         gl_FragColor = vec4(float(r)); }",
    );
    ok(s.clone());
    let text = s.module.unwrap().to_string();
    assert!(text.contains("case 0:\n"), "{text}");
    assert!(text.contains("case 1u:\n"), "{text}");
    // Selector, labels and their types.
    fails(
        v130("void main() { switch (1.0) { case 1: break; } }"),
        Code::TypeMismatch,
    );
    fails(
        v130("void main() { switch (ivec2(1)) { default: break; } }"),
        Code::TypeMismatch,
    );
    fails(
        v130("void main() { uint x = 1u; switch (x) { case 1: break; } }"),
        Code::TypeMismatch,
    );
    fails(
        v130("uniform int u; void main() { switch (1) { case u: break; } }"),
        Code::NotConstant,
    );
    fails(
        v130("void main() { switch (1) { case 1.0: break; } }"),
        Code::NotConstant,
    );
    // Duplicates, two defaults, misplaced labels and statements.
    fails(
        v130("void main() { switch (1) { case 1: break; case 0 + 1: break; } }"),
        Code::BadControlFlow,
    );
    fails(
        v130("void main() { switch (1) { default: break; default: break; } }"),
        Code::BadControlFlow,
    );
    fails(
        v130("void main() { switch (1) { int a = 1; case 1: break; } }"),
        Code::BadControlFlow,
    );
    fails(v130("void main() { case 1: ; }"), Code::BadControlFlow);
    fails(
        v130("void main() { switch (1) { case 0: while (true) { default: break; } } }"),
        Code::BadControlFlow,
    );
    fails(
        v130("void main() { switch (1) { case 0: } }"),
        Code::BadControlFlow,
    );
    fails(
        v130("void main() { switch (1) { case 0: break; default: } }"),
        Code::BadControlFlow,
    );
    ok(v130("void main() { switch (1) { case 0: ; } }"));
    // `break' leaves a switch; `continue' needs a loop.
    fails(
        v130("void main() { switch (1) { case 0: continue; } }"),
        Code::BadControlFlow,
    );
    ok(v130(
        "void main() { for (;;) { switch (1) { case 0: continue; default: break; } break; } }",
    ));
    // Declarations of one case are visible in the next (one scope), not
    // after the switch.
    ok(v130(
        "void main() { switch (1) { case 0: int a = 1; case 1: a = 2; break; } }",
    ));
    fails(
        v130("void main() { switch (1) { case 0: int a = 1; break; } a = 2; }"),
        Code::Undeclared,
    );
    // Before 1.30 the words are reserved or plain identifiers.
    assert!(!frag("void main() { switch (1) { } }").ok());
}

#[test]
fn uint_indices() {
    ok(v130(
        "uniform float a[4]; uniform uint k; void main() { vec4 v = vec4(1.0); \
         gl_FragColor = vec4(a[k], a[2u], v[k], a[k & 1u]); }",
    ));
    fails(
        v130("uniform float a[4]; void main() { gl_FragColor = vec4(a[4u]); }"),
        Code::IndexOutOfRange,
    );
    fails(
        v130("uniform float a[4]; void main() { gl_FragColor = vec4(a[0xffffffffu]); }"),
        Code::IndexOutOfRange,
    );
}

#[test]
fn texel_offsets_and_sampler_array_indices_are_constant_from_130() {
    let s = frag(
        "#version 130\nuniform sampler2D a;\nuniform ivec2 o;\nvoid main() { gl_FragColor = texelFetchOffset(a, ivec2(0), 0, o); }\n",
    );
    assert!(
        s.info_log().contains("must be a constant expression"),
        "{}",
        s.info_log()
    );
    ok(frag(
        "#version 130\nuniform sampler2D a;\nvoid main() { gl_FragColor = textureOffset(a, vec2(0.0), ivec2(1, -1), 2.0); }\n",
    ));
    let src = |v: u32| {
        format!("#version {v}\nuniform sampler2D s[4];\nuniform int x;\nvoid main() {{ gl_FragColor = texture2D(s[x], vec2(0.0)) + texture2D(s[1], vec2(0.0)); }}\n")
    };
    ok(frag(&src(120)));
    fails(frag(&src(130)), Code::NotConstant);
}

#[test]
fn texture_array_lookups_need_their_extension() {
    let body = "uniform sampler2DArray s;\nuniform sampler1DArrayShadow h;\nvoid main() { gl_FragColor = texture2DArray(s, vec3(0.0), 1.0) + shadow1DArrayLod(h, vec3(0.0), 0.0); }";
    ok(frag(&format!(
        "#version 130\n#extension GL_EXT_texture_array : enable\n{body}"
    )));
    ok(frag(&format!(
        "#version 150 compatibility\n#extension GL_EXT_texture_array : require\n{body}"
    )));
    fails(
        frag("#version 130\nuniform sampler2DArray s;\nvoid main() { gl_FragColor = texture2DArray(s, vec3(0.0)); }"),
        Code::Undeclared,
    );
    // The bias form is the fragment stage's.
    fails(
        vert("#version 130\n#extension GL_EXT_texture_array : enable\nuniform sampler2DArray s;\nvoid main() { gl_Position = texture2DArray(s, vec3(0.0), 1.0); }"),
        Code::NoMatchingOverload,
    );
    ok(vert("#version 130\n#extension GL_EXT_texture_array : enable\nuniform sampler2DArray s;\nvoid main() { gl_Position = texture2DArrayLod(s, vec3(0.0), 1.0); }"));
}

#[test]
fn shader_texture_lod_lookups_need_their_extension() {
    let ext = "#extension GL_ARB_shader_texture_lod : require\n";
    // Explicit LOD in a 1.10 fragment shader, derivatives in any stage.
    let lod =
        "uniform sampler2D s;\nvoid main() { gl_FragColor = texture2DLod(s, vec2(0.0), 1.0); }";
    ok(frag(&format!("{ext}{lod}")));
    fails(frag(lod), Code::VersionTooLow);
    let grad = "uniform sampler2DShadow s;\nvoid main() { gl_Position = shadow2DProjGradARB(s, vec4(0.0), vec2(1.0), vec2(0.0)); }";
    ok(vert(&format!("{ext}{grad}")));
    fails(vert(grad), Code::Undeclared);
    // The rectangle forms where the language has the samplers.
    ok(vert(&format!(
        "#version 140\n{ext}uniform sampler2DRect r;\nin vec4 v;\nvoid main() {{ gl_Position = texture2DRectProjGradARB(r, v, v.xy, v.zw); }}"
    )));
}
