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


def fmt(v):
    return "(" + ", ".join(f"{x:.3f}" for x in v) + ")"


def raster_state(log, what):
    valid = bool(GL.glGetBooleanv(GL.GL_CURRENT_RASTER_POSITION_VALID))
    pos = GL.glGetFloatv(GL.GL_CURRENT_RASTER_POSITION)
    col = GL.glGetFloatv(GL.GL_CURRENT_RASTER_COLOR)
    tex = GL.glGetFloatv(GL.GL_CURRENT_RASTER_TEXTURE_COORDS)
    if valid:
        log.append(f"{what}: valid, window {fmt(pos)}, color {fmt(col)}, texcoord {fmt(tex)}")
    else:
        log.append(f"{what}: invalid")


@scene("raster_pos_state", 64, 48)
def raster_pos_state(log):
    raster_state(log, "initial")
    pixel_ortho(64, 48)
    GL.glColor4f(0.25, 0.5, 0.75, 1.0)
    GL.glTexCoord4f(0.5, 0.25, 0.0, 1.0)
    GL.glRasterPos2i(10, 20)
    raster_state(log, "glRasterPos2i(10, 20)")
    GL.glRasterPos3f(10.5, 20.25, 0.5)
    raster_state(log, "glRasterPos3f(10.5, 20.25, 0.5)")
    GL.glRasterPos4f(20, 10, 0.0, 2.0)
    raster_state(log, "glRasterPos4f(20, 10, 0, 2)")
    GL.glRasterPos2i(-1, 20)
    raster_state(log, "glRasterPos2i(-1, 20) (outside)")
    GL.glRasterPos3f(5, 5, 2.0)
    raster_state(log, "glRasterPos3f(5, 5, 2) (beyond far)")
    GL.glMatrixMode(GL.GL_TEXTURE)
    GL.glTranslatef(1.0, 2.0, 0.0)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glTranslatef(3.0, 4.0, 0.0)
    GL.glScalef(2.0, 2.0, 1.0)
    GL.glRasterPos2f(5, 6)
    raster_state(log, "translated, scaled, texture matrix")
    GL.glMatrixMode(GL.GL_TEXTURE)
    GL.glLoadIdentity()
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()
    GL.glEnable(GL.GL_CLIP_PLANE0)
    GL.glClipPlane(GL.GL_CLIP_PLANE0, (1.0, 0.0, 0.0, -30.0))
    GL.glRasterPos2i(20, 20)
    raster_state(log, "clip plane x >= 30, at x 20")
    GL.glRasterPos2i(40, 20)
    raster_state(log, "clip plane x >= 30, at x 40")
    GL.glDisable(GL.GL_CLIP_PLANE0)
    GL.glColor3f(1.0, 0.0, 0.5)
    GL.glWindowPos2i(-5, 7)
    raster_state(log, "glWindowPos2i(-5, 7)")
    GL.glDepthRange(0.25, 0.75)
    GL.glWindowPos3f(1.5, 2.5, 0.5)
    raster_state(log, "glWindowPos3f(1.5, 2.5, 0.5) with depth range 0.25..0.75")
    GL.glDepthRange(0.0, 1.0)
    # Lighting colours the raster position.
    GL.glEnable(GL.GL_LIGHTING)
    GL.glEnable(GL.GL_LIGHT0)
    GL.glLightfv(GL.GL_LIGHT0, GL.GL_POSITION, (0.0, 0.0, 1.0, 0.0))
    GL.glLightfv(GL.GL_LIGHT0, GL.GL_DIFFUSE, (0.5, 0.5, 0.5, 1.0))
    GL.glMaterialfv(GL.GL_FRONT_AND_BACK, GL.GL_DIFFUSE, (1.0, 0.5, 0.0, 1.0))
    GL.glNormal3f(0.0, 0.0, 1.0)
    GL.glRasterPos2i(32, 24)
    raster_state(log, "lit")
    GL.glDisable(GL.GL_LIGHTING)
    # glPushAttrib(GL_CURRENT_BIT) saves the raster position.
    GL.glPushAttrib(GL.GL_CURRENT_BIT)
    GL.glRasterPos2i(1, 1)
    GL.glPopAttrib()
    raster_state(log, "after push/pop of GL_CURRENT_BIT")
    # In a display list.
    lst = GL.glGenLists(1)
    GL.glNewList(lst, GL.GL_COMPILE)
    GL.glColor3f(0.0, 1.0, 0.0)
    GL.glRasterPos2i(7, 9)
    GL.glEndList()
    GL.glCallList(lst)
    raster_state(log, "from a display list")
    return False


