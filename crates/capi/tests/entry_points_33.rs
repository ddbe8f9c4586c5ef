//! The GL 3.0–3.3 entry points that complete libOSMesa.so's 3.3 set,
//! driven as a C program would on a 3.3 core context: sampler objects,
//! glClampColor, the layer and layered framebuffer attachments, and
//! dual-source blending; and their lookup by name.

use gl::enums::*;
use std::ffi::{c_void, CString};
use std::ptr::null_mut;
use OSMesa::*;

mod common;

const NAMES: &[&str] = &[
    "glGenSamplers",
    "glDeleteSamplers",
    "glIsSampler",
    "glBindSampler",
    "glSamplerParameteri",
    "glSamplerParameterf",
    "glSamplerParameteriv",
    "glSamplerParameterfv",
    "glSamplerParameterIiv",
    "glSamplerParameterIuiv",
    "glGetSamplerParameteriv",
    "glGetSamplerParameterfv",
    "glGetSamplerParameterIiv",
    "glGetSamplerParameterIuiv",
    "glClampColor",
    "glFramebufferTexture3D",
    "glFramebufferTextureLayer",
    "glFramebufferTexture",
    "glBindFragDataLocationIndexed",
    "glGetFragDataIndex",
];

#[test]
fn entry_points_are_exported_by_name() {
    common::assert_exported(NAMES);
}

/// Links `vs` and `fs`, makes the program current and sets up a
/// full-window quad in a vertex array object (attribute `pos`).
unsafe fn program_and_quad(vs: &str, fs: &str) -> u32 {
    let prog = common::program(vs, fs);
    common::quad_vertex_array(prog, "pos");
    prog
}

const VS: &str = "#version 330 core\n\
    in vec2 pos;\n\
    void main() { gl_Position = vec4(pos, 0.0, 1.0); }";

#[test]
fn a_bound_sampler_replaces_the_textures_filter() {
    common::with_context(8, 8, Some(OSMESA_CORE_PROFILE), |_| unsafe {
        // 2×1 texture, red then green, LINEAR on the texture.
        let texels: [u8; 8] = [255, 0, 0, 255, 0, 255, 0, 255];
        let mut t = 0;
        glGenTextures(1, &mut t);
        glBindTexture(GL_TEXTURE_2D, t);
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA8 as i32,
            2,
            1,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            texels.as_ptr() as *const c_void,
        );
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
        let fs = "#version 330 core\n\
            uniform sampler2D s;\n\
            out vec4 c;\n\
            void main() { c = texture(s, vec2(0.4, 0.5)); }";
        program_and_quad(VS, fs);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        let linear = common::pixel_at(4, 4);
        assert!(linear[0] > 100 && linear[1] > 30, "{linear:?}");

        let mut s = [0u32; 2];
        glGenSamplers(2, s.as_mut_ptr());
        assert_eq!(glIsSampler(s[0]), OSMesa::GL_TRUE);
        assert_eq!(glIsSampler(0), OSMesa::GL_FALSE);
        glSamplerParameteri(s[0], GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
        let nearest = [GL_NEAREST as i32];
        glSamplerParameteriv(s[0], GL_TEXTURE_MAG_FILTER, nearest.as_ptr());
        glBindSampler(0, s[0]);
        assert_eq!(glGetError(), GL_NO_ERROR);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        assert_eq!(common::pixel_at(4, 4), [255, 0, 0, 255]);
        let mut v = [0i32; 4];
        glGetIntegerv(GL_SAMPLER_BINDING, v.as_mut_ptr());
        assert_eq!(v[0], s[0] as i32);
        // The texture's parameter is still LINEAR.
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, v.as_mut_ptr());
        assert_eq!(v[0], GL_LINEAR as i32);

        // The parameter forms and queries.
        glSamplerParameterf(s[1], GL_TEXTURE_MIN_LOD, 2.6);
        let mut f = [0f32; 4];
        glGetSamplerParameterfv(s[1], GL_TEXTURE_MIN_LOD, f.as_mut_ptr());
        assert_eq!(f[0], 2.6);
        glGetSamplerParameteriv(s[1], GL_TEXTURE_MIN_LOD, v.as_mut_ptr());
        assert_eq!(v[0], 3);
        let border = [0.0f32, 1.0, 0.5, 1.0];
        glSamplerParameterfv(s[1], GL_TEXTURE_BORDER_COLOR, border.as_ptr());
        glGetSamplerParameterfv(s[1], GL_TEXTURE_BORDER_COLOR, f.as_mut_ptr());
        assert_eq!(f, border);
        glGetSamplerParameteriv(s[1], GL_TEXTURE_BORDER_COLOR, v.as_mut_ptr());
        // Normalized: 1.0 is the largest integer (glGetIntegerv's mapping).
        assert_eq!((v[1], v[3]), (i32::MAX, i32::MAX));
        let ints = [0i32, 1, 1, 1];
        glSamplerParameterIiv(s[1], GL_TEXTURE_BORDER_COLOR, ints.as_ptr());
        glGetSamplerParameterIiv(s[1], GL_TEXTURE_BORDER_COLOR, v.as_mut_ptr());
        assert_eq!(v, ints);
        let wrap = [GL_CLAMP_TO_EDGE];
        glSamplerParameterIuiv(s[1], GL_TEXTURE_WRAP_T, wrap.as_ptr());
        let mut u = [0u32; 4];
        glGetSamplerParameterIuiv(s[1], GL_TEXTURE_WRAP_T, u.as_mut_ptr());
        assert_eq!(u[0], GL_CLAMP_TO_EDGE);
        assert_eq!(glGetError(), GL_NO_ERROR);

        // Errors.
        glBindSampler(0, 999);
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        glBindSampler(1000, s[0]);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glSamplerParameteri(s[0], GL_TEXTURE_BASE_LEVEL, 1);
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        glDeleteSamplers(-1, s.as_ptr());
        assert_eq!(glGetError(), GL_INVALID_VALUE);

        // Deleting the bound sampler unbinds it: LINEAR again.
        glDeleteSamplers(2, s.as_ptr());
        assert_eq!(glIsSampler(s[0]), OSMesa::GL_FALSE);
        glGetIntegerv(GL_SAMPLER_BINDING, v.as_mut_ptr());
        assert_eq!(v[0], 0);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        assert_eq!(common::pixel_at(4, 4), linear);
    });
}

