//! GL 3.0–3.3 state entry points, driven as a C program would on a 3.3
//! compatibility context: the provoking vertex, per-draw-buffer blending
//! and masks and their indexed queries, glClearBuffer*, fragment-output
//! locations, transform feedback, and their lookup by name.

use gl::enums::*;
use std::ffi::{c_void, CString};
use OSMesa::*;

mod common;

const NAMES: &[&str] = &[
    "glProvokingVertex",
    "glEnablei",
    "glDisablei",
    "glIsEnabledi",
    "glColorMaski",
    "glGetBooleani_v",
    "glGetIntegeri_v",
    "glClearBufferfv",
    "glClearBufferiv",
    "glClearBufferuiv",
    "glClearBufferfi",
    "glBindFragDataLocation",
    "glGetFragDataLocation",
    "glTransformFeedbackVaryings",
    "glGetTransformFeedbackVarying",
    "glBeginTransformFeedback",
    "glEndTransformFeedback",
    "glSampleMaski",
    "glGetMultisamplefv",
];

unsafe fn pixel() -> [u8; 4] {
    common::pixel_at(4, 4)
}

#[test]
fn entry_points_are_exported_by_name() {
    common::assert_exported(NAMES);
}

#[test]
fn per_buffer_state_clears_and_frag_data_locations() {
    common::with_context(8, 8, Some(OSMESA_COMPAT_PROFILE), |_| unsafe {
        glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
        let mut v = [0i32; 4];
        glGetIntegerv(GL_PROVOKING_VERTEX, v.as_mut_ptr());
        assert_eq!(v[0], GL_FIRST_VERTEX_CONVENTION as i32);

        glColorMaski(0, 1, 0, 1, 1);
        let mut m = [9u8; 4];
        glGetBooleani_v(GL_COLOR_WRITEMASK, 0, m.as_mut_ptr());
        assert_eq!(m, [1, 0, 1, 1]);
        glGetIntegeri_v(GL_COLOR_WRITEMASK, 1, v.as_mut_ptr());
        assert_eq!(v, [1, 1, 1, 1]);
        glEnablei(GL_BLEND, 2);
        assert_eq!(glIsEnabledi(GL_BLEND, 2), 1);
        assert_eq!(glIsEnabledi(GL_BLEND, 0), 0);
        glDisablei(GL_BLEND, 2);
        assert_eq!(glIsEnabledi(GL_BLEND, 2), 0);
        assert_eq!(glGetError(), GL_NO_ERROR);

        // Green is masked off on draw buffer 0.
        let white = [1.0f32; 4];
        glClearBufferfv(GL_COLOR, 0, white.as_ptr());
        assert_eq!(pixel(), [255, 0, 255, 255]);
        glColorMask(1, 1, 1, 1);
        glClearBufferfi(GL_DEPTH_STENCIL, 0, 0.5, 1);
        let mut d = 0f32;
        glReadPixels(
            4,
            4,
            1,
            1,
            GL_DEPTH_COMPONENT,
            GL_FLOAT,
            &mut d as *mut f32 as *mut c_void,
        );
        assert!((d - 0.5).abs() < 1e-6, "{d}");
        let s = [2i32];
        glClearBufferiv(GL_STENCIL, 0, s.as_ptr());
        let mut st = 0u8;
        glReadPixels(
            4,
            4,
            1,
            1,
            GL_STENCIL_INDEX,
            GL_UNSIGNED_BYTE,
            &mut st as *mut u8 as *mut c_void,
        );
        assert_eq!(st, 2);
        assert_eq!(glGetError(), GL_NO_ERROR);
        glClearBufferuiv(GL_DEPTH, 0, [0u32].as_ptr());
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glClearBufferfv(GL_COLOR, 8, white.as_ptr());
        assert_eq!(glGetError(), GL_INVALID_VALUE);

        // Fragment outputs: a binding places `b` on draw buffer 0.
        let p = glCreateProgram();
        let fs = "#version 130\nout vec4 a;\nout vec4 b;\nvoid main() { a = vec4(1.0); b = vec4(0.0, 0.0, 1.0, 1.0); }\n";
        glAttachShader(p, common::shader(GL_FRAGMENT_SHADER, fs));
        let (a, b) = (CString::new("a").unwrap(), CString::new("b").unwrap());
        glBindFragDataLocation(p, 0, b.as_ptr());
        glLinkProgram(p);
        assert_eq!(glGetFragDataLocation(p, b.as_ptr()), 0);
        assert_eq!(glGetFragDataLocation(p, a.as_ptr()), 1);
        glUseProgram(p);
        glBegin(GL_QUADS);
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            glVertex2f(x, y);
        }
        glEnd();
        assert_eq!(pixel(), [0, 0, 255, 255]);
        glBindFragDataLocation(p, 8, a.as_ptr());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
    });
}

#[test]
fn transform_feedback_captures_points() {
    common::with_context(8, 8, Some(OSMESA_COMPAT_PROFILE), |_| unsafe {
        let p = glCreateProgram();
        let vs = "#version 130\nin float x;\nout float y;\nvoid main() { gl_Position = vec4(x); y = 2.0 * x; }\n";
        glAttachShader(p, common::shader(GL_VERTEX_SHADER, vs));
        let x = CString::new("x").unwrap();
        glBindAttribLocation(p, 0, x.as_ptr());
        let names = [
            CString::new("y").unwrap(),
            CString::new("gl_Position").unwrap(),
        ];
        let ptrs: Vec<*const GLchar> = names.iter().map(|n| n.as_ptr()).collect();
        glTransformFeedbackVaryings(p, 2, ptrs.as_ptr(), GL_INTERLEAVED_ATTRIBS);
        glLinkProgram(p);
        let mut ok = 0;
        glGetProgramiv(p, GL_LINK_STATUS, &mut ok);
        assert_eq!(ok, 1);
        let (mut n, mut size, mut ty) = (0, 0, 0u32);
        let mut name = [0 as GLchar; 32];
        glGetTransformFeedbackVarying(p, 1, 32, &mut n, &mut size, &mut ty, name.as_mut_ptr());
        assert_eq!((n, size, ty), (11, 1, GL_FLOAT_VEC4));
        glUseProgram(p);
        let mut b = 0;
        glGenBuffers(1, &mut b);
        glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, b);
        glBufferData(
            GL_TRANSFORM_FEEDBACK_BUFFER,
            60,
            std::ptr::null(),
            GL_STREAM_READ,
        );
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, b);
        let xs = [1.0f32, 2.0, 3.0];
        glVertexAttribPointer(0, 1, GL_FLOAT, 0, 0, xs.as_ptr() as *const c_void);
        glEnableVertexAttribArray(0);
        glEnable(GL_RASTERIZER_DISCARD);
        glBeginTransformFeedback(GL_POINTS);
        glDrawArrays(GL_POINTS, 0, 3);
        glEndTransformFeedback();
        glDisable(GL_RASTERIZER_DISCARD);
        assert_eq!(glGetError(), GL_NO_ERROR);
        let mut out = [0f32; 15];
        glGetBufferSubData(
            GL_TRANSFORM_FEEDBACK_BUFFER,
            0,
            60,
            out.as_mut_ptr() as *mut c_void,
        );
        for (i, x) in xs.iter().enumerate() {
            assert_eq!(&out[i * 5..i * 5 + 5], &[2.0 * x, *x, *x, *x, *x]);
        }
        glEndTransformFeedback();
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
    });
}
