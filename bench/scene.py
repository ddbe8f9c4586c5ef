#!/usr/bin/env python3
"""One benchmark scene on whichever libOSMesa PyOpenGL loads.

    PYOPENGL_PLATFORM=osmesa [LD_LIBRARY_PATH=DIR] python3 bench/scene.py SPEC \
        --frames N --budget SECONDS --out PIXELS.bin

bench/run.py starts this once per (implementation, scene) so each runs in its
own process with its own library. SPEC names the scene (see `build` below):

    adk:WxH:ortho|persp:none|linear|exp|exp2[:seed|:points]
                                                     a real structure, 47,681
                                                     atoms (bench/structure.py:
                                                     adenylate kinase in water,
                                                     fetched once), as the
                                                     spheres scenes draw atoms
    spheres:N:WxH:ortho|persp:none|linear|exp|exp2[:OPTION...]
                                                     sphere impostors of
                                                     shaders/sphere.*; options:
                                                     dense: protein density
                                                     (0.09 atoms per Å³, many
                                                     spheres behind a pixel)
                                                     instead of one atom per
                                                     1000 Å³; seed: the seed
                                                     talk's sphere shaders as
                                                     written (rays from
                                                     interpolated varyings,
                                                     crates/glsl/tests/seeds/
                                                     000-sphere.*); points:
                                                     one point per atom
                                                     expanded by
                                                     shaders/sphere.geom
                                                     (GL_EXT_geometry_shader4,
                                                     shaderbox only); tris:
                                                     each quad as the two
                                                     GL_TRIANGLES the points'
                                                     strip makes (an ablation)
    mesh:TRIANGLES:WxH                               seed materials shader
    ffmesh:TRIANGLES:WxH                             fixed-function lighting + fog
    textured:LAYERS:WxH[:notex][:noblend][:texN]     mipmapped texture layers
                                                     (options for ablations:
                                                     no texturing, no blending,
                                                     an N×N texture)
    tiny:TRIANGLES:WxH                               many sub-pixel triangles
    compile:sphere|materials                         compile + link time
    core-spheres|core-mesh|core-itex:...             OpenGL 3.3 core scenes
                                                     (bench/scenes33.py)

A frame is glClear + the scene's draws + glFinish. --count-fragments also
reports how many fragments the scene's draws rasterize ("fragments": the
samples an occlusion query counts with the fragment shader replaced by one
that writes a constant and the depth test off, i.e. every fragment the
real program shades, as it writes gl_FragDepth and so cannot be culled
before shading), for costs per fragment. Warm-up frames (at least
one, until WARMUP_SECONDS have gone), then
frames until N are timed or the time budget is spent (at least 2). Prints
one JSON line: {"renderer", "warmup", "times": [seconds...]}; --out gets the
last frame's RGBA pixels (bottom row first) for the image comparison.
Everything is generated from fixed seeds, so both implementations draw the
same data. Needs only PyOpenGL (no numpy).
"""
import argparse
import array
import ctypes
import gc
import json
import math
import os
import random
import sys
import time

import OpenGL

OpenGL.ERROR_CHECKING = False
from OpenGL import GL, arrays, osmesa  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Lights of crates/render (eye-space direction, ambient, diffuse, specular).
LIGHTS = [
    ([-0.4, 0.55, 1.0, 0.0], 0.15, 0.75, 0.6),
    ([0.6, -0.3, 0.7, 0.0], 0.05, 0.3, 0.15),
]
# Element-like radius and colour of the random atoms.
ELEMENTS = [
    (1.70, (0.55, 0.55, 0.55), 0.55),
    (1.55, (0.19, 0.31, 0.97), 0.2),
    (1.52, (1.0, 0.05, 0.05), 0.2),
    (1.80, (1.0, 1.0, 0.19), 0.05),
]
FOG_AT_BACK = 0.35
# A quad's corners (GL_QUADS), and the same quad as the two triangles of
# sphere.geom's strip (-1,-1), (1,-1), (-1,1), (1,1).
QUAD_CORNERS = ((-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0))
TRI_CORNERS = ((-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0))
# Seconds of untimed frames before the timed ones (see main).
WARMUP_SECONDS = 0.5
# Volume per random atom (Å^3): a sparse cloud, and protein density
# (about 0.09 atoms per Å^3 counting hydrogens).
ATOM_VOLUME = 1000.0
DENSE_ATOM_VOLUME = 1.0 / 0.09
# The seed talk's sphere pair; the files carry their GLSL version in a
# header comment only.
SEED_SPHERE = ("crates/glsl/tests/seeds/000-sphere.vert", "crates/glsl/tests/seeds/000-sphere.frag")


