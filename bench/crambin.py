#!/usr/bin/env python3
"""The README's main job timed, and the same GL calls timed on Mesa.

    python3 bench/crambin.py [--size 1024x1024] [--runs 5] [--bin SHADERBOX] [--lib DIR]

Issue 5's speed bar: `shaderbox render` of a 1CRN-sized molecule at
1024x1024 in under half a second on the 2-core machine, with Mesa running
the same scene beside it. Three measurements, each the median of --runs:

1. `shaderbox render --size WxH -o OUT.png` (the embedded crambin, the
   library's sphere impostors, the default style and effect), wall time
   from process start to the PNG written, with SHADERBOX_THREADS=1 and 2.
2. The same render's GL calls (`--export-scene`) replayed through PyOpenGL
   on Debian's libOSMesa (llvmpipe, LP_NUM_THREADS=1 and 2): context,
   program compile + link, state, the draws, glFinish and glReadPixels.
3. The same replay on shaderbox's libOSMesa.so (--lib, default the release
   build), so the two libraries are compared through the same calls.

The replay is scripts/regen-references.py's (the one that makes the render
reference images). Each replay runs in its own process; prints a table.
Needs python3, PyOpenGL and libosmesa6.
"""
import argparse
import importlib.util
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def child(scene_path, runs):
    """Replays the scene `runs` times on whichever libOSMesa PyOpenGL loads;
    prints JSON with the times."""
    spec = importlib.util.spec_from_file_location(
        "regen", os.path.join(ROOT, "scripts", "regen-references.py"))
    regen = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(regen)
    with open(scene_path) as f:
        scene = json.load(f)
    regen.replay(scene)  # warm-up (library loading, first compile)
    times = []
    for _ in range(runs):
        t = time.perf_counter()
        regen.replay(scene)
        times.append(time.perf_counter() - t)
    print(json.dumps({"times": times}))


def median_ms(times):
    return 1000.0 * statistics.median(times)


def spread(times):
    return f"{median_ms(times):.0f} ms ({1000 * min(times):.0f}–{1000 * max(times):.0f}, n={len(times)})"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--size", default="1024x1024")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--bin", help="the shaderbox binary (default: target/release/shaderbox)")
    ap.add_argument("--lib", help="directory of shaderbox's libOSMesa.so (default: target/release)")
    ap.add_argument("--child", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        child(args.child, args.runs)
        return

    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target"))
    binary = args.bin or os.path.join(target, "release", "shaderbox")
    lib = args.lib or os.path.join(target, "release")
    if not args.bin or not args.lib:
        subprocess.run(["cargo", "build", "--release", "-q", "-p", "shaderbox-cli",
                        "-p", "shaderbox-capi"], cwd=ROOT, check=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        png = os.path.join(tmp, "m.png")
        scene = os.path.join(tmp, "scene.json")
        subprocess.run([binary, "render", "--size", args.size, "-o", png,
                        "--export-scene", scene], check=True, capture_output=True)
        for threads in (1, 2):
            env = dict(os.environ, SHADERBOX_THREADS=str(threads))
            times = []
            for _ in range(args.runs):
                t = time.perf_counter()
                subprocess.run([binary, "render", "--size", args.size, "-o", png],
                               env=env, check=True, capture_output=True)
                times.append(time.perf_counter() - t)
            rows.append((f"`shaderbox render --size {args.size}` (process, PNG written)",
                         threads, times))
        for name, extra in (("Mesa llvmpipe", {"LP_NUM_THREADS": None}),
                            ("shaderbox libOSMesa.so", {"LD_LIBRARY_PATH": lib,
                                                        "SHADERBOX_THREADS": None})):
            for threads in (1, 2):
                env = dict(os.environ, PYOPENGL_PLATFORM="osmesa")
                for k, v in extra.items():
                    env[k] = v if v is not None else str(threads)
                out = subprocess.run([sys.executable, __file__, "--child", scene,
                                      "--runs", str(args.runs)],
                                     env=env, check=True, capture_output=True, text=True)
                times = json.loads(out.stdout.strip().splitlines()[-1])["times"]
                rows.append((f"the exported calls replayed on {name}", threads, times))
    load = os.getloadavg()[0]
    print(f"crambin (1CRN, 327 atoms) at {args.size}, load average {load:.1f}")
    print()
    print("| what | threads | median (min–max, runs) |")
    print("|---|---|---|")
    for what, threads, times in rows:
        print(f"| {what} | {threads} | {spread(times)} |")


if __name__ == "__main__":
    main()
