//! The gallery: every program of the shader library drawn on a scene that
//! suits it, for `shaderbox gallery -o DIR`.
//!
//! - sphere impostor programs (and the effects): crambin, [`crate::render`];
//! - the cylinder program: crambin in ball-and-stick;
//! - lighting, materials, toon, trivial, wireframe (both forms), normals:
//!   a torus (the
//!   two-sided lighting program: an open tube whose inside shows its back
//!   faces), perspective, lit by directional, point and spot lights; the
//!   normals view draws the torus with the materials program first and
//!   its lines over it;
//! - texturing: a quad with vertex colours, a checkerboard texture with
//!   alpha on unit 0 and a ring texture on unit 1, once per environment
//!   mode;
//! - volume: the unit cube holding a 32^3 RGBA texture of two blobs in a
//!   shell.
//!
//! [`entries`] lists the pictures; [`draw`] renders one; [`index_html`]
//! writes the page that shows them.

use crate::library::{self, Program, SceneKind};
use crate::{
    image, Atoms, Background, Effect, Fog, Image, Projection, RenderError, RenderOptions, Style,
};
use gl::enums::*;
use gl::{ArrayData, Context, Param};

/// One picture of the gallery.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// File name without extension.
    pub file: String,
    pub program: &'static Program,
    /// Texture environment mode of the texturing programs (unit 0, unit 1).
    pub modes: Option<(i32, i32)>,
    /// The settings, as shown on the page.
    pub settings: String,
}

const MODE_NAMES: [&str; 6] = ["replace", "modulate", "decal", "blend", "add", "combine"];

/// Every picture: one per program, one per environment mode for
/// single-texture.
pub fn entries() -> Vec<Entry> {
    let mut out = Vec::new();
    for p in library::PROGRAMS {
        let base = |settings: String| Entry {
            file: p.name.to_string(),
            program: p,
            modes: None,
            settings,
        };
        match p.scene {
            SceneKind::Molecule | SceneKind::BallAndStick => {
                out.push(base(molecule_options(p, 1).describe()));
            }
            SceneKind::TexturedQuad if p.name == "single-texture" => {
                for (mode, name) in MODE_NAMES.iter().enumerate() {
                    out.push(Entry {
                        file: format!("{}-{name}", p.name),
                        modes: Some((mode as i32, 0)),
                        settings: format!("TexturingType = {mode} ({})", name.to_uppercase()),
                        ..base(String::new())
                    });
                }
            }
            SceneKind::TexturedQuad => out.push(Entry {
                modes: Some((1, 4)),
                settings: "TexturingType0 = 1 (MODULATE), TexturingType1 = 4 (ADD)".into(),
                ..base(String::new())
            }),
            SceneKind::Mesh | SceneKind::WireMesh | SceneKind::Normals => {
                out.push(base(mesh_settings(p)))
            }
            SceneKind::Volume => out.push(base(
                "32^3 RGBA texture, steps = 96, opacity = 0.5, perspective".into(),
            )),
        }
    }
    out
}

fn molecule_options(p: &Program, size: u32) -> RenderOptions {
    let effect = match p.name {
        "outline" => Effect::Outline,
        "x" => Effect::X,
        "x-red" => Effect::XRed,
        "transparent" => Effect::Transparent,
        _ => Effect::Plain,
    };
    RenderOptions {
        width: size,
        height: size,
        projection: Projection::Perspective,
        fog: Fog::Linear,
        rotate: [20.0, 30.0, 0.0],
        background: Background::Color([0.1, 0.1, 0.12]),
        effect,
        atoms: if p.geometry.is_some() {
            Atoms::Points
        } else {
            Atoms::Quads
        },
        style: if p.scene == SceneKind::BallAndStick {
            Style::BallAndStick
        } else {
            Style::Spacefill
        },
        ..RenderOptions::default()
    }
}

