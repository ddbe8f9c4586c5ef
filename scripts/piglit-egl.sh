#!/usr/bin/env bash
# Runs piglit's own shader_runner and glslparsertest binaries (Debian's,
# built against Mesa) on shaderbox through its EGL library, through
# piglit's framework: the drop-in route (LD_LIBRARY_PATH at libEGL.so.1 /
# libGL.so.1 from scripts/egl-libs.sh) or, with --glvnd, the system's
# libglvnd libEGL.so.1 dispatching to shaderbox's vendor library
# (__EGL_VENDOR_LIBRARY_FILENAMES). The results are compared with the
# expected failures of shaderbox's own runners (the same tests must pass).
#
# --suite opengl runs piglit's C tests (tests/opengl.xml.gz) of the folders
# `spec@!opengl 1.0@` ... `spec@!opengl 2.1@` and of the extensions a 2.1
# context advertises (OPENGL_EXTENSION_FOLDERS below), compared with
# tests/piglit/expected-failures-egl-opengl.txt; the tests of
# tests/piglit/egl-opengl-excluded.txt (piglit's framework aborts them on
# surfaceless_egl whatever the driver) are left out. With --mesa the same
# tests run on Mesa instead (the system's libEGL.so.1 and libGL.so.1, no
# shaderbox library on the path): counts only, for the comparison.
#
# Usage: scripts/piglit-egl.sh [--suite shader|glslparser|opengl] [--glvnd|--mesa]
#                              [--debug] [-j JOBS] [-t REGEX]... [--quick]
#
# --quick (opengl): only the folders of OPENGL_QUICK_FOLDERS, whose tests
# take seconds on shaderbox (311 tests, about 10 s; CI's subset).
#
# -t restricts the run to tests matching REGEX (piglit's -t; a subset, not
# compared with the full counts). Counts of a full run go to
# tests/piglit/egl-TAG-counts.txt (egl-glvnd-TAG with --glvnd, mesa-egl-TAG
# with --mesa).
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
# The opengl suite's folders: GL 1.0-2.1, and the extensions a 2.1 context
# advertises (gl::get::EXTENSIONS and the geometry-shader extensions of
# gl::Api::extensions) that have a folder in the profile.
OPENGL_VERSION_FOLDERS=("!opengl 1.0" "!opengl 1.1" "!opengl 1.2" "!opengl 1.3"
    "!opengl 1.4" "!opengl 1.5" "!opengl 2.0" "!opengl 2.1")
OPENGL_EXTENSION_FOLDERS=(arb_texture_cube_map arb_depth_texture arb_texture_float
    arb_vertex_buffer_object arb_shader_objects arb_draw_buffers arb_point_sprite
    arb_framebuffer_object ext_framebuffer_object ext_texture_lod_bias ext_fog_coord
    sgis_generate_mipmap ext_provoking_vertex arb_vertex_array_object arb_draw_instanced
    arb_instanced_arrays arb_draw_elements_base_vertex arb_half_float_vertex
    arb_vertex_type_2_10_10_10_rev arb_vertex_array_bgra arb_map_buffer_range
    arb_copy_buffer arb_uniform_buffer_object arb_explicit_attrib_location arb_texture_rg
    ext_texture_srgb arb_sampler_objects arb_geometry_shader4)
# The opengl folders whose C tests finish in seconds on shaderbox (the
# others hold tests that upload or draw thousands of times).
OPENGL_QUICK_FOLDERS=("!opengl 1.3" "!opengl 1.5" "!opengl 2.1" arb_texture_cube_map
    arb_depth_texture arb_texture_float arb_shader_objects arb_draw_buffers
    arb_point_sprite arb_framebuffer_object ext_texture_lod_bias ext_fog_coord
    sgis_generate_mipmap ext_provoking_vertex arb_vertex_array_object arb_draw_instanced
    arb_instanced_arrays arb_draw_elements_base_vertex arb_half_float_vertex
    arb_vertex_array_bgra arb_copy_buffer arb_uniform_buffer_object
    arb_explicit_attrib_location arb_texture_rg ext_texture_srgb arb_sampler_objects
    arb_geometry_shader4)
suite=shader
profile=release
route=egl
jobs="$(nproc 2>/dev/null || echo 2)"
filters=()
while [ $# -gt 0 ]; do
    case "$1" in
        --suite) suite="$2"; shift ;;
        --glvnd) route=egl-glvnd ;;
        --mesa) route=mesa-egl ;;
        --debug) profile=debug ;;
        -j) jobs="$2"; shift ;;
        -t) filters+=(-t "$2"); shift ;;
        --quick)
            for f in "${OPENGL_QUICK_FOLDERS[@]}"; do filters+=(-t "spec@${f//./\\.}@"); done ;;
        *) echo "piglit-egl: unknown argument \`$1'" >&2; exit 2 ;;
    esac
    shift
