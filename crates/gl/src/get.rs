//! State queries: glGetIntegerv / glGetFloatv / glGetBooleanv /
//! glGetDoublev and glGetString (GL 2.1 §6.1, conversions of §6.1.2).

use crate::enums::*;
use crate::Context;
use glsl::limits;

/// How a queried value converts between the glGet* flavours.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// Integers and enums: floats convert exactly.
    Int,
    /// Floats: integer queries round to nearest.
    Float,
    /// Colors / normals: integer queries map [-1, 1] linearly onto the
    /// integer range (GL 2.1 §6.1.2).
    Normalized,
    Bool,
}

/// The extensions shaderbox implements (and reports).
pub const EXTENSIONS: &[&str] = &[
    "GL_ARB_multitexture",
    "GL_ARB_texture_cube_map",
    "GL_ARB_texture_env_add",
    "GL_ARB_depth_texture",
    "GL_ARB_shadow",
    "GL_ARB_texture_non_power_of_two",
    "GL_ARB_texture_float",
    "GL_ARB_vertex_buffer_object",
    "GL_ARB_shader_objects",
    "GL_ARB_vertex_shader",
    "GL_ARB_fragment_shader",
    "GL_ARB_shading_language_100",
    "GL_ARB_draw_buffers",
    "GL_ARB_point_sprite",
    "GL_ARB_framebuffer_object",
    "GL_EXT_framebuffer_object",
    "GL_EXT_blend_color",
    "GL_EXT_blend_minmax",
    "GL_EXT_blend_subtract",
    "GL_EXT_blend_func_separate",
    "GL_EXT_blend_equation_separate",
    "GL_EXT_stencil_wrap",
    "GL_EXT_texture_lod_bias",
    "GL_EXT_fog_coord",
    "GL_EXT_secondary_color",
    "GL_SGIS_generate_mipmap",
    "GL_EXT_provoking_vertex",
    "GL_ARB_vertex_array_object",
    "GL_ARB_draw_instanced",
    "GL_ARB_instanced_arrays",
    "GL_ARB_draw_elements_base_vertex",
    "GL_ARB_half_float_vertex",
    "GL_ARB_vertex_type_2_10_10_10_rev",
    "GL_ARB_vertex_array_bgra",
    "GL_ARB_map_buffer_range",
    "GL_ARB_copy_buffer",
    "GL_ARB_uniform_buffer_object",
    "GL_ARB_explicit_attrib_location",
    "GL_ARB_texture_rg",
    "GL_EXT_texture_sRGB",
    "GL_ARB_sampler_objects",
    // Needs GLSL 1.20, which every context's newest GLSL version reaches.
    "GL_ARB_arrays_of_arrays",
    // Needs GL 2.0 and GL_ARB_explicit_attrib_location, which every
    // context has; written for 2.1 implementations too (its "Dependencies
    // on GLSL 1.40 and earlier"). Geometry stages are the EXT form's on
    // 2.1, GL 3.2's on 3.3; no context has tessellation stages.
    "GL_ARB_separate_shader_objects",
];

/// The extensions a 3.3 context adds (their GL 3.2–3.3 core features,
/// whose entry points and enums a 2.1 context does not take).
pub const EXTENSIONS_33: &[&str] = &[
    "GL_ARB_sync",
    "GL_ARB_timer_query",
    "GL_ARB_occlusion_query2",
    "GL_ARB_provoking_vertex",
    "GL_ARB_blend_func_extended",
    // Its functions take and return `uint`s: GLSL 1.30 and later, which
    // a 2.1 context's shaders cannot have.
    "GL_ARB_shading_language_packing",
    // Needs GL 3.0 and GLSL 1.30 (its samplers' lookups).
    "GL_ARB_texture_cube_map_array",
    // A language-only extension that needs GLSL 1.30.
    "GL_ARB_shading_language_420pack",
    // GL 4.3's compute stage and storage blocks (`crate::storage`).
    "GL_ARB_compute_shader",
    "GL_ARB_shader_storage_buffer_object",
];

/// One glPixelStore mode of `store` (Table 6.17's pixel storage state).
fn pixel_store_value(store: &crate::pixel_store::PixelStore, pname: u32) -> i64 {
    let v = match pname {
        GL_UNPACK_ALIGNMENT | GL_PACK_ALIGNMENT => store.alignment,
        GL_UNPACK_ROW_LENGTH | GL_PACK_ROW_LENGTH => store.row_length,
        GL_UNPACK_SKIP_ROWS | GL_PACK_SKIP_ROWS => store.skip_rows,
        GL_UNPACK_SKIP_PIXELS | GL_PACK_SKIP_PIXELS => store.skip_pixels,
        GL_UNPACK_IMAGE_HEIGHT | GL_PACK_IMAGE_HEIGHT => store.image_height,
        GL_UNPACK_SKIP_IMAGES | GL_PACK_SKIP_IMAGES => store.skip_images,
        GL_UNPACK_SWAP_BYTES | GL_PACK_SWAP_BYTES => store.swap_bytes as usize,
        _ => store.lsb_first as usize,
    };
    i64::try_from(v).unwrap_or(i64::MAX)
}

