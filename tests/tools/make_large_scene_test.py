#!/usr/bin/env python3
"""tools/make_large_scene.py: the scene it writes has at least the triangles asked for and a
camera that looks at the scene from outside it, and a count below 1 is refused (one argparse
line naming --triangles, exit 2) without a file. Standard library only."""

import json
import math
import os
import subprocess
import sys
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
TOOL = os.path.join(ROOT, "tools", "make_large_scene.py")
SCRATCH = os.path.join(os.environ.get("RADCACHE_TEST_SCRATCH_DIR") or "/tmp",
                       "make_large_scene_test")
TRIANGLES_PER_SPHERE = 9024  # the built-in sphere's triangles (docs/reliability.md)


def run(*arguments):
    return subprocess.run([sys.executable, TOOL] + list(arguments), capture_output=True,
                          text=True)


class MakeLargeSceneTest(unittest.TestCase):
    def setUp(self):
        os.makedirs(SCRATCH, exist_ok=True)

    def test_small_counts_give_a_camera_outside_the_spheres(self):
        for triangles in (1, 10, 20000):
            out = os.path.join(SCRATCH, "scene-%d.json" % triangles)
            result = run(out, "--triangles", str(triangles))
            self.assertEqual(result.returncode, 0, result.stderr)
            with open(out) as f:
                scene = json.load(f)
            spheres = [s for s in scene["shapes"] if s["type"] == "sphere"]
            self.assertGreaterEqual(len(spheres) * TRIANGLES_PER_SPHERE, triangles)
            camera = scene["camera"]
            distance = math.dist(camera["position"], camera["look_at"])
            reach = max(math.hypot(*s["center"]) + s["radius"] for s in spheres)
            self.assertGreater(distance, reach, "the camera stands among the spheres")

    def test_counts_below_one_are_refused_without_a_file(self):
        for bad in ("0", "-5", "many"):
            out = os.path.join(SCRATCH, "refused-%s.json" % bad)
            result = run(out, "--triangles", bad)
            self.assertEqual(result.returncode, 2)
            self.assertIn("--triangles", result.stderr)
            self.assertFalse(os.path.exists(out))


if __name__ == "__main__":
    unittest.main()
