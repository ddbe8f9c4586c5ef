//! Unit tests of the geometry stage's `gl_PerVertex` input block: its
//! redeclaration (GLSL 1.50 §7.1), the linker's rules on it within the
//! stage and against the vertex stage, and the sizes `gl_in[]`'s unsized
//! members take at link time.

use crate::diag::Code;
use crate::ir::{ExprKind, Stage, Storage};
use crate::types::{ArraySize, Base, Type};
use crate::{compile, link::link, CompileOptions, Shader};

use super::interface::tests::{fails, ok};

fn stage(stage: Stage, src: &str) -> Shader {
    compile(&[src], &CompileOptions::new(stage))
}

fn geom(src: &str) -> Shader {
    stage(Stage::Geometry, src)
}

const LAYOUTS: &str =
    "#version 150\nlayout(triangles) in;\nlayout(triangle_strip, max_vertices = 3) out;\n";
const FS: &str = "#version 150\nvoid main() { gl_FragColor = vec4(1.0); }";

/// The members of `gl_in`'s struct in a compiled geometry shader.
fn gl_in_members(s: &Shader) -> Vec<(String, Type)> {
    let m = s.module.as_ref().expect("compiled");
    let g = m.globals.iter().find(|g| g.name == "gl_in").expect("gl_in");
    let Base::Struct(sid) = g.ty.base else {
        panic!("gl_in is {:?}", g.ty)
    };
    m.structs[sid.0 as usize]
        .members
        .iter()
        .map(|x| (x.name.clone(), x.ty))
        .collect()
}

#[test]
fn input_block_redeclared_with_a_subset() {
    let g = geom(&format!(
        "{LAYOUTS}in gl_PerVertex {{ vec4 gl_Position; float gl_ClipDistance[2]; }} gl_in[];\n\
         void main() {{ gl_Position = gl_in[0].gl_Position + vec4(gl_in[1].gl_ClipDistance[1]); \
         gl_PointSize = float(gl_in[0].gl_ClipDistance.length()); EmitVertex(); }}"
    ));
    ok(&g);
    let members = gl_in_members(&g);
    assert_eq!(members.len(), 2);
    assert_eq!(members[1].0, "gl_ClipDistance");
    assert_eq!(members[1].1.array, Some(ArraySize::Sized(2)));
    let m = g.module.as_ref().expect("compiled");
    let gl_in = m.globals.iter().find(|g| g.name == "gl_in").expect("gl_in");
    assert_eq!(gl_in.storage, Storage::PerVertexInput);
    assert_eq!(gl_in.ty.array, Some(ArraySize::Sized(3)));
    assert!(gl_in.block.is_none());
    assert_eq!(m.per_vertex_in.as_ref().map(Vec::len), Some(2));
    // The layout may come after the redeclaration; `gl_in[3]' with it.
    ok(&geom(
        "#version 150\nin gl_PerVertex { vec4 gl_Position; } gl_in[3];\n\
         layout(triangles) in;\nlayout(points, max_vertices = 1) out;\n\
         void main() { gl_Position = gl_in[2].gl_Position; EmitVertex(); }",
    ));
}

#[test]
fn input_block_redeclaration_errors() {
    let body = "void main() { gl_Position = gl_in[0].gl_Position; EmitVertex(); }";
    // A member left out is no longer a field.
    fails(
        &geom(&format!(
            "{LAYOUTS}in gl_PerVertex {{ vec4 gl_Position; }} gl_in[];\n\
             void main() {{ gl_Position = vec4(gl_in[0].gl_PointSize); EmitVertex(); }}"
        )),
        Code::Undeclared,
    );
    // Not a member, another type, too large an array.
    for (decl, code) in [
        ("vec4 gl_Position; vec4 gl_Color;", Code::Redeclared),
        ("vec3 gl_Position;", Code::TypeMismatch),
        (
            "vec4 gl_Position; float gl_ClipDistance[9];",
            Code::BadArraySize,
        ),
    ] {
        fails(
            &geom(&format!(
                "{LAYOUTS}in gl_PerVertex {{ {decl} }} gl_in[];\n{body}"
            )),
            code,
        );
    }
    // Another instance name, no array, twice, after a use.
    for src in [
        format!("{LAYOUTS}in gl_PerVertex {{ vec4 gl_Position; }} verts[];\n{body}"),
        format!("{LAYOUTS}in gl_PerVertex {{ vec4 gl_Position; }} gl_in;\n{body}"),
        format!(
            "{LAYOUTS}in gl_PerVertex {{ vec4 gl_Position; }} gl_in[];\n\
             in gl_PerVertex {{ vec4 gl_Position; }} gl_in[];\n{body}"
        ),
        format!(
            "{LAYOUTS}vec4 f() {{ return gl_in[0].gl_Position; }}\n\
             in gl_PerVertex {{ vec4 gl_Position; }} gl_in[];\n{body}"
        ),
    ] {
        assert!(!geom(&src).ok(), "{src}");
    }
    // Vertex and fragment shaders have no input `gl_PerVertex'.
    fails(
        &stage(
            Stage::Fragment,
            "#version 150\nin gl_PerVertex { vec4 gl_Position; } gl_in[];\nvoid main() {}",
        ),
        Code::Redeclared,
    );
}

