"""Differential error paths: each scene makes invalid GL 2.1 calls of one
entry-point family and logs the error each raised (glGetError drained after
every call), plus compile/link statuses and whether an info log was given
(not its wording: that is implementation-defined). compare.py requires the
logs of shaderbox and Mesa to be equal; both must also survive every call.

Checks where GL 2.1 leaves the result open, or where Mesa departs from the
spec, are left out (and named in docs/CONFORMANCE.md).
"""
import ctypes
import os
import sys

from harness import GL, SEEDS, errors, main, scene, shader, source
# After harness (it sets PyOpenGL's flags first). Raw entry points where
# PyOpenGL's wrappers would reject the invalid argument before GL sees it.
from OpenGL.GL.EXT import framebuffer_object as fbo  # noqa: E402
from OpenGL.raw.GL.VERSION import GL_1_0 as raw10, GL_1_1 as raw11, GL_1_5 as raw15  # noqa: E402
from OpenGL.raw.GL.VERSION import GL_2_0 as raw20  # noqa: E402


def text(x):
    return x.decode(errors="replace") if isinstance(x, bytes) else str(x)

c_float_p = ctypes.POINTER(ctypes.c_float)


def check(log, what, f, *args):
    """Runs f(*args) on a clean error state; logs `what: <errors>`."""
    errors()
    r = f(*args)
    log.append(f"{what}: {errors()}")
    return r


def in_begin_end(log, what, f, *args):
    """f(*args) between glBegin/glEnd: GL_INVALID_OPERATION expected."""
    errors()
    GL.glBegin(GL.GL_TRIANGLES)
    f(*args)
    GL.glEnd()
    log.append(f"inside begin/end {what}: {errors()}")


def seed(name):
    return source(os.path.join(SEEDS, name), 120)


def status_line(what, ok, log_text):
    return f"{what}: status {int(ok)}, info log {'present' if log_text.strip() else 'empty'}"


@scene("err_compile_seed_outline", 8, 8)
def compile_outline(log):
    s, ok, info = shader(GL.GL_FRAGMENT_SHADER, seed("000-outline.frag"))
    log.append(status_line("000-outline.frag (unbalanced braces)", ok, info))
    log.append(f"GL_INFO_LOG_LENGTH > 1: {GL.glGetShaderiv(s, GL.GL_INFO_LOG_LENGTH) > 1}")
    v, vok, _ = shader(GL.GL_VERTEX_SHADER, seed("000-sphere.vert"))
    p = GL.glCreateProgram()
    GL.glAttachShader(p, v)
    GL.glAttachShader(p, s)
    check(log, "link with a failed shader", GL.glLinkProgram, p)
    log.append(status_line("link", GL.glGetProgramiv(p, GL.GL_LINK_STATUS),
                           text(GL.glGetProgramInfoLog(p))))
    check(log, "glUseProgram(unlinked)", GL.glUseProgram, p)
    check(log, "glGetUniformLocation(unlinked)", GL.glGetUniformLocation, p, "perspective")
    return False


@scene("err_compile_seed_transparent", 8, 8)
def compile_transparent(log):
    s, ok, info = shader(GL.GL_FRAGMENT_SHADER, seed("000-transparent.frag"))
    log.append(status_line("000-transparent.frag (reserved %, misplaced })", ok, info))
    return False


@scene("err_compile_and_link", 8, 8)
def compile_and_link(log):
    cases = [
        ("type mismatch", GL.GL_FRAGMENT_SHADER, "void main(){ float f = vec2(1.0); gl_FragColor = vec4(f); }"),
        ("undeclared identifier", GL.GL_VERTEX_SHADER, "void main(){ gl_Position = nope; }"),
        ("syntax error", GL.GL_FRAGMENT_SHADER, "void main() { gl_FragColor = vec4(1.0) }"),
        ("valid", GL.GL_FRAGMENT_SHADER, "void main(){ gl_FragColor = vec4(1.0); }"),
    ]
    for what, kind, src in cases:
        s, ok, info = shader(kind, src)
        log.append(f"compile {what}: status {int(ok)}, info log {'present' if (not ok and info.strip()) else ('n/a' if ok else 'empty')}")
    # Link failures: no main in the fragment stage; a varying read but not
    # written; a function declared, called and defined nowhere.
    links = [
        ("no main", ["void main(){ gl_Position = ftransform(); }"],
         ["void helper(){}"]),
        ("varying not written", ["void main(){ gl_Position = ftransform(); }"],
         ["varying vec4 v; void main(){ gl_FragColor = v; }"]),
        ("undefined function", ["void main(){ gl_Position = ftransform(); }"],
         ["vec4 f(); void main(){ gl_FragColor = f(); }"]),
        ("good", ["void main(){ gl_Position = ftransform(); }"],
         ["void main(){ gl_FragColor = vec4(1.0); }"]),
    ]
    for what, vss, fss in links:
        p = GL.glCreateProgram()
        for kind, srcs in ((GL.GL_VERTEX_SHADER, vss), (GL.GL_FRAGMENT_SHADER, fss)):
            for src in srcs:
                s, _, _ = shader(kind, src)
                GL.glAttachShader(p, s)
        GL.glLinkProgram(p)
        ok = GL.glGetProgramiv(p, GL.GL_LINK_STATUS)
        info = text(GL.glGetProgramInfoLog(p))
        log.append(f"link {what}: status {int(ok)}, info log {'present' if (not ok and info.strip()) else ('n/a' if ok else 'empty')}")
        GL.glValidateProgram(p)
        log.append(f"  validate {what}: {GL.glGetProgramiv(p, GL.GL_VALIDATE_STATUS)}, {errors()}")
    return False


