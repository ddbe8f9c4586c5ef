"""Vertex data, drawing, textures, and the fixed-function state reaching shaders."""

import numpy as np
import pytest

import shaderbox
from conftest import BIG_TRIANGLE, FS, VS

# Writes one value to the whole screen.
SHOW_VS = "void main() { gl_Position = gl_Vertex; }"


def show(ctx, expr, decls=""):
    """Draws a full-screen triangle whose colour is the GLSL ``expr``; returns pixel (0, 0)."""
    prog = ctx.program(vertex_shader=SHOW_VS, fragment_shader=f"{decls}\nvoid main() {{ gl_FragColor = {expr}; }}")
    vao = ctx.vertex_array(prog, [(BIG_TRIANGLE, "2f", "gl_Vertex")])
    ctx.clear()
    return prog, vao


def pixel(ctx, vao):
    vao.render()
    return ctx.read()[0, 0].tolist()


def test_user_attributes_and_builtin_color(ctx):
    vs = """
    attribute vec2 pos;
    varying vec4 c;
    void main() { c = gl_Color; gl_Position = vec4(pos, 0.0, 1.0); }
    """
    fs = "varying vec4 c; void main() { gl_FragColor = c; }"
    prog = ctx.program(vertex_shader=vs, fragment_shader=fs)
    colors = np.array([[255, 0, 0, 255]] * 3, dtype=np.uint8)  # normalized by GL for gl_Color
    vao = ctx.vertex_array(prog, [(BIG_TRIANGLE, "2f", "pos"), (colors, "4u1", "gl_Color")])
    assert vao.vertices == 3
    ctx.clear()
    vao.render("triangles")
    assert (ctx.read() == [255, 0, 0, 255]).all()


def test_interleaved_buffer_with_padding(ctx):
    vs = """
    attribute vec2 pos;
    attribute vec3 col;
    varying vec3 c;
    void main() { c = col; gl_Position = vec4(pos, 0.0, 1.0); }
    """
    prog = ctx.program(vertex_shader=vs, fragment_shader="varying vec3 c; void main() { gl_FragColor = vec4(c, 1.0); }")
    data = np.zeros((3, 6), dtype=np.float32)  # pos (2), 4 bytes of padding, col (3)
    data[:, :2] = BIG_TRIANGLE
    data[:, 3:] = (0.0, 0.0, 1.0)
    vao = ctx.vertex_array(prog, [(ctx.buffer(data), "2f 4x 3f", "pos", "col")])
    ctx.clear()
    vao.render()
    assert (ctx.read() == [0, 0, 255, 255]).all()


def test_indexed_drawing_and_partial_draws(ctx):
    prog = ctx.program(vertex_shader=VS, fragment_shader=FS)
    quad = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=np.float32)
    prog["color"] = (1, 1, 1, 1)
    vao = ctx.vertex_array(prog, [(quad, "2f", "pos")], index_buffer=[0, 1, 2])
    assert vao.vertices == 3 and vao.index_buffer.dtype == np.uint32
    ctx.clear()
    vao.render()
    px = ctx.read()
    # Lower-right half only: bottom-right corner white, top-left corner black.
    assert px[-1, -1].tolist() == [255, 255, 255, 255] and px[0, 0].tolist() == [0, 0, 0, 255]
    full = ctx.vertex_array(prog, [(quad, "2f", "pos")], index_buffer=np.array([0, 1, 2, 0, 2, 3], dtype=np.uint16))
    full.render()
    assert (ctx.read() == 255).all()
    ctx.clear()
    plain = ctx.vertex_array(prog, [(quad, "2f", "pos")])
    plain.render("triangle_fan", vertices=3)
    assert ctx.read()[0, 0].tolist() == [0, 0, 0, 255]
    plain.render("quads")
    assert (ctx.read() == 255).all()


