#!/usr/bin/env python3
"""tools/sweep.py end to end on a tiny Cornell box: the CSV has the documented columns, one row
per point, errors that fall with the sample count, medians and spreads over the repeats, grids
scaled from the auto grid, and the chart and report are written; a render that is not the same
on a repeat (a wrapper that changes the seed) fails the sweep; an animated scene's frame finds its
own reference; bad input is refused. The methods and knobs come from radcache's option tables:
a --ladder curve of one knob, ladders generated from a knob's default, direction and range, and
the refusals (an option that is not a knob of the method, an unknown method, a curated curve whose
knob the table no longer marks) with one line and no output. Run by CTest with $RADCACHE set to
the built executable."""

import csv
import json
import math
import os
import shutil
import subprocess
import sys
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SWEEP = os.path.join(ROOT, "tools", "sweep.py")
RADCACHE = os.environ.get("RADCACHE") or os.path.join(ROOT, "build", "radcache")
sys.path.insert(0, os.path.join(ROOT, "tools"))
import sweep_knobs  # noqa: E402
SCRATCH = os.path.join(os.environ.get("RADCACHE_TEST_SCRATCH_DIR") or "/tmp", "sweep_test")
# The columns docs/results.md and the sweep's docstring document, in order.
DOCUMENTED_COLUMNS = ["scene", "frame", "method", "curve", "setting", "spp", "accuracy",
                      "ic_rays", "ic_min_spacing", "rc_rays", "sdrc_interp", "photons", "grid",
                      "gather_rays", "repeats",
                      "wall_seconds", "wall_seconds_min", "wall_seconds_max", "render_seconds",
                      "render_seconds_min", "render_seconds_max", "kernel_seconds",
                      "kernel_seconds_min", "kernel_seconds_max", "compile_seconds",
                      "denoise_seconds", "rmse",
                      "relmse", "relmse_net", "flip", "indirect_relmse", "records", "device",
                      "image"]
# A radcache that renders with a new seed at every call: its repeats differ.
RESEEDING = """#!/bin/sh
count=$(cat "$0.count" 2>/dev/null || echo 0)
echo $((count + 1)) > "$0.count"
if [ "$1" = render ]; then exec "%s" "$@" --seed "$count"; fi
exec "%s" "$@"
"""

# A radcache whose ic table no longer marks --ic-rays a quality knob.
DROPS_A_KNOB = """#!%s
import json, os, subprocess, sys
real = %r
if "--list-knobs" in sys.argv:
    listing = json.loads(subprocess.run([real] + sys.argv[1:], capture_output=True, text=True,
                                        check=True).stdout)
    for entry in listing:
        if entry["method"] == "ic":
            entry["knobs"] = [k for k in entry["knobs"] if k["name"] != "--ic-rays"]
    print(json.dumps(listing))
    sys.exit(0)
os.execv(real, [real] + sys.argv[1:])
"""


