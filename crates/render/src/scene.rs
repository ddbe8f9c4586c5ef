//! The GL calls a render issues, recorded as data ([`Scene`]) so another
//! OpenGL can replay them: `shaderbox render --export-scene FILE.json`
//! writes them, and `scripts/regen-references.py` replays them through
//! PyOpenGL on Mesa to make the reference images the tests compare with.
//!
//! [`Recorder`] wraps a [`gl::Context`]: every call both runs on the
//! context and is appended to the scene, so the scene is by construction
//! what shaderbox drew. Uniforms are recorded by name (locations are the
//! implementation's), programs by their shader sources, vertex arrays by
//! their contents. Enum values are GL's numbers. A program's geometry
//! stage (GL_EXT_geometry_shader4: `--atoms points`) is recorded with its
//! program parameters; scenes written before geometry stages existed
//! have neither field and load as programs without one. Mesa cannot
//! replay such a program (it never had the extension form).

use gl::enums::*;
use gl::{ArrayData, Context, Param};
use serde::{Deserialize, Serialize};

/// One recorded GL call (the JSON form: `{"call": "Enable", "args": ...}`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "call", content = "args")]
pub enum Call {
    MatrixMode(u32),
    LoadIdentity,
    Ortho([f64; 6]),
    Frustum([f64; 6]),
    Translate([f32; 3]),
    /// Angle in degrees, axis.
    Rotate([f32; 4]),
    /// light, pname, params.
    Light(u32, u32, Vec<f32>),
    /// face, pname, params.
    Material(u32, u32, Vec<f32>),
    Enable(u32),
    Disable(u32),
    /// pname, params (glFogfv; GL_FOG_MODE as a float).
    Fog(u32, Vec<f32>),
    ClearColor([f32; 4]),
    ClearDepth(f64),
    Clear(u32),
    DepthFunc(u32),
    /// Builds program number `id` (0, 1, ...) from these shader objects
    /// and uses it.
    Program {
        id: usize,
        vertex: Vec<String>,
        /// Geometry shader objects (empty: no geometry stage).
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        geometry: Vec<String>,
        /// glProgramParameteriEXT `(pname, value)` pairs set before the
        /// link, in order (the geometry stage's primitive types and
        /// output vertex count).
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        parameters: Vec<(u32, i32)>,
        fragment: Vec<String>,
    },
    UseProgram(usize),
    /// Uniform name and its float values (glUniform{1,2,3,4}f or, for an
    /// array, glUniform1fv with all of them).
    Uniform {
        name: String,
        values: Vec<f32>,
        array: bool,
    },
    /// Client vertex arrays (each: components per vertex, values), then
    /// glDrawArrays(mode, 0, count).
    Draw {
        mode: u32,
        count: usize,
        vertex: (i32, Vec<f32>),
        texcoord0: Option<(i32, Vec<f32>)>,
        texcoord1: Option<(i32, Vec<f32>)>,
        color: Option<(i32, Vec<f32>)>,
    },
}

/// Everything a replay needs: framebuffer size and the calls in order.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Scene {
    pub width: u32,
    pub height: u32,
    /// What drew it ("shaderbox render ...").
    pub description: String,
    pub calls: Vec<Call>,
}

/// A [`gl::Context`] that records every call it makes.
///
/// The library programs it builds stay in the context, keyed by their
/// names, and [`Recorder::begin`] starts a new recording on the same
/// context: a [`crate::Renderer`] draws molecule after molecule without
/// creating a context or compiling a program again. The recording of
/// each render still lists every program it used with its sources, so a
/// replay does not depend on what earlier renders built.
pub struct Recorder {
    pub ctx: Context,
    pub calls: Vec<Call>,
    /// This recording's program ids (the `id` of [`Call::Program`]) to
    /// the context's program names.
    programs: Vec<u32>,
    /// Library programs built on the context so far: name, program name.
    built: Vec<(&'static str, u32)>,
}

impl Recorder {
    /// A new context of `width` x `height` pixels.
    pub fn new(width: u32, height: u32) -> Recorder {
        Recorder {
            ctx: Context::new(width as i32, height as i32),
            calls: Vec::new(),
            programs: Vec::new(),
            built: Vec::new(),
        }
    }

    /// Forgets the calls recorded so far (not the programs built): the
    /// next call starts a new scene.
    pub fn begin(&mut self) {
        self.calls.clear();
        self.programs.clear();
    }

    /// Runs `call` on the context and records it.
    fn run(&mut self, call: Call) {
        // Only Program can fail, and `program` below builds it itself.
        let _ = call.apply(&mut self.ctx, &mut self.programs);
        self.calls.push(call);
    }

