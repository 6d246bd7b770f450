#!/usr/bin/env python3
"""Checks configs/sweep.schema.json against the sweep files and the metric list.

1. The schema is a valid JSON Schema (draft 2020-12).
2. Every shipped sweep configs/sweep_*.json and test sweep tests/data/sweeps/*.json validates.
3. Files mssph rejects for a rule the schema states fail validation too.
4. The schema's metric names are scripts/analysis/log_metrics.py's, in its order.
5. configs/README.md mentions every key the schema defines.

Run from the repository root; exits 1 listing every failure.
"""
import copy
import json
import pathlib
import sys

import jsonschema

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "scripts" / "analysis"))
import log_metrics  # noqa: E402

SCHEMA = json.loads((ROOT / "configs" / "sweep.schema.json").read_text())
VALID = {"name": "s", "scene": "x.json", "parameters": [{"path": "bodies/b/density", "values": [1, 2]}]}
# Each breaks one rule the schema states (and mssph checks: tests/sweep/sweep_file_test.cpp).
REJECTED = {
    "unknown key": {"colour": 1},
    "empty parameter list": {"parameters": []},
    "empty value list": {"parameters": [{"path": "a/b", "values": []}]},
    "duplicate value": {"parameters": [{"path": "a/b", "values": [1, 1]}]},
    "values and a range": {"parameters": [{"path": "a/b", "values": [1], "log": {"from": 1, "to": 2, "count": 2}}]},
    "no values": {"parameters": [{"path": "a/b"}]},
    "log from 0": {"parameters": [{"path": "a/b", "log": {"from": 0, "to": 2, "count": 2}}]},
    "count 1": {"parameters": [{"path": "a/b", "linear": {"from": 0, "to": 2, "count": 1}}]},
    "seed as a parameter": {"parameters": [{"path": "simulation/seed", "values": [1, 2]}]},
    "reserved name": {"parameters": [{"path": "a/b", "name": "state", "values": [1]}]},
    "unknown metric": {"metrics": ["peak_force"]},
    "negative seed": {"repetitions": {"seeds": [1, -1]}},
    "bad combine": {"combine": "cross"},
    "name with a space": {"name": "a b"},
}


def main():
    failures = []
    validator_class = jsonschema.validators.validator_for(SCHEMA)
    validator_class.check_schema(SCHEMA)
    validator = validator_class(SCHEMA)
    files = sorted((ROOT / "configs").glob("sweep_*.json")) + sorted((ROOT / "tests" / "data" / "sweeps").glob("*.json"))
    if len(files) < 3:
        failures.append(f"expected the shipped and test sweeps, found {files}")
    for path in files:
        for error in validator.iter_errors(json.loads(path.read_text())):
            failures.append(f"{path.relative_to(ROOT)}: {error.json_path}: {error.message}")
    for what, change in REJECTED.items():
        document = copy.deepcopy(VALID)
        document.update(change)
        if validator.is_valid(document):
            failures.append(f"schema accepts a sweep with {what}: {json.dumps(document)}")
    if not validator.is_valid(VALID):
        failures.append("schema rejects the minimal valid sweep")
    if SCHEMA["properties"]["metrics"]["items"]["enum"] != list(log_metrics.METRICS):
        failures.append("schema's metric names differ from log_metrics.METRICS")
    readme = (ROOT / "configs" / "README.md").read_text()
    keys = set(SCHEMA["properties"]) | set(SCHEMA["$defs"]["parameter"]["properties"]) | {"seeds", "from", "to", "count"}
    for key in sorted(keys - {"$schema"}):
        if f"`{key}`" not in readme:
            failures.append(f"configs/README.md does not document `{key}`")
    for f in failures:
        print("FAIL:", f)
    print(f"sweep schema: {len(files)} files, {len(REJECTED)} rejections checked, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
