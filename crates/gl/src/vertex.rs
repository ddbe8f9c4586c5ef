//! Vertex specification (GL 2.1 §2.7-2.9): current attribute values,
//! glBegin/glEnd, client vertex arrays and their fetch.
//!
//! Array data is either an offset into the buffer object that was bound to
//! GL_ARRAY_BUFFER when the pointer was specified, or a byte copy of client
//! memory ([`ArrayData::Client`]): a Rust context cannot hold C pointers, so
//! callers (and a C ABI) hand over the bytes the draw will read.

use crate::enums::*;
use crate::{Context, MAX_TEXTURE_UNITS, MAX_VERTEX_ATTRIBS};
use std::sync::Arc;

/// Where an array's bytes are.
#[derive(Clone, Debug, PartialEq)]
pub enum ArrayData {
    /// Byte offset into the buffer bound when the pointer was specified
    /// (with no buffer bound, a null client pointer: reads give defaults).
    Offset(usize),
    /// Client memory, copied.
    Client(Arc<[u8]>),
}

impl Default for ArrayData {
    fn default() -> Self {
        ArrayData::Offset(0)
    }
}

impl ArrayData {
    pub fn from_bytes(b: &[u8]) -> ArrayData {
        ArrayData::Client(Arc::from(b))
    }

    pub fn from_f32(v: &[f32]) -> ArrayData {
        let b: Vec<u8> = v.iter().flat_map(|f| f.to_le_bytes()).collect();
        ArrayData::Client(Arc::from(b))
    }

    pub fn from_u32(v: &[u32]) -> ArrayData {
        let b: Vec<u8> = v.iter().flat_map(|f| f.to_le_bytes()).collect();
        ArrayData::Client(Arc::from(b))
    }

    pub fn from_u16(v: &[u16]) -> ArrayData {
        let b: Vec<u8> = v.iter().flat_map(|f| f.to_le_bytes()).collect();
        ArrayData::Client(Arc::from(b))
    }
}

/// One vertex array's state (GL 2.1 Table 6.6/6.7).
#[derive(Clone, Debug, PartialEq)]
pub struct ArrayState {
    pub enabled: bool,
    pub size: i32,
    pub ty: u32,
    pub normalized: bool,
    pub stride: i32,
    /// The buffer bound to GL_ARRAY_BUFFER at pointer time (0: client).
    pub buffer: u32,
    pub data: ArrayData,
    /// Specified by glVertexAttribIPointer: the components are integers
    /// handed to integer shader inputs unconverted (GL 3.3 §2.8).
    pub integer: bool,
    /// Instances per element (glVertexAttribDivisor; 0: one element per
    /// vertex).
    pub divisor: u32,
}

impl ArrayState {
    fn new(size: i32) -> ArrayState {
        ArrayState {
            enabled: false,
            size,
            ty: GL_FLOAT,
            normalized: false,
            stride: 0,
            buffer: 0,
            data: ArrayData::default(),
            integer: false,
            divisor: 0,
        }
    }
}

/// How a current generic attribute value was specified (GL 3.3 §2.7:
/// glVertexAttrib*, glVertexAttribI* with signed or unsigned values).
/// Integer values are kept as their bits in the `f32` slots.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ValueKind {
    #[default]
    Float,
    Int,
    Uint,
}

/// The state a vertex array object holds (GL 3.3 compatibility §2.10,
/// Table 6.5-6.8): every array and the element-array buffer binding.
/// The bound object's state lives in [`VertexState`]'s fields; the others
/// are kept as this (the `vertex_array` module).
#[derive(Clone, Debug, PartialEq)]
pub struct VaoArrays {
    pub vertex_array: ArrayState,
    pub normal_array: ArrayState,
    pub color_array: ArrayState,
    pub secondary_array: ArrayState,
    pub fog_array: ArrayState,
    pub tex_arrays: Vec<ArrayState>,
    pub generic_arrays: Vec<ArrayState>,
    pub element_buffer: u32,
}

impl VaoArrays {
    /// A new object's state (GL 3.3 §2.10: the initial values of the
    /// tables).
    pub fn new() -> VaoArrays {
        let mut normal_array = ArrayState::new(3);
        normal_array.normalized = true;
        let mut color_array = ArrayState::new(4);
        color_array.normalized = true;
        let mut secondary_array = ArrayState::new(3);
        secondary_array.normalized = true;
        VaoArrays {
            vertex_array: ArrayState::new(4),
            normal_array,
            color_array,
            secondary_array,
            fog_array: ArrayState::new(1),
            tex_arrays: vec![ArrayState::new(4); MAX_TEXTURE_UNITS],
            generic_arrays: vec![ArrayState::new(4); MAX_VERTEX_ATTRIBS],
            element_buffer: 0,
        }
    }
}

impl Default for VaoArrays {
    fn default() -> Self {
        VaoArrays::new()
    }
}

/// Which vertex attribute a shader input reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum AttribSource {
    Position,
    Color,
    SecondaryColor,
    Normal,
    FogCoord,
    TexCoord(u8),
    Generic(u8),
}

impl AttribSource {
    /// The source of a built-in attribute name, if it is one.
    pub fn builtin(name: &str) -> Option<AttribSource> {
        Some(match name {
            "gl_Vertex" => AttribSource::Position,
            "gl_Color" => AttribSource::Color,
            "gl_SecondaryColor" => AttribSource::SecondaryColor,
            "gl_Normal" => AttribSource::Normal,
            "gl_FogCoord" => AttribSource::FogCoord,
            _ => {
                let n: u8 = name.strip_prefix("gl_MultiTexCoord")?.parse().ok()?;
                if n as usize >= MAX_TEXTURE_UNITS {
                    return None;
                }
                AttribSource::TexCoord(n)
            }
        })
    }
}

/// A vertex recorded between glBegin and glEnd: every attribute's current
/// value when glVertex was called.
#[derive(Clone, Debug, PartialEq)]
pub struct ImmVertex {
    pub position: [f32; 4],
    pub color: [f32; 4],
    pub secondary: [f32; 4],
    pub normal: [f32; 4],
    pub fog: [f32; 4],
    pub tex: [[f32; 4]; MAX_TEXTURE_UNITS],
    pub generic: [[f32; 4]; MAX_VERTEX_ATTRIBS],
}

