#!/usr/bin/env python3
"""Checks that README.md's layout names every workspace member.

    python3 scripts/check-readme.py

Reads the `members` of the `[workspace]` table of Cargo.toml and the
README's "## Layout" section (up to the next "## " heading); each member
(`crates/glsl`, ...) must begin a line of that section, with or without a
trailing slash. Exits 1 naming the members the layout leaves out, 0 when
it names them all. Standard library only (.ci/run runs it).
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def members(cargo_toml):
    try:
        import tomllib  # Python 3.11+
    except ModuleNotFoundError:
        tomllib = None
    with open(cargo_toml, "rb") as f:
        data = f.read()
    if tomllib is not None:
        return tomllib.loads(data.decode())["workspace"]["members"]
    # Older Pythons: the members array of the [workspace] table.
    text = data.decode()
    m = re.search(r"^\[workspace\]\s*$(.*?)(?=^\[)", text + "\n[", re.M | re.S)
    arr = re.search(r"^members\s*=\s*\[(.*?)\]", m.group(1) if m else "", re.M | re.S)
    if not arr:
        sys.exit("check-readme: no [workspace] members in Cargo.toml")
    return re.findall(r'"([^"]+)"', arr.group(1))


def layout_section(readme):
    with open(readme, encoding="utf-8") as f:
        text = f.read()
    m = re.search(r"^## Layout[ \t]*$(.*?)(?=^## |\Z)", text, re.M | re.S)
    if not m:
        sys.exit("check-readme: README.md has no '## Layout' section")
    return m.group(1)


def main():
    section = layout_section(os.path.join(ROOT, "README.md"))
    named = {line.split()[0].rstrip("/") for line in section.splitlines() if line.strip()}
    wanted = [m.rstrip("/") for m in members(os.path.join(ROOT, "Cargo.toml"))]
    missing = [m for m in wanted if m not in named]
    if missing:
        print("README.md's layout does not name these workspace members: " + ", ".join(missing))
        print("(add a line per member to the '## Layout' section, starting with its path)")
        return 1
    print(f"README.md's layout names all {len(wanted)} workspace members")
    return 0


if __name__ == "__main__":
    sys.exit(main())
