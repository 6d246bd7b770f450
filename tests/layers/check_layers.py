#!/usr/bin/python3
"""Checks that every quoted #include of mssph's code points down the layers of ARCHITECTURE.md.

Each source folder (or file) belongs to one component with a rank; a file may include its own
component's files and those of lower-ranked components, never a higher-ranked one nor a sibling
of the same rank (the three backends do not include each other). Includes are resolved the way
the build resolves them: next to the including file, then under each include root. Includes that
resolve to nothing in the tree (generated files, system headers in quotes) are not judged.

Usage: check_layers.py [ROOT]   (ROOT defaults to the repository holding this script)
Prints one line per upward include and exits 1 if there is any, 0 otherwise.
"""
import pathlib
import re
import sys

# (component, rank, paths relative to ROOT: a folder ends with "/"). The first match of a file,
# most specific first, names its component.
COMPONENTS = [
    ("foundation/util", 0, ["src/util/"]),
    ("foundation/config", 1, ["src/config/"]),
    ("model", 2, ["src/scene/", "src/model/"]),
    ("backend interface", 3, ["src/sim/backend.hpp", "src/sim/state_arrays.hpp"]),
    ("float physics (kernels/common)", 4, ["kernels/common/"]),
    ("backend reference", 5, ["cpu_reference/"]),
    ("backend cpu", 5, ["kernels/cpu/"]),
    ("backend cuda", 5, ["kernels/cuda/"]),
    ("backend factory", 6, ["src/backends/"]),
    ("run machinery", 7, ["src/sim/", "src/io/", "src/haptics/"]),
    ("sweeps", 8, ["src/sweep/"]),
    ("benchmark comparison", 8, ["src/bench/"]),
    ("cli", 9, ["src/cli/"]),
    ("validation", 10, ["validation/"]),
    ("benchmarks", 10, ["benchmarks/"]),
    ("executable", 11, ["src/cli/main.cpp", "src/cli/bench_command.cpp"]),
]
# The targets' include directories, in the order a bare name is looked up.
INCLUDE_ROOTS = ["src", "cpu_reference", "kernels", "src/cli", "validation", "benchmarks"]
SOURCE_SUFFIXES = {".hpp", ".cpp", ".cu", ".cuh", ".h"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def component_of(relative):
    """The component of a path relative to ROOT, the most specific (longest) match, or None."""
    best = None
    for name, rank, paths in COMPONENTS:
        for p in paths:
            hit = relative == p if not p.endswith("/") else relative.startswith(p)
            if hit and (best is None or len(p) > best[2]):
                best = (name, rank, len(p))
    return None if best is None else best[:2]


def resolve(root, including, name):
    for base in [including.parent] + [root / r for r in INCLUDE_ROOTS]:
        candidate = (base / name).resolve()
        if candidate.is_file():
            return candidate
    return None


def violations(root):
    root = root.resolve()
    found = []
    for path in sorted(root.rglob("*")):
        if path.suffix not in SOURCE_SUFFIXES or not path.is_file():
            continue
        relative = path.relative_to(root).as_posix()
        if relative.startswith(("build", "tests/", ".git/")):
            continue
        owner = component_of(relative)
        if owner is None:
            continue
        for name in INCLUDE.findall(path.read_text(encoding="utf-8", errors="replace")):
            target = resolve(root, path, name)
            if target is None or root not in target.parents:
                continue
            target_component = component_of(target.relative_to(root).as_posix())
            if target_component is None or target_component[0] == owner[0]:
                continue
            if target_component[1] >= owner[1]:
                kind = "a sibling" if target_component[1] == owner[1] else "a higher layer"
                found.append(f'{relative} ({owner[0]}, rank {owner[1]}) includes "{name}" '
                             f"({target_component[0]}, rank {target_component[1]}): {kind}")
    return found


def main():
    root = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2]
    found = violations(root)
    for line in found:
        print(line)
    print(f"{len(found)} upward include(s) under {root}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
