//! gl_PrimitiveID in a fragment shader without a geometry shader (GL 3.3
//! §3.12.2): primitives numbered from zero in each draw, a quad counted
//! once, a restart index leaving the counter alone, every instance
//! numbered afresh.

use gl::enums::*;
use gl::{Api, ArrayData, Context};

mod common;

const W: i32 = 32;
const H: i32 = 32;

fn program(ctx: &mut Context) -> u32 {
    // Each vertex carries the ID its primitive should have when it is
    // that primitive's provoking (last) vertex; instance i is moved up
    // by i.
    let vs = "#version 150 compatibility\n\
        in vec2 pos; in float expected;\n\
        flat out int want;\n\
        void main() { gl_Position = vec4(pos + vec2(0.0, float(gl_InstanceID)), 0.0, 1.0); want = int(expected); }";
    let fs = "#version 150 compatibility\n\
        flat in int want;\n\
        void main() { gl_FragColor = want == gl_PrimitiveID ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0); }";
    common::program(ctx, vs, fs)
}

/// Draws `mode` from vertices `(x, y, expected ID)`, through `indices`
/// (with restart index 99) when given, `instances` times; returns the
/// number of green pixels, asserting no other colour was drawn.
fn draw(mode: u32, verts: &[[f32; 3]], indices: Option<&[u32]>, instances: i32) -> usize {
    let mut ctx = Context::with_api(W, H, Api::GL33_COMPAT);
    let p = program(&mut ctx);
    ctx.clear_color(0.0, 0.0, 0.0, 0.0);
    ctx.clear(GL_COLOR_BUFFER_BIT);
    let pos: Vec<f32> = verts.iter().flat_map(|v| [v[0], v[1]]).collect();
    let expected: Vec<f32> = verts.iter().map(|v| v[2]).collect();
    for (name, size, data) in [("pos", 2, &pos), ("expected", 1, &expected)] {
        let loc = ctx.get_attrib_location(p, name);
        assert!(loc >= 0, "{name}");
        ctx.vertex_attrib_pointer(
            loc as u32,
            size,
            GL_FLOAT,
            false,
            0,
            ArrayData::from_f32(data),
        );
        ctx.enable_vertex_attrib_array(loc as u32);
    }
    match indices {
        Some(list) => {
            ctx.enable(GL_PRIMITIVE_RESTART);
            ctx.primitive_restart_index(99);
            ctx.draw_elements_instanced(
                mode,
                list.len() as i32,
                GL_UNSIGNED_INT,
                ArrayData::from_u32(list),
                instances,
            );
        }
        None => ctx.draw_arrays_instanced(mode, 0, verts.len() as i32, instances),
    }
    assert_eq!(ctx.get_error(), GL_NO_ERROR);
    assert_eq!(ctx.take_draw_error(), None);
    let img = ctx.read_pixels_f32(0, 0, W, H);
    let mut green = 0;
    for (i, px) in img.iter().enumerate() {
        match px {
            [0.0, 1.0, 0.0, 1.0] => green += 1,
            [0.0, 0.0, 0.0, 0.0] => {}
            other => panic!("mode {mode:#x}, pixel {i}: {other:?}"),
        }
    }
    green
}

/// A strip of two triangles over `[x, x + 0.5] × [-1, 0]`, its second
/// and third... vertices expecting `first` and `first + 1`.
fn strip(x: f32, first: f32) -> [[f32; 3]; 4] {
    [
        [x, -1.0, -1.0],
        [x + 0.5, -1.0, -1.0],
        [x, 0.0, first],
        [x + 0.5, 0.0, first + 1.0],
    ]
}

#[test]
fn quads_count_once() {
    // Two quads side by side: IDs 0 and 1 (the fourth vertex provokes).
    let mut verts = Vec::new();
    for (q, x) in [-1.0f32, 0.0].into_iter().enumerate() {
        for (dx, dy) in [(0.0, -1.0), (1.0, -1.0), (1.0, 1.0), (0.0, 1.0)] {
            verts.push([x + dx, dy, q as f32]);
        }
    }
    assert_eq!(draw(GL_QUADS, &verts, None, 1), (W * H) as usize);
}

#[test]
fn strips_restart_and_instances() {
    // Two strips, the second after a restart index: IDs 0, 1, then 2, 3.
    let mut verts = strip(-1.0, 0.0).to_vec();
    verts.extend(strip(0.0, 2.0));
    let list = [0, 1, 2, 3, 99, 4, 5, 6, 7];
    let one = draw(GL_TRIANGLE_STRIP, &verts, Some(&list), 1);
    assert_eq!(one, (W * H / 4) as usize);
    // Instanced (one draw for the instances together): each instance's
    // IDs start at zero again.
    assert_eq!(draw(GL_TRIANGLE_STRIP, &verts, Some(&list), 2), 2 * one);
    assert_eq!(draw(GL_TRIANGLE_STRIP, &verts[..4], None, 2), one);
}

#[test]
fn quad_strips_restart_and_instances() {
    // A one-quad strip, a restart, a two-quad strip: IDs 0, then 1, 2.
    let verts = [
        [-1.0, -1.0, -1.0],
        [-0.5, -1.0, -1.0],
        [-1.0, 0.0, -1.0],
        [-0.5, 0.0, 0.0],
        [0.0, -1.0, -1.0],
        [0.5, -1.0, -1.0],
        [0.0, -0.5, -1.0],
        [0.5, -0.5, 1.0],
        [0.0, 0.0, -1.0],
        [0.5, 0.0, 2.0],
    ];
    let list = [0, 1, 2, 3, 99, 4, 5, 6, 7, 8, 9];
    let one = draw(GL_QUAD_STRIP, &verts, Some(&list), 1);
    assert_eq!(one, (W * H / 4) as usize);
    assert_eq!(draw(GL_QUAD_STRIP, &verts, Some(&list), 2), 2 * one);
}
