//! Unit tests of the tessellation stages' language
//! (GL_ARB_tessellation_shader): the extension and version they need,
//! `patch` inputs and outputs, the control shader's output patch layout
//! and its per-vertex outputs, the evaluation shader's layouts, the
//! built-ins, `barrier()`'s placement, and the link rules of programs
//! with tessellation stages.

use crate::diag::Code;
use crate::ir::{Stage, Storage, TessMode, TessSpacing, VertexOrder};
use crate::link::link;
use crate::{compile, CompileOptions, Shader};

use super::interface::tests::{fails, global, ok};

const EXT: &str = "#extension GL_ARB_tessellation_shader : require\n";

fn shader(stage: Stage, body: &str) -> Shader {
    let src = format!("#version 150\n{EXT}{body}");
    compile(&[&src], &CompileOptions::new(stage))
}

fn tcs(body: &str) -> Shader {
    shader(Stage::TessControl, body)
}

fn tes(body: &str) -> Shader {
    shader(Stage::TessEvaluation, body)
}

const TCS_MAIN: &str = "layout(vertices = 3) out;
void main() {
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
    gl_TessLevelOuter = float[4](1.0, 1.0, 1.0, 1.0);
    gl_TessLevelInner = float[2](1.0, 1.0);
}
";

#[test]
fn the_stages_need_the_extension() {
    let src = "#version 150\nlayout(vertices = 3) out;\nvoid main() { }\n";
    let s = compile(&[src], &CompileOptions::new(Stage::TessControl));
    fails(&s, Code::VersionTooLow);
    assert!(
        s.info_log().contains("GL_ARB_tessellation_shader"),
        "{}",
        s.info_log()
    );
    // GLSL 1.40 has the stages (not the gl_in/gl_out blocks); 1.30 not.
    let old = format!("#version 140\n{EXT}void main() {{ gl_TessLevelOuter[0] = 1.0; }}\n");
    ok(&compile(&[&old], &CompileOptions::new(Stage::TessControl)));
    let older = format!("#version 130\n{EXT}void main() {{ }}\n");
    fails(
        &compile(&[&older], &CompileOptions::new(Stage::TessEvaluation)),
        Code::VersionTooLow,
    );
    // `patch' is an identifier without the extension.
    let vs = "#version 150\nfloat patch = 1.0;\nvoid main() { gl_Position = vec4(patch); }\n";
    ok(&compile(&[vs], &CompileOptions::new(Stage::Vertex)));
}

#[test]
fn a_control_shader_sizes_its_outputs_by_the_patch() {
    let s = tcs("out float before[];\nlayout(vertices = 4) out;\nout float after[];\npatch out float p[2];\nint a[before.length() == 4 ? 1 : -1];\nint b[after.length() + gl_out.length() == 8 ? 1 : -1];\nint c[gl_in.length() == gl_MaxPatchVertices ? 1 : -1];\n");
    ok(&s);
    let m = s.module.as_ref().unwrap();
    assert_eq!(m.tessellation.vertices, Some(4));
    assert_eq!(global(&s, "before").storage, Storage::PerVertexOutput);
    assert_eq!(global(&s, "p").storage, Storage::Varying);
    assert!(global(&s, "p").patch);
    // A sized output disagreeing with the patch, before or after it.
    fails(
        &tcs("layout(vertices = 3) out;\nout vec4 v[4];\n"),
        Code::BadArraySize,
    );
    fails(
        &tcs("out vec4 v[4];\nlayout(vertices = 3) out;\n"),
        Code::BadArraySize,
    );
    // The size is 1 to gl_MaxPatchVertices, one value per program.
    fails(&tcs("layout(vertices = 0) out;\n"), Code::BadQualifier);
    fails(&tcs("layout(vertices = 33) out;\n"), Code::BadQualifier);
    fails(
        &tcs("layout(vertices = 3) out;\nlayout(vertices = 4) out;\n"),
        Code::Redeclared,
    );
    ok(&tcs(
        "layout(vertices = 3) out;\nlayout(vertices = 3) out;\n",
    ));
    // `.length()' before the layout names what is missing.
    let s = tcs("int n = gl_out.length();\nlayout(vertices = 3) out;\n");
    fails(&s, Code::BadArraySize);
    assert!(
        s.info_log().contains("layout(vertices = N) out;"),
        "{}",
        s.info_log()
    );
}

