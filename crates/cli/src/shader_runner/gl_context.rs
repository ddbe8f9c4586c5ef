//! `GlApi` for `gl::Context` (feature `gl-context`): one forwarding call
//! per entry point. TEMPORARY: written against the gl branch's API
//! (commit 5c83a3f) before it landed on main; when it does, fold the runner
//! onto `gl::Context` and delete this file and `gl_api.rs`.

use super::gl_api::GlApi;
use super::run::Verdict;
use super::script::Script;
use super::{execute_on, Options};
use gl::enums::*;
use gl::{ArrayData, Param};

/// Creates the script's context and runs it. (`gl::Context::new` always has
/// depth and stencil buffers; piglit's window has a depth buffer only with
/// `depthbuffer`, which only matters to depth tests without one.)
pub fn execute(opts: &Options, name: &str, script: &Script) -> (Verdict, String, String) {
    let mut ctx = context(&super::run::window_config(script));
    execute_on(&mut ctx, opts, name, script)
}

/// The context a script with `window` runs on: its size and the API it
/// asks for.
pub fn context(window: &super::run::WindowConfig) -> gl::Context {
    let mut ctx = gl::Context::with_api(window.width, window.height, window.api);
    // Core contexts draw only with a vertex array object bound; piglit
    // binds one for the whole test.
    if window.api.is_core() {
        if let Some(&vao) = ctx.gen_vertex_arrays(1).first() {
            ctx.bind_vertex_array(vao);
        }
    }
    ctx
}

/// The data of attribute `index`'s next pointer: the values themselves
/// (a client array), or in a core context, which has no client arrays,
/// offset 0 of the buffer the attribute already reads (or a new one),
/// filled with them and left bound to GL_ARRAY_BUFFER for the pointer
/// call ([`restore_array_buffer`] unbinds it), as piglit streams its
/// arrays there.
fn array_data(ctx: &mut gl::Context, index: u32, values: &[f32]) -> ArrayData {
    if !ctx.is_core() {
        return ArrayData::from_f32(values);
    }
    let bound = ctx.get_vertex_attrib_array(index, GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING);
    let buffer = match bound {
        Some(b) if b > 0 => b as u32,
        _ => ctx.gen_buffers(1).first().copied().unwrap_or(0),
    };
    ctx.bind_buffer(GL_ARRAY_BUFFER, buffer);
    let bytes = f32_bytes(values);
    ctx.buffer_data(
        GL_ARRAY_BUFFER,
        bytes.len() as isize,
        Some(&bytes),
        GL_STREAM_DRAW,
    );
    ArrayData::Offset(0)
}

/// Unbinds the buffer [`array_data`] bound (the runner binds no array
/// buffer of its own).
fn restore_array_buffer(ctx: &mut gl::Context) {
    if ctx.is_core() {
        ctx.bind_buffer(GL_ARRAY_BUFFER, 0);
    }
}

fn f32_bytes(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|f| f.to_le_bytes()).collect()
}

