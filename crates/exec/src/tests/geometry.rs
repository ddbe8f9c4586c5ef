//! Geometry kernels: `EmitVertex`/`EndPrimitive` fill each lane's emit
//! buffer ([`crate::Emitted`]) the same way in every executor variant.

use super::bits_of;
use crate::{supported_variants, Batch, Kernel, NoTextures, LANES};
use glsl::ir::Stage;
use glsl::{compile, CompileOptions};

const VS: &str = "#version 150\nin vec4 p;\nout vec4 c;\nvoid main() { gl_Position = p; c = p; }";

/// The geometry kernel of a program of `VS` and the geometry shader `gs`.
fn geometry(gs: &str) -> Kernel {
    let v = compile(&[VS], &CompileOptions::new(Stage::Vertex));
    let g = compile(&[gs], &CompileOptions::new(Stage::Geometry));
    assert!(g.ok(), "{}", g.info_log());
    let prog = glsl::link::link(&[&v, &g]);
    assert!(prog.ok(), "{}", prog.info_log());
    let stage = prog.stage(Stage::Geometry).expect("geometry stage");
    Kernel::new(stage).unwrap_or_else(|e| panic!("lowering failed: {e}"))
}

/// Lane `l`'s input `name` component `c`.
fn set_input(k: &Kernel, b: &mut Batch, name: &str, c: usize, f: impl Fn(usize) -> f32) {
    let s = k
        .interface()
        .input(name)
        .unwrap_or_else(|| panic!("input {name}"));
    for l in 0..LANES {
        b.inputs[s.offset + c][l] = f(l);
    }
}

/// Where input vertex `v`'s `name` starts.
fn vertex_input(k: &Kernel, v: usize, name: &str) -> usize {
    let inputs = k.interface().vertex_inputs();
    let i = inputs.iter().find(|i| i.vertex == v && i.name == name);
    i.unwrap_or_else(|| panic!("no {name} of vertex {v}: {inputs:?}"))
        .offset
}

/// Lane `l`'s emitted vertices: (strip number, components).
fn emitted(k: &Kernel, b: &Batch, l: usize) -> Vec<(i32, Vec<f32>)> {
    let e = k.interface().emitted.expect("a geometry kernel");
    let n = b.outputs[e.count()][l].to_bits() as usize;
    (0..n)
        .map(|v| {
            let strip = b.outputs[e.strip(v)][l].to_bits() as i32;
            let comps = (0..e.vertex_components)
                .map(|c| b.outputs[e.vertex(v) + c][l])
                .collect();
            (strip, comps)
        })
        .collect()
}

/// Each lane emits as many vertices as its primitive ID says (more than
/// `max_vertices` are dropped), cutting the strip after every second;
/// the inputs come from `gl_in[]` and a user array.
const COUNTING: &str = "#version 150
layout(triangles) in;
layout(triangle_strip, max_vertices = 5) out;
in vec4 c[];
out vec4 color;
out float k;
void main() {
    for (int i = 0; i < gl_PrimitiveIDIn; i++) {
        gl_Position = gl_in[i % 3].gl_Position + vec4(float(i));
        color = c[2 - i % 3];
        k = float(i);
        EmitVertex();
        if (i % 2 == 1) EndPrimitive();
    }
}";

#[test]
fn emit_vertex_and_end_primitive_fill_the_buffer() {
    let k = geometry(COUNTING);
    let e = k.interface().emitted.expect("emitted");
    assert_eq!(e.max_vertices, 5);
    assert_eq!(e.input, glsl::ir::InputPrimitive::Triangles);
    assert_eq!(e.output, glsl::ir::OutputPrimitive::TriangleStrip);
    let per = e.vertex_components;
    assert_eq!(per, 4 + 4 + 1, "{:?}", k.interface().outputs);
    let mut b = Batch::for_kernel(&k, 0xffff);
    set_input(&k, &mut b, "gl_PrimitiveIDIn", 0, |l| {
        f32::from_bits(l as u32)
    });
    for v in 0..3 {
        let pos = vertex_input(&k, v, "gl_Position");
        let c = vertex_input(&k, v, "c");
        for l in 0..LANES {
            b.inputs[pos][l] = (10 * v + l) as f32;
            b.inputs[c][l] = 100.0 * v as f32 + l as f32;
        }
    }
    k.run(&mut b, &[], &NoTextures).expect("runs");
    let color = k.interface().output("color").expect("color").offset;
    let kk = k.interface().output("k").expect("k").offset;
    let position = k.interface().output("gl_Position").expect("pos").offset;
    for l in 0..LANES {
        let got = emitted(&k, &b, l);
        assert_eq!(got.len(), l.min(5), "lane {l}");
        for (i, (strip, comps)) in got.iter().enumerate() {
            assert_eq!(*strip, (i / 2) as i32, "lane {l} vertex {i}");
            assert_eq!(comps[kk], i as f32);
            assert_eq!(comps[position], (10 * (i % 3) + l + i) as f32);
            assert_eq!(comps[color], 100.0 * (2 - i % 3) as f32 + l as f32);
        }
    }
}

