"""import shaderbox.pyopengl: PyOpenGL scripts on shaderbox's GL, in process.

Each script of crates/capi/tests/python/ runs in a subprocess that imports
shaderbox.pyopengl first (no environment variables). The scripts check
their own pixels and exit non-zero on a mismatch. When
SHADERBOX_OSMESA_DIR names a directory with crates/capi's libOSMesa.so
(CI builds it), the image must be byte-identical to the same script run
through PYOPENGL_PLATFORM=osmesa LD_LIBRARY_PATH=that directory.
"""

import os
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("OpenGL")

ROOT = Path(__file__).resolve().parents[3]
SCRIPTS = ROOT / "crates" / "capi" / "tests" / "python"
RUN_WITH_IMPORT = (
    "import runpy, sys\n"
    "import shaderbox.pyopengl\n"
    "sys.argv = sys.argv[1:]\n"
    "runpy.run_path(sys.argv[0], run_name='__main__')\n"
)


def clean_env():
    env = dict(os.environ)
    for k in ("PYOPENGL_PLATFORM", "LD_LIBRARY_PATH"):
        env.pop(k, None)
    return env


SCRIPT_NAMES = ["shaded_triangle.py", "fixed_function.py", "textured_fbo.py"]


def run_via_import(script, out):
    r = subprocess.run(
        [sys.executable, "-c", RUN_WITH_IMPORT, str(SCRIPTS / script), str(out)],
        env=clean_env(), capture_output=True, text=True, timeout=300,
    )
    assert r.returncode == 0, r.stdout + r.stderr
    return out.read_bytes()


@pytest.mark.parametrize("script", SCRIPT_NAMES)
def test_differential_script_via_import(script, tmp_path):
    # The script checks its own pixels (exit 1 on a mismatch).
    assert len(run_via_import(script, tmp_path / "import.bin")) > 0


@pytest.mark.parametrize("script", SCRIPT_NAMES)
def test_same_image_as_through_ld_library_path(script, tmp_path):
    libdir = os.environ.get("SHADERBOX_OSMESA_DIR")
    if not libdir:
        pytest.skip("SHADERBOX_OSMESA_DIR not set: no libOSMesa.so to compare with")
    assert (Path(libdir) / "libOSMesa.so").exists(), libdir
    via_import = run_via_import(script, tmp_path / "import.bin")
    ref = tmp_path / "ld.bin"
    env = dict(clean_env(), PYOPENGL_PLATFORM="osmesa", LD_LIBRARY_PATH=libdir)
    r = subprocess.run([sys.executable, str(SCRIPTS / script), str(ref)], env=env, capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    assert via_import == ref.read_bytes()


def test_renderer_is_shaderbox_and_context_helper():
    code = (
        "import shaderbox.pyopengl as sp\n"
        "from OpenGL import GL\n"
        "ctx, buf = sp.context(8, 4)\n"
        "GL.glClearColor(1.0, 0.0, 0.0, 1.0)\n"
        "GL.glClear(GL.GL_COLOR_BUFFER_BIT)\n"
        "GL.glFinish()\n"
        "print(GL.glGetString(GL.GL_RENDERER).decode())\n"
        "print(bytes(buf)[:4].hex(), len(bytes(buf)))\n"
    )
    r = subprocess.run([sys.executable, "-c", code], env=clean_env(), capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    renderer, px = r.stdout.splitlines()[-2:]
    assert "shaderbox" in renderer.lower()
    assert px == "ff0000ff 128"


def test_too_late_is_an_import_error():
    code = "import OpenGL.GL\nimport shaderbox.pyopengl\n"
    r = subprocess.run([sys.executable, "-c", code], env=clean_env(), capture_output=True, text=True, timeout=120)
    assert r.returncode != 0
    assert "import shaderbox.pyopengl before anything from OpenGL" in r.stderr