def test_vertex_array_errors(ctx):
    prog = ctx.program(vertex_shader=VS, fragment_shader=FS)
    with pytest.raises(TypeError, match="reads float32 but the buffer for \\['pos'\\] holds float64"):
        ctx.vertex_array(prog, [(BIG_TRIANGLE.astype(np.float64), "2f", "pos")])
    # The matching format for float64 data works.
    ctx.vertex_array(prog, [(BIG_TRIANGLE.astype(np.float64), "2f8", "pos")])
    with pytest.raises(KeyError, match="no active attribute 'position'.*pos"):
        ctx.vertex_array(prog, [(BIG_TRIANGLE, "2f", "position")])
    with pytest.raises(ValueError, match="1 attribute\\(s\\) but 2 name"):
        ctx.vertex_array(prog, [(BIG_TRIANGLE, "2f", "pos", "gl_Color")])
    with pytest.raises(ValueError, match="'2q' is not COUNT\\+TYPE"):
        ctx.vertex_array(prog, [(BIG_TRIANGLE, "2q", "pos")])
    with pytest.raises(ValueError, match="1-4"):
        ctx.vertex_array(prog, [(BIG_TRIANGLE, "5f", "pos")])
    with pytest.raises(ValueError, match="only integer types"):
        ctx.vertex_array(prog, [(BIG_TRIANGLE, "2fn", "pos")])
    with pytest.raises(ValueError, match="given twice"):
        ctx.vertex_array(prog, [(BIG_TRIANGLE, "2f", "pos"), (BIG_TRIANGLE, "2f", "pos")])
    with pytest.raises(TypeError, match="indices must be integers"):
        ctx.vertex_array(prog, [(BIG_TRIANGLE, "2f", "pos")], index_buffer=[0.0, 1.0, 2.0])
    with pytest.raises(TypeError, match="needs a Program"):
        ctx.vertex_array("prog", [(BIG_TRIANGLE, "2f", "pos")])
    with pytest.raises(TypeError, match="numbers"):
        ctx.buffer(np.array(["a", "b"]))
    vao = ctx.vertex_array(prog, [(BIG_TRIANGLE, "2f", "pos")])
    with pytest.raises(ValueError, match="mode 'hexagons'"):
        vao.render("hexagons")
    with pytest.raises(ValueError, match="the buffers hold 3"):
        vao.render(vertices=4)
    bad_builtin = ctx.vertex_array(prog, [(BIG_TRIANGLE, "2f", "gl_Banana")])
    with pytest.raises(KeyError, match="not a built-in attribute"):
        bad_builtin.render()


def test_depth_test_and_depth_buffer(ctx):
    prog = ctx.program(vertex_shader="uniform float z; void main() { gl_Position = vec4(gl_Vertex.xy, z, 1.0); }",
                       fragment_shader=FS)
    vao = ctx.vertex_array(prog, [(BIG_TRIANGLE, "2f", "gl_Vertex")])
    ctx.depth_test = True
    ctx.clear()
    prog["z"], prog["color"] = 0.5, (1, 0, 0, 1)
    vao.render()
    prog["z"], prog["color"] = 0.8, (0, 1, 0, 1)  # behind: rejected
    vao.render()
    assert (ctx.read() == [255, 0, 0, 255]).all()
    assert np.allclose(ctx.read_depth(), 0.75, atol=1e-6)


def test_nonsquare_matrix_layout_in_the_shader(ctx):
    prog, vao = show(ctx, "vec4(m * vec2(1.0, 0.0), 1.0)", "#version 120\nuniform mat2x3 m;")
    prog["m"] = [[0.2, 0.9], [0.4, 0.9], [0.6, 0.9]]  # m[row, col]: column 0 is (0.2, 0.4, 0.6)
    assert pixel(ctx, vao) == [51, 102, 153, 255]


def test_lights_material_and_fog_reach_the_shader(ctx):
    prog, vao = show(ctx, "gl_LightSource[2].diffuse")
    ctx.lights[2].diffuse = (0.2, 0.4, 0.6, 0.8)
    assert np.allclose(ctx.lights[2].diffuse, [0.2, 0.4, 0.6, 0.8])
    assert pixel(ctx, vao) == [51, 102, 153, 204]

    prog, vao = show(ctx, "vec4(gl_LightSource[0].position.xyz, 1.0)")
    ctx.modelview = np.diag([0.5, 0.5, 0.5, 1.0])  # positions are transformed when set
    ctx.lights[0].position = (1.0, 0.5, 1.0, 0.0)
    ctx.modelview = np.identity(4)
    assert np.allclose(ctx.lights[0].position, [0.5, 0.25, 0.5, 0.0])
    assert pixel(ctx, vao) == [128, 64, 128, 255]
    assert not ctx.lights[0].enabled
    ctx.lights[0].enabled = True
    assert ctx.lights[0].enabled

    prog, vao = show(ctx, "vec4(gl_FrontMaterial.shininess / 128.0, gl_FrontMaterial.emission.g, 0.0, 1.0)")
    ctx.material.shininess = 64
    ctx.material.emission = (0, 1, 0, 1)
    assert ctx.material.shininess == 64.0
    assert pixel(ctx, vao) == [128, 255, 0, 255]

    prog, vao = show(ctx, "vec4(gl_Fog.density, gl_Fog.start, gl_Fog.end / 4.0, gl_Fog.scale)")
    ctx.fog.mode = "exp2"
    ctx.fog.density, ctx.fog.start, ctx.fog.end = 0.5, 0.25, 2.0
    assert ctx.fog.mode == "exp2" and ctx.fog.density == 0.5
    ctx.fog.enabled = True
    assert ctx.fog.enabled
    # scale = 1 / (end - start)
    assert pixel(ctx, vao) == [128, 64, 128, 146]

    prog, vao = show(ctx, "gl_LightModel.ambient")
    ctx.light_model_ambient = (0, 0, 1, 1)
    assert pixel(ctx, vao) == [0, 0, 255, 255]


