//! Unit tests of GL_ARB_shading_language_420pack: initializer lists and
//! their diagnostics, `.length()` of vectors and matrices, swizzles of
//! scalars, `const` locals from expressions, qualifiers in any order,
//! `layout(binding)` and its link rules, and the language without the
//! extension.

use crate::diag::Code;
use crate::ir::{ConstScalar, Stage};
use crate::link::link;
use crate::{compile, CompileOptions, Shader};

use super::interface::tests::{fails, global, global_type, ok};

const EXT: &str = "#extension GL_ARB_shading_language_420pack : enable\n";

fn shader(stage: Stage, version: u32, ext: bool, body: &str) -> Shader {
    let src = format!("#version {version}\n{}{body}", if ext { EXT } else { "" });
    compile(&[&src], &CompileOptions::new(stage))
}

fn frag(body: &str) -> Shader {
    shader(Stage::Fragment, 130, true, body)
}

/// The constant value of global `name`, as floats.
fn const_floats(s: &Shader, name: &str) -> Vec<f32> {
    let c = global(s, name).init.as_ref().expect("constant");
    c.components
        .iter()
        .map(|c| match c {
            ConstScalar::Float(f) => *f,
            ConstScalar::Int(i) => *i as f32,
            ConstScalar::Uint(u) => *u as f32,
            ConstScalar::Bool(b) => f32::from(u8::from(*b)),
        })
        .collect()
}

#[test]
fn initializer_lists_build_the_aggregate_they_stand_for() {
    let s = frag(
        "struct S { float a; ivec2 b; };
const mat2 m = { { 1.0, 2.0 }, vec2(3.0, 4.0) };
const vec3 v[] = { { 1, 2, 3 }, vec3(4.0), };
const S s = { 5, { 6, 7 } };
#extension GL_ARB_arrays_of_arrays : enable
const float f[2][2] = { { 1.0, 2.0 }, { 3.0, 4.0 } };
void main() { gl_FragColor = vec4(m[1], v[1].xy) + vec4(s.a) + vec4(f[1][0]); }",
    );
    ok(&s);
    assert_eq!(const_floats(&s, "m"), [1.0, 2.0, 3.0, 4.0]);
    assert_eq!(global_type(&s, "v"), "vec3[2]");
    assert_eq!(const_floats(&s, "v"), [1.0, 2.0, 3.0, 4.0, 4.0, 4.0]);
    assert_eq!(const_floats(&s, "s"), [5.0, 6.0, 7.0]);
    assert_eq!(const_floats(&s, "f"), [1.0, 2.0, 3.0, 4.0]);
}

#[test]
fn initializer_lists_take_expressions_in_functions() {
    ok(&frag(
        "uniform float u;
void main() { vec2 a[2] = { vec2(u), { u, 2.0 * u } }; mat2 m = { a[0], a[1] }; gl_FragColor = vec4(m[0], m[1]); }",
    ));
}

#[test]
fn initializer_lists_must_match_the_aggregate_exactly() {
    for (body, what) in [
        ("float a[2] = { 1.0, 2.0, 3.0 };", "too many elements"),
        ("vec2 b = { 1.0, 2.0, 3.0 };", "too many components"),
        ("vec4 b = { 1.0, 2.0 };", "too few components"),
        (
            "mat3 c = { vec3(0.0), vec3(1.0), vec3(2.0), vec3(3.0) };",
            "too many columns",
        ),
        ("mat2 d = { 1.0, 0.0, 0.0, 1.0 };", "flattened nesting"),
        (
            "struct T { float a; int b; }; T e = { 1.2, 2, 3 };",
            "too many members",
        ),
        ("int i = { 1 };", "scalar"),
        ("vec4 b2[2] = { vec4(0.0), 1.0 };", "wrong element type"),
        ("mat4x2 c2 = { vec3(0.0), vec3(1.0) };", "wrong column type"),
        ("ivec2 x = { 1.0, 2.0 };", "float to int"),
    ] {
        let s = frag(&format!("{body}\nvoid main() {{ }}"));
        assert!(!s.ok(), "{what}: {body}");
    }
    let s = frag("vec2 b = { 1.0, 2.0, 3.0 };\nvoid main() { }");
    assert!(
        s.info_log()
            .contains("has 3 initializers, expected 2 (one per component)"),
        "{}",
        s.info_log()
    );
}

#[test]
fn initializer_lists_need_the_extension() {
    let s = shader(
        Stage::Fragment,
        130,
        false,
        "vec2 b = { 1.0, 2.0 };\nvoid main() { }",
    );
    fails(&s, Code::VersionTooLow);
    assert!(
        s.info_log().contains("GL_ARB_shading_language_420pack"),
        "{}",
        s.info_log()
    );
}

#[test]
fn length_of_vectors_and_matrices_is_a_constant() {
    let s = frag(
        "const int a = vec3(0.0).length();
const int b = mat3x4(0.0).length();
const int c = bvec2(true).length();
void main() { gl_FragColor = vec4(float(a), float(b), float(c), 0.0); }",
    );
    ok(&s);
    assert_eq!(const_floats(&s, "a"), [3.0]);
    assert_eq!(const_floats(&s, "b"), [3.0]);
    assert_eq!(const_floats(&s, "c"), [2.0]);
    let without = shader(
        Stage::Fragment,
        130,
        false,
        "void main() { int n = vec3(0.0).length(); }",
    );
    fails(&without, Code::TypeMismatch);
    fails(
        &frag("void main() { int n = (1.0).length(); }"),
        Code::TypeMismatch,
    );
}

