#!/usr/bin/env python3
"""Tests of scripts/analysis/log_metrics.py on synthetic run logs with answers worked out by hand.

Each log is written with h5py in the run log's layout (docs/run-log.md): a proxy whose
centre of mass follows chosen piecewise sines and whose interaction force is a half sine, a
haptic loop with chosen rendered forces, flags and energies, and chosen step times. Expected
values come from the formulas of those curves, not from the code under test.
"""
import json
import math
import pathlib
import sys
import tempfile
import unittest

import h5py
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "scripts" / "analysis"))
import log_metrics  # noqa: E402

DT_LOG = 0.001  # [s] logged sample spacing
T = np.round(np.arange(0, 1001) * DT_LOG, 9)  # 0 ... 1 s


def height(t):
    """Height of the proxy's centre of mass [m]: rest at 0.5 m, pushed 3 cm down by the contact
    (0.2-0.4 s), thrown 5 cm up (to 0.52 m at 0.6 s), back to rest at 0.5 m by 0.8 s."""
    return np.select(
        [t < 0.2, t <= 0.4, t <= 0.6, t <= 0.8],
        [0.5,
         0.5 - 0.03 * np.sin(np.pi * (t - 0.2) / 0.4),
         0.47 + 0.05 * np.sin(np.pi * (t - 0.4) / 0.4),
         0.52 - 0.02 * np.sin(np.pi * (t - 0.6) / 0.4)],
        0.5)


def force_magnitude(t):
    """|F| [N]: a 100 N half sine over 0.2-0.4 s, peak at 0.3 s, zero elsewhere."""
    return np.where((t >= 0.2) & (t <= 0.4), 100.0 * np.sin(np.pi * (t - 0.2) / 0.2), 0.0)


def write_log(path, up_axis=2, gravity=(0.0, 0.0, -9.81), proxy=True, haptics=True, status="completed",
              force_scale=1.0):
    with h5py.File(path, "w") as f:
        config = {"simulation": {"gravity": list(gravity)}, "bodies": {"ball": {}}}
        if proxy:
            config["proxy"] = {"body": "ball"}
        f.attrs["config"] = json.dumps(config)
        f.attrs["status"] = status
        f.attrs["dt"] = 0.0005
        f["/time"] = T
        com = np.zeros((T.size, 3))
        com[:, up_axis] = height(T)
        force = np.zeros((T.size, 3))
        force[:, up_axis] = force_scale * force_magnitude(T)  # pushes the ball up
        f["/bodies/ball/centre_of_mass"] = com
        f["/bodies/ball/interaction_force"] = force
        if haptics:
            rendered = np.zeros((100, 3))
            rendered[:, 0] = 1.0
            rendered[40] = [3.0, 4.0, 0.0]  # |f| = 5 N, the largest
            f["/haptics/rendered/force"] = rendered
            saturation = np.zeros((100, 3))
            saturation[0:10, 0] = 1.0    # force clamp on 10 ticks
            saturation[5:15, 2] = 1.0    # workspace stop on 10 ticks, 5 of them shared: 15 ticks in all
            saturation[50:60, 1] = 1.0   # torque clamp on 10 more: 25 of 100
            f["/haptics/saturation"] = saturation
            f["/haptics/injected_energy"] = np.linspace(0.0, -0.3, 100)
        f["/timing/step_wall_time"] = np.tile([0.001, 0.003], 1000)


