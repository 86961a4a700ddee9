#!/usr/bin/env python3
"""The shipped references' layout (tools/references.py against scenes/README.md's rule, checked
on the files themselves) and tools/render-references.sh end to end at a smoke setting (1 sample
per pixel into a scratch folder): the same layout, records that state the command, device, seed
and samples, and bad input refused. Run by CTest with $RADCACHE set to the built executable."""

import json
import os
import re
import subprocess
import sys
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from radcache_tools import references  # noqa: E402

SCRIPT = os.path.join(ROOT, "tools", "render-references.sh")
RADCACHE = os.environ.get("RADCACHE") or os.path.join(ROOT, "build", "radcache")
SCRATCH = os.path.join(os.environ.get("RADCACHE_TEST_SCRATCH_DIR") or "/tmp", "references_test")
SCENES = os.path.join(ROOT, "scenes")


def run(command):
    return subprocess.run(command, capture_output=True, text=True,
                          env=dict(os.environ, RADCACHE=RADCACHE))


class Layout(unittest.TestCase):
    def test_comments_are_stripped_outside_strings_only(self):
        text = '{"a": "x//y", /* block\n */ "b": [1, 2] // tail\n, "c": "/*z*/"}'
        self.assertEqual(json.loads(references.strip_comments(text)),
                         {"a": "x//y", "b": [1, 2], "c": "/*z*/"})

    def test_frame_ranges_of_the_shipped_scenes(self):
        self.assertEqual(references.frame_range(os.path.join(SCENES, "moving-sphere",
                                                             "scene.json")), (0, 23))
        self.assertEqual(references.frame_range(os.path.join(SCENES, "cornell-box",
                                                             "scene.json")), (0, 0))
        self.assertEqual(references.frame_range(os.path.join(SCENES, "kettle", "scene.json")),
                         (0, 0))
        self.assertEqual(references.frame_range(os.path.join(SCENES, "moving-light",
                                                             "scene.json")), (0, 15))

    def test_every_named_reference_exists_with_its_record(self):
        named = []
        for scene in ("cornell-box", "glossy-box", "two-rooms", "kettle", "relief"):
            named.append((references.reference_path(os.path.join(SCENES, scene)), 0))
        for frame in range(24):
            named.append((references.reference_path(os.path.join(SCENES, "moving-sphere"),
                                                    frame), frame))
        for frame in range(16):
            named.append((references.reference_path(os.path.join(SCENES, "moving-light"),
                                                    frame), frame))
        self.assertTrue(named[5][0].endswith(os.path.join("reference", "frame0000.exr")))
        self.assertTrue(named[-1][0].endswith(os.path.join("moving-light", "reference",
                                                           "frame0015.exr")))
        for path, frame in named:
            self.assertTrue(os.path.isfile(path), path)
            with open(os.path.splitext(path)[0] + ".json") as f:
                record = json.load(f)
            self.assertEqual(record["file"], os.path.basename(path))
            self.assertEqual(record["frame"], frame)

    def test_no_reference_for_a_frame_outside_the_scene(self):
        with self.assertRaises(references.ReferenceError):
            references.reference_path(os.path.join(SCENES, "moving-sphere"), 24)
        with self.assertRaises(references.ReferenceError):
            references.reference_path(os.path.join(SCENES, "cornell-box"), 1)

    def test_shipped_frames_are_in_order(self):
        # The ball rolls across the box, the light moves across the ceiling: frame 0 is nearer
        # to frame 1 than to the last frame (relMSE of the direct layer), so the frames are
        # distinct and in order.
        for scene, last in (("moving-sphere", 23), ("moving-light", 15)):
            folder = os.path.join(SCENES, scene, "reference")

            def relmse(a, b):
                result = run([RADCACHE, "compare", os.path.join(folder, "frame%04d.exr" % a),
                              os.path.join(folder, "frame%04d.exr" % b), "--aov", "direct"])
                self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
                return float(re.search(r"relmse (\S+)", result.stdout).group(1))

            near, far = relmse(0, 1), relmse(0, last)
            self.assertGreater(near, 0.0, scene)
            self.assertGreater(far, 2.0 * near, scene)

    def test_records_of_a_run_follow_the_layout(self):
        stats = {"method": "pt", "seed": 5, "resolution": [8, 8], "max_depth": 64,
                 "device": "d", "rays": 30, "nonfinite_samples": 0,
                 "seconds": {"render": 3.0, "total": 4.0},
                 "frames": [{"frame": f, "spp": 2, "seconds": 1.0, "rays": 10}
                            for f in (4, 5, 6)]}
        records = references.record(stats, os.path.join(SCENES, "moving-sphere"), "D", "cmd",
                                    "abc", "2026-01-01")
        self.assertEqual(sorted(records), [os.path.join("D", "reference", "frame%04d.json" % f)
                                           for f in (4, 5, 6)])
        one = records[os.path.join("D", "reference", "frame0005.json")]
        self.assertEqual((one["file"], one["frame"], one["spp"], one["rays"], one["run_rays"]),
                         ("frame0005.exr", 5, 2, 10, 30))
        with self.assertRaises(references.ReferenceError):
            references.record(stats, os.path.join(SCENES, "cornell-box"), "D", "cmd", "abc",
                              "2026-01-01")


