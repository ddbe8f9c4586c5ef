# Sourced by run.sh and vispy.sh (with `here` and `root` set and the
# scripts' first argument as VENV): the clients' venv (default
# TARGET/clients-venv) with the pip packages of requirements.txt and
# PyOpenGL 3.1.10 over pyrender's pin, and shaderbox's release library
# under every name the clients load (scripts/osmesa-libs.sh) in `libdir`.
venv=${1:-${CARGO_TARGET_DIR:-$root/target}/clients-venv}
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
pip="$venv/bin/python -m pip install -q --disable-pip-version-check"
$pip -r "$here/requirements.txt"
$pip --no-deps PyOpenGL==3.1.10
libdir=$(bash "$root/scripts/osmesa-libs.sh" --release)
