#!/usr/bin/env bash
# Runs piglit's own shader_runner and glslparsertest binaries (Debian's,
# built against Mesa) on shaderbox through its EGL library, through
# piglit's framework: the drop-in route (LD_LIBRARY_PATH at libEGL.so.1 /
# libGL.so.1 from scripts/egl-libs.sh) or, with --glvnd, the system's
# libglvnd libEGL.so.1 dispatching to shaderbox's vendor library
# (__EGL_VENDOR_LIBRARY_FILENAMES). The results are compared with the
# expected failures of shaderbox's own runners (the same tests must pass).
#
# Usage: scripts/piglit-egl.sh [--suite shader|glslparser] [--glvnd]
#                              [--debug] [-j JOBS] [-t REGEX]...
#
# -t restricts the run to tests matching REGEX (piglit's -t; a subset, not
# compared with the full counts). Counts of a full run go to
# tests/piglit/egl-TAG-counts.txt (egl-glvnd-TAG with --glvnd).
#
# Needs scripts/piglit-fetch.sh and scripts/piglit-mesa.sh's extraction of
# the binaries ($PIGLIT_CACHE/mesa; done here when missing), and libwaffle
# (waffle dlopens libEGL.so.1: Debian's libwaffle-1-0).
set -euo pipefail
root_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cache="${PIGLIT_CACHE:-$root_dir/.piglit}"
data_rel=usr/lib/x86_64-linux-gnu/piglit
data="$cache/root/$data_rel"
# shellcheck source=piglit-sets.sh
. "$root_dir/scripts/piglit-sets.sh"
suite=shader
profile=release
route=egl
jobs="$(nproc 2>/dev/null || echo 2)"
filters=()
while [ $# -gt 0 ]; do
    case "$1" in
        --suite) suite="$2"; shift ;;
        --glvnd) route=egl-glvnd ;;
        --debug) profile=debug ;;
        -j) jobs="$2"; shift ;;
        -t) filters+=(-t "$2"); shift ;;
        *) echo "piglit-egl: unknown argument \`$1'" >&2; exit 2 ;;
    esac
    shift
done
log() { printf 'piglit-egl: %s\n' "$*" >&2; }
[ -d "$data/framework" ] || { log "run scripts/piglit-fetch.sh first"; exit 2; }
mesa="$cache/mesa"
if [ ! -x "$mesa/$data_rel/bin/shader_runner" ]; then
    deb="$(ls -1 "$cache"/debs/piglit_*.deb 2>/dev/null | tail -n 1 || true)"
    [ -n "$deb" ] || { log "no piglit .deb in $cache/debs (run scripts/piglit-fetch.sh)"; exit 2; }
    rm -rf "$mesa" && mkdir -p "$mesa"
    dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$mesa" --wildcards \
        "./$data_rel/bin/shader_runner" "./$data_rel/bin/glslparsertest" "./$data_rel/lib/*"
fi
ldconfig -p | grep -q libwaffle-1 || { log "install libwaffle-1-0 (waffle)"; exit 2; }

libs="$(bash "$root_dir/scripts/egl-libs.sh" "--$profile")"
if [ "$route" = egl-glvnd ]; then
    export __EGL_VENDOR_LIBRARY_FILENAMES="$libs/glvnd/50_shaderbox.json"
    libpath="$libs/glvnd:$mesa/$data_rel/lib"
else
    libpath="$libs:$mesa/$data_rel/lib"
fi

build="$cache/egl-build"
mkdir -p "$build"
ln -sfn "$mesa/$data_rel/bin" "$build/bin"
ln -sfn "$data/tests" "$build/tests"
ln -sfn "$data/generated_tests" "$build/generated_tests"
tag="$(piglit_tag "$suite" legacy)"
results="$cache/results/$route-$tag"
rm -rf "$results"
read -r -a folders <<<"$(piglit_folders legacy)"
[ ${#filters[@]} -gt 0 ] || mapfile -t filters < <(piglit_filters "${folders[@]}")
log "running $suite tests (${filters[*]}) on shaderbox by $route ($profile, $jobs jobs)"
ulimit -c 0
start=$(date +%s)
(
    cd "$cache"
    PIGLIT_BUILD_DIR="$build" PIGLIT_NO_FAST_SKIP=1 PIGLIT_PLATFORM=surfaceless_egl \
        SHADERBOX_THREADS="${SHADERBOX_THREADS:-1}" PYTHONWARNINGS=ignore \
        LD_LIBRARY_PATH="$libpath${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
        /usr/bin/python3 "$cache/root/usr/bin/piglit" run "$suite" "${filters[@]}" \
        -c -j "$jobs" --timeout 120 -l dummy -n "shaderbox-$route" "$results"
) >"$results.log" 2>&1 || { cat "$results.log" >&2; log "piglit itself failed"; exit 2; }
elapsed=$(( $(date +%s) - start ))
if [ "${filters[1]}" = "spec@glsl-1\\.10@" ]; then
    /usr/bin/python3 "$root_dir/scripts/piglit_compare.py" "$results" \
        "$root_dir/tests/piglit/expected-failures-$tag.txt" \
        --counts "$root_dir/tests/piglit/$route-$tag-counts.txt" --title "$route-$tag" \
        --folders "$(piglit_prefixes "${folders[@]}")" --profile "$data/tests/$suite.xml.gz" \
        --elapsed "$elapsed"
else
    /usr/bin/python3 "$root_dir/scripts/piglit_compare.py" "$results" \
        "$root_dir/tests/piglit/expected-failures-$tag.txt" --title "$route-$tag (subset)" --elapsed "$elapsed"
fi
