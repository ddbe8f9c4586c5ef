#!/bin/sh
# Real client programs, unmodified, on shaderbox's libOSMesa and on Mesa's
# (Debian's libosmesa6), images compared by ../python/compare.py with the
# differential suite's bar: pyrender's OffscreenRenderer, VTK and PyVista
# through vtkOSOpenGLRenderWindow, GLFW's OSMesa back end; then the EGL
# programs (moderngl's standalone context, pyglet's headless mode) on
# shaderbox's libEGL.so.1 and on the system's libglvnd + Mesa. Every one
# asks for an OpenGL 3.2+ core context.
#   crates/capi/tests/clients/run.sh [VENV]
# VENV (default TARGET/clients-venv) gets the pip packages of
# requirements.txt; shaderbox's library is built and offered under every
# name these programs load (scripts/osmesa-libs.sh).
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../../.." && pwd)
. "$here/venv.sh"
egldir=$(bash "$root/scripts/egl-libs.sh")
status=0
"$venv/bin/python" "$here/../python/compare.py" "$libdir" \
    "$here/pyrender_scenes.py" "$here/vtk_scenes.py" "$here/glfw_core.py" || status=1
"$venv/bin/python" "$here/../python/compare.py" "$egldir" "$here/egl_clients.py" || status=1
exit $status