#[test]
fn scalars_swizzle_with_their_one_component() {
    let s = frag(
        "const vec4 a = (1.5).xxxx;
const vec2 b = (1).rr;
void main() { float f = 2.0; f.x = 3.0; gl_FragColor = a + vec4(b, f.s, f); }",
    );
    ok(&s);
    assert_eq!(const_floats(&s, "a"), [1.5; 4]);
    assert_eq!(global_type(&s, "b"), "vec2");
    fails(
        &frag("void main() { float f = 1.0; vec2 g = f.xy; }"),
        Code::BadSwizzle,
    );
    fails(
        &frag("void main() { float f = 1.0; f.xx = vec2(1.0); }"),
        Code::NotAnLvalue,
    );
    fails(
        &shader(
            Stage::Fragment,
            130,
            false,
            "void main() { float f = 1.0; vec2 g = f.xx; }",
        ),
        Code::BadSwizzle,
    );
}

#[test]
fn const_locals_may_take_expressions_that_are_not_constant() {
    ok(&frag(
        "uniform float u;
void main() { const float k = u * 2.0; gl_FragColor = vec4(k); }",
    ));
    // Still read-only, and still constant at global scope.
    fails(
        &frag("uniform float u;\nvoid main() { const float k = u; k = 1.0; }"),
        Code::ReadOnly,
    );
    fails(
        &frag("uniform float u;\nconst float k = u;\nvoid main() { }"),
        Code::NotConstant,
    );
    fails(
        &shader(
            Stage::Fragment,
            130,
            false,
            "uniform float u;\nvoid main() { const float k = u; }",
        ),
        Code::NotConstant,
    );
}

#[test]
fn qualifiers_come_in_any_order_one_of_each_class() {
    let s = shader(
        Stage::Vertex,
        130,
        true,
        "out flat invariant float a;
centroid flat out float b;
out centroid float c;
void f(in const float x, const in float y, highp in float z) { }
void main() { a = 1.0; b = 2.0; c = 3.0; gl_Position = vec4(0.0); }",
    );
    ok(&s);
    for body in [
        "flat smooth out float a;",
        "out in float a;",
        "centroid centroid out float a;",
        "invariant invariant out float a;",
        "void f(const const float x) { }",
        "void f(out const float x) { }",
    ] {
        let s = shader(
            Stage::Vertex,
            130,
            true,
            &format!("{body}\nvoid main() {{ gl_Position = vec4(0.0); }}"),
        );
        fails(&s, Code::BadQualifier);
    }
    // Without the extension the order of GLSL 1.30 §4.7 holds.
    fails(
        &shader(
            Stage::Vertex,
            130,
            false,
            "out flat float a;\nvoid main() { a = 1.0; }",
        ),
        Code::BadQualifier,
    );
    fails(
        &shader(
            Stage::Vertex,
            130,
            false,
            "void f(in const float x) { }\nvoid main() { }",
        ),
        Code::BadQualifier,
    );
}

#[test]
fn several_layout_qualifiers_need_the_extension() {
    let two = "layout(std140) layout(row_major) uniform B { mat2 m; };\nvoid main() { gl_FragColor = vec4(m[0], m[1]); }";
    ok(&shader(Stage::Fragment, 140, true, two));
    fails(
        &shader(Stage::Fragment, 140, false, two),
        Code::BadQualifier,
    );
}

#[test]
fn bindings_of_samplers_and_blocks() {
    let s = shader(
        Stage::Fragment,
        140,
        true,
        "layout(binding = 3) uniform sampler2D t[2];
layout(std140, binding = 5) uniform B { vec4 c; } b[2];
void main() { gl_FragColor = texture(t[1], vec2(0.0)) + b[1].c; }",
    );
    ok(&s);
    assert_eq!(global(&s, "t").binding, Some(3));
    let m = s.module.as_ref().expect("compiled");
    assert_eq!(
        m.blocks
            .iter()
            .find(|b| b.name == "B")
            .and_then(|b| b.binding),
        Some(5)
    );
    for body in [
        // Not a sampler or a block.
        "layout(binding = 1) uniform float f;",
        // Past the texture units (32), counting every element.
        "layout(binding = 31) uniform sampler2D t[2];",
        // Past the 36 uniform buffer binding points.
        "layout(binding = 36) uniform B { vec4 c; };",
        // Not on members, not as a default.
        "uniform B { layout(binding = 1) vec4 c; };",
        "layout(binding = 1) uniform;",
    ] {
        let s = shader(
            Stage::Fragment,
            140,
            true,
            &format!("{body}\nvoid main() {{ }}"),
        );
        fails(&s, Code::BadQualifier);
    }
    let without = shader(
        Stage::Fragment,
        140,
        false,
        "layout(binding = 1) uniform sampler2D t;\nvoid main() { }",
    );
    fails(&without, Code::VersionTooLow);
}

#[test]
fn different_bindings_of_one_name_do_not_link() {
    let vs = |b: &str| {
        shader(
            Stage::Vertex,
            150,
            true,
            &format!(
                "{b} uniform sampler2D t;\nvoid main() {{ gl_Position = texture(t, vec2(0.0)); }}"
            ),
        )
    };
    let fs = |b: &str| {
        shader(
            Stage::Fragment,
            150,
            true,
            &format!("{b} uniform sampler2D t;\nout vec4 o;\nvoid main() {{ o = texture(t, vec2(0.0)); }}"),
        )
    };
    let linked = |v: &Shader, f: &Shader| link(&[v, f]).ok();
    assert!(!linked(
        &vs("layout(binding = 0)"),
        &fs("layout(binding = 1)")
    ));
    // A binding in one stage and none in the other is the same uniform.
    assert!(linked(&vs("layout(binding = 2)"), &fs("")));
    assert!(linked(
        &vs("layout(binding = 2)"),
        &fs("layout(binding = 2)")
    ));
}