fn mesh_settings(p: &Program) -> String {
    match p.name {
        "two-sided-lighting" => "open tube; front material orange, back material blue; light 0 directional, 1 point, 2 spot".into(),
        "one-sided-lighting" => "torus; light 0 directional, 1 point, 2 spot; front material".into(),
        "variable-lights" => "torus; light_enabled = 1,1,1,0,0,0,0,0 (three coloured directional lights)".into(),
        "wireframe" => "torus; line_width = 1.5 px, line_color black".into(),
        "wireframe-geom" => "torus (no corner attributes); line_width = 1.5 px, line_color black".into(),
        "normals" => "torus drawn by materials, then normal_length = 0.15, root_color yellow, tip_color red".into(),
        "toon" => "torus; light 0 directional, bands 1.0/0.6/0.4/0.2".into(),
        _ => "torus; lights 0 and 1 directional; vertex colours".into(),
    }
}

/// Renders one picture, `size` x `size` pixels.
pub fn draw(entry: &Entry, size: u32) -> Result<Image, RenderError> {
    let p = entry.program;
    match p.scene {
        SceneKind::Molecule | SceneKind::BallAndStick => {
            crate::render(&crate::crambin(), &molecule_options(p, size))
        }
        _ => {
            if size == 0 || size > crate::MAX_SIDE {
                return Err(RenderError::Size {
                    width: size,
                    height: size,
                });
            }
            let mut ctx = Context::new(size as i32, size as i32);
            let program = library::build(&mut ctx, p).map_err(RenderError::Shader)?;
            setup(&mut ctx, p.scene);
            ctx.use_program(program);
            match p.scene {
                SceneKind::TexturedQuad => quad(&mut ctx, program, entry.modes.unwrap_or((1, 0))),
                SceneKind::Volume => volume(&mut ctx, program),
                SceneKind::Normals => {
                    let lit = library::program("materials").unwrap_or(&library::SPHERE);
                    let fill = library::build(&mut ctx, lit).map_err(RenderError::Shader)?;
                    ctx.use_program(fill);
                    // The mesh's arrays stay set: the same triangles again,
                    // into the normals' lines.
                    let count = mesh(&mut ctx, fill, p, size);
                    ctx.use_program(program);
                    uniform_f(&mut ctx, program, "normal_length", &[0.15]);
                    uniform_f(&mut ctx, program, "root_color", &[1.0, 0.9, 0.2, 1.0]);
                    uniform_f(&mut ctx, program, "tip_color", &[0.9, 0.1, 0.1, 1.0]);
                    ctx.draw_arrays(GL_TRIANGLES, 0, count);
                }
                _ => {
                    mesh(&mut ctx, program, p, size);
                }
            }
            if let Some(e) = ctx.take_draw_error() {
                return Err(RenderError::Draw(e));
            }
            match ctx.get_error() {
                GL_NO_ERROR => {}
                code => {
                    return Err(RenderError::Gl {
                        code,
                        during: "drawing a gallery scene",
                    })
                }
            }
            let px = ctx.read_pixels_f32(0, 0, size as i32, size as i32);
            Ok(image::downsample(&px, size, size, 1, false))
        }
    }
}