impl GlApi for gl::Context {
    fn get_string(&mut self, name: u32) -> String {
        // Core contexts have no GL_EXTENSIONS string; the runner checks
        // extensions the way piglit does there, through glGetStringi.
        if name == gl::enums::GL_EXTENSIONS && self.is_core() {
            return self.api().extensions().join(" ");
        }
        gl::Context::get_string(self, name)
    }
    fn get_integer_v(&mut self, pname: u32, params: &mut [i32]) {
        let v = gl::Context::get_integerv(self, pname);
        for (p, x) in params.iter_mut().zip(v) {
            *p = x;
        }
    }
    fn get_error(&mut self) -> u32 {
        gl::Context::get_error(self)
    }
    fn take_draw_failure(&mut self) -> Option<String> {
        gl::Context::take_draw_error(self)
    }
    fn create_shader(&mut self, kind: u32) -> u32 {
        gl::Context::create_shader(self, kind)
    }
    fn shader_source(&mut self, shader: u32, sources: &[&str]) {
        gl::Context::shader_source(self, shader, sources)
    }
    fn compile_shader(&mut self, shader: u32) {
        gl::Context::compile_shader(self, shader)
    }
    fn get_shader_iv(&mut self, shader: u32, pname: u32, params: &mut [i32]) {
        if let Some(p) = params.first_mut() {
            *p = gl::Context::get_shaderiv(self, shader, pname);
        }
    }
    fn get_shader_info_log(&mut self, shader: u32) -> String {
        gl::Context::get_shader_info_log(self, shader)
    }
    fn delete_shader(&mut self, shader: u32) {
        gl::Context::delete_shader(self, shader)
    }
    fn get_active_uniform_block_iv(&mut self, program: u32, index: u32, pname: u32) -> i32 {
        gl::Context::get_active_uniform_blockiv(self, program, index, pname)
            .and_then(|v| v.first().copied())
            .unwrap_or(0)
    }
    fn uniform_block_binding(&mut self, program: u32, index: u32, binding: u32) {
        gl::Context::uniform_block_binding(self, program, index, binding)
    }
    fn get_uniform_index(&mut self, program: u32, name: &str) -> u32 {
        gl::Context::get_uniform_indices(self, program, &[name])
            .and_then(|v| v.first().copied())
            .unwrap_or(gl::uniform_block::INVALID_INDEX)
    }
    fn get_active_uniform_iv(&mut self, program: u32, index: u32, pname: u32) -> i32 {
        gl::Context::get_active_uniformsiv(self, program, &[index], pname)
            .and_then(|v| v.first().copied())
            .unwrap_or(0)
    }
    fn get_active_uniform(&mut self, program: u32, index: u32) -> Option<(String, i32, u32)> {
        gl::Context::get_active_uniform(self, program, index).map(|i| (i.name, i.size, i.ty))
    }
    fn gen_buffer(&mut self) -> u32 {
        gl::Context::gen_buffers(self, 1)
            .first()
            .copied()
            .unwrap_or(0)
    }
    fn bind_buffer(&mut self, target: u32, buffer: u32) {
        gl::Context::bind_buffer(self, target, buffer)
    }
    fn buffer_data(&mut self, target: u32, data: &[u8], usage: u32) {
        gl::Context::buffer_data(self, target, data.len() as isize, Some(data), usage)
    }
    fn buffer_sub_data(&mut self, target: u32, offset: isize, data: &[u8]) {
        gl::Context::buffer_sub_data(self, target, offset, data)
    }
    fn bind_buffer_base(&mut self, target: u32, index: u32, buffer: u32) {
        gl::Context::bind_buffer_base(self, target, index, buffer)
    }
    fn get_buffer_sub_data(&mut self, target: u32, offset: isize, size: usize) -> Vec<u8> {
        gl::Context::get_buffer_sub_data(self, target, offset, size as isize)
    }
    fn dispatch_compute(&mut self, x: u32, y: u32, z: u32) {
        gl::Context::dispatch_compute(self, x, y, z)
    }
    fn memory_barrier(&mut self, barriers: u32) {
        gl::Context::memory_barrier(self, barriers)
    }
    fn create_program(&mut self) -> u32 {
        gl::Context::create_program(self)
    }
    fn attach_shader(&mut self, program: u32, shader: u32) {
        gl::Context::attach_shader(self, program, shader)
    }
    fn bind_attrib_location(&mut self, program: u32, index: u32, name: &str) {
        gl::Context::bind_attrib_location(self, program, index, name)
    }
    fn link_program(&mut self, program: u32) {
        gl::Context::link_program(self, program)
    }
    fn program_parameter_i(&mut self, program: u32, pname: u32, value: i32) {
        gl::Context::program_parameteri(self, program, pname, value)
    }
    fn get_program_iv(&mut self, program: u32, pname: u32, params: &mut [i32]) {
        if let Some(p) = params.first_mut() {
            *p = gl::Context::get_programiv(self, program, pname);
        }
    }
    fn get_program_info_log(&mut self, program: u32) -> String {
        gl::Context::get_program_info_log(self, program)
    }
    fn use_program(&mut self, program: u32) {
        gl::Context::use_program(self, program)
    }
    fn gen_program_pipeline(&mut self) -> u32 {
        gl::Context::gen_program_pipelines(self, 1)
            .first()
            .copied()
            .unwrap_or(0)
    }
    fn bind_program_pipeline(&mut self, pipeline: u32) {
        gl::Context::bind_program_pipeline(self, pipeline)
    }
    fn use_program_stages(&mut self, pipeline: u32, stages: u32, program: u32) {
        gl::Context::use_program_stages(self, pipeline, stages, program)
    }
    fn active_shader_program(&mut self, pipeline: u32, program: u32) {
        gl::Context::active_shader_program(self, pipeline, program)
    }
    fn get_program_pipeline_iv(&mut self, pipeline: u32, pname: u32) -> i32 {
        gl::Context::get_program_pipelineiv(self, pipeline, pname)
    }
    fn get_uniform_location(&mut self, program: u32, name: &str) -> i32 {
        gl::Context::get_uniform_location(self, program, name)
    }
    fn get_attrib_location(&mut self, program: u32, name: &str) -> i32 {
        gl::Context::get_attrib_location(self, program, name)
    }
    fn uniform_1fv(&mut self, l: i32, c: i32, v: &[f32]) {
        gl::Context::uniform_1fv(self, l, c, v)
    }
    fn uniform_2fv(&mut self, l: i32, c: i32, v: &[f32]) {
        gl::Context::uniform_2fv(self, l, c, v)
    }
    fn uniform_3fv(&mut self, l: i32, c: i32, v: &[f32]) {
        gl::Context::uniform_3fv(self, l, c, v)
    }
    fn uniform_4fv(&mut self, l: i32, c: i32, v: &[f32]) {
        gl::Context::uniform_4fv(self, l, c, v)
    }
    fn uniform_1iv(&mut self, l: i32, c: i32, v: &[i32]) {
        gl::Context::uniform_1iv(self, l, c, v)
    }
    fn uniform_2iv(&mut self, l: i32, c: i32, v: &[i32]) {
        gl::Context::uniform_2iv(self, l, c, v)
    }
    fn uniform_3iv(&mut self, l: i32, c: i32, v: &[i32]) {
        gl::Context::uniform_3iv(self, l, c, v)
    }
    fn uniform_4iv(&mut self, l: i32, c: i32, v: &[i32]) {
        gl::Context::uniform_4iv(self, l, c, v)
    }
    fn uniform_1uiv(&mut self, l: i32, c: i32, v: &[u32]) {
        gl::Context::uniform_1uiv(self, l, c, v)
    }
    fn uniform_2uiv(&mut self, l: i32, c: i32, v: &[u32]) {
        gl::Context::uniform_2uiv(self, l, c, v)
    }
    fn uniform_3uiv(&mut self, l: i32, c: i32, v: &[u32]) {
        gl::Context::uniform_3uiv(self, l, c, v)
    }
    fn uniform_4uiv(&mut self, l: i32, c: i32, v: &[u32]) {
        gl::Context::uniform_4uiv(self, l, c, v)
    }
    fn uniform_matrix_2fv(&mut self, l: i32, c: i32, t: bool, v: &[f32]) {
        gl::Context::uniform_matrix_2fv(self, l, c, t, v)
    }
    fn uniform_matrix_3fv(&mut self, l: i32, c: i32, t: bool, v: &[f32]) {
        gl::Context::uniform_matrix_3fv(self, l, c, t, v)
    }
    fn uniform_matrix_4fv(&mut self, l: i32, c: i32, t: bool, v: &[f32]) {
        gl::Context::uniform_matrix_4fv(self, l, c, t, v)
    }
    fn uniform_matrix_2x3fv(&mut self, l: i32, c: i32, t: bool, v: &[f32]) {
        gl::Context::uniform_matrix_2x3fv(self, l, c, t, v)
    }
    fn uniform_matrix_2x4fv(&mut self, l: i32, c: i32, t: bool, v: &[f32]) {
        gl::Context::uniform_matrix_2x4fv(self, l, c, t, v)
    }
    fn uniform_matrix_3x2fv(&mut self, l: i32, c: i32, t: bool, v: &[f32]) {
        gl::Context::uniform_matrix_3x2fv(self, l, c, t, v)
    }
    fn uniform_matrix_3x4fv(&mut self, l: i32, c: i32, t: bool, v: &[f32]) {
        gl::Context::uniform_matrix_3x4fv(self, l, c, t, v)
    }
    fn uniform_matrix_4x2fv(&mut self, l: i32, c: i32, t: bool, v: &[f32]) {
        gl::Context::uniform_matrix_4x2fv(self, l, c, t, v)
    }
    fn uniform_matrix_4x3fv(&mut self, l: i32, c: i32, t: bool, v: &[f32]) {
        gl::Context::uniform_matrix_4x3fv(self, l, c, t, v)
    }
    fn clear_color(&mut self, r: f32, g: f32, b: f32, a: f32) {
        gl::Context::clear_color(self, r, g, b, a)
    }
    fn clear_depth(&mut self, depth: f64) {
        gl::Context::clear_depth(self, depth)
    }
    fn clear(&mut self, mask: u32) {
        gl::Context::clear(self, mask)
    }
    fn matrix_mode(&mut self, mode: u32) {
        gl::Context::matrix_mode(self, mode)
    }
    fn load_identity(&mut self) {
        gl::Context::load_identity(self)
    }
    fn ortho(&mut self, l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) {
        gl::Context::ortho(self, l, r, b, t, n, f)
    }
    fn frustum(&mut self, l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) {
        gl::Context::frustum(self, l, r, b, t, n, f)
    }
    fn enable(&mut self, cap: u32) {
        gl::Context::enable(self, cap)
    }
    fn disable(&mut self, cap: u32) {
        gl::Context::disable(self, cap)
    }
    fn clear_stencil(&mut self, s: i32) {
        gl::Context::clear_stencil(self, s)
    }
    fn stencil_func(&mut self, func: u32, reference: i32, mask: u32) {
        gl::Context::stencil_func(self, func, reference, mask)
    }
    fn stencil_op(&mut self, fail: u32, zfail: u32, zpass: u32) {
        gl::Context::stencil_op(self, fail, zfail, zpass)
    }
    fn blend_func(&mut self, src: u32, dst: u32) {
        gl::Context::blend_func(self, src, dst)
    }
    fn hint(&mut self, target: u32, mode: u32) {
        gl::Context::hint(self, target, mode)
    }
    fn shade_model(&mut self, mode: u32) {
        gl::Context::shade_model(self, mode)
    }
    fn clip_plane(&mut self, plane: u32, equation: &[f64; 4]) {
        gl::Context::clip_plane(self, plane, equation)
    }
    fn light_f(&mut self, light: u32, pname: u32, param: f32) {
        gl::Context::light(self, light, pname, Param::F(param))
    }
    fn light_fv(&mut self, light: u32, pname: u32, params: &[f32]) {
        gl::Context::light(self, light, pname, Param::Fv(params))
    }
    fn light_i(&mut self, light: u32, pname: u32, param: i32) {
        gl::Context::light(self, light, pname, Param::I(param))
    }
    fn light_iv(&mut self, light: u32, pname: u32, params: &[i32]) {
        gl::Context::light(self, light, pname, Param::Iv(params))
    }
    fn color_4fv(&mut self, v: &[f32; 4]) {
        gl::Context::color_4fv(self, v)
    }
    fn vertex_pointer(&mut self, size: i32, ty: u32, stride: i32, data: &[f32]) {
        gl::Context::vertex_pointer(self, size, ty, stride, ArrayData::from_f32(data))
    }
    fn tex_coord_pointer(&mut self, size: i32, ty: u32, stride: i32, data: &[f32]) {
        gl::Context::tex_coord_pointer(self, size, ty, stride, ArrayData::from_f32(data))
    }
    fn enable_client_state(&mut self, array: u32) {
        gl::Context::enable_client_state(self, array)
    }
    fn disable_client_state(&mut self, array: u32) {
        gl::Context::disable_client_state(self, array)
    }
    fn vertex_attrib_pointer(&mut self, i: u32, s: i32, ty: u32, n: bool, st: i32, d: &[f32]) {
        let data = array_data(self, i, d);
        gl::Context::vertex_attrib_pointer(self, i, s, ty, n, st, data);
        restore_array_buffer(self);
    }
    fn vertex_attrib_i_pointer(&mut self, i: u32, s: i32, ty: u32, st: i32, d: &[f32]) {
        let data = array_data(self, i, d);
        gl::Context::vertex_attrib_i_pointer(self, i, s, ty, st, data);
        restore_array_buffer(self);
    }
    fn enable_vertex_attrib_array(&mut self, index: u32) {
        gl::Context::enable_vertex_attrib_array(self, index)
    }
    fn disable_vertex_attrib_array(&mut self, index: u32) {
        gl::Context::disable_vertex_attrib_array(self, index)
    }
    fn draw_arrays_instanced(&mut self, mode: u32, first: i32, count: i32, instances: i32) {
        gl::Context::draw_arrays_instanced(self, mode, first, count, instances)
    }
    fn polygon_mode(&mut self, face: u32, mode: u32) {
        gl::Context::polygon_mode(self, face, mode)
    }
    fn provoking_vertex(&mut self, mode: u32) {
        gl::Context::provoking_vertex(self, mode)
    }
    fn active_texture(&mut self, unit: u32) {
        gl::Context::active_texture(self, unit)
    }
    fn gen_texture(&mut self) -> u32 {
        gl::Context::gen_textures(self, 1)
            .first()
            .copied()
            .unwrap_or(0)
    }
    fn bind_texture(&mut self, target: u32, texture: u32) {
        gl::Context::bind_texture(self, target, texture)
    }
    fn tex_parameter_i(&mut self, target: u32, pname: u32, param: i32) {
        gl::Context::tex_parameter(self, target, pname, Param::I(param))
    }
    fn tex_parameter_f(&mut self, target: u32, pname: u32, param: f32) {
        gl::Context::tex_parameter(self, target, pname, Param::F(param))
    }
    fn tex_parameter_fv(&mut self, target: u32, pname: u32, params: &[f32]) {
        gl::Context::tex_parameter(self, target, pname, Param::Fv(params))
    }
    fn tex_image_1d(&mut self, t: u32, l: i32, i: i32, w: i32, b: i32, f: u32, ty: u32, p: &[f32]) {
        gl::Context::tex_image(self, t, l, i, [w], b, f, ty, Some(&f32_bytes(p)))
    }
    fn tex_image_2d(
        &mut self,
        t: u32,
        l: i32,
        i: i32,
        w: i32,
        h: i32,
        b: i32,
        f: u32,
        ty: u32,
        p: &[f32],
    ) {
        gl::Context::tex_image(self, t, l, i, [w, h], b, f, ty, Some(&f32_bytes(p)))
    }
    fn tex_image_3d(
        &mut self,
        t: u32,
        l: i32,
        i: i32,
        w: i32,
        h: i32,
        d: i32,
        b: i32,
        f: u32,
        ty: u32,
        p: &[f32],
    ) {
        gl::Context::tex_image(self, t, l, i, [w, h, d], b, f, ty, Some(&f32_bytes(p)))
    }
    fn read_pixels_f32(&mut self, x: i32, y: i32, w: i32, h: i32, f: u32, p: &mut [f32]) {
        let comps = match f {
            gl::enums::GL_RGBA => 4,
            gl::enums::GL_RGB => 3,
            _ => 1, // GL_DEPTH_COMPONENT and single channels
        };
        let n = (w.max(0) as usize) * (h.max(0) as usize) * comps;
        let mut bytes = vec![0u8; n * 4];
        gl::Context::read_pixels(self, x, y, w, h, f, gl::enums::GL_FLOAT, &mut bytes);
        for (o, c) in p.iter_mut().zip(bytes.chunks_exact(4)) {
            *o = f32::from_le_bytes([c[0], c[1], c[2], c[3]]);
        }
    }
    fn read_pixels(&mut self, x: i32, y: i32, w: i32, h: i32, f: u32, ty: u32, p: &mut [u8]) {
        gl::Context::read_pixels(self, x, y, w, h, f, ty, p)
    }
}
