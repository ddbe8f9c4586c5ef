//! The server and client attribute stacks: glPushAttrib / glPopAttrib and
//! glPushClientAttrib / glPopClientAttrib (GL 2.1 §6.1.14, the attribute
//! groups of Tables 6.5-6.37).
//!
//! A push saves the whole server (or client) state with its mask; a pop
//! restores only the groups in that mask. Limitations: texture *object*
//! parameters (GL_TEXTURE_BIT's per-texture filters and wraps) and hints
//! (not kept by the context) are not saved; GL_EVAL_BIT, GL_LIST_BIT and
//! GL_ACCUM_BUFFER_BIT have no state here.

use crate::enums::*;
use crate::state::State;
use crate::vertex::VaoArrays;
use crate::{Context, MAX_CLIP_PLANES, MAX_LIGHTS, MAX_TEXTURE_UNITS, MAX_VERTEX_ATTRIBS};

/// GL_MAX_ATTRIB_STACK_DEPTH and GL_MAX_CLIENT_ATTRIB_STACK_DEPTH.
pub const MAX_ATTRIB_STACK_DEPTH: usize = 16;

/// A glPushAttrib entry.
pub(crate) struct ServerAttribs {
    mask: u32,
    st: State,
    viewport: [i32; 4],
    depth_range: [f32; 2],
    clip_planes: [[f32; 4]; MAX_CLIP_PLANES],
    matrix_mode: u32,
    current: [[f32; 4]; 4],
    current_tex: [[f32; 4]; MAX_TEXTURE_UNITS],
    current_generic: [[f32; 4]; MAX_VERTEX_ATTRIBS],
    raster: crate::pixel_path::RasterPos,
    bound_textures: Vec<[u32; crate::objects::TEXTURE_TARGET_COUNT]>,
}

/// A glPushClientAttrib entry.
pub(crate) struct ClientAttribs {
    mask: u32,
    /// The bound vertex array object and its state.
    vao: u32,
    arrays: VaoArrays,
    client_active_texture: u32,
    array_buffer: u32,
    /// Primitive restart: enabled, and the index.
    restart: (bool, u32),
    pack: crate::pixel_store::PixelStore,
    unpack: crate::pixel_store::PixelStore,
    pack_buffer: u32,
    unpack_buffer: u32,
}

/// The attribute group of an enable cap (GL_ENABLE_BIT covers them all).
fn cap_group(cap: u32) -> u32 {
    let light = GL_LIGHT0..GL_LIGHT0 + MAX_LIGHTS as u32;
    let plane = GL_CLIP_PLANE0..GL_CLIP_PLANE0 + MAX_CLIP_PLANES as u32;
    match cap {
        GL_ALPHA_TEST | GL_BLEND | GL_DITHER | GL_COLOR_LOGIC_OP | GL_INDEX_LOGIC_OP => {
            GL_COLOR_BUFFER_BIT
        }
        GL_DEPTH_TEST => GL_DEPTH_BUFFER_BIT,
        GL_FOG => GL_FOG_BIT,
        GL_LIGHTING | GL_COLOR_MATERIAL => GL_LIGHTING_BIT,
        c if light.contains(&c) => GL_LIGHTING_BIT,
        GL_LINE_SMOOTH | GL_LINE_STIPPLE => GL_LINE_BIT,
        GL_POINT_SMOOTH | GL_POINT_SPRITE => GL_POINT_BIT,
        GL_CULL_FACE
        | GL_POLYGON_SMOOTH
        | GL_POLYGON_STIPPLE
        | GL_POLYGON_OFFSET_FILL
        | GL_POLYGON_OFFSET_LINE
        | GL_POLYGON_OFFSET_POINT => GL_POLYGON_BIT,
        GL_SCISSOR_TEST => GL_SCISSOR_BIT,
        GL_STENCIL_TEST => GL_STENCIL_BUFFER_BIT,
        GL_TEXTURE_1D | GL_TEXTURE_2D | GL_TEXTURE_3D | GL_TEXTURE_CUBE_MAP | GL_TEXTURE_GEN_S
        | GL_TEXTURE_GEN_T | GL_TEXTURE_GEN_R | GL_TEXTURE_GEN_Q => GL_TEXTURE_BIT,
        GL_NORMALIZE | GL_RESCALE_NORMAL => GL_TRANSFORM_BIT,
        c if plane.contains(&c) => GL_TRANSFORM_BIT,
        GL_MULTISAMPLE
        | GL_SAMPLE_ALPHA_TO_COVERAGE
        | GL_SAMPLE_ALPHA_TO_ONE
        | GL_SAMPLE_COVERAGE => GL_MULTISAMPLE_BIT,
        _ => 0,
    }
}

