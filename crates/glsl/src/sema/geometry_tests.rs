//! Unit tests of the geometry stage: its built-ins, layouts, input array
//! sizing (GLSL 1.50 §4.3.8.1's examples) and link rules.

use crate::diag::Code;
use crate::ir::{InputPrimitive, OutputPrimitive, Stage, Storage};
use crate::types::ArraySize;
use crate::{compile, link::link, CompileOptions, Shader};

fn geom(src: &str) -> Shader {
    compile(&[src], &CompileOptions::new(Stage::Geometry))
}

fn stage(stage: Stage, src: &str) -> Shader {
    compile(&[src], &CompileOptions::new(stage))
}

// The checks the interface tests use.
use super::interface::tests::{fails, ok};

/// The seed lecture's "Simple Program" (vertex + geometry + fragment), its
/// geometry shader a pass-through of triangles in GLSL 1.50.
const VS: &str = "#version 150\nin vec4 position;\nout vec4 color;\nvoid main() { color = position; gl_Position = position; }";
const GS: &str = "#version 150
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec4 color[];
out vec4 fcolor;
void main()
{
    for (int i = 0; i < gl_in.length(); i++) {
        gl_Position = gl_in[i].gl_Position;
        fcolor = color[i];
        gl_PrimitiveID = gl_PrimitiveIDIn;
        EmitVertex();
    }
    EndPrimitive();
}";
const FS: &str = "#version 150\nin vec4 fcolor;\nout vec4 frag;\nvoid main() { frag = fcolor; }";

#[test]
fn pass_through_program_links() {
    let (v, g, f) = (
        stage(Stage::Vertex, VS),
        geom(GS),
        stage(Stage::Fragment, FS),
    );
    ok(&g);
    let m = g.module.as_ref().expect("compiled");
    assert_eq!(m.geometry.input, Some(InputPrimitive::Triangles));
    assert_eq!(m.geometry.output, Some(OutputPrimitive::TriangleStrip));
    assert_eq!(m.geometry.max_vertices, Some(3));
    let color = m.globals.iter().find(|x| x.name == "color").expect("input");
    assert_eq!(color.storage, Storage::PerVertexInput);
    assert_eq!(color.ty.array, Some(ArraySize::Sized(3)));
    let p = link(&[&f, &v, &g]);
    assert!(p.ok(), "{}", p.info_log());
    let stages: Vec<Stage> = p.stages.iter().map(|s| s.stage).collect();
    assert_eq!(stages, [Stage::Vertex, Stage::Geometry, Stage::Fragment]);
    assert!(m
        .to_string()
        .contains("layout(triangle_strip, max_vertices = 3) out;"));
}

#[test]
fn link_rules() {
    let (v, g, f) = (
        stage(Stage::Vertex, VS),
        geom(GS),
        stage(Stage::Fragment, FS),
    );
    // No vertex shader.
    assert!(!link(&[&g, &f]).ok());
    // The fragment input is the geometry output, not the vertex output.
    let f2 = stage(
        Stage::Fragment,
        "#version 150\nin vec4 color;\nout vec4 frag;\nvoid main() { frag = color; }",
    );
    assert!(!link(&[&v, &g, &f2]).ok());
    // A geometry input the vertex shader does not write, or of another type.
    let v2 = stage(
        Stage::Vertex,
        "#version 150\nout vec3 color;\nvoid main() { color = vec3(1.0); gl_Position = vec4(0.0); }",
    );
    let p = link(&[&v2, &g, &f]);
    assert!(!p.ok());
    assert!(p.info_log().contains("geometry"), "{}", p.info_log());
    // Layouts split across objects link; a missing or contradicting one
    // does not.
    let main = geom("#version 150\nlayout(points) in;\nvoid emit();\nvoid main() { emit(); }");
    let out = geom(
        "#version 150\nlayout(points, max_vertices = 1) out;\nvoid emit() { gl_Position = gl_in[0].gl_Position; EmitVertex(); }",
    );
    ok(&main);
    ok(&out);
    assert!(link(&[&v, &main, &out]).ok());
    assert!(!link(&[&v, &main]).ok());
    let lines =
        geom("#version 150\nlayout(lines) in;\nlayout(points, max_vertices = 1) out;\nvoid f() {}");
    assert!(!link(&[&v, &main, &out, &lines]).ok());
}

