"""shaderbox.render_molecule: the CLI's render from Python."""

import numpy as np
import pytest

import shaderbox


def test_default_molecule():
    img = shaderbox.render_molecule(size=(48, 40))
    assert (img.width, img.height) == (48, 40) and not img.has_alpha
    a = np.asarray(img)
    assert a[0, 0].tolist() == [0, 0, 0, 255]
    assert (a[:, :, :3].sum(axis=2) > 0).mean() > 0.2  # crambin fills a good part of the frame
    # Deterministic.
    assert shaderbox.render_molecule(size="48x40") == img


def test_options_change_the_picture():
    base = shaderbox.render_molecule(size=(64, 64))
    for kw in [
        dict(projection="perspective"),
        dict(fog="exp2"),
        dict(lights="none"),
        dict(lights=[0]),
        dict(rotate=(90, 0, 0)),
        dict(supersample=2),
        dict(background="#336699"),
        dict(background=(1.0, 1.0, 1.0)),
        dict(effect="outline"),
        dict(style="ballstick"),
    ]:
        assert shaderbox.render_molecule(size=(64, 64), **kw) != base, kw
    # The geometry-shader path draws the same image.
    assert shaderbox.render_molecule(size=(64, 64), atoms="points") == base
    t = shaderbox.render_molecule(size=(32, 32), background="transparent")
    assert t.has_alpha and np.asarray(t)[0, 0, 3] == 0
    assert np.asarray(t)[16, 16, 3] == 255


def test_bad_options(tmp_path):
    with pytest.raises(ValueError, match="projection .fisheye. is not one of: ortho, perspective"):
        shaderbox.render_molecule(size=(8, 8), projection="fisheye")
    with pytest.raises(ValueError, match="fog .smog."):
        shaderbox.render_molecule(size=(8, 8), fog="smog")
    with pytest.raises(ValueError, match="effect .sepia. is not one of: plain, outline, x, x-red, transparent"):
        shaderbox.render_molecule(size=(8, 8), effect="sepia")
    with pytest.raises(ValueError, match="style .wireframe. is not one of: spacefill, ballstick"):
        shaderbox.render_molecule(size=(8, 8), style="wireframe")
    with pytest.raises(ValueError, match="atoms .lines. is not one of: quads, points"):
        shaderbox.render_molecule(size=(8, 8), atoms="lines")
    with pytest.raises(ValueError, match="light 9"):
        shaderbox.render_molecule(size=(8, 8), lights=[9])
    with pytest.raises(ValueError, match="size"):
        shaderbox.render_molecule(size="big")
    with pytest.raises(ValueError, match="image size 9000x8"):
        shaderbox.render_molecule(size=(9000, 8))
    with pytest.raises(ValueError, match="supersampling 9"):
        shaderbox.render_molecule(size=(8, 8), supersample=9)
    with pytest.raises(ValueError, match="background 'mauve'"):
        shaderbox.render_molecule(size=(8, 8), background="mauve")
    with pytest.raises(OSError, match="cannot read"):
        shaderbox.render_molecule(tmp_path / "missing.pdb", size=(8, 8))
    bad = tmp_path / "bad.pdb"
    bad.write_text("ATOM      1  N   THR A   1      17.047  xx.xxx   3.625  1.00 13.79           N\n")
    with pytest.raises(RuntimeError, match="bad.pdb"):
        shaderbox.render_molecule(bad, size=(8, 8))


def test_pdb_file(tmp_path):
    pdb = tmp_path / "two.pdb"
    pdb.write_text(
        "ATOM      1  O   HOH A   1       0.000   0.000   0.000  1.00  0.00           O\n"
        "ATOM      2  C   HOH A   1       2.000   0.000   0.000  1.00  0.00           C\n"
        "END\n"
    )
    a = np.asarray(shaderbox.render_molecule(pdb, size=(40, 20)))
    # Oxygen is red (left), carbon grey (right).
    left, right = a[10, :20].astype(int), a[10, 20:].astype(int)
    assert (left[:, 0] - left[:, 2]).max() > 50
    assert abs(int(right[:, 0].max()) - int(right[:, 2].max())) < 30


def test_molecule_renderer_keeps_one_context(tmp_path):
    pdb = tmp_path / "two.pdb"
    text = (
        "ATOM      1  O   HOH A   1       0.000   0.000   0.000  1.00  0.00           O\n"
        "ATOM      2  C   HOH A   1       2.000   0.000   0.000  1.00  0.00           C\n"
        "END\n"
    )
    pdb.write_text(text)
    r = shaderbox.MoleculeRenderer(size=(48, 40), fog="linear")
    # Each image equals render_molecule's, whatever the renderer drew before.
    for path, kw in [
        (None, {}),
        (pdb, dict(style="ballstick", effect="outline", projection="perspective")),
        (None, dict(atoms="points", background="transparent")),
        (pdb, dict(size=(32, 32), supersample=2)),
        (None, {}),
    ]:
        img = r.render(path, **kw)
        assert img == shaderbox.render_molecule(path, **dict(dict(size=(48, 40), fog="linear"), **kw)), (path, kw)
    # Text in place of a file: the same picture; errors name it.
    assert r.render(text=text) == r.render(pdb)
    assert r.render(text=text.encode()) == r.render(pdb)
    with pytest.raises(RuntimeError, match="lig.pdb"):
        r.render(text="ATOM      1  N   THR A   1      17.047  xx.xxx\n", name="lig.pdb")
    with pytest.raises(TypeError, match="path or text"):
        r.render(pdb, text=text)
    with pytest.raises(TypeError, match="unknown rendering option"):
        shaderbox.MoleculeRenderer(colour="red")
    with pytest.raises(ValueError, match="effect"):
        r.render(effect="sepia")