fn b(x: bool) -> f64 {
    if x {
        1.0
    } else {
        0.0
    }
}

impl Context {
    /// The 64-bit integer states (GL 3.2-3.3), which glGetInteger64v
    /// returns exactly and glGetIntegerv clamps.
    fn int64_state(&self, pname: u32) -> Option<i64> {
        match pname {
            GL_MAX_SERVER_WAIT_TIMEOUT if self.api.at_least(3, 2) => {
                Some(crate::sync::MAX_SERVER_WAIT_TIMEOUT)
            }
            GL_TIMESTAMP if self.api.at_least(3, 3) => Some(crate::occlusion::timestamp_ns()),
            _ => None,
        }
    }

    fn query(&mut self, pname: u32) -> Option<(Vec<f64>, Kind)> {
        use Kind::*;
        if self.is_removed_state(pname) {
            return None;
        }
        if let Some(v) = self.int64_state(pname) {
            return Some((vec![v as f64], Int));
        }
        let unit = self.st.active_texture as usize;
        let int = |v: &[i64]| Some((v.iter().map(|&x| x as f64).collect(), Int));
        let flt = |v: &[f32]| Some((v.iter().map(|&x| x as f64).collect(), Float));
        let nrm = |v: &[f32]| Some((v.iter().map(|&x| x as f64).collect(), Normalized));
        let st = &self.st;
        let fb = self.objects.draw_framebuffer;
        let api = self.api;
        match pname {
            // The context's version and profile (GL 3.0+ queries).
            GL_MAJOR_VERSION if api.at_least(3, 0) => int(&[api.major as i64]),
            GL_MINOR_VERSION if api.at_least(3, 0) => int(&[api.minor as i64]),
            GL_NUM_EXTENSIONS if api.at_least(3, 0) => int(&[api.extensions().len() as i64]),
            GL_CONTEXT_FLAGS if api.at_least(3, 0) => int(&[0]),
            GL_CONTEXT_PROFILE_MASK if api.at_least(3, 2) => int(&[api.profile_mask() as i64]),
            GL_MAX_LIGHTS => int(&[limits::MAX_LIGHTS as i64]),
            GL_MAX_CLIP_PLANES => int(&[limits::MAX_CLIP_PLANES as i64]),
            GL_MAX_TEXTURE_UNITS => int(&[limits::MAX_TEXTURE_UNITS as i64]),
            GL_MAX_TEXTURE_COORDS => int(&[limits::MAX_TEXTURE_COORDS as i64]),
            GL_MAX_TEXTURE_IMAGE_UNITS => int(&[limits::MAX_TEXTURE_IMAGE_UNITS as i64]),
            GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS => {
                int(&[limits::MAX_VERTEX_TEXTURE_IMAGE_UNITS as i64])
            }
            GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS => {
                int(&[limits::MAX_COMBINED_TEXTURE_IMAGE_UNITS as i64])
            }
            GL_MAX_VERTEX_ATTRIBS => int(&[limits::MAX_VERTEX_ATTRIBS as i64]),
            GL_MAX_VARYING_FLOATS => int(&[limits::MAX_VARYING_FLOATS as i64]),
            // The stage interface limits of GL 3.2 (§6.2, table 6.43).
            GL_MAX_VERTEX_OUTPUT_COMPONENTS if api.at_least(3, 2) => {
                int(&[limits::MAX_VERTEX_OUTPUT_COMPONENTS as i64])
            }
            GL_MAX_FRAGMENT_INPUT_COMPONENTS if api.at_least(3, 2) => {
                int(&[limits::MAX_FRAGMENT_INPUT_COMPONENTS as i64])
            }
            GL_MAX_GEOMETRY_INPUT_COMPONENTS if self.has_geometry_shaders() => {
                int(&[limits::MAX_GEOMETRY_INPUT_COMPONENTS as i64])
            }
            GL_MAX_GEOMETRY_OUTPUT_COMPONENTS if self.has_geometry_shaders() => {
                int(&[limits::MAX_GEOMETRY_OUTPUT_COMPONENTS as i64])
            }
            GL_MAX_GEOMETRY_OUTPUT_VERTICES if self.has_geometry_shaders() => {
                int(&[limits::MAX_GEOMETRY_OUTPUT_VERTICES as i64])
            }
            GL_MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS if self.has_geometry_shaders() => {
                int(&[limits::MAX_GEOMETRY_TOTAL_OUTPUT_COMPONENTS as i64])
            }
            GL_MAX_GEOMETRY_UNIFORM_COMPONENTS if self.has_geometry_shaders() => {
                int(&[limits::MAX_GEOMETRY_UNIFORM_COMPONENTS as i64])
            }
            GL_MAX_GEOMETRY_TEXTURE_IMAGE_UNITS if self.has_geometry_shaders() => {
                int(&[limits::MAX_GEOMETRY_TEXTURE_IMAGE_UNITS as i64])
            }
            GL_MAX_GEOMETRY_VARYING_COMPONENTS_ARB if self.has_geometry_shaders() => {
                int(&[limits::MAX_GEOMETRY_VARYING_COMPONENTS as i64])
            }
            GL_MAX_COMBINED_GEOMETRY_UNIFORM_COMPONENTS if self.has_geometry_shaders() => {
                int(&[crate::uniform_block::combined_components(
                    limits::MAX_GEOMETRY_UNIFORM_COMPONENTS as i64,
                )])
            }
            GL_MAX_VERTEX_UNIFORM_COMPONENTS => {
                int(&[limits::MAX_VERTEX_UNIFORM_COMPONENTS as i64])
            }
            GL_MAX_FRAGMENT_UNIFORM_COMPONENTS => {
                int(&[limits::MAX_FRAGMENT_UNIFORM_COMPONENTS as i64])
            }
            GL_MAX_DRAW_BUFFERS | GL_MAX_COLOR_ATTACHMENTS => {
                int(&[limits::MAX_DRAW_BUFFERS as i64])
            }
            GL_MAX_TEXTURE_SIZE | GL_MAX_CUBE_MAP_TEXTURE_SIZE | GL_MAX_RENDERBUFFER_SIZE => {
                int(&[crate::MAX_TEXTURE_SIZE as i64])
            }
            GL_MAX_3D_TEXTURE_SIZE | GL_MAX_ARRAY_TEXTURE_LAYERS => {
                int(&[crate::MAX_3D_TEXTURE_SIZE.into()])
            }
            GL_MAX_RECTANGLE_TEXTURE_SIZE => int(&[crate::MAX_TEXTURE_SIZE as i64]),
            // The texel offsets the lookups take (GL 3.0 §3.8.8: at least
            // −8 to 7); any integer works.
            GL_MIN_PROGRAM_TEXEL_OFFSET => int(&[glsl::limits::MIN_PROGRAM_TEXEL_OFFSET.into()]),
            GL_MAX_TEXTURE_BUFFER_SIZE => {
                int(&[crate::texture_buffer::MAX_TEXTURE_BUFFER_SIZE as i64])
            }
            GL_TEXTURE_BUFFER_DATA_STORE_BINDING => {
                int(&[self.active_tex_buffer().map_or(0, |b| b.buffer) as i64])
            }
            GL_MAX_PROGRAM_TEXEL_OFFSET => int(&[glsl::limits::MAX_PROGRAM_TEXEL_OFFSET.into()]),
            GL_MAX_VIEWPORT_DIMS => int(&[crate::MAX_TEXTURE_SIZE as i64; 2]),
            GL_MAX_MODELVIEW_STACK_DEPTH
            | GL_MAX_PROJECTION_STACK_DEPTH
            | GL_MAX_TEXTURE_STACK_DEPTH => int(&[crate::MAX_MATRIX_STACK_DEPTH as i64]),
            GL_MAX_ELEMENTS_VERTICES | GL_MAX_ELEMENTS_INDICES => int(&[1 << 20]),
            GL_MAX_ATTRIB_STACK_DEPTH | GL_MAX_CLIENT_ATTRIB_STACK_DEPTH => {
                int(&[crate::attrib_stack::MAX_ATTRIB_STACK_DEPTH as i64])
            }
            GL_ATTRIB_STACK_DEPTH => int(&[self.attrib_stack_depths().0 as i64]),
            GL_CLIENT_ATTRIB_STACK_DEPTH => int(&[self.attrib_stack_depths().1 as i64]),
            GL_MAX_TEXTURE_LOD_BIAS => flt(&[16.0]),
            GL_SUBPIXEL_BITS => int(&[8]),
            GL_NUM_COMPRESSED_TEXTURE_FORMATS => int(&[0]),
            GL_MAX_SAMPLES
            | GL_MAX_COLOR_TEXTURE_SAMPLES
            | GL_MAX_DEPTH_TEXTURE_SAMPLES
            | GL_MAX_INTEGER_SAMPLES => int(&[crate::framebuffer::MAX_SAMPLES as i64]),
            GL_SAMPLE_BUFFERS | GL_SAMPLES => {
                let samples = self.draw_framebuffer_samples() as i64;
                if pname == GL_SAMPLES {
                    int(&[samples])
                } else {
                    int(&[(samples > 0) as i64])
                }
            }
            GL_MAX_SAMPLE_MASK_WORDS if api.at_least(3, 2) => {
                int(&[crate::rasterization::MAX_SAMPLE_MASK_WORDS as i64])
            }
            GL_RED_BITS | GL_GREEN_BITS | GL_BLUE_BITS | GL_ALPHA_BITS | GL_DEPTH_BITS
            | GL_STENCIL_BITS => int(&[self.framebuffer_bits(pname) as i64]),
            GL_DOUBLEBUFFER => Some((vec![1.0], Bool)),
            GL_RGBA_MODE => Some((vec![1.0], Bool)),
            GL_VIEWPORT => int(&self.viewport.map(|x| x as i64)),
            GL_DEPTH_RANGE => nrm(&self.depth_range),
            GL_SCISSOR_BOX => int(&st.scissor.map(|x| x as i64)),
            // GL 3.3 compatibility §6.1.2: clamped when fragment colour
            // clamping is on.
            GL_COLOR_CLEAR_VALUE if st.clamp_fragment_color == GL_TRUE => {
                nrm(&st.clear_color.map(|c| c.clamp(0.0, 1.0)))
            }
            GL_COLOR_CLEAR_VALUE => nrm(&st.clear_color),
            GL_DEPTH_CLEAR_VALUE => nrm(&[st.clear_depth]),
            GL_STENCIL_CLEAR_VALUE => int(&[st.clear_stencil as i64]),
            GL_CURRENT_PROGRAM => int(&[self.current_program_query() as i64]),
            GL_PROGRAM_PIPELINE_BINDING => int(&[self.pipelines.bound as i64]),
            GL_CURRENT_COLOR => nrm(&self.va.color),
            GL_CURRENT_RASTER_POSITION => flt(&self.raster.window),
            GL_CURRENT_RASTER_POSITION_VALID => Some((vec![b(self.raster.valid)], Bool)),
            GL_CURRENT_RASTER_COLOR => nrm(&self.raster.color),
            GL_CURRENT_RASTER_SECONDARY_COLOR => nrm(&self.raster.secondary),
            GL_CURRENT_RASTER_TEXTURE_COORDS => flt(self
                .raster
                .tex
                .get(unit)
                .map_or(&[0.0, 0.0, 0.0, 1.0][..], |t| &t[..])),
            GL_CURRENT_RASTER_DISTANCE => flt(&[self.raster.distance]),
            GL_CURRENT_RASTER_INDEX => flt(&[1.0]),
            GL_CURRENT_SECONDARY_COLOR => nrm(&self.va.secondary),
            GL_CURRENT_NORMAL => nrm(&self.va.normal[..3]),
            GL_CURRENT_TEXTURE_COORDS => {
                flt(self.va.tex.get(unit).map_or(&[0.0; 4][..], |t| &t[..]))
            }
            GL_CURRENT_FOG_COORD => flt(&self.va.fog[..1]),
            GL_MODELVIEW_MATRIX => flt(&self.modelview_matrix()),
            GL_PROJECTION_MATRIX => flt(&self.projection_matrix()),
            GL_TEXTURE_MATRIX => flt(&self.texture_matrix(unit)),
            GL_TRANSPOSE_MODELVIEW_MATRIX => {
                flt(&crate::matrix::transpose(&self.modelview_matrix()))
            }
            GL_TRANSPOSE_PROJECTION_MATRIX => {
                flt(&crate::matrix::transpose(&self.projection_matrix()))
            }
            GL_MODELVIEW_STACK_DEPTH => int(&[self.modelview.len() as i64]),
            GL_PROJECTION_STACK_DEPTH => int(&[self.projection.len() as i64]),
            GL_TEXTURE_STACK_DEPTH => {
                int(&[self.texture_matrix.get(unit).map_or(1, |s| s.len()) as i64])
            }
            GL_MATRIX_MODE => int(&[self.matrix_mode as i64]),
            GL_ACTIVE_TEXTURE => int(&[(GL_TEXTURE0 + st.active_texture) as i64]),
            GL_CLIENT_ACTIVE_TEXTURE => {
                int(&[(GL_TEXTURE0 + self.va.client_active_texture) as i64])
            }
            GL_TEXTURE_BINDING_1D
            | GL_TEXTURE_BINDING_2D
            | GL_TEXTURE_BINDING_3D
            | GL_TEXTURE_BINDING_CUBE_MAP
            | GL_TEXTURE_BINDING_1D_ARRAY
            | GL_TEXTURE_BINDING_2D_ARRAY
            | GL_TEXTURE_BINDING_RECTANGLE
            | GL_TEXTURE_BINDING_BUFFER
            | GL_TEXTURE_BINDING_CUBE_MAP_ARRAY_ARB => {
                let ti = match pname {
                    GL_TEXTURE_BINDING_1D => 0,
                    GL_TEXTURE_BINDING_2D => 1,
                    GL_TEXTURE_BINDING_3D => 2,
                    GL_TEXTURE_BINDING_CUBE_MAP => 3,
                    GL_TEXTURE_BINDING_1D_ARRAY => 4,
                    GL_TEXTURE_BINDING_2D_ARRAY => 5,
                    GL_TEXTURE_BINDING_RECTANGLE => 6,
                    GL_TEXTURE_BINDING_CUBE_MAP_ARRAY_ARB => 10,
                    _ => 7,
                };
                int(&[self.objects.bound.get(unit).map_or(0, |b| b[ti]) as i64])
            }
            GL_CLAMP_READ_COLOR if api.at_least(3, 0) => int(&[st.clamp_read_color as i64]),
            GL_MAX_DUAL_SOURCE_DRAW_BUFFERS if api.at_least(3, 3) => {
                int(&[crate::program_outputs::MAX_DUAL_SOURCE_DRAW_BUFFERS as i64])
            }
            GL_CLAMP_VERTEX_COLOR | GL_CLAMP_FRAGMENT_COLOR
                if api.is_core() || !api.at_least(3, 0) =>
            {
                None
            }
            GL_CLAMP_VERTEX_COLOR => int(&[st.clamp_vertex_color as i64]),
            GL_CLAMP_FRAGMENT_COLOR => int(&[st.clamp_fragment_color as i64]),
            GL_SAMPLER_BINDING => {
                int(&[self.objects.bound_samplers.get(unit).copied().unwrap_or(0) as i64])
            }
            GL_VERTEX_ARRAY_SIZE => int(&[self.va.vertex_array.size as i64]),
            GL_VERTEX_ARRAY_TYPE => int(&[self.va.vertex_array.ty as i64]),
            GL_VERTEX_ARRAY_STRIDE => int(&[self.va.vertex_array.stride as i64]),
            GL_VERTEX_ARRAY_BUFFER_BINDING => int(&[self.va.vertex_array.buffer as i64]),
            GL_NORMAL_ARRAY_TYPE => int(&[self.va.normal_array.ty as i64]),
            GL_NORMAL_ARRAY_STRIDE => int(&[self.va.normal_array.stride as i64]),
            GL_NORMAL_ARRAY_BUFFER_BINDING => int(&[self.va.normal_array.buffer as i64]),
            GL_COLOR_ARRAY_SIZE => int(&[self.va.color_array.size as i64]),
            GL_COLOR_ARRAY_TYPE => int(&[self.va.color_array.ty as i64]),
            GL_COLOR_ARRAY_STRIDE => int(&[self.va.color_array.stride as i64]),
            GL_COLOR_ARRAY_BUFFER_BINDING => int(&[self.va.color_array.buffer as i64]),
            GL_SECONDARY_COLOR_ARRAY_SIZE => int(&[self.va.secondary_array.size as i64]),
            GL_SECONDARY_COLOR_ARRAY_TYPE => int(&[self.va.secondary_array.ty as i64]),
            GL_SECONDARY_COLOR_ARRAY_STRIDE => int(&[self.va.secondary_array.stride as i64]),
            GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING => {
                int(&[self.va.secondary_array.buffer as i64])
            }
            GL_FOG_COORD_ARRAY_TYPE => int(&[self.va.fog_array.ty as i64]),
            GL_FOG_COORD_ARRAY_STRIDE => int(&[self.va.fog_array.stride as i64]),
            GL_FOG_COORD_ARRAY_BUFFER_BINDING => int(&[self.va.fog_array.buffer as i64]),
            GL_TEXTURE_COORD_ARRAY_SIZE
            | GL_TEXTURE_COORD_ARRAY_TYPE
            | GL_TEXTURE_COORD_ARRAY_STRIDE
            | GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING => {
                let a = self
                    .va
                    .tex_arrays
                    .get(self.va.client_active_texture as usize)?;
                int(&[match pname {
                    GL_TEXTURE_COORD_ARRAY_SIZE => a.size as i64,
                    GL_TEXTURE_COORD_ARRAY_TYPE => a.ty as i64,
                    GL_TEXTURE_COORD_ARRAY_STRIDE => a.stride as i64,
                    _ => a.buffer as i64,
                }])
            }
            GL_ARRAY_BUFFER_BINDING => int(&[self.va.array_buffer as i64]),
            GL_VERTEX_ARRAY_BINDING => int(&[self.va.vao as i64]),
            GL_PRIMITIVE_RESTART_INDEX => int(&[self.va.restart_index as i64]),
            GL_ELEMENT_ARRAY_BUFFER_BINDING => int(&[self.va.element_buffer as i64]),
            GL_PIXEL_PACK_BUFFER_BINDING => int(&[self.objects.pack_buffer as i64]),
            GL_PIXEL_UNPACK_BUFFER_BINDING => int(&[self.objects.unpack_buffer as i64]),
            // The GL 3.x targets are their own binding queries, but for the
            // ones named *_BINDING (GL 3.3 Table 6.6, 6.x).
            GL_UNIFORM_BUFFER_BINDING
            | GL_COPY_READ_BUFFER
            | GL_COPY_WRITE_BUFFER
            | GL_TEXTURE_BUFFER
            | GL_TRANSFORM_FEEDBACK_BUFFER_BINDING => int(&[self.bound_buffer(match pname {
                GL_UNIFORM_BUFFER_BINDING => GL_UNIFORM_BUFFER,
                GL_TRANSFORM_FEEDBACK_BUFFER_BINDING => GL_TRANSFORM_FEEDBACK_BUFFER,
                p => p,
            }) as i64]),
            GL_MAX_UNIFORM_BUFFER_BINDINGS => {
                int(&[crate::buffers::MAX_UNIFORM_BUFFER_BINDINGS as i64])
            }
            // GL_ARB_shader_storage_buffer_object and GL_ARB_compute_shader
            // (3.3 contexts).
            GL_SHADER_STORAGE_BUFFER_BINDING if api.at_least(3, 3) => {
                int(&[self.bound_buffer(GL_SHADER_STORAGE_BUFFER) as i64])
            }
            GL_DISPATCH_INDIRECT_BUFFER_BINDING if api.at_least(3, 3) => {
                int(&[self.bound_buffer(GL_DISPATCH_INDIRECT_BUFFER) as i64])
            }
            p if api.at_least(3, 3) && crate::storage::limit(p).is_some() => {
                int(&[crate::storage::limit(p).unwrap_or(0)])
            }
            GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT => {
                int(&[crate::buffers::UNIFORM_BUFFER_OFFSET_ALIGNMENT])
            }
            GL_MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS => {
                int(&[crate::buffers::MAX_TRANSFORM_FEEDBACK_BUFFERS as i64])
            }
            GL_MAX_TRANSFORM_FEEDBACK_INTERLEAVED_COMPONENTS if api.at_least(3, 0) => {
                int(&[crate::transform_feedback::MAX_INTERLEAVED_COMPONENTS as i64])
            }
            GL_MAX_TRANSFORM_FEEDBACK_SEPARATE_COMPONENTS if api.at_least(3, 0) => {
                int(&[crate::transform_feedback::MAX_SEPARATE_COMPONENTS as i64])
            }
            GL_MAX_UNIFORM_BLOCK_SIZE => {
                int(&[crate::uniform_block::MAX_UNIFORM_BLOCK_SIZE as i64])
            }
            GL_MAX_VERTEX_UNIFORM_BLOCKS
            | GL_MAX_GEOMETRY_UNIFORM_BLOCKS
            | GL_MAX_FRAGMENT_UNIFORM_BLOCKS => {
                int(&[crate::uniform_block::MAX_STAGE_UNIFORM_BLOCKS as i64])
            }
            GL_MAX_COMBINED_UNIFORM_BLOCKS => {
                int(&[crate::uniform_block::MAX_COMBINED_UNIFORM_BLOCKS as i64])
            }
            GL_MAX_COMBINED_VERTEX_UNIFORM_COMPONENTS => {
                int(&[crate::uniform_block::combined_components(
                    limits::MAX_VERTEX_UNIFORM_COMPONENTS as i64,
                )])
            }
            GL_MAX_COMBINED_FRAGMENT_UNIFORM_COMPONENTS => {
                int(&[crate::uniform_block::combined_components(
                    limits::MAX_FRAGMENT_UNIFORM_COMPONENTS as i64,
                )])
            }
            GL_FRAMEBUFFER_BINDING => int(&[fb as i64]),
            GL_READ_FRAMEBUFFER_BINDING => int(&[self.objects.read_framebuffer as i64]),
            GL_RENDERBUFFER_BINDING => int(&[self.objects.bound_renderbuffer as i64]),
            GL_BLEND_SRC | GL_BLEND_SRC_RGB => int(&[st.blend_src[0] as i64]),
            GL_BLEND_DST | GL_BLEND_DST_RGB => int(&[st.blend_dst[0] as i64]),
            GL_BLEND_SRC_ALPHA => int(&[st.blend_src[1] as i64]),
            GL_BLEND_DST_ALPHA => int(&[st.blend_dst[1] as i64]),
            GL_BLEND_EQUATION_RGB => int(&[st.blend_eq[0] as i64]),
            GL_BLEND_EQUATION_ALPHA => int(&[st.blend_eq[1] as i64]),
            GL_BLEND_COLOR => nrm(&st.blend_color),
            GL_LOGIC_OP_MODE => int(&[st.logic_op as i64]),
            GL_DEPTH_FUNC => int(&[st.depth_func as i64]),
            GL_DEPTH_WRITEMASK => Some((vec![b(st.depth_mask)], Bool)),
            GL_COLOR_WRITEMASK => Some((st.color_masks[0].iter().map(|&m| b(m)).collect(), Bool)),
            GL_STENCIL_FUNC => int(&[st.stencil[0].func as i64]),
            GL_STENCIL_REF => int(&[st.stencil[0].reference as i64]),
            GL_STENCIL_VALUE_MASK => int(&[st.stencil[0].value_mask as i32 as i64]),
            GL_STENCIL_FAIL => int(&[st.stencil[0].fail as i64]),
            GL_STENCIL_PASS_DEPTH_FAIL => int(&[st.stencil[0].zfail as i64]),
            GL_STENCIL_PASS_DEPTH_PASS => int(&[st.stencil[0].zpass as i64]),
            GL_STENCIL_WRITEMASK => int(&[st.stencil[0].write_mask as i32 as i64]),
            GL_STENCIL_BACK_FUNC => int(&[st.stencil[1].func as i64]),
            GL_STENCIL_BACK_REF => int(&[st.stencil[1].reference as i64]),
            GL_STENCIL_BACK_VALUE_MASK => int(&[st.stencil[1].value_mask as i32 as i64]),
            GL_STENCIL_BACK_FAIL => int(&[st.stencil[1].fail as i64]),
            GL_STENCIL_BACK_PASS_DEPTH_FAIL => int(&[st.stencil[1].zfail as i64]),
            GL_STENCIL_BACK_PASS_DEPTH_PASS => int(&[st.stencil[1].zpass as i64]),
            GL_STENCIL_BACK_WRITEMASK => int(&[st.stencil[1].write_mask as i32 as i64]),
            GL_ALPHA_TEST_FUNC => int(&[st.alpha_func as i64]),
            GL_ALPHA_TEST_REF => nrm(&[st.alpha_ref]),
            GL_CULL_FACE_MODE => int(&[st.cull_face as i64]),
            GL_FRONT_FACE => int(&[st.front_face as i64]),
            GL_POLYGON_MODE => int(&st.polygon_mode.map(|m| m as i64)),
            GL_POLYGON_OFFSET_FACTOR => flt(&st.polygon_offset[..1]),
            GL_POLYGON_OFFSET_UNITS => flt(&st.polygon_offset[1..]),
            GL_SHADE_MODEL => int(&[st.shade_model as i64]),
            GL_PROVOKING_VERTEX if api.at_least(3, 2) => int(&[st.provoking_vertex as i64]),
            // Quads take the provoking vertex of the convention in effect.
            GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION if api.at_least(3, 2) => {
                Some((vec![1.0], Bool))
            }
            GL_POINT_SIZE => flt(&[st.point.size]),
            GL_POINT_SIZE_MIN => flt(&[st.point.size_min]),
            GL_POINT_SIZE_MAX => flt(&[st.point.size_max]),
            GL_POINT_FADE_THRESHOLD_SIZE => flt(&[st.point.fade_threshold]),
            GL_POINT_DISTANCE_ATTENUATION => flt(&st.point.attenuation),
            GL_POINT_SIZE_RANGE | GL_ALIASED_POINT_SIZE_RANGE => {
                flt(&[1.0, crate::state::MAX_POINT_SIZE])
            }
            GL_POINT_SIZE_GRANULARITY | GL_LINE_WIDTH_GRANULARITY => flt(&[0.125]),
            GL_LINE_WIDTH => flt(&[st.line_width]),
            GL_LINE_WIDTH_RANGE | GL_ALIASED_LINE_WIDTH_RANGE => {
                flt(&[1.0, crate::state::MAX_POINT_SIZE])
            }
            GL_UNPACK_ALIGNMENT
            | GL_UNPACK_ROW_LENGTH
            | GL_UNPACK_SKIP_ROWS
            | GL_UNPACK_SKIP_PIXELS
            | GL_UNPACK_IMAGE_HEIGHT
            | GL_UNPACK_SKIP_IMAGES
            | GL_UNPACK_SWAP_BYTES
            | GL_UNPACK_LSB_FIRST => int(&[pixel_store_value(&st.unpack, pname)]),
            GL_PACK_ALIGNMENT | GL_PACK_ROW_LENGTH | GL_PACK_SKIP_ROWS | GL_PACK_SKIP_PIXELS
            | GL_PACK_IMAGE_HEIGHT | GL_PACK_SKIP_IMAGES | GL_PACK_SWAP_BYTES
            | GL_PACK_LSB_FIRST => int(&[pixel_store_value(&st.pack, pname)]),
            GL_FOG_MODE => int(&[st.fog.mode as i64]),
            GL_FOG_DENSITY => flt(&[st.fog.density]),
            GL_FOG_START => flt(&[st.fog.start]),
            GL_FOG_END => flt(&[st.fog.end]),
            GL_FOG_COLOR => nrm(&st.fog.color),
            GL_FOG_COORD_SRC => int(&[st.fog.coord_src as i64]),
            GL_LIGHT_MODEL_AMBIENT => nrm(&st.light_model_ambient),
            GL_LIGHT_MODEL_LOCAL_VIEWER => Some((vec![b(st.light_model_local_viewer)], Bool)),
            GL_LIGHT_MODEL_TWO_SIDE => Some((vec![b(st.light_model_two_side)], Bool)),
            GL_LIGHT_MODEL_COLOR_CONTROL => int(&[st.light_model_color_control as i64]),
            GL_COLOR_MATERIAL_FACE => int(&[st.color_material_face as i64]),
            GL_COLOR_MATERIAL_PARAMETER => int(&[st.color_material_mode as i64]),
            GL_DRAW_BUFFER => {
                let db = if fb == 0 {
                    st.draw_buffers.first().copied()
                } else {
                    self.objects
                        .framebuffers
                        .get(&fb)
                        .and_then(|f| f.draw_buffers.first().copied())
                };
                int(&[db.unwrap_or(GL_NONE) as i64])
            }
            p if (GL_DRAW_BUFFER0..GL_DRAW_BUFFER0 + crate::MAX_DRAW_BUFFERS as u32)
                .contains(&p) =>
            {
                let i = (p - GL_DRAW_BUFFER0) as usize;
                let list = if fb == 0 {
                    st.draw_buffers.clone()
                } else {
                    self.objects
                        .framebuffers
                        .get(&fb)
                        .map(|f| f.draw_buffers.clone())
                        .unwrap_or_default()
                };
                int(&[list.get(i).copied().unwrap_or(GL_NONE) as i64])
            }
            GL_READ_BUFFER => {
                let rb = self.objects.read_framebuffer;
                let v = if rb == 0 {
                    st.read_buffer
                } else {
                    self.objects
                        .framebuffers
                        .get(&rb)
                        .map_or(GL_NONE, |f| f.read_buffer)
                };
                int(&[v as i64])
            }
            _ => {
                // Capabilities are queryable too (GL 2.1 §6.1.1).
                let saved = self.error;
                let on = self.is_enabled(pname);
                if self.error != saved && saved == GL_NO_ERROR {
                    self.error = GL_NO_ERROR;
                    return None;
                }
                Some((vec![b(on)], Bool))
            }
        }
    }

