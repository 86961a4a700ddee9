#!/usr/bin/env python3
"""Every method at its defaults with the same time budget (`render --time`), against the shipped
references: the table an automatic choice of method must beat, and the figures the README's
"which method when" rests on.

For each scene and budget, renders each method with `--time SECONDS` at WIDTH x HEIGHT, its
other options at their defaults (the scene's render defaults included), and measures the beauty
and indirect layers' relMSE against the scene's reference (`radcache compare`; a reference at k
times the size is box-filtered to it). Reports each run's render seconds (the render phase of
`--stats`), samples per pixel, passes and first-pass seconds (the cache and one sample per pixel:
docs/rendering-by-time.md), and each method's relMSE over pt's at that budget. All runs happen
side by side in this one invocation, on one device, kernel binaries warm (an untimed tiny render
of each method first).

Usage: tools/bench/equal_time.py [--scenes cornell-box glossy-box] [--budgets 10 30]
           [--methods pt ic rc sdrc ivg-gather decomposition] [--width 128] [--height 128]
           [--out build/bench/equal_time] [-- extra render options]
Writes OUT/equal_time.json (every run) and OUT/equal_time.md (the tables), and prints the
tables. Python 3 standard library only.
"""

import argparse
import json
import os
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import references  # noqa: E402
from arg_types import positive_int, positive_seconds  # noqa: E402
from extra_options import parse_with_extra  # noqa: E402
from radcache_process import run  # noqa: E402

DEFAULT_METHODS = ["pt", "ic", "rc", "sdrc", "ivg-gather", "decomposition"]


def relmse(image, reference, aov, json_path):
    run(["compare", image, reference, "--aov", aov, "--json", json_path])
    with open(json_path) as f:
        return json.load(f)["relmse"]


def measure(scene, method, budget, args, extra, out):
    """One render of `method` by `budget` seconds: its figures and relMSEs."""
    name = "%s-%s-%gs" % (scene, method, budget)
    image = os.path.join(out, name + ".exr")
    stats_path = os.path.join(out, name + ".stats.json")
    scene_json = os.path.join(ROOT, "scenes", scene, "scene.json")
    run(["render", scene_json, "-o", image, "--stats", stats_path, "--quiet", "--method", method,
         "--time", "%g" % budget, "--width", str(args.width), "--height", str(args.height)] + extra)
    with open(stats_path) as f:
        stats = json.load(f)
    frame = stats["frames"][0]
    time = frame.get("time", {})
    reference = references.reference_path(os.path.join(ROOT, "scenes", scene))
    row = {"scene": scene, "method": method, "budget": budget,
           "seconds": stats["seconds"]["render"], "spp": frame["spp"],
           "passes": time.get("passes", frame["spp"]),
           "first_pass_seconds": time.get("first_pass_seconds")}
    for aov in ("beauty", "indirect"):
        row["relmse_" + aov] = relmse(image, reference, aov,
                                      os.path.join(out, "%s.%s.json" % (name, aov)))
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
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenes", nargs="+", default=["cornell-box", "glossy-box"])
    parser.add_argument("--budgets", nargs="+", type=positive_seconds, default=[10.0, 30.0])
    parser.add_argument("--methods", nargs="+", default=DEFAULT_METHODS)
    parser.add_argument("--width", type=positive_int, default=128)
    parser.add_argument("--height", type=positive_int, default=128)
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "bench", "equal_time"))
    args, extra = parse_with_extra(parser, argv)
    references.require_references(parser, args.scenes)
    os.makedirs(args.out, exist_ok=True)
    warm = os.path.join(ROOT, "scenes", args.scenes[0], "scene.json")
    for method in args.methods:  # kernel binaries built and cached before any timed run
        run(["render", warm, "-o", os.path.join(args.out, "warm.exr"), "--quiet", "--method",
             method, "--spp", "1", "--width", "8", "--height", "8"] + extra)
    rows = []
    for scene in args.scenes:
        for budget in args.budgets:
            for method in args.methods:
                rows.append(measure(scene, method, budget, args, extra, args.out))
                print("%s %s %gs: relMSE %.3e" % (scene, method, budget, rows[-1]["relmse_beauty"]),
                      file=sys.stderr)
    with open(os.path.join(args.out, "equal_time.json"), "w") as f:
        json.dump(rows, f, indent=1)
    text = "\n".join(table(rows, s, b) for s in args.scenes for b in args.budgets)
    with open(os.path.join(args.out, "equal_time.md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main(sys.argv[1:])
