//! Unit tests of the GLSL 1.30-3.30 declarations: storage, interpolation,
//! precision and layout qualifiers, blocks, and their link rules.

use crate::diag::Code;
use crate::ir::{BlockLayout, Interpolation, Stage, Storage};
use crate::{compile, CompileOptions, Shader};

fn frag(src: &str) -> Shader {
    compile(&[src], &CompileOptions::new(Stage::Fragment))
}

fn vert(src: &str) -> Shader {
    compile(&[src], &CompileOptions::new(Stage::Vertex))
}

#[track_caller]
pub(crate) fn ok(s: &Shader) {
    assert!(s.ok(), "expected success:\n{}", s.info_log());
}

#[track_caller]
pub(crate) fn fails(s: &Shader, code: Code) {
    let codes: Vec<Code> = s
        .diagnostics
        .iter()
        .filter(|d| d.is_error())
        .map(|d| d.code)
        .collect();
    assert!(!s.ok(), "expected failure");
    assert!(codes.contains(&code), "{codes:?}\n{}", s.info_log());
}

pub(crate) fn global<'a>(s: &'a Shader, name: &str) -> &'a crate::ir::Global {
    let m = s.module.as_ref().expect("compiled");
    m.globals
        .iter()
        .find(|g| g.name == name)
        .expect("global exists")
}

/// The type of global `name`, spelled.
pub(crate) fn global_type(s: &Shader, name: &str) -> String {
    let m = s.module.as_ref().expect("compiled");
    m.type_name(global(s, name).ty)
}

#[test]
fn stage_inputs_and_outputs_map_to_storages() {
    let v = vert(
        "#version 130\nin vec4 p; centroid out vec2 t; flat out int k; noperspective out float z;\n\
         void main() { gl_Position = p; t = p.xy; k = 1; z = 0.0; }",
    );
    ok(&v);
    assert_eq!(global(&v, "p").storage, Storage::Attribute);
    assert_eq!(global(&v, "t").storage, Storage::Varying);
    assert!(global(&v, "t").centroid);
    assert_eq!(global(&v, "k").interpolation, Some(Interpolation::Flat));
    assert_eq!(
        global(&v, "z").interpolation,
        Some(Interpolation::NoPerspective)
    );
    let f = frag("#version 130\nin vec2 t; out vec4 c; void main() { c = t.xyxy; }");
    ok(&f);
    assert_eq!(global(&f, "t").storage, Storage::Varying);
    assert_eq!(global(&f, "c").storage, Storage::FragOutput);
}

#[test]
fn in_out_need_130_and_global_scope() {
    fails(
        &vert("in vec4 p; void main() { gl_Position = p; }"),
        Code::BadQualifier,
    );
    fails(
        &vert("#version 130\nvoid main() { in vec4 p; gl_Position = vec4(0); }"),
        Code::BadQualifier,
    );
    fails(
        &vert("#version 130\ninout vec4 p; void main() {}"),
        Code::BadQualifier,
    );
    // The message names the version that has them.
    let s = vert("#version 120\nin vec4 p; void main() { gl_Position = p; }");
    assert!(s.info_log().contains("needs GLSL 1.30"), "{}", s.info_log());
}

#[test]
fn interpolation_rules() {
    // Only on vertex outputs and fragment inputs, never on varying.
    fails(
        &vert("#version 130\nflat in vec4 p; void main() {}"),
        Code::BadQualifier,
    );
    fails(
        &frag("#version 130\nflat out vec4 c; void main() {}"),
        Code::BadQualifier,
    );
    fails(
        &frag("#version 130\nsmooth varying float x; void main() {}"),
        Code::BadQualifier,
    );
    fails(
        &frag("#version 130\nflat smooth in float x; void main() {}"),
        Code::BadQualifier,
    );
    fails(
        &frag("#version 130\nvoid main() { smooth float x = 0.0; }"),
        Code::BadQualifier,
    );
    // Integer fragment inputs must be flat; integer vertex outputs need not.
    fails(
        &frag("#version 130\nin int i; void main() {}"),
        Code::BadQualifier,
    );
    ok(&frag("#version 130\nflat in int i; void main() {}"));
    ok(&vert("#version 130\nout int i; void main() { i = 1; }"));
    // Interpolation qualifiers exist from 1.30 on.
    fails(
        &frag("#version 120\nflat varying float x; void main() {}"),
        Code::Syntax,
    );
    // The colour varyings may be redeclared with one.
    let f = frag("#version 130\nflat in vec4 gl_Color; void main() { gl_FragColor = gl_Color; }");
    ok(&f);
    assert_eq!(
        global(&f, "gl_Color").interpolation,
        Some(Interpolation::Flat)
    );
}

