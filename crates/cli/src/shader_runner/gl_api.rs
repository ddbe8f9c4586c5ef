//! The GL entry points the runner calls, as a trait: the whole surface
//! of GL a `.shader_test` script can reach, one method per entry point
//! under the project's naming rule (`glFooBar4fv` -> `foo_bar_4fv`),
//! implemented for `gl::Context` by forwarding (`gl_context.rs`). It is
//! not a GL implementation: there is none in this crate.
//!
//! Client-side arrays are passed as slices of floats (`stride` in bytes, 0
//! for tightly packed), pixel data of type `GL_FLOAT` likewise.

#[allow(clippy::too_many_arguments)]
pub trait GlApi {
    // Queries.
    fn get_string(&mut self, name: u32) -> String;
    fn get_integer_v(&mut self, pname: u32, params: &mut [i32]);
    fn get_error(&mut self) -> u32;
    /// Why the last draw call failed inside the pipeline (an executor error
    /// such as the loop budget), if it did; cleared by the call.
    fn take_draw_failure(&mut self) -> Option<String>;

    // Shaders and programs.
    fn create_shader(&mut self, kind: u32) -> u32;
    fn shader_source(&mut self, shader: u32, sources: &[&str]);
    fn compile_shader(&mut self, shader: u32);
    fn get_shader_iv(&mut self, shader: u32, pname: u32, params: &mut [i32]);
    fn get_shader_info_log(&mut self, shader: u32) -> String;
    fn delete_shader(&mut self, shader: u32);
    fn create_program(&mut self) -> u32;
    fn attach_shader(&mut self, program: u32, shader: u32);
    fn bind_attrib_location(&mut self, program: u32, index: u32, name: &str);
    fn link_program(&mut self, program: u32);
    /// glProgramParameteriEXT (GL_ARB/EXT_geometry_shader4).
    fn program_parameter_i(&mut self, program: u32, pname: u32, value: i32);
    fn get_program_iv(&mut self, program: u32, pname: u32, params: &mut [i32]);
    fn get_program_info_log(&mut self, program: u32) -> String;
    fn use_program(&mut self, program: u32);
    // Program pipelines (GL_ARB_separate_shader_objects).
    fn gen_program_pipeline(&mut self) -> u32;
    fn bind_program_pipeline(&mut self, pipeline: u32);
    fn use_program_stages(&mut self, pipeline: u32, stages: u32, program: u32);
    fn active_shader_program(&mut self, pipeline: u32, program: u32);
    fn get_program_pipeline_iv(&mut self, pipeline: u32, pname: u32) -> i32;
    fn get_uniform_location(&mut self, program: u32, name: &str) -> i32;
    fn get_attrib_location(&mut self, program: u32, name: &str) -> i32;

    // Uniform blocks and their buffers (GL 3.1).
    fn get_active_uniform_block_iv(&mut self, program: u32, index: u32, pname: u32) -> i32;
    fn uniform_block_binding(&mut self, program: u32, index: u32, binding: u32);
    /// glGetUniformIndices of one name.
    fn get_uniform_index(&mut self, program: u32, name: &str) -> u32;
    /// glGetActiveUniformsiv of one uniform.
    fn get_active_uniform_iv(&mut self, program: u32, index: u32, pname: u32) -> i32;
    /// glGetActiveUniform: name, size, type (None: no such uniform).
    fn get_active_uniform(&mut self, program: u32, index: u32) -> Option<(String, i32, u32)>;
    fn gen_buffer(&mut self) -> u32;
    fn bind_buffer(&mut self, target: u32, buffer: u32);
    fn buffer_data(&mut self, target: u32, data: &[u8], usage: u32);
    fn buffer_sub_data(&mut self, target: u32, offset: isize, data: &[u8]);
    fn bind_buffer_base(&mut self, target: u32, index: u32, buffer: u32);
    fn get_buffer_sub_data(&mut self, target: u32, offset: isize, size: usize) -> Vec<u8>;

    // Compute (GL_ARB_compute_shader).
    fn dispatch_compute(&mut self, x: u32, y: u32, z: u32);
    fn memory_barrier(&mut self, barriers: u32);

