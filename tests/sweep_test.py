#!/usr/bin/env python3
"""tools/sweep.py end to end on a tiny Cornell box: the CSV has the documented columns, one row
per run, errors that fall with the sample count, and the chart and report are written; bad
input is refused. Run by CTest with $RADCACHE set to the built executable."""

import csv
import json
import math
import os
import shutil
import subprocess
import sys
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
SWEEP = os.path.join(ROOT, "tools", "sweep.py")
RADCACHE = os.environ.get("RADCACHE") or os.path.join(ROOT, "build", "radcache")
SCRATCH = os.path.join(os.environ.get("RADCACHE_TEST_SCRATCH_DIR") or "/tmp", "sweep_test")
# The columns docs/results.md and the sweep's docstring document, in order.
DOCUMENTED_COLUMNS = ["scene", "method", "curve", "setting", "spp", "accuracy", "ic_rays",
                      "photons", "grid", "gather_rays", "wall_seconds", "render_seconds",
                      "kernel_seconds", "compile_seconds", "rmse", "relmse", "flip",
                      "indirect_relmse", "records", "device", "image", "relmse_net"]


def run(command):
    return subprocess.run(command, capture_output=True, text=True,
                          env=dict(os.environ, RADCACHE=RADCACHE))


class SweepTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        shutil.rmtree(SCRATCH, ignore_errors=True)
        os.makedirs(SCRATCH)
        cls.reference = os.path.join(SCRATCH, "reference.exr")
        result = run([RADCACHE, "render",
                      os.path.join(ROOT, "scenes", "cornell-box", "scene.json"), "-o",
                      cls.reference, "--width", "24", "--height", "24", "--spp", "512",
                      "--aovs", "beauty,direct,indirect,stddev", "--stats",
                      os.path.join(SCRATCH, "reference.stats.json"), "--quiet"])
        assert result.returncode == 0, result.stdout + result.stderr
        cls.out = os.path.join(SCRATCH, "out")
        cls.result = run([sys.executable, SWEEP, os.path.join(ROOT, "scenes", "cornell-box"),
                          "--reference", cls.reference, "--width", "24", "--height", "24",
                          "--pt-spp", "1", "64", "--ic-accuracy", "0.5", "--ic-spp", "1",
                          "--ic-rays", "256", "--methods", "pt", "ic", "ivg-gather",
                          "--gather-rays", "4", "--out", cls.out])

    def test_runs_end_to_end(self):
        self.assertEqual(self.result.returncode, 0, self.result.stdout + self.result.stderr)
        for name in ("sweep.csv", "sweep.json", "index.html", "error-vs-time.png",
                     "indirect-error-vs-time.png"):
            self.assertTrue(os.path.isfile(os.path.join(self.out, name)), name)

    def test_csv_has_the_documented_columns_and_one_row_per_run(self):
        with open(os.path.join(self.out, "sweep.csv")) as f:
            reader = csv.DictReader(f)
            self.assertEqual(reader.fieldnames, DOCUMENTED_COLUMNS)
            rows = list(reader)
        self.assertEqual([r["method"] for r in rows], ["pt", "pt", "ic", "ivg-gather"])
        self.assertEqual([r["spp"] for r in rows], ["1", "64", "1", "1"])
        self.assertEqual(rows[3]["gather_rays"], "4")
        self.assertGreater(int(rows[3]["photons"]), 0)
        for r in rows:
            self.assertEqual(r["scene"], "cornell-box")
            for column in ("wall_seconds", "render_seconds", "kernel_seconds", "rmse", "relmse",
                           "flip", "indirect_relmse"):
                value = float(r[column])
                self.assertTrue(math.isfinite(value) and value >= 0.0, (column, r[column]))
            self.assertGreater(float(r["relmse"]), 0.0)
            self.assertLess(float(r["flip"]), 1.0)
            self.assertLessEqual(float(r["render_seconds"]), float(r["wall_seconds"]))
            self.assertTrue(os.path.isfile(os.path.join(self.out, r["image"])), r["image"])
        # 64 samples per pixel: far below the error of one (relMSE falls as 1/spp).
        self.assertLess(float(rows[1]["relmse"]), 0.25 * float(rows[0]["relmse"]))
        self.assertGreater(int(rows[2]["records"]), 0)

    def test_json_matches_csv_and_names_the_timing(self):
        with open(os.path.join(self.out, "sweep.json")) as f:
            report = json.load(f)
        self.assertEqual(report["columns"], DOCUMENTED_COLUMNS)
        self.assertEqual(len(report["rows"]), 4)
        self.assertIn("compilation excluded", report["timing"])
        # The relMSE of a row is what radcache compare reports for its image.
        row = report["rows"][0]
        compare = run([RADCACHE, "compare", os.path.join(self.out, row["image"]),
                       self.reference])
        self.assertEqual(compare.returncode, 0, compare.stdout + compare.stderr)
        self.assertIn("relmse %.6g" % row["relmse"], compare.stdout)
        # Net of the reference's noise (its stddev layer, spp from reference.stats.json): what
        # compare reports, below the plain figure by the reference's share.
        self.assertIn("relMSE net of the reference's noise %.6g" % row["relmse_net"],
                      compare.stdout)
        for r in report["rows"]:
            self.assertLess(r["relmse_net"], r["relmse"])

    def test_refuses_bad_input(self):
        missing = run([sys.executable, SWEEP, os.path.join(SCRATCH, "no-such-scene"),
                       "--out", os.path.join(SCRATCH, "bad")])
        self.assertNotEqual(missing.returncode, 0)
        self.assertIn("no-such-scene", missing.stderr)
        no_reference = run([sys.executable, SWEEP, os.path.join(ROOT, "scenes", "furnace"),
                            "--out", os.path.join(SCRATCH, "bad")])
        self.assertNotEqual(no_reference.returncode, 0)
        self.assertIn("reference not found", no_reference.stderr)
        negative = run([sys.executable, SWEEP, os.path.join(ROOT, "scenes", "cornell-box"),
                        "--pt-spp", "0", "--out", os.path.join(SCRATCH, "bad")])
        self.assertNotEqual(negative.returncode, 0)
        self.assertIn("--pt-spp", negative.stderr)


if __name__ == "__main__":
    unittest.main()
