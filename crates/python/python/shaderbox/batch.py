"""``shaderbox.batch``: many molecules to PNG files on a Dask cluster.

Contract (docs/BATCH.md says it at length):

- Inputs are PDB/mmCIF file paths or ``"ccd:ID"`` for a component of
  biotite's bundled Chemical Component Dictionary (its ideal coordinates,
  the model coordinates where ideal ones are missing). Each input has a
  *name*: the file's stem or the component ID (a repeated stem gets
  ``-2``, ``-3``... in input order). Its image is ``OUT/<name>.png``.
- Every image is written to a temporary name in ``OUT`` and renamed, so a
  PNG in ``OUT`` is always whole.
- ``OUT/manifest.jsonl`` has one JSON object per line: ``name``,
  ``input``, ``status`` (``"ok"`` or ``"failed"``), ``output`` (the PNG's
  file name, or null), ``sha256`` (of the PNG, or null), ``seconds``
  (rendering time on the worker) and ``error`` (null, or why it failed).
  Rows are appended by the client as results arrive; when the batch ends
  the manifest is rewritten (atomically) with one row per name, the
  latest.
- ``OUT/index.html`` is a contact sheet of this batch's images with its
  failures listed, rewritten when a batch ends.
- A rerun skips names whose latest row is ``ok`` with the PNG present and
  of that SHA-256, and names whose latest row is ``failed`` (unless
  ``retry_failed``); everything else is rendered.
- A molecule that cannot be read or drawn gets a ``failed`` row with the
  error and the batch goes on. A worker that dies has its task rerun
  elsewhere by Dask; rows come only from finished tasks, so nothing is
  recorded twice.
- Workers render with the same code and options, so a molecule gives the
  same bytes on every worker (draws are bit-identical whatever the thread
  count).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import math
import os
import sys
import tempfile
import time
from typing import Any, Callable, Dict, Iterable, List, Optional, Sequence, Tuple

from ._molecule import _DEFAULTS, MoleculeRenderer, _background, _check_option_names, _lights, _size

__all__ = ["render_many", "inputs_from", "ccd_inputs", "main"]

MANIFEST = "manifest.jsonl"
STRUCTURE_SUFFIXES = (".pdb", ".ent", ".cif", ".mmcif")
_CCD_PREFIX = "ccd:"

# A test-only hook: when this variable names a file that does not exist
# yet, the first worker task to see it creates the file and ends its
# process at once (os._exit), as a crashed or killed worker would.
_DIE_ONCE_ENV = "SHADERBOX_BATCH_TEST_DIE_ONCE"

# The rendering options render_many accepts: render_molecule's, with a
# small image size by default.
_OPTION_DEFAULTS: Dict[str, Any] = dict(_DEFAULTS, size=(256, 256))


# ---------------------------------------------------------------- inputs


def ccd_inputs(limit: Optional[int] = None) -> List[str]:
    """``"ccd:ID"`` for every component of biotite's bundled dictionary, in
    its order (the first ``limit`` when given)."""
    try:
        from biotite.structure import info
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError("--ccd needs biotite: pip install shaderbox[batch]") from e
    names = list(info.all_residues())
    if limit is not None:
        names = names[: max(0, limit)]
    return [_CCD_PREFIX + n for n in names]


def inputs_from(source: str, limit: Optional[int] = None) -> List[str]:
    """The inputs a command-line SOURCE names: a folder (its files ending
    in .pdb, .ent, .cif, .mmcif, sorted by name, not recursive) or a list
    file (one path a line, relative to the list's folder; blank lines and
    ``#`` comments skipped)."""
    if os.path.isdir(source):
        found = sorted(
            os.path.join(source, f)
            for f in os.listdir(source)
            if f.lower().endswith(STRUCTURE_SUFFIXES) and os.path.isfile(os.path.join(source, f))
        )
    elif os.path.isfile(source):
        base = os.path.dirname(os.path.abspath(source))
        found = []
        with open(source, encoding="utf-8") as f:
            for line in f:
                t = line.strip()
                if t and not t.startswith("#"):
                    found.append(t if os.path.isabs(t) else os.path.join(base, t))
    else:
        raise FileNotFoundError(f"{source}: neither a folder of structure files nor a list file")
    return found[:limit] if limit is not None else found


def _units(inputs: Sequence[str], turntable: Optional[int] = None) -> List[Tuple[str, str, float]]:
    """The images to make, in order: ``(name, input, turn)``, one per input
    or, with a turntable of N frames, N per input (``turn`` = 360 k / N
    degrees added to the Y rotation, names ending ``-0001`` ... as
    ``shaderbox render --turntable`` numbers its frames). Names are unique
    (see the module docs)."""
    seen: Dict[str, int] = {}
    out = []
    frames = turntable or 1
    digits = max(4, len(str(frames)))
    for inp in inputs:
        if inp.startswith(_CCD_PREFIX):
            stem = inp[len(_CCD_PREFIX) :]
        else:
            stem = os.path.basename(inp)
            for suffix in STRUCTURE_SUFFIXES:
                if stem.lower().endswith(suffix):
                    stem = stem[: -len(suffix)]
                    break
        # A file name must not leave OUT.
        stem = stem.replace(os.sep, "_").replace("/", "_") or "_"
        for k in range(frames):
            base = stem if turntable is None else f"{stem}-{k + 1:0{digits}d}"
            n = seen.get(base, 0) + 1
            seen[base] = n
            turn = 0.0 if turntable is None else 360.0 * k / frames
            out.append((base if n == 1 else f"{base}-{n}", inp, turn))
    return out


# ---------------------------------------------------------------- workers


class _CcdIndex:
    """biotite's dictionary decoded once per worker process: the
    ``chem_comp_atom`` and ``chem_comp_bond`` columns as numpy arrays and
    each component's row range (its rows are contiguous). biotite's own
    per-component lookup masks the whole category each call (~30 ms); a
    slice here costs microseconds. Coordinates are chosen as biotite's
    ``info.residue`` does: the ideal ones when all are present, else the
    model ones, else none."""

    def __init__(self) -> None:
        import numpy as np
        from biotite.structure.info.ccd import get_ccd

        block = get_ccd()
        atoms = block["chem_comp_atom"]
        bonds = block["chem_comp_bond"]
        self.atom_comp = atoms["comp_id"].as_array(str)
        self.atom_name = atoms["atom_id"].as_array(str)
        self.element = atoms["type_symbol"].as_array(str)

        def coords(fields):
            return np.stack([atoms[f].as_array(np.float64, masked_value=np.nan) for f in fields], axis=1)

        self.ideal = coords([f"pdbx_model_Cartn_{d}_ideal" for d in "xyz"])
        self.model = coords([f"model_Cartn_{d}" for d in "xyz"])
        self.atom_ranges = self._ranges(self.atom_comp)
        self.bond_comp = bonds["comp_id"].as_array(str)
        self.bond_1 = bonds["atom_id_1"].as_array(str)
        self.bond_2 = bonds["atom_id_2"].as_array(str)
        self.bond_ranges = self._ranges(self.bond_comp)

    @staticmethod
    def _ranges(ids) -> Dict[str, Tuple[int, int]]:
        import numpy as np

        if len(ids) == 0:
            return {}
        starts = np.concatenate([[0], np.flatnonzero(ids[1:] != ids[:-1]) + 1])
        ends = np.concatenate([starts[1:], [len(ids)]])
        ranges = {str(ids[a]): (int(a), int(b)) for a, b in zip(starts, ends)}
        if len(ranges) != len(starts):
            raise RuntimeError("biotite's Chemical Component Dictionary lists a component's rows apart")
        return ranges

    def pdb(self, component: str) -> bytes:
        """The component's atoms (and bonds, as CONECT) as PDB text."""
        import numpy as np

        if component not in self.atom_ranges:
            raise RuntimeError(f"ccd:{component}: the component has no atoms")
        a, b = self.atom_ranges[component]
        xyz = self.ideal[a:b]
        if not np.isfinite(xyz).all():
            xyz = self.model[a:b]
        if not np.isfinite(xyz).all():
            raise RuntimeError(f"ccd:{component}: the component has no coordinates (neither ideal nor model)")
        names = [str(n) for n in self.atom_name[a:b]]
        lines = []
        for i, (name, element, (x, y, z)) in enumerate(zip(names, self.element[a:b], xyz)):
            el = str(element).upper()[:2]
            lines.append(f"HETATM{i + 1:5d} {name[:4]:<4s} UNL A   1    {x:8.3f}{y:8.3f}{z:8.3f}  1.00  0.00          {el:>2s}")
        index = {n: i for i, n in enumerate(names)}
        partners: Dict[int, List[int]] = {}
        ba, bb = self.bond_ranges.get(component, (0, 0))
        for n1, n2 in zip(self.bond_1[ba:bb], self.bond_2[ba:bb]):
            i, j = index.get(str(n1)), index.get(str(n2))
            if i is None or j is None:
                continue
            partners.setdefault(i, []).append(j)
            partners.setdefault(j, []).append(i)
        for i in sorted(partners):
            ps = sorted(partners[i])
            for k in range(0, len(ps), 4):
                lines.append("CONECT" + f"{i + 1:5d}" + "".join(f"{p + 1:5d}" for p in ps[k : k + 4]))
        lines.append("END")
        return ("\n".join(lines) + "\n").encode("ascii")


_CCD: List[_CcdIndex] = []


def _ccd_pdb(component: str) -> bytes:
    """The component as PDB text, from this process's dictionary index."""
    if not _CCD:
        _CCD.append(_CcdIndex())
    return _CCD[0].pdb(component)


class _Renderer:
    """One worker process's rendering state, kept across its tasks: a
    :class:`MoleculeRenderer` (one GL context and the compiled programs for
    every molecule) with the checked options, and the thread count it set."""

    def __init__(self, options: Dict[str, Any], threads: int):
        if threads <= 0:
            try:
                threads = len(os.sched_getaffinity(0))
            except AttributeError:  # pragma: no cover - not Linux
                threads = os.cpu_count() or 1
        # gl::Context reads it when it is made (the renderer's first draw).
        os.environ["SHADERBOX_THREADS"] = str(threads)
        self.threads = threads
        self.options = options
        self.renderer = MoleculeRenderer(**options)

    def render(self, unit: Tuple[str, str, float], out_dir: str) -> Dict[str, Any]:
        name, inp, turn = unit
        row: Dict[str, Any] = {"name": name, "input": inp, "status": "failed", "output": None, "sha256": None}
        t0 = time.perf_counter()
        try:
            rx, ry, rz = self.options["rotate"]
            rotate = (rx, ry + turn, rz)
            if inp.startswith(_CCD_PREFIX):
                image = self.renderer.render(text=_ccd_pdb(inp[len(_CCD_PREFIX) :]), name=inp, rotate=rotate)
            else:
                image = self.renderer.render(inp, rotate=rotate)
            png = image.to_png()
            output = f"{name}.png"
            fd, tmp = tempfile.mkstemp(prefix=f".{name}.", suffix=".tmp", dir=out_dir)
            try:
                with os.fdopen(fd, "wb") as f:
                    f.write(png)
                os.replace(tmp, os.path.join(out_dir, output))
            except BaseException:
                if os.path.exists(tmp):
                    os.unlink(tmp)
                raise
            row.update(status="ok", output=output, sha256=hashlib.sha256(png).hexdigest(), error=None)
        except Exception as e:  # noqa: BLE001 - every failure is a row, the batch goes on
            row["error"] = f"{type(e).__name__}: {e}"
        row["seconds"] = round(time.perf_counter() - t0, 4)
        return row


_RENDERERS: Dict[str, _Renderer] = {}


def _render_chunk(chunk: List[Tuple[str, str, float]], out_dir: str, options: Dict[str, Any], threads: int) -> List[Dict[str, Any]]:
    """A task: renders each (name, input, turn) of the chunk (``turn``:
    degrees added to the Y rotation) with the process's renderer for these
    options, returns their manifest rows."""
    marker = os.environ.get(_DIE_ONCE_ENV)
    if marker:
        try:
            fd = os.open(marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
        except FileExistsError:
            pass
        else:
            os.close(fd)
            os._exit(17)
    key = json.dumps([options, threads], sort_keys=True)
    renderer = _RENDERERS.get(key)
    if renderer is None:
        renderer = _RENDERERS[key] = _Renderer(options, threads)
    return [renderer.render(unit, out_dir) for unit in chunk]


# ---------------------------------------------------------------- manifest


def _sha256_file(path: str) -> Optional[str]:
    try:
        with open(path, "rb") as f:
            return hashlib.sha256(f.read()).hexdigest()
    except OSError:
        return None


def read_manifest(out_dir: str) -> Dict[str, Dict[str, Any]]:
    """The latest row of each name in ``OUT/manifest.jsonl`` (empty when
    there is none). A torn last line (an interrupted append) is skipped."""
    rows: Dict[str, Dict[str, Any]] = {}
    try:
        with open(os.path.join(out_dir, MANIFEST), encoding="utf-8") as f:
            for line in f:
                try:
                    row = json.loads(line)
                except ValueError:
                    continue
                if isinstance(row, dict) and isinstance(row.get("name"), str):
                    rows[row["name"]] = row
    except FileNotFoundError:
        pass
    return rows


def _is_done(row: Optional[Dict[str, Any]], out_dir: str, retry_failed: bool) -> bool:
    if row is None:
        return False
    if row.get("status") == "failed":
        return not retry_failed
    if row.get("status") != "ok" or not row.get("output"):
        return False
    return _sha256_file(os.path.join(out_dir, row["output"])) == row.get("sha256")


def _rewrite_manifest(out_dir: str, rows: Dict[str, Dict[str, Any]]) -> None:
    path = os.path.join(out_dir, MANIFEST)
    fd, tmp = tempfile.mkstemp(prefix=".manifest.", suffix=".tmp", dir=out_dir)
    with os.fdopen(fd, "w", encoding="utf-8") as f:
        for row in rows.values():
            f.write(json.dumps(row, sort_keys=True) + "\n")
    os.replace(tmp, path)


def _write_index(out_dir: str, rows: List[Dict[str, Any]]) -> None:
    """``OUT/index.html``: a contact sheet of the images (the shader
    gallery's look) and a table of the failures, rewritten atomically."""
    from html import escape

    ok = [r for r in rows if r["status"] == "ok"]
    bad = [r for r in rows if r["status"] != "ok"]
    parts = [
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>shaderbox batch</title>\n"
        "<style>body{font-family:sans-serif;background:#222;color:#ddd}figure{display:inline-block;"
        "width:140px;vertical-align:top;margin:6px}img{width:128px;height:128px}"
        "figcaption{font-size:12px;overflow-wrap:anywhere}code{color:#9cf}td{padding:2px 8px;vertical-align:top}"
        "</style></head><body>\n",
        f"<h1>shaderbox batch: {len(ok)} images, {len(bad)} failed</h1>\n",
    ]
    for r in ok:
        name = escape(r["name"])
        src = escape(r["output"], quote=True)
        parts.append(f'<figure><img src="{src}" loading="lazy" alt="{name}"><figcaption>{name}</figcaption></figure>\n')
    if bad:
        parts.append("<h2>Failed</h2>\n<table>\n")
        for r in bad:
            parts.append(f"<tr><td><code>{escape(r['name'])}</code></td><td>{escape(str(r.get('error')))}</td></tr>\n")
        parts.append("</table>\n")
    parts.append("</body></html>\n")
    fd, tmp = tempfile.mkstemp(prefix=".index.", suffix=".tmp", dir=out_dir)
    with os.fdopen(fd, "w", encoding="utf-8") as f:
        f.write("".join(parts))
    os.replace(tmp, os.path.join(out_dir, "index.html"))


# ---------------------------------------------------------------- driver


def _check_options(options: Dict[str, Any]) -> Dict[str, Any]:
    _check_option_names(options)
    opts = dict(_OPTION_DEFAULTS)
    opts.update(options)
    # Plain values (they travel to workers as JSON-able data) and an early
    # ValueError for a bad option instead of one failed row per molecule.
    opts["size"] = list(_size(opts["size"]))
    if min(opts["size"]) < 1:
        raise ValueError(f"size {options.get('size')!r} is not at least 1x1 pixels")
    opts["lights"] = _lights(opts["lights"])
    _background(opts["background"])
    if isinstance(opts["background"], tuple):
        opts["background"] = list(opts["background"])
    opts["rotate"] = [float(v) for v in opts["rotate"]]
    MoleculeRenderer().render(None, **dict(opts, size=(1, 1)))  # the enumerated options
    return opts


def _local_threads(workers: int) -> int:
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - not Linux
        cores = os.cpu_count() or 1
    return max(1, cores // max(1, workers))


def render_many(
    inputs: Iterable[Any],
    out_dir: Any,
    client: Any = None,
    *,
    workers: Optional[int] = None,
    threads: Optional[int] = None,
    chunk_size: Optional[int] = None,
    retries: int = 3,
    retry_failed: bool = False,
    turntable: Optional[int] = None,
    progress: Optional[Callable[[int, int, int], None]] = None,
    **options: Any,
) -> List[Dict[str, Any]]:
    """Renders every input to ``out_dir/<name>.png`` and returns the
    manifest row of each input, in input order (see the module docs).

    ``inputs``: file paths, or ``"ccd:ID"``. ``client``: a
    ``dask.distributed.Client``; without one a ``LocalCluster`` of
    ``workers`` processes (default: the machine's cores) runs the batch and
    is closed after. ``threads``: draw threads per worker (default: the
    cores divided among a local cluster's workers; with a given client, each
    worker's own cores). ``chunk_size``: molecules per task (default: about
    four tasks per worker, at most 64 molecules each). ``retries``: reruns
    of a task whose worker raised (a worker that dies is Dask's
    ``allowed-failures``). ``turntable``: N images per input turning once
    about the screen's vertical axis (added to ``rotate``'s Y; names
    ``<name>-0001`` ...; one manifest row per image). ``progress(done,
    failed, total)`` is called as rows arrive. ``options``: ``render_molecule``'s (size, projection, fog,
    lights, rotate, supersample, background, effect, style, atoms)."""
    from dask.distributed import Client, LocalCluster, as_completed

    out_dir = os.fspath(out_dir)
    inputs = [i if isinstance(i, str) and i.startswith(_CCD_PREFIX) else os.path.abspath(os.fspath(i)) for i in inputs]
    opts = _check_options(options)
    if turntable is not None and (isinstance(turntable, bool) or not isinstance(turntable, int) or not 1 <= turntable <= 3600):
        raise ValueError(f"turntable {turntable!r} is not a number of frames 1-3600")
    os.makedirs(out_dir, exist_ok=True)
    out_abs = os.path.abspath(out_dir)

    units = _units(inputs, turntable)
    names = [u[0] for u in units]
    previous = read_manifest(out_dir)
    rows: Dict[str, Dict[str, Any]] = dict(previous)
    todo = [u for u in units if not _is_done(previous.get(u[0]), out_dir, retry_failed)]
    total = len(units)
    done = total - len(todo)
    failed = sum(1 for n in names if n in previous and _is_done(previous[n], out_dir, retry_failed) and previous[n]["status"] == "failed")
    if progress:
        progress(done, failed, total)

    if todo:
        own_cluster = None
        own_client = None
        if client is None:
            n_workers = workers or _local_threads(1)
            own_cluster = LocalCluster(
                n_workers=n_workers,
                threads_per_worker=1,
                processes=True,
                # Any free port: a fixed one may be taken on a shared machine.
                dashboard_address=":0",
                silence_logs=40,
            )
            own_client = client = Client(own_cluster)
            n_task_workers = n_workers
            worker_threads = threads if threads is not None else _local_threads(n_workers)
        else:
            n_task_workers = max(1, len(client.scheduler_info().get("workers", {})))
            worker_threads = threads if threads is not None else 0
        try:
            size = chunk_size or max(1, min(64, math.ceil(len(todo) / (4 * n_task_workers))))
            chunks = [todo[k : k + size] for k in range(0, len(todo), size)]
            futures = [
                client.submit(_render_chunk, c, out_abs, opts, worker_threads, retries=retries, pure=False) for c in chunks
            ]
            with open(os.path.join(out_dir, MANIFEST), "a", encoding="utf-8") as manifest:
                for fut in as_completed(futures):
                    for row in fut.result():
                        rows[row["name"]] = row
                        manifest.write(json.dumps(row, sort_keys=True) + "\n")
                        done += 1
                        failed += row["status"] == "failed"
                    manifest.flush()
                    if progress:
                        progress(done, failed, total)
        finally:
            if own_client is not None:
                own_client.close()
            if own_cluster is not None:
                own_cluster.close()
        _rewrite_manifest(out_dir, rows)
    result = [rows[n] for n in names]
    _write_index(out_dir, result)
    return result


# ---------------------------------------------------------------- command


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="shaderbox-batch",
        description="Render many molecules to OUT/<name>.png on a Dask cluster, with a resumable manifest.",
    )
    p.add_argument("source", nargs="?", help="a folder of PDB/mmCIF files, or a text file listing paths")
    p.add_argument("--ccd", action="store_true", help="every component of biotite's Chemical Component Dictionary")
    p.add_argument("-o", "--out", required=True, help="output folder (images and manifest.jsonl)")
    p.add_argument("--limit", type=int, help="only the first N inputs")
    p.add_argument("--workers", type=int, help="local worker processes (default: the machine's cores)")
    p.add_argument("--threads", type=int, help="draw threads per worker (default: cores / local workers)")
    p.add_argument("--scheduler", help="address of a running Dask scheduler (tcp://host:8786) instead of a local cluster")
    p.add_argument("--chunk-size", type=int, help="molecules per task")
    p.add_argument("--retry-failed", action="store_true", help="render again the inputs that failed before")
    p.add_argument("--size", default="256x256", help="WIDTHxHEIGHT (default 256x256)")
    p.add_argument("--projection", default="ortho", choices=["ortho", "perspective"])
    p.add_argument("--fog", default="none", choices=["none", "linear", "exp", "exp2"])
    p.add_argument("--lights", default="0,1", help="light numbers 0-7, comma-separated, or none")
    p.add_argument("--rotate", default="0,0,0", help="X,Y,Z: degrees about X, then Y, then Z (as shaderbox render)")
    p.add_argument("--turntable", type=int, metavar="N", help="N images per input turning once about the vertical axis")
    p.add_argument("--supersample", type=int, default=1)
    p.add_argument("--background", default="black", help="black, white, gray, #RRGGBB or transparent")
    p.add_argument("--effect", default="plain", choices=["plain", "outline", "x", "x-red", "transparent"])
    p.add_argument("--style", default="spacefill", choices=["spacefill", "ballstick"])
    p.add_argument("--atoms", default="quads", choices=["quads", "points"])
    p.add_argument("-q", "--quiet", action="store_true", help="no progress line")
    return p


def _has_dashboard() -> bool:
    """Whether Dask serves its dashboard (it needs bokeh)."""
    try:
        import bokeh  # noqa: F401
    except ImportError:
        return False
    return True


def main(argv: Optional[Sequence[str]] = None) -> int:
    """``shaderbox-batch``; exit status 0 when every input has an image, 1
    when some failed (each has its error in the manifest), 2 on misuse."""
    p = _parser()
    a = p.parse_args(argv)
    if bool(a.source) == bool(a.ccd):
        p.error("give exactly one of SOURCE (folder or list file) and --ccd")
    try:
        inputs = ccd_inputs(a.limit) if a.ccd else inputs_from(a.source, a.limit)
    except (OSError, ImportError) as e:
        p.error(str(e))
    try:
        rotate = [float(v) for v in a.rotate.split(",")]
    except ValueError:
        rotate = []
    if len(rotate) != 3 or not all(math.isfinite(v) for v in rotate):
        p.error(f"--rotate {a.rotate!r} is not X,Y,Z in degrees (three numbers)")
    if a.turntable is not None and not 1 <= a.turntable <= 3600:
        p.error(f"--turntable {a.turntable} is not a number of frames 1-3600")
    options = dict(
        size=a.size,
        projection=a.projection,
        fog=a.fog,
        lights=a.lights,
        rotate=rotate,
        supersample=a.supersample,
        background=a.background,
        effect=a.effect,
        style=a.style,
        atoms=a.atoms,
    )
    t0 = time.perf_counter()
    last = [0.0]
    skipped: List[int] = []

    def progress(done: int, failed: int, total: int) -> None:
        if not skipped:
            skipped.append(done)
        now = time.perf_counter()
        if a.quiet or (now - last[0] < 0.5 and done < total):
            return
        last[0] = now
        width = 30
        filled = width * done // max(1, total)
        sys.stderr.write(f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total} failed {failed}")
        sys.stderr.flush()

    try:
        # Before starting a cluster: a bad option is misuse (exit 2).
        _check_options(options)
    except (ValueError, TypeError) as e:
        p.error(str(e))
    from dask.distributed import Client, LocalCluster

    client = cluster = None
    threads = a.threads
    try:
        if a.scheduler:
            client = Client(a.scheduler)
        else:
            workers = a.workers or _local_threads(1)
            cluster = LocalCluster(
                n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=":0", silence_logs=40
            )
            client = Client(cluster)
            if threads is None:
                threads = _local_threads(workers)
        if not a.quiet and _has_dashboard():
            sys.stderr.write(f"Dask dashboard: {client.dashboard_link}\n")
        try:
            rows = render_many(
                inputs,
                a.out,
                client,
                threads=threads,
                chunk_size=a.chunk_size,
                retry_failed=a.retry_failed,
                turntable=a.turntable,
                progress=progress,
                **options,
            )
        except (ValueError, TypeError) as e:
            p.error(str(e))
    finally:
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()
    seconds = time.perf_counter() - t0
    if not a.quiet:
        sys.stderr.write("\n")
    ok = sum(r["status"] == "ok" for r in rows)
    failed = len(rows) - ok
    ran = len(rows) - (skipped[0] if skipped else 0)
    rate = ran / seconds if seconds > 0 else 0.0
    print(
        f"{len(rows)} inputs: {ok} ok, {failed} failed; {ran} rendered this run in {seconds:.1f} s "
        f"({rate:.2f} molecules/s); manifest {os.path.join(a.out, MANIFEST)}, contact sheet {os.path.join(a.out, 'index.html')}"
    )
    return 1 if failed else 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