#[test]
fn input_sizing_follows_the_spec_examples() {
    // §4.3.8.1: an unsized input takes the primitive's size, before or
    // after the layout; sizes must agree with it and with each other.
    ok(&geom(
        "#version 150\nlayout(lines) in;\nin vec4 c[];\nuniform int u[c.length() == 2 ? 1 : -1];",
    ));
    ok(&geom(
        "#version 150\nin vec4 c[];\nlayout(lines) in;\nuniform int u[c.length() == 2 ? 1 : -1];",
    ));
    ok(&geom(
        "#version 150\nin vec4 c[];\nvec4 f() { return c[2]; }\nlayout(triangles) in;",
    ));
    ok(&geom(
        "#version 150\nin vec4 a[3];\nlayout(triangles) in;\nlayout(triangles) in;",
    ));
    fails(
        &geom("#version 150\nin vec4 c[];\nvec4 f() { return c[2]; }\nlayout(lines) in;"),
        Code::IndexOutOfRange,
    );
    fails(
        &geom("#version 150\nin vec4 c[];\nint f() { return c.length(); }\nlayout(lines) in;"),
        Code::BadArraySize,
    );
    fails(
        &geom("#version 150\nin vec4 a[2];\nin vec4 b[3];"),
        Code::BadArraySize,
    );
    fails(
        &geom("#version 150\nin vec4 a[3];\nlayout(lines) in;"),
        Code::BadArraySize,
    );
    fails(
        &geom("#version 150\nlayout(lines) in;\nin vec4 a[3];"),
        Code::BadArraySize,
    );
    fails(
        &geom("#version 150\nlayout(lines) in;\nlayout(triangles) in;"),
        Code::Redeclared,
    );
    // Blocks: arrays, sized the same way.
    ok(&geom("#version 150\nin B { vec4 p; } b[];\nlayout(triangles) in;\nuniform int u[b.length() == 3 ? 1 : -1];"));
    fails(
        &geom("#version 150\nin B { vec4 p; } b;"),
        Code::TypeMismatch,
    );
    fails(&geom("#version 150\nin vec4 c;"), Code::TypeMismatch);
}

#[test]
fn layouts_belong_to_geometry_shaders() {
    fails(
        &geom("#version 150\nlayout(points, points) in;"),
        Code::BadQualifier,
    );
    fails(
        &geom("#version 150\nlayout(line_strip) in;"),
        Code::BadQualifier,
    );
    fails(
        &geom("#version 150\nlayout(triangles) out;"),
        Code::BadQualifier,
    );
    fails(
        &geom("#version 150\nlayout(std140) in;"),
        Code::BadQualifier,
    );
    fails(
        &geom("#version 150\nlayout(points) in float c[];"),
        Code::BadQualifier,
    );
    fails(
        &geom("#version 150\nlayout(max_vertices = 257) out;"),
        Code::BadQualifier,
    );
    ok(&geom("#version 150\nlayout(max_vertices = 256) out;"));
    fails(
        &geom("#version 150\nlayout(max_vertices = 2) out;\nlayout(max_vertices = 3) out;"),
        Code::Redeclared,
    );
    fails(
        &stage(Stage::Vertex, "#version 150\nlayout(triangles) in;"),
        Code::StageMismatch,
    );
    // A geometry shader needs GLSL 1.50.
    fails(&geom("#version 130\nvoid main() {}"), Code::VersionTooLow);
}

/// Without #version a shader is GLSL 1.10, which has no geometry stage;
/// a core profile context has no 1.10 at all, so there a versionless
/// geometry shader compiles as 1.50 core, with a warning saying so.
#[test]
fn versionless_geometry_shaders_are_150_on_core_contexts() {
    let src = "void main() { gl_Position = vec4(gl_DepthRange.near); EmitVertex(); }";
    let mut opts = CompileOptions::new(Stage::Geometry);
    opts.compatibility_context = false;
    let core = compile(&[src], &opts);
    assert!(core.ok(), "{}", core.info_log());
    assert_eq!(core.language.version, crate::Version::V150);
    assert!(core
        .info_log()
        .contains("no #version directive: compiled as GLSL 1.50"));
    fails(&geom(src), Code::VersionTooLow);
    // An explicit version is kept.
    let old = compile(&["#version 130\nvoid main() {}"], &opts);
    assert!(!old.ok());
}

