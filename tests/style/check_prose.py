#!/usr/bin/python3
"""Checks that the front-door prose stays readable: README.md at most 200 lines, and no paragraph
over 800 characters in README.md, ARCHITECTURE.md, CHANGELOG.md, docs/, configs/, validation/
(each case's README), or the hand-written pages of results/ (all but the validation reports,
which `mssph validate` writes).

A paragraph is a run of non-blank lines outside code fences; each list item (with its
continuation lines), table row and heading counts as a paragraph of its own.

Usage: check_prose.py [ROOT]   (ROOT defaults to the repository holding this script)
Prints one line per finding and exits 1 if there is any, 0 otherwise.
"""
import pathlib
import re
import sys

MAX_PARAGRAPH = 800
MAX_README_LINES = 200
FOLDERS = ("docs", "configs", "validation", "results/current", "results/decisions", "results/baselines",
           "results/figure3")


def pages(root):
    for name in ("README.md", "ARCHITECTURE.md", "CHANGELOG.md", "results/README.md", "results/reliability.md"):
        if (root / name).is_file():
            yield root / name
    for folder in FOLDERS:
        yield from sorted((root / folder).rglob("*.md")) if (root / folder).is_dir() else []


ITEM = re.compile(r"^(\d+\.|[-*]|\||#+)\s")


def paragraphs(text):
    """(first line number, text) of each paragraph: a list item, table row or heading starts a new
    one, and a list item's continuation lines belong to it."""
    block, start, fenced = [], 0, False
    for number, line in enumerate(text.splitlines() + [""], 1):
        stripped = line.strip()
        if stripped.startswith("```"):
            fenced = not fenced
            stripped = ""
        if fenced or not stripped or ITEM.match(stripped):
            if block:
                yield start, " ".join(block)
            block = []
            if fenced or not stripped:
                continue
        if not block:
            start = number
        block.append(stripped)


def findings(root):
    found = []
    readme = root / "README.md"
    if readme.is_file():
        lines = len(readme.read_text(encoding="utf-8").splitlines())
        if lines > MAX_README_LINES:
            found.append(f"README.md: {lines} lines, more than {MAX_README_LINES}")
    for page in pages(root):
        text = page.read_text(encoding="utf-8")
        for number, paragraph in paragraphs(text):
            if len(paragraph) > MAX_PARAGRAPH:
                found.append(f"{page.relative_to(root).as_posix()}:{number}: paragraph of "
                             f"{len(paragraph)} characters, more than {MAX_PARAGRAPH}")
    return found


def main():
    root = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2]
    found = findings(root.resolve())
    for line in found:
        print(line)
    print(f"{len(found)} finding(s) in the prose")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
