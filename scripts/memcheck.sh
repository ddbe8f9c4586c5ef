#!/usr/bin/env bash
# valgrind memcheck over shaderbox's unsafe code paths: the C-ABI
# differential scenes (crates/capi/tests/python, PyOpenGL on libOSMesa.so)
# and a fixed list of piglit execution tests run by `shaderbox
# shader-runner` (tests/memcheck/piglit-200.txt). One process under
# valgrind at a time.
#
# Usage: scripts/memcheck.sh [--part capi|piglit|all] [--skip N] [--limit N]
#                            [--kernel VARIANT] [--jit-after N]
#                            [--logs DIR] [--no-build]
#
#   --part     which part to run (default all)
#   --skip N   leave out the first N tests of the piglit list (to run a
#              list in parts: --limit 105, then --skip 105)
#   --limit N  only the first N tests of the piglit list (after --skip)
#   --kernel   SHADERBOX_KERNEL for every run (default: the process's own
#              choice, native code where Cranelift runs; valgrind 3.19 runs
#              AVX2 but not AVX-512, so pass portable or avx2 on an
#              AVX-512 machine)
#   --jit-after N
#              SHADERBOX_JIT_AFTER for every run: kernels compile to native
#              code on their Nth run (1: native from the first run; by
#              default the 1,024th, which the C-ABI scenes, mostly 64x64
#              pixels, do not reach)
#   --logs DIR keep valgrind's log of every process in DIR (default: a
#              temporary directory, removed at the end)
#   --no-build use the binaries already in $CARGO_TARGET_DIR/memcheck/
#
# The build: profile `memcheck` (release code, full debug info) without the
# `mimalloc` feature, so every heap block goes through malloc and memcheck
# sees it; in $CARGO_TARGET_DIR/memcheck/, apart from the release build.
#
# What counts as an error: anything memcheck reports (invalid reads and
# writes, uses of uninitialised values, bad frees, overlapping copies) and
# definitely-lost blocks (a leak that grows per call is lost memory;
# memory still reachable at exit is not an error). CPython's own reports
# are suppressed by tests/memcheck/python.supp; a process that fails on
# its own (a scene that raises, a test that crashes) is counted too.
# Prints the errors per process that has any, then one summary line;
# exit status 1 on any error, 2 on setup problems.
#
# Environment: CARGO_TARGET_DIR, PIGLIT_CACHE (default .piglit/, see
# scripts/piglit-fetch.sh), VALGRIND (default valgrind).

set -euo pipefail

root_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
part=all
limit=
skip=0
kernel=
jit_after=
logs=
build=1
while [ $# -gt 0 ]; do
    case "$1" in
        --part) part="$2"; shift ;;
        --limit) limit="$2"; shift ;;
        --skip) skip="$2"; shift ;;
        --kernel) kernel="$2"; shift ;;
        --jit-after) jit_after="$2"; shift ;;
        --logs) logs="$2"; shift ;;
        --no-build) build= ;;
        -h|--help) sed -n '2,/^$/p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "memcheck: unknown argument \`$1'" >&2; exit 2 ;;
    esac
    shift
done
for n in "$skip" ${limit:+"$limit"}; do
    case "$n" in
        '' | *[!0-9]*) echo "memcheck: --skip and --limit take a number, not \`$n'" >&2; exit 2 ;;
    esac
done
case "$part" in
    capi|piglit|all) ;;
    *) echo "memcheck: unknown part \`$part' (capi, piglit or all)" >&2; exit 2 ;;
esac

log() { printf 'memcheck: %s\n' "$*" >&2; }

valgrind="${VALGRIND:-valgrind}"
command -v "$valgrind" >/dev/null || { log "valgrind not found"; exit 2; }
if [ -n "$logs" ]; then
    mkdir -p "$logs"
else
    logs="$(mktemp -d)"
    trap 'rm -rf "$logs"' EXIT
fi
logs="$(cd "$logs" && pwd)"
[ -n "$kernel" ] && export SHADERBOX_KERNEL="$kernel"
[ -n "$jit_after" ] && export SHADERBOX_JIT_AFTER="$jit_after"

target_dir="${CARGO_TARGET_DIR:-$root_dir/target}"
bindir="$target_dir/memcheck"
if [ -n "$build" ]; then
    log "building (profile memcheck, without mimalloc)"
    (cd "$root_dir" && cargo build --quiet --profile memcheck --no-default-features \
        -p shaderbox-cli -p shaderbox-capi) || { log "build failed"; exit 2; }
fi

# --error-exitcode is not used: errors are read from each log's ERROR
# SUMMARY line, so a process's own failure stays distinguishable.
vg_args=(--tool=memcheck --leak-check=full --show-leak-kinds=definite
    --errors-for-leak-kinds=definite --num-callers=30
    "--suppressions=$root_dir/tests/memcheck/python.supp")

processes=0
errors=0
failures=0
bad_lines=()

# vg NAME CMD...: runs CMD under memcheck with its log in $logs/NAME.log
# and its output in $logs/NAME.out; counts its errors; its exit status in
# $vg_rc.
vg_rc=0
vg() {
    local name="$1" n
    shift
    vg_rc=0
    "$valgrind" "${vg_args[@]}" "--log-file=$logs/$name.log" "$@" \
        >"$logs/$name.out" 2>&1 || vg_rc=$?
    processes=$((processes + 1))
    n="$(awk '/ERROR SUMMARY:/ { n = $4 } END { print (n == "" ? -1 : n) }' "$logs/$name.log")"
    if [ "$n" -lt 0 ]; then
        bad_lines+=("$name: no error summary (valgrind itself failed, exit $vg_rc)")
        failures=$((failures + 1))
        return
    fi
    errors=$((errors + n))
    if [ "$n" -gt 0 ]; then bad_lines+=("$name: $n errors (log: $logs/$name.log)"); fi
}

