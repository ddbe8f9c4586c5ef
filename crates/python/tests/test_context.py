"""Contexts, clearing, reading, images."""

import numpy as np
import pytest

import shaderbox


def test_size_and_repr(ctx):
    assert (ctx.width, ctx.height) == (32, 24)
    assert ctx.size == (32, 24)
    assert ctx.viewport == (0, 0, 32, 24)
    assert "32x24" in repr(ctx)


@pytest.mark.parametrize("w,h", [(0, 10), (10, -1), (9000, 10)])
def test_bad_sizes_are_value_errors(w, h):
    with pytest.raises(ValueError, match="each side must be 1-8192"):
        shaderbox.Context(w, h)


def test_size_must_be_int():
    with pytest.raises(TypeError, match="width must be an int"):
        shaderbox.Context(10.5, 10)
    with pytest.raises(ValueError, match="threads"):
        shaderbox.Context(4, 4, threads=-1)


def test_reading_before_drawing_is_an_error(ctx):
    with pytest.raises(shaderbox.Error, match="nothing has been drawn"):
        ctx.read()
    with pytest.raises(shaderbox.Error, match="nothing has been drawn"):
        ctx.read_depth()
    with pytest.raises(shaderbox.Error, match="nothing has been drawn"):
        ctx.image()


def test_clear_and_read(ctx):
    ctx.clear((1.0, 0.5, 0.0))
    px = ctx.read()
    assert px.shape == (24, 32, 4) and px.dtype == np.uint8
    assert (px == [255, 128, 0, 255]).all()
    depth = ctx.read_depth()
    assert depth.shape == (24, 32) and depth.dtype == np.float32
    assert np.all(depth == 1.0)
    ctx.clear((0, 0, 0, 0), depth=0.25)
    assert (ctx.read() == 0).all()
    assert np.allclose(ctx.read_depth(), 0.25, atol=1e-6)


def test_clear_color_errors(ctx):
    with pytest.raises(ValueError, match="clear color needs 4 numbers"):
        ctx.clear((1, 2))
    with pytest.raises(TypeError, match="real numbers"):
        ctx.clear("red")
    with pytest.raises(ValueError, match="finite"):
        ctx.clear((np.nan, 0, 0, 1))


def test_image_png_and_save(ctx, tmp_path):
    ctx.clear((0.0, 0.0, 1.0, 1.0))
    img = ctx.image()
    assert (img.width, img.height) == (32, 24)
    png = img._repr_png_()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    out = tmp_path / "out.png"
    img.save(out)
    assert out.read_bytes() == png
    assert np.array_equal(np.asarray(img), ctx.read())
    with pytest.raises(ValueError, match="PNG only"):
        img.save(tmp_path / "out.jpg")
    pil = pytest.importorskip("PIL.Image")
    back = pil.open(out)
    assert back.size == (32, 24) and back.mode == "RGB"
    assert back.getpixel((0, 0)) == (0, 0, 255)
    assert img.to_pil().mode == "RGB"
    assert ctx.image(alpha=True).to_pil().mode == "RGBA"


def test_image_checks_its_array():
    with pytest.raises(TypeError, match="uint8"):
        shaderbox.Image(np.zeros((2, 2, 4), dtype=np.float32))
    with pytest.raises(ValueError, match="H x W x 4"):
        shaderbox.Image(np.zeros((2, 2, 3), dtype=np.uint8))


def test_matrices_round_trip(ctx):
    assert np.array_equal(ctx.modelview, np.identity(4))
    m = np.arange(16, dtype=np.float32).reshape(4, 4)
    ctx.modelview = m
    assert np.array_equal(ctx.modelview, m)
    ctx.ortho(-2, 2, -1, 1, 0.5, 10)
    p = ctx.projection
    assert p[0, 0] == pytest.approx(0.5) and p[1, 1] == pytest.approx(1.0)
    assert p[2, 3] == pytest.approx(-10.5 / 9.5)
    ctx.perspective(90, 1.0, 1.0, 3.0)
    p = ctx.projection
    assert p[3, 2] == -1 and p[3, 3] == 0 and p[0, 0] == pytest.approx(1.0)
    ctx.look_at((0, 0, 5), (0, 0, 0), (0, 1, 0))
    assert np.allclose(ctx.modelview[:3, 3], [0, 0, -5])
    with pytest.raises(ValueError, match="4x4"):
        ctx.modelview = np.identity(3)
    with pytest.raises(ValueError, match="must differ"):
        ctx.ortho(1, 1, 0, 1)
    with pytest.raises(ValueError, match="same point"):
        ctx.look_at((1, 1, 1), (1, 1, 1))


def test_capabilities(ctx):
    assert not ctx.depth_test
    ctx.depth_test = True
    assert ctx.depth_test and ctx.is_enabled("depth_test")
    ctx.enable("blend", "cull_face")
    assert ctx.is_enabled("blend")
    ctx.disable("blend")
    assert not ctx.is_enabled("blend")
    with pytest.raises(ValueError, match="capability 'wireframe'"):
        ctx.enable("wireframe")
    with pytest.raises(ValueError, match="depth function"):
        ctx.depth_func("sometimes")
    with pytest.raises(ValueError, match="blend factor"):
        ctx.blend_func("one", "many")
