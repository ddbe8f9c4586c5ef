#!/usr/bin/env bash
# Runs the same piglit suites on Mesa (llvmpipe, through EGL surfaceless),
# the oracle shaderbox is compared with: counts and wall time, for
# docs/CONFORMANCE.md.
#
# Usage: scripts/piglit-mesa.sh [--suite shader|glslparser]
#                               [--folders legacy|glsl3|all] [-j JOBS]
#
# --folders chooses the same tests as scripts/piglit-run.sh's (default
# legacy: GLSL 1.10 and 1.20; see scripts/piglit-sets.sh). The counts, with
# one line per folder, go to tests/piglit/mesa-TAG-counts.txt (TAG as in
# piglit-run.sh: glslparser, glslparser-glsl3...; an `all` run writes the
# legacy and glsl3 files), written by scripts/piglit_compare.py
# --summary-only; the tests Mesa neither passes nor skips are listed.
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
# shellcheck source=piglit-sets.sh
. "$root_dir/scripts/piglit-sets.sh"
suite=shader
set=legacy
jobs="$(nproc 2>/dev/null || echo 2)"
while [ $# -gt 0 ]; do
    case "$1" in
        --suite) suite="$2"; shift ;;
        --folders) set="$2"; shift ;;
        -j) jobs="$2"; shift ;;
        *) echo "piglit-mesa: unknown argument \`$1'" >&2; exit 2 ;;
    esac
    shift
done
log() { printf 'piglit-mesa: %s\n' "$*" >&2; }
[ -d "$data/framework" ] || { log "run scripts/piglit-fetch.sh first"; exit 2; }
case "$suite" in glslparser|shader) ;; *) log "unknown suite \`$suite'"; exit 2 ;; esac
folders_line="$(piglit_folders "$set")" || { log "unknown folder set \`$set' (legacy, glsl3 or all)"; exit 2; }
read -r -a folders <<<"$folders_line"
for f in "${folders[@]}"; do
    piglit_fetched "$data" "$f" || { log "piglit's $f tests are not fetched yet: run scripts/piglit-fetch.sh"; exit 2; }
done
case "$set" in all) compared=(legacy glsl3) ;; *) compared=("$set") ;; esac
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
results="$cache/results/mesa-$(piglit_tag "$suite" "$set")"
rm -rf "$results"
mapfile -t filters < <(piglit_filters "${folders[@]}")
log "running $suite tests of ${folders[*]} on Mesa ($jobs jobs)"
start=$(date +%s)
PIGLIT_BUILD_DIR="$build" PIGLIT_NO_FAST_SKIP=1 PIGLIT_PLATFORM=surfaceless_egl \
    LD_LIBRARY_PATH="$mesa/$data_rel/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
    /usr/bin/python3 "$cache/root/usr/bin/piglit" run "$suite" \
    "${filters[@]}" -c -j "$jobs" --timeout 120 "$results" >/dev/null 2>&1 || true
elapsed=$(( $(date +%s) - start ))
status=0
for s in "${compared[@]}"; do
    t="$(piglit_tag "$suite" "$s")"
    read -r -a set_folders <<<"$(piglit_folders "$s")"
    rc=0
    /usr/bin/python3 "$root_dir/scripts/piglit_compare.py" "$results" --summary-only \
        --title "mesa-$t" --counts "$root_dir/tests/piglit/mesa-$t-counts.txt" \
        --folders "$(piglit_prefixes "${set_folders[@]}")" --profile "$data/tests/$suite.xml.gz" \
        --elapsed "$elapsed" || rc=$?
    [ "$rc" -gt "$status" ] && status=$rc
done
exit "$status"