@scene("err_begin_end", 8, 8)
def begin_end(log):
    check(log, "glBegin(bad mode)", GL.glBegin, 0x20)
    check(log, "glEnd without glBegin", GL.glEnd)
    errors()
    GL.glBegin(GL.GL_POINTS)
    GL.glBegin(GL.GL_POINTS)
    GL.glEnd()
    log.append(f"glBegin inside glBegin: {errors()}")
    in_begin_end(log, "glClear", GL.glClear, GL.GL_COLOR_BUFFER_BIT)
    in_begin_end(log, "glEnable", GL.glEnable, GL.GL_DEPTH_TEST)
    in_begin_end(log, "glMatrixMode", GL.glMatrixMode, GL.GL_PROJECTION)
    in_begin_end(log, "glLoadIdentity", GL.glLoadIdentity)
    in_begin_end(log, "glViewport", GL.glViewport, 0, 0, 4, 4)
    in_begin_end(log, "glPushMatrix", GL.glPushMatrix)
    in_begin_end(log, "glBindTexture", GL.glBindTexture, GL.GL_TEXTURE_2D, 0)
    in_begin_end(log, "glUseProgram", GL.glUseProgram, 0)
    in_begin_end(log, "glFinish", GL.glFinish)
    in_begin_end(log, "glDepthFunc", GL.glDepthFunc, GL.GL_LESS)
    in_begin_end(log, "glBlendFunc", GL.glBlendFunc, GL.GL_ONE, GL.GL_ONE)
    in_begin_end(log, "glNewList", GL.glNewList, 1, GL.GL_COMPILE)
    in_begin_end(log, "glGenLists", GL.glGenLists, 1)
    in_begin_end(log, "glIsEnabled", GL.glIsEnabled, GL.GL_BLEND)
    in_begin_end(log, "glDrawArrays", GL.glDrawArrays, GL.GL_POINTS, 0, 0)
    in_begin_end(log, "glClearColor", GL.glClearColor, 0, 0, 0, 0)
    in_begin_end(log, "glLineWidth", GL.glLineWidth, 2.0)
    # Per-vertex calls are legal inside.
    in_begin_end(log, "glColor/glNormal/glMaterial (legal)",
                 lambda: (GL.glColor3f(1, 0, 0), GL.glNormal3f(0, 0, 1),
                          GL.glMaterialf(GL.GL_FRONT, GL.GL_SHININESS, 5.0)))
    return False


@scene("err_state", 8, 8)
def state(log):
    check(log, "glEnable(bad)", GL.glEnable, 0x1234)
    check(log, "glIsEnabled(bad)", GL.glIsEnabled, 0x1234)
    check(log, "glGetIntegerv(bad)", GL.glGetIntegerv, 0x1234, (ctypes.c_int * 16)())
    check(log, "glGetString(bad)", GL.glGetString, 0x1234)
    check(log, "glClear(bad bit)", GL.glClear, 0x1)
    check(log, "glDepthFunc(bad)", GL.glDepthFunc, GL.GL_ONE)
    check(log, "glBlendFunc(bad)", GL.glBlendFunc, GL.GL_LESS, GL.GL_ONE)
    check(log, "glBlendEquation(bad)", GL.glBlendEquation, GL.GL_ONE)
    check(log, "glAlphaFunc(bad)", GL.glAlphaFunc, GL.GL_ONE, 0.5)
    check(log, "glCullFace(bad)", GL.glCullFace, GL.GL_LESS)
    check(log, "glFrontFace(bad)", GL.glFrontFace, GL.GL_FRONT)
    check(log, "glPolygonMode(bad face)", GL.glPolygonMode, GL.GL_LESS, GL.GL_LINE)
    check(log, "glPolygonMode(bad mode)", GL.glPolygonMode, GL.GL_FRONT, GL.GL_LESS)
    check(log, "glShadeModel(bad)", GL.glShadeModel, GL.GL_LESS)
    check(log, "glStencilFunc(bad)", GL.glStencilFunc, GL.GL_ONE, 0, 0xff)
    check(log, "glStencilOp(bad)", GL.glStencilOp, GL.GL_KEEP, GL.GL_LESS, GL.GL_KEEP)
    check(log, "glHint(bad target)", GL.glHint, 0x1234, GL.GL_NICEST)
    check(log, "glHint(bad mode)", GL.glHint, GL.GL_FOG_HINT, GL.GL_LESS)
    check(log, "glLineWidth(0)", GL.glLineWidth, 0.0)
    check(log, "glPointSize(-1)", GL.glPointSize, -1.0)
    check(log, "glViewport(w < 0)", GL.glViewport, 0, 0, -1, 4)
    check(log, "glScissor(h < 0)", GL.glScissor, 0, 0, 4, -1)
    check(log, "glPixelStorei(PACK_ALIGNMENT 3)", GL.glPixelStorei, GL.GL_PACK_ALIGNMENT, 3)
    check(log, "glPixelStorei(bad)", GL.glPixelStorei, 0x1234, 1)
    check(log, "glFogi(FOG_MODE bad)", GL.glFogi, GL.GL_FOG_MODE, GL.GL_LESS)
    check(log, "glFogf(FOG_DENSITY -1)", GL.glFogf, GL.GL_FOG_DENSITY, -1.0)
    check(log, "glLightf(LIGHT0+8)", GL.glLightf, GL.GL_LIGHT0 + 8, GL.GL_SPOT_EXPONENT, 1.0)
    check(log, "glLightf(SPOT_EXPONENT 200)", GL.glLightf, GL.GL_LIGHT0, GL.GL_SPOT_EXPONENT, 200.0)
    check(log, "glLightf(SPOT_CUTOFF 100)", GL.glLightf, GL.GL_LIGHT0, GL.GL_SPOT_CUTOFF, 100.0)
    check(log, "glLightf(bad pname)", GL.glLightf, GL.GL_LIGHT0, 0x1234, 1.0)
    check(log, "glMaterialf(SHININESS 200)", GL.glMaterialf, GL.GL_FRONT, GL.GL_SHININESS, 200.0)
    check(log, "glMaterialf(bad face)", GL.glMaterialf, GL.GL_LESS, GL.GL_SHININESS, 1.0)
    check(log, "glLightModeli(bad)", GL.glLightModeli, 0x1234, 0)
    check(log, "glColorMaterial(bad)", GL.glColorMaterial, GL.GL_FRONT, GL.GL_LESS)
    check(log, "glClipPlane(bad)", GL.glClipPlane, GL.GL_LIGHT0, (ctypes.c_double * 4)(0, 0, 1, 0))
    return False


