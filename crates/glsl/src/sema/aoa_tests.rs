//! Unit tests of GL_ARB_arrays_of_arrays: the declaration forms, types
//! and their spelling, constructors, indexing, `.length()`, assignment,
//! comparison, parameters and returns, interfaces between stages, and
//! the diagnostics without the extension.

use crate::diag::Code;
use crate::ir::Stage;
use crate::link::link;
use crate::{compile, CompileOptions, Shader};

use super::interface::tests::{fails, global_type, ok};

const EXT: &str = "#extension GL_ARB_arrays_of_arrays : enable\n";

fn shader(stage: Stage, version: u32, body: &str) -> Shader {
    let src = format!("#version {version}\n{EXT}{body}");
    compile(&[&src], &CompileOptions::new(stage))
}

fn vert(body: &str) -> Shader {
    shader(Stage::Vertex, 120, body)
}

#[test]
fn every_declaration_form_gives_the_same_type() {
    let s = vert(
        "uniform float a[2][3];
uniform float[2][3] b;
uniform float[3] c[2];
uniform vec4 d[1][2][3];
uniform int[4][5][6] e[1][2][3];
void main() { gl_Position = vec4(a[1][2] + b[1][2] + c[1][2] + d[0][1][2].x + float(e[0][1][2][3][4][5])); }",
    );
    ok(&s);
    for n in ["a", "b", "c"] {
        assert_eq!(global_type(&s, n), "float[2][3]", "{n}");
    }
    assert_eq!(global_type(&s, "d"), "vec4[1][2][3]");
    assert_eq!(global_type(&s, "e"), "int[1][2][3][4][5][6]");
}

#[test]
fn values_of_arrays_of_arrays_are_first_class() {
    ok(&vert(
        "float g(float x[2][3]) { return x[1][2]; }
float h(in float[2][3] x, out float[3] y[2]) { y = x; return float(x.length()); }
float[2][3] make() { return float[2][3](float[3](1.0, 2.0, 3.0), float[3](4.0, 5.0, 6.0)); }
void main() {
  float a[2][3] = make();
  float[3] b[2];
  b = a;
  int i = int(gl_Vertex.x);
  float s = a[i][i] + a[1][i] + a[i][2] + g(a) + h(a, b);
  if (a == b && !(a != make())) s += 1.0;
  float row[3] = a[1];
  a[0] = row;
  a[i][1] = 2.0;
  float e[][3] = float[][3](float[3](1.0, 2.0, 3.0));
  const int n = e.length() + a.length() + a[0].length();
  float check[n == 6 ? 1 : -1];
  gl_Position = vec4(s);
}",
    ));
}

#[test]
fn constructors_and_initializers_are_checked_per_level() {
    // Too few rows, a row of the wrong size, a scalar where a row goes.
    fails(
        &vert("void main() { float a[2][3] = float[2][3](float[3](1.0, 2.0, 3.0)); gl_Position = vec4(a[0][0]); }"),
        Code::BadConstructor,
    );
    fails(
        &vert("void main() { float a[2][3] = float[2][3](float[3](1.0, 2.0, 3.0), float[2](1.0, 2.0)); gl_Position = vec4(a[0][0]); }"),
        Code::TypeMismatch,
    );
    fails(
        &vert("void main() { float a[1][3] = float[1][3](1.0); gl_Position = vec4(a[0][0]); }"),
        Code::TypeMismatch,
    );
    // Different dimensions are different types.
    fails(
        &vert("void main() { float a[2][3]; float b[3][2]; a = b; gl_Position = vec4(0.0); }"),
        Code::TypeMismatch,
    );
}

#[test]
fn constant_indices_are_checked_on_every_level() {
    fails(
        &vert("void main() { float a[2][3]; gl_Position = vec4(a[1][3]); }"),
        Code::IndexOutOfRange,
    );
    fails(
        &vert("void main() { float a[2][3]; gl_Position = vec4(a[2][0]); }"),
        Code::IndexOutOfRange,
    );
}