def test_state_errors(ctx):
    with pytest.raises(ValueError, match="fog mode 'soup'"):
        ctx.fog.mode = "soup"
    with pytest.raises(ValueError, match="position needs 4 numbers"):
        ctx.lights[0].position = (1, 2, 3)
    with pytest.raises(TypeError, match="real numbers"):
        ctx.material.diffuse = "white"
    with pytest.raises(shaderbox.GLError, match="GL_INVALID_VALUE while setting the material"):
        ctx.material.shininess = 500  # GL allows 0-128
    with pytest.raises(shaderbox.GLError, match="GL_INVALID_VALUE") as info:
        ctx.lights[1].spot_cutoff = 120
    assert info.value.code == 0x0501
    assert len(ctx.lights) == 8


def test_textures_from_numpy_and_pil(ctx):
    fs = "uniform sampler2D tex; void main() { gl_FragColor = texture2D(tex, vec2(0.25, 0.25)); }"
    prog = ctx.program(vertex_shader=SHOW_VS, fragment_shader=fs)
    vao = ctx.vertex_array(prog, [(BIG_TRIANGLE, "2f", "gl_Vertex")])
    rgba = np.zeros((2, 2, 4), dtype=np.uint8)
    rgba[0, 0] = (10, 20, 30, 255)  # row 0 is t = 0
    tex = ctx.texture(rgba, filter="nearest")
    prog["tex"] = tex
    ctx.clear()
    assert pixel(ctx, vao) == [10, 20, 30, 255]

    lum = np.full((4, 4), 0.5, dtype=np.float32)
    tex2 = ctx.texture(lum, unit=1, filter="nearest", wrap="clamp")
    prog["tex"] = tex2
    assert tex2.unit == 1 and prog["tex"] == 1
    assert pixel(ctx, vao) == [128, 128, 128, 255]
    # Unit 0 still holds the first texture.
    prog["tex"] = 0
    assert pixel(ctx, vao) == [10, 20, 30, 255]

    pil = pytest.importorskip("PIL.Image")
    img = pil.new("RGB", (3, 3), (200, 100, 50))
    ctx.texture(img, unit=2, mipmaps=True)
    prog["tex"] = 2
    assert pixel(ctx, vao) == [200, 100, 50, 255]


def test_texture_errors(ctx):
    with pytest.raises(TypeError, match="uint8 .* or float32, got float64"):
        ctx.texture(np.zeros((2, 2, 3)))
    with pytest.raises(TypeError, match="got int64"):
        ctx.texture(np.zeros((2, 2), dtype=np.int64))
    with pytest.raises(ValueError, match="H x W or H x W x 1-4"):
        ctx.texture(np.zeros((2, 2, 5), dtype=np.uint8))
    with pytest.raises(ValueError, match="texture unit 99"):
        ctx.texture(np.zeros((2, 2), dtype=np.uint8), unit=99)
    with pytest.raises(ValueError, match="filter 'cubic'"):
        ctx.texture(np.zeros((2, 2), dtype=np.uint8), filter="cubic")
    with pytest.raises(ValueError, match="wrap 'tile'"):
        ctx.texture(np.zeros((2, 2), dtype=np.uint8), wrap="tile")


def test_fixed_function_vertex_stage(ctx):
    # No vertex shader: the generated fixed-function stage transforms gl_Vertex.
    prog = ctx.program(fragment_shader="void main() { gl_FragColor = vec4(1.0, 1.0, 0.0, 1.0); }")
    vao = ctx.vertex_array(prog, [(BIG_TRIANGLE, "2f", "gl_Vertex")])
    ctx.clear()
    vao.render()
    assert (ctx.read() == [255, 255, 0, 255]).all()
    # A model-view that moves the triangle off screen.
    ctx.modelview = np.array([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    ctx.clear()
    vao.render()
    assert (ctx.read() == [0, 0, 0, 255]).all()


def test_spheres_from_numpy():
    ctx = shaderbox.Context(64, 64, threads=1)
    centers = np.array([[0, 0, 0], [3, 0, 0]], dtype=np.float32)
    prog = ctx.draw_spheres(centers, radii=[1.0, 1.5], colors=[(1, 0, 0), (0, 0, 1)])
    px = ctx.read()
    # Left sphere reddish, right one bluish, corners background.
    row = px[32]
    assert row[:, 0].max() > 100 and row[:, 2].max() > 100
    assert px[0, 0].tolist() == [0, 0, 0, 255]
    assert prog["light_enabled"][:2].tolist() == [1.0, 1.0]
    # Deterministic whatever the thread count.
    ctx2 = shaderbox.Context(64, 64, threads=2)
    ctx2.draw_spheres(centers, radii=[1.0, 1.5], colors=[(1, 0, 0), (0, 0, 1)])
    assert np.array_equal(ctx2.read(), px)
    for effect in ("outline", "x", "x-red", "transparent"):
        ctx.draw_spheres(centers, effect=effect)
    with pytest.raises(ValueError, match="N x 3"):
        ctx.draw_spheres(np.zeros((2, 2)))
    with pytest.raises(ValueError, match="radii"):
        ctx.draw_spheres(centers, radii=[1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="> 0"):
        ctx.draw_spheres(centers, radii=0.0)
    with pytest.raises(ValueError, match="effect 'glow'"):
        ctx.draw_spheres(centers, effect="glow")
