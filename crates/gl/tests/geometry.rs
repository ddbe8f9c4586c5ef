//! Geometry shaders through `gl::Context` (GL 3.3 §2.12): points
//! expanded to quads, primitive IDs in and out, the draw-mode check, the
//! program queries, and the adjacency modes without a geometry stage.

use gl::enums::*;
use gl::{Api, ArrayData, Context};

mod common;

const W: i32 = 32;
const H: i32 = 32;

const VS: &str = "#version 150 compatibility
in vec2 pos;
in vec3 color;
out vec3 vcolor;
void main() { gl_Position = vec4(pos, 0.0, 1.0); vcolor = color; }";

/// Each point becomes an 8×8-pixel square in its vertex's colour; its
/// primitive ID goes to the fragment stage plus 10.
const GS: &str = "#version 150
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
in vec3 vcolor[];
out vec3 gcolor;
void main() {
    for (int i = 0; i < 4; i++) {
        vec2 corner = vec2(i % 2, i / 2) * 0.5 - 0.25;
        gl_Position = gl_in[0].gl_Position + vec4(corner, 0.0, 0.0);
        gcolor = vcolor[0];
        gl_PrimitiveID = gl_PrimitiveIDIn + 10;
        EmitVertex();
    }
}";

const FS: &str = "#version 150
in vec3 gcolor;
out vec4 frag;
void main() { frag = vec4(gcolor, float(gl_PrimitiveID) / 255.0); }";

/// A 3.3 compatibility context with `verts` (x, y, r, g, b) in client
/// arrays for `pos` and `color` of program `p`.
fn setup(stages: &[(u32, &str)], verts: &[[f32; 5]]) -> (Context, u32) {
    let mut ctx = Context::with_api(W, H, Api::GL33_COMPAT);
    let p = common::linked_stages(&mut ctx, stages);
    ctx.clear_color(0.0, 0.0, 0.0, 0.0);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    let pos: Vec<f32> = verts.iter().flat_map(|v| [v[0], v[1]]).collect();
    let color: Vec<f32> = verts.iter().flat_map(|v| [v[2], v[3], v[4]]).collect();
    for (name, size, data) in [("pos", 2, &pos), ("color", 3, &color)] {
        let loc = ctx.get_attrib_location(p, name);
        if loc < 0 {
            continue;
        }
        let data = ArrayData::from_f32(data);
        ctx.vertex_attrib_pointer(loc as u32, size, GL_FLOAT, false, 0, data);
        ctx.enable_vertex_attrib_array(loc as u32);
    }
    (ctx, p)
}

/// The pixels of each distinct colour, brightest first.
fn histogram(ctx: &mut Context) -> Vec<([u8; 4], usize)> {
    let img = ctx.read_pixels_f32(0, 0, W, H);
    let mut counts = std::collections::BTreeMap::new();
    for px in img {
        *counts
            .entry(px.map(|c| (c * 255.0).round() as u8))
            .or_insert(0) += 1;
    }
    let mut v: Vec<_> = counts.into_iter().collect();
    v.sort_by_key(|e| std::cmp::Reverse(e.0));
    v
}

#[test]
fn points_become_quads_with_primitive_ids() {
    let stages = [
        (GL_VERTEX_SHADER, VS),
        (GL_GEOMETRY_SHADER, GS),
        (GL_FRAGMENT_SHADER, FS),
    ];
    let verts = [[-0.5, -0.5, 1.0, 0.0, 0.0], [0.5, 0.5, 0.0, 1.0, 0.0]];
    let (mut ctx, p) = setup(&stages, &verts);
    ctx.draw_arrays(GL_POINTS, 0, 2);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.take_draw_error(), None);
    assert_eq!(
        histogram(&mut ctx),
        vec![
            ([255, 0, 0, 10], 64),
            ([0, 255, 0, 11], 64),
            ([0, 0, 0, 0], (W * H - 128) as usize),
        ]
    );
    assert_eq!(ctx.get_programiv(p, GL_GEOMETRY_VERTICES_OUT), 4);
    assert_eq!(
        ctx.get_programiv(p, GL_GEOMETRY_INPUT_TYPE),
        GL_POINTS as i32
    );
    assert_eq!(
        ctx.get_programiv(p, GL_GEOMETRY_OUTPUT_TYPE),
        GL_TRIANGLE_STRIP as i32
    );
    assert_eq!(ctx.get_error(), GL_NO_ERROR);

    // A mode the geometry stage does not take: GL_INVALID_OPERATION and
    // nothing drawn.
    ctx.clear(GL_COLOR_BUFFER_BIT);
    ctx.draw_arrays(GL_LINES, 0, 2);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    assert_eq!(histogram(&mut ctx), vec![([0, 0, 0, 0], (W * H) as usize)]);
}

