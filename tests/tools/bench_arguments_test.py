#!/usr/bin/env python3
"""The benchmark scripts refuse bad arguments before any render: one argparse line naming the
option (no Python traceback), exit status 2. Standard library only; nothing is rendered."""

import os
import subprocess
import sys
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
BENCH = os.path.join(ROOT, "tools", "bench")

CASES = [
    ("equal_time.py", ["--scenes", "no-such-scene"], "--scenes no-such-scene"),
    ("equal_time.py", ["--budgets", "0"], "--budgets"),
    ("equal_time.py", ["--budgets", "ten"], "--budgets"),
    ("equal_time.py", ["--width", "0"], "--width"),
    ("auto.py", ["--scenes", "no-such-scene"], "--scenes no-such-scene"),
    ("auto.py", ["--budgets", "-3"], "--budgets"),
    ("auto.py", ["--width", "0"], "--width"),
    ("temporal.py", ["--frames", "x"], "--frames"),
    ("temporal.py", ["--frames", "5:2"], "--frames"),
]


class BenchArgumentsTest(unittest.TestCase):
    def test_bad_arguments_are_refused_in_one_line(self):
        for script, arguments, named in CASES:
            with self.subTest(script=script, arguments=arguments):
                result = subprocess.run([sys.executable, os.path.join(BENCH, script)] + arguments,
                                        capture_output=True, text=True, timeout=60)
                self.assertEqual(result.returncode, 2, result.stderr)
                self.assertNotIn("Traceback", result.stderr)
                last = result.stderr.strip().splitlines()[-1]
                self.assertIn("error:", last)
                self.assertIn(named, last)


if __name__ == "__main__":
    unittest.main()
