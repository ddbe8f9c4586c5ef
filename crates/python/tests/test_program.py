"""Programs: compile and link errors, the interface, uniforms."""

import numpy as np
import pytest

import shaderbox
from conftest import FS, VS


def test_compile_error_carries_diagnostics(ctx):
    bad = "void main() {\n    gl_FragColor = vec4(1.0) * intensty;\n}\n"
    with pytest.raises(shaderbox.CompileError) as info:
        ctx.program(vertex_shader=VS, fragment_shader=bad)
    e = info.value
    assert len(e.diagnostics.errors) >= 1
    d = e.diagnostics.errors[0]
    assert (d.stage, d.severity, d.line) == ("fragment", "error", 2)
    assert d.column == 32
    assert "intensty" in d.message and d.code.startswith("E")
    # The rendered text names the shader and shows the line.
    assert "fragment_shader" in e.text and "gl_FragColor = vec4(1.0) * intensty;" in e.text
    assert e.info_log.startswith("0:2(32): error:")
    assert "fragment shader did not compile" in str(e)
    assert isinstance(e, shaderbox.Error)


def test_errors_in_both_stages_are_reported_together(ctx):
    with pytest.raises(shaderbox.CompileError) as info:
        ctx.program(vertex_shader="void main() { gl_Position = nope; }", fragment_shader="void main() { x; }")
    stages = {d.stage for d in info.value.diagnostics.errors}
    assert stages == {"vertex", "fragment"}
    assert "the vertex and fragment shaders did not compile: vertex shader, 0:1(29): error: `nope' undeclared" in str(info.value)


def test_link_error(ctx):
    fs = "varying vec3 never_written;\nvoid main() { gl_FragColor = vec4(never_written, 1.0); }"
    with pytest.raises(shaderbox.LinkError) as info:
        ctx.program(vertex_shader=VS, fragment_shader=fs)
    e = info.value
    assert any("never_written" in d.message for d in e.diagnostics)
    assert e.info_log and "never_written" in e.text
    assert not isinstance(e, shaderbox.CompileError)


def test_link_error_undefined_function(ctx):
    fs = "vec4 shade();\nvoid main() { gl_FragColor = shade(); }"
    with pytest.raises(shaderbox.LinkError, match="shade"):
        ctx.program(fragment_shader=fs)


def test_program_arguments(ctx):
    with pytest.raises(ValueError, match="needs a vertex_shader"):
        ctx.program()
    with pytest.raises(TypeError, match="GLSL source text"):
        ctx.program(fragment_shader=b"void main() {}")


def test_warnings_are_kept(ctx):
    prog = ctx.program(fragment_shader="#version 120\n#extension GL_ARB_texture_rectangle : warn\nvoid main() { gl_FragColor = vec4(1.0); }")
    assert prog.warnings.ok
    assert all(d.severity != "error" for d in prog.warnings)


INTERFACE_VS = """
attribute vec3 position;
attribute vec4 weights;
uniform mat4 transform;
uniform float scales[3];
void main() { gl_Position = transform * vec4(position * scales[0] * weights.x, 1.0) + gl_Color; }
"""
INTERFACE_FS = """
#version 120
uniform vec3 tint;
uniform int mode;
uniform bool flag;
uniform bvec2 flags2;
uniform ivec3 counts;
uniform mat2 m2;
uniform mat3 m3;
uniform mat2x3 m23;
uniform mat4x2 m42;
uniform vec2 offsets[4];
uniform sampler2D tex;
struct S { float a; vec2 b; };
uniform S s;
void main() {
    vec4 c = texture2D(tex, vec2(0.5)) + vec4(tint, float(mode) + float(flag) + float(flags2.x));
    c.xy += offsets[3] + m2[0] + (m3 * vec3(1.0)).xy + (m23 * vec2(1.0)).xy + (m42 * vec4(1.0));
    c.x += float(counts.z) + s.a + s.b.y;
    gl_FragColor = c;
}
"""


@pytest.fixture
def iprog(ctx):
    return ctx.program(vertex_shader=INTERFACE_VS, fragment_shader=INTERFACE_FS)


def test_interface(iprog):
    u = iprog.uniforms
    assert u["tint"].type == "vec3" and u["tint"].shape == (3,) and u["tint"].array_length is None
    assert u["scales"].type == "float" and u["scales"].array_length == 3 and u["scales"].shape == (3,)
    assert u["offsets"].shape == (4, 2)
    assert u["transform"].shape == (4, 4)
    assert u["m23"].type == "mat2x3" and u["m23"].shape == (3, 2)
    assert u["tex"].type == "sampler2D" and u["tex"].kind == "sampler"
    assert "s.a" in u and u["s.b"].type == "vec2"
    a = iprog.attributes
    assert a["position"].type == "vec3" and a["position"].location >= 0 and not a["position"].builtin
    assert a["weights"].type == "vec4"
    assert a["gl_Color"].builtin and a["gl_Color"].location == -1
    assert "tint" in iprog and "nope" not in iprog


def test_uniforms_of_every_kind_round_trip(iprog):
    iprog["tint"] = (0.25, 0.5, 0.75)
    assert np.allclose(iprog["tint"], [0.25, 0.5, 0.75])
    iprog["tint"] = np.array([1, 2, 3])  # integers convert to float
    assert np.allclose(iprog["tint"], [1, 2, 3])
    iprog["mode"] = 7
    assert iprog["mode"] == 7
    iprog["flag"] = True
    assert iprog["flag"] is True
    iprog["flags2"] = (True, False)
    assert iprog["flags2"].tolist() == [True, False]
    iprog["counts"] = np.array([1, -2, 3], dtype=np.int64)
    assert iprog["counts"].tolist() == [1, -2, 3]
    m = np.arange(16, dtype=np.float32).reshape(4, 4)
    iprog["transform"] = m
    assert np.array_equal(iprog["transform"], m)
    iprog["transform"] = m.reshape(-1)  # flat: row by row
    assert np.array_equal(iprog["transform"], m)
    m23 = np.array([[1, 2], [3, 4], [5, 6]], dtype=np.float32)  # 3 rows, 2 columns
    iprog["m23"] = m23
    assert np.array_equal(iprog["m23"], m23)
    m42 = np.arange(8, dtype=np.float32).reshape(2, 4)
    iprog["m42"] = m42
    assert np.array_equal(iprog["m42"], m42)
    iprog["m2"] = [[1, 2], [3, 4]]
    assert np.array_equal(iprog["m2"], [[1, 2], [3, 4]])
    iprog["scales"] = [1.0, 2.0, 3.0]
    assert np.array_equal(iprog["scales"], [1, 2, 3])
    iprog["scales[1]"] = 9.0
    assert iprog["scales[1]"] == 9.0
    assert np.array_equal(iprog["scales"], [1, 9, 3])
    iprog["offsets"] = np.ones((4, 2))
    iprog["offsets"] = [[5, 6], [7, 8]]  # the first two elements
    assert np.array_equal(iprog["offsets"], [[5, 6], [7, 8], [1, 1], [1, 1]])
    iprog["s.a"] = 0.5
    iprog["s.b"] = (1, 2)
    assert iprog["s.a"] == 0.5 and iprog["s.b"].tolist() == [1, 2]
    iprog["tex"] = 3
    assert iprog["tex"] == 3


def test_unknown_uniform_is_a_key_error(iprog):
    with pytest.raises(KeyError, match="no active uniform 'tnit'.*tint"):
        iprog["tnit"] = 1.0
    with pytest.raises(KeyError, match="index 3 is out of range"):
        iprog["scales[3]"] = 1.0
    with pytest.raises(KeyError):
        iprog["nope"]
    with pytest.raises(TypeError, match="strings"):
        iprog[3] = 1.0


@pytest.mark.parametrize(
    "name,value,match",
    [
        ("tint", (1.0, 2.0), r"vec3: expected shape \(3,\) \(or 3 values\), got shape \(2,\)"),
        ("tint", 1.0, r"expected shape \(3,\)"),
        ("transform", np.identity(3), r"mat4: expected shape \(4, 4\)"),
        ("mode", (1, 2), "a single number"),
        ("scales", [1, 2, 3, 4], r"float\[3\]: expected shape \(3,\)"),
        ("offsets", np.ones((4, 3)), r"vec2\[4\]"),
        ("tint", (np.inf, 0, 0), "finite"),
        ("tex", 99, "texture units are 0-"),
        ("mode", 2**40, "32 bits"),
        ("tint", [[1, 2], [3]], "not an array of numbers"),
    ],
)
def test_bad_uniform_values_are_value_errors(iprog, name, value, match):
    with pytest.raises(ValueError, match=match):
        iprog[name] = value


@pytest.mark.parametrize(
    "name,value,match",
    [
        ("mode", 1.5, "int.* takes integers, got float64"),
        ("counts", np.array([1.0, 2.0, 3.0], dtype=np.float32), "takes integers, got float32"),
        ("tex", 0.0, "texture unit"),
        ("tint", "red", "vec3"),
        ("tint", np.array([1j, 2, 3]), "real numbers, got dtype complex128"),
        ("tint", np.array(["a", "b", "c"]), "real numbers"),
    ],
)
def test_wrong_uniform_dtypes_are_type_errors(iprog, name, value, match):
    with pytest.raises(TypeError, match=match):
        iprog[name] = value


def test_uniform_drives_the_picture(ctx):
    from conftest import BIG_TRIANGLE

    prog = ctx.program(vertex_shader=VS, fragment_shader=FS)
    vao = ctx.vertex_array(prog, [(BIG_TRIANGLE, "2f", "pos")])
    ctx.clear()
    prog["color"] = (0.0, 1.0, 0.0, 1.0)
    vao.render()
    assert (ctx.read() == [0, 255, 0, 255]).all()
    prog["color"] = np.array([1.0, 0.0, 0.0, 1.0])
    vao.render()
    assert (ctx.read() == [255, 0, 0, 255]).all()
