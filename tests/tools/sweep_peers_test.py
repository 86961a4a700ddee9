#!/usr/bin/env python3
"""tools/sweep.py --denoise --mitsuba on a tiny Cornell box: every radcache point has a +oidn
row whose times are the point's plus its denoise_seconds and whose error is measured on the
denoised image; the Mitsuba rows carry their samples per pixel and times; a scene the exporter
refuses (the glossy box's Phong) loses only the Mitsuba curve, with one warning naming the
material; and without the packages (hidden by the test) both are skipped with one warning each.
Skips (exit 0) only when pyoidn, OpenEXR or mitsuba is not installed. Run by CTest with
$RADCACHE set to the built executable."""

import csv
import os
import shutil
import subprocess
import sys
import unittest

import optional_packages

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SWEEP = os.path.join(ROOT, "tools", "sweep.py")
RADCACHE = os.environ.get("RADCACHE") or os.path.join(ROOT, "build", "radcache")
SCRATCH = os.path.join(os.environ.get("RADCACHE_TEST_SCRATCH_DIR") or "/tmp", "sweep_peers_test")
SIZE = ["--width", "16", "--height", "16"]


def run(command, env=None):
    return subprocess.run(command, capture_output=True, text=True,
                          env=dict(env or os.environ, RADCACHE=RADCACHE))


def reference(scene, name):
    path = os.path.join(SCRATCH, name + ".exr")
    result = run([RADCACHE, "render", os.path.join(ROOT, "scenes", scene, "scene.json"), "-o",
                  path, "--spp", "64", "--aovs", "beauty,direct,indirect", "--quiet"] + SIZE)
    assert result.returncode == 0, result.stderr
    return path


def rows_of(out):
    with open(os.path.join(out, "sweep.csv")) as f:
        return list(csv.DictReader(f))


class SweepPeersTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        shutil.rmtree(SCRATCH, ignore_errors=True)
        os.makedirs(SCRATCH)
        cls.cornell = reference("cornell-box", "cornell")
        cls.out = os.path.join(SCRATCH, "out")
        cls.result = run([sys.executable, SWEEP, os.path.join(ROOT, "scenes", "cornell-box"),
                          "--reference", cls.cornell, "--methods", "pt", "--pt-spp", "1",
                          "--repeats", "1", "--denoise", "--mitsuba", "2", "--out", cls.out] + SIZE)

    def test_denoised_rows_carry_the_denoise_time(self):
        self.assertEqual(self.result.returncode, 0, self.result.stderr)
        rows = rows_of(self.out)
        raw = {r["setting"]: r for r in rows if r["method"] == "pt"}
        denoised = [r for r in rows if r["method"] == "pt+oidn"]
        self.assertEqual(sorted(r["setting"] for r in denoised), sorted(raw))
        for row in denoised:
            point = raw[row["setting"]]
            seconds = float(row["denoise_seconds"])
            self.assertGreater(seconds, 0.0)
            self.assertEqual(point["denoise_seconds"], "")
            for key in ("render_seconds", "wall_seconds"):
                self.assertAlmostEqual(float(row[key]), float(point[key]) + seconds, places=6)
            self.assertEqual(row["curve"], "pt +oidn")
            self.assertTrue(os.path.isfile(os.path.join(self.out, row["image"])))
            self.assertNotEqual(row["image"], point["image"])
            self.assertNotEqual(row["relmse"], point["relmse"])
            self.assertGreater(float(row["relmse"]), 0.0)

    def test_mitsuba_rows(self):
        self.assertEqual(self.result.returncode, 0, self.result.stderr)
        rows = [r for r in rows_of(self.out) if r["method"] == "mitsuba"]
        self.assertEqual([r["spp"] for r in rows], ["2"])
        self.assertLess(float(rows[0]["render_seconds"]), float(rows[0]["wall_seconds"]))
        self.assertGreater(float(rows[0]["relmse"]), 0.0)
        self.assertEqual(rows[0]["denoise_seconds"], "")

    def test_a_refused_scene_loses_only_the_mitsuba_curve(self):
        glossy = reference("glossy-box", "glossy")
        out = os.path.join(SCRATCH, "glossy")
        result = run([sys.executable, SWEEP, os.path.join(ROOT, "scenes", "glossy-box"),
                      "--reference", glossy, "--methods", "pt", "--pt-spp", "1", "--repeats",
                      "1", "--mitsuba", "2", "--out", out] + SIZE)
        self.assertEqual(result.returncode, 0, result.stderr)
        warnings = [l for l in result.stderr.splitlines() if "no Mitsuba curve" in l]
        self.assertEqual(len(warnings), 1, result.stderr)
        self.assertIn("phong", warnings[0])
        self.assertEqual([r["method"] for r in rows_of(out)], ["pt"])

    def test_without_the_packages_one_warning_each(self):
        hidden = os.path.join(SCRATCH, "hidden")
        os.makedirs(hidden, exist_ok=True)
        for name in ("pyoidn", "mitsuba"):
            with open(os.path.join(hidden, name + ".py"), "w") as f:
                f.write("raise ImportError('%s hidden by the test')\n" % name)
        env = dict(os.environ, PYTHONPATH=hidden + os.pathsep + os.environ.get("PYTHONPATH", ""))
        out = os.path.join(SCRATCH, "hidden-out")
        result = run([sys.executable, SWEEP, os.path.join(ROOT, "scenes", "cornell-box"),
                      "--reference", self.cornell, "--methods", "pt", "--pt-spp", "1",
                      "--repeats", "1", "--denoise", "--mitsuba", "--out", out] + SIZE, env)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stderr.count("no +oidn curves"), 1, result.stderr)
        self.assertEqual(result.stderr.count("no Mitsuba curve"), 1, result.stderr)
        self.assertEqual([r["method"] for r in rows_of(out)], ["pt"])


if __name__ == "__main__":
    optional_packages.main_unless_missing("sweep_peers_test", ("OpenEXR", "pyoidn", "mitsuba"))
