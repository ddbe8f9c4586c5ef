"""Differential scenes: the shader library of shaders/ (the seeds' classic
pairs) with the GL state each reads — the texture combine library with each
mode on one texture and with two textures, Phong lighting with a
directional, a point and a spot light, two-sided lighting, toon shading,
the single-pass wireframe — plus fixed-function drawing with no shader
(texture environment, fog, two-sided lighting, clip plane).

Run by compare.py (python3 library_shaders.py OUTDIR [SCENE...]); see
harness.py.
"""
import ctypes
import math
import sys

from harness import (GL, lib, main, material, pattern_texture, perspective, program, scene,
                     tess_sphere, uniform, uniform_i)


def textured_quad():
    """A quad filling most of the view, vertex colours, coordinate sets 0
    (0..2 repeats) and 1 (0..3)."""
    corners = [(-0.9, -0.9, (1.0, 0.3, 0.2, 1.0)), (0.9, -0.9, (0.2, 1.0, 0.3, 0.8)),
               (0.9, 0.9, (0.3, 0.2, 1.0, 1.0)), (-0.9, 0.9, (1.0, 1.0, 0.4, 0.6))]
    GL.glBegin(GL.GL_QUADS)
    for x, y, col in corners:
        GL.glColor4f(*col)
        GL.glMultiTexCoord2f(GL.GL_TEXTURE0, (x + 0.9) / 0.9, (y + 0.9) / 0.9)
        GL.glMultiTexCoord2f(GL.GL_TEXTURE1, 1.5 * (x + 0.9) / 0.9, (y + 0.9) / 0.6)
        GL.glVertex2f(x, y)
    GL.glEnd()


MODES = {"replace": 0, "modulate": 1, "decal": 2, "blend": 3, "add": 4, "combine": 5}


def texture_scene(modes):
    def f(log):
        if len(modes) == 1:
            p = program([lib("texturing.vert")], [lib("single-texture.frag"), lib("texturing-lib.frag")])
        else:
            p = program([lib("texturing.vert")], [lib("multi-texture.frag"), lib("texturing-lib.frag")])
        GL.glClearColor(0.1, 0.1, 0.1, 1.0)
        GL.glClear(GL.GL_COLOR_BUFFER_BIT)
        pattern_texture(0, 32, (250, 40, 20, 255), (30, 200, 240, 90))
        pattern_texture(1, 16, (20, 20, 20, 255), (200, 220, 60, 160), cells=3)
        for unit in (0, 1):
            GL.glActiveTexture(GL.GL_TEXTURE0 + unit)
            GL.glTexEnvfv(GL.GL_TEXTURE_ENV, GL.GL_TEXTURE_ENV_COLOR,
                          (0.9, 0.5, 0.1, 1.0) if unit == 0 else (0.1, 0.6, 0.9, 1.0))
        GL.glActiveTexture(GL.GL_TEXTURE0)
        if len(modes) == 1:
            uniform_i(p, "TexUnit0", 0)
            uniform_i(p, "TexturingType", MODES[modes[0]])
        else:
            uniform_i(p, "TexUnit0", 0)
            uniform_i(p, "TexUnit1", 1)
            uniform_i(p, "TexturingType0", MODES[modes[0]])
            uniform_i(p, "TexturingType1", MODES[modes[1]])
        textured_quad()
    return f


for _m in MODES:
    scene(f"texture_single_{_m}")(texture_scene([_m]))
for _a, _b in (("modulate", "add"), ("decal", "blend"), ("replace", "combine"),
               ("blend", "modulate")):
    scene(f"texture_two_{_a}_{_b}")(texture_scene([_a, _b]))


def set_light(i, pos, diffuse, spot=None, atten=(1.0, 0.0, 0.0)):
    """Light i at `pos` (eye space: identity model-view), white-ish
    specular, optional spot (direction, cutoff, exponent)."""
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glPushMatrix()
    GL.glLoadIdentity()
    light = GL.GL_LIGHT0 + i
    GL.glLightfv(light, GL.GL_POSITION, pos)
    GL.glLightfv(light, GL.GL_AMBIENT, (0.08, 0.08, 0.08, 1.0))
    GL.glLightfv(light, GL.GL_DIFFUSE, diffuse)
    GL.glLightfv(light, GL.GL_SPECULAR, (0.7, 0.7, 0.7, 1.0))
    GL.glLightf(light, GL.GL_CONSTANT_ATTENUATION, atten[0])
    GL.glLightf(light, GL.GL_LINEAR_ATTENUATION, atten[1])
    GL.glLightf(light, GL.GL_QUADRATIC_ATTENUATION, atten[2])
    if spot:
        GL.glLightfv(light, GL.GL_SPOT_DIRECTION, spot[0])
        GL.glLightf(light, GL.GL_SPOT_CUTOFF, spot[1])
        GL.glLightf(light, GL.GL_SPOT_EXPONENT, spot[2])
    GL.glEnable(light)
    GL.glPopMatrix()