#[test]
fn per_vertex_inputs_and_outputs_are_arrays() {
    fails(&tcs("in vec4 x;\n"), Code::TypeMismatch);
    fails(&tes("in vec4 x;\n"), Code::TypeMismatch);
    fails(&tcs("out vec4 x;\n"), Code::TypeMismatch);
    fails(&tcs("in B { vec4 x; } b;\n"), Code::TypeMismatch);
    fails(&tcs("out B { vec4 x; };\n"), Code::TypeMismatch);
    ok(&tcs(
        "in B { vec4 x; } b[];\nout C { vec4 y; } c[];\nuniform U { vec4 u; } un;\n",
    ));
    // Inputs have gl_MaxPatchVertices elements.
    ok(&tes(
        "in float xs[];\nint t[xs.length() == gl_MaxPatchVertices ? 1 : -1];\n",
    ));
    fails(&tes("in float xs[3];\n"), Code::BadArraySize);
    ok(&tes("in float xs[gl_MaxPatchVertices];\n"));
    // A patch input is not per vertex: unsized, it has no length.
    fails(
        &tes("patch in float p[];\nint t[p.length()];\n"),
        Code::BadArraySize,
    );
    ok(&tes("patch in vec4 p;\npatch in float q[4];\nlayout(triangles) in;\nvoid main() { gl_Position = p * q[1]; }\n"));
}

#[test]
fn patch_belongs_to_control_outputs_and_evaluation_inputs() {
    fails(&tcs("patch in float p;\n"), Code::BadQualifier);
    fails(&tes("patch out float p;\n"), Code::BadQualifier);
    fails(&tcs("patch float p;\n"), Code::BadQualifier);
    fails(&tcs("void main() { patch float p; }\n"), Code::BadQualifier);
    let vs = format!("#version 150\n{EXT}patch out float p;\nvoid main() {{ }}\n");
    fails(
        &compile(&[&vs], &CompileOptions::new(Stage::Vertex)),
        Code::BadQualifier,
    );
    // An evaluation shader's patch inputs are read-only.
    fails(
        &tes("patch in float p;\nvoid main() { p = 1.0; }\n"),
        Code::ReadOnly,
    );
    fails(
        &tes("void main() { gl_TessLevelOuter[0] = 1.0; }\n"),
        Code::ReadOnly,
    );
}

#[test]
fn an_invocation_writes_only_its_own_vertex() {
    ok(&tcs(TCS_MAIN));
    ok(&tcs("layout(vertices = 3) out;\nout vec4 x[];\nout B { vec4 y[2]; } b[];\nvoid main() {\n  x[gl_InvocationID].xy = vec2(1.0);\n  b[gl_InvocationID].y[1] = x[0];\n}\n"));
    for write in [
        "x[0] = vec4(0.0);",
        "int n = gl_InvocationID; x[n] = vec4(0.0);",
        "gl_out[1].gl_Position = vec4(0.0);",
        "b[0].y[0] = vec4(0.0);",
    ] {
        let s = tcs(&format!(
            "layout(vertices = 3) out;\nout vec4 x[];\nout B {{ vec4 y[2]; }} b[];\nvoid main() {{ {write} }}\n"
        ));
        fails(&s, Code::NotAnLvalue);
        assert!(s.info_log().contains("gl_InvocationID"), "{}", s.info_log());
    }
    // A shader's own variable named gl_InvocationID is not the built-in.
    fails(
        &tcs("layout(vertices = 3) out;\nout vec4 x[];\nvoid f(int gl_InvocationID) { x[gl_InvocationID] = vec4(0.0); }\n"),
        Code::NotAnLvalue,
    );
}

