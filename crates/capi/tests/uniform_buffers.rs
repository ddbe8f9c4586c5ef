//! The GL 3.0–3.3 buffer-object and uniform-block entry points, driven as a
//! C program would: mapping through the returned pointer, copies, indexed
//! bindings, the 64-bit queries, and a uniform block read at draw time.

use gl::enums::*;
use std::ffi::{c_void, CStr};
use std::ptr::{null, null_mut};
use OSMesa::*;

mod common;

const W: i32 = 8;
const H: i32 = 8;

unsafe fn buffer_bytes(target: u32, n: usize) -> Vec<u8> {
    let mut v = vec![0u8; n];
    glGetBufferSubData(target, 0, n as isize, v.as_mut_ptr() as *mut c_void);
    v
}

#[test]
fn map_range_flush_copy_and_queries() {
    common::with_context(W, H, None, |_| unsafe {
        let mut b = [0u32; 2];
        glGenBuffers(2, b.as_mut_ptr());
        glBindBuffer(GL_COPY_READ_BUFFER, b[0]);
        let init: Vec<u8> = (0..16).collect();
        glBufferData(
            GL_COPY_READ_BUFFER,
            16,
            init.as_ptr() as *const c_void,
            GL_STATIC_DRAW,
        );
        // Write through the pointer: the whole range lands at unmap.
        let p = glMapBufferRange(
            GL_COPY_READ_BUFFER,
            4,
            4,
            GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT,
        ) as *mut u8;
        assert!(!p.is_null());
        let mut q = null_mut();
        glGetBufferPointerv(GL_COPY_READ_BUFFER, GL_BUFFER_MAP_POINTER, &mut q);
        assert_eq!(q as *mut u8, p);
        let mut v = 0i64;
        glGetBufferParameteri64v(GL_COPY_READ_BUFFER, GL_BUFFER_MAP_OFFSET, &mut v);
        assert_eq!(v, 4);
        let mut iv = 0;
        glGetBufferParameteriv(GL_COPY_READ_BUFFER, GL_BUFFER_MAP_LENGTH, &mut iv);
        assert_eq!(iv, 4);
        glGetBufferParameteriv(GL_COPY_READ_BUFFER, GL_BUFFER_ACCESS_FLAGS, &mut iv);
        assert_eq!(iv as u32, GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT);
        for i in 0..4 {
            *p.add(i) = 100 + i as u8;
        }
        assert_eq!(glUnmapBuffer(GL_COPY_READ_BUFFER), 1);
        assert_eq!(glUnmapBuffer(GL_COPY_READ_BUFFER), 0);
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        assert_eq!(
            &buffer_bytes(GL_COPY_READ_BUFFER, 16)[3..9],
            &[3, 100, 101, 102, 103, 8]
        );
        // Explicit flushes: only the flushed bytes land.
        let p = glMapBufferRange(
            GL_COPY_READ_BUFFER,
            8,
            8,
            GL_MAP_WRITE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT,
        ) as *mut u8;
        assert!(!p.is_null());
        std::ptr::write_bytes(p, 0xAA, 8);
        glFlushMappedBufferRange(GL_COPY_READ_BUFFER, 2, 1);
        glFlushMappedBufferRange(GL_COPY_READ_BUFFER, 6, 4);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        glUnmapBuffer(GL_COPY_READ_BUFFER);
        assert_eq!(
            &buffer_bytes(GL_COPY_READ_BUFFER, 16)[9..12],
            &[9, 0xAA, 11]
        );
        // Errors return null.
        assert!(glMapBufferRange(
            GL_COPY_READ_BUFFER,
            0,
            4,
            GL_MAP_READ_BIT | GL_MAP_INVALIDATE_BUFFER_BIT
        )
        .is_null());
        assert_eq!(glGetError(), GL_INVALID_OPERATION);
        assert!(glMapBufferRange(GL_COPY_READ_BUFFER, 8, 9, GL_MAP_READ_BIT).is_null());
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        // Read mapping sees the store.
        let p = glMapBufferRange(GL_COPY_READ_BUFFER, 0, 2, GL_MAP_READ_BIT) as *const u8;
        assert_eq!((*p, *p.add(1)), (0, 1));
        glUnmapBuffer(GL_COPY_READ_BUFFER);

        // glCopyBufferSubData between the copy targets.
        glBindBuffer(GL_COPY_WRITE_BUFFER, b[1]);
        glBufferData(GL_COPY_WRITE_BUFFER, 4, null(), GL_STATIC_DRAW);
        glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 4, 0, 4);
        assert_eq!(
            buffer_bytes(GL_COPY_WRITE_BUFFER, 4),
            vec![100, 101, 102, 103]
        );
        glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_READ_BUFFER, 0, 1, 2);
        assert_eq!(glGetError(), GL_INVALID_VALUE);

        // Indexed bindings and their queries.
        glBindBufferRange(GL_UNIFORM_BUFFER, 7, b[0], 0, 16);
        glBindBufferBase(GL_UNIFORM_BUFFER, 8, b[1]);
        let mut x = 0;
        glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 7, &mut x);
        assert_eq!(x as u32, b[0]);
        glGetIntegeri_v(GL_UNIFORM_BUFFER_SIZE, 7, &mut x);
        assert_eq!(x, 16);
        let mut y = 0i64;
        glGetInteger64i_v(GL_UNIFORM_BUFFER_BINDING, 8, &mut y);
        assert_eq!(y as u32, b[1]);
        glGetIntegerv(GL_UNIFORM_BUFFER_BINDING, &mut x);
        assert_eq!(x as u32, b[1]);
        glGetInteger64v(GL_MAX_UNIFORM_BLOCK_SIZE, &mut y);
        assert_eq!(y, 65536);
        glBindBufferRange(GL_UNIFORM_BUFFER, 0, b[0], 4, 4);
        assert_eq!(glGetError(), GL_INVALID_VALUE);
        assert_eq!(glGetError(), GL_NO_ERROR);

        for name in [
            c"glMapBufferRange",
            c"glFlushMappedBufferRange",
            c"glCopyBufferSubData",
            c"glBindBufferBase",
            c"glBindBufferRange",
            c"glGetIntegeri_v",
            c"glGetInteger64i_v",
            c"glGetInteger64v",
            c"glGetBooleani_v",
            c"glGetBufferParameteri64v",
            c"glGetUniformBlockIndex",
            c"glGetActiveUniformBlockiv",
            c"glGetActiveUniformBlockName",
            c"glUniformBlockBinding",
            c"glGetUniformIndices",
            c"glGetActiveUniformsiv",
            c"glGetActiveUniformName",
        ] {
            assert!(OSMesaGetProcAddress(name.as_ptr()).is_some(), "{name:?}");
        }
    });
}

