//! Drives the C entry points the way a C program would.

use gl::enums::*;
use std::ffi::{c_void, CStr};
use std::ptr::{null, null_mut};
use OSMesa::*;
use OSMesa::{GL_FALSE, GL_TRUE};

mod common;
use common::shader;

const W: i32 = 32;
const H: i32 = 16;

const VS: &str = "attribute vec2 pos;\nattribute vec3 col;\nvarying vec3 v;\n\
void main() { v = col; gl_Position = vec4(pos, 0.0, 1.0); }\n";
const FS: &str =
    "varying vec3 v;\nuniform float k;\nvoid main() { gl_FragColor = vec4(v * k, 1.0); }\n";

unsafe fn info_log(s: u32) -> String {
    let mut buf = vec![0 as GLchar; 4096];
    let mut len = 0;
    glGetShaderInfoLog(s, buf.len() as i32, &mut len, buf.as_mut_ptr());
    CStr::from_ptr(buf.as_ptr()).to_string_lossy().into_owned()
}

fn px(buf: &[u8], x: i32, y: i32) -> [u8; 4] {
    let i = ((y * W + x) * 4) as usize;
    [buf[i], buf[i + 1], buf[i + 2], buf[i + 3]]
}

#[test]
fn triangle_with_attrib_pointers_lands_in_the_client_buffer() {
    unsafe {
        let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, null_mut());
        assert!(!ctx.is_null());
        let mut buf = vec![7u8; (W * H * 4) as usize];
        assert_eq!(
            OSMesaMakeCurrent(ctx, buf.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, W, H),
            GL_TRUE
        );
        assert_eq!(OSMesaGetCurrentContext(), ctx);
        let mut v = [0i32; 4];
        glGetIntegerv(GL_VIEWPORT, v.as_mut_ptr());
        assert_eq!(v, [0, 0, W, H]);
        let version = CStr::from_ptr(glGetString(GL_VERSION) as *const _);
        assert!(version.to_str().unwrap().starts_with("2.1 shaderbox"));

        let vs = shader(GL_VERTEX_SHADER, VS);
        let fs = shader(GL_FRAGMENT_SHADER, FS);
        let mut ok = 0;
        glGetShaderiv(vs, GL_COMPILE_STATUS, &mut ok);
        assert_eq!(ok, 1, "{}", info_log(vs));
        let prog = glCreateProgram();
        glAttachShader(prog, vs);
        glAttachShader(prog, fs);
        glBindAttribLocation(prog, 1, c"col".as_ptr());
        glLinkProgram(prog);
        glGetProgramiv(prog, GL_LINK_STATUS, &mut ok);
        assert_eq!(ok, 1);
        glUseProgram(prog);
        assert_eq!(glGetAttribLocation(prog, c"col".as_ptr()), 1);
        let k = glGetUniformLocation(prog, c"k".as_ptr());
        assert!(k >= 0);
        glUniform1f(k, 1.0);

        glClearColor(0.0, 0.0, 1.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        // Not copied until a flush (Mesa's llvmpipe bins draws too).
        assert_eq!(px(&buf, 0, 0), [7, 7, 7, 7]);
        glFlush();
        assert_eq!(px(&buf, 0, 0), [0, 0, 255, 255]);

        // Interleaved: pos.xy, col.rgb; a big triangle covering the lower
        // left half, red at every vertex.
        let verts: Vec<f32> = vec![
            -1.0, -1.0, 1.0, 0.0, 0.0, //
            3.0, -1.0, 1.0, 0.0, 0.0, //
            -1.0, 3.0, 1.0, 0.0, 0.0,
        ];
        let pos = glGetAttribLocation(prog, c"pos".as_ptr()) as u32;
        glVertexAttribPointer(pos, 2, GL_FLOAT, 0, 20, verts.as_ptr() as *const c_void);
        glVertexAttribPointer(
            1,
            3,
            GL_FLOAT,
            0,
            20,
            verts.as_ptr().add(2) as *const c_void,
        );
        glEnableVertexAttribArray(pos);
        glEnableVertexAttribArray(1);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glFinish();
        assert_eq!(glGetError(), GL_NO_ERROR);
        assert_eq!(px(&buf, 0, 0), [255, 0, 0, 255]);
        assert_eq!(px(&buf, W - 1, H - 1), [255, 0, 0, 255]);

        // Indexed, with half brightness, on the top-right region only.
        glClear(GL_COLOR_BUFFER_BIT);
        glUniform1f(k, 0.5);
        let quad: Vec<f32> = vec![
            0.0, 0.0, 0.0, 1.0, 0.0, //
            1.0, 0.0, 0.0, 1.0, 0.0, //
            1.0, 1.0, 0.0, 1.0, 0.0, //
            0.0, 1.0, 0.0, 1.0, 0.0,
        ];
        glVertexAttribPointer(pos, 2, GL_FLOAT, 0, 20, quad.as_ptr() as *const c_void);
        glVertexAttribPointer(1, 3, GL_FLOAT, 0, 20, quad.as_ptr().add(2) as *const c_void);
        let idx: [u16; 6] = [0, 1, 2, 0, 2, 3];
        glDrawElements(
            GL_TRIANGLES,
            6,
            GL_UNSIGNED_SHORT,
            idx.as_ptr() as *const c_void,
        );
        glFinish();
        assert_eq!(glGetError(), GL_NO_ERROR);
        assert_eq!(px(&buf, 0, 0), [0, 0, 255, 255]);
        assert_eq!(px(&buf, W - 1, H - 1), [0, 128, 0, 255]);

        // glReadPixels agrees with the buffer (both bottom row first).
        let mut rp = vec![0u8; (W * H * 4) as usize];
        glReadPixels(
            0,
            0,
            W,
            H,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            rp.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(rp, buf);

        // Y_UP = 0: memory is now read top row first (the buffer is the
        // framebuffer, as in Mesa): GL's bottom-right pixel is the last
        // memory row's, green.
        OSMesaPixelStore(OSMESA_Y_UP, 0);
        assert_eq!(px(&buf, W - 1, H - 1), [0, 128, 0, 255]);
        let mut one = [0u8; 4];
        glReadPixels(
            W - 1,
            0,
            1,
            1,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            one.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(one, [0, 128, 0, 255]);
        // New drawing lands top row first: GL's row y=0 is memory row H-1.
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, W, 1);
        glClearColor(1.0, 1.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        glFinish();
        assert_eq!(px(&buf, 0, H - 1), [255, 255, 0, 255]);
        assert_eq!(px(&buf, 0, 0), [0, 0, 255, 255]);

        // Errors, never crashes.
        glShaderSource(vs, -1, null(), null());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        // A NULL string in the array: GL_INVALID_OPERATION, as Mesa.
        let some = c"void main() {}".as_ptr();
        let with_null = [some, null()];
        glShaderSource(vs, 2, with_null.as_ptr(), null());
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        glShaderSource(0xbad, 2, with_null.as_ptr(), null());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glEnable(0xdead);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glLoadMatrixf(null());
        glDrawArrays(GL_TRIANGLES, 0, -1);
        assert_eq!(glGetError(), GL_INVALID_VALUE);

        OSMesaDestroyContext(ctx);
        assert!(OSMesaGetCurrentContext().is_null());
        assert_eq!(glGetError(), GL_NO_ERROR); // no context: nothing
        OSMesaDestroyContext(ctx); // stale handle: ignored
    }
}

#[test]
fn bad_shader_reports_compile_status_false_with_a_log() {
    unsafe {
        let ctx = OSMesaCreateContext(OSMESA_BGRA, null_mut());
        let mut buf = vec![0u8; 4 * 4 * 4];
        assert_eq!(
            OSMesaMakeCurrent(ctx, buf.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, 4, 4),
            GL_TRUE
        );
        let s = shader(
            GL_FRAGMENT_SHADER,
            "void main() { gl_FragColor = undefined_thing; }",
        );
        let mut ok = 1;
        glGetShaderiv(s, GL_COMPILE_STATUS, &mut ok);
        assert_eq!(ok, 0);
        let mut len = 0;
        glGetShaderiv(s, GL_INFO_LOG_LENGTH, &mut len);
        assert!(len > 1);
        let log = info_log(s);
        assert!(log.contains("undefined_thing"), "{log}");

        // BGRA byte order.
        glClearColor(1.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glFinish();
        assert_eq!(&buf[0..4], &[0, 0, 255, 255]);
        OSMesaMakeCurrent(null_mut(), null_mut(), 0, 0, 0);
        OSMesaDestroyContext(ctx);
    }
}

#[test]
fn context_attribs_and_queries() {
    unsafe {
        let attribs = [
            OSMESA_FORMAT,
            OSMESA_RGB as i32,
            OSMESA_DEPTH_BITS,
            16,
            OSMESA_PROFILE,
            OSMESA_COMPAT_PROFILE,
            OSMESA_CONTEXT_MAJOR_VERSION,
            2,
            OSMESA_CONTEXT_MINOR_VERSION,
            1,
            0,
        ];
        let ctx = OSMesaCreateContextAttribs(attribs.as_ptr(), null_mut());
        assert!(!ctx.is_null());
        let v34 = [
            OSMESA_CONTEXT_MAJOR_VERSION,
            3,
            OSMESA_CONTEXT_MINOR_VERSION,
            4,
            0,
        ];
        assert!(OSMesaCreateContextAttribs(v34.as_ptr(), null_mut()).is_null());
        let bad_profile = [OSMESA_PROFILE, 0x99, 0];
        assert!(OSMesaCreateContextAttribs(bad_profile.as_ptr(), null_mut()).is_null());

        let mut buf = vec![0u8; 5 * 3 * 3];
        let p = buf.as_mut_ptr() as *mut c_void;
        assert_eq!(OSMesaMakeCurrent(ctx, p, GL_FLOAT, 0, 3), GL_FALSE);
        assert_eq!(OSMesaMakeCurrent(ctx, p, GL_UNSIGNED_BYTE, 5, 3), GL_TRUE);
        let mut w = 0;
        OSMesaGetIntegerv(OSMESA_WIDTH, &mut w);
        assert_eq!(w, 5);
        glClearDepth(0.5);
        glClear(GL_DEPTH_BUFFER_BIT);
        let (mut dw, mut dh, mut bpv, mut dp) = (0, 0, 0, null_mut());
        assert_eq!(
            OSMesaGetDepthBuffer(ctx, &mut dw, &mut dh, &mut bpv, &mut dp),
            GL_TRUE
        );
        assert_eq!((dw, dh, bpv), (5, 3, 2));
        let d = *(dp as *const u16);
        assert!((d as i32 - 32767).abs() <= 1, "{d}");

        let f = OSMesaGetProcAddress(c"glClear".as_ptr());
        assert!(f.is_some());
        assert!(OSMesaGetProcAddress(c"glNoSuchThing".as_ptr()).is_none());
        // The advertised extensions' suffixed names are the core functions.
        for (ext, core) in [
            (c"glActiveTextureARB", c"glActiveTexture"),
            (c"glBindBufferARB", c"glBindBuffer"),
            (c"glBlendEquationEXT", c"glBlendEquation"),
            (c"glVertexAttribDivisorARB", c"glVertexAttribDivisor"),
        ] {
            let e = OSMesaGetProcAddress(ext.as_ptr()).map(|f| f as usize);
            let c = OSMesaGetProcAddress(core.as_ptr()).map(|f| f as usize);
            assert!(e.is_some() && e == c, "{ext:?}");
        }
        // ARB_vertex_program's names are not GLSL's functions.
        assert!(OSMesaGetProcAddress(c"glIsProgramARB".as_ptr()).is_none());
        assert!(OSMesaGetProcAddress(c"glNoSuchThingEXT".as_ptr()).is_none());
        OSMesaDestroyContext(ctx);
    }
}

unsafe fn string(name: u32) -> Option<String> {
    let p = glGetString(name);
    (!p.is_null()).then(|| CStr::from_ptr(p as *const _).to_string_lossy().into_owned())
}

unsafe fn integer(pname: u32) -> i32 {
    let mut v = -1;
    glGetIntegerv(pname, &mut v);
    v
}

/// A context made current on a fresh `W`x`H` buffer from an attribute
/// list, with what GL_VERSION says.
unsafe fn attrib_context(attribs: &[i32], buf: &mut [u8]) -> (OSMesaContext, String) {
    let ctx = OSMesaCreateContextAttribs(attribs.as_ptr(), null_mut());
    assert!(!ctx.is_null(), "{attribs:x?}");
    let p = buf.as_mut_ptr() as *mut c_void;
    assert_eq!(OSMesaMakeCurrent(ctx, p, GL_UNSIGNED_BYTE, W, H), GL_TRUE);
    (ctx, string(GL_VERSION).unwrap())
}

#[test]
fn contexts_by_version_and_profile() {
    unsafe {
        let mut buf = vec![0u8; (W * H * 4) as usize];
        let (ctx, v) = attrib_context(&[0], &mut buf);
        assert!(v.starts_with("2.1 shaderbox"), "{v}");
        assert_eq!(string(GL_SHADING_LANGUAGE_VERSION).unwrap(), "1.20");
        assert_eq!(integer(GL_MAJOR_VERSION), -1);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        OSMesaDestroyContext(ctx);

        let compat = [
            OSMESA_CONTEXT_MAJOR_VERSION,
            3,
            OSMESA_CONTEXT_MINOR_VERSION,
            2,
            0,
        ];
        let (ctx, v) = attrib_context(&compat, &mut buf);
        assert!(
            v.starts_with("3.3 (Compatibility Profile) shaderbox"),
            "{v}"
        );
        assert_eq!(integer(GL_CONTEXT_PROFILE_MASK), 2);
        assert!(string(GL_EXTENSIONS)
            .unwrap()
            .contains("GL_ARB_compatibility"));
        glBegin(GL_TRIANGLES);
        glEnd();
        assert_eq!(glGetError(), GL_NO_ERROR);
        OSMesaDestroyContext(ctx);

        // Mesa answers a core request of any version up to its own with a
        // core context; so does shaderbox.
        for minor in [0, 3] {
            let core = [
                OSMESA_PROFILE,
                OSMESA_CORE_PROFILE,
                OSMESA_CONTEXT_MAJOR_VERSION,
                3,
                OSMESA_CONTEXT_MINOR_VERSION,
                minor,
                0,
            ];
            let (ctx, v) = attrib_context(&core, &mut buf);
            assert!(v.starts_with("3.3 (Core Profile) shaderbox"), "{v}");
            assert_eq!(string(GL_SHADING_LANGUAGE_VERSION).unwrap(), "3.30");
            assert_eq!(
                (integer(GL_MAJOR_VERSION), integer(GL_MINOR_VERSION)),
                (3, 3)
            );
            assert_eq!(integer(GL_CONTEXT_PROFILE_MASK), 1);
            assert_eq!(integer(GL_CONTEXT_FLAGS), 0);
            assert_eq!(glGetError(), GL_NO_ERROR);
            // No unified extension string: glGetStringi numbers them.
            assert_eq!(string(GL_EXTENSIONS), None);
            assert_eq!(glGetError(), GL_INVALID_ENUM);
            let n = integer(GL_NUM_EXTENSIONS);
            let names: Vec<String> = (0..n as u32)
                .map(|i| {
                    CStr::from_ptr(glGetStringi(GL_EXTENSIONS, i) as *const _)
                        .to_string_lossy()
                        .into_owned()
                })
                .collect();
            assert!(
                names.iter().any(|e| e == "GL_ARB_framebuffer_object"),
                "{names:?}"
            );
            assert!(!names.iter().any(|e| e == "GL_ARB_compatibility"));
            assert!(glGetStringi(GL_EXTENSIONS, n as u32).is_null());
            assert_eq!(glGetError(), GL_INVALID_VALUE);
            // What the core profile removes: entry points, capabilities,
            // state, draw modes, drawing without a program.
            glBegin(GL_TRIANGLES);
            assert_eq!(glGetError(), GL_INVALID_OPERATION);
            glMatrixMode(GL_PROJECTION);
            assert_eq!(glGetError(), GL_INVALID_OPERATION);
            assert_eq!(glGenLists(1), 0);
            assert_eq!(glGetError(), GL_INVALID_OPERATION);
            glEnable(GL_LIGHTING);
            assert_eq!(glGetError(), GL_INVALID_ENUM);
            glEnable(GL_DEPTH_TEST);
            assert_eq!(glGetError(), GL_NO_ERROR);
            glDisable(GL_DEPTH_TEST);
            assert_eq!(integer(GL_MODELVIEW_STACK_DEPTH), -1);
            assert_eq!(glGetError(), GL_INVALID_ENUM);
            assert_eq!(integer(GL_ACCUM_RED_BITS), -1);
            assert_eq!(glGetError(), GL_INVALID_ENUM);
            glDrawArrays(GL_TRIANGLES, 0, 3);
            assert_eq!(glGetError(), GL_INVALID_OPERATION);
            glDrawArrays(GL_QUADS, 0, 4);
            assert_eq!(glGetError(), GL_INVALID_ENUM);
            // GLSL 1.10 and 1.20 are gone; 1.30+ compile.
            let old = shader(
                GL_FRAGMENT_SHADER,
                "void main() { gl_FragColor = vec4(1.0); }\n",
            );
            let mut ok = 1;
            glGetShaderiv(old, GL_COMPILE_STATUS, &mut ok);
            assert_eq!(ok, 0);
            assert!(
                info_log(old).contains("core-profile context"),
                "{}",
                info_log(old)
            );
            let new = shader(
                GL_FRAGMENT_SHADER,
                "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n",
            );
            glGetShaderiv(new, GL_COMPILE_STATUS, &mut ok);
            assert_eq!(ok, 1, "{}", info_log(new));
            // A core draw: a program, a vertex array object, a buffer.
            let vs = shader(
                GL_VERTEX_SHADER,
                "#version 330 core\nlayout(location = 0) in vec2 p;\n\
                 void main() { gl_Position = vec4(p, 0.0, 1.0); }\n",
            );
            let prog = glCreateProgram();
            glAttachShader(prog, vs);
            glAttachShader(prog, new);
            glLinkProgram(prog);
            glUseProgram(prog);
            glDrawArrays(GL_TRIANGLES, 0, 3);
            assert_eq!(glGetError(), GL_INVALID_OPERATION, "no vertex array object");
            let tri: [f32; 6] = [-1.0, -1.0, 3.0, -1.0, -1.0, 3.0];
            glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, tri.as_ptr() as *const c_void);
            assert_eq!(glGetError(), GL_INVALID_OPERATION, "no client arrays");
            let (mut vao, mut vbo) = (0, 0);
            glGenVertexArrays(1, &mut vao);
            glBindVertexArray(vao);
            glGenBuffers(1, &mut vbo);
            glBindBuffer(GL_ARRAY_BUFFER, vbo);
            glBufferData(
                GL_ARRAY_BUFFER,
                24,
                tri.as_ptr() as *const c_void,
                GL_STATIC_DRAW,
            );
            glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, null());
            glEnableVertexAttribArray(0);
            glClearColor(0.0, 0.0, 0.0, 0.0);
            glClear(GL_COLOR_BUFFER_BIT);
            glDrawArrays(GL_TRIANGLES, 0, 3);
            assert_eq!(glGetError(), GL_NO_ERROR);
            let idx: [u16; 3] = [0, 1, 2];
            glDrawElements(
                GL_TRIANGLES,
                3,
                GL_UNSIGNED_SHORT,
                idx.as_ptr() as *const c_void,
            );
            assert_eq!(glGetError(), GL_INVALID_OPERATION, "no client index arrays");
            glFinish();
            assert_eq!(px(&buf, 3, 3), [255, 255, 255, 255]);
            OSMesaDestroyContext(ctx);
        }
    }
}

#[test]
fn texture_vbo_and_pbo_guard() {
    unsafe {
        let ctx = OSMesaCreateContext(OSMESA_RGBA, null_mut());
        let mut buf = vec![0u8; (W * H * 4) as usize];
        OSMesaMakeCurrent(ctx, buf.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, W, H);
        // A 2x1 texture: left texel red, right texel green, nearest.
        let mut tex = 0;
        glGenTextures(1, &mut tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        let texels: [u8; 8] = [255, 0, 0, 255, 0, 255, 0, 255];
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            2,
            1,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            texels.as_ptr() as *const c_void,
        );
        glEnable(GL_TEXTURE_2D);
        // A full-screen quad from a vertex buffer object (offsets, not pointers).
        let quad: [f32; 16] = [
            -1.0, -1.0, 0.0, 0.0, 1.0, -1.0, 1.0, 0.0, 1.0, 1.0, 1.0, 1.0, -1.0, 1.0, 0.0, 1.0,
        ];
        let mut vbo = 0;
        glGenBuffers(1, &mut vbo);
        glBindBuffer(GL_ARRAY_BUFFER, vbo);
        glBufferData(
            GL_ARRAY_BUFFER,
            64,
            quad.as_ptr() as *const c_void,
            GL_STATIC_DRAW,
        );
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glVertexPointer(2, GL_FLOAT, 16, null());
        glTexCoordPointer(2, GL_FLOAT, 16, 8 as *const c_void);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glDrawArrays(GL_QUADS, 0, 4);
        glFinish();
        assert_eq!(glGetError(), GL_NO_ERROR);
        assert_eq!(px(&buf, 1, H / 2), [255, 0, 0, 255]);
        assert_eq!(px(&buf, W - 2, H / 2), [0, 255, 0, 255]);

        // Active uniform/attrib queries are reachable.
        let mut n = 0;
        let mut shaders = [0u32; 4];
        glGetAttachedShaders(0, 4, &mut n, shaders.as_mut_ptr());
        assert_eq!(glGetError(), GL_INVALID_VALUE);

        // With a pixel-unpack buffer bound the pointer is an offset: refused,
        // never dereferenced.
        let mut pbo = 0;
        glGenBuffers(1, &mut pbo);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo);
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            2,
            1,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            16 as *const c_void,
        );
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        OSMesaDestroyContext(ctx);
    }
}

