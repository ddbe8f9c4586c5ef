"""VTK's Python wheel and PyVista, unmodified, on OSMesa
(VTK_DEFAULT_OPENGL_WINDOW=vtkOSOpenGLRenderWindow, which loads
libOSMesa.so.8 and asks for a 3.2+ core context): a VTK pipeline with
scalars through a lookup table and a text actor; PyVista's off-screen
screenshot() of a mesh with scalars and a colour map with a scalar bar, of
a volume (the GPU ray-cast mapper: 3D textures, GLSL 1.50), and of text.

Multisampling is off in every scene: shaderbox's multisample buffers take
every sample at the pixel centre (docs/CONFORMANCE.md), so with it on
the two implementations would differ at every edge by design.
"""
import os

os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkOSOpenGLRenderWindow")

import numpy as np  # noqa: E402
import pyvista as pv  # noqa: E402
import vtk  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

from output import run, save  # noqa: E402

W, H = 320, 240
pv.OFF_SCREEN = True


def vtk_elevation(outdir, name):
    sphere = vtk.vtkSphereSource()
    sphere.SetThetaResolution(40)
    sphere.SetPhiResolution(40)
    elev = vtk.vtkElevationFilter()
    elev.SetInputConnection(sphere.GetOutputPort())
    elev.SetLowPoint(0, -0.5, 0)
    elev.SetHighPoint(0, 0.5, 0)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(elev.GetOutputPort())
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    ren = vtk.vtkRenderer()
    ren.AddActor(actor)
    ren.SetBackground(0.1, 0.2, 0.3)
    text = vtk.vtkTextActor()
    text.SetInput("shaderbox")
    text.GetTextProperty().SetFontSize(24)
    ren.AddViewProp(text)
    win = vtk.vtkRenderWindow()
    win.SetMultiSamples(0)
    win.SetOffScreenRendering(1)
    win.AddRenderer(ren)
    win.SetSize(W, H)
    win.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.Update()
    img = grab.GetOutput()
    w, h, _ = img.GetDimensions()
    px = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, -1)
    save(outdir, name, px, top_first=False)
    win.Finalize()


def plotter():
    p = pv.Plotter(off_screen=True, window_size=(W, H))
    p.disable_anti_aliasing()
    p.ren_win.SetMultiSamples(0)
    return p


def pyvista_scalars(outdir, name):
    mesh = pv.ParametricRandomHills(random_seed=3, u_res=60, v_res=60)
    mesh["height"] = mesh.points[:, 2]
    p = plotter()
    p.add_mesh(mesh, scalars="height", cmap="viridis", smooth_shading=True,
               scalar_bar_args={"title": "height"})
    p.camera_position = [(30, -40, 30), (0, 0, 2), (0, 0, 1)]
    save(outdir, name, p.screenshot(return_img=True))
    p.close()


def pyvista_volume(outdir, name):
    n = 48
    g = (np.indices((n, n, n)) + 0.5) / n * 2 - 1
    r = np.sqrt((g ** 2).sum(axis=0))
    values = np.exp(-8 * (r - 0.6) ** 2) + 0.5 * np.exp(-30 * ((g[0] - 0.2) ** 2 + g[1] ** 2 + g[2] ** 2))
    grid = pv.ImageData(dimensions=(n, n, n))
    grid.point_data["density"] = values.ravel(order="F").astype(np.float32)
    p = plotter()
    p.add_volume(grid, scalars="density", cmap="magma", opacity="sigmoid", show_scalar_bar=False)
    p.camera_position = [(120, 90, 80), (n / 2, n / 2, n / 2), (0, 0, 1)]
    save(outdir, name, p.screenshot(return_img=True))
    p.close()


def pyvista_text(outdir, name):
    p = plotter()
    p.set_background("white")
    p.add_text("shaderbox 3.3", position="upper_left", font_size=18, color="black")
    # Back faces culled: the hidden bottom face meets the sides along the
    # silhouette at equal depth, where either may win by a rounding.
    p.add_mesh(pv.Cube(), color="tan", culling="back")
    p.camera_position = "iso"
    save(outdir, name, p.screenshot(return_img=True))
    p.close()


def pyvista_edges(outdir, name):
    # show_edges: VTK's polydata mapper draws each triangle's edges in the
    # fragment shader from distances a geometry shader computes.
    p = plotter()
    p.add_mesh(pv.Sphere(theta_resolution=12, phi_resolution=9), color="lightsteelblue",
               show_edges=True, edge_color="black", line_width=2)
    p.camera_position = [(2.2, -2.9, 1.6), (0, 0, 0), (0, 0, 1)]
    save(outdir, name, p.screenshot(return_img=True))
    p.close()


if __name__ == "__main__":
    run([("vtk_elevation_text", vtk_elevation), ("pyvista_scalars", pyvista_scalars),
         ("pyvista_volume", pyvista_volume), ("pyvista_text", pyvista_text),
         ("pyvista_edges", pyvista_edges)])
