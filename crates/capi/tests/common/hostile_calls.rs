//! One decoder of hostile GL call sequences through the C ABI, shared
//! by the capi test `fuzz_calls` (a fixed pseudo-random program) and the
//! cargo-fuzz target `gl_calls` (the fuzzer's bytes as the program), so
//! that the two exercise the same calls with the same argument tables.
//!
//! A program is a stream of choices ([`Choices`]): one choosing the entry
//! point, then one per argument choosing from tables of hostile values
//! (bad enums, negative and huge sizes, stale names, NaN and infinite
//! floats). Pointer arguments point into [`Buffers`], sized for the
//! largest transfer the clamped arguments allow (64x64 RGBA float pixels,
//! 32x32 float texels with a border, 1024 indices below 300 into 16-byte
//! vertices); a read or write outside them is a bug in an entry point's
//! size computation.
//!
//! The crate that includes this file (`#[path]`) imports the capi entry
//! points (`OSMesa::*` in the tests, `capi::*` in the fuzz target) and
//! `gl::enums::*` at its root; the module takes them from there.

use super::*;
use std::ffi::c_void;
use std::ptr::{null, null_mut};

pub const ENUMS: &[u32] = &[
    0,
    0xdead,
    GL_TRIANGLES,
    GL_POINTS,
    GL_LINES,
    GL_LINE_LOOP,
    GL_QUADS,
    GL_POLYGON,
    GL_TRIANGLE_STRIP,
    GL_TRIANGLE_FAN,
    GL_LINES_ADJACENCY,
    GL_FLOAT,
    GL_UNSIGNED_BYTE,
    GL_BYTE,
    GL_UNSIGNED_SHORT,
    GL_UNSIGNED_INT,
    GL_INT,
    GL_DOUBLE,
    GL_HALF_FLOAT,
    GL_UNSIGNED_INT_8_8_8_8_REV,
    GL_UNSIGNED_SHORT_5_6_5,
    GL_RGBA,
    GL_RGB,
    GL_RED,
    GL_RG,
    GL_BGRA,
    GL_LUMINANCE,
    GL_ALPHA,
    GL_RGBA8,
    GL_RGBA32F,
    GL_R8,
    GL_RGBA16I,
    GL_DEPTH_COMPONENT,
    GL_DEPTH_COMPONENT24,
    GL_DEPTH24_STENCIL8,
    GL_DEPTH_STENCIL,
    GL_STENCIL_INDEX,
    GL_STENCIL_INDEX8,
    GL_TEXTURE_1D,
    GL_TEXTURE_2D,
    GL_TEXTURE_3D,
    GL_TEXTURE_CUBE_MAP,
    GL_TEXTURE_CUBE_MAP_POSITIVE_X,
    GL_TEXTURE_RECTANGLE,
    GL_TEXTURE_2D_ARRAY,
    GL_LIGHT0,
    GL_LIGHT7,
    GL_POSITION,
    GL_DIFFUSE,
    GL_SPOT_DIRECTION,
    GL_FRONT,
    GL_BACK,
    GL_FRONT_AND_BACK,
    GL_NONE,
    GL_SHININESS,
    GL_DEPTH_TEST,
    GL_STENCIL_TEST,
    GL_SCISSOR_TEST,
    GL_CULL_FACE,
    GL_BLEND,
    GL_LIGHTING,
    GL_FOG,
    GL_FOG_COLOR,
    GL_POLYGON_OFFSET_FILL,
    GL_LINE_SMOOTH,
    GL_POINT_SPRITE,
    GL_VERTEX_PROGRAM_POINT_SIZE,
    GL_CLIP_PLANE0,
    GL_VERTEX_SHADER,
    GL_FRAGMENT_SHADER,
    GL_GEOMETRY_SHADER,
    GL_COMPILE_STATUS,
    GL_LINK_STATUS,
    GL_INFO_LOG_LENGTH,
    GL_ACTIVE_UNIFORMS,
    GL_ARRAY_BUFFER,
    GL_ELEMENT_ARRAY_BUFFER,
    GL_PIXEL_PACK_BUFFER,
    GL_PIXEL_UNPACK_BUFFER,
    GL_UNIFORM_BUFFER,
    GL_TEXTURE_BUFFER,
    GL_COPY_READ_BUFFER,
    GL_FRAMEBUFFER,
    GL_READ_FRAMEBUFFER,
    GL_DRAW_FRAMEBUFFER,
    GL_RENDERBUFFER,
    GL_COLOR_ATTACHMENT0,
    GL_COLOR_ATTACHMENT1,
    GL_DEPTH_ATTACHMENT,
    GL_STENCIL_ATTACHMENT,
    GL_DEPTH_STENCIL_ATTACHMENT,
    GL_COLOR,
    GL_DEPTH,
    GL_STENCIL,
    GL_MODELVIEW,
    GL_PROJECTION,
    GL_TEXTURE,
    GL_VIEWPORT,
    GL_MODELVIEW_MATRIX,
    GL_VERTEX_ARRAY,
    GL_COLOR_ARRAY,
    GL_NORMAL_ARRAY,
    GL_TEXTURE_COORD_ARRAY,
    GL_TEXTURE0,
    GL_TEXTURE7,
    GL_C4F_N3F_V3F,
    GL_T2F_V3F,
    GL_SELECT,
    GL_FEEDBACK,
    GL_RENDER,
    GL_COMPILE,
    GL_COMPILE_AND_EXECUTE,
    GL_TEXTURE_WIDTH,
    GL_TEXTURE_MIN_FILTER,
    GL_TEXTURE_MAG_FILTER,
    GL_TEXTURE_WRAP_S,
    GL_TEXTURE_BASE_LEVEL,
    GL_TEXTURE_MAX_LEVEL,
    GL_TEXTURE_COMPARE_MODE,
    GL_GENERATE_MIPMAP,
    GL_NEAREST,
    GL_LINEAR,
    GL_LINEAR_MIPMAP_LINEAR,
    GL_REPEAT,
    GL_CLAMP_TO_EDGE,
    GL_VERTEX_ATTRIB_ARRAY_SIZE,
    GL_VERTEX_ATTRIB_ARRAY_DIVISOR,
    GL_SRC_ALPHA,
    GL_ONE,
    GL_ZERO,
    GL_CONSTANT_COLOR,
    GL_LESS,
    GL_ALWAYS,
    GL_NEVER,
    GL_KEEP,
    GL_INCR_WRAP,
    GL_INVERT,
    GL_LINE,
    GL_POINT,
    GL_FILL,
    GL_PRIMITIVE_RESTART,
    GL_SAMPLES_PASSED,
    GL_ANY_SAMPLES_PASSED,
    GL_TIME_ELAPSED,
    GL_QUERY_RESULT,
    GL_QUERY_RESULT_AVAILABLE,
    GL_READ_ONLY,
    GL_WRITE_ONLY,
    GL_READ_WRITE,
    GL_STATIC_DRAW,
    GL_STREAM_DRAW,
    GL_BUFFER_SIZE,
    GL_EXTENSIONS,
    GL_VERSION,
    GL_SHADING_LANGUAGE_VERSION,
    GL_MAX_TEXTURE_SIZE,
    GL_DRAW_BUFFER,
    GL_READ_BUFFER,
    GL_FRAMEBUFFER_BINDING,
];