/// What a vertex array object name has.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum VaoSlot {
    /// Generated, never bound: no state yet.
    Generated,
    /// Not bound: its state.
    Stored(Box<VaoArrays>),
    /// Bound: its state is in [`VertexState`]'s fields.
    Bound,
}

/// Vertex-specification state.
pub struct VertexState {
    pub color: [f32; 4],
    pub secondary: [f32; 4],
    pub normal: [f32; 4],
    pub fog: [f32; 4],
    pub tex: [[f32; 4]; MAX_TEXTURE_UNITS],
    pub generic: [[f32; 4]; MAX_VERTEX_ATTRIBS],
    /// How each current generic value was specified.
    pub generic_kind: [ValueKind; MAX_VERTEX_ATTRIBS],
    pub vertex_array: ArrayState,
    pub normal_array: ArrayState,
    pub color_array: ArrayState,
    pub secondary_array: ArrayState,
    pub fog_array: ArrayState,
    pub tex_arrays: Vec<ArrayState>,
    pub generic_arrays: Vec<ArrayState>,
    pub client_active_texture: u32,
    pub begin_mode: Option<u32>,
    pub immediate: Vec<ImmVertex>,
    pub array_buffer: u32,
    pub element_buffer: u32,
    /// The bound vertex array object (0: the default one).
    pub vao: u32,
    /// Every vertex array object name, and the state of those not bound.
    pub(crate) vaos: std::collections::BTreeMap<u32, VaoSlot>,
    /// glPrimitiveRestartIndex.
    pub restart_index: u32,
}

/// Vertices kept between glBegin and glEnd at most (more are dropped).
pub const MAX_IMMEDIATE_VERTICES: usize = 1 << 20;

impl VertexState {
    pub fn new() -> VertexState {
        let VaoArrays {
            vertex_array,
            normal_array,
            color_array,
            secondary_array,
            fog_array,
            tex_arrays,
            generic_arrays,
            element_buffer,
        } = VaoArrays::new();
        VertexState {
            color: [1.0; 4],
            secondary: [0.0, 0.0, 0.0, 1.0],
            normal: [0.0, 0.0, 1.0, 1.0],
            fog: [0.0, 0.0, 0.0, 1.0],
            tex: [[0.0, 0.0, 0.0, 1.0]; MAX_TEXTURE_UNITS],
            generic: [[0.0, 0.0, 0.0, 1.0]; MAX_VERTEX_ATTRIBS],
            generic_kind: [ValueKind::Float; MAX_VERTEX_ATTRIBS],
            vertex_array,
            normal_array,
            color_array,
            secondary_array,
            fog_array,
            tex_arrays,
            generic_arrays,
            client_active_texture: 0,
            begin_mode: None,
            immediate: Vec::new(),
            array_buffer: 0,
            element_buffer,
            vao: 0,
            vaos: [(0, VaoSlot::Bound)].into(),
            restart_index: 0,
        }
    }

    pub fn current_color(&self) -> [f32; 4] {
        self.color
    }

    /// The array that feeds `src`, if enabled. Generic attribute 0 and the
    /// vertex position alias (GL 2.1 §2.7): the generic array wins.
    pub fn array_for(&self, src: AttribSource) -> Option<&ArrayState> {
        let a = match src {
            AttribSource::Position | AttribSource::Generic(0) => {
                let g = &self.generic_arrays[0];
                if g.enabled {
                    g
                } else {
                    &self.vertex_array
                }
            }
            AttribSource::Color => &self.color_array,
            AttribSource::SecondaryColor => &self.secondary_array,
            AttribSource::Normal => &self.normal_array,
            AttribSource::FogCoord => &self.fog_array,
            AttribSource::TexCoord(i) => self.tex_arrays.get(i as usize)?,
            AttribSource::Generic(i) => self.generic_arrays.get(i as usize)?,
        };
        a.enabled.then_some(a)
    }

    /// The current value of `src` (used when its array is disabled).
    pub fn current_value(&self, src: AttribSource) -> [f32; 4] {
        match src {
            AttribSource::Position => [0.0, 0.0, 0.0, 1.0],
            AttribSource::Color => self.color,
            AttribSource::SecondaryColor => self.secondary,
            AttribSource::Normal => self.normal,
            AttribSource::FogCoord => self.fog,
            AttribSource::TexCoord(i) => self
                .tex
                .get(i as usize)
                .copied()
                .unwrap_or([0.0, 0.0, 0.0, 1.0]),
            AttribSource::Generic(i) => match self.current_generic(i as usize) {
                Some((v, kind)) => float_view(v, kind),
                None => [0.0, 0.0, 0.0, 1.0],
            },
        }
    }

    /// Current generic value `i` as stored (integer values as bits) and
    /// how it was specified.
    pub fn current_generic(&self, i: usize) -> Option<([f32; 4], ValueKind)> {
        Some((*self.generic.get(i)?, *self.generic_kind.get(i)?))
    }

    pub(crate) fn snapshot(&self, position: [f32; 4]) -> ImmVertex {
        ImmVertex {
            position,
            color: self.color,
            secondary: self.secondary,
            normal: self.normal,
            fog: self.fog,
            tex: self.tex,
            generic: self.generic,
        }
    }
}

impl Default for VertexState {
    fn default() -> Self {
        VertexState::new()
    }
}

impl ImmVertex {
    pub fn value(&self, src: AttribSource) -> [f32; 4] {
        match src {
            AttribSource::Position | AttribSource::Generic(0) => self.position,
            AttribSource::Color => self.color,
            AttribSource::SecondaryColor => self.secondary,
            AttribSource::Normal => self.normal,
            AttribSource::FogCoord => self.fog,
            AttribSource::TexCoord(i) => self
                .tex
                .get(i as usize)
                .copied()
                .unwrap_or([0.0, 0.0, 0.0, 1.0]),
            AttribSource::Generic(i) => self
                .generic
                .get(i as usize)
                .copied()
                .unwrap_or([0.0, 0.0, 0.0, 1.0]),
        }
    }
}

/// A stored value as floats: integer values (kept as bits) converted.
pub fn float_view(v: [f32; 4], kind: ValueKind) -> [f32; 4] {
    match kind {
        ValueKind::Float => v,
        ValueKind::Int => v.map(|x| x.to_bits() as i32 as f32),
        ValueKind::Uint => v.map(|x| x.to_bits() as f32),
    }
}

