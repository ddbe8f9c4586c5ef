#!/usr/bin/env bash
# Run piglit's GLSL 1.10/1.20 compiler tests against shaderbox, through
# piglit's own framework, and compare with the expected failures.
#
# Usage: scripts/piglit-run.sh [--debug] [--bless] [-j JOBS] [--timeout SECONDS]
#
#   --debug     build and test the debug binary (default: release)
#   --bless     rewrite tests/piglit/expected-failures-glslparser.txt to the
#               current failures (crashes and timeouts are never blessed)
#   -j JOBS     concurrent tests (default: number of CPUs)
#   --timeout   seconds per test before piglit calls it a timeout (default 30)
#
# Environment: PIGLIT_CACHE (default .piglit/, see piglit-fetch.sh),
# CARGO_TARGET_DIR, SHADERBOX_BIN (test this binary instead of building).
#
# Needs scripts/piglit-fetch.sh to have run. Exit status: 0 when nothing
# new failed, 1 on a new failure, crash or timeout, 2 on setup problems.
#
# How piglit is driven: a PIGLIT_BUILD_DIR-style directory whose
# bin/glslparsertest runs `shaderbox glslparsertest "$@"`, with piglit's
# tests/ and generated_tests/ linked in; `piglit run glslparser` with the
# test names filtered to spec@glsl-1.10@ and spec@glsl-1.20@ (1678 tests);
# the results JSON is then read by scripts/piglit_compare.py.

set -euo pipefail

root_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cache="${PIGLIT_CACHE:-$root_dir/.piglit}"
data="$cache/root/usr/lib/x86_64-linux-gnu/piglit"
runner="$cache/root/usr/bin/piglit"
expected="$root_dir/tests/piglit/expected-failures-glslparser.txt"
counts="$root_dir/tests/piglit/glslparser-counts.txt"

profile=release
bless=()
jobs="$(nproc 2>/dev/null || echo 2)"
timeout=30
while [ $# -gt 0 ]; do
    case "$1" in
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

[ -x "$runner" ] && [ -d "$data/framework" ] || {
    log "piglit is not fetched yet: run scripts/piglit-fetch.sh first"
    exit 2
}

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
chmod +x "$build/bin/glslparsertest"

# 3. Run. Fast skipping needs waffle's wflinfo to ask a GL driver for its
# versions; without it every test would be skipped, so it is disabled and
# glslparsertest decides skips itself. No core dumps from crashing tests.
results="$cache/results/glslparser"
mkdir -p "$(dirname "$results")"
level=dummy
[ -t 1 ] && [ -z "${CI:-}" ] && level=quiet
log "running 1678 glslparser tests ($profile build, $jobs jobs, ${timeout}s timeout)"
ulimit -c 0
start=$(date +%s.%N)
(
    cd "$cache"
    PIGLIT_BUILD_DIR="$build" PIGLIT_NO_FAST_SKIP=1 PYTHONWARNINGS=ignore \
        /usr/bin/python3 "$runner" run glslparser \
        -t 'spec@glsl-1\.10@' -t 'spec@glsl-1\.20@' \
        -c -j "$jobs" --timeout "$timeout" -l "$level" -n shaderbox -o "$results"
) >"$cache/results/glslparser.log" 2>&1 || {
    cat "$cache/results/glslparser.log" >&2
    log "piglit itself failed (see above)"
    exit 2
}
end=$(date +%s.%N)
elapsed=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }')

# 4. Compare with the expected failures.
/usr/bin/python3 "$root_dir/scripts/piglit_compare.py" "$results" "$expected" \
    --counts "$counts" --elapsed "$elapsed" --title glslparser "${bless[@]}"
