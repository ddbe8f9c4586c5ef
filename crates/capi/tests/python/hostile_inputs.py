"""Hostile inputs beside Mesa: each case of docs/RELIABILITY.md's table run
through the C ABI on shaderbox's libOSMesa.so and on Mesa's, one process
per case and library, with a time limit; prints what each did (the GL
statuses and errors the case logs, or how the process ended), its wall
time and its peak memory, side by side.

    python3 hostile_inputs.py LIBDIR [CASE...]     # the table
    python3 hostile_inputs.py --case NAME          # one case, in this process

LIBDIR holds shaderbox's libOSMesa.so; Mesa's is the system's (Debian
libosmesa6). This is a measurement, not a pass/fail test: the two
implementations are expected to differ, and the table records how.
"""
import ctypes
import os
import subprocess
import sys
import time

TIMEOUT = 30


def gl_setup(w=32, h=32):
    import OpenGL
    OpenGL.ERROR_CHECKING = False
    OpenGL.ERROR_ON_COPY = False
    from OpenGL import GL, arrays, osmesa
    ctx = osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 24, 8, 0, None)
    buf = arrays.GLubyteArray.zeros((h, w, 4))
    if not ctx or not osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_UNSIGNED_BYTE, w, h):
        raise RuntimeError("no OSMesa context")
    return GL, (ctx, buf)


NAMES = {0: "NO_ERROR", 0x500: "INVALID_ENUM", 0x501: "INVALID_VALUE",
         0x502: "INVALID_OPERATION", 0x505: "OUT_OF_MEMORY"}


def errors(GL):
    out = []
    for _ in range(4):
        e = GL.glGetError()
        if not e:
            break
        out.append(NAMES.get(e, hex(e)))
    return "+".join(out) or "NO_ERROR"


def strings(arr):
    """A C array of char pointers as the GLchar** PyOpenGL's raw call wants."""
    return ctypes.cast(arr, ctypes.POINTER(ctypes.POINTER(ctypes.c_char)))


def compile_src(GL, src, kind=None):
    """Compile status and the first line of the info log, with the source
    passed as one counted string (so NUL-free megabytes go through)."""
    kind = kind or GL.GL_FRAGMENT_SHADER
    s = GL.glCreateShader(kind)
    data = src.encode()
    p = ctypes.c_char_p(data)
    arr = (ctypes.c_char_p * 1)(p)
    ln = (ctypes.c_int * 1)(len(data))
    from OpenGL.raw.GL.VERSION import GL_2_0 as raw20
    raw20.glShaderSource(s, 1, strings(arr), ln)
    GL.glCompileShader(s)
    ok = GL.glGetShaderiv(s, GL.GL_COMPILE_STATUS)
    log = GL.glGetShaderInfoLog(s)
    log = log.decode(errors="replace") if isinstance(log, bytes) else str(log)
    first = next((x.strip() for x in log.splitlines() if x.strip()), "")
    return s, int(ok), first[:110]


def link(GL, shaders):
    p = GL.glCreateProgram()
    for s in shaders:
        GL.glAttachShader(p, s)
    GL.glLinkProgram(p)
    ok = GL.glGetProgramiv(p, GL.GL_LINK_STATUS)
    log = GL.glGetProgramInfoLog(p)
    log = log.decode(errors="replace") if isinstance(log, bytes) else str(log)
    first = next((x.strip() for x in log.splitlines() if x.strip()), "")
    return p, int(ok), first[:110]


def compile_case(src):
    def run():
        GL, keep = gl_setup()
        _, ok, log = compile_src(GL, src() if callable(src) else src)
        return f"compile {ok}; {log!r}"
    return run


def chain(n):
    fs = ["float f0(float x) { return x + 0.25; }"]
    fs += [f"float f{i}(float x) {{ return f{i - 1}(x); }}" for i in range(1, n)]
    return "\n".join(fs) + f"\nvoid main() {{ gl_FragColor = vec4(f{n - 1}(0.0)); }}\n"


