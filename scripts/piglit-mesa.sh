#!/usr/bin/env bash
# Runs the same piglit suites on Mesa (llvmpipe, through EGL surfaceless),
# the oracle shaderbox is compared with: counts and wall time, for
# docs/CONFORMANCE.md.
#
# Usage: scripts/piglit-mesa.sh [--suite shader|glslparser] [-j JOBS]
#
# Needs scripts/piglit-fetch.sh first (framework and test data). Extracts
# piglit's own shader_runner and glslparsertest binaries with their
# libraries from the same Debian package into .piglit/mesa/, and installs
# Mesa's runtime (libgl1-mesa-dri, libegl1, libwaffle) when missing.
set -euo pipefail
root_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cache="${PIGLIT_CACHE:-$root_dir/.piglit}"
data_rel=usr/lib/x86_64-linux-gnu/piglit
data="$cache/root/$data_rel"
suite=shader
jobs="$(nproc 2>/dev/null || echo 2)"
while [ $# -gt 0 ]; do
    case "$1" in
        --suite) suite="$2"; shift ;;
        -j) jobs="$2"; shift ;;
        *) echo "piglit-mesa: unknown argument \`$1'" >&2; exit 2 ;;
    esac
    shift
done
log() { printf 'piglit-mesa: %s\n' "$*" >&2; }
[ -d "$data/framework" ] || { log "run scripts/piglit-fetch.sh first"; exit 2; }
deb="$(ls -1 "$cache"/debs/piglit_*.deb 2>/dev/null | tail -n 1 || true)"
[ -n "$deb" ] || { log "no piglit .deb in $cache/debs (run scripts/piglit-fetch.sh)"; exit 2; }

if ! ldconfig -p | grep -q libwaffle-1 || ! ls /usr/lib/x86_64-linux-gnu/dri/swrast_dri.so >/dev/null 2>&1; then
    log "installing Mesa's runtime"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
        libegl1 libgl1 libwaffle-1-0 libgl1-mesa-dri libegl-mesa0 libgles2 libvulkan1 \
        libwayland-client0 libxkbcommon0 ocl-icd-libopencl1 >/dev/null
fi
mesa="$cache/mesa"
if [ ! -x "$mesa/$data_rel/bin/shader_runner" ]; then
    log "extracting piglit's runners from $(basename "$deb")"
    rm -rf "$mesa" && mkdir -p "$mesa"
    dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$mesa" --wildcards \
        "./$data_rel/bin/shader_runner" "./$data_rel/bin/glslparsertest" "./$data_rel/lib/*"
fi
build="$cache/mesa-build"
mkdir -p "$build"
ln -sfn "$mesa/$data_rel/bin" "$build/bin"
ln -sfn "$data/tests" "$build/tests"
ln -sfn "$data/generated_tests" "$build/generated_tests"
results="$cache/results/mesa-$suite"
rm -rf "$results"
start=$(date +%s)
PIGLIT_BUILD_DIR="$build" PIGLIT_NO_FAST_SKIP=1 PIGLIT_PLATFORM=surfaceless_egl \
    LD_LIBRARY_PATH="$mesa/$data_rel/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
    /usr/bin/python3 "$cache/root/usr/bin/piglit" run "$suite" \
    -t 'spec@glsl-1\.10@' -t 'spec@glsl-1\.20@' -c -j "$jobs" --timeout 120 "$results" >/dev/null 2>&1 || true
elapsed=$(( $(date +%s) - start ))
/usr/bin/python3 - "$results" "$elapsed" <<'PY'
import bz2, collections, glob, json, os, sys
res, elapsed = sys.argv[1], sys.argv[2]
path = (glob.glob(os.path.join(res, "results.json*")) or [None])[0]
if path is None:
    sys.exit("piglit-mesa: no results written")
opener = bz2.open if path.endswith(".bz2") else open
tests = json.load(opener(path, "rt"))["tests"]
c = collections.Counter(t["result"] for t in tests.values())
print(f"mesa {os.path.basename(res)[5:]}: {len(tests)} tests: " + ", ".join(f"{n} {k}" for k, n in sorted(c.items())) + f"; run took {elapsed} s")
for name, t in sorted(tests.items()):
    if t["result"] not in ("pass", "skip"):
        print(f"  {name} [{t['result']}]")
PY
