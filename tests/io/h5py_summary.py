"""Prints what h5py sees in an HDF5 file as JSON, for the C++ tests to compare with what they wrote.

Usage: h5py_summary.py FILE
Output: {"attributes": {name: value}, "objects": {path: {"kind": "group" | "dataset",
"attributes": {...}, "shape": [...], "dtype": "float64", "data": [flattened values]}}}
"""
import json
import sys

import h5py
import numpy


def plain(value):
    """An attribute or dataset value as JSON: strings decoded, arrays as lists, Empty as None."""
    if isinstance(value, h5py.Empty):
        return None
    if isinstance(value, bytes):
        return value.decode("utf-8")
    if isinstance(value, numpy.ndarray):
        return [plain(v) for v in value.ravel().tolist()]
    if isinstance(value, numpy.generic):
        return value.item()
    return value


def attributes(obj):
    return {name: plain(obj.attrs[name]) for name in obj.attrs}


def main(path):
    objects = {}

    def visit(name, obj):
        entry = {"attributes": attributes(obj)}
        if isinstance(obj, h5py.Dataset):
            entry.update(kind="dataset", shape=list(obj.shape), dtype=str(obj.dtype), data=plain(obj[()]))
        else:
            entry["kind"] = "group"
        objects["/" + name] = entry

    with h5py.File(path, "r") as f:
        f.visititems(visit)
        json.dump({"attributes": attributes(f), "objects": objects}, sys.stdout)


if __name__ == "__main__":
    main(sys.argv[1])
