"""The example notebooks: committed without outputs, and they run.

Executed with nbclient on the ipykernel of this Python (the same
environment the package is installed in).
"""

import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
NOTEBOOKS = sorted((ROOT / "examples").glob("*.ipynb"))


def test_there_are_notebooks():
    assert NOTEBOOKS, "examples/*.ipynb"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_outputs_are_stripped(path):
    nb = json.loads(path.read_text())
    for cell in nb["cells"]:
        if cell["cell_type"] == "code":
            assert cell.get("outputs") == [] and cell.get("execution_count") is None, (path.name, cell.get("id"))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_runs(path, tmp_path):
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    nb = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}})
    client.execute()  # raises CellExecutionError on any error
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    pngs = [o for o in outputs if "image/png" in o.get("data", {})]
    if path.name == "shaderbox.ipynb":
        # The diagnostic was shown, then pictures.
        text = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
        assert "normalise" in text and "error" in text
        assert len(pngs) >= 3
        # The OpenGL 3.3 core section: its context, its uniform block's
        # std140 layout, one instanced draw of the grid, and its pictures.
        assert "(3, 3) core" in text and "view       mat4  offset  64" in text
        assert "81 instances" in text
        core_cells = [c for c in nb.cells if c.cell_type == "code" and "instances=k * k" in c.source]
        core_pngs = [o for c in core_cells for o in c.outputs if "image/png" in o.get("data", {})]
        assert len(core_pngs) == 2
        image = pytest.importorskip("PIL.Image")
        import base64
        import io

        import numpy as np

        for o in core_pngs:
            px = np.asarray(image.open(io.BytesIO(base64.b64decode(o["data"]["image/png"]))).convert("RGB"))
            background = (px == px[0, 0]).all(axis=2)
            # Spheres cover much of the picture.
            assert 0.2 < 1 - background.mean() < 0.9
