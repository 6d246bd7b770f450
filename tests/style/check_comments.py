#!/usr/bin/python3
"""Checks that source comments say what and why in the present tense, not what was measured when.

A comment in C++, CUDA, CMake, Python or shell code may not carry a timing (a number of us or
ns, "ms per step", "Nx faster/slower"; physical times such as a 1 ms haptic tick stay allowed), a
GPU card name, a date, or a commit hash: the history of a measured
change belongs in its commit message and in a decision record under results/.

Usage: check_comments.py [ROOT]   (ROOT defaults to the repository holding this script)
Prints one line per offending comment and exits 1 if there is any, 0 otherwise.
"""
import pathlib
import re
import sys

FOLDERS = ["src", "kernels", "cpu_reference", "benchmarks", "validation", "tests", "scripts", "cmake"]
SKIP = ("tests/style/data/",)
C_LIKE = {".cpp", ".hpp", ".cu", ".cuh", ".h"}
HASH_LIKE = {".py", ".sh", ".cmake", ".txt"}
RULES = [
    ("a timing", re.compile(r"\b\d+(\.\d+)? ?(us|µs|ns)\b|\b\d+(\.\d+)? ?ms (per|a|each) step\b"
                            r"|\b\d+(\.\d+)?x (faster|slower)\b")),
    ("a GPU card name", re.compile(r"\b(H100|H200|A100|V100|L40S?|RTX ?\d{4}|GeForce|Tesla [A-Z]\d+)\b")),
    ("a date", re.compile(r"\b20\d\d-[01]\d-[0-3]\d\b")),
    ("a commit hash", re.compile(r"\b(?=[0-9a-f]*[a-f])(?=[0-9a-f]*\d)[0-9a-f]{7,12}\b|\b[0-9a-f]{40}\b")),
]
LINE_COMMENT_C = re.compile(r"//(.*)$")
LINE_COMMENT_HASH = re.compile(r"(?:^|\s)#(?!include|pragma|define|if|endif|else|elif|undef|!)(.*)$")


def comments(path):
    """(line number, comment text) of each comment line in the file."""
    text = path.read_text(encoding="utf-8", errors="replace")
    if path.suffix in C_LIKE:
        in_block = False
        for number, line in enumerate(text.splitlines(), 1):
            if in_block or "/*" in line:
                yield number, line
                in_block = "*/" not in line.split("/*")[-1] if "/*" in line else "*/" not in line
                continue
            match = LINE_COMMENT_C.search(line)
            if match:
                yield number, match.group(1)
    elif path.suffix in HASH_LIKE or path.name == "CMakeLists.txt":
        for number, line in enumerate(text.splitlines(), 1):
            match = LINE_COMMENT_HASH.search(line)
            if match:
                yield number, match.group(1)


def offences(root):
    found = []
    for folder in FOLDERS:
        for path in sorted((root / folder).rglob("*")):
            relative = path.relative_to(root).as_posix()
            if not path.is_file() or relative.startswith(SKIP):
                continue
            if path.suffix not in C_LIKE | HASH_LIKE and path.name != "CMakeLists.txt":
                continue
            for number, comment in comments(path):
                for what, pattern in RULES:
                    if pattern.search(comment):
                        found.append(f"{relative}:{number}: comment carries {what}: {comment.strip()[:100]}")
                        break
    return found


def main():
    root = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2]
    found = offences(root.resolve())
    for line in found:
        print(line)
    print(f"{len(found)} comment(s) with measurements, card names, dates or commit hashes")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
