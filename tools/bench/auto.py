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

import json
import os
import sys

from radcache_tools import ROOT, equal_time, references
from radcache_tools.error import relmse

TARGET_OVER_PT_AT_30 = {"cornell-box": 20.0, "two-rooms": 50.0, "glossy-box": 4.0}


def measure(scene, method, budget, size, extra, out):
    name, image, frame, row = equal_time.render_by_time(scene, method, budget, size, extra, out)
    reference = references.best_reference_path(os.path.join(ROOT, "scenes", scene))
    row["relmse"] = relmse(image, reference, os.path.join(out, name + ".compare.json"))
    if "auto" in frame:
        row["plan"] = frame["auto"]["line"]
    return row


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
    args, extra = equal_time.parse_arguments(__doc__, argv,
                                             ["cornell-box", "two-rooms", "glossy-box"],
                                             [10, 30, 100], 256, "auto")
    equal_time.warm_up(args.scenes, ["auto"] + args.methods, extra, args.out)
    sizes = {scene: references.camera_size(references.shipped_scene_json(scene), args.width)
             for scene in args.scenes}
    rows = equal_time.measure_all(
        args, ["auto"] + args.methods,
        lambda s, m, b: measure(s, m, b, sizes[s], extra, args.out),
        lambda r: "%s %s %gs: %.3e in %.1f s" % (r["scene"], r["method"], r["budget"],
                                                 r["relmse"], r["seconds"]))
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