    pub fn matrix_mode(&mut self, mode: u32) {
        self.run(Call::MatrixMode(mode));
    }
    pub fn load_identity(&mut self) {
        self.run(Call::LoadIdentity);
    }
    pub fn ortho(&mut self, a: [f64; 6]) {
        self.run(Call::Ortho(a));
    }
    pub fn frustum(&mut self, a: [f64; 6]) {
        self.run(Call::Frustum(a));
    }
    pub fn translate(&mut self, v: [f32; 3]) {
        self.run(Call::Translate(v));
    }
    pub fn rotate(&mut self, angle: f32, axis: [f32; 3]) {
        self.run(Call::Rotate([angle, axis[0], axis[1], axis[2]]));
    }
    pub fn light(&mut self, light: u32, pname: u32, params: &[f32]) {
        self.run(Call::Light(light, pname, params.to_vec()));
    }
    pub fn material(&mut self, face: u32, pname: u32, params: &[f32]) {
        self.run(Call::Material(face, pname, params.to_vec()));
    }
    pub fn enable(&mut self, cap: u32) {
        self.run(Call::Enable(cap));
    }
    pub fn disable(&mut self, cap: u32) {
        self.run(Call::Disable(cap));
    }
    pub fn fog(&mut self, pname: u32, params: &[f32]) {
        self.run(Call::Fog(pname, params.to_vec()));
    }
    pub fn clear_color(&mut self, c: [f32; 4]) {
        self.run(Call::ClearColor(c));
    }
    pub fn clear_depth(&mut self, d: f64) {
        self.run(Call::ClearDepth(d));
    }
    pub fn clear(&mut self, mask: u32) {
        self.run(Call::Clear(mask));
    }
    pub fn depth_func(&mut self, func: u32) {
        self.run(Call::DepthFunc(func));
    }

    /// Builds a library program (once per context: later calls reuse it)
    /// and uses it; returns its scene id. (Built from the library's files
    /// so that errors name them.)
    pub fn program(&mut self, p: &crate::library::Program) -> Result<usize, String> {
        let gl_name = match self.built.iter().find(|(name, _)| *name == p.name) {
            Some(&(_, gl_name)) => gl_name,
            None => {
                let gl_name = crate::library::build(&mut self.ctx, p)?;
                self.built.push((p.name, gl_name));
                gl_name
            }
        };
        self.ctx.use_program(gl_name);
        let id = self.programs.len();
        self.programs.push(gl_name);
        let sources = |files: &[crate::library::ShaderFile]| -> Vec<String> {
            files.iter().map(|f| f.source.to_string()).collect()
        };
        self.calls.push(Call::Program {
            id,
            vertex: sources(p.vertex),
            geometry: p.geometry.map_or_else(Vec::new, |g| sources(g.files)),
            parameters: p
                .geometry
                .map_or_else(Vec::new, |g| g.parameters().to_vec()),
            fragment: sources(p.fragment),
        });
        Ok(id)
    }

    /// Uses program `id` of [`Recorder::program`].
    pub fn use_program(&mut self, id: usize) {
        self.run(Call::UseProgram(id));
    }

    /// glUniform{1,2,3,4}f of the current program (1-4 values).
    pub fn uniform(&mut self, name: &str, values: &[f32]) {
        self.run(Call::Uniform {
            name: name.to_string(),
            values: values.to_vec(),
            array: false,
        });
    }

    /// glUniform1fv of a float array of the current program.
    pub fn uniform_array(&mut self, name: &str, values: &[f32]) {
        self.run(Call::Uniform {
            name: name.to_string(),
            values: values.to_vec(),
            array: true,
        });
    }

    /// Draws `count` vertices from client arrays (vertex array and the
    /// optional texture coordinate sets 0, 1 and colour array).
    pub fn draw(
        &mut self,
        mode: u32,
        count: usize,
        vertex: (i32, Vec<f32>),
        texcoord0: Option<(i32, Vec<f32>)>,
        texcoord1: Option<(i32, Vec<f32>)>,
        color: Option<(i32, Vec<f32>)>,
    ) {
        self.run(Call::Draw {
            mode,
            count,
            vertex,
            texcoord0,
            texcoord1,
            color,
        });
    }