/// Camera, lights, material, clear.
fn setup(ctx: &mut Context, scene: SceneKind) {
    ctx.matrix_mode(GL_PROJECTION);
    ctx.load_identity();
    ctx.frustum(-0.5, 0.5, -0.5, 0.5, 1.5, 20.0);
    ctx.matrix_mode(GL_MODELVIEW);
    ctx.load_identity();
    // Lights in eye space: 0 directional, 1 point, 2 spot at the object.
    ctx.light(GL_LIGHT0, GL_POSITION, Param::Fv(&[-0.5, 0.7, 1.0, 0.0]));
    ctx.light(GL_LIGHT0, GL_AMBIENT, Param::Fv(&[0.15, 0.15, 0.15, 1.0]));
    ctx.light(GL_LIGHT0, GL_DIFFUSE, Param::Fv(&[0.8, 0.8, 0.8, 1.0]));
    ctx.light(GL_LIGHT0, GL_SPECULAR, Param::Fv(&[0.6, 0.6, 0.6, 1.0]));
    ctx.light(GL_LIGHT1, GL_POSITION, Param::Fv(&[2.0, -1.0, -2.0, 1.0]));
    ctx.light(GL_LIGHT1, GL_DIFFUSE, Param::Fv(&[0.3, 0.3, 0.6, 1.0]));
    ctx.light(GL_LIGHT1, GL_SPECULAR, Param::Fv(&[0.3, 0.3, 0.3, 1.0]));
    ctx.light(GL_LIGHT1, GL_LINEAR_ATTENUATION, Param::F(0.1));
    ctx.light(GL_LIGHT2, GL_POSITION, Param::Fv(&[0.0, 3.0, -2.0, 1.0]));
    ctx.light(GL_LIGHT2, GL_DIFFUSE, Param::Fv(&[0.6, 0.5, 0.2, 1.0]));
    ctx.light(GL_LIGHT2, GL_SPOT_DIRECTION, Param::Fv(&[0.0, -1.0, -1.2]));
    ctx.light(GL_LIGHT2, GL_SPOT_CUTOFF, Param::F(25.0));
    ctx.light(GL_LIGHT2, GL_SPOT_EXPONENT, Param::F(8.0));
    if scene == SceneKind::Mesh || scene == SceneKind::WireMesh {
        // variable-lights' third light (two more directions, coloured).
        ctx.light(GL_LIGHT1, GL_AMBIENT, Param::Fv(&[0.0, 0.0, 0.0, 1.0]));
    }
    for l in [GL_LIGHT0, GL_LIGHT1, GL_LIGHT2] {
        ctx.enable(l);
    }
    ctx.enable(GL_LIGHTING);
    ctx.material(GL_FRONT, GL_AMBIENT, Param::Fv(&[1.0, 0.6, 0.2, 1.0]));
    ctx.material(GL_FRONT, GL_DIFFUSE, Param::Fv(&[1.0, 0.6, 0.2, 1.0]));
    ctx.material(GL_BACK, GL_AMBIENT, Param::Fv(&[0.2, 0.4, 1.0, 1.0]));
    ctx.material(GL_BACK, GL_DIFFUSE, Param::Fv(&[0.2, 0.4, 1.0, 1.0]));
    ctx.material(
        GL_FRONT_AND_BACK,
        GL_SPECULAR,
        Param::Fv(&[0.8, 0.8, 0.8, 1.0]),
    );
    ctx.material(GL_FRONT_AND_BACK, GL_SHININESS, Param::F(40.0));
    ctx.clear_color(0.1, 0.1, 0.12, 1.0);
    ctx.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    ctx.enable(GL_DEPTH_TEST);
    ctx.translatef(0.0, 0.0, -5.0);
    ctx.rotatef(35.0, 1.0, 0.0, 0.0);
    ctx.rotatef(20.0, 0.0, 1.0, 0.0);
}

fn uniform_f(ctx: &mut Context, program: u32, name: &str, v: &[f32]) {
    let loc = ctx.get_uniform_location(program, name);
    match *v {
        [x] => ctx.uniform_1f(loc, x),
        [x, y, z] => ctx.uniform_3f(loc, x, y, z),
        [x, y, z, w] => ctx.uniform_4f(loc, x, y, z, w),
        _ => ctx.uniform_1fv(loc, v.len() as i32, v),
    }
}

fn uniform_i(ctx: &mut Context, program: u32, name: &str, v: i32) {
    let loc = ctx.get_uniform_location(program, name);
    ctx.uniform_1i(loc, v);
}

/// Triangles of a torus (or an open tube): positions, normals, colours.
/// Positions, normals and colours of a triangle list.
type Triangles = (Vec<[f32; 3]>, Vec<[f32; 3]>, Vec<[f32; 4]>);