@scene("err_matrices", 8, 8)
def matrices(log):
    check(log, "glMatrixMode(bad)", GL.glMatrixMode, GL.GL_LESS)
    check(log, "glPopMatrix at depth 1", GL.glPopMatrix)
    depth = GL.glGetIntegerv(GL.GL_MAX_PROJECTION_STACK_DEPTH)
    GL.glMatrixMode(GL.GL_PROJECTION)
    errors()
    for _ in range(int(depth) - 1):
        GL.glPushMatrix()
    log.append(f"push to the max projection depth: {errors()}")
    check(log, "one push more", GL.glPushMatrix)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    check(log, "glFrustum(near 0)", GL.glFrustum, -1, 1, -1, 1, 0, 1)
    check(log, "glFrustum(left == right)", GL.glFrustum, 1, 1, -1, 1, 1, 2)
    check(log, "glOrtho(near == far)", GL.glOrtho, -1, 1, -1, 1, 1, 1)
    return False


def tex_image(level, ifmt, w, h, border, fmt, ty, data=None):
    raw10.glTexImage2D(GL.GL_TEXTURE_2D, level, ifmt, w, h, border, fmt, ty, data)


@scene("err_textures", 8, 8)
def textures(log):
    t = GL.glGenTextures(1)
    check(log, "glBindTexture(bad target)", GL.glBindTexture, GL.GL_LESS, t)
    check(log, "glBindTexture(2D)", GL.glBindTexture, GL.GL_TEXTURE_2D, t)
    check(log, "glBindTexture(1D) of a 2D texture", GL.glBindTexture, GL.GL_TEXTURE_1D, t)
    rgba = GL.GL_RGBA
    ub = GL.GL_UNSIGNED_BYTE
    check(log, "glTexImage2D(null data)", tex_image, 0, rgba, 4, 4, 0, rgba, ub)
    check(log, "glTexImage2D(level -1)", tex_image, -1, rgba, 4, 4, 0, rgba, ub)
    check(log, "glTexImage2D(width -1)", tex_image, 0, rgba, -1, 4, 0, rgba, ub)
    check(log, "glTexImage2D(border 2)", tex_image, 0, rgba, 4, 4, 2, rgba, ub)
    check(log, "glTexImage2D(bad format)", tex_image, 0, rgba, 4, 4, 0, GL.GL_LESS, ub)
    check(log, "glTexImage2D(bad type)", tex_image, 0, rgba, 4, 4, 0, rgba, GL.GL_LESS)
    check(log, "glTexImage2D(bad internal format)", tex_image, 0, 0x1234, 4, 4, 0, rgba, ub)
    check(log, "glTexImage2D(width 5: NPOT, legal)", tex_image, 0, rgba, 5, 3, 0, rgba, ub)
    check(log, "glTexImage2D(huge level)", tex_image, 40, rgba, 1, 1, 0, rgba, ub)
    check(log, "glTexImage2D(5_6_5 with RGBA)", tex_image, 0, GL.GL_RGB, 4, 4, 0, rgba,
          GL.GL_UNSIGNED_SHORT_5_6_5)
    tex_image(0, rgba, 4, 4, 0, rgba, ub)
    data = bytes(64)
    check(log, "glTexSubImage2D(in range)", GL.glTexSubImage2D, GL.GL_TEXTURE_2D, 0, 1, 1, 2, 2,
          rgba, ub, data)
    check(log, "glTexSubImage2D(out of range)", GL.glTexSubImage2D, GL.GL_TEXTURE_2D, 0, 3, 3, 2,
          2, rgba, ub, data)
    check(log, "glTexSubImage2D(undefined level)", GL.glTexSubImage2D, GL.GL_TEXTURE_2D, 1, 0,
          0, 1, 1, rgba, ub, data)
    check(log, "glTexParameteri(MIN_FILTER bad)", GL.glTexParameteri, GL.GL_TEXTURE_2D,
          GL.GL_TEXTURE_MIN_FILTER, GL.GL_LESS)
    check(log, "glTexParameteri(bad pname)", GL.glTexParameteri, GL.GL_TEXTURE_2D, 0x1234, 0)
    check(log, "glTexParameteri(bad target)", GL.glTexParameteri, GL.GL_LESS,
          GL.GL_TEXTURE_MIN_FILTER, GL.GL_LINEAR)
    check(log, "glTexEnvi(bad mode)", GL.glTexEnvi, GL.GL_TEXTURE_ENV, GL.GL_TEXTURE_ENV_MODE,
          GL.GL_LESS)
    check(log, "glTexEnvi(bad target)", GL.glTexEnvi, GL.GL_LESS, GL.GL_TEXTURE_ENV_MODE,
          GL.GL_MODULATE)
    units = max(int(GL.glGetIntegerv(GL.GL_MAX_TEXTURE_COORDS)),
                int(GL.glGetIntegerv(GL.GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS)))
    check(log, "glActiveTexture(TEXTURE0 + max units)", GL.glActiveTexture, GL.GL_TEXTURE0 + units)
    check(log, "glGenTextures(-1)", raw11.glGenTextures, -1, (ctypes.c_uint * 1)())
    check(log, "glDeleteTextures(-1)", GL.glDeleteTextures, -1, (ctypes.c_uint * 1)(t))
    check(log, "glGenerateMipmapEXT(bad target)", fbo.glGenerateMipmapEXT, GL.GL_LESS)
    return False


