//! Unit tests of shader storage blocks' language
//! (GL_ARB_shader_storage_buffer_object): blocks and their layouts and
//! bindings, memory qualifiers and what they forbid, the last member of
//! unknown size and its `.length()`, atomics on buffer variables, and the
//! words without the extension.

use crate::diag::Code;
use crate::ir::{BlockLayout, Stage, Storage};
use crate::{compile, CompileOptions, Shader};

use super::interface::tests::{fails, ok};

const EXT: &str = "#extension GL_ARB_shader_storage_buffer_object : enable\n";

fn shader(stage: Stage, version: u32, body: &str) -> Shader {
    let src = format!("#version {version}\n{EXT}{body}");
    compile(&[&src], &CompileOptions::new(stage))
}

fn frag(body: &str) -> Shader {
    shader(Stage::Fragment, 330, body)
}

#[test]
fn storage_blocks_with_layouts_bindings_and_a_runtime_array() {
    let s = frag(
        "layout(std430, binding = 3) coherent buffer Particles {
    readonly vec4 origin;
    int count;
    vec4 positions[];
} particles;
out vec4 o;
void main() {
    particles.count = particles.positions.length();
    particles.positions[particles.count - 1] = particles.origin;
    atomicAdd(particles.count, 1);
    o = particles.positions[0];
}",
    );
    ok(&s);
    let m = s.module.as_ref().expect("compiled");
    let b = m
        .blocks
        .iter()
        .find(|b| b.name == "Particles")
        .expect("block");
    assert_eq!(b.storage, Storage::Buffer);
    assert_eq!(b.layout, BlockLayout::Std430);
    assert_eq!(b.binding, Some(3));
    assert!(b.members[0].readonly && !b.members[1].readonly);
    // The length is the buffer's: a node of its own, not a constant.
    let text = crate::ir::print::print(m);
    assert!(text.contains("positions.length()"), "{text}");
}

#[test]
fn memory_qualifiers_forbid_what_they_say() {
    for (body, what) in [
        (
            "buffer B { readonly float a; };\nvoid main() { a = 1.0; }",
            "written",
        ),
        (
            "readonly buffer B { float a; } b;\nvoid main() { b.a += 1.0; }",
            "written",
        ),
        (
            "buffer B { writeonly float a; };\nvoid main() { gl_FragColor = vec4(a); }",
            "read",
        ),
        (
            "writeonly buffer B { float a[2]; } b;\nvoid main() { gl_FragColor = vec4(b.a[1]); }",
            "read",
        ),
    ] {
        let s = shader(Stage::Fragment, 120, body);
        fails(&s, Code::ReadOnly);
        assert!(s.info_log().contains(what), "{}", s.info_log());
    }
    ok(&shader(
        Stage::Fragment,
        120,
        "buffer B { writeonly float a; readonly float r; };\nvoid main() { a = r; }",
    ));
}

#[test]
fn what_storage_blocks_cannot_have() {
    for body in [
        // Memory qualifiers and std430 belong to storage blocks.
        "uniform U { readonly float a; };",
        "layout(std430) uniform U { float a; };",
        "readonly uniform float u;",
        // Buffer variables live in blocks.
        "buffer float x;",
        "buffer B { float a = 1.0; };",
        "buffer B { sampler2D s; };",
        "layout(binding = 8) buffer B { float a; };",
        "buffer B { layout(binding = 1) float a; };",
    ] {
        let s = shader(Stage::Fragment, 130, &format!("{body}\nvoid main() {{ }}"));
        assert!(!s.ok(), "{body}");
    }
    // The runtime array is no value: not passed, not assigned whole.
    let s = shader(
        Stage::Fragment,
        120,
        "buffer B { int s[]; };\nint f(int a[2]) { return a[0]; }\nvoid main() { int v = f(s); }",
    );
    fails(&s, Code::BadArraySize);
}

#[test]
fn the_words_belong_to_the_extension() {
    let src = "#version 330\nfloat buffer;\nfloat readonly;\nvoid main() { gl_FragColor = vec4(buffer + readonly); }\n";
    ok(&compile(&[src], &CompileOptions::new(Stage::Fragment)));
    let src = "#version 330\nbuffer B { float a; };\nvoid main() { }\n";
    assert!(!compile(&[src], &CompileOptions::new(Stage::Fragment)).ok());
    // Atomics on buffer variables in every stage, the `int' forms in
    // GLSL 1.20 too; never on a plain global.
    ok(&shader(
        Stage::Vertex,
        120,
        "buffer B { ivec4 v; };\nvoid main() { atomicMin(v.x, 2); gl_Position = vec4(0.0); }",
    ));
    fails(
        &shader(
            Stage::Vertex,
            130,
            "int g;\nvoid main() { atomicMin(g, 2); gl_Position = vec4(0.0); }",
        ),
        Code::TypeMismatch,
    );
}
