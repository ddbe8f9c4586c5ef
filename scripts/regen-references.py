#!/usr/bin/env python3
"""Regenerates the reference images of crates/render/tests/references/ with
Mesa (llvmpipe through Debian's libosmesa6 and PyOpenGL).

For every effect x fog mode x projection of spacefill, and every fog mode x
projection of ball-and-stick, it runs

    shaderbox render --size 256x256 ... --export-scene SCENE.json

which writes every GL call shaderbox made (the library's shader sources,
matrices, lights, material, fog, uniforms by name, the vertex arrays), then
replays those calls through PyOpenGL on Mesa's OSMesa and stores what Mesa
drew as NAME.png (RGB, top row first). So the references are Mesa running
the same library shaders with the same state and geometry; the Rust test
crates/render/tests/references.rs renders the same scenes with shaderbox and
compares.

Usage: scripts/regen-references.py [SHADERBOX_BINARY]
  (default: $CARGO_TARGET_DIR or target, release, then debug build)
Needs: python3, PyOpenGL, libosmesa6 (apt-get install python3-opengl
libosmesa6). Mesa is picked with PYOPENGL_PLATFORM=osmesa, set here.
"""
import ctypes
import json
import os
import struct
import subprocess
import sys
import tempfile
import zlib

os.environ["PYOPENGL_PLATFORM"] = "osmesa"
from OpenGL import GL, arrays, osmesa  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "crates", "render", "tests", "references")
SIZE = 256
EFFECTS = ["plain", "outline", "x", "x-red", "transparent"]
FOGS = ["none", "linear", "exp", "exp2"]
PROJECTIONS = ["ortho", "perspective"]


def cases():
    """(file name, shaderbox render arguments) of every reference."""
    for effect in EFFECTS:
        for fog in FOGS:
            for proj in PROJECTIONS:
                yield (f"spacefill-{effect}-{fog}-{proj}",
                       ["--style", "spacefill", "--effect", effect, "--fog", fog,
                        "--projection", proj])
    for fog in FOGS:
        for proj in PROJECTIONS:
            yield (f"ballstick-plain-{fog}-{proj}",
                   ["--style", "ballstick", "--effect", "plain", "--fog", fog,
                    "--projection", proj])


def find_binary():
    if len(sys.argv) > 1:
        return sys.argv[1]
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target"))
    for profile in ("release", "debug"):
        p = os.path.join(target, profile, "shaderbox")
        if os.path.exists(p):
            return p
    sys.exit("no shaderbox binary: build it (cargo build --release -p shaderbox-cli) or pass its path")


def floats(values):
    return (ctypes.c_float * len(values))(*values)


def compile_program(vertex, fragment, geometry=(), parameters=()):
    """A scene's program; a geometry stage (GL_EXT_geometry_shader4, which
    Mesa never implemented: its compile fails there, loudly) gets its
    program parameters before the link."""
    prog = GL.glCreateProgram()
    stages = [(GL.GL_VERTEX_SHADER, vertex), (GL.GL_FRAGMENT_SHADER, fragment)]
    from OpenGL.GL.EXT import geometry_shader4 as ext
    if geometry:
        stages.append((ext.GL_GEOMETRY_SHADER_EXT, geometry))
    for kind, sources in stages:
        for src in sources:
            sh = GL.glCreateShader(kind)
            GL.glShaderSource(sh, src)
            GL.glCompileShader(sh)
            if not GL.glGetShaderiv(sh, GL.GL_COMPILE_STATUS):
                raise RuntimeError("Mesa compile failed: %s" % GL.glGetShaderInfoLog(sh))
            GL.glAttachShader(prog, sh)
    for pname, value in parameters:
        ext.glProgramParameteriEXT(prog, pname, value)
    GL.glLinkProgram(prog)
    if not GL.glGetProgramiv(prog, GL.GL_LINK_STATUS):
        raise RuntimeError("Mesa link failed: %s" % GL.glGetProgramInfoLog(prog))
    return prog


