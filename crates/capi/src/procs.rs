//! OSMesaGetProcAddress and its table: every exported function by name.
//! It names every entry-point module; nothing depends back on it.

use crate::context::guard;
use crate::osmesa::*;
use std::ffi::{c_char, CStr};

/// The address of the exported function `name` (gl* or OSMesa*), or for
/// an ARB or EXT name that the core function it became has the name of
/// without the suffix (`glActiveTextureARB`, `glBlendEquationEXT`), that
/// core function: the extensions' entry points behave as the core ones
/// (GL 2.1's and 3.x's promotions kept their semantics), and programs
/// written for the extensions look them up by the suffixed names.
pub fn lookup(name: &str) -> Option<*const ()> {
    lookup_exact(name).or_else(|| {
        let core = name
            .strip_suffix("ARB")
            .or_else(|| name.strip_suffix("EXT"))?;
        if NOT_ALIASES.contains(&name) {
            return None;
        }
        lookup_exact(core)
    })
}

/// Suffixed names whose unsuffixed form is a different core function:
/// ARB_vertex_program's (its programs are not GLSL program objects).
const NOT_ALIASES: &[&str] = &["glIsProgramARB", "glGetProgramivARB"];

/// The address of the exported function of exactly this name.
fn lookup_exact(name: &str) -> Option<*const ()> {
    for table in [
        crate::attribs::lookup,
        crate::buffers::lookup,
        crate::drawing::lookup,
        crate::fixed_function::lookup,
        crate::framebuffer::lookup,
        crate::framebuffer_objects::lookup,
        crate::legacy::lookup,
        crate::occlusion::lookup,
        crate::pixel_path::lookup,
        crate::pixels::lookup,
        crate::queries::lookup,
        crate::rasterization::lookup,
        crate::shaders::lookup,
        crate::sync::lookup,
        crate::textures::lookup,
        crate::transform::lookup,
        crate::uniforms::lookup,
        crate::variants::lookup,
        crate::vertex_arrays::lookup,
        crate::vertex_arrays::lookup_extra,
    ] {
        if let Some(p) = table(name) {
            return Some(p);
        }
    }
    Some(match name {
        "OSMesaCreateContext" => OSMesaCreateContext as *const (),
        "OSMesaCreateContextExt" => OSMesaCreateContextExt as *const (),
        "OSMesaCreateContextAttribs" => OSMesaCreateContextAttribs as *const (),
        "OSMesaDestroyContext" => OSMesaDestroyContext as *const (),
        "OSMesaMakeCurrent" => OSMesaMakeCurrent as *const (),
        "OSMesaGetCurrentContext" => OSMesaGetCurrentContext as *const (),
        "OSMesaPixelStore" => OSMesaPixelStore as *const (),
        "OSMesaGetIntegerv" => OSMesaGetIntegerv as *const (),
        "OSMesaGetDepthBuffer" => OSMesaGetDepthBuffer as *const (),
        "OSMesaGetColorBuffer" => OSMesaGetColorBuffer as *const (),
        "OSMesaGetProcAddress" => OSMesaGetProcAddress as *const (),
        "OSMesaColorClamp" => OSMesaColorClamp as *const (),
        "glNewList" => crate::lists::glNewList as *const (),
        "glEndList" => crate::lists::glEndList as *const (),
        "glCallList" => crate::lists::glCallList as *const (),
        "glCallLists" => crate::lists::glCallLists as *const (),
        "glGenLists" => crate::lists::glGenLists as *const (),
        "glDeleteLists" => crate::lists::glDeleteLists as *const (),
        "glIsList" => crate::lists::glIsList as *const (),
        "glListBase" => crate::lists::glListBase as *const (),
        _ => return None,
    })
}

/// OSMesaGetProcAddress: the entry points this library exports, by name.
#[no_mangle]
pub unsafe extern "C" fn OSMesaGetProcAddress(name: *const c_char) -> OSMESAproc {
    guard(None, || {
        if name.is_null() {
            return None;
        }
        // SAFETY: a NUL-terminated C string per osmesa.h.
        let name = unsafe { CStr::from_ptr(name) }.to_str().ok()?;
        let p = lookup(name)?;
        // SAFETY: `p` is the address of one of our extern "C" functions;
        // the caller casts it back to that function's real signature.
        Some(unsafe { std::mem::transmute::<*const (), unsafe extern "C" fn()>(p) })
    })
}