#[test]
fn qualifier_order_is_strict() {
    ok(&vert(
        "#version 130\ninvariant smooth centroid out highp float x; void main() { x = 0.0; }",
    ));
    for bad in [
        "smooth invariant out float x;",
        "smooth out invariant float x;",
        "highp smooth out float x;",
        "centroid smooth out float x;",
    ] {
        fails(
            &vert(&format!("#version 130\n{bad} void main() {{}}")),
            Code::BadQualifier,
        );
    }
    ok(&vert(
        "#version 130\nfloat f(const in highp float x) { return x; } void main() {}",
    ));
    fails(
        &vert("#version 130\nfloat f(highp in float x) { return x; } void main() {}"),
        Code::BadQualifier,
    );
}

#[test]
fn storage_types_per_version() {
    fails(
        &frag("#version 130\nflat in bool b; void main() {}"),
        Code::TypeMismatch,
    );
    fails(
        &frag("#version 130\nstruct S { vec4 v; }; in S s; void main() {}"),
        Code::TypeMismatch,
    );
    fails(
        &vert("#version 130\nin float a[2]; void main() {}"),
        Code::TypeMismatch,
    );
    ok(&vert(
        "#version 150\nin float a[2]; void main() { gl_Position = vec4(a[0]); }",
    ));
    ok(&frag(
        "#version 150\nflat in struct A { int x; vec3 z; } a; out vec4 c; void main() { c = vec4(a.z, 1.0); }",
    ));
    fails(
        &frag("#version 130\nout mat4 m; void main() {}"),
        Code::TypeMismatch,
    );
    fails(
        &frag("#version 130\ncentroid out vec4 c; void main() {}"),
        Code::BadQualifier,
    );
    fails(
        &vert("#version 130\ncentroid in vec4 c; void main() {}"),
        Code::BadQualifier,
    );
    fails(
        &frag("#version 130\nin float x; void main() { x = 1.0; }"),
        Code::ReadOnly,
    );
}

#[test]
fn user_outputs_exclude_gl_fragcolor() {
    fails(
        &frag("#version 130\nout vec4 c; void main() { gl_FragColor = vec4(1); if (false) c = vec4(0); }"),
        Code::TypeMismatch,
    );
    ok(&frag(
        "#version 130\nout vec4 unused; void main() { gl_FragColor = vec4(1); }",
    ));
}

#[test]
fn precision_qualifiers() {
    ok(&frag(
        "#version 130\nprecision mediump float; precision lowp int; precision highp sampler2D;\n\
         uniform lowp sampler2D s; highp float a[4]; struct S { lowp float x; };\n\
         highp float f(lowp int x) { mediump vec2 v; return 1.0; } void main() {}",
    ));
    fails(
        &frag("#version 130\nprecision highp bool; void main() {}"),
        Code::BadQualifier,
    );
    fails(
        &frag("#version 130\nprecision highp vec2; void main() {}"),
        Code::BadQualifier,
    );
    fails(
        &frag("#version 130\nvoid main() { highp bool b; }"),
        Code::BadQualifier,
    );
    fails(
        &frag("#version 130\nhighp struct S { float a; }; void main() {}"),
        Code::BadQualifier,
    );
    fails(
        &frag("#version 130\nvoid main() { lowp lowp float x; }"),
        Code::BadQualifier,
    );
}

#[test]
fn explicit_locations() {
    let ext = "#version 110\n#extension GL_ARB_explicit_attrib_location : require\n";
    let v = vert(&format!(
        "{ext}layout(location = 0x3) in vec4 p; void main() {{ gl_Position = p; }}"
    ));
    ok(&v);
    assert_eq!(global(&v, "p").location, Some(3));
    let f = frag(&format!(
        "{ext}layout(location = 1) out vec4 c; void main() {{ c = vec4(1); }}"
    ));
    ok(&f);
    for bad in [
        "layout(location = 0.0) out vec4 c;",
        "layout(location = 1 - 1) out vec4 c;",
        "out layout(location = 0) vec4 c;",
        "layout(location = 0) varying vec4 c;",
        "layout(location = 0) uniform vec4 c;",
        "layout(locaton = 0) out vec4 c;",
        "layout(location) out vec4 c;",
    ] {
        let s = frag(&format!("{ext}{bad} void main() {{}}"));
        assert!(!s.ok(), "{bad}");
    }
    // Without the extension, 3.30 has it and 1.50 does not.
    ok(&frag(
        "#version 330\nlayout(location = 0) out vec4 c; void main() { c = vec4(1); }",
    ));
    let s = frag("#version 150\nlayout(location = 0) out vec4 c; void main() { c = vec4(1); }");
    assert!(
        s.info_log().contains("GL_ARB_explicit_attrib_location"),
        "{}",
        s.info_log()
    );
    // `layout' is an identifier where no extension makes it a keyword.
    ok(&frag("#version 130\nfloat layout; void main() {}"));
}