fn surface(tube: bool, nu: usize, nv: usize) -> Triangles {
    let point = |i: usize, j: usize| -> ([f32; 3], [f32; 3]) {
        let u = i as f32 / nu as f32 * 2.0 * std::f32::consts::PI;
        let v = j as f32 / nv as f32;
        let (su, cu) = (glsl::math::sin(u), glsl::math::cos(u));
        if tube {
            ([0.9 * cu, 1.6 * v - 0.8, 0.9 * su], [cu, 0.0, su])
        } else {
            let a = v * 2.0 * std::f32::consts::PI;
            let (sa, ca) = (glsl::math::sin(a), glsl::math::cos(a));
            let r = 1.0 + 0.45 * ca;
            ([r * cu, 0.45 * sa, r * su], [ca * cu, sa, ca * su])
        }
    };
    let color = |i: usize| -> [f32; 4] {
        let t = i as f32 / nu as f32;
        [0.5 + 0.5 * t, 0.8 - 0.5 * t, 0.3 + 0.6 * (1.0 - t), 1.0]
    };
    let (mut pos, mut nor, mut col) = (Vec::new(), Vec::new(), Vec::new());
    for i in 0..nu {
        for j in 0..nv {
            let quad = [
                (i, j),
                (i + 1, j),
                (i + 1, j + 1),
                (i, j),
                (i + 1, j + 1),
                (i, j + 1),
            ];
            for (a, b) in quad {
                let (p, n) = point(a, if tube { b } else { b % nv });
                pos.push(p);
                nor.push(n);
                col.push(color(a));
            }
        }
    }
    (pos, nor, col)
}

fn flat(v: &[[f32; 3]]) -> Vec<f32> {
    v.iter().flatten().copied().collect()
}

/// Draws the scene's torus (or tube) with `program`, set up for `p`
/// (which may be another program: the normals view's fill); returns the
/// vertex count, its client arrays left enabled.
fn mesh(ctx: &mut Context, program: u32, p: &Program, size: u32) -> i32 {
    let tube = p.name == "two-sided-lighting";
    // The wireframe and the normals get coarser meshes so that their
    // triangles and lines are visible.
    let (nu, nv) = match p.scene {
        SceneKind::WireMesh => (16, 8),
        SceneKind::Normals => (24, 12),
        _ => (40, 20),
    };
    let (pos, nor, col) = surface(tube, nu, nv);
    if p.name == "variable-lights" {
        ctx.light(GL_LIGHT1, GL_POSITION, Param::Fv(&[1.0, -0.3, 0.6, 0.0]));
        ctx.light(GL_LIGHT2, GL_POSITION, Param::Fv(&[0.0, -1.0, 0.3, 0.0]));
        uniform_f(
            ctx,
            program,
            "light_enabled",
            &[1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        );
    }
    if p.scene == SceneKind::WireMesh {
        uniform_f(
            ctx,
            program,
            "viewport",
            &[0.0, 0.0, size as f32, size as f32],
        );
        uniform_f(ctx, program, "line_width", &[1.5]);
        uniform_f(ctx, program, "line_color", &[0.0, 0.0, 0.0, 1.0]);
    }
    if p.scene == SceneKind::WireMesh && p.geometry.is_none() {
        // Every vertex carries its triangle's three corners.
        let mut corners = [Vec::new(), Vec::new(), Vec::new()];
        for tri in pos.chunks(3) {
            for _ in 0..3 {
                for (k, c) in corners.iter_mut().enumerate() {
                    c.extend_from_slice(tri.get(k).unwrap_or(&[0.0; 3]));
                }
            }
        }
        for (k, c) in corners.iter().enumerate() {
            ctx.client_active_texture(GL_TEXTURE0 + k as u32);
            ctx.tex_coord_pointer(3, GL_FLOAT, 0, ArrayData::from_f32(c));
            ctx.enable_client_state(GL_TEXTURE_COORD_ARRAY);
        }
        ctx.client_active_texture(GL_TEXTURE0);
    }
    ctx.vertex_pointer(3, GL_FLOAT, 0, ArrayData::from_f32(&flat(&pos)));
    ctx.normal_pointer(GL_FLOAT, 0, ArrayData::from_f32(&flat(&nor)));
    let col: Vec<f32> = col.iter().flatten().copied().collect();
    ctx.color_pointer(4, GL_FLOAT, 0, ArrayData::from_f32(&col));
    ctx.enable_client_state(GL_VERTEX_ARRAY);
    ctx.enable_client_state(GL_NORMAL_ARRAY);
    ctx.enable_client_state(GL_COLOR_ARRAY);
    ctx.draw_arrays(GL_TRIANGLES, 0, pos.len() as i32);
    pos.len() as i32
}

fn texture_2d(ctx: &mut Context, unit: u32, size: usize, texel: impl Fn(usize, usize) -> [u8; 4]) {
    let mut data = Vec::with_capacity(size * size * 4);
    for y in 0..size {
        for x in 0..size {
            data.extend_from_slice(&texel(x, y));
        }
    }
    ctx.active_texture(GL_TEXTURE0 + unit);
    let name = ctx.gen_textures(1).first().copied().unwrap_or(0);
    ctx.bind_texture(GL_TEXTURE_2D, name);
    for filter in [GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER] {
        ctx.tex_parameter(GL_TEXTURE_2D, filter, Param::I(GL_LINEAR as i32));
    }
    let s = size as i32;
    ctx.tex_image(
        GL_TEXTURE_2D,
        0,
        GL_RGBA as i32,
        [s, s],
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&data),
    );
}

