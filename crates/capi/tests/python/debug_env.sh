#!/bin/sh
# The debugger through the C ABI: an unmodified PyOpenGL program run with
# SHADERBOX_DEBUG_PIXEL set writes the trace of that pixel (text, then
# JSON) to SHADERBOX_DEBUG_OUT; a malformed value is a warning, not a crash.
#   crates/capi/tests/python/debug_env.sh LIBDIR
set -e
here=$(cd "$(dirname "$0")" && pwd)
libdir=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run() {
    PYOPENGL_PLATFORM=osmesa LD_LIBRARY_PATH="$libdir" python3 "$here/shaded_triangle.py" >/dev/null
}
SHADERBOX_DEBUG_PIXEL=32,24 SHADERBOX_DEBUG_OUT="$tmp/trace.txt" run
grep -q "at pixel (32, 24): 1 fragment" "$tmp/trace.txt"
grep -q "gl_FragColor = vec4(v \* k, 1.0);" "$tmp/trace.txt"
grep -q "inputs: v = " "$tmp/trace.txt"
SHADERBOX_DEBUG_PIXEL=32,24 SHADERBOX_DEBUG_FORMAT=json SHADERBOX_DEBUG_OUT="$tmp/trace.json" run
python3 -c "import json,sys; r=json.load(open(sys.argv[1])); assert r['pixel']==[32,24] and r['draws'][0]['fragments'], r" "$tmp/trace.json"
SHADERBOX_DEBUG_PIXEL=nonsense run 2>"$tmp/err.txt"
grep -q "SHADERBOX_DEBUG_PIXEL=\`nonsense'" "$tmp/err.txt"
echo "debug_env: pixel traces through the C ABI ok"
