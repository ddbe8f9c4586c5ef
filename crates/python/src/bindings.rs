//! The PyO3 module `shaderbox._shaderbox`: a thin, checked layer over
//! [`gl::Context`] ([`RawContext`]), the compiler's reports
//! ([`crate::report`]), molecules ([`crate::molecule`]) and PNG encoding.
//! The Python package (`crates/python/python/shaderbox`) builds the public
//! API on top; nothing here is meant to be called directly by users.
//!
//! Every method is total: bad arguments become Python exceptions or GL
//! errors (read back with `get_error`), never a panic. Draws release the
//! GIL.

use crate::molecule::{self, MoleculeArgs, MoleculeError, Source};
use crate::report::{self, Located, Report};
use gl::enums::*;
use gl::{ArrayData, Context, Param};
use pyo3::exceptions::{PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use std::path::PathBuf;
use std::sync::{Mutex, MutexGuard};

// The OSMesa + gl* C ABI and the EGL one, linked into this extension so
// that their `#[no_mangle]` symbols are exported from it (see
// shaderbox/pyopengl.py and shaderbox/egl.py).
extern crate capi as _;
extern crate egl as _;

type DiagTuple = (
    Option<&'static str>,
    &'static str,
    &'static str,
    String,
    Option<u32>,
    Option<u32>,
    Option<u32>,
    Vec<String>,
);
type ReportTuple = (bool, Vec<DiagTuple>, String, String);
/// A uniform block member: (name, GL type, array size, offset, array
/// stride, matrix stride, row major).
type MemberTuple = (String, u32, i32, i32, i32, i32, bool);
/// A uniform block: (name, index, binding, data size, members).
type BlockTuple = (String, u32, u32, i32, Vec<MemberTuple>);

fn diag_tuple(d: Located) -> DiagTuple {
    (
        d.stage,
        d.severity,
        d.code,
        d.message,
        d.line,
        d.column,
        d.source_string,
        d.notes,
    )
}

fn report_tuple(r: Report) -> ReportTuple {
    (
        r.ok,
        r.diagnostics.into_iter().map(diag_tuple).collect(),
        r.text,
        r.info_log,
    )
}

fn stage_of(name: &str) -> PyResult<glsl::Stage> {
    report::parse_stage(name).ok_or_else(|| {
        PyValueError::new_err(format!(
            "stage {name:?} is not 'vertex', 'tess_control', 'tess_evaluation', 'geometry', 'fragment' or 'compute'"
        ))
    })
}

fn version_of(v: Option<u32>) -> PyResult<Option<glsl::Version>> {
    match v {
        None => Ok(None),
        Some(n) => glsl::Version::from_number(n).map(Some).ok_or_else(|| {
            let known: Vec<String> = glsl::Version::ALL
                .iter()
                .map(|v| v.number().to_string())
                .collect();
            PyValueError::new_err(format!(
                "version {n} is not a GLSL version shaderbox knows ({})",
                known.join(", ")
            ))
        }),
    }
}

/// compile_report(source, stage, version, name, compatibility) -> (ok,
/// diagnostics, text, info_log); `compatibility`: whether the context
/// offers the compatibility profile (false for core contexts).
#[pyfunction]
#[pyo3(signature = (source, stage, version=None, name="<shader>", compatibility=true))]
fn compile_report(
    source: &str,
    stage: &str,
    version: Option<u32>,
    name: &str,
    compatibility: bool,
) -> PyResult<ReportTuple> {
    let shader = report::compile_for(
        source,
        stage_of(stage)?,
        version_of(version)?,
        name,
        compatibility,
    );
    Ok(report_tuple(report::compile_report(&shader)))
}

/// link_report(vertex, fragment, compatibility, geometry) -> (ok,
/// diagnostics, text, info_log). Every given shader must compile (call
/// compile_report first).
#[pyfunction]
#[pyo3(signature = (vertex=None, fragment=None, compatibility=true, geometry=None))]
fn link_report(
    vertex: Option<&str>,
    fragment: Option<&str>,
    compatibility: bool,
    geometry: Option<&str>,
) -> ReportTuple {
    let mut shaders = Vec::new();
    for (src, stage, name) in [
        (vertex, glsl::Stage::Vertex, "vertex_shader"),
        (geometry, glsl::Stage::Geometry, "geometry_shader"),
        (fragment, glsl::Stage::Fragment, "fragment_shader"),
    ] {
        if let Some(src) = src {
            shaders.push(report::compile_for(src, stage, None, name, compatibility));
        }
    }
    let refs: Vec<&glsl::Shader> = shaders.iter().collect();
    report_tuple(report::link_report(&refs))
}

/// The project's shader library: [(file name, source)].
#[pyfunction]
fn library_shaders() -> Vec<(&'static str, &'static str)> {
    vec![
        ("sphere.vert", render::SPHERE_VERT),
        ("sphere.frag", render::SPHERE_FRAG),
        ("outline.frag", render::OUTLINE_FRAG),
        ("x.vert", render::X_VERT),
        ("x.frag", render::X_FRAG),
        ("x-red.frag", render::X_RED_FRAG),
        ("transparent.frag", render::TRANSPARENT_FRAG),
    ]
}

/// encode_png(width, height, rgba, has_alpha) -> bytes. `rgba` is
/// width*height*4 bytes, top row first.
#[pyfunction]
fn encode_png<'py>(
    py: Python<'py>,
    width: u32,
    height: u32,
    rgba: &[u8],
    has_alpha: bool,
) -> PyResult<Bound<'py, PyBytes>> {
    let n = (width as usize)
        .checked_mul(height as usize)
        .and_then(|n| n.checked_mul(4));
    if width == 0 || height == 0 || n != Some(rgba.len()) {
        return Err(PyValueError::new_err(format!(
            "{} bytes are not a {width}x{height} RGBA image",
            rgba.len()
        )));
    }
    let image = render::Image {
        width,
        height,
        pixels: rgba
            .chunks_exact(4)
            .map(|c| [c[0], c[1], c[2], c[3]])
            .collect(),
        has_alpha,
    };
    let png = image
        .to_png()
        .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    Ok(PyBytes::new(py, &png))
}

