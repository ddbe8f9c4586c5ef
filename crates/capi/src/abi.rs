//! The C side of the boundary, depending on no other module of the crate:
//! the GL C types (x86-64 / aarch64 Linux), reading and writing the memory
//! C pointers designate, C argument values to GL values, and
//! `gl_entry_points!`, which turns a table of `fn glX(args) => |c| body`
//! into the exported `extern "C"` functions.

use std::ffi::{c_char, CStr};

// ---- C types ----

pub type GLenum = u32;
pub type GLboolean = u8;
pub type GLbitfield = u32;
pub type GLbyte = i8;
pub type GLshort = i16;
pub type GLint = i32;
pub type GLsizei = i32;
pub type GLubyte = u8;
pub type GLushort = u16;
pub type GLuint = u32;
pub type GLfloat = f32;
pub type GLclampf = f32;
pub type GLdouble = f64;
pub type GLclampd = f64;
pub type GLchar = std::ffi::c_char;
pub type GLsizeiptr = isize;
pub type GLintptr = isize;
pub type GLint64 = i64;
pub type GLuint64 = u64;
/// A sync object handle: the context's nonzero handle as the pointer's
/// value ([`gl::sync`]); never dereferenced.
pub type GLsync = *const std::ffi::c_void;

pub const GL_FALSE: GLboolean = 0;
pub const GL_TRUE: GLboolean = 1;

// ---- C memory ----

/// Reads `N` values at `p` (None for null).
pub(crate) unsafe fn rd<const N: usize, T: Copy>(p: *const T) -> Option<[T; N]> {
    if p.is_null() {
        None
    } else {
        // SAFETY: GL's contract for vector arguments: N values at p.
        Some(unsafe { std::ptr::read_unaligned(p as *const [T; N]) })
    }
}

/// Reads `n` values at `p` (empty for null or n <= 0).
pub(crate) unsafe fn rd_vec<T: Copy>(p: *const T, n: i64) -> Vec<T> {
    if p.is_null() || n <= 0 {
        return Vec::new();
    }
    // SAFETY: GL's contract: n values at p.
    (0..n as usize)
        .map(|i| unsafe { std::ptr::read_unaligned(p.add(i)) })
        .collect()
}

/// Writes `v` at `p` (nothing for null).
pub(crate) unsafe fn wr<T: Copy>(p: *mut T, v: &[T]) {
    if p.is_null() {
        return;
    }
    for (i, x) in v.iter().enumerate() {
        // SAFETY: GL's contract: the query's value count fits at p.
        unsafe { std::ptr::write_unaligned(p.add(i), *x) };
    }
}

/// A C string argument (lossy UTF-8).
pub(crate) unsafe fn cstr(p: *const c_char) -> Option<String> {
    if p.is_null() {
        return None;
    }
    // SAFETY: NUL-terminated per GL's contract.
    Some(unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned())
}

/// The `len` bytes at `p` (empty for null or `len` 0).
///
/// # Safety
/// Unless null, `p` designates `len` readable bytes that stay unchanged
/// for the returned lifetime (GL's contract for the call's data argument).
pub(crate) unsafe fn bytes<'a, T>(p: *const T, len: usize) -> &'a [u8] {
    if p.is_null() || len == 0 {
        return &[];
    }
    // SAFETY: the caller's.
    unsafe { std::slice::from_raw_parts(p as *const u8, len) }
}

// ---- C values to GL values ----

/// A C GLboolean as a bool (any nonzero value is true).
pub(crate) fn as_bool(x: GLboolean) -> bool {
    x != 0
}

/// A signed integer color/normal component to [-1, 1]: (2c + 1) / (2^b - 1)
/// (GL 2.1 Table 2.9); `max` is 2^b - 1.
pub(crate) fn snorm(x: f64, max: f64) -> f32 {
    ((2.0 * x + 1.0) / max) as f32
}

/// An unsigned integer color component to [0, 1]: c / (2^b - 1) (GL 2.1
/// Table 2.9); `max` is 2^b - 1. Computed in f64 and rounded once, which
/// for 8- and 16-bit values equals the f32 quotient (tested below).
pub(crate) fn unorm(x: f64, max: f64) -> f32 {
    (x / max) as f32
}

// ---- the entry-point macro ----

