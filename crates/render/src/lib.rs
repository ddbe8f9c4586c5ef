//! # shaderbox-render: molecules drawn by the project's shader library
//!
//! Loads atoms ([`structure`]: a strict PDB reader, [`mmcif`]: a strict
//! mmCIF reader, and crambin, PDB 1CRN, embedded), gives them CPK colours,
//! van der Waals and covalent radii ([`elements`]), finds bonds
//! ([`bonds`]: CONECT records and covalent distances), fits a camera
//! ([`camera`]), sets up the OpenGL 2.1
//! state the library's sphere impostor shaders read (`shaders/sphere.vert`
//! and `shaders/sphere.frag`: lights, material, fog, the `perspective`,
//! `fogging[4]`, `light_enabled[8]`, `right_vector`, `up_vector`
//! uniforms, and `viewport`, from which the impostors cast each pixel's ray
//! through `gl_FragCoord`) on a [`gl::Context`], draws every atom as one GL_QUADS quad
//! from client vertex arrays (or, with [`Atoms::Points`], as one point
//! that a geometry shader, `shaders/sphere.geom`, expands to the same
//! quad), reads the pixels back, box-filters
//! supersampled renders down and writes PNG ([`image`]). Ball-and-stick
//! ([`Style::BallAndStick`]) draws smaller atoms and every bond as two
//! cylinder impostors (`shaders/cylinder.*`), which write their true depth
//! too, so bonds and atoms cut each other correctly.
//!
//! Every GL call goes through a [`scene::Recorder`], so a render can hand
//! back exactly what it drew ([`render_scene`]) for replaying on Mesa.
//! [`library`] lists and embeds every program of the shader library.
//!
//! The seed talk's effects ([`Effect`]) swap in the library's other pairs:
//! `outline.frag` (black interiors, lit rims [`OUTLINE_PIXELS`] wide),
//! `x.vert` + `x.frag` (dark X on every atom), `x.vert` + `x-red.frag`
//! (yellow X on red atoms) and `transparent.frag` (screen-door
//! checkerboard on red atoms). Which atoms are red travels in `gl_Color`,
//! as in the seed.
//!
//! ## Contract
//! - [`render`] never panics; bad sizes, shader or GL failures are
//!   [`RenderError`]s. Output is deterministic (same bytes on every
//!   machine): the pipeline is, and the camera uses `glsl::math`.
//! - [`Atoms::Points`] draws the same image as [`Atoms::Quads`] for every
//!   effect and style, byte for byte (`tests/points.rs`): sphere-point.vert
//!   and sphere.geom compute each corner with sphere.vert's (and
//!   x.vert's) operations, the strip's two triangles cover exactly the
//!   quad's pixels, and the fragment stages read only the pixel's
//!   `gl_FragCoord`, the quad's plane and varyings that are the same at
//!   all four corners (the per-atom ones; `point` and `view_direction`
//!   are unread), which come out of either triangle as out of the quad.
//! - Spheres intersect correctly: the fragment shader writes the depth of
//!   the sphere surface, and the depth test (GL_LESS) is on.
//! - Lights are directional, defined in eye space (they do not turn with
//!   the molecule): light 0 a key light from the upper left, light 1 a
//!   weaker fill light from the lower right, lights 2-7 weaker lights from
//!   other sides; [`RenderOptions::lights`] picks which are on.
//! - Fog is computed per atom from the eye distance of its centre, as the
//!   seed talk does: linear fog runs from the front of the molecule (no
//!   fog) to a fog factor of [`FOG_AT_BACK`] at its back; exp and exp2
//!   densities give that factor at the back too (so they fog the front a
//!   little: fog grows from the eye). The fog colour is the background's.
//!
//! ## Limitations
//! - The effects change only the atoms' program; ball-and-stick bonds are
//!   always drawn plain (lit, fogged cylinders).
//! - mmCIF files give no bonds of their own (bonds by distance only).
//! - The effects' "red atom" test (x-red, transparent) is the seed's
//!   colour test on gl_Color (r > 0.7, g < 0.3, b < 0.3), so it marks
//!   oxygen in the element colours and would mark any other red-coloured
//!   atom; there is no per-atom selection yet.
//! - Supersampling box-filters N x N samples in linear 0-1 colour values
//!   (not gamma-aware).

