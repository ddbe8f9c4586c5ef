#!/bin/sh
# Differential suite: every scene script here on shaderbox's libOSMesa and on
# Mesa's (Debian libosmesa6), compared by compare.py (images within the
# issue-4 bar, logs of error codes/statuses equal). Needs python3 + PyOpenGL.
#   crates/capi/tests/python/run_all.sh [LIBDIR [MARKDOWN]]
#   crates/capi/tests/python/run_all.sh --egl [EGLDIR]
# LIBDIR defaults to target/release (built first); with MARKDOWN, a
# table row per scene is appended to that file. --egl runs the harness
# scenes on PyOpenGL's EGL platform instead: shaderbox's libEGL.so.1
# (EGLDIR, default scripts/egl-libs.sh's directory, built first) against
# Mesa's EGL through the system's libglvnd (compare.py --egl).
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../../.." && pwd)
if [ "$1" = --egl ]; then
    egldir=${2:-$(bash "$root/scripts/egl-libs.sh")}
    exec python3 "$here/compare.py" --egl "$egldir" \
        "$here/seed_shaders.py" "$here/library_shaders.py" "$here/error_paths.py" \
        "$here/pixel_paths.py" "$here/uniform_buffers.py" "$here/gl33_state.py" \
        "$here/seed_core.py" "$here/seed_geometry.py" "$here/gl33_entry_points.py"
fi
if [ -n "$1" ]; then
    libdir=$1
else
    # Always (re)build: cargo is incremental, and a library left over from
    # an older checkout would test old code.
    libdir=${CARGO_TARGET_DIR:-$root/target}/release
    (cd "$root" && cargo build --release -p shaderbox-capi)
fi
md=
[ -n "$2" ] && md="--markdown $2"
# shellcheck disable=SC2086
python3 "$here/compare.py" $md "$libdir" \
    "$here/shaded_triangle.py" "$here/fixed_function.py" "$here/textured_fbo.py" \
    "$here/seed_shaders.py" "$here/library_shaders.py" "$here/error_paths.py" \
    "$here/pixel_paths.py" "$here/uniform_buffers.py" "$here/gl33_state.py" \
    "$here/seed_core.py" "$here/seed_geometry.py" "$here/gl33_entry_points.py"
# Mipmapped lookups, held to the bounds their level of detail explains.
python3 "$here/compare.py" $md --bounds "$here/texture_lod_bounds.txt" "$libdir" \
    "$here/texture_lod.py"
sh "$here/debug_env.sh" "$libdir"
