#!/usr/bin/env python3
"""Throughput of ``shaderbox-batch`` on the Chemical Component Dictionary,
beside a shell loop of ``shaderbox render`` over the same inputs.

For each round, in turn: ``shaderbox-batch --ccd --limit N`` with each
worker count of ``--workers`` (a fresh output folder each time, so all
molecules render), then, with ``--shell``, a ``sh`` loop running
``shaderbox render FILE --size S -o OUT/NAME.png`` once per component,
over the same components written as PDB files (the text the batch's
workers render). Prints a table (wall seconds, molecules per second,
failures) and checks that the loop's images equal the batch's byte for
byte. Each time is the whole command: for the batch, cluster start, each
worker's dictionary index, drawing, PNG encoding, writing, manifest and
contact sheet.

    python3 bench/batch.py --limit 2000 --workers 1,2,4 --shell --rounds 2
    python3 bench/batch.py --workers 2 --shell          # the whole dictionary

Needs the package with its ``batch`` extra installed in this Python and
the ``shaderbox`` command (``--cli``, default: on PATH).
"""

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time


def export_components(limit, folder):
    """Writes each component the batch would render as FOLDER/ID.pdb (the
    ones without coordinates are skipped: the batch fails them too and
    the loop would have nothing to read). Returns (written, skipped)."""
    from shaderbox import batch

    written = skipped = 0
    for inp in batch.ccd_inputs(limit):
        comp = inp[len("ccd:") :]
        try:
            text = batch._ccd_pdb(comp)
        except RuntimeError:
            skipped += 1
            continue
        with open(os.path.join(folder, comp.replace("/", "_") + ".pdb"), "wb") as f:
            f.write(text)
        written += 1
    return written, skipped


def run_batch(limit, workers, size, out):
    cmd = [sys.executable, "-m", "shaderbox.batch", "--ccd", "-o", out, "--workers", str(workers), "--size", size, "-q"]
    if limit is not None:
        cmd += ["--limit", str(limit)]
    t0 = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode not in (0, 1):
        sys.exit(f"shaderbox-batch failed ({p.returncode}): {p.stderr}")
    failed = sum(1 for line in open(os.path.join(out, "manifest.jsonl")) if '"status": "failed"' in line)
    return wall, failed


def run_shell(cli, folder, size, out):
    script = f'for f in "$1"/*.pdb; do n=$(basename "$f" .pdb); "$2" render "$f" --size {size} -o "$3/$n.png" 2>/dev/null || echo "$n" >> "$3/failed.txt"; done'
    t0 = time.perf_counter()
    subprocess.run(["sh", "-c", script, "loop", folder, cli, out], check=True)
    wall = time.perf_counter() - t0
    failed_file = os.path.join(out, "failed.txt")
    failed = sum(1 for _ in open(failed_file)) if os.path.exists(failed_file) else 0
    return wall, failed


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--limit", type=int, help="the first N components (default: all)")
    ap.add_argument("--workers", default="2", help="comma-separated worker counts (default 2)")
    ap.add_argument("--size", default="128x128")
    ap.add_argument("--shell", action="store_true", help="also the shell loop of shaderbox render")
    ap.add_argument("--cli", default=shutil.which("shaderbox") or "shaderbox", help="the shaderbox command")
    ap.add_argument("--rounds", type=int, default=1)
    ap.add_argument("--keep", help="keep the outputs under this folder")
    a = ap.parse_args()
    from shaderbox import batch

    total = len(batch.ccd_inputs(a.limit))
    root = a.keep or tempfile.mkdtemp(prefix="shaderbox-bench-batch-")
    os.makedirs(root, exist_ok=True)
    files = os.path.join(root, "pdb")
    if a.shell:
        os.makedirs(files, exist_ok=True)
        written, skipped = export_components(a.limit, files)
        print(f"{total} components: {written} written as PDB files, {skipped} without coordinates", flush=True)
    load = os.getloadavg()[0]
    print(f"load average before: {load:.1f}; {os.cpu_count()} CPUs", flush=True)
    print("| round | run | wall (s) | molecules/s | failed |")
    print("|---|---|---|---|---|")
    for r in range(a.rounds):
        batch_out = None
        for w in [int(x) for x in a.workers.split(",")]:
            out = os.path.join(root, f"batch-w{w}-r{r}")
            shutil.rmtree(out, ignore_errors=True)
            wall, failed = run_batch(a.limit, w, a.size, out)
            batch_out = batch_out or out
            print(f"| {r + 1} | shaderbox-batch, {w} worker(s) | {wall:.1f} | {total / wall:.1f} | {failed} |", flush=True)
        if a.shell:
            out = os.path.join(root, f"shell-r{r}")
            shutil.rmtree(out, ignore_errors=True)
            os.makedirs(out)
            wall, failed = run_shell(a.cli, files, a.size, out)
            print(f"| {r + 1} | shell loop of `shaderbox render` | {wall:.1f} | {total / wall:.1f} | {failed} |", flush=True)
            differ = [
                f
                for f in os.listdir(out)
                if f.endswith(".png") and open(os.path.join(out, f), "rb").read() != open(os.path.join(batch_out, f), "rb").read()
            ]
            if differ:
                sys.exit(f"{len(differ)} images of the loop differ from the batch's, e.g. {differ[:3]}")
    print(f"load average after: {os.getloadavg()[0]:.1f}; the loop's images equal the batch's" if a.shell else "")
    if not a.keep:
        shutil.rmtree(root, ignore_errors=True)


if __name__ == "__main__":
    main()
