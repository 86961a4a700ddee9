"""What the benchmark scripts share: the radcache executable ($RADCACHE, else build/radcache),
running it (exit with its output when it fails) and the CPU seconds its processes have used."""

import json
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


def compared_relmse(image, reference, json_path, aov="beauty"):
    """`radcache compare`'s relMSE of IMAGE's AOV against REFERENCE (written to JSON_PATH), net of
    the reference's noise where compare knows it."""
    run(["compare", image, reference, "--aov", aov, "--json", json_path])
    with open(json_path) as f:
        c = json.load(f)
    return c["relmse_net"] if c.get("relmse_net") is not None else c["relmse"]
