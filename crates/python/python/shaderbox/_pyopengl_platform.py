"""PyOpenGL's OSMesa and EGL platforms, loading shaderbox's extension
module as the GL + OSMesa library (see :mod:`shaderbox.pyopengl`) or the
EGL + GL library (see :mod:`shaderbox.egl`)."""

import ctypes

from OpenGL.platform import baseplatform
from OpenGL.platform.egl import EGLPlatform
from OpenGL.platform.osmesa import OSMesaPlatform

from . import _shaderbox


class ShaderboxPlatform(OSMesaPlatform):
    """OSMesa on shaderbox: ``GL`` and ``OSMesa`` are the loaded extension
    module (which exports the C ABI of crates/capi); GLU, GLUT and GLE are
    not provided (no windows here; GLU would pull in a system libGL)."""

    _shaderbox = True

    @baseplatform.lazy_property
    def GL(self):
        # The module is already loaded; dlopen returns the same handle and
        # RTLD_GLOBAL makes its symbols visible to later libraries.
        return ctypes.CDLL(_shaderbox.__file__, mode=ctypes.RTLD_GLOBAL)

    @baseplatform.lazy_property
    def GLU(self):
        return None

    @baseplatform.lazy_property
    def GLUT(self):
        return None

    @baseplatform.lazy_property
    def GLE(self):
        return None


class ShaderboxEGLPlatform(EGLPlatform):
    """EGL on shaderbox (see :mod:`shaderbox.egl`): ``EGL`` and ``GL`` are
    the loaded extension module, which exports crates/egl's EGL C ABI and
    crates/capi's gl* functions; OpenGL ES, GLU, GLUT and GLE are not
    provided."""

    _shaderbox_egl = True

    @baseplatform.lazy_property
    def EGL(self):
        return ctypes.CDLL(_shaderbox.__file__, mode=ctypes.RTLD_GLOBAL)

    @baseplatform.lazy_property
    def GL(self):
        return self.EGL

    @baseplatform.lazy_property
    def GLES1(self):
        return None

    @baseplatform.lazy_property
    def GLES2(self):
        return None

    @baseplatform.lazy_property
    def GLU(self):
        return None

    @baseplatform.lazy_property
    def GLUT(self):
        return None

    @baseplatform.lazy_property
    def GLE(self):
        return None
