//! Entry points beyond drawing: the errors invalid calls raise, and the
//! queries/pixel paths added after the first increment, driven as a C
//! program would.

use gl::enums::*;
use std::ffi::c_void;
use std::ptr::null_mut;
use OSMesa::*;

/// A current W x H RGBA context over `buf`; destroyed by the caller.
unsafe fn context(buf: &mut Vec<u8>, w: i32, h: i32) -> OSMesaContext {
    *buf = vec![0u8; (w * h * 4) as usize];
    let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, null_mut());
    assert!(!ctx.is_null());
    assert_eq!(
        OSMesaMakeCurrent(ctx, buf.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, w, h),
        OSMesa::GL_TRUE
    );
    ctx
}

#[test]
fn list_commands_between_begin_and_end_are_invalid_operations() {
    unsafe {
        let mut buf = Vec::new();
        let ctx = context(&mut buf, 4, 4);
        glBegin(GL_TRIANGLES);
        glNewList(1, GL_COMPILE);
        glEnd();
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        // No list is being compiled: glClearColor runs now.
        glClearColor(1.0, 0.0, 0.0, 1.0);
        let mut c = [0f32; 4];
        glGetFloatv(GL_COLOR_CLEAR_VALUE, c.as_mut_ptr());
        assert_eq!(c, [1.0, 0.0, 0.0, 1.0]);
        for f in [
            (|| {
                glGenLists(1);
            }) as fn(),
            || glEndList(),
            || glDeleteLists(1, 1),
            || glListBase(3),
            || {
                glIsList(1);
            },
        ] {
            glBegin(GL_POINTS);
            f();
            glEnd();
            assert_eq!(glGetError(), GL_INVALID_OPERATION);
        }
        // glCallList is legal inside.
        glBegin(GL_POINTS);
        glCallList(1);
        glEnd();
        assert_eq!(glGetError(), GL_NO_ERROR);
        OSMesaDestroyContext(ctx);
    }
}
