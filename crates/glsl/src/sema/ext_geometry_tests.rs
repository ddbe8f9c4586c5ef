//! Unit tests of GL_EXT_geometry_shader4's form of the geometry stage (and
//! its other name, GL_ARB_geometry_shader4): `varying in`/`varying out`,
//! the `...In[]` built-ins, `gl_VerticesIn`, and the link that takes the
//! primitives and the vertex count from the program's parameters.

use crate::diag::Code;
use crate::ir::{InputPrimitive, OutputPrimitive, Stage, Storage};
use crate::limits::MAX_GEOMETRY_OUTPUT_VERTICES;
use crate::link::{link, link_with, GeometryParams, LinkOptions, Program};
use crate::types::ArraySize;
use crate::{compile, CompileOptions, Shader};

use super::interface::tests::{fails, ok};

fn stage(stage: Stage, src: &str) -> Shader {
    compile(&[src], &CompileOptions::new(stage))
}

fn geom(src: &str) -> Shader {
    stage(Stage::Geometry, src)
}

fn params(input: InputPrimitive, output: OutputPrimitive, vertices_out: u32) -> LinkOptions {
    LinkOptions {
        geometry: GeometryParams {
            input,
            output,
            vertices_out,
        },
        ..LinkOptions::default()
    }
}

fn link_tri(shaders: &[&Shader]) -> Program {
    link_with(
        shaders,
        &params(InputPrimitive::Triangles, OutputPrimitive::TriangleStrip, 3),
    )
}

#[track_caller]
fn linked(p: &Program) {
    assert!(p.ok(), "expected a link:\n{}", p.info_log());
}

#[track_caller]
fn not_linked(p: &Program, words: &str) {
    assert!(!p.ok(), "expected a link error");
    assert!(p.info_log().contains(words), "{}", p.info_log());
}

/// The seed lecture's "Simple Program": a vertex, a geometry
/// (GL_GEOMETRY_SHADER_EXT, `ex.geom`) and a fragment shader, with
/// GEOMETRY_INPUT_TYPE GL_TRIANGLES, GEOMETRY_OUTPUT_TYPE
/// GL_TRIANGLE_STRIP and GEOMETRY_VERTICES_OUT the implementation's
/// maximum. The vertex and fragment shaders are its "Simple Coloring
/// Faces" pair; the geometry shader passes each triangle through.
const SEED_VS: &str = "// vertex shader
void main(void)
{
 gl_Position = gl_ModelViewProjectionMatrix*gl_Vertex;
 gl_FrontColor = gl_Color;
 gl_BackColor = vec4(0,0,0,0); // black for backface
}";
const SEED_GS: &str = "#version 120
#extension GL_EXT_geometry_shader4 : enable
void main()
{
    for (int i = 0; i < gl_VerticesIn; i++) {
        gl_Position = gl_PositionIn[i];
        gl_FrontColor = gl_FrontColorIn[i];
        gl_BackColor = gl_BackColorIn[i];
        EmitVertex();
    }
    EndPrimitive();
}";
const SEED_FS: &str = "// fragment shader
void main(void)
{
 gl_FragColor = gl_Color;
}";

