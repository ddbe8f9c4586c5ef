"""The project's shader library (``shaders/`` in the repository), as strings.

``SPHERE_VERT`` + ``SPHERE_FRAG`` are the seed talk's ray-cast sphere
impostors (what ``shaderbox render`` and :func:`shaderbox.spheres.draw_spheres`
use); ``OUTLINE_FRAG``, ``X_VERT`` + ``X_FRAG`` / ``X_RED_FRAG`` and
``TRANSPARENT_FRAG`` are its effects. ``LIBRARY`` maps file names to sources.
"""

from typing import Dict

from . import _shaderbox

LIBRARY: Dict[str, str] = dict(_shaderbox.library_shaders())

SPHERE_VERT: str = LIBRARY["sphere.vert"]
SPHERE_FRAG: str = LIBRARY["sphere.frag"]
OUTLINE_FRAG: str = LIBRARY["outline.frag"]
X_VERT: str = LIBRARY["x.vert"]
X_FRAG: str = LIBRARY["x.frag"]
X_RED_FRAG: str = LIBRARY["x-red.frag"]
TRANSPARENT_FRAG: str = LIBRARY["transparent.frag"]

#: effect name -> (vertex shader, fragment shader), as ``shaderbox render --effect``.
EFFECTS: Dict[str, tuple] = {
    "plain": (SPHERE_VERT, SPHERE_FRAG),
    "outline": (SPHERE_VERT, OUTLINE_FRAG),
    "x": (X_VERT, X_FRAG),
    "x-red": (X_VERT, X_RED_FRAG),
    "transparent": (SPHERE_VERT, TRANSPARENT_FRAG),
}
