#!/usr/bin/env python3
"""Merges the reports of a validation run in parts into one report.

Usage: merge_reports.py [--force] PART_DIR [PART_DIR ...] OUT_DIR

Each PART_DIR holds report.json and validation.h5 from `mssph validate --case ...`, run on one
build, backend, device, mode and seed (a full report split across jobs with a time limit). The
parts must name disjoint cases. OUT_DIR receives report.json, validation.h5 and report.md with its
plots (drawn by report.py): the cases by suite, in the parts' order within a suite; the command
lines and dates of all parts. Existing outputs in OUT_DIR are replaced only with --force.

Exit codes: 0 merged; 2 bad arguments, parts that do not belong together, or outputs in the way.
"""
import json
import os
import sys

import h5py

import report

SUITE_ORDER = ["kernels", "physics", "convergence", "selftest"]
# The run facts every part must share; the command lines and dates are joined instead.
SHARED_FACTS = ["mssph_version", "git_commit", "mode", "physics_backend", "physics_device", "physics_precision",
                "fast_backends", "host_cpu", "gpus", "seed"]
OUTPUTS = ["report.json", "validation.h5", "report.md"]


class MergeError(Exception):
    pass


def read_part(folder):
    path = os.path.join(folder, "report.json")
    try:
        with open(path) as f:
            part = json.load(f)
    except (OSError, ValueError) as e:
        raise MergeError(f"{path}: cannot read the part's report ({e})")
    for key in ("run", "cases"):
        if key not in part:
            raise MergeError(f"{path}: no key '{key}' (not a report of `mssph validate`)")
    h5_path = os.path.join(folder, "validation.h5")
    if not os.path.isfile(h5_path):
        raise MergeError(f"{h5_path}: missing (each part needs the report.json and validation.h5 of one run)")
    return path, part, h5_path


def merged_run(parts):
    first_path, first, _ = parts[0]
    for path, part, _ in parts[1:]:
        for key in SHARED_FACTS:
            if part["run"].get(key) != first["run"].get(key):
                raise MergeError(f"{path}: run/{key} is {part['run'].get(key)!r}, but {first_path} has "
                                 f"{first['run'].get(key)!r} (parts must come from one build, device, mode and seed)")
    run = dict(first["run"])
    run["command_line"] = "; ".join(p["run"]["command_line"] for _, p, _ in parts)
    run["date"] = ", ".join(p["run"]["date"] for _, p, _ in parts)
    return run


def merged_cases(parts):
    seen = {}
    cases = []
    for path, part, _ in parts:
        for case in part["cases"]:
            name = f"{case['suite']}/{case['case']}"
            if name in seen:
                raise MergeError(f"{path}: case {name} is also in {seen[name]} (parts must name disjoint cases)")
            seen[name] = path
            cases.append(case)
    rank = {suite: k for k, suite in enumerate(SUITE_ORDER)}
    return sorted(cases, key=lambda c: rank.get(c["suite"], len(SUITE_ORDER)))  # stable: parts' order kept


def write_h5(parts, run, path):
    with h5py.File(path, "w") as out:
        for key, value in run.items():
            out.attrs[key] = ", ".join(value) if isinstance(value, list) else value
        for _, _, h5_path in parts:
            with h5py.File(h5_path, "r") as part:
                for suite in part:
                    group = out.require_group(suite)
                    for case in part[suite]:
                        part.copy(part[suite][case], group, name=case)


def main(argv):
    args = argv[1:]
    force = "--force" in args
    args = [a for a in args if a != "--force"]
    if len(args) < 3 or any(a.startswith("-") for a in args):
        print(__doc__, file=sys.stderr)
        return 2
    *part_dirs, out_dir = args
    try:
        for name in OUTPUTS:
            target = os.path.join(out_dir, name)
            if os.path.lexists(target) and not (force and os.path.isfile(target) and not os.path.islink(target)):
                raise MergeError(f"{target}: exists; pass --force to replace it (regular files only)")
        parts = [read_part(folder) for folder in part_dirs]
        run = merged_run(parts)
        cases = merged_cases(parts)
    except MergeError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    os.makedirs(out_dir, exist_ok=True)
    json_path = os.path.join(out_dir, "report.json")
    h5_path = os.path.join(out_dir, "validation.h5")
    write_h5(parts, run, h5_path + ".part")
    with open(json_path + ".part", "w") as f:
        json.dump({"run": run, "cases": cases}, f, indent=2, sort_keys=True)
    os.replace(h5_path + ".part", h5_path)
    os.replace(json_path + ".part", json_path)
    drawn = report.main(["report.py", json_path, h5_path, out_dir])
    print(f"merged {len(cases)} case(s) from {len(parts)} part(s): {out_dir}/report.md")
    return drawn


if __name__ == "__main__":
    sys.exit(main(sys.argv))
