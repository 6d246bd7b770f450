"""scripts/validation/report.py on a made-up report: a series named with spaces (as the dam
break's are, after the experiments) is drawn into a file whose name is one word, and report.md
links to that file. Run by ctest with Debian's python3."""
import json
import os
import re
import sys
import tempfile
import unittest

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "validation"))

import report  # noqa: E402

RUN = {"mode": "quick", "command_line": "mssph validate --quick", "physics_backend": "cpu",
       "physics_precision": "float32", "physics_device": "test CPU", "fast_backends": ["cpu"], "seed": 1,
       "host_cpu": "test CPU", "gpus": [], "mssph_version": "0.1.0", "git_commit": "test", "date": "today"}


class PlotFileNames(unittest.TestCase):
    def test_a_series_named_with_spaces_gets_a_linkable_file(self):
        with tempfile.TemporaryDirectory() as out:
            group = "/physics/dam_break/front Martin and Moyce 1952"
            with h5py.File(os.path.join(out, "validation.h5"), "w") as h5:
                h5.create_dataset(group + "/x", data=np.linspace(0.0, 1.0, 5))
                h5.create_dataset(group + "/y0", data=np.linspace(1.0, 2.0, 5))
            case = {"suite": "physics", "case": "dam_break", "status": "PASS", "wall_seconds": 1.0, "title": "t",
                    "folder": "validation/physics/dam_break", "resolution": "", "details": "", "error": "",
                    "checks": [], "series": [{"name": "front Martin and Moyce 1952", "hdf5_group": group,
                                              "x_label": "T", "columns": ["Z"], "log_log": False}]}
            with open(os.path.join(out, "report.json"), "w") as f:
                json.dump({"run": RUN, "cases": [case]}, f)
            self.assertEqual(report.main(["report.py", os.path.join(out, "report.json"),
                                          os.path.join(out, "validation.h5"), out]), 0)
            with open(os.path.join(out, "report.md")) as f:
                links = re.findall(r"!\[[^\]]*\]\(([^)]*)\)", f.read())
            self.assertEqual(links, ["physics_dam_break_front_Martin_and_Moyce_1952.png"])
            self.assertTrue(os.path.isfile(os.path.join(out, links[0])))


if __name__ == "__main__":
    unittest.main()