/// A molecule renderer keeping one GL context and its compiled programs
/// across calls ([`render::Renderer`]); `shaderbox.MoleculeRenderer` and
/// `shaderbox.render_molecule` (a new one per call) wrap it. Calls lock it.
#[pyclass(module = "shaderbox._shaderbox")]
#[derive(Default)]
struct RawMoleculeRenderer {
    renderer: Mutex<render::Renderer>,
}

#[pymethods]
impl RawMoleculeRenderer {
    #[new]
    fn new() -> RawMoleculeRenderer {
        RawMoleculeRenderer::default()
    }

    /// render(path, text, name, width, height, projection, fog, lights,
    /// rotate, supersample, background, effect, style, atoms) -> (width,
    /// height, rgba, has_alpha). The structure: `text` (PDB or mmCIF,
    /// called `name` in errors) when given, else the file `path`, else
    /// crambin.
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (path, text, name, width, height, projection, fog, lights, rotate, supersample, background, effect, style, atoms))]
    fn render<'py>(
        &self,
        py: Python<'py>,
        path: Option<PathBuf>,
        text: Option<Vec<u8>>,
        name: &str,
        width: u32,
        height: u32,
        projection: &str,
        fog: &str,
        lights: Vec<u8>,
        rotate: [f32; 3],
        supersample: u32,
        background: Option<[f32; 3]>,
        effect: &str,
        style: &str,
        atoms: &str,
    ) -> PyResult<(u32, u32, Bound<'py, PyBytes>, bool)> {
        let args = MoleculeArgs {
            width,
            height,
            projection,
            fog,
            lights,
            rotate,
            supersample,
            background,
            effect,
            style,
            atoms,
        };
        let source = match (&text, &path) {
            (Some(t), _) => Source::Text(t, name),
            (None, Some(p)) => Source::File(p),
            (None, None) => Source::Crambin,
        };
        let result = py.detach(|| {
            // A panic while locked cannot happen (render never panics); if
            // it did, the renderer makes a new context on a size change
            // and draws with fully specified state anyway.
            let mut r = self.renderer.lock().unwrap_or_else(|e| e.into_inner());
            molecule::render_molecule(&mut r, source, &args)
        });
        match result {
            Ok(img) => {
                let bytes: Vec<u8> = img.pixels.iter().flatten().copied().collect();
                Ok((
                    img.width,
                    img.height,
                    PyBytes::new(py, &bytes),
                    img.has_alpha,
                ))
            }
            Err(MoleculeError::Option(m)) => Err(PyValueError::new_err(m)),
            Err(MoleculeError::Io(m)) => Err(PyOSError::new_err(m)),
            Err(MoleculeError::Failed(m)) => Err(PyRuntimeError::new_err(m)),
        }
    }
}

/// One GL context (see the module docs). Not shared between threads
/// while a call runs: calls lock it.
#[pyclass(module = "shaderbox._shaderbox")]
struct RawContext {
    ctx: Mutex<Context>,
}

