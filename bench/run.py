#!/usr/bin/env python3
"""shaderbox vs Mesa llvmpipe, same scenes, same PyOpenGL program, same run.

    python3 bench/run.py [--quick] [--check-only] [--write-docs] [--only SUBSTR] [--rounds N]

Builds shaderbox's libOSMesa.so (`cargo build --release -p shaderbox-capi`)
unless --lib DIR is given, then runs every scene of bench/scene.py once per
implementation, each in its own process: shaderbox with
LD_LIBRARY_PATH=<its target/release>, Mesa with the system's libOSMesa
(Debian libosmesa6, llvmpipe). Both get the same thread count
(SHADERBOX_THREADS / LP_NUM_THREADS; 2 unless the scene says 1). Per scene:
warm-up frames (at least one, for half a second: scene.py's
WARMUP_SECONDS, so that both have compiled their shaders), then up to
--frames timed frames (fewer when --budget
seconds are spent, at least 2). Each scene runs --rounds times per
implementation, alternating (shaderbox then Mesa, then Mesa then
shaderbox, ...), so that a neighbour's load on the shared machine falls
on both; the frames of all rounds are pooled. The table gives the
median with the min–max spread, the ratio of the medians (shaderbox /
Mesa; below 1 means shaderbox is faster) with the spread of the rounds'
own ratios, and the share of pixels within 2/255 of Mesa's image (so a
fast wrong picture cannot hide).

--quick runs the scenes the issue's bars name; --check-only draws the
warm-up frame only and exits 1 when an image agrees on fewer than
--min-agree percent of its pixels (scenes of AGREE_FLOORS excepted).
--write-docs replaces the generated table in docs/PERFORMANCE.md (between
the bench markers).
Needs python3 and PyOpenGL (no numpy); the full run takes about 3 minutes
on 2 cores with the default 3 rounds.
"""
import argparse
import array
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DOC = os.path.join(ROOT, "docs", "PERFORMANCE.md")
BEGIN = "<!-- bench/run.py: begin (generated, do not edit by hand) -->"
END = "<!-- bench/run.py: end -->"

# (scene spec, threads, what it shows)
FULL = [
    ("spheres:2000:1024x1024:ortho:none", 2, "seed sphere impostors, 2,000 random atoms"),
    ("spheres:20000:1024x1024:ortho:none", 2, "20,000 atoms, orthographic (issue bar)"),
    ("spheres:20000:1024x1024:persp:none", 2, "20,000 atoms, perspective (issue bar)"),
    ("spheres:100000:1024x1024:ortho:none", 2, "100,000 atoms"),
    ("spheres:20000:512x512:ortho:none", 2, "20,000 atoms at 512²"),
    ("spheres:20000:1920x1080:ortho:none", 2, "20,000 atoms at 1920×1080"),
    ("spheres:20000:1024x1024:ortho:linear", 2, "linear fog"),
    ("spheres:20000:1024x1024:ortho:exp", 2, "exp fog"),
    ("spheres:20000:1024x1024:persp:exp2", 2, "exp2 fog, perspective"),
    ("spheres:20000:1024x1024:ortho:none:dense", 2, "20,000 atoms at protein density (0.09/Å³)"),
    ("spheres:20000:1024x1024:persp:none:dense", 2, "protein density, perspective"),
    ("spheres:20000:1024x1024:ortho:none:seed", 2, "the seed's sphere shaders as written, sparse"),
    ("spheres:20000:1024x1024:ortho:none:dense:seed", 2, "the seed's shaders, protein density"),
    ("spheres:20000:1024x1024:persp:none:dense:seed", 2, "the seed's shaders, protein density, perspective"),
    ("adk:1024x1024:ortho:none", 2, "a real structure: adenylate kinase in water, 47,681 atoms"),
    ("adk:1024x1024:persp:none", 2, "the real structure, perspective"),
    ("adk:1024x1024:ortho:none:seed", 2, "the real structure, the seed's shaders as written"),
    ("spheres:20000:1024x1024:ortho:none", 1, "one thread (scaling)"),
    ("spheres:20000:1024x1024:persp:none", 1, "one thread (scaling)"),
    ("mesh:100000:1024x1024", 2, "seed materials shader, 100k triangles (VBO)"),
    ("mesh:1000000:1024x1024", 2, "seed materials shader, 1M triangles"),
    ("ffmesh:300000:1024x1024", 2, "fixed-function lights + fog, 300k triangles"),
    ("textured:8:1024x1024", 2, "8 blended mipmapped texture layers"),
    ("tiny:300000:1024x1024", 2, "300k sub-pixel triangles (geometry-bound)"),
    ("compile:sphere", 2, "compile + link shaders/sphere.{vert,frag}"),
    ("compile:materials", 2, "compile + link the seed materials shaders"),
    ("core-spheres:20000:1024x1024", 2, "3.3 core: 20,000 instanced impostors, UBO camera"),
    ("core-mesh:100000:1024x1024", 2, "3.3 core: 100k-triangle VAO mesh, UBO-lit per fragment"),
    ("core-itex:8:1024x1024", 2, "3.3 core: 8 blended passes of R16UI texelFetch + UBO palette"),
]
QUICK = [
    ("spheres:20000:1024x1024:ortho:none", 2, "20,000 atoms, orthographic (issue bar)"),
    ("spheres:20000:1024x1024:persp:none", 2, "20,000 atoms, perspective (issue bar)"),
    ("spheres:20000:1024x1024:ortho:none", 1, "one thread (scaling)"),
    ("mesh:100000:1024x1024", 2, "seed materials shader, 100k triangles (VBO)"),
    ("ffmesh:100000:1024x1024", 2, "fixed-function lights + fog, 100k triangles"),
    ("textured:8:1024x1024", 2, "8 blended mipmapped texture layers"),
    ("tiny:100000:1024x1024", 2, "100k sub-pixel triangles (geometry-bound)"),
    ("compile:sphere", 2, "compile + link shaders/sphere.{vert,frag}"),
]


