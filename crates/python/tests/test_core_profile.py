"""OpenGL 3.3 core contexts from Python: `in`/`out` programs with explicit
attribute locations, instanced draws (``/i`` formats, ``gl_InstanceID``),
integer attributes, uniform blocks fed from buffers, unsigned uniforms,
and the errors of each."""

import numpy as np
import pytest

import shaderbox

W, H = 32, 24
BIG_TRIANGLE = np.array([[-1, -1], [3, -1], [-1, 3]], dtype=np.float32)

FLAT_VS = """#version 330 core
layout(location = 0) in vec2 pos;
void main() { gl_Position = vec4(pos, 0.0, 1.0); }
"""
FLAT_FS = """#version 330 core
uniform vec4 color;
out vec4 frag;
void main() { frag = color; }
"""


@pytest.fixture
def core():
    return shaderbox.Context(W, H, threads=1, version=(3, 3), profile="core")


def test_core_context_draws_a_330_program(core):
    assert core.version == (3, 3) and core.profile == "core"
    prog = core.program(vertex_shader=FLAT_VS, fragment_shader=FLAT_FS)
    assert prog.attributes["pos"].location == 0
    prog["color"] = (0.0, 1.0, 0.0, 1.0)
    vao = core.vertex_array(prog, [(core.buffer(BIG_TRIANGLE), "2f", "pos")])
    core.clear((1.0, 0.0, 0.0, 1.0))
    vao.render()
    assert (core.read() == [0, 255, 0, 255]).all()