pub mod bonds;
pub mod camera;
pub mod elements;
pub mod gallery;
pub mod image;
pub mod library;
pub mod load;
pub mod mmcif;
pub mod pdb;
pub mod scene;
pub mod structure;

pub use camera::{Camera, Projection};
pub use elements::Element;
pub use image::Image;
pub use load::{crambin, load_file, parse};
pub use pdb::parse_pdb;
pub use scene::{Recorder, Scene};
pub use structure::{Atom, LoadError, Structure};

use gl::enums::*;
use gl::Context;
use thiserror::Error;

/// The library's sphere impostor vertex shader.
pub const SPHERE_VERT: &str = library::SPHERE_VERT.source;
/// The library's sphere impostor fragment shader.
pub const SPHERE_FRAG: &str = library::SPHERE_FRAG.source;
/// Outline effect fragment shader (with [`SPHERE_VERT`]).
pub const OUTLINE_FRAG: &str = library::OUTLINE_FRAG.source;
/// Sphere impostor vertex shader that passes the quad corner on (X effects).
pub const X_VERT: &str = library::X_VERT.source;
/// Dark X on every atom (with [`X_VERT`]).
pub const X_FRAG: &str = library::X_FRAG.source;
/// Yellow X on red atoms (with [`X_VERT`]).
pub const X_RED_FRAG: &str = library::X_RED_FRAG.source;
/// Screen-door transparency of red atoms (with [`SPHERE_VERT`]).
pub const TRANSPARENT_FRAG: &str = library::TRANSPARENT_FRAG.source;

/// Width of the outline effect's lit rim, in pixels (of the supersampled
/// framebuffer) at the depth of the molecule's centre.
pub const OUTLINE_PIXELS: f32 = 1.5;

/// The seed talk's effects: which library shader pair draws the atoms.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Effect {
    /// Lit spheres (`sphere.vert` + `sphere.frag`).
    #[default]
    Plain,
    /// Black sphere interiors, lit rims: outlines of the structure
    /// (`sphere.vert` + `outline.frag`).
    Outline,
    /// A dark X on every atom (`x.vert` + `x.frag`).
    X,
    /// A yellow X on red atoms only (`x.vert` + `x-red.frag`).
    XRed,
    /// Red atoms 50% transparent by a screen-door checkerboard
    /// (`sphere.vert` + `transparent.frag`).
    Transparent,
}

impl Effect {
    /// Every effect, in the order of the CLI's list.
    pub const ALL: [Effect; 5] = [
        Effect::Plain,
        Effect::Outline,
        Effect::X,
        Effect::XRed,
        Effect::Transparent,
    ];

    /// The effect's name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Effect::Plain => "plain",
            Effect::Outline => "outline",
            Effect::X => "x",
            Effect::XRed => "x-red",
            Effect::Transparent => "transparent",
        }
    }

    /// The effect called `name` (as [`Effect::name`] spells it).
    pub fn from_name(name: &str) -> Option<Effect> {
        Effect::ALL.into_iter().find(|e| e.name() == name)
    }

    /// The library program that draws the atoms as quads.
    pub fn program(self) -> &'static library::Program {
        self.program_for(Atoms::Quads)
    }

    /// The library program that draws the atoms as `atoms`.
    pub fn program_for(self, atoms: Atoms) -> &'static library::Program {
        let name = match (self, atoms) {
            (Effect::Plain, Atoms::Quads) => "sphere",
            (Effect::Outline, Atoms::Quads) => "outline",
            (Effect::X, Atoms::Quads) => "x",
            (Effect::XRed, Atoms::Quads) => "x-red",
            (Effect::Transparent, Atoms::Quads) => "transparent",
            (Effect::Plain, Atoms::Points) => "sphere-points",
            (Effect::Outline, Atoms::Points) => "outline-points",
            (Effect::X, Atoms::Points) => "x-points",
            (Effect::XRed, Atoms::Points) => "x-red-points",
            (Effect::Transparent, Atoms::Points) => "transparent-points",
        };
        library::program(name).unwrap_or(&library::SPHERE)
    }
}

