"""Differential GL 3.0–3.3 state, queries, sync objects and transform
feedback on 3.3 core contexts: fences and their errors, occlusion /
primitive / timer queries and conditional rendering (results and errors;
elapsed times only as "positive"), the provoking-vertex convention on flat
values, fragment-output locations, glClearBuffer*, per-buffer colour masks,
depth clamping, and what transform feedback writes (interleaved and
separate, strips, overflow) with its errors.
"""
import ctypes
import sys

from harness import GL, errors, main, program, scene
from OpenGL.raw.GL.VERSION import GL_3_2 as raw32  # noqa: E402

CORE = (3, 3, "core")

VS_POS = """#version 330 core
layout(location = 0) in vec4 pos;
flat out int vid;
void main() { gl_Position = pos; vid = gl_VertexID; }
"""
FS_FLAT = """#version 330 core
flat in int vid;
out vec4 c;
void main() { c = vec4(float(vid) / 8.0, 0.5, 0.0, 1.0); }
"""


def proc(name, *argtypes):
    """An entry point by OSMesaGetProcAddress (PyOpenGL's binding of some
    GL 3.3 functions looks only in the library's exported symbols, which
    Mesa's libOSMesa lacks for them)."""
    from OpenGL import platform
    addr = platform.PLATFORM.getExtensionProcedure(name.encode())
    return ctypes.CFUNCTYPE(None, *argtypes)(ctypes.cast(addr, ctypes.c_void_p).value)


def check(log, what, f, *args):
    errors()
    r = f(*args)
    log.append(f"{what}: {errors()}")
    return r


def vertices(points):
    """A VAO with `points` (vec4s) at attribute 0; returns nothing."""
    vao = GL.glGenVertexArrays(1)
    GL.glBindVertexArray(vao)
    b = GL.glGenBuffers(1)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, b)
    flat = [c for p in points for c in p]
    data = (ctypes.c_float * len(flat))(*flat)
    GL.glBufferData(GL.GL_ARRAY_BUFFER, ctypes.sizeof(data), data, GL.GL_STATIC_DRAW)
    GL.glVertexAttribPointer(0, 4, GL.GL_FLOAT, GL.GL_FALSE, 0, None)
    GL.glEnableVertexAttribArray(0)


STRIP = [(-1, -1, 0, 1), (-1, 1, 0, 1), (1, -1, 0, 1), (1, 1, 0, 1)]


@scene("gl33_sync", 8, 8, CORE)
def sync(log):
    s = check(log, "glFenceSync", GL.glFenceSync, GL.GL_SYNC_GPU_COMMANDS_COMPLETE, 0)
    log.append(f"  IsSync: {bool(GL.glIsSync(s))}")
    r = check(log, "glClientWaitSync", GL.glClientWaitSync, s, GL.GL_SYNC_FLUSH_COMMANDS_BIT, 1000000)
    log.append(f"  -> {int(r):#x}")
    check(log, "glWaitSync", GL.glWaitSync, s, 0, GL.GL_TIMEOUT_IGNORED)
    check(log, "glWaitSync(timeout 0)", GL.glWaitSync, s, 0, 0)
    check(log, "glWaitSync(flags 1)", GL.glWaitSync, s, 1, GL.GL_TIMEOUT_IGNORED)
    r = check(log, "glClientWaitSync(flags 2)", GL.glClientWaitSync, s, 2, 0)
    log.append(f"  -> {int(r):#x}")
    for pname in (GL.GL_OBJECT_TYPE, GL.GL_SYNC_STATUS, GL.GL_SYNC_CONDITION, GL.GL_SYNC_FLAGS):
        v = (ctypes.c_int * 1)(-1)
        n = ctypes.c_int(-1)
        check(log, f"glGetSynciv({int(pname):#x})", GL.glGetSynciv, s, pname, 1, ctypes.byref(n), v)
        log.append(f"  -> {n.value} {v[0]:#x}")
    v = (ctypes.c_int * 1)(-1)
    check(log, "glGetSynciv(bad pname)", GL.glGetSynciv, s, GL.GL_SYNC_FENCE, 1, None, v)
    check(log, "glFenceSync(bad condition)", GL.glFenceSync, 0, 0)
    check(log, "glFenceSync(flags 1)", GL.glFenceSync, GL.GL_SYNC_GPU_COMMANDS_COMPLETE, 1)
    check(log, "glDeleteSync", GL.glDeleteSync, s)
    log.append(f"  IsSync: {bool(GL.glIsSync(s))}")
    check(log, "glDeleteSync(0)", GL.glDeleteSync, None)
    t = ctypes.c_int64(0)
    raw32.glGetInteger64v(GL.GL_MAX_SERVER_WAIT_TIMEOUT, ctypes.byref(t))
    log.append(f"max server wait timeout positive: {t.value > 0} {errors()}")
    return False


