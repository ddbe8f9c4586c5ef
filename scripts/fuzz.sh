#!/usr/bin/env bash
# Builds the cargo-fuzz targets under fuzz/ and runs each in turn for a
# fixed time, on one core, with its seed corpus and dictionary.
#
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]
#
# SECONDS_PER_TARGET defaults to 60; the targets default to all of them
# (preprocess compile shader_test pdb mmcif gl_calls). Per target it prints
# the executions, the corpus size and the crashes found (libFuzzer's
# artifacts: crash-*, timeout-*, oom-*, leak-*, in fuzz/artifacts/TARGET/),
# then a summary; the exit status is non-zero when any target found one,
# or when the build fails. libFuzzer's slow-unit-* files (an input that
# took over 10 s, written for information) are counted apart: on a loaded
# machine, or under nice, they are usually the scheduler's doing; rerun
# one alone to see.
#
# What each run reads and writes:
# - fuzz/corpus/TARGET/: the seed corpus, in git (small, hand-made or from
#   the project's own files; scripts/fuzz-corpus.sh rebuilds `compile`'s);
# - fuzz/corpus/piglit*/: seeds taken from piglit by scripts/fuzz-corpus.sh
#   when piglit has been fetched (git-ignored: piglit's files);
# - fuzz/corpus-run/TARGET/: the corpus the runs grow, kept between runs
#   and git-ignored (minimize it with libFuzzer's -merge=1 before adding
#   anything from it to the seeds);
# - fuzz/dict/TARGET.dict (the GLSL targets share glsl.dict).
#
# Environment: FUZZ_TARGET_DIR (cargo-fuzz's target directory, default
# fuzz/target), FUZZ_TIMEOUT (seconds one input may take before libFuzzer
# reports a timeout, default 20), FUZZ_RSS_MB (memory limit, default 2048).
# Needs the nightly toolchain and cargo-fuzz (`rustup toolchain install
# nightly --profile minimal`, `cargo install cargo-fuzz --locked`).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
all_targets=(preprocess compile shader_test pdb mmcif gl_calls)
seconds="${1:-60}"
[ $# -gt 0 ] && shift
case "$seconds" in
    '' | *[!0-9]*) echo "usage: scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]" >&2; exit 2 ;;
esac
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=("${all_targets[@]}")
for t in "${targets[@]}"; do
    case " ${all_targets[*]} " in
        *" $t "*) ;;
        *) echo "unknown target '$t' (targets: ${all_targets[*]})" >&2; exit 2 ;;
    esac
done
target_dir="${FUZZ_TARGET_DIR:-$root/fuzz/target}"
timeout="${FUZZ_TIMEOUT:-20}"
rss="${FUZZ_RSS_MB:-2048}"

# Release with debug assertions and overflow checks: an overflow the
# release build would wrap silently is a finding too.
# `cargo fuzz build` builds one target or all of them.
if [ ${#targets[@]} -eq ${#all_targets[@]} ]; then
    (cd "$root/fuzz" && cargo +nightly fuzz build -O -a --target-dir "$target_dir")
else
    for t in "${targets[@]}"; do
        (cd "$root/fuzz" && cargo +nightly fuzz build -O -a --target-dir "$target_dir" "$t")
    done
fi
bin_dir="$target_dir/x86_64-unknown-linux-gnu/release"

# Seed folders and the longest input per target.
seeds_of() {
    case "$1" in
        preprocess | compile) echo "fuzz/corpus/$1 fuzz/corpus/$([ "$1" = compile ] && echo preprocess || echo compile) fuzz/corpus/piglit" ;;
        shader_test) echo "fuzz/corpus/shader_test fuzz/corpus/piglit-shader_test" ;;
        *) echo "fuzz/corpus/$1" ;;
    esac
}
max_len_of() {
    case "$1" in
        pdb | mmcif) echo 40000 ;;
        gl_calls) echo 2048 ;;
        *) echo 8192 ;;
    esac
}
dict_of() {
    case "$1" in
        preprocess | compile) echo fuzz/dict/glsl.dict ;;
        *) echo "fuzz/dict/$1.dict" ;;
    esac
}

cd "$root"
summary=()
found=0
for t in "${targets[@]}"; do
    run="fuzz/corpus-run/$t"
    artifacts="fuzz/artifacts/$t"
    mkdir -p "$run" "$artifacts"
    seeds=()
    for d in $(seeds_of "$t"); do
        [ -d "$d" ] && seeds+=("$d")
    done
    findings() { find "$artifacts" -type f ! -name 'slow-unit-*' | wc -l; }
    slow_before="$(find "$artifacts" -type f -name 'slow-unit-*' | wc -l)"
    before="$(findings)"
    log="$(mktemp)"
    echo "=== $t: ${seconds}s, corpus $run (seeds: ${seeds[*]}), dictionary $(dict_of "$t")"
    set +e
    "$bin_dir/$t" "$run" "${seeds[@]}" \
        -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb="$rss" \
        -max_len="$(max_len_of "$t")" -dict="$(dict_of "$t")" \
        -artifact_prefix="$artifacts/" -print_final_stats=1 >"$log" 2>&1
    rc=$?
    set -e
    execs="$(awk '/stat::number_of_executed_units:/ { print $2 }' "$log" | tail -n 1)"
    corpus="$(find "$run" -type f | wc -l)"
    new=$(($(findings) - before))
    slow=$(($(find "$artifacts" -type f -name 'slow-unit-*' | wc -l) - slow_before))
    if [ "$rc" -ne 0 ] || [ "$new" -gt 0 ]; then
        found=1
        grep -E '^(==[0-9]+==ERROR|SUMMARY|thread .* panicked|.*(deadly signal|Test unit written|ALARM|out-of-memory))' "$log" | head -n 20 || true
        echo "log: $log"
    else
        rm -f "$log"
    fi
    line="$t: ${seconds}s, ${execs:-?} executions, corpus $corpus, crashes $new, slow units $slow (exit $rc)"
    echo "$line"
    summary+=("$line")
done
echo "=== summary"
printf '%s\n' "${summary[@]}"
if [ "$found" -ne 0 ]; then
    echo "crashes found: see fuzz/artifacts/ (reproduce: $bin_dir/TARGET ARTIFACT)"
    exit 1
fi