/// What each atom is sent to GL as.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Atoms {
    /// One GL_QUADS quad of four vertices at the centre, the corner in
    /// gl_MultiTexCoord0 (`sphere.vert`, `x.vert`): runs on any GL 2.0.
    #[default]
    Quads,
    /// One GL_POINTS vertex at the centre, radius in gl_MultiTexCoord0.x,
    /// expanded to the quad by `sphere.geom` (GL_EXT_geometry_shader4): a
    /// quarter of the vertices, a fifth of the vertex data.
    Points,
}

impl Atoms {
    /// Both, in the order of the CLI's list.
    pub const ALL: [Atoms; 2] = [Atoms::Quads, Atoms::Points];

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Atoms::Quads => "quads",
            Atoms::Points => "points",
        }
    }

    /// The value called `name` (as [`Atoms::name`] spells it).
    pub fn from_name(name: &str) -> Option<Atoms> {
        Atoms::ALL.into_iter().find(|a| a.name() == name)
    }
}

/// How atoms (and bonds) are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Style {
    /// Atoms at their van der Waals radii, no bonds.
    #[default]
    Spacefill,
    /// Atoms at [`BALL_SCALE`] of their radii, bonds as cylinders of
    /// [`BOND_RADIUS`] (each half in its atom's colour).
    BallAndStick,
}

impl Style {
    /// The style's name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Style::Spacefill => "spacefill",
            Style::BallAndStick => "ballstick",
        }
    }
}

/// Ball radius / van der Waals radius in ball-and-stick.
pub const BALL_SCALE: f32 = 0.3;
/// Bond cylinder radius in ball-and-stick, Å.
pub const BOND_RADIUS: f32 = 0.17;

/// Largest side of the (supersampled) framebuffer.
pub const MAX_SIDE: u32 = gl::MAX_TEXTURE_SIZE as u32;
/// Largest supersampling factor.
pub const MAX_SUPERSAMPLE: u32 = 8;
/// Fog factor (1 = clear, 0 = fog colour) at the back of the molecule.
pub const FOG_AT_BACK: f32 = 0.35;

/// Fog mode (GL_FOG_MODE emulated by the shader's `fogging[4]`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Fog {
    #[default]
    None,
    Linear,
    Exp,
    Exp2,
}

/// What is behind the molecule.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Background {
    /// An opaque colour, RGB in [0, 1].
    Color([f32; 3]),
    /// Alpha 0 (the PNG gets an alpha channel); fog fades to black.
    Transparent,
}

impl Default for Background {
    fn default() -> Self {
        Background::Color([0.0; 3])
    }
}

/// Everything [`render`] needs besides the atoms.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderOptions {
    pub width: u32,
    pub height: u32,
    pub projection: Projection,
    pub fog: Fog,
    /// GL lights that are on (0-7).
    pub lights: Vec<u8>,
    /// Rotation about X, then Y, then Z, in degrees.
    pub rotate: [f32; 3],
    /// Render N times larger and box-filter down (1 = off).
    pub supersample: u32,
    pub background: Background,
    /// Which of the seed's effects draws the atoms.
    pub effect: Effect,
    pub style: Style,
    /// Quads, or points expanded by a geometry shader.
    pub atoms: Atoms,
}

