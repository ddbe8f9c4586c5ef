"""Differential scenes of occlusion queries, the raster-position pixel path
(glRasterPos / glWindowPos, glDrawPixels, glBitmap, glCopyPixels) and
vertex arrays compiled into display lists: images and logs (query results,
raster-position state, error codes) against Mesa's.

Geometry is axis-aligned on pixel boundaries (an orthographic projection
of one unit per pixel) so that fragment counts do not depend on how either
implementation breaks ties on edges.
"""
import ctypes

from harness import GL, errors, main, scene
from OpenGL.raw.GL.VERSION import GL_1_0 as raw10, GL_1_5 as raw15  # noqa: E402


def pixel_ortho(w=64, h=64):
    GL.glViewport(0, 0, w, h)
    GL.glMatrixMode(GL.GL_PROJECTION)
    GL.glLoadIdentity()
    GL.glOrtho(0, w, 0, h, -1, 1)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()


def rect(x0, y0, x1, y1, z=0.0):
    GL.glBegin(GL.GL_QUADS)
    for x, y in ((x0, y0), (x1, y0), (x1, y1), (x0, y1)):
        GL.glVertex3f(x, y, z)
    GL.glEnd()


def check(log, what, f, *args):
    errors()
    r = f(*args)
    log.append(f"{what}: {errors()}")
    return r


def query_result(q):
    v = ctypes.c_uint()
    raw15.glGetQueryObjectuiv(q, GL.GL_QUERY_RESULT, ctypes.byref(v))
    return v.value


@scene("occlusion_queries")
def occlusion_queries(log):
    pixel_ortho()
    GL.glClearColor(0.1, 0.1, 0.2, 1)
    GL.glClearStencil(0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT | GL.GL_STENCIL_BUFFER_BIT)
    GL.glEnable(GL.GL_DEPTH_TEST)
    q = (ctypes.c_uint * 6)()
    raw15.glGenQueries(6, q)
    log.append(f"names: {list(q)}; is query before begin: {bool(GL.glIsQuery(q[0]))}")
    # 1: an occluder, 32x32 pixels, all visible.
    GL.glBeginQuery(GL.GL_SAMPLES_PASSED, q[0])
    cur = ctypes.c_int()
    raw15.glGetQueryiv(GL.GL_SAMPLES_PASSED, GL.GL_CURRENT_QUERY, ctypes.byref(cur))
    log.append(f"current query: {cur.value == q[0]}")
    GL.glColor3f(0.9, 0.2, 0.2)
    rect(8, 8, 40, 40, 0.5)  # z_eye = 0.5: nearer than z = -0.5
    GL.glEndQuery(GL.GL_SAMPLES_PASSED)
    # 2: a quad behind it, partly hidden; colour and depth writes off.
    GL.glColorMask(False, False, False, False)
    GL.glDepthMask(False)
    GL.glBeginQuery(GL.GL_SAMPLES_PASSED, q[1])
    rect(24, 24, 56, 56, -0.5)
    GL.glEndQuery(GL.GL_SAMPLES_PASSED)
    GL.glColorMask(True, True, True, True)
    GL.glDepthMask(True)
    # 3: stencil: mark a band, then count only inside it.
    GL.glEnable(GL.GL_STENCIL_TEST)
    GL.glStencilFunc(GL.GL_ALWAYS, 1, 0xff)
    GL.glStencilOp(GL.GL_KEEP, GL.GL_KEEP, GL.GL_REPLACE)
    GL.glColor3f(0.2, 0.8, 0.2)
    rect(0, 44, 64, 52, 0.9)
    GL.glStencilFunc(GL.GL_EQUAL, 1, 0xff)
    GL.glStencilOp(GL.GL_KEEP, GL.GL_KEEP, GL.GL_KEEP)
    GL.glDepthFunc(GL.GL_ALWAYS)
    GL.glBeginQuery(GL.GL_SAMPLES_PASSED, q[2])
    GL.glColor3f(0.2, 0.2, 0.9)
    rect(10, 0, 20, 64, 0.0)
    GL.glEndQuery(GL.GL_SAMPLES_PASSED)
    GL.glDisable(GL.GL_STENCIL_TEST)
    GL.glDepthFunc(GL.GL_LESS)
    # 4: the alpha test rejects everything.
    GL.glEnable(GL.GL_ALPHA_TEST)
    GL.glAlphaFunc(GL.GL_GREATER, 0.5)
    GL.glBeginQuery(GL.GL_SAMPLES_PASSED, q[3])
    GL.glColor4f(1, 1, 1, 0.25)
    rect(0, 0, 64, 64, 0.95)
    GL.glEndQuery(GL.GL_SAMPLES_PASSED)
    GL.glDisable(GL.GL_ALPHA_TEST)
    # 5: several draws, a scissor, and a query with a clear only.
    GL.glEnable(GL.GL_SCISSOR_TEST)
    GL.glScissor(0, 0, 16, 64)
    GL.glBeginQuery(GL.GL_SAMPLES_PASSED, q[4])
    GL.glColor3f(0.9, 0.9, 0.1)
    rect(0, 0, 64, 4, 0.95)
    rect(0, 60, 64, 64, 0.95)
    GL.glEndQuery(GL.GL_SAMPLES_PASSED)
    GL.glDisable(GL.GL_SCISSOR_TEST)
    GL.glBeginQuery(GL.GL_SAMPLES_PASSED, q[5])
    GL.glClear(GL.GL_DEPTH_BUFFER_BIT)
    GL.glEndQuery(GL.GL_SAMPLES_PASSED)
    for i in range(6):
        # Availability before the result is implementation-dependent (Mesa
        # may still be drawing); after reading the result it is true.
        n = query_result(q[i])
        avail = ctypes.c_int()
        raw15.glGetQueryObjectiv(q[i], GL.GL_QUERY_RESULT_AVAILABLE, ctypes.byref(avail))
        log.append(f"query {i + 1}: {n} samples, available {avail.value}")
    # A query reused restarts at 0; a deleted one is no longer a query.
    GL.glBeginQuery(GL.GL_SAMPLES_PASSED, q[0])
    GL.glColor3f(0.5, 0.5, 0.5)
    rect(48, 0, 64, 8, 0.99)
    GL.glEndQuery(GL.GL_SAMPLES_PASSED)
    log.append(f"query 1 reused: {query_result(q[0])} samples")
    raw15.glDeleteQueries(1, q)
    log.append(f"is query after delete: {bool(GL.glIsQuery(q[0]))}")