class RenderReferences(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.out = os.path.join(SCRATCH, "out")
        subprocess.run(["rm", "-rf", SCRATCH], check=True)
        cls.result = run([SCRIPT, "--spp", "1", "--out", cls.out, "cornell-box", "moving-sphere"])

    def test_smoke_run_writes_the_shipped_layout(self):
        self.assertEqual(self.result.returncode, 0, self.result.stdout + self.result.stderr)
        cornell = os.path.join(self.out, "cornell-box")
        self.assertEqual(sorted(os.listdir(cornell)), ["reference.exr", "reference.json"])
        frames = sorted(os.listdir(os.path.join(self.out, "moving-sphere", "reference")))
        self.assertEqual(frames, sorted(["frame%04d.%s" % (f, e) for f in range(24)
                                         for e in ("exr", "json")]))

    def test_records_state_the_command_that_ran(self):
        with open(os.path.join(self.out, "cornell-box", "reference.json")) as f:
            record = json.load(f)
        self.assertEqual(record["spp"], 1)
        self.assertEqual(record["seed"], 20261123)
        self.assertEqual(record["resolution"], [512, 512])
        self.assertEqual(record["command"],
                         "radcache render scenes/cornell-box/scene.json -o cornell-box.exr "
                         "--spp 1 --seed 20261123 --sampler independent --width 512 --height 512 "
                         "--half --aovs beauty,direct,indirect,stddev --stats cornell-box.stats.json")
        with open(os.path.join(SCENES, "cornell-box", "reference.json")) as f:
            shipped = json.load(f)
        # The shipped reference's command, but for the samples; it was rendered before pixel
        # samplers existed, when every sample was independent (what --sampler independent gives).
        shipped_command = shipped["command"].replace("--spp 65536", "--spp 1")
        if "--sampler" not in shipped_command:
            shipped_command = shipped_command.replace(
                "--seed 20261123", "--seed 20261123 --sampler independent")
        self.assertEqual(record["command"], shipped_command)
        with open(os.path.join(self.out, "moving-sphere", "reference", "frame0017.json")) as f:
            frame = json.load(f)
        self.assertEqual((frame["frame"], frame["file"], frame["run_frames"]),
                         (17, "frame0017.exr", [0, 23]))
        self.assertIn("--frames 0:23 -o moving-sphere/frame####.exr --spp 1", frame["command"])

    def test_compare_reads_the_samples_from_the_record(self):
        frame = os.path.join(self.out, "moving-sphere", "reference", "frame0003.exr")
        result = run([RADCACHE, "compare", frame, frame])
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertIn("spp 1 from %s" % os.path.splitext(frame)[0] + ".json", result.stdout)

    def test_refuses_bad_input_before_rendering(self):
        low = run([SCRIPT, "--spp", "4", "cornell-box"])
        self.assertEqual(low.returncode, 2)
        self.assertIn("--out", low.stderr)
        unknown = run([SCRIPT, "--out", os.path.join(SCRATCH, "bad"), "furnace"])
        self.assertEqual(unknown.returncode, 2)
        self.assertIn("'furnace'", unknown.stderr)
        spp = run([SCRIPT, "--out", os.path.join(SCRATCH, "bad"), "--spp", "0"])
        self.assertEqual(spp.returncode, 2)
        self.assertIn("--spp", spp.stderr)
        self.assertFalse(os.path.exists(os.path.join(SCRATCH, "bad")))


if __name__ == "__main__":
    unittest.main()
