//! OSMesa's enums (values of Mesa's `GL/osmesa.h`).

pub const OSMESA_COLOR_INDEX: u32 = gl::enums::GL_COLOR_INDEX;
pub const OSMESA_RGBA: u32 = gl::enums::GL_RGBA;
pub const OSMESA_BGRA: u32 = 0x1;
pub const OSMESA_ARGB: u32 = 0x2;
pub const OSMESA_RGB: u32 = gl::enums::GL_RGB;
pub const OSMESA_BGR: u32 = 0x4;
pub const OSMESA_RGB_565: u32 = 0x5;

pub const OSMESA_ROW_LENGTH: i32 = 0x10;
pub const OSMESA_Y_UP: i32 = 0x11;

pub const OSMESA_WIDTH: i32 = 0x20;
pub const OSMESA_HEIGHT: i32 = 0x21;
pub const OSMESA_FORMAT: i32 = 0x22;
pub const OSMESA_TYPE: i32 = 0x23;
pub const OSMESA_MAX_WIDTH: i32 = 0x24;
pub const OSMESA_MAX_HEIGHT: i32 = 0x25;

pub const OSMESA_DEPTH_BITS: i32 = 0x30;
pub const OSMESA_STENCIL_BITS: i32 = 0x31;
pub const OSMESA_ACCUM_BITS: i32 = 0x32;
pub const OSMESA_PROFILE: i32 = 0x33;
pub const OSMESA_CORE_PROFILE: i32 = 0x34;
pub const OSMESA_COMPAT_PROFILE: i32 = 0x35;
pub const OSMESA_CONTEXT_MAJOR_VERSION: i32 = 0x36;
pub const OSMESA_CONTEXT_MINOR_VERSION: i32 = 0x37;
