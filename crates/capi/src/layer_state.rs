//! The state this crate keeps for a context beside its [`gl::Context`]:
//! display lists ([`Lists`], recorded at the C level), buffer mappings
//! ([`Mapping`]), and the GL 1.x state kept but not applied ([`Legacy`]).
//! Plain data, so that [`crate::context::OsContext`] can hold it without
//! depending on the entry points that use it.

use gl::enums::*;
use std::collections::BTreeMap;
use std::rc::Rc;

// ---- display lists (GL 2.1 §5.4; entry points in crate::lists) ----

/// A recorded command.
pub type Cmd = Box<dyn Fn()>;

/// GL_MAX_LIST_NESTING.
pub const MAX_LIST_NESTING: u32 = 64;

/// Display-list state of one context.
#[derive(Default)]
pub struct Lists {
    pub lists: BTreeMap<u32, Rc<Vec<Cmd>>>,
    /// The list being compiled: name, mode, commands so far.
    pub compiling: Option<(u32, u32, Vec<Cmd>)>,
    /// glCallList nesting depth (recording is off while replaying).
    pub replaying: u32,
    pub base: u32,
}

// ---- buffer mappings (GL 2.1 §2.9; entry points in crate::buffers) ----

/// A mapped buffer: the copy handed to the client and the access asked.
pub struct Mapping {
    pub data: Box<[u8]>,
    pub access: u32,
}

// ---- GL 1.x state kept, not applied (entry points in crate::legacy) ----

/// GL_MAX_PIXEL_MAP_TABLE.
pub const MAX_PIXEL_MAP_TABLE: i32 = 256;
/// GL_MAX_NAME_STACK_DEPTH.
pub const MAX_NAME_STACK_DEPTH: i32 = 64;

/// The state of the GL 1.x calls kept at the C level ([`crate::legacy`]).
pub struct Legacy {
    pub current_index: f32,
    pub clear_index: f32,
    pub index_mask: u32,
    pub index_pointer: usize,
    pub index_type: u32,
    pub index_stride: i32,
    pub edge_flag: bool,
    pub edge_flag_pointer: usize,
    pub edge_flag_stride: i32,
    pub select_buffer: usize,
    pub select_size: i32,
    pub feedback_buffer: usize,
    pub feedback_size: i32,
    pub feedback_type: u32,
    pub line_stipple: (i32, u16),
    pub polygon_stipple: [u8; 128],
    pub sample_coverage: (f32, bool),
    pub pixel_zoom: (f32, f32),
    pub pixel_transfer: BTreeMap<u32, f32>,
    pub pixel_maps: BTreeMap<u32, Vec<f32>>,
    pub accum_clear: [f32; 4],
}

impl Default for Legacy {
    fn default() -> Legacy {
        let mut pixel_transfer = BTreeMap::new();
        for (p, v) in [
            (GL_MAP_COLOR, 0.0),
            (GL_MAP_STENCIL, 0.0),
            (GL_INDEX_SHIFT, 0.0),
            (GL_INDEX_OFFSET, 0.0),
            (GL_RED_SCALE, 1.0),
            (GL_GREEN_SCALE, 1.0),
            (GL_BLUE_SCALE, 1.0),
            (GL_ALPHA_SCALE, 1.0),
            (GL_DEPTH_SCALE, 1.0),
            (GL_RED_BIAS, 0.0),
            (GL_GREEN_BIAS, 0.0),
            (GL_BLUE_BIAS, 0.0),
            (GL_ALPHA_BIAS, 0.0),
            (GL_DEPTH_BIAS, 0.0),
        ] {
            pixel_transfer.insert(p, v);
        }
        let pixel_maps = PIXEL_MAPS.iter().map(|&m| (m, vec![0.0])).collect();
        Legacy {
            current_index: 1.0,
            clear_index: 0.0,
            index_mask: u32::MAX,
            index_pointer: 0,
            index_type: GL_FLOAT,
            index_stride: 0,
            edge_flag: true,
            edge_flag_pointer: 0,
            edge_flag_stride: 0,
            select_buffer: 0,
            select_size: 0,
            feedback_buffer: 0,
            feedback_size: 0,
            feedback_type: GL_2D,
            line_stipple: (1, 0xffff),
            polygon_stipple: [0xff; 128],
            sample_coverage: (1.0, false),
            pixel_zoom: (1.0, 1.0),
            pixel_transfer,
            pixel_maps,
            accum_clear: [0.0; 4],
        }
    }
}

