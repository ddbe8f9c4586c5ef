#!/usr/bin/env bash
# Obtain piglit's framework and the test folders of every set in
# scripts/piglit-sets.sh (GLSL 1.10-3.30 and their extensions) from
# Debian's `piglit` package, without installing it (the full install is
# 2 GB and pulls in Mesa, Vulkan and OpenCL).
#
# Usage: scripts/piglit-fetch.sh
#
# Environment:
#   PIGLIT_CACHE  where to keep the .deb and the extracted tree
#                 (default: .piglit/ at the repository root, gitignored)
#   PIGLIT_DEB    use this .deb instead of `apt-get download piglit`
#
# Result: $PIGLIT_CACHE/root/ holds the extracted subset:
#   usr/bin/piglit                               the runner script
#   usr/lib/x86_64-linux-gnu/piglit/framework/   its Python framework
#   usr/lib/x86_64-linux-gnu/piglit/tests/{glslparser,shader}.xml.gz
#   usr/lib/x86_64-linux-gnu/piglit/{tests,generated_tests}/spec/FOLDER/
#                                                for each FOLDER of the sets
# and the Python modules the framework imports (mako, six) are installed
# for /usr/bin/python3, the interpreter the runner script names.
#
# Idempotent: a second run with the same .deb does nothing. root/.extracted-from
# names the .deb and root/.extracted-folders the folders taken from it (a
# tree without the latter has the GLSL 1.10/1.20 folders); folders missing
# from a tree of the same .deb are added to it, and a different .deb
# replaces the tree.

set -euo pipefail

root_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cache="${PIGLIT_CACHE:-$root_dir/.piglit}"
data_rel="usr/lib/x86_64-linux-gnu/piglit"
# shellcheck source=piglit-sets.sh
. "$root_dir/scripts/piglit-sets.sh"
read -r -a folders <<<"$(piglit_folders all)"

log() { printf 'piglit-fetch: %s\n' "$*" >&2; }
die() { log "error: $*"; exit 1; }

# Runs a command as root (directly, or through sudo when available).
as_root() {
    if [ "$(id -u)" -eq 0 ]; then
        "$@"
    elif command -v sudo >/dev/null 2>&1; then
        sudo "$@"
    else
        die "need root to run: $* (run as root or install sudo)"
    fi
}

apt_updated=0
apt_update_once() {
    if [ "$apt_updated" -eq 0 ]; then
        log "apt-get update"
        as_root apt-get update -qq
        apt_updated=1
    fi
}

# The tools this script and piglit's runner need.
ensure_tools() {
    local missing=()
    command -v dpkg-deb >/dev/null 2>&1 || die "dpkg-deb not found: this script needs a Debian-based system"
    if [ ! -x /usr/bin/python3 ]; then
        missing+=(python3 python3-mako python3-six)
    else
        /usr/bin/python3 -c 'import mako' 2>/dev/null || missing+=(python3-mako)
        /usr/bin/python3 -c 'import six' 2>/dev/null || missing+=(python3-six)
    fi
    if [ "${#missing[@]}" -gt 0 ]; then
        # The framework imports mako (for HTML summaries) at start-up and six
        # in places; numpy, lxml, psutil and simplejson are optional.
        log "installing ${missing[*]}"
        if ! apt_install "${missing[@]}"; then
            apt_update_once
            apt_install "${missing[@]}" || die "could not install ${missing[*]}"
        fi
    fi
}

apt_install() {
    as_root env DEBIAN_FRONTEND=noninteractive \
        apt-get install -y -qq --no-install-recommends "$@" >/dev/null
}

