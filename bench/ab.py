#!/usr/bin/env python3
"""Two builds of shaderbox's libOSMesa.so, one scene, interleaved runs.

    python3 bench/ab.py SPEC BASE_DIR NEW_DIR [--rounds N] [--threads T] [--frames F]

Runs bench/scene.py on SPEC alternately with LD_LIBRARY_PATH=BASE_DIR and
NEW_DIR (each a directory holding a libOSMesa.so), --rounds times each,
and prints the medians and minima of the timed frames, the median
processor time per frame (every thread of the process: it moves less than
wall time when other work shares the machine), the ratios new/base, and
whether the two builds drew the same bytes. For checking one change on a
shared machine; bench/run.py is the comparison with Mesa.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def run(spec, lib, threads, out, frames):
    env = dict(os.environ, PYOPENGL_PLATFORM="osmesa", LD_LIBRARY_PATH=lib,
               SHADERBOX_THREADS=str(threads), LP_NUM_THREADS=str(threads))
    p = subprocess.run(
        [sys.executable, os.path.join(HERE, "scene.py"), spec, "--frames", str(frames), "--budget", "6", "--out", out],
        env=env, capture_output=True, text=True)
    lines = [l for l in p.stdout.splitlines() if l.startswith("{")]
    if p.returncode != 0 or not lines:
        raise SystemExit(f"scene.py failed with {lib}:\n{p.stderr[-2000:]}")
    return json.loads(lines[-1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("spec")
    ap.add_argument("base")
    ap.add_argument("new")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--frames", type=int, default=5,
                    help="timed frames per run (more make the fastest frame steadier)")
    a = ap.parse_args()
    for d in (a.base, a.new):
        if not os.path.isfile(os.path.join(d, "libOSMesa.so")):
            raise SystemExit(f"{d} holds no libOSMesa.so")
    times = {a.base: [], a.new: []}
    cpu = {a.base: [], a.new: []}
    with tempfile.TemporaryDirectory() as tmp:
        outs = {a.base: os.path.join(tmp, "base.bin"), a.new: os.path.join(tmp, "new.bin")}
        for _ in range(a.rounds):
            for d in (a.base, a.new):
                r = run(a.spec, d, a.threads, outs[d], a.frames)
                times[d] += r["times"]
                cpu[d].append(r["cpu_per_frame"])
        with open(outs[a.base], "rb") as f, open(outs[a.new], "rb") as g:
            same = f.read() == g.read()
    ms = lambda x: f"{x * 1000:.1f} ms"
    for what, f in (("median frame", statistics.median), ("fastest frame", min)):
        b, n = f(times[a.base]), f(times[a.new])
        print(f"{what:14}: base {ms(b)}, new {ms(n)}, new/base {n / b:.3f}")
    b, n = statistics.median(cpu[a.base]), statistics.median(cpu[a.new])
    print(f"{'cpu per frame':14}: base {ms(b)}, new {ms(n)}, new/base {n / b:.3f}")
    print(f"images: {'identical' if same else 'DIFFERENT'} ({a.spec}, {a.threads} threads, {a.rounds} rounds)")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