#[test]
fn frag_coord_layouts() {
    ok(&frag(
        "#version 150\nlayout(PIXEL_center_inTEger) in vec4 gl_FragCoord; out vec4 c; void main() { c = gl_FragCoord; }",
    ));
    let f = frag("#version 150\nlayout(origin_upper_left) in vec4 gl_FragCoord; out vec4 c; void main() { c = gl_FragCoord; }");
    ok(&f);
    assert!(f
        .module
        .as_ref()
        .is_some_and(|m| m.frag_coord.origin_upper_left));
    fails(
        &frag("#version 150\nvec4 p = gl_FragCoord;\nlayout(origin_upper_left) in vec4 gl_FragCoord; void main() {}"),
        Code::Redeclared,
    );
    fails(
        &frag("#version 150\nlayout(origin_upper_left) in vec4 gl_FragCoord;\nin vec4 gl_FragCoord; void main() {}"),
        Code::Redeclared,
    );
    fails(
        &frag("#version 130\nlayout(origin_upper_left) in vec4 gl_FragCoord; void main() {}"),
        Code::Syntax,
    );
    fails(
        &frag("#version 150\nlayout(points) out vec4 b; void main() {}"),
        Code::StageMismatch,
    );
}

#[test]
fn uniform_blocks() {
    let v = vert(
        "#version 140\nlayout(std140) uniform;\n\
         uniform B { vec4 a; layout(row_major) mat4 m; };\n\
         uniform C { vec4 b; } c[2];\n\
         void main() { gl_Position = a * m + c[1].b; }",
    );
    ok(&v);
    let m = v.module.as_ref().expect("compiled");
    assert_eq!(m.blocks.len(), 2);
    assert_eq!(m.blocks[0].layout, BlockLayout::Std140);
    assert!(m.blocks[0].members[1].row_major);
    assert_eq!(m.blocks[1].array, Some(2));
    assert_eq!(global(&v, "a").block, Some(crate::ir::BlockId(0)));
    assert_eq!(global(&v, "c").storage, Storage::Uniform);
    for bad in [
        "uniform B { sampler2D s; };",
        "uniform B { float x = 1.0; };",
        "uniform B { float x; }; float x;",
        "float x; uniform B { float x; };",
        "uniform B { float x; }; uniform B { float y; };",
        "uniform B { varying float x; };",
        "uniform B { float x; float x; };",
        "uniform a { vec4 b; }; float a;",
        "uniform a { vec4 b; }; struct a { vec4 c; };",
        "uniform a { vec4 b; }; float a(void) { return b.x; }",
        "struct a { vec4 c; }; uniform a { vec4 b; };",
    ] {
        let s = vert(&format!("#version 140\n{bad} void main() {{}}"));
        assert!(!s.ok(), "{bad}");
    }
    fails(
        &vert("#version 130\nuniform B { float x; }; void main() {}"),
        Code::VersionTooLow,
    );
    ok(&vert(
        "#version 130\n#extension GL_ARB_uniform_buffer_object : enable\nlayout(std140) uniform B { float x; }; void main() { gl_Position = vec4(x); }",
    ));
}

#[test]
fn uniform_block_arrays_take_constant_indices() {
    fails(
        &vert(
            "#version 140\nuniform B { vec4 v; } b[2]; uniform int i;\n\
             void main() { gl_Position = b[i].v; }",
        ),
        Code::NotConstant,
    );
    ok(&vert(
        "#version 140\nuniform B { vec4 v; } b[2]; void main() { gl_Position = b[1].v; }",
    ));
}

#[test]
fn in_out_blocks() {
    ok(&vert(
        "#version 150\nout B { smooth out vec4 v; } b; void main() { b.v = vec4(1); gl_Position = vec4(0); }",
    ));
    fails(
        &vert("#version 150\nin B { vec4 v; } b; void main() {}"),
        Code::StageMismatch,
    );
    fails(
        &frag("#version 150\nout B { vec4 v; } b; void main() {}"),
        Code::StageMismatch,
    );
    fails(
        &vert("#version 140\nout B { vec4 v; } b; void main() {}"),
        Code::VersionTooLow,
    );
    fails(
        &frag("#version 150\nin B { vec4 v; } b; void main() { b.v = vec4(0); }"),
        Code::ReadOnly,
    );
}