impl RawContext {
    fn gl(&self) -> MutexGuard<'_, Context> {
        // A panic while locked cannot happen (gl never panics); if it did,
        // the state is still a valid context.
        self.ctx.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// Texture coordinate unit of `gl_MultiTexCoordN`.
fn multi_tex_coord_unit(name: &str) -> Option<u32> {
    let n: u32 = name.strip_prefix("gl_MultiTexCoord")?.parse().ok()?;
    (n < gl::MAX_TEXTURE_UNITS as u32).then_some(n)
}

#[pymethods]
impl RawContext {
    #[new]
    #[pyo3(signature = (width, height, major=2, minor=1, profile="compatibility"))]
    fn new(width: i32, height: i32, major: i32, minor: i32, profile: &str) -> PyResult<RawContext> {
        let max = gl::MAX_TEXTURE_SIZE;
        if !(1..=max).contains(&width) || !(1..=max).contains(&height) {
            return Err(PyValueError::new_err(format!(
                "context size {width}x{height} is invalid: each side must be 1-{max}"
            )));
        }
        let profile = match profile {
            "core" => gl::Profile::Core,
            "compatibility" => gl::Profile::Compatibility,
            other => {
                return Err(PyValueError::new_err(format!(
                    "profile {other:?} is not 'core' or 'compatibility'"
                )))
            }
        };
        let api = gl::Api::for_request(major, minor, profile).ok_or_else(|| {
            PyValueError::new_err(format!(
                "OpenGL {major}.{minor} is not available: shaderbox implements 2.1 and 3.3 \
                 (core and compatibility); ask for a version up to 3.3"
            ))
        })?;
        let mut ctx = Context::with_api(width, height, api);
        // Core contexts draw only with a vertex array object: the
        // package's vertex arrays share this one (their attributes are
        // set before each draw).
        if api.is_core() {
            if let Some(&vao) = ctx.gen_vertex_arrays(1).first() {
                ctx.bind_vertex_array(vao);
            }
        }
        // Tightly packed rows, as numpy arrays are.
        ctx.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        ctx.pixel_storei(GL_PACK_ALIGNMENT, 1);
        Ok(RawContext {
            ctx: Mutex::new(ctx),
        })
    }

    /// The context's (major, minor, profile).
    fn api(&self) -> (u32, u32, &'static str) {
        let api = self.gl().api();
        let profile = if api.is_core() {
            "core"
        } else {
            "compatibility"
        };
        (api.major, api.minor, profile)
    }

    /// Starts tracing `pixel` in the following draws (see
    /// `gl::Context::set_debug`); `debug_end` returns the report.
    #[pyo3(signature = (x, y, draw=None, vertex=None))]
    fn debug_begin(&self, x: u32, y: u32, draw: Option<usize>, vertex: Option<usize>) {
        let mut req = gl::debug::DebugRequest::pixel(x, y);
        req.draw = draw;
        req.vertex = vertex;
        self.gl().set_debug(Some(req));
    }

    /// Stops tracing; the report of the draws since `debug_begin` as
    /// (text, JSON).
    fn debug_end(&self) -> (String, String) {
        let mut ctx = self.gl();
        let records = ctx.take_debug_records();
        let pixel = records.first().map_or((0, 0), |r| r.probe.pixel);
        ctx.set_debug(None);
        let report = debugger::Report::from_records(pixel, &records);
        (report.text(), report.json())
    }

