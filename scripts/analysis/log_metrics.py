#!/usr/bin/env python3
"""Per-run metrics of an mssph run log: the one definition of each.

Each metric is a plain function of NumPy arrays (what the log stores) returning a float, so that
sweeps (scripts/sweep/summarize.py), figures and users' notebooks compute the same numbers. The
thin loader `read_log` takes what the metrics need from a run log (layout: docs/run-log.md);
`compute_metrics` applies them.

The metrics, all in SI units:

  peak_interaction_force   N    max over logged samples of |F|, F the sum of the SPH forces of other
                                bodies on the proxy body's particles (/bodies/<proxy>/interaction_force,
                                paper eq. 8)
  time_to_peak             s    simulated time of that maximum (its first sample)
  penetration_depth        m    how far the proxy's centre of mass moves down (along gravity) from
                                contact onset to its lowest point after it; contact onset is the first
                                sample where |F| reaches CONTACT_FRACTION of its peak. 0 without contact
  rebound_height           m    how far the centre of mass rises from that lowest point to its highest
                                point after it. 0 without contact
  settle_time              s    simulated time from which the centre of mass stays within
                                SETTLE_FRACTION of its largest distance from its final position (the
                                classic 2 % settling time); a run that has not settled reports a time
                                near its end
  peak_rendered_force      N    max over haptic ticks of |rendered force| (/haptics/rendered/force):
                                what the hand feels, after scaling and clamping
  saturation_ratio         1    fraction of haptic ticks with any saturation flag (force clamp, torque
                                clamp, workspace stop; /haptics/saturation)
  coupling_energy_balance  J    the passivity observer's energy at the last tick
                                (/haptics/injected_energy): work the virtual coupling did on proxy and
                                handle; <= 0 for a passive coupling (Hannaford and Ryu 2002)
  mean_step_time           s    mean wall-clock time of a simulation step (/timing/step_wall_time)
  real_time_factor         1    wall-clock seconds per simulated second over the steps' compute: the
                                summed step times over steps x dt; below 1 is faster than real time
  final_status             -    the log's status: "completed", "failed: <reason>", "running" (a killed
                                run), ...

A metric the log cannot give (no proxy, no haptic loop, no steps) is NaN.

Command line: `log_metrics.py --list` prints the metric names; `log_metrics.py LOG.h5 ...` prints
each log's metrics as JSON.
"""
import json
import math
import sys

import numpy as np

# Contact onset: |F| at 1 % of its peak. Small enough to catch the first touch, large enough that
# the float32 noise of a body at rest far from others (|F| ~ 1e-6 of a contact force) never counts.
CONTACT_FRACTION = 0.01
# Settling band, as a fraction of the largest distance from the final position.
SETTLE_FRACTION = 0.02


def _norms(vectors):
    return np.linalg.norm(np.asarray(vectors, dtype=float).reshape(-1, 3), axis=1)


def peak_interaction_force(force):
    """Max |F| over samples; force is (n, 3) [N]."""
    norms = _norms(force)
    return float(norms.max()) if norms.size else math.nan


def time_to_peak(time, force):
    """Simulated time [s] of the first sample where |F| is largest."""
    norms = _norms(force)
    return float(np.asarray(time, dtype=float)[int(np.argmax(norms))]) if norms.size else math.nan


def _heights(centre_of_mass, down):
    """Height against gravity: -(x . down) with down a unit vector."""
    down = np.asarray(down, dtype=float)
    return -np.asarray(centre_of_mass, dtype=float).reshape(-1, 3) @ (down / np.linalg.norm(down))


def _contact_onset(force):
    """Index of the first sample with |F| >= CONTACT_FRACTION * peak, or None without contact."""
    norms = _norms(force)
    if norms.size == 0 or norms.max() <= 0.0:
        return None
    return int(np.argmax(norms >= CONTACT_FRACTION * norms.max()))


def penetration_depth(force, centre_of_mass, down):
    """Drop of the centre of mass [m] from contact onset to its lowest point after it."""
    if len(force) == 0:
        return math.nan
    onset = _contact_onset(force)
    if onset is None:
        return 0.0
    h = _heights(centre_of_mass, down)
    return float(h[onset] - h[onset:].min())


def rebound_height(force, centre_of_mass, down):
    """Rise of the centre of mass [m] from its lowest point after contact onset to its highest after that."""
    if len(force) == 0:
        return math.nan
    onset = _contact_onset(force)
    if onset is None:
        return 0.0
    h = _heights(centre_of_mass, down)
    lowest = onset + int(np.argmin(h[onset:]))
    return float(h[lowest:].max() - h[lowest])