def chain_draw(n):
    def run():
        GL, keep = gl_setup()
        s, ok, log = compile_src(GL, chain(n))
        p, lok, llog = link(GL, [s])
        GL.glUseProgram(p)
        GL.glRecti(-1, -1, 1, 1)
        GL.glFinish()
        px = GL.glReadPixels(16, 16, 1, 1, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE)
        return f"compile {ok}, link {lok}; pixel {list(bytes(px))}; {errors(GL)}; {(log or llog)!r}"
    return run


def empty_program():
    GL, keep = gl_setup()
    _, ok, log = link(GL, [])
    return f"link {ok}; {errors(GL)}"


def null_string():
    GL, keep = gl_setup()
    from OpenGL.raw.GL.VERSION import GL_2_0 as raw20
    s = GL.glCreateShader(GL.GL_FRAGMENT_SHADER)
    arr = (ctypes.c_char_p * 1)(None)
    raw20.glShaderSource(s, 1, strings(arr), None)
    return errors(GL)


def negative_count_source():
    GL, keep = gl_setup()
    from OpenGL.raw.GL.VERSION import GL_2_0 as raw20
    s = GL.glCreateShader(GL.GL_FRAGMENT_SHADER)
    arr = (ctypes.c_char_p * 1)(b"void main(){}")
    raw20.glShaderSource(s, -1, strings(arr), None)
    return errors(GL)


def negative_draw_count():
    GL, keep = gl_setup()
    from OpenGL.raw.GL.VERSION import GL_1_1 as raw11
    raw11.glDrawArrays(GL.GL_TRIANGLES, 0, -1)
    return errors(GL)


def huge_vertex_count():
    GL, keep = gl_setup()
    from OpenGL.raw.GL.VERSION import GL_1_1 as raw11
    raw11.glDrawArrays(GL.GL_POINTS, 0, 0x7fffffff)
    GL.glFinish()
    return errors(GL)


def tex_image(w, h):
    def run():
        GL, keep = gl_setup()
        from OpenGL.raw.GL.VERSION import GL_1_0 as raw10
        t = GL.glGenTextures(1)
        GL.glBindTexture(GL.GL_TEXTURE_2D, t)
        raw10.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL.GL_RGBA8, w, h, 0, GL.GL_RGBA,
                           GL.GL_UNSIGNED_BYTE, None)
        return errors(GL)
    return run


def renderbuffer(w, h):
    def run():
        GL, keep = gl_setup()
        from OpenGL.GL.EXT import framebuffer_object as fbo
        rb = fbo.glGenRenderbuffersEXT(1)
        fbo.glBindRenderbufferEXT(fbo.GL_RENDERBUFFER_EXT, rb)
        fbo.glRenderbufferStorageEXT(fbo.GL_RENDERBUFFER_EXT, GL.GL_RGBA8, w, h)
        return errors(GL)
    return run


def osmesa_huge_buffer():
    import OpenGL
    OpenGL.ERROR_CHECKING = False
    from OpenGL import GL, osmesa
    ctx = osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 24, 8, 0, None)
    buf = (ctypes.c_ubyte * 16)()
    ok = osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_UNSIGNED_BYTE, 100000, 100000)
    return f"OSMesaMakeCurrent {int(bool(ok))}"


def infinite_loop():
    GL, keep = gl_setup(8, 8)
    src = ("uniform float u;\nvoid main() { float x = 0.0;\n"
           " for (int i = 0; i >= 0; i += int(u)) { x += 1.0; }\n"
           " gl_FragColor = vec4(x); }\n")
    s, ok, log = compile_src(GL, src)
    p, lok, _ = link(GL, [s])
    GL.glUseProgram(p)
    GL.glRecti(-1, -1, 1, 1)
    GL.glFinish()
    return f"compile {ok}, link {lok}; draw {errors(GL)}"


def main_fs(body=""):
    return body + "void main() { gl_FragColor = vec4(1.0); }\n"


