#!/usr/bin/env python3
"""Draws and checks the one-world scene (configs/tap_squeeze_stir.json, the paper's Figure 4 idea):
one proxy taps a rigid body, squeezes a deformable one and stirs a fluid. From its run log alone:
the rendered force and torque against time with the phases shaded, and the checks that each phase
touches the body it should, in order, and that the device's force stays within its limits.
Exit code 1 when a check fails, 2 when the log is missing or incomplete.

usage: tss.py --out DIR LOG.h5
"""
import argparse
import json
import os
import sys

import h5py
import numpy as np

from figure_common import finish_checks, plt, provenance, save, stamp, text_attribute

# A contact episode: the proxy's interaction force above this; episodes closer than MERGE_GAP
# seconds are one (a tap's bounce, a stir's passing lulls).
CONTACT_FORCE = 0.5   # [N]
MERGE_GAP = 0.15      # [s]
# The Virtuose 6D35-45's limits, the defaults of proxy/device/max_force and max_torque
# (configs/README.md) when the scene does not set them.
DEFAULT_MAX_FORCE = 30.0   # [N]
DEFAULT_MAX_TORQUE = 3.0   # [N m]
PHASE_ORDER = [("tap", "rigid"), ("squeeze", "deformable"), ("stir", "fluid")]
# Newton's third law: the body the proxy touches takes its push, so the change of that body's
# interaction force must carry at least half the proxy's peak force in the phase (the rest goes to
# the body's own supports within the sampling), and an untouched body's change at most a quarter
# of the touched one's.
TOUCHED_SHARE = 0.5
UNTOUCHED_SHARE = 0.25


def load(path):
    with h5py.File(path, "r") as h5:
        status = text_attribute(h5, "status")
        if status != "completed":
            sys.exit(f"error: {path}: status is '{status}', not 'completed'")
        config = json.loads(text_attribute(h5, "config"))
        proxy = config["proxy"]["body"]
        bodies = {name: {"kind": body["kind"], "position": np.array(body["position"]),
                         "force": h5["bodies"][name]["interaction_force"][:]}
                  for name, body in config["bodies"].items() if name != proxy and body["kind"] != "boundary"}
        device = config["proxy"].get("device", {})
        return {
            "context": provenance(h5),
            "time": h5["time"][:],
            "haptic_time": h5["haptics/time"][:],
            "proxy_position": h5["haptics/proxy/position"][:],
            "proxy_force": h5["haptics/interaction/force"][:],
            "rendered_force": h5["haptics/rendered/force"][:],
            "rendered_torque": h5["haptics/rendered/torque"][:],
            "saturation": h5["haptics/saturation"][:],
            "bodies": bodies,
            "max_force": device.get("max_force", DEFAULT_MAX_FORCE),
            "max_torque": device.get("max_torque", DEFAULT_MAX_TORQUE),
        }


def contact_phases(run):
    """[(start, end, body)]: the proxy's contact episodes, merged across short gaps, each given to
    the body whose centre is horizontally nearest the proxy during it."""
    t = run["haptic_time"]
    touching = np.linalg.norm(run["proxy_force"], axis=1) > CONTACT_FORCE
    episodes = []
    for k in np.flatnonzero(touching):
        if episodes and t[k] - episodes[-1][1] <= MERGE_GAP:
            episodes[-1][1] = t[k]
        else:
            episodes.append([t[k], t[k]])
    phases = []
    for start, end in episodes:
        inside = (t >= start) & (t <= end)
        where = run["proxy_position"][inside, :2].mean(axis=0)
        body = min(run["bodies"], key=lambda b: np.linalg.norm(run["bodies"][b]["position"][:2] - where))
        if phases and phases[-1][2] == body:
            phases[-1] = (phases[-1][0], end, body)
        else:
            phases.append((start, end, body))
    return phases


def force_changes(run, phases):
    """For each phase and body, the largest change of the body's interaction force from its value at
    rest (mean from the end of the start-up, 0.3 s, to the first contact) [N], and the proxy's peak
    force [N]. The largest change, not the mean: a body's support (the bone's ground, the blood's
    basin) takes over a steady push, but not at once."""
    t = run["time"]
    first = phases[0][0]
    rest_window = (t >= min(0.3, 0.5 * first)) & (t < first)
    changes = []
    for start, end, _ in phases:
        inside = (t >= start) & (t <= end)
        per_body = {}
        for name, body in run["bodies"].items():
            rest = body["force"][rest_window].mean(axis=0)
            per_body[name] = float(np.linalg.norm(body["force"][inside] - rest, axis=1).max())
        haptic_inside = (run["haptic_time"] >= start) & (run["haptic_time"] <= end)
        changes.append((per_body, float(np.linalg.norm(run["proxy_force"][haptic_inside], axis=1).max())))
    return changes


