#!/usr/bin/env python3
"""tools/flicker_chart.py end to end on a tiny clip of the moving-light scene (16 x 12, frames
0-3): path-traced test sequences at 1 and 4 samples per pixel (a seed per frame) against
64-sample frames; the chart is written, its figures are those of radcache compare --frames, the
noisier sequence has the larger error and flicker, compare's JSON is read as well as a pattern,
and bad input is refused without a chart. Run by CTest with $RADCACHE set to the built
executable."""

import json
import os
import shutil
import subprocess
import sys
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
CHART = os.path.join(ROOT, "tools", "flicker_chart.py")
RADCACHE = os.environ.get("RADCACHE") or os.path.join(ROOT, "build", "radcache")
SCRATCH = os.path.join(os.environ.get("RADCACHE_TEST_SCRATCH_DIR") or "/tmp",
                       "flicker_chart_test")
SCENE = os.path.join(ROOT, "scenes", "moving-light", "scene.json")
REFERENCE_SPP = 64


def run(command):
    return subprocess.run(command, capture_output=True, text=True,
                          env=dict(os.environ, RADCACHE=RADCACHE))


def render(name, spp, seed, aovs="beauty", reseed=False):
    """Frames 0-3 of the scene in SCRATCH/name/frame####.exr: one run with one seed, or with
    `reseed` a run per frame with seed + frame, so that the frames' noise is independent (one run
    draws the same samples in every frame, and its noise barely flickers)."""
    os.makedirs(os.path.join(SCRATCH, name))
    pattern = os.path.join(SCRATCH, name, "frame####.exr")
    runs = [("%d:%d" % (f, f), seed + f) for f in range(4)] if reseed else [("0:3", seed)]
    for frames, run_seed in runs:
        result = run([RADCACHE, "render", SCENE, "--frames", frames, "-o", pattern, "--width",
                      "16", "--height", "12", "--spp", str(spp), "--seed", str(run_seed),
                      "--aovs", aovs, "--quiet"])
        assert result.returncode == 0, result.stdout + result.stderr
    return pattern


class FlickerChartTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        shutil.rmtree(SCRATCH, ignore_errors=True)
        os.makedirs(SCRATCH)
        cls.reference = render("reference", REFERENCE_SPP, 1, "beauty,stddev")
        cls.one = render("spp1", 1, 10, reseed=True)
        cls.four = render("spp4", 4, 20, reseed=True)
        cls.chart = os.path.join(SCRATCH, "flicker.png")
        cls.summary = os.path.join(SCRATCH, "summary.json")
        cls.result = run([sys.executable, CHART, "--reference", cls.reference, "--frames", "0:3",
                          "--reference-spp", str(REFERENCE_SPP), "--out", cls.chart,
                          "--summary", cls.summary, "--keep", os.path.join(SCRATCH, "kept"),
                          "1 spp=" + cls.one, "4 spp=" + cls.four])

    def load_summary(self, path=None):
        with open(path or self.summary) as f:
            return json.load(f)

    def test_writes_the_chart_and_a_line_per_sequence(self):
        self.assertEqual(self.result.returncode, 0, self.result.stdout + self.result.stderr)
        with open(self.chart, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        self.assertIn("1 spp", self.result.stdout)
        self.assertIn("4 spp", self.result.stdout)

    def test_figures_are_those_of_compare(self):
        compare_json = os.path.join(SCRATCH, "compare.json")
        compare = run([RADCACHE, "compare", "--frames", "0:3", self.four, self.reference,
                       "--reference-spp", str(REFERENCE_SPP), "--json", compare_json])
        self.assertEqual(compare.returncode, 0, compare.stdout + compare.stderr)
        with open(compare_json) as f:
            direct = json.load(f)
        four = self.load_summary()["sequences"][1]
        self.assertEqual(four["label"], "4 spp")
        self.assertEqual(four["mean"], direct["mean"])
        self.assertEqual([f["temporal_error"] for f in four["frames"]],
                         [f["temporal_error"] for f in direct["frames"]])
        self.assertIsNone(four["frames"][0]["temporal_error"])

    def test_the_noisier_sequence_has_more_error_and_flicker(self):
        one, four = self.load_summary()["sequences"]
        for key in ("relmse", "temporal_error"):
            # Independent noise: error and flicker fall as 1 / spp, four times the samples
            # about a quarter of both.
            self.assertGreater(one["mean"][key], 2.0 * four["mean"][key], key)
            self.assertGreater(four["first_over_this_" + key], 2.0, key)
            self.assertEqual(one["first_over_this_" + key], 1.0)

    def test_reads_the_json_of_compare(self):
        kept = os.path.join(SCRATCH, "kept", "sequence00.json")
        chart = os.path.join(SCRATCH, "from-json.svg")
        summary = os.path.join(SCRATCH, "from-json.json")
        result = run([sys.executable, CHART, "--out", chart, "--summary", summary, "--net",
                      "one=" + kept])
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertTrue(os.path.isfile(chart))
        from_json = self.load_summary(summary)["sequences"][0]
        self.assertEqual(from_json["mean"], self.load_summary()["sequences"][0]["mean"])
        self.assertEqual(self.load_summary(summary)["figures"],
                         ["relmse_net", "temporal_error_net"])

    def test_refuses_bad_input_without_a_chart(self):
        chart = os.path.join(SCRATCH, "bad.png")
        base = [sys.executable, CHART, "--out", chart]
        with_reference = base + ["--reference", self.reference, "--frames", "0:3"]
        cases = [
            (base + ["no-label"], 2, "LABEL=TEST####"),
            (base + ["a=" + self.one], 2, "needs --reference and --frames"),
            (with_reference + ["a=" + self.one, "a=" + self.four], 2, "given twice"),
            (base + ["--frames", "3:3", "a=" + self.one], 2, "--frames"),
            (base[:-1] + [os.path.join(SCRATCH, "bad.txt"), "a=x.json"], 2, "--out"),
            (base + ["a=" + os.path.join(SCRATCH, "missing.json")], 1, "missing.json"),
            (base[:-1] + [chart, "--reference", self.reference, "--frames", "0:5",
                          "a=" + self.one], 1, "no file"),
            # Without the references' sample count there are no net figures to draw.
            (with_reference + ["--net", "a=" + self.one], 2, "relmse_net"),
        ]
        for command, status, message in cases:
            result = run(command)
            self.assertEqual(result.returncode, status, (command, result.stderr))
            self.assertIn(message, result.stderr)
            self.assertEqual(len(result.stderr.strip().splitlines()), 1, result.stderr)
            self.assertFalse(os.path.exists(chart))


if __name__ == "__main__":
    unittest.main()