/// A stored value as the bits of an integer shader input of `want`
/// (Int or Uint): integer values as they are, float values converted
/// (GL leaves a float value read by an integer input undefined; this is
/// the value's integer part, saturated).
pub fn integer_bits(v: [f32; 4], kind: ValueKind, want: ValueKind) -> [u32; 4] {
    match kind {
        ValueKind::Int | ValueKind::Uint => v.map(f32::to_bits),
        ValueKind::Float if want == ValueKind::Uint => v.map(|x| x as u32),
        ValueKind::Float => v.map(|x| x as i32 as u32),
    }
}

/// Reads one element of an integer array (glVertexAttribIPointer):
/// `size` components of `ty` at `at`, signed types sign-extended, missing
/// components from (0, 0, 0, 1). Out-of-range reads give the defaults.
pub fn read_integer_element(bytes: &[u8], at: usize, size: usize, ty: u32) -> [u32; 4] {
    let mut out = [0, 0, 0, 1];
    let Some(cs) = type_size(ty) else {
        return out;
    };
    for (c, o) in out.iter_mut().enumerate().take(size.min(4)) {
        let start = at.saturating_add(c * cs);
        let Some(b) = bytes.get(start..start.saturating_add(cs)) else {
            return [0, 0, 0, 1];
        };
        *o = match (ty, b) {
            (GL_BYTE, [x]) => *x as i8 as i32 as u32,
            (GL_UNSIGNED_BYTE, [x]) => *x as u32,
            (GL_SHORT, [x, y]) => i16::from_le_bytes([*x, *y]) as i32 as u32,
            (GL_UNSIGNED_SHORT, [x, y]) => u16::from_le_bytes([*x, *y]) as u32,
            (_, [x, y, z, w]) => u32::from_le_bytes([*x, *y, *z, *w]),
            _ => 0,
        };
    }
    out
}

/// Bytes per component of an array type (none for the packed types,
/// [`element_size`]).
pub fn type_size(ty: u32) -> Option<usize> {
    Some(match ty {
        GL_BYTE | GL_UNSIGNED_BYTE => 1,
        GL_SHORT | GL_UNSIGNED_SHORT | GL_HALF_FLOAT => 2,
        GL_INT | GL_UNSIGNED_INT | GL_FLOAT => 4,
        GL_DOUBLE => 8,
        _ => return None,
    })
}

/// Whether `ty` packs a whole element into one 32-bit word (GL 3.3 §2.8:
/// GL_INT_2_10_10_10_REV, GL_UNSIGNED_INT_2_10_10_10_REV).
pub fn is_packed(ty: u32) -> bool {
    matches!(ty, GL_INT_2_10_10_10_REV | GL_UNSIGNED_INT_2_10_10_10_REV)
}

/// The size a pointer call takes for four components in B, G, R, A
/// order (GL 3.3 §2.8, ARB_vertex_array_bgra).
pub const SIZE_BGRA: i32 = GL_BGRA as i32;

/// Bytes of one element of an array of `size` components (or
/// [`SIZE_BGRA`]) of `ty`.
pub fn element_size(size: i32, ty: u32) -> Option<usize> {
    if is_packed(ty) {
        return Some(4);
    }
    let n = if size == SIZE_BGRA {
        4
    } else {
        size.clamp(1, 4) as usize
    };
    Some(n * type_size(ty)?)
}

/// A half float's value (GL 3.3 §2.1.2).
fn half_to_f32(h: u16) -> f32 {
    let sign = if h & 0x8000 != 0 { -1.0 } else { 1.0 };
    let e = ((h >> 10) & 0x1f) as i32;
    let m = (h & 0x3ff) as f32;
    sign * match e {
        0 => m * (2.0f32).powi(-24),
        31 if m == 0.0 => f32::INFINITY,
        31 => f32::NAN,
        _ => (1.0 + m / 1024.0) * (2.0f32).powi(e - 15),
    }
}

/// The four fields of a packed 2_10_10_10 word (x in the low bits), as
/// values (GL 3.3 §2.8, Table 2.7), normalized per §2.1.6 when asked.
pub fn unpack_2_10_10_10(word: u32, ty: u32, normalized: bool) -> [f32; 4] {
    let bits = [10u32, 10, 10, 2];
    let mut out = [0.0; 4];
    let mut shift = 0;
    for (o, b) in out.iter_mut().zip(bits) {
        let field = (word >> shift) & ((1 << b) - 1);
        shift += b;
        let max = ((1u32 << b) - 1) as f32;
        *o = if ty == GL_INT_2_10_10_10_REV {
            // Sign-extended from b bits.
            let v = ((field << (32 - b)) as i32 >> (32 - b)) as f32;
            if normalized {
                (2.0 * v + 1.0) / max
            } else {
                v
            }
        } else if normalized {
            field as f32 / max
        } else {
            field as f32
        };
    }
    out
}

