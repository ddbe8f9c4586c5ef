"""``import shaderbox.egl``: PyOpenGL's EGL platform in this process draws with shaderbox.

Import it before anything from ``OpenGL``. It makes PyOpenGL choose its
EGL platform with ``EGL`` and ``GL`` taken from shaderbox's own extension
module, which exports the EGL 1.5 C ABI of crates/egl (and the gl* entry
points of crates/capi), so headless PyOpenGL code written for EGL runs with
no GPU driver, no system ``libEGL`` and no ``PYOPENGL_PLATFORM`` /
``LD_LIBRARY_PATH``::

    import shaderbox.egl                 # first
    from OpenGL import EGL, GL
    dpy = EGL.eglGetDisplay(EGL.EGL_DEFAULT_DISPLAY)
    EGL.eglInitialize(dpy, None, None)
    ...                                  # choose a config, bind EGL_OPENGL_API,
                                         # create a context, make it current

:func:`context` does the EGL part (a surfaceless OpenGL context, drawing
into framebuffer objects, or a pbuffer). What EGL offers here (displays,
configs, context versions 2.1 and 3.3 core/compatibility) is docs/EGL.md's
list. The GL state is the C ABI's (crates/capi): separate from
:class:`shaderbox.Context` objects, one current context per thread. GLU,
GLUT and OpenGL ES are not provided.

Raises ``ImportError`` if PyOpenGL is missing, if PyOpenGL already chose
another platform in this process (``shaderbox.pyopengl`` included: one
platform per process), or if the extension module was built without the
EGL C ABI.
"""

from __future__ import annotations

import ctypes
import sys
from typing import Any, Optional, Tuple

from . import _shaderbox

#: The file PyOpenGL loads as its EGL and GL library.
LIBRARY: str = _shaderbox.__file__


def _check_library() -> None:
    lib = ctypes.CDLL(LIBRARY)
    if not hasattr(lib, "eglGetDisplay"):
        raise ImportError(
            f"{LIBRARY} does not export the EGL C ABI: the shaderbox extension was built "
            "without crates/egl (the `python` feature of shaderbox-python links it)"
        )


def _install() -> None:
    loaded = sys.modules.get("OpenGL.platform")
    if loaded is not None:
        if getattr(getattr(loaded, "PLATFORM", None), "_shaderbox_egl", False):
            return
        raise ImportError(
            "PyOpenGL has already chosen its platform in this process (OpenGL.platform is imported): "
            "import shaderbox.egl before anything from OpenGL"
        )
    _check_library()
    try:
        from OpenGL import plugins
    except ImportError as e:
        raise ImportError("shaderbox.egl needs PyOpenGL: pip install PyOpenGL") from e
    ours = plugins.PlatformPlugin("shaderbox-egl", "shaderbox._pyopengl_platform.ShaderboxEGLPlatform")
    original = plugins.PlatformPlugin.__dict__["match"]
    # OpenGL.platform picks the plugin matching PYOPENGL_PLATFORM, the
    # session type or sys.platform; for this one import, ours matches.
    plugins.PlatformPlugin.match = classmethod(lambda cls, key: ours)  # type: ignore[method-assign]
    try:
        import OpenGL.platform  # noqa: F401
    finally:
        plugins.PlatformPlugin.match = original  # type: ignore[method-assign]


_install()


def context(
    width: int = 0, height: int = 0, version: Tuple[int, int] = (2, 1), core: Optional[bool] = None
) -> Tuple[Any, Any, Any]:
    """Initializes EGL's default display, creates an OpenGL context of
    ``version`` (``(2, 1)``, or up to ``(3, 3)``; for 3.2 and 3.3 ``core``
    chooses the profile, default core; shaderbox's EGL answers every
    request but 3.2/3.3 core with the 3.3 compatibility profile, which
    contains all of OpenGL 2.1, as EGL allows and Mesa does) with an RGBA8 config with 24-bit
    depth and 8-bit stencil, and makes it current: with a ``width`` x
    ``height`` pbuffer if both are positive, with no surface (draw into a
    framebuffer object) otherwise. Returns ``(display, context, surface)``
    (``surface`` is ``EGL_NO_SURFACE`` when surfaceless); ``eglTerminate``
    on the display releases them."""
    from OpenGL import EGL

    def call(what: str, f: Any, *args: Any) -> Any:
        # PyOpenGL raises EGLError for some failed calls and returns the
        # failure value for others: both become one RuntimeError.
        try:
            r = f(*args)
        except EGL.EGLError as e:
            raise RuntimeError(f"{what} failed (EGL error 0x{e.err:x})") from None
        if not r:
            raise RuntimeError(f"{what} failed (EGL error 0x{EGL.eglGetError():x})")
        return r

    dpy = call("eglGetDisplay", EGL.eglGetDisplay, EGL.EGL_DEFAULT_DISPLAY)
    major, minor = EGL.EGLint(), EGL.EGLint()
    call("eglInitialize", EGL.eglInitialize, dpy, ctypes.pointer(major), ctypes.pointer(minor))
    attribs = (EGL.EGLint * 11)(
        EGL.EGL_SURFACE_TYPE, EGL.EGL_PBUFFER_BIT,
        EGL.EGL_RENDERABLE_TYPE, EGL.EGL_OPENGL_BIT,
        EGL.EGL_DEPTH_SIZE, 24,
        EGL.EGL_STENCIL_SIZE, 8,
        EGL.EGL_RED_SIZE, 8,
        EGL.EGL_NONE,
    )
    configs = (EGL.EGLConfig * 1)()
    n = EGL.EGLint()
    call("eglChooseConfig", EGL.eglChooseConfig, dpy, attribs, configs, 1, ctypes.pointer(n))
    if n.value != 1:
        raise RuntimeError("eglChooseConfig found no RGBA8 config with depth 24 and stencil 8")
    config = configs[0]
    call("eglBindAPI", EGL.eglBindAPI, EGL.EGL_OPENGL_API)
    ctx_attribs = [EGL.EGL_CONTEXT_MAJOR_VERSION, version[0], EGL.EGL_CONTEXT_MINOR_VERSION, version[1]]
    if core is not None:
        ctx_attribs += [
            EGL.EGL_CONTEXT_OPENGL_PROFILE_MASK,
            EGL.EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT if core else EGL.EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
        ]
    ctx_attribs.append(EGL.EGL_NONE)
    ctx = call(
        f"eglCreateContext for OpenGL {version[0]}.{version[1]}",
        EGL.eglCreateContext, dpy, config, EGL.EGL_NO_CONTEXT, (EGL.EGLint * len(ctx_attribs))(*ctx_attribs),
    )
    surface = EGL.EGL_NO_SURFACE
    if width > 0 and height > 0:
        size = (EGL.EGLint * 5)(EGL.EGL_WIDTH, width, EGL.EGL_HEIGHT, height, EGL.EGL_NONE)
        surface = call(f"eglCreatePbufferSurface {width}x{height}", EGL.eglCreatePbufferSurface, dpy, config, size)
    call("eglMakeCurrent", EGL.eglMakeCurrent, dpy, surface, surface, ctx)
    return dpy, ctx, surface