    fn set_threads(&self, threads: usize) {
        self.gl().set_threads(threads);
    }
    fn threads(&self) -> usize {
        self.gl().threads()
    }
    fn width(&self) -> i32 {
        self.gl().width()
    }
    fn height(&self) -> i32 {
        self.gl().height()
    }
    fn get_error(&self) -> u32 {
        self.gl().get_error()
    }
    fn enable(&self, cap: u32) {
        self.gl().enable(cap);
    }
    fn disable(&self, cap: u32) {
        self.gl().disable(cap);
    }
    fn is_enabled(&self, cap: u32) -> bool {
        self.gl().is_enabled(cap)
    }
    fn clear_color(&self, r: f32, g: f32, b: f32, a: f32) {
        self.gl().clear_color(r, g, b, a);
    }
    fn clear_depth(&self, d: f64) {
        self.gl().clear_depth(d);
    }
    fn clear(&self, py: Python<'_>, mask: u32) {
        py.detach(|| self.gl().clear(mask));
    }
    fn viewport(&self, x: i32, y: i32, w: i32, h: i32) {
        self.gl().viewport(x, y, w, h);
    }
    fn depth_func(&self, func: u32) {
        self.gl().depth_func(func);
    }
    fn depth_mask(&self, flag: bool) {
        self.gl().depth_mask(flag);
    }
    fn blend_func(&self, src: u32, dst: u32) {
        self.gl().blend_func(src, dst);
    }
    fn cull_face(&self, mode: u32) {
        self.gl().cull_face(mode);
    }
    fn point_size(&self, size: f32) {
        self.gl().point_size(size);
    }
    fn matrix_mode(&self, mode: u32) {
        self.gl().matrix_mode(mode);
    }
    /// glLoadMatrixf: 16 values, column-major.
    fn load_matrixf(&self, m: Vec<f32>) -> PyResult<()> {
        let m: [f32; 16] = m
            .try_into()
            .map_err(|_| PyValueError::new_err("a matrix needs 16 values"))?;
        self.gl().load_matrixf(&m);
        Ok(())
    }
    fn get_floatv(&self, pname: u32) -> Vec<f32> {
        self.gl().get_floatv(pname)
    }
    fn get_integerv(&self, pname: u32) -> Vec<i32> {
        self.gl().get_integerv(pname)
    }
    fn lightfv(&self, light: u32, pname: u32, v: Vec<f32>) {
        self.gl().light(light, pname, Param::Fv(&v));
    }
    fn get_lightfv(&self, light: u32, pname: u32) -> Vec<f32> {
        self.gl().get_lightfv(light, pname)
    }
    fn materialfv(&self, face: u32, pname: u32, v: Vec<f32>) {
        self.gl().material(face, pname, Param::Fv(&v));
    }
    fn get_materialfv(&self, face: u32, pname: u32) -> Vec<f32> {
        self.gl().get_materialfv(face, pname)
    }
    fn fogfv(&self, pname: u32, v: Vec<f32>) {
        self.gl().fog(pname, Param::Fv(&v));
    }
    fn fogi(&self, pname: u32, v: i32) {
        self.gl().fog(pname, Param::I(v));
    }
    fn light_modelfv(&self, pname: u32, v: Vec<f32>) {
        self.gl().light_model(pname, Param::Fv(&v));
    }

