//! A deterministic pseudo-random sequence of API calls with hostile
//! arguments (bad enums, negative sizes, stale names, nulls, calls inside
//! glBegin/glEnd): no crash, no panic caught at the C boundary, and the
//! context keeps working afterwards.

use gl::enums::*;
use std::ffi::c_void;
use std::ptr::{null, null_mut};
use OSMesa::*;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u32 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 33) as u32
    }
    fn pick<T: Copy>(&mut self, v: &[T]) -> T {
        v[self.next() as usize % v.len()]
    }
    fn int(&mut self) -> i32 {
        self.pick(&[-1, 0, 1, 2, 3, 4, 7, 16, 1000, -1000, i32::MAX, i32::MIN])
    }
    fn f(&mut self) -> f32 {
        self.pick(&[0.0, 1.0, -1.0, 0.5, 1e30, -1e30, f32::NAN, f32::INFINITY])
    }
}

const ENUMS: &[u32] = &[
    0,
    0xdead,
    GL_TRIANGLES,
    GL_POINTS,
    GL_LINES,
    GL_QUADS,
    GL_POLYGON,
    GL_FLOAT,
    GL_UNSIGNED_BYTE,
    GL_UNSIGNED_SHORT,
    GL_UNSIGNED_INT,
    GL_DOUBLE,
    GL_RGBA,
    GL_RGB,
    GL_DEPTH_COMPONENT,
    GL_TEXTURE_2D,
    GL_LIGHT0,
    GL_LIGHT7,
    GL_POSITION,
    GL_DIFFUSE,
    GL_SPOT_DIRECTION,
    GL_FRONT,
    GL_BACK,
    GL_FRONT_AND_BACK,
    GL_SHININESS,
    GL_DEPTH_TEST,
    GL_BLEND,
    GL_LIGHTING,
    GL_FOG,
    GL_FOG_COLOR,
    GL_VERTEX_SHADER,
    GL_FRAGMENT_SHADER,
    GL_COMPILE_STATUS,
    GL_LINK_STATUS,
    GL_INFO_LOG_LENGTH,
    GL_ARRAY_BUFFER,
    GL_ELEMENT_ARRAY_BUFFER,
    GL_PIXEL_PACK_BUFFER,
    GL_FRAMEBUFFER,
    GL_COLOR_ATTACHMENT0,
    GL_MODELVIEW,
    GL_PROJECTION,
    GL_TEXTURE,
    GL_VIEWPORT,
    GL_MODELVIEW_MATRIX,
    GL_VERTEX_ARRAY,
    GL_COLOR_ARRAY,
    GL_TEXTURE_COORD_ARRAY,
    GL_TEXTURE0,
    GL_PIXEL_UNPACK_BUFFER,
    GL_C4F_N3F_V3F,
    GL_T2F_V3F,
    GL_SELECT,
    GL_TEXTURE_WIDTH,
    GL_VERTEX_ATTRIB_ARRAY_SIZE,
    GL_TEXTURE7,
    GL_TEXTURE_MIN_FILTER,
    GL_NEAREST,
    GL_LINEAR,
    GL_SRC_ALPHA,
    GL_ONE,
    GL_LESS,
    GL_TRIANGLE_STRIP,
    GL_INT,
    GL_PRIMITIVE_RESTART,
    GL_VERTEX_ATTRIB_ARRAY_DIVISOR,
];

const VS: &[u8] = b"attribute vec4 p; uniform mat4 m; uniform vec4 u[3]; void main() { gl_Position = m * p + u[1]; }\0";
const FS: &[u8] = b"uniform vec4 col; void main() { gl_FragColor = col; }\0";

