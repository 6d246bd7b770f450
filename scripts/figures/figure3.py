#!/usr/bin/env python3
"""Draws the paper's Figure 3 (Cirio et al. 2011: forces on a sphere dropped on rigid, deformable and
fluid blocks) from the three sphere-drop run logs, checks each curve's shape against physics, prints
the checks and writes them to DIR/figure3_checks.json. Exit code 1 when a check fails, 2 when a log
is missing, incomplete or not a sphere drop.

usage: figure3.py --out DIR [--resolution NAME] LOG.h5 [LOG.h5 ...]
"""
import argparse
import os
import sys

import numpy as np

from drop_log import DropLog
from figure3_checks import deformable_checks, fluid_checks, rigid_checks
from figure_common import finish_checks, plt, save, stamp

LINE_STYLES = {"rigid": "--", "deformable": "-", "fluid": ":"}
MEDIA = ("rigid", "deformable", "fluid")


def load(paths):
    drops = {}
    for path in paths:
        try:
            drop = DropLog(path)
        except (OSError, KeyError, ValueError) as error:
            sys.exit(f"error: {path}: not a readable sphere-drop run log ({error})")
        if drop.status != "completed":
            sys.exit(f"error: {path}: status is '{drop.status}', not 'completed'")
        if drop.block_kind not in MEDIA:
            sys.exit(f"error: {path}: its block is {drop.block_kind}, expected one of {', '.join(MEDIA)}")
        drops[drop.block_kind] = drop
    return drops


def draw(drops, folder, resolution):
    figure, (interaction, rendered) = plt.subplots(2, 1, figsize=(7.0, 6.4), sharex=True)
    for medium in MEDIA:
        if medium not in drops:
            continue
        d = drops[medium]
        interaction.plot(d.time, np.linalg.norm(d.force, axis=1), LINE_STYLES[medium], color="tab:orange",
                         linewidth=2.0, alpha=0.6, label=f"{medium}: magnitude")
        interaction.plot(d.time, d.fz, LINE_STYLES[medium], color="black", linewidth=1.0, label=f"{medium}: vertical")
        rendered.plot(d.haptic_time, np.linalg.norm(d.rendered_force, axis=1), LINE_STYLES[medium], color="black",
                      linewidth=1.0, label=medium)
    interaction.set_ylabel("interaction force on the sphere [N]")
    interaction.legend(fontsize=7, ncol=3)
    interaction.grid(alpha=0.3)
    rendered.set_ylabel("force rendered by the device [N]")
    rendered.set_xlabel("time [s]")
    rendered.legend(fontsize=7)
    rendered.grid(alpha=0.3)
    interaction.set_title("Figure 3: a 20 cm sphere dropped on rigid, deformable and fluid blocks", fontsize=9)
    figure.tight_layout(rect=(0, 0.03, 1, 1))
    any_drop = next(iter(drops.values()))
    stamp(figure, any_drop.context, f"{resolution} resolution, spacing {any_drop.spacing:g} m")
    return save(figure, folder, "figure3")


def all_checks(drops):
    checks = []
    if "rigid" in drops:
        checks += rigid_checks(drops["rigid"])
    if "deformable" in drops:
        checks += deformable_checks(drops["deformable"], drops.get("rigid"))
    if "fluid" in drops:
        checks += fluid_checks(drops["fluid"])
    return checks


def print_table(checks):
    print(f"{'medium':<11}{'check':<42}{'measured':>12}  {'expected':<16}{'tol':>6}  result")
    for c in checks:
        tolerance = f"{100 * c['tolerance']:.0f}%" if c["tolerance"] is not None else ""
        expected = f"{c['expected']:.4g}" if isinstance(c["expected"], float) else str(c["expected"])
        print(f"{c['medium']:<11}{c['name']:<42}{c['measured']:>12.4g}  {expected + ' ' + c['unit']:<16}"
              f"{tolerance:>6}  {'PASS' if c['passed'] else 'FAIL'}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("logs", nargs="+", help="run logs of configs/sphere_drop_{rigid,deformable,fluid}.json")
    parser.add_argument("--out", required=True, help="output folder")
    parser.add_argument("--resolution", default="custom", help="label for the figure (coarse, paper, fine)")
    args = parser.parse_args()
    for path in args.logs:
        if not os.path.isfile(path):
            sys.exit(f"error: {path}: no such file")
    drops = load(args.logs)
    written = draw(drops, args.out, args.resolution)
    checks = all_checks(drops)
    print_table(checks)
    report = {
        "resolution": args.resolution,
        "logs": {medium: os.path.abspath(d.path) for medium, d in drops.items()},
        "context": next(iter(drops.values())).context,
        "checks": checks,
    }
    finish_checks(report, args.out, "figure3_checks", "figure 3", written)


if __name__ == "__main__":
    main()