def lit_scene(fs, light_setup, draw=None, vs="lighting.vert", extra_fs=("phong-lighting-lib.frag",)):
    def f(log):
        p = program([lib(vs)], [lib(fs)] + [lib(x) for x in extra_fs])
        GL.glClearColor(0.0, 0.0, 0.05, 1.0)
        GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
        GL.glEnable(GL.GL_DEPTH_TEST)
        perspective(0.45)
        light_setup()
        material(ambient=(0.3, 0.25, 0.2, 1.0), diffuse=(0.8, 0.6, 0.4, 1.0),
                 specular=(0.6, 0.6, 0.6, 1.0), emission=(0.0, 0.0, 0.0, 1.0), shininess=20.0)
        GL.glLightModelfv(GL.GL_LIGHT_MODEL_AMBIENT, (0.1, 0.1, 0.1, 1.0))
        GL.glTranslatef(0.0, 0.0, -3.0)
        GL.glRotatef(20.0, 1.0, 0.5, 0.0)
        if draw:
            draw(p)
        else:
            tess_sphere(1.0, color=lambda n: (0.9, 0.7, 0.5, 1.0))
    return f


scene("phong_directional")(lit_scene(
    "one-sided-lighting.frag",
    lambda: set_light(0, (-1.0, 1.0, 1.5, 0.0), (0.9, 0.9, 0.8, 1.0))))
scene("phong_point")(lit_scene(
    "one-sided-lighting.frag",
    lambda: set_light(0, (1.2, 0.8, -1.0, 1.0), (1.0, 0.9, 0.7, 1.0), atten=(0.6, 0.2, 0.05))))
scene("phong_spot")(lit_scene(
    "one-sided-lighting.frag",
    lambda: set_light(0, (0.0, 0.0, 0.0, 1.0), (1.0, 1.0, 0.9, 1.0),
                      spot=((0.15, 0.1, -1.0), 20.0, 8.0))))
scene("phong_three_lights")(lit_scene(
    "one-sided-lighting.frag",
    lambda: (set_light(0, (-1.0, 1.0, 1.5, 0.0), (0.5, 0.5, 0.4, 1.0)),
             set_light(1, (1.2, -0.8, -1.5, 1.0), (0.2, 0.5, 0.9, 1.0), atten=(0.8, 0.1, 0.0)),
             set_light(2, (0.0, 0.0, 0.0, 1.0), (0.9, 0.4, 0.2, 1.0),
                       spot=((-0.2, 0.1, -1.0), 15.0, 4.0)))))


def open_tube(p):
    """An open cylinder around y, tilted: its inside (back faces) shows."""
    material(GL.GL_BACK, ambient=(0.2, 0.3, 0.2, 1.0), diffuse=(0.2, 0.8, 0.3, 1.0),
             specular=(0.2, 0.2, 0.2, 1.0), emission=(0.0, 0.0, 0.0, 1.0), shininess=5.0)
    GL.glRotatef(50.0, 1.0, 0.0, 0.0)
    GL.glBegin(GL.GL_QUAD_STRIP)
    n = 24
    for j in range(n + 1):
        a = 2 * math.pi * j / n
        x, z = math.cos(a), math.sin(a)
        GL.glNormal3f(x, 0.0, z)
        GL.glVertex3f(0.8 * x, 0.9, 0.8 * z)
        GL.glVertex3f(0.8 * x, -0.9, 0.8 * z)
    GL.glEnd()


scene("two_sided_lighting")(lit_scene(
    "two-sided-lighting.frag",
    lambda: (set_light(0, (-1.0, 1.0, 1.5, 0.0), (0.9, 0.9, 0.8, 1.0)),
             set_light(1, (0.5, -0.3, 0.5, 1.0), (0.5, 0.5, 0.9, 1.0))),
    draw=open_tube))

scene("toon")(lit_scene(
    "toon.frag", lambda: set_light(0, (-1.0, 1.0, 1.5, 0.0), (1.0, 1.0, 1.0, 1.0)), extra_fs=()))


