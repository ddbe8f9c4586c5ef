"""Shared harness of the differential scene scripts (compare.py runs each
script once on shaderbox's libOSMesa and once on Mesa's).

A scene script registers scenes with @scene("name") and calls main(). Run as
`python3 SCRIPT OUTDIR [NAME...]`, it renders every scene (or the named ones)
in a fresh OSMesa context of its own size (with PYOPENGL_PLATFORM=egl, an
EGL context current on a pbuffer of that size) and writes into OUTDIR:
  NAME.rgba  the RGBA8 pixels, bottom row first, preceded by an 8-byte
             header (width, height as little-endian u32) — compared with a
             tolerance;
  NAME.txt   the scene's log lines (error codes, statuses, query results) —
             compared exactly, so a log must only hold what GL specifies
             (not info-log wording, which is implementation-defined).
A scene that raises writes NAME.fail with the traceback (compare.py then
fails the scene). GL error checking of PyOpenGL is off: scenes read
glGetError themselves, and every image scene logs the error state at its end.
"""
import ctypes
import os
import struct
import sys
import traceback

import OpenGL

OpenGL.ERROR_CHECKING = False
OpenGL.ERROR_ON_COPY = False

# The context API: OSMesa, or EGL when PyOpenGL's platform is EGL (the
# scenes draw into a pbuffer then; compare.py --egl).
EGL_MODE = os.environ.get("PYOPENGL_PLATFORM") == "egl"
if EGL_MODE:
    # With error checking off, PyOpenGL 3.1's EGL wrappers look for an
    # `_error_checker` its _errors module then leaves undefined.
    from OpenGL.raw.EGL import _errors as _egl_errors  # noqa: E402

    if not hasattr(_egl_errors, "_error_checker"):
        _egl_errors._error_checker = None
    from OpenGL import EGL  # noqa: E402
else:
    from OpenGL import osmesa  # noqa: E402
from OpenGL import GL, arrays  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", "..", ".."))
SHADERS = os.path.join(ROOT, "shaders")
SEEDS = os.path.join(ROOT, "crates", "glsl", "tests", "seeds")

_SCENES = []


def scene(name, w=64, h=64, version=None):
    """Registers a scene function f(log) rendering into a w x h context;
    `log` is a list the scene appends text lines to. `version`, e.g.
    (3, 3, "core"): the context comes from OSMesaCreateContextAttribs with
    that version and profile ("core" or "compat") instead of
    OSMesaCreateContextExt."""
    def reg(f):
        _SCENES.append((name, w, h, f, version))
        return f
    return reg


def source(path, version=None):
    """A shader file's text, with `#version N` put first when given (the
    seed files carry their version in a `// version:` header only)."""
    with open(path) as f:
        text = f.read()
    return f"#version {version}\n{text}" if version else text


def lib(name):
    """The text of the shader library's shaders/NAME."""
    return source(os.path.join(SHADERS, name))


def shader(kind, src):
    """Compiles; returns (shader, compile status, info log)."""
    s = GL.glCreateShader(kind)
    GL.glShaderSource(s, src)
    GL.glCompileShader(s)
    ok = GL.glGetShaderiv(s, GL.GL_COMPILE_STATUS)
    log = GL.glGetShaderInfoLog(s)
    return s, bool(ok), log.decode(errors="replace") if isinstance(log, bytes) else str(log)


def program(vs_srcs, fs_srcs, attribs=()):
    """Compiles and links (with `attribs`, (location, name) pairs, bound
    first), uses and returns the program; raises with the info logs on
    failure."""
    p = GL.glCreateProgram()
    for kind, srcs in ((GL.GL_VERTEX_SHADER, vs_srcs), (GL.GL_FRAGMENT_SHADER, fs_srcs)):
        for src in srcs:
            s, ok, log = shader(kind, src)
            if not ok:
                raise RuntimeError(f"compile failed: {log}")
            GL.glAttachShader(p, s)
    for loc, name in attribs:
        GL.glBindAttribLocation(p, loc, name)
    GL.glLinkProgram(p)
    if not GL.glGetProgramiv(p, GL.GL_LINK_STATUS):
        raise RuntimeError(f"link failed: {GL.glGetProgramInfoLog(p)}")
    GL.glUseProgram(p)
    return p