done
log() { printf 'piglit-egl: %s\n' "$*" >&2; }
[ -d "$data/framework" ] || { log "run scripts/piglit-fetch.sh first"; exit 2; }
mesa="$cache/mesa"
deb="$(ls -1 "$cache"/debs/piglit_*.deb 2>/dev/null | tail -n 1 || true)"
if [ ! -x "$mesa/$data_rel/bin/shader_runner" ]; then
    [ -n "$deb" ] || { log "no piglit .deb in $cache/debs (run scripts/piglit-fetch.sh)"; exit 2; }
    rm -rf "$mesa" && mkdir -p "$mesa"
    dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$mesa" --wildcards \
        "./$data_rel/bin/shader_runner" "./$data_rel/bin/glslparsertest" "./$data_rel/lib/*"
fi
# The C tests: every binary (38 MB) and the opengl profile.
if [ "$suite" = opengl ] && [ ! -f "$mesa/.opengl-extracted" ]; then
    [ -n "$deb" ] || { log "no piglit .deb in $cache/debs (run scripts/piglit-fetch.sh)"; exit 2; }
    dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$mesa" --wildcards \
        "./$data_rel/bin/*" "./$data_rel/tests/opengl.xml.gz"
    touch "$mesa/.opengl-extracted"
fi
# grep reads all of ldconfig's output: with -q it may stop early, and
# pipefail would then report ldconfig's SIGPIPE.
ldconfig -p | grep libwaffle-1 >/dev/null || { log "install libwaffle-1-0 (waffle)"; exit 2; }

if [ "$route" = mesa-egl ]; then
    libpath="$mesa/$data_rel/lib"
elif libs="$(bash "$root_dir/scripts/egl-libs.sh" "--$profile")" && [ "$route" = egl-glvnd ]; then
    export __EGL_VENDOR_LIBRARY_FILENAMES="$libs/glvnd/50_shaderbox.json"
    libpath="$libs/glvnd:$mesa/$data_rel/lib"
else
    libpath="$libs:$mesa/$data_rel/lib"
fi

build="$cache/egl-build"
[ "$suite" = opengl ] && build="$cache/egl-build-opengl"
mkdir -p "$build"
ln -sfn "$mesa/$data_rel/bin" "$build/bin"
ln -sfn "$data/generated_tests" "$build/generated_tests"
tag="$(piglit_tag "$suite" legacy)"
results="$cache/results/$route-$tag"
rm -rf "$results"
# A full run is one without -t: its counts are written.
full_run=1
[ ${#filters[@]} -gt 0 ] && full_run=0
excludes=()
if [ "$suite" = opengl ]; then
    # The profile beside the shader and glslparser ones, which stay
    # piglit-fetch.sh's tree.
    tests="$cache/egl-tests"
    mkdir -p "$tests"
    for f in "$data/tests/"*; do ln -sfn "$f" "$tests/"; done
    ln -sfn "$mesa/$data_rel/tests/opengl.xml.gz" "$tests/opengl.xml.gz"
    ln -sfn "$tests" "$build/tests"
    folders=("${OPENGL_VERSION_FOLDERS[@]}" "${OPENGL_EXTENSION_FOLDERS[@]}")
    if [ ${#filters[@]} -eq 0 ]; then
        for f in "${folders[@]}"; do filters+=(-t "spec@${f//./\\.}@"); done
    fi
    # piglit's -x takes a regular expression: each excluded name, escaped
    # and anchored.
    mapfile -t excludes < <(/usr/bin/python3 -c '
import re, sys
for line in open(sys.argv[1]):
    name = line.split(" # ")[0].strip()
    if name and not name.startswith("#"):
        print("-x")
        print("^" + re.escape(name) + "$")
' "$root_dir/tests/piglit/egl-opengl-excluded.txt")
else
    ln -sfn "$data/tests" "$build/tests"
    read -r -a folders <<<"$(piglit_folders legacy)"
    [ ${#filters[@]} -gt 0 ] || mapfile -t filters < <(piglit_filters "${folders[@]}")
fi
log "running $suite tests (${filters[*]}) by $route ($profile, $jobs jobs)"
ulimit -c 0
start=$(date +%s)
(
    cd "$cache"
    PIGLIT_BUILD_DIR="$build" PIGLIT_NO_FAST_SKIP=1 PIGLIT_PLATFORM=surfaceless_egl \
        SHADERBOX_THREADS="${SHADERBOX_THREADS:-1}" PYTHONWARNINGS=ignore \
        LD_LIBRARY_PATH="$libpath${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
        /usr/bin/python3 "$cache/root/usr/bin/piglit" run "$suite" "${filters[@]}" "${excludes[@]}" \
        -c -j "$jobs" --timeout 120 -l dummy -n "shaderbox-$route" "$results"
) >"$results.log" 2>&1 || { cat "$results.log" >&2; log "piglit itself failed"; exit 2; }
elapsed=$(( $(date +%s) - start ))
prefixes="$(printf 'spec@%s@,' "${folders[@]}")"
expected="$root_dir/tests/piglit/expected-failures-$tag.txt"
[ "$suite" = opengl ] && expected="$root_dir/tests/piglit/expected-failures-egl-opengl.txt"
if [ "$route" = mesa-egl ]; then
    summary=(--title "$route-$tag (subset)")
    [ "$full_run" = 1 ] && summary=(--title "$route-$tag" --counts "$root_dir/tests/piglit/$route-$tag-counts.txt")
    /usr/bin/python3 "$root_dir/scripts/piglit_compare.py" "$results" --summary-only \
        "${summary[@]}" --folders "$prefixes" --elapsed "$elapsed"
elif [ "$full_run" = 1 ]; then
    # The opengl runs leave tests out: no check of the profile's total.
    profile_check=(--profile "$build/tests/$suite.xml.gz")
    [ "$suite" = opengl ] && profile_check=()
    /usr/bin/python3 "$root_dir/scripts/piglit_compare.py" "$results" "$expected" \
        --counts "$root_dir/tests/piglit/$route-$tag-counts.txt" --title "$route-$tag" \
        --folders "$prefixes" "${profile_check[@]}" --elapsed "$elapsed"
else
    /usr/bin/python3 "$root_dir/scripts/piglit_compare.py" "$results" \
        "$expected" --title "$route-$tag (subset)" --elapsed "$elapsed"
fi