#[test]
fn barrier_is_called_only_at_the_top_of_main() {
    let at = |body: &str| {
        tcs(&format!(
            "layout(vertices = 3) out;\nuniform int u;\nvoid main() {{ {body} }}\n"
        ))
    };
    ok(&at("barrier();"));
    for (body, why) in [
        ("if (u > 0) barrier();", "inside an `if'"),
        ("for (int i = 0; i < 2; i++) barrier();", "inside a loop"),
        ("switch (u) { default: barrier(); }", "inside a `switch'"),
        ("if (u > 0) return; barrier();", "after a `return'"),
    ] {
        let s = at(body);
        fails(&s, Code::StageMismatch);
        assert!(s.info_log().contains(why), "{body}: {}", s.info_log());
    }
    fails(
        &tcs("layout(vertices = 3) out;\nvoid f() { barrier(); }\nvoid main() { f(); }\n"),
        Code::StageMismatch,
    );
    // A function of the shader's own named barrier hides the built-in.
    ok(&tcs("layout(vertices = 3) out;\nvoid barrier() { }\nvoid main() { for (int i = 0; i < 2; i++) barrier(); }\n"));
    // Evaluation shaders have no barrier().
    fails(&tes("void main() { barrier(); }\n"), Code::StageMismatch);
}

#[test]
fn evaluation_layouts() {
    let s = tes("layout(quads, fractional_odd_spacing, cw, point_mode) in;\nlayout(quads) in;\n");
    ok(&s);
    let t = s.module.as_ref().unwrap().tessellation;
    assert_eq!(t.mode, Some(TessMode::Quads));
    assert_eq!(t.spacing, Some(TessSpacing::FractionalOdd));
    assert_eq!(t.order, Some(VertexOrder::Cw));
    assert!(t.point_mode);
    fails(
        &tes("layout(triangles) in;\nlayout(isolines) in;\n"),
        Code::Redeclared,
    );
    fails(&tes("layout(vertices = 3) in;\n"), Code::BadQualifier);
    fails(&tcs("layout(triangles) out;\n"), Code::BadQualifier);
    let s = tes("layout(quads) out;\n");
    fails(&s, Code::BadQualifier);
    assert!(
        s.info_log().contains("`layout(quads) in;'"),
        "{}",
        s.info_log()
    );
    // On a declaration, and in other stages, they are misplaced.
    fails(&tes("layout(cw) in vec4 v[];\n"), Code::BadQualifier);
    let fs = format!("#version 150\n{EXT}layout(quads) in;\nvoid main() {{ }}\n");
    fails(
        &compile(&[&fs], &CompileOptions::new(Stage::Fragment)),
        Code::StageMismatch,
    );
}

#[test]
fn builtins_of_each_stage() {
    ok(&tes("layout(triangles) in;\nvoid main() {\n  gl_Position = gl_in[0].gl_Position * gl_TessCoord.x + vec4(gl_TessLevelOuter[1] + gl_TessLevelInner[0]) + vec4(float(gl_PatchVerticesIn + gl_PrimitiveID));\n}\n"));
    ok(&tcs("layout(vertices = 1) out;\nint t[gl_MaxTessGenLevel == 64 && gl_MaxTessPatchComponents == 120 ? 1 : -1];\nvoid main() { gl_out[gl_InvocationID].gl_PointSize = float(gl_PatchVerticesIn); }\n"));
    // gl_TessCoord and gl_InvocationID belong to one stage each.
    fails(
        &tcs("void main() { vec3 c = gl_TessCoord; }\n"),
        Code::StageMismatch,
    );
    fails(
        &tes("void main() { int i = gl_InvocationID; }\n"),
        Code::StageMismatch,
    );
    // Inputs are read-only.
    fails(
        &tcs("layout(vertices = 3) out;\nvoid main() { gl_in[0].gl_Position = vec4(0.0); }\n"),
        Code::ReadOnly,
    );
    // gl_out can be redeclared, as gl_in can.
    ok(&tcs("out gl_PerVertex { vec4 gl_Position; } gl_out[];\nin gl_PerVertex { vec4 gl_Position; } gl_in[];\nlayout(vertices = 3) out;\nvoid main() { gl_out[gl_InvocationID].gl_Position = gl_in[0].gl_Position; }\n"));
    fails(
        &tcs("out gl_PerVertex { vec4 gl_Position; vec4 junk; } gl_out[];\n"),
        Code::Redeclared,
    );
    fails(
        &tcs("out gl_PerVertex { vec4 gl_Position; };\n"),
        Code::BadQualifier,
    );
}

