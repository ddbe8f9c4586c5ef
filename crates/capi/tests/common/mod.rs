//! Helpers the capi integration tests share (each test file is its own
//! crate and takes this module with `mod common;`).

use gl::enums::*;
use std::ffi::{c_void, CString};
use OSMesa::*;

/// Asserts OSMesaGetProcAddress finds every name.
#[allow(dead_code)]
pub fn assert_exported(names: &[&str]) {
    for name in names {
        let c = CString::new(*name).unwrap();
        assert!(
            unsafe { OSMesaGetProcAddress(c.as_ptr()) }.is_some(),
            "{name}"
        );
    }
}

/// The current context's RGBA8 pixel at (x, y), through glReadPixels.
///
/// # Safety
/// A context is current.
#[allow(dead_code)]
pub unsafe fn pixel_at(x: i32, y: i32) -> [u8; 4] {
    let mut p = [0u8; 4];
    glReadPixels(
        x,
        y,
        1,
        1,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        p.as_mut_ptr() as *mut c_void,
    );
    p
}

/// A context made current on `buf` (resized to `w`×`h` RGBA8): with
/// `profile` None a compatibility context from OSMesaCreateContextExt
/// (24 depth bits, 8 stencil bits), with Some(OSMESA_CORE_PROFILE or
/// OSMESA_COMPAT_PROFILE) a 3.3 context of that profile from
/// OSMesaCreateContextAttribs (the same buffers).
///
/// # Safety
/// `buf` outlives the context's use.
#[allow(dead_code)]
pub unsafe fn current_context(
    buf: &mut Vec<u8>,
    w: i32,
    h: i32,
    profile: Option<i32>,
) -> OSMesaContext {
    *buf = vec![0u8; (w * h * 4) as usize];
    let ctx = match profile {
        None => OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, std::ptr::null_mut()),
        Some(profile) => {
            let attribs = [
                OSMESA_FORMAT,
                OSMESA_RGBA as i32,
                OSMESA_DEPTH_BITS,
                24,
                OSMESA_STENCIL_BITS,
                8,
                OSMESA_PROFILE,
                profile,
                OSMESA_CONTEXT_MAJOR_VERSION,
                3,
                OSMESA_CONTEXT_MINOR_VERSION,
                3,
                0,
            ];
            OSMesaCreateContextAttribs(attribs.as_ptr(), std::ptr::null_mut())
        }
    };
    assert!(!ctx.is_null());
    let made = OSMesaMakeCurrent(ctx, buf.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, w, h);
    assert_eq!(made, OSMesa::GL_TRUE);
    ctx
}

/// A shader object of `kind` with `src` as its one string, compiled;
/// whether it compiled is the caller's to check.
///
/// # Safety
/// A context is current.
#[allow(dead_code)]
pub unsafe fn shader(kind: u32, src: &str) -> u32 {
    let s = glCreateShader(kind);
    let (ptr, len) = (src.as_ptr() as *const GLchar, src.len() as GLint);
    glShaderSource(s, 1, &ptr, &len);
    glCompileShader(s);
    s
}

/// A new program with a shader of each (kind, source) of `stages`
/// attached, each asserted to compile; not linked yet, so that the
/// caller may bind locations first.
///
/// # Safety
/// A context is current.
#[allow(dead_code)]
pub unsafe fn attached(stages: &[(u32, &str)]) -> u32 {
    let p = glCreateProgram();
    for &(kind, src) in stages {
        let s = shader(kind, src);
        let mut ok = 0;
        glGetShaderiv(s, GL_COMPILE_STATUS, &mut ok);
        assert_eq!(ok, 1, "{src}");
        glAttachShader(p, s);
    }
    p
}

/// Links `p`, asserting that it links, and makes it current.
///
/// # Safety
/// A context is current.
#[allow(dead_code)]
pub unsafe fn link_and_use(p: u32) -> u32 {
    glLinkProgram(p);
    let mut ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &mut ok);
    assert_eq!(ok, 1, "program {p} does not link");
    glUseProgram(p);
    p
}

/// The current program of vertex shader `vs` and fragment shader `fs`
/// ([`attached`] and [`link_and_use`]).
///
/// # Safety
/// A context is current.
#[allow(dead_code)]
pub unsafe fn program(vs: &str, fs: &str) -> u32 {
    link_and_use(attached(&[
        (GL_VERTEX_SHADER, vs),
        (GL_FRAGMENT_SHADER, fs),
    ]))
}

/// The location of active attribute `name` of program `p`, asserted to
/// exist.
///
/// # Safety
/// A context is current.
#[allow(dead_code)]
pub unsafe fn attrib_location(p: u32, name: &str) -> u32 {
    let n = CString::new(name).unwrap();
    let l = glGetAttribLocation(p, n.as_ptr());
    assert!(l >= 0, "{name}");
    l as u32
}

/// A new buffer object bound to `target` and filled with `data`
/// (GL_STATIC_DRAW).
///
/// # Safety
/// A context is current.
#[allow(dead_code)]
pub unsafe fn buffer<T>(target: u32, data: &[T]) -> u32 {
    let mut b = 0;
    glGenBuffers(1, &mut b);
    glBindBuffer(target, b);
    let size = std::mem::size_of_val(data) as isize;
    glBufferData(target, size, data.as_ptr() as *const c_void, GL_STATIC_DRAW);
    b
}

/// The corners of a full-window triangle strip.
#[allow(dead_code)]
pub const QUAD: [f32; 8] = [-1.0, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0];

/// A new vertex array object, left bound, whose attribute `name` of
/// program `p` (two floats) reads [`QUAD`] from a buffer object.
///
/// # Safety
/// A context is current.
#[allow(dead_code)]
pub unsafe fn quad_vertex_array(p: u32, name: &str) -> u32 {
    let mut vao = 0;
    glGenVertexArrays(1, &mut vao);
    glBindVertexArray(vao);
    buffer(GL_ARRAY_BUFFER, &QUAD);
    let loc = attrib_location(p, name);
    glVertexAttribPointer(loc, 2, GL_FLOAT, 0, 0, std::ptr::null());
    glEnableVertexAttribArray(loc);
    vao
}

/// Runs `body` with a context from [`current_context`] (`w`×`h`,
/// `profile`) current, handing it the buffer the context renders into,
/// then destroys the context.
#[allow(dead_code)]
pub fn with_context<R>(
    w: i32,
    h: i32,
    profile: Option<i32>,
    body: impl FnOnce(&mut Vec<u8>) -> R,
) -> R {
    let mut buf = Vec::new();
    // SAFETY: `buf` outlives the context, destroyed below.
    let ctx = unsafe { current_context(&mut buf, w, h, profile) };
    let r = body(&mut buf);
    unsafe { OSMesaDestroyContext(ctx) };
    r
}