/// Emission under divergent control flow, in subroutine mode too, gives
/// the same bytes in every executor variant as the reference.
#[test]
fn every_variant_emits_the_same_bytes() {
    let src = "#version 150
layout(points) in;
layout(line_strip, max_vertices = 7) out;
out vec2 v;
void emit2(float x) { v = vec2(x, -x); EmitVertex(); v.y += 1.0; EmitVertex(); }
void main() {
    float x = gl_in[0].gl_Position.x;
    int n = int(abs(x) * 9.0);
    while (n > 0) {
        if (x > 0.25) emit2(x * float(n)); else { v = vec2(float(n)); EmitVertex(); }
        if (n == 3) EndPrimitive();
        n--;
        if (x < -0.8) break;
    }
    gl_Position = vec4(x);
    EmitVertex();
}";
    let k = geometry(src);
    let linked = {
        let v = compile(&[VS], &CompileOptions::new(Stage::Vertex));
        let g = compile(&[src], &CompileOptions::new(Stage::Geometry));
        glsl::link::link(&[&v, &g])
            .stage(Stage::Geometry)
            .cloned()
            .expect("links")
    };
    let subroutines = Kernel::with_inline_limit(&linked, 0).expect("lowers");
    for k in [k, subroutines] {
        for round in 0..20u32 {
            let mut base = Batch::for_kernel(&k, if round % 3 == 2 { 0x5a5a } else { 0xffff });
            let pos = vertex_input(&k, 0, "gl_Position");
            for l in 0..LANES {
                base.inputs[pos][l] = ((l as u32 * 7 + round * 13) % 23) as f32 / 11.0 - 1.0;
            }
            let mut want = base.clone();
            k.run_reference(&mut want, &[], &NoTextures).expect("runs");
            for &v in &supported_variants() {
                let mut got = base.clone();
                k.run_variant(v, &mut got, &[], &NoTextures).expect("runs");
                assert_eq!(
                    bits_of(&got.outputs),
                    bits_of(&want.outputs),
                    "{} round {round}",
                    v.name()
                );
            }
        }
    }
}

/// A user array of structs is one input per vertex, named by the array,
/// taking the whole struct; only `gl_in[]` is listed by member.
#[test]
fn struct_array_inputs_are_matched_whole() {
    let s = "struct S { vec4 a; float b; };\n";
    let v = compile(
        &[&format!("#version 150\n{s}out S s;\nvoid main() {{ gl_Position = vec4(0.0); s.a = vec4(1.0); s.b = 2.0; }}")],
        &CompileOptions::new(Stage::Vertex),
    );
    let g = compile(
        &[&format!(
            "#version 150\nlayout(triangles) in;\nlayout(points, max_vertices = 1) out;\n{s}in S s[];\n\
             out float x;\nvoid main() {{ x = s[2].b + s[1].a.x; gl_Position = gl_in[0].gl_Position; EmitVertex(); }}"
        )],
        &CompileOptions::new(Stage::Geometry),
    );
    let prog = glsl::link::link(&[&v, &g]);
    assert!(prog.ok(), "{}", prog.info_log());
    let k = Kernel::new(prog.stage(Stage::Geometry).expect("geometry")).expect("lowered");
    let inputs = k.interface().vertex_inputs();
    let whole: Vec<_> = inputs.iter().filter(|i| i.name == "s").collect();
    assert_eq!(whole.len(), 3, "{inputs:?}");
    assert!(whole.iter().all(|i| i.components == 5), "{inputs:?}");
    assert!(inputs.iter().any(|i| i.name == "gl_Position"), "{inputs:?}");
    assert!(
        !inputs.iter().any(|i| i.name == "a" || i.name == "b"),
        "{inputs:?}"
    );
}
