"""shaderbox: OpenGL 2.1 and 3.3 and GLSL 1.10-3.30 on the CPU, from Python.

Compile, run and look at legacy (compatibility-profile) shaders with
nothing else installed: no GPU, driver, X server or EGL::

    import numpy as np, shaderbox
    xyz = np.random.default_rng(1).normal(0, 8, (300, 3)).astype("f4")
    ctx = shaderbox.Context(512, 512)
    ctx.draw_spheres(xyz, radii=1.5, colors=(0.3, 0.6, 1.0))
    ctx.image().save("spheres.png")

The pieces: :class:`Context` (programs, buffers, vertex arrays, textures,
lights, material, fog, matrices, reading pixels), :func:`check` (GLSL
diagnostics), :func:`render_molecule` (``shaderbox render``) and
:class:`MoleculeRenderer` (many molecules on one context),
:mod:`shaderbox.shaders` (the seed's sphere impostor shaders) and
``import shaderbox.pyopengl`` (PyOpenGL on shaderbox).
"""

from . import _shaderbox
from ._check import check
from ._context import (
    Attribute,
    BlockMember,
    Buffer,
    Context,
    Fog,
    Light,
    Material,
    PixelDebug,
    Program,
    Texture,
    Uniform,
    UniformBlock,
    VertexArray,
    parse_format,
)
from ._errors import CompileError, Diagnostic, Diagnostics, Error, GLError, LinkError
from ._image import Image
from ._molecule import MoleculeRenderer, render_molecule

__version__: str = _shaderbox.__version__

__all__ = [
    "Attribute",
    "BlockMember",
    "Buffer",
    "CompileError",
    "Context",
    "Diagnostic",
    "Diagnostics",
    "Error",
    "Fog",
    "GLError",
    "Image",
    "Light",
    "LinkError",
    "Material",
    "MoleculeRenderer",
    "PixelDebug",
    "Program",
    "Texture",
    "Uniform",
    "UniformBlock",
    "VertexArray",
    "check",
    "parse_format",
    "render_molecule",
]