def read(path):
    with open(os.path.join(ROOT, path)) as f:
        return f.read()


def program(vs_src, fs_src, gs_src=None, gs_params=()):
    """Compiles and links; a geometry shader (GL_EXT_geometry_shader4) gets
    its (pname, value) program parameters before the link."""
    def shader(kind, src):
        s = GL.glCreateShader(kind)
        GL.glShaderSource(s, src)
        GL.glCompileShader(s)
        if not GL.glGetShaderiv(s, GL.GL_COMPILE_STATUS):
            raise RuntimeError(GL.glGetShaderInfoLog(s))
        return s

    p = GL.glCreateProgram()
    GL.glAttachShader(p, shader(GL.GL_VERTEX_SHADER, vs_src))
    GL.glAttachShader(p, shader(GL.GL_FRAGMENT_SHADER, fs_src))
    if gs_src is not None:
        from OpenGL.GL.EXT import geometry_shader4 as ext
        GL.glAttachShader(p, shader(ext.GL_GEOMETRY_SHADER_EXT, gs_src))
        for pname, value in gs_params:
            ext.glProgramParameteriEXT(p, pname, value)
    GL.glLinkProgram(p)
    if not GL.glGetProgramiv(p, GL.GL_LINK_STATUS):
        raise RuntimeError(GL.glGetProgramInfoLog(p))
    return p


def vbo(data):
    """Uploads an array.array to a new GL_ARRAY_BUFFER (or element buffer)."""
    name = GL.glGenBuffers(1)
    target = GL.GL_ELEMENT_ARRAY_BUFFER if data.typecode == "I" else GL.GL_ARRAY_BUFFER
    GL.glBindBuffer(target, name)
    ptr = (ctypes.c_char * (len(data) * data.itemsize)).from_buffer(data)
    GL.glBufferData(target, len(data) * data.itemsize, ptr, GL.GL_STATIC_DRAW)
    return name


def set_lights(count=2):
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()
    for i, (pos, a, d, s) in enumerate(LIGHTS[:count]):
        light = GL.GL_LIGHT0 + i
        GL.glLightfv(light, GL.GL_POSITION, pos)
        GL.glLightfv(light, GL.GL_AMBIENT, [a, a, a, 1.0])
        GL.glLightfv(light, GL.GL_DIFFUSE, [d, d, d, 1.0])
        GL.glLightfv(light, GL.GL_SPECULAR, [s, s, s, 1.0])
        GL.glEnable(light)
    GL.glEnable(GL.GL_LIGHTING)
    for pname, v in ((GL.GL_AMBIENT, 1.0), (GL.GL_DIFFUSE, 1.0), (GL.GL_SPECULAR, 1.0)):
        GL.glMaterialfv(GL.GL_FRONT_AND_BACK, pname, [v, v, v, 1.0])
    GL.glMaterialfv(GL.GL_FRONT_AND_BACK, GL.GL_EMISSION, [0.0, 0.0, 0.0, 1.0])
    GL.glMaterialf(GL.GL_FRONT_AND_BACK, GL.GL_SHININESS, 50.0)


def camera(center, radius, proj, w, h):
    """The projection and model-view of crates/render's camera fit; returns
    (distance, radius) for the fog range."""
    fitted = radius * 1.05
    aspect = w / h
    GL.glMatrixMode(GL.GL_PROJECTION)
    GL.glLoadIdentity()
    if proj == "ortho":
        hw, hh = (fitted * aspect, fitted) if aspect >= 1 else (fitted, fitted / aspect)
        d = 3.0 * radius
        GL.glOrtho(-hw, hw, -hh, hh, d - 1.5 * radius, d + 1.5 * radius)
    else:
        t = math.tan(math.radians(15.0))
        tx, ty = (t * aspect, t) if aspect >= 1 else (t, t / aspect)
        tm = min(tx, ty)
        d = fitted * math.sqrt(1 + tm * tm) / tm
        near = max(d - 1.1 * radius, d * 0.01)
        GL.glFrustum(-near * tx, near * tx, -near * ty, near * ty, near, d + 1.1 * radius)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()
    GL.glTranslatef(0.0, 0.0, -d)
    GL.glRotatef(20.0, 1.0, 0.0, 0.0)
    GL.glRotatef(30.0, 0.0, 1.0, 0.0)
    GL.glTranslatef(-center[0], -center[1], -center[2])
    return d, radius