@scene("gl33_queries", 16, 16, CORE)
def queries(log):
    program([VS_POS], [FS_FLAT])
    vertices(STRIP)
    q = GL.glGenQueries(6)
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    GL.glBeginQuery(GL.GL_ANY_SAMPLES_PASSED, q[0])
    check(log, "glBeginQuery(SAMPLES_PASSED while ANY active)", GL.glBeginQuery, GL.GL_SAMPLES_PASSED, q[1])
    GL.glBeginQuery(GL.GL_PRIMITIVES_GENERATED, q[2])
    GL.glBeginQuery(GL.GL_TIME_ELAPSED, q[3])
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    GL.glEndQuery(GL.GL_ANY_SAMPLES_PASSED)
    GL.glBeginQuery(GL.GL_SAMPLES_PASSED, q[1])
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)  # equal depth: fails GL_LESS
    GL.glEndQuery(GL.GL_SAMPLES_PASSED)
    GL.glEndQuery(GL.GL_PRIMITIVES_GENERATED)
    GL.glEndQuery(GL.GL_TIME_ELAPSED)
    proc('glQueryCounter', ctypes.c_uint, ctypes.c_uint)(q[4], GL.GL_TIMESTAMP)
    for i, what in enumerate(["any", "samples", "prims"]):
        i = [0, 1, 2][i]
        r = GL.glGetQueryObjectuiv(q[i], GL.GL_QUERY_RESULT)
        log.append(f"{what}: {int(r)}")
    e = ctypes.c_uint64(0)
    proc('glGetQueryObjectui64v', ctypes.c_uint, ctypes.c_uint, ctypes.c_void_p)(q[3], GL.GL_QUERY_RESULT, ctypes.byref(e))
    t = ctypes.c_int64(0)
    proc('glGetQueryObjecti64v', ctypes.c_uint, ctypes.c_uint, ctypes.c_void_p)(q[4], GL.GL_QUERY_RESULT, ctypes.byref(t))
    log.append(f"elapsed > 0: {e.value > 0}, timestamp > 0: {t.value > 0} {errors()}")
    bits = GL.glGetQueryiv(GL.GL_TIMESTAMP, GL.GL_QUERY_COUNTER_BITS)
    log.append(f"timestamp bits >= 30: {int(bits) >= 30}")
    check(log, "glBeginQuery(TIMESTAMP)", GL.glBeginQuery, GL.GL_TIMESTAMP, q[5])
    check(log, "glQueryCounter(TIME_ELAPSED)", proc('glQueryCounter', ctypes.c_uint, ctypes.c_uint), q[5], GL.GL_TIME_ELAPSED)
    check(log, "glQueryCounter(an elapsed-time query)", proc('glQueryCounter', ctypes.c_uint, ctypes.c_uint), q[3], GL.GL_TIMESTAMP)
    check(log, "glBeginQuery(unnamed id)", GL.glBeginQuery, GL.GL_SAMPLES_PASSED, 999)
    # Conditional rendering: q[1] passed nothing, q[0] something.
    GL.glDisable(GL.GL_DEPTH_TEST)
    GL.glClearColor(0.0, 0.0, 1.0, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT)
    check(log, "glBeginConditionalRender(zero)", GL.glBeginConditionalRender, q[1], GL.GL_QUERY_WAIT)
    GL.glClearColor(1.0, 0.0, 0.0, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    check(log, "glBeginConditionalRender(nested)", GL.glBeginConditionalRender, q[0], GL.GL_QUERY_WAIT)
    GL.glEndConditionalRender()
    check(log, "glEndConditionalRender(none)", GL.glEndConditionalRender)
    check(log, "glBeginConditionalRender(bad mode)", GL.glBeginConditionalRender, q[0], GL.GL_QUERY_RESULT)
    check(log, "glBeginConditionalRender(not a query)", GL.glBeginConditionalRender, 999, GL.GL_QUERY_WAIT)
    check(log, "glBeginConditionalRender(primitive query)", GL.glBeginConditionalRender, q[2], GL.GL_QUERY_WAIT)
    # The left half drawn under a query that passed.
    GL.glViewport(0, 0, 8, 16)
    GL.glBeginConditionalRender(q[0], GL.GL_QUERY_NO_WAIT)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    GL.glEndConditionalRender()


@scene("gl33_provoking_vertex", 32, 16, CORE)
def provoking(log):
    program([VS_POS], [FS_FLAT])
    # Two strips side by side: last convention left, first right.
    left = [(-1, -1, 0, 1), (-1, 1, 0, 1), (0, -1, 0, 1), (0, 1, 0, 1), (-0.5, -1, 0, 1)]
    vertices(left + [(x + 1, y, z, w) for x, y, z, w in left])
    log.append(f"default: {int(GL.glGetIntegerv(GL.GL_PROVOKING_VERTEX)):#x}")
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 5)
    check(log, "glProvokingVertex(first)", GL.glProvokingVertex, GL.GL_FIRST_VERTEX_CONVENTION)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 5, 5)
    check(log, "glProvokingVertex(bad)", GL.glProvokingVertex, GL.GL_FLAT)
    log.append(f"now: {int(GL.glGetIntegerv(GL.GL_PROVOKING_VERTEX)):#x}")