# Scenes allowed to agree with Mesa on fewer pixels than --min-agree in
# --check-only (spec substring -> percent). Empty since the library's
# sphere shaders compute the ray-sphere test without cancelling large
# numbers (before, the perspective sphere scenes agreed on ~90 %).
AGREE_FLOORS = {}


def floor_for(spec, default):
    return min([v for k, v in AGREE_FLOORS.items() if k in spec] + [default])


def machine():
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    mem = ""
    try:
        with open("/proc/meminfo") as f:
            kb = int(f.readline().split()[1])
            mem = f", {kb / 1024 / 1024:.0f} GiB"
    except (OSError, ValueError, IndexError):
        pass
    return f"{os.cpu_count()}-core {model}{mem}, {platform.system()} {platform.release()}"


def run_scene(spec, impl, libdir, threads, frames, budget, out, extra=()):
    env = dict(os.environ, PYOPENGL_PLATFORM="osmesa")
    env.pop("LD_LIBRARY_PATH", None)
    if impl == "shaderbox":
        env["LD_LIBRARY_PATH"] = libdir
        env["SHADERBOX_THREADS"] = str(threads)
    else:
        env["LP_NUM_THREADS"] = str(threads)
    cmd = [sys.executable, os.path.join(HERE, "scene.py"), spec, "--frames", str(frames),
           "--budget", str(budget), "--out", out, *extra]
    r = subprocess.run(cmd, env=env, capture_output=True, text=True)
    lines = [ln for ln in r.stdout.splitlines() if ln.startswith("{")]
    if r.returncode != 0 or not lines:
        err = (r.stderr.strip().splitlines() or ["no output"])[-1]
        return {"error": f"{impl} failed (exit {r.returncode}): {err}"}
    return json.loads(lines[-1])


def agreement(a_path, b_path):
    """Percent of pixels whose RGBA channels all lie within 2/255."""
    try:
        with open(a_path, "rb") as f:
            a = f.read()
        with open(b_path, "rb") as f:
            b = f.read()
    except OSError:
        return None
    if len(a) != len(b) or not a or len(a) % 4:
        return None
    if a == b:
        return 100.0
    wa, wb = array.array("I", a), array.array("I", b)
    bad = 0
    for i in range(len(wa)):
        if wa[i] != wb[i]:
            x, y = wa[i], wb[i]
            for s in (0, 8, 16, 24):
                if abs(((x >> s) & 255) - ((y >> s) & 255)) > 2:
                    bad += 1
                    break
    return 100.0 * (len(wa) - bad) / len(wa)


def fmt_time(t):
    if t is None:
        return "—"
    if t < 1e-3:
        return f"{t * 1e6:.0f} µs"
    if t < 1.0:
        return f"{t * 1e3:.1f} ms"
    return f"{t:.2f} s"


def pooled(results):
    """One result from several rounds of a scene: their frames together
    (the first failure, if a round failed)."""
    for r in results:
        if "error" in r:
            return r
    out = dict(results[-1])
    out["times"] = [t for r in results for t in r.get("times") or []]
    return out


def summary(res):
    if "error" in res:
        return None, res["error"]
    ts = res.get("times") or []
    if not ts:
        return None, "no frames"
    med = statistics.median(ts)
    return med, f"{fmt_time(med)} ({fmt_time(min(ts))}–{fmt_time(max(ts))}, n={len(ts)})"


def build(libdir_arg):
    if libdir_arg:
        return os.path.abspath(libdir_arg)
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target"))
    subprocess.run(["cargo", "build", "--release", "-q", "-p", "shaderbox-capi"], cwd=ROOT, check=True)
    return os.path.join(os.path.abspath(target), "release")