#[test]
fn builtins_of_the_geometry_stage() {
    ok(&geom(
        "#version 150\nlayout(points) in;\nvoid main() { gl_Layer = gl_PrimitiveIDIn; gl_PointSize = gl_in[0].gl_PointSize; gl_ClipDistance[0] = 1.0; EmitVertex(); EndPrimitive(); }",
    ));
    // Inputs are read-only; no derivatives or bias forms; EmitVertex only
    // here.
    fails(
        &geom("#version 150\nin vec4 c[];\nvoid main() { c[0] = vec4(1.0); }"),
        Code::ReadOnly,
    );
    fails(
        &geom("#version 150\nvoid main() { gl_PrimitiveIDIn = 1; }"),
        Code::ReadOnly,
    );
    fails(
        &geom("#version 150\nin float c[];\nvoid main() { gl_Position = vec4(dFdx(c[0])); }"),
        Code::StageMismatch,
    );
    fails(
        &stage(Stage::Vertex, "#version 150\nvoid main() { EmitVertex(); }"),
        Code::StageMismatch,
    );
    // The compatibility profile's `gl_in[]' has the colours (§7.1.1).
    ok(&geom("#version 150 compatibility\nlayout(points) in;\nvoid main() { gl_FrontColor = gl_in[0].gl_FrontColor; gl_TexCoord[0] = gl_in[0].gl_TexCoord[0]; }"));
    let core = geom(
        "#version 150\nlayout(points) in;\nvoid main() { gl_Position = gl_in[0].gl_FrontColor; }",
    );
    assert!(!core.ok());
}

#[test]
fn invariant_on_geometry_inputs_and_outputs() {
    let vs = |inv: &str| {
        stage(
            Stage::Vertex,
            &format!("#version 150\nin vec4 p;\n{inv} out vec4 pos;\nvoid main() {{ gl_Position = p; pos = p; }}"),
        )
    };
    let gs = |inv_in: &str, inv_out: &str| {
        geom(&format!(
            "#version 150\nlayout(triangles) in;\nlayout(points, max_vertices = 1) out;\n\
             {inv_in} in vec4 pos[];\n{inv_out} out vec4 c;\ninvariant gl_Position;\n\
             void main() {{ c = pos[0]; gl_Position = pos[1]; EmitVertex(); }}"
        ))
    };
    let fs = |inv: &str| {
        stage(
            Stage::Fragment,
            &format!("#version 150\nin vec4 c;\n{inv}\nout vec4 o;\nvoid main() {{ o = c; }}"),
        )
    };
    ok(&gs("invariant", "invariant"));
    // The identifier-list form on an input.
    ok(&geom(
        "#version 150\nlayout(triangles) in;\nlayout(points, max_vertices = 1) out;\n\
         in vec4 pos[];\ninvariant pos;\nvoid main() { gl_Position = pos[0]; EmitVertex(); }",
    ));
    // Still not on a uniform, nor on a vertex input.
    fails(
        &geom("#version 150\nlayout(triangles) in;\ninvariant uniform vec4 u;\nvoid main() {}"),
        Code::BadQualifier,
    );
    fails(
        &stage(
            Stage::Vertex,
            "#version 150\ninvariant in vec4 p;\nvoid main() { gl_Position = p; }",
        ),
        Code::BadQualifier,
    );
    // Both sides of each interface agree, or the link fails.
    for (v, gi, go, f, links) in [
        ("invariant", "invariant", "invariant", "invariant c;", true),
        ("", "", "", "", true),
        ("invariant", "", "invariant", "invariant c;", false),
        ("invariant", "invariant", "invariant", "", false),
    ] {
        let p = link(&[&vs(v), &gs(gi, go), &fs(f)]);
        assert_eq!(p.ok(), links, "{v}/{gi}/{go}/{f}\n{}", p.info_log());
    }
}