pub const INTS: &[i32] = &[
    -1,
    0,
    1,
    2,
    3,
    4,
    7,
    16,
    64,
    255,
    1000,
    -1000,
    65536,
    i32::MAX,
    i32::MIN,
];

pub const FLOATS: &[f32] = &[
    0.0,
    1.0,
    -1.0,
    0.5,
    2.0,
    -0.25,
    1e30,
    -1e30,
    1e-30,
    f32::NAN,
    f32::INFINITY,
    f32::NEG_INFINITY,
];

pub const SHADERS: &[&[u8]] = &[
    b"attribute vec4 p; uniform mat4 m; uniform vec4 u[3]; void main() { gl_Position = m * p + u[1]; }\0",
    b"uniform vec4 col; void main() { gl_FragColor = col; }\0",
    b"#version 130\nin vec4 p; out vec2 t; void main() { t = p.xy; gl_Position = p; }\0",
    b"#version 130\nuniform sampler2D s; in vec2 t; out vec4 c; void main() { c = texture(s, t); }\0",
    b"#version 150\nlayout(triangles) in; layout(triangle_strip, max_vertices = 3) out;\nvoid main() { for (int i = 0; i < 3; i++) { gl_Position = gl_in[i].gl_Position; EmitVertex(); } }\0",
    b"void main() { gl_FragColor = vec4(1.0 / 0.0); }\0",
    b"not a shader\0",
];

