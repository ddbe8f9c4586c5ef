//! The GL calls a render issues, recorded as data ([`Scene`]) so another
//! OpenGL can replay them: `shaderbox render --export-scene FILE.json`
//! writes them, and `scripts/regen-references.py` replays them through
//! PyOpenGL on Mesa to make the reference images the tests compare with.
//!
//! [`Recorder`] wraps a [`gl::Context`]: every call both runs on the
//! context and is appended to the scene, so the scene is by construction
//! what shaderbox drew. Uniforms are recorded by name (locations are the
//! implementation's), programs by their shader sources, vertex arrays by
//! their contents. Enum values are GL's numbers.

use gl::enums::*;
use gl::{ArrayData, Context};
use serde::Serialize;

/// One recorded GL call (the JSON form: `{"call": "Enable", "args": ...}`).
#[derive(Clone, Debug, PartialEq, Serialize)]
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
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Scene {
    pub width: u32,
    pub height: u32,
    /// What drew it ("shaderbox render ...").
    pub description: String,
    pub calls: Vec<Call>,
}

/// A [`gl::Context`] that records every call it makes.
pub struct Recorder {
    pub ctx: Context,
    pub calls: Vec<Call>,
    programs: Vec<u32>,
}

impl Recorder {
    /// A new context of `width` x `height` pixels.
    pub fn new(width: u32, height: u32) -> Recorder {
        Recorder {
            ctx: Context::new(width as i32, height as i32),
            calls: Vec::new(),
            programs: Vec::new(),
        }
    }

    pub fn matrix_mode(&mut self, mode: u32) {
        self.ctx.matrix_mode(mode);
        self.calls.push(Call::MatrixMode(mode));
    }
    pub fn load_identity(&mut self) {
        self.ctx.load_identity();
        self.calls.push(Call::LoadIdentity);
    }
    pub fn ortho(&mut self, a: [f64; 6]) {
        self.ctx.ortho(a[0], a[1], a[2], a[3], a[4], a[5]);
        self.calls.push(Call::Ortho(a));
    }
    pub fn frustum(&mut self, a: [f64; 6]) {
        self.ctx.frustum(a[0], a[1], a[2], a[3], a[4], a[5]);
        self.calls.push(Call::Frustum(a));
    }
    pub fn translate(&mut self, v: [f32; 3]) {
        self.ctx.translatef(v[0], v[1], v[2]);
        self.calls.push(Call::Translate(v));
    }
    pub fn rotate(&mut self, angle: f32, axis: [f32; 3]) {
        self.ctx.rotatef(angle, axis[0], axis[1], axis[2]);
        self.calls
            .push(Call::Rotate([angle, axis[0], axis[1], axis[2]]));
    }
    pub fn light(&mut self, light: u32, pname: u32, params: &[f32]) {
        self.ctx.lightfv(light, pname, params);
        self.calls.push(Call::Light(light, pname, params.to_vec()));
    }
    pub fn material(&mut self, face: u32, pname: u32, params: &[f32]) {
        self.ctx.materialfv(face, pname, params);
        self.calls
            .push(Call::Material(face, pname, params.to_vec()));
    }
    pub fn enable(&mut self, cap: u32) {
        self.ctx.enable(cap);
        self.calls.push(Call::Enable(cap));
    }
    pub fn disable(&mut self, cap: u32) {
        self.ctx.disable(cap);
        self.calls.push(Call::Disable(cap));
    }
    pub fn fog(&mut self, pname: u32, params: &[f32]) {
        self.ctx.fogfv(pname, params);
        self.calls.push(Call::Fog(pname, params.to_vec()));
    }
    pub fn clear_color(&mut self, c: [f32; 4]) {
        self.ctx.clear_color(c[0], c[1], c[2], c[3]);
        self.calls.push(Call::ClearColor(c));
    }
    pub fn clear_depth(&mut self, d: f64) {
        self.ctx.clear_depth(d);
        self.calls.push(Call::ClearDepth(d));
    }
    pub fn clear(&mut self, mask: u32) {
        self.ctx.clear(mask);
        self.calls.push(Call::Clear(mask));
    }
    pub fn depth_func(&mut self, func: u32) {
        self.ctx.depth_func(func);
        self.calls.push(Call::DepthFunc(func));
    }

    /// Builds a library program and uses it; returns its scene id.
    pub fn program(&mut self, p: &crate::library::Program) -> Result<usize, String> {
        let gl_name = crate::library::build(&mut self.ctx, p)?;
        self.ctx.use_program(gl_name);
        let id = self.programs.len();
        self.programs.push(gl_name);
        self.calls.push(Call::Program {
            id,
            vertex: p.vertex.iter().map(|f| f.source.to_string()).collect(),
            fragment: p.fragment.iter().map(|f| f.source.to_string()).collect(),
        });
        Ok(id)
    }

    /// Uses program `id` of [`Recorder::program`].
    pub fn use_program(&mut self, id: usize) {
        let name = self.programs.get(id).copied().unwrap_or(0);
        self.ctx.use_program(name);
        self.calls.push(Call::UseProgram(id));
    }

    fn current_program(&mut self) -> u32 {
        self.ctx
            .get_integerv(GL_CURRENT_PROGRAM)
            .first()
            .copied()
            .unwrap_or(0) as u32
    }

    /// glUniform{1,2,3,4}f of the current program (1-4 values).
    pub fn uniform(&mut self, name: &str, values: &[f32]) {
        let program = self.current_program();
        let loc = self.ctx.get_uniform_location(program, name);
        match *values {
            [x] => self.ctx.uniform_1f(loc, x),
            [x, y] => self.ctx.uniform_2f(loc, x, y),
            [x, y, z] => self.ctx.uniform_3f(loc, x, y, z),
            [x, y, z, w] => self.ctx.uniform_4f(loc, x, y, z, w),
            _ => self.ctx.uniform_1fv(loc, values.len() as i32, values),
        }
        self.calls.push(Call::Uniform {
            name: name.to_string(),
            values: values.to_vec(),
            array: false,
        });
    }

    /// glUniform1fv of a float array of the current program.
    pub fn uniform_array(&mut self, name: &str, values: &[f32]) {
        let program = self.current_program();
        let loc = self.ctx.get_uniform_location(program, name);
        self.ctx.uniform_1fv(loc, values.len() as i32, values);
        self.calls.push(Call::Uniform {
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
        let ctx = &mut self.ctx;
        ctx.vertex_pointer(vertex.0, GL_FLOAT, 0, ArrayData::from_f32(&vertex.1));
        ctx.enable_client_state(GL_VERTEX_ARRAY);
        for (unit, set) in [(GL_TEXTURE0, &texcoord0), (GL_TEXTURE1, &texcoord1)] {
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
        match &color {
            Some((n, v)) => {
                ctx.color_pointer(*n, GL_FLOAT, 0, ArrayData::from_f32(v));
                ctx.enable_client_state(GL_COLOR_ARRAY);
            }
            None => ctx.disable_client_state(GL_COLOR_ARRAY),
        }
        let n = i32::try_from(count).unwrap_or(i32::MAX);
        ctx.draw_arrays(mode, 0, n);
        self.calls.push(Call::Draw {
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

impl Scene {
    /// The scene as JSON text.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }
}
