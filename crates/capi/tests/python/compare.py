"""Differential run: a PyOpenGL script on shaderbox's libOSMesa and on Mesa's.

Usage: python3 compare.py LIBDIR SCRIPT.py
LIBDIR holds shaderbox's libOSMesa.so (e.g. target/release). The script must
write its RGBA pixels to the path given as its first argument. Prints the
fraction of pixels within 2/255, the max difference and PSNR; exits 1 when the
issue-4 bar (>= 99.5% within 2/255, none off by more than 8/255) is missed.
"""
import math
import os
import subprocess
import sys
import tempfile


def run(script, out, libdir):
    env = dict(os.environ, PYOPENGL_PLATFORM="osmesa")
    env.pop("LD_LIBRARY_PATH", None)
    if libdir:
        env["LD_LIBRARY_PATH"] = libdir
    r = subprocess.run([sys.executable, script, out], env=env, capture_output=True, text=True)
    if r.returncode != 0:
        sys.stderr.write(r.stdout + r.stderr)
    return r.returncode


def main():
    libdir, script = os.path.abspath(sys.argv[1]), sys.argv[2]
    with tempfile.TemporaryDirectory() as d:
        a, b = os.path.join(d, "shaderbox.bin"), os.path.join(d, "mesa.bin")
        if run(script, a, libdir) or run(script, b, None):
            print("FAIL: a run failed")
            return 1
        x, y = open(a, "rb").read(), open(b, "rb").read()
    if len(x) != len(y) or not x:
        print("FAIL: sizes differ", len(x), len(y))
        return 1
    n = len(x) // 4
    diffs = [abs(p - q) for p, q in zip(x, y)]
    close = sum(1 for i in range(n) if max(diffs[4 * i:4 * i + 4]) <= 2)
    mx = max(diffs)
    mse = sum(v * v for v in diffs) / len(diffs)
    psnr = float("inf") if mse == 0 else 10 * math.log10(255 * 255 / mse)
    ok = close / n >= 0.995 and mx <= 8
    print(f"{os.path.basename(script)}: {close / n:.4%} within 2/255, max diff {mx}, PSNR {psnr:.1f} dB: {'PASS' if ok else 'FAIL'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