@scene("err_buffers_and_arrays", 8, 8)
def buffers(log):
    b = GL.glGenBuffers(1)
    check(log, "glBindBuffer(bad target)", GL.glBindBuffer, GL.GL_LESS, b)
    check(log, "glBufferData(none bound)", GL.glBufferData, GL.GL_ARRAY_BUFFER, 16, None,
          GL.GL_STATIC_DRAW)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, b)
    check(log, "glBufferData(size -1)", GL.glBufferData, GL.GL_ARRAY_BUFFER, -1, None,
          GL.GL_STATIC_DRAW)
    check(log, "glBufferData(bad usage)", GL.glBufferData, GL.GL_ARRAY_BUFFER, 16, None,
          GL.GL_LESS)
    check(log, "glBufferData(null data)", GL.glBufferData, GL.GL_ARRAY_BUFFER, 16, None,
          GL.GL_STATIC_DRAW)
    check(log, "glBufferSubData(out of range)", GL.glBufferSubData, GL.GL_ARRAY_BUFFER, 8, 16,
          bytes(16))
    check(log, "glBufferSubData(offset -1)", GL.glBufferSubData, GL.GL_ARRAY_BUFFER, -1, 4,
          bytes(4))
    check(log, "glGenBuffers(-1)", raw15.glGenBuffers, -1, (ctypes.c_uint * 1)())
    check(log, "glDrawArrays(bad mode)", GL.glDrawArrays, GL.GL_LESS, 0, 3)
    check(log, "glDrawArrays(count -1)", GL.glDrawArrays, GL.GL_TRIANGLES, 0, -1)
    check(log, "glDrawElements(bad type)", GL.glDrawElements, GL.GL_TRIANGLES, 3, GL.GL_FLOAT,
          None)
    check(log, "glDrawElements(count -1)", GL.glDrawElements, GL.GL_TRIANGLES, -1,
          GL.GL_UNSIGNED_SHORT, None)
    check(log, "glDrawRangeElements(end < start)", GL.glDrawRangeElements, GL.GL_TRIANGLES, 5, 2,
          3, GL.GL_UNSIGNED_SHORT, None)
    check(log, "glVertexPointer(size 1)", GL.glVertexPointer, 1, GL.GL_FLOAT, 0, None)
    check(log, "glVertexPointer(stride -1)", GL.glVertexPointer, 3, GL.GL_FLOAT, -1, None)
    check(log, "glVertexPointer(bad type)", GL.glVertexPointer, 3, GL.GL_UNSIGNED_BYTE, 0, None)
    check(log, "glColorPointer(size 2)", GL.glColorPointer, 2, GL.GL_FLOAT, 0, None)
    check(log, "glNormalPointer(bad type)", GL.glNormalPointer, GL.GL_UNSIGNED_BYTE, 0, None)
    check(log, "glTexCoordPointer(size 5)", GL.glTexCoordPointer, 5, GL.GL_FLOAT, 0, None)
    check(log, "glEnableClientState(bad)", GL.glEnableClientState, GL.GL_LESS)
    mx = int(GL.glGetIntegerv(GL.GL_MAX_VERTEX_ATTRIBS))
    check(log, "glVertexAttribPointer(index max)", GL.glVertexAttribPointer, mx, 4, GL.GL_FLOAT,
          GL.GL_FALSE, 0, None)
    check(log, "glVertexAttribPointer(size 5)", GL.glVertexAttribPointer, 1, 5, GL.GL_FLOAT,
          GL.GL_FALSE, 0, None)
    check(log, "glEnableVertexAttribArray(max)", GL.glEnableVertexAttribArray, mx)
    check(log, "glVertexAttrib4f(index max)", GL.glVertexAttrib4f, mx, 0, 0, 0, 1)
    check(log, "glDeleteBuffers(-1)", GL.glDeleteBuffers, -1, (ctypes.c_uint * 1)(b))
    check(log, "glIsBuffer(bound)", lambda: log.append(f"  glIsBuffer: {GL.glIsBuffer(b)}"))
    return False


