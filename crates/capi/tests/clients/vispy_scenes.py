"""vispy's scene visuals, unmodified, on OSMesa: the wheel's osmesa app
back end (`vispy.use(app="osmesa")`) loads the library that
`OSMESA_LIBRARY` names and takes its GL functions from it too, as vispy's
users run it headless. compare.py runs this script once with
`LD_LIBRARY_PATH` at shaderbox's library directory and once without; each
run points `OSMESA_LIBRARY` at the `libOSMesa.so.8` the dynamic loader
picks (so shaderbox's, then Debian's libosmesa6).

vispy makes a GL 2.1 context (GLSL 1.20 shaders) and renders each canvas
into its own framebuffer object; `SceneCanvas.render()` reads it back.
The scenes: markers in every mode (antialiased discs, spherical impostors
writing `gl_FragDepth` with blending on, the whole symbol set), `Line` in
both methods (`gl`: GL lines of the width asked; `agg`: triangles with an
antialiasing shader) at widths 1, 2 and 5, SDF text, an isosurface, a mesh
in each shading mode, an image with each of vispy's interpolations (the
texture's own nearest/linear and the kernels of spatial_filters.frag) and a
volume with each rendering method (3D texture ray casting).

Each scene's bound against Mesa is in vispy_bounds.txt (compare.py
--bounds).
"""
import ctypes
import os


def _osmesa_library():
    """The path of the libOSMesa.so.8 that this process's dynamic loader
    resolves (LD_LIBRARY_PATH first, then the system's)."""
    ctypes.CDLL("libOSMesa.so.8")
    with open("/proc/self/maps") as maps:
        for line in maps:
            fields = line.split()
            if len(fields) >= 6 and "libOSMesa" in os.path.basename(fields[-1]):
                return fields[-1]
    raise OSError("libOSMesa.so.8 loaded but not found in /proc/self/maps")


os.environ["OSMESA_LIBRARY"] = _osmesa_library()

import numpy as np  # noqa: E402
import vispy  # noqa: E402

vispy.use(app="osmesa")

from vispy import scene  # noqa: E402
from vispy.geometry import create_sphere  # noqa: E402
from vispy.visuals.markers import symbol_shaders  # noqa: E402

from output import run, save  # noqa: E402

W, H = 320, 320


def canvas():
    c = scene.SceneCanvas(size=(W, H), show=False, bgcolor="black")
    return c, c.central_widget.add_view()


def finish(outdir, name, c):
    save(outdir, name, c.render())
    c.close()


def markers_spherical(outdir, name):
    # 300 lit spheres that overlap: each fragment writes gl_FragDepth
    # (the sphere's surface) with blending on and an antialiased rim.
    c, v = canvas()
    pos = np.random.default_rng(7).normal(size=(300, 3)).astype(np.float32)
    m = scene.visuals.Markers(parent=v.scene, spherical=True, scaling=True)
    m.set_data(pos, size=0.4, face_color=(0.3, 0.6, 1.0, 1.0), edge_width=0)
    v.camera = "turntable"
    v.camera.fov = 45
    v.camera.distance = 8
    finish(outdir, name, c)


def markers_disc(outdir, name):
    c, v = canvas()
    pos = np.random.default_rng(8).normal(size=(300, 2)).astype(np.float32) * 60 + 160
    m = scene.visuals.Markers(parent=v.scene)
    m.set_data(pos, size=14, face_color=(1, 0.5, 0.2, 1), edge_color="white", edge_width=1.5)
    finish(outdir, name, c)