    /// The recorded scene.
    pub fn scene(&self, description: String) -> Scene {
        Scene {
            width: self.ctx.width() as u32,
            height: self.ctx.height() as u32,
            description,
            calls: self.calls.clone(),
        }
    }
}

impl Call {
    /// Runs the call on `ctx`. `programs` maps the scene's program ids to
    /// the context's program names (a `Program` call adds one). Errors:
    /// a program that does not compile or link.
    pub fn apply(&self, ctx: &mut Context, programs: &mut Vec<u32>) -> Result<(), String> {
        match self {
            Call::MatrixMode(mode) => ctx.matrix_mode(*mode),
            Call::LoadIdentity => ctx.load_identity(),
            Call::Ortho(a) => ctx.ortho(a[0], a[1], a[2], a[3], a[4], a[5]),
            Call::Frustum(a) => ctx.frustum(a[0], a[1], a[2], a[3], a[4], a[5]),
            Call::Translate(v) => ctx.translatef(v[0], v[1], v[2]),
            Call::Rotate(r) => ctx.rotatef(r[0], r[1], r[2], r[3]),
            Call::Light(light, pname, params) => ctx.light(*light, *pname, Param::Fv(params)),
            Call::Material(face, pname, params) => ctx.material(*face, *pname, Param::Fv(params)),
            Call::Enable(cap) => ctx.enable(*cap),
            Call::Disable(cap) => ctx.disable(*cap),
            Call::Fog(pname, params) => ctx.fog(*pname, Param::Fv(params)),
            Call::ClearColor(c) => ctx.clear_color(c[0], c[1], c[2], c[3]),
            Call::ClearDepth(d) => ctx.clear_depth(*d),
            Call::Clear(mask) => ctx.clear(*mask),
            Call::DepthFunc(func) => ctx.depth_func(*func),
            Call::Program {
                id,
                vertex,
                geometry,
                parameters,
                fragment,
            } => {
                let mut objects = Vec::new();
                for (kind, stage, sources) in [
                    (GL_VERTEX_SHADER, "vertex", vertex),
                    (GL_GEOMETRY_SHADER_EXT, "geometry", geometry),
                    (GL_FRAGMENT_SHADER, "fragment", fragment),
                ] {
                    for (i, src) in sources.iter().enumerate() {
                        objects.push((
                            kind,
                            format!("program {id}, {stage} shader {}", i + 1),
                            src.as_str(),
                        ));
                    }
                }
                let name = crate::library::build_objects(
                    ctx,
                    &format!("program {id}"),
                    &objects,
                    parameters,
                )?;
                ctx.use_program(name);
                programs.push(name);
            }
            Call::UseProgram(id) => ctx.use_program(programs.get(*id).copied().unwrap_or(0)),
            Call::Uniform {
                name,
                values,
                array,
            } => {
                let program = ctx
                    .get_integerv(GL_CURRENT_PROGRAM)
                    .first()
                    .copied()
                    .unwrap_or(0) as u32;
                let loc = ctx.get_uniform_location(program, name);
                match (array, values.as_slice()) {
                    (false, [x]) => ctx.uniform_1f(loc, *x),
                    (false, [x, y]) => ctx.uniform_2f(loc, *x, *y),
                    (false, [x, y, z]) => ctx.uniform_3f(loc, *x, *y, *z),
                    (false, [x, y, z, w]) => ctx.uniform_4f(loc, *x, *y, *z, *w),
                    _ => ctx.uniform_1fv(loc, values.len() as i32, values),
                }
            }
            Call::Draw {
                mode,
                count,
                vertex,
                texcoord0,
                texcoord1,
                color,
            } => {
                ctx.vertex_pointer(vertex.0, GL_FLOAT, 0, ArrayData::from_f32(&vertex.1));
                ctx.enable_client_state(GL_VERTEX_ARRAY);
                for (unit, set) in [(GL_TEXTURE0, texcoord0), (GL_TEXTURE1, texcoord1)] {
                    ctx.client_active_texture(unit);
                    match set {
                        Some((n, v)) => {
                            ctx.tex_coord_pointer(*n, GL_FLOAT, 0, ArrayData::from_f32(v));
                            ctx.enable_client_state(GL_TEXTURE_COORD_ARRAY);
                        }
                        None => ctx.disable_client_state(GL_TEXTURE_COORD_ARRAY),
                    }
                }
                ctx.client_active_texture(GL_TEXTURE0);
                match color {
                    Some((n, v)) => {
                        ctx.color_pointer(*n, GL_FLOAT, 0, ArrayData::from_f32(v));
                        ctx.enable_client_state(GL_COLOR_ARRAY);
                    }
                    None => ctx.disable_client_state(GL_COLOR_ARRAY),
                }
                ctx.draw_arrays(*mode, 0, i32::try_from(*count).unwrap_or(i32::MAX));
            }
        }
        Ok(())
    }
}

impl Scene {
    /// The scene from the JSON of [`Scene::to_json`].
    pub fn from_json(text: &str) -> Result<Scene, String> {
        serde_json::from_str(text).map_err(|e| format!("not a shaderbox scene: {e}"))
    }

    /// Runs every call on a fresh context of the scene's size (which the
    /// caller may set up first, e.g. for debugging) and returns it.
    pub fn replay_on(&self, mut ctx: Context) -> Result<Context, String> {
        let mut programs = Vec::new();
        for (i, call) in self.calls.iter().enumerate() {
            call.apply(&mut ctx, &mut programs)
                .map_err(|e| format!("call {i}: {e}"))?;
        }
        Ok(ctx)
    }

    /// The scene as JSON text.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }
}
