"""Programs that get their context through EGL, unmodified, on shaderbox's
libEGL.so.1 (scripts/egl-libs.sh's directory on LD_LIBRARY_PATH) and on
the system's (libglvnd dispatching to Mesa): moderngl's standalone
`backend="egl"` context (glcontext dlopens libEGL and libGL) drawing an
indexed, textured, depth-tested cube into its own framebuffer; pyglet 2's
headless mode (an EGL pbuffer window) drawing its `shapes` with pyglet's
own shaders through a batch; VTK's vtkEGLRenderWindow (the wheel's EGL
window, chosen by VTK_DEFAULT_OPENGL_WINDOW) with the OSMesa scenes'
elevation pipeline and PyVista's show_edges.
"""
import math
import os

os.environ["VTK_DEFAULT_OPENGL_WINDOW"] = "vtkEGLRenderWindow"

import numpy as np  # noqa: E402

import vtk_scenes  # noqa: E402
from output import run, save  # noqa: E402

W, H = 160, 120


def perspective(fovy, aspect, near, far):
    f = 1.0 / math.tan(fovy / 2)
    return np.array([[f / aspect, 0, 0, 0], [0, f, 0, 0],
                     [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)],
                     [0, 0, -1, 0]], dtype="f4")


def rotation(ax, ay):
    cx, sx, cy, sy = math.cos(ax), math.sin(ax), math.cos(ay), math.sin(ay)
    rx = np.array([[1, 0, 0, 0], [0, cx, -sx, 0], [0, sx, cx, 0], [0, 0, 0, 1]], dtype="f4")
    ry = np.array([[cy, 0, sy, 0], [0, 1, 0, 0], [-sy, 0, cy, 0], [0, 0, 0, 1]], dtype="f4")
    return rx @ ry


def cube():
    """24 vertices (position, normal, uv) and 36 indices."""
    verts, idx = [], []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            n = [0.0, 0.0, 0.0]
            n[axis] = sign
            u = [0.0, 0.0, 0.0]
            v = [0.0, 0.0, 0.0]
            u[(axis + 1) % 3] = 1.0
            v[(axis + 2) % 3] = sign
            base = len(verts)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.6 * (n[k] + a * u[k] + b * v[k]) for k in range(3)]
                verts.append(p + n + [(a + 1) / 2, (b + 1) / 2])
            idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return np.array(verts, dtype="f4"), np.array(idx, dtype="i4")


def moderngl_cube(outdir, name):
    import moderngl
    ctx = moderngl.create_standalone_context(backend="egl", require=330)
    prog = ctx.program(
        vertex_shader="""#version 330 core
uniform mat4 mvp;
uniform mat4 model;
in vec3 in_pos; in vec3 in_normal; in vec2 in_uv;
out vec3 normal; out vec2 uv;
void main() {
    gl_Position = mvp * vec4(in_pos, 1.0);
    normal = mat3(model) * in_normal;
    uv = in_uv;
}""",
        fragment_shader="""#version 330 core
uniform sampler2D tex;
in vec3 normal; in vec2 uv;
out vec4 frag;
void main() {
    float light = 0.25 + 0.75 * max(dot(normalize(normal), normalize(vec3(0.4, 0.7, 0.6))), 0.0);
    frag = vec4(texture(tex, uv).rgb * light, 1.0);
}""",
    )
    verts, idx = cube()
    vao = ctx.vertex_array(prog, [(ctx.buffer(verts.tobytes()), "3f 3f 2f", "in_pos", "in_normal", "in_uv")],
                           index_buffer=ctx.buffer(idx.tobytes()), index_element_size=4)
    # An 8x8 checkerboard, mipmapped; linear filtering.
    checker = np.zeros((8, 8, 3), dtype="u1")
    for y in range(8):
        for x in range(8):
            checker[y, x] = (230, 140, 40) if (x + y) % 2 else (40, 90, 200)
    tex = ctx.texture((8, 8), 3, checker.tobytes())
    tex.build_mipmaps()
    tex.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
    tex.use(0)
    prog["tex"].value = 0
    model = rotation(0.55, 0.8)
    view = np.eye(4, dtype="f4")
    view[2, 3] = -3.0
    mvp = perspective(0.9, W / H, 0.5, 10.0) @ view @ model
    # moderngl writes matrices column-major from row-major numpy arrays.
    prog["mvp"].write(mvp.T.copy().tobytes())
    prog["model"].write(model.T.copy().tobytes())
    fbo = ctx.framebuffer(ctx.renderbuffer((W, H)), ctx.depth_renderbuffer((W, H)))
    fbo.use()
    ctx.enable(moderngl.DEPTH_TEST)
    fbo.clear(0.1, 0.12, 0.15, 1.0, depth=1.0)
    vao.render()
    data = np.frombuffer(fbo.read(components=4), dtype="u1").reshape(H, W, 4)
    save(outdir, name, data, top_first=False)
    ctx.release()


def pyglet_shapes(outdir, name):
    import pyglet
    pyglet.options["headless"] = True
    pyglet.options["shadow_window"] = False
    from pyglet import gl, shapes
    # RGBA8 asked for: the first config Mesa offers a pbuffer is RGB565.
    config = gl.Config(red_size=8, green_size=8, blue_size=8, alpha_size=8, depth_size=24)
    win = pyglet.window.Window(W, H, visible=False, config=config)
    win.switch_to()
    batch = pyglet.graphics.Batch()
    items = [
        shapes.Rectangle(10, 12, 70, 40, color=(200, 60, 60), batch=batch),
        shapes.Circle(110, 70, 33, segments=48, color=(60, 170, 90, 200), batch=batch),
        shapes.Triangle(20, 100, 70, 60, 95, 112, color=(70, 90, 220), batch=batch),
        shapes.Line(5, 5, 155, 110, thickness=3, color=(240, 230, 80), batch=batch),
    ]
    gl.glClearColor(0.15, 0.15, 0.18, 1.0)
    win.clear()
    batch.draw()
    image = pyglet.image.get_buffer_manager().get_color_buffer().get_image_data()
    data = np.frombuffer(image.get_data("RGBA", W * 4), dtype="u1").reshape(H, W, 4)
    save(outdir, name, data, top_first=False)
    del items
    win.close()


if __name__ == "__main__":
    run([("moderngl_egl_cube", moderngl_cube), ("pyglet_headless_shapes", pyglet_shapes),
         ("vtk_egl_elevation_text", vtk_scenes.vtk_elevation),
         ("pyvista_egl_edges", vtk_scenes.pyvista_edges)])
