"""Running a command the way the measurement tools do: echoed first, its stdout returned, and the
tool exits naming the command and its output when it fails."""

import subprocess
import sys


def echoed_run(tool, command):
    """Prints `+ COMMAND`, runs it and returns its stdout; exits with `TOOL: COMMAND failed:` and
    its output when it fails."""
    print("+ " + " ".join(command), flush=True)
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("%s: %s failed:\n%s%s" % (tool, " ".join(command), result.stdout, result.stderr))
    return result.stdout