@scene("err_lists", 8, 8)
def lists(log):
    check(log, "glNewList(0)", GL.glNewList, 0, GL.GL_COMPILE)
    check(log, "glNewList(bad mode)", GL.glNewList, 1, GL.GL_LESS)
    check(log, "glEndList without glNewList", GL.glEndList)
    check(log, "glGenLists(-1)", GL.glGenLists, -1)
    GL.glNewList(5, GL.GL_COMPILE)
    check(log, "glNewList inside glNewList", GL.glNewList, 6, GL.GL_COMPILE)
    # Errors of commands compiled into a list are raised at execution.
    check(log, "compiling glEnable(bad)", GL.glEnable, 0x1234)
    GL.glEndList()
    check(log, "glCallList with a bad glEnable", GL.glCallList, 5)
    check(log, "glCallList(unknown list)", GL.glCallList, 77)
    check(log, "glDeleteLists(range -1)", GL.glDeleteLists, 1, -1)
    return False


@scene("err_programs", 8, 8)
def programs(log):
    r = check(log, "glCreateShader(bad)", GL.glCreateShader, GL.GL_LESS)
    log.append(f"  returned {r}")
    check(log, "glShaderSource(unknown name)", GL.glShaderSource, 9999, ["void main(){}"])
    p = GL.glCreateProgram()
    check(log, "glCompileShader(a program)", GL.glCompileShader, p)
    check(log, "glGetShaderiv(a program)", GL.glGetShaderiv, p, GL.GL_COMPILE_STATUS)
    vs, _, _ = shader(GL.GL_VERTEX_SHADER, "attribute vec4 a; void main(){ gl_Position = a; }")
    fs, _, _ = shader(GL.GL_FRAGMENT_SHADER,
                      "uniform float f; uniform vec3 v; uniform sampler2D s; uniform float arr[3];"
                      " void main(){ gl_FragColor = vec4(v, f + arr[2]) * texture2D(s, vec2(0.5)); }")
    check(log, "glGetProgramiv(a shader)", GL.glGetProgramiv, vs, GL.GL_LINK_STATUS)
    check(log, "glGetShaderiv(bad pname)", GL.glGetShaderiv, vs, GL.GL_LESS)
    check(log, "glAttachShader(program, program)", GL.glAttachShader, p, p)
    check(log, "glAttachShader", GL.glAttachShader, p, vs)
    check(log, "glAttachShader twice", GL.glAttachShader, p, vs)
    check(log, "glDetachShader(not attached)", GL.glDetachShader, p, fs)
    GL.glAttachShader(p, fs)
    check(log, "glBindAttribLocation(gl_ prefix)", GL.glBindAttribLocation, p, 1, "gl_Vertex")
    mx = int(GL.glGetIntegerv(GL.GL_MAX_VERTEX_ATTRIBS))
    check(log, "glBindAttribLocation(index max)", GL.glBindAttribLocation, p, mx, "a")
    check(log, "glUniform1f(no current program)", GL.glUniform1f, 0, 1.0)
    check(log, "glUseProgram(unknown name)", GL.glUseProgram, 9999)
    check(log, "glLinkProgram", GL.glLinkProgram, p)
    log.append(f"  link status {GL.glGetProgramiv(p, GL.GL_LINK_STATUS)}")
    GL.glUseProgram(p)
    lf = GL.glGetUniformLocation(p, "f")
    lv = GL.glGetUniformLocation(p, "v")
    ls = GL.glGetUniformLocation(p, "s")
    la = GL.glGetUniformLocation(p, "arr")
    check(log, "glUniform1f(location -1)", GL.glUniform1f, -1, 1.0)
    check(log, "glUniform1i on a float", GL.glUniform1i, lf, 1)
    check(log, "glUniform1f on a vec3", GL.glUniform1f, lv, 1.0)
    check(log, "glUniform3f on a vec3", GL.glUniform3f, lv, 1.0, 2.0, 3.0)
    check(log, "glUniform1f on a sampler", GL.glUniform1f, ls, 1.0)
    check(log, "glUniform1i on a sampler", GL.glUniform1i, ls, 0)
    check(log, "glUniform1fv(count 2) on a non-array", GL.glUniform1fv, lf, 2,
          (ctypes.c_float * 2)(1, 2))
    check(log, "glUniform1fv(count 5) on float[3]", GL.glUniform1fv, la, 5,
          (ctypes.c_float * 5)(1, 2, 3, 4, 5))
    check(log, "glUniform1fv(count -1)", GL.glUniform1fv, la, -1, (ctypes.c_float * 1)(1))
    check(log, "glUniform1f(bogus location)", GL.glUniform1f, 9999, 1.0)
    check(log, "glUniformMatrix4fv on a float", GL.glUniformMatrix4fv, lf, 1, GL.GL_FALSE,
          (ctypes.c_float * 16)())
    out = (ctypes.c_float * 4)()
    check(log, "glGetUniformfv(bogus location)", GL.glGetUniformfv, p, 9999, out)
    n, sz, ty = ctypes.c_int(), ctypes.c_int(), ctypes.c_uint()
    name = ctypes.create_string_buffer(32)
    check(log, "glGetActiveUniform(index past the end)", raw20.glGetActiveUniform, p, 99, 32,
          ctypes.byref(n), ctypes.byref(sz), ctypes.byref(ty), name)
    check(log, "glGetAttribLocation(unknown program)", GL.glGetAttribLocation, 9999, "a")
    q = GL.glCreateProgram()
    check(log, "glGetUniformfv(unlinked)", GL.glGetUniformfv, q, 0, out)
    check(log, "glGetAttribLocation(unlinked)", GL.glGetAttribLocation, q, "a")
    check(log, "glValidateProgram(unknown)", GL.glValidateProgram, 9999)
    # Deleting: the current program lives on, flagged.
    check(log, "glDeleteProgram(current)", GL.glDeleteProgram, p)
    log.append(f"  still a program: {GL.glIsProgram(p)}, DELETE_STATUS "
               f"{GL.glGetProgramiv(p, GL.GL_DELETE_STATUS)}")
    GL.glUseProgram(0)
    log.append(f"  after glUseProgram(0): glIsProgram {GL.glIsProgram(p)}")
    check(log, "glUseProgram(deleted)", GL.glUseProgram, p)
    GL.glDeleteShader(fs)
    log.append(f"  attached shader after glDeleteShader: glIsShader {GL.glIsShader(fs)}")
    check(log, "glDeleteShader(0)", GL.glDeleteShader, 0)
    check(log, "glDeleteProgram(0)", GL.glDeleteProgram, 0)
    s2, _, _ = shader(GL.GL_VERTEX_SHADER, "void main(){ gl_Position = vec4(0.0); }")
    GL.glDeleteShader(s2)
    check(log, "glCompileShader(deleted)", GL.glCompileShader, s2)
    return False


