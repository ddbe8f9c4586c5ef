"""pyrender's OffscreenRenderer, unmodified, on OSMesa (it asks for a 3.3
core context through OSMesaCreateContextAttribs): a lit, textured trimesh
scene with directional shadows and a spot light; a normal-mapped,
metallic-roughness surface under a point light (pyrender's fragment shader
builds the tangent frame from dFdx/dFdy); and the depth buffer it reads
back, mapped to grey levels."""
import os

os.environ.setdefault("PYOPENGL_PLATFORM", "osmesa")

import numpy as np  # noqa: E402
import pyrender  # noqa: E402
import trimesh  # noqa: E402
from PIL import Image  # noqa: E402

from output import run, save  # noqa: E402

W, H = 320, 240


def camera_pose(eye, target):
    pose = np.eye(4)
    pose[:3, 3] = eye
    look = np.asarray(target, float) - eye
    look /= np.linalg.norm(look)
    right = np.cross(look, [0, 1, 0])
    right /= np.linalg.norm(right)
    pose[:3, 0], pose[:3, 1], pose[:3, 2] = right, np.cross(right, look), -look
    return pose


def checker(size, cells, c0, c1):
    ij = np.indices((size, size)) * cells // size
    mask = (ij.sum(axis=0) % 2 == 0)[..., None]
    return np.where(mask, np.array(c0, np.uint8), np.array(c1, np.uint8)).astype(np.uint8)


def shadow_scene():
    box = trimesh.creation.box(extents=(1, 1, 1))
    uv = np.random.default_rng(0).random((len(box.vertices), 2))
    box.visual = trimesh.visual.TextureVisuals(
        uv=uv, image=Image.fromarray(checker(64, 8, (255, 128, 0), (0, 0, 0))))
    sphere = trimesh.creation.icosphere(subdivisions=3, radius=0.4)
    sphere.apply_translation((1.2, 0, 0))
    ground = trimesh.creation.box(extents=(6, 0.1, 6))
    ground.apply_translation((0, -0.6, 0))
    scene = pyrender.Scene(ambient_light=[0.1, 0.1, 0.1])
    for m in (box, sphere, ground):
        scene.add(pyrender.Mesh.from_trimesh(m))
    pose = camera_pose(np.array([0.5, 1.5, 3.5]), [0.3, 0, 0])
    scene.add(pyrender.PerspectiveCamera(yfov=np.pi / 3.0), pose=pose)
    # From the upper left, so the shadows fall visibly on the ground.
    scene.add(pyrender.DirectionalLight(color=np.ones(3), intensity=3.0),
              pose=camera_pose(np.array([-2.0, 4.0, 1.5]), [0, 0, 0]))
    scene.add(pyrender.SpotLight(color=np.ones(3), intensity=8.0, innerConeAngle=0.3,
                                 outerConeAngle=0.6), pose=pose)
    return scene


def shadows(outdir, name):
    r = pyrender.OffscreenRenderer(W, H)
    try:
        color, _ = r.render(shadow_scene(), flags=pyrender.RenderFlags.SHADOWS_DIRECTIONAL)
    finally:
        r.delete()
    save(outdir, name, color)


def depth(outdir, name):
    r = pyrender.OffscreenRenderer(W, H)
    try:
        z = r.render(shadow_scene(), flags=pyrender.RenderFlags.DEPTH_ONLY)
    finally:
        r.delete()
    # Linear depth in metres, 0 where nothing was drawn; 0..8 m to 0..255.
    save(outdir, name, np.repeat(np.clip(z * 32.0, 0, 255).astype(np.uint8)[..., None], 3, axis=2))


def normal_map(outdir, name):
    # A bumpy normal map: rings of tilted normals, encoded as 0.5 + n/2.
    size = 128
    y, x = (np.indices((size, size)) + 0.5) / size * 2 - 1
    phase = np.sin(np.hypot(x, y) * 18.0)
    n = np.stack([0.6 * phase * x, 0.6 * phase * y, np.ones_like(x)], axis=-1)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    normals = ((n * 0.5 + 0.5) * 255).astype(np.uint8)
    material = pyrender.MetallicRoughnessMaterial(
        baseColorTexture=pyrender.Texture(source=checker(64, 4, (200, 180, 150), (90, 120, 160)),
                                          source_channels="RGB"),
        normalTexture=pyrender.Texture(source=normals, source_channels="RGB"),
        metallicFactor=0.2, roughnessFactor=0.5)
    plane = trimesh.creation.box(extents=(2.5, 2.5, 0.05))
    uv = (plane.vertices[:, :2] / 2.5 + 0.5)
    plane.visual = trimesh.visual.TextureVisuals(uv=uv)
    scene = pyrender.Scene(ambient_light=[0.05, 0.05, 0.05])
    scene.add(pyrender.Mesh.from_trimesh(plane, material=material))
    scene.add(pyrender.PerspectiveCamera(yfov=np.pi / 3.5), pose=camera_pose(np.array([0.0, -1.2, 3.0]), [0, 0, 0]))
    light = np.eye(4)
    light[:3, 3] = (1.0, 1.0, 1.5)
    scene.add(pyrender.PointLight(color=np.ones(3), intensity=12.0), pose=light)
    r = pyrender.OffscreenRenderer(W, H)
    try:
        color, _ = r.render(scene)
    finally:
        r.delete()
    save(outdir, name, color)


if __name__ == "__main__":
    run([("pyrender_shadows", shadows), ("pyrender_normal_map", normal_map),
         ("pyrender_depth", depth)])