#[test]
fn hostile_call_sequences_never_crash() {
    unsafe {
        let ctx = OSMesaCreateContext(OSMESA_RGBA, null_mut());
        let mut buf = vec![0u8; 24 * 16 * 4];
        assert_eq!(
            OSMesaMakeCurrent(
                ctx,
                buf.as_mut_ptr() as *mut c_void,
                GL_UNSIGNED_BYTE,
                24,
                16
            ),
            1
        );
        let floats: Vec<f32> = (0..4096)
            .map(|i| ((i * 37) % 200) as f32 / 100.0 - 1.0)
            .collect();
        let fp = floats.as_ptr();
        let idx: Vec<u32> = (0..1024).map(|i| (i * 7) % 300).collect();
        let mut out = vec![0u8; 1 << 16];
        let op = out.as_mut_ptr();
        let mut names: Vec<u32> = vec![0, 1, 2, 9999];
        for step in 0..160_000u64 {
            if step % 20_000 == 0 {
                // A new seed, and out of any glBegin left open.
                glEnd();
            }
            let mut rng = Rng(0x5eed
                ^ (step / 20_000).wrapping_mul(0x9e37_79b9)
                ^ step.wrapping_mul(0x2545_f491));
            let e = rng.pick(ENUMS);
            let e2 = rng.pick(ENUMS);
            let n = names[rng.next() as usize % names.len()];
            let (a, b) = (rng.int(), rng.int().clamp(-4, 64));
            match rng.next() % 71 {
                0 => glBegin(e),
                1 => glEnd(),
                2 => glVertex3f(rng.f(), rng.f(), rng.f()),
                3 => glDrawArrays(e, a.clamp(-1, 200), b),
                4 => glDrawElements(e, b, e2, idx.as_ptr() as *const c_void),
                5 => glEnable(e),
                6 => glDisable(e),
                7 => glVertexAttribPointer(
                    n % 20,
                    a,
                    e,
                    0,
                    rng.pick(&[0, 4, 16, -1]),
                    fp as *const c_void,
                ),
                8 => glEnableVertexAttribArray(n % 20),
                9 => glVertexPointer(a, e, rng.pick(&[0, 8, -4]), fp as *const c_void),
                10 => glEnableClientState(e),
                11 => glColorPointer(
                    a,
                    e,
                    0,
                    if rng.pick(&[true, false]) {
                        null()
                    } else {
                        fp as *const c_void
                    },
                ),
                12 => {
                    let s = glCreateShader(e);
                    names.push(s);
                    let src = if e == GL_VERTEX_SHADER { VS } else { FS };
                    let p = src.as_ptr() as *const GLchar;
                    glShaderSource(s, rng.pick(&[1, 0, -1]), &p, null());
                    glCompileShader(s);
                }
                13 => {
                    let p = glCreateProgram();
                    names.push(p);
                    glAttachShader(p, n);
                }
                14 => glLinkProgram(n),
                15 => glUseProgram(n),
                16 => glUniform4fv(a, b, fp),
                17 => glUniformMatrix4fv(a, b, 0, fp),
                18 => glGetIntegerv(e, op as *mut GLint),
                19 => glGetFloatv(e, op as *mut GLfloat),
                20 => glLightfv(e, e2, fp),
                21 => glMaterialfv(e, e2, fp),
                22 => glMatrixMode(e),
                23 => glPushMatrix(),
                24 => glPopMatrix(),
                25 => glLoadMatrixf(if rng.pick(&[true, false, false]) {
                    null()
                } else {
                    fp
                }),
                26 => glReadPixels(a.clamp(-5, 30), 0, b, b, e, e2, op as *mut c_void),
                27 => glTexImage2D(
                    e,
                    a.clamp(-1, 3),
                    e2 as i32,
                    b.min(32),
                    b.min(32),
                    rng.pick(&[0, 1]),
                    GL_RGBA,
                    GL_FLOAT,
                    fp as *const c_void,
                ),
                28 => glBindTexture(e, n),
                29 => glBindBuffer(e, n),
                30 => glBufferData(
                    e,
                    rng.pick(&[-1, 0, 64, 4096]) as isize,
                    fp as *const c_void,
                    GL_STATIC_DRAW,
                ),
                31 => glGetShaderInfoLog(n, b, null_mut(), op as *mut GLchar),
                32 => glGetProgramiv(n, e, op as *mut GLint),
                33 => glDeleteShader(n),
                34 => glDeleteProgram(n),
                35 => glClear(rng.next()),
                36 => glViewport(a.clamp(-5, 5), 0, b, b),
                37 => glBindFramebuffer(e, n),
                38 => glTexCoordPointer(a, e, 0, fp as *const c_void),
                39 => {
                    let p = glMapBuffer(e, rng.pick(&[GL_READ_ONLY, GL_WRITE_ONLY, e2]));
                    if !p.is_null() {
                        let mut size = 0;
                        glGetBufferParameteriv(e, GL_BUFFER_SIZE, &mut size);
                        if size > 0 {
                            *(p as *mut u8) = 7;
                        }
                    }
                }
                40 => {
                    glUnmapBuffer(e);
                }
                41 => glGetTexImage(GL_TEXTURE_2D, a.clamp(-1, 3), e, e2, op as *mut c_void),
                42 => glCopyTexImage2D(e, a.clamp(-1, 2), e2, 0, 0, b, b, rng.pick(&[0, 1])),
                43 => glCopyTexSubImage2D(e, a.clamp(-1, 2), b, 1, 0, 0, b, 2),
                44 => glPushAttrib(rng.next()),
                45 => glPopAttrib(),
                46 => glPushClientAttrib(rng.next()),
                47 => glPopClientAttrib(),
                48 => glArrayElement(a.clamp(-1, 250)),
                49 => glGetVertexAttribiv(n % 20, e, op as *mut GLint),
                50 => glGetTexLevelParameteriv(e, a.clamp(-1, 3), e2, op as *mut GLint),
                51 => {
                    glRenderMode(e);
                }
                52 => glInterleavedArrays(e, rng.pick(&[0, 8, -1]), fp as *const c_void),
                53 => glBeginQuery(rng.pick(&[e, GL_SAMPLES_PASSED]), n),
                54 => glEndQuery(rng.pick(&[e, GL_SAMPLES_PASSED])),
                55 => glGetQueryObjectuiv(n, rng.pick(&[e, GL_QUERY_RESULT]), op as *mut GLuint),
                56 => glRasterPos4f(rng.f(), rng.f(), rng.f(), rng.f()),
                57 => glWindowPos3f(rng.f() * 8.0, rng.f() * 8.0, rng.f()),
                58 => glDrawPixels(
                    a.clamp(-1, 16),
                    b.clamp(-1, 16),
                    rng.pick(&[e, GL_RGBA, GL_DEPTH_COMPONENT, GL_STENCIL_INDEX]),
                    rng.pick(&[e2, GL_FLOAT, GL_UNSIGNED_BYTE]),
                    fp as *const c_void,
                ),
                59 => glBitmap(
                    a.clamp(-1, 16),
                    b.clamp(-1, 16),
                    rng.f(),
                    rng.f(),
                    rng.f(),
                    rng.f(),
                    fp as *const GLubyte,
                ),
                60 => glCopyPixels(a, b, a.clamp(-1, 30), b.clamp(-1, 30), e),
                61 => glPixelZoom(rng.f(), rng.f()),
                62 => {
                    let mut v = [0u32; 2];
                    glGenVertexArrays(rng.pick(&[-1, 0, 1, 2]), v.as_mut_ptr());
                    names.extend(v.iter().filter(|&&x| x != 0));
                }
                63 => glBindVertexArray(n),
                64 => glDeleteVertexArrays(1, &n),
                65 => glDrawArraysInstanced(e, a.clamp(-1, 200), b, rng.pick(&[-1, 0, 1, 3])),
                66 => glDrawElementsInstancedBaseVertex(
                    e,
                    b,
                    e2,
                    idx.as_ptr() as *const c_void,
                    rng.pick(&[-1, 0, 1, 3]),
                    a.clamp(-300, 300),
                ),
                67 => glVertexAttribIPointer(
                    n % 20,
                    a,
                    e,
                    rng.pick(&[0, 4, 16, -1]),
                    fp as *const c_void,
                ),
                68 => glVertexAttribDivisor(n % 20, rng.pick(&[0, 1, 2, u32::MAX])),
                69 => glPrimitiveRestartIndex(rng.pick(&[0, 7, 0xffff, u32::MAX])),
                _ => {
                    let _ = glGetError();
                }
            }
        }
        glEnd();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glUseProgram(0);
        while glGetError() != 0 {}
        // Still works.
        glDisable(GL_SCISSOR_TEST);
        glColorMask(1, 1, 1, 1);
        glClearColor(0.0, 1.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glFinish();
        assert_eq!(glGetError(), GL_NO_ERROR);
        assert_eq!(&buf[0..4], &[0, 255, 0, 255]);
        assert_eq!(OSMesa::context::caught_panics(), 0);
        OSMesaDestroyContext(ctx);
    }
}