def settle_time(time, centre_of_mass):
    """First time [s] from which |x - x_final| stays within SETTLE_FRACTION of its maximum."""
    x = np.asarray(centre_of_mass, dtype=float).reshape(-1, 3)
    t = np.asarray(time, dtype=float)
    if t.size == 0:
        return math.nan
    distance = np.linalg.norm(x - x[-1], axis=1)
    outside = np.nonzero(distance > SETTLE_FRACTION * distance.max())[0]
    return float(t[0]) if outside.size == 0 else float(t[outside[-1] + 1])


def peak_rendered_force(rendered_force):
    """Max |rendered force| over haptic ticks [N]."""
    return peak_interaction_force(rendered_force)


def saturation_ratio(saturation):
    """Fraction of ticks with any of the (n, 3) saturation flags set."""
    flags = np.asarray(saturation, dtype=float).reshape(-1, 3)
    return float(np.any(flags != 0.0, axis=1).mean()) if flags.shape[0] else math.nan


def coupling_energy_balance(injected_energy):
    """The passivity observer's energy at the last tick [J]."""
    e = np.asarray(injected_energy, dtype=float)
    return float(e[-1]) if e.size else math.nan


def mean_step_time(step_wall_time):
    """Mean wall-clock time of a step [s]."""
    s = np.asarray(step_wall_time, dtype=float)
    return float(s.mean()) if s.size else math.nan


def real_time_factor(step_wall_time, dt):
    """Summed step wall time over simulated time (steps x dt)."""
    s = np.asarray(step_wall_time, dtype=float)
    return float(s.sum() / (s.size * dt)) if s.size and dt > 0 else math.nan


# name -> (unit, function of the dictionary read_log returns)
METRICS = {
    "peak_interaction_force": ("N", lambda g: peak_interaction_force(g["force"])),
    "time_to_peak": ("s", lambda g: time_to_peak(g["time"], g["force"])),
    "penetration_depth": ("m", lambda g: penetration_depth(g["force"], g["centre_of_mass"], g["down"])),
    "rebound_height": ("m", lambda g: rebound_height(g["force"], g["centre_of_mass"], g["down"])),
    "settle_time": ("s", lambda g: settle_time(g["time"], g["centre_of_mass"])),
    "peak_rendered_force": ("N", lambda g: peak_rendered_force(g["rendered_force"])),
    "saturation_ratio": ("1", lambda g: saturation_ratio(g["saturation"])),
    "coupling_energy_balance": ("J", lambda g: coupling_energy_balance(g["injected_energy"])),
    "mean_step_time": ("s", lambda g: mean_step_time(g["step_wall_time"])),
    "real_time_factor": ("1", lambda g: real_time_factor(g["step_wall_time"], g["dt"])),
    "final_status": ("", lambda g: g["status"]),
}


def _attribute_text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def read_log(h5file):
    """What the metrics need from an open h5py.File; absent series are empty arrays."""
    def series(path, columns):
        return np.asarray(h5file[path][()], dtype=float) if path in h5file else np.empty((0, columns))

    config = json.loads(_attribute_text(h5file.attrs.get("config", "{}")))
    proxy = (config.get("proxy") or {}).get("body")
    gravity = np.asarray((config.get("simulation") or {}).get("gravity", [0.0, 0.0, -9.81]), dtype=float)
    # Without gravity there is no "down": heights are then measured along z.
    down = gravity if np.linalg.norm(gravity) > 0.0 else np.array([0.0, 0.0, -1.0])
    body = f"/bodies/{proxy}" if proxy else None
    rows = 0 if body is None else len(series(f"{body}/interaction_force", 3))
    time = series("/time", 1)[:rows] if rows else np.empty(0)  # a killed run may hold one more time row
    return {
        "status": _attribute_text(h5file.attrs.get("status", "")),
        "dt": float(h5file.attrs.get("dt", math.nan)),
        "down": down,
        "time": time,
        "force": series(f"{body}/interaction_force", 3)[: len(time)] if body else np.empty((0, 3)),
        "centre_of_mass": series(f"{body}/centre_of_mass", 3)[: len(time)] if body else np.empty((0, 3)),
        "rendered_force": series("/haptics/rendered/force", 3),
        "saturation": series("/haptics/saturation", 3),
        "injected_energy": series("/haptics/injected_energy", 1),
        "step_wall_time": series("/timing/step_wall_time", 1),
    }


def compute_metrics(path, names=None):
    """The named metrics (default all) of the run log at `path`, by name."""
    import h5py

    with h5py.File(path, "r") as f:
        log = read_log(f)
    return {name: METRICS[name][1](log) for name in (names or METRICS)}


def main(argv):
    if argv == ["--list"]:
        print("\n".join(METRICS))
        return 0
    if not argv or argv[0].startswith("-"):
        print("usage: log_metrics.py --list | LOG.h5 ...", file=sys.stderr)
        return 2
    print(json.dumps({path: compute_metrics(path) for path in argv}, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