start=$(date +%s)

# ---- the C ABI -------------------------------------------------------------

capi_processes=0
capi_errors=0
capi_scenes=0
if [ "$part" != piglit ]; then
    here="$root_dir/crates/capi/tests/python"
    python3 -c 'import OpenGL' 2>/dev/null || { log "PyOpenGL is missing (pip install PyOpenGL)"; exit 2; }
    # The interpreter itself, not a wrapper script (pyenv's shims are
    # shell scripts, and memcheck would check the shell).
    python="$(python3 -c 'import sys; print(sys.executable)')"
    scripts=(shaded_triangle fixed_function textured_fbo seed_shaders library_shaders
        error_paths pixel_paths uniform_buffers gl33_state)
    # pymalloc off: memcheck then sees CPython's blocks as malloc's and does
    # not report its arena reads as uninitialised.
    export PYTHONMALLOC=malloc
    before=$errors
    for s in "${scripts[@]}"; do
        out="$logs/capi-$s"
        rm -rf "$out"
        PYOPENGL_PLATFORM=osmesa LD_LIBRARY_PATH="$bindir" \
            vg "capi-$s" "$python" "$here/$s.py" "$out"
        # A scene script writes NAME.fail for a scene that raised.
        if [ "$vg_rc" != 0 ] || compgen -G "$out/*.fail" >/dev/null; then
            bad_lines+=("capi-$s: the script failed (exit $vg_rc; see $logs/capi-$s.out and $out)")
            failures=$((failures + 1))
        fi
        # A harness.py script writes a directory of scenes, an older one
        # the pixels of its one scene.
        scenes=1
        [ -d "$out" ] && scenes="$(find "$out" -name '*.rgba' -o -name '*.txt' | sed 's/\.[a-z]*$//' | sort -u | wc -l)"
        capi_scenes=$((capi_scenes + scenes))
        echo "capi $s: $(awk '/ERROR SUMMARY:/ { print $4 }' "$logs/capi-$s.log") errors ($scenes scenes)"
    done
    # The debugger's trace through the C ABI (crates/capi/tests/python/debug_env.sh).
    SHADERBOX_DEBUG_PIXEL=32,24 SHADERBOX_DEBUG_OUT="$logs/capi-debug.trace" \
        PYOPENGL_PLATFORM=osmesa LD_LIBRARY_PATH="$bindir" \
        vg capi-debug "$python" "$here/shaded_triangle.py" "$logs/capi-debug.rgba"
    if [ "$vg_rc" != 0 ] || ! grep -q "at pixel (32, 24): 1 fragment" "$logs/capi-debug.trace" 2>/dev/null; then
        bad_lines+=("capi-debug: no pixel trace (exit $vg_rc)")
        failures=$((failures + 1))
    fi
    echo "capi debug trace: $(awk '/ERROR SUMMARY:/ { print $4 }' "$logs/capi-debug.log") errors"
    unset PYTHONMALLOC
    capi_processes=$processes
    capi_errors=$((errors - before))
fi
capi_end=$(date +%s)

# ---- piglit ----------------------------------------------------------------

piglit_ran=0
piglit_errors=0
declare -A verdicts=()
if [ "$part" != capi ]; then
    cache="${PIGLIT_CACHE:-$root_dir/.piglit}"
    data="$cache/root/usr/lib/x86_64-linux-gnu/piglit"
    [ -d "$data/tests/spec" ] || { log "piglit is not fetched: run scripts/piglit-fetch.sh"; exit 2; }
    mapfile -t tests < <(grep -v '^#' "$root_dir/tests/memcheck/piglit-200.txt" | grep .)
    tests=("${tests[@]:$skip}")
    [ -n "$limit" ] && tests=("${tests[@]:0:$limit}")
    before=$errors
    # One draw thread, as piglit-run.sh runs the tests; the threaded paths
    # are run by the C-ABI part (the context's default thread count).
    export SHADERBOX_THREADS=1
    for t in "${tests[@]}"; do
        [ -f "$data/$t" ] || { log "missing piglit test $t"; exit 2; }
        name="piglit-$(echo "$t" | sed 's|^.*spec/||; s|/|@|g; s|\.shader_test$||')"
        vg "$name" "$bindir/shaderbox" shader-runner "$data/$t" -auto -fbo
        verdict="$(sed -n 's/^PIGLIT: {"result": "\([a-z]*\)".*/\1/p' "$logs/$name.out" | tail -n 1)"
        verdict="${verdict:-none}"
        verdicts[$verdict]=$((${verdicts[$verdict]:-0} + 1))
        # Under valgrind a test may still pass or fail on its own (valgrind
        # ignores MXCSR.DAZ, so native code can see subnormals); a crash is
        # a failure of this check.
        if [ "$verdict" = none ]; then
            bad_lines+=("$name: no piglit verdict (exit $vg_rc; see $logs/$name.out)")
            failures=$((failures + 1))
        fi
        piglit_ran=$((piglit_ran + 1))
    done
    unset SHADERBOX_THREADS
    piglit_errors=$((errors - before))
    v=""
    for k in "${!verdicts[@]}"; do v="$v ${verdicts[$k]} $k,"; done
    echo "piglit: $piglit_ran tests,${v%,}; $piglit_errors errors"
fi
end=$(date +%s)

for l in "${bad_lines[@]}"; do echo "$l"; done
echo "memcheck: $processes processes (C ABI: $capi_processes, $capi_scenes scenes, in $((capi_end - start))s;" \
    "piglit: $piglit_ran in $((end - capi_end))s), $errors errors, $failures failed runs"
[ "$errors" -eq 0 ] && [ "$failures" -eq 0 ]
