"""Differential scenes: the example shaders of seed document 000 (the GLSL
1.20 talk) with the GL state each expects — the trivial pair, the materials
shader with two lights, variable lights with 0..8 enabled, and the sphere
impostors of shaders/ (seed technique, fixed text) in orthographic and
perspective projection with each fog mode plus the outline, X, yellow-X and
transparent effects; also the seed's own sphere and X pairs as written.

Run by compare.py (python3 seed_shaders.py OUTDIR [SCENE...]); see harness.py.
"""
import math
import os
import sys

from harness import (GL, SEEDS, lib, lights, main, material, ortho, perspective, program,
                     scene, source, tess_sphere, uniform)


def seed(name):
    return source(os.path.join(SEEDS, name), 120)


def rainbow(n):
    return (0.5 + 0.5 * n[0], 0.5 + 0.5 * n[1], 0.6 - 0.3 * n[2], 1.0)


@scene("trivial")
def trivial(log):
    program([seed("000-trivial.vert")], [seed("000-trivial.frag")])
    GL.glClearColor(0.1, 0.2, 0.3, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT)
    GL.glBegin(GL.GL_TRIANGLES)
    GL.glColor3f(1, 0, 0)
    GL.glVertex2f(-0.9, -0.8)
    GL.glColor3f(0, 1, 0)
    GL.glVertex2f(0.8, -0.6)
    GL.glColor3f(0, 0, 1)
    GL.glVertex2f(-0.2, 0.9)
    GL.glEnd()


def lit_sphere_scene(fs, enabled, p_setup=None):
    p = program([seed("000-materials.vert")], [seed(fs)])
    GL.glClearColor(0.0, 0.0, 0.0, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    GL.glEnable(GL.GL_DEPTH_TEST)
    perspective(0.45)
    on = lights(enabled)
    if p_setup:
        p_setup(p, on)
    material()
    GL.glTranslatef(0.0, 0.0, -3.0)
    GL.glRotatef(25.0, 1.0, 0.3, 0.0)
    tess_sphere(1.0, color=rainbow)


@scene("materials_two_lights")
def materials_two_lights(log):
    lit_sphere_scene("000-materials.frag", {0, 1})


def variable_lights(n):
    def f(log):
        lit_sphere_scene("000-variable-lights.frag", set(range(n)),
                         lambda p, on: uniform(p, "light_enabled", *on, count=8))
    return f


for _n in range(9):
    scene(f"variable_lights_{_n}")(variable_lights(_n))


# ---- sphere impostors ----

# A small molecule: (centre, radius, colour). Spheres overlap (their depth
# written per pixel must cut them) and some are red (x-red, transparent).
ATOMS = [
    ((0.0, 0.0, 0.0), 0.45, (0.9, 0.1, 0.1, 1.0)),
    ((0.55, 0.2, -0.2), 0.35, (0.9, 0.9, 0.9, 1.0)),
    ((-0.5, 0.3, 0.25), 0.4, (0.2, 0.3, 0.95, 1.0)),
    ((0.1, -0.55, 0.3), 0.3, (0.85, 0.15, 0.1, 1.0)),
    ((-0.35, -0.45, -0.5), 0.38, (0.5, 0.5, 0.5, 1.0)),
    ((0.6, -0.45, -0.6), 0.28, (0.95, 0.85, 0.1, 1.0)),
    ((-0.1, 0.65, -0.45), 0.33, (0.8, 0.05, 0.2, 1.0)),
]

FOGS = {"none": (GL.GL_LINEAR, 0), "linear": (GL.GL_LINEAR, 1),
        "exp": (GL.GL_EXP, 2), "exp2": (GL.GL_EXP2, 3)}


def impostors(vs, fs, persp, fog="none", extra=None, seed_text=False):
    """Draws ATOMS as impostor quads with the given shader pair."""
    p = program([vs], [fs])
    bg = (0.15, 0.15, 0.2, 1.0)
    GL.glClearColor(*bg)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    GL.glEnable(GL.GL_DEPTH_TEST)
    if persp:
        perspective(0.3, 2.0, 8.0)
    else:
        ortho(1.25, 0.0, 10.0)
    on = lights({0, 1, 2})
    material(GL.GL_FRONT, ambient=(0.2, 0.2, 0.2, 1.0), diffuse=(0.8, 0.8, 0.8, 1.0),
             specular=(0.6, 0.6, 0.6, 1.0), emission=(0.0, 0.0, 0.0, 1.0), shininess=30.0)
    mode, onehot = FOGS[fog]
    GL.glFogi(GL.GL_FOG_MODE, mode)
    GL.glFogf(GL.GL_FOG_START, 4.2)
    GL.glFogf(GL.GL_FOG_END, 6.5)
    GL.glFogf(GL.GL_FOG_DENSITY, 0.18)
    GL.glFogfv(GL.GL_FOG_COLOR, bg)
    GL.glTranslatef(0.0, 0.0, -5.0)
    GL.glRotatef(30.0, 0.0, 1.0, 0.0)
    GL.glRotatef(-20.0, 1.0, 0.0, 0.0)
    m = GL.glGetFloatv(GL.GL_MODELVIEW_MATRIX)
    # Object-space directions the model-view maps to eye +x, +y: rows of
    # its rotation (m[col][row] in PyOpenGL's column-major result).
    uniform(p, "right_vector", m[0][0], m[1][0], m[2][0], optional=seed_text)
    uniform(p, "up_vector", m[0][1], m[1][1], m[2][1], optional=seed_text)
    uniform(p, "perspective", 1.0 if persp else 0.0, optional=seed_text)
    # The library's impostors cast each pixel's ray from gl_FragCoord.
    uniform(p, "viewport", *[float(v) for v in GL.glGetIntegerv(GL.GL_VIEWPORT)],
            optional=seed_text)
    uniform(p, "fogging", *[1.0 if i == onehot else 0.0 for i in range(4)], count=4, optional=seed_text)
    if not seed_text:
        uniform(p, "light_enabled", *on, count=8)
    if extra:
        extra(p)
    GL.glBegin(GL.GL_QUADS)
    for c, r, col in ATOMS:
        GL.glColor4f(*col)
        for right, up in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            GL.glMultiTexCoord3f(GL.GL_TEXTURE0, right, up, r)
            GL.glVertex3f(*c)
    GL.glEnd()


def sphere_scene(persp, fog):
    def f(log):
        impostors(lib("sphere.vert"), lib("sphere.frag"), persp, fog)
    return f


for _proj in ("ortho", "persp"):
    for _fog in FOGS:
        scene(f"sphere_{_proj}_fog_{_fog}")(sphere_scene(_proj == "persp", _fog))


def effect(name, vs, fs, extra=None):
    for proj in ("ortho", "persp"):
        def f(log, proj=proj):
            impostors(lib(vs), lib(fs), proj == "persp", "linear", extra)
        scene(f"{name}_{proj}")(f)


effect("outline", "sphere.vert", "outline.frag",
       lambda p: uniform(p, "outline_width", 0.07))
effect("x", "x.vert", "x.frag")
effect("x_yellow_on_red", "x.vert", "x-red.frag")
effect("transparent", "sphere.vert", "transparent.frag")


@scene("seed_sphere_as_written")
def seed_sphere(log):
    # The talk's own pair (its exp2 slip included; linear fog avoids it).
    impostors(seed("000-sphere.vert"), seed("000-sphere.frag"), False, "linear",
              seed_text=True)


@scene("seed_x_as_written")
def seed_x(log):
    impostors(seed("000-x.vert"), seed("000-x.frag"), False, "linear", seed_text=True)


if __name__ == "__main__":
    sys.exit(main())
