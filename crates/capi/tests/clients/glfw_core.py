"""GLFW's OSMesa back end (the `glfw` wheel, null platform, no display)
with a 3.3 core-profile hint, unmodified: GLFW loads libOSMesa.so.8 and
creates the context with OSMesaCreateContextAttribs; a VAO-and-program
triangle and a clear, read back with glReadPixels."""
import ctypes
import os

os.environ.setdefault("PYOPENGL_PLATFORM", "osmesa")

import glfw  # noqa: E402
import numpy as np  # noqa: E402

from output import run, save  # noqa: E402

W, H = 96, 64

VS = """#version 330 core
layout(location = 0) in vec2 p;
layout(location = 1) in vec3 c;
out vec3 colour;
void main() { gl_Position = vec4(p, 0.0, 1.0); colour = c; }
"""
FS = """#version 330 core
in vec3 colour;
out vec4 frag;
void main() { frag = vec4(colour, 1.0); }
"""


def triangle(outdir, name):
    glfw.init_hint(glfw.PLATFORM, glfw.PLATFORM_NULL)
    if not glfw.init():
        raise RuntimeError("glfw.init failed")
    try:
        glfw.window_hint(glfw.CONTEXT_CREATION_API, glfw.OSMESA_CONTEXT_API)
        glfw.window_hint(glfw.CONTEXT_VERSION_MAJOR, 3)
        glfw.window_hint(glfw.CONTEXT_VERSION_MINOR, 3)
        glfw.window_hint(glfw.OPENGL_PROFILE, glfw.OPENGL_CORE_PROFILE)
        glfw.window_hint(glfw.VISIBLE, False)
        win = glfw.create_window(W, H, "shaderbox", None, None)
        if not win:
            raise RuntimeError("glfw.create_window failed")
        glfw.make_context_current(win)
        from OpenGL import GL
        from OpenGL.GL import shaders
        if GL.glGetIntegerv(GL.GL_MAJOR_VERSION) < 3:  # Mesa gives 4.5 for 3.3
            raise RuntimeError("not a 3.x context")
        vao = GL.glGenVertexArrays(1)
        GL.glBindVertexArray(vao)
        prog = shaders.compileProgram(shaders.compileShader(VS, GL.GL_VERTEX_SHADER),
                                      shaders.compileShader(FS, GL.GL_FRAGMENT_SHADER))
        data = np.array([-0.8, -0.7, 1, 0, 0, 0.9, -0.5, 0, 1, 0, -0.1, 0.8, 0, 0, 1], np.float32)
        buf = GL.glGenBuffers(1)
        GL.glBindBuffer(GL.GL_ARRAY_BUFFER, buf)
        GL.glBufferData(GL.GL_ARRAY_BUFFER, data, GL.GL_STATIC_DRAW)
        GL.glVertexAttribPointer(0, 2, GL.GL_FLOAT, False, 20, None)
        GL.glVertexAttribPointer(1, 3, GL.GL_FLOAT, False, 20, ctypes.c_void_p(8))
        GL.glEnableVertexAttribArray(0)
        GL.glEnableVertexAttribArray(1)
        GL.glUseProgram(prog)
        GL.glClearColor(0.2, 0.2, 0.2, 1.0)
        GL.glClear(GL.GL_COLOR_BUFFER_BIT)
        GL.glDrawArrays(GL.GL_TRIANGLES, 0, 3)
        GL.glFinish()
        px = GL.glReadPixels(0, 0, W, H, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE)
        save(outdir, name, np.frombuffer(bytes(px), np.uint8).reshape(H, W, 4), top_first=False)
    finally:
        glfw.terminate()


if __name__ == "__main__":
    run([("glfw_core_triangle", triangle)])