def gradient(w, h, comps, scale=255):
    data = []
    for y in range(h):
        for x in range(w):
            px = [x * scale // max(w - 1, 1), y * scale // max(h - 1, 1),
                  (x + y) * scale // max(w + h - 2, 1), scale]
            data.extend(px[:comps])
    return data


@scene("draw_pixels_color")
def draw_pixels_color(log):
    pixel_ortho()
    GL.glClearColor(0.1, 0.1, 0.1, 1)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    img = (ctypes.c_ubyte * (16 * 16 * 4))(*gradient(16, 16, 4))
    GL.glRasterPos2i(2, 2)
    GL.glDrawPixels(16, 16, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, img)
    # RGB floats, unpack alignment 1 with an odd width.
    rgb = (ctypes.c_float * (7 * 5 * 3))(*[v / 255.0 for v in gradient(7, 5, 3)])
    GL.glWindowPos2i(22, 2)
    GL.glDrawPixels(7, 5, GL.GL_RGB, GL.GL_FLOAT, rgb)
    GL.glPixelStorei(GL.GL_UNPACK_ALIGNMENT, 1)
    lum = (ctypes.c_ubyte * (5 * 3))(*[40 * i % 256 for i in range(15)])
    GL.glWindowPos2i(32, 2)
    GL.glDrawPixels(5, 3, GL.GL_LUMINANCE, GL.GL_UNSIGNED_BYTE, lum)
    GL.glPixelStorei(GL.GL_UNPACK_ALIGNMENT, 4)
    bgra = (ctypes.c_ubyte * (4 * 4 * 4))(*gradient(4, 4, 4))
    GL.glWindowPos2i(40, 2)
    GL.glDrawPixels(4, 4, GL.GL_BGRA, GL.GL_UNSIGNED_BYTE, bgra)
    # Zoom, including a flip.
    GL.glPixelZoom(2.0, 3.0)
    GL.glWindowPos2i(2, 20)
    GL.glDrawPixels(8, 4, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, img)
    GL.glPixelZoom(-1.0, 1.0)
    GL.glWindowPos2i(40, 20)
    GL.glDrawPixels(16, 8, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, img)
    GL.glPixelZoom(1.0, 1.0)
    # Scale and bias.
    GL.glPixelTransferf(GL.GL_RED_SCALE, 0.5)
    GL.glPixelTransferf(GL.GL_BLUE_BIAS, 0.5)
    GL.glWindowPos2i(44, 40)
    GL.glDrawPixels(16, 16, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, img)
    GL.glPixelTransferf(GL.GL_RED_SCALE, 1.0)
    GL.glPixelTransferf(GL.GL_BLUE_BIAS, 0.0)
    # Depth test against a quad, blending, scissor.
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glColor3f(0.8, 0.8, 0.2)
    rect(2, 36, 20, 62, 0.0)
    GL.glRasterPos3f(10, 40, 0.5)  # behind the quad (window z 0.25 vs 0.5)
    GL.glDrawPixels(16, 16, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, img)
    GL.glDisable(GL.GL_DEPTH_TEST)
    GL.glEnable(GL.GL_BLEND)
    GL.glBlendFunc(GL.GL_SRC_ALPHA, GL.GL_ONE_MINUS_SRC_ALPHA)
    half = (ctypes.c_ubyte * (8 * 8 * 4))(*([200, 40, 40, 128] * 64))
    GL.glEnable(GL.GL_SCISSOR_TEST)
    GL.glScissor(0, 0, 34, 64)
    GL.glWindowPos2i(28, 44)
    GL.glDrawPixels(8, 8, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, half)
    GL.glDisable(GL.GL_SCISSOR_TEST)
    GL.glDisable(GL.GL_BLEND)
    # Outside the window on the left and an invalid raster position.
    GL.glWindowPos2i(-8, 30)
    GL.glDrawPixels(16, 4, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, img)
    GL.glRasterPos2i(-10, 30)
    GL.glDrawPixels(16, 16, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, img)
    raster_state(log, "after drawing at an invalid position")
    # Compiled into a display list: the image is copied at compile time.
    lst = GL.glGenLists(1)
    small = (ctypes.c_ubyte * (6 * 6 * 4))(*gradient(6, 6, 4))
    GL.glNewList(lst, GL.GL_COMPILE)
    GL.glWindowPos2i(56, 2)
    GL.glDrawPixels(6, 6, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, small)
    GL.glEndList()
    ctypes.memset(small, 0, ctypes.sizeof(small))
    GL.glCallList(lst)


@scene("draw_pixels_depth_stencil")
def draw_pixels_depth_stencil(log):
    pixel_ortho()
    GL.glClearColor(0, 0, 0, 1)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT | GL.GL_STENCIL_BUFFER_BIT)
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glDepthFunc(GL.GL_ALWAYS)
    # A depth ramp (colour writes off), then a flat quad at depth 0.5.
    GL.glColorMask(False, False, False, False)
    ramp = (ctypes.c_float * (32 * 32))(*[x / 31.0 for y in range(32) for x in range(32)])
    GL.glWindowPos2i(0, 0)
    GL.glDrawPixels(32, 32, GL.GL_DEPTH_COMPONENT, GL.GL_FLOAT, ramp)
    GL.glColorMask(True, True, True, True)
    GL.glDepthFunc(GL.GL_LESS)
    GL.glColor3f(0.2, 0.9, 0.4)
    rect(0, 0, 32, 32, 0.0)
    # Depth pixels drawn with the raster colour.
    GL.glDepthFunc(GL.GL_ALWAYS)
    GL.glColor3f(0.9, 0.3, 0.1)
    GL.glWindowPos2i(0, 34)
    GL.glDrawPixels(16, 8, GL.GL_DEPTH_COMPONENT, GL.GL_FLOAT, ramp)
    # A stencil pattern, then a quad through the stencil test.
    pattern = (ctypes.c_ubyte * (24 * 24))(
        *[1 if ((x // 4) + (y // 4)) % 2 else 0 for y in range(24) for x in range(24)])
    GL.glPixelStorei(GL.GL_UNPACK_ALIGNMENT, 1)
    GL.glWindowPos2i(36, 4)
    GL.glDrawPixels(24, 24, GL.GL_STENCIL_INDEX, GL.GL_UNSIGNED_BYTE, pattern)
    GL.glPixelStorei(GL.GL_UNPACK_ALIGNMENT, 4)
    GL.glEnable(GL.GL_STENCIL_TEST)
    GL.glStencilFunc(GL.GL_EQUAL, 1, 0xff)
    GL.glColor3f(0.3, 0.5, 1.0)
    rect(32, 0, 64, 32, 0.0)
    GL.glDisable(GL.GL_STENCIL_TEST)
    q = (ctypes.c_uint * 1)()
    raw15.glGenQueries(1, q)
    GL.glDepthFunc(GL.GL_LESS)
    GL.glBeginQuery(GL.GL_SAMPLES_PASSED, q[0])
    img = (ctypes.c_ubyte * (16 * 16 * 4))(*gradient(16, 16, 4))
    GL.glRasterPos3f(8, 8, 0.2)  # window z 0.4: in front where the ramp is above 0.4
    GL.glDrawPixels(16, 16, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, img)
    GL.glEndQuery(GL.GL_SAMPLES_PASSED)
    log.append(f"samples passed by glDrawPixels: {query_result(q[0])}")


GLYPHS = {
    "A": [0x18, 0x24, 0x42, 0x7e, 0x42, 0x42, 0x42, 0x00],
    "B": [0x7c, 0x42, 0x42, 0x7c, 0x42, 0x42, 0x7c, 0x00],
    "C": [0x3c, 0x42, 0x40, 0x40, 0x40, 0x42, 0x3c, 0x00],
    "x": [0x00, 0x00, 0x42, 0x24, 0x18, 0x24, 0x42, 0x00],
}


@scene("bitmap_text")
def bitmap_text(log):
    pixel_ortho()
    GL.glClearColor(0.05, 0.05, 0.15, 1)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT)
    GL.glPixelStorei(GL.GL_UNPACK_ALIGNMENT, 1)
    base = GL.glGenLists(128)
    for ch, rows in GLYPHS.items():
        bits = (ctypes.c_ubyte * 8)(*reversed(rows))  # bottom row first
        GL.glNewList(base + ord(ch), GL.GL_COMPILE)
        GL.glBitmap(8, 8, 0.0, 0.0, 9.0, 0.0, bits)
        GL.glEndList()
    GL.glListBase(base)
    GL.glColor3f(1.0, 1.0, 0.2)
    GL.glRasterPos2i(2, 50)
    text = b"ABCxABC"
    GL.glCallLists(len(text), GL.GL_UNSIGNED_BYTE, text)
    raster_state(log, "after the first line")
    GL.glColor3f(0.2, 1.0, 1.0)  # the colour is latched by glRasterPos
    GL.glWindowPos2i(2, 38)
    GL.glCallLists(3, GL.GL_UNSIGNED_BYTE, b"CBA")
    # Origin offsets, a 12-bit wide bitmap (two bytes a row), alignment 4.
    GL.glPixelStorei(GL.GL_UNPACK_ALIGNMENT, 4)
    wide = (ctypes.c_ubyte * (4 * 6))(*([0xf0, 0xf0, 0, 0, 0x0f, 0x0f, 0, 0] * 3))
    GL.glColor3f(1.0, 0.3, 0.3)
    GL.glWindowPos2i(20, 20)
    GL.glBitmap(12, 6, 2.0, 1.0, 0.0, -10.0, wide)
    GL.glBitmap(12, 6, -3.0, 0.0, 0.0, 0.0, wide)
    # glBitmap with no image moves the raster position only.
    GL.glBitmap(0, 0, 0.0, 0.0, 5.5, 2.0, None)
    raster_state(log, "after the moves")
    # Stencil-tested bitmaps. They do not overlap: Mesa's state tracker
    # merges consecutive glBitmap calls into one cached image (one
    # fragment where they overlap), where GL 2.1 §3.7 makes each bitmap
    # its own fragments (shaderbox).
    GL.glEnable(GL.GL_STENCIL_TEST)
    GL.glClear(GL.GL_STENCIL_BUFFER_BIT)
    GL.glStencilFunc(GL.GL_ALWAYS, 1, 0xff)
    GL.glStencilOp(GL.GL_KEEP, GL.GL_KEEP, GL.GL_INCR)
    GL.glColor3f(0.5, 1.0, 0.5)
    GL.glWindowPos2i(24, 2)
    for i in range(3):
        GL.glBitmap(12, 6, 0.0, 0.0, 13.0, 1.0, wide)
    GL.glDisable(GL.GL_STENCIL_TEST)
    st = (ctypes.c_ubyte * (40 * 10))()
    GL.glReadPixels(24, 2, 40, 10, GL.GL_STENCIL_INDEX, GL.GL_UNSIGNED_BYTE, st)
    log.append(f"stencil after three bitmaps: {sum(st)}")


@scene("copy_pixels")
def copy_pixels(log):
    pixel_ortho()
    GL.glClearColor(0.0, 0.0, 0.0, 1)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT | GL.GL_STENCIL_BUFFER_BIT)
    GL.glBegin(GL.GL_QUADS)
    GL.glColor3f(1, 0, 0); GL.glVertex2f(0, 0)
    GL.glColor3f(0, 1, 0); GL.glVertex2f(16, 0)
    GL.glColor3f(0, 0, 1); GL.glVertex2f(16, 16)
    GL.glColor3f(1, 1, 1); GL.glVertex2f(0, 16)
    GL.glEnd()
    GL.glRasterPos2i(20, 0)
    GL.glCopyPixels(0, 0, 16, 16, GL.GL_COLOR)
    # A zoom with no pixel center on a column boundary in range: where
    # one lies exactly on a boundary, Mesa (a textured quad) may round
    # either way.
    GL.glPixelZoom(1.37, 2.0)
    GL.glWindowPos2i(40, 0)
    GL.glCopyPixels(0, 0, 16, 16, GL.GL_COLOR)
    GL.glPixelZoom(1.0, 1.0)
    # Overlapping copy onto itself, shifted.
    GL.glWindowPos2i(4, 4)
    GL.glCopyPixels(0, 0, 12, 12, GL.GL_COLOR)
    # Partly outside the window (reads outside are undefined: kept inside).
    GL.glWindowPos2i(56, 40)
    GL.glCopyPixels(0, 0, 16, 16, GL.GL_COLOR)
    # Depth: draw a tilted quad's depth, copy it, then draw through it.
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glColorMask(False, False, False, False)
    GL.glBegin(GL.GL_QUADS)
    GL.glVertex3f(0, 40, -0.9); GL.glVertex3f(16, 40, 0.9)
    GL.glVertex3f(16, 56, 0.9); GL.glVertex3f(0, 56, -0.9)
    GL.glEnd()
    GL.glColorMask(True, True, True, True)
    GL.glDepthFunc(GL.GL_ALWAYS)
    GL.glWindowPos2i(20, 40)
    GL.glCopyPixels(0, 40, 16, 16, GL.GL_DEPTH)
    GL.glDepthFunc(GL.GL_LESS)
    GL.glColor3f(1.0, 0.6, 0.0)
    rect(18, 38, 38, 58, 0.0)
    # Stencil copy.
    GL.glEnable(GL.GL_STENCIL_TEST)
    GL.glStencilFunc(GL.GL_ALWAYS, 3, 0xff)
    GL.glStencilOp(GL.GL_KEEP, GL.GL_KEEP, GL.GL_REPLACE)
    GL.glDisable(GL.GL_DEPTH_TEST)
    GL.glColorMask(False, False, False, False)
    rect(40, 40, 46, 50)
    GL.glColorMask(True, True, True, True)
    GL.glWindowPos2i(48, 40)
    GL.glCopyPixels(40, 40, 8, 12, GL.GL_STENCIL)
    GL.glStencilFunc(GL.GL_EQUAL, 3, 0xff)
    GL.glStencilOp(GL.GL_KEEP, GL.GL_KEEP, GL.GL_KEEP)
    GL.glColor3f(0.6, 0.2, 1.0)
    rect(38, 38, 64, 56)
    GL.glDisable(GL.GL_STENCIL_TEST)


@scene("err_pixel_path", 8, 8)
def err_pixel_path(log):
    px = (ctypes.c_ubyte * 256)()
    check(log, "glDrawPixels(w -1)", raw10.glDrawPixels, -1, 1, GL.GL_RGBA,
          GL.GL_UNSIGNED_BYTE, px)
    check(log, "glDrawPixels(bad format)", raw10.glDrawPixels, 1, 1, GL.GL_LESS,
          GL.GL_UNSIGNED_BYTE, px)
    check(log, "glDrawPixels(bad type)", raw10.glDrawPixels, 1, 1, GL.GL_RGBA, GL.GL_LESS, px)
    check(log, "glDrawPixels(RGBA, 5_6_5)", raw10.glDrawPixels, 1, 1, GL.GL_RGBA,
          GL.GL_UNSIGNED_SHORT_5_6_5, px)
    check(log, "glDrawPixels(RGBA, BITMAP)", raw10.glDrawPixels, 1, 1, GL.GL_RGBA,
          GL.GL_BITMAP, px)
    check(log, "glDrawPixels(RGB, 5_6_5)", raw10.glDrawPixels, 1, 1, GL.GL_RGB,
          GL.GL_UNSIGNED_SHORT_5_6_5, px)
    check(log, "glDrawPixels(DEPTH_COMPONENT)", raw10.glDrawPixels, 1, 1,
          GL.GL_DEPTH_COMPONENT, GL.GL_FLOAT, px)
    check(log, "glBitmap(h -1)", raw10.glBitmap, 1, -1, 0.0, 0.0, 0.0, 0.0, px)
    check(log, "glBitmap", raw10.glBitmap, 8, 1, 0.0, 0.0, 1.0, 0.0, px)
    check(log, "glCopyPixels(bad type)", raw10.glCopyPixels, 0, 0, 1, 1, GL.GL_RGBA)
    check(log, "glCopyPixels(w -1)", raw10.glCopyPixels, 0, 0, -1, 1, GL.GL_COLOR)
    check(log, "glCopyPixels(DEPTH)", raw10.glCopyPixels, 0, 0, 2, 2, GL.GL_DEPTH)
    check(log, "glRasterPos2f", GL.glRasterPos2f, 0.0, 0.0)
    check(log, "glWindowPos2f", GL.glWindowPos2f, 1.0, 1.0)
    # A framebuffer object without depth or stencil attachments.
    fb = GL.glGenFramebuffers(1)
    rb = GL.glGenRenderbuffers(1)
    GL.glBindRenderbuffer(GL.GL_RENDERBUFFER, rb)
    GL.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_RGBA8, 8, 8)
    GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, fb)
    GL.glFramebufferRenderbuffer(GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0,
                                 GL.GL_RENDERBUFFER, rb)
    check(log, "FBO glDrawPixels(DEPTH_COMPONENT)", raw10.glDrawPixels, 1, 1,
          GL.GL_DEPTH_COMPONENT, GL.GL_FLOAT, px)
    check(log, "FBO glDrawPixels(STENCIL_INDEX)", raw10.glDrawPixels, 1, 1,
          GL.GL_STENCIL_INDEX, GL.GL_UNSIGNED_BYTE, px)
    check(log, "FBO glCopyPixels(DEPTH)", raw10.glCopyPixels, 0, 0, 1, 1, GL.GL_DEPTH)
    check(log, "FBO glCopyPixels(COLOR)", raw10.glCopyPixels, 0, 0, 1, 1, GL.GL_COLOR)
    GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, 0)
    for what, f, args in (
            ("glRasterPos2f", GL.glRasterPos2f, (0.0, 0.0)),
            ("glWindowPos2f", GL.glWindowPos2f, (0.0, 0.0)),
            ("glDrawPixels", raw10.glDrawPixels, (1, 1, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, px)),
            ("glBitmap", raw10.glBitmap, (1, 1, 0.0, 0.0, 0.0, 0.0, px)),
            ("glCopyPixels", raw10.glCopyPixels, (0, 0, 1, 1, GL.GL_COLOR))):
        errors()
        GL.glBegin(GL.GL_POINTS)
        f(*args)
        GL.glEnd()
        log.append(f"inside begin/end {what}: {errors()}")
    return False