#[test]
fn link_matches_interpolation_blocks_and_locations() {
    let link = |v: &str, f: &str| {
        let (v, f) = (vert(v), frag(f));
        ok(&v);
        ok(&f);
        crate::link::link(&[&v, &f])
    };
    let p = link(
        "#version 130\nin vec4 p; out vec3 v; void main() { gl_Position = p; v = p.xyz; }",
        "#version 130\nin vec3 v; out vec4 c; void main() { c = vec4(v, 1.0); }",
    );
    assert!(p.ok(), "{}", p.info_log());
    let p = link(
        "#version 130\nflat out vec3 v; void main() { gl_Position = vec4(0); v = vec3(0); }",
        "#version 130\nsmooth in vec3 v; out vec4 c; void main() { c = vec4(v, 1.0); }",
    );
    assert!(!p.ok());
    assert!(p.info_log().contains("interpolated"), "{}", p.info_log());
    let p = link(
        "#version 150\nout B { vec4 v; } b; void main() { b.v = vec4(0); }",
        "#version 150\nin B { vec4 v; } other; out vec4 c; void main() { c = other.v; }",
    );
    assert!(p.ok(), "{}", p.info_log());
    let p = link(
        "#version 150\nout B { vec3 v; } b; void main() { b.v = vec3(0); }",
        "#version 150\nin B { vec4 v; } b; out vec4 c; void main() { c = b.v; }",
    );
    assert!(!p.ok());
    let p = link(
        "#version 150\nvoid main() { gl_Position = vec4(0); }",
        "#version 150\nin B { vec4 v; } b; out vec4 c; void main() { c = b.v; }",
    );
    assert!(!p.ok());
    let p = link(
        "#version 330\nvoid main() { gl_Position = vec4(0); }",
        "#version 330\nlayout(location = 1) out vec4 a; layout(location = 1) out vec4 b;\n\
         void main() { a = vec4(0); b = vec4(1); }",
    );
    assert!(!p.ok());
    let p = link(
        "#version 330\nlayout(location = 15) in mat2 m; void main() { gl_Position = vec4(m[0], m[1]); }",
        "#version 330\nout vec4 c; void main() { c = vec4(0); }",
    );
    assert!(!p.ok(), "a mat2 at 15 needs locations 15 and 16");
    // Aliased vertex inputs link (GL 2.0 allows aliasing).
    let p = link(
        "#version 330\nlayout(location = 0) in vec4 a; layout(location = 0) in vec4 b;\n\
         void main() { gl_Position = a + b; }",
        "#version 330\nout vec4 c; void main() { c = vec4(0); }",
    );
    assert!(p.ok(), "{}", p.info_log());
}

#[test]
fn built_in_colors_match_gl_color_interpolation() {
    let link = |v: &str, f: &str| crate::link::link(&[&vert(v), &frag(f)]);
    let vs = |decl: &str| {
        format!("#version 130\n{decl}\nvoid main() {{ gl_Position = vec4(0); gl_FrontColor = vec4(0); }}")
    };
    let fs = |decl: &str, read: bool| {
        let body = if read {
            "c = gl_Color;"
        } else {
            "c = vec4(0);"
        };
        format!("#version 130\n{decl}\nout vec4 c;\nvoid main() {{ {body} }}")
    };
    // An unqualified declaration matches only an unqualified one.
    assert!(!link(&vs("smooth out vec4 gl_FrontColor;"), &fs("", true)).ok());
    assert!(!link(&vs(""), &fs("flat in vec4 gl_Color;", true)).ok());
    assert!(link(&vs(""), &fs("", true)).ok());
    let p = link(
        &vs("flat out vec4 gl_FrontColor;"),
        &fs("flat in vec4 gl_Color;", true),
    );
    assert!(p.ok(), "{}", p.info_log());
    // Only statically used variables are compared.
    assert!(link(
        &vs("flat out vec4 gl_FrontColor;"),
        &fs("in vec4 gl_Color;", false)
    )
    .ok());
    let p = link(&vs("smooth out vec4 gl_FrontColor;"), &fs("", true));
    assert!(p.info_log().contains("§4.3.7"), "{}", p.info_log());
}

#[test]
fn frag_coord_redeclarations_agree_across_objects() {
    let vs = vert("#version 150\nin vec4 p; void main() { gl_Position = p; }");
    let main = |decl: &str| {
        frag(&format!(
            "#version 150\n{decl}\nvoid foo();\nvoid main() {{ gl_FragColor = gl_FragCoord; foo(); }}"
        ))
    };
    let foo =
        |decl: &str, body: &str| frag(&format!("#version 150\n{decl}\nvoid foo() {{ {body} }}"));
    let link = |a: &Shader, b: &Shader| crate::link::link(&[&vs, a, b]);
    let ul = "layout(origin_upper_left) in vec4 gl_FragCoord;";
    let both = "layout(origin_upper_left, pixel_center_integer) in vec4 gl_FragCoord;";
    assert!(link(&main(ul), &foo(ul, "")).ok());
    assert!(
        !link(&main(ul), &foo(both, "")).ok(),
        "different qualifiers"
    );
    // An object that uses gl_FragCoord must redeclare it as the others do;
    // one that does not use it need not.
    assert!(!link(&main(ul), &foo("", "vec4 x = gl_FragCoord;")).ok());
    assert!(link(&main(ul), &foo("", "")).ok());
}