def uniform(p, name, *vals, count=None, optional=False):
    """Sets a float uniform (1-4 components, or a float array via count);
    raises when it is not active unless `optional`."""
    loc = GL.glGetUniformLocation(p, name)
    if loc < 0:
        if optional:
            return
        raise RuntimeError(f"uniform {name} not active")
    if count is not None:
        GL.glUniform1fv(loc, count, (ctypes.c_float * count)(*vals))
    else:
        getattr(GL, f"glUniform{len(vals)}f")(loc, *vals)


def uniform_i(p, name, v):
    """Sets an int (or sampler) uniform; raises when it is not active."""
    loc = GL.glGetUniformLocation(p, name)
    if loc < 0:
        raise RuntimeError(f"uniform {name} not active")
    GL.glUniform1i(loc, v)


def error_name(e):
    return {
        0: "GL_NO_ERROR",
        0x0500: "GL_INVALID_ENUM",
        0x0501: "GL_INVALID_VALUE",
        0x0502: "GL_INVALID_OPERATION",
        0x0503: "GL_STACK_OVERFLOW",
        0x0504: "GL_STACK_UNDERFLOW",
        0x0505: "GL_OUT_OF_MEMORY",
        0x0506: "GL_INVALID_FRAMEBUFFER_OPERATION",
    }.get(int(e), hex(int(e)))


def errors():
    """Every error flag set, drained (GL may keep one per kind)."""
    out = []
    for _ in range(8):
        e = GL.glGetError()
        if not e:
            break
        out.append(error_name(e))
    return " ".join(out) or "GL_NO_ERROR"


def _context(version):
    if version is None:
        return osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 24, 8, 0, None)
    major, minor, profile = version
    prof = osmesa.OSMESA_CORE_PROFILE if profile == "core" else osmesa.OSMESA_COMPAT_PROFILE
    attribs = [osmesa.OSMESA_FORMAT, osmesa.OSMESA_RGBA, osmesa.OSMESA_DEPTH_BITS, 24,
               osmesa.OSMESA_STENCIL_BITS, 8, osmesa.OSMESA_PROFILE, prof,
               osmesa.OSMESA_CONTEXT_MAJOR_VERSION, major,
               osmesa.OSMESA_CONTEXT_MINOR_VERSION, minor, 0]
    return osmesa.OSMesaCreateContextAttribs((ctypes.c_int * len(attribs))(*attribs), None)


_EGL_DISPLAY = None


def _egl_display():
    """The EGL display, initialized once (EGL_DEFAULT_DISPLAY: compare.py
    sets EGL_PLATFORM=surfaceless, which Mesa reads and shaderbox's
    headless library does not need)."""
    global _EGL_DISPLAY
    if _EGL_DISPLAY is None:
        dpy = EGL.eglGetDisplay(EGL.EGL_DEFAULT_DISPLAY)
        if not dpy or not EGL.eglInitialize(dpy, None, None):
            raise RuntimeError(f"eglInitialize failed (0x{EGL.eglGetError():x})")
        if not EGL.eglBindAPI(EGL.EGL_OPENGL_API):
            raise RuntimeError("eglBindAPI(EGL_OPENGL_API) failed")
        _EGL_DISPLAY = dpy
    return _EGL_DISPLAY


