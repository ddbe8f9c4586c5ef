#!/usr/bin/env python3
"""Interpolated values bit for bit: shaderbox's libOSMesa against Mesa's.

Draws random primitives of every polygon mode (triangles, strips, fans,
quads, quad strips, polygons) with a different 1/w at each vertex (so that
every smooth varying is perspective-corrected) on a 3.3 compatibility
context, once into the context's own (window-system) framebuffer and once
into a framebuffer object, and reads back, for every pixel, the exact bits
of each interpolated value: a smooth vec4 with large values, a smooth vec4
in [-1, 1], a `noperspective` vec4 and gl_FragCoord (each float written as
its four bytes, `floatBitsToUint`, into an RGBA8 target). The two
libraries run in their own processes (LD_LIBRARY_PATH=LIBDIR for
shaderbox, the system's libOSMesa.so.8 for Mesa).

GL leaves the rounding of interpolation to the implementation; shaderbox
sets up and evaluates its planes as llvmpipe does (crates/raster/src/
interpolate.rs), so a program whose picture rests on the last bits of an
interpolated value (or a depth test on a tie) draws what it draws on Mesa.

llvmpipe evaluates a plane with fused multiply-adds where its CPU has
them (every x86-64 CPU with AVX2); on one without, Mesa's own values
round differently and this comparison does not hold.

Usage: scripts/interpolation-bits.py [--libdir DIR] [--seeds N]
  DIR holds shaderbox's libOSMesa.so (default target/release).
Exit status 1 when a pixel is covered by one library only, or a varying or
a component of gl_FragCoord differs in any bit.
"""
import argparse
import ctypes
import json
import math
import os
import random
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The differential suite's harness (its `program`: compile, link, use).
HARNESS = os.path.join(ROOT, "crates", "capi", "tests", "python")
MODES = ["GL_TRIANGLES", "GL_TRIANGLE_STRIP", "GL_TRIANGLE_FAN", "GL_QUADS",
         "GL_QUAD_STRIP", "GL_POLYGON"]
TARGETS = ["window", "fbo"]
VALUES = ["smooth", "unit", "noperspective", "gl_FragCoord"]
W, H = 96, 80
VS = """#version 330
layout(location = 0) in vec4 pos;
layout(location = 1) in vec4 a;
layout(location = 2) in vec4 b;
out vec4 smooth_;
out vec4 unit;
noperspective out vec4 linear;
void main() { smooth_ = a; unit = b; linear = a; gl_Position = pos; }
"""
FS = """#version 330
in vec4 smooth_;
in vec4 unit;
noperspective in vec4 linear;
uniform int which;
uniform int comp;
out vec4 color;
void main() {
    vec4 v = which == 0 ? smooth_ : which == 1 ? unit : which == 2 ? linear : gl_FragCoord;
    uint u = floatBitsToUint(v[comp]);
    color = vec4(u & 255u, (u >> 8) & 255u, (u >> 16) & 255u, u >> 24) / 255.0;
}
"""
# The clear value: a NaN no interpolation gives (bytes 1, 2, 3, 255).
EMPTY = 0xFF030201


def geometry(mode, seed):
    """Clip-space vertices (x, y, z, w with w in [0.4, 3]) and two vec4s
    each; convex polygons, strips and fans whose triangles do not fold."""
    rng = random.Random(f"{mode}-{seed}")
    if mode in ("GL_TRIANGLE_FAN", "GL_POLYGON"):
        cx, cy = rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)
        n = 9 if mode == "GL_TRIANGLE_FAN" else 8
        pts = [(cx, cy)] if mode == "GL_TRIANGLE_FAN" else []
        span = 0.9 if mode == "GL_TRIANGLE_FAN" else 1.0
        for i in range(n):
            t = 2 * math.pi * i / n * span
            r = rng.uniform(0.65, 0.7)
            pts.append((cx + r * math.cos(t), cy + r * math.sin(t)))
    elif mode == "GL_QUADS":
        pts = []
        for _ in range(6):
            x, y, s = rng.uniform(-0.9, 0.5), rng.uniform(-0.9, 0.5), rng.uniform(0.15, 0.4)
            j = lambda: rng.uniform(-0.04, 0.04)
            pts += [(x + j(), y + j()), (x + s + j(), y + j()), (x + s + j(), y + s + j()),
                    (x + j(), y + s + j())]
    elif mode in ("GL_TRIANGLE_STRIP", "GL_QUAD_STRIP"):
        pts = []
        for i in range(7):
            x = -0.9 + 1.8 * i / 6
            pts += [(x + rng.uniform(-0.03, 0.03), rng.uniform(-0.8, -0.2)),
                    (x + rng.uniform(-0.03, 0.03), rng.uniform(0.2, 0.8))]
    else:
        pts = [(rng.uniform(-1, 1), rng.uniform(-1, 1)) for _ in range(30)]
    verts = []
    for x, y in pts:
        w = rng.uniform(0.4, 3.0)
        verts.append(([x * w, y * w, rng.uniform(-0.9, 0.9) * w, w],
                      [rng.uniform(-50, 50) for _ in range(4)],
                      [rng.uniform(-1, 1) for _ in range(4)]))
    return verts


