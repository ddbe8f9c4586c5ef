#!/usr/bin/env python3
"""The module graph of each workspace crate, and its cycles.

Usage: scripts/module-graph.py [CRATE ...] [--edges] [--check]

A node is a crate's top-level module (`src/foo.rs` or `src/foo/`); an
edge A -> B means a non-test file of A names `crate::B` (in a `use` or a
path) or an item the crate root re-exports from B. Items defined in the
crate root itself (`lib.rs`) are the crate's facade and are not a node.
Test code (`tests.rs`, `*_tests.rs`, `tests/` folders, and everything from
a `#[cfg(test)]` line to the end of a file) is left out: a test may reach
anywhere.

It prints, per crate, the strongly connected components with more than one
module (the cycles) and, with --edges, every edge. A cycle that is meant is
named in the crate's `module-graph.allow` beside Cargo.toml (one line of
space-separated module names, the component exactly, then `#` and why).
--check exits 1 when a crate has a cycle its allow file does not name.

It reads the code as text, so a path spelled through a macro or a glob
import of a glob may be missed; it is the evidence docs/ARCHITECTURE.md
quotes, not a compiler.
"""

import os
import re
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
IDENT = r"[A-Za-z_][A-Za-z0-9_]*"


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def without_tests(text):
    """The text before its first inline test module (`#[cfg(test)]` then
    `mod name {`); a `#[cfg(test)] mod name;` declaration is kept past."""
    m = re.search(r"^\s*#\[cfg\(test\)\]\s*mod\s+\w+\s*\{", text, flags=re.M)
    return text[: m.start()] if m else text


def is_test_file(rel):
    parts = rel.split(os.sep)
    name = parts[-1]
    return (
        "tests" in parts[:-1]
        or name == "tests.rs"
        or name.endswith("_tests.rs")
    )


def brace_group(text, i):
    """The text inside the brace group opening at text[i]."""
    depth = 0
    for j in range(i, len(text)):
        if text[j] == "{":
            depth += 1
        elif text[j] == "}":
            depth -= 1
            if depth == 0:
                return text[i + 1 : j]
    return text[i + 1 :]


def top_names(group):
    """The first segment of each comma-separated path in a use group."""
    names, depth, start = [], 0, 0
    for k, ch in enumerate(group + ","):
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif ch == "," and depth == 0:
            m = re.match(r"\s*(" + IDENT + ")", group[start:k])
            if m:
                names.append(m.group(1))
            start = k + 1
    return names


def crate_refs(text):
    """First segments after every `crate::` in the text."""
    out = []
    for m in re.finditer(r"\bcrate::", text):
        rest = text[m.end() :]
        if rest.startswith("{"):
            out += top_names(brace_group(text, m.end()))
        else:
            n = re.match(IDENT, rest)
            if n:
                out.append(n.group(0))
    return out


def reexports(lib_text, modules):
    """Names the crate root re-exports, mapped to their module."""
    owner = {}
    for m in re.finditer(r"pub\s+use\s+(" + IDENT + r")::([^;]*);", lib_text):
        module, rest = m.group(1), m.group(2)
        if module not in modules:
            continue
        for name in re.findall(IDENT, rest):
            if name not in ("self", "as", "super", "crate"):
                owner.setdefault(name, module)
    return owner


def crate_graph(src):
    modules = {}
    for entry in sorted(os.listdir(src)):
        path = os.path.join(src, entry)
        if entry in ("lib.rs", "main.rs"):
            continue
        if entry.endswith(".rs"):
            modules.setdefault(entry[:-3], [])
        elif os.path.isdir(path):
            modules.setdefault(entry, [])
    for dirpath, _, files in os.walk(src):
        for f in files:
            if not f.endswith(".rs"):
                continue
            full = os.path.join(dirpath, f)
            rel = os.path.relpath(full, src)
            top = rel.split(os.sep)[0]
            top = top[:-3] if top.endswith(".rs") else top
            if top in modules and not is_test_file(rel):
                modules[top].append(full)
    lib = os.path.join(src, "lib.rs")
    lib_text = strip_comments(open(lib).read()) if os.path.exists(lib) else ""
    owner = reexports(lib_text, modules)
    edges = {m: set() for m in modules}
    for module, files in modules.items():
        for full in files:
            text = without_tests(strip_comments(open(full).read()))
            for name in crate_refs(text):
                target = name if name in modules else owner.get(name)
                if target and target != module:
                    edges[module].add(target)
    return edges


def cycles(edges):
    """Strongly connected components with more than one node (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(edges[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    sys.setrecursionlimit(10000)
    for v in sorted(edges):
        if v not in index:
            visit(v)
    return sorted(out)


def allowed(crate_dir):
    path = os.path.join(crate_dir, "module-graph.allow")
    out = []
    if os.path.exists(path):
        for line in open(path):
            body = line.split("#", 1)[0].split()
            if body:
                out.append(sorted(body))
    return out


def main(argv):
    show_edges = "--edges" in argv
    check = "--check" in argv
    wanted = [a for a in argv if not a.startswith("--")]
    crates_dir = os.path.join(ROOT, "crates")
    bad = False
    for crate in sorted(os.listdir(crates_dir)):
        if wanted and crate not in wanted:
            continue
        src = os.path.join(crates_dir, crate, "src")
        if not os.path.isdir(src):
            continue
        edges = crate_graph(src)
        found = cycles(edges)
        ok = allowed(os.path.join(crates_dir, crate))
        print(f"{crate}: {len(edges)} modules, {sum(len(e) for e in edges.values())} edges")
        for comp in found:
            mark = "allowed" if comp in ok else "CYCLE"
            bad |= comp not in ok
            print(f"  {mark}: {{{', '.join(comp)}}}")
        if show_edges:
            for v in sorted(edges):
                if edges[v]:
                    print(f"    {v} -> {', '.join(sorted(edges[v]))}")
    return 1 if check and bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
