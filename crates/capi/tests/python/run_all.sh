#!/bin/sh
# Differential suite: every scene script here on shaderbox's libOSMesa and on
# Mesa's (Debian libosmesa6), compared by compare.py. Needs python3 + PyOpenGL.
#   crates/capi/tests/python/run_all.sh [LIBDIR]   (default: target/release)
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../../.." && pwd)
libdir=${1:-${CARGO_TARGET_DIR:-$root/target}/release}
[ -f "$libdir/libOSMesa.so" ] || (cd "$root" && cargo build --release -p shaderbox-capi)
status=0
for s in "$here"/shaded_triangle.py "$here"/fixed_function.py "$here"/textured_fbo.py; do
    python3 "$here/compare.py" "$libdir" "$s" || status=1
done
exit $status
