//! Buffer, texture, renderbuffer and framebuffer objects (GL 2.1 §2.9,
//! §3.8; EXT_framebuffer_object / ARB_framebuffer_object).
//!
//! Texture images are stored as RGBA `f32` texels in the form sampling
//! returns them (GL 2.1 Table 3.20: LUMINANCE → (L, L, L, 1), ALPHA →
//! (0, 0, 0, A), INTENSITY → (I, I, I, I)...), quantized to the internal
//! format's precision (8 bits per component for the unsized and `*8`
//! formats, 16 for `*16`, none for float formats). Depth images keep the
//! depth in every color component and alpha 1.

use crate::enums::*;
use crate::{Context, MAX_TEXTURE_SIZE};
use std::collections::BTreeMap;
use std::sync::Arc;

/// A buffer object's store.
#[derive(Clone, Debug, Default)]
pub struct BufferObj {
    pub data: Arc<[u8]>,
    pub usage: u32,
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
    /// Bumped on every change (for caches).
    pub generation: u64,
}

impl TextureObj {
    pub fn image(&self, face: usize, level: usize) -> Option<&Image> {
        self.faces.get(face)?.get(level)?.as_ref()
    }

    pub fn base_image(&self) -> Option<&Image> {
        self.image(0, self.params.base_level.max(0) as usize)
    }
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
}

/// What a framebuffer attachment point refers to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Attachment {
    Texture {
        texture: u32,
        /// Cube face index (0..6) or 0.
        face: u32,
        level: i32,
        zoffset: i32,
    },
    Renderbuffer(u32),
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

/// All named objects and their bindings.
pub struct Objects {
    pub buffers: BTreeMap<u32, BufferObj>,
    pub next_buffer: u32,
    pub textures: BTreeMap<u32, TextureObj>,
    pub next_texture: u32,
    /// Default textures (name 0) per target.
    pub default_textures: BTreeMap<u32, TextureObj>,
    /// `bound[unit][target index]`.
    pub bound: Vec<[u32; 4]>,
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
}

