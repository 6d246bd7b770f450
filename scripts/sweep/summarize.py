#!/usr/bin/env python3
"""Summary of a sweep's output folder: `mssph sweep merge DIR` runs this (and so does a sweep that
ran every point itself).

Reads DIR/sweep.json (the points, written by `mssph sweep`) and every point's log that exists, and
writes

  DIR/summary.h5   root attributes: the sweep (name, files, parameter names, paths and scales,
                   metric names and units, counts); /table/<column>: one row per point in sweep
                   order (/table's attribute `columns` gives the column order) (index, point, seed with repetitions, each parameter, each metric, state);
                   /points/point-<hash>: a group per point with its parameter values as attributes
                   and, when its log exists, `log`, an HDF5 external link to that log's root
  DIR/summary.csv  the same table

A point's state: completed, failed (its log says "failed: ..."), interrupted, incomplete (a log
still "running": in progress, or left by a killed run) or missing (no log yet). Metrics come
from scripts/analysis/log_metrics.py, computed on whatever each log holds; a missing point's are
NaN (empty in the CSV). The points that are not completed are listed on stdout.

Exit codes: 0 written; 2 DIR is not a sweep's folder, or its sweep.json is damaged.
"""
import csv
import datetime
import json
import math
import os
import pathlib
import sys

# Logs of points still running are read while their runs write them.
os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")

import h5py  # noqa: E402  (after the environment it reads)
import numpy as np  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "analysis"))
import log_metrics  # noqa: E402


def point_state(status):
    """The state a log's status means, as `mssph sweep` judges it when resuming."""
    if status == "completed":
        return "completed"
    if status.startswith("interrupted") or status.startswith("failed: interrupted"):
        return "interrupted"
    if status.startswith("failed"):
        return "failed"
    return "incomplete"


def read_point(directory, point, metrics):
    # `mssph run` publishes a log under its name only once completed; a failed, interrupted or
    # running one is at <log>.partial.
    path = directory / point["log"]
    if not path.exists():
        path = path.with_name(path.name + ".partial")
    if not path.exists():
        return "missing", {name: (math.nan if name != "final_status" else "") for name in metrics}
    try:
        values = log_metrics.compute_metrics(str(path), metrics)
        with h5py.File(path, "r") as f:
            status = log_metrics._attribute_text(f.attrs.get("status", ""))
    except (OSError, KeyError, ValueError) as error:  # a log being created, or cut short
        print(f"note: {path}: unreadable now ({error})", file=sys.stderr)
        return "incomplete", {name: (math.nan if name != "final_status" else "unreadable") for name in metrics}
    return point_state(status), values


def column_array(values):
    """Numbers as int64 or float64, anything else as UTF-8 strings (JSON text for lists)."""
    if all(isinstance(v, bool) for v in values):
        return np.asarray(values, dtype=bool)
    if all(isinstance(v, int) and not isinstance(v, bool) for v in values):
        return np.asarray(values, dtype=np.int64)
    if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
        return np.asarray(values, dtype=float)
    texts = [v if isinstance(v, str) else json.dumps(v) for v in values]
    return np.asarray(texts, dtype=h5py.string_dtype())


def write_h5(path, manifest, columns, units, states, directory):
    partial = path.with_name(path.name + ".partial")
    with h5py.File(partial, "w") as f:
        f.attrs["format"] = "mssph sweep summary 1"
        for key in ("name", "description", "sweep_file", "scene", "backend", "combine", "mssph_version", "git_commit"):
            f.attrs[key] = str(manifest.get(key, ""))
        f.attrs["command_line_overrides"] = json.dumps(manifest["command_line_overrides"])
        f.attrs["parameters"] = [p["name"] for p in manifest["parameters"]]
        f.attrs["parameter_paths"] = [p["path"] for p in manifest["parameters"]]
        f.attrs["parameter_scales"] = [p["scale"] for p in manifest["parameters"]]
        f.attrs["metrics"] = manifest["metrics"]
        f.attrs["metric_units"] = [log_metrics.METRICS[m][0] for m in manifest["metrics"]]
        f.attrs["created"] = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
        for state in ("completed", "failed", "interrupted", "incomplete", "missing"):
            f.attrs[state] = sum(1 for s in states if s == state)
        table = f.create_group("table")
        table.attrs["columns"] = list(columns)  # the table's column order (HDF5 lists members by name)
        for name, values in columns.items():
            d = table.create_dataset(name, data=column_array(values))
            if units.get(name):
                d.attrs["units"] = units[name]
        for point, state in zip(manifest["points"], states):
            g = f.create_group(f"points/point-{point['hash']}")
            g.attrs["index"] = point["index"]
            g.attrs["state"] = state
            if point["seed"] is not None:
                g.attrs["seed"] = point["seed"]
            for name, value in point["parameters"].items():
                g.attrs[name] = value if isinstance(value, (int, float, str)) else json.dumps(value)
            g.attrs["overrides"] = point["overrides"]
            if (directory / point["log"]).exists():
                # Relative to summary.h5's folder, so the folder can be moved or copied whole.
                g["log"] = h5py.ExternalLink(point["log"], "/")
    os.replace(partial, path)