/// The ten pixel maps and, for each, its size query.
pub const PIXEL_MAPS: [u32; 10] = [
    GL_PIXEL_MAP_I_TO_I,
    GL_PIXEL_MAP_S_TO_S,
    GL_PIXEL_MAP_I_TO_R,
    GL_PIXEL_MAP_I_TO_G,
    GL_PIXEL_MAP_I_TO_B,
    GL_PIXEL_MAP_I_TO_A,
    GL_PIXEL_MAP_R_TO_R,
    GL_PIXEL_MAP_G_TO_G,
    GL_PIXEL_MAP_B_TO_B,
    GL_PIXEL_MAP_A_TO_A,
];

impl Legacy {
    /// glGet* values of this state (None: `pname` is not one of them).
    pub fn get(&self, pname: u32) -> Option<Vec<f64>> {
        let l = self;
        let b = |x: bool| x as i32 as f64;
        Some(match pname {
            GL_CURRENT_INDEX => vec![l.current_index as f64],
            GL_INDEX_CLEAR_VALUE => vec![l.clear_index as f64],
            GL_INDEX_WRITEMASK => vec![l.index_mask as f64],
            GL_INDEX_ARRAY_TYPE => vec![l.index_type as f64],
            GL_INDEX_ARRAY_STRIDE => vec![l.index_stride as f64],
            GL_EDGE_FLAG => vec![b(l.edge_flag)],
            GL_EDGE_FLAG_ARRAY_STRIDE => vec![l.edge_flag_stride as f64],
            GL_RENDER_MODE => vec![GL_RENDER as f64],
            GL_SELECTION_BUFFER_SIZE => vec![l.select_size as f64],
            GL_FEEDBACK_BUFFER_SIZE => vec![l.feedback_size as f64],
            GL_FEEDBACK_BUFFER_TYPE => vec![l.feedback_type as f64],
            GL_NAME_STACK_DEPTH => vec![0.0],
            GL_MAX_NAME_STACK_DEPTH => vec![MAX_NAME_STACK_DEPTH as f64],
            GL_LINE_STIPPLE_PATTERN => vec![l.line_stipple.1 as f64],
            GL_LINE_STIPPLE_REPEAT => vec![l.line_stipple.0 as f64],
            GL_SAMPLE_COVERAGE_VALUE => vec![l.sample_coverage.0 as f64],
            GL_SAMPLE_COVERAGE_INVERT => vec![b(l.sample_coverage.1)],
            GL_ZOOM_X => vec![l.pixel_zoom.0 as f64],
            GL_ZOOM_Y => vec![l.pixel_zoom.1 as f64],
            GL_ACCUM_CLEAR_VALUE => l.accum_clear.iter().map(|&x| x as f64).collect(),
            GL_ACCUM_RED_BITS | GL_ACCUM_GREEN_BITS | GL_ACCUM_BLUE_BITS | GL_ACCUM_ALPHA_BITS => {
                vec![0.0]
            }
            GL_INDEX_BITS => vec![0.0],
            GL_INDEX_MODE => vec![0.0],
            GL_RGBA_MODE => vec![1.0],
            GL_MAX_PIXEL_MAP_TABLE => vec![MAX_PIXEL_MAP_TABLE as f64],
            p if PIXEL_MAPS
                .iter()
                .any(|&m| m - GL_PIXEL_MAP_I_TO_I + GL_PIXEL_MAP_I_TO_I_SIZE == p) =>
            {
                let m = p - GL_PIXEL_MAP_I_TO_I_SIZE + GL_PIXEL_MAP_I_TO_I;
                vec![l.pixel_maps.get(&m).map_or(1, |v| v.len()) as f64]
            }
            p => vec![*l.pixel_transfer.get(&p)? as f64],
        })
    }
}
