#!/usr/bin/env python3
"""Cost per fragment of the sphere scenes, shaderbox beside llvmpipe: the
table at the top of docs/PERFORMANCE.md ("Cost per fragment").

    python3 bench/cost.py [--lib DIR] [--rounds N] [--instructions shaderbox|both]
        [--write-docs]

For each scene (20,000 impostor atoms at 1024², sparse and at protein
density, with shaders/sphere.* and with the seed talk's shaders as
written), one thread each:

- fragments: what a frame rasterizes (bench/scene.py --count-fragments:
  llvmpipe shades every one, as the programs write gl_FragDepth;
  shaderbox drops those its depth bounds reject first);
- ns per fragment: the median frame over the fragments, shaderbox and
  llvmpipe run alternately (--rounds each), and cycles at the clock
  /proc/cpuinfo reports (the guest's nominal clock: hardware counters
  are not available on the shared VMs);
- with --instructions, exact instructions per fragment from valgrind's
  callgrind (bench/instructions.py; a run of two frames less a run of
  one, so set-up drops out): shaderbox's in all, in its own code
  (rasterization, interpolation, depth tests, batches) and in generated
  code (the shaders' native code); llvmpipe's in all and in generated
  code (its whole fragment pipeline is generated);
- the arithmetic limit: shaderbox's generated instructions per fragment
  at 4 a cycle (Zen 2's sustained width), the cycles a fragment would
  take if nothing but the shader's own instructions ran, at full width.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import instructions  # noqa: E402
import run  # noqa: E402

BEGIN = "<!-- bench/cost.py: begin (generated, do not edit by hand) -->"
END = "<!-- bench/cost.py: end -->"

SCENES = [
    ("spheres:20000:1024x1024:ortho:none", "sparse, shaders/sphere.*"),
    ("spheres:20000:1024x1024:ortho:none:seed", "sparse, the seed's shaders"),
    ("spheres:20000:1024x1024:ortho:none:dense", "protein density, shaders/sphere.*"),
    ("spheres:20000:1024x1024:ortho:none:dense:seed", "protein density, the seed's shaders"),
]
# Instructions a Zen 2 core sustains per cycle at best.
ISSUE_WIDTH = 4


def clock_ghz():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("cpu MHz"):
                    return float(line.split(":", 1)[1]) / 1000.0
    except (OSError, ValueError):
        pass
    return None


def timed(spec, libdir, rounds, frames):
    """{impl: (median frame seconds, fragments)} over alternating rounds."""
    times = {"shaderbox": [], "llvmpipe": []}
    fragments = {}
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "px.bin")
        for _ in range(rounds):
            for impl in times:
                r = run.run_scene(spec, impl, libdir, 1, frames, 30.0, out, ["--count-fragments"])
                if "error" in r:
                    raise SystemExit(f"{spec}: {r['error']}")
                times[impl].extend(r["times"])
                fragments[impl] = r["fragments"]
    if abs(fragments["shaderbox"] - fragments["llvmpipe"]) > 0.001 * fragments["llvmpipe"]:
        print(f"note: {spec}: fragment counts differ: {fragments}", file=sys.stderr)
    return {impl: (statistics.median(t), fragments[impl]) for impl, t in times.items()}


def counted(spec, libdir, fragments):
    """Instructions per fragment of one frame under callgrind: (all, own
    code, generated code) for the library in `libdir` (None: Mesa). The
    run with one frame more, less the run with the warm-up frame alone,
    so that set-up (the scene's Python, compiling) drops out."""
    def run_frames(frames):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "callgrind.out")
            instructions.run_callgrind(spec, libdir, frames, out)
            costs = instructions.self_costs(out)
        totals = {fn: sum(c.values()) for fn, c in costs.items()}
        own = sum(n for fn, n in totals.items() if instructions.is_ours(fn))
        generated = sum(n for fn, n in totals.items() if instructions.is_generated(fn))
        return sum(totals.values()), own, generated

    one, two = run_frames(0), run_frames(1)
    return tuple((b - a) / fragments for a, b in zip(one, two))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lib", help="directory of shaderbox's libOSMesa.so (default: build it)")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--frames", type=int, default=3)
    ap.add_argument("--only", action="append",
                    help="a scene's spec, or a part of specs (repeatable): only those")
    ap.add_argument("--instructions", choices=["shaderbox", "both"],
                    help="also count instructions with callgrind (slow: llvmpipe's dense "
                         "scenes take most of an hour), of shaderbox or of both")
    ap.add_argument("--write-docs", action="store_true")
    args = ap.parse_args()
    libdir = run.build(args.lib)
    ghz = clock_ghz()
    rows = []
    for spec, what in SCENES:
        exact = [o for o in args.only or [] if o in (sc for sc, _ in SCENES)]
        if args.only and not (spec in exact or any(o in spec for o in args.only if o not in exact)):
            continue
        t = timed(spec, libdir, args.rounds, args.frames)
        (sb, n), (lp, _) = t["shaderbox"], t["llvmpipe"]
        ns_sb, ns_lp = 1e9 * sb / n, 1e9 * lp / n
        cyc = (lambda ns: f"{ns * ghz:.0f}") if ghz else (lambda ns: "n/a")
        row = [f"`{spec}`", what, f"{n / 1e6:.2f} M", f"{ns_sb:.1f} ({cyc(ns_sb)})",
               f"{ns_lp:.1f} ({cyc(ns_lp)})", f"{sb / lp:.2f}×"]
        if args.instructions:
            all_sb, own_sb, gen_sb = counted(spec, libdir, n)
            mesa = "not counted"
            if args.instructions == "both":
                all_lp, _, gen_lp = counted(spec, None, n)
                mesa = f"{all_lp:.0f} ({gen_lp:.0f} generated)"
            row += [f"{all_sb:.0f} = {own_sb:.0f} own + {gen_sb:.0f} generated + {all_sb - own_sb - gen_sb:.0f} other",
                    mesa, f"{gen_sb / ISSUE_WIDTH:.0f}"]
        rows.append(row)
        print(" | ".join(row), flush=True)
    head = ["scene", "what", "fragments / frame", "shaderbox ns (cycles) / fragment",
            "llvmpipe ns (cycles) / fragment", "ratio"]
    if args.instructions:
        head += ["shaderbox instructions / fragment", "llvmpipe instructions / fragment",
                 "arithmetic limit, cycles / fragment"]
    load = os.getloadavg()[0]
    text = "\n".join([
        f"Run on {run.machine()}, clock {ghz:.2f} GHz as /proc/cpuinfo reports it, "
        f"load average {load:.1f} at the end; one thread each, medians of {args.rounds} "
        f"alternating rounds. `python3 bench/cost.py"
        f"{' --instructions ' + args.instructions if args.instructions else ''}` regenerates it.",
        "",
        "| " + " | ".join(head) + " |",
        "|" + "---|" * len(head),
        *["| " + " | ".join(r) + " |" for r in rows],
    ])
    print(text)
    if args.write_docs:
        doc = run.DOC
        with open(doc) as f:
            s = f.read()
        block = f"{BEGIN}\n{text}\n{END}"
        if BEGIN in s and END in s:
            head_, rest = s.split(BEGIN, 1)
            s = head_ + block + rest.split(END, 1)[1]
        else:
            raise SystemExit(f"{doc} has no {BEGIN} marker")
        with open(doc, "w") as f:
            f.write(s)


if __name__ == "__main__":
    main()