/// Copies the fields named from `$old` back into `$st`: the members of an
/// attribute group being popped.
macro_rules! restore {
    ($st:ident, $old:ident, $($field:ident)+) => {
        $($st.$field = $old.$field;)+
    };
}

impl Context {
    /// glPushAttrib.
    pub fn push_attrib(&mut self, mask: u32) {
        if self.reject_in_begin() {
            return;
        }
        if self.attrib_stack.len() >= MAX_ATTRIB_STACK_DEPTH {
            self.set_error(GL_STACK_OVERFLOW);
            return;
        }
        let va = &self.va;
        self.attrib_stack.push(ServerAttribs {
            mask,
            st: self.st.clone(),
            viewport: self.viewport,
            depth_range: self.depth_range,
            clip_planes: self.clip_planes,
            matrix_mode: self.matrix_mode,
            current: [va.color, va.secondary, va.normal, va.fog],
            current_tex: va.tex,
            current_generic: va.generic,
            raster: self.raster.clone(),
            bound_textures: self.objects.bound.clone(),
        });
    }

    /// glPopAttrib: restores the groups of the matching push's mask.
    pub fn pop_attrib(&mut self) {
        if self.reject_in_begin() {
            return;
        }
        let Some(s) = self.attrib_stack.pop() else {
            self.set_error(GL_STACK_UNDERFLOW);
            return;
        };
        let m = s.mask;
        let has = |bit: u32| m & bit != 0;
        let old = s.st;
        let st = &mut self.st;
        // Enables: every cap of a restored group (all for GL_ENABLE_BIT).
        let restored =
            // Primitive restart is vertex-array state (GL 3.3
            // compatibility Table 6.8): glPopClientAttrib's.
            |cap: u32| {
                cap != GL_PRIMITIVE_RESTART
                    && (has(GL_ENABLE_BIT) || (cap_group(cap) != 0 && has(cap_group(cap))))
            };
        st.enabled.retain(|&(cap, _)| !restored(cap));
        st.enabled
            .extend(old.enabled.iter().filter(|&&(cap, _)| restored(cap)));
        if has(GL_COLOR_BUFFER_BIT) {
            restore!(st, old, alpha_func alpha_ref blend_src blend_dst blend_eq blend_color
                logic_op color_masks clear_color);
            st.draw_buffers = old.draw_buffers.clone();
            // GL 3.0 compatibility's colour-buffer group holds glClampColor's
            // fragment and read clamping.
            restore!(st, old, clamp_fragment_color clamp_read_color);
        }
        if has(GL_DEPTH_BUFFER_BIT) {
            restore!(st, old, depth_func depth_mask clear_depth);
        }
        if has(GL_FOG_BIT) {
            st.fog = old.fog;
        }
        if has(GL_LIGHTING_BIT) {
            restore!(st, old, lights material light_model_ambient light_model_local_viewer
                light_model_two_side light_model_color_control color_material_face
                color_material_mode shade_model provoking_vertex clamp_vertex_color);
        }
        if has(GL_LINE_BIT) {
            st.line_width = old.line_width;
        }
        if has(GL_POINT_BIT) {
            st.point = old.point;
            for (e, o) in st.tex_env.iter_mut().zip(old.tex_env.iter()) {
                e.coord_replace = o.coord_replace;
            }
        }
        if has(GL_POLYGON_BIT) {
            restore!(st, old, cull_face front_face polygon_mode polygon_offset);
        }
        if has(GL_SCISSOR_BIT) {
            st.scissor = old.scissor;
        }
        if has(GL_STENCIL_BUFFER_BIT) {
            restore!(st, old, stencil clear_stencil);
        }
        if has(GL_TEXTURE_BIT) {
            st.active_texture = old.active_texture;
            for (e, o) in st.tex_env.iter_mut().zip(old.tex_env.iter()) {
                let keep = e.coord_replace;
                *e = *o;
                e.coord_replace = keep;
            }
            st.tex_gen = old.tex_gen;
            // Bindings of textures deleted since revert to 0.
            let textures = &self.objects.textures;
            self.objects.bound = s
                .bound_textures
                .iter()
                .map(|u| {
                    u.map(|t| {
                        if t == 0 || textures.contains_key(&t) {
                            t
                        } else {
                            0
                        }
                    })
                })
                .collect();
        }
        if has(GL_PIXEL_MODE_BIT) {
            st.read_buffer = old.read_buffer;
        }
        if has(GL_CURRENT_BIT) {
            let [color, secondary, normal, fog] = s.current;
            self.va.color = color;
            self.va.secondary = secondary;
            self.va.normal = normal;
            self.va.fog = fog;
            self.va.tex = s.current_tex;
            self.va.generic = s.current_generic;
            self.raster = s.raster.clone();
        }
        if has(GL_TRANSFORM_BIT) {
            self.matrix_mode = s.matrix_mode;
            self.clip_planes = s.clip_planes;
        }
        if has(GL_VIEWPORT_BIT) {
            self.viewport = s.viewport;
            self.depth_range = s.depth_range;
        }
    }