#[test]
fn geometry_queries_need_a_geometry_stage() {
    let fs = "#version 150\nin vec3 vcolor;\nout vec4 c;\nvoid main() { c = vec4(vcolor, 1.0); }";
    let (mut ctx, p) = setup(&[(GL_VERTEX_SHADER, VS), (GL_FRAGMENT_SHADER, fs)], &[]);
    assert_eq!(ctx.get_programiv(p, GL_GEOMETRY_VERTICES_OUT), 0);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    // A 2.1 context creates geometry shaders (GL_EXT_geometry_shader4)
    // but has no GL 3.2 queries.
    let mut old = Context::with_api(W, H, Api::GL21);
    assert_ne!(old.create_shader(GL_GEOMETRY_SHADER_EXT), 0);
    let p = old.create_program();
    assert_eq!(old.get_programiv(p, GL_GEOMETRY_VERTICES_OUT), 0);
    assert_eq!(old.get_error(), GL_INVALID_ENUM);
    // Nor does a core context have the extension's parameters.
    let mut core = Context::with_api(W, H, Api::GL33_CORE);
    let p = core.create_program();
    core.program_parameteri(p, GL_GEOMETRY_VERTICES_OUT_EXT, 3);
    assert_eq!(core.get_error(), GL_INVALID_ENUM);
}

/// Strips are cut by `EndPrimitive`, emission past `max_vertices` is
/// dropped, and odd triangles keep the strip's winding (culling back
/// faces removes none).
#[test]
fn strips_end_and_stop_at_max_vertices() {
    let gs = "#version 150
layout(triangles) in;
layout(triangle_strip, max_vertices = 6) out;
in vec3 vcolor[];
out vec3 gcolor;
void main() {
    // Two 3-vertex strips, the left and right halves of the screen
    // (each a triangle), then vertices beyond max_vertices.
    for (int s = 0; s < 2; s++) {
        float x0 = s == 0 ? -1.0 : 0.0;
        gl_Position = vec4(x0, -1.0, 0.0, 1.0); gcolor = vcolor[s]; EmitVertex();
        gl_Position = vec4(x0 + 1.0, -1.0, 0.0, 1.0); EmitVertex();
        gl_Position = vec4(x0, 1.0, 0.0, 1.0); EmitVertex();
        EndPrimitive();
    }
    gl_Position = vec4(1.0, 1.0, 0.0, 1.0); gcolor = vec3(1.0); EmitVertex();
    EmitVertex();
    EmitVertex();
}";
    let fs = "#version 150\nin vec3 gcolor;\nout vec4 c;\nvoid main() { c = vec4(gcolor, 1.0); }";
    let stages = [
        (GL_VERTEX_SHADER, VS),
        (GL_GEOMETRY_SHADER, gs),
        (GL_FRAGMENT_SHADER, fs),
    ];
    let verts = [
        [0.0, 0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, 0.0, 0.0, 1.0],
        [0.0, 0.0, 0.0, 0.0, 0.0],
    ];
    let (mut ctx, _) = setup(&stages, &verts);
    ctx.enable(GL_CULL_FACE);
    ctx.draw_arrays(GL_TRIANGLES, 0, 3);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    let h = histogram(&mut ctx);
    // Each half's lower-left triangle: 16×32 pixels halved (no pixel
    // centre lies on the diagonals).
    let tri = |c: [u8; 4]| h.iter().find(|(k, _)| *k == c).map_or(0, |e| e.1);
    assert_eq!(tri([255, 0, 0, 255]), 256, "{h:?}");
    assert_eq!(tri([0, 0, 255, 255]), 256, "{h:?}");
    assert_eq!(tri([255, 255, 255, 255]), 0, "{h:?}");
}

