"""shaderbox.batch: many molecules on a Dask LocalCluster, resumable."""

import hashlib
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("dask.distributed", reason="shaderbox.batch needs dask[distributed]: pip install shaderbox[batch]")
pytest.importorskip("biotite", reason="shaderbox.batch's --ccd needs biotite: pip install shaderbox[batch]")

from dask.distributed import Client, LocalCluster  # noqa: E402

import shaderbox  # noqa: E402
from shaderbox import batch  # noqa: E402

ROOT = Path(__file__).resolve().parents[3]
SIZE = (64, 64)


@pytest.fixture(scope="module")
def client():
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0", silence_logs=40)
    c = Client(cluster)
    yield c
    c.close()
    cluster.close()


@pytest.fixture
def structures(tmp_path):
    """A folder of structure files: three PDB files from the repository, an
    mmCIF file biotite writes, a file that is not a structure and one
    without atoms."""
    d = tmp_path / "in"
    d.mkdir()
    shutil.copy(ROOT / "crates/render/data/1crn.pdb", d / "1crn.pdb")
    shutil.copy(ROOT / "crates/cli/tests/debug/two-atoms.pdb", d / "two-atoms.pdb")
    shutil.copy(ROOT / "fuzz/corpus/pdb/hetatm-conect-models.pdb", d / "hetatm.pdb")
    from biotite.structure import info
    from biotite.structure.io import pdbx

    cif = pdbx.CIFFile()
    pdbx.set_structure(cif, info.residue("TRP"))
    cif.write(str(d / "trp.cif"))
    (d / "garbage.pdb").write_text("ATOM      1  CA  GLY A   1      not numbers at all\n")
    (d / "empty.pdb").write_text("REMARK nothing here\nEND\n")
    (d / "notes.txt").write_text("not an input: the folder reader skips other suffixes\n")
    return d


def manifest_lines(out):
    return [json.loads(line) for line in (out / "manifest.jsonl").read_text().splitlines()]


def sha(path):
    return hashlib.sha256(path.read_bytes()).hexdigest()


def test_folder(client, structures, tmp_path):
    out = tmp_path / "out"
    rows = batch.render_many(batch.inputs_from(str(structures)), out, client, size=SIZE)
    by = {r["name"]: r for r in rows}
    assert sorted(by) == ["1crn", "empty", "garbage", "hetatm", "trp", "two-atoms"]
    for name in ["1crn", "hetatm", "trp", "two-atoms"]:
        r = by[name]
        assert r["status"] == "ok" and r["error"] is None and r["output"] == f"{name}.png", r
        assert sha(out / r["output"]) == r["sha256"]
        assert r["seconds"] >= 0
    # The worker's image is render_molecule's, byte for byte.
    direct = shaderbox.render_molecule(structures / "1crn.pdb", size=SIZE).to_png()
    assert (out / "1crn.png").read_bytes() == direct
    for name, words in [("garbage", "garbage.pdb:1"), ("empty", "no atoms")]:
        r = by[name]
        assert r["status"] == "failed" and r["output"] is None and r["sha256"] is None
        assert words in r["error"], r["error"]
        assert not (out / f"{name}.png").exists()
    # One row per input; no temporary files left.
    assert sorted(r["name"] for r in manifest_lines(out)) == sorted(by)
    assert sorted(p.name for p in out.iterdir()) == sorted(
        ["index.html", "manifest.jsonl"] + [f"{n}.png" for n in ["1crn", "hetatm", "trp", "two-atoms"]]
    )
    # The contact sheet shows the images and lists the failures.
    html = (out / "index.html").read_text()
    assert "4 images, 2 failed" in html
    assert all(f'src="{n}.png"' in html for n in ["1crn", "hetatm", "trp", "two-atoms"])
    assert "garbage.pdb:1" in html and 'src="garbage.png"' not in html


