"""The Figure 3 resolution table (scripts/figures/figure3_resolutions.py) on drops whose answer is
known: a half-sine force pulse of given height and length, then rest on the block. Run by ctest
with Debian's python3."""
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "figures"))

from drop_log import DropLog  # noqa: E402
from figure3_resolutions import relative_change, summary, table  # noqa: E402

DT = 1e-3
MASS = 10.0
WEIGHT = MASS * 9.81


def drop(spacing, peak, contact, afloat=False):
    """A sphere falling at 1 m/s that meets the block at t = 0.1 s, feels a half-sine pulse of
    `peak` newtons lasting `contact` seconds, then rests on the block (or floats, still touching)."""
    log = DropLog.__new__(DropLog)
    log.time = np.arange(0.0, 2.0, DT)
    log.spacing = spacing
    log.mass = MASS
    log.gravity = 9.81
    t = log.time - 0.1
    pulse = np.where((t >= 0) & (t <= contact), peak * np.sin(np.pi * np.clip(t / contact, 0, 1)), 0.0)
    fz = pulse.copy()
    fz[t > contact + 0.3] = WEIGHT  # settled on the block after a flight
    if afloat:
        fz[t >= 0] = np.maximum(pulse[t >= 0], WEIGHT)
    log.force = np.zeros((len(t), 3))
    log.force[:, 2] = fz
    log.vz = np.where(t < 0, -1.0, 0.0)
    log.z = np.zeros(len(t))
    return log


class Summary(unittest.TestCase):
    def test_first_impact_and_settled_state(self):
        row = summary(drop(0.02, 500.0, 0.05))
        self.assertAlmostEqual(row["peak_force"], 500.0, delta=0.5)
        self.assertAlmostEqual(row["contact_duration"], 0.05, delta=2 * DT)
        self.assertAlmostEqual(row["peak_width"], 0.05 * 2 / 3, delta=2 * DT)  # sin > 1/2 over [1/6, 5/6]
        self.assertAlmostEqual(row["impact_speed"], 1.0)
        self.assertAlmostEqual(row["settled_speed_ratio"], 0.0)
        self.assertAlmostEqual(row["settled_support"], 1.0)

    def test_a_contact_that_never_ends_has_no_width_or_duration(self):
        row = summary(drop(0.02, 500.0, 0.05, afloat=True))
        self.assertIsNone(row["contact_duration"])
        self.assertIsNone(row["peak_width"])

    def test_changes_between_the_two_finest(self):
        rows = [summary(drop(s, p, c)) for s, p, c in ((0.04, 400.0, 0.08), (0.02, 500.0, 0.05), (0.01, 450.0, 0.06))]
        self.assertAlmostEqual(relative_change(rows, "peak_force"), -0.10, delta=2e-3)
        self.assertAlmostEqual(relative_change(rows, "contact_duration"), 0.20, delta=0.05)
        text = table({"deformable": rows})
        self.assertIn("| deformable | -10.0 % | +20.0 % |", text)


if __name__ == "__main__":
    unittest.main()
