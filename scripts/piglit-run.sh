#!/usr/bin/env bash
# Run piglit's GLSL tests against shaderbox, through piglit's own
# framework, and compare with the expected failures.
#
# Usage: scripts/piglit-run.sh [--suite glslparser|shader]
#                              [--folders legacy|glsl3|all] [--debug]
#                              [--bless] [-j JOBS] [--timeout SECONDS]
#
#   --suite     glslparser (default): the compiler tests, run by
#               `shaderbox glslparsertest`; shader: the execution tests
#               (.shader_test files), run by `shaderbox shader-runner`
#   --folders   which of piglit's spec/ folders (scripts/piglit-sets.sh):
#               legacy (default): glsl-1.10 and glsl-1.20 (glslparser 1678
#               tests, shader 3138); glsl3: glsl-1.30, 1.40, 1.50, 3.30,
#               arb_geometry_shader4, arb_explicit_attrib_location,
#               arb_uniform_buffer_object, arb_arrays_of_arrays,
#               arb_shading_language_packing and arb_texture_cube_map_array
#               (glslparser 3771, shader 3744); all: both, run
#               once and compared set by set. The number of tests is taken
#               from piglit's test list and checked against the results.
#   --debug     build and test the debug binary (default: release)
#   --bless     rewrite the set's expected-failures list to the current
#               failures (crashes and timeouts are never blessed)
#   -j JOBS     concurrent tests (default: number of CPUs)
#   --timeout   seconds per test before piglit calls it a timeout (default 30
#               for glslparser, 60 for shader)
#
# Environment: PIGLIT_CACHE (default .piglit/, see piglit-fetch.sh),
# CARGO_TARGET_DIR, SHADERBOX_BIN (test this binary instead of building).
#
# Needs scripts/piglit-fetch.sh to have run. Exit status: 0 when nothing
# new failed, 1 on a new failure, crash or timeout, 2 on setup problems
# (including a run that does not hold every test of the folders).
#
# Files, per suite and set, named by TAG = SUITE for legacy (the names CI
# has always used) and SUITE-SET otherwise (glslparser-glsl3):
#   tests/piglit/expected-failures-TAG.txt   the expected failures
#   tests/piglit/TAG-counts.txt              counts of the last run, with
#                                            one line per folder
#   $PIGLIT_CACHE/results/TAG/               piglit's results
# An `all` run writes results/SUITE-all/ and compares the legacy and glsl3
# folders each with its own list and counts, exactly as separate runs would.
#
# How piglit is driven: a PIGLIT_BUILD_DIR-style directory whose
# bin/glslparsertest runs `shaderbox glslparsertest "$@"` and whose
# bin/shader_runner runs `shaderbox shader-runner "$@"`, with piglit's
# tests/ and generated_tests/ linked in; `piglit run glslparser` or
# `piglit run shader` with the test names filtered to the set's folders
# (spec@glsl-1.10@...); the results JSON is then read by
# scripts/piglit_compare.py, which writes the counts.

set -euo pipefail

root_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cache="${PIGLIT_CACHE:-$root_dir/.piglit}"
data="$cache/root/usr/lib/x86_64-linux-gnu/piglit"
runner="$cache/root/usr/bin/piglit"
# shellcheck source=piglit-sets.sh
. "$root_dir/scripts/piglit-sets.sh"

suite=glslparser
set=legacy
profile=release
bless=()
jobs="$(nproc 2>/dev/null || echo 2)"
timeout=
while [ $# -gt 0 ]; do
    case "$1" in
        --suite) suite="$2"; shift ;;
        --suite=*) suite="${1#--suite=}" ;;
        --folders) set="$2"; shift ;;
        --folders=*) set="${1#--folders=}" ;;
        --debug) profile=debug ;;
        --release) profile=release ;;
        --bless) bless=(--bless) ;;
        -j) jobs="$2"; shift ;;
        -j*) jobs="${1#-j}" ;;
        --timeout) timeout="$2"; shift ;;
        -h|--help) sed -n '2,/^$/p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "piglit-run: unknown argument \`$1'" >&2; exit 2 ;;
    esac
    shift
done

log() { printf 'piglit-run: %s\n' "$*" >&2; }

case "$suite" in
    glslparser) default_timeout=30 ;;
    shader) default_timeout=60 ;;
    *) log "unknown suite \`$suite' (glslparser or shader)"; exit 2 ;;
