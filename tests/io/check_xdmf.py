"""Checks an XDMF sidecar against its HDF5 file: the sidecar must parse as XML, and every HDF
data item must name a dataset that exists with the stated dimensions and number type.

Usage: check_xdmf.py FILE.xdmf
Prints "grids N" (the temporal collection's member count) and exits 0, or prints each problem
and exits 1.
"""
import os
import sys
import xml.etree.ElementTree as ElementTree

import h5py

# XDMF NumberType and Precision of each HDF5 type the run log writes.
NUMPY_TYPES = {("Float", "4"): "float32", ("Float", "8"): "float64", ("Int", "4"): "int32"}


def main(xdmf_path):
    problems = []
    root = ElementTree.parse(xdmf_path).getroot()
    if root.tag != "Xdmf":
        problems.append(f"root element is <{root.tag}>, expected <Xdmf>")
    collections = root.findall("./Domain/Grid[@GridType='Collection']")
    if len(collections) != 1:
        problems.append(f"{len(collections)} grid collections, expected 1")
    grids = [g for c in collections for g in c.findall("Grid")]
    times = []
    directory = os.path.dirname(os.path.abspath(xdmf_path))
    for grid in grids:
        name = grid.get("Name")
        times.append(float(grid.find("Time").get("Value")))
        elements = int(grid.find("Topology").get("NumberOfElements"))
        for item in grid.iter("DataItem"):
            if item.get("Format") != "HDF":
                problems.append(f"{name}: data item in format {item.get('Format')}, expected HDF")
                continue
            file_name, _, dataset_path = item.text.strip().partition(":")
            dims = [int(d) for d in item.get("Dimensions").split()]
            if dims[0] != elements:
                problems.append(f"{name}: {dataset_path} has {dims[0]} rows for {elements} elements")
            with h5py.File(os.path.join(directory, file_name), "r") as f:
                if dataset_path not in f:
                    problems.append(f"{name}: {file_name}:{dataset_path} does not exist")
                    continue
                dataset = f[dataset_path]
                if list(dataset.shape) != dims:
                    problems.append(f"{name}: {dataset_path} has shape {list(dataset.shape)}, XDMF says {dims}")
                expected = NUMPY_TYPES.get((item.get("NumberType"), item.get("Precision")))
                if str(dataset.dtype) != expected:
                    problems.append(f"{name}: {dataset_path} is {dataset.dtype}, XDMF says {expected}")
    if times != sorted(times):
        problems.append(f"times out of order: {times}")
    for p in problems:
        print(p)
    print("grids", len(grids))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
