"""The tools' tests that need optional Python packages (tools/requirements.txt, installed by
tools/install-deps.sh): they run their unittest cases only when every package imports, and
otherwise skip (exit 0) with one line naming the first one missing."""

import sys
import unittest


def missing_package(names):
    """The first of `names` that does not import, or None."""
    for name in names:
        try:
            __import__(name)
        except ImportError:
            return name
    return None


def main_unless_missing(test_name, names):
    """unittest.main() over the calling script's cases, or the skip line and exit 0."""
    missing = missing_package(names)
    if missing:
        print("%s: skipped: %s is not installed (tools/install-deps.sh)" % (test_name, missing))
        sys.exit(0)
    unittest.main()