#[test]
fn seed_lecture_program_links_with_its_parameters() {
    let v = stage(Stage::Vertex, SEED_VS);
    let g = geom(SEED_GS);
    let f = stage(Stage::Fragment, SEED_FS);
    ok(&v);
    ok(&g);
    ok(&f);
    // The compiled object declares no layout: the program's parameters do.
    let m = g.module.as_ref().expect("compiled");
    assert_eq!(m.geometry, Default::default());
    let p = link_with(
        &[&f, &v, &g],
        &params(
            InputPrimitive::Triangles,
            OutputPrimitive::TriangleStrip,
            MAX_GEOMETRY_OUTPUT_VERTICES,
        ),
    );
    linked(&p);
    let gs = p.stage(Stage::Geometry).expect("geometry stage");
    assert_eq!(gs.module.geometry.input, Some(InputPrimitive::Triangles));
    assert_eq!(
        gs.module.geometry.output,
        Some(OutputPrimitive::TriangleStrip)
    );
    assert_eq!(
        gs.module.geometry.max_vertices,
        Some(MAX_GEOMETRY_OUTPUT_VERTICES)
    );
    let pos = gs
        .module
        .globals
        .iter()
        .find(|x| x.name == "gl_PositionIn")
        .expect("gl_PositionIn");
    assert_eq!(pos.storage, Storage::PerVertexInput);
    assert_eq!(pos.ty.array, Some(ArraySize::Sized(3)));
    // The same program in the 1.50 form links to the same layout.
    let g150 = geom(
        "#version 150 compatibility
layout(triangles) in;
layout(triangle_strip, max_vertices = 256) out;
void main() {
    for (int i = 0; i < gl_in.length(); i++) {
        gl_Position = gl_in[i].gl_Position;
        gl_FrontColor = gl_in[i].gl_FrontColor;
        EmitVertex();
    }
}",
    );
    let p150 = link(&[&v, &g150, &f]);
    linked(&p150);
    assert_eq!(
        p150.stage(Stage::Geometry).expect("gs").module.geometry,
        gs.module.geometry
    );
    // GL_ARB_geometry_shader4 is the same extension.
    let arb = geom(&SEED_GS.replace("GL_EXT_geometry_shader4", "GL_ARB_geometry_shader4"));
    linked(&link_tri(&[&v, &arb, &f]));
}

#[test]
fn the_initial_vertex_count_fails_the_link() {
    let v = stage(Stage::Vertex, SEED_VS);
    let g = geom(SEED_GS);
    // GEOMETRY_VERTICES_OUT starts at 0.
    not_linked(&link(&[&v, &g]), "GEOMETRY_VERTICES_OUT is 0");
    not_linked(
        &link_with(
            &[&v, &g],
            &params(
                InputPrimitive::Triangles,
                OutputPrimitive::Points,
                MAX_GEOMETRY_OUTPUT_VERTICES + 1,
            ),
        ),
        "over GL_MAX_GEOMETRY_OUTPUT_VERTICES_EXT",
    );
    // A program needs a vertex shader.
    not_linked(&link_tri(&[&g]), "no vertex shader");
}

#[test]
fn the_extension_is_needed_and_defines_its_macros() {
    for ext in ["GL_EXT_geometry_shader4", "GL_ARB_geometry_shader4"] {
        for behavior in ["enable", "require"] {
            let src = format!(
                "#version 110\n#extension {ext} : {behavior}\n#if {ext} != 1\n#error no macro\n#endif\nvoid main() {{ gl_Position = gl_PositionIn[0]; EmitVertex(); }}"
            );
            ok(&geom(&src));
            // The macro exists in every stage.
            ok(&stage(
                Stage::Vertex,
                &format!("#extension {ext} : enable\n#ifndef {ext}\n#error\n#endif\nvoid main() {{ gl_Position = vec4(0.0); }}"),
            ));
        }
    }
    // A 1.10 geometry shader without it names the extension.
    let g = geom("void main() { EmitVertex(); }");
    fails(&g, Code::VersionTooLow);
    assert!(
        g.info_log().contains("GL_EXT_geometry_shader4"),
        "{}",
        g.info_log()
    );
    // 1.30 is a version the extension extends too.
    ok(&geom(
        "#version 130\n#extension GL_ARB_geometry_shader4 : enable\nin float v[];\nout float w;\nvoid main() { w = v[0]; gl_Position = gl_PositionIn[0]; EmitVertex(); }",
    ));
}