def random_atoms(n, options):
    """n random atoms in a ball: [(position, radius, colour)] and the
    ball's radius. Sparse, one atom per 1000 Å^3, so 20,000 atoms at 1024²
    cover about two million fragments (depth complexity ~2); dense, the same
    atoms at protein density."""
    rng = random.Random(7)
    volume = DENSE_ATOM_VOLUME if "dense" in options else ATOM_VOLUME
    big_r = (3.0 * volume * n / (4.0 * math.pi)) ** (1.0 / 3.0)
    cum = []
    acc = 0.0
    for e in ELEMENTS:
        acc += e[2]
        cum.append(acc)
    out = []
    for _ in range(n):
        while True:
            p = [rng.uniform(-big_r, big_r) for _ in range(3)]
            if p[0] ** 2 + p[1] ** 2 + p[2] ** 2 <= big_r * big_r:
                break
        u = rng.random() * acc
        r, c, _ = next(e for e, k in zip(ELEMENTS, cum) if u <= k)
        out.append((p, r, c))
    return out, big_r


def spheres(n, proj, fog, w, h, options=()):
    atoms, big_r = random_atoms(n, options)
    return impostors(atoms, ((0.0, 0.0, 0.0), big_r), proj, fog, (w, h), options)


def structure(proj, fog, w, h, options=()):
    """bench/structure.py's adenylate kinase system, framed as
    crates/render frames a molecule (centre of the atoms, radius to the
    farthest)."""
    import structure as adk
    atoms = adk.atoms(adk.adk_path())
    n = len(atoms)
    centre = [sum(a[0][k] for a in atoms) / n for k in range(3)]
    big_r = max(math.dist(a[0], centre) for a in atoms)
    return impostors(atoms, (centre, big_r), proj, fog, (w, h), options)