#[test]
fn input_block_redeclarations_agree_within_the_stage() {
    let vs = stage(
        Stage::Vertex,
        "#version 150\nin vec4 p;\nout gl_PerVertex { vec4 gl_Position; };\nvoid main() { gl_Position = p; }",
    );
    let fs = stage(Stage::Fragment, FS);
    let main = geom(&format!(
        "{LAYOUTS}in gl_PerVertex {{ vec4 gl_Position; }} gl_in[];\nvec4 foo();\n\
         void main() {{ gl_Position = gl_in[0].gl_Position + foo(); EmitVertex(); }}"
    ));
    ok(&main);
    // Another object using `gl_in' without redeclaring it.
    let other = geom("#version 150\nvec4 foo() { return gl_in[0].gl_Position; }");
    let p = link(&[&vs, &main, &other, &fs]);
    assert!(!p.ok());
    assert!(
        p.info_log().contains("without redeclaring"),
        "{}",
        p.info_log()
    );
    // Another object redeclaring it otherwise.
    let other = geom(
        "#version 150\nin gl_PerVertex { vec4 gl_Position; float gl_PointSize; } gl_in[];\n\
         vec4 foo() { return vec4(gl_in[0].gl_PointSize); }",
    );
    let p = link(&[&vs, &main, &other, &fs]);
    assert!(!p.ok());
    assert!(p.info_log().contains("other members"), "{}", p.info_log());
    // An object that does not use `gl_in' need not redeclare it; the same
    // redeclaration everywhere links.
    for src in [
        "#version 150\nvec4 foo() { return vec4(1.0); }".to_string(),
        "#version 150\nin gl_PerVertex { vec4 gl_Position; } gl_in[];\n\
         vec4 foo() { return gl_in[1].gl_Position; }"
            .to_string(),
    ] {
        let p = link(&[&vs, &main, &geom(&src), &fs]);
        assert!(p.ok(), "{src}\n{}", p.info_log());
    }
}

#[test]
fn per_vertex_blocks_agree_between_vertex_and_geometry_stages() {
    let vs = |decl: &str| {
        stage(
            Stage::Vertex,
            &format!("#version 150\nin vec4 p;\n{decl}\nvoid main() {{ gl_Position = p; }}"),
        )
    };
    let gs = |decl: &str, read: &str| {
        geom(&format!(
            "{LAYOUTS}{decl}\nvoid main() {{ gl_Position = {read}; EmitVertex(); }}"
        ))
    };
    let fs = stage(Stage::Fragment, FS);
    let pos = "out gl_PerVertex { vec4 gl_Position; };";
    let pos_size = "out gl_PerVertex { vec4 gl_Position; float gl_PointSize; };";
    let in_pos = "in gl_PerVertex { vec4 gl_Position; } gl_in[];";
    let in_pos_size = "in gl_PerVertex { vec4 gl_Position; float gl_PointSize; } gl_in[];";
    let read = "gl_in[0].gl_Position";
    for (v, g, read, links) in [
        ("", "", read, true),
        (pos, in_pos, read, true),
        (pos_size, in_pos_size, read, true),
        // A geometry shader that does not read `gl_in' forms no block.
        (pos, "", "vec4(0.0)", true),
        (pos, in_pos_size, read, false),
        (pos, "", read, false),
        ("", in_pos, read, false),
    ] {
        let p = link(&[&vs(v), &gs(g, read), &fs]);
        assert_eq!(p.ok(), links, "{v} / {g}\n{}", p.info_log());
    }
}

#[test]
fn unsized_gl_in_members_take_the_vertex_stage_size() {
    let gs = geom(&format!(
        "{LAYOUTS}void main() {{ gl_Position = vec4(gl_in[0].gl_ClipDistance[1]); EmitVertex(); }}"
    ));
    ok(&gs);
    let fs = stage(Stage::Fragment, FS);
    let linked_size = |vs_body: &str| {
        let vs = stage(
            Stage::Vertex,
            &format!("#version 150\nvoid main() {{ gl_Position = vec4(0.0); {vs_body} }}"),
        );
        let p = link(&[&vs, &gs, &fs]);
        assert!(p.ok(), "{}", p.info_log());
        let m = &p.stage(Stage::Geometry).expect("geometry").module;
        let g = m.globals.iter().find(|g| g.name == "gl_in").expect("gl_in");
        let Base::Struct(sid) = g.ty.base else {
            panic!("gl_in is {:?}", g.ty)
        };
        let def = &m.structs[sid.0 as usize];
        let k = def
            .members
            .iter()
            .position(|x| x.name == "gl_ClipDistance")
            .expect("member");
        // Every expression reading the member has the sized type.
        let mut seen = 0;
        for f in &m.functions {
            let Some(b) = &f.body else { continue };
            crate::ir::for_each_block_expr(b, &mut |e| {
                walk(e, &mut |x| {
                    if let ExprKind::Member { index, .. } = x.kind {
                        if index as usize == k {
                            seen += 1;
                            assert_eq!(x.ty, def.members[k].ty);
                        }
                    }
                })
            });
        }
        assert_eq!(seen, 1);
        def.members[k].ty.array
    };
    // The vertex stage's `gl_ClipDistance' size, else gl_MaxClipDistances.
    assert_eq!(
        linked_size("gl_ClipDistance[3] = 1.0;"),
        Some(ArraySize::Sized(4))
    );
    assert_eq!(linked_size(""), Some(ArraySize::Sized(8)));
}

fn walk(e: &crate::ir::Expr, f: &mut impl FnMut(&crate::ir::Expr)) {
    f(e);
    e.for_each_child(|c| walk(c, f));
}

#[test]
fn constant_indices_of_unsized_gl_in_members_are_bounded() {
    let read = |index: &str| {
        geom(&format!(
            "{LAYOUTS}void main() {{ gl_Position = vec4(gl_in[0].gl_ClipDistance[{index}]); EmitVertex(); }}"
        ))
    };
    ok(&read("gl_MaxClipDistances - 1"));
    fails(&read("gl_MaxClipDistances"), Code::IndexOutOfRange);
}