#[test]
fn misuse_gets_diagnostics_that_say_what_to_write() {
    // `varying in` outside a geometry shader.
    let v = stage(
        Stage::Vertex,
        "#extension GL_EXT_geometry_shader4 : enable\nvarying in vec4 c;\nvoid main() { gl_Position = c; }",
    );
    fails(&v, Code::StageMismatch);
    assert!(v.info_log().contains("only allowed in geometry shaders"));
    let f = stage(
        Stage::Fragment,
        "varying out vec4 c;\nvoid main() { gl_FragColor = vec4(1.0); }",
    );
    fails(&f, Code::StageMismatch);
    // In a GLSL 1.50 geometry shader.
    let g = geom("#version 150\nlayout(points) in;\nlayout(points, max_vertices = 1) out;\nvarying in vec4 c[];\nvoid main() { EmitVertex(); }");
    fails(&g, Code::BadQualifier);
    assert!(g.info_log().contains("writes `in'"), "{}", g.info_log());
    // The EXT form's built-ins without the extension.
    let g = geom("#version 120\nvoid main() { gl_Position = gl_PositionIn[0]; }");
    assert!(
        g.info_log()
            .contains("#extension GL_EXT_geometry_shader4 : enable"),
        "{}",
        g.info_log()
    );
    let v = stage(
        Stage::Vertex,
        "#extension GL_EXT_geometry_shader4 : enable\nvoid main() { gl_Position = gl_PositionIn[0]; EmitVertex(); }",
    );
    fails(&v, Code::StageMismatch);
    assert!(
        v.info_log().contains("only available in geometry shaders"),
        "{}",
        v.info_log()
    );
    // An input that is not an array.
    let g = geom("#extension GL_EXT_geometry_shader4 : enable\nvarying in vec4 c;\nvoid main() { gl_Position = c; EmitVertex(); }");
    fails(&g, Code::TypeMismatch);
    assert!(
        g.info_log().contains("`varying in vec4 c[];'"),
        "{}",
        g.info_log()
    );
    // Inputs are float-based before 1.30; structs are not varyings.
    fails(
        &geom("#extension GL_EXT_geometry_shader4 : enable\nvarying in int c[];\nvoid main() { EmitVertex(); }"),
        Code::TypeMismatch,
    );
    // No layouts: the primitives are the program's parameters.
    let g = geom("#version 140\n#extension GL_EXT_geometry_shader4 : enable\nlayout(triangles) in;\nvoid main() { EmitVertex(); }");
    fails(&g, Code::BadQualifier);
    assert!(g.info_log().contains("GL_GEOMETRY_INPUT_TYPE_EXT"));
    // Two sizes only on inputs, and the second is required.
    let g = geom("#extension GL_EXT_geometry_shader4 : enable\nvarying out float v[2][2];\nvoid main() { EmitVertex(); }");
    fails(&g, Code::VersionTooLow);
    assert!(
        g.info_log().contains("GL_ARB_arrays_of_arrays"),
        "{}",
        g.info_log()
    );
    let g = geom("#extension GL_EXT_geometry_shader4 : enable\nvarying in float v[][];\nvoid main() { EmitVertex(); }");
    fails(&g, Code::BadArraySize);
    assert!(g.info_log().contains("second size"), "{}", g.info_log());
    fails(
        &geom("#extension GL_EXT_geometry_shader4 : enable\nvoid main() { float a[2][2]; EmitVertex(); }"),
        Code::VersionTooLow,
    );
    // Without the extension, the error names GL_ARB_arrays_of_arrays.
    let v = stage(
        Stage::Vertex,
        "#version 120\nvarying float v[2][2];\nvoid main() { gl_Position = vec4(0.0); }",
    );
    fails(&v, Code::VersionTooLow);
    assert!(
        v.info_log().contains("GL_ARB_arrays_of_arrays"),
        "{}",
        v.info_log()
    );
}

#[test]
fn two_dimensional_inputs_are_read_per_vertex() {
    let v = stage(
        Stage::Vertex,
        "#version 120\nvarying float v[4];\nvoid main() { for (int i = 0; i < 4; i++) v[i] = float(i); gl_Position = gl_Vertex; }",
    );
    // Indexed twice, passed whole, its `.length()', assigned whole.
    let g = geom(
        "#version 120
#extension GL_ARB_geometry_shader4 : enable
varying in float v[][4];
varying out float o;
float sum(float a[4]) { return a[0] + a[1] + a[2] + a[3]; }
void main() {
  for (int i = 0; i < gl_VerticesIn; i++) {
    float row[4] = v[i];
    o = v[i][3] + sum(v[i]) + float(v[i].length()) + row[0] + float(v.length());
    gl_Position = gl_PositionIn[i];
    EmitVertex();
  }
}",
    );
    ok(&g);
    linked(&link_tri(&[&v, &g]));
    // The element is the vertex output: its size must match at link.
    let v2 = stage(
        Stage::Vertex,
        "#version 120\nvarying float v[2];\nvoid main() { v[0] = 0.0; v[1] = 1.0; gl_Position = gl_Vertex; }",
    );
    not_linked(&link_tri(&[&v2, &g]), "varying `v'");
    // The second index is checked against its size, the first against
    // the input primitive's vertices, and rows of another size are not
    // assignable.
    let bad = |body: &str| {
        geom(&format!(
            "#version 120\n#extension GL_ARB_geometry_shader4 : enable\nvarying in float v[3][2];\nvoid main() {{ {body} EmitVertex(); }}"
        ))
    };
    fails(&bad("float s = v[0][2];"), Code::IndexOutOfRange);
    let g = bad("float s = v[3][0];");
    fails(&g, Code::IndexOutOfRange);
    assert!(g.info_log().contains("float[3][2]"), "{}", g.info_log());
    fails(&bad("float a[3] = v[0];"), Code::TypeMismatch);
    ok(&bad("float s = v[2][1];"));
}

