//! Entry points beyond drawing: the errors invalid calls raise, and the
//! queries/pixel paths added after the first increment, driven as a C
//! program would.

use gl::enums::*;
use std::ffi::c_void;
use std::ptr::null_mut;
use OSMesa::*;

mod common;

#[test]
fn list_commands_between_begin_and_end_are_invalid_operations() {
    common::with_context(4, 4, None, |_| unsafe {
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
        // glGetError is not: it returns no error and records one.
        glBegin(GL_POINTS);
        assert_eq!(glGetError(), GL_NO_ERROR);
        glEnd();
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
    });
}

#[test]
fn vertex_attrib_and_pointer_queries() {
    common::with_context(4, 4, None, |_| unsafe {
        let data = [0f32; 16];
        glVertexAttribPointer(3, 2, GL_FLOAT, 1, 8, data.as_ptr() as *const c_void);
        glEnableVertexAttribArray(3);
        let mut v = [0i32; 1];
        for (pname, want) in [
            (GL_VERTEX_ATTRIB_ARRAY_ENABLED, 1),
            (GL_VERTEX_ATTRIB_ARRAY_SIZE, 2),
            (GL_VERTEX_ATTRIB_ARRAY_STRIDE, 8),
            (GL_VERTEX_ATTRIB_ARRAY_TYPE, GL_FLOAT as i32),
            (GL_VERTEX_ATTRIB_ARRAY_NORMALIZED, 1),
            (GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, 0),
        ] {
            glGetVertexAttribiv(3, pname, v.as_mut_ptr());
            assert_eq!(v[0], want, "pname {pname:#x}");
        }
        let mut p: *mut c_void = null_mut();
        glGetVertexAttribPointerv(3, GL_VERTEX_ATTRIB_ARRAY_POINTER, &mut p);
        assert_eq!(p as usize, data.as_ptr() as usize);
        glVertexAttrib4f(2, 1.0, 2.0, 3.0, 4.0);
        let mut d = [0f64; 4];
        glGetVertexAttribdv(2, GL_CURRENT_VERTEX_ATTRIB, d.as_mut_ptr());
        assert_eq!(d, [1.0, 2.0, 3.0, 4.0]);
        assert_eq!(glGetError(), GL_NO_ERROR);
        glGetVertexAttribiv(99, GL_VERTEX_ATTRIB_ARRAY_SIZE, v.as_mut_ptr());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glGetVertexAttribiv(3, GL_TEXTURE_2D, v.as_mut_ptr());
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glVertexPointer(3, GL_FLOAT, 0, data.as_ptr().add(4) as *const c_void);
        glGetPointerv(GL_VERTEX_ARRAY_POINTER, &mut p);
        assert_eq!(p as usize, data.as_ptr().add(4) as usize);
    });
}

#[test]
fn map_buffer_pbo_round_trip_and_tex_image_readback() {
    common::with_context(4, 4, None, |_| unsafe {
        glClearColor(1.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        let mut b = 0u32;
        glGenBuffers(1, &mut b);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, b);
        glBufferData(GL_PIXEL_PACK_BUFFER, 64, std::ptr::null(), GL_STREAM_READ);
        glReadPixels(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, std::ptr::null_mut());
        assert_eq!(glGetError(), GL_NO_ERROR);
        let p = glMapBuffer(GL_PIXEL_PACK_BUFFER, GL_READ_ONLY) as *const u8;
        assert!(!p.is_null());
        assert_eq!(std::slice::from_raw_parts(p, 4), &[255, 0, 0, 255]);
        let mut mapped = 0;
        glGetBufferParameteriv(GL_PIXEL_PACK_BUFFER, GL_BUFFER_MAPPED, &mut mapped);
        assert_eq!(mapped, 1);
        // A second map, reading into a mapped buffer: invalid operations.
        assert!(glMapBuffer(GL_PIXEL_PACK_BUFFER, GL_READ_ONLY).is_null());
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, std::ptr::null_mut());
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        assert_eq!(glUnmapBuffer(GL_PIXEL_PACK_BUFFER), 1);
        assert_eq!(glUnmapBuffer(GL_PIXEL_PACK_BUFFER), 0);
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        // Out of the buffer's range.
        glReadPixels(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, 8 as *mut c_void);
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        // The same buffer as an unpack source for a texture, read back.
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, b);
        let mut t = 0u32;
        glGenTextures(1, &mut t);
        glBindTexture(GL_TEXTURE_2D, t);
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            4,
            4,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            std::ptr::null(),
        );
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        assert_eq!(glGetError(), GL_NO_ERROR);
        let mut out = [0u8; 64];
        glGetTexImage(
            GL_TEXTURE_2D,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            out.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(&out[60..64], &[255, 0, 0, 255]);
        let mut w = 0f32;
        glGetTexLevelParameterfv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &mut w);
        assert_eq!(w, 4.0);
        let mut bits = 0;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &mut bits);
        assert_eq!(bits, 8);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, &mut bits);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        // Sub-image 1D/3D.
        let mut t1 = 0u32;
        glGenTextures(1, &mut t1);
        glBindTexture(GL_TEXTURE_1D, t1);
        glTexImage1D(
            GL_TEXTURE_1D,
            0,
            GL_RGBA as i32,
            4,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            std::ptr::null(),
        );
        let px = [9u8, 8, 7, 6];
        glTexSubImage1D(
            GL_TEXTURE_1D,
            0,
            2,
            1,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            px.as_ptr() as *const c_void,
        );
        glGetTexImage(
            GL_TEXTURE_1D,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            out.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(&out[8..12], &px);
        glTexSubImage1D(
            GL_TEXTURE_1D,
            0,
            3,
            2,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            px.as_ptr() as *const c_void,
        );
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        let mut t3 = 0u32;
        glGenTextures(1, &mut t3);
        glBindTexture(GL_TEXTURE_3D, t3);
        glTexImage3D(
            GL_TEXTURE_3D,
            0,
            GL_RGBA as i32,
            2,
            2,
            2,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            std::ptr::null(),
        );
        glTexSubImage3D(
            GL_TEXTURE_3D,
            0,
            1,
            1,
            1,
            1,
            1,
            1,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            px.as_ptr() as *const c_void,
        );
        glGetTexImage(
            GL_TEXTURE_3D,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            out.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(&out[28..32], &px);
        assert_eq!(glGetError(), GL_NO_ERROR);
    });
}

