"""A PyOpenGL program using OSMesa: clear, a GLSL-shaded triangle, glReadPixels.

Run: PYOPENGL_PLATFORM=osmesa LD_LIBRARY_PATH=target/release python3 shaded_triangle.py
Prints the renderer string and checks a few pixels; exits non-zero on a mismatch.
With an argument, writes the RGBA pixels (bottom row first) to that file.
"""
import ctypes
import sys

from OpenGL import GL, arrays
from OpenGL import osmesa

W, H = 64, 48

VS = """
attribute vec2 pos;
attribute vec3 col;
varying vec3 v;
void main() { v = col; gl_Position = vec4(pos, 0.0, 1.0); }
"""
FS = """
varying vec3 v;
uniform float k;
void main() { gl_FragColor = vec4(v * k, 1.0); }
"""


def compile_shader(kind, src):
    s = GL.glCreateShader(kind)
    GL.glShaderSource(s, src)
    GL.glCompileShader(s)
    if not GL.glGetShaderiv(s, GL.GL_COMPILE_STATUS):
        raise RuntimeError(GL.glGetShaderInfoLog(s))
    return s


def main():
    ctx = osmesa.OSMesaCreateContextExt(osmesa.OSMESA_RGBA, 24, 8, 0, None)
    assert ctx, "OSMesaCreateContextExt failed"
    buf = arrays.GLubyteArray.zeros((H, W, 4))
    assert osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_UNSIGNED_BYTE, W, H), "MakeCurrent failed"
    print("GL_RENDERER:", GL.glGetString(GL.GL_RENDERER).decode())
    print("GL_VERSION:", GL.glGetString(GL.GL_VERSION).decode())

    prog = GL.glCreateProgram()
    GL.glAttachShader(prog, compile_shader(GL.GL_VERTEX_SHADER, VS))
    GL.glAttachShader(prog, compile_shader(GL.GL_FRAGMENT_SHADER, FS))
    GL.glLinkProgram(prog)
    assert GL.glGetProgramiv(prog, GL.GL_LINK_STATUS), GL.glGetProgramInfoLog(prog)
    GL.glUseProgram(prog)
    GL.glUniform1f(GL.glGetUniformLocation(prog, "k"), 1.0)

    GL.glClearColor(0.0, 0.0, 0.25, 1.0)
    GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)

    verts = (ctypes.c_float * 15)(
        -1.0, -1.0, 1.0, 0.0, 0.0,
        1.0, -1.0, 0.0, 1.0, 0.0,
        0.0, 1.0, 0.0, 0.0, 1.0,
    )
    pos = GL.glGetAttribLocation(prog, "pos")
    col = GL.glGetAttribLocation(prog, "col")
    GL.glVertexAttribPointer(pos, 2, GL.GL_FLOAT, GL.GL_FALSE, 20, verts)
    GL.glVertexAttribPointer(col, 3, GL.GL_FLOAT, GL.GL_FALSE, 20,
                             ctypes.byref(verts, 8))
    GL.glEnableVertexAttribArray(pos)
    GL.glEnableVertexAttribArray(col)
    GL.glDrawArrays(GL.GL_TRIANGLES, 0, 3)
    GL.glFinish()

    px = GL.glReadPixels(0, 0, W, H, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE)
    px = bytes(px)
    def at(x, y):
        i = (y * W + x) * 4
        return tuple(px[i:i + 4])
    corner, center = at(W - 1, H - 1), at(W // 2, H // 3)
    print("corner", corner, "center", center)
    ok = corner == (0, 0, 64, 255) and center[3] == 255 and center[0] > 40 and center[1] > 40 and center[2] > 40
    # The OSMesa buffer holds the same image (bottom row first).
    ok = ok and bytes(buf) == px
    if len(sys.argv) > 1:
        with open(sys.argv[1], "wb") as f:
            f.write(px)
    err = GL.glGetError()
    print("glGetError:", err)
    osmesa.OSMesaDestroyContext(ctx)
    print("OK" if ok and err == 0 else "MISMATCH")
    return 0 if ok and err == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