CASES = {
    "empty source": compile_case(""),
    "#version only": compile_case("#version 110\n"),
    "no shaders, link": empty_program,
    "#line 1+1": compile_case("#line 1+1\nvoid main() { undeclared = 1.0; }\n"),
    "#line 10 in GLSL 3.30": compile_case("#version 330\n#line 10\nvoid main() { undeclared = 1.0; }\n"),
    "glShaderSource NULL string": null_string,
    "glShaderSource count -1": negative_count_source,
    "call chain 100 deep, draw": chain_draw(100),
    "call chain 200 deep, draw": chain_draw(200),
    "call chain 3000 deep, draw": chain_draw(3000),
    "call chain 4000 deep, draw": chain_draw(4000),
    "100,000 nested (": compile_case(
        lambda: "void main() { gl_FragColor = vec4(" + "(" * 100000 + "1.0"
        + ")" * 100000 + "); }\n"),
    "100,000 nested {": compile_case(
        lambda: "void main() {" + "{" * 100000 + "}" * 100000 + "}\n"),
    "100,000 nested #if": compile_case(
        lambda: "#if 1\n" * 100000 + "#endif\n" * 100000 + main_fs()),
    "1 MB identifier": compile_case(
        lambda: "void main() { float " + "a" * 1000000 + " = 1.0; gl_FragColor = vec4("
        + "a" * 1000000 + "); }\n"),
    "array of 2^30": compile_case(main_fs("uniform float a[1073741824];\n")),
    "25 MB of newlines": compile_case(lambda: "\n" * 25000000 + main_fs()),
    "10 MB of ;": compile_case(lambda: ";" * 10000000 + "\n" + main_fs()),
    "macro bomb": compile_case(
        lambda: "#define A0 x\n" + "".join(f"#define A{i} A{i-1} A{i-1}\n"
                                           for i in range(1, 40)) + "A39\n" + main_fs()),
    "glTexImage2D 100000x100000": tex_image(100000, 100000),
    "glTexImage2D -1x1": tex_image(-1, 1),
    "glRenderbufferStorage 100000x100000": renderbuffer(100000, 100000),
    "OSMesaMakeCurrent 100000x100000": osmesa_huge_buffer,
    "glDrawArrays count -1": negative_draw_count,
    "glDrawArrays 2^31-1 points": huge_vertex_count,
    "fragment loop that never ends": infinite_loop,
}


def measure(name, libdir):
    env = dict(os.environ, PYOPENGL_PLATFORM="osmesa")
    env.pop("LD_LIBRARY_PATH", None)
    if libdir:
        env["LD_LIBRARY_PATH"] = libdir
    t0 = time.monotonic()
    p = subprocess.Popen([sys.executable, __file__, "--case", name], env=env,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    while True:
        pid, status, ru = os.wait4(p.pid, os.WNOHANG)
        if pid:
            break
        if time.monotonic() - t0 > TIMEOUT:
            p.kill()
            pid, status, ru = os.wait4(p.pid, 0)
            return f"no answer in {TIMEOUT} s (killed)", TIMEOUT, ru.ru_maxrss
        time.sleep(0.01)
    dt = time.monotonic() - t0
    out = p.stdout.read().strip().splitlines()
    if os.WIFSIGNALED(status):
        what = f"killed by signal {os.WTERMSIG(status)}"
    elif os.WEXITSTATUS(status) != 0:
        err = p.stderr.read().strip().splitlines()
        what = f"exit {os.WEXITSTATUS(status)}: {(err or ['?'])[-1][:100]}"
    else:
        what = out[-1] if out else "?"
    return what, dt, ru.ru_maxrss


def main():
    if sys.argv[1] == "--case":
        print(CASES[sys.argv[2]]())
        return 0
    libdir = sys.argv[1]
    names = sys.argv[2:] or list(CASES)
    for name in names:
        for side, lib in (("shaderbox", libdir), ("mesa", None)):
            what, dt, rss = measure(name, lib)
            print(f"{name} | {side} | {what} | {dt:.2f} s | {rss // 1024} MB", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