    /// glPushClientAttrib.
    pub fn push_client_attrib(&mut self, mask: u32) {
        if self.client_attrib_stack.len() >= MAX_ATTRIB_STACK_DEPTH {
            self.set_error(GL_STACK_OVERFLOW);
            return;
        }
        let va = &self.va;
        self.client_attrib_stack.push(ClientAttribs {
            mask,
            vao: va.vao,
            arrays: va.arrays_copy(),
            client_active_texture: va.client_active_texture,
            array_buffer: va.array_buffer,
            restart: (self.st.is_on(GL_PRIMITIVE_RESTART), va.restart_index),
            pack: self.st.pack,
            unpack: self.st.unpack,
            pack_buffer: self.objects.pack_buffer,
            unpack_buffer: self.objects.unpack_buffer,
        });
    }

    /// glPopClientAttrib; returns the mask restored (None: the stack was
    /// empty, GL_STACK_UNDERFLOW).
    pub fn pop_client_attrib(&mut self) -> Option<u32> {
        let Some(s) = self.client_attrib_stack.pop() else {
            self.set_error(GL_STACK_UNDERFLOW);
            return None;
        };
        let live = |b: u32, bufs: &std::collections::BTreeMap<u32, crate::objects::BufferObj>| {
            if b == 0 || bufs.contains_key(&b) {
                b
            } else {
                0
            }
        };
        if s.mask & GL_CLIENT_PIXEL_STORE_BIT != 0 {
            self.st.pack = s.pack;
            self.st.unpack = s.unpack;
            self.objects.pack_buffer = live(s.pack_buffer, &self.objects.buffers);
            self.objects.unpack_buffer = live(s.unpack_buffer, &self.objects.buffers);
        }
        if s.mask & GL_CLIENT_VERTEX_ARRAY_BIT != 0 {
            // The object bound at push time is bound again and gets its
            // arrays back; one deleted since keeps the current binding
            // and state.
            if self.va.bind_vao(s.vao) {
                let mut arrays = s.arrays;
                arrays.element_buffer = live(arrays.element_buffer, &self.objects.buffers);
                self.va.set_arrays(arrays);
            }
            self.va.client_active_texture = s.client_active_texture;
            self.va.array_buffer = live(s.array_buffer, &self.objects.buffers);
            let (restart, index) = s.restart;
            if restart {
                self.st.enabled.insert((GL_PRIMITIVE_RESTART, 0));
            } else {
                self.st.enabled.remove(&(GL_PRIMITIVE_RESTART, 0));
            }
            self.va.restart_index = index;
        }
        Some(s.mask)
    }