#[test]
fn only_the_outermost_size_may_be_missing() {
    let s = vert("uniform float a[2][]; void main() { gl_Position = vec4(0.0); }");
    fails(&s, Code::BadArraySize);
    assert!(s.info_log().contains("outermost"), "{}", s.info_log());
    fails(
        &vert("uniform float[] a[2]; void main() { gl_Position = vec4(0.0); }"),
        Code::BadArraySize,
    );
}

#[test]
fn without_the_extension_the_error_names_it() {
    for src in [
        "#version 120\nuniform float a[2][3];\nvoid main() { gl_Position = vec4(0.0); }",
        "#version 120\nuniform float[3] a[2];\nvoid main() { gl_Position = vec4(0.0); }",
        "#version 150\nvoid main() { float[2][3] a; gl_Position = vec4(0.0); }",
    ] {
        let s = compile(&[src], &CompileOptions::new(Stage::Vertex));
        fails(&s, Code::VersionTooLow);
        let d = s.diagnostics.iter().find(|d| d.is_error()).unwrap();
        assert!(
            d.message
                .contains("`#extension GL_ARB_arrays_of_arrays : enable'"),
            "{}",
            d.message
        );
        assert!(d
            .notes
            .iter()
            .any(|n| n.contains("GL_ARB_arrays_of_arrays")));
    }
    // GLSL 1.10 shaders may enable it too (the extension's "GLSL 1.2 is
    // required" is asked of the implementation), with its macro; they
    // still have no array type syntax.
    let s = compile(
        &[&format!(
            "#version 110\n{EXT}#if GL_ARB_arrays_of_arrays != 1\n#error no macro\n#endif\nuniform float a[2][3];\nvoid main() {{ gl_Position = vec4(a[1][2]); }}"
        )],
        &CompileOptions::new(Stage::Vertex),
    );
    ok(&s);
    fails(
        &compile(
            &[&format!("#version 110\n{EXT}uniform float[3] a[2];\nvoid main() {{ gl_Position = vec4(a[1][2]); }}")],
            &CompileOptions::new(Stage::Vertex),
        ),
        Code::VersionTooLow,
    );
}

#[test]
fn precision_applies_to_the_innermost_element() {
    ok(&shader(
        Stage::Fragment,
        130,
        "uniform mediump sampler2D s[2][2];\nuniform highp float f[2][3];\nvoid main() { gl_FragColor = texture(s[1][0], vec2(f[1][2])); }",
    ));
    fails(
        &shader(
            Stage::Fragment,
            130,
            "uniform mediump bool b[2][2];\nvoid main() { gl_FragColor = vec4(b[0][0]); }",
        ),
        Code::BadQualifier,
    );
}

#[test]
fn stage_interfaces_match_arrays_of_arrays() {
    let vs = shader(
        Stage::Vertex,
        150,
        "in vec4 p;\nout vec4 c[2][3];\nflat out ivec2 f[4];\nvoid main() { c[1][2] = p; f[3] = ivec2(1); gl_Position = p; }",
    );
    let fs = shader(
        Stage::Fragment,
        150,
        "in vec4[3] c[2];\nout vec4 o;\nvoid main() { o = c[1][2]; }",
    );
    ok(&vs);
    ok(&fs);
    let p = link(&[&vs, &fs]);
    assert!(p.ok(), "{}", p.info_log());
    // A geometry input adds the vertex level to the output's array.
    let gs = shader(
        Stage::Geometry,
        150,
        "layout(triangles) in;\nlayout(points, max_vertices = 1) out;\nflat in ivec2 f[3][4];\nflat in ivec2 g[][4];\nvoid main() { gl_Position = vec4(f[2][3] + g[1][0], 0.0, 1.0); EmitVertex(); }",
    );
    ok(&gs);
    assert_eq!(global_type(&gs, "f"), "ivec2[3][4]");
    assert_eq!(global_type(&gs, "g"), "ivec2[3][4]");
    let bad = shader(
        Stage::Fragment,
        150,
        "in vec4 c[3][2];\nout vec4 o;\nvoid main() { o = c[1][1]; }",
    );
    let p = link(&[&vs, &bad]);
    assert!(!p.ok(), "the dimensions differ");
}

