#!/usr/bin/env bash
# Builds shaderbox's libOSMesa.so and prints the directory a program's
# LD_LIBRARY_PATH names to run on it under every name OSMesa programs
# load: DIR/libOSMesa.so, DIR/libOSMesa.so.8 (Mesa's current SONAME: VTK's
# vtkOSOpenGLRenderWindow and GLFW's OSMesa back end dlopen that one) and
# DIR/libOSMesa.so.6 (older Mesa), one file under all three names.
#
# Usage: scripts/osmesa-libs.sh [--debug|--release]   (default --release)
# Environment: CARGO_TARGET_DIR. DIR is TARGET/PROFILE/osmesa.
set -euo pipefail
root_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
profile=release
case "${1:-}" in
    --debug) profile=debug ;;
    --release|"") profile=release ;;
    *) echo "osmesa-libs: unknown argument \`$1'" >&2; exit 2 ;;
esac
flag=()
[ "$profile" = release ] && flag=(--release)
(cd "$root_dir" && cargo build --quiet "${flag[@]}" -p shaderbox-capi >&2)
target_dir="${CARGO_TARGET_DIR:-$root_dir/target}"
target_dir="$(cd "$target_dir" && pwd)"
dir="$target_dir/$profile/osmesa"
mkdir -p "$dir"
for name in libOSMesa.so libOSMesa.so.8 libOSMesa.so.6; do
    ln -sfn ../libOSMesa.so "$dir/$name"
done
echo "$dir"
