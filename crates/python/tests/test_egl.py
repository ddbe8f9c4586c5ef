"""import shaderbox.egl: PyOpenGL's EGL platform on shaderbox, in process.

Each check runs in a subprocess (PyOpenGL chooses one platform per
process) with PYOPENGL_PLATFORM and LD_LIBRARY_PATH removed: the EGL and
GL functions must come from the shaderbox extension module alone.
"""

import os
import subprocess
import sys

import pytest

pytest.importorskip("OpenGL")

# A red triangle on blue, through the fixed-function pipeline (2.1) or a
# GLSL 3.30 program and a buffer object (3.3 compatibility: the default
# vertex array; capi has no vertex array object entry points), drawn into a
# framebuffer object of a surfaceless context or into a pbuffer; the
# centre pixel is red, a corner blue.
TRIANGLE = r"""
import ctypes, sys
import shaderbox.egl as se
from OpenGL import EGL, GL

mode = sys.argv[1]
W = H = 32
if mode == "compat33":
    dpy, ctx, surface = se.context(version=(3, 3), core=False)
elif mode == "pbuffer":
    dpy, ctx, surface = se.context(W, H)
else:
    dpy, ctx, surface = se.context()
print("EGL_VENDOR", EGL.eglQueryString(dpy, EGL.EGL_VENDOR).decode())
print("GL_RENDERER", GL.glGetString(GL.GL_RENDERER).decode())
print("GL_VERSION", GL.glGetString(GL.GL_VERSION).decode())
if surface == EGL.EGL_NO_SURFACE:
    fbo = GL.glGenFramebuffers(1)
    GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, fbo)
    rb = GL.glGenRenderbuffers(1)
    GL.glBindRenderbuffer(GL.GL_RENDERBUFFER, rb)
    GL.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_RGBA8, W, H)
    GL.glFramebufferRenderbuffer(GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, GL.GL_RENDERBUFFER, rb)
    assert GL.glCheckFramebufferStatus(GL.GL_FRAMEBUFFER) == GL.GL_FRAMEBUFFER_COMPLETE
GL.glViewport(0, 0, W, H)
GL.glClearColor(0, 0, 1, 1)
GL.glClear(GL.GL_COLOR_BUFFER_BIT)
if mode == "compat33":
    from OpenGL.GL import shaders
    prog = shaders.compileProgram(
        shaders.compileShader(
            "#version 330\nlayout(location = 0) in vec2 p;\n"
            "void main() { gl_Position = vec4(p, 0.0, 1.0); }", GL.GL_VERTEX_SHADER),
        shaders.compileShader(
            "#version 330\nout vec4 c;\nvoid main() { c = vec4(1.0, 0.0, 0.0, 1.0); }",
            GL.GL_FRAGMENT_SHADER),
        validate=False,
    )
    GL.glUseProgram(prog)
    vbo = GL.glGenBuffers(1)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, vbo)
    data = (ctypes.c_float * 6)(-0.5, -0.5, 0.5, -0.5, 0.0, 0.5)
    GL.glBufferData(GL.GL_ARRAY_BUFFER, ctypes.sizeof(data), data, GL.GL_STATIC_DRAW)
    GL.glEnableVertexAttribArray(0)
    GL.glVertexAttribPointer(0, 2, GL.GL_FLOAT, GL.GL_FALSE, 0, None)
    GL.glDrawArrays(GL.GL_TRIANGLES, 0, 3)
else:
    GL.glColor3f(1, 0, 0)
    GL.glBegin(GL.GL_TRIANGLES)
    GL.glVertex2f(-0.5, -0.5)
    GL.glVertex2f(0.5, -0.5)
    GL.glVertex2f(0.0, 0.5)
    GL.glEnd()
if surface != EGL.EGL_NO_SURFACE:
    assert EGL.eglSwapBuffers(dpy, surface)
pixels = GL.glReadPixels(0, 0, W, H, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE)
assert GL.glGetError() == GL.GL_NO_ERROR
def at(x, y):
    i = (y * W + x) * 4
    return tuple(pixels[i:i + 4])
print("centre", at(W // 2, H // 2), "corner", at(1, 1))
assert at(W // 2, H // 2) == (255, 0, 0, 255), at(W // 2, H // 2)
assert at(1, 1) == (0, 0, 255, 255), at(1, 1)
assert EGL.eglMakeCurrent(dpy, EGL.EGL_NO_SURFACE, EGL.EGL_NO_SURFACE, EGL.EGL_NO_CONTEXT)
assert EGL.eglTerminate(dpy)
print("ok")
"""


def clean_env():
    env = dict(os.environ)
    for k in ("PYOPENGL_PLATFORM", "LD_LIBRARY_PATH", "__EGL_VENDOR_LIBRARY_FILENAMES"):
        env.pop(k, None)
    return env


def run(code, *args):
    return subprocess.run(
        [sys.executable, "-c", code, *args],
        env=clean_env(), capture_output=True, text=True, timeout=300,
    )


@pytest.mark.parametrize("mode", ["surfaceless", "pbuffer", "compat33"])
def test_triangle_through_shaderbox_egl(mode):
    r = run(TRIANGLE, mode)
    assert r.returncode == 0 and r.stdout.endswith("ok\n"), r.stdout + r.stderr
    assert "EGL_VENDOR shaderbox\n" in r.stdout
    assert "GL_RENDERER shaderbox" in r.stdout
    # A 2.1 request gets the 3.3 compatibility profile (it contains 2.1).
    assert "GL_VERSION 3.3 (Compatibility Profile)" in r.stdout, r.stdout


def test_library_is_the_extension_module():
    r = run("import shaderbox.egl as se, shaderbox._shaderbox as m\n"
            "from OpenGL import platform\n"
            "assert se.LIBRARY == m.__file__\n"
            "assert platform.PLATFORM.EGL._name == m.__file__\n"
            "assert platform.PLATFORM.GL._name == m.__file__\n"
            "print('ok')\n")
    assert r.returncode == 0 and "ok" in r.stdout, r.stdout + r.stderr


def test_unsupported_version_is_an_egl_error():
    r = run("import shaderbox.egl as se\nse.context(version=(4, 1), core=True)\n")
    assert r.returncode != 0
    assert "eglCreateContext for OpenGL 4.1 failed (EGL error 0x3009)" in r.stderr, r.stderr


def test_after_another_platform_is_an_import_error():
    r = run("import shaderbox.pyopengl\nimport shaderbox.egl\n")
    assert r.returncode != 0
    assert "import shaderbox.egl before anything from OpenGL" in r.stderr, r.stderr
