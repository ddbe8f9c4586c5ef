#!/usr/bin/env bash
# Rebuilds fuzz/corpus/compile/ from the project's own shaders (golden,
# seed and example shaders) and, when piglit has been fetched, a sample of
# piglit's GLSL compiler tests (1.10 to 3.30) for the compile and
# preprocess targets and of its .shader_test files for the shader_test
# target. The other targets' seeds (fuzz/corpus/TARGET/) are hand-made
# and kept in git as they are. Each corpus file is one
# control byte (bits 0-1: 0 = vertex, 1 = fragment, 2 = geometry,
# 3 = compute; 0x40 and 0x41 the tessellation control and evaluation
# stages; the other bits as fuzz/fuzz_targets/common/control.rs reads
# them, left 0 here: a compatibility context, default version 1.10)
# followed by the shader text.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$root/fuzz/corpus/compile"
# piglit's tests are not ours to commit: they go to a git-ignored folder
# that a run names after the main corpus.
piglit_out="$root/fuzz/corpus/piglit"
piglit_tests_out="$root/fuzz/corpus/piglit-shader_test"
mkdir -p "$out" "$piglit_out"
add() {
    local f="$1" byte
    case "$f" in
        *.vert) byte='\000' ;;
        *.frag) byte='\001' ;;
        *.geom) byte='\002' ;;
        *.comp) byte='\003' ;;
        *.tesc) byte='\100' ;;
        *.tese) byte='\101' ;;
        *) return ;;
    esac
    local name
    name="$(sha1sum "$f" | cut -c1-16)"
    { printf "$byte"; cat "$f"; } >"${2:-$out}/$name"
}
while IFS= read -r -d '' f; do add "$f"; done < <(find "$root/crates/glsl/tests" "$root/examples" "$root/fuzz/seeds" \( -name '*.vert' -o -name '*.frag' -o -name '*.geom' -o -name '*.comp' -o -name '*.tesc' -o -name '*.tese' \) -print0)
piglit="${PIGLIT_CACHE:-$root/.piglit}/root/usr/lib/x86_64-linux-gnu/piglit/tests/spec"
if [ -d "$piglit" ]; then
    # 400 per version folder that is present, in a fixed order.
    for v in glsl-1.10 glsl-1.20 glsl-1.30 glsl-1.40 glsl-1.50 glsl-3.30 \
        arb_shading_language_420pack arb_compute_shader arb_shader_storage_buffer_object \
        arb_tessellation_shader; do
        [ -d "$piglit/$v" ] || continue
        while IFS= read -r -d '' f; do add "$f" "$piglit_out"; done < <(find "$piglit/$v" \( -name '*.vert' -o -name '*.frag' -o -name '*.geom' -o -name '*.comp' -o -name '*.tesc' -o -name '*.tese' \) -print0 | sort -z | head -z -n 400)
    done
    # 150 execution tests per version folder, the smallest first (under
    # 4 KB: the target's inputs stay short), in a fixed order.
    mkdir -p "$piglit_tests_out"
    for v in glsl-1.10 glsl-1.20 glsl-1.30 glsl-1.40 glsl-1.50 glsl-3.30; do
        [ -d "$piglit/$v/execution" ] || continue
        while IFS= read -r -d '' f; do
            cp "$f" "$piglit_tests_out/$(sha1sum "$f" | cut -c1-16)"
        done < <(find "$piglit/$v/execution" -name '*.shader_test' -size -4k -print0 | sort -z | head -z -n 150)
    done
fi
echo "fuzz corpus: $(ls "$out" | wc -l) files in $out, $(ls "$piglit_out" | wc -l) in $piglit_out, $(ls "$piglit_tests_out" 2>/dev/null | wc -l) in $piglit_tests_out"