def impostors(atoms, bounds, proj, fog, size, options):
    """Sphere impostors of `atoms` [(position, radius, colour)] inside the
    ball `bounds` (centre, radius), with the library's shaders, the seed's
    as written (`seed`) or one point per atom (`points`)."""
    points, tris = "points" in options, "tris" in options
    (w, h), n = size, len(atoms)
    pos, tex, col = array.array("f"), array.array("f"), array.array("f")
    for p, r, c in atoms:
        if points:
            pos.extend(p)
            tex.append(r)
            col.extend((c[0], c[1], c[2], 1.0))
            continue
        for x, y in TRI_CORNERS if tris else QUAD_CORNERS:
            pos.extend(p)
            tex.extend((x, y, r))
            col.extend((c[0], c[1], c[2], 1.0))
    if points:
        from OpenGL.GL.EXT import geometry_shader4 as ext
        params = [(ext.GL_GEOMETRY_INPUT_TYPE_EXT, GL.GL_POINTS),
                  (ext.GL_GEOMETRY_OUTPUT_TYPE_EXT, GL.GL_TRIANGLE_STRIP),
                  (ext.GL_GEOMETRY_VERTICES_OUT_EXT, 4)]
        prog = program(read("shaders/sphere-point.vert"), read("shaders/sphere.frag"),
                       read("shaders/sphere.geom"), params)
    elif "seed" in options:
        prog = program("#version 120\n" + read(SEED_SPHERE[0]),
                       "#version 120\n" + read(SEED_SPHERE[1]))
    else:
        prog = program(read("shaders/sphere.vert"), read("shaders/sphere.frag"))
    set_lights()
    dist, rad = camera(bounds[0], bounds[1] + 1.8, proj, w, h)
    front, back = dist - rad, dist + rad
    k = -math.log(FOG_AT_BACK)
    GL.glFogi(GL.GL_FOG_MODE, {"exp": GL.GL_EXP, "exp2": GL.GL_EXP2}.get(fog, GL.GL_LINEAR))
    GL.glFogf(GL.GL_FOG_START, front)
    GL.glFogf(GL.GL_FOG_END, (back - FOG_AT_BACK * front) / (1.0 - FOG_AT_BACK))
    GL.glFogf(GL.GL_FOG_DENSITY, math.sqrt(k) / back if fog == "exp2" else k / back)
    GL.glFogfv(GL.GL_FOG_COLOR, [0.0, 0.0, 0.0, 1.0])
    mv = GL.glGetFloatv(GL.GL_MODELVIEW_MATRIX)
    flat = [float(v) for row in mv for v in row] if hasattr(mv[0], "__len__") else list(mv)
    right = [flat[0], flat[4], flat[8]]
    up = [flat[1], flat[5], flat[9]]
    GL.glUseProgram(prog)
    GL.glUniform3f(GL.glGetUniformLocation(prog, "right_vector"), *right)
    GL.glUniform3f(GL.glGetUniformLocation(prog, "up_vector"), *up)
    GL.glUniform1f(GL.glGetUniformLocation(prog, "perspective"), 1.0 if proj == "persp" else 0.0)
    GL.glUniform4f(GL.glGetUniformLocation(prog, "viewport"), 0.0, 0.0, float(w), float(h))
    onehot = [1.0 if m == fog else 0.0 for m in ("none", "linear", "exp", "exp2")]
    GL.glUniform1fv(GL.glGetUniformLocation(prog, "fogging"), 4, onehot)
    GL.glUniform1fv(GL.glGetUniformLocation(prog, "light_enabled"), 8, [1.0, 1.0] + [0.0] * 6)
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glDepthFunc(GL.GL_LESS)
    bufs = [vbo(pos), vbo(tex), vbo(col)]
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, bufs[0])
    GL.glVertexPointer(3, GL.GL_FLOAT, 0, None)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, bufs[1])
    GL.glClientActiveTexture(GL.GL_TEXTURE0)
    GL.glTexCoordPointer(1 if points else 3, GL.GL_FLOAT, 0, None)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, bufs[2])
    GL.glColorPointer(4, GL.GL_FLOAT, 0, None)
    for s in (GL.GL_VERTEX_ARRAY, GL.GL_TEXTURE_COORD_ARRAY, GL.GL_COLOR_ARRAY):
        GL.glEnableClientState(s)
    if points:
        return lambda: GL.glDrawArrays(GL.GL_POINTS, 0, n)
    if tris:
        return lambda: GL.glDrawArrays(GL.GL_TRIANGLES, 0, 6 * n)
    count = 4 * n
    return lambda: GL.glDrawArrays(GL.GL_QUADS, 0, count)


def surface(triangles, seed=3):
    """A wavy lit surface: a grid of about `triangles` triangles folded into
    three overlapping sheets (depth complexity ~3) in [-1, 1]^2."""
    side = max(2, int(math.sqrt(triangles / 6.0)))
    pos, nrm, col, idx = array.array("f"), array.array("f"), array.array("f"), array.array("I")
    rng = random.Random(seed)
    for sheet in range(3):
        base = len(pos) // 3
        ph = rng.uniform(0, 6.28)
        z0 = -0.3 + 0.3 * sheet
        c = [(0.9, 0.4, 0.3), (0.3, 0.8, 0.4), (0.35, 0.45, 0.95)][sheet]
        for j in range(side + 1):
            v = -1.0 + 2.0 * j / side
            for i in range(side + 1):
                u = -1.0 + 2.0 * i / side
                a, b = 5.0 * u + ph, 4.0 * v - ph
                z = z0 + 0.15 * math.sin(a) * math.cos(b)
                dzdu = 0.75 * math.cos(a) * math.cos(b)
                dzdv = -0.6 * math.sin(a) * math.sin(b)
                ln = math.sqrt(dzdu * dzdu + dzdv * dzdv + 1.0)
                pos.extend((u, v, z))
                nrm.extend((-dzdu / ln, -dzdv / ln, 1.0 / ln))
                col.extend((c[0], c[1], c[2], 1.0))
        for j in range(side):
            for i in range(side):
                k = base + j * (side + 1) + i
                idx.extend((k, k + 1, k + side + 2, k, k + side + 2, k + side + 1))
    return pos, nrm, col, idx


