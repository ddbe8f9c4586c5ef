#!/usr/bin/env python3
"""Exact instruction counts of one scene, per function and per inlined
source line, from valgrind's callgrind (for machines without hardware
counters, such as the shared VMs the benchmarks run on).

    python3 bench/instructions.py SPEC LIB_DIR [--frames N] [--per N]
        [--function NAME ...] [--lines N]

Runs bench/scene.py on SPEC once under `valgrind --tool=callgrind
--dump-instr=yes` with LD_LIBRARY_PATH=LIB_DIR (a directory holding a
shaderbox libOSMesa.so built with debug info, as the release profile is)
and one thread, then prints:

- the instructions executed in the library's functions, in generated code
  (native shader code, which has no symbol) and in all; then the
  functions of the library with the most instructions executed in
  them (self cost), divided by --per (for instance the number of 16-lane
  batches or of fragments the run drew, to get a cost per unit);
- for each --function (a demangled name as callgrind prints it, e.g.
  `raster::texture_2d::sample_avx2`), its instructions attributed to the
  innermost function of this repository that each instruction was
  inlined from (`addr2line -i`), then to the source line.

Counts are exact and do not depend on the machine's load, which makes
them a steady complement to `bench/ab.py`'s times; but time does not
follow them everywhere (instructions off the critical path can be free),
so a change is kept on its time, not its count. Needs valgrind and
binutils (`addr2line`, `objdump` not needed). The warm-up frame and the
timed frames are all counted: divide by the draws they made (`--per`).
shaderbox's kernels compile to native code on their 1,024th run, on the
drawing thread (`SHADERBOX_JIT_AFTER=1024`, unless set), so every run
counts the same instructions.
"""
import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def run_callgrind(spec, lib, frames, out):
    """Runs the scene once under callgrind with one thread, on the
    libOSMesa.so of directory `lib` (None: the system's, i.e. Mesa's)."""
    env = dict(os.environ, PYOPENGL_PLATFORM="osmesa", SHADERBOX_THREADS="1", LP_NUM_THREADS="1")
    # Kernels compile at their default run count, but on the drawing
    # thread: valgrind runs one thread at a time, and a compiling thread
    # of its own would finish at a different point of each run.
    env.setdefault("SHADERBOX_JIT_AFTER", "1024")
    env.pop("LD_LIBRARY_PATH", None)
    if lib:
        env["LD_LIBRARY_PATH"] = lib
    cmd = ["valgrind", "--tool=callgrind", "--dump-instr=yes",
           f"--callgrind-out-file={out}", sys.executable,
           os.path.join(HERE, "scene.py"), spec, "--frames", str(frames), "--budget", "1"]
    p = subprocess.run(cmd, env=env, capture_output=True, text=True)
    if p.returncode != 0 or not os.path.exists(out):
        raise SystemExit(f"callgrind run failed:\n{p.stderr[-2000:]}")


def is_ours(fn):
    """Whether a callgrind function name is one of this repository's (a
    Rust path outside the standard library)."""
    return "::" in fn and not fn.startswith(("core::", "alloc::", "std::"))


def is_generated(fn):
    """Whether a callgrind function name is generated code: it has no
    symbol, so callgrind names it by its address."""
    return re.fullmatch(r"0x[0-9a-fA-F]+", fn) is not None


def position(token, previous):
    """A callgrind position: absolute, +n / -n relative, or * (same)."""
    if token == "*":
        return previous
    if token.startswith("+"):
        return previous + int(token[1:], 0)
    if token.startswith("-"):
        return previous - int(token[1:], 0)
    return int(token, 0)


def self_costs(path):
    """{function: {address: instructions executed there}} (self cost: the
    inclusive costs of calls are left out) of a `--dump-instr=yes` file."""
    names, costs = {}, collections.defaultdict(collections.Counter)
    current, addr, line, after_call = None, 0, 0, False
    named = re.compile(r"c?fn=\((\d+)\)(?: (.*))?")
    with open(path) as f:
        for raw in f:
            if raw.startswith(("fn=", "cfn=")):
                m = named.match(raw.strip())
                if m and m.group(2):
                    names[m.group(1)] = m.group(2)
                if raw.startswith("fn=") and m:
                    current = names.get(m.group(1), "?")
                continue
            if raw.startswith("calls="):
                after_call = True
                continue
            if not raw or raw[0] not in "0123456789+-*":
                continue
            parts = raw.split()
            if len(parts) < 3:
                continue
            addr, line = position(parts[0], addr), position(parts[1], line)
            if after_call:
                # The inclusive cost of the call on the line before.
                after_call = False
                continue
            costs[current][addr] += int(parts[2])
    return costs