def test_resume(client, structures, tmp_path):
    out = tmp_path / "out"
    inputs = batch.inputs_from(str(structures))
    batch.render_many(inputs, out, client, size=SIZE)
    first = {r["name"]: r for r in manifest_lines(out)}
    inode = {p.name: p.stat().st_ino for p in out.glob("*.png")}

    # A rerun of a finished batch renders nothing: failures are kept too.
    calls = []
    rows = batch.render_many(inputs, out, client, size=SIZE, progress=lambda *a: calls.append(a))
    assert calls == [(6, 2, 6)]
    assert {r["name"]: r for r in rows} == first
    assert {p.name: p.stat().st_ino for p in out.glob("*.png")} == inode

    # An interrupted batch: one image gone, one torn (not its SHA-256), one
    # row missing and a torn last manifest line. Only those three render.
    (out / "1crn.png").unlink()
    (out / "trp.png").write_bytes(b"\x89PNG torn")
    kept = [r for r in manifest_lines(out) if r["name"] != "hetatm"]
    (out / "manifest.jsonl").write_text("".join(json.dumps(r) + "\n" for r in kept) + '{"name": "two-at')
    calls = []
    rows = batch.render_many(inputs, out, client, size=SIZE, progress=lambda *a: calls.append(a))
    assert calls[0] == (3, 2, 6) and calls[-1] == (6, 2, 6)
    assert {r["name"]: r["sha256"] for r in rows} == {n: r["sha256"] for n, r in first.items()}
    assert (out / "two-atoms.png").stat().st_ino == inode["two-atoms.png"]
    assert (out / "hetatm.png").stat().st_ino != inode["hetatm.png"]
    assert sorted(r["name"] for r in manifest_lines(out)) == sorted(first)

    # --retry-failed renders the failures again (and they fail again).
    calls = []
    rows = batch.render_many(inputs, out, client, size=SIZE, retry_failed=True, progress=lambda *a: calls.append(a))
    assert calls[0] == (4, 0, 6) and calls[-1] == (6, 2, 6)


def test_ccd(client, tmp_path):
    out = tmp_path / "ccd"
    inputs = batch.ccd_inputs(limit=20)
    assert len(inputs) == 20 and all(i.startswith("ccd:") for i in inputs)
    rows = batch.render_many(inputs, out, client, size=SIZE, style="ballstick", chunk_size=3)
    assert [r["input"] for r in rows] == inputs
    assert len(manifest_lines(out)) == 20
    for r in rows:
        if r["status"] == "ok":
            assert sha(out / r["output"]) == r["sha256"]
        else:
            assert r["error"], r
    assert sum(r["status"] == "ok" for r in rows) >= 15


def test_ccd_pdb_text():
    """The worker's dictionary index gives biotite's atoms, coordinates
    (ideal, else model) and bonds."""
    import warnings

    import numpy as np
    from biotite.structure import info

    text = batch._ccd_pdb("ALA").decode()
    hetatm = [line for line in text.splitlines() if line.startswith("HETATM")]
    assert len(hetatm) == 13 and hetatm[0][76:78] == " N"
    for name in ["ALA", "ATP", "HEM", "000", "NAG", "SO4"] + list(info.all_residues()[:40]):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            ref = info.residue(name)
        lines = batch._ccd_pdb(name).decode().splitlines()
        het = [line for line in lines if line.startswith("HETATM")]
        xyz = np.array([[float(line[k : k + 8]) for k in (30, 38, 46)] for line in het])
        assert len(het) == ref.array_length(), name
        assert np.allclose(xyz, ref.coord, atol=6e-4), name
        assert [line[76:78].strip() for line in het] == [e.upper() for e in ref.element], name
        conect = set()
        for line in lines:
            if line.startswith("CONECT"):
                a = int(line[6:11])
                for k in range(11, len(line), 5):
                    b = int(line[k : k + 5])
                    conect.add((min(a, b) - 1, max(a, b) - 1))
        assert conect == {(min(a, b), max(a, b)) for a, b, _ in ref.bonds.as_array()}, name
    with pytest.raises(RuntimeError, match="no atoms"):
        batch._ccd_pdb("NOT-A-COMPONENT")


