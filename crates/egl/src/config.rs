//! Frame buffer configurations: RGBA8 with a 24-bit depth and 8-bit
//! stencil buffer, and RGBA8 alone; pbuffers only (no native windows),
//! OpenGL only. eglGetConfigs, eglChooseConfig (EGL 1.5 §3.4.1: matching
//! rules, defaults, sort order), eglGetConfigAttrib.

use crate::error::api;
use crate::objects;
use crate::types::*;

pub use crate::handles::{config as handle, config_of as lookup, Config, CONFIGS};

/// Largest pbuffer side (the renderer's largest framebuffer).
pub const MAX_PBUFFER: EGLint = gl::MAX_TEXTURE_SIZE;

impl Config {
    /// The value of `attribute`, or None for an unknown one.
    pub fn attrib(&self, attribute: EGLint) -> Option<EGLint> {
        Some(match attribute {
            EGL_BUFFER_SIZE => 32,
            EGL_RED_SIZE | EGL_GREEN_SIZE | EGL_BLUE_SIZE | EGL_ALPHA_SIZE => 8,
            EGL_DEPTH_SIZE => self.depth,
            EGL_STENCIL_SIZE => self.stencil,
            EGL_CONFIG_CAVEAT => EGL_NONE,
            EGL_CONFIG_ID => self.id,
            EGL_LEVEL => 0,
            EGL_MAX_PBUFFER_WIDTH | EGL_MAX_PBUFFER_HEIGHT => MAX_PBUFFER,
            EGL_MAX_PBUFFER_PIXELS => MAX_PBUFFER * MAX_PBUFFER,
            EGL_NATIVE_RENDERABLE => EGL_FALSE as EGLint,
            EGL_NATIVE_VISUAL_ID => 0,
            EGL_NATIVE_VISUAL_TYPE => EGL_NONE,
            EGL_SAMPLES | EGL_SAMPLE_BUFFERS => 0,
            EGL_SURFACE_TYPE => EGL_PBUFFER_BIT,
            EGL_TRANSPARENT_TYPE => EGL_NONE,
            EGL_TRANSPARENT_RED_VALUE
            | EGL_TRANSPARENT_GREEN_VALUE
            | EGL_TRANSPARENT_BLUE_VALUE => 0,
            EGL_BIND_TO_TEXTURE_RGB | EGL_BIND_TO_TEXTURE_RGBA => EGL_FALSE as EGLint,
            EGL_MIN_SWAP_INTERVAL | EGL_MAX_SWAP_INTERVAL => 0,
            EGL_LUMINANCE_SIZE | EGL_ALPHA_MASK_SIZE => 0,
            EGL_COLOR_BUFFER_TYPE => EGL_RGB_BUFFER,
            EGL_RENDERABLE_TYPE | EGL_CONFORMANT => EGL_OPENGL_BIT,
            _ => return None,
        })
    }
}

/// How eglChooseConfig compares a requested value (EGL 1.5 Table 3.4).
#[derive(Clone, Copy, PartialEq)]
enum Rule {
    AtLeast,
    Exact,
    Mask,
}