/// Reads one element of an array: `size` components (or
/// [`SIZE_BGRA`], as usize) of `ty` starting at `at`, normalized per
/// GL 2.1 Table 2.9 when asked, missing components from (0, 0, 0, 1).
/// Out-of-range reads give the defaults.
pub fn read_element(bytes: &[u8], at: usize, size: usize, ty: u32, normalized: bool) -> [f32; 4] {
    let bgra = size == SIZE_BGRA as usize;
    if is_packed(ty) {
        let Some(&[a, b, c, d]) = bytes.get(at..at.saturating_add(4)) else {
            return [0.0, 0.0, 0.0, 1.0];
        };
        let mut v = unpack_2_10_10_10(u32::from_le_bytes([a, b, c, d]), ty, normalized);
        if bgra {
            v.swap(0, 2);
        }
        return v;
    }
    let mut out = [0.0, 0.0, 0.0, 1.0];
    let Some(cs) = type_size(ty) else {
        return out;
    };
    let n = if bgra { 4 } else { size.min(4) };
    for (c, o) in out.iter_mut().enumerate().take(n) {
        let start = at.saturating_add(c * cs);
        let Some(b) = bytes.get(start..start.saturating_add(cs)) else {
            return [0.0, 0.0, 0.0, 1.0];
        };
        let mut raw = [0u8; 8];
        raw[..cs].copy_from_slice(b);
        *o = match ty {
            GL_BYTE => {
                let v = raw[0] as i8 as f64;
                if normalized {
                    ((2.0 * v + 1.0) / 255.0) as f32
                } else {
                    v as f32
                }
            }
            GL_UNSIGNED_BYTE => {
                let v = raw[0] as f64;
                if normalized {
                    (v / 255.0) as f32
                } else {
                    v as f32
                }
            }
            GL_SHORT => {
                let v = i16::from_le_bytes([raw[0], raw[1]]) as f64;
                if normalized {
                    ((2.0 * v + 1.0) / 65535.0) as f32
                } else {
                    v as f32
                }
            }
            GL_UNSIGNED_SHORT => {
                let v = u16::from_le_bytes([raw[0], raw[1]]) as f64;
                if normalized {
                    (v / 65535.0) as f32
                } else {
                    v as f32
                }
            }
            GL_INT => {
                let v = i32::from_le_bytes([raw[0], raw[1], raw[2], raw[3]]) as f64;
                if normalized {
                    ((2.0 * v + 1.0) / 4294967295.0) as f32
                } else {
                    v as f32
                }
            }
            GL_UNSIGNED_INT => {
                let v = u32::from_le_bytes([raw[0], raw[1], raw[2], raw[3]]) as f64;
                if normalized {
                    (v / 4294967295.0) as f32
                } else {
                    v as f32
                }
            }
            GL_FLOAT => f32::from_le_bytes([raw[0], raw[1], raw[2], raw[3]]),
            GL_HALF_FLOAT => half_to_f32(u16::from_le_bytes([raw[0], raw[1]])),
            _ => f64::from_le_bytes(raw) as f32,
        };
    }
    if bgra {
        out.swap(0, 2);
    }
    out
}

impl Context {
    /// Resolves an array's bytes (client copy or buffer store).
    pub(crate) fn array_bytes(&self, a: &ArrayState) -> Option<(Arc<[u8]>, usize)> {
        match &a.data {
            ArrayData::Client(b) => Some((b.clone(), 0)),
            ArrayData::Offset(off) if a.buffer != 0 => {
                let b = self.objects.buffers.get(&a.buffer)?;
                Some((b.data.clone(), *off))
            }
            ArrayData::Offset(_) => None,
        }
    }

    /// The value of attribute `src` for array element `index`.
    pub fn fetch_attrib(&self, src: AttribSource, index: u32) -> [f32; 4] {
        match self.va.array_for(src) {
            Some(a) => {
                let Some((bytes, base)) = self.array_bytes(a) else {
                    return [0.0, 0.0, 0.0, 1.0];
                };
                let stride = if a.stride > 0 {
                    a.stride as usize
                } else {
                    element_size(a.size, a.ty).unwrap_or(16)
                };
                let at = base.saturating_add(stride.saturating_mul(index as usize));
                read_element(&bytes, at, a.size.max(1) as usize, a.ty, a.normalized)
            }
            None => self.va.current_value(src),
        }
    }

    fn client_array_mut(&mut self, cap: u32) -> Option<&mut ArrayState> {
        let unit = self.va.client_active_texture as usize;
        Some(match cap {
            GL_VERTEX_ARRAY => &mut self.va.vertex_array,
            GL_NORMAL_ARRAY => &mut self.va.normal_array,
            GL_COLOR_ARRAY => &mut self.va.color_array,
            GL_SECONDARY_COLOR_ARRAY => &mut self.va.secondary_array,
            GL_FOG_COORD_ARRAY => &mut self.va.fog_array,
            GL_TEXTURE_COORD_ARRAY => self.va.tex_arrays.get_mut(unit)?,
            _ => return None,
        })
    }

    /// glIsEnabled for the client arrays.
    pub(crate) fn client_state_enabled(&mut self, cap: u32) -> Option<bool> {
        if cap == GL_INDEX_ARRAY || cap == GL_EDGE_FLAG_ARRAY {
            return Some(false);
        }
        self.client_array_mut(cap).map(|a| a.enabled)
    }

