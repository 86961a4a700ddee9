#!/usr/bin/env python3
"""Every method at its defaults with the same time budget (`render --time`), against the shipped
references: the table an automatic choice of method must beat, and the figures the README's
"which method when" rests on.

For each scene and budget, renders each method with `--time SECONDS` at WIDTH x HEIGHT, its
other options at their defaults (the scene's render defaults included), and measures the beauty
and indirect layers' relMSE against the scene's reference (`radcache compare`; a reference at k
times the size is box-filtered to it; the beauty's net of the reference's noise). Reports each
run's render seconds (the render phase of `--stats`), samples per pixel, passes and first-pass
seconds (the cache and one sample per pixel: docs/rendering-by-time.md), and each method's relMSE over pt's at that budget. All runs happen
side by side in this one invocation, on one device, kernel binaries warm (an untimed tiny render
of each method first).

Usage: tools/bench/equal_time.py [--scenes cornell-box glossy-box] [--budgets 10 30]
           [--methods pt ic rc sdrc ivg-gather decomposition] [--width 128] [--height 128]
           [--out build/bench/equal_time] [-- extra render options]
Writes OUT/equal_time.json (every run) and OUT/equal_time.md (the tables), and prints the
tables. Python 3 standard library only.
"""

import json
import os
import sys

from radcache_tools import ROOT, equal_time, references
from radcache_tools.error import relmse


def measure(scene, method, budget, args, extra, out):
    """One render of `method` by `budget` seconds: its figures and relMSEs (tools/radcache_tools/
    error.py: the beauty's net of the reference's noise)."""
    name, image, frame, row = equal_time.render_by_time(scene, method, budget,
                                                        (args.width, args.height), extra, out)
    time = frame.get("time", {})
    row.update({"passes": time.get("passes", frame["spp"]),
                "first_pass_seconds": time.get("first_pass_seconds")})
    reference = references.reference_path(os.path.join(ROOT, "scenes", scene))
    for aov in ("beauty", "indirect"):
        row["relmse_" + aov] = relmse(image, reference,
                                      os.path.join(out, "%s.%s.json" % (name, aov)), aov)
    return row


def table(rows, scene, budget):
    """The markdown table of one scene at one budget."""
    at = [r for r in rows if r["scene"] == scene and r["budget"] == budget]
    pt = next((r for r in at if r["method"] == "pt"), None)
    lines = ["%s, --time %g:" % (scene, budget), "",
             "| method | render s | spp | passes | first pass s | relMSE | indirect relMSE "
             "| pt's relMSE / this |", "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in at:
        ratio = pt["relmse_beauty"] / r["relmse_beauty"] if pt and r["relmse_beauty"] > 0 else None
        first = r["first_pass_seconds"]
        lines.append("| %s | %.1f | %d | %d | %s | %.3e | %.3e | %s |" % (
            r["method"], r["seconds"], r["spp"], r["passes"],
            "%.1f" % first if first is not None else "-", r["relmse_beauty"],
            r["relmse_indirect"], "%.2f" % ratio if ratio is not None else "-"))
    return "\n".join(lines) + "\n"


def main(argv):
    args, extra = equal_time.parse_arguments(__doc__, argv, ["cornell-box", "glossy-box"],
                                             [10.0, 30.0], 128, "equal_time", height=True)
    # Kernel binaries built and cached before any timed run.
    equal_time.warm_up(args.scenes[:1], args.methods, extra, args.out)
    rows = equal_time.measure_all(
        args, args.methods, lambda s, m, b: measure(s, m, b, args, extra, args.out),
        lambda r: "%s %s %gs: relMSE %.3e" % (r["scene"], r["method"], r["budget"],
                                             r["relmse_beauty"]), sys.stderr)
    with open(os.path.join(args.out, "equal_time.json"), "w") as f:
        json.dump(rows, f, indent=1)
    text = "\n".join(table(rows, s, b) for s in args.scenes for b in args.budgets)
    with open(os.path.join(args.out, "equal_time.md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main(sys.argv[1:])
