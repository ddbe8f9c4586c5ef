"""``import shaderbox.pyopengl``: PyOpenGL in this process draws with shaderbox.

Import it before anything from ``OpenGL`` (``OpenGL.GL``,
``OpenGL.osmesa``...). It makes PyOpenGL choose its OSMesa platform, with
the OSMesa context API and the ``gl*`` entry points taken from shaderbox's
own extension module (which exports the C ABI of ``libOSMesa.so``), so
existing PyOpenGL code written for OSMesa runs with no GPU driver, no
system libOSMesa, and no ``PYOPENGL_PLATFORM`` / ``LD_LIBRARY_PATH``::

    import shaderbox.pyopengl            # first
    from OpenGL import GL, osmesa, arrays
    ctx = osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 24, 8, 0, None)
    buf = arrays.GLubyteArray.zeros((64, 64, 4))
    osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_UNSIGNED_BYTE, 64, 64)
    ...

:func:`context` does the last three lines. The GL state is the C ABI's
(crates/capi): separate from :class:`shaderbox.Context` objects, one
current context per thread. GLU and GLUT are not provided.

Raises ``ImportError`` if PyOpenGL is missing, or if PyOpenGL already
chose another platform in this process.
"""

from __future__ import annotations

import sys
from typing import Any, Tuple

from . import _shaderbox

#: The file PyOpenGL loads as its GL and OSMesa library.
LIBRARY: str = _shaderbox.__file__


def _install() -> None:
    loaded = sys.modules.get("OpenGL.platform")
    if loaded is not None:
        if getattr(getattr(loaded, "PLATFORM", None), "_shaderbox", False):
            return
        raise ImportError(
            "PyOpenGL has already chosen its platform in this process (OpenGL.platform is imported): "
            "import shaderbox.pyopengl before anything from OpenGL"
        )
    try:
        from OpenGL import plugins
    except ImportError as e:
        raise ImportError("shaderbox.pyopengl needs PyOpenGL: pip install PyOpenGL") from e
    ours = plugins.PlatformPlugin("shaderbox", "shaderbox._pyopengl_platform.ShaderboxPlatform")
    original = plugins.PlatformPlugin.__dict__["match"]
    # OpenGL.platform picks the plugin matching PYOPENGL_PLATFORM, the
    # session type or sys.platform; for this one import, ours matches.
    plugins.PlatformPlugin.match = classmethod(lambda cls, key: ours)  # type: ignore[method-assign]
    try:
        import OpenGL.platform  # noqa: F401
    finally:
        plugins.PlatformPlugin.match = original  # type: ignore[method-assign]


_install()


def context(width: int, height: int) -> Tuple[Any, Any]:
    """Creates an OSMesa RGBA context with a depth and stencil buffer and a
    ``height x width x 4`` uint8 buffer, makes it current, and returns
    ``(context, buffer)`` (the buffer holds the image after ``glFinish``,
    bottom row first)."""
    from OpenGL import GL, arrays, osmesa

    ctx = osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 24, 8, 0, None)
    if not ctx:
        raise RuntimeError("OSMesaCreateContextExt failed")
    buf = arrays.GLubyteArray.zeros((height, width, 4))
    if not osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_UNSIGNED_BYTE, width, height):
        raise RuntimeError(f"OSMesaMakeCurrent failed for {width}x{height}")
    return ctx, buf