def write_docs(text):
    with open(DOC) as f:
        doc = f.read()
    block = f"{BEGIN}\n{text}\n{END}"
    if BEGIN in doc and END in doc:
        head, rest = doc.split(BEGIN, 1)
        tail = rest.split(END, 1)[1]
        doc = head + block + tail
    else:
        doc = doc.rstrip("\n") + "\n\n" + block + "\n"
    with open(DOC, "w") as f:
        f.write(doc)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="only the scenes of the issue's bars")
    ap.add_argument("--check-only", action="store_true", help="one frame per scene, compare images only")
    ap.add_argument("--write-docs", action="store_true", help="update the table in docs/PERFORMANCE.md")
    ap.add_argument("--only", help="run the scenes whose spec contains this")
    ap.add_argument("--lib", help="directory of shaderbox's libOSMesa.so (default: build it)")
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--rounds", type=int, default=3, help="alternating runs per implementation and scene")
    ap.add_argument("--budget", type=float, default=12.0, help="seconds of timed frames per run")
    ap.add_argument("--min-agree", type=float, default=99.0, help="--check-only threshold (percent)")
    ap.add_argument("--json", help="also write the raw results here")
    args = ap.parse_args()
    libdir = build(args.lib)
    scenes = QUICK if args.quick else FULL
    if args.only:
        scenes = [s for s in scenes if args.only in s[0]]
    frames = 0 if args.check_only else args.frames
    load0 = os.getloadavg()
    started = time.time()
    rows, raw, failed = [], [], False
    with tempfile.TemporaryDirectory() as tmp:
        for spec, threads, what in scenes:
            outs = {i: os.path.join(tmp, f"{i}.bin") for i in ("shaderbox", "mesa")}
            for p in outs.values():
                if os.path.exists(p):
                    os.remove(p)
            # --check-only: the warm-up frame only (its image is compared).
            rounds = 1 if args.check_only else max(1, args.rounds)
            runs = {"shaderbox": [], "mesa": []}
            for k in range(rounds):
                order = ("shaderbox", "mesa") if k % 2 == 0 else ("mesa", "shaderbox")
                for i in order:
                    runs[i].append(run_scene(spec, i, libdir, threads,
                                             max(frames, 2) if not args.check_only else 0,
                                             (args.budget if not args.check_only else 0.0) / rounds,
                                             outs[i]))
            res = {i: pooled(r) for i, r in runs.items()}
            agree = None if spec.startswith("compile") else agreement(outs["shaderbox"], outs["mesa"])
            ms, ss = summary(res["shaderbox"])
            mm, sm = summary(res["mesa"])
            ratio = f"{ms / mm:.2f}×" if ms and mm else "—"
            medians = {i: [summary(r)[0] for r in rs] for i, rs in runs.items()}
            per_round = [a / b for a, b in zip(medians["shaderbox"], medians["mesa"]) if a and b]
            if len(per_round) > 1:
                ratio += f" ({min(per_round):.2f}–{max(per_round):.2f})"
            ag = "—" if agree is None else f"{agree:.2f} %"
            if spec.startswith("compile"):
                ag = "n/a"
            elif agree is None or agree < floor_for(spec, args.min_agree):
                failed = True
            rows.append(f"| `{spec}` | {threads} | {what} | {ss} | {sm} | {ratio} | {ag} |")
            raw.append({"spec": spec, "threads": threads, "results": res, "agree": agree})
            print(rows[-1], flush=True)
    load1 = os.getloadavg()
    header = [
        f"Run {datetime.date.today().isoformat()} on {machine()}; load average "
        f"{load0[0]:.1f} before, {load1[0]:.1f} after; {time.time() - started:.0f} s in all; "
        f"{1 if args.check_only else max(1, args.rounds)} alternating round(s) per scene"
        f"{' (--quick)' if args.quick else ''}.",
        f"Renderers: {raw[0]['results']['shaderbox'].get('renderer', '?') if raw else '?'} vs "
        f"{raw[0]['results']['mesa'].get('renderer', '?') if raw else '?'}.",
        "",
        "| scene | threads | what | shaderbox median (min–max, frames) | Mesa llvmpipe median (min–max, frames) | ratio (rounds' spread) | pixels within 2/255 |",
        "|---|---|---|---|---|---|---|",
    ]
    text = "\n".join(header + rows)
    print()
    print(text)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"machine": machine(), "load": [load0, load1], "scenes": raw}, f, indent=1)
    if args.write_docs and not args.check_only:
        write_docs(text)
    if args.check_only and failed:
        print(f"FAIL: an image agrees with Mesa's on fewer than {args.min_agree} % of its pixels")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