/// The rule and default of a selectable attribute; None for an unknown
/// one (EGL_BAD_ATTRIBUTE).
fn rule(attribute: EGLint) -> Option<(Rule, EGLint)> {
    use Rule::*;
    Some(match attribute {
        EGL_BUFFER_SIZE | EGL_RED_SIZE | EGL_GREEN_SIZE | EGL_BLUE_SIZE | EGL_ALPHA_SIZE
        | EGL_DEPTH_SIZE | EGL_STENCIL_SIZE | EGL_SAMPLES | EGL_SAMPLE_BUFFERS
        | EGL_LUMINANCE_SIZE | EGL_ALPHA_MASK_SIZE => (AtLeast, 0),
        EGL_CONFIG_CAVEAT
        | EGL_CONFIG_ID
        | EGL_NATIVE_VISUAL_TYPE
        | EGL_BIND_TO_TEXTURE_RGB
        | EGL_BIND_TO_TEXTURE_RGBA
        | EGL_MIN_SWAP_INTERVAL
        | EGL_MAX_SWAP_INTERVAL
        | EGL_NATIVE_RENDERABLE
        | EGL_TRANSPARENT_RED_VALUE
        | EGL_TRANSPARENT_GREEN_VALUE
        | EGL_TRANSPARENT_BLUE_VALUE => (Exact, EGL_DONT_CARE),
        EGL_LEVEL => (Exact, 0),
        EGL_TRANSPARENT_TYPE => (Exact, EGL_NONE),
        EGL_COLOR_BUFFER_TYPE => (Exact, EGL_RGB_BUFFER),
        EGL_SURFACE_TYPE => (Mask, EGL_WINDOW_BIT),
        EGL_RENDERABLE_TYPE => (Mask, EGL_OPENGL_ES_BIT),
        EGL_CONFORMANT => (Mask, 0),
        // Ignored by eglChooseConfig (EGL 1.5 §3.4.1).
        EGL_MAX_PBUFFER_WIDTH
        | EGL_MAX_PBUFFER_HEIGHT
        | EGL_MAX_PBUFFER_PIXELS
        | EGL_NATIVE_VISUAL_ID => (Exact, EGL_DONT_CARE),
        EGL_MATCH_NATIVE_PIXMAP => (Exact, EGL_NONE),
        _ => return None,
    })
}

/// The configs matching `requested` (attribute, value) pairs, best first.
pub fn choose(requested: &[(EGLint, EGLint)]) -> Result<Vec<&'static Config>, EGLint> {
    let mut wanted: Vec<(EGLint, Rule, EGLint)> = Vec::new();
    let mut by_id = None;
    for &(a, v) in requested {
        let (r, _) = rule(a).ok_or(EGL_BAD_ATTRIBUTE)?;
        if a == EGL_CONFIG_ID && v != EGL_DONT_CARE {
            by_id = Some(v);
        }
        wanted.retain(|w| w.0 != a);
        wanted.push((a, r, v));
    }
    if let Some(id) = by_id {
        // EGL_CONFIG_ID given: every other attribute is ignored.
        return Ok(CONFIGS.iter().filter(|c| c.id == id).collect());
    }
    // The defaults of the attributes not given.
    for a in [
        EGL_LEVEL,
        EGL_TRANSPARENT_TYPE,
        EGL_COLOR_BUFFER_TYPE,
        EGL_SURFACE_TYPE,
        EGL_RENDERABLE_TYPE,
    ] {
        if !wanted.iter().any(|w| w.0 == a) {
            if let Some((r, v)) = rule(a) {
                wanted.push((a, r, v));
            }
        }
    }
    let mut out: Vec<&'static Config> = CONFIGS
        .iter()
        .filter(|c| {
            wanted.iter().all(|&(a, r, v)| {
                if v == EGL_DONT_CARE
                    || matches!(
                        a,
                        EGL_MAX_PBUFFER_WIDTH
                            | EGL_MAX_PBUFFER_HEIGHT
                            | EGL_MAX_PBUFFER_PIXELS
                            | EGL_NATIVE_VISUAL_ID
                            | EGL_MATCH_NATIVE_PIXMAP
                    )
                {
                    return true;
                }
                let have = c.attrib(a).unwrap_or(0);
                match r {
                    Rule::AtLeast => have >= v,
                    Rule::Exact => have == v,
                    Rule::Mask => have & v == v,
                }
            })
        })
        .collect();
    // Sort (EGL 1.5 §3.4.1.2): color sizes and caveats are equal; smaller
    // depth, then smaller stencil, then smaller id.
    out.sort_by_key(|c| (c.depth, c.stencil, c.id));
    Ok(out)
}

