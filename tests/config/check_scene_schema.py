#!/usr/bin/env python3
"""Checks configs/scene.schema.json against the scenes and the loader's contract.

1. The schema is a valid JSON Schema (draft 2020-12) and documents every key it defines.
2. Every shipped scene configs/*.json validates.
3. The variants of tests/config/data/scene_cases.json: 'accepted' ones validate, 'rejected' ones
   fail validation, except 'loader_only' ones (rules JSON Schema cannot state), which must
   validate so the list stays a true account of what only the loader checks. The C++ test
   tests/config/scene_cases_test.cpp loads the same variants through load_scene.
4. configs/README.md mentions every key the schema defines.

Run from the repository root; exits 1 listing every failure.
"""
import copy
import json
import pathlib
import re
import sys

import jsonschema

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCHEMA_PATH = ROOT / "configs" / "scene.schema.json"
CASES_PATH = ROOT / "tests" / "config" / "data" / "scene_cases.json"
BASE_PATH = ROOT / "tests" / "config" / "data" / "base_scene.json"
README_PATH = ROOT / "configs" / "README.md"


def load_json(path):
    # nlohmann-json rejects NaN and Infinity literals; Python's json module would accept them.
    def reject_constant(name):
        raise ValueError(f"{path}: non-standard JSON constant {name}")

    return json.loads(path.read_text(encoding="utf-8"), parse_constant=reject_constant)


def pointer_tokens(pointer):
    """RFC 6901: '/a~1b/0' -> ['a/b', '0']."""
    if pointer == "":
        return []
    if not pointer.startswith("/"):
        raise ValueError(f"JSON pointer without leading '/': {pointer!r}")
    return [t.replace("~1", "/").replace("~0", "~") for t in pointer[1:].split("/")]


def escape_pointer(tokens):
    """RFC 6901: ['a/b', 0] -> '/a~1b/0'."""
    return "".join("/" + str(t).replace("~", "~0").replace("/", "~1") for t in tokens)


def within(pointer, ancestor):
    """Whether `ancestor` is `pointer` or one of its ancestors ('/' names the document itself)."""
    if ancestor == "" or pointer == ancestor:
        return True
    return pointer.startswith(ancestor + "/")


def apply_patch(document, patch):
    """RFC 6902 'add', 'remove' and 'replace' (the operations scene_cases.json uses); the C++
    side applies the same patches with nlohmann::json::patch."""
    document = copy.deepcopy(document)
    for op in patch:
        tokens = pointer_tokens(op["path"])
        if not tokens:
            if op["op"] not in ("add", "replace"):
                raise ValueError(f"cannot {op['op']} the whole document")
            document = copy.deepcopy(op["value"])
            continue
        parent = document
        for token in tokens[:-1]:
            parent = parent[int(token)] if isinstance(parent, list) else parent[token]
        last = tokens[-1]
        if isinstance(parent, list):
            index = len(parent) if last == "-" else int(last)
            if op["op"] == "add":
                parent.insert(index, copy.deepcopy(op["value"]))
            elif op["op"] == "replace":
                parent[index] = copy.deepcopy(op["value"])
            elif op["op"] == "remove":
                del parent[index]
            else:
                raise ValueError(f"unsupported patch operation {op['op']!r}")
        else:
            if op["op"] in ("replace", "remove") and last not in parent:
                raise KeyError(f"{op['op']} of missing member {op['path']}")
            if op["op"] in ("add", "replace"):
                parent[last] = copy.deepcopy(op["value"])
            elif op["op"] == "remove":
                del parent[last]
            else:
                raise ValueError(f"unsupported patch operation {op['op']!r}")
    return document


def defined_keys(schema):
    """(key, definition) for every key the schema defines: the 'properties' reachable through
    'properties', 'additionalProperties', 'items' and '$defs'. The conditions under 'allOf'
    only restate keys defined there."""
    found = []

    def walk(node):
        if not isinstance(node, dict):
            return
        for key, value in node.get("properties", {}).items():
            found.append((key, value))
            walk(value)
        for child in (node.get("additionalProperties"), node.get("items")):
            walk(child)
        for value in node.get("$defs", {}).values():
            walk(value)

    walk(schema)
    return found


def resolve(schema, definition):
    while isinstance(definition, dict) and "description" not in definition and "$ref" in definition:
        definition = schema["$defs"][definition["$ref"].removeprefix("#/$defs/")]
    return definition


def main():
    failures = []
    schema = load_json(SCHEMA_PATH)
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)

    def errors_of(document):
        """(JSON pointer of the offending value, message) of every schema violation."""
        return [(escape_pointer(e.absolute_path), e.message) for e in validator.iter_errors(document)]

    for key, definition in defined_keys(schema):
        if not resolve(schema, definition).get("description"):
            failures.append(f"schema: key '{key}' has no description")

    # Sweep files (sweep_*.json) have their own schema, checked by tests/sweep/check_sweep_schema.py.
    scenes = sorted(p for p in (ROOT / "configs").glob("*.json")
                    if not p.name.endswith(".schema.json") and not p.name.startswith("sweep_"))
    if not scenes:
        failures.append("configs/: no scene files found")
    for path in scenes:
        for where, message in errors_of(load_json(path)):
            failures.append(f"{path.relative_to(ROOT)}: {where}: {message}")

    cases = load_json(CASES_PATH)
    base = load_json(BASE_PATH)
    for case in cases["accepted"]:
        for where, message in errors_of(apply_patch(base, case["patch"])):
            failures.append(f"accepted case {case['name']}: schema rejects it: {where}: {message}")
    rejected_by_schema = 0
    for case in cases["rejected"]:
        errors = errors_of(apply_patch(base, case["patch"]))
        if "loader_only" in case:
            if errors:
                failures.append(f"rejected case {case['name']} is marked loader_only, but the schema rejects it "
                                f"({errors[0][0]}: {errors[0][1]}); remove its 'loader_only'")
            continue
        # The schema must object to the value the loader names, to an ancestor (it reports a
        # missing or unknown key at the object holding it) or to a descendant (it names the
        # offending element of an array): not to something else the patch broke.
        if any(within(case["pointer"], where) or within(where, case["pointer"]) for where, _ in errors):
            rejected_by_schema += 1
        elif errors:
            failures.append(f"rejected case {case['name']}: the schema objects elsewhere ({errors[0][0]}: "
                            f"{errors[0][1]}), not at, above or below {case['pointer']}")
        else:
            failures.append(f"rejected case {case['name']}: the schema accepts it (the loader rejects "
                            f"{case['pointer']}: {case['expected']})")

    readme = README_PATH.read_text(encoding="utf-8")
    for key in sorted({key for key, _ in defined_keys(schema)}):
        if not re.search(r"`" + re.escape(key) + r"`", readme):
            failures.append(f"configs/README.md does not document `{key}`")

    for failure in failures:
        print(f"FAIL {failure}")
    print(f"{len(scenes)} shipped scenes, {len(cases['accepted'])} accepted variants, "
          f"{rejected_by_schema} variants rejected by the schema, "
          f"{sum('loader_only' in c for c in cases['rejected'])} loader-only rules; {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
