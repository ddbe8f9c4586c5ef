//! Unit tests of the compute stage's language (GL_ARB_compute_shader):
//! the extension and version it needs, the work-group size layout and
//! `gl_WorkGroupSize`, `shared` variables, the built-in IDs, barriers and
//! atomics, and the link rules of compute programs.

use crate::diag::Code;
use crate::ir::{ConstScalar, Stage, Storage};
use crate::link::link;
use crate::{compile, CompileOptions, Shader};

use super::interface::tests::{fails, global, ok};

const EXT: &str = "#extension GL_ARB_compute_shader : enable\n";

fn comp(body: &str) -> Shader {
    let src = format!("#version 330\n{EXT}{body}");
    compile(&[&src], &CompileOptions::new(Stage::Compute))
}

#[test]
fn a_compute_shader_needs_the_extension_and_glsl_130() {
    let src = "#version 330\nlayout(local_size_x = 1) in;\nvoid main() { }\n";
    let s = compile(&[src], &CompileOptions::new(Stage::Compute));
    fails(&s, Code::VersionTooLow);
    assert!(
        s.info_log().contains("GL_ARB_compute_shader"),
        "{}",
        s.info_log()
    );
    let old = format!("#version 120\n{EXT}void main() {{ }}\n");
    fails(
        &compile(&[&old], &CompileOptions::new(Stage::Compute)),
        Code::VersionTooLow,
    );
}

#[test]
fn the_work_group_size_is_declared_once_or_the_same_each_time() {
    let s = comp(
        "layout(local_size_x = 3, local_size_y = 5, local_size_z = 7) in;
layout(local_size_x = 3, local_size_z = 7, local_size_y = 5) in;
void main() { int x[gl_WorkGroupSize.x == 3u ? 1 : -1]; uvec3 s = gl_WorkGroupSize; }",
    );
    ok(&s);
    assert_eq!(
        s.module.as_ref().and_then(|m| m.local_size),
        Some([3, 5, 7])
    );
    // Dimensions left out are 1.
    let s = comp("layout(local_size_x = 1) in;\nlayout(local_size_y = 1) in;\nvoid main() { }");
    ok(&s);
    assert_eq!(
        s.module.as_ref().and_then(|m| m.local_size),
        Some([1, 1, 1])
    );
    for bad in [
        "layout(local_size_x = 2) in;\nlayout(local_size_x = 3) in;",
        "layout(local_size_y = 0) in;",
        "layout(local_size_y = -1) in;",
        "layout(local_size_z = 65) in;",
        "layout(local_size_x = 64, local_size_y = 32) in;",
    ] {
        fails(
            &comp(&format!("{bad}\nvoid main() {{ }}")),
            Code::BadQualifier,
        );
    }
}

#[test]
fn gl_work_group_size_needs_the_size_declared_first() {
    for body in [
        "void main() { uvec3 s = gl_WorkGroupSize; }",
        "void main() { uvec3 s = gl_WorkGroupSize; }\nlayout(local_size_x = 3) in;",
    ] {
        let s = comp(body);
        fails(&s, Code::Undeclared);
        assert!(
            s.info_log().contains("before the shader declares"),
            "{}",
            s.info_log()
        );
    }
}

#[test]
fn compute_shaders_read_their_ids_and_share_variables() {
    let s = comp(
        "layout(local_size_x = 8) in;
shared float tile[8];
shared uint count;
void main() {
  uint i = gl_LocalInvocationIndex + gl_LocalInvocationID.x + gl_WorkGroupID.y + gl_NumWorkGroups.z;
  tile[gl_GlobalInvocationID.x % 8u] = float(i);
  barrier();
  memoryBarrierShared();
  groupMemoryBarrier();
  uint before = atomicAdd(count, 1u);
  atomicCompSwap(count, before, 0u);
}",
    );
    ok(&s);
    assert_eq!(global(&s, "tile").storage, Storage::Shared);
    assert_eq!(
        global(&s, "gl_GlobalInvocationID").storage,
        Storage::Varying
    );
    let s = comp(
        "layout(local_size_x = 1) in;
const int z = gl_MaxComputeWorkGroupSize.z * gl_MaxComputeWorkGroupCount.x;
void main() { }",
    );
    ok(&s);
    let z = global(&s, "z").init.as_ref().map(|c| c.components.clone());
    assert_eq!(z, Some(vec![ConstScalar::Int(64 * 65535)]));
}

#[test]
fn what_compute_shaders_cannot_have() {
    for (body, code) in [
        ("in int i;", Code::StageMismatch),
        ("out int o;", Code::StageMismatch),
        ("shared int s = 1;", Code::BadQualifier),
        ("int g;\nvoid f() { atomicAdd(g, 1); }", Code::TypeMismatch),
        ("void f() { shared int s; }", Code::BadQualifier),
    ] {
        let s = comp(&format!(
            "layout(local_size_x = 1) in;\n{body}\nvoid main() {{ }}"
        ));
        fails(&s, code);
    }
    // `shared` and the compute built-ins belong to compute shaders.
    let fs = compile(
        &[&format!(
            "#version 330\n{EXT}shared int s;\nvoid main() {{ barrier(); }}\n"
        )],
        &CompileOptions::new(Stage::Fragment),
    );
    fails(&fs, Code::StageMismatch);
    fails(&fs, Code::Undeclared);
    // Without the extension `shared' is an identifier (`layout(shared)').
    let vs = compile(
        &["#version 330\nint shared;\nlayout(shared) uniform B { vec4 v; };\nvoid main() { gl_Position = v * float(shared); }\n"],
        &CompileOptions::new(Stage::Vertex),
    );
    ok(&vs);
}

#[test]
fn compute_programs_link_alone_with_one_size() {
    let a = comp("layout(local_size_x = 4) in;\nvoid f();\nvoid main() { f(); }");
    let b = comp("layout(local_size_x = 4) in;\nvoid f() { }");
    let c = comp("layout(local_size_x = 2) in;\nvoid f() { }");
    let none = comp("void f() { }");
    let bare = comp("void main() { }");
    assert!(link(&[&a, &b]).ok());
    assert!(link(&[&a, &none]).ok());
    assert!(!link(&[&a, &c]).ok());
    assert!(!link(&[&bare]).ok());
    let fs = compile(
        &["#version 330\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n"],
        &CompileOptions::new(Stage::Fragment),
    );
    assert!(!link(&[&a, &b, &fs]).ok());
}