#[test]
fn integer_members_of_fragment_input_blocks_are_flat() {
    fails(
        &frag("#version 150\nin B { int i; } b; void main() {}"),
        Code::BadQualifier,
    );
    ok(&frag(
        "#version 150\nin B { flat int i; } b; void main() {}",
    ));
    ok(&frag(
        "#version 150\nflat in B { int i; } b; void main() {}",
    ));
}

#[test]
fn fragment_output_index_needs_a_location() {
    let ext = "#version 110\n#extension GL_ARB_explicit_attrib_location : require\n";
    let f = frag(&format!(
        "{ext}layout(location = 0, index = 1) out vec4 c; \
         layout(location = 0) out vec4 d; void main() {{ c = vec4(1); d = c; }}"
    ));
    ok(&f);
    // The index is kept for the GL layer (dual-source blending).
    assert_eq!(global(&f, "c").index, Some(1));
    assert_eq!(global(&f, "d").index, None);
    let f = frag(
        "#version 330\nlayout(location = 0, index = 0) out vec4 c; void main() { c = vec4(1); }",
    );
    ok(&f);
    assert_eq!(global(&f, "c").index, Some(0));
    // GL_ARB_blend_func_extended is accepted (and defined) beside the
    // explicit-location extension that brings `layout(index)` to 1.50.
    let f = frag(
        "#version 150\n\
         #extension GL_ARB_blend_func_extended : require\n\
         #extension GL_ARB_explicit_attrib_location : require\n\
         #ifndef GL_ARB_blend_func_extended\n\
         #error not defined\n\
         #endif\n\
         layout(location = 0, index = 1) out vec4 c; void main() { c = vec4(1); }",
    );
    ok(&f);
    assert_eq!(global(&f, "c").index, Some(1));
    fails(
        &frag(&format!(
            "{ext}layout(index = 1) out vec4 c; void main() {{}}"
        )),
        Code::BadQualifier,
    );
}

/// Links the shaders (each compiled, and checked to compile).
fn link_all(shaders: &[Shader]) -> crate::link::Program {
    for s in shaders {
        ok(s);
    }
    let refs: Vec<&Shader> = shaders.iter().collect();
    crate::link::link(&refs)
}

const FS_WHITE: &str = "#version 150\nvoid main() { gl_FragColor = vec4(1.0); }";

#[test]
fn per_vertex_output_redeclared() {
    // A subset of the members: the others are no longer names.
    let s = vert(
        "#version 150\nin vec4 p; out gl_PerVertex { vec4 gl_Position; float gl_PointSize; };\n\
         void main() { gl_Position = p; gl_PointSize = 2.0; }",
    );
    ok(&s);
    let m = s.module.as_ref().expect("compiled");
    let names: Vec<&str> = m
        .per_vertex_out
        .as_ref()
        .expect("redeclared")
        .iter()
        .map(|x| x.name.as_str())
        .collect();
    assert_eq!(names, ["gl_Position", "gl_PointSize"]);
    // The members stay the built-in outputs, not block members.
    assert!(global(&s, "gl_Position").builtin);
    assert!(m.blocks.is_empty());
    fails(
        &vert(
            "#version 150\nout gl_PerVertex { vec4 gl_Position; };\n\
             void main() { gl_Position = vec4(0); gl_PointSize = 1.0; }",
        ),
        Code::Undeclared,
    );
    // Not a member, a wrong type, an instance name, after a use, twice.
    fails(
        &vert(
            "#version 150\nout gl_PerVertex { vec4 gl_Position; vec4 gl_Color; };\nvoid main() {}",
        ),
        Code::Redeclared,
    );
    fails(
        &vert("#version 150\nout gl_PerVertex { vec3 gl_Position; };\nvoid main() {}"),
        Code::TypeMismatch,
    );
    fails(
        &vert("#version 150\nout gl_PerVertex { vec4 gl_Position; } pv;\nvoid main() {}"),
        Code::BadQualifier,
    );
    fails(
        &vert(
            "#version 150\nvoid f() { gl_Position = vec4(0); }\n\
             out gl_PerVertex { vec4 gl_Position; };\nvoid main() { f(); }",
        ),
        Code::Redeclared,
    );
    fails(
        &vert(
            "#version 150\nout gl_PerVertex { vec4 gl_Position; };\n\
             out gl_PerVertex { vec4 gl_Position; };\nvoid main() {}",
        ),
        Code::Redeclared,
    );
    // A member is redeclared in the block or on its own, not both.
    for src in [
        "out float gl_ClipDistance[];\nout gl_PerVertex { vec4 gl_Position; float gl_ClipDistance[4]; };",
        "out gl_PerVertex { vec4 gl_Position; };\nout float gl_ClipDistance[4];",
    ] {
        fails(
            &vert(&format!("#version 150\n{src}\nvoid main() {{}}")),
            Code::Redeclared,
        );
    }
    // A sized gl_ClipDistance sizes the built-in.
    let s = vert(
        "#version 150\nout gl_PerVertex { vec4 gl_Position; float gl_ClipDistance[3]; };\n\
         void main() { gl_Position = vec4(0); gl_ClipDistance[2] = 1.0; }",
    );
    ok(&s);
    assert_eq!(
        global(&s, "gl_ClipDistance").ty.array,
        Some(crate::types::ArraySize::Sized(3))
    );
}

