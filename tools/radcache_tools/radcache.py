"""Running radcache, the one way the tools do: the executable is $RADCACHE when set, else
build/radcache of this checkout; a run that fails exits the tool with the command and its output.
"""

import json
import os
import resource
import subprocess
import sys
import time

from radcache_tools import ROOT


def executable():
    """The radcache the tools run: $RADCACHE when set, else build/radcache of this checkout."""
    return os.environ.get("RADCACHE") or os.path.join(ROOT, "build", "radcache")


def _prefix(tool):
    return tool + ": " if tool else ""


def require_built(tool=None):
    """Exits with one line (naming TOOL when given) unless the executable is there to run."""
    path = executable()
    if not os.access(path, os.X_OK):
        sys.exit("%sbuild radcache first (see README): %s is missing" % (_prefix(tool), path))


def run_command(command, tool=None, echo=False, name=None):
    """Runs COMMAND (a list) and returns its stdout; prints `+ COMMAND` first with ECHO. When it
    fails, exits with `TOOL: NAME failed:` (NAME: the command line) and its output."""
    if echo:
        print("+ " + " ".join(command), flush=True)
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("%s%s failed:\n%s%s" % (_prefix(tool), name or " ".join(command),
                                         result.stdout, result.stderr))
    return result.stdout


def run(args, tool=None, echo=False):
    """radcache ARGS; its stdout. Exits naming `radcache ARGS` and its output when it fails."""
    return run_command([executable()] + list(args), tool, echo,
                       name="radcache " + " ".join(args))


def attempt(args, **options):
    """radcache ARGS whatever its exit status: the CompletedProcess (text output captured), for
    a caller that reads the status itself."""
    return subprocess.run([executable()] + list(args), capture_output=True, text=True, **options)


def stats_path_of(image):
    """Where render() writes an image's --stats: IMAGE without its extension, .stats.json."""
    return os.path.splitext(image)[0] + ".stats.json"


def timed_render(scene, image, options, stats_path=None, tool=None, echo=False):
    """`radcache render SCENE -o IMAGE --stats STATS --quiet OPTIONS`: (the process's wall
    seconds, the --stats JSON). STATS defaults to stats_path_of(IMAGE)."""
    stats_path = stats_path or stats_path_of(image)
    start = time.perf_counter()
    run(["render", scene, "-o", image, "--stats", stats_path, "--quiet"] + list(options), tool,
        echo)
    wall = time.perf_counter() - start
    with open(stats_path) as f:
        return wall, json.load(f)


def render(scene, image, options, stats_path=None, tool=None, echo=False):
    """timed_render's --stats JSON alone."""
    return timed_render(scene, image, options, stats_path, tool, echo)[1]


def cpu_seconds():
    """User + system CPU seconds of every finished child process so far."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime
