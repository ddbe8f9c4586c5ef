"""shaderbox.check: diagnostics without a context."""

from pathlib import Path

import pytest

import shaderbox

ROOT = Path(__file__).resolve().parents[3]


def test_clean_shader():
    d = shaderbox.check("void main() { gl_FragColor = vec4(1.0); }", stage="fragment")
    assert d.ok and list(d) == [] and d.text == ""


def test_error_is_located():
    d = shaderbox.check("void main() {\n  gl_Position = vec4(1.0) + vec3(1.0);\n}\n", stage="vertex")
    assert not d.ok
    e = d.errors[0]
    assert (e.stage, e.line, e.severity) == ("vertex", 2, "error")
    assert e.column is not None and e.code.startswith("E")
    assert "vec4" in e.message and "vec3" in e.message
    assert "gl_Position = vec4(1.0) + vec3(1.0);" in d.text
    assert d.info_log.startswith("0:2(")
    assert str(e).startswith("0:2(")
    assert str(d) == d.text


def test_version_default():
    src = "void main() { float a[2] = float[2](1.0, 2.0); gl_FragColor = vec4(a[1]); }"
    assert not shaderbox.check(src, stage="fragment").ok
    assert shaderbox.check(src, stage="fragment", version=120).ok
    # A #version line wins over the default.
    assert not shaderbox.check("#version 110\n" + src, stage="fragment", version=120).ok


def test_paths_and_stage_from_extension():
    d = shaderbox.check(ROOT / "shaders" / "sphere.frag")
    assert d.ok, d.text
    mistakes = shaderbox.check(ROOT / "examples" / "shaders" / "mistakes.frag")
    assert not mistakes.ok and len(mistakes.errors) >= 2
    assert "mistakes.frag" in mistakes.text


def test_compute_shaders():
    # The compiler has the compute stage's language (GL_ARB_compute_shader).
    src = """#version 330
#extension GL_ARB_compute_shader : enable
layout(local_size_x = 4) in;
shared uint total;
void main() { atomicAdd(total, gl_LocalInvocationIndex); barrier(); }
"""
    assert shaderbox.check(src, stage="compute").ok
    bad = shaderbox.check(src.replace("layout(local_size_x = 4) in;", "out int o;"), stage="compute")
    assert not bad.ok
    assert "no user-defined inputs or outputs" in bad.errors[0].message


def test_tessellation_stages():
    ext = "#version 150\n#extension GL_ARB_tessellation_shader : require\n"
    ok = shaderbox.check(ext + "layout(vertices = 3) out;\nvoid main() { gl_out[gl_InvocationID].gl_Position = vec4(0.0); }\n", stage="tess_control")
    assert ok.ok, ok
    bad = shaderbox.check(ext + "layout(vertices = 3) out;\nvoid main() { gl_out[0].gl_Position = vec4(0.0); }\n", stage="tess_control")
    assert not bad.ok
    assert "gl_InvocationID" in bad.errors[0].message
    assert bad.errors[0].stage == "tessellation control"
    assert shaderbox.check(ext + "layout(quads) in;\nvoid main() { gl_Position = vec4(gl_TessCoord, 1.0); }\n", stage="tese").ok


def test_bad_arguments():
    with pytest.raises(ValueError, match="needs stage"):
        shaderbox.check("void main() {}")
    with pytest.raises(ValueError, match="stage .tessellation. is not 'vertex', 'tess_control', 'tess_evaluation', 'geometry', 'fragment' or 'compute'"):
        shaderbox.check("void main() {}", stage="tessellation")
    with pytest.raises(ValueError, match="version 135 is not a GLSL version"):
        shaderbox.check("void main() {}", stage="vertex", version=135)
    with pytest.raises(TypeError, match="GLSL text"):
        shaderbox.check(42, stage="vertex")
    with pytest.raises(ValueError, match="cannot tell the stage"):
        shaderbox.check(ROOT / "README.md")


def test_hostile_input_does_not_crash():
    # Deep nesting, a runaway macro and garbage bytes: diagnostics, never a crash.
    for src in ["(" * 10000, "#define A A A\nA", "\x00\xff\ufffd void main(", "#if\n#endif"]:
        d = shaderbox.check(src, stage="fragment")
        assert not d.ok