#[test]
fn uniform_block_draws_from_its_buffer() {
    common::with_context(W, H, None, |buf| unsafe {
        let prog = common::program(
            "#version 150\nin vec4 pos;\nvoid main() { gl_Position = pos; }\n",
            "#version 150\nuniform Tint { float pad; vec4 colour; } tint;\nout vec4 o;\n\
             void main() { o = tint.colour; }\n",
        );
        let idx = glGetUniformBlockIndex(prog, c"Tint".as_ptr());
        assert_eq!(idx, 0);
        assert_eq!(glGetUniformBlockIndex(prog, c"tint".as_ptr()), u32::MAX);
        let mut size = 0;
        glGetActiveUniformBlockiv(prog, idx, GL_UNIFORM_BLOCK_DATA_SIZE, &mut size);
        assert_eq!(size, 32);
        let mut name = [0 as GLchar; 16];
        let mut len = 0;
        glGetActiveUniformBlockName(prog, idx, 16, &mut len, name.as_mut_ptr());
        assert_eq!(CStr::from_ptr(name.as_ptr()).to_str().unwrap(), "Tint");
        assert_eq!(len, 4);
        let names = [
            c"Tint.colour".as_ptr(),
            c"Tint.pad".as_ptr(),
            c"nope".as_ptr(),
        ];
        let mut indices = [0u32; 3];
        glGetUniformIndices(prog, 3, names.as_ptr(), indices.as_mut_ptr());
        assert_eq!(indices[2], u32::MAX);
        let mut offsets = [0; 2];
        glGetActiveUniformsiv(
            prog,
            2,
            indices.as_ptr(),
            GL_UNIFORM_OFFSET,
            offsets.as_mut_ptr(),
        );
        assert_eq!(offsets, [16, 0]);
        glGetActiveUniformName(prog, indices[0], 16, &mut len, name.as_mut_ptr());
        assert_eq!(
            CStr::from_ptr(name.as_ptr()).to_str().unwrap(),
            "Tint.colour"
        );
        glUniformBlockBinding(prog, idx, 3);
        assert_eq!(glGetError(), GL_NO_ERROR);

        let mut ubo = 0;
        glGenBuffers(1, &mut ubo);
        glBindBuffer(GL_UNIFORM_BUFFER, ubo);
        let data: [f32; 8] = [9.0, 9.0, 9.0, 9.0, 1.0, 0.0, 0.0, 1.0];
        glBufferData(
            GL_UNIFORM_BUFFER,
            32,
            data.as_ptr() as *const c_void,
            GL_DYNAMIC_DRAW,
        );
        glBindBufferBase(GL_UNIFORM_BUFFER, 3, ubo);
        let quad: [f32; 8] = [-1.0, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0];
        let pos = glGetAttribLocation(prog, c"pos".as_ptr()) as u32;
        glVertexAttribPointer(pos, 2, GL_FLOAT, 0, 0, quad.as_ptr() as *const c_void);
        glEnableVertexAttribArray(pos);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glFinish();
        assert_eq!(&buf[..4], &[255, 0, 0, 255]);
        // Through a mapping this time: green.
        let p = glMapBufferRange(GL_UNIFORM_BUFFER, 16, 16, GL_MAP_WRITE_BIT) as *mut f32;
        for (i, v) in [0.0f32, 1.0, 0.0, 1.0].into_iter().enumerate() {
            *p.add(i) = v;
        }
        glUnmapBuffer(GL_UNIFORM_BUFFER);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glFinish();
        assert_eq!(&buf[..4], &[0, 255, 0, 255]);
        assert_eq!(glGetError(), GL_NO_ERROR);
    });
}