/// Without a geometry shader the adjacency modes draw their primitives
/// and ignore the adjacent vertices (GL 3.3 §2.6.1).
#[test]
fn adjacency_modes_without_a_geometry_stage() {
    let fs = "#version 150\nin vec3 vcolor;\nout vec4 c;\nvoid main() { c = vec4(vcolor, 1.0); }";
    let stages = [(GL_VERTEX_SHADER, VS), (GL_FRAGMENT_SHADER, fs)];
    // Triangles with adjacency: vertices 0, 2, 4 make the triangle (the
    // lower-left half of the screen); 1, 3, 5 are far away.
    let far = [5.0, 5.0, 0.0, 0.0, 0.0];
    let verts = [
        [-1.0, -1.0, 1.0, 1.0, 1.0],
        far,
        [1.0, -1.0, 1.0, 1.0, 1.0],
        far,
        [-1.0, 1.0, 1.0, 1.0, 1.0],
        far,
    ];
    let (mut ctx, _) = setup(&stages, &verts);
    ctx.draw_arrays(GL_TRIANGLES_ADJACENCY, 0, 6);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    // The lower-left half of 32×32 pixels: 496 centres inside, the 32 on
    // the diagonal belong to the triangle on its other side (GL 3.3
    // §3.6.1's rule).
    let white = histogram(&mut ctx)[0];
    assert_eq!(white, ([255, 255, 255, 255], 496));
}

/// Transform feedback captures the geometry stage's outputs, its strips
/// decomposed into independent primitives, and needs the feedback mode
/// of the geometry stage's output; GL_PRIMITIVES_GENERATED counts the
/// emitted primitives (GL 3.3 §2.16).
#[test]
fn transform_feedback_captures_the_emitted_primitives() {
    let vs =
        "#version 150\nin float x;\nout float vx;\nvoid main() { vx = x; gl_Position = vec4(x); }";
    // Each point becomes a 4-vertex line strip: 3 lines.
    let gs = "#version 150
layout(points) in;
layout(line_strip, max_vertices = 4) out;
in float vx[];
out float v;
void main() { for (int i = 0; i < 4; i++) { v = vx[0] * 10.0 + float(i); EmitVertex(); } }";
    let fs = "#version 150\nout vec4 c;\nvoid main() { c = vec4(1.0); }";
    let mut ctx = Context::with_api(W, H, Api::GL33_COMPAT);
    let stages = [
        (GL_VERTEX_SHADER, vs),
        (GL_GEOMETRY_SHADER, gs),
        (GL_FRAGMENT_SHADER, fs),
    ];
    let p = common::attached_stages(&mut ctx, &stages);
    ctx.bind_attrib_location(p, 0, "x");
    ctx.transform_feedback_varyings(p, &["v".to_string()], GL_INTERLEAVED_ATTRIBS);
    common::link_and_use(&mut ctx, p);
    let b = common::feedback_buffer(&mut ctx, 0, 64 * 4);
    ctx.vertex_attrib_pointer(0, 1, GL_FLOAT, false, 0, ArrayData::from_f32(&[1.0, 2.0]));
    ctx.enable_vertex_attrib_array(0);
    // Points captured as points: the geometry stage emits lines.
    ctx.begin_transform_feedback(GL_POINTS);
    ctx.draw_arrays(GL_POINTS, 0, 2);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    ctx.end_transform_feedback();
    let q = ctx.gen_queries(1)[0];
    ctx.begin_query(GL_PRIMITIVES_GENERATED, q);
    ctx.begin_transform_feedback(GL_LINES);
    ctx.draw_arrays(GL_POINTS, 0, 2);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    ctx.end_transform_feedback();
    ctx.end_query(GL_PRIMITIVES_GENERATED);
    // The geometry stage's primitives are counted: 3 lines per point.
    assert_eq!(ctx.get_query_object(q, GL_QUERY_RESULT), Some(6));
    let got = common::floats(&mut ctx, b, 12);
    let want = [
        10.0, 11.0, 11.0, 12.0, 12.0, 13.0, 20.0, 21.0, 21.0, 22.0, 22.0, 23.0,
    ];
    assert_eq!(got, want);
}