def mesh(triangles, w, h, shaded):
    pos, nrm, col, idx = surface(triangles)
    set_lights()
    GL.glMatrixMode(GL.GL_PROJECTION)
    GL.glLoadIdentity()
    GL.glFrustum(-0.5 * w / h, 0.5 * w / h, -0.5, 0.5, 1.5, 6.0)
    GL.glMatrixMode(GL.GL_MODELVIEW)
    GL.glLoadIdentity()
    GL.glTranslatef(0.0, 0.0, -3.0)
    GL.glRotatef(-35.0, 1.0, 0.0, 0.0)
    GL.glRotatef(15.0, 0.0, 0.0, 1.0)
    if shaded:
        vs = read("crates/glsl/tests/seeds/000-materials.vert")
        fs = read("crates/glsl/tests/seeds/000-materials.frag")
        GL.glUseProgram(program(vs, fs))
    else:
        GL.glShadeModel(GL.GL_SMOOTH)
        GL.glEnable(GL.GL_COLOR_MATERIAL)
        GL.glColorMaterial(GL.GL_FRONT_AND_BACK, GL.GL_AMBIENT_AND_DIFFUSE)
        GL.glLightModeli(GL.GL_LIGHT_MODEL_TWO_SIDE, GL.GL_TRUE)
        GL.glEnable(GL.GL_FOG)
        GL.glFogi(GL.GL_FOG_MODE, GL.GL_LINEAR)
        GL.glFogf(GL.GL_FOG_START, 2.0)
        GL.glFogf(GL.GL_FOG_END, 5.0)
        GL.glFogfv(GL.GL_FOG_COLOR, [0.1, 0.1, 0.15, 1.0])
    GL.glEnable(GL.GL_DEPTH_TEST)
    bufs = [vbo(pos), vbo(nrm), vbo(col)]
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, bufs[0])
    GL.glVertexPointer(3, GL.GL_FLOAT, 0, None)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, bufs[1])
    GL.glNormalPointer(GL.GL_FLOAT, 0, None)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, bufs[2])
    GL.glColorPointer(4, GL.GL_FLOAT, 0, None)
    for s in (GL.GL_VERTEX_ARRAY, GL.GL_NORMAL_ARRAY, GL.GL_COLOR_ARRAY):
        GL.glEnableClientState(s)
    vbo(idx)  # stays bound as GL_ELEMENT_ARRAY_BUFFER
    count = len(idx)
    return lambda: GL.glDrawElements(GL.GL_TRIANGLES, count, GL.GL_UNSIGNED_INT, None)


