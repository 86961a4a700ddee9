"""Every method by the same time budget (`render --time SECONDS`) on the shipped scenes with
references: what tools/bench/equal_time.py (each method against pt) and tools/bench/auto.py
(--method auto against each method) share: their options, the untimed warm-up that builds and
caches the kernel binaries, and one render by time with its figures."""

import argparse
import os
import sys

from radcache_tools import ROOT, radcache, references
from radcache_tools.arguments import parse_with_extra, positive_int, positive_seconds

DEFAULT_METHODS = ["pt", "ic", "rc", "sdrc", "ivg-gather", "decomposition"]


def parse_arguments(doc, argv, scenes, budgets, width, out, height=False):
    """--scenes, --budgets, --methods, --width (and --height with HEIGHT), --out (default
    build/bench/OUT) and the render options after `--`: (arguments, extra options). Stops with
    one line for a scene without a reference; makes the output folder."""
    parser = argparse.ArgumentParser(description=doc.split("\n")[0])
    parser.add_argument("--scenes", nargs="+", default=scenes)
    parser.add_argument("--budgets", nargs="+", type=positive_seconds, default=budgets)
    parser.add_argument("--methods", nargs="+", default=DEFAULT_METHODS)
    parser.add_argument("--width", type=positive_int, default=width)
    if height:
        parser.add_argument("--height", type=positive_int, default=width)
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "bench", out))
    args, extra = parse_with_extra(parser, argv)
    references.require_references(parser, args.scenes)
    os.makedirs(args.out, exist_ok=True)
    return args, extra


def warm_up(scenes, methods, extra, out):
    """Untimed: one tiny render (8 x 8, one sample) of each method on each scene, so that no
    timed run builds a kernel."""
    for scene in scenes:
        for method in methods:
            radcache.run(["render", references.shipped_scene_json(scene), "-o",
                          os.path.join(out, "warm.exr"), "--quiet", "--method", method, "--spp",
                          "1", "--width", "8", "--height", "8"] + extra)


def render_by_time(scene, method, budget, size, extra, out):
    """One render of METHOD on the shipped SCENE by BUDGET seconds at SIZE (width, height) into
    OUT/SCENE-METHOD-BUDGETs.exr: (that name, the image, its first frame's stats, the row's first
    columns: scene, method, budget, render seconds, spp)."""
    name = "%s-%s-%gs" % (scene, method, budget)
    image = os.path.join(out, name + ".exr")
    stats = radcache.render(references.shipped_scene_json(scene), image,
                            ["--method", method, "--time", "%g" % budget, "--width",
                             str(size[0]), "--height", str(size[1])] + extra)
    frame = stats["frames"][0]
    row = {"scene": scene, "method": method, "budget": budget,
           "seconds": stats["seconds"]["render"], "spp": frame["spp"]}
    return name, image, frame, row


def measure_all(args, methods, measure, line, stream=sys.stdout):
    """measure(scene, method, budget) for every scene, budget and method in that order; prints
    line(row) after each. The rows."""
    rows = []
    for scene in args.scenes:
        for budget in args.budgets:
            for method in methods:
                rows.append(measure(scene, method, budget))
                print(line(rows[-1]), file=stream, flush=True)
    return rows