/// gl_Layer sends each emitted primitive to a layer of a layered
/// framebuffer: the layers of a 2D array texture, the faces of a cube map
/// (GL 3.3 §4.4.7), the layer-faces of a cube map array
/// (GL_ARB_texture_cube_map_array); a layer the framebuffer lacks draws
/// nothing.
#[test]
fn gl_layer_selects_the_layer_drawn() {
    let vs = "#version 150\nin vec2 pos;\nvoid main() { gl_Position = vec4(pos, 0.0, 1.0); }";
    let gs = "#version 150
layout(triangles) in;
layout(triangle_strip, max_vertices = 39) out;
uniform int layers;
flat out int layer;
void main() {
    // One more layer than the framebuffer has: not drawn.
    for (int l = 0; l <= layers; l++) {
        for (int i = 0; i < 3; i++) {
            gl_Position = gl_in[i].gl_Position;
            gl_Layer = l;
            layer = l;
            EmitVertex();
        }
        EndPrimitive();
    }
}";
    let fs = "#version 150\nflat in int layer;\nout vec4 c;\nvoid main() { c = vec4(float(layer + 1) / 255.0, 0.0, 0.0, 1.0); }";
    for (target, layers) in [
        (GL_TEXTURE_2D_ARRAY, 3),
        (GL_TEXTURE_CUBE_MAP, 6),
        (GL_TEXTURE_CUBE_MAP_ARRAY_ARB, 12),
    ] {
        let mut ctx = Context::with_api(4, 4, Api::GL33_COMPAT);
        let p = common::linked_stages(
            &mut ctx,
            &[
                (GL_VERTEX_SHADER, vs),
                (GL_GEOMETRY_SHADER, gs),
                (GL_FRAGMENT_SHADER, fs),
            ],
        );
        let loc = ctx.get_uniform_location(p, "layers");
        ctx.uniform_1i(loc, layers);
        let t = ctx.gen_textures(1)[0];
        ctx.bind_texture(target, t);
        let zeros = vec![0u8; 4 * 4 * 4 * 12];
        if target == GL_TEXTURE_CUBE_MAP {
            for f in 0..6 {
                ctx.tex_image(
                    GL_TEXTURE_CUBE_MAP_POSITIVE_X + f,
                    0,
                    GL_RGBA8 as i32,
                    [4, 4],
                    0,
                    GL_RGBA,
                    GL_UNSIGNED_BYTE,
                    Some(&zeros[..64]),
                );
            }
        } else {
            let bytes = &zeros[..64 * layers as usize];
            ctx.tex_image(
                target,
                0,
                GL_RGBA8 as i32,
                [4, 4, layers],
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(bytes),
            );
        }
        let fb = ctx.gen_framebuffers(1)[0];
        ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
        ctx.framebuffer_texture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t, 0);
        assert_eq!(
            ctx.check_framebuffer_status(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_COMPLETE
        );
        ctx.viewport(0, 0, 4, 4);
        let tri = [-1.0f32, -1.0, 3.0, -1.0, -1.0, 3.0];
        let loc = ctx.get_attrib_location(p, "pos") as u32;
        ctx.vertex_attrib_pointer(loc, 2, GL_FLOAT, false, 0, ArrayData::from_f32(&tri));
        ctx.enable_vertex_attrib_array(loc);
        ctx.draw_arrays(GL_TRIANGLES, 0, 3);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(ctx.take_draw_error(), None);
        for l in 0..layers {
            let bytes = if target == GL_TEXTURE_CUBE_MAP {
                ctx.get_tex_image(
                    GL_TEXTURE_CUBE_MAP_POSITIVE_X + l as u32,
                    0,
                    GL_RGBA,
                    GL_UNSIGNED_BYTE,
                )
            } else {
                let all = ctx.get_tex_image(target, 0, GL_RGBA, GL_UNSIGNED_BYTE);
                all[64 * l as usize..64 * (l as usize + 1)].to_vec()
            };
            for px in bytes.chunks_exact(4) {
                assert_eq!(px, [l as u8 + 1, 0, 0, 255], "target {target:#x} layer {l}");
            }
        }
    }
}