#[test]
fn per_vertex_redeclarations_agree_within_a_stage() {
    let main = "#version 150\nout gl_PerVertex { vec4 gl_Position; };\n\
                void foo();\nvoid main() { gl_Position = vec4(1.0); foo(); }";
    // Another object redeclaring it otherwise.
    let p = link_all(&[
        vert(main),
        vert("#version 150\nout gl_PerVertex { float gl_PointSize; };\nvoid foo() { gl_PointSize = 1.0; }"),
        frag(FS_WHITE),
    ]);
    assert!(!p.ok());
    assert!(p.info_log().contains("other members"), "{}", p.info_log());
    // Another object using a member without redeclaring it.
    let p = link_all(&[
        vert(main),
        vert("#version 150\nvoid foo() { gl_PointSize = 1.0; }"),
        frag(FS_WHITE),
    ]);
    assert!(!p.ok());
    assert!(p.info_log().contains("gl_PointSize"), "{}", p.info_log());
    // An object that uses no member need not redeclare it; the same
    // redeclaration everywhere links.
    for other in [
        "#version 150\nvoid foo() {}",
        "#version 150\nout gl_PerVertex { vec4 gl_Position; };\nvoid foo() { gl_Position.x = 0.0; }",
    ] {
        let p = link_all(&[vert(main), vert(other), frag(FS_WHITE)]);
        assert!(p.ok(), "{}", p.info_log());
    }
}

#[test]
fn unsized_block_members_are_sized_by_use() {
    let vs = |decl: &str, body: &str| {
        vert(&format!(
            "#version 150\nout blk {{ float foo[]; }}{decl};\nvoid main() {{ {body} gl_Position = vec4(0); }}"
        ))
    };
    let fs = |decl: &str, body: &str| {
        frag(&format!(
            "#version 150\nin blk {{ float foo[]; }}{decl};\nvoid main() {{ gl_FragColor = vec4({body}); }}"
        ))
    };
    // Named instances: the largest constant index sizes the member, in
    // the block and in the instance's type.
    let p = link_all(&[
        vs(" ifc", "ifc.foo[0] = 1.0; ifc.foo[2] = 1.0;"),
        fs(" ifc", "ifc.foo[1] + ifc.foo[2]"),
    ]);
    assert!(p.ok(), "{}", p.info_log());
    for stage in [Stage::Vertex, Stage::Fragment] {
        let m = &p.stage(stage).expect("linked").module;
        let b = &m.blocks[0];
        assert_eq!(m.type_name(b.members[0].ty), "float[3]");
        let inst = m
            .globals
            .iter()
            .find(|g| g.name == "ifc")
            .expect("instance");
        let crate::types::Base::Struct(sid) = inst.ty.base else {
            panic!("instance is a struct")
        };
        assert_eq!(
            m.type_name(m.structs[sid.0 as usize].members[0].ty),
            "float[3]"
        );
    }
    // Without an instance name, as an unsized array global.
    let p = link_all(&[vs("", "foo[2] = 1.0;"), fs("", "foo[2]")]);
    assert!(p.ok(), "{}", p.info_log());
    // Different sizes in the two stages do not match.
    let p = link_all(&[vs(" ifc", "ifc.foo[1] = 1.0;"), fs(" ifc", "ifc.foo[2]")]);
    assert!(!p.ok());
    let p = link_all(&[vs("", "foo[1] = 1.0;"), fs("", "foo[2]")]);
    assert!(!p.ok());
    // A dynamic index needs a size, as for any unsized array.
    fails(
        &vert("#version 150\nout blk { float foo[]; } ifc;\nuniform int i;\nvoid main() { ifc.foo[i] = 1.0; }"),
        Code::BadArraySize,
    );
    // A uniform block's layout needs its sizes.
    fails(
        &vert("#version 150\nuniform U { float foo[]; };\nvoid main() {}"),
        Code::BadArraySize,
    );
}

