"""What the benchmark scripts share: the radcache executable ($RADCACHE, else build/radcache),
running it (exit with its output when it fails) and the CPU seconds its processes have used."""

import os
import resource
import subprocess
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
RADCACHE = os.environ.get("RADCACHE") or os.path.join(ROOT, "build", "radcache")


def run(args):
    """radcache ARGS; its stdout. Exits naming the command and its output when it fails."""
    result = subprocess.run([RADCACHE] + args, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("radcache %s failed:\n%s%s" % (" ".join(args), result.stdout, result.stderr))
    return result.stdout


def cpu_seconds():
    """User + system CPU seconds of every finished child process so far."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime
