//! The object tables: every buffer, texture, renderbuffer and framebuffer
//! object by name, the bindings that select them, and glGen* name
//! reservation (GL 2.1 §2.9, §3.8.12; EXT/ARB_framebuffer_object).
//!
//! Contract: this module holds the objects' data and the name bookkeeping
//! only. The entry points that create, specify and query each kind live
//! with their job: [`crate::buffers`], [`crate::textures`],
//! [`crate::mipmap`], [`crate::framebuffer`]. A name exists once glGen*
//! reserved it or a bind created it; name 0 is the default texture of each
//! target and the default framebuffer.

use crate::enums::*;
use crate::Context;
use std::collections::BTreeMap;
use std::sync::Arc;

/// A buffer object's store.
#[derive(Clone, Debug, Default)]
pub struct BufferObj {
    pub data: Arc<[u8]>,
    pub usage: u32,
    /// The mapped range, while mapped.
    pub map: Option<BufferMap>,
    /// Bound once: a name glGenBuffers returned is a buffer object only
    /// from its first bind (GL 2.1 §2.9; glIsBuffer is false before).
    pub bound: bool,
}

/// GL_MAX_UNIFORM_BUFFER_BINDINGS (GL 3.3's minimum is 36).
pub const MAX_UNIFORM_BUFFER_BINDINGS: usize = glsl::limits::MAX_UNIFORM_BUFFER_BINDINGS as usize;
/// GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT: glBindBufferRange offsets on
/// GL_UNIFORM_BUFFER are multiples of this (a vec4).
pub const UNIFORM_BUFFER_OFFSET_ALIGNMENT: i64 = 16;
/// GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS (GL_ARB_shader_storage_buffer_object).
pub const MAX_SHADER_STORAGE_BUFFER_BINDINGS: usize =
    glsl::limits::MAX_SHADER_STORAGE_BUFFER_BINDINGS as usize;
/// GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT: a word's (llvmpipe's is
/// 16; any power of two the spec allows up to 256).
pub const SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT: i64 = 4;
/// GL_MAX_TRANSFORM_FEEDBACK_SEPARATE_ATTRIBS (GL 3.0's minimum).
pub const MAX_TRANSFORM_FEEDBACK_BUFFERS: usize = 4;
/// A buffer's mapped range (GL 3.3 Table 2.11).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BufferMap {
    pub offset: usize,
    pub length: usize,
    /// GL_BUFFER_ACCESS_FLAGS: the GL_MAP_*_BIT bits asked for.
    pub access: u32,
}

impl BufferMap {
    /// GL_BUFFER_ACCESS: the GL 1.5 enum the read/write bits stand for.
    pub fn access_enum(&self) -> u32 {
        match self.access & (GL_MAP_READ_BIT | GL_MAP_WRITE_BIT) {
            GL_MAP_READ_BIT => GL_READ_ONLY,
            GL_MAP_WRITE_BIT => GL_WRITE_ONLY,
            _ => GL_READ_WRITE,
        }
    }
}

/// One indexed binding point (GL 3.3 §2.9.1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct IndexedBinding {
    pub buffer: u32,
    pub offset: i64,
    /// The glBindBufferRange size; `None` after glBindBufferBase (the
    /// whole store, whatever its size when it is used).
    pub size: Option<i64>,
}

/// The buffer targets added by GL 3.0–3.1 and the indexed binding points.
#[derive(Clone, Debug)]
pub struct BufferTargets {
    pub uniform: u32,
    pub copy_read: u32,
    pub copy_write: u32,
    pub texture: u32,
    pub transform_feedback: u32,
    pub storage: u32,
    pub dispatch_indirect: u32,
    pub uniform_bindings: [IndexedBinding; MAX_UNIFORM_BUFFER_BINDINGS],
    pub feedback_bindings: [IndexedBinding; MAX_TRANSFORM_FEEDBACK_BUFFERS],
    pub storage_bindings: [IndexedBinding; MAX_SHADER_STORAGE_BUFFER_BINDINGS],
}

impl Default for BufferTargets {
    fn default() -> Self {
        BufferTargets {
            uniform: 0,
            copy_read: 0,
            copy_write: 0,
            texture: 0,
            transform_feedback: 0,
            storage: 0,
            dispatch_indirect: 0,
            uniform_bindings: [IndexedBinding::default(); MAX_UNIFORM_BUFFER_BINDINGS],
            feedback_bindings: [IndexedBinding::default(); MAX_TRANSFORM_FEEDBACK_BUFFERS],
            storage_bindings: [IndexedBinding::default(); MAX_SHADER_STORAGE_BUFFER_BINDINGS],
        }
    }
}

/// One mipmap level (or cube face level) of a texture.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pub width: i32,
    pub height: i32,
    pub depth: i32,
    pub internal_format: u32,
    /// `width * height * depth` texels, row 0 at the bottom (t = 0).
    pub texels: Vec<[f32; 4]>,
}

/// Sampler parameters of a texture object (GL 2.1 Table 6.20 defaults).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexParams {
    pub min_filter: u32,
    pub mag_filter: u32,
    pub wrap: [u32; 3],
    pub border_color: [f32; 4],
    pub min_lod: f32,
    pub max_lod: f32,
    pub base_level: i32,
    pub max_level: i32,
    pub lod_bias: f32,
    pub compare_mode: u32,
    pub compare_func: u32,
    pub depth_mode: u32,
    pub generate_mipmap: bool,
    /// TEXTURE_SWIZZLE_R, _G, _B, _A (GL 3.3 §3.9.8).
    pub swizzle: [u32; 4],
}

impl Default for TexParams {
    fn default() -> Self {
        TexParams {
            min_filter: GL_NEAREST_MIPMAP_LINEAR,
            mag_filter: GL_LINEAR,
            wrap: [GL_REPEAT; 3],
            border_color: [0.0; 4],
            min_lod: -1000.0,
            max_lod: 1000.0,
            base_level: 0,
            max_level: 1000,
            lod_bias: 0.0,
            compare_mode: GL_NONE,
            compare_func: GL_LEQUAL,
            depth_mode: GL_LUMINANCE,
            generate_mipmap: false,
            swizzle: [GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA],
        }
    }
}

/// A texture object.
#[derive(Clone, Debug, Default)]
pub struct TextureObj {
    /// 0 until first bound.
    pub target: u32,
    /// `faces[face][level]`: one face except for cube maps (+X, -X, +Y,
    /// -Y, +Z, -Z).
    pub faces: Vec<Vec<Option<Image>>>,
    pub params: TexParams,
    /// A buffer texture's data store (glTexBuffer).
    pub buffer: Option<TexBuffer>,
    /// A multisample texture's sample count (glTexImage2DMultisample;
    /// one value per texel is kept, as for multisample renderbuffers).
    pub samples: i32,
    /// Bumped on every change (for caches).
    pub generation: u64,
}

/// The buffer object a buffer texture reads and the format of its texels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TexBuffer {
    pub buffer: u32,
    pub internal_format: u32,
}

impl TextureObj {
    pub fn image(&self, face: usize, level: usize) -> Option<&Image> {
        self.faces.get(face)?.get(level)?.as_ref()
    }

    pub fn base_image(&self) -> Option<&Image> {
        self.image(0, self.params.base_level.max(0) as usize)
    }
}

/// A sampler object (GL 3.3 §3.9.2): the sampling half of
/// [`TexParams`]. Only the sampler state of GL 3.3 Table 6.23 is meaningful
/// in `params` (filters, wraps, border colour, LOD range and bias, compare
/// mode and function); the texture-only fields keep their defaults.
#[derive(Clone, Debug, Default)]
pub struct SamplerObj {
    pub params: TexParams,
    /// Bumped on every change (for caches).
    pub generation: u64,
}

/// A renderbuffer object.
#[derive(Clone, Debug, Default)]
pub struct RenderbufferObj {
    pub internal_format: u32,
    pub width: i32,
    pub height: i32,
    /// Contents (kept between draws), RGBA or depth in .0.
    pub texels: Vec<[f32; 4]>,
    pub stencil: Vec<u8>,
    /// GL_RENDERBUFFER_SAMPLES: what glRenderbufferStorageMultisample
    /// asked for, rounded up to a supported count (0: single-sampled).
    pub samples: i32,
}

/// What a framebuffer attachment point refers to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Attachment {
    Texture {
        texture: u32,
        /// Cube face index (0..6) or 0.
        face: u32,
        level: i32,
        /// GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER: the layer of a 3D or
        /// array texture's level that is the attached image (0 otherwise).
        layer: i32,
        /// GL_FRAMEBUFFER_ATTACHMENT_LAYERED: the whole level of a 3D,
        /// cube map or array texture (glFramebufferTexture). With no
        /// geometry stage to choose a layer, drawing goes to layer 0 (the
        /// +X face of a cube map).
        layered: bool,
    },
    Renderbuffer(u32),
}

impl Attachment {
    /// One image of level `level` of `texture`: cube face `face` of a
    /// cube map, layer `layer` of a 3D or array level (each 0 otherwise).
    pub fn texture_image(texture: u32, level: i32, face: u32, layer: i32) -> Attachment {
        Attachment::Texture {
            texture,
            face,
            level,
            layer,
            layered: false,
        }
    }
}

/// Where the 2D image at `layer` of the level image `img` of a texture
/// of `target` lies in `img.texels`: (first texel, width, height). A layer
/// of a 3D, 2D array or cube map array level (a layer-face: face + 6 ·
/// cube) is one `width × height` slice, a layer of a
/// 1D array level one row; other targets have layer 0 only. None for a
/// layer the level does not have.
pub fn layer_span(target: u32, img: &Image, layer: i32) -> Option<(usize, i32, i32)> {
    let (w, h) = (img.width.max(0), img.height.max(0));
    match target {
        GL_TEXTURE_3D
        | GL_TEXTURE_2D_ARRAY
        | GL_TEXTURE_2D_MULTISAMPLE_ARRAY
        | GL_TEXTURE_CUBE_MAP_ARRAY_ARB => (0..img.depth)
            .contains(&layer)
            .then(|| (layer as usize * (w * h) as usize, w, h)),
        GL_TEXTURE_1D_ARRAY => (0..h)
            .contains(&layer)
            .then(|| (layer as usize * w as usize, w, 1)),
        _ => (layer == 0).then_some((0, w, h)),
    }
}

/// A framebuffer object.
#[derive(Clone, Debug)]
pub struct FramebufferObj {
    pub color: [Option<Attachment>; crate::MAX_DRAW_BUFFERS],
    pub depth: Option<Attachment>,
    pub stencil: Option<Attachment>,
    pub draw_buffers: Vec<u32>,
    pub read_buffer: u32,
}

impl FramebufferObj {
    /// Every attachment made: the colour ones in order, then depth, then
    /// stencil.
    pub fn attachments(&self) -> impl Iterator<Item = &Attachment> {
        self.color
            .iter()
            .flatten()
            .chain(self.depth.iter())
            .chain(self.stencil.iter())
    }
}

/// All named objects and their bindings.
pub struct Objects {
    pub buffers: BTreeMap<u32, BufferObj>,
    pub next_buffer: u32,
    pub textures: BTreeMap<u32, TextureObj>,
    pub next_texture: u32,
    /// Default textures (name 0) per target.
    pub default_textures: BTreeMap<u32, TextureObj>,
    /// `bound[unit][target index]` ([`TEXTURE_TARGETS`] order).
    pub bound: Vec<[u32; TEXTURE_TARGET_COUNT]>,
    /// Sampler objects by name (created by glGenSamplers only).
    pub samplers: BTreeMap<u32, SamplerObj>,
    pub next_sampler: u32,
    /// The sampler bound to each texture image unit (0: none, the bound
    /// textures' own parameters apply).
    pub bound_samplers: Vec<u32>,
    pub renderbuffers: BTreeMap<u32, RenderbufferObj>,
    pub next_renderbuffer: u32,
    pub bound_renderbuffer: u32,
    pub framebuffers: BTreeMap<u32, FramebufferObj>,
    pub next_framebuffer: u32,
    pub draw_framebuffer: u32,
    pub read_framebuffer: u32,
    /// GL_PIXEL_PACK_BUFFER / GL_PIXEL_UNPACK_BUFFER bindings (the C layer
    /// moves pixels through them; the context only keeps the names).
    pub pack_buffer: u32,
    pub unpack_buffer: u32,
    /// The GL 3.x buffer targets and indexed binding points.
    pub buffer_targets: BufferTargets,
    /// The proxy image arrays (GL 3.3 §3.8.15), keyed by the target they
    /// stand for: level sizes and internal formats, no texels.
    pub proxies: BTreeMap<u32, TextureObj>,
}

/// Number of texture targets a unit binds.
pub const TEXTURE_TARGET_COUNT: usize = 11;

/// Texture targets in binding-table order.
pub const TEXTURE_TARGETS: [u32; TEXTURE_TARGET_COUNT] = [
    GL_TEXTURE_1D,
    GL_TEXTURE_2D,
    GL_TEXTURE_3D,
    GL_TEXTURE_CUBE_MAP,
    GL_TEXTURE_1D_ARRAY,
    GL_TEXTURE_2D_ARRAY,
    GL_TEXTURE_RECTANGLE,
    GL_TEXTURE_BUFFER,
    GL_TEXTURE_2D_MULTISAMPLE,
    GL_TEXTURE_2D_MULTISAMPLE_ARRAY,
    GL_TEXTURE_CUBE_MAP_ARRAY_ARB,
];