#[test]
fn struct_members_and_arrays_of_structs() {
    ok(&vert(
        "struct S { float m[2][3]; vec2 v; };
uniform S s[2][2];
void main() { S t = s[1][0]; gl_Position = vec4(t.m[1][2] + s[0][1].m[0][0] + s[1][1].v.x); }",
    ));
}

#[test]
fn block_instances_may_be_arrays_of_arrays() {
    let s = shader(
        Stage::Vertex,
        150,
        "uniform B { mat4 a; vec4 v[2][2]; } i[4][5];\nout O { vec4 c; } o[2][3];\nvoid main() { o[1][2].c = i[3][4].v[1][0]; gl_Position = i[1][2].a[0]; }",
    );
    ok(&s);
    let m = s.module.as_ref().unwrap();
    let b = m.blocks.iter().find(|b| b.name == "B").unwrap();
    assert_eq!((b.array, b.inner.clone()), (Some(4), vec![5]));
    assert_eq!(b.elements(), 20);
    assert_eq!(b.element_suffix(0), "[0][0]");
    assert_eq!(b.element_suffix(13), "[2][3]");
    assert_eq!(global_type(&s, "i"), "B[4][5]");
    let o = m.blocks.iter().find(|b| b.name == "O").unwrap();
    assert_eq!(o.dims(), vec![2, 3]);
    // A geometry input block array of arrays: the outer size is the
    // primitive's vertex count, the inner the vertex stage's instance.
    let gs = shader(
        Stage::Geometry,
        150,
        "layout(lines) in;\nlayout(points, max_vertices = 1) out;\nin O { vec4 c; } o[][2][3];\nvoid main() { gl_Position = o[1][1][2].c; EmitVertex(); }",
    );
    ok(&gs);
    let g = gs.module.as_ref().unwrap();
    let gb = g.blocks.iter().find(|b| b.name == "O").unwrap();
    assert_eq!(gb.dims(), vec![2, 2, 3]);
    // `gl_in` keeps its one dimension.
    fails(
        &shader(
            Stage::Geometry,
            150,
            "layout(triangles) in;\nlayout(points, max_vertices = 1) out;\nin gl_PerVertex { vec4 gl_Position; } gl_in[][2];\nvoid main() { EmitVertex(); }",
        ),
        Code::BadQualifier,
    );
}

#[test]
fn sampler_and_block_arrays_of_arrays_keep_constant_indices() {
    // GLSL 1.30 §4.1.7 and 1.50 §4.3.7 hold at every level.
    fails(
        &shader(
            Stage::Fragment,
            130,
            "uniform sampler2D s[2][2];\nuniform int i;\nvoid main() { gl_FragColor = texture(s[i][0], vec2(0.0)); }",
        ),
        Code::NotConstant,
    );
    fails(
        &shader(
            Stage::Fragment,
            130,
            "uniform sampler2D s[2][2];\nuniform int i;\nvoid main() { gl_FragColor = texture(s[0][i], vec2(0.0)); }",
        ),
        Code::NotConstant,
    );
    fails(
        &shader(
            Stage::Vertex,
            150,
            "uniform B { vec4 v; } b[2][2];\nuniform int i;\nvoid main() { gl_Position = b[1][i].v; }",
        ),
        Code::NotConstant,
    );
    ok(&shader(
        Stage::Vertex,
        150,
        "uniform B { vec4 v[2]; } b[2][2];\nuniform int i;\nvoid main() { gl_Position = b[1][0].v[i]; }",
    ));
}