    fn set_client_state(&mut self, cap: u32, on: bool) {
        if cap == GL_INDEX_ARRAY || cap == GL_EDGE_FLAG_ARRAY {
            return;
        }
        match self.client_array_mut(cap) {
            Some(a) => a.enabled = on,
            None => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glEnableClientState.
    pub fn enable_client_state(&mut self, cap: u32) {
        self.set_client_state(cap, true);
    }

    /// glDisableClientState.
    pub fn disable_client_state(&mut self, cap: u32) {
        self.set_client_state(cap, false);
    }

    /// glClientActiveTexture.
    pub fn client_active_texture(&mut self, unit: u32) {
        let i = unit.wrapping_sub(GL_TEXTURE0);
        if i as usize >= MAX_TEXTURE_UNITS {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        self.va.client_active_texture = i;
    }

    /// glEnableVertexAttribArray.
    pub fn enable_vertex_attrib_array(&mut self, index: u32) {
        self.set_attrib_array(index, true);
    }

    /// glDisableVertexAttribArray.
    pub fn disable_vertex_attrib_array(&mut self, index: u32) {
        self.set_attrib_array(index, false);
    }

    fn set_attrib_array(&mut self, index: u32, on: bool) {
        if self.reject_in_begin() {
            return;
        }
        match self.va.generic_arrays.get_mut(index as usize) {
            Some(a) => a.enabled = on,
            None => self.set_error(GL_INVALID_VALUE),
        }
    }

    /// Common checks and storage of the gl*Pointer calls.
    #[allow(clippy::too_many_arguments)]
    fn set_pointer(
        &mut self,
        which: PointerTarget,
        size: i32,
        sizes: &[i32],
        ty: u32,
        types: &[u32],
        normalized: bool,
        stride: i32,
        data: ArrayData,
    ) {
        if self.reject_in_begin() {
            return;
        }
        if !sizes.contains(&size) || stride < 0 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if !types.contains(&ty) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let buffer = self.va.array_buffer;
        // Client memory is the default object's alone (GL 3.3 §2.8: a
        // non-null pointer with no buffer bound while a vertex array
        // object is bound).
        // The core profile has no default object and no client arrays
        // (GL 3.3 core appendix E.2.2).
        if (self.va.vao != 0 && buffer == 0 && !matches!(data, ArrayData::Offset(0)))
            || (self.is_core() && self.va.vao == 0)
        {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        let unit = self.va.client_active_texture as usize;
        let a = match which {
            PointerTarget::Vertex => &mut self.va.vertex_array,
            PointerTarget::Normal => &mut self.va.normal_array,
            PointerTarget::Color => &mut self.va.color_array,
            PointerTarget::Secondary => &mut self.va.secondary_array,
            PointerTarget::Fog => &mut self.va.fog_array,
            PointerTarget::TexCoord => match self.va.tex_arrays.get_mut(unit) {
                Some(a) => a,
                None => return,
            },
            PointerTarget::Generic(i) | PointerTarget::GenericInteger(i) => {
                match self.va.generic_arrays.get_mut(i as usize) {
                    Some(a) => a,
                    None => {
                        self.set_error(GL_INVALID_VALUE);
                        return;
                    }
                }
            }
        };
        a.size = size;
        a.ty = ty;
        a.normalized = normalized;
        a.stride = stride;
        a.buffer = buffer;
        a.data = data;
        a.integer = matches!(which, PointerTarget::GenericInteger(_));
    }

    /// glVertexPointer.
    pub fn vertex_pointer(&mut self, size: i32, ty: u32, stride: i32, data: ArrayData) {
        let types = [GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE];
        self.set_pointer(
            PointerTarget::Vertex,
            size,
            &[2, 3, 4],
            ty,
            &types,
            false,
            stride,
            data,
        );
    }

    /// glNormalPointer.
    pub fn normal_pointer(&mut self, ty: u32, stride: i32, data: ArrayData) {
        let types = [GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE];
        self.set_pointer(
            PointerTarget::Normal,
            3,
            &[3],
            ty,
            &types,
            true,
            stride,
            data,
        );
    }

    /// glColorPointer.
    pub fn color_pointer(&mut self, size: i32, ty: u32, stride: i32, data: ArrayData) {
        self.set_pointer(
            PointerTarget::Color,
            size,
            &[3, 4],
            ty,
            &ALL_TYPES,
            true,
            stride,
            data,
        );
    }

    /// glSecondaryColorPointer.
    pub fn secondary_color_pointer(&mut self, size: i32, ty: u32, stride: i32, data: ArrayData) {
        self.set_pointer(
            PointerTarget::Secondary,
            size,
            &[3],
            ty,
            &ALL_TYPES,
            true,
            stride,
            data,
        );
    }

    /// glFogCoordPointer.
    pub fn fog_coord_pointer(&mut self, ty: u32, stride: i32, data: ArrayData) {
        let types = [GL_FLOAT, GL_DOUBLE];
        self.set_pointer(PointerTarget::Fog, 1, &[1], ty, &types, false, stride, data);
    }

    /// glTexCoordPointer (for the client active texture unit).
    pub fn tex_coord_pointer(&mut self, size: i32, ty: u32, stride: i32, data: ArrayData) {
        let types = [GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE];
        self.set_pointer(
            PointerTarget::TexCoord,
            size,
            &[1, 2, 3, 4],
            ty,
            &types,
            false,
            stride,
            data,
        );
    }

    /// glVertexAttribPointer.
    pub fn vertex_attrib_pointer(
        &mut self,
        index: u32,
        size: i32,
        ty: u32,
        normalized: bool,
        stride: i32,
        data: ArrayData,
    ) {
        if index as usize >= MAX_VERTEX_ATTRIBS {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let sizes = [1, 2, 3, 4, SIZE_BGRA];
        let types = [
            GL_BYTE,
            GL_UNSIGNED_BYTE,
            GL_SHORT,
            GL_UNSIGNED_SHORT,
            GL_INT,
            GL_UNSIGNED_INT,
            GL_FLOAT,
            GL_DOUBLE,
            GL_HALF_FLOAT,
            GL_INT_2_10_10_10_REV,
            GL_UNSIGNED_INT_2_10_10_10_REV,
        ];
        // GL 3.3 §2.8: BGRA only for unsigned bytes and the packed types,
        // normalized; the packed types only with four components.
        let bgra = size == SIZE_BGRA;
        if sizes.contains(&size)
            && types.contains(&ty)
            && stride >= 0
            && ((bgra && !(ty == GL_UNSIGNED_BYTE || is_packed(ty)))
                || (is_packed(ty) && !(size == 4 || bgra))
                || (bgra && !normalized))
        {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        self.set_pointer(
            PointerTarget::Generic(index),
            size,
            &sizes,
            ty,
            &types,
            normalized,
            stride,
            data,
        );
    }

    /// glVertexAttribIPointer: integer components, never converted
    /// (GL 3.3 §2.8; float types are GL_INVALID_ENUM).
    pub fn vertex_attrib_i_pointer(
        &mut self,
        index: u32,
        size: i32,
        ty: u32,
        stride: i32,
        data: ArrayData,
    ) {
        if index as usize >= MAX_VERTEX_ATTRIBS {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        self.set_pointer(
            PointerTarget::GenericInteger(index),
            size,
            &[1, 2, 3, 4],
            ty,
            &INTEGER_TYPES,
            false,
            stride,
            data,
        );
    }

    /// glVertexAttribP{1,2,3,4}ui: the first `components` fields of a
    /// packed 2_10_10_10 word (GL 3.3 §2.7), the others from (0, 0, 0, 1).
    pub fn vertex_attrib_p(
        &mut self,
        index: u32,
        ty: u32,
        normalized: bool,
        components: usize,
        value: u32,
    ) {
        if !is_packed(ty) {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        let mut v = [0.0, 0.0, 0.0, 1.0];
        let fields = unpack_2_10_10_10(value, ty, normalized);
        v[..components.min(4)].copy_from_slice(&fields[..components.min(4)]);
        self.vertex_attrib_4f(index, v[0], v[1], v[2], v[3]);
    }

    /// glVertexAttribDivisor (GL 3.3 §2.8.2).
    pub fn vertex_attrib_divisor(&mut self, index: u32, divisor: u32) {
        if self.reject_in_begin() {
            return;
        }
        match self.va.generic_arrays.get_mut(index as usize) {
            Some(a) => a.divisor = divisor,
            None => self.set_error(GL_INVALID_VALUE),
        }
    }

    /// glVertexAttribI4i (the other glVertexAttribI* forms fill in
    /// (0, 0, 0, 1) and call this or [`Context::vertex_attrib_i4ui`]).
    /// Index 0 inside glBegin/glEnd emits a vertex, as glVertexAttrib4f.
    pub fn vertex_attrib_i4i(&mut self, index: u32, v: [i32; 4]) {
        self.set_integer_attrib(index, v.map(|x| x as u32), ValueKind::Int);
    }

    /// glVertexAttribI4ui.
    pub fn vertex_attrib_i4ui(&mut self, index: u32, v: [u32; 4]) {
        self.set_integer_attrib(index, v, ValueKind::Uint);
    }

    fn set_integer_attrib(&mut self, index: u32, v: [u32; 4], kind: ValueKind) {
        if index as usize >= MAX_VERTEX_ATTRIBS {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        let f = float_view(v.map(f32::from_bits), kind);
        if index == 0 {
            self.vertex_4f(f[0], f[1], f[2], f[3]);
        }
        self.va.generic[index as usize] = v.map(f32::from_bits);
        self.va.generic_kind[index as usize] = kind;
    }

    /// glGetVertexAttribI{i,ui}v with GL_CURRENT_VERTEX_ATTRIB: the
    /// current value's integer bits (a float value converted).
    pub fn get_current_vertex_attrib_integer(&mut self, index: u32, unsigned: bool) -> [u32; 4] {
        if index == 0 || index as usize >= MAX_VERTEX_ATTRIBS {
            self.set_error(if index == 0 {
                GL_INVALID_OPERATION
            } else {
                GL_INVALID_VALUE
            });
            return [0; 4];
        }
        let want = if unsigned {
            ValueKind::Uint
        } else {
            ValueKind::Int
        };
        integer_bits(
            self.va.generic[index as usize],
            self.va.generic_kind[index as usize],
            want,
        )
    }

    // ---- current values ----

    /// glColor4f.
    pub fn color_4f(&mut self, r: f32, g: f32, b: f32, a: f32) {
        self.va.color = [r, g, b, a];
        self.track_color_material();
    }

    /// glColor3f.
    pub fn color_3f(&mut self, r: f32, g: f32, b: f32) {
        self.color_4f(r, g, b, 1.0);
    }

    /// glColor4fv.
    pub fn color_4fv(&mut self, v: &[f32; 4]) {
        self.color_4f(v[0], v[1], v[2], v[3]);
    }

    /// glColor3fv.
    pub fn color_3fv(&mut self, v: &[f32; 3]) {
        self.color_4f(v[0], v[1], v[2], 1.0);
    }

    /// glColor4ub.
    pub fn color_4ub(&mut self, r: u8, g: u8, b: u8, a: u8) {
        let n = |x: u8| x as f32 / 255.0;
        self.color_4f(n(r), n(g), n(b), n(a));
    }

    /// glColor3ub.
    pub fn color_3ub(&mut self, r: u8, g: u8, b: u8) {
        self.color_4ub(r, g, b, 255);
    }

    /// glSecondaryColor3f.
    pub fn secondary_color_3f(&mut self, r: f32, g: f32, b: f32) {
        self.va.secondary = [r, g, b, 1.0];
    }

    /// glNormal3f.
    pub fn normal_3f(&mut self, x: f32, y: f32, z: f32) {
        self.va.normal = [x, y, z, 1.0];
    }

    /// glNormal3fv.
    pub fn normal_3fv(&mut self, v: &[f32; 3]) {
        self.normal_3f(v[0], v[1], v[2]);
    }

    /// glFogCoordf.
    pub fn fog_coordf(&mut self, f: f32) {
        self.va.fog = [f, 0.0, 0.0, 1.0];
    }

    /// glMultiTexCoord4f.
    pub fn multi_tex_coord_4f(&mut self, target: u32, s: f32, t: f32, r: f32, q: f32) {
        let i = target.wrapping_sub(GL_TEXTURE0) as usize;
        match self.va.tex.get_mut(i) {
            Some(c) => *c = [s, t, r, q],
            None => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glMultiTexCoord1f.
    pub fn multi_tex_coord_1f(&mut self, target: u32, s: f32) {
        self.multi_tex_coord_4f(target, s, 0.0, 0.0, 1.0);
    }

    /// glMultiTexCoord2f.
    pub fn multi_tex_coord_2f(&mut self, target: u32, s: f32, t: f32) {
        self.multi_tex_coord_4f(target, s, t, 0.0, 1.0);
    }

    /// glMultiTexCoord3f.
    pub fn multi_tex_coord_3f(&mut self, target: u32, s: f32, t: f32, r: f32) {
        self.multi_tex_coord_4f(target, s, t, r, 1.0);
    }

    /// glMultiTexCoord4fv.
    pub fn multi_tex_coord_4fv(&mut self, target: u32, v: &[f32; 4]) {
        self.multi_tex_coord_4f(target, v[0], v[1], v[2], v[3]);
    }

    /// glTexCoord4f (unit 0).
    pub fn tex_coord_4f(&mut self, s: f32, t: f32, r: f32, q: f32) {
        self.va.tex[0] = [s, t, r, q];
    }

    /// glTexCoord1f.
    pub fn tex_coord_1f(&mut self, s: f32) {
        self.tex_coord_4f(s, 0.0, 0.0, 1.0);
    }

    /// glTexCoord2f.
    pub fn tex_coord_2f(&mut self, s: f32, t: f32) {
        self.tex_coord_4f(s, t, 0.0, 1.0);
    }

    /// glTexCoord3f.
    pub fn tex_coord_3f(&mut self, s: f32, t: f32, r: f32) {
        self.tex_coord_4f(s, t, r, 1.0);
    }

    /// glTexCoord4fv.
    pub fn tex_coord_4fv(&mut self, v: &[f32; 4]) {
        self.tex_coord_4f(v[0], v[1], v[2], v[3]);
    }

    /// glVertexAttrib4f. Index 0 is the vertex position: inside
    /// glBegin/glEnd it emits a vertex (GL 2.1 §2.7).
    pub fn vertex_attrib_4f(&mut self, index: u32, x: f32, y: f32, z: f32, w: f32) {
        if index as usize >= MAX_VERTEX_ATTRIBS {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        if index == 0 {
            self.vertex_4f(x, y, z, w);
        }
        self.va.generic[index as usize] = [x, y, z, w];
        self.va.generic_kind[index as usize] = ValueKind::Float;
    }

    /// glVertexAttrib1f.
    pub fn vertex_attrib_1f(&mut self, index: u32, x: f32) {
        self.vertex_attrib_4f(index, x, 0.0, 0.0, 1.0);
    }

    /// glVertexAttrib2f.
    pub fn vertex_attrib_2f(&mut self, index: u32, x: f32, y: f32) {
        self.vertex_attrib_4f(index, x, y, 0.0, 1.0);
    }

    /// glVertexAttrib3f.
    pub fn vertex_attrib_3f(&mut self, index: u32, x: f32, y: f32, z: f32) {
        self.vertex_attrib_4f(index, x, y, z, 1.0);
    }

    /// glVertexAttrib4fv.
    pub fn vertex_attrib_4fv(&mut self, index: u32, v: &[f32; 4]) {
        self.vertex_attrib_4f(index, v[0], v[1], v[2], v[3]);
    }

    /// glVertexAttrib4Nub.
    pub fn vertex_attrib_4nub(&mut self, index: u32, x: u8, y: u8, z: u8, w: u8) {
        let n = |v: u8| v as f32 / 255.0;
        self.vertex_attrib_4f(index, n(x), n(y), n(z), n(w));
    }

    /// glGetVertexAttribfv with GL_CURRENT_VERTEX_ATTRIB.
    pub fn get_current_vertex_attrib(&mut self, index: u32) -> [f32; 4] {
        if index == 0 || index as usize >= MAX_VERTEX_ATTRIBS {
            self.set_error(if index == 0 {
                GL_INVALID_OPERATION
            } else {
                GL_INVALID_VALUE
            });
            return [0.0; 4];
        }
        let i = index as usize;
        float_view(self.va.generic[i], self.va.generic_kind[i])
    }

    // ---- glBegin / glEnd ----

    /// glBegin.
    pub fn begin(&mut self, mode: u32) {
        if self.in_begin_end() {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        if mode > GL_POLYGON {
            self.set_error(GL_INVALID_ENUM);
            return;
        }
        // The mode must make transform feedback's primitives while it
        // is active (GL 3.3 compatibility §2.20).
        if !self.feedback_allows(mode) {
            return;
        }
        self.va.begin_mode = Some(mode);
        self.va.immediate.clear();
    }

    /// glVertex4f: outside glBegin/glEnd it has no effect.
    pub fn vertex_4f(&mut self, x: f32, y: f32, z: f32, w: f32) {
        if self.va.begin_mode.is_some() && self.va.immediate.len() < MAX_IMMEDIATE_VERTICES {
            let v = self.va.snapshot([x, y, z, w]);
            self.va.immediate.push(v);
        }
    }

    /// glVertex2f.
    pub fn vertex_2f(&mut self, x: f32, y: f32) {
        self.vertex_4f(x, y, 0.0, 1.0);
    }

    /// glVertex3f.
    pub fn vertex_3f(&mut self, x: f32, y: f32, z: f32) {
        self.vertex_4f(x, y, z, 1.0);
    }

    /// glVertex3fv.
    pub fn vertex_3fv(&mut self, v: &[f32; 3]) {
        self.vertex_4f(v[0], v[1], v[2], 1.0);
    }

    /// glVertex4fv.
    pub fn vertex_4fv(&mut self, v: &[f32; 4]) {
        self.vertex_4f(v[0], v[1], v[2], v[3]);
    }

    /// glEnd: draws the recorded vertices.
    pub fn end(&mut self) {
        let Some(mode) = self.va.begin_mode.take() else {
            self.set_error(GL_INVALID_OPERATION);
            return;
        };
        let verts = std::mem::take(&mut self.va.immediate);
        self.draw_immediate(mode, &verts);
    }

    /// glRectf: a polygon (x1,y1) (x2,y1) (x2,y2) (x1,y2) (GL 2.1 §2.10).
    pub fn rectf(&mut self, x1: f32, y1: f32, x2: f32, y2: f32) {
        if self.reject_in_begin() {
            return;
        }
        self.begin(GL_POLYGON);
        self.vertex_2f(x1, y1);
        self.vertex_2f(x2, y1);
        self.vertex_2f(x2, y2);
        self.vertex_2f(x1, y2);
        self.end();
    }
}

const ALL_TYPES: [u32; 8] = [
    GL_BYTE,
    GL_UNSIGNED_BYTE,
    GL_SHORT,
    GL_UNSIGNED_SHORT,
    GL_INT,
    GL_UNSIGNED_INT,
    GL_FLOAT,
    GL_DOUBLE,
];

const INTEGER_TYPES: [u32; 6] = [
    GL_BYTE,
    GL_UNSIGNED_BYTE,
    GL_SHORT,
    GL_UNSIGNED_SHORT,
    GL_INT,
    GL_UNSIGNED_INT,
];

#[derive(Clone, Copy)]
enum PointerTarget {
    Vertex,
    Normal,
    Color,
    Secondary,
    Fog,
    TexCoord,
    Generic(u32),
    /// glVertexAttribIPointer.
    GenericInteger(u32),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalization_table_2_9() {
        assert_eq!(
            read_element(&[255, 0], 0, 2, GL_UNSIGNED_BYTE, true),
            [1.0, 0.0, 0.0, 1.0]
        );
        assert_eq!(read_element(&[0x7f], 0, 1, GL_BYTE, true)[0], 1.0);
        assert_eq!(read_element(&[0x80], 0, 1, GL_BYTE, true)[0], -1.0);
        assert_eq!(
            read_element(&[200], 0, 1, GL_UNSIGNED_BYTE, false)[0],
            200.0
        );
        // Out of range: defaults.
        assert_eq!(
            read_element(&[1, 2], 0, 3, GL_FLOAT, false),
            [0.0, 0.0, 0.0, 1.0]
        );
    }

    #[test]
    fn fetch_client_arrays_and_current_values() {
        let mut ctx = Context::new(4, 4);
        ctx.vertex_pointer(
            2,
            GL_FLOAT,
            16,
            ArrayData::from_f32(&[1.0, 2.0, 9.0, 9.0, 3.0, 4.0]),
        );
        ctx.enable_client_state(GL_VERTEX_ARRAY);
        assert_eq!(
            ctx.fetch_attrib(AttribSource::Position, 1),
            [3.0, 4.0, 0.0, 1.0]
        );
        ctx.color_4f(0.5, 0.5, 0.5, 0.5);
        assert_eq!(ctx.fetch_attrib(AttribSource::Color, 7), [0.5; 4]);
        ctx.client_active_texture(GL_TEXTURE1);
        ctx.tex_coord_pointer(2, GL_FLOAT, 0, ArrayData::from_f32(&[0.0, 1.0, 2.0, 3.0]));
        ctx.enable_client_state(GL_TEXTURE_COORD_ARRAY);
        assert_eq!(
            ctx.fetch_attrib(AttribSource::TexCoord(1), 1),
            [2.0, 3.0, 0.0, 1.0]
        );
        assert_eq!(
            ctx.fetch_attrib(AttribSource::TexCoord(0), 1),
            [0.0, 0.0, 0.0, 1.0]
        );
        // Generic 0 overrides the vertex array.
        ctx.vertex_attrib_pointer(0, 1, GL_FLOAT, false, 0, ArrayData::from_f32(&[7.0, 8.0]));
        ctx.enable_vertex_attrib_array(0);
        assert_eq!(
            ctx.fetch_attrib(AttribSource::Position, 1),
            [8.0, 0.0, 0.0, 1.0]
        );
        ctx.vertex_attrib_pointer(0, 5, GL_FLOAT, false, 0, ArrayData::Offset(0));
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.vertex_pointer(4, GL_UNSIGNED_BYTE, 0, ArrayData::Offset(0));
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.enable_client_state(GL_LIGHTING);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn half_packed_and_bgra_elements() {
        // 1.0, -2.0, 0.5 as half floats; a subnormal; infinity.
        let halves: Vec<u8> = [0x3c00u16, 0xc000, 0x3800, 0x0001, 0x7c00]
            .iter()
            .flat_map(|h| h.to_le_bytes())
            .collect();
        assert_eq!(
            read_element(&halves, 0, 3, GL_HALF_FLOAT, false),
            [1.0, -2.0, 0.5, 1.0]
        );
        assert_eq!(
            read_element(&halves, 6, 2, GL_HALF_FLOAT, false),
            [2.0f32.powi(-24), f32::INFINITY, 0.0, 1.0]
        );
        // x = 1023, y = -512 (signed), z = 5, w = 3 / -1.
        let word: u32 = 1023 | (512 << 10) | (5 << 20) | (3 << 30);
        let b = word.to_le_bytes();
        assert_eq!(
            read_element(&b, 0, 4, GL_UNSIGNED_INT_2_10_10_10_REV, false),
            [1023.0, 512.0, 5.0, 3.0]
        );
        assert_eq!(
            read_element(&b, 0, 4, GL_INT_2_10_10_10_REV, false),
            [-1.0, -512.0, 5.0, -1.0]
        );
        assert_eq!(
            read_element(&b, 0, 4, GL_UNSIGNED_INT_2_10_10_10_REV, true),
            [1.0, 512.0 / 1023.0, 5.0 / 1023.0, 1.0]
        );
        // Signed normalization (2c + 1) / (2^b - 1): -512 gives -1.
        assert_eq!(read_element(&b, 0, 4, GL_INT_2_10_10_10_REV, true)[1], -1.0);
        assert_eq!(
            read_element(
                &b,
                0,
                SIZE_BGRA as usize,
                GL_UNSIGNED_INT_2_10_10_10_REV,
                false
            ),
            [5.0, 512.0, 1023.0, 3.0]
        );
        assert_eq!(
            read_element(
                &[255, 0, 51, 255],
                0,
                SIZE_BGRA as usize,
                GL_UNSIGNED_BYTE,
                true
            ),
            [0.2, 0.0, 1.0, 1.0]
        );
        assert_eq!(element_size(SIZE_BGRA, GL_UNSIGNED_BYTE), Some(4));
        assert_eq!(element_size(4, GL_INT_2_10_10_10_REV), Some(4));
        assert_eq!(element_size(3, GL_HALF_FLOAT), Some(6));
    }

    #[test]
    fn bgra_and_packed_pointer_rules() {
        let mut ctx = Context::new(4, 4);
        let d = || ArrayData::Offset(0);
        ctx.vertex_attrib_pointer(1, SIZE_BGRA, GL_UNSIGNED_BYTE, true, 0, d());
        ctx.vertex_attrib_pointer(1, 4, GL_INT_2_10_10_10_REV, true, 0, d());
        ctx.vertex_attrib_pointer(1, 3, GL_HALF_FLOAT, false, 0, d());
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        ctx.vertex_attrib_pointer(1, SIZE_BGRA, GL_UNSIGNED_BYTE, false, 0, d());
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.vertex_attrib_pointer(1, SIZE_BGRA, GL_FLOAT, true, 0, d());
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.vertex_attrib_pointer(1, 3, GL_UNSIGNED_INT_2_10_10_10_REV, true, 0, d());
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.vertex_attrib_i_pointer(1, 4, GL_INT_2_10_10_10_REV, 0, d());
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
        ctx.vertex_attrib_i_pointer(1, SIZE_BGRA, GL_UNSIGNED_BYTE, 0, d());
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
        ctx.vertex_attrib_p(2, GL_UNSIGNED_INT_2_10_10_10_REV, false, 3, 7 | (3 << 30));
        assert_eq!(ctx.get_current_vertex_attrib(2), [7.0, 0.0, 0.0, 1.0]);
        ctx.vertex_attrib_p(2, GL_FLOAT, false, 4, 0);
        assert_eq!(ctx.get_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn begin_end_records() {
        let mut ctx = Context::new(4, 4);
        ctx.end();
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.begin(GL_TRIANGLES);
        ctx.begin(GL_TRIANGLES);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.color_3f(1.0, 0.0, 0.0);
        ctx.vertex_2f(0.0, 0.0);
        ctx.enable(GL_BLEND);
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        assert_eq!(ctx.va.immediate.len(), 1);
        assert_eq!(ctx.va.immediate[0].color, [1.0, 0.0, 0.0, 1.0]);
        ctx.end();
        assert!(!ctx.in_begin_end());
    }
}