#[test]
fn copy_tex_image_takes_the_framebuffer() {
    common::with_context(8, 8, None, |_| unsafe {
        glClearColor(0.0, 1.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        let mut t = 0u32;
        glGenTextures(1, &mut t);
        glBindTexture(GL_TEXTURE_2D, t);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 1, 1, 4, 2, 0);
        assert_eq!(glGetError(), GL_NO_ERROR);
        let mut out = [0u8; 4 * 2 * 4];
        glGetTexImage(
            GL_TEXTURE_2D,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            out.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(&out[0..4], &[0, 255, 0, 255]);
        glClearColor(0.0, 0.0, 1.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 3, 1, 0, 0, 1, 1);
        glGetTexImage(
            GL_TEXTURE_2D,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            out.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(&out[28..32], &[0, 0, 255, 255]);
        assert_eq!(&out[24..28], &[0, 255, 0, 255]);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 4, 4, 1);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 3, 1, 0, 0, 2, 1);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
    });
}

#[test]
fn interleaved_arrays_array_element_and_multi_draw() {
    common::with_context(8, 8, None, |buf| unsafe {
        // C4UB_V2F: a red then a blue full-screen triangle pair.
        #[repr(C)]
        struct V {
            c: [u8; 4],
            p: [f32; 2],
        }
        let quad =
            |c: [u8; 4]| [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]].map(|p| V { c, p });
        let red = quad([255, 0, 0, 255]);
        glInterleavedArrays(GL_C4UB_V2F, 0, red.as_ptr() as *const c_void);
        assert_eq!(glGetError(), GL_NO_ERROR);
        glBegin(GL_QUADS);
        for i in 0..4 {
            glArrayElement(i);
        }
        glEnd();
        glFinish();
        assert_eq!(&buf[0..4], &[255, 0, 0, 255]);
        let blue = quad([0, 0, 255, 255]);
        glInterleavedArrays(GL_C4UB_V2F, 0, blue.as_ptr() as *const c_void);
        let a: [u16; 3] = [0, 1, 2];
        let b: [u16; 3] = [0, 2, 3];
        let counts = [3, 3];
        let ptrs = [a.as_ptr() as *const c_void, b.as_ptr() as *const c_void];
        glMultiDrawElements(
            GL_TRIANGLES,
            counts.as_ptr(),
            GL_UNSIGNED_SHORT,
            ptrs.as_ptr(),
            2,
        );
        glFinish();
        assert!(buf.chunks(4).all(|p| p == [0, 0, 255, 255]));
        glInterleavedArrays(GL_TEXTURE_2D, 0, blue.as_ptr() as *const c_void);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
    });
}

