//! The fixed-function state a draw needs, as plain data.
//!
//! [`PipelineState::default`] is the GL 2.1 initial state except for the
//! viewport, which starts empty (0×0) because the window size is not known
//! here; the gl crate fills it in.

/// A window-space rectangle: lower-left corner and size in pixels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Rect {
    pub x: i32,
    pub y: i32,
    pub w: i32,
    pub h: i32,
}

impl Rect {
    pub const fn new(x: i32, y: i32, w: i32, h: i32) -> Rect {
        Rect { x, y, w, h }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CullFace {
    Front,
    Back,
    FrontAndBack,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum FrontFace {
    #[default]
    Ccw,
    Cw,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum PolygonMode {
    Point,
    Line,
    #[default]
    Fill,
}

/// Comparison functions of the alpha, stencil, depth and shadow tests.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum CompareFunc {
    Never,
    #[default]
    Less,
    Equal,
    LessEqual,
    Greater,
    NotEqual,
    GreaterEqual,
    Always,
}

impl CompareFunc {
    /// `a func b` (e.g. `Less`: `a < b`). NaN compares false except for
    /// `NotEqual` and `Always`.
    pub fn test<T: PartialOrd>(self, a: T, b: T) -> bool {
        match self {
            CompareFunc::Never => false,
            CompareFunc::Less => a < b,
            CompareFunc::Equal => a == b,
            CompareFunc::LessEqual => a <= b,
            CompareFunc::Greater => a > b,
            CompareFunc::NotEqual => a != b,
            CompareFunc::GreaterEqual => a >= b,
            CompareFunc::Always => true,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum StencilOp {
    #[default]
    Keep,
    Zero,
    Replace,
    Incr,
    Decr,
    Invert,
    IncrWrap,
    DecrWrap,
}

/// Stencil state of one face (GL 2.1 §4.1.5, StencilFuncSeparate /
/// StencilOpSeparate / StencilMaskSeparate).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StencilFace {
    pub func: CompareFunc,
    pub reference: i32,
    pub value_mask: u32,
    pub fail: StencilOp,
    pub depth_fail: StencilOp,
    pub depth_pass: StencilOp,
    pub write_mask: u32,
}

impl Default for StencilFace {
    fn default() -> StencilFace {
        StencilFace {
            func: CompareFunc::Always,
            reference: 0,
            value_mask: !0,
            fail: StencilOp::Keep,
            depth_fail: StencilOp::Keep,
            depth_pass: StencilOp::Keep,
            write_mask: !0,
        }
    }
}

/// `[front, back]`. Points and lines use the front state.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct StencilState {
    pub front: StencilFace,
    pub back: StencilFace,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BlendFactor {
    Zero,
    One,
    SrcColor,
    OneMinusSrcColor,
    DstColor,
    OneMinusDstColor,
    SrcAlpha,
    OneMinusSrcAlpha,
    DstAlpha,
    OneMinusDstAlpha,
    ConstantColor,
    OneMinusConstantColor,
    ConstantAlpha,
    OneMinusConstantAlpha,
    SrcAlphaSaturate,
    /// The second source colour's (dual-source blending, GL 3.3 §4.1.8).
    Src1Color,
    OneMinusSrc1Color,
    Src1Alpha,
    OneMinusSrc1Alpha,
}

impl BlendFactor {
    /// Whether the factor reads the second source colour.
    pub fn is_src1(self) -> bool {
        matches!(
            self,
            BlendFactor::Src1Color
                | BlendFactor::OneMinusSrc1Color
                | BlendFactor::Src1Alpha
                | BlendFactor::OneMinusSrc1Alpha
        )
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum BlendEquation {
    #[default]
    Add,
    Subtract,
    ReverseSubtract,
    Min,
    Max,
}

/// Blending state (GL 2.1 §4.1.8), applied when enabled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Blend {
    pub src_rgb: BlendFactor,
    pub dst_rgb: BlendFactor,
    pub src_alpha: BlendFactor,
    pub dst_alpha: BlendFactor,
    pub equation_rgb: BlendEquation,
    pub equation_alpha: BlendEquation,
    /// BlendColor (already clamped to [0, 1] by the GL layer).
    pub color: [f32; 4],
}

impl Blend {
    /// Whether any factor reads the second source colour (dual-source
    /// blending).
    pub fn uses_src1(&self) -> bool {
        [self.src_rgb, self.dst_rgb, self.src_alpha, self.dst_alpha]
            .iter()
            .any(|f| f.is_src1())
    }
}

impl Default for Blend {
    fn default() -> Blend {
        Blend {
            src_rgb: BlendFactor::One,
            dst_rgb: BlendFactor::Zero,
            src_alpha: BlendFactor::One,
            dst_alpha: BlendFactor::Zero,
            equation_rgb: BlendEquation::Add,
            equation_alpha: BlendEquation::Add,
            color: [0.0; 4],
        }
    }
}

/// The sixteen logic operations of GL 2.1 §4.1.10 (RGBA8 buffers only).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LogicOp {
    Clear,
    And,
    AndReverse,
    Copy,
    AndInverted,
    Noop,
    Xor,
    Or,
    Nor,
    Equiv,
    Invert,
    OrReverse,
    CopyInverted,
    OrInverted,
    Nand,
    Set,
}

impl LogicOp {
    /// Every operation in the order of their GL enums (GL_CLEAR ...
    /// GL_SET are consecutive).
    pub const ALL: [LogicOp; 16] = [
        LogicOp::Clear,
        LogicOp::And,
        LogicOp::AndReverse,
        LogicOp::Copy,
        LogicOp::AndInverted,
        LogicOp::Noop,
        LogicOp::Xor,
        LogicOp::Or,
        LogicOp::Nor,
        LogicOp::Equiv,
        LogicOp::Invert,
        LogicOp::OrReverse,
        LogicOp::CopyInverted,
        LogicOp::OrInverted,
        LogicOp::Nand,
        LogicOp::Set,
    ];

    /// `s op d` on bits.
    pub fn apply(self, s: u8, d: u8) -> u8 {
        match self {
            LogicOp::Clear => 0,
            LogicOp::And => s & d,
            LogicOp::AndReverse => s & !d,
            LogicOp::Copy => s,
            LogicOp::AndInverted => !s & d,
            LogicOp::Noop => d,
            LogicOp::Xor => s ^ d,
            LogicOp::Or => s | d,
            LogicOp::Nor => !(s | d),
            LogicOp::Equiv => !(s ^ d),
            LogicOp::Invert => !d,
            LogicOp::OrReverse => s | !d,
            LogicOp::CopyInverted => !s,
            LogicOp::OrInverted => !s | d,
            LogicOp::Nand => !(s & d),
            LogicOp::Set => 0xff,
        }
    }
}

/// Polygon offset (GL 2.1 §3.5.5): `o = m · factor + r · units` with
/// `r = 1 / (2^24 - 1)`, enabled per polygon mode.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct PolygonOffset {
    pub factor: f32,
    pub units: f32,
    pub fill: bool,
    pub line: bool,
    pub point: bool,
}

/// Everything fixed-function a draw needs.
#[derive(Clone, Debug, PartialEq)]
pub struct PipelineState {
    pub viewport: Rect,
    /// DepthRange (n, f), already clamped to [0, 1].
    pub depth_range: (f32, f32),
    /// GL_DEPTH_CLAMP: primitives are not clipped by the near and far
    /// planes; fragment depths are clamped to [0, 1] as they are stored.
    pub depth_clamp: bool,
    /// The scissor box when the scissor test is enabled.
    pub scissor: Option<Rect>,
    pub cull: Option<CullFace>,
    pub front_face: FrontFace,
    /// `[front, back]` polygon modes.
    pub polygon_mode: [PolygonMode; 2],
    /// ShadeModel(FLAT): gl_Color / gl_SecondaryColor come from the
    /// provoking vertex.
    pub flat_shading: bool,
    /// The target is a window-system framebuffer, whose rows Mesa numbers
    /// from the top: interpolation planes are then set up and evaluated
    /// in those rows (`crate::interpolate`), as llvmpipe does there. The
    /// picture, coverage and gl_FragCoord are the same either way; only
    /// the rounding of interpolated values follows the convention.
    pub top_down: bool,
    /// ProvokingVertex(FIRST_VERTEX_CONVENTION) (GL 3.3 §2.19, table
    /// 2.15): flat values come from each primitive's first vertex instead
    /// of its last (quads follow the convention too).
    pub provoking_first: bool,
    /// PointSize (used unless `vertex_program_point_size` and the vertex
    /// shader writes gl_PointSize).
    pub point_size: f32,
    pub point_sprite: bool,
    /// COORD_REPLACE per texture coordinate set (bit i = set i).
    pub coord_replace: u32,
    /// POINT_SPRITE_COORD_ORIGIN == LOWER_LEFT (default UPPER_LEFT).
    pub point_sprite_origin_lower_left: bool,
    pub vertex_program_point_size: bool,
    pub line_width: f32,
    /// VERTEX_PROGRAM_TWO_SIDE.
    pub two_sided_color: bool,
    /// Clamp vertex colors to [0, 1] (GL 2.1 §2.14.6; always on in GL 2.1).
    pub clamp_vertex_color: bool,
    /// Clamp fragment colors to [0, 1] before blending (GL 2.1 always
    /// does; only matters for float color buffers).
    pub clamp_fragment_color: bool,
    /// Enabled user clip planes in eye space.
    pub clip_planes: [Option<[f32; 4]>; 8],
    pub alpha_test: Option<(CompareFunc, f32)>,
    pub stencil: Option<StencilState>,
    pub depth_test: Option<CompareFunc>,
    pub depth_mask: bool,
    pub blend: Option<Blend>,
    /// ColorMask (r, g, b, a), for all draw buffers unless `per_buffer`
    /// says otherwise.
    pub color_mask: [bool; 4],
    /// Per-draw-buffer blending and masks (glEnablei(BLEND, i),
    /// glColorMaski; GL 3.3 §4.1.8, §4.2.2): `None` when every draw buffer
    /// blends as `blend` says and masks with `color_mask`; else, for draw
    /// buffer (fragment output) i, whether `blend` applies to it and its
    /// mask (`blend` then holds the equations and factors if any buffer
    /// blends).
    pub per_buffer: Option<[(bool, [bool; 4]); 8]>,
    pub logic_op: Option<LogicOp>,
    pub polygon_offset: PolygonOffset,
    /// DrawBuffers: fragment output i (`gl_FragData[i]`; gl_FragColor goes to
    /// every one) is written to `Framebuffer::color[draw_buffers[i]]`;
    /// `None` is GL_NONE.
    pub draw_buffers: [Option<usize>; 8],
    /// How the draw's primitives are numbered for gl_PrimitiveID.
    pub primitive_ids: PrimitiveIds,
    /// Whether the fragments passing the depth test are counted
    /// (`Framebuffer::samples_passed`; an occlusion query is active).
    /// Without, the fragment stage may depth-test a tile's primitives out
    /// of draw order where the pixels cannot tell (near ones first).
    pub count_samples: bool,
}

/// The gl_PrimitiveID of a draw's primitives (GL 3.3 §3.12.2, without a
/// geometry shader): primitive `k` of the draw (its assembled
/// primitives counted from zero, a quad or a polygon drawn as lines or
/// points once) has ID `first + k % period`. A draw that stands for part
/// of a GL draw (after a restart index) starts where the earlier parts
/// stopped; one that stands for several instances restarts at each
/// (`period`: the primitives of one instance).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PrimitiveIds {
    pub first: u32,
    /// Never zero.
    pub period: u32,
}

impl Default for PrimitiveIds {
    fn default() -> PrimitiveIds {
        PrimitiveIds {
            first: 0,
            period: u32::MAX,
        }
    }
}

impl PrimitiveIds {
    /// The ID of primitive `k` of the draw.
    pub fn of(self, k: u32) -> u32 {
        self.first.wrapping_add(k % self.period.max(1))
    }
}

impl Default for PipelineState {
    fn default() -> PipelineState {
        PipelineState {
            viewport: Rect::default(),
            depth_range: (0.0, 1.0),
            depth_clamp: false,
            scissor: None,
            cull: None,
            front_face: FrontFace::Ccw,
            polygon_mode: [PolygonMode::Fill; 2],
            flat_shading: false,
            top_down: false,
            provoking_first: false,
            point_size: 1.0,
            point_sprite: false,
            coord_replace: 0,
            point_sprite_origin_lower_left: false,
            vertex_program_point_size: false,
            line_width: 1.0,
            two_sided_color: false,
            clamp_vertex_color: true,
            clamp_fragment_color: true,
            clip_planes: [None; 8],
            alpha_test: None,
            stencil: None,
            depth_test: None,
            depth_mask: true,
            blend: None,
            color_mask: [true; 4],
            per_buffer: None,
            logic_op: None,
            primitive_ids: PrimitiveIds::default(),
            count_samples: true,
            polygon_offset: PolygonOffset::default(),
            draw_buffers: [Some(0), None, None, None, None, None, None, None],
        }
    }
}
