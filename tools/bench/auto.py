#!/usr/bin/env python3
"""`--method auto` against every method at its defaults with the same --time (docs/auto.md).

For each scene and budget, renders `--method auto --time SECONDS` and each of --methods with the
same --time at WIDTH (the height keeps the scene camera's aspect), their other options at their
defaults, and measures the beauty layer's relMSE against the scene's least noisy reference (the
65 536-spp one of ../shared/references where there is one, net of its noise). Reports, per scene
and budget, every run's render seconds, samples per pixel and relMSE; auto's plan; auto's relMSE
over the best method's and over pt's; and auto's render seconds over the budget. The targets
(docs/auto.md): auto within 1.1x the best and never above pt; at 30 s, pt's relMSE over auto's at
least 20 (cornell-box), 50 (two-rooms) and 4 (glossy-box). All runs happen side by side in this
one invocation, on one device, kernel binaries warm (an untimed tiny render of each method
first; auto's throughput measured then if it was not cached).

Usage: tools/bench/auto.py [--scenes cornell-box two-rooms glossy-box] [--budgets 10 30 100]
           [--methods pt ic rc sdrc ivg-gather decomposition] [--width 256]
           [--out build/bench/auto] [-- extra render options]
Writes OUT/auto.json (every run), OUT/auto.md (the tables) and OUT/auto-SCENE.png (relMSE against
the budget, a line per method; with matplotlib), and prints the tables.
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
from radcache_process import compared_relmse, run  # noqa: E402
from references import shipped_scene_json as scene_json  # noqa: E402

DEFAULT_METHODS = ["pt", "ic", "rc", "sdrc", "ivg-gather", "decomposition"]
TARGET_OVER_PT_AT_30 = {"cornell-box": 20.0, "two-rooms": 50.0, "glossy-box": 4.0}


def measure(scene, method, budget, size, extra, out):
    name = "%s-%s-%gs" % (scene, method, budget)
    image = os.path.join(out, name + ".exr")
    stats_path = os.path.join(out, name + ".stats.json")
    run(["render", scene_json(scene), "-o", image, "--stats", stats_path, "--quiet", "--method",
         method, "--time", "%g" % budget, "--width", str(size[0]), "--height", str(size[1])] +
        extra)
    with open(stats_path) as f:
        stats = json.load(f)
    frame = stats["frames"][0]
    reference = references.best_reference_path(os.path.join(ROOT, "scenes", scene))
    row = {"scene": scene, "method": method, "budget": budget,
           "seconds": stats["seconds"]["render"], "spp": frame["spp"],
           "relmse": compared_relmse(image, reference, os.path.join(out, name + ".compare.json"))}
    if "auto" in frame:
        row["plan"] = frame["auto"]["line"]
    return row


def warm_up(scenes, methods, extra, out):
    for scene in scenes:
        for method in methods:
            run(["render", scene_json(scene), "-o", os.path.join(out, "warm.exr"), "--quiet",
                 "--method", method, "--spp", "1", "--width", "8", "--height", "8"] + extra)


def table(rows, scene, budget):
    at = [r for r in rows if r["scene"] == scene and r["budget"] == budget]
    auto = next(r for r in at if r["method"] == "auto")
    others = [r for r in at if r["method"] != "auto"]
    best = min(others, key=lambda r: r["relmse"])
    pt = next((r for r in others if r["method"] == "pt"), None)
    lines = ["%s, --time %g:" % (scene, budget), "",
             "| method | render s | spp | relMSE | over auto's |", "| --- | --- | --- | --- | --- |"]
    for r in at:
        lines.append("| %s | %.1f | %d | %.3e | %.2f |" % (
            r["method"], r["seconds"], r["spp"], r["relmse"], r["relmse"] / auto["relmse"]))
    lines += ["", "plan: %s" % auto.get("plan", ""),
              "auto / best (%s): %.2f (target <= 1.1); render s / budget: %.2f" % (
                  best["method"], auto["relmse"] / best["relmse"], auto["seconds"] / budget)]
    if pt:
        target = TARGET_OVER_PT_AT_30.get(scene) if budget == 30 else None
        lines.append("pt / auto: %.2f (target >= %s)" % (
            pt["relmse"] / auto["relmse"], "%g" % target if target else "1"))
    return "\n".join(lines) + "\n"


def chart(rows, scene, path):
    """relMSE against the budget, one line per method, auto's thicker: OUT/auto-SCENE.png."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    methods = []
    for r in rows:
        if r["scene"] == scene and r["method"] not in methods:
            methods.append(r["method"])
    for method in methods:
        points = sorted((r["budget"], r["relmse"]) for r in rows
                        if r["scene"] == scene and r["method"] == method)
        ax.plot([p[0] for p in points], [p[1] for p in points], marker="o", label=method,
                linewidth=3 if method == "auto" else 1.2, zorder=3 if method == "auto" else 2)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("--time (s)")
    ax.set_ylabel("image relMSE")
    ax.set_title("%s: every method at its defaults, and auto" % scene)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenes", nargs="+", default=["cornell-box", "two-rooms", "glossy-box"])
    parser.add_argument("--budgets", nargs="+", type=positive_seconds, default=[10, 30, 100])
    parser.add_argument("--methods", nargs="+", default=DEFAULT_METHODS)
    parser.add_argument("--width", type=positive_int, default=256)
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "bench", "auto"))
    args, extra = parse_with_extra(parser, argv)
    references.require_references(parser, args.scenes)
    os.makedirs(args.out, exist_ok=True)
    warm_up(args.scenes, ["auto"] + args.methods, extra, args.out)
    rows = []
    for scene in args.scenes:
        size = references.camera_size(scene_json(scene), args.width)
        for budget in args.budgets:
            for method in ["auto"] + args.methods:
                rows.append(measure(scene, method, budget, size, extra, args.out))
                print("%s %s %gs: %.3e in %.1f s" % (scene, method, budget, rows[-1]["relmse"],
                                                    rows[-1]["seconds"]), flush=True)
    text = "\n".join(table(rows, s, b) for s in args.scenes for b in args.budgets)
    with open(os.path.join(args.out, "auto.json"), "w") as f:
        json.dump(rows, f, indent=1)
    with open(os.path.join(args.out, "auto.md"), "w") as f:
        f.write(text)
    try:
        for scene in args.scenes:
            chart(rows, scene, os.path.join(args.out, "auto-%s.png" % scene))
    except ImportError:
        print("auto.py: matplotlib is not installed: no charts", file=sys.stderr)
    print(text)


if __name__ == "__main__":
    main(sys.argv[1:])