# Prints the path of the piglit .deb, downloading it into the cache if
# there is none yet.
find_deb() {
    if [ -n "${PIGLIT_DEB:-}" ]; then
        [ -f "$PIGLIT_DEB" ] || die "PIGLIT_DEB=$PIGLIT_DEB is not a file"
        printf '%s\n' "$PIGLIT_DEB"
        return
    fi
    mkdir -p "$cache/debs"
    local deb
    deb="$(ls -1 "$cache"/debs/piglit_*.deb 2>/dev/null | tail -n 1 || true)"
    if [ -z "$deb" ]; then
        if ! apt-cache show piglit >/dev/null 2>&1; then
            apt_update_once
        fi
        log "apt-get download piglit (about 35 MB)"
        # apt downloads as the unprivileged _apt user when it can; a
        # directory it cannot write only earns a warning, so silence it.
        (cd "$cache/debs" && apt-get download -qq piglit 2>&1 | grep -v 'unsandboxed' >&2 || true)
        deb="$(ls -1 "$cache"/debs/piglit_*.deb 2>/dev/null | tail -n 1 || true)"
        [ -n "$deb" ] || die "apt-get download piglit produced no .deb (is the Debian 'main' archive in sources.list?)"
    fi
    printf '%s\n' "$deb"
}

# The tar members of FOLDER's tests: of tests/ and generated_tests/, those
# the package has (tar fails on a pattern that matches nothing, and some
# folders are generated only). Reads $listing, the package's member list.
folder_members() {
    local kind
    for kind in tests generated_tests; do
        if grep -q "^\./$data_rel/$kind/spec/$1/" <<<"$listing"; then
            printf '%s\n' "./$data_rel/$kind/spec/$1/*"
        fi
    done
}

extract() {
    local deb="$1" listing
    listing="$(dpkg-deb --fsys-tarfile "$deb" | tar -t)"
    local stamp="$cache/root/.extracted-from" have_file="$cache/root/.extracted-folders"
    local tmp="$cache/root.tmp" members=() missing=() have f
    rm -rf "$tmp"
    mkdir -p "$tmp"
    if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$(basename "$deb")" ]; then
        # A tree from this .deb: add the folders it lacks.
        have="$piglit_legacy_folders"
        [ -f "$have_file" ] && have="$(cat "$have_file")"
        for f in "${folders[@]}"; do
            case " $have " in *" $f "*) ;; *) missing+=("$f") ;; esac
        done
        if [ "${#missing[@]}" -eq 0 ]; then
            rmdir "$tmp"
            log "up to date ($(basename "$deb"))"
            return
        fi
        log "adding ${missing[*]} from $(basename "$deb")"
        for f in "${missing[@]}"; do mapfile -t -O "${#members[@]}" members < <(folder_members "$f"); done
        dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$tmp" --wildcards "${members[@]}"
        # Move each folder in whole, then record it: an interrupted run
        # leaves folders that the next run extracts again.
        local kind
        for f in "${missing[@]}"; do
            for kind in tests generated_tests; do
                if [ -d "$tmp/$data_rel/$kind/spec/$f" ]; then
                    mkdir -p "$cache/root/$data_rel/$kind/spec"
                    rm -rf "$cache/root/$data_rel/$kind/spec/$f"
                    mv "$tmp/$data_rel/$kind/spec/$f" "$cache/root/$data_rel/$kind/spec/$f"
                fi
            done
        done
        echo "$have ${missing[*]}" >"$have_file"
        rm -rf "$tmp"
        return
    fi
    log "extracting from $(basename "$deb")"
    members=(./usr/bin/piglit "./$data_rel/framework/*"
        "./$data_rel/tests/glslparser.xml.gz" "./$data_rel/tests/shader.xml.gz")
    for f in "${folders[@]}"; do mapfile -t -O "${#members[@]}" members < <(folder_members "$f"); done
    dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$tmp" --wildcards "${members[@]}"
    basename "$deb" >"$tmp/.extracted-from"
    echo "${folders[*]}" >"$tmp/.extracted-folders"
    rm -rf "$cache/root"
    mv "$tmp" "$cache/root"
}

ensure_tools
deb="$(find_deb)"
extract "$deb"
/usr/bin/python3 "$cache/root/usr/bin/piglit" run --help >/dev/null \
    || die "the extracted piglit does not start; see the error above"
log "ready: $cache/root/usr/bin/piglit"
