//! The GL 3.0-3.3 texture entry points, driven as a C program would:
//! buffer textures (glTexBuffer), four-valued swizzles through
//! glTexParameteriv, the integer parameter forms, and their lookup by
//! name.

use gl::enums::*;
use std::ffi::c_void;
use std::ptr::null_mut;
use OSMesa::*;

mod common;

const W: i32 = 4;
const H: i32 = 4;

const NAMES: &[&str] = &[
    "glTexBuffer",
    "glTexBufferARB",
    "glTexBufferEXT",
    "glTexParameterIiv",
    "glTexParameterIuiv",
    "glGetTexParameterIiv",
    "glGetTexParameterIuiv",
];

#[test]
fn every_new_entry_point_is_exported() {
    common::assert_exported(NAMES);
}

#[test]
fn buffer_textures_and_swizzles_through_the_c_abi() {
    unsafe {
        let mut buf = vec![0u8; (W * H * 4) as usize];
        let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, null_mut());
        assert!(!ctx.is_null());
        assert_eq!(
            OSMesaMakeCurrent(ctx, buf.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, W, H),
            OSMesa::GL_TRUE
        );
        // A buffer of RGBA8 texels: texel 1 is (0, 255, 0, 255).
        let texels: [u8; 8] = [255, 0, 0, 255, 0, 255, 0, 255];
        let b = common::buffer(GL_TEXTURE_BUFFER, &texels);
        let mut t = 0;
        glGenTextures(1, &mut t);
        glBindTexture(GL_TEXTURE_BUFFER, t);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA8, b);
        assert_eq!(glGetError(), GL_NO_ERROR);
        let vs = "#version 140\nin vec2 p;\nvoid main() { gl_Position = vec4(p, 0.0, 1.0); }";
        let fs = "#version 140\nuniform samplerBuffer s;\nout vec4 c;\n\
                  void main() { c = texelFetch(s, textureSize(s) - 1); }";
        let prog = common::program(vs, fs);
        let p = common::attrib_location(prog, "p");
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        let quad = common::QUAD.as_ptr() as *const c_void;
        glVertexAttribPointer(p, 2, GL_FLOAT, 0, 0, quad);
        glEnableVertexAttribArray(p);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glFinish();
        assert_eq!(buf[..4], [0, 255, 0, 255]);
        // Four swizzles in one glTexParameteriv, read back with the
        // integer query.
        let mut t2 = 0;
        glGenTextures(1, &mut t2);
        glBindTexture(GL_TEXTURE_2D, t2);
        let swizzle = [GL_ALPHA, GL_ZERO, GL_ONE, GL_RED].map(|x| x as GLint);
        glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, swizzle.as_ptr());
        assert_eq!(glGetError(), GL_NO_ERROR);
        let mut got = [0 as GLint; 4];
        glGetTexParameterIiv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, got.as_mut_ptr());
        assert_eq!(got, swizzle);
        let mut one = [0 as GLuint; 1];
        glGetTexParameterIuiv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_G, one.as_mut_ptr());
        assert_eq!(one[0], GL_ZERO);
        let bad = [GL_LESS as GLint];
        glTexParameterIiv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_B, bad.as_ptr());
        assert_eq!(glGetError(), GL_INVALID_ENUM);
        OSMesaDestroyContext(ctx);
    }
}