#[test]
fn tex_coord_and_clip_distance_inputs_are_two_dimensional() {
    // gl_TexCoordIn[][]: constant indices within gl_MaxTextureCoords, or
    // any index once redeclared with a size.
    let g = geom("#extension GL_ARB_geometry_shader4 : enable\nvoid main() { gl_Position = gl_TexCoordIn[0][1]; EmitVertex(); }");
    ok(&g);
    let g = geom("#extension GL_ARB_geometry_shader4 : enable\nuniform int k;\nvoid main() { gl_Position = gl_TexCoordIn[0][k]; EmitVertex(); }");
    fails(&g, Code::BadArraySize);
    let g = geom("#extension GL_ARB_geometry_shader4 : enable\nuniform int k;\nvarying in vec4 gl_TexCoordIn[][2];\nvoid main() { gl_Position = gl_TexCoordIn[0][k] + gl_TexCoordIn[1][1]; EmitVertex(); }");
    ok(&g);
    fails(
        &geom("#extension GL_ARB_geometry_shader4 : enable\nvarying in vec4 gl_TexCoordIn[][2];\nvoid main() { gl_Position = gl_TexCoordIn[0][2]; EmitVertex(); }"),
        Code::IndexOutOfRange,
    );
    // gl_ClipDistanceIn[][] (GLSL 1.30): unsized rows have no length
    // and take constant indices below gl_MaxClipDistances.
    let clip = |decl: &str, expr: &str| {
        geom(&format!(
            "#version 130\n#extension GL_ARB_geometry_shader4 : enable\n{decl}\nvoid main() {{ gl_Position = vec4({expr}); EmitVertex(); }}"
        ))
    };
    ok(&clip("", "gl_ClipDistanceIn[0][7]"));
    fails(
        &clip("", "gl_ClipDistanceIn[0][gl_MaxClipDistances]"),
        Code::IndexOutOfRange,
    );
    fails(
        &clip("", "gl_ClipDistanceIn[0].length()"),
        Code::BadArraySize,
    );
    let sized = "in float gl_ClipDistanceIn[3][2];";
    ok(&clip(sized, "gl_ClipDistanceIn[2][1] + float(gl_ClipDistanceIn[0].length() + gl_ClipDistanceIn.length())"));
    fails(
        &clip(sized, "gl_ClipDistanceIn[0][2]"),
        Code::IndexOutOfRange,
    );
    fails(
        &clip(
            "in float gl_ClipDistanceIn[3][gl_MaxClipDistances + 1];",
            "0.0",
        ),
        Code::BadArraySize,
    );
    fails(
        &clip("in vec4 gl_ClipDistanceIn[3][2];", "0.0"),
        Code::Redeclared,
    );
    // Before 1.30 there is no gl_ClipDistanceIn.
    fails(
        &geom("#version 120\n#extension GL_ARB_geometry_shader4 : enable\nvoid main() { gl_Position = vec4(gl_ClipDistanceIn[0][0]); EmitVertex(); }"),
        Code::Undeclared,
    );
    // Linked, an unsized row takes the vertex stage's size.
    let v = stage(
        Stage::Vertex,
        "#version 130\nout float gl_ClipDistance[3];\nvoid main() { gl_ClipDistance[2] = 1.0; gl_Position = gl_Vertex; }",
    );
    let g = clip("", "gl_ClipDistanceIn[1][2]");
    let p = link_tri(&[&v, &g]);
    linked(&p);
    let gs = p.stage(Stage::Geometry).expect("a geometry stage");
    let g = gs
        .module
        .globals
        .iter()
        .find(|g| g.name == "gl_ClipDistanceIn")
        .expect("gl_ClipDistanceIn");
    assert_eq!(g.ty.array, Some(ArraySize::Sized(3)));
    let crate::types::Base::Struct(id) = g.ty.base else {
        panic!("{:?}", g.ty)
    };
    let row = gs.module.structs[id.0 as usize].members[0].ty;
    assert_eq!(row.array, Some(ArraySize::Sized(3)));
}