/// Generates, from a table of entries, the `#[no_mangle] extern "C"`
/// functions and the module's `lookup` (its part of the
/// OSMesaGetProcAddress table, [`crate::procs`]).
///
/// An entry is `fn glName(arg: CType, ...) -> Ret [default] => |c| { body }`:
/// the function runs `body` on the thread's current context `c`, returns
/// `default` when there is none, and catches panics (they never unwind
/// into C). An entry prefixed `[list]` is compiled into display lists
/// (GL 2.1 §5.4): while a list is being compiled the call is recorded with
/// its arguments and, in GL_COMPILE mode, not executed. An entry point
/// the core profile removes ([`gl::version::removed_in_core`], decided by
/// name at compile time) records `GL_INVALID_OPERATION` and returns
/// `default` in a core context.
///
/// The expansion calls `with_ctx(default, |c| ...)` and, for `[list]`
/// entries, `record_call(replay)` unqualified, so the invoking module
/// imports both from `crate::context`: this module stays free of the
/// context type.
macro_rules! gl_entry_points {
    ($(
        $(#[$m:meta])*
        $([$list:ident])? fn $name:ident($($a:ident: $t:ty),*) $(-> $r:ty [$def:expr])? => |$c:ident| $body:block
    )*) => {
        $(
            $(#[$m])*
            #[no_mangle]
            #[allow(unused_unsafe, clippy::too_many_arguments, clippy::unnecessary_cast)]
            pub unsafe extern "C" fn $name($($a: $t),*) $(-> $r)? {
                // Decided per entry point at compile time; a core context
                // refuses the removed ones (GL 3.3 core appendix E.2.2).
                const REMOVED_IN_CORE: bool = gl::version::removed_in_core(stringify!($name));
                gl_entry_points!(@maybe [$($list)?] $name($($a),*));
                with_ctx(gl_entry_points!(@def $($def)?), |$c| unsafe {
                    if REMOVED_IN_CORE && $c.gl.refuse_removed() {
                        return gl_entry_points!(@def $($def)?);
                    }
                    $body
                })
            }
        )*

        /// The address of the gl* entry point `name`.
        pub fn lookup(name: &str) -> Option<*const ()> {
            match name {
                $(stringify!($name) => Some($name as *const ()),)*
                _ => None,
            }
        }
    };
    // Compiled into display lists (GL 2.1 §5.4): record a re-issue of the
    // call; in GL_COMPILE mode do not execute it now.
    (@maybe [] $name:ident($($a:ident),*)) => {};
    (@maybe [list] $name:ident($($a:ident),*)) => {
        if record_call(move || unsafe { $name($($a),*) }) {
            return;
        }
    };
    (@def) => { () };
    (@def $d:expr) => { $d };
}
pub(crate) use gl_entry_points;

#[cfg(test)]
mod tests {
    use super::*;

    /// `unorm` for 8- and 16-bit values equals the f32 quotient
    /// (gl::Context::color_4ub's rule), so glColor*ub and the other
    /// unsigned forms agree.
    #[test]
    fn unorm_matches_the_f32_quotient() {
        for x in 0..=u8::MAX {
            assert_eq!(unorm(x as f64, 255.0), x as f32 / 255.0);
        }
        for x in 0..=u16::MAX {
            assert_eq!(unorm(x as f64, 65535.0), x as f32 / 65535.0);
        }
    }

    #[test]
    fn snorm_ends() {
        assert_eq!(snorm(127.0, 255.0), 1.0);
        assert_eq!(snorm(-128.0, 255.0), -1.0);
    }

    /// The pointer helpers on what C callers pass: unaligned data (a
    /// float vector inside a byte buffer at an odd offset), null
    /// pointers, counts of zero and below, a NUL-terminated string with
    /// invalid UTF-8. Run under Miri too (docs/RELIABILITY.md), which
    /// checks every access stays inside its allocation.
    #[test]
    fn pointer_helpers_read_and_write_only_what_they_are_given() {
        let values = [1.5f32, -2.0, 3.25, 0.5];
        let mut buf = vec![0u8; 1 + 4 * values.len()];
        for (i, v) in values.iter().enumerate() {
            buf[1 + 4 * i..5 + 4 * i].copy_from_slice(&v.to_ne_bytes());
        }
        let p = buf[1..].as_ptr() as *const f32;
        unsafe {
            assert_eq!(rd::<4, f32>(p), Some(values));
            assert_eq!(rd::<4, f32>(std::ptr::null()), None);
            assert_eq!(rd_vec(p, 3), values[..3].to_vec());
            assert!(rd_vec(p, 0).is_empty() && rd_vec(p, -5).is_empty());
            assert!(rd_vec::<f32>(std::ptr::null(), 4).is_empty());
            assert_eq!(bytes(p, 8), &buf[1..9]);
            assert!(bytes(p, 0).is_empty() && bytes::<f32>(std::ptr::null(), 8).is_empty());

            let mut out = [0u8; 2 + 4 * 3];
            let q = out[2..].as_mut_ptr() as *mut f32;
            wr(q, &values[..3]);
            wr(std::ptr::null_mut(), &values);
            assert_eq!(rd_vec(q as *const f32, 3), values[..3].to_vec());
            assert_eq!(&out[..2], &[0, 0]);

            let text = b"gl_\xffPosition\0ignored";
            let got = cstr(text.as_ptr() as *const c_char).unwrap();
            assert_eq!(got, "gl_\u{fffd}Position");
            assert_eq!(cstr(std::ptr::null()), None);
        }
    }
}