def checks_of(run, phases):
    checks = []
    kinds = [run["bodies"][b]["kind"] for _, _, b in phases]
    expected_kinds = [kind for _, kind in PHASE_ORDER]
    checks.append({"name": "phases in order", "measured": " -> ".join(kinds), "expected": " -> ".join(expected_kinds),
                   "passed": kinds == expected_kinds,
                   "how": "contact episodes of the proxy, each given to the horizontally nearest body"})
    if kinds == expected_kinds:
        for (label, _), (start, end, body), (per_body, proxy_peak) in zip(PHASE_ORDER, phases,
                                                                          force_changes(run, phases)):
            touched = per_body[body]
            others = {b: v for b, v in per_body.items() if b != body}
            checks.append({"name": f"{label}: {body} takes the push", "measured": touched / proxy_peak,
                           "expected": f">= {TOUCHED_SHARE}", "passed": touched >= TOUCHED_SHARE * proxy_peak,
                           "how": f"largest change of {body}'s interaction force over the proxy's peak force, "
                                  f"{start:.2f}-{end:.2f} s"})
            worst = max(others, key=others.get)
            checks.append({"name": f"{label}: other bodies untouched", "measured": others[worst] / touched,
                           "expected": f"<= {UNTOUCHED_SHARE}", "passed": others[worst] <= UNTOUCHED_SHARE * touched,
                           "how": f"largest change among the other bodies ({worst}) over {body}'s"})
    peak_force = float(np.linalg.norm(run["rendered_force"], axis=1).max())
    peak_torque = float(np.linalg.norm(run["rendered_torque"], axis=1).max())
    # The device clamps what it renders: 1e-9 relative covers the rounding of the clamp.
    checks.append({"name": "rendered force within the device limit", "measured": peak_force,
                   "expected": f"<= {run['max_force']:g} N", "passed": peak_force <= run["max_force"] * (1 + 1e-9),
                   "how": "largest |rendered force|"})
    checks.append({"name": "rendered torque within the device limit", "measured": peak_torque,
                   "expected": f"<= {run['max_torque']:g} N m",
                   "passed": peak_torque <= run["max_torque"] * (1 + 1e-9), "how": "largest |rendered torque|"})
    return checks


def draw(run, phases, folder):
    figure, (force, torque, bodies) = plt.subplots(3, 1, figsize=(7.5, 7.5), sharex=True)
    t = run["haptic_time"]
    for axis, data, name, unit in ((force, run["rendered_force"], "force", "N"),
                                   (torque, run["rendered_torque"], "torque", "N m")):
        for c, label in enumerate("xyz"):
            axis.plot(t, data[:, c], linewidth=0.8, label=label)
        axis.plot(t, np.linalg.norm(data, axis=1), color="black", linewidth=1.0, label="magnitude")
        axis.set_ylabel(f"rendered {name} [{unit}]")
        axis.legend(fontsize=7, ncol=4, loc="upper left")
    rest = run["time"] < phases[0][0] if phases else np.ones_like(run["time"], dtype=bool)
    for name, body in run["bodies"].items():
        change = np.linalg.norm(body["force"] - body["force"][rest][-100:].mean(axis=0), axis=1)
        bodies.plot(run["time"], change, linewidth=0.8, label=f"{name} ({body['kind']})")
    bodies.set_ylabel("change of interaction force [N]")
    bodies.set_xlabel("time [s]")
    bodies.legend(fontsize=7)
    labels = dict((kind, label) for label, kind in PHASE_ORDER)
    for axis in (force, torque, bodies):
        axis.grid(alpha=0.3)
        for start, end, body in phases:
            axis.axvspan(start, end, color="0.85", zorder=0)
    for start, end, body in phases:
        force.text(0.5 * (start + end), force.get_ylim()[1], f"{labels.get(run['bodies'][body]['kind'], '?')} {body}",
                   ha="center", va="bottom", fontsize=8)
    figure.tight_layout(rect=(0, 0.03, 1, 0.97))
    stamp(figure, run["context"])
    return save(figure, folder, "tss")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("log", help="run log of configs/tap_squeeze_stir.json")
    parser.add_argument("--out", required=True, help="output folder")
    args = parser.parse_args()
    if not os.path.isfile(args.log):
        sys.exit(f"error: {args.log}: no such file")
    run = load(args.log)
    phases = contact_phases(run)
    written = draw(run, phases, args.out)
    checks = checks_of(run, phases)
    saturation = run["saturation"].mean(axis=0) if len(run["saturation"]) else np.zeros(3)
    print(f"{'check':<42}{'measured':>22}  {'expected':<26}result")
    for c in checks:
        shown = f"{c['measured']:.4g}" if isinstance(c["measured"], float) else c["measured"]
        print(f"{c['name']:<42}{shown:>22}  {c['expected']:<26}{'PASS' if c['passed'] else 'FAIL'}")
    print(f"device saturation: force {100 * saturation[0]:.1f} %, torque {100 * saturation[1]:.1f} %, "
          f"workspace {100 * saturation[2]:.1f} % of haptic ticks")
    report = {"log": os.path.abspath(args.log), "context": run["context"],
              "phases": [{"start": s, "end": e, "body": b, "kind": run["bodies"][b]["kind"]} for s, e, b in phases],
              "saturation_ratio": {"force": float(saturation[0]), "torque": float(saturation[1]),
                                   "workspace": float(saturation[2])},
              "checks": checks}
    finish_checks(report, args.out, "tss_checks", "figure tss", written)


if __name__ == "__main__":
    main()