@scene("err_framebuffers_and_reads", 8, 8)
def framebuffers(log):
    px = (ctypes.c_ubyte * 256)()
    check(log, "glReadPixels(w -1)", GL.glReadPixels, 0, 0, -1, 1, GL.GL_RGBA,
          GL.GL_UNSIGNED_BYTE, px)
    check(log, "glReadPixels(bad format)", GL.glReadPixels, 0, 0, 1, 1, GL.GL_LESS,
          GL.GL_UNSIGNED_BYTE, px)
    check(log, "glReadPixels(bad type)", raw10.glReadPixels, 0, 0, 1, 1, GL.GL_RGBA, GL.GL_LESS,
          px)
    check(log, "glReadPixels(DEPTH_COMPONENT, float)", GL.glReadPixels, 0, 0, 1, 1,
          GL.GL_DEPTH_COMPONENT, GL.GL_FLOAT, px)
    f = fbo.glGenFramebuffersEXT(1)
    check(log, "glBindFramebufferEXT(bad target)", fbo.glBindFramebufferEXT, GL.GL_LESS, f)
    check(log, "glFramebufferTexture2DEXT(default fb)", fbo.glFramebufferTexture2DEXT,
          fbo.GL_FRAMEBUFFER_EXT, fbo.GL_COLOR_ATTACHMENT0_EXT, GL.GL_TEXTURE_2D, 0, 0)
    fbo.glBindFramebufferEXT(fbo.GL_FRAMEBUFFER_EXT, f)
    st = fbo.glCheckFramebufferStatusEXT(fbo.GL_FRAMEBUFFER_EXT)
    log.append(f"empty fbo complete: {st == fbo.GL_FRAMEBUFFER_COMPLETE_EXT}")
    check(log, "glClear(incomplete fbo)", GL.glClear, GL.GL_COLOR_BUFFER_BIT)
    check(log, "glDrawArrays(incomplete fbo)", GL.glDrawArrays, GL.GL_POINTS, 0, 1)
    check(log, "glReadPixels(incomplete fbo)", GL.glReadPixels, 0, 0, 1, 1, GL.GL_RGBA,
          GL.GL_UNSIGNED_BYTE, px)
    check(log, "glFramebufferTexture2DEXT(unknown texture)", fbo.glFramebufferTexture2DEXT,
          fbo.GL_FRAMEBUFFER_EXT, fbo.GL_COLOR_ATTACHMENT0_EXT, GL.GL_TEXTURE_2D, 4321, 0)
    check(log, "glFramebufferTexture2DEXT(bad attachment)", fbo.glFramebufferTexture2DEXT,
          fbo.GL_FRAMEBUFFER_EXT, GL.GL_LESS, GL.GL_TEXTURE_2D, 0, 0)
    r = fbo.glGenRenderbuffersEXT(1)
    check(log, "glRenderbufferStorageEXT(none bound)", fbo.glRenderbufferStorageEXT,
          fbo.GL_RENDERBUFFER_EXT, GL.GL_RGBA8, 4, 4)
    fbo.glBindRenderbufferEXT(fbo.GL_RENDERBUFFER_EXT, r)
    check(log, "glRenderbufferStorageEXT(w -1)", fbo.glRenderbufferStorageEXT,
          fbo.GL_RENDERBUFFER_EXT, GL.GL_RGBA8, -1, 4)
    check(log, "glRenderbufferStorageEXT(bad format)", fbo.glRenderbufferStorageEXT,
          fbo.GL_RENDERBUFFER_EXT, GL.GL_LESS, 4, 4)
    check(log, "glRenderbufferStorageEXT", fbo.glRenderbufferStorageEXT,
          fbo.GL_RENDERBUFFER_EXT, GL.GL_RGBA8, 4, 4)
    check(log, "glFramebufferRenderbufferEXT", fbo.glFramebufferRenderbufferEXT,
          fbo.GL_FRAMEBUFFER_EXT, fbo.GL_COLOR_ATTACHMENT0_EXT, fbo.GL_RENDERBUFFER_EXT, r)
    st = fbo.glCheckFramebufferStatusEXT(fbo.GL_FRAMEBUFFER_EXT)
    log.append(f"fbo with a colour renderbuffer complete: {st == fbo.GL_FRAMEBUFFER_COMPLETE_EXT}")
    check(log, "glDeleteFramebuffersEXT(bound)", fbo.glDeleteFramebuffersEXT, 1,
          (ctypes.c_uint * 1)(f))
    log.append(f"binding after delete: {GL.glGetIntegerv(fbo.GL_FRAMEBUFFER_BINDING_EXT)}")
    return False


