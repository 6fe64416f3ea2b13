#!/usr/bin/env python3
"""The include graph of ochre's layers (docs/architecture.md, "Design rules"): no include from a layer into a
layer above it (spectra <- materials <- renderer <- tools), and no cycle between the sub-folders of one
layer (materials/lobes may use materials/numerics, never both ways). In tools/ every source is in a
sub-folder (a program's, or the shared library tools/cli: docs/architecture.md, "The tools"), none at the
top for the sub-folders to share. Prints every violation with the includes that make it and exits 1;
exits 0 when the graph is clean.

usage: folder_cycles.py SOURCE_DIR [LAYER ...]   (default: every layer)
"""
import collections
import os
import re
import sys

LAYERS = ["spectra", "materials", "renderer", "tools"]
# Layers whose sources all sit in sub-folders.
NO_TOP_LEVEL_SOURCES = {"tools"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
SOURCE_SUFFIXES = (".h", ".hpp", ".cpp", ".cc")


def includes(root, layer):
    """(file, line number, included path) for every quoted include of the layer's sources."""
    for folder, _, files in os.walk(os.path.join(root, layer)):
        for name in sorted(files):
            if not name.endswith(SOURCE_SUFFIXES):
                continue
            path = os.path.join(folder, name)
            with open(path, errors="replace") as f:
                for number, line in enumerate(f, 1):
                    m = INCLUDE.match(line)
                    if m:
                        yield os.path.relpath(path, root), number, m.group(1)


def top_folder(path_in_layer):
    """The first sub-folder of a path inside a layer, '.' for a file at the layer's top."""
    parts = path_in_layer.split("/")
    return parts[0] if len(parts) > 1 else "."


def find_cycles(edges):
    """Every elementary cycle found by depth-first search, each once (as a list of folders)."""
    cycles, state = [], {}

    def visit(u, stack):
        state[u] = 1
        stack.append(u)
        for v in sorted(edges.get(u, ())):
            if state.get(v) == 1:
                cycles.append(stack[stack.index(v):] + [v])
            elif v not in state:
                visit(v, stack)
        stack.pop()
        state[u] = 2

    for u in sorted(edges):
        if u not in state:
            visit(u, [])
    return cycles


def check_layer(root, layer):
    problems = []
    if layer in NO_TOP_LEVEL_SOURCES:
        for name in sorted(os.listdir(os.path.join(root, layer))):
            if name.endswith(SOURCE_SUFFIXES):
                problems.append(f"{layer}/{name}: a source at the top of {layer}/ (put it in the sub-folder of its "
                                f"program, or in {layer}/cli when several use it)")
    above = LAYERS[LAYERS.index(layer) + 1:]
    edges = collections.defaultdict(set)
    reasons = collections.defaultdict(list)
    for source, number, target in includes(root, layer):
        target_layer = target.split("/")[0]
        if target_layer in above:
            problems.append(f"{source}:{number}: includes {target} of the layer above ({target_layer})")
        if target_layer != layer:
            continue
        a = top_folder(os.path.relpath(source, layer))
        b = top_folder(target[len(layer) + 1:])
        if a != b:
            edges[a].add(b)
            reasons[(a, b)].append(f"{source}:{number} -> {target}")
    for cycle in find_cycles(edges):
        problems.append(f"{layer}: cycle between sub-folders {' -> '.join(cycle)}")
        for a, b in zip(cycle, cycle[1:]):
            for reason in reasons[(a, b)][:3]:
                problems.append(f"    {a} -> {b}: {reason}")
    return problems, edges


def main():
    if len(sys.argv) < 2 or any(layer not in LAYERS for layer in sys.argv[2:]):
        print(__doc__, file=sys.stderr)
        return 2
    root = sys.argv[1]
    problems = []
    for layer in sys.argv[2:] or LAYERS:
        layer_problems, edges = check_layer(root, layer)
        problems += layer_problems
        folders = sorted(set(edges) | {v for vs in edges.values() for v in vs})
        print(f"{layer}: {len(folders)} sub-folders, {len(layer_problems)} problems")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