/// The seed lecture's "Simple Program" (GL_EXT_geometry_shader4 on a GL
/// 2.1 context): the program parameters set with GL 3.2's names as the
/// lecture passes them, the vertex count the implementation's maximum,
/// a pass-through geometry shader of its "Simple Coloring Faces" pair;
/// front faces take their colour, back faces black.
#[test]
fn the_seed_lecture_program_on_a_2_1_context() {
    let vs = "// vertex shader
void main(void)
{
 gl_Position = gl_ModelViewProjectionMatrix*gl_Vertex;
 gl_FrontColor = gl_Color;
 gl_BackColor = vec4(0,0,0,0); // black for backface
}";
    let gs = "#version 120
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
    let fs = "// fragment shader
void main(void)
{
 gl_FragColor = gl_Color;
}";
    let mut ctx = Context::with_api(W, H, Api::GL21);
    assert!(ctx
        .get_string(GL_EXTENSIONS)
        .contains("GL_EXT_geometry_shader4"));
    // Attached in the lecture's order.
    let stages = [
        (GL_FRAGMENT_SHADER, fs),
        (GL_VERTEX_SHADER, vs),
        (GL_GEOMETRY_SHADER_EXT, gs),
    ];
    let p = common::attached_stages(&mut ctx, &stages);
    ctx.program_parameteri(p, GL_GEOMETRY_INPUT_TYPE, GL_TRIANGLES as i32);
    ctx.program_parameteri(p, GL_GEOMETRY_OUTPUT_TYPE, GL_TRIANGLE_STRIP as i32);
    let max = ctx.get_integerv(GL_MAX_GEOMETRY_OUTPUT_VERTICES_EXT)[0];
    assert_eq!(max, 256);
    ctx.program_parameteri(p, GL_GEOMETRY_VERTICES_OUT_EXT, max);
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.get_programiv(p, GL_GEOMETRY_VERTICES_OUT_EXT), 256);
    assert_eq!(
        ctx.get_programiv(p, GL_GEOMETRY_INPUT_TYPE_EXT),
        GL_TRIANGLES as i32
    );
    common::link_and_use(&mut ctx, p);
    ctx.enable(GL_VERTEX_PROGRAM_TWO_SIDE);
    ctx.clear_color(0.0, 0.0, 1.0, 1.0);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    // A counter-clockwise (front) red triangle on the left, a clockwise
    // (back) one on the right.
    ctx.begin(GL_TRIANGLES);
    ctx.color_4f(1.0, 0.0, 0.0, 1.0);
    for (x, y) in [(-1.0, -1.0), (0.0, -1.0), (-1.0, 1.0)] {
        ctx.vertex_4f(x, y, 0.0, 1.0);
    }
    for (x, y) in [(0.0, -1.0), (0.0, 1.0), (1.0, -1.0)] {
        ctx.vertex_4f(x, y, 0.0, 1.0);
    }
    ctx.end();
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.take_draw_error(), None);
    let h = histogram(&mut ctx);
    let count = |c: [u8; 4]| h.iter().find(|(k, _)| *k == c).map_or(0, |e| e.1);
    assert_eq!(count([255, 0, 0, 255]), 256, "{h:?}");
    assert_eq!(count([0, 0, 0, 0]), 256, "{h:?}");
    // Points do not feed a triangles geometry stage.
    ctx.begin(GL_POINTS);
    assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
}