def write_csv(path, columns):
    partial = path.with_name(path.name + ".partial")
    names = list(columns)
    with open(partial, "w", newline="") as out:
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(names)
        for row in zip(*(columns[n] for n in names)):
            writer.writerow(["" if isinstance(v, float) and math.isnan(v) else
                             (repr(v) if isinstance(v, float) else v if isinstance(v, (int, str)) else json.dumps(v))
                             for v in row])
    os.replace(partial, path)


class DamagedManifest(Exception):
    """sweep.json is not what `mssph sweep` writes."""


def expect(condition, what):
    if not condition:
        raise DamagedManifest(what)


def read_manifest(path):
    """DIR/sweep.json, checked for every key this script reads: a damaged file is an error that says
    what is wrong, not a traceback."""
    try:
        manifest = json.loads(path.read_text())
    except (ValueError, UnicodeDecodeError) as error:
        raise DamagedManifest(f"not JSON ({error})") from None
    expect(isinstance(manifest, dict), "not a JSON object")
    for key, kind in (("name", str), ("metrics", list), ("points", list), ("seeds", list),
                      ("parameters", list), ("command_line_overrides", list)):
        expect(isinstance(manifest.get(key), kind), f"no \"{key}\" {kind.__name__}")
    for metric in manifest["metrics"]:
        expect(metric in log_metrics.METRICS, f"/metrics: unknown metric {json.dumps(metric)}")
    for i, parameter in enumerate(manifest["parameters"]):
        expect(isinstance(parameter, dict) and all(isinstance(parameter.get(k), str) for k in ("name", "path", "scale")),
               f"/parameters/{i}: expected an object with \"name\", \"path\" and \"scale\" strings")
    names = [parameter["name"] for parameter in manifest["parameters"]]
    for i, point in enumerate(manifest["points"]):
        where = f"/points/{i}"
        expect(isinstance(point, dict), f"{where}: expected an object")
        expect(isinstance(point.get("index"), int) and isinstance(point.get("hash"), str) and
               isinstance(point.get("log"), str) and isinstance(point.get("overrides"), list),
               f"{where}: expected \"index\" (a number), \"hash\" and \"log\" (strings) and \"overrides\" (a list)")
        expect(point.get("seed") is None or isinstance(point["seed"], int), f"{where}/seed: expected a number or null")
        expect(isinstance(point.get("parameters"), dict) and all(n in point["parameters"] for n in names),
               f"{where}/parameters: expected a value for each of {', '.join(names)}")
    return manifest


def main(argv):
    if len(argv) != 1:
        print("usage: summarize.py DIR", file=sys.stderr)
        return 2
    directory = pathlib.Path(argv[0])
    manifest_path = directory / "sweep.json"
    if not manifest_path.is_file():
        print(f"error: {directory}: no sweep.json: not the --out folder of an mssph sweep", file=sys.stderr)
        return 2
    try:
        manifest = read_manifest(manifest_path)
    except DamagedManifest as error:
        print(f"error: {manifest_path}: damaged: {error}; running the sweep again (mssph sweep SWEEP.json --out "
              f"{directory}) rewrites it", file=sys.stderr)
        return 2
    metrics = manifest["metrics"]
    points = manifest["points"]

    columns = {"index": [p["index"] for p in points], "point": [p["hash"] for p in points]}
    if manifest["seeds"]:
        columns["seed"] = [p["seed"] for p in points]
    for parameter in manifest["parameters"]:
        columns[parameter["name"]] = [p["parameters"][parameter["name"]] for p in points]
    units = {name: log_metrics.METRICS[name][0] for name in metrics}
    states = []
    metric_values = {name: [] for name in metrics}
    for point in points:
        state, values = read_point(directory, point, metrics)
        states.append(state)
        for name in metrics:
            metric_values[name].append(values[name])
    columns.update(metric_values)
    columns["state"] = states

    write_h5(directory / "summary.h5", manifest, columns, units, states, directory)
    write_csv(directory / "summary.csv", columns)
    counts = {s: states.count(s) for s in ("completed", "failed", "interrupted", "incomplete", "missing")}
    print(f"sweep {manifest['name']}: {directory / 'summary.h5'}, {directory / 'summary.csv'}: {len(points)} points, " +
          ", ".join(f"{n} {s}" for s, n in counts.items()))
    for point, state in zip(points, states):
        if state != "completed":
            values = " ".join(f"{k}={json.dumps(v)}" for k, v in point["parameters"].items())
            seed = f" seed={point['seed']}" if point["seed"] is not None else ""
            print(f"  {state}: point {point['index']} {point['log']} ({values}{seed})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