fn vs(body: &str) -> Shader {
    let src = format!("#version 150\n{body}");
    compile(&[&src], &CompileOptions::new(Stage::Vertex))
}

const VS: &str = "out vec4 color;\nvoid main() { gl_Position = vec4(0.0); color = vec4(1.0); }\n";
const TES: &str = "layout(triangles) in;\nin vec4 tc[];\npatch in float level;\nout vec4 c;\nvoid main() { gl_Position = gl_in[0].gl_Position * level; c = tc[1]; }\n";
const FS: &str = "in vec4 c;\nout vec4 o;\nvoid main() { o = c; }\n";

#[test]
fn a_program_links_through_both_stages() {
    let v = vs(VS);
    let c = tcs("layout(vertices = 3) out;\nin vec4 color[];\nout vec4 tc[];\npatch out float level;\nvoid main() {\n  tc[gl_InvocationID] = color[gl_InvocationID];\n  level = 2.0;\n  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;\n}\n");
    let e = tes(TES);
    let f_src = format!("#version 150\n{FS}");
    let fr = compile(&[&f_src], &CompileOptions::new(Stage::Fragment));
    for s in [&v, &c, &e, &fr] {
        ok(s);
    }
    let p = link(&[&v, &c, &e, &fr]);
    assert!(p.ok(), "{}", p.info_log());
    let stages: Vec<Stage> = p.stages.iter().map(|s| s.stage).collect();
    assert_eq!(
        stages,
        [
            Stage::Vertex,
            Stage::TessControl,
            Stage::TessEvaluation,
            Stage::Fragment
        ]
    );
    // Without the control stage, the evaluation stage reads the vertex
    // outputs; `level' then has no writer, `tc' neither.
    let p = link(&[&v, &e, &fr]);
    assert!(!p.ok());
    // A per-vertex output read as a per-patch input does not match.
    let c2 = tcs("layout(vertices = 3) out;\nout vec4 tc[];\nout float level[];\nvoid main() { tc[gl_InvocationID] = vec4(1.0); level[gl_InvocationID] = 1.0; }\n");
    let p = link(&[&v, &c2, &e, &fr]);
    assert!(!p.ok());
    assert!(p.info_log().contains("per-patch"), "{}", p.info_log());
}

#[test]
fn link_rules_of_the_layouts() {
    let v = vs(VS);
    // The output patch size is declared by some object, the same by all.
    let c =
        tcs("void f();\nvoid main() { gl_out[gl_InvocationID].gl_Position = vec4(0.0); f(); }\n");
    ok(&c);
    let p = link(&[&v, &c]);
    assert!(!p.ok());
    assert!(
        p.info_log().contains("output patch size"),
        "{}",
        p.info_log()
    );
    let c3 = tcs("layout(vertices = 3) out;\nvoid f() { }\n");
    let c4 = tcs("layout(vertices = 4) out;\n");
    assert!(link(&[&v, &c, &c3]).ok());
    assert!(!link(&[&v, &c, &c3, &c4]).ok());
    // The primitive mode likewise; spacing and order agree when given.
    let e = tes("void f();\nvoid main() { gl_Position = vec4(0.0); f(); }\n");
    let p = link(&[&v, &e]);
    assert!(!p.ok());
    assert!(p.info_log().contains("primitive mode"), "{}", p.info_log());
    let eq = tes("layout(quads, cw) in;\nvoid f() { }\n");
    let et = tes("layout(triangles) in;\n");
    let eccw = tes("layout(ccw) in;\n");
    assert!(link(&[&v, &e, &eq]).ok());
    assert!(!link(&[&v, &e, &eq, &et]).ok());
    assert!(!link(&[&v, &e, &eq, &eccw]).ok());
    // A tessellation stage needs a vertex stage.
    let lone = tcs("layout(vertices = 3) out;\nvoid main() { }\n");
    let p = link(&[&lone]);
    assert!(!p.ok());
    assert!(
        p.info_log().contains("no vertex shader"),
        "{}",
        p.info_log()
    );
}
