#!/usr/bin/env bash
# Rebuilds fuzz/corpus/compile/ from the project's own shaders (golden,
# seed and example shaders) and, when piglit has been fetched, a sample of
# piglit's GLSL 1.10/1.20 compiler tests. Each corpus file is one stage byte
# (0 = vertex, 1 = fragment) followed by the shader text, the input format
# of fuzz/fuzz_targets/compile.rs.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$root/fuzz/corpus/compile"
mkdir -p "$out"
add() {
    local f="$1" byte
    case "$f" in
        *.vert) byte='\000' ;;
        *.frag) byte='\001' ;;
        *) return ;;
    esac
    local name
    name="$(sha1sum "$f" | cut -c1-16)"
    { printf "$byte"; cat "$f"; } >"$out/$name"
}
while IFS= read -r -d '' f; do add "$f"; done < <(find "$root/crates/glsl/tests" "$root/examples" \( -name '*.vert' -o -name '*.frag' \) -print0)
piglit="${PIGLIT_CACHE:-$root/.piglit}/root/usr/lib/x86_64-linux-gnu/piglit/tests/spec"
if [ -d "$piglit" ]; then
    while IFS= read -r -d '' f; do add "$f"; done < <(find "$piglit/glsl-1.10" "$piglit/glsl-1.20" \( -name '*.vert' -o -name '*.frag' \) -print0 | head -z -n 400)
fi
echo "fuzz corpus: $(ls "$out" | wc -l) files in $out"
