"""Differential GL 3.3 entry points added last to libOSMesa (3.3 core
contexts): sampler objects over a texture's own state, glClampColor's read
clamping of a float buffer, layer and layered framebuffer attachments of
an array texture, and dual-source blending; their queries and errors.
"""
import ctypes

from harness import GL, errors, main, program, scene

CORE = (3, 3, "core")
U, I, F, E, P = ctypes.c_uint, ctypes.c_int, ctypes.c_float, ctypes.c_uint, ctypes.c_void_p


def proc(name, restype, *argtypes):
    """An entry point by OSMesaGetProcAddress (Mesa's libOSMesa exports few
    GL 3.3 symbols, so PyOpenGL's own bindings may not find them)."""
    from OpenGL import platform
    addr = platform.PLATFORM.getExtensionProcedure(name.encode())
    return ctypes.CFUNCTYPE(restype, *argtypes)(ctypes.cast(addr, ctypes.c_void_p).value)


def check(log, what, f, *args):
    errors()
    r = f(*args)
    log.append(f"{what}: {errors()}")
    return r


VS = """#version 330 core
layout(location = 0) in vec2 pos;
out vec2 tc;
void main() { gl_Position = vec4(pos, 0.0, 1.0); tc = pos * 0.5 + 0.5; }
"""

QUAD = [-1, -1, 1, -1, -1, 1, 1, 1]


def quad():
    vao = GL.glGenVertexArrays(1)
    GL.glBindVertexArray(vao)
    b = GL.glGenBuffers(1)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, b)
    data = (ctypes.c_float * 8)(*QUAD)
    GL.glBufferData(GL.GL_ARRAY_BUFFER, ctypes.sizeof(data), data, GL.GL_STATIC_DRAW)
    GL.glVertexAttribPointer(0, 2, GL.GL_FLOAT, GL.GL_FALSE, 0, None)
    GL.glEnableVertexAttribArray(0)