pub fn target_index(target: u32) -> Option<usize> {
    TEXTURE_TARGETS.iter().position(|&t| t == target)
}

impl Objects {
    pub fn new(_w: i32, _h: i32) -> Objects {
        let mut default_textures = BTreeMap::new();
        for t in TEXTURE_TARGETS {
            default_textures.insert(t, TextureObj::new(t));
        }
        Objects {
            buffers: BTreeMap::new(),
            next_buffer: 1,
            textures: BTreeMap::new(),
            next_texture: 1,
            default_textures,
            bound: vec![[0; TEXTURE_TARGET_COUNT]; crate::MAX_TEXTURE_IMAGE_UNITS],
            samplers: BTreeMap::new(),
            next_sampler: 1,
            bound_samplers: vec![0; crate::MAX_TEXTURE_IMAGE_UNITS],
            renderbuffers: BTreeMap::new(),
            next_renderbuffer: 1,
            bound_renderbuffer: 0,
            framebuffers: BTreeMap::new(),
            next_framebuffer: 1,
            draw_framebuffer: 0,
            read_framebuffer: 0,
            pack_buffer: 0,
            unpack_buffer: 0,
            buffer_targets: BufferTargets::default(),
            proxies: BTreeMap::new(),
        }
    }

    /// The texture bound to `target` on `unit` (the default texture for 0).
    pub fn bound_texture(&self, unit: usize, target: u32) -> Option<&TextureObj> {
        let ti = target_index(target)?;
        let name = self.bound.get(unit)?[ti];
        if name == 0 {
            self.default_textures.get(&target)
        } else {
            self.textures.get(&name)
        }
    }

    pub(crate) fn bound_texture_mut(
        &mut self,
        unit: usize,
        target: u32,
    ) -> Option<&mut TextureObj> {
        let ti = target_index(target)?;
        let name = self.bound.get(unit)?[ti];
        if name == 0 {
            self.default_textures.get_mut(&target)
        } else {
            self.textures.get_mut(&name)
        }
    }

    pub fn texture_by_name(&self, name: u32) -> Option<&TextureObj> {
        self.textures.get(&name)
    }

    /// The sampler object bound to `unit`, if any.
    pub fn bound_sampler(&self, unit: usize) -> Option<(u32, &SamplerObj)> {
        let name = *self.bound_samplers.get(unit)?;
        self.samplers.get(&name).map(|s| (name, s))
    }
}

impl TextureObj {
    pub(crate) fn new(target: u32) -> TextureObj {
        let mut t = TextureObj {
            target,
            ..Default::default()
        };
        t.faces = vec![Vec::new(); if target == GL_TEXTURE_CUBE_MAP { 6 } else { 1 }];
        if target == GL_TEXTURE_RECTANGLE {
            // GL 3.1 §3.8.7's initial state of rectangle textures.
            t.params.wrap = [GL_CLAMP_TO_EDGE; 3];
            t.params.min_filter = GL_LINEAR;
        }
        t
    }
}

/// Target of a glTexImage call: (binding target, face).
pub(crate) fn image_target(target: u32, dims: u32) -> Option<(u32, usize)> {
    match (dims, target) {
        (1, GL_TEXTURE_1D) => Some((GL_TEXTURE_1D, 0)),
        (2, GL_TEXTURE_2D) => Some((GL_TEXTURE_2D, 0)),
        (2, GL_TEXTURE_1D_ARRAY) => Some((GL_TEXTURE_1D_ARRAY, 0)),
        (2, GL_TEXTURE_RECTANGLE) => Some((GL_TEXTURE_RECTANGLE, 0)),
        (2, GL_TEXTURE_2D_MULTISAMPLE) => Some((GL_TEXTURE_2D_MULTISAMPLE, 0)),
        (3, GL_TEXTURE_2D_ARRAY) => Some((GL_TEXTURE_2D_ARRAY, 0)),
        (3, GL_TEXTURE_CUBE_MAP_ARRAY_ARB) => Some((GL_TEXTURE_CUBE_MAP_ARRAY_ARB, 0)),
        (2, t)
            if (GL_TEXTURE_CUBE_MAP_POSITIVE_X..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z).contains(&t) =>
        {
            Some((
                GL_TEXTURE_CUBE_MAP,
                (t - GL_TEXTURE_CUBE_MAP_POSITIVE_X) as usize,
            ))
        }
        (3, GL_TEXTURE_3D) => Some((GL_TEXTURE_3D, 0)),
        _ => None,
    }
}