#[test]
fn inputs_and_outputs_match_the_other_stages_by_name() {
    let v = stage(
        Stage::Vertex,
        "varying vec4 color;\nvarying float size;\nvoid main() { color = gl_Vertex; size = 1.0; gl_Position = gl_Vertex; }",
    );
    let g = geom(
        "#version 120
#extension GL_EXT_geometry_shader4 : enable
varying in vec4 color[];
varying in float size[gl_VerticesIn];
varying out vec4 fcolor;
varying float fsize;
void main() {
    for (int i = 0; i < gl_VerticesIn; ++i) {
        fcolor = color[i];
        fsize = size[i] * float(color.length());
        gl_Position = gl_PositionIn[i];
        EmitVertex();
    }
}",
    );
    ok(&g);
    let m = g.module.as_ref().expect("compiled");
    let color = m.globals.iter().find(|x| x.name == "color").expect("color");
    assert_eq!(color.storage, Storage::PerVertexInput);
    for out in ["fcolor", "fsize"] {
        let o = m.globals.iter().find(|x| x.name == out).expect("output");
        assert_eq!(o.storage, Storage::Varying, "{out}");
    }
    let f = stage(
        Stage::Fragment,
        "varying vec4 fcolor;\nvarying float fsize;\nvoid main() { gl_FragColor = fcolor * fsize; }",
    );
    for (input, n) in [
        (InputPrimitive::Points, 1),
        (InputPrimitive::Lines, 2),
        (InputPrimitive::LinesAdjacency, 4),
        (InputPrimitive::Triangles, 3),
        (InputPrimitive::TrianglesAdjacency, 6),
    ] {
        let p = link_with(&[&v, &g, &f], &params(input, OutputPrimitive::Points, 1));
        linked(&p);
        let gs = &p.stage(Stage::Geometry).expect("gs").module;
        for name in ["color", "size", "gl_PositionIn"] {
            let x = gs.globals.iter().find(|x| x.name == name).expect(name);
            assert_eq!(x.ty.array, Some(ArraySize::Sized(n)), "{name} {input:?}");
        }
    }
    // A vertex output of another type.
    let v2 = stage(
        Stage::Vertex,
        "varying vec3 color;\nvarying float size;\nvoid main() { color = vec3(0.0); size = 1.0; gl_Position = gl_Vertex; }",
    );
    not_linked(&link_tri(&[&v2, &g, &f]), "`color'");
    // A fragment input the geometry shader does not declare.
    let f2 = stage(
        Stage::Fragment,
        "varying vec4 color;\nvoid main() { gl_FragColor = color; }",
    );
    not_linked(&link_tri(&[&v, &g, &f2]), "`color'");
}