def markers_symbols(outdir, name):
    # Every symbol of vispy's marker shader, three sizes each, one per
    # cell of a grid (a per-marker symbol array).
    c, v = canvas()
    names = list(symbol_shaders)
    pos, sym, size = [], [], []
    for i, s in enumerate(names):
        for j, sz in enumerate((9, 16, 25)):
            pos.append((20 + (i % 5) * 62 + j * 16, 40 + (i // 5) * 100 + j * 26))
            sym.append(s)
            size.append(sz)
    m = scene.visuals.Markers(parent=v.scene)
    m.set_data(np.array(pos, np.float32), symbol=np.array(sym), size=np.array(size, np.float32),
               face_color=(0.2, 0.8, 0.4, 1), edge_color=(1, 1, 1, 1), edge_width=1)
    finish(outdir, name, c)


def line(width, method):
    def draw(outdir, name):
        c, v = canvas()
        t = np.linspace(0, 4 * np.pi, 200)
        pos = np.c_[160 + 120 * np.cos(t) * t / 12, 160 + 120 * np.sin(t) * t / 12]
        scene.visuals.Line(pos=pos.astype(np.float32), color=(0.9, 0.9, 0.2, 1), width=width,
                           method=method, parent=v.scene)
        finish(outdir, name, c)
    return draw


def text(outdir, name):
    c, v = canvas()
    scene.visuals.Text("shaderbox", color="white", font_size=28, pos=(160, 110), parent=v.scene)
    scene.visuals.Text("vispy 0.17 SDF text", color=(1, 0.8, 0.3, 1), font_size=14,
                       pos=(160, 200), parent=v.scene)
    finish(outdir, name, c)


def isosurface(outdir, name):
    c, v = canvas()
    x, y, z = np.mgrid[-1:1:32j, -1:1:32j, -1:1:32j]
    data = (x ** 2 + y ** 2 * 1.5 + z ** 2 * 0.7).astype(np.float32)
    # The isosurface's vertices are in voxel units (0..31): the camera
    # looks at the volume's centre from a distance that frames it.
    scene.visuals.Isosurface(data, level=0.6, color=(0.5, 0.6, 1, 1), shading="smooth",
                             parent=v.scene)
    v.camera = scene.TurntableCamera(fov=45, distance=70, elevation=25, azimuth=35,
                                     center=(15.5, 15.5, 15.5))
    finish(outdir, name, c)


def mesh(shading):
    def draw(outdir, name):
        c, v = canvas()
        md = create_sphere(20, 20, radius=1.0)
        scene.visuals.Mesh(meshdata=md, shading=shading, color=(0.4, 0.7, 0.3, 1),
                           parent=v.scene)
        v.camera = "turntable"
        v.camera.distance = 4
        finish(outdir, name, c)
    return draw


def image(interpolation):
    def draw(outdir, name):
        c, v = canvas()
        data = np.random.default_rng(9).random((16, 16)).astype(np.float32)
        im = scene.visuals.Image(data, interpolation=interpolation, cmap="viridis",
                                 parent=v.scene)
        im.transform = scene.STTransform(scale=(20, 20))
        finish(outdir, name, c)
    return draw


def volume(method):
    def draw(outdir, name):
        c, v = canvas()
        n = 32
        g = (np.indices((n, n, n)) + 0.5) / n * 2 - 1
        r = np.sqrt((g ** 2).sum(axis=0))
        vol = (np.exp(-8 * (r - 0.6) ** 2)
               + 0.5 * np.exp(-30 * ((g[0] - 0.2) ** 2 + g[1] ** 2 + g[2] ** 2)))
        scene.visuals.Volume(vol.astype(np.float32), method=method, threshold=0.6,
                             parent=v.scene)
        v.camera = scene.TurntableCamera(fov=45, distance=70, elevation=25, azimuth=35,
                                         center=(n / 2, n / 2, n / 2))
        finish(outdir, name, c)
    return draw


INTERPOLATIONS = ("nearest", "linear", "bessel", "bicubic", "blackman", "catrom", "gaussian",
                  "hamming", "hanning", "hermite", "kaiser", "lanczos", "mitchell", "quadric",
                  "sinc", "spline16", "spline36")
VOLUME_METHODS = ("mip", "minip", "attenuated_mip", "iso", "translucent", "additive", "average")

SCENES = ([("markers_spherical", markers_spherical), ("markers_disc", markers_disc),
           ("markers_symbols", markers_symbols)]
          + [(f"line_{m}_w{w}", line(w, m)) for m in ("gl", "agg") for w in (1, 2, 5)]
          + [("text", text), ("isosurface", isosurface)]
          + [(f"mesh_{s}", mesh(s)) for s in (None, "flat", "smooth")]
          + [(f"image_{i}", image(i)) for i in INTERPOLATIONS]
          + [(f"volume_{m}", volume(m)) for m in VOLUME_METHODS])

if __name__ == "__main__":
    run(SCENES)
