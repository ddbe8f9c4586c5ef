"""``shaderbox.render_molecule`` and ``shaderbox.MoleculeRenderer``:
``shaderbox render`` from Python."""

from __future__ import annotations

import os
import re
from typing import Any, Optional, Sequence, Tuple, Union

import numpy as np

from . import _shaderbox
from ._image import Image

_NAMED = {"black": (0.0, 0.0, 0.0), "white": (1.0, 1.0, 1.0), "gray": (0.5, 0.5, 0.5), "grey": (0.5, 0.5, 0.5)}


def _background(bg: Any) -> Optional[Tuple[float, float, float]]:
    if isinstance(bg, str):
        t = bg.strip().lower()
        if t == "transparent":
            return None
        if t in _NAMED:
            return _NAMED[t]
        m = re.fullmatch(r"#?([0-9a-f]{6})", t)
        if not m:
            raise ValueError(f"background {bg!r} is not black, white, gray, #RRGGBB, transparent or an RGB tuple")
        h = m.group(1)
        return tuple(int(h[i : i + 2], 16) / 255.0 for i in (0, 2, 4))  # type: ignore[return-value]
    a = np.asarray(bg, dtype=np.float64).reshape(-1)
    if a.size != 3:
        raise ValueError(f"background {bg!r} is not an (r, g, b) tuple in 0-1")
    return (float(a[0]), float(a[1]), float(a[2]))


def _size(size: Any) -> Tuple[int, int]:
    if isinstance(size, str):
        m = re.fullmatch(r"\s*(\d+)\s*[xX]\s*(\d+)\s*", size)
        if not m:
            raise ValueError(f"size {size!r} is not WIDTHxHEIGHT (e.g. '800x600')")
        return int(m.group(1)), int(m.group(2))
    w, h = size
    if not all(isinstance(v, (int, np.integer)) and not isinstance(v, bool) for v in (w, h)) or w < 1 or h < 1:
        raise ValueError(f"size {size!r} is not (width, height) in pixels")
    return int(w), int(h)


def _lights(lights: Any) -> list:
    if isinstance(lights, str):
        if lights.strip().lower() == "none":
            return []
        parts = [p.strip() for p in lights.split(",")]
        if not all(p.isdigit() for p in parts):
            raise ValueError(f"lights {lights!r} is not a list of light numbers 0-7 (or 'none')")
        lights = [int(p) for p in parts]
    out = []
    for light in lights:
        if not isinstance(light, (int, np.integer)) or not 0 <= int(light) <= 7:
            raise ValueError(f"light {light!r} is not a light number 0-7")
        out.append(int(light))
    return out


class MoleculeRenderer:
    """Renders molecule after molecule on one GL context, keeping the shader
    programs it compiled: what batches use (``shaderbox.batch`` keeps one
    per worker process), as creating a context and compiling programs costs
    more than drawing a small molecule. Each image is the same bytes as
    :func:`render_molecule` gives for the same structure and options,
    whatever was rendered before. Not for concurrent use from several
    threads (calls wait for each other).

    ``options`` are :func:`render_molecule`'s defaults for this renderer;
    each :meth:`render` call may override any of them."""

    def __init__(self, **options: Any) -> None:
        _check_option_names(options)
        self.options = dict(_DEFAULTS, **options)
        self._raw = _shaderbox.RawMoleculeRenderer()

    def render(
        self,
        path: Union[None, str, "os.PathLike[str]"] = None,
        *,
        text: Union[None, str, bytes] = None,
        name: str = "<text>",
        **options: Any,
    ) -> Image:
        """Draws the structure in ``path`` (PDB or mmCIF), or given as
        ``text`` (``str`` or ``bytes``; ``name`` is what errors call it), or
        crambin when neither is given. Errors as :func:`render_molecule`'s."""
        _check_option_names(options)
        o = dict(self.options, **options)
        w, h = _size(o["size"])
        rot = np.asarray(o["rotate"], dtype=np.float64).reshape(-1)
        if rot.size != 3:
            raise ValueError(f"rotate {o['rotate']!r} is three angles (x, y, z) in degrees")
        supersample = o["supersample"]
        if not isinstance(supersample, (int, np.integer)) or isinstance(supersample, bool):
            raise TypeError(f"supersample must be an int 1-8, got {supersample!r}")
        if text is not None and path is not None:
            raise TypeError("give a path or text, not both")
        data_in = text.encode() if isinstance(text, str) else text
        p = None if path is None else os.fspath(path)
        width, height, data, has_alpha = self._raw.render(
            p,
            data_in,
            name,
            w,
            h,
            o["projection"],
            o["fog"],
            _lights(o["lights"]),
            [float(v) for v in rot],
            int(supersample),
            _background(o["background"]),
            o["effect"],
            o["style"],
            o["atoms"],
        )
        return Image(np.frombuffer(data, dtype=np.uint8).reshape(height, width, 4), has_alpha=has_alpha)