@scene("gl33_samplers", 32, 16, CORE)
def samplers(log):
    gen = proc("glGenSamplers", None, I, P)
    delete = proc("glDeleteSamplers", None, I, P)
    is_sampler = proc("glIsSampler", ctypes.c_ubyte, U)
    bind = proc("glBindSampler", None, U, U)
    pi = proc("glSamplerParameteri", None, U, E, I)
    pf = proc("glSamplerParameterf", None, U, E, F)
    pfv = proc("glSamplerParameterfv", None, U, E, P)
    gfv = proc("glGetSamplerParameterfv", None, U, E, P)
    giv = proc("glGetSamplerParameteriv", None, U, E, P)
    # A 4×4 checker of red and green, LINEAR and REPEAT on the texture.
    t = GL.glGenTextures(1)
    GL.glBindTexture(GL.GL_TEXTURE_2D, t)
    texels = []
    for y in range(4):
        for x in range(4):
            texels += [255, 0, 0, 255] if (x + y) % 2 else [0, 255, 0, 255]
    data = (ctypes.c_ubyte * len(texels))(*texels)
    GL.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL.GL_RGBA8, 4, 4, 0, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, data)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_LINEAR)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_LINEAR)
    program([VS], ["""#version 330 core
in vec2 tc;
uniform sampler2D s;
out vec4 c;
void main() { c = texture(s, tc * 1.5 - 0.25); }
"""])
    quad()
    s = (ctypes.c_uint * 2)()
    check(log, "glGenSamplers", gen, 2, s)
    log.append(f"  IsSampler: {is_sampler(s[0])} {is_sampler(0)} {is_sampler(12345)}")
    # Left half: the texture's own state.
    GL.glViewport(0, 0, 16, 16)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    # Right half: NEAREST and CLAMP_TO_EDGE from the sampler.
    check(log, "glSamplerParameteri(MIN_FILTER)", pi, s[0], GL.GL_TEXTURE_MIN_FILTER, GL.GL_NEAREST)
    check(log, "glSamplerParameteri(MAG_FILTER)", pi, s[0], GL.GL_TEXTURE_MAG_FILTER, GL.GL_NEAREST)
    check(log, "glSamplerParameteri(WRAP_S)", pi, s[0], GL.GL_TEXTURE_WRAP_S, GL.GL_CLAMP_TO_EDGE)
    check(log, "glSamplerParameteri(WRAP_T)", pi, s[0], GL.GL_TEXTURE_WRAP_T, GL.GL_CLAMP_TO_BORDER)
    border = (ctypes.c_float * 4)(0.0, 0.0, 1.0, 1.0)
    check(log, "glSamplerParameterfv(BORDER_COLOR)", pfv, s[0], GL.GL_TEXTURE_BORDER_COLOR, border)
    check(log, "glBindSampler", bind, 0, s[0])
    log.append(f"  SAMPLER_BINDING: {int(GL.glGetIntegerv(GL.GL_SAMPLER_BINDING)) == s[0]}")
    GL.glViewport(16, 0, 16, 16)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    log.append(f"  texture MIN_FILTER: {int(GL.glGetTexParameteriv(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER)):#x}")
    # Parameter values back, the defaults of the second sampler.
    out = (ctypes.c_float * 4)()
    for pname in (GL.GL_TEXTURE_MIN_FILTER, GL.GL_TEXTURE_WRAP_R, GL.GL_TEXTURE_MIN_LOD,
                  GL.GL_TEXTURE_MAX_LOD, GL.GL_TEXTURE_LOD_BIAS, GL.GL_TEXTURE_COMPARE_MODE,
                  GL.GL_TEXTURE_COMPARE_FUNC):
        check(log, f"glGetSamplerParameterfv({int(pname):#x})", gfv, s[1], pname, out)
        log.append(f"  -> {out[0]}")
    check(log, "glGetSamplerParameterfv(BORDER_COLOR)", gfv, s[0], GL.GL_TEXTURE_BORDER_COLOR, out)
    log.append(f"  -> {list(out)}")
    check(log, "glSamplerParameterf(MAX_LOD)", pf, s[1], GL.GL_TEXTURE_MAX_LOD, 2.6)
    iv = (ctypes.c_int * 4)()
    check(log, "glGetSamplerParameteriv(MAX_LOD)", giv, s[1], GL.GL_TEXTURE_MAX_LOD, iv)
    log.append(f"  -> {iv[0]}")
    # Errors.
    check(log, "glBindSampler(unknown name)", bind, 0, 12345)
    check(log, "glBindSampler(unit past the limit)", bind, 1000, s[0])
    check(log, "glSamplerParameteri(BASE_LEVEL)", pi, s[0], GL.GL_TEXTURE_BASE_LEVEL, 1)
    check(log, "glSamplerParameteri(unknown sampler)", pi, 12345, GL.GL_TEXTURE_MIN_FILTER, GL.GL_NEAREST)
    check(log, "glGetSamplerParameterfv(unknown sampler)", gfv, 12345, GL.GL_TEXTURE_MIN_FILTER, out)
    check(log, "glSamplerParameteri(bad filter)", pi, s[0], GL.GL_TEXTURE_MAG_FILTER, GL.GL_LINEAR_MIPMAP_LINEAR)
    check(log, "glSamplerParameteri(bad wrap)", pi, s[0], GL.GL_TEXTURE_WRAP_S, GL.GL_LINEAR)
    check(log, "glGetSamplerParameterfv(DEPTH_TEXTURE_MODE)", gfv, s[0], GL.GL_TEXTURE_SWIZZLE_R, out)
    check(log, "glDeleteSamplers(-1)", delete, -1, s)
    # Deleting the bound sampler unbinds it.
    check(log, "glDeleteSamplers", delete, 2, s)
    log.append(f"  SAMPLER_BINDING: {int(GL.glGetIntegerv(GL.GL_SAMPLER_BINDING))}")
    log.append(f"  IsSampler: {is_sampler(s[0])}")


