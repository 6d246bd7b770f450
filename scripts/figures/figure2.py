#!/usr/bin/env python3
"""Draws the paper's Figure 2 (Cirio et al. 2011: time per step against particle count for a rigid,
a deformable and a fluid block) from the timings `mssph figure 2` wrote, writes them as CSV, and
prints the fitted slopes and update rates next to the paper's.

usage: figure2.py FIGURE2.h5 [--out DIR]
"""
import argparse
import csv
import os
import sys

import h5py
import numpy as np

from figure_common import plt, provenance, save, stamp, text_attribute

# The paper draws rigid dashed, deformable continuous, fluid dotted.
LINE_STYLES = {"rigid": "--", "deformable": "-", "fluid": ":"}
PAPER_RANGE = (2000, 30000)
# What the paper reports (section 5.1, Figure 2; Quadro FX 3600M, 2010): the deformable curve's
# slope about twice the fluid's and six times the rigid's; above 70 Hz for 20,000 fluid particles
# and 150 Hz for 5,000 deformable ones.
PAPER_SLOPE_RATIOS = {("deformable", "fluid"): 2.0, ("deformable", "rigid"): 6.0}
PAPER_RATES = [("fluid", 20000, "> 70 Hz"), ("deformable", 5000, "150 Hz")]


def read_timings(path):
    with h5py.File(path, "r") as h5:
        status = text_attribute(h5, "status")
        if status != "completed":
            sys.exit(f"error: {path}: status is '{status}', not 'completed': the timings are incomplete")
        media = {}
        for medium, group in h5["figure2"].items():
            media[medium] = {
                "block_particles": group["block_particles"][:],
                "particles": group["particles"][:],
                "spacing": group["spacing"][:],
                "height": group["height"][:],
                "dt": group["dt"][:],
                "steps": group["steps"][:],
                "step_time": group["step_time"][:],  # columns min, median, max [s]
                "phase_time": group["phase_time"][:],
                "phase_names": [c.decode() if isinstance(c, bytes) else str(c)
                                for c in group["phase_time"].attrs["columns"]],
            }
        return media, provenance(h5), text_attribute(h5, "geometry")


def write_csv(media, path):
    with open(path, "w", newline="") as out:
        writer = csv.writer(out)
        phases = next(iter(media.values()))["phase_names"]
        writer.writerow(["medium", "block_particles", "particles", "spacing_m", "height_m", "dt_s", "steps",
                         "min_ms", "median_ms", "max_ms"] + [f"phase_{p}_ms" for p in phases])
        for medium, m in media.items():
            for k in range(len(m["block_particles"])):
                writer.writerow([medium, int(m["block_particles"][k]), int(m["particles"][k]),
                                 f"{m['spacing'][k]:.6g}", f"{m['height'][k]:.6g}", f"{m['dt'][k]:.6g}",
                                 int(m["steps"][k])]
                                + [f"{1e3 * v:.6g}" for v in m["step_time"][k]]
                                + [f"{1e3 * v:.6g}" for v in m["phase_time"][k]])


def slope_ms_per_1000(m):
    """Least-squares slope of the median step time over the paper's range [ms per 1,000 particles]."""
    n = m["block_particles"]
    # The paper geometry rounds N to whole layers of 625 particles (2,000 -> 1,875): 10 % slack.
    inside = (n >= 0.9 * PAPER_RANGE[0]) & (n <= 1.1 * PAPER_RANGE[1])
    if inside.sum() < 2:
        return None
    return np.polyfit(n[inside] / 1000.0, 1e3 * m["step_time"][inside, 1], 1)[0]


def exponent_above(m, n_min=100000):
    """Exponent b of t ~ N^b fitted on log-log axes above n_min particles (None with fewer than 2)."""
    n = m["block_particles"]
    above = n >= n_min
    if above.sum() < 2:
        return None
    return np.polyfit(np.log(n[above]), np.log(m["step_time"][above, 1]), 1)[0]


def rate_at(m, particles):
    """Update rate [Hz] at a particle count, the median step time interpolated linearly in N."""
    n = m["block_particles"]
    if not n.min() <= particles <= n.max():
        return None
    return 1.0 / np.interp(particles, n, m["step_time"][:, 1])


def print_summary(media):
    print("Figure 2 summary (medians):")
    slopes = {medium: slope_ms_per_1000(m) for medium, m in media.items()}
    for medium, s in slopes.items():
        print(f"  {medium:<10} slope {s:.4g} ms per 1,000 particles over 2,000-30,000" if s is not None
              else f"  {medium:<10} slope: fewer than two sizes in 2,000-30,000")
    for (a, b), paper in PAPER_SLOPE_RATIOS.items():
        if slopes.get(a) is not None and slopes.get(b) is not None and slopes[b] > 0:
            print(f"  slope ratio {a}/{b}: {slopes[a] / slopes[b]:.2f} (paper ~{paper:.0f})")
    for medium, particles, paper in PAPER_RATES:
        if medium in media:
            rate = rate_at(media[medium], particles)
            shown = f"{rate:.4g} Hz" if rate is not None else "outside the timed sizes"
            print(f"  update rate, {particles:,} {medium} particles: {shown} (paper {paper} on a Quadro FX 3600M)")
    for medium, m in media.items():
        b = exponent_above(m)
        if b is not None:
            print(f"  {medium:<10} time ~ N^{b:.3f} above 100,000 particles")


def draw(media, context, geometry, folder, log_axes):
    figure, axes = plt.subplots(figsize=(6.4, 4.4))
    for medium in ("rigid", "deformable", "fluid"):
        if medium not in media:
            continue
        m = media[medium]
        t = 1e3 * m["step_time"]
        axes.errorbar(m["block_particles"], t[:, 1], yerr=[t[:, 1] - t[:, 0], t[:, 2] - t[:, 1]],
                      linestyle=LINE_STYLES[medium], color="black", marker="o", markersize=3, capsize=2,
                      label=medium)
    axes.set_xlabel("particles")
    axes.set_ylabel("time per step [ms]")
    if log_axes:
        axes.set_xscale("log")
        axes.set_yscale("log")
    axes.set_title(f"Figure 2: step time ({geometry} geometry; median, min-max bars)", fontsize=9)
    axes.legend()
    axes.grid(alpha=0.3, which="both" if log_axes else "major")
    figure.tight_layout(rect=(0, 0.03, 1, 1))
    stamp(figure, context)
    return save(figure, folder, "figure2_loglog" if log_axes else "figure2")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("timings", help="figure2.h5 written by mssph figure 2")
    parser.add_argument("--out", help="output folder (default: the timings' folder)")
    args = parser.parse_args()
    if not os.path.isfile(args.timings):
        sys.exit(f"error: {args.timings}: no such file")
    folder = args.out or os.path.dirname(os.path.abspath(args.timings))
    media, context, geometry = read_timings(args.timings)
    csv_path = os.path.join(folder, "figure2.csv")
    os.makedirs(folder, exist_ok=True)
    write_csv(media, csv_path)
    written = [csv_path] + draw(media, context, geometry, folder, log_axes=False)
    sizes = np.concatenate([m["block_particles"] for m in media.values()])
    if sizes.max() > 10 * sizes.min():
        written += draw(media, context, geometry, folder, log_axes=True)
    print_summary(media)
    print("figure 2: wrote " + ", ".join(written))


if __name__ == "__main__":
    main()
