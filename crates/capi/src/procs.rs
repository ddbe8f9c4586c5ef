//! The OSMesaGetProcAddress table: every exported entry point by name.

use crate::osmesa::*;

/// The address of the exported function `name` (gl* or OSMesa*).
pub fn lookup(name: &str) -> Option<*const ()> {
    for table in [
        crate::entry::lookup,
        crate::buffers::lookup,
        crate::queries::lookup,
        crate::legacy::lookup,
        crate::attribs::lookup,
        crate::pixels::lookup,
        crate::array_draws::lookup,
        crate::array_draws::lookup_extra,
        crate::occlusion::lookup,
        crate::pixel_path::lookup,
        crate::variants::lookup,
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
