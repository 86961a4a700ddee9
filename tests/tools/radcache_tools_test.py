#!/usr/bin/env python3
"""The tools' package (tools/radcache_tools/): its relMSE against `radcache compare` on images
written here (the C++ implementation as the oracle: the plain figure, and the figure net of a
reference's noise from its stddev layer and spp record), the one rule that finds radcache and a
failed run's message, and no script under tools/ editing sys.path. Run by CTest with $RADCACHE
set to the built executable."""

import json
import os
import random
import re
import shutil
import struct
import subprocess
import sys
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
TOOLS = os.path.join(ROOT, "tools")
sys.path.insert(0, TOOLS)
from radcache_tools import error, radcache  # noqa: E402

SCRATCH = os.path.join(os.environ.get("RADCACHE_TEST_SCRATCH_DIR") or "/tmp",
                       "radcache_tools_test")
WIDTH, HEIGHT = 6, 4


def write_pfm(path, pixels):
    """An RGB PFM (little-endian floats) of rows of (r, g, b) pixels, top row first."""
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (WIDTH, HEIGHT))
        for row in reversed(pixels):  # PFM stores the bottom row first
            for pixel in row:
                f.write(struct.pack("<3f", *pixel))


def image(seed, scale):
    generator = random.Random(seed)
    # Values exactly representable as float32 (multiples of 1/1024), some near 0 where the
    # denominator's 0.01 matters.
    return [[tuple(round(scale * generator.random() * 1024) / 1024 for _ in range(3))
             for _ in range(WIDTH)] for _ in range(HEIGHT)]


def flat(pixels):
    return [v for row in pixels for pixel in row for v in pixel]


@unittest.skipUnless(os.access(radcache.executable(), os.X_OK), "radcache is not built")
class RelmseAgainstCompare(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        shutil.rmtree(SCRATCH, ignore_errors=True)
        os.makedirs(SCRATCH)
        cls.test, cls.reference, cls.stddev = image(1, 2.0), image(2, 1.5), image(3, 0.8)
        cls.test_path = os.path.join(SCRATCH, "test.pfm")
        cls.reference_path = os.path.join(SCRATCH, "reference.pfm")
        write_pfm(cls.test_path, cls.test)
        write_pfm(cls.reference_path, cls.reference)

    def test_plain_relmse_is_compares(self):
        figures = error.compare(self.test_path, self.reference_path)
        self.assertIsNone(figures["relmse_net"])  # a PFM has no stddev layer
        expected = error.relmse_of_arrays(flat(self.test), flat(self.reference))
        self.assertGreater(expected, 0.0)
        self.assertAlmostEqual(figures["relmse"], expected, delta=1e-6 * expected)
        self.assertEqual(error.relmse(self.test_path, self.reference_path), figures["relmse"])
        self.assertEqual(error.relmse(self.reference_path, self.reference_path), 0.0)

    @unittest.skipUnless(shutil.which("oiiotool"), "oiiotool (openimageio-tools) is missing")
    def test_net_relmse_is_compares_with_a_noisy_reference(self):
        stddev_path = os.path.join(SCRATCH, "stddev.pfm")
        write_pfm(stddev_path, self.stddev)
        noisy = os.path.join(SCRATCH, "noisy.exr")
        subprocess.run(["oiiotool", self.reference_path, "--chnames", "R,G,B", stddev_path,
                        "--chnames", "stddev.R,stddev.G,stddev.B", "--chappend", "-d", "float",
                        "-o", noisy], check=True, capture_output=True)
        spp = 16
        with open(os.path.join(SCRATCH, "noisy.json"), "w") as f:
            json.dump({"spp": spp}, f)
        figures = error.compare(self.test_path, noisy, os.path.join(SCRATCH, "net.json"))
        self.assertIsNotNone(figures["relmse_net"])
        self.assertLess(figures["relmse_net"], figures["relmse"])
        expected = error.relmse_of_arrays(flat(self.test), flat(self.reference),
                                          flat(self.stddev), spp)
        self.assertAlmostEqual(figures["relmse_net"], expected, delta=1e-6 * figures["relmse"])
        noise = error.noise_of_arrays(flat(self.reference), flat(self.stddev), spp)
        self.assertAlmostEqual(figures["reference_noise"], noise, delta=1e-6 * noise)
        # The one relMSE the tools report is the net figure where compare knows the noise.
        self.assertEqual(error.relmse(self.test_path, noisy), figures["relmse_net"])
        self.assertEqual(error.relmse_of(figures), figures["relmse_net"])


class Runner(unittest.TestCase):
    def test_radcache_is_the_environments_else_this_checkouts(self):
        saved = os.environ.get("RADCACHE")
        try:
            os.environ["RADCACHE"] = "/somewhere/radcache"
            self.assertEqual(radcache.executable(), "/somewhere/radcache")
            del os.environ["RADCACHE"]
            self.assertEqual(radcache.executable(), os.path.join(ROOT, "build", "radcache"))
        finally:
            if saved is not None:
                os.environ["RADCACHE"] = saved

    @unittest.skipUnless(os.access(radcache.executable(), os.X_OK), "radcache is not built")
    def test_a_failed_run_exits_naming_the_command_and_its_output(self):
        with self.assertRaises(SystemExit) as caught:
            radcache.run(["compare", "/nonexistent/a.exr", "/nonexistent/b.exr"], "tool")
        message = str(caught.exception.code)
        self.assertTrue(message.startswith("tool: radcache compare /nonexistent/a.exr "
                                           "/nonexistent/b.exr failed:\n"), message)
        self.assertIn("a.exr", message.split("\n", 1)[1])

    def test_a_missing_executable_is_one_line(self):
        saved = os.environ.get("RADCACHE")
        try:
            os.environ["RADCACHE"] = "/nonexistent/radcache"
            with self.assertRaises(SystemExit) as caught:
                radcache.require_built("tool")
            self.assertEqual(caught.exception.code, "tool: build radcache first (see README): "
                                                    "/nonexistent/radcache is missing")
        finally:
            if saved is None:
                os.environ.pop("RADCACHE", None)
            else:
                os.environ["RADCACHE"] = saved


class NoPathEdits(unittest.TestCase):
    def test_no_script_under_tools_edits_sys_path(self):
        edit = re.compile(r"sys\.path\s*(\.(insert|append|extend)|\[|\+?=)")
        for folder, _, names in os.walk(TOOLS):
            for name in names:
                if name.endswith(".py"):
                    with open(os.path.join(folder, name)) as f:
                        for number, line in enumerate(f, 1):
                            self.assertIsNone(edit.search(line), "%s:%d: %s" % (
                                os.path.join(folder, name), number, line.strip()))

    def test_every_subfolder_script_finds_the_package(self):
        package = os.path.realpath(os.path.join(TOOLS, "radcache_tools"))
        for folder, directories, names in os.walk(TOOLS):
            directories[:] = [d for d in directories if d != "radcache_tools"]
            if folder == TOOLS or not any(n.endswith(".py") for n in names):
                continue
            link = os.path.join(folder, "radcache_tools")
            self.assertEqual(os.path.realpath(link), package, link)
            with_root = subprocess.run(
                [sys.executable, "-c", "import radcache_tools; print(radcache_tools.ROOT)"],
                cwd=folder, capture_output=True, text=True, check=True)
            self.assertEqual(with_root.stdout.strip(), os.path.realpath(ROOT))


if __name__ == "__main__":
    unittest.main()
