#!/usr/bin/env python3
"""tools/bench/collection.py on a made-up collection: a scene that renders once its missing
texture and PLY mesh are stood in for, one radcache refuses (subsurface scattering: exit status 2, the
refusal's line in the table), one that fails (malformed: exit status 1), a file included by
another (not a scene of its own); the source folder is left as it was. Run by CTest with
$RADCACHE set to the built executable."""

import json
import os
import shutil
import subprocess
import sys
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
RADCACHE = os.environ.get("RADCACHE") or os.path.join(ROOT, "build", "radcache")
SCRATCH = os.path.join(os.environ.get("RADCACHE_TEST_SCRATCH_DIR") or "/tmp", "collection_test")
HEAD = ('LookAt 0 0 -5  0 0 0  0 1 0\nCamera "perspective"\nFilm "rgb"\nWorldBegin\n'
        'LightSource "point" "point3 from" [0 0 -4]\n')
TRIANGLE = 'Shape "trianglemesh" "point3 P" [0 0 0 1 0 0 0 1 0] "point2 uv" [0 0 1 0 0 1]\n'


class CollectionTest(unittest.TestCase):
    def test_tabulates_rendered_refused_and_failed(self):
        shutil.rmtree(SCRATCH, ignore_errors=True)
        source = os.path.join(SCRATCH, "collection")
        os.makedirs(os.path.join(source, "a"))
        with open(os.path.join(source, "a", "good.pbrt"), "w") as f:
            f.write(HEAD + 'Texture "t" "spectrum" "imagemap" "string filename" "tex/wood.png"\n'
                    'Material "diffuse" "texture reflectance" "t"\n' + TRIANGLE +
                    'Shape "plymesh" "string filename" "meshes/body.ply.gz"\n'
                    'Include "lights.pbrt"\n')
        with open(os.path.join(source, "a", "lights.pbrt"), "w") as f:
            f.write('LightSource "distant" "point3 to" [0 0 1]\n')
        with open(os.path.join(source, "glass.pbrt"), "w") as f:
            f.write(HEAD + 'Material "subsurface"\n' + TRIANGLE)
        with open(os.path.join(source, "broken.pbrt"), "w") as f:
            f.write(HEAD + 'Shape "trianglemesh" "point3 P" [0 0 0 1 0 0\n')
        before = sorted(os.walk(source))
        out = os.path.join(SCRATCH, "out")
        result = subprocess.run(
            [sys.executable, os.path.join(ROOT, "tools", "bench", "collection.py"), source,
             "--out", out, "--radcache", RADCACHE, "--methods", "pt"],
            capture_output=True, text=True)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertIn("pt: 1 of 3 rendered, 1 refused, 1 failed", result.stdout)
        with open(os.path.join(out, "collection.json")) as f:
            runs = {r["scene"]: r for r in json.load(f)["runs"]}
        self.assertEqual(sorted(runs), ["a/good.pbrt", "broken.pbrt", "glass.pbrt"])
        self.assertEqual(runs["a/good.pbrt"]["outcome"], "rendered")
        self.assertEqual(sorted(runs["a/good.pbrt"]["stand_ins"]),
                         ["a/meshes/body.ply.gz (mesh)", "a/tex/wood.png (image)"])
        self.assertEqual(runs["glass.pbrt"]["outcome"], "refused")
        self.assertIn('Material "subsurface"', runs["glass.pbrt"]["message"])
        self.assertEqual(runs["broken.pbrt"]["outcome"], "failed")
        self.assertEqual(runs["broken.pbrt"]["exit_status"], 1)
        with open(os.path.join(out, "collection.md")) as f:
            self.assertIn("| glass.pbrt | refused | 0 |", f.read())
        self.assertEqual(sorted(os.walk(source)), before)


if __name__ == "__main__":
    unittest.main()