FS_TWO = """#version 330 core
out vec4 a;
out vec4 b;
void main() { a = vec4(1.0, 0.0, 0.0, 1.0); b = vec4(0.0, 1.0, 0.0, 1.0); }
"""


@scene("gl33_outputs_and_clears", 16, 16, CORE)
def outputs(log):
    from harness import shader
    p = GL.glCreateProgram()
    for kind, src in ((GL.GL_VERTEX_SHADER, VS_POS), (GL.GL_FRAGMENT_SHADER, FS_TWO)):
        GL.glAttachShader(p, shader(kind, src)[0])
    check(log, "glBindFragDataLocation(b, 0)", GL.glBindFragDataLocation, p, 0, b"b")
    check(log, "glBindFragDataLocation(a, 1)", GL.glBindFragDataLocation, p, 1, b"a")
    check(log, "glBindFragDataLocation(8)", GL.glBindFragDataLocation, p, 8, b"a")
    check(log, "glBindFragDataLocation(gl_)", GL.glBindFragDataLocation, p, 0, b"gl_FragColor")
    GL.glLinkProgram(p)
    log.append(f"link: {GL.glGetProgramiv(p, GL.GL_LINK_STATUS)}")
    for n in (b"a", b"b", b"c"):
        log.append(f"location {n.decode()}: {GL.glGetFragDataLocation(p, n)}")
    GL.glUseProgram(p)
    vertices(STRIP)
    # Per-buffer mask, clears of one buffer and of depth / stencil.
    check(log, "glColorMaski(0)", GL.glColorMaski, 0, 1, 1, 0, 1)
    m = (GL.GLboolean * 4)()
    GL.glGetBooleani_v(GL.GL_COLOR_WRITEMASK, 0, m)
    log.append(f"mask 0: {list(m)}")
    check(log, "glColorMaski(8)", GL.glColorMaski, 8, 1, 1, 1, 1)
    check(log, "glEnablei(BLEND, 1)", GL.glEnablei, GL.GL_BLEND, 1)
    log.append(f"blend 0, 1: {GL.glIsEnabledi(GL.GL_BLEND, 0)}, {GL.glIsEnabledi(GL.GL_BLEND, 1)}")
    check(log, "glEnablei(DEPTH_TEST)", GL.glEnablei, GL.GL_DEPTH_TEST, 0)
    check(log, "glEnablei(BLEND, 8)", GL.glEnablei, GL.GL_BLEND, 8)
    GL.glDisablei(GL.GL_BLEND, 1)
    white = (ctypes.c_float * 4)(1, 1, 1, 1)
    check(log, "glClearBufferfv(COLOR, 0)", GL.glClearBufferfv, GL.GL_COLOR, 0, white)
    check(log, "glClearBufferfv(COLOR, 8)", GL.glClearBufferfv, GL.GL_COLOR, 8, white)
    check(log, "glClearBufferfv(STENCIL)", GL.glClearBufferfv, GL.GL_STENCIL, 0, white)
    check(log, "glClearBufferiv(DEPTH)", GL.glClearBufferiv, GL.GL_DEPTH, 0, (ctypes.c_int * 1)(0))
    check(log, "glClearBufferuiv(DEPTH)", GL.glClearBufferuiv, GL.GL_DEPTH, 0, (ctypes.c_uint * 1)(0))
    check(log, "glClearBufferfi(DEPTH)", GL.glClearBufferfi, GL.GL_DEPTH, 0, 1.0, 0)
    check(log, "glClearBufferfi(DEPTH_STENCIL, 1)", GL.glClearBufferfi, GL.GL_DEPTH_STENCIL, 1, 1.0, 0)
    check(log, "glClearBufferfi(DEPTH_STENCIL)", GL.glClearBufferfi, GL.GL_DEPTH_STENCIL, 0, 0.25, 3)
    d = (ctypes.c_float * 1)()
    GL.glReadPixels(2, 2, 1, 1, GL.GL_DEPTH_COMPONENT, GL.GL_FLOAT, d)
    log.append(f"depth: {round(d[0], 5)}")
    GL.glEnable(GL.GL_STENCIL_TEST)
    GL.glStencilFunc(GL.GL_EQUAL, 3, 0xff)
    # b goes to draw buffer 0, through the mask (no blue).
    GL.glViewport(0, 0, 8, 16)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)