    /// Compiles and links a program through GL; returns (name, compiled,
    /// linked, info log). The caller checks the sources first
    /// (compile_report, link_report) for structured diagnostics; what
    /// only the context refuses (GLSL 1.10 in a core context) fails here.
    #[pyo3(signature = (vertex=None, fragment=None, geometry=None))]
    fn build_program(
        &self,
        vertex: Option<&str>,
        fragment: Option<&str>,
        geometry: Option<&str>,
    ) -> (u32, bool, bool, String) {
        let mut gl = self.gl();
        let program = gl.create_program();
        let mut log = String::new();
        let mut compiled = true;
        for (kind, src) in [
            (GL_VERTEX_SHADER, vertex),
            (GL_GEOMETRY_SHADER, geometry),
            (GL_FRAGMENT_SHADER, fragment),
        ] {
            let Some(src) = src else { continue };
            let sh = gl.create_shader(kind);
            gl.shader_source(sh, &[src]);
            gl.compile_shader(sh);
            if gl.get_shaderiv(sh, GL_COMPILE_STATUS) == 0 {
                compiled = false;
                log.push_str(&gl.get_shader_info_log(sh));
            }
            gl.attach_shader(program, sh);
            // Freed with the program.
            gl.delete_shader(sh);
        }
        gl.link_program(program);
        let linked = gl.get_programiv(program, GL_LINK_STATUS) != 0;
        log.push_str(&gl.get_program_info_log(program));
        (program, compiled, linked, log)
    }
    fn delete_program(&self, program: u32) {
        self.gl().delete_program(program);
    }
    fn use_program(&self, program: u32) {
        self.gl().use_program(program);
    }
    /// [(name, array size, GL type, location, block index)] of every
    /// active uniform; members of uniform blocks have location -1 and the
    /// index of their block, the others block index -1.
    fn active_uniforms(&self, program: u32) -> Vec<(String, i32, u32, i32, i32)> {
        let mut gl = self.gl();
        let n = gl.get_programiv(program, GL_ACTIVE_UNIFORMS).max(0) as u32;
        let mut out = Vec::new();
        for i in 0..n {
            if let Some(info) = gl.get_active_uniform(program, i) {
                let loc = gl.get_uniform_location(program, &info.name);
                let block = gl
                    .get_active_uniformsiv(program, &[i], GL_UNIFORM_BLOCK_INDEX)
                    .and_then(|v| v.first().copied())
                    .unwrap_or(-1);
                out.push((info.name, info.size, info.ty, loc, block));
            }
        }
        out
    }
    /// [(name, index, binding, data size, members)] of every active
    /// uniform block, members as [(name, GL type, array size, offset,
    /// array stride, matrix stride, row major)] (glGetActiveUniformsiv).
    fn uniform_blocks(&self, program: u32) -> Vec<BlockTuple> {
        let mut gl = self.gl();
        let n = gl.get_programiv(program, GL_ACTIVE_UNIFORM_BLOCKS).max(0) as u32;
        let mut out = Vec::new();
        for b in 0..n {
            let Some(name) = gl.get_active_uniform_block_name(program, b) else {
                continue;
            };
            let mut iv = |pname| {
                gl.get_active_uniform_blockiv(program, b, pname)
                    .unwrap_or_default()
            };
            let binding = iv(GL_UNIFORM_BLOCK_BINDING).first().copied().unwrap_or(0);
            let size = iv(GL_UNIFORM_BLOCK_DATA_SIZE).first().copied().unwrap_or(0);
            let indices: Vec<u32> = iv(GL_UNIFORM_BLOCK_ACTIVE_UNIFORM_INDICES)
                .into_iter()
                .map(|i| i as u32)
                .collect();
            let mut q = |pname| {
                gl.get_active_uniformsiv(program, &indices, pname)
                    .unwrap_or_else(|| vec![0; indices.len()])
            };
            let [types, sizes, offsets, astrides, mstrides, row_major] = [
                GL_UNIFORM_TYPE,
                GL_UNIFORM_SIZE,
                GL_UNIFORM_OFFSET,
                GL_UNIFORM_ARRAY_STRIDE,
                GL_UNIFORM_MATRIX_STRIDE,
                GL_UNIFORM_IS_ROW_MAJOR,
            ]
            .map(&mut q);
            let mut members = Vec::new();
            for (k, &i) in indices.iter().enumerate() {
                let Some(mname) = gl.get_active_uniform_name(program, i) else {
                    continue;
                };
                members.push((
                    mname,
                    types[k] as u32,
                    sizes[k],
                    offsets[k],
                    astrides[k],
                    mstrides[k],
                    row_major[k] != 0,
                ));
            }
            out.push((name, b, binding as u32, size, members));
        }
        out
    }
    /// glUniformBlockBinding.
    fn uniform_block_binding(&self, program: u32, index: u32, binding: u32) {
        self.gl().uniform_block_binding(program, index, binding);
    }
    /// [(name, GL type, location)] of every active attribute; built-in
    /// attributes (gl_Vertex...) have location -1.
    fn active_attributes(&self, program: u32) -> Vec<(String, u32, i32)> {
        let mut gl = self.gl();
        let n = gl.get_programiv(program, GL_ACTIVE_ATTRIBUTES).max(0) as u32;
        let mut out = Vec::new();
        for i in 0..n {
            if let Some(info) = gl.get_active_attrib(program, i) {
                let loc = gl.get_attrib_location(program, &info.name);
                out.push((info.name, info.ty, loc));
            }
        }
        out
    }
    fn uniform_location(&self, program: u32, name: &str) -> i32 {
        self.gl().get_uniform_location(program, name)
    }
    /// glUniform{comps}fv.
    fn uniform_f(&self, loc: i32, comps: u32, count: i32, v: Vec<f32>) -> PyResult<()> {
        let mut gl = self.gl();
        match comps {
            1 => gl.uniform_1fv(loc, count, &v),
            2 => gl.uniform_2fv(loc, count, &v),
            3 => gl.uniform_3fv(loc, count, &v),
            4 => gl.uniform_4fv(loc, count, &v),
            _ => return Err(PyValueError::new_err("components must be 1-4")),
        }
        Ok(())
    }
    /// glUniform{comps}iv.
    fn uniform_i(&self, loc: i32, comps: u32, count: i32, v: Vec<i32>) -> PyResult<()> {
        let mut gl = self.gl();
        match comps {
            1 => gl.uniform_1iv(loc, count, &v),
            2 => gl.uniform_2iv(loc, count, &v),
            3 => gl.uniform_3iv(loc, count, &v),
            4 => gl.uniform_4iv(loc, count, &v),
            _ => return Err(PyValueError::new_err("components must be 1-4")),
        }
        Ok(())
    }
    /// glUniform{comps}uiv.
    fn uniform_u(&self, loc: i32, comps: u32, count: i32, v: Vec<u32>) -> PyResult<()> {
        let mut gl = self.gl();
        match comps {
            1 => gl.uniform_1uiv(loc, count, &v),
            2 => gl.uniform_2uiv(loc, count, &v),
            3 => gl.uniform_3uiv(loc, count, &v),
            4 => gl.uniform_4uiv(loc, count, &v),
            _ => return Err(PyValueError::new_err("components must be 1-4")),
        }
        Ok(())
    }
    /// glUniformMatrix{cols}x{rows}fv with row-major input (transpose).
    fn uniform_matrix(
        &self,
        loc: i32,
        cols: u32,
        rows: u32,
        count: i32,
        v: Vec<f32>,
    ) -> PyResult<()> {
        let mut gl = self.gl();
        match (cols, rows) {
            (2, 2) => gl.uniform_matrix_2fv(loc, count, true, &v),
            (3, 3) => gl.uniform_matrix_3fv(loc, count, true, &v),
            (4, 4) => gl.uniform_matrix_4fv(loc, count, true, &v),
            (2, 3) => gl.uniform_matrix_2x3fv(loc, count, true, &v),
            (2, 4) => gl.uniform_matrix_2x4fv(loc, count, true, &v),
            (3, 2) => gl.uniform_matrix_3x2fv(loc, count, true, &v),
            (3, 4) => gl.uniform_matrix_3x4fv(loc, count, true, &v),
            (4, 2) => gl.uniform_matrix_4x2fv(loc, count, true, &v),
            (4, 3) => gl.uniform_matrix_4x3fv(loc, count, true, &v),
            _ => return Err(PyValueError::new_err("matrices are 2-4 x 2-4")),
        }
        Ok(())
    }
    fn get_uniformf(&self, program: u32, loc: i32) -> Vec<f32> {
        self.gl().get_uniformfv(program, loc)
    }
    fn get_uniformi(&self, program: u32, loc: i32) -> Vec<i32> {
        self.gl().get_uniformiv(program, loc)
    }
    fn get_uniformu(&self, program: u32, loc: i32) -> Vec<u32> {
        self.gl().get_uniformuiv(program, loc)
    }