@scene("array_draws_in_lists")
def array_draws_in_lists(log):
    import math
    GL.glClearColor(0.1, 0.1, 0.1, 1)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    GL.glMatrixMode(GL.GL_PROJECTION)
    GL.glLoadIdentity()
    GL.glOrtho(-2, 2, -2, 2, -5, 5)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()
    GL.glEnable(GL.GL_DEPTH_TEST)
    # A lit sphere from client arrays (positions = normals, colours),
    # drawn by glDrawElements into a list.
    slices, stacks = 16, 10
    pos, col = [], []
    for i in range(stacks + 1):
        a = math.pi * i / stacks
        for j in range(slices + 1):
            b = 2 * math.pi * j / slices
            n = (math.sin(a) * math.cos(b), math.sin(a) * math.sin(b), math.cos(a))
            pos.extend(n)
            col.extend((0.5 + 0.5 * n[0], 0.5 + 0.5 * n[1], 0.8, 1.0))
    idx = []
    for i in range(stacks):
        for j in range(slices):
            a, b = i * (slices + 1) + j, (i + 1) * (slices + 1) + j
            idx.extend((a, b, b + 1, a, b + 1, a + 1))
    P = (ctypes.c_float * len(pos))(*pos)
    C = (ctypes.c_float * len(col))(*col)
    I = (ctypes.c_ushort * len(idx))(*idx)
    GL.glEnableClientState(GL.GL_VERTEX_ARRAY)
    GL.glEnableClientState(GL.GL_NORMAL_ARRAY)
    GL.glEnableClientState(GL.GL_COLOR_ARRAY)
    GL.glVertexPointer(3, GL.GL_FLOAT, 0, P)
    GL.glNormalPointer(GL.GL_FLOAT, 0, P)
    GL.glColorPointer(4, GL.GL_FLOAT, 0, C)
    base = GL.glGenLists(4)
    GL.glNewList(base, GL.GL_COMPILE)
    GL.glDrawElements(GL.GL_TRIANGLES, len(idx), GL.GL_UNSIGNED_SHORT, I)
    GL.glEndList()
    # glDrawArrays and glMultiDrawArrays of a strip, glDrawRangeElements.
    strip = (ctypes.c_float * 16)(-0.5, -0.25, 0.5, -0.25, -0.5, 0.25, 0.5, 0.25,
                                  -0.25, -0.5, 0.25, -0.5, -0.25, 0.5, 0.25, 0.5)
    GL.glDisableClientState(GL.GL_NORMAL_ARRAY)
    GL.glDisableClientState(GL.GL_COLOR_ARRAY)
    GL.glVertexPointer(2, GL.GL_FLOAT, 0, strip)
    GL.glNewList(base + 1, GL.GL_COMPILE)
    GL.glColor3f(1.0, 0.5, 0.1)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 0, 4)
    GL.glEndList()
    GL.glNewList(base + 2, GL.GL_COMPILE)
    firsts = (ctypes.c_int * 2)(0, 4)
    counts = (ctypes.c_int * 2)(4, 4)
    GL.glColor3f(0.2, 0.9, 0.3)
    GL.glMultiDrawArrays(GL.GL_TRIANGLE_FAN, firsts, counts, 2)
    ri = (ctypes.c_ubyte * 3)(4, 5, 6)
    GL.glColor3f(0.9, 0.9, 0.9)
    GL.glDrawRangeElements(GL.GL_TRIANGLES, 4, 6, 3, GL.GL_UNSIGNED_BYTE, ri)
    GL.glEndList()
    # From a vertex buffer object, compiled and executed.
    vbo = GL.glGenBuffers(1)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, vbo)
    GL.glBufferData(GL.GL_ARRAY_BUFFER, ctypes.sizeof(strip), strip, GL.GL_STATIC_DRAW)
    GL.glVertexPointer(2, GL.GL_FLOAT, 0, None)
    GL.glNewList(base + 3, GL.GL_COMPILE_AND_EXECUTE)
    GL.glPushMatrix()
    GL.glTranslatef(-1.4, 1.4, 1.0)
    GL.glColor3f(0.3, 0.3, 1.0)
    GL.glDrawArrays(GL.GL_TRIANGLE_STRIP, 4, 4)
    GL.glPopMatrix()
    GL.glEndList()
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, 0)
    # The client memory changes after compiling: the lists keep the values.
    for arr in (P, C, strip):
        ctypes.memset(arr, 0, ctypes.sizeof(arr))
    GL.glDisableClientState(GL.GL_VERTEX_ARRAY)
    GL.glEnable(GL.GL_LIGHTING)
    GL.glEnable(GL.GL_LIGHT0)
    GL.glEnable(GL.GL_COLOR_MATERIAL)
    GL.glLightfv(GL.GL_LIGHT0, GL.GL_POSITION, (0.5, 0.5, 1.0, 0.0))
    GL.glPushMatrix()
    GL.glTranslatef(0.6, -0.6, 0.0)
    GL.glCallList(base)
    GL.glPopMatrix()
    GL.glDisable(GL.GL_LIGHTING)
    GL.glPushMatrix()
    GL.glTranslatef(-1.2, -1.2, 2.0)
    GL.glCallList(base + 1)
    GL.glTranslatef(0.02, 2.23, 0.0)
    GL.glCallList(base + 2)
    GL.glPopMatrix()
    log.append(f"errors after replay: {errors()}")


if __name__ == "__main__":
    main()
