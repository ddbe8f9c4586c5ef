#!/usr/bin/env bash
# Builds shaderbox's EGL library and prints the directory a program's
# LD_LIBRARY_PATH names to run on it:
#
#   DIR/libEGL.so.1, DIR/libGL.so.1, DIR/libOpenGL.so.0 (and the
#       unversioned libEGL.so, libGL.so, libOpenGL.so PyOpenGL loads)
#       one file (target/PROFILE/libEGL.so) under all these names;
#   DIR/glvnd/libEGL_shaderbox.so.0, DIR/glvnd/50_shaderbox.json
#       the GLVND vendor library and its JSON, for the system's libglvnd
#       libEGL.so.1: __EGL_VENDOR_LIBRARY_FILENAMES=DIR/glvnd/50_shaderbox.json
#
# Usage: scripts/egl-libs.sh [--debug|--release]   (default --release)
# Environment: CARGO_TARGET_DIR. DIR is TARGET/PROFILE/egl.
set -euo pipefail
root_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
profile=release
case "${1:-}" in
    --debug) profile=debug ;;
    --release|"") profile=release ;;
    *) echo "egl-libs: unknown argument \`$1'" >&2; exit 2 ;;
esac
flag=()
[ "$profile" = release ] && flag=(--release)
(cd "$root_dir" && cargo build --quiet "${flag[@]}" -p shaderbox-egl >&2)
target_dir="${CARGO_TARGET_DIR:-$root_dir/target}"
target_dir="$(cd "$target_dir" && pwd)"
dir="$target_dir/$profile/egl"
mkdir -p "$dir/glvnd"
# PyOpenGL loads the unversioned names (libEGL.so, libOpenGL.so).
for name in libEGL.so.1 libGL.so.1 libOpenGL.so.0 libEGL.so libGL.so libOpenGL.so; do
    ln -sfn ../libEGL.so "$dir/$name"
done
ln -sfn ../../libEGL.so "$dir/glvnd/libEGL_shaderbox.so.0"
cat >"$dir/glvnd/50_shaderbox.json" <<JSON
{
    "file_format_version" : "1.0.0",
    "ICD" : {
        "library_path" : "$dir/glvnd/libEGL_shaderbox.so.0"
    }
}
JSON
echo "$dir"
