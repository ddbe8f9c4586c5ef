#!/usr/bin/env bash
# Compile+link time of the seed's sphere-impostor program, shaderbox and
# Mesa side by side in one run (docs/PERFORMANCE.md): as GLSL 1.10 (the
# files have no #version) and as GLSL 1.50 compatibility (a first source
# string "#version 150 compatibility").
#
#   bash bench/compile.sh
#
# shaderbox: the criterion benchmark crates/glsl/benches/compile.rs.
# Mesa: bench/mesa_compile.py through Debian's libOSMesa (installed if
# missing). Both read crates/glsl/tests/seeds/000-sphere.{vert,frag}.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
if ! ldconfig -p | grep -q libOSMesa; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq libosmesa6 >/dev/null
fi
vs=crates/glsl/tests/seeds/000-sphere.vert
fs=crates/glsl/tests/seeds/000-sphere.frag
# The seed shaders have no #version; Mesa compiles them as 1.10, and so does
# the benchmark when the file says nothing (see the bench source).
mesa=$(python3 bench/mesa_compile.py "$vs" "$fs" --iterations 300)
mesa150=$(python3 bench/mesa_compile.py "$vs" "$fs" --iterations 300 --first $'#version 150 compatibility\n')
sb=$(cargo bench -q -p shaderbox-glsl --bench compile -- --noplot 2>/dev/null | grep -E "time:")
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
echo "mesa 1.10:           $mesa"
echo "mesa 1.50 compat:    $mesa150"
echo "shaderbox (1.10, then 1.50 compat):"
echo "$sb"