fn quad(ctx: &mut Context, program: u32, (mode0, mode1): (i32, i32)) {
    ctx.load_identity();
    ctx.translatef(0.0, 0.0, -4.2);
    ctx.rotatef(-25.0, 1.0, 0.0, 0.0);
    // Unit 0: checkerboard, white opaque / orange half transparent.
    texture_2d(ctx, 0, 64, |x, y| {
        if (x / 8 + y / 8) & 1 == 0 {
            [255, 255, 255, 255]
        } else {
            [255, 140, 0, 128]
        }
    });
    ctx.tex_env(
        GL_TEXTURE_ENV,
        GL_TEXTURE_ENV_COLOR,
        Param::Fv(&[0.2, 0.6, 1.0, 1.0]),
    );
    // Unit 1: rings.
    texture_2d(ctx, 1, 64, |x, y| {
        let (dx, dy) = (x as f32 - 31.5, y as f32 - 31.5);
        let r = glsl::math::sqrt(dx * dx + dy * dy);
        let v = if (r as usize / 5) & 1 == 0 { 90 } else { 0 };
        [v, v / 2, 0, 255]
    });
    ctx.active_texture(GL_TEXTURE0);
    uniform_i(ctx, program, "TexUnit0", 0);
    uniform_i(ctx, program, "TexUnit1", 1);
    uniform_i(ctx, program, "TexturingType", mode0);
    uniform_i(ctx, program, "TexturingType0", mode0);
    uniform_i(ctx, program, "TexturingType1", mode1);
    let pos = [
        -1.0, -1.0, 0.0, 1.0, -1.0, 0.0, 1.0, 1.0, 0.0, -1.0, 1.0, 0.0,
    ];
    let tc = [0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0];
    let col = [
        1.0, 0.2, 0.2, 1.0, 0.2, 1.0, 0.2, 1.0, 0.2, 0.2, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0,
    ];
    ctx.vertex_pointer(3, GL_FLOAT, 0, ArrayData::from_f32(&pos));
    for unit in [GL_TEXTURE0, GL_TEXTURE1] {
        ctx.client_active_texture(unit);
        ctx.tex_coord_pointer(2, GL_FLOAT, 0, ArrayData::from_f32(&tc));
        ctx.enable_client_state(GL_TEXTURE_COORD_ARRAY);
    }
    ctx.client_active_texture(GL_TEXTURE0);
    ctx.color_pointer(4, GL_FLOAT, 0, ArrayData::from_f32(&col));
    ctx.enable_client_state(GL_VERTEX_ARRAY);
    ctx.enable_client_state(GL_COLOR_ARRAY);
    ctx.draw_arrays(GL_QUADS, 0, 4);
}

