#!/bin/sh
# vispy's scene visuals (vispy_scenes.py), unmodified, on shaderbox's
# libOSMesa and on Mesa's (Debian's libosmesa6) through OSMESA_LIBRARY,
# each scene held by ../python/compare.py to its bound in vispy_bounds.txt
# (the agreement recorded in docs/CONFORMANCE.md, "Real programs").
#   crates/capi/tests/clients/vispy.sh [VENV]
# VENV (default TARGET/clients-venv, shared with run.sh) gets vispy and
# the pip packages of requirements.txt; PyOpenGL is vispy's way to 3D
# textures (the volume scenes).
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../../.." && pwd)
. "$here/venv.sh"
exec "$venv/bin/python" "$here/../python/compare.py" --bounds "$here/vispy_bounds.txt" \
    "$libdir" "$here/vispy_scenes.py"