#[test]
fn vertices_in_is_a_constant_of_the_programs_input_type() {
    // piglit's verticesin-const: an array size, a constant initializer,
    // a sampler-array index, a texel offset.
    let g = geom(
        "#version 130
#extension GL_ARB_geometry_shader4 : enable
uniform int idx;
uniform sampler2D tex;
uniform sampler2D tex_array[10];
void main() {
    texture(tex_array[gl_VerticesIn * 2 - 2], vec2(0, 0));
    float array[gl_VerticesIn * 2 - 2];
    array[idx];
    const int var = gl_VerticesIn * 2 - 2;
    textureOffset(tex, vec2(0, 0), ivec2(gl_VerticesIn));
    gl_Position = vec4(float(var));
    EmitVertex();
}",
    );
    ok(&g);
    let v = stage(
        Stage::Vertex,
        "#version 130\nvoid main() { gl_Position = vec4(0.0); }",
    );
    // 6 × 2 − 2 = 10 is past the sampler array: not with triangles
    // adjacency, fine with every other input type.
    linked(&link_tri(&[&v, &g]));
    not_linked(
        &link_with(
            &[&v, &g],
            &params(
                InputPrimitive::TrianglesAdjacency,
                OutputPrimitive::Points,
                1,
            ),
        ),
        "GL_TRIANGLES_ADJACENCY_EXT",
    );
    // Valid for some input type compiles; the link decides.
    let g = geom("#extension GL_EXT_geometry_shader4 : enable\nfloat a[gl_VerticesIn - 3];\nvoid main() { gl_Position = vec4(a[0]); EmitVertex(); }");
    ok(&g);
    let v = stage(Stage::Vertex, SEED_VS);
    not_linked(&link_tri(&[&v, &g]), "gl_VerticesIn is 3");
    linked(&link_with(
        &[&v, &g],
        &params(InputPrimitive::LinesAdjacency, OutputPrimitive::Points, 1),
    ));
    // Valid for none: the diagnostics are the triangles', with a note.
    let g = geom("#extension GL_EXT_geometry_shader4 : enable\nfloat a[gl_VerticesIn - 6];\nvoid main() { gl_Position = vec4(a[0]); EmitVertex(); }");
    fails(&g, Code::BadArraySize);
    assert!(
        g.info_log().contains("gl_VerticesIn = 3"),
        "{}",
        g.info_log()
    );
}

#[test]
fn input_sizes_and_indices_are_checked_at_link() {
    let v = stage(
        Stage::Vertex,
        "varying float x;\nvoid main() { x = 1.0; gl_Position = gl_Vertex; }",
    );
    // piglit's input-overrun tests: a constant index past the vertices.
    let g = geom("#version 110\n#extension GL_ARB_geometry_shader4 : enable\nvoid main() { gl_Position = gl_PositionIn[2]; EmitVertex(); }");
    ok(&g);
    for (input, fine) in [
        (InputPrimitive::Points, false),
        (InputPrimitive::Lines, false),
        (InputPrimitive::Triangles, true),
        (InputPrimitive::LinesAdjacency, true),
    ] {
        let p = link_with(&[&v, &g], &params(input, OutputPrimitive::Points, 1));
        assert_eq!(p.ok(), fine, "{input:?}: {}", p.info_log());
    }
    // A sized input array must have the input type's vertex count.
    let g = geom("#extension GL_EXT_geometry_shader4 : enable\nvarying in float x[3];\nvoid main() { gl_Position = vec4(x[0]); EmitVertex(); }");
    ok(&g);
    linked(&link_tri(&[&v, &g]));
    not_linked(
        &link_with(
            &[&v, &g],
            &params(InputPrimitive::Lines, OutputPrimitive::LineStrip, 2),
        ),
        "input primitives of type GL_LINES have 2 vertices",
    );
    // Sized inputs of two sizes can never link: a compile error.
    fails(
        &geom("#extension GL_EXT_geometry_shader4 : enable\nvarying in float x[3];\nvarying in float y[2];\nvoid main() { EmitVertex(); }"),
        Code::BadArraySize,
    );
    // Past every primitive's vertices: compiles (with a warning), and no
    // input type links (GL_EXT_geometry_shader4 §4.3.6).
    let g = geom("#version 110\n#extension GL_ARB_geometry_shader4 : enable\nvoid main() { gl_Position = gl_PositionIn[6]; EmitVertex(); }");
    ok(&g);
    assert!(g.info_log().contains("warning"), "{}", g.info_log());
    for input in [
        InputPrimitive::Triangles,
        InputPrimitive::TrianglesAdjacency,
    ] {
        let p = link_with(&[&v, &g], &params(input, OutputPrimitive::Points, 1));
        not_linked(&p, "out of range");
    }
    // Other errors are still errors.
    fails(
        &geom("#version 110\n#extension GL_ARB_geometry_shader4 : enable\nvoid main() { gl_Position = gl_PositionIn[6]; int k = 1.0; EmitVertex(); }"),
        Code::TypeMismatch,
    );
    // Link errors point into the object.
    let g = geom("#extension GL_EXT_geometry_shader4 : enable\nvarying in float x[];\nvoid main() {\n gl_Position = vec4(x[4]);\n EmitVertex();\n}");
    ok(&g);
    let p = link_tri(&[&v, &g]);
    not_linked(&p, "0:4(");
}