@scene("wireframe")
def wireframe(log):
    p = program([lib("wireframe.vert")], [lib("wireframe.frag")])
    GL.glClearColor(1.0, 1.0, 1.0, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    GL.glEnable(GL.GL_DEPTH_TEST)
    perspective(0.45)
    vp = GL.glGetIntegerv(GL.GL_VIEWPORT)
    uniform(p, "viewport", *[float(x) for x in vp])
    uniform(p, "line_width", 1.0)
    uniform(p, "line_color", 0.0, 0.0, 0.0, 1.0)
    GL.glTranslatef(0.0, 0.0, -3.0)
    GL.glRotatef(30.0, 1.0, 1.0, 0.0)
    # An icosahedron-ish triangle fan set: an octahedron, each triangle
    # with its three corners on every vertex.
    pts = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    tris = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    GL.glBegin(GL.GL_TRIANGLES)
    for t in tris:
        corners = [pts[i] for i in t]
        nx = sum(c[0] for c in corners) / 3
        ny = sum(c[1] for c in corners) / 3
        nz = sum(c[2] for c in corners) / 3
        for c in corners:
            GL.glColor3f(0.6 + 0.3 * c[0], 0.6 + 0.3 * c[1], 0.6 + 0.3 * c[2])
            GL.glNormal3f(nx, ny, nz)
            for k in range(3):
                GL.glMultiTexCoord3f(GL.GL_TEXTURE0 + k, *corners[k])
            GL.glVertex3f(*c)
    GL.glEnd()


# ---- fixed function, no shader ----

@scene("ff_texture_env_fog")
def ff_texture_env_fog(log):
    GL.glClearColor(0.3, 0.3, 0.35, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    GL.glEnable(GL.GL_DEPTH_TEST)
    perspective(0.5)
    pattern_texture(0, 32, (250, 200, 20, 255), (30, 60, 240, 255))
    GL.glEnable(GL.GL_TEXTURE_2D)
    GL.glTexEnvi(GL.GL_TEXTURE_ENV, GL.GL_TEXTURE_ENV_MODE, GL.GL_MODULATE)
    GL.glEnable(GL.GL_FOG)
    GL.glFogi(GL.GL_FOG_MODE, GL.GL_EXP)
    GL.glFogf(GL.GL_FOG_DENSITY, 0.25)
    GL.glFogfv(GL.GL_FOG_COLOR, (0.3, 0.3, 0.35, 1.0))
    GL.glTranslatef(0.0, -0.5, -3.0)
    GL.glRotatef(-70.0, 1.0, 0.0, 0.0)
    GL.glBegin(GL.GL_QUADS)
    for (s, t, x, y) in ((0, 0, -2, -2), (3, 0, 2, -2), (3, 3, 2, 2), (0, 3, -2, 2)):
        GL.glColor3f(0.6 + 0.1 * s, 0.9, 0.7 + 0.1 * t)
        GL.glTexCoord2f(s, t)
        GL.glVertex3f(x, y, 0.0)
    GL.glEnd()


@scene("ff_two_sided_clip_plane")
def ff_two_sided_clip_plane(log):
    GL.glClearColor(0.0, 0.0, 0.0, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    GL.glEnable(GL.GL_DEPTH_TEST)
    perspective(0.45)
    GL.glEnable(GL.GL_LIGHTING)
    set_light(0, (-1.0, 1.0, 1.5, 0.0), (0.9, 0.9, 0.8, 1.0))
    GL.glLightModeli(GL.GL_LIGHT_MODEL_TWO_SIDE, GL.GL_TRUE)
    material(GL.GL_FRONT, diffuse=(0.9, 0.5, 0.2, 1.0))
    material(GL.GL_BACK, diffuse=(0.2, 0.5, 0.9, 1.0), specular=(0.0, 0.0, 0.0, 1.0))
    GL.glTranslatef(0.0, 0.0, -3.0)
    GL.glRotatef(25.0, 1.0, 0.4, 0.0)
    # Cut the sphere's front cap off: its inside shows, lit as back faces.
    GL.glClipPlane(GL.GL_CLIP_PLANE0, (ctypes.c_double * 4)(0.3, 0.2, -1.0, 0.33))
    GL.glEnable(GL.GL_CLIP_PLANE0)
    tess_sphere(1.0)


if __name__ == "__main__":
    sys.exit(main())