def render(seed):
    """Child process: every mode, target, value and component as a list of
    W*H 32-bit words (hex), on whichever libOSMesa the process loads."""
    os.environ["PYOPENGL_PLATFORM"] = "osmesa"
    sys.path.insert(0, HARNESS)
    from harness import GL, arrays, osmesa, program
    attrs = (ctypes.c_int * 11)(
        osmesa.OSMESA_FORMAT, osmesa.OSMESA_RGBA, osmesa.OSMESA_DEPTH_BITS, 0,
        osmesa.OSMESA_PROFILE, osmesa.OSMESA_COMPAT_PROFILE,
        osmesa.OSMESA_CONTEXT_MAJOR_VERSION, 3, osmesa.OSMESA_CONTEXT_MINOR_VERSION, 3, 0)
    ctx = osmesa.OSMesaCreateContextAttribs(attrs, None)
    if not ctx:
        raise RuntimeError("no 3.3 compatibility context")
    buf = arrays.GLubyteArray.zeros((H, W, 4))
    if not osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_UNSIGNED_BYTE, W, H):
        raise RuntimeError("OSMesaMakeCurrent failed")
    fbo = GL.glGenFramebuffers(1)
    GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, fbo)
    rb = GL.glGenRenderbuffers(1)
    GL.glBindRenderbuffer(GL.GL_RENDERBUFFER, rb)
    GL.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_RGBA8, W, H)
    GL.glFramebufferRenderbuffer(GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0,
                                 GL.GL_RENDERBUFFER, rb)
    if GL.glCheckFramebufferStatus(GL.GL_FRAMEBUFFER) != GL.GL_FRAMEBUFFER_COMPLETE:
        raise RuntimeError("framebuffer incomplete")
    prog = program([VS], [FS])
    which, comp = (GL.glGetUniformLocation(prog, n) for n in ("which", "comp"))
    GL.glViewport(0, 0, W, H)
    out = {}
    for mode in MODES:
        verts = geometry(mode, seed)
        keep = []
        for i in range(3):
            data = (ctypes.c_float * (4 * len(verts)))(*[c for v in verts for c in v[i]])
            keep.append(data)
            GL.glEnableVertexAttribArray(i)
            GL.glVertexAttribPointer(i, 4, GL.GL_FLOAT, False, 0, data)
        for target in TARGETS:
            GL.glBindFramebuffer(GL.GL_FRAMEBUFFER, fbo if target == "fbo" else 0)
            for v in range(len(VALUES)):
                for c in range(4):
                    GL.glUniform1i(which, v)
                    GL.glUniform1i(comp, c)
                    GL.glClearColor(1 / 255, 2 / 255, 3 / 255, 1.0)
                    GL.glClear(GL.GL_COLOR_BUFFER_BIT)
                    GL.glDrawArrays(getattr(GL, mode), 0, len(verts))
                    px = GL.glReadPixels(0, 0, W, H, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE)
                    raw = bytes(px) if isinstance(px, (bytes, bytearray)) else ctypes.string_at(
                        arrays.ArrayDatatype.dataPointer(px), W * H * 4)
                    out[f"{mode} {target} {v} {c}"] = raw.hex()
        err = GL.glGetError()
        if err:
            raise RuntimeError("GL error 0x%04x" % err)
    osmesa.OSMesaDestroyContext(ctx)
    return out


def run_on(libdir, seed):
    env = dict(os.environ)
    env.pop("LD_LIBRARY_PATH", None)
    if libdir:
        env["LD_LIBRARY_PATH"] = libdir
    p = subprocess.run([sys.executable, os.path.abspath(__file__), "--child", str(seed)],
                       env=env, capture_output=True, text=True)
    if p.returncode:
        sys.exit(f"{'shaderbox' if libdir else 'Mesa'} failed:\n{p.stderr}")
    return json.loads(p.stdout.strip().splitlines()[-1])


def words(hexdata):
    raw = bytes.fromhex(hexdata)
    return [int.from_bytes(raw[i:i + 4], "little") for i in range(0, len(raw), 4)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--libdir", default=os.path.join(
        os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target")), "release"))
    ap.add_argument("--seeds", type=int, default=3, help="random scenes per mode")
    ap.add_argument("--child", type=int, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child is not None:
        print(json.dumps(render(args.child)))
        return 0
    if not os.path.exists(os.path.join(args.libdir, "libOSMesa.so")):
        sys.exit(f"no libOSMesa.so in {args.libdir}: build it (cargo build --release -p shaderbox-capi)")
    failed = 0
    for seed in range(1, args.seeds + 1):
        ours, mesa = run_on(args.libdir, seed), run_on(None, seed)
        for mode in MODES:
            for target in TARGETS:
                line = []
                for v, name in enumerate(VALUES):
                    covered = coverage = differ = 0
                    for c in range(4):
                        key = f"{mode} {target} {v} {c}"
                        a, b = words(ours[key]), words(mesa[key])
                        for x, y in zip(a, b):
                            if (x == EMPTY) != (y == EMPTY):
                                coverage += 1
                            elif x != EMPTY:
                                covered += c == 0
                                differ += x != y
                    failed += coverage + differ
                    line.append(f"{name} {differ} differ" + (f", coverage {coverage}" if coverage else ""))
                print(f"seed {seed} {mode:18} {target:6} {covered:5} px: " + "; ".join(line))
    print("every interpolated value the same bits" if not failed
          else f"{failed} values or coverages differ")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