@scene("occlusion_query_fbo_and_lists")
def occlusion_query_fbo_and_lists(log):
    pixel_ortho()
    fb = GL.glGenFramebuffers(1)
    rb = GL.glGenRenderbuffers(2)
    GL.glBindRenderbuffer(GL.GL_RENDERBUFFER, rb[0])
    GL.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_RGBA8, 64, 64)
    GL.glBindRenderbuffer(GL.GL_RENDERBUFFER, rb[1])
    GL.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_DEPTH_COMPONENT24, 64, 64)
    GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, fb)
    GL.glFramebufferRenderbuffer(GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0,
                                 GL.GL_RENDERBUFFER, rb[0])
    GL.glFramebufferRenderbuffer(GL.GL_FRAMEBUFFER, GL.GL_DEPTH_ATTACHMENT,
                                 GL.GL_RENDERBUFFER, rb[1])
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    GL.glEnable(GL.GL_DEPTH_TEST)
    q = (ctypes.c_uint * 2)()
    raw15.glGenQueries(2, q)
    GL.glBeginQuery(GL.GL_SAMPLES_PASSED, q[0])
    rect(0, 0, 40, 20, 0.5)
    rect(20, 0, 64, 30, -0.5)
    GL.glEndQuery(GL.GL_SAMPLES_PASSED)
    GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, 0)
    log.append(f"fbo query: {query_result(q[0])} samples")
    # Begin/end compiled into a display list.
    lst = GL.glGenLists(1)
    GL.glNewList(lst, GL.GL_COMPILE)
    GL.glBeginQuery(GL.GL_SAMPLES_PASSED, q[1])
    GL.glColor3f(0.3, 0.6, 0.9)
    rect(5, 5, 15, 25, 0.0)
    GL.glEndQuery(GL.GL_SAMPLES_PASSED)
    GL.glEndList()
    log.append(f"compiled, is query: {bool(GL.glIsQuery(q[1]))}")
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    GL.glCallList(lst)
    log.append(f"list query: {query_result(q[1])} samples")