def textured(layers, w, h, options=()):
    """`layers` blended, tilted, textured planes: a 512² procedural texture
    with mipmaps (GL_GENERATE_MIPMAP), trilinear filtering, modulated by the
    vertex colour. `options` (for ablations): "notex" draws the planes
    untextured, "noblend" without blending, "texN" uses an N×N texture."""
    size = 512
    for o in options:
        if o.startswith("tex") and o[3:].isdigit():
            size = int(o[3:])
        elif o not in ("notex", "noblend"):
            raise SystemExit(f"unknown textured option {o!r}")
    rng = random.Random(5)
    cells = [[rng.random() for _ in range(16)] for _ in range(16)]
    texels = bytearray(size * size * 4)
    for y in range(size):
        for x in range(size):
            c = cells[y * 16 // size][x * 16 // size]
            check = ((x >> 3) ^ (y >> 3)) & 1
            i = 4 * (y * size + x)
            texels[i] = int(255 * c)
            texels[i + 1] = 64 + 160 * check
            texels[i + 2] = (x * 255) // size
            texels[i + 3] = 200
    tex = GL.glGenTextures(1)
    GL.glBindTexture(GL.GL_TEXTURE_2D, tex)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_GENERATE_MIPMAP, GL.GL_TRUE)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_LINEAR_MIPMAP_LINEAR)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_LINEAR)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_S, GL.GL_REPEAT)
    GL.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_T, GL.GL_REPEAT)
    data = (ctypes.c_ubyte * len(texels)).from_buffer(texels)
    GL.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL.GL_RGBA, size, size, 0, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, data)
    if "notex" not in options:
        GL.glEnable(GL.GL_TEXTURE_2D)
    GL.glTexEnvi(GL.GL_TEXTURE_ENV, GL.GL_TEXTURE_ENV_MODE, GL.GL_MODULATE)
    if "noblend" not in options:
        GL.glEnable(GL.GL_BLEND)
    GL.glBlendFunc(GL.GL_SRC_ALPHA, GL.GL_ONE_MINUS_SRC_ALPHA)
    GL.glMatrixMode(GL.GL_PROJECTION)
    GL.glLoadIdentity()
    GL.glFrustum(-0.1 * w / h, 0.1 * w / h, -0.1, 0.1, 0.1, 40.0)
    pos, tc, col = array.array("f"), array.array("f"), array.array("f")
    for k in range(layers):
        # Planes receding into the distance at different tilts and scales.
        tilt = -60.0 + 120.0 * k / max(1, layers - 1)
        s = 6.0 + 2.0 * k
        ca, sa = math.cos(math.radians(tilt)), math.sin(math.radians(tilt))
        for u, v in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            x, y = 4.0 * u, 4.0 * v * ca
            z = -6.0 - 4.0 * v * sa - 0.5 * k
            pos.extend((x, y, z))
            tc.extend((s * (u + 1) / 2, s * (v + 1) / 2))
            col.extend((1.0, 1.0 - 0.05 * k, 0.8 + 0.02 * k, 0.6))
    bufs = [vbo(pos), vbo(tc), vbo(col)]
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, bufs[0])
    GL.glVertexPointer(3, GL.GL_FLOAT, 0, None)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, bufs[1])
    GL.glTexCoordPointer(2, GL.GL_FLOAT, 0, None)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, bufs[2])
    GL.glColorPointer(4, GL.GL_FLOAT, 0, None)
    for s in (GL.GL_VERTEX_ARRAY, GL.GL_TEXTURE_COORD_ARRAY, GL.GL_COLOR_ARRAY):
        GL.glEnableClientState(s)
    count = 4 * layers
    return lambda: GL.glDrawArrays(GL.GL_QUADS, 0, count)


def tiny(triangles, w, h):
    """Geometry-bound: random triangles about half a pixel across, flat
    colours, depth test, no shaders."""
    rng = random.Random(11)
    pos, col = array.array("f"), array.array("f")
    px = 2.0 / w
    for _ in range(triangles):
        x, y, z = rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)
        c = (rng.random(), rng.random(), rng.random(), 1.0)
        for dx, dy in ((0.0, 0.0), (1.5 * px, 0.2 * px), (0.3 * px, 1.4 * px)):
            pos.extend((x + dx, y + dy, z))
            col.extend(c)
    GL.glEnable(GL.GL_DEPTH_TEST)
    bufs = [vbo(pos), vbo(col)]
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, bufs[0])
    GL.glVertexPointer(3, GL.GL_FLOAT, 0, None)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, bufs[1])
    GL.glColorPointer(4, GL.GL_FLOAT, 0, None)
    GL.glEnableClientState(GL.GL_VERTEX_ARRAY)
    GL.glEnableClientState(GL.GL_COLOR_ARRAY)
    count = 3 * triangles
    return lambda: GL.glDrawArrays(GL.GL_TRIANGLES, 0, count)


def compile_times(which, frames, budget):
    if which == "sphere":
        vs, fs = read("shaders/sphere.vert"), read("shaders/sphere.frag")
    else:
        vs = read("crates/glsl/tests/seeds/000-materials.vert")
        fs = read("crates/glsl/tests/seeds/000-materials.frag")
    for _ in range(3):
        program(vs, fs)
    times = []
    start = time.perf_counter()
    while len(times) < frames * 20 and (len(times) < 20 or time.perf_counter() - start < budget):
        t = time.perf_counter()
        program(vs, fs)
        GL.glFinish()
        times.append(time.perf_counter() - t)
    return times