def _check_option_names(options: Any) -> None:
    """TypeError naming the options that are not render_molecule's."""
    unknown = sorted(set(options) - set(_DEFAULTS))
    if unknown:
        raise TypeError(f"unknown rendering option(s) {', '.join(unknown)}; known: {', '.join(_DEFAULTS)}")


# render_molecule's options and their defaults.
_DEFAULTS = {
    "size": (800, 800),
    "projection": "ortho",
    "fog": "none",
    "lights": (0, 1),
    "rotate": (0.0, 0.0, 0.0),
    "supersample": 1,
    "background": "black",
    "effect": "plain",
    "style": "spacefill",
    "atoms": "quads",
}


def render_molecule(
    path: Union[None, str, "os.PathLike[str]"] = None,
    *,
    size: Union[str, Tuple[int, int]] = (800, 800),
    projection: str = "ortho",
    fog: str = "none",
    lights: Union[str, Sequence[int]] = (0, 1),
    rotate: Sequence[float] = (0.0, 0.0, 0.0),
    supersample: int = 1,
    background: Any = "black",
    effect: str = "plain",
    style: str = "spacefill",
    atoms: str = "quads",
) -> Image:
    """Draws a molecule as ``shaderbox render`` does and returns the :class:`Image`.

    ``path`` is a PDB or mmCIF file (default: crambin, PDB 1CRN, built in). The
    options are the command's: ``size`` (``(w, h)`` or ``"800x600"``),
    ``projection`` (``"ortho"``, ``"perspective"``), ``fog`` (``"none"``,
    ``"linear"``, ``"exp"``, ``"exp2"``), ``lights`` (light numbers 0-7, or
    ``"none"``), ``rotate`` (degrees about X, then Y, then Z),
    ``supersample`` (1-8), ``background`` (``"black"``, ``"white"``,
    ``"gray"``, ``"#RRGGBB"``, an RGB tuple in 0-1, or ``"transparent"``)
    ``effect`` (``"plain"``, ``"outline"``, ``"x"``, ``"x-red"``,
    ``"transparent"``), ``style`` (``"spacefill"``, ``"ballstick"``) and
    ``atoms`` (``"quads"``, or ``"points"``: one point per atom expanded to
    its quad by a geometry shader; the same image).
    (The command's ``--turntable`` is a loop over ``rotate``.) Bad options
    raise ``ValueError``, an unreadable file ``OSError``, a malformed one ``RuntimeError`` naming the line.
    Each call makes a GL context and compiles its programs: for many
    molecules, :class:`MoleculeRenderer` keeps them."""
    return MoleculeRenderer().render(
        path,
        size=size,
        projection=projection,
        fog=fog,
        lights=lights,
        rotate=rotate,
        supersample=supersample,
        background=background,
        effect=effect,
        style=style,
        atoms=atoms,
    )