/// Where a program's choices come from.
pub trait Choices {
    /// The next choice.
    fn byte(&mut self) -> u8;

    fn pick<T: Copy>(&mut self, v: &[T]) -> T {
        v[usize::from(self.byte()) % v.len()]
    }
    fn e(&mut self) -> u32 {
        self.pick(ENUMS)
    }
    fn int(&mut self) -> i32 {
        self.pick(INTS)
    }
    /// -4..=64: sizes and counts the buffers hold.
    fn small(&mut self) -> i32 {
        i32::from(self.byte() % 69) - 4
    }
    fn f(&mut self) -> f32 {
        self.pick(FLOATS)
    }
    fn bool(&mut self) -> bool {
        self.byte() & 1 == 1
    }
}

/// The framebuffer's size.
pub const W: i32 = 24;
pub const H: i32 = 16;

/// What the calls' pointers point into.
pub struct Buffers {
    floats: Vec<f32>,
    indices: Vec<u32>,
    out: Vec<u8>,
}

impl Default for Buffers {
    fn default() -> Self {
        Buffers {
            floats: (0..8192)
                .map(|i| ((i * 37) % 200) as f32 / 100.0 - 1.0)
                .collect(),
            indices: (0..1024).map(|i| (i * 7) % 300).collect(),
            out: vec![0u8; 1 << 17],
        }
    }
}

/// A compatibility context (24 depth, 8 stencil bits) made current on
/// `framebuffer` (W x H RGBA8), and its initial draw buffer.
///
/// # Safety
/// `framebuffer` outlives the context's use.
pub unsafe fn current_context(framebuffer: &mut [u8]) -> (OSMesaContext, u32) {
    assert_eq!(framebuffer.len(), (W * H * 4) as usize);
    let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, null_mut());
    assert!(!ctx.is_null());
    let fb = framebuffer.as_mut_ptr() as *mut c_void;
    assert_eq!(OSMesaMakeCurrent(ctx, fb, GL_UNSIGNED_BYTE, W, H), 1);
    let mut draw_buffer = 0;
    glGetIntegerv(GL_DRAW_BUFFER, &mut draw_buffer);
    (ctx, draw_buffer as u32)
}