#[test]
fn clamp_color_and_layer_attachments() {
    common::with_context(8, 8, Some(OSMESA_CORE_PROFILE), |_| unsafe {
        let mut v = [0i32; 4];
        glGetIntegerv(GL_CLAMP_READ_COLOR, v.as_mut_ptr());
        assert_eq!(v[0], GL_FIXED_ONLY as i32);
        // A core context has no fragment clamping target.
        glClampColor(GL_CLAMP_FRAGMENT_COLOR, gl::enums::GL_TRUE);
        assert_eq!(glGetError(), GL_INVALID_ENUM);

        // Layer 1 of a 2×2×2 RGBA32F array texture as the colour buffer.
        let mut t = 0;
        glGenTextures(1, &mut t);
        glBindTexture(GL_TEXTURE_2D_ARRAY, t);
        glTexImage3D(
            GL_TEXTURE_2D_ARRAY,
            0,
            GL_RGBA32F as i32,
            2,
            2,
            2,
            0,
            GL_RGBA,
            GL_FLOAT,
            std::ptr::null(),
        );
        let mut fb = 0;
        glGenFramebuffers(1, &mut fb);
        glBindFramebuffer(GL_FRAMEBUFFER, fb);
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t, 0, 1);
        assert_eq!(
            glCheckFramebufferStatus(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_COMPLETE
        );
        glGetFramebufferAttachmentParameteriv(
            GL_FRAMEBUFFER,
            GL_COLOR_ATTACHMENT0,
            GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER,
            v.as_mut_ptr(),
        );
        assert_eq!(v[0], 1);
        // Out-of-range colours through a float buffer: kept, and read
        // clamped only when CLAMP_READ_COLOR says so.
        let fs = "#version 330 core\n\
            out vec4 c;\n\
            void main() { c = vec4(2.0, -1.0, 0.5, 1.0); }";
        program_and_quad(VS, fs);
        glViewport(0, 0, 2, 2);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        let mut px = [0f32; 4];
        glReadPixels(
            0,
            0,
            1,
            1,
            GL_RGBA,
            GL_FLOAT,
            px.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(px, [2.0, -1.0, 0.5, 1.0]);
        glClampColor(GL_CLAMP_READ_COLOR, gl::enums::GL_TRUE);
        glReadPixels(
            0,
            0,
            1,
            1,
            GL_RGBA,
            GL_FLOAT,
            px.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(px, [1.0, 0.0, 0.5, 1.0]);
        // Only layer 1 was drawn.
        let mut all = [0f32; 2 * 2 * 2 * 4];
        glGetTexImage(
            GL_TEXTURE_2D_ARRAY,
            0,
            GL_RGBA,
            GL_FLOAT,
            all.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(all[..4], [0.0; 4]);
        assert_eq!(all[16..20], [2.0, -1.0, 0.5, 1.0]);

        // glFramebufferTexture: a layered attachment.
        glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t, 0);
        glGetFramebufferAttachmentParameteriv(
            GL_FRAMEBUFFER,
            GL_COLOR_ATTACHMENT0,
            GL_FRAMEBUFFER_ATTACHMENT_LAYERED,
            v.as_mut_ptr(),
        );
        assert_eq!(v[0], 1);
        // glFramebufferTexture3D on a 3D texture's slice; a 2D array is
        // refused.
        glFramebufferTexture3D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_3D, t, 0, 0);
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        let mut t3 = 0;
        glGenTextures(1, &mut t3);
        glBindTexture(GL_TEXTURE_3D, t3);
        glTexImage3D(
            GL_TEXTURE_3D,
            0,
            GL_RGBA8 as i32,
            2,
            2,
            3,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            std::ptr::null(),
        );
        glFramebufferTexture3D(
            GL_FRAMEBUFFER,
            GL_COLOR_ATTACHMENT0,
            GL_TEXTURE_3D,
            t3,
            0,
            2,
        );
        assert_eq!(glGetError(), GL_NO_ERROR);
        assert_eq!(
            glCheckFramebufferStatus(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_COMPLETE
        );
        glClearColor(0.0, 1.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        let mut bytes = [0u8; 2 * 2 * 3 * 4];
        glGetTexImage(
            GL_TEXTURE_3D,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            bytes.as_mut_ptr() as *mut c_void,
        );
        assert_eq!(bytes[..4], [0, 0, 0, 0]);
        assert_eq!(bytes[32..36], [0, 255, 0, 255]);
        assert_eq!(glGetError(), GL_NO_ERROR);
    });
}

#[test]
fn dual_source_blending_through_the_c_abi() {
    common::with_context(8, 8, Some(OSMESA_CORE_PROFILE), |_| unsafe {
        let mut v = [0i32; 4];
        glGetIntegerv(GL_MAX_DUAL_SOURCE_DRAW_BUFFERS, v.as_mut_ptr());
        assert_eq!(v[0], 1);
        let fs = "#version 330 core\n\
            out vec4 a;\n\
            out vec4 b;\n\
            void main() { a = vec4(1.0, 0.0, 0.0, 1.0); b = vec4(0.0, 1.0, 0.0, 1.0); }";
        let prog = common::attached(&[(GL_VERTEX_SHADER, VS), (GL_FRAGMENT_SHADER, fs)]);
        let (a, b) = (CString::new("a").unwrap(), CString::new("b").unwrap());
        glBindFragDataLocationIndexed(prog, 0, 0, a.as_ptr());
        glBindFragDataLocationIndexed(prog, 0, 1, b.as_ptr());
        glBindFragDataLocationIndexed(prog, 1, 1, b.as_ptr());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glLinkProgram(prog);
        assert_eq!(glGetFragDataIndex(prog, b.as_ptr()), 1);
        assert_eq!(glGetFragDataIndex(prog, a.as_ptr()), 0);
        assert_eq!(glGetFragDataLocation(prog, b.as_ptr()), 0);
        // Draw with the quad set up by the helper's program, then switch.
        program_and_quad(VS, fs);
        glUseProgram(prog);
        glClearColor(0.0, 0.0, 1.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glEnable(GL_BLEND);
        // a + dst · b: red plus the blue background's green (none).
        glBlendFunc(GL_ONE, GL_SRC1_COLOR);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        assert_eq!(common::pixel_at(4, 4), [255, 0, 0, 255]);
        // a · (1 - b) + dst · b: red from a, the background's green kept
        // through b, its blue dropped.
        glClearColor(0.0, 1.0, 1.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glBlendFunc(GL_ONE_MINUS_SRC1_COLOR, GL_SRC1_COLOR);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        assert_eq!(common::pixel_at(4, 4), [255, 255, 0, 255]);
        assert_eq!(glGetError(), GL_NO_ERROR);
    });
}

/// Hostile arguments to every new entry point (bad enums, stale and
/// unknown names, negative and huge values, null pointers) on a 3.3
/// compatibility context: each records an error or succeeds, none
/// panics (no panic caught at the C boundary), and drawing still works
/// afterwards.
#[test]
fn hostile_arguments_never_crash() {
    common::with_context(8, 8, Some(OSMESA_COMPAT_PROFILE), |_| unsafe {
        let ints = [-1, 0, 1, 2, 3, 7, 1000, i32::MAX, i32::MIN];
        let enums = [
            0,
            0xdead,
            GL_TEXTURE_2D,
            GL_TEXTURE_3D,
            GL_TEXTURE_2D_ARRAY,
            GL_TEXTURE_MIN_FILTER,
            GL_TEXTURE_BORDER_COLOR,
            GL_TEXTURE_WRAP_R,
            GL_TEXTURE_COMPARE_FUNC,
            GL_FRAMEBUFFER,
            GL_READ_FRAMEBUFFER,
            GL_COLOR_ATTACHMENT0,
            GL_DEPTH_STENCIL_ATTACHMENT,
            GL_CLAMP_READ_COLOR,
            GL_CLAMP_FRAGMENT_COLOR,
            GL_FIXED_ONLY,
            GL_NEAREST,
            GL_REPEAT,
        ];
        let mut names = vec![0u32, 1, 2, 12345];
        let mut s = [0u32; 3];
        glGenSamplers(3, s.as_mut_ptr());
        names.extend(s);
        let mut t = [0u32; 3];
        glGenTextures(3, t.as_mut_ptr());
        glBindTexture(GL_TEXTURE_3D, t[0]);
        glTexImage3D(
            GL_TEXTURE_3D,
            0,
            GL_RGBA8 as i32,
            2,
            2,
            2,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            std::ptr::null(),
        );
        glBindTexture(GL_TEXTURE_2D_ARRAY, t[1]);
        glTexImage3D(
            GL_TEXTURE_2D_ARRAY,
            0,
            GL_RGBA8 as i32,
            2,
            2,
            2,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            std::ptr::null(),
        );
        names.extend(t);
        let mut fb = 0;
        glGenFramebuffers(1, &mut fb);
        let name = CString::new("c").unwrap();
        let prog = glCreateProgram();
        let mut out = [0u8; 64];
        let op = out.as_mut_ptr();
        let mut x: u64 = 0x5eed;
        let mut next = || {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (x >> 33) as usize
        };
        for step in 0..20_000 {
            let (e, e2) = (enums[next() % enums.len()], enums[next() % enums.len()]);
            let n = names[next() % names.len()];
            let (a, b) = (ints[next() % ints.len()], ints[next() % ints.len()]);
            if step % 500 == 0 {
                glBindFramebuffer(GL_FRAMEBUFFER, if next() % 2 == 0 { fb } else { 0 });
            }
            match next() % 16 {
                0 => glBindSampler(a as u32, n),
                1 => glSamplerParameteri(n, e, e2 as i32),
                2 => glSamplerParameterf(n, e, f32::NAN),
                3 => glSamplerParameterfv(
                    n,
                    e,
                    if a < 0 {
                        std::ptr::null()
                    } else {
                        op as *const f32
                    },
                ),
                4 => glSamplerParameterIiv(n, e, op as *const i32),
                5 => glSamplerParameterIuiv(n, e, op as *const u32),
                6 => glGetSamplerParameteriv(n, e, op as *mut i32),
                7 => glGetSamplerParameterfv(n, e, if b < 0 { null_mut() } else { op as *mut f32 }),
                8 => glGetSamplerParameterIiv(n, e, op as *mut i32),
                9 => glGetSamplerParameterIuiv(n, e, op as *mut u32),
                10 => glDeleteSamplers(b.clamp(-1, 2), [n, n].as_ptr()),
                11 => glClampColor(e, e2),
                12 => glFramebufferTexture3D(e, e2, enums[next() % enums.len()], n, a, b),
                13 => glFramebufferTextureLayer(e, e2, n, a, b),
                14 => glFramebufferTexture(e, e2, n, a),
                _ => {
                    glBindFragDataLocationIndexed(prog, a as u32, b as u32, name.as_ptr());
                    glGetFragDataIndex(
                        n,
                        if a < 0 {
                            std::ptr::null()
                        } else {
                            name.as_ptr()
                        },
                    );
                }
            }
            // A draw now and then with whatever was bound.
            if step % 1000 == 0 {
                glBegin(GL_TRIANGLES);
                glVertex2f(-1.0, -1.0);
                glVertex2f(1.0, -1.0);
                glVertex2f(0.0, 1.0);
                glEnd();
            }
        }
        while glGetError() != GL_NO_ERROR {}
        assert_eq!(OSMesa::context::caught_panics(), 0);
        // The context still draws.
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glUseProgram(0);
        for u in 0..16 {
            glBindSampler(u, 0);
        }
        glDisable(GL_TEXTURE_2D);
        glClearColor(0.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glColor4f(0.0, 1.0, 0.0, 1.0);
        glBegin(GL_QUADS);
        glVertex2f(-1.0, -1.0);
        glVertex2f(1.0, -1.0);
        glVertex2f(1.0, 1.0);
        glVertex2f(-1.0, 1.0);
        glEnd();
        assert_eq!(common::pixel_at(4, 4), [0, 255, 0, 255]);
        assert_eq!(glGetError(), GL_NO_ERROR);
    });
}