@scene("gl33_clamp_read_color", 8, 8, CORE)
def clamp_read_color(log):
    clamp = proc("glClampColor", None, E, E)
    log.append(f"CLAMP_READ_COLOR: {int(GL.glGetIntegerv(GL.GL_CLAMP_READ_COLOR)):#x}")
    check(log, "glClampColor(FRAGMENT)", clamp, GL.GL_CLAMP_FRAGMENT_COLOR, GL.GL_TRUE)
    check(log, "glClampColor(bad value)", clamp, GL.GL_CLAMP_READ_COLOR, GL.GL_RED)
    t = GL.glGenTextures(1)
    GL.glBindTexture(GL.GL_TEXTURE_2D, t)
    GL.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL.GL_RGBA32F, 8, 8, 0, GL.GL_RGBA, GL.GL_FLOAT, None)
    fb = GL.glGenFramebuffers(1)
    GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, fb)
    GL.glFramebufferTexture2D(GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, GL.GL_TEXTURE_2D, t, 0)
    program([VS], ["""#version 330 core
out vec4 c;
void main() { c = vec4(2.0, -1.0, 0.5, 1.0); }
"""])
    quad()
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    for mode in (GL.GL_FIXED_ONLY, GL.GL_TRUE, GL.GL_FALSE):
        check(log, f"glClampColor(READ, {int(mode):#x})", clamp, GL.GL_CLAMP_READ_COLOR, mode)
        px = (ctypes.c_float * 4)()
        GL.glReadPixels(0, 0, 1, 1, GL.GL_RGBA, GL.GL_FLOAT, px)
        log.append(f"  -> {list(px)}")
    return False


@scene("gl33_layers", 24, 8, CORE)
def layers(log):
    layer = proc("glFramebufferTextureLayer", None, E, E, U, I, I)
    layered = proc("glFramebufferTexture", None, E, E, U, I)
    tex3d = proc("glFramebufferTexture3D", None, E, E, E, U, I, I)
    t = GL.glGenTextures(1)
    GL.glBindTexture(GL.GL_TEXTURE_2D_ARRAY, t)
    GL.glTexImage3D(GL.GL_TEXTURE_2D_ARRAY, 0, GL.GL_RGBA8, 4, 4, 3, 0, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, None)
    GL.glTexParameteri(GL.GL_TEXTURE_2D_ARRAY, GL.GL_TEXTURE_MIN_FILTER, GL.GL_NEAREST)
    fb = GL.glGenFramebuffers(1)
    GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, fb)
    for i, c in enumerate([(1, 0, 0, 1), (0, 1, 0, 1), (0, 0, 1, 1)]):
        check(log, f"glFramebufferTextureLayer({i})", layer, GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, t, 0, i)
        log.append(f"  status: {int(GL.glCheckFramebufferStatus(GL.GL_FRAMEBUFFER)):#x}")
        v = GL.glGetFramebufferAttachmentParameteriv(GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, GL.GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER)
        log.append(f"  layer: {int(v)}")
        GL.glClearColor(*c)
        GL.glClear(GL.GL_COLOR_BUFFER_BIT)
    check(log, "glFramebufferTexture", layered, GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, t, 0)
    v = GL.glGetFramebufferAttachmentParameteriv(GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, GL.GL_FRAMEBUFFER_ATTACHMENT_LAYERED)
    log.append(f"  layered: {int(v)} status: {int(GL.glCheckFramebufferStatus(GL.GL_FRAMEBUFFER)):#x}")
    rb = GL.glGenRenderbuffers(1)
    GL.glBindRenderbuffer(GL.GL_RENDERBUFFER, rb)
    GL.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_RGBA8, 4, 4)
    GL.glFramebufferRenderbuffer(GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT1, GL.GL_RENDERBUFFER, rb)
    log.append(f"  beside a renderbuffer: {int(GL.glCheckFramebufferStatus(GL.GL_FRAMEBUFFER)):#x}")
    GL.glFramebufferRenderbuffer(GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT1, GL.GL_RENDERBUFFER, 0)
    # Errors.
    t2 = GL.glGenTextures(1)
    GL.glBindTexture(GL.GL_TEXTURE_2D, t2)
    GL.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL.GL_RGBA8, 4, 4, 0, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, None)
    check(log, "glFramebufferTextureLayer(2D texture)", layer, GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, t2, 0, 0)
    check(log, "glFramebufferTextureLayer(negative layer)", layer, GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, t, 0, -1)
    check(log, "glFramebufferTexture3D(array texture)", tex3d, GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, GL.GL_TEXTURE_3D, t, 0, 0)
    check(log, "glFramebufferTexture(unknown name)", layered, GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, 4321, 0)
    # Each layer, sampled side by side into the window.
    GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, 0)
    p = program([VS], ["""#version 330 core
in vec2 tc;
uniform sampler2DArray s;
uniform float layer;
out vec4 c;
void main() { c = texture(s, vec3(tc, layer)); }
"""])
    quad()
    for i in range(3):
        GL.glUniform1f(GL.glGetUniformLocation(p, "layer"), float(i))
        GL.glViewport(8 * i, 0, 8, 8)
        GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)