/// After a program: back to a state in which a clear reaches the window
/// (out of glBegin, list compilation and selection, the window bound and
/// drawn to), then asserts that a green clear lands in `framebuffer`.
///
/// # Safety
/// The context made by [`current_context`] on `framebuffer` is current.
pub unsafe fn assert_still_clears(framebuffer: &[u8], draw_buffer: u32) {
    glEnd();
    glEndList();
    glRenderMode(GL_RENDER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDrawBuffer(draw_buffer);
    glUseProgram(0);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(1, 1, 1, 1);
    glClearColor(0.0, 1.0, 0.0, 1.0);
    while glGetError() != GL_NO_ERROR {}
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    assert_eq!(glGetError(), GL_NO_ERROR, "the context still clears");
    assert_eq!(&framebuffer[0..4], &[0, 255, 0, 255]);
}

/// Makes one call chosen by the next byte.
pub unsafe fn call(input: &mut impl Choices, names: &mut Vec<u32>, bufs: &mut Buffers) {
    let fp = bufs.floats.as_ptr();
    let vp = fp as *const c_void;
    let op = bufs.out.as_mut_ptr();
    let which = input.byte();
    let e = input.e();
    let e2 = input.e();
    let n = input.pick(names);
    let (a, b) = (input.int(), input.small());
    match which % 100 {
        0 => glBegin(e),
        1 => glEnd(),
        2 => glVertex3f(input.f(), input.f(), input.f()),
        3 => glDrawArrays(e, a.clamp(-1, 200), b),
        4 => glDrawElements(e, b, e2, bufs.indices.as_ptr() as *const c_void),
        5 => glEnable(e),
        6 => glDisable(e),
        7 => glVertexAttribPointer(n % 20, a, e, 0, input.pick(&[0, 4, 16, -1]), vp),
        8 => glEnableVertexAttribArray(n % 20),
        9 => glVertexPointer(a, e, input.pick(&[0, 8, -4]), vp),
        10 => glEnableClientState(e),
        11 => glColorPointer(a, e, 0, if input.bool() { null() } else { vp }),
        12 => {
            let s = glCreateShader(e);
            names.push(s);
            // Mostly the shader of the stage asked for, else any of them.
            let src = match e {
                GL_VERTEX_SHADER if input.bool() => SHADERS[0],
                GL_FRAGMENT_SHADER if input.bool() => SHADERS[1],
                _ => input.pick(SHADERS),
            };
            let p = src.as_ptr() as *const GLchar;
            glShaderSource(s, input.pick(&[1, 0, -1]), &p, null());
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
        25 => glLoadMatrixf(if input.bool() { null() } else { fp }),
        26 => glReadPixels(a.clamp(-5, 30), 0, b, b, e, e2, op as *mut c_void),
        27 => glTexImage2D(
            e,
            a.clamp(-1, 3),
            e2 as i32,
            b.min(32),
            b.min(32),
            input.pick(&[0, 1]),
            GL_RGBA,
            GL_FLOAT,
            if input.bool() { null() } else { vp },
        ),
        28 => glBindTexture(e, n),
        29 => glBindBuffer(e, n),
        30 => glBufferData(
            e,
            input.pick(&[-1, 0, 64, 4096]) as isize,
            if input.bool() { null() } else { vp },
            input.e(),
        ),
        31 => glGetShaderInfoLog(n, b, null_mut(), op as *mut GLchar),
        32 => glGetProgramiv(n, e, op as *mut GLint),
        33 => glDeleteShader(n),
        34 => glDeleteProgram(n),
        35 => glClear(input.pick(&[
            GL_COLOR_BUFFER_BIT,
            GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
            GL_ACCUM_BUFFER_BIT,
            0xffff_ffff,
        ])),
        36 => glViewport(a.clamp(-5, 5), 0, b, b),
        37 => glBindFramebuffer(e, n),
        38 => glTexCoordPointer(a, e, 0, vp),
        39 => {
            let p = glMapBuffer(e, input.pick(&[GL_READ_ONLY, GL_WRITE_ONLY, e2]));
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
        42 => glCopyTexImage2D(e, a.clamp(-1, 2), e2, 0, 0, b, b, input.pick(&[0, 1])),
        43 => glCopyTexSubImage2D(e, a.clamp(-1, 2), b, 1, 0, 0, b, 2),
        44 => glPushAttrib(input.pick(&[0xffff_ffff, GL_ENABLE_BIT, GL_COLOR_BUFFER_BIT])),
        45 => glPopAttrib(),
        46 => glPushClientAttrib(input.pick(&[0xffff_ffff, GL_CLIENT_VERTEX_ARRAY_BIT])),
        47 => glPopClientAttrib(),
        48 => glArrayElement(a.clamp(-1, 250)),
        49 => glGetVertexAttribiv(n % 20, e, op as *mut GLint),
        50 => glGetTexLevelParameteriv(e, a.clamp(-1, 3), e2, op as *mut GLint),
        51 => {
            glRenderMode(e);
        }
        52 => glInterleavedArrays(e, input.pick(&[0, 8, -1]), vp),
        53 => glBeginQuery(input.pick(&[e, GL_SAMPLES_PASSED]), n),
        54 => glEndQuery(input.pick(&[e, GL_SAMPLES_PASSED])),
        55 => glGetQueryObjectuiv(n, input.pick(&[e, GL_QUERY_RESULT]), op as *mut GLuint),
        56 => glRasterPos4f(input.f(), input.f(), input.f(), input.f()),
        57 => glWindowPos3f(input.f() * 8.0, input.f() * 8.0, input.f()),
        58 => glDrawPixels(
            a.clamp(-1, 16),
            b.clamp(-1, 16),
            input.pick(&[e, GL_RGBA, GL_DEPTH_COMPONENT, GL_STENCIL_INDEX]),
            input.pick(&[e2, GL_FLOAT, GL_UNSIGNED_BYTE]),
            vp,
        ),
        59 => glBitmap(
            a.clamp(-1, 16),
            b.clamp(-1, 16),
            input.f(),
            input.f(),
            input.f(),
            input.f(),
            fp as *const GLubyte,
        ),
        60 => glCopyPixels(a, b, a.clamp(-1, 30), b.clamp(-1, 30), e),
        61 => glPixelZoom(input.f(), input.f()),
        62 => {
            let mut v = [0u32; 2];
            glGenVertexArrays(input.pick(&[-1, 0, 1, 2]), v.as_mut_ptr());
            names.extend(v.iter().filter(|&&x| x != 0));
        }
        63 => glBindVertexArray(n),
        64 => glDeleteVertexArrays(1, &n),
        65 => glDrawArraysInstanced(e, a.clamp(-1, 200), b, input.pick(&[-1, 0, 1, 3])),
        66 => glDrawElementsInstancedBaseVertex(
            e,
            b,
            e2,
            bufs.indices.as_ptr() as *const c_void,
            input.pick(&[-1, 0, 1, 3]),
            a.clamp(-300, 300),
        ),
        67 => glVertexAttribIPointer(n % 20, a, e, input.pick(&[0, 4, 16, -1]), vp),
        68 => glVertexAttribDivisor(n % 20, input.pick(&[0, 1, 2, u32::MAX])),
        69 => glPrimitiveRestartIndex(input.pick(&[0, 7, 0xffff, u32::MAX])),
        70 => {
            let mut v = [0u32; 2];
            match input.byte() % 4 {
                0 => glGenTextures(2, v.as_mut_ptr()),
                1 => glGenBuffers(2, v.as_mut_ptr()),
                2 => glGenFramebuffers(2, v.as_mut_ptr()),
                _ => glGenRenderbuffers(2, v.as_mut_ptr()),
            }
            names.extend(v.iter().filter(|&&x| x != 0));
        }
        71 => glTexParameteri(e, e2, input.e() as i32),
        72 => glTexSubImage2D(
            e,
            a.clamp(-1, 3),
            b,
            input.small(),
            input.small().min(32),
            input.small().min(32),
            GL_RGBA,
            GL_FLOAT,
            vp,
        ),
        73 => glFramebufferTexture2D(e, e2, input.e(), n, a.clamp(-1, 3)),
        74 => glBindRenderbuffer(e, n),
        75 => glRenderbufferStorage(e, e2, b, input.small()),
        76 => glFramebufferRenderbuffer(e, e2, input.e(), n),
        77 => {
            glCheckFramebufferStatus(e);
        }
        78 => glBlitFramebuffer(
            a.clamp(-50, 100),
            b,
            input.small(),
            input.small(),
            input.small(),
            input.small(),
            input.int().clamp(-50, 100),
            input.small(),
            input.pick(&[
                GL_COLOR_BUFFER_BIT,
                GL_DEPTH_BUFFER_BIT,
                GL_STENCIL_BUFFER_BIT,
                0xffff_ffff,
            ]),
            e2,
        ),
        79 => glClearBufferfv(e, b, fp),
        80 => glBufferSubData(
            e,
            input.pick(&[-1, 0, 4, 100]) as isize,
            input.pick(&[-1, 0, 16, 64]) as isize,
            vp,
        ),
        81 => {
            let v = [e, e2, input.e(), input.e()];
            glDrawBuffers(input.pick(&[-1, 0, 1, 2, 4]), v.as_ptr());
        }
        82 => {
            glGetStringi(e, b as u32);
        }
        83 => {
            glGetString(e);
        }
        84 => glBlendFunc(e, e2),
        85 => glDepthFunc(e),
        86 => glScissor(a.clamp(-5, 30), b, b, input.small()),
        87 => glPolygonMode(e, e2),
        88 => glStencilFunc(e, a, input.int() as u32),
        89 => glStencilOp(e, e2, input.e()),
        90 => glColor4f(input.f(), input.f(), input.f(), input.f()),
        91 => glPointSize(input.f()),
        92 => glOrtho(
            f64::from(input.f()),
            f64::from(input.f()),
            f64::from(input.f()),
            f64::from(input.f()),
            f64::from(input.f()),
            f64::from(input.f()),
        ),
        93 => glRotatef(input.f(), input.f(), input.f(), input.f()),
        94 => glDrawBuffer(e),
        95 => glReadBuffer(e),
        96 => glNewList(n, e),
        97 => glEndList(),
        98 => glCallList(n),
        _ => {
            let _ = glGetError();
            let loc = glGetUniformLocation(n, c"col".as_ptr());
            glUniform1i(loc, a);
            glGenerateMipmap(e);
        }
    }
}