fn volume(ctx: &mut Context, program: u32) {
    const N: usize = 32;
    let mut data = Vec::with_capacity(N * N * N * 4);
    for z in 0..N {
        for y in 0..N {
            for x in 0..N {
                let p = [x, y, z].map(|c| (c as f32 + 0.5) / N as f32);
                let d = |c: [f32; 3]| {
                    let v = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
                    glsl::math::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
                };
                let blob_a = (1.0 - d([0.35, 0.5, 0.5]) / 0.2).max(0.0);
                let blob_b = (1.0 - d([0.68, 0.55, 0.45]) / 0.15).max(0.0);
                let shell = (1.0 - (d([0.5; 3]) - 0.45).abs() / 0.05).max(0.0) * 0.4;
                let a = (blob_a + blob_b + shell).min(1.0);
                let rgb = [
                    blob_a + 0.3 * shell,
                    0.4 * blob_a + blob_b,
                    0.2 + 0.8 * shell,
                ];
                let b = |v: f32| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
                data.extend_from_slice(&[b(rgb[0]), b(rgb[1]), b(rgb[2]), b(a)]);
            }
        }
    }
    ctx.active_texture(GL_TEXTURE0);
    let name = ctx.gen_textures(1).first().copied().unwrap_or(0);
    ctx.bind_texture(GL_TEXTURE_3D, name);
    for filter in [GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER] {
        ctx.tex_parameter(GL_TEXTURE_3D, filter, Param::I(GL_LINEAR as i32));
    }
    for wrap in [GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R] {
        ctx.tex_parameter(GL_TEXTURE_3D, wrap, Param::I(GL_CLAMP_TO_EDGE as i32));
    }
    let n = N as i32;
    ctx.tex_image(
        GL_TEXTURE_3D,
        0,
        GL_RGBA as i32,
        [n, n, n],
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&data),
    );
    uniform_i(ctx, program, "volume", 0);
    uniform_i(ctx, program, "steps", 96);
    uniform_f(ctx, program, "opacity", &[0.5]);
    uniform_f(ctx, program, "background", &[0.1, 0.1, 0.12]);
    uniform_f(ctx, program, "perspective", &[1.0]);
    ctx.scalef(2.0, 2.0, 2.0);
    ctx.translatef(-0.5, -0.5, -0.5);
    ctx.enable(GL_CULL_FACE);
    ctx.cull_face(GL_BACK);
    // The unit cube's six faces, counter-clockwise from outside.
    let faces: [[[f32; 3]; 4]; 6] = [
        [[0., 0., 1.], [1., 0., 1.], [1., 1., 1.], [0., 1., 1.]],
        [[1., 0., 0.], [0., 0., 0.], [0., 1., 0.], [1., 1., 0.]],
        [[1., 0., 1.], [1., 0., 0.], [1., 1., 0.], [1., 1., 1.]],
        [[0., 0., 0.], [0., 0., 1.], [0., 1., 1.], [0., 1., 0.]],
        [[0., 1., 1.], [1., 1., 1.], [1., 1., 0.], [0., 1., 0.]],
        [[0., 0., 0.], [1., 0., 0.], [1., 0., 1.], [0., 0., 1.]],
    ];
    let pos: Vec<f32> = faces.iter().flatten().flatten().copied().collect();
    ctx.vertex_pointer(3, GL_FLOAT, 0, ArrayData::from_f32(&pos));
    ctx.client_active_texture(GL_TEXTURE0);
    ctx.tex_coord_pointer(3, GL_FLOAT, 0, ArrayData::from_f32(&pos));
    ctx.enable_client_state(GL_TEXTURE_COORD_ARRAY);
    ctx.enable_client_state(GL_VERTEX_ARRAY);
    ctx.draw_arrays(GL_QUADS, 0, 24);
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The gallery page: every entry's picture (`FILE.png`), program name,
/// shader files, summary and settings.
pub fn index_html(entries: &[Entry]) -> String {
    let mut h = String::from(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>shaderbox shader library</title>\n<style>body{font-family:sans-serif;background:#222;color:#ddd}figure{display:inline-block;width:280px;vertical-align:top;margin:8px}img{width:256px;height:256px;image-rendering:pixelated}code{color:#9cf}figcaption{font-size:13px}</style></head><body>\n<h1>The shaderbox shader library</h1>\n<p>Every program of <code>shaders/</code>, drawn by shaderbox (OpenGL 2.1 on the CPU).</p>\n",
    );
    for e in entries {
        let geometry = e.program.geometry.map_or(&[][..], |g| g.files);
        let files: Vec<&str> = e
            .program
            .vertex
            .iter()
            .chain(geometry)
            .chain(e.program.fragment)
            .map(|f| f.name)
            .collect();
        h += &format!(
            "<figure><img src=\"{file}.png\" alt=\"{file}\"><figcaption><b>{name}</b> &mdash; {summary}<br><code>{files}</code><br>{settings}</figcaption></figure>\n",
            file = escape(&e.file),
            name = escape(&e.file),
            summary = escape(e.program.summary),
            files = escape(&files.join(" + ")),
            settings = escape(&e.settings),
        );
    }
    h += "</body></html>\n";
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_program_has_an_entry() {
        let e = entries();
        for p in library::PROGRAMS {
            assert!(e.iter().any(|x| x.program == p), "{}", p.name);
        }
        let html = index_html(&e);
        for x in &e {
            assert!(html.contains(&format!("src=\"{}.png\"", x.file)));
        }
    }

    fn entry(file: &str) -> Entry {
        entries().into_iter().find(|e| e.file == file).unwrap()
    }

    #[test]
    fn the_geometry_shader_wireframe_draws_the_attribute_wireframe() {
        // Same edge-distance formulas on the same window positions, same
        // triangles: byte for byte, without the corner attributes.
        let a = draw(&entry("wireframe"), 64).unwrap();
        let b = draw(&entry("wireframe-geom"), 64).unwrap();
        assert_eq!(a, b);
        // And it is a wireframe: dark line pixels on a lit fill.
        let dark = a
            .pixels
            .iter()
            .filter(|p| p[..3].iter().all(|c| *c < 40))
            .count();
        assert!(dark > 64 * 64 / 20, "{dark} line pixels");
    }

    #[test]
    fn the_normals_view_draws_lines_over_the_lit_mesh() {
        let count = |img: &Image| {
            let yellow = |p: &&[u8; 4]| p[0] > 200 && p[1] > 180 && p[2] < 90;
            let red = |p: &&[u8; 4]| p[0] > 150 && p[1] < 60 && p[2] < 60;
            let y = img.pixels.iter().filter(yellow).count();
            (y, img.pixels.iter().filter(red).count())
        };
        // The lit torus alone has (almost) none of the lines' colours.
        let (y0, r0) = count(&draw(&entry("materials"), 64).unwrap());
        let normals = draw(&entry("normals"), 64).unwrap();
        let (y, r) = count(&normals);
        assert!(
            y > y0 + 16 && r > r0 + 16,
            "yellow {y0} -> {y}, red {r0} -> {r}"
        );
        // Lines, not a filled picture: most pixels are not theirs.
        assert!(y + r < 64 * 64 / 3, "yellow {y}, red {r}");
    }

    #[test]
    fn non_molecule_scenes_are_not_blank() {
        for e in entries() {
            if matches!(
                e.program.scene,
                SceneKind::Molecule | SceneKind::BallAndStick
            ) {
                continue;
            }
            let img = draw(&e, 32).unwrap_or_else(|err| panic!("{}: {err}", e.file));
            let bg = img.pixel(0, 0).unwrap();
            let other = img.pixels.iter().filter(|p| **p != bg).count();
            assert!(
                other > 32 * 32 / 10,
                "{}: {other} non-background pixels",
                e.file
            );
        }
    }
}