@scene("gl33_depth_clamp", 16, 16, CORE)
def depth_clamp(log):
    program([VS_POS], [FS_FLAT])
    # Left quad in front of the near plane, right quad behind the far one.
    vertices([(-1, -1, -3, 1), (-1, 1, -3, 1), (0, -1, -3, 1), (0, 1, -3, 1),
              (0, -1, 3, 1), (0, 1, 3, 1), (1, -1, 3, 1), (1, 1, 3, 1)])
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glDepthFunc(GL.GL_ALWAYS)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    GL.glViewport(0, 0, 16, 8)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 4, 4)
    check(log, "glEnable(DEPTH_CLAMP)", GL.glEnable, GL.GL_DEPTH_CLAMP)
    log.append(f"enabled: {GL.glIsEnabled(GL.GL_DEPTH_CLAMP)}")
    GL.glViewport(0, 8, 16, 8)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 4, 4)
    d = (ctypes.c_float * 2)()
    GL.glReadPixels(3, 12, 1, 1, GL.GL_DEPTH_COMPONENT, GL.GL_FLOAT, d)
    GL.glReadPixels(12, 12, 1, 1, GL.GL_DEPTH_COMPONENT, GL.GL_FLOAT, ctypes.byref(d, 4))
    log.append(f"depths: {round(d[0], 5)} {round(d[1], 5)}")


VS_TF = """#version 330 core
layout(location = 0) in vec4 pos;
out vec2 a;
out float b;
flat out int k;
void main() { gl_Position = pos; a = pos.xy * 10.0; b = pos.x + 100.0; k = gl_VertexID; }
"""