#[test]
fn block_array_sizes_match() {
    // Between stages: an output block array and an input block array of
    // another size; a uniform block array of two sizes.
    let p = link_all(&[
        vert("#version 150\nout block { vec4 a; } vs_block[3];\nvoid main() { vs_block[0].a = vec4(1); }"),
        frag("#version 150\nin block { vec4 a; } fs_block[2];\nout vec4 c;\nvoid main() { c = fs_block[0].a; }"),
    ]);
    assert!(!p.ok());
    assert!(p.info_log().contains("array sizes"), "{}", p.info_log());
    let p = link_all(&[
        vert("#version 150\nuniform Foo { vec4 x; } foo[3];\nvoid main() { gl_Position = foo[0].x; }"),
        frag("#version 150\nuniform Foo { vec4 x; } bar[2];\nvoid main() { gl_FragColor = bar[0].x; }"),
    ]);
    assert!(!p.ok());
    // The same size under other instance names matches.
    let p = link_all(&[
        vert("#version 150\nuniform Foo { vec4 x; } foo[2];\nvoid main() { gl_Position = foo[0].x; }"),
        frag("#version 150\nuniform Foo { vec4 x; } bar[2];\nvoid main() { gl_FragColor = bar[1].x; }"),
    ]);
    assert!(p.ok(), "{}", p.info_log());
    // Within a stage: an array in one object, not in another.
    let p = link_all(&[
        vert("#version 150\nout blk { vec4 foo; };\nvoid f() { foo = vec4(1.0); }"),
        vert("#version 150\nout blk { vec4 foo; } inst[3];\nvoid f();\nvoid main() { f(); inst[2].foo = vec4(1.0); }"),
    ]);
    assert!(!p.ok());
    assert!(p.info_log().contains("array size"), "{}", p.info_log());
}

#[test]
fn block_names_live_per_interface() {
    // A uniform block and an output block may share a block name.
    let s = vert(
        "#version 150\nuniform block { vec4 color; } ucolor;\nout block { vec4 color; } vcolor;\n\
         void main() { vcolor.color = ucolor.color; gl_Position = vec4(0); }",
    );
    ok(&s);
    assert_eq!(s.module.as_ref().expect("compiled").blocks.len(), 2);
    // Not two blocks of one interface, nor a block name and a variable.
    fails(
        &vert("#version 150\nout block { vec4 a; } x;\nout block { vec4 b; } y;\nvoid main() {}"),
        Code::Redeclared,
    );
    fails(
        &vert("#version 150\nuniform float block;\nout block { vec4 a; } x;\nvoid main() {}"),
        Code::Redeclared,
    );
}

/// GLSL 1.50 §4.3.7: "structure definitions cannot be nested inside a
/// block"; a struct declared before the block may type a member.
#[test]
fn structs_are_not_defined_inside_blocks() {
    fails(
        &vert("#version 150\nout B { struct S { int a; } c; float d; } inst;\nvoid main() { inst.d = 1.0; }"),
        Code::TypeMismatch,
    );
    ok(&vert(
        "#version 150\nstruct S { int a; };\nuniform U { S c; float d; } u;\nout float x;\nvoid main() { x = u.d + float(u.c.a); }",
    ));
}

