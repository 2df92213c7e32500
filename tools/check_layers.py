#!/usr/bin/env python3
"""The layer check: no include, instantiation or import points up.

The layers are written down once, bottom first, in docs/architecture.md's
```layers block. A folder may use its own layer and the ones listed before
it. What is checked:
  - C++ (#include "..." and <...>): resolved against the include paths
    the build gives that part of the tree (a models/ file: its own folder,
    then models/; elsewhere its own folder, then studies/, sim/, models/), so
    "dda/x.hpp" names the file it is;
  - SystemVerilog: a module instantiated from another folder's file;
  - Python (tools/, studies/): `import NAME` of a script beside it;
  - models/ includes only models/, the headers generated from config/
    (girtd/...), the C++ library, nlohmann-json, GLM, Abseil's hash maps,
    oneTBB's loops and POSIX threads' fork hook: the golden model runs without SystemC, Verilator or the
    simulator's I/O.
Every folder holding source must belong to a layer (a new folder fails the
check until it is placed), and every listed folder must exist.

Usage: check_layers.py REPO_ROOT
Prints `FILE:LINE: what points up` per problem; exit 1 when there is one.
"""
import pathlib
import re
import sys

CPP = {".cpp", ".hpp", ".h", ".cc"}
SV = {".sv", ".svh"}
PY = {".py"}
SKIP_PARTS = {"build", "node_modules", ".git", "out"}


def read_layers(root):
    doc = root / "docs" / "architecture.md"
    text = doc.read_text()
    m = re.search(r"^```layers\n(.*?)^```", text, re.S | re.M)
    if not m:
        sys.exit(f"{doc}:1: no ```layers block")
    layers = []
    for line in m.group(1).splitlines():
        line = line.split("#", 1)[0].strip()
        if line:
            layers.append(line.rstrip("/"))
    return layers


def layer_of(rel, layers):
    """The index of the longest listed folder holding `rel` (a path string)."""
    best, best_len = None, -1
    for i, folder in enumerate(layers):
        if (rel == folder or rel.startswith(folder + "/")) and len(folder) > best_len:
            best, best_len = i, len(folder)
    return best


def sources(root):
    for top in ("models", "sim", "hw", "python", "examples", "studies", "testbench", "tools", "traces"):
        for p in sorted((root / top).rglob("*")):
            if p.is_file() and p.suffix in CPP | SV | PY and not SKIP_PARTS & set(p.relative_to(root).parts):
                yield p


def cpp_uses(root, path):
    rel = path.relative_to(root)
    in_models = rel.parts[0] == "models"
    # The build's include paths: studies/ (its own), sim/, models/; no folder
    # name is in two of them, so the order decides nothing.
    roots = [path.parent, root / "models"] if in_models else [path.parent, root / "studies", root / "sim", root / "models"]
    for n, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
        m = re.match(r'\s*#\s*include\s*([<"])([^>"]+)[>"]', line)
        if not m:
            continue
        quote, name = m.groups()
        spelled = f'"{name}"' if quote == '"' else f"<{name}>"
        # "..." searches the file's own folder first; <...> only the include paths.
        target = next((t for r in (roots if quote == '"' else roots[1:])
                       if (t := (r / name).resolve()).is_file() and root in t.parents), None)
        if target is not None:
            yield n, target.relative_to(root), f"includes {spelled}"
        elif in_models and not (quote == '"' and name.startswith("girtd/")) and (
                quote == '"' or re.match(r"(systemc|tlm|verilated)", name)
                or not re.match(r"([a-z_]+|nlohmann/.*|glm/.*|absl/(hash|container)/.*|oneapi/tbb/.*|pthread\.h)$", name)):
            yield n, None, (f"includes {spelled}: models/ uses models/, girtd/ (generated), the C++ library, "
                            "nlohmann-json, GLM, Abseil, oneTBB and pthread.h only")


def sv_uses(root, path, modules):
    for n, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
        m = re.match(r"\s*([a-z_][a-z0-9_]*)\s*(#\s*\(|[a-z_][a-z0-9_]*\s*\()", line)
        if m and m.group(1) in modules:
            yield n, modules[m.group(1)], f"instantiates {m.group(1)}"


def py_uses(root, path):
    for n, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
        m = re.match(r"\s*(?:from\s+([a-z_0-9]+)\s+import|import\s+([a-z_0-9]+))", line)
        if m:
            name = m.group(1) or m.group(2)
            target = path.parent / f"{name}.py"
            if target.is_file():
                yield n, target.relative_to(root), f"imports {name}"


def check(root):
    layers = read_layers(root)
    problems = []
    files = list(sources(root))
    modules = {}
    for p in files:
        if p.suffix in SV:
            for m in re.finditer(r"^\s*module\s+([a-z_][a-z0-9_]*)", p.read_text(errors="replace"), re.M):
                modules[m.group(1)] = p.relative_to(root)
    unplaced = set()
    for p in files:
        rel = p.relative_to(root)
        mine = layer_of(str(rel.parent), layers)
        if mine is None:
            unplaced.add(str(rel.parent))
            continue
        if p.suffix in CPP:
            uses = cpp_uses(root, p)
        elif p.suffix in SV:
            uses = sv_uses(root, p, modules)
        else:
            uses = py_uses(root, p)
        for n, target, what in uses:
            if target is None:
                problems.append(f"{rel}:{n}: {what}")
                continue
            theirs = layer_of(str(target.parent), layers)
            if theirs is None:
                continue  # reported as unplaced by its own files
            if theirs > mine:
                problems.append(f"{rel}:{n}: {what}, in {layers[theirs]}, a layer above {layers[mine]}")
    for folder in sorted(unplaced):
        problems.append(f"{folder}: holds source but is in no layer of docs/architecture.md")
    for folder in layers:
        if not (root / folder).is_dir():
            problems.append(f"docs/architecture.md: layer {folder} is not a folder")
    return layers, len(files), problems


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check_layers.py REPO_ROOT")
    root = pathlib.Path(sys.argv[1]).resolve()
    layers, nfiles, problems = check(root)
    for p in problems:
        print(p)
    print(f"{len(problems)} problem(s) in {nfiles} files over {len(layers)} layers")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