def test_worker_death(structures, tmp_path, monkeypatch):
    inputs = batch.inputs_from(str(structures))
    calm = batch.render_many(inputs, tmp_path / "calm", workers=2, size=SIZE, chunk_size=1)
    # The first task on any worker ends its process; the nanny starts a new
    # worker and the scheduler reruns the task.
    marker = tmp_path / "died"
    monkeypatch.setenv(batch._DIE_ONCE_ENV, str(marker))
    out = tmp_path / "out"
    rows = batch.render_many(inputs, out, workers=2, size=SIZE, chunk_size=1)
    assert marker.exists()
    assert [dict(r, seconds=0) for r in rows] == [dict(r, seconds=0) for r in calm]
    names = [r["name"] for r in manifest_lines(out)]
    assert sorted(names) == sorted(set(names)) and len(names) == len(inputs)
    for r in rows:
        if r["output"]:
            assert (out / r["output"]).read_bytes() == (tmp_path / "calm" / r["output"]).read_bytes()


def test_worker_killed_mid_batch(tmp_path):
    """SIGKILL to a worker process while tasks are still queued: the batch
    completes with one row per input and the bytes of an undisturbed run."""
    import signal

    inputs = batch.ccd_inputs(limit=40)
    calm = batch.render_many(inputs, tmp_path / "calm", workers=2, size=SIZE, chunk_size=2)
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0", silence_logs=50)
    c = Client(cluster)
    try:
        pids = c.run(os.getpid)
        killed = []

        def progress(done, failed, total):
            if not killed and done >= 4:
                victim = sorted(pids.values())[0]
                os.kill(victim, signal.SIGKILL)
                killed.append((victim, done))

        out = tmp_path / "out"
        rows = batch.render_many(inputs, out, c, size=SIZE, chunk_size=2, progress=progress)
        assert killed and killed[0][1] < len(inputs), killed  # mid-batch
        assert killed[0][0] not in c.run(os.getpid).values()
    finally:
        c.close()
        cluster.close()
    assert [dict(r, seconds=0) for r in rows] == [dict(r, seconds=0) for r in calm]
    names = [r["name"] for r in manifest_lines(out)]
    assert sorted(names) == sorted(r["name"] for r in calm)
    for r in rows:
        if r["output"]:
            assert (out / r["output"]).read_bytes() == (tmp_path / "calm" / r["output"]).read_bytes()


def test_options_are_checked(tmp_path):
    with pytest.raises(ValueError, match="size"):
        batch.render_many([], tmp_path, size="big")
    with pytest.raises(ValueError):
        batch.render_many([], tmp_path, effect="sparkles")
    with pytest.raises(TypeError, match="unknown rendering option"):
        batch.render_many([], tmp_path, colour="red")


def test_list_file_and_names(structures, tmp_path):
    lst = tmp_path / "list.txt"
    lst.write_text(f"# a comment\n\nin/1crn.pdb\n{structures / 'two-atoms.pdb'}\nin/1crn.pdb\n")
    inputs = batch.inputs_from(str(lst))
    assert inputs == [str(tmp_path / "in/1crn.pdb"), str(structures / "two-atoms.pdb"), str(tmp_path / "in/1crn.pdb")]
    names = [u[0] for u in batch._units(inputs + ["ccd:ALA"])]
    assert names == ["1crn", "two-atoms", "1crn-2", "ALA"]
    frames = batch._units(inputs[:2], turntable=2)
    assert frames == [
        ("1crn-0001", inputs[0], 0.0),
        ("1crn-0002", inputs[0], 180.0),
        ("two-atoms-0001", inputs[1], 0.0),
        ("two-atoms-0002", inputs[1], 180.0),
    ]
    assert batch.inputs_from(str(lst), limit=1) == inputs[:1]
    with pytest.raises(FileNotFoundError):
        batch.inputs_from(str(tmp_path / "nowhere"))