@scene("err_occlusion_queries", 8, 8)
def err_occlusion_queries(log):
    q = (ctypes.c_uint * 2)()
    v = ctypes.c_int()
    check(log, "glGenQueries(-1)", raw15.glGenQueries, -1, q)
    check(log, "glDeleteQueries(-1)", raw15.glDeleteQueries, -1, q)
    check(log, "glGenQueries(2)", raw15.glGenQueries, 2, q)
    check(log, "glBeginQuery(bad target)", raw15.glBeginQuery, GL.GL_LESS, q[0])
    check(log, "glBeginQuery(0)", raw15.glBeginQuery, GL.GL_SAMPLES_PASSED, 0)
    check(log, "glEndQuery(none active)", raw15.glEndQuery, GL.GL_SAMPLES_PASSED)
    check(log, "glGetQueryObjectiv(never begun)", raw15.glGetQueryObjectiv, q[0],
          GL.GL_QUERY_RESULT, ctypes.byref(v))
    check(log, "glBeginQuery", raw15.glBeginQuery, GL.GL_SAMPLES_PASSED, q[0])
    check(log, "glBeginQuery(second)", raw15.glBeginQuery, GL.GL_SAMPLES_PASSED, q[1])
    check(log, "glGetQueryObjectiv(active)", raw15.glGetQueryObjectiv, q[0],
          GL.GL_QUERY_RESULT, ctypes.byref(v))
    check(log, "glEndQuery(bad target)", raw15.glEndQuery, GL.GL_LESS)
    check(log, "glEndQuery", raw15.glEndQuery, GL.GL_SAMPLES_PASSED)
    check(log, "glGetQueryiv(bad target)", raw15.glGetQueryiv, GL.GL_LESS,
          GL.GL_CURRENT_QUERY, ctypes.byref(v))
    check(log, "glGetQueryiv(bad pname)", raw15.glGetQueryiv, GL.GL_SAMPLES_PASSED,
          GL.GL_LESS, ctypes.byref(v))
    check(log, "glGetQueryiv(CURRENT_QUERY)", raw15.glGetQueryiv, GL.GL_SAMPLES_PASSED,
          GL.GL_CURRENT_QUERY, ctypes.byref(v))
    log.append(f"  current: {v.value}")
    check(log, "glGetQueryiv(QUERY_COUNTER_BITS)", raw15.glGetQueryiv, GL.GL_SAMPLES_PASSED,
          GL.GL_QUERY_COUNTER_BITS, ctypes.byref(v))
    log.append(f"  counter bits: {v.value}")
    check(log, "glGetQueryObjectiv(bad pname)", raw15.glGetQueryObjectiv, q[0], GL.GL_LESS,
          ctypes.byref(v))
    check(log, "glGetQueryObjectiv(not a name)", raw15.glGetQueryObjectiv, 77,
          GL.GL_QUERY_RESULT, ctypes.byref(v))
    check(log, "glGetQueryObjectuiv(0)", raw15.glGetQueryObjectuiv, 0, GL.GL_QUERY_RESULT,
          ctypes.byref(v))
    check(log, "glBeginQuery(unused name 50)", raw15.glBeginQuery, GL.GL_SAMPLES_PASSED, 50)
    log.append(f"  is query 50: {bool(GL.glIsQuery(50))}")
    check(log, "glDeleteQueries(active)", raw15.glDeleteQueries, 1,
          (ctypes.c_uint * 1)(50))
    check(log, "glEndQuery(after deleting the active one)", raw15.glEndQuery,
          GL.GL_SAMPLES_PASSED)
    errors()
    GL.glBegin(GL.GL_POINTS)
    raw15.glBeginQuery(GL.GL_SAMPLES_PASSED, q[1])
    GL.glEnd()
    log.append(f"inside begin/end glBeginQuery: {errors()}")
    return False


if __name__ == "__main__":
    main()
