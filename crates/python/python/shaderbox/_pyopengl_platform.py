"""PyOpenGL's OSMesa platform, loading shaderbox's extension module as the
GL + OSMesa library (see :mod:`shaderbox.pyopengl`)."""

import ctypes

from OpenGL.platform import baseplatform
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