#[test]
fn legacy_calls_keep_state_or_raise_what_the_spec_says() {
    common::with_context(4, 4, None, |_| unsafe {
        assert_eq!(glRenderMode(GL_RENDER), 0);
        assert_eq!(glGetError(), GL_NO_ERROR);
        glRenderMode(GL_SELECT);
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        glPushName(3);
        assert_eq!(glGetError(), GL_NO_ERROR);
        glAccum(GL_LOAD, 1.0);
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        glLineStipple(3, 0xf0f0);
        let mut v = [0i32; 4];
        glGetIntegerv(GL_LINE_STIPPLE_PATTERN, v.as_mut_ptr());
        assert_eq!(v[0], 0xf0f0);
        glIndexf(5.0);
        glGetIntegerv(GL_CURRENT_INDEX, v.as_mut_ptr());
        assert_eq!(v[0], 5);
        glPixelTransferf(GL_RED_SCALE, 2.0);
        let mut f = 0f32;
        glGetFloatv(GL_RED_SCALE, &mut f);
        assert_eq!(f, 2.0);
        glPixelTransferf(GL_TEXTURE_2D, 2.0);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 3, [0.0f32; 3].as_ptr());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, 16, std::ptr::null());
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD as i32);
        glGetTexEnviv(GL_TEXTURE_ENV, GL_COMBINE_RGB, v.as_mut_ptr());
        assert_eq!(v[0], GL_ADD as i32);
        glGetTexEnviv(GL_TEXTURE_ENV, GL_OPERAND2_RGB, v.as_mut_ptr());
        assert_eq!(v[0], GL_SRC_ALPHA as i32);
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
        glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, v.as_mut_ptr());
        assert_eq!(v[0], GL_SPHERE_MAP as i32);
        glGetTexGeniv(GL_S, GL_TEXTURE_2D, v.as_mut_ptr());
        assert_eq!(glGetError(), GL_INVALID_ENUM);
    });
}

#[test]
fn attribute_stacks_restore_state_and_client_pointers() {
    common::with_context(4, 4, None, |_| unsafe {
        let a = [0f32; 8];
        let b = [0f32; 8];
        glVertexPointer(2, GL_FLOAT, 0, a.as_ptr() as *const c_void);
        glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
        glVertexPointer(3, GL_FLOAT, 0, b.as_ptr() as *const c_void);
        glPopClientAttrib();
        let mut p: *mut c_void = null_mut();
        glGetPointerv(GL_VERTEX_ARRAY_POINTER, &mut p);
        assert_eq!(p as usize, a.as_ptr() as usize);
        let mut size = 0;
        glGetIntegerv(GL_VERTEX_ARRAY_SIZE, &mut size);
        assert_eq!(size, 2);
        // glPushAttrib inside a display list.
        glNewList(1, GL_COMPILE);
        glPushAttrib(GL_ENABLE_BIT);
        glEnable(GL_CULL_FACE);
        glEndList();
        glCallList(1);
        assert_eq!(glIsEnabled(GL_CULL_FACE), 1);
        glPopAttrib();
        assert_eq!(glIsEnabled(GL_CULL_FACE), 0);
        glPopAttrib();
        assert_eq!(glGetError(), GL_STACK_UNDERFLOW);
        glPopClientAttrib();
        assert_eq!(glGetError(), GL_STACK_UNDERFLOW);
    });
}