@scene("err_queries_buffers_attribs", 8, 8)
def queries_buffers_attribs(log):
    v = (ctypes.c_int * 4)()
    f = (ctypes.c_float * 4)()
    mx = int(GL.glGetIntegerv(GL.GL_MAX_VERTEX_ATTRIBS))
    check(log, "glGetVertexAttribiv(index max)", raw20.glGetVertexAttribiv, mx,
          GL.GL_VERTEX_ATTRIB_ARRAY_SIZE, v)
    check(log, "glGetVertexAttribiv(bad pname)", raw20.glGetVertexAttribiv, 1, GL.GL_LESS, v)
    check(log, "glGetVertexAttribfv(0, CURRENT_VERTEX_ATTRIB)", raw20.glGetVertexAttribfv, 0,
          GL.GL_CURRENT_VERTEX_ATTRIB, f)
    p = ctypes.c_void_p()
    check(log, "glGetPointerv(bad)", raw11.glGetPointerv, GL.GL_LESS, ctypes.byref(p))
    check(log, "glGetTexLevelParameteriv(level -1)", raw10.glGetTexLevelParameteriv,
          GL.GL_TEXTURE_2D, -1, GL.GL_TEXTURE_WIDTH, v)
    check(log, "glGetTexLevelParameteriv(bad target)", raw10.glGetTexLevelParameteriv,
          GL.GL_LESS, 0, GL.GL_TEXTURE_WIDTH, v)
    check(log, "glGetTexParameterfv(bad pname)", raw10.glGetTexParameterfv, GL.GL_TEXTURE_2D,
          GL.GL_LESS, f)
    check(log, "glGetTexEnvfv(bad pname)", raw10.glGetTexEnvfv, GL.GL_TEXTURE_ENV, GL.GL_LESS, f)
    check(log, "glGetTexGenfv(bad coord)", raw10.glGetTexGenfv, GL.GL_LESS,
          GL.GL_TEXTURE_GEN_MODE, f)
    px = (ctypes.c_ubyte * 64)()
    check(log, "glGetTexImage(bad format)", raw10.glGetTexImage, GL.GL_TEXTURE_2D, 0,
          GL.GL_LESS, GL.GL_UNSIGNED_BYTE, px)
    check(log, "glGetTexImage(level -1)", raw10.glGetTexImage, GL.GL_TEXTURE_2D, -1,
          GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, px)
    # Not compared: glCopyTexImage2D with border 1 (GL 2.1 allows texture
    # borders, shaderbox does not implement them: GL_INVALID_VALUE), and a
    # draw sourcing a mapped buffer (GL 2.1 §2.9.1: GL_INVALID_OPERATION,
    # which shaderbox raises; Mesa 22 draws). docs/CONFORMANCE.md.
    check(log, "glCopyTexImage2D(w -1)", raw11.glCopyTexImage2D, GL.GL_TEXTURE_2D, 0,
          GL.GL_RGBA, 0, 0, -1, 4, 0)
    check(log, "glCopyTexImage2D", raw11.glCopyTexImage2D, GL.GL_TEXTURE_2D, 0, GL.GL_RGBA,
          0, 0, 4, 4, 0)
    check(log, "glCopyTexSubImage2D(out of range)", raw11.glCopyTexSubImage2D,
          GL.GL_TEXTURE_2D, 0, 2, 2, 0, 0, 4, 4)
    check(log, "glTexSubImage1D(undefined image)", raw11.glTexSubImage1D, GL.GL_TEXTURE_1D, 0,
          0, 1, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, px)
    b = (ctypes.c_uint * 1)()
    raw15.glGenBuffers(1, b)
    check(log, "glMapBuffer(none bound)", raw15.glMapBuffer, GL.GL_ARRAY_BUFFER, GL.GL_READ_ONLY)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, b[0])
    GL.glBufferData(GL.GL_ARRAY_BUFFER, 16, None, GL.GL_STATIC_DRAW)
    check(log, "glMapBuffer(bad access)", raw15.glMapBuffer, GL.GL_ARRAY_BUFFER, GL.GL_LESS)
    check(log, "glMapBuffer", raw15.glMapBuffer, GL.GL_ARRAY_BUFFER, GL.GL_WRITE_ONLY)
    check(log, "glMapBuffer twice", raw15.glMapBuffer, GL.GL_ARRAY_BUFFER, GL.GL_WRITE_ONLY)
    check(log, "glBufferSubData(mapped)", raw15.glBufferSubData, GL.GL_ARRAY_BUFFER, 0, 4,
          px)
    check(log, "glGetBufferSubData(mapped)", raw15.glGetBufferSubData, GL.GL_ARRAY_BUFFER, 0,
          4, px)
    check(log, "glGetBufferParameteriv(MAPPED)", raw15.glGetBufferParameteriv,
          GL.GL_ARRAY_BUFFER, GL.GL_BUFFER_MAPPED, v)
    log.append(f"  mapped: {v[0]}")
    check(log, "glGetBufferParameteriv(bad)", raw15.glGetBufferParameteriv,
          GL.GL_ARRAY_BUFFER, GL.GL_LESS, v)
    r = check(log, "glUnmapBuffer", raw15.glUnmapBuffer, GL.GL_ARRAY_BUFFER)
    log.append(f"  returned {r}")
    r = check(log, "glUnmapBuffer twice", raw15.glUnmapBuffer, GL.GL_ARRAY_BUFFER)
    log.append(f"  returned {r}")
    check(log, "glGetBufferSubData(out of range)", raw15.glGetBufferSubData,
          GL.GL_ARRAY_BUFFER, 8, 16, px)
    check(log, "glPopAttrib(empty)", GL.glPopAttrib)
    check(log, "glPopClientAttrib(empty)", GL.glPopClientAttrib)
    check(log, "glPushAttrib", GL.glPushAttrib, GL.GL_ALL_ATTRIB_BITS)
    check(log, "glPopAttrib", GL.glPopAttrib)
    in_begin_end(log, "glPushAttrib", GL.glPushAttrib, GL.GL_ENABLE_BIT)
    check(log, "glRenderMode(bad)", GL.glRenderMode, GL.GL_LESS)
    check(log, "glAccum(bad op)", GL.glAccum, GL.GL_LESS, 1.0)
    check(log, "glPixelTransferf(bad)", GL.glPixelTransferf, GL.GL_LESS, 1.0)
    check(log, "glInterleavedArrays(bad format)", raw11.glInterleavedArrays, GL.GL_LESS, 0,
          None)
    check(log, "glInterleavedArrays(stride -1)", raw11.glInterleavedArrays, GL.GL_V3F, -1,
          None)
    check(log, "glIndexPointer(bad type)", raw11.glIndexPointer, GL.GL_LESS, 0, None)
    check(log, "glEdgeFlagPointer(stride -1)", raw11.glEdgeFlagPointer, -1, None)
    check(log, "glSelectBuffer(size -1)", raw10.glSelectBuffer, -1, None)
    fb = (ctypes.c_float * 4)()
    check(log, "glFeedbackBuffer(bad type)", raw10.glFeedbackBuffer, 4, GL.GL_LESS, fb)
    check(log, "glPixelMapfv(size 0)", raw10.glPixelMapfv, GL.GL_PIXEL_MAP_R_TO_R, 0, f)
    check(log, "glPixelMapfv(I_TO_R size 3)", raw10.glPixelMapfv, GL.GL_PIXEL_MAP_I_TO_R, 3, f)
    check(log, "glGetPixelMapfv(bad)", raw10.glGetPixelMapfv, GL.GL_LESS, f)
    GL.glLineStipple(2, 0x0f0f)
    log.append(f"  line stipple: {GL.glGetIntegerv(GL.GL_LINE_STIPPLE_PATTERN)}, "
               f"{GL.glGetIntegerv(GL.GL_LINE_STIPPLE_REPEAT)}")
    return False


if __name__ == "__main__":
    sys.exit(main())
