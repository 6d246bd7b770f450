"""Figure 3 across resolutions: per medium, the first impact's peak force, its width at half
maximum and its contact duration, and the settled state, at each resolution, and their relative
change between the two finest. Reads
the run logs that `mssph figure 3 --out DIR` leaves in each DIR, writes
OUT/figure3_resolutions.json and .md, and prints the table.

    figure3_resolutions.py --out OUT DIR [DIR ...]

Exit code 2 when a folder lacks a drop's log."""
import argparse
import json
import os
import sys

import numpy as np

from drop_log import DropLog
from figure3_checks import SETTLE_WINDOW, first_contact, peak_width

MEDIA = ("rigid", "deformable", "fluid")
# The quantities whose change between the two finest resolutions is reported.
CHANGES = ("peak_force", "peak_width", "contact_duration")


def summary(log):
    """The first impact (peak force [N], its full width at half maximum [s], contact duration [s],
    impact speed [m/s]) and the settled
    state (RMS vertical speed over the last SETTLE_WINDOW over the measured impact speed, where
    Figure 3's check takes the free fall's sqrt(2 g h); mean upward force there over the weight)
    of one drop. A sphere afloat has neither width nor duration: its force never falls back."""
    contact = first_contact(log)
    settled = log.settled(SETTLE_WINDOW)
    row = {"spacing": log.spacing, "peak_force": None, "peak_width": None, "contact_duration": None,
           "impact_speed": None,
           "settled_speed_ratio": None, "settled_support": float(np.mean(log.fz[settled]) / log.weight)}
    if contact is None:
        return row
    start, peak, end = contact
    impact_speed = float(-log.vz[:start + 1].min())
    afloat = end == len(log.time) - 1  # the first contact lasts to the end of the run
    duration = None if afloat else float(log.time[end] - log.time[start])
    width = None if afloat else float(peak_width(log, peak))
    row.update(peak_force=float(log.fz[peak]), peak_width=width, contact_duration=duration,
               impact_speed=impact_speed,
               settled_speed_ratio=float(np.sqrt(np.mean(log.vz[settled] ** 2)) / impact_speed))
    return row


def relative_change(rows, key):
    """(finest - second finest) / second finest of rows[key], rows ordered coarse to fine."""
    if len(rows) < 2 or rows[-1][key] is None or rows[-2][key] is None:
        return None
    return rows[-1][key] / rows[-2][key] - 1.0


def table(media):
    """The markdown table: a row per medium and resolution, then a row per medium of changes."""
    def cell(value, digits=4):
        return "-" if value is None else f"{value:.{digits}g}"
    lines = ["| medium | dx [m] | first peak force [N] | its width at half maximum [s] | first contact [s] "
             "| settled speed / impact speed | support / weight |",
             "|---|---|---|---|---|---|---|"]
    for medium, rows in media.items():
        for r in rows:
            lines.append(f"| {medium} | {cell(r['spacing'])} | {cell(r['peak_force'])} | {cell(r['peak_width'], 3)} | "
                         f"{cell(r['contact_duration'])} | {cell(r['settled_speed_ratio'], 3)} | "
                         f"{cell(r['settled_support'], 3)} |")
    lines += ["", "| medium | change of the peak force, two finest | of its width | of the contact duration |",
              "|---|---|---|---|"]
    for medium, rows in media.items():
        changes = [relative_change(rows, key) for key in CHANGES]
        lines.append(f"| {medium} | " + " | ".join("-" if c is None else f"{100 * c:+.1f} %" for c in changes) + " |")
    lines += ["", "A first contact that lasts to the end of the run (a sphere afloat) has no width or duration (-)."]
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folders", nargs="+", help="output folders of `mssph figure 3`, one per resolution")
    parser.add_argument("--out", required=True, help="folder for figure3_resolutions.json and .md")
    args = parser.parse_args()
    logs = {}
    for folder in args.folders:
        for medium in MEDIA:
            path = os.path.join(folder, f"sphere_drop_{medium}.h5")
            if not os.path.isfile(path):
                print(f"figure3_resolutions.py: {folder}: no sphere_drop_{medium}.h5 there", file=sys.stderr)
                sys.exit(2)
            logs.setdefault(medium, []).append(DropLog(path))
    media = {m: sorted((summary(log) for log in logs[m]), key=lambda r: -r["spacing"]) for m in MEDIA}
    report = {"media": media,
              "changes": {m: {k: relative_change(rows, k) for k in CHANGES}
                          for m, rows in media.items()},
              "context": [logs[m][0].context for m in MEDIA]}
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "figure3_resolutions.json"), "w") as out:
        json.dump(report, out, indent=2)
    text = table(media)
    with open(os.path.join(args.out, "figure3_resolutions.md"), "w") as out:
        out.write(text)
    print(text, end="")


if __name__ == "__main__":
    main()
