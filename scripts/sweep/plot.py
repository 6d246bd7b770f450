#!/usr/bin/env python3
"""Plots of a merged sweep: `mssph sweep plot DIR [--metric M]` runs this on DIR/summary.h5.

For each metric (or the one asked for): the metric against the first parameter, one line per value
of the second parameter if there is one; log axes for parameters swept on a log range; repetitions
(seeds) averaged, with bars from their minimum to their maximum. With two parameters combined as a
product, also a heat map of the metric over both. Only completed points are drawn. Files:
DIR/plots/<metric>.png and .svg, DIR/plots/<metric>_heatmap.png and .svg.

Exit codes: 0 written; 2 no summary, an unknown metric, or more than two parameters.
"""
import argparse
import collections
import pathlib
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
matplotlib.rcParams["svg.fonttype"] = "none"  # SVG text stays text: editable and searchable
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)


def text_list(values):
    return [v.decode() if isinstance(v, bytes) else str(v) for v in values]


def axis_values(column):
    """Sorted distinct values of a parameter column, and whether they are numbers."""
    numeric = column.dtype.kind in "biuf"
    values = column if numeric else np.asarray(text_list(column))
    return sorted(set(values.tolist())), numeric


def mean_and_range(rows, metric_column):
    values = metric_column[rows]
    return values.mean(), values.min(), values.max()


def save(figure, folder, stem):
    paths = []
    for suffix in (".png", ".svg"):
        path = folder / (stem + suffix)
        figure.savefig(path, dpi=150, bbox_inches="tight")
        paths.append(path)
    plt.close(figure)
    return paths


def label(name, unit):
    return f"{name} [{unit}]" if unit else name


def line_plot(summary, metric, unit, folder):
    names, scales, table, completed = summary["parameters"], summary["scales"], summary["table"], summary["completed"]
    x_name = names[0]
    x_values, x_numeric = axis_values(table[x_name])
    x_column = table[x_name] if x_numeric else np.asarray(text_list(table[x_name]))
    groups = [(None, completed)]
    # Zipped parameters move together: their points form one line along the first.
    if len(names) == 2 and summary["combine"] == "product":
        line_name = names[1]
        line_values, line_numeric = axis_values(table[line_name])
        line_column = table[line_name] if line_numeric else np.asarray(text_list(table[line_name]))
        groups = [(f"{line_name} = {v:g}" if line_numeric else f"{line_name} = {v}", completed & (line_column == v))
                  for v in line_values]
    figure, axes = plt.subplots(figsize=(6.4, 4.4))
    for legend, selected in groups:
        xs, means, lows, highs = [], [], [], []
        for i, x in enumerate(x_values):
            rows = selected & (x_column == x)
            if not rows.any():
                continue
            mean, low, high = mean_and_range(rows, table[metric])
            xs.append(x if x_numeric else i)
            means.append(mean)
            lows.append(mean - low)
            highs.append(high - mean)
        if xs:
            axes.errorbar(xs, means, yerr=[lows, highs], marker="o", capsize=3, label=legend)
    if x_numeric and scales[0] == "log":
        axes.set_xscale("log")
    if not x_numeric:
        axes.set_xticks(range(len(x_values)), [str(v) for v in x_values])
    axes.set_xlabel(x_name)
    axes.set_ylabel(label(metric, unit))
    axes.set_title(f"sweep {summary['name']}: {metric}")
    axes.grid(True, which="both", alpha=0.3)
    if len(groups) > 1:
        axes.legend(fontsize="small")
    return save(figure, folder, metric)


def heat_map(summary, metric, unit, folder):
    names, table, completed = summary["parameters"], summary["table"], summary["completed"]
    (x_values, x_numeric), (y_values, y_numeric) = axis_values(table[names[0]]), axis_values(table[names[1]])
    x_column = table[names[0]] if x_numeric else np.asarray(text_list(table[names[0]]))
    y_column = table[names[1]] if y_numeric else np.asarray(text_list(table[names[1]]))
    grid = np.full((len(y_values), len(x_values)), np.nan)
    for j, y in enumerate(y_values):
        for i, x in enumerate(x_values):
            rows = completed & (x_column == x) & (y_column == y)
            if rows.any():
                grid[j, i] = table[metric][rows].mean()
    figure, axes = plt.subplots(figsize=(6.4, 4.8))
    # Cells by index, labelled with the values: even and readable for log and uneven ranges alike.
    image = axes.imshow(grid, origin="lower", aspect="auto", cmap="viridis")
    axes.set_xticks(range(len(x_values)), [f"{v:g}" if x_numeric else str(v) for v in x_values], rotation=45)
    axes.set_yticks(range(len(y_values)), [f"{v:g}" if y_numeric else str(v) for v in y_values])
    axes.set_xlabel(names[0])
    axes.set_ylabel(names[1])
    axes.set_title(f"sweep {summary['name']}: {metric} (blank: not completed)")
    figure.colorbar(image, ax=axes, label=label(metric, unit))
    return save(figure, folder, metric + "_heatmap")


def read_summary(path):
    with h5py.File(path, "r") as f:
        table = {name: f["table"][name][()] for name in f["table"]}
        return {
            "name": str(f.attrs["name"]),
            "parameters": text_list(f.attrs["parameters"]),
            "scales": text_list(f.attrs["parameter_scales"]),
            "metrics": text_list(f.attrs["metrics"]),
            "units": text_list(f.attrs["metric_units"]),
            "combine": str(f.attrs["combine"]),
            "table": table,
            "completed": np.asarray(text_list(table["state"])) == "completed",
        }


def main(argv):
    parser = argparse.ArgumentParser(description="Plot a merged mssph sweep.")
    parser.add_argument("directory", type=pathlib.Path)
    parser.add_argument("--metric")
    args = parser.parse_args(argv)
    path = args.directory / "summary.h5"
    if not path.is_file():
        print(f"error: {path}: no summary; run `mssph sweep merge {args.directory}` first", file=sys.stderr)
        return 2
    summary = read_summary(path)
    numeric = collections.OrderedDict(
        (m, u) for m, u in zip(summary["metrics"], summary["units"]) if summary["table"][m].dtype.kind in "biuf")
    if args.metric and args.metric not in numeric:
        print(f"error: --metric {args.metric}: this summary's numeric metrics are {', '.join(numeric)}", file=sys.stderr)
        return 2
    if len(summary["parameters"]) > 2:
        print(f"error: {path}: {len(summary['parameters'])} parameters; plots show one or two", file=sys.stderr)
        return 2
    if not summary["completed"].any():
        print(f"error: {path}: no completed point to plot", file=sys.stderr)
        return 1
    folder = args.directory / "plots"
    folder.mkdir(exist_ok=True)
    written = []
    for metric, unit in numeric.items():
        if args.metric and metric != args.metric:
            continue
        written += line_plot(summary, metric, unit, folder)
        if len(summary["parameters"]) == 2 and summary["combine"] == "product":
            written += heat_map(summary, metric, unit, folder)
    print("\n".join(str(p) for p in written))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
