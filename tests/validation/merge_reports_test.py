"""scripts/validation/merge_reports.py on the reports of real `mssph validate` runs: two parts of
one quick run merge into the report a single run writes, and parts that do not belong together
are refused with the file and key. Run by ctest with Debian's python3 and the mssph binary as the
argument."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
MERGE = os.path.join(ROOT, "scripts", "validation", "merge_reports.py")
MSSPH = None  # set from argv


def validate(out, cases, seed):
    command = [MSSPH, "validate", "--quick", "--backend", "cpu", "--seed", str(seed), "--out", out]
    for case in cases:
        command += ["--case", case]
    env = dict(os.environ, MSSPH_PYTHON=sys.executable)
    subprocess.run(command, check=True, cwd=ROOT, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def merge(*args):
    return subprocess.run([sys.executable, MERGE, *args], capture_output=True, text=True)


def load(folder):
    with open(os.path.join(folder, "report.json")) as f:
        return json.load(f)


class MergeReports(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.a = os.path.join(cls.tmp.name, "a")
        cls.b = os.path.join(cls.tmp.name, "b")
        cls.other_seed = os.path.join(cls.tmp.name, "c")
        validate(cls.a, ["coupling_step"], 7)
        validate(cls.b, ["one_step", "patch_tests"], 7)
        validate(cls.other_seed, ["patch_tests"], 8)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_parts_merge_into_one_report(self):
        out = os.path.join(self.tmp.name, "merged")
        result = merge(self.a, self.b, out)
        self.assertEqual(result.returncode, 0, result.stderr)
        merged, a, b = load(out), load(self.a), load(self.b)
        # By suite (kernels before physics), the parts' order within one.
        self.assertEqual([c["case"] for c in merged["cases"]], ["one_step", "coupling_step", "patch_tests"])
        by_name = {c["case"]: c for c in a["cases"] + b["cases"]}
        for case in merged["cases"]:
            self.assertEqual(case, by_name[case["case"]])
        self.assertEqual(merged["run"]["seed"], 7)
        self.assertIn("--case coupling_step", merged["run"]["command_line"])
        self.assertIn("--case one_step --case patch_tests --seed 7", merged["run"]["command_line"])
        with h5py.File(os.path.join(out, "validation.h5")) as h5:
            for part in (self.a, self.b):
                with h5py.File(os.path.join(part, "validation.h5")) as source:
                    for suite in source:
                        for case in source[suite]:
                            for series in source[suite][case]:
                                for column in source[suite][case][series]:
                                    np.testing.assert_array_equal(h5[suite][case][series][column][()],
                                                                  source[suite][case][series][column][()])
            self.assertEqual(h5.attrs["seed"], 7)
        with open(os.path.join(out, "report.md")) as f:
            text = f.read()
        self.assertIn("**3 passed, 0 failed, 0 skipped**", text)
        self.assertTrue(os.path.isfile(os.path.join(out, "physics_coupling_step_translation_step.png")))

    def assert_refused(self, parts, message):
        """merge_reports.py refuses the parts with exit 2, names the reason and writes nothing."""
        out = os.path.join(self.tmp.name, "refused")
        result = merge(*parts, out)
        self.assertEqual(result.returncode, 2)
        self.assertIn(message, result.stderr)
        self.assertFalse(os.path.exists(out))

    def test_parts_of_different_runs_are_refused(self):
        self.assert_refused([self.a, self.other_seed], "run/seed")

    def test_a_case_in_two_parts_is_refused(self):
        self.assert_refused([self.b, self.b], "kernels/one_step is also in")

    def test_an_earlier_report_is_replaced_only_with_force(self):
        out = os.path.join(self.tmp.name, "again")
        self.assertEqual(merge(self.a, self.b, out).returncode, 0)
        refused = merge(self.a, self.b, out)
        self.assertEqual(refused.returncode, 2)
        self.assertIn("pass --force", refused.stderr)
        self.assertEqual(merge("--force", self.a, self.b, out).returncode, 0)


if __name__ == "__main__":
    MSSPH = os.path.abspath(sys.argv.pop(1))
    unittest.main()
