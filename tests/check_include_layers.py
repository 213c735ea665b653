#!/usr/bin/env python3
"""The source folders form layers: a file may include its own folder's headers and those of
folders in a lower layer, never one above it, so no two folders include each other.

usage: check_include_layers.py ROOT [--doctored FOLDER:HEADER]
  ROOT: the repository (its src/ and kernels/ are read)
  --doctored: pretend FOLDER has one more file that includes HEADER (the check must fail)
Exit 0 when every include goes down or sideways within a folder; 1 with one line per
include that goes up (file:line: from -> to); 2 when a folder is not in the table.
"""
import pathlib
import re
import sys

# higher includes lower; folders of one layer include none of each other
LAYERS = {
    "app": 9,        # the command line, validate
    "run": 8,        # the time loop, the recorder, restarts
    "observers": 7,  # error norms read from a const simulation
    "solver": 6,     # Simulation<D>, domain, scheme, walls, refinement, open boundaries
    "io": 5,         # snapshots, checkpoints, atomic writes
    "parallel": 4,   # communicator, decomposition, exchange
    "scene": 4,      # the case file and the scene it describes
    "particles": 3,  # the particle set
    "reference": 2,  # analytic solutions and published data (parameters only)
    "geometry": 1,   # meshes, quadrature
    "kernels": 0,    # device code: depends on nothing in src/
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/')


def folder_of(path, root):
    rel = path.relative_to(root).parts
    return rel[1] if rel[0] == "src" else rel[0]


def main():
    args = sys.argv[1:]
    if not args:
        print(__doc__, file=sys.stderr)
        return 2
    root = pathlib.Path(args[0])
    extra = []
    if len(args) == 3 and args[1] == "--doctored":
        f, h = args[2].split(":", 1)
        extra.append((f"{f}/doctored.cpp (pretended)", 1, f, h.split("/")[0]))
    files = sorted(p for d in ("src", "kernels") for p in (root / d).rglob("*") if p.suffix in (".hpp", ".cpp"))
    if not files:
        print(f"{root}: no src/ or kernels/ sources found", file=sys.stderr)
        return 2
    edges = list(extra)
    for p in files:
        src = folder_of(p, root)
        for n, line in enumerate(p.read_text(errors="replace").splitlines(), 1):
            m = INCLUDE.match(line)
            if m:
                edges.append((str(p.relative_to(root)), n, src, m.group(1)))
    bad = 0
    for where, n, a, b in edges:
        for f in (a, b):
            if f not in LAYERS:
                print(f"{where}:{n}: folder '{f}' is not in check_include_layers.py's LAYERS: give it a layer", file=sys.stderr)
                return 2
        if a != b and LAYERS[b] >= LAYERS[a]:
            print(f"{where}:{n}: {a}/ (layer {LAYERS[a]}) includes {b}/ (layer {LAYERS[b]}): only lower layers may be included")
            bad += 1
    if bad:
        return 1
    print(f"{len(files)} files, {len(edges)} includes: every folder includes only lower layers")
    return 0


if __name__ == "__main__":
    sys.exit(main())
