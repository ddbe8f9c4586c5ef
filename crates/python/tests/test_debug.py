"""ctx.debug_pixel: the trace of one pixel from Python."""

import numpy as np
import pytest

import shaderbox
from conftest import BIG_TRIANGLE

VS = "void main() { gl_Position = gl_Vertex; }"
FS = """
uniform float edge;
void main() {
    float x = gl_FragCoord.x;
    if (x < edge)
        discard;
    gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0);
}
"""


def draw(ctx, edge):
    prog = ctx.program(vertex_shader=VS, fragment_shader=FS)
    prog["edge"] = edge
    vao = ctx.vertex_array(prog, [(BIG_TRIANGLE, "2f", "gl_Vertex")])
    vao.render()


def test_trace_shows_statements_values_and_operations(ctx):
    with ctx.debug_pixel(10, 3) as dbg:
        draw(ctx, 4.0)
    assert len(dbg.fragments) == 1
    f = dbg.fragments[0]
    assert f["discarded"] is None
    stores = {s["name"]: s["values"] for step in f["steps"] for s in step["stores"]}
    assert stores["x"] == [10.5]
    assert stores["gl_FragColor"] == [0.0, 1.0, 0.0, 1.0]
    assert f["operations"]["written"] is True
    assert "float x = gl_FragCoord.x;" in dbg.text
    assert "→ x = 10.5" in dbg.text
    assert ctx.read()[3, 10].tolist() == [0, 255, 0, 255]


def test_discard_is_named(ctx):
    with ctx.debug_pixel(1, 1) as dbg:
        draw(ctx, 4.0)
    f = dbg.fragments[0]
    assert f["discarded"]["source"] == "discard;"
    assert "discarded at line" in str(dbg)


def test_only_draws_inside_the_block_are_traced(ctx):
    draw(ctx, 0.0)
    with ctx.debug_pixel(5, 5, draw=1) as dbg:
        draw(ctx, 0.0)
        draw(ctx, 0.0)
    assert [d["draw"] for d in dbg.data["draws"]] == [1]
    draw(ctx, 0.0)  # after the block: no tracing, no error
    assert repr(dbg).startswith("<PixelDebug (5, 5)")


@pytest.mark.parametrize("bad", [-1, 1.5, True, "3"])
def test_bad_coordinates_are_errors(ctx, bad):
    with pytest.raises(ValueError):
        ctx.debug_pixel(bad, 0)
    with pytest.raises(ValueError):
        ctx.debug_pixel(0, 0, draw=bad)