impl RenderOptions {
    /// The options as `shaderbox render` arguments.
    pub fn describe(&self) -> String {
        let fog = match self.fog {
            Fog::None => "none",
            Fog::Linear => "linear",
            Fog::Exp => "exp",
            Fog::Exp2 => "exp2",
        };
        let projection = match self.projection {
            Projection::Orthographic => "ortho",
            Projection::Perspective => "perspective",
        };
        let lights: Vec<String> = self.lights.iter().map(|l| l.to_string()).collect();
        let lights = if lights.is_empty() {
            "none".to_string()
        } else {
            lights.join(",")
        };
        let [x, y, z] = self.rotate;
        let background = match self.background {
            Background::Transparent => "transparent".to_string(),
            Background::Color(c) => {
                let [r, g, b] = c.map(|v| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8);
                format!("#{r:02x}{g:02x}{b:02x}")
            }
        };
        format!(
            "--size {}x{} --style {} --effect {} --atoms {} --fog {fog} --projection {projection} --lights {lights} --rotate {x},{y},{z} --supersample {} --background {background}",
            self.width,
            self.height,
            self.style.name(),
            self.effect.name(),
            self.atoms.name(),
            self.supersample
        )
    }
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            width: 800,
            height: 800,
            projection: Projection::Orthographic,
            fog: Fog::None,
            lights: vec![0, 1],
            rotate: [0.0; 3],
            supersample: 1,
            background: Background::default(),
            effect: Effect::Plain,
            style: Style::Spacefill,
            atoms: Atoms::Quads,
        }
    }
}

