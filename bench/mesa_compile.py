#!/usr/bin/env python3
"""Times Mesa's compile+link of a vertex/fragment shader pair.

Loads Debian's libOSMesa (Mesa llvmpipe/softpipe off-screen), makes a small
context current, and compiles and links the pair N times with fresh shader
and program objects, printing the median and spread in microseconds as JSON.

    python3 bench/mesa_compile.py VERT FRAG [--iterations N] [--first STRING]

--first passes STRING (e.g. "#version 150 compatibility\n") as a first
source string before each file, as programs that share one version line do.

Only ctypes from the standard library is used, so nothing but libosmesa6 is
needed.
"""
import argparse
import ctypes
import ctypes.util
import json
import statistics
import sys
import time

GL_VERTEX_SHADER = 0x8B31
GL_FRAGMENT_SHADER = 0x8B30
GL_COMPILE_STATUS = 0x8B81
GL_LINK_STATUS = 0x8B82
GL_UNSIGNED_BYTE = 0x1401
OSMESA_RGBA = 0x1908


def load_osmesa():
    for name in ("libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"):
        try:
            return ctypes.CDLL(name)
        except OSError:
            continue
    path = ctypes.util.find_library("OSMesa")
    if path:
        return ctypes.CDLL(path)
    sys.exit("libOSMesa not found: install Debian's libosmesa6")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("vert")
    ap.add_argument("frag")
    ap.add_argument("--iterations", type=int, default=200)
    ap.add_argument("--first", default=None, help="a first source string before each file")
    args = ap.parse_args()
    osm = load_osmesa()
    osm.OSMesaCreateContextExt.restype = ctypes.c_void_p
    osm.OSMesaCreateContextExt.argtypes = [ctypes.c_uint, ctypes.c_int, ctypes.c_int, ctypes.c_int, ctypes.c_void_p]
    osm.OSMesaMakeCurrent.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_uint, ctypes.c_int, ctypes.c_int]
    osm.OSMesaGetProcAddress.restype = ctypes.c_void_p
    osm.OSMesaGetProcAddress.argtypes = [ctypes.c_char_p]
    ctx = osm.OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, None)
    if not ctx:
        sys.exit("OSMesaCreateContextExt failed")
    w = h = 64
    buf = (ctypes.c_ubyte * (w * h * 4))()
    if not osm.OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, w, h):
        sys.exit("OSMesaMakeCurrent failed")

    def gl(name, restype, *argtypes):
        addr = osm.OSMesaGetProcAddress(name.encode())
        if not addr:
            sys.exit(f"{name} not found")
        return ctypes.CFUNCTYPE(restype, *argtypes)(addr)

    uint, i32, p = ctypes.c_uint, ctypes.c_int, ctypes.c_void_p
    create_shader = gl("glCreateShader", uint, uint)
    shader_source = gl("glShaderSource", None, uint, i32, ctypes.POINTER(ctypes.c_char_p), p)
    compile_shader = gl("glCompileShader", None, uint)
    get_shaderiv = gl("glGetShaderiv", None, uint, uint, ctypes.POINTER(i32))
    create_program = gl("glCreateProgram", uint)
    attach = gl("glAttachShader", None, uint, uint)
    link = gl("glLinkProgram", None, uint)
    get_programiv = gl("glGetProgramiv", None, uint, uint, ctypes.POINTER(i32))
    delete_shader = gl("glDeleteShader", None, uint)
    delete_program = gl("glDeleteProgram", None, uint)
    finish = gl("glFinish", None)

    sources = []
    for path, kind in ((args.vert, GL_VERTEX_SHADER), (args.frag, GL_FRAGMENT_SHADER)):
        with open(path, "rb") as f:
            sources.append((kind, f.read()))

    def once():
        prog = create_program()
        shaders = []
        for kind, text in sources:
            s = create_shader(kind)
            strings = [args.first.encode(), text] if args.first else [text]
            arr = (ctypes.c_char_p * len(strings))(*strings)
            shader_source(s, len(strings), arr, None)
            compile_shader(s)
            ok = i32()
            get_shaderiv(s, GL_COMPILE_STATUS, ctypes.byref(ok))
            if not ok.value:
                log = (ctypes.c_char * 4096)()
                get_log = gl("glGetShaderInfoLog", None, uint, i32, p, p)
                get_log(s, 4096, None, log)
                sys.exit("Mesa failed to compile the shader: " + log.value.decode(errors="replace"))
            attach(prog, s)
            shaders.append(s)
        link(prog)
        ok = i32()
        get_programiv(prog, GL_LINK_STATUS, ctypes.byref(ok))
        if not ok.value:
            sys.exit("Mesa failed to link the program")
        finish()
        for s in shaders:
            delete_shader(s)
        delete_program(prog)

    for _ in range(5):
        once()
    times = []
    for _ in range(args.iterations):
        t = time.perf_counter()
        once()
        times.append((time.perf_counter() - t) * 1e6)
    q = statistics.quantiles(times, n=10)
    print(json.dumps({
        "implementation": "mesa-osmesa",
        "iterations": args.iterations,
        "median_us": round(statistics.median(times), 1),
        "p10_us": round(q[0], 1),
        "p90_us": round(q[-1], 1),
    }))


if __name__ == "__main__":
    main()