esac
timeout="${timeout:-$default_timeout}"
folders_line="$(piglit_folders "$set")" || {
    log "unknown folder set \`$set' (legacy, glsl3 or all)"
    exit 2
}
read -r -a folders <<<"$folders_line"
# The sets compared, each with its own list and counts.
case "$set" in
    all) compared=(legacy glsl3) ;;
    *) compared=("$set") ;;
esac
tag="$(piglit_tag "$suite" "$set")"

[ -x "$runner" ] && [ -d "$data/framework" ] || {
    log "piglit is not fetched yet: run scripts/piglit-fetch.sh first"
    exit 2
}
for f in "${folders[@]}"; do
    piglit_fetched "$data" "$f" || {
        log "piglit's $f tests are not fetched yet: run scripts/piglit-fetch.sh"
        exit 2
    }
done
profile_list="$data/tests/$suite.xml.gz"
ntests="$(/usr/bin/python3 "$root_dir/scripts/piglit_compare.py" --count-profile "$profile_list" \
    --folders "$(piglit_prefixes "${folders[@]}")")" || exit 2

# 1. The binary under test.
if [ -n "${SHADERBOX_BIN:-}" ]; then
    bin="$SHADERBOX_BIN"
else
    target_dir="${CARGO_TARGET_DIR:-$root_dir/target}"
    if [ "$profile" = release ]; then
        (cd "$root_dir" && cargo build --quiet --release -p shaderbox-cli)
    else
        (cd "$root_dir" && cargo build --quiet -p shaderbox-cli)
    fi
    bin="$target_dir/$profile/shaderbox"
fi
[ -x "$bin" ] || { log "no shaderbox binary at $bin"; exit 2; }
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"

# 2. The PIGLIT_BUILD_DIR piglit's framework looks into.
build="$cache/build"
mkdir -p "$build/bin"
ln -sfn "$data/tests" "$build/tests"
ln -sfn "$data/generated_tests" "$build/generated_tests"
cat >"$build/bin/glslparsertest" <<EOF
#!/bin/sh
exec "$bin" glslparsertest "\$@"
EOF
cat >"$build/bin/shader_runner" <<EOF
#!/bin/sh
# piglit already runs one test per core: one thread per test process.
export SHADERBOX_THREADS="\${SHADERBOX_THREADS:-1}"
exec "$bin" shader-runner "\$@"
EOF
chmod +x "$build/bin/glslparsertest" "$build/bin/shader_runner"

# 3. Run. Fast skipping needs waffle's wflinfo to ask a GL driver for its
# versions; without it every test would be skipped, so it is disabled and
# the programs decide skips themselves. No core dumps from crashing tests.
results="$cache/results/$tag"
mkdir -p "$(dirname "$results")"
level=dummy
[ -t 1 ] && [ -z "${CI:-}" ] && level=quiet
mapfile -t filters < <(piglit_filters "${folders[@]}")
log "running $ntests $suite tests of ${folders[*]} ($profile build, $jobs jobs, ${timeout}s timeout)"
ulimit -c 0
start=$(date +%s.%N)
(
    cd "$cache"
    PIGLIT_BUILD_DIR="$build" PIGLIT_NO_FAST_SKIP=1 PYTHONWARNINGS=ignore \
        /usr/bin/python3 "$runner" run "$suite" "${filters[@]}" \
        -c -j "$jobs" --timeout "$timeout" -l "$level" -n shaderbox -o "$results"
) >"$cache/results/$tag.log" 2>&1 || {
    cat "$cache/results/$tag.log" >&2
    log "piglit itself failed (see above)"
    exit 2
}
end=$(date +%s.%N)
elapsed=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }')

# 4. Compare with the expected failures, set by set. The worst status wins
# (2 over 1 over 0).
status=0
for s in "${compared[@]}"; do
    t="$(piglit_tag "$suite" "$s")"
    read -r -a set_folders <<<"$(piglit_folders "$s")"
    rc=0
    /usr/bin/python3 "$root_dir/scripts/piglit_compare.py" "$results" \
        "$root_dir/tests/piglit/expected-failures-$t.txt" \
        --counts "$root_dir/tests/piglit/$t-counts.txt" --title "$t" \
        --folders "$(piglit_prefixes "${set_folders[@]}")" --profile "$profile_list" \
        --elapsed "$elapsed" "${bless[@]}" || rc=$?
    [ "$rc" -gt "$status" ] && status=$rc
done
exit "$status"