/// Why a render failed.
#[derive(Debug, Error, PartialEq)]
pub enum RenderError {
    #[error("image size {width}x{height} is invalid (each side 1-{MAX_SIDE})")]
    Size { width: u32, height: u32 },
    #[error("supersampling {factor} is invalid: 1-{MAX_SUPERSAMPLE}, and at most {MAX_SIDE} pixels per side after it")]
    Supersample { factor: u32 },
    #[error("light {0} does not exist (lights are 0-7)")]
    Light(u8),
    #[error("the sphere shaders failed to build: {0}")]
    Shader(String),
    #[error("OpenGL error 0x{code:04x} while {during}")]
    Gl { code: u32, during: &'static str },
    #[error("drawing failed: {0}")]
    Draw(String),
}

/// Direction (eye space, w = 0), ambient, diffuse, specular of lights 0-7.
const LIGHTS: [([f32; 4], f32, f32, f32); 8] = [
    ([-0.4, 0.55, 1.0, 0.0], 0.15, 0.75, 0.6),
    ([0.6, -0.3, 0.7, 0.0], 0.05, 0.3, 0.15),
    ([1.0, 1.0, 0.3, 0.0], 0.0, 0.3, 0.2),
    ([-1.0, -1.0, 0.3, 0.0], 0.0, 0.3, 0.2),
    ([0.0, 0.0, 1.0, 0.0], 0.0, 0.3, 0.2),
    ([-1.0, 0.0, 0.2, 0.0], 0.0, 0.3, 0.2),
    ([1.0, 0.0, 0.2, 0.0], 0.0, 0.3, 0.2),
    ([0.0, 1.0, 0.2, 0.0], 0.0, 0.3, 0.2),
];

/// Material shininess (specular exponent).
pub const SHININESS: f32 = 50.0;

fn check(ctx: &mut Context, during: &'static str) -> Result<(), RenderError> {
    match ctx.get_error() {
        GL_NO_ERROR => Ok(()),
        code => Err(RenderError::Gl { code, during }),
    }
}

/// Fog state: GL_FOG_* values and the one-hot `fogging[4]` uniform.
fn set_fog(rec: &mut Recorder, fog: Fog, camera: &Camera, color: [f32; 4]) -> [f32; 4] {
    let (front, back) = camera.depth_span();
    let back = back.max(1e-3);
    // ln(1 / FOG_AT_BACK)
    let k = -glsl::math::log(FOG_AT_BACK);
    let (mode, onehot) = match fog {
        Fog::None => (GL_LINEAR, [1.0, 0.0, 0.0, 0.0]),
        Fog::Linear => (GL_LINEAR, [0.0, 1.0, 0.0, 0.0]),
        Fog::Exp => (GL_EXP, [0.0, 0.0, 1.0, 0.0]),
        Fog::Exp2 => (GL_EXP2, [0.0, 0.0, 0.0, 1.0]),
    };
    // Linear: factor 1 at the front, FOG_AT_BACK at the back:
    // (end - back) = FOG_AT_BACK (end - front).
    let end = (back - FOG_AT_BACK * front) / (1.0 - FOG_AT_BACK);
    let density = match fog {
        Fog::Exp2 => glsl::math::sqrt(k) / back,
        _ => k / back,
    };
    rec.fog(GL_FOG_MODE, &[mode as f32]);
    rec.fog(GL_FOG_START, &[front]);
    rec.fog(GL_FOG_END, &[end]);
    rec.fog(GL_FOG_DENSITY, &[density]);
    rec.fog(GL_FOG_COLOR, &color);
    onehot
}

fn check_options(opts: &RenderOptions) -> Result<(), RenderError> {
    let (w, h, ss) = (opts.width, opts.height, opts.supersample);
    if w == 0 || h == 0 || w > MAX_SIDE || h > MAX_SIDE {
        return Err(RenderError::Size {
            width: w,
            height: h,
        });
    }
    if ss == 0 || ss > MAX_SUPERSAMPLE || w * ss > MAX_SIDE || h * ss > MAX_SIDE {
        return Err(RenderError::Supersample { factor: ss });
    }
    if let Some(bad) = opts.lights.iter().find(|l| **l >= 8) {
        return Err(RenderError::Light(*bad));
    }
    Ok(())
}

/// Renders `structure` into an image (top row first), on a context of
/// its own ([`Renderer`] keeps one for many renders).
pub fn render(structure: &Structure, opts: &RenderOptions) -> Result<Image, RenderError> {
    Renderer::new().render(structure, opts)
}

/// Renders `structure` and returns the image with the GL calls that drew
/// it ([`scene::Scene`], for `--export-scene`).
pub fn render_scene(
    structure: &Structure,
    opts: &RenderOptions,
) -> Result<(Image, Scene), RenderError> {
    Renderer::new().render_scene(structure, opts)
}

/// Renders molecule after molecule on one GL context, keeping the
/// library programs it has compiled: for batches, where creating a
/// context and compiling the programs would cost more than drawing a
/// small molecule.
///
/// Every render sets all the state it draws with (matrices, lights,
/// material, fog parameters, clear values, depth test, program and
/// uniforms, vertex arrays), so an image does not depend on what was
/// rendered before: it is the same bytes as [`render`]'s
/// (`tests/renderer.rs`). The context is kept while the framebuffer size
/// (width and height times the supersampling) stays the same and made
/// anew when it changes; after a failed render it is dropped.
#[derive(Default)]
pub struct Renderer {
    session: Option<Recorder>,
}

impl Renderer {
    /// A renderer with no context yet (the first render makes it).
    pub fn new() -> Renderer {
        Renderer::default()
    }

    /// Renders `structure` into an image (top row first), as [`render`].
    pub fn render(
        &mut self,
        structure: &Structure,
        opts: &RenderOptions,
    ) -> Result<Image, RenderError> {
        self.render_scene(structure, opts).map(|(image, _)| image)
    }