def _egl_current(w, h, version):
    """An EGL context (the `version` of scene(); none: EGL's default
    context) current on a w x h RGBA8 pbuffer with 24 depth and 8 stencil
    bits: (display, context, surface)."""
    dpy = _egl_display()
    want = [EGL.EGL_SURFACE_TYPE, EGL.EGL_PBUFFER_BIT, EGL.EGL_RENDERABLE_TYPE,
            EGL.EGL_OPENGL_BIT, EGL.EGL_RED_SIZE, 8, EGL.EGL_GREEN_SIZE, 8,
            EGL.EGL_BLUE_SIZE, 8, EGL.EGL_ALPHA_SIZE, 8, EGL.EGL_DEPTH_SIZE, 24,
            EGL.EGL_STENCIL_SIZE, 8, EGL.EGL_NONE]
    configs = (EGL.EGLConfig * 1)()
    n = EGL.EGLint()
    if not EGL.eglChooseConfig(dpy, (EGL.EGLint * len(want))(*want), configs, 1,
                               ctypes.pointer(n)) or n.value < 1:
        raise RuntimeError("eglChooseConfig found no RGBA8 pbuffer config")
    attribs = []
    if version is not None:
        major, minor, profile = version
        bit = (EGL.EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT if profile == "core"
               else EGL.EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT)
        attribs = [EGL.EGL_CONTEXT_MAJOR_VERSION, major, EGL.EGL_CONTEXT_MINOR_VERSION, minor,
                   EGL.EGL_CONTEXT_OPENGL_PROFILE_MASK, bit]
    attribs.append(EGL.EGL_NONE)
    ctx = EGL.eglCreateContext(dpy, configs[0], EGL.EGL_NO_CONTEXT,
                               (EGL.EGLint * len(attribs))(*attribs))
    if not ctx:
        raise RuntimeError(f"eglCreateContext failed (0x{EGL.eglGetError():x})")
    size = (EGL.EGLint * 5)(EGL.EGL_WIDTH, w, EGL.EGL_HEIGHT, h, EGL.EGL_NONE)
    surface = EGL.eglCreatePbufferSurface(dpy, configs[0], size)
    if not surface or not EGL.eglMakeCurrent(dpy, surface, surface, ctx):
        raise RuntimeError(f"pbuffer {w}x{h} failed (0x{EGL.eglGetError():x})")
    return dpy, ctx, surface


def _scene(name, w, h, f, outdir):
    """Runs scene f in the current context and writes its files."""
    log = []
    image = f(log)
    log.append(f"end: {errors()}")
    if image is not False:
        GL.glFinish()
        px = bytes(GL.glReadPixels(0, 0, w, h, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE))
        with open(os.path.join(outdir, name + ".rgba"), "wb") as o:
            o.write(struct.pack("<II", w, h) + px)
    with open(os.path.join(outdir, name + ".txt"), "w") as o:
        o.write("\n".join(log) + "\n")


def _run(name, w, h, f, outdir, version=None):
    if EGL_MODE:
        dpy, ctx, surface = _egl_current(w, h, version)
        try:
            _scene(name, w, h, f, outdir)
        finally:
            EGL.eglMakeCurrent(dpy, EGL.EGL_NO_SURFACE, EGL.EGL_NO_SURFACE, EGL.EGL_NO_CONTEXT)
            EGL.eglDestroySurface(dpy, surface)
            EGL.eglDestroyContext(dpy, ctx)
        return
    ctx = _context(version)
    if not ctx:
        raise RuntimeError("OSMesaCreateContext failed")
    buf = arrays.GLubyteArray.zeros((h, w, 4))
    try:
        if not osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_UNSIGNED_BYTE, w, h):
            raise RuntimeError("OSMesaMakeCurrent failed")
        _scene(name, w, h, f, outdir)
    finally:
        osmesa.OSMesaDestroyContext(ctx)


def main():
    outdir = sys.argv[1]
    only = set(sys.argv[2:])
    os.makedirs(outdir, exist_ok=True)
    for name, w, h, f, version in _SCENES:
        if only and name not in only:
            continue
        try:
            _run(name, w, h, f, outdir, version)
        except Exception:
            with open(os.path.join(outdir, name + ".fail"), "w") as o:
                o.write(traceback.format_exc())
    return 0


# ---- geometry and state shared by the scene scripts ----

def perspective(fovy_half=0.5, near=1.0, far=10.0, aspect=1.0):
    GL.glMatrixMode(GL.GL_PROJECTION)
    GL.glLoadIdentity()
    GL.glFrustum(-fovy_half * aspect, fovy_half * aspect, -fovy_half, fovy_half, near, far)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()


def ortho(half=1.0, near=-10.0, far=10.0):
    GL.glMatrixMode(GL.GL_PROJECTION)
    GL.glLoadIdentity()
    GL.glOrtho(-half, half, -half, half, near, far)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()


