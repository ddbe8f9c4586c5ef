"""``shaderbox.check``: compile GLSL and get its diagnostics."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Optional, Union

from . import _shaderbox
from ._errors import Diagnostics, _diagnostics

_EXTENSIONS = {
    ".vert": "vertex",
    ".vs": "vertex",
    ".tesc": "tess_control",
    ".tese": "tess_evaluation",
    ".geom": "geometry",
    ".gs": "geometry",
    ".frag": "fragment",
    ".fs": "fragment",
    ".comp": "compute",
}


def check(
    source: Union[str, "os.PathLike[str]"],
    stage: Optional[str] = None,
    version: Optional[int] = None,
) -> Diagnostics:
    """Compiles ``source`` (GLSL text, or a ``pathlib.Path`` to a shader
    file) as a ``"vertex"``, ``"tess_control"``, ``"tess_evaluation"``,
    ``"geometry"``, ``"fragment"`` or ``"compute"`` shader and returns its
    :class:`Diagnostics` (empty and ``ok`` when it compiles cleanly).

    ``stage`` is required for text; for a path it defaults from the
    extension (``.vert``/``.vs``, ``.tesc``, ``.tese``, ``.geom``/``.gs``,
    ``.frag``/``.fs``, ``.comp``). ``version`` (110,
    120, 130, 140, 150 or 330) is the version of a shader without ``#version`` (1.10 by
    default, as the spec says); a ``#version`` line always wins."""
    name = "<shader>"
    if isinstance(source, os.PathLike):
        path = Path(source)
        name = str(path)
        if stage is None:
            stage = _EXTENSIONS.get(path.suffix.lower())
            if stage is None:
                raise ValueError(f"{name}: cannot tell the stage from the extension; pass stage='vertex', 'tess_control', 'tess_evaluation', 'geometry', 'fragment' or 'compute'")
        source = path.read_bytes().decode("utf-8", errors="replace")
    elif not isinstance(source, str):
        raise TypeError(f"source must be GLSL text (str) or a path, got {type(source).__name__}")
    if stage is None:
        raise ValueError("check() needs stage='vertex', 'tess_control', 'tess_evaluation', 'geometry', 'fragment' or 'compute' for source text")
    if version is not None and not isinstance(version, int):
        raise TypeError(f"version must be an int such as 330, got {type(version).__name__}")
    return _diagnostics(_shaderbox.compile_report(source, stage, version, name))