/// The generated type/arity variants (src/variants.rs) convert as GL 2.1
/// §2.7 / Table 2.9 say: integer colors and normals normalized, positions
/// and texture coordinates not; vector forms compiled into a list keep the
/// values read at compile time.
#[test]
fn generated_variants_convert_and_compile_into_lists() {
    common::with_context(4, 4, None, |_| unsafe {
        let get = |pname: u32| {
            let mut v = [0f32; 4];
            glGetFloatv(pname, v.as_mut_ptr());
            v
        };
        let snorm = |x: f64, max: f64| ((2.0 * x + 1.0) / max) as f32;

        glColor3ub(255, 0, 51);
        assert_eq!(get(GL_CURRENT_COLOR), [1.0, 0.0, 51.0 / 255.0, 1.0]);
        glColor4s(32767, 0, -32768, 32767);
        assert_eq!(get(GL_CURRENT_COLOR), [1.0, snorm(0.0, 65535.0), -1.0, 1.0]);
        let us = [65535u16, 0, 32768, 65535];
        glColor4usv(us.as_ptr());
        assert_eq!(
            get(GL_CURRENT_COLOR),
            [1.0, 0.0, (32768.0 / 65535.0f64) as f32, 1.0]
        );

        glNormal3b(-128, 0, 127);
        let n = get(GL_CURRENT_NORMAL);
        assert_eq!(&n[..3], &[-1.0, snorm(0.0, 255.0), 1.0]);

        glTexCoord2s(3, 4);
        assert_eq!(get(GL_CURRENT_TEXTURE_COORDS), [3.0, 4.0, 0.0, 1.0]);
        let t = [1i32, 2, 3];
        glMultiTexCoord3iv(GL_TEXTURE1, t.as_ptr());
        glActiveTexture(GL_TEXTURE1);
        assert_eq!(get(GL_CURRENT_TEXTURE_COORDS), [1.0, 2.0, 3.0, 1.0]);
        glActiveTexture(GL_TEXTURE0);

        let mut a = [0f32; 4];
        glVertexAttrib4Nusv(1, us.as_ptr());
        glGetVertexAttribfv(1, GL_CURRENT_VERTEX_ATTRIB, a.as_mut_ptr());
        assert_eq!(a, [1.0, 0.0, (32768.0 / 65535.0f64) as f32, 1.0]);
        glVertexAttrib4usv(1, us.as_ptr());
        glGetVertexAttribfv(1, GL_CURRENT_VERTEX_ATTRIB, a.as_mut_ptr());
        assert_eq!(a, [65535.0, 0.0, 32768.0, 65535.0]);
        glVertexAttrib2d(2, 0.5, 2.0);
        glGetVertexAttribfv(2, GL_CURRENT_VERTEX_ATTRIB, a.as_mut_ptr());
        assert_eq!(a, [0.5, 2.0, 0.0, 1.0]);

        glIndexs(7);
        assert_eq!(get(GL_CURRENT_INDEX)[0], 7.0);

        // A vector call compiled into a list keeps the values it read.
        let mut v = [0u8, 255, 0];
        glNewList(1, GL_COMPILE);
        glColor3ubv(v.as_ptr());
        glEndList();
        assert_eq!(
            get(GL_CURRENT_COLOR),
            [1.0, 0.0, (32768.0 / 65535.0f64) as f32, 1.0]
        );
        v[1] = 0;
        std::hint::black_box(&v);
        glCallList(1);
        assert_eq!(get(GL_CURRENT_COLOR), [0.0, 1.0, 0.0, 1.0]);
        assert_eq!(glGetError(), GL_NO_ERROR);
    });
}

#[test]
fn arb_shader_objects_names_work_on_shader_and_program_objects() {
    common::with_context(4, 4, None, |_| unsafe {
        let vs = glCreateShaderObjectARB(GL_VERTEX_SHADER);
        let src = c"void main() { gl_Position = gl_Vertex; }";
        let ptr = src.as_ptr();
        glShaderSource(vs, 1, &ptr, std::ptr::null());
        glCompileShader(vs);
        let p = glCreateProgramObjectARB();
        glAttachObjectARB(p, vs);
        glLinkProgram(p);
        let mut v = 0;
        // GL_OBJECT_TYPE_ARB, GL_OBJECT_SUBTYPE_ARB, GL_OBJECT_COMPILE_STATUS_ARB.
        glGetObjectParameterivARB(vs, 0x8B4E, &mut v);
        assert_eq!(v, 0x8B48);
        glGetObjectParameterivARB(vs, 0x8B4F, &mut v);
        assert_eq!(v, GL_VERTEX_SHADER as i32);
        glGetObjectParameterivARB(vs, 0x8B81, &mut v);
        assert_eq!(v, 1);
        glGetObjectParameterivARB(p, 0x8B4E, &mut v);
        assert_eq!(v, 0x8B40);
        let mut f = 0.0f32;
        glGetObjectParameterfvARB(p, GL_LINK_STATUS, &mut f);
        assert_eq!(f, 1.0);
        glGetObjectParameterivARB(p, 0x8B4F, &mut v);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glGetObjectParameterivARB(999, 0x8B4E, &mut v);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        let (mut n, mut objs) = (0, [0u32; 2]);
        glGetAttachedObjectsARB(p, 2, &mut n, objs.as_mut_ptr());
        assert_eq!((n, objs[0]), (1, vs));
        let mut log = [0 as GLchar; 8];
        glGetInfoLogARB(vs, 8, &mut n, log.as_mut_ptr());
        assert_eq!(glGetError(), GL_NO_ERROR);
        glUseProgramObjectARB(p);
        assert_eq!(glGetHandleARB(0x8B40), p);
        glGetHandleARB(GL_VERTEX_SHADER);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glUseProgramObjectARB(0);
        glDetachObjectARB(p, vs);
        glDeleteObjectARB(vs);
        assert_eq!(glIsShader(vs), 0);
        glDeleteObjectARB(p);
        assert_eq!(glIsProgram(p), 0);
        glDeleteObjectARB(p);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        assert_eq!(glGetError(), GL_NO_ERROR);
    });
}