/// xorshift64*: a fixed sequence of arguments.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn pick<T: Copy>(&mut self, v: &[T]) -> T {
        v[self.next() as usize % v.len()]
    }
    fn int(&mut self) -> isize {
        self.pick(&[-17, -1, 0, 1, 3, 4, 15, 16, 32, 48, 64, 100, 256, 4096])
    }
}

#[test]
fn hostile_buffer_and_block_calls_never_crash() {
    common::with_context(W, H, None, |buf| unsafe {
        let prog = common::program(
            "#version 150\nuniform V { mat4 m; float s[2]; };\nin vec4 pos;\n\
             void main() { gl_Position = m * pos * s[1]; }\n",
            "#version 150\nuniform F { vec4 c; layout(row_major) mat3 r; } f[2];\nout vec4 o;\n\
             void main() { o = f[0].c + vec4(f[1].r[2], 0.0); }\n",
        );
        let quad: [f32; 8] = [-1.0, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0];
        glVertexAttribPointer(0, 2, GL_FLOAT, 0, 0, quad.as_ptr() as *const c_void);
        glEnableVertexAttribArray(0);
        let targets = [
            GL_UNIFORM_BUFFER,
            GL_COPY_READ_BUFFER,
            GL_COPY_WRITE_BUFFER,
            GL_TEXTURE_BUFFER,
            GL_TRANSFORM_FEEDBACK_BUFFER,
            GL_ARRAY_BUFFER,
            GL_LESS,
        ];
        let pnames = [
            GL_UNIFORM_BLOCK_BINDING,
            GL_UNIFORM_BLOCK_DATA_SIZE,
            GL_UNIFORM_BLOCK_ACTIVE_UNIFORM_INDICES,
            GL_UNIFORM_OFFSET,
            GL_UNIFORM_ARRAY_STRIDE,
            GL_UNIFORM_BUFFER_SIZE,
            GL_UNIFORM_BUFFER_START,
            GL_BUFFER_MAP_LENGTH,
            GL_LESS,
        ];
        let data: Vec<u8> = (0..4096u32).map(|i| (i * 37 % 251) as u8).collect();
        let mut out = vec![0i32; 4096];
        let mut names = vec![0u32, 1, 2, 9999];
        let mut rng = Rng(0x05ee_d0b0);
        for _ in 0..40_000 {
            let t = rng.pick(&targets);
            let t2 = rng.pick(&targets);
            let n = rng.pick(&names);
            let (a, b) = (rng.int(), rng.int());
            let bits = (rng.next() % 0x80) as u32;
            let pname = rng.pick(&pnames);
            match rng.next() % 16 {
                0 => {
                    let mut x = 0;
                    glGenBuffers(1, &mut x);
                    names.push(x);
                }
                1 => glBindBuffer(t, n),
                2 => glBufferData(
                    t,
                    b.min(4096),
                    data.as_ptr() as *const c_void,
                    GL_DYNAMIC_DRAW,
                ),
                3 => {
                    let p = glMapBufferRange(t, a, b, bits) as *mut u8;
                    if !p.is_null() {
                        let mut len = 0;
                        glGetBufferParameteriv(t, GL_BUFFER_MAP_LENGTH, &mut len);
                        std::ptr::write_bytes(p, 0x3c, len.max(0) as usize);
                    }
                }
                4 => glFlushMappedBufferRange(t, a, b),
                5 => {
                    glUnmapBuffer(t);
                }
                6 => glCopyBufferSubData(t, t2, a, b, rng.int()),
                7 => glBindBufferRange(t, (rng.next() % 40) as u32, n, a, b),
                8 => glBindBufferBase(t, (rng.next() % 40) as u32, n),
                9 => glGetIntegeri_v(pname, (rng.next() % 40) as u32, out.as_mut_ptr()),
                10 => {
                    glUniformBlockBinding(prog, (rng.next() % 6) as u32, (rng.next() % 40) as u32)
                }
                11 => glGetActiveUniformBlockiv(
                    prog,
                    (rng.next() % 6) as u32,
                    pname,
                    out.as_mut_ptr(),
                ),
                12 => {
                    let idx: Vec<u32> = (0..4).map(|_| (rng.next() % 12) as u32).collect();
                    glGetActiveUniformsiv(
                        prog,
                        rng.pick(&[0, 1, 4, -1]),
                        idx.as_ptr(),
                        pname,
                        out.as_mut_ptr(),
                    );
                }
                13 => glDrawArrays(GL_TRIANGLE_STRIP, 0, 4),
                14 => glDeleteBuffers(1, &n),
                _ => {
                    glGetBufferParameteri64v(t, pname, out.as_mut_ptr() as *mut i64);
                }
            }
        }
        while glGetError() != 0 {}
        glClearColor(0.0, 1.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glFinish();
        assert_eq!(glGetError(), GL_NO_ERROR);
        assert_eq!(&buf[0..4], &[0, 255, 0, 255]);
        assert_eq!(OSMesa::context::caught_panics(), 0);
    });
}