/// Reads an EGL_NONE-terminated attribute list of EGLint pairs.
///
/// # Safety
/// `list` is null or EGL_NONE-terminated (EGL's contract).
pub unsafe fn pairs(list: *const EGLint) -> Vec<(EGLint, EGLint)> {
    let mut out = Vec::new();
    if list.is_null() {
        return out;
    }
    for i in 0..1024 {
        // SAFETY: the caller's.
        let a = unsafe { *list.add(2 * i) };
        if a == EGL_NONE {
            break;
        }
        out.push((a, unsafe { *list.add(2 * i + 1) }));
    }
    out
}

/// Reads an EGL_NONE-terminated list of EGLAttrib pairs (EGL 1.5's form).
///
/// # Safety
/// As [`pairs`].
pub unsafe fn attrib_pairs(list: *const EGLAttrib) -> Vec<(EGLint, EGLAttrib)> {
    let mut out = Vec::new();
    if list.is_null() {
        return out;
    }
    for i in 0..1024 {
        // SAFETY: the caller's.
        let a = unsafe { *list.add(2 * i) };
        if a == EGL_NONE as EGLAttrib {
            break;
        }
        out.push((a as EGLint, unsafe { *list.add(2 * i + 1) }));
    }
    out
}

/// Writes up to `size` of `list`'s handles to `configs` (unless null) and
/// the count written (or, for null `configs`, available) to `num`.
unsafe fn hand_out(
    d: usize,
    list: &[&Config],
    configs: *mut EGLConfig,
    size: EGLint,
    num: *mut EGLint,
) {
    let n = if configs.is_null() {
        list.len()
    } else {
        let n = list.len().min(size.max(0) as usize);
        for (i, c) in list.iter().take(n).enumerate() {
            // SAFETY: `configs` holds `size` handles.
            unsafe { *configs.add(i) = handle(d, c) };
        }
        n
    };
    // SAFETY: one EGLint (checked non-null by the caller).
    unsafe { *num = n as EGLint };
}

/// eglGetConfigs.
#[no_mangle]
pub unsafe extern "C" fn eglGetConfigs(
    dpy: EGLDisplay,
    configs: *mut EGLConfig,
    size: EGLint,
    num: *mut EGLint,
) -> EGLBoolean {
    api(EGL_FALSE, || {
        let d = objects::lock().initialized(dpy)?;
        if num.is_null() {
            return Err(EGL_BAD_PARAMETER);
        }
        let all: Vec<&Config> = CONFIGS.iter().collect();
        // SAFETY: EGL's contract for the arrays.
        unsafe { hand_out(d, &all, configs, size, num) };
        Ok(EGL_TRUE)
    })
}

/// eglChooseConfig.
#[no_mangle]
pub unsafe extern "C" fn eglChooseConfig(
    dpy: EGLDisplay,
    attribs: *const EGLint,
    configs: *mut EGLConfig,
    size: EGLint,
    num: *mut EGLint,
) -> EGLBoolean {
    api(EGL_FALSE, || {
        let d = objects::lock().initialized(dpy)?;
        if num.is_null() {
            return Err(EGL_BAD_PARAMETER);
        }
        // SAFETY: EGL's contract for the list.
        let list = choose(&unsafe { pairs(attribs) })?;
        // SAFETY: EGL's contract for the arrays.
        unsafe { hand_out(d, &list, configs, size, num) };
        Ok(EGL_TRUE)
    })
}

/// eglGetConfigAttrib.
#[no_mangle]
pub unsafe extern "C" fn eglGetConfigAttrib(
    dpy: EGLDisplay,
    config: EGLConfig,
    attribute: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    api(EGL_FALSE, || {
        let d = objects::lock().initialized(dpy)?;
        let c = lookup(d, config)?;
        let v = c.attrib(attribute).ok_or(EGL_BAD_ATTRIBUTE)?;
        if value.is_null() {
            return Err(EGL_BAD_PARAMETER);
        }
        // SAFETY: one EGLint.
        unsafe { *value = v };
        Ok(EGL_TRUE)
    })
}
