//! Display lists (GL 2.1 §5.4), kept at the C ABI level: while a list is
//! being compiled, every entry point GL compiles into lists records a
//! closure that re-issues the call with the same arguments (pointer
//! arguments copied at compile time, as §5.4 requires), and glCallList
//! replays them. Commands §5.4 excludes (queries, object creation, client
//! state, pixel store, glFinish...) execute immediately.
//!
//! Vertex-array draws (glDrawArrays, glDrawElements, glDrawRangeElements,
//! glMultiDraw*, glArrayElement) dereference the enabled arrays at compile
//! time and record the elements' values, replayed as glBegin / attribute
//! calls / glEnd (`crate::drawing::compile_draw`); an invalid call
//! records its error, raised when the list runs. Pixel images
//! (glDrawPixels, glBitmap) are copied at compile time too.

use crate::abi::*;
use crate::context::{guard, record_call, refused_in_core, with_ctx};
use crate::layer_state::MAX_LIST_NESTING;
use gl::enums::*;
use std::rc::Rc;

#[no_mangle]
pub extern "C" fn glNewList(list: GLuint, mode: GLenum) {
    if refused_in_core() {
        return;
    }
    with_ctx((), |c| {
        if c.gl.reject_in_begin() {
            return;
        }
        if list == 0 {
            c.gl.record_error(GL_INVALID_VALUE);
        } else if mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE {
            c.gl.record_error(GL_INVALID_ENUM);
        } else if c.lists.compiling.is_some() {
            c.gl.record_error(GL_INVALID_OPERATION);
        } else {
            c.lists.compiling = Some((list, mode, Vec::new()));
        }
    })
}

#[no_mangle]
pub extern "C" fn glEndList() {
    if refused_in_core() {
        return;
    }
    with_ctx((), |c| {
        if c.gl.reject_in_begin() {
            return;
        }
        match c.lists.compiling.take() {
            Some((name, _, cmds)) => {
                c.lists.lists.insert(name, Rc::new(cmds));
            }
            None => c.gl.record_error(GL_INVALID_OPERATION),
        }
    })
}

/// Replays list `n` (no-op for an undefined list, GL 2.1 §5.4).
fn call_list(n: u32) {
    let cmds = with_ctx(None, |c| {
        if c.lists.replaying >= MAX_LIST_NESTING {
            return None;
        }
        let cmds = c.lists.lists.get(&n).cloned();
        if cmds.is_some() {
            c.lists.replaying += 1;
        }
        cmds
    });
    if let Some(cmds) = cmds {
        for cmd in cmds.iter() {
            cmd();
        }
        with_ctx((), |c| {
            c.lists.replaying = c.lists.replaying.saturating_sub(1)
        });
    }
}

#[no_mangle]
pub extern "C" fn glCallList(list: GLuint) {
    if refused_in_core() {
        return;
    }
    guard((), || {
        if record_call(move || call_list(list)) {
            return;
        }
        call_list(list)
    })
}

/// glCallLists: `n` names of `ty` at `lists`, each offset by glListBase.
#[no_mangle]
pub unsafe extern "C" fn glCallLists(n: GLsizei, ty: GLenum, lists: *const std::ffi::c_void) {
    if refused_in_core() {
        return;
    }
    guard((), || {
        let size = match ty {
            GL_BYTE | GL_UNSIGNED_BYTE => 1,
            GL_SHORT | GL_UNSIGNED_SHORT | GL_2_BYTES => 2,
            GL_3_BYTES => 3,
            GL_INT | GL_UNSIGNED_INT | GL_FLOAT | GL_4_BYTES => 4,
            _ => {
                with_ctx((), |c| c.gl.record_error(GL_INVALID_ENUM));
                return;
            }
        };
        if n < 0 {
            with_ctx((), |c| c.gl.record_error(GL_INVALID_VALUE));
            return;
        }
        if lists.is_null() || n == 0 {
            return;
        }
        // SAFETY: GL's contract: n names of `ty` at `lists`.
        let bytes = unsafe { std::slice::from_raw_parts(lists as *const u8, n as usize * size) };
        let names: Vec<u32> = bytes
            .chunks_exact(size)
            .map(|b| match (ty, b) {
                (GL_BYTE, [x]) => *x as i8 as i32 as u32,
                (GL_SHORT, [x, y]) => i16::from_ne_bytes([*x, *y]) as i32 as u32,
                (GL_UNSIGNED_SHORT, [x, y]) => u16::from_ne_bytes([*x, *y]) as u32,
                (GL_2_BYTES, [x, y]) => (*x as u32) << 8 | *y as u32,
                (GL_3_BYTES, [x, y, z]) => (*x as u32) << 16 | (*y as u32) << 8 | *z as u32,
                (GL_FLOAT, [a, b2, c2, d]) => f32::from_ne_bytes([*a, *b2, *c2, *d]) as u32,
                (GL_INT | GL_UNSIGNED_INT, [a, b2, c2, d]) => {
                    u32::from_ne_bytes([*a, *b2, *c2, *d])
                }
                (GL_4_BYTES, [a, b2, c2, d]) => u32::from_be_bytes([*a, *b2, *c2, *d]),
                (_, [x]) => *x as u32,
                _ => 0,
            })
            .collect();
        let base = with_ctx(0, |c| c.lists.base);
        let names: Vec<u32> = names.iter().map(|&x| x.wrapping_add(base)).collect();
        let replay = names.clone();
        if record_call(move || replay.iter().for_each(|&l| call_list(l))) {
            return;
        }
        names.iter().for_each(|&l| call_list(l));
    })
}

#[no_mangle]
pub extern "C" fn glGenLists(range: GLsizei) -> GLuint {
    if refused_in_core() {
        return 0;
    }
    with_ctx(0, |c| {
        if c.gl.reject_in_begin() {
            return 0;
        }
        if range < 0 {
            c.gl.record_error(GL_INVALID_VALUE);
            return 0;
        }
        if range == 0 {
            return 0;
        }
        // Past the largest name in use (names are never reused-wrapped).
        let start = c
            .lists
            .lists
            .keys()
            .next_back()
            .map_or(1, |&k| k.saturating_add(1));
        if start.checked_add(range as u32).is_none() {
            return 0;
        }
        for i in 0..range as u32 {
            c.lists.lists.insert(start + i, Rc::new(Vec::new()));
        }
        start
    })
}

#[no_mangle]
pub extern "C" fn glDeleteLists(list: GLuint, range: GLsizei) {
    if refused_in_core() {
        return;
    }
    with_ctx((), |c| {
        if c.gl.reject_in_begin() {
            return;
        }
        if range < 0 {
            c.gl.record_error(GL_INVALID_VALUE);
            return;
        }
        let end = list.saturating_add(range as u32);
        let doomed: Vec<u32> = c.lists.lists.range(list..end).map(|(&k, _)| k).collect();
        for k in doomed {
            c.lists.lists.remove(&k);
        }
    })
}

#[no_mangle]
pub extern "C" fn glIsList(list: GLuint) -> GLboolean {
    if refused_in_core() {
        return 0;
    }
    with_ctx(0, |c| {
        if c.gl.reject_in_begin() {
            return 0;
        }
        c.lists.lists.contains_key(&list) as GLboolean
    })
}

#[no_mangle]
pub extern "C" fn glListBase(base: GLuint) {
    if refused_in_core() {
        return;
    }
    guard((), || {
        if record_call(move || glListBase(base)) {
            return;
        }
        with_ctx((), |c| {
            if !c.gl.reject_in_begin() {
                c.lists.base = base
            }
        })
    })
}
