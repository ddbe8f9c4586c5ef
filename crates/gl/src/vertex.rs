//! Vertex specification (GL 2.1 §2.7-2.9, GL 3.3 §2.8): the vertex state
//! (current values, arrays, the glBegin/glEnd record), the array pointer
//! calls with their errors, and one element's fetch. Formats and their
//! decoding are `vertex_format`'s; the current-value and immediate-mode
//! calls are `immediate`'s.
//!
//! Array data is either an offset into the buffer object that was bound to
//! GL_ARRAY_BUFFER when the pointer was specified, or a byte copy of client
//! memory ([`ArrayData::Client`]): a Rust context cannot hold C pointers, so
//! callers (and a C ABI) hand over the bytes the draw will read.

use crate::enums::*;
use crate::vertex_format::{
    element_size, float_view, is_packed, read_element, unpack_2_10_10_10, ValueKind, SIZE_BGRA,
};
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
            AttribSource::Generic(i) => match self.current_generic(i as usize) {
                Some((v, kind)) => float_view(v, kind),
                None => [0.0, 0.0, 0.0, 1.0],
            },
            _ => fixed_value(
                src,
                [self.color, self.secondary, self.normal, self.fog],
                &self.tex,
            ),
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
            AttribSource::Generic(i) => self
                .generic
                .get(i as usize)
                .copied()
                .unwrap_or([0.0, 0.0, 0.0, 1.0]),
            _ => fixed_value(
                src,
                [self.color, self.secondary, self.normal, self.fog],
                &self.tex,
            ),
        }
    }
}

/// The value of the fixed-function attribute `src` (colour, secondary
/// colour, normal, fog coordinate or texture coordinates) among `fixed`
/// (those first four, in that order) and the per-unit `tex`, where the
/// current values and an immediate-mode vertex keep them alike; an unknown
/// unit reads (0, 0, 0, 1). The position and generic attributes, which
/// the two answer differently, are the callers'.
fn fixed_value(src: AttribSource, fixed: [[f32; 4]; 4], tex: &[[f32; 4]]) -> [f32; 4] {
    let [color, secondary, normal, fog] = fixed;
    match src {
        AttribSource::Color => color,
        AttribSource::SecondaryColor => secondary,
        AttribSource::Normal => normal,
        AttribSource::FogCoord => fog,
        AttribSource::TexCoord(i) => tex.get(i as usize).copied().unwrap_or([0.0, 0.0, 0.0, 1.0]),
        AttribSource::Position | AttribSource::Generic(_) => [0.0, 0.0, 0.0, 1.0],
    }
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

    /// GL_ARB_vertex_array_bgra's rule for the colour arrays: size GL_BGRA
    /// only with unsigned bytes (GL_INVALID_OPERATION); records the error
    /// and returns true when it applies.
    fn reject_bgra_type(&mut self, size: i32, ty: u32, stride: i32) -> bool {
        let wrong = size == SIZE_BGRA
            && ty != GL_UNSIGNED_BYTE
            && ALL_TYPES.contains(&ty)
            && stride >= 0
            && !self.in_begin_end();
        if wrong {
            self.set_error(GL_INVALID_OPERATION);
        }
        wrong
    }

    /// glColorPointer (size 3, 4 or GL_BGRA).
    pub fn color_pointer(&mut self, size: i32, ty: u32, stride: i32, data: ArrayData) {
        if self.reject_bgra_type(size, ty, stride) {
            return;
        }
        self.set_pointer(
            PointerTarget::Color,
            size,
            &[3, 4, SIZE_BGRA],
            ty,
            &ALL_TYPES,
            true,
            stride,
            data,
        );
    }

    /// glSecondaryColorPointer (size 3 or GL_BGRA).
    pub fn secondary_color_pointer(&mut self, size: i32, ty: u32, stride: i32, data: ArrayData) {
        if self.reject_bgra_type(size, ty, stride) {
            return;
        }
        self.set_pointer(
            PointerTarget::Secondary,
            size,
            &[3, SIZE_BGRA],
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
        // GL 3.3 §2.8: BGRA only for unsigned bytes and the packed types,
        // normalized; the packed types only with four components.
        let bgra = size == SIZE_BGRA;
        if sizes.contains(&size)
            && GENERIC_TYPES.contains(&ty)
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
            &GENERIC_TYPES,
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
}

/// The component types of integer arrays (glVertexAttribIPointer).
const INTEGER_TYPES: [u32; 6] = [
    GL_BYTE,
    GL_UNSIGNED_BYTE,
    GL_SHORT,
    GL_UNSIGNED_SHORT,
    GL_INT,
    GL_UNSIGNED_INT,
];

/// The component types of the fixed-function arrays: the integer ones and
/// the two float ones.
const ALL_TYPES: [u32; 8] = concat(INTEGER_TYPES, [GL_FLOAT, GL_DOUBLE]);

/// The component types of glVertexAttribPointer: those and, from GL 3.3,
/// half floats and the packed 2_10_10_10 words.
const GENERIC_TYPES: [u32; 11] = concat(
    ALL_TYPES,
    [
        GL_HALF_FLOAT,
        GL_INT_2_10_10_10_REV,
        GL_UNSIGNED_INT_2_10_10_10_REV,
    ],
);

/// `a` then `b`, for building one type table from another.
const fn concat<const A: usize, const B: usize, const C: usize>(
    a: [u32; A],
    b: [u32; B],
) -> [u32; C] {
    assert!(A + B == C);
    let mut out = [0; C];
    let mut i = 0;
    while i < C {
        out[i] = if i < A { a[i] } else { b[i - A] };
        i += 1;
    }
    out
}

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
        // GL_ARB_vertex_array_bgra's colour arrays.
        ctx.color_pointer(SIZE_BGRA, GL_UNSIGNED_BYTE, 0, d());
        ctx.secondary_color_pointer(SIZE_BGRA, GL_UNSIGNED_BYTE, 0, d());
        assert_eq!(ctx.get_error(), GL_NO_ERROR);
        assert_eq!(ctx.get_integerv(GL_COLOR_ARRAY_SIZE), vec![SIZE_BGRA]);
        assert_eq!(
            ctx.get_integerv(GL_SECONDARY_COLOR_ARRAY_SIZE),
            vec![SIZE_BGRA]
        );
        ctx.color_pointer(SIZE_BGRA, GL_FLOAT, 0, d());
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.secondary_color_pointer(SIZE_BGRA, GL_SHORT, 0, d());
        assert_eq!(ctx.get_error(), GL_INVALID_OPERATION);
        ctx.color_pointer(2, GL_FLOAT, 0, d());
        assert_eq!(ctx.get_error(), GL_INVALID_VALUE);
    }
}
