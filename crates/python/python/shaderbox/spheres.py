"""Spheres from numpy arrays with the seed talk's ray-cast impostor shaders.

:func:`draw_spheres` is a short path through the public API (a program
from :mod:`shaderbox.shaders`, one interleaved buffer, the built-in
attributes ``gl_Vertex``, ``gl_MultiTexCoord0`` and ``gl_Color``, the GL
lights and material, and the shaders' own uniforms); the example notebook
spells the same steps out.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

import numpy as np

from .shaders import EFFECTS

if TYPE_CHECKING:
    # Annotations only: Context.draw_spheres calls into this module, so a
    # run-time import back would make the two modules a cycle.
    from ._context import Context, Program

#: Direction (eye space), ambient, diffuse, specular of the default lights
#: (those of ``shaderbox render``: a key light from the upper left and a
#: fill light from the lower right).
DEFAULT_LIGHTS = (
    ((-0.4, 0.55, 1.0, 0.0), 0.15, 0.75, 0.6),
    ((0.6, -0.3, 0.7, 0.0), 0.05, 0.3, 0.15),
)
CORNERS = np.array([(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)], dtype=np.float32)


def _per_sphere(value: Any, n: int, widths: tuple, what: str) -> np.ndarray:
    """``value`` for each of ``n`` spheres: a row of width ``w`` (0: a
    number) given once or per sphere."""
    a = np.asarray(value)
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{what} must be numbers, got dtype {a.dtype}")
    a = a.astype(np.float32)
    for w in widths:
        one, each = ((w,), (n, w)) if w else ((), (n,))
        if a.shape == one:
            return np.broadcast_to(a, each).copy()
        if a.shape == each:
            return a
    shapes = " or ".join(f"{((w,) if w else ())} or {((n, w) if w else (n,))}" for w in widths)
    raise ValueError(f"{what}: expected shape {shapes} for {n} spheres, got {a.shape}")


def fit_camera(ctx: Context, centers: np.ndarray, radii: np.ndarray, margin: float = 1.05) -> None:
    """Points an orthographic camera down -z at the spheres' bounding box so
    that all of them are in view (sets ``ctx.projection`` and ``ctx.modelview``)."""
    lo = (centers - radii[:, None]).min(axis=0)
    hi = (centers + radii[:, None]).max(axis=0)
    mid = (lo + hi) / 2
    reach = float(np.max(np.linalg.norm(centers - mid, axis=1) + radii)) * margin
    reach = max(reach, 1e-3)
    aspect = ctx.width / ctx.height
    hw, hh = reach * max(1.0, aspect), reach * max(1.0, 1.0 / aspect)
    distance = 3.0 * reach
    ctx.ortho(-hw, hw, -hh, hh, distance - 1.5 * reach, distance + 1.5 * reach)
    m = np.identity(4)
    m[:3, 3] = -mid
    m[2, 3] -= distance
    ctx.modelview = m


def draw_spheres(
    ctx: Context,
    centers: Any,
    radii: Any = 1.0,
    colors: Any = (0.8, 0.8, 0.8),
    *,
    effect: str = "plain",
    fit: bool = True,
    clear: bool = True,
    background: Any = (0.0, 0.0, 0.0),
) -> Program:
    """Draws one ray-cast sphere per row of ``centers`` (``N x 3``), with
    ``radii`` (a number or ``N``) and ``colors`` (RGB/RGBA in 0-1, one for all
    or ``N x 3``/``N x 4``), using the seed's ``sphere.vert`` + ``sphere.frag``
    (or another ``effect``: ``"outline"``, ``"x"``, ``"x-red"``,
    ``"transparent"``).

    ``fit`` frames the spheres with an orthographic camera (otherwise the
    context's projection and model-view are used as they are); ``clear``
    clears to ``background`` first. When no GL light is enabled, lights 0
    and 1 and a white material with shininess 50 are set up as
    ``shaderbox render`` does. Fog follows ``ctx.fog`` when it is enabled.
    Returns the program (its uniforms show what was set)."""
    c = np.asarray(centers)
    if c.dtype.kind not in "biuf":
        raise TypeError(f"centers must be numbers, got dtype {c.dtype}")
    if c.ndim != 2 or c.shape[1] != 3 or c.shape[0] == 0:
        raise ValueError(f"centers is N x 3 (N >= 1), got shape {c.shape}")
    c = c.astype(np.float32)
    n = c.shape[0]
    r = _per_sphere(radii, n, (0,), "radii")
    if np.any(~np.isfinite(r)) or np.any(r <= 0) or np.any(~np.isfinite(c)):
        raise ValueError("centers must be finite and radii finite and > 0")
    col = np.asarray(colors)
    col = _per_sphere(col, n, (3, 4), "colors")
    if col.shape[1] == 3:
        col = np.column_stack([col, np.ones(n, dtype=np.float32)])
    if effect not in EFFECTS:
        raise ValueError(f"effect {effect!r} is not one of: {', '.join(EFFECTS)}")

    cache = ctx.__dict__.setdefault("_sphere_programs", {})
    prog = cache.get(effect)
    if prog is None:
        vs, fs = EFFECTS[effect]
        prog = cache[effect] = ctx.program(vertex_shader=vs, fragment_shader=fs)

    if fit:
        fit_camera(ctx, c, r)
    if not any(light.enabled for light in ctx.lights):
        saved = ctx.modelview
        ctx.modelview = np.identity(4)
        for i, (pos, a, d, s) in enumerate(DEFAULT_LIGHTS):
            light = ctx.lights[i]
            light.position = pos
            light.ambient = (a, a, a, 1.0)
            light.diffuse = (d, d, d, 1.0)
            light.specular = (s, s, s, 1.0)
            light.enabled = True
        ctx.modelview = saved
        ctx.material.ambient = ctx.material.diffuse = ctx.material.specular = (1.0, 1.0, 1.0, 1.0)
        ctx.material.shininess = 50.0

    mv = ctx.modelview
    right, up = mv[0, :3].astype(np.float64), mv[1, :3].astype(np.float64)
    prog["right_vector"] = right / max(float(np.linalg.norm(right)), 1e-12)
    prog["up_vector"] = up / max(float(np.linalg.norm(up)), 1e-12)
    perspective = 1.0 if ctx.projection[3, 3] == 0.0 else 0.0
    prog["perspective"] = perspective
    # The impostors cast each pixel's ray from gl_FragCoord and the viewport.
    prog["viewport"] = [float(v) for v in ctx.viewport]
    fogging = np.zeros(4, dtype=np.float32)
    fogging[{"linear": 1, "exp": 2, "exp2": 3}.get(ctx.fog.mode, 0) if ctx.fog.enabled else 0] = 1.0
    if "fogging" in prog:
        prog["fogging"] = fogging
    if "light_enabled" in prog:
        prog["light_enabled"] = [1.0 if light.enabled else 0.0 for light in ctx.lights]
    if "outline_width" in prog:
        # 1.5 pixels in eye space (orthographic: from the projection's x scale).
        prog["outline_width"] = 1.5 * 2.0 / (ctx.width * abs(float(ctx.projection[0, 0])) or 1.0)

    tex = np.column_stack([np.tile(CORNERS, (n, 1)), np.repeat(r, 4)])
    data = np.column_stack([np.repeat(c, 4, axis=0), tex, np.repeat(col, 4, axis=0)]).astype(np.float32)
    vao = ctx.vertex_array(prog, [(data, "3f 3f 4f", "gl_Vertex", "gl_MultiTexCoord0", "gl_Color")])
    if clear:
        ctx.clear(background)
    ctx.depth_test = True
    ctx.depth_func("less")
    vao.render("quads")
    return prog
