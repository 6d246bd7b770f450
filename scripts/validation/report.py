#!/usr/bin/env python3
"""Draws report.md and its plots from the outputs of `mssph validate`.

Usage: report.py REPORT_JSON VALIDATION_H5 OUT_DIR

Reads only report.json (the table, run facts) and validation.h5 (the raw series), so the report
can be redrawn or restyled without running the cases again. Plots are PNG files in OUT_DIR,
drawn with matplotlib's Agg backend.
"""
import json
import math
import os
import re
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def fmt(x):
    if x is None:
        return "nan"
    if x == 0 or (1e-3 <= abs(x) < 1e5):
        return f"{x:.4g}"
    return f"{x:.3e}"


def file_name(text):
    """A plot's file name from its suite, case and series: runs of characters other than letters,
    digits, '.', '-' and '_' (a series may be named after a paper, with spaces) become one '_',
    so that the name is a valid Markdown link and a plain shell word."""
    return re.sub(r"[^A-Za-z0-9._-]+", "_", text)


def plot_series(h5, case, series, out_dir):
    """One PNG per series: every column against x; log-log where the case asks for it."""
    group = h5[series["hdf5_group"]]
    x = group["x"][()]
    fig, ax = plt.subplots(figsize=(6.0, 4.0))
    for k, label in enumerate(series["columns"]):
        y = group[f"y{k}"][()]
        if series["log_log"]:
            keep = (x > 0) & (y > 0)
            ax.loglog(x[keep], y[keep], "o-" if len(x) < 10 else "-", label=label)
        else:
            ax.plot(x, y, "o-" if len(x) < 10 else "-", label=label)
    ax.set_xlabel(series["x_label"])
    ax.set_title(f"{case['suite']}/{case['case']}: {series['name']}", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    name = file_name(f"{case['suite']}_{case['case']}_{series['name']}") + ".png"
    fig.savefig(os.path.join(out_dir, name), dpi=110)
    plt.close(fig)
    return name


def plot_kernel_errors(cases, out_dir):
    """Float32 backends against the reference: every bounded relative error with its bound."""
    rows = []
    for case in cases:
        if case["suite"] != "kernels":
            continue
        for check in case["checks"]:
            if check["status"] != "SKIPPED" and check["error_kind"] == "bound" and check["measured"] is not None:
                rows.append(check)
    if not rows:
        return None
    fig, ax = plt.subplots(figsize=(7.0, max(3.0, 0.18 * len(rows))))
    y = list(range(len(rows)))
    floor = 1e-12
    ax.barh(y, [max(r["measured"], floor) for r in rows], color=["tab:red" if r["status"] == "FAIL" else "tab:blue" for r in rows])
    ax.scatter([r["tolerance"] for r in rows], y, marker="|", s=120, color="black", label="bound")
    ax.set_xscale("log")
    ax.set_yticks(y)
    ax.set_yticklabels([r["quantity"] for r in rows], fontsize=6)
    ax.invert_yaxis()
    ax.set_xlabel("relative error against the float64 reference (bar), bound (|)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    name = "kernels_errors.png"
    fig.savefig(os.path.join(out_dir, name), dpi=110)
    plt.close(fig)
    return name


def main(argv):
    if len(argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    report_json, validation_h5, out_dir = argv[1:]
    with open(report_json) as f:
        report = json.load(f)
    run, cases = report["run"], report["cases"]
    lines = [
        "# mssph validation report",
        "",
        f"- mode: {run['mode']}; command: `{run['command_line']}`",
        f"- physics backend: {run['physics_backend']} ({run['physics_precision']}) on {run['physics_device']}",
        f"- kernels suite: {', '.join(run['fast_backends'])} against the float64 reference; seed {run['seed']}",
        f"- host CPU: {run['host_cpu']}; GPUs: {', '.join(run['gpus']) or 'none'}",
        f"- mssph {run['mssph_version']}, commit {run['git_commit']}, {run['date']}",
        "",
    ]
    counts = {"PASS": 0, "FAIL": 0, "SKIPPED": 0}
    for case in cases:
        counts[case["status"]] += 1
    lines += [f"**{counts['PASS']} passed, {counts['FAIL']} failed, {counts['SKIPPED']} skipped** "
              f"(each case's formula, source, set-up and tolerance reason: its folder's README.md).", ""]
    lines += ["| suite | case | status | wall time [s] |", "|---|---|---|---|"]
    for case in cases:
        lines.append(f"| {case['suite']} | [{case['case']}](#{case['suite']}-{case['case']}) | {case['status']} | "
                     f"{case['wall_seconds']:.1f} |")
    lines.append("")
    errors_plot = plot_kernel_errors(cases, out_dir)
    if errors_plot:
        lines += ["## Float32 kernels against the reference", "", f"![kernel errors]({errors_plot})", ""]
    with h5py.File(validation_h5, "r") as h5:
        for case in cases:
            lines += [f"<a id=\"{case['suite']}-{case['case']}\"></a>",
                      f"## {case['suite']} / {case['case']}: {case['status']}", "",
                      f"{case['title']} (`{case['folder']}/`).", "",
                      f"Resolution: {case['resolution'] or '-'}", ""]
            if case["details"]:
                lines += [case["details"], ""]
            if case["error"]:
                lines += [f"The case stopped with an error: `{case['error']}`", ""]
            lines += ["| quantity | backend | expected | measured | error | tolerance | status |",
                      "|---|---|---|---|---|---|---|"]
            for c in case["checks"]:
                status = c["status"] + (f" ({c['note']})" if c["note"] else "")
                if c["status"] == "SKIPPED":
                    lines.append(f"| {c['quantity']} | {c['backend']} | - | - | - | - | {status} |")
                else:
                    unit = f" {c['unit']}" if c["unit"] not in ("", "-") else ""
                    lines.append(f"| {c['quantity']} | {c['backend']} | {c['expected_text']}{unit} | {fmt(c['measured'])} | "
                                 f"{fmt(c['error'])} ({c['error_kind']}) | {fmt(c['tolerance'])} | {status} |")
            lines.append("")
            for series in case["series"]:
                name = plot_series(h5, case, series, out_dir)
                lines += [f"![{series['name']}]({name})", ""]
    with open(os.path.join(out_dir, "report.md"), "w") as f:
        f.write("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
