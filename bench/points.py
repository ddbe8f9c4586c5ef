#!/usr/bin/env python3
"""Sphere impostors as quads and as geometry-shader points, beside llvmpipe.

    python3 bench/points.py --lib DIR [--rounds N] [--frames F] [--threads T] [SPEC...]

For each sphere scene of bench/scene.py (default: the 2,000, 20,000 and
100,000-atom scenes at 1024², orthographic, and 20,000 in perspective)
runs three renderers, each in its own process, alternating their order
every round so that a neighbour's load falls on all three:

    shaderbox quads    SPEC          (4 vertices per atom, sphere.vert)
    shaderbox points   SPEC:points   (1 vertex per atom, sphere.geom)
    llvmpipe quads     SPEC          (Mesa cannot run the EXT geometry form)

and prints, per scene, each one's median frame (all rounds' timed frames
pooled) and processor time per frame, the ratios points/quads and
points/llvmpipe of the medians, and whether shaderbox's two images are
the same bytes and how many pixels of the points image lie within 2/255
of llvmpipe's. DIR holds shaderbox's libOSMesa.so (a release build).
Needs python3 and PyOpenGL.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = [
    "spheres:2000:1024x1024:ortho:none",
    "spheres:20000:1024x1024:ortho:none",
    "spheres:20000:1024x1024:persp:none",
    "spheres:100000:1024x1024:ortho:none",
]


def run(spec, lib, threads, frames, out):
    env = dict(os.environ, PYOPENGL_PLATFORM="osmesa")
    env.pop("LD_LIBRARY_PATH", None)
    if lib:
        env["LD_LIBRARY_PATH"] = lib
        env["SHADERBOX_THREADS"] = str(threads)
    else:
        env["LP_NUM_THREADS"] = str(threads)
    p = subprocess.run(
        [sys.executable, os.path.join(HERE, "scene.py"), spec, "--frames", str(frames),
         "--budget", "8", "--out", out], env=env, capture_output=True, text=True)
    lines = [ln for ln in p.stdout.splitlines() if ln.startswith("{")]
    if p.returncode != 0 or not lines:
        raise SystemExit(f"scene.py {spec} failed:\n{p.stderr[-2000:]}")
    return json.loads(lines[-1])


def within(a_path, b_path, tol=2):
    with open(a_path, "rb") as f:
        a = f.read()
    with open(b_path, "rb") as f:
        b = f.read()
    if len(a) != len(b) or not a:
        return 0.0
    good = sum(1 for i in range(0, len(a), 4)
               if all(abs(a[i + c] - b[i + c]) <= tol for c in range(4)))
    return 100.0 * good / (len(a) // 4)


def ms(s):
    return f"{1000 * s:.1f} ms"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("specs", nargs="*", default=SCENES)
    ap.add_argument("--lib", required=True, help="directory of shaderbox's libOSMesa.so")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--threads", type=int, default=2)
    a = ap.parse_args()
    runners = [("shaderbox quads", a.lib, ""), ("shaderbox points", a.lib, ":points"),
               ("llvmpipe quads", None, "")]
    print("| scene | shaderbox quads | shaderbox points | llvmpipe quads | points / quads | "
          "points / llvmpipe | points = quads | points within 2/255 of llvmpipe |")
    print("|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for spec in a.specs:
            times = {name: [] for name, _, _ in runners}
            cpu = {name: [] for name, _, _ in runners}
            outs = {name: os.path.join(tmp, f"{i}.bin") for i, (name, _, _) in enumerate(runners)}
            for r in range(a.rounds):
                order = runners if r % 2 == 0 else runners[::-1]
                for name, lib, suffix in order:
                    res = run(spec + suffix, lib, a.threads, a.frames, outs[name])
                    times[name] += res["times"]
                    if "cpu_per_frame" in res:
                        cpu[name].append(res["cpu_per_frame"])
            med = {k: statistics.median(v) for k, v in times.items()}
            cells = [f"{ms(med[n])} (cpu {ms(statistics.median(cpu[n]))}, n={len(times[n])})"
                     if cpu[n] else ms(med[n]) for n, _, _ in runners]
            with open(outs["shaderbox quads"], "rb") as f:
                q = f.read()
            with open(outs["shaderbox points"], "rb") as f:
                same = "yes" if f.read() == q else "NO"
            agree = within(outs["shaderbox points"], outs["llvmpipe quads"])
            print(f"| `{spec}` | " + " | ".join(cells) +
                  f" | {med['shaderbox points'] / med['shaderbox quads']:.2f}× | "
                  f"{med['shaderbox points'] / med['llvmpipe quads']:.2f}× | {same} | {agree:.2f} % |",
                  flush=True)


if __name__ == "__main__":
    main()