def tess_sphere(r, slices=20, stacks=14, color=None, texcoords=False):
    """An immediate-mode sphere of quad strips with normals (and per-vertex
    colours from color(n) or texture coordinates (u, v))."""
    import math
    for i in range(stacks):
        a0, a1 = math.pi * i / stacks, math.pi * (i + 1) / stacks
        GL.glBegin(GL.GL_QUAD_STRIP)
        for j in range(slices + 1):
            b = 2 * math.pi * j / slices
            for a in (a0, a1):
                n = (math.sin(a) * math.cos(b), math.sin(a) * math.sin(b), math.cos(a))
                if color:
                    GL.glColor4f(*color(n))
                if texcoords:
                    GL.glMultiTexCoord2f(GL.GL_TEXTURE0, 2.0 * j / slices, a / math.pi)
                    GL.glMultiTexCoord2f(GL.GL_TEXTURE1, 3.0 * j / slices, 2.0 * a / math.pi)
                GL.glNormal3f(*n)
                GL.glVertex3f(r * n[0], r * n[1], r * n[2])
        GL.glEnd()


# Eight directional lights (eye space, w = 0): direction, diffuse colour.
LIGHTS = [
    ((-1.0, 1.0, 2.0), (0.8, 0.8, 0.75)),
    ((1.0, -0.5, 1.0), (0.3, 0.35, 0.5)),
    ((0.0, 1.0, 0.3), (0.4, 0.1, 0.1)),
    ((1.0, 1.0, 0.5), (0.1, 0.4, 0.1)),
    ((-1.0, -1.0, 0.5), (0.1, 0.1, 0.4)),
    ((0.1, 0.15, 1.0), (0.2, 0.2, 0.2)),
    ((2.0, 0.2, 1.0), (0.3, 0.2, 0.0)),
    ((-0.3, -1.0, 1.0), (0.0, 0.2, 0.3)),
]


def lights(enabled, ambient=0.05, specular=0.6):
    """Sets the eight LIGHTS (with an identity model-view: eye space) and
    enables those in `enabled`; returns the light_enabled[8] values."""
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glPushMatrix()
    GL.glLoadIdentity()
    for i, (d, col) in enumerate(LIGHTS):
        light = GL.GL_LIGHT0 + i
        GL.glLightfv(light, GL.GL_POSITION, (d[0], d[1], d[2], 0.0))
        GL.glLightfv(light, GL.GL_AMBIENT, (ambient, ambient, ambient, 1.0))
        GL.glLightfv(light, GL.GL_DIFFUSE, (col[0], col[1], col[2], 1.0))
        GL.glLightfv(light, GL.GL_SPECULAR, (specular, specular, specular, 1.0))
        (GL.glEnable if i in enabled else GL.glDisable)(light)
    GL.glPopMatrix()
    return [1.0 if i in enabled else 0.0 for i in range(8)]


def material(face=GL.GL_FRONT_AND_BACK, ambient=(0.3, 0.3, 0.3, 1.0),
             diffuse=(0.8, 0.8, 0.8, 1.0), specular=(0.7, 0.7, 0.7, 1.0),
             emission=(0.05, 0.02, 0.0, 1.0), shininess=24.0):
    GL.glMaterialfv(face, GL.GL_AMBIENT, ambient)
    GL.glMaterialfv(face, GL.GL_DIFFUSE, diffuse)
    GL.glMaterialfv(face, GL.GL_SPECULAR, specular)
    GL.glMaterialfv(face, GL.GL_EMISSION, emission)
    GL.glMaterialf(face, GL.GL_SHININESS, shininess)


def pattern_texture(unit, size, c0, c1, cells=2):
    """A size x size RGBA texture on texture unit `unit` blending c0 and c1
    in a smooth (sinusoidal) pattern of `cells` periods, linear filtering,
    repeat. Smooth on purpose: with sharp texel edges a sub-pixel difference
    in texture coordinates between two correct implementations flips whole
    pixels."""
    import math
    data = bytearray()
    for y in range(size):
        for x in range(size):
            k = 0.5 + 0.25 * (math.sin(2 * math.pi * cells * (x + 0.5) / size)
                              + math.cos(2 * math.pi * cells * (y + 0.5) / size))
            data += bytes(int(round(a + (b - a) * k)) for a, b in zip(c0, c1))
    GL.glActiveTexture(GL.GL_TEXTURE0 + unit)
    t = GL.glGenTextures(1)
    GL.glBindTexture(GL.GL_TEXTURE_2D, t)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_LINEAR)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_LINEAR)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_S, GL.GL_REPEAT)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_T, GL.GL_REPEAT)
    GL.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL.GL_RGBA, size, size, 0, GL.GL_RGBA,
                    GL.GL_UNSIGNED_BYTE, bytes(data))
    GL.glActiveTexture(GL.GL_TEXTURE0)
    return t