#[test]
fn row_length_resize_and_other_types() {
    unsafe {
        let ctx = OSMesaCreateContext(OSMESA_RGBA, null_mut());
        // 4x2 image in rows of 6 pixels: padding pixels stay untouched.
        let mut buf = vec![9u8; 6 * 2 * 4];
        OSMesaMakeCurrent(ctx, buf.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, 4, 2);
        OSMesaPixelStore(OSMESA_ROW_LENGTH, 6);
        glClearColor(1.0, 1.0, 1.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glFinish();
        assert_eq!(&buf[12..16], &[255; 4]);
        assert_eq!(&buf[16..24], &[9; 8]);
        assert_eq!(&buf[24..28], &[255; 4]);
        OSMesaPixelStore(OSMESA_ROW_LENGTH, 0);

        // The buffer's contents are the framebuffer's: a scissored clear
        // keeps what the client put outside the scissor box.
        let mut pre = vec![[10u8, 20, 30, 40]; 4 * 2];
        OSMesaMakeCurrent(ctx, pre.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, 4, 2);
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, 2, 2);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        glFinish();
        assert_eq!(pre[0], [255; 4]);
        assert_eq!(pre[3], [10, 20, 30, 40]);

        // Same context, a bigger float buffer: the framebuffer follows; the
        // viewport set by the first MakeCurrent stays (window resize).
        let mut fbuf = vec![0f32; 8 * 8 * 4];
        assert_eq!(
            OSMesaMakeCurrent(ctx, fbuf.as_mut_ptr() as *mut c_void, GL_FLOAT, 8, 8),
            GL_TRUE
        );
        glClearColor(0.0, 0.2, 1.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glFinish();
        assert_eq!(&fbuf[63 * 4..64 * 4], &[0.0, 0.2, 1.0, 1.0]);
        let mut v = [0i32; 4];
        glGetIntegerv(GL_VIEWPORT, v.as_mut_ptr());
        assert_eq!(v, [0, 0, 4, 2]);
        OSMesaDestroyContext(ctx);

        let ctx = OSMesaCreateContext(OSMESA_RGB_565, null_mut());
        let mut sbuf = vec![0u16; 4];
        assert_eq!(
            OSMesaMakeCurrent(
                ctx,
                sbuf.as_mut_ptr() as *mut c_void,
                GL_UNSIGNED_BYTE,
                2,
                2
            ),
            GL_FALSE
        );
        assert_eq!(
            OSMesaMakeCurrent(
                ctx,
                sbuf.as_mut_ptr() as *mut c_void,
                GL_UNSIGNED_SHORT_5_6_5,
                2,
                2
            ),
            GL_TRUE
        );
        glClearColor(0.0, 1.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glFlush();
        assert_eq!(sbuf, vec![0x07e0; 4]);
        OSMesaDestroyContext(ctx);
    }
}

#[test]
fn contexts_on_two_threads_are_independent() {
    let run = |r: f32| {
        std::thread::spawn(move || unsafe {
            let ctx = OSMesaCreateContext(OSMESA_RGBA, null_mut());
            let mut buf = vec![0u8; 16 * 16 * 4];
            OSMesaMakeCurrent(
                ctx,
                buf.as_mut_ptr() as *mut c_void,
                GL_UNSIGNED_BYTE,
                16,
                16,
            );
            for _ in 0..50 {
                glClearColor(r, 0.0, 0.0, 1.0);
                glClear(GL_COLOR_BUFFER_BIT);
                glFinish();
            }
            OSMesaDestroyContext(ctx);
            buf[0]
        })
    };
    let (a, b) = (run(1.0), run(0.0));
    assert_eq!(a.join().unwrap(), 255);
    assert_eq!(b.join().unwrap(), 0);
}

#[test]
fn display_lists_replay_what_they_recorded() {
    unsafe {
        let ctx = OSMesaCreateContext(OSMESA_RGBA, null_mut());
        let mut buf = vec![0u8; (W * H * 4) as usize];
        OSMesaMakeCurrent(ctx, buf.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, W, H);
        let l = glGenLists(2);
        assert!(l > 0 && glIsList(l) == 1 && glIsList(l + 1) == 1);
        glNewList(l, GL_COMPILE);
        glColor3fv([0.0f32, 1.0, 0.0].as_ptr());
        glBegin(GL_TRIANGLES);
        glVertex2f(-1.0, -1.0);
        glVertex2f(3.0, -1.0);
        glVertex2f(-1.0, 3.0);
        glEnd();
        glEndList();
        // GL_COMPILE: nothing drawn, current color untouched.
        glFinish();
        assert_eq!(px(&buf, 0, 0), [0, 0, 0, 0]);
        let mut col = [0f32; 4];
        glGetFloatv(GL_CURRENT_COLOR, col.as_mut_ptr());
        assert_eq!(col, [1.0; 4]);
        // A list calling a list, and glCallLists with a base.
        glNewList(l + 1, GL_COMPILE_AND_EXECUTE);
        glClearColor(0.0, 0.0, 1.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glEndList();
        glFinish();
        assert_eq!(px(&buf, 0, 0), [0, 0, 255, 255]);
        glClearColor(0.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glListBase(l);
        let offsets: [u8; 2] = [1, 0];
        glCallLists(2, GL_UNSIGNED_BYTE, offsets.as_ptr() as *const c_void);
        glFinish();
        assert_eq!(px(&buf, 0, 0), [0, 255, 0, 255]);
        // Vertex arrays are dereferenced at compile time (GL 2.1 §5.4):
        // changing the client memory afterwards does not change the list.
        let mut verts: [f32; 6] = [-1.0, -1.0, 3.0, -1.0, -1.0, 3.0];
        let mut colors: [f32; 9] = [1.0, 0.0, 1.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0];
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glVertexPointer(2, GL_FLOAT, 0, verts.as_ptr() as *const c_void);
        glColorPointer(3, GL_FLOAT, 0, colors.as_ptr() as *const c_void);
        glNewList(l + 1, GL_COMPILE);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDrawArrays(GL_LESS, 0, 3); // raises GL_INVALID_ENUM when run
        glEndList();
        assert_eq!(glGetError(), GL_NO_ERROR);
        verts = [0.0; 6];
        colors = [0.0; 9];
        std::hint::black_box((&verts, &colors));
        glDisableClientState(GL_VERTEX_ARRAY);
        glDisableClientState(GL_COLOR_ARRAY);
        glCallList(l + 1);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glFinish();
        assert_eq!(px(&buf, 0, 0), [255, 0, 255, 255]);
        // Errors: nested glNewList, glEndList outside.
        glNewList(l, GL_COMPILE);
        glNewList(l + 1, GL_COMPILE);
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        glEndList();
        glEndList();
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        glDeleteLists(l, 2);
        assert_eq!(glIsList(l), 0);
        glCallList(l); // deleted: no-op
        assert_eq!(glGetError(), GL_NO_ERROR);
        OSMesaDestroyContext(ctx);
    }
}