def inlined_from(lib, addresses):
    """{address: [(function, file:line), ...]} innermost first."""
    out = {}
    addresses = list(addresses)
    for start in range(0, len(addresses), 2000):
        chunk = [hex(a) for a in addresses[start:start + 2000]]
        lines = subprocess.run(["addr2line", "-a", "-i", "-f", "-C", "-e", lib] + chunk,
                               capture_output=True, text=True).stdout.splitlines()
        current, i = None, 0
        while i < len(lines):
            if lines[i].startswith("0x"):
                current = int(lines[i], 16)
                out[current] = []
                i += 1
                continue
            loc = lines[i + 1] if i + 1 < len(lines) else ""
            out[current].append((lines[i], loc))
            i += 2
    return out


def print_asm(lib, by_addr, per):
    """The executed instructions of one function, in address order, each
    with its count divided by `per` (needs objdump)."""
    lo, hi = min(by_addr), max(by_addr)
    text = subprocess.run(["objdump", "-d", "--no-show-raw-insn", "-C",
                           f"--start-address={hex(lo)}", f"--stop-address={hex(hi + 1)}", lib],
                          capture_output=True, text=True).stdout
    print("executed instructions")
    for row in text.splitlines():
        m = re.match(r"\s*([0-9a-f]+):\s+(.*)", row)
        if m and int(m.group(1), 16) in by_addr:
            print(f"{by_addr[int(m.group(1), 16)] / per:10.2f}  {m.group(1)}  {m.group(2)}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("spec")
    ap.add_argument("lib_dir")
    ap.add_argument("--frames", type=int, default=2)
    ap.add_argument("--per", type=float, default=1.0,
                    help="divide the counts by this (batches, fragments, ...)")
    ap.add_argument("--function", action="append", default=[])
    ap.add_argument("--lines", type=int, default=25)
    ap.add_argument("--asm", action="store_true",
                    help="also print each --function's executed instructions "
                         "in address order with their counts (objdump)")
    args = ap.parse_args()
    lib = os.path.join(args.lib_dir, "libOSMesa.so")
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "callgrind.out")
        run_callgrind(args.spec, os.path.abspath(args.lib_dir), args.frames, out)
        costs = self_costs(out)
    totals = {fn: sum(c.values()) for fn, c in costs.items()}
    mine = {fn: n for fn, n in totals.items() if is_ours(fn)}
    jit = sum(n for fn, n in totals.items() if is_generated(fn))
    print(f"{args.spec}: instructions per {args.per:g} (self cost)")
    print(f"{sum(mine.values()) / args.per:14.1f}  in this repository's functions")
    print(f"{jit / args.per:14.1f}  in generated code (shaders' native code; named by address)")
    print(f"{sum(totals.values()) / args.per:14.1f}  in all (Python, libc, ... too)")
    for fn, n in sorted(mine.items(), key=lambda kv: -kv[1])[:args.lines]:
        print(f"{n / args.per:14.1f}  {fn}")
    for name in args.function:
        by_addr = costs.get(name)
        if not by_addr:
            print(f"\n{name}: not found")
            continue
        chains = inlined_from(lib, by_addr.keys())
        by_fn, by_line = collections.Counter(), collections.Counter()
        for a, n in by_addr.items():
            ours = [(f, l) for f, l in chains.get(a, []) if ROOT in l]
            f, l = ours[0] if ours else ("?", "?")
            by_fn[re.sub(r"<.*?>", "", f)] += n
            by_line[l.replace(ROOT + "/", "").split(" ")[0]] += n
        print(f"\n{name}: {sum(by_addr.values()) / args.per:.1f} by innermost function")
        for f, n in by_fn.most_common(args.lines):
            print(f"{n / args.per:14.1f}  {f}")
        print("by source line")
        for l, n in by_line.most_common(args.lines):
            print(f"{n / args.per:14.1f}  {l}")
        if args.asm:
            print_asm(lib, by_addr, args.per)


if __name__ == "__main__":
    main()