def tf_program(log, names, mode):
    from harness import shader
    p = GL.glCreateProgram()
    GL.glAttachShader(p, shader(GL.GL_VERTEX_SHADER, VS_TF)[0])
    GL.glAttachShader(p, shader(GL.GL_FRAGMENT_SHADER, FS_TWO)[0])
    arr = varyings(names)
    check(log, f"glTransformFeedbackVaryings({names})", GL.glTransformFeedbackVaryings, p, len(names), arr, mode)
    GL.glLinkProgram(p)
    ok = GL.glGetProgramiv(p, GL.GL_LINK_STATUS)
    log.append(f"  link: {ok}")
    return p if ok else None


def varyings(names):
    arr = (ctypes.c_char_p * len(names))(*names)
    return ctypes.cast(arr, ctypes.POINTER(ctypes.POINTER(ctypes.c_char)))


def tf_buffer(index, size):
    b = GL.glGenBuffers(1)
    GL.glBindBuffer(GL.GL_TRANSFORM_FEEDBACK_BUFFER, b)
    GL.glBufferData(GL.GL_TRANSFORM_FEEDBACK_BUFFER, size, None, GL.GL_STREAM_READ)
    GL.glBindBufferBase(GL.GL_TRANSFORM_FEEDBACK_BUFFER, index, b)
    return b


def tf_read(b, n, kind=ctypes.c_float):
    out = (kind * n)()
    GL.glBindBuffer(GL.GL_TRANSFORM_FEEDBACK_BUFFER, b)
    GL.glGetBufferSubData(GL.GL_TRANSFORM_FEEDBACK_BUFFER, 0, ctypes.sizeof(out), out)
    return list(out)


@scene("gl33_transform_feedback", 8, 8, CORE)
def transform_feedback(log):
    vertices([(0.5 * i - 1, 0.25 * i, 0, 1) for i in range(5)])
    for names in ([b"nope"], [b"a", b"a"]):
        tf_program(log, names, GL.GL_INTERLEAVED_ATTRIBS)
    p = tf_program(log, [b"b", b"gl_Position", b"a"], GL.GL_INTERLEAVED_ATTRIBS)
    log.append(f"  varyings: {GL.glGetProgramiv(p, GL.GL_TRANSFORM_FEEDBACK_VARYINGS)}"
               f" max length: {GL.glGetProgramiv(p, GL.GL_TRANSFORM_FEEDBACK_VARYING_MAX_LENGTH)}"
               f" mode: {int(GL.glGetProgramiv(p, GL.GL_TRANSFORM_FEEDBACK_BUFFER_MODE)):#x}")
    n, size, ty = ctypes.c_int(), ctypes.c_int(), ctypes.c_uint()
    name = ctypes.create_string_buffer(32)
    for i in range(4):
        check(log, f"glGetTransformFeedbackVarying({i})", GL.glGetTransformFeedbackVarying,
              p, i, 32, ctypes.byref(n), ctypes.byref(size), ctypes.byref(ty), name)
        log.append(f"  -> {name.value} {size.value} {ty.value:#x}")
    GL.glUseProgram(p)
    check(log, "glBeginTransformFeedback(no buffer)", GL.glBeginTransformFeedback, GL.GL_TRIANGLES)
    # Room for two of the strip's three triangles (7 floats a vertex).
    b = tf_buffer(0, 7 * 4 * 3 * 2 + 8)
    q = GL.glGenQueries(2)
    GL.glBeginQuery(GL.GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, q[0])
    GL.glBeginQuery(GL.GL_PRIMITIVES_GENERATED, q[1])
    check(log, "glBeginTransformFeedback(strip)", GL.glBeginTransformFeedback, GL.GL_TRIANGLE_STRIP)
    check(log, "glBeginTransformFeedback", GL.glBeginTransformFeedback, GL.GL_TRIANGLES)
    check(log, "glBeginTransformFeedback(again)", GL.glBeginTransformFeedback, GL.GL_TRIANGLES)
    GL.glEnable(GL.GL_RASTERIZER_DISCARD)
    check(log, "glDrawArrays(TRIANGLE_STRIP)", GL.glDrawArrays, GL.GL_TRIANGLE_STRIP, 0, 5)
    check(log, "glDrawArrays(POINTS)", GL.glDrawArrays, GL.GL_POINTS, 0, 5)
    check(log, "glUseProgram(0)", GL.glUseProgram, 0)
    check(log, "glBindBufferBase", GL.glBindBufferBase, GL.GL_TRANSFORM_FEEDBACK_BUFFER, 0, b)
    check(log, "glEndTransformFeedback", GL.glEndTransformFeedback)
    check(log, "glEndTransformFeedback(again)", GL.glEndTransformFeedback)
    GL.glDisable(GL.GL_RASTERIZER_DISCARD)
    GL.glEndQuery(GL.GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN)
    GL.glEndQuery(GL.GL_PRIMITIVES_GENERATED)
    log.append(f"written {GL.glGetQueryObjectuiv(q[0], GL.GL_QUERY_RESULT)}"
               f" generated {GL.glGetQueryObjectuiv(q[1], GL.GL_QUERY_RESULT)}")
    log.append(f"interleaved: {[round(x, 4) for x in tf_read(b, 7 * 6 + 2)]}")
    # Separate, a line loop into two buffers, one with a range.
    p = tf_program(log, [b"k", b"a"], GL.GL_SEPARATE_ATTRIBS)
    GL.glUseProgram(p)
    bk = tf_buffer(0, 64)
    ba = tf_buffer(1, 64)
    GL.glBindBufferRange(GL.GL_TRANSFORM_FEEDBACK_BUFFER, 1, ba, 8, 32)
    GL.glBeginTransformFeedback(GL.GL_LINES)
    check(log, "glDrawArrays(LINE_LOOP)", GL.glDrawArrays, GL.GL_LINE_LOOP, 0, 3)
    GL.glEndTransformFeedback()
    log.append(f"k: {tf_read(bk, 8, ctypes.c_int)}")
    log.append(f"a: {[round(x, 4) for x in tf_read(ba, 12)]}")
    five = varyings([b"a", b"b", b"k", b"gl_Position", b"a"])
    check(log, "glTransformFeedbackVaryings(5 separate)", GL.glTransformFeedbackVaryings, p, 5, five,
          GL.GL_SEPARATE_ATTRIBS)
    check(log, "glTransformFeedbackVaryings(bad mode)", GL.glTransformFeedbackVaryings, p, 1, five, GL.GL_FLOAT)
    return False