class LogMetrics(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.folder.cleanup()

    def metrics_of(self, **kwargs):
        path = pathlib.Path(self.folder.name) / "log.h5"
        write_log(path, **kwargs)
        return log_metrics.compute_metrics(str(path))

    def test_every_metric_on_a_known_log(self):
        m = self.metrics_of()
        self.assertAlmostEqual(m["peak_interaction_force"], 100.0, places=9)
        self.assertAlmostEqual(m["time_to_peak"], 0.3, places=9)
        # Contact onset: the first sample with |F| >= 1 N, i.e. sin(pi (t - 0.2) / 0.2) >= 0.01:
        # t >= 0.2 + 0.2 asin(0.01) / pi = 0.200637 s, the sample at 0.201 s. The height there is
        # 0.5 - 0.03 sin(pi 0.001 / 0.4); the lowest point after it is 0.47 m.
        onset_height = 0.5 - 0.03 * math.sin(math.pi * 0.001 / 0.4)
        self.assertAlmostEqual(m["penetration_depth"], onset_height - 0.47, places=12)
        # From the lowest point (0.47 m at 0.4 s) up to the highest after it (0.52 m at 0.6 s).
        self.assertAlmostEqual(m["rebound_height"], 0.05, places=12)
        # Final position 0.5 m; largest distance from it 0.03 m, so the band is 0.0006 m. After
        # 0.6 s the distance is 0.02 (1 - sin(pi (t - 0.6) / 0.4)), inside the band from
        # t = 0.6 + 0.4 asin(0.97) / pi = 0.76873 s: the first sample there is 0.769 s.
        settle = 0.6 + 0.4 * math.asin(0.97) / math.pi
        self.assertAlmostEqual(settle, 0.76873, places=5)
        self.assertAlmostEqual(m["settle_time"], math.ceil(settle / DT_LOG) * DT_LOG, places=9)
        self.assertAlmostEqual(m["peak_rendered_force"], 5.0, places=12)
        self.assertAlmostEqual(m["saturation_ratio"], 0.25, places=12)
        self.assertAlmostEqual(m["coupling_energy_balance"], -0.3, places=12)
        self.assertAlmostEqual(m["mean_step_time"], 0.002, places=12)
        # 2000 steps of 0.0005 s = 1 s simulated in 2000 x 0.002 s = 4 s of steps.
        self.assertAlmostEqual(m["real_time_factor"], 4.0, places=12)
        self.assertEqual(m["final_status"], "completed")

    def test_heights_follow_gravity_not_z(self):
        # The same motion along y with gravity along -y gives the same answers.
        along_z = self.metrics_of()
        along_y = self.metrics_of(up_axis=1, gravity=(0.0, -3.0, 0.0))
        for name in ("penetration_depth", "rebound_height", "settle_time", "peak_interaction_force"):
            self.assertAlmostEqual(along_y[name], along_z[name], places=12, msg=name)

    def test_contact_onset_scales_with_the_peak(self):
        # The onset threshold is a fraction of the peak, so scaling the force changes nothing.
        self.assertAlmostEqual(self.metrics_of(force_scale=1e3)["penetration_depth"],
                               self.metrics_of()["penetration_depth"], places=12)

    def test_without_contact_nothing_penetrates(self):
        m = self.metrics_of(force_scale=0.0)
        self.assertEqual(m["peak_interaction_force"], 0.0)
        self.assertEqual(m["penetration_depth"], 0.0)
        self.assertEqual(m["rebound_height"], 0.0)

    def test_what_the_log_lacks_is_nan(self):
        m = self.metrics_of(proxy=False, haptics=False, status="failed: blow-up at t = 0.1 s")
        for name in ("peak_interaction_force", "time_to_peak", "penetration_depth", "rebound_height", "settle_time",
                     "peak_rendered_force", "saturation_ratio", "coupling_energy_balance"):
            self.assertTrue(math.isnan(m[name]), name)
        self.assertAlmostEqual(m["mean_step_time"], 0.002, places=12)
        self.assertEqual(m["final_status"], "failed: blow-up at t = 0.1 s")

    def test_functions_take_plain_arrays(self):
        # What other scripts call: arrays in, floats out.
        self.assertEqual(log_metrics.peak_interaction_force([[0, 0, 0], [0, -2, 0]]), 2.0)
        self.assertEqual(log_metrics.saturation_ratio([[0, 0, 0], [0, 0, 1]]), 0.5)
        self.assertEqual(log_metrics.real_time_factor([0.5, 0.5], 0.25), 2.0)
        self.assertIsInstance(log_metrics.settle_time(T, np.zeros((T.size, 3))), float)

    def test_the_list_names_every_metric_once(self):
        self.assertEqual(len(set(log_metrics.METRICS)), 11)
        self.assertIn("final_status", log_metrics.METRICS)


if __name__ == "__main__":
    unittest.main()