    /// A buffer object holding `data`; returns its name.
    fn create_buffer(&self, data: &[u8]) -> PyResult<u32> {
        let size =
            isize::try_from(data.len()).map_err(|_| PyValueError::new_err("buffer too large"))?;
        let mut gl = self.gl();
        let name = gl.gen_buffers(1).first().copied().unwrap_or(0);
        gl.bind_buffer(GL_ARRAY_BUFFER, name);
        gl.buffer_data(GL_ARRAY_BUFFER, size, Some(data), GL_STATIC_DRAW);
        gl.bind_buffer(GL_ARRAY_BUFFER, 0);
        Ok(name)
    }
    fn delete_buffer(&self, name: u32) {
        self.gl().delete_buffers(&[name]);
    }
    /// glBufferSubData on buffer `name`.
    fn buffer_sub_data(&self, name: u32, offset: usize, data: &[u8]) -> PyResult<()> {
        let offset =
            isize::try_from(offset).map_err(|_| PyValueError::new_err("offset too large"))?;
        let mut gl = self.gl();
        gl.bind_buffer(GL_ARRAY_BUFFER, name);
        gl.buffer_sub_data(GL_ARRAY_BUFFER, offset, data);
        gl.bind_buffer(GL_ARRAY_BUFFER, 0);
        Ok(())
    }
    /// glGetBufferSubData of buffer `name`.
    fn get_buffer_sub_data<'py>(
        &self,
        py: Python<'py>,
        name: u32,
        offset: usize,
        size: usize,
    ) -> PyResult<Bound<'py, PyBytes>> {
        let (Ok(offset), Ok(size)) = (isize::try_from(offset), isize::try_from(size)) else {
            return Err(PyValueError::new_err("range too large"));
        };
        let mut gl = self.gl();
        gl.bind_buffer(GL_ARRAY_BUFFER, name);
        let bytes = gl.get_buffer_sub_data(GL_ARRAY_BUFFER, offset, size);
        gl.bind_buffer(GL_ARRAY_BUFFER, 0);
        Ok(PyBytes::new(py, &bytes))
    }
    /// Binds buffer `name` to uniform-buffer binding point `binding`:
    /// glBindBufferBase, or glBindBufferRange with `range` = (offset, size).
    #[pyo3(signature = (binding, name, range=None))]
    fn bind_uniform_buffer(
        &self,
        binding: u32,
        name: u32,
        range: Option<(usize, usize)>,
    ) -> PyResult<()> {
        let mut gl = self.gl();
        match range {
            None => gl.bind_buffer_base(GL_UNIFORM_BUFFER, binding, name),
            Some((offset, size)) => {
                let (Ok(offset), Ok(size)) = (isize::try_from(offset), isize::try_from(size))
                else {
                    return Err(PyValueError::new_err("range too large"));
                };
                gl.bind_buffer_range(GL_UNIFORM_BUFFER, binding, name, offset, size);
            }
        }
        Ok(())
    }
    /// Disables every vertex array (client state and generic) and resets
    /// the generic arrays' divisors. Core contexts have no client-state
    /// arrays.
    fn reset_arrays(&self) {
        let mut gl = self.gl();
        for i in 0..gl::MAX_VERTEX_ATTRIBS as u32 {
            gl.disable_vertex_attrib_array(i);
            gl.vertex_attrib_divisor(i, 0);
        }
        if gl.api().is_core() {
            return;
        }
        for cap in [
            GL_VERTEX_ARRAY,
            GL_NORMAL_ARRAY,
            GL_COLOR_ARRAY,
            GL_SECONDARY_COLOR_ARRAY,
            GL_FOG_COORD_ARRAY,
        ] {
            gl.disable_client_state(cap);
        }
        for unit in 0..gl::MAX_TEXTURE_UNITS as u32 {
            gl.client_active_texture(GL_TEXTURE0 + unit);
            gl.disable_client_state(GL_TEXTURE_COORD_ARRAY);
        }
        gl.client_active_texture(GL_TEXTURE0);
    }
    /// Points a built-in attribute (`gl_Vertex`, `gl_Normal`, `gl_Color`,
    /// `gl_SecondaryColor`, `gl_FogCoord`, `gl_MultiTexCoordN`) at a
    /// buffer and enables it. Returns false for another name.
    #[allow(clippy::too_many_arguments)]
    fn builtin_pointer(
        &self,
        name: &str,
        size: i32,
        ty: u32,
        stride: i32,
        buffer: u32,
        offset: usize,
    ) -> bool {
        let mut gl = self.gl();
        gl.bind_buffer(GL_ARRAY_BUFFER, buffer);
        let data = ArrayData::Offset(offset);
        let cap = match name {
            "gl_Vertex" => {
                gl.vertex_pointer(size, ty, stride, data);
                GL_VERTEX_ARRAY
            }
            "gl_Normal" => {
                gl.normal_pointer(ty, stride, data);
                GL_NORMAL_ARRAY
            }
            "gl_Color" => {
                gl.color_pointer(size, ty, stride, data);
                GL_COLOR_ARRAY
            }
            "gl_SecondaryColor" => {
                gl.secondary_color_pointer(size, ty, stride, data);
                GL_SECONDARY_COLOR_ARRAY
            }
            "gl_FogCoord" => {
                gl.fog_coord_pointer(ty, stride, data);
                GL_FOG_COORD_ARRAY
            }
            _ => match multi_tex_coord_unit(name) {
                Some(unit) => {
                    gl.client_active_texture(GL_TEXTURE0 + unit);
                    gl.tex_coord_pointer(size, ty, stride, data);
                    gl.enable_client_state(GL_TEXTURE_COORD_ARRAY);
                    gl.client_active_texture(GL_TEXTURE0);
                    gl.bind_buffer(GL_ARRAY_BUFFER, 0);
                    return true;
                }
                None => {
                    gl.bind_buffer(GL_ARRAY_BUFFER, 0);
                    return false;
                }
            },
        };
        gl.enable_client_state(cap);
        gl.bind_buffer(GL_ARRAY_BUFFER, 0);
        true
    }
    /// glVertexAttribPointer (glVertexAttribIPointer when `integer`:
    /// the values reach the shader unconverted) into a buffer, with
    /// glVertexAttribDivisor(`divisor`), and enables the array.
    #[allow(clippy::too_many_arguments)]
    #[pyo3(signature = (index, size, ty, normalized, stride, buffer, offset, integer=false, divisor=0))]
    fn attrib_pointer(
        &self,
        index: u32,
        size: i32,
        ty: u32,
        normalized: bool,
        stride: i32,
        buffer: u32,
        offset: usize,
        integer: bool,
        divisor: u32,
    ) {
        let mut gl = self.gl();
        gl.bind_buffer(GL_ARRAY_BUFFER, buffer);
        let data = ArrayData::Offset(offset);
        if integer {
            gl.vertex_attrib_i_pointer(index, size, ty, stride, data);
        } else {
            gl.vertex_attrib_pointer(index, size, ty, normalized, stride, data);
        }
        gl.vertex_attrib_divisor(index, divisor);
        gl.enable_vertex_attrib_array(index);
        gl.bind_buffer(GL_ARRAY_BUFFER, 0);
    }
    /// glDrawArraysInstanced (glDrawArrays for one instance); returns the
    /// pipeline's error message, if any (GL errors are read with
    /// get_error).
    #[pyo3(signature = (mode, first, count, instances=1))]
    fn draw_arrays(
        &self,
        py: Python<'_>,
        mode: u32,
        first: i32,
        count: i32,
        instances: i32,
    ) -> Option<String> {
        py.detach(|| {
            let mut gl = self.gl();
            gl.draw_arrays_instanced(mode, first, count, instances);
            gl.take_draw_error()
        })
    }
    /// glDrawElementsInstanced with the indices in buffer `indices`.
    #[pyo3(signature = (mode, count, ty, indices, instances=1))]
    fn draw_elements(
        &self,
        py: Python<'_>,
        mode: u32,
        count: i32,
        ty: u32,
        indices: u32,
        instances: i32,
    ) -> Option<String> {
        py.detach(|| {
            let mut gl = self.gl();
            gl.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, indices);
            gl.draw_elements_instanced(mode, count, ty, ArrayData::Offset(0), instances);
            gl.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, 0);
            gl.take_draw_error()
        })
    }

    fn gen_texture(&self) -> u32 {
        self.gl().gen_textures(1).first().copied().unwrap_or(0)
    }
    fn delete_texture(&self, name: u32) {
        self.gl().delete_textures(&[name]);
    }
    /// Binds texture `name` (GL_TEXTURE_2D) to texture unit `unit`.
    fn bind_texture(&self, unit: u32, name: u32) {
        let mut gl = self.gl();
        gl.active_texture(GL_TEXTURE0 + unit);
        gl.bind_texture(GL_TEXTURE_2D, name);
        gl.active_texture(GL_TEXTURE0);
    }
    /// glTexImage2D on the GL_TEXTURE_2D bound to texture unit `unit`.
    #[allow(clippy::too_many_arguments)]
    fn tex_image_2d(
        &self,
        unit: u32,
        internal: i32,
        width: i32,
        height: i32,
        format: u32,
        ty: u32,
        data: &[u8],
    ) {
        let mut gl = self.gl();
        gl.active_texture(GL_TEXTURE0 + unit);
        gl.tex_image(
            GL_TEXTURE_2D,
            0,
            internal,
            [width, height],
            0,
            format,
            ty,
            Some(data),
        );
        gl.active_texture(GL_TEXTURE0);
    }
    /// glTexParameteri on the GL_TEXTURE_2D bound to texture unit `unit`.
    fn tex_parameteri(&self, unit: u32, pname: u32, value: i32) {
        let mut gl = self.gl();
        gl.active_texture(GL_TEXTURE0 + unit);
        gl.tex_parameter(GL_TEXTURE_2D, pname, Param::I(value));
        gl.active_texture(GL_TEXTURE0);
    }
    /// glGenerateMipmap on the GL_TEXTURE_2D bound to texture unit `unit`.
    fn generate_mipmap(&self, unit: u32) {
        let mut gl = self.gl();
        gl.active_texture(GL_TEXTURE0 + unit);
        gl.generate_mipmap(GL_TEXTURE_2D);
        gl.active_texture(GL_TEXTURE0);
    }

    /// RGBA8 pixels of the rectangle, bottom row first.
    fn read_pixels<'py>(
        &self,
        py: Python<'py>,
        x: i32,
        y: i32,
        w: i32,
        h: i32,
    ) -> Bound<'py, PyBytes> {
        let n = (w.max(0) as usize).saturating_mul(h.max(0) as usize);
        let mut out = vec![0u8; n.saturating_mul(4)];
        self.gl()
            .read_pixels(x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, &mut out);
        PyBytes::new(py, &out)
    }
    /// Window depth (float32 little-endian bytes), bottom row first.
    fn read_depth<'py>(
        &self,
        py: Python<'py>,
        x: i32,
        y: i32,
        w: i32,
        h: i32,
    ) -> Bound<'py, PyBytes> {
        let n = (w.max(0) as usize).saturating_mul(h.max(0) as usize);
        let mut out = vec![0u8; n.saturating_mul(4)];
        self.gl()
            .read_pixels(x, y, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, &mut out);
        PyBytes::new(py, &out)
    }
}

/// The module `shaderbox._shaderbox`.
#[pymodule]
fn _shaderbox(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("MAX_SIZE", gl::MAX_TEXTURE_SIZE)?;
    m.add("MAX_LIGHTS", gl::MAX_LIGHTS)?;
    m.add("MAX_TEXTURE_UNITS", gl::MAX_TEXTURE_IMAGE_UNITS)?;
    m.add_class::<RawContext>()?;
    m.add_function(wrap_pyfunction!(compile_report, m)?)?;
    m.add_function(wrap_pyfunction!(link_report, m)?)?;
    m.add_function(wrap_pyfunction!(library_shaders, m)?)?;
    m.add_function(wrap_pyfunction!(encode_png, m)?)?;
    m.add_class::<RawMoleculeRenderer>()?;
    Ok(())
}