@scene("gl33_multisample_state", 8, 8, CORE)
def multisample_state(log):
    v = (ctypes.c_float * 2)(-1, -1)
    check(log, "glGetMultisamplefv(SAMPLE_POSITION, 0)", GL.glGetMultisamplefv, GL.GL_SAMPLE_POSITION, 0, v)
    check(log, "glGetMultisamplefv(SAMPLES)", GL.glGetMultisamplefv, GL.GL_SAMPLES, 0, v)
    log.append(f"max words: {GL.glGetIntegerv(GL.GL_MAX_SAMPLE_MASK_WORDS)} {errors()}")
    check(log, "glSampleMaski(1)", GL.glSampleMaski, 1, 5)
    x = (ctypes.c_int * 1)()
    GL.glGetIntegeri_v(GL.GL_SAMPLE_MASK_VALUE, 0, x)
    log.append(f"initial mask: {x[0]} {errors()}")
    check(log, "glSampleMaski(0)", GL.glSampleMaski, 0, 5)
    GL.glGetIntegeri_v(GL.GL_SAMPLE_MASK_VALUE, 0, x)
    log.append(f"mask: {x[0]} {errors()}")
    check(log, "glGetIntegeri_v(SAMPLE_MASK_VALUE, 1)", GL.glGetIntegeri_v, GL.GL_SAMPLE_MASK_VALUE, 1, x)
    check(log, "glEnable(SAMPLE_MASK)", GL.glEnable, GL.GL_SAMPLE_MASK)
    log.append(f"enabled: {GL.glIsEnabled(GL.GL_SAMPLE_MASK)}")
    return False


if __name__ == "__main__":
    sys.exit(main())
