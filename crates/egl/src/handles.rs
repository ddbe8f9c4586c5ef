//! The handles EGL hands out for fixed things, at the bottom of the crate:
//! the three displays and the device (addresses of statics, so they never
//! change and anything else is refused) and the configs (a handle names
//! its display: `(display + 1) << 8 | EGL_CONFIG_ID`, so one of another
//! display is EGL_BAD_CONFIG).

use crate::types::*;

/// Number of displays: 0 = EGL_DEFAULT_DISPLAY (eglGetDisplay), 1 = the
/// surfaceless platform's, 2 = the device platform's.
pub const DISPLAY_COUNT: usize = 3;

static DISPLAYS: [u8; DISPLAY_COUNT] = [0, 1, 2];
/// The one EGLDeviceEXT (its address is the handle).
static DEVICE: u8 = 0;

/// The handle of display `i`.
pub fn display(i: usize) -> EGLDisplay {
    &DISPLAYS[i] as *const u8 as EGLDisplay
}

/// The index of display handle `dpy`, if it is one of ours.
pub fn display_index(dpy: EGLDisplay) -> Option<usize> {
    (0..DISPLAY_COUNT).find(|&i| display(i) == dpy)
}

/// The device handle.
pub fn device() -> EGLDeviceEXT {
    &DEVICE as *const u8 as EGLDeviceEXT
}

/// One frame buffer configuration (RGBA8; [`Config::attrib`] has the rest).
pub struct Config {
    pub id: EGLint,
    pub depth: EGLint,
    pub stencil: EGLint,
}

/// Every config, in eglGetConfigs's order.
pub static CONFIGS: [Config; 2] = [
    Config {
        id: 1,
        depth: 24,
        stencil: 8,
    },
    Config {
        id: 2,
        depth: 0,
        stencil: 0,
    },
];

/// The handle of config `c` of display `d`.
pub fn config(d: usize, c: &Config) -> EGLConfig {
    (((d + 1) << 8) | c.id as usize) as EGLConfig
}

/// The config `h` names on display `d` (EGL_BAD_CONFIG otherwise).
pub fn config_of(d: usize, h: EGLConfig) -> Result<&'static Config, EGLint> {
    let v = h as usize;
    if v >> 8 != d + 1 {
        return Err(EGL_BAD_CONFIG);
    }
    CONFIGS
        .iter()
        .find(|c| c.id as usize == v & 0xff)
        .ok_or(EGL_BAD_CONFIG)
}