    /// `pname`'s values as glGetInteger64v returns them, and whether
    /// glGetIntegerv saturates them at 32 bits (the 64-bit states and
    /// floats) rather than truncating; GL_INVALID_ENUM and None for a
    /// pname there is no state of.
    fn integer_query(&mut self, pname: u32) -> Option<(Vec<i64>, bool)> {
        if let Some(v) = self.int64_state(pname) {
            return Some((vec![v], true));
        }
        let Some((v, kind)) = self.query(pname) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        let ints = v
            .iter()
            .map(|&x| match kind {
                Kind::Normalized => {
                    let c = x.clamp(-1.0, 1.0);
                    ((c * 4294967295.0 - 1.0) / 2.0).round() as i64
                }
                Kind::Float => x.round() as i64,
                _ => x as i64,
            })
            .collect();
        Some((ints, kind == Kind::Float))
    }

    /// glGetIntegerv.
    pub fn get_integerv(&mut self, pname: u32) -> Vec<i32> {
        let Some((v, saturate)) = self.integer_query(pname) else {
            return Vec::new();
        };
        v.into_iter()
            .map(|x| {
                if saturate {
                    x.clamp(i32::MIN.into(), i32::MAX.into()) as i32
                } else {
                    x as i32
                }
            })
            .collect()
    }