    /// GL_ATTRIB_STACK_DEPTH, GL_CLIENT_ATTRIB_STACK_DEPTH.
    pub(crate) fn attrib_stack_depths(&self) -> (usize, usize) {
        (self.attrib_stack.len(), self.client_attrib_stack.len())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pop_restores_only_the_pushed_groups() {
        let mut ctx = Context::new(4, 4);
        ctx.push_attrib(GL_DEPTH_BUFFER_BIT | GL_VIEWPORT_BIT);
        ctx.enable(GL_DEPTH_TEST);
        ctx.enable(GL_BLEND);
        ctx.depth_func(GL_GREATER);
        ctx.clear_color(1.0, 0.0, 0.0, 1.0);
        ctx.viewport(1, 1, 2, 2);
        ctx.pop_attrib();
        assert!(!ctx.is_enabled(GL_DEPTH_TEST));
        assert!(ctx.is_enabled(GL_BLEND));
        assert_eq!(ctx.get_integerv(GL_DEPTH_FUNC), vec![GL_LESS as i32]);
        assert_eq!(
            ctx.get_floatv(GL_COLOR_CLEAR_VALUE),
            vec![1.0, 0.0, 0.0, 1.0]
        );
        assert_eq!(ctx.get_integerv(GL_VIEWPORT), vec![0, 0, 4, 4]);
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.pop_attrib();
        assert_eq!(ctx.get_error(), GL_STACK_UNDERFLOW);
        for _ in 0..MAX_ATTRIB_STACK_DEPTH {
            ctx.push_attrib(GL_ALL_ATTRIB_BITS);
        }
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.push_attrib(GL_ALL_ATTRIB_BITS);
        assert_eq!(ctx.get_error(), GL_STACK_OVERFLOW);
        assert_eq!(ctx.get_integerv(GL_ATTRIB_STACK_DEPTH), vec![16]);
    }

    #[test]
    fn client_pop_restores_arrays_and_alignment() {
        let mut ctx = Context::new(4, 4);
        ctx.push_client_attrib(GL_CLIENT_ALL_ATTRIB_BITS);
        ctx.enable_client_state(GL_VERTEX_ARRAY);
        ctx.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        assert_eq!(ctx.pop_client_attrib(), Some(GL_CLIENT_ALL_ATTRIB_BITS));
        assert!(!ctx.vertex_state().vertex_array.enabled);
        // Primitive restart is client vertex-array state.
        ctx.push_attrib(GL_ALL_ATTRIB_BITS);
        ctx.push_client_attrib(GL_CLIENT_VERTEX_ARRAY_BIT);
        ctx.enable(GL_PRIMITIVE_RESTART);
        ctx.primitive_restart_index(9);
        ctx.pop_attrib();
        assert!(ctx.is_enabled(GL_PRIMITIVE_RESTART));
        ctx.pop_client_attrib();
        assert!(!ctx.is_enabled(GL_PRIMITIVE_RESTART));
        assert_eq!(ctx.get_integerv(GL_PRIMITIVE_RESTART_INDEX), vec![0]);
        assert_eq!(ctx.get_integerv(GL_UNPACK_ALIGNMENT), vec![4]);
        assert_eq!(ctx.pop_client_attrib(), None);
        assert_eq!(ctx.get_error(), GL_STACK_UNDERFLOW);
    }
}