/// The texture target a proxy target of a `dims`-dimensional glTexImage
/// call stands for (GL 3.3 §3.8.15), None for any other target.
pub(crate) fn proxy_target(target: u32, dims: u32) -> Option<u32> {
    match (dims, target) {
        (1, GL_PROXY_TEXTURE_1D) => Some(GL_TEXTURE_1D),
        (2, GL_PROXY_TEXTURE_2D) => Some(GL_TEXTURE_2D),
        (2, GL_PROXY_TEXTURE_1D_ARRAY) => Some(GL_TEXTURE_1D_ARRAY),
        (2, GL_PROXY_TEXTURE_RECTANGLE) => Some(GL_TEXTURE_RECTANGLE),
        (2, GL_PROXY_TEXTURE_CUBE_MAP) => Some(GL_TEXTURE_CUBE_MAP),
        (3, GL_PROXY_TEXTURE_3D) => Some(GL_TEXTURE_3D),
        (3, GL_PROXY_TEXTURE_2D_ARRAY) => Some(GL_TEXTURE_2D_ARRAY),
        (3, GL_PROXY_TEXTURE_CUBE_MAP_ARRAY_ARB) => Some(GL_TEXTURE_CUBE_MAP_ARRAY_ARB),
        _ => None,
    }
}

/// Largest mipmap level index accepted.
pub(crate) const MAX_LEVELS: i32 = 14;

/// Deletes the objects `names` of one table (glDelete*); each binding in
/// `bindings` that names one of them reverts to 0. Name 0 is skipped.
pub(crate) fn delete_names<T>(
    map: &mut BTreeMap<u32, T>,
    names: &[u32],
    bindings: &mut [&mut u32],
) {
    for &name in names.iter().filter(|&&n| n != 0) {
        map.remove(&name);
        for b in bindings.iter_mut().filter(|b| ***b == name) {
            **b = 0;
        }
    }
}

impl Context {
    /// glGen*: reserves `n` names unused in the table `table` picks,
    /// searching upward from its next-name counter and skipping 0, and
    /// creates each object with `make` (GL 2.1 §2.9). A negative `n` is
    /// GL_INVALID_VALUE; at most 65536 names per call.
    pub(crate) fn gen_objects<T>(
        &mut self,
        n: i32,
        table: impl FnOnce(&mut Objects) -> (&mut BTreeMap<u32, T>, &mut u32),
        make: impl Fn() -> T,
    ) -> Vec<u32> {
        if n < 0 {
            self.set_error(GL_INVALID_VALUE);
            return Vec::new();
        }
        let (map, next) = table(&mut self.objects);
        (0..n.min(1 << 16))
            .map(|_| {
                while map.contains_key(next) || *next == 0 {
                    *next = next.wrapping_add(1);
                }
                let name = *next;
                map.insert(name, make());
                *next = next.wrapping_add(1);
                name
            })
            .collect()
    }
}

impl FramebufferObj {
    pub(crate) fn new() -> FramebufferObj {
        FramebufferObj::default()
    }
}

impl Default for FramebufferObj {
    fn default() -> Self {
        FramebufferObj {
            color: [None; crate::MAX_DRAW_BUFFERS],
            depth: None,
            stencil: None,
            draw_buffers: vec![GL_COLOR_ATTACHMENT0],
            read_buffer: GL_COLOR_ATTACHMENT0,
        }
    }
}

/// Stores `img` as level `level` of face `face` (growing the tables) and
/// bumps the texture's generation.
/// Makes image `level` of `face` undefined.
pub(crate) fn clear_image(tex: &mut TextureObj, face: usize, level: usize) {
    if let Some(slot) = tex.faces.get_mut(face).and_then(|f| f.get_mut(level)) {
        *slot = None;
        tex.generation += 1;
    }
}

pub(crate) fn set_image(tex: &mut TextureObj, face: usize, level: usize, img: Image) {
    if tex.faces.len() <= face {
        tex.faces.resize(face + 1, Vec::new());
    }
    let f = &mut tex.faces[face];
    if f.len() <= level {
        f.resize(level + 1, None);
    }
    f[level] = Some(img);
    tex.generation += 1;
}