    /// glGetInteger64v (GL 3.2): glGetIntegerv without the 32-bit clamp.
    pub fn get_integer64v(&mut self, pname: u32) -> Vec<i64> {
        self.integer_query(pname).map_or_else(Vec::new, |(v, _)| v)
    }

    /// glGetFloatv.
    pub fn get_floatv(&mut self, pname: u32) -> Vec<f32> {
        match self.query(pname) {
            Some((v, _)) => v.iter().map(|&x| x as f32).collect(),
            None => {
                self.set_error(GL_INVALID_ENUM);
                Vec::new()
            }
        }
    }

    /// glGetDoublev.
    pub fn get_doublev(&mut self, pname: u32) -> Vec<f64> {
        match self.query(pname) {
            Some((v, _)) => v,
            None => {
                self.set_error(GL_INVALID_ENUM);
                Vec::new()
            }
        }
    }

    /// glGetBooleanv (non-zero is true).
    pub fn get_booleanv(&mut self, pname: u32) -> Vec<bool> {
        match self.query(pname) {
            Some((v, _)) => v.iter().map(|&x| x != 0.0).collect(),
            None => {
                self.set_error(GL_INVALID_ENUM);
                Vec::new()
            }
        }
    }

    /// glGetString.
    pub fn get_string(&mut self, name: u32) -> String {
        match name {
            GL_VENDOR => "shaderbox".into(),
            GL_RENDERER => "shaderbox software renderer".into(),
            GL_VERSION => self.api.version_string(),
            GL_SHADING_LANGUAGE_VERSION => self.api.glsl_version_string().into(),
            // The core profile removes the unified extension string (GL 3.3
            // core appendix E.2.2): glGetStringi numbers them instead. Each
            // name is followed by a space, the last one too, as Mesa's and
            // other drivers' strings are: programs print or split the string
            // assuming it (piglit's glinfo writes it one name a line by
            // turning spaces into newlines, and its result line then needs
            // the last one).
            GL_EXTENSIONS if !self.api.is_core() => self
                .api
                .extensions()
                .iter()
                .map(|e| format!("{e} "))
                .collect(),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                String::new()
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn queries() {
        let mut ctx = Context::new(32, 16);
        assert_eq!(ctx.get_integerv(GL_VIEWPORT), vec![0, 0, 32, 16]);
        assert_eq!(ctx.get_integerv(GL_MAX_TEXTURE_COORDS), vec![8]);
        ctx.clear_color(1.0, 0.5, 0.0, 2.0);
        assert_eq!(
            ctx.get_floatv(GL_COLOR_CLEAR_VALUE),
            vec![1.0, 0.5, 0.0, 1.0]
        );
        assert_eq!(ctx.get_integerv(GL_COLOR_CLEAR_VALUE)[0], i32::MAX);
        assert_eq!(ctx.get_booleanv(GL_DEPTH_TEST), vec![false]);
        ctx.enable(GL_DEPTH_TEST);
        assert_eq!(ctx.get_integerv(GL_DEPTH_TEST), vec![1]);
        assert!(ctx.get_integerv(0x1234).is_empty());
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        assert!(ctx.get_string(GL_VERSION).starts_with("2.1"));
        let extensions = ctx.get_string(GL_EXTENSIONS);
        assert!(extensions.contains("GL_EXT_framebuffer_object "));
        assert!(extensions.ends_with(' ') && !extensions.ends_with("  "));
        ctx.translatef(1.0, 2.0, 3.0);
        assert_eq!(
            &ctx.get_floatv(GL_MODELVIEW_MATRIX)[12..15],
            &[1.0, 2.0, 3.0]
        );
    }
}