#[test]
fn outputs_and_fixed_function_built_ins() {
    // piglit's constants.geom and the outputs of GL_EXT_geometry_shader4
    // §7.1 and §7.6.
    let g = geom(
        "#extension GL_ARB_geometry_shader4: enable
uniform sampler2D s;
void main()
{
  int i = gl_MaxLights + gl_MaxClipPlanes + gl_MaxTextureUnits + gl_MaxTextureCoords
    + gl_MaxVertexAttribs + gl_MaxVertexUniformComponents + gl_MaxVaryingFloats
    + gl_MaxVertexTextureImageUnits + gl_MaxCombinedTextureImageUnits
    + gl_MaxTextureImageUnits + gl_MaxFragmentUniformComponents + gl_MaxDrawBuffers;
  gl_Position = gl_ModelViewProjectionMatrix * vec4(i);
  gl_PointSize = gl_PointSizeIn[0];
  gl_ClipVertex = gl_ClipVertexIn[0];
  gl_FrontColor = gl_FrontColorIn[0];
  gl_BackColor = gl_BackColorIn[0];
  gl_FrontSecondaryColor = gl_FrontSecondaryColorIn[0];
  gl_BackSecondaryColor = gl_BackSecondaryColorIn[0];
  gl_TexCoord[0] = texture2DLod(s, vec2(gl_FogFragCoordIn[0]), 0.0);
  gl_FogFragCoord = 1.0;
  gl_Layer = 0;
  gl_PrimitiveID = gl_PrimitiveIDIn;
  EmitVertex();
  EndPrimitive();
}",
    );
    ok(&g);
    // Inputs are read-only.
    fails(
        &geom("#extension GL_EXT_geometry_shader4 : enable\nvoid main() { gl_PositionIn[0] = vec4(0.0); }"),
        Code::ReadOnly,
    );
    // `gl_VerticesIn` is a constant.
    fails(
        &geom("#extension GL_EXT_geometry_shader4 : enable\nvoid main() { gl_VerticesIn = 2; }"),
        Code::ReadOnly,
    );
}

#[test]
fn the_extensions_built_in_environments_are_clean() {
    use crate::lang::{Extension, Profile, Version};
    for v in [Version::V110, Version::V120, Version::V130, Version::V140] {
        for profile in [Profile::Core, Profile::Compatibility] {
            for e in [Extension::ExtGeometryShader4, Extension::ArbGeometryShader4] {
                let mut lang = crate::Language::new(v, true);
                lang.profile = profile;
                lang.extensions.set(e, true);
                for p in InputPrimitive::ALL {
                    let env = super::builtin_env_for_input(lang, Stage::Geometry, p);
                    assert!(
                        env.diagnostics.is_empty(),
                        "{v:?} {profile:?}: {:?}",
                        env.diagnostics
                    );
                    let compat = profile == Profile::Compatibility || v < Version::V140;
                    for name in [
                        "gl_PositionIn",
                        "gl_PrimitiveIDIn",
                        "gl_VerticesIn",
                        "EmitVertex",
                        "gl_Layer",
                    ] {
                        assert!(env.lookup(name).is_some(), "{name} {v:?}");
                    }
                    assert_eq!(
                        env.lookup("gl_FrontColorIn").is_some(),
                        compat,
                        "{v:?} {profile:?}"
                    );
                    assert!(env.lookup("gl_in").is_none());
                }
            }
        }
    }
    // Without the extension, and in GLSL 1.50, none of its names.
    let lang = crate::Language::new(Version::V150, true);
    assert!(super::builtin_env(lang, Stage::Geometry)
        .lookup("gl_PositionIn")
        .is_none());
    let mut lang = crate::Language::new(Version::V120, true);
    lang.extensions.set(Extension::ExtGeometryShader4, true);
    assert!(super::builtin_env(lang, Stage::Vertex)
        .lookup("gl_PositionIn")
        .is_none());
}