    // Uniforms.
    fn uniform_1fv(&mut self, location: i32, count: i32, value: &[f32]);
    fn uniform_2fv(&mut self, location: i32, count: i32, value: &[f32]);
    fn uniform_3fv(&mut self, location: i32, count: i32, value: &[f32]);
    fn uniform_4fv(&mut self, location: i32, count: i32, value: &[f32]);
    fn uniform_1iv(&mut self, location: i32, count: i32, value: &[i32]);
    fn uniform_2iv(&mut self, location: i32, count: i32, value: &[i32]);
    fn uniform_3iv(&mut self, location: i32, count: i32, value: &[i32]);
    fn uniform_4iv(&mut self, location: i32, count: i32, value: &[i32]);
    fn uniform_1uiv(&mut self, location: i32, count: i32, value: &[u32]);
    fn uniform_2uiv(&mut self, location: i32, count: i32, value: &[u32]);
    fn uniform_3uiv(&mut self, location: i32, count: i32, value: &[u32]);
    fn uniform_4uiv(&mut self, location: i32, count: i32, value: &[u32]);
    fn uniform_matrix_2fv(&mut self, location: i32, count: i32, transpose: bool, value: &[f32]);
    fn uniform_matrix_3fv(&mut self, location: i32, count: i32, transpose: bool, value: &[f32]);
    fn uniform_matrix_4fv(&mut self, location: i32, count: i32, transpose: bool, value: &[f32]);
    fn uniform_matrix_2x3fv(&mut self, location: i32, count: i32, transpose: bool, value: &[f32]);
    fn uniform_matrix_2x4fv(&mut self, location: i32, count: i32, transpose: bool, value: &[f32]);
    fn uniform_matrix_3x2fv(&mut self, location: i32, count: i32, transpose: bool, value: &[f32]);
    fn uniform_matrix_3x4fv(&mut self, location: i32, count: i32, transpose: bool, value: &[f32]);
    fn uniform_matrix_4x2fv(&mut self, location: i32, count: i32, transpose: bool, value: &[f32]);
    fn uniform_matrix_4x3fv(&mut self, location: i32, count: i32, transpose: bool, value: &[f32]);

    // Fixed-function state.
    fn clear_color(&mut self, r: f32, g: f32, b: f32, a: f32);
    fn clear_depth(&mut self, depth: f64);
    fn clear(&mut self, mask: u32);
    fn matrix_mode(&mut self, mode: u32);
    fn load_identity(&mut self);
    fn ortho(&mut self, left: f64, right: f64, bottom: f64, top: f64, near: f64, far: f64);
    fn frustum(&mut self, left: f64, right: f64, bottom: f64, top: f64, near: f64, far: f64);
    fn enable(&mut self, cap: u32);
    fn disable(&mut self, cap: u32);
    fn hint(&mut self, target: u32, mode: u32);
    fn blend_func(&mut self, src: u32, dst: u32);
    fn clear_stencil(&mut self, s: i32);
    fn stencil_func(&mut self, func: u32, reference: i32, mask: u32);
    fn stencil_op(&mut self, fail: u32, zfail: u32, zpass: u32);
    fn shade_model(&mut self, mode: u32);
    fn clip_plane(&mut self, plane: u32, equation: &[f64; 4]);
    fn light_f(&mut self, light: u32, pname: u32, param: f32);
    fn light_fv(&mut self, light: u32, pname: u32, params: &[f32]);
    fn light_i(&mut self, light: u32, pname: u32, param: i32);
    fn light_iv(&mut self, light: u32, pname: u32, params: &[i32]);
    fn color_4fv(&mut self, v: &[f32; 4]);

    // Vertex arrays (client memory).
    fn vertex_pointer(&mut self, size: i32, ty: u32, stride: i32, data: &[f32]);
    fn tex_coord_pointer(&mut self, size: i32, ty: u32, stride: i32, data: &[f32]);
    fn enable_client_state(&mut self, array: u32);
    fn disable_client_state(&mut self, array: u32);
    fn vertex_attrib_pointer(
        &mut self,
        index: u32,
        size: i32,
        ty: u32,
        normalized: bool,
        stride: i32,
        data: &[f32],
    );
    /// glVertexAttribIPointer: `data` holds the integers' bits.
    fn vertex_attrib_i_pointer(
        &mut self,
        index: u32,
        size: i32,
        ty: u32,
        stride: i32,
        data: &[f32],
    );
    fn enable_vertex_attrib_array(&mut self, index: u32);
    fn disable_vertex_attrib_array(&mut self, index: u32);
    fn draw_arrays_instanced(&mut self, mode: u32, first: i32, count: i32, instances: i32);
    fn polygon_mode(&mut self, face: u32, mode: u32);
    fn provoking_vertex(&mut self, mode: u32);

    // Textures.
    fn active_texture(&mut self, unit: u32);
    fn gen_texture(&mut self) -> u32;
    fn bind_texture(&mut self, target: u32, texture: u32);
    fn tex_parameter_i(&mut self, target: u32, pname: u32, param: i32);
    fn tex_parameter_f(&mut self, target: u32, pname: u32, param: f32);
    fn tex_parameter_fv(&mut self, target: u32, pname: u32, params: &[f32]);
    fn tex_image_1d(
        &mut self,
        target: u32,
        level: i32,
        internal_format: i32,
        width: i32,
        border: i32,
        format: u32,
        ty: u32,
        pixels: &[f32],
    );
    fn tex_image_2d(
        &mut self,
        target: u32,
        level: i32,
        internal_format: i32,
        width: i32,
        height: i32,
        border: i32,
        format: u32,
        ty: u32,
        pixels: &[f32],
    );
    fn tex_image_3d(
        &mut self,
        target: u32,
        level: i32,
        internal_format: i32,
        width: i32,
        height: i32,
        depth: i32,
        border: i32,
        format: u32,
        ty: u32,
        pixels: &[f32],
    );

    // Read-back.
    fn read_pixels_f32(
        &mut self,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        format: u32,
        pixels: &mut [f32],
    );
    fn read_pixels(
        &mut self,
        x: i32,
        y: i32,
        width: i32,
        height: i32,
        format: u32,
        ty: u32,
        pixels: &mut [u8],
    );
}