def run(command, radcache=RADCACHE):
    return subprocess.run(command, capture_output=True, text=True,
                          env=dict(os.environ, RADCACHE=radcache))


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
                          "--ic-rays", "256", "--ic-min-spacing", "default", "3px", "--methods",
                          "pt", "ic", "ivg", "--ivg-photons", "20000", "--ivg-grid", "auto*2",
                          "--repeats", "2", "--out", cls.out])

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
        self.assertEqual([r["method"] for r in rows], ["pt", "pt", "ic", "ic", "ivg"])
        self.assertEqual([r["spp"] for r in rows], ["1", "64", "1", "1", "4"])
        self.assertEqual([r["ic_min_spacing"] for r in rows[2:4]], ["default", "3px"])
        self.assertEqual(int(rows[4]["photons"]), 20000)
        # auto*2: twice the auto grid's voxels per axis, as radcache reported the auto grid in
        # the --stats of the warm-up render (no --grid).
        with open(os.path.join(self.out, "warm-ivg.stats.json")) as f:
            auto = json.load(f)["frames"][0]["grid"]["cells"]
        self.assertEqual([int(c) for c in rows[4]["grid"].split("x")], [2 * c for c in auto])
        for r in rows:
            self.assertEqual(r["scene"], "cornell-box")
            self.assertEqual(r["frame"], "0")
            self.assertEqual(r["repeats"], "2")
            for column in ("wall_seconds", "render_seconds", "kernel_seconds", "rmse", "relmse",
                           "flip", "indirect_relmse"):
                value = float(r[column])
                self.assertTrue(math.isfinite(value) and value >= 0.0, (column, r[column]))
            for column in ("wall_seconds", "render_seconds", "kernel_seconds"):
                self.assertLessEqual(float(r[column + "_min"]), float(r[column]))
                self.assertLessEqual(float(r[column]), float(r[column + "_max"]))
                # The median of two repeats is their mean.
                self.assertAlmostEqual(float(r[column]), 0.5 * (float(r[column + "_min"]) +
                                                                float(r[column + "_max"])))
            self.assertGreater(float(r["relmse"]), 0.0)
            self.assertLess(float(r["flip"]), 1.0)
            self.assertLessEqual(float(r["render_seconds_max"]), float(r["wall_seconds_max"]))
            self.assertTrue(os.path.isfile(os.path.join(self.out, r["image"])), r["image"])
        # 64 samples per pixel: far below the error of one (relMSE falls as 1/spp).
        self.assertLess(float(rows[1]["relmse"]), 0.25 * float(rows[0]["relmse"]))
        self.assertGreater(int(rows[2]["records"]), 0)
        # A smaller spacing allows more records.
        self.assertGreater(int(rows[3]["records"]), int(rows[2]["records"]))
        # Only the first repeat's image is kept.
        self.assertEqual([n for n in os.listdir(self.out) if "repeat" in n], [])

    def test_json_matches_csv_and_names_the_timing(self):
        with open(os.path.join(self.out, "sweep.json")) as f:
            report = json.load(f)
        self.assertEqual(report["columns"], DOCUMENTED_COLUMNS)
        self.assertEqual(len(report["rows"]), 5)
        self.assertEqual(report["repeats"], 2)
        self.assertIn("compilation excluded", report["timing"])
        self.assertIn("median over 2 repeats", report["timing"])
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

    def test_repeats_that_differ_fail_the_sweep(self):
        wrapper = os.path.join(SCRATCH, "reseeding-radcache")
        with open(wrapper, "w") as f:
            f.write(RESEEDING % (RADCACHE, RADCACHE))
        os.chmod(wrapper, 0o755)
        result = run([sys.executable, SWEEP, os.path.join(ROOT, "scenes", "cornell-box"),
                      "--reference", self.reference, "--width", "24", "--height", "24",
                      "--methods", "pt", "--pt-spp", "2", "--repeats", "2",
                      "--out", os.path.join(SCRATCH, "reseeded")], radcache=wrapper)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("not deterministic: pt-00 (spp=2): repeat 2's pixels", result.stderr)

    def test_an_animated_scene_finds_its_frame_reference(self):
        # The size check fails before any render and names the reference the frame found.
        scene = os.path.join(ROOT, "scenes", "moving-sphere")
        for frame, name in ((["--frame", "5"], "frame0005.exr"), ([], "frame0000.exr")):
            result = run([sys.executable, SWEEP, scene, "--width", "24", "--height", "24",
                          "--out", os.path.join(SCRATCH, "bad")] + frame)
            self.assertNotEqual(result.returncode, 0)
            self.assertIn(os.path.join("moving-sphere", "reference", name) + " is 256x256",
                          result.stderr)
        outside = run([sys.executable, SWEEP, scene, "--frame", "24",
                       "--out", os.path.join(SCRATCH, "bad")])
        self.assertNotEqual(outside.returncode, 0)
        self.assertIn("--frame 24", outside.stderr)

    def test_runs_without_flip_evaluator_with_one_warning(self):
        # A flip_evaluator module that cannot be imported, first on the path.
        hidden = os.path.join(SCRATCH, "no_flip")
        os.makedirs(hidden, exist_ok=True)
        with open(os.path.join(hidden, "flip_evaluator.py"), "w") as f:
            f.write("raise ImportError('flip_evaluator hidden by the test')\n")
        out = os.path.join(SCRATCH, "no_flip_out")
        env = dict(os.environ, RADCACHE=RADCACHE,
                   PYTHONPATH=hidden + os.pathsep + os.environ.get("PYTHONPATH", ""))
        result = subprocess.run([sys.executable, SWEEP, os.path.join(ROOT, "scenes", "cornell-box"),
                                 "--reference", self.reference, "--width", "24", "--height", "24",
                                 "--methods", "pt", "--pt-spp", "1", "--out", out],
                                capture_output=True, text=True, env=env)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertEqual(result.stderr.count("flip-evaluator is not installed"), 1, result.stderr)
        with open(os.path.join(out, "sweep.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(len(rows), 1)
        self.assertEqual(rows[0]["flip"], "")
        self.assertGreater(float(rows[0]["relmse"]), 0.0)

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
        for bad, option in ((["--repeats", "0"], "--repeats"), (["--ivg-grid", "auto*"],
                            "--ivg-grid"), (["--ic-min-spacing", "8pt"], "--ic-min-spacing"),
                            (["--width", "0"], "--width"), (["--height", "-3"], "--height")):
            refused = run([sys.executable, SWEEP, os.path.join(ROOT, "scenes", "cornell-box"),
                           "--out", os.path.join(SCRATCH, "bad")] + bad)
            self.assertNotEqual(refused.returncode, 0)
            self.assertIn(option, refused.stderr)


class LadderTest(unittest.TestCase):
    """--ladder and the checks against the option tables."""
    @classmethod
    def setUpClass(cls):
        os.makedirs(SCRATCH, exist_ok=True)
        cls.reference = os.path.join(SCRATCH, "ladder-reference.exr")
        result = run([RADCACHE, "render",
                      os.path.join(ROOT, "scenes", "cornell-box", "scene.json"), "-o",
                      cls.reference, "--width", "16", "--height", "16", "--spp", "64", "--quiet"])
        assert result.returncode == 0, result.stdout + result.stderr

    def sweep(self, options, out, radcache=RADCACHE):
        return run([sys.executable, SWEEP, os.path.join(ROOT, "scenes", "cornell-box"),
                    "--reference", self.reference, "--width", "16", "--height", "16",
                    "--repeats", "1", "--out", out] + options, radcache)

    def test_a_ladder_draws_one_curve_of_a_knob(self):
        out = os.path.join(SCRATCH, "ladder")
        result = self.sweep(["--ladder", "ic:--ic-rays=64,256", "--ladder-spp", "1"], out)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        with open(os.path.join(out, "sweep.csv")) as f:
            rows = list(csv.DictReader(f))
        # Only the ladder: no --methods given.
        self.assertEqual([(r["method"], r["curve"], r["setting"], r["ic_rays"], r["spp"])
                          for r in rows],
                         [("ic", "ic --ic-rays ladder", "--ic-rays=64", "64", "1"),
                          ("ic", "ic --ic-rays ladder", "--ic-rays=256", "256", "1")])
        for r in rows:
            self.assertGreater(float(r["relmse"]), 0.0)
            self.assertGreater(int(r["records"]), 0)
            self.assertEqual(r["accuracy"], "")
        with open(os.path.join(out, "sweep.json")) as f:
            report = json.load(f)
        self.assertEqual([r["ic_rays"] for r in report["rows"]], [64, 256])
        self.assertTrue(os.path.isfile(os.path.join(out, "error-vs-time.png")))

    def test_generated_ladders_follow_the_table(self):
        tables = sweep_knobs.read_tables(
            lambda args: subprocess.run([RADCACHE] + args, capture_output=True, text=True,
                                        check=True).stdout)
        rays = tables.knobs["ic"]["--ic-rays"]
        self.assertEqual(sweep_knobs.ladder("ic:--ic-rays", tables, {}).values,
                         [str(min(int(rays["default"]) * 2 ** k, rays["max"]))
                          for k in range(4)])
        # Hand-worked: /1.5 a step from 0.35 ("decrease"); x2 from 40 clamped to 100 and
        # de-duplicated; rounded integers; a choice knob's choices.
        knob = {"name": "--k", "type": "number", "default": "0.35", "knob": "decrease",
                "min": 0.001, "max": 1.0}
        self.assertEqual(sweep_knobs.generated_values(knob), ["0.35", "0.233", "0.156", "0.104"])
        knob.update(type="integer", default="40", knob="increase", min=1, max=100)
        self.assertEqual(sweep_knobs.generated_values(knob), ["40", "80", "100"])
        knob.update(default="5", knob="decrease")
        self.assertEqual(sweep_knobs.generated_values(knob), ["5", "3", "2", "1"])
        self.assertEqual(sweep_knobs.generated_values(
            {"type": "choice", "choices": ["low", "high"], "default": "low",
             "knob": "increase"}), ["low", "high"])
        # A default that depends on other options, a length: their values must be given.
        for spec, words in (("ivg:--photons", "depends on other options"),
                            ("ic:--ic-min-spacing", "length knob")):
            with self.assertRaises(sweep_knobs.KnobError) as refused:
                sweep_knobs.ladder(spec, tables, {})
            self.assertIn(words, str(refused.exception))
        self.assertEqual(sweep_knobs.ladder("ivg:--photons=10,20", tables, {}).values,
                         ["10", "20"])

    def assertRefused(self, result, out, *names):
        self.assertNotEqual(result.returncode, 0)
        # One error line (beside the warning of a missing flip-evaluator, if any).
        lines = [l for l in result.stderr.strip().splitlines() if "warning" not in l]
        self.assertEqual(len(lines), 1, result.stderr)
        for name in names:
            self.assertIn(name, lines[0])
        self.assertFalse(os.path.exists(out), out)

    def test_refuses_what_the_tables_do_not_have(self):
        out = os.path.join(SCRATCH, "refused")
        shutil.rmtree(out, ignore_errors=True)
        for options, names in (
                (["--ladder", "pt:--ic-rays"], ["not a quality knob of pt", "--ic-rays"]),
                (["--ladder", "nosuch:--ic-rays"], ["unknown method 'nosuch'"]),
                (["--methods", "nosuch"], ["--methods nosuch", "unknown method"]),
                (["--methods", "normals"], ["normals", "no quality knobs"]),
                (["--ladder", "ic:--ic-rays=64,2"], ["--ic-rays 2", "[4, 65536]"])):
            self.assertRefused(self.sweep(options, out), out, *names)

    def test_a_curated_knob_the_table_drops_fails_the_sweep(self):
        wrapper = os.path.join(SCRATCH, "drops-a-knob-radcache")
        with open(wrapper, "w") as f:
            f.write(DROPS_A_KNOB % (sys.executable, RADCACHE))
        os.chmod(wrapper, 0o755)
        out = os.path.join(SCRATCH, "dropped")
        shutil.rmtree(out, ignore_errors=True)
        # Even a sweep of pt alone: the tool and the tables must agree.
        result = self.sweep(["--methods", "pt", "--pt-spp", "1"], out, radcache=wrapper)
        self.assertRefused(result, out, "ic: the sweep varies --ic-rays", "quality knob")


if __name__ == "__main__":
    unittest.main()