#[test]
fn struct_varyings_cross_the_geometry_stage() {
    let s = "struct Foo { mat2 a; vec3 b; };\n";
    let vs = stage(
        Stage::Vertex,
        &format!("#version 150\n{s}out Foo foo;\nvoid main() {{ gl_Position = vec4(0.0); foo.b = vec3(1.0); }}"),
    );
    let gs = geom(&format!(
        "#version 150\nlayout(triangles) in;\nlayout(points, max_vertices = 1) out;\n{s}\
         in Foo foo[];\nout Foo bar;\nvoid main() {{ bar = foo[0]; gl_Position = vec4(foo[1].b, 1.0); EmitVertex(); }}"
    ));
    let fs = stage(
        Stage::Fragment,
        &format!("#version 150\n{s}in Foo bar;\nout vec4 o;\nvoid main() {{ o = vec4(bar.b, bar.a[0].x); }}"),
    );
    let p = link(&[&vs, &gs, &fs]);
    assert!(p.ok(), "{}", p.info_log());
    // A struct of another shape, or of another name, does not match.
    for other in [
        "struct Foo { mat2 a; vec4 b; };\n",
        "struct Foo { mat2 a; vec3 c; };\n",
    ] {
        let fs = stage(
            Stage::Fragment,
            &format!("#version 150\n{other}in Foo bar;\nout vec4 o;\nvoid main() {{ o = vec4(bar.a[0].x); }}"),
        );
        let p = link(&[&vs, &gs, &fs]);
        assert!(!p.ok(), "{other}");
        assert!(p.info_log().contains("varying `bar'"), "{}", p.info_log());
    }
}

#[test]
fn unsized_input_block_arrays_take_the_stage_size() {
    let vs = stage(
        Stage::Vertex,
        "#version 150\nout Blk { vec4 a; } i;\nvoid main() { i.a = vec4(1.0); gl_Position = vec4(1.0); }",
    );
    let sized = "#version 150\nlayout(lines_adjacency) in;\nlayout(triangle_strip, max_vertices = 3) out;\n\
                 in Blk { vec4 a; } i[4];\nvec4 f();\nvoid main() { gl_Position = i[3].a + f(); EmitVertex(); }";
    let unsized_ = "#version 150\nin Blk { vec4 a; } i[];\nvec4 f() { return i[3].a; }";
    for objects in [[sized, unsized_], [unsized_, sized]] {
        let (a, b) = (geom(objects[0]), geom(objects[1]));
        ok(&a);
        ok(&b);
        let p = link(&[&vs, &a, &b]);
        assert!(p.ok(), "{}", p.info_log());
        let m = &p.stage(Stage::Geometry).expect("geometry").module;
        let blk = m.blocks.iter().find(|b| b.name == "Blk").expect("block");
        assert_eq!(blk.array, Some(4));
    }
    // Two different sizes still differ.
    let other = geom("#version 150\nin Blk { vec4 a; } i[3];\nvec4 f() { return i[0].a; }");
    assert!(!link(&[&vs, &geom(sized), &other]).ok());
}

#[test]
fn uniforms_match_between_vertex_and_fragment_around_a_geometry_stage() {
    let gs = geom(
        "#version 150\nlayout(triangles) in;\nlayout(triangle_strip, max_vertices = 3) out;\n\
         void main() { for (int i = 0; i < 3; i++) { gl_Position = gl_in[i].gl_Position; EmitVertex(); } }",
    );
    let vs = |decl: &str, read: &str| {
        stage(
            Stage::Vertex,
            &format!("#version 150\n{decl}\nvoid main() {{ gl_Position = vec4({read}); }}"),
        )
    };
    let fs = |decl: &str, read: &str| {
        stage(
            Stage::Fragment,
            &format!("#version 150\n{decl}\nvoid main() {{ gl_FragColor = vec4({read}); }}"),
        )
    };
    for (v, f, links) in [
        (
            ("uniform Foo { vec4 x; } foo[3];", "foo[0].x"),
            ("uniform Foo { vec4 x; } bar[3];", "bar[0].x"),
            true,
        ),
        (
            ("uniform Foo { vec4 x; } foo[3];", "foo[0].x"),
            ("uniform Foo { vec4 x; } bar[2];", "bar[0].x"),
            false,
        ),
        (
            ("uniform Foo { vec4 x; };", "x"),
            ("uniform Foo { vec3 x; };", "x, 1.0"),
            false,
        ),
        (("uniform vec4 u;", "u"), ("uniform vec4 u;", "u"), true),
        (
            ("uniform vec4 u;", "u"),
            ("uniform vec3 u;", "u, 1.0"),
            false,
        ),
    ] {
        let p = link(&[&vs(v.0, v.1), &gs, &fs(f.0, f.1)]);
        assert_eq!(p.ok(), links, "{v:?} / {f:?}\n{}", p.info_log());
    }
}