def count_fragments(draw):
    """The fragments the draws rasterize (module docs): an occlusion query
    over one frame with the current program's vertex shader linked to a
    constant fragment shader, and no depth test. Restores the state."""
    current = GL.glGetIntegerv(GL.GL_CURRENT_PROGRAM)
    current = int(current[0] if hasattr(current, "__len__") else current)
    counter = None
    if current:
        shaders = GL.glGetAttachedShaders(current)
        vertex = [sh for sh in shaders
                  if GL.glGetShaderiv(sh, GL.GL_SHADER_TYPE) == GL.GL_VERTEX_SHADER]
        counter = GL.glCreateProgram()
        for sh in vertex:
            GL.glAttachShader(counter, sh)
        fs = GL.glCreateShader(GL.GL_FRAGMENT_SHADER)
        GL.glShaderSource(fs, "void main() { gl_FragColor = vec4(1.0); }")
        GL.glCompileShader(fs)
        GL.glAttachShader(counter, fs)
        GL.glLinkProgram(counter)
        if not GL.glGetProgramiv(counter, GL.GL_LINK_STATUS):
            raise SystemExit(f"fragment counter link: {GL.glGetProgramInfoLog(counter)}")
        # The scene's uniforms (the vertex shader's among them) are set on
        # its own program: copy those the vertex shader reads.
        GL.glUseProgram(counter)
        for i in range(GL.glGetProgramiv(counter, GL.GL_ACTIVE_UNIFORMS)):
            name, size, kind = GL.glGetActiveUniform(counter, i)
            name = bytes(name).split(b"\0")[0].decode()
            width = {GL.GL_FLOAT: 1, GL.GL_FLOAT_VEC2: 2, GL.GL_FLOAT_VEC3: 3,
                     GL.GL_FLOAT_VEC4: 4}.get(kind)
            if name.startswith("gl_"):
                continue
            if width is None or size != 1:
                raise SystemExit(f"fragment counter: uniform {name} of type {kind:#x} not copied")
            v = (ctypes.c_float * 4)()
            GL.glGetUniformfv(current, GL.glGetUniformLocation(current, name), v)
            setter = (GL.glUniform1f, GL.glUniform2f, GL.glUniform3f, GL.glUniform4f)[width - 1]
            setter(GL.glGetUniformLocation(counter, name), *list(v)[:width])
        GL.glUseProgram(counter)
    depth = GL.glIsEnabled(GL.GL_DEPTH_TEST)
    GL.glDisable(GL.GL_DEPTH_TEST)
    query = GL.glGenQueries(1)
    query = int(query[0] if hasattr(query, "__len__") else query)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
    GL.glBeginQuery(GL.GL_SAMPLES_PASSED, query)
    draw()
    GL.glEndQuery(GL.GL_SAMPLES_PASSED)
    n = GL.glGetQueryObjectuiv(query, GL.GL_QUERY_RESULT)
    n = int(n[0] if hasattr(n, "__len__") else n)
    GL.glDeleteQueries(1, [query])
    if depth:
        GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glUseProgram(current)
    if counter is not None:
        GL.glDeleteProgram(counter)
    return n


def parse_size(s):
    w, h = s.split("x")
    return int(w), int(h)


def build(spec):
    """(width, height, draw) for a scene spec."""
    kind, *args = spec.split(":")
    if kind == "spheres":
        w, h = parse_size(args[1])
        options = tuple(args[4:])
        known = ("points", "tris", "dense", "seed")
        if any(o not in known for o in options) or ("seed" in options and
                                                    ("points" in options or "tris" in options)):
            raise SystemExit(f"unknown sphere option (or combination) in {spec!r}")
        return w, h, lambda: spheres(int(args[0]), args[2], args[3], w, h, options)
    if kind == "adk":
        w, h = parse_size(args[0])
        options = tuple(args[3:])
        if any(o not in ("seed", "points") for o in options) or len(options) > 1:
            raise SystemExit(f"unknown structure option (or combination) in {spec!r}")
        return w, h, lambda: structure(args[1], args[2], w, h, options)
    if kind in ("mesh", "ffmesh"):
        w, h = parse_size(args[1])
        return w, h, lambda: mesh(int(args[0]), w, h, kind == "mesh")
    if kind == "textured":
        w, h = parse_size(args[1])
        return w, h, lambda: textured(int(args[0]), w, h, tuple(args[2:]))
    if kind == "tiny":
        w, h = parse_size(args[1])
        return w, h, lambda: tiny(int(args[0]), w, h)
    if kind == "compile":
        return 64, 64, None
    import scenes33
    core = scenes33.build(kind, args, parse_size)
    if core is not None:
        return core
    raise SystemExit(f"unknown scene {spec!r}")