@scene("gl33_dual_source", 16, 16, CORE)
def dual_source(log):
    bind = proc("glBindFragDataLocationIndexed", None, U, U, U, ctypes.c_char_p)
    index = proc("glGetFragDataIndex", I, U, ctypes.c_char_p)
    log.append(f"MAX_DUAL_SOURCE_DRAW_BUFFERS: {int(GL.glGetIntegerv(GL.GL_MAX_DUAL_SOURCE_DRAW_BUFFERS))}")
    p = program([VS], ["""#version 330 core
in vec2 tc;
layout(location = 0, index = 0) out vec4 c0;
layout(location = 0, index = 1) out vec4 c1;
void main() { c0 = vec4(tc, 0.25, 0.5); c1 = vec4(0.5, 1.0 - tc.x, tc.y, 0.75); }
"""])
    log.append(f"index c0 {index(p, b'c0')} c1 {index(p, b'c1')} none {index(p, b'none')}")
    quad()
    GL.glClearColor(0.2, 0.4, 0.6, 0.8)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT)
    GL.glEnable(GL.GL_BLEND)
    GL.glViewport(0, 0, 8, 8)
    check(log, "glBlendFunc(ONE, SRC1_COLOR)", GL.glBlendFunc, GL.GL_ONE, GL.GL_SRC1_COLOR)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    GL.glViewport(8, 0, 8, 8)
    GL.glBlendFunc(GL.GL_SRC1_ALPHA, GL.GL_ONE_MINUS_SRC1_ALPHA)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    GL.glViewport(0, 8, 8, 8)
    GL.glBlendFuncSeparate(GL.GL_ONE_MINUS_SRC1_COLOR, GL.GL_SRC1_COLOR, GL.GL_ONE, GL.GL_ZERO)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    # Bound by name instead of by layout.
    q = GL.glCreateProgram()
    for kind, src in ((GL.GL_VERTEX_SHADER, VS), (GL.GL_FRAGMENT_SHADER, """#version 330 core
in vec2 tc;
out vec4 a;
out vec4 b;
void main() { a = vec4(tc.y, 0.5, tc.x, 1.0); b = vec4(1.0, tc.x, 0.0, 0.5); }
""")):
        s = GL.glCreateShader(kind)
        GL.glShaderSource(s, src)
        GL.glCompileShader(s)
        GL.glAttachShader(q, s)
    check(log, "glBindFragDataLocationIndexed(a)", bind, q, 0, 0, b"a")
    check(log, "glBindFragDataLocationIndexed(b)", bind, q, 0, 1, b"b")
    check(log, "glBindFragDataLocationIndexed(index 2)", bind, q, 0, 2, b"b")
    check(log, "glBindFragDataLocationIndexed(color 1, index 1)", bind, q, 1, 1, b"b")
    GL.glLinkProgram(q)
    log.append(f"link: {int(GL.glGetProgramiv(q, GL.GL_LINK_STATUS))} index a {index(q, b'a')} b {index(q, b'b')}")
    GL.glUseProgram(q)
    GL.glViewport(8, 8, 8, 8)
    GL.glBlendFunc(GL.GL_ONE, GL.GL_ONE_MINUS_SRC1_COLOR)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)


if __name__ == "__main__":
    main()