    /// Renders `structure` and returns the image with the GL calls that
    /// drew it, as [`render_scene`].
    pub fn render_scene(
        &mut self,
        structure: &Structure,
        opts: &RenderOptions,
    ) -> Result<(Image, Scene), RenderError> {
        check_options(opts)?;
        let ss = opts.supersample;
        let (fw, fh) = (opts.width * ss, opts.height * ss);
        let mut rec = match self.session.take() {
            Some(mut rec) if (rec.ctx.width(), rec.ctx.height()) == (fw as i32, fh as i32) => {
                rec.begin();
                rec
            }
            _ => Recorder::new(fw, fh),
        };
        let out = draw(&mut rec, structure, opts)?;
        self.session = Some(rec);
        Ok(out)
    }
}

/// Draws `structure` with `opts` (already checked) on the recorder's
/// context, whose framebuffer is the supersampled size.
fn draw(
    rec: &mut Recorder,
    structure: &Structure,
    opts: &RenderOptions,
) -> Result<(Image, Scene), RenderError> {
    let ss = opts.supersample;
    let (fw, fh) = (opts.width * ss, opts.height * ss);

    let radius_of = |a: &Atom| match opts.style {
        Style::Spacefill => a.element.radius(),
        Style::BallAndStick => BALL_SCALE * a.element.radius(),
    };
    let spheres: Vec<([f32; 3], f32)> = structure
        .atoms
        .iter()
        .map(|a| (a.position, radius_of(a)))
        .collect();
    let camera = Camera::fit(&spheres, opts.projection, fw, fh, opts.rotate);

    // Projection.
    rec.matrix_mode(GL_PROJECTION);
    rec.load_identity();
    let (hw, hh) = (camera.half_width as f64, camera.half_height as f64);
    let (n, f) = (camera.near as f64, camera.far as f64);
    match camera.projection {
        Projection::Orthographic => rec.ortho([-hw, hw, -hh, hh, n, f]),
        Projection::Perspective => rec.frustum([-hw, hw, -hh, hh, n, f]),
    }

    // Lights, in eye space (identity model-view when specified).
    rec.matrix_mode(GL_MODELVIEW);
    rec.load_identity();
    let mut enabled = [0.0f32; 8];
    for (i, (pos, a, d, s)) in LIGHTS.iter().enumerate() {
        let light = GL_LIGHT0 + i as u32;
        rec.light(light, GL_POSITION, pos);
        rec.light(light, GL_AMBIENT, &[*a, *a, *a, 1.0]);
        rec.light(light, GL_DIFFUSE, &[*d, *d, *d, 1.0]);
        rec.light(light, GL_SPECULAR, &[*s, *s, *s, 1.0]);
        if opts.lights.contains(&(i as u8)) {
            rec.enable(light);
            enabled[i] = 1.0;
        } else {
            rec.disable(light);
        }
    }
    rec.enable(GL_LIGHTING);
    rec.material(GL_FRONT_AND_BACK, GL_AMBIENT, &[1.0, 1.0, 1.0, 1.0]);
    rec.material(GL_FRONT_AND_BACK, GL_DIFFUSE, &[1.0, 1.0, 1.0, 1.0]);
    rec.material(GL_FRONT_AND_BACK, GL_SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    rec.material(GL_FRONT_AND_BACK, GL_EMISSION, &[0.0, 0.0, 0.0, 1.0]);
    rec.material(GL_FRONT_AND_BACK, GL_SHININESS, &[SHININESS]);
    check(&mut rec.ctx, "setting lights and material")?;

    // Model-view: eye at +distance on z, molecule turned about its centre.
    let [rx, ry, rz] = camera.rotate;
    rec.translate([0.0, 0.0, -camera.distance]);
    rec.rotate(rz, [0.0, 0.0, 1.0]);
    rec.rotate(ry, [0.0, 1.0, 0.0]);
    rec.rotate(rx, [1.0, 0.0, 0.0]);
    let c = camera.center;
    rec.translate([-c[0], -c[1], -c[2]]);
    let mv = rec.ctx.get_floatv(GL_MODELVIEW_MATRIX);
    let row = |r: usize| -> [f32; 3] { [0, 4, 8].map(|o| mv.get(o + r).copied().unwrap_or(0.0)) };
    let (right, up) = (row(0), row(1));

    // Background and fog.
    let (bg, alpha) = match opts.background {
        Background::Color(c) => (c, 1.0),
        Background::Transparent => ([0.0; 3], 0.0),
    };
    let fogging = set_fog(rec, opts.fog, &camera, [bg[0], bg[1], bg[2], 1.0]);
    rec.clear_color([bg[0], bg[1], bg[2], alpha]);
    rec.clear_depth(1.0);
    rec.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rec.enable(GL_DEPTH_TEST);
    rec.depth_func(GL_LESS);
    check(&mut rec.ctx, "setting fog, depth and clearing")?;

    // Atoms: the effect's sphere program.
    let program = opts.effect.program_for(opts.atoms);
    rec.program(program).map_err(RenderError::Shader)?;
    rec.uniform("right_vector", &right);
    rec.uniform("up_vector", &up);
    let persp = match camera.projection {
        Projection::Orthographic => 0.0,
        Projection::Perspective => 1.0,
    };
    rec.uniform("perspective", &[persp]);
    let viewport = [0.0, 0.0, fw as f32, fh as f32];
    rec.uniform("viewport", &viewport);
    rec.uniform_array("fogging", &fogging);
    rec.uniform_array("light_enabled", &enabled);
    if opts.effect == Effect::Outline {
        // Eye-space size of a pixel at the centre's depth (perspective:
        // the near-plane size scaled out to the centre).
        let mut pixel = 2.0 * camera.half_width / fw as f32;
        if camera.projection == Projection::Perspective {
            pixel *= camera.distance / camera.near.max(1e-6);
        }
        rec.uniform("outline_width", &[OUTLINE_PIXELS * pixel]);
    }
    check(&mut rec.ctx, "setting the shader uniforms")?;

    // Quads: one quad per atom, four vertices at the centre, corners in
    // gl_MultiTexCoord0 = (right, up, radius), colour in gl_Color.
    // Points: one vertex at the centre, gl_MultiTexCoord0 = radius.
    let n = structure.atoms.len();
    let (mode, corners): (u32, &[(f32, f32)]) = match opts.atoms {
        Atoms::Quads => (
            GL_QUADS,
            &[(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)],
        ),
        Atoms::Points => (GL_POINTS, &[(0.0, 0.0)]),
    };
    let tex_size = if opts.atoms == Atoms::Quads { 3 } else { 1 };
    let k = corners.len();
    let mut pos = Vec::with_capacity(n * k * 3);
    let mut tex = Vec::with_capacity(n * k * tex_size);
    let mut col = Vec::with_capacity(n * k * 4);
    for a in &structure.atoms {
        let r = radius_of(a);
        let [cr, cg, cb] = a.element.color();
        for &(x, y) in corners {
            pos.extend_from_slice(&a.position);
            match opts.atoms {
                Atoms::Quads => tex.extend_from_slice(&[x, y, r]),
                Atoms::Points => tex.push(r),
            }
            col.extend_from_slice(&[cr, cg, cb, 1.0]);
        }
    }
    rec.draw(
        mode,
        n.saturating_mul(k),
        (3, pos),
        Some((tex_size as i32, tex)),
        None,
        Some((4, col)),
    );
    if let Some(e) = rec.ctx.take_draw_error() {
        return Err(RenderError::Draw(e));
    }
    check(&mut rec.ctx, "drawing the atoms")?;

    if opts.style == Style::BallAndStick {
        draw_bonds(rec, structure, persp, viewport, &fogging, &enabled)?;
    }

    let pixels = rec.ctx.read_pixels_f32(0, 0, fw as i32, fh as i32);
    check(&mut rec.ctx, "reading the pixels")?;
    let image = image::downsample(&pixels, fw, fh, ss, alpha < 1.0);
    let scene = rec.scene(opts.describe());
    Ok((image, scene))
}

/// Ball-and-stick bonds: two cylinder impostors per bond (each half in
/// its atom's colour), from the first atom's centre to the midpoint and
/// on to the second's.
fn draw_bonds(
    rec: &mut Recorder,
    structure: &Structure,
    persp: f32,
    viewport: [f32; 4],
    fogging: &[f32; 4],
    enabled: &[f32; 8],
) -> Result<(), RenderError> {
    let bonds = bonds::find_bonds(structure);
    if bonds.is_empty() {
        return Ok(());
    }
    rec.program(&library::CYLINDER)
        .map_err(RenderError::Shader)?;
    rec.uniform("perspective", &[persp]);
    rec.uniform("viewport", &viewport);
    rec.uniform_array("fogging", fogging);
    rec.uniform_array("light_enabled", enabled);
    let halves = bonds.len() * 2;
    let mut pos = Vec::with_capacity(halves * 12);
    let mut tex0 = Vec::with_capacity(halves * 16);
    let mut tex1 = Vec::with_capacity(halves * 8);
    let mut col = Vec::with_capacity(halves * 16);
    for (i, j) in bonds {
        let (Some(a), Some(b)) = (structure.atoms.get(i), structure.atoms.get(j)) else {
            continue;
        };
        let mid = [0, 1, 2].map(|k| 0.5 * a.position[k] + 0.5 * b.position[k]);
        for (atom, from, to) in [(a, a.position, mid), (b, mid, b.position)] {
            let [cr, cg, cb] = atom.element.color();
            for (along, side) in [(0.0, -1.0), (1.0, -1.0), (1.0, 1.0), (0.0, 1.0)] {
                pos.extend_from_slice(&from);
                tex0.extend_from_slice(&[to[0], to[1], to[2], BOND_RADIUS]);
                tex1.extend_from_slice(&[along, side]);
                col.extend_from_slice(&[cr, cg, cb, 1.0]);
            }
        }
    }
    let count = pos.len() / 3;
    rec.draw(
        GL_QUADS,
        count,
        (3, pos),
        Some((4, tex0)),
        Some((2, tex1)),
        Some((4, col)),
    );
    if let Some(e) = rec.ctx.take_draw_error() {
        return Err(RenderError::Draw(e));
    }
    check(&mut rec.ctx, "drawing the bonds")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shaders_build() {
        for effect in Effect::ALL {
            for atoms in Atoms::ALL {
                let mut ctx = Context::new(4, 4);
                let built = library::build(&mut ctx, effect.program_for(atoms));
                assert!(built.is_ok(), "{effect:?} {atoms:?}: {built:?}");
            }
        }
    }

    #[test]
    fn each_effect_and_atoms_has_its_own_program() {
        let mut seen = Vec::new();
        for effect in Effect::ALL {
            for atoms in Atoms::ALL {
                let p = effect.program_for(atoms);
                assert_eq!(p.geometry.is_some(), atoms == Atoms::Points);
                assert!(!seen.contains(&p.name), "{}", p.name);
                seen.push(p.name);
            }
        }
        for atoms in Atoms::ALL {
            assert_eq!(Atoms::from_name(atoms.name()), Some(atoms));
        }
        assert_eq!(Atoms::from_name("lines"), None);
    }

    #[test]
    fn effect_names_round_trip() {
        for effect in Effect::ALL {
            assert_eq!(Effect::from_name(effect.name()), Some(effect));
        }
        assert_eq!(Effect::from_name("sepia"), None);
        assert_eq!(Effect::from_name("X"), None);
    }

    #[test]
    fn bad_options_are_errors() {
        let s = crambin();
        let mut o = RenderOptions {
            width: 0,
            ..RenderOptions::default()
        };
        assert!(matches!(render(&s, &o), Err(RenderError::Size { .. })));
        o.width = 4000;
        o.supersample = 3;
        assert!(matches!(
            render(&s, &o),
            Err(RenderError::Supersample { factor: 3 })
        ));
        o.width = 8;
        o.height = 8;
        o.supersample = 1;
        o.lights = vec![9];
        assert_eq!(render(&s, &o), Err(RenderError::Light(9)));
    }
}
