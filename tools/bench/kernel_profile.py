#!/usr/bin/env python3
"""Where a kernel's time goes, by the source function each instruction came from.

Runs a radcache command under `perf record` with PoCL told to keep debug information in the
kernels it compiles (POCL_EXTRA_BUILD_FLAGS=-g, the kernel cache bypassed so they are compiled
afresh), then reads the samples that landed in PoCL's compiled kernels: `perf report` gives each
kernel symbol's share, `perf annotate` each instruction's, and the line markers perf prints from
the debug information name the (inlined) kernel function the instruction belongs to. Prints the
functions' shares of all kernel samples, largest first.

    python3 tools/bench/kernel_profile.py [--top N] [--json FILE] -- bench pt --width 256 ...

Sampling, not counting: figures vary by a percent or two run to run; compare two kernels side by
side in one session. Needs `perf` (Debian's linux-perf) and a kernel that lets it sample
(/proc/sys/kernel/perf_event_paranoid at most 2); PoCL only (other implementations' kernels are
not shared objects perf can annotate).
"""

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

from radcache_tools import radcache

# `perf report` rows: "  54.27%  path_trace_pass.so  [.] rc_path_radiance".
REPORT_ROW = re.compile(r"^\s*([0-9.]+)%\s+(\S+)\s+\[\.\]\s+(\S+)")
# `perf annotate --stdio` lines: a source marker " : 331  rc_light_sample():" and an instruction
# "    4.84 :   9ada:   vsubps ...".
SOURCE_MARKER = re.compile(r"^\s+:\s+[0-9]+\s+([A-Za-z_][A-Za-z_0-9]*)\(\):")
INSTRUCTION = re.compile(r"^\s+([0-9]+\.[0-9]+)\s+:\s+[0-9a-f]+:")


# The phase of a path sample a kernel function belongs to, by its name (first match wins); the rest
# is "other" (the work-group loop, camera ray, film update and whatever is not named here).
PHASES = [
    ("traversal", re.compile(r"intersect|traverse|wide_slab|watertight|traceable|traversal|"
                             r"box_ray|bvh|packet|triangle_cross|triangle_magnitude|"
                             r"triangle_unit|lowest_bit")),
    ("random numbers", re.compile(r"philox|rng_|unit_float")),
    ("light sampling", re.compile(r"light|spherical|arc_|atan2|argReduction|sample_cdf|"
                                  r"cdf_probability|environment|occluded")),
    ("BSDF sampling and evaluation", re.compile(r"material|bsdf|brdf|concentric|hemisphere|"
                                                r"reflection|bounce|phong|ward|conductor|"
                                                r"dielectric|fresnel|trowbridge|power_heuristic")),
    ("surface point", re.compile(r"surface_point|offset|hit_point|triangle_normal|"
                                 r"orthonormal|to_local|from_local|texture")),
]


def phase_of(function):
    """The phase (PHASES) kernel function FUNCTION belongs to."""
    for phase, pattern in PHASES:
        if pattern.search(function):
            return phase
    return "other"


def kernel_symbols(report_text):
    """(share %, dso, symbol) of every sampled symbol in a PoCL kernel object (a .so whose name
    PoCL gives after the kernel), from `perf report --sort dso,symbol` text."""
    rows = []
    for line in report_text.splitlines():
        m = REPORT_ROW.match(line)
        if m and m.group(2).endswith(".so") and not m.group(2).startswith("lib"):
            rows.append((float(m.group(1)), m.group(2), m.group(3)))
    return rows


def function_shares(annotate_text, symbol):
    """{source function: % of the symbol's samples} from `perf annotate --stdio` text of one
    symbol: each instruction's percentage goes to the function of the source marker above it (the
    symbol itself before any marker)."""
    shares = {}
    function = symbol
    for line in annotate_text.splitlines():
        marker = SOURCE_MARKER.match(line)
        if marker:
            function = marker.group(1)
            continue
        instruction = INSTRUCTION.match(line)
        if instruction:
            shares[function] = shares.get(function, 0.0) + float(instruction.group(1))
    return shares


def profile(command, data_path):
    """Records COMMAND (radcache arguments) into DATA_PATH; returns {function: % of all kernel
    samples}."""
    env = dict(os.environ, POCL_EXTRA_BUILD_FLAGS="-g")
    record = ["perf", "record", "-q", "-o", data_path, radcache.executable()] + command + ["--no-kernel-cache"]
    result = subprocess.run(record, env=env, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("kernel_profile: %s failed:\n%s%s" % (" ".join(record), result.stdout,
                                                       result.stderr))
    report = subprocess.run(["perf", "report", "-i", data_path, "--stdio", "--no-children",
                             "--sort", "dso,symbol", "-g", "none"],
                            capture_output=True, text=True, check=True).stdout
    symbols = kernel_symbols(report)
    total = sum(share for share, _, _ in symbols)
    if total <= 0.0:
        sys.exit("kernel_profile: no samples landed in a PoCL kernel (is the device PoCL's?)")
    functions = {}
    for share, _, symbol in symbols:
        annotate = subprocess.run(["perf", "annotate", "-i", data_path, "--stdio", symbol],
                                  capture_output=True, text=True).stdout
        parts = function_shares(annotate, symbol) or {symbol: 100.0}
        parts_total = sum(parts.values())
        for function, part in parts.items():
            functions[function] = functions.get(function, 0.0) + (
                100.0 * share / total * part / parts_total)
    return functions


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--top", type=int, default=25, help="functions to print (default 25)")
    parser.add_argument("--json", help="also write {function: share %%} to this file")
    parser.add_argument("command", nargs=argparse.REMAINDER,
                        help="radcache arguments after --, e.g. -- bench pt --width 256")
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not command:
        parser.error("give the radcache command to profile after --")
    if args.top < 1:
        parser.error("--top must be at least 1, not %d" % args.top)
    with tempfile.TemporaryDirectory() as scratch:
        functions = profile(command, os.path.join(scratch, "perf.data"))
    ranked = sorted(functions.items(), key=lambda item: -item[1])
    print("share of kernel samples by source function (radcache %s)" % " ".join(command))
    for function, share in ranked[:args.top]:
        print("%6.2f%%  %s" % (share, function))
    phases = {}
    for function, share in functions.items():
        phases[phase_of(function)] = phases.get(phase_of(function), 0.0) + share
    print("by phase")
    for phase, share in sorted(phases.items(), key=lambda item: -item[1]):
        print("%6.2f%%  %s" % (share, phase))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(dict(ranked), f, indent=1)


if __name__ == "__main__":
    main()