def replay(scene):
    """Runs the scene's calls on a new OSMesa context; RGBA rows, bottom first."""
    w, h = scene["width"], scene["height"]
    ctx = osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 24, 8, 0, None)
    if not ctx:
        raise RuntimeError("OSMesaCreateContextExt failed")
    buf = arrays.GLubyteArray.zeros((h, w, 4))
    if not osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_UNSIGNED_BYTE, w, h):
        raise RuntimeError("OSMesaMakeCurrent failed")
    programs = {}
    current = [0]
    keep = []
    for c in scene["calls"]:
        name, a = c["call"], c.get("args")
        if name == "MatrixMode":
            GL.glMatrixMode(a)
        elif name == "LoadIdentity":
            GL.glLoadIdentity()
        elif name == "Ortho":
            GL.glOrtho(*a)
        elif name == "Frustum":
            GL.glFrustum(*a)
        elif name == "Translate":
            GL.glTranslatef(*a)
        elif name == "Rotate":
            GL.glRotatef(*a)
        elif name == "Light":
            GL.glLightfv(a[0], a[1], floats(a[2]))
        elif name == "Material":
            GL.glMaterialfv(a[0], a[1], floats(a[2]))
        elif name == "Enable":
            GL.glEnable(a)
        elif name == "Disable":
            GL.glDisable(a)
        elif name == "Fog":
            GL.glFogfv(a[0], floats(a[1]))
        elif name == "ClearColor":
            GL.glClearColor(*a)
        elif name == "ClearDepth":
            GL.glClearDepth(a)
        elif name == "Clear":
            GL.glClear(a)
        elif name == "DepthFunc":
            GL.glDepthFunc(a)
        elif name == "Program":
            programs[a["id"]] = compile_program(a["vertex"], a["fragment"],
                                                a.get("geometry", ()), a.get("parameters", ()))
            current[0] = programs[a["id"]]
            GL.glUseProgram(current[0])
        elif name == "UseProgram":
            current[0] = programs[a]
            GL.glUseProgram(current[0])
        elif name == "Uniform":
            loc = GL.glGetUniformLocation(current[0], a["name"])
            v = a["values"]
            if a["array"] or len(v) > 4:
                GL.glUniform1fv(loc, len(v), floats(v))
            else:
                [GL.glUniform1f, GL.glUniform2f, GL.glUniform3f, GL.glUniform4f][len(v) - 1](loc, *v)
        elif name == "Draw":
            n, v = a["vertex"]
            data = floats(v)
            keep.append(data)
            GL.glVertexPointer(n, GL.GL_FLOAT, 0, data)
            GL.glEnableClientState(GL.GL_VERTEX_ARRAY)
            for unit, key in ((GL.GL_TEXTURE0, "texcoord0"), (GL.GL_TEXTURE1, "texcoord1")):
                GL.glClientActiveTexture(unit)
                if a[key] is None:
                    GL.glDisableClientState(GL.GL_TEXTURE_COORD_ARRAY)
                else:
                    data = floats(a[key][1])
                    keep.append(data)
                    GL.glTexCoordPointer(a[key][0], GL.GL_FLOAT, 0, data)
                    GL.glEnableClientState(GL.GL_TEXTURE_COORD_ARRAY)
            GL.glClientActiveTexture(GL.GL_TEXTURE0)
            if a["color"] is None:
                GL.glDisableClientState(GL.GL_COLOR_ARRAY)
            else:
                data = floats(a["color"][1])
                keep.append(data)
                GL.glColorPointer(a["color"][0], GL.GL_FLOAT, 0, data)
                GL.glEnableClientState(GL.GL_COLOR_ARRAY)
            GL.glDrawArrays(a["mode"], 0, a["count"])
        else:
            raise RuntimeError("unknown call %s" % name)
        err = GL.glGetError()
        if err:
            raise RuntimeError("GL error 0x%04x after %s" % (err, name))
    GL.glFinish()
    px = bytes(GL.glReadPixels(0, 0, w, h, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE))
    osmesa.OSMesaDestroyContext(ctx)
    return w, h, px


def write_png(path, w, h, rgba_bottom_first):
    rows = []
    for y in range(h - 1, -1, -1):
        row = rgba_bottom_first[y * w * 4:(y + 1) * w * 4]
        rgb = bytearray()
        for x in range(w):
            rgb += row[x * 4:x * 4 + 3]
        rows.append(b"\0" + bytes(rgb))
    raw = b"".join(rows)

    def chunk(kind, data):
        c = struct.pack(">I", len(data)) + kind + data
        return c + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def main():
    binary = find_binary()
    os.makedirs(OUT, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        for name, args in cases():
            scene_path = os.path.join(tmp, name + ".json")
            cmd = [binary, "render", "--size", f"{SIZE}x{SIZE}", *args,
                   "-o", os.path.join(tmp, name + ".png"), "--export-scene", scene_path]
            subprocess.run(cmd, check=True, stderr=subprocess.DEVNULL)
            with open(scene_path) as f:
                scene = json.load(f)
            w, h, px = replay(scene)
            write_png(os.path.join(OUT, name + ".png"), w, h, px)
            print("wrote", name + ".png", "(" + scene["description"] + ")")
    print("renderer:", "Mesa OSMesa via PyOpenGL")


if __name__ == "__main__":
    main()
