#!/usr/bin/python3
"""Checks the code against the one layer table, the one in ARCHITECTURE.md.

The table's rows are ranked bottom first; each folder of a row is a component. A file may include
its own component's files and those of lower-ranked components, never a higher-ranked one nor a
sibling of the same rank (the three backends do not include each other). Includes are resolved the
way the build resolves them: next to the including file, then under each include root. Includes
that resolve to nothing in the tree (generated files, system headers in quotes) are not judged.

The table must also agree with the tree: every folder directly under src/ is in it, and each
row's target is defined (add_library or add_executable) in its folder's CMakeLists.txt or the
parent folder's.

Usage: check_layers.py [ROOT]   (ROOT defaults to the repository holding this script)
Prints one line per disagreement and exits 1 if there is any, 0 otherwise.
"""
import pathlib
import re
import sys

# The targets' include directories, in the order a bare name is looked up.
INCLUDE_ROOTS = ["src", "cpu_reference", "kernels", "validation", "benchmarks"]
SOURCE_SUFFIXES = {".hpp", ".cpp", ".cu", ".cuh", ".h"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)
TABLE_ROW = re.compile(r"^\|\s*(\d+)\s*\|([^|]*)\|([^|]*)\|([^|]*)\|")
BACKTICKED = re.compile(r"`([^`]+)`")


def layer_table(root):
    """[(rank, layer name, [folders], [targets])] from the Layers section of ARCHITECTURE.md."""
    text = (root / "ARCHITECTURE.md").read_text(encoding="utf-8")
    section = text.split("\n## Layers", 1)[1].split("\n## ", 1)[0]
    rows = []
    for line in section.splitlines():
        match = TABLE_ROW.match(line)
        if match:
            rank, name, folders, targets = match.groups()
            rows.append((int(rank), name.strip(), BACKTICKED.findall(folders), BACKTICKED.findall(targets)))
    if not rows:
        raise SystemExit("ARCHITECTURE.md: no rows in the Layers table")
    return rows


def component_of(components, relative):
    """The (folder, rank) whose folder holds the path relative to ROOT, most specific first."""
    best = None
    for folder, rank in components:
        if relative.startswith(folder) and (best is None or len(folder) > len(best[0])):
            best = (folder, rank)
    return best


def resolve(root, including, name):
    for base in [including.parent] + [root / r for r in INCLUDE_ROOTS]:
        candidate = (base / name).resolve()
        if candidate.is_file():
            return candidate
    return None


def include_violations(root, components):
    found = []
    for path in sorted(root.rglob("*")):
        if path.suffix not in SOURCE_SUFFIXES or not path.is_file():
            continue
        relative = path.relative_to(root).as_posix()
        if relative.startswith(("build", "tests/", ".git/")):
            continue
        owner = component_of(components, relative)
        if owner is None:
            continue
        for name in INCLUDE.findall(path.read_text(encoding="utf-8", errors="replace")):
            target = resolve(root, path, name)
            if target is None or root not in target.parents:
                continue
            target_component = component_of(components, target.relative_to(root).as_posix())
            if target_component is None or target_component[0] == owner[0]:
                continue
            if target_component[1] >= owner[1]:
                kind = "a sibling" if target_component[1] == owner[1] else "a higher layer"
                found.append(f'{relative} ({owner[0]}, rank {owner[1]}) includes "{name}" '
                             f"({target_component[0]}, rank {target_component[1]}): {kind}")
    return found


def table_disagreements(root, rows):
    found = []
    listed = {folder for _, _, folders, _ in rows for folder in folders}
    for folder in sorted(p for p in (root / "src").iterdir() if p.is_dir()):
        if f"src/{folder.name}/" not in listed:
            found.append(f"src/{folder.name}/ is in no row of ARCHITECTURE.md's layer table")
    for rank, name, folders, targets in rows:
        for folder in folders:
            if not (root / folder).is_dir():
                found.append(f"ARCHITECTURE.md: layer {rank} ({name}) names {folder}, which does not exist")
        cmake_text = ""
        for folder in folders:
            for place in (root / folder, (root / folder).parent):
                if (place / "CMakeLists.txt").is_file():
                    cmake_text += (place / "CMakeLists.txt").read_text(encoding="utf-8")
        for target in targets:
            if not re.search(rf"add_(library|executable)\(\s*{re.escape(target)}\b", cmake_text):
                found.append(f"ARCHITECTURE.md: layer {rank} ({name}) names target {target}, which no "
                             f"CMakeLists.txt of {', '.join(folders)} defines")
    return found


def main():
    root = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2]
    root = root.resolve()
    rows = layer_table(root)
    components = [(folder, rank) for rank, _, folders, _ in rows for folder in folders]
    found = table_disagreements(root, rows) + include_violations(root, components)
    for line in found:
        print(line)
    print(f"{len(found)} disagreement(s) with the layer table under {root}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