def test_core_context_draws_a_triangle_where_it_should(core):
    prog = core.program(vertex_shader=FLAT_VS, fragment_shader=FLAT_FS)
    prog["color"] = (1.0, 1.0, 1.0, 1.0)
    # The left half of the window only.
    tri = np.array([[-1, -1], [0, -1], [0, 3], [-1, -1], [0, 3], [-1, 3]], dtype=np.float32)
    vao = core.vertex_array(prog, [(tri, "2f", "pos")])
    core.clear()
    vao.render()
    px = core.read()
    assert (px[:, : W // 2] == 255).all() and (px[:, W // 2 :, :3] == 0).all()


def test_core_context_refuses_fixed_function_state(core):
    for what in ("lights", "material", "fog", "modelview", "projection", "light_model_ambient"):
        with pytest.raises(RuntimeError, match="core profile"):
            getattr(core, what)
    with pytest.raises(RuntimeError, match="core profile"):
        core.modelview = np.identity(4)
    with pytest.raises(RuntimeError, match="core profile"):
        core.look_at((0, 0, 5))


def test_core_context_refuses_legacy_glsl(core):
    with pytest.raises(shaderbox.CompileError, match="did not compile") as e:
        core.program(vertex_shader="void main() { gl_Position = gl_Vertex; }")
    assert "#version 330 core" in e.value.info_log
    with pytest.raises(shaderbox.CompileError) as e:
        core.program(fragment_shader="#version 150 compatibility\nvoid main() { gl_FragColor = vec4(1.0); }")
    assert e.value.diagnostics.errors and e.value.diagnostics.errors[0].line == 1
    # A compatibility context accepts both.
    compat = shaderbox.Context(8, 8, threads=1, version=(3, 3), profile="compatibility")
    compat.program(fragment_shader="#version 150 compatibility\nvoid main() { gl_FragColor = vec4(1.0); }")


def test_core_context_refuses_draw_spheres(core):
    with pytest.raises(RuntimeError, match="profile='compatibility'"):
        core.draw_spheres([[0, 0, 0]])


def test_core_context_refuses_builtin_attributes_and_quads(core):
    prog = core.program(vertex_shader=FLAT_VS, fragment_shader=FLAT_FS)
    with pytest.raises(ValueError, match="compatibility profile"):
        core.vertex_array(prog, [(BIG_TRIANGLE, "2f", "gl_Vertex")])
    quad = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=np.float32)
    vao = core.vertex_array(prog, [(quad, "2f", "pos")])
    core.clear()
    with pytest.raises(shaderbox.GLError, match="GL_INVALID_ENUM"):
        vao.render("quads")


def test_compatibility_context_runs_330_programs_too():
    ctx = shaderbox.Context(W, H, threads=1, version=(3, 3), profile="compatibility")
    prog = ctx.program(vertex_shader=FLAT_VS, fragment_shader=FLAT_FS)
    prog["color"] = (0.0, 0.0, 1.0, 1.0)
    vao = ctx.vertex_array(prog, [(BIG_TRIANGLE, "2f", "pos")])
    ctx.clear()
    vao.render()
    assert (ctx.read() == [0, 0, 255, 255]).all()
    ctx.modelview = np.identity(4)  # the fixed-function state stays


# ---- instancing ----------------------------------------------------------------

QUAD = np.array([[0, 0], [1, 0], [1, 1], [0, 0], [1, 1], [0, 1]], dtype=np.float32)

INSTANCED_VS = """#version 330 core
layout(location = 0) in vec2 corner;
layout(location = 1) in vec2 offset;
layout(location = 2) in vec3 color;
out vec3 c;
uniform vec2 cell;
void main() {
    c = color;
    gl_Position = vec4(-1.0 + (offset + corner) * cell, 0.0, 1.0);
}
"""
COLOR_FS = """#version 330 core
in vec3 c;
out vec4 frag;
void main() { frag = vec4(c, 1.0); }
"""


def test_parse_format_rates():
    assert [f.divisor for f in shaderbox.parse_format("3f 4f/i")] == [1, 1]
    assert [f.divisor for f in shaderbox.parse_format("2f/v")] == [0]
    assert shaderbox.parse_format("2f /r")[0].divisor > 1
    with pytest.raises(ValueError, match="not a rate"):
        shaderbox.parse_format("2f/x")
    with pytest.raises(ValueError, match="no fields"):
        shaderbox.parse_format("/i")


def test_per_instance_attributes_place_and_colour_quads(core):
    prog = core.program(vertex_shader=INSTANCED_VS, fragment_shader=COLOR_FS)
    # A 4 x 3 grid of cells, 8 x 8 pixels each; one quad per cell.
    prog["cell"] = (2 / 4, 2 / 3)
    offsets = np.array([[x, y] for y in range(3) for x in range(4)], dtype=np.float32)
    colors = np.array([[x / 3, y / 2, 1.0] for y in range(3) for x in range(4)], dtype=np.float32)
    inst = np.hstack([offsets, colors]).astype(np.float32)
    vao = core.vertex_array(prog, [(QUAD, "2f", "corner"), (inst, "2f 3f/i", "offset", "color")])
    assert vao.vertices == 6 and vao.instances == 12
    core.clear()
    vao.render(instances=12)
    px = core.read()[::-1]  # bottom row first, as the grid counts
    for y in range(3):
        for x in range(4):
            want = np.round(np.array([x / 3, y / 2, 1.0]) * 255)
            got = px[y * 8 + 4, x * 8 + 4, :3].astype(float)
            assert np.abs(got - want).max() <= 1, (x, y, got, want)
    # One instance: only the first cell.
    core.clear()
    vao.render(instances=1)
    px = core.read()[::-1]
    assert px[4, 4, 2] == 255 and (px[4, 12, :3] == 0).all()


def test_instances_beyond_the_buffers_are_refused(core):
    prog = core.program(vertex_shader=INSTANCED_VS, fragment_shader=COLOR_FS)
    inst = np.zeros((2, 5), dtype=np.float32)
    vao = core.vertex_array(prog, [(QUAD, "2f", "corner"), (inst, "2f 3f/i", "offset", "color")])
    core.clear()
    with pytest.raises(ValueError, match="hold 2"):
        vao.render(instances=3)
    with pytest.raises(ValueError, match=">= 0"):
        vao.render(instances=-1)
    with pytest.raises(TypeError):
        vao.render(instances=1.5)


def test_gl_instance_id_and_vertex_id_without_vertex_buffers(core):
    vs = """#version 330 core
    out vec3 c;
    void main() {
        // Quad corners from gl_VertexID, one column of the window per instance.
        vec2 corner = vec2(float(gl_VertexID == 1 || gl_VertexID == 2 || gl_VertexID == 4),
                           float(gl_VertexID == 2 || gl_VertexID == 4 || gl_VertexID == 5));
        c = vec3(float(gl_InstanceID) / 3.0, 0.0, 1.0);
        gl_Position = vec4(-1.0 + vec2((float(gl_InstanceID) + corner.x) * 0.5, corner.y * 2.0), 0.0, 1.0);
    }
    """
    prog = core.program(vertex_shader=vs, fragment_shader=COLOR_FS)
    vao = core.vertex_array(prog, [])
    assert vao.vertices is None
    with pytest.raises(ValueError, match="render\\(vertices="):
        vao.render()
    core.clear()
    vao.render(vertices=6, instances=4)
    row = core.read()[H // 2]
    for i in range(4):
        assert abs(int(row[i * 8 + 4, 0]) - round(i / 3 * 255)) <= 1 and row[i * 8 + 4, 2] == 255


def test_instanced_indexed_draw(core):
    prog = core.program(vertex_shader=INSTANCED_VS, fragment_shader=COLOR_FS)
    prog["cell"] = (1.0, 2.0)
    corners = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=np.float32)
    inst = np.array([[0, 0, 1, 0, 0], [1, 0, 0, 1, 0]], dtype=np.float32)
    vao = core.vertex_array(
        prog, [(corners, "2f", "corner"), (inst, "2f 3f/i", "offset", "color")], index_buffer=[0, 1, 2, 0, 2, 3]
    )
    core.clear()
    vao.render(instances=2)
    px = core.read()
    assert px[H // 2, W // 4].tolist() == [255, 0, 0, 255] and px[H // 2, 3 * W // 4].tolist() == [0, 255, 0, 255]


def test_per_render_attribute_is_the_same_for_every_instance(core):
    prog = core.program(vertex_shader=INSTANCED_VS, fragment_shader=COLOR_FS)
    prog["cell"] = (0.5, 2.0)
    offsets = np.array([[0, 0], [1, 0], [2, 0], [3, 0]], dtype=np.float32)
    color = np.array([[0, 1, 1]], dtype=np.float32)
    vao = core.vertex_array(
        prog, [(QUAD, "2f", "corner"), (offsets, "2f/i", "offset"), (color, "3f/r", "color")]
    )
    assert vao.instances == 4
    core.clear()
    vao.render(instances=4)
    assert (core.read()[:, :, :3] == [0, 255, 255]).all()


# ---- integer attributes --------------------------------------------------------

# The comparison happens in the vertex shader: the attribute arrives
# exactly there (integer varyings travel as floats, see exec's crate docs).
INT_VS = """#version 330 core
layout(location = 0) in vec2 pos;
layout(location = 1) in {ty} value;
uniform {ty} expected;
out vec4 c;
void main() {{
    c = value == expected ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0);
    gl_Position = vec4(pos, 0.0, 1.0);
}}
"""
INT_FS = """#version 330 core
in vec4 c;
out vec4 frag;
void main() { frag = c; }
"""


@pytest.mark.parametrize(
    "ty, fmt, value",
    [
        ("int", "i", 16777217),  # 2^24 + 1: a float would round it
        ("int", "i", -2147483647),
        ("uint", "u", 4294967295),
        ("uint", "u", 16777219),
        ("ivec2", "2i", (33554433, -33554433)),
        ("uvec3", "3u", (4000000001, 16777217, 7)),
        ("ivec4", "4i2", (-32768, 32767, 1, -1)),
        ("uvec2", "2u1", (255, 3)),
    ],
)
def test_integer_attributes_reach_the_shader_exactly(core, ty, fmt, value):
    prog = core.program(vertex_shader=INT_VS.format(ty=ty), fragment_shader=INT_FS)
    assert prog.attributes["value"].integer
    dtype = shaderbox._context._NUMPY_OF[(shaderbox.parse_format(fmt)[0].gl_type, shaderbox.parse_format(fmt)[0].size)]
    data = np.array([value] * 3, dtype=dtype).reshape(3, -1)
    prog["expected"] = value
    assert np.array_equal(np.asarray(prog["expected"]).reshape(-1), np.asarray(value).reshape(-1))
    vao = core.vertex_array(prog, [(BIG_TRIANGLE, "2f", "pos"), (data, fmt, "value")])
    core.clear()
    vao.render()
    assert (core.read() == [0, 255, 0, 255]).all()


def test_integer_attribute_per_instance(core):
    vs = """#version 330 core
    layout(location = 0) in vec2 corner;
    layout(location = 1) in uint id;
    out vec4 c;
    void main() {
        c = vec4(float(id & 255u) / 255.0, float(id >> 24u) / 255.0, 0.0, 1.0);
        gl_Position = vec4(-1.0 + vec2(float(gl_InstanceID) + corner.x, corner.y * 2.0), 0.0, 1.0);
    }
    """
    prog = core.program(vertex_shader=vs, fragment_shader=INT_FS)
    ids = np.array([0x11000022, 0xFF000001], dtype=np.uint32)
    vao = core.vertex_array(prog, [(QUAD, "2f", "corner"), (ids, "u/i", "id")])
    core.clear()
    vao.render(instances=2)
    px = core.read()
    assert px[H // 2, W // 4, :2].tolist() == [0x22, 0x11] and px[H // 2, 3 * W // 4, :2].tolist() == [1, 255]


def test_integer_attributes_refuse_float_and_normalized_formats(core):
    prog = core.program(vertex_shader=INT_VS.format(ty="int"), fragment_shader=INT_FS)
    with pytest.raises(TypeError, match="integer attribute"):
        core.vertex_array(prog, [(BIG_TRIANGLE, "2f", "pos"), (np.zeros(3, np.float32), "f", "value")])
    with pytest.raises(TypeError, match="integer attribute"):
        core.vertex_array(prog, [(BIG_TRIANGLE, "2f", "pos"), (np.zeros(3, np.int32), "in", "value")])


def test_float_attribute_from_integer_data_is_converted(core):
    vs = """#version 330 core
    layout(location = 0) in vec2 pos;
    layout(location = 1) in float value;
    out float v;
    void main() { v = value; gl_Position = vec4(pos, 0.0, 1.0); }
    """
    fs = """#version 330 core
    in float v;
    out vec4 frag;
    void main() { frag = vec4(v / 255.0, 0.0, 0.0, 1.0); }
    """
    prog = core.program(vertex_shader=vs, fragment_shader=fs)
    assert not prog.attributes["value"].integer
    vao = core.vertex_array(prog, [(BIG_TRIANGLE, "2f", "pos"), (np.full(3, 128, np.int32), "i", "value")])
    core.clear()
    vao.render()
    assert core.read()[0, 0].tolist() == [128, 0, 0, 255]


# ---- uniform blocks ------------------------------------------------------------

UBO_VS = """#version 330 core
layout(location = 0) in vec2 corner;
layout(std140) uniform Grid {
    vec4 offsets[4];
    vec4 colors[4];
    mat2 scale;
    float alpha;
    uint mask;
};
out vec4 c;
void main() {
    c = vec4(colors[gl_InstanceID].rgb, alpha);
    if ((mask & (1u << uint(gl_InstanceID))) == 0u) c = vec4(0.0);
    gl_Position = vec4(-1.0 + scale * (corner + offsets[gl_InstanceID].xy), 0.0, 1.0);
}
"""
UBO_FS = """#version 330 core
in vec4 c;
out vec4 frag;
void main() { frag = c; }
"""


def test_uniform_block_info_is_the_std140_layout(core):
    prog = core.program(vertex_shader=UBO_VS, fragment_shader=UBO_FS)
    block = prog["Grid"]
    assert block is prog.uniform_blocks["Grid"] and "Grid" in prog
    assert isinstance(block, shaderbox.UniformBlock)
    m = block.members
    assert (m["offsets"].offset, m["offsets"].array_stride, m["offsets"].array_length) == (0, 16, 4)
    assert (m["colors"].offset, m["colors"].array_stride) == (64, 16)
    assert (m["scale"].offset, m["scale"].matrix_stride, m["scale"].type) == (128, 16, "mat2")
    assert (m["alpha"].offset, m["mask"].offset, m["mask"].type) == (160, 164, "uint")
    assert block.size == 176
    # Matrices are given as m[row, col] and stored column by column.
    data = np.frombuffer(block.pack({"scale": [[1, 2], [3, 4]], "mask": 7, "alpha": 0.5}), dtype="<f4")
    assert data[32:34].tolist() == [1, 3] and data[36:38].tolist() == [2, 4] and data[40] == 0.5
    assert np.frombuffer(data[41:42].tobytes(), dtype="<u4")[0] == 7
    assert block.binding == 0
    block.binding = 3
    assert block.binding == 3
    assert "offsets" not in prog.uniforms


def test_row_major_block_matrices(core):
    vs = """#version 330 core
    layout(location = 0) in vec2 pos;
    layout(std140, row_major) uniform M { mat2x3 m; };
    out vec4 c;
    void main() {
        // m[col][row]: column 1 is (2, 4, 6) for the rows below.
        c = m[1] == vec3(2.0, 4.0, 6.0) && m[0][2] == 5.0 ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0);
        gl_Position = vec4(pos, 0.0, 1.0);
    }
    """
    prog = core.program(vertex_shader=vs, fragment_shader="#version 330 core\nin vec4 c; out vec4 f; void main() { f = c; }")
    block = prog["M"]
    m = block.members["m"]
    assert m.row_major and m.type == "mat2x3" and m.matrix_stride == 16
    rows = [[1, 2], [3, 4], [5, 6]]
    data = np.frombuffer(block.pack({"m": rows}), dtype="<f4")
    assert data[0:2].tolist() == [1, 2] and data[4:6].tolist() == [3, 4] and data[8:10].tolist() == [5, 6]
    core.buffer(data).bind_to_uniform_block(0)
    vao = core.vertex_array(prog, [(BIG_TRIANGLE, "2f", "pos")])
    core.clear()
    vao.render()
    assert core.read()[0, 0].tolist() == [0, 255, 0, 255]


def test_instanced_quads_from_a_uniform_block(core):
    prog = core.program(vertex_shader=UBO_VS, fragment_shader=UBO_FS)
    block = prog["Grid"]
    block.binding = 2
    offsets = [(0, 0, 0, 0), (1, 0, 0, 0), (0, 1, 0, 0), (1, 1, 0, 0)]
    colors = [(1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (1, 1, 1, 0)]
    data = block.pack({"offsets": offsets, "colors": colors, "scale": np.identity(2), "alpha": 1.0, "mask": 0b1011})
    assert len(data) == block.size
    ubo = core.buffer(data)
    ubo.bind_to_uniform_block(2)
    vao = core.vertex_array(prog, [(QUAD, "2f", "corner")])
    core.clear()
    vao.render(instances=4)
    px = core.read()
    q = lambda x, y: px[H - 1 - (y * H // 2 + H // 4), x * W // 2 + W // 4].tolist()  # noqa: E731
    assert q(0, 0) == [255, 0, 0, 255] and q(1, 0) == [0, 255, 0, 255]
    assert q(0, 1) == [0, 0, 0, 0]  # instance 2 masked off
    assert q(1, 1) == [255, 255, 255, 255]
    # New data through Buffer.write: the next draw reads it.
    ubo.write(block.pack({"mask": 0b0100}, into=data))
    core.clear()
    vao.render(instances=4)
    px = core.read()
    assert q(0, 1) == [0, 0, 255, 255] and q(0, 0) == [0, 0, 0, 0]


def test_uniform_block_from_a_buffer_range(core):
    fs = """#version 330 core
    layout(std140) uniform Tint { vec4 tint; } t;
    out vec4 frag;
    void main() { frag = t.tint; }
    """
    prog = core.program(vertex_shader=FLAT_VS, fragment_shader=fs)
    block = prog["Tint"]
    assert list(block.members) == ["Tint.tint"]
    align = core._raw.get_integerv(shaderbox._gl.UNIFORM_BUFFER_OFFSET_ALIGNMENT)[0]
    data = bytearray(align + 16)
    data[:16] = block.pack({"tint": (1, 0, 0, 1)})
    data[align:] = block.pack({"Tint.tint": (0, 0, 1, 1)})
    ubo = core.buffer(bytes(data))
    vao = core.vertex_array(prog, [(BIG_TRIANGLE, "2f", "pos")])
    ubo.bind_to_uniform_block(0, offset=align, size=16)
    core.clear()
    vao.render()
    assert core.read()[0, 0].tolist() == [0, 0, 255, 255]
    ubo.bind_to_uniform_block(0, offset=0, size=16)
    vao.render()
    assert core.read()[0, 0].tolist() == [255, 0, 0, 255]
    with pytest.raises(ValueError, match="multiple of"):
        ubo.bind_to_uniform_block(0, offset=4, size=16)
    with pytest.raises(ValueError, match="past the buffer"):
        ubo.bind_to_uniform_block(0, offset=align, size=32)


def test_uniform_block_errors(core):
    prog = core.program(vertex_shader=UBO_VS, fragment_shader=UBO_FS)
    with pytest.raises(TypeError, match="bind_to_uniform_block"):
        prog["alpha"] = 0.5
    with pytest.raises(TypeError, match="uniform block 'Grid'"):
        prog["offsets[1]"] = (1, 2, 3, 4)
    with pytest.raises(TypeError, match="buffer"):
        prog["alpha"]
    with pytest.raises(TypeError, match=r"\.binding"):
        prog["Grid"] = 1
    block = prog["Grid"]
    with pytest.raises(ValueError, match="binding points are 0-"):
        block.binding = 1000
    with pytest.raises(KeyError, match="no active member"):
        block.pack({"nope": 1})
    with pytest.raises(TypeError, match="integers"):
        block.pack({"mask": 1.5})
    with pytest.raises(ValueError, match="0 to 2\\*\\*32-1"):
        block.pack({"mask": -1})
    with pytest.raises(ValueError, match="expected shape"):
        block.pack({"scale": (1, 2, 3)})
    ubo = core.buffer(reserve=16)
    with pytest.raises(ValueError, match="binding points are 0-"):
        ubo.bind_to_uniform_block(-1)
    with pytest.raises(ValueError, match="past the buffer"):
        ubo.write(b"\0" * 17)


def test_uniform_buffers_need_a_3x_context():
    ctx = shaderbox.Context(8, 8, threads=1)
    with pytest.raises(RuntimeError, match="OpenGL 3.1"):
        ctx.buffer(reserve=16).bind_to_uniform_block(0)


def test_buffer_write_and_read(core):
    buf = core.buffer(reserve=12)
    assert buf.read() == bytes(12)
    buf.write(np.array([1, 2], dtype=np.uint32), offset=4)
    assert np.frombuffer(buf.read(), dtype="<u4").tolist() == [0, 1, 2]
    assert buf.read(4, offset=8) == (2).to_bytes(4, "little")
    with pytest.raises(ValueError, match="reserve"):
        core.buffer()


# ---- unsigned uniforms ---------------------------------------------------------


def test_unsigned_uniforms(core):
    fs = """#version 330 core
    uniform uint u;
    uniform uvec2 uu[2];
    out vec4 frag;
    void main() {
        bool ok = u == 4000000000u && uu[1] == uvec2(3u, 16777217u);
        frag = ok ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0);
    }
    """
    prog = core.program(vertex_shader=FLAT_VS, fragment_shader=fs)
    assert prog.uniforms["u"].kind == "uint" and prog.uniforms["uu"].type == "uvec2"
    prog["u"] = 4000000000
    prog["uu"] = [(1, 2), (3, 16777217)]
    assert prog["u"] == 4000000000
    assert prog["uu"].tolist() == [[1, 2], [3, 16777217]] and prog["uu"].dtype == np.uint32
    vao = core.vertex_array(prog, [(BIG_TRIANGLE, "2f", "pos")])
    core.clear()
    vao.render()
    assert core.read()[0, 0].tolist() == [0, 255, 0, 255]
    with pytest.raises(ValueError, match="0 to 2\\*\\*32-1"):
        prog["u"] = -1
    with pytest.raises(TypeError, match="integers"):
        prog["u"] = 1.5


POINT_VS = """#version 330 core
layout(location = 0) in vec2 pos;
void main() { gl_Position = vec4(pos, 0.0, 1.0); }
"""
# Each point becomes a square half the window wide around it.
SQUARE_GS = """#version 330 core
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
void main() {
    for (int i = 0; i < 4; i++) {
        gl_Position = gl_in[0].gl_Position + vec4(vec2(i % 2, i / 2) - 0.5, 0.0, 0.0);
        EmitVertex();
    }
}
"""


def test_core_context_runs_a_geometry_shader(core):
    prog = core.program(vertex_shader=POINT_VS, geometry_shader=SQUARE_GS, fragment_shader=FLAT_FS)
    prog["color"] = (1.0, 1.0, 1.0, 1.0)
    vao = core.vertex_array(prog, [(np.array([[0.0, 0.0]], dtype=np.float32), "2f", "pos")])
    core.clear()
    vao.render("points")
    lit = (core.read()[:, :, 0] == 255).sum()
    assert lit == (W // 2) * (H // 2)


def test_geometry_shader_errors_name_the_stage(core):
    with pytest.raises(shaderbox.CompileError, match="geometry_shader"):
        core.program(vertex_shader=POINT_VS, geometry_shader="#version 330 core\nvoid main() { EmitVertex() }", fragment_shader=FLAT_FS)
    # A geometry shader without its output layout does not link.
    no_layout = "#version 330 core\nlayout(points) in;\nvoid main() { EmitVertex(); }"
    with pytest.raises(shaderbox.LinkError):
        core.program(vertex_shader=POINT_VS, geometry_shader=no_layout, fragment_shader=FLAT_FS)