/// Texture targets in binding-table order.
pub const TEXTURE_TARGETS: [u32; 4] = [
    GL_TEXTURE_1D,
    GL_TEXTURE_2D,
    GL_TEXTURE_3D,
    GL_TEXTURE_CUBE_MAP,
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
            bound: vec![[0; 4]; crate::MAX_TEXTURE_IMAGE_UNITS],
            renderbuffers: BTreeMap::new(),
            next_renderbuffer: 1,
            bound_renderbuffer: 0,
            framebuffers: BTreeMap::new(),
            next_framebuffer: 1,
            draw_framebuffer: 0,
            read_framebuffer: 0,
            pack_buffer: 0,
            unpack_buffer: 0,
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

    fn bound_texture_mut(&mut self, unit: usize, target: u32) -> Option<&mut TextureObj> {
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
}

impl TextureObj {
    fn new(target: u32) -> TextureObj {
        let mut t = TextureObj {
            target,
            ..Default::default()
        };
        t.faces = vec![Vec::new(); if target == GL_TEXTURE_CUBE_MAP { 6 } else { 1 }];
        t
    }
}

/// The base internal format (GL 2.1 Table 3.15/3.16) of an internal format.
pub fn base_format(internal: i32) -> Option<u32> {
    let f = internal as u32;
    Some(match f {
        1 | GL_LUMINANCE | GL_LUMINANCE4 | GL_LUMINANCE8 | GL_LUMINANCE12 | GL_LUMINANCE16
        | GL_LUMINANCE32F_ARB | GL_LUMINANCE16F_ARB | GL_SLUMINANCE | GL_SLUMINANCE8 => {
            GL_LUMINANCE
        }
        2
        | GL_LUMINANCE_ALPHA
        | GL_LUMINANCE4_ALPHA4
        | GL_LUMINANCE6_ALPHA2
        | GL_LUMINANCE8_ALPHA8
        | GL_LUMINANCE12_ALPHA4
        | GL_LUMINANCE12_ALPHA12
        | GL_LUMINANCE16_ALPHA16
        | GL_LUMINANCE_ALPHA32F_ARB
        | GL_LUMINANCE_ALPHA16F_ARB
        | GL_SLUMINANCE_ALPHA
        | GL_SLUMINANCE8_ALPHA8 => GL_LUMINANCE_ALPHA,
        3 | GL_RGB | GL_R3_G3_B2 | GL_RGB4 | GL_RGB5 | GL_RGB8 | GL_RGB10 | GL_RGB12 | GL_RGB16
        | GL_RGB32F | GL_RGB16F | GL_SRGB | GL_SRGB8 => GL_RGB,
        4 | GL_RGBA | GL_RGBA2 | GL_RGBA4 | GL_RGB5_A1 | GL_RGBA8 | GL_RGB10_A2 | GL_RGBA12
        | GL_RGBA16 | GL_RGBA32F | GL_RGBA16F | GL_SRGB_ALPHA | GL_SRGB8_ALPHA8 => GL_RGBA,
        GL_ALPHA | GL_ALPHA4 | GL_ALPHA8 | GL_ALPHA12 | GL_ALPHA16 | GL_ALPHA32F_ARB
        | GL_ALPHA16F_ARB => GL_ALPHA,
        GL_INTENSITY | GL_INTENSITY4 | GL_INTENSITY8 | GL_INTENSITY12 | GL_INTENSITY16
        | GL_INTENSITY32F_ARB | GL_INTENSITY16F_ARB => GL_INTENSITY,
        GL_RED | GL_R8 | GL_R16 | GL_R16F | GL_R32F => GL_RED,
        GL_RG | GL_RG8 | GL_RG16 | GL_RG16F | GL_RG32F => GL_RG,
        GL_DEPTH_COMPONENT
        | GL_DEPTH_COMPONENT16
        | GL_DEPTH_COMPONENT24
        | GL_DEPTH_COMPONENT32
        | GL_DEPTH_COMPONENT32F => GL_DEPTH_COMPONENT,
        GL_DEPTH_STENCIL | GL_DEPTH24_STENCIL8 | GL_DEPTH32F_STENCIL8 => GL_DEPTH_STENCIL,
        _ => return None,
    })
}

/// Quantization of an internal format: `Some(bits)` for normalized fixed
/// point, `None` for float formats.
fn format_bits(internal: i32) -> Option<u32> {
    let f = internal as u32;
    match f {
        GL_RGBA32F
        | GL_RGB32F
        | GL_RGBA16F
        | GL_RGB16F
        | GL_ALPHA32F_ARB
        | GL_ALPHA16F_ARB
        | GL_LUMINANCE32F_ARB
        | GL_LUMINANCE16F_ARB
        | GL_LUMINANCE_ALPHA32F_ARB
        | GL_LUMINANCE_ALPHA16F_ARB
        | GL_INTENSITY32F_ARB
        | GL_INTENSITY16F_ARB
        | GL_R16F
        | GL_R32F
        | GL_RG16F
        | GL_RG32F
        | GL_DEPTH_COMPONENT32F
        | GL_DEPTH32F_STENCIL8 => None,
        GL_RGBA16
        | GL_RGB16
        | GL_ALPHA16
        | GL_LUMINANCE16
        | GL_LUMINANCE16_ALPHA16
        | GL_INTENSITY16
        | GL_R16
        | GL_RG16
        | GL_DEPTH_COMPONENT16 => Some(16),
        GL_DEPTH_COMPONENT | GL_DEPTH_COMPONENT24 | GL_DEPTH24_STENCIL8 | GL_DEPTH_STENCIL => {
            Some(24)
        }
        GL_DEPTH_COMPONENT32 => None,
        _ => Some(8),
    }
}

/// True for formats whose texels are not clamped to [0, 1].
pub fn is_float_format(internal: i32) -> bool {
    format_bits(internal).is_none() && base_format(internal) != Some(GL_DEPTH_COMPONENT)
}

fn quantize(x: f32, bits: Option<u32>) -> f32 {
    match bits {
        None => x,
        Some(b) => {
            let x = if x > 0.0 { x.min(1.0) } else { 0.0 };
            let max = ((1u64 << b) - 1) as f64;
            ((x as f64 * max + 0.5).floor() / max) as f32
        }
    }
}

/// Components per pixel of a client format.
pub fn format_components(format: u32) -> Option<usize> {
    Some(match format {
        GL_RED | GL_GREEN | GL_BLUE | GL_ALPHA | GL_LUMINANCE | GL_DEPTH_COMPONENT
        | GL_STENCIL_INDEX | GL_COLOR_INDEX => 1,
        GL_LUMINANCE_ALPHA | GL_RG | GL_DEPTH_STENCIL => 2,
        GL_RGB | GL_BGR => 3,
        GL_RGBA | GL_BGRA => 4,
        _ => return None,
    })
}

/// Bytes per pixel and per component of a client format/type pair (packed
/// types count as one component), or `None` if the pair is invalid.
pub fn pixel_size(format: u32, ty: u32) -> Option<(usize, usize)> {
    let n = format_components(format)?;
    let packed = |comps: usize, bytes: usize| (n == comps).then_some((bytes, bytes));
    match ty {
        GL_UNSIGNED_BYTE | GL_BYTE => Some((n, 1)),
        GL_UNSIGNED_SHORT | GL_SHORT | GL_HALF_FLOAT => Some((2 * n, 2)),
        GL_UNSIGNED_INT | GL_INT | GL_FLOAT => Some((4 * n, 4)),
        GL_UNSIGNED_INT_8_8_8_8 | GL_UNSIGNED_INT_8_8_8_8_REV | GL_UNSIGNED_INT_2_10_10_10_REV => {
            packed(4, 4)
        }
        GL_UNSIGNED_INT_24_8 => (format == GL_DEPTH_STENCIL).then_some((4, 4)),
        GL_UNSIGNED_SHORT_5_6_5 | GL_UNSIGNED_SHORT_5_6_5_REV => packed(3, 2),
        GL_UNSIGNED_SHORT_4_4_4_4
        | GL_UNSIGNED_SHORT_4_4_4_4_REV
        | GL_UNSIGNED_SHORT_5_5_5_1
        | GL_UNSIGNED_SHORT_1_5_5_5_REV => packed(4, 2),
        _ => None,
    }
}

/// Row stride in bytes under an alignment (GL 2.1 §3.6.4, Unpacking).
pub fn row_stride(width: usize, format: u32, ty: u32, alignment: usize) -> usize {
    let Some((px, comp)) = pixel_size(format, ty) else {
        return 0;
    };
    let raw = px.saturating_mul(width);
    let a = alignment.max(1);
    if comp >= a {
        raw
    } else {
        raw.div_ceil(a).saturating_mul(a)
    }
}

fn half_to_f32(h: u16) -> f32 {
    let sign = if h & 0x8000 != 0 { -1.0f32 } else { 1.0 };
    let e = ((h >> 10) & 0x1f) as i32;
    let m = (h & 0x3ff) as f32;
    let v = match e {
        0 => m * (2.0f32).powi(-24),
        31 => {
            if m == 0.0 {
                f32::INFINITY
            } else {
                f32::NAN
            }
        }
        _ => (1.0 + m / 1024.0) * (2.0f32).powi(e - 15),
    };
    sign * v
}

/// Decodes one pixel of client data into component values (before the
/// format's conversion to RGBA).
fn decode_pixel(b: &[u8], n: usize, ty: u32) -> [f32; 4] {
    let mut out = [0.0f32; 4];
    let rd = |i: usize, s: usize| -> u32 {
        let mut v = [0u8; 4];
        if let Some(src) = b.get(i * s..i * s + s) {
            v[..s].copy_from_slice(src);
        }
        u32::from_le_bytes(v)
    };
    let unpack = |word: u32, shifts: [(u32, u32); 4]| -> [f32; 4] {
        shifts.map(|(shift, bits)| {
            let max = (1u32 << bits) - 1;
            ((word >> shift) & max) as f32 / max as f32
        })
    };
    match ty {
        GL_UNSIGNED_BYTE => (0..n).for_each(|i| out[i] = rd(i, 1) as f32 / 255.0),
        GL_BYTE => (0..n).for_each(|i| out[i] = ((rd(i, 1) as u8 as i8) as f32 / 127.0).max(-1.0)),
        GL_UNSIGNED_SHORT => (0..n).for_each(|i| out[i] = rd(i, 2) as f32 / 65535.0),
        GL_SHORT => {
            (0..n).for_each(|i| out[i] = ((rd(i, 2) as u16 as i16) as f32 / 32767.0).max(-1.0))
        }
        GL_UNSIGNED_INT => (0..n).for_each(|i| out[i] = (rd(i, 4) as f64 / 4294967295.0) as f32),
        GL_INT => {
            (0..n).for_each(|i| out[i] = ((rd(i, 4) as i32) as f64 / 2147483647.0).max(-1.0) as f32)
        }
        GL_FLOAT => (0..n).for_each(|i| out[i] = f32::from_bits(rd(i, 4))),
        GL_HALF_FLOAT => (0..n).for_each(|i| out[i] = half_to_f32(rd(i, 2) as u16)),
        GL_UNSIGNED_INT_8_8_8_8 => out = unpack(rd(0, 4), [(24, 8), (16, 8), (8, 8), (0, 8)]),
        GL_UNSIGNED_INT_8_8_8_8_REV => out = unpack(rd(0, 4), [(0, 8), (8, 8), (16, 8), (24, 8)]),
        GL_UNSIGNED_INT_2_10_10_10_REV => {
            out = unpack(rd(0, 4), [(0, 10), (10, 10), (20, 10), (30, 2)])
        }
        GL_UNSIGNED_INT_24_8 => out[0] = (rd(0, 4) >> 8) as f32 / 16777215.0,
        GL_UNSIGNED_SHORT_5_6_5 => {
            let v = unpack(rd(0, 2), [(11, 5), (5, 6), (0, 5), (0, 1)]);
            out = [v[0], v[1], v[2], 0.0];
        }
        GL_UNSIGNED_SHORT_5_6_5_REV => {
            let v = unpack(rd(0, 2), [(0, 5), (5, 6), (11, 5), (0, 1)]);
            out = [v[0], v[1], v[2], 0.0];
        }
        GL_UNSIGNED_SHORT_4_4_4_4 => out = unpack(rd(0, 2), [(12, 4), (8, 4), (4, 4), (0, 4)]),
        GL_UNSIGNED_SHORT_4_4_4_4_REV => out = unpack(rd(0, 2), [(0, 4), (4, 4), (8, 4), (12, 4)]),
        GL_UNSIGNED_SHORT_5_5_5_1 => out = unpack(rd(0, 2), [(11, 5), (6, 5), (1, 5), (0, 1)]),
        GL_UNSIGNED_SHORT_1_5_5_5_REV => out = unpack(rd(0, 2), [(0, 5), (5, 5), (10, 5), (15, 1)]),
        _ => {}
    }
    out
}

/// Client pixel components to RGBA (GL 2.1 §3.6.4, "Conversion to RGB"):
/// missing color components are 0, missing alpha 1; luminance goes to red.
fn to_rgba(c: [f32; 4], format: u32) -> [f32; 4] {
    match format {
        GL_RED | GL_LUMINANCE | GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL => [c[0], 0.0, 0.0, 1.0],
        GL_GREEN => [0.0, c[0], 0.0, 1.0],
        GL_BLUE => [0.0, 0.0, c[0], 1.0],
        GL_ALPHA => [0.0, 0.0, 0.0, c[0]],
        GL_LUMINANCE_ALPHA => [c[0], 0.0, 0.0, c[1]],
        GL_RG => [c[0], c[1], 0.0, 1.0],
        GL_RGB => [c[0], c[1], c[2], 1.0],
        GL_BGR => [c[2], c[1], c[0], 1.0],
        GL_BGRA => [c[2], c[1], c[0], c[3]],
        _ => c,
    }
}

/// RGBA to the texel sampling returns for a base internal format (GL 2.1
/// Table 3.20), quantized.
pub fn texel_for(rgba: [f32; 4], internal: i32) -> [f32; 4] {
    let bits = format_bits(internal);
    let q = |x: f32| quantize(x, bits);
    let [r, g, b, a] = rgba;
    match base_format(internal).unwrap_or(GL_RGBA) {
        GL_ALPHA => [0.0, 0.0, 0.0, q(a)],
        GL_LUMINANCE => [q(r), q(r), q(r), 1.0],
        GL_LUMINANCE_ALPHA => [q(r), q(r), q(r), q(a)],
        GL_INTENSITY => [q(r); 4],
        GL_RED => [q(r), 0.0, 0.0, 1.0],
        GL_RG => [q(r), q(g), 0.0, 1.0],
        GL_RGB => [q(r), q(g), q(b), 1.0],
        GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL => {
            // Depth is always clamped to [0, 1] (GL 2.1 §3.8.1).
            let d = quantize(r, bits);
            let d = if d.is_nan() { 0.0 } else { d.clamp(0.0, 1.0) };
            [d, d, d, 1.0]
        }
        _ => [q(r), q(g), q(b), q(a)],
    }
}

/// Unpacks `w * h` client pixels of `format`/`ty` (rows at `alignment`,
/// bottom row first) into RGBA values before any texture-format
/// conversion (GL 2.1 §3.6.4 "Conversion to RGB": missing color
/// components 0, missing alpha 1, luminance L to (L, L, L); depth and
/// stencil values in red).
pub fn unpack_rgba(
    data: &[u8],
    w: usize,
    h: usize,
    format: u32,
    ty: u32,
    alignment: usize,
) -> Vec<[f32; 4]> {
    let (px, _) = pixel_size(format, ty).unwrap_or((4, 1));
    let n = format_components(format).unwrap_or(4);
    let stride = row_stride(w, format, ty, alignment);
    let mut out = Vec::with_capacity(w.saturating_mul(h).min(1 << 24));
    for y in 0..h {
        let row = y.saturating_mul(stride);
        for x in 0..w {
            let at = row.saturating_add(x * px);
            let b = data.get(at..at.saturating_add(px)).unwrap_or(&[]);
            let c = to_rgba(decode_pixel(b, n, ty), format);
            out.push(match format {
                // Conversion to RGB: L becomes (L, L, L).
                GL_LUMINANCE | GL_LUMINANCE_ALPHA => [c[0], c[0], c[0], c[3]],
                _ => c,
            });
        }
    }
    out
}

/// Unpacks a client image into texels for `internal`.
#[allow(clippy::too_many_arguments)]
pub fn unpack_image(
    data: Option<&[u8]>,
    w: usize,
    h: usize,
    d: usize,
    format: u32,
    ty: u32,
    internal: i32,
    alignment: usize,
) -> Vec<[f32; 4]> {
    let len = w.saturating_mul(h).saturating_mul(d);
    let Some(data) = data else {
        return vec![texel_for([0.0; 4], internal); len];
    };
    let (px, _) = pixel_size(format, ty).unwrap_or((4, 1));
    let n = format_components(format).unwrap_or(4);
    let stride = row_stride(w, format, ty, alignment);
    let mut out = Vec::with_capacity(len);
    for z in 0..d {
        for y in 0..h {
            let row = (z * h + y).saturating_mul(stride);
            for x in 0..w {
                let at = row.saturating_add(x * px);
                let b = data.get(at..at.saturating_add(px)).unwrap_or(&[]);
                let c = decode_pixel(b, n, ty);
                out.push(texel_for(to_rgba(c, format), internal));
            }
        }
    }
    out
}

fn valid_filter(f: u32, min: bool) -> bool {
    matches!(f, GL_NEAREST | GL_LINEAR)
        || (min
            && matches!(
                f,
                GL_NEAREST_MIPMAP_NEAREST
                    | GL_LINEAR_MIPMAP_NEAREST
                    | GL_NEAREST_MIPMAP_LINEAR
                    | GL_LINEAR_MIPMAP_LINEAR
            ))
}

/// Target of a glTexImage call: (binding target, face).
fn image_target(target: u32, dims: u32) -> Option<(u32, usize)> {
    match (dims, target) {
        (1, GL_TEXTURE_1D) => Some((GL_TEXTURE_1D, 0)),
        (2, GL_TEXTURE_2D) => Some((GL_TEXTURE_2D, 0)),
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

/// Largest mipmap level index accepted.
const MAX_LEVELS: i32 = 14;

/// Reserves `n` names unused in `map`, searching upward from `*next` and
/// skipping 0, and creates each object with `make` (glGen*, GL 2.1 §2.9).
fn gen_names<T>(
    map: &mut BTreeMap<u32, T>,
    next: &mut u32,
    n: usize,
    make: impl Fn() -> T,
) -> Vec<u32> {
    (0..n)
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

impl Context {
    /// The count of a glGen* call: negative is GL_INVALID_VALUE; at most
    /// 65536 names per call.
    fn gen_count(&mut self, n: i32) -> Option<usize> {
        if n < 0 {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        Some(n.min(1 << 16) as usize)
    }

    // ---- buffers ----

    /// glGenBuffers.
    pub fn gen_buffers(&mut self, n: i32) -> Vec<u32> {
        let Some(n) = self.gen_count(n) else {
            return Vec::new();
        };
        let o = &mut self.objects;
        gen_names(&mut o.buffers, &mut o.next_buffer, n, BufferObj::default)
    }

    /// glDeleteBuffers (unbinds them).
    pub fn delete_buffers(&mut self, names: &[u32]) {
        for &b in names {
            if b == 0 {
                continue;
            }
            self.objects.buffers.remove(&b);
            if self.va.array_buffer == b {
                self.va.array_buffer = 0;
            }
            if self.va.element_buffer == b {
                self.va.element_buffer = 0;
            }
            if self.objects.pack_buffer == b {
                self.objects.pack_buffer = 0;
            }
            if self.objects.unpack_buffer == b {
                self.objects.unpack_buffer = 0;
            }
        }
    }

    /// The buffer bound to `target` (0: none or not a buffer target).
    pub fn bound_buffer(&self, target: u32) -> u32 {
        match target {
            GL_ARRAY_BUFFER => self.va.array_buffer,
            GL_ELEMENT_ARRAY_BUFFER => self.va.element_buffer,
            GL_PIXEL_PACK_BUFFER => self.objects.pack_buffer,
            GL_PIXEL_UNPACK_BUFFER => self.objects.unpack_buffer,
            _ => 0,
        }
    }

    /// Size in bytes and usage of buffer `name`.
    pub fn buffer_info(&self, name: u32) -> Option<(usize, u32)> {
        self.objects
            .buffers
            .get(&name)
            .map(|b| (b.data.len(), b.usage))
    }

    /// glIsBuffer.
    pub fn is_buffer(&self, name: u32) -> bool {
        name != 0 && self.objects.buffers.contains_key(&name)
    }

    /// glBindBuffer (creates the object on first bind).
    pub fn bind_buffer(&mut self, target: u32, buffer: u32) {
        if self.reject_in_begin() {
            return;
        }
        let slot = match target {
            GL_ARRAY_BUFFER => &mut self.va.array_buffer,
            GL_ELEMENT_ARRAY_BUFFER => &mut self.va.element_buffer,
            GL_PIXEL_PACK_BUFFER => &mut self.objects.pack_buffer,
            GL_PIXEL_UNPACK_BUFFER => &mut self.objects.unpack_buffer,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return;
            }
        };
        *slot = buffer;
        if buffer != 0 {
            self.objects.buffers.entry(buffer).or_default();
        }
    }

    fn bound_buffer_name(&mut self, target: u32) -> Option<u32> {
        let b = match target {
            GL_ARRAY_BUFFER => self.va.array_buffer,
            GL_ELEMENT_ARRAY_BUFFER => self.va.element_buffer,
            GL_PIXEL_PACK_BUFFER => self.objects.pack_buffer,
            GL_PIXEL_UNPACK_BUFFER => self.objects.unpack_buffer,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        if b == 0 {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        Some(b)
    }

    /// glBufferData (`data` None: uninitialized, zeros here).
    pub fn buffer_data(&mut self, target: u32, size: isize, data: Option<&[u8]>, usage: u32) {
        if self.reject_in_begin() {
            return;
        }
        if size < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if !matches!(
            usage,
            GL_STREAM_DRAW
                | GL_STREAM_READ
                | GL_STREAM_COPY
                | GL_STATIC_DRAW
                | GL_STATIC_READ
                | GL_STATIC_COPY
                | GL_DYNAMIC_DRAW
                | GL_DYNAMIC_READ
                | GL_DYNAMIC_COPY
        ) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let Some(b) = self.bound_buffer_name(target) else {
            return;
        };
        let size = size as usize;
        if size > (1 << 30) {
            self.set_error(GL_OUT_OF_MEMORY);
            return;
        }
        let mut store = vec![0u8; size];
        if let Some(d) = data {
            let n = d.len().min(size);
            store[..n].copy_from_slice(&d[..n]);
        }
        self.objects.buffers.insert(
            b,
            BufferObj {
                data: Arc::from(store),
                usage,
            },
        );
    }

    /// glBufferSubData.
    pub fn buffer_sub_data(&mut self, target: u32, offset: isize, data: &[u8]) {
        if self.reject_in_begin() {
            return;
        }
        let Some(b) = self.bound_buffer_name(target) else {
            return;
        };
        let Some(obj) = self.objects.buffers.get_mut(&b) else {
            return;
        };
        if offset < 0 || offset as usize + data.len() > obj.data.len() {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let mut v = obj.data.to_vec();
        v[offset as usize..offset as usize + data.len()].copy_from_slice(data);
        obj.data = Arc::from(v);
    }

    /// glGetBufferSubData.
    pub fn get_buffer_sub_data(&mut self, target: u32, offset: isize, size: isize) -> Vec<u8> {
        let Some(b) = self.bound_buffer_name(target) else {
            return Vec::new();
        };
        let data = self
            .objects
            .buffers
            .get(&b)
            .map(|o| o.data.clone())
            .unwrap_or_else(|| Arc::from(Vec::new()));
        if offset < 0 || size < 0 || offset as usize + size as usize > data.len() {
            self.set_error(GL_INVALID_VALUE);
            return Vec::new();
        }
        data[offset as usize..offset as usize + size as usize].to_vec()
    }

    // ---- textures ----

    /// glGenTextures.
    pub fn gen_textures(&mut self, n: i32) -> Vec<u32> {
        let Some(n) = self.gen_count(n) else {
            return Vec::new();
        };
        let o = &mut self.objects;
        gen_names(&mut o.textures, &mut o.next_texture, n, TextureObj::default)
    }

    /// glDeleteTextures (bindings revert to 0, attachments are removed).
    pub fn delete_textures(&mut self, names: &[u32]) {
        for &t in names {
            if t == 0 || self.objects.textures.remove(&t).is_none() {
                continue;
            }
            for unit in &mut self.objects.bound {
                for b in unit.iter_mut() {
                    if *b == t {
                        *b = 0;
                    }
                }
            }
            let cur = self.objects.draw_framebuffer;
            if let Some(fb) = self.objects.framebuffers.get_mut(&cur) {
                let is_t = |a: &Option<Attachment>| matches!(a, Some(Attachment::Texture { texture, .. }) if *texture == t);
                for c in fb.color.iter_mut() {
                    if is_t(c) {
                        *c = None;
                    }
                }
                if is_t(&fb.depth) {
                    fb.depth = None;
                }
                if is_t(&fb.stencil) {
                    fb.stencil = None;
                }
            }
        }
    }

    /// glIsTexture.
    pub fn is_texture(&self, name: u32) -> bool {
        self.objects
            .textures
            .get(&name)
            .is_some_and(|t| t.target != 0)
    }

    /// glBindTexture.
    pub fn bind_texture(&mut self, target: u32, texture: u32) {
        if self.reject_in_begin() {
            return;
        }
        let Some(ti) = target_index(target) else {
            self.set_error(GL_INVALID_ENUM);
            return;
        };
        if texture != 0 {
            let t = self.objects.textures.entry(texture).or_default();
            if t.target == 0 {
                *t = TextureObj::new(target);
            } else if t.target != target {
                self.set_error(GL_INVALID_OPERATION);
                return;
            }
        }
        let unit = self.st.active_texture as usize;
        if let Some(b) = self.objects.bound.get_mut(unit) {
            b[ti] = texture;
        }
    }

    /// glTexImage1D.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_image_1d(
        &mut self,
        target: u32,
        level: i32,
        internal: i32,
        w: i32,
        border: i32,
        format: u32,
        ty: u32,
        data: Option<&[u8]>,
    ) {
        self.tex_image(
            1,
            target,
            level,
            internal,
            [w, 1, 1],
            border,
            format,
            ty,
            data,
        );
    }

    /// glTexImage2D.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_image_2d(
        &mut self,
        target: u32,
        level: i32,
        internal: i32,
        w: i32,
        h: i32,
        border: i32,
        format: u32,
        ty: u32,
        data: Option<&[u8]>,
    ) {
        self.tex_image(
            2,
            target,
            level,
            internal,
            [w, h, 1],
            border,
            format,
            ty,
            data,
        );
    }

    /// glTexImage3D.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_image_3d(
        &mut self,
        target: u32,
        level: i32,
        internal: i32,
        w: i32,
        h: i32,
        d: i32,
        border: i32,
        format: u32,
        ty: u32,
        data: Option<&[u8]>,
    ) {
        self.tex_image(
            3,
            target,
            level,
            internal,
            [w, h, d],
            border,
            format,
            ty,
            data,
        );
    }

    /// Checks of GL 2.1 §3.8.1 shared by the glTexImage calls.
    #[allow(clippy::too_many_arguments)]
    fn tex_image(
        &mut self,
        dims: u32,
        target: u32,
        level: i32,
        internal: i32,
        size: [i32; 3],
        border: i32,
        format: u32,
        ty: u32,
        data: Option<&[u8]>,
    ) {
        if self.reject_in_begin() {
            return;
        }
        let Some((bind_target, face)) = image_target(target, dims) else {
            self.set_error(GL_INVALID_ENUM);
            return;
        };
        if format_components(format).is_none() {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if !matches!(
            ty,
            GL_UNSIGNED_BYTE
                | GL_BYTE
                | GL_UNSIGNED_SHORT
                | GL_SHORT
                | GL_UNSIGNED_INT
                | GL_INT
                | GL_FLOAT
                | GL_HALF_FLOAT
                | GL_UNSIGNED_INT_8_8_8_8
                | GL_UNSIGNED_INT_8_8_8_8_REV
                | GL_UNSIGNED_INT_2_10_10_10_REV
                | GL_UNSIGNED_INT_24_8
                | GL_UNSIGNED_SHORT_5_6_5
                | GL_UNSIGNED_SHORT_5_6_5_REV
                | GL_UNSIGNED_SHORT_4_4_4_4
                | GL_UNSIGNED_SHORT_4_4_4_4_REV
                | GL_UNSIGNED_SHORT_5_5_5_1
                | GL_UNSIGNED_SHORT_1_5_5_5_REV
        ) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let Some(base) = base_format(internal) else {
            self.set_error(GL_INVALID_VALUE);
            return;
        };
        if !(0..MAX_LEVELS).contains(&level)
            || size.iter().any(|&s| !(0..=MAX_TEXTURE_SIZE).contains(&s))
            || border != 0
            || (dims == 3 && size.iter().any(|&s| s > 2048))
        {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if bind_target == GL_TEXTURE_CUBE_MAP && size[0] != size[1] {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if pixel_size(format, ty).is_none() {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        // Depth formats need depth data and vice versa (GL 2.1 §3.8.1).
        let depth_fmt = matches!(base, GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL);
        let depth_data = matches!(format, GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL);
        if depth_fmt != depth_data
            || (depth_fmt && !matches!(bind_target, GL_TEXTURE_1D | GL_TEXTURE_2D))
        {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let (w, h, d) = (size[0] as usize, size[1] as usize, size[2] as usize);
        if w.saturating_mul(h).saturating_mul(d) > (1 << 26) {
            self.set_error(GL_OUT_OF_MEMORY);
            return;
        }
        let alignment = self.st.unpack_alignment as usize;
        let texels = unpack_image(data, w, h, d, format, ty, internal, alignment);
        let unit = self.st.active_texture as usize;
        let Some(tex) = self.objects.bound_texture_mut(unit, bind_target) else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let img = Image {
            width: size[0],
            height: size[1],
            depth: size[2],
            internal_format: internal as u32,
            texels,
        };
        set_image(tex, face, level as usize, img);
        if tex.params.generate_mipmap && level == tex.params.base_level {
            generate_mipmaps(tex, face);
        }
    }

    /// glTexSubImage2D.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_sub_image_2d(
        &mut self,
        target: u32,
        level: i32,
        xoff: i32,
        yoff: i32,
        w: i32,
        h: i32,
        format: u32,
        ty: u32,
        data: &[u8],
    ) {
        self.tex_sub_image(
            2,
            target,
            level,
            [xoff, yoff, 0],
            [w, h, 1],
            format,
            ty,
            data,
        );
    }

    /// glTexSubImage1D.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_sub_image_1d(
        &mut self,
        target: u32,
        level: i32,
        xoff: i32,
        w: i32,
        format: u32,
        ty: u32,
        data: &[u8],
    ) {
        self.tex_sub_image(1, target, level, [xoff, 0, 0], [w, 1, 1], format, ty, data);
    }

    /// glTexSubImage3D.
    #[allow(clippy::too_many_arguments)]
    pub fn tex_sub_image_3d(
        &mut self,
        target: u32,
        level: i32,
        off: [i32; 3],
        size: [i32; 3],
        format: u32,
        ty: u32,
        data: &[u8],
    ) {
        self.tex_sub_image(3, target, level, off, size, format, ty, data);
    }

    /// glTexSubImage{1,2,3}D: replaces the `size` block at `off` of an
    /// existing image (`data`: the client image, already validated in
    /// size by the caller, or empty for a null pointer).
    #[allow(clippy::too_many_arguments)]
    fn tex_sub_image(
        &mut self,
        dims: u32,
        target: u32,
        level: i32,
        off: [i32; 3],
        size: [i32; 3],
        format: u32,
        ty: u32,
        data: &[u8],
    ) {
        if self.reject_in_begin() {
            return;
        }
        let Some((bind_target, face)) = image_target(target, dims) else {
            self.set_error(GL_INVALID_ENUM);
            return;
        };
        if format_components(format).is_none() {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if pixel_size(format, ty).is_none() {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if !(0..MAX_LEVELS).contains(&level) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let alignment = self.st.unpack_alignment as usize;
        let unit = self.st.active_texture as usize;
        let Some(tex) = self.objects.bound_texture_mut(unit, bind_target) else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let Some(img) = tex
            .faces
            .get_mut(face)
            .and_then(|f| f.get_mut(level as usize))
            .and_then(|i| i.as_mut())
        else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let dim = [img.width, img.height, img.depth];
        let fits = (0..3).all(|i| {
            off[i] >= 0 && size[i] >= 0 && off[i].checked_add(size[i]).is_some_and(|e| e <= dim[i])
        });
        if !fits {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let (w, h, d) = (size[0] as usize, size[1] as usize, size[2] as usize);
        if w == 0 || h == 0 || d == 0 || data.is_empty() {
            return;
        }
        let internal = img.internal_format as i32;
        let texels = unpack_image(Some(data), w, h, d, format, ty, internal, alignment);
        let (iw, ih) = (img.width as usize, img.height as usize);
        for z in 0..d {
            for y in 0..h {
                for x in 0..w {
                    let dst = ((off[2] as usize + z) * ih + off[1] as usize + y) * iw
                        + off[0] as usize
                        + x;
                    if let (Some(t), Some(src)) =
                        (img.texels.get_mut(dst), texels.get((z * h + y) * w + x))
                    {
                        *t = *src;
                    }
                }
            }
        }
        tex.generation += 1;
        if tex.params.generate_mipmap && level == tex.params.base_level {
            generate_mipmaps(tex, face);
        }
    }

    /// glTexParameteri.
    pub fn tex_parameteri(&mut self, target: u32, pname: u32, v: i32) {
        self.tex_parameter(target, pname, &[v as f32], v as u32);
    }

    /// glTexParameterf.
    pub fn tex_parameterf(&mut self, target: u32, pname: u32, v: f32) {
        self.tex_parameter(target, pname, &[v], v as u32);
    }

    /// glTexParameterfv.
    pub fn tex_parameterfv(&mut self, target: u32, pname: u32, v: &[f32]) {
        let e = v.first().map(|&x| x as u32).unwrap_or(0);
        self.tex_parameter(target, pname, v, e);
    }

    fn tex_parameter(&mut self, target: u32, pname: u32, v: &[f32], e: u32) {
        if self.reject_in_begin() {
            return;
        }
        if target_index(target).is_none() {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let need = if pname == GL_TEXTURE_BORDER_COLOR {
            4
        } else {
            1
        };
        if v.len() < need {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let unit = self.st.active_texture as usize;
        let Some(tex) = self.objects.bound_texture_mut(unit, target) else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let p = &mut tex.params;
        let mut err = GL_NO_ERROR;
        match pname {
            GL_TEXTURE_MIN_FILTER if valid_filter(e, true) => p.min_filter = e,
            GL_TEXTURE_MAG_FILTER if valid_filter(e, false) => p.mag_filter = e,
            GL_TEXTURE_WRAP_S | GL_TEXTURE_WRAP_T | GL_TEXTURE_WRAP_R
                if matches!(
                    e,
                    GL_REPEAT
                        | GL_CLAMP
                        | GL_CLAMP_TO_EDGE
                        | GL_CLAMP_TO_BORDER
                        | GL_MIRRORED_REPEAT
                ) =>
            {
                let i = match pname {
                    GL_TEXTURE_WRAP_S => 0,
                    GL_TEXTURE_WRAP_T => 1,
                    _ => 2,
                };
                p.wrap[i] = e;
            }
            GL_TEXTURE_BORDER_COLOR => {
                p.border_color = [v[0], v[1], v[2], v[3]].map(|x| x.clamp(0.0, 1.0))
            }
            GL_TEXTURE_MIN_LOD => p.min_lod = v[0],
            GL_TEXTURE_MAX_LOD => p.max_lod = v[0],
            GL_TEXTURE_LOD_BIAS => p.lod_bias = v[0],
            GL_TEXTURE_BASE_LEVEL | GL_TEXTURE_MAX_LEVEL => {
                let l = v[0] as i32;
                if l < 0 {
                    err = GL_INVALID_VALUE;
                } else if pname == GL_TEXTURE_BASE_LEVEL {
                    p.base_level = l;
                } else {
                    p.max_level = l;
                }
            }
            GL_TEXTURE_COMPARE_MODE if e == GL_NONE || e == GL_COMPARE_R_TO_TEXTURE => {
                p.compare_mode = e
            }
            GL_TEXTURE_COMPARE_FUNC if (GL_NEVER..=GL_ALWAYS).contains(&e) => p.compare_func = e,
            GL_DEPTH_TEXTURE_MODE
                if matches!(e, GL_LUMINANCE | GL_INTENSITY | GL_ALPHA | GL_RED) =>
            {
                p.depth_mode = e
            }
            GL_GENERATE_MIPMAP => p.generate_mipmap = v[0] != 0.0,
            GL_TEXTURE_PRIORITY => {}
            GL_TEXTURE_MIN_FILTER
            | GL_TEXTURE_MAG_FILTER
            | GL_TEXTURE_WRAP_S
            | GL_TEXTURE_WRAP_T
            | GL_TEXTURE_WRAP_R
            | GL_TEXTURE_COMPARE_MODE
            | GL_TEXTURE_COMPARE_FUNC
            | GL_DEPTH_TEXTURE_MODE => err = GL_INVALID_ENUM,
            _ => err = GL_INVALID_ENUM,
        }
        tex.generation += 1;
        if err != GL_NO_ERROR {
            self.set_error(err);
        }
    }

    /// glGetTexParameteriv (single-valued parameters).
    pub fn get_tex_parameteriv(&mut self, target: u32, pname: u32) -> i32 {
        let unit = self.st.active_texture as usize;
        let Some(t) = self.objects.bound_texture(unit, target) else {
            self.set_error(GL_INVALID_ENUM);
            return 0;
        };
        let p = t.params;
        match pname {
            GL_TEXTURE_MIN_FILTER => p.min_filter as i32,
            GL_TEXTURE_MAG_FILTER => p.mag_filter as i32,
            GL_TEXTURE_WRAP_S => p.wrap[0] as i32,
            GL_TEXTURE_WRAP_T => p.wrap[1] as i32,
            GL_TEXTURE_WRAP_R => p.wrap[2] as i32,
            GL_TEXTURE_BASE_LEVEL => p.base_level,
            GL_TEXTURE_MAX_LEVEL => p.max_level,
            GL_TEXTURE_COMPARE_MODE => p.compare_mode as i32,
            GL_TEXTURE_COMPARE_FUNC => p.compare_func as i32,
            GL_DEPTH_TEXTURE_MODE => p.depth_mode as i32,
            GL_GENERATE_MIPMAP => p.generate_mipmap as i32,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                0
            }
        }
    }

    /// glGetTexLevelParameteriv: sizes, internal format, border, component
    /// sizes (8 bits per stored component, 24 for depth), compression.
    pub fn get_tex_level_parameteriv(&mut self, target: u32, level: i32, pname: u32) -> i32 {
        let Some(img) = self.level_image(target, level) else {
            return 0;
        };
        let info = img.map(|i| {
            (
                [i.width, i.height, i.depth],
                i.internal_format,
                base_format(i.internal_format as i32).unwrap_or(GL_RGBA),
            )
        });
        let bits = |has: &[u32]| match info {
            Some((_, _, base)) if has.contains(&base) => {
                if base == GL_DEPTH_COMPONENT {
                    24
                } else {
                    8
                }
            }
            _ => 0,
        };
        match pname {
            GL_TEXTURE_WIDTH => info.map_or(0, |i| i.0[0]),
            GL_TEXTURE_HEIGHT => info.map_or(0, |i| i.0[1]),
            GL_TEXTURE_DEPTH => info.map_or(0, |i| i.0[2]),
            GL_TEXTURE_INTERNAL_FORMAT => info.map_or(1, |i| i.1 as i32),
            GL_TEXTURE_BORDER | GL_TEXTURE_COMPRESSED => 0,
            GL_TEXTURE_RED_SIZE => bits(&[GL_RGB, GL_RGBA, GL_RED, GL_RG]),
            GL_TEXTURE_GREEN_SIZE => bits(&[GL_RGB, GL_RGBA, GL_RG]),
            GL_TEXTURE_BLUE_SIZE => bits(&[GL_RGB, GL_RGBA]),
            GL_TEXTURE_ALPHA_SIZE => bits(&[GL_RGBA, GL_ALPHA, GL_LUMINANCE_ALPHA]),
            GL_TEXTURE_LUMINANCE_SIZE => bits(&[GL_LUMINANCE, GL_LUMINANCE_ALPHA]),
            GL_TEXTURE_INTENSITY_SIZE => bits(&[GL_INTENSITY]),
            GL_TEXTURE_DEPTH_SIZE => bits(&[GL_DEPTH_COMPONENT]),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                0
            }
        }
    }

    /// glGetTexParameterfv: the float parameters (border colour, LOD
    /// range, priority, residency) and the others as floats.
    pub fn get_tex_parameterfv(&mut self, target: u32, pname: u32) -> Vec<f32> {
        let unit = self.st.active_texture as usize;
        let Some(t) = self.objects.bound_texture(unit, target) else {
            self.set_error(GL_INVALID_ENUM);
            return Vec::new();
        };
        let p = t.params;
        match pname {
            GL_TEXTURE_BORDER_COLOR => p.border_color.to_vec(),
            GL_TEXTURE_MIN_LOD => vec![p.min_lod],
            GL_TEXTURE_MAX_LOD => vec![p.max_lod],
            GL_TEXTURE_LOD_BIAS => vec![p.lod_bias],
            GL_TEXTURE_PRIORITY | GL_TEXTURE_RESIDENT => vec![1.0],
            _ => vec![self.get_tex_parameteriv(target, pname) as f32],
        }
    }

    /// The image `level` of the texture `target` names (a 1D/2D/3D target
    /// or a cube face) on the active unit; None with GL_INVALID_ENUM or
    /// GL_INVALID_VALUE set for a bad target or level, Some(None) for an
    /// undefined image.
    fn level_image(&mut self, target: u32, level: i32) -> Option<Option<&Image>> {
        let Some((bind, face)) = image_target(target, 2)
            .or_else(|| image_target(target, 1))
            .or_else(|| image_target(target, 3))
        else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        if !(0..MAX_LEVELS).contains(&level) {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let unit = self.st.active_texture as usize;
        Some(
            self.objects
                .bound_texture(unit, bind)
                .and_then(|t| t.image(face, level as usize)),
        )
    }

    /// glGetTexImage: the image as `format`/`ty` rows at the pack
    /// alignment (empty for an undefined image). Components are taken per
    /// GL 2.1 Table 6.1 (luminance and intensity to red).
    pub fn get_tex_image(&mut self, target: u32, level: i32, format: u32, ty: u32) -> Vec<u8> {
        if self.reject_in_begin() {
            return Vec::new();
        }
        if format_components(format).is_none()
            || matches!(format, GL_STENCIL_INDEX | GL_DEPTH_STENCIL | GL_COLOR_INDEX)
        {
            self.set_error(GL_INVALID_ENUM);
            return Vec::new();
        }
        let Some((px, comp)) = pixel_size(format, ty) else {
            self.set_error(GL_INVALID_ENUM);
            return Vec::new();
        };
        let align = self.st.pack_alignment.max(1) as usize;
        let Some(img) = self.level_image(target, level) else {
            return Vec::new();
        };
        let Some(img) = img.cloned() else {
            return Vec::new();
        };
        let base = base_format(img.internal_format as i32).unwrap_or(GL_RGBA);
        let is_depth = matches!(base, GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL);
        if is_depth != (format == GL_DEPTH_COMPONENT) {
            self.set_error(GL_INVALID_OPERATION);
            return Vec::new();
        }
        let n = format_components(format).unwrap_or(4);
        if comp != px / n.max(1) {
            // Packed types are not implemented for reads.
            self.set_error(GL_INVALID_OPERATION);
            return Vec::new();
        }
        let (w, h, d) = (
            img.width.max(0) as usize,
            img.height.max(0) as usize,
            img.depth.max(0) as usize,
        );
        let texels: Vec<[f32; 4]> = img
            .texels
            .iter()
            .map(|&[r, g, b, a]| match base {
                GL_ALPHA => [0.0, 0.0, 0.0, a],
                GL_LUMINANCE | GL_INTENSITY | GL_RED => [r, 0.0, 0.0, 1.0],
                GL_LUMINANCE_ALPHA => [r, 0.0, 0.0, a],
                GL_RG => [r, g, 0.0, 1.0],
                GL_RGB => [r, g, b, 1.0],
                _ => [r, g, b, a],
            })
            .collect();
        crate::draw::pack_pixels(&texels, w, h.saturating_mul(d), format, ty, align)
    }

    /// glGenerateMipmap / glGenerateMipmapEXT: box-filtered levels down to
    /// 1x1 from the base level.
    pub fn generate_mipmap(&mut self, target: u32) {
        if self.reject_in_begin() {
            return;
        }
        if !matches!(
            target,
            GL_TEXTURE_1D | GL_TEXTURE_2D | GL_TEXTURE_3D | GL_TEXTURE_CUBE_MAP
        ) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let unit = self.st.active_texture as usize;
        if let Some(tex) = self.objects.bound_texture_mut(unit, target) {
            for face in 0..tex.faces.len() {
                generate_mipmaps(tex, face);
            }
        }
    }

    /// glGenerateMipmapEXT.
    pub fn generate_mipmap_ext(&mut self, target: u32) {
        self.generate_mipmap(target);
    }

    // ---- renderbuffers ----

    /// glGenRenderbuffers(EXT).
    pub fn gen_renderbuffers(&mut self, n: i32) -> Vec<u32> {
        let Some(n) = self.gen_count(n) else {
            return Vec::new();
        };
        let o = &mut self.objects;
        gen_names(
            &mut o.renderbuffers,
            &mut o.next_renderbuffer,
            n,
            RenderbufferObj::default,
        )
    }

    /// glGenRenderbuffersEXT.
    pub fn gen_renderbuffers_ext(&mut self, n: i32) -> Vec<u32> {
        self.gen_renderbuffers(n)
    }

    /// glBindRenderbuffer(EXT).
    pub fn bind_renderbuffer(&mut self, target: u32, rb: u32) {
        if target != GL_RENDERBUFFER {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if rb != 0 {
            self.objects.renderbuffers.entry(rb).or_default();
        }
        self.objects.bound_renderbuffer = rb;
    }

    /// glBindRenderbufferEXT.
    pub fn bind_renderbuffer_ext(&mut self, target: u32, rb: u32) {
        self.bind_renderbuffer(target, rb);
    }

    /// glDeleteRenderbuffers(EXT).
    pub fn delete_renderbuffers(&mut self, names: &[u32]) {
        for &r in names {
            if r == 0 {
                continue;
            }
            self.objects.renderbuffers.remove(&r);
            if self.objects.bound_renderbuffer == r {
                self.objects.bound_renderbuffer = 0;
            }
        }
    }

    /// glRenderbufferStorage(EXT).
    pub fn renderbuffer_storage(&mut self, target: u32, internal: u32, w: i32, h: i32) {
        if target != GL_RENDERBUFFER {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let ok_format = base_format(internal as i32).is_some()
            || matches!(
                internal,
                GL_STENCIL_INDEX8
                    | GL_STENCIL_INDEX
                    | GL_STENCIL_INDEX1
                    | GL_STENCIL_INDEX4
                    | GL_STENCIL_INDEX16
            );
        if !ok_format {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if !(0..=MAX_TEXTURE_SIZE).contains(&w) || !(0..=MAX_TEXTURE_SIZE).contains(&h) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let rb = self.objects.bound_renderbuffer;
        let Some(r) = self.objects.renderbuffers.get_mut(&rb).filter(|_| rb != 0) else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let n = w as usize * h as usize;
        *r = RenderbufferObj {
            internal_format: internal,
            width: w,
            height: h,
            texels: vec![[0.0, 0.0, 0.0, 0.0]; n],
            stencil: vec![0; n],
        };
    }

    /// glRenderbufferStorageEXT.
    pub fn renderbuffer_storage_ext(&mut self, target: u32, internal: u32, w: i32, h: i32) {
        self.renderbuffer_storage(target, internal, w, h);
    }

    // ---- framebuffers ----

    /// glGenFramebuffers(EXT).
    pub fn gen_framebuffers(&mut self, n: i32) -> Vec<u32> {
        let Some(n) = self.gen_count(n) else {
            return Vec::new();
        };
        let o = &mut self.objects;
        gen_names(
            &mut o.framebuffers,
            &mut o.next_framebuffer,
            n,
            FramebufferObj::new,
        )
    }

    /// glGenFramebuffersEXT.
    pub fn gen_framebuffers_ext(&mut self, n: i32) -> Vec<u32> {
        self.gen_framebuffers(n)
    }

    /// glBindFramebuffer(EXT).
    pub fn bind_framebuffer(&mut self, target: u32, fb: u32) {
        if self.reject_in_begin() {
            return;
        }
        if !matches!(
            target,
            GL_FRAMEBUFFER | GL_DRAW_FRAMEBUFFER | GL_READ_FRAMEBUFFER
        ) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if fb != 0 {
            self.objects.framebuffers.entry(fb).or_default();
        }
        if target != GL_READ_FRAMEBUFFER {
            self.objects.draw_framebuffer = fb;
        }
        if target != GL_DRAW_FRAMEBUFFER {
            self.objects.read_framebuffer = fb;
        }
    }

    /// glBindFramebufferEXT.
    pub fn bind_framebuffer_ext(&mut self, target: u32, fb: u32) {
        self.bind_framebuffer(target, fb);
    }

    /// glDeleteFramebuffers(EXT): bindings revert to the default framebuffer.
    pub fn delete_framebuffers(&mut self, names: &[u32]) {
        for &f in names {
            if f == 0 {
                continue;
            }
            self.objects.framebuffers.remove(&f);
            if self.objects.draw_framebuffer == f {
                self.objects.draw_framebuffer = 0;
            }
            if self.objects.read_framebuffer == f {
                self.objects.read_framebuffer = 0;
            }
        }
    }

    /// glIsFramebuffer.
    pub fn is_framebuffer(&self, name: u32) -> bool {
        name != 0 && self.objects.framebuffers.contains_key(&name)
    }

    fn attachment_slot(&mut self, target: u32, attachment: u32) -> Option<u32> {
        if !matches!(
            target,
            GL_FRAMEBUFFER | GL_DRAW_FRAMEBUFFER | GL_READ_FRAMEBUFFER
        ) {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        let fb = if target == GL_READ_FRAMEBUFFER {
            self.objects.read_framebuffer
        } else {
            self.objects.draw_framebuffer
        };
        if fb == 0 {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        let ok = (GL_COLOR_ATTACHMENT0..GL_COLOR_ATTACHMENT0 + crate::MAX_DRAW_BUFFERS as u32)
            .contains(&attachment)
            || matches!(
                attachment,
                GL_DEPTH_ATTACHMENT | GL_STENCIL_ATTACHMENT | GL_DEPTH_STENCIL_ATTACHMENT
            );
        if !ok {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        Some(fb)
    }

    fn set_attachment(&mut self, fb: u32, attachment: u32, a: Option<Attachment>) {
        let Some(f) = self.objects.framebuffers.get_mut(&fb) else {
            return;
        };
        match attachment {
            GL_DEPTH_ATTACHMENT => f.depth = a,
            GL_STENCIL_ATTACHMENT => f.stencil = a,
            GL_DEPTH_STENCIL_ATTACHMENT => {
                f.depth = a;
                f.stencil = a;
            }
            _ => {
                if let Some(c) = f
                    .color
                    .get_mut(attachment.wrapping_sub(GL_COLOR_ATTACHMENT0) as usize)
                {
                    *c = a;
                }
            }
        }
    }

    /// glFramebufferTexture2D(EXT).
    pub fn framebuffer_texture_2d(
        &mut self,
        target: u32,
        attachment: u32,
        textarget: u32,
        texture: u32,
        level: i32,
    ) {
        let Some(fb) = self.attachment_slot(target, attachment) else {
            return;
        };
        if texture == 0 {
            self.set_attachment(fb, attachment, None);
            return;
        }
        let Some((bind, face)) = image_target(textarget, 2).or_else(|| image_target(textarget, 1))
        else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let tex_target = self.objects.textures.get(&texture).map(|t| t.target);
        match tex_target {
            None => {
                self.set_error(GL_INVALID_OPERATION);
                return;
            }
            Some(t) if t != bind => {
                self.set_error(GL_INVALID_OPERATION);
                return;
            }
            _ => {}
        }
        if !(0..MAX_LEVELS).contains(&level) {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        self.set_attachment(
            fb,
            attachment,
            Some(Attachment::Texture {
                texture,
                face: face as u32,
                level,
                zoffset: 0,
            }),
        );
    }

    /// glFramebufferTexture2DEXT.
    pub fn framebuffer_texture_2d_ext(
        &mut self,
        target: u32,
        attachment: u32,
        textarget: u32,
        texture: u32,
        level: i32,
    ) {
        self.framebuffer_texture_2d(target, attachment, textarget, texture, level);
    }

    /// glFramebufferTexture1D(EXT).
    pub fn framebuffer_texture_1d(
        &mut self,
        target: u32,
        attachment: u32,
        textarget: u32,
        texture: u32,
        level: i32,
    ) {
        self.framebuffer_texture_2d(target, attachment, textarget, texture, level);
    }

    /// glFramebufferRenderbuffer(EXT).
    pub fn framebuffer_renderbuffer(
        &mut self,
        target: u32,
        attachment: u32,
        rbtarget: u32,
        rb: u32,
    ) {
        let Some(fb) = self.attachment_slot(target, attachment) else {
            return;
        };
        if rbtarget != GL_RENDERBUFFER {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        if rb != 0 && !self.objects.renderbuffers.contains_key(&rb) {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let a = (rb != 0).then_some(Attachment::Renderbuffer(rb));
        self.set_attachment(fb, attachment, a);
    }

    /// glFramebufferRenderbufferEXT.
    pub fn framebuffer_renderbuffer_ext(
        &mut self,
        target: u32,
        attachment: u32,
        rbtarget: u32,
        rb: u32,
    ) {
        self.framebuffer_renderbuffer(target, attachment, rbtarget, rb);
    }

    /// Size and internal format of an attachment's image.
    pub(crate) fn attachment_info(&self, a: &Attachment) -> Option<(i32, i32, u32)> {
        match *a {
            Attachment::Texture {
                texture,
                face,
                level,
                ..
            } => {
                let img = self
                    .objects
                    .textures
                    .get(&texture)?
                    .image(face as usize, level as usize)?;
                Some((img.width, img.height, img.internal_format))
            }
            Attachment::Renderbuffer(rb) => {
                let r = self.objects.renderbuffers.get(&rb)?;
                Some((r.width, r.height, r.internal_format))
            }
        }
    }

    /// Completeness of a framebuffer object (EXT_framebuffer_object §4.4.4).
    pub(crate) fn framebuffer_status(&self, fb: u32) -> u32 {
        if fb == 0 {
            return GL_FRAMEBUFFER_COMPLETE;
        }
        let Some(f) = self.objects.framebuffers.get(&fb) else {
            return GL_FRAMEBUFFER_UNSUPPORTED;
        };
        let mut sizes = Vec::new();
        for c in f.color.iter().flatten() {
            let Some((w, h, fmt)) = self.attachment_info(c) else {
                return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
            };
            if w == 0 || h == 0 {
                return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
            }
            match base_format(fmt as i32) {
                Some(GL_RGB | GL_RGBA | GL_RED | GL_RG) => {}
                Some(GL_ALPHA | GL_LUMINANCE | GL_LUMINANCE_ALPHA | GL_INTENSITY) => {
                    return GL_FRAMEBUFFER_UNSUPPORTED
                }
                _ => return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT,
            }
            sizes.push((w, h));
        }
        for (a, want_depth) in [(&f.depth, true), (&f.stencil, false)] {
            let Some(a) = a else { continue };
            let Some((w, h, fmt)) = self.attachment_info(a) else {
                return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
            };
            if w == 0 || h == 0 {
                return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
            }
            let base = base_format(fmt as i32);
            let ok = if want_depth {
                matches!(base, Some(GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL))
            } else {
                base == Some(GL_DEPTH_STENCIL)
                    || matches!(
                        fmt,
                        GL_STENCIL_INDEX8
                            | GL_STENCIL_INDEX
                            | GL_STENCIL_INDEX1
                            | GL_STENCIL_INDEX4
                            | GL_STENCIL_INDEX16
                    )
            };
            if !ok {
                return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
            }
            sizes.push((w, h));
        }
        if sizes.is_empty() {
            return GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT;
        }
        if sizes.iter().any(|s| *s != sizes[0]) {
            return GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_EXT;
        }
        for &db in &f.draw_buffers {
            if db != GL_NONE {
                let i = db.wrapping_sub(GL_COLOR_ATTACHMENT0) as usize;
                if f.color.get(i).is_none_or(|c| c.is_none()) {
                    return GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER;
                }
            }
        }
        GL_FRAMEBUFFER_COMPLETE
    }

    /// glCheckFramebufferStatus(EXT).
    pub fn check_framebuffer_status(&mut self, target: u32) -> u32 {
        let fb = match target {
            GL_FRAMEBUFFER | GL_DRAW_FRAMEBUFFER => self.objects.draw_framebuffer,
            GL_READ_FRAMEBUFFER => self.objects.read_framebuffer,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return 0;
            }
        };
        self.framebuffer_status(fb)
    }

    /// glCheckFramebufferStatusEXT.
    pub fn check_framebuffer_status_ext(&mut self, target: u32) -> u32 {
        self.check_framebuffer_status(target)
    }

    /// glDrawBuffers.
    pub fn draw_buffers(&mut self, bufs: &[u32]) {
        if self.reject_in_begin() {
            return;
        }
        if bufs.len() > crate::MAX_DRAW_BUFFERS {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let fb = self.objects.draw_framebuffer;
        for (i, &b) in bufs.iter().enumerate() {
            let ok = if fb == 0 {
                matches!(
                    b,
                    GL_NONE
                        | GL_FRONT_LEFT
                        | GL_BACK_LEFT
                        | GL_FRONT
                        | GL_BACK
                        | GL_LEFT
                        | GL_FRONT_AND_BACK
                )
            } else {
                b == GL_NONE
                    || (GL_COLOR_ATTACHMENT0..GL_COLOR_ATTACHMENT0 + crate::MAX_DRAW_BUFFERS as u32)
                        .contains(&b)
            };
            if !ok {
                self.set_error(GL_INVALID_ENUM);
                return;
            }
            if bufs[..i].contains(&b) && b != GL_NONE {
                self.set_error(GL_INVALID_OPERATION);
                return;
            }
        }
        if fb == 0 {
            self.st.draw_buffers = bufs.to_vec();
        } else if let Some(f) = self.objects.framebuffers.get_mut(&fb) {
            f.draw_buffers = bufs.to_vec();
        }
    }

    /// glDrawBuffer.
    pub fn draw_buffer(&mut self, buf: u32) {
        let fb = self.objects.draw_framebuffer;
        if fb == 0
            && !matches!(
                buf,
                GL_NONE
                    | GL_FRONT_LEFT
                    | GL_BACK_LEFT
                    | GL_FRONT
                    | GL_BACK
                    | GL_LEFT
                    | GL_FRONT_AND_BACK
            )
        {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.draw_buffers(&[buf]);
    }

    /// glReadBuffer.
    pub fn read_buffer(&mut self, buf: u32) {
        if self.reject_in_begin() {
            return;
        }
        let fb = self.objects.read_framebuffer;
        if fb == 0 {
            self.st.read_buffer = buf;
        } else if let Some(f) = self.objects.framebuffers.get_mut(&fb) {
            f.read_buffer = buf;
        }
    }
}

impl FramebufferObj {
    fn new() -> FramebufferObj {
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

fn set_image(tex: &mut TextureObj, face: usize, level: usize, img: Image) {
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

/// Box-filters levels base+1.. from the base level (GL 2.1 §3.8.8,
/// GENERATE_MIPMAP: any filter that averages 2x2(x2) blocks is allowed).
fn generate_mipmaps(tex: &mut TextureObj, face: usize) {
    let base = tex.params.base_level.max(0) as usize;
    let Some(mut cur) = tex.image(face, base).cloned() else {
        return;
    };
    let mut level = base;
    while (cur.width > 1 || cur.height > 1 || cur.depth > 1) && level < MAX_LEVELS as usize {
        let (w, h, d) = (cur.width as usize, cur.height as usize, cur.depth as usize);
        let (nw, nh, nd) = ((w / 2).max(1), (h / 2).max(1), (d / 2).max(1));
        let mut texels = Vec::with_capacity(nw * nh * nd);
        for z in 0..nd {
            for y in 0..nh {
                for x in 0..nw {
                    let mut sum = [0.0f32; 4];
                    let mut n = 0.0f32;
                    for dz in 0..(if d > 1 { 2 } else { 1 }) {
                        for dy in 0..(if h > 1 { 2 } else { 1 }) {
                            for dx in 0..(if w > 1 { 2 } else { 1 }) {
                                let (sx, sy, sz) = (2 * x + dx, 2 * y + dy, 2 * z + dz);
                                if let Some(t) = cur.texels.get((sz * h + sy) * w + sx) {
                                    for c in 0..4 {
                                        sum[c] += t[c];
                                    }
                                    n += 1.0;
                                }
                            }
                        }
                    }
                    let avg = sum.map(|s| if n > 0.0 { s / n } else { 0.0 });
                    texels.push(texel_for_stored(avg, cur.internal_format as i32));
                }
            }
        }
        cur = Image {
            width: nw as i32,
            height: nh as i32,
            depth: nd as i32,
            internal_format: cur.internal_format,
            texels,
        };
        level += 1;
        set_image(tex, face, level, cur.clone());
    }
}

/// Re-quantizes an already expanded texel (for generated mipmaps).
fn texel_for_stored(t: [f32; 4], internal: i32) -> [f32; 4] {
    let bits = format_bits(internal);
    if base_format(internal) == Some(GL_DEPTH_COMPONENT) {
        return t;
    }
    t.map(|x| quantize(x, bits))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn luminance_and_alignment() {
        let mut ctx = Context::new(4, 4);
        let t = ctx.gen_textures(1)[0];
        ctx.bind_texture(GL_TEXTURE_2D, t);
        // 3x2 luminance bytes with 4-byte row alignment: rows are 4 bytes.
        let data = [10u8, 20, 30, 0, 40, 50, 60, 0];
        ctx.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_LUMINANCE as i32,
            3,
            2,
            0,
            GL_LUMINANCE,
            GL_UNSIGNED_BYTE,
            Some(&data),
        );
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        let img = ctx.objects.textures[&t].image(0, 0).unwrap().clone();
        assert_eq!(
            img.texels[3],
            [40.0 / 255.0, 40.0 / 255.0, 40.0 / 255.0, 1.0]
        );
        ctx.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_ALPHA as i32,
            1,
            1,
            0,
            GL_RGBA,
            GL_FLOAT,
            Some(&[0u8; 16]),
        );
        let img = ctx.objects.textures[&t].image(0, 0).unwrap().clone();
        assert_eq!(img.texels[0], [0.0; 4]);
        ctx.tex_image_2d(GL_TEXTURE_2D, 0, 0x1234, 1, 1, 0, GL_RGBA, GL_FLOAT, None);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            1,
            1,
            1,
            GL_RGBA,
            GL_FLOAT,
            None,
        );
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_DEPTH_COMPONENT as i32,
            1,
            1,
            0,
            GL_RGBA,
            GL_FLOAT,
            None,
        );
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.bind_texture(GL_TEXTURE_3D, t);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
    }

    #[test]
    fn float_texels_unclamped_and_mipmaps() {
        let mut ctx = Context::new(4, 4);
        let t = ctx.gen_textures(1)[0];
        ctx.bind_texture(GL_TEXTURE_2D, t);
        let px: Vec<f32> = vec![
            2.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 2.0, 0.0, 0.0, 1.0,
        ];
        let bytes: Vec<u8> = px.iter().flat_map(|f| f.to_le_bytes()).collect();
        ctx.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA32F as i32,
            2,
            2,
            0,
            GL_RGBA,
            GL_FLOAT,
            Some(&bytes),
        );
        ctx.generate_mipmap(GL_TEXTURE_2D);
        let tex = &ctx.objects.textures[&t];
        assert_eq!(tex.image(0, 0).unwrap().texels[0][0], 2.0);
        assert_eq!(tex.image(0, 1).unwrap().texels, vec![[1.0, 0.0, 0.0, 1.0]]);
    }

    #[test]
    fn framebuffer_completeness() {
        let mut ctx = Context::new(4, 4);
        let fb = ctx.gen_framebuffers(1)[0];
        ctx.bind_framebuffer(GL_FRAMEBUFFER, fb);
        assert_eq!(
            ctx.check_framebuffer_status(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT
        );
        let t = ctx.gen_textures(1)[0];
        ctx.bind_texture(GL_TEXTURE_2D, t);
        ctx.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            8,
            8,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            None,
        );
        ctx.framebuffer_texture_2d(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 0);
        assert_eq!(
            ctx.check_framebuffer_status(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_COMPLETE
        );
        let rb = ctx.gen_renderbuffers(1)[0];
        ctx.bind_renderbuffer(GL_RENDERBUFFER, rb);
        ctx.renderbuffer_storage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, 4, 4);
        ctx.framebuffer_renderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb);
        assert_eq!(
            ctx.check_framebuffer_status(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_EXT
        );
        ctx.bind_framebuffer(GL_FRAMEBUFFER, 0);
        ctx.framebuffer_texture_2d(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 0);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        assert_eq!(
            ctx.check_framebuffer_status(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_COMPLETE
        );
    }

    #[test]
    fn buffers() {
        let mut ctx = Context::new(4, 4);
        ctx.buffer_data(GL_ARRAY_BUFFER, 4, None, GL_STATIC_DRAW);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        let b = ctx.gen_buffers(1)[0];
        ctx.bind_buffer(GL_ARRAY_BUFFER, b);
        ctx.buffer_data(GL_ARRAY_BUFFER, 8, Some(&[1, 2, 3]), GL_STATIC_DRAW);
        ctx.buffer_sub_data(GL_ARRAY_BUFFER, 6, &[9, 9]);
        assert_eq!(
            ctx.get_buffer_sub_data(GL_ARRAY_BUFFER, 0, 8),
            vec![1, 2, 3, 0, 0, 0, 9, 9]
        );
        ctx.buffer_sub_data(GL_ARRAY_BUFFER, 7, &[9, 9]);
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.buffer_data(GL_ARRAY_BUFFER, 8, None, 0);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    }
}