/// GL_ARB_separate_shader_objects' GLSL side: `layout(location)` on the
/// inputs and outputs between stages, global `in`/`out` before 1.30, and
/// inputs matched to outputs by location when linked together.
#[test]
fn separate_shader_objects_varying_locations() {
    let ext = "#version 150\n#extension GL_ARB_separate_shader_objects : require\n";
    let v = vert(&format!(
        "{ext}in vec4 p; layout(location = 2) out vec4 a; void main() {{ gl_Position = p; a = p; }}"
    ));
    ok(&v);
    assert_eq!(global(&v, "a").location, Some(2));
    let f = frag(&format!(
        "{ext}layout(location = 2) in vec4 b; out vec4 c; void main() {{ c = b; }}"
    ));
    ok(&f);
    assert_eq!(global(&f, "b").location, Some(2));
    // Matched by location whatever the names; a location no output has
    // leaves the input without one.
    assert!(crate::link::link(&[&v, &f]).ok());
    let g = frag(&format!(
        "{ext}layout(location = 3) in vec4 a; out vec4 c; void main() {{ c = a; }}"
    ));
    assert!(!crate::link::link(&[&v, &g]).ok());
    // Structures matched by location need the same members, not the
    // same name; matched by name, they still need the same name.
    let vs = vert(&format!(
        "{ext}in vec4 p; layout(location = 0) out struct S {{ vec4 a; }} s; void main() {{ gl_Position = p; s.a = p; }}"
    ));
    let by_location = frag(&format!(
        "{ext}layout(location = 0) in struct T {{ vec4 a; }} t; out vec4 c; void main() {{ c = t.a; }}"
    ));
    assert!(crate::link::link(&[&vs, &by_location]).ok());
    let other_member = frag(&format!(
        "{ext}layout(location = 0) in struct T {{ vec4 b; }} t; out vec4 c; void main() {{ c = t.b; }}"
    ));
    assert!(!crate::link::link(&[&vs, &other_member]).ok());
    let by_name = |name: &str| {
        let v = vert(
            "#version 150\nin vec4 p; out struct S { vec4 a; } s; void main() { gl_Position = p; s.a = p; }",
        );
        let f = frag(&format!(
            "#version 150\nin struct {name} {{ vec4 a; }} s; out vec4 c; void main() {{ c = s.a; }}"
        ));
        crate::link::link(&[&v, &f]).ok()
    };
    assert!(by_name("S"));
    assert!(!by_name("T"));
    // Two outputs on one location, or one past the last, do not link.
    for bad in [
        "layout(location = 1) out vec4 a; layout(location = 1) out vec4 b;",
        "layout(location = 0) out vec4 a[2]; layout(location = 1) out vec4 b;",
        "layout(location = 31) out vec4 a[2]; out vec4 b;",
    ] {
        let v = vert(&format!(
            "{ext}in vec4 p; {bad} void main() {{ gl_Position = p; }}"
        ));
        ok(&v);
        assert!(!crate::link::link(&[&v]).ok(), "{bad}");
    }
    // The extension is what allows them: 1.50 and 3.30 alone do not (3.30
    // has `layout(location)', on vertex inputs and fragment outputs only).
    for version in ["150", "330"] {
        let s = vert(&format!(
            "#version {version}\nin vec4 p; layout(location = 0) out vec4 a; void main() {{ gl_Position = p; a = p; }}"
        ));
        assert!(!s.ok(), "{version}");
    }
    let s = vert("#version 330\nin vec4 p; layout(location = 0) out vec4 a; void main() { gl_Position = p; a = p; }");
    assert!(
        s.info_log().contains("GL_ARB_separate_shader_objects"),
        "{}",
        s.info_log()
    );
    // `index` stays a fragment output's; uniforms take no location.
    for bad in [
        "layout(location = 0, index = 1) in vec4 b; void main() {}",
        "layout(location = 0) uniform vec4 u; void main() {}",
    ] {
        assert!(!frag(&format!("{ext}{bad}")).ok(), "{bad}");
    }
    // Global `in`/`out` (and `layout`) before GLSL 1.30 with the extension.
    let old = "#version 120\n#extension GL_ARB_separate_shader_objects : require\n";
    ok(&vert(&format!(
        "{old}in vec4 p; layout(location = 1) out vec4 a; void main() {{ gl_Position = p; a = p; }}"
    )));
    assert!(!vert("#version 120\nout vec4 a; void main() { gl_Position = a; }").ok());
    // The macro is defined.
    ok(&frag(&format!(
        "{ext}#if GL_ARB_separate_shader_objects != 1\n#error missing\n#endif\nout vec4 c; void main() {{ c = vec4(1); }}"
    )));
}

/// A separable program may hold a geometry stage without a vertex stage
/// (GL_ARB_separate_shader_objects); other programs may not.
#[test]
fn separable_programs_need_no_vertex_stage() {
    let gs = compile(
        &["#version 150\nlayout(triangles) in; layout(triangle_strip, max_vertices = 3) out;\nvoid main() { gl_Position = gl_in[0].gl_Position; EmitVertex(); }"],
        &CompileOptions::new(Stage::Geometry),
    );
    ok(&gs);
    assert!(!crate::link::link(&[&gs]).ok());
    let opts = crate::link::LinkOptions {
        separable: true,
        ..Default::default()
    };
    let p = crate::link::link_with(&[&gs], &opts);
    assert!(p.ok(), "{}", p.info_log());
    // GL_EXT_separate_shader_objects' rule: without user-defined inputs.
    let lone = crate::link::LinkOptions {
        lone_geometry: true,
        ..Default::default()
    };
    assert!(crate::link::link_with(&[&gs], &lone).ok());
    let reads_user = compile(
        &["#version 150\nlayout(triangles) in; layout(triangle_strip, max_vertices = 3) out;\nin vec4 c[];\nvoid main() { gl_Position = c[0]; EmitVertex(); }"],
        &CompileOptions::new(Stage::Geometry),
    );
    ok(&reads_user);
    assert!(!crate::link::link_with(&[&reads_user], &lone).ok());
}
