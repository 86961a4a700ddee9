#!/usr/bin/env python3
"""The benchmark scripts and tools refuse bad arguments before any render: one line naming the
option or the file (no Python traceback), a non-zero exit status (2 for argparse's refusals).
Standard library only; nothing is rendered."""

import os
import subprocess
import sys
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
TOOLS = os.path.join(ROOT, "tools")

CASES = [
    ("bench/equal_time.py", ["--scenes", "no-such-scene"], "--scenes no-such-scene"),
    ("bench/equal_time.py", ["--budgets", "0"], "--budgets"),
    ("bench/equal_time.py", ["--budgets", "ten"], "--budgets"),
    ("bench/equal_time.py", ["--width", "0"], "--width"),
    ("bench/auto.py", ["--scenes", "no-such-scene"], "--scenes no-such-scene"),
    ("bench/auto.py", ["--budgets", "-3"], "--budgets"),
    ("bench/auto.py", ["--width", "0"], "--width"),
    ("bench/temporal.py", ["--frames", "x"], "--frames"),
    ("bench/temporal.py", ["--frames", "5:2"], "--frames"),
]


# Tools given a path that does not exist: one line naming it, no traceback.
MISSING = "/nonexistent-radcache-test/x.json"
FILE_CASES = [
    ("check_doc_links.py", [MISSING], 1),
    ("make_large_scene.py", [MISSING], 2),
    ("peers/mitsuba/check_reference.py", [MISSING], 2),
    ("auto_model.py", ["fit", "--data", MISSING], 1),
    ("auto_model.py", ["repilot", "--data", MISSING], 1),
]


class BenchArgumentsTest(unittest.TestCase):
    def test_a_missing_path_is_one_line_naming_it(self):
        for script, arguments, status in FILE_CASES:
            with self.subTest(script=script):
                result = subprocess.run([sys.executable, os.path.join(TOOLS, script)] + arguments,
                                        capture_output=True, text=True, timeout=60)
                self.assertEqual(result.returncode, status, result.stderr)
                self.assertNotIn("Traceback", result.stderr)
                self.assertEqual(len(result.stderr.strip().splitlines()[-1:]), 1)
                self.assertIn(MISSING, result.stderr.strip().splitlines()[-1])
                self.assertFalse(os.path.exists(os.path.dirname(MISSING)))


    def test_bad_arguments_are_refused_in_one_line(self):
        for script, arguments, named in CASES:
            with self.subTest(script=script, arguments=arguments):
                result = subprocess.run([sys.executable, os.path.join(TOOLS, script)] + arguments,
                                        capture_output=True, text=True, timeout=60)
                self.assertEqual(result.returncode, 2, result.stderr)
                self.assertNotIn("Traceback", result.stderr)
                last = result.stderr.strip().splitlines()[-1]
                self.assertIn("error:", last)
                self.assertIn(named, last)


if __name__ == "__main__":
    unittest.main()