def create_context(spec):
    """A compatibility context (OSMesaCreateContextExt), or for the core-*
    scenes a 3.3 core one (OSMesaCreateContextAttribs, PyOpenGL >= 3.1.10)."""
    if not spec.startswith("core-"):
        return osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 24, 8, 0, None)
    attribs = [osmesa.OSMESA_FORMAT, osmesa.OSMESA_RGBA, osmesa.OSMESA_DEPTH_BITS, 24,
               osmesa.OSMESA_STENCIL_BITS, 8, osmesa.OSMESA_PROFILE, osmesa.OSMESA_CORE_PROFILE,
               osmesa.OSMESA_CONTEXT_MAJOR_VERSION, 3, osmesa.OSMESA_CONTEXT_MINOR_VERSION, 3, 0]
    return osmesa.OSMesaCreateContextAttribs((ctypes.c_int * len(attribs))(*attribs), None)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("spec")
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--budget", type=float, default=20.0, help="seconds of timed frames at most")
    ap.add_argument("--out")
    ap.add_argument("--count-fragments", action="store_true",
                    help="also report the fragments a frame rasterizes (module docs)")
    args = ap.parse_args()
    w, h, setup = build(args.spec)
    ctx = create_context(args.spec)
    if not ctx:
        raise SystemExit("creating the OSMesa context failed")
    buf = arrays.GLubyteArray.zeros((h, w, 4))
    if not osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_UNSIGNED_BYTE, w, h):
        raise SystemExit("OSMesaMakeCurrent failed")
    renderer = GL.glGetString(GL.GL_RENDERER).decode()
    result = {"renderer": renderer}
    if setup is None:
        result["times"] = compile_times(args.spec.split(":")[1], args.frames, args.budget)
        result["warmup"] = 0.0
    else:
        GL.glViewport(0, 0, w, h)
        GL.glClearColor(0.0, 0.0, 0.0, 1.0)
        draw = setup()
        err = GL.glGetError()
        if err:
            raise SystemExit(f"GL error {err:#x} during set-up")

        def frame():
            t = time.perf_counter()
            GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
            draw()
            GL.glFinish()
            return time.perf_counter() - t

        # Warm-up: the first frame (its time is reported), then more until
        # half a second has gone, so both implementations have compiled
        # their shaders (llvmpipe at the first draw, shaderbox's native
        # code on a background thread) before the timed frames.
        result["warmup"] = frame()
        warm = [result["warmup"]]
        while args.frames > 0 and sum(warm) < WARMUP_SECONDS and len(warm) < 20:
            warm.append(frame())
        result["warmup_frames"] = len(warm)
        times = []
        # Processor time (every thread of the process) beside the wall
        # time: on a shared machine it moves less with the neighbours'
        # load, which makes A/B comparisons of one renderer steadier.
        # Python's cyclic garbage collector is off while frames are timed
        # (as `timeit` does): its pauses, up to a few milliseconds a frame,
        # belong to neither renderer.
        gc.collect()
        gc.disable()
        cpu = time.process_time()
        start = time.perf_counter()
        while len(times) < args.frames and (len(times) < 2 or time.perf_counter() - start < args.budget):
            times.append(frame())
        result["times"] = times
        # (No timed frames with --frames 0: the warm-up frame's image only.)
        result["cpu_per_frame"] = (time.process_time() - cpu) / max(1, len(times))
        gc.enable()
        err = GL.glGetError()
        if err:
            raise SystemExit(f"GL error {err:#x} while drawing")
        if args.out:
            px = GL.glReadPixels(0, 0, w, h, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE)
            with open(args.out, "wb") as f:
                f.write(bytes(px))
        if args.count_fragments:
            result["fragments"] = count_fragments(draw)
            err = GL.glGetError()
            if err:
                raise SystemExit(f"GL error {err:#x} while counting fragments")
    print(json.dumps(result))


if __name__ == "__main__":
    sys.exit(main())