def test_turntable_and_rotate(client, structures, tmp_path):
    out = tmp_path / "out"
    one = [str(structures / "1crn.pdb")]
    rows = batch.render_many(one, out, client, size=SIZE, rotate=(10, 20, 0), turntable=4)
    assert [r["name"] for r in rows] == ["1crn-0001", "1crn-0002", "1crn-0003", "1crn-0004"]
    assert all(r["status"] == "ok" for r in rows)
    # Frame k is the molecule turned 90 k degrees more about Y.
    for k, r in enumerate(rows):
        direct = shaderbox.render_molecule(one[0], size=SIZE, rotate=(10, 20 + 90 * k, 0)).to_png()
        assert (out / r["output"]).read_bytes() == direct, r["name"]
    assert len({r["sha256"] for r in rows}) == 4
    with pytest.raises(ValueError, match="turntable"):
        batch.render_many(one, out, turntable=0)


def test_command(structures, tmp_path):
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "shaderbox.batch", str(structures), "-o", str(out), "--workers", "2", "--size", "48x40", "-q"]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    assert p.returncode == 1, p.stderr  # two inputs fail
    assert "6 inputs: 4 ok, 2 failed; 6 rendered this run" in p.stdout, p.stdout
    assert len(manifest_lines(out)) == 6
    # The rerun has nothing left to render.
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    assert p.returncode == 1 and "6 inputs: 4 ok, 2 failed; 0 rendered this run" in p.stdout, p.stdout
    # Misuse: exit 2 with the reason.
    p = subprocess.run([sys.executable, "-m", "shaderbox.batch", "-o", str(out)], capture_output=True, text=True)
    assert p.returncode == 2 and "exactly one of SOURCE" in p.stderr
    p = subprocess.run(cmd[:-1] + ["--size", "0x3"], capture_output=True, text=True, timeout=600)
    assert p.returncode == 2 and "size" in p.stderr
    p = subprocess.run(cmd[:-1] + ["--rotate", "1,2"], capture_output=True, text=True, timeout=600)
    assert p.returncode == 2 and "--rotate" in p.stderr
    assert os.path.exists(out / "manifest.jsonl")


def test_command_on_a_separate_scheduler_and_workers(structures, tmp_path):
    """The multi-node route on one machine: a `dask scheduler` process and
    two `dask worker` processes started as a cluster's nodes would start
    them, and shaderbox-batch --scheduler; the images equal a local run's."""
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    address = f"tcp://127.0.0.1:{port}"
    dask = [sys.executable, "-m", "distributed.cli.dask_scheduler"]
    procs = [
        subprocess.Popen(
            dask + ["--host", "127.0.0.1", "--port", str(port), "--dashboard-address", ":0"],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
    ]
    try:
        for _ in range(2):
            procs.append(
                subprocess.Popen(
                    [sys.executable, "-m", "distributed.cli.dask_worker", address, "--nworkers", "1", "--nthreads", "1"],
                    stdout=subprocess.DEVNULL,
                    stderr=subprocess.DEVNULL,
                )
            )
        with Client(address, timeout=60) as c:
            c.wait_for_workers(2, timeout=60)
        out = tmp_path / "out"
        cmd = [sys.executable, "-m", "shaderbox.batch", str(structures), "-o", str(out), "--scheduler", address, "--size", "48x40", "-q"]
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
        assert p.returncode == 1, p.stderr  # two inputs fail
        assert "6 inputs: 4 ok, 2 failed; 6 rendered this run" in p.stdout, p.stdout
        local = tmp_path / "local"
        local_cmd = [sys.executable, "-m", "shaderbox.batch", str(structures), "-o", str(local), "--workers", "1", "--size", "48x40", "-q"]
        p = subprocess.run(local_cmd, capture_output=True, text=True, timeout=600)
        assert p.returncode == 1, p.stderr
        for name in ["1crn", "hetatm", "trp", "two-atoms"]:
            assert (out / f"{name}.png").read_bytes() == (local / f"{name}.png").read_bytes(), name
    finally:
        for proc in procs:
            proc.terminate()
        for proc in procs:
            try:
                proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                proc.kill()
